//! Allocation-free exact determinants of matrices whose column-scaled entries fit in `i128`.
//!
//! The exact path's usual inputs — degenerate configurations built on a grid, such as the friction
//! pyramids of the grasp layer, whose edges lie exactly in one plane per contact — have entries
//! that are small integers once each *column* is scaled by its own power of two (which multiplies
//! the determinant by a positive power of two, so its sign and the direction of the cofactor
//! vector, after undoing the scaling, are unchanged). Their determinants then fit in a few hundred
//! bits, and a Laplace expansion over column subsets (the same minors-of-minors scheme the filter
//! uses) in fixed-width two's-complement integers is an order of magnitude faster than `BigInt`
//! Bareiss, which allocates for every operation. Entries of up to 126 bits cover the caller's raw
//! floating-point data too (a column holding 1 and 6e−17, as rounded cone edges do, needs 107
//! bits), where `BigInt` was most of the time of a hull of raw wrenches. No maintained crate
//! offers fixed-width signed integers of ~1000 bits with `i128` scaling and no allocation, hence
//! the small type below.

use super::Sign;
use super::exact::decompose;

/// 1088 bits: a minor of order r ≤ 8 with |entries| < 2^127 is below r!·2^(127·r) < 2^1032, and
/// so is every partial sum of its expansion (bounded by the permanent); a side test adds at most
/// 2^(127·7 + 16) · 2^127 · 8 < 2^1035. Callers size the limbs they use from their entries, and
/// fall back on `BigInt` when even this is too few.
const LIMBS: usize = 17;

/// A fixed-width two's-complement integer of which only the low `len` limbs are used: arithmetic
/// is modulo 2^(64·len), exact whenever every value fits (the caller sizes `len` from its entries'
/// bit lengths), and costs O(len) instead of O(LIMBS).
#[derive(Clone, Copy, Debug)]
struct Wide([u64; LIMBS]);

impl Wide {
    const ZERO: Wide = Wide([0; LIMBS]);
    const ONE: Wide = {
        let mut limbs = [0; LIMBS];
        limbs[0] = 1;
        Wide(limbs)
    };

    fn is_negative(&self, len: usize) -> bool {
        self.0[len - 1] >> 63 == 1
    }

    fn sign(&self, len: usize) -> Sign {
        if self.is_negative(len) {
            Sign::Negative
        } else if self.0[..len].iter().all(|&l| l == 0) {
            Sign::Zero
        } else {
            Sign::Positive
        }
    }

    /// Copies the sign bit of limb `from − 1` into the limbs `from..to`.
    fn sign_extend_to(&mut self, from: usize, to: usize) {
        let fill = if self.is_negative(from) { u64::MAX } else { 0 };
        for limb in &mut self.0[from..to.max(from)] {
            *limb = fill;
        }
    }

    /// Copies the sign bit of limb `len − 1` into every limb above it.
    fn sign_extend(&mut self, len: usize) {
        let fill = if self.is_negative(len) { u64::MAX } else { 0 };
        for limb in &mut self.0[len..] {
            *limb = fill;
        }
    }

    fn negate(&mut self, len: usize) {
        let mut carry = 1u64;
        for limb in &mut self.0[..len] {
            let (v, c) = (!*limb).overflowing_add(carry);
            *limb = v;
            carry = u64::from(c);
        }
    }

    /// `self += a · m`, or `self -= a · m` when `subtract`: the 128-bit factor as two 64-bit
    /// halves, each one pass over the limbs.
    fn add_product(&mut self, a: i128, subtract: bool, m: &Wide, len: usize) {
        if a == 0 {
            return;
        }
        let factor = a.unsigned_abs();
        let negative = (a < 0) != subtract;
        self.add_scaled(factor as u64, 0, negative, m, len);
        let high = (factor >> 64) as u64;
        if high != 0 && len > 1 {
            self.add_scaled(high, 1, negative, m, len);
        }
    }

