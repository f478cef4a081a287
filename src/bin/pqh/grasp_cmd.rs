//! `pqh grasp`: Q1 / Q∞ of grasps given as JSON, one JSON line out per grasp, in input order.

use crate::error::CliError;
use clap::{Args, ValueEnum};
use pqhull::grasp::quality::{Evaluator, Method, Metric, Quality, QualityError};
use pqhull::grasp::{Contact, FrictionModel, Grasp};
use serde_json::{Value, json};
use std::io::{Read, Write};
use std::path::PathBuf;

pub const LONG_ABOUT: &str = "\
Evaluates grasp quality. Input (a file, or standard input for '-' or no path): one grasp, a JSON
array of grasps, or JSON Lines. A grasp is
  {\"contacts\":[{\"position\":[x,y,z],\"normal\":[x,y,z],\"tangent\":[x,y,z]?}, ...],
   \"friction\":mu, \"cone_edges\":k, \"torque_reference\":[x,y,z]?, \"torque_scale\":rho?}
with inward unit normals (the direction the finger pushes). Output: one JSON line per grasp, in
input order: index, force_closure, quality, stats {points_processed, facets_created, elapsed_us}.
A malformed grasp gets {\"index\":i,\"error\":\"...\"} and the others are still evaluated.";

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum MetricArg {
    /// Ferrari–Canny Q1 over the union of contact wrenches
    Q1,
    /// Q∞ over the Minkowski sum (implicit for the partial method)
    Qinf,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum MethodArg {
    /// Partial hull: stop once the nearest facet is certain (default)
    Partial,
    /// Full hull with pqhull's engine
    Full,
    /// Full hull with Qhull (needs the `qhull` feature)
    Qhull,
}

#[derive(Debug, Args)]
pub struct GraspArgs {
    /// Grasps file (JSON, JSON array or JSON Lines); '-' or nothing reads standard input
    pub file: Option<PathBuf>,
    /// Metric
    #[arg(long, value_enum, default_value_t = MetricArg::Q1)]
    pub metric: MetricArg,
    /// Method
    #[arg(long, value_enum, default_value_t = MethodArg::Partial)]
    pub method: MethodArg,
    /// Worker threads (default: all cores)
    #[arg(long)]
    pub threads: Option<usize>,
    /// Q∞ with the zero wrench added to every contact (GraspIt!'s variant)
    #[arg(long)]
    pub zero_wrench: bool,
}

pub fn method(arg: MethodArg) -> Result<Method, CliError> {
    match arg {
        MethodArg::Partial => Ok(Method::Partial),
        MethodArg::Full => Ok(Method::Full),
        #[cfg(feature = "qhull")]
        MethodArg::Qhull => Ok(Method::Qhull),
        #[cfg(not(feature = "qhull"))]
        MethodArg::Qhull => Err(CliError::Usage(
            "--method qhull needs pqh built with the `qhull` feature".into(),
        )),
    }
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

/// The grasps as JSON values: one document (object or array) or JSON Lines. A line that is not
/// JSON becomes an error entry for its index.
fn split(text: &str) -> Vec<Result<Value, String>> {
    if let Ok(value) = serde_json::from_str::<Value>(text) {
        return match value {
            Value::Array(items) => items.into_iter().map(Ok).collect(),
            other => vec![Ok(other)],
        };
    }
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(n, l)| serde_json::from_str(l).map_err(|e| format!("line {}: not JSON: {e}", n + 1)))
        .collect()
}

fn vec3(value: &Value, what: &str) -> Result<[f64; 3], String> {
    let items = value
        .as_array()
        .filter(|a| a.len() == 3)
        .ok_or_else(|| format!("{what}: expected an array of 3 numbers"))?;
    let mut out = [0.0; 3];
    for (o, v) in out.iter_mut().zip(items) {
        *o = v
            .as_f64()
            .ok_or_else(|| format!("{what}: {v} is not a number"))?;
    }
    Ok(out)
}

/// Parses one grasp (errors name the field and contact).
pub fn parse_grasp(value: &Value) -> Result<Grasp, String> {
    let object = value.as_object().ok_or("a grasp must be a JSON object")?;
    let contacts = object
        .get("contacts")
        .and_then(Value::as_array)
        .ok_or("missing \"contacts\" array")?;
    let mut parsed = Vec::with_capacity(contacts.len());
    for (i, c) in contacts.iter().enumerate() {
        let field = |name: &str| {
            c.get(name)
                .ok_or(format!("contact {i}: missing \"{name}\""))
        };
        let position = vec3(field("position")?, &format!("contact {i} position"))?;
        let normal = vec3(field("normal")?, &format!("contact {i} normal"))?;
        let tangent = match c.get("tangent") {
            Some(t) => Some(vec3(t, &format!("contact {i} tangent"))?),
            None => None,
        };
        parsed.push(
            Contact::try_new(position, normal, tangent).map_err(|e| e.at_contact(i).to_string())?,
        );
    }
    let friction = object
        .get("friction")
        .and_then(Value::as_f64)
        .ok_or("missing or non-numeric \"friction\"")?;
    let edges = object
        .get("cone_edges")
        .and_then(Value::as_u64)
        .ok_or("missing or non-integer \"cone_edges\"")?;
    let model = FrictionModel::try_new(friction, edges as usize).map_err(|e| e.to_string())?;
    let mut builder = Grasp::builder(parsed, model);
    if let Some(c) = object.get("torque_reference") {
        builder = builder.torque_reference(vec3(c, "torque_reference")?);
    }
    if let Some(rho) = object.get("torque_scale") {
        let rho = rho.as_f64().ok_or("\"torque_scale\" is not a number")?;
        builder = builder.torque_scale(rho);
    }
    builder.build().map_err(|e| e.to_string())
}

pub fn quality_json(index: usize, result: &Result<Quality, QualityError>) -> Value {
    match result {
        Ok(q) => json!({
            "index": index,
            "force_closure": q.force_closure,
            "quality": q.value,
            "stats": {
                "points_processed": q.stats.points_processed,
                "facets_created": q.stats.facets_created,
                "elapsed_us": q.stats.elapsed.as_secs_f64() * 1e6,
            }
        }),
        Err(e) => json!({"index": index, "error": e.to_string()}),
    }
}

pub fn run(args: &GraspArgs) -> Result<(), CliError> {
    let metric = match args.metric {
        MetricArg::Q1 => Metric::Q1,
        MetricArg::Qinf => Metric::QInf {
            with_zero_wrench: args.zero_wrench,
        },
    };
    let method = method(args.method)?;
    let text = read_input(&args.file)?;
    let entries: Vec<Result<Grasp, String>> = split(&text)
        .into_iter()
        .map(|v| v.and_then(|v| parse_grasp(&v)))
        .collect();
    let evaluate = || -> Vec<Option<Result<Quality, QualityError>>> {
        use rayon::prelude::*;
        entries
            .par_iter()
            .map_init(
                || Evaluator::new(metric, method),
                |ev, g| g.as_ref().ok().map(|g| ev.evaluate(g)),
            )
            .collect()
    };
    let results = match args.threads {
        Some(0) => return Err(CliError::Usage("--threads must be at least 1".into())),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| CliError::Usage(format!("cannot start {n} threads: {e}")))?
            .install(evaluate),
        None => evaluate(),
    };
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    for (index, (entry, result)) in entries.iter().zip(&results).enumerate() {
        let line = match (entry, result) {
            (Err(message), _) => json!({"index": index, "error": message}),
            (Ok(_), Some(result)) => quality_json(index, result),
            (Ok(_), None) => unreachable!("every parsed grasp is evaluated"),
        };
        writeln!(out, "{line}")?;
    }
    out.flush()?;
    Ok(())
}
