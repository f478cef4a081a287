//! `pqh bench gws`: the seed paper's GWS evaluation, every method side by side in one run, plus
//! Q∞ by the partial hull and the batch throughput of `evaluate_batch` on 1, 2, … threads.

use crate::error::CliError;
use crate::methods::GwsMethodArg;
use clap::{Args, ValueEnum};
use pqhull_cli::bench::gws::{self, GwsConfig, GwsError, GwsReport};
use pqhull_cli::bench::workloads::GwsObject;
use std::io::Write;

pub const GWS_LONG_ABOUT: &str = "\
Random 4-contact grasps on a 1 x 0.4 x 0.2 bar (mu = 0.5, torque scale = half-diagonal) or,
with --object ellipsoid, on the ellipsoid of semi-axes 0.5, 0.2, 0.1 (torque scale 0.5), for
each number of cone edges k: Q1 by every --methods entry on the same grasps (full and qhull on
the first --full-grasps), with full/partial ratios of time, points and facets and a count of
disagreements; Q-inf by the partial method over the implicit Minkowski sum (--qinf-max-edges,
--qinf), grasps it cannot evaluate counted in `errors`; and the throughput of `evaluate_batch` in
a pool of each --threads size (--batch-rounds, --batch-min-ms; one untimed pass per pool first),
batch results that differ from the sequential ones counted in `mismatches`. Times are wall
clock on whatever else the machine is doing: compare rows of one run.

Details and measured runs: docs/benchmarks.md, \"Grasp wrench space\"; limits: docs/limits.md.";

/// Which Q∞: with or without the zero wrench in every contact's set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum QinfVariant {
    /// The zero wrench joins every contact's set (GraspIt!): Q∞ ≥ Q1, same force closure
    ZeroWrench,
    /// The Minkowski sum of the cone edges alone: rarely force closure on random grasps
    Plain,
}

impl QinfVariant {
    fn variant(self) -> gws::QinfVariant {
        match self {
            QinfVariant::ZeroWrench => gws::QinfVariant::ZeroWrench,
            QinfVariant::Plain => gws::QinfVariant::Plain,
        }
    }
}

/// `--object`'s values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ObjectArg {
    /// The 1 x 0.4 x 0.2 bar
    Bar,
    /// The ellipsoid of semi-axes 0.5, 0.2, 0.1
    Ellipsoid,
}

#[derive(Debug, Args)]
pub struct GwsArgs {
    /// Random grasps per k (partial method, Q∞ and batch), 1 to 100000
    #[arg(long, default_value_t = 200, value_parser = crate::limits::bench_grasps())]
    pub grasps: usize,
    /// At most this many of them for the full-hull methods (they are slow at large k), 0 to 100000
    #[arg(long, default_value_t = 10, value_parser = crate::limits::bench_subset())]
    pub full_grasps: usize,
    /// Cone edges, comma separated, each 3 to 1024
    #[arg(long, value_delimiter = ',', default_value = "4,8,16,32,64",
          value_parser = crate::limits::cone_edges())]
    pub edges: Vec<usize>,
    /// Contacts per grasp, 1 to 256
    #[arg(long, default_value_t = 4, value_parser = crate::limits::contacts())]
    pub contacts: usize,
    /// Q1 methods, comma separated (qhull needs the `qhull` feature); partial always runs, first
    #[arg(
        long,
        value_delimiter = ',',
        value_enum,
        default_value = "partial,full"
    )]
    pub methods: Vec<GwsMethodArg>,
    /// Q∞ (partial, implicit Minkowski sum) for every k up to this; 0: no Q∞
    #[arg(long, value_name = "K", default_value_t = 32)]
    pub qinf_max_edges: usize,
    /// Q∞ variants, comma separated: `zero-wrench` (GraspIt!'s: the zero wrench joins every
    /// contact's set) and/or `plain`
    #[arg(
        long,
        value_delimiter = ',',
        value_enum,
        default_value = "zero-wrench,plain"
    )]
    pub qinf: Vec<QinfVariant>,
    /// Batch pool sizes, comma separated, each 1 to 256 (default: 1 and the available parallelism)
    #[arg(long, value_delimiter = ',', value_name = "N,...",
          value_parser = crate::limits::threads())]
    pub threads: Option<Vec<usize>>,
    /// Timed rounds of each batch measurement (the median is reported), 0 to 1000; 0: no batch
    #[arg(long, default_value_t = 3, value_parser = crate::limits::count(0, 1000))]
    pub batch_rounds: usize,
    /// Each batch round repeats the set until this much one-thread work (ms); 0: one pass
    #[arg(long, default_value_t = 200.0)]
    pub batch_min_ms: f64,
    /// Seed of the random grasps
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The object the grasps are on: `bar` (axis-aligned normals) or `ellipsoid` (every normal
    /// different)
    #[arg(long, value_enum, default_value = "bar")]
    pub object: ObjectArg,
    /// One JSON document instead of the tables
    #[arg(long)]
    pub json: bool,
}

