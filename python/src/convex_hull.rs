//! `ConvexHull`: scipy.spatial.ConvexHull's interface — its attributes, `incremental` with
//! `add_points` and `close`, and `qhull_options` — over the exact hull.
//!
//! Facets are listed by their vertex indices taken largest first, compared lexicographically:
//! the order in which inserting the points one at a time, in input order, creates them — what
//! Qhull's incremental `add_points` does. So after `add_points` the facets that survive keep
//! their order and the new ones (each has a new point as a vertex) follow, as in scipy, and the
//! order does not depend on how the engine got there (at once, grown, or rebuilt). Each row of
//! `simplices` lists its vertices largest first as far as the facet's orientation allows (the
//! last two swapped when needed), `neighbors` following. Indices are `np.intc`, as scipy's.

use crate::errors;
use crate::hull::{float_array, with_dimension};
use crate::qhull_options::{self, Options};
use numpy::ndarray::{Array2, ArrayView2, Axis, concatenate};
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods,
    ToPyArray,
};
use pqhull::predicates::Sign;
use pqhull::{FacetId, Hull, HullError};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use rayon::prelude::*;

/// A built hull, kept while an incremental `ConvexHull` is open.
enum Engine {
    D2(Box<Hull<2>>),
    D3(Box<Hull<3>>),
    D4(Box<Hull<4>>),
    D5(Box<Hull<5>>),
    D6(Box<Hull<6>>),
    D7(Box<Hull<7>>),
    D8(Box<Hull<8>>),
}

/// `impl From<Hull<D>> for Engine` for each dimension.
macro_rules! engine_from {
    ($($variant:ident: $d:literal),*) => {
        $(impl From<Hull<$d>> for Engine {
            fn from(hull: Hull<$d>) -> Self {
                Engine::$variant(Box::new(hull))
            }
        })*
    };
}
engine_from!(D2: 2, D3: 3, D4: 4, D5: 5, D6: 6, D7: 7, D8: 8);

/// Evaluates `$body` with `$hull` bound to the engine's `&mut Box<Hull<D>>`.
macro_rules! with_engine {
    ($engine:expr, $hull:ident => $body:expr) => {
        match $engine {
            Engine::D2($hull) => $body,
            Engine::D3($hull) => $body,
            Engine::D4($hull) => $body,
            Engine::D5($hull) => $body,
            Engine::D6($hull) => $body,
            Engine::D7($hull) => $body,
            Engine::D8($hull) => $body,
        }
    };
}

/// What a build needs besides the points.
struct Setup {
    options: Options,
    /// The coordinates of the good point (`QGn`), which the hull leaves out.
    good_point: Option<Vec<f64>>,
}

impl Setup {
    /// The index in `points` of the hull's point `i` (the good point is not in the hull).
    fn external(&self, i: usize) -> usize {
        match self.options.good {
            Some(good) if i >= good.point => i + 1,
            _ => i,
        }
    }
}

/// What a hull leaves for Python, flat, indices already in `points`' numbering.
struct Snapshot {
    vertices: Vec<i32>,
    /// Facet vertices, `d` per facet.
    simplices: Vec<i32>,
    /// Facet neighbours (positions), `d` per facet: `j` is opposite vertex `j`.
    neighbors: Vec<i32>,
    /// `normal · x + offset ≤ 0` inside: `d + 1` per facet.
    equations: Vec<f64>,
    /// `[point, facet, nearest vertex]` rows, 3 per row.
    coplanar: Vec<i32>,
    good: Option<Vec<bool>>,
    volume: f64,
    area: f64,
    points_processed: usize,
    facets_created: usize,
}

/// `i` as a numpy `intc` (the count was checked against `i32::MAX` on the way in).
fn intc(i: usize) -> i32 {
    i32::try_from(i).unwrap_or(i32::MAX)
}

