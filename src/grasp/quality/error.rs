//! Why a grasp could not be evaluated: the one error of every metric.

use super::{MAX_WRENCH_COORDINATE, MINKOWSKI_MATERIALISE_LIMIT, Method, Metric};
use crate::geometry::EllipsoidError;
use crate::grasp::GraspError;
use crate::grasp::ows::OwsError;
use crate::hull::HullError;
use crate::strategy::SourceError;
use std::fmt;

/// Why a grasp could not be evaluated, by any metric and method: the one error of
/// [`Evaluator`](crate::grasp::Evaluator) and of every metric function. Wrapped errors are given
/// by [`source`](std::error::Error::source).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum QualityError {
    /// A wrench overflowed (a friction coefficient, a lever arm or the inverse torque scale too
    /// large for `f64`).
    NonFiniteWrench,
    /// A wrench coordinate above [`MAX_WRENCH_COORDINATE`].
    WrenchTooLarge {
        /// The largest wrench coordinate (absolute value).
        largest: f64,
    },
    /// The full or Qhull method would have to materialise more Minkowski points than
    /// [`MINKOWSKI_MATERIALISE_LIMIT`] (`None`: more than `usize::MAX`).
    MinkowskiTooLarge {
        /// k^m (or (k+1)^m with the zero wrench).
        points: Option<usize>,
    },
    /// Qhull failed (feature `qhull`).
    #[cfg(feature = "qhull")]
    Qhull(crate::qhull_baseline::QhullError),
    /// [`Method::Qhull`] in a build without the `qhull` feature.
    QhullUnavailable,
    /// [`Metric::Ows`] without the object's wrench space, or a wrench space given for another
    /// metric ([`Evaluator::new`](crate::grasp::Evaluator::new)).
    OwsNeedsWrenchSpace,
    /// The method does not compute this metric (see [`Method`]).
    UnsupportedMethod {
        /// The method asked for.
        method: Method,
        /// The metric asked for.
        metric: Metric,
    },
    /// Q_OWS: the grasp's torque frame is not the object wrench space's (build the grasp with
    /// [`ObjectWrenchSpace::frame`](crate::grasp::ows::ObjectWrenchSpace::frame)).
    TorqueFrameMismatch {
        /// The grasp's (torque reference, torque scale).
        grasp: ([f64; 3], f64),
        /// The space's.
        space: ([f64; 3], f64),
    },
    /// Q_OWS (or wrench resistance) beyond `f64::MAX`: the disturbances are so small beside the
    /// grasp's wrenches (1e−310 against 1, say) that the multiple of them it resists is not
    /// representable.
    OwsValueOverflow,
    /// Q_OWS by the ellipsoid method: no enclosing ellipsoid (the disturbances span fewer than six
    /// dimensions).
    Ellipsoid(EllipsoidError),
    /// Q_OWS by the ellipsoid method: the grasp is force closure, but Q1 of its wrenches mapped
    /// by the ellipsoid is no positive number (the origin within rounding of the mapped hull's
    /// boundary), so there is no approximate value.
    EllipsoidBoundary {
        /// Q1 of the mapped wrenches.
        mapped_q1: f64,
    },
    /// [`Metric::ConeBracket`]: the circumscribed pyramids' friction coefficient, μ / cos(π/k),
    /// is refused (it overflows). Through [`Evaluator`](crate::grasp::Evaluator) the inscribed
    /// Q1, computed first, refuses such a friction already ([`QualityError::WrenchTooLarge`]:
    /// μ > 1e100); this variant keeps the circumscribed grasp's construction from being
    /// assumed infallible.
    CircumscribedFriction(GraspError),
    /// [`Metric::Resist`]: the wrench to resist is zero, or has a NaN or infinite coordinate.
    ResistedWrench(OwsError),
    /// [`Metric::SigmaMin`] or [`Metric::Isotropy`]: the grasp matrix's singular value
    /// decomposition did not converge (not seen on finite input).
    SvdNoConvergence,
    /// [`Metric::Volume`]: the volume is beyond `f64::MAX` (wrench coordinates near the metrics'
    /// limit of 1e100 in every direction): not representable.
    VolumeOverflow,
    /// The hull engine refused the wrench set for a reason other than its being flat (which the
    /// metrics answer without a hull): not expected of a grasp's checked wrenches, reported
    /// rather than assumed away.
    Hull(HullError),
    /// The implicit Minkowski sum broke the partial hull's point-source contract (a point not
    /// strictly beyond the facet it was asked about, or out of the seeds' range): a bug of
    /// Q∞'s own source, reported rather than assumed away.
    Source(SourceError<6>),
}

