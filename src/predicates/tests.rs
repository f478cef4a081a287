//! Tests of the predicates against a slow, independent reference: the exact determinant by rational
//! Gaussian elimination on the exact values of the `f64` inputs.

// Index loops read better than iterator chains in matrix code.
#![allow(clippy::needless_range_loop)]

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};

use super::exact::{orientation_bareiss, rational};
use super::{FacetPlane, Sign, affinely_independent_subset, orientation};

/// Exact `det[v1 − v0; …; p − v0]` by rational Gaussian elimination.
fn reference_det<const D: usize>(vertices: &[[f64; D]; D], p: &[f64; D]) -> BigRational {
    let v0: Vec<BigRational> = vertices[0].iter().map(|&x| rational(x)).collect();
    let mut a: Vec<Vec<BigRational>> = vertices[1..]
        .iter()
        .chain(std::iter::once(p))
        .map(|r| r.iter().zip(&v0).map(|(&x, o)| rational(x) - o).collect())
        .collect();
    let mut det = BigRational::from_integer(1.into());
    for k in 0..D {
        let Some(r) = (k..D).find(|&r| !a[r][k].is_zero()) else {
            return BigRational::zero();
        };
        if r != k {
            a.swap(r, k);
            det = -det;
        }
        det *= &a[k][k];
        for i in k + 1..D {
            if a[i][k].is_zero() {
                continue;
            }
            let f = &a[i][k] / &a[k][k];
            for j in k + 1..D {
                let t = &f * &a[k][j];
                a[i][j] -= t;
            }
        }
    }
    det
}

fn sign_of(x: &BigRational) -> Sign {
    if x.is_positive() {
        Sign::Positive
    } else if x.is_negative() {
        Sign::Negative
    } else {
        Sign::Zero
    }
}

fn in_unit_box<const D: usize>(vertices: &[[f64; D]; D], p: &[f64; D]) -> bool {
    vertices
        .iter()
        .chain(std::iter::once(p))
        .flatten()
        .all(|x| x.abs() <= 1.0)
}

/// Checks every implementation against the reference on one case; returns the exact sign.
fn check<const D: usize>(vertices: &[[f64; D]; D], p: &[f64; D]) -> Sign {
    let exact = reference_det(vertices, p);
    let want = sign_of(&exact);
    let ctx = || format!("D = {D}, vertices = {vertices:?}, p = {p:?}");
    assert_eq!(orientation(vertices, p), want, "orientation: {}", ctx());
    assert_eq!(orientation_bareiss(vertices, p), want, "bareiss: {}", ctx());
    let plane = FacetPlane::new(vertices);
    assert_eq!(plane.side(p, || *vertices), want, "side: {}", ctx());
    assert_eq!(plane.base(), &vertices[0]);
    let (value, bound) = plane.evaluate(p);
    if in_unit_box(vertices, p) {
        assert!(bound.is_finite(), "bound not finite: {}", ctx());
        let err = (rational(value) - &exact).abs();
        assert!(
            err <= rational(bound),
            "|value − exact| > bound: value = {value}, bound = {bound}, exact ≈ {}: {}",
            num_traits::ToPrimitive::to_f64(&exact).unwrap_or(f64::NAN),
            ctx()
        );
        // The same value, and as certified a bound, without the box test.
        let (unchecked, unchecked_bound) = plane.evaluate_in_box(p);
        assert_eq!(
            unchecked.to_bits(),
            value.to_bits(),
            "evaluate_in_box: {}",
            ctx()
        );
        assert!(
            err <= rational(unchecked_bound),
            "evaluate_in_box bound: {}",
            ctx()
        );
    } else {
        assert_eq!(bound, f64::INFINITY, "bound must be infinite: {}", ctx());
    }
    want
}

fn runner(seed: u64, cases: u32) -> TestRunner {
    TestRunner::new(Config {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        ..Config::default()
    })
}

fn split<const D: usize>(c: &[f64]) -> ([[f64; D]; D], [f64; D]) {
    let mut v = [[0.0; D]; D];
    for (k, row) in v.iter_mut().enumerate() {
        row.copy_from_slice(&c[k * D..(k + 1) * D]);
    }
    let mut p = [0.0; D];
    p.copy_from_slice(&c[D * D..D * D + D]);
    (v, p)
}

macro_rules! all_dims {
    ($f:ident) => {{
        $f::<2>();
        $f::<3>();
        $f::<4>();
        $f::<5>();
        $f::<6>();
        $f::<7>();
        $f::<8>();
    }};
}

// ---------------------------------------------------------------------------------------------
// Random points.

fn random_case<const D: usize>() {
    let strategy = prop::collection::vec(-1.0f64..=1.0, D * (D + 1));
    runner(0x5eed + D as u64, 64)
        .run(&strategy, |c| {
            let (v, p) = split::<D>(&c);
            check(&v, &p);
            Ok(())
        })
        .unwrap();
}

#[test]
fn random_points_agree_with_reference() {
    all_dims!(random_case);
}

/// Bound must also be reasonably tight: a few hundred ulps of the permanent, not more.
fn bound_is_tight<const D: usize>() {
    let strategy = prop::collection::vec(-1.0f64..=1.0, D * (D + 1));
    runner(7 + D as u64, 16)
        .run(&strategy, |c| {
            let (v, p) = split::<D>(&c);
            let (_, bound) = FacetPlane::new(&v).evaluate(&p);
            prop_assert!(bound < 1e-9, "bound {bound} too loose");
            Ok(())
        })
        .unwrap();
}

#[test]
fn bound_is_not_absurd() {
    all_dims!(bound_is_tight);
}