/// Reads `hull` out: facets in order (see the module), vertices, `coplanar` and `good` as asked.
fn snapshot<const D: usize>(hull: &Hull<D>, setup: &Setup) -> Snapshot {
    // Facets by their vertex indices, largest first, compared lexicographically.
    let mut order: Vec<([usize; D], FacetId)> = hull
        .facets()
        .map(|(id, f)| {
            let mut key = f.vertices();
            key.sort_unstable_by(|a, b| b.cmp(a));
            (key, id)
        })
        .collect();
    order.sort_unstable();
    let ids: Vec<FacetId> = order.into_iter().map(|(_, id)| id).collect();
    // Each facet's vertices (and neighbours with them) in that order too, as far as the
    // orientation allows: sorted largest first, the last two swapped when that permutation is
    // odd. So the arrays do not depend on how the engine got to the hull.
    let permutation = |vertices: [usize; D]| -> [usize; D] {
        let mut at: [usize; D] = std::array::from_fn(|j| j);
        at.sort_unstable_by(|&a, &b| vertices[b].cmp(&vertices[a]));
        let mut seen = [false; D];
        let mut odd = false;
        for start in 0..D {
            let mut j = start;
            let mut length = 0;
            while !seen[j] {
                seen[j] = true;
                j = at[j];
                length += 1;
            }
            odd ^= length > 0 && length % 2 == 0;
        }
        if odd {
            at.swap(D - 2, D - 1);
        }
        at
    };
    let slots = ids.iter().map(|id| id.index() + 1).max().unwrap_or(0);
    let mut position = vec![usize::MAX; slots];
    for (at, id) in ids.iter().enumerate() {
        position[id.index()] = at;
    }
    let external = |i: usize| intc(setup.external(i));
    let (mut simplices, mut neighbors, mut equations) = (Vec::new(), Vec::new(), Vec::new());
    for &id in &ids {
        let facet = hull.facet(id);
        let (vertices, next) = (facet.vertices(), facet.neighbors());
        for j in permutation(vertices) {
            simplices.push(external(vertices[j]));
            neighbors.push(intc(position[next[j].index()]));
        }
        equations.extend(facet.normal());
        equations.push(-facet.offset());
    }
    let vertices = if D == 2 {
        // scipy lists a polygon's vertices counter-clockwise; start at the first facet's last.
        let start = ids
            .first()
            .and_then(|&id| hull.facet(id).vertices().into_iter().max());
        let mut order = counter_clockwise(hull);
        if let Some(at) = start.and_then(|v| order.iter().position(|&u| u == v)) {
            order.rotate_left(at);
        }
        order
    } else {
        hull.vertex_indices()
    };
    let good = match (&setup.good_point, setup.options.good) {
        (Some(p), Some(good)) if setup.options.report_good => {
            let x: [f64; D] = std::array::from_fn(|j| p[j]);
            // Visible: strictly beyond the facet's plane, exactly (on it is not visible).
            Some(
                ids.iter()
                    .map(|&id| (hull.side_of(id, &x) == Sign::Positive) == good.visible)
                    .collect(),
            )
        }
        _ => None,
    };
    let stats = hull.stats();
    Snapshot {
        vertices: vertices.into_iter().map(external).collect(),
        simplices,
        neighbors,
        equations,
        coplanar: coplanar(hull, &ids, setup),
        good,
        volume: hull.volume(),
        area: hull.area(),
        points_processed: stats.points_processed,
        facets_created: stats.facets_created,
    }
}

