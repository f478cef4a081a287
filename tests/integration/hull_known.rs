//! Known answers, errors and degenerate inputs of `Hull<D>`.

use super::monotone_chain::monotone_chain;
use super::support::brute_inside::{brute_force_inside, integer_normal};
use pqhull::geometry::Rng;
use pqhull::hull::{Partition, StrategyHooks};
use pqhull::predicates::{Sign, orientation};
use pqhull::{ClosestToOrigin, Hull, HullError, Step, Strategy};

/// Corners of [0, 1]^D.
fn cube<const D: usize>() -> Vec<[f64; D]> {
    (0..1usize << D)
        .map(|m| std::array::from_fn(|c| ((m >> c) & 1) as f64))
        .collect()
}

#[test]
fn cube_corners_with_interior_and_face_points() {
    fn run<const D: usize>() {
        let mut points = cube::<D>();
        let corners = points.len();
        points.push([0.5; D]); // centre
        let mut face = [0.5; D];
        face[0] = 1.0; // centre of a face: coplanar with a facet
        points.push(face);
        points.extend(cube::<D>()); // every corner twice
        let hull = Hull::try_new(&points).unwrap();
        hull.check().unwrap();
        let vertices = hull.vertex_indices();
        assert_eq!(
            vertices.len(),
            corners,
            "D={D}: duplicates or face points became vertices"
        );
        assert!(
            (hull.volume() - 1.0).abs() < 1e-12,
            "D={D}: volume {}",
            hull.volume()
        );
        // Every corner of the cube appears, once (either copy may be the one kept).
        let mut seen: Vec<[f64; D]> = vertices.iter().map(|&v| points[v]).collect();
        seen.sort_by(|a, b| a.partial_cmp(b).unwrap());
        seen.dedup();
        assert_eq!(seen.len(), corners);
        // Distance from the centre to the boundary is 1/2.
        let (_, r) = Hull::try_with_strategy(&points, ClosestToOrigin::towards([0.5; D])).unwrap();
        assert!((r.signed_distance - 0.5).abs() < 1e-15);
    }
    run::<2>();
    run::<3>();
    run::<4>();
    run::<5>();
    run::<6>();
}

#[test]
fn simplex_volume_is_one_over_d_factorial() {
    fn run<const D: usize>() {
        let mut points = vec![[0.0; D]];
        for i in 0..D {
            let mut e = [0.0; D];
            e[i] = 1.0;
            points.push(e);
        }
        let hull = Hull::try_new(&points).unwrap();
        hull.check().unwrap();
        let factorial: f64 = (1..=D).map(|k| k as f64).product();
        assert!((hull.volume() - 1.0 / factorial).abs() < 1e-15);
        assert_eq!(hull.facet_count(), D + 1);
    }
    run::<2>();
    run::<3>();
    run::<4>();
    run::<5>();
    run::<6>();
    run::<7>();
    run::<8>();
}

/// Brute force: a D-subset is a facet iff every other point lies strictly on one side of it.
fn brute_force_facets<const D: usize>(points: &[[f64; D]]) -> Vec<Vec<usize>> {
    let n = points.len();
    let mut found = Vec::new();
    let mut subset: Vec<usize> = (0..D).collect();
    loop {
        let vertices: [[f64; D]; D] = std::array::from_fn(|k| points[subset[k]]);
        let mut signs = (0..n)
            .filter(|i| !subset.contains(i))
            .map(|i| orientation(&vertices, &points[i]));
        let first = signs.next().unwrap();
        if first != Sign::Zero && signs.all(|s| s == first) {
            found.push(subset.clone());
        }
        // Next combination.
        let mut k = D;
        while k > 0 && subset[k - 1] == n - D + k - 1 {
            k -= 1;
        }
        if k == 0 {
            break;
        }
        subset[k - 1] += 1;
        for j in k..D {
            subset[j] = subset[j - 1] + 1;
        }
    }
    found.sort();
    found
}

