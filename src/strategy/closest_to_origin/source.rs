//! What [`ClosestToOrigin`](super::ClosestToOrigin) asks of the set beyond its input: the
//! [`PointSource`] of an implicit set (a Minkowski sum given by its support function), the
//! [`NoSource`] of none, and the [`SourceError`] of a source that breaks its contract.

use crate::geometry::Support;
use crate::hull::{FacetId, Hull};
use crate::predicates::Sign;
use std::fmt;

/// Points that are not in the hull's input but belong to the set whose hull is sought — an
/// implicit set, such as the Q∞ Minkowski sum, answered through its support function.
///
/// [`ClosestToOrigin::with_source`](super::ClosestToOrigin::with_source) asks it before
/// declaring a facet certain, so "nothing beyond" covers the implicit points too. The hull's
/// input must contain the set's extreme points along every coordinate axis (see
/// [`StrategyHooks::insert_beyond`](crate::hull::StrategyHooks::insert_beyond)).
///
/// ```
/// use pqhull::geometry::Support;
/// use pqhull::strategy::PointSource;
/// use pqhull::{ClosestToOrigin, FacetId, Hull};
///
/// /// The square [−1, 1]² given by its corners, of which the input holds only three.
/// struct Corners;
/// impl PointSource<2> for Corners {
///     fn beyond(&mut self, hull: &Hull<2>, id: FacetId) -> Option<[f64; 2]> {
///         let n = hull.facet(id).normal();
///         let corner = [n[0].signum(), n[1].signum()];
///         (hull.facet(id).signed_distance(&corner) > 1e-12).then_some(corner)
///     }
/// }
/// impl Support<2> for Corners {
///     fn support_point(&mut self, d: &[f64; 2]) -> Option<[f64; 2]> {
///         Some([d[0].signum(), d[1].signum()])
///     }
/// }
/// let input = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]];
/// let strategy = ClosestToOrigin::with_source([0.5, 0.0], Corners);
/// // With a source, the run's output is a `Result`: `SourceError` if the source breaks its
/// // contract.
/// let (_, result) = Hull::try_with_strategy(&input, strategy)?;
/// let result = result?;
/// // The triangle alone would give 0.25/√2 ≈ 0.18; the square gives 0.5.
/// assert!((result.signed_distance - 0.5).abs() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Contract
///
/// Every point returned — by [`beyond`](Self::beyond) or by
/// [`support_point`](Support::support_point) — must be finite and within the hull's coordinate
/// range ([`StrategyHooks::coordinate_bound`](crate::hull::StrategyHooks::coordinate_bound): seed the input with the set's extreme points along every
/// axis), and a point from `beyond` must be strictly beyond the facet asked about. The strategy
/// checks both exactly; a point that breaks them ends the run with a [`SourceError`] (it used to
/// panic).
pub trait PointSource<const D: usize>: Support<D> {
    /// A point of the implicit set strictly beyond facet `id` of `hull` (by the exact
    /// [`Hull::side_of`]), or `None` only when there is none.
    fn beyond(&mut self, hull: &Hull<D>, id: FacetId) -> Option<[f64; D]>;
}

/// No implicit points: the hull's input is the whole set. The default source of
/// [`ClosestToOrigin`](super::ClosestToOrigin), whose run then cannot fail (it gives a bare
/// [`DistanceResult`](super::DistanceResult)); it is not a [`PointSource`].
#[derive(Clone, Copy, Debug, Default)]
pub struct NoSource;

impl<const D: usize> Support<D> for NoSource {
    fn support_point(&mut self, _: &[f64; D]) -> Option<[f64; D]> {
        None
    }
}

/// What the strategy asks of its source: nothing of [`NoSource`], the [`PointSource`] otherwise.
/// Public only in name (this module is private): it lets one implementation serve both.
pub trait Implicit<const D: usize> {
    /// [`PointSource::beyond`].
    fn beyond(&mut self, hull: &Hull<D>, id: FacetId) -> Option<[f64; D]>;
    /// [`Support::support_point`].
    fn support_point(&mut self, direction: &[f64; D]) -> Option<[f64; D]>;
}

