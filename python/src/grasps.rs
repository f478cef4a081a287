//! Grasps as arrays: `q1`, `qinf`, `ows` on one grasp, and `evaluate` on a batch (GIL
//! released); `gradient=True` (Q1, Q∞, Q_OWS) adds the exact gradient (crate::gradient).

use crate::errors;
use crate::gradient::{self, Columns};
use crate::ows::ObjectWrenchSpace;
use numpy::ndarray::{ArrayView1, ArrayView2};
use numpy::{
    PyArray1, PyArray2, PyArray3, PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArray3,
    PyUntypedArrayMethods, ToPyArray,
};
use pqhull::grasp::ows::ObjectWrenchSpace as Space;
use pqhull::grasp::quality::NameError;
use pqhull::grasp::{
    Contact, Evaluation, Evaluator, FrictionModel, Gradient, Grasp, Method, Metric, QualityError,
    evaluate_batch,
};
use pyo3::prelude::*;

/// One grasp's quality.
#[pyclass(module = "pqhull", frozen, get_all)]
pub struct Quality {
    /// The metric on the caller's wrenches: positive inside (force closure), negative outside;
    /// for Q_OWS, None when the grasp is not force closure (it has no value then).
    value: Option<f64>,
    /// Whether the grasp is force closure (decided on the certified value).
    force_closure: bool,
    /// Points added to the (partial) hull.
    points_processed: usize,
    /// Facets created.
    facets_created: usize,
    /// Time spent in the library (µs), to tell Python's per-call overhead from the work.
    elapsed_us: f64,
    /// `gradient=True` (q1, qinf, ows): ∂value/∂p_i, an (m, 3) array in input order; None
    /// otherwise, and for Q_OWS without a value.
    gradient_positions: Option<Py<PyArray2<f64>>>,
    /// `gradient=True`: ∂value/∂n_i with respect to the unit normal (each row orthogonal to it;
    /// for a normal given with length L, divide by L), (m, 3); None as `gradient_positions`.
    gradient_normals: Option<Py<PyArray2<f64>>>,
    /// `gradient=True`: ∂value/∂μ; None as `gradient_positions`.
    gradient_friction: Option<f64>,
    /// `gradient=True`: whether the value is differentiable at the grasp (False: the numbers
    /// are the derivative along the deciding face found); None as `gradient_positions`.
    differentiable: Option<bool>,
}

#[pymethods]
impl Quality {
    fn __repr__(&self) -> String {
        let bool_name = |b: bool| if b { "True" } else { "False" };
        // With gradient=True, the derivative's summary too (the arrays are attributes).
        let gradient = match (self.gradient_friction, self.differentiable) {
            (Some(f), Some(d)) => {
                format!(", gradient_friction={f:e}, differentiable={}", bool_name(d))
            }
            _ => String::new(),
        };
        format!(
            "Quality(value={}, force_closure={}, points_processed={}, facets_created={}{gradient})",
            self.value.map_or("None".to_string(), |v| format!("{v:e}")),
            bool_name(self.force_closure),
            self.points_processed,
            self.facets_created
        )
    }
}

/// A batch's results: `quality` and `force_closure` per row (NaN and False for a bad row), and
/// `errors`, `(row, message)` for every bad row.
#[pyclass(module = "pqhull", frozen, get_all)]
pub struct Batch {
    quality: Py<PyArray1<f64>>,
    force_closure: Py<PyArray1<bool>>,
    errors: Vec<(usize, String)>,
    /// Wall time of the library's batch evaluation alone (s): the rest of the call is Python's.
    evaluation_s: f64,
    /// `gradient=True` (q1, qinf, ows): ∂value/∂p, (N, m, 3), NaN for a row without a value (a
    /// bad row; Q_OWS not in force closure); None otherwise.
    gradient_positions: Option<Py<PyArray3<f64>>>,
    /// `gradient=True`: ∂value/∂n with respect to the unit normals, (N, m, 3), NaN as above.
    gradient_normals: Option<Py<PyArray3<f64>>>,
    /// `gradient=True`: ∂value/∂μ, (N,), NaN as above.
    gradient_friction: Option<Py<PyArray1<f64>>>,
    /// `gradient=True`: whether the value is differentiable at each grasp, (N,), False for a
    /// row without a value.
    differentiable: Option<Py<PyArray1<bool>>>,
}

