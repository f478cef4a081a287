//! Queries far from the hull (1e155 up to 1.7e308 with a unit hull): the nearest point must be
//! the exact one, rounded, and the signed distance right. Before the fix the square [−1, 1]² seen
//! from (0, 1e170) gave the nearest point (1, 0): every `p − q` rounded to (±1, −1e170), the
//! square collapsed to a segment and every vertex tied in Wolfe's optimality test.
//!
//! The reference is a brute force written here: the exact (rational) projection of the query on
//! the affine hull of every affinely independent subset of the points, kept when it falls in the
//! subset's simplex, the nearest one taken — the nearest point of the hull, in exact arithmetic.

use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use pqhull::geometry::Rng;
use pqhull::{ClosestToOrigin, Hull};

fn rational(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

/// Exact projection of `q` on the affine hull of `face`, if its points are affinely independent
/// and the projection lies in their simplex: the point and its squared distance.
fn project(
    face: &[Vec<BigRational>],
    q: &[BigRational],
) -> Option<(Vec<BigRational>, BigRational)> {
    let d = q.len();
    let k = face.len() - 1;
    let edge =
        |i: usize| -> Vec<BigRational> { (0..d).map(|c| &face[i + 1][c] - &face[0][c]).collect() };
    let edges: Vec<Vec<BigRational>> = (0..k).map(edge).collect();
    let dot = |a: &[BigRational], b: &[BigRational]| -> BigRational {
        a.iter().zip(b).map(|(x, y)| x * y).sum()
    };
    let r: Vec<BigRational> = (0..d).map(|c| &q[c] - &face[0][c]).collect();
    // Gram system [G | b], Gauss–Jordan in rationals.
    let mut m: Vec<Vec<BigRational>> = (0..k)
        .map(|i| {
            let mut row: Vec<BigRational> = (0..k).map(|j| dot(&edges[i], &edges[j])).collect();
            row.push(dot(&edges[i], &r));
            row
        })
        .collect();
    for col in 0..k {
        let pivot = (col..k).find(|&i| !m[i][col].is_zero())?;
        m.swap(col, pivot);
        let p = m[col][col].clone();
        for x in m[col].iter_mut() {
            *x = &*x / &p;
        }
        let pivot_row = m[col].clone();
        for (i, row) in m.iter_mut().enumerate() {
            if i != col && !row[col].is_zero() {
                let f = row[col].clone();
                for (x, p) in row.iter_mut().zip(&pivot_row) {
                    *x = &*x - p * &f;
                }
            }
        }
    }
    let mu: Vec<BigRational> = (0..k).map(|i| m[i][k].clone()).collect();
    let first = BigRational::one() - mu.iter().sum::<BigRational>();
    if first.is_negative() || mu.iter().any(|w| w.is_negative()) {
        return None;
    }
    let x: Vec<BigRational> = (0..d)
        .map(|c| &face[0][c] + (0..k).map(|i| &mu[i] * &edges[i][c]).sum::<BigRational>())
        .collect();
    let diff: Vec<BigRational> = (0..d).map(|c| &q[c] - &x[c]).collect();
    let squared = dot(&diff, &diff);
    Some((x, squared))
}

/// The point of conv(`points`) nearest `q`, exactly: over every subset of at most D + 1 points
/// (at most D when `q` is known to be outside: its nearest point is then on a facet, in the
/// convex hull of at most D points of the facet's hyperplane, by Carathéodory).
fn brute_force<const D: usize>(
    points: &[[f64; D]],
    q: &[f64; D],
    outside: bool,
) -> Vec<BigRational> {
    let largest = if outside { D } else { D + 1 };
    let exact: Vec<Vec<BigRational>> = points
        .iter()
        .map(|p| p.iter().map(|&x| rational(x)).collect())
        .collect();
    let query: Vec<BigRational> = q.iter().map(|&x| rational(x)).collect();
    let n = points.len();
    assert!(n < 32);
    let mut best: Option<(Vec<BigRational>, BigRational)> = None;
    for mask in 1u32..(1 << n) {
        if mask.count_ones() as usize > largest {
            continue;
        }
        let face: Vec<Vec<BigRational>> = (0..n)
            .filter(|i| mask & (1 << i) != 0)
            .map(|i| exact[i].clone())
            .collect();
        if let Some((x, s)) = project(&face, &query)
            && best.as_ref().is_none_or(|(_, b)| s < *b)
        {
            best = Some((x, s));
        }
    }
    best.expect("single points always project").0
}

/// `|v|` in f64 without overflow of the squares.
fn length(v: &[f64]) -> f64 {
    let largest = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if largest == 0.0 {
        return 0.0;
    }
    let unit = 2f64.powi(largest.log2().floor() as i32);
    v.iter().map(|x| (x / unit).powi(2)).sum::<f64>().sqrt() * unit
}

/// Runs `ClosestToOrigin` toward `q` and checks it against the brute force: the nearest point is
/// the exact one rounded to the nearest `f64` (so a point of the hull to half an ulp), the signed
/// distance −|q − x| to 1e−15 (−∞ beyond `f64::MAX`).
fn check<const D: usize>(points: &[[f64; D]], q: [f64; D]) -> [f64; D] {
    let (_, r) = Hull::try_with_strategy(points, ClosestToOrigin::towards(q)).unwrap();
    let exact = brute_force(points, &q, r.signed_distance < 0.0);
    let rounded: Vec<f64> = exact.iter().map(|x| x.to_f64().unwrap()).collect();
    assert_eq!(
        r.nearest_point.to_vec(),
        rounded,
        "query {q:?}: nearest point"
    );
    let offset: Vec<f64> = (0..D)
        .map(|c| (&exact[c] - rational(q[c])).to_f64().unwrap())
        .collect();
    let distance = length(&offset);
    if distance.is_infinite() || distance > f64::MAX {
        assert_eq!(r.signed_distance, f64::NEG_INFINITY, "query {q:?}");
    } else if distance == 0.0 {
        assert!(r.signed_distance >= 0.0, "query {q:?}");
    } else {
        assert!(
            (r.signed_distance + distance).abs() <= 1e-15 * distance,
            "query {q:?}: {} for −{distance}",
            r.signed_distance
        );
    }
    r.nearest_point
}

const SQUARE: [[f64; 2]; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];

fn cube() -> Vec<[f64; 3]> {
    (0..8)
        .map(|i| std::array::from_fn(|c| if i & (1 << c) != 0 { 1.0 } else { -1.0 }))
        .collect()
}

/// The standard 5-simplex: the origin and the unit vectors.
fn simplex5() -> Vec<[f64; 5]> {
    (0..6)
        .map(|i| std::array::from_fn(|c| if i == c + 1 { 1.0 } else { 0.0 }))
        .collect()
}

#[test]
fn square_far_queries() {
    for (q, expected) in [
        ([0.0, 1e170], [0.0, 1.0]),
        ([1e170, 0.0], [1.0, 0.0]),
        ([-1e300, 1e300], [-1.0, 1.0]),
        ([0.5e200, 1e200], [1.0, 1.0]),
        ([0.25, -1.7e308], [0.25, -1.0]),
        ([-1e155, 0.5], [-1.0, 0.5]),
        ([1.7e308, 1.7e308], [1.0, 1.0]),
        ([0.0, 1e100], [0.0, 1.0]),
        ([0.0, 3.0], [0.0, 1.0]),
    ] {
        assert_eq!(check(&SQUARE, q), expected, "query {q:?}");
    }
}

#[test]
fn cube_far_queries() {
    let cube = cube();
    for (q, expected) in [
        ([0.5, -0.25, 1e200], [0.5, -0.25, 1.0]),
        ([1e250, 1e250, 0.3], [1.0, 1.0, 0.3]),
        ([-1e160, 2e160, -3e160], [-1.0, 1.0, -1.0]),
        ([0.0, -1.7e308, 0.0], [0.0, -1.0, 0.0]),
    ] {
        assert_eq!(check(&cube, q), expected, "query {q:?}");
    }
}

#[test]
fn simplex_far_queries() {
    let simplex = simplex5();
    // Along (1, …, 1): the projection on the facet x₁ + … + x₅ = 1 is (0.2, …, 0.2) exactly, which
    // rounds to 0.2 in every coordinate.
    assert_eq!(check(&simplex, [1e200; 5]), [0.2; 5]);
    assert_eq!(check(&simplex, [-1e300; 5]), [0.0; 5]);
    assert_eq!(
        check(&simplex, [1e170, 1e170, 0.0, -1e170, 0.25]),
        [0.5, 0.5, 0.0, 0.0, 0.0]
    );
    check(&simplex, [1e200, 1e200, 1e200, -0.5, 0.5]);
    check(&simplex, [0.1, 0.3, -1.7e308, 1.7e308, 0.0]);
}

/// A random direction with magnitude 10^U(155, 308.23) (at most 1.7e308); with `mixed`, some
/// coordinates are instead small (in [−1.5, 1.5]) so that the query faces edges and facets, not
/// only vertices.
fn far_query<const D: usize>(rng: &mut Rng, mixed: bool) -> [f64; D] {
    let magnitude = 10f64.powf(rng.uniform_in(155.0, 308.23)).min(1.7e308);
    let direction = rng.unit_vector(D);
    let keep = rng.index(D);
    std::array::from_fn(|c| {
        if mixed && c != keep && rng.uniform() < 0.5 {
            rng.uniform_in(-1.5, 1.5)
        } else {
            direction[c] * magnitude
        }
    })
}

fn random_points<const D: usize>(rng: &mut Rng, n: usize) -> Vec<[f64; D]> {
    (0..n)
        .map(|_| std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0)))
        .collect()
}

