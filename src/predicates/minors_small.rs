//! The cofactor minors of 3-D, 4-D and 5-D planes, written out as [`minors6`](super::minors6)
//! writes out the 6-D ones, by the same rule: every minor a local, expanded exactly as the
//! programme ([`cofactor_minors`](super::minors::cofactor_minors)) expands it, so that the two
//! give the same numbers bit for bit and the filter's error analysis holds unchanged (the test
//! below). Why: the programme's loop over a table of masks was a quarter of a 4-D sphere's
//! build (`FacetPlane::new`, `profile_rbox sphere 4 5000`).

use super::minors::MinorScalar;

/// [`cofactor_minors`](super::minors::cofactor_minors) for D = 3, written out.
#[rustfmt::skip]
#[inline(always)]
pub(in crate::predicates) fn minors3<T: MinorScalar>(rows: &[[T; 3]; 3]) -> [T; 3] {
    let (a, f, o) = (T::accumulate, T::first, T::ONE);
    let [_, r1, r2] = rows;
    let m1 = f(r1[0], o, false);
    let m2 = f(r1[1], o, false);
    let m4 = f(r1[2], o, false);
    let m3 = a(f(r2[0], m2, true), r2[1], m1, false);
    let m5 = a(f(r2[0], m4, true), r2[2], m1, false);
    let m6 = a(f(r2[1], m4, true), r2[2], m2, false);
    [m6, m5, m3]
}

/// [`cofactor_minors`](super::minors::cofactor_minors) for D = 4, written out.
#[rustfmt::skip]
#[inline(always)]
pub(in crate::predicates) fn minors4<T: MinorScalar>(rows: &[[T; 4]; 4]) -> [T; 4] {
    let (a, f, o) = (T::accumulate, T::first, T::ONE);
    let [_, r1, r2, r3] = rows;
    let m1 = f(r1[0], o, false);
    let m2 = f(r1[1], o, false);
    let m4 = f(r1[2], o, false);
    let m8 = f(r1[3], o, false);
    let m3 = a(f(r2[0], m2, true), r2[1], m1, false);
    let m5 = a(f(r2[0], m4, true), r2[2], m1, false);
    let m6 = a(f(r2[1], m4, true), r2[2], m2, false);
    let m9 = a(f(r2[0], m8, true), r2[3], m1, false);
    let m10 = a(f(r2[1], m8, true), r2[3], m2, false);
    let m12 = a(f(r2[2], m8, true), r2[3], m4, false);
    let m7 = a(a(f(r3[0], m6, false), r3[1], m5, true), r3[2], m3, false);
    let m11 = a(a(f(r3[0], m10, false), r3[1], m9, true), r3[3], m3, false);
    let m13 = a(a(f(r3[0], m12, false), r3[2], m9, true), r3[3], m5, false);
    let m14 = a(a(f(r3[1], m12, false), r3[2], m10, true), r3[3], m6, false);
    [m14, m13, m11, m7]
}

/// [`cofactor_minors`](super::minors::cofactor_minors) for D = 5, written out.
#[rustfmt::skip]
#[inline(always)]
pub(in crate::predicates) fn minors5<T: MinorScalar>(rows: &[[T; 5]; 5]) -> [T; 5] {
    let (a, f, o) = (T::accumulate, T::first, T::ONE);
    let [_, r1, r2, r3, r4] = rows;
    let m1 = f(r1[0], o, false);
    let m2 = f(r1[1], o, false);
    let m4 = f(r1[2], o, false);
    let m8 = f(r1[3], o, false);
    let m16 = f(r1[4], o, false);
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
    let m15 = a(a(a(f(r4[0], m14, true), r4[1], m13, false), r4[2], m11, true), r4[3], m7, false);
    let m23 = a(a(a(f(r4[0], m22, true), r4[1], m21, false), r4[2], m19, true), r4[4], m7, false);
    let m27 = a(a(a(f(r4[0], m26, true), r4[1], m25, false), r4[3], m19, true), r4[4], m11, false);
    let m29 = a(a(a(f(r4[0], m28, true), r4[2], m25, false), r4[3], m21, true), r4[4], m13, false);
    let m30 = a(a(a(f(r4[1], m28, true), r4[2], m26, false), r4[3], m22, true), r4[4], m14, false);
    [m30, m29, m27, m23, m15]
}

#[cfg(test)]
mod tests {
    use super::{minors3, minors4, minors5};
    use crate::geometry::Rng;
    use crate::predicates::minors::{Tracked, cofactor_minors};

    fn rows<const D: usize>(rng: &mut Rng) -> [[Tracked; D]; D] {
        std::array::from_fn(|_| {
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
        })
    }

    fn same<const D: usize>(written: [Tracked; D], programme: [Tracked; D], case: usize) {
        for j in 0..D {
            assert_eq!(
                (written[j].value.to_bits(), written[j].magnitude.to_bits()),
                (
                    programme[j].value.to_bits(),
                    programme[j].magnitude.to_bits()
                ),
                "D = {D}, case {case}, minor {j}"
            );
        }
    }

    #[test]
    fn written_out_minors_are_the_programme_s_bit_for_bit() {
        let mut rng = Rng::new(345);
        for case in 0..2000 {
            let r = rows::<3>(&mut rng);
            same(minors3(&r), cofactor_minors::<Tracked, 3, 8>(&r), case);
            let r = rows::<4>(&mut rng);
            same(minors4(&r), cofactor_minors::<Tracked, 4, 16>(&r), case);
            let r = rows::<5>(&mut rng);
            same(minors5(&r), cofactor_minors::<Tracked, 5, 32>(&r), case);
        }
    }
}
