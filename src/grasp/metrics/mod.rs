//! The other metrics planners rank grasps by, beside Q1, Q∞ and Q_OWS:
//!
//! * [`cone_bracket`] — Q1 of the true circular friction cones, bracketed: the k-edge pyramid
//!   inscribed in each cone gives a lower bound, the one circumscribed about it (rim scaled by
//!   1/cos(π/k)) an upper bound; both by partial hulls;
//! * [`resist`] — how large a multiple of one given wrench (gravity at the centre of mass, say)
//!   the grasp resists: Q_OWS with that single disturbance, by the partial hull;
//! * [`gws_volume`] — the volume of the grasp wrench space (the full hull: a volume needs every
//!   facet, so there is no partial shortcut);
//! * [`grasp_matrix`] and [`GraspMatrix`] — the smallest singular value of the grasp matrix and
//!   the isotropy index σ_min / σ_max;
//! * [`Scorer`] — any [`Metric`] (these and Q1, Q∞, Q_OWS) through one call giving one
//!   [`Score`], which is what `pqh plan --metric` ranks by.
//!
//! ```
//! use pqhull::grasp::metrics::{cone_bracket, grasp_matrix_metrics, resist};
//! use pqhull::grasp::quality::Method;
//! use pqhull::grasp::{Contact, FrictionModel, Grasp};
//!
//! // Three fingers around a ball of radius 0.1, pushing toward its centre.
//! let contacts = [[1.0, 0.0, 0.0], [-0.5, 0.8, 0.0], [-0.5, -0.8, 0.3]]
//!     .map(|d: [f64; 3]| {
//!         let n = d.map(|x| -x / d.iter().map(|y| y * y).sum::<f64>().sqrt());
//!         Contact::try_new(n.map(|x| -0.1 * x), n, None).unwrap()
//!     });
//! let grasp = Grasp::builder(contacts.to_vec(), FrictionModel::try_new(0.6, 8)?)
//!     .torque_scale(0.1)
//!     .build()?;
//! let bracket = cone_bracket(&grasp, Method::Partial)?;
//! assert!(bracket.low() <= bracket.high());
//! // Gravity, -z, at the centre: the grasp resists some multiple of it.
//! let lift = resist(&grasp, [0.0, 0.0, -1.0, 0.0, 0.0, 0.0], Method::Partial)?;
//! assert!(lift.value.unwrap() > 0.0);
//! let g = grasp_matrix_metrics(&grasp)?;
//! assert!(g.sigma_min() > 0.0 && g.isotropy() <= 1.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::ows::{ObjectWrenchSpace, OwsError, OwsEvaluator, OwsQuality};
use super::quality::{Evaluator, Method, Metric, Quality, QualityError};
use super::{FrictionModel, Grasp, GraspError};
use crate::geometry::vector::cross;
use crate::hull::{Hull, HullError, Stats};
use std::f64::consts::PI;
use std::fmt;
use std::time::Instant;

mod scorer;

pub use scorer::{Score, Scorer, score_batch};

/// Why a metric could not be computed.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum MetricError {
    /// The circumscribed cones' grasp could not be built (its friction coefficient overflowed).
    Grasp(GraspError),
    /// The evaluation failed.
    Quality(QualityError),
    /// The wrench to resist is zero, or has a NaN or infinite coordinate.
    Wrench(OwsError),
    /// The hull of the wrenches failed for a reason other than a flat set.
    Hull(HullError),
    /// The singular value decomposition did not converge.
    Svd(String),
    /// The GWS volume is beyond `f64::MAX` (wrench coordinates near the metrics' limit of
    /// 1e100 in every direction): not representable.
    VolumeOverflow,
}

impl fmt::Display for MetricError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MetricError::Grasp(e) => write!(f, "{e}"),
            MetricError::Quality(e) => write!(f, "{e}"),
            MetricError::Wrench(OwsError::AllZero) => {
                write!(
                    f,
                    "the wrench to resist is zero: every multiple of it is resisted"
                )
            }
            MetricError::Wrench(OwsError::NonFinite { .. }) => {
                write!(f, "the wrench to resist has a NaN or infinite coordinate")
            }
            MetricError::Wrench(e) => write!(f, "the wrench to resist: {e}"),
            MetricError::Hull(e) => write!(f, "{e}"),
            MetricError::Svd(e) => write!(f, "grasp matrix: {e}"),
            MetricError::VolumeOverflow => write!(
                f,
                "the grasp wrench space's volume is beyond f64::MAX (1.8e308): use other units \
                 (positions, torque_scale) or a smaller friction coefficient"
            ),
        }
    }
}

