//! The exact gradient of Q1 with respect to the grasp's own inputs: every contact's position
//! and normal, and the friction coefficient.
//!
//! # Why the deciding face gives it
//!
//! Q1 is `V = min_{|u|=1} h(u)`, `h(u) = max_w u·w` over the grasp's wrenches: the signed
//! distance from the origin to the boundary of their hull (positive inside). At the optimum
//! `u*`, the wrenches attaining `h(u*)` span the deciding face (the nearest facet inside; the
//! face holding the nearest point outside), and the point `x = Σ_j λ_j w_j` of that face
//! nearest the origin has `|x| = |V|` (`x = V·u*` inside, `x = −|V|·u*` outside). By Danskin's
//! theorem for this min–max, wherever the deciding face is unique, its weights positive and no
//! other wrench on its supporting plane,
//!
//! `dV = Σ_j λ_j u*·dw_j`,
//!
//! and each `w_j = [f; ((p − c) × f ± γn)/ρ]` with `f = n + μ(cos θ_j t + sin θ_j (n × t))` is a
//! smooth function of its contact's position `p`, unit normal `n` (the tangent `t` re-derived
//! from it as the contact does: the given tangent orthogonalised against `n`, or the default
//! `(n × e_a)/|n × e_a|`) and the friction `μ`. Where those conditions fail — a tie, a zero
//! weight, a wrench on the supporting plane outside the face, the default tangent's axis at a
//! tie, the origin on the boundary — the value is not differentiable there; the same formula
//! then gives one subgradient-like element (the derivative along the face found) and the
//! result says so.
//!
//! A tie between two *different* facets at the same distance (a grasp with a symmetry, whose
//! nearest facet and its mirror image are equally near) is seen on the hull the value came
//! from ([`Evaluation::tied`]) and flagged; the numbers are then the derivative along the face
//! found (what moving into that face's side gives), not a gradient. Q_OWS's ties through
//! another facet likewise.

use super::quality::Metric;
use super::{Contact, Evaluation, Grasp};
use crate::geometry::min_norm_point;
use crate::geometry::vector::{add, cross, dot, norm, scale, sub};
use faer::Mat;
use faer::linalg::solvers::SolveLstsq;
use std::f64::consts::PI;
use std::fmt;

/// Q1's or Q∞'s value and wrench scale from `quality`, which must be of the metric named
/// `expected` (`is_expected`).
fn hull_value(
    quality: &Evaluation,
    expected: &'static str,
    is_expected: bool,
) -> Result<(f64, f64), GradientError> {
    match (is_expected, quality.value, quality.scale) {
        (true, Some(value), Some(scale)) => Ok((value, scale)),
        _ => Err(GradientError::OtherMetric {
            expected,
            found: quality.metric,
        }),
    }
}

/// The derivative of a metric's value with respect to the grasp's inputs, contact by contact in
/// input order.
#[derive(Clone, Debug, PartialEq)]
pub struct Gradient {
    /// `∂V/∂p_i` for each contact.
    pub positions: Vec<[f64; 3]>,
    /// `∂V/∂n_i` for each contact, with respect to the unit normal (orthogonal to it: moving
    /// `n` along itself changes nothing; for a normal given with length `L`, divide by `L`).
    pub normals: Vec<[f64; 3]>,
    /// `∂V/∂μ`.
    pub friction: f64,
    /// Whether the value is differentiable at this grasp (see the module docs): when `false`,
    /// the numbers are the derivative along the deciding face that was found, one element of
    /// the generalised gradient, not the gradient.
    pub differentiable: bool,
}

/// Why [`q1_gradient`] could not differentiate.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum GradientError {
    /// A deciding wrench of the quality is none of the grasp's wrenches: the quality is not
    /// this grasp's Q1 (or was evaluated in a rescaled unit, for wrenches beyond 2^±256).
    NotThisGrasp {
        /// The deciding wrench's position in [`Evaluation::deciding_wrenches`].
        deciding: usize,
    },
    /// The quality names no deciding wrench.
    NoDecidingFace,
    /// The evaluation is of another metric than the one this function differentiates.
    OtherMetric {
        /// The metric differentiated.
        expected: &'static str,
        /// The evaluation's metric.
        found: Metric,
    },
}

