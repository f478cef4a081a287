//! One call for every metric: what a planner, `pqh grasp` and the Python batch rank grasps by.

use super::{MetricError, grasp_matrix_metrics, gws_volume};
use crate::grasp::Grasp;
use crate::grasp::ows::{ObjectWrenchSpace, OwsEvaluator, evaluate_ows_batch};
use crate::grasp::quality::{
    Evaluator, Method, Metric, QualityError, evaluate_batch, find_or_make,
};
use crate::hull::Stats;
use std::time::Instant;

/// One grasp's score by a [`Scorer`]: the shape every metric shares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Score {
    /// Whether the grasp is force closure. Q1, Q∞ and Q_OWS decide it with their value; the
    /// volume and the grasp-matrix metrics by Q1 beside it, by the scorer's method.
    pub force_closure: bool,
    /// The metric's value. `None` only for Q_OWS and wrench resistance of a grasp that is not
    /// force closure (no multiple of the disturbances is resisted, not even zero times them).
    pub value: Option<f64>,
    /// The work done: the hull's (for the volume: its full hull's plus the verdict's), and the
    /// wall time of the whole call.
    pub stats: Stats,
}

/// The object wrench space a scorer evaluates against.
#[derive(Debug)]
enum Space<'a> {
    /// Not an OWS metric.
    None,
    /// Q_OWS: the caller's.
    Borrowed(&'a ObjectWrenchSpace),
    /// Wrench resistance: the one-disturbance space, built once.
    Owned(Box<ObjectWrenchSpace>),
}

/// Computes any [`Metric`] by one [`Method`] for many grasps, reusing its evaluators' buffers.
///
/// Q1 and Q∞ go to an [`Evaluator`], Q_OWS and wrench resistance to an [`OwsEvaluator`], the
/// volume to [`gws_volume`] and the grasp-matrix metrics to [`grasp_matrix_metrics`]; for those
/// last three the method decides how the force-closure verdict (Q1) is computed, and the value is
/// the same whatever the method.
///
/// ```
/// use pqhull::grasp::metrics::Scorer;
/// use pqhull::grasp::quality::{q1, Method, Metric};
/// use pqhull::grasp::{Contact, FrictionModel, Grasp};
///
/// let contacts = [[1.0, 0.0, 0.0], [-0.5, 0.8, 0.0], [-0.5, -0.8, 0.3]].map(|d: [f64; 3]| {
///     let n = d.map(|x| -x / d.iter().map(|y| y * y).sum::<f64>().sqrt());
///     Contact::try_new(n.map(|x| -0.1 * x), n, None).unwrap()
/// });
/// let grasp = Grasp::builder(contacts.to_vec(), FrictionModel::try_new(0.6, 8)?)
///     .torque_scale(0.1)
///     .build()?;
/// for metric in [Metric::Q1, Metric::Volume, Metric::SigmaMin, Metric::Isotropy] {
///     let score = Scorer::new(metric, Method::Partial, None)?.score(&grasp)?;
///     assert_eq!(score.force_closure, q1(&grasp)?.force_closure);
///     assert!(score.value.unwrap() >= 0.0);
/// }
/// let gravity = Metric::Resist { wrench: [0.0, 0.0, -1.0, 0.0, 0.0, 0.0] };
/// assert!(Scorer::new(gravity, Method::Partial, None)?.score(&grasp)?.value.unwrap() > 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct Scorer<'a> {
    metric: Metric,
    method: Method,
    /// Q1 or Q∞ (the verdict's Q1 for the volume and the grasp-matrix metrics).
    hull: Evaluator,
    ows: OwsEvaluator,
    space: Space<'a>,
}

impl<'a> Scorer<'a> {
    /// A scorer of `metric` by `method`; `space` is the object's wrench space, which
    /// [`Metric::Ows`] needs and only it takes.
    ///
    /// # Errors
    /// [`MetricError::Quality`] with [`QualityError::UnsupportedMethod`] when `method` does not
    /// compute `metric`, or [`QualityError::OwsNeedsWrenchSpace`] when `space` is missing for Q_OWS
    /// or given for another metric; [`MetricError::Wrench`] for a zero or non-finite wrench to
    /// resist.
    pub fn new(
        metric: Metric,
        method: Method,
        space: Option<&'a ObjectWrenchSpace>,
    ) -> Result<Self, MetricError> {
        if !method.supports(metric) {
            return Err(MetricError::Quality(QualityError::UnsupportedMethod {
                method,
                metric,
            }));
        }
        let space = match (metric, space) {
            (Metric::Ows, Some(space)) => Space::Borrowed(space),
            (Metric::Ows, None) | (_, Some(_)) => {
                return Err(MetricError::Quality(QualityError::OwsNeedsWrenchSpace));
            }
            (Metric::Resist { wrench }, None) => Space::Owned(Box::new(
                ObjectWrenchSpace::from_disturbances(vec![wrench]).map_err(MetricError::Wrench)?,
            )),
            (_, None) => Space::None,
        };
        let hull_metric = match metric {
            Metric::QInf { .. } => metric,
            _ => Metric::Q1,
        };
        Ok(Scorer {
            metric,
            method,
            hull: Evaluator::new(hull_metric, method),
            ows: OwsEvaluator::new(method),
            space,
        })
    }

