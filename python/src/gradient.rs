//! `gradient=True` of `q1` and `evaluate(metric="q1")`: the exact gradient of Q1
//! ([`pqhull::grasp::q1_gradient`]) with respect to every contact's position and unit normal and
//! the friction coefficient, as numpy arrays.

use crate::errors;
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, ToPyArray};
use pqhull::grasp::quality::{Evaluator, Method, Metric, Quality as Q1};
use pqhull::grasp::{Gradient, GradientError, Grasp, q1_gradient};
use pyo3::prelude::*;

/// The refusal of `gradient=True` for another metric than Q1.
pub(crate) fn only_q1(metric: &str) -> PyErr {
    errors::input(format!(
        "gradient is computed for q1 only so far (metric {metric:?} has none): \
         ask for metric=\"q1\" or gradient=False"
    ))
}

/// The message of a grasp whose Q1 was found but could not be differentiated.
pub(crate) fn message(e: &GradientError) -> String {
    format!("gradient: {e}")
}

/// Why a single grasp has no value or no gradient (kept apart so the library's errors become
/// Python ones after the GIL is taken back).
pub(crate) enum Failure {
    Quality(pqhull::grasp::quality::QualityError),
    Gradient(GradientError),
}

impl Failure {
    pub(crate) fn into_py(self) -> PyErr {
        match self {
            Failure::Quality(e) => errors::quality(e),
            Failure::Gradient(e) => errors::QualityError::new_err(message(&e)),
        }
    }
}

/// Q1 of `grasp` by `method` and its gradient (run with the GIL released by the caller).
pub(crate) fn q1_and_gradient(grasp: &Grasp, method: Method) -> Result<(Q1, Gradient), Failure> {
    let quality = Evaluator::new(Metric::Q1, method)
        .evaluate(grasp)
        .map_err(Failure::Quality)?;
    let gradient = q1_gradient(grasp, &quality).map_err(Failure::Gradient)?;
    Ok((quality, gradient))
}

/// One grasp's gradient as Python values: (m, 3) positions, (m, 3) normals, friction and
/// whether Q1 is differentiable there.
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

/// A batch's gradients, row by row: NaN (and `differentiable` False) for a row without one.
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