impl fmt::Display for GradientError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GradientError::NotThisGrasp { deciding } => write!(
                f,
                "deciding wrench {deciding} of the quality is not a wrench of this grasp: \
                 differentiate the Q1 evaluated on it"
            ),
            GradientError::NoDecidingFace => f.write_str("the quality names no deciding wrench"),
            GradientError::OtherMetric { expected, found } => write!(
                f,
                "the evaluation is of {found}, not of {expected}: differentiate the metric it \
                 evaluated"
            ),
        }
    }
}

impl std::error::Error for GradientError {}

/// Relative tolerance of the differentiability tests (weights, other wrenches on the
/// supporting plane, the value against the band): far above the value's own accuracy (1e−12),
/// far below a generic grasp's margins.
const TIE: f64 = 1e-9;

/// A wrench within this fraction of the scale of the supporting plane is on it: the raw
/// wrenches of one friction pyramid are coplanar to rounding (about 1e−16 of the scale), and the
/// value is accurate to 1e−12 of it.
const ON_PLANE: f64 = 1e-11;

/// The gradient of `quality`, this grasp's Q1 (by any method of
/// [`Evaluator`](super::Evaluator)), with respect to every contact's position and normal and the
/// friction coefficient.
///
/// ```
/// use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric, q1_gradient};
/// let contacts = [[1.0, 0.1, 0.0], [-1.0, 0.0, 0.2], [0.1, 1.0, 0.0], [0.0, -1.0, -0.1]]
///     .map(|p| Contact::try_new(p, p.map(|x| -x), None).unwrap());
/// let grasp = Grasp::builder(contacts.to_vec(), FrictionModel::try_new(0.5, 8)?).build()?;
/// let q1 = Evaluator::new(Metric::Q1, Method::Partial, None)?.evaluate(&grasp)?;
/// let gradient = q1_gradient(&grasp, &q1)?;
/// assert_eq!(gradient.positions.len(), 4);
/// assert!(gradient.friction > 0.0); // more friction, a wider cone: a better grasp
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`GradientError::OtherMetric`] when `quality` is not of Q1; [`GradientError::NotThisGrasp`]
/// when it is not this grasp's (its deciding wrenches are not the grasp's wrenches).
pub fn q1_gradient(grasp: &Grasp, quality: &Evaluation) -> Result<Gradient, GradientError> {
    let (value, scale) = hull_value(quality, "q1", quality.metric == Metric::Q1)?;
    let wrenches = grasp.wrenches();
    let deciding = quality.deciding_wrenches();
    if deciding.is_empty() {
        return Err(GradientError::NoDecidingFace);
    }
    for (index, w) in deciding.iter().enumerate() {
        if !wrenches.contains(w) {
            return Err(GradientError::NotThisGrasp { deciding: index });
        }
    }
    // u*: from the origin toward the deciding face's nearest point inside, away from it outside.
    let (_, x) = nearest_in_affine_hull(deciding);
    let distance = norm(x);
    let sign = if value > 0.0 { 1.0 } else { -1.0 };
    let u: [f64; 6] = std::array::from_fn(|c| sign * x[c] / distance);
    if !(distance > 0.0 && distance.is_finite()) {
        // The deciding face passes through the origin: no direction, Q1 = 0 on the boundary.
        return Ok(Gradient::zero(grasp.contact_count(), false));
    }
    // A tie with another facet (`Quality::tied`): a minimum of two faces' distances.
    let mut differentiable = value != 0.0 && value.abs() > TIE * scale && !quality.tied();
    // The whole face along u*: every wrench on the supporting plane u*·w = V. The deciding
    // wrenches are one simplex of it; a friction pyramid with three wrenches on the plane lies
    // in it whole (its k edges span one 2-flat, and stay in one as the inputs move), so the
    // face is rarely a simplex. Its point nearest the origin, by Wolfe's algorithm, is `x`
    // again; the weights of that point on its support are the dual weights Danskin's theorem
    // asks for (any such weights give the same derivative where V is differentiable).
    let plane: Vec<usize> = (0..wrenches.len())
        .filter(|&j| dot6(&u, &wrenches[j]) >= value - ON_PLANE * scale)
        .collect();
    let nearest = min_norm_point(plane.len(), |i| wrenches[plane[i]], &[0.0; 6]);
    let support: Vec<usize> = nearest.support().iter().map(|&i| plane[i]).collect();
    let face: Vec<[f64; 6]> = support.iter().map(|&j| wrenches[j]).collect();
    let (weights, foot) = nearest_in_affine_hull(&face);
    // The foot of the face found must be the deciding one's, in the face's relative interior.
    differentiable &= norm(sub6(&foot, &x)) <= TIE * scale && weights.iter().all(|&l| l > TIE);
    // A repeated wrench (contacts listed twice): which copy decides is a tie.
    differentiable &= support
        .iter()
        .all(|&j| wrenches.iter().filter(|w| **w == wrenches[j]).count() == 1);
    let indices = support;

    let mut gradient = Gradient::zero(grasp.contact_count(), differentiable);
    for (&index, &lambda) in indices.iter().zip(&weights) {
        let (i, within) = contact_of(grasp, index);
        gradient.add_wrench(grasp, &u, i, within, lambda);
    }
    Ok(gradient)
}

