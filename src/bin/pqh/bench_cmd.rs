//! `pqh bench gws`: the seed paper's GWS evaluation, every method side by side in one run.

use crate::error::CliError;
use crate::grasp_cmd::{MethodArg, method};
use clap::{Args, Subcommand};
use pqhull::grasp::quality::{Evaluator, Method, Metric, Quality};
use pqhull::grasp::{FrictionModel, Grasp};
use pqhull::rbox::Rng;
use serde_json::json;

#[derive(Debug, Args)]
pub struct BenchArgs {
    #[command(subcommand)]
    pub which: Which,
}

#[derive(Debug, Subcommand)]
pub enum Which {
    /// Q1 on random 4-contact grasps on a box, k = 4 … 64: partial vs full vs Qhull
    Gws(GwsArgs),
}

#[derive(Debug, Args)]
pub struct GwsArgs {
    /// Random grasps per k (partial method)
    #[arg(long, default_value_t = 200)]
    pub grasps: usize,
    /// At most this many of them for the full-hull methods (they are slow at large k)
    #[arg(long, default_value_t = 10)]
    pub full_grasps: usize,
    /// Cone edges, comma separated
    #[arg(long, value_delimiter = ',', default_value = "4,8,16,32,64")]
    pub edges: Vec<usize>,
    /// Contacts per grasp
    #[arg(long, default_value_t = 4)]
    pub contacts: usize,
    /// Methods, comma separated (qhull needs the `qhull` feature)
    #[arg(
        long,
        value_delimiter = ',',
        value_enum,
        default_value = "partial,full"
    )]
    pub methods: Vec<MethodArg>,
    /// Seed of the random grasps
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// One JSON document instead of the table
    #[arg(long)]
    pub json: bool,
}

/// Random grasps on a 1 × 0.4 × 0.2 bar, μ = 0.5 (`Grasp::random_on_box`).
fn grasps(seed: u64, count: usize, contacts: usize, k: usize) -> Result<Vec<Grasp>, CliError> {
    let mut rng = Rng::new(seed);
    let friction =
        FrictionModel::try_new(0.5, k).map_err(|e| CliError::Usage(format!("--edges: {e}")))?;
    Ok((0..count)
        .map(|_| Grasp::random_on_box(&mut rng, [0.5, 0.2, 0.1], contacts, friction))
        .collect())
}

struct Row {
    method: &'static str,
    times_us: Vec<f64>,
    points: Vec<usize>,
    facets: Vec<usize>,
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}

fn mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = values.fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    sum / n as f64
}

fn name(method: Method) -> &'static str {
    match method {
        Method::Partial => "partial",
        Method::Full => "full",
        #[cfg(feature = "qhull")]
        Method::Qhull => "qhull",
    }
}