#[test]
fn facets_match_brute_force_in_general_position() {
    fn run<const D: usize>(n: usize, seeds: u64) {
        for seed in 0..seeds {
            let points = pqhull::rbox::generate::<D>(&pqhull::rbox::Family::UniformCube, n, seed);
            let hull = Hull::try_new(&points).unwrap();
            let mut facets: Vec<Vec<usize>> = hull
                .facets()
                .map(|(_, f)| {
                    let mut v = f.vertices().to_vec();
                    v.sort();
                    v
                })
                .collect();
            facets.sort();
            assert_eq!(facets, brute_force_facets(&points), "D={D} seed={seed}");
        }
    }
    run::<2>(12, 20);
    run::<3>(12, 20);
    run::<4>(11, 10);
    run::<5>(10, 5);
}

#[test]
fn errors_name_what_is_wrong() {
    assert_eq!(
        Hull::<3>::try_new(&[[0.0; 3]; 3]).unwrap_err(),
        HullError::TooFewPoints { needed: 4, got: 3 }
    );
    let mut points = cube::<3>();
    points[5][2] = f64::NAN;
    assert_eq!(
        Hull::try_new(&points).unwrap_err(),
        HullError::NonFinite {
            index: 5,
            coordinate: 2
        }
    );
    points[5][2] = f64::NEG_INFINITY;
    assert_eq!(
        Hull::try_new(&points).unwrap_err(),
        HullError::NonFinite {
            index: 5,
            coordinate: 2
        }
    );
    // Rank 0, 1, 2 in 3-D.
    let same = vec![[1.5, -2.0, 3.0]; 10];
    assert_eq!(
        Hull::try_new(&same).unwrap_err(),
        HullError::AffinelyDependent {
            rank: 0,
            dimension: 3
        }
    );
    let line: Vec<[f64; 3]> = (0..10)
        .map(|i| [i as f64 * 0.1, 2.0 * i as f64 * 0.1, 3.0])
        .collect();
    assert_eq!(
        Hull::try_new(&line).unwrap_err(),
        HullError::AffinelyDependent {
            rank: 1,
            dimension: 3
        }
    );
    let plane: Vec<[f64; 3]> = (0..30)
        .map(|i| {
            // Dyadic coordinates: the plane z = x − 2y + 1 holds them exactly.
            let (x, y) = ((i % 6) as f64 * 0.25, (i / 6) as f64 * 0.5);
            [x, y, x - 2.0 * y + 1.0]
        })
        .collect();
    assert_eq!(
        Hull::try_new(&plane).unwrap_err(),
        HullError::AffinelyDependent {
            rank: 2,
            dimension: 3
        }
    );
    // A 5-D set lying in a 4-D hyperplane.
    let flat: Vec<[f64; 5]> = (0..40)
        .map(|i| {
            let t = i as f64;
            [t.sin(), t.cos(), (2.0 * t).sin(), (3.0 * t).cos(), 0.0]
        })
        .collect();
    assert_eq!(
        Hull::try_new(&flat).unwrap_err(),
        HullError::AffinelyDependent {
            rank: 4,
            dimension: 5
        }
    );
    // Messages say what and where.
    let message = HullError::NonFinite {
        index: 5,
        coordinate: 2,
    }
    .to_string();
    assert!(
        message.contains("point 5") && message.contains("coordinate 2"),
        "{message}"
    );
}

#[test]
fn huge_and_tiny_coordinates_scale_exactly() {
    fn run<const D: usize>() {
        let base = pqhull::rbox::generate::<D>(&pqhull::rbox::Family::SphereSurface, 60, 7);
        let reference = Hull::try_new(&base).unwrap();
        for factor in [1e-200, 1e-30, 1e30, 1e200] {
            let scaled: Vec<[f64; D]> = base.iter().map(|p| p.map(|x| x * factor)).collect();
            let hull = Hull::try_new(&scaled).unwrap();
            hull.check().unwrap();
            assert_eq!(
                hull.vertex_indices(),
                reference.vertex_indices(),
                "factor {factor}"
            );
            let expected = reference.volume() * factor.powi(D as i32);
            if expected.is_normal() {
                assert!(
                    (hull.volume() / expected - 1.0).abs() < 1e-9,
                    "factor {factor}"
                );
            }
        }
    }
    run::<2>();
    run::<3>();
    run::<4>();
}

