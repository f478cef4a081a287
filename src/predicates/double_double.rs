//! The second stage of the side test: the facet's hyperplane in double-double arithmetic, with a
//! certified error bound.
//!
//! Between the `f64` filter (relative accuracy ~2^-53 of the permanent) and exact integer
//! arithmetic sits a large class of inputs: points that are *nearly* on a facet's hyperplane
//! because the caller's data are degenerate only up to rounding — the raw wrenches of a contact,
//! which lie in one plane up to the rounding of their torques, and Minkowski sums of them. Their
//! determinants are around 2^-53 of the permanent: too small for the filter, and every one sent
//! to the exact path cost the exact cofactors of its facet (most of a raw wrench hull's time).
//! Double-double arithmetic (each value an unevaluated sum `hi + lo` of two `f64`) carries about
//! 2^-101 relative accuracy at ~20 `f64` operations per operation, so it decides those signs with
//! a margin of ~2^48, and leaves to the exact path only the determinants that are zero or within
//! ~2^-97 of the permanent.
//!
//! No maintained crate offers double-double arithmetic with the *rigorous* per-operation bounds
//! this certificate needs (the `twofloat` and `qd` ports document no bounds), hence the few
//! functions below, each from the literature with its proven bound.
//!
//! # Error model
//!
//! With `u = 2^-53`, every operation below returns `(x ∘ y)(1 + δ)` with `|δ| ≤ U2 = 2^-101 =
//! 32u²`, barring underflow (treated as for the filter, by an absolute slack):
//! * [`add`] is Joldes, Muller and Popescu's *AccurateDWPlusDW* (ACM TOMS 44(2), 2017, Algorithm
//!   6): `|δ| ≤ 3u² + 13u³`;
//! * [`mul`] is their *DWTimesDW1* (Algorithm 10, Dekker's product), with Veltkamp's splitting
//!   for the exact product of the high parts: `|δ| ≤ 7u²` (CRlibm's `Mul22`, the same algorithm,
//!   documents `2^-102 = 16u²`);
//! * the difference of two `f64` is exact as a double-double ([`two_sum`]).
//!
//! Splitting is exact for `|x| ≤ 2^996`; the plane is only built for coordinates in `[−1, 1]`,
//! where every minor is below `D!·2^D`.

use super::minors::{MinorScalar, minors_inlined, minors_of};
use super::{FacetPlane, Sign};

#[cfg(target_arch = "x86_64")]
mod lanes;

/// The per-operation relative error bound of the model, `2^-101` (over four times the proven
/// bounds of [`add`] and [`mul`]).
const U2: f64 = 3.944304526105059e-31; // 2^-101

/// Unit roundoff of `f64` (round to nearest).
const U: f64 = f64::EPSILON / 2.0;

/// `2^27 + 1`, Veltkamp's splitting constant for 53-bit significands.
const SPLITTER: f64 = 134_217_729.0;

/// An unevaluated sum `hi + lo` with `|lo| ≤ ulp(hi)/2` (after normalisation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::predicates) struct Dd {
    hi: f64,
    lo: f64,
}

/// `(s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly (Knuth's TwoSum, no precondition).
#[inline(always)]
fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let a1 = s - b;
    let b1 = s - a1;
    Dd {
        hi: s,
        lo: (a - a1) + (b - b1),
    }
}

/// TwoSum when `|a| ≥ |b|` (or `a` is zero): three operations (Dekker's Fast2Sum).
#[inline(always)]
fn fast_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    Dd {
        hi: s,
        lo: b - (s - a),
    }
}

