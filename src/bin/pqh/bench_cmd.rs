//! `pqh bench gws`: the seed paper's GWS evaluation, every method side by side in one run, plus
//! Q∞ by the partial hull and the batch throughput of `evaluate_batch` on 1, 2, … threads.

use crate::error::CliError;
use crate::grasp_cmd::{MethodArg, method};
use clap::{Args, Subcommand, ValueEnum};
use pqhull::geometry::Rng;
use pqhull::grasp::quality::{Evaluator, Method, Metric, Quality, evaluate_batch};
use pqhull::grasp::{FrictionModel, Grasp};
use serde_json::{Value, json};
use std::io::Write;
use std::time::Instant;

pub const GWS_LONG_ABOUT: &str = "\
Random 4-contact grasps on a 1 x 0.4 x 0.2 bar (mu = 0.5, torque scale = half-diagonal), for
each number of cone edges k:

  Q1      every --methods entry on the same grasps (partial on all --grasps, always first; full
          and qhull on the first --full-grasps), with full/partial ratios of time, points
          processed and facets created, and a count of grasps where the methods disagree.
  Q-inf   the partial method over the implicit Minkowski sum (k^m points, never materialised),
          on all --grasps, for every k <= --qinf-max-edges (default 32; 0 turns it off), for
          each --qinf variant (default both: zero-wrench, then plain): force-closure count,
          median, mean and largest time per grasp. Most random grasps are not force closure
          for the plain variant. A grasp the library cannot evaluate is counted in `errors`,
          not fatal.
  batch   `evaluate_batch` (Q1, partial) of all --grasps inside a rayon pool of each --threads
          size (default 1 and the available parallelism), rounds interleaved across sizes,
          median of --batch-rounds (0 turns it off): grasps/s and the speed-up over 1 thread.
          Each timed round evaluates the set `passes` times inside the pool, enough to last
          --batch-min-ms (default 200) on one thread: waking an idle worker costs milliseconds
          on a virtual machine, which would otherwise swamp a batch of small grasps (steady
          throughput is measured; --batch-min-ms 0 times single passes, wake-up included).
          Every pool runs one untimed pass first. The batch results must equal the sequential
          ones (counted in `mismatches`).

Times are wall clock on whatever else the machine is doing: compare rows of one run.";

#[derive(Debug, Args)]
pub struct BenchArgs {
    #[command(subcommand)]
    pub which: Which,
}

#[derive(Debug, Subcommand)]
pub enum Which {
    /// Random 4-contact grasps on a box, k = 4 … 64: Q1 partial vs full vs Qhull, Q∞, batch
    /// throughput on 1…n threads
    #[command(long_about = GWS_LONG_ABOUT)]
    Gws(GwsArgs),
    /// Q_OWS on random surface grasps of a mesh: partial vs brute force vs ellipsoid, vs Q1
    Ows(crate::bench_ows::OwsArgs),
}

/// Which Q∞: with or without the zero wrench in every contact's set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum QinfVariant {
    /// The zero wrench joins every contact's set (GraspIt!): Q∞ ≥ Q1, same force closure
    ZeroWrench,
    /// The Minkowski sum of the cone edges alone: rarely force closure on random grasps
    Plain,
}

impl QinfVariant {
    fn name(self) -> &'static str {
        match self {
            QinfVariant::ZeroWrench => "zero-wrench",
            QinfVariant::Plain => "plain",
        }
    }
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
    pub methods: Vec<MethodArg>,
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
    /// Batch pool sizes, comma separated, each 1 to 256 [default: 1,<available parallelism>]
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
    /// One JSON document instead of the tables
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
    force_closure: usize,
    /// Per evaluated grasp: its index in the set, its time, points, facets and verdict.
    grasp: Vec<usize>,
    times_us: Vec<f64>,
    points: Vec<usize>,
    facets: Vec<usize>,
    closure: Vec<bool>,
    values: Vec<f64>,
    /// The grasps the method could not evaluate (e.g. Qhull's topology errors on nearly flat
    /// wrench sets), named: counted and shown, not fatal.
    errors: Vec<String>,
}