/// The `coplanar` rows `[point, facet position, nearest vertex]` (points' numbering), by facet
/// then point: with `Qc` every input point exactly on the boundary that is not a vertex (exact
/// test), on the facet through it that contains it; with `Qi` every point strictly inside, on
/// the facet whose plane is nearest. The nearest vertex is the facet's vertex nearest the point.
fn coplanar<const D: usize>(hull: &Hull<D>, ids: &[FacetId], setup: &Setup) -> Vec<i32> {
    let (on_boundary, inside) = (setup.options.coplanar, setup.options.interior);
    if !on_boundary && !inside {
        return Vec::new();
    }
    let mut is_vertex = vec![false; hull.point_count()];
    // Per facet: how far the floating-point distance of a point on its plane can be from zero
    // (the normal and offset are certified to a relative 1e-11; 1e-8 of the magnitudes is a
    // wide margin), when the normal is certified at all.
    let mut slack = Vec::with_capacity(ids.len());
    for &id in ids {
        let facet = hull.facet(id);
        let mut largest: f64 = 0.0;
        for v in facet.vertices() {
            is_vertex[v] = true;
            largest = largest.max(hull.point(v).iter().map(|c| c.abs()).sum());
        }
        slack.push(
            facet
                .normal_is_precise()
                .then_some(largest + facet.offset().abs()),
        );
    }
    let mut rows: Vec<[usize; 3]> = (0..hull.point_count())
        .into_par_iter()
        .filter(|&i| !is_vertex[i])
        .filter_map(|i| {
            let x = hull.point(i);
            let size: f64 = x.iter().map(|c| c.abs()).sum();
            // The nearest plane (floating point), and the facet through x that best contains it.
            let mut nearest = (f64::NEG_INFINITY, 0);
            let mut through: Option<(f64, usize)> = None;
            for (at, &id) in ids.iter().enumerate() {
                let facet = hull.facet(id);
                let distance = facet.signed_distance(&x);
                if distance > nearest.0 {
                    nearest = (distance, at);
                }
                let possible = slack[at].is_none_or(|s| distance >= -1e-8 * (size + s));
                if possible && hull.side_of(id, &x) == Sign::Zero {
                    let fit = min_barycentric(hull, facet.vertices(), &x);
                    if through.is_none_or(|(best, _)| fit > best) {
                        through = Some((fit, at));
                    }
                }
            }
            let at = match through {
                Some((_, at)) if on_boundary => at,
                None if inside => nearest.1,
                _ => return None,
            };
            let vertex = hull
                .facet(ids[at])
                .vertices()
                .into_iter()
                .min_by(|&a, &b| {
                    squared_distance(&hull.point(a), &x)
                        .total_cmp(&squared_distance(&hull.point(b), &x))
                })?;
            Some([setup.external(i), at, setup.external(vertex)])
        })
        .collect();
    rows.sort_unstable_by_key(|&[point, at, _]| (at, point));
    rows.into_iter().flatten().map(intc).collect()
}

fn squared_distance<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum()
}

/// The smallest barycentric coordinate of `x` (on the facet's plane) in the facet's simplex,
/// in floating point: non-negative when the simplex contains it. `-∞` if the system is singular.
fn min_barycentric<const D: usize>(hull: &Hull<D>, vertices: [usize; D], x: &[f64; D]) -> f64 {
    let m = D - 1;
    let origin = hull.point(vertices[0]);
    let edges: Vec<[f64; D]> = vertices[1..]
        .iter()
        .map(|&v| {
            let p = hull.point(v);
            std::array::from_fn(|a| p[a] - origin[a])
        })
        .collect();
    let r: [f64; D] = std::array::from_fn(|a| x[a] - origin[a]);
    let dot = |a: &[f64; D], b: &[f64; D]| -> f64 { a.iter().zip(b).map(|(p, q)| p * q).sum() };
    // The Gram system (m ≤ 7 unknowns), augmented, solved with partial pivoting.
    let mut g = [[0.0f64; 9]; 8];
    for j in 0..m {
        for k in 0..m {
            g[j][k] = dot(&edges[j], &edges[k]);
        }
        g[j][m] = dot(&edges[j], &r);
    }
    for col in 0..m {
        let Some(pivot) = (col..m).max_by(|&a, &b| g[a][col].abs().total_cmp(&g[b][col].abs()))
        else {
            return f64::NEG_INFINITY;
        };
        if g[pivot][col] == 0.0 || !g[pivot][col].is_finite() {
            return f64::NEG_INFINITY;
        }
        g.swap(col, pivot);
        let (upper, lower) = g.split_at_mut(col + 1);
        let top = &upper[col];
        for row in &mut lower[..m - col - 1] {
            let factor = row[col] / top[col];
            for (x, &y) in row[col..=m].iter_mut().zip(&top[col..=m]) {
                *x -= factor * y;
            }
        }
    }
    let mut lambda = [0.0f64; 8];
    for row in (0..m).rev() {
        let tail: f64 = (row + 1..m).map(|k| g[row][k] * lambda[k]).sum();
        lambda[row] = (g[row][m] - tail) / g[row][row];
    }
    let first = 1.0 - lambda[..m].iter().sum::<f64>();
    lambda[..m].iter().copied().fold(first, f64::min)
}

