//! Issue 12, item 3: outputs right at every scale. Power-of-two rescaling is exact, so the hull
//! of rescaled points is the rescaled hull: vertex sets must not change under any per-axis
//! rescaling that keeps the coordinates normal, and distances must scale with a uniform one, over
//! the whole `f64` range. Wide per-axis ranges are checked against exact rational distances, and
//! far queries against the answer worked out by hand.

use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};
use pqhull::geometry::Rng;
use pqhull::grasp::quality::q1_of_wrenches;
use pqhull::grasp::{FrictionModel, Grasp, Method};
use pqhull::rbox::{Family, generate};
use pqhull::{ClosestToOrigin, Hull};

/// `x · 2^e` by repeated exact steps (the factor alone may not be representable).
fn times_power_of_two(mut x: f64, mut e: i32) -> f64 {
    while e > 500 {
        x *= 2f64.powi(500);
        e -= 500;
    }
    while e < -500 {
        x *= 2f64.powi(-500);
        e += 500;
    }
    x * 2f64.powi(e)
}

/// `points` with axis c multiplied by 2^exponents[c], or `None` when some coordinate would not
/// stay normal (the rescaling would then round).
fn rescaled<const D: usize>(points: &[[f64; D]], exponents: &[i32; D]) -> Option<Vec<[f64; D]>> {
    let mut out = Vec::with_capacity(points.len());
    for p in points {
        let q: [f64; D] = std::array::from_fn(|c| times_power_of_two(p[c], exponents[c]));
        let exact =
            q.iter().zip(p).zip(exponents).all(|((&y, &x), &e)| {
                (y == 0.0 || y.is_normal()) && times_power_of_two(y, -e) == x
            });
        if !exact {
            return None;
        }
        out.push(q);
    }
    Some(out)
}

fn sorted_facets<const D: usize>(hull: &Hull<D>) -> Vec<Vec<usize>> {
    let mut facets: Vec<Vec<usize>> = hull
        .facets()
        .map(|(_, f)| {
            let mut v = f.vertices().to_vec();
            v.sort();
            v
        })
        .collect();
    facets.sort();
    facets
}

/// Every facet's normal is a finite unit vector.
fn assert_unit_normals<const D: usize>(hull: &Hull<D>, what: &str) {
    for (_, f) in hull.facets() {
        let n = f.normal();
        let length = n.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!(
            (length - 1.0).abs() < 1e-12 && f.offset().is_finite(),
            "{what}: normal {n:?}, offset {}",
            f.offset()
        );
    }
}

#[test]
fn per_axis_power_of_two_rescaling_keeps_the_hull() {
    fn run<const D: usize>(rng: &mut Rng, cases: usize) -> usize {
        let mut checked = 0;
        for case in 0..cases {
            let points = generate::<D>(&Family::UniformCube, 2 * D + 8, rng.next_u64());
            let exponents: [i32; D] = std::array::from_fn(|_| rng.below(1900) as i32 - 900);
            let Some(scaled) = rescaled(&points, &exponents) else {
                continue;
            };
            let what = format!("D={D} case {case} exponents {exponents:?}");
            let (a, b) = (
                Hull::try_new(&points).unwrap(),
                Hull::try_new(&scaled).unwrap(),
            );
            b.check().unwrap_or_else(|e| panic!("{what}: {e:?}"));
            assert_eq!(a.vertex_indices(), b.vertex_indices(), "{what}");
            assert_eq!(sorted_facets(&a), sorted_facets(&b), "{what}");
            assert_unit_normals(&b, &what);
            let (_, r) =
                Hull::try_with_strategy(&scaled, ClosestToOrigin::towards([0.0; D])).unwrap();
            assert!(
                r.signed_distance.is_finite() && r.nearest_point.iter().all(|x| x.is_finite()),
                "{what}: {r:?}"
            );
            checked += 1;
        }
        checked
    }
    let mut rng = Rng::new(123);
    let checked = run::<2>(&mut rng, 30)
        + run::<3>(&mut rng, 30)
        + run::<4>(&mut rng, 20)
        + run::<6>(&mut rng, 10)
        + run::<8>(&mut rng, 6);
    // Uniform points are rarely so small that 2^−900 makes them subnormal.
    assert!(
        checked >= 80,
        "only {checked} of 96 cases could be rescaled exactly"
    );
}