    /// `self ± (f · m) · 2^(64·offset)` in the low `len` limbs ([`scaled_into`]).
    fn add_scaled(&mut self, f: u64, offset: usize, negative: bool, m: &Wide, len: usize) {
        if f == 0 {
            return;
        }
        let target = &mut self.0[offset..len];
        macro_rules! fixed {
            ($($n:literal)*) => {
                match target.len() {
                    $($n => scaled_fixed::<$n>(target, f, negative, &m.0),)*
                    _ => scaled_into(target, f, negative, &m.0),
                }
            };
        }
        // A width known at compile time unrolls the limb loop: the widths are few (1 to
        // LIMBS) and each call's is fixed by the caller's entries. Cachegrind counts 3.7 %
        // fewer instructions on the 4 × 16 wrench hull and 3.9 % fewer on the 3 × 6 Minkowski
        // sum (CHANGELOG).
        fixed!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17);
    }

    /// `(mantissa, exponent)` with `self ≈ mantissa · 2^exponent`, the mantissa holding the top 64
    /// significant bits (truncated, then rounded to `f64`: a relative error below 2^-52).
    fn to_f64_parts(self, len: usize) -> (f64, i32) {
        let negative = self.is_negative(len);
        let mut magnitude = self;
        if negative {
            magnitude.negate(len);
        }
        let Some(top) = (0..len).rev().find(|&i| magnitude.0[i] != 0) else {
            return (0.0, 0);
        };
        let lead = magnitude.0[top].leading_zeros();
        let high = u128::from(magnitude.0[top]) << 64
            | u128::from(if top > 0 { magnitude.0[top - 1] } else { 0 });
        let bits = (high << lead >> 64) as u64;
        let exponent = 64 * top as i32 - lead as i32;
        let value = bits as f64;
        (if negative { -value } else { value }, exponent)
    }
}

/// `target ± f · m` modulo 2^(64·target.len()): the product limb by limb into one carry
/// (addition) or one borrow (subtraction), so no temporary is built.
///
/// Why one: `m_i·f + target_i + carry ≤ (2^64 − 1)² + 2(2^64 − 1) = 2^128 − 1` fits in `u128`,
/// so the sum's high half is the next carry; for subtraction, `p = m_i·f + borrow ≤ 2^128 −
/// 2^64`, and `target_i − low(p)` borrows at most one more, so the next borrow, `high(p) + 1 ≤
/// 2^64 − 1`, fits in `u64`. One dependency chain per limb instead of a product carry and an
/// addition carry. The unsigned product of `f` and `m`'s two's-complement limbs is `f·m` modulo
/// that power of two, added or subtracted according to the sign.
#[inline(always)]
fn scaled_into(target: &mut [u64], f: u64, negative: bool, m: &[u64]) {
    let factor = u128::from(f);
    let limbs = target.iter_mut().zip(m);
    if negative {
        let mut borrow = 0u64;
        for (limb, &factor_limb) in limbs {
            let p = u128::from(factor_limb) * factor + u128::from(borrow);
            let (d, b) = limb.overflowing_sub(p as u64);
            *limb = d;
            borrow = (p >> 64) as u64 + u64::from(b);
        }
    } else {
        let mut carry = 0u64;
        for (limb, &factor_limb) in limbs {
            let t = u128::from(factor_limb) * factor + u128::from(*limb) + u128::from(carry);
            *limb = t as u64;
            carry = (t >> 64) as u64;
        }
    }
}

/// [`scaled_into`] over exactly `N` limbs, so the loop's trip count is a constant.
#[inline(always)]
fn scaled_fixed<const N: usize>(target: &mut [u64], f: u64, negative: bool, m: &[u64]) {
    match (
        <&mut [u64; N]>::try_from(&mut *target),
        m.get(..N).map(<&[u64; N]>::try_from),
    ) {
        (Ok(target), Some(Ok(m))) => scaled_into(target, f, negative, m),
        _ => scaled_into(target, f, negative, m),
    }
}

/// The difference matrix `[p1 − p0; p2 − p0; …]` of `points` (rows beyond `points.len() − 1` stay
/// zero) with every column scaled to integers, the scaling exponent of each column, and the bit
/// length of each column's largest entry (a minor over any set of columns is below
/// 8!·2^(Σ bits) < 2^(Σ bits + 16)); `None` when some scaled coordinate does not fit in 126 bits
/// (the caller then uses `BigInt`).
///
/// # Panics
/// If a coordinate is not finite.
fn integer_columns<const D: usize>(points: &[&[f64; D]]) -> Option<IntegerColumns<D>> {
    let mut matrix = [[0i128; D]; D];
    let mut exponents = [0i32; D];
    let mut column_bits = [0u32; D];
    let mut base = [0i128; D];
    // Each coordinate decomposed once per column, for its exponent and then its integer (two
    // decompositions each were a third of this function on raw sums, which build an exact
    // plane for two facets in five).
    let mut parts = [(0i64, 0i32); 9];
    debug_assert!(points.len() <= parts.len(), "at most D + 1 ≤ 9 points");
    for c in 0..D {
        let mut emin = i32::MAX;
        for (part, p) in parts.iter_mut().zip(points) {
            *part = decompose(p[c]);
            if part.0 != 0 {
                emin = emin.min(part.1);
            }
        }
        let emin = if emin == i32::MAX { 0 } else { emin };
        exponents[c] = emin;
        let origin = column_integer(parts[0], emin)?;
        base[c] = origin;
        let mut largest = 0u128;
        for r in 1..points.len() {
            let entry = column_integer(parts[r], emin)? - origin;
            matrix[r - 1][c] = entry;
            largest = largest.max(entry.unsigned_abs());
        }
        column_bits[c] = 128 - largest.leading_zeros();
    }
    Some(IntegerColumns {
        matrix,
        exponents,
        column_bits,
        base,
    })
}