#[test]
fn nearly_coincident_points_and_one_ulp_moves() {
    // A square whose edge midpoints are moved in or out by one ulp: exactly decided.
    let mut points = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    points.push([0.5, f64::next_down(0.0)]); // one ulp below the bottom edge: a vertex
    points.push([f64::next_down(1.0), 0.5]); // one ulp inside the right edge: not a vertex
    points.push([0.5, 1.0]); // on the top edge: not a vertex
    let hull = Hull::try_new(&points).unwrap();
    hull.check().unwrap();
    assert_eq!(hull.vertex_indices(), vec![0, 1, 2, 3, 4]);
}

#[test]
fn closest_to_origin_outside_and_on_boundary() {
    // Unit cube [0,1]^3: from (2, 0.5, 0.5) the distance is 1, from (2, 2, 0.5) it is √2 (edge),
    // from (2, 2, 2) it is √3 (corner) — the facet-plane rule would give 1 in every case.
    let points = cube::<3>();
    for (q, d) in [
        ([2.0, 0.5, 0.5], 1.0),
        ([2.0, 2.0, 0.5], 2f64.sqrt()),
        ([2.0, 2.0, 2.0], 3f64.sqrt()),
        ([1.0, 0.5, 0.5], 0.0),
        ([1.0, 1.0, 1.0], 0.0),
    ] {
        let (partial, r) = Hull::try_with_strategy(&points, ClosestToOrigin::towards(q)).unwrap();
        partial.check().unwrap();
        assert!(
            (r.signed_distance + d).abs() < 1e-15,
            "q={q:?}: {}",
            r.signed_distance
        );
        let gap: f64 = r
            .nearest_point
            .iter()
            .zip(&q)
            .map(|(a, b)| (a - b) * (a - b))
            .sum::<f64>()
            .sqrt();
        assert!((gap - d).abs() < 1e-15);
    }
}

/// `ClosestToOrigin` as it is, except that it partitions to the farthest facet (its own choice
/// until the query is inside the partial hull): a public-hook wrapper that sets
/// `Partition::Farthest` before each of its steps.
struct FarthestPartition<const D: usize>(ClosestToOrigin<D>);

impl<const D: usize> Strategy<D> for FarthestPartition<D> {
    type Output = <ClosestToOrigin<D> as Strategy<D>>::Output;
    fn start(&mut self, hull: &Hull<D>) {
        self.0.start(hull);
    }
    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        hull.set_partition(Partition::Farthest);
        self.0.step(hull)
    }
    fn finish(self, hull: &Hull<D>) -> Self::Output {
        self.0.finish(hull)
    }
    fn partitions_to_farthest(&self) -> bool {
        true
    }
}

