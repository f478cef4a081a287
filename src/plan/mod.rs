//! Grasp planners: a GraspIt!-like random sampler ([`plan`]: sample contacts on the surface,
//! keep the best grasp) and a planner that climbs the metric's exact gradient over the surface
//! ([`plan_descent`]; its rules in [`descent`]).
//!
//! # The sampler
//!
//!
//! Each sample places `m` contacts uniformly by area on the object's surface (inward face normals,
//! [`Mesh::sample_surface`]), builds the grasp in the object's torque frame (centre of mass and
//! characteristic length ρ) and evaluates one metric. The best force-closure grasp is kept. Time
//! is split between quality evaluation and everything else (sampling, building the grasp), which
//! is the quantity the seed paper's Table 1 compares between the partial and the full-hull methods.
//! This sampler is the paper's random sampler of Fig. 12, not the planner behind its Table 1
//! (`pqh reproduce fig12` runs the comparison; docs/paper.md).
//!
//! ```
//! use pqhull::grasp::FrictionModel;
//! use pqhull::mesh::Mesh;
//! use pqhull::grasp::quality::{Method, Metric};
//! use pqhull::plan::{plan, BestComparison, PlanConfig};
//!
//! let object = Mesh::uv_sphere(0.3, 8, 16)?;
//! let config = PlanConfig {
//!     contacts: 4,
//!     samples: 50,
//!     friction: FrictionModel::try_new(0.5, 8)?,
//!     metric: Metric::Q1,
//!     seed: 7,
//! };
//! let partial = plan(&object, None, &config, Method::Partial)?;
//! let full = plan(&object, None, &config, Method::Full)?;
//! // Same samples, same metric values: the same best grasp.
//! assert_eq!(partial.compare_best(&full), BestComparison::Same);
//! let (a, b) = (partial.best.unwrap(), full.best.unwrap());
//! assert_eq!(a.sample, b.sample);
//! assert!((a.value - b.value).abs() <= 1e-12 * b.value.abs().max(1e-2));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::geometry::Rng;
use crate::grasp::json::write_contact;
use crate::grasp::ows::ObjectWrenchSpace;
use crate::grasp::{Contact, FrictionModel, Grasp, GraspError, MAX_CONTACTS};
use crate::grasp::{Evaluator, Method, Metric, QualityError};
use crate::mesh::{Mesh, SurfaceSampler};
use serde_json::{Value, json};
use std::fmt;
use std::time::{Duration, Instant};

pub mod descent;

pub use descent::{
    DescentConfig, DescentReport, MAX_EVALUATIONS, MAX_SCREEN, MAX_STARTS, PlannedGrasp, StepRule,
    Stop, plan_descent,
};

/// The most samples a plan accepts: 1,000,000.
///
/// Why this bound: a plan keeps only its best grasp, so its memory does not grow with the samples,
/// but its time does: every sample is one quality evaluation (at worst a full hull, or the hull
/// of a Minkowski sum of k^m points; per-grasp times in docs/benchmarks.md), and a million of them
/// is already far more than a plan needs. A larger count is almost certainly a typing error, and
/// is refused before any work starts.
pub const MAX_SAMPLES: usize = 1_000_000;

/// What to plan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanConfig {
    /// Contacts per grasp (1 ≤ m ≤ [`MAX_CONTACTS`]).
    pub contacts: usize,
    /// Grasps sampled (1 ≤ samples ≤ [`MAX_SAMPLES`]).
    pub samples: usize,
    /// Friction model of every contact.
    pub friction: FrictionModel,
    /// The metric to maximise: any of them ([`Evaluator`] computes it). Grasps are ranked by value
    /// among the force-closure ones only.
    pub metric: Metric,
    /// Seed of the contact sampling: the same seed gives the same grasps for every method.
    pub seed: u64,
}

/// The best grasp found.
#[derive(Clone, Debug, PartialEq)]
pub struct BestGrasp {
    /// Which sample (0-based) it was.
    pub sample: usize,
    /// The grasp, in the object's torque frame.
    pub grasp: Grasp,
    /// Its metric value.
    pub value: f64,
}

