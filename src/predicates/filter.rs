//! The floating-point filter: a cached hyperplane with a certified error bound.

use super::minors::{MinorScalar, Tracked, tracked_minors};
use super::{Sign, double_double::DdPlane, exact, wide::ExactPlane};
use std::mem::ManuallyDrop;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicU8, Ordering};

/// Unit roundoff of `f64` (round to nearest).
const U: f64 = f64::EPSILON / 2.0;

/// Absolute slack covering every underflow, valid when all coordinates are in `[−1, 1]`.
///
/// An underflowing product or sum commits an *absolute* error of at most `2^-1075` instead of a
/// relative one. With coordinates in `[−1, 1]` every difference is at most 2 in magnitude, so such
/// an error is amplified by at most `2` per Laplace level and summed over at most `D ≤ 8` terms per
/// level: at most `(2·8)^9 · 2^-1075 < 2^-1030` in the end. `2^-1000` is a generous cover, and is
/// itself far below any meaningful determinant.
const UNDERFLOW_SLACK: f64 = 9.332636185032189e-302; // 2^-1000

/// 2^52: below it (with a factor-2 margin for the rounded permanent) integers are exact in f64.
const TWO_52: f64 = 4_503_599_627_370_496.0;

/// `2^e`, exactly, for `e` in the normal range `−1022..=1023`, built from its bits (`powi` is a
/// library call, and this is on every slow side test).
fn pow2(e: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&e));
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// The exponent of the coarsest power-of-two grid holding all the (non-zero) values: the smallest
/// exponent of their lowest set bits. `i32::MAX` if all are zero.
fn grid_exponent<'a>(values: impl Iterator<Item = &'a f64>) -> i32 {
    values
        .filter(|x| **x != 0.0 && x.is_finite())
        .map(|&x| exact::lowest_bit_exponent(x))
        .min()
        .unwrap_or(i32::MAX)
}

/// Whether a determinant's `permanent` is below 2^51 units of 2^(g·D) (see
/// [`FacetPlane::value_is_exact`]), in two steps so that neither factor overflows; `false` when
/// g·D is out of range (underflow would then be possible), `true` for `g = i32::MAX` (every
/// entry zero). For `g·D ≤ 1000` it only fails more on a finer grid (smaller `g`).
#[inline(always)]
fn permanent_fits<const D: usize>(permanent: f64, g: i32) -> bool {
    if g == i32::MAX {
        return true;
    }
    let Some(units) = g
        .checked_mul(D as i32)
        .filter(|u| (-1000..=1000).contains(u))
    else {
        return false;
    };
    let half = -units / 2;
    permanent * pow2(half) * pow2(-units - half) < TWO_52 / 2.0
}

/// The largest cofactor error [`FacetPlane::refined_normal_direction`] accepts from the
/// double-double plane, relative to the largest cofactor: `2^-51`, four ulps. The exact route
/// rounds each cofactor correctly (half an ulp); metrics that read the normal (Q_OWS's support
/// of the disturbances) keep their accuracy within a few ulps either way.
const DD_NORMAL_TOLERANCE: f64 = 4.440892098500626e-16; // 2^-51

/// Below this the double-double cofactors' magnitudes are near the subnormal range, where their
/// error bounds need not hold: the exact path decides (the engine's own threshold for `f64`).
const MIN_DD_NORMAL: f64 = 1e-270;

/// Relative inflation covering the roundings of the bound computation itself (at most ~30
/// operations on non-negative numbers, each with relative error `u = 2^-53`: `30u < 2^-40`).
const BOUND_INFLATION: f64 = 1.0 + 1.0 / (1u64 << 40) as f64;

/// A bound on [`FacetPlane::evaluate`]'s per-point bound `fl(Σ_j err_j·|d̂_j|)·I + slack` that
/// holds for every `p` in `[−1, 1]^D` (`I` is `BOUND_INFLATION`, `d̂_j = fl(p_j − v0_j)`).
///
/// Why it is one: `|d̂_j| ≤ (|p_j| + |v0_j|)(1 + u) ≤ (1 + |v0_j|)(1 + u)`, so the computed sum
/// is at most `(1 + γ_D)(1 + u)·S` with `S = Σ_j err_j·(1 + |v0_j|)`; the computed `Ŝ` (one
/// rounding for `1 + |v0_j|`, one per product, D − 1 for the sum) is at least
/// `(1 − γ_(D+2))·S`; so `fl(Ŝ·I) ≥ Ŝ(1 + 2^-40)(1 − u)` exceeds the computed sum for D ≤ 8
/// (`(2D + 4)u < 2^-40`), and rounding is monotone. Underflow (absolute errors of `2^-1075` per
/// operation, either sum) is covered by a second `slack`. NaN (an overflowed error) fails every
/// `>` test: the per-point path runs.
fn coarse_bound<const D: usize>(error: &[f64; D], base: &[f64; D], slack: f64) -> f64 {
    let mut sum = 0.0;
    for (&e, &b) in error.iter().zip(base) {
        sum += e * (1.0 + b.abs());
    }
    (sum * BOUND_INFLATION) * BOUND_INFLATION + 2.0 * slack
}

