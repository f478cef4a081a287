//! The one front door of the grasp metrics: [`Evaluator`] and [`evaluate_batch`], for every
//! [`Metric`] and [`Method`], giving one [`Evaluation`] or one [`QualityError`].

use super::Grasp;
use super::evaluation::{Bracket, Evaluation};
use super::metrics::{circumscribed, grasp_matrix_singular_values, volume_and_work};
use super::ows::{ObjectWrenchSpace, OwsEvaluator, evaluate_ows_batch};
use super::quality::{
    HullEvaluator, Method, Metric, Quality, QualityError, evaluate_hull_batch, find_or_make,
};
use std::time::Instant;

/// The object wrench space an evaluator evaluates against.
#[derive(Debug)]
enum Space<'a> {
    /// Not an OWS metric.
    None,
    /// Q_OWS: the caller's.
    Borrowed(&'a ObjectWrenchSpace),
    /// Wrench resistance: the one-disturbance space, built once.
    Owned(Box<ObjectWrenchSpace>),
}

/// Evaluates any [`Metric`] by one [`Method`] for many grasps, reusing its buffers (the hull's
/// arena, the partial strategy's queue, GJK's corral, the wrenches): the one way in to the grasp
/// metrics, and what `pqh grasp`, the planners and the Python package call.
///
/// Q1 and Q∞ are computed by the certified cascade (`grasp/pipeline.rs`); Q_OWS and wrench
/// resistance by the same steps with the disturbances' gauge; the cone bracket by two Q1
/// evaluations; the volume by the full hull and the grasp-matrix metrics by faer's SVD, with the
/// force-closure verdict by Q1 beside them (by the evaluator's method; the value is the same
/// whatever the method).
///
/// ```
/// use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric};
///
/// let contacts = [[1.0, 0.0, 0.0], [-0.5, 0.8, 0.0], [-0.5, -0.8, 0.3]].map(|d: [f64; 3]| {
///     let n = d.map(|x| -x / d.iter().map(|y| y * y).sum::<f64>().sqrt());
///     Contact::try_new(n.map(|x| -0.1 * x), n, None).unwrap()
/// });
/// let grasp = Grasp::builder(contacts.to_vec(), FrictionModel::try_new(0.6, 8)?)
///     .torque_scale(0.1)
///     .build()?;
/// let q1 = Evaluator::new(Metric::Q1, Method::Partial, None)?.evaluate(&grasp)?;
/// for metric in [Metric::Volume, Metric::SigmaMin, Metric::Isotropy, Metric::ConeBracket] {
///     let evaluation = Evaluator::new(metric, Method::Partial, None)?.evaluate(&grasp)?;
///     assert_eq!(evaluation.force_closure, q1.force_closure);
///     assert!(evaluation.value.unwrap() >= 0.0);
/// }
/// // Gravity, −z, at the centre: the grasp resists some multiple of it.
/// let gravity = Metric::Resist { wrench: [0.0, 0.0, -1.0, 0.0, 0.0, 0.0] };
/// let lift = Evaluator::new(gravity, Method::Partial, None)?.evaluate(&grasp)?;
/// assert!(lift.value.unwrap() > 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct Evaluator<'a> {
    metric: Metric,
    method: Method,
    /// Q1 or Q∞ (the verdict's Q1 for the volume, the grasp-matrix metrics and the cone
    /// bracket).
    hull: HullEvaluator,
    ows: OwsEvaluator,
    space: Space<'a>,
}

impl<'a> Evaluator<'a> {
    /// An evaluator of `metric` by `method`; `space` is the object's wrench space, which
    /// [`Metric::Ows`] needs and only it takes. Every refusal is made here, before any grasp.
    ///
    /// # Errors
    /// [`QualityError::UnsupportedMethod`] when `method` does not compute `metric`;
    /// [`QualityError::OwsNeedsWrenchSpace`] when `space` is missing for Q_OWS or given for
    /// another metric; [`QualityError::ResistedWrench`] for a zero or non-finite wrench to
    /// resist.
    pub fn new(
        metric: Metric,
        method: Method,
        space: Option<&'a ObjectWrenchSpace>,
    ) -> Result<Self, QualityError> {
        if !method.supports(metric) {
            return Err(QualityError::UnsupportedMethod { method, metric });
        }
        let space = match (metric, space) {
            (Metric::Ows, Some(space)) => Space::Borrowed(space),
            (Metric::Ows, None) | (_, Some(_)) => return Err(QualityError::OwsNeedsWrenchSpace),
            (Metric::Resist { wrench }, None) => Space::Owned(Box::new(resisted(wrench)?)),
            (_, None) => Space::None,
        };
        let hull_metric = match metric {
            Metric::QInf { .. } => metric,
            _ => Metric::Q1,
        };
        Ok(Evaluator {
            metric,
            method,
            hull: HullEvaluator::new(hull_metric, method),
            ows: OwsEvaluator::new(method),
            space,
        })
    }