#[test]
fn uniform_power_of_two_rescaling_scales_distances() {
    fn run<const D: usize>(rng: &mut Rng, cases: usize) {
        for case in 0..cases {
            let points = generate::<D>(&Family::UniformCube, 3 * D + 6, rng.next_u64());
            // Inside near the centre, or outside beyond a face or a corner.
            let query: [f64; D] = std::array::from_fn(|_| rng.uniform_in(-0.8, 0.8));
            let e = rng.below(2000) as i32 - 1000;
            let Some(scaled) = rescaled(&points, &[e; D]) else {
                continue;
            };
            let scaled_query = query.map(|x| times_power_of_two(x, e));
            let what = format!("D={D} case {case} e={e}");
            let (_, a) = Hull::try_with_strategy(&points, ClosestToOrigin::towards(query)).unwrap();
            let (_, b) =
                Hull::try_with_strategy(&scaled, ClosestToOrigin::towards(scaled_query)).unwrap();
            let expected = times_power_of_two(a.signed_distance, e);
            assert!(
                (b.signed_distance - expected).abs() <= 1e-13 * expected.abs(),
                "{what}: {} vs {expected}",
                b.signed_distance
            );
            for c in 0..D {
                let x = times_power_of_two(a.nearest_point[c], e);
                assert!(
                    (b.nearest_point[c] - x).abs() <= 1e-13 * times_power_of_two(1.0, e),
                    "{what}: nearest point {:?} vs {:?}",
                    b.nearest_point,
                    a.nearest_point
                );
            }
        }
    }
    let mut rng = Rng::new(1231);
    run::<2>(&mut rng, 40);
    run::<3>(&mut rng, 40);
    run::<4>(&mut rng, 20);
    run::<6>(&mut rng, 8);
    run::<8>(&mut rng, 4);
}

