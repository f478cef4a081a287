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

/// The Python exception of a library [`QualityError`](pqhull::grasp::QualityError) with
/// `message`: a [`GraspError`] when the circumscribed cones' grasp could not be built, an
/// [`InputError`] for a wrench to resist that is zero or not finite, a volume beyond `f64::MAX`
/// or a grasp matrix whose SVD did not converge (the classes of the metrics' errors before they
/// became `QualityError`s), a [`QualityError`] otherwise.
fn of_quality(e: &pqhull::grasp::QualityError, message: String) -> PyErr {
    use pqhull::grasp::QualityError as E;
    match e {
        E::CircumscribedFriction(_) => GraspError::new_err(message),
        E::ResistedWrench(_) | E::SvdNoConvergence | E::VolumeOverflow => {
            InputError::new_err(message)
        }
        _ => QualityError::new_err(message),
    }
}

/// The `pqhull.Error` of a library [`QualityError`](pqhull::grasp::QualityError) (see
/// [`of_quality`]), with its message; the circumscribed cones' grasp error keeps the grasp
/// error's own message, as before the library wrapped it.
pub fn quality(e: pqhull::grasp::QualityError) -> PyErr {
    let message = match &e {
        pqhull::grasp::QualityError::CircumscribedFriction(g) => g.to_string(),
        e => e.to_string(),
    };
    of_quality(&e, message)
}

/// The `pqhull.Error` of a planner's error, with the library's message: a [`GraspError`] or a
/// [`QualityError`] when a grasp or its evaluation failed, an [`InputError`] for a configuration
/// the planner refuses (its bounds, a metric it does not climb, ...); a metric's error has its
/// class as in [`quality`].
pub fn plan(e: pqhull::plan::PlanError) -> PyErr {
    use pqhull::plan::PlanError;
    let message = e.to_string();
    match e {
        PlanError::Grasp(_) => GraspError::new_err(message),
        PlanError::Quality(e) => of_quality(&e, message),
        _ => InputError::new_err(message),
    }
}
