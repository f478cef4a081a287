//! Public behaviour of `pqhull::geometry::ellipsoid`: known minimum-volume centred ellipsoids,
//! affine equivariance, containment, the volume guarantee, and errors.

use std::time::Instant;

use pqhull::geometry::Rng;
use pqhull::geometry::ellipsoid::{
    CONTAINMENT_SLACK, CentredEllipsoid, EllipsoidError, MAX_ITERATIONS,
};
use pqhull::grasp::{Contact, FrictionModel, Grasp};
use pqhull::rbox::{Family, generate};

/// Largest entry-wise difference between two matrices, relative to the largest entry of `b`.
fn relative_difference<const D: usize>(a: &[[f64; D]; D], b: &[[f64; D]; D]) -> f64 {
    let scale = b.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    let diff = (0..D)
        .flat_map(|i| (0..D).map(move |j| (i, j)))
        .fold(0.0_f64, |m, (i, j)| m.max((a[i][j] - b[i][j]).abs()));
    diff / scale
}

fn diagonal<const D: usize>(d: [f64; D]) -> [[f64; D]; D] {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { d[i] } else { 0.0 }))
}

/// Every input point inside (gauge ≤ 1 exactly as computed), the farthest on the boundary.
fn assert_encloses_tightly<const D: usize>(e: &CentredEllipsoid<D>, points: &[[f64; D]]) {
    let mut max_gauge = 0.0_f64;
    for (i, p) in points.iter().enumerate() {
        let g = e.gauge(p);
        assert!(g <= 1.0, "point {i}: gauge {g}");
        assert!(e.contains(p), "point {i}");
        max_gauge = max_gauge.max(g);
    }
    assert!(max_gauge >= 1.0 - 1e-12, "max gauge {max_gauge}");
    assert!(e.log_volume_gap_bound() >= 0.0);
}

/// The points ±a_i e_i (a_i = i + 1), optionally with interior points `a ⊙ c / √D`, c uniform in
/// the cube [−½, ½)^D (so |c/√D| ≤ ½): the minimum-volume centred ellipsoid is diag(a)·B, i.e.
/// A = diag(1/a_i²) — the image of the cross-polytope's minimum ellipsoid, the unit ball.
fn cross_polytope<const D: usize>(interior: usize) -> (Vec<[f64; D]>, [[f64; D]; D]) {
    let a: [f64; D] = std::array::from_fn(|i| (i + 1) as f64);
    let mut points = Vec::new();
    for i in 0..D {
        for sign in [1.0, -1.0] {
            let mut p = [0.0; D];
            p[i] = sign * a[i];
            points.push(p);
        }
    }
    let root = (D as f64).sqrt();
    for c in generate::<D>(&Family::UniformCube, interior, 11) {
        points.push(std::array::from_fn(|i| a[i] * c[i] / root));
    }
    (points, diagonal(a.map(|a| 1.0 / (a * a))))
}

fn check_cross_polytope<const D: usize>() {
    // Uniform weights are already optimal: no iteration, exact answer.
    let (points, expected) = cross_polytope::<D>(0);
    let e = CentredEllipsoid::try_enclosing(&points, 1e-9).unwrap();
    assert_eq!(e.iterations(), 0);
    assert!(
        relative_difference(&e.matrix(), &expected) < 1e-14,
        "D = {D}"
    );
    assert_encloses_tightly(&e, &points);

    // With interior points: uniform weights are not optimal.
    let (points, expected) = cross_polytope::<D>(200);
    let tolerance = 1e-12;
    let e = CentredEllipsoid::try_enclosing(&points, tolerance).unwrap();
    assert!(
        e.log_volume_gap_bound() <= 0.5 * D as f64 * tolerance + 1e-13,
        "D = {D}: gap {}",
        e.log_volume_gap_bound()
    );
    let err = relative_difference(&e.matrix(), &expected);
    assert!(err < 1e-5, "D = {D}: relative difference {err}");
    assert_encloses_tightly(&e, &points);
}

#[test]
fn cross_polytope_gives_the_axis_aligned_ellipsoid() {
    check_cross_polytope::<2>();
    check_cross_polytope::<3>();
    check_cross_polytope::<6>();
}