pub fn run(args: &BenchArgs) -> Result<(), CliError> {
    let Which::Gws(args) = &args.which;
    if args.contacts == 0 || args.grasps == 0 {
        return Err(CliError::Usage(
            "--grasps and --contacts must be at least 1".into(),
        ));
    }
    let methods: Vec<Method> = args
        .methods
        .iter()
        .map(|&m| method(m))
        .collect::<Result<_, _>>()?;
    let mut report = Vec::new();
    for &k in &args.edges {
        let set = grasps(args.seed, args.grasps, args.contacts, k)?;
        let mut rows = Vec::new();
        let mut values: Vec<Vec<f64>> = Vec::new();
        for &m in &methods {
            let n = if m == Method::Partial {
                set.len()
            } else {
                args.full_grasps.min(set.len())
            };
            let mut evaluator = Evaluator::new(Metric::Q1, m);
            let results: Vec<Quality> = set[..n]
                .iter()
                .map(|g| evaluator.evaluate(g))
                .collect::<Result<_, _>>()
                .map_err(|e| CliError::Geometry(e.to_string()))?;
            values.push(results.iter().map(|q| q.value).collect());
            rows.push(Row {
                method: name(m),
                times_us: results
                    .iter()
                    .map(|q| q.stats.elapsed.as_secs_f64() * 1e6)
                    .collect(),
                points: results.iter().map(|q| q.stats.points_processed).collect(),
                facets: results.iter().map(|q| q.stats.facets_created).collect(),
            });
        }
        // Every method must give the same answers on the grasps they share.
        let disagreements = values
            .iter()
            .skip(1)
            .map(|v| {
                v.iter()
                    .zip(&values[0])
                    .filter(|(a, b)| (*a - *b).abs() > 1e-9 * a.abs().max(1e-3))
                    .count()
            })
            .sum::<usize>();
        let partial = &rows[0];
        let mut entries = Vec::new();
        for row in &rows {
            let n = row.times_us.len();
            // Ratios over the grasps both methods evaluated: median of per-grasp ratios.
            let mut time_ratio: Vec<f64> = (0..n)
                .map(|i| row.times_us[i] / partial.times_us[i])
                .collect();
            let points_ratio = mean((0..n).map(|i| row.points[i] as f64))
                / mean((0..n).map(|i| partial.points[i] as f64));
            let facets_ratio = mean((0..n).map(|i| row.facets[i] as f64))
                / mean((0..n).map(|i| partial.facets[i] as f64));
            entries.push(json!({
                "method": row.method,
                "grasps": n,
                "median_us": median(&mut row.times_us.clone()),
                "mean_us": mean(row.times_us.iter().copied()),
                "mean_points_processed": mean(row.points.iter().map(|&p| p as f64)),
                "mean_facets_created": mean(row.facets.iter().map(|&p| p as f64)),
                "time_ratio_vs_partial": median(&mut time_ratio),
                "points_ratio_vs_partial": points_ratio,
                "facets_ratio_vs_partial": facets_ratio,
            }));
        }
        report.push(json!({"cone_edges": k, "contacts": args.contacts, "disagreements": disagreements, "methods": entries}));
    }
    if args.json {
        println!(
            "{}",
            json!({"benchmark": "gws", "seed": args.seed, "results": report})
        );
        return Ok(());
    }
    println!(
        "GWS Q1, {} contacts, random grasps on a 1 x 0.4 x 0.2 bar (seed {})",
        args.contacts, args.seed
    );
    println!(
        "{:>4} {:>8} {:>6} {:>12} {:>12} {:>10} {:>10} {:>10} {:>10} {:>10}",
        "k",
        "method",
        "grasps",
        "median_us",
        "mean_us",
        "points",
        "facets",
        "x time",
        "x points",
        "x facets"
    );
    for entry in &report {
        for m in entry["methods"].as_array().expect("array") {
            println!(
                "{:>4} {:>8} {:>6} {:>12.1} {:>12.1} {:>10.1} {:>10.1} {:>10.1} {:>10.2} {:>10.1}",
                entry["cone_edges"],
                m["method"].as_str().unwrap_or(""),
                m["grasps"],
                m["median_us"].as_f64().unwrap_or(f64::NAN),
                m["mean_us"].as_f64().unwrap_or(f64::NAN),
                m["mean_points_processed"].as_f64().unwrap_or(f64::NAN),
                m["mean_facets_created"].as_f64().unwrap_or(f64::NAN),
                m["time_ratio_vs_partial"].as_f64().unwrap_or(f64::NAN),
                m["points_ratio_vs_partial"].as_f64().unwrap_or(f64::NAN),
                m["facets_ratio_vs_partial"].as_f64().unwrap_or(f64::NAN)
            );
        }
        if entry["disagreements"] != 0 {
            println!(
                "     !! {} grasps where methods disagree",
                entry["disagreements"]
            );
        }
    }
    println!(
        "x = full method / partial, on the grasps both evaluated (time: median of per-grasp ratios)"
    );
    Ok(())
}
