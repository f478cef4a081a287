//! Exact (slow-path) arithmetic: the sign of an orientation determinant and the exact affine rank.
//!
//! Every finite `f64` is an integer times a power of two, so a set of coordinates can be scaled by a
//! single power of two into integers without any rounding. Determinants of those integers are then
//! computed exactly: in the fixed-width integers of [`super::wide`] when every column, scaled by
//! its own power of two, fits in `i64` (lattices, snapped wrenches: exactly the inputs on which
//! the filter fails), otherwise by fraction-free Bareiss elimination in `BigInt`.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::Sign;
use crate::geometry::exact_int::{bareiss_determinant, odd_mantissa};

/// Coordinates inside `[2^-EXP_LIMIT, 2^EXP_LIMIT]` (in absolute value) or zero are safe for the
/// adaptive expansion arithmetic of `robust` (no underflow nor overflow can occur in its
/// intermediate expansions for polynomials of degree ≤ 3; see [`robust_safe`]).
const EXP_LIMIT: i32 = 250;

/// Whether every coordinate is zero or has magnitude in `[2^-250, 2^250]`.
///
/// Shewchuk's expansions are exact only without underflow and overflow. Every coordinate in that
/// range is an integer multiple of `2^-302` (its ulp), so every term of the degree-3 polynomial, and
/// every roundoff tail the expansions produce, is a multiple of `2^-906 > 2^-1074` (no underflow),
/// and all magnitudes stay below `2^(3·251 + a few)` (no overflow).
fn robust_safe<const D: usize>(vertices: &[[f64; D]; D], p: &[f64; D]) -> bool {
    // 2^±250, exact powers of two (written as bits: `powi` is a library call on the slow path).
    const LO: f64 = f64::from_bits(((1023 - EXP_LIMIT) as u64) << 52);
    const HI: f64 = f64::from_bits(((1023 + EXP_LIMIT) as u64) << 52);
    vertices
        .iter()
        .flatten()
        .chain(p)
        .all(|&x| x == 0.0 || (x.abs() >= LO && x.abs() <= HI))
}

/// The exponent of the lowest set bit of a finite non-zero `x` (`x` is an odd multiple of 2^e).
pub(crate) fn lowest_bit_exponent(x: f64) -> i32 {
    decompose(x).1
}

/// Converts a finite `f64` into `(m, e)` with `x = m · 2^e`, `m` odd (or `m = 0`).
///
/// # Panics
/// If `x` is not finite.
pub(in crate::predicates) fn decompose(x: f64) -> (i64, i32) {
    assert!(
        x.is_finite(),
        "pqhull::predicates: non-finite coordinate {x} given to an exact predicate"
    );
    odd_mantissa(x).unwrap_or((0, 0))
}

/// The decomposed coordinates of a set of points, all to be scaled to the common exponent `emin`.
struct Scaled {
    /// `(mantissa, exponent)` for every coordinate, point-major.
    parts: Vec<(i64, i32)>,
    /// The smallest exponent among the nonzero coordinates (0 if all are zero).
    emin: i32,
}

fn scale(points: &[&[f64]]) -> Scaled {
    let parts: Vec<(i64, i32)> = points
        .iter()
        .flat_map(|p| p.iter())
        .map(|&x| decompose(x))
        .collect();
    let nonzero = || parts.iter().filter(|(m, _)| *m != 0);
    let emin = nonzero().map(|&(_, e)| e).min().unwrap_or(0);
    Scaled { parts, emin }
}

