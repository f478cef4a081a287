//! The inputs of tests/data/ that once gave wrong answers, read, with their exact references.

use super::min_norm::exact_min_norm_distance;
use super::points_as_vecs;
use pqhull::Hull;
use pqhull::predicates::Sign;

/// 32 wrenches of a grasp on a cylinder (4 contacts × 8 cone edges, μ = 0.5), one 6-D point a
/// line. The origin lies about 4.6e−19 outside their hull, beyond a facet of a flat, finely
/// triangulated region; `pqh` once reported −0.016 for it.
pub const CYLINDER: &str = "near-boundary-cylinder-6d.csv";

pub fn read_points<const D: usize>(name: &str) -> Vec<[f64; D]> {
    let path = &super::data_file(name);
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
pub fn scale<const D: usize>(points: &[[f64; D]]) -> f64 {
    points
        .iter()
        .map(|p| p.iter().map(|x| x * x).sum::<f64>().sqrt())
        .fold(0.0, f64::max)
}

/// The exact signed distance of the origin to the hull's boundary, negative outside: exact
/// rational Wolfe (independent of the engine) for the magnitude, the full hull's exact
/// predicates for the side.
pub fn reference<const D: usize>(points: &[[f64; D]]) -> f64 {
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
