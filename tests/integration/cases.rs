//! Regression tests on inputs that once gave a wrong answer (`tests/data/`), each checked against
//! an independent exact reference.

use crate::support::cases::{CYLINDER, read_points, reference, scale};
use pqhull::{ClosestToOrigin, Hull};

#[test]
fn near_boundary_cylinder_6d() {
    let points = read_points::<6>(CYLINDER);
    assert_eq!(points.len(), 32);
    let scale = scale(&points);
    let expected = reference(&points);
    assert!(
        expected < 0.0 && expected > -1e-18,
        "reference {expected:e}: the origin is just outside"
    );
    let (partial, result) =
        Hull::try_with_strategy(&points, ClosestToOrigin::new()).expect("partial hull");
    partial.check().expect("partial hull invariants");
    let got = result.signed_distance;
    assert!(got < 0.0, "the origin is outside: got {got:e}");
    assert!(got.abs() <= 1e-15 * scale, "|{got:e}| > 1e-15 · {scale}");
    assert!(
        (got - expected).abs() <= 1e-12 * expected.abs(),
        "got {got:e}, exact {expected:e}"
    );
    // The reported nearest point is that far from the origin (it lies in the reported facet).
    let norm = result
        .nearest_point
        .iter()
        .map(|x| x * x)
        .sum::<f64>()
        .sqrt();
    assert!((norm - got.abs()).abs() <= 1e-15 * scale, "|x| = {norm:e}");
}
