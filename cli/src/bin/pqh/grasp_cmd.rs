//! `pqh grasp`: Q1 / Q∞ / Q_OWS of grasps given as JSON, one JSON line out per grasp, in input
//! order.

use crate::error::CliError;
use crate::limits::{FULL_QINF_POINTS, MAX_THREADS};
use crate::methods::{MethodArg, MetricArg, method_for};
use clap::Args;
use pqhull::grasp::json::{error_line, parse_grasp, quality_line, split_grasps};
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::{
    Evaluation, Evaluator, FrictionModel, Gradient, Grasp, Method, Metric, QualityError,
    ThreadsError, ows_gradient, q1_gradient, qinf_gradient,
};
use pqhull::mesh::Mesh;
use serde_json::Value;
use std::io::{Read, Write};
use std::path::PathBuf;

pub const LONG_ABOUT: &str = "\
Evaluates the quality of grasps read from FILE (standard input for '-' or no FILE): one grasp, a
JSON array of grasps, or JSON Lines, each
  {\"contacts\":[{\"position\":[x,y,z],\"normal\":[x,y,z],\"tangent\":[x,y,z]?,\"torsion\":g?}, ...],
   \"friction\":mu, \"cone_edges\":k, \"torque_reference\":[x,y,z]?, \"torque_scale\":rho?}
with inward unit normals. Output: one JSON line per grasp, in input order: index, force_closure,
quality (null when the metric has no value), stats {points_processed, facets_created,
elapsed_us}; a grasp that cannot be read or evaluated gets {\"index\":i,\"error\":\"...\"}
and the others are still evaluated. --metric ows needs --mesh or --disturbances. --gradient
(q1, qinf, ows by an exact method; null where the quality is) adds \"gradient\": {positions, normals (one [x,y,z] per contact, input order), friction,
differentiable}, the exact derivative of the value.

Details: README.md, \"Grasp quality\", \"Object wrench space\" and \"Other metrics\" (soft
fingers, the bracket); limits (cone_edges 3 to 1024, 1 to 256 contacts per grasp) and exit
statuses: docs/limits.md.";

#[derive(Debug, Args)]
pub struct GraspArgs {
    /// Grasps file (JSON, JSON array or JSON Lines); '-' or nothing reads standard input
    pub file: Option<PathBuf>,
    /// Metric
    #[arg(long, value_enum, default_value_t = MetricArg::Q1)]
    pub metric: MetricArg,
    /// Q1: add a "bracket" pair (low, high) to each line, Q1 of the pyramids inscribed in and
    /// circumscribed about the friction cones (Q1 of the true cones lies between)
    #[arg(long)]
    pub cone_bracket: bool,
    /// Q1, Q∞ and Q_OWS (exact methods): add the exact "gradient" of the value with respect to every contact's position and
    /// normal and the friction coefficient (and whether the value is differentiable there)
    #[arg(long, conflicts_with = "cone_bracket")]
    pub gradient: bool,
    /// resist: the wrench to resist, fx,fy,fz,tx,ty,tz in the grasps' torque units (a row of
    /// --disturbances)
    #[arg(long, allow_hyphen_values = true)]
    pub wrench: Option<String>,
    /// Method
    #[arg(long, value_enum, default_value_t = MethodArg::Partial)]
    pub method: MethodArg,
    /// Worker threads, 1 to 256 (default: all cores)
    #[arg(long, value_parser = crate::limits::threads())]
    pub threads: Option<usize>,
    /// Q∞ with the zero wrench added to every contact (GraspIt!'s variant)
    #[arg(long)]
    pub zero_wrench: bool,
    /// Run Q∞ by --method full or qhull even above 4096 Minkowski points per grasp (it hulls all
    /// k^m of them exactly, far slower than --method partial, same value; docs/limits.md)
    #[arg(long)]
    pub force: bool,
    /// OWS: the object's mesh (OBJ or STL)
    #[arg(long, conflicts_with = "disturbances")]
    pub mesh: Option<PathBuf>,
    /// OWS: a task wrench space instead of a mesh (one 6-D wrench per line, comma or space
    /// separated, in the grasps' torque units)
    #[arg(long)]
    pub disturbances: Option<PathBuf>,
    /// OWS with --mesh: friction coefficient of the disturbance cones (default: the first grasp's)
    #[arg(long)]
    pub ows_friction: Option<f64>,
    /// OWS with --mesh: edges of the disturbance cones, 3 to 1024 (default: the first grasp's)
    #[arg(long, value_parser = crate::limits::cone_edges())]
    pub ows_edges: Option<usize>,
}