/// Exact sign of `det[v1 − v0; …; v(D−1) − v0; p − v0]`, using `robust` for D = 2, 3 when the
/// coordinates are in its safe range, integer Bareiss elimination otherwise.
pub(in crate::predicates) fn orientation<const D: usize>(
    vertices: &[[f64; D]; D],
    p: &[f64; D],
) -> Sign {
    // Repeated points make the determinant vanish; this is the most common reason the filter
    // fails (a hull vertex tested against its own facets, duplicates), and costs D² comparisons.
    if vertices.iter().any(|v| v == p)
        || (0..D).any(|i| (i + 1..D).any(|j| vertices[i] == vertices[j]))
    {
        for x in p.iter() {
            assert!(
                x.is_finite(),
                "pqhull::predicates: non-finite coordinate {x} given to orientation"
            );
        }
        return Sign::Zero;
    }
    // From 4-D on, the certified floating-point filter first (192 multiply-adds in 6-D for the
    // plane, against a full determinant in wide integers): it decides every determinant above
    // its error bound, and the exact path below the rest. (It answers `None` unless every
    // coordinate is in [−1, 1], as the hull's scaled points are, and for non-finite input.)
    if D >= 4
        && let Some(sign) = super::filter::FacetPlane::new(vertices).filter_sign(p)
    {
        return sign;
    }
    if D == 2 || D == 3 {
        // No allocation: this is the 2-D and 3-D exact path of every undecided side test.
        for x in vertices.iter().flatten().chain(p) {
            assert!(
                x.is_finite(),
                "pqhull::predicates: non-finite coordinate {x} given to orientation"
            );
        }
        if robust_safe(vertices, p) {
            return if D == 2 {
                orientation_robust2(&vertices[0], &vertices[1], p)
            } else {
                orientation_robust3(&vertices[0], &vertices[1], &vertices[2], p)
            };
        }
    }
    orientation_bareiss(vertices, p)
}

/// `robust::orient2d(a, b, c)` is `det[a − c; b − c] = det[b − a; c − a]` (translate by −a, then
/// subtract row 1 from row 2), exactly our determinant with `(a, b, c) = (v0, v1, p)`.
fn orientation_robust2(a: &[f64], b: &[f64], c: &[f64]) -> Sign {
    let coord = |q: &[f64]| robust::Coord { x: q[0], y: q[1] };
    sign_of(robust::orient2d(coord(a), coord(b), coord(c)))
}

/// `robust::orient3d(a, b, c, d)` is `det[a − d; b − d; c − d]`. With `x = a − d`:
/// `det[x; (b − a) + x; (c − a) + x] = det[x; b − a; c − a] = det[b − a; c − a; x]` (a cyclic,
/// hence even, row permutation) `= −det[b − a; c − a; d − a]`. So our determinant with
/// `(a, b, c, d) = (v0, v1, v2, p)` is the *negated* `orient3d`.
fn orientation_robust3(a: &[f64], b: &[f64], c: &[f64], d: &[f64]) -> Sign {
    let coord = |q: &[f64]| robust::Coord3D {
        x: q[0],
        y: q[1],
        z: q[2],
    };
    let s = robust::orient3d(coord(a), coord(b), coord(c), coord(d));
    sign_of(-s)
}

pub(in crate::predicates) fn sign_of(x: f64) -> Sign {
    if x > 0.0 {
        Sign::Positive
    } else if x < 0.0 {
        Sign::Negative
    } else {
        Sign::Zero
    }
}

fn sign_of_int<T: Signed>(x: &T) -> Sign {
    if x.is_positive() {
        Sign::Positive
    } else if x.is_negative() {
        Sign::Negative
    } else {
        Sign::Zero
    }
}

/// The exact integer path, valid for every D (also used to cross-check `robust` in tests).
pub(in crate::predicates) fn orientation_bareiss<const D: usize>(
    vertices: &[[f64; D]; D],
    p: &[f64; D],
) -> Sign {
    // Fixed-width integers when the column-scaled entries fit in i64 (allocation-free; covers
    // lattices and snapped wrenches), BigInt otherwise.
    super::wide::orientation(vertices, p).unwrap_or_else(|| orientation_big(vertices, p))
}

/// The `BigInt` path of [`orientation_bareiss`], valid for every input.
pub(in crate::predicates) fn orientation_big<const D: usize>(
    vertices: &[[f64; D]; D],
    p: &[f64; D],
) -> Sign {
    let mut all: Vec<&[f64]> = vertices.iter().map(|v| &v[..]).collect();
    all.push(&p[..]);
    let s = scale(&all);
    let (v0, rest) = s.parts.split_at(D);
    let rows = rest.chunks_exact(D);
    let int = |(m, e): (i64, i32)| -> BigInt {
        if m == 0 {
            BigInt::zero()
        } else {
            BigInt::from(m) << ((e - s.emin) as usize)
        }
    };
    let matrix: Vec<Vec<BigInt>> = rows
        .map(|r| (0..D).map(|j| int(r[j]) - int(v0[j])).collect())
        .collect();
    bareiss_big(matrix)
}

