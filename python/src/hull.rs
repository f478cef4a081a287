//! `ConvexHull` (scipy's layout) and `distance_to_boundary` (the partial hull).

use crate::errors;
use numpy::{
    PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods, ToPyArray,
};
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

/// The rows of an (n, D) array as points.
fn rows<const D: usize>(points: &PyReadonlyArray2<'_, f64>) -> Vec<[f64; D]> {
    let view = points.as_array();
    view.rows()
        .into_iter()
        .map(|r| std::array::from_fn(|j| r[j]))
        .collect()
}

/// The convex hull of points in 2 to 8 dimensions, exact, in scipy.spatial.ConvexHull's layout.
#[pyclass(module = "pqhull", frozen)]
pub struct ConvexHull {
    points: Py<PyArray2<f64>>,
    dimension: usize,
    built: Built,
}

/// What a hull build leaves for Python, flat.
struct Built {
    vertices: Vec<usize>,
    /// Facet vertices, `dimension` per facet.
    simplices: Vec<usize>,
    /// Facet neighbours (positions), `dimension` per facet: `j` is opposite vertex `j`.
    neighbors: Vec<usize>,
    /// `normal · x + offset ≤ 0` inside: `dimension + 1` per facet.
    equations: Vec<f64>,
    volume: f64,
    points_processed: usize,
    facets_created: usize,
}

fn build<const D: usize>(py: Python<'_>, points: &PyReadonlyArray2<'_, f64>) -> PyResult<Built> {
    let input = rows::<D>(points);
    let hull = py
        .detach(|| Hull::<D>::try_new(&input))
        .map_err(errors::hull)?;
    let ids: Vec<_> = hull.facets().map(|(id, _)| id).collect();
    let mut position = vec![usize::MAX; ids.iter().map(|id| id.index() + 1).max().unwrap_or(0)];
    for (at, id) in ids.iter().enumerate() {
        position[id.index()] = at;
    }
    let (mut simplices, mut neighbors, mut equations) = (Vec::new(), Vec::new(), Vec::new());
    for &id in &ids {
        let facet = hull.facet(id);
        simplices.extend(facet.vertices());
        neighbors.extend(facet.neighbors().iter().map(|n| position[n.index()]));
        equations.extend(facet.normal());
        equations.push(-facet.offset());
    }
    let mut vertices = hull.vertex_indices();
    if D == 2 {
        // scipy lists a polygon's vertices counter-clockwise: walk the edges.
        vertices = counter_clockwise(&hull);
    }
    let stats = hull.stats();
    Ok(Built {
        vertices,
        simplices,
        neighbors,
        equations,
        volume: hull.volume(),
        points_processed: stats.points_processed,
        facets_created: stats.facets_created,
    })
}

/// A polygon's vertices, counter-clockwise: each edge's outward normal is its direction turned
/// clockwise, so following edges from their first to their second vertex goes either way; the
/// orientation is fixed by the sign of the area.
fn counter_clockwise<const D: usize>(hull: &Hull<D>) -> Vec<usize> {
    let edges: Vec<[usize; D]> = hull.facets().map(|(_, f)| f.vertices()).collect();
    let Some(first) = edges.first() else {
        return Vec::new();
    };
    let next: std::collections::HashMap<usize, usize> =
        edges.iter().map(|e| (e[0], e[1])).collect();
    let mut order = vec![first[0]];
    while let Some(&v) = next.get(order.last().unwrap_or(&first[0])) {
        if v == order[0] || order.len() > edges.len() {
            break;
        }
        order.push(v);
    }
    let p = |i: usize| hull.point(i);
    let twice_area: f64 = (0..order.len())
        .map(|k| {
            let (a, b) = (p(order[k]), p(order[(k + 1) % order.len()]));
            a[0] * b[1] - a[1] * b[0]
        })
        .sum();
    if twice_area < 0.0 {
        order.reverse();
    }
    order
}

#[pymethods]
impl ConvexHull {
    /// ConvexHull(points): the exact convex hull of an (n, d) array of numbers, 2 ≤ d ≤ 8.
    #[new]
    fn new(py: Python<'_>, points: &Bound<'_, PyAny>) -> PyResult<Self> {
        let points = float_array(points, "points")?;
        let points: PyReadonlyArray2<'_, f64> = points
            .extract()
            .map_err(|_| errors::input("points must be a 2-dimensional array (n, d)"))?;
        let dimension = points.shape()[1];
        let built = with_dimension!(dimension, build(py, &points))?;
        Ok(ConvexHull {
            points: points.as_array().to_pyarray(py).unbind(),
            dimension,
            built,
        })
    }

    /// The input points, (n, d).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.points.bind(py).clone()
    }

    /// Indices of the hull's vertices: counter-clockwise in 2-D, increasing otherwise.
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<usize>> {
        self.built.vertices.to_pyarray(py)
    }

    /// The facets' vertex indices, (nfacet, d).
    #[getter]
    fn simplices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<usize>>> {
        table(py, &self.built.simplices, self.dimension)
    }

    /// `neighbors[i, j]`: the facet opposite vertex `j` of facet `i`, (nfacet, d).
    #[getter]
    fn neighbors<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<usize>>> {
        table(py, &self.built.neighbors, self.dimension)
    }

    /// `[normal, offset]` per facet, with `normal · x + offset ≤ 0` inside, (nfacet, d + 1).
    #[getter]
    fn equations<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        table(py, &self.built.equations, self.dimension + 1)
    }

    /// The hull's d-dimensional volume.
    #[getter]
    fn volume(&self) -> f64 {
        self.built.volume
    }

    /// Points added to the hull (the engine's work counter).
    #[getter]
    fn points_processed(&self) -> usize {
        self.built.points_processed
    }

    /// Facets created while building it.
    #[getter]
    fn facets_created(&self) -> usize {
        self.built.facets_created
    }

    fn __repr__(&self) -> String {
        format!(
            "ConvexHull(dimension={}, vertices={}, facets={}, volume={:e})",
            self.dimension,
            self.built.vertices.len(),
            self.built.simplices.len() / self.dimension,
            self.built.volume
        )
    }
}

/// `value` as a C-contiguous float64 numpy array (numpy.ascontiguousarray), or an input error.
pub fn float_array<'py>(value: &Bound<'py, PyAny>, name: &str) -> PyResult<Bound<'py, PyAny>> {
    let numpy = value.py().import("numpy")?;
    numpy
        .call_method1("ascontiguousarray", (value, "float64"))
        .map_err(|e| errors::input(format!("{name}: not an array of numbers ({e})")))
}

/// A flat vector as a (len / width, width) array.
fn table<'py, T: numpy::Element + Copy>(
    py: Python<'py>,
    flat: &[T],
    width: usize,
) -> PyResult<Bound<'py, PyArray2<T>>> {
    let rows: Vec<Vec<T>> = flat.chunks(width).map(<[T]>::to_vec).collect();
    if rows.is_empty() {
        return Ok(PyArray2::zeros(py, [0, width], false));
    }
    PyArray2::from_vec2(py, &rows).map_err(|e| errors::input(e.to_string()))
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