impl Gradient {
    fn zero(contacts: usize, differentiable: bool) -> Self {
        Gradient {
            positions: vec![[0.0; 3]; contacts],
            normals: vec![[0.0; 3]; contacts],
            friction: 0.0,
            differentiable,
        }
    }

    /// Adds `λ u*·dw` for wrench `within` of contact `i` (its position in
    /// [`Grasp::contact_wrenches`]; the zero wrench of Q∞, past them, adds nothing).
    fn add_wrench(&mut self, grasp: &Grasp, u: &[f64; 6], i: usize, within: usize, lambda: f64) {
        let friction = grasp.friction();
        let (mu, k) = (friction.friction(), friction.cone_edges());
        let contact = &grasp.contacts()[i];
        let (edge, twist_sign) = match (contact.is_soft(), within < k) {
            _ if within >= grasp.contact_wrench_count(i) => return, // the zero wrench
            (false, _) => (within, 0.0),
            (true, true) => (within, 1.0),
            (true, false) => (within - k, -1.0),
        };
        let rho = grasp.torque_scale();
        let (u_f, u_t) = ([u[0], u[1], u[2]], [u[3], u[4], u[5]]);
        // u*·dw for a change (df, dτ) of the wrench's force and torque.
        let along = |df: [f64; 3], dtau: [f64; 3]| dot(u_f, df) + dot(u_t, dtau) / rho;
        let (n, t, b) = (contact.normal(), contact.tangent(), contact.bitangent());
        let (sin, cos) = (2.0 * PI * edge as f64 / k as f64).sin_cos();
        let g = add(scale(t, cos), scale(b, sin));
        let f = add(n, scale(g, mu));
        let r = sub(contact.position(), grasp.torque_reference());
        // Position: u_τ·(dp × f)/ρ = dp·(f × u_τ)/ρ.
        self.positions[i] = add(self.positions[i], scale(cross(f, u_t), lambda / rho));
        // Friction: df = g.
        self.friction += lambda * along(g, cross(r, g));
        // Normal: along each axis projected on the sphere, with the tangent re-derived.
        let (tangent_of, tie) = tangent_derivative(contact);
        self.differentiable &= !tie;
        for axis in 0..3 {
            let mut e = [0.0; 3];
            e[axis] = 1.0;
            let dn = sub(e, scale(n, n[axis]));
            let dt = tangent_of(dn);
            let db = add(cross(dn, t), cross(n, dt));
            let df = add(dn, scale(add(scale(dt, cos), scale(db, sin)), mu));
            let dtau = add(cross(r, df), scale(dn, twist_sign * contact.torsion()));
            self.normals[i][axis] += lambda * along(df, dtau);
        }
    }
}

/// The most tuples of per-contact faces [`qinf_gradient`] sums (the face of the Minkowski sum
/// along the deciding direction): a few per contact in general, k for a whole pyramid.
const MAX_FACE_TUPLES: usize = 1 << 16;

