//! How hard a hull's own certificate is to decide: for every ridge of a finished hull, the
//! determinant that says the two facets meeting there are convex to each other (a facet's
//! vertices and the neighbour's opposite vertex), evaluated exactly, binned by its size against
//! the product of its rows' lengths (its *Hadamard ratio*, in `[0, 1]`).
//!
//! The a-priori error bounds of a determinant evaluated in unit roundoff `u` (Laplace
//! expansion or elimination: pqhull's filter and its double-double stage among them) are `u`
//! times the rows' products up to a factor that depends on the dimension (the permanent of the
//! entries' magnitudes, at most `D^(D/2)` times the product of the rows' lengths), and
//! perturbing the entries by a relative `u` moves the determinant by up to about that much. A
//! ridge whose ratio is far below `2^−53` is out of reach of such `f64` bounds, one far below
//! `2^−106` of double-double's; the bins are the scales, not sharp thresholds. This is a
//! property of the output and the caller's points, not of the engine that built the hull:
//! `pqh bench hull`'s raw Minkowski sums are the family where it matters (docs/benchmarks.md,
//! "Why the raw sums stay below 1.0").
//!
//! The exact determinants are [`orientation_value`]'s (Bareiss elimination in `BigInt`): a few
//! microseconds each, for a measurement, not a predicate.
//!
//! ```
//! use pqhull::Hull;
//! use pqhull_cli::bench::census::{check_ridges, ridge_census};
//!
//! // A cube's corners: every ridge between two triangles of one square face is exactly flat.
//! let corners: Vec<[f64; 3]> = (0..8)
//!     .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64])
//!     .collect();
//! let census = ridge_census(&Hull::try_new(&corners)?);
//! assert_eq!(census.ridges, 18);
//! assert_eq!(census.zero, 6);
//! assert_eq!(census.above_double, 12);
//! assert_eq!(check_ridges(&Hull::try_new(&corners)?).not_convex, 0);
//! # Ok::<(), pqhull::HullError>(())
//! ```

use pqhull::Hull;
use pqhull::predicates::{FacetPlane, Sign, orientation, orientation_value};
use std::time::{Duration, Instant};

/// The ridges of a hull binned by the Hadamard ratio of their convexity determinants (see the
/// [module](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RidgeCensus {
    /// Ridges of the hull (pairs of neighbouring facets).
    pub ridges: usize,
    /// Determinants exactly zero: the two facets lie in one hyperplane (a triangulated face).
    pub zero: usize,
    /// Nonzero, ratio below `2^−106`: beyond double-double.
    pub below_double_double: usize,
    /// Ratio in `[2^−106, 2^−53)`: beyond `f64`, within double-double's reach.
    pub below_double: usize,
    /// Ratio at least `2^−53`.
    pub above_double: usize,
    /// Facets with at least one ridge below `2^−53` that is not exactly flat.
    pub facets_beyond_double: usize,
    /// The smallest nonzero ratio, as a power of two (`0` when every ridge is flat or there is
    /// none).
    pub smallest_log2: i64,
}

/// The census of every ridge of `hull` (see the [module](self)). Costs one exact determinant
/// per ridge: seconds for a hull of 60,000 facets in 6-D.
///
/// # Panics
/// If a coordinate of a vertex is not finite (a hull never holds one), or if the exact
/// determinant's sign disagrees with [`orientation`]'s (a defect of one of the two).
pub fn ridge_census<const D: usize>(hull: &Hull<D>) -> RidgeCensus {
    let mut census = RidgeCensus::default();
    for (id, facet) in hull.facets() {
        let vertices = facet.vertices();
        let mut hard = false;
        for neighbor in facet.neighbors() {
            let other = hull.facet(neighbor).vertices();
            let Some(&opposite) = other.iter().find(|v| !vertices.contains(v)) else {
                continue;
            };
            let rows: [[f64; D]; D] = std::array::from_fn(|i| hull.point(vertices[i]));
            let apex = hull.point(opposite);
            let (sign, log2) = hadamard_log2(&rows, &apex);
            assert_eq!(
                sign,
                orientation(&rows, &apex),
                "the census' exact determinant disagrees with the predicate"
            );
            let counted = neighbor.index() > id.index();
            match log2 {
                None => census.zero += usize::from(counted),
                Some(l) => {
                    hard |= l < -53;
                    if counted {
                        if l < -106 {
                            census.below_double_double += 1;
                        } else if l < -53 {
                            census.below_double += 1;
                        } else {
                            census.above_double += 1;
                        }
                        if census.smallest_log2 == 0 || l < census.smallest_log2 {
                            census.smallest_log2 = l;
                        }
                    }
                }
            }
            census.ridges += usize::from(counted);
        }
        census.facets_beyond_double += usize::from(hard);
    }
    census
}

