//! Degenerate input (issue 24): integer grids, cube corners with face centres and interior points,
//! the coplanar regions and the exact-grid certificate that make them fast, and the checks of
//! `Hull::rebuild_with_flats`. Every hull is checked from scratch (`Hull::check`) and its vertex
//! set compared with the truth known in the test (the cube's corners).

use pqhull::hull::NO_FLAT;
use pqhull::rbox::{Family, generate};
use pqhull::{FarthestPoint, Hull, HullError};

/// Every point of {0, …, m − 1}^D, in odometer order.
fn grid<const D: usize>(m: usize) -> Vec<[f64; D]> {
    let count = m.pow(D as u32);
    (0..count)
        .map(|mut i| {
            std::array::from_fn(|_| {
                let c = i % m;
                i /= m;
                c as f64
            })
        })
        .collect()
}

/// Whether `p` is a corner of the box spanned by `low` and `high` (every coordinate at a bound).
fn is_corner<const D: usize>(p: &[f64; D], low: f64, high: f64) -> bool {
    p.iter().all(|&x| x == low || x == high)
}

/// The hull of the grid is the cube: exactly its 2^D corners, volume (m − 1)^D.
fn grid_case<const D: usize>(m: usize) {
    let points = grid::<D>(m);
    let hull = Hull::try_new(&points).unwrap();
    hull.check()
        .unwrap_or_else(|e| panic!("{D}-D grid {m}: {e}"));
    let vertices = hull.vertex_indices();
    assert_eq!(vertices.len(), 1 << D, "{D}-D grid {m}: {vertices:?}");
    let top = (m - 1) as f64;
    for &v in &vertices {
        assert!(
            is_corner(&points[v], 0.0, top),
            "{D}-D grid {m}: {:?} is not a corner",
            points[v]
        );
    }
    let volume = top.powi(D as i32);
    assert!(
        (hull.volume() - volume).abs() <= 1e-12 * volume,
        "{D}-D grid {m}: volume {}",
        hull.volume()
    );
}

#[test]
fn integer_grids_are_cubes() {
    grid_case::<3>(12);
    grid_case::<4>(6);
    grid_case::<5>(4);
    grid_case::<6>(4);
}

/// Qhull reports 33 vertices on {0, …, 4}^5 (scipy's defaults; the `qhull` crate's in
/// `pqh bench hull` too), among them
/// (4, 0, 4, 3, 4), which is not a corner: the exact engine gives the 32 corners.
#[test]
fn five_dimensional_grid_where_qhull_adds_a_vertex() {
    grid_case::<5>(5);
    let points = grid::<5>(5);
    let hull = Hull::try_new(&points).unwrap();
    let bogus = [4.0, 0.0, 4.0, 3.0, 4.0];
    let index = points.iter().position(|p| *p == bogus).unwrap();
    assert!(!hull.vertex_indices().contains(&index));
}

/// Cube corners, face centres and random interior points (`rbox c`): the corners alone.
fn corners_case<const D: usize>(n: usize) {
    let points = generate::<D>(&Family::CubeCornersDiamond, n, 7);
    let hull = Hull::try_new(&points).unwrap();
    hull.check()
        .unwrap_or_else(|e| panic!("{D}-D corners: {e}"));
    let vertices = hull.vertex_indices();
    assert_eq!(vertices, (0..1 << D).collect::<Vec<_>>(), "{D}-D corners");
    assert!((hull.volume() - 1.0).abs() < 1e-12, "{D}-D corners");
}

#[test]
fn cube_corners_with_face_centres_and_interior_points() {
    corners_case::<3>(2000);
    corners_case::<4>(2000);
    corners_case::<5>(2000);
    corners_case::<6>(1000);
}