/// Bareiss elimination in `BigInt` (the geometry layer's, `exact_int::bareiss_determinant`).
fn bareiss_big(a: Vec<Vec<BigInt>>) -> Sign {
    sign_of_int(&bareiss_determinant(a))
}

pub(in crate::predicates) fn flip(s: Sign) -> Sign {
    match s {
        Sign::Negative => Sign::Positive,
        Sign::Zero => Sign::Zero,
        Sign::Positive => Sign::Negative,
    }
}

/// Exact rational conversion of a finite `f64`.
///
/// # Panics
/// If `x` is not finite.
pub(in crate::predicates) fn rational(x: f64) -> BigRational {
    BigRational::from_float(x).unwrap_or_else(|| {
        panic!("pqhull::predicates: non-finite coordinate {x} given to an exact predicate")
    })
}

/// Greedy exact affine basis: see [`super::affinely_independent_subset`].
pub(in crate::predicates) fn affinely_independent_subset<const D: usize>(
    points: &[[f64; D]],
) -> Vec<usize> {
    let Some(first) = points.first() else {
        return Vec::new();
    };
    let origin: Vec<BigRational> = first.iter().map(|&x| rational(x)).collect();
    let mut kept = vec![0];
    // Row-echelon basis of the kept difference vectors: (pivot column, row), where each row is zero
    // in the pivot columns of the rows before it.
    let mut basis: Vec<(usize, Vec<BigRational>)> = Vec::with_capacity(D);
    for (i, q) in points.iter().enumerate().skip(1) {
        if basis.len() == D {
            break; // Full rank: no later point can raise it.
        }
        let mut v: Vec<BigRational> = q
            .iter()
            .zip(&origin)
            .map(|(&x, o)| rational(x) - o)
            .collect();
        for (c, row) in &basis {
            if !v[*c].is_zero() {
                let f = &v[*c] / &row[*c];
                for (vj, rj) in v.iter_mut().zip(row).skip(*c) {
                    *vj -= &f * rj;
                }
            }
        }
        if let Some(c) = v.iter().position(|x| !x.is_zero()) {
            kept.push(i);
            basis.push((c, v));
        }
    }
    kept
}

/// The cofactor vector of `[v1 − v0; …; v(D−1) − v0; ·]` computed exactly, then rounded to `f64`
/// after a common power-of-two scaling (so only its direction is meaningful).
///
/// Used when the floating-point cofactors of a facet cancel too much to give an accurate normal
/// (slivers, tiny clusters): each component is then within a few ulps of the exact direction's.
pub fn exact_cofactor_direction<const D: usize>(vertices: &[[f64; D]; D]) -> [f64; D] {
    super::wide::cofactor_direction(vertices)
        .unwrap_or_else(|| exact_cofactor_direction_big(vertices))
}

/// The `BigInt` path of [`exact_cofactor_direction`], valid for every input.
pub(in crate::predicates) fn exact_cofactor_direction_big<const D: usize>(
    vertices: &[[f64; D]; D],
) -> [f64; D] {
    let all: Vec<&[f64]> = vertices.iter().map(|v| &v[..]).collect();
    let s = scale(&all);
    let cofactors = cofactors_big::<D>(&integer_differences(&s, D));
    // Shift so that the largest magnitude has about 62 bits, then convert: f64 rounding of each
    // component is then the only error.
    let bits = cofactors.iter().map(|c| c.bits()).max().unwrap_or(0);
    let shift = bits.saturating_sub(62);
    let mut out = [0.0; D];
    for (o, c) in out.iter_mut().zip(&cofactors) {
        let shifted: BigInt = c >> (shift as usize);
        *o = num_traits::ToPrimitive::to_f64(&shifted).unwrap_or(0.0);
    }
    out
}

