//! A planner that climbs the metric: contacts moved over the surface along the exact gradient.
//!
//! Each planned grasp starts from a random grasp drawn as the sampler draws them ([`samples`],
//! same seed, same starts) — or from the best of [`DescentConfig::screen`] random grasps, that
//! one and more from a second stream — and repeats:
//!
//! 1. **Direction.** The exact gradient of the value ([`q1_gradient`], [`qinf_gradient`],
//!    [`ows_gradient`]) with respect to each contact's position, projected on that contact's
//!    tangent plane (`g − (g·n)n`). The normals are not free variables here: a contact's normal
//!    is its triangle's, a function of where it lands. Near a kink — two deciding faces tied,
//!    as at most optima of a min–max — no single face's gradient is an ascent direction, so the
//!    run keeps a bundle of gradients (the grasp's and those of the rejected moves around it,
//!    at most six) and moves along the least-norm point of their convex hull: the steepest
//!    ascent of the minimum of those faces (a bundle method's direction).
//! 2. **Step.** Every contact moves by `α·ρ·d_i / max_j |d_j|` (the contact with the largest
//!    share of the direction `d` moves `α·ρ`, ρ the object's characteristic length) and is put
//!    back on the surface at the nearest point, with that triangle's inward normal
//!    ([`Mesh::nearest_surface_point`]'s answer, from a [`SurfaceIndex`] built once per call).
//! 3. **Acceptance** (a backtracking rule). The moved grasp is evaluated; it is kept only if it
//!    is strictly better, and then `α` grows by [`StepRule::grow`] (at most [`StepRule::max`]);
//!    otherwise `α` is halved and the step retried from the same grasp. So the value never
//!    decreases along a run: every planned grasp is at least as good as its start.
//! 4. **Probes.** When `α` falls below [`StepRule::min`] at a force-closure grasp, four random
//!    tangential moves of 0.1, 0.03, 0.01 and 0.003 ρ are tried: the gradient cannot see across
//!    an edge of the mesh, where a contact's normal jumps. The first that is better is kept
//!    and the run goes on from it with `α` reset.
//! 5. **Stop** when the probes fail too ([`Stop::StepTooSmall`]), when the planned grasp has
//!    used its evaluations ([`DescentConfig::evaluations`], its start's included), or when the
//!    direction vanishes ([`Stop::Stationary`]). A run that stops short of force closure (on a
//!    plateau of Q1, such as every contact on one face) starts again from a fresh random grasp
//!    (a second seeded stream) while evaluations remain — and, when screening
//!    ([`DescentConfig::screen`] above 1), so does one that stops at an optimum; the planned
//!    grasp is the best it found.
//!
//! **Force closure first, then the metric.** Grasps are compared by (force closure, value): a
//! force-closure grasp beats every grasp that is not. A start that is not force closure climbs
//! Q1 (negative outside: minus the distance from the origin to the hull), which reaches force
//! closure where it becomes positive; from there the run climbs the metric. For Q1 both are the
//! same function. A Q_OWS run (Q_OWS is undefined without force closure) climbs Q1 to its own
//! optimum first, then Q_OWS from there: Q_OWS ties among disturbances at most grasps and its
//! climbs stop at those kinks sooner.
//!
//! **Against the seed paper's planner** (only described there, as a gradient-descent-like search
//! over the surface): this one uses the exact gradient rather than a numerical or heuristic
//! direction, and its step and stopping rules are the ones above.
//!
//! ```
//! use pqhull::grasp::FrictionModel;
//! use pqhull::grasp::quality::{Method, Metric};
//! use pqhull::mesh::Mesh;
//! use pqhull::plan::{DescentConfig, plan_descent};
//!
//! let object = Mesh::cuboid([0.3, 0.2, 0.1])?;
//! let config = DescentConfig {
//!     starts: 3,
//!     evaluations: 30,
//!     ..DescentConfig::new(4, FrictionModel::try_new(0.5, 8)?, Metric::Q1)
//! };
//! let report = plan_descent(&object, None, &config, Method::Partial)?;
//! for planned in &report.planned {
//!     // Never worse than where it started.
//!     assert!((planned.force_closure, planned.value) >= (planned.start_force_closure, planned.start_value));
//!     assert!(planned.evaluations <= 30);
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{PlanError, samples, torque_frame};
use crate::geometry::Rng;
use crate::grasp::json::write_grasp;
use crate::grasp::ows::ObjectWrenchSpace;
use crate::grasp::{Evaluation, Evaluator, Method, Metric};
use crate::grasp::{
    FrictionModel, Gradient, Grasp, GraspError, MAX_CONTACTS, ows_gradient, q1_gradient,
    qinf_gradient,
};
use crate::mesh::{Mesh, SurfaceIndex};
use serde_json::{Value, json};
use std::time::{Duration, Instant};

