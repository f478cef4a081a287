//! The 6-D double-double minors four at a time in 256-bit vectors: the expansion of
//! [`minors6`](crate::predicates::minors6) with [`Fused`](super::Fused)'s products, term for term
//! and rounding for rounding, the minors of one size computed in groups of four lanes.
//!
//! Why: the written-out scalar expansion runs ~30 `f64` operations per term, scalar or in pairs,
//! for 186 terms: about 4,600 instructions per plane (this: about 2,000), the largest part of the
//! double-double stage (docs/benchmarks.md, "the raw sums perturbed"). Each vector operation
//! below is the scalar one of [`super`] on four lanes, in the same order, so every minor is the
//! same to the last bit (`tests::fused_products_give_the_same_minors_bit_for_bit`, which a
//! single fused product here fails) and the plane's error analysis is untouched. Loops over
//! `[f64; 4]` lanes were not vectorised by the compiler (the perturbed sum at ε = 1e−8 took 654
//! and 843 million instructions with two such forms, 535 million before), hence the intrinsics;
//! none takes a pointer, so none is `unsafe` inside these `avx,fma` functions.

use super::Dd;
use core::arch::x86_64::{
    __m256d, _mm_cvtsd_f64, _mm_unpackhi_pd, _mm256_add_pd, _mm256_castpd256_pd128,
    _mm256_extractf128_pd, _mm256_fmsub_pd, _mm256_mul_pd, _mm256_set_pd, _mm256_set1_pd,
    _mm256_sub_pd, _mm256_xor_pd,
};

/// Four double-doubles, high and low parts in two vectors.
#[derive(Clone, Copy)]
struct Dd4 {
    hi: __m256d,
    lo: __m256d,
}

// `super`'s `two_sum`, `fast_two_sum`, `mul_with(·, ·, two_prod_fused)` and `add`, lane-wise,
// each operation in the same order (so the same roundings; no product is fused that the scalar
// code rounds).

#[inline]
#[target_feature(enable = "avx,fma")]
fn two_sum(a: __m256d, b: __m256d) -> Dd4 {
    let s = _mm256_add_pd(a, b);
    let a1 = _mm256_sub_pd(s, b);
    let b1 = _mm256_sub_pd(s, a1);
    Dd4 {
        hi: s,
        lo: _mm256_add_pd(_mm256_sub_pd(a, a1), _mm256_sub_pd(b, b1)),
    }
}

#[inline]
#[target_feature(enable = "avx,fma")]
fn fast_two_sum(a: __m256d, b: __m256d) -> Dd4 {
    let s = _mm256_add_pd(a, b);
    Dd4 {
        hi: s,
        lo: _mm256_sub_pd(b, _mm256_sub_pd(s, a)),
    }
}

#[inline]
#[target_feature(enable = "avx,fma")]
fn mul(x: Dd4, y: Dd4) -> Dd4 {
    let p = _mm256_mul_pd(x.hi, y.hi);
    // fl(x.hi·y.hi − p), one rounding: the scalar `mul_add(b, −p)`.
    let e = _mm256_fmsub_pd(x.hi, y.hi, p);
    let cross = _mm256_add_pd(_mm256_mul_pd(x.hi, y.lo), _mm256_mul_pd(x.lo, y.hi));
    fast_two_sum(p, _mm256_add_pd(e, cross))
}

#[inline]
#[target_feature(enable = "avx,fma")]
fn add(x: Dd4, y: Dd4) -> Dd4 {
    let s = two_sum(x.hi, y.hi);
    let t = two_sum(x.lo, y.lo);
    let v = fast_two_sum(s.hi, _mm256_add_pd(s.lo, t.hi));
    fast_two_sum(v.hi, _mm256_add_pd(t.lo, v.lo))
}

/// The four lanes of `v`.
#[inline]
#[target_feature(enable = "avx,fma")]
fn lanes(v: __m256d) -> [f64; 4] {
    let low = _mm256_castpd256_pd128(v);
    let high = _mm256_extractf128_pd::<1>(v);
    [
        _mm_cvtsd_f64(low),
        _mm_cvtsd_f64(_mm_unpackhi_pd(low, low)),
        _mm_cvtsd_f64(high),
        _mm_cvtsd_f64(_mm_unpackhi_pd(high, high)),
    ]
}

/// Column `t` (counting set bits from the lowest) of `mask`.
#[inline(always)]
const fn nth_column(mask: u8, t: usize) -> usize {
    let mut bits = mask;
    let mut i = 0;
    while i < t {
        bits &= bits - 1;
        i += 1;
    }
    bits.trailing_zeros() as usize
}