impl Row {
    fn new(method: &'static str, results: &[Result<Quality, String>]) -> Row {
        let mut row = Row {
            method,
            force_closure: 0,
            grasp: Vec::new(),
            times_us: Vec::new(),
            points: Vec::new(),
            facets: Vec::new(),
            closure: Vec::new(),
            values: Vec::new(),
            errors: Vec::new(),
        };
        for (i, result) in results.iter().enumerate() {
            match result {
                Ok(q) => {
                    row.force_closure += usize::from(q.force_closure);
                    row.grasp.push(i);
                    row.times_us.push(q.stats.elapsed.as_secs_f64() * 1e6);
                    row.points.push(q.stats.points_processed);
                    row.facets.push(q.stats.facets_created);
                    row.closure.push(q.force_closure);
                    row.values.push(q.value);
                }
                Err(e) => row.errors.push(format!("grasp {i}: {e}")),
            }
        }
        row
    }

    /// The entry of grasp `g`, when this method evaluated it.
    fn at(&self, g: usize) -> Option<usize> {
        self.grasp.binary_search(&g).ok()
    }

    /// Pairs of entries (this row's, `base`'s) for the grasps both evaluated.
    fn pairs<'a>(&'a self, base: &'a Row) -> impl Iterator<Item = (usize, usize)> + 'a {
        (0..self.grasp.len()).filter_map(|j| base.at(self.grasp[j]).map(|p| (j, p)))
    }
}

pub(crate) fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}

pub(crate) fn mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = values.fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    sum / n as f64
}

fn name(method: Method) -> &'static str {
    method.name()
}

/// Evaluates `set` one grasp after another with one evaluator; a grasp the method cannot
/// evaluate keeps its error.
fn evaluate_all(set: &[Grasp], metric: Metric, method: Method) -> Vec<Result<Quality, String>> {
    let mut evaluator = Evaluator::new(metric, method);
    let bar = crate::progress::bar(set.len(), name(method));
    let results = set
        .iter()
        .map(|g| {
            let q = evaluator.evaluate(g).map_err(|e| e.to_string());
            bar.inc(1);
            q
        })
        .collect();
    bar.finish_and_clear();
    results
}

/// The pool sizes: `--threads`, or 1 and the available parallelism.
fn thread_counts(args: &GwsArgs) -> Result<Vec<usize>, CliError> {
    let counts = match &args.threads {
        Some(counts) => counts.clone(),
        None => {
            let n = std::thread::available_parallelism().map_or(1, |n| n.get());
            if n > 1 { vec![1, n] } else { vec![1] }
        }
    };
    let max = crate::limits::MAX_THREADS;
    if let Some(n) = counts.iter().find(|&&n| !(1..=max).contains(&n)) {
        return Err(CliError::Usage(format!(
            "--threads: pool size {n} is not in 1..={max}"
        )));
    }
    Ok(counts)
}

/// Batch throughput of Q1 by the partial method in pools of each size; rounds interleaved across
/// sizes so a change of load hits them alike. `seconds` is the seconds per pass of a round.
fn batch(
    set: &[Grasp],
    sequential: &[Quality],
    pools: &[(usize, rayon::ThreadPool)],
    rounds: usize,
    min_ms: f64,
) -> Vec<Value> {
    if rounds == 0 {
        return Vec::new();
    }
    // Passes per round: `min_ms` of sequential work (see the help text).
    let sequential_s: f64 = sequential
        .iter()
        .map(|q| q.stats.elapsed.as_secs_f64())
        .sum();
    let passes = ((min_ms / 1e3 / sequential_s.max(1e-9)).ceil() as usize).clamp(1, 1000);
    for (_, pool) in pools {
        pool.install(|| evaluate_batch(set, Metric::Q1, Method::Partial));
    }
    let mut seconds = vec![Vec::with_capacity(rounds); pools.len()];
    let mut mismatches = vec![0usize; pools.len()];
    for _ in 0..rounds {
        for (i, (_, pool)) in pools.iter().enumerate() {
            let started = Instant::now();
            // All passes inside the pool, so its threads are not put back to sleep in between.
            let results = pool.install(|| {
                let mut results = Vec::new();
                for _ in 0..passes {
                    results = evaluate_batch(set, Metric::Q1, Method::Partial);
                }
                results
            });
            seconds[i].push(started.elapsed().as_secs_f64() / passes as f64);
            mismatches[i] += results
                .iter()
                .zip(sequential)
                .filter(|(r, s)| {
                    r.as_ref().map_or(true, |r| {
                        r.value.to_bits() != s.value.to_bits() || r.force_closure != s.force_closure
                    })
                })
                .count();
        }
    }
    let rate = |i: usize| set.len() as f64 / median(&mut seconds[i].clone());
    let one_thread = pools.iter().position(|(n, _)| *n == 1).map(rate);
    pools
        .iter()
        .enumerate()
        .map(|(i, (threads, _))| {
            let grasps_per_s = rate(i);
            json!({
                "threads": threads,
                "grasps": set.len(),
                "rounds": rounds,
                "passes": passes,
                "median_s": median(&mut seconds[i].clone()),
                "best_s": seconds[i].iter().copied().fold(f64::INFINITY, f64::min),
                "grasps_per_s": grasps_per_s,
                "speedup_vs_1_thread": one_thread.map(|one| grasps_per_s / one),
                "mismatches": mismatches[i],
            })
        })
        .collect()
}