/// Whether every coordinate of `p` is in `[−1, 1]` (false for NaN): the points for which
/// [`FacetPlane::evaluate_in_box`] may be called.
#[inline]
pub(crate) fn in_box<const D: usize>(p: &[f64; D]) -> bool {
    p.iter().all(|x| x.abs() <= 1.0)
}

/// The hyperplane through D points, cached for fast exact side tests.
///
/// Stores the base vertex `v0`, the cofactors `C_j` of the last row of
/// `[v1 − v0; …; v(D−1) − v0; ·]`, and per-coordinate error coefficients, so that
/// `Σ_j C_j·(p_j − v0_j)` approximates `det[v1 − v0; …; v(D−1) − v0; p − v0]` with a certified
/// error bound `Σ_j err_j·|p_j − v0_j|` (see [`FacetPlane::evaluate`]).
#[derive(Clone, Debug)]
pub struct FacetPlane<const D: usize> {
    base: [f64; D],
    cofactors: [f64; D],
    error: [f64; D],
    /// Permanents of |minor| behind each cofactor (for the exact-arithmetic test of `side`).
    pub(in crate::predicates) permanents: [f64; D],
    /// `UNDERFLOW_SLACK` if every vertex coordinate is in `[−1, 1]`, `+∞` otherwise (filter off).
    slack: f64,
    /// A bound that holds for every `p` in `[−1, 1]^D` at once (see [`evaluate`](Self::evaluate)):
    /// a value beyond it is decided with no per-point bound.
    coarse: f64,
    /// The slower stages, allocated the first time the filter fails on this plane (so that a
    /// plane the filter always decides carries one pointer's worth of them).
    refined: OnceLock<Box<Refined<D>>>,
}

/// The stages behind the filter, each built on first use.
#[derive(Debug, Default)]
struct Refined<const D: usize> {
    /// The double-double plane; `None` inside when a vertex coordinate is outside `[−1, 1]`.
    dd: OnceLock<Option<DdPlane<D>>>,
    /// Exact integer cofactors; `None` inside when the vertices do not fit (then every
    /// exact test computes a full determinant). Inline (about 1 KB in 6-D), so that a plane
    /// allocates once whatever the stages it needs.
    exact: OnceLock<Option<ExactPlane<D>>>,
    /// The same hyperplane from better rows, when there are any (see [`better_order`]): its
    /// filter and double-double stage decide much of what this plane's could not.
    rebased: OnceLock<Box<Rebased<D>>>,
    /// Whether [`better_order`] was asked: 0 (not yet, the default), [`NO_ORDER`] (no better
    /// rows) or [`REBUILT`] (`rebased` holds them). A plain flag rather than a `OnceLock`, whose
    /// initialisation cost 1 % of a raw wrench hull for the common answer, none.
    rebase: AtomicU8,
    /// The exponent of the coarsest power-of-two grid holding the base vertex's coordinates:
    /// no finer than the grid of all the vertices (see [`FacetPlane::value_is_exact`]), so a
    /// permanent that does not fit it fits no grid of theirs. Kept with the double-double
    /// stage, for [`FacetPlane::built_double_double`]; D bit scans, where the grid of every
    /// vertex costs D² (on the tilted family in 5-D that was 7 % of the hull's instructions).
    base_grid: OnceLock<i32>,
}

const NO_ORDER: u8 = 1;
const REBUILT: u8 = 2;

impl<const D: usize> Clone for Refined<D> {
    fn clone(&self) -> Self {
        Refined {
            dd: self.dd.clone(),
            exact: self.exact.clone(),
            rebased: self.rebased.clone(),
            rebase: AtomicU8::new(self.rebase.load(Ordering::Relaxed)),
            base_grid: self.base_grid.clone(),
        }
    }
}

/// A plane through the same vertices as another, listed in another order (see
/// [`better_order`]) and built from consecutive differences ([`FacetPlane::chained`]), with
/// its own double-double stage: what the filter and that stage decide for it, they decide for
/// the original, up to the permutation's sign.
#[derive(Clone, Debug)]
struct Rebased<const D: usize> {
    /// Only its filter is read (its own cache is never built: the double-double stage is
    /// `dd` below, the exact one the original plane's), so there is nothing of it to drop;
    /// `ManuallyDrop` keeps the drop glue of `FacetPlane` from recursing through this type,
    /// which kept the compiler from inlining it where facets are overwritten (`push_facet`:
    /// the 4-D sphere of `pqh bench hull` 11 % slower).
    plane: ManuallyDrop<FacetPlane<D>>,
    vertices: [[f64; D]; D],
    /// Whether the permutation is odd (its orientation determinant is the original's negated).
    odd: bool,
    dd: OnceLock<Option<DdPlane<D>>>,
}

/// The largest coordinate of `a − b` in magnitude.
fn distance_inf<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    (0..D).fold(0.0f64, |m, j| m.max((a[j] - b[j]).abs()))
}

impl<const D: usize> Drop for Rebased<D> {
    fn drop(&mut self) {
        debug_assert!(
            self.plane.refined.get().is_none(),
            "a rebased plane's own cache was built: it would leak"
        );
    }
}

