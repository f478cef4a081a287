//! Tests of the test-support reference `min_norm_point` (Wolfe's algorithm) against closed forms
//! and against brute-force projection onto every face.

use crate::support::{min_norm_point, points_as_vecs};
use pqhull::geometry::Rng;
use pqhull::rbox::{Family, generate};

fn dist(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

fn assert_close(got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol,
        "got {got}, want {want} (diff {:e})",
        got - want
    );
}

#[test]
fn square() {
    let sq = points_as_vecs(&[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]);
    let (p, d) = min_norm_point(&sq, &[0.0, 0.0]);
    assert_eq!(d, 0.0);
    assert!(p.iter().all(|x| x.abs() <= 1.0));
    let (p, d) = min_norm_point(&sq, &[3.0, 0.5]);
    assert_close(d, 2.0, 1e-15);
    assert_close(p[0], 1.0, 1e-15);
    assert_close(p[1], 0.5, 1e-15);
    let (p, d) = min_norm_point(&sq, &[2.0, 2.0]);
    assert_close(d, 2f64.sqrt(), 1e-15);
    assert_eq!(p, vec![1.0, 1.0]);
    let (p, d) = min_norm_point(&sq, &[0.0, -5.0]);
    assert_close(d, 4.0, 1e-15);
    assert_close(p[0], 0.0, 1e-15);
    assert_close(p[1], -1.0, 1e-15);
}

#[test]
fn square_with_duplicates_and_collinear_points() {
    let pts = points_as_vecs(&[
        [-1.0, -1.0],
        [1.0, -1.0],
        [0.0, -1.0],
        [1.0, 1.0],
        [1.0, 1.0],
        [-1.0, 1.0],
        [-1.0, -1.0],
        [0.5, -1.0],
    ]);
    let (p, d) = min_norm_point(&pts, &[0.25, -3.0]);
    assert_close(d, 2.0, 1e-14);
    assert_close(p[0], 0.25, 1e-14);
    assert_close(p[1], -1.0, 1e-14);
    let (_, d) = min_norm_point(&pts, &[0.1, 0.2]);
    assert_close(d, 0.0, 1e-15);
}

#[test]
fn single_point_and_segment() {
    let one = vec![vec![1.0, 2.0, 3.0]];
    let (p, d) = min_norm_point(&one, &[1.0, 2.0, 4.0]);
    assert_eq!(p, one[0]);
    assert_close(d, 1.0, 1e-15);
    let seg = vec![vec![0.0, 0.0, 0.0], vec![2.0, 0.0, 0.0]];
    let (p, d) = min_norm_point(&seg, &[1.5, 1.0, 0.0]);
    assert_close(d, 1.0, 1e-15);
    assert_close(p[0], 1.5, 1e-15);
}

#[test]
fn standard_simplex_3d() {
    let s = points_as_vecs(&[
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ]);
    // Beyond the slanted facet: projection onto x + y + z = 1.
    let (p, d) = min_norm_point(&s, &[1.0, 1.0, 1.0]);
    assert_close(d, 2.0 / 3f64.sqrt(), 1e-15);
    for x in p {
        assert_close(x, 1.0 / 3.0, 1e-15);
    }
    // A vertex is the nearest point.
    let (p, d) = min_norm_point(&s, &[-1.0, -2.0, -3.0]);
    assert_close(d, 14f64.sqrt(), 1e-14);
    assert_eq!(p, vec![0.0, 0.0, 0.0]);
    // Nearest point on an edge.
    let (p, d) = min_norm_point(&s, &[0.5, 0.5, -1.0]);
    assert_close(d, 1.0, 1e-15);
    assert_close(p[0], 0.5, 1e-15);
    assert_close(p[1], 0.5, 1e-15);
    assert_close(p[2], 0.0, 1e-15);
    // Inside.
    let (_, d) = min_norm_point(&s, &[0.1, 0.2, 0.3]);
    assert_close(d, 0.0, 1e-15);
}

#[test]
fn high_dimensional_simplex_and_sphere() {
    // The rbox simplex family: vertices (−1,…,−1) and (D+1)e_i − 1, centroid at the origin.
    let pts = generate::<6>(&Family::Simplex, 30, 1);
    let v = points_as_vecs(&pts);
    let (_, d) = min_norm_point(&v, &[0.0; 6]);
    assert_close(d, 0.0, 1e-14);
    // Beyond the facet Σx = 1 (opposite v_0): distance (Σq − 1)/√D.
    let q = [1.0; 6];
    let (p, d) = min_norm_point(&v, &q);
    assert_close(d, 5.0 / 6f64.sqrt(), 1e-13);
    assert_close(p.iter().sum::<f64>(), 1.0, 1e-13);
    // Points on the sphere of radius 0.5: a query at distance 2 from the centre is between 1.5
    // and 1.5 + (gap of the sampled sphere) away.
    let sphere = points_as_vecs(&generate::<5>(&Family::SphereSurface, 400, 2));
    let (p, d) = min_norm_point(&sphere, &[2.0, 0.0, 0.0, 0.0, 0.0]);
    assert!((1.5..1.6).contains(&d), "{d}");
    assert_close(dist(&p, &[2.0, 0.0, 0.0, 0.0, 0.0]), d, 1e-14);
    let (_, d) = min_norm_point(&sphere, &[0.01, 0.0, -0.02, 0.0, 0.0]);
    assert_close(d, 0.0, 1e-14);
}

