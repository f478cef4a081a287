//! `pqh bench ows`: the seed paper's OWS evaluation (its Fig. 8 and 9), every method side by side.

use crate::bench_cmd::{mean, median};
use crate::error::CliError;
use crate::grasp_cmd::describe_space;
use crate::plan_cmd::load_object;
use clap::Args;
use pqhull::geometry::Rng;
use pqhull::grasp::ows::{ObjectWrenchSpace, OwsEvaluator, OwsQuality, relative_error};
use pqhull::grasp::quality::{Evaluator, Method, Metric};
use pqhull::grasp::{FrictionModel, Grasp};
use pqhull::mesh::SurfaceSampler;
use serde_json::{Value, json};
use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Debug, Args)]
pub struct OwsArgs {
    /// Object mesh (OBJ or STL) [default: the built-in spot.obj]
    #[arg(long)]
    pub mesh: Option<PathBuf>,
    /// Random grasps (contacts sampled on the surface by area), 1 to 100000
    #[arg(long, default_value_t = 200, value_parser = crate::limits::bench_grasps())]
    pub grasps: usize,
    /// At most this many of them for the brute-force method (it is slow), 0 to 100000
    #[arg(long, default_value_t = 20, value_parser = crate::limits::bench_subset())]
    pub brute_grasps: usize,
    /// At most this many for Algorithm 2 as published (`partial-rays`: every disturbance
    /// assigned to a facet; tens of ms per grasp on a mesh), 0 to 100000
    #[arg(long, default_value_t = 20, value_parser = crate::limits::bench_subset())]
    pub rays_grasps: usize,
    /// Contacts per grasp, 1 to 256
    #[arg(long, default_value_t = 4, value_parser = crate::limits::contacts())]
    pub contacts: usize,
    /// Cone edges, for the grasps and the disturbances alike, 3 to 1024 (the object wrench space
    /// of a mesh holds 3·(k + 1) disturbances per triangle)
    #[arg(long, default_value_t = 16, value_parser = crate::limits::cone_edges())]
    pub edges: usize,
    /// Friction coefficient, for the grasps and the disturbances alike
    #[arg(long, default_value_t = 0.5)]
    pub friction: f64,
    /// Keep only the convex-hull vertices of the disturbances first (slow for smooth meshes)
    #[arg(long)]
    pub reduce: bool,
    /// Seed of the random grasps
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// One JSON document instead of the table
    #[arg(long)]
    pub json: bool,
}

fn quantiles(values: &mut [f64]) -> Value {
    values.sort_by(f64::total_cmp);
    let at = |q: f64| {
        values
            .get(((values.len() as f64 - 1.0) * q).round() as usize)
            .copied()
    };
    json!({
        "min": at(0.0), "q25": at(0.25), "median": at(0.5), "q75": at(0.75), "max": at(1.0),
        "count": values.len(),
    })
}

fn micros(q: &OwsQuality) -> f64 {
    q.stats.elapsed.as_secs_f64() * 1e6
}

fn summary(name: &str, times: &mut [f64]) -> Value {
    json!({
        "method": name,
        "grasps": times.len(),
        "mean_us": mean(times.iter().copied()),
        "median_us": median(times),
    })
}