/// The outcome of a plan.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanReport {
    /// The force-closure grasp with the largest value (`None` if no sample was force closure).
    pub best: Option<BestGrasp>,
    /// Samples evaluated.
    pub samples: usize,
    /// How many were force closure.
    pub force_closure: usize,
    /// Time spent in quality evaluation.
    pub quality_time: Duration,
    /// Everything else: sampling contacts and building grasps.
    pub other_time: Duration,
    /// Facets created by all the evaluations.
    pub facets_created: usize,
}

/// What comparing the best grasps of two plans over the same samples found
/// ([`PlanReport::compare_best`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BestComparison {
    /// Both chose the same grasp: the same sample, or one with the same value (within 1e−9
    /// relative: an exact tie that rounding broke the other way).
    Same,
    /// They chose different grasps, or only one of them found a force-closure grasp.
    Different,
    /// Neither found a force-closure grasp among its samples: there is nothing to compare, and
    /// their timings compare no hull the metric needed either (such grasps are settled without
    /// one by the partial method).
    NothingToCompare,
}

impl BestComparison {
    /// `Some(true)` for [`Same`](Self::Same), `Some(false)` for [`Different`](Self::Different),
    /// `None` when there was nothing to compare.
    pub fn same(self) -> Option<bool> {
        match self {
            BestComparison::Same => Some(true),
            BestComparison::Different => Some(false),
            BestComparison::NothingToCompare => None,
        }
    }

    /// The name `pqh` prints for it: `same`, `different` or `nothing_to_compare`.
    pub fn name(self) -> &'static str {
        match self {
            BestComparison::Same => "same",
            BestComparison::Different => "different",
            BestComparison::NothingToCompare => "nothing_to_compare",
        }
    }
}

impl PlanReport {
    /// Compares this plan's best grasp with `other`'s — a plan over the same samples by another
    /// method. See [`BestComparison`]; both finding none is
    /// [`NothingToCompare`](BestComparison::NothingToCompare), not agreement.
    pub fn compare_best(&self, other: &PlanReport) -> BestComparison {
        match (&self.best, &other.best) {
            (Some(a), Some(b))
                if a.sample == b.sample
                    || (a.value - b.value).abs() <= 1e-9 * b.value.abs().max(1e-3) =>
            {
                BestComparison::Same
            }
            (None, None) => BestComparison::NothingToCompare,
            _ => BestComparison::Different,
        }
    }

    /// Seconds of quality evaluation per sample.
    pub fn quality_seconds_per_sample(&self) -> f64 {
        self.quality_time.as_secs_f64() / self.samples as f64
    }

    /// This plan's quality evaluation time per sample over `other`'s (a plan over the same
    /// samples by another method), only when there was a best grasp to compare: grasps that are
    /// not force closure are settled by the partial method without any hull, so over those
    /// alone the ratio would time a full hull against a separation certificate, not the
    /// metric's work.
    pub fn quality_speedup_over(&self, other: &PlanReport) -> Option<f64> {
        (self.compare_best(other) != BestComparison::NothingToCompare)
            .then(|| self.quality_seconds_per_sample() / other.quality_seconds_per_sample())
    }

    /// The report as `pqh plan --json` gives it: `samples`, `force_closure`, `quality_s`,
    /// `other_s`, `facets_created` and `best` (null, or its `sample`, `value` and `contacts`
    /// as [`write_contact`] writes them).
    ///
    /// ```
    /// use pqhull::grasp::FrictionModel;
    /// use pqhull::mesh::Mesh;
    /// use pqhull::grasp::quality::{Method, Metric};
    /// use pqhull::plan::{plan, PlanConfig};
    ///
    /// let object = Mesh::uv_sphere(0.3, 8, 16)?;
    /// let config = PlanConfig {
    ///     contacts: 3,
    ///     samples: 20,
    ///     friction: FrictionModel::try_new(0.5, 6)?,
    ///     metric: Metric::Q1,
    ///     seed: 2,
    /// };
    /// let report = plan(&object, None, &config, Method::Partial)?.to_json();
    /// assert_eq!(report["samples"], 20);
    /// assert!(report["best"].is_null() || report["best"]["contacts"].as_array().unwrap().len() == 3);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn to_json(&self) -> Value {
        json!({
            "samples": self.samples,
            "force_closure": self.force_closure,
            "quality_s": self.quality_time.as_secs_f64(),
            "other_s": self.other_time.as_secs_f64(),
            "facets_created": self.facets_created,
            "best": self.best.as_ref().map(|b| json!({
                "sample": b.sample,
                "value": b.value,
                "contacts": b.grasp.contacts().iter().map(write_contact).collect::<Vec<_>>(),
            })),
        })
    }
}