/// The torque frame and friction shared by every grasp of a call.
pub(crate) struct Frame {
    torque_reference: Option<[f64; 3]>,
    torque_scale: Option<f64>,
    cone_edges: usize,
}

/// One grasp from its contacts' (m, 3) positions, normals and optional tangents.
fn grasp(
    positions: ArrayView2<'_, f64>,
    normals: ArrayView2<'_, f64>,
    tangents: Option<ArrayView2<'_, f64>>,
    torsion: Option<ArrayView1<'_, f64>>,
    friction: f64,
    frame: &Frame,
) -> Result<Grasp, String> {
    let row = |a: &ArrayView2<'_, f64>, i: usize| -> [f64; 3] { [a[[i, 0]], a[[i, 1]], a[[i, 2]]] };
    let model = FrictionModel::try_new(friction, frame.cone_edges).map_err(|e| e.to_string())?;
    let contacts = (0..positions.nrows())
        .map(|i| {
            let tangent = tangents.as_ref().map(|t| row(t, i));
            let contact = Contact::try_new(row(&positions, i), row(&normals, i), tangent)
                .map_err(|e| format!("contact {i}: {e}"))?;
            match &torsion {
                Some(t) => contact
                    .with_torsion(t[i])
                    .map_err(|e| format!("contact {i}: {e}")),
                None => Ok(contact),
            }
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut builder = Grasp::builder(contacts, model);
    if let Some(c) = frame.torque_reference {
        builder = builder.torque_reference(c);
    }
    if let Some(rho) = frame.torque_scale {
        builder = builder.torque_scale(rho);
    }
    builder.build().map_err(|e| e.to_string())
}

/// `(m, 3)`, or an input error naming `what`.
fn check_contacts(what: &str, shape: &[usize], m: Option<usize>) -> PyResult<()> {
    let ok = shape.len() == 2 && shape[1] == 3 && m.is_none_or(|m| shape[0] == m);
    if !ok {
        return Err(errors::input(format!(
            "{what} must have shape (m, 3){}, not {shape:?}",
            m.map_or(String::new(), |m| format!(" with m = {m}"))
        )));
    }
    Ok(())
}

/// The batch's metric from its name (the library's vocabulary, [`Metric`]'s `FromStr`),
/// `with_zero_wrench` (Q∞) and the wrench `resist` takes.
pub(crate) fn metric_of(
    name: &str,
    with_zero_wrench: bool,
    wrench: Option<&[f64]>,
) -> PyResult<Metric> {
    if wrench.is_some() && name != "resist" {
        return Err(errors::input("wrench= is for metric \"resist\""));
    }
    if name == "resist" {
        let w = wrench.ok_or_else(|| errors::input("metric \"resist\" needs wrench="))?;
        let wrench = w
            .try_into()
            .map_err(|_| errors::input(format!("wrench must have 6 numbers, not {}", w.len())))?;
        return Ok(Metric::Resist { wrench });
    }
    match name.parse::<Metric>() {
        Ok(Metric::QInf { .. }) if name == "qinf" => Ok(Metric::QInf { with_zero_wrench }),
        Ok(metric) => Ok(metric),
        Err(e) => Err(errors::input(e.to_string())),
    }
}

/// A method by its name ([`Method`]'s `FromStr`).
pub(crate) fn method_named(name: &str) -> PyResult<Method> {
    name.parse()
        .map_err(|e: NameError| errors::input(e.to_string()))
}

/// A method by its name ([`Method`]'s `FromStr`), checked against `metric`.
pub(crate) fn method_of(name: &str, metric: Metric) -> PyResult<Method> {
    let method = method_named(name)?;
    if !method.supports(metric) {
        return Err(errors::quality(QualityError::UnsupportedMethod {
            method,
            metric,
        }));
    }
    Ok(method)
}

/// `grasp` in `space`'s torque frame; an error when the caller gave a frame of their own.
fn in_frame(space: &Space, grasp: Grasp, frame: &Frame) -> Result<Grasp, String> {
    if space.torque_frame().is_some()
        && (frame.torque_reference.is_some() || frame.torque_scale.is_some())
    {
        return Err(
            "the grasp is evaluated in the object wrench space's torque frame: \
                    give no torque_reference or torque_scale"
                .into(),
        );
    }
    space.frame(&grasp).map_err(|e| e.to_string())
}

fn frame(
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
) -> PyResult<Frame> {
    let torque_reference = match torque_reference {
        None => None,
        Some(c) => {
            let c = c.as_slice().map_err(|e| errors::input(e.to_string()))?;
            if c.len() != 3 {
                return Err(errors::input(format!(
                    "torque_reference must have 3 coordinates, not {}",
                    c.len()
                )));
            }
            Some([c[0], c[1], c[2]])
        }
    };
    Ok(Frame {
        torque_reference,
        torque_scale,
        cone_edges,
    })
}

/// One grasp from the single-grasp functions' arguments, and its frame.
#[allow(clippy::too_many_arguments)] // the Python signature's grasp fields
pub(crate) fn one_grasp(
    positions: PyReadonlyArray2<'_, f64>,
    normals: PyReadonlyArray2<'_, f64>,
    tangents: Option<PyReadonlyArray2<'_, f64>>,
    torsion: Option<PyReadonlyArray1<'_, f64>>,
    friction: f64,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
) -> PyResult<(Grasp, Frame)> {
    check_contacts("positions", positions.shape(), None)?;
    let m = positions.shape()[0];
    check_contacts("normals", normals.shape(), Some(m))?;
    if let Some(t) = &tangents {
        check_contacts("tangents", t.shape(), Some(m))?;
    }
    if let Some(t) = &torsion
        && t.shape() != [m]
    {
        return Err(errors::input(format!(
            "torsion must have shape ({m},), one per contact, not {:?}",
            t.shape()
        )));
    }
    let frame = frame(cone_edges, torque_reference, torque_scale)?;
    let g = grasp(
        positions.as_array(),
        normals.as_array(),
        tangents.as_ref().map(|t| t.as_array()),
        torsion.as_ref().map(|t| t.as_array()),
        friction,
        &frame,
    )
    .map_err(errors::grasp)?;
    Ok((g, frame))
}

impl Quality {
    /// The Python value of an [`Evaluation`] (no value for Q_OWS or resistance when not force
    /// closure).
    pub(crate) fn of_evaluation(s: &Evaluation) -> Self {
        Quality {
            value: s.value,
            force_closure: s.force_closure,
            points_processed: s.stats.points_processed,
            facets_created: s.stats.facets_created,
            elapsed_us: s.stats.elapsed.as_secs_f64() * 1e6,
            gradient_positions: None,
            gradient_normals: None,
            gradient_friction: None,
            differentiable: None,
        }
    }

    /// An evaluation with its gradient ([`gradient::One`]; None for Q_OWS without a value).
    fn of_gradient(s: &Evaluation, g: Option<gradient::One>) -> Self {
        let quality = Quality::of_evaluation(s);
        match g {
            None => quality,
            Some(g) => Quality {
                gradient_positions: Some(g.positions),
                gradient_normals: Some(g.normals),
                gradient_friction: Some(g.friction),
                differentiable: Some(g.differentiable),
                ..quality
            },
        }
    }
}

/// One grasp by any metric ([`Evaluator`]), for the single-grasp functions; with `gradient` (Q1,
/// Q∞, Q_OWS by an exact method), the value's gradient too.
#[allow(clippy::too_many_arguments)] // the Python signature
pub(crate) fn single(
    py: Python<'_>,
    positions: PyReadonlyArray2<'_, f64>,
    normals: PyReadonlyArray2<'_, f64>,
    tangents: Option<PyReadonlyArray2<'_, f64>>,
    torsion: Option<PyReadonlyArray1<'_, f64>>,
    friction: f64,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
    metric: Metric,
    method: &str,
    space: Option<&Space>,
    gradient: bool,
) -> PyResult<Quality> {
    let method = method_of(method, metric)?;
    if gradient {
        gradient::check(metric, method, metric.name())?;
    }
    let (g, frame) = one_grasp(
        positions,
        normals,
        tangents,
        torsion,
        friction,
        cone_edges,
        torque_reference,
        torque_scale,
    )?;
    let g = match space {
        Some(space) => in_frame(space, g, &frame).map_err(errors::grasp)?,
        None => g,
    };
    if gradient {
        let (evaluation, d) = py
            .detach(|| gradient::one(&g, metric, method, space))
            .map_err(gradient::Failure::into_py)?;
        let d = d.map(|d| gradient::One::new(py, &d));
        return Ok(Quality::of_gradient(&evaluation, d));
    }
    let evaluation = py
        .detach(|| Evaluator::new(metric, method, space)?.evaluate(&g))
        .map_err(errors::quality)?;
    Ok(Quality::of_evaluation(&evaluation))
}

/// q1(positions, normals, tangents=None, *, friction, cone_edges, torque_reference=None,
/// torque_scale=None, method="partial", gradient=False): Ferrari–Canny Q1 of one grasp, exact on
/// its wrenches; with `gradient`, also its exact gradient (the `gradient_*` attributes).
#[pyfunction]
#[pyo3(signature = (positions, normals, tangents=None, *, torsion=None, friction, cone_edges,
                    torque_reference=None, torque_scale=None, method="partial", gradient=false))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn q1(
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
    gradient: bool,
) -> PyResult<Quality> {
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
        Metric::Q1,
        method,
        None,
        gradient,
    )
}