/// The gradient of `quality`, this grasp's Q∞ (with or without the zero wrench, as evaluated), with
/// respect to every contact's position and normal and the friction coefficient.
///
/// Q∞ is the signed distance from the origin to the boundary of the Minkowski sum `⊕_i W_i` of
/// the contacts' wrench sets, `min_{|u|=1} Σ_i max_{w ∈ W_i} u·w`: the same theorem as for
/// [`q1_gradient`], on the sum's face along the deciding direction `u*`, which is the sum of
/// each contact's face `F_i = argmax_{W_i} u*·w`. Its point nearest the origin, by Wolfe's
/// algorithm over the (few) sums of one wrench of each `F_i`, has weights on those sums; each
/// wrench's weight is the total of the sums it is in.
///
/// ```
/// use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric, qinf_gradient};
/// let contacts = [[0.9, 0.1, 0.2], [-0.8, 0.3, 0.1], [0.2, -0.9, 0.3], [0.1, 0.2, -0.95]]
///     .map(|p| Contact::try_new(p, p.map(|x| -x), None).unwrap());
/// let grasp = Grasp::builder(contacts.to_vec(), FrictionModel::try_new(0.6, 6)?).build()?;
/// let metric = Metric::QInf { with_zero_wrench: false };
/// let qinf = Evaluator::new(metric, Method::Partial, None)?.evaluate(&grasp)?;
/// let gradient = qinf_gradient(&grasp, &qinf)?;
/// assert_eq!(gradient.normals.len(), 4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`GradientError::OtherMetric`] when `quality` is not of Q∞;
/// [`GradientError::NoDecidingFace`] when it names no deciding wrench.
pub fn qinf_gradient(grasp: &Grasp, quality: &Evaluation) -> Result<Gradient, GradientError> {
    let Metric::QInf { with_zero_wrench } = quality.metric else {
        return Err(GradientError::OtherMetric {
            expected: "qinf",
            found: quality.metric,
        });
    };
    let (value, scale) = hull_value(quality, "qinf", true)?;
    let deciding = quality.deciding_wrenches();
    if deciding.is_empty() {
        return Err(GradientError::NoDecidingFace);
    }
    let (_, x) = nearest_in_affine_hull(deciding);
    let distance = norm(x);
    let sign = if value > 0.0 { 1.0 } else { -1.0 };
    let u: [f64; 6] = std::array::from_fn(|c| sign * x[c] / distance);
    let m = grasp.contact_count();
    if !(distance > 0.0 && distance.is_finite()) {
        // The deciding face holds the origin (the zero wrench's sum): Q∞ = 0 on the boundary.
        return Ok(Gradient::zero(m, false));
    }
    // A tie with another facet (`Quality::tied`): a minimum of two faces' distances.
    let mut differentiable = value != 0.0 && value.abs() > TIE * scale && !quality.tied();
    // Each contact's face along u*, and the support value it adds.
    let mut faces: Vec<Vec<(usize, [f64; 6])>> = Vec::with_capacity(m);
    let mut support = 0.0;
    for i in 0..m {
        let mut set = vec![[0.0; 6]; grasp.contact_wrench_count(i)];
        grasp.contact_wrenches(i, &mut set);
        if with_zero_wrench {
            set.push([0.0; 6]);
        }
        let size = set.iter().map(|w| dot6(w, w)).fold(0.0, f64::max).sqrt();
        let best = set
            .iter()
            .map(|w| dot6(&u, w))
            .fold(f64::NEG_INFINITY, f64::max);
        support += best;
        faces.push(
            set.iter()
                .enumerate()
                .filter(|(_, w)| dot6(&u, w) >= best - ON_PLANE * size)
                .map(|(j, w)| (j, *w))
                .collect(),
        );
    }
    // The deciding direction must be the one whose support is the value.
    differentiable &= (support - value).abs() <= TIE * scale;
    let count = faces
        .iter()
        .try_fold(1usize, |n, f| n.checked_mul(f.len()))
        .filter(|&n| n <= MAX_FACE_TUPLES);
    let mut gradient = Gradient::zero(m, false);
    let Some(count) = count else {
        return Ok(gradient); // a face too large to sum: reported as not differentiable
    };
    // Every sum of one wrench of each face (odometer), and its tuple.
    let mut sums = Vec::with_capacity(count);
    let mut tuples = Vec::with_capacity(count * m);
    let mut position = vec![0usize; m];
    loop {
        let mut total = [0.0; 6];
        for (face, &p) in faces.iter().zip(&position) {
            for (t, c) in total.iter_mut().zip(&face[p].1) {
                *t += c;
            }
        }
        sums.push(total);
        tuples.extend_from_slice(&position);
        let mut i = m;
        let advanced = loop {
            if i == 0 {
                break false;
            }
            i -= 1;
            position[i] += 1;
            if position[i] < faces[i].len() {
                break true;
            }
            position[i] = 0;
        };
        if !advanced {
            break;
        }
    }
    let nearest = min_norm_point(sums.len(), |s| sums[s], &[0.0; 6]);
    let chosen: Vec<usize> = nearest.support().to_vec();
    let face: Vec<[f64; 6]> = chosen.iter().map(|&s| sums[s]).collect();
    let (weights, foot) = nearest_in_affine_hull(&face);
    differentiable &= norm(sub6(&foot, &x)) <= TIE * scale && weights.iter().all(|&l| l > TIE);
    // A generic face of the sum is the sum of faces whose dimensions add up to its own; more
    // (three whole pyramids tied along u*, say) is a degenerate direction where a slight move
    // of the inputs breaks the ties one way or the other.
    // Each contact's face dimension is measured, not inferred from its point count: a pyramid's
    // whole rim (k points) is 2-dimensional with or without the zero wrench beside it, and a
    // soft finger's quadrilateral side is 2-dimensional with 4 points.
    let dimensions: usize = faces.iter().map(|f| affine_dimension(f)).sum();
    differentiable &= dimensions + 1 == chosen.len();
    gradient.differentiable = differentiable;
    for (&s, &lambda) in chosen.iter().zip(&weights) {
        for i in 0..m {
            let within = faces[i][tuples[s * m + i]].0;
            gradient.add_wrench(grasp, &u, i, within, lambda);
        }
    }
    // Repeated contacts: their wrench sets are equal, a tie between their summands.
    let contacts = grasp.contacts();
    if (0..m).any(|i| (i + 1..m).any(|j| contacts[i] == contacts[j])) {
        gradient.differentiable = false;
    }
    Ok(gradient)
}