mod moves;
use moves::{largest_move, least_norm, step_on_surface, tangential, tangential_of};

/// The most planned grasps one call accepts: 100,000 (each is a run of up to
/// [`MAX_EVALUATIONS`] evaluations).
pub const MAX_STARTS: usize = 100_000;

/// The most evaluations one planned grasp may use: 10,000. A run that has not stopped by then is
/// taking steps too small to matter.
pub const MAX_EVALUATIONS: usize = 10_000;

/// The most candidates [`DescentConfig::screen`] accepts: [`MAX_EVALUATIONS`] (each costs at
/// least one evaluation).
pub const MAX_SCREEN: usize = MAX_EVALUATIONS;

/// What the seed of the restarts differs from [`DescentConfig::seed`] by (exclusive or): the
/// restarts are their own stream, so the starts stay the sampler's samples.
const RESTART_SEED: u64 = 0x9e37_79b9_7f4a_7c15;

/// Likewise for the random probes' directions.
const PROBE_SEED: u64 = 0xd1b5_4a32_d192_ed03;

/// The step rule of [`plan_descent`], in units of the object's characteristic length ρ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepRule {
    /// The first step: the contact with the largest tangential gradient moves `initial · ρ`.
    pub initial: f64,
    /// The largest step.
    pub max: f64,
    /// A run stops when its step falls below `min · ρ`.
    pub min: f64,
    /// The factor a step grows by after an accepted move (a rejected one halves it).
    pub grow: f64,
}

impl Default for StepRule {
    /// `initial` 0.1, `max` 0.5, `min` 1e−3, `grow` 1.5.
    fn default() -> Self {
        StepRule {
            initial: 0.1,
            max: 0.5,
            min: 1e-3,
            grow: 1.5,
        }
    }
}

/// What to plan by [`plan_descent`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DescentConfig {
    /// Contacts per grasp (1 ≤ m ≤ [`MAX_CONTACTS`]).
    pub contacts: usize,
    /// Planned grasps: one run from each of this many random starts (1 to [`MAX_STARTS`]).
    pub starts: usize,
    /// Metric evaluations one planned grasp may use, its start's included (1 to
    /// [`MAX_EVALUATIONS`]; at least 2 for Q_OWS). Every metric call counts: a Q_OWS run's grasp
    /// that is not force closure costs two (Q_OWS, then the Q1 it climbs instead).
    pub evaluations: usize,
    /// Friction model of every contact.
    pub friction: FrictionModel,
    /// The metric climbed: [`Metric::Q1`], [`Metric::QInf`] or [`Metric::Ows`].
    pub metric: Metric,
    /// Candidates screened per planned grasp (1 to [`MAX_SCREEN`]): the run's start is the best
    /// (by force closure, then value) of its sampler start and `screen − 1` further random
    /// grasps from the restarts' stream, each one evaluation (two for a Q_OWS candidate that
    /// is not force closure) out of [`evaluations`](Self::evaluations). 1, the default, climbs
    /// from the sampler's start itself. Above 1, a climb that stops with evaluations left
    /// (at an optimum, or short of force closure) screens a fresh start and climbs again, the
    /// planned grasp being the best found. Worth 10 or so for Q_OWS, whose climbs stop at
    /// kinks (ties among disturbances) soon after they start: where a climb starts matters.
    pub screen: usize,
    /// Seed of the starts: the same seed gives the same starts as [`plan`](super::plan)'s
    /// samples.
    pub seed: u64,
    /// How far to move and when to stop.
    pub step: StepRule,
}

impl DescentConfig {
    /// A configuration with 10 starts, 50 evaluations each, no screening (`screen` 1), seed 1
    /// and the default step rule.
    pub fn new(contacts: usize, friction: FrictionModel, metric: Metric) -> Self {
        DescentConfig {
            contacts,
            starts: 10,
            evaluations: 50,
            screen: 1,
            friction,
            metric,
            seed: 1,
            step: StepRule::default(),
        }
    }
}