/// The partition changes the work, not the answer: on integer point sets holding the origin,
/// `ClosestToOrigin` (which partitions nearest the query first once the query is inside) and
/// the same with the farthest partition both give the exact distance of a brute force over
/// every supporting hyperplane (in integers), and their hulls pass `Hull::check`. (On sets this
/// small the expansions no longer depend on the partition: each adds the support point of its
/// facet among all the points, `StrategyHooks::expand_to_support`; the partition decides where
/// the other points wait, and what the assignment costs.)
#[test]
fn the_partition_does_not_change_the_brute_force_distance() {
    fn run<const D: usize>(seed: u64, count: usize, radius: u64) -> usize {
        let mut inside = 0;
        let mut rng = Rng::new(seed);
        for case in 0..24 {
            // Integer points in a shell of radii 0.9·R to R, off-centre by a few percent (so
            // that the nearest facet is not found at once): most are hull vertices. R is large
            // enough that the set is not a certified exact grid (see `ExactGrid`), on which
            // the engine always partitions to the farthest facet.
            let mut points: Vec<[f64; D]> = Vec::with_capacity(count);
            while points.len() < count {
                let p: [f64; D] =
                    std::array::from_fn(|_| rng.below(2 * radius + 1) as f64 - radius as f64);
                let r2: f64 = p.iter().map(|c| c * c).sum();
                let r = radius as f64;
                if (0.81 * r * r..=r * r).contains(&r2) {
                    points.push(std::array::from_fn(|c| {
                        p[c] + ((c as f64 + 1.0) * r / 32.0).round()
                    }));
                }
            }
            let Some(exact) = brute_force_inside(&points) else {
                continue; // the origin outside or on the boundary
            };
            if exact == 0.0 {
                continue;
            }
            inside += 1;
            let (hull, first) =
                Hull::try_with_strategy(&points, ClosestToOrigin::new()).expect("full-dimensional");
            hull.check().unwrap();
            let strategy = FarthestPartition(ClosestToOrigin::new());
            let (hull, farthest) = Hull::try_with_strategy(&points, strategy).unwrap();
            hull.check().unwrap();
            // Far from the boundary the inside distance is the floating-point normal's (its
            // documented accuracy: 1e−11 relative; a wrong facet is off by far more here).
            for (name, r) in [("farthest", &farthest), ("nearest first", &first)] {
                assert!(
                    (r.signed_distance - exact).abs() <= 1e-11 * exact,
                    "{D}-D case {case}, {name}: {} against {exact}",
                    r.signed_distance
                );
            }
        }
        inside
    }
    let runs = [
        run::<3>(1, 60, 1 << 16),
        run::<4>(2, 40, 1 << 12),
        run::<5>(3, 24, 1 << 10),
    ];
    for inside in runs {
        assert!(inside >= 15, "only {inside} sets held the origin");
    }
}

/// `StrategyHooks::expand_to_support` adds, at every step, a point farthest beyond the facet
/// among *all* the input points (heights in integers), wherever the partition filed it; the
/// hull it grows is checked and has the full hull's vertices.
#[test]
fn expansion_to_support_adds_the_farthest_of_all_points() {
    /// The first facet with outside points, expanded by its support point; per step, whether
    /// the point added was as high as the highest input point, and whether the facet's own
    /// outside set held it.
    struct Support<const D: usize> {
        integers: Vec<[i128; D]>,
        steps: usize,
        taken_elsewhere: usize,
    }
    impl<const D: usize> Strategy<D> for Support<D> {
        type Output = (usize, usize);
        fn start(&mut self, _: &Hull<D>) {}
        fn step(&mut self, hull: &mut Hull<D>) -> Step {
            hull.set_partition(Partition::FirstFound);
            let Some((id, facet)) = hull.facets().find(|(_, f)| f.outside_len() > 0) else {
                return Step::Stop;
            };
            let p = &self.integers;
            let vertices = facet.vertices();
            let normal = integer_normal(p, &vertices);
            let height = |x: &[i128; D]| {
                (0..D)
                    .map(|c| normal[c] * (x[c] - p[vertices[0]][c]))
                    .sum::<i128>()
            };
            // Oriented by a point of the outside set (strictly beyond the facet).
            let orientation = height(&p[facet.outside_set().next().unwrap()]).signum();
            let highest = p.iter().map(|x| orientation * height(x)).max().unwrap();
            let own: Vec<usize> = facet.outside_set().collect();
            assert!(hull.expand_to_support(id));
            // The apex is the one vertex every new facet has.
            let created = hull.last_created();
            let apex = hull
                .facet(created[0])
                .vertices()
                .into_iter()
                .find(|v| {
                    created
                        .iter()
                        .all(|&c| hull.facet(c).vertices().contains(v))
                })
                .expect("the new facets share their apex");
            assert_eq!(
                orientation * height(&p[apex]),
                highest,
                "step {}",
                self.steps
            );
            self.steps += 1;
            if !own.contains(&apex) {
                self.taken_elsewhere += 1;
            }
            Step::Continue
        }
        fn finish(self, _: &Hull<D>) -> (usize, usize) {
            (self.steps, self.taken_elsewhere)
        }
    }
    // Coordinates wide enough that no set is a certified exact grid (where the partition is
    // always the farthest), small enough for the heights in `i128`.
    fn run<const D: usize>(seed: u64, count: usize, radius: u64) -> usize {
        let mut rng = Rng::new(seed);
        let mut elsewhere = 0;
        for _ in 0..8 {
            let integers: Vec<[i128; D]> = (0..count)
                .map(|_| {
                    std::array::from_fn(|_| rng.below(2 * radius + 1) as i128 - radius as i128)
                })
                .collect();
            let points: Vec<[f64; D]> = integers.iter().map(|x| x.map(|c| c as f64)).collect();
            let strategy = Support {
                integers,
                steps: 0,
                taken_elsewhere: 0,
            };
            let (hull, (steps, taken)) = Hull::try_with_strategy(&points, strategy).unwrap();
            hull.check().unwrap();
            let mut vertices = hull.vertex_indices();
            let mut full = Hull::try_new(&points).unwrap().vertex_indices();
            vertices.sort_unstable();
            full.sort_unstable();
            assert_eq!(vertices, full);
            assert!(steps > 0);
            elsewhere += taken;
        }
        elsewhere
    }
    let elsewhere = [
        run::<3>(11, 200, 1 << 20),
        run::<4>(12, 120, 1 << 16),
        run::<6>(13, 60, 1000),
    ];
    eprintln!("points taken from another facet's outside set: {elsewhere:?}");
    assert!(elsewhere.iter().all(|&n| n > 0), "{elsewhere:?}");
}

