//! `pqh hull`: the convex hull of a points file, full or partial.

use crate::error::CliError;
use crate::input::{Source, parse_point};
use clap::{Args, ValueEnum};
use pqhull::points_file::PointTable;
use pqhull::{ClosestToOrigin, FacetId, Hull, HullError, Stats};
use serde_json::{Value, json};
use std::collections::HashMap;
use std::io::Write;
use std::path::PathBuf;

/// The long help of `pqh hull`.
pub const LONG_ABOUT: &str = "\
Builds the convex hull of the points in FILE (standard input for '-' or no FILE).

--strategy full (the default) runs QuickHull to completion and reports the vertices, facets and
volume. --strategy closest-to-origin grows the hull only toward the query point (--origin,
default the origin) and stops as soon as the facet nearest it is certain; it reports the signed
distance from the query point to the hull boundary (positive inside, negative outside), the
closest facet and the nearest boundary point. The facets listed are those of the partial hull.

The dimension is that of the file (2 to 8).";

/// Arguments of `pqh hull`.
#[derive(Debug, Args)]
pub struct HullArgs {
    /// Points file; '-' or nothing reads standard input
    #[arg(value_name = "FILE")]
    file: Option<PathBuf>,

    /// How far to grow the hull
    #[arg(long, value_enum, default_value_t = StrategyArg::Full)]
    strategy: StrategyArg,

    /// Query point for closest-to-origin, as x,y,...; it must have the points' dimension
    /// [default: the origin]
    #[arg(long, value_name = "X,Y,...", allow_hyphen_values = true)]
    origin: Option<String>,

    /// Print one JSON object instead of a human-readable summary
    #[arg(long)]
    json: bool,
}

/// The `--strategy` values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum StrategyArg {
    /// The full hull (QuickHull, farthest point first)
    Full,
    /// A partial hull, grown toward the query point until its nearest facet is certain
    ClosestToOrigin,
}

impl StrategyArg {
    fn name(self) -> &'static str {
        match self {
            StrategyArg::Full => "full",
            StrategyArg::ClosestToOrigin => "closest-to-origin",
        }
    }
}

/// One facet, with neighbours as positions in the report's facet list.
struct FacetReport {
    vertices: Vec<usize>,
    normal: Vec<f64>,
    offset: f64,
    neighbors: Vec<Option<usize>>,
}

/// The closest-to-origin answer.
struct DistanceReport {
    query: Vec<f64>,
    signed_distance: f64,
    closest_facet_vertices: Vec<usize>,
    closest_facet_position: Option<usize>,
    nearest_point: Vec<f64>,
}

/// A hull, with the dimension erased, ready to print.
struct HullReport {
    dimension: usize,
    points: usize,
    strategy: StrategyArg,
    vertices: Vec<usize>,
    facets: Vec<FacetReport>,
    volume: Option<f64>,
    distance: Option<DistanceReport>,
    stats: Stats,
}

/// Runs `pqh hull`.
pub fn run(args: &HullArgs) -> Result<(), CliError> {
    let origin = match (&args.origin, args.strategy) {
        (None, _) => None,
        (Some(text), StrategyArg::ClosestToOrigin) => Some(parse_point("--origin", text)?),
        (Some(_), StrategyArg::Full) => {
            return Err(CliError::Usage(
                "--origin only applies to --strategy closest-to-origin".to_string(),
            ));
        }
    };
    let source = Source::new(args.file.as_deref());
    let table = source.read_points()?;
    let d = table.dimension();
    if let Some(q) = &origin
        && q.len() != d
    {
        return Err(CliError::Usage(format!(
            "--origin has {} coordinate(s) but the points in {} have dimension {d}",
            q.len(),
            source.name()
        )));
    }
    let job = Job {
        table: &table,
        strategy: args.strategy,
        origin: origin.as_deref(),
    };
    let report = match d {
        2 => job.run::<2>(),
        3 => job.run::<3>(),
        4 => job.run::<4>(),
        5 => job.run::<5>(),
        6 => job.run::<6>(),
        7 => job.run::<7>(),
        8 => job.run::<8>(),
        _ => {
            return Err(CliError::Input(format!(
                "{}: the points have dimension {d} (from line {}); pqh supports dimensions 2 to 8",
                source.name(),
                table.line(0)
            )));
        }
    }
    .map_err(|e| CliError::Geometry(format!("{}: {e}", source.name())))?;

    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    if args.json {
        serde_json::to_writer(&mut out, &report.to_json()).map_err(std::io::Error::from)?;
        writeln!(out)?;
    } else {
        report.write_human(&mut out, &source.name())?;
    }
    out.flush()?;
    Ok(())
}

/// What to build, independent of the dimension.
struct Job<'a> {
    table: &'a PointTable,
    strategy: StrategyArg,
    origin: Option<&'a [f64]>,
}

