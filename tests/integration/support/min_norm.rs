//! Reference distance from a point to a convex hull: Wolfe's minimum-norm-point algorithm.
//!
//! P. Wolfe, "Finding the nearest point in a polytope", Mathematical Programming 11 (1976)
//! 128–149. The points are shifted so that the query is the origin; the algorithm keeps a
//! "corral" `S` of affinely independent points and the current point `x ∈ conv(S)` with its
//! convex weights. A major cycle adds the point `p_j` minimising `x · p_j` (if `x` does not already
//! satisfy Wolfe's optimality test `x · x ≤ x · p_j`); minor cycles move to the nearest point of
//! the affine hull of `S` when that lies inside `conv(S)`, or else walk toward it until a weight
//! reaches zero and drop that point.
//!
//! The affine minimisation is solved with the normal equations on differences from the first
//! point of `S`, by Gaussian elimination with partial pivoting and one step of iterative
//! refinement, in `f64`. For well-conditioned inputs the distance is accurate to about `1e−13`
//! relative to the size of the point set. This helper knows nothing of hulls, facets or
//! predicates: it is the independent reference the engine's distances are checked against.
//!
//! [`exact_min_norm_distance`] runs the same algorithm in rational arithmetic, with no tolerance
//! at all (warm-started from the floating-point corral): the reference for queries within
//! rounding of the hull, where `1e−13` of the set's size is far more than the distance itself.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Optimality tolerance: stop when `x·x − min_j x·p_j ≤ TOL · M · |x|` (`M` = largest `|p_j|`),
/// which bounds the error of `|x|` by `TOL · M`.
const TOL: f64 = 1e-13;

/// Relative pivot size below which the points of the corral are taken as affinely dependent.
const SINGULAR: f64 = 1e-14;

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Solves `a · x = b` (n × n, row-major) by Gaussian elimination with partial pivoting; `None` if
/// a pivot is below `SINGULAR` times the largest entry of `a`.
fn solve(a: &[f64], b: &[f64], n: usize) -> Option<Vec<f64>> {
    let scale = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if scale == 0.0 {
        return if n == 0 { Some(Vec::new()) } else { None };
    }
    let mut m = a.to_vec();
    let mut x = b.to_vec();
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| m[i * n + col].abs().total_cmp(&m[j * n + col].abs()))
            .expect("non-empty");
        if m[pivot * n + col].abs() <= SINGULAR * scale {
            return None;
        }
        if pivot != col {
            for k in 0..n {
                m.swap(pivot * n + k, col * n + k);
            }
            x.swap(pivot, col);
        }
        for row in col + 1..n {
            let f = m[row * n + col] / m[col * n + col];
            if f != 0.0 {
                for k in col..n {
                    m[row * n + k] -= f * m[col * n + k];
                }
                x[row] -= f * x[col];
            }
        }
    }
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| m[row * n + k] * x[k]).sum();
        x[row] = (x[row] - s) / m[row * n + row];
    }
    Some(x)
}

/// The affine weights (summing to 1) of the point of `aff{p_i : i ∈ s}` nearest the origin, or
/// `None` if those points are (numerically) affinely dependent.
fn affine_minimiser(p: &[Vec<f64>], s: &[usize]) -> Option<Vec<f64>> {
    let base = &p[s[0]];
    let e: Vec<Vec<f64>> = s[1..]
        .iter()
        .map(|&i| p[i].iter().zip(base).map(|(a, b)| a - b).collect())
        .collect();
    let k = e.len();
    // Normal equations: (EᵀE) β = −Eᵀ base; x = base + Σ β_i e_i.
    let mut g = vec![0.0; k * k];
    for i in 0..k {
        for j in 0..k {
            g[i * k + j] = dot(&e[i], &e[j]);
        }
    }
    let rhs: Vec<f64> = e.iter().map(|ei| -dot(ei, base)).collect();
    let mut beta = solve(&g, &rhs, k)?;
    // One step of iterative refinement.
    let residual: Vec<f64> = (0..k)
        .map(|i| rhs[i] - (0..k).map(|j| g[i * k + j] * beta[j]).sum::<f64>())
        .collect();
    if let Some(delta) = solve(&g, &residual, k) {
        beta.iter_mut().zip(delta).for_each(|(b, d)| *b += d);
    }
    let mut alpha = Vec::with_capacity(k + 1);
    alpha.push(1.0 - beta.iter().sum::<f64>());
    alpha.extend(beta);
    Some(alpha)
}

fn combination(p: &[Vec<f64>], s: &[usize], weights: &[f64]) -> Vec<f64> {
    let mut x = vec![0.0; p[s[0]].len()];
    for (&i, &w) in s.iter().zip(weights) {
        for (xk, pk) in x.iter_mut().zip(&p[i]) {
            *xk += w * pk;
        }
    }
    x
}

/// The point of `conv(points)` nearest `query`, and its distance from `query` (0 when `query` is
/// inside the hull).
///
/// # Panics
///
/// If `points` is empty or a point's length differs from `query`'s.
pub fn min_norm_point(points: &[Vec<f64>], query: &[f64]) -> (Vec<f64>, f64) {
    let (s, lam, x) = wolfe(points, query);
    let nearest = combination(points, &s, &lam);
    (nearest, dot(&x, &x).sqrt())
}

