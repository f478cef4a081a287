//! `pqh bench hull`: the hull suite, pqhull's full hull and Qhull side by side in one run.

use crate::error::CliError;
use clap::Args;
use clap::builder::PossibleValuesParser;
use pqhull_cli::bench::hull::{
    self, CaseRow, FAMILY_NAMES, HullBenchConfig, HullBenchReport, Preset,
};
use std::io::Write;

pub const LONG_ABOUT: &str = "\
pqhull's full hull against Qhull on the same points, case by case, all generated in-process
from --seed: the rbox families in 3-D to 6-D, and in 2-D, 7-D and 8-D when --dimensions asks
(corners: cube corners and face centres; shell: a thin shell; clusters: near-duplicates;
tilted: the faces of a rotated cube, coplanar only up to rounding), the
integer grids {0, ..., m-1}^D, the raw wrenches of a force-closure random 4-contact bar grasp
(8, 16, 32 edges; timed as Hull::try_new and as the GWS volume) and the materialised Minkowski
sum of a 3-contact one (6, 8 edges; timed as plain Q-inf by the full method and as
Hull::try_new). Each call: the best of --repeats wall-clock runs on one
thread, interleaved with Qhull's (absent without the `qhull` feature); vertex counts and
Hull::check once, untimed. Compare rows of one run.

Details and a measured run: docs/benchmarks.md, \"Hull suite against Qhull\"; limits:
docs/limits.md.";

#[derive(Debug, Args)]
pub struct HullArgs {
    /// Only these families, comma separated
    #[arg(long, value_delimiter = ',', value_name = "NAME,...",
          value_parser = PossibleValuesParser::new(FAMILY_NAMES))]
    pub families: Vec<String>,
    /// Only these dimensions, comma separated, each 2 to 8 (3 to 6 when not given; 2, 7 and 8
    /// only when asked)
    #[arg(long, value_delimiter = ',', value_name = "D,...",
          value_parser = crate::limits::count(2, 8))]
    pub dimensions: Vec<usize>,
    /// Small sizes: a twentieth of the point counts, smaller grids, fewer edges (what tests run)
    #[arg(long)]
    pub quick: bool,
    /// Timed runs of each call, the best reported, 1 to 1000
    #[arg(long, default_value_t = 3, value_parser = crate::limits::bench_repeats())]
    pub repeats: usize,
    /// Seed of every generated input
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// One JSON document instead of the table
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: &HullArgs) -> Result<(), CliError> {
    let config = HullBenchConfig {
        preset: if args.quick {
            Preset::Quick
        } else {
            Preset::Standard
        },
        families: args.families.clone(),
        dimensions: args.dimensions.clone(),
        repeats: args.repeats,
        seed: args.seed,
    };
    if !cfg!(feature = "qhull") {
        eprintln!(
            "pqh: note: built without the `qhull` feature: pqhull's columns only (build with \
             --features qhull for Qhull's)"
        );
    }
    let mut bars = crate::progress::Phases::default();
    let report = hull::run(&config, &mut |label, done, total| {
        bars.update(label, done, total)
    })
    .map_err(|e| CliError::Usage(e.to_string()))?;
    drop(bars);
    crate::format::write_report(
        args.json,
        || report.to_json(),
        |out| print_table(out, &report),
    )?;
    match report.failures() {
        0 => Ok(()),
        n => Err(CliError::Geometry(format!(
            "{n} rows where pqhull failed or its hull failed Hull::check"
        ))),
    }
}

/// A time or ratio as the table prints it.
fn fixed(x: Option<f64>, decimals: usize) -> String {
    match x {
        Some(x) if x.is_finite() => format!("{x:.decimals$}"),
        _ => "-".to_string(),
    }
}

fn print_table(out: &mut impl Write, report: &HullBenchReport) -> std::io::Result<()> {
    let qhull = report.qhull_available;
    writeln!(
        out,
        "Full hull, pqhull{} ({} preset, best of {}, seed {})",
        if qhull { " vs Qhull" } else { "" },
        report.preset.name(),
        report.repeats,
        report.seed
    )?;
    if qhull {
        writeln!(
            out,
            "{:<26} {:>2} {:>7} {:>10} {:>10} {:>8} {:>15} {:>5}",
            "case", "D", "points", "pqhull ms", "qhull ms", "q/pq", "vertices pq/q", "check"
        )?;
    } else {
        writeln!(
            out,
            "{:<26} {:>2} {:>7} {:>10} {:>8} {:>5}",
            "case", "D", "points", "pqhull ms", "vertices", "check"
        )?;
    }
    let mut notes = Vec::new();
    for row in &report.rows {
        let (ms, vertices, check) = match &row.pqhull {
            Ok(p) => (
                Some(p.ms),
                p.vertices.to_string(),
                if p.check.is_ok() { "ok" } else { "FAIL" },
            ),
            Err(_) => (None, "-".to_string(), "FAIL"),
        };
        if qhull {
            let (q_ms, q_vertices) = match &row.qhull {
                Some(Ok(q)) => (Some(q.ms), q.vertices.to_string()),
                _ => (None, "-".to_string()),
            };
            writeln!(
                out,
                "{:<26} {:>2} {:>7} {:>10} {:>10} {:>8} {:>15} {:>5}",
                row.label(),
                row.case.dimension,
                row.points,
                fixed(ms, 3),
                fixed(q_ms, 3),
                fixed(row.ratio(), 2),
                format!("{vertices}/{q_vertices}"),
                check
            )?;
        } else {
            writeln!(
                out,
                "{:<26} {:>2} {:>7} {:>10} {:>8} {:>5}",
                row.label(),
                row.case.dimension,
                row.points,
                fixed(ms, 3),
                vertices,
                check
            )?;
        }
        notes.extend(row_notes(row));
    }
    for note in &notes {
        writeln!(out, "  !! {note}")?;
    }
    if qhull {
        let summary = |m: Option<(f64, &CaseRow)>| match m {
            Some((x, row)) => format!("{x:.2} ({}, {}-D)", row.label(), row.case.dimension),
            None => "-".to_string(),
        };
        writeln!(
            out,
            "min qhull/pqhull: {} over all cases; {} over the random ones (cube, sphere)",
            summary(report.min_ratio()),
            summary(report.min_random_ratio())
        )?;
    }
    Ok(())
}

/// What a row's cells cannot say: errors, a failed check, a grasp that is not force closure.
fn row_notes(row: &CaseRow) -> Vec<String> {
    let mut notes = Vec::new();
    let label = format!("{} ({}-D)", row.label(), row.case.dimension);
    match &row.pqhull {
        Err(e) => notes.push(format!("{label}: pqhull failed: {e}")),
        Ok(p) => {
            if let Err(e) = &p.check {
                notes.push(format!("{label}: Hull::check failed: {e}"));
            }
        }
    }
    if let Some(Err(e)) = &row.qhull {
        notes.push(format!("{label}: Qhull failed: {e}"));
    }
    if row.force_closure == Some(false) && row.timed == hull::Timed::Hull {
        notes.push(format!(
            "{label}: no force-closure grasp among {} candidates; the first was taken",
            hull::GRASP_CANDIDATES
        ));
    }
    notes
}
