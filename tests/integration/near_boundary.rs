//! `ClosestToOrigin` for queries within rounding of the hull's boundary: the sign must be the
//! exact one and the magnitude accurate to 1e−12 of itself or 1e−15 of the input's scale,
//! checked against exact rational references (`tests/support/min_norm.rs`) that share no code
//! with the engine.

use crate::support::min_norm::{exact_distance_to_affine_hull, exact_min_norm_distance};
use pqhull::geometry::Rng;
use pqhull::predicates::Sign;
use pqhull::rbox::{self, Family};
use pqhull::{ClosestToOrigin, Hull};
use proptest::prelude::*;

fn signed_distance<const D: usize>(points: &[[f64; D]], query: [f64; D]) -> f64 {
    let (partial, result) =
        Hull::try_with_strategy(points, ClosestToOrigin::towards(query)).expect("hull");
    partial.check().expect("partial hull invariants");
    result.signed_distance
}

fn assert_ulps(got: f64, want: f64, ulps: f64) {
    assert!(
        (got - want).abs() <= ulps * f64::EPSILON * want.abs(),
        "got {got:e}, want {want:e}"
    );
}

/// The unit right triangle: its hypotenuse x + y = 1 passes through (0.5, 0.5), and the nearest
/// doubles on either side of it are 2^-54 below and 2^-53 above in y. The floating-point plane
/// distance of the inside one rounds to 0.
#[test]
fn triangle_hypotenuse_within_rounding() {
    let triangle = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    let tiny = 2f64.powi(-54);
    assert_eq!(signed_distance(&triangle, [0.5, 0.5]), 0.0);
    let inside = signed_distance(&triangle, [0.5, 0.5 - tiny]);
    assert_ulps(inside, tiny / 2f64.sqrt(), 4.0);
    let outside = signed_distance(&triangle, [0.5, 0.5 + 2.0 * tiny]);
    assert_ulps(outside, -2.0 * tiny / 2f64.sqrt(), 4.0);
    // A vertex and a point of an edge: on the boundary.
    assert_eq!(signed_distance(&triangle, [1.0, 0.0]), 0.0);
    assert_eq!(signed_distance(&triangle, [0.25, 0.0]), 0.0);
}

/// The same in 4-D, on the facet Σx = 1 of the unit simplex, and with a query off the vertices'
/// binary grid (0.1 + 0.2 + 0.3 + 0.4 is not 1 in binary), which takes the `BigInt` path.
#[test]
fn simplex_facet_within_rounding_4d() {
    let mut simplex = vec![[0.0; 4]];
    for i in 0..4 {
        let mut e = [0.0; 4];
        e[i] = 1.0;
        simplex.push(e);
    }
    let tiny = 2f64.powi(-55);
    assert_eq!(signed_distance(&simplex, [0.25; 4]), 0.0);
    let inside = signed_distance(&simplex, [0.25, 0.25, 0.25, 0.25 - tiny]);
    assert_ulps(inside, tiny / 2.0, 4.0);
    let outside = signed_distance(&simplex, [0.25, 0.25, 0.25, 0.25 + 2.0 * tiny]);
    assert_ulps(outside, -tiny, 4.0);

    let q = [0.1, 0.2, 0.3, 0.4];
    let facet: Vec<Vec<f64>> = simplex[1..].iter().map(|p| p.to_vec()).collect();
    let exact = exact_distance_to_affine_hull(&facet, &q).expect("a simplex facet");
    assert!(exact > 0.0 && exact < 1e-16, "{exact:e}");
    let full = Hull::try_new(&simplex).expect("hull");
    let outside = full
        .facets()
        .any(|(id, _)| full.side_of(id, &q) == Sign::Positive);
    let want = if outside { -exact } else { exact };
    assert_ulps(signed_distance(&simplex, q), want, 8.0);
}

/// Cases per dimension of the property tests (`PROPTEST_CASES` overrides).
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(64)
}

/// Points per set: enough for facets of every shape, few enough for the rational references.
fn size_for(d: usize) -> usize {
    match d {
        2 | 3 => 40,
        4 => 30,
        _ => 20,
    }
}

/// A query near a random face of a random facet of the full hull — the facet itself or a lower
/// face — moved along a normal of that face (outward when `outward`) by `t · scale`, and what the
/// test knows about it.
struct Case<const D: usize> {
    points: Vec<[f64; D]>,
    full: Hull<D>,
    query: [f64; D],
    scale: f64,
    what: String,
}

