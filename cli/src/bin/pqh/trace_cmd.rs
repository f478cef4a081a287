//! `pqh trace`: a strategy's run, step by step, as a self-contained HTML page.

use crate::dispatch::with_dimension;
use crate::error::CliError;
use crate::input::{Source, parse_point};
use clap::{Args, ValueEnum};
use pqhull::geometry::Rng;
use pqhull::hull::{Event, Trace};
use pqhull::rbox::{Family, generate_flat};
use pqhull::viz::{html, svg};
use pqhull::{ClosestToOrigin, FarthestPoint, Hull, OwsInflation};
use std::io::Write;
use std::path::{Path, PathBuf};

/// The long help of `pqh trace`.
pub const LONG_ABOUT: &str = "\
Records a strategy's run on 2-D or 3-D points (FILE, '-' for standard input, or a generated
--family) and draws it step by step as one self-contained HTML page (the script is inline, no
network): the partial hull, the points still outside it, the facet the strategy chose and why,
the point added, and the reason it could stop. --compare draws a second strategy's run beside the
first; for 2-D input, --svg-dir also writes one SVG per step. The strategies are those of
`pqh hull` plus ows-inflation; the short names farthest, closest and ows still work.

Details: README.md, \"Seeing a run\"; limits: docs/limits.md.";

/// Inputs larger than this make pages too heavy to be useful.
const MAX_POINTS: usize = 5000;

/// Arguments of `pqh trace`.
#[derive(Debug, Args)]
pub struct TraceArgs {
    /// Points file ('-' reads standard input); or use --family
    #[arg(value_name = "FILE")]
    file: Option<PathBuf>,

    /// Generate the points from this family instead of reading a file: cube, sphere, corners,
    /// simplex, shell, lens, lattice, clusters, duplicates or tilted
    #[arg(long, value_name = "NAME")]
    family: Option<String>,

    /// Number of generated points, at most 5000 (default: 40)
    #[arg(long, value_name = "N")]
    points: Option<usize>,

    /// Dimension of the generated points, 2 or 3 (default: 3)
    #[arg(long, value_name = "D")]
    dimension: Option<usize>,

    /// Seed of the generated points and of the default disturbances (default: 1)
    #[arg(long, value_name = "S")]
    seed: Option<u64>,

    /// The strategy to trace
    #[arg(long, value_enum)]
    strategy: StrategyArg,

    /// A second strategy, drawn beside the first on the same points
    #[arg(long, value_enum, value_name = "STRATEGY")]
    compare: Option<StrategyArg>,

    /// Query point of closest-to-origin, as x,y or x,y,z (default: the origin)
    #[arg(
        long,
        alias = "origin",
        value_name = "X,Y[,Z]",
        allow_hyphen_values = true
    )]
    query: Option<String>,

    /// Points file of disturbances for ows-inflation, each resisted along its opposite
    /// (default: a few seeded unit directions)
    #[arg(long, value_name = "FILE")]
    disturbances: Option<PathBuf>,

    /// Where to write the HTML page
    #[arg(long, value_name = "OUT.html")]
    output: PathBuf,

    /// Also write one SVG per step into this directory (2-D only)
    #[arg(long, value_name = "DIR")]
    svg_dir: Option<PathBuf>,

    /// The page's title (default: the input and the strategies)
    #[arg(long)]
    title: Option<String>,
}

/// The `--strategy` / `--compare` values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum StrategyArg {
    /// FarthestPoint: the full hull
    #[value(alias = "farthest", alias = "full")]
    FarthestPoint,
    /// ClosestToOrigin: distance from the query point
    #[value(alias = "closest")]
    ClosestToOrigin,
    /// OwsInflation: the object-wrench-space metric
    #[value(alias = "ows")]
    OwsInflation,
}

impl StrategyArg {
    fn name(self) -> &'static str {
        match self {
            StrategyArg::FarthestPoint => "farthest-point",
            StrategyArg::ClosestToOrigin => "closest-to-origin",
            StrategyArg::OwsInflation => "ows-inflation",
        }
    }
}

/// Runs `pqh trace`.
pub fn run(args: &TraceArgs) -> Result<(), CliError> {
    let usage = |m: &str| Err(CliError::Usage(m.to_string()));
    let strategies: Vec<StrategyArg> = [Some(args.strategy), args.compare]
        .into_iter()
        .flatten()
        .collect();
    if args.query.is_some() && !strategies.contains(&StrategyArg::ClosestToOrigin) {
        return usage("--query only applies to the closest-to-origin strategy");
    }
    if args.disturbances.is_some() && !strategies.contains(&StrategyArg::OwsInflation) {
        return usage("--disturbances only applies to the ows-inflation strategy");
    }
    let (input, name) = match (&args.file, &args.family) {
        (Some(_), Some(_)) => return usage("give a points FILE or --family, not both"),
        (None, None) => {
            return usage("give a points FILE ('-' for standard input) or --family NAME");
        }
        (Some(file), None) => {
            if args.points.is_some() || args.dimension.is_some() || args.seed.is_some() {
                return usage("--points, --dimension and --seed only apply to --family");
            }
            let source = Source::new(Some(file));
            let table = source.read_points()?;
            let input = Input {
                dimension: table.dimension(),
                coords: table.coords().to_vec(),
            };
            (input, source.name())
        }
        (None, Some(family)) => generated(args, family)?,
    };
    let count = input.coords.len() / input.dimension;
    if count > MAX_POINTS {
        return Err(CliError::Input(format!(
            "{name}: {count} points; pqh trace draws at most {MAX_POINTS}"
        )));
    }
    with_dimension!(
        input.dimension,
        [2, 3],
        |D| trace::<D>(args, &input, &name, &strategies),
        else |d| Err(CliError::Input(format!(
            "{name}: the points have dimension {d}; pqh trace draws 2-D and 3-D inputs"
        )))
    )
}