/// Veltkamp's split of `a` into two halves of at most 26 significant bits each.
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `(p, e)` with `p = fl(a·b)` and `p + e = a·b` exactly (Dekker's TwoProduct; exact barring
/// underflow and overflow). Written without `mul_add`, which is a library call where the target
/// has no FMA instruction.
#[inline(always)]
fn two_prod(a: f64, b: f64) -> Dd {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    Dd {
        hi: p,
        lo: ((ah * bh - p) + ah * bl + al * bh) + al * bl,
    }
}

/// [`two_prod`] from one fused multiply-add: `fl(a·b − p)` is `a·b − p` exactly (the error of
/// a rounded product is representable, barring underflow), so the pair is the same as Dekker's,
/// bit for bit, in 2 operations instead of 17.
#[inline(always)]
fn two_prod_fused(a: f64, b: f64) -> Dd {
    let p = a * b;
    Dd {
        hi: p,
        lo: a.mul_add(b, -p),
    }
}

/// `x + y` (AccurateDWPlusDW).
#[inline(always)]
fn add(x: Dd, y: Dd) -> Dd {
    let s = two_sum(x.hi, y.hi);
    let t = two_sum(x.lo, y.lo);
    let v = fast_two_sum(s.hi, s.lo + t.hi);
    fast_two_sum(v.hi, t.lo + v.lo)
}

/// `x·y` (DWTimesDW1).
#[inline(always)]
fn mul(x: Dd, y: Dd) -> Dd {
    mul_with(x, y, two_prod)
}

/// DWTimesDW1 with the exact product of the high parts from `two_prod` (Dekker's or the fused
/// one: the same pair, so the same result).
#[inline(always)]
fn mul_with(x: Dd, y: Dd, two_prod: impl Fn(f64, f64) -> Dd) -> Dd {
    let c = two_prod(x.hi, y.hi);
    let cross = x.hi * y.lo + x.lo * y.hi;
    fast_two_sum(c.hi, c.lo + cross)
}

impl Dd {
    const ONE: Dd = Dd { hi: 1.0, lo: 0.0 };
    const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };

    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    /// The exact difference `a − b`.
    fn difference(a: f64, b: f64) -> Dd {
        two_sum(a, -b)
    }
}

impl MinorScalar for Dd {
    const ONE: Self = Dd::ONE;
    const ZERO: Self = Dd::ZERO;
    #[inline(always)]
    fn accumulate(acc: Self, entry: Self, minor: Self, negative: bool) -> Self {
        let term = mul(entry, minor);
        add(acc, if negative { term.neg() } else { term })
    }
    /// The term alone: [`add`] of zero and a normalised double-double (which [`mul`] returns)
    /// is that double-double (up to the sign of a zero), so this is `accumulate(ZERO, …)` with
    /// no rounding skipped — the error model is unchanged — at two thirds of its cost.
    #[inline(always)]
    fn first(entry: Self, minor: Self, negative: bool) -> Self {
        let term = mul(entry, minor);
        if negative { term.neg() } else { term }
    }
}

/// A double-double of the minors' expansion whose products take a fused multiply-add
/// ([`two_prod_fused`]): the same numbers as [`Dd`]'s, bit for bit, in about two thirds of the
/// time where the processor fuses (see [`dd_minors`]); elsewhere `mul_add` is a library call,
/// correct but slow.
#[derive(Clone, Copy, Debug)]
struct Fused(Dd);

impl MinorScalar for Fused {
    const ONE: Self = Fused(Dd::ONE);
    const ZERO: Self = Fused(Dd::ZERO);
    #[inline(always)]
    fn accumulate(acc: Self, entry: Self, minor: Self, negative: bool) -> Self {
        let term = mul_with(entry.0, minor.0, two_prod_fused);
        Fused(add(acc.0, if negative { term.neg() } else { term }))
    }
    /// As [`Dd`]'s `first`: the term alone.
    #[inline(always)]
    fn first(entry: Self, minor: Self, negative: bool) -> Self {
        let term = mul_with(entry.0, minor.0, two_prod_fused);
        Fused(if negative { term.neg() } else { term })
    }
}