    /// The metric scored.
    pub fn metric(&self) -> Metric {
        self.metric
    }

    /// The method used.
    pub fn method(&self) -> Method {
        self.method
    }

    /// Scores `grasp`.
    ///
    /// # Errors
    /// As the metric's own call: [`Evaluator::evaluate`], [`OwsEvaluator::evaluate`],
    /// [`gws_volume`], [`grasp_matrix_metrics`].
    pub fn score(&mut self, grasp: &Grasp) -> Result<Score, MetricError> {
        let started = Instant::now();
        let space = match &self.space {
            Space::None => None,
            Space::Borrowed(space) => Some(*space),
            Space::Owned(space) => Some(&**space),
        };
        if let Some(space) = space {
            let q = self.ows.evaluate(grasp, space)?;
            return Ok(Score {
                force_closure: q.force_closure,
                value: q.value,
                stats: q.stats,
            });
        }
        let verdict = self.hull.evaluate(grasp)?;
        let (value, mut stats) = match self.metric {
            Metric::Volume => {
                let (volume, hull) = gws_volume(grasp)?;
                (volume, hull + verdict.stats)
            }
            Metric::SigmaMin => (grasp_matrix_metrics(grasp)?.sigma_min(), verdict.stats),
            Metric::Isotropy => (grasp_matrix_metrics(grasp)?.isotropy(), verdict.stats),
            _ => (verdict.value, verdict.stats),
        };
        stats.elapsed = started.elapsed();
        Ok(Score {
            force_closure: verdict.force_closure,
            value: Some(value),
            stats,
        })
    }
}

/// Scores every grasp by `metric` and `method` (`space`: the object's wrench space, for
/// [`Metric::Ows`] only), results in input order: on all cores (rayon's current pool) with the
/// `parallel` feature, else one after another. The one batch call for every metric, and the one
/// per-thread reuse: Q1 and Q∞ go through
/// [`evaluate_batch`](crate::grasp::quality::evaluate_batch), Q_OWS and wrench resistance
/// through [`evaluate_ows_batch`] (the resisted wrench's space built once for the batch), and
/// the volume and the grasp-matrix metrics through one [`Scorer`] per worker thread, kept for
/// the life of the thread (rayon's `map_init` would make one per job it splits off).
///
/// ```
/// use pqhull::grasp::metrics::{score_batch, Scorer};
/// use pqhull::grasp::quality::{Method, Metric};
/// use pqhull::grasp::{FrictionModel, Grasp};
/// use pqhull::geometry::Rng;
///
/// let friction = FrictionModel::try_new(0.5, 6)?;
/// let mut rng = Rng::new(2);
/// let grasps: Vec<Grasp> =
///     (0..8).map(|_| Grasp::random_on_box(&mut rng, [0.5, 0.2, 0.1], 4, friction)).collect();
/// for metric in [Metric::Q1, Metric::Volume, Metric::Isotropy] {
///     let scores = score_batch(&grasps, metric, Method::Partial, None)?;
///     let mut one = Scorer::new(metric, Method::Partial, None)?;
///     for (score, grasp) in scores.iter().zip(&grasps) {
///         let (a, b) = (score.as_ref().unwrap(), one.score(grasp)?);
///         assert_eq!((a.force_closure, a.value), (b.force_closure, b.value));
///     }
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`Scorer::new`], before any grasp is scored; each grasp's own error in its entry.
pub fn score_batch(
    grasps: &[Grasp],
    metric: Metric,
    method: Method,
    space: Option<&ObjectWrenchSpace>,
) -> Result<Vec<Result<Score, MetricError>>, MetricError> {
    // The refusals of `Scorer::new`, once: every entry below would repeat them.
    Scorer::new(metric, method, space)?;
    let ows = |space: &ObjectWrenchSpace| {
        evaluate_ows_batch(grasps, space, method)
            .into_iter()
            .map(|r| {
                r.map(|q| Score {
                    force_closure: q.force_closure,
                    value: q.value,
                    stats: q.stats,
                })
                .map_err(MetricError::Quality)
            })
            .collect()
    };
    Ok(match (metric, space) {
        (Metric::Q1 | Metric::QInf { .. }, _) => evaluate_batch(grasps, metric, method)
            .into_iter()
            .map(|r| {
                r.map(|q| Score {
                    force_closure: q.force_closure,
                    value: Some(q.value),
                    stats: q.stats,
                })
                .map_err(MetricError::Quality)
            })
            .collect(),
        (Metric::Ows, Some(space)) => ows(space),
        (Metric::Resist { wrench }, _) => {
            let space =
                ObjectWrenchSpace::from_disturbances(vec![wrench]).map_err(MetricError::Wrench)?;
            ows(&space)
        }
        _ => crate::grasp::map_in_order(grasps, |grasp| {
            SCORERS.with_borrow_mut(|kept| {
                let scorer = find_or_make(
                    kept,
                    |s| s.metric == metric && s.method == method,
                    || Scorer::new(metric, method, None).expect("checked above"),
                );
                scorer.score(grasp)
            })
        }),
    })
}

thread_local! {
    /// The scorers of [`score_batch`] on this thread (metrics without a wrench space), one per
    /// (metric, method) used.
    static SCORERS: std::cell::RefCell<Vec<Scorer<'static>>> = const {
        std::cell::RefCell::new(Vec::new())
    };
}