/// What [`integer_columns`] returns.
struct IntegerColumns<const D: usize> {
    /// The difference rows in column units.
    matrix: [[i128; D]; D],
    /// Column c holds multiples of `2^exponents[c]`.
    exponents: [i32; D],
    /// Bit length of each column's largest entry.
    column_bits: [u32; D],
    /// The first point in column units.
    base: [i128; D],
}

/// `⌈log2 r!⌉` for r = 0…8: a minor of order r, and every partial sum of its expansion (bounded
/// by the permanent), is below r!·Π_{c∈S} 2^(bits_c) ≤ 2^(LOG2_FACTORIAL\[r\] + Σ bits_c).
const LOG2_FACTORIAL: [u32; 9] = [0, 0, 1, 3, 5, 7, 10, 13, 16];

/// Limbs for the minors of each order r = 1…D of a matrix whose columns' largest entries have
/// `column_bits` bits: a minor of order r is below 2^(⌈log2 r!⌉ + the r largest bits)
/// ([`LOG2_FACTORIAL`]). Working each order in its own width halves the Laplace expansion's limb
/// operations against using the last order's everywhere.
fn limbs_per_order<const D: usize>(column_bits: &[u32; D]) -> [usize; 9] {
    let mut sorted = *column_bits;
    sorted.sort_unstable_by(|a, b| b.cmp(a));
    let mut limbs = [1usize; 9];
    let mut bits = 0;
    for r in 1..=D {
        bits += sorted[r - 1];
        limbs[r] = limbs_for(bits + LOG2_FACTORIAL[r]).unwrap_or(LIMBS);
    }
    limbs
}

/// Limbs for values below 2^bits, plus a sign bit; `None` beyond [`LIMBS`].
fn limbs_for(bits: u32) -> Option<usize> {
    let limbs = ((bits + 1) as usize).div_ceil(64).max(1);
    (limbs <= LIMBS).then_some(limbs)
}

thread_local! {
    /// Scratch for [`subset_minors`]: 35 KB that would otherwise be zeroed on every call.
    static MINORS: std::cell::RefCell<Box<[Wide; 256]>> =
        std::cell::RefCell::new(Box::new([Wide::ZERO; 256]));
}

/// Minors of the first `rows` rows over every column subset of size `rows`, by Laplace expansion
/// along each new row (`minors[mask]` for `mask.count_ones() == rows`), handed to `read`. The
/// minors of order r are computed in `limbs[r]` limbs (nondecreasing in r, `limbs[rows]` at most
/// `len`), then sign-extended to `len`, which `read` may use for all of them.
fn subset_minors<const D: usize, T>(
    matrix: &[[i128; D]; D],
    rows: usize,
    limbs: &[usize; 9],
    len: usize,
    read: impl FnOnce(&[Wide]) -> T,
) -> T {
    // Each entry's magnitude (as two 64-bit halves) and sign, split once here: the products
    // below then run at a width fixed at compile time, with no dispatch per product.
    let mut low = [[0u64; 8]; 8];
    let mut high = [[0u64; 8]; 8];
    let mut negative = [[false; 8]; 8];
    for (r, row) in matrix[..rows].iter().enumerate() {
        for (c, &x) in row.iter().enumerate() {
            let magnitude = x.unsigned_abs();
            low[r][c] = magnitude as u64;
            high[r][c] = (magnitude >> 64) as u64;
            negative[r][c] = x < 0;
        }
    }
    MINORS.with_borrow_mut(|minors| {
        let minors: &mut [Wide; 256] = minors;
        minors[0] = Wide::ONE;
        // One pass in increasing mask order: every sub-mask S \ {c} is smaller than S, so its
        // minor is ready. A pass per order that skipped the masks of other sizes cost D times
        // the iterations, and its size test mispredicted: 40 % of this function's time on raw
        // wrench hulls.
        for mask in 1usize..1 << D {
            // A table, not `count_ones`: no single instruction on baseline x86-64.
            let order = super::minors::SUBSET_SIZE[mask] as usize;
            if order > rows {
                continue;
            }
            let width = limbs[order].min(len);
            let subtract = order.is_multiple_of(2);
            let r = (order - 1) & 7;
            let entries = (&low[r], &high[r], &negative[r]);
            macro_rules! fixed {
                ($($n:literal)*) => {
                    match width {
                        $($n => {
                            let sum = fixed_minor::<$n>(entries, mask, minors, subtract);
                            minors[mask].0[..$n].copy_from_slice(&sum);
                        })*
                        _ => wide_minor(&matrix[order - 1], mask, minors, subtract, width),
                    }
                };
            }
            // Widths up to 12 limbs: every minor of a plane up to 6-D (at most 11 limbs, five
            // columns of 127 bits and ⌈log2 5!⌉). The raw 4 × 16 wrenches' planes, some with a
            // column of up to 108 bits (1 and 6e−17 in one column), take 5 to 7. Wider minors
            // (7-D and 8-D with entries beyond 64 bits) keep the width known at run time.
            fixed!(1 2 3 4 5 6 7 8 9 10 11 12);
            minors[mask].sign_extend_to(width, len);
        }
        read(&minors[..])
    })
}

