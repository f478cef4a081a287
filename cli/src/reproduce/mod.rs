//! The seed paper's experiments, re-run: each figure's per-grasp data, its plot and its numbers
//! beside the paper's. What `pqh reproduce` runs.
//!
//! * [`gws`] — Fig. 6 (PQHGWS against QuickHull on random bar grasps: points processed,
//!   hyperplanes created, time) and Fig. 7 (their ratios as the cone edges grow);
//! * [`ows`] — Fig. 8 (PQHOWS against brute force and the ellipsoid method) and Fig. 9 (the
//!   ellipsoid's error);
//! * [`planning`] — Fig. 10 (the Q1-best and the OWS-best grasp of one set of samples) and
//!   Fig. 12 with Table 1's quantity (planning by random sampling with each metric, partial
//!   against full hull).
//!
//! Every experiment returns a [`Figure`]: its data as [`Table`]s (written as CSV, one row per
//! grasp or sample), the side-by-side rows ([`Comparison`]: the paper's figure and ours for the
//! same quantity) and an SVG drawn from exactly those tables
//! ([`plot`]).
//!
//! The paper's numbers quoted here are those its text states (as restated in the project's
//! issue tracker); where this crate does not hold the paper's number for a quantity, the
//! comparison says so instead of guessing.

pub mod gws;
pub mod ows;
pub mod planning;
pub mod plot;
mod table;
pub mod table1;

pub use table::{Column, Table};

use std::fmt;
use std::path::{Path, PathBuf};

/// Progress of a long experiment (the same callback as the benchmarks').
pub use crate::bench::Progress;

/// How large the experiments are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    /// A few grasps per method, for tests and CI.
    Smoke,
    /// The paper's grasp counts for the fast methods, subsets for the slow full-hull baselines.
    /// The default.
    Default,
    /// The paper's grasp counts for every method of Figs. 6 and 8 (their full-hull baselines on
    /// every grasp), Fig. 7 up to k = 64, larger sample sets for Figs. 10 and 12. The default's
    /// and this size's run times are in docs/paper.md.
    Full,
}

impl Size {
    /// The name `pqh reproduce --size` takes.
    pub fn name(self) -> &'static str {
        match self {
            Size::Smoke => "smoke",
            Size::Default => "default",
            Size::Full => "full",
        }
    }
}

/// The figures, by the paper's numbering.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum FigureId {
    /// PQHGWS against QuickHull on bar grasps.
    Fig6,
    /// The ratios of Fig. 6 as the cone edges grow.
    Fig7,
    /// PQHOWS against brute force and the ellipsoid method.
    Fig8,
    /// The ellipsoid method's relative error.
    Fig9,
    /// The Q1-best and the OWS-best grasp.
    Fig10,
    /// Planning with each metric (and Table 1's speed-up).
    Fig12,
    /// Table 1: the descent planner on five objects, full against partial hull.
    Table1,
}

impl FigureId {
    /// Every figure, in the paper's order.
    pub const ALL: [FigureId; 7] = [
        FigureId::Fig6,
        FigureId::Fig7,
        FigureId::Fig8,
        FigureId::Fig9,
        FigureId::Fig10,
        FigureId::Fig12,
        FigureId::Table1,
    ];

    /// `fig6`, …: the name of the figure's files and of `pqh reproduce`'s argument.
    pub fn name(self) -> &'static str {
        match self {
            FigureId::Fig6 => "fig6",
            FigureId::Fig7 => "fig7",
            FigureId::Fig8 => "fig8",
            FigureId::Fig9 => "fig9",
            FigureId::Fig10 => "fig10",
            FigureId::Fig12 => "fig12",
            FigureId::Table1 => "table1",
        }
    }

    /// The figure of a name (`fig6` or `6`; `table1` is Fig. 12's).
    pub fn parse(name: &str) -> Option<FigureId> {
        let name = name.trim().to_ascii_lowercase();
        let name = name.strip_prefix("fig").unwrap_or(&name);
        Some(match name {
            "6" => FigureId::Fig6,
            "7" => FigureId::Fig7,
            "8" => FigureId::Fig8,
            "9" => FigureId::Fig9,
            "10" => FigureId::Fig10,
            "12" => FigureId::Fig12,
            "table1" | "table" => FigureId::Table1,
            _ => return None,
        })
    }
}