#[test]
fn partial_hull_does_less_work_on_a_sphere() {
    let points = pqhull::rbox::generate::<6>(&pqhull::rbox::Family::SphereSurface, 400, 3);
    let full = Hull::try_new(&points).unwrap();
    let (_, r) = Hull::try_with_strategy(&points, ClosestToOrigin::new()).unwrap();
    // 4.6× fewer facets here (it was over 5×): since `claim_beyond` claims only the points of
    // the nearest rings of facets that hold any, the point added is the farthest of those rather
    // than of all, which costs a few facets and saves a scan of every outside set per claim
    // (3.9× faster than the full hull on 10k points, where it used to be slower).
    assert!(
        r.stats.facets_created * 4 < full.stats().facets_created,
        "{:?} vs {:?}",
        r.stats,
        full.stats()
    );
    assert!(r.stats.points_processed < full.stats().points_processed);
}

#[test]
fn sliver_facets_get_finite_normals() {
    // Nearly (not exactly) coplanar: rounding of 0.25x − 0.5y + 1 lifts some points by an ulp, so
    // the hull is a genuine sliver whose facets have cofactors that cancel to zero in floating
    // point. Their normals must still be finite unit vectors.
    let points: Vec<[f64; 3]> = (0..30)
        .map(|i| {
            let (x, y) = ((i % 6) as f64 * 0.3, (i / 6) as f64 * 0.7);
            [x, y, 0.25 * x - 0.5 * y + 1.0]
        })
        .collect();
    let hull = Hull::try_new(&points).unwrap();
    hull.check().unwrap();
    for (_, f) in hull.facets() {
        assert!(f.normal().iter().all(|c| c.is_finite()) && f.offset().is_finite());
    }
}