impl std::error::Error for MetricError {
    /// The wrapped error, as [`QualityError`]'s variants give theirs.
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            MetricError::Grasp(e) => Some(e),
            MetricError::Quality(e) => Some(e),
            MetricError::Wrench(e) => Some(e),
            MetricError::Hull(e) => Some(e),
            MetricError::Svd(_) | MetricError::VolumeOverflow => None,
        }
    }
}

impl From<QualityError> for MetricError {
    fn from(e: QualityError) -> Self {
        MetricError::Quality(e)
    }
}

/// Q1 of the pyramids inscribed in the friction cones and of those circumscribed about them:
/// Q1 of the true circular cones lies between the two.
///
/// Why it is a bracket: with every force's normal component 1, a cone's forces form a disc of
/// radius μ; the k-edge pyramid's forces form the inscribed k-gon, and the pyramid with the rim
/// scaled by 1/cos(π/k) the circumscribed one. The grasp wrench spaces nest the same way (each
/// is the hull of the contacts' force sets mapped linearly to wrenches), and the signed distance
/// from the origin to a convex set's boundary only grows with the set. Exact in the model; the
/// wrenches themselves carry their computation's rounding (≈ 1e−16 of their size), far below the
/// width, 1 − cos(π/k) in relative terms.
#[derive(Clone, Debug, PartialEq)]
pub struct ConeBracket {
    /// Q1 with the k-edge pyramids inscribed in the cones (the usual Q1).
    pub inscribed: Quality,
    /// Q1 with the pyramids circumscribed about the cones.
    pub circumscribed: Quality,
}

/// The accuracy the evaluator promises for `q` ([`Quality::value`]: 1e−12 relative, or
/// 1e−14 of the wrench scale near zero).
fn accuracy(q: &Quality) -> f64 {
    (1e-12 * q.value.abs()).max(1e-14 * q.scale)
}

impl ConeBracket {
    /// The lower bound on Q1 of the circular cones: the inscribed pyramids' Q1 less its
    /// evaluation's accuracy, so that the bracket holds however near zero the values are.
    pub fn low(&self) -> f64 {
        self.inscribed.value - accuracy(&self.inscribed)
    }

    /// The upper bound: the circumscribed pyramids' Q1 plus its evaluation's accuracy.
    pub fn high(&self) -> f64 {
        self.circumscribed.value + accuracy(&self.circumscribed)
    }
}

/// The friction model whose k-edge pyramid circumscribes `friction`'s cone: the same k, μ
/// divided by cos(π/k), rounded up (by 4 ulps, more than the rounding of the division and of the
/// cosine) so that the pyramid still contains the cone.
///
/// # Errors
/// [`GraspError::InvalidFriction`] if μ / cos(π/k) overflows.
pub fn circumscribed(friction: FrictionModel) -> Result<FrictionModel, GraspError> {
    let k = friction.cone_edges();
    let mu = friction.friction() / (PI / k as f64).cos() * (1.0 + 4.0 * f64::EPSILON);
    FrictionModel::try_new(mu, k)
}

/// [`ConeBracket`] of `grasp`, both Q1 values by `method`.
///
/// # Errors
/// [`MetricError::Grasp`] if the circumscribed friction overflows; [`MetricError::Quality`] as
/// [`Evaluator::evaluate`].
pub fn cone_bracket(grasp: &Grasp, method: Method) -> Result<ConeBracket, MetricError> {
    let mut evaluator = Evaluator::new(Metric::Q1, method);
    let inscribed = evaluator.evaluate(grasp).map_err(MetricError::Quality)?;
    let outer = circumscribed(grasp.friction()).map_err(MetricError::Grasp)?;
    let outer = Grasp::builder(grasp.contacts().to_vec(), outer)
        .torque_reference(grasp.torque_reference())
        .torque_scale(grasp.torque_scale())
        .build()
        .map_err(MetricError::Grasp)?;
    let circumscribed = evaluator.evaluate(&outer).map_err(MetricError::Quality)?;
    Ok(ConeBracket {
        inscribed,
        circumscribed,
    })
}

/// The largest t such that the grasp resists the wrench `−t·wrench`: Q_OWS with `wrench` as the
/// only disturbance ([`ObjectWrenchSpace::from_disturbances`]), so it equals `pqh grasp --metric
/// ows --disturbances` with that one row. `wrench` is in the grasp's own torque units (torque
/// divided by its torque scale), like a disturbance row. As for Q_OWS, the value is `None` when
/// the grasp is not force closure.
///
/// # Errors
/// [`MetricError::Wrench`] for a zero or non-finite wrench; [`MetricError::Quality`] as
/// [`OwsEvaluator::evaluate`] (the ellipsoid method has no ellipsoid around one wrench).
pub fn resist(grasp: &Grasp, wrench: [f64; 6], method: Method) -> Result<OwsQuality, MetricError> {
    let space = ObjectWrenchSpace::from_disturbances(vec![wrench]).map_err(MetricError::Wrench)?;
    OwsEvaluator::new(method)
        .evaluate(grasp, &space)
        .map_err(MetricError::Quality)
}

