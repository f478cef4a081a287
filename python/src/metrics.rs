//! The other metrics from Python, one grasp at a time: the cone bracket and wrench resistance
//! (`pqhull::grasp::Evaluator`), the GWS volume and the grasp matrix's singular values
//! (`pqhull::grasp::metrics`).

use crate::errors;
use crate::grasps::{Quality, method_of, one_grasp, single};
use numpy::{PyArray1, PyReadonlyArray1, PyReadonlyArray2, ToPyArray};
use pqhull::grasp::metrics;
use pqhull::grasp::{Evaluator, Metric, QualityError};
use pyo3::prelude::*;

/// cone_bracket(positions, normals, tangents=None, *, friction, cone_edges, torque_reference=None,
/// torque_scale=None, method="partial") -> (low, high): Q1 of the true circular friction cones
/// lies between them (the pyramids inscribed in and circumscribed about the cones, each widened
/// by its evaluation's accuracy).
#[pyfunction]
#[pyo3(signature = (positions, normals, tangents=None, *, torsion=None, friction, cone_edges,
                    torque_reference=None, torque_scale=None, method="partial"))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn cone_bracket(
    py: Python<'_>,
    positions: PyReadonlyArray2<'_, f64>,
    normals: PyReadonlyArray2<'_, f64>,
    tangents: Option<PyReadonlyArray2<'_, f64>>,
    torsion: Option<PyReadonlyArray1<'_, f64>>,
    friction: f64,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
    method: &str,
) -> PyResult<(f64, f64)> {
    let method = method_of(method, Metric::Q1)?;
    let (g, _) = one_grasp(
        positions,
        normals,
        tangents,
        torsion,
        friction,
        cone_edges,
        torque_reference,
        torque_scale,
    )?;
    let evaluation = py
        .detach(|| Evaluator::new(Metric::ConeBracket, method, None)?.evaluate(&g))
        .map_err(errors::quality)?;
    let bracket = evaluation
        .bracket
        .expect("the cone bracket's evaluation has a bracket");
    Ok((bracket.low, bracket.high))
}

/// resist(positions, normals, tangents=None, *, wrench, friction, cone_edges,
/// torque_reference=None, torque_scale=None, method="partial") -> Quality: the largest t with
/// -t*wrench in the grasp wrench space (Q_OWS with that one disturbance; value None when the grasp
/// is not force closure). `wrench` is 6 numbers in the grasp's torque units.
#[pyfunction]
#[pyo3(signature = (positions, normals, tangents=None, *, torsion=None, wrench, friction, cone_edges,
                    torque_reference=None, torque_scale=None, method="partial"))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn resist(
    py: Python<'_>,
    positions: PyReadonlyArray2<'_, f64>,
    normals: PyReadonlyArray2<'_, f64>,
    tangents: Option<PyReadonlyArray2<'_, f64>>,
    torsion: Option<PyReadonlyArray1<'_, f64>>,
    wrench: PyReadonlyArray1<'_, f64>,
    friction: f64,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
    method: &str,
) -> PyResult<Quality> {
    let w = wrench
        .as_slice()
        .map_err(|e| errors::input(e.to_string()))?;
    let wrench: [f64; 6] = w
        .try_into()
        .map_err(|_| errors::input(format!("wrench must have 6 numbers, not {}", w.len())))?;
    single(
        py,
        positions,
        normals,
        tangents,
        torsion,
        friction,
        cone_edges,
        torque_reference,
        torque_scale,
        Metric::Resist { wrench },
        method,
        None,
        false,
    )
}

/// gws_volume(positions, normals, tangents=None, *, friction, cone_edges, torque_reference=None,
/// torque_scale=None) -> float: the volume of the grasp wrench space (its full hull).
#[pyfunction]
#[pyo3(signature = (positions, normals, tangents=None, *, torsion=None, friction, cone_edges,
                    torque_reference=None, torque_scale=None))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn gws_volume(
    py: Python<'_>,
    positions: PyReadonlyArray2<'_, f64>,
    normals: PyReadonlyArray2<'_, f64>,
    tangents: Option<PyReadonlyArray2<'_, f64>>,
    torsion: Option<PyReadonlyArray1<'_, f64>>,
    friction: f64,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
) -> PyResult<f64> {
    let (g, _) = one_grasp(
        positions,
        normals,
        tangents,
        torsion,
        friction,
        cone_edges,
        torque_reference,
        torque_scale,
    )?;
    py.detach(|| metrics::gws_volume(&g)).map_err(|e| match e {
        // The hull engine's refusal (non-finite wrenches) is an input error with the engine's
        // message, as before the library wrapped it.
        QualityError::Hull(e) => errors::input(e.to_string()),
        e => errors::quality(e),
    })
}

/// grasp_matrix_metrics(positions, normals, tangents=None, *, friction, cone_edges,
/// torque_reference=None, torque_scale=None) -> (singular_values, sigma_min, isotropy): the
/// grasp matrix's six singular values (largest first), the smallest, and their ratio.
#[pyfunction]
#[pyo3(signature = (positions, normals, tangents=None, *, torsion=None, friction, cone_edges,
                    torque_reference=None, torque_scale=None))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn grasp_matrix_metrics<'py>(
    py: Python<'py>,
    positions: PyReadonlyArray2<'_, f64>,
    normals: PyReadonlyArray2<'_, f64>,
    tangents: Option<PyReadonlyArray2<'_, f64>>,
    torsion: Option<PyReadonlyArray1<'_, f64>>,
    friction: f64,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
) -> PyResult<(Bound<'py, PyArray1<f64>>, f64, f64)> {
    let (g, _) = one_grasp(
        positions,
        normals,
        tangents,
        torsion,
        friction,
        cone_edges,
        torque_reference,
        torque_scale,
    )?;
    let s = metrics::grasp_matrix_singular_values(&g).map_err(errors::quality)?;
    // Largest first: σ_min is the last, the isotropy σ_min / σ_max (0 when σ_max is 0).
    let isotropy = if s[0] > 0.0 { s[5] / s[0] } else { 0.0 };
    Ok((s.to_pyarray(py), s[5], isotropy))
}
