//! `strategy::penetration_depth` against references built here on every pairwise difference:
//! an exact brute force on integer bodies (every supporting hyperplane through D differences,
//! in integers; the outside distance by Wolfe's algorithm in rationals, `support/min_norm.rs`),
//! and Qhull's hull of the differences on real-valued bodies (feature `qhull`).

use super::support::brute_inside::brute_force_inside;
use super::support::min_norm::exact_min_norm_distance;
use super::support::points_as_vecs;
use pqhull::geometry::Rng;
use pqhull::strategy::{Body, PenetrationError, Relation, penetration_depth};

/// Every difference `a_i − b_j`, rounded as `f64` computes it.
fn differences<const D: usize>(a: &[[f64; D]], b: &[[f64; D]]) -> Vec<[f64; D]> {
    a.iter()
        .flat_map(|p| b.iter().map(move |q| std::array::from_fn(|c| p[c] - q[c])))
        .collect()
}

/// The exact depth of the integer bodies `a`, `b`: brute force inside, minus Wolfe's exact
/// distance outside.
fn integer_reference<const D: usize>(a: &[[f64; D]], b: &[[f64; D]]) -> f64 {
    let diffs = differences(a, b);
    match brute_force_inside(&diffs) {
        Some(depth) => depth,
        None => -exact_min_norm_distance(&points_as_vecs(&diffs), &[0.0; D]),
    }
}

fn integer_body<const D: usize>(rng: &mut Rng, count: usize, span: i64) -> Vec<[f64; D]> {
    (0..count)
        .map(|_| std::array::from_fn(|_| (rng.below(2 * span as u64 + 1) as i64 - span) as f64))
        .collect()
}

/// Integer bodies, moved by integer offsets so that many overlap, many touch (a shared face,
/// edge or vertex: an exact zero) and many are apart: depth and relation exact.
fn check_integer_bodies<const D: usize>(cases: usize, seed: u64) {
    let mut rng = Rng::new(seed);
    let mut tally = [0usize; 3];
    for case in 0..cases {
        let (na, nb) = (D + 2 + rng.index(3), D + 2 + rng.index(3));
        let a = integer_body::<D>(&mut rng, na, 3);
        let mut b = integer_body::<D>(&mut rng, nb, 3);
        let shift: [f64; D] = std::array::from_fn(|_| (rng.below(7) as i64 - 3) as f64);
        if case % 4 == 0 {
            // B is A mirrored in the plane of A's highest point along an axis: they share
            // that face (or edge, or vertex) and touch.
            let k = rng.index(D);
            let high = a.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
            b = a.clone();
            for p in &mut b {
                p[k] = 2.0 * high - p[k];
            }
        } else {
            for p in &mut b {
                for c in 0..D {
                    p[c] += shift[c];
                }
            }
        }
        // Skip bodies whose difference is flat (the brute force needs a full-dimensional one).
        let diffs = differences(&a, &b);
        if pqhull::Hull::try_new(&diffs).is_err() {
            continue;
        }
        let expected = integer_reference(&a, &b);
        let got = penetration_depth(&a, &b).unwrap();
        assert_eq!(
            got.rounding, 0.0,
            "case {case}: integer differences are exact"
        );
        let relation = if expected > 0.0 {
            Relation::Overlapping
        } else if expected < 0.0 {
            Relation::Separated
        } else {
            Relation::Touching
        };
        tally[relation as usize] += 1;
        assert_eq!(
            got.relation, relation,
            "D = {D}, case {case}: {a:?} {b:?}: {got:?}, exact {expected}"
        );
        let error = (got.depth - expected).abs();
        assert!(
            error <= 4.0 * f64::EPSILON * expected.abs(),
            "D = {D}, case {case}: depth {} against the exact {expected} ({a:?}, {b:?})",
            got.depth
        );
        if expected == 0.0 {
            assert_eq!(got.depth, 0.0, "touching is exactly 0");
        }
    }
    // The families must exercise every relation.
    assert!(
        tally.iter().all(|&n| n >= cases / 20),
        "D = {D}: overlapping, touching, separated = {tally:?}"
    );
}

#[test]
fn integer_bodies_in_2d_match_the_exact_brute_force() {
    check_integer_bodies::<2>(300, 1);
}

#[test]
fn integer_bodies_in_3d_match_the_exact_brute_force() {
    check_integer_bodies::<3>(200, 2);
}

#[test]
fn integer_bodies_in_4d_match_the_exact_brute_force() {
    check_integer_bodies::<4>(40, 3);
}

