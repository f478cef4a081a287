//! The descent grasp planner from Python (`pqhull::plan::plan_descent`, `pqh plan --planner
//! descent`): grasps planned on a mesh by climbing Q1, Q∞ or Q_OWS, the GIL released.

use crate::errors;
use crate::grasps::{method_named, metric_of};
use crate::ows::{self, ObjectWrenchSpace};
use numpy::{PyArray1, PyArray3, PyArrayMethods, ToPyArray};
use pqhull::grasp::{Method, Metric};
use pqhull::plan::{DescentConfig, DescentReport as Report, PlanError, plan_descent as plan};
use pyo3::prelude::*;

/// The planned grasps of one `plan_descent` call (S starts of m contacts), and the run's work.
#[pyclass(module = "pqhull", frozen, get_all)]
pub struct DescentReport {
    /// Contact positions of each planned grasp, (S, m, 3), on the mesh's surface.
    positions: Py<PyArray3<f64>>,
    /// Their unit inward normals (the faces' they lie on), (S, m, 3).
    normals: Py<PyArray3<f64>>,
    /// Each planned grasp's value, (S,): the metric's when force closure, else the value climbed
    /// toward it (≤ 0: Q1's, Q∞'s own for Q∞).
    values: Py<PyArray1<f64>>,
    /// Whether each planned grasp is force closure, (S,).
    force_closure: Py<PyArray1<bool>>,
    /// Each start's value, (S,), as `values`.
    start_values: Py<PyArray1<f64>>,
    /// Whether each start was force closure, (S,).
    start_force_closure: Py<PyArray1<bool>>,
    /// Metric evaluations each planned grasp used, its start's included, (S,).
    evaluations: Py<PyArray1<i64>>,
    /// Moves each run accepted, (S,).
    steps: Py<PyArray1<i64>>,
    /// Why each run stopped: "step", "evaluations" or "stationary".
    stop: Vec<&'static str>,
    /// The index of the best force-closure planned grasp, or None.
    best: Option<usize>,
    /// Metric evaluations of the whole run (the sum of `evaluations`).
    total_evaluations: usize,
    /// Time spent evaluating the metric (s).
    quality_s: f64,
    /// Time spent computing gradients (s).
    gradient_s: f64,
    /// The rest of the planning time (s): drawing starts, moving contacts onto the surface.
    other_s: f64,
    /// Facets created by all the evaluations.
    facets_created: usize,
    /// The torque reference point of the planned grasps, (3,).
    torque_reference: Py<PyArray1<f64>>,
    /// Their torque scale.
    torque_scale: f64,
    /// The metric climbed (its name: "q1", "qinf", "qinf0" or "ows").
    metric: &'static str,
    /// The method it was computed by ("partial" or "full").
    method: &'static str,
}

#[pymethods]
impl DescentReport {
    fn __len__(&self) -> usize {
        self.stop.len()
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let closure = self
            .force_closure
            .bind(py)
            .to_vec()
            .map_or(0, |v| v.into_iter().filter(|&c| c).count());
        let best = match self.best {
            Some(i) => {
                let value = self.values.bind(py).get_owned(i).unwrap_or(f64::NAN);
                format!("{i} (value {value:e})")
            }
            None => "None".into(),
        };
        format!(
            "DescentReport({} starts, metric={:?}, method={:?}, force_closure={closure}, \
             best={best}, total_evaluations={})",
            self.stop.len(),
            self.metric,
            self.method,
            self.total_evaluations
        )
    }
}

