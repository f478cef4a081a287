//! `pqh hull`: the convex hull of a points file, full or partial.

use crate::dispatch::with_dimension;
use crate::error::CliError;
use crate::format::number;
use crate::input::{Source, parse_point};
use clap::{Args, ValueEnum};
use pqhull::strategy::{DistanceResult, QueryError, distances_to_boundary};
use pqhull::{ClosestToOrigin, FacetId, Hull, HullError, Stats};
use pqhull_cli::points_file::PointTable;
use std::io::Write;
use std::path::PathBuf;

/// The long help of `pqh hull`.
pub const LONG_ABOUT: &str = "\
Builds the convex hull of the points in FILE (standard input for '-' or no FILE), in the file's
dimension, 2 to 8. --strategy farthest-point (the default; `full` is an alias) runs QuickHull to
completion and reports the vertices, facets and volume. --strategy closest-to-origin grows the
hull only toward the query point (--query, default the origin; `--origin` is an alias) until the
facet nearest it is certain, and reports the signed distance from the query point to the hull
boundary (positive inside), the closest facet and the nearest boundary point; the facets listed
are the partial hull's. --queries QFILE answers every point of QFILE (a points file of the same
dimension) as a query, from partial hulls shared by the queries: one line per query.

Details (points files, JSON keys): README.md, \"The pqh hull command\"; limits: docs/limits.md.";

/// Arguments of `pqh hull`.
#[derive(Debug, Args)]
pub struct HullArgs {
    /// Points file; '-' or nothing reads standard input
    #[arg(value_name = "FILE")]
    file: Option<PathBuf>,

    /// How far to grow the hull
    #[arg(long, value_enum, default_value_t = StrategyArg::FarthestPoint)]
    strategy: StrategyArg,

    /// Query point for closest-to-origin, as x,y,...; it must have the points' dimension
    /// (default: the origin)
    #[arg(
        long,
        alias = "origin",
        value_name = "X,Y,...",
        allow_hyphen_values = true
    )]
    query: Option<String>,

    /// A points file of query points (the points' dimension): the signed distance of each, one
    /// line per query in order, from partial hulls shared by the queries (whatever --strategy)
    #[arg(long, value_name = "QFILE", conflicts_with = "query")]
    queries: Option<PathBuf>,

    /// Print one JSON object instead of a human-readable summary (with --queries, one JSON
    /// object per line)
    #[arg(long)]
    json: bool,
}

/// The `--strategy` values: the library's strategy names, as `pqh trace` takes them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum StrategyArg {
    /// FarthestPoint: the full hull (QuickHull, farthest point first)
    #[value(alias = "full", alias = "farthest")]
    FarthestPoint,
    /// ClosestToOrigin: a partial hull, grown toward the query point until its nearest facet is
    /// certain
    #[value(alias = "closest")]
    ClosestToOrigin,
}

impl StrategyArg {
    fn name(self) -> &'static str {
        match self {
            StrategyArg::FarthestPoint => "farthest-point",
            StrategyArg::ClosestToOrigin => "closest-to-origin",
        }
    }
}

/// Runs `pqh hull`.
pub fn run(args: &HullArgs) -> Result<(), CliError> {
    if let Some(queries) = &args.queries {
        return run_queries(args, queries);
    }
    let origin = match (&args.query, args.strategy) {
        (None, _) => None,
        (Some(text), StrategyArg::ClosestToOrigin) => Some(parse_point("--query", text)?),
        (Some(_), StrategyArg::FarthestPoint) => {
            return Err(CliError::Usage(
                "--query only applies to --strategy closest-to-origin".to_string(),
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
            "--query has {} coordinate(s) but the points in {} have dimension {d}",
            q.len(),
            source.name()
        )));
    }
    let name = source.name();
    let first_line = table.line(0);
    let job = Job {
        table,
        strategy: args.strategy,
        origin: origin.as_deref(),
        json: args.json,
        source: &name,
    };
    with_dimension!(d, |D| job.run::<D>(), else |_| Err(CliError::Input(format!(
        "{name}: the points have dimension {d} (from line {first_line}); pqh supports \
         dimensions 2 to 8"
    ))))
}

