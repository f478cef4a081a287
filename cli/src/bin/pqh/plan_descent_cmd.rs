//! `pqh plan --planner descent`: the planner that climbs the metric, by partial and by full
//! hulls from the same starts.

use crate::error::CliError;
use crate::plan_cmd::PlanArgs;
use pqhull::grasp::FrictionModel;
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::quality::{Method, Metric};
use pqhull::mesh::Mesh;
use pqhull::plan::{DescentConfig, DescentReport, plan_descent};
use serde_json::json;
use std::io::Write;

/// Runs the descent planner as `args` say, on `mesh` (`name` in reports).
pub fn run(
    args: &PlanArgs,
    mesh: &Mesh,
    name: &str,
    friction: FrictionModel,
    metric: Metric,
) -> Result<(), CliError> {
    if !matches!(metric, Metric::Q1 | Metric::QInf { .. } | Metric::Ows) {
        return Err(CliError::Usage(format!(
            "--planner descent climbs q1, qinf, qinf0 and ows, not {metric}: use --planner sampler"
        )));
    }
    if args.output.is_some() {
        return Err(CliError::Usage(
            "--output draws the sampler's plans: use it with --planner sampler".into(),
        ));
    }
    let space = match metric {
        Metric::Ows => Some(
            ObjectWrenchSpace::from_mesh(mesh, friction)
                .map_err(|e| CliError::Input(format!("{name}: {e}")))?,
        ),
        _ => None,
    };
    let config = DescentConfig {
        starts: args.starts,
        evaluations: args.evaluations,
        screen: args.screen,
        seed: args.seed,
        ..DescentConfig::new(args.contacts, friction, metric)
    };
    let fail = |e: pqhull::plan::PlanError| CliError::Geometry(format!("{name}: {e}"));
    let partial = plan_descent(mesh, space.as_ref(), &config, Method::Partial).map_err(fail)?;
    // Q∞ by the full method hulls every Minkowski point: not run here (as for the sampler).
    let full = match (metric, args.full_samples) {
        (Metric::QInf { .. }, _) | (_, Some(0)) => None,
        _ => Some(plan_descent(mesh, space.as_ref(), &config, Method::Full).map_err(fail)?),
    };
    let same_best = full.as_ref().map(|f| same(&partial, f));
    let speedup = full
        .as_ref()
        .map(|f| f.quality_time.as_secs_f64() / partial.quality_time.as_secs_f64());
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    if args.json {
        let document = json!({
            "mesh": name,
            "planner": "descent",
            "metric": metric.name(),
            "contacts": args.contacts,
            "edges": args.edges,
            "friction": args.friction,
            "seed": args.seed,
            "starts": args.starts,
            "evaluations_per_start": args.evaluations,
            "partial": partial.to_json(),
            "full": full.as_ref().map(DescentReport::to_json),
            "same_best": same_best,
            "quality_speedup": speedup,
        });
        writeln!(out, "{document}")?;
    } else {
        writeln!(
            out,
            "descent on {name}: {} starts × at most {} evaluations, {} contacts, μ = {}, {} cone \
             edges, metric {}",
            args.starts,
            args.evaluations,
            args.contacts,
            args.friction,
            args.edges,
            metric.name()
        )?;
        writeln!(
            out,
            "{:<10} {:>11} {:>8} {:>12} {:>12} {:>12} {:>12}",
            "method", "evaluations", "closure", "quality s", "gradient s", "other s", "best"
        )?;
        let mut rows = vec![("partial", &partial)];
        rows.extend(full.as_ref().map(|f| ("full", f)));
        for (method, r) in rows {
            writeln!(
                out,
                "{:<10} {:>11} {:>8} {:>12.4} {:>12.4} {:>12.4} {:>12}",
                method,
                r.evaluations,
                r.force_closure(),
                r.quality_time.as_secs_f64(),
                r.gradient_time.as_secs_f64(),
                r.other_time.as_secs_f64(),
                r.best().map_or("none".to_string(), |b| format!(
                    "{:.6} (#{})",
                    b.value, b.start
                ))
            )?;
        }
        if let (Some(s), Some(same)) = (speedup, same_best) {
            writeln!(
                out,
                "quality evaluation: full / partial = {s:.1}×; same best grasp: {}",
                if same { "yes" } else { "no" }
            )?;
        }
    }
    out.flush()?;
    Ok(())
}

/// Whether two descents from the same starts found the same best value (within 1e−9 relative:
/// the methods agree to 1e−12, so the runs part only at an exact tie rounding broke apart).
fn same(a: &DescentReport, b: &DescentReport) -> bool {
    match (a.best(), b.best()) {
        (Some(x), Some(y)) => (x.value - y.value).abs() <= 1e-9 * y.value.abs().max(1e-3),
        (None, None) => true,
        _ => false,
    }
}
