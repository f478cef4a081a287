//! Incremental hulls (`Hull::add_points`, `add_points_with_strategy`): a hull grown by new points
//! is the hull of all of them, checked against an independent test (every point weakly inside
//! every facet, exactly: `Hull::check`) and, with the `qhull` feature, Qhull's vertex set; a
//! partial strategy resumed on the grown hull gives the distance an exact rational Wolfe gives
//! on all the points.

use crate::support::min_norm::exact_min_norm_distance;
use crate::support::points_as_vecs;
use pqhull::rbox::{Family, generate};
use pqhull::{ClosestToOrigin, Hull, HullError};

/// Facets as sorted vertex lists, sorted: the hull's combinatorics, independent of ids.
fn facets<const D: usize>(hull: &Hull<D>) -> Vec<Vec<usize>> {
    let mut all: Vec<Vec<usize>> = hull
        .facets()
        .map(|(_, f)| {
            let mut v = f.vertices().to_vec();
            v.sort_unstable();
            v
        })
        .collect();
    all.sort();
    all
}

/// Builds from the first `start` points, adds the rest in chunks of `chunk`, and checks the
/// result against the hull of all the points (and Qhull's vertices when `general`: input in
/// general position, where Qhull's floating-point answer is the exact one).
fn grow_in_chunks<const D: usize>(
    points: &[[f64; D]],
    start: usize,
    chunk: usize,
    general: bool,
    what: &str,
) {
    let mut hull = Hull::try_new(&points[..start]).unwrap_or_else(|e| panic!("{what}: {e}"));
    let mut at = start;
    while at < points.len() {
        let end = (at + chunk).min(points.len());
        let added = hull.add_points(&points[at..end]).expect("finite points");
        assert_eq!(added, at..end, "{what}");
        hull.check()
            .unwrap_or_else(|e| panic!("{what}, after {end}: {e}"));
        at = end;
    }
    assert_eq!(hull.point_count(), points.len(), "{what}");
    let full = Hull::try_new(points).unwrap();
    assert_eq!(hull.vertex_indices(), full.vertex_indices(), "{what}");
    if general {
        // Coplanar faces (a cube's) may be triangulated either way; simplicial ones only one.
        assert_eq!(facets(&hull), facets(&full), "{what}: facets");
    }
    let (volume, area) = (full.volume(), full.area());
    assert!(
        (hull.volume() - volume).abs() <= 1e-12 * volume,
        "{what}: volume"
    );
    assert!((hull.area() - area).abs() <= 1e-12 * area, "{what}: area");
    #[cfg(not(feature = "qhull"))]
    let _ = general;
    #[cfg(feature = "qhull")]
    if general && D <= 6 {
        let qhull = pqhull::qhull_baseline::qhull_full_hull(points).expect("Qhull");
        assert_eq!(
            hull.vertex_indices(),
            qhull.vertices,
            "{what}: Qhull's vertices"
        );
    }
}

fn grow_every_family<const D: usize>() {
    for (family, n) in [
        (Family::UniformCube, 400),
        (Family::SphereSurface, 150),
        (Family::CubeCornersDiamond, 200),
        (Family::Simplex, 100),
    ] {
        for seed in 1..=3u64 {
            let points = generate::<D>(&family, n, seed);
            let what = format!("{family:?} D={D} seed {seed}");
            // Starting from a simplex's worth of points is a hull only when they are
            // independent: start from the family's first 2D + 2 points (independent in each).
            let start = (2 * D + 2).min(points.len());
            if Hull::try_new(&points[..start]).is_err() {
                continue;
            }
            let general = matches!(family, Family::UniformCube | Family::SphereSurface);
            grow_in_chunks(&points, start, 1 + seed as usize * 37, general, &what);
        }
    }
}

#[test]
fn a_grown_hull_is_the_hull_of_all_its_points() {
    grow_every_family::<2>();
    grow_every_family::<3>();
    grow_every_family::<4>();
    grow_every_family::<5>();
}

#[test]
fn a_grown_hull_in_six_to_eight_dimensions() {
    for seed in 1..=2u64 {
        let points = generate::<6>(&Family::UniformCube, 150, seed);
        grow_in_chunks(&points, 20, 40, true, "cube D=6");
        let points = generate::<7>(&Family::UniformCube, 60, seed);
        grow_in_chunks(&points, 16, 15, true, "cube D=7");
        let points = generate::<8>(&Family::UniformCube, 40, seed);
        grow_in_chunks(&points, 18, 11, true, "cube D=8");
    }
}

/// Integer grids grown from their corners, in shuffled chunks: most new points lie exactly on a
/// facet, a ridge or the line from the hull's interior point through a vertex (the walk's
/// degenerate cases, where every orientation it tests is an exact zero).
#[test]
fn grids_grown_from_their_corners() {
    fn grid<const D: usize>(side: usize, seed: u64) {
        let mut points: Vec<[f64; D]> = (0..side.pow(D as u32))
            .map(|mut i| {
                std::array::from_fn(|_| {
                    let c = (i % side) as f64;
                    i /= side;
                    c
                })
            })
            .collect();
        // Corners first, the rest in a seeded order.
        let corner = |p: &[f64; D]| p.iter().all(|&c| c == 0.0 || c == (side - 1) as f64);
        points.sort_by_key(|p| !corner(p));
        let corners = points.iter().filter(|p| corner(p)).count();
        let mut rng = pqhull::geometry::Rng::new(seed);
        for i in (corners + 1..points.len()).rev() {
            let j = corners + rng.index(i - corners + 1);
            points.swap(i, j);
        }
        let what = format!("grid {side}^{D}");
        grow_in_chunks(&points, corners, 7 + seed as usize, false, &what);
        // Points added beyond the grid's corners grow it; the centre's rays then cross the
        // old vertices exactly.
        let mut hull = Hull::try_new(&points).unwrap();
        let far: Vec<[f64; D]> = points
            .iter()
            .filter(|p| corner(p))
            .map(|p| p.map(|c| 2.0 * c - (side - 1) as f64 / 2.0))
            .collect();
        hull.add_points(&far).unwrap();
        hull.check().unwrap_or_else(|e| panic!("{what}: {e}"));
        let mut all = points.clone();
        all.extend_from_slice(&far);
        assert_eq!(
            hull.vertex_indices(),
            Hull::try_new(&all).unwrap().vertex_indices(),
            "{what}"
        );
    }
    grid::<2>(9, 1);
    grid::<3>(5, 2);
    grid::<4>(4, 3);
}