/// A grid scaled by c = 1 + 2^−40 (exact for these small integers: 41 significant bits) is an
/// exact linear image of the grid, so its hull is the scaled cube, but its coordinates sit on a
/// grid 2^40 times finer, which the certificate cannot cover: the filter and the exact fallbacks
/// decide every zero, and the answer is still the corners alone.
#[test]
fn grids_off_the_certificate_give_the_corners() {
    fn run<const D: usize>(m: usize) {
        let c = 1.0 + 2f64.powi(-40);
        let points: Vec<[f64; D]> = grid::<D>(m).into_iter().map(|p| p.map(|x| x * c)).collect();
        assert!(
            pqhull::predicates::ExactGrid::of(&points).is_none(),
            "D={D}"
        );
        let hull = Hull::try_new(&points).unwrap();
        hull.check().unwrap();
        let vertices = hull.vertex_indices();
        assert_eq!(vertices.len(), 1 << D, "D={D}");
        let top = (m - 1) as f64 * c;
        for &v in &vertices {
            assert!(is_corner(&points[v], 0.0, top), "D={D}: {:?}", points[v]);
        }
    }
    run::<3>(6);
    run::<4>(4);
    run::<5>(3);
}

/// A lattice whose extent breaks the certificate's bound (D!·Π spans ≥ 2^52) still decides
/// every sign exactly, through the filter and its exact fallbacks.
#[test]
fn lattices_beyond_the_certificate_bound() {
    // 6-D: 720 · (2^8)^6 = 2^57.5 > 2^52, with many points on the cube's faces.
    let mut points = Vec::new();
    let mut rng = pqhull::geometry::Rng::new(3);
    for corner in 0..64usize {
        points.push(std::array::from_fn::<f64, 6, _>(|c| {
            if (corner >> c) & 1 == 1 { 256.0 } else { 0.0 }
        }));
    }
    for _ in 0..600 {
        let mut p: [f64; 6] = std::array::from_fn(|_| rng.index(257) as f64);
        p[rng.index(6)] = if rng.index(2) == 0 { 0.0 } else { 256.0 };
        points.push(p);
    }
    let hull = Hull::try_new(&points).unwrap();
    hull.check().unwrap();
    assert_eq!(hull.vertex_indices(), (0..64).collect::<Vec<_>>());
}

/// The square pyramid with its base declared as a 2-flat.
fn pyramid() -> Vec<[f64; 3]> {
    vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.5, 0.5, 1.0],
    ]
}

#[test]
fn declared_flats_are_checked() {
    let points = pyramid();
    let mut hull = Hull::<3>::empty();
    hull.rebuild_with_flats(&points, &[0, 0, 0, 0, NO_FLAT], 2, FarthestPoint::new())
        .unwrap();
    hull.check().unwrap();
    assert_eq!(hull.vertex_indices(), vec![0, 1, 2, 3, 4]);

    // A flat dimension outside 1..D.
    for flat_dim in [0, 3, 7] {
        let error = hull
            .rebuild_with_flats(&points, &[0, 0, 0, 0], flat_dim, FarthestPoint::new())
            .unwrap_err();
        assert_eq!(
            error,
            HullError::FlatDimension {
                flat_dim,
                dimension: 3
            }
        );
        assert!(error.to_string().contains("1 to 2"), "{error}");
        assert_eq!(hull.facet_count(), 0, "the hull is left empty");
    }
    // The apex declared in the base's plane: the release build refuses it too.
    let error = hull
        .rebuild_with_flats(&points, &[0, 0, 0, 0, 0], 2, FarthestPoint::new())
        .unwrap_err();
    assert_eq!(
        error,
        HullError::NotInFlat {
            flat: 0,
            index: 4,
            flat_dim: 2
        }
    );
    // A 1-flat claimed for three points of a 2-flat.
    let error = hull
        .rebuild_with_flats(&points, &[5, 5, 5], 1, FarthestPoint::new())
        .unwrap_err();
    assert!(
        matches!(
            error,
            HullError::NotInFlat {
                flat: 5,
                index: 2,
                ..
            }
        ),
        "{error}"
    );
    // More labels than points.
    let error = hull
        .rebuild_with_flats(&points, &[NO_FLAT; 6], 2, FarthestPoint::new())
        .unwrap_err();
    assert_eq!(
        error,
        HullError::TooManyFlatLabels {
            labels: 6,
            points: 5
        }
    );
    // A non-finite coordinate is named before any exact arithmetic sees it.
    let mut bad = points.clone();
    bad[2][1] = f64::NAN;
    let error = hull
        .rebuild_with_flats(&bad, &[0, 0, 0, 0], 2, FarthestPoint::new())
        .unwrap_err();
    assert_eq!(
        error,
        HullError::NonFinite {
            index: 2,
            coordinate: 1
        }
    );
    // After the errors the same storage builds again.
    hull.rebuild_with_flats(&points, &[0, 0, 0, 0], 2, FarthestPoint::new())
        .unwrap();
    hull.check().unwrap();
}

