//! The view of a plan: the best grasp by Q1 beside the best by the object wrench space metric
//! (the seed paper's Fig. 10), as [`scene`](super::scene) panels and a self-contained page.

use super::scene::{Color, Panel, Scene, scene_page_with_note};
use crate::grasp::Evaluator;
use crate::grasp::Grasp;
use crate::grasp::ows::ObjectWrenchSpace;
use crate::grasp::quality::q1;
use crate::grasp::quality::{Method, Metric};
use crate::mesh::Mesh;
use crate::plan::{BestGrasp, PlanConfig, PlanError, PlanReport, plan};

/// Contact markers: one colour per finger, so the two panels can be compared finger by finger.
const FINGERS: [Color; 6] = [
    Color::RED,
    Color::BLUE,
    Color::GREEN,
    Color::rgb(230, 150, 30),
    Color::rgb(140, 60, 170),
    Color::rgb(20, 160, 170),
];

/// The object as a translucent skin with `grasp`'s contacts: per finger a marker, its approach
/// from outside along −n ending at the contact, a label and its friction cone's edges.
///
/// ```
/// use pqhull::mesh::Mesh;
/// use pqhull::viz::plan_scene::grasp_scene;
/// let cube = Mesh::cuboid([0.5, 0.5, 0.5])?;
/// let page = grasp_scene(&cube, None, "the bare object").to_html("cube");
/// assert!(page.contains("the bare object"));
/// # Ok::<(), pqhull::mesh::MeshError>(())
/// ```
pub fn grasp_scene(mesh: &Mesh, grasp: Option<&Grasp>, caption: impl Into<String>) -> Scene {
    let mut scene = Scene::new(caption);
    let skin = Color::rgb(200, 205, 215).with_alpha(0.55);
    for t in mesh.triangles() {
        scene.triangle(t.map(|i| mesh.vertices()[i as usize]), skin);
    }
    let Some(grasp) = grasp else {
        return scene;
    };
    let size = 0.25 * grasp.torque_scale();
    for (i, c) in grasp.contacts().iter().enumerate() {
        let colour = FINGERS[i % FINGERS.len()];
        let p = c.position();
        let n = c.normal();
        let from = std::array::from_fn(|k| p[k] - size * n[k]);
        scene
            .segment(from, p, colour, 3.0)
            .point(p, colour, 6.0)
            .label(from, format!("finger {}", i + 1), colour);
        for f in grasp.cone_edges(i) {
            let length = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
            let tip = std::array::from_fn(|k| p[k] - 0.6 * size * f[k] / length);
            scene.segment(tip, p, colour.with_alpha(0.45), 1.0);
        }
    }
    scene
}

/// The best grasp of `config`'s samples by `metric`: `report`'s own when it is that plan's,
/// else a partial plan over the same samples (the same grasps, so the panels compare metrics).
fn best_by(
    metric: Metric,
    mesh: &Mesh,
    space: &ObjectWrenchSpace,
    config: &PlanConfig,
    report: &PlanReport,
) -> Result<Option<BestGrasp>, PlanError> {
    if config.metric == metric {
        return Ok(report.best.clone());
    }
    let other = PlanConfig { metric, ..*config };
    plan(mesh, Some(space), &other, Method::Partial).map(|r| r.best)
}

/// Both metrics of `grasp`: (Q1, Q_OWS); `None` where a metric has no value.
fn both_metrics(grasp: &Grasp, space: &ObjectWrenchSpace) -> (Option<f64>, Option<f64>) {
    let q = q1(grasp).ok().and_then(|q| q.value);
    let ows = Evaluator::new(Metric::Ows, Method::Partial, Some(space))
        .and_then(|mut e| e.evaluate(grasp))
        .ok()
        .and_then(|q| q.value);
    (q, ows)
}

fn format_value(v: Option<f64>) -> String {
    v.map_or("—".to_string(), |v| format!("{v:.4}"))
}

/// The best grasp of a plan's samples by one metric, with both metrics' values.
#[derive(Clone, Debug, PartialEq)]
pub struct MetricBest {
    /// The best grasp (`None` when no sample was force closure).
    pub best: Option<BestGrasp>,
    /// Its Q1 (`None` without a best, or where Q1 has no value).
    pub q1: Option<f64>,
    /// Its Q_OWS (`None` without a best, or where Q_OWS has no value).
    pub ows: Option<f64>,
}

/// The best grasps of the plan's samples by Q1 and by Q_OWS, each with both of its values.
/// `report` is the plan of `config` (by the partial method); the other metric's plan is run here
/// on the same samples.
///
/// # Errors
/// [`PlanError`] when the other metric's plan fails.
pub fn metric_bests(
    mesh: &Mesh,
    space: &ObjectWrenchSpace,
    config: &PlanConfig,
    report: &PlanReport,
) -> Result<[MetricBest; 2], PlanError> {
    let by = |metric| -> Result<MetricBest, PlanError> {
        Ok(MetricBest::new(
            best_by(metric, mesh, space, config, report)?,
            space,
        ))
    };
    Ok([by(Metric::Q1)?, by(Metric::Ows)?])
}

impl MetricBest {
    /// `best` with its Q1 and its Q_OWS in `space` (both by the partial method).
    pub fn new(best: Option<BestGrasp>, space: &ObjectWrenchSpace) -> Self {
        let (q1, ows) = best
            .as_ref()
            .map_or((None, None), |b| both_metrics(&b.grasp, space));
        MetricBest { best, q1, ows }
    }
}