/// `Σ ± row[c]·minors[mask ∖ {c}]` over the set bits `c` of `mask`, signs alternating from
/// `subtract`, in `W` limbs, for one row's entries given as magnitudes (low and high 64-bit
/// halves) and signs: one product pass per half that is not zero.
#[inline(always)]
fn fixed_minor<const W: usize>(
    (low, high, negative): (&[u64; 8], &[u64; 8], &[bool; 8]),
    mask: usize,
    minors: &[Wide; 256],
    mut subtract: bool,
) -> [u64; W] {
    let mut sum = [0u64; W];
    let mut bits = mask;
    while bits != 0 {
        let c = bits.trailing_zeros() as usize & 7;
        bits &= bits - 1;
        let m = minors[(mask & !(1 << c)) & 255]
            .0
            .first_chunk::<W>()
            .expect("W ≤ 12 < LIMBS");
        let minus = negative[c] != subtract;
        if low[c] != 0 {
            scaled_into(&mut sum, low[c], minus, m);
        }
        if high[c] != 0 {
            scaled_into(&mut sum[1..], high[c], minus, m);
        }
        subtract = !subtract;
    }
    sum
}

/// The minor of [`fixed_minor`] at a width known only at run time,
/// written in place into `minors[mask]`.
fn wide_minor(
    row: &[i128],
    mask: usize,
    minors: &mut [Wide; 256],
    mut subtract: bool,
    width: usize,
) {
    let (lower, upper) = minors.split_at_mut(mask);
    let sum = &mut upper[0];
    sum.0[..width].fill(0);
    let mut bits = mask;
    while bits != 0 {
        let c = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        sum.add_product(row[c], subtract, &lower[mask & !(1 << c)], width);
        subtract = !subtract;
    }
}

/// A facet's hyperplane with exact integer cofactors, for repeated exact side tests against the
/// same facet (a point of a planar friction pyramid is tested against every facet through three of
/// its neighbours, and the determinant is exactly zero each time): one test then costs D products
/// instead of a full determinant.
#[derive(Clone, Debug)]
pub(in crate::predicates) struct ExactPlane<const D: usize> {
    /// Signed cofactors `C_j` of the column-scaled difference matrix, sign-extended to every
    /// limb (so that any `len` of at least their own reads them right).
    cofactors: [Wide; D],
    /// Bits of the largest cofactor: a side test's sum is below 2^(cofactor_bits + 3) times
    /// its largest coordinate difference.
    cofactor_bits: u32,
    /// Column scaling: column j holds multiples of `2^exponents[j]`.
    exponents: [i32; D],
    /// The base vertex `v0` in column units.
    base: [i128; D],
}

impl<const D: usize> ExactPlane<D> {
    /// `None` when the column-scaled vertex coordinates do not fit in `i128`.
    pub(in crate::predicates) fn new(vertices: &[[f64; D]; D]) -> Option<Self> {
        let points: [&[f64; D]; D] = std::array::from_fn(|i| &vertices[i]);
        let IntegerColumns {
            matrix,
            exponents,
            column_bits,
            base,
        } = integer_columns(&points)?;
        // Every cofactor is a minor of order D − 1 over all columns but one: below
        // (D − 1)!·2^(Σ bits − the fewest bits of a column).
        let fewest = column_bits.iter().copied().min().unwrap_or(0);
        let cofactor_bits =
            column_bits.iter().sum::<u32>() - fewest + LOG2_FACTORIAL[D.saturating_sub(1)];
        let len = limbs_for(cofactor_bits)?;
        let full = (1usize << D) - 1;
        let limbs = limbs_per_order(&column_bits);
        // Written in place, `len` limbs each: whole copies of 17-limb values were a twelfth
        // of the time of hulls that build many exact planes (libc `memmove`).
        let mut cofactors = [Wide::ZERO; D];
        subset_minors(&matrix, D - 1, &limbs, len, |minors| {
            for (j, c) in cofactors.iter_mut().enumerate() {
                c.0[..len].copy_from_slice(&minors[full & !(1 << j)].0[..len]);
                if (D - 1 + j) % 2 == 1 {
                    c.negate(len);
                }
                c.sign_extend(len);
            }
        });
        Some(ExactPlane {
            cofactors,
            cofactor_bits,
            exponents,
            base,
        })
    }