/// How many binary orders of magnitude the product of the rows' sizes must shrink by for a
/// plane to be rebuilt in another order: far above the ordinary spread of random facets, so
/// that only planes whose vertices gather in tight clusters are rebuilt.
const REBASE_BITS: i64 = 24;

/// The binary exponent of the largest coordinate of `a − b` (its size, for [`better_order`]).
fn size_exponent<const D: usize>(a: &[f64; D], b: &[f64; D]) -> i64 {
    ((distance_inf(a, b).to_bits() >> 52) & 0x7ff) as i64
}

/// An order of the vertices whose consecutive differences have a product of sizes smaller than
/// that of the rows `v_k − v0` by more than [`REBASE_BITS`] (sizes as binary exponents,
/// summed), with whether the permutation is odd; `None` when there is none. The order starts
/// at the vertex nearest the others (the best single base) and goes on to the nearest vertex
/// not yet taken.
///
/// Why it matters: the filter's and the double-double plane's error bounds are proportional to
/// the permanents of the rows, about the product of their sizes, while the determinant is the
/// same for every such set of rows. A facet with vertices in tight clusters of nearly
/// coincident points has rows from its base to another cluster that are large and nearly
/// parallel, their determinant tiny against their permanent: the filter and the double-double
/// stage fail and the exact stage decides (on the 6-D clusters of `pqh bench hull`, the exact
/// planes were the largest share of the build). Chained through each cluster, the rows are the
/// small exact differences within it and one jump per cluster, and the filter decides.
pub(in crate::predicates) fn better_order<const D: usize>(
    vertices: &[[f64; D]; D],
) -> Option<([usize; D], bool)> {
    // Every pair's size once (D(D − 1)/2 differences).
    let mut size = [[0i64; D]; D];
    let mut closest = i64::MAX;
    for i in 0..D {
        for j in i + 1..D {
            let s = size_exponent(&vertices[i], &vertices[j]);
            (size[i][j], size[j][i]) = (s, s);
            closest = closest.min(s);
        }
    }
    let first: i64 = size[0][1..].iter().sum();
    // No chain of D − 1 differences is smaller than D − 1 of the closest pair's: the common
    // case (no clusters) ends here.
    if (D as i64 - 1).saturating_mul(closest) + REBASE_BITS >= first {
        return None;
    }
    let spread = |b: usize| -> i64 { size[b].iter().sum::<i64>() - size[b][b] };
    let start = (0..D).min_by_key(|&b| spread(b))?;
    let mut order = [start; D];
    let mut taken = [false; D];
    taken[start] = true;
    let mut chain = 0;
    for i in 1..D {
        let last = order[i - 1];
        let next = (0..D)
            .filter(|&k| !taken[k])
            .min_by_key(|&k| size[last][k])?;
        order[i] = next;
        taken[next] = true;
        chain += size[last][next];
    }
    if chain + REBASE_BITS >= first {
        return None;
    }
    let inversions = (0..D)
        .flat_map(|i| (i + 1..D).map(move |j| (i, j)))
        .filter(|&(i, j)| order[i] > order[j])
        .count();
    Some((order, inversions % 2 == 1))
}