/// Why a run stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    /// The step fell below [`StepRule::min`]: no nearby move improves the grasp.
    StepTooSmall,
    /// The run used its [`DescentConfig::evaluations`].
    Evaluations,
    /// The tangential gradient is zero (or the value has no gradient there).
    Stationary,
}

impl Stop {
    /// The name `pqh plan --json` gives it: `step`, `evaluations` or `stationary`.
    pub fn name(self) -> &'static str {
        match self {
            Stop::StepTooSmall => "step",
            Stop::Evaluations => "evaluations",
            Stop::Stationary => "stationary",
        }
    }
}

/// One planned grasp: the end of one run.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannedGrasp {
    /// Which start (0-based) it climbed from: the sampler's sample of that index, or the best of
    /// the candidates screened with it ([`DescentConfig::screen`]).
    pub start: usize,
    /// Whether the grasp the climb started from was force closure.
    pub start_force_closure: bool,
    /// That grasp's value: the metric's when force closure, else the value climbed toward it (≤ 0:
    /// Q1's, or Q∞'s own in a Q∞ run).
    pub start_value: f64,
    /// The planned grasp, in the object's torque frame.
    pub grasp: Grasp,
    /// Whether it is force closure.
    pub force_closure: bool,
    /// Its value: the metric's when force closure, else as for `start_value`.
    pub value: f64,
    /// Evaluations the run used.
    pub evaluations: usize,
    /// Moves accepted.
    pub steps: usize,
    /// Why it stopped.
    pub stop: Stop,
}

/// The outcome of [`plan_descent`].
#[derive(Clone, Debug, PartialEq)]
pub struct DescentReport {
    /// One planned grasp per start, in start order.
    pub planned: Vec<PlannedGrasp>,
    /// Metric evaluations, over all runs.
    pub evaluations: usize,
    /// Time spent in metric evaluation.
    pub quality_time: Duration,
    /// Time spent computing gradients (Q_OWS's runs one more partial hull per gradient).
    pub gradient_time: Duration,
    /// Everything else: drawing starts, moving contacts onto the surface, building grasps.
    pub other_time: Duration,
    /// Facets created by all the evaluations.
    pub facets_created: usize,
}

impl DescentReport {
    /// The best planned grasp that is force closure, or `None`.
    pub fn best(&self) -> Option<&PlannedGrasp> {
        self.planned
            .iter()
            .filter(|p| p.force_closure)
            .max_by(|a, b| a.value.total_cmp(&b.value))
    }

    /// How many planned grasps are force closure.
    pub fn force_closure(&self) -> usize {
        self.planned.iter().filter(|p| p.force_closure).count()
    }

    /// The whole planning time: quality, gradients and the rest.
    pub fn planning_time(&self) -> Duration {
        self.quality_time + self.gradient_time + self.other_time
    }

    /// The report as `pqh plan --planner descent --json` gives it: `starts`, `evaluations`,
    /// `force_closure`, `quality_s`, `gradient_s`, `other_s`, `facets_created`, and `best` (null,
    /// or its `start`, `value`, `start_value`, `steps`, `evaluations`, `stop` and `grasp`, in the
    /// grasp format `pqh grasp` reads, torque frame included).
    pub fn to_json(&self) -> Value {
        json!({
            "starts": self.planned.len(),
            "evaluations": self.evaluations,
            "force_closure": self.force_closure(),
            "quality_s": self.quality_time.as_secs_f64(),
            "gradient_s": self.gradient_time.as_secs_f64(),
            "other_s": self.other_time.as_secs_f64(),
            "facets_created": self.facets_created,
            "best": self.best().map(|b| json!({
                "start": b.start,
                "value": b.value,
                "start_value": b.start_force_closure.then_some(b.start_value),
                "steps": b.steps,
                "evaluations": b.evaluations,
                "stop": b.stop.name(),
                "grasp": write_grasp(&b.grasp),
            })),
        })
    }
}

/// One grasp's evaluation: its rank and what its gradient needs.
enum Evaluated {
    /// Q1 or Q∞ (the climb toward force closure of a Q_OWS run included).
    Hull(Box<Evaluation>),
    /// Q_OWS of a force-closure grasp.
    Ows(Box<Evaluation>),
}

