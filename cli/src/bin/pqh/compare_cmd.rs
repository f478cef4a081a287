//! `pqh compare`: full hull vs partial hull on built-in seeded point sets.

use crate::dispatch::with_dimension;
use crate::error::CliError;
use clap::Args;
use pqhull_cli::bench::compare::{CompareReport, TOLERANCE, compare_sets, ms};
use std::io::Write;

/// The long help of `pqh compare`.
pub const LONG_ABOUT: &str = "\
Shows what pqhull is for, on built-in seeded point sets (no input needed): computes the distance
from the origin to the hull boundary (the Ferrari-Canny metric when the points are contact
wrenches) from the full hull (FarthestPoint) and from a partial hull grown toward the origin
(ClosestToOrigin), and prints both, their difference and the work each did: points added, facets
created, time, and the ratios full / partial. Point sets: 'sphere' (uniform on the radius-0.5
sphere: every point a hull vertex), 'cube' (uniform in [-0.5, 0.5)^D) and, in 6-D only,
'wrenches' (32 wrenches: 4 random contacts on the unit box, 8 cone edges each, mu = 0.5).
Answers more than 1e-9 apart are still printed, then pqh exits with status 1. Times are
meaningful only in a release build.

Measured ratios: docs/benchmarks.md, \"Distance from the origin\"; limits: docs/limits.md.";

/// Arguments of `pqh compare`.
#[derive(Debug, Args)]
pub struct CompareArgs {
    /// Seed of every generated point set
    #[arg(long, default_value_t = 20240601)]
    seed: u64,

    /// Dimension of the sphere and cube point sets (the wrench set is always 6-D)
    #[arg(long, value_name = "D", default_value_t = 6,
          value_parser = clap::value_parser!(u8).range(3..=8))]
    dimension: u8,

    /// Points in each of the sphere and cube sets
    #[arg(long, value_name = "N", default_value_t = 1000,
          value_parser = clap::value_parser!(u32).range(16..=1_000_000))]
    points: u32,

    /// Print one JSON object instead of tables
    #[arg(long)]
    json: bool,
}

/// Runs `pqh compare`.
pub fn run(args: &CompareArgs) -> Result<(), CliError> {
    let (n, seed) = (args.points as usize, args.seed);
    let report = with_dimension!(
        args.dimension,
        [3, 4, 5, 6, 7, 8],
        |D| compare_sets::<D>(n, seed)
            .map_err(|e| CliError::Geometry(format!("compare: {e}"))),
        else |d| Err(CliError::Usage(format!(
            "--dimension {d}: supported are 3 to 8"
        )))
    )?;

    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    if args.json {
        serde_json::to_writer(&mut out, &report.to_json()).map_err(std::io::Error::from)?;
        writeln!(out)?;
    } else {
        write_human(&mut out, &report)?;
    }
    out.flush()?;
    drop(out);

    let disagree = report.disagreements();
    if disagree.is_empty() {
        Ok(())
    } else {
        Err(CliError::Geometry(format!(
            "compare: the full and the partial hull disagree on {} (bug: please report it with the \
             seed)",
            disagree.join(", ")
        )))
    }
}

fn write_human(out: &mut impl Write, report: &CompareReport) -> std::io::Result<()> {
    let table = &report.rows;
    writeln!(
        out,
        "pqh compare: distance from the origin to the hull boundary (the Ferrari-Canny metric for \
         wrenches),"
    )?;
    writeln!(
        out,
        "from the full hull (FarthestPoint) and from a partial hull (ClosestToOrigin)."
    )?;
    writeln!(
        out,
        "dimension {}, seed {}{}",
        report.dimension,
        report.seed,
        if cfg!(debug_assertions) {
            "  (debug build: times are not representative, use --release)"
        } else {
            ""
        }
    )?;
    writeln!(out)?;
    for r in table {
        writeln!(out, "  {:<9} {}", r.name, r.description)?;
    }
    writeln!(out)?;
    writeln!(
        out,
        "{:<9} {:>7}  {:<9} {:>20} {:>20} {:>10}",
        "set", "points", "origin", "full hull", "partial hull", "|diff|"
    )?;
    for r in table {
        match r.full_distance() {
            Some(d) => writeln!(
                out,
                "{:<9} {:>7}  {:<9} {:>20.15} {:>20.15} {:>10.1e}",
                r.name,
                r.points,
                r.origin(),
                d,
                r.partial,
                r.difference().unwrap_or(f64::NAN)
            )?,
            None => writeln!(
                out,
                "{:<9} {:>7}  {:<9} {:>20} {:>20.15} {:>10}",
                r.name, r.points, "outside", "not force closure", r.partial, "-"
            )?,
        }
    }
    writeln!(out)?;
    writeln!(
        out,
        "{:<9} {:>17} {:>19} {:>19}   speed-up (full/partial)",
        "", "points processed", "facets created", "time ms"
    )?;
    writeln!(
        out,
        "{:<9} {:>8} {:>8} {:>9} {:>9} {:>9} {:>9}   {:>6} {:>7} {:>7}",
        "set", "full", "partial", "full", "partial", "full", "partial", "time", "facets", "points"
    )?;
    for r in table {
        let (f, p) = (&r.full_stats, &r.partial_stats);
        writeln!(
            out,
            "{:<9} {:>8} {:>8} {:>9} {:>9} {:>9.1} {:>9.1}   {:>5.1}x {:>6.1}x {:>6.1}x",
            r.name,
            f.points_processed,
            p.points_processed,
            f.facets_created,
            p.facets_created,
            ms(f),
            ms(p),
            r.time_speedup(),
            r.facets_speedup(),
            r.points_speedup(),
        )?;
    }
    writeln!(out)?;
    let verdict = if report.agrees() {
        format!("full and partial hull agree on every set (|diff| <= {TOLERANCE:e}).")
    } else {
        "full and partial hull DISAGREE (see above).".to_string()
    };
    writeln!(out, "{verdict}")?;
    writeln!(
        out,
        "'outside' means the origin is not inside the hull (for wrenches: not force closure); the \
         partial hull's value is then minus the distance to the hull; 'boundary' (decided \
         exactly) means distance 0."
    )
}