fn cube<const D: usize>(offset: [f64; D]) -> Vec<[f64; D]> {
    (0..1usize << D)
        .map(|i| std::array::from_fn(|c| ((i >> c) & 1) as f64 + offset[c]))
        .collect()
}

/// Unit cubes overlapping by 0.25 along one axis, from 2-D to 8-D (2^16 pairs in 8-D, never
/// materialised): the depth exactly 0.25, the translation along that axis.
#[test]
fn shifted_cubes_overlap_by_the_shift_in_every_dimension() {
    fn check<const D: usize>() {
        let mut shift = [0.1; D];
        shift[D - 1] = 0.75;
        let p = penetration_depth(&cube::<D>([0.0; D]), &cube::<D>(shift)).unwrap();
        assert_eq!(p.relation, Relation::Overlapping, "D = {D}");
        assert_eq!(p.depth, 0.25, "D = {D}");
        let mut expected = [0.0; D];
        expected[D - 1] = 0.25;
        assert_eq!(p.translation(), expected, "D = {D}");
        // Disjoint by 0.5 along the first axis.
        let mut apart = [0.0; D];
        apart[0] = 1.5;
        let q = penetration_depth(&cube::<D>([0.0; D]), &cube::<D>(apart)).unwrap();
        assert_eq!(q.relation, Relation::Separated, "D = {D}");
        assert!((q.depth + 0.5).abs() <= 1e-15, "D = {D}: {}", q.depth);
        // Sharing a face: exactly touching.
        apart[0] = 1.0;
        let t = penetration_depth(&cube::<D>([0.0; D]), &cube::<D>(apart)).unwrap();
        assert_eq!((t.relation, t.depth), (Relation::Touching, 0.0), "D = {D}");
    }
    check::<2>();
    check::<3>();
    check::<4>();
    check::<5>();
    check::<6>();
    check::<7>();
    check::<8>();
}

fn sphere_body<const D: usize>(
    rng: &mut Rng,
    count: usize,
    centre: [f64; D],
    radius: f64,
) -> Vec<[f64; D]> {
    (0..count)
        .map(|_| {
            let u = rng.unit_vector(D);
            std::array::from_fn(|c| centre[c] + radius * u[c])
        })
        .collect()
}

/// Real-valued bodies: the translation the answer names makes them touch (within the promised
/// accuracy), the answer is symmetric, and separated bodies' depth is minus Wolfe's exact
/// distance over every rounded difference.
#[test]
fn translation_touches_and_swapping_the_bodies_negates_the_direction() {
    fn check<const D: usize>(seed: u64) {
        let mut rng = Rng::new(seed);
        for case in 0..20 {
            let a = sphere_body::<D>(&mut rng, 30, [0.0; D], 1.0);
            let centre: [f64; D] = std::array::from_fn(|_| rng.uniform_in(-1.5, 1.5));
            let b = sphere_body::<D>(&mut rng, 25, centre, 0.7);
            let p = penetration_depth(&a, &b).unwrap();
            assert!(p.rounding > 0.0 && p.rounding < 1e-15 * p.scale);
            let q = penetration_depth(&b, &a).unwrap();
            let tolerance = 1e-12 * p.depth.abs() + 2e-15 * p.scale;
            assert!(
                (p.depth - q.depth).abs() <= tolerance,
                "D = {D}, case {case}"
            );
            for c in 0..D {
                assert!(
                    (p.direction[c] + q.direction[c]).abs() < 1e-9,
                    "D = {D}, case {case}"
                );
            }
            let t = p.translation();
            let moved: Vec<[f64; D]> = b
                .iter()
                .map(|x| std::array::from_fn(|c| x[c] + t[c]))
                .collect();
            let touching = penetration_depth(&a, &moved).unwrap();
            assert!(
                touching.depth.abs() <= 1e-12 * p.depth.abs() + 1e-14 * p.scale,
                "D = {D}, case {case}: depth {} moved by its translation leaves {}",
                p.depth,
                touching.depth
            );
            if p.depth < 0.0 {
                let diffs = differences(&a, &b);
                let exact = exact_min_norm_distance(&points_as_vecs(&diffs), &[0.0; D]);
                assert!(
                    (p.depth + exact).abs() <= 1e-12 * exact + 2e-15 * p.scale,
                    "D = {D}, case {case}: {} against −{exact}",
                    p.depth
                );
            }
        }
    }
    check::<2>(11);
    check::<3>(12);
    check::<5>(13);
}

