//! The point of a convex hull nearest a query point: Wolfe's minimum-norm-point algorithm.
//!
//! P. Wolfe, "Finding the nearest point in a polytope", Mathematical Programming 11 (1976)
//! 128–149. It keeps a "corral" of at most D + 1 affinely independent points and the current
//! point `x` in their convex hull; a major cycle adds the point that most violates the optimality
//! test `(p − x)·(q − x) ≤ 0`, minor cycles move to the nearest point of the corral's affine hull
//! (or toward it until a weight vanishes, dropping that point). It works on any number of points
//! — a partial hull's vertices, or a wrench set too degenerate to have a hull — in a handful of
//! iterations, and allocates nothing. Floating point: the result is accurate to about 1e−13
//! relative to the size of the point set on well-conditioned input; callers that need a
//! certificate check the supporting hyperplane themselves.
//!
//! [`min_norm_point_accurate`] runs the same iterations with the residual `x − q` kept accurate:
//! `p − q` and the corral's edges are split exactly into two doubles, the point of the affine
//! hull is summed in double-double, and the least-squares problem for it (a QR factorisation
//! instead of the normal equations, so that clustered corrals stay solvable) is refined against
//! that residual. Its distance is then accurate relative to itself, not to the size of the point
//! set — what a query within rounding of the hull needs (plain Wolfe only knows such a distance
//! to about 1e−16 of the set's size, so its direction `q − x`, and every decision taken from it,
//! are noise). A corral made numerically dependent by the entering point (a cluster) has the
//! entering point swapped in for one of the others when that gets strictly nearer.

use super::vector::dot;

mod exact;
pub use exact::min_norm_point_exact;

/// Optimality tolerance: stop when `|x|² − min_j x·p_j ≤ TOL·M·|x|` (`M` = largest `|p_j − q|`).
const TOL: f64 = 1e-14;

/// Relative pivot size below which a corral is taken as affinely dependent.
const SINGULAR: f64 = 1e-13;

/// Optimality tolerance of [`min_norm_point_accurate`]: its residual is accurate to a few ulps, so
/// the test is limited only by the rounding of the dot products `x·(p_j − q)` (about D ulps of
/// `|x|·M`). A point beyond the optimality plane by less than `TOL_ACCURATE·M` changes the distance
/// by a second-order amount unless it is that close to `x` too.
const TOL_ACCURATE: f64 = 1e-15;

/// Relative length (to the longest edge) below which an edge of a corral, orthogonalised against
/// the others, is taken as affinely dependent in [`min_norm_point_accurate`]: its refinement
/// converges while this times 1/ε stays well below 1.
const SINGULAR_QR: f64 = 1e-14;

/// The nearest point and the (at most D + 1) input points whose convex hull holds it.
#[derive(Clone, Copy, Debug)]
pub struct Nearest<const D: usize> {
    /// The nearest point.
    pub point: [f64; D],
    /// `point − query`, computed before adding the query back (so accurate even when it is tiny).
    pub offset: [f64; D],
    /// Its distance from the query.
    pub distance: f64,
    support: [usize; 9],
    support_len: usize,
}

impl<const D: usize> Nearest<D> {
    /// Indices (into the caller's point numbering) of the points spanning the nearest face.
    pub fn support(&self) -> &[usize] {
        &self.support[..self.support_len]
    }
}

/// The point of `conv{point(0), …, point(count − 1)}` nearest `query`.
///
/// # Panics
/// If `count == 0`.
pub fn min_norm_point<const D: usize>(
    count: usize,
    point: impl Fn(usize) -> [f64; D],
    query: &[f64; D],
) -> Nearest<D> {
    wolfe::<D, false>(count, point, query, &[])
}