fn check_cube<const D: usize>() {
    // The corners {±1}^D alone: the ball of radius √D, at once.
    let corners: Vec<[f64; D]> = (0..1usize << D)
        .map(|bits| std::array::from_fn(|i| if bits >> i & 1 == 1 { 1.0 } else { -1.0 }))
        .collect();
    let e = CentredEllipsoid::try_enclosing(&corners, 1e-9).unwrap();
    assert_eq!(e.iterations(), 0);
    let ball = diagonal([1.0 / D as f64; D]);
    assert!(relative_difference(&e.matrix(), &ball) < 1e-14);
    let log_ball = 0.5 * D as f64 * (D as f64).ln();
    assert!((e.log_volume_ratio_to_ball() - log_ball).abs() < 1e-12);

    // Corners of [−½, ½]^D, face centres and 500 interior points: the ball of radius √D / 2.
    let points = generate::<D>(&Family::CubeCornersDiamond, 500, 3);
    let tolerance = 1e-12;
    let e = CentredEllipsoid::try_enclosing(&points, tolerance).unwrap();
    let ball = diagonal([4.0 / D as f64; D]);
    let err = relative_difference(&e.matrix(), &ball);
    assert!(err < 1e-5, "D = {D}: relative difference {err}");
    let log_ball = 0.5 * D as f64 * (0.25 * D as f64).ln();
    let excess = e.log_volume_ratio_to_ball() - log_ball;
    assert!(
        (-1e-12..=0.5 * D as f64 * tolerance + 1e-12).contains(&excess),
        "D = {D}: {excess}"
    );
    assert_encloses_tightly(&e, &points);
}

#[test]
fn cube_gives_the_ball_of_radius_root_d() {
    check_cube::<2>();
    check_cube::<3>();
    check_cube::<6>();
}

/// T = (rotation by Gram–Schmidt of random vectors) · diag(scales).
fn random_transform<const D: usize>(seed: u64) -> [[f64; D]; D] {
    let mut rng = Rng::new(seed);
    let mut q = [[0.0; D]; D];
    for k in 0..D {
        let mut v: [f64; D] = std::array::from_fn(|_| rng.normal());
        for row in &q[..k] {
            let dot: f64 = (0..D).map(|i| v[i] * row[i]).sum();
            (0..D).for_each(|i| v[i] -= dot * row[i]);
        }
        let norm = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        q[k] = v.map(|x| x / norm);
    }
    let scales: [f64; D] = std::array::from_fn(|i| 0.1 * (3.0_f64).powi(i as i32));
    std::array::from_fn(|i| std::array::from_fn(|j| q[i][j] * scales[j]))
}

fn apply<const D: usize>(t: &[[f64; D]; D], x: &[f64; D]) -> [f64; D] {
    std::array::from_fn(|i| (0..D).map(|j| t[i][j] * x[j]).sum())
}

fn check_equivariance<const D: usize>(family: Family) {
    let points = generate::<D>(&family, 300, 5);
    let t = random_transform::<D>(9);
    let moved: Vec<[f64; D]> = points.iter().map(|p| apply(&t, p)).collect();
    let tolerance = 1e-12;
    let e = CentredEllipsoid::try_enclosing(&points, tolerance).unwrap();
    let f = CentredEllipsoid::try_enclosing(&moved, tolerance).unwrap();
    // A' = T⁻ᵀ A T⁻¹  ⇔  Tᵀ A' T = A.
    let a2 = f.matrix();
    let pulled: [[f64; D]; D] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..D)
                .flat_map(|k| (0..D).map(move |l| (k, l)))
                .map(|(k, l)| t[k][i] * a2[k][l] * t[l][j])
                .sum()
        })
    });
    let err = relative_difference(&pulled, &e.matrix());
    assert!(err < 1e-8, "D = {D}, {family}: relative difference {err}");
    let log_det_t = (0..D)
        .map(|i| (0.1 * 3.0_f64.powi(i as i32)).ln())
        .sum::<f64>();
    let dv = f.log_volume() - e.log_volume() - log_det_t;
    assert!(dv.abs() < 0.5 * D as f64 * tolerance + 1e-9, "{dv}");
    for p in points.iter().take(50) {
        assert!((f.gauge(&apply(&t, p)) - e.gauge(p)).abs() < 1e-8);
    }
    assert_encloses_tightly(&f, &moved);
}

#[test]
fn rotated_and_scaled_points_give_the_transformed_ellipsoid() {
    check_equivariance::<3>(Family::UniformCube);
    check_equivariance::<6>(Family::UniformCube);
    check_equivariance::<6>(Family::SphereSurface);
}

