//! The suite's raw Minkowski sum (`pqh bench hull`'s `minkowski-3xK/hull` row) hulled as it is
//! and with every coordinate moved by a uniform random amount of at most ε times the largest
//! coordinate, for ε from 1e−14 to 1e−3: pqhull's exact hull beside Qhull's (with
//! `--features qhull`), each the best of the same rounds, with both engines' final and created
//! facets and, untimed, how many of Qhull's facets are wrong: not facets of the exact hull (an
//! input point strictly beyond, or a flat simplex through the centroid; exact orientation:
//! `pqhull_cli::bench::perturb`).
//!
//! What it measures: how much of each engine's time on the raw sum is the size of the answer
//! and how much the precision of its decisions. A perturbed sum has an exact hull of about the
//! same size (each contact's wrench set is still a nearly planar polygon, so each facet of the
//! ideal sum is still covered by thousands of slivers), but at ε well above rounding its
//! decisions are ones the `f64` filter makes and Qhull's answer needs no merging; near rounding
//! Qhull's merges may fail (its error is printed). docs/benchmarks.md, "Issue 24: the raw sums
//! perturbed".
//!
//! ```sh
//! cargo build --release -p pqhull-cli --features qhull --example perturbed_sum
//! ./target/release/examples/perturbed_sum 6 3
//! ./target/release/examples/perturbed_sum 8 3
//! ```
//!
//! Arguments: cone edges (6), rounds (3), optionally one ε (a number such as `1e-8`) to run
//! that scale alone (for a profiler), and then the perturbation's seed (7). The grasp is the
//! suite's (seed 1); with the same seed, every run hulls the same points.

use pqhull::Hull;
use pqhull_cli::bench::hull::grasp_points;
use pqhull_cli::bench::perturb::perturbed;
use pqhull_cli::bench::stats::{best_of, numeric_args};

/// The relative perturbations, 0 (the raw sum itself) first.
const SCALES: [f64; 11] = [
    0.0, 1e-14, 1e-12, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3,
];

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: perturbed_sum [edges] [rounds] [eps] [seed]";
    let [edges, rounds] = numeric_args(&args[..args.len().min(2)], 0, [6, 3]).unwrap_or_else(|e| {
        eprintln!("{usage}: {e}");
        std::process::exit(2);
    });
    let scales: Vec<f64> = match args.get(2).map(|a| a.parse::<f64>()) {
        None => SCALES.to_vec(),
        Some(Ok(eps)) if (0.0..=1.0).contains(&eps) => vec![eps],
        Some(_) => {
            eprintln!("{usage}: eps must be a number from 0 to 1, got {}", args[2]);
            std::process::exit(2);
        }
    };
    // The perturbation's seed (7 unless a fourth argument names another).
    let seed = match args.get(3).map(|a| a.parse::<u64>()) {
        None => 7,
        Some(Ok(seed)) => seed,
        Some(Err(_)) => {
            eprintln!("{usage}: seed must be a whole number, got {}", args[3]);
            std::process::exit(2);
        }
    };
    if !(3..=64).contains(&edges) {
        eprintln!("{usage}: edges must be 3 to 64, got {edges}");
        std::process::exit(2);
    }
    let (_, _, raw) = grasp_points(1, 3, edges, true);
    println!(
        "raw Minkowski sum 3x{edges} ({} points), best of {rounds}; us/created = time per created facet",
        raw.len()
    );
    println!(
        "{:>8} {:>10} {:>7} {:>8} {:>6} {:>10} {:>7} {:>8} {:>6} {:>6} {:>7}",
        "eps",
        "pqhull ms",
        "facets",
        "created",
        "us/cr",
        "qhull ms",
        "facets",
        "created",
        "us/cr",
        "q/pq",
        "wrong"
    );
    for eps in scales {
        let points = perturbed(&raw, eps, seed);
        let mut built = None;
        let elapsed = best_of(rounds, || built = Some(Hull::try_new(&points)));
        let ms = elapsed.as_secs_f64() * 1e3;
        let hull = match built.expect("at least one round") {
            Ok(hull) => hull,
            Err(e) => {
                println!("{eps:>8.0e} pqhull error: {e}");
                continue;
            }
        };
        let created = hull.stats().facets_created;
        print!(
            "{eps:>8.0e} {ms:>10.1} {:>7} {created:>8} {:>6.2}",
            hull.facet_count(),
            ms * 1e3 / created as f64
        );
        qhull_columns(&points, rounds, ms);
    }
}

/// Qhull's columns of one row: its time, final and created facets, and the ratio of its time
/// to pqhull's `pqhull_ms`; or its error, shortened to its first line.
#[cfg(feature = "qhull")]
fn qhull_columns(points: &[[f64; 6]], rounds: usize, pqhull_ms: f64) {
    use pqhull::qhull_baseline::qhull_stats;
    use pqhull_cli::bench::stats::first_line;
    let mut run = None;
    let elapsed = best_of(rounds, || run = Some(qhull_stats(points)));
    let ms = elapsed.as_secs_f64() * 1e3;
    match run.expect("at least one round") {
        Ok(q) => println!(
            " {ms:>10.1} {:>7} {:>8} {:>6.2} {:>6.2} {:>7}",
            q.facets,
            q.facets_created,
            ms * 1e3 / q.facets_created.max(1) as f64,
            ms / pqhull_ms,
            // Untimed, on a second run of Qhull.
            pqhull_cli::bench::perturb::qhull_wrong_facets(points)
                .map_or_else(|_| "-".to_string(), |(wrong, _)| wrong.to_string())
        ),
        Err(e) => println!("  qhull fails: {}", first_line(&e.to_string(), 90)),
    }
}

#[cfg(not(feature = "qhull"))]
fn qhull_columns(_: &[[f64; 6]], _: usize, _: f64) {
    println!("  (Qhull: build with --features qhull)");
}
