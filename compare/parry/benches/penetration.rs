//! pqhull's `penetration_depth` against parry3d's `query::contact` (GJK, then EPA) on the same
//! pairs of 3-D convex bodies (issue 27): `cargo bench -p pqhull-parry-compare`.
//!
//! pqhull is timed on the raw points; parry on shapes built beforehand by
//! `ConvexPolyhedron::from_convex_hull` (the build is its own benchmark, `parry-f64 build`), with
//! identity poses and prediction 10 (so that separated pairs report their distance).

use criterion::{Criterion, criterion_group, criterion_main};
use pqhull::strategy::penetration_depth;
use pqhull_parry_compare::{Pair, Point, pairs};
use std::hint::black_box;
use std::time::Duration;

#[path = "../shared/parry_adapter.rs"]
mod parry_adapter;
use parry_adapter::{parry32, parry64};

/// A few pairs of the table: the spheres deep and separated at each size, the cube (corners
/// only and with face grids) deep, touching and with coplanar faces.
fn selected() -> Vec<Pair> {
    pairs()
        .into_iter()
        .filter(|p| {
            let sphere = p.family.starts_with("sphere");
            let cube = p.family.starts_with("cube");
            let config = p.config.as_str();
            (sphere && (config == "deep" || config.starts_with("separated")))
                || (cube
                    && (config == "deep"
                        || config == "touching"
                        || config == "coplanar faces, shift (0.5, 0, 0)"))
        })
        .collect()
}

fn penetration(c: &mut Criterion) {
    for pair in selected() {
        let name = format!("{}, {}", pair.family, pair.config);
        let mut group = c.benchmark_group(name);
        group
            .sample_size(20)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(1));
        let (a, b): (&[Point], &[Point]) = (&pair.a, &pair.b);
        group.bench_function("pqhull", |bench| {
            bench.iter(|| penetration_depth(black_box(a), black_box(b)).ok());
        });
        let hull = "parry builds the selected pairs' hulls";
        let (a64, b64) = (
            parry64::shape(a).expect(hull),
            parry64::shape(b).expect(hull),
        );
        group.bench_function("parry-f64 query", |bench| {
            bench.iter(|| parry64::depth(black_box(&a64), black_box(&b64)));
        });
        let (a32, b32) = (
            parry32::shape(a).expect(hull),
            parry32::shape(b).expect(hull),
        );
        group.bench_function("parry-f32 query", |bench| {
            bench.iter(|| parry32::depth(black_box(&a32), black_box(&b32)));
        });
        group.bench_function("parry-f64 build", |bench| {
            bench.iter(|| (parry64::shape(black_box(a)), parry64::shape(black_box(b))));
        });
        group.finish();
    }
}

criterion_group!(benches, penetration);
criterion_main!(benches);
