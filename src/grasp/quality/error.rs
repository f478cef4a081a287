//! Why a grasp could not be evaluated.

use super::{MAX_WRENCH_COORDINATE, MINKOWSKI_MATERIALISE_LIMIT, Method, Metric};
use crate::hull::HullError;
use crate::strategy::SourceError;
use std::fmt;

/// Why a grasp could not be evaluated.
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
    Qhull(String),
    /// [`Method::Qhull`] in a build without the `qhull` feature.
    QhullUnavailable,
    /// [`Metric::Ows`] given to [`Evaluator`](super::Evaluator): Q_OWS needs the object's wrench space, so it is
    /// [`OwsEvaluator`](crate::grasp::ows::OwsEvaluator)'s.
    OwsNeedsWrenchSpace,
    /// A metric of [`Scorer`](crate::grasp::metrics::Scorer)'s (wrench resistance, the volume, the
    /// grasp-matrix metrics) given to [`Evaluator`](super::Evaluator), which computes Q1 and Q∞.
    NotEvaluatorMetric {
        /// The metric asked for.
        metric: Metric,
    },
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
    Ellipsoid(String),
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
            QualityError::NotEvaluatorMetric { metric } => write!(
                f,
                "metric {} is computed by pqhull::grasp::metrics::Scorer, not by Evaluator \
                 (which computes q1 and qinf)",
                metric.name()
            ),
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
            QualityError::Qhull(message) => write!(f, "qhull failed: {message}"),
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
                "Q_OWS needs the object's wrench space: evaluate it with an OwsEvaluator",
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
            QualityError::Ellipsoid(message) => write!(f, "no enclosing ellipsoid: {message}"),
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
            _ => None,
        }
    }
}