/// The body of [`FacetPlane::new`] (rows `v_k − v0`) and of `FacetPlane::chained` (rows
/// `v_k − v_(k−1)`, when `$chained`): a macro rather than a shared function, because `new` as
/// a call to a shared function (or a wrapper around one) compiled differently — inlined into
/// `push_facet`, or with its 6-D minors 16 % slower — and `new` is the hot path of every hull.
macro_rules! plane_through {
    ($vertices:expr, $chained:expr) => {{
        let vertices: &[[f64; D]; D] = $vertices;
        plane_through!(vertices, $chained, vertices.iter().flatten().all(|x| x.abs() <= 1.0))
    }};
    ($vertices:expr, $chained:expr, $in_range:expr) => {{
        const { assert!(D >= 1 && D <= 8, "FacetPlane supports 1 ≤ D ≤ 8") };
        let vertices: &[[f64; D]; D] = $vertices;
        let base = vertices[0];
        let in_range: bool = $in_range;

        // The rows e_k = v_k − v0 (rounded) with their magnitudes, once (the expansion reads
        // each entry up to 2^(D−2) times); chained, e_k = v_k − v_(k−1).
        let mut rows = [[Tracked::ZERO; D]; D];
        for k in 1..D {
            let from = if $chained { &vertices[k - 1] } else { &base };
            for j in 0..D {
                let value = vertices[k][j] - from[j];
                rows[k][j] = Tracked {
                    value,
                    magnitude: value.abs(),
                };
            }
        }
        let minors = tracked_minors(&rows);


        // Error analysis (why these constants are safe; u = 2^-53, γ_n = nu/(1 − nu)). Every
        // rounding below attaches a factor (1 + δ), |δ| ≤ u, to whole product terms, so a
        // product of at most n of them is 1 + θ with |θ| ≤ γ_n (Higham, Lemma 3.1).
        // * Entries: ê = fl(v_k − v0) = e(1 + δ) (a difference that underflows is exact).
        // * A minor of size k is fl(Σ_i ±ê_(k,j_i)·m̂_i), the first term added to zero (exact):
        //   each of its k products carries at most k roundings (its own and the k − 1 sums), so
        //   level k adds at most k factors to each elementary term of the expansion (a product
        //   of k entries, one per row). Size-1 minors are the entries, exact.
        // * So each term of a computed cofactor (size D − 1) carries at most
        //   n = Σ_(k=2..D−1) k + (D − 1) = (D − 1)(D + 2)/2 − 1 factors (19 in 6-D), and
        //   |Ĉ_j − C_j| ≤ γ_n·P_j, P_j the permanent of the exact |e| behind cofactor j. The
        //   computed permanent P̂_j (the same expansion on |ê|, sums of non-negative terms)
        //   is at least (1 − γ_n)·P_j, so |Ĉ_j − C_j| ≤ γ_n/(1 − γ_n)·P̂_j = nu/(1 − 2nu)·P̂_j.
        // * The value Σ_j Ĉ_j·d̂_j (d̂_j = fl(p_j − v0_j) = d_j(1 + δ), the first term added to
        //   zero) differs from Σ_j Ĉ_j·d_j by at most γ_(D+1)·Σ_j |Ĉ_j|·|d_j|, and |d_j| ≤
        //   |d̂_j|/(1 − u): so |value − det| ≤ Σ_j err_j·|d̂_j| with
        //   err_j = [nu/(1 − 2nu)·P̂_j + γ_(D+1)·|Ĉ_j|]/(1 − u).
        // We take (n + 1)u and (D + 2)u: their excess over those coefficients, 1/n and 1/(D + 1)
        // relative, covers the second-order terms and the two roundings of err_j's own
        // computation ((n + 1)(1 − u)² ≥ n/((1 − 2nu)(1 − u)) for n ≤ 34, D = 8). The
        // per-point sum Σ err_j·|d̂_j| is covered by `BOUND_INFLATION`, underflow by `slack`.
        // (Before 2026-12-07 the coefficient was 2(D² + 4D + 8)u, a first-order estimate
        // inflated fourfold: 136u against 20u in 6-D. The tight one lets the filter decide
        // values 6.8 times nearer the plane, and certify the normals of more thin facets.)
        let d = D as f64;
        let n = ((D - 1) * (D + 2) / 2).saturating_sub(1) as f64;
        let c_perm = (n + 1.0) * U;
        let c_cof = (d + 2.0) * U;
        let mut cofactors = [0.0; D];
        let mut error = [0.0; D];
        let mut permanents = [0.0; D];
        for j in 0..D {
            let Tracked { value, magnitude } = minors[j];
            let c = if (D - 1 + j) % 2 == 1 { -value } else { value };
            cofactors[j] = c;
            permanents[j] = magnitude;
            error[j] = c_perm * magnitude + c_cof * c.abs();
        }
        let slack = if in_range {
            UNDERFLOW_SLACK
        } else {
            f64::INFINITY
        };
        FacetPlane {
            base,
            cofactors,
            error,
            permanents,
            slack,
            coarse: coarse_bound(&error, &base, slack),
            refined: OnceLock::new(),
        }
    }};
}

impl<const D: usize> FacetPlane<D> {
    /// Caches the hyperplane through `vertices` (`vertices[0]` is the base `v0`).
    ///
    /// Costs `D·2^(D−1)` multiply-adds (1024 for D = 8) and no allocation: all the
    /// (D−1)×(D−1) minors are computed at once by a dynamic programme over column subsets.
    ///
    /// The error bounds of [`evaluate`](Self::evaluate) are only finite when every vertex coordinate
    /// is in `[−1, 1]`; otherwise the plane is still usable, but [`side`](Self::side) always takes
    /// the exact path.
    ///
    /// Compile-time error if `D` is 0 or greater than 8.
    pub fn new(vertices: &[[f64; D]; D]) -> Self {
        plane_through!(vertices, false)
    }

    /// [`new`](Self::new) for a caller that knows whether every coordinate of `vertices` is in
    /// `[−1, 1]` (a hull whose points all are: `in_range`), without checking the D² coordinates
    /// again (a fifth of the 6-D plane's instructions); `in_range == false` checks them.
    ///
    /// # Panics
    /// In debug builds, if `in_range` is true and a coordinate is not in `[−1, 1]` (in release
    /// builds the filter's bound would not hold).
    pub(crate) fn new_in_range(vertices: &[[f64; D]; D], in_range: bool) -> Self {
        debug_assert!(
            !in_range || vertices.iter().all(in_box),
            "new_in_range: {vertices:?} is not in [−1, 1]^D"
        );
        if in_range {
            plane_through!(vertices, false, true)
        } else {
            plane_through!(vertices, false)
        }
    }

    /// The plane through `vertices` from the rows `v_k − v_(k−1)` instead of `v_k − v0`: the
    /// same exact cofactors (the rows are a unit-triangular transform of the others), with
    /// error bounds from the chain's permanents, far smaller when the vertices are ordered so
    /// that consecutive ones are close (see `better_order`). Its side tests still measure
    /// `p − v0`.
    pub(in crate::predicates) fn chained(vertices: &[[f64; D]; D]) -> Self {
        plane_through!(vertices, true)
    }

