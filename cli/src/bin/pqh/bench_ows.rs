//! `pqh bench ows`: the seed paper's OWS evaluation (its Fig. 8 and 9), every method side by side.

use crate::error::CliError;
use clap::Args;
use pqhull::grasp::FrictionModel;
use pqhull_cli::bench::ows::{self, OwsBenchError, OwsConfig, OwsReport};
use std::io::Write;
use std::path::PathBuf;

#[derive(Debug, Args)]
pub struct OwsArgs {
    /// Object mesh, OBJ or STL (default: the built-in spot.obj)
    #[arg(long)]
    pub mesh: Option<PathBuf>,
    /// Random grasps (contacts sampled on the surface by area), 1 to 100000
    #[arg(long, default_value_t = 200, value_parser = crate::limits::bench_grasps())]
    pub grasps: usize,
    /// At most this many of them for the brute-force method (it is slow), 0 to 100000
    #[arg(long, default_value_t = 20, value_parser = crate::limits::bench_subset())]
    pub brute_grasps: usize,
    /// At most this many for Algorithm 2 as published (`partial-rays`: every disturbance
    /// assigned to a facet, far slower than partial on a mesh's many disturbances), 0 to 100000
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

pub fn run(args: &OwsArgs) -> Result<(), CliError> {
    if args.grasps == 0 || args.contacts == 0 {
        return Err(CliError::Usage(
            "--grasps and --contacts must be at least 1".into(),
        ));
    }
    let friction = FrictionModel::try_new(args.friction, args.edges)
        .map_err(|e| CliError::Usage(format!("--friction/--edges: {e}")))?;
    let (mesh, mesh_name) = crate::input::object(args.mesh.as_deref())?;
    let config = OwsConfig {
        grasps: args.grasps,
        brute_grasps: args.brute_grasps,
        rays_grasps: args.rays_grasps,
        contacts: args.contacts,
        friction,
        reduce: args.reduce,
        seed: args.seed,
    };
    let mut bars = crate::progress::Phases::default();
    let report = ows::run(&mesh, &mesh_name, &config, &mut |label, done, total| {
        bars.update(label, done, total)
    })
    .map_err(|e| match e {
        OwsBenchError::Space(e) => CliError::Input(format!("{mesh_name}: {e}")),
        e => CliError::Geometry(e.to_string()),
    })?;
    drop(bars);
    crate::format::write_report(
        args.json,
        || report.to_json(),
        |out| print_table(out, &report),
    )?;
    Ok(())
}

/// The figures as the table prints them: what JSON cannot hold (NaN, infinities) reads as NaN,
/// as in the JSON document.
fn num(x: f64) -> f64 {
    if x.is_finite() { x } else { f64::NAN }
}

fn print_table(out: &mut impl Write, report: &OwsReport) -> std::io::Result<()> {
    writeln!(
        out,
        "OWS on {}: {} vertices, {} disturbances (prepared in {:.0} ms); {} \
         grasps, {} contacts × {} edges, μ = {}",
        report.mesh,
        report.vertices,
        report.disturbances,
        report.prepare_ms,
        report.grasps,
        report.contacts,
        report.edges,
        report.friction
    )?;
    writeln!(
        out,
        "force closure: {}; partial vs brute force: {} disagreements \
         of {}; vs partial-rays: {} of {}",
        report.force_closure,
        report.disagreements,
        report.compared_with_brute,
        report.rays_disagreements,
        report.compared_with_rays
    )?;
    writeln!(
        out,
        "(the ellipsoid of the disturbances took {:.1} ms, once per object; \
         '-fc' rows: force-closure grasps only)",
        report.ellipsoid_ms
    )?;
    writeln!(
        out,
        "{:<16} {:>7} {:>12} {:>12}",
        "method", "grasps", "median µs", "mean µs"
    )?;
    for row in &report.methods {
        writeln!(
            out,
            "{:<16} {:>7} {:>12.1} {:>12.1}",
            row.method,
            row.grasps,
            num(row.median_us),
            num(row.mean_us)
        )?;
    }
    let r = &report.ratios;
    writeln!(
        out,
        "brute / partial (same grasps): {:.1}× (force closure only: {:.1}×)   partial OWS / \
         partial Q1: {:.2}× (force closure only: {:.2}×)",
        num(r.brute_over_partial),
        num(r.brute_over_partial_force_closure),
        num(r.partial_over_q1),
        num(r.partial_over_q1_force_closure)
    )?;
    writeln!(
        out,
        "partial-rays (Algorithm 2 as published) / partial (same grasps): {:.1}× (force closure \
         only: {:.1}×)",
        num(r.rays_over_partial),
        num(r.rays_over_partial_force_closure)
    )?;
    let e = &report.ellipsoid_relative_error;
    let q = |x: Option<f64>| {
        x.filter(|x| x.is_finite())
            .map_or("-".to_string(), |x| format!("{x:+.4}"))
    };
    writeln!(
        out,
        "ellipsoid relative error (approx − exact) / exact over {} force-closure grasps: min {} \
         q25 {} median {} q75 {} max {}",
        e.count,
        q(e.min),
        q(e.q25),
        q(e.median),
        q(e.q75),
        q(e.max)
    )
}
