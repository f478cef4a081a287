//! Reference values of Q1, Q∞ and Q_OWS on a grasp's *raw* wrenches, independent of the crate's
//! hull engine, and the bookkeeping of the checks against them (tests/raw_reference.rs and
//! tests/cli_raw_reference.rs include this file with `#[path]`, next to `support/min_norm.rs`).
//!
//! * Raw wrenches: exactly [`Grasp::wrenches`]; [`formula_wrenches`] recomputes them from the
//!   contact data with the documented formula so a test can check the two agree to rounding.
//! * Origin inside (Qhull, on the raw wrenches, finds a hull with every facet offset < 0): the
//!   value is the smallest distance to a facet plane. Qhull's planes are floating point, so the
//!   facets within a hair of the nearest are re-derived *exactly*: the hyperplane through the
//!   facet's six vertices from integer cofactors (the f64 inputs are dyadic rationals), and the
//!   value is the exact support function h(u) = max_i u·w_i of its unit normal u, rounded once.
//!   For any unit u, h(u) is an upper bound of the true Q1 (Q1 = min over unit u of h(u)), so
//!   the reference never undershoots by more than the final rounding; it is the true value when
//!   the six vertices span a facet of the raw hull.
//!   Near the boundary, Qhull's merged facets differ from the raw hull's rounding-level sliver
//!   facets by ~1e-17 absolute: far below the 1e-14·scale floor of the Q1 check.
//! * Origin outside, on the boundary, or a flat set (Qhull error QH6154, or too few points):
//!   −(distance to the hull) by Wolfe's algorithm ([`wolfe_point`]: the algorithm of
//!   `support/min_norm.rs`, which knows nothing of the crate, run to rounding level and
//!   cross-checked against it), with its duality gap min_j x̂·w_j as a certificate. When Wolfe
//!   finds the origin clearly outside (> 1e-11·scale) Qhull is skipped.
//! * Q∞: the same over the Minkowski sum, materialised: every tuple, summed left to right in f64
//!   (up to [`MINKOWSKI_REFERENCE_LIMIT`] points; with the zero wrench, a grasp whose union is
//!   clearly not force closure has Q∞ = 0 exactly at any size, see [`qinf_reference`]).
//! * Q_OWS: Qhull's planes pick the candidate disturbances (min over facets with n·(−d) > 0 of
//!   offset / n·(−d), within 1e-3 of the smallest); the value is then *exact*: for each
//!   candidate, the linear program max r s.t. −r·d ∈ CH(w) solved by an integer simplex
//!   ([`exact_ray_exit`]) on the raw wrenches, rounded once.
//!
//! Seeded grasp families (ellipsoid, box, cylinder; physically degenerate ones; near-boundary
//! bisections) and the check bookkeeping ([`Report`]: failures collected, a summary printed with
//! `eprintln!`) are shared by both test files. `RAW_REFERENCE_FAILURES=all` lists every failed
//! check instead of the first 40.

pub use super::exact_lp::{IntegerPoints, exact_ray_exit};
use super::min_norm::min_norm_point;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use pqhull::geometry::Rng;
use pqhull::grasp::{Contact, FrictionModel, Grasp};
use pqhull::grasp::{Evaluation, Evaluator, Method, Metric, QualityError};
use pqhull::qhull_baseline::{QhullError, QhullHull, qhull_full_hull};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::{Duration, Instant};

/// The force-closure tolerance of the contract (1e-12): a grasp with |Q| below ε × scale is a
/// boundary grasp, not force closure. The crate's own constant, checked against the contract's
/// value in [`check_epsilon`]. (Before it existed, these tests defined it locally as 1e-12.)
pub use pqhull::grasp::quality::FORCE_CLOSURE_EPSILON;

/// The crate's ε is the contract's.
pub fn check_epsilon() {
    assert_eq!(FORCE_CLOSURE_EPSILON, 1e-12, "the contract's ε is 1e-12");
}

/// The reference's sign is trusted only when |value| exceeds this times the scale.
pub const TRUST: f64 = 1e-13;

/// Verdict checks are skipped when the reference lies within this times the scale of ε × scale.
pub const VERDICT_SKIP: f64 = 1e-13;

/// Value tolerance: relative to the reference ...
pub const REL_TOL: f64 = 1e-12;
/// ... or absolute, times the scale, for values near zero.
pub const ABS_TOL: f64 = 1e-14;

/// Materialise Minkowski sums up to this many points for the Q∞ reference (Qhull takes ~1 s on
/// 1300 summed wrenches: their rounding slivers give ~10^5 facets).
pub const MINKOWSKI_REFERENCE_LIMIT: usize = 1300;