#[test]
fn random_far_queries_match_the_brute_force() {
    let mut rng = Rng::new(20_250_170);
    let cube = cube();
    let simplex = simplex5();
    for case in 0..40 {
        let mixed = case % 2 == 1;
        check(&SQUARE, far_query(&mut rng, mixed));
        check(&cube, far_query(&mut rng, mixed));
        check(&simplex, far_query(&mut rng, mixed));
        if case % 4 == 0 {
            let points = random_points::<2>(&mut rng, 9);
            check(&points, far_query(&mut rng, mixed));
            let points = random_points::<4>(&mut rng, 9);
            check(&points, far_query(&mut rng, mixed));
        }
        if case % 8 == 0 {
            let points = random_points::<6>(&mut rng, 8);
            check(&points, far_query(&mut rng, mixed));
        }
    }
}

/// Inside and on the far side of a huge hull, and a tiny hull seen from very far.
#[test]
fn huge_and_tiny_hulls() {
    let huge = cube()
        .iter()
        .map(|p| p.map(|x| x * 1e300))
        .collect::<Vec<_>>();
    let (_, r) =
        Hull::try_with_strategy(&huge, ClosestToOrigin::towards([0.5e300, 0.0, 0.0])).unwrap();
    assert!((r.signed_distance - 0.5e300).abs() <= 1e-15 * 0.5e300);
    check(&huge, [1.7e308, 0.5e300, -0.25e300]);
    let tiny = cube()
        .iter()
        .map(|p| p.map(|x| x * 1e-100))
        .collect::<Vec<_>>();
    assert_eq!(check(&tiny, [0.0, 0.0, 1e300]), [0.0, 0.0, 1e-100]);
    check(&tiny, [1e250, -1e-101, 3e250]);
}

/// The brute force itself, on answers worked out by hand.
#[test]
fn brute_force_reference() {
    let to_f64 = |v: Vec<BigRational>| v.iter().map(|x| x.to_f64().unwrap()).collect::<Vec<_>>();
    assert_eq!(
        to_f64(brute_force(&SQUARE, &[3.0, 3.0], true)),
        vec![1.0, 1.0]
    );
    assert_eq!(
        to_f64(brute_force(&SQUARE, &[0.5, 7.0], true)),
        vec![0.5, 1.0]
    );
    assert_eq!(
        to_f64(brute_force(&SQUARE, &[0.5, 0.25], false)),
        vec![0.5, 0.25]
    );
}
