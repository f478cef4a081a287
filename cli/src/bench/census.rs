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
//! The exact determinants are fraction-free Gaussian elimination (Bareiss) in `BigInt` on the
//! coordinates scaled to integers: a few microseconds each, for a measurement, not a predicate.
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

use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use pqhull::Hull;
use pqhull::predicates::{FacetPlane, Sign, orientation};
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
    // Every coordinate as an integer times 2^lowest.
    let points: Vec<&[f64; D]> = vertices.iter().chain(std::iter::once(p)).collect();
    let parts: Vec<[(BigInt, i64); D]> = points
        .iter()
        .map(|q| (**q).map(|x| integer_parts(x).expect("a finite hull coordinate")))
        .collect();
    let lowest = parts
        .iter()
        .flatten()
        .filter(|(m, _)| !m.is_zero())
        .map(|&(_, e)| e)
        .min()
        .unwrap_or(0);
    let scaled: Vec<Vec<BigInt>> = parts
        .iter()
        .map(|q| q.iter().map(|(m, e)| m << (e - lowest) as usize).collect())
        .collect();
    let mut rows: Vec<Vec<BigInt>> = scaled[1..]
        .iter()
        .map(|q| q.iter().zip(&scaled[0]).map(|(a, b)| a - b).collect())
        .collect();
    // log2 of the product of the rows' lengths, in units of 2^lowest.
    let lengths: f64 = rows
        .iter()
        .map(|row| {
            let top = row.iter().map(|x| x.bits()).max().unwrap_or(0);
            let shift = top.saturating_sub(60);
            let squares: f64 = row
                .iter()
                .map(|x| {
                    let x = f64_of(&(x >> shift as usize));
                    x * x
                })
                .sum();
            0.5 * squares.log2() + shift as f64
        })
        .sum();
    let det = bareiss(&mut rows);
    if det.is_zero() {
        return (Sign::Zero, None);
    }
    let sign = if det.is_positive() {
        Sign::Positive
    } else {
        Sign::Negative
    };
    let shift = det.bits().saturating_sub(60);
    let log2 = f64_of(&(det.abs() >> shift as usize)).log2() + shift as f64;
    (sign, Some((log2 - lengths).floor() as i64))
}

/// `x = m · 2^e` with `m` an integer; `None` if `x` is not finite.
fn integer_parts(x: f64) -> Option<(BigInt, i64)> {
    if !x.is_finite() {
        return None;
    }
    if x == 0.0 {
        return Some((BigInt::zero(), 0));
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i64;
    let fraction = bits & ((1u64 << 52) - 1);
    let (m, e) = if exponent == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), exponent - 1075)
    };
    let m = BigInt::from(m);
    Some((if x < 0.0 { -m } else { m }, e))
}

/// A `BigInt` below 2^61 in magnitude as `f64` (rounded).
fn f64_of(x: &BigInt) -> f64 {
    let (sign, digits) = x.to_u64_digits();
    let magnitude = digits.first().copied().unwrap_or(0) as f64;
    if sign == num_bigint::Sign::Minus {
        -magnitude
    } else {
        magnitude
    }
}

/// The determinant of a square integer matrix by fraction-free elimination (every division is
/// exact), with row swaps for zero pivots.
fn bareiss(m: &mut [Vec<BigInt>]) -> BigInt {
    let n = m.len();
    let mut negate = false;
    let mut previous = BigInt::from(1);
    for k in 0..n {
        let Some(pivot) = (k..n).find(|&r| !m[r][k].is_zero()) else {
            return BigInt::zero();
        };
        if pivot != k {
            m.swap(pivot, k);
            negate = !negate;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let value = (&m[i][j] * &m[k][k] - &m[i][k] * &m[k][j]) / &previous;
                m[i][j] = value;
            }
        }
        previous = m[k][k].clone();
    }
    let det = m[n - 1][n - 1].clone();
    if negate { -det } else { det }
}