// ---------------------------------------------------------------------------------------------
// Raw wrenches and scales

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub fn norm6(w: &[f64; 6]) -> f64 {
    w.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The documented wrenches, recomputed from the contact data: f = n + μ(cos θ_j t + sin θ_j
/// (n × t)), θ_j = 2πj/k, w = [f; (p − c) × f / ρ], contact-major.
pub fn formula_wrenches(grasp: &Grasp) -> Vec<[f64; 6]> {
    let fm = grasp.friction();
    let (mu, k) = (fm.friction(), fm.cone_edges());
    let c = grasp.torque_reference();
    let rho = grasp.torque_scale();
    let mut out = Vec::new();
    for contact in grasp.contacts() {
        let (n, t, p) = (contact.normal(), contact.tangent(), contact.position());
        let b = cross(n, t);
        let r = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
        for j in 0..k {
            let theta = 2.0 * PI * j as f64 / k as f64;
            let (s, co) = theta.sin_cos();
            let f: [f64; 3] = std::array::from_fn(|a| n[a] + mu * (co * t[a] + s * b[a]));
            let tau = cross(r, f);
            out.push([f[0], f[1], f[2], tau[0] / rho, tau[1] / rho, tau[2] / rho]);
        }
    }
    out
}

/// The largest coordinate difference between `grasp.wrenches()` and [`formula_wrenches`], in
/// units of a rounding bound (≤ 1 passes), and whether they agree bit for bit.
pub fn wrench_formula_error(grasp: &Grasp) -> (f64, bool) {
    let raw = grasp.wrenches();
    let ours = formula_wrenches(grasp);
    assert_eq!(raw.len(), ours.len(), "wrench count");
    let mu = grasp.friction().friction();
    let c = grasp.torque_reference();
    let rho = grasp.torque_scale();
    let k = grasp.friction().cone_edges();
    let mut worst = 0.0f64;
    let mut identical = true;
    for (i, (a, b)) in raw.iter().zip(&ours).enumerate() {
        let p = grasp.contacts()[i / k].position();
        let lever = ((p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2) + (p[2] - c[2]).powi(2)).sqrt();
        // |f| ≤ 1 + μ; each coordinate of f or of r × f / ρ is a handful of roundings away.
        let bound = 16.0 * f64::EPSILON * (1.0 + mu) * (1.0 + lever / rho);
        for (x, y) in a.iter().zip(b) {
            identical &= x.to_bits() == y.to_bits();
            worst = worst.max((x - y).abs() / bound);
        }
    }
    (worst, identical)
}

/// Q1 / Q_OWS scale: the largest Euclidean norm of the raw wrenches.
pub fn union_scale(w: &[[f64; 6]]) -> f64 {
    w.iter().map(norm6).fold(0.0, f64::max)
}

/// Q∞ scale: the sum over contacts of each contact's largest raw wrench norm.
pub fn minkowski_scale(grasp: &Grasp) -> f64 {
    let k = grasp.friction().cone_edges();
    grasp
        .wrenches()
        .chunks(k)
        .map(|c| c.iter().map(norm6).fold(0.0, f64::max))
        .sum()
}

/// The Minkowski sum ⊕_i W_i of the contacts' raw wrench sets (with the zero wrench in each when
/// asked), every tuple summed left to right in f64; `None` above `limit` points.
pub fn minkowski_points(grasp: &Grasp, with_zero: bool, limit: usize) -> Option<Vec<[f64; 6]>> {
    let k = grasp.friction().cone_edges();
    let sets: Vec<Vec<[f64; 6]>> = grasp
        .wrenches()
        .chunks(k)
        .map(|c| {
            let mut s = c.to_vec();
            if with_zero {
                s.push([0.0; 6]);
            }
            s
        })
        .collect();
    let mut count = 1usize;
    for s in &sets {
        count = count.checked_mul(s.len())?;
        if count > limit {
            return None;
        }
    }
    let mut out = Vec::with_capacity(count);
    let mut index = vec![0usize; sets.len()];
    loop {
        let mut sum = sets[0][index[0]];
        for (set, &j) in sets.iter().zip(&index).skip(1) {
            for (s, x) in sum.iter_mut().zip(&set[j]) {
                *s += x;
            }
        }
        out.push(sum);
        // Mixed-radix increment, last contact fastest.
        let mut a = sets.len();
        loop {
            if a == 0 {
                return Some(out);
            }
            a -= 1;
            index[a] += 1;
            if index[a] < sets[a].len() {
                break;
            }
            index[a] = 0;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Exact hyperplanes (integer cofactors of the dyadic inputs)

/// Determinant by fraction-free Bareiss elimination.
fn determinant(mut a: Vec<Vec<BigInt>>) -> BigInt {
    let n = a.len();
    let mut negate = false;
    let mut previous = BigInt::from(1);
    for k in 0..n {
        if a[k][k].is_zero() {
            let Some(p) = (k + 1..n).find(|&i| !a[i][k].is_zero()) else {
                return BigInt::zero();
            };
            a.swap(k, p);
            negate = !negate;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = (&a[i][j] * &a[k][k] - &a[i][k] * &a[k][j]) / &previous;
                a[i][j] = v;
            }
        }
        previous = a[k][k].clone();
    }
    let d = a[n - 1][n - 1].clone();
    if negate { -d } else { d }
}

fn dot_int(a: &[BigInt; 6], b: &[BigInt; 6]) -> BigInt {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The integer normal (cofactors) of the hyperplane through six points, oriented along `hint`;
/// `None` when they are affinely dependent.
pub fn exact_normal(p: &[[BigInt; 6]], vertices: &[usize], hint: &[f64]) -> Option<[BigInt; 6]> {
    if vertices.len() != 6 {
        return None;
    }
    let base = &p[vertices[0]];
    let rows: Vec<[BigInt; 6]> = vertices[1..]
        .iter()
        .map(|&v| std::array::from_fn(|c| &p[v][c] - &base[c]))
        .collect();
    let mut n: [BigInt; 6] = std::array::from_fn(|j| {
        let minor: Vec<Vec<BigInt>> = rows
            .iter()
            .map(|r| (0..6).filter(|&c| c != j).map(|c| r[c].clone()).collect())
            .collect();
        let d = determinant(minor);
        if j % 2 == 1 { -d } else { d }
    });
    if n.iter().all(Zero::is_zero) {
        return None;
    }
    debug_assert!(rows.iter().all(|r| dot_int(&n, r).is_zero()));
    // Orient along Qhull's (outward) normal: compare in floating point, scaled to avoid overflow.
    let big = n.iter().map(|x| x.bits()).max().unwrap_or(0);
    let drop = big.saturating_sub(60) as usize;
    let along: f64 = n
        .iter()
        .zip(hint)
        .map(|(x, h)| (x >> drop).to_f64().unwrap_or(0.0) * h)
        .sum();
    if along < 0.0 {
        for x in n.iter_mut() {
            *x = -x.clone();
        }
    }
    Some(n)
}

fn ratio_to_f64(num: BigInt, den: BigInt) -> f64 {
    BigRational::new(num, den).to_f64().expect("finite ratio")
}

/// h(u) = max_i u·w_i for the unit normal u of the integer normal `n`, exactly, rounded once
/// (then a square root); in the points' original units.
pub fn exact_support(points: &IntegerPoints, set: usize, n: &[BigInt; 6]) -> f64 {
    let h = points.sets[set]
        .iter()
        .map(|p| dot_int(n, p))
        .max()
        .expect("points");
    let nn: BigInt = n.iter().map(|x| x * x).sum();
    let sign = if h.is_negative() { -1.0 } else { 1.0 };
    let scale = BigInt::from(1) << (2 * points.shift.max(0)) as usize;
    let scale_down = BigInt::from(1) << (2 * (-points.shift).max(0)) as usize;
    sign * ratio_to_f64(&h * &h * scale_down, nn * scale).sqrt()
}

// ---------------------------------------------------------------------------------------------
// Q1 / Q∞ reference

/// The reference for one point set.
#[derive(Clone, Debug)]
pub struct HullReference {
    /// The signed distance (positive inside).
    pub value: f64,
    pub scale: f64,
    /// Qhull found a hull with every facet offset < 0.
    pub inside: bool,
    /// Qhull's own nearest-plane value (−min offset), when inside.
    pub qhull_value: Option<f64>,
    /// Wolfe's distance from the origin to the hull, and its duality gap.
    pub wolfe_distance: f64,
    pub wolfe_gap: f64,
    /// Facet planes re-derived exactly.
    pub exact_planes: usize,
    /// Qhull's hull of the point set (for Q_OWS), when inside.
    pub hull: Option<QhullHull>,
    /// Why Qhull gave no hull, if it did not.
    pub qhull_error: Option<String>,
}

impl HullReference {
    /// The reference's sign can be trusted.
    pub fn trusted(&self) -> bool {
        self.value.abs() > TRUST * self.scale
    }

    /// The verdict the contract expects, `None` when the reference is too close to ε × scale to
    /// call (within [`VERDICT_SKIP`] × scale of it).
    pub fn expected_verdict(&self) -> Option<bool> {
        expected_verdict(self.value, self.scale)
    }
}

/// `Some(value ≥ ε·scale)`, or `None` within [`VERDICT_SKIP`]·scale of ε·scale.
pub fn expected_verdict(value: f64, scale: f64) -> Option<bool> {
    let threshold = FORCE_CLOSURE_EPSILON * scale;
    if (value - threshold).abs() <= VERDICT_SKIP * scale {
        None
    } else {
        Some(value >= threshold)
    }
}

fn dot6(a: &[f64], b: &[f64; 6]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Wolfe's minimum-norm point of CH(p) (the algorithm of `support/min_norm.rs`), run to rounding
/// level: the stopping tolerance there (1e-13 of the largest norm) leaves errors of ~1e-14 in the
/// distance, too coarse for a reference at 1e-14 × scale. The affine minimiser is the residual of
/// projecting out the corral's differences (modified Gram–Schmidt, twice), not the normal
/// equations, so its error stays at rounding level when the corral is thin. Returns the nearest
/// point.
pub fn wolfe_point(p: &[[f64; 6]]) -> [f64; 6] {
    let dot = |a: &[f64; 6], b: &[f64; 6]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let big_m = p.iter().map(norm6).fold(0.0, f64::max);
    let combination = |s: &[usize], weights: &[f64]| {
        let mut x = [0.0; 6];
        for (&i, &w) in s.iter().zip(weights) {
            for (xk, pk) in x.iter_mut().zip(&p[i]) {
                *xk += w * pk;
            }
        }
        x
    };
    // The affine weights of the point of aff{p_i : i ∈ s} nearest the origin, and that point;
    // None when the corral is affinely dependent.
    let affine = |s: &[usize]| -> Option<(Vec<f64>, [f64; 6])> {
        let base = p[s[0]];
        let k = s.len() - 1;
        let mut q: Vec<[f64; 6]> = Vec::with_capacity(k);
        let mut r = vec![0.0; k * k]; // upper triangular, column-major r[row + col·k]
        for (col, &i) in s[1..].iter().enumerate() {
            let e: [f64; 6] = std::array::from_fn(|c| p[i][c] - base[c]);
            let length = norm6(&e);
            let mut v = e;
            for _ in 0..2 {
                for (row, qr) in q.iter().enumerate() {
                    let c = dot(qr, &v);
                    r[row + col * k] += c;
                    for (vc, qc) in v.iter_mut().zip(qr) {
                        *vc -= c * qc;
                    }
                }
            }
            let rest = norm6(&v);
            if rest.is_nan() || rest <= 1e-14 * length || length == 0.0 {
                return None;
            }
            r[col + col * k] = rest;
            q.push(v.map(|x| x / rest));
        }
        // x = base − Q Qᵀ base, twice.
        let mut x = base;
        for _ in 0..2 {
            for qr in &q {
                let c = dot(qr, &x);
                for (xc, qc) in x.iter_mut().zip(qr) {
                    *xc -= c * qc;
                }
            }
        }
        // R β = Qᵀ (x − base).
        let d: [f64; 6] = std::array::from_fn(|c| x[c] - base[c]);
        let mut beta: Vec<f64> = q.iter().map(|qr| dot(qr, &d)).collect();
        for row in (0..k).rev() {
            let mut v = beta[row];
            for col in row + 1..k {
                v -= r[row + col * k] * beta[col];
            }
            beta[row] = v / r[row + row * k];
        }
        let mut alpha = Vec::with_capacity(k + 1);
        alpha.push(1.0 - beta.iter().sum::<f64>());
        alpha.extend(beta);
        Some((alpha, x))
    };
    let j0 = (0..p.len())
        .min_by(|&a, &b| dot(&p[a], &p[a]).total_cmp(&dot(&p[b], &p[b])))
        .expect("points");
    let mut s = vec![j0];
    let mut lam = vec![1.0];
    let mut x = p[j0];
    for _ in 0..100 * (p.len() + 7) {
        let xx = dot(&x, &x);
        if xx == 0.0 {
            break;
        }
        let (j, xpj) = (0..p.len())
            .map(|j| (j, dot(&x, &p[j])))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .expect("points");
        if xx - xpj <= 1e-15 * big_m * xx.sqrt() || s.contains(&j) || s.len() > 6 {
            break;
        }
        s.push(j);
        lam.push(0.0);
        loop {
            let Some((alpha, y)) = affine(&s) else {
                s.pop();
                lam.pop();
                return x;
            };
            if alpha.iter().all(|&a| a > 0.0) {
                x = y;
                lam = alpha;
                break;
            }
            // Walk from λ toward α until the first weight reaches zero.
            let mut theta = 1.0f64;
            let mut hit = 0;
            for (i, (&l, &a)) in lam.iter().zip(&alpha).enumerate() {
                if a <= 0.0 {
                    let t = if l - a > 0.0 { l / (l - a) } else { 0.0 };
                    if t < theta {
                        theta = t;
                        hit = i;
                    }
                }
            }
            for (l, a) in lam.iter_mut().zip(&alpha) {
                *l = (1.0 - theta) * *l + theta * a;
            }
            lam[hit] = 0.0;
            let mut i = 0;
            while i < s.len() {
                if lam[i] <= 0.0 {
                    s.remove(i);
                    lam.remove(i);
                } else {
                    i += 1;
                }
            }
            let total: f64 = lam.iter().sum();
            lam.iter_mut().for_each(|l| *l /= total);
            x = combination(&s, &lam);
            if s.len() == 1 {
                break;
            }
        }
    }
    x
}

/// Wolfe's distance from the origin to CH(w) (rounding level, [`wolfe_point`]; cross-checked
/// against `support/min_norm.rs`), and the duality gap |x| − min_j x̂·w_j certifying it (the
/// hull lies beyond the plane x̂·y = |x| − gap; meaningful when the origin is outside).
pub fn wolfe(w: &[[f64; 6]]) -> (f64, f64) {
    let x = wolfe_point(w);
    let distance = norm6(&x);
    let points: Vec<Vec<f64>> = w.iter().map(|p| p.to_vec()).collect();
    let (_, coarse) = min_norm_point(&points, &[0.0; 6]);
    let scale = union_scale(w);
    // Both are norms of points of the hull, so upper bounds of the distance; the one run to
    // rounding level is never the worse (support/min_norm.rs stops early on thin corrals).
    assert!(
        distance <= coarse + 1e-12 * scale,
        "reference: Wolfe at rounding level ({distance:e}) is farther than support/min_norm.rs \
         ({coarse:e})"
    );
    if distance == 0.0 {
        return (0.0, 0.0);
    }
    let lower = w
        .iter()
        .map(|p| dot6(&x, p) / distance)
        .fold(f64::INFINITY, f64::min);
    (distance, distance - lower)
}

/// Wolfe's distance above this times the scale: the origin is outside, no hull needed.
pub const CLEARLY_OUTSIDE: f64 = 1e-11;

/// Facets within this (relative to the nearest, or times the scale) of the nearest are refined.
const CANDIDATE_WINDOW: f64 = 1e-9;

/// The reference Q1 of the explicit point set `w` (the union, or a materialised Minkowski sum)
/// with the given scale.
pub fn hull_reference(w: &[[f64; 6]], scale: f64) -> HullReference {
    hull_reference_with(w, scale, true)
}

/// Q1 / scale of `grasp` by the reference without the exact re-derivation of Qhull's planes
/// (accurate to ~1e-16·scale): enough to steer a bisection or a search.
pub fn rough_q1(grasp: &Grasp) -> f64 {
    let w = grasp.wrenches();
    let scale = union_scale(&w);
    hull_reference_with(&w, scale, false).value / scale
}

/// [`hull_reference`], with the exact re-derivation of the nearest facet planes when `exact`.
pub fn hull_reference_with(w: &[[f64; 6]], scale: f64, exact: bool) -> HullReference {
    let (wolfe_distance, wolfe_gap) = wolfe(w);
    let mut reference = HullReference {
        value: -wolfe_distance,
        scale,
        inside: false,
        qhull_value: None,
        wolfe_distance,
        wolfe_gap,
        exact_planes: 0,
        hull: None,
        qhull_error: None,
    };
    if wolfe_distance > CLEARLY_OUTSIDE * scale {
        // Clearly outside: Wolfe's distance (certified by its duality gap) is the answer, and
        // Qhull (seconds on a Minkowski sum: its rounding slivers give 10^5 facets) is not needed.
        return reference;
    }
    let hull = match qhull_full_hull(w) {
        Ok(hull) => hull,
        Err(e @ QhullError::TooFewPoints { .. }) => {
            reference.qhull_error = Some(e.to_string());
            return reference;
        }
        Err(QhullError::Qhull { code, message }) => {
            // QH6154: the input is flat (rank < 6). Anything else is reported by the caller.
            reference.qhull_error = Some(format!("QH{code}: {}", message.trim()));
            return reference;
        }
        Err(e) => panic!("qhull: {e}"),
    };
    if !hull.facets.iter().all(|f| f.offset < 0.0) {
        // Outside, or on the boundary: Wolfe's distance. A facet plane is never farther than the
        // hull itself.
        let plane = hull
            .facets
            .iter()
            .map(|f| f.offset)
            .fold(f64::NEG_INFINITY, f64::max);
        assert!(
            plane <= wolfe_distance + 1e-12 * scale,
            "reference: a Qhull plane ({plane}) beyond Wolfe's distance ({wolfe_distance})"
        );
        reference.hull = Some(hull);
        return reference;
    }
    let qhull_value = hull
        .facets
        .iter()
        .map(|f| -f.offset)
        .fold(f64::INFINITY, f64::min);
    let window = CANDIDATE_WINDOW * qhull_value + 1e-12 * scale;
    let sets: &[&[[f64; 6]]] = if exact { &[w] } else { &[] };
    let integers = IntegerPoints::new(sets);
    let mut value = f64::INFINITY;
    for facet in hull
        .facets
        .iter()
        .filter(|f| -f.offset <= qhull_value + window)
    {
        // The support function at Qhull's own (floating) normal: an upper bound too.
        let length = facet.normal.iter().map(|x| x * x).sum::<f64>().sqrt();
        let h = w
            .iter()
            .map(|p| dot6(&facet.normal, p) / length)
            .fold(f64::NEG_INFINITY, f64::max);
        let normal = if exact {
            exact_normal(&integers.sets[0], &facet.vertices, &facet.normal)
        } else {
            None
        };
        let candidate = match normal {
            Some(n) => {
                reference.exact_planes += 1;
                exact_support(&integers, 0, &n)
            }
            None => h,
        };
        value = value.min(candidate);
    }
    assert!(
        wolfe_distance <= 1e-13 * scale || value <= TRUST * scale,
        "reference: Qhull puts the origin inside ({value}) but Wolfe finds it at {wolfe_distance}"
    );
    reference.value = value;
    reference.inside = true;
    reference.qhull_value = Some(qhull_value);
    reference.hull = Some(hull);
    reference
}

/// Disturbances whose floating-point estimate (Qhull's planes) lies within this factor of the
/// smallest get the exact linear program. Qhull's planes are good to ~1e-16·scale, which near the
/// boundary (Q_OWS ~ 1e-11) is 1e-5 relative: the window is wide on purpose.
const OWS_CANDIDATE_WINDOW: f64 = 1e-3;

/// The reference Q_OWS of a force-closure point set against `disturbances`: (value, Qhull's
/// floating-point value).
///
/// Qhull's planes only pick the candidate disturbances. The value is exact: for each candidate
/// d, the largest r with −r·d ∈ CH(w) is the optimum of the linear program
/// max r s.t. Σ λ_i w_i + r·d = 0, Σ λ_i = 1, λ ≥ 0, r ≥ 0, solved in integer arithmetic
/// ([`exact_ray_exit`]) on the raw wrenches — no plane, merged facet or triangulation involved
/// (near the boundary Qhull's merged facets are off by ~1e-17 absolute, 1e-6 of a Q_OWS of
/// 1e-11).
pub fn ows_reference(w: &[[f64; 6]], hull: &QhullHull, disturbances: &[[f64; 6]]) -> (f64, f64) {
    let estimate = |d: &[f64; 6]| {
        hull.facets
            .iter()
            .filter_map(|f| {
                let along = -dot6(&f.normal, d);
                (along > 0.0).then(|| -f.offset / along)
            })
            .fold(f64::INFINITY, f64::min)
    };
    let estimates: Vec<f64> = disturbances.iter().map(estimate).collect();
    let qhull_value = estimates.iter().copied().fold(f64::INFINITY, f64::min);
    let integers = IntegerPoints::new(&[w, disturbances]);
    let mut value = f64::INFINITY;
    for (i, e) in estimates.iter().enumerate() {
        if *e > qhull_value * (1.0 + OWS_CANDIDATE_WINDOW) {
            continue;
        }
        let r = exact_ray_exit(&integers.sets[0], &integers.sets[1][i])
            .expect("the origin is inside the hull");
        value = value.min(r.to_f64().expect("finite"));
    }
    (value, qhull_value)
}

// ---------------------------------------------------------------------------------------------
// Seeded grasps: support/grasps.rs, re-exported for the tests that take them from here.

pub use super::grasps::{Shape, random_disturbances, random_grasp};
use super::grasps::{unit3, with_contact_moved, with_friction};

/// Bisects the parameter until the reference Q1 / scale of `make(parameter)` is within 5 % of
/// `target`. `seen` holds every (parameter, Q1 / scale) evaluated so far for this `make` (the
/// endpoints first), so that later targets start from the tightest bracket already known: each
/// step bisects the shortest interval between neighbouring evaluations that straddles the target.
/// Returns the parameter and the reference there.
pub fn bisect(
    make: impl Fn(f64) -> Grasp,
    target: f64,
    seen: &mut Vec<(f64, f64)>,
) -> Option<(f64, HullReference)> {
    for _ in 0..300 {
        seen.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (lo, hi) = seen
            .windows(2)
            .filter(|p| (p[0].1 - target).signum() != (p[1].1 - target).signum())
            .map(|p| (p[0].0, p[1].0))
            .min_by(|a, b| (a.1 - a.0).total_cmp(&(b.1 - b.0)))?;
        let mid = lo + (hi - lo) / 2.0;
        if mid == lo || mid == hi {
            return None;
        }
        let f = rough_q1(&make(mid));
        seen.push((mid, f));
        if (f - target).abs() <= 0.05 * target.abs() {
            let w = make(mid).wrenches();
            return Some((mid, hull_reference(&w, union_scale(&w))));
        }
    }
    None
}

// ---------------------------------------------------------------------------------------------
// Bookkeeping

/// The figures of one (metric, method).
#[derive(Default)]
pub struct Tally {
    /// |got − ref| / |ref| over trusted references.
    pub relative: Vec<f64>,
    /// |got − ref| / scale over every value check.
    pub absolute: Vec<f64>,
    pub values: usize,
    pub value_failures: usize,
    pub verdicts: usize,
    /// Expected force closure, got not.
    pub missed: usize,
    /// Expected not force closure, got force closure.
    pub false_closure: usize,
    pub skipped: usize,
    pub errors: usize,
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Every check of one test, and the failures to report.
#[derive(Default)]
pub struct Report {
    pub tallies: BTreeMap<String, Tally>,
    pub failures: Vec<String>,
    /// Free-form lines for the summary.
    pub notes: Vec<String>,
    /// Time spent per key: (calls, total, slowest).
    pub timings: BTreeMap<String, (usize, Duration, Duration)>,
}

impl Report {
    pub fn tally(&mut self, key: &str) -> &mut Tally {
        self.tallies.entry(key.to_string()).or_default()
    }

    /// A value check: |got − reference| ≤ max(1e-12 |reference|, 1e-14 scale) (`scale` 0: purely
    /// relative, as for Q_OWS).
    pub fn value(&mut self, key: &str, case: &str, got: f64, reference: f64, scale: f64) {
        let error = (got - reference).abs();
        let tolerance = (REL_TOL * reference.abs()).max(ABS_TOL * scale);
        let t = self.tally(key);
        t.values += 1;
        if scale > 0.0 {
            t.absolute.push(if error.is_nan() {
                f64::INFINITY
            } else {
                error / scale
            });
        }
        if reference.abs() > TRUST * scale {
            t.relative.push(if error.is_nan() {
                f64::INFINITY
            } else {
                error / reference.abs()
            });
        }
        if error.is_nan() || error > tolerance {
            t.value_failures += 1;
            let of_scale = if scale > 0.0 {
                format!(", {:.3e} of the scale {scale:.3}", error / scale)
            } else {
                String::new()
            };
            self.failures.push(format!(
                "{key} {case}: value {got:e} vs reference {reference:e}: off by {error:.3e} = \
                 {:.3e} relative{of_scale}",
                error / reference.abs(),
            ));
        }
    }

    /// A verdict check (`expected` None: skipped, too close to ε·scale).
    pub fn verdict(&mut self, key: &str, case: &str, got: bool, expected: Option<bool>, why: &str) {
        let t = self.tally(key);
        let Some(expected) = expected else {
            t.skipped += 1;
            return;
        };
        t.verdicts += 1;
        if got != expected {
            if expected {
                t.missed += 1;
            } else {
                t.false_closure += 1;
            }
            self.failures.push(format!(
                "{key} {case}: force_closure {got}, expected {expected} ({why})"
            ));
        }
    }

    /// An error where the contract asks for nothing more than a verdict when there is one (the
    /// ellipsoid method): counted in the `errors` column and listed in the notes, not a failure.
    pub fn soft_error(&mut self, key: &str, case: &str, message: &str) {
        self.tally(key).errors += 1;
        self.notes.push(format!(
            "{key} {case}: no verdict (not counted as a failure): {message}"
        ));
    }

    pub fn error(&mut self, key: &str, case: &str, message: &str) {
        self.tally(key).errors += 1;
        self.failures
            .push(format!("{key} {case}: evaluation failed: {message}"));
    }

    /// Runs `f`, adding its time to `key`.
    pub fn time<T>(&mut self, key: &str, f: impl FnOnce() -> T) -> T {
        let started = Instant::now();
        let out = f();
        self.add_time(key, started.elapsed());
        out
    }

    /// Adds one call of `elapsed` to `key`'s time.
    pub fn add_time(&mut self, key: &str, elapsed: Duration) {
        let entry = self.timings.entry(key.to_string()).or_default();
        entry.0 += 1;
        entry.1 += elapsed;
        entry.2 = entry.2.max(elapsed);
    }

    pub fn note(&mut self, line: String) {
        self.notes.push(line);
    }

    pub fn absorb(&mut self, other: Report) {
        for (k, t) in other.tallies {
            let mine = self.tally(&k);
            mine.relative.extend(t.relative);
            mine.absolute.extend(t.absolute);
            mine.values += t.values;
            mine.value_failures += t.value_failures;
            mine.verdicts += t.verdicts;
            mine.missed += t.missed;
            mine.false_closure += t.false_closure;
            mine.skipped += t.skipped;
            mine.errors += t.errors;
        }
        self.failures.extend(other.failures);
        self.notes.extend(other.notes);
        for (k, (n, total, slowest)) in other.timings {
            let e = self.timings.entry(k).or_default();
            e.0 += n;
            e.1 += total;
            e.2 = e.2.max(slowest);
        }
    }

    /// Prints the summary and panics when a check failed.
    pub fn finish(mut self, title: &str) {
        let mut out = format!("\n==== {title} ====\n");
        out += &format!(
            "{:<28} {:>6} {:>6} {:>10} {:>10} {:>10} {:>7} {:>6} {:>6} {:>6} {:>6}\n",
            "metric/method",
            "values",
            "fail",
            "max rel",
            "med rel",
            "max abs/s",
            "verdict",
            "missed",
            "false+",
            "skip",
            "errors"
        );
        for (key, t) in self.tallies.iter_mut() {
            let max_rel = t.relative.iter().copied().fold(0.0, f64::max);
            let max_abs = t.absolute.iter().copied().fold(0.0, f64::max);
            out += &format!(
                "{key:<28} {:>6} {:>6} {:>10.2e} {:>10.2e} {:>10.2e} {:>7} {:>6} {:>6} {:>6} {:>6}\n",
                t.values,
                t.value_failures,
                max_rel,
                median(&mut t.relative),
                max_abs,
                t.verdicts,
                t.missed,
                t.false_closure,
                t.skipped,
                t.errors
            );
        }
        for line in &self.notes {
            out += line;
            out += "\n";
        }
        for (key, (n, total, slowest)) in &self.timings {
            out += &format!(
                "time {key}: {:.2} s over {n} calls (slowest {:.1} ms)\n",
                total.as_secs_f64(),
                slowest.as_secs_f64() * 1e3
            );
        }
        if !self.failures.is_empty() {
            // RAW_REFERENCE_FAILURES=all lists every failed check.
            let all = std::env::var("RAW_REFERENCE_FAILURES").is_ok_and(|v| v == "all");
            let shown = if all { self.failures.len() } else { 40 };
            out += &format!(
                "{} failed checks; the first {shown} (RAW_REFERENCE_FAILURES=all for every one):\n",
                self.failures.len()
            );
            for f in self.failures.iter().take(shown) {
                out += "  ";
                out += f;
                out += "\n";
            }
        }
        eprintln!("{out}");
        assert!(
            self.failures.is_empty(),
            "{title}: {} failed checks (summary above)",
            self.failures.len()
        );
    }
}

/// One evaluation may take this long before it is reported as a failure ("timed out") and the
/// suite moves on; the evaluation's thread is left running (a core stays busy until the test
/// binary exits), so that a hang costs one failed check rather than the whole summary.
pub const EVALUATION_TIMEOUT: Duration = Duration::from_secs(30);

/// Runs `f` on its own thread, turning a panic into an error message and giving up after
/// [`EVALUATION_TIMEOUT`].
pub fn guarded<T: Send + 'static>(
    f: impl FnOnce() -> Result<T, QualityError> + Send + 'static,
) -> Result<T, String> {
    let (send, receive) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let outcome = match catch_unwind(AssertUnwindSafe(f)) {
            Ok(Ok(v)) => Ok(v),
            Ok(Err(e)) => Err(e.to_string()),
            Err(p) => Err(format!(
                "panicked: {}",
                p.downcast_ref::<String>()
                    .cloned()
                    .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default()
            )),
        };
        let _ = send.send(outcome);
    });
    receive
        .recv_timeout(EVALUATION_TIMEOUT)
        .unwrap_or_else(|_| Err(format!("timed out after {EVALUATION_TIMEOUT:?}")))
}

/// Evaluates `metric` by `method` (a fresh evaluator: a panic cannot poison a reused one).
pub fn evaluate(metric: Metric, method: Method, grasp: &Grasp) -> Result<Evaluation, String> {
    let grasp = grasp.clone();
    guarded(move || Evaluator::new(metric, method, None)?.evaluate(&grasp))
}

// ---------------------------------------------------------------------------------------------
// Shared families and checks (the library tests and the CLI tests)

/// A seed from parts.
pub fn seed(parts: &[u64]) -> u64 {
    parts.iter().fold(0x51_7cc1_b727_220a_u64, |h, p| {
        (h ^ p).wrapping_mul(0x9e37_79b9_7f4a_7c15)
    })
}

pub fn random_unit(rng: &mut Rng) -> [f64; 3] {
    unit3(rng)
}

/// Reference Q1 targets of the near-boundary grasps, times the scale. The last is a boundary
/// grasp (0 < Q < ε·scale): not force closure although the origin is inside.
pub const TARGETS: [f64; 5] = [1e-9, -1e-9, 1e-11, -1e-11, 5e-13];

/// A seeded force-closure grasp to push to the boundary: 3 or 4 contacts, k = 6 (even, so that
/// the hull grows with μ), force closure at μ = 1 by a margin.
pub fn base_grasp(index: u64) -> Grasp {
    for attempt in 0.. {
        let mut rng = Rng::new(seed(&[8, index, attempt]));
        let shape = Shape::ALL[index as usize % 3];
        let m = 3 + rng.index(2);
        let friction = FrictionModel::try_new(1.0, 6).expect("friction");
        let g = random_grasp(&mut rng, shape, m, friction);
        if rough_q1(&g) > 0.02 {
            return g;
        }
    }
    unreachable!()
}

/// A force-closure grasp (3 or 4 contacts, k = 6, μ = 0.5) and a line along which moving its
/// contact 0 by `s` leaves it clearly not force closure (Q1 < −1e-8·scale).
pub fn moving_contact(index: u64) -> (Grasp, [f64; 3], f64) {
    for attempt in 0.. {
        let mut rng = Rng::new(seed(&[9, index, attempt]));
        let shape = Shape::ALL[index as usize % 3];
        let m = 3 + rng.index(2);
        let friction = FrictionModel::try_new(0.5, 6).expect("friction");
        let base = random_grasp(&mut rng, shape, m, friction);
        if rough_q1(&base) <= 1e-6 {
            continue;
        }
        for _ in 0..8 {
            let v = unit3(&mut rng);
            for step in 1..=15 {
                let s = 0.1 * step as f64;
                if rough_q1(&with_contact_moved(&base, 0, v, s)) < -1e-8 {
                    return (base, v, s);
                }
            }
        }
    }
    unreachable!()
}

/// Near-boundary grasps from base grasp `index`, one per target of [`TARGETS`]: (case, grasp,
/// reference Q1). Indices below 8 bisect μ in [0, 1] (μ = 0: at most four wrenches, never force
/// closure); the others move contact 0 along a line, from its place (force closure) to where the
/// grasp no longer is.
pub fn near_boundary_family(index: u64) -> Vec<(String, Grasp, HullReference)> {
    let (what, make, open_end, closed_end): (String, Box<dyn Fn(f64) -> Grasp>, f64, f64) =
        if index < 8 {
            let b = base_grasp(index);
            (
                "μ".into(),
                Box::new(move |mu| with_friction(&b, mu)),
                0.0,
                1.0,
            )
        } else {
            let (b, v, s) = moving_contact(index);
            (
                format!("contact 0 moved along {v:.3?} by t·{s:.2}"),
                Box::new(move |t| with_contact_moved(&b, 0, v, t * s)),
                1.0,
                0.0,
            )
        };
    let mut seen: Vec<(f64, f64)> = [open_end, closed_end]
        .iter()
        .map(|&p| (p, rough_q1(&make(p))))
        .collect();
    TARGETS
        .iter()
        .map(|&target| {
            let (parameter, r) = bisect(&make, target, &mut seen).unwrap_or_else(|| {
                panic!("grasp {index} ({what}): no parameter reaches {target:e}·scale")
            });
            (
                format!(
                    "near-boundary #{index} ({what}, parameter {parameter}) at {:+.2e}·scale",
                    r.value / r.scale
                ),
                make(parameter),
                r,
            )
        })
        .collect()
}

/// A grasp as `pqh grasp` takes it (every field, tangents and torque frame included).
pub fn grasp_to_json(grasp: &Grasp) -> serde_json::Value {
    let contacts: Vec<serde_json::Value> = grasp
        .contacts()
        .iter()
        .map(|c| {
            serde_json::json!({
                "position": c.position(),
                "normal": c.normal(),
                "tangent": c.tangent(),
            })
        })
        .collect();
    serde_json::json!({
        "contacts": contacts,
        "friction": grasp.friction().friction(),
        "cone_edges": grasp.friction().cone_edges(),
        "torque_reference": grasp.torque_reference(),
        "torque_scale": grasp.torque_scale(),
    })
}

/// The grasp of a JSON object, built as `pqh grasp` builds it (`Contact::try_new` on the parsed
/// numbers; tangent, torque reference and scale optional).
pub fn grasp_from_json(v: &serde_json::Value) -> Grasp {
    let vec3 = |v: &serde_json::Value| -> [f64; 3] {
        std::array::from_fn(|a| v[a].as_f64().expect("number"))
    };
    let contacts = v["contacts"]
        .as_array()
        .expect("contacts")
        .iter()
        .map(|c| {
            let tangent = c.get("tangent").map(vec3);
            Contact::try_new(vec3(&c["position"]), vec3(&c["normal"]), tangent).expect("contact")
        })
        .collect();
    let friction = FrictionModel::try_new(
        v["friction"].as_f64().expect("friction"),
        v["cone_edges"].as_u64().expect("cone_edges") as usize,
    )
    .expect("friction model");
    let mut builder = Grasp::builder(contacts, friction);
    if let Some(c) = v.get("torque_reference") {
        builder = builder.torque_reference(vec3(c));
    }
    if let Some(rho) = v.get("torque_scale") {
        builder = builder.torque_scale(rho.as_f64().expect("torque_scale"));
    }
    builder.build().expect("grasp")
}

/// The path of tests/data/near-boundary-cylinder-grasp.json (a copy of
/// `../shared/cases/near-boundary-cylinder-grasp.json`).
pub fn cylinder_case_path() -> String {
    super::data_file("near-boundary-cylinder-grasp.json")
}

/// The grasp of [`cylinder_case_path`].
pub fn cylinder_case() -> Grasp {
    let text = std::fs::read_to_string(cylinder_case_path()).expect("read the case file");
    grasp_from_json(&serde_json::from_str(&text).expect("JSON"))
}

/// The raw wrenches are `Grasp::wrenches()`, and those follow the documented formula.
pub fn check_formula(report: &mut Report, case: &str, grasp: &Grasp) {
    let (error, identical) = wrench_formula_error(grasp);
    let t = report.tally("wrench formula (vs rounding bound)");
    t.values += 1;
    t.absolute.push(error);
    if !identical {
        t.skipped += 1; // counted here: agree to rounding, not bit for bit
    }
    if error > 1.0 {
        t.value_failures += 1;
        report.failures.push(format!(
            "wrench formula {case}: Grasp::wrenches() is {error:.2} rounding bounds away from \
             the documented formula"
        ));
    }
}

/// The expected verdict of a grasp: never force closure when degenerate; otherwise the
/// reference's (None within 1e-13·scale of ε·scale).
pub fn expected_for(reference: &HullReference, degenerate: bool) -> (Option<bool>, String) {
    if degenerate {
        (Some(false), "physically degenerate".to_string())
    } else {
        (
            reference.expected_verdict(),
            format!("reference {:e}·scale", reference.value / reference.scale),
        )
    }
}

/// One Q1 or Q∞ answer against its reference: value and verdict.
pub fn judge(
    report: &mut Report,
    key: &str,
    case: &str,
    force_closure: bool,
    value: f64,
    reference: &HullReference,
    degenerate: bool,
) {
    report.value(key, case, value, reference.value, reference.scale);
    let (expected, why) = expected_for(reference, degenerate);
    report.verdict(key, case, force_closure, expected, &why);
}

/// Q1 by Partial and Full against `reference` (of `grasp.wrenches()`).
pub fn check_q1(
    report: &mut Report,
    case: &str,
    grasp: &Grasp,
    reference: &HullReference,
    degenerate: bool,
) {
    for method in [Method::Partial, Method::Full] {
        let key = format!("Q1 {method:?}");
        match report.time(&key, || evaluate(Metric::Q1, method, grasp)) {
            Err(e) => report.error(&key, case, &e),
            Ok(q) => judge(
                report,
                &key,
                case,
                q.force_closure,
                q.value.expect("Q1 has a value"),
                reference,
                degenerate,
            ),
        }
    }
}

/// Q∞ by Full only up to this many Minkowski points (it materialises them; today's full method
/// takes 3–5 s on 216–343 points, 50 ms on 144).
pub const FULL_QINF_LIMIT: usize = 400;

/// The Q∞ reference of one variant: (Minkowski points, reference), or None when the sum has
/// more than [`MINKOWSKI_REFERENCE_LIMIT`] points and no shortcut applies.
///
/// Shortcut, with the zero wrench: the origin is itself a point of the sum (the all-zero tuple).
/// When the union of the raw wrenches is at a distance δ > 1e-11·scale from the origin, a
/// direction u with u·w ≥ δ for every raw wrench makes u·s > 0 for every other float-summed
/// point s (rounding of m-term sums is ~1e-16·scale ≪ δ), so the origin is a vertex of the sum's
/// hull and the exact value is 0.
pub fn qinf_reference(grasp: &Grasp, with_zero: bool) -> Option<(usize, HullReference)> {
    let scale = minkowski_scale(grasp);
    let k = grasp.friction().cone_edges() + usize::from(with_zero);
    let count = k
        .checked_pow(grasp.contact_count() as u32)
        .unwrap_or(usize::MAX);
    if with_zero {
        let w = grasp.wrenches();
        let (distance, gap) = wolfe(&w);
        if distance > CLEARLY_OUTSIDE * union_scale(&w) {
            let reference = HullReference {
                value: 0.0,
                scale,
                inside: false,
                qhull_value: None,
                wolfe_distance: 0.0,
                wolfe_gap: gap,
                exact_planes: 0,
                hull: None,
                qhull_error: None,
            };
            return Some((count, reference));
        }
    }
    minkowski_points(grasp, with_zero, MINKOWSKI_REFERENCE_LIMIT)
        .map(|points| (points.len(), hull_reference(&points, scale)))
}

/// Q∞ (one variant) by Partial, and by Full when asked and the sum is small, against the
/// materialised sum.
/// Without a reference (sum too large) only a degenerate grasp's verdict is checked.
pub fn check_qinf(
    report: &mut Report,
    case: &str,
    grasp: &Grasp,
    with_zero: bool,
    degenerate: bool,
    full: bool,
) {
    let variant = if with_zero { "Qinf+0" } else { "Qinf" };
    let reference = report.time(&format!("reference {variant}"), || {
        qinf_reference(grasp, with_zero)
    });
    let mut methods = vec![Method::Partial];
    if full
        && reference
            .as_ref()
            .is_some_and(|(n, _)| *n <= FULL_QINF_LIMIT)
    {
        methods.push(Method::Full);
    }
    let metric = Metric::QInf {
        with_zero_wrench: with_zero,
    };
    for method in methods {
        let key = format!("{variant} {method:?}");
        match report.time(&key, || evaluate(metric, method, grasp)) {
            Err(e) => report.error(&key, case, &e),
            Ok(q) => match &reference {
                Some((_, r)) => {
                    let value = q.value.expect("Q∞ has a value");
                    judge(report, &key, case, q.force_closure, value, r, degenerate)
                }
                None => {
                    let expected = degenerate.then_some(false);
                    let why = "physically degenerate";
                    report.verdict(&key, case, q.force_closure, expected, why);
                }
            },
        }
    }
}

/// The Q_OWS reference value when the reference says force closure.
pub fn ows_reference_for(
    grasp: &Grasp,
    q1: &HullReference,
    disturbances: &[[f64; 6]],
    degenerate: bool,
) -> Option<f64> {
    let (expected, _) = expected_for(q1, degenerate);
    match (expected, &q1.hull) {
        (Some(true), Some(hull)) if q1.inside => {
            Some(ows_reference(&grasp.wrenches(), hull, disturbances).0)
        }
        _ => None,
    }
}

/// One Q_OWS answer: the verdict of Q1; a value exactly when force closure, within 1e-12 of the
/// reference (not for the ellipsoid method, an approximation: verdict only).
#[allow(clippy::too_many_arguments)]
pub fn judge_ows(
    report: &mut Report,
    key: &str,
    case: &str,
    force_closure: bool,
    value: Option<f64>,
    q1: &HullReference,
    degenerate: bool,
    reference: Option<f64>,
    ellipsoid: bool,
) {
    let (expected, why) = expected_for(q1, degenerate);
    report.verdict(key, case, force_closure, expected, &why);
    if ellipsoid {
        return;
    }
    if force_closure != value.is_some() {
        report.failures.push(format!(
            "{key} {case}: value {value:?} with force_closure {force_closure}"
        ));
    }
    if let (Some(got), Some(r)) = (value, reference) {
        report.value(key, case, got, r, 0.0);
    }
}

/// Q_OWS by Partial and BruteForce (verdict and value) and Ellipsoid (verdict only).
pub fn check_ows(
    report: &mut Report,
    case: &str,
    grasp: &Grasp,
    disturbances: &[[f64; 6]],
    q1: &HullReference,
    degenerate: bool,
) {
    use pqhull::grasp::ows::ObjectWrenchSpace;
    let space = ObjectWrenchSpace::from_disturbances(disturbances.to_vec()).expect("space");
    let reference = report.time("reference OWS", || {
        ows_reference_for(grasp, q1, disturbances, degenerate)
    });
    for method in [Method::Partial, Method::Full, Method::Ellipsoid] {
        let key = format!("OWS {method:?}");
        let result = report.time(&key, || {
            let (grasp, space) = (grasp.clone(), space.clone());
            guarded(move || Evaluator::new(Metric::Ows, method, Some(&space))?.evaluate(&grasp))
        });
        match result {
            Err(e) if method == Method::Ellipsoid => report.soft_error(&key, case, &e),
            Err(e) => report.error(&key, case, &e),
            Ok(q) => judge_ows(
                report,
                &key,
                case,
                q.force_closure,
                q.value,
                q1,
                degenerate,
                reference,
                method == Method::Ellipsoid,
            ),
        }
    }
}

/// A summary line on the references themselves.
pub fn note_references(report: &mut Report, what: &str, refs: &[HullReference]) {
    let inside = refs.iter().filter(|r| r.inside).count();
    let moved = refs
        .iter()
        .filter_map(|r| r.qhull_value.map(|q| (q - r.value).abs() / r.scale))
        .fold(0.0, f64::max);
    let gap = refs
        .iter()
        .filter(|r| r.wolfe_distance > 1e-12 * r.scale)
        .map(|r| r.wolfe_gap / r.scale)
        .fold(0.0, f64::max);
    let flat = refs.iter().filter(|r| r.qhull_error.is_some()).count();
    let untrusted = refs.iter().filter(|r| !r.trusted()).count();
    let fc = refs
        .iter()
        .filter(|r| r.value >= FORCE_CLOSURE_EPSILON * r.scale)
        .count();
    let exact = refs.iter().map(|r| r.exact_planes).sum::<usize>();
    report.note(format!(
        "{what}: {} references ({fc} ≥ ε·scale, {inside} inside by Qhull, {flat} without a Qhull \
         hull, {untrusted} within 1e-13·scale of 0); {exact} facet planes re-derived exactly, \
         moving Qhull's value by ≤ {moved:.1e}·scale; Wolfe's duality gap (origin outside) ≤ \
         {gap:.1e}·scale",
        refs.len()
    ));
}

// ---------------------------------------------------------------------------------------------
// Physically degenerate grasps

/// A contact with a random normal and (half the time) a random tangent.
pub fn any_contact(rng: &mut Rng, p: [f64; 3]) -> Contact {
    let n = random_unit(rng);
    let t = (rng.uniform() < 0.5).then(|| random_unit(rng));
    Contact::try_new(p, n, t)
        .or_else(|_| Contact::try_new(p, n, None))
        .expect("valid")
}

/// A dyadic number with few bits: sums and products of a few of them are exact in f64.
pub fn dyadic(rng: &mut Rng, range: f64) -> f64 {
    (rng.uniform_in(-range, range) * 1024.0).round() / 1024.0
}

pub fn build(contacts: Vec<Contact>, friction: FrictionModel, rng: &mut Rng, exact: bool) -> Grasp {
    let (c, rho) = if exact {
        ([dyadic(rng, 0.1), dyadic(rng, 0.1), dyadic(rng, 0.1)], 0.5)
    } else {
        (
            [
                rng.uniform_in(-0.1, 0.1),
                rng.uniform_in(-0.1, 0.1),
                rng.uniform_in(-0.1, 0.1),
            ],
            rng.uniform_in(0.2, 1.0),
        )
    };
    Grasp::builder(contacts, friction)
        .torque_reference(c)
        .torque_scale(rho)
        .build()
        .expect("valid")
}

/// The degenerate families: (family name, grasp).
pub fn degenerate_grasps() -> Vec<(String, Grasp)> {
    let mut out = Vec::new();
    let friction = |rng: &mut Rng| {
        FrictionModel::try_new(rng.uniform_in(0.2, 1.0), 6 + rng.index(7)).expect("valid")
    };
    // Two contacts on a shape.
    for (s, shape) in Shape::ALL.into_iter().enumerate() {
        for i in 0..30 {
            let mut rng = Rng::new(seed(&[3, s as u64, i]));
            let fm = friction(&mut rng);
            out.push((
                format!("two contacts on a {} #{i}", shape.name()),
                random_grasp(&mut rng, shape, 2, fm),
            ));
        }
    }
    // Two antipodal contacts: the chord between them along both normals.
    for i in 0..60 {
        let mut rng = Rng::new(seed(&[4, i]));
        let fm = friction(&mut rng);
        let (p, q, n) = match i % 3 {
            0 => {
                // Sphere.
                let u = random_unit(&mut rng);
                let r = rng.uniform_in(0.05, 0.5);
                (u.map(|x| r * x), u.map(|x| -r * x), u.map(|x| -x))
            }
            1 => {
                // Box: a point on face −h_a and the one opposite.
                let axis = rng.index(3);
                let h = rng.uniform_in(0.05, 0.5);
                let mut p: [f64; 3] = std::array::from_fn(|_| rng.uniform_in(-0.3, 0.3));
                p[axis] = -h;
                let mut q = p;
                q[axis] = h;
                let mut n = [0.0; 3];
                n[axis] = 1.0;
                (p, q, n)
            }
            _ => {
                // Cylinder side: across the axis at one height.
                let phi = rng.uniform_in(0.0, 2.0 * std::f64::consts::PI);
                let (r, z) = (rng.uniform_in(0.02, 0.5), rng.uniform_in(-0.3, 0.3));
                let u = [phi.cos(), phi.sin(), 0.0];
                (
                    [r * u[0], r * u[1], z],
                    [-r * u[0], -r * u[1], z],
                    u.map(|x| -x),
                )
            }
        };
        let t = (rng.uniform() < 0.5).then(|| random_unit(&mut rng));
        let a = Contact::try_new(p, n, t)
            .unwrap_or_else(|_| Contact::try_new(p, n, None).expect("valid"));
        let b = Contact::try_new(q, n.map(|x| -x), None).expect("valid");
        let g = build(vec![a, b], fm, &mut rng, false);
        out.push((format!("two antipodal contacts #{i}"), g));
    }
    // 3–5 contacts on one line, random normals: exactly collinear dyadic points (with a dyadic
    // torque frame), and points computed in floating point (collinear to rounding).
    for i in 0..120 {
        let mut rng = Rng::new(seed(&[5, i]));
        let fm = friction(&mut rng);
        let m = 3 + rng.index(3);
        let exact = i % 2 == 0;
        let (p0, v) = if exact {
            (
                [
                    dyadic(&mut rng, 0.3),
                    dyadic(&mut rng, 0.3),
                    dyadic(&mut rng, 0.3),
                ],
                [
                    dyadic(&mut rng, 1.0),
                    dyadic(&mut rng, 1.0),
                    dyadic(&mut rng, 1.0),
                ],
            )
        } else {
            let p0 = [
                rng.uniform_in(-0.3, 0.3),
                rng.uniform_in(-0.3, 0.3),
                rng.uniform_in(-0.3, 0.3),
            ];
            (p0, random_unit(&mut rng))
        };
        let contacts = (0..m)
            .map(|_| {
                let s = if exact {
                    dyadic(&mut rng, 0.5)
                } else {
                    rng.uniform_in(-0.5, 0.5)
                };
                let p = std::array::from_fn(|a| p0[a] + s * v[a]);
                any_contact(&mut rng, p)
            })
            .collect();
        let what = if exact { "exactly" } else { "to rounding" };
        out.push((
            format!("{m} contacts on a line ({what}) #{i}"),
            build(contacts, fm, &mut rng, exact),
        ));
    }
    // Coinciding contact points: all at one point, or at two.
    for i in 0..80 {
        let mut rng = Rng::new(seed(&[6, i]));
        let fm = friction(&mut rng);
        let m = 2 + rng.index(4);
        let points: Vec<[f64; 3]> = (0..1 + i as usize % 2)
            .map(|_| std::array::from_fn(|_| rng.uniform_in(-0.3, 0.3)))
            .collect();
        let contacts = (0..m)
            .map(|j| any_contact(&mut rng, points[j % points.len()]))
            .collect();
        out.push((
            format!("{m} contacts at {} point(s) #{i}", points.len()),
            build(contacts, fm, &mut rng, false),
        ));
    }
    out
}