    /// The differences `p − v0` in units of `2^(exponents[j] − shift)` per column `j`, the
    /// `shift` (0 when `p` is on this plane's column grid, else the most bits a coordinate of
    /// `p` has below its column's unit), and the limbs their side-test sum needs; `None` when a
    /// difference or the sum is too wide.
    ///
    /// Why a shift: the columns were scaled by the *vertices'* lowest bits, and a tested point
    /// (raw data: any `f64`) often has a bit below them. Every column then scales by the same
    /// further `2^shift`, which multiplies the sum by a positive power of two: its sign is
    /// unchanged, and [`distance`](Self::distance) takes the power back out. Without it such a
    /// point cost a whole exact determinant instead of D products.
    fn differences(&self, p: &[f64; D]) -> Option<([i128; D], u32, usize)> {
        let mut shift = 0u32;
        // Each coordinate decomposed once, for the shift and then its integer.
        let parts = p.map(decompose);
        for (&(m, e), &exponent) in parts.iter().zip(&self.exponents) {
            if m != 0 && e < exponent {
                shift = shift.max(u32::try_from(exponent - e).ok()?);
            }
        }
        let mut differences = [0i128; D];
        let mut largest = 0u128;
        for (j, &part) in parts.iter().enumerate() {
            // The base vertex in the finer units: exact, or `None` if it no longer fits.
            let base = if shift == 0 {
                self.base[j]
            } else if shift < 127 {
                self.base[j].checked_mul(1i128 << shift)?
            } else {
                return None;
            };
            let unit = self.exponents[j].checked_sub(i32::try_from(shift).ok()?)?;
            let x = column_integer(part, unit)?.checked_sub(base)?;
            differences[j] = x;
            largest = largest.max(x.unsigned_abs());
        }
        let len = limbs_for(self.cofactor_bits + (128 - largest.leading_zeros()) + 3)?;
        Some((differences, shift, len))
    }

    /// `Σ_j C_j·(p_j − v0_j)` times `2^shift`, `shift`, and the limbs the sum is exact in.
    fn sum(&self, p: &[f64; D]) -> Option<(Wide, u32, usize)> {
        let (differences, shift, len) = self.differences(p)?;
        let mut sum = Wide::ZERO;
        for (d, c) in differences.iter().zip(&self.cofactors) {
            sum.add_product(*d, false, c, len);
        }
        Some((sum, shift, len))
    }

    /// The direction of the exact cofactor vector (the facet's outward normal), rounded to `f64`.
    pub(in crate::predicates) fn normal_direction(&self) -> [f64; D] {
        scaled_direction(
            self.cofactors.map(|c| c.to_f64_parts(LIMBS)),
            &self.exponents,
        )
    }

    /// Exact sign of `det[v1 − v0; …; v(D−1) − v0; p − v0] = Σ_j C_j·(p_j − v0_j)`, or `None` when
    /// a coordinate difference of `p`, in the finest units its coordinates need, does not fit in
    /// `i128` (or the sum in [`LIMBS`]).
    ///
    /// # Panics
    /// If a coordinate of `p` is not finite.
    pub(in crate::predicates) fn side(&self, p: &[f64; D]) -> Option<Sign> {
        let (sum, _, len) = self.sum(p)?;
        Some(sum.sign(len))
    }

    /// `det[v1 − v0; …; v(D−1) − v0; p − v0] / |C|` — the signed distance of `p` beyond the
    /// plane — from the exact determinant and the exact cofactors, each rounded once (a few ulps
    /// in all), or `None` when a difference or the sum is too wide (as for [`side`](Self::side)).
    ///
    /// # Panics
    /// If a coordinate of `p` is not finite.
    pub(in crate::predicates) fn distance(&self, p: &[f64; D]) -> Option<f64> {
        let (sum, shift, len) = self.sum(p)?;
        // With S = Σ e_c, the determinant is 2^(S − shift)·sum and cofactor j is
        // C'_j·2^(S − e_j): the common 2^S cancels, leaving 2^(−shift)·sum / |(C'_j·2^(−e_j))_j|.
        let (value, exponent) = sum.to_f64_parts(len);
        let exponent = exponent - i32::try_from(shift).ok()?;
        if value == 0.0 {
            return Some(0.0);
        }
        let parts: [(f64, i32); D] = std::array::from_fn(|j| {
            let (m, e) = self.cofactors[j].to_f64_parts(LIMBS);
            (m, e - self.exponents[j])
        });
        let top = parts
            .iter()
            .filter(|(m, _)| *m != 0.0)
            .map(|&(_, e)| e)
            .max()?;
        let norm = parts
            .iter()
            .map(|&(m, e)| {
                let c = times_power_of_two(m, e - top);
                c * c
            })
            .sum::<f64>()
            .sqrt();
        Some(times_power_of_two(value / norm, exponent - top))
    }
}