/// What [`check_ridges`] measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RidgeCheck {
    /// Wall time of the whole check, one thread.
    pub elapsed: Duration,
    /// Ridge tests made: every facet against the opposite vertex of each neighbour (each ridge
    /// twice).
    pub tests: usize,
    /// Facets whose neighbours' opposite vertices were not all on one side (a hull that is not
    /// locally convex; 0 for a correct one).
    pub not_convex: usize,
}

/// Decides, with pqhull's own predicates from cold caches, that `hull` is locally convex at
/// every ridge: for each facet a new [`FacetPlane`] (the engine's filter, then its
/// double-double and exact stages as they are needed) and one side test per neighbour's
/// opposite vertex. What a program that only *checks* this exact hull's ridges spends, whatever
/// built it: the lower end of what building it can cost with these predicates.
pub fn check_ridges<const D: usize>(hull: &Hull<D>) -> RidgeCheck {
    let started = Instant::now();
    let (mut tests, mut not_convex) = (0, 0);
    for (_, facet) in hull.facets() {
        let vertices = facet.vertices();
        let coords: [[f64; D]; D] = std::array::from_fn(|i| hull.point(vertices[i]));
        let plane = FacetPlane::new(&coords);
        let (mut positive, mut negative) = (false, false);
        for neighbor in facet.neighbors() {
            let other = hull.facet(neighbor).vertices();
            let Some(&opposite) = other.iter().find(|v| !vertices.contains(v)) else {
                continue;
            };
            tests += 1;
            match plane.side(&hull.point(opposite), || coords) {
                Sign::Positive => positive = true,
                Sign::Negative => negative = true,
                Sign::Zero => {}
            }
        }
        not_convex += usize::from(positive && negative);
    }
    RidgeCheck {
        elapsed: started.elapsed(),
        tests,
        not_convex,
    }
}

/// The exact sign of `det[v1 − v0; …; v(D−1) − v0; p − v0]` and `⌊log2⌋` of its Hadamard ratio
/// (`None` when it is zero), to within one (the row lengths are rounded).
fn hadamard_log2<const D: usize>(vertices: &[[f64; D]; D], p: &[f64; D]) -> (Sign, Option<i64>) {
    let (m, e) = orientation_value(vertices, p);
    if m == 0.0 {
        return (Sign::Zero, None);
    }
    let sign = if m > 0.0 {
        Sign::Positive
    } else {
        Sign::Negative
    };
    let lengths: f64 = (1..=D)
        .map(|k| log2_length(if k < D { &vertices[k] } else { p }, &vertices[0]))
        .sum();
    let log2 = m.abs().log2() + e as f64;
    (sign, Some((log2 - lengths).floor() as i64))
}

/// `log2 |a − b|` for `a ≠ b` (a difference of distinct floats is never zero), without overflow
/// of the difference (halved when it overflows) or of the squares.
fn log2_length<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    let mut row: [f64; D] = std::array::from_fn(|j| a[j] - b[j]);
    let mut doubled = 0.0;
    if row.iter().any(|x| !x.is_finite()) {
        row = std::array::from_fn(|j| a[j] * 0.5 - b[j] * 0.5);
        doubled = 1.0;
    }
    let largest = row.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let squares: f64 = row.iter().map(|x| (x / largest) * (x / largest)).sum();
    doubled + largest.log2() + 0.5 * squares.log2()
}