/// Wolfe's algorithm in `f64`: the final corral (indices), its weights, and the nearest point
/// relative to the query.
fn wolfe(points: &[Vec<f64>], query: &[f64]) -> (Vec<usize>, Vec<f64>, Vec<f64>) {
    assert!(!points.is_empty(), "min_norm_point: no points");
    assert!(
        points.iter().all(|p| p.len() == query.len()),
        "min_norm_point: dimension mismatch"
    );
    let d = query.len();
    let p: Vec<Vec<f64>> = points
        .iter()
        .map(|x| x.iter().zip(query).map(|(a, q)| a - q).collect())
        .collect();
    let big_m = p.iter().map(|x| dot(x, x).sqrt()).fold(0.0, f64::max);

    let j0 = (0..p.len())
        .min_by(|&a, &b| dot(&p[a], &p[a]).total_cmp(&dot(&p[b], &p[b])))
        .expect("non-empty");
    let mut s = vec![j0];
    let mut lam = vec![1.0];
    let mut x = p[j0].clone();

    let max_iterations = 100 * (p.len() + d + 1);
    'major: for _ in 0..max_iterations {
        let xx = dot(&x, &x);
        if xx == 0.0 {
            break;
        }
        let (j, xpj) = (0..p.len())
            .map(|j| (j, dot(&x, &p[j])))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .expect("non-empty");
        if xx - xpj <= TOL * big_m * xx.sqrt() || s.contains(&j) || s.len() > d {
            break;
        }
        s.push(j);
        lam.push(0.0);
        loop {
            let Some(alpha) = affine_minimiser(&p, &s) else {
                // Numerically dependent corral: keep the last good point.
                s.pop();
                lam.pop();
                break 'major;
            };
            if alpha.iter().all(|&a| a > 0.0) {
                x = combination(&p, &s, &alpha);
                lam = alpha;
                break;
            }
            // Walk from lam toward alpha until the first weight reaches zero.
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
            x = combination(&p, &s, &lam);
            if s.len() == 1 {
                break;
            }
        }
    }
    (s, lam, x)
}

/// Coordinates relative to the query as integers in units of a common power of two (exact:
/// every `f64` is an integer times a power of two), and that unit's exponent.
fn integer_points(points: &[Vec<f64>], query: &[f64]) -> (Vec<Vec<BigInt>>, i64) {
    let rational = |x: f64| BigRational::from_float(x).expect("finite coordinate");
    let rel: Vec<Vec<BigRational>> = points
        .iter()
        .map(|p| {
            p.iter()
                .zip(query)
                .map(|(&a, &q)| rational(a) - rational(q))
                .collect()
        })
        .collect();
    // Denominators are powers of two: the largest one is the common unit.
    let denominator = rel
        .iter()
        .flatten()
        .map(|x| x.denom().clone())
        .max()
        .unwrap_or_else(BigInt::one);
    let exponent = -(denominator.bits() as i64 - 1);
    let ints = rel
        .iter()
        .map(|p| {
            p.iter()
                .map(|x| (x * BigRational::from_integer(denominator.clone())).to_integer())
                .collect()
        })
        .collect();
    (ints, exponent)
}

fn rdot(a: &[BigRational], b: &[BigInt]) -> BigRational {
    a.iter()
        .zip(b)
        .map(|(x, y)| x * BigRational::from_integer(y.clone()))
        .fold(BigRational::zero(), |s, t| s + t)
}

/// `Σ λ_i p_{s_i}`.
fn rcombination(p: &[Vec<BigInt>], s: &[usize], weights: &[BigRational]) -> Vec<BigRational> {
    let d = p[s[0]].len();
    let mut x = vec![BigRational::zero(); d];
    for (&i, w) in s.iter().zip(weights) {
        for (xc, pc) in x.iter_mut().zip(&p[i]) {
            *xc += w * BigRational::from_integer(pc.clone());
        }
    }
    x
}

/// Exact affine weights of the point of `aff{p_i : i ∈ s}` nearest the origin, or `None` if the
/// points are affinely dependent (exactly).
fn raffine_minimiser(p: &[Vec<BigInt>], s: &[usize]) -> Option<Vec<BigRational>> {
    let base = &p[s[0]];
    let e: Vec<Vec<BigInt>> = s[1..]
        .iter()
        .map(|&i| p[i].iter().zip(base).map(|(a, b)| a - b).collect())
        .collect();
    let k = e.len();
    let idot = |a: &[BigInt], b: &[BigInt]| -> BigInt { a.iter().zip(b).map(|(x, y)| x * y).sum() };
    // Augmented normal equations [EᵀE | −Eᵀ base], Gauss–Jordan over the rationals.
    let mut m: Vec<Vec<BigRational>> = (0..k)
        .map(|r| {
            let mut row: Vec<BigRational> = (0..k)
                .map(|c| BigRational::from_integer(idot(&e[r], &e[c])))
                .collect();
            row.push(BigRational::from_integer(-idot(&e[r], base)));
            row
        })
        .collect();
    for col in 0..k {
        let pivot = (col..k).find(|&r| !m[r][col].is_zero())?;
        m.swap(col, pivot);
        for r in 0..k {
            if r != col && !m[r][col].is_zero() {
                let f = &m[r][col] / &m[col][col];
                let pivot_row = m[col].clone();
                for (target, source) in m[r][col..].iter_mut().zip(&pivot_row[col..]) {
                    *target -= &f * source;
                }
            }
        }
    }
    let beta: Vec<BigRational> = (0..k).map(|r| &m[r][k] / &m[r][r]).collect();
    let mut alpha = vec![BigRational::one() - beta.iter().fold(BigRational::zero(), |a, b| a + b)];
    alpha.extend(beta);
    Some(alpha)
}