impl DescentReport {
    fn new(py: Python<'_>, report: &Report, metric: Metric, method: Method) -> PyResult<Self> {
        let planned = &report.planned;
        // Every planned grasp is in the one torque frame of the run (the space's or the mesh's).
        let first = planned
            .first()
            .ok_or_else(|| errors::input("the planner returned no grasp"))?;
        let (s, m) = (planned.len(), first.grasp.contact_count());
        let contacts = |of: fn(&pqhull::grasp::Contact) -> [f64; 3]| -> PyResult<_> {
            let flat: Vec<f64> = planned
                .iter()
                .flat_map(|p| p.grasp.contacts().iter().flat_map(of))
                .collect();
            Ok(PyArray1::from_vec(py, flat).reshape([s, m, 3])?.unbind())
        };
        let count = |n: usize| i64::try_from(n).unwrap_or(i64::MAX);
        Ok(DescentReport {
            positions: contacts(pqhull::grasp::Contact::position)?,
            normals: contacts(pqhull::grasp::Contact::normal)?,
            values: column(py, planned.iter().map(|p| p.value)),
            force_closure: column(py, planned.iter().map(|p| p.force_closure)),
            start_values: column(py, planned.iter().map(|p| p.start_value)),
            start_force_closure: column(py, planned.iter().map(|p| p.start_force_closure)),
            evaluations: column(py, planned.iter().map(|p| count(p.evaluations))),
            steps: column(py, planned.iter().map(|p| count(p.steps))),
            stop: planned.iter().map(|p| p.stop.name()).collect(),
            best: report.best().map(|b| b.start),
            total_evaluations: report.evaluations,
            quality_s: report.quality_time.as_secs_f64(),
            gradient_s: report.gradient_time.as_secs_f64(),
            other_s: report.other_time.as_secs_f64(),
            facets_created: report.facets_created,
            torque_reference: first.grasp.torque_reference().to_pyarray(py).unbind(),
            torque_scale: first.grasp.torque_scale(),
            metric: metric.name(),
            method: method.name(),
        })
    }
}

/// One value per planned grasp, as a numpy array.
fn column<T: numpy::Element>(py: Python<'_>, values: impl Iterator<Item = T>) -> Py<PyArray1<T>> {
    PyArray1::from_vec(py, values.collect()).unbind()
}

/// plan_descent(mesh, *, contacts=4, friction, cone_edges, metric="q1", starts=10,
/// evaluations=50, screen=1, seed=1, method="partial", space=None) -> DescentReport: grasps planned on a
/// mesh by climbing the metric from `starts` random starts (see `pqhull.plan_descent`).
#[pyfunction]
#[pyo3(signature = (mesh, *, contacts=4, friction, cone_edges, metric="q1", starts=10,
                    evaluations=50, screen=1, seed=1, method="partial", space=None))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn plan_descent(
    py: Python<'_>,
    mesh: &Bound<'_, PyAny>,
    contacts: usize,
    friction: f64,
    cone_edges: usize,
    metric: &str,
    starts: usize,
    evaluations: usize,
    screen: usize,
    seed: u64,
    method: &str,
    space: Option<PyRef<'_, ObjectWrenchSpace>>,
) -> PyResult<DescentReport> {
    let metric = match metric {
        // The planner's own refusal names it (it does not climb resistance; no wrench is used).
        "resist" => Metric::Resist { wrench: [0.0; 6] },
        name => metric_of(name, false, None)?,
    };
    let method = method_named(method)?;
    if !matches!(method, Method::Partial | Method::Full) {
        // The planner climbs Q1 toward force closure (but for Q∞) and follows gradients: a
        // method of Q1 and of every metric it climbs, and exact (this build has no Qhull).
        return Err(errors::input(format!(
            "the descent planner evaluates by method \"partial\" or \"full\", not {:?}",
            method.name()
        )));
    }
    if space.is_some() && metric != Metric::Ows {
        return Err(errors::input(
            "space= is for metric \"ows\" (an ObjectWrenchSpace of the same mesh)",
        ));
    }
    let model = ows::friction(friction, cone_edges)?;
    let mesh = ows::mesh_of(py, mesh)?;
    let config = DescentConfig {
        starts,
        evaluations,
        screen,
        seed,
        ..DescentConfig::new(contacts, model, metric)
    };
    // Q_OWS without a space: the mesh's own, with the grasps' friction (as `pqh plan` builds
    // it), built only for a configuration the planner accepts. Without a space the planner
    // refuses a bad configuration, or else the missing space, before any work (its documented
    // order): so asking it first costs nothing and spares building the space for nothing.
    let own = match (metric, &space) {
        (Metric::Ows, None) => {
            match plan(&mesh, None, &config, method) {
                Ok(_) | Err(PlanError::NoWrenchSpace) => {}
                Err(e) => return Err(errors::plan(e)),
            }
            Some(ows::from_mesh(py, &mesh, model)?.inner)
        }
        _ => None,
    };
    let space = space.as_ref().map(|s| &s.inner).or(own.as_ref());
    let report = py
        .detach(|| plan(&mesh, space, &config, method))
        .map_err(errors::plan)?;
    DescentReport::new(py, &report, metric, method)
}
