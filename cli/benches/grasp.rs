//! Criterion benchmarks of the grasp metrics, always side by side in one run (read the ratio, not
//! the absolute time).
//!
//! Every group evaluates one fixed set of random 4-contact grasps on a 1 × 0.4 × 0.2 bar
//! (`Grasp::random_on_box`, μ = 0.5, torque scale = half-diagonal, seed [`SEED`]: the grasps of
//! `pqh bench gws --seed 1`) by each method; criterion reports the time per set and, through the
//! element throughput, grasps per second.
//!
//! * `q1/k=8` (16 grasps), `q1/k=32` (the first 2 grasps: the full hull takes ~0.4 s per grasp
//!   there): Q1 by the partial hull (`Method::Partial`) against the full hull (`Method::Full`)
//!   and, with the cargo feature `qhull`, Qhull (`Method::Qhull`).
//! * `qinf/k=4` (the first 2 grasps): Q∞ by the partial hull over the implicit Minkowski sum
//!   against the full hull of the materialised sum (4⁴ = 256 points; 5⁴ = 625 with the zero
//!   wrench), for both variants: `plain`, and `zero-wrench` (GraspIt!'s: the zero wrench in every
//!   contact's set). Not at k = 8: the materialised sum there (4096 points, 6561 with the zero
//!   wrench) is so degenerate (many coplanar points) that the full hull takes 30–70 s per grasp.
//! * `qinf/k=8` (8 grasps), `qinf/k=32` (8 grasps; 32⁴ ≈ 10⁶ points): the partial hull only,
//!   both variants.
//! * `batch`: `evaluate_batch` (Q1, partial) of 64 grasps at k = 16 inside a rayon pool of 1 and
//!   of 2 threads (`threads=1`, `threads=2`; the pools are built outside the timing).
//!
//! * `gradient/k=8`, `gradient/k=32` (16 grasps each): Q1 by the partial hull alone, and with
//!   its exact gradient (`grasp::q1_gradient`) after it.
//!
//! Run with `cargo bench -p pqhull-cli --features qhull --bench grasp` (or without the feature for pqhull
//! only); about 4 minutes on 2 quiet cores. One group: `... --bench grasp -- '^batch/'`.

use criterion::{Criterion, SamplingMode, Throughput, criterion_group, criterion_main};
use pqhull::grasp::{Evaluator, FrictionModel, Grasp, Method, Metric, evaluate_batch, q1_gradient};
use pqhull_cli::bench::workloads::{BAR_FRICTION, bar_grasps};
use std::hint::black_box;
use std::time::Duration;

/// Seed of every grasp set (the default of `pqh bench gws`).
const SEED: u64 = 1;

/// Small samples and short measurements: the whole run takes a few minutes on 2 cores.
fn configure() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(4))
}

/// The first `count` random 4-contact grasps with `k` cone edges.
fn grasps(count: usize, k: usize) -> Vec<Grasp> {
    let friction = FrictionModel::try_new(BAR_FRICTION, k).expect("valid friction model");
    bar_grasps(SEED, count, 4, friction)
}

/// One group: every (label, metric, method) on the same grasp set, one evaluator each.
fn compare(
    c: &mut Criterion,
    group: &str,
    set: &[Grasp],
    runs: &[(&str, Metric, Method)],
    slow: bool,
) {
    let mut group = c.benchmark_group(group);
    group.throughput(Throughput::Elements(set.len() as u64));
    if slow {
        // A set takes ~1 s by the full hull: one iteration per sample, ten samples.
        group.sampling_mode(SamplingMode::Flat);
        group.measurement_time(Duration::from_secs(10));
    }
    for &(label, metric, method) in runs {
        let mut evaluator = Evaluator::new(metric, method, None).expect("a method of the metric");
        group.bench_function(label, |b| {
            b.iter(|| {
                for grasp in set {
                    let quality = evaluator.evaluate(black_box(grasp)).expect("evaluable");
                    black_box(quality.value);
                }
            })
        });
    }
    group.finish();
}

/// The Q1 methods: partial, full and (feature `qhull`) Qhull.
fn q1_methods() -> Vec<(&'static str, Metric, Method)> {
    vec![
        ("partial", Metric::Q1, Method::Partial),
        ("full", Metric::Q1, Method::Full),
        #[cfg(feature = "qhull")]
        ("qhull", Metric::Q1, Method::Qhull),
    ]
}

fn q1(c: &mut Criterion) {
    compare(c, "q1/k=8", &grasps(16, 8), &q1_methods(), false);
    compare(c, "q1/k=32", &grasps(2, 32), &q1_methods(), true);
}

fn qinf(c: &mut Criterion) {
    let plain = Metric::QInf {
        with_zero_wrench: false,
    };
    let zero = Metric::QInf {
        with_zero_wrench: true,
    };
    compare(
        c,
        "qinf/k=4",
        &grasps(2, 4),
        &[
            ("partial plain", plain, Method::Partial),
            ("full plain", plain, Method::Full),
            ("partial zero-wrench", zero, Method::Partial),
            ("full zero-wrench", zero, Method::Full),
        ],
        true,
    );
    compare(
        c,
        "qinf/k=8",
        &grasps(8, 8),
        &[
            ("partial plain", plain, Method::Partial),
            ("partial zero-wrench", zero, Method::Partial),
        ],
        false,
    );
    compare(
        c,
        "qinf/k=32",
        &grasps(8, 32),
        &[
            ("partial plain", plain, Method::Partial),
            ("partial zero-wrench", zero, Method::Partial),
        ],
        false,
    );
}

fn gradient(c: &mut Criterion) {
    for k in [8, 32] {
        let set = grasps(16, k);
        let mut group = c.benchmark_group(format!("gradient/k={k}"));
        group.throughput(Throughput::Elements(set.len() as u64));
        let mut evaluator =
            Evaluator::new(Metric::Q1, Method::Partial, None).expect("Q1 by the partial method");
        group.bench_function("value", |b| {
            b.iter(|| {
                for grasp in &set {
                    black_box(
                        evaluator
                            .evaluate(black_box(grasp))
                            .expect("evaluable")
                            .value,
                    );
                }
            })
        });
        group.bench_function("value+gradient", |b| {
            b.iter(|| {
                for grasp in &set {
                    let quality = evaluator.evaluate(black_box(grasp)).expect("evaluable");
                    black_box(q1_gradient(grasp, &quality).expect("its own Q1"));
                }
            })
        });
        group.finish();
    }
}

fn batch(c: &mut Criterion) {
    let set = grasps(64, 16);
    let mut group = c.benchmark_group("batch");
    group.throughput(Throughput::Elements(set.len() as u64));
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool");
        group.bench_function(format!("threads={threads}"), |b| {
            b.iter(|| {
                let results = pool.install(|| {
                    evaluate_batch(black_box(&set), Metric::Q1, Method::Partial, None)
                        .expect("Q1 by the partial method")
                });
                black_box(results.len())
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = configure();
    targets = q1, qinf, batch, gradient
}
criterion_main!(benches);