    /// Approximate value of `det[v1 − v0; …; v(D−1) − v0; p − v0]` (the determinant whose sign is
    /// [`orientation`](super::orientation)`(vertices, p)`) and a certified bound on its absolute
    /// error: `|value − exact| ≤ bound`.
    ///
    /// The bound is finite only if every coordinate of `p` and of the vertices is in `[−1, 1]`;
    /// otherwise (including NaN or infinite `p`) it is `+∞`.
    ///
    /// The value is [`value`](Self::value); the bound is the per-point `Σ_j err_j·|p_j − v0_j|`
    /// only when the value is within the plane's coarse bound (the same sum taken over the whole
    /// box, a constant of the plane), so a value beyond it costs no per-point sum.
    #[inline(always)]
    pub fn evaluate(&self, p: &[f64; D]) -> (f64, f64) {
        if in_box(p) {
            self.evaluate_in_box(p)
        } else {
            (self.value(p), f64::INFINITY)
        }
    }

    /// [`evaluate`](Self::evaluate) for a point the caller has checked to lie in `[−1, 1]^D`
    /// (`in_box`), without checking it again: for loops that test one point against many planes.
    ///
    /// # Panics
    /// In debug builds, if `p` is not in the box (in release builds the bound would not hold).
    #[inline(always)]
    pub(crate) fn evaluate_in_box(&self, p: &[f64; D]) -> (f64, f64) {
        debug_assert!(in_box(p), "evaluate_in_box: {p:?} is outside [−1, 1]^D");
        let value = self.value(p);
        if value.abs() > self.coarse {
            (value, self.coarse)
        } else {
            (value, self.point_bound(p))
        }
    }

    /// [`evaluate`](Self::evaluate)'s per-point bound (out of line: the coarse bound decides
    /// most tests).
    #[inline(never)]
    fn point_bound(&self, p: &[f64; D]) -> f64 {
        let mut bound = 0.0;
        for ((&x, &b), &e) in p.iter().zip(&self.base).zip(&self.error) {
            bound += e * (x - b).abs();
        }
        bound * BOUND_INFLATION + self.slack
    }

    /// The floating-point value of `det[v1 − v0; …; v(D−1) − v0; p − v0]` alone (the first half of
    /// [`evaluate`](Self::evaluate), without its error bound): the exact determinant when the
    /// vertices and `p` are covered by one [`ExactGrid`](super::ExactGrid).
    #[inline]
    pub fn value(&self, p: &[f64; D]) -> f64 {
        // From −0, which adds nothing (the compiler drops that addition; not from +0, which
        // would turn a −0 sum into +0 and so is kept): one addition fewer on every test's
        // critical path. Only a zero's sign could differ from a sum begun at +0.
        let mut value = -0.0;
        for ((&x, &b), &c) in p.iter().zip(&self.base).zip(&self.cofactors) {
            value += c * (x - b);
        }
        value
    }

    /// Whether every coordinate of the vertices this plane was built from is in `[−1, 1]` (its
    /// filter's bound is then finite): the later stages need to know, and need not check again.
    pub(in crate::predicates) fn in_range(&self) -> bool {
        self.slack.is_finite()
    }

    /// A copy of the plane without its exact-arithmetic cache (which a clone would copy, and
    /// allocate for): the floating-point part alone, for a second facet in the same hyperplane.
    pub(crate) fn clone_uncached(&self) -> Self {
        FacetPlane {
            base: self.base,
            cofactors: self.cofactors,
            error: self.error,
            permanents: self.permanents,
            slack: self.slack,
            coarse: self.coarse,
            refined: OnceLock::new(),
        }
    }

    /// The sign of `det[v1 − v0; …; p − v0]` when the floating-point filter alone decides it
    /// (`|value| > bound`, see [`evaluate`](Self::evaluate)); `None` when only the exact path of
    /// [`side`](Self::side) can.
    #[inline]
    pub fn filter_sign(&self, p: &[f64; D]) -> Option<Sign> {
        let (value, bound) = self.evaluate(p);
        if value > bound {
            Some(Sign::Positive)
        } else if -value > bound {
            Some(Sign::Negative)
        } else {
            None
        }
    }

    /// The exact sign of [`orientation`](super::orientation)`(vertices, p)` when this plane's
    /// vertices and `p` lie in the box and on the grid of one [`ExactGrid`](super::ExactGrid):
    /// the sign of [`value`](Self::value), which is then exact. For any other input the answer
    /// means nothing: callers hold the certificate.
    #[inline]
    pub fn side_on_grid(&self, p: &[f64; D]) -> Sign {
        exact::sign_of(self.value(p))
    }

    /// The exact sign of [`orientation`](super::orientation)`(vertices, p)`, where `vertices` are
    /// the points this plane was built from.
    ///
    /// Decided by the filter ([`evaluate`](Self::evaluate)) when `|value| > bound`; only otherwise
    /// is `vertices` called, and the exact predicate run. The closure must return the same
    /// vertices that were given to [`new`](Self::new), in the same order.
    ///
    /// # Panics
    /// On the exact path, if a coordinate is not finite.
    #[inline]
    pub fn side(&self, p: &[f64; D], vertices: impl FnOnce() -> [[f64; D]; D]) -> Sign {
        let (value, bound) = self.evaluate(p);
        if value > bound {
            Sign::Positive
        } else if -value > bound {
            Sign::Negative
        } else {
            self.side_after_filter(value, p, vertices)
        }
    }

