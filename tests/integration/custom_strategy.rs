//! `examples/custom_strategy.rs` — a strategy written from the public API alone — against a
//! brute force: the support value it finds equals the scan of every point, bit for bit, on seeded
//! sets in D = 2…6, and it adds fewer points to the hull than the full hull does.

#[path = "../../examples/custom_strategy.rs"]
mod example;

use example::support_value;
use pqhull::geometry::Rng;
use pqhull::geometry::vector::dot;
use pqhull::rbox::{Family, generate};

fn brute_force<const D: usize>(points: &[[f64; D]], u: [f64; D]) -> f64 {
    points
        .iter()
        .map(|&p| dot(u, p))
        .fold(f64::NEG_INFINITY, f64::max)
}

fn check<const D: usize>(family: &Family, n: usize, seed: u64) -> (usize, usize) {
    let points = generate::<D>(family, n, seed);
    let mut rng = Rng::new(seed);
    let full_hull = pqhull::Hull::try_new(&points)
        .unwrap()
        .stats()
        .points_processed;
    let (mut partial, mut full) = (0, 0);
    for _ in 0..5 {
        let u: [f64; D] = std::array::from_fn(|_| rng.normal());
        let found = support_value(&points, u).expect("a full-dimensional set");
        let expected = brute_force(&points, u);
        assert_eq!(
            found.value, expected,
            "D = {D}, {family:?}, seed {seed}, u = {u:?}"
        );
        assert_eq!(dot(u, points[found.point]), expected);
        partial += found.stats.points_processed;
        full += full_hull;
    }
    (partial, full)
}

#[test]
fn support_value_equals_a_scan_in_every_dimension() {
    let mut totals = (0, 0);
    for seed in 0..4 {
        for family in [
            Family::SphereSurface,
            Family::UniformCube,
            Family::CubeCornersDiamond,
        ] {
            let add = |t: (usize, usize), s: (usize, usize)| (t.0 + s.0, t.1 + s.1);
            totals = add(totals, check::<2>(&family, 300, seed));
            totals = add(totals, check::<3>(&family, 300, seed));
            totals = add(totals, check::<4>(&family, 200, seed));
            totals = add(totals, check::<6>(&family, 100, seed));
        }
    }
    println!("points added: partial {} vs full {}", totals.0, totals.1);
    assert!(
        totals.0 * 3 < totals.1,
        "the partial hull should add far fewer points: {totals:?}"
    );
}

#[test]
fn ties_and_repeats_keep_the_scan_s_value() {
    // A cube's corners (a whole face ties along an axis), each listed twice, plus inner points.
    let mut points: Vec<[f64; 3]> = (0..8)
        .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64])
        .collect();
    points.extend(points.clone());
    points.push([0.5, 0.5, 0.5]);
    for u in [
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 2.0, 3.0],
        [0.0, 0.0, -1.0],
    ] {
        let found = support_value(&points, u).unwrap();
        assert_eq!(found.value, brute_force(&points, u), "u = {u:?}");
    }
}

#[test]
fn bad_input_is_the_engine_s_typed_error() {
    let flat = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
    ];
    assert!(support_value(&flat, [0.0, 0.0, 1.0]).is_err());
    assert!(support_value(&[[f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]], [1.0, 0.0]).is_err());
}
