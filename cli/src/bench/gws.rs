//! The seed paper's GWS evaluation: Q1 by every method on the same random grasps of a bar, Q∞
//! by the partial hull, and the batch throughput of `evaluate_batch` on 1, 2, … threads (what
//! `pqh bench gws` runs).

use super::Progress;
use super::batch::{BatchRow, PoolError, Pools, batch};
use super::runs::{MethodRun, RunSummary, evaluate_all};
use super::stats::{mean, median};
use super::workloads::{BAR_FRICTION, GwsObject, object_grasps};
use pqhull::grasp::{Evaluation, FrictionModel, GraspError, Method, Metric};
use serde_json::{Value, json};
use std::fmt;

/// Which Q∞: with or without the zero wrench in every contact's set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QinfVariant {
    /// The zero wrench joins every contact's set (GraspIt!): Q∞ ≥ Q1, same force closure.
    ZeroWrench,
    /// The Minkowski sum of the cone edges alone: rarely force closure on random grasps.
    Plain,
}

impl QinfVariant {
    /// The name the reports give it: `zero-wrench` or `plain`.
    pub fn name(self) -> &'static str {
        match self {
            QinfVariant::ZeroWrench => "zero-wrench",
            QinfVariant::Plain => "plain",
        }
    }
}

/// What to measure.
#[derive(Clone, Debug, PartialEq)]
pub struct GwsConfig {
    /// Random grasps per cone-edge count (partial method, Q∞ and batch).
    pub grasps: usize,
    /// At most this many of them for the methods other than partial (0: partial only).
    pub full_grasps: usize,
    /// The cone-edge counts k, one result each.
    pub edges: Vec<usize>,
    /// Contacts per grasp.
    pub contacts: usize,
    /// Q1 methods; partial always runs, first (the ratios are against it), and each runs once.
    pub methods: Vec<Method>,
    /// Q∞ for every k up to this (0: none).
    pub qinf_max_edges: usize,
    /// The Q∞ variants, each once, in this order.
    pub qinf: Vec<QinfVariant>,
    /// Batch pool sizes (empty: no batch measurement).
    pub threads: Vec<usize>,
    /// Timed rounds of each batch measurement, median reported (0: none).
    pub batch_rounds: usize,
    /// Each batch round repeats the set until this much one-thread work (ms; 0: one pass).
    pub batch_min_ms: f64,
    /// Seed of the random grasps.
    pub seed: u64,
    /// The object the grasps are on.
    pub object: GwsObject,
}

impl Default for GwsConfig {
    /// `pqh bench gws`'s defaults.
    fn default() -> Self {
        GwsConfig {
            grasps: 200,
            full_grasps: 10,
            edges: vec![4, 8, 16, 32, 64],
            contacts: 4,
            methods: vec![Method::Partial, Method::Full],
            qinf_max_edges: 32,
            qinf: vec![QinfVariant::ZeroWrench, QinfVariant::Plain],
            threads: default_thread_counts(),
            batch_rounds: 3,
            batch_min_ms: 200.0,
            seed: 1,
            object: GwsObject::Bar,
        }
    }
}

/// The available parallelism (1 when it cannot be read).
pub fn available_parallelism() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// The default batch pool sizes: 1 and the available parallelism (just 1 on one core).
pub fn default_thread_counts() -> Vec<usize> {
    let n = available_parallelism();
    if n > 1 { vec![1, n] } else { vec![1] }
}

/// One Q1 method on the grasps of one k, with its ratios to the partial method.
#[derive(Clone, Debug, PartialEq)]
pub struct MethodRow {
    /// `partial`, `full` or `qhull`.
    pub method: &'static str,
    /// Times, work and verdicts.
    pub summary: RunSummary,
    /// Median over the grasps both evaluated of (this method's time / partial's).
    pub time_ratio_vs_partial: f64,
    /// The same over the grasps partial found force closure (its slow kind: the others are
    /// settled by GJK without a hull).
    pub force_closure_time_ratio_vs_partial: f64,
    /// Mean points processed over partial's, on the grasps both evaluated.
    pub points_ratio_vs_partial: f64,
    /// Mean facets created over partial's, on the grasps both evaluated.
    pub facets_ratio_vs_partial: f64,
}

/// One Q∞ variant by the partial hull on the grasps of one k.
#[derive(Clone, Debug, PartialEq)]
pub struct QinfRow {
    /// The variant.
    pub variant: QinfVariant,
    /// Times, work and verdicts (a grasp the library cannot evaluate is counted in `errors`).
    pub summary: RunSummary,
}

