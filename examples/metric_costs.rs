//! What each metric of `pqhull::grasp::metrics` costs per grasp, beside Q1 on the same grasps.
//!
//! `cargo run --release --example metric_costs [GRASPS] [EDGES]` (defaults 200 and 8): random
//! 4-contact grasps on the benchmarks' bar (μ = 0.5, seed 1), each metric timed per grasp with
//! `Instant` around the library call; medians and means in µs, and the median's ratio to Q1's.

use pqhull::bench::stats::{mean, median};
use pqhull::bench::workloads::{BAR_FRICTION, bar_grasps};
use pqhull::grasp::FrictionModel;
use pqhull::grasp::metrics::{cone_bracket, grasp_matrix_metrics, gws_volume, resist};
use pqhull::grasp::quality::{Method, q1};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let grasps: usize = args.next().map_or(Ok(200), |a| a.parse())?;
    let edges: usize = args.next().map_or(Ok(8), |a| a.parse())?;
    let set = bar_grasps(1, grasps, 4, FrictionModel::try_new(BAR_FRICTION, edges)?);
    let gravity = [0.0, 0.0, -1.0, 0.0, 0.0, 0.0];
    type Run<'a> =
        Box<dyn Fn(&pqhull::grasp::Grasp) -> Result<(), Box<dyn std::error::Error>> + 'a>;
    let metrics: Vec<(&str, Run)> = vec![
        (
            "q1 (partial)",
            Box::new(|g| q1(g).map(drop).map_err(Into::into)),
        ),
        (
            "cone bracket (two Q1)",
            Box::new(|g| {
                cone_bracket(g, Method::Partial)
                    .map(drop)
                    .map_err(Into::into)
            }),
        ),
        (
            "resist gravity (partial)",
            Box::new(|g| {
                resist(g, gravity, Method::Partial)
                    .map(drop)
                    .map_err(Into::into)
            }),
        ),
        (
            "gws volume (full hull)",
            Box::new(|g| gws_volume(g).map(drop).map_err(Into::into)),
        ),
        (
            "sigma-min, isotropy (SVD)",
            Box::new(|g| grasp_matrix_metrics(g).map(drop).map_err(Into::into)),
        ),
    ];
    println!("{grasps} bar grasps, 4 contacts x {edges} edges, mu = {BAR_FRICTION}");
    println!(
        "{:<28} {:>12} {:>12} {:>10}",
        "metric", "median us", "mean us", "x q1"
    );
    let mut q1_median = f64::NAN;
    for (name, run) in &metrics {
        let mut times = Vec::with_capacity(set.len());
        for g in &set {
            let started = Instant::now();
            run(g)?;
            times.push(started.elapsed().as_secs_f64() * 1e6);
        }
        let m = median(&mut times.clone());
        if q1_median.is_nan() {
            q1_median = m;
        }
        println!(
            "{name:<28} {m:>12.1} {:>12.1} {:>10.2}",
            mean(times.iter().copied()),
            m / q1_median
        );
    }
    Ok(())
}