#[test]
fn map_sends_the_boundary_to_the_unit_sphere() {
    let points = generate::<6>(&Family::UniformCube, 400, 21);
    let e = CentredEllipsoid::try_enclosing(&points, 1e-8).unwrap();
    let r = e.factor();
    let mut rng = Rng::new(4);
    for _ in 0..200 {
        let w: [f64; 6] = std::array::from_fn(|_| rng.normal());
        let x = w.map(|c| c / e.gauge(&w));
        let y = e.map(&x);
        assert!((y.iter().map(|c| c * c).sum::<f64>().sqrt() - 1.0).abs() < 1e-12);
        assert!(e.contains(&x));
        assert!(!e.contains(&x.map(|c| c * (1.0 + 1e-9))));
        // map is the matrix R, and A = RᵀR.
        let ry = apply(&r, &x);
        assert!((0..6).all(|i| (ry[i] - y[i]).abs() < 1e-12));
        let a = e.matrix();
        let quad: f64 = (0..6)
            .flat_map(|i| (0..6).map(move |j| (i, j)))
            .map(|(i, j)| x[i] * a[i][j] * x[j])
            .sum();
        assert!((quad - 1.0).abs() < 1e-10);
    }
    assert_eq!(e.gauge(&[0.0; 6]), 0.0);
}

#[test]
fn every_family_is_enclosed() {
    for family in Family::ALL {
        let points = generate::<6>(&family, 300, 17);
        let e = CentredEllipsoid::try_enclosing(&points, 1e-7)
            .unwrap_or_else(|err| panic!("{family}: {err}"));
        assert_encloses_tightly(&e, &points);
        assert!(e.log_volume_gap_bound() <= 3.0 * 1e-7 + 1e-12, "{family}");
    }
    // Huge and tiny coordinates.
    let points = generate::<6>(&Family::UniformCube, 300, 1);
    for factor in [1e-200, 1e200] {
        let scaled: Vec<[f64; 6]> = points.iter().map(|p| p.map(|c| c * factor)).collect();
        let e = CentredEllipsoid::try_enclosing(&scaled, 1e-7).unwrap();
        assert_encloses_tightly(&e, &scaled);
        assert!(e.log_volume().is_finite());
    }
}

/// Random 6-D clouds: containment, and the coarse run's volume within its guarantee of a fine
/// run's (which is itself within its own of the minimum).
fn check_random_cloud(family: Family, n: usize) {
    let points = generate::<6>(&family, n, 2024);
    let (coarse_tolerance, fine_tolerance) = (1e-5, 1e-10);
    let start = Instant::now();
    let coarse = CentredEllipsoid::try_enclosing(&points, coarse_tolerance).unwrap();
    let coarse_time = start.elapsed();
    let start = Instant::now();
    let fine = CentredEllipsoid::try_enclosing(&points, fine_tolerance).unwrap();
    let fine_time = start.elapsed();
    eprintln!(
        "{family} n = {n}: tolerance {coarse_tolerance:e}: {} iterations, {:.1} ms; \
         tolerance {fine_tolerance:e}: {} iterations, {:.1} ms",
        coarse.iterations(),
        coarse_time.as_secs_f64() * 1e3,
        fine.iterations(),
        fine_time.as_secs_f64() * 1e3
    );
    assert!(fine.iterations() < MAX_ITERATIONS);
    assert_encloses_tightly(&coarse, &points);
    assert_encloses_tightly(&fine, &points);

    let coarse_bound = 3.0 * (1.0 + coarse_tolerance).ln();
    let fine_bound = 3.0 * (1.0 + fine_tolerance).ln();
    assert!(coarse.log_volume_gap_bound() <= coarse_bound + 1e-12);
    assert!(fine.log_volume_gap_bound() <= fine_bound + 1e-12);
    let excess = coarse.log_volume() - fine.log_volume();
    assert!(excess <= coarse_bound + 1e-12, "{family} n = {n}: {excess}");
    assert!(excess >= -fine_bound - 1e-12, "{family} n = {n}: {excess}");
    // Closeness in the gauge, which the metric uses: O(√ε) at worst.
    let worst = points
        .iter()
        .map(|p| (coarse.gauge(p) - fine.gauge(p)).abs())
        .fold(0.0_f64, f64::max);
    assert!(worst < 0.05, "{family} n = {n}: {worst}");
}

#[test]
fn random_clouds_of_100_points() {
    check_random_cloud(Family::UniformCube, 100);
    check_random_cloud(Family::SphereSurface, 100);
}

#[test]
fn random_clouds_of_10000_points() {
    check_random_cloud(Family::UniformCube, 10_000);
    check_random_cloud(Family::SphereSurface, 10_000);
}

