//! Point sets moved off their degeneracy by a chosen amount, and how many of Qhull's facets are
//! not facets of the exact hull: the measurements of the `perturbed_sum` and `qhull_options`
//! examples (`cli/examples/`; issue 24, docs/benchmarks.md, "the raw sums perturbed" and
//! "Qhull's three answers"), shared with their tests.

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
    qhull_wrong_facets_with(points, pqhull::qhull_baseline::QhullOptions::Merged)
}

/// [`qhull_wrong_facets`] for a run of Qhull with `options`: with
/// [`QhullOptions::Joggled`](pqhull::qhull_baseline::QhullOptions::Joggled), Qhull's facets of
/// the joggled points judged against the caller's `points`.
///
/// # Errors
/// Qhull's, when it fails on `points`.
#[cfg(feature = "qhull")]
pub fn qhull_wrong_facets_with<const D: usize>(
    points: &[[f64; D]],
    options: pqhull::qhull_baseline::QhullOptions,
) -> Result<(usize, usize), pqhull::qhull_baseline::QhullError> {
    let hull = pqhull::qhull_baseline::qhull_full_hull_with(points, options)?;
    let facets: Vec<&[usize]> = hull.facets.iter().map(|f| f.vertices.as_slice()).collect();
    Ok((wrong_facets(points, &facets), facets.len()))
}

/// How many of `facets` (each D indices into `points`, in any order) are not facets of the
/// exact hull of `points`: [`judge_facets`]'s total.
///
/// ```
/// use pqhull_cli::bench::perturb::wrong_facets;
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let sides: [&[usize]; 4] = [&[0, 1], &[1, 2], &[2, 3], &[3, 0]];
/// assert_eq!(wrong_facets(&square, &sides), 0);
/// assert_eq!(wrong_facets(&square, &[&[0, 2], &[0, 1], &[0, 0]]), 2); // a diagonal, a point
/// ```
pub fn wrong_facets<const D: usize>(points: &[[f64; D]], facets: &[&[usize]]) -> usize {
    judge_facets(points, facets).total()
}

/// [`judge_facets`]'s counts of the facets that are not facets of the exact hull, by reason.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WrongFacets {
    /// With other than D indices, or an index out of range.
    pub malformed: usize,
    /// With the centroid of the points on their hyperplane: a flat simplex (Qhull's
    /// triangulation of a merged facet makes some) or a plane through the interior.
    pub flat: usize,
    /// With a point strictly beyond them (and not flat).
    pub beyond: usize,
}

impl WrongFacets {
    /// All of them.
    pub fn total(&self) -> usize {
        self.malformed + self.flat + self.beyond
    }
}

/// Which of `facets` (each D indices into `points`, in any order) are not facets of the exact
/// hull of `points`, by exact orientation ([`pqhull::predicates::orientation`]): a facet of the
/// exact hull has the centroid of the points strictly inside and no point strictly beyond.
/// Costs one orientation per point and facet.
///
/// ```
/// use pqhull_cli::bench::perturb::{WrongFacets, judge_facets};
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5]];
/// let judged = judge_facets(&square, &[&[0, 2], &[0, 1], &[0, 0], &[0, 4]]);
/// // the diagonal holds the centroid; (0, 0)–(0.5, 0.5) too; a repeated index is a point
/// assert_eq!(judged, WrongFacets { malformed: 0, flat: 3, beyond: 0 });
/// assert_eq!(judge_facets(&square, &[&[0, 1, 2], &[1, 9]]).malformed, 2);
/// // (4, 0)–(1, 1) cuts the triangle: the centroid on one side, (0, 0) strictly beyond
/// let triangle = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [1.0, 1.0]];
/// assert_eq!(judge_facets(&triangle, &[&[1, 3]]).beyond, 1);
/// ```
pub fn judge_facets<const D: usize>(points: &[[f64; D]], facets: &[&[usize]]) -> WrongFacets {
    use pqhull::predicates::{Sign, orientation};
    let n = points.len() as f64;
    let centroid: [f64; D] = std::array::from_fn(|c| points.iter().map(|p| p[c]).sum::<f64>() / n);
    let mut judged = WrongFacets::default();
    for facet in facets {
        if facet.len() != D || facet.iter().any(|&i| i >= points.len()) {
            judged.malformed += 1;
            continue;
        }
        let vertices: [[f64; D]; D] = std::array::from_fn(|i| points[facet[i]]);
        let inside = orientation(&vertices, &centroid);
        if inside == Sign::Zero {
            judged.flat += 1;
        } else if points
            .iter()
            .any(|p| orientation(&vertices, p) == inside.flip())
        {
            judged.beyond += 1;
        }
    }
    judged
}