/// Brute force: the nearest point of conv(P) lies in the relative interior of the hull of some
/// affinely independent subset S, where it is the projection of the query onto aff(S). So the
/// distance is the minimum, over all subsets of at most D + 1 points whose projection lies inside
/// their simplex, of the distance to that projection. Projections here use modified Gram–Schmidt
/// and back substitution (not Wolfe's normal equations).
fn brute_force(points: &[Vec<f64>], q: &[f64]) -> (Vec<f64>, f64) {
    let n = points.len();
    let d = q.len();
    let mut best = (Vec::new(), f64::INFINITY);
    for mask in 1u32..(1 << n) {
        let subset: Vec<&Vec<f64>> = (0..n)
            .filter(|i| mask >> i & 1 == 1)
            .map(|i| &points[i])
            .collect();
        if subset.len() > d + 1 {
            continue;
        }
        let s0 = subset[0];
        let k = subset.len() - 1;
        // Orthonormal basis of the differences (MGS), with R upper triangular: diff_i = Σ_j R[j][i] e_j.
        let mut basis: Vec<Vec<f64>> = Vec::new();
        let mut r = vec![vec![0.0; k]; k];
        let mut degenerate = false;
        for i in 0..k {
            let mut v: Vec<f64> = subset[i + 1].iter().zip(s0).map(|(a, b)| a - b).collect();
            for (j, e) in basis.iter().enumerate() {
                let c: f64 = v.iter().zip(e).map(|(a, b)| a * b).sum();
                r[j][i] = c;
                v.iter_mut().zip(e).for_each(|(a, b)| *a -= c * b);
            }
            let norm = v.iter().map(|a| a * a).sum::<f64>().sqrt();
            if norm < 1e-9 {
                degenerate = true;
                break;
            }
            r[i][i] = norm;
            basis.push(v.into_iter().map(|a| a / norm).collect());
        }
        if degenerate {
            continue;
        }
        let w: Vec<f64> = q.iter().zip(s0).map(|(a, b)| a - b).collect();
        let c: Vec<f64> = basis
            .iter()
            .map(|e| e.iter().zip(&w).map(|(a, b)| a * b).sum())
            .collect();
        let mut beta = vec![0.0; k];
        for i in (0..k).rev() {
            let s: f64 = (i + 1..k).map(|j| r[i][j] * beta[j]).sum();
            beta[i] = (c[i] - s) / r[i][i];
        }
        let alpha0 = 1.0 - beta.iter().sum::<f64>();
        if alpha0 < -1e-12 || beta.iter().any(|&b| b < -1e-12) {
            continue;
        }
        let mut proj = s0.clone();
        for (e, ci) in basis.iter().zip(&c) {
            proj.iter_mut().zip(e).for_each(|(p, ek)| *p += ci * ek);
        }
        let dd = dist(&proj, q);
        if dd < best.1 {
            best = (proj, dd);
        }
    }
    best
}

fn random_cases(d: usize, max_points: usize, cases: usize, seed: u64) {
    let mut rng = Rng::new(seed);
    for case in 0..cases {
        let n = d + 1 + rng.index(max_points - d);
        let points: Vec<Vec<f64>> = (0..n)
            .map(|_| (0..d).map(|_| rng.uniform_in(-1.0, 1.0)).collect())
            .collect();
        // Half the queries near the set (often inside), half well outside.
        let spread = if case % 2 == 0 { 1.0 } else { 3.0 };
        let q: Vec<f64> = (0..d).map(|_| rng.uniform_in(-spread, spread)).collect();
        let (p, got) = min_norm_point(&points, &q);
        let (bp, want) = brute_force(&points, &q);
        assert!(
            (got - want).abs() <= 1e-12 * (1.0 + want),
            "d={d} case {case}: wolfe {got}, brute force {want}\npoints {points:?}\nquery {q:?}"
        );
        assert!(
            dist(&p, &bp) <= 1e-9,
            "d={d} case {case}: nearest points differ: {p:?} vs {bp:?}"
        );
        assert!((dist(&p, &q) - got).abs() <= 1e-12 * (1.0 + got));
    }
}

#[test]
fn random_2d_against_brute_force() {
    random_cases(2, 8, 400, 20);
}

#[test]
fn random_3d_against_brute_force() {
    random_cases(3, 8, 300, 30);
}

#[test]
fn random_4d_against_brute_force() {
    random_cases(4, 8, 100, 40);
}
