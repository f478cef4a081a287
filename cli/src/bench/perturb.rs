//! Point sets moved off their degeneracy by a chosen amount, and how many of Qhull's facets are
//! not facets of the exact hull: the measurements of `cli/examples/perturbed_sum.rs` (issue 24,
//! docs/benchmarks.md, "the raw sums perturbed"), shared with its tests.

use pqhull::geometry::Rng;

/// `points` with every coordinate moved by a uniform random amount in `[−eps·m, eps·m]`, `m`
/// the largest coordinate magnitude, drawn from `Rng::new(seed)` point by point and coordinate
/// by coordinate (so the same arguments give the same points). `eps = 0` returns the points
/// unchanged.
///
/// ```
/// use pqhull_cli::bench::perturb::perturbed;
/// let square = [[1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]];
/// let moved = perturbed(&square, 1e-6, 7);
/// assert_eq!(perturbed(&square, 0.0, 7), square.to_vec());
/// assert!(moved.iter().zip(&square).all(|(a, b)| (0..2).all(|c| (a[c] - b[c]).abs() <= 1e-6)));
/// assert_ne!(moved, square.to_vec());
/// ```
pub fn perturbed<const D: usize>(points: &[[f64; D]], eps: f64, seed: u64) -> Vec<[f64; D]> {
    if eps == 0.0 {
        return points.to_vec();
    }
    let largest = points.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut rng = Rng::new(seed);
    points
        .iter()
        .map(|p| p.map(|x| x + eps * largest * rng.uniform_in(-1.0, 1.0)))
        .collect()
}

/// How many of Qhull's (triangulated) facets of `points` are not facets of their exact hull:
/// those with an input point strictly beyond them, or with the centroid of the points on them (a
/// flat simplex of Qhull's triangulation), by exact orientation
/// ([`pqhull::predicates::orientation`]); with Qhull's facet count. Costs one orientation per
/// point and facet: seconds for tens of thousands of facets.
///
/// # Errors
/// Qhull's, when it fails on `points`.
#[cfg(feature = "qhull")]
pub fn qhull_wrong_facets<const D: usize>(
    points: &[[f64; D]],
) -> Result<(usize, usize), pqhull::qhull_baseline::QhullError> {
    use pqhull::predicates::{Sign, orientation};
    let hull = pqhull::qhull_baseline::qhull_full_hull(points)?;
    let n = points.len() as f64;
    let centroid: [f64; D] = std::array::from_fn(|c| points.iter().map(|p| p[c]).sum::<f64>() / n);
    let wrong = hull
        .facets
        .iter()
        .filter(|facet| {
            let vertices: [[f64; D]; D] = std::array::from_fn(|i| points[facet.vertices[i]]);
            let inside = orientation(&vertices, &centroid);
            inside == Sign::Zero
                || points
                    .iter()
                    .any(|p| orientation(&vertices, p) == inside.flip())
        })
        .count();
    Ok((wrong, hull.facets.len()))
}
