//! What each grasp metric costs per grasp, beside Q1 on the same grasps.
//!
//! `cargo run --release -p pqhull-cli --example metric_costs [GRASPS] [EDGES]` (defaults 200 and 8): random
//! 4-contact grasps on the benchmarks' bar (μ = 0.5, seed 1), each metric timed per grasp with
//! `Instant` around the library call; medians and means in µs, and the median's ratio to Q1's.
//! The soft rows give every contact torsion γ = 0.01 (a tenth of the bar's half-thickness).

use pqhull::grasp::metrics::{grasp_matrix_singular_values, gws_volume};
use pqhull::grasp::quality::q1;
use pqhull::grasp::{Evaluator, FrictionModel, Grasp, Method, Metric};
use pqhull_cli::bench::stats::{mean, median};
use pqhull_cli::bench::workloads::{BAR_FRICTION, bar_grasps};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let grasps: usize = args.next().map_or(Ok(200), |a| a.parse())?;
    let edges: usize = args.next().map_or(Ok(8), |a| a.parse())?;
    let set = bar_grasps(1, grasps, 4, FrictionModel::try_new(BAR_FRICTION, edges)?);
    let soft: Vec<Grasp> = set
        .iter()
        .map(|g| {
            let contacts = g
                .contacts()
                .iter()
                .map(|c| c.with_torsion(0.01))
                .collect::<Result<_, _>>()?;
            Grasp::builder(contacts, g.friction())
                .torque_reference(g.torque_reference())
                .torque_scale(g.torque_scale())
                .build()
        })
        .collect::<Result<_, _>>()?;
    let gravity = [0.0, 0.0, -1.0, 0.0, 0.0, 0.0];
    let qinf = Metric::QInf {
        with_zero_wrench: false,
    };
    // A metric's run on grasp i: of the hard grasps, or of their soft copies.
    type Run<'a> = Box<dyn Fn(usize) -> Result<(), Box<dyn std::error::Error>> + 'a>;
    let metrics: Vec<(&str, Run)> = vec![
        (
            "q1 (partial)",
            Box::new(|i| q1(&set[i]).map(drop).map_err(Into::into)),
        ),
        (
            "cone bracket (two Q1)",
            Box::new(|i| {
                Evaluator::new(Metric::ConeBracket, Method::Partial, None)
                    .and_then(|mut bracket| bracket.evaluate(&set[i]))
                    .map(drop)
                    .map_err(Into::into)
            }),
        ),
        (
            "resist gravity (partial)",
            Box::new(|i| {
                let resist = Metric::Resist { wrench: gravity };
                Evaluator::new(resist, Method::Partial, None)
                    .and_then(|mut resist| resist.evaluate(&set[i]))
                    .map(drop)
                    .map_err(Into::into)
            }),
        ),
        (
            "gws volume (full hull)",
            Box::new(|i| gws_volume(&set[i]).map(drop).map_err(Into::into)),
        ),
        (
            "sigma-min, isotropy (SVD)",
            Box::new(|i| {
                grasp_matrix_singular_values(&set[i])
                    .map(drop)
                    .map_err(Into::into)
            }),
        ),
        (
            "q1 soft (partial)",
            Box::new(|i| q1(&soft[i]).map(drop).map_err(Into::into)),
        ),
        (
            "qinf (partial)",
            Box::new(|i| {
                Evaluator::new(qinf, Method::Partial, None)
                    .and_then(|mut qinf| qinf.evaluate(&set[i]))
                    .map(drop)
                    .map_err(Into::into)
            }),
        ),
        (
            "qinf soft (partial)",
            Box::new(|i| {
                Evaluator::new(qinf, Method::Partial, None)
                    .and_then(|mut qinf| qinf.evaluate(&soft[i]))
                    .map(drop)
                    .map_err(Into::into)
            }),
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
        for i in 0..set.len() {
            let started = Instant::now();
            run(i)?;
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