/// qinf(positions, normals, tangents=None, *, friction, cone_edges, torque_reference=None,
/// torque_scale=None, with_zero_wrench=False, method="partial", gradient=False): Q∞ of one grasp;
/// with `gradient`, also its exact gradient (the `gradient_*` attributes).
#[pyfunction]
#[pyo3(signature = (positions, normals, tangents=None, *, torsion=None, friction, cone_edges,
                    torque_reference=None, torque_scale=None, with_zero_wrench=false,
                    method="partial", gradient=false))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn qinf(
    py: Python<'_>,
    positions: PyReadonlyArray2<'_, f64>,
    normals: PyReadonlyArray2<'_, f64>,
    tangents: Option<PyReadonlyArray2<'_, f64>>,
    torsion: Option<PyReadonlyArray1<'_, f64>>,
    friction: f64,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
    with_zero_wrench: bool,
    method: &str,
    gradient: bool,
) -> PyResult<Quality> {
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
        Metric::QInf { with_zero_wrench },
        method,
        None,
        gradient,
    )
}

/// ows(positions, normals, tangents=None, *, space, friction, cone_edges, method="partial",
/// gradient=False): Q_OWS of one grasp against an ObjectWrenchSpace (None when not force
/// closure); with `gradient` (an exact method), also its exact gradient (None without a value).
#[pyfunction]
#[pyo3(signature = (positions, normals, tangents=None, *, torsion=None, space, friction, cone_edges,
                    torque_reference=None, torque_scale=None, method="partial", gradient=false))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn ows(
    py: Python<'_>,
    positions: PyReadonlyArray2<'_, f64>,
    normals: PyReadonlyArray2<'_, f64>,
    tangents: Option<PyReadonlyArray2<'_, f64>>,
    torsion: Option<PyReadonlyArray1<'_, f64>>,
    space: &ObjectWrenchSpace,
    friction: f64,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
    method: &str,
    gradient: bool,
) -> PyResult<Quality> {
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
        Metric::Ows,
        method,
        Some(&space.inner),
        gradient,
    )
}

