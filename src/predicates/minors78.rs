//! The cofactor minors of 7-D and 8-D planes, written out as [`minors6`](super::minors6) writes
//! out the 6-D ones, by the same rule: every minor a local, expanded exactly as the programme
//! ([`cofactor_minors`](super::minors::cofactor_minors)) expands it, so that the two give the
//! same numbers bit for bit and the filter's error analysis holds unchanged (the test below).
//! Why: the programme's loop over its table of masks was nine tenths of a 7-D or 8-D hull's
//! instructions (an 8-D sphere of 60 points: 25,800 instructions a plane), and an 8-D sphere
//! took longer to hull than Qhull (docs/benchmarks.md, "2-D, 7-D and 8-D").

use super::minors::MinorScalar;

/// [`cofactor_minors`](super::minors::cofactor_minors) for D = 7, written out.
#[rustfmt::skip]
#[inline(always)]
pub(in crate::predicates) fn minors7<T: MinorScalar>(rows: &[[T; 7]; 7]) -> [T; 7] {
    let (a, f, o) = (T::accumulate, T::first, T::ONE);
    let [_, r1, r2, r3, r4, r5, r6] = rows;
    let m1 = f(r1[0], o, false);
    let m2 = f(r1[1], o, false);
    let m4 = f(r1[2], o, false);
    let m8 = f(r1[3], o, false);
    let m16 = f(r1[4], o, false);
    let m32 = f(r1[5], o, false);
    let m64 = f(r1[6], o, false);
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
    let m65 = a(f(r2[0], m64, true), r2[6], m1, false);
    let m66 = a(f(r2[1], m64, true), r2[6], m2, false);
    let m68 = a(f(r2[2], m64, true), r2[6], m4, false);
    let m72 = a(f(r2[3], m64, true), r2[6], m8, false);
    let m80 = a(f(r2[4], m64, true), r2[6], m16, false);
    let m96 = a(f(r2[5], m64, true), r2[6], m32, false);
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
    let m67 = a(a(f(r3[0], m66, false), r3[1], m65, true), r3[6], m3, false);
    let m69 = a(a(f(r3[0], m68, false), r3[2], m65, true), r3[6], m5, false);
    let m70 = a(a(f(r3[1], m68, false), r3[2], m66, true), r3[6], m6, false);
    let m73 = a(a(f(r3[0], m72, false), r3[3], m65, true), r3[6], m9, false);
    let m74 = a(a(f(r3[1], m72, false), r3[3], m66, true), r3[6], m10, false);
    let m76 = a(a(f(r3[2], m72, false), r3[3], m68, true), r3[6], m12, false);
    let m81 = a(a(f(r3[0], m80, false), r3[4], m65, true), r3[6], m17, false);
    let m82 = a(a(f(r3[1], m80, false), r3[4], m66, true), r3[6], m18, false);
    let m84 = a(a(f(r3[2], m80, false), r3[4], m68, true), r3[6], m20, false);
    let m88 = a(a(f(r3[3], m80, false), r3[4], m72, true), r3[6], m24, false);
    let m97 = a(a(f(r3[0], m96, false), r3[5], m65, true), r3[6], m33, false);
    let m98 = a(a(f(r3[1], m96, false), r3[5], m66, true), r3[6], m34, false);
    let m100 = a(a(f(r3[2], m96, false), r3[5], m68, true), r3[6], m36, false);
    let m104 = a(a(f(r3[3], m96, false), r3[5], m72, true), r3[6], m40, false);
    let m112 = a(a(f(r3[4], m96, false), r3[5], m80, true), r3[6], m48, false);
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
    let m71 = a(a(a(f(r4[0], m70, true), r4[1], m69, false), r4[2], m67, true), r4[6], m7, false);
    let m75 = a(a(a(f(r4[0], m74, true), r4[1], m73, false), r4[3], m67, true), r4[6], m11, false);
    let m77 = a(a(a(f(r4[0], m76, true), r4[2], m73, false), r4[3], m69, true), r4[6], m13, false);
    let m78 = a(a(a(f(r4[1], m76, true), r4[2], m74, false), r4[3], m70, true), r4[6], m14, false);
    let m83 = a(a(a(f(r4[0], m82, true), r4[1], m81, false), r4[4], m67, true), r4[6], m19, false);
    let m85 = a(a(a(f(r4[0], m84, true), r4[2], m81, false), r4[4], m69, true), r4[6], m21, false);
    let m86 = a(a(a(f(r4[1], m84, true), r4[2], m82, false), r4[4], m70, true), r4[6], m22, false);
    let m89 = a(a(a(f(r4[0], m88, true), r4[3], m81, false), r4[4], m73, true), r4[6], m25, false);
    let m90 = a(a(a(f(r4[1], m88, true), r4[3], m82, false), r4[4], m74, true), r4[6], m26, false);
    let m92 = a(a(a(f(r4[2], m88, true), r4[3], m84, false), r4[4], m76, true), r4[6], m28, false);
    let m99 = a(a(a(f(r4[0], m98, true), r4[1], m97, false), r4[5], m67, true), r4[6], m35, false);
    let m101 = a(a(a(f(r4[0], m100, true), r4[2], m97, false), r4[5], m69, true), r4[6], m37, false);
    let m102 = a(a(a(f(r4[1], m100, true), r4[2], m98, false), r4[5], m70, true), r4[6], m38, false);
    let m105 = a(a(a(f(r4[0], m104, true), r4[3], m97, false), r4[5], m73, true), r4[6], m41, false);
    let m106 = a(a(a(f(r4[1], m104, true), r4[3], m98, false), r4[5], m74, true), r4[6], m42, false);
    let m108 = a(a(a(f(r4[2], m104, true), r4[3], m100, false), r4[5], m76, true), r4[6], m44, false);
    let m113 = a(a(a(f(r4[0], m112, true), r4[4], m97, false), r4[5], m81, true), r4[6], m49, false);
    let m114 = a(a(a(f(r4[1], m112, true), r4[4], m98, false), r4[5], m82, true), r4[6], m50, false);
    let m116 = a(a(a(f(r4[2], m112, true), r4[4], m100, false), r4[5], m84, true), r4[6], m52, false);
    let m120 = a(a(a(f(r4[3], m112, true), r4[4], m104, false), r4[5], m88, true), r4[6], m56, false);
    let m31 = a(a(a(a(f(r5[0], m30, false), r5[1], m29, true), r5[2], m27, false), r5[3], m23, true), r5[4], m15, false);
    let m47 = a(a(a(a(f(r5[0], m46, false), r5[1], m45, true), r5[2], m43, false), r5[3], m39, true), r5[5], m15, false);
    let m55 = a(a(a(a(f(r5[0], m54, false), r5[1], m53, true), r5[2], m51, false), r5[4], m39, true), r5[5], m23, false);
    let m59 = a(a(a(a(f(r5[0], m58, false), r5[1], m57, true), r5[3], m51, false), r5[4], m43, true), r5[5], m27, false);
    let m61 = a(a(a(a(f(r5[0], m60, false), r5[2], m57, true), r5[3], m53, false), r5[4], m45, true), r5[5], m29, false);
    let m62 = a(a(a(a(f(r5[1], m60, false), r5[2], m58, true), r5[3], m54, false), r5[4], m46, true), r5[5], m30, false);
    let m79 = a(a(a(a(f(r5[0], m78, false), r5[1], m77, true), r5[2], m75, false), r5[3], m71, true), r5[6], m15, false);
    let m87 = a(a(a(a(f(r5[0], m86, false), r5[1], m85, true), r5[2], m83, false), r5[4], m71, true), r5[6], m23, false);
    let m91 = a(a(a(a(f(r5[0], m90, false), r5[1], m89, true), r5[3], m83, false), r5[4], m75, true), r5[6], m27, false);
    let m93 = a(a(a(a(f(r5[0], m92, false), r5[2], m89, true), r5[3], m85, false), r5[4], m77, true), r5[6], m29, false);
    let m94 = a(a(a(a(f(r5[1], m92, false), r5[2], m90, true), r5[3], m86, false), r5[4], m78, true), r5[6], m30, false);
    let m103 = a(a(a(a(f(r5[0], m102, false), r5[1], m101, true), r5[2], m99, false), r5[5], m71, true), r5[6], m39, false);
    let m107 = a(a(a(a(f(r5[0], m106, false), r5[1], m105, true), r5[3], m99, false), r5[5], m75, true), r5[6], m43, false);
    let m109 = a(a(a(a(f(r5[0], m108, false), r5[2], m105, true), r5[3], m101, false), r5[5], m77, true), r5[6], m45, false);
    let m110 = a(a(a(a(f(r5[1], m108, false), r5[2], m106, true), r5[3], m102, false), r5[5], m78, true), r5[6], m46, false);
    let m115 = a(a(a(a(f(r5[0], m114, false), r5[1], m113, true), r5[4], m99, false), r5[5], m83, true), r5[6], m51, false);
    let m117 = a(a(a(a(f(r5[0], m116, false), r5[2], m113, true), r5[4], m101, false), r5[5], m85, true), r5[6], m53, false);
    let m118 = a(a(a(a(f(r5[1], m116, false), r5[2], m114, true), r5[4], m102, false), r5[5], m86, true), r5[6], m54, false);
    let m121 = a(a(a(a(f(r5[0], m120, false), r5[3], m113, true), r5[4], m105, false), r5[5], m89, true), r5[6], m57, false);
    let m122 = a(a(a(a(f(r5[1], m120, false), r5[3], m114, true), r5[4], m106, false), r5[5], m90, true), r5[6], m58, false);
    let m124 = a(a(a(a(f(r5[2], m120, false), r5[3], m116, true), r5[4], m108, false), r5[5], m92, true), r5[6], m60, false);
    let m63 = a(a(a(a(a(f(r6[0], m62, true), r6[1], m61, false), r6[2], m59, true), r6[3], m55, false), r6[4], m47, true), r6[5], m31, false);
    let m95 = a(a(a(a(a(f(r6[0], m94, true), r6[1], m93, false), r6[2], m91, true), r6[3], m87, false), r6[4], m79, true), r6[6], m31, false);
    let m111 = a(a(a(a(a(f(r6[0], m110, true), r6[1], m109, false), r6[2], m107, true), r6[3], m103, false), r6[5], m79, true), r6[6], m47, false);
    let m119 = a(a(a(a(a(f(r6[0], m118, true), r6[1], m117, false), r6[2], m115, true), r6[4], m103, false), r6[5], m87, true), r6[6], m55, false);
    let m123 = a(a(a(a(a(f(r6[0], m122, true), r6[1], m121, false), r6[3], m115, true), r6[4], m107, false), r6[5], m91, true), r6[6], m59, false);
    let m125 = a(a(a(a(a(f(r6[0], m124, true), r6[2], m121, false), r6[3], m117, true), r6[4], m109, false), r6[5], m93, true), r6[6], m61, false);
    let m126 = a(a(a(a(a(f(r6[1], m124, true), r6[2], m122, false), r6[3], m118, true), r6[4], m110, false), r6[5], m94, true), r6[6], m62, false);
    [m126, m125, m123, m119, m111, m95, m63]
}

