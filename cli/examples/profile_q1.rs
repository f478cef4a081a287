//! A profiling target: Q1 by the partial method on `pqh bench gws`'s random grasps, force-closure
//! or not, evaluated over and over with one reused evaluator, so that `perf record` sees only the
//! kind of grasp asked for.
//!
//! ```sh
//! cargo build --release -p pqhull-cli --example profile_q1
//! perf record -e cpu-clock -g ./target/release/examples/profile_q1 force-closure 32 200 30
//! perf report --no-children
//! ```
//!
//! Arguments: `force-closure` or `other`, cone edges (32), grasps (200), rounds (30), object
//! (`bar` or `ellipsoid`, as `pqh bench gws --object`; default `bar`). Prints the mean time per
//! grasp and the work counters.

use pqhull::grasp::{Evaluator, FrictionModel, Grasp, Method, Metric};
use pqhull_cli::bench::stats::numeric_args;
use pqhull_cli::bench::workloads::{GwsObject, object_grasps};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: profile_q1 force-closure|other [edges] [grasps] [rounds] [bar|ellipsoid]";
    let want_closure = match args.first().map(String::as_str) {
        Some("force-closure") => true,
        Some("other") => false,
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    };
    let [edges, count, rounds] = numeric_args(&args, 1, [32, 200, 30]).unwrap_or_else(|e| {
        eprintln!("{usage}: {e}");
        std::process::exit(2);
    });
    let friction = FrictionModel::try_new(0.5, edges).unwrap_or_else(|e| {
        eprintln!("{usage}: {e}");
        std::process::exit(2);
    });
    let object = match args.get(4).map(String::as_str) {
        None | Some("bar") => GwsObject::Bar,
        Some("ellipsoid") => GwsObject::Ellipsoid,
        Some(other) => {
            eprintln!("{usage}: not an object: {other}");
            std::process::exit(2);
        }
    };
    // The grasps of `pqh bench gws` (seed 1).
    let grasps: Vec<Grasp> = object_grasps(object, 1, count, 4, friction);
    let mut evaluator =
        Evaluator::new(Metric::Q1, Method::Partial, None).expect("Q1 by the partial method");
    let chosen: Vec<&Grasp> = grasps
        .iter()
        .filter(|g| {
            evaluator
                .evaluate(g)
                .is_ok_and(|q| q.force_closure == want_closure)
        })
        .collect();
    if chosen.is_empty() {
        eprintln!("no grasp of that kind among {count}");
        std::process::exit(1);
    }
    let (mut facets, mut points) = (0usize, 0usize);
    // Each grasp's best time over the rounds, for the median beside the mean.
    let mut best = vec![f64::INFINITY; chosen.len()];
    let started = Instant::now();
    for _ in 0..rounds {
        for (g, best) in chosen.iter().zip(&mut best) {
            let one = Instant::now();
            let q = evaluator.evaluate(g).expect("evaluated above");
            *best = best.min(one.elapsed().as_secs_f64() * 1e6);
            facets += q.stats.facets_created;
            points += q.stats.points_processed;
        }
    }
    best.sort_unstable_by(f64::total_cmp);
    let median = best[best.len() / 2];
    let runs = (rounds * chosen.len()).max(1) as f64;
    println!(
        "{} grasps of {count} ({}), {rounds} rounds: {:.1} µs per grasp, {:.0} facets created, \
         {:.1} points processed; median of the grasps' best times {median:.1} µs",
        chosen.len(),
        if want_closure {
            "force closure"
        } else {
            "not force closure"
        },
        started.elapsed().as_secs_f64() * 1e6 / runs,
        facets as f64 / runs,
        points as f64 / runs
    );
}
