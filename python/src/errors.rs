//! The `pqhull.Error` hierarchy: `ValueError` subclasses, one per library error family.

use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

create_exception!(
    pqhull,
    Error,
    PyValueError,
    "Every pqhull error: a ValueError with the library's message."
);
create_exception!(
    pqhull,
    HullError,
    Error,
    "The points admit no hull (too few, flat, not finite, ...)."
);
create_exception!(
    pqhull,
    GraspError,
    Error,
    "A contact, friction model or grasp is invalid."
);
create_exception!(
    pqhull,
    QualityError,
    Error,
    "A grasp could not be evaluated."
);
create_exception!(
    pqhull,
    InputError,
    Error,
    "An array has the wrong shape, or an argument is out of range."
);

/// Adds the exception classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("Error", py.get_type::<Error>())?;
    m.add("HullError", py.get_type::<HullError>())?;
    m.add("GraspError", py.get_type::<GraspError>())?;
    m.add("QualityError", py.get_type::<QualityError>())?;
    m.add("InputError", py.get_type::<InputError>())?;
    Ok(())
}

/// An [`InputError`] with `message`.
pub fn input(message: impl Into<String>) -> PyErr {
    InputError::new_err(message.into())
}

/// A [`HullError`] from the library's.
pub fn hull(e: pqhull::HullError) -> PyErr {
    HullError::new_err(e.to_string())
}

/// A [`GraspError`] with `message`.
pub fn grasp(message: impl Into<String>) -> PyErr {
    GraspError::new_err(message.into())
}

/// A [`QualityError`] from the library's.
pub fn quality(e: pqhull::grasp::quality::QualityError) -> PyErr {
    QualityError::new_err(e.to_string())
}

/// The `pqhull.Error` of a planner's error, with the library's message: a [`GraspError`] or a
/// [`QualityError`] when a grasp or its evaluation failed, an [`InputError`] for a configuration
/// the planner refuses (its bounds, a metric it does not climb, ...).
pub fn plan(e: pqhull::plan::PlanError) -> PyErr {
    use pqhull::grasp::metrics::MetricError;
    use pqhull::plan::PlanError;
    let message = e.to_string();
    match e {
        PlanError::Grasp(_) | PlanError::Metric(MetricError::Grasp(_)) => {
            GraspError::new_err(message)
        }
        PlanError::Quality(_) | PlanError::Metric(MetricError::Quality(_)) => {
            QualityError::new_err(message)
        }
        _ => InputError::new_err(message),
    }
}
