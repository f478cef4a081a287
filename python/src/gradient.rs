//! `gradient=True` of `q1`, `qinf`, `ows` and `evaluate(metric="q1" / "qinf" / "ows")`: the
//! exact gradient of Q1, Q∞ and Q_OWS ([`pqhull::grasp::q1_gradient`], [`qinf_gradient`],
//! [`ows_gradient`]) with respect to every contact's position and unit normal and the friction
//! coefficient, as numpy arrays.

use crate::errors;
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, ToPyArray};
use pqhull::grasp::ows::ObjectWrenchSpace as Space;
use pqhull::grasp::{
    Evaluation, Evaluator, Gradient, GradientError, Grasp, Method, Metric, QualityError,
    evaluate_batch, ows_gradient, q1_gradient, qinf_gradient,
};
use pyo3::prelude::*;
use std::time::Instant;

/// Whether `metric` by `method` has a gradient: Q1 and Q∞ by any of their methods, Q_OWS by an
/// exact one. The refusal (an input error naming the metric as the caller did, `name`)
/// otherwise.
pub(crate) fn check(metric: Metric, method: Method, name: &str) -> PyResult<()> {
    if !matches!(metric, Metric::Q1 | Metric::QInf { .. } | Metric::Ows) {
        return Err(unsupported(name));
    }
    if method == Method::Ellipsoid {
        return Err(errors::input(
            "gradient needs an exact method (the ellipsoid's value is an approximation): \
             method=\"partial\", \"full\" or \"partial-rays\"",
        ));
    }
    Ok(())
}

/// The refusal of `gradient=True` for a metric without one (named as the caller did).
fn unsupported(name: &str) -> PyErr {
    errors::input(format!(
        "gradient is computed for q1, qinf and ows only (metric {name:?} has none): \
         ask for one of them or gradient=False"
    ))
}

/// The message of a grasp whose value was found but could not be differentiated.
pub(crate) fn message(e: &GradientError) -> String {
    format!("gradient: {e}")
}

/// The message of a force-closure grasp whose Q_OWS was found but not its gradient (the facet
/// the deciding disturbance's ray leaves by could not be recovered).
const NO_OWS_GRADIENT: &str = "gradient: Q_OWS has a value but the facet its deciding \
                               disturbance leaves by was not found, so no gradient";

/// Why a single grasp has no value or no gradient (kept apart so the library's errors become
/// Python ones after the GIL is taken back).
pub(crate) enum Failure {
    Quality(QualityError),
    Gradient(GradientError),
    /// Q_OWS with a value and no gradient.
    NoOwsGradient,
    /// A metric without a gradient (refused by [`check`] before any work).
    Unsupported(Metric),
}

impl Failure {
    pub(crate) fn into_py(self) -> PyErr {
        match self {
            Failure::Quality(e) => errors::quality(e),
            Failure::Gradient(e) => errors::QualityError::new_err(message(&e)),
            Failure::NoOwsGradient => errors::QualityError::new_err(NO_OWS_GRADIENT),
            Failure::Unsupported(metric) => unsupported(metric.name()),
        }
    }
}

/// `metric` of one grasp by `method` (`space`: Q_OWS's), and its gradient; run with the GIL
/// released by the caller. The evaluation's time is the whole call's (the value and its
/// gradient). The gradient is None exactly when the value is (Q_OWS of a grasp not in force
/// closure).
pub(crate) fn one(
    grasp: &Grasp,
    metric: Metric,
    method: Method,
    space: Option<&Space>,
) -> Result<(Evaluation, Option<Gradient>), Failure> {
    let started = Instant::now();
    if !matches!(metric, Metric::Q1 | Metric::QInf { .. } | Metric::Ows) {
        return Err(Failure::Unsupported(metric));
    }
    // Only Q_OWS takes the space (and needs it).
    let space = space.filter(|_| metric == Metric::Ows);
    let mut evaluation = Evaluator::new(metric, method, space)
        .and_then(|mut evaluator| evaluator.evaluate(grasp))
        .map_err(Failure::Quality)?;
    let gradient = match space {
        Some(space) => ows_row_gradient(grasp, space, &evaluation).ok_or(Failure::NoOwsGradient)?,
        None => Some(hull_gradient(grasp, &evaluation).map_err(Failure::Gradient)?),
    };
    evaluation.stats.elapsed = started.elapsed();
    Ok((evaluation, gradient))
}

/// Q1's or Q∞'s gradient (the evaluation's metric says which) of `evaluation`, the grasp's value.
fn hull_gradient(grasp: &Grasp, evaluation: &Evaluation) -> Result<Gradient, GradientError> {
    match evaluation.metric {
        Metric::QInf { .. } => qinf_gradient(grasp, evaluation),
        _ => q1_gradient(grasp, evaluation),
    }
}