/// The metric evaluators of a run, and the time and work they took.
struct Climber<'a> {
    metric: Metric,
    space: Option<&'a ObjectWrenchSpace>,
    q1: Evaluator<'static>,
    qinf: Option<Evaluator<'static>>,
    /// Q_OWS, in a run that climbs it.
    ows: Option<Evaluator<'a>>,
    /// The random probes' directions.
    rng: Rng,
    report: DescentReport,
}

impl Climber<'_> {
    /// The most evaluations one [`evaluate`](Self::evaluate) may count.
    fn cost(&self) -> usize {
        if self.metric == Metric::Ows { 2 } else { 1 }
    }

    /// Evaluates `grasp`: its rank `(force closure, value)` and its evaluation; counts the
    /// evaluations (two for a Q_OWS run's grasp that is not force closure: Q_OWS, then Q1) in
    /// `planned`.
    fn evaluate(
        &mut self,
        grasp: &Grasp,
        planned: &mut usize,
    ) -> Result<((bool, f64), Evaluated), PlanError> {
        let timer = Instant::now();
        let before = self.report.evaluations;
        let result = self.evaluate_untimed(grasp);
        self.report.quality_time += timer.elapsed();
        *planned += self.report.evaluations - before;
        result
    }

    fn evaluate_untimed(&mut self, grasp: &Grasp) -> Result<((bool, f64), Evaluated), PlanError> {
        // `metric` is Q1 during a Q_OWS run's climb to force closure: Q_OWS only when it is not.
        if let (Metric::Ows, Some(ows)) = (self.metric, self.ows.as_mut()) {
            let q = ows.evaluate(grasp)?;
            self.report.evaluations += 1;
            self.report.facets_created += q.stats.facets_created;
            if let Some(value) = q.value {
                return Ok(((true, value), Evaluated::Ows(Box::new(q))));
            }
        }
        let evaluator = match (self.metric, self.qinf.as_mut()) {
            (Metric::QInf { .. }, Some(e)) => e,
            _ => &mut self.q1,
        };
        let q = evaluator.evaluate(grasp)?;
        self.report.evaluations += 1;
        self.report.facets_created += q.stats.facets_created;
        // A Q_OWS run ranks a grasp it found not force closure below every one it did.
        let closure = q.force_closure && self.metric != Metric::Ows;
        // Q1 and Q∞ always have a value.
        let value = q.value.unwrap_or(f64::NEG_INFINITY);
        Ok(((closure, value), Evaluated::Hull(Box::new(q))))
    }

    /// The gradient of the value at `grasp`, or `None` where there is none to follow.
    fn gradient(&mut self, grasp: &Grasp, evaluated: &Evaluated) -> Option<Gradient> {
        let timer = Instant::now();
        let gradient = match evaluated {
            Evaluated::Hull(q) => match q.metric {
                Metric::QInf { .. } => qinf_gradient(grasp, q).ok(),
                _ => q1_gradient(grasp, q).ok(),
            },
            Evaluated::Ows(q) => self.space.and_then(|space| ows_gradient(grasp, space, q)),
        };
        self.report.gradient_time += timer.elapsed();
        gradient
    }
}