    /// [`side`](Self::side) for a point the filter has already left undecided (`evaluate(p)`
    /// gave `|value| ≤ bound`, or a NaN): the exact stages alone, without evaluating the bound
    /// again (the caller's partition loop has just done so). `vertices` as for `side`.
    pub(crate) fn side_undecided(
        &self,
        p: &[f64; D],
        vertices: impl FnOnce() -> [[f64; D]; D],
    ) -> Sign {
        self.side_after_filter(self.value(p), p, vertices)
    }

    /// [`side_undecided`](Self::side_undecided) given the filter's `value` at `p` (this plane's
    /// [`value`](Self::value), which the caller's loop has just computed): not computed again.
    pub(crate) fn side_undecided_at(
        &self,
        value: f64,
        p: &[f64; D],
        vertices: impl FnOnce() -> [[f64; D]; D],
    ) -> Sign {
        debug_assert!(value.to_bits() == self.value(p).to_bits() || value.is_nan());
        self.side_after_filter(value, p, vertices)
    }

    /// The stages after the filter: the double-double plane first when this plane has built it
    /// and it needs no vertex ([`built_double_double`](Self::built_double_double)), the later
    /// stages only if it cannot decide; else every stage. The vertices are asked for only
    /// when a stage past the double-double one runs.
    #[inline(never)]
    fn side_after_filter(
        &self,
        value: f64,
        p: &[f64; D],
        vertices: impl FnOnce() -> [[f64; D]; D],
    ) -> Sign {
        let Some(dd) = self.built_double_double(p) else {
            return self.side_beyond_filter(value, p, &vertices(), false);
        };
        match dd.sign(&self.base, p, self.slack) {
            Some(sign) => sign,
            // Not again on the full route (on the raw Minkowski sums, whose points lie on
            // many planes exactly, the repeat was 3.4 % of Q∞'s instructions on 3 × 8).
            None => self.side_beyond_filter(value, p, &vertices(), true),
        }
    }

    /// The shortcut's answer alone (see [`built_double_double`](Self::built_double_double)):
    /// for the tests, which check it against the exact determinant.
    #[cfg(test)]
    pub(in crate::predicates) fn side_on_built_stages(&self, p: &[f64; D]) -> Option<Sign> {
        self.built_double_double(p)?.sign(&self.base, p, self.slack)
    }

    /// The double-double plane, when [`side_beyond_filter`](Self::side_beyond_filter)'s answer
    /// is sure to come from it or from a later stage and this plane has built it: its route is
    /// the plain one (no rebuilt rows), and the `f64` value is not exact, because `p`'s
    /// permanent does not fit even the base vertex's grid (every grid holding all the vertices
    /// and `p` is as fine or finer, and fits less). `None` otherwise: the full route decides.
    ///
    /// Why: on nearly coplanar input (a face sampled densely in a general pose) most points
    /// meet the filter's limit at every expansion near their face, and the same few planes
    /// decide them. There the full route took about three times the double-double test itself
    /// (424 instructions per test against 136, callgrind, the `tilted` family in 3-D): gathering
    /// the vertices from the point array, scanning `p`'s bits, asking which stages exist.
    #[inline(always)]
    fn built_double_double(&self, p: &[f64; D]) -> Option<&DdPlane<D>> {
        let refined = self.refined.get()?;
        if D >= 3 && refined.rebase.load(Ordering::Relaxed) != NO_ORDER {
            return None;
        }
        let dd = refined.dd.get()?.as_ref()?;
        let &base_grid = refined.base_grid.get()?;
        // A NaN permanent (a coordinate not finite) fits nothing: the double-double plane
        // then refuses `p` (it takes only coordinates in [−1, 1]).
        if base_grid == i32::MAX || permanent_fits::<D>(self.permanent(p), base_grid) {
            return None;
        }
        Some(dd)
    }

    /// The stages after the filter (see [`side`](Self::side)), out of line: compiled once per
    /// dimension rather than into every caller's loop, so that the callers' hot paths stay
    /// small and their inlining does not change with the stages (a build whose inlining of
    /// the wide-integer expansion changed ran the raw wrench hulls a quarter slower).
    /// `dd_tried`: the plain double-double stage has just failed to decide (it is skipped).
    #[inline(never)]
    fn side_beyond_filter(
        &self,
        value: f64,
        p: &[f64; D],
        vertices: &[[f64; D]; D],
        dd_tried: bool,
    ) -> Sign {
        if self.value_is_exact(vertices, p) {
            return exact::sign_of(value);
        }
        let finite = p.iter().all(|x| x.is_finite());
        if D >= 3
            && finite
            && let Some(rebased) = self.rebased(vertices)
        {
            let orient = |sign: Sign| if rebased.odd { sign.flip() } else { sign };
            let (value, bound) = rebased.plane.evaluate(p);
            if value > bound {
                return orient(Sign::Positive);
            }
            if -value > bound {
                return orient(Sign::Negative);
            }
            let dd = rebased
                .dd
                .get_or_init(|| DdPlane::new(&rebased.vertices, &rebased.plane, true));
            if let Some(sign) = dd
                .as_ref()
                .and_then(|plane| plane.sign(&rebased.plane.base, p, rebased.plane.slack))
            {
                return orient(sign);
            }
        } else if finite && !dd_tried {
            let refined = self.refined();
            refined
                .base_grid
                .get_or_init(|| grid_exponent(self.base.iter()));
            let dd = refined
                .dd
                .get_or_init(|| DdPlane::new(vertices, self, false));
            if let Some(sign) = dd
                .as_ref()
                .and_then(|plane| plane.sign(&self.base, p, self.slack))
            {
                return sign;
            }
        }
        if finite && let Some(sign) = self.exact_plane(vertices).and_then(|plane| plane.side(p)) {
            return sign;
        }
        exact::orientation(vertices, p)
    }