#[test]
fn non_finite_coordinates_are_named() {
    let mut points = generate::<6>(&Family::UniformCube, 20, 1);
    points[7][4] = f64::NAN;
    points[12][0] = f64::INFINITY;
    let err = CentredEllipsoid::try_enclosing(&points, 1e-7).unwrap_err();
    assert_eq!(
        err,
        EllipsoidError::NonFinite {
            index: 7,
            coordinate: 4
        }
    );
    assert!(err.to_string().contains("point 7"), "{err}");
    let boxed: Box<dyn std::error::Error> = Box::new(err);
    assert!(boxed.to_string().contains("NaN or infinite"));
}

#[test]
fn too_few_points() {
    let points = generate::<6>(&Family::UniformCube, 5, 1);
    let err = CentredEllipsoid::try_enclosing(&points, 1e-7).unwrap_err();
    assert_eq!(
        err,
        EllipsoidError::TooFewPoints {
            points: 5,
            required: 6
        }
    );
    assert!(err.to_string().contains("5 given"), "{err}");
    let err = CentredEllipsoid::<3>::try_enclosing(&[], 1e-7).unwrap_err();
    assert_eq!(
        err,
        EllipsoidError::TooFewPoints {
            points: 0,
            required: 3
        }
    );
}

#[test]
fn rank_deficient_points() {
    // In the coordinate hyperplane x_5 = 0.
    let mut points = generate::<6>(&Family::UniformCube, 100, 2);
    points.iter_mut().for_each(|p| p[5] = 0.0);
    let err = CentredEllipsoid::try_enclosing(&points, 1e-7).unwrap_err();
    assert_eq!(
        err,
        EllipsoidError::RankDeficient {
            rank: 5,
            dimension: 6
        }
    );
    assert!(err.to_string().contains("5 of 6"), "{err}");

    // In a rotated hyperplane (with rounding) and on a rotated line.
    let t = random_transform::<6>(3);
    let flat: Vec<[f64; 6]> = points.iter().map(|p| apply(&t, p)).collect();
    let err = CentredEllipsoid::try_enclosing(&flat, 1e-7).unwrap_err();
    assert!(
        matches!(err, EllipsoidError::RankDeficient { rank: 5, .. }),
        "{err}"
    );
    let line: Vec<[f64; 6]> = (0..10)
        .map(|i| apply(&t, &[i as f64 - 4.5, 0.0, 0.0, 0.0, 0.0, 0.0]))
        .collect();
    let err = CentredEllipsoid::try_enclosing(&line, 1e-7).unwrap_err();
    assert!(
        matches!(err, EllipsoidError::RankDeficient { rank: 1, .. }),
        "{err}"
    );

    // All at the origin.
    let err = CentredEllipsoid::try_enclosing(&[[0.0; 3]; 4], 1e-7).unwrap_err();
    assert!(
        matches!(err, EllipsoidError::RankDeficient { rank: 0, .. }),
        "{err}"
    );

    // Not flat, only thin: accepted.
    let mut thin = generate::<6>(&Family::UniformCube, 100, 2);
    thin.iter_mut().for_each(|p| p[5] *= 1e-4);
    let e = CentredEllipsoid::try_enclosing(&thin, 1e-7).unwrap();
    assert_encloses_tightly(&e, &thin);
}

#[test]
fn invalid_tolerances() {
    let points = generate::<3>(&Family::UniformCube, 20, 1);
    for tolerance in [0.0, -1e-7, f64::NAN, f64::INFINITY] {
        let err = CentredEllipsoid::try_enclosing(&points, tolerance).unwrap_err();
        assert!(
            matches!(err, EllipsoidError::InvalidTolerance { .. }),
            "{tolerance}: {err}"
        );
        assert!(err.to_string().contains("tolerance"));
    }
    // A huge tolerance is valid: it stops at once, and still encloses every point.
    let e = CentredEllipsoid::try_enclosing(&points, 1e6).unwrap();
    assert_eq!(e.iterations(), 0);
    assert_encloses_tightly(&e, &points);
    // Just outside, within the documented slack: still contained.
    let p = points[0].map(|c| c / e.gauge(&points[0]) * (1.0 + 0.25 * CONTAINMENT_SLACK));
    assert!(e.gauge(&p) > 1.0 && e.contains(&p));
}

