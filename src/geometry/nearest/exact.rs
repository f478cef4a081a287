//! Wolfe's algorithm in exact integer arithmetic, for queries far from the point set.
//!
//! Far from a point set, the nearest point is decided by differences far below the rounding of
//! anything measured from the query: with the unit square and `q = (0, 10^170)`, every `p − q` is
//! `(±1, −10^170)` in `f64`, the square collapses to a segment, and every vertex ties in Wolfe's
//! optimality test. No change of frame helps on its own — the in-plane position of `q` relative
//! to a face, `⟨e, q − f⟩` for an edge `e` of it, is a sum of terms of size `|e|·|q|` that cancel
//! to the size of the face. Here every coordinate (the points' and the query's) is an integer
//! multiple of one power of two, so the whole algorithm runs on integers: corrals, affine
//! minimisers (Cramer's rule on the Gram matrix, Bareiss determinants), the optimality test and
//! the walk of the minor cycles are exact, and the nearest point is the exact one, rounded once
//! per coordinate. Its integers have at most about 2,100 bits (the span of `f64` exponents), its
//! determinants a few times that: each operation on them costs far more than one in `f64`.

use super::{Nearest, dot, power_of_two_below};
use crate::geometry::exact_int::{bareiss_determinant as determinant, odd_mantissa};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The point of `conv{point(0), …, point(count − 1)}` nearest `query`, computed exactly and
/// rounded once per coordinate: `point` within half an ulp of the exact nearest point (so of a
/// point of the hull), `offset` (`point − query`) within half an ulp of the exact difference,
/// `distance` a few ulps of the exact one (`+∞` beyond `f64::MAX`). `start` (indices of
/// affinely independent points, such as a floating-point run's support) is used as the first
/// corral when the exact affine minimiser lies strictly inside it; otherwise the run starts from
/// the exactly nearest point.
///
/// Meant for queries far from the points (farther than about 2^10 times their extent), where the
/// floating-point [`min_norm_point_accurate`](super::min_norm_point_accurate) cannot tell the
/// faces apart; it is correct for any finite input, only slower.
///
/// ```
/// use pqhull::geometry::min_norm_point_exact;
/// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
/// let n = min_norm_point_exact(4, |i| square[i], &[0.0, 1e170], &[]);
/// assert_eq!(n.point, [0.0, 1.0]);
/// assert_eq!(n.distance, 1e170);
/// ```
///
/// # Panics
/// If `count == 0`, a coordinate is not finite, or an index of `start` is `count` or more.
pub fn min_norm_point_exact<const D: usize>(
    count: usize,
    point: impl Fn(usize) -> [f64; D],
    query: &[f64; D],
    start: &[usize],
) -> Nearest<D> {
    assert!(count > 0, "min_norm_point_exact: no points");
    let problem = Problem::new(count, &point, query);
    let mut state = problem.initial(start);
    // Each major cycle strictly decreases the distance (exact arithmetic), and a corral is one of
    // finitely many affinely independent subsets: the loop ends. The cap only guards a bug.
    for _ in 0..100 * (count + D + 1) {
        let Some(entering) = problem.most_violating(&state) else {
            break;
        };
        if state.corral.contains(&entering) || state.corral.len() > D {
            break; // impossible in exact arithmetic
        }
        match problem.minor_cycles(&state, entering) {
            Some(next) => state = next,
            None => break,
        }
    }
    problem.finish(&state)
}

/// The points and the query as integers: coordinate = integer · 2^`exponent`.
struct Problem<const D: usize> {
    points: Vec<[BigInt; D]>,
    query: [BigInt; D],
    exponent: i32,
}

/// A corral and the exact affine minimiser of its points, which lies strictly inside their
/// simplex: weights `numerators[i] / denominator` (`denominator > 0`, the Gram determinant).
struct State {
    corral: Vec<usize>,
    numerators: Vec<BigInt>,
    denominator: BigInt,
}