/// The pool sizes: `--threads`, or 1 and the available parallelism.
fn thread_counts(args: &GwsArgs) -> Result<Vec<usize>, CliError> {
    let counts = match &args.threads {
        Some(counts) => counts.clone(),
        None => gws::default_thread_counts(),
    };
    let max = crate::limits::MAX_THREADS;
    if let Some(n) = counts.iter().find(|&&n| !(1..=max).contains(&n)) {
        return Err(CliError::Usage(format!(
            "--threads: pool size {n} is not in 1..={max}"
        )));
    }
    Ok(counts)
}

pub fn run(args: &GwsArgs) -> Result<(), CliError> {
    if args.contacts == 0 || args.grasps == 0 {
        return Err(CliError::Usage(
            "--grasps and --contacts must be at least 1".into(),
        ));
    }
    let methods = args
        .methods
        .iter()
        .map(|&m| m.method())
        .collect::<Result<Vec<_>, _>>()?;
    let threads = if args.batch_rounds == 0 {
        Vec::new()
    } else {
        thread_counts(args)?
    };
    let config = GwsConfig {
        grasps: args.grasps,
        full_grasps: args.full_grasps,
        edges: args.edges.clone(),
        contacts: args.contacts,
        methods,
        qinf_max_edges: args.qinf_max_edges,
        qinf: args.qinf.iter().map(|v| v.variant()).collect(),
        threads,
        batch_rounds: args.batch_rounds,
        batch_min_ms: args.batch_min_ms,
        seed: args.seed,
        object: match args.object {
            ObjectArg::Bar => GwsObject::Bar,
            ObjectArg::Ellipsoid => GwsObject::Ellipsoid,
        },
    };
    let mut bars = crate::progress::Phases::default();
    let report = gws::run(&config, &mut |label, done, total| {
        bars.update(label, done, total)
    })
    .map_err(|e| match e {
        GwsError::Edges(e) => CliError::Usage(format!("--edges: {e}")),
        GwsError::Pool(e) => CliError::Usage(e.to_string()),
        e @ GwsError::PartialFailed { .. } => CliError::Geometry(e.to_string()),
        e => CliError::Usage(e.to_string()),
    })?;
    drop(bars);
    crate::format::write_report(
        args.json,
        || report.to_json(),
        |out| print_tables(out, &report),
    )?;
    Ok(())
}

/// A figure as the tables print it: what JSON cannot hold (NaN, infinities) reads as NaN, as in
/// the JSON document.
fn num(x: f64) -> f64 {
    if x.is_finite() { x } else { f64::NAN }
}