/// [`cofactor_minors`](super::minors::cofactor_minors) for D = 8, written out.
#[rustfmt::skip]
#[inline(always)]
pub(in crate::predicates) fn minors8<T: MinorScalar>(rows: &[[T; 8]; 8]) -> [T; 8] {
    let (a, f, o) = (T::accumulate, T::first, T::ONE);
    let [_, r1, r2, r3, r4, r5, r6, r7] = rows;
    let m1 = f(r1[0], o, false);
    let m2 = f(r1[1], o, false);
    let m4 = f(r1[2], o, false);
    let m8 = f(r1[3], o, false);
    let m16 = f(r1[4], o, false);
    let m32 = f(r1[5], o, false);
    let m64 = f(r1[6], o, false);
    let m128 = f(r1[7], o, false);
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
    let m65 = a(f(r2[0], m64, true), r2[6], m1, false);
    let m66 = a(f(r2[1], m64, true), r2[6], m2, false);
    let m68 = a(f(r2[2], m64, true), r2[6], m4, false);
    let m72 = a(f(r2[3], m64, true), r2[6], m8, false);
    let m80 = a(f(r2[4], m64, true), r2[6], m16, false);
    let m96 = a(f(r2[5], m64, true), r2[6], m32, false);
    let m129 = a(f(r2[0], m128, true), r2[7], m1, false);
    let m130 = a(f(r2[1], m128, true), r2[7], m2, false);
    let m132 = a(f(r2[2], m128, true), r2[7], m4, false);
    let m136 = a(f(r2[3], m128, true), r2[7], m8, false);
    let m144 = a(f(r2[4], m128, true), r2[7], m16, false);
    let m160 = a(f(r2[5], m128, true), r2[7], m32, false);
    let m192 = a(f(r2[6], m128, true), r2[7], m64, false);
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
    let m67 = a(a(f(r3[0], m66, false), r3[1], m65, true), r3[6], m3, false);
    let m69 = a(a(f(r3[0], m68, false), r3[2], m65, true), r3[6], m5, false);
    let m70 = a(a(f(r3[1], m68, false), r3[2], m66, true), r3[6], m6, false);
    let m73 = a(a(f(r3[0], m72, false), r3[3], m65, true), r3[6], m9, false);
    let m74 = a(a(f(r3[1], m72, false), r3[3], m66, true), r3[6], m10, false);
    let m76 = a(a(f(r3[2], m72, false), r3[3], m68, true), r3[6], m12, false);
    let m81 = a(a(f(r3[0], m80, false), r3[4], m65, true), r3[6], m17, false);
    let m82 = a(a(f(r3[1], m80, false), r3[4], m66, true), r3[6], m18, false);
    let m84 = a(a(f(r3[2], m80, false), r3[4], m68, true), r3[6], m20, false);
    let m88 = a(a(f(r3[3], m80, false), r3[4], m72, true), r3[6], m24, false);
    let m97 = a(a(f(r3[0], m96, false), r3[5], m65, true), r3[6], m33, false);
    let m98 = a(a(f(r3[1], m96, false), r3[5], m66, true), r3[6], m34, false);
    let m100 = a(a(f(r3[2], m96, false), r3[5], m68, true), r3[6], m36, false);
    let m104 = a(a(f(r3[3], m96, false), r3[5], m72, true), r3[6], m40, false);
    let m112 = a(a(f(r3[4], m96, false), r3[5], m80, true), r3[6], m48, false);
    let m131 = a(a(f(r3[0], m130, false), r3[1], m129, true), r3[7], m3, false);
    let m133 = a(a(f(r3[0], m132, false), r3[2], m129, true), r3[7], m5, false);
    let m134 = a(a(f(r3[1], m132, false), r3[2], m130, true), r3[7], m6, false);
    let m137 = a(a(f(r3[0], m136, false), r3[3], m129, true), r3[7], m9, false);
    let m138 = a(a(f(r3[1], m136, false), r3[3], m130, true), r3[7], m10, false);
    let m140 = a(a(f(r3[2], m136, false), r3[3], m132, true), r3[7], m12, false);
    let m145 = a(a(f(r3[0], m144, false), r3[4], m129, true), r3[7], m17, false);
    let m146 = a(a(f(r3[1], m144, false), r3[4], m130, true), r3[7], m18, false);
    let m148 = a(a(f(r3[2], m144, false), r3[4], m132, true), r3[7], m20, false);
    let m152 = a(a(f(r3[3], m144, false), r3[4], m136, true), r3[7], m24, false);
    let m161 = a(a(f(r3[0], m160, false), r3[5], m129, true), r3[7], m33, false);
    let m162 = a(a(f(r3[1], m160, false), r3[5], m130, true), r3[7], m34, false);
    let m164 = a(a(f(r3[2], m160, false), r3[5], m132, true), r3[7], m36, false);
    let m168 = a(a(f(r3[3], m160, false), r3[5], m136, true), r3[7], m40, false);
    let m176 = a(a(f(r3[4], m160, false), r3[5], m144, true), r3[7], m48, false);
    let m193 = a(a(f(r3[0], m192, false), r3[6], m129, true), r3[7], m65, false);
    let m194 = a(a(f(r3[1], m192, false), r3[6], m130, true), r3[7], m66, false);
    let m196 = a(a(f(r3[2], m192, false), r3[6], m132, true), r3[7], m68, false);
    let m200 = a(a(f(r3[3], m192, false), r3[6], m136, true), r3[7], m72, false);
    let m208 = a(a(f(r3[4], m192, false), r3[6], m144, true), r3[7], m80, false);
    let m224 = a(a(f(r3[5], m192, false), r3[6], m160, true), r3[7], m96, false);
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
    let m71 = a(a(a(f(r4[0], m70, true), r4[1], m69, false), r4[2], m67, true), r4[6], m7, false);
    let m75 = a(a(a(f(r4[0], m74, true), r4[1], m73, false), r4[3], m67, true), r4[6], m11, false);
    let m77 = a(a(a(f(r4[0], m76, true), r4[2], m73, false), r4[3], m69, true), r4[6], m13, false);
    let m78 = a(a(a(f(r4[1], m76, true), r4[2], m74, false), r4[3], m70, true), r4[6], m14, false);
    let m83 = a(a(a(f(r4[0], m82, true), r4[1], m81, false), r4[4], m67, true), r4[6], m19, false);
    let m85 = a(a(a(f(r4[0], m84, true), r4[2], m81, false), r4[4], m69, true), r4[6], m21, false);
    let m86 = a(a(a(f(r4[1], m84, true), r4[2], m82, false), r4[4], m70, true), r4[6], m22, false);
    let m89 = a(a(a(f(r4[0], m88, true), r4[3], m81, false), r4[4], m73, true), r4[6], m25, false);
    let m90 = a(a(a(f(r4[1], m88, true), r4[3], m82, false), r4[4], m74, true), r4[6], m26, false);
    let m92 = a(a(a(f(r4[2], m88, true), r4[3], m84, false), r4[4], m76, true), r4[6], m28, false);
    let m99 = a(a(a(f(r4[0], m98, true), r4[1], m97, false), r4[5], m67, true), r4[6], m35, false);
    let m101 = a(a(a(f(r4[0], m100, true), r4[2], m97, false), r4[5], m69, true), r4[6], m37, false);
    let m102 = a(a(a(f(r4[1], m100, true), r4[2], m98, false), r4[5], m70, true), r4[6], m38, false);
    let m105 = a(a(a(f(r4[0], m104, true), r4[3], m97, false), r4[5], m73, true), r4[6], m41, false);
    let m106 = a(a(a(f(r4[1], m104, true), r4[3], m98, false), r4[5], m74, true), r4[6], m42, false);
    let m108 = a(a(a(f(r4[2], m104, true), r4[3], m100, false), r4[5], m76, true), r4[6], m44, false);
    let m113 = a(a(a(f(r4[0], m112, true), r4[4], m97, false), r4[5], m81, true), r4[6], m49, false);
    let m114 = a(a(a(f(r4[1], m112, true), r4[4], m98, false), r4[5], m82, true), r4[6], m50, false);
    let m116 = a(a(a(f(r4[2], m112, true), r4[4], m100, false), r4[5], m84, true), r4[6], m52, false);
    let m120 = a(a(a(f(r4[3], m112, true), r4[4], m104, false), r4[5], m88, true), r4[6], m56, false);
    let m135 = a(a(a(f(r4[0], m134, true), r4[1], m133, false), r4[2], m131, true), r4[7], m7, false);
    let m139 = a(a(a(f(r4[0], m138, true), r4[1], m137, false), r4[3], m131, true), r4[7], m11, false);
    let m141 = a(a(a(f(r4[0], m140, true), r4[2], m137, false), r4[3], m133, true), r4[7], m13, false);
    let m142 = a(a(a(f(r4[1], m140, true), r4[2], m138, false), r4[3], m134, true), r4[7], m14, false);
    let m147 = a(a(a(f(r4[0], m146, true), r4[1], m145, false), r4[4], m131, true), r4[7], m19, false);
    let m149 = a(a(a(f(r4[0], m148, true), r4[2], m145, false), r4[4], m133, true), r4[7], m21, false);
    let m150 = a(a(a(f(r4[1], m148, true), r4[2], m146, false), r4[4], m134, true), r4[7], m22, false);
    let m153 = a(a(a(f(r4[0], m152, true), r4[3], m145, false), r4[4], m137, true), r4[7], m25, false);
    let m154 = a(a(a(f(r4[1], m152, true), r4[3], m146, false), r4[4], m138, true), r4[7], m26, false);
    let m156 = a(a(a(f(r4[2], m152, true), r4[3], m148, false), r4[4], m140, true), r4[7], m28, false);
    let m163 = a(a(a(f(r4[0], m162, true), r4[1], m161, false), r4[5], m131, true), r4[7], m35, false);
    let m165 = a(a(a(f(r4[0], m164, true), r4[2], m161, false), r4[5], m133, true), r4[7], m37, false);
    let m166 = a(a(a(f(r4[1], m164, true), r4[2], m162, false), r4[5], m134, true), r4[7], m38, false);
    let m169 = a(a(a(f(r4[0], m168, true), r4[3], m161, false), r4[5], m137, true), r4[7], m41, false);
    let m170 = a(a(a(f(r4[1], m168, true), r4[3], m162, false), r4[5], m138, true), r4[7], m42, false);
    let m172 = a(a(a(f(r4[2], m168, true), r4[3], m164, false), r4[5], m140, true), r4[7], m44, false);
    let m177 = a(a(a(f(r4[0], m176, true), r4[4], m161, false), r4[5], m145, true), r4[7], m49, false);
    let m178 = a(a(a(f(r4[1], m176, true), r4[4], m162, false), r4[5], m146, true), r4[7], m50, false);
    let m180 = a(a(a(f(r4[2], m176, true), r4[4], m164, false), r4[5], m148, true), r4[7], m52, false);
    let m184 = a(a(a(f(r4[3], m176, true), r4[4], m168, false), r4[5], m152, true), r4[7], m56, false);
    let m195 = a(a(a(f(r4[0], m194, true), r4[1], m193, false), r4[6], m131, true), r4[7], m67, false);
    let m197 = a(a(a(f(r4[0], m196, true), r4[2], m193, false), r4[6], m133, true), r4[7], m69, false);
    let m198 = a(a(a(f(r4[1], m196, true), r4[2], m194, false), r4[6], m134, true), r4[7], m70, false);
    let m201 = a(a(a(f(r4[0], m200, true), r4[3], m193, false), r4[6], m137, true), r4[7], m73, false);
    let m202 = a(a(a(f(r4[1], m200, true), r4[3], m194, false), r4[6], m138, true), r4[7], m74, false);
    let m204 = a(a(a(f(r4[2], m200, true), r4[3], m196, false), r4[6], m140, true), r4[7], m76, false);
    let m209 = a(a(a(f(r4[0], m208, true), r4[4], m193, false), r4[6], m145, true), r4[7], m81, false);
    let m210 = a(a(a(f(r4[1], m208, true), r4[4], m194, false), r4[6], m146, true), r4[7], m82, false);
    let m212 = a(a(a(f(r4[2], m208, true), r4[4], m196, false), r4[6], m148, true), r4[7], m84, false);
    let m216 = a(a(a(f(r4[3], m208, true), r4[4], m200, false), r4[6], m152, true), r4[7], m88, false);
    let m225 = a(a(a(f(r4[0], m224, true), r4[5], m193, false), r4[6], m161, true), r4[7], m97, false);
    let m226 = a(a(a(f(r4[1], m224, true), r4[5], m194, false), r4[6], m162, true), r4[7], m98, false);
    let m228 = a(a(a(f(r4[2], m224, true), r4[5], m196, false), r4[6], m164, true), r4[7], m100, false);
    let m232 = a(a(a(f(r4[3], m224, true), r4[5], m200, false), r4[6], m168, true), r4[7], m104, false);
    let m240 = a(a(a(f(r4[4], m224, true), r4[5], m208, false), r4[6], m176, true), r4[7], m112, false);
    let m31 = a(a(a(a(f(r5[0], m30, false), r5[1], m29, true), r5[2], m27, false), r5[3], m23, true), r5[4], m15, false);
    let m47 = a(a(a(a(f(r5[0], m46, false), r5[1], m45, true), r5[2], m43, false), r5[3], m39, true), r5[5], m15, false);
    let m55 = a(a(a(a(f(r5[0], m54, false), r5[1], m53, true), r5[2], m51, false), r5[4], m39, true), r5[5], m23, false);
    let m59 = a(a(a(a(f(r5[0], m58, false), r5[1], m57, true), r5[3], m51, false), r5[4], m43, true), r5[5], m27, false);
    let m61 = a(a(a(a(f(r5[0], m60, false), r5[2], m57, true), r5[3], m53, false), r5[4], m45, true), r5[5], m29, false);
    let m62 = a(a(a(a(f(r5[1], m60, false), r5[2], m58, true), r5[3], m54, false), r5[4], m46, true), r5[5], m30, false);
    let m79 = a(a(a(a(f(r5[0], m78, false), r5[1], m77, true), r5[2], m75, false), r5[3], m71, true), r5[6], m15, false);
    let m87 = a(a(a(a(f(r5[0], m86, false), r5[1], m85, true), r5[2], m83, false), r5[4], m71, true), r5[6], m23, false);
    let m91 = a(a(a(a(f(r5[0], m90, false), r5[1], m89, true), r5[3], m83, false), r5[4], m75, true), r5[6], m27, false);
    let m93 = a(a(a(a(f(r5[0], m92, false), r5[2], m89, true), r5[3], m85, false), r5[4], m77, true), r5[6], m29, false);
    let m94 = a(a(a(a(f(r5[1], m92, false), r5[2], m90, true), r5[3], m86, false), r5[4], m78, true), r5[6], m30, false);
    let m103 = a(a(a(a(f(r5[0], m102, false), r5[1], m101, true), r5[2], m99, false), r5[5], m71, true), r5[6], m39, false);
    let m107 = a(a(a(a(f(r5[0], m106, false), r5[1], m105, true), r5[3], m99, false), r5[5], m75, true), r5[6], m43, false);
    let m109 = a(a(a(a(f(r5[0], m108, false), r5[2], m105, true), r5[3], m101, false), r5[5], m77, true), r5[6], m45, false);
    let m110 = a(a(a(a(f(r5[1], m108, false), r5[2], m106, true), r5[3], m102, false), r5[5], m78, true), r5[6], m46, false);
    let m115 = a(a(a(a(f(r5[0], m114, false), r5[1], m113, true), r5[4], m99, false), r5[5], m83, true), r5[6], m51, false);
    let m117 = a(a(a(a(f(r5[0], m116, false), r5[2], m113, true), r5[4], m101, false), r5[5], m85, true), r5[6], m53, false);
    let m118 = a(a(a(a(f(r5[1], m116, false), r5[2], m114, true), r5[4], m102, false), r5[5], m86, true), r5[6], m54, false);
    let m121 = a(a(a(a(f(r5[0], m120, false), r5[3], m113, true), r5[4], m105, false), r5[5], m89, true), r5[6], m57, false);
    let m122 = a(a(a(a(f(r5[1], m120, false), r5[3], m114, true), r5[4], m106, false), r5[5], m90, true), r5[6], m58, false);
    let m124 = a(a(a(a(f(r5[2], m120, false), r5[3], m116, true), r5[4], m108, false), r5[5], m92, true), r5[6], m60, false);
    let m143 = a(a(a(a(f(r5[0], m142, false), r5[1], m141, true), r5[2], m139, false), r5[3], m135, true), r5[7], m15, false);
    let m151 = a(a(a(a(f(r5[0], m150, false), r5[1], m149, true), r5[2], m147, false), r5[4], m135, true), r5[7], m23, false);
    let m155 = a(a(a(a(f(r5[0], m154, false), r5[1], m153, true), r5[3], m147, false), r5[4], m139, true), r5[7], m27, false);
    let m157 = a(a(a(a(f(r5[0], m156, false), r5[2], m153, true), r5[3], m149, false), r5[4], m141, true), r5[7], m29, false);
    let m158 = a(a(a(a(f(r5[1], m156, false), r5[2], m154, true), r5[3], m150, false), r5[4], m142, true), r5[7], m30, false);
    let m167 = a(a(a(a(f(r5[0], m166, false), r5[1], m165, true), r5[2], m163, false), r5[5], m135, true), r5[7], m39, false);
    let m171 = a(a(a(a(f(r5[0], m170, false), r5[1], m169, true), r5[3], m163, false), r5[5], m139, true), r5[7], m43, false);
    let m173 = a(a(a(a(f(r5[0], m172, false), r5[2], m169, true), r5[3], m165, false), r5[5], m141, true), r5[7], m45, false);
    let m174 = a(a(a(a(f(r5[1], m172, false), r5[2], m170, true), r5[3], m166, false), r5[5], m142, true), r5[7], m46, false);
    let m179 = a(a(a(a(f(r5[0], m178, false), r5[1], m177, true), r5[4], m163, false), r5[5], m147, true), r5[7], m51, false);
    let m181 = a(a(a(a(f(r5[0], m180, false), r5[2], m177, true), r5[4], m165, false), r5[5], m149, true), r5[7], m53, false);
    let m182 = a(a(a(a(f(r5[1], m180, false), r5[2], m178, true), r5[4], m166, false), r5[5], m150, true), r5[7], m54, false);
    let m185 = a(a(a(a(f(r5[0], m184, false), r5[3], m177, true), r5[4], m169, false), r5[5], m153, true), r5[7], m57, false);
    let m186 = a(a(a(a(f(r5[1], m184, false), r5[3], m178, true), r5[4], m170, false), r5[5], m154, true), r5[7], m58, false);
    let m188 = a(a(a(a(f(r5[2], m184, false), r5[3], m180, true), r5[4], m172, false), r5[5], m156, true), r5[7], m60, false);
    let m199 = a(a(a(a(f(r5[0], m198, false), r5[1], m197, true), r5[2], m195, false), r5[6], m135, true), r5[7], m71, false);
    let m203 = a(a(a(a(f(r5[0], m202, false), r5[1], m201, true), r5[3], m195, false), r5[6], m139, true), r5[7], m75, false);
    let m205 = a(a(a(a(f(r5[0], m204, false), r5[2], m201, true), r5[3], m197, false), r5[6], m141, true), r5[7], m77, false);
    let m206 = a(a(a(a(f(r5[1], m204, false), r5[2], m202, true), r5[3], m198, false), r5[6], m142, true), r5[7], m78, false);
    let m211 = a(a(a(a(f(r5[0], m210, false), r5[1], m209, true), r5[4], m195, false), r5[6], m147, true), r5[7], m83, false);
    let m213 = a(a(a(a(f(r5[0], m212, false), r5[2], m209, true), r5[4], m197, false), r5[6], m149, true), r5[7], m85, false);
    let m214 = a(a(a(a(f(r5[1], m212, false), r5[2], m210, true), r5[4], m198, false), r5[6], m150, true), r5[7], m86, false);
    let m217 = a(a(a(a(f(r5[0], m216, false), r5[3], m209, true), r5[4], m201, false), r5[6], m153, true), r5[7], m89, false);
    let m218 = a(a(a(a(f(r5[1], m216, false), r5[3], m210, true), r5[4], m202, false), r5[6], m154, true), r5[7], m90, false);
    let m220 = a(a(a(a(f(r5[2], m216, false), r5[3], m212, true), r5[4], m204, false), r5[6], m156, true), r5[7], m92, false);
    let m227 = a(a(a(a(f(r5[0], m226, false), r5[1], m225, true), r5[5], m195, false), r5[6], m163, true), r5[7], m99, false);
    let m229 = a(a(a(a(f(r5[0], m228, false), r5[2], m225, true), r5[5], m197, false), r5[6], m165, true), r5[7], m101, false);
    let m230 = a(a(a(a(f(r5[1], m228, false), r5[2], m226, true), r5[5], m198, false), r5[6], m166, true), r5[7], m102, false);
    let m233 = a(a(a(a(f(r5[0], m232, false), r5[3], m225, true), r5[5], m201, false), r5[6], m169, true), r5[7], m105, false);
    let m234 = a(a(a(a(f(r5[1], m232, false), r5[3], m226, true), r5[5], m202, false), r5[6], m170, true), r5[7], m106, false);
    let m236 = a(a(a(a(f(r5[2], m232, false), r5[3], m228, true), r5[5], m204, false), r5[6], m172, true), r5[7], m108, false);
    let m241 = a(a(a(a(f(r5[0], m240, false), r5[4], m225, true), r5[5], m209, false), r5[6], m177, true), r5[7], m113, false);
    let m242 = a(a(a(a(f(r5[1], m240, false), r5[4], m226, true), r5[5], m210, false), r5[6], m178, true), r5[7], m114, false);
    let m244 = a(a(a(a(f(r5[2], m240, false), r5[4], m228, true), r5[5], m212, false), r5[6], m180, true), r5[7], m116, false);
    let m248 = a(a(a(a(f(r5[3], m240, false), r5[4], m232, true), r5[5], m216, false), r5[6], m184, true), r5[7], m120, false);
    let m63 = a(a(a(a(a(f(r6[0], m62, true), r6[1], m61, false), r6[2], m59, true), r6[3], m55, false), r6[4], m47, true), r6[5], m31, false);
    let m95 = a(a(a(a(a(f(r6[0], m94, true), r6[1], m93, false), r6[2], m91, true), r6[3], m87, false), r6[4], m79, true), r6[6], m31, false);
    let m111 = a(a(a(a(a(f(r6[0], m110, true), r6[1], m109, false), r6[2], m107, true), r6[3], m103, false), r6[5], m79, true), r6[6], m47, false);
    let m119 = a(a(a(a(a(f(r6[0], m118, true), r6[1], m117, false), r6[2], m115, true), r6[4], m103, false), r6[5], m87, true), r6[6], m55, false);
    let m123 = a(a(a(a(a(f(r6[0], m122, true), r6[1], m121, false), r6[3], m115, true), r6[4], m107, false), r6[5], m91, true), r6[6], m59, false);
    let m125 = a(a(a(a(a(f(r6[0], m124, true), r6[2], m121, false), r6[3], m117, true), r6[4], m109, false), r6[5], m93, true), r6[6], m61, false);
    let m126 = a(a(a(a(a(f(r6[1], m124, true), r6[2], m122, false), r6[3], m118, true), r6[4], m110, false), r6[5], m94, true), r6[6], m62, false);
    let m159 = a(a(a(a(a(f(r6[0], m158, true), r6[1], m157, false), r6[2], m155, true), r6[3], m151, false), r6[4], m143, true), r6[7], m31, false);
    let m175 = a(a(a(a(a(f(r6[0], m174, true), r6[1], m173, false), r6[2], m171, true), r6[3], m167, false), r6[5], m143, true), r6[7], m47, false);
    let m183 = a(a(a(a(a(f(r6[0], m182, true), r6[1], m181, false), r6[2], m179, true), r6[4], m167, false), r6[5], m151, true), r6[7], m55, false);
    let m187 = a(a(a(a(a(f(r6[0], m186, true), r6[1], m185, false), r6[3], m179, true), r6[4], m171, false), r6[5], m155, true), r6[7], m59, false);
    let m189 = a(a(a(a(a(f(r6[0], m188, true), r6[2], m185, false), r6[3], m181, true), r6[4], m173, false), r6[5], m157, true), r6[7], m61, false);
    let m190 = a(a(a(a(a(f(r6[1], m188, true), r6[2], m186, false), r6[3], m182, true), r6[4], m174, false), r6[5], m158, true), r6[7], m62, false);
    let m207 = a(a(a(a(a(f(r6[0], m206, true), r6[1], m205, false), r6[2], m203, true), r6[3], m199, false), r6[6], m143, true), r6[7], m79, false);
    let m215 = a(a(a(a(a(f(r6[0], m214, true), r6[1], m213, false), r6[2], m211, true), r6[4], m199, false), r6[6], m151, true), r6[7], m87, false);
    let m219 = a(a(a(a(a(f(r6[0], m218, true), r6[1], m217, false), r6[3], m211, true), r6[4], m203, false), r6[6], m155, true), r6[7], m91, false);
    let m221 = a(a(a(a(a(f(r6[0], m220, true), r6[2], m217, false), r6[3], m213, true), r6[4], m205, false), r6[6], m157, true), r6[7], m93, false);
    let m222 = a(a(a(a(a(f(r6[1], m220, true), r6[2], m218, false), r6[3], m214, true), r6[4], m206, false), r6[6], m158, true), r6[7], m94, false);
    let m231 = a(a(a(a(a(f(r6[0], m230, true), r6[1], m229, false), r6[2], m227, true), r6[5], m199, false), r6[6], m167, true), r6[7], m103, false);
    let m235 = a(a(a(a(a(f(r6[0], m234, true), r6[1], m233, false), r6[3], m227, true), r6[5], m203, false), r6[6], m171, true), r6[7], m107, false);
    let m237 = a(a(a(a(a(f(r6[0], m236, true), r6[2], m233, false), r6[3], m229, true), r6[5], m205, false), r6[6], m173, true), r6[7], m109, false);
    let m238 = a(a(a(a(a(f(r6[1], m236, true), r6[2], m234, false), r6[3], m230, true), r6[5], m206, false), r6[6], m174, true), r6[7], m110, false);
    let m243 = a(a(a(a(a(f(r6[0], m242, true), r6[1], m241, false), r6[4], m227, true), r6[5], m211, false), r6[6], m179, true), r6[7], m115, false);
    let m245 = a(a(a(a(a(f(r6[0], m244, true), r6[2], m241, false), r6[4], m229, true), r6[5], m213, false), r6[6], m181, true), r6[7], m117, false);
    let m246 = a(a(a(a(a(f(r6[1], m244, true), r6[2], m242, false), r6[4], m230, true), r6[5], m214, false), r6[6], m182, true), r6[7], m118, false);
    let m249 = a(a(a(a(a(f(r6[0], m248, true), r6[3], m241, false), r6[4], m233, true), r6[5], m217, false), r6[6], m185, true), r6[7], m121, false);
    let m250 = a(a(a(a(a(f(r6[1], m248, true), r6[3], m242, false), r6[4], m234, true), r6[5], m218, false), r6[6], m186, true), r6[7], m122, false);
    let m252 = a(a(a(a(a(f(r6[2], m248, true), r6[3], m244, false), r6[4], m236, true), r6[5], m220, false), r6[6], m188, true), r6[7], m124, false);
    let m127 = a(a(a(a(a(a(f(r7[0], m126, false), r7[1], m125, true), r7[2], m123, false), r7[3], m119, true), r7[4], m111, false), r7[5], m95, true), r7[6], m63, false);
    let m191 = a(a(a(a(a(a(f(r7[0], m190, false), r7[1], m189, true), r7[2], m187, false), r7[3], m183, true), r7[4], m175, false), r7[5], m159, true), r7[7], m63, false);
    let m223 = a(a(a(a(a(a(f(r7[0], m222, false), r7[1], m221, true), r7[2], m219, false), r7[3], m215, true), r7[4], m207, false), r7[6], m159, true), r7[7], m95, false);
    let m239 = a(a(a(a(a(a(f(r7[0], m238, false), r7[1], m237, true), r7[2], m235, false), r7[3], m231, true), r7[5], m207, false), r7[6], m175, true), r7[7], m111, false);
    let m247 = a(a(a(a(a(a(f(r7[0], m246, false), r7[1], m245, true), r7[2], m243, false), r7[4], m231, true), r7[5], m215, false), r7[6], m183, true), r7[7], m119, false);
    let m251 = a(a(a(a(a(a(f(r7[0], m250, false), r7[1], m249, true), r7[3], m243, false), r7[4], m235, true), r7[5], m219, false), r7[6], m187, true), r7[7], m123, false);
    let m253 = a(a(a(a(a(a(f(r7[0], m252, false), r7[2], m249, true), r7[3], m245, false), r7[4], m237, true), r7[5], m221, false), r7[6], m189, true), r7[7], m125, false);
    let m254 = a(a(a(a(a(a(f(r7[1], m252, false), r7[2], m250, true), r7[3], m246, false), r7[4], m238, true), r7[5], m222, false), r7[6], m190, true), r7[7], m126, false);
    [m254, m253, m251, m247, m239, m223, m191, m127]
}

#[cfg(test)]
mod tests {
    use super::{minors7, minors8};
    use crate::geometry::Rng;
    use crate::predicates::minors::{Tracked, cofactor_minors};

    /// Rows of every kind the filter meets: random entries, exact zeros, tiny entries (as
    /// snapped and nearly flat rows have), and nearly dependent rows (slivers).
    fn rows<const D: usize>(rng: &mut Rng) -> [[Tracked; D]; D] {
        let base: [f64; D] = std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0));
        std::array::from_fn(|_| {
            let tilt = 2f64.powi(-(rng.below(50) as i32));
            std::array::from_fn(|j| {
                let value = match rng.below(8) {
                    0 => 0.0,
                    1 => rng.uniform_in(-1.0, 1.0) * 1e-12,
                    2 => base[j] + rng.uniform_in(-1.0, 1.0) * tilt,
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
        let mut rng = Rng::new(78);
        for case in 0..2000 {
            let r = rows::<7>(&mut rng);
            same(minors7(&r), cofactor_minors::<Tracked, 7, 128>(&r), case);
            let r = rows::<8>(&mut rng);
            same(minors8(&r), cofactor_minors::<Tracked, 8, 256>(&r), case);
        }
    }
}