impl<const D: usize> Problem<D> {
    fn new(count: usize, point: &impl Fn(usize) -> [f64; D], query: &[f64; D]) -> Self {
        let raw: Vec<[f64; D]> = (0..count).map(point).collect();
        let exponent = raw
            .iter()
            .chain(std::iter::once(query))
            .flatten()
            .filter_map(|&x| decompose(x).map(|(_, e)| e))
            .min()
            .unwrap_or(0);
        let integer = |p: &[f64; D]| -> [BigInt; D] {
            std::array::from_fn(|c| match decompose(p[c]) {
                None => BigInt::zero(),
                Some((m, e)) => BigInt::from(m) << (e - exponent) as usize,
            })
        };
        Problem {
            points: raw.iter().map(integer).collect(),
            query: integer(query),
            exponent,
        }
    }

    /// The first corral: `start` if its affine minimiser is strictly inside it, else the nearest
    /// point.
    fn initial(&self, start: &[usize]) -> State {
        if (2..=D + 1).contains(&start.len())
            && let Some(state) = self.affine_minimiser(start.to_vec())
            && state.numerators.iter().all(|w| w.is_positive())
        {
            return state;
        }
        let squared = |j: usize| {
            let r: [BigInt; D] = std::array::from_fn(|c| &self.points[j][c] - &self.query[c]);
            idot(&r, &r)
        };
        let mut best = (squared(0), 0);
        for j in 1..self.points.len() {
            let s = squared(j);
            if s < best.0 {
                best = (s, j);
            }
        }
        State {
            corral: vec![best.1],
            numerators: vec![BigInt::one()],
            denominator: BigInt::one(),
        }
    }

    /// `denominator · x` for the state's point `x`.
    fn scaled_point(&self, state: &State) -> [BigInt; D] {
        std::array::from_fn(|c| {
            state
                .corral
                .iter()
                .zip(&state.numerators)
                .map(|(&j, w)| w * &self.points[j][c])
                .sum()
        })
    }

    /// The point most beyond Wolfe's optimality plane through the state's point `x` — the `j`
    /// minimising `(x − q)·p_j`, if `(x − q)·(p_j − x) < 0` — or `None` when `x` is the nearest
    /// point.
    fn most_violating(&self, state: &State) -> Option<usize> {
        let n = self.scaled_point(state);
        let den = &state.denominator;
        let g: [BigInt; D] = std::array::from_fn(|c| &n[c] - den * &self.query[c]);
        if g.iter().all(|x| x.is_zero()) {
            return None; // the query is a point of the hull
        }
        let at_x = idot(&g, &n);
        let (j, value) = (0..self.points.len())
            .map(|j| (j, idot(&g, &self.points[j])))
            .min_by(|a, b| a.1.cmp(&b.1))?;
        (den * value < at_x).then_some(j)
    }

    /// Wolfe's minor cycles after `entering` joins the corral: the affine minimiser of the corral,
    /// or a walk toward it until a weight vanishes (that point leaves), until the minimiser lies
    /// strictly inside.
    fn minor_cycles(&self, state: &State, entering: usize) -> Option<State> {
        let mut corral = state.corral.clone();
        corral.push(entering);
        let ratio = |n: &BigInt, d: &BigInt| BigRational::new(n.clone(), d.clone());
        let mut weights: Vec<BigRational> = state
            .numerators
            .iter()
            .map(|n| ratio(n, &state.denominator))
            .chain(std::iter::once(BigRational::zero()))
            .collect();
        loop {
            let target = self.affine_minimiser(corral.clone())?;
            if target.numerators.iter().all(|w| w.is_positive()) {
                return Some(target);
            }
            let alpha: Vec<BigRational> = target
                .numerators
                .iter()
                .map(|n| ratio(n, &target.denominator))
                .collect();
            // Walk from the weights toward alpha until the first weight reaches zero.
            let mut theta = BigRational::one();
            for (l, a) in weights.iter().zip(&alpha) {
                if !a.is_positive() {
                    let t = if l > a {
                        l / (l - a)
                    } else {
                        BigRational::zero()
                    };
                    if t < theta {
                        theta = t;
                    }
                }
            }
            let keep = BigRational::one() - &theta;
            let mut kept_corral = Vec::with_capacity(corral.len());
            let mut kept_weights = Vec::with_capacity(corral.len());
            for ((&j, l), a) in corral.iter().zip(&weights).zip(&alpha) {
                let w = &keep * l + &theta * a;
                if w.is_positive() {
                    kept_corral.push(j);
                    kept_weights.push(w);
                }
            }
            if kept_corral.len() == corral.len() || kept_corral.is_empty() {
                return None; // no weight vanished: impossible in exact arithmetic
            }
            corral = kept_corral;
            weights = kept_weights;
        }
    }