/// The contact of wrench `index` in [`Grasp::wrenches`]' order, and its position among that
/// contact's wrenches.
fn contact_of(grasp: &Grasp, index: usize) -> (usize, usize) {
    let mut start = 0;
    for i in 0..grasp.contact_count() {
        let count = grasp.contact_wrench_count(i);
        if index < start + count {
            return (i, index - start);
        }
        start += count;
    }
    unreachable!("the index was found among the grasp's wrenches")
}

/// `dt` as a function of `dn` (tangent to the sphere at `n`), for the contact's tangent rule,
/// and whether the rule is at a switch (the default tangent's axis tied: not differentiable).
fn tangent_derivative(contact: &Contact) -> (impl Fn([f64; 3]) -> [f64; 3], bool) {
    let (n, t) = (contact.normal(), contact.tangent());
    // d(q/|q|) = (I − t tᵀ) dq / |q| for the unnormalised tangent q.
    let project =
        move |dq: [f64; 3], length: f64| scale(sub(dq, scale(t, dot(t, dq))), 1.0 / length);
    let (source, tie) = match contact.tangent_input() {
        Some(given) => (Source::Given(given), false),
        None => {
            let magnitudes = n.map(f64::abs);
            let a = (1..3).fold(0, |a, i| if magnitudes[i] < magnitudes[a] { i } else { a });
            let tie = (0..3).any(|i| i != a && magnitudes[i] <= magnitudes[a] * (1.0 + TIE));
            let mut e = [0.0; 3];
            e[a] = 1.0;
            (Source::Axis(e), tie)
        }
    };
    let derivative = move |dn: [f64; 3]| match source {
        // q = t_g − (t_g·n) n
        Source::Given(g) => {
            let q = sub(g, scale(n, dot(g, n)));
            let dq = sub(scale(n, -dot(g, dn)), scale(dn, dot(g, n)));
            project(dq, norm(q))
        }
        // q = n × e
        Source::Axis(e) => project(cross(dn, e), norm(cross(n, e))),
    };
    (derivative, tie)
}