    /// The metric evaluated.
    pub fn metric(&self) -> Metric {
        self.metric
    }

    /// The method used.
    pub fn method(&self) -> Method {
        self.method
    }

    /// Evaluates `grasp`: the exact metric on the caller's wrenches ([`Grasp::wrenches`]),
    /// found on snapped ones and certified on the raw ones (see
    /// [`quality`](crate::grasp::quality)'s module docs). For Q_OWS against a space built from
    /// a mesh, the grasp must use the mesh's torque frame
    /// ([`ObjectWrenchSpace::frame`]).
    ///
    /// # Errors
    /// [`QualityError::NonFiniteWrench`] when the torque scale overflows the wrenches;
    /// [`QualityError::WrenchTooLarge`] above
    /// [`MAX_WRENCH_COORDINATE`](crate::grasp::quality::MAX_WRENCH_COORDINATE);
    /// [`QualityError::MinkowskiTooLarge`] for Q∞ by a full method with too many points;
    /// [`QualityError::TorqueFrameMismatch`] for Q_OWS in another torque frame;
    /// [`QualityError::OwsValueOverflow`], [`QualityError::Ellipsoid`],
    /// [`QualityError::EllipsoidBoundary`], [`QualityError::CircumscribedFriction`],
    /// [`QualityError::VolumeOverflow`] and [`QualityError::SvdNoConvergence`] for their
    /// metrics; [`QualityError::QhullUnavailable`] (or a Qhull failure) for [`Method::Qhull`].
    pub fn evaluate(&mut self, grasp: &Grasp) -> Result<Evaluation, QualityError> {
        let started = Instant::now();
        let (metric, method) = (self.metric, self.method);
        let space = match &self.space {
            Space::None => None,
            Space::Borrowed(space) => Some(*space),
            Space::Owned(space) => Some(&**space),
        };
        if let Some(space) = space {
            return Ok(self
                .ows
                .evaluate(grasp, space)?
                .into_evaluation(metric, method));
        }
        let verdict = self.hull.evaluate(grasp)?;
        let mut evaluation = match metric {
            Metric::Q1 | Metric::QInf { .. } => return Ok(verdict.into_evaluation(metric, method)),
            Metric::Volume => {
                let (volume, hull) = volume_and_work(grasp)?;
                with_verdict(verdict, metric, method, volume, hull + verdict.stats)
            }
            Metric::SigmaMin => {
                let sigma = grasp_matrix_singular_values(grasp)?;
                with_verdict(verdict, metric, method, sigma[5], verdict.stats)
            }
            Metric::Isotropy => {
                let sigma = grasp_matrix_singular_values(grasp)?;
                let isotropy = if sigma[0] > 0.0 {
                    sigma[5] / sigma[0]
                } else {
                    0.0
                };
                with_verdict(verdict, metric, method, isotropy, verdict.stats)
            }
            Metric::ConeBracket => {
                let outer = circumscribed(grasp.friction())
                    .and_then(|friction| {
                        Grasp::builder(grasp.contacts().to_vec(), friction)
                            .torque_reference(grasp.torque_reference())
                            .torque_scale(grasp.torque_scale())
                            .build()
                    })
                    .map_err(QualityError::CircumscribedFriction)?;
                let outer = self.hull.evaluate(&outer)?;
                let mut evaluation = verdict.into_evaluation(metric, method);
                evaluation.bracket = Some(Bracket {
                    low: verdict.value - accuracy(&verdict),
                    high: outer.value + accuracy(&outer),
                });
                evaluation.stats = verdict.stats + outer.stats;
                evaluation
            }
            // `new` took the space these need.
            Metric::Ows | Metric::Resist { .. } => {
                return Err(QualityError::OwsNeedsWrenchSpace);
            }
        };
        evaluation.stats.elapsed = started.elapsed();
        Ok(evaluation)
    }
}