/// `sqrt(x) · 2^exponent` for a non-negative rational `x`, to about one ulp.
fn rational_sqrt(x: &BigRational, exponent: i64) -> f64 {
    if x.is_zero() {
        return 0.0;
    }
    let parts = |v: &BigInt| -> (f64, i64) {
        let shift = v.bits().saturating_sub(64);
        ((v >> shift).to_f64().expect("64 bits fit"), shift as i64)
    };
    let (n, en) = parts(x.numer());
    let (d, ed) = parts(x.denom());
    let mut e = en - ed;
    let mut ratio = n / d;
    if e % 2 != 0 {
        ratio *= 2.0;
        e -= 1;
    }
    let total = (e / 2 + exponent).clamp(-2000, 2000) as i32;
    ratio.sqrt() * 2f64.powi(total / 2) * 2f64.powi(total - total / 2)
}

/// The distance from `query` to `conv(points)`, computed exactly (rational Wolfe, no tolerance)
/// and rounded once: 0 exactly when the query is in the hull.
///
/// Starts from the corral the floating-point [`min_norm_point`] ends with when that corral's
/// affine minimiser lies strictly inside it, so it usually needs one or two exact iterations.
///
/// # Panics
///
/// If `points` is empty or a point's length differs from `query`'s.
pub fn exact_min_norm_distance(points: &[Vec<f64>], query: &[f64]) -> f64 {
    let d = query.len();
    let (p, exponent) = integer_points(points, query);
    let (warm, _, _) = wolfe(points, query);
    let start = raffine_minimiser(&p, &warm)
        .filter(|alpha| alpha.iter().all(|a| a.is_positive()))
        .map(|alpha| (warm.clone(), alpha));
    let (mut s, mut lam) = start.unwrap_or_else(|| {
        let norm2 = |v: &Vec<BigInt>| -> BigInt { v.iter().map(|x| x * x).sum() };
        let j0 = (0..p.len())
            .min_by(|&a, &b| norm2(&p[a]).cmp(&norm2(&p[b])))
            .expect("non-empty");
        (vec![j0], vec![BigRational::one()])
    });
    let mut x = rcombination(&p, &s, &lam);
    loop {
        let xx = x.iter().fold(BigRational::zero(), |a, c| a + c * c);
        if xx.is_zero() {
            return 0.0;
        }
        let (j, xpj) = (0..p.len())
            .map(|j| (j, rdot(&x, &p[j])))
            .min_by(|a, b| a.1.cmp(&b.1))
            .expect("non-empty");
        if xpj >= xx {
            return rational_sqrt(&xx, exponent);
        }
        // Exact arithmetic: the entering point is affinely independent of the corral.
        assert!(
            s.len() <= d && !s.contains(&j),
            "exact Wolfe: corral invariant broken"
        );
        s.push(j);
        lam.push(BigRational::zero());
        loop {
            let alpha = raffine_minimiser(&p, &s).expect("affinely independent corral");
            if alpha.iter().all(|a| a.is_positive()) {
                lam = alpha;
                x = rcombination(&p, &s, &lam);
                break;
            }
            let theta = lam
                .iter()
                .zip(&alpha)
                .filter(|(_, a)| !a.is_positive())
                .map(|(l, a)| l / (l - a))
                .min()
                .expect("a non-positive weight");
            for (l, a) in lam.iter_mut().zip(&alpha) {
                *l = (BigRational::one() - &theta) * &*l + &theta * a;
            }
            let mut i = 0;
            while i < s.len() {
                if lam[i].is_positive() {
                    i += 1;
                } else {
                    s.remove(i);
                    lam.remove(i);
                }
            }
            x = rcombination(&p, &s, &lam);
            if s.len() == 1 {
                break;
            }
        }
    }
}

/// The exact distance from `query` to the affine hull of `points` (affinely independent), rounded
/// once; `None` if the points are affinely dependent.
pub fn exact_distance_to_affine_hull(points: &[Vec<f64>], query: &[f64]) -> Option<f64> {
    let (p, exponent) = integer_points(points, query);
    let s: Vec<usize> = (0..p.len()).collect();
    let alpha = raffine_minimiser(&p, &s)?;
    let x = rcombination(&p, &s, &alpha);
    let xx = x.iter().fold(BigRational::zero(), |a, c| a + c * c);
    Some(rational_sqrt(&xx, exponent))
}
