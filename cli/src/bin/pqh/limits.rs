//! Size limits of `pqh`'s options, checked by clap while the command line is parsed — before
//! anything is allocated. The library's own limits ([`MAX_CONE_EDGES`], [`MAX_CONTACTS`],
//! [`MAX_SAMPLES`]) apply to every option that sizes the same thing; docs/limits.md lists them all
//! with the reasons.

pub use pqhull::grasp::{MAX_CONE_EDGES, MAX_CONTACTS, MIN_CONE_EDGES};
pub use pqhull::plan::MAX_SAMPLES;

/// The most worker threads `--threads` starts (`pqh grasp`, each pool of `pqh bench gws`): the
/// library's one thread policy (see [`pqhull::grasp::MAX_THREADS`] for why).
pub use pqhull::grasp::MAX_THREADS;

/// The most random grasps `pqh bench gws|ows --grasps` generates.
///
/// Why: a benchmark keeps every grasp and every result in memory (a few hundred bytes a grasp)
/// and evaluates each by several methods; 100,000 is far more than a stable median needs.
pub const MAX_BENCH_GRASPS: usize = 100_000;

/// The most timed runs per case of `pqh bench hull --repeats` (the library's
/// [`MAX_REPEATS`](pqhull_cli::bench::hull::MAX_REPEATS)).
///
/// Why: the best of a few runs is what the suite reports; a thousand runs is a thousand times
/// the suite's work (cases of up to about 100,000 points; their times in docs/benchmarks.md),
/// far more than a stable best needs.
pub const MAX_BENCH_REPEATS: usize = pqhull_cli::bench::hull::MAX_REPEATS;

/// The most Minkowski points per grasp (`Grasp::minkowski_points`) that Q∞ by a full method
/// (`--method full` or `qhull`) hulls without `--force` (`pqh grasp`) or an explicit
/// `--full-samples` (`pqh plan`).
///
/// Why: the full hull of a Minkowski sum is exact but grows fast with its points, which are
/// highly degenerate: 4 contacts × 8 edges (4,096 points, the bound) take about a second and
/// 175 MB by the full method (Qhull's method 2.7 s), 4 × 16 (65,536) 35 s and 2.7 GB
/// (docs/limits.md, "Q∞ by a full method: time and memory"), while the partial method gives
/// the same value in milliseconds without materialising the sum.
pub const FULL_QINF_POINTS: usize = 4096;

/// The most Minkowski points per sample for which `pqh plan --metric qinf` compares with the
/// full method by default (on its first 2 samples; `--full-samples` asks for it above).
///
/// Why lower than [`FULL_QINF_POINTS`]: the default comparison is a side result that few samples
/// make meaningful (5 of the 200 default samples on the built-in object are force closure, so
/// the first 2 rarely are). At 4 contacts × 8 edges it spent 1.6 s of a 1.7 s plan comparing
/// nothing; below 1,000 points it costs a fraction of that.
pub const PLAN_FULL_QINF_POINTS: usize = 1000;

/// The parser of a whole-number option from `min` to `max` inclusive, run while the command line
/// is parsed; its error names the bound (clap adds the option and the value).
pub fn count(
    min: usize,
    max: usize,
) -> impl Fn(&str) -> Result<usize, String> + Clone + Send + Sync + 'static {
    move |text: &str| {
        let digits = text.strip_prefix('+').unwrap_or(text);
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(format!("not a whole number from {min} to {max}"));
        }
        // All digits: a parse failure can only be an overflow, far over the limit.
        let n = digits.parse::<usize>().unwrap_or(usize::MAX);
        if n < min {
            Err(format!("{n} is too small (at least {min})"))
        } else if n > max {
            Err(format!("{digits} is over the limit (at most {max})"))
        } else {
            Ok(n)
        }
    }
}

/// `--threads`: 1 to [`MAX_THREADS`].
pub fn threads() -> impl Fn(&str) -> Result<usize, String> + Clone + Send + Sync + 'static {
    count(1, MAX_THREADS)
}

/// Cone edges: [`MIN_CONE_EDGES`] to [`MAX_CONE_EDGES`].
pub fn cone_edges() -> impl Fn(&str) -> Result<usize, String> + Clone + Send + Sync + 'static {
    count(MIN_CONE_EDGES, MAX_CONE_EDGES)
}

/// Contacts per grasp: 1 to [`MAX_CONTACTS`].
pub fn contacts() -> impl Fn(&str) -> Result<usize, String> + Clone + Send + Sync + 'static {
    count(1, MAX_CONTACTS)
}

/// Samples of a plan (`pqh plan`, `pqh demo`): 1 to [`MAX_SAMPLES`].
pub fn samples() -> impl Fn(&str) -> Result<usize, String> + Clone + Send + Sync + 'static {
    count(1, MAX_SAMPLES)
}

/// Grasps of a benchmark: 1 to [`MAX_BENCH_GRASPS`].
pub fn bench_grasps() -> impl Fn(&str) -> Result<usize, String> + Clone + Send + Sync + 'static {
    count(1, MAX_BENCH_GRASPS)
}

/// Grasps of a benchmark's slow methods (0 turns them off): 0 to [`MAX_BENCH_GRASPS`].
pub fn bench_subset() -> impl Fn(&str) -> Result<usize, String> + Clone + Send + Sync + 'static {
    count(0, MAX_BENCH_GRASPS)
}

/// Timed runs per case of `pqh bench hull`: 1 to [`MAX_BENCH_REPEATS`].
pub fn bench_repeats() -> impl Fn(&str) -> Result<usize, String> + Clone + Send + Sync + 'static {
    count(1, MAX_BENCH_REPEATS)
}

/// `pqh demo`'s options are defined in `demo_cmd.rs`; their limits are attached here, on the
/// built command (the same parsers and help as `pqh plan`'s).
pub fn with_demo_limits(command: clap::Command) -> clap::Command {
    command.mut_subcommand("demo", |demo| {
        demo.mut_arg("samples", |a| {
            a.value_parser(samples())
                .help(format!("Grasps sampled per metric, 1 to {MAX_SAMPLES}"))
        })
        .mut_arg("full_samples", |a| {
            a.value_parser(count(0, MAX_SAMPLES)).help(format!(
                "Samples for the (slow) full-hull runs: the first ones of the same sequence, \
                 0 to {MAX_SAMPLES} (at least 1 is run)"
            ))
        })
    })
}