    /// The point of the affine hull of `corral` nearest the query, by Cramer's rule on the Gram
    /// system of the edges from the first point; `None` if the points are affinely dependent.
    fn affine_minimiser(&self, corral: Vec<usize>) -> Option<State> {
        let k = corral.len() - 1;
        let base = &self.points[corral[0]];
        let edges: Vec<[BigInt; D]> = corral[1..]
            .iter()
            .map(|&j| std::array::from_fn(|c| &self.points[j][c] - &base[c]))
            .collect();
        let r: [BigInt; D] = std::array::from_fn(|c| &self.query[c] - &base[c]);
        let gram: Vec<Vec<BigInt>> = (0..k)
            .map(|i| (0..k).map(|j| idot(&edges[i], &edges[j])).collect())
            .collect();
        let rhs: Vec<BigInt> = edges.iter().map(|e| idot(e, &r)).collect();
        let denominator = determinant(gram.clone());
        if denominator.is_zero() {
            return None;
        }
        let mut numerators = vec![BigInt::zero(); k + 1];
        for i in 0..k {
            let mut m = gram.clone();
            for (row, b) in m.iter_mut().zip(&rhs) {
                row[i] = b.clone();
            }
            numerators[i + 1] = determinant(m);
        }
        numerators[0] = &denominator - numerators[1..].iter().sum::<BigInt>();
        Some(State {
            corral,
            numerators,
            denominator,
        })
    }

    fn finish(&self, state: &State) -> Nearest<D> {
        let n = self.scaled_point(state);
        let den = &state.denominator;
        let to_f64 = |numerator: BigInt| {
            let (mut numerator, mut denominator) = (numerator, den.clone());
            if self.exponent >= 0 {
                numerator <<= self.exponent as usize;
            } else {
                denominator <<= (-self.exponent) as usize;
            }
            BigRational::new_raw(numerator, denominator)
                .to_f64()
                .expect("a ratio of integers with a positive denominator")
        };
        let point: [f64; D] = std::array::from_fn(|c| to_f64(n[c].clone()));
        let offset: [f64; D] = std::array::from_fn(|c| to_f64(&n[c] - den * &self.query[c]));
        let mut support = [0usize; 9];
        support[..state.corral.len()].copy_from_slice(&state.corral);
        Nearest {
            point,
            offset,
            distance: length(&offset),
            support,
            support_len: state.corral.len(),
        }
    }
}

/// `x = m · 2^e` with `m` odd (`None` for zero).
fn decompose(x: f64) -> Option<(i64, i32)> {
    assert!(
        x.is_finite(),
        "min_norm_point_exact: a coordinate is not finite"
    );
    odd_mantissa(x)
}

fn idot<const D: usize>(a: &[BigInt; D], b: &[BigInt; D]) -> BigInt {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `|v|` without overflow or underflow of the squares (`+∞` only when the length itself exceeds
/// `f64::MAX`).
fn length<const D: usize>(v: &[f64; D]) -> f64 {
    let largest = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if largest == 0.0 || !largest.is_finite() {
        return largest;
    }
    let unit = power_of_two_below(largest);
    let scaled = v.map(|x| x / unit);
    dot(scaled, scaled).sqrt() * unit
}

#[cfg(test)]
mod tests {
    use super::min_norm_point_exact;

    #[test]
    fn far_queries_on_the_square() {
        let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
        for (q, expected) in [
            ([0.0, 1e170], [0.0, 1.0]),
            ([1e170, 0.0], [1.0, 0.0]),
            ([-1e300, 1e300], [-1.0, 1.0]),
            ([0.5e200, 1e200], [1.0, 1.0]),
            ([0.25, -1.7e308], [0.25, -1.0]),
            ([0.25, 0.5], [0.25, 0.5]),
            ([3.0, 0.5], [1.0, 0.5]),
        ] {
            let n = min_norm_point_exact(4, |i| square[i], &q, &[]);
            assert_eq!(n.point, expected, "query {q:?}");
        }
    }
}