/// A hull rebuilt in place (reused arena) equals a fresh one, also after a failed rebuild.
#[test]
fn rebuilt_hulls_equal_fresh_ones() {
    use pqhull::rbox::{Family, generate};
    use pqhull::{ClosestToOrigin, FarthestPoint, HullError};

    fn facets<const D: usize>(hull: &Hull<D>) -> Vec<[usize; D]> {
        let mut f: Vec<[usize; D]> = hull.facets().map(|(_, f)| f.vertices()).collect();
        f.sort_unstable();
        f
    }

    let mut reused: Option<Hull<6>> = None;
    let mut strategy = ClosestToOrigin::new();
    for (round, family) in [
        Family::SphereSurface,
        Family::UniformCube,
        Family::CubeCornersDiamond,
        Family::SphereSurface,
    ]
    .iter()
    .enumerate()
    {
        let points = generate::<6>(family, 150 + 40 * round, round as u64);
        let fresh = Hull::try_new(&points).unwrap();
        let (_, expected) = Hull::try_with_strategy(&points, ClosestToOrigin::new()).unwrap();
        match reused.as_mut() {
            None => reused = Some(Hull::try_new(&points).unwrap()),
            Some(hull) => {
                hull.rebuild_with_strategy(&points, FarthestPoint::new())
                    .unwrap();
            }
        }
        let hull = reused.as_mut().unwrap();
        hull.check().unwrap();
        assert_eq!(facets(hull), facets(&fresh), "round {round}");
        assert_eq!(hull.stats().facets_created, fresh.stats().facets_created);
        assert!((hull.volume() - fresh.volume()).abs() <= 1e-12 * fresh.volume());
        // The partial strategy, reused too.
        let got = hull.rebuild_with_strategy(&points, &mut strategy).unwrap();
        assert_eq!(
            got.signed_distance, expected.signed_distance,
            "round {round}"
        );
        hull.check().unwrap();
        // A failed rebuild leaves an empty hull that can be rebuilt again.
        let flat: Vec<[f64; 6]> = points
            .iter()
            .map(|p| [p[0], p[1], 0.0, 0.0, 0.0, 0.0])
            .collect();
        let error = hull
            .rebuild_with_strategy(&flat, FarthestPoint::new())
            .unwrap_err();
        assert!(matches!(error, HullError::AffinelyDependent { .. }));
        assert_eq!(hull.facet_count(), 0);
    }
}

/// Issue 12, item 4: repeated points cost nothing. Each point listed r times (copies scattered
/// through the input) gives the facets of the brute force on the distinct points, and the same
/// work as the input without repeats: only the first copy of a point enters an outside set.
#[test]
fn repeated_points_are_merged() {
    fn run<const D: usize>(n: usize, seed: u64, r: usize) {
        let distinct = pqhull::rbox::generate::<D>(&pqhull::rbox::Family::UniformCube, n, seed);
        // Copy c of point i at position c·n + i: copies are n apart.
        let repeated: Vec<[f64; D]> = (0..r).flat_map(|_| distinct.iter().copied()).collect();
        let canonical = |facets: Vec<Vec<usize>>| {
            let mut facets: Vec<Vec<usize>> = facets
                .into_iter()
                .map(|f| {
                    let mut f: Vec<usize> = f.into_iter().map(|v| v % n).collect();
                    f.sort();
                    f
                })
                .collect();
            facets.sort();
            facets
        };
        let once = Hull::try_new(&distinct).unwrap();
        for strategy in [false, true] {
            let hull = if strategy {
                Hull::try_with_strategy(&repeated, ClosestToOrigin::towards([0.0; D]))
                    .unwrap()
                    .0
            } else {
                Hull::try_new(&repeated).unwrap()
            };
            hull.check().unwrap();
            if !strategy {
                let facets = hull.facets().map(|(_, f)| f.vertices().to_vec()).collect();
                let what = format!("D={D} seed={seed} r={r}");
                assert_eq!(canonical(facets), brute_force_facets(&distinct), "{what}");
                assert!(hull.vertex_indices().iter().all(|&v| v < n), "{what}");
                let (a, b) = (once.stats(), hull.stats());
                assert_eq!(
                    (a.points_processed, a.facets_created, a.expansions),
                    (b.points_processed, b.facets_created, b.expansions),
                    "{what}"
                );
            }
        }
    }
    for seed in 0..5 {
        run::<2>(12, seed, 7);
        run::<3>(12, seed, 4);
        run::<4>(11, seed, 3);
    }
    // A 6-D Gaussian cloud of 2,000 points listed 10 times took 7× as long as once before the
    // merge; the work is now identical.
    let cloud = pqhull::rbox::generate::<6>(&pqhull::rbox::Family::UniformCube, 400, 1);
    let tenfold: Vec<[f64; 6]> = (0..10).flat_map(|_| cloud.iter().copied()).collect();
    let (a, b) = (
        Hull::try_new(&cloud).unwrap(),
        Hull::try_new(&tenfold).unwrap(),
    );
    assert_eq!(a.vertex_indices(), b.vertex_indices());
    assert_eq!(a.stats().facets_created, b.stats().facets_created);
}

