//! Criterion benchmarks, always side by side in one run (read the ratio, not the absolute time).
//!
//! * `full/<input>`: pqhull's full hull (`Hull::try_new`, strategy `FarthestPoint`) against
//!   Qhull (`qhull_facet_count`: Qhull's defaults plus `Qt`) — the Qhull half only with the cargo
//!   feature `qhull`.
//! * `partial/<input>`: `ClosestToOrigin` (partial hull, distance from the origin) against
//!   `FarthestPoint` (full hull) on the same input, plus Qhull users' way of getting the same
//!   number (full Qhull hull, min over facets of −offset) with the feature `qhull`.
//!
//! * `full/grid-6d-m4`, `full/corners-6d-2000`, `full/wrenches-4x16`: the hot paths of
//!   `pqh bench hull` — the integer grid {0..3}^6, `CubeCornersDiamond` in 6-D, and the raw
//!   wrenches of a force-closure 4-contact, 16-edge bar grasp — pqhull vs Qhull as above.
//!
//! Inputs are fixed-seed `pqhull::rbox` families (and `pqhull_cli::bench::hull`'s grid and grasp).
//! Run with
//! `cargo bench -p pqhull-cli --features qhull --bench hull` (or without the feature for pqhull only).

use criterion::{Criterion, criterion_group, criterion_main};
use pqhull::grasp::FrictionModel;
use pqhull::grasp::quality::q1;
use pqhull::rbox::{Family, generate};
use pqhull::strategy::distances_to_boundary;
use pqhull::{ClosestToOrigin, FarthestPoint, Hull};
use pqhull_cli::bench::hull::grid;
use pqhull_cli::bench::workloads::{BAR_FRICTION, bar_grasps};
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
    full_of(c, &format!("full/{family}-{D}d-{n}"), &points, None);
}

/// The group `name`: pqhull's full hull of `points` vs Qhull's, measured for `measurement`
/// (the configured time when `None`).
fn full_of<const D: usize>(
    c: &mut Criterion,
    name: &str,
    points: &[[f64; D]],
    measurement: Option<Duration>,
) {
    let mut group = c.benchmark_group(name);
    if let Some(time) = measurement {
        group.measurement_time(time);
    }
    group.bench_function("pqhull FarthestPoint", |b| {
        b.iter(|| {
            let hull = Hull::try_new(black_box(points)).expect("full-dimensional input");
            black_box(hull.facet_count())
        })
    });
    #[cfg(feature = "qhull")]
    group.bench_function("qhull", |b| {
        b.iter(|| {
            pqhull::qhull_baseline::qhull_facet_count(black_box(points))
                .expect("full-dimensional input")
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

/// The hull suite's hot paths (`pqh bench hull`): a grid, cube corners, a raw wrench set, with
/// shorter measurements (3 s each) to keep the file cheap.
fn suite_hull(c: &mut Criterion) {
    let short = Some(Duration::from_secs(3));
    full_of(c, "full/grid-6d-m4", &grid::<6>(4), short);
    let corners = generate::<6>(&Family::CubeCornersDiamond, 2_000, SEED);
    full_of(c, "full/corners-6d-2000", &corners, short);
    let friction = FrictionModel::try_new(BAR_FRICTION, 16).expect("16 cone edges");
    let grasp = bar_grasps(SEED, 100, 4, friction)
        .into_iter()
        .find(|g| q1(g).is_ok_and(|q| q.force_closure))
        .expect("a force-closure grasp among 100");
    full_of(c, "full/wrenches-4x16", &grasp.wrenches(), short);
}

fn partial_hull(c: &mut Criterion) {
    partial::<6>(c, Family::SphereSurface, 1_000);
    partial::<6>(c, Family::UniformCube, 2_000);
}

/// Incremental hulls: 1 % more points added to a built hull (`Hull::add_points`) against the
/// hull of all the points built afresh, side by side.
fn incremental_hull(c: &mut Criterion) {
    fn grow<const D: usize>(c: &mut Criterion, family: Family, n: usize) {
        let points = generate::<D>(&family, n + n / 100, SEED);
        let (old, new) = points.split_at(n);
        let built = Hull::try_new(old).expect("general-position input");
        let mut group = c.benchmark_group(format!("incremental/{family}-{D}d-{n}+1%"));
        group.bench_function("add_points", |b| {
            b.iter_batched(
                || built.clone(),
                |mut hull| hull.add_points(new).expect("finite points"),
                criterion::BatchSize::LargeInput,
            )
        });
        group.bench_function("rebuild", |b| {
            b.iter(|| Hull::try_new(&points).expect("general-position input"))
        });
        group.finish();
    }
    grow::<3>(c, Family::UniformCube, 100_000);
    grow::<3>(c, Family::SphereSurface, 20_000);
    grow::<5>(c, Family::UniformCube, 5_000);
}

/// Many distance queries against one point set: one partial hull shared by every query
/// (`strategy::distances_to_boundary`), a partial hull per query, and the full hull built once
/// and then asked every query.
fn many_queries(c: &mut Criterion) {
    fn queries<const D: usize>(c: &mut Criterion, family: Family, n: usize, count: usize) {
        let points = generate::<D>(&family, n, SEED);
        let queries = generate::<D>(&Family::UniformCube, count, SEED + 1);
        let mut group = c.benchmark_group(format!("queries/{family}-{D}d-{n}/{count}"));
        group.bench_function("one shared partial hull", |b| {
            b.iter(|| distances_to_boundary(&points, &queries).expect("valid input"))
        });
        group.bench_function("a partial hull per query", |b| {
            b.iter(|| {
                for &q in &queries {
                    black_box(
                        Hull::try_with_strategy(&points, ClosestToOrigin::towards(q))
                            .expect("valid input"),
                    );
                }
            })
        });
        group.bench_function("full hull, then every query", |b| {
            b.iter(|| {
                let mut hull = Hull::try_new(&points).expect("valid input");
                for &q in &queries {
                    black_box(
                        hull.resume_with_strategy(ClosestToOrigin::towards(q))
                            .expect("a hull"),
                    );
                }
            })
        });
        group.finish();
    }
    queries::<3>(c, Family::UniformCube, 20_000, 500);
    queries::<5>(c, Family::UniformCube, 2_000, 500);
    queries::<6>(c, Family::SphereSurface, 1_000, 100);
}

criterion_group! {
    name = benches;
    config = configure();
    targets = full_hull, suite_hull, partial_hull, incremental_hull, many_queries
}
criterion_main!(benches);