/// The minors of [`minors_of`] in double-double, with fused multiply-adds where the processor
/// has them: the same numbers either way (see [`Fused`]), so the plane's error analysis is
/// untouched. Raw wrench hulls build this plane for about two facets in five, and Dekker's
/// products were most of its time (the raw wrench hull at 4 × 16 took 11 % less time with them
/// fused, `cli/examples/profile_hull.rs`).
fn dd_minors<const D: usize>(rows: &[[Dd; D]; D]) -> [Dd; D] {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("fma") && std::arch::is_x86_feature_detected!("avx")
        {
            // One of the library's three `unsafe` calls (lib.rs says why they are allowed).
            #[allow(unsafe_code)]
            // SAFETY: `fused_minors_x86` only requires the `avx` and `fma` target features,
            // which the processor was just found to have.
            return unsafe { fused_minors_x86(rows) };
        }
        minors_of(rows)
    }
    #[cfg(target_arch = "aarch64")]
    {
        // Every AArch64 processor fuses.
        fused_minors(rows)
    }
    #[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
    {
        minors_of(rows)
    }
}

/// [`fused_minors`] compiled with the `avx` and `fma` features, so that `mul_add` is one
/// instruction (the expansion is inlined into it); in 6-D, four minors at a time in 256-bit
/// vectors ([`lanes`]: the same numbers, bit for bit).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx,fma")]
fn fused_minors_x86<const D: usize>(rows: &[[Dd; D]; D]) -> [Dd; D] {
    if D == 6 {
        let mut six = [[Dd::ZERO; 6]; 6];
        for (to, from) in six.iter_mut().zip(rows) {
            to.copy_from_slice(&from[..6]);
        }
        let minors = lanes::minors6_lanes(&six);
        let mut out = [Dd::ZERO; D];
        out[..6].copy_from_slice(&minors);
        return out;
    }
    fused_minors(rows)
}

/// The minors with [`Fused`] products, the expansion inlined here (a call to a generic
/// expansion compiled without the `fma` feature would turn every `mul_add` into a library call).
#[inline(always)]
fn fused_minors<const D: usize>(rows: &[[Dd; D]; D]) -> [Dd; D] {
    let fused = rows.map(|row| row.map(Fused));
    minors_inlined(&fused).map(|m| m.0)
}

/// A facet's hyperplane in double-double: the cofactors of the last row of
/// `[v1 − v0; …; v(D−1) − v0; ·]` and per-coordinate error coefficients, so that
/// `Σ_j C_j·(p_j − v0_j)` approximates the orientation determinant with a certified bound
/// `Σ_j err_j·|p_j − v0_j| + slack`.
#[derive(Clone, Debug)]
pub(in crate::predicates) struct DdPlane<const D: usize> {
    cofactors: [Dd; D],
    error: [f64; D],
}

/// The error coefficients of [`DdPlane::new`]: on the filter's permanent `P̂_j`, and on `|C_j|`.
///
/// Why they are safe, under the model `fl(x ∘ y) = (x ∘ y)(1 + δ)`, `|δ| ≤ U2` (the counting of
/// [`FacetPlane::new`](super::FacetPlane::new)'s analysis, `γ_n = n·U2/(1 − n·U2)`): the rows are
/// exact, a minor of size k carries at most k factors on each of its terms (one product, at most
/// k − 1 sums; a first term is the product alone, a size-1 minor one product by one), so each
/// term of a cofactor carries at most `n = 1 + Σ_(k=2..D−1) k = (D − 1)D/2` (15 in 6-D) and
/// `|Ĉ_j − C_j| ≤ γ_n·P_j`, `P_j` the exact permanent. The filter computed `P̂_j ≥ (1 −
/// γ_m(u))·P_j` (`m ≤ 34` roundings of `f64`, its own analysis), a relative `2^-46` at most. The
/// side test's dot product (a product and at most D sums per term, on exact differences) adds
/// `γ_(D+1)·Σ|C_j|·|d_j|`. So `(n + 1)·U2` and `(D + 2)·U2`: their excess over `γ_n/(1 − 2^-46)`
/// and `γ_(D+1)`, a relative `1/n` and `1/(D + 1)`, covers the second-order terms and the few
/// `f64` roundings of the errors' own computation. (Until 2026-12-07 they were
/// `2(D² + 4D + 8)·U2` and `(D + 3)·U2`, the filter's old first-order estimate: 136 against
/// 16 in 6-D.)
fn coefficients<const D: usize>() -> (f64, f64) {
    let n = ((D - 1) * D / 2) as f64;
    ((n + 1.0) * U2, (D as f64 + 2.0) * U2)
}