/// A polygon's vertices (the hull's numbering), counter-clockwise: each edge's outward normal
/// is its direction turned clockwise, so following edges from their first to their second
/// vertex goes either way; the orientation is fixed by the sign of the area.
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

/// The hull of `points` (the good point left out), built without the GIL, and its snapshot.
fn build<const D: usize>(
    py: Python<'_>,
    points: ArrayView2<'_, f64>,
    setup: &Setup,
) -> PyResult<(Engine, Snapshot)>
where
    Engine: From<Hull<D>>,
{
    let left_out = setup.options.good.map(|g| g.point);
    let input: Vec<[f64; D]> = points
        .rows()
        .into_iter()
        .enumerate()
        .filter(|&(i, _)| Some(i) != left_out)
        .map(|(_, r)| std::array::from_fn(|j| r[j]))
        .collect();
    let built = py.detach(|| {
        Hull::<D>::try_new(&input).map(|hull| {
            let snapshot = snapshot(&hull, setup);
            (hull, snapshot)
        })
    });
    match built {
        Ok((hull, snapshot)) => Ok((Engine::from(hull), snapshot)),
        Err(e) => Err(match left_out {
            Some(n) => {
                errors::HullError::new_err(format!("{e} (without point {n}, left out by QG{n})"))
            }
            None => errors::hull(e),
        }),
    }
}

/// Grows `hull` by `points` (exact; without the GIL) and snapshots it.
fn grow<const D: usize>(
    py: Python<'_>,
    hull: &mut Hull<D>,
    points: ArrayView2<'_, f64>,
    setup: &Setup,
) -> PyResult<Snapshot> {
    let input: Vec<[f64; D]> = points
        .rows()
        .into_iter()
        .map(|r| std::array::from_fn(|j| r[j]))
        .collect();
    py.detach(|| hull.add_points(&input).map(|_| snapshot(hull, setup)))
        .map_err(errors::hull)
}

/// A `HullError` for the first NaN or infinite coordinate of `points` (row `first` onwards).
fn check_finite(points: ArrayView2<'_, f64>, first: usize) -> PyResult<()> {
    for (i, row) in points.rows().into_iter().enumerate() {
        if let Some(coordinate) = row.iter().position(|x| !x.is_finite()) {
            return Err(errors::hull(HullError::NonFinite {
                index: first + i,
                coordinate,
            }));
        }
    }
    Ok(())
}

/// The attributes, as numpy arrays made once per build (each access returns the same array,
/// as scipy's attributes do).
struct Output {
    vertices: Py<PyArray1<i32>>,
    simplices: Py<PyArray2<i32>>,
    neighbors: Py<PyArray2<i32>>,
    equations: Py<PyArray2<f64>>,
    coplanar: Py<PyArray2<i32>>,
    good: Option<Py<PyArray1<bool>>>,
    min_bound: Py<PyArray1<f64>>,
    max_bound: Py<PyArray1<f64>>,
    volume: f64,
    area: f64,
    nsimplex: usize,
    points_processed: usize,
    facets_created: usize,
}

