//! One method's run over a grasp set: per-grasp times, work and verdicts, and their summary.

use super::Progress;
use super::stats::{max_or_zero, mean, median_of, micros};
use pqhull::grasp::{Evaluation, Evaluator, Grasp, Method, Metric};

/// Evaluates `set` one grasp after another with one [`Evaluator`] (its buffers reused, as a
/// planner would); a grasp the method cannot evaluate keeps its error's message (every grasp
/// keeps the evaluator's refusal, when the method does not compute the metric). `progress` is
/// called with the method's name before the first grasp and after each.
pub fn evaluate_all(
    set: &[Grasp],
    metric: Metric,
    method: Method,
    progress: Progress<'_>,
) -> Vec<Result<Evaluation, String>> {
    let mut evaluator = Evaluator::new(metric, method, None).map_err(|e| e.to_string());
    let label = method.name();
    progress(label, 0, set.len());
    set.iter()
        .enumerate()
        .map(|(i, g)| {
            let q = match &mut evaluator {
                Ok(evaluator) => evaluator.evaluate(g).map_err(|e| e.to_string()),
                Err(refused) => Err(refused.clone()),
            };
            progress(label, i + 1, set.len());
            q
        })
        .collect()
}

/// The per-grasp figures of one method's run, over the grasps it could evaluate.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MethodRun {
    /// The grasps' indices in the set, increasing.
    pub grasp: Vec<usize>,
    /// Time per grasp, µs.
    pub times_us: Vec<f64>,
    /// Points added to the hull per grasp.
    pub points: Vec<usize>,
    /// Facets created per grasp.
    pub facets: Vec<usize>,
    /// Force closure per grasp.
    pub closure: Vec<bool>,
    /// The metric per grasp.
    pub values: Vec<f64>,
    /// The grasps the method could not evaluate (e.g. Qhull's topology errors on nearly flat
    /// wrench sets), as `grasp i: message`: counted and shown, not fatal.
    pub errors: Vec<String>,
}

impl MethodRun {
    /// The run of `results` (entry `i` is grasp `i`'s).
    pub fn new(results: &[Result<Evaluation, String>]) -> MethodRun {
        let mut run = MethodRun::default();
        for (i, result) in results.iter().enumerate() {
            match result {
                Ok(q) => {
                    run.grasp.push(i);
                    run.times_us.push(micros(q.stats.elapsed));
                    run.points.push(q.stats.points_processed);
                    run.facets.push(q.stats.facets_created);
                    run.closure.push(q.force_closure);
                    run.values
                        .push(q.value.expect("Q1 and Q∞ always have a value"));
                }
                Err(e) => run.errors.push(format!("grasp {i}: {e}")),
            }
        }
        run
    }

    /// How many evaluated grasps were force closure.
    pub fn force_closure(&self) -> usize {
        self.closure.iter().filter(|&&c| c).count()
    }

    /// The entry of grasp `g`, when this method evaluated it.
    pub fn at(&self, g: usize) -> Option<usize> {
        self.grasp.binary_search(&g).ok()
    }

    /// Pairs of entries (this run's, `base`'s) for the grasps both evaluated.
    pub fn pairs<'a>(&'a self, base: &'a MethodRun) -> impl Iterator<Item = (usize, usize)> + 'a {
        (0..self.grasp.len()).filter_map(|j| base.at(self.grasp[j]).map(|p| (j, p)))
    }

    /// The grasps where this run's value and `base`'s differ by more than 1e−9 relative (or
    /// 1e−12 absolute near zero), among those both evaluated.
    pub fn disagreements(&self, base: &MethodRun) -> usize {
        self.pairs(base)
            .filter(|&(j, p)| {
                let (a, b) = (self.values[j], base.values[p]);
                (a - b).abs() > 1e-9 * a.abs().max(1e-3)
            })
            .count()
    }

    /// The summary of this run (see [`RunSummary`]).
    pub fn summary(&self) -> RunSummary {
        RunSummary {
            grasps: self.grasp.len(),
            errors: self.errors.len(),
            first_error: self.errors.first().cloned(),
            force_closure: self.force_closure(),
            median_us: median_of(&self.times_us),
            mean_us: mean(self.times_us.iter().copied()),
            max_us: max_or_zero(&self.times_us),
            mean_points_processed: mean(self.points.iter().map(|&p| p as f64)),
            mean_facets_created: mean(self.facets.iter().map(|&p| p as f64)),
        }
    }
}

/// What a method's run over a grasp set measured.
#[derive(Clone, Debug, PartialEq)]
pub struct RunSummary {
    /// Grasps evaluated.
    pub grasps: usize,
    /// Grasps the method could not evaluate.
    pub errors: usize,
    /// The first of those errors, `grasp i: message`.
    pub first_error: Option<String>,
    /// Force-closure grasps among those evaluated.
    pub force_closure: usize,
    /// Median time per grasp, µs (NaN when none was evaluated).
    pub median_us: f64,
    /// Mean time per grasp, µs.
    pub mean_us: f64,
    /// Largest time per grasp, µs (0 when none).
    pub max_us: f64,
    /// Mean points added to the hull per grasp.
    pub mean_points_processed: f64,
    /// Mean facets created per grasp.
    pub mean_facets_created: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::workloads::bar_grasps;
    use pqhull::grasp::FrictionModel;

    #[test]
    fn runs_pair_up_by_grasp_and_report_progress() {
        let set = bar_grasps(2, 5, 4, FrictionModel::try_new(0.5, 6).unwrap());
        let mut calls = Vec::new();
        let results = evaluate_all(&set, Metric::Q1, Method::Partial, &mut |l, d, t| {
            calls.push((l.to_string(), d, t))
        });
        assert_eq!(calls.len(), 6);
        assert_eq!(calls[0], ("partial".to_string(), 0, 5));
        assert_eq!(calls[5].1, 5);
        let partial = MethodRun::new(&results);
        let mut fewer = results[..3].to_vec();
        fewer[1] = Err("refused".to_string());
        let other = MethodRun::new(&fewer);
        assert_eq!(other.grasp, [0, 2]);
        assert_eq!(other.errors, ["grasp 1: refused"]);
        assert_eq!(other.pairs(&partial).collect::<Vec<_>>(), [(0, 0), (1, 2)]);
        assert_eq!(other.disagreements(&partial), 0);
        let summary = other.summary();
        assert_eq!((summary.grasps, summary.errors), (2, 1));
        assert_eq!(summary.first_error.as_deref(), Some("grasp 1: refused"));
        assert!(summary.median_us <= summary.max_us);
    }
}