pub fn run(args: &BenchArgs) -> Result<(), CliError> {
    let args = match &args.which {
        Which::Gws(args) => args,
        Which::Ows(args) => return crate::bench_ows::run(args),
    };
    if args.contacts == 0 || args.grasps == 0 {
        return Err(CliError::Usage(
            "--grasps and --contacts must be at least 1".into(),
        ));
    }
    // Partial first (the ratios are against it), then the others once each.
    let mut methods = vec![Method::Partial];
    for &arg in &args.methods {
        let m = method(arg)?;
        if !methods.contains(&m) {
            methods.push(m);
        }
    }
    let threads = if args.batch_rounds == 0 {
        Vec::new()
    } else {
        thread_counts(args)?
    };
    let pools = threads
        .iter()
        .map(|&n| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map(|pool| (n, pool))
                .map_err(|e| CliError::Usage(format!("cannot start {n} threads: {e}")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut variants: Vec<QinfVariant> = Vec::new();
    for &v in &args.qinf {
        if !variants.contains(&v) {
            variants.push(v);
        }
    }
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let mut report = Vec::new();
    for &k in &args.edges {
        let set = grasps(args.seed, args.grasps, args.contacts, k)?;
        let mut rows = Vec::new();
        let mut partial_results = Vec::new();
        for &m in &methods {
            let n = if m == Method::Partial {
                set.len()
            } else {
                args.full_grasps.min(set.len())
            };
            if n == 0 {
                continue; // --full-grasps 0: partial only
            }
            let results = evaluate_all(&set[..n], Metric::Q1, m);
            rows.push(Row::new(name(m), &results));
            if m == Method::Partial {
                partial_results = results;
            }
        }
        let partial = &rows[0];
        if !partial.errors.is_empty() {
            return Err(CliError::Geometry(format!(
                "the partial method failed on {} grasps, first: {}",
                partial.errors.len(),
                partial.errors[0]
            )));
        }
        let partial_results: Vec<Quality> = partial_results.into_iter().flatten().collect();
        // Every method must give the same answers on the grasps they share.
        let disagreements = rows
            .iter()
            .skip(1)
            .map(|row| {
                row.pairs(partial)
                    .filter(|&(j, p)| {
                        let (a, b) = (row.values[j], partial.values[p]);
                        (a - b).abs() > 1e-9 * a.abs().max(1e-3)
                    })
                    .count()
            })
            .sum::<usize>();
        let mut entries = Vec::new();
        for row in &rows {
            // Ratios over the grasps both methods evaluated: median of per-grasp ratios.
            let pairs: Vec<(usize, usize)> = row.pairs(partial).collect();
            let mut time_ratio: Vec<f64> = pairs
                .iter()
                .map(|&(j, p)| row.times_us[j] / partial.times_us[p])
                .collect();
            // The same over the force-closure grasps alone (the partial method's slow kind:
            // the others are settled by GJK without a hull).
            let mut closure_ratio: Vec<f64> = pairs
                .iter()
                .zip(&time_ratio)
                .filter(|((_, p), _)| partial.closure[*p])
                .map(|(_, &r)| r)
                .collect();
            let points_ratio = mean(pairs.iter().map(|&(j, _)| row.points[j] as f64))
                / mean(pairs.iter().map(|&(_, p)| partial.points[p] as f64));
            let facets_ratio = mean(pairs.iter().map(|&(j, _)| row.facets[j] as f64))
                / mean(pairs.iter().map(|&(_, p)| partial.facets[p] as f64));
            entries.push(json!({
                "method": row.method,
                "grasps": row.grasp.len(),
                "errors": row.errors.len(),
                "first_error": row.errors.first(),
                "force_closure": row.force_closure,
                "median_us": median(&mut row.times_us.clone()),
                "mean_us": mean(row.times_us.iter().copied()),
                "max_us": row.times_us.iter().copied().fold(0.0, f64::max),
                "mean_points_processed": mean(row.points.iter().map(|&p| p as f64)),
                "mean_facets_created": mean(row.facets.iter().map(|&p| p as f64)),
                "time_ratio_vs_partial": median(&mut time_ratio),
                "force_closure_time_ratio_vs_partial": median(&mut closure_ratio),
                "points_ratio_vs_partial": points_ratio,
                "facets_ratio_vs_partial": facets_ratio,
            }));
        }
        let mut qinf = Vec::new();
        for &variant in variants.iter().filter(|_| k <= args.qinf_max_edges) {
            qinf.push(qinf_row(&set, variant));
        }
        let batch = batch(
            &set,
            &partial_results,
            &pools,
            args.batch_rounds,
            args.batch_min_ms,
        );
        report.push(json!({
            "cone_edges": k,
            "contacts": args.contacts,
            "disagreements": disagreements,
            "methods": entries,
            "qinf": qinf,
            "batch": batch,
        }));
    }
    if args.json {
        writeln!(
            out,
            "{}",
            json!({
                "benchmark": "gws",
                "seed": args.seed,
                "threads": threads,
                "available_parallelism": std::thread::available_parallelism().map_or(1, |n| n.get()),
                "batch_rounds": args.batch_rounds,
                "batch_min_ms": args.batch_min_ms,
                "qinf_max_edges": args.qinf_max_edges,
                "results": report,
            })
        )?;
        out.flush()?;
        return Ok(());
    }
    print_tables(&mut out, args, &report)?;
    out.flush()?;
    Ok(())
}

/// Q∞ of every grasp of `set` by the partial hull. A grasp the library cannot evaluate is
/// counted, not fatal (the timings are over the others).
fn qinf_row(set: &[Grasp], variant: QinfVariant) -> Value {
    let metric = Metric::QInf {
        with_zero_wrench: variant == QinfVariant::ZeroWrench,
    };
    let mut evaluator = Evaluator::new(metric, Method::Partial);
    let results: Vec<_> = set
        .iter()
        .map(|g| evaluator.evaluate(g).map_err(|e| e.to_string()))
        .collect();
    let row = Row::new("partial", &results);
    json!({
        "variant": variant.name(),
        "method": row.method,
        "grasps": row.grasp.len(),
        "errors": row.errors.len(),
        "first_error": row.errors.first(),
        "force_closure": row.force_closure,
        "median_us": median(&mut row.times_us.clone()),
        "mean_us": mean(row.times_us.iter().copied()),
        "max_us": row.times_us.iter().copied().fold(0.0, f64::max),
        "mean_points_processed": mean(row.points.iter().map(|&p| p as f64)),
        "mean_facets_created": mean(row.facets.iter().map(|&p| p as f64)),
    })
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

fn print_tables(out: &mut impl Write, args: &GwsArgs, report: &[Value]) -> std::io::Result<()> {
    writeln!(
        out,
        "GWS Q1, {} contacts, random grasps on a 1 x 0.4 x 0.2 bar (seed {})",
        args.contacts, args.seed
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
    for entry in report {
        for m in entry["methods"].as_array().expect("array") {
            writeln!(
                out,
                "{:>4} {:>8} {:>6} {:>4} {:>12.1} {:>12.1} {:>10.1} {:>10.1} {:>10.1} {:>10.1} \
                 {:>10.2} {:>10.1}",
                entry["cone_edges"].as_u64().unwrap_or(0),
                m["method"].as_str().unwrap_or(""),
                m["grasps"].as_u64().unwrap_or(0),
                m["force_closure"].as_u64().unwrap_or(0),
                num(&m["median_us"]),
                num(&m["mean_us"]),
                num(&m["mean_points_processed"]),
                num(&m["mean_facets_created"]),
                num(&m["time_ratio_vs_partial"]),
                num(&m["force_closure_time_ratio_vs_partial"]),
                num(&m["points_ratio_vs_partial"]),
                num(&m["facets_ratio_vs_partial"])
            )?;
        }
        for m in entry["methods"].as_array().expect("array") {
            if m["errors"] != 0 {
                writeln!(
                    out,
                    "     !! {}: {} grasps not evaluated (left out of the ratios), first: {}",
                    m["method"].as_str().unwrap_or(""),
                    m["errors"],
                    // Qhull's messages run to pages: their first sentence names the error.
                    m["first_error"]
                        .as_str()
                        .unwrap_or("")
                        .chars()
                        .take(160)
                        .collect::<String>()
                )?;
            }
        }
        if entry["disagreements"] != 0 {
            writeln!(
                out,
                "     !! {} grasps where methods disagree",
                entry["disagreements"]
            )?;
        }
    }
    writeln!(
        out,
        "x = full method / partial, on the grasps both evaluated (time: median of per-grasp ratios; \
         x time fc: the same over the force-closure grasps alone)"
    )?;
    if report
        .iter()
        .any(|e| e["qinf"].as_array().is_some_and(|q| !q.is_empty()))
    {
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
        for entry in report {
            for q in entry["qinf"].as_array().into_iter().flatten() {
                writeln!(
                    out,
                    "{:>4} {:>12} {:>6} {:>6} {:>12.1} {:>12.1} {:>12.1} {:>10.1} {:>10.1}",
                    entry["cone_edges"].as_u64().unwrap_or(0),
                    q["variant"].as_str().unwrap_or(""),
                    q["grasps"].as_u64().unwrap_or(0),
                    q["force_closure"].as_u64().unwrap_or(0),
                    num(&q["median_us"]),
                    num(&q["mean_us"]),
                    num(&q["max_us"]),
                    num(&q["mean_points_processed"]),
                    num(&q["mean_facets_created"])
                )?;
                if q["errors"] != 0 {
                    writeln!(
                        out,
                        "     !! {} grasps not evaluated, first: {}",
                        q["errors"],
                        q["first_error"].as_str().unwrap_or("")
                    )?;
                }
            }
        }
    }
    if report
        .iter()
        .any(|e| e["batch"].as_array().is_some_and(|b| !b.is_empty()))
    {
        writeln!(out)?;
        writeln!(
            out,
            "Batch Q1 (partial, evaluate_batch), median of {} rounds of `passes` passes each \
             (median_s: per pass)",
            args.batch_rounds
        )?;
        writeln!(
            out,
            "{:>4} {:>7} {:>6} {:>6} {:>10} {:>10} {:>10}",
            "k", "threads", "grasps", "passes", "median_s", "grasps/s", "x 1 thread"
        )?;
        for entry in report {
            for b in entry["batch"].as_array().into_iter().flatten() {
                writeln!(
                    out,
                    "{:>4} {:>7} {:>6} {:>6} {:>10.4} {:>10.1} {:>10.2}",
                    entry["cone_edges"].as_u64().unwrap_or(0),
                    b["threads"].as_u64().unwrap_or(0),
                    b["grasps"].as_u64().unwrap_or(0),
                    b["passes"].as_u64().unwrap_or(0),
                    num(&b["median_s"]),
                    num(&b["grasps_per_s"]),
                    num(&b["speedup_vs_1_thread"])
                )?;
                if b["mismatches"] != 0 {
                    writeln!(
                        out,
                        "     !! {} batch results differ from sequential",
                        b["mismatches"]
                    )?;
                }
            }
        }
    }
    Ok(())
}