fn rational(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

/// The determinant of a square matrix of rationals (Gaussian elimination, exact).
fn determinant(mut m: Vec<Vec<BigRational>>) -> BigRational {
    let n = m.len();
    let mut det = BigRational::from_integer(1.into());
    for col in 0..n {
        let Some(pivot) = (col..n).find(|&r| !m[r][col].is_zero()) else {
            return BigRational::zero();
        };
        if pivot != col {
            m.swap(pivot, col);
            det = -det;
        }
        det *= m[col][col].clone();
        let pivot_row = m[col].clone();
        for row in &mut m[col + 1..] {
            let factor = row[col].clone() / pivot_row[col].clone();
            for (x, p) in row.iter_mut().zip(&pivot_row).skip(col) {
                *x -= factor.clone() * p.clone();
            }
        }
    }
    det
}

/// The exact distance from the origin to the plane through `vertices`, rounded once to `f64`.
fn exact_plane_distance<const D: usize>(vertices: &[[f64; D]]) -> f64 {
    let v: Vec<Vec<BigRational>> = vertices
        .iter()
        .map(|p| p.iter().map(|&x| rational(x)).collect())
        .collect();
    let edges: Vec<Vec<BigRational>> = v[1..]
        .iter()
        .map(|p| p.iter().zip(&v[0]).map(|(a, b)| a - b).collect())
        .collect();
    // Normal: the cofactors of the (D − 1) × D edge matrix.
    let normal: Vec<BigRational> = (0..D)
        .map(|skip| {
            let minor = edges
                .iter()
                .map(|row| {
                    row.iter()
                        .enumerate()
                        .filter(|&(c, _)| c != skip)
                        .map(|(_, x)| x.clone())
                        .collect()
                })
                .collect();
            let d = determinant(minor);
            if skip % 2 == 0 { d } else { -d }
        })
        .collect();
    let offset: BigRational = normal.iter().zip(&v[0]).map(|(n, x)| n * x).sum();
    let length: BigRational = normal.iter().map(|n| n * n).sum();
    let squared = offset.clone() * offset / length;
    squared.to_f64().expect("representable").sqrt()
}

/// The 6-D points of the report (one axis 1e40 or 1e60 times the others) and an 8-D cloud with
/// one axis 1e30 times: the origin's distance to the hull, by the partial and the full hull,
/// against the smallest exact plane distance over the full hull's facets (the origin is inside).
/// Before the fix, 58 of 9,122 facets had null normals at 1e40 and the distance was 0.848714
/// for 0.848703; at 1e60 it was 2.2e−308.
#[test]
fn wide_per_axis_ranges_against_exact_distances() {
    fn run<const D: usize>(seed: u64, exponent: i32) {
        let mut rng = Rng::new(seed);
        // Random points, and ±e_i so the origin is inside.
        let mut points: Vec<[f64; D]> = (0..D + 4)
            .map(|_| std::array::from_fn(|_| rng.normal()))
            .collect();
        for i in 0..2 * D {
            let mut p = [0.0; D];
            p[i / 2] = if i % 2 == 0 { 1.0 } else { -1.0 };
            points.push(p);
        }
        for p in &mut points {
            p[0] = times_power_of_two(p[0], exponent);
        }
        let what = format!("D={D} seed {seed} axis 0 × 2^{exponent}");
        let full = Hull::try_new(&points).unwrap();
        full.check().unwrap_or_else(|e| panic!("{what}: {e:?}"));
        assert_unit_normals(&full, &what);
        // The exact distance of every facet whose floating-point plane distance is within 2× of
        // the smallest (the exact rational determinants cost seconds per hundred 8-D facets).
        let float = |f: &pqhull::Facet<D>| -f.offset();
        let nearest_float = full
            .facets()
            .map(|(_, f)| float(f))
            .fold(f64::INFINITY, f64::min);
        let reference = full
            .facets()
            .filter(|(_, f)| float(f) <= 2.0 * nearest_float)
            .map(|(_, f)| {
                let vertices: Vec<[f64; D]> = f.vertices().iter().map(|&v| points[v]).collect();
                exact_plane_distance(&vertices)
            })
            .fold(f64::INFINITY, f64::min);
        let (_, partial) =
            Hull::try_with_strategy(&points, ClosestToOrigin::towards([0.0; D])).unwrap();
        assert!(
            (partial.signed_distance - reference).abs() <= 1e-12 * reference,
            "{what}: {} vs exact {reference}",
            partial.signed_distance
        );
        let nearest = partial
            .nearest_point
            .iter()
            .map(|x| x * x)
            .sum::<f64>()
            .sqrt();
        assert!(
            (nearest - reference).abs() <= 1e-12 * reference,
            "{what}: nearest point {:?} at {nearest}",
            partial.nearest_point
        );
    }
    for seed in 0..3 {
        run::<6>(seed, 133);
        run::<6>(seed, 200);
        run::<4>(seed, 260);
    }
    run::<8>(0, 100);
    run::<8>(1, 100);
}

/// A query far from the unit square: right up to 1e154 and −∞ with the nearest point (0, −1)
/// from 1e155 before the fix (squared distances overflowed).
#[test]
fn far_queries() {
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    for q in [1e100, 1e155, 1e200, 1e300, 1.7e308] {
        for (query, expected) in [
            ([q, 0.5], [1.0, 0.5]),
            ([-q, -q], [0.0, 0.0]),
            ([0.25, -q], [0.25, 0.0]),
        ] {
            let (_, r) = Hull::try_with_strategy(&square, ClosestToOrigin::towards(query)).unwrap();
            // Beyond f64::MAX (the diagonal query near it), the documented −∞.
            let exact = (query[0] - expected[0]).hypot(query[1] - expected[1]);
            if exact.is_infinite() {
                assert_eq!(r.signed_distance, f64::NEG_INFINITY, "query {query:?}");
            } else {
                assert!(
                    (r.signed_distance + exact).abs() <= 1e-15 * exact,
                    "query {query:?}: {} for −{exact}",
                    r.signed_distance
                );
            }
            // The nearest point is on the square, to the precision the query's size allows.
            for (x, e) in r.nearest_point.iter().zip(expected) {
                assert!(
                    (x - e).abs() <= 4.0 * f64::EPSILON * q,
                    "query {query:?}: nearest point {:?}",
                    r.nearest_point
                );
                assert!((-1e-12..=1.0 + 1e-12).contains(x));
            }
        }
    }
}

/// Q1 of a grasp's wrenches multiplied by 2^e is 2^e times Q1, from 2^−900 up to the wrench
/// limit (1e100 ≈ 2^332).
#[test]
fn grasp_quality_scales_with_its_wrenches() {
    let mut rng = Rng::new(1232);
    for case in 0..12 {
        let grasp = Grasp::random_on_box(
            &mut rng,
            [0.5, 0.2, 0.1],
            4,
            FrictionModel::try_new(0.6, 8).unwrap(),
        );
        let wrenches = grasp.wrenches();
        let base = q1_of_wrenches(&wrenches, Method::Partial).unwrap();
        for e in [-900, -600, -300, -40, 40, 300, 330] {
            let scaled: Vec<[f64; 6]> = wrenches
                .iter()
                .map(|w| w.map(|x| times_power_of_two(x, e)))
                .collect();
            let q = q1_of_wrenches(&scaled, Method::Partial).unwrap();
            let value = q.value.unwrap();
            let expected = times_power_of_two(base.value.unwrap(), e);
            let what = format!("case {case}, 2^{e}: {value} vs {expected}");
            assert_eq!(q.force_closure, base.force_closure, "{what}");
            assert!(
                (value - expected).abs() <= 1e-12 * times_power_of_two(base.scale.unwrap(), e),
                "{what}"
            );
        }
    }
}

/// A cube of half-width `s` at every scale, up to coordinates near `f64::MAX` (where the
/// engine's internal scale is 2^−1024 and its inverse overflows): every facet's offset is `s`
/// to two ulps (the unit normal's rounding) and its normal a signed axis.
#[test]
fn facet_offsets_are_right_at_every_scale() {
    for s in [1.7e308, f64::MAX, 1e200, 3.0, 1e-300, 2.5e-308] {
        let corners: Vec<[f64; 3]> = (0..8)
            .map(|i| std::array::from_fn(|c| if i >> c & 1 == 1 { s } else { -s }))
            .collect();
        let hull = Hull::try_new(&corners).unwrap();
        assert_eq!(hull.facet_count(), 12, "s = {s:e}");
        for (_, facet) in hull.facets() {
            let offset = facet.offset();
            assert!(
                (offset - s).abs() <= 2.0 * f64::EPSILON * s,
                "s = {s:e}: offset {offset:e}"
            );
            let n = facet.normal();
            assert_eq!(
                n.iter()
                    .filter(|x| (x.abs() - 1.0).abs() <= f64::EPSILON)
                    .count(),
                1,
                "s = {s:e}: {n:?}"
            );
            assert_eq!(
                n.iter().filter(|x| **x == 0.0).count(),
                2,
                "s = {s:e}: {n:?}"
            );
        }
    }
}

/// `predicates::orientation_value` against the rational determinant of the same rows, over
/// coordinates spread across the exponent range and near-degenerate rows (a point nudged off
/// the others' hyperplane by a few ulps): the same sign, zero exactly when it is zero, and the
/// value within 2^−52 relative.
#[test]
fn orientation_value_is_the_rational_determinant() {
    use num_traits::Signed;
    use pqhull::predicates::orientation_value;
    fn run<const D: usize>(rng: &mut Rng) {
        for case in 0..60 {
            let e = rng.below(1200) as i32 - 600;
            let mut points: [[f64; D]; 7] = [[0.0; D]; 7];
            for p in &mut points {
                *p = std::array::from_fn(|_| times_power_of_two(rng.uniform_in(-1.0, 1.0), e));
            }
            let vertices: [[f64; D]; D] = std::array::from_fn(|i| points[i]);
            let mut p = points[D];
            if case % 3 == 0 {
                // On the line through two vertices, then (every other time) nudged by an ulp.
                p = std::array::from_fn(|j| {
                    vertices[0][j] + (vertices[1][j] - vertices[0][j]) * 0.5
                });
                if case % 2 == 0 {
                    p[0] = f64::from_bits(p[0].to_bits() + 1);
                }
            }
            let rows: Vec<Vec<BigRational>> = (1..=D)
                .map(|k| {
                    let row = if k < D { &vertices[k] } else { &p };
                    (0..D)
                        .map(|j| rational(row[j]) - rational(vertices[0][j]))
                        .collect()
                })
                .collect();
            let exact = determinant(rows);
            let (m, e) = orientation_value(&vertices, &p);
            assert_eq!(m == 0.0, exact.is_zero(), "D = {D}, case {case}");
            if m == 0.0 {
                assert_eq!(e, 0);
                continue;
            }
            let power = BigRational::from_integer(num_bigint::BigInt::from(1) << e.unsigned_abs());
            let value = if e >= 0 {
                rational(m) * power
            } else {
                rational(m) / power
            };
            let error = ((value - exact.clone()) / exact).abs();
            assert!(
                error <= rational(2f64.powi(-52)),
                "D = {D}, case {case}: relative error {error}"
            );
        }
    }
    let mut rng = Rng::new(52);
    run::<3>(&mut rng);
    run::<4>(&mut rng);
    run::<6>(&mut rng);
}
