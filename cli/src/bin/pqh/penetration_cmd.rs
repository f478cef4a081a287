//! `pqh penetration`: the signed penetration depth of two convex polytopes given as points files.

use crate::dispatch::with_dimension;
use crate::error::CliError;
use crate::format::{number, write_report};
use crate::input::Source;
use clap::Args;
use pqhull::strategy::{Penetration, PenetrationError, Relation, penetration_depth};
use pqhull_cli::points_file::PointTable;
use serde_json::json;
use std::io::Write;
use std::path::PathBuf;

/// The long help of `pqh penetration`.
pub const LONG_ABOUT: &str = "\
The signed penetration depth of the convex hulls of the points in A and B (points files of one
dimension, 2 to 8; '-' reads one of them from standard input): positive when their interiors
overlap — the length of the smallest translation of B that separates them — negative when they
are disjoint (minus their distance), 0 when they touch. Also the direction (translating B by
depth × direction makes them touch) and how they lie: overlapping, touching or separated.

Exact on the given coordinates to 1e-12 of the depth or 2e-15 of the size of A - B: the partial
hull of the Minkowski difference A - B grown toward the origin (never materialised), GJK first
for separated bodies. Details: README.md, \"Partial hulls outside grasping\".";

/// Arguments of `pqh penetration`.
#[derive(Debug, Args)]
pub struct PenetrationArgs {
    /// Points file of the first body
    #[arg(value_name = "A")]
    a: PathBuf,

    /// Points file of the second body
    #[arg(value_name = "B")]
    b: PathBuf,

    /// Print one JSON object instead of a human-readable summary
    #[arg(long)]
    json: bool,
}

/// Runs `pqh penetration`.
pub fn run(args: &PenetrationArgs) -> Result<(), CliError> {
    if args.a.as_os_str() == "-" && args.b.as_os_str() == "-" {
        return Err(CliError::Usage(
            "A and B cannot both be standard input ('-')".to_string(),
        ));
    }
    let (a_source, b_source) = (Source::new(Some(&args.a)), Source::new(Some(&args.b)));
    let a = a_source.read_points()?;
    let b = b_source.read_points()?;
    let d = a.dimension();
    if b.dimension() != d {
        return Err(CliError::Input(format!(
            "{} has dimension {d} but {} has dimension {}",
            a_source.name(),
            b_source.name(),
            b.dimension()
        )));
    }
    let names = [a_source.name(), b_source.name()];
    with_dimension!(d, |D| report::<D>(&a, &b, &names, args.json), else |_| Err(CliError::Input(
        format!("{}: the points have dimension {d}; pqh supports dimensions 2 to 8", names[0])
    )))
}

fn report<const D: usize>(
    a: &PointTable,
    b: &PointTable,
    names: &[String; 2],
    json: bool,
) -> Result<(), CliError> {
    let a = a.to_arrays::<D>().expect("dispatched on A's dimension");
    let b = b.to_arrays::<D>().expect("B has A's dimension");
    let p = penetration_depth(&a, &b).map_err(|e| match e {
        // The bodies' own data (overflowing differences, a flat case too large) is input.
        PenetrationError::Source(_) | PenetrationError::Hull(_) => {
            CliError::Geometry(e.to_string())
        }
        _ => CliError::Input(format!("{} and {}: {e}", names[0], names[1])),
    })?;
    write_report(json, || to_json(&p), |out| table(out, &p, names))?;
    Ok(())
}

fn relation_name(relation: Relation) -> &'static str {
    match relation {
        Relation::Overlapping => "overlapping",
        Relation::Touching => "touching",
        Relation::Separated => "separated",
    }
}

fn to_json<const D: usize>(p: &Penetration<D>) -> serde_json::Value {
    json!({
        "depth": p.depth,
        "direction": p.direction.to_vec(),
        "translation": p.translation().to_vec(),
        "relation": relation_name(p.relation),
        "rounding": p.rounding,
        "scale": p.scale,
        "stats": {
            "points_processed": p.stats.points_processed,
            "facets_created": p.stats.facets_created,
            "expansions": p.stats.expansions,
            "elapsed_us": p.stats.elapsed.as_micros() as u64,
        },
    })
}

fn table<const D: usize>(
    out: &mut impl Write,
    p: &Penetration<D>,
    names: &[String; 2],
) -> std::io::Result<()> {
    let vector = |v: [f64; D]| v.map(number).join(", ");
    writeln!(out, "bodies:      {} and {}", names[0], names[1])?;
    writeln!(out, "relation:    {}", relation_name(p.relation))?;
    writeln!(out, "depth:       {}", number(p.depth))?;
    writeln!(out, "direction:   ({})", vector(p.direction))?;
    writeln!(
        out,
        "translation: ({})  (of B, to touch)",
        vector(p.translation())
    )?;
    writeln!(
        out,
        "work:        {} points, {} facets, {} µs",
        p.stats.points_processed,
        p.stats.facets_created,
        p.stats.elapsed.as_micros()
    )
}