impl<const D: usize> DdPlane<D> {
    /// The plane through `vertices`, every coordinate in `[−1, 1]` (`None` otherwise), with the
    /// permanents of |minor| behind each cofactor as `filter`, the filter's plane through the same
    /// `vertices`, computed them; from the rows `v_k − v_(k−1)` when `chained` (as
    /// [`FacetPlane`]'s chained plane), else `v_k − v0`. Whether the coordinates are in range is
    /// `filter`'s answer ([`FacetPlane::in_range`]): checking the D² coordinates again cost a
    /// twentieth of this plane.
    ///
    /// # Panics
    /// In debug builds, if `filter` was not built from coordinates in range exactly when these
    /// are.
    ///
    /// Error analysis: the rows `v_k − v0` are exact double-doubles, so only the expansion and the
    /// final dot product round; the coefficients and why they are safe are [`coefficients`]'s.
    /// The permanents are the filter's, computed in `f64` from rounded entries.
    pub(in crate::predicates) fn new(
        vertices: &[[f64; D]; D],
        filter: &FacetPlane<D>,
        chained: bool,
    ) -> Option<Self> {
        let in_range = filter.in_range();
        debug_assert_eq!(in_range, vertices.iter().flatten().all(|x| x.abs() <= 1.0));
        if !in_range {
            return None;
        }
        let permanents = &filter.permanents;
        let base = vertices[0];
        let mut rows = [[Dd::ZERO; D]; D];
        for k in 1..D {
            let from = if chained { &vertices[k - 1] } else { &base };
            for j in 0..D {
                rows[k][j] = Dd::difference(vertices[k][j], from[j]);
            }
        }
        let minors = dd_minors(&rows);
        let (c_perm, c_cof) = coefficients::<D>();
        let mut cofactors = [Dd::ZERO; D];
        let mut error = [0.0; D];
        for j in 0..D {
            let c = if (D - 1 + j) % 2 == 1 {
                minors[j].neg()
            } else {
                minors[j]
            };
            cofactors[j] = c;
            // |C| ≤ |hi|(1 + u): the factor covers the low part.
            error[j] = (c_perm * permanents[j] + c_cof * c.hi.abs()) * (1.0 + 2.0 * U);
        }
        Some(DdPlane { cofactors, error })
    }

    /// Whether the plane [`new`](Self::new) would build with these `permanents` surely fails a
    /// normal's certificate — [`cofactors_with_error`](Self::cofactors_with_error) giving some
    /// error above `tolerance` times the largest cofactor — given `largest`, an upper bound on
    /// every exact cofactor's magnitude: then building it for a normal is wasted (the exact
    /// cofactors are needed).
    ///
    /// Why it is sure: every error the plane reports is at least `c_perm·permanents[j]` (see
    /// [`new`](Self::new)), so `least_error` below is at most the worst. If the certificate held,
    /// `worst ≤ tolerance·|hi_k|` for the largest high part `hi_k`, whose distance to the exact
    /// `C_k` is at most that worst: `|hi_k| ≤ |C_k|/(1 − tolerance) ≤ largest/(1 − tolerance)`,
    /// hence `least_error ≤ tolerance·largest/(1 − tolerance)`. The factor `1 + 2^-40` covers
    /// `1/(1 − tolerance)` for any tolerance below `2^-42` and the roundings on both sides.
    pub(in crate::predicates) fn normal_surely_uncertified(
        largest: f64,
        permanents: &[f64; D],
        tolerance: f64,
    ) -> bool {
        debug_assert!(tolerance < 1.0 / (1u64 << 42) as f64);
        let (c_perm, _) = coefficients::<D>();
        let least_error = permanents.iter().fold(0.0f64, |m, &q| m.max(c_perm * q));
        tolerance * largest * (1.0 + 1.0 / (1u64 << 40) as f64) < least_error
    }