/// Q_OWS's gradient: `Some(None)` without a value (not force closure: no gradient either),
/// `None` for a value without a gradient.
fn ows_row_gradient(
    grasp: &Grasp,
    space: &Space,
    evaluation: &Evaluation,
) -> Option<Option<Gradient>> {
    match evaluation.value {
        None => Some(None),
        Some(_) => ows_gradient(grasp, space, evaluation).map(Some),
    }
}

/// One batch row: the value (None: Q_OWS not in force closure), force closure, the gradient
/// (None exactly when the value is).
pub(crate) type Row = (Option<f64>, bool, Option<Gradient>);

/// `metric` of every grasp by `method` and its gradient, in input order (the library's batch
/// evaluation, then each row's gradient on rayon's pool): run inside the caller's thread pool,
/// with the GIL released. A row whose value is found but not its gradient is a bad row (its
/// message).
pub(crate) fn batch(
    grasps: &[Grasp],
    metric: Metric,
    method: Method,
    space: Option<&Space>,
) -> Vec<Result<Row, String>> {
    use rayon::prelude::*;
    let space = match (metric, space) {
        (Metric::Q1 | Metric::QInf { .. }, _) => None,
        (Metric::Ows, Some(space)) => Some(space),
        (metric, space) => {
            let why = match space {
                None if metric == Metric::Ows => QualityError::OwsNeedsWrenchSpace.to_string(),
                _ => format!("gradient: metric {metric} has none"),
            };
            return grasps.iter().map(|_| Err(why.clone())).collect();
        }
    };
    let values = match evaluate_batch(grasps, metric, method, space) {
        Ok(values) => values,
        Err(e) => return grasps.iter().map(|_| Err(e.to_string())).collect(),
    };
    grasps
        .par_iter()
        .zip(values.into_par_iter())
        .map(|(g, r)| {
            let q = r.map_err(|e| e.to_string())?;
            let d = match space {
                Some(space) => ows_row_gradient(g, space, &q).ok_or(NO_OWS_GRADIENT)?,
                None => Some(hull_gradient(g, &q).map_err(|e| message(&e))?),
            };
            Ok((q.value, q.force_closure, d))
        })
        .collect()
}

/// One grasp's gradient as Python values: (m, 3) positions, (m, 3) normals, friction and
/// whether the value is differentiable there.
pub(crate) struct One {
    pub(crate) positions: Py<PyArray2<f64>>,
    pub(crate) normals: Py<PyArray2<f64>>,
    pub(crate) friction: f64,
    pub(crate) differentiable: bool,
}

impl One {
    pub(crate) fn new(py: Python<'_>, g: &Gradient) -> Self {
        let rows = |v: &[[f64; 3]]| {
            Array2::from_shape_vec((v.len(), 3), v.as_flattened().to_vec())
                .expect("m rows of 3")
                .into_pyarray(py)
                .unbind()
        };
        One {
            positions: rows(&g.positions),
            normals: rows(&g.normals),
            friction: g.friction,
            differentiable: g.differentiable,
        }
    }
}

/// A batch's gradients, row by row: NaN (and `differentiable` False) for a row without one (a
/// bad row, or Q_OWS of a grasp not in force closure, whose value is NaN too).
pub(crate) struct Columns {
    contacts: usize,
    positions: Vec<f64>,
    normals: Vec<f64>,
    friction: Vec<f64>,
    differentiable: Vec<bool>,
}

/// The batch's gradient arrays: (N, m, 3), (N, m, 3), (N,) and (N,) bool.
pub(crate) type Arrays = (
    Py<PyArray3<f64>>,
    Py<PyArray3<f64>>,
    Py<PyArray1<f64>>,
    Py<PyArray1<bool>>,
);

impl Columns {
    /// `rows` grasps of `contacts` contacts, none filled yet.
    pub(crate) fn new(rows: usize, contacts: usize) -> Self {
        Columns {
            contacts,
            positions: vec![f64::NAN; rows * contacts * 3],
            normals: vec![f64::NAN; rows * contacts * 3],
            friction: vec![f64::NAN; rows],
            differentiable: vec![false; rows],
        }
    }

    /// Row `i`'s gradient.
    pub(crate) fn set(&mut self, i: usize, g: &Gradient) {
        let span = i * self.contacts * 3..(i + 1) * self.contacts * 3;
        self.positions[span.clone()].copy_from_slice(g.positions.as_flattened());
        self.normals[span].copy_from_slice(g.normals.as_flattened());
        self.friction[i] = g.friction;
        self.differentiable[i] = g.differentiable;
    }

    pub(crate) fn into_arrays(self, py: Python<'_>) -> Arrays {
        let rows = self.friction.len();
        let shape = (rows, self.contacts, 3);
        let cube = |v: Vec<f64>| {
            Array3::from_shape_vec(shape, v)
                .expect("N·m·3 values")
                .into_pyarray(py)
                .unbind()
        };
        (
            cube(self.positions),
            cube(self.normals),
            self.friction.to_pyarray(py).unbind(),
            self.differentiable.to_pyarray(py).unbind(),
        )
    }
}