impl fmt::Display for FigureId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One side-by-side row: a quantity, what the paper reports and what this run measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// The quantity, e.g. "points processed, QuickHull / PQHGWS".
    pub quantity: String,
    /// The paper's figure as its text gives it, or why there is none here.
    pub paper: String,
    /// This run's figure.
    pub pqhull: String,
}

impl Comparison {
    /// A row.
    pub fn new(quantity: impl Into<String>, paper: &str, pqhull: impl Into<String>) -> Self {
        Comparison {
            quantity: quantity.into(),
            paper: paper.to_string(),
            pqhull: pqhull.into(),
        }
    }
}

/// What the paper's text does not give this crate for a quantity.
pub const PAPER_NOT_QUOTED: &str = "not restated here";

/// One reproduced figure: data, side-by-side rows, and how the experiment differs from the
/// paper's.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// Which figure.
    pub id: FigureId,
    /// A title for the plot.
    pub title: String,
    /// The data, one CSV file each (`<figure>.csv`, then `<figure>_<name>.csv`).
    pub tables: Vec<Table>,
    /// The paper's figures beside ours.
    pub comparisons: Vec<Comparison>,
    /// Where this experiment differs from the paper's (hardware, baseline, arithmetic, …).
    pub differences: Vec<String>,
}

impl Figure {
    /// The table named `name` (the first table's name is the figure's).
    pub fn table(&self, name: &str) -> Option<&Table> {
        self.tables.iter().find(|t| t.name == name)
    }

    /// Writes every table as CSV into `dir`; returns the paths written.
    ///
    /// # Errors
    /// The first I/O error, with the path.
    pub fn write_tables(&self, dir: &Path) -> Result<Vec<PathBuf>, ReproduceError> {
        self.tables
            .iter()
            .map(|t| {
                let path = dir.join(format!("{}.csv", t.name));
                std::fs::write(&path, t.to_csv()).map_err(|e| ReproduceError::io(&path, e))?;
                Ok(path)
            })
            .collect()
    }

    /// The figure's section of the summary: a Markdown table of paper against pqhull, then the
    /// differences.
    pub fn summary_markdown(&self) -> String {
        let mut out = format!("## {} — {}\n\n", self.id.name(), self.title);
        out.push_str("| quantity | paper | pqhull |\n|---|---|---|\n");
        for c in &self.comparisons {
            out.push_str(&format!(
                "| {} | {} | {} |\n",
                c.quantity, c.paper, c.pqhull
            ));
        }
        if !self.differences.is_empty() {
            out.push('\n');
            for d in &self.differences {
                out.push_str(&format!("- {d}\n"));
            }
        }
        out
    }
}

/// Why an experiment could not run or its results could not be written.
#[derive(Debug)]
#[non_exhaustive]
pub enum ReproduceError {
    /// An experiment failed (a method's error, an invalid configuration), with what it was.
    Experiment(String),
    /// A file could not be written.
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A plot could not be drawn.
    Plot(String),
}

impl ReproduceError {
    fn io(path: &Path, source: std::io::Error) -> Self {
        ReproduceError::Io {
            path: path.to_path_buf(),
            source,
        }
    }
}

impl fmt::Display for ReproduceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReproduceError::Experiment(e) => write!(f, "{e}"),
            ReproduceError::Io { path, source } => write!(f, "{}: {source}", path.display()),
            ReproduceError::Plot(e) => write!(f, "plot: {e}"),
        }
    }
}

impl std::error::Error for ReproduceError {}

/// Runs one figure's experiment at `size` with `seed`.
///
/// # Errors
/// [`ReproduceError::Experiment`] when a method fails.
pub fn run(
    id: FigureId,
    size: Size,
    seed: u64,
    progress: Progress<'_>,
) -> Result<Figure, ReproduceError> {
    match id {
        FigureId::Fig6 => gws::fig6(size, seed, progress),
        FigureId::Fig7 => gws::fig7(size, seed, progress),
        FigureId::Fig8 => ows::fig8(size, seed, progress),
        FigureId::Fig9 => ows::fig9(size, seed, progress),
        FigureId::Fig10 => planning::fig10(size, seed, progress),
        FigureId::Fig12 => planning::fig12(size, seed, progress),
        FigureId::Table1 => table1::table1(size, seed, progress),
    }
}
