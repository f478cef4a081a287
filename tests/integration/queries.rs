//! Many distance queries from one partial hull (`strategy::distances_to_boundary`,
//! `BoundaryDistances`): each answer against the same query answered from scratch, the exact
//! side from the full hull's exact predicates, and, outside, exact rational Wolfe.

use crate::support::min_norm::exact_min_norm_distance;
use crate::support::points_as_vecs;
use pqhull::geometry::Rng;
use pqhull::predicates::Sign;
use pqhull::rbox::{Family, generate};
use pqhull::strategy::{BoundaryDistances, QueryError, distances_to_boundary};
use pqhull::{ClosestToOrigin, Hull, HullError};

fn queries_against_references<const D: usize>(family: Family, n: usize, seed: u64) {
    let points = generate::<D>(&family, n, seed);
    let full = Hull::try_new(&points).unwrap();
    let scale = points
        .iter()
        .map(|p| p.iter().map(|x| x * x).sum::<f64>().sqrt())
        .fold(0.0, f64::max);
    let mut rng = Rng::new(seed);
    // Inside, outside (up to twice the set's size away) and on the boundary (vertices).
    let mut queries: Vec<[f64; D]> = (0..60)
        .map(|_| std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0) * scale))
        .collect();
    queries.extend(full.vertex_indices().iter().take(5).map(|&v| points[v]));
    let answers = distances_to_boundary(&points, &queries).unwrap();
    for (q, got) in queries.iter().zip(&answers) {
        let what = format!("{family:?} D={D} seed {seed}, query {q:?}");
        let beyond = full
            .facets()
            .any(|(id, _)| full.side_of(id, q) == Sign::Positive);
        let on = !beyond
            && full
                .facets()
                .any(|(id, _)| full.side_of(id, q) == Sign::Zero);
        let d = got.signed_distance;
        assert_eq!(d < 0.0, beyond, "{what}: sign of {d:e}");
        assert_eq!(d == 0.0, on, "{what}: {d:e} on the boundary");
        let (_, fresh) = Hull::try_with_strategy(&points, ClosestToOrigin::towards(*q)).unwrap();
        assert!(
            (d - fresh.signed_distance).abs() <= 1e-12 * scale,
            "{what}: {d:e} against {:e} from scratch",
            fresh.signed_distance
        );
        if beyond {
            let exact = exact_min_norm_distance(&points_as_vecs(&points), q);
            assert!(
                (-d - exact).abs() <= 1e-12 * exact.max(1e-3 * scale),
                "{what}: {d:e}, exact {exact:e}"
            );
        }
    }
}

#[test]
fn every_answer_is_the_answer_from_scratch() {
    for seed in 1..=2 {
        queries_against_references::<2>(Family::UniformCube, 300, seed);
        queries_against_references::<3>(Family::SphereSurface, 300, seed);
        queries_against_references::<4>(Family::UniformCube, 400, seed);
        queries_against_references::<5>(Family::CubeCornersDiamond, 100, seed);
        queries_against_references::<6>(Family::UniformCube, 200, seed);
    }
}

/// The hull the queries leave is a valid partial hull, and it only grows.
#[test]
fn the_shared_hull_only_grows_and_stays_valid() {
    let points = generate::<3>(&Family::UniformCube, 2000, 5);
    let mut distances = BoundaryDistances::new(&points).unwrap();
    let mut processed = distances.hull().stats().points_processed;
    for q in [[0.0; 3], [0.6, 0.0, 0.0], [0.0, -0.49, 0.1], [0.0; 3]] {
        distances.distance(q).unwrap();
        let now = distances.hull().stats().points_processed;
        assert!(now >= processed);
        processed = now;
        distances.hull().check().unwrap();
    }
    // The repeated first query adds nothing.
    let before = distances.hull().stats().points_processed;
    distances.distance([0.0; 3]).unwrap();
    assert_eq!(distances.hull().stats().points_processed, before);
}

#[test]
fn bad_queries_and_points_are_typed_errors() {
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    assert_eq!(
        distances_to_boundary(&square, &[[0.5, 0.5], [f64::INFINITY, 0.0]]).unwrap_err(),
        QueryError::NonFiniteQuery {
            index: 1,
            coordinate: 0
        }
    );
    let line = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
    assert!(matches!(
        distances_to_boundary(&line, &[[0.0, 0.0]]),
        Err(QueryError::Hull(HullError::AffinelyDependent { .. }))
    ));
    let error = BoundaryDistances::new(&square)
        .unwrap()
        .distance([f64::NAN, 0.0])
        .unwrap_err();
    assert!(error.to_string().contains("NaN or infinite"), "{error}");
}