/// Why a plan could not run.
///
/// Non-exhaustive: more limits may be added.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum PlanError {
    /// `contacts`, `samples`, `starts` or `evaluations` is zero.
    Empty,
    /// More samples than [`MAX_SAMPLES`].
    TooManySamples {
        /// The number of samples asked for.
        samples: usize,
        /// The limit, [`MAX_SAMPLES`].
        max: usize,
    },
    /// More starts than [`MAX_STARTS`] for [`plan_descent`].
    TooManyStarts {
        /// The number of starts asked for.
        starts: usize,
        /// The limit, [`MAX_STARTS`].
        max: usize,
    },
    /// More evaluations per start than [`MAX_EVALUATIONS`] for [`plan_descent`].
    TooManyEvaluations {
        /// The number asked for.
        evaluations: usize,
        /// The limit, [`MAX_EVALUATIONS`].
        max: usize,
    },
    /// More candidates screened per start than [`MAX_SCREEN`] for [`plan_descent`]
    /// ([`DescentConfig::screen`]).
    TooManyScreened {
        /// The number asked for.
        screen: usize,
        /// The limit, [`MAX_SCREEN`].
        max: usize,
    },
    /// Fewer evaluations per start than the metric's start can take ([`plan_descent`] with
    /// `Metric::Ows` needs 2: a start that is not force closure takes Q_OWS and Q1).
    TooFewEvaluations {
        /// The number asked for.
        evaluations: usize,
        /// The least the metric needs.
        needed: usize,
    },
    /// `Metric::Ows` without an object wrench space.
    NoWrenchSpace,
    /// A sampled contact or grasp was invalid (cannot happen for a valid mesh; reported, not
    /// hidden).
    Grasp(GraspError),
    /// A metric failed (for instance a zero wrench to resist).
    Quality(QualityError),
    /// [`plan_descent`] climbs Q1, Q∞ and Q_OWS, whose gradients it has; not this metric.
    NotClimbable(Metric),
    /// A [`StepRule`] that is not `0 < min ≤ initial ≤ max < ∞` with a finite `grow ≥ 1`.
    StepRule(StepRule),
}

impl fmt::Display for PlanError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlanError::Empty => write!(
                f,
                "a plan needs at least one contact and one sample (or start, evaluation and screened \
                 candidate)"
            ),
            PlanError::TooManySamples { samples, max } => {
                write!(
                    f,
                    "{samples} samples are too many for one plan (at most {max})"
                )
            }
            PlanError::TooManyStarts { starts, max } => {
                write!(
                    f,
                    "{starts} starts are too many for one plan (at most {max})"
                )
            }
            PlanError::TooManyEvaluations { evaluations, max } => write!(
                f,
                "{evaluations} evaluations per start are too many (at most {max})"
            ),
            PlanError::TooManyScreened { screen, max } => write!(
                f,
                "{screen} candidates screened per start are too many (at most {max})"
            ),
            PlanError::TooFewEvaluations {
                evaluations,
                needed,
            } => write!(
                f,
                "{evaluations} evaluations per start are too few for this metric (at least \
                 {needed})"
            ),
            PlanError::NoWrenchSpace => {
                write!(f, "the OWS metric needs the object's wrench space")
            }
            // Too many contacts is the configuration's fault, found before any sampling.
            PlanError::Grasp(e @ GraspError::TooManyContacts { .. }) => write!(f, "{e}"),
            PlanError::Grasp(e) => write!(f, "sampled grasp: {e}"),
            PlanError::Quality(e) => write!(f, "quality: {e}"),
            PlanError::NotClimbable(metric) => write!(
                f,
                "the descent planner climbs q1, qinf, qinf0 and ows, not {metric}: \
                 use the sampler for it"
            ),
            PlanError::StepRule(s) => write!(
                f,
                "step rule: initial {}, max {}, min {}, grow {}: expected \
                 0 < min ≤ initial ≤ max < ∞ and a finite grow ≥ 1",
                s.initial, s.max, s.min, s.grow
            ),
        }
    }
}

