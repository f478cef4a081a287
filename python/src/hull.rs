//! `distance_to_boundary` (the partial hull), and what the hull classes share: the dispatch on
//! the dimension and the conversion of arrays. `ConvexHull` is in `convex_hull.rs`.

use crate::errors;
use numpy::{PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pqhull::{ClosestToOrigin, Hull};
use pyo3::prelude::*;

/// Runs `$run::<D>($args)` for the dimension `$d` (2 to 8), else an input error.
macro_rules! with_dimension {
    ($d:expr, $run:ident($($args:expr),*)) => {
        match $d {
            2 => $run::<2>($($args),*),
            3 => $run::<3>($($args),*),
            4 => $run::<4>($($args),*),
            5 => $run::<5>($($args),*),
            6 => $run::<6>($($args),*),
            7 => $run::<7>($($args),*),
            8 => $run::<8>($($args),*),
            d => Err(errors::input(format!(
                "points have {d} coordinates; pqhull works in 2 to 8 dimensions"
            ))),
        }
    };
}
pub(crate) use with_dimension;

/// The rows of an (n, D) array as points.
fn rows<const D: usize>(points: &PyReadonlyArray2<'_, f64>) -> Vec<[f64; D]> {
    let view = points.as_array();
    view.rows()
        .into_iter()
        .map(|r| std::array::from_fn(|j| r[j]))
        .collect()
}

/// `value` as a C-contiguous float64 numpy array (numpy.ascontiguousarray), or an input error.
pub fn float_array<'py>(value: &Bound<'py, PyAny>, name: &str) -> PyResult<Bound<'py, PyAny>> {
    let numpy = value.py().import("numpy")?;
    numpy
        .call_method1("ascontiguousarray", (value, "float64"))
        .map_err(|e| errors::input(format!("{name}: not an array of numbers ({e})")))
}

/// The signed distance from a query point to a hull's boundary, from a partial hull.
#[pyclass(module = "pqhull", frozen, get_all)]
pub struct Distance {
    /// Positive inside, negative outside, zero on the boundary (the sign is exact).
    signed_distance: f64,
    /// The deciding facet's vertex indices.
    facet: Vec<usize>,
    /// The point of the boundary nearest the query.
    nearest_point: Vec<f64>,
    /// Points added to the partial hull.
    points_processed: usize,
    /// Facets created.
    facets_created: usize,
    /// Expansions.
    expansions: usize,
}

#[pymethods]
impl Distance {
    fn __repr__(&self) -> String {
        format!(
            "Distance(signed_distance={:e}, facet={:?}, points_processed={})",
            self.signed_distance, self.facet, self.points_processed
        )
    }
}

fn distance<const D: usize>(
    py: Python<'_>,
    points: &PyReadonlyArray2<'_, f64>,
    query: Option<&PyReadonlyArray1<'_, f64>>,
) -> PyResult<Distance> {
    let input = rows::<D>(points);
    let q: [f64; D] = match query {
        None => [0.0; D],
        Some(q) => {
            let q = q.as_slice().map_err(|e| errors::input(e.to_string()))?;
            if q.len() != D {
                return Err(errors::input(format!(
                    "query has {} coordinates but the points have {D}",
                    q.len()
                )));
            }
            std::array::from_fn(|j| q[j])
        }
    };
    if q.iter().any(|x| !x.is_finite()) {
        return Err(errors::input("query has a NaN or infinite coordinate"));
    }
    let (_, result) = py
        .detach(|| Hull::try_with_strategy(&input, ClosestToOrigin::towards(q)))
        .map_err(errors::hull)?;
    Ok(Distance {
        signed_distance: result.signed_distance,
        facet: result.closest_facet_vertices.to_vec(),
        nearest_point: result.nearest_point.to_vec(),
        points_processed: result.stats.points_processed,
        facets_created: result.stats.facets_created,
        expansions: result.stats.expansions,
    })
}

/// distance_to_boundary(points, query=None): the signed distance from `query` (default the
/// origin) to the boundary of the hull of `points`, positive inside, by a partial hull that stops
/// as soon as the nearest facet is certain.
#[pyfunction]
#[pyo3(signature = (points, query=None))]
pub fn distance_to_boundary(
    py: Python<'_>,
    points: PyReadonlyArray2<'_, f64>,
    query: Option<PyReadonlyArray1<'_, f64>>,
) -> PyResult<Distance> {
    let dimension = points.shape()[1];
    with_dimension!(dimension, distance(py, &points, query.as_ref()))
}