/// What to build and print, independent of the dimension.
struct Job<'a> {
    table: PointTable,
    strategy: StrategyArg,
    origin: Option<&'a [f64]>,
    json: bool,
    /// The input's name, for messages and the human output.
    source: &'a str,
}

/// What a run found besides the hull itself.
struct Outcome<const D: usize> {
    strategy: StrategyArg,
    volume: Option<f64>,
    distance: Option<([f64; D], DistanceResult<D>)>,
    stats: Stats,
}

impl Job<'_> {
    /// Builds the hull, then writes it to standard output straight from the hull's facets.
    fn run<const D: usize>(self) -> Result<(), CliError> {
        let points = self
            .table
            .to_arrays::<D>()
            .expect("dispatched on the table's dimension");
        // The hull copies the points: the table is not needed once the arrays are made, nor the
        // arrays once the hull is built.
        drop(self.table);
        let geometry = |e: HullError| CliError::Geometry(format!("{}: {e}", self.source));
        let (hull, outcome) = match self.strategy {
            StrategyArg::FarthestPoint => {
                let hull = Hull::<D>::try_new(&points).map_err(geometry)?;
                let outcome = Outcome {
                    strategy: self.strategy,
                    volume: Some(hull.volume()),
                    distance: None,
                    stats: hull.stats(),
                };
                (hull, outcome)
            }
            StrategyArg::ClosestToOrigin => {
                let query: [f64; D] = match self.origin {
                    Some(q) => std::array::from_fn(|i| q[i]),
                    None => [0.0; D],
                };
                let (hull, result) =
                    Hull::try_with_strategy(&points, ClosestToOrigin::towards(query))
                        .map_err(geometry)?;
                let outcome = Outcome {
                    strategy: self.strategy,
                    volume: None,
                    stats: result.stats,
                    distance: Some((query, result)),
                };
                (hull, outcome)
            }
        };
        drop(points);
        // JSON has no infinity, and a null would read as "no value": a number beyond the f64
        // range is an error there (the human output prints it as `inf`).
        if self.json {
            let too_large = |what: &str| {
                CliError::Input(format!(
                    "{}: the {what} exceeds the largest f64 (1.8e308) and cannot be written as                      JSON; divide the input by a power of two",
                    self.source
                ))
            };
            if outcome.volume.is_some_and(|v| !v.is_finite()) {
                return Err(too_large("volume"));
            }
            if let Some((_, d)) = &outcome.distance
                && !d.signed_distance.is_finite()
            {
                return Err(too_large("distance to the query point"));
            }
        }

        let stdout = std::io::stdout();
        let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
        if self.json {
            write_json(&mut out, &hull, &outcome)?;
            writeln!(out)?;
        } else {
            write_human(&mut out, &hull, &outcome, self.source)?;
        }
        out.flush()?;
        Ok(())
    }
}

/// Writes `value` as serde_json writes it (compact; floats shortest round-trip, NaN and
/// infinities as `null`), so that the streamed document is the one `serde_json::to_writer` of a
/// `Value` gave.
macro_rules! put {
    ($out:expr, $value:expr) => {
        serde_json::to_writer(&mut *$out, $value).map_err(std::io::Error::from)
    };
}

/// Writes the members of one JSON object, keys in the order serde_json's default (sorted) `Map`
/// printed them before the output was streamed: strictly increasing, checked in debug builds.
struct JsonObject<'k> {
    last: Option<&'k str>,
}

impl<'k> JsonObject<'k> {
    fn begin(out: &mut impl Write) -> std::io::Result<Self> {
        out.write_all(b"{")?;
        Ok(Self { last: None })
    }

    /// Writes `,` if needed and `"key":`; the value follows.
    fn key(&mut self, out: &mut impl Write, key: &'k str) -> std::io::Result<()> {
        debug_assert!(
            self.last.is_none_or(|last| last < key),
            "JSON keys out of order: {:?} then {key:?}",
            self.last
        );
        debug_assert!(
            key.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_'),
            "{key:?} needs escaping"
        );
        if self.last.is_some() {
            out.write_all(b",")?;
        }
        self.last = Some(key);
        write!(out, "\"{key}\":")
    }

    fn end(self, out: &mut impl Write) -> std::io::Result<()> {
        out.write_all(b"}")
    }
}