fn read_input(file: &Option<PathBuf>) -> Result<String, CliError> {
    match file.as_deref().filter(|p| p.as_os_str() != "-") {
        Some(path) => std::fs::read_to_string(path)
            .map_err(|e| CliError::Input(format!("cannot read {}: {e}", path.display()))),
        None => {
            let mut text = String::new();
            std::io::stdin()
                .read_to_string(&mut text)
                .map_err(|e| CliError::Input(format!("cannot read <stdin>: {e}")))?;
            Ok(text)
        }
    }
}

/// The grasps as JSON values (see [`split_grasps`]), errors as their messages.
fn split(text: &str) -> Vec<Result<Value, String>> {
    split_grasps(text)
        .into_iter()
        .map(|v| v.map_err(|e| e.to_string()))
        .collect()
}

/// The output line of grasp `index` from its evaluation: verdict, value and work.
fn evaluation_line(index: usize, e: &Evaluation) -> Value {
    quality_line(index, e.force_closure, e.value, &e.stats)
}

/// Evaluates every parsed grasp on `threads` workers (one evaluator each, with a progress bar)
/// and returns the output lines in input order; entries that did not parse keep their error.
/// Q∞ by a full method on a grasp whose Minkowski sum has more than
/// [`FULL_QINF_POINTS`] points: a usage error (before any work) naming the grasp, unless forced.
fn refuse_large_minkowski_sums(
    entries: &[Result<Grasp, String>],
    zero_wrench: bool,
) -> Result<(), CliError> {
    let largest = entries
        .iter()
        .enumerate()
        .filter_map(|(i, g)| Some((i, g.as_ref().ok()?.minkowski_points(zero_wrench))))
        .max_by_key(|&(_, n)| n.unwrap_or(usize::MAX));
    match largest {
        Some((index, n)) if n.is_none_or(|n| n > FULL_QINF_POINTS) => {
            let points = n.map_or("more than 2^64".to_string(), |n| n.to_string());
            Err(CliError::Usage(format!(
                "grasp {index}: Q∞ by a full method hulls its {points} Minkowski points (more than \
                 {FULL_QINF_POINTS}: seconds to minutes and up to gigabytes per grasp; 4 contacts \
                 × 16 edges took 35 s and 2.7 GB); --method partial gives the same value in \
                 milliseconds, --force runs it anyway"
            )))
        }
        _ => Ok(()),
    }
}

fn evaluate_lines<E, T: Send, Er: std::fmt::Display + Send>(
    entries: &[Result<Grasp, String>],
    threads: Option<usize>,
    new_evaluator: impl Fn() -> E + Sync + Send,
    evaluate: impl Fn(&mut E, &Grasp) -> Result<T, Er> + Sync + Send,
    line: impl Fn(usize, &T) -> Value,
) -> Result<Vec<Value>, CliError> {
    let bar = crate::progress::bar(entries.len(), "grasps");
    // A few runs of consecutive grasps per worker, one evaluator each, reused along its run
    // (rayon's `map_init` makes one per job it splits off: a cold hull arena each time).
    let results = with_threads(threads, || {
        use rayon::prelude::*;
        let runs = 4 * rayon::current_num_threads();
        let size = entries.len().div_ceil(runs).max(1);
        entries
            .par_chunks(size)
            .map(|run| {
                let mut ev = new_evaluator();
                run.iter()
                    .map(|g| {
                        let result = g.as_ref().ok().map(|g| evaluate(&mut ev, g));
                        bar.inc(1);
                        result
                    })
                    .collect::<Vec<_>>()
            })
            .collect::<Vec<_>>()
            .into_iter()
            .flatten()
            .collect::<Vec<_>>()
    })?;
    bar.finish_and_clear();
    Ok(entries
        .iter()
        .zip(&results)
        .enumerate()
        .map(|(index, (entry, result))| match (entry, result) {
            (Err(message), _) => error_line(index, message),
            (Ok(_), Some(Ok(result))) => line(index, result),
            (Ok(_), Some(Err(e))) => error_line(index, &e.to_string()),
            (Ok(_), None) => unreachable!("every parsed grasp is evaluated"),
        })
        .collect())
}

/// Runs `work` on `threads` workers (default: rayon's global pool, all cores), by the
/// library's thread policy.
pub fn with_threads<T: Send>(
    threads: Option<usize>,
    work: impl FnOnce() -> T + Send,
) -> Result<T, CliError> {
    pqhull::grasp::with_threads(threads, work).map_err(|e| match e {
        ThreadsError::OutOfRange { threads } => {
            CliError::Usage(format!("--threads: {threads} is not in 1..={MAX_THREADS}"))
        }
        e => CliError::Usage(e.to_string()),
    })
}

