//! pqhull against Qhull, and the partial hull against the full one, in one table.
//!
//! ```text
//! cargo run --release --features qhull --example compare_qhull [runs]
//! ```
//!
//! For each input (fixed-seed `pqhull::rbox` families, the same as `benches/hull.rs`) it reports
//! the median wall time of `runs` runs (default 5) measured side by side, the ratio, and the work
//! counters: facets created by pqhull and (approximately, from Qhull's sequential facet ids) by
//! Qhull; points processed and facets created by `ClosestToOrigin` and `FarthestPoint`.
//! `docs/benchmarks.md` quotes its output.

use pqhull::qhull_baseline::{qhull_facet_count, qhull_origin_distance, qhull_stats};
use pqhull::rbox::{Family, generate};
use pqhull::{ClosestToOrigin, FarthestPoint, Hull, Stats};
use std::time::{Duration, Instant};

/// Seed of every input (the same as the criterion benches).
const SEED: u64 = 20240601;

/// Median wall time of `runs` calls of `f`, and the last call's value. The contenders of one row
/// run one after the other, seconds apart, so machine noise affects them alike.
fn median_time<T>(runs: usize, mut f: impl FnMut() -> T) -> (Duration, T) {
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs {
        let start = Instant::now();
        let value = f();
        times.push(start.elapsed());
        last = Some(value);
    }
    times.sort();
    (times[times.len() / 2], last.expect("runs >= 1"))
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn full_row<const D: usize>(family: Family, n: usize, runs: usize) {
    let points = generate::<D>(&family, n, SEED);
    let (t_pq, stats) = median_time(runs, || {
        let hull = Hull::try_new(&points).expect("general-position input");
        (
            hull.stats(),
            hull.facet_count(),
            hull.vertex_indices().len(),
        )
    });
    let (t_qh, _) = median_time(runs, || qhull_facet_count(&points).expect("Qhull"));
    let qh = qhull_stats(&points).expect("Qhull");
    let (pq_stats, pq_facets, pq_vertices): (Stats, usize, usize) = stats;
    println!(
        "| {family}-{D}d-{n} | {:.1} | {:.1} | {:.2} | {} / {} | {} / {} | {} / {} |",
        ms(t_pq),
        ms(t_qh),
        t_pq.as_secs_f64() / t_qh.as_secs_f64(),
        pq_vertices,
        qh.vertices,
        pq_facets,
        qh.facets,
        pq_stats.facets_created,
        qh.facets_created,
    );
}

fn partial_row<const D: usize>(family: Family, n: usize, runs: usize) {
    let points = generate::<D>(&family, n, SEED);
    let (t_partial, result) = median_time(runs, || {
        Hull::try_with_strategy(&points, ClosestToOrigin::new())
            .expect("general-position input")
            .1
    });
    let (t_full, full) = median_time(runs, || {
        Hull::try_with_strategy(&points, FarthestPoint::new())
            .expect("general-position input")
            .0
            .stats()
    });
    let (t_qh, qh_distance) = median_time(runs, || qhull_origin_distance(&points).expect("Qhull"));
    let s = result.stats;
    println!(
        "| {family}-{D}d-{n} | {:.2} | {:.1} | {:.1}x | {} / {} | {} / {} | {:.1} | {:.6} | {:.6} |",
        ms(t_partial),
        ms(t_full),
        t_full.as_secs_f64() / t_partial.as_secs_f64(),
        s.points_processed,
        full.points_processed,
        s.facets_created,
        full.facets_created,
        ms(t_qh),
        result.signed_distance,
        qh_distance,
    );
}

fn main() {
    let runs: usize = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("runs: a positive integer"))
        .unwrap_or(5)
        .max(1);
    println!(
        "Full hull: pqhull (FarthestPoint, exact) vs Qhull (defaults + Qt); median of {runs} runs, ms."
    );
    println!();
    println!(
        "| input | pqhull ms | Qhull ms | pqhull/Qhull | vertices pq / Qh | facets pq / Qh | facets created pq / Qh (≈) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    full_row::<3>(Family::UniformCube, 100_000, runs);
    full_row::<5>(Family::UniformCube, 5_000, runs);
    full_row::<6>(Family::UniformCube, 2_000, runs);
    full_row::<4>(Family::SphereSurface, 5_000, runs);
    println!();
    println!(
        "Distance from the origin: ClosestToOrigin (partial) vs FarthestPoint (full); median of {runs} runs."
    );
    println!();
    println!(
        "| input | ClosestToOrigin ms | FarthestPoint ms | speed-up | points processed C / F | facets created C / F | Qhull min-facet ms | pqhull distance | Qhull distance |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    partial_row::<6>(Family::SphereSurface, 1_000, runs);
    partial_row::<6>(Family::UniformCube, 2_000, runs);
}
