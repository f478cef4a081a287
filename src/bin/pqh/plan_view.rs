//! The HTML view of a plan: the best grasp by Q1 beside the best by OWS (the seed's Fig. 10).

use crate::error::CliError;
use pqhull::grasp::Grasp;
use pqhull::grasp::ows::{ObjectWrenchSpace, OwsEvaluator};
use pqhull::grasp::quality::q1;
use pqhull::grasp::quality::{Method, Metric};
use pqhull::mesh::Mesh;
use pqhull::plan::{BestGrasp, PlanConfig, PlanReport, plan};
use pqhull::viz::scene::{Color, Panel, Scene, scene_page};
use std::path::{Path, PathBuf};

/// Contact markers: one colour per finger, so the two panels can be compared finger by finger.
const FINGERS: [Color; 6] = [
    Color::RED,
    Color::BLUE,
    Color::GREEN,
    Color::rgb(230, 150, 30),
    Color::rgb(140, 60, 170),
    Color::rgb(20, 160, 170),
];

/// The best grasp of `config`'s samples by `metric` (reusing `report` when it is that plan).
fn best_by(
    metric: Metric,
    mesh: &Mesh,
    space: &ObjectWrenchSpace,
    config: &PlanConfig,
    report: &PlanReport,
) -> Result<Option<BestGrasp>, CliError> {
    if config.metric == metric {
        return Ok(report.best.clone());
    }
    let other = PlanConfig { metric, ..*config };
    plan(mesh, Some(space), &other, Method::Partial)
        .map(|r| r.best)
        .map_err(|e| CliError::Geometry(e.to_string()))
}

/// Both metrics of `grasp`: (Q1, Q_OWS).
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

/// The object with `grasp`'s contacts (markers, pushing directions, friction cone edges).
fn grasp_scene(mesh: &Mesh, grasp: Option<&Grasp>, caption: String) -> Scene {
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
        // The finger comes from outside: draw its approach along −n, ending at the contact.
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

/// Writes the view to `path`; returns the path written.
///
/// # Errors
/// A failed plan or an unwritable path.
pub fn write(
    path: &Path,
    mesh: &Mesh,
    name: &str,
    space: &ObjectWrenchSpace,
    config: &PlanConfig,
    report: &PlanReport,
) -> Result<PathBuf, CliError> {
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
    let title = format!(
        "{name}: the best of {} random {}-contact grasps by Q1 and by the object wrench space \
         metric",
        config.samples, config.contacts
    );
    let page = scene_page(&title, &panels);
    std::fs::write(path, page)
        .map_err(|e| CliError::Input(format!("cannot write {}: {e}", path.display())))?;
    Ok(path.to_path_buf())
}