/// Position of each live facet in the order of [`Hull::facets`], indexed by its arena slot
/// ([`FacetId::index`]); `u32::MAX` for a slot holding no live facet. Four bytes per slot where
/// a `HashMap<FacetId, usize>` took several times that.
fn facet_positions<const D: usize>(hull: &Hull<D>) -> Vec<u32> {
    let slots = hull.facets().last().map_or(0, |(id, _)| id.index() + 1);
    let mut positions = vec![u32::MAX; slots];
    for (position, (id, _)) in hull.facets().enumerate() {
        positions[id.index()] = u32::try_from(position).expect("facet ids are u32");
    }
    positions
}

/// The position of facet `id` in the output's facet list, if it is live.
fn position(positions: &[u32], id: FacetId) -> Option<usize> {
    positions
        .get(id.index())
        .filter(|&&p| p != u32::MAX)
        .map(|&p| p as usize)
}

/// The JSON document, written facet by facet.
fn write_json<const D: usize>(
    out: &mut impl Write,
    hull: &Hull<D>,
    outcome: &Outcome<D>,
) -> std::io::Result<()> {
    let positions = facet_positions(hull);
    let mut obj = JsonObject::begin(out)?;
    if let Some((_, result)) = &outcome.distance {
        obj.key(out, "closest_facet")?;
        put!(out, &result.closest_facet_vertices[..])?;
        obj.key(out, "closest_facet_index")?;
        put!(out, &position(&positions, result.closest_facet))?;
    }
    obj.key(out, "dimension")?;
    put!(out, &D)?;
    obj.key(out, "facets")?;
    out.write_all(b"[")?;
    for (i, (_, facet)) in hull.facets().enumerate() {
        if i > 0 {
            out.write_all(b",")?;
        }
        let mut f = JsonObject::begin(out)?;
        f.key(out, "neighbors")?;
        put!(out, &facet.neighbors().map(|n| position(&positions, n))[..])?;
        f.key(out, "normal")?;
        put!(out, &facet.normal()[..])?;
        f.key(out, "offset")?;
        put!(out, &facet.offset())?;
        f.key(out, "vertices")?;
        put!(out, &facet.vertices()[..])?;
        f.end(out)?;
    }
    out.write_all(b"]")?;
    if let Some((query, result)) = &outcome.distance {
        obj.key(out, "nearest_point")?;
        put!(out, &result.nearest_point[..])?;
        obj.key(out, "origin")?;
        put!(out, &query[..])?;
        obj.key(out, "origin_distance")?;
        put!(out, &result.signed_distance)?;
    }
    obj.key(out, "points")?;
    put!(out, &hull.point_count())?;
    obj.key(out, "stats")?;
    let stats = &outcome.stats;
    let mut s = JsonObject::begin(out)?;
    s.key(out, "elapsed_us")?;
    put!(
        out,
        &u64::try_from(stats.elapsed.as_micros()).unwrap_or(u64::MAX)
    )?;
    s.key(out, "expansions")?;
    put!(out, &stats.expansions)?;
    s.key(out, "facets_created")?;
    put!(out, &stats.facets_created)?;
    s.key(out, "points_processed")?;
    put!(out, &stats.points_processed)?;
    s.end(out)?;
    obj.key(out, "strategy")?;
    put!(out, outcome.strategy.name())?;
    obj.key(out, "vertices")?;
    put!(out, &hull.vertex_indices())?;
    if let Some(volume) = outcome.volume {
        obj.key(out, "volume")?;
        put!(out, &volume)?;
    }
    obj.end(out)
}