/// A flat vector as a `(len / width, width)` numpy array.
fn table<T: numpy::Element>(
    py: Python<'_>,
    flat: Vec<T>,
    width: usize,
) -> PyResult<Py<PyArray2<T>>> {
    let rows = flat.len() / width;
    let array =
        Array2::from_shape_vec((rows, width), flat).map_err(|e| errors::input(e.to_string()))?;
    Ok(array.into_pyarray(py).unbind())
}

impl Output {
    fn new(
        py: Python<'_>,
        snapshot: Snapshot,
        points: ArrayView2<'_, f64>,
        d: usize,
    ) -> PyResult<Self> {
        let nsimplex = snapshot.simplices.len() / d;
        Ok(Output {
            vertices: snapshot.vertices.into_pyarray(py).unbind(),
            simplices: table(py, snapshot.simplices, d)?,
            neighbors: table(py, snapshot.neighbors, d)?,
            equations: table(py, snapshot.equations, d + 1)?,
            coplanar: table(py, snapshot.coplanar, 3)?,
            good: snapshot.good.map(|g| g.into_pyarray(py).unbind()),
            min_bound: points
                .fold_axis(Axis(0), f64::INFINITY, |a, &b| a.min(b))
                .into_pyarray(py)
                .unbind(),
            max_bound: points
                .fold_axis(Axis(0), f64::NEG_INFINITY, |a, &b| a.max(b))
                .into_pyarray(py)
                .unbind(),
            volume: snapshot.volume,
            area: snapshot.area,
            nsimplex,
            points_processed: snapshot.points_processed,
            facets_created: snapshot.facets_created,
        })
    }
}

/// ConvexHull(points, incremental=False, qhull_options=None)
///
/// The exact convex hull of an (n, d) array of points, 2 <= d <= 8, as a drop-in for
/// scipy.spatial.ConvexHull: the same attributes (`points`, `vertices`, `simplices`,
/// `neighbors`, `equations`, `coplanar`, `good`, `area`, `volume`, `ndim`, `npoints`,
/// `nsimplex`, `min_bound`, `max_bound`), indices as np.intc, vertices counter-clockwise in
/// 2-D and increasing otherwise, facets ordered by their vertex indices taken largest first
/// (after `add_points` the new facets follow the ones that survive, as in scipy).
///
/// With incremental=True, `add_points(points, restart=False)` grows the hull exactly (restart
/// rebuilds from all the points: the same hull), and `close()` ends that (add_points then
/// raises RuntimeError, as scipy's).
///
/// qhull_options: Qhull's options are accepted where they only tune how Qhull copes with
/// rounding (Qt, Qbb, Qx, Qs, QJ, Q0-Q12, Q14, Pp, En, C-n, ...: no effect, the hull is
/// exact); Qc and Qi fill `coplanar`, QGn / QG-n fill `good`; anything else raises
/// pqhull.InputError naming the option. See help(pqhull) for every difference from scipy.
#[pyclass(module = "pqhull", subclass)]
pub struct ConvexHull {
    /// The hull itself, while incremental and not closed.
    engine: Option<Engine>,
    setup: Setup,
    /// `qhull_options` as given (for pickling).
    options_text: Option<String>,
    ndim: usize,
    /// Every input point, the good point included, (npoints, ndim).
    points: Py<PyArray2<f64>>,
    out: Output,
}

/// What `__reduce__` gives pickle: the class and `(points, incremental, qhull_options)`.
type Reduced<'py> = (
    Bound<'py, pyo3::types::PyType>,
    (Bound<'py, PyArray2<f64>>, bool, Option<String>),
);

/// The text of a `qhull_options` argument: a str, or bytes (Latin-1).
fn option_text(value: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(text) = value.extract::<String>() {
        return Ok(text);
    }
    value
        .extract::<Vec<u8>>()
        .map(|bytes| bytes.into_iter().map(char::from).collect())
        .map_err(|_| errors::input("qhull_options must be a string"))
}