/// Repeated points on an input large enough (over 2^17 points) that the engine finds them
/// bucket by bucket, behind a table of recent points: the copies of a point scattered at
/// random through the input (most far apart, some adjacent), the vertices must be first copies
/// and the work that of the distinct points. The references are written here: each point's
/// first position by a scan, and the distinct points' hull vertices by Andrew's monotone chain
/// on `robust::orient2d` (Shewchuk's exact orientation, not the engine's).
#[test]
fn repeated_points_are_merged_on_large_inputs() {
    let distinct = pqhull::rbox::generate::<2>(&pqhull::rbox::Family::UniformCube, 30_000, 3);
    let mut rng = Rng::new(11);
    // Five copies of each point in a random order, and one more right after some of them.
    let mut order: Vec<usize> = (0..5 * distinct.len())
        .map(|k| k % distinct.len())
        .collect();
    for k in (1..order.len()).rev() {
        order.swap(k, rng.index(k + 1));
    }
    let mut listed = Vec::with_capacity(order.len() + order.len() / 7);
    for (k, &i) in order.iter().enumerate() {
        listed.push(i);
        if k % 7 == 0 {
            listed.push(i);
        }
    }
    assert!(listed.len() > 1 << 17);
    let points: Vec<[f64; 2]> = listed.iter().map(|&i| distinct[i]).collect();
    // Each distinct point's first position in `points`.
    let mut first = vec![usize::MAX; distinct.len()];
    for (position, &i) in listed.iter().enumerate() {
        first[i] = first[i].min(position);
    }
    let chain = monotone_chain(&distinct);
    let once = Hull::try_new(&distinct).unwrap();
    let hull = Hull::try_new(&points).unwrap();
    hull.check().unwrap();
    let mut expected: Vec<usize> = chain.iter().map(|&v| first[v]).collect();
    expected.sort_unstable();
    let mut found = hull.vertex_indices().to_vec();
    found.sort_unstable();
    assert_eq!(found, expected);
    let (a, b) = (once.stats(), hull.stats());
    assert_eq!(
        (a.points_processed, a.facets_created, a.expansions),
        (b.points_processed, b.facets_created, b.expansions)
    );
}

/// In the plane the initial triangle is widened to the polygon of the axis-extreme points
/// before the first partition (`Hull::widen_to_extremes`). Inputs where that step meets its
/// edge cases: extreme points repeated and tied along an axis, an extreme point exactly on an
/// edge of the triangle (not beyond it), extremes that are all on one line (a grid), a polygon
/// of four extremes, and the turned square whose sides are collinear only up to rounding. Each
/// hull's vertices must be the monotone chain's (exact orientation, written in the test), each
/// a first copy, and `Hull::check` must hold.
#[test]
fn the_initial_polygon_of_extreme_points_gives_the_exact_hull() {
    let mut rng = Rng::new(5);
    let mut cases: Vec<(&str, Vec<[f64; 2]>)> = Vec::new();
    // A square's corners, each listed three times, points on its edges (ties at every extreme
    // coordinate) and inside.
    let mut square = Vec::new();
    for _ in 0..3 {
        square.extend([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]);
    }
    for k in 0..40 {
        let t = -1.0 + k as f64 / 20.0;
        square.extend([[t, -1.0], [t, 1.0], [-1.0, t], [1.0, t]]);
        square.push([rng.uniform_in(-1.0, 1.0), rng.uniform_in(-1.0, 1.0)]);
    }
    cases.push(("square", square));
    // A diamond: four extremes, the polygon is the hull's quadrilateral itself.
    let mut diamond = vec![[0.0, -2.0], [2.0, 0.0], [0.0, 2.0], [-2.0, 0.0]];
    diamond.extend((0..200).map(|_| {
        let (a, b) = (rng.uniform_in(-1.0, 1.0), rng.uniform_in(-1.0, 1.0));
        [a + b, a - b]
    }));
    cases.push(("diamond", diamond));
    // A triangle whose lowest point (the first listed of the lowest, so the extreme taken) is
    // the middle of its bottom edge: on the line of the initial triangle's edge, not beyond it.
    let mut triangle = vec![[0.0, 0.0], [-4.0, 0.0], [4.0, 0.0], [0.0, 4.0], [0.5, 0.0]];
    triangle.extend((0..100).map(|_| {
        let y = rng.uniform_in(0.0, 2.0);
        [rng.uniform_in(-(4.0 - y) / 2.0, (4.0 - y) / 2.0), y]
    }));
    cases.push(("triangle", triangle));
    // Points on a parabola (every point a vertex), and a turned square's sides.
    cases.push((
        "parabola",
        (0..300)
            .map(|k| {
                let x = k as f64 / 299.0 * 2.0 - 1.0;
                [x, x * x]
            })
            .collect(),
    ));
    // A full grid listed row by row: every axis extreme (the first lowest, the last highest)
    // is on the diagonal between the first two vertices, so the third is found by the pass.
    cases.push((
        "grid",
        (0..900)
            .map(|i| [(i / 30) as f64, (i % 30) as f64])
            .collect(),
    ));
    for seed in [1, 2, 3] {
        cases.push((
            "tilted",
            pqhull::rbox::generate::<2>(&pqhull::rbox::Family::TiltedFaces, 2_000, seed),
        ));
    }
    for (name, points) in &cases {
        let hull = Hull::try_new(points).unwrap();
        hull.check().unwrap();
        assert_eq!(
            sorted_vertices(&hull, points, name),
            chain_vertices(points),
            "{name}"
        );
    }
}