    /// Whether `evaluate(p)`'s value is exactly the determinant: true when every coordinate lies on
    /// a power-of-two grid 2^g and the determinant's permanent is below 2^52 grid units^D (integer
    /// lattices, cube corners, dyadic input — exactly the inputs whose determinants vanish).
    ///
    /// Why it suffices: in units of the grid every entry is an integer; every product and partial
    /// sum that contributes to the value is bounded by the permanent (a sub-minor only contributes
    /// multiplied by non-zero entries, each at least one unit, so its permanent is no larger), hence
    /// is an integer below 2^52, exactly representable, so no operation rounds. Non-contributing
    /// sub-minors are multiplied by exact zeros. Underflow is excluded by `g·D ≥ −1000`.
    fn value_is_exact(&self, vertices: &[[f64; D]; D], p: &[f64; D]) -> bool {
        if !p.iter().all(|x| x.is_finite()) {
            return false;
        }
        let permanent = self.permanent(p);
        let fits = |g: i32| permanent_fits::<D>(permanent, g);
        // The grid of all the entries is no coarser than `p`'s alone, so a permanent too large
        // in `p`'s units is too large in theirs. Nor is it coarser than any one coordinate's,
        // and `fits` only fails more on a finer grid (more units; below the range too) once
        // `g·D ≤ 1000`: so the first such coordinate whose own grid does not fit answers, and
        // every slow test on raw floating-point data (lowest bits near 2^-53 of the largest)
        // is turned away after one bit scan rather than D.
        let mut own = i32::MAX;
        for &x in p.iter().filter(|&&x| x != 0.0) {
            let g = exact::lowest_bit_exponent(x);
            if g.saturating_mul(D as i32) <= 1000 && !fits(g) {
                return false;
            }
            own = own.min(g);
        }
        if !fits(own) {
            return false;
        }
        // Computed here, on the slow path, rather than cached per facet: it costs D² bit scans.
        fits(own.min(grid_exponent(vertices.iter().flatten())))
    }

    /// The permanent of `det[v1 − v0; …; p − v0]` (the determinant with every product's
    /// absolute value), from the plane's per-column permanents: what
    /// [`value_is_exact`](Self::value_is_exact) bounds.
    #[inline(always)]
    fn permanent(&self, p: &[f64; D]) -> f64 {
        p.iter()
            .zip(&self.base)
            .zip(&self.permanents)
            .map(|((&x, &b), &q)| q * (x - b).abs())
            .sum()
    }

    /// Per-component error coefficients: `|Ĉ_j − C_j| ≤ cofactor_errors()[j]` for the computed
    /// cofactors `Ĉ` (the coefficients also cover the rounding of `p − v0` in
    /// [`evaluate`](Self::evaluate), so they are a little generous as cofactor bounds).
    pub fn cofactor_errors(&self) -> &[f64; D] {
        &self.error
    }

    /// The direction of the exact cofactor vector, correctly rounded up to a common power-of-two
    /// scale: an accurate normal even when the floating-point cofactors cancel (slivers).
    ///
    /// Costs D exact (D−1)×(D−1) determinants: use it only when
    /// [`cofactor_errors`](Self::cofactor_errors) says the floating-point cofactors are poor.
    ///
    /// The exact cofactors are kept for this plane's later exact side tests.
    pub fn exact_normal_direction(&self, vertices: &[[f64; D]; D]) -> [f64; D] {
        match self.exact_plane(vertices) {
            Some(plane) => plane.normal_direction(),
            None => exact::exact_cofactor_direction(vertices),
        }
    }

    /// The direction of the cofactor vector up to a positive scale, every component within
    /// `2^-51` of the largest (four ulps) of the exact cofactors at that scale: from the
    /// double-double plane when its certified cofactor errors allow it (D ≥ 4; built on first
    /// use and kept for later side tests), else from the exact cofactors
    /// ([`exact_normal_direction`](Self::exact_normal_direction)).
    ///
    /// Why: a full hull refines the normal of every thin facet (whose `f64` cofactors cancel),
    /// and on rounding-degenerate input (raw wrench sets) that is half the facets; the exact
    /// cofactors cost about twice the double-double plane, which certifies all but the thinnest.
    pub fn refined_normal_direction(&self, vertices: &[[f64; D]; D]) -> [f64; D] {
        if D >= 4 {
            let refined = self.refined();
            // A sliver's double-double cofactors cannot be certified to four ulps (their error
            // bound scales with the permanent, they with the tiny |C|): unless the plane is
            // there already, its `f64` cofactors say so, and the exact route is taken at once.
            if refined.dd.get().is_none() && self.dd_normal_surely_uncertified() {
                return self.exact_normal_direction(vertices);
            }
            let dd = refined
                .dd
                .get_or_init(|| DdPlane::new(vertices, self, false));
            if let Some(plane) = dd {
                let (cofactors, error) = plane.cofactors_with_error();
                let largest = cofactors.iter().fold(0.0f64, |m, c| m.max(c.abs()));
                let worst = error.iter().fold(0.0f64, |m, e| m.max(*e));
                if largest >= MIN_DD_NORMAL && worst <= DD_NORMAL_TOLERANCE * largest {
                    return cofactors;
                }
            }
        }
        self.exact_normal_direction(vertices)
    }