impl<const D: usize> Implicit<D> for NoSource {
    fn beyond(&mut self, _: &Hull<D>, _: FacetId) -> Option<[f64; D]> {
        None
    }
    fn support_point(&mut self, _: &[f64; D]) -> Option<[f64; D]> {
        None
    }
}

impl<const D: usize, S: PointSource<D>> Implicit<D> for S {
    fn beyond(&mut self, hull: &Hull<D>, id: FacetId) -> Option<[f64; D]> {
        PointSource::beyond(self, hull, id)
    }
    fn support_point(&mut self, direction: &[f64; D]) -> Option<[f64; D]> {
        Support::support_point(self, direction)
    }
}

/// A [`PointSource`] broke its contract: what it returned, and for which facet. The run stopped
/// there; the partial hull is valid and does not hold the point.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SourceError<const D: usize> {
    /// [`PointSource::beyond`] returned a point that is not strictly beyond the facet it was
    /// asked about (exact test).
    NotBeyond {
        /// The facet asked about.
        facet: FacetId,
        /// Its vertices (input indices).
        facet_vertices: [usize; D],
        /// The point returned.
        point: [f64; D],
        /// Its exact side of the facet's plane: [`Sign::Zero`] on it, [`Sign::Negative`] beneath.
        side: Sign,
    },
    /// [`PointSource::beyond`] returned a point with a coordinate that is not finite or is
    /// larger in magnitude than the hull's [`coordinate_bound`](crate::hull::StrategyHooks::coordinate_bound).
    OutOfRange {
        /// The facet asked about.
        facet: FacetId,
        /// Its vertices (input indices).
        facet_vertices: [usize; D],
        /// The point returned.
        point: [f64; D],
        /// The hull's coordinate bound.
        bound: f64,
    },
    /// [`Support::support_point`] returned, for the outside certificate's direction, a point
    /// with a coordinate that is not finite or is beyond the hull's coordinate bound: the
    /// certificate could not be checked against it.
    SupportOutOfRange {
        /// The direction asked about.
        direction: [f64; D],
        /// The point returned.
        point: [f64; D],
        /// The hull's coordinate bound.
        bound: f64,
    },
    /// The hull holds as many points as its indices can address (`u32::MAX`): the point
    /// returned for the facet could not be added.
    TooManyPoints {
        /// The facet asked about.
        facet: FacetId,
        /// The point returned.
        point: [f64; D],
    },
}

impl<const D: usize> fmt::Display for SourceError<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SourceError::NotBeyond {
                facet,
                facet_vertices,
                point,
                side,
            } => {
                let side = match side {
                    Sign::Zero => "on its plane",
                    _ => "beneath it",
                };
                write!(
                    f,
                    "PointSource::beyond returned {point:?} for facet {} (vertices \
                     {facet_vertices:?}), which is not strictly beyond it: the exact test puts \
                     it {side}",
                    facet.index()
                )
            }
            SourceError::OutOfRange {
                facet,
                facet_vertices,
                point,
                bound,
            } => write!(
                f,
                "PointSource::beyond returned {point:?} for facet {} (vertices \
                 {facet_vertices:?}), outside the hull's coordinate range (finite, magnitude at \
                 most {bound:e}: seed the input with the set's extreme points along every axis)",
                facet.index()
            ),
            SourceError::SupportOutOfRange {
                direction,
                point,
                bound,
            } => write!(
                f,
                "Support::support_point returned {point:?} for direction {direction:?}, outside \
                 the hull's coordinate range (finite, magnitude at most {bound:e}: seed the \
                 input with the set's extreme points along every axis)"
            ),
            SourceError::TooManyPoints { facet, point } => write!(
                f,
                "PointSource::beyond returned {point:?} for facet {}, but the hull already \
                 holds as many points as it can address ({})",
                facet.index(),
                u32::MAX
            ),
        }
    }
}

impl<const D: usize> std::error::Error for SourceError<D> {}