impl std::error::Error for PlanError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PlanError::Grasp(e) => Some(e),
            PlanError::Quality(e) => Some(e),
            _ => None,
        }
    }
}

impl From<GraspError> for PlanError {
    fn from(e: GraspError) -> Self {
        PlanError::Grasp(e)
    }
}

impl From<QualityError> for PlanError {
    fn from(e: QualityError) -> Self {
        PlanError::Quality(e)
    }
}

/// The torque frame of grasps on `mesh`: the space's when there is one (it was built from the
/// same mesh), else the mesh's own centre of mass and characteristic length.
fn torque_frame(mesh: &Mesh, space: Option<&ObjectWrenchSpace>) -> ([f64; 3], f64) {
    space
        .and_then(ObjectWrenchSpace::torque_frame)
        .unwrap_or_else(|| {
            let mass = mesh.mass_properties();
            (mass.centre_of_mass, mass.characteristic_length)
        })
}

/// The grasps a plan samples, in order: `contacts` contacts each, uniformly by area on the
/// surface with inward face normals, in the object's torque frame (`space`'s when given, else the
/// mesh's centre of mass and characteristic length). Endless; the same `seed` gives the same
/// grasps for every metric and method ([`samples`]).
pub struct Samples<'a> {
    sampler: SurfaceSampler<'a>,
    rng: Rng,
    contacts: usize,
    friction: FrictionModel,
    frame: ([f64; 3], f64),
}

impl Iterator for Samples<'_> {
    type Item = Result<Grasp, GraspError>;

    fn next(&mut self) -> Option<Self::Item> {
        let contacts: Result<Vec<Contact>, GraspError> = (0..self.contacts)
            .map(|_| {
                let s = self.sampler.sample(&mut self.rng);
                Contact::try_new(s.position, s.inward_normal, None)
            })
            .collect();
        Some(contacts.and_then(|contacts| {
            Grasp::builder(contacts, self.friction)
                .torque_reference(self.frame.0)
                .torque_scale(self.frame.1)
                .build()
        }))
    }
}

/// The grasps [`plan`] samples with this seed (see [`Samples`]).
///
/// ```
/// use pqhull::grasp::FrictionModel;
/// use pqhull::mesh::Mesh;
/// use pqhull::plan::samples;
///
/// let object = Mesh::uv_sphere(0.3, 8, 16)?;
/// let friction = FrictionModel::try_new(0.5, 8)?;
/// let a: Vec<_> = samples(&object, None, 4, friction, 7).take(3).collect::<Result<_, _>>()?;
/// let b: Vec<_> = samples(&object, None, 4, friction, 7).take(3).collect::<Result<_, _>>()?;
/// assert_eq!(a, b);
/// assert_eq!(a[0].contacts().len(), 4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn samples<'a>(
    mesh: &'a Mesh,
    space: Option<&ObjectWrenchSpace>,
    contacts: usize,
    friction: FrictionModel,
    seed: u64,
) -> Samples<'a> {
    Samples {
        sampler: SurfaceSampler::new(mesh),
        rng: Rng::new(seed),
        contacts,
        friction,
        frame: torque_frame(mesh, space),
    }
}

/// Samples `config.samples` grasps on `mesh` and keeps the best by `config.metric`, computed by
/// `method`. `space` is the object's wrench space, required for [`Metric::Ows`] (and, when
/// given, it fixes the torque frame).
///
/// # Errors
/// [`PlanError`] for an empty configuration, more than [`MAX_SAMPLES`] samples
/// ([`PlanError::TooManySamples`]) or [`MAX_CONTACTS`] contacts
/// ([`GraspError::TooManyContacts`] in [`PlanError::Grasp`]; both checked before any work), a
/// missing wrench space, or a failed evaluation.
pub fn plan(
    mesh: &Mesh,
    space: Option<&ObjectWrenchSpace>,
    config: &PlanConfig,
    method: Method,
) -> Result<PlanReport, PlanError> {
    plan_with_progress(mesh, space, config, method, |_| {})
}

