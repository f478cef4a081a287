//! Progress bars on stderr for long work: shown only on a terminal and without `--quiet`.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::quality::Method;
use pqhull::mesh::Mesh;
use pqhull::plan::{PlanConfig, PlanError, PlanReport, plan_with_progress};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};

static QUIET: AtomicBool = AtomicBool::new(false);

/// `--quiet`: no progress bars at all.
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, Ordering::Relaxed);
}

/// A bar counting to `len`, labelled `message`; hidden when stderr is not a terminal or with
/// `--quiet`, so pipes and CI logs stay clean.
pub fn bar(len: usize, message: &str) -> ProgressBar {
    let visible = !QUIET.load(Ordering::Relaxed) && std::io::stderr().is_terminal();
    let target = if visible {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    };
    let bar = ProgressBar::with_draw_target(Some(len as u64), target);
    if let Ok(style) =
        ProgressStyle::with_template("{msg:>14} [{bar:40}] {pos}/{len} ({elapsed}, eta {eta})")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(message.to_string());
    bar
}

/// Runs `work` with a bar counting to `len`, which `work` moves by calling the function it is
/// given with the count done; the bar is cleared afterwards.
pub fn counting<T>(len: usize, message: &str, work: impl FnOnce(&mut dyn FnMut(usize)) -> T) -> T {
    let bar = bar(len, message);
    let result = work(&mut |done| bar.set_position(done as u64));
    bar.finish_and_clear();
    result
}

/// One plan (`pqhull::plan::plan_with_progress`) with a bar labelled `label`.
pub fn plan(
    mesh: &Mesh,
    space: Option<&ObjectWrenchSpace>,
    config: &PlanConfig,
    method: Method,
    label: &str,
) -> Result<PlanReport, PlanError> {
    warn_if_long(mesh, space, config, method, label)?;
    counting(config.samples, label, |tick| {
        plan_with_progress(mesh, space, config, method, tick)
    })
}

/// The bars of the library's `(label, done, total)` progress reports (`pqhull_cli::bench`): a new
/// bar whenever a phase starts (`done == 0`), cleared when it is complete or this is dropped.
#[derive(Default)]
pub struct Phases {
    bar: Option<ProgressBar>,
}

impl Phases {
    /// Shows one report.
    pub fn update(&mut self, label: &str, done: usize, total: usize) {
        if done == 0 {
            self.clear();
            self.bar = Some(bar(total, label));
        }
        if let Some(bar) = &self.bar {
            bar.set_position(done as u64);
        }
        if done >= total {
            self.clear();
        }
    }

    fn clear(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}

impl Drop for Phases {
    fn drop(&mut self) {
        self.clear();
    }
}

/// Samples timed before a plan starts, to estimate its length.
const PROBE_SAMPLES: usize = 2;

/// A plan whose estimate exceeds this prints a note first (seconds).
const LONG_PLAN_SECONDS: f64 = 10.0;

/// Times the first [`PROBE_SAMPLES`] samples of the plan (the same grasps it starts with, the seed
/// being the same) and, when the whole plan would take longer than [`LONG_PLAN_SECONDS`], says so
/// before it starts, with the estimate: Q∞ by a full method hulls k^m points per sample, and a
/// full hull creates every facet.
fn warn_if_long(
    mesh: &Mesh,
    space: Option<&ObjectWrenchSpace>,
    config: &PlanConfig,
    method: Method,
    label: &str,
) -> Result<(), PlanError> {
    if config.samples <= 2 * PROBE_SAMPLES {
        return Ok(());
    }
    let probe = PlanConfig {
        samples: PROBE_SAMPLES,
        ..*config
    };
    let started = std::time::Instant::now();
    plan_with_progress(mesh, space, &probe, method, |_| {})?;
    let each = started.elapsed().as_secs_f64() / PROBE_SAMPLES as f64;
    let total = each * config.samples as f64;
    if total > LONG_PLAN_SECONDS {
        eprintln!(
            "pqh: note: {label} ({} by {}): about {} for {} samples ({:.2} s each over the first \
             {PROBE_SAMPLES}); --samples or --full-samples make it shorter",
            config.metric.name(),
            method.name(),
            duration(total),
            config.samples,
            each
        );
    }
    Ok(())
}

/// `secs` for a person: seconds, or minutes, or hours.
fn duration(secs: f64) -> String {
    if secs < 120.0 {
        format!("{secs:.0} s")
    } else if secs < 7200.0 {
        format!("{:.0} min", secs / 60.0)
    } else {
        format!("{:.1} h", secs / 3600.0)
    }
}
