//! Regression tests on inputs that once gave a wrong answer (`tests/data/`), each checked against
//! an independent exact reference.

mod support;

#[path = "support/cli.rs"]
#[allow(dead_code)] // each test binary uses part of it
mod cli_support;

use pqhull::predicates::Sign;
use pqhull::{ClosestToOrigin, Hull};
use support::min_norm::exact_min_norm_distance;
use support::points_as_vecs;

/// 32 wrenches of a grasp on a cylinder (4 contacts × 8 cone edges, μ = 0.5), one 6-D point a
/// line. The origin lies about 4.6e−19 outside their hull, beyond a facet of a flat, finely
/// triangulated region; `pqh` once reported −0.016 for it.
const CYLINDER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/near-boundary-cylinder-6d.csv"
);

fn read_points<const D: usize>(path: &str) -> Vec<[f64; D]> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("read {path}: {e}"));
    text.lines()
        .filter(|line| !line.trim().is_empty())
        .map(|line| {
            let row: Vec<f64> = line
                .split(',')
                .map(|x| x.trim().parse().expect("a number"))
                .collect();
            assert_eq!(row.len(), D, "{path}: {line}");
            std::array::from_fn(|c| row[c])
        })
        .collect()
}

/// The largest point norm: the scale the accuracy promise is relative to.
fn scale<const D: usize>(points: &[[f64; D]]) -> f64 {
    points
        .iter()
        .map(|p| p.iter().map(|x| x * x).sum::<f64>().sqrt())
        .fold(0.0, f64::max)
}

/// The exact signed distance of the origin to the hull's boundary, negative outside: exact
/// rational Wolfe (independent of the engine) for the magnitude, the full hull's exact
/// predicates for the side.
fn reference<const D: usize>(points: &[[f64; D]]) -> f64 {
    let full = Hull::try_new(points).expect("full hull");
    let outside = full
        .facets()
        .any(|(id, _)| full.side_of(id, &[0.0; D]) == Sign::Positive);
    let distance = exact_min_norm_distance(&points_as_vecs(points), &[0.0; D]);
    assert_eq!(
        outside,
        distance > 0.0,
        "exact Wolfe and the exact predicates disagree"
    );
    -distance
}

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

#[test]
fn near_boundary_cylinder_6d_cli() {
    let points = read_points::<6>(CYLINDER);
    let scale = scale(&points);
    let expected = reference(&points);
    let output = cli_support::pqh(
        &[
            "hull",
            "--strategy",
            "closest-to-origin",
            CYLINDER,
            "--json",
        ],
        None,
    );
    assert!(
        output.status.success(),
        "pqh failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let json: serde_json::Value =
        serde_json::from_slice(&output.stdout).expect("stdout is one JSON object");
    let got = json["origin_distance"]
        .as_f64()
        .expect("origin_distance is a number");
    assert!(got < 0.0, "origin_distance {got:e}: the origin is outside");
    assert!(
        got.abs() <= 1e-15 * scale,
        "origin_distance {got:e} is not tiny"
    );
    assert!(
        (got - expected).abs() <= 1e-12 * expected.abs(),
        "origin_distance {got:e}, exact {expected:e}"
    );
}