/// [`min_norm_point`] with an accurate residual (see the module documentation), started from the
/// corral `start` (indices of affinely independent points, such as the support of a plain
/// [`min_norm_point`] run) when its affine minimiser lies inside it, else from the nearest point.
///
/// The distance is accurate to about 1e−15 relative to itself plus 1e−30 of the point set's size
/// times the corral's condition, for corrals whose edges, orthogonalised against each other, keep
/// more than 1e−14 of the longest one's length (others count as dependent).
///
/// A query farther from the points than [`FAR`] times their extent is handed to
/// [`min_norm_point_exact`]: there the differences that decide the nearest face are below the
/// rounding of anything measured from the query.
///
/// # Panics
/// If `count == 0` or an index of `start` is `count` or more.
pub fn min_norm_point_accurate<const D: usize>(
    count: usize,
    point: impl Fn(usize) -> [f64; D],
    query: &[f64; D],
    start: &[usize],
) -> Nearest<D> {
    if is_far(count, &point, query) {
        return min_norm_point_exact(count, point, query, start);
    }
    wolfe::<D, true>(count, point, query, start)
}

/// A query is *far* from a point set when its largest coordinate difference from the first point
/// exceeds `FAR` times the set's extent (the largest coordinate difference of a point from the
/// first). Beyond it, floating-point Wolfe decides between faces on differences of relative size
/// below extent/distance, and places the nearest point only to an ulp of the query's distance
/// (`2^10` ulps of the set's size here); [`min_norm_point_exact`] is exact there.
pub const FAR: f64 = 1024.0;

/// Whether `query` is [`FAR`] from the points.
fn is_far<const D: usize>(
    count: usize,
    point: &impl Fn(usize) -> [f64; D],
    query: &[f64; D],
) -> bool {
    if count == 0 {
        return false;
    }
    let first = point(0);
    let spread = |p: &[f64; D]| (0..D).fold(0.0f64, |m, c| m.max((p[c] - first[c]).abs()));
    let extent = (1..count).fold(0.0f64, |m, i| m.max(spread(&point(i))));
    spread(query) > FAR * extent
}

/// Coordinates (of the points and the query together) whose largest magnitude lies outside
/// [2^−`SQUARE_SAFE`, 2^`SQUARE_SAFE`] are first brought to [0.5, 1) by a power of two: squared
/// distances of larger ones overflow (a query at 1e155 from a unit hull gave −∞), and of smaller
/// ones underflow. 2^400 leaves room for D ≤ 8 squares and their sums.
const SQUARE_SAFE: i32 = 400;

/// Wolfe's algorithm; `ACCURATE` selects the double-double residual (and `start`, which the plain
/// variant ignores). Works in units of a power of two when the coordinates are huge or tiny (see
/// [`SQUARE_SAFE`]): an exact change of units, except that coordinates below 2^−1022 of the
/// largest lose low bits, far below the result's rounding.
fn wolfe<const D: usize, const ACCURATE: bool>(
    count: usize,
    point: impl Fn(usize) -> [f64; D],
    query: &[f64; D],
    start: &[usize],
) -> Nearest<D> {
    assert!(count > 0, "min_norm_point: no points");
    let magnitude = |p: &[f64; D]| p.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let largest = (0..count).fold(magnitude(query), |m, i| m.max(magnitude(&point(i))));
    let safe = 2f64.powi(SQUARE_SAFE);
    if largest <= safe && (largest >= 1.0 / safe || largest == 0.0) || !largest.is_finite() {
        return wolfe_in_range::<D, ACCURATE>(count, point, query, start);
    }
    // 2^e ≤ largest < 2^(e+1): divide by 2^(e+1), in two factors so neither over- nor underflows
    // (as `rescaled`).
    let e = power_of_two_below(largest).log2() as i32 + 1;
    // Each factor alone may overflow (2^1024 for a query near f64::MAX): applied in two steps.
    let (down, up) = (
        (2f64.powi(-e / 2), 2f64.powi(-e - (-e / 2))),
        (2f64.powi(e / 2), 2f64.powi(e - e / 2)),
    );
    let scaled = |p: [f64; D]| p.map(|x| x * down.0 * down.1);
    let mut nearest =
        wolfe_in_range::<D, ACCURATE>(count, |i| scaled(point(i)), &scaled(*query), start);
    nearest.point = nearest.point.map(|x| x * up.0 * up.1);
    nearest.offset = nearest.offset.map(|x| x * up.0 * up.1);
    nearest.distance = nearest.distance * up.0 * up.1;
    nearest
}