/// The object wrench space for `--metric ows`, from `--mesh` or `--disturbances`; `friction` is
/// the disturbance cones' model when it comes from a mesh.
pub fn prepare_space(
    mesh: Option<&std::path::Path>,
    disturbances: Option<&std::path::Path>,
    friction: impl FnOnce() -> Result<FrictionModel, CliError>,
) -> Result<ObjectWrenchSpace, CliError> {
    match (mesh, disturbances) {
        (Some(path), None) => {
            let mesh = Mesh::load(path).map_err(|e| CliError::Input(e.to_string()))?;
            ObjectWrenchSpace::from_mesh(&mesh, friction()?)
                .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))
        }
        (None, Some(path)) => {
            let text = std::fs::read_to_string(path)
                .map_err(|e| CliError::Input(format!("cannot read {}: {e}", path.display())))?;
            let table = pqhull_cli::points_file::parse_points(&text)
                .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
            let wrenches = table.to_arrays::<6>().ok_or_else(|| {
                CliError::Input(format!(
                    "{}: disturbances must have 6 coordinates, found {}",
                    path.display(),
                    table.dimension()
                ))
            })?;
            ObjectWrenchSpace::from_disturbances(wrenches)
                .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))
        }
        _ => Err(CliError::Usage(
            "--metric ows needs --mesh FILE or --disturbances FILE".into(),
        )),
    }
}

fn run_ows(
    args: &GraspArgs,
    method: Method,
    entries: Vec<Result<Grasp, String>>,
    values: &[Result<Value, String>],
) -> Result<Vec<Value>, CliError> {
    let first = entries
        .iter()
        .find_map(|g| g.as_ref().ok())
        .map(Grasp::friction);
    let friction = || {
        let default = first.ok_or_else(|| {
            CliError::Input("no valid grasp to take the disturbance cones' friction from".into())
        })?;
        FrictionModel::try_new(
            args.ows_friction.unwrap_or(default.friction()),
            args.ows_edges.unwrap_or(default.cone_edges()),
        )
        .map_err(|e| CliError::Usage(format!("--ows-friction/--ows-edges: {e}")))
    };
    let started = std::time::Instant::now();
    let space = prepare_space(args.mesh.as_deref(), args.disturbances.as_deref(), friction)?;
    eprintln!(
        "pqh: note: {} (prepared in {:.1} ms)",
        space.describe(),
        started.elapsed().as_secs_f64() * 1e3
    );
    // With a mesh, every grasp is put in the mesh's torque frame; one that names its own is an
    // error rather than silently moved.
    let framed: Vec<Result<Grasp, String>> = entries
        .into_iter()
        .zip(values)
        .map(|(g, v)| {
            let g = g?;
            let sets_frame = v.as_ref().is_ok_and(|v| {
                v.get("torque_reference").is_some() || v.get("torque_scale").is_some()
            });
            if space.torque_frame().is_some() && sets_frame {
                return Err(
                    "with --mesh the torque frame is the mesh's (centre of mass, \
                            characteristic length): remove torque_reference/torque_scale"
                        .to_string(),
                );
            }
            space.frame(&g).map_err(|e| e.to_string())
        })
        .collect();
    if args.gradient {
        // One evaluator per worker, its gradient through the deciding disturbance's facet.
        return evaluate_lines(
            &framed,
            args.threads,
            || Evaluator::new(Metric::Ows, method, Some(&space)),
            |evaluator, g| {
                let quality = evaluator.as_mut().map_err(|e| e.clone())?.evaluate(g)?;
                Ok::<_, QualityError>((quality, ows_gradient(g, &space, &quality)))
            },
            |index, (q, gradient): &(Evaluation, Option<Gradient>)| {
                let mut line = evaluation_line(index, q);
                // No value (not force closure): no gradient either, as `quality` is null.
                line["gradient"] = gradient.as_ref().map_or(Value::Null, gradient_json);
                line
            },
        );
    }
    score_lines(
        &framed,
        args.threads,
        Metric::Ows,
        method,
        Some(&space),
        evaluation_line,
    )
}

/// The lines of `metric` by `method` ([`Evaluator`]; `space` for Q_OWS), each made by `line`.
/// An evaluator that cannot be made (a zero wrench to resist) is a usage error, before any work.
fn score_lines(
    entries: &[Result<Grasp, String>],
    threads: Option<usize>,
    metric: Metric,
    method: Method,
    space: Option<&ObjectWrenchSpace>,
    line: impl Fn(usize, &Evaluation) -> Value,
) -> Result<Vec<Value>, CliError> {
    Evaluator::new(metric, method, space)
        .map_err(|e| CliError::Usage(format!("--metric {}: {e}", metric.name())))?;
    evaluate_lines(
        entries,
        threads,
        || Evaluator::new(metric, method, space),
        |evaluator, g| evaluator.as_mut().map_err(|e| e.clone())?.evaluate(g),
        line,
    )
}

