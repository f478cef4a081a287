//! `pqh plan`: a GraspIt!-like random planner, partial vs full-hull quality evaluation.

use crate::error::CliError;
use crate::limits::PLAN_FULL_QINF_POINTS;
use crate::methods::MetricArg;
use crate::progress;
use clap::Args;
use pqhull::grasp::FrictionModel;
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::quality::Method;
use pqhull::plan::{BestComparison, PlanConfig};
use pqhull::viz::plan_scene::metric_bests;
use serde_json::json;
use std::io::Write;
use std::path::PathBuf;

pub const LONG_ABOUT: &str = "\
Plans grasps on a mesh the way GraspIt!'s random planner does: samples --samples grasps of
--contacts contacts on the surface (by area, inward face normals, in the object's torque frame),
keeps the best force-closure grasp by --metric, and runs again on the same samples with full
hulls (brute force for ows and resist). It reports the time each run spent in quality evaluation
(the quantity of the seed paper's Table 1) and whether both chose the same best grasp; --output
writes an HTML view of the Q1-best grasp beside the OWS-best one.

--planner descent climbs the metric instead (q1, qinf, qinf0 or ows): from --starts random
starts, contacts move over the surface along the exact gradient, at most --evaluations metric
evaluations per planned grasp; the same starts are climbed again with full hulls.

Details (the comparison, its JSON, Q-infinity's full run): README.md, \"Planning grasps\";
limits: docs/limits.md.";

/// Which planner `pqh plan` runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PlannerArg {
    /// Random samples, the best kept (GraspIt!'s random planner; --samples)
    Sampler,
    /// Climbs the metric's exact gradient over the surface from --starts random starts, at most
    /// --evaluations metric evaluations each (q1, qinf, qinf0, ows)
    Descent,
}

#[derive(Debug, Args)]
pub struct PlanArgs {
    /// The planner
    #[arg(long, value_enum, default_value_t = PlannerArg::Sampler)]
    pub planner: PlannerArg,
    /// descent: planned grasps, each climbed from one random start, 1 to 100000
    #[arg(long, default_value_t = 10, value_parser = crate::limits::count(1, pqhull::plan::MAX_STARTS))]
    pub starts: usize,
    /// descent: metric evaluations per planned grasp, its start's included, 2 to 10000
    #[arg(long, default_value_t = 50, value_parser = crate::limits::count(2, pqhull::plan::MAX_EVALUATIONS))]
    pub evaluations: usize,
    /// descent: candidates screened per planned grasp, the best one climbed (each costs an
    /// evaluation out of --evaluations; worth 10 to 30 for ows), 1 to 10000
    #[arg(long, default_value_t = 1, value_parser = crate::limits::count(1, pqhull::plan::MAX_SCREEN))]
    pub screen: usize,
    /// Object mesh, OBJ or STL (default: the built-in spot.obj, whatever the working directory)
    #[arg(long)]
    pub mesh: Option<PathBuf>,
    /// Contacts per grasp, 1 to 256
    #[arg(long, default_value_t = 4, value_parser = crate::limits::contacts())]
    pub contacts: usize,
    /// Grasps sampled, 1 to 1000000
    #[arg(long, default_value_t = 200, value_parser = crate::limits::samples())]
    pub samples: usize,
    /// Samples for the full-hull run, the first ones, 0 (skip it) to 1000000 (default: --samples;
    /// for qinf 2, or 0 above 1000 Minkowski points per grasp, all hulled exactly: docs/limits.md)
    #[arg(long, value_parser = crate::limits::count(0, crate::limits::MAX_SAMPLES))]
    pub full_samples: Option<usize>,
    /// Metric to maximise among the force-closure samples
    #[arg(long, value_enum, default_value_t = MetricArg::Q1)]
    pub metric: MetricArg,
    /// resist: the wrench to resist, fx,fy,fz,tx,ty,tz, in the object's torque frame (about its
    /// centre of mass, torques divided by its characteristic length): 0,0,-1,0,0,0 is gravity
    #[arg(long, allow_hyphen_values = true)]
    pub wrench: Option<String>,
    /// Friction coefficient (contacts and, for ows, disturbances)
    #[arg(long, default_value_t = 0.5)]
    pub friction: f64,
    /// Friction cone edges, 3 to 1024
    #[arg(long, default_value_t = 8, value_parser = crate::limits::cone_edges())]
    pub edges: usize,
    /// Seed of the contact sampling
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Write an HTML view of the Q1-best and OWS-best grasps
    #[arg(long)]
    pub output: Option<PathBuf>,
    /// One JSON document instead of the table
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: &PlanArgs) -> Result<(), CliError> {
    let friction = FrictionModel::try_new(args.friction, args.edges)
        .map_err(|e| CliError::Usage(format!("--friction/--edges: {e}")))?;
    if args.contacts == 0 || args.samples == 0 {
        return Err(CliError::Usage(
            "--contacts and --samples must be at least 1".into(),
        ));
    }
    let metric = args.metric.metric(false, args.wrench.as_deref())?;
    let (mesh, name) = crate::input::object(args.mesh.as_deref())?;
    if args.planner == PlannerArg::Descent {
        return crate::plan_descent_cmd::run(args, &mesh, &name, friction, metric);
    }
    let needs_space = matches!(args.metric, MetricArg::Ows) || args.output.is_some();
    let space = if needs_space {
        Some(
            ObjectWrenchSpace::from_mesh(&mesh, friction)
                .map_err(|e| CliError::Input(format!("{name}: {e}")))?,
        )
    } else {
        None
    };
    let config = PlanConfig {
        contacts: args.contacts,
        samples: args.samples,
        friction,
        metric,
        seed: args.seed,
    };
    let partial = progress::plan(&mesh, space.as_ref(), &config, Method::Partial, "partial")?;
    // Q∞ by the full method hulls all k^m Minkowski points of each sample, exactly and slowly
    // (they are highly degenerate): above PLAN_FULL_QINF_POINTS (4 × 8, about 0.8 s a sample,
    // is above it) the comparison runs only when asked for.
    let minkowski = args.edges.checked_pow(args.contacts as u32);
    let default_full = match args.metric {
        MetricArg::Qinf if minkowski.is_none_or(|n| n > PLAN_FULL_QINF_POINTS) => {
            if args.full_samples.is_none() {
                eprintln!(
                    "pqh: note: no full-hull comparison: Q∞ by the full method hulls {} Minkowski \
                     points per sample (0.15 s at 1,296 points, 1 s at 4,096, 35 s at 65,536); \
                     --full-samples N runs it on N samples",
                    minkowski.map_or("more than 2^64".to_string(), |n| n.to_string())
                );
            }
            0
        }
        MetricArg::Qinf => 2,
        _ => args.samples,
    };
    let full_samples = args.full_samples.unwrap_or(default_full).min(args.samples);
    let comparison = if full_samples > 0 {
        let short = PlanConfig {
            samples: full_samples,
            ..config
        };
        let full = progress::plan(&mesh, space.as_ref(), &short, Method::Full, "full hull")?;
        // The partial plan over the same first samples, to compare the best grasps.
        let partial_short = if full_samples == args.samples {
            partial.clone()
        } else {
            progress::plan(&mesh, space.as_ref(), &short, Method::Partial, "partial")?
        };
        Some((full, partial_short))
    } else {
        None
    };
    let views = match (&args.output, &space) {
        (Some(path), Some(space)) => {
            let bests = metric_bests(&mesh, space, &config, &partial)
                .map_err(|e| CliError::Geometry(e.to_string()))?;
            Some(crate::plan_view::write(
                path, &mesh, &name, &config, &bests,
            )?)
        }
        _ => None,
    };

    // What the full-hull run is compared on: the same first samples by both methods.
    let compared = comparison
        .as_ref()
        .map(|(full, partial_short)| (full, partial_short, full.compare_best(partial_short)));
    let same_best = compared.and_then(|(_, _, c)| c.same());
    let speedup = compared.and_then(|(full, short, _)| full.quality_speedup_over(short));
    let note = compared.and_then(|(full, _, c)| {
        (c == BestComparison::NothingToCompare).then(|| {
            format!(
                "nothing to compare: neither method found a force-closure grasp among the first \
                 {} samples both ran (raise --full-samples)",
                full.samples
            )
        })
    });
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    if args.json {
        let document = json!({
            "mesh": name,
            "metric": metric.name(),
            "contacts": args.contacts,
            "edges": args.edges,
            "friction": args.friction,
            "seed": args.seed,
            "partial": partial.to_json(),
            "full": comparison.as_ref().map(|(full, _)| full.to_json()),
            "comparison": compared.map(|(_, _, c)| c.name()),
            "same_best": same_best,
            "quality_speedup": speedup,
            "comparison_note": note,
            "output": views.as_ref().map(|p| p.display().to_string()),
        });
        writeln!(out, "{document}")?;
    } else {
        writeln!(
            out,
            "plan on {name}: {} samples × {} contacts, μ = {}, {} cone edges, metric {}",
            args.samples,
            args.contacts,
            args.friction,
            args.edges,
            metric.name()
        )?;
        writeln!(
            out,
            "{:<10} {:>8} {:>8} {:>12} {:>12} {:>12}",
            "method", "samples", "closure", "quality s", "other s", "best"
        )?;
        let mut rows = vec![("partial", &partial)];
        if let Some((full, _)) = &comparison {
            rows.push(("full", full));
        }
        for (method, r) in rows {
            writeln!(
                out,
                "{:<10} {:>8} {:>8} {:>12.4} {:>12.4} {:>12}",
                method,
                r.samples,
                r.force_closure,
                r.quality_time.as_secs_f64(),
                r.other_time.as_secs_f64(),
                r.best.as_ref().map_or("none".to_string(), |b| format!(
                    "{:.6} (#{})",
                    b.value, b.sample
                ))
            )?;
        }
        if let (Some(s), Some(same)) = (speedup, same_best) {
            writeln!(
                out,
                "quality evaluation per sample: full / partial = {s:.1}×; same best grasp: {}",
                if same { "yes" } else { "NO" }
            )?;
        }
        if let Some(note) = &note {
            writeln!(out, "full vs partial: {note}")?;
        }
        if let Some(path) = &views {
            writeln!(out, "wrote {}", path.display())?;
        }
    }
    out.flush()?;
    drop(out);
    if same_best == Some(false) {
        return Err(CliError::Geometry(
            "the partial and full-hull plans chose different best grasps".into(),
        ));
    }
    Ok(())
}
