//! `penetration_depth` (`pqhull::strategy::penetration_depth`): the signed penetration depth of
//! two convex polytopes, with the direction that separates them.

use crate::errors;
use crate::hull::{rows, with_dimension};
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pqhull::strategy::{PenetrationError, Relation, penetration_depth as depth_of};
use pyo3::prelude::*;

/// The signed penetration depth of two convex polytopes, from `penetration_depth`.
#[pyclass(module = "pqhull", frozen)]
pub struct Penetration {
    depth: f64,
    direction: Py<PyArray1<f64>>,
    translation: Py<PyArray1<f64>>,
    relation: &'static str,
    rounding: f64,
    scale: f64,
    points_processed: usize,
    facets_created: usize,
}

#[pymethods]
impl Penetration {
    /// Signed: the length of the smallest translation that separates the interiors (positive,
    /// overlapping), or minus the distance between the bodies (negative, disjoint); zero when
    /// they touch.
    #[getter]
    fn depth(&self) -> f64 {
        self.depth
    }

    /// Unit, (d,): translating `b` by `depth * direction` (or `a` by the opposite) makes the
    /// bodies touch.
    #[getter]
    fn direction<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.direction.bind(py).clone()
    }

    /// `depth * direction`, (d,): the translation of `b` that makes the bodies touch.
    #[getter]
    fn translation<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.translation.bind(py).clone()
    }

    /// "overlapping" (the depth is positive), "touching" (within `rounding` of zero, exactly
    /// zero when every difference a - b is exact in float64) or "separated" (negative).
    #[getter]
    fn relation(&self) -> &'static str {
        self.relation
    }

    /// A bound on the rounding of every difference a - b computed in float64 (0 when each is
    /// exact), and so on how far the depth can be from the one of the exact differences.
    #[getter]
    fn rounding(&self) -> f64 {
        self.rounding
    }

    /// A bound on the norm of every difference a - b: the size the accuracy is measured in.
    #[getter]
    fn scale(&self) -> f64 {
        self.scale
    }

    /// Points the partial hull added (0 when GJK decided: separated bodies need no hull).
    #[getter]
    fn points_processed(&self) -> usize {
        self.points_processed
    }

    /// Facets it created.
    #[getter]
    fn facets_created(&self) -> usize {
        self.facets_created
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "Penetration(depth={:e}, relation={:?}, direction={:?})",
            self.depth,
            self.relation,
            self.direction.bind(py).to_vec().unwrap_or_default()
        )
    }
}

/// The library's error: input the bodies' hulls cannot be taken from (an empty body, a NaN or
/// infinite coordinate, differences that overflow, a flat difference too large) is a
/// `HullError`, as for the points of a hull; the message, naming the body and the vertex, is
/// the library's.
fn error<const D: usize>(e: PenetrationError<D>) -> PyErr {
    errors::HullError::new_err(e.to_string())
}

fn penetration<const D: usize>(
    py: Python<'_>,
    a: &PyReadonlyArray2<'_, f64>,
    b: &PyReadonlyArray2<'_, f64>,
) -> PyResult<Penetration> {
    if b.shape()[1] != D {
        return Err(errors::input(format!(
            "b has {} coordinates but a has {D}",
            b.shape()[1]
        )));
    }
    let (a, b) = (rows::<D>(a), rows::<D>(b));
    let p = py.detach(|| depth_of(&a, &b)).map_err(error)?;
    Ok(Penetration {
        depth: p.depth,
        direction: PyArray1::from_slice(py, &p.direction).unbind(),
        translation: PyArray1::from_slice(py, &p.translation()).unbind(),
        relation: match p.relation {
            Relation::Overlapping => "overlapping",
            Relation::Touching => "touching",
            Relation::Separated => "separated",
        },
        rounding: p.rounding,
        scale: p.scale,
        points_processed: p.stats.points_processed,
        facets_created: p.stats.facets_created,
    })
}

/// penetration_depth(a, b): the signed penetration depth of the convex hulls of `a` ((n, d))
/// and `b` ((m, d)): the signed distance from the origin to the boundary of their Minkowski
/// difference, positive when they overlap, negative when disjoint; by GJK, then the partial
/// hull over the implicit difference; the GIL released.
#[pyfunction]
pub fn penetration_depth(
    py: Python<'_>,
    a: PyReadonlyArray2<'_, f64>,
    b: PyReadonlyArray2<'_, f64>,
) -> PyResult<Penetration> {
    let dimension = a.shape()[1];
    with_dimension!(dimension, penetration(py, &a, &b))
}
