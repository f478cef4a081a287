//! The (D−1)×(D−1) minors behind a hyperplane's cofactors, by a dynamic programme over column
//! subsets, for any scalar with a signed multiply-accumulate: `f64` with its permanent (the
//! filter) and double-double (the second stage).

/// The number of elements of every subset of 0..8 given as a bit mask (a table: `count_ones` is
/// not one instruction on baseline x86-64, and a plane asks it 2^D times).
pub(in crate::predicates) const SUBSET_SIZE: [u8; 256] = {
    let mut table = [0u8; 256];
    let mut mask = 1;
    while mask < 256 {
        table[mask] = table[mask >> 1] + (mask & 1) as u8;
        mask += 1;
    }
    table
};

/// A scalar of the expansion.
pub(in crate::predicates) trait MinorScalar: Copy {
    /// The empty minor (the determinant of a 0×0 matrix).
    const ONE: Self;
    /// The additive identity.
    const ZERO: Self;
    /// `acc − entry·minor` if `negative`, else `acc + entry·minor`.
    fn accumulate(acc: Self, entry: Self, minor: Self, negative: bool) -> Self;
    /// [`accumulate`](Self::accumulate) onto [`ZERO`](Self::ZERO): the first term of an
    /// expansion. A scalar whose addition of zero is exact but not free (double-double's
    /// costs a third of an accumulation) returns the term itself.
    #[inline(always)]
    fn first(entry: Self, minor: Self, negative: bool) -> Self {
        Self::accumulate(Self::ZERO, entry, minor, negative)
    }
}

/// The (D−1)×(D−1) minors of `rows[1..D]` omitting each column j: `minor[S]` is the determinant
/// of rows 1..=k restricted to the k columns of the bit set S (ascending), expanded along row k.
/// Masks are visited in increasing order, so S \ {j} (a smaller number) is always ready before S.
/// `N` ≥ 2^D is the table size (64 up to D = 6, else 256: zeroing 4 KB per facet was a
/// measurable share of a 6-D hull's time).
#[inline(always)]
pub(in crate::predicates) fn cofactor_minors<T: MinorScalar, const D: usize, const N: usize>(
    rows: &[[T; D]; D],
) -> [T; D] {
    let mut minor = [T::ZERO; N];
    minor[0] = T::ONE;
    let full = (1usize << D) - 1;
    for mask in 1..full {
        let k = SUBSET_SIZE[mask] as usize;
        if k >= D {
            continue;
        }
        let row = &rows[k];
        // Sign of column position t in S is (−1)^((k−1)+t).
        let mut negative = (k - 1) % 2 == 1;
        let mut bits = mask;
        let j = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        let mut m = T::first(row[j], minor[mask & !(1 << j)], negative);
        negative = !negative;
        while bits != 0 {
            let j = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            m = T::accumulate(m, row[j], minor[mask & !(1 << j)], negative);
            negative = !negative;
        }
        minor[mask] = m;
    }
    std::array::from_fn(|j| minor[full & !(1 << j)])
}

/// [`cofactor_minors`] with the table size chosen from `D`; for D = 6, the same minors written
/// out ([`minors6`](super::minors6::minors6)).
pub(in crate::predicates) fn minors_of<T: MinorScalar, const D: usize>(
    rows: &[[T; D]; D],
) -> [T; D] {
    minors_inlined(rows)
}

/// [`minors_of`], inlined into its caller: for a caller compiled with a target feature its
/// scalar's arithmetic needs (the fused double-double products).
#[inline(always)]
pub(in crate::predicates) fn minors_inlined<T: MinorScalar, const D: usize>(
    rows: &[[T; D]; D],
) -> [T; D] {
    // D = 3 to 8 written out (`minors_small`, `minors6`, `minors78`). The copies in and out
    // are of a constant size and vanish once inlined.
    macro_rules! written {
        ($n:literal, $f:path) => {{
            let rows: [[T; $n]; $n] = std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j]));
            let minors = $f(&rows);
            std::array::from_fn(|j| minors[j])
        }};
    }
    // Otherwise (2-D, and dimensions the hull refuses) the table as small as 2^D allows: it is
    // zeroed for every plane.
    match D {
        3 => written!(3, super::minors_small::minors3),
        4 => written!(4, super::minors_small::minors4),
        5 => written!(5, super::minors_small::minors5),
        6 => written!(6, super::minors6::minors6),
        0..=2 => cofactor_minors::<T, D, 4>(rows),
        7 => written!(7, super::minors78::minors7),
        8 => written!(8, super::minors78::minors8),
        _ => cofactor_minors::<T, D, 256>(rows),
    }
}

