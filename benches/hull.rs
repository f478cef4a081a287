//! Criterion benchmarks, always side by side in one run (read the ratio, not the absolute time).
//!
//! * `full/<input>`: pqhull's full hull (`Hull::try_new`, strategy `FarthestPoint`) against
//!   Qhull (`qhull_facet_count`: Qhull's defaults plus `Qt`) — the Qhull half only with the cargo
//!   feature `qhull`.
//! * `partial/<input>`: `ClosestToOrigin` (partial hull, distance from the origin) against
//!   `FarthestPoint` (full hull) on the same input, plus Qhull users' way of getting the same
//!   number (full Qhull hull, min over facets of −offset) with the feature `qhull`.
//!
//! Inputs are fixed-seed `pqhull::rbox` families. Run with
//! `cargo bench --features qhull --bench hull` (or without the feature for pqhull only).

use criterion::{Criterion, criterion_group, criterion_main};
use pqhull::rbox::{Family, generate};
use pqhull::{ClosestToOrigin, FarthestPoint, Hull};
use std::hint::black_box;
use std::time::Duration;

/// Seed of every benchmark input.
const SEED: u64 = 20240601;

/// Small samples and short measurements: the whole run takes a few minutes on 2 cores.
fn configure() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(7))
}

/// One group per input: pqhull's full hull vs Qhull.
fn full<const D: usize>(c: &mut Criterion, family: Family, n: usize) {
    let points = generate::<D>(&family, n, SEED);
    let mut group = c.benchmark_group(format!("full/{family}-{D}d-{n}"));
    group.bench_function("pqhull FarthestPoint", |b| {
        b.iter(|| {
            let hull = Hull::try_new(black_box(&points)).expect("general-position input");
            black_box(hull.facet_count())
        })
    });
    #[cfg(feature = "qhull")]
    group.bench_function("qhull", |b| {
        b.iter(|| {
            pqhull::qhull_baseline::qhull_facet_count(black_box(&points))
                .expect("general-position input")
        })
    });
    group.finish();
}

/// One group per input: ClosestToOrigin (partial) vs FarthestPoint (full), same input.
fn partial<const D: usize>(c: &mut Criterion, family: Family, n: usize) {
    let points = generate::<D>(&family, n, SEED);
    let mut group = c.benchmark_group(format!("partial/{family}-{D}d-{n}"));
    group.bench_function("ClosestToOrigin", |b| {
        b.iter(|| {
            let (_, result) = Hull::try_with_strategy(black_box(&points), ClosestToOrigin::new())
                .expect("general-position input");
            black_box(result.signed_distance)
        })
    });
    group.bench_function("FarthestPoint", |b| {
        b.iter(|| {
            let (hull, ()) = Hull::try_with_strategy(black_box(&points), FarthestPoint::new())
                .expect("general-position input");
            black_box(hull.facet_count())
        })
    });
    #[cfg(feature = "qhull")]
    group.bench_function("qhull min facet distance", |b| {
        b.iter(|| {
            pqhull::qhull_baseline::qhull_origin_distance(black_box(&points))
                .expect("general-position input")
        })
    });
    group.finish();
}

fn full_hull(c: &mut Criterion) {
    full::<3>(c, Family::UniformCube, 100_000);
    full::<5>(c, Family::UniformCube, 5_000);
    full::<6>(c, Family::UniformCube, 2_000);
    full::<4>(c, Family::SphereSurface, 5_000);
}

fn partial_hull(c: &mut Criterion) {
    partial::<6>(c, Family::SphereSurface, 1_000);
    partial::<6>(c, Family::UniformCube, 2_000);
}

criterion_group! {
    name = benches;
    config = configure();
    targets = full_hull, partial_hull
}
criterion_main!(benches);
