//! `distance_to_boundary` (the partial hull), and what the hull classes share: the dispatch on
//! the dimension and the conversion of arrays. `ConvexHull` is in `convex_hull.rs`.

use crate::errors;
use numpy::{PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pqhull::strategy::{QueryError, distances_to_boundary as distances_of};
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
pub(crate) fn rows<const D: usize>(points: &PyReadonlyArray2<'_, f64>) -> Vec<[f64; D]> {
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

/// Signed distances from many query points to one hull's boundary.
#[pyclass(module = "pqhull", frozen)]
pub struct Distances {
    signed_distance: Py<PyArray1<f64>>,
    facets: Py<PyArray2<i32>>,
    nearest_points: Py<PyArray2<f64>>,
    points_processed: usize,
    facets_created: usize,
}

#[pymethods]
impl Distances {
    /// Per query: positive inside, negative outside, zero on the boundary (the sign is exact).
    #[getter]
    fn signed_distance<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.signed_distance.bind(py).clone()
    }

    /// Per query, the deciding facet's vertex indices, (m, d).
    #[getter]
    fn facets<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i32>> {
        self.facets.bind(py).clone()
    }

    /// Per query, the point of the boundary nearest it, (m, d).
    #[getter]
    fn nearest_points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.nearest_points.bind(py).clone()
    }

    /// Points the shared partial hull (or the largest fresh one) added.
    #[getter]
    fn points_processed(&self) -> usize {
        self.points_processed
    }

    /// Facets it created.
    #[getter]
    fn facets_created(&self) -> usize {
        self.facets_created
    }

    fn __len__(&self, py: Python<'_>) -> usize {
        self.signed_distance.bind(py).len()
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "Distances(queries={}, points_processed={})",
            self.signed_distance.bind(py).len(),
            self.points_processed
        )
    }
}

fn distances<const D: usize>(
    py: Python<'_>,
    points: &PyReadonlyArray2<'_, f64>,
    queries: &PyReadonlyArray2<'_, f64>,
) -> PyResult<Distances> {
    if queries.shape()[1] != D {
        return Err(errors::input(format!(
            "queries have {} coordinates but the points have {D}",
            queries.shape()[1]
        )));
    }
    let (input, qs) = (rows::<D>(points), rows::<D>(queries));
    let results = py
        .detach(|| distances_of(&input, &qs))
        .map_err(|e| match e {
            QueryError::Hull(e) => errors::hull(e),
            e => errors::input(e.to_string()),
        })?;
    let facets = results
        .iter()
        .map(|r| {
            r.closest_facet_vertices
                .iter()
                .map(|&v| i32::try_from(v).map_err(|_| errors::input("more than 2^31 points")))
                .collect::<PyResult<Vec<i32>>>()
        })
        .collect::<PyResult<Vec<_>>>()?;
    let table = |rows: Vec<Vec<f64>>| -> PyResult<Py<PyArray2<f64>>> {
        if rows.is_empty() {
            return Ok(PyArray2::zeros(py, [0, D], false).unbind());
        }
        Ok(PyArray2::from_vec2(py, &rows)
            .map_err(|e| errors::input(e.to_string()))?
            .unbind())
    };
    let facets = if facets.is_empty() {
        PyArray2::zeros(py, [0, D], false).unbind()
    } else {
        PyArray2::from_vec2(py, &facets)
            .map_err(|e| errors::input(e.to_string()))?
            .unbind()
    };
    let work = results
        .iter()
        .map(|r| r.stats)
        .max_by_key(|s| s.points_processed);
    Ok(Distances {
        signed_distance: PyArray1::from_vec(
            py,
            results.iter().map(|r| r.signed_distance).collect(),
        )
        .unbind(),
        facets,
        nearest_points: table(results.iter().map(|r| r.nearest_point.to_vec()).collect())?,
        points_processed: work.map_or(0, |s| s.points_processed),
        facets_created: work.map_or(0, |s| s.facets_created),
    })
}

/// distances_to_boundary(points, queries): the signed distance from each row of `queries`
/// ((m, d)) to the boundary of the hull of `points`, from one partial hull shared by the queries
/// (each exact, as a query answered alone); the GIL released.
#[pyfunction]
pub fn distances_to_boundary(
    py: Python<'_>,
    points: PyReadonlyArray2<'_, f64>,
    queries: PyReadonlyArray2<'_, f64>,
) -> PyResult<Distances> {
    let dimension = points.shape()[1];
    with_dimension!(dimension, distances(py, &points, &queries))
}