// ---------------------------------------------------------------------------------------------
// Exactly degenerate cases on a dyadic lattice, then one-ulp perturbations.

/// `p = v0 + Σ λ_k (v_k − v0)` on a dyadic lattice: every operation is exact, so `p` is exactly on
/// the hyperplane. Then one coordinate of `p` is moved by one ulp up or down.
fn lattice_case<const D: usize>() {
    let strategy = (
        prop::collection::vec(-8i32..=8, D * D),
        prop::collection::vec(-4i32..=4, D - 1),
        0..D,
        any::<bool>(),
    );
    runner(0xde9 + D as u64, 64)
        .run(&strategy, |(ints, lambdas, j, up)| {
            // Coordinates in [−1/2, 1/2] (multiples of 1/16), weights in [−1, 1] (multiples of 1/4);
            // everything scaled by 1/8 at the end (exact) so that p is in [−1, 1].
            let mut v = [[0.0; D]; D];
            for k in 0..D {
                for i in 0..D {
                    v[k][i] = f64::from(ints[k * D + i]) / 16.0;
                }
            }
            let mut p = v[0];
            for k in 1..D {
                let l = f64::from(lambdas[k - 1]) / 4.0;
                for i in 0..D {
                    p[i] += l * (v[k][i] - v[0][i]);
                }
            }
            for x in v.iter_mut().flatten().chain(p.iter_mut()) {
                *x /= 8.0;
            }
            assert_eq!(check(&v, &p), Sign::Zero);
            // p equal to a vertex.
            assert_eq!(check(&v, &v[D - 1]), Sign::Zero);
            let mut q = p;
            q[j] = if up { q[j].next_up() } else { q[j].next_down() };
            let s = check(&v, &q);
            // The change is C_j·(±ulp) exactly, so the sign follows the exact cofactor, which
            // the filter computes exactly on this lattice.
            let c = FacetPlane::new(&v).cofactors()[j];
            let expected = match (c.partial_cmp(&0.0).unwrap(), up) {
                (std::cmp::Ordering::Equal, _) => Sign::Zero,
                (std::cmp::Ordering::Greater, true) | (std::cmp::Ordering::Less, false) => {
                    Sign::Positive
                }
                _ => Sign::Negative,
            };
            prop_assert_eq!(s, expected);
            Ok(())
        })
        .unwrap();
}

#[test]
fn lattice_degenerate_and_one_ulp_moves() {
    all_dims!(lattice_case);
}