/// Everything measured for one cone-edge count k.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgesResult {
    /// k.
    pub cone_edges: usize,
    /// Contacts per grasp.
    pub contacts: usize,
    /// Grasps where a method's value differs from partial's.
    pub disagreements: usize,
    /// One row per Q1 method, partial first.
    pub methods: Vec<MethodRow>,
    /// One row per Q∞ variant (none when k > `qinf_max_edges`).
    pub qinf: Vec<QinfRow>,
    /// One row per batch pool size.
    pub batch: Vec<BatchRow>,
}

/// The whole GWS benchmark.
#[derive(Clone, Debug, PartialEq)]
pub struct GwsReport {
    /// The seed of the grasps.
    pub seed: u64,
    /// The object the grasps are on.
    pub object: GwsObject,
    /// Contacts per grasp.
    pub contacts: usize,
    /// The batch pool sizes.
    pub threads: Vec<usize>,
    /// The machine's available parallelism.
    pub available_parallelism: usize,
    /// Timed rounds of each batch measurement.
    pub batch_rounds: usize,
    /// Minimum one-thread work per batch round, ms.
    pub batch_min_ms: f64,
    /// Q∞ was measured for k up to this.
    pub qinf_max_edges: usize,
    /// One entry per k, in the configured order.
    pub results: Vec<EdgesResult>,
}

/// Why the GWS benchmark could not run.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum GwsError {
    /// No grasps or no contacts asked for.
    Empty,
    /// A cone-edge count the friction model refuses.
    Edges(GraspError),
    /// A batch pool could not be started.
    Pool(PoolError),
    /// The partial method (the reference of every ratio) failed on some grasps.
    PartialFailed {
        /// How many.
        failed: usize,
        /// The first, `grasp i: message`.
        first: String,
    },
}

impl fmt::Display for GwsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GwsError::Empty => write!(f, "the benchmark needs at least one grasp and one contact"),
            GwsError::Edges(e) => write!(f, "cone edges: {e}"),
            GwsError::Pool(e) => write!(f, "{e}"),
            GwsError::PartialFailed { failed, first } => write!(
                f,
                "the partial method failed on {failed} grasps, first: {first}"
            ),
        }
    }
}

impl std::error::Error for GwsError {}

/// The methods in the order they run: partial, then the others once each.
fn ordered(methods: &[Method]) -> Vec<Method> {
    let mut out = vec![Method::Partial];
    for &m in methods {
        if !out.contains(&m) {
            out.push(m);
        }
    }
    out
}

