//! The view of a plan: the best grasp by Q1 beside the best by the object wrench space metric
//! (the seed paper's Fig. 10), as [`scene`](super::scene) panels and a self-contained page.

use super::scene::{Color, Panel, Scene, scene_page};
use crate::grasp::Grasp;
use crate::grasp::ows::{ObjectWrenchSpace, OwsEvaluator};
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
    let q = q1(grasp).ok().map(|q| q.value);
    let ows = OwsEvaluator::new(Method::Partial)
        .evaluate(grasp, space)
        .ok()
        .and_then(|q| q.value);
    (q, ows)
}

fn format_value(v: Option<f64>) -> String {
    v.map_or("—".to_string(), |v| format!("{v:.4}"))
}

/// Two panels, the best grasp of the plan's samples by Q1 and by Q_OWS, each captioned with
/// both of its metrics. `report` is the plan of `config` (by the partial method); the other
/// metric's plan is run here on the same samples.
///
/// # Errors
/// [`PlanError`] when the other metric's plan fails.
pub fn plan_panels(
    mesh: &Mesh,
    space: &ObjectWrenchSpace,
    config: &PlanConfig,
    report: &PlanReport,
) -> Result<Vec<Panel>, PlanError> {
    let mut panels = Vec::new();
    for (metric, label) in [(Metric::Q1, "Q1"), (Metric::Ows, "OWS")] {
        let best = best_by(metric, mesh, space, config, report)?;
        let caption = match &best {
            Some(b) => {
                let (q, ows) = both_metrics(&b.grasp, space);
                format!(
                    "best by {label} (sample #{}): Q1 = {}, Q_OWS = {}",
                    b.sample,
                    format_value(q),
                    format_value(ows)
                )
            }
            None => format!("best by {label}: no force-closure grasp among the samples"),
        };
        let scene = grasp_scene(mesh, best.as_ref().map(|b| &b.grasp), caption);
        panels.push(Panel::new(format!("best by {label}"), vec![scene]));
    }
    Ok(panels)
}

/// The self-contained HTML page of [`plan_panels`], titled with the object's `name`: what
/// `pqh plan --output` and `pqh demo` write.
///
/// ```
/// use pqhull::grasp::FrictionModel;
/// use pqhull::grasp::ows::ObjectWrenchSpace;
/// use pqhull::mesh::Mesh;
/// use pqhull::grasp::quality::{Method, Metric};
/// use pqhull::plan::{plan, PlanConfig};
/// use pqhull::viz::plan_scene::plan_page;
///
/// let object = Mesh::cuboid([0.3, 0.2, 0.1])?;
/// let friction = FrictionModel::try_new(0.5, 4)?;
/// let space = ObjectWrenchSpace::from_mesh(&object, friction)?;
/// let config = PlanConfig { contacts: 4, samples: 10, friction, metric: Metric::Q1, seed: 1 };
/// let report = plan(&object, Some(&space), &config, Method::Partial)?;
/// let page = plan_page(&object, "a box", &space, &config, &report)?;
/// assert!(page.contains("best by Q1") && page.contains("best by OWS"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`plan_panels`].
pub fn plan_page(
    mesh: &Mesh,
    name: &str,
    space: &ObjectWrenchSpace,
    config: &PlanConfig,
    report: &PlanReport,
) -> Result<String, PlanError> {
    let panels = plan_panels(mesh, space, config, report)?;
    let title = format!(
        "{name}: the best of {} random {}-contact grasps by Q1 and by the object wrench space \
         metric",
        config.samples, config.contacts
    );
    Ok(scene_page(&title, &panels))
}