#[pymethods]
impl ConvexHull {
    #[new]
    #[pyo3(
        signature = (points, incremental = None, qhull_options = None),
        text_signature = "(points, incremental=False, qhull_options=None)"
    )]
    fn new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        incremental: Option<&Bound<'_, PyAny>>,
        qhull_options: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        // Any truthy value, as in scipy.
        let incremental = incremental.map_or(Ok(false), |v| v.is_truthy())?;
        // A masked array exists only once numpy.ma is imported (which takes a while).
        let masked = match py.import("sys")?.getattr("modules")?.get_item("numpy.ma") {
            Ok(ma) => ma.call_method1("isMaskedArray", (points,))?.is_truthy()?,
            Err(_) => false,
        };
        if masked {
            return Err(errors::input("Input points cannot be a masked array"));
        }
        let array = float_array(points, "points")?;
        let array: PyReadonlyArray2<'_, f64> = array
            .extract()
            .map_err(|_| errors::input("points must be a 2-dimensional array (n, d)"))?;
        let view = array.as_array();
        let (n, d) = view.dim();
        let options_text = qhull_options.map(option_text).transpose()?;
        let options =
            qhull_options::parse(options_text.as_deref().unwrap_or("")).map_err(errors::input)?;
        if incremental && !options.not_incremental.is_empty() {
            return Err(errors::input(format!(
                "Qhull options {:?} are incompatible with incremental mode",
                options.not_incremental
            )));
        }
        if n > i32::MAX as usize {
            return Err(errors::input(format!(
                "{n} points: indices are np.intc, at most {} points",
                i32::MAX
            )));
        }
        check_finite(view, 0)?;
        let good_point = match options.good {
            Some(good) if good.point >= n => {
                return Err(errors::input(format!(
                    "qhull_options: QG{}: there is no point {} among {n}",
                    good.point, good.point
                )));
            }
            Some(good) => Some(view.row(good.point).to_vec()),
            None => None,
        };
        let setup = Setup {
            options,
            good_point,
        };
        let (engine, snapshot) = with_dimension!(d, build(py, view, &setup))?;
        Ok(ConvexHull {
            engine: incremental.then_some(engine),
            out: Output::new(py, snapshot, view, d)?,
            setup,
            options_text,
            ndim: d,
            points: view.to_pyarray(py).unbind(),
        })
    }

    /// add_points(points, restart=False): adds an (m, ndim) array of points (incremental hulls
    /// only) and grows the hull to the exact hull of all the points; their indices follow the
    /// old ones. restart=True rebuilds from all the points instead (the same hull).
    #[pyo3(
        signature = (points, restart = None),
        text_signature = "($self, points, restart=False)"
    )]
    fn add_points(
        &mut self,
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        restart: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<()> {
        let restart = restart.map_or(Ok(false), |v| v.is_truthy())?;
        if self.engine.is_none() {
            return Err(PyRuntimeError::new_err(
                "incremental mode not enabled or already closed",
            ));
        }
        let array = float_array(points, "points")?;
        let array: PyReadonlyArray2<'_, f64> = array
            .extract()
            .map_err(|_| errors::input("invalid size for new points array"))?;
        let new = array.as_array();
        if new.ncols() != self.ndim {
            return Err(errors::input("invalid size for new points array"));
        }
        if new.nrows() == 0 {
            return Ok(());
        }
        let all = {
            let old = self.points.bind(py).readonly();
            let old = old.as_array();
            if old.nrows() + new.nrows() > i32::MAX as usize {
                return Err(errors::input(format!(
                    "indices are np.intc: at most {} points",
                    i32::MAX
                )));
            }
            check_finite(new, old.nrows())?;
            concatenate(Axis(0), &[old, new]).map_err(|e| errors::input(e.to_string()))?
        };
        let snapshot = if restart {
            let (engine, snapshot) =
                with_dimension!(self.ndim, build(py, all.view(), &self.setup))?;
            self.engine = Some(engine);
            snapshot
        } else {
            let setup = &self.setup;
            match self.engine.as_mut() {
                Some(engine) => with_engine!(engine, hull => grow(py, &mut **hull, new, setup))?,
                None => unreachable!("checked above"),
            }
        };
        self.out = Output::new(py, snapshot, all.view(), self.ndim)?;
        self.points = all.into_pyarray(py).unbind();
        Ok(())
    }

    /// close(): ends incremental processing and frees the hull; the attributes stay, and
    /// add_points raises RuntimeError from then on.
    fn close(&mut self) {
        self.engine = None;
    }

    /// The input points, (npoints, ndim), added points included.
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.points.bind(py).clone()
    }

    /// Indices of the hull's vertices: counter-clockwise in 2-D, increasing otherwise.
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i32>> {
        self.out.vertices.bind(py).clone()
    }

    /// The facets' vertex indices, (nsimplex, ndim).
    #[getter]
    fn simplices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i32>> {
        self.out.simplices.bind(py).clone()
    }

    /// `neighbors[i, j]`: the facet opposite vertex `j` of facet `i`, (nsimplex, ndim).
    #[getter]
    fn neighbors<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i32>> {
        self.out.neighbors.bind(py).clone()
    }

    /// `[normal, offset]` per facet, with `normal · x + offset ≤ 0` inside, (nsimplex, ndim + 1).
    #[getter]
    fn equations<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.out.equations.bind(py).clone()
    }

    /// `[point, facet, nearest vertex]` rows (k, 3): with Qc the input points on the boundary
    /// that are not vertices, with Qi those strictly inside; empty otherwise.
    #[getter]
    fn coplanar<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i32>> {
        self.out.coplanar.bind(py).clone()
    }

    /// With QGn (QG-n): per facet, whether point n sees it (does not), exactly; else None.
    #[getter]
    fn good<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<bool>>> {
        self.out.good.as_ref().map(|g| g.bind(py).clone())
    }

    /// The hull's d-dimensional volume (the area in 2-D).
    #[getter]
    fn volume(&self) -> f64 {
        self.out.volume
    }

    /// The measure of the hull's boundary (the perimeter in 2-D).
    #[getter]
    fn area(&self) -> f64 {
        self.out.area
    }

    /// The dimension d.
    #[getter]
    fn ndim(&self) -> usize {
        self.ndim
    }

    /// The number of input points.
    #[getter]
    fn npoints(&self, py: Python<'_>) -> usize {
        self.points.bind(py).shape()[0]
    }

    /// The number of facets.
    #[getter]
    fn nsimplex(&self) -> usize {
        self.out.nsimplex
    }

    /// The smallest coordinates of the input points, (ndim,).
    #[getter]
    fn min_bound<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.out.min_bound.bind(py).clone()
    }

    /// The largest coordinates of the input points, (ndim,).
    #[getter]
    fn max_bound<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.out.max_bound.bind(py).clone()
    }

    /// Points added to the hull (the engine's work counter, over every add_points).
    #[getter]
    fn points_processed(&self) -> usize {
        self.out.points_processed
    }

    /// Facets created while building it (over every add_points).
    #[getter]
    fn facets_created(&self) -> usize {
        self.out.facets_created
    }

    /// Pickles as the arguments that rebuild it: all the points, whether it is still
    /// incremental, and the options (the same hull, exactly, in the same order).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> Reduced<'py> {
        let this = slf.borrow();
        (
            slf.get_type(),
            (
                this.points.bind(slf.py()).clone(),
                this.engine.is_some(),
                this.options_text.clone(),
            ),
        )
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "ConvexHull(dimension={}, points={}, vertices={}, facets={}, volume={:e})",
            self.ndim,
            self.npoints(py),
            self.out.vertices.bind(py).len(),
            self.out.nsimplex,
            self.out.volume
        )
    }
}