impl fmt::Display for QualityError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            QualityError::OwsValueOverflow => write!(
                f,
                "the multiple of the disturbances the grasp resists is beyond f64::MAX: the \
                 disturbances (or the wrench to resist) are too small for the grasp's units; \
                 scale them up"
            ),
            QualityError::NonFiniteWrench => write!(
                f,
                "a wrench is not finite: the friction coefficient, a lever arm or 1/torque_scale \
                 overflows f64"
            ),
            QualityError::WrenchTooLarge { largest } => write!(
                f,
                "a wrench coordinate is {largest:e}, above the {MAX_WRENCH_COORDINATE:e} the \
                 metrics accept (their squared norms would overflow): use other units (positions, \
                 torque_scale) or a smaller friction coefficient"
            ),
            QualityError::MinkowskiTooLarge { points } => {
                let count = points.map_or("more than usize::MAX".to_string(), |p| p.to_string());
                write!(
                    f,
                    "the Minkowski sum has {count} points, more than the {MINKOWSKI_MATERIALISE_LIMIT} \
                     the full and qhull methods materialise; use the partial method"
                )
            }
            #[cfg(feature = "qhull")]
            QualityError::Qhull(e) => write!(f, "qhull failed: {e}"),
            QualityError::UnsupportedMethod { method, metric } => {
                let takes: Vec<&str> = [
                    Method::Partial,
                    Method::Full,
                    Method::Qhull,
                    Method::PartialRays,
                    Method::Ellipsoid,
                ]
                .into_iter()
                .filter(|m| m.supports(*metric))
                .map(Method::name)
                .collect();
                write!(
                    f,
                    "the {} method does not compute {} (it takes {})",
                    method.name(),
                    metric.name(),
                    takes.join(", ")
                )
            }
            QualityError::OwsNeedsWrenchSpace => f.write_str(
                "Q_OWS needs the object's wrench space, and only Q_OWS takes one",
            ),
            QualityError::QhullUnavailable => f.write_str(
                "the Qhull method needs pqhull built with the `qhull` feature (which needs libclang)",
            ),
            QualityError::TorqueFrameMismatch { grasp, space } => write!(
                f,
                "the grasp's torque frame (reference {:?}, scale {}) is not the object wrench \
                 space's (reference {:?}, scale {})",
                grasp.0, grasp.1, space.0, space.1
            ),
            QualityError::Ellipsoid(e) => write!(f, "no enclosing ellipsoid: {e}"),
            QualityError::EllipsoidBoundary { mapped_q1 } => write!(
                f,
                "no enclosing ellipsoid usable for this grasp: it is force closure, but Q1 of its \
                 wrenches mapped by the ellipsoid is {mapped_q1} (the origin within rounding of \
                 the mapped hull's boundary), so there is no approximate value"
            ),
            QualityError::CircumscribedFriction(e) => {
                write!(f, "the circumscribed friction pyramids: {e}")
            }
            QualityError::ResistedWrench(OwsError::AllZero) => {
                write!(
                    f,
                    "the wrench to resist is zero: every multiple of it is resisted"
                )
            }
            QualityError::ResistedWrench(OwsError::NonFinite { .. }) => {
                write!(f, "the wrench to resist has a NaN or infinite coordinate")
            }
            QualityError::ResistedWrench(e) => write!(f, "the wrench to resist: {e}"),
            QualityError::SvdNoConvergence => {
                f.write_str("grasp matrix: the singular value decomposition did not converge")
            }
            QualityError::VolumeOverflow => write!(
                f,
                "the grasp wrench space's volume is beyond f64::MAX (1.8e308): use other units \
                 (positions, torque_scale) or a smaller friction coefficient"
            ),
            QualityError::Hull(e) => write!(f, "the hull engine refused the wrenches: {e}"),
            QualityError::Source(e) => write!(f, "internal error in Q∞'s Minkowski sum: {e}"),
        }
    }
}

impl std::error::Error for QualityError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            QualityError::Hull(e) => Some(e),
            QualityError::Source(e) => Some(e),
            #[cfg(feature = "qhull")]
            QualityError::Qhull(e) => Some(e),
            QualityError::Ellipsoid(e) => Some(e),
            QualityError::CircumscribedFriction(e) => Some(e),
            QualityError::ResistedWrench(e) => Some(e),
            _ => None,
        }
    }
}