/// `det[v1 − v0; …; v(D−1) − v0; p − v0] / |C|`, the signed distance of `p` beyond the plane
/// through `vertices`, from the exact determinant and exact cofactors in `BigInt`, each rounded
/// once (valid for every finite input; 0 for affinely dependent vertices).
///
/// # Panics
/// If a coordinate is not finite.
pub(in crate::predicates) fn distance_big<const D: usize>(
    vertices: &[[f64; D]; D],
    p: &[f64; D],
) -> f64 {
    let mut all: Vec<&[f64]> = vertices.iter().map(|v| &v[..]).collect();
    all.push(&p[..]);
    let s = scale(&all);
    let rows = integer_differences(&s, D);
    let cofactors = cofactors_big::<D>(&rows[..D - 1]);
    let norm2: BigInt = cofactors.iter().map(|c| c * c).sum();
    if norm2.is_zero() {
        return 0.0;
    }
    // Units: the determinant is in grid^D, the cofactors in grid^(D−1), grid = 2^emin.
    let (value, e1) = big_to_parts(&bareiss_determinant(rows));
    let (mut m2, mut e2) = big_to_parts(&norm2);
    if e2 % 2 != 0 {
        m2 *= 2.0;
        e2 -= 1;
    }
    let exponent = i64::from(e1) - i64::from(e2 / 2) + i64::from(s.emin);
    let exponent = exponent.clamp(-4000, 4000) as i32;
    super::wide::times_power_of_two(value / m2.sqrt(), exponent)
}

/// The rows `q_k − q_0` (k = 1..points) of the scaled points, as integers in units of 2^emin.
fn integer_differences(s: &Scaled, d: usize) -> Vec<Vec<BigInt>> {
    let int = |(m, e): (i64, i32)| -> BigInt {
        if m == 0 {
            BigInt::zero()
        } else {
            BigInt::from(m) << ((e - s.emin) as usize)
        }
    };
    let (v0, rest) = s.parts.split_at(d);
    rest.chunks_exact(d)
        .map(|r| (0..d).map(|j| int(r[j]) - int(v0[j])).collect())
        .collect()
}

/// The signed cofactors of the last row of `[edges; ·]` (`edges`: D − 1 rows of D integers).
fn cofactors_big<const D: usize>(edges: &[Vec<BigInt>]) -> Vec<BigInt> {
    (0..D)
        .map(|j| {
            let minor: Vec<Vec<BigInt>> = edges
                .iter()
                .map(|row| (0..D).filter(|&c| c != j).map(|c| row[c].clone()).collect())
                .collect();
            let det = bareiss_determinant(minor);
            if (D - 1 + j) % 2 == 1 { -det } else { det }
        })
        .collect()
}

/// `(m, e)` with `x ≈ m·2^e`, `m` holding the top 64 bits of `x` (one rounding to `f64`).
fn big_to_parts(x: &BigInt) -> (f64, i32) {
    let shift = x.bits().saturating_sub(64);
    let top: BigInt = x.abs() >> (shift as usize);
    let m = num_traits::ToPrimitive::to_f64(&top).unwrap_or(0.0);
    let e = i32::try_from(shift).unwrap_or(i32::MAX);
    (if x.is_negative() { -m } else { m }, e)
}

/// `det[v1 − v0; …; v(D−1) − v0; p − v0]` exactly in `BigInt`, rounded once: `(m, e)` with
/// the determinant `≈ m·2^e` (relative error below 2^−52), `(0.0, 0)` when it is zero.
///
/// # Panics
/// If a coordinate is not finite.
pub(in crate::predicates) fn orientation_parts<const D: usize>(
    vertices: &[[f64; D]; D],
    p: &[f64; D],
) -> (f64, i64) {
    let mut all: Vec<&[f64]> = vertices.iter().map(|v| &v[..]).collect();
    all.push(&p[..]);
    let s = scale(&all);
    let det = bareiss_determinant(integer_differences(&s, D));
    if det.is_zero() {
        return (0.0, 0);
    }
    // The rows are in units of 2^emin: the determinant in units of 2^(D·emin).
    let (m, e) = big_to_parts(&det);
    (m, i64::from(e) + D as i64 * i64::from(s.emin))
}
