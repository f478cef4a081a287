//! Property tests of the engine on seeded rbox-style families, D = 2…8:
//! the validator passes, the volume matches independent computations, and the partial
//! `ClosestToOrigin` answer equals the full hull's answer (inside: nearest facet plane; outside:
//! an independent minimum-norm-point computation).

use crate::support::min_norm::min_norm_point;
use crate::support::points_as_vecs;
use pqhull::rbox::{self, Family};
use pqhull::{ClosestToOrigin, Hull};
use proptest::prelude::*;

/// Cases per dimension; the default keeps the suite to a few minutes in release on 2 cores. Set
/// PROPTEST_CASES to run more.
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(24)
}

/// Cases in dimension `d`: a third of [`cases`] in 7-D and 8-D, where one case of a family whose
/// 30 points are all hull vertices (a sphere: tens of thousands of facets, built four times per
/// case) can take tens of seconds: the 8-D suite once ran over 5 minutes in CI at 24 cases.
fn cases_for(d: usize) -> u32 {
    if d >= 7 {
        (cases() / 3).max(1)
    } else {
        cases()
    }
}

/// Points per set: enough to be interesting, small enough for debug builds in high D.
fn size_for(d: usize) -> usize {
    match d {
        2 | 3 => 120,
        4 => 80,
        5 => 50,
        6 => 40,
        _ => 30,
    }
}

fn families() -> Vec<Family> {
    rbox::Family::ALL.to_vec()
}

/// Volume by the divergence theorem, facet areas from a QR factorisation of the edge vectors
/// (modified Gram–Schmidt, twice) — shares no code with `Hull::volume` (which sums cofactor cone
/// volumes). A Gram determinant would be simpler but loses accuracy on slivers (clusters).
fn divergence_volume<const D: usize>(hull: &Hull<D>) -> f64 {
    let mut total = 0.0;
    for (_, facet) in hull.facets() {
        let v = facet.vertices().map(|i| hull.point(i));
        let mut basis: Vec<[f64; D]> = Vec::new();
        let mut area = 1.0;
        for k in 1..D {
            let mut r: [f64; D] = std::array::from_fn(|c| v[k][c] - v[0][c]);
            for _ in 0..2 {
                for b in &basis {
                    let p: f64 = b.iter().zip(&r).map(|(x, y)| x * y).sum();
                    for (x, y) in r.iter_mut().zip(b) {
                        *x -= p * y;
                    }
                }
            }
            let norm = r.iter().map(|x| x * x).sum::<f64>().sqrt();
            area *= norm;
            if norm > 0.0 {
                basis.push(r.map(|x| x / norm));
            }
        }
        let factorial: f64 = (1..D).map(|k| k as f64).product();
        // Height of the facet's plane above the origin, from its own vertex.
        let height: f64 = facet.normal().iter().zip(&v[0]).map(|(n, x)| n * x).sum();
        total += area / factorial * height / D as f64;
    }
    total
}