#[derive(Clone, Copy)]
enum Source {
    Given([f64; 3]),
    Axis([f64; 3]),
}

/// The dimension of the affine hull of a face's wrenches: the rank of their differences from
/// the first, by Gram–Schmidt with pivoting, a residual below [`TIE`] of the face's extent
/// counting as zero (the face's points are a friction pyramid's vertices, far apart or equal).
fn affine_dimension(face: &[(usize, [f64; 6])]) -> usize {
    let Some((_, first)) = face.first() else {
        return 0;
    };
    let mut rest: Vec<[f64; 6]> = face[1..].iter().map(|(_, w)| sub6(w, first)).collect();
    let extent = rest.iter().map(norm6).fold(0.0, f64::max);
    let mut rank = 0;
    while let Some((at, largest)) = rest
        .iter()
        .map(norm6)
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(&b.1))
    {
        if largest.is_nan() || largest <= TIE * extent {
            break;
        }
        let axis = rest.swap_remove(at).map(|c| c / largest);
        for d in &mut rest {
            let along = dot6(d, &axis);
            for (c, a) in d.iter_mut().zip(axis) {
                *c -= along * a;
            }
        }
        rank += 1;
    }
    rank
}

fn norm6(a: &[f64; 6]) -> f64 {
    dot6(a, a).sqrt()
}

fn sub6(a: &[f64; 6], b: &[f64; 6]) -> [f64; 6] {
    std::array::from_fn(|c| a[c] - b[c])
}

