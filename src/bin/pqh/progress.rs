//! Progress bars on stderr for long work: shown only on a terminal and without `--quiet`.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::mesh::Mesh;
use pqhull::plan::{PlanConfig, PlanError, PlanMethod, PlanReport, plan_with_progress};
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
    method: PlanMethod,
    label: &str,
) -> Result<PlanReport, PlanError> {
    counting(config.samples, label, |tick| {
        plan_with_progress(mesh, space, config, method, tick)
    })
}

/// The bars of the library's `(label, done, total)` progress reports (`pqhull::bench`): a new
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
