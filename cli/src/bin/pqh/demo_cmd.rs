//! `pqh demo`: what pqhull is for — plan grasps on an object with partial hulls, compare with full
//! hulls, and write the views.

use crate::error::CliError;
use crate::progress;
use clap::Args;
use pqhull::grasp::FrictionModel;
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::quality::{Method, Metric};
use pqhull::plan::{BestComparison, PlanConfig, PlanReport};
use pqhull::viz::plan_scene::{MetricBest, metrics_note};
use serde_json::json;
use std::path::PathBuf;

/// The long help of `pqh demo`.
pub const LONG_ABOUT: &str = "\
Shows what pqhull is for, with no input: a random grasp planner (as GraspIt!'s) on an object (the
built-in spot.obj unless --mesh) picks the best of --samples 4-contact grasps by Q1 and by the
object wrench space metric, evaluated with partial hulls and again, on the first --full-samples,
with full hulls. It prints the best grasps and the time each method spent in quality evaluation,
says how the Q1-best and the OWS-best grasps differ (each one's value under the other metric),
writes an HTML view of the two side by side (--output), and exits with status 1 if the two
methods disagree on the best grasp. The default seed, 6, is one whose two bests differ.

Details: README.md, \"Getting started\"; limits: docs/limits.md.";

/// Arguments of `pqh demo`.
#[derive(Debug, Args)]
pub struct DemoArgs {
    /// Object mesh, OBJ or STL (default: the built-in spot.obj)
    #[arg(long)]
    mesh: Option<PathBuf>,
    /// Grasps sampled per metric
    #[arg(long, default_value_t = 300)]
    samples: usize,
    /// Samples for the (slow) full-hull runs: the first ones of the same sequence
    #[arg(long, default_value_t = 60)]
    full_samples: usize,
    /// Seed of the contact sampling
    #[arg(long, default_value_t = 6)]
    seed: u64,
    /// Where to write the HTML view
    #[arg(long, default_value = "pqh-demo.html")]
    output: PathBuf,
    /// One JSON document instead of the tables
    #[arg(long)]
    json: bool,
}

struct MetricRun {
    name: &'static str,
    partial: PlanReport,
    partial_short: PlanReport,
    full: PlanReport,
}

impl MetricRun {
    /// Full over partial quality time, when there was a best grasp to compare.
    fn speedup(&self) -> Option<f64> {
        self.full.quality_speedup_over(&self.partial_short)
    }

    fn comparison(&self) -> BestComparison {
        self.full.compare_best(&self.partial_short)
    }
}

pub fn run(args: &DemoArgs) -> Result<(), CliError> {
    if args.samples == 0 {
        return Err(CliError::Usage("--samples must be at least 1".into()));
    }
    let friction = FrictionModel::try_new(0.5, 8).map_err(|e| CliError::Usage(e.to_string()))?;
    let (mesh, name) = crate::input::object(args.mesh.as_deref())?;
    let space = ObjectWrenchSpace::from_mesh(&mesh, friction)
        .map_err(|e| CliError::Input(format!("{name}: {e}")))?;
    let full_samples = args.full_samples.clamp(1, args.samples);
    let mut runs = Vec::new();
    for (metric, label) in [(Metric::Q1, "Q1"), (Metric::Ows, "OWS")] {
        let config = PlanConfig {
            contacts: 4,
            samples: args.samples,
            friction,
            metric,
            seed: args.seed,
        };
        let short = PlanConfig {
            samples: full_samples,
            ..config
        };
        let s = Some(&space);
        runs.push(MetricRun {
            name: label,
            partial: progress::plan(&mesh, s, &config, Method::Partial, label)?,
            partial_short: progress::plan(&mesh, s, &short, Method::Partial, label)?,
            full: progress::plan(&mesh, s, &short, Method::Full, "full hull")?,
        });
    }
    let q1_config = PlanConfig {
        contacts: 4,
        samples: args.samples,
        friction,
        metric: Metric::Q1,
        seed: args.seed,
    };
    let bests = [&runs[0], &runs[1]].map(|r| MetricBest::new(r.partial.best.clone(), &space));
    let note = metrics_note(&bests);
    let view = crate::plan_view::write(&args.output, &mesh, &name, &q1_config, &bests);
    if args.json {
        let document = json!({
            "mesh": name,
            "disturbances": space.len(),
            "samples": args.samples,
            "full_samples": full_samples,
            "seed": args.seed,
            "metrics": runs.iter().map(|r| json!({
                "metric": r.name,
                "partial": r.partial.to_json(),
                "full": r.full.to_json(),
                "quality_speedup": r.speedup(),
                "comparison": r.comparison().name(),
                "same_best": r.comparison().same(),
            })).collect::<Vec<_>>(),
            "bests_differ": bests_differ(&bests),
            "note": note,
            "output": view.as_ref().ok().map(|p| p.display().to_string()),
        });
        println!("{document}");
    } else {
        println!(
            "pqh demo: random grasp planning on {name} ({} vertices; object wrench space of {} \
             disturbances), {} samples of 4 contacts, μ = 0.5, 8 cone edges\n",
            mesh.vertices().len(),
            space.len(),
            args.samples
        );
        for r in &runs {
            match &r.partial.best {
                Some(best) => {
                    println!(
                        "best by {:<3}: {:.6} (sample #{}, {} of {} samples force closure)",
                        r.name, best.value, best.sample, r.partial.force_closure, r.partial.samples
                    );
                    for c in best.grasp.contacts() {
                        let (p, n) = (c.position(), c.normal());
                        println!(
                            "    contact at ({:>8.4}, {:>8.4}, {:>8.4})  pushing ({:>6.3}, {:>6.3}, {:>6.3})",
                            p[0], p[1], p[2], n[0], n[1], n[2]
                        );
                    }
                }
                None => println!("best by {}: no force-closure grasp sampled", r.name),
            }
        }
        println!("\n{note}");
        println!(
            "\nquality evaluation on the first {full_samples} samples (same grasps, same answers):"
        );
        println!(
            "{:<6} {:>14} {:>14} {:>10} {:>16} {:>16} {:>11}",
            "metric",
            "partial ms",
            "full ms",
            "speed-up",
            "facets partial",
            "facets full",
            "same best"
        );
        for r in &runs {
            println!(
                "{:<6} {:>14.1} {:>14.1} {:>10} {:>16} {:>16} {:>11}",
                r.name,
                r.partial_short.quality_time.as_secs_f64() * 1e3,
                r.full.quality_time.as_secs_f64() * 1e3,
                r.speedup().map_or("-".to_string(), |s| format!("{s:.1}×")),
                r.partial_short.facets_created,
                r.full.facets_created,
                match r.comparison() {
                    BestComparison::Same => "yes",
                    BestComparison::Different => "NO",
                    BestComparison::NothingToCompare => "no fc grasp",
                }
            );
        }
        if let Ok(path) = &view {
            println!("\nwrote {} (Q1-best beside OWS-best)", path.display());
        }
    }
    if runs
        .iter()
        .any(|r| r.comparison() == BestComparison::Different)
    {
        return Err(CliError::Geometry(
            "demo: the partial and full-hull plans chose different best grasps (bug: please \
             report it)"
                .into(),
        ));
    }
    // The view was asked for (--output has a default): not writing it is an error (exit 2).
    view?;
    Ok(())
}

/// Whether the Q1-best and the OWS-best are different samples (`None` when either is missing).
fn bests_differ(bests: &[MetricBest; 2]) -> Option<bool> {
    match (&bests[0].best, &bests[1].best) {
        (Some(a), Some(b)) => Some(a.sample != b.sample),
        _ => None,
    }
}