impl Job<'_> {
    fn run<const D: usize>(&self) -> Result<HullReport, HullError> {
        let points = self
            .table
            .to_arrays::<D>()
            .expect("dispatched on the table's dimension");
        let (hull, volume, distance, stats) = match self.strategy {
            StrategyArg::Full => {
                let hull = Hull::<D>::try_new(&points)?;
                let (volume, stats) = (hull.volume(), hull.stats());
                (hull, Some(volume), None, stats)
            }
            StrategyArg::ClosestToOrigin => {
                let query: [f64; D] = match self.origin {
                    Some(q) => std::array::from_fn(|i| q[i]),
                    None => [0.0; D],
                };
                let (hull, result) =
                    Hull::try_with_strategy(&points, ClosestToOrigin::towards(query))?;
                let stats = result.stats;
                (hull, None, Some((query, result)), stats)
            }
        };
        let positions: HashMap<FacetId, usize> = hull
            .facets()
            .enumerate()
            .map(|(pos, (id, _))| (id, pos))
            .collect();
        let facets = hull
            .facets()
            .map(|(_, f)| FacetReport {
                vertices: f.vertices().to_vec(),
                normal: f.normal().to_vec(),
                offset: f.offset(),
                neighbors: f
                    .neighbors()
                    .iter()
                    .map(|n| positions.get(n).copied())
                    .collect(),
            })
            .collect();
        let distance = distance.map(|(query, r)| DistanceReport {
            query: query.to_vec(),
            signed_distance: r.signed_distance,
            closest_facet_vertices: r.closest_facet_vertices.to_vec(),
            closest_facet_position: positions.get(&r.closest_facet).copied(),
            nearest_point: r.nearest_point.to_vec(),
        });
        Ok(HullReport {
            dimension: D,
            points: points.len(),
            strategy: self.strategy,
            vertices: hull.vertex_indices(),
            facets,
            volume,
            distance,
            stats,
        })
    }
}

impl HullReport {
    fn to_json(&self) -> Value {
        let facets: Vec<Value> = self
            .facets
            .iter()
            .map(|f| {
                json!({
                    "vertices": f.vertices,
                    "normal": f.normal,
                    "offset": f.offset,
                    "neighbors": f.neighbors,
                })
            })
            .collect();
        let mut obj = json!({
            "dimension": self.dimension,
            "points": self.points,
            "strategy": self.strategy.name(),
            "vertices": self.vertices,
            "facets": facets,
            "stats": {
                "points_processed": self.stats.points_processed,
                "facets_created": self.stats.facets_created,
                "expansions": self.stats.expansions,
                "elapsed_us": u64::try_from(self.stats.elapsed.as_micros()).unwrap_or(u64::MAX),
            },
        });
        let map = obj.as_object_mut().expect("an object");
        if let Some(volume) = self.volume {
            map.insert("volume".into(), json!(volume));
        }
        if let Some(d) = &self.distance {
            map.insert("origin".into(), json!(d.query));
            map.insert("origin_distance".into(), json!(d.signed_distance));
            map.insert("closest_facet".into(), json!(d.closest_facet_vertices));
            map.insert(
                "closest_facet_index".into(),
                json!(d.closest_facet_position),
            );
            map.insert("nearest_point".into(), json!(d.nearest_point));
        }
        obj
    }

    fn write_human(&self, out: &mut impl Write, source: &str) -> std::io::Result<()> {
        const SHOWN: usize = 32;
        let list = |xs: &[usize]| {
            let mut s: Vec<String> = xs.iter().take(SHOWN).map(usize::to_string).collect();
            if xs.len() > SHOWN {
                s.push(format!("... ({} more)", xs.len() - SHOWN));
            }
            s.join(" ")
        };
        let point = |xs: &[f64]| {
            let s: Vec<String> = xs.iter().map(f64::to_string).collect();
            format!("({})", s.join(", "))
        };
        writeln!(out, "input            {source}")?;
        writeln!(out, "dimension        {}", self.dimension)?;
        writeln!(out, "points           {}", self.points)?;
        writeln!(out, "strategy         {}", self.strategy.name())?;
        let partial = if self.strategy == StrategyArg::Full {
            ""
        } else {
            " (of the partial hull)"
        };
        writeln!(
            out,
            "vertices         {}{partial}: {}",
            self.vertices.len(),
            list(&self.vertices)
        )?;
        writeln!(out, "facets           {}{partial}", self.facets.len())?;
        if let Some(volume) = self.volume {
            writeln!(out, "volume           {volume}")?;
        }
        if let Some(d) = &self.distance {
            let side = if d.signed_distance > 0.0 {
                "inside"
            } else if d.signed_distance < 0.0 {
                "outside"
            } else {
                "on the boundary"
            };
            writeln!(out, "query point      {}", point(&d.query))?;
            writeln!(out, "signed distance  {} ({side})", d.signed_distance)?;
            writeln!(
                out,
                "closest facet    vertices {}",
                list(&d.closest_facet_vertices)
            )?;
            writeln!(out, "nearest point    {}", point(&d.nearest_point))?;
        }
        writeln!(
            out,
            "work             {} points processed, {} facets created, {} expansions, {:.3} ms",
            self.stats.points_processed,
            self.stats.facets_created,
            self.stats.expansions,
            self.stats.elapsed.as_secs_f64() * 1e3
        )
    }
}