/// `x · 2^e`, in steps that cannot overflow or underflow before the end.
pub fn times_power_of_two(mut x: f64, mut e: i32) -> f64 {
    while e > 1000 {
        x *= 2f64.powi(1000);
        e -= 1000;
    }
    while e < -1000 {
        x *= 2f64.powi(-1000);
        e += 1000;
    }
    x * 2f64.powi(e)
}

/// `x / 2^exponent`, for `x` [`decompose`]d into `(m, e)`, when it is an integer of magnitude
/// below 2^126 (so that a difference of two fits in `i128`).
fn column_integer((m, e): (i64, i32), exponent: i32) -> Option<i128> {
    if m == 0 {
        return Some(0);
    }
    let shift = u32::try_from(e - exponent).ok()?;
    let bits = 64 - m.unsigned_abs().leading_zeros();
    (bits + shift <= 126).then(|| i128::from(m) << shift)
}

/// Exact sign of `det[v1 − v0; …; v(D−1) − v0; p − v0]`, or `None` when the column-scaled entries
/// do not fit in `i128`.
pub(in crate::predicates) fn orientation<const D: usize>(
    vertices: &[[f64; D]; D],
    p: &[f64; D],
) -> Option<Sign> {
    let mut points: [&[f64; D]; 9] = [p; 9];
    for (slot, v) in points.iter_mut().zip(vertices) {
        *slot = v;
    }
    let IntegerColumns {
        matrix,
        column_bits,
        ..
    } = integer_columns(&points[..=D])?;
    let len = limbs_for(column_bits.iter().sum::<u32>() + LOG2_FACTORIAL[D])?;
    let limbs = limbs_per_order(&column_bits);
    Some(subset_minors(&matrix, D, &limbs, len, |minors| {
        minors[(1 << D) - 1].sign(len)
    }))
}

/// The exact cofactor vector of `[v1 − v0; …; v(D−1) − v0; ·]`, rounded to `f64` after a common
/// power-of-two scaling (only its direction is meaningful), or `None` when the column-scaled
/// entries do not fit in `i128`.
pub(in crate::predicates) fn cofactor_direction<const D: usize>(
    vertices: &[[f64; D]; D],
) -> Option<[f64; D]> {
    ExactPlane::new(vertices).map(|plane| plane.normal_direction())
}