/// `part` as a percentage of `whole` (`whose` value), when both exist and `whole` is positive.
fn percent(part: Option<f64>, whole: Option<f64>, whose: &str) -> String {
    match (part, whole) {
        (Some(p), Some(w)) if w > 0.0 => format!(" ({:.0} % of the {whose}'s)", 100.0 * p / w),
        _ => String::new(),
    }
}

/// One paragraph saying how the Q1-best and the OWS-best grasps of [`metric_bests`] differ: each
/// one's value under the other metric (the seed paper's Fig. 10), or that both metrics chose the
/// same sample.
///
/// ```
/// use pqhull::grasp::FrictionModel;
/// use pqhull::grasp::ows::ObjectWrenchSpace;
/// use pqhull::grasp::quality::{Method, Metric};
/// use pqhull::mesh::Mesh;
/// use pqhull::plan::{plan, PlanConfig};
/// use pqhull::viz::plan_scene::{metric_bests, metrics_note};
///
/// let object = Mesh::cuboid([0.3, 0.2, 0.1])?;
/// let friction = FrictionModel::try_new(0.5, 4)?;
/// let space = ObjectWrenchSpace::from_mesh(&object, friction)?;
/// let config = PlanConfig { contacts: 4, samples: 20, friction, metric: Metric::Q1, seed: 1 };
/// let report = plan(&object, Some(&space), &config, Method::Partial)?;
/// let note = metrics_note(&metric_bests(&object, &space, &config, &report)?);
/// assert!(note.contains("Q_OWS"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn metrics_note(bests: &[MetricBest; 2]) -> String {
    let [by_q1, by_ows] = bests;
    match (&by_q1.best, &by_ows.best) {
        (None, None) => "Neither metric has a best grasp: no sample was force closure.".into(),
        (Some(a), Some(b)) if a.sample == b.sample => format!(
            "Both metrics choose the same grasp, sample #{} (Q1 = {}, Q_OWS = {}). Other seeds \
             or more samples often give two different grasps, as in the seed paper's Fig. 10.",
            a.sample,
            format_value(by_q1.q1),
            format_value(by_q1.ows)
        ),
        (Some(a), Some(b)) => format!(
            "The two grasps differ. The Q1-best, sample #{}, has Q1 = {} and Q_OWS = {}{}; the \
             OWS-best, sample #{}, has Q_OWS = {} and Q1 = {}{}. Q1 asks a grasp to resist \
             disturbances of every direction equally; Q_OWS only those the object's own \
             surface can produce (the seed paper's Fig. 10), so each best gives up some of the \
             other metric.",
            a.sample,
            format_value(by_q1.q1),
            format_value(by_q1.ows),
            percent(by_q1.ows, by_ows.ows, "OWS-best"),
            b.sample,
            format_value(by_ows.ows),
            format_value(by_ows.q1),
            percent(by_ows.q1, by_q1.q1, "Q1-best")
        ),
        _ => "Only one metric has a best grasp.".into(),
    }
}

/// Two panels, the best grasp of the plan's samples by Q1 and by Q_OWS ([`metric_bests`]), each
/// captioned with both of its metrics.
///
/// # Errors
/// [`PlanError`] when the other metric's plan fails.
pub fn plan_panels(
    mesh: &Mesh,
    space: &ObjectWrenchSpace,
    config: &PlanConfig,
    report: &PlanReport,
) -> Result<Vec<Panel>, PlanError> {
    Ok(panels(mesh, &metric_bests(mesh, space, config, report)?))
}

fn panels(mesh: &Mesh, bests: &[MetricBest; 2]) -> Vec<Panel> {
    let mut panels = Vec::new();
    for (b, label) in bests.iter().zip(["Q1", "OWS"]) {
        let caption = match &b.best {
            Some(best) => format!(
                "best by {label} (sample #{}): Q1 = {}, Q_OWS = {}",
                best.sample,
                format_value(b.q1),
                format_value(b.ows)
            ),
            None => format!("best by {label}: no force-closure grasp among the samples"),
        };
        let scene = grasp_scene(mesh, b.best.as_ref().map(|b| &b.grasp), caption);
        panels.push(Panel::new(format!("best by {label}"), vec![scene]));
    }
    panels
}

/// The self-contained HTML page of two best grasps ([`metric_bests`]) on `mesh`, titled with
/// the object's `name`, with [`metrics_note`] under the panels: what `pqh plan --output` and
/// `pqh demo` write. `config` is the plan's (its sample and contact counts are in the title).
///
/// ```
/// use pqhull::grasp::FrictionModel;
/// use pqhull::grasp::ows::ObjectWrenchSpace;
/// use pqhull::mesh::Mesh;
/// use pqhull::grasp::quality::{Method, Metric};
/// use pqhull::plan::{plan, PlanConfig};
/// use pqhull::viz::plan_scene::{metric_bests, plan_page};
///
/// let object = Mesh::cuboid([0.3, 0.2, 0.1])?;
/// let friction = FrictionModel::try_new(0.5, 4)?;
/// let space = ObjectWrenchSpace::from_mesh(&object, friction)?;
/// let config = PlanConfig { contacts: 4, samples: 10, friction, metric: Metric::Q1, seed: 1 };
/// let report = plan(&object, Some(&space), &config, Method::Partial)?;
/// let bests = metric_bests(&object, &space, &config, &report)?;
/// let page = plan_page(&object, "a box", &config, &bests);
/// assert!(page.contains("best by Q1") && page.contains("best by OWS"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn plan_page(mesh: &Mesh, name: &str, config: &PlanConfig, bests: &[MetricBest; 2]) -> String {
    let title = format!(
        "{name}: the best of {} random {}-contact grasps by Q1 and by the object wrench space \
         metric",
        config.samples, config.contacts
    );
    scene_page_with_note(&title, &panels(mesh, bests), &metrics_note(bests))
}
