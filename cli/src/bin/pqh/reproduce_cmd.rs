//! `pqh reproduce`: the seed paper's figures, re-run, plotted and set beside its numbers.

use crate::error::CliError;
use clap::{Args, ValueEnum};
use pqhull_cli::reproduce::{self, FigureId, Size, plot};
use std::io::Write;
use std::path::PathBuf;

pub const LONG_ABOUT: &str = "\
Re-runs the experiments of Liu & Carpin's Figs. 6 to 10 and 12 (with Table 1's quantity) on this
machine. Into --output-dir it writes, for each figure, <fig>.csv (one row per grasp or sample: every
number the plot shows; an empty cell was not measured) and <fig>.svg (the plot, its caption giving
the paper's figure beside this run's), and summary.md (every side-by-side table and how each
experiment differs from the paper's). --size sets how many grasps each method runs; the qhull
method runs only in a build with the `qhull` feature.

Details (the figures, the methods, run times): docs/paper.md; README.md, \"The paper's
figures\".";

/// How large the experiments are.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum SizeArg {
    /// A few grasps per method (for tests and CI)
    Smoke,
    /// The paper's counts for the fast methods, subsets for the full-hull baselines
    Default,
    /// The paper's counts for every method of Figs. 6 and 8, k up to 64 in Fig. 7
    Full,
}

#[derive(Debug, Args)]
pub struct ReproduceArgs {
    /// Figures to run (fig6 fig7 fig8 fig9 fig10 fig12 table1, or 6 … 12); all when none
    #[arg(value_name = "FIGURE")]
    figures: Vec<String>,
    /// Where the CSV files, plots and summary.md go (created if missing)
    #[arg(long, short = 'o', default_value = "pqh-reproduce")]
    output_dir: PathBuf,
    /// How large the experiments are
    #[arg(long, value_enum, default_value_t = SizeArg::Default)]
    size: SizeArg,
    /// The same as --size full
    #[arg(long, conflicts_with = "size")]
    full: bool,
    /// Seed of the grasps
    #[arg(long, default_value_t = 1)]
    seed: u64,
}

pub fn run(args: &ReproduceArgs) -> Result<(), CliError> {
    let mut figures = Vec::new();
    for name in &args.figures {
        let id = FigureId::parse(name).ok_or_else(|| {
            CliError::Usage(format!(
                "unknown figure '{name}'; the figures are fig6, fig7, fig8, fig9, fig10, fig12, table1"
            ))
        })?;
        if !figures.contains(&id) {
            figures.push(id);
        }
    }
    if figures.is_empty() {
        figures = FigureId::ALL.to_vec();
    }
    let size = match (args.full, args.size) {
        (true, _) | (_, SizeArg::Full) => Size::Full,
        (_, SizeArg::Default) => Size::Default,
        (_, SizeArg::Smoke) => Size::Smoke,
    };
    let dir = &args.output_dir;
    std::fs::create_dir_all(dir)
        .map_err(|e| CliError::Usage(format!("{}: cannot create: {e}", dir.display())))?;
    let mut summary = format!(
        "# pqh reproduce --size {}\n\nSeed {}; qhull feature {}.\n\n",
        size.name(),
        args.seed,
        if cfg!(feature = "qhull") { "on" } else { "off" }
    );
    let stderr = std::io::stderr();
    for id in figures {
        let mut bars = crate::progress::Phases::default();
        let figure = reproduce::run(id, size, args.seed, &mut |label, done, total| {
            bars.update(&format!("{id}: {label}"), done, total)
        })
        .map_err(|e| CliError::Geometry(format!("{id}: {e}")))?;
        drop(bars);
        let written = figure.write_tables(dir).map_err(output)?;
        let svg = plot::figure_svg(&figure).map_err(output)?;
        let path = dir.join(format!("{id}.svg"));
        std::fs::write(&path, svg)
            .map_err(|e| CliError::Usage(format!("{}: cannot write: {e}", path.display())))?;
        summary.push_str(&figure.summary_markdown());
        summary.push('\n');
        let mut err = stderr.lock();
        let _ = writeln!(
            err,
            "pqh: note: {id}: wrote {} and {}",
            written
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", "),
            path.display()
        );
    }
    let path = dir.join("summary.md");
    std::fs::write(&path, &summary)
        .map_err(|e| CliError::Usage(format!("{}: cannot write: {e}", path.display())))?;
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    out.write_all(summary.as_bytes())?;
    Ok(())
}

fn output(e: reproduce::ReproduceError) -> CliError {
    CliError::Usage(e.to_string())
}