/// `--cone-bracket`: Q1's line (the inscribed pyramids' Q1) with `"bracket": [low, high]`.
fn bracket_line(index: usize, e: &Evaluation) -> Value {
    let mut line = evaluation_line(index, e);
    let bracket = e
        .bracket
        .expect("the cone bracket's evaluation has a bracket");
    line["bracket"] = serde_json::json!([bracket.low, bracket.high]);
    line
}

/// `--gradient`: Q1's line with `"gradient": {positions, normals, friction, differentiable}`.
fn gradient_line(index: usize, (q, g): &(Evaluation, Gradient)) -> Value {
    let mut line = evaluation_line(index, q);
    line["gradient"] = gradient_json(g);
    line
}

/// `{positions, normals, friction, differentiable}`.
fn gradient_json(g: &Gradient) -> Value {
    serde_json::json!({
        "positions": g.positions,
        "normals": g.normals,
        "friction": g.friction,
        "differentiable": g.differentiable,
    })
}

pub fn run(args: &GraspArgs) -> Result<(), CliError> {
    let metric = args
        .metric
        .metric(args.zero_wrench, args.wrench.as_deref())?;
    if args.cone_bracket && metric != Metric::Q1 {
        return Err(CliError::Usage("--cone-bracket is for --metric q1".into()));
    }
    if args.gradient && !matches!(metric, Metric::Q1 | Metric::QInf { .. } | Metric::Ows) {
        return Err(CliError::Usage(
            "--gradient is computed for --metric q1, qinf and ows (not for the others)".into(),
        ));
    }
    // Options that would be silently ignored are errors instead.
    if metric != Metric::Ows && (args.mesh.is_some() || args.disturbances.is_some()) {
        return Err(CliError::Usage(
            "--mesh and --disturbances are for --metric ows".into(),
        ));
    }
    if (args.ows_friction.is_some() || args.ows_edges.is_some()) && args.mesh.is_none() {
        return Err(CliError::Usage(
            "--ows-friction and --ows-edges are for --metric ows --mesh".into(),
        ));
    }
    let method = method_for(args.method, metric)?;
    if args.gradient && method == Method::Ellipsoid {
        return Err(CliError::Usage(
            "--gradient needs an exact method (the ellipsoid's value is an approximation)".into(),
        ));
    }
    let text = read_input(&args.file)?;
    let values = split(&text);
    if values.is_empty() {
        return Err(CliError::Input(format!(
            "{}: no grasp in the input (expected a JSON object, a JSON array or JSON Lines)",
            input_name(&args.file)
        )));
    }
    let entries: Vec<Result<Grasp, String>> = values
        .iter()
        .map(|v| {
            v.clone()
                .and_then(|v| parse_grasp(&v).map_err(|e| e.to_string()))
        })
        .collect();
    let readable = entries.iter().filter(|e| e.is_ok()).count();
    let lines = match metric {
        Metric::Ows => run_ows(args, method, entries, &values)?,
        metric if args.gradient => {
            if matches!(metric, Metric::QInf { .. }) && method != Method::Partial && !args.force {
                refuse_large_minkowski_sums(&entries, args.zero_wrench)?;
            }
            evaluate_lines(
                &entries,
                args.threads,
                || Evaluator::new(metric, method, None),
                |evaluator, g| {
                    let quality = evaluator
                        .as_mut()
                        .map_err(|e| e.to_string())?
                        .evaluate(g)
                        .map_err(|e| e.to_string())?;
                    let gradient = match metric {
                        Metric::QInf { .. } => qinf_gradient(g, &quality),
                        _ => q1_gradient(g, &quality),
                    };
                    Ok::<_, String>((quality, gradient.map_err(|e| e.to_string())?))
                },
                gradient_line,
            )?
        }
        Metric::Q1 if args.cone_bracket => score_lines(
            &entries,
            args.threads,
            Metric::ConeBracket,
            method,
            None,
            bracket_line,
        )?,
        metric => {
            if matches!(metric, Metric::QInf { .. }) && method != Method::Partial && !args.force {
                refuse_large_minkowski_sums(&entries, args.zero_wrench)?;
            }
            score_lines(
                &entries,
                args.threads,
                metric,
                method,
                None,
                evaluation_line,
            )?
        }
    };
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    for line in lines {
        writeln!(out, "{line}")?;
    }
    out.flush()?;
    if readable == 0 {
        let what = match values.len() {
            1 => "the grasp could not be read (see its error line)".to_string(),
            n => format!("none of the {n} grasps could be read (see the error lines)"),
        };
        return Err(CliError::Input(format!(
            "{}: {what}",
            input_name(&args.file)
        )));
    }
    Ok(())
}

/// The input's name in messages: the path, or `<stdin>`.
fn input_name(file: &Option<PathBuf>) -> String {
    match file.as_deref().filter(|p| p.as_os_str() != "-") {
        Some(path) => path.display().to_string(),
        None => "<stdin>".to_string(),
    }
}