fn dot6(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The point of the affine hull of `face` nearest the origin, `x = Σ λ_j w_j` with `Σ λ_j = 1`,
/// and its weights: `x = w_0 + E μ` with `E` the edges from `w_0`, `μ` the least-squares
/// solution of `E μ = −w_0` (faer's QR).
fn nearest_in_affine_hull(face: &[[f64; 6]]) -> (Vec<f64>, [f64; 6]) {
    let base = face[0];
    let edges = face.len() - 1;
    if edges == 0 {
        return (vec![1.0], base);
    }
    let e = Mat::from_fn(6, edges, |r, c| face[c + 1][r] - base[r]);
    let rhs = Mat::from_fn(6, 1, |r, _| -base[r]);
    let mu = e.qr().solve_lstsq(&rhs);
    let mut weights = Vec::with_capacity(face.len());
    weights.push(1.0 - (0..edges).map(|c| mu[(c, 0)]).sum::<f64>());
    weights.extend((0..edges).map(|c| mu[(c, 0)]));
    let x =
        std::array::from_fn(|r| base[r] + (0..edges).map(|c| e[(r, c)] * mu[(c, 0)]).sum::<f64>());
    (weights, x)
}

/// The gradient of `quality`, this grasp's Q_OWS against `space` (by an exact method of
/// [`Evaluator`](super::Evaluator)), with respect to every contact's position and normal and the
/// friction coefficient; `None` when the grasp is not force closure (Q_OWS has no value), the
/// method named no deciding disturbance (the ellipsoid's approximation), or `quality` is not of
/// Q_OWS.
///
/// Q_OWS is `ρ* = min_d max {ρ : −ρ d ∈ H}` over the disturbances `d`, `H` the hull of the
/// wrenches. The deciding disturbance's exit point `y = −ρ* d*` lies on a facet of `H` with
/// outward unit normal `u` at offset `h`, so `ρ* = h / (−u·d*)`; moving the facet's wrenches,
/// `dρ* = Σ_j μ_j u·dw_j / (−u·d*)` with `μ` the weights of `y` on the facet (the facet
/// completed by every wrench on its plane, as for Q1). Flagged not differentiable: `y` on a
/// ridge (a weight near zero), and another disturbance whose ray crosses the facet's plane as
/// early (a tie among disturbances), and a tie through another facet
/// ([`Evaluation::tied`]).
///
/// ```
/// use pqhull::grasp::ows::ObjectWrenchSpace;
/// use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric, ows_gradient};
/// let contacts = [[0.9, 0.1, 0.2], [-0.8, 0.3, 0.1], [0.2, -0.9, 0.3], [0.1, 0.2, -0.95]]
///     .map(|p| Contact::try_new(p, p.map(|x| -x), None).unwrap());
/// let grasp = Grasp::builder(contacts.to_vec(), FrictionModel::try_new(0.6, 6)?).build()?;
/// let space = ObjectWrenchSpace::from_disturbances(vec![
///     [0.0, 0.0, -1.0, 0.0, 0.0, 0.0],
///     [0.3, 0.0, 0.0, 0.0, 0.1, 0.0],
/// ])?;
/// let ows = Evaluator::new(Metric::Ows, Method::Partial, Some(&space))?.evaluate(&grasp)?;
/// let gradient = ows_gradient(&grasp, &space, &ows).expect("force closure");
/// assert_eq!(gradient.positions.len(), 4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn ows_gradient(
    grasp: &Grasp,
    space: &super::ows::ObjectWrenchSpace,
    quality: &Evaluation,
) -> Option<Gradient> {
    if quality.metric != Metric::Ows {
        return None;
    }
    let rho = quality.value?;
    let deciding = quality.deciding_disturbance?;
    let disturbances = space.disturbances();
    let d = *disturbances.get(deciding)?;
    let wrenches = grasp.wrenches();
    let y: [f64; 6] = std::array::from_fn(|c| -rho * d[c]);
    // The facet through y: the partial hull toward y (on the boundary, within rounding).
    let hull_points = &wrenches;
    let (_, result) =
        crate::Hull::try_with_strategy(hull_points, crate::strategy::ClosestToOrigin::towards(y))
            .ok()?;
    let facet: Vec<[f64; 6]> = result
        .closest_facet_vertices
        .iter()
        .map(|&v| wrenches[v])
        .collect();
    let (_, foot) = nearest_in_affine_hull(&facet);
    let h = norm(foot);
    let m = grasp.contact_count();
    if !(h > 0.0 && h.is_finite()) {
        return Some(Gradient::zero(m, false));
    }
    let u: [f64; 6] = std::array::from_fn(|c| foot[c] / h);
    let scale = wrenches
        .iter()
        .map(|w| dot6(w, w))
        .fold(0.0, f64::max)
        .sqrt();
    let plane: Vec<usize> = (0..wrenches.len())
        .filter(|&j| dot6(&u, &wrenches[j]) >= h - ON_PLANE * scale)
        .collect();
    let nearest = min_norm_point(plane.len(), |i| wrenches[plane[i]], &y);
    let support: Vec<usize> = nearest.support().iter().map(|&i| plane[i]).collect();
    // y's weights on the support: the nearest point of its affine hull to y, from y.
    let shifted: Vec<[f64; 6]> = support.iter().map(|&j| sub6(&wrenches[j], &y)).collect();
    let (weights, offset) = nearest_in_affine_hull(&shifted);
    let across = -dot6(&u, &d);
    let mut differentiable = !quality.tied()
        && across > 0.0
        && norm(offset) <= TIE * scale
        && weights.iter().all(|&l| l > TIE)
        && support
            .iter()
            .all(|&j| wrenches.iter().filter(|w| **w == wrenches[j]).count() == 1);
    // Another disturbance crossing the facet's plane as early ties with d*.
    differentiable &= disturbances.iter().enumerate().all(|(i, e)| {
        let through = -dot6(&u, e);
        i == deciding || through <= 0.0 || h / through > rho * (1.0 + TIE)
    });
    let mut gradient = Gradient::zero(m, differentiable);
    for (&index, &mu_j) in support.iter().zip(&weights) {
        let (i, within) = contact_of(grasp, index);
        gradient.add_wrench(grasp, &u, i, within, mu_j / across);
    }
    Some(gradient)
}