/// Runs the benchmark. `progress` hears of each Q1 method's run (the slow part).
///
/// ```
/// use pqhull_cli::bench::gws::{GwsConfig, run};
/// let config = GwsConfig {
///     grasps: 4,
///     full_grasps: 2,
///     edges: vec![4],
///     threads: vec![1],
///     batch_rounds: 1,
///     batch_min_ms: 0.0,
///     ..GwsConfig::default()
/// };
/// let report = run(&config, &mut |_, _, _| {})?;
/// let k4 = &report.results[0];
/// assert_eq!(k4.disagreements, 0);
/// assert_eq!(k4.methods[0].method, "partial");
/// assert_eq!(k4.methods[1].summary.grasps, 2);
/// assert_eq!(k4.qinf.len(), 2);
/// assert_eq!(k4.batch[0].mismatches, 0);
/// assert_eq!(report.to_json()["benchmark"], "gws");
/// # Ok::<(), pqhull_cli::bench::gws::GwsError>(())
/// ```
///
/// # Errors
/// [`GwsError`]: an empty configuration, an invalid k, a pool that cannot start (checked before
/// any grasp is evaluated) or a failure of the partial method. Another method's failures on
/// some grasps are counted in its row, not fatal.
pub fn run(config: &GwsConfig, progress: Progress<'_>) -> Result<GwsReport, GwsError> {
    if config.grasps == 0 || config.contacts == 0 {
        return Err(GwsError::Empty);
    }
    let methods = ordered(&config.methods);
    let threads = if config.batch_rounds == 0 {
        Vec::new()
    } else {
        config.threads.clone()
    };
    let pools = Pools::new(&threads).map_err(GwsError::Pool)?;
    let mut variants: Vec<QinfVariant> = Vec::new();
    for &v in &config.qinf {
        if !variants.contains(&v) {
            variants.push(v);
        }
    }
    let mut results = Vec::new();
    for &k in &config.edges {
        let friction = FrictionModel::try_new(BAR_FRICTION, k).map_err(GwsError::Edges)?;
        let set = object_grasps(
            config.object,
            config.seed,
            config.grasps,
            config.contacts,
            friction,
        );
        let mut runs = Vec::new();
        let mut partial_results = Vec::new();
        for &m in &methods {
            let n = if m == Method::Partial {
                set.len()
            } else {
                config.full_grasps.min(set.len())
            };
            if n == 0 {
                continue;
            }
            let results = evaluate_all(&set[..n], Metric::Q1, m, &mut *progress);
            runs.push((m.name(), MethodRun::new(&results)));
            if m == Method::Partial {
                partial_results = results;
            }
        }
        let partial = &runs[0].1;
        if let Some(first) = partial.errors.first() {
            return Err(GwsError::PartialFailed {
                failed: partial.errors.len(),
                first: first.clone(),
            });
        }
        let partial_results: Vec<Evaluation> = partial_results.into_iter().flatten().collect();
        let disagreements = runs
            .iter()
            .skip(1)
            .map(|(_, run)| run.disagreements(partial))
            .sum();
        let methods = runs
            .iter()
            .map(|(name, run)| method_row(name, run, partial))
            .collect();
        let qinf = variants
            .iter()
            .filter(|_| k <= config.qinf_max_edges)
            .map(|&variant| qinf_row(&set, variant))
            .collect();
        let batch = batch(
            &set,
            &partial_results,
            &pools,
            config.batch_rounds,
            config.batch_min_ms,
        );
        results.push(EdgesResult {
            cone_edges: k,
            contacts: config.contacts,
            disagreements,
            methods,
            qinf,
            batch,
        });
    }
    Ok(GwsReport {
        seed: config.seed,
        object: config.object,
        contacts: config.contacts,
        threads,
        available_parallelism: available_parallelism(),
        batch_rounds: config.batch_rounds,
        batch_min_ms: config.batch_min_ms,
        qinf_max_edges: config.qinf_max_edges,
        results,
    })
}

/// A method's row: its summary and its ratios to `partial` over the grasps both evaluated
/// (time: median of per-grasp ratios; points and facets: ratio of means).
fn method_row(method: &'static str, run: &MethodRun, partial: &MethodRun) -> MethodRow {
    let pairs: Vec<(usize, usize)> = run.pairs(partial).collect();
    let mut time_ratio: Vec<f64> = pairs
        .iter()
        .map(|&(j, p)| run.times_us[j] / partial.times_us[p])
        .collect();
    let mut closure_ratio: Vec<f64> = pairs
        .iter()
        .zip(&time_ratio)
        .filter(|((_, p), _)| partial.closure[*p])
        .map(|(_, &r)| r)
        .collect();
    let points_ratio = mean(pairs.iter().map(|&(j, _)| run.points[j] as f64))
        / mean(pairs.iter().map(|&(_, p)| partial.points[p] as f64));
    let facets_ratio = mean(pairs.iter().map(|&(j, _)| run.facets[j] as f64))
        / mean(pairs.iter().map(|&(_, p)| partial.facets[p] as f64));
    MethodRow {
        method,
        summary: run.summary(),
        time_ratio_vs_partial: median(&mut time_ratio),
        force_closure_time_ratio_vs_partial: median(&mut closure_ratio),
        points_ratio_vs_partial: points_ratio,
        facets_ratio_vs_partial: facets_ratio,
    }
}

/// Q∞ of every grasp of `set` by the partial hull. A grasp the library cannot evaluate is
/// counted, not fatal (the timings are over the others).
fn qinf_row(set: &[pqhull::grasp::Grasp], variant: QinfVariant) -> QinfRow {
    let metric = Metric::QInf {
        with_zero_wrench: variant == QinfVariant::ZeroWrench,
    };
    let results = evaluate_all(set, metric, Method::Partial, &mut |_, _, _| {});
    QinfRow {
        variant,
        summary: MethodRun::new(&results).summary(),
    }
}