/// The human-readable summary (no facet list).
fn write_human<const D: usize>(
    out: &mut impl Write,
    hull: &Hull<D>,
    outcome: &Outcome<D>,
    source: &str,
) -> std::io::Result<()> {
    const SHOWN: usize = 32;
    let list = |xs: &[usize]| {
        let mut s: Vec<String> = xs.iter().take(SHOWN).map(usize::to_string).collect();
        if xs.len() > SHOWN {
            s.push(format!("... ({} more)", xs.len() - SHOWN));
        }
        s.join(" ")
    };
    let point = |xs: &[f64]| {
        let s: Vec<String> = xs.iter().map(|&x| number(x)).collect();
        format!("({})", s.join(", "))
    };
    let vertices = hull.vertex_indices();
    writeln!(out, "input            {source}")?;
    writeln!(out, "dimension        {D}")?;
    writeln!(out, "points           {}", hull.point_count())?;
    writeln!(out, "strategy         {}", outcome.strategy.name())?;
    let partial = if outcome.strategy == StrategyArg::FarthestPoint {
        ""
    } else {
        " (of the partial hull)"
    };
    writeln!(
        out,
        "vertices         {}{partial}: {}",
        vertices.len(),
        list(&vertices)
    )?;
    writeln!(out, "facets           {}{partial}", hull.facet_count())?;
    if let Some(volume) = outcome.volume {
        writeln!(out, "volume           {}", number(volume))?;
    }
    if let Some((query, d)) = &outcome.distance {
        let side = if d.signed_distance > 0.0 {
            "inside"
        } else if d.signed_distance < 0.0 {
            "outside"
        } else {
            "on the boundary"
        };
        writeln!(out, "query point      {}", point(query))?;
        writeln!(
            out,
            "signed distance  {} ({side})",
            number(d.signed_distance)
        )?;
        writeln!(
            out,
            "closest facet    vertices {}",
            list(&d.closest_facet_vertices)
        )?;
        writeln!(out, "nearest point    {}", point(&d.nearest_point))?;
    }
    let stats = &outcome.stats;
    writeln!(
        out,
        "work             {} points processed, {} facets created, {} expansions, {:.3} ms",
        stats.points_processed,
        stats.facets_created,
        stats.expansions,
        stats.elapsed.as_secs_f64() * 1e3
    )
}

/// `pqh hull --queries`: every query's signed distance, a line each.
fn run_queries(args: &HullArgs, queries: &std::path::Path) -> Result<(), CliError> {
    let source = Source::new(args.file.as_deref());
    let table = source.read_points()?;
    let query_source = Source::new(Some(queries));
    let query_table = query_source.read_points()?;
    let (d, name, query_name) = (table.dimension(), source.name(), query_source.name());
    if query_table.dimension() != d {
        return Err(CliError::Usage(format!(
            "the queries in {query_name} have dimension {} but the points in {name} have {d}",
            query_table.dimension()
        )));
    }
    let json = args.json;
    with_dimension!(d, |D| write_queries::<D>(&table, &query_table, json, &name), else |_| Err(CliError::Input(format!(
        "{name}: the points have dimension {d}; pqh supports dimensions 2 to 8"
    ))))
}

fn write_queries<const D: usize>(
    table: &PointTable,
    queries: &PointTable,
    json: bool,
    name: &str,
) -> Result<(), CliError> {
    let points = table
        .to_arrays::<D>()
        .expect("dispatched on the table's dimension");
    let qs = queries
        .to_arrays::<D>()
        .expect("the same dimension, checked");
    let answers = distances_to_boundary(&points, &qs).map_err(|e| match e {
        QueryError::Hull(e) => CliError::Geometry(format!("{name}: {e}")),
        e => CliError::Input(e.to_string()),
    })?;
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
    for (q, a) in qs.iter().zip(&answers) {
        if json {
            if !a.signed_distance.is_finite() {
                return Err(CliError::Input(format!(
                    "{name}: the distance to query {q:?} exceeds the largest f64 (1.8e308) and \
                     cannot be written as JSON; divide the input by a power of two"
                )));
            }
            let mut obj = JsonObject::begin(&mut out)?;
            obj.key(&mut out, "closest_facet")?;
            put!(&mut out, &a.closest_facet_vertices[..])?;
            obj.key(&mut out, "nearest_point")?;
            put!(&mut out, &a.nearest_point[..])?;
            obj.key(&mut out, "origin")?;
            put!(&mut out, &q[..])?;
            obj.key(&mut out, "origin_distance")?;
            put!(&mut out, &a.signed_distance)?;
            obj.end(&mut out)?;
            writeln!(out)?;
        } else {
            let coords = |xs: &[f64]| xs.iter().map(|&x| number(x)).collect::<Vec<_>>().join(", ");
            writeln!(
                out,
                "query ({})  signed distance {}  nearest point ({})",
                coords(q),
                number(a.signed_distance),
                coords(&a.nearest_point)
            )?;
        }
    }
    out.flush()?;
    Ok(())
}