/// Points read or generated, row-major.
struct Input {
    dimension: usize,
    coords: Vec<f64>,
}

/// Points of `--family`, and their description.
fn generated(args: &TraceArgs, family: &str) -> Result<(Input, String), CliError> {
    let family: Family = family
        .parse()
        .map_err(|e| CliError::Usage(format!("--family: {e}")))?;
    let (n, d, seed) = (
        args.points.unwrap_or(40),
        args.dimension.unwrap_or(3),
        args.seed.unwrap_or(1),
    );
    if !(2..=3).contains(&d) {
        return Err(CliError::Usage(format!(
            "--dimension: pqh trace draws 2-D and 3-D inputs, not {d}"
        )));
    }
    if n > MAX_POINTS {
        return Err(CliError::Usage(format!(
            "--points: pqh trace draws at most {MAX_POINTS} points"
        )));
    }
    let input = Input {
        dimension: d,
        coords: generate_flat(&family, d, n, seed),
    };
    let count = input.coords.len() / d;
    Ok((
        input,
        format!("{family}, {count} points, {d}-D, seed {seed}"),
    ))
}

fn trace<const D: usize>(
    args: &TraceArgs,
    input: &Input,
    name: &str,
    strategies: &[StrategyArg],
) -> Result<(), CliError> {
    let points: Vec<[f64; D]> = input
        .coords
        .chunks_exact(D)
        .map(|p| std::array::from_fn(|i| p[i]))
        .collect();
    let query: [f64; D] = match &args.query {
        None => [0.0; D],
        Some(text) => {
            let q = parse_point("--query", text)?;
            if q.len() != D {
                return Err(CliError::Usage(format!(
                    "--query has {} coordinate(s) but the points have dimension {D}",
                    q.len()
                )));
            }
            std::array::from_fn(|i| q[i])
        }
    };
    let disturbances = disturbances::<D>(args)?;
    if args.svg_dir.is_some() && D != 2 {
        return Err(CliError::Usage(
            "--svg-dir: SVG pictures are drawn for 2-D inputs only".into(),
        ));
    }
    let mut traces: Vec<Trace<D>> = Vec::new();
    for &s in strategies {
        let traced = match s {
            StrategyArg::FarthestPoint => {
                Hull::try_with_strategy_traced(&points, FarthestPoint::new()).map(|r| r.2)
            }
            StrategyArg::ClosestToOrigin => {
                Hull::try_with_strategy_traced(&points, ClosestToOrigin::towards(query))
                    .map(|r| r.2)
            }
            StrategyArg::OwsInflation => {
                Hull::try_with_strategy_traced(&points, OwsInflation::with_rays(&disturbances))
                    .map(|r| r.2)
            }
        };
        traces.push(traced.map_err(|e| CliError::Geometry(format!("{name}: {e}")))?);
    }
    let title = args.title.clone().unwrap_or_else(|| {
        let names: Vec<&str> = strategies.iter().map(|s| s.name()).collect();
        format!("pqh trace: {name}: {}", names.join(" vs "))
    });
    let refs: Vec<&Trace<D>> = traces.iter().collect();
    let page = html::trace_page(&title, &refs).map_err(|e| CliError::Usage(e.to_string()))?;
    write(&args.output, page.as_bytes())?;
    if let Some(dir) = &args.svg_dir {
        std::fs::create_dir_all(dir)
            .map_err(|e| CliError::Input(format!("{}: cannot create: {e}", dir.display())))?;
        for (s, trace) in strategies.iter().zip(&traces) {
            let pictures = svg::trace_svgs(trace).map_err(|e| CliError::Usage(e.to_string()))?;
            for (k, picture) in pictures.iter().enumerate() {
                write(
                    &dir.join(format!("{}-{k:04}.svg", s.name())),
                    picture.as_bytes(),
                )?;
            }
        }
    }
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    for (s, trace) in strategies.iter().zip(&traces) {
        let expansions = trace
            .events
            .iter()
            .filter(|e| matches!(e, Event::Expanded { .. }))
            .count();
        writeln!(
            out,
            "{}: {} steps, {expansions} expansions; {}",
            s.name(),
            trace.events.len(),
            trace.stop_reason().unwrap_or("no stop recorded")
        )?;
    }
    writeln!(out, "wrote {}", args.output.display())?;
    Ok(())
}

/// `--disturbances FILE`, or seeded unit directions (8 in 2-D, 12 in 3-D).
fn disturbances<const D: usize>(args: &TraceArgs) -> Result<Vec<[f64; D]>, CliError> {
    let Some(path) = &args.disturbances else {
        let mut rng = Rng::new(args.seed.unwrap_or(1) ^ 0x0d15_7b5e);
        let count = if D == 2 { 8 } else { 12 };
        return Ok((0..count)
            .map(|_| {
                let u = rng.unit_vector(D);
                std::array::from_fn(|i| u[i])
            })
            .collect());
    };
    let source = Source::new(Some(path));
    let table = source.read_points()?;
    table.to_arrays::<D>().ok_or_else(|| {
        CliError::Input(format!(
            "{}: the disturbances have dimension {} but the points have dimension {D}",
            source.name(),
            table.dimension()
        ))
    })
}

fn write(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    std::fs::write(path, bytes)
        .map_err(|e| CliError::Input(format!("{}: cannot write: {e}", path.display())))
}