/// The hull's vertices as sorted coordinates, each checked to be a first copy (`label` names
/// the case in the failure).
fn sorted_vertices(hull: &Hull<2>, points: &[[f64; 2]], label: &str) -> Vec<[f64; 2]> {
    let mut found: Vec<[f64; 2]> = hull
        .vertex_indices()
        .iter()
        .map(|&v| {
            assert!(
                points[..v].iter().all(|p| *p != points[v]),
                "{label}: vertex {v} is not a first copy"
            );
            points[v]
        })
        .collect();
    found.sort_by(|a, b| a.partial_cmp(b).unwrap());
    found
}

/// The monotone chain's vertices (the test's reference) as sorted coordinates.
fn chain_vertices(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut expected: Vec<[f64; 2]> = monotone_chain(points).iter().map(|&v| points[v]).collect();
    expected.sort_by(|a, b| a.partial_cmp(b).unwrap());
    expected
}

/// Random 2-D sets built to be degenerate: coordinates from a few small integers (ties among the
/// axis extremes, collinear runs on every edge, repeats), the same scaled by 0.1 (rounded: nearly
/// collinear instead of exactly) and turned by a small angle. The initial polygon of extremes,
/// its widening and the partition must give Andrew's monotone chain on `robust::orient2d`,
/// written in the test; a set on one line must be refused as flat.
#[test]
fn degenerate_plane_sets_give_the_monotone_chain() {
    let mut rng = Rng::new(24);
    let mut checked = 0;
    for case in 0..600 {
        let n = 3 + rng.below(60) as usize;
        let range = 2 + rng.below(6);
        let mut points: Vec<[f64; 2]> = (0..n)
            .map(|_| [rng.below(range) as f64, rng.below(range) as f64])
            .collect();
        match case % 3 {
            1 => points
                .iter_mut()
                .for_each(|p| *p = [p[0] * 0.1, p[1] * 0.1]),
            2 => {
                let (s, c) = (1e-3f64).sin_cos();
                points
                    .iter_mut()
                    .for_each(|p| *p = [c * p[0] - s * p[1], s * p[0] + c * p[1]]);
            }
            _ => {}
        }
        let expected = chain_vertices(&points);
        match Hull::try_new(&points) {
            Ok(hull) => {
                hull.check()
                    .unwrap_or_else(|e| panic!("case {case}: {e}: {points:?}"));
                assert_eq!(
                    sorted_vertices(&hull, &points, &format!("case {case}")),
                    expected,
                    "case {case}: {points:?}"
                );
                checked += 1;
            }
            Err(HullError::AffinelyDependent { .. }) => {
                assert!(expected.len() <= 2, "case {case}: refused {points:?}")
            }
            Err(e) => panic!("case {case}: {e}"),
        }
    }
    assert!(checked > 500, "only {checked} sets were full-dimensional");
}