    /// The high parts of the cofactors and a bound on the error of each as an approximation of
    /// the exact cofactor: the generous coefficients of [`new`](Self::new) (which also cover the
    /// dot product of a side test) plus the dropped low part (at most half an ulp of the high).
    pub(in crate::predicates) fn cofactors_with_error(&self) -> ([f64; D], [f64; D]) {
        let hi = self.cofactors.map(|c| c.hi);
        let error = std::array::from_fn(|j| self.error[j] + hi[j].abs() * U);
        (hi, error)
    }

    /// [`evaluate_then`](Self::evaluate_then)'s value and bound themselves, for the tests (the
    /// engine asks only for the [`sign`](Self::sign)).
    #[cfg(test)]
    pub(in crate::predicates) fn evaluate(
        &self,
        base: &[f64; D],
        p: &[f64; D],
        slack: f64,
    ) -> Option<((f64, f64), f64)> {
        self.evaluate_then(base, p, slack, |evaluated| evaluated)
    }

    /// `finish` applied to the double-double value of `det[v1 − v0; …; p − v0]` (as `(hi, lo)`)
    /// and a certified bound on its error: `|hi + lo − det| ≤ bound`. `base` is `v0`; `slack`
    /// the filter's absolute underflow slack (finite: the vertices are in `[−1, 1]`). `None`
    /// unless every coordinate of `p` is in `[−1, 1]`.
    ///
    /// The bound adds `Σ err_j·|d_j|` (cofactor errors and the dot product's `D` roundings are in
    /// `err_j`, see [`new`](Self::new)), inflated by `1 + 2^-40` for its own `f64` roundings and
    /// for `|d_j| ≤ |fl(d_j)|(1 + u)`, and the underflow slack: the filter's argument holds for
    /// the ~20 `f64` operations of each double-double one (`(2·8)^9 · 20 · 2^-1075 < 2^-1000`).
    ///
    /// `finish` runs inside the code compiled for fused products where the processor has them,
    /// so that a caller that wants less than the value and bound (the [`sign`](Self::sign))
    /// gets it without them passing through memory: on the `tilted` family in 3-D, a `sign`
    /// call took 194 instructions, 58 of them outside the evaluation, before `finish` moved in
    /// (callgrind).
    #[inline]
    fn evaluate_then<R>(
        &self,
        base: &[f64; D],
        p: &[f64; D],
        slack: f64,
        finish: impl FnOnce(((f64, f64), f64)) -> R,
    ) -> Option<R> {
        if !p.iter().all(|x| x.abs() <= 1.0) {
            return None;
        }
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("fma")
                && std::arch::is_x86_feature_detected!("avx")
            {
                // One of the library's three `unsafe` calls (lib.rs says why they are allowed).
                #[allow(unsafe_code)]
                // SAFETY: `evaluate_fused_x86` only requires the `avx` and `fma` target
                // features, which the processor was just found to have.
                return Some(unsafe { self.evaluate_fused_x86(base, p, slack, finish) });
            }
        }
        Some(finish(self.evaluate_with(base, p, slack, two_prod)))
    }

    /// [`evaluate_with`](Self::evaluate_with) with fused products, compiled with the `avx` and
    /// `fma` features so that `mul_add` is one instruction: the same numbers as Dekker's, bit
    /// for bit (see [`two_prod_fused`]). On nearly coplanar 3-D input, where this test runs for
    /// most points near a face, a side test on this plane took 40 % more instructions with
    /// Dekker's products (274 against 194 per `DdPlane::sign` call, callgrind).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx,fma")]
    fn evaluate_fused_x86<R>(
        &self,
        base: &[f64; D],
        p: &[f64; D],
        slack: f64,
        finish: impl FnOnce(((f64, f64), f64)) -> R,
    ) -> R {
        finish(self.evaluate_with(base, p, slack, two_prod_fused))
    }

    /// The value and bound of [`evaluate_then`](Self::evaluate_then), for `p` in the box, with the exact
    /// products of `two_prod` (Dekker's or the fused one: the same pair).
    #[inline(always)]
    fn evaluate_with(
        &self,
        base: &[f64; D],
        p: &[f64; D],
        slack: f64,
        two_prod: impl Fn(f64, f64) -> Dd + Copy,
    ) -> ((f64, f64), f64) {
        // The first term alone, not added to zero: `add` of zero and a normalised double-double
        // (which `mul_with` returns) is that double-double up to the sign of a zero, so no
        // rounding is skipped and the bound is unchanged (as `MinorScalar::first`).
        let d = Dd::difference(p[0], base[0]);
        let mut value = mul_with(self.cofactors[0], d, two_prod);
        let mut bound = self.error[0] * d.hi.abs();
        for j in 1..D {
            let d = Dd::difference(p[j], base[j]);
            value = add(value, mul_with(self.cofactors[j], d, two_prod));
            bound += self.error[j] * d.hi.abs();
        }
        let bound = bound * (1.0 + 1.0 / (1u64 << 40) as f64) + slack;
        ((value.hi, value.lo), bound)
    }

    /// The sign of `det[v1 − v0; …; p − v0]` when the double-double value exceeds its bound
    /// ([`evaluate_then`](Self::evaluate_then)), `None` otherwise.
    #[inline]
    pub(in crate::predicates) fn sign(
        &self,
        base: &[f64; D],
        p: &[f64; D],
        slack: f64,
    ) -> Option<Sign> {
        self.evaluate_then(base, p, slack, |((hi, _), bound)| {
            // |hi + lo| ≥ |hi|·(1 − u) after normalisation; 2^-50 covers it.
            if hi.abs() * (1.0 - 1.0 / (1u64 << 50) as f64) > bound {
                Some(if hi > 0.0 {
                    Sign::Positive
                } else {
                    Sign::Negative
                })
            } else {
                None
            }
        })?
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fails on an x86-64 processor without AVX and FMA, where the dispatch under test would be
    /// Dekker's `what` itself and a comparison with Dekker's would be vacuous.
    #[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))]
    fn assert_the_processor_fuses(what: &str) {
        #[cfg(target_arch = "x86_64")]
        assert!(
            std::arch::is_x86_feature_detected!("fma")
                && std::arch::is_x86_feature_detected!("avx"),
            "this processor lacks AVX or FMA: the dispatch would compare Dekker's {what} with \
             itself"
        );
    }

    /// `first` is `accumulate` onto zero, to the last bit of both parts (the minors' claim that
    /// skipping the addition changes no number), on terms of every magnitude and sign.
    #[test]
    fn the_first_term_is_the_accumulation_onto_zero() {
        let mut rng = crate::geometry::Rng::new(17);
        for case in 0..20_000 {
            let dd = |rng: &mut crate::geometry::Rng| {
                let hi = rng.uniform_in(-1.0, 1.0) * 2f64.powi(rng.below(120) as i32 - 60);
                two_sum(hi, hi * rng.uniform_in(-1.0, 1.0) * 2f64.powi(-60))
            };
            let (entry, minor) = (dd(&mut rng), dd(&mut rng));
            let negative = case % 2 == 0;
            let skipped = Dd::first(entry, minor, negative);
            let added = Dd::accumulate(Dd::ZERO, entry, minor, negative);
            assert_eq!(
                (skipped.hi.to_bits(), skipped.lo.to_bits()),
                (added.hi.to_bits(), added.lo.to_bits()),
                "case {case}: {entry:?} × {minor:?}"
            );
        }
    }

    /// The fused products give the expansion's numbers bit for bit (the claim that lets the
    /// plane's error analysis stand unchanged): on random rows of every magnitude, in 4-D to
    /// 8-D, through the dispatch (fused where this processor fuses, four lanes at a time in 6-D
    /// where it has AVX) and through the portable expansion with `Fused` (`mul_add` correctly
    /// rounded in software elsewhere), against Dekker's products. On an x86-64 processor
    /// without AVX and FMA the dispatch would be Dekker's expansion itself, and the test fails
    /// rather than pass with half its comparisons vacuous.
    #[test]
    fn fused_products_give_the_same_minors_bit_for_bit() {
        assert_the_processor_fuses("minors");
        fn check<const D: usize>(rng: &mut crate::geometry::Rng) {
            for case in 0..300 {
                let rows: [[Dd; D]; D] = std::array::from_fn(|_| {
                    std::array::from_fn(|_| {
                        let scale = 2f64.powi(rng.below(40) as i32 - 20);
                        let a = rng.uniform_in(-1.0, 1.0) * scale;
                        Dd::difference(a, rng.uniform_in(-1.0, 1.0) * scale)
                    })
                });
                let bits = |m: [Dd; D]| m.map(|d| (d.hi.to_bits(), d.lo.to_bits()));
                let dekker = bits(minors_of(&rows));
                assert_eq!(bits(dd_minors(&rows)), dekker, "{D}-D case {case}");
                assert_eq!(bits(fused_minors(&rows)), dekker, "{D}-D case {case}");
            }
        }
        let mut rng = crate::geometry::Rng::new(29);
        // 6-D (where x86-64 with AVX takes the four-lane expansion, `lanes`) also on rows with
        // exact zeros and entries 2^±40 apart, and on nearly dependent rows (the slivers the
        // stage exists for): many more cases.
        for case in 0..5_000 {
            let base: [f64; 6] = std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0));
            let rows: [[Dd; 6]; 6] = std::array::from_fn(|_| {
                let tilt = 2f64.powi(-(rng.below(50) as i32));
                std::array::from_fn(|j| match rng.below(8) {
                    0 => Dd::ZERO,
                    1 => Dd::difference(base[j], base[j] * (1.0 - tilt)),
                    // Operands far apart: an inexact difference, so a low part to multiply.
                    2 | 3 => Dd::difference(base[j], rng.uniform_in(-1.0, 1.0) * tilt),
                    _ => {
                        let scale = 2f64.powi(rng.below(80) as i32 - 40);
                        let a = rng.uniform_in(-1.0, 1.0) * scale;
                        Dd::difference(a, rng.uniform_in(-1.0, 1.0) * scale)
                    }
                })
            });
            let bits = |m: [Dd; 6]| m.map(|d| (d.hi.to_bits(), d.lo.to_bits()));
            assert_eq!(
                bits(dd_minors(&rows)),
                bits(minors_of(&rows)),
                "6-D case {case}"
            );
        }
        check::<4>(&mut rng);
        check::<5>(&mut rng);
        check::<6>(&mut rng);
        check::<7>(&mut rng);
        check::<8>(&mut rng);
    }

    /// A side test's value and bound with fused products (the dispatch of `evaluate`) are
    /// Dekker's, bit for bit, in 2-D to 8-D, on points near and far from planes through random
    /// and nearly dependent vertices. Without AVX and FMA the test fails rather than compare
    /// Dekker's evaluation with itself.
    #[test]
    fn fused_evaluation_is_dekker_s_bit_for_bit() {
        assert_the_processor_fuses("evaluation");
        fn check<const D: usize>(rng: &mut crate::geometry::Rng) {
            for case in 0..400 {
                let mut vertices: [[f64; D]; D] =
                    std::array::from_fn(|_| std::array::from_fn(|_| rng.uniform_in(-0.5, 0.5)));
                if case % 2 == 1 {
                    // A sliver: the last vertex a hair off the first two's line.
                    let t = rng.uniform();
                    let hair = 2f64.powi(-2 - rng.below(58) as i32);
                    vertices[D - 1] = std::array::from_fn(|j| {
                        vertices[0][j]
                            + t * (vertices[1][j] - vertices[0][j])
                            + hair * rng.uniform_in(-1.0, 1.0)
                    });
                }
                let plane = FacetPlane::new(&vertices);
                let (dd, base, slack) = plane.double_double(&vertices);
                let dd = dd.expect("vertices in the box");
                for k in 0..8 {
                    // Near the plane (a vertex moved by a little) or anywhere in the box.
                    let p: [f64; D] = if k % 2 == 0 {
                        let offset = 2f64.powi(-(rng.below(100) as i32));
                        vertices[k % D]
                            .map(|x| (x + offset * rng.uniform_in(-1.0, 1.0)).clamp(-1.0, 1.0))
                    } else {
                        std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0))
                    };
                    let bits = |((hi, lo), bound): ((f64, f64), f64)| {
                        (hi.to_bits(), lo.to_bits(), bound.to_bits())
                    };
                    let dekker = bits(dd.evaluate_with(&base, &p, slack, two_prod));
                    let dispatched = dd.evaluate(&base, &p, slack).expect("p in the box");
                    assert_eq!(bits(dispatched), dekker, "{D}-D case {case}, point {k}");
                }
            }
        }
        let mut rng = crate::geometry::Rng::new(31);
        check::<2>(&mut rng);
        check::<3>(&mut rng);
        check::<4>(&mut rng);
        check::<6>(&mut rng);
        check::<8>(&mut rng);
    }

    #[test]
    fn two_prod_and_two_sum_are_exact() {
        // (1 + 2^-30)² = 1 + 2^-29 + 2^-60: the last term is the error of the rounded product.
        let a = 1.0 + 2f64.powi(-30);
        let p = two_prod(a, a);
        assert_eq!((p.hi, p.lo), (1.0 + 2f64.powi(-29), 2f64.powi(-60)));
        let s = two_sum(1.0, 2f64.powi(-80));
        assert_eq!((s.hi, s.lo), (1.0, 2f64.powi(-80)));
    }

    #[test]
    fn products_and_sums_carry_about_a_hundred_bits() {
        // (1 + 2^-60)·3: the low part carries what one f64 would round away.
        let x = Dd {
            hi: 1.0,
            lo: 2f64.powi(-60),
        };
        let z = mul(x, Dd { hi: 3.0, lo: 0.0 });
        assert_eq!((z.hi, z.lo), (3.0, 3.0 * 2f64.powi(-60)));
        // (1 + 2^-70) + (−1 + 2^-71) = 3·2^-71: the high parts cancel, the low parts remain.
        let a = Dd {
            hi: 1.0,
            lo: 2f64.powi(-70),
        };
        let b = Dd {
            hi: -1.0,
            lo: 2f64.powi(-71),
        };
        let w = add(a, b);
        assert_eq!((w.hi, w.lo), (3.0 * 2f64.powi(-71), 0.0));
        // (1 + 2^-60)·(1 − 2^-60) = 1 − 2^-120, within 2^-101 relative.
        let y = Dd {
            hi: 1.0,
            lo: -(2f64.powi(-60)),
        };
        let z = mul(x, y);
        assert!(((z.hi - 1.0) + z.lo + 2f64.powi(-120)).abs() <= U2);
    }
}