/// evaluate(positions, normals, tangents=None, *, friction, cone_edges, torque_reference=None,
/// torque_scale=None, metric="q1", method="partial", with_zero_wrench=False, threads=None,
/// gradient=False): the metric of N grasps of m contacts ((N, m, 3) arrays; `friction` one value
/// or one per grasp) on all cores (or `threads`), the GIL released. A bad row gives NaN and an
/// error entry. `gradient` (q1, qinf, ows) adds the value's gradient per row, NaN for a row
/// without a value.
#[pyfunction]
#[pyo3(signature = (positions, normals, tangents=None, *, torsion=None, friction, cone_edges,
                    torque_reference=None, torque_scale=None, metric="q1", method="partial",
                    with_zero_wrench=false, space=None, threads=None, wrench=None,
                    gradient=false))]
#[allow(clippy::too_many_arguments)] // the Python signature
pub fn evaluate(
    py: Python<'_>,
    positions: PyReadonlyArray3<'_, f64>,
    normals: PyReadonlyArray3<'_, f64>,
    tangents: Option<PyReadonlyArray3<'_, f64>>,
    torsion: Option<PyReadonlyArray2<'_, f64>>,
    friction: PyReadonlyArray1<'_, f64>,
    cone_edges: usize,
    torque_reference: Option<PyReadonlyArray1<'_, f64>>,
    torque_scale: Option<f64>,
    metric: &str,
    method: &str,
    with_zero_wrench: bool,
    space: Option<PyRef<'_, ObjectWrenchSpace>>,
    threads: Option<usize>,
    wrench: Option<PyReadonlyArray1<'_, f64>>,
    gradient: bool,
) -> PyResult<Batch> {
    let shape = positions.shape().to_vec();
    if shape.len() != 3 || shape[2] != 3 {
        return Err(errors::input(format!(
            "positions must have shape (N, m, 3), not {shape:?}"
        )));
    }
    let n = shape[0];
    for (what, s) in [
        ("normals", normals.shape()),
        (
            "tangents",
            tangents.as_ref().map_or(&shape[..], |t| t.shape()),
        ),
    ] {
        if s != shape.as_slice() {
            return Err(errors::input(format!(
                "{what} must have the shape of positions, {shape:?}, not {s:?}"
            )));
        }
    }
    if let Some(t) = &torsion
        && t.shape() != [n, shape[1]]
    {
        return Err(errors::input(format!(
            "torsion must have shape (N, m) = ({n}, {}), one per contact, not {:?}",
            shape[1],
            t.shape()
        )));
    }
    let friction = friction
        .as_slice()
        .map_err(|e| errors::input(e.to_string()))?;
    if friction.len() != 1 && friction.len() != n {
        return Err(errors::input(format!(
            "friction must be one value or one per grasp ({n}), not {}",
            friction.len()
        )));
    }
    let wrench = match &wrench {
        Some(w) => Some(w.as_slice().map_err(|e| errors::input(e.to_string()))?),
        None => None,
    };
    let name = metric;
    let metric = metric_of(name, with_zero_wrench, wrench)?;
    let method = method_of(method, metric)?;
    if gradient {
        gradient::check(metric, method, name)?;
    }
    let space = space.as_ref().map(|s| &s.inner);
    if (metric == Metric::Ows) != space.is_some() {
        return Err(errors::input(
            "metric \"ows\" needs space= (an ObjectWrenchSpace), and only it takes one",
        ));
    }
    // An evaluator that cannot be made (a zero wrench to resist) is refused before any work.
    Evaluator::new(metric, method, space).map_err(errors::quality)?;
    let frame = frame(cone_edges, torque_reference, torque_scale)?;
    if let Some(t) = threads {
        pqhull::grasp::check_threads(t).map_err(|e| errors::input(e.to_string()))?;
    }
    let (p, nrm) = (positions.as_array(), normals.as_array());
    let t = tangents.as_ref().map(|t| t.as_array());
    let soft = torsion.as_ref().map(|t| t.as_array());
    // Build every grasp (a bad row keeps its message), then evaluate the good ones.
    let built: Vec<Result<Grasp, String>> = (0..n)
        .map(|i| {
            let mu = friction[if friction.len() == 1 { 0 } else { i }];
            grasp(
                p.index_axis(numpy::ndarray::Axis(0), i),
                nrm.index_axis(numpy::ndarray::Axis(0), i),
                t.as_ref().map(|t| t.index_axis(numpy::ndarray::Axis(0), i)),
                soft.as_ref()
                    .map(|s| s.index_axis(numpy::ndarray::Axis(0), i)),
                mu,
                &frame,
            )
            .and_then(|g| match space {
                Some(space) => in_frame(space, g, &frame),
                None => Ok(g),
            })
        })
        .collect();
    // The good grasps move into the batch; a bad row keeps only its message.
    let mut good = Vec::with_capacity(n);
    let built: Vec<Result<(), String>> =
        built.into_iter().map(|g| g.map(|g| good.push(g))).collect();
    // Each row as (value, force closure, gradient): Q_OWS has no value for a grasp not in force
    // closure; only `gradient` gives a gradient.
    type Row = (Option<f64>, bool, Option<Gradient>);
    let run = || -> Vec<Result<Row, String>> {
        if gradient {
            // The batch's values, then each one's gradient beside it.
            return gradient::batch(&good, metric, method, space);
        }
        // Refusals were checked above, before any work: a failure here is the batch's own.
        match evaluate_batch(&good, metric, method, space) {
            Ok(evaluations) => evaluations
                .into_iter()
                .map(|r| {
                    r.map(|s| (s.value, s.force_closure, None))
                        .map_err(|e| e.to_string())
                })
                .collect(),
            Err(e) => vec![Err(e.to_string()); good.len()],
        }
    };
    let started = std::time::Instant::now();
    let results = py.detach(|| -> Result<_, String> {
        pqhull::grasp::with_threads(threads, run).map_err(|e| e.to_string())
    });
    let evaluation_s = started.elapsed().as_secs_f64();
    let results = results.map_err(errors::input)?;
    let mut quality = vec![f64::NAN; n];
    let mut force_closure = vec![false; n];
    let mut errors_out = Vec::new();
    let mut gradients = gradient.then(|| Columns::new(n, shape[1]));
    let mut next = results.into_iter();
    for (i, g) in built.iter().enumerate() {
        match g {
            Err(message) => errors_out.push((i, format!("row {i}: {message}"))),
            Ok(_) => match next.next() {
                Some(Ok((value, closure, d))) => {
                    // NaN without an error entry: Q_OWS of a grasp not in force closure.
                    quality[i] = value.unwrap_or(f64::NAN);
                    force_closure[i] = closure;
                    if let (Some(columns), Some(d)) = (gradients.as_mut(), d) {
                        columns.set(i, &d);
                    }
                }
                Some(Err(e)) => errors_out.push((i, format!("row {i}: {e}"))),
                None => errors_out.push((i, format!("row {i}: not evaluated"))),
            },
        }
    }
    let (gradient_positions, gradient_normals, gradient_friction, differentiable) =
        match gradients.map(|c| c.into_arrays(py)) {
            Some((p, n, f, d)) => (Some(p), Some(n), Some(f), Some(d)),
            None => (None, None, None, None),
        };
    Ok(Batch {
        quality: quality.to_pyarray(py).unbind(),
        force_closure: force_closure.to_pyarray(py).unbind(),
        errors: errors_out,
        evaluation_s,
        gradient_positions,
        gradient_normals,
        gradient_friction,
        differentiable,
    })
}