/// Plans `config.starts` grasps on `mesh` by climbing `config.metric` (computed by `method`)
/// from random starts; see the [module documentation](self) for the rules. `space` is the
/// object's wrench space, required for [`Metric::Ows`] (and, when given, it fixes the torque
/// frame, as for [`plan`](super::plan)).
///
/// # Errors
/// [`PlanError`] for an empty configuration, more than [`MAX_STARTS`] starts
/// ([`PlanError::TooManyStarts`]) or [`MAX_EVALUATIONS`] evaluations
/// ([`PlanError::TooManyEvaluations`]) or [`MAX_SCREEN`] candidates screened
/// ([`PlanError::TooManyScreened`]), fewer than 2 evaluations for Q_OWS
/// ([`PlanError::TooFewEvaluations`]), more than [`MAX_CONTACTS`]
/// contacts, a metric the planner does not climb ([`PlanError::NotClimbable`]), a step rule that
/// is not `0 < min ≤ initial ≤ max`, `grow ≥ 1` ([`PlanError::StepRule`]), a missing wrench space,
/// or a failed evaluation — all but the last checked before any work.
pub fn plan_descent(
    mesh: &Mesh,
    space: Option<&ObjectWrenchSpace>,
    config: &DescentConfig,
    method: Method,
) -> Result<DescentReport, PlanError> {
    check(config)?;
    let started = Instant::now();
    let space = match config.metric {
        Metric::Ows => Some(space.ok_or(PlanError::NoWrenchSpace)?),
        _ => space,
    };
    let rho = torque_frame(mesh, space).1;
    // Built once, inside the timed span: its cost is part of `other_time`.
    let surface = SurfaceIndex::new(mesh);
    let mut climber = Climber {
        metric: config.metric,
        space,
        q1: Evaluator::new(Metric::Q1, method, None)?,
        qinf: match config.metric {
            Metric::QInf { .. } => Some(Evaluator::new(config.metric, method, None)?),
            _ => None,
        },
        ows: match (config.metric, space) {
            (Metric::Ows, Some(space)) => Some(Evaluator::new(Metric::Ows, method, Some(space))?),
            _ => None,
        },
        rng: Rng::new(config.seed ^ PROBE_SEED),
        report: DescentReport {
            planned: Vec::with_capacity(config.starts),
            evaluations: 0,
            quality_time: Duration::ZERO,
            gradient_time: Duration::ZERO,
            other_time: Duration::ZERO,
            facets_created: 0,
        },
    };
    let starts = samples(mesh, space, config.contacts, config.friction, config.seed);
    let mut restarts = samples(
        mesh,
        space,
        config.contacts,
        config.friction,
        config.seed ^ RESTART_SEED,
    );
    for (start, grasp) in starts.take(config.starts).enumerate() {
        let planned = climb(
            &surface,
            &mut climber,
            config,
            rho,
            start,
            grasp?,
            &mut restarts,
        )?;
        climber.report.planned.push(planned);
    }
    let mut report = climber.report;
    report.other_time = started
        .elapsed()
        .saturating_sub(report.quality_time + report.gradient_time);
    Ok(report)
}

/// The configuration's bounds, checked before any work.
fn check(config: &DescentConfig) -> Result<(), PlanError> {
    if config.contacts == 0 || config.starts == 0 || config.evaluations == 0 || config.screen == 0 {
        return Err(PlanError::Empty);
    }
    if config.starts > MAX_STARTS {
        return Err(PlanError::TooManyStarts {
            starts: config.starts,
            max: MAX_STARTS,
        });
    }
    if config.evaluations > MAX_EVALUATIONS {
        return Err(PlanError::TooManyEvaluations {
            evaluations: config.evaluations,
            max: MAX_EVALUATIONS,
        });
    }
    if config.screen > MAX_SCREEN {
        return Err(PlanError::TooManyScreened {
            screen: config.screen,
            max: MAX_SCREEN,
        });
    }
    if config.contacts > MAX_CONTACTS {
        return Err(PlanError::Grasp(GraspError::TooManyContacts {
            contacts: config.contacts,
            max: MAX_CONTACTS,
        }));
    }
    if config.metric == Metric::Ows && config.evaluations < 2 {
        // The start alone may take two: Q_OWS, and Q1 when it is not force closure.
        return Err(PlanError::TooFewEvaluations {
            evaluations: config.evaluations,
            needed: 2,
        });
    }
    if !matches!(
        config.metric,
        Metric::Q1 | Metric::QInf { .. } | Metric::Ows
    ) {
        return Err(PlanError::NotClimbable(config.metric));
    }
    let s = config.step;
    let valid = s.min > 0.0
        && s.min <= s.initial
        && s.initial <= s.max
        && s.max.is_finite()
        && s.grow >= 1.0
        && s.grow.is_finite();
    if !valid {
        return Err(PlanError::StepRule(s));
    }
    Ok(())
}

/// The most gradients a run's bundle holds: the current grasp's and those of the latest
/// rejected or accepted neighbours.
const BUNDLE: usize = 6;

