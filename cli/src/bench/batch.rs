//! Batch throughput: [`evaluate_batch`] of one grasp set inside thread pools of several sizes.
//!
//! Each size gets its own pool, started by the library's thread policy
//! ([`pqhull::grasp::thread_pool`]: 1 to [`MAX_THREADS`](pqhull::grasp::MAX_THREADS) threads).

use super::stats::{median_of, min_or_infinity};
use pqhull::grasp::{Evaluation, Grasp, Method, Metric, ThreadsError, evaluate_batch, thread_pool};
use std::time::Instant;

/// A pool of the requested size could not be had: the library's [`ThreadsError`].
pub type PoolError = ThreadsError;

/// Thread pools of the given sizes, started once and reused by every measurement.
pub struct Pools {
    sizes: Vec<usize>,
    pools: Vec<rayon::ThreadPool>,
}

impl Pools {
    /// One pool per size, in order.
    ///
    /// # Errors
    /// [`PoolError`] for a size out of range (0, or above the library's `MAX_THREADS`), or a
    /// pool the system cannot start.
    pub fn new(sizes: &[usize]) -> Result<Pools, PoolError> {
        let pools = sizes
            .iter()
            .map(|&n| thread_pool(n))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Pools {
            sizes: sizes.to_vec(),
            pools,
        })
    }

    /// The pool sizes.
    pub fn sizes(&self) -> &[usize] {
        &self.sizes
    }

    /// Runs `work` inside pool `i`.
    fn install<R: Send>(&self, i: usize, work: impl FnOnce() -> R + Send) -> R {
        self.pools[i].install(work)
    }
}

/// One pool size's throughput.
#[derive(Clone, Debug, PartialEq)]
pub struct BatchRow {
    /// The pool size.
    pub threads: usize,
    /// Grasps in the set.
    pub grasps: usize,
    /// Timed rounds.
    pub rounds: usize,
    /// Passes over the set in each round.
    pub passes: usize,
    /// Median over the rounds of the seconds per pass.
    pub median_s: f64,
    /// The fastest round's seconds per pass.
    pub best_s: f64,
    /// Grasps per second at the median.
    pub grasps_per_s: f64,
    /// Throughput over that of the one-thread pool, when there is one.
    pub speedup_vs_1_thread: Option<f64>,
    /// Batch results that differ from the sequential ones (value bits or verdict), over all
    /// rounds: 0 unless something is wrong.
    pub mismatches: usize,
}

/// Passes per round: enough that one round of sequential work lasts `min_ms` (waking an idle
/// worker, slow on a virtual machine, would otherwise swamp a batch of small grasps), from 1 to
/// 1000.
pub fn passes(sequential: &[Evaluation], min_ms: f64) -> usize {
    let sequential_s: f64 = sequential
        .iter()
        .map(|q| q.stats.elapsed.as_secs_f64())
        .sum();
    ((min_ms / 1e3 / sequential_s.max(1e-9)).ceil() as usize).clamp(1, 1000)
}

/// Batch throughput of Q1 by the partial method on `set` in each of `pools`, `rounds` timed
/// rounds interleaved across the pools (so that a change of load hits them alike), each round
/// [`passes`] passes inside the pool after one untimed pass per pool. `sequential` holds the
/// one-by-one results the batch ones must equal. No rows when `rounds` is 0.
pub fn batch(
    set: &[Grasp],
    sequential: &[Evaluation],
    pools: &Pools,
    rounds: usize,
    min_ms: f64,
) -> Vec<BatchRow> {
    if rounds == 0 {
        return Vec::new();
    }
    let passes = passes(sequential, min_ms);
    let count = pools.sizes().len();
    for i in 0..count {
        pools.install(i, || q1_batch(set));
    }
    let mut seconds = vec![Vec::with_capacity(rounds); count];
    let mut mismatches = vec![0usize; count];
    for _ in 0..rounds {
        for i in 0..count {
            let started = Instant::now();
            // All passes inside the pool, so its threads are not put back to sleep in between.
            let results = pools.install(i, || {
                let mut results = Vec::new();
                for _ in 0..passes {
                    results = q1_batch(set);
                }
                results
            });
            seconds[i].push(started.elapsed().as_secs_f64() / passes as f64);
            mismatches[i] += results
                .iter()
                .zip(sequential)
                .filter(|(r, s)| {
                    r.as_ref().map_or(true, |r| {
                        r.value.map(f64::to_bits) != s.value.map(f64::to_bits)
                            || r.force_closure != s.force_closure
                    })
                })
                .count();
        }
    }
    let rate = |i: usize| set.len() as f64 / median_of(&seconds[i]);
    let one_thread = pools.sizes().iter().position(|&n| n == 1).map(rate);
    pools
        .sizes()
        .iter()
        .enumerate()
        .map(|(i, &threads)| {
            let grasps_per_s = rate(i);
            BatchRow {
                threads,
                grasps: set.len(),
                rounds,
                passes,
                median_s: median_of(&seconds[i]),
                best_s: min_or_infinity(&seconds[i]),
                grasps_per_s,
                speedup_vs_1_thread: one_thread.map(|one| grasps_per_s / one),
                mismatches: mismatches[i],
            }
        })
        .collect()
}

/// [`evaluate_batch`] of Q1 by the partial method, which every grasp set is accepted by.
fn q1_batch(set: &[Grasp]) -> Vec<Result<Evaluation, pqhull::grasp::QualityError>> {
    evaluate_batch(set, Metric::Q1, Method::Partial, None)
        .expect("Q1 by the partial method, without a wrench space, is never refused")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::workloads::bar_grasps;
    use pqhull::grasp::Evaluator;
    use pqhull::grasp::FrictionModel;

    #[test]
    fn batch_results_equal_the_sequential_ones() {
        let set = bar_grasps(5, 4, 4, FrictionModel::try_new(0.5, 4).unwrap());
        let mut evaluator = Evaluator::new(Metric::Q1, Method::Partial, None).unwrap();
        let sequential: Vec<Evaluation> =
            set.iter().map(|g| evaluator.evaluate(g).unwrap()).collect();
        let pools = Pools::new(&[1]).unwrap();
        let rows = batch(&set, &sequential, &pools, 2, 0.0);
        assert_eq!(rows.len(), 1);
        let row = &rows[0];
        assert_eq!(
            (row.threads, row.grasps, row.rounds, row.passes),
            (1, 4, 2, 1)
        );
        assert_eq!(row.mismatches, 0);
        assert_eq!(row.speedup_vs_1_thread, Some(1.0));
        assert!(row.best_s <= row.median_s);
        assert!(batch(&set, &sequential, &pools, 0, 0.0).is_empty());
        assert!(Pools::new(&[1, 0]).is_err());
    }
}