/// Whether the build ran a second phase (see `src/hull/coplanar.rs`): each phase processes its
/// initial simplex's D + 1 points and one per expansion.
fn two_phases<const D: usize>(hull: &Hull<D>) -> bool {
    let stats = hull.stats();
    match stats.points_processed - stats.expansions {
        n if n == D + 1 => false,
        n if n == 2 * (D + 1) => true,
        n => panic!("{n} points processed beyond the expansions"),
    }
}

/// A full build keeps coplanar facets in a first phase; when that leaves points on faces as
/// vertices, a second phase builds on the extreme vertices alone. Cube corners with face centres
/// and the 6-D grid {0, 1, 2}^6 take the second phase; the answer is still the corners. (The 5-D
/// grid {0, …, 3}^5 took it too while pending facets were expanded oldest first; farthest
/// first, its corners come first and one phase suffices: its answer is checked all the same.)
#[test]
fn the_second_phase_leaves_the_corners() {
    fn corners<const D: usize>(n: usize) {
        let points = generate::<D>(&Family::CubeCornersDiamond, n, 1);
        let hull = Hull::try_new(&points).unwrap();
        assert!(two_phases(&hull), "{D}-D corners: one phase");
        hull.check().unwrap();
        assert_eq!(hull.vertex_indices(), (0..1 << D).collect::<Vec<_>>());
    }
    corners::<3>(100);
    corners::<4>(100);
    corners::<5>(400);
    corners::<6>(400);
    let points = grid::<6>(3);
    let hull = Hull::try_new(&points).unwrap();
    assert!(two_phases(&hull), "6-D grid: one phase");
    hull.check().unwrap();
    let vertices = hull.vertex_indices();
    assert_eq!(vertices.len(), 64);
    assert!(vertices.iter().all(|&v| is_corner(&points[v], 0.0, 2.0)));
    let points = grid::<5>(4);
    let hull = Hull::try_new(&points).unwrap();
    let vertices = hull.vertex_indices();
    assert_eq!(vertices.len(), 32);
    assert!(vertices.iter().all(|&v| is_corner(&points[v], 0.0, 3.0)));
    // Points in general position never keep a coplanar facet: one phase.
    let random = generate::<5>(&Family::UniformCube, 500, 9);
    assert!(!two_phases(&Hull::try_new(&random).unwrap()));
}

/// Every vertex of the hull of an integer lattice (rbox `M`, many points on common faces) is
/// extreme: it lies strictly beyond the hull of the other vertices (a separate build, without
/// it), and every input point lies inside (`Hull::check`).
#[test]
fn lattice_vertices_are_extreme() {
    fn run<const D: usize>(n: usize, seed: u64) {
        let points = generate::<D>(&Family::IntegerLattice { half_width: 2 }, n, seed);
        let hull = Hull::try_new(&points).unwrap();
        hull.check().unwrap();
        let vertices = hull.vertex_indices();
        for &v in &vertices {
            let others: Vec<[f64; D]> = vertices
                .iter()
                .filter(|&&w| w != v)
                .map(|&w| points[w])
                .collect();
            let without = Hull::try_new(&others).unwrap();
            assert!(
                without
                    .facets()
                    .any(|(id, _)| without.side_of(id, &points[v])
                        == pqhull::predicates::Sign::Positive),
                "{D}-D lattice: vertex {v} {:?} is inside the others' hull",
                points[v]
            );
        }
    }
    run::<3>(400, 1);
    run::<4>(400, 2);
    run::<5>(300, 3);
    run::<6>(150, 4);
}