/// The members every summary row has, in a JSON object.
fn summary_json(method: &str, s: &RunSummary) -> Value {
    json!({
        "method": method,
        "grasps": s.grasps,
        "errors": s.errors,
        "first_error": s.first_error,
        "force_closure": s.force_closure,
        "median_us": s.median_us,
        "mean_us": s.mean_us,
        "max_us": s.max_us,
        "mean_points_processed": s.mean_points_processed,
        "mean_facets_created": s.mean_facets_created,
    })
}

impl MethodRow {
    /// The row as `pqh bench gws --json` gives it.
    pub fn to_json(&self) -> Value {
        let mut value = summary_json(self.method, &self.summary);
        value["time_ratio_vs_partial"] = json!(self.time_ratio_vs_partial);
        value["force_closure_time_ratio_vs_partial"] =
            json!(self.force_closure_time_ratio_vs_partial);
        value["points_ratio_vs_partial"] = json!(self.points_ratio_vs_partial);
        value["facets_ratio_vs_partial"] = json!(self.facets_ratio_vs_partial);
        value
    }
}

impl QinfRow {
    /// The row as `pqh bench gws --json` gives it.
    pub fn to_json(&self) -> Value {
        let mut value = summary_json("partial", &self.summary);
        value["variant"] = json!(self.variant.name());
        value
    }
}

impl BatchRow {
    /// The row as `pqh bench gws --json` gives it.
    pub fn to_json(&self) -> Value {
        json!({
            "threads": self.threads,
            "grasps": self.grasps,
            "rounds": self.rounds,
            "passes": self.passes,
            "median_s": self.median_s,
            "best_s": self.best_s,
            "grasps_per_s": self.grasps_per_s,
            "speedup_vs_1_thread": self.speedup_vs_1_thread,
            "mismatches": self.mismatches,
        })
    }
}

impl GwsReport {
    /// The report as `pqh bench gws --json` gives it.
    pub fn to_json(&self) -> Value {
        let results: Vec<Value> = self
            .results
            .iter()
            .map(|r| {
                json!({
                    "cone_edges": r.cone_edges,
                    "contacts": r.contacts,
                    "disagreements": r.disagreements,
                    "methods": r.methods.iter().map(MethodRow::to_json).collect::<Vec<_>>(),
                    "qinf": r.qinf.iter().map(QinfRow::to_json).collect::<Vec<_>>(),
                    "batch": r.batch.iter().map(BatchRow::to_json).collect::<Vec<_>>(),
                })
            })
            .collect();
        json!({
            "benchmark": "gws",
            "seed": self.seed,
            "object": self.object.name(),
            "threads": self.threads,
            "available_parallelism": self.available_parallelism,
            "batch_rounds": self.batch_rounds,
            "batch_min_ms": self.batch_min_ms,
            "qinf_max_edges": self.qinf_max_edges,
            "results": results,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn partial_runs_first_and_once() {
        assert_eq!(
            ordered(&[Method::Full, Method::Partial, Method::Full]),
            [Method::Partial, Method::Full]
        );
    }

    #[test]
    fn switches_leave_out_their_measurements() {
        let config = GwsConfig {
            grasps: 3,
            full_grasps: 0,
            edges: vec![4, 5],
            qinf_max_edges: 4,
            qinf: vec![QinfVariant::Plain, QinfVariant::Plain],
            batch_rounds: 0,
            ..GwsConfig::default()
        };
        let mut phases = Vec::new();
        let report = run(&config, &mut |label, done, _| {
            if done == 0 {
                phases.push(label.to_string())
            }
        })
        .unwrap();
        assert_eq!(phases, ["partial", "partial"]); // --full-grasps 0: partial only
        assert!(report.threads.is_empty());
        let [k4, k5] = &report.results[..] else {
            panic!("two results")
        };
        assert_eq!(k4.methods.len(), 1);
        assert_eq!(k4.qinf.len(), 1);
        assert!(k5.qinf.is_empty() && k5.batch.is_empty());
        let json = report.to_json();
        assert_eq!(json["results"][0]["qinf"][0]["variant"], "plain");
        assert_eq!(
            json["results"][0]["methods"][0]["time_ratio_vs_partial"],
            1.0
        );
        assert_eq!(
            run(
                &GwsConfig {
                    contacts: 0,
                    ..config.clone()
                },
                &mut |_, _, _| {}
            ),
            Err(GwsError::Empty)
        );
        assert!(matches!(
            run(
                &GwsConfig {
                    edges: vec![2],
                    ..config
                },
                &mut |_, _, _| {}
            ),
            Err(GwsError::Edges(_))
        ));
    }
}