/// One planned grasp from `grasp`, drawing fresh starts from `restarts` while its runs stop short
/// of force closure and evaluations remain.
#[allow(clippy::too_many_arguments)]
fn climb(
    surface: &SurfaceIndex<'_>,
    climber: &mut Climber<'_>,
    config: &DescentConfig,
    rho: f64,
    start: usize,
    grasp: Grasp,
    restarts: &mut super::Samples<'_>,
) -> Result<PlannedGrasp, PlanError> {
    let mut evaluations = 0;
    let (grasp, rank, evaluated) = screened(climber, config, grasp, &mut evaluations, restarts)?;
    let mut planned = PlannedGrasp {
        start,
        start_force_closure: rank.0,
        start_value: rank.1,
        grasp,
        force_closure: rank.0,
        value: rank.1,
        evaluations,
        steps: 0,
        stop: Stop::Evaluations,
    };
    let mut run = Some((planned.grasp.clone(), rank, evaluated));
    while let Some((mut grasp, mut rank, mut evaluated)) = run.take() {
        if config.metric == Metric::Ows && planned.evaluations + 3 <= config.evaluations {
            // Q1 first, to its own optimum: Q_OWS's kinks (a tie among disturbances at most
            // grasps) stop its climb sooner, and from a Q1 optimum it has less to climb.
            climber.metric = Metric::Q1;
            let (q1_rank, q1_evaluated) = climber.evaluate(&grasp, &mut planned.evaluations)?;
            let (end, _, _) = ascend(
                surface,
                climber,
                config,
                rho,
                grasp,
                q1_rank,
                q1_evaluated,
                &mut planned,
                // Room for the Q_OWS evaluation at its end.
                config.evaluations - 2,
            )?;
            climber.metric = Metric::Ows;
            grasp = end;
            (rank, evaluated) = climber.evaluate(&grasp, &mut planned.evaluations)?;
        }
        let (end, end_rank, stop) = ascend(
            surface,
            climber,
            config,
            rho,
            grasp,
            rank,
            evaluated,
            &mut planned,
            config.evaluations,
        )?;
        if end_rank > (planned.force_closure, planned.value) {
            (planned.grasp, planned.force_closure, planned.value) = (end, end_rank.0, end_rank.1);
        }
        planned.stop = stop;
        // Stuck short of force closure (a plateau or a kink Q1 cannot leave), or, when
        // screening, stopped at an optimum with evaluations left: a fresh (screened) start.
        if (planned.force_closure && config.screen == 1)
            || stop == Stop::Evaluations
            || planned.evaluations + climber.cost() > config.evaluations
        {
            break;
        }
        let next = restarts.next().expect("an endless sequence")?;
        let (g, r, e) = screened(climber, config, next, &mut planned.evaluations, restarts)?;
        run = Some((g, r, e));
    }
    Ok(planned)
}

/// The best (by force closure, then value) of `first` and up to `screen − 1` more random grasps
/// from `restarts`, with its rank and evaluation, leaving room for at least one step after it.
fn screened(
    climber: &mut Climber<'_>,
    config: &DescentConfig,
    first: Grasp,
    evaluations: &mut usize,
    restarts: &mut super::Samples<'_>,
) -> Result<(Grasp, (bool, f64), Evaluated), PlanError> {
    let (rank, evaluated) = climber.evaluate(&first, evaluations)?;
    let mut best = (first, rank, evaluated);
    for _ in 1..config.screen {
        if *evaluations + 2 * climber.cost() > config.evaluations {
            break;
        }
        let candidate = restarts.next().expect("an endless sequence")?;
        let (r, e) = climber.evaluate(&candidate, evaluations)?;
        if r > best.1 {
            best = (candidate, r, e);
        }
    }
    Ok(best)
}