/// The one-disturbance space of wrench resistance.
fn resisted(wrench: [f64; 6]) -> Result<ObjectWrenchSpace, QualityError> {
    ObjectWrenchSpace::from_disturbances(vec![wrench]).map_err(QualityError::ResistedWrench)
}

/// A metric's `value` with Q1's force-closure verdict beside it (no deciding wrenches: they
/// decide Q1, not this value).
fn with_verdict(
    verdict: Quality,
    metric: Metric,
    method: Method,
    value: f64,
    stats: crate::hull::Stats,
) -> Evaluation {
    let mut evaluation = Evaluation::new(metric, method, verdict.force_closure, Some(value), stats);
    evaluation.scale = Some(verdict.scale);
    evaluation
}

/// The accuracy the evaluator promises for Q1's `q` (1e−12 relative, or 1e−14 of the wrench
/// scale near zero): how far the cone bracket's ends are widened so that it holds however near
/// zero the values are.
fn accuracy(q: &Quality) -> f64 {
    (1e-12 * q.value.abs()).max(1e-14 * q.scale)
}

/// Evaluates every grasp by `metric` and `method` (`space`: the object's wrench space, for
/// [`Metric::Ows`] only), results in input order: on all cores (rayon's current pool) with the
/// `parallel` feature, else one after another. The one batch call for every metric, and the one
/// per-thread reuse: each worker thread keeps its evaluators for the life of the thread (rayon's
/// `map_init` would make one per job it splits off, a cold hull arena each time, which cost a
/// quarter of the two-thread speed-up on batches of small grasps); the resisted wrench's space is
/// built once for the batch. Run it inside [`with_threads`](crate::grasp::with_threads) to
/// choose the number of threads.
///
/// ```
/// use pqhull::grasp::{evaluate_batch, Evaluator, FrictionModel, Grasp, Method, Metric};
/// use pqhull::geometry::Rng;
///
/// let friction = FrictionModel::try_new(0.5, 6)?;
/// let mut rng = Rng::new(2);
/// let grasps: Vec<Grasp> =
///     (0..8).map(|_| Grasp::random_on_box(&mut rng, [0.5, 0.2, 0.1], 4, friction)).collect();
/// for metric in [Metric::Q1, Metric::Volume, Metric::Isotropy] {
///     let batch = evaluate_batch(&grasps, metric, Method::Partial, None)?;
///     let mut one = Evaluator::new(metric, Method::Partial, None)?;
///     for (evaluation, grasp) in batch.iter().zip(&grasps) {
///         let (a, b) = (evaluation.as_ref().unwrap(), one.evaluate(grasp)?);
///         assert_eq!((a.force_closure, a.value), (b.force_closure, b.value));
///     }
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`Evaluator::new`], before any grasp is evaluated; each grasp's own error in its entry.
pub fn evaluate_batch(
    grasps: &[Grasp],
    metric: Metric,
    method: Method,
    space: Option<&ObjectWrenchSpace>,
) -> Result<Vec<Result<Evaluation, QualityError>>, QualityError> {
    // The refusals of `Evaluator::new`, once: every entry below would repeat them.
    Evaluator::new(metric, method, space)?;
    let ows = |space: &ObjectWrenchSpace| {
        evaluate_ows_batch(grasps, space, method)
            .into_iter()
            .map(|r| r.map(|q| q.into_evaluation(metric, method)))
            .collect()
    };
    Ok(match (metric, space) {
        (Metric::Q1 | Metric::QInf { .. }, _) => evaluate_hull_batch(grasps, metric, method)
            .into_iter()
            .map(|r| r.map(|q| q.into_evaluation(metric, method)))
            .collect(),
        (Metric::Ows, Some(space)) => ows(space),
        (Metric::Resist { wrench }, _) => ows(&resisted(wrench)?),
        _ => super::map_in_order(grasps, |grasp| {
            EVALUATORS.with_borrow_mut(|kept| {
                let evaluator = find_or_make(
                    kept,
                    |e| e.metric == metric && e.method == method,
                    || Evaluator::new(metric, method, None).expect("checked above"),
                );
                evaluator.evaluate(grasp)
            })
        }),
    })
}

thread_local! {
    /// The evaluators of [`evaluate_batch`] on this thread (metrics without a wrench space), one
    /// per (metric, method) used.
    static EVALUATORS: std::cell::RefCell<Vec<Evaluator<'static>>> = const {
        std::cell::RefCell::new(Vec::new())
    };
}