pub fn run(args: &OwsArgs) -> Result<(), CliError> {
    if args.grasps == 0 || args.contacts == 0 {
        return Err(CliError::Usage(
            "--grasps and --contacts must be at least 1".into(),
        ));
    }
    let friction = FrictionModel::try_new(args.friction, args.edges)
        .map_err(|e| CliError::Usage(format!("--friction/--edges: {e}")))?;
    let (mesh, mesh_name) = load_object(args.mesh.as_deref())?;
    let started = Instant::now();
    let mut space = ObjectWrenchSpace::from_mesh(&mesh, friction)
        .map_err(|e| CliError::Input(format!("{mesh_name}: {e}")))?;
    if args.reduce {
        space
            .reduce_to_hull_vertices()
            .map_err(|e| CliError::Geometry(e.to_string()))?;
    }
    let prepare_ms = started.elapsed().as_secs_f64() * 1e3;
    // The ellipsoid is per object too: compute it before timing the grasps.
    let started = Instant::now();
    let ellipsoid_ready = space.ellipsoid().is_ok();
    let ellipsoid_ms = started.elapsed().as_secs_f64() * 1e3;

    let mut rng = Rng::new(args.seed);
    let sampler = SurfaceSampler::new(&mesh);
    let grasps: Vec<Grasp> = (0..args.grasps)
        .map(|_| {
            let grasp = Grasp::random_on_surface(&mut rng, &sampler, args.contacts, friction)?;
            space.frame(&grasp)
        })
        .collect::<Result<_, _>>()
        .map_err(|e| CliError::Geometry(e.to_string()))?;

    let evaluate = |method: Method, set: &[Grasp]| -> Result<Vec<OwsQuality>, CliError> {
        let mut evaluator = OwsEvaluator::new(method);
        let bar = crate::progress::bar(set.len(), &format!("{method:?}"));
        let results = set
            .iter()
            .map(|g| {
                let q = evaluator.evaluate(g, &space);
                bar.inc(1);
                q
            })
            .collect::<Result<_, _>>()
            .map_err(|e| CliError::Geometry(e.to_string()));
        bar.finish_and_clear();
        results
    };
    // Partial first, so the others cannot warm caches for it.
    let partial = evaluate(Method::Partial, &grasps)?;
    let mut q1 = Evaluator::new(Metric::Q1, Method::Partial);
    let mut q1_times = grasps
        .iter()
        .map(|g| q1.evaluate(g).map(|q| q.stats.elapsed.as_secs_f64() * 1e6))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| CliError::Geometry(e.to_string()))?;
    let brute_set = &grasps[..args.brute_grasps.min(grasps.len())];
    let brute = evaluate(Method::Full, brute_set)?;
    let rays = evaluate(
        Method::PartialRays,
        &grasps[..args.rays_grasps.min(grasps.len())],
    )?;
    let ellipsoid = evaluate(Method::Ellipsoid, &grasps)?;

    let disagree = |other: &[OwsQuality]| {
        partial
            .iter()
            .zip(other)
            .filter(|(p, b)| match (p.value, b.value) {
                (Some(x), Some(y)) => (x - y).abs() > 1e-9 * y.max(1e-4),
                (x, y) => x.is_some() != y.is_some(),
            })
            .count()
    };
    let disagreements = disagree(&brute);
    let rays_disagreements = disagree(&rays);
    let force_closure = partial.iter().filter(|q| q.force_closure).count();
    let mut errors: Vec<f64> = partial
        .iter()
        .zip(&ellipsoid)
        .filter_map(|(p, e)| Some(relative_error(e.value?, p.value?)))
        .collect();

    let closure_times = |results: &[OwsQuality]| -> Vec<f64> {
        results
            .iter()
            .zip(&partial)
            .filter(|(_, p)| p.force_closure)
            .map(|(q, _)| micros(q))
            .collect()
    };
    let mut partial_closure = closure_times(&partial);
    let mut q1_closure: Vec<f64> = q1_times
        .iter()
        .zip(&partial)
        .filter(|(_, p)| p.force_closure)
        .map(|(&t, _)| t)
        .collect();
    let mut brute_closure = closure_times(&brute);
    let mut partial_closure_on_brute = closure_times(&partial[..brute.len()]);
    let mut partial_times: Vec<f64> = partial.iter().map(micros).collect();
    let mut partial_on_brute: Vec<f64> = partial_times[..brute.len()].to_vec();
    let mut brute_times: Vec<f64> = brute.iter().map(micros).collect();
    let mut ellipsoid_times: Vec<f64> = ellipsoid.iter().map(micros).collect();
    let mut rays_times: Vec<f64> = rays.iter().map(micros).collect();
    let mut partial_on_rays: Vec<f64> = partial_times[..rays.len()].to_vec();
    let mut rays_closure = closure_times(&rays);
    let mut partial_closure_on_rays = closure_times(&partial[..rays.len()]);
    let rows = vec![
        summary("partial", &mut partial_times),
        summary("brute", &mut brute_times),
        summary("ellipsoid", &mut ellipsoid_times),
        summary("q1-partial", &mut q1_times),
        summary("partial-fc", &mut partial_closure),
        summary("brute-fc", &mut brute_closure),
        summary("partial-rays", &mut rays_times),
        summary("partial-rays-fc", &mut rays_closure),
        summary("q1-partial-fc", &mut q1_closure),
    ];
    let median_of = |v: &Value| v["median_us"].as_f64().unwrap_or(f64::NAN);
    let partial_brute_median = summary("", &mut partial_on_brute);
    let partial_rays_median = summary("", &mut partial_on_rays);
    let partial_rays_closure = summary("", &mut partial_closure_on_rays);
    let partial_brute_closure = summary("", &mut partial_closure_on_brute);
    let report = json!({
        "mesh": mesh_name,
        "vertices": mesh.vertices().len(),
        "disturbances": space.len(),
        "space": describe_space(&space),
        "prepare_ms": prepare_ms,
        "ellipsoid_ms": ellipsoid_ready.then_some(ellipsoid_ms),
        "contacts": args.contacts,
        "edges": args.edges,
        "friction": args.friction,
        "seed": args.seed,
        "force_closure": force_closure,
        "disagreements": disagreements,
        "compared_with_brute": brute.len(),
        "rays_disagreements": rays_disagreements,
        "compared_with_rays": rays.len(),
        "methods": rows,
        "ratios": {
            "brute_over_partial": median_of(&rows[1]) / median_of(&partial_brute_median),
            "brute_over_partial_force_closure":
                median_of(&rows[5]) / median_of(&partial_brute_closure),
            "partial_over_q1": median_of(&rows[0]) / median_of(&rows[3]),
            "partial_over_q1_force_closure": median_of(&rows[4]) / median_of(&rows[8]),
            "rays_over_partial": median_of(&rows[6]) / median_of(&partial_rays_median),
            "rays_over_partial_force_closure":
                median_of(&rows[7]) / median_of(&partial_rays_closure),
        },
        "ellipsoid_relative_error": quantiles(&mut errors),
    });
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    if args.json {
        writeln!(out, "{report}")?;
        out.flush()?;
        return Ok(());
    }
    writeln!(
        out,
        "OWS on {mesh_name}: {} vertices, {} disturbances (prepared in {prepare_ms:.0} ms); {} \
         grasps, {} contacts × {} edges, μ = {}",
        report["vertices"],
        report["disturbances"],
        args.grasps,
        args.contacts,
        args.edges,
        args.friction
    )?;
    writeln!(
        out,
        "force closure: {force_closure}; partial vs brute force: {disagreements} disagreements \
         of {}; vs partial-rays: {rays_disagreements} of {}",
        brute.len(),
        rays.len()
    )?;
    writeln!(
        out,
        "(the ellipsoid of the disturbances took {ellipsoid_ms:.1} ms, once per object; \
         '-fc' rows: force-closure grasps only)"
    )?;
    writeln!(
        out,
        "{:<16} {:>7} {:>12} {:>12}",
        "method", "grasps", "median µs", "mean µs"
    )?;
    for row in &rows {
        writeln!(
            out,
            "{:<16} {:>7} {:>12.1} {:>12.1}",
            row["method"].as_str().unwrap_or(""),
            row["grasps"].as_u64().unwrap_or(0),
            median_of(row),
            row["mean_us"].as_f64().unwrap_or(f64::NAN)
        )?;
    }
    let ratio = |key: &str| report["ratios"][key].as_f64().unwrap_or(f64::NAN);
    writeln!(
        out,
        "brute / partial (same grasps): {:.1}× (force closure only: {:.1}×)   partial OWS / \
         partial Q1: {:.2}× (force closure only: {:.2}×)",
        ratio("brute_over_partial"),
        ratio("brute_over_partial_force_closure"),
        ratio("partial_over_q1"),
        ratio("partial_over_q1_force_closure")
    )?;
    writeln!(
        out,
        "partial-rays (Algorithm 2 as published) / partial (same grasps): {:.1}× (force closure \
         only: {:.1}×)",
        ratio("rays_over_partial"),
        ratio("rays_over_partial_force_closure")
    )?;
    let e = &report["ellipsoid_relative_error"];
    let q = |key: &str| {
        e[key]
            .as_f64()
            .map_or("-".to_string(), |x| format!("{x:+.4}"))
    };
    writeln!(
        out,
        "ellipsoid relative error (approx − exact) / exact over {} force-closure grasps: min {} \
         q25 {} median {} q75 {} max {}",
        e["count"],
        q("min"),
        q("q25"),
        q("median"),
        q("q75"),
        q("max")
    )?;
    out.flush()?;
    Ok(())
}
