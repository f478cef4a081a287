//! The cofactor minors of a 6-D plane (the grasp wrench space's dimension), written out.

use super::minors::MinorScalar;

/// [`cofactor_minors`](super::minors::cofactor_minors) for D = 6, written out: every minor a
/// local, every expansion one expression, so that the independent minors of one size overlap in
/// the processor instead of waiting on the programme's table in memory (force-closure Q1 at
/// 4 × 8: about a sixth less time, docs/benchmarks.md). Minor `m{S}` (S a bit set of columns) is
/// expanded exactly as the programme expands it — along row |S|, over the columns of S in
/// ascending order, signs alternating from (−1)^(|S|−1) — so the two give the same numbers bit
/// for bit and the filter's error analysis holds unchanged (the test below). Written out by that
/// rule, one line per minor; a macro over subsets would be harder to read than these lines.
#[rustfmt::skip]
#[inline(always)]
pub(in crate::predicates) fn minors6<T: MinorScalar>(rows: &[[T; 6]; 6]) -> [T; 6] {
    let (a, f, o) = (T::accumulate, T::first, T::ONE);
    let [_, r1, r2, r3, r4, r5] = rows;
    let m1 = f(r1[0], o, false);
    let m2 = f(r1[1], o, false);
    let m4 = f(r1[2], o, false);
    let m8 = f(r1[3], o, false);
    let m16 = f(r1[4], o, false);
    let m32 = f(r1[5], o, false);
    let m3 = a(f(r2[0], m2, true), r2[1], m1, false);
    let m5 = a(f(r2[0], m4, true), r2[2], m1, false);
    let m6 = a(f(r2[1], m4, true), r2[2], m2, false);
    let m9 = a(f(r2[0], m8, true), r2[3], m1, false);
    let m10 = a(f(r2[1], m8, true), r2[3], m2, false);
    let m12 = a(f(r2[2], m8, true), r2[3], m4, false);
    let m17 = a(f(r2[0], m16, true), r2[4], m1, false);
    let m18 = a(f(r2[1], m16, true), r2[4], m2, false);
    let m20 = a(f(r2[2], m16, true), r2[4], m4, false);
    let m24 = a(f(r2[3], m16, true), r2[4], m8, false);
    let m33 = a(f(r2[0], m32, true), r2[5], m1, false);
    let m34 = a(f(r2[1], m32, true), r2[5], m2, false);
    let m36 = a(f(r2[2], m32, true), r2[5], m4, false);
    let m40 = a(f(r2[3], m32, true), r2[5], m8, false);
    let m48 = a(f(r2[4], m32, true), r2[5], m16, false);
    let m7 = a(a(f(r3[0], m6, false), r3[1], m5, true), r3[2], m3, false);
    let m11 = a(a(f(r3[0], m10, false), r3[1], m9, true), r3[3], m3, false);
    let m13 = a(a(f(r3[0], m12, false), r3[2], m9, true), r3[3], m5, false);
    let m14 = a(a(f(r3[1], m12, false), r3[2], m10, true), r3[3], m6, false);
    let m19 = a(a(f(r3[0], m18, false), r3[1], m17, true), r3[4], m3, false);
    let m21 = a(a(f(r3[0], m20, false), r3[2], m17, true), r3[4], m5, false);
    let m22 = a(a(f(r3[1], m20, false), r3[2], m18, true), r3[4], m6, false);
    let m25 = a(a(f(r3[0], m24, false), r3[3], m17, true), r3[4], m9, false);
    let m26 = a(a(f(r3[1], m24, false), r3[3], m18, true), r3[4], m10, false);
    let m28 = a(a(f(r3[2], m24, false), r3[3], m20, true), r3[4], m12, false);
    let m35 = a(a(f(r3[0], m34, false), r3[1], m33, true), r3[5], m3, false);
    let m37 = a(a(f(r3[0], m36, false), r3[2], m33, true), r3[5], m5, false);
    let m38 = a(a(f(r3[1], m36, false), r3[2], m34, true), r3[5], m6, false);
    let m41 = a(a(f(r3[0], m40, false), r3[3], m33, true), r3[5], m9, false);
    let m42 = a(a(f(r3[1], m40, false), r3[3], m34, true), r3[5], m10, false);
    let m44 = a(a(f(r3[2], m40, false), r3[3], m36, true), r3[5], m12, false);
    let m49 = a(a(f(r3[0], m48, false), r3[4], m33, true), r3[5], m17, false);
    let m50 = a(a(f(r3[1], m48, false), r3[4], m34, true), r3[5], m18, false);
    let m52 = a(a(f(r3[2], m48, false), r3[4], m36, true), r3[5], m20, false);
    let m56 = a(a(f(r3[3], m48, false), r3[4], m40, true), r3[5], m24, false);
    let m15 = a(a(a(f(r4[0], m14, true), r4[1], m13, false), r4[2], m11, true), r4[3], m7, false);
    let m23 = a(a(a(f(r4[0], m22, true), r4[1], m21, false), r4[2], m19, true), r4[4], m7, false);
    let m27 = a(a(a(f(r4[0], m26, true), r4[1], m25, false), r4[3], m19, true), r4[4], m11, false);
    let m29 = a(a(a(f(r4[0], m28, true), r4[2], m25, false), r4[3], m21, true), r4[4], m13, false);
    let m30 = a(a(a(f(r4[1], m28, true), r4[2], m26, false), r4[3], m22, true), r4[4], m14, false);
    let m39 = a(a(a(f(r4[0], m38, true), r4[1], m37, false), r4[2], m35, true), r4[5], m7, false);
    let m43 = a(a(a(f(r4[0], m42, true), r4[1], m41, false), r4[3], m35, true), r4[5], m11, false);
    let m45 = a(a(a(f(r4[0], m44, true), r4[2], m41, false), r4[3], m37, true), r4[5], m13, false);
    let m46 = a(a(a(f(r4[1], m44, true), r4[2], m42, false), r4[3], m38, true), r4[5], m14, false);
    let m51 = a(a(a(f(r4[0], m50, true), r4[1], m49, false), r4[4], m35, true), r4[5], m19, false);
    let m53 = a(a(a(f(r4[0], m52, true), r4[2], m49, false), r4[4], m37, true), r4[5], m21, false);
    let m54 = a(a(a(f(r4[1], m52, true), r4[2], m50, false), r4[4], m38, true), r4[5], m22, false);
    let m57 = a(a(a(f(r4[0], m56, true), r4[3], m49, false), r4[4], m41, true), r4[5], m25, false);
    let m58 = a(a(a(f(r4[1], m56, true), r4[3], m50, false), r4[4], m42, true), r4[5], m26, false);
    let m60 = a(a(a(f(r4[2], m56, true), r4[3], m52, false), r4[4], m44, true), r4[5], m28, false);
    let m31 = a(a(a(a(f(r5[0], m30, false), r5[1], m29, true), r5[2], m27, false), r5[3], m23, true), r5[4], m15, false);
    let m47 = a(a(a(a(f(r5[0], m46, false), r5[1], m45, true), r5[2], m43, false), r5[3], m39, true), r5[5], m15, false);
    let m55 = a(a(a(a(f(r5[0], m54, false), r5[1], m53, true), r5[2], m51, false), r5[4], m39, true), r5[5], m23, false);
    let m59 = a(a(a(a(f(r5[0], m58, false), r5[1], m57, true), r5[3], m51, false), r5[4], m43, true), r5[5], m27, false);
    let m61 = a(a(a(a(f(r5[0], m60, false), r5[2], m57, true), r5[3], m53, false), r5[4], m45, true), r5[5], m29, false);
    let m62 = a(a(a(a(f(r5[1], m60, false), r5[2], m58, true), r5[3], m54, false), r5[4], m46, true), r5[5], m30, false);
    [m62, m61, m59, m55, m47, m31]
}

#[cfg(test)]
mod tests {
    use super::minors6;
    use crate::geometry::Rng;
    use crate::predicates::minors::{Tracked, cofactor_minors};

    #[test]
    fn written_out_minors_are_the_programme_s_bit_for_bit() {
        let mut rng = Rng::new(6);
        for case in 0..2000 {
            let rows: [[Tracked; 6]; 6] = std::array::from_fn(|_| {
                std::array::from_fn(|_| {
                    // Exact zeros and tiny entries too, as snapped and near-flat rows have.
                    let value = match rng.below(8) {
                        0 => 0.0,
                        1 => rng.uniform_in(-1.0, 1.0) * 1e-12,
                        _ => rng.uniform_in(-1.0, 1.0),
                    };
                    Tracked {
                        value,
                        magnitude: value.abs(),
                    }
                })
            });
            let written = minors6(&rows);
            let programme = cofactor_minors::<Tracked, 6, 64>(&rows);
            for j in 0..6 {
                assert_eq!(
                    (written[j].value.to_bits(), written[j].magnitude.to_bits()),
                    (
                        programme[j].value.to_bits(),
                        programme[j].magnitude.to_bits()
                    ),
                    "case {case}, minor {j}"
                );
            }
        }
    }
}
