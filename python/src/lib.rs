//! `pqhull._pqhull`: the Python extension module behind the `pqhull` package (python/pqhull).
//!
//! Arrays come in as numpy `float64` arrays (read in place, no copy of the caller's data beyond
//! the one into the hull's own scaled storage) and go out as new numpy arrays. Every error is a
//! `pqhull.Error` subclass carrying the library's message (but `ConvexHull.add_points` on a
//! hull that is not incremental, or closed, raises scipy's `RuntimeError`); batch evaluation
//! reports a bad row as NaN plus an error entry and keeps the other rows. Long computations
//! release the GIL.

mod convex_hull;
mod errors;
mod gradient;
mod grasps;
mod hull;
mod metrics;
mod ows;
mod penetration;
mod plan;
mod qhull_options;

use pyo3::prelude::*;

/// The extension module.
#[pymodule]
fn _pqhull(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    m.add_class::<convex_hull::ConvexHull>()?;
    m.add_class::<hull::Distance>()?;
    m.add_class::<hull::Distances>()?;
    m.add_class::<grasps::Quality>()?;
    m.add_class::<grasps::Batch>()?;
    m.add_class::<ows::ObjectWrenchSpace>()?;
    m.add_class::<penetration::Penetration>()?;
    m.add_class::<plan::DescentReport>()?;
    m.add_function(wrap_pyfunction!(hull::distance_to_boundary, m)?)?;
    m.add_function(wrap_pyfunction!(hull::distances_to_boundary, m)?)?;
    m.add_function(wrap_pyfunction!(penetration::penetration_depth, m)?)?;
    m.add_function(wrap_pyfunction!(grasps::q1, m)?)?;
    m.add_function(wrap_pyfunction!(grasps::qinf, m)?)?;
    m.add_function(wrap_pyfunction!(grasps::ows, m)?)?;
    m.add_function(wrap_pyfunction!(grasps::evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(ows::load_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(plan::plan_descent, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::cone_bracket, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::resist, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::gws_volume, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::grasp_matrix_metrics, m)?)?;
    Ok(())
}