/// The filter's minors ([`minors_of`] on [`Tracked`]), in 4-D to 8-D compiled for AVX where
/// the processor has it: the same operations in the same order, so the same numbers to the
/// last bit (only `avx` is enabled, no product is fused, and Rust never contracts `a·b + c`),
/// in VEX's three-operand encoding, without most of the register copies that baseline SSE2's
/// two-operand form needs. Why: the filter's plane is the largest single cost of a hull on
/// generic input (half of a 6-D sphere's instructions). Measured in instructions
/// (docs/benchmarks.md, "the filter's minors compiled for AVX"): the 6-D sphere of 300 points
/// −17.7 %, the 5-D sphere −7.8 %, the 4-D −2.1 %. In 3-D the call the dispatch needs cost more
/// than it saved, hence 4-D and up, and the whole plane compiled for AVX, rather than its minors
/// alone, saved less (both builds uncommitted: their figures are in issue 24's note of
/// 2026-12-07). `tests::avx_minors_are_the_portable_ones_bit_for_bit` checks the sameness.
#[inline(always)]
pub(in crate::predicates) fn tracked_minors<const D: usize>(
    rows: &[[Tracked; D]; D],
) -> [Tracked; D] {
    #[cfg(target_arch = "x86_64")]
    if D >= 4 && std::arch::is_x86_feature_detected!("avx") {
        // One of the library's three `unsafe` calls (lib.rs says why they are allowed).
        #[allow(unsafe_code)]
        // SAFETY: `tracked_minors_avx` only requires the `avx` target feature, which the
        // processor was just found to have.
        return unsafe { tracked_minors_avx(rows) };
    }
    minors_of(rows)
}

/// [`tracked_minors`]'s expansion, inlined into a function compiled for AVX.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
fn tracked_minors_avx<const D: usize>(rows: &[[Tracked; D]; D]) -> [Tracked; D] {
    minors_inlined(rows)
}

/// An `f64` entry or minor with the permanent of absolute values behind it.
#[derive(Clone, Copy, Debug)]
pub(in crate::predicates) struct Tracked {
    /// The floating-point value.
    pub value: f64,
    /// The permanent of |entries| (for an entry, its magnitude).
    pub magnitude: f64,
}

impl MinorScalar for Tracked {
    const ONE: Self = Tracked {
        value: 1.0,
        magnitude: 1.0,
    };
    const ZERO: Self = Tracked {
        value: 0.0,
        magnitude: 0.0,
    };
    #[inline(always)]
    fn accumulate(acc: Self, entry: Self, minor: Self, negative: bool) -> Self {
        let term = entry.value * minor.value;
        Tracked {
            value: if negative {
                acc.value - term
            } else {
                acc.value + term
            },
            magnitude: acc.magnitude + entry.magnitude * minor.magnitude,
        }
    }
}

// The one test compares the AVX path with the portable one, which only x86-64 has.
#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::{Tracked, minors_of, tracked_minors};
    use crate::geometry::Rng;

    /// The filter's minors through the dispatch (compiled for AVX on an x86-64 processor that
    /// has it, as every machine this is tested on has) are the portable ones bit for bit, values
    /// and permanents, in 2-D to 8-D: on entries of every magnitude, exact zeros, and nearly
    /// dependent rows (slivers, whose minors cancel). On an x86-64 processor without AVX both
    /// sides would be the portable code, and the test fails rather than pass having compared
    /// nothing; elsewhere there is no AVX path to compare, and no test.
    #[test]
    fn avx_minors_are_the_portable_ones_bit_for_bit() {
        assert!(
            std::arch::is_x86_feature_detected!("avx"),
            "this processor has no AVX: the dispatch would compare the portable minors with \
             themselves"
        );
        fn check<const D: usize>(rng: &mut Rng, cases: usize) {
            for case in 0..cases {
                let base: [f64; D] = std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0));
                let rows: [[Tracked; D]; D] = std::array::from_fn(|_| {
                    let tilt = 2f64.powi(-(rng.below(50) as i32));
                    std::array::from_fn(|j| {
                        let value = match rng.below(6) {
                            0 => 0.0,
                            1 => base[j] * tilt,
                            2 => base[j] + rng.uniform_in(-1.0, 1.0) * tilt,
                            _ => rng.uniform_in(-1.0, 1.0) * 2f64.powi(rng.below(80) as i32 - 40),
                        };
                        Tracked {
                            value,
                            magnitude: value.abs(),
                        }
                    })
                });
                let bits = |m: [Tracked; D]| m.map(|t| (t.value.to_bits(), t.magnitude.to_bits()));
                assert_eq!(
                    bits(tracked_minors(&rows)),
                    bits(minors_of(&rows)),
                    "{D}-D case {case}"
                );
            }
        }
        let mut rng = Rng::new(41);
        check::<2>(&mut rng, 200);
        check::<3>(&mut rng, 500);
        check::<4>(&mut rng, 2_000);
        check::<5>(&mut rng, 2_000);
        check::<6>(&mut rng, 5_000);
        check::<7>(&mut rng, 1_000);
        check::<8>(&mut rng, 500);
    }
}