/// Points added to a hull built in two phases are added the default way: a corner that a new
/// point puts on an edge (the segment from the opposite corner of that edge to the new point)
/// stops being a vertex, as in a build from all the points.
#[test]
fn points_added_after_a_second_phase_keep_the_vertices_extreme() {
    // A far point on the −x side widens the coordinates' range, so that the new point fits in
    // it and is added incrementally (not by a rebuild from all the points).
    let mut points = generate::<3>(&Family::CubeCornersDiamond, 100, 1);
    points.push([-4.0, 0.0, 0.0]);
    let mut hull = Hull::try_new(&points).unwrap();
    assert!(two_phases(&hull));
    let expansions = hull.stats().expansions;
    // Corner 7 is (0.5, 0.5, 0.5), corner 6 (−0.5, 0.5, 0.5): 7 lies between 6 and the new point.
    let added = hull.add_points(&[[1.5, 0.5, 0.5]]).unwrap();
    hull.check().unwrap();
    let mut all = points.clone();
    all.push([1.5, 0.5, 0.5]);
    let fresh = Hull::try_new(&all).unwrap();
    assert_eq!(hull.vertex_indices(), fresh.vertex_indices());
    assert!(!hull.vertex_indices().contains(&7));
    assert!(hull.vertex_indices().contains(&added.start));
    assert_eq!(
        hull.stats().expansions,
        expansions + 1,
        "added incrementally"
    );
}

/// The vertices of hulls of small integer point sets with many points on common faces (random
/// points of {0, …, 3}^D, a third of them pushed onto a face of the box), by the two-phase
/// build, against an exact reference written in the test: a point is extreme exactly when the
/// origin is not in the hull of the other points less it (exact rational linear programs,
/// `support::exact_lp`, on the points embedded in 6-D).
#[test]
fn vertices_equal_the_exact_extreme_points() {
    use crate::support::exact_lp::exact_ray_exit;
    use num_bigint::BigInt;
    fn run<const D: usize>(seed: u64, n: usize) -> bool {
        let mut rng = pqhull::geometry::Rng::new(seed);
        let points: Vec<[f64; D]> = (0..n)
            .map(|i| {
                let mut p: [f64; D] = std::array::from_fn(|_| rng.index(4) as f64);
                if i % 3 == 0 {
                    p[rng.index(D)] = if rng.index(2) == 0 { 0.0 } else { 3.0 };
                }
                p
            })
            .collect();
        let Ok(hull) = Hull::try_new(&points) else {
            return false; // flat or too few distinct points: nothing to compare
        };
        hull.check().unwrap();
        let mut extreme = Vec::new();
        for (i, p) in points.iter().enumerate() {
            // Repeats of an earlier point are not vertices (first copies are).
            if points[..i].contains(p) {
                continue;
            }
            let others: Vec<[BigInt; 6]> = points
                .iter()
                .filter(|q| *q != p)
                .map(|q| {
                    std::array::from_fn(|c| {
                        BigInt::from(if c < D { (q[c] - p[c]) as i64 } else { 0 })
                    })
                })
                .collect();
            // The origin is in their hull exactly when the line through it along an axis meets
            // the hull on both sides of it (or at it): both rays' programs are feasible.
            let axis = |s: i64| -> [BigInt; 6] {
                std::array::from_fn(|c| BigInt::from(if c == 0 { s } else { 0 }))
            };
            let inside = exact_ray_exit(&others, &axis(1)).is_some()
                && exact_ray_exit(&others, &axis(-1)).is_some();
            if !inside {
                extreme.push(i);
            }
        }
        assert_eq!(hull.vertex_indices(), extreme, "{D}-D, seed {seed}");
        two_phases(&hull)
    }
    let mut second_phases = 0;
    for seed in 0..6 {
        second_phases += usize::from(run::<3>(seed, 40));
        second_phases += usize::from(run::<4>(seed + 10, 40));
        second_phases += usize::from(run::<5>(seed + 20, 40));
        second_phases += usize::from(run::<6>(seed + 30, 40));
    }
    eprintln!("{second_phases} of 24 builds ran a second phase");
    assert!(second_phases >= 3, "{second_phases} second phases");
}
