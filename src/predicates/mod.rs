//! Exact orientation predicates in any dimension D (2 ≤ D ≤ 8).
//!
//! # Sign convention
//!
//! For D points `v0, …, v(D−1)` (a facet) and a query point `p`, the *orientation* is the sign of
//!
//! ```text
//! det[ v1 − v0 ; v2 − v0 ; … ; v(D−1) − v0 ; p − v0 ]      (rows are the difference vectors)
//! ```
//!
//! It is `Zero` exactly when `p` lies on the affine hull of the vertices (or the vertices are
//! affinely dependent), and swapping two vertices flips it. In 2-D it is positive when `p` is to the
//! left of the directed line `v0 → v1`; in 3-D positive when `v0, v1, v2` appear counter-clockwise
//! seen from `p`.
//!
//! # Filter and exact fallbacks
//!
//! [`orientation`] is always exact:
//! * D = 2, 3: Shewchuk's adaptive predicates from the `robust` crate (`orient2d` has our sign,
//!   `orient3d` the opposite one), used when all coordinates are zero or of magnitude in
//!   `[2^-250, 2^250]` where its expansion arithmetic cannot underflow or overflow;
//! * otherwise, and for every D ≥ 4: coordinates are scaled by powers of two into integers
//!   (exactly: every `f64` is an integer times a power of two), and the sign of the integer
//!   determinant of differences is found by a Laplace expansion in allocation-free fixed-width
//!   integers when every column fits in `i128` (each column scaled by its own power of two), by
//!   fraction-free Bareiss elimination in `BigInt` otherwise.
//!
//! [`FacetPlane`] is the fast path used by the hull engine: it caches the cofactors of the
//! facet, so that evaluating the determinant for a new `p` is a D-term dot product, together with
//! a certified error bound ([`FacetPlane::evaluate`]). [`FacetPlane::side`] returns the sign of the
//! approximation when it exceeds the bound; otherwise (D ≥ 4) the same plane in double-double
//! arithmetic with its own certified bound (~2^−101 relative), then exact integer cofactors, both
//! built once per plane and kept, and last [`orientation`].
//!
//! **Precondition of the filter**: the error bound is finite only when every coordinate (of the
//! vertices and of `p`) is in `[−1, 1]` — the hull engine scales every input by a power of two
//! (which is exact) to ensure it. Outside that range the bound is `+∞` and every call of `side`
//! takes the exact path: correctness never depends on the precondition, only speed does.
//!
//! [`affinely_independent_subset`] finds the affine rank of a point set exactly (rational
//! arithmetic), for choosing the initial simplex and detecting degenerate (flat) inputs.
//!
//! # Examples
//!
//! ```
//! use pqhull::predicates::{orientation, FacetPlane, Sign};
//!
//! // 2-D: p is to the left of the directed line v0 → v1.
//! let line = [[0.0, 0.0], [1.0, 0.0]];
//! assert_eq!(orientation(&line, &[0.5, 0.25]), Sign::Positive);
//! assert_eq!(orientation(&line, &[0.5, -0.25]), Sign::Negative);
//! assert_eq!(orientation(&line, &[0.75, 0.0]), Sign::Zero);
//!
//! // 3-D: the plane z = 0 through a counter-clockwise triangle (seen from above).
//! let tri = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
//! let plane = FacetPlane::new(&tri);
//! assert_eq!(plane.side(&[0.1, 0.1, 0.5], || tri), Sign::Positive);
//! assert_eq!(plane.side(&[0.1, 0.1, -1e-300], || tri), Sign::Negative);
//! assert_eq!(plane.side(&[0.3, 0.3, 0.0], || tri), Sign::Zero);
//!
//! // The approximate value, with its certified error bound.
//! let (value, bound) = plane.evaluate(&[0.1, 0.1, 0.5]);
//! assert!((value - 0.5).abs() <= bound);
//! assert_eq!(plane.cofactors(), &[0.0, 0.0, 1.0]);
//! ```