/// Bodies whose difference is flat — polygons in one plane of 3-D, in parallel planes — go
/// through the materialised fallback: their interiors cannot overlap.
#[test]
fn flat_differences_touch_or_are_apart() {
    let square = |x: f64, z: f64| {
        vec![
            [x, 0.0, z],
            [x + 1.0, 0.0, z],
            [x + 1.0, 1.0, z],
            [x, 1.0, z],
        ]
    };
    let overlapping = penetration_depth(&square(0.0, 0.0), &square(0.5, 0.0)).unwrap();
    assert_eq!(
        (overlapping.relation, overlapping.depth),
        (Relation::Touching, 0.0)
    );
    assert!(
        overlapping.direction[2].abs() > 0.999_999,
        "{overlapping:?}"
    );
    let apart = penetration_depth(&square(0.0, 0.0), &square(3.0, 0.0)).unwrap();
    assert_eq!((apart.relation, apart.depth), (Relation::Separated, -2.0));
    let parallel = penetration_depth(&square(0.0, 0.0), &square(0.5, 1.0)).unwrap();
    assert_eq!(
        (parallel.relation, parallel.depth),
        (Relation::Separated, -1.0)
    );
    // B is above A: moving it down by 1 (depth −1 times the direction) makes them touch.
    assert_eq!(parallel.direction, [0.0, 0.0, 1.0]);
    assert_eq!(parallel.translation(), [0.0, 0.0, -1.0]);
}

#[test]
fn bad_bodies_are_refused_with_the_body_and_vertex() {
    let a = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    assert_eq!(
        penetration_depth(&a, &[]).unwrap_err(),
        PenetrationError::Empty { body: Body::B }
    );
    let nan = [[0.0, 0.0], [1.0, f64::NAN]];
    let e = penetration_depth(&nan, &a).unwrap_err();
    assert_eq!(
        e,
        PenetrationError::NonFinite {
            body: Body::A,
            index: 1,
            coordinate: 1
        }
    );
    assert!(e.to_string().contains("vertex 1 of body a"), "{e}");
    let far = [[f64::MAX, 0.0], [f64::MAX, 1.0], [f64::MAX / 2.0, 0.0]];
    let near = [[-f64::MAX, 0.0], [-f64::MAX, 1.0], [-f64::MAX / 2.0, 0.0]];
    assert_eq!(
        penetration_depth(&far, &near).unwrap_err(),
        PenetrationError::DifferenceOverflow { coordinate: 0 }
    );
}

/// Real-valued bodies against Qhull's hull of every difference: the smallest facet offset when
/// the origin is inside (Qhull's planes, floating point), minus Wolfe's exact distance when not.
#[cfg(feature = "qhull")]
#[test]
fn real_bodies_match_qhull_on_every_difference() {
    use pqhull::qhull_baseline::qhull_full_hull;
    fn check<const D: usize>(seed: u64, cases: usize) {
        let mut rng = Rng::new(seed);
        let mut inside = 0;
        for case in 0..cases {
            let a = sphere_body::<D>(&mut rng, 12, [0.0; D], 1.0);
            // Half of them overlap: the centre's norm about the sum of the radii.
            let reach = 2.2 / D as f64;
            let centre: [f64; D] = std::array::from_fn(|_| rng.uniform_in(-reach, reach));
            let radius = rng.uniform_in(0.2, 1.0);
            let b = sphere_body::<D>(&mut rng, 10, centre, radius);
            let diffs = differences(&a, &b);
            let qh = qhull_full_hull(&diffs).unwrap();
            let offset = qh
                .facets
                .iter()
                .map(|f| f.offset)
                .fold(f64::NEG_INFINITY, f64::max);
            let got = penetration_depth(&a, &b).unwrap();
            let reference = if offset < -1e-9 {
                inside += 1;
                -offset
            } else {
                -exact_min_norm_distance(&points_as_vecs(&diffs), &[0.0; D])
            };
            // Qhull's planes are floating point: a few ulps of the scale.
            let tolerance = 1e-12 * reference.abs() + 1e-14 * got.scale;
            assert!(
                (got.depth - reference).abs() <= tolerance,
                "D = {D}, case {case}: {} against {reference}",
                got.depth
            );
        }
        assert!(
            inside >= cases / 10 && inside <= cases - cases / 10,
            "D = {D}: {inside} inside"
        );
    }
    check::<2>(21, 60);
    check::<3>(22, 60);
    check::<4>(23, 40);
    check::<5>(24, 20);
    check::<6>(25, 10);
}
