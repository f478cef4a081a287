//! A profiling target: one of `pqh bench hull`'s grasp rows alone, run over and over, so that
//! `perf record` sees only that call (the bench also runs Qhull and, untimed, `Hull::check`).
//!
//! ```sh
//! cargo build --release -p pqhull-cli --example profile_hull
//! perf record -e cpu-clock -g ./target/release/examples/profile_hull minkowski-hull 8 5
//! perf report --no-children
//! ```
//!
//! Arguments: the row (`wrenches-hull`, `wrenches-volume`: 4 contacts; `minkowski-hull`,
//! `minkowski-qinf`: the materialised sum of 3 contacts, Q∞ by the full method;
//! `wrenches-census`, `minkowski-census`: the hull's rows, then, untimed, the exact census of
//! its ridges, `pqhull_cli::bench::census`), cone edges (8), rounds (5). The grasp is the suite's (`pqhull_cli::bench::hull::grasp_for`, seed 1). Prints
//! the best and mean time per call, then on standard error the last run's work: the hull's
//! `Stats` (facets created, points processed) and final facets, or the evaluation's `Stats`;
//! built with `--features qhull`, Qhull's final and created facets on the same points too.

use pqhull::grasp::metrics::gws_volume;
use pqhull::grasp::{Evaluator, Method, Metric};
use pqhull::hull::Hull;
use pqhull_cli::bench::census;
use pqhull_cli::bench::hull::grasp_points;
use pqhull_cli::bench::stats::numeric_args;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: profile_hull wrenches-hull|wrenches-volume|wrenches-census|\
                 minkowski-hull|minkowski-qinf|minkowski-census [edges] [rounds]";
    let row = args.first().map(String::as_str).unwrap_or("");
    let [edges, rounds] = numeric_args(&args, 1, [8, 5]).unwrap_or_else(|e| {
        eprintln!("{usage}: {e}");
        std::process::exit(2);
    });
    let rounds = rounds.max(1);
    let (contacts, full_sum) = match row {
        "wrenches-hull" | "wrenches-volume" | "wrenches-census" => (4, false),
        "minkowski-hull" | "minkowski-qinf" | "minkowski-census" => (3, true),
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    };
    let (grasp, _, points) = grasp_points(1, contacts, edges, full_sum);
    let mut evaluator = Evaluator::new(
        Metric::QInf {
            with_zero_wrench: false,
        },
        Method::Full,
        None,
    )
    .expect("Q∞ by the full method");
    // The work of the last run, printed after the loop so that no printing is timed.
    let (mut best, mut total, mut work) = (f64::INFINITY, 0.0, String::new());
    let mut hull = None;
    for _ in 0..rounds {
        let started = Instant::now();
        work = match row {
            "wrenches-hull" | "minkowski-hull" | "wrenches-census" | "minkowski-census" => {
                match Hull::try_new(&points) {
                    Ok(h) => {
                        let work =
                            format!("{:?}, {} facets in the end", h.stats(), h.facet_count());
                        hull = Some(h);
                        work
                    }
                    Err(e) => e.to_string(),
                }
            }
            "wrenches-volume" => match gws_volume(&grasp) {
                Ok(v) => format!("volume {v:e}"),
                Err(e) => e.to_string(),
            },
            _ => match evaluator.evaluate(&grasp) {
                Ok(q) => format!("{:?}, value {:?}", q.stats, q.value),
                Err(e) => e.to_string(),
            },
        };
        let ms = started.elapsed().as_secs_f64() * 1e3;
        best = best.min(ms);
        total += ms;
    }
    println!(
        "{row} {contacts}x{edges} ({} points): best {best:.3} ms, mean {:.3} ms over {rounds}",
        points.len(),
        total / rounds as f64
    );
    eprintln!("{work}");
    if let (true, Some(hull)) = (row.ends_with("census"), &hull) {
        let c = census::ridge_census(hull);
        println!(
            "ridges {}: exactly flat {}, ratio below 2^-106 {}, in [2^-106, 2^-53) {}, at least \
             2^-53 {}; facets with a ridge below 2^-53 {} of {}; smallest ratio 2^{}",
            c.ridges,
            c.zero,
            c.below_double_double,
            c.below_double,
            c.above_double,
            c.facets_beyond_double,
            hull.facet_count(),
            c.smallest_log2
        );
        // Best of the rounds, each from cold caches.
        let check = (0..rounds)
            .map(|_| census::check_ridges(hull))
            .min_by_key(|c| c.elapsed)
            .expect("at least one round");
        println!(
            "checking every ridge with pqhull's predicates: {:.3} ms for {} tests, {} facets not \
             locally convex",
            check.elapsed.as_secs_f64() * 1e3,
            check.tests,
            check.not_convex
        );
        // Qhull's whole hull of the same points, timed the same way (with `--features qhull`).
        #[cfg(feature = "qhull")]
        {
            let qhull = (0..rounds)
                .map(|_| {
                    let started = Instant::now();
                    let facets = pqhull::qhull_baseline::qhull_facet_count(&points);
                    (started.elapsed(), facets)
                })
                .min_by_key(|r| r.0)
                .expect("at least one round");
            println!(
                "qhull_facet_count (Qhull's hull, as pqh bench hull times it): {:.3} ms, {:?} facets",
                qhull.0.as_secs_f64() * 1e3,
                qhull.1
            );
        }
    }
    // Qhull's counts on the same points (built with `--features qhull`), untimed: its final
    // (triangulated) facets and how many it created, against pqhull's above.
    #[cfg(feature = "qhull")]
    match pqhull::qhull_baseline::qhull_stats(&points) {
        Ok(q) => eprintln!(
            "qhull: {} facets in the end, about {} created, {} vertices",
            q.facets, q.facets_created, q.vertices
        ),
        Err(e) => eprintln!("qhull: {e}"),
    }
}