#[test]
fn one_dimensional_interval() {
    let e = CentredEllipsoid::try_enclosing(&[[2.0], [-3.0], [1.0]], 1e-12).unwrap();
    assert!((e.matrix()[0][0] - 1.0 / 9.0).abs() < 1e-15);
    assert!((e.log_volume() - 6.0_f64.ln()).abs() < 1e-14); // the interval [−3, 3]
    assert!(e.contains(&[-3.0]) && !e.contains(&[3.001]));
}

#[test]
fn unit_ball_volumes() {
    // log_volume − log_volume_ratio_to_ball = ln vol(B_D), from the cross-polytope's unit ball.
    fn log_ball<const D: usize>() -> f64 {
        let e = CentredEllipsoid::try_enclosing(&cross_polytope::<D>(0).0, 1e-9).unwrap();
        e.log_volume() - e.log_volume_ratio_to_ball()
    }
    let pi = std::f64::consts::PI;
    let expected = [
        2.0,
        pi,
        4.0 * pi / 3.0,
        pi * pi / 2.0,
        8.0 * pi * pi / 15.0,
        pi.powi(3) / 6.0,
    ];
    let computed = [
        log_ball::<1>(),
        log_ball::<2>(),
        log_ball::<3>(),
        log_ball::<4>(),
        log_ball::<5>(),
        log_ball::<6>(),
    ];
    for (d, (v, c)) in expected.iter().zip(computed).enumerate() {
        assert!((c - v.ln()).abs() < 1e-14, "D = {}", d + 1);
    }
}

#[test]
fn power_of_two_scaling_is_exact() {
    let points = generate::<4>(&Family::UniformCube, 200, 8);
    let factor = 2f64.powi(600);
    let big: Vec<[f64; 4]> = points.iter().map(|p| p.map(|c| c * factor)).collect();
    let e = CentredEllipsoid::try_enclosing(&points, 1e-9).unwrap();
    let f = CentredEllipsoid::try_enclosing(&big, 1e-9).unwrap();
    assert_eq!(e.iterations(), f.iterations());
    assert_eq!(e.factor().map(|row| row.map(|r| r / factor)), f.factor());
    assert!(
        points
            .iter()
            .zip(&big)
            .all(|(p, q)| e.gauge(p) == f.gauge(q))
    );
    let shift = 4.0 * 600.0 * 2f64.ln();
    assert!((f.log_volume() - e.log_volume() - shift).abs() < 1e-9);
}

/// 10,000 points on a 6-D sphere: nearly all lie close to the optimal ellipsoid, where
/// first-order steps alone did not reach 1e−7 in 100,000 steps (the Newton steps fix it).
#[test]
fn points_nearly_all_on_the_ellipsoid_converge() {
    let points = generate::<6>(&Family::SphereSurface, 10_000, 7);
    let e = CentredEllipsoid::try_enclosing(&points, 1e-7).unwrap();
    assert!(e.iterations() < 5_000, "{} iterations", e.iterations());
    assert_encloses_tightly(&e, &points);
    // Nearly the ball of radius 0.5.
    assert!((e.log_volume_ratio_to_ball() - 6.0 * 0.5_f64.ln()).abs() < 0.01);
}

/// An object-wrench-space-like set: unit-normal-force wrenches of contacts all over a sphere.
#[test]
fn object_wrench_space_of_a_sphere() {
    let mut rng = Rng::new(12);
    let contacts: Vec<Contact> = (0..pqhull::grasp::MAX_CONTACTS)
        .map(|_| {
            let v = rng.unit_vector(3);
            let position = [0.5 * v[0], 0.5 * v[1], 0.5 * v[2]];
            Contact::try_new(position, [-v[0], -v[1], -v[2]], None).unwrap()
        })
        .collect();
    let grasp = Grasp::builder(contacts, FrictionModel::try_new(0.5, 8).unwrap())
        .build()
        .unwrap();
    let wrenches = grasp.wrenches();
    let e = CentredEllipsoid::try_enclosing(&wrenches, 1e-9).unwrap();
    assert_encloses_tightly(&e, &wrenches);
    assert!(e.log_volume_gap_bound() <= 3.0 * 1e-9 + 1e-12);
    // The mapped set lies in the unit ball and touches its boundary.
    let radii: Vec<f64> = wrenches
        .iter()
        .map(|w| e.map(w).iter().map(|c| c * c).sum::<f64>().sqrt())
        .collect();
    assert!(radii.iter().all(|&r| r <= 1.0 + 1e-12));
    assert!(radii.iter().any(|&r| r >= 1.0 - 1e-12));
}