/// [`wolfe`] on coordinates whose squares neither overflow nor underflow.
fn wolfe_in_range<const D: usize, const ACCURATE: bool>(
    count: usize,
    point: impl Fn(usize) -> [f64; D],
    query: &[f64; D],
    start: &[usize],
) -> Nearest<D> {
    let mut largest = 0.0f64;
    let mut first = (f64::INFINITY, 0);
    for i in 0..count {
        let p = point(i);
        let r: [f64; D] = std::array::from_fn(|c| p[c] - query[c]);
        let n2 = dot(r, r);
        largest = largest.max(n2);
        if n2 < first.0 {
            first = (n2, i);
        }
    }
    let largest = largest.sqrt();
    // The accurate variant works in units of a power of two near the set's size (an exact change
    // of units), so that squares of tiny residuals neither underflow nor lose their low bits.
    let unit = if ACCURATE {
        power_of_two_below(largest)
    } else {
        1.0
    };
    let largest = largest / unit;
    // Points relative to the query, which becomes the origin: `p − q = hi + lo` exactly in the
    // accurate variant (two_sum), `hi` alone (rounded) in the plain one.
    let rel = |i: usize| -> ([f64; D], [f64; D]) {
        let p = point(i);
        let mut hi = [0.0; D];
        let mut lo = [0.0; D];
        for c in 0..D {
            if ACCURATE {
                let (s, e) = two_sum(p[c], -query[c]);
                hi[c] = s / unit;
                lo[c] = e / unit;
            } else {
                hi[c] = p[c] - query[c];
            }
        }
        (hi, lo)
    };
    let mut corral = [0usize; 9];
    let mut cp = [[0.0; D]; 9]; // corral points, relative (high parts)
    let mut cl = [[0.0; D]; 9]; // their low parts (accurate variant)
    let mut weights = [0.0; 9];
    let mut len = 0;
    let mut x = [0.0; D];
    if ACCURATE && (2..=D + 1).contains(&start.len()) {
        for (slot, &i) in start.iter().enumerate() {
            corral[slot] = i;
            (cp[slot], cl[slot]) = rel(i);
        }
        if let Some((alpha, at)) = affine_minimiser_accurate(&cp[..start.len()], &cl[..start.len()])
            && alpha[..start.len()].iter().all(|&a| a > 0.0)
        {
            len = start.len();
            weights = alpha;
            x = at;
        }
    }
    if len == 0 {
        len = 1;
        corral[0] = first.1;
        (cp[0], cl[0]) = rel(first.1);
        weights[0] = 1.0;
        x = cp[0];
    }
    let tolerance = if ACCURATE { TOL_ACCURATE } else { TOL };

    for _ in 0..100 * (count + D + 1) {
        let xx = dot(x, x);
        if xx == 0.0 {
            break;
        }
        let (j, xpj) = (0..count)
            .map(|j| {
                let (hi, lo) = rel(j);
                (
                    j,
                    if ACCURATE {
                        dot(x, hi) + dot(x, lo)
                    } else {
                        dot(x, hi)
                    },
                )
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .expect("count > 0");
        if xx - xpj <= tolerance * largest * xx.sqrt() || corral[..len].contains(&j) || len > D {
            break;
        }
        let before = x;
        corral[len] = j;
        (cp[len], cl[len]) = rel(j);
        weights[len] = 0.0;
        len += 1;
        let mut entering = true;
        loop {
            let minimiser = if ACCURATE {
                affine_minimiser_accurate(&cp[..len], &cl[..len])
            } else {
                affine_minimiser(&cp[..len]).map(|alpha| (alpha, [0.0; D]))
            };
            let Some((alpha, at)) = minimiser else {
                len -= 1;
                if ACCURATE
                    && entering
                    && let Some((slot, alpha, at)) = swap(&cp[..=len], &cl[..=len], xx)
                {
                    // The entering point takes the place of one it nearly coincides with (a
                    // cluster): stopping here would leave the distance off by up to the
                    // cluster's spread.
                    corral[slot] = corral[len];
                    cp[slot] = cp[len];
                    cl[slot] = cl[len];
                    weights = alpha;
                    x = at;
                    break;
                }
                // Numerically dependent corral: keep the last good point.
                return finish(query, x, corral, len, unit);
            };
            entering = false;
            if alpha[..len].iter().all(|&a| a > 0.0) {
                weights = alpha;
                x = if ACCURATE {
                    at
                } else {
                    combination(&cp[..len], &weights)
                };
                break;
            }
            // Walk from the weights toward alpha until the first one reaches zero.
            let mut theta = 1.0f64;
            let mut hit = 0;
            for i in 0..len {
                let (l, a) = (weights[i], alpha[i]);
                if a <= 0.0 {
                    let t = if l - a > 0.0 { l / (l - a) } else { 0.0 };
                    if t < theta {
                        theta = t;
                        hit = i;
                    }
                }
            }
            for i in 0..len {
                weights[i] = (1.0 - theta) * weights[i] + theta * alpha[i];
            }
            weights[hit] = 0.0;
            let mut kept = 0;
            for i in 0..len {
                if weights[i] > 0.0 {
                    corral[kept] = corral[i];
                    cp[kept] = cp[i];
                    cl[kept] = cl[i];
                    weights[kept] = weights[i];
                    kept += 1;
                }
            }
            len = kept;
            let total: f64 = weights[..len].iter().sum();
            weights[..len].iter_mut().for_each(|w| *w /= total);
            x = if ACCURATE {
                affine_point(
                    &cp[..len],
                    &cl[..len],
                    &weights[1..len],
                    &[0.0; 8][..len - 1],
                )
            } else {
                combination(&cp[..len], &weights)
            };
            if len == 1 {
                break;
            }
        }
        if x == before {
            // The new point was dropped at once: the next major cycle would pick it again.
            break;
        }
    }
    finish(query, x, corral, len, unit)
}

fn finish<const D: usize>(
    query: &[f64; D],
    x: [f64; D],
    support: [usize; 9],
    len: usize,
    unit: f64,
) -> Nearest<D> {
    let offset = x.map(|c| c * unit);
    Nearest {
        point: std::array::from_fn(|c| offset[c] + query[c]),
        offset,
        distance: dot(x, x).sqrt() * unit,
        support,
        support_len: len,
    }
}

/// The largest power of two not above `x` (1 for zero or non-finite `x`), built in two halves so
/// that neither factor overflows.
/// `v` divided by a power of two that brings its largest coordinate into [0.5, 1) (zero stays
/// zero): an exact change of length, after which dot products with it neither overflow nor
/// underflow where `v`'s own square would.
pub fn rescaled<const D: usize>(v: &[f64; D]) -> [f64; D] {
    let largest = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if largest == 0.0 || !largest.is_finite() {
        return *v;
    }
    let e = power_of_two_below(largest).log2() as i32 + 1;
    let down = (2f64.powi(-e / 2), 2f64.powi(-e - (-e / 2)));
    v.map(|x| x * down.0 * down.1)
}

fn power_of_two_below(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let e = x.log2().floor() as i32;
    let p = 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
    // log2 may round across a power of two.
    if p > x {
        p / 2.0
    } else if 2.0 * p <= x {
        2.0 * p
    } else {
        p
    }
}

/// `a + b = s + e` exactly (Knuth's TwoSum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `c_0 + Σ_{i≥1} μ_i·(c_i − c_0)` for the points `c_i = hi_i + lo_i` and the weights
/// `μ_i = mu_hi_i + mu_lo_i`, with the edges split exactly and the sum compensated
/// (double-double): accurate to a few ulps of the result plus about 1e−31 of the points' size,
/// however much the sum cancels. Any `μ` gives a point of the affine hull, so the first weight is
/// implicit.
fn affine_point<const D: usize>(
    hi: &[[f64; D]],
    lo: &[[f64; D]],
    mu_hi: &[f64],
    mu_lo: &[f64],
) -> [f64; D] {
    std::array::from_fn(|c| {
        let (mut s, mut t) = (hi[0][c], lo[0][c]);
        for (((h, l), &m), &m_lo) in hi[1..].iter().zip(&lo[1..]).zip(mu_hi).zip(mu_lo) {
            let (e, e_lo) = two_sum(h[c], -hi[0][c]);
            let e_lo = e_lo + (l[c] - lo[0][c]);
            let p = m * e;
            let p_lo = m.mul_add(e, -p) + (m * e_lo + m_lo * e);
            let (sum, err) = two_sum(s, p);
            s = sum;
            t += err + p_lo;
        }
        s + t
    })
}

/// Accurate variant of [`affine_minimiser`]: the weights and the point of the affine hull of the
/// points `hi + lo` nearest the origin, or `None` if the points are numerically dependent.
///
/// A least-squares problem `min |c_0 + E·β|` over the edges `E = (c_i − c_0)`, solved with a QR
/// factorisation of `E` (Gram–Schmidt twice) rather than the normal equations, whose condition
/// is the square of E's: a corral holding two points of a tight cluster (edges 1e−12 of the
/// others) is then still solvable. It is refined against the residual computed by
/// [`affine_point`] (iterative refinement with an extended-precision residual) until the
/// correction stops mattering, the weights kept as unevaluated sums of two doubles — a
/// correction below half an ulp of a weight still moves the point by up to an ulp of the
/// points' size, far more than the distance near the boundary.
fn affine_minimiser_accurate<const D: usize>(
    hi: &[[f64; D]],
    lo: &[[f64; D]],
) -> Option<([f64; 9], [f64; D])> {
    let k = hi.len() - 1;
    let mut q = [[0.0; D]; 8];
    let mut r = [[0.0; 8]; 8];
    let mut lengths = [0.0; 8];
    for i in 0..k {
        let edge: [f64; D] = std::array::from_fn(|c| hi[i + 1][c] - hi[0][c]);
        lengths[i] = dot(edge, edge).sqrt();
    }
    let longest = lengths[..k].iter().fold(0.0f64, |m, &l| m.max(l));
    for i in 0..k {
        let mut v: [f64; D] = std::array::from_fn(|c| hi[i + 1][c] - hi[0][c]);
        for _ in 0..2 {
            for j in 0..i {
                let c = dot(q[j], v);
                r[j][i] += c;
                for (vc, qc) in v.iter_mut().zip(&q[j]) {
                    *vc -= c * qc;
                }
            }
        }
        let norm = dot(v, v).sqrt();
        if norm.is_nan() || norm <= SINGULAR_QR * longest {
            return None;
        }
        r[i][i] = norm;
        q[i] = v.map(|x| x / norm);
    }
    let (mut beta, mut beta_lo) = ([0.0; 8], [0.0; 8]);
    let mut x = affine_point(hi, lo, &beta[..k], &beta_lo[..k]);
    let mut previous = f64::INFINITY;
    for _ in 0..12 {
        // δ minimising |x + E·δ|: R·δ = −Qᵀx.
        let mut delta = [0.0; 8];
        for i in (0..k).rev() {
            let tail: f64 = (i + 1..k).map(|j| r[i][j] * delta[j]).sum();
            delta[i] = (-dot(q[i], x) - tail) / r[i][i];
        }
        let moved: f64 = (0..k).map(|i| delta[i].abs() * lengths[i]).sum();
        if moved.is_nan() || moved >= previous {
            break; // no longer converging: keep the best point so far
        }
        previous = moved;
        for i in 0..k {
            (beta[i], beta_lo[i]) = two_sum(beta[i], beta_lo[i] + delta[i]);
        }
        x = affine_point(hi, lo, &beta[..k], &beta_lo[..k]);
        if moved <= 1e-32 * longest {
            break; // below the residual's own accuracy
        }
    }
    // The first weight, 1 − Σβ, compensated too: its sign decides whether the query is past the
    // face opposite the first point, which near the boundary is a matter of the last bits.
    let mut alpha = [0.0; 9];
    let (mut first, mut first_lo) = (1.0, 0.0);
    for i in 0..k {
        let (s, e) = two_sum(first, -beta[i]);
        first = s;
        first_lo += e - beta_lo[i];
        alpha[i + 1] = beta[i] + beta_lo[i];
    }
    alpha[0] = first + first_lo;
    Some((alpha, x))
}

/// For a corral whose last point (the entering one) is numerically in the affine hull of the
/// others: the best corral with the entering point in place of one of the others — the slot, the
/// weights and the point — among those whose affine minimiser lies strictly inside and is nearer
/// than `bound` (squared), if any. Strict improvement is what keeps Wolfe's iteration from
/// cycling.
fn swap<const D: usize>(
    hi: &[[f64; D]],
    lo: &[[f64; D]],
    bound: f64,
) -> Option<(usize, [f64; 9], [f64; D])> {
    let last = hi.len() - 1;
    let mut best: Option<(usize, [f64; 9], [f64; D], f64)> = None;
    for slot in 0..last {
        let (mut h, mut l) = ([[0.0; D]; 9], [[0.0; D]; 9]);
        h[..last].copy_from_slice(&hi[..last]);
        l[..last].copy_from_slice(&lo[..last]);
        h[slot] = hi[last];
        l[slot] = lo[last];
        if let Some((alpha, at)) = affine_minimiser_accurate(&h[..last], &l[..last])
            && alpha[..last].iter().all(|&a| a > 0.0)
        {
            let squared = dot(at, at);
            if squared < bound && best.is_none_or(|(_, _, _, b)| squared < b) {
                best = Some((slot, alpha, at, squared));
            }
        }
    }
    best.map(|(slot, alpha, at, _)| (slot, alpha, at))
}

fn combination<const D: usize>(points: &[[f64; D]], weights: &[f64; 9]) -> [f64; D] {
    let mut x = [0.0; D];
    for (p, &w) in points.iter().zip(weights) {
        for (xc, pc) in x.iter_mut().zip(p) {
            *xc += w * pc;
        }
    }
    x
}

/// The barycentric coordinates of the origin in the simplex on `points` (D + 1 affinely
/// independent points), by [`affine_minimiser`]; `None` when they are numerically dependent.
pub(crate) fn origin_weights<const D: usize>(points: &[[f64; D]]) -> Option<[f64; 9]> {
    (points.len() == D + 1)
        .then(|| affine_minimiser(points))
        .flatten()
}

/// Affine weights (summing to 1) of the point of the affine hull of `points` nearest the origin,
/// or `None` if the points are (numerically) affinely dependent. Normal equations on differences
/// from the first point, Gaussian elimination with partial pivoting, one refinement step.
fn affine_minimiser<const D: usize>(points: &[[f64; D]]) -> Option<[f64; 9]> {
    let base = points[0];
    let k = points.len() - 1;
    let mut edges = [[0.0; D]; 8];
    for (e, p) in edges.iter_mut().zip(&points[1..]) {
        *e = std::array::from_fn(|c| p[c] - base[c]);
    }
    let mut gram = [[0.0; 8]; 8];
    let mut rhs = [0.0; 8];
    for r in 0..k {
        for c in 0..k {
            gram[r][c] = dot(edges[r], edges[c]);
        }
        rhs[r] = -dot(edges[r], base);
    }
    let mut beta = solve(&gram, &rhs, k)?;
    let mut residual = [0.0; 8];
    for r in 0..k {
        residual[r] = rhs[r] - (0..k).map(|c| gram[r][c] * beta[c]).sum::<f64>();
    }
    if let Some(delta) = solve(&gram, &residual, k) {
        for r in 0..k {
            beta[r] += delta[r];
        }
    }
    let mut alpha = [0.0; 9];
    alpha[0] = 1.0 - beta[..k].iter().sum::<f64>();
    alpha[1..=k].copy_from_slice(&beta[..k]);
    Some(alpha)
}

/// Solves `a·x = b` (k × k); `None` if a pivot is below `SINGULAR` times the largest entry.
pub(in crate::geometry) fn solve(a: &[[f64; 8]; 8], b: &[f64; 8], k: usize) -> Option<[f64; 8]> {
    let scale = (0..k)
        .flat_map(|r| a[r][..k].iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    if k > 0 && scale == 0.0 {
        return None;
    }
    let (mut m, mut x) = (*a, *b);
    for col in 0..k {
        let pivot = (col..k).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        if m[pivot][col].abs() <= SINGULAR * scale {
            return None;
        }
        m.swap(col, pivot);
        x.swap(col, pivot);
        for row in col + 1..k {
            let f = m[row][col] / m[col][col];
            if f != 0.0 {
                let pivot_row = m[col];
                for (target, &source) in m[row][col..k].iter_mut().zip(&pivot_row[col..k]) {
                    *target -= f * source;
                }
                x[row] -= f * x[col];
            }
        }
    }
    for row in (0..k).rev() {
        let tail: f64 = (row + 1..k).map(|c| m[row][c] * x[c]).sum();
        x[row] = (x[row] - tail) / m[row][row];
    }
    Some(x)
}

/// Nearest point of the simplex spanned by `vertices` (at most D + 1 points) to `query`, and
/// its distance: computed exactly ([`min_norm_point_exact`]) and rounded once, whatever the
/// conditioning (clusters of nearly coincident vertices, coordinates of very different
/// magnitudes). It used to project onto every face in floating point, dropping faces whose pivots
/// looked negligible: wrong by far more than rounding on such input.
///
/// ```
/// use pqhull::geometry::nearest_in_simplex;
/// let triangle = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
/// let (x, d) = nearest_in_simplex(&triangle, &[2.0, 2.0, 0.0]);
/// assert_eq!(x, [0.5, 0.5, 0.0]);
/// assert!((d - 4.5f64.sqrt()).abs() <= 4.0 * f64::EPSILON);
/// ```
///
/// # Panics
/// If `vertices` is empty or a coordinate is not finite.
pub fn nearest_in_simplex<const D: usize>(
    vertices: &[[f64; D]],
    query: &[f64; D],
) -> ([f64; D], f64) {
    let (x, d, _) = nearest_face_in_simplex(vertices, query);
    (x, d)
}

/// [`nearest_in_simplex`], with the face holding the nearest point (a bit mask of `vertices`:
/// the points whose convex combination it is).
///
/// # Panics
/// As [`nearest_in_simplex`].
pub fn nearest_face_in_simplex<const D: usize>(
    vertices: &[[f64; D]],
    query: &[f64; D],
) -> ([f64; D], f64, u32) {
    let nearest = min_norm_point_exact(vertices.len(), |i| vertices[i], query, &[]);
    let face = nearest.support().iter().fold(0u32, |m, &i| m | 1 << i);
    (nearest.point, nearest.distance, face)
}

#[cfg(test)]
mod tests {
    use super::{min_norm_point, nearest_in_simplex};

    fn nearest<const D: usize>(points: &[[f64; D]], q: [f64; D]) -> ([f64; D], f64) {
        let n = min_norm_point(points.len(), |i| points[i], &q);
        (n.point, n.distance)
    }

    #[test]
    fn triangle_in_3d_regions() {
        let t = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
        let (x, d) = nearest(&t, [0.5, 0.5, 3.0]);
        assert!((x[0] - 0.5).abs() < 1e-15 && (x[1] - 0.5).abs() < 1e-15 && x[2].abs() < 1e-15);
        assert!((d - 3.0).abs() < 1e-15);
        let (x, d) = nearest(&t, [2.0, 2.0, 0.0]);
        assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
        assert!((d - 2f64.sqrt()).abs() < 1e-15);
        let (x, d) = nearest(&t, [-1.0, -1.0, 0.0]);
        assert_eq!(x, [0.0, 0.0, 0.0]);
        assert!((d - 2f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn segment_and_inside_in_2d() {
        let s = [[0.0, 0.0], [4.0, 0.0]];
        let (x, d) = nearest(&s, [1.0, 3.0]);
        assert!((x[0] - 1.0).abs() < 1e-15 && x[1].abs() < 1e-15 && (d - 3.0).abs() < 1e-15);
        assert_eq!(nearest(&s, [7.0, 4.0]), ([4.0, 0.0], 5.0));
        let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
        assert_eq!(nearest(&square, [0.25, 0.5]).1, 0.0);
    }

    #[test]
    fn simplex_fallback_regions() {
        let t = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
        let (x, d) = nearest_in_simplex(&t, &[2.0, 2.0, 0.0]);
        assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
        assert!((d - 2f64.sqrt()).abs() < 1e-15);
        assert_eq!(
            nearest_in_simplex(&t, &[-1.0, -1.0, 0.0]).0,
            [0.0, 0.0, 0.0]
        );
    }

    #[test]
    fn support_spans_the_nearest_face() {
        // A square far from the query: the nearest point is on the edge x = 1.
        let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
        let n = min_norm_point(4, |i| square[i], &[3.0, 0.5]);
        let mut support = n.support().to_vec();
        support.sort();
        assert_eq!(support, vec![1, 2]);
        assert!((n.distance - 2.0).abs() < 1e-15);
    }
}