/// [`plan`], calling `progress(samples done)` after each sample (for a progress bar).
///
/// # Errors
/// As [`plan`].
pub fn plan_with_progress(
    mesh: &Mesh,
    space: Option<&ObjectWrenchSpace>,
    config: &PlanConfig,
    method: Method,
    mut progress: impl FnMut(usize),
) -> Result<PlanReport, PlanError> {
    if config.contacts == 0 || config.samples == 0 {
        return Err(PlanError::Empty);
    }
    if config.samples > MAX_SAMPLES {
        return Err(PlanError::TooManySamples {
            samples: config.samples,
            max: MAX_SAMPLES,
        });
    }
    if config.contacts > MAX_CONTACTS {
        return Err(PlanError::Grasp(GraspError::TooManyContacts {
            contacts: config.contacts,
            max: MAX_CONTACTS,
        }));
    }
    let started = Instant::now();
    let ows = match config.metric {
        Metric::Ows => Some(space.ok_or(PlanError::NoWrenchSpace)?),
        _ => None,
    };
    let mut evaluator = Evaluator::new(config.metric, method, ows)?;
    let mut grasps = samples(mesh, space, config.contacts, config.friction, config.seed);
    let mut report = PlanReport {
        best: None,
        samples: config.samples,
        force_closure: 0,
        quality_time: Duration::ZERO,
        other_time: Duration::ZERO,
        facets_created: 0,
    };
    for sample in 0..config.samples {
        let grasp = grasps.next().expect("an endless sequence")?;
        let timer = Instant::now();
        let score = evaluator.evaluate(&grasp)?;
        report.quality_time += timer.elapsed();
        report.facets_created += score.stats.facets_created;
        if score.force_closure {
            report.force_closure += 1;
            if let Some(value) = score.value
                && report.best.as_ref().is_none_or(|b| value > b.value)
            {
                report.best = Some(BestGrasp {
                    sample,
                    grasp,
                    value,
                });
            }
        }
        progress(sample + 1);
    }
    report.other_time = started.elapsed().saturating_sub(report.quality_time);
    Ok(report)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report(best: Option<(usize, f64)>) -> PlanReport {
        let friction = FrictionModel::try_new(0.5, 4).unwrap();
        let contact = Contact::try_new([0.0; 3], [1.0, 0.0, 0.0], None).unwrap();
        PlanReport {
            best: best.map(|(sample, value)| BestGrasp {
                sample,
                grasp: Grasp::builder(vec![contact], friction).build().unwrap(),
                value,
            }),
            samples: 2,
            force_closure: usize::from(best.is_some()),
            quality_time: Duration::ZERO,
            other_time: Duration::ZERO,
            facets_created: 0,
        }
    }

    #[test]
    fn sizes_are_checked_before_any_work() {
        let object = Mesh::uv_sphere(0.3, 4, 8).unwrap();
        let config = PlanConfig {
            contacts: 4,
            samples: MAX_SAMPLES + 1,
            friction: FrictionModel::try_new(0.5, 4).unwrap(),
            metric: Metric::Q1,
            seed: 1,
        };
        let mut calls = 0;
        let got = plan_with_progress(&object, None, &config, Method::Partial, |_| calls += 1);
        assert_eq!(
            got,
            Err(PlanError::TooManySamples {
                samples: MAX_SAMPLES + 1,
                max: MAX_SAMPLES
            })
        );
        assert_eq!(calls, 0);
        let many = PlanConfig {
            contacts: usize::MAX,
            samples: 1,
            ..config
        };
        let err = plan(&object, None, &many, Method::Partial).unwrap_err();
        assert!(
            matches!(
                err,
                PlanError::Grasp(GraspError::TooManyContacts {
                    max: MAX_CONTACTS,
                    ..
                })
            ),
            "{err:?}"
        );
        assert!(err.to_string().contains("at most 256"), "{err}");
    }

    #[test]
    fn both_finding_nothing_is_not_agreement() {
        let none = report(None);
        assert_eq!(none.compare_best(&none), BestComparison::NothingToCompare);
        assert_eq!(none.compare_best(&none).same(), None);
        let one = report(Some((1, 0.2)));
        assert_eq!(one.compare_best(&none), BestComparison::Different);
        assert_eq!(none.compare_best(&one), BestComparison::Different);
        assert_eq!(one.compare_best(&one), BestComparison::Same);
        // A tie broken the other way by rounding.
        let tie = report(Some((0, 0.2 * (1.0 + 1e-12))));
        assert_eq!(one.compare_best(&tie).same(), Some(true));
        assert_eq!(
            one.compare_best(&report(Some((0, 0.3)))).same(),
            Some(false)
        );
    }
}