mod double_double;
mod exact;
mod filter;
mod grid;
mod minors;
mod minors6;
mod minors78;
mod minors_small;
#[cfg(test)]
mod tests;
mod wide;

pub use exact::exact_cofactor_direction;
pub(crate) use exact::lowest_bit_exponent;
pub use filter::FacetPlane;
pub(crate) use filter::in_box;
pub use grid::ExactGrid;
pub use wide::times_power_of_two;

/// The sign of an orientation determinant.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// Strictly negative.
    Negative,
    /// Exactly zero.
    Zero,
    /// Strictly positive.
    Positive,
}

impl Sign {
    /// The opposite sign (`Zero` stays `Zero`).
    pub fn flip(self) -> Sign {
        exact::flip(self)
    }
}

/// Exact sign of `det[v1 − v0; …; v(D−1) − v0; p − v0]` (rows are the D difference vectors).
///
/// See the [module documentation](self) for the convention and the methods used. No precondition
/// on the magnitude of the coordinates.
///
/// ```
/// use pqhull::predicates::{orientation, Sign};
///
/// let simplex = [[0.0; 4], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]];
/// assert_eq!(orientation(&simplex, &[0.0, 0.0, 0.0, 1.0]), Sign::Positive);
/// // Any point with last coordinate 0 is on the hyperplane, however large.
/// assert_eq!(orientation(&simplex, &[1e300, -3.0, 0.5, 0.0]), Sign::Zero);
/// ```
///
/// # Panics
/// If any coordinate is NaN or infinite (a caller bug: the hull engine rejects such input).
pub fn orientation<const D: usize>(vertices: &[[f64; D]; D], p: &[f64; D]) -> Sign {
    exact::orientation(vertices, p)
}

/// The exact value of [`orientation`]'s determinant, `det[v1 − v0; …; v(D−1) − v0; p − v0]`,
/// as `(m, e)` with the determinant `≈ m·2^e`: computed exactly (Bareiss elimination in `BigInt`
/// on the coordinates as integers) and rounded once, so `m` is within 2^−52 of it relative and
/// `e` may lie far outside `f64`'s range (a determinant of 2^−3000 is `(m, −3000 − …)`).
/// `(0.0, 0)` exactly when the determinant is zero.
///
/// For measuring how near to degenerate a configuration is (how far below its rows' sizes the
/// determinant lies); a side test needs only [`orientation`], which is much cheaper.
///
/// ```
/// use pqhull::predicates::orientation_value;
///
/// // A unit square lifted at one corner by 2^−80: the determinant is −2^−80.
/// let facet = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 2f64.powi(-80)]];
/// let (m, e) = orientation_value(&facet, &[0.0, 1.0, 0.0]);
/// assert_eq!(m * 2f64.powi((e + 80) as i32), -1.0);
/// assert_eq!(orientation_value(&facet, &[0.5, 0.0, 0.0]), (0.0, 0));
/// ```
///
/// # Panics
/// If any coordinate is NaN or infinite.
pub fn orientation_value<const D: usize>(vertices: &[[f64; D]; D], p: &[f64; D]) -> (f64, i64) {
    exact::orientation_parts(vertices, p)
}

/// Indices of a maximal affinely independent subset of `points`, found with exact (rational)
/// arithmetic; its length minus one is the affine rank (and it is empty for no points).
///
/// Greedy in input order: index `i` is kept iff `points[i]` is not in the affine hull of the
/// points kept before it (index 0 is always kept). Stops scanning once `D + 1` indices are kept.
///
/// ```
/// use pqhull::predicates::affinely_independent_subset;
///
/// // Four points on a line in 3-D, then one off it: rank 2.
/// let pts = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [0.5, 0.5, 0.5], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
/// assert_eq!(affinely_independent_subset(&pts), vec![0, 1, 4]);
/// ```
///
/// # Panics
/// If a coordinate that has to be examined is NaN or infinite.
pub fn affinely_independent_subset<const D: usize>(points: &[[f64; D]]) -> Vec<usize> {
    exact::affinely_independent_subset(points)
}