/// Inside points, repeats of vertices and points on facets change nothing.
#[test]
fn points_inside_or_on_the_hull_change_nothing() {
    let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    let mut hull = Hull::try_new(&square).unwrap();
    let before = facets(&hull);
    let added = hull
        .add_points(&[[1.0, 1.0], [2.0, 2.0], [1.0, 0.0], [0.0, 0.5]])
        .unwrap();
    assert_eq!(added, 4..8);
    assert_eq!(facets(&hull), before);
    assert_eq!(hull.vertex_indices(), vec![0, 1, 2, 3]);
    hull.check().unwrap();
}

/// A new coordinate beyond the range the hull was scaled for: rebuilt from all the points, the
/// same hull, exactly.
#[test]
fn far_points_are_added_exactly() {
    let points = generate::<3>(&Family::UniformCube, 100, 9);
    let mut hull = Hull::try_new(&points).unwrap();
    let far = [[1e6, 0.0, 0.0], [-3e-3, 7e5, 1.0], [0.0, 0.0, -2e9]];
    hull.add_points(&far).unwrap();
    hull.check().unwrap();
    let mut all = points.clone();
    all.extend_from_slice(&far);
    assert_eq!(facets(&hull), facets(&Hull::try_new(&all).unwrap()));
    // And a tiny hull grown by ordinary points (its scale is far finer than theirs).
    let tiny: Vec<[f64; 2]> = [[0.0, 0.0], [1e-300, 0.0], [0.0, 1e-300]].into();
    let mut hull = Hull::try_new(&tiny).unwrap();
    hull.add_points(&[[1.0, 1.0]]).unwrap();
    hull.check().unwrap();
    assert_eq!(hull.vertex_indices(), vec![0, 1, 2, 3]);
}

#[test]
fn a_non_finite_point_is_an_error_and_leaves_the_hull() {
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let mut hull = Hull::try_new(&square).unwrap();
    let error = hull.add_points(&[[3.0, 3.0], [0.5, f64::NAN]]).unwrap_err();
    assert_eq!(
        error,
        HullError::NonFinite {
            index: 5,
            coordinate: 1
        }
    );
    assert_eq!(hull.point_count(), 4);
    assert_eq!(hull.vertex_indices(), vec![0, 1, 2, 3]);
    hull.check().unwrap();
}

/// An empty hull grown by points is their hull; too few of them is the build's error.
#[test]
fn an_empty_hull_grows_into_a_hull() {
    let mut hull = Hull::<3>::empty();
    assert!(matches!(
        hull.add_points(&[[0.0; 3], [1.0, 0.0, 0.0]]),
        Err(HullError::TooFewPoints { .. })
    ));
    let points = generate::<3>(&Family::UniformCube, 50, 4);
    let mut hull = Hull::<3>::empty();
    assert_eq!(hull.add_points(&points).unwrap(), 0..50);
    assert_eq!(facets(&hull), facets(&Hull::try_new(&points).unwrap()));
}

/// `ClosestToOrigin` resumed on a partial hull grown by new points: the distance of all the
/// points, against exact rational Wolfe (outside) and the exact sign.
#[test]
fn closest_to_origin_resumes_with_the_new_points() {
    fn check<const D: usize>(points: &[[f64; D]], split: usize, query: [f64; D], what: &str) {
        let strategy = || ClosestToOrigin::towards(query);
        let (mut hull, _) = Hull::try_with_strategy(&points[..split], strategy()).unwrap();
        let (added, resumed) = hull
            .add_points_with_strategy(&points[split..], strategy())
            .unwrap();
        assert_eq!(added, split..points.len());
        hull.check().unwrap_or_else(|e| panic!("{what}: {e}"));
        let (_, fresh) = Hull::try_with_strategy(points, strategy()).unwrap();
        let scale = points
            .iter()
            .map(|p| p.iter().map(|x| x * x).sum::<f64>().sqrt())
            .fold(0.0, f64::max);
        let got = resumed.signed_distance;
        assert!(
            (got - fresh.signed_distance).abs() <= 1e-12 * scale,
            "{what}: resumed {got:e}, fresh {:e}",
            fresh.signed_distance
        );
        if got < 0.0 {
            let exact = exact_min_norm_distance(&points_as_vecs(points), &query);
            assert!(
                (-got - exact).abs() <= 1e-12 * exact.max(1e-3 * scale),
                "{what}: resumed {got:e}, exact {exact:e}"
            );
        }
    }
    for seed in 1..=4u64 {
        let cube = generate::<3>(&Family::UniformCube, 300, seed);
        check(&cube, 40, [0.0; 3], "cube 3-D, inside");
        check(&cube, 40, [0.7, 0.1, -0.2], "cube 3-D, outside");
        let sphere = generate::<4>(&Family::SphereSurface, 200, seed);
        check(&sphere, 30, [0.01, 0.0, 0.02, 0.0], "sphere 4-D, inside");
        check(&sphere, 30, [0.9, 0.0, 0.0, 0.1], "sphere 4-D, outside");
    }
}
