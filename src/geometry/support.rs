//! Support functions: the one description of a convex set that GJK, the partial hull's implicit
//! point sources and the ball tree share.

use super::SupportIndex;
use super::vector::dot;

/// A set given by its support function: a point maximising `direction · p`.
///
/// Implemented by point slices (a scan), by [`SupportIndex`] (a ball tree over a fixed set) and by
/// the implicit sets a partial hull grows over
/// (the strategies' `PointSource`, e.g. a grasp's Minkowski sum of friction cones); consumed by [`Gjk`](super::Gjk) and by the strategies.
///
/// ```
/// use pqhull::geometry::Support;
/// let mut square: &[[f64; 2]] = &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// assert_eq!(square.support_point(&[1.0, 0.1]), Some([1.0, 1.0]));
/// let mut empty: &[[f64; 2]] = &[];
/// assert_eq!(empty.support_point(&[1.0, 0.0]), None);
/// ```
pub trait Support<const D: usize> {
    /// A point of the set maximising `direction · p` (in floating point: a consumer that needs
    /// certainty checks what it is given), or `None` for an empty set.
    fn support_point(&mut self, direction: &[f64; D]) -> Option<[f64; D]>;
}

impl<const D: usize> Support<D> for &[[f64; D]] {
    /// A scan; the first of ties.
    fn support_point(&mut self, direction: &[f64; D]) -> Option<[f64; D]> {
        let mut best: Option<(f64, [f64; D])> = None;
        for &p in self.iter() {
            let height = dot(*direction, p);
            if best.is_none_or(|(h, _)| height > h) {
                best = Some((height, p));
            }
        }
        best.map(|(_, p)| p)
    }
}

impl<const D: usize> Support<D> for &SupportIndex<D> {
    fn support_point(&mut self, direction: &[f64; D]) -> Option<[f64; D]> {
        self.support(direction).map(|(_, at)| self.point(at))
    }
}

/// The largest Euclidean norm of `points` (0 for none): the size a support-function algorithm
/// measures its tolerances in.
pub fn largest_norm<const D: usize>(points: &[[f64; D]]) -> f64 {
    points.iter().map(|&w| dot(w, w)).fold(0.0, f64::max).sqrt()
}

/// A support function given as a closure returning a maximising point (of a non-empty set).
///
/// ```
/// use pqhull::geometry::{Support, SupportFn};
/// // The unit disc: its support point in direction v is v/|v|.
/// let mut disc = SupportFn(|v: &[f64; 2]| {
///     let n = v[0].hypot(v[1]);
///     [v[0] / n, v[1] / n]
/// });
/// assert_eq!(disc.support_point(&[0.0, 2.0]), Some([0.0, 1.0]));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct SupportFn<F>(pub F);

impl<const D: usize, F: FnMut(&[f64; D]) -> [f64; D]> Support<D> for SupportFn<F> {
    fn support_point(&mut self, direction: &[f64; D]) -> Option<[f64; D]> {
        Some((self.0)(direction))
    }
}
