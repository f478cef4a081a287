//! `pqh compare`: full hull vs partial hull on built-in seeded point sets.

use crate::error::CliError;
use clap::Args;
use pqhull::geometry::Rng;
use pqhull::predicates::Sign;
use pqhull::rbox::{Family, generate};
use pqhull::{ClosestToOrigin, FarthestPoint, Hull, HullError, Stats};
use serde_json::{Value, json};
use std::io::Write;

/// The long help of `pqh compare`.
pub const LONG_ABOUT: &str = "\
Shows what pqhull is for, on built-in seeded point sets (no input needed).

For each point set the distance from the origin to the hull boundary (the Ferrari-Canny grasp
metric when the points are contact wrenches) is computed twice: from the full hull (strategy
FarthestPoint: min over its facets of the origin's depth below the facet's plane) and from a
partial hull grown toward the origin (strategy ClosestToOrigin). The two answers are printed with
their absolute difference, then the work each did: points added to the hull, facets created,
time, and the ratios full / partial.

Point sets: 'sphere' (uniform on the sphere of radius 0.5: every point is a hull vertex, the
hardest case), 'cube' (uniform in [-0.5, 0.5)^D) and, in 6-D only, 'wrenches' (32 grasp-like
wrenches: 4 random contacts on the unit box, 8 friction-cone edges each, mu = 0.5).

If the two answers differ by more than 1e-9 the table is still printed and pqh exits with
status 1. Times are only meaningful in a release build (cargo run --release).";

/// Two answers agree when they differ by at most this much.
const TOLERANCE: f64 = 1e-9;

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

/// The full hull's view of the origin.
enum FullAnswer {
    /// Strictly inside: min over facets of −signed_distance(origin).
    Inside(f64),
    /// On a facet's plane and inside every other one (exact): distance 0.
    Boundary,
    /// Strictly beyond some facet of the full hull (exact test): not force closure.
    Outside,
}

/// One point set, both strategies.
struct Row {
    name: &'static str,
    description: String,
    points: usize,
    full: FullAnswer,
    full_stats: Stats,
    partial: f64,
    partial_stats: Stats,
}

impl Row {
    /// Where the origin is relative to the full hull (decided exactly).
    fn origin(&self) -> &'static str {
        match self.full {
            FullAnswer::Boundary => "boundary",
            FullAnswer::Inside(_) => "inside",
            FullAnswer::Outside => "outside",
        }
    }

    /// The full hull's distance, when the origin is not outside.
    fn full_distance(&self) -> Option<f64> {
        match self.full {
            FullAnswer::Inside(d) => Some(d),
            FullAnswer::Boundary => Some(0.0),
            FullAnswer::Outside => None,
        }
    }

    /// |full − partial| when the origin is not outside.
    fn difference(&self) -> Option<f64> {
        self.full_distance().map(|d| (d - self.partial).abs())
    }

    /// Whether the two strategies agree: the same distance (inside), or both outside.
    fn agrees(&self) -> bool {
        match self.difference() {
            Some(difference) => difference <= TOLERANCE,
            None => self.partial < 0.0,
        }
    }
}

/// Runs both strategies on `points`.
fn compare<const D: usize>(
    name: &'static str,
    description: String,
    points: &[[f64; D]],
) -> Result<Row, HullError> {
    let origin = [0.0; D];
    let (full, ()) = Hull::try_with_strategy(points, FarthestPoint::new())?;
    let sides: Vec<Sign> = full
        .facets()
        .map(|(id, _)| full.side_of(id, &origin))
        .collect();
    let answer = if sides.contains(&Sign::Positive) {
        FullAnswer::Outside
    } else if sides.contains(&Sign::Zero) {
        FullAnswer::Boundary
    } else {
        let depth = full
            .facets()
            .map(|(_, f)| -f.signed_distance(&origin))
            .fold(f64::INFINITY, f64::min);
        FullAnswer::Inside(depth)
    };
    let (_, partial) = Hull::try_with_strategy(points, ClosestToOrigin::new())?;
    Ok(Row {
        name,
        description,
        points: points.len(),
        full: answer,
        full_stats: full.stats(),
        partial: partial.signed_distance,
        partial_stats: partial.stats,
    })
}