fn make_case<const D: usize>(seed: u64, t: f64, outward: bool) -> Case<D> {
    let mut rng = Rng::new(seed);
    let family = Family::ALL[rng.index(Family::ALL.len())];
    let points = rbox::generate::<D>(&family, size_for(D), seed);
    let full = Hull::try_new(&points).expect("rbox families are full-dimensional");
    let scale = points
        .iter()
        .map(|p| p.iter().map(|x| x * x).sum::<f64>().sqrt())
        .fold(0.0, f64::max);
    let facets: Vec<_> = full.facets().map(|(id, _)| id).collect();
    let id = facets[rng.index(facets.len())];
    let facet = full.facet(id);
    // The face: the facet's vertices, or a random nonempty proper subset of them.
    let vertices = facet.vertices();
    let mut face: Vec<usize> = (0..D).collect();
    if rng.below(2) == 1 {
        let keep = 1 + rng.index(D - 1);
        for i in (1..D).rev() {
            face.swap(i, rng.index(i + 1));
        }
        face.truncate(keep);
    }
    // A point of its relative interior, away from its relative boundary.
    let weights: Vec<f64> = face.iter().map(|_| rng.uniform_in(0.2, 1.0)).collect();
    let total: f64 = weights.iter().sum();
    let y: [f64; D] = std::array::from_fn(|c| {
        face.iter()
            .zip(&weights)
            .map(|(&i, w)| w / total * points[vertices[i]][c])
            .sum()
    });
    // A normal of the face: the facet's, or, for a ridge, a positive combination with the
    // neighbour's across it (both contain the ridge).
    let mut normal = facet.normal();
    if face.len() == D - 1 {
        let opposite = (0..D)
            .find(|i| !face.contains(i))
            .expect("one vertex left out");
        let other = full.facet(facet.neighbors()[opposite]).normal();
        let a = rng.uniform_in(0.1, 1.0);
        let combined: [f64; D] = std::array::from_fn(|c| a * normal[c] + (1.0 - a) * other[c]);
        let length = combined.iter().map(|x| x * x).sum::<f64>().sqrt();
        normal = combined.map(|x| x / length);
    }
    let step = if outward { t * scale } else { -t * scale };
    let query = std::array::from_fn(|c| y[c] + step * normal[c]);
    let what = format!(
        "D={D} {family:?} seed {seed} face of {} vertices, t = {t:e}, outward {outward}, q = {query:?}",
        face.len()
    );
    Case {
        points,
        full,
        query,
        scale,
        what,
    }
}

/// The exact signed distance of the case's query to the full hull's boundary: minus the exact
/// (rational Wolfe) distance outside, the smallest exact distance to a facet's plane inside (from
/// the facets whose floating-point plane distance is within 1e−9 of the scale of the smallest),
/// and the exact side from the full hull's predicates.
fn reference<const D: usize>(case: &Case<D>) -> (f64, Sign) {
    let q = case.query;
    let full = &case.full;
    let sides: Vec<Sign> = full.facets().map(|(id, _)| full.side_of(id, &q)).collect();
    let side = if sides.contains(&Sign::Positive) {
        Sign::Positive
    } else if sides.contains(&Sign::Zero) {
        Sign::Zero
    } else {
        Sign::Negative
    };
    let vertices: Vec<Vec<f64>> = full
        .vertex_indices()
        .iter()
        .map(|&v| case.points[v].to_vec())
        .collect();
    let outside = exact_min_norm_distance(&vertices, &q);
    assert_eq!(
        side == Sign::Positive,
        outside > 0.0,
        "{}: exact Wolfe ({outside:e}) and the exact predicates disagree",
        case.what
    );
    match side {
        Sign::Positive => (-outside, side),
        Sign::Zero => (0.0, side),
        Sign::Negative => {
            let float: Vec<(f64, Vec<Vec<f64>>)> = full
                .facets()
                .map(|(_, f)| {
                    let plane = f.vertices().map(|v| case.points[v].to_vec());
                    (-f.signed_distance(&q), plane.to_vec())
                })
                .collect();
            let nearest = float.iter().map(|(d, _)| *d).fold(f64::INFINITY, f64::min);
            let inside = float
                .iter()
                .filter(|(d, _)| *d <= nearest + 1e-9 * case.scale)
                .map(|(_, plane)| exact_distance_to_affine_hull(plane, &q).expect("a facet"))
                .fold(f64::INFINITY, f64::min);
            (inside, side)
        }
    }
}

fn check<const D: usize>(seed: u64, exponent: f64, outward: bool) -> Result<(), TestCaseError> {
    let t = 10f64.powf(exponent);
    let case = make_case::<D>(seed, t, outward);
    let (want, side) = reference(&case);
    let got = signed_distance(&case.points, case.query);
    let what = &case.what;
    match side {
        Sign::Positive => prop_assert!(got < 0.0, "{what}: outside, got {got:e}"),
        Sign::Zero => prop_assert!(got == 0.0, "{what}: on the boundary, got {got:e}"),
        Sign::Negative => prop_assert!(got > 0.0, "{what}: inside, got {got:e}"),
    }
    let tolerance = (1e-12 * want.abs()).max(1e-15 * case.scale);
    prop_assert!(
        (got - want).abs() <= tolerance,
        "{what}: got {got:e}, exact {want:e} (error {:e}, tolerance {tolerance:e})",
        got - want
    );
    Ok(())
}

macro_rules! near_boundary_suite {
    ($($outside:ident, $inside:ident => $d:literal),*) => {$(
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(cases()))]
            /// Moved outward by t · scale, t log-uniform in [1e−15, 1e−3].
            #[test]
            fn $outside(seed in any::<u64>(), exponent in -15.0f64..=-3.0) {
                check::<$d>(seed, exponent, true)?;
            }

            /// Moved inward by t · scale, t log-uniform in [1e−15, 1e−11]: within rounding of the
            /// boundary, where the inside distance comes from exact determinants. (Farther in, it
            /// is the floating-point distance to a plane whose normal is certified to 1e−11.)
            #[test]
            fn $inside(seed in any::<u64>(), exponent in -15.0f64..=-11.0) {
                check::<$d>(seed, exponent, false)?;
            }
        }
    )*};
}

near_boundary_suite!(
    outside_2d, inside_2d => 2,
    outside_3d, inside_3d => 3,
    outside_4d, inside_4d => 4,
    outside_5d, inside_5d => 5,
    outside_6d, inside_6d => 6
);