/// General (non-lattice) vertices: `p` equal to a vertex (Zero), one ulp off it both ways (opposite
/// signs), `p = v0 + 2·(v1 − v0)` (Zero whenever the rounded computation happens to be exact), and
/// duplicate vertices (Zero for every `p`).
fn vertex_and_duplicate_case<const D: usize>() {
    let strategy = (prop::collection::vec(-1.0f64..=1.0, D * D), 0..D, 0..D);
    runner(0xd00 + D as u64, 8)
        .run(&strategy, |(c, k, j)| {
            let mut v = [[0.0; D]; D];
            for k in 0..D {
                v[k].copy_from_slice(&c[k * D..(k + 1) * D]);
            }
            let p = v[k];
            prop_assert_eq!(check(&v, &p), Sign::Zero);
            // One ulp off a vertex, both ways: opposite signs (or both Zero).
            let mut q = p;
            q[j] = q[j].next_up();
            let up = check(&v, &q);
            q[j] = p[j].next_down();
            prop_assert_eq!(check(&v, &q), up.flip());
            let on_line: [f64; D] = std::array::from_fn(|i| v[0][i] + 2.0 * (v[1][i] - v[0][i]));
            let s = check(&v, &on_line);
            let exact = (0..D).all(|i| {
                rational(on_line[i])
                    == rational(v[0][i]) + rational(2.0) * (rational(v[1][i]) - rational(v[0][i]))
            });
            prop_assert!(!exact || s == Sign::Zero);
            // Duplicate vertices: always Zero, wherever p is.
            let mut w = v;
            w[D - 1] = w[0];
            let p = [0.25; D];
            prop_assert_eq!(check(&w, &p), Sign::Zero);
            if D > 2 {
                let mut w = v;
                w[1] = w[2];
                prop_assert_eq!(check(&w, &p), Sign::Zero);
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn vertices_and_duplicates_are_zero() {
    all_dims!(vertex_and_duplicate_case);
}

// ---------------------------------------------------------------------------------------------
// Scales: nearly coincident points, tiny and huge coordinates.

fn scaled_case<const D: usize>() {
    let strategy = (
        prop::collection::vec(-1.0f64..=1.0, D * (D + 1)),
        prop::collection::vec(-1.0f64..=1.0, D),
    );
    runner(0x5ca1e + D as u64, 4)
        .run(&strategy, |(c, centre)| {
            // Nearly coincident: a cluster of radius ~1e-15 around a centre.
            let mut near = c.clone();
            for (i, x) in near.iter_mut().enumerate() {
                *x = centre[i % D] * 0.5 + *x * 1e-15;
            }
            let (v, p) = split::<D>(&near);
            check(&v, &p);
            for scale in [1e-30, 1e30, 1e-300, 1e300, 4.9e-324, 1e-310] {
                let scaled: Vec<f64> = c.iter().map(|x| x * scale).collect();
                let (v, p) = split::<D>(&scaled);
                check(&v, &p);
            }
            // Degenerate at extreme scales: p = v1.
            for scale in [1e-30, 1e300] {
                let scaled: Vec<f64> = c.iter().map(|x| x * scale).collect();
                let (v, _) = split::<D>(&scaled);
                prop_assert_eq!(check(&v, &v[1]), Sign::Zero);
            }
            // Mixed magnitudes.
            let mixed: Vec<f64> = c
                .iter()
                .enumerate()
                .map(|(i, x)| x * [1.0, 1e-200, 1e200, 1e-20][i % 4])
                .collect();
            let (v, p) = split::<D>(&mixed);
            check(&v, &p);
            Ok(())
        })
        .unwrap();
}

#[test]
fn tiny_huge_and_clustered_coordinates() {
    all_dims!(scaled_case);
}

// ---------------------------------------------------------------------------------------------
// Algebraic identities.

fn swap_case<const D: usize>() {
    let strategy = (
        prop::collection::vec(-1.0f64..=1.0, D * (D + 1)),
        0..D,
        0..D,
    );
    runner(0x5a9 + D as u64, 32)
        .run(&strategy, |(c, a, b)| {
            let (v, p) = split::<D>(&c);
            prop_assume!(a != b);
            let mut w = v;
            w.swap(a, b);
            let s = orientation(&v, &p);
            prop_assert_eq!(orientation(&w, &p), s.flip());
            prop_assert_eq!(FacetPlane::new(&w).side(&p, || w), s.flip());
            Ok(())
        })
        .unwrap();
}

#[test]
fn swapping_two_vertices_flips_the_sign() {
    all_dims!(swap_case);
}

#[test]
fn sign_conventions_2d_3d() {
    // 2-D: left of v0 → v1 is positive.
    let line = [[0.0, 0.0], [1.0, 0.0]];
    assert_eq!(orientation(&line, &[0.0, 1.0]), Sign::Positive);
    assert_eq!(orientation_bareiss(&line, &[0.0, 1.0]), Sign::Positive);
    // 3-D: e1, e2, e3 is a positive basis.
    let tri = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    assert_eq!(orientation(&tri, &[0.0, 0.0, 1.0]), Sign::Positive);
    assert_eq!(orientation_bareiss(&tri, &[0.0, 0.0, 1.0]), Sign::Positive);
    assert_eq!(orientation(&tri, &[0.0, 0.0, -1e-310]), Sign::Negative);
    // Same identity for D = 4..8: the standard simplex with p = e_D.
    fn standard<const D: usize>() {
        let mut v = [[0.0; D]; D];
        for k in 1..D {
            v[k][k - 1] = 1.0;
        }
        let mut p = [0.0; D];
        p[D - 1] = 1.0;
        assert_eq!(check(&v, &p), Sign::Positive);
        assert_eq!(FacetPlane::new(&v).cofactors()[D - 1], 1.0);
        p[D - 1] = -f64::from_bits(1); // smallest subnormal
        assert_eq!(check(&v, &p), Sign::Negative);
    }
    all_dims!(standard);
}

#[test]
fn out_of_range_input_takes_the_exact_path() {
    let tri = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
    let plane = FacetPlane::new(&tri);
    assert_eq!(plane.evaluate(&[0.1, 0.1, 0.1]).1, f64::INFINITY);
    assert_eq!(plane.side(&[0.1, 0.1, 0.1], || tri), Sign::Positive);
    let tri = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let plane = FacetPlane::new(&tri);
    assert_eq!(plane.evaluate(&[0.1, 0.1, 3.0]).1, f64::INFINITY);
    assert_eq!(plane.evaluate(&[0.1, f64::NAN, 0.1]).1, f64::INFINITY);
    assert_eq!(plane.side(&[5.0, 5.0, -3.0], || tri), Sign::Negative);
    // The closure is not called when the filter decides.
    assert_eq!(
        plane.side(&[0.1, 0.1, 0.5], || panic!("exact path taken")),
        Sign::Positive
    );
}

#[test]
#[should_panic(expected = "non-finite")]
fn nan_panics_in_orientation() {
    let v = [[0.0; 4]; 4];
    orientation(&v, &[f64::NAN, 0.0, 0.0, 0.0]);
}

#[test]
#[should_panic(expected = "non-finite")]
fn infinity_panics_in_orientation_2d() {
    orientation(&[[0.0, 0.0], [1.0, 0.0]], &[0.0, f64::INFINITY]);
}

// ---------------------------------------------------------------------------------------------
// Affine rank.

#[test]
fn affine_subset_cases() {
    assert_eq!(affinely_independent_subset::<3>(&[]), Vec::<usize>::new());
    assert_eq!(affinely_independent_subset(&[[0.5, 0.5]]), vec![0]);
    // Duplicates only.
    assert_eq!(affinely_independent_subset(&[[0.5, 0.5]; 5]), vec![0]);
    // On a line (with duplicates and a point one ulp off at the end).
    let mut line: Vec<[f64; 4]> = (0..10)
        .map(|i| {
            let t = f64::from(i) / 8.0;
            [t, 2.0 * t, -t, 0.5]
        })
        .collect();
    line.insert(3, line[1]);
    assert_eq!(affinely_independent_subset(&line), vec![0, 1]);
    let mut off = line.clone();
    off.push([0.25, 0.5, -0.25, 0.5f64.next_up()]);
    assert_eq!(affinely_independent_subset(&off), vec![0, 1, off.len() - 1]);
    // General position: the first D + 1 points.
    let general = [
        [0.1, 0.2, 0.3],
        [0.9, -0.1, 0.4],
        [-0.3, 0.7, 0.2],
        [0.5, 0.5, -0.8],
        [0.0, 0.0, 0.0],
    ];
    assert_eq!(affinely_independent_subset(&general), vec![0, 1, 2, 3]);
}

/// Random points on a hyperplane (exactly, on a dyadic lattice): rank D − 1.
fn hyperplane_rank_case<const D: usize>() {
    let strategy = (
        prop::collection::vec(-8i32..=8, D * D),
        prop::collection::vec(prop::collection::vec(-4i32..=4, D - 1), 1..20),
    );
    runner(0xa1 + D as u64, 16)
        .run(&strategy, |(ints, combos)| {
            let basis: Vec<[f64; D]> = (0..D)
                .map(|k| std::array::from_fn(|i| f64::from(ints[k * D + i]) / 16.0))
                .collect();
            let mut points: Vec<[f64; D]> = basis.clone();
            for l in &combos {
                let mut q = basis[0];
                for k in 1..D {
                    for i in 0..D {
                        q[i] += f64::from(l[k - 1]) / 4.0 * (basis[k][i] - basis[0][i]);
                    }
                }
                points.push(q);
            }
            let got = affinely_independent_subset(&points);
            // The count must match an independent elimination, and the kept points must span the
            // same rank on their own.
            let rank = reference_affine_rank(&points);
            prop_assert_eq!(got.len(), rank + 1);
            prop_assert!(rank < D);
            prop_assert_eq!(got[0], 0);
            prop_assert!(got.windows(2).all(|w| w[0] < w[1]));
            prop_assert_eq!(
                reference_affine_rank(&got.iter().map(|&i| points[i]).collect::<Vec<_>>()),
                rank
            );
            // Plus one general point raises the rank by exactly one.
            let mut more = points.clone();
            let mut extra = [0.0; D];
            for (i, x) in extra.iter_mut().enumerate() {
                *x = 0.3 + 0.01 * i as f64 * i as f64;
            }
            more.push(extra);
            let got_more = affinely_independent_subset(&more);
            let r2 = reference_affine_rank(&more);
            prop_assert_eq!(got_more.len(), r2 + 1);
            Ok(())
        })
        .unwrap();
}

/// Rank of the differences to the first point, by rational elimination (independent of the order).
fn reference_affine_rank<const D: usize>(points: &[[f64; D]]) -> usize {
    let Some(first) = points.first() else {
        return 0;
    };
    let mut rows: Vec<Vec<BigRational>> = points[1..]
        .iter()
        .map(|q| {
            q.iter()
                .zip(first)
                .map(|(&x, &o)| rational(x) - rational(o))
                .collect()
        })
        .collect();
    let mut rank = 0;
    for col in 0..D {
        let Some(r) = (rank..rows.len()).find(|&r| !rows[r][col].is_zero()) else {
            continue;
        };
        rows.swap(rank, r);
        for i in rank + 1..rows.len() {
            let f = &rows[i][col] / &rows[rank][col];
            for j in col..D {
                let t = &f * &rows[rank][j];
                rows[i][j] -= t;
            }
        }
        rank += 1;
    }
    rank
}

#[test]
fn affine_subset_on_hyperplanes() {
    all_dims!(hyperplane_rank_case);
}

#[test]
fn affine_subset_random_is_full_rank() {
    fn case<const D: usize>() {
        let strategy = prop::collection::vec(-1.0f64..=1.0, D * (D + 3));
        runner(0xf011 + D as u64, 8)
            .run(&strategy, |c| {
                let pts: Vec<[f64; D]> = c
                    .chunks_exact(D)
                    .map(|r| std::array::from_fn(|i| r[i]))
                    .collect();
                let got = affinely_independent_subset(&pts);
                prop_assert_eq!(got.len(), reference_affine_rank(&pts) + 1);
                Ok(())
            })
            .unwrap();
    }
    all_dims!(case);
}

// ---------------------------------------------------------------------------------------------
// Stress test of the filter bound (run in release: `cargo test --release --lib predicates -- --ignored`).

/// Adversarial-ish random configurations: nearly degenerate vertices (some rows scaled down by up to
/// 2^-40), `p` rounded from a point on the hyperplane plus a tiny offset, so that the value suffers
/// heavy cancellation. Checks `|value − exact| ≤ bound` and the exact sign of `side`, and reports
/// the largest ratio error/bound seen (which shows how much slack the constant has).
fn stress<const D: usize>(cases: usize) -> f64 {
    let mut state: u64 = 0x9e37_79b9_7f4a_7c15 ^ D as u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut worst: f64 = 0.0;
    for case in 0..cases {
        let mut v = [[0.0; D]; D];
        for i in 0..D {
            v[0][i] = next() * 0.5;
        }
        for k in 1..D {
            let squeeze = (2.0f64).powi(-(((case * k) % 41) as i32));
            for i in 0..D {
                v[k][i] = v[0][i] + next() * 0.5 * squeeze;
            }
        }
        let mut p = v[0];
        for k in 1..D {
            let l = next();
            for i in 0..D {
                p[i] += l * (v[k][i] - v[0][i]) * 0.5;
            }
        }
        let tiny = (2.0f64).powi(-((case % 60) as i32) - 20);
        for x in p.iter_mut() {
            *x = (*x + next() * tiny).clamp(-1.0, 1.0);
        }
        let exact = reference_det(&v, &p);
        let plane = FacetPlane::new(&v);
        let (value, bound) = plane.evaluate(&p);
        let err = (rational(value) - &exact).abs();
        assert!(err <= rational(bound), "D = {D}: {v:?} {p:?}");
        assert_eq!(plane.side(&p, || v), sign_of(&exact));
        let err = num_traits::ToPrimitive::to_f64(&err).unwrap();
        worst = worst.max(err / bound);
    }
    worst
}

/// The heaviest test here (2,000 cases in each dimension from 2 to 8, each against an exact
/// rational determinant), but not ignored: it runs in release, the profile the test command uses,
/// and an ignored test shows as skipped, which CI treats as a failure.
#[test]
fn stress_filter_bound() {
    let n = 2_000;
    let w = [
        stress::<2>(n),
        stress::<3>(n),
        stress::<4>(n),
        stress::<5>(n),
        stress::<6>(n),
        stress::<7>(n),
        stress::<8>(n),
    ];
    eprintln!("largest error/bound ratio for D = 2..8: {w:?}");
}

// ---------------------------------------------------------------------------------------------
// Exact distances.

/// `det[v1 − v0; …; v(D−1) − v0; e_j]` for each j: the exact cofactors.
fn reference_cofactors<const D: usize>(vertices: &[[f64; D]; D]) -> Vec<BigRational> {
    let v0: Vec<BigRational> = vertices[0].iter().map(|&x| rational(x)).collect();
    (0..D)
        .map(|j| {
            let mut rows: Vec<Vec<BigRational>> = vertices[1..]
                .iter()
                .map(|r| r.iter().zip(&v0).map(|(&x, o)| rational(x) - o).collect())
                .collect();
            let mut e = vec![BigRational::zero(); D];
            e[j] = BigRational::from_integer(1.into());
            rows.push(e);
            rational_det(rows)
        })
        .collect()
}

/// The determinant of a square rational matrix by Gaussian elimination.
fn rational_det(mut a: Vec<Vec<BigRational>>) -> BigRational {
    let n = a.len();
    let mut det = BigRational::from_integer(1.into());
    for k in 0..n {
        let Some(r) = (k..n).find(|&r| !a[r][k].is_zero()) else {
            return BigRational::zero();
        };
        if r != k {
            a.swap(r, k);
            det = -det;
        }
        det *= &a[k][k];
        for i in k + 1..n {
            if a[i][k].is_zero() {
                continue;
            }
            let f = &a[i][k] / &a[k][k];
            for j in k + 1..n {
                let t = &f * &a[k][j];
                a[i][j] -= t;
            }
        }
    }
    det
}

/// `FacetPlane::exact_distance` (cached integer plane or `BigInt`) and the `BigInt` path alone
/// against det / |C| from the exact rationals, each rounded once: a few ulps apart, for points
/// near the plane (an affine combination of the vertices, rounded, then nudged by a few ulps)
/// and away from it, on and off the vertices' binary grid.
fn exact_distance_case<const D: usize>() {
    let strategy = (
        prop::collection::vec(-1.0f64..=1.0, D * D),
        prop::collection::vec(0.0f64..=1.0, D),
        -3i32..=3,
        any::<bool>(),
    );
    runner(0xd157 + D as u64, 48)
        .run(&strategy, |(coordinates, weights, nudge, far)| {
            let mut v = [[0.0; D]; D];
            for (k, row) in v.iter_mut().enumerate() {
                row.copy_from_slice(&coordinates[k * D..(k + 1) * D]);
            }
            let total: f64 = weights.iter().sum::<f64>().max(1e-3);
            let mut p: [f64; D] =
                std::array::from_fn(|c| (0..D).map(|k| weights[k] / total * v[k][c]).sum::<f64>());
            if far {
                p[0] += 0.25;
            } else {
                for _ in 0..nudge.unsigned_abs() {
                    p[D - 1] = if nudge > 0 {
                        p[D - 1].next_up()
                    } else {
                        p[D - 1].next_down()
                    };
                }
            }
            let det = reference_det(&v, &p);
            let cofactors = reference_cofactors(&v);
            let to_f64 = |x: &BigRational| num_traits::ToPrimitive::to_f64(x).unwrap();
            let norm = cofactors
                .iter()
                .map(|c| to_f64(c).powi(2))
                .sum::<f64>()
                .sqrt();
            prop_assume!(norm > 0.0);
            let want = to_f64(&det) / norm;
            let plane = FacetPlane::new(&v);
            for (path, got) in [
                ("exact_distance", plane.exact_distance(&v, &p)),
                ("distance_big", super::exact::distance_big(&v, &p)),
            ] {
                prop_assert!(
                    (got - want).abs() <= 8.0 * f64::EPSILON * want.abs(),
                    "{path}: D = {D}, got {got:e}, want {want:e}, vertices {v:?}, p {p:?}"
                );
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn exact_distance_agrees_with_rational_reference() {
    all_dims!(exact_distance_case);
}

/// Points on a grid whose certificate holds, at the edge of its bound: the floating-point value
/// *is* the determinant (equal to the rational reference, not only in sign); and a grid just
/// past the bound is refused.
fn exact_grid_case<const D: usize>() {
    use super::ExactGrid;
    // The largest span s with D!·s^D < 2^52, and the grid step 2^−e that fits s units in [0, 1].
    let factorial: f64 = (1..=D).map(|k| k as f64).product();
    let mut span = 1u64;
    while factorial * ((span + 1) as f64).powi(D as i32) < 4_503_599_627_370_496.0 {
        span += 1;
    }
    let step = 1.0 / (span as f64).log2().ceil().exp2();
    let mut rng = crate::geometry::Rng::new(D as u64);
    let coordinate = |rng: &mut crate::geometry::Rng| {
        // Extremes and zeros often, so that cancellations and the largest permanents occur.
        let u = match rng.index(4) {
            0 => 0,
            1 => span,
            _ => rng.index(span as usize + 1) as u64,
        };
        u as f64 * step
    };
    for case in 0..400 {
        let mut points: Vec<[f64; D]> = (0..D + 1)
            .map(|_| std::array::from_fn(|_| coordinate(&mut rng)))
            .collect();
        if case % 3 == 0 {
            // p on the plane of the vertices: an affine combination with integer weights.
            let (a, b) = (points[0], points[1]);
            points[D] = std::array::from_fn(|j| {
                let x = 2.0 * a[j] - b[j];
                if (0.0..=span as f64 * step).contains(&x) {
                    x
                } else {
                    a[j]
                }
            });
        }
        // Pin the box: both ends of every axis present, so that the spans are exactly `span`.
        let mut set = points.clone();
        set.push([0.0; D]);
        set.push([span as f64 * step; D]);
        let grid = ExactGrid::of(&set).expect("within the bound");
        let vertices: [[f64; D]; D] = std::array::from_fn(|i| points[i]);
        let p = points[D];
        assert!(grid.contains(&p));
        let plane = FacetPlane::new(&vertices);
        let value = plane.value(&p);
        let reference = reference_det(&vertices, &p);
        assert_eq!(
            rational(value),
            reference,
            "D={D} case {case}: the value is not the exact determinant"
        );
        assert_eq!(
            plane.side_on_grid(&p),
            sign_of(&reference),
            "D={D} case {case}"
        );
    }
    // One more unit of span breaks the bound.
    let past = (span + 1) as f64 * step;
    // `step` itself is in the set, so that the grid is not coarser than it.
    let set = vec![[0.0; D], [step; D], [past.min(1.0); D]];
    if past <= 1.0 {
        assert!(
            ExactGrid::of(&set).is_none(),
            "D={D}: span {} accepted",
            span + 1
        );
    }
    // Off-grid and out-of-box points are not covered; non-finite input has no certificate.
    let grid = ExactGrid::of(&[[0.0; D], [0.5; D]]).unwrap();
    assert!(!grid.contains(&[0.25 + f64::EPSILON; D]));
    assert!(!grid.contains(&[0.75; D]));
    assert!(ExactGrid::of(&[[f64::NAN; D]]).is_none());
    assert!(ExactGrid::of(&[[2.0; D]]).is_none());
}

#[test]
fn exact_grid_values_are_the_determinant() {
    exact_grid_case::<2>();
    exact_grid_case::<3>();
    exact_grid_case::<4>();
    exact_grid_case::<5>();
    exact_grid_case::<6>();
    exact_grid_case::<7>();
    exact_grid_case::<8>();
}

// ---------------------------------------------------------------------------------------------
// The double-double second stage.

/// Points near the hyperplane of `v` (a combination of the vertices, rounded, then moved by
/// `offset` times a random vector): the determinants the `f64` filter cannot decide. Checks the
/// double-double bound against the rational determinant on each (and `side` against its sign),
/// and returns how many of the determinants the filter missed that are above 2^-30 of the
/// filter's bound it decided, and how many there were.
fn double_double_case<const D: usize>(cases: usize, scale: f64) -> (usize, usize) {
    let mut state: u64 = 0x2545_f491_4f6c_dd1d ^ (D as u64) << 32;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let (mut decided, mut decidable) = (0, 0);
    for case in 0..cases {
        let mut v = [[0.0; D]; D];
        for row in v.iter_mut() {
            for x in row.iter_mut() {
                *x = next() * 0.5 * scale;
            }
        }
        let mut p = v[0];
        for k in 1..D {
            let l = next();
            for i in 0..D {
                p[i] += l * (v[k][i] - v[0][i]) * 0.5;
            }
        }
        // 2^-40 … 2^-119 of the scale, and every eighth case exactly on a vertex's coordinates.
        let offset = scale * 2f64.powi(-40 - (case % 80) as i32);
        if case % 8 != 7 {
            for x in p.iter_mut() {
                *x = (*x + next() * offset).clamp(-1.0, 1.0);
            }
        } else {
            p = v[case % D];
        }
        let exact = reference_det(&v, &p);
        let plane = FacetPlane::new(&v);
        let (dd, base, slack) = plane.double_double(&v);
        let dd = dd.expect("vertices in [-1, 1]");
        let ((hi, lo), bound) = dd.evaluate(&base, &p, slack).expect("p in [-1, 1]");
        let err = (rational(hi) + rational(lo) - &exact).abs();
        assert!(
            err <= rational(bound),
            "D = {D}: |dd − det| > bound ({bound:e}) for {v:?}, {p:?}"
        );
        let want = sign_of(&exact);
        if let Some(sign) = dd.sign(&base, &p, slack) {
            assert_eq!(sign, want, "D = {D}: {v:?}, {p:?}");
        }
        assert_eq!(plane.side(&p, || v), want, "side, D = {D}: {v:?}, {p:?}");
        let (_, filter_bound) = plane.evaluate(&p);
        let det = num_traits::ToPrimitive::to_f64(&exact).unwrap_or(0.0).abs();
        if plane.filter_sign(&p).is_none() && det > filter_bound * 2f64.powi(-30) {
            decidable += 1;
            if dd.sign(&base, &p, slack).is_some() {
                decided += 1;
            }
        }
    }
    (decided, decidable)
}

/// The second stage's bound holds on points within 2^-40 … 2^-119 of the hyperplane, at unit
/// scale and at 2^-900 (where the underflow slack matters), and it decides every determinant the
/// filter misses that is above 2^-30 of the filter's bound (~2^-75 of the permanent: ~2^25 times
/// its own bound).
#[test]
fn double_double_stage_is_certified_and_decides_near_coplanar_points() {
    fn dims<const D: usize>() {
        let (decided, decidable) = double_double_case::<D>(800, 1.0);
        assert!(
            decidable >= 100,
            "D = {D}: only {decidable} cases in the band"
        );
        assert_eq!(decided, decidable, "D = {D}");
        double_double_case::<D>(200, 2f64.powi(-900));
    }
    dims::<2>();
    dims::<3>();
    dims::<4>();
    dims::<5>();
    dims::<6>();
    dims::<7>();
    dims::<8>();
}

/// One plane asked about many points, as a hull asks the planes of a face: once the first test
/// has built the double-double stage, later ones may take the built stages' shortcut
/// (`side_on_built_stages`), which must answer as the exact determinant does, and must leave to
/// the full route every point whose `f64` value is exact (grid points) or that the
/// double-double value cannot decide (points on the plane). In 2-D to 6-D, on raw vertices
/// (points within 2^-40 … 2^-110 of the plane, and the vertices themselves) and on vertices on
/// a coarse grid (grid points on and off the plane).
#[test]
fn the_built_stages_shortcut_answers_as_the_exact_determinant() {
    fn case<const D: usize>() {
        let mut rng = crate::geometry::Rng::new(0x5eed ^ D as u64);
        // Raw: the plane's vertices and points near it, all rounded.
        let mut v = [[0.0; D]; D];
        for row in v.iter_mut() {
            for x in row.iter_mut() {
                *x = rng.uniform_in(-0.5, 0.5);
            }
        }
        let plane = FacetPlane::new(&v);
        let near = |rng: &mut crate::geometry::Rng, k: usize| {
            let mut p = v[0];
            for r in 1..D {
                let l = rng.uniform_in(-0.5, 1.0);
                for i in 0..D {
                    p[i] += l * (v[r][i] - v[0][i]);
                }
            }
            let offset = 2f64.powi(-40 - (k % 71) as i32);
            p.map(|x| (x + rng.uniform_in(-1.0, 1.0) * offset).clamp(-1.0, 1.0))
        };
        let (mut shortcut, mut asked) = (0, 0);
        for k in 0..400 {
            let p = if k % 10 == 9 {
                v[k % D]
            } else {
                near(&mut rng, k)
            };
            let want = sign_of(&reference_det(&v, &p));
            if plane.filter_sign(&p).is_some() {
                continue;
            }
            asked += 1;
            if let Some(sign) = plane.side_on_built_stages(&p) {
                assert_eq!(sign, want, "shortcut, D = {D}: {v:?}, {p:?}");
                assert!(k % 10 != 9, "D = {D}: a vertex decided off the plane");
                shortcut += 1;
            }
            assert_eq!(plane.side(&p, || v), want, "side, D = {D}: {v:?}, {p:?}");
        }
        assert!(
            shortcut * 10 >= asked * 7,
            "D = {D}: the shortcut answered {shortcut} of {asked} undecided points"
        );
        // A grid: vertices and points on multiples of 2^-4, where the `f64` value is exact and
        // the shortcut must stand aside, even with its stage built (by a raw point first).
        let grid =
            |rng: &mut crate::geometry::Rng| [0.0; D].map(|_| (rng.below(17) as f64 - 8.0) / 16.0);
        let g = [0.0; D].map(|_| [0.0; D]).map(|_| grid(&mut rng));
        let plane = FacetPlane::new(&g);
        let raw = near(&mut rng, 3).map(|x| x * 0.999);
        assert_eq!(plane.side(&raw, || g), sign_of(&reference_det(&g, &raw)));
        for k in 0..200 {
            let p = if k % 2 == 0 { g[k % D] } else { grid(&mut rng) };
            let want = sign_of(&reference_det(&g, &p));
            if plane.filter_sign(&p).is_none() {
                assert_eq!(
                    plane.side_on_built_stages(&p),
                    None,
                    "D = {D}: {g:?}, {p:?}"
                );
            }
            assert_eq!(
                plane.side(&p, || g),
                want,
                "grid side, D = {D}: {g:?}, {p:?}"
            );
        }
    }
    case::<2>();
    case::<3>();
    case::<4>();
    case::<5>();
    case::<6>();
}

/// `refined_normal_direction` on slivers (the last vertex within 2^-8 … 2^-60 of the others'
/// affine hull, so the `f64` cofactors cancel): every component within the documented `2^-51`
/// of the largest (plus the normalisation's roundings) of the exact rational cofactors. The
/// double-double route must be the one that answers on the moderate slivers (its certified
/// errors allow it), and the exact route on the thinnest, so both are exercised.
fn refined_normal_case<const D: usize>() -> (usize, usize, usize) {
    let mut rng = crate::geometry::Rng::new(0x5e1f + D as u64);
    let (mut by_dd, mut cases, mut skipped) = (0, 0, 0);
    for case in 0..120 {
        let mut v = [[0.0; D]; D];
        for row in v.iter_mut().take(D - 1) {
            for x in row.iter_mut() {
                *x = 0.5 * rng.uniform() - 0.25;
            }
        }
        // Inside [−1, 1] (the double-double plane's domain): |v0| ≤ 1/4, the combination ≤ 1/2.
        let offset = 2f64.powi(-8 - (case % 53));
        for i in 0..D {
            let along: f64 = (1..D - 1)
                .map(|k| (v[k][i] - v[0][i]) * (0.5 + k as f64) / (D * D) as f64)
                .sum();
            v[D - 1][i] = v[0][i] + along + offset * (rng.uniform() - 0.5);
        }
        let exact = reference_cofactors(&v);
        let to_f64 = |x: &BigRational| num_traits::ToPrimitive::to_f64(x).unwrap();
        let exact: Vec<f64> = exact.iter().map(to_f64).collect();
        let largest = exact.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        if largest == 0.0 {
            continue;
        }
        cases += 1;
        let plane = FacetPlane::new(&v);
        let got = plane.refined_normal_direction(&v);
        let got_largest = got.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        for j in 0..D {
            let (a, b) = (got[j] / got_largest, exact[j] / largest);
            assert!(
                (a - b).abs() <= 2f64.powi(-51) * 1.01 + 4.0 * f64::EPSILON,
                "D = {D}, offset {offset:e}, component {j}: {a:e} against {b:e} ({v:?})"
            );
        }
        let (dd, _, _) = plane.double_double(&v);
        let (dd_cofactors, dd_error) = dd.expect("vertices in [-1, 1]").cofactors_with_error();
        if got == dd_cofactors {
            by_dd += 1;
        }
        // The skip of the double-double plane is sound: whenever the `f64` cofactors say its
        // certificate must fail, it does (the criterion `refined_normal_direction` applies).
        if FacetPlane::new(&v).dd_normal_surely_uncertified() {
            skipped += 1;
            let dd_largest = dd_cofactors.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            let worst = dd_error.iter().fold(0.0f64, |m, e| m.max(*e));
            assert!(
                worst > 2f64.powi(-51) * dd_largest,
                "D = {D}, offset {offset:e}: skipped, yet certified ({v:?})"
            );
        }
    }
    (by_dd, cases, skipped)
}

#[test]
fn refined_normals_are_within_four_ulps_of_the_exact_cofactors() {
    fn dims<const D: usize>() {
        let (by_dd, cases, skipped) = refined_normal_case::<D>();
        assert!(cases >= 100, "D = {D}: {cases} cases");
        assert!(
            by_dd >= cases / 4 && by_dd < cases,
            "D = {D}: the double-double route answered {by_dd} of {cases}"
        );
        // The thinnest slivers skip the double-double plane, the moderate ones do not.
        assert!(
            skipped > 0 && skipped + by_dd <= cases,
            "D = {D}: {skipped} skipped, {by_dd} by double-double, of {cases}"
        );
    }
    dims::<4>();
    dims::<5>();
    dims::<6>();
    dims::<7>();
    dims::<8>();
}

/// Facets with most vertices in one tight cluster (spread 2^−40) and their base vertex in
/// another: `better_order` rebuilds such planes from consecutive differences
/// (`FacetPlane::chained`), whose filter and double-double bounds are certified against the
/// rational reference (for the reordered vertices, whose determinant is the original's times
/// the permutation's sign), which decide far more of the near-plane points than the original
/// plane's filter, and `side` agrees with the reference on every point.
#[test]
fn clustered_facets_are_rebuilt_in_chain_order() {
    use super::double_double::DdPlane;
    use super::filter::better_order;
    fn case<const D: usize>(cases: usize) -> (usize, usize) {
        let mut rng = crate::geometry::Rng::new(0x5eed ^ D as u64);
        let spread = 2f64.powi(-40);
        let (mut original, mut chained) = (0, 0);
        for case in 0..cases {
            let centre = |rng: &mut crate::geometry::Rng| -> [f64; D] {
                std::array::from_fn(|_| rng.uniform_in(-0.5, 0.5))
            };
            let (a, b) = (centre(&mut rng), centre(&mut rng));
            let near = |rng: &mut crate::geometry::Rng, c: &[f64; D]| -> [f64; D] {
                std::array::from_fn(|j| c[j] + rng.uniform_in(-spread, spread))
            };
            // v0 (and, every other case from 4-D on, v1) in cluster b; the rest in cluster a.
            let in_b = if D >= 4 { 1 + case % 2 } else { 1 };
            let v: [[f64; D]; D] = std::array::from_fn(|k| {
                if k < in_b {
                    near(&mut rng, &b)
                } else {
                    near(&mut rng, &a)
                }
            });
            // A point of cluster a within 2^−30 … 2^−90 of the cluster's size off the plane
            // through its vertices there.
            let mut p = v[in_b];
            for k in in_b + 1..D {
                let l = rng.uniform_in(-1.0, 1.0);
                for j in 0..D {
                    p[j] += l * (v[k][j] - v[in_b][j]);
                }
            }
            let offset = spread * 2f64.powi(-30 - (case % 60) as i32);
            for x in p.iter_mut() {
                *x += rng.uniform_in(-1.0, 1.0) * offset;
            }
            let want = sign_of(&reference_det(&v, &p));
            let plane = FacetPlane::new(&v);
            assert_eq!(plane.side(&p, || v), want, "D = {D}: {v:?}, {p:?}");
            let (order, odd) = better_order(&v).expect("a clustered facet is rebuilt");
            let w = order.map(|k| v[k]);
            let exact = reference_det(&w, &p);
            let flip = |s: Sign| if odd { s.flip() } else { s };
            assert_eq!(flip(sign_of(&exact)), want, "D = {D}: permutation sign");
            let rebuilt = FacetPlane::chained(&w);
            let (value, bound) = rebuilt.evaluate(&p);
            assert!(
                (rational(value) - &exact).abs() <= rational(bound),
                "D = {D}: chained filter bound, {v:?}, {p:?}"
            );
            if D >= 4 {
                let dd = DdPlane::new(&w, &rebuilt, true).expect("in the box");
                let ((hi, lo), dd_bound) =
                    dd.evaluate(rebuilt.base(), &p, 0.0).expect("in the box");
                assert!(
                    (rational(hi) + rational(lo) - &exact).abs() <= rational(dd_bound),
                    "D = {D}: chained double-double bound, {v:?}, {p:?}"
                );
            }
            if plane.filter_sign(&p).is_some() {
                original += 1;
            }
            if value.abs() > bound {
                chained += 1;
            }
        }
        (original, chained)
    }
    let decided = [
        case::<3>(300),
        case::<4>(300),
        case::<5>(300),
        case::<6>(300),
        case::<8>(100),
    ];
    eprintln!("(decided by the original filter, by the chained one): {decided:?}");
    for (original, chained) in decided {
        assert!(chained > 2 * original + 50, "{decided:?}");
    }
}