/// Grasp-like 6-D wrenches: 4 contacts on distinct faces of the unit box `[−0.5, 0.5]^3` (centred
/// on the torque reference, the origin), each with an 8-edge friction cone,
/// `f = n + μ (cos θ t + sin θ b)`, μ = 0.5, `n` the inward normal, and the wrench `[f; p × f]`.
///
/// A stand-in until the grasp module (issue 3) exists; it will replace this generator.
fn wrenches(seed: u64) -> Vec<[f64; 6]> {
    const CONTACTS: usize = 4;
    const EDGES: usize = 8;
    const MU: f64 = 0.5;
    let mut rng = Rng::new(seed);
    // A random choice of 4 of the 6 faces (partial Fisher–Yates shuffle).
    let mut faces: [usize; 6] = [0, 1, 2, 3, 4, 5];
    for i in 0..CONTACTS {
        let j = i + rng.index(6 - i);
        faces.swap(i, j);
    }
    let mut out = Vec::with_capacity(CONTACTS * EDGES);
    for &face in &faces[..CONTACTS] {
        let (axis, sign) = (face / 2, if face % 2 == 0 { -1.0 } else { 1.0 });
        let mut p = [0.0; 3];
        for (c, x) in p.iter_mut().enumerate() {
            *x = if c == axis {
                0.5 * sign
            } else {
                rng.uniform_in(-0.5, 0.5)
            };
        }
        let mut n = [0.0; 3];
        n[axis] = -sign;
        let mut t = [0.0; 3];
        t[(axis + 1) % 3] = 1.0;
        let b = cross(&n, &t);
        for j in 0..EDGES {
            let theta = std::f64::consts::TAU * j as f64 / EDGES as f64;
            let f: [f64; 3] =
                std::array::from_fn(|c| n[c] + MU * (theta.cos() * t[c] + theta.sin() * b[c]));
            let torque = cross(&p, &f);
            out.push([f[0], f[1], f[2], torque[0], torque[1], torque[2]]);
        }
    }
    out
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The rows for dimension `D`.
fn rows<const D: usize>(n: usize, seed: u64) -> Result<Vec<Row>, CliError> {
    let geometry = |name: &str, e: HullError| CliError::Geometry(format!("compare: {name}: {e}"));
    let mut rows = Vec::new();
    let sphere = generate::<D>(&Family::SphereSurface, n, seed);
    rows.push(
        compare(
            "sphere",
            format!("{n} points on the {D}-D sphere of radius 0.5 (all extreme)"),
            &sphere,
        )
        .map_err(|e| geometry("sphere", e))?,
    );
    let cube = generate::<D>(&Family::UniformCube, n, seed);
    rows.push(
        compare(
            "cube",
            format!("{n} points uniform in [-0.5, 0.5)^{D}"),
            &cube,
        )
        .map_err(|e| geometry("cube", e))?,
    );
    Ok(rows)
}

/// Runs `pqh compare`.
pub fn run(args: &CompareArgs) -> Result<(), CliError> {
    let n = args.points as usize;
    let seed = args.seed;
    let mut table = match args.dimension {
        3 => rows::<3>(n, seed),
        4 => rows::<4>(n, seed),
        5 => rows::<5>(n, seed),
        6 => rows::<6>(n, seed),
        7 => rows::<7>(n, seed),
        8 => rows::<8>(n, seed),
        d => Err(CliError::Usage(format!(
            "--dimension {d}: supported are 3 to 8"
        ))),
    }?;
    if args.dimension == 6 {
        let w = wrenches(seed);
        table.push(
            compare(
                "wrenches",
                "32 grasp-like wrenches: 4 contacts x 8 friction-cone edges, mu = 0.5".to_string(),
                &w,
            )
            .map_err(|e| CliError::Geometry(format!("compare: wrenches: {e}")))?,
        );
    }

    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    if args.json {
        serde_json::to_writer(&mut out, &to_json(args, &table)).map_err(std::io::Error::from)?;
        writeln!(out)?;
    } else {
        write_human(&mut out, args, &table)?;
    }
    out.flush()?;
    drop(out);

    let disagree: Vec<&str> = table
        .iter()
        .filter(|r| !r.agrees())
        .map(|r| r.name)
        .collect();
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

fn ms(stats: &Stats) -> f64 {
    stats.elapsed.as_secs_f64() * 1e3
}

fn ratio(full: f64, partial: f64) -> f64 {
    if partial > 0.0 {
        full / partial
    } else {
        f64::INFINITY
    }
}

fn stats_json(stats: &Stats) -> Value {
    json!({
        "points_processed": stats.points_processed,
        "facets_created": stats.facets_created,
        "expansions": stats.expansions,
        "elapsed_us": u64::try_from(stats.elapsed.as_micros()).unwrap_or(u64::MAX),
    })
}

fn to_json(args: &CompareArgs, table: &[Row]) -> Value {
    let sets: Vec<Value> = table
        .iter()
        .map(|r| {
            let full_distance = json!(r.full_distance());
            let mut full = stats_json(&r.full_stats);
            full["signed_distance"] = full_distance;
            let mut partial = stats_json(&r.partial_stats);
            partial["signed_distance"] = json!(r.partial);
            json!({
                "name": r.name,
                "description": r.description,
                "points": r.points,
                "origin": r.origin(),
                "origin_inside": r.origin() == "inside",
                "full": full,
                "partial": partial,
                "difference": r.difference(),
                "agree": r.agrees(),
                "speedup": {
                    "time": ratio(ms(&r.full_stats), ms(&r.partial_stats)),
                    "facets_created": ratio(
                        r.full_stats.facets_created as f64,
                        r.partial_stats.facets_created as f64,
                    ),
                    "points_processed": ratio(
                        r.full_stats.points_processed as f64,
                        r.partial_stats.points_processed as f64,
                    ),
                },
            })
        })
        .collect();
    json!({
        "dimension": args.dimension,
        "points": args.points,
        "seed": args.seed,
        "tolerance": TOLERANCE,
        "release_build": !cfg!(debug_assertions),
        "agree": table.iter().all(Row::agrees),
        "sets": sets,
    })
}

fn write_human(out: &mut impl Write, args: &CompareArgs, table: &[Row]) -> std::io::Result<()> {
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
        args.dimension,
        args.seed,
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
            ratio(ms(f), ms(p)),
            ratio(f.facets_created as f64, p.facets_created as f64),
            ratio(f.points_processed as f64, p.points_processed as f64),
        )?;
    }
    writeln!(out)?;
    let verdict = if table.iter().all(Row::agrees) {
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