/// The volume of the grasp wrench space (the hull of the Q1 wrenches), from the full hull: a
/// volume needs every facet, so no partial hull can give it. 0 for wrenches spanning fewer than
/// six dimensions: a lower-dimensional set has no volume. A set flat only in exact arithmetic
/// (two contacts: their wrenches have no moment about the line through them) is, once computed,
/// usually full-dimensional by its rounding, and gets a volume of that order (2.5e−20 for the
/// pinch in `tests/metrics.rs`), which is the exact answer for those wrenches, up to the
/// floating-point volume sum.
///
/// Returns the volume and the full hull's work.
///
/// # Errors
/// [`MetricError::Hull`] for non-finite wrenches (a torque scale far too small);
/// [`MetricError::VolumeOverflow`] for a volume beyond `f64::MAX`.
pub fn gws_volume(grasp: &Grasp) -> Result<(f64, Stats), MetricError> {
    let started = Instant::now();
    match Hull::try_new(&grasp.wrenches()) {
        Ok(hull) => {
            let volume = hull.volume();
            if volume == f64::INFINITY {
                return Err(MetricError::VolumeOverflow);
            }
            let mut stats = hull.stats();
            stats.elapsed = started.elapsed();
            Ok((volume, stats))
        }
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
            let stats = Stats {
                elapsed: started.elapsed(),
                ..Stats::default()
            };
            Ok((0.0, stats))
        }
        Err(e) => Err(MetricError::Hull(e)),
    }
}

/// The grasp matrix G as its columns: contact i's force along axis a maps to the wrench
/// `[e_a; (p_i − c) × e_a / ρ]`, in the grasp's torque frame (the same map as
/// [`Grasp::wrenches`]); a soft contact adds a fourth column, its torsional moment about the
/// normal, `[0; n_i / ρ]`. Its singular values do not depend on the frame chosen at each contact.
pub fn grasp_matrix(grasp: &Grasp) -> Vec<[f64; 6]> {
    let (c, rho) = (grasp.torque_reference(), grasp.torque_scale());
    let mut columns = Vec::with_capacity(3 * grasp.contact_count());
    for contact in grasp.contacts() {
        let p = contact.position();
        let r = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
        for a in 0..3 {
            let mut e = [0.0; 3];
            e[a] = 1.0;
            let t = cross(r, e);
            columns.push([e[0], e[1], e[2], t[0] / rho, t[1] / rho, t[2] / rho]);
        }
        if contact.is_soft() {
            let n = contact.normal();
            columns.push([0.0, 0.0, 0.0, n[0] / rho, n[1] / rho, n[2] / rho]);
        }
    }
    columns
}

/// The singular values of the grasp matrix, largest first; six of them (zeros beyond 3m for a
/// single contact).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GraspMatrix {
    /// σ_1 ≥ … ≥ σ_6 ≥ 0.
    pub singular_values: [f64; 6],
}

impl GraspMatrix {
    /// The smallest singular value: how weakly the grasp's contact forces reach the worst
    /// direction of wrench space. Near 0 (within about 1e−15 · σ_max of it) for a rank-deficient
    /// matrix: two contacts cannot act about the line through them.
    pub fn sigma_min(&self) -> f64 {
        self.singular_values[5]
    }

    /// The largest singular value.
    pub fn sigma_max(&self) -> f64 {
        self.singular_values[0]
    }

    /// The isotropy index σ_min / σ_max, in [0, 1] (0 when σ_max is 0).
    pub fn isotropy(&self) -> f64 {
        if self.sigma_max() > 0.0 {
            self.sigma_min() / self.sigma_max()
        } else {
            0.0
        }
    }
}

/// The grasp matrix's singular values ([`GraspMatrix`]), by faer's SVD.
///
/// # Errors
/// [`MetricError::Svd`] if the decomposition does not converge (not seen on finite input).
pub fn grasp_matrix_metrics(grasp: &Grasp) -> Result<GraspMatrix, MetricError> {
    let columns = grasp_matrix(grasp);
    let g = faer::Mat::from_fn(6, columns.len(), |i, j| columns[j][i]);
    let values = g
        .as_ref()
        .singular_values()
        .map_err(|e| MetricError::Svd(format!("{e:?}")))?;
    let mut singular_values = [0.0; 6];
    for (s, v) in singular_values.iter_mut().zip(values) {
        *s = v;
    }
    Ok(GraspMatrix { singular_values })
}