/// Undo the column scaling of exact cofactors given as `(mantissa, exponent)` pairs: column c was
/// scaled by 2^(−e_c), so cofactor j (which omits column j) by 2^(e_j − S), S = Σ e_c; the common
/// factor 2^(−S) does not change the direction. The result is scaled so that its largest
/// component is below 1 in magnitude.
fn scaled_direction<const D: usize>(parts: [(f64, i32); D], exponents: &[i32; D]) -> [f64; D] {
    let parts: [(f64, i32); D] = std::array::from_fn(|j| (parts[j].0, parts[j].1 - exponents[j]));
    let top = parts
        .iter()
        .filter(|(m, _)| *m != 0.0)
        .map(|&(_, e)| e)
        .max()
        .unwrap_or(0);
    parts.map(|(m, e)| {
        // 2^(e − top) ≤ 1; split the power so that neither factor underflows prematurely.
        let shift = e - top;
        m * 2f64.powi(shift / 2) * 2f64.powi(shift - shift / 2) * 2f64.powi(-64)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Rng;
    use crate::predicates::exact::{exact_cofactor_direction_big, orientation_big};

    /// Random points on a coarse grid (many exact zeros) or with full mantissas, with columns of
    /// very different magnitudes.
    fn points<const D: usize>(rng: &mut Rng, grid: bool) -> [[f64; D]; 9] {
        let column_scale: [f64; D] = std::array::from_fn(|_| 2f64.powi(rng.below(40) as i32 - 20));
        let value = |rng: &mut Rng, c: usize| {
            let x = if grid {
                rng.below(5) as f64 - 2.0
            } else {
                rng.uniform_in(-1.0, 1.0)
            };
            x * column_scale[c]
        };
        std::array::from_fn(|_| std::array::from_fn(|c| value(rng, c)))
    }

    fn check<const D: usize>() {
        let mut rng = Rng::new(11 + D as u64);
        for case in 0..400 {
            let grid = case % 2 == 0;
            let pts = points::<D>(&mut rng, grid);
            let vertices: [[f64; D]; D] = std::array::from_fn(|i| pts[i]);
            let p = pts[D];
            let fast = orientation(&vertices, &p).expect("small entries fit");
            assert_eq!(fast, orientation_big(&vertices, &p), "D = {D}, case {case}");
            let direction = cofactor_direction(&vertices).expect("small entries fit");
            let reference = exact_cofactor_direction_big(&vertices);
            let norm = |v: &[f64; D]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
            let (a, b) = (norm(&direction), norm(&reference));
            assert_eq!(a == 0.0, b == 0.0, "D = {D}, case {case}");
            for c in 0..D {
                let (x, y) = (
                    direction[c] / a.max(f64::MIN_POSITIVE),
                    reference[c] / b.max(f64::MIN_POSITIVE),
                );
                assert!(
                    (x - y).abs() <= 1e-14,
                    "D = {D}, case {case}: {direction:?} vs {reference:?}"
                );
            }
        }
    }

    #[test]
    fn agrees_with_bigint_in_every_dimension() {
        check::<2>();
        check::<3>();
        check::<4>();
        check::<5>();
        check::<6>();
        check::<7>();
        check::<8>();
    }

    #[test]
    fn cached_plane_agrees_with_bigint() {
        fn run<const D: usize>() {
            let mut rng = Rng::new(5 + D as u64);
            for case in 0..300 {
                let pts = points::<D>(&mut rng, case % 2 == 0);
                let vertices: [[f64; D]; D] = std::array::from_fn(|i| pts[i]);
                let plane = ExactPlane::new(&vertices).expect("small entries fit");
                for p in &pts {
                    if let Some(sign) = plane.side(p) {
                        assert_eq!(sign, orientation_big(&vertices, p), "D = {D}, case {case}");
                    }
                }
            }
        }
        run::<2>();
        run::<3>();
        run::<4>();
        run::<6>();
        run::<8>();
    }

    /// Sylvester's Hadamard matrix of order `n` (a power of two): ±1 entries whose determinant,
    /// n^(n/2), is the largest any ±1 matrix has.
    fn hadamard(n: usize) -> Vec<Vec<f64>> {
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        if (i & j).count_ones().is_multiple_of(2) {
                            1.0
                        } else {
                            -1.0
                        }
                    })
                    .collect()
            })
            .collect()
    }

    /// The widths are sized from ⌈log2 r!⌉ plus the columns' bits. The largest minor that entries
    /// of those bit lengths allow is Hadamard's, r^(r/2) times the product of the columns'
    /// largest entries: below the r! of the sizing, so it fits. These entries reach it: every
    /// column holds ±(2^b − 1) in a Hadamard sign pattern, with bit lengths that put the minor
    /// just below a limb boundary, so that, with its sign bit, it needs one limb more than a
    /// sizing two bits short would give. The signs of both orientations and of the cached
    /// plane's side tests are `BigInt`'s.
    #[test]
    fn largest_minors_fit_their_tightest_widths() {
        fn orientations<const D: usize>(bits: [u32; D]) {
            let hadamard_bits = D.ilog2() * D as u32 / 2;
            assert_eq!(
                (bits.iter().sum::<u32>() + hadamard_bits) % 64,
                0,
                "D = {D}"
            );
            let h = hadamard(D);
            let m: [f64; D] = bits.map(|b| 2f64.powi(b as i32) - 1.0);
            for negated in [false, true] {
                let row = |i: usize| -> [f64; D] {
                    let flip = if negated && i == 0 { -1.0 } else { 1.0 };
                    std::array::from_fn(|c| flip * h[i][c] * m[c])
                };
                // v0 = 0, so the difference rows are H's rows scaled per column.
                let vertices: [[f64; D]; D] =
                    std::array::from_fn(|i| if i == 0 { [0.0; D] } else { row(i - 1) });
                let p = row(D - 1);
                let sign = orientation(&vertices, &p).expect("53-bit entries fit");
                assert_ne!(sign, Sign::Zero);
                assert_eq!(
                    sign,
                    orientation_big(&vertices, &p),
                    "D = {D}, negated {negated}"
                );
            }
        }
        orientations::<4>([53, 53, 53, 29]);
        orientations::<8>([53, 53, 53, 53, 53, 53, 53, 1]);

        // D = 5: the cofactor that omits the last column is ±16·Π m_c over a Hadamard block of
        // order 4, just below 2^192.
        let bits = [53u32, 53, 53, 29, 1];
        let h = hadamard(4);
        let m: [f64; 5] = bits.map(|b| 2f64.powi(b as i32) - 1.0);
        let vertices: [[f64; 5]; 5] = std::array::from_fn(|i| {
            std::array::from_fn(|c| match (i, c) {
                (0, _) | (_, 4) => 0.0,
                _ => h[i - 1][c] * m[c],
            })
        });
        let plane = ExactPlane::new(&vertices).expect("53-bit entries fit");
        for p in [
            [0.0, 0.0, 0.0, 0.0, 1.0],
            [0.0, 0.0, 0.0, 0.0, -1.0],
            [m[0], -m[1], m[2], -m[3], 1.0],
            [m[0], m[1], m[2], m[3], -1.0],
        ] {
            assert_eq!(
                plane.side(&p),
                Some(orientation_big(&vertices, &p)),
                "{p:?}"
            );
        }
    }

    /// Columns holding full-mantissa values of magnitudes 2^0 … 2^−60 (raw cone edges: 1 beside a
    /// rounded 6e−17): column integers of 64 to 126 bits, beyond the former `i64` entries, and
    /// nearly flat sets, so that the signs are small differences of large products.
    #[test]
    fn wide_entries_agree_with_bigint() {
        fn run<const D: usize>() {
            let mut rng = Rng::new(77 + D as u64);
            let mut wide_cases = 0;
            for case in 0..300 {
                let mut pts: [[f64; D]; 9] = std::array::from_fn(|_| {
                    std::array::from_fn(|_| {
                        rng.uniform_in(-1.0, 1.0) * 2f64.powi(-(rng.below(61) as i32))
                    })
                });
                if case % 2 == 0 {
                    // p nearly on the plane: an affine combination of the vertices, rounded.
                    pts[D] = std::array::from_fn(|c| 0.5 * pts[0][c] + 0.5 * pts[1][c]);
                }
                let vertices: [[f64; D]; D] = std::array::from_fn(|i| pts[i]);
                let p = pts[D];
                if let Some(sign) = orientation(&vertices, &p) {
                    wide_cases += 1;
                    assert_eq!(sign, orientation_big(&vertices, &p), "D = {D}, case {case}");
                }
                if let Some(plane) = ExactPlane::new(&vertices) {
                    for q in &pts {
                        if let Some(sign) = plane.side(q) {
                            assert_eq!(sign, orientation_big(&vertices, q), "D = {D}, case {case}");
                        }
                    }
                }
            }
            assert!(wide_cases > 250, "D = {D}: only {wide_cases} cases fit");
        }
        run::<2>();
        run::<3>();
        run::<4>();
        run::<6>();
        run::<8>();
    }

    /// A point with bits below the vertices' column grid (raw data tested against a facet of
    /// coarser vertices) is decided by the cached plane in finer units, not refused: the sign
    /// and the distance agree with `BigInt`'s on points on, near and off the plane.
    #[test]
    fn points_off_the_column_grid_are_decided() {
        fn run<const D: usize>() {
            let mut rng = Rng::new(303 + D as u64);
            let mut decided = 0;
            for case in 0..200 {
                // Vertices on the integer grid of a few bits, so every column unit is ≥ 1/2.
                let vertices: [[f64; D]; D] = std::array::from_fn(|_| {
                    std::array::from_fn(|_| (rng.below(9) as f64 - 4.0) / 2.0)
                });
                let Some(plane) = ExactPlane::new(&vertices) else {
                    continue;
                };
                // On the plane (the vertices' midpoint), then moved by 2^-k in one coordinate:
                // below every column's unit for k ≥ 2.
                let k = 2 + rng.below(60) as i32;
                let mut p: [f64; D] =
                    std::array::from_fn(|c| 0.5 * (vertices[0][c] + vertices[1][c]));
                p[case % D] += 2f64.powi(-k) * if case % 3 == 0 { -1.0 } else { 1.0 };
                let sign = plane
                    .side(&p)
                    .expect("an off-grid point within range is decided");
                assert_eq!(sign, orientation_big(&vertices, &p), "D = {D}, case {case}");
                if sign != Sign::Zero {
                    let want = crate::predicates::exact::distance_big(&vertices, &p);
                    let got = plane.distance(&p).expect("decided above");
                    assert!(
                        (got - want).abs() <= 4.0 * f64::EPSILON * want.abs(),
                        "D = {D}, case {case}: {got:e} vs {want:e}"
                    );
                    decided += 1;
                }
            }
            assert!(
                decided > 50,
                "D = {D}: only {decided} off-grid points off the plane"
            );
        }
        run::<2>();
        run::<3>();
        run::<4>();
        run::<6>();
        run::<8>();
    }

    #[test]
    fn refuses_entries_beyond_i128() {
        let vertices = [[1.0, 0.0], [1e-60, 1.0]];
        assert!(orientation(&vertices, &[0.5, 0.5]).is_none());
        assert!(cofactor_direction(&vertices).is_none());
    }
}