/// One run of steps from `grasp` (rank `rank`), spending `planned`'s evaluations; returns where it
/// ended, its rank and why it stopped.
#[allow(clippy::too_many_arguments)]
fn ascend(
    surface: &SurfaceIndex<'_>,
    climber: &mut Climber<'_>,
    config: &DescentConfig,
    rho: f64,
    mut grasp: Grasp,
    mut rank: (bool, f64),
    mut evaluated: Evaluated,
    planned: &mut PlannedGrasp,
    limit: usize,
) -> Result<(Grasp, (bool, f64), Stop), PlanError> {
    let mut alpha = config.step.initial;
    // Gradients of the value at the grasp and at points near it (tangential to the grasp's
    // contacts): near a kink — where two deciding faces tie, as they do at most optima of a
    // min–max — no single one is an ascent direction, and the least-norm element of their convex
    // hull is the steepest ascent of the minimum (a bundle method's direction).
    let mut bundle: Vec<Vec<f64>> = Vec::with_capacity(BUNDLE);
    let stop = 'run: loop {
        let Some(g) = climber.gradient(&grasp, &evaluated) else {
            break Stop::Stationary;
        };
        push(&mut bundle, tangential(&grasp, &g));
        // Retry from this grasp with smaller steps until one is better.
        loop {
            let direction = least_norm(&bundle);
            let largest = largest_move(&direction);
            if !(largest > 0.0 && largest.is_finite()) {
                if bundle.len() > 1 {
                    // The bundle's gradients cancel: keep the grasp's own and try it alone.
                    bundle.drain(..bundle.len() - 1);
                    continue;
                }
                break 'run Stop::Stationary;
            }
            if alpha < config.step.min {
                // Before giving up on a force-closure grasp, random moves: the gradient cannot
                // see across an edge of the mesh (a contact's normal jumps there), a probe can.
                // (Short of force closure, a fresh start does better.)
                let probed = match rank.0 {
                    true => probe(surface, climber, rho, &grasp, rank, planned, limit)?,
                    false => None,
                };
                match probed {
                    Some((g, r, e)) => {
                        if r.0 != rank.0 && climber.metric == Metric::Ows {
                            bundle.clear();
                        }
                        (grasp, rank, evaluated) = (g, r, e);
                        planned.steps += 1;
                        alpha = config.step.initial;
                        break;
                    }
                    None => break 'run Stop::StepTooSmall,
                }
            }
            if planned.evaluations + climber.cost() > limit {
                break 'run Stop::Evaluations;
            }
            let Some(moved) = step_on_surface(surface, &grasp, &direction, alpha * rho / largest)?
            else {
                // Every contact landed where it was: a smaller step cannot do better.
                alpha *= 0.5;
                continue;
            };
            let (trial, trial_evaluated) = climber.evaluate(&moved, &mut planned.evaluations)?;
            if trial > rank {
                if trial.0 != rank.0 && climber.metric == Metric::Ows {
                    // Force closure reached: another function from here (Q_OWS after Q1).
                    bundle.clear();
                }
                (grasp, rank, evaluated) = (moved, trial, trial_evaluated);
                planned.steps += 1;
                alpha = (alpha * config.step.grow).min(config.step.max);
                break;
            }
            // The neighbour's gradient (another deciding face, when a kink was crossed), when it
            // is of the same function.
            if trial.0 == rank.0
                && let Some(h) = climber.gradient(&moved, &trial_evaluated)
            {
                let h = tangential(&grasp, &h);
                let last = bundle.pop();
                push(&mut bundle, h);
                bundle.extend(last);
            }
            alpha *= 0.5;
        }
    };
    Ok((grasp, rank, stop))
}

/// Random moves of `grasp`'s contacts tried when its gradient steps have shrunk below the
/// step rule's minimum, one of each length in [`PROBE_LENGTHS`] (times ρ): the first better
/// grasp, or `None`.
#[allow(clippy::type_complexity)]
fn probe(
    surface: &SurfaceIndex<'_>,
    climber: &mut Climber<'_>,
    rho: f64,
    grasp: &Grasp,
    rank: (bool, f64),
    planned: &mut PlannedGrasp,
    limit: usize,
) -> Result<Option<(Grasp, (bool, f64), Evaluated)>, PlanError> {
    for length in PROBE_LENGTHS {
        if planned.evaluations + climber.cost() > limit {
            break;
        }
        let direction: Vec<f64> = (0..3 * grasp.contact_count())
            .map(|_| 2.0 * climber.rng.uniform() - 1.0)
            .collect();
        let direction = tangential_of(grasp, &direction);
        let largest = largest_move(&direction);
        if largest <= 0.0 || !largest.is_finite() {
            continue;
        }
        let Some(moved) = step_on_surface(surface, grasp, &direction, length * rho / largest)?
        else {
            continue;
        };
        let (trial, evaluated) = climber.evaluate(&moved, &mut planned.evaluations)?;
        if trial > rank {
            return Ok(Some((moved, trial, evaluated)));
        }
    }
    Ok(None)
}

/// The lengths of the random probes, in units of ρ, longest first.
const PROBE_LENGTHS: [f64; 4] = [0.1, 0.03, 0.01, 0.003];

/// Adds `g` to the bundle, dropping the oldest beyond [`BUNDLE`].
fn push(bundle: &mut Vec<Vec<f64>>, g: Vec<f64>) {
    if bundle.len() == BUNDLE {
        bundle.remove(0);
    }
    bundle.push(g);
}