/// Andrew's monotone chain (`monotone_chain.rs`) + shoelace: an independent 2-D hull area.
fn monotone_chain_area(points: &[[f64; 2]]) -> f64 {
    let hull = super::monotone_chain::monotone_chain(points);
    let n = hull.len();
    (0..n)
        .map(|i| {
            let (a, b) = (points[hull[i]], points[hull[(i + 1) % n]]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum::<f64>()
        / 2.0
}

/// The full hull's answer for query `q`: nearest facet plane when inside (decided exactly),
/// minus the minimum-norm-point distance (Wolfe, on the raw points) when outside.
fn full_answer<const D: usize>(full: &Hull<D>, points: &[[f64; D]], q: &[f64; D]) -> f64 {
    let inside = full
        .facets()
        .all(|(id, _)| full.side_of(id, q) != pqhull::predicates::Sign::Positive);
    if inside {
        full.facets()
            .map(|(_, f)| -f.signed_distance(q))
            .fold(f64::INFINITY, f64::min)
    } else {
        let (_, d) = min_norm_point(&points_as_vecs(points), q);
        -d
    }
}

fn extent<const D: usize>(points: &[[f64; D]]) -> f64 {
    points
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()))
}

fn check_case<const D: usize>(family: &Family, seed: u64) -> Result<(), TestCaseError> {
    let points = rbox::generate::<D>(family, size_for(D), seed);
    let full = Hull::try_new(&points)
        .map_err(|e| TestCaseError::fail(format!("{family:?} seed {seed}: {e}")))?;
    full.check()
        .map_err(|e| TestCaseError::fail(format!("{family:?} seed {seed}: {e}")))?;
    prop_assert!(!full.has_outside_points());

    let volume = full.volume();
    let scale = extent(&points).powi(D as i32);
    let divergence = divergence_volume(&full);
    prop_assert!(
        (volume - divergence).abs() <= 1e-9 * scale,
        "{family:?} seed {seed}: volume {volume} vs divergence-theorem volume {divergence}"
    );
    if D == 2 {
        let flat: Vec<[f64; 2]> = points.iter().map(|p| [p[0], p[1]]).collect();
        let chain = monotone_chain_area(&flat);
        prop_assert!(
            (volume - chain).abs() <= 1e-12 * scale,
            "area {volume} vs monotone chain {chain}"
        );
    }

    // Queries: the origin, an interior point, a point outside.
    let vertices = full.vertex_indices();
    let a = points[vertices[seed as usize % vertices.len()]];
    let b = points[vertices[(seed as usize / 7) % vertices.len()]];
    let centroid: [f64; D] = std::array::from_fn(|c| {
        vertices.iter().map(|&v| points[v][c]).sum::<f64>() / vertices.len() as f64
    });
    let inner: [f64; D] = std::array::from_fn(|c| 0.5 * centroid[c] + 0.25 * (a[c] + b[c]));
    let outer: [f64; D] = std::array::from_fn(|c| 2.5 * a[c] - 1.5 * centroid[c]);
    let tolerance = 1e-9 * extent(&points).max(1e-300);
    for q in [[0.0; D], inner, outer] {
        let (partial, result) = Hull::try_with_strategy(&points, ClosestToOrigin::towards(q))
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        partial
            .check()
            .map_err(|e| TestCaseError::fail(format!("partial hull: {e}")))?;
        let expected = full_answer(&full, &points, &q);
        prop_assert!(
            (result.signed_distance - expected).abs() <= tolerance,
            "{family:?} seed {seed} D={D} q={q:?}: partial {} vs full {expected}",
            result.signed_distance
        );
    }
    Ok(())
}

macro_rules! dimension_suite {
    ($($(#[$attr:meta])* $name:ident => $d:literal),*) => {$(
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(cases_for($d)))]
            #[test]
            $(#[$attr])*
            fn $name(seed in any::<u64>(), which in 0usize..64) {
                let families = families();
                let family = &families[which % families.len()];
                check_case::<$d>(family, seed)?;
            }
        }
    )*};
}

dimension_suite!(
    invariants_2d => 2,
    invariants_3d => 3,
    invariants_4d => 4,
    invariants_5d => 5,
    invariants_6d => 6,
    invariants_7d => 7,
    #[ignore = "extended (about 100 s): --run-ignored all runs it, as CI does"]
    invariants_8d => 8
);

/// Every family in every dimension at least once, with a fixed seed (proptest samples randomly).
#[test]
#[ignore = "extended (about 60 s): --run-ignored all runs it, as CI does"]
fn every_family_every_dimension() {
    fn run<const D: usize>() {
        for family in families() {
            check_case::<D>(&family, 0x5eed).unwrap_or_else(|e| panic!("D={D} {family:?}: {e}"));
        }
    }
    run::<2>();
    run::<3>();
    run::<4>();
    run::<5>();
    run::<6>();
    run::<7>();
    run::<8>();
}