fn print_tables(out: &mut impl Write, report: &GwsReport) -> std::io::Result<()> {
    writeln!(
        out,
        "GWS Q1, {} contacts, random grasps on {} (seed {})",
        report.contacts,
        match report.object {
            GwsObject::Bar => "a 1 x 0.4 x 0.2 bar",
            GwsObject::Ellipsoid => "the ellipsoid of semi-axes 0.5, 0.2, 0.1",
        },
        report.seed
    )?;
    writeln!(
        out,
        "{:>4} {:>8} {:>6} {:>4} {:>12} {:>12} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}",
        "k",
        "method",
        "grasps",
        "fc",
        "median_us",
        "mean_us",
        "points",
        "facets",
        "x time",
        "x time fc",
        "x points",
        "x facets"
    )?;
    for entry in &report.results {
        for m in &entry.methods {
            let s = &m.summary;
            writeln!(
                out,
                "{:>4} {:>8} {:>6} {:>4} {:>12.1} {:>12.1} {:>10.1} {:>10.1} {:>10.1} {:>10.1} \
                 {:>10.2} {:>10.1}",
                entry.cone_edges,
                m.method,
                s.grasps,
                s.force_closure,
                num(s.median_us),
                num(s.mean_us),
                num(s.mean_points_processed),
                num(s.mean_facets_created),
                num(m.time_ratio_vs_partial),
                num(m.force_closure_time_ratio_vs_partial),
                num(m.points_ratio_vs_partial),
                num(m.facets_ratio_vs_partial)
            )?;
        }
        for m in &entry.methods {
            if m.summary.errors != 0 {
                writeln!(
                    out,
                    "     !! {}: {} grasps not evaluated (left out of the ratios), first: {}",
                    m.method,
                    m.summary.errors,
                    // Qhull's messages run to pages: their first sentence names the error.
                    m.summary
                        .first_error
                        .as_deref()
                        .unwrap_or("")
                        .chars()
                        .take(160)
                        .collect::<String>()
                )?;
            }
        }
        if entry.disagreements != 0 {
            writeln!(
                out,
                "     !! {} grasps where methods disagree",
                entry.disagreements
            )?;
        }
    }
    writeln!(
        out,
        "x = full method / partial, on the grasps both evaluated (time: median of per-grasp ratios; \
         x time fc: the same over the force-closure grasps alone)"
    )?;
    if report.results.iter().any(|e| !e.qinf.is_empty()) {
        writeln!(out)?;
        writeln!(
            out,
            "Q-inf by the partial hull (implicit Minkowski sum; fc = force closure)"
        )?;
        writeln!(
            out,
            "{:>4} {:>12} {:>6} {:>6} {:>12} {:>12} {:>12} {:>10} {:>10}",
            "k", "variant", "grasps", "fc", "median_us", "mean_us", "max_us", "points", "facets"
        )?;
        for entry in &report.results {
            for q in &entry.qinf {
                let s = &q.summary;
                writeln!(
                    out,
                    "{:>4} {:>12} {:>6} {:>6} {:>12.1} {:>12.1} {:>12.1} {:>10.1} {:>10.1}",
                    entry.cone_edges,
                    q.variant.name(),
                    s.grasps,
                    s.force_closure,
                    num(s.median_us),
                    num(s.mean_us),
                    num(s.max_us),
                    num(s.mean_points_processed),
                    num(s.mean_facets_created)
                )?;
                if s.errors != 0 {
                    writeln!(
                        out,
                        "     !! {} grasps not evaluated, first: {}",
                        s.errors,
                        s.first_error.as_deref().unwrap_or("")
                    )?;
                }
            }
        }
    }
    if report.results.iter().any(|e| !e.batch.is_empty()) {
        writeln!(out)?;
        writeln!(
            out,
            "Batch Q1 (partial, evaluate_batch), median of {} rounds of `passes` passes each \
             (median_s: per pass)",
            report.batch_rounds
        )?;
        writeln!(
            out,
            "{:>4} {:>7} {:>6} {:>6} {:>10} {:>10} {:>10}",
            "k", "threads", "grasps", "passes", "median_s", "grasps/s", "x 1 thread"
        )?;
        for entry in &report.results {
            for b in &entry.batch {
                writeln!(
                    out,
                    "{:>4} {:>7} {:>6} {:>6} {:>10.4} {:>10.1} {:>10.2}",
                    entry.cone_edges,
                    b.threads,
                    b.grasps,
                    b.passes,
                    num(b.median_s),
                    num(b.grasps_per_s),
                    num(b.speedup_vs_1_thread.unwrap_or(f64::NAN))
                )?;
                if b.mismatches != 0 {
                    writeln!(
                        out,
                        "     !! {} batch results differ from sequential",
                        b.mismatches
                    )?;
                }
            }
        }
    }
    Ok(())
}