/// Column `t` of each lane's mask, for `t` below the masks' size (zero beyond it).
const fn columns(masks: [u8; 4]) -> [[usize; 4]; 5] {
    let mut out = [[0; 4]; 5];
    let mut t = 0;
    while t < 5 {
        let mut l = 0;
        while l < 4 {
            if (t as u32) < masks[l].count_ones() {
                out[t][l] = nth_column(masks[l], t);
            }
            l += 1;
        }
        t += 1;
    }
    out
}

/// The mask without column `t`, lane by lane: the minor that term `t` multiplies.
const fn rests(masks: [u8; 4]) -> [[usize; 4]; 5] {
    let columns = columns(masks);
    let mut out = [[0; 4]; 5];
    let mut t = 0;
    while t < 5 {
        let mut l = 0;
        while l < 4 {
            out[t][l] = (masks[l] & !(1u8 << columns[t][l])) as usize;
            l += 1;
        }
        t += 1;
    }
    out
}

/// The minors of `rows[1..6]` omitting each column, as [`minors6`](crate::predicates::minors6)
/// orders them.
#[target_feature(enable = "avx,fma")]
pub(super) fn minors6_lanes(rows: &[[Dd; 6]; 6]) -> [Dd; 6] {
    // Every minor by its column mask; the empty minor is 1.
    let mut hi = [0.0f64; 64];
    let mut lo = [0.0f64; 64];
    hi[0] = 1.0;
    let negate = _mm256_set1_pd(-0.0);
    let zero = _mm256_set1_pd(0.0);
    // The four minors of size $k on the columns $m (ascending masks; a size's last group
    // repeats its last mask in the lanes it does not fill), written out so that every index is
    // a constant: term t of each lane is its t-th column's entry times the minor without that
    // column, signs alternating from (−1)^(k−1), the first term alone (`MinorScalar::first`).
    macro_rules! group {
        ($k:literal: $m0:literal $m1:literal $m2:literal $m3:literal) => {{
            let row = &rows[$k];
            const MASKS: [u8; 4] = [$m0, $m1, $m2, $m3];
            const COLUMN: [[usize; 4]; 5] = columns(MASKS);
            const REST: [[usize; 4]; 5] = rests(MASKS);
            let mut acc = Dd4 { hi: zero, lo: zero };
            for t in 0..$k {
                let (c, r) = (COLUMN[t], REST[t]);
                let entry = Dd4 {
                    hi: _mm256_set_pd(row[c[3]].hi, row[c[2]].hi, row[c[1]].hi, row[c[0]].hi),
                    lo: _mm256_set_pd(row[c[3]].lo, row[c[2]].lo, row[c[1]].lo, row[c[0]].lo),
                };
                let minor = Dd4 {
                    hi: _mm256_set_pd(hi[r[3]], hi[r[2]], hi[r[1]], hi[r[0]]),
                    lo: _mm256_set_pd(lo[r[3]], lo[r[2]], lo[r[1]], lo[r[0]]),
                };
                let mut term = mul(entry, minor);
                if ($k - 1 + t) % 2 == 1 {
                    // The sign bit flipped, as `Dd::neg` (zeros included).
                    term = Dd4 {
                        hi: _mm256_xor_pd(term.hi, negate),
                        lo: _mm256_xor_pd(term.lo, negate),
                    };
                }
                acc = if t == 0 { term } else { add(acc, term) };
            }
            let (h, l) = (lanes(acc.hi), lanes(acc.lo));
            for i in 0..4 {
                hi[MASKS[i] as usize] = h[i];
                lo[MASKS[i] as usize] = l[i];
            }
        }};
    }
    group!(1: 1 2 4 8);
    group!(1: 16 32 32 32);
    group!(2: 3 5 6 9);
    group!(2: 10 12 17 18);
    group!(2: 20 24 33 34);
    group!(2: 36 40 48 48);
    group!(3: 7 11 13 14);
    group!(3: 19 21 22 25);
    group!(3: 26 28 35 37);
    group!(3: 38 41 42 44);
    group!(3: 49 50 52 56);
    group!(4: 15 23 27 29);
    group!(4: 30 39 43 45);
    group!(4: 46 51 53 54);
    group!(4: 57 58 60 60);
    group!(5: 31 47 55 59);
    group!(5: 61 62 62 62);
    let minor = |m: usize| Dd {
        hi: hi[m],
        lo: lo[m],
    };
    [
        minor(62),
        minor(61),
        minor(59),
        minor(55),
        minor(47),
        minor(31),
    ]
}