    /// Whether the double-double plane's cofactors surely miss the normal's certificate (see
    /// [`DdPlane::normal_surely_uncertified`]), from the `f64` cofactors and their certified
    /// errors: every exact cofactor is at most `|Ĉ_j| + error_j` (times `1 + 2^-40` there for
    /// this sum's rounding).
    pub(in crate::predicates) fn dd_normal_surely_uncertified(&self) -> bool {
        let largest = self
            .cofactors
            .iter()
            .zip(&self.error)
            .fold(0.0f64, |m, (c, e)| m.max(c.abs() + e));
        DdPlane::normal_surely_uncertified(largest, &self.permanents, DD_NORMAL_TOLERANCE)
    }

    /// The signed distance of `p` beyond the plane through `vertices` (the points this plane was
    /// built from), `det[v1 − v0; …; p − v0] / |C|`, from the exact determinant and the exact
    /// cofactors: a few ulps however close `p` is to the plane, where the floating-point value
    /// is only accurate to the rounding of the plane's offset.
    ///
    /// Costs the exact plane (built once and kept) and one exact evaluation — as much as a slow
    /// [`side`](Self::side) test: for points the filter cannot place far from the plane.
    ///
    /// # Panics
    /// If a coordinate is not finite.
    pub fn exact_distance(&self, vertices: &[[f64; D]; D], p: &[f64; D]) -> f64 {
        match self
            .exact_plane(vertices)
            .and_then(|plane| plane.distance(p))
        {
            Some(distance) => distance,
            None => exact::distance_big(vertices, p),
        }
    }

    /// The cached exact plane, built on first use.
    fn exact_plane(&self, vertices: &[[f64; D]; D]) -> Option<&ExactPlane<D>> {
        self.refined()
            .exact
            .get_or_init(|| ExactPlane::new(vertices))
            .as_ref()
    }

    /// The double-double plane through the same vertices, as [`side`](Self::side) builds it,
    /// with the base and the slack its evaluation takes (for the tests of the second stage).
    #[cfg(test)]
    pub(in crate::predicates) fn double_double(
        &self,
        vertices: &[[f64; D]; D],
    ) -> (Option<DdPlane<D>>, [f64; D], f64) {
        (DdPlane::new(vertices, self, false), self.base, self.slack)
    }

    /// The slower stages' cache, allocated on first use.
    fn refined(&self) -> &Refined<D> {
        self.refined.get_or_init(Box::default)
    }

    /// The plane rebuilt from better rows, if [`better_order`] finds them: decided once per
    /// plane whose slower stages exist (every answer is right whichever a race between threads
    /// gives: `None` leaves the test to this plane's own stages).
    fn rebased(&self, vertices: &[[f64; D]; D]) -> Option<&Rebased<D>> {
        if let Some(refined) = self.refined.get() {
            match refined.rebase.load(Ordering::Relaxed) {
                NO_ORDER => return None,
                REBUILT => return refined.rebased.get().map(|r| &**r),
                _ => {}
            }
        }
        match better_order(vertices) {
            None => {
                // Without the stages' cache (3-D, or before the double-double stage), the
                // question is asked again next time: cheaper than allocating the cache.
                if let Some(refined) = self.refined.get() {
                    refined.rebase.store(NO_ORDER, Ordering::Relaxed);
                }
                None
            }
            Some((order, odd)) => {
                let refined = self.refined();
                let rebased = refined.rebased.get_or_init(|| {
                    let vertices = order.map(|k| vertices[k]);
                    Box::new(Rebased {
                        plane: ManuallyDrop::new(FacetPlane::chained(&vertices)),
                        vertices,
                        odd,
                        dd: OnceLock::new(),
                    })
                });
                refined.rebase.store(REBUILT, Ordering::Relaxed);
                Some(rebased)
            }
        }
    }

    /// The cofactor vector `C`: `det[v1 − v0; …; v(D−1) − v0; p − v0] = Σ_j C_j·(p_j − v0_j)`
    /// exactly for the exact cofactors; these are their floating-point approximations. It is an
    /// unnormalised normal of the hyperplane, pointing to its positive side.
    pub fn cofactors(&self) -> &[f64; D] {
        &self.cofactors
    }

    /// The base vertex `v0` (the first vertex given to [`new`](Self::new)).
    pub fn base(&self) -> &[f64; D] {
        &self.base
    }
}
