//! The seed paper's OWS evaluation (its Fig. 8 and 9): Q_OWS of random surface grasps of a mesh
//! by the partial hull, the brute force, Algorithm 2 as published and the ellipsoid
//! approximation, against Q1 by the partial hull (what `pqh bench ows` runs).

use super::Progress;
use super::stats::{Quantiles, mean, median, micros};
use super::workloads::surface_grasps;
use pqhull::grasp::ows::relative_error;
use pqhull::grasp::ows::{ObjectWrenchSpace, OwsError};
use pqhull::grasp::{
    Evaluation, Evaluator, FrictionModel, Grasp, GraspError, Method, Metric, QualityError,
};
use pqhull::hull::HullError;
use pqhull::mesh::Mesh;
use serde_json::{Value, json};
use std::fmt;
use std::time::Instant;

/// What to measure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OwsConfig {
    /// Random grasps (contacts sampled on the surface by area).
    pub grasps: usize,
    /// At most this many of them for the brute force (it is slow).
    pub brute_grasps: usize,
    /// At most this many for Algorithm 2 as published (`partial-rays`).
    pub rays_grasps: usize,
    /// Contacts per grasp.
    pub contacts: usize,
    /// Friction of the grasps and of the disturbance cones alike.
    pub friction: FrictionModel,
    /// Keep only the convex-hull vertices of the disturbances first.
    pub reduce: bool,
    /// Seed of the random grasps.
    pub seed: u64,
}

/// Median and mean time of one method over its grasps.
#[derive(Clone, Debug, PartialEq)]
pub struct TimeRow {
    /// The row's name: a method, `-fc` for its force-closure grasps only.
    pub method: &'static str,
    /// Grasps timed.
    pub grasps: usize,
    /// Mean time per grasp, µs.
    pub mean_us: f64,
    /// Median time per grasp, µs (NaN when none).
    pub median_us: f64,
}

impl TimeRow {
    /// The row of `times` (sorted in place).
    fn new(method: &'static str, times: &mut [f64]) -> TimeRow {
        TimeRow {
            method,
            grasps: times.len(),
            mean_us: mean(times.iter().copied()),
            median_us: median(times),
        }
    }
}

/// Median-time ratios, each on the same grasps (the second method's subset).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OwsRatios {
    /// Brute force over partial.
    pub brute_over_partial: f64,
    /// The same, force-closure grasps only.
    pub brute_over_partial_force_closure: f64,
    /// Partial Q_OWS over partial Q1.
    pub partial_over_q1: f64,
    /// The same, force-closure grasps only.
    pub partial_over_q1_force_closure: f64,
    /// Algorithm 2 as published over partial.
    pub rays_over_partial: f64,
    /// The same, force-closure grasps only.
    pub rays_over_partial_force_closure: f64,
}

/// The whole OWS benchmark.
#[derive(Clone, Debug, PartialEq)]
pub struct OwsReport {
    /// The mesh's name.
    pub mesh: String,
    /// Its vertices.
    pub vertices: usize,
    /// Disturbances in the object wrench space.
    pub disturbances: usize,
    /// [`ObjectWrenchSpace::describe`].
    pub space: String,
    /// Building (and reducing) the space, ms.
    pub prepare_ms: f64,
    /// Computing the disturbances' ellipsoid (once per object), ms, whether or not it succeeded.
    pub ellipsoid_ms: f64,
    /// Whether the ellipsoid could be computed (the ellipsoid method needs it).
    pub ellipsoid_ready: bool,
    /// Grasps.
    pub grasps: usize,
    /// Contacts per grasp.
    pub contacts: usize,
    /// Cone edges.
    pub edges: usize,
    /// Friction coefficient.
    pub friction: f64,
    /// Seed of the grasps.
    pub seed: u64,
    /// Force-closure grasps (by the partial method).
    pub force_closure: usize,
    /// Grasps where brute force and partial differ.
    pub disagreements: usize,
    /// Grasps compared with brute force.
    pub compared_with_brute: usize,
    /// Grasps where Algorithm 2 as published and partial differ.
    pub rays_disagreements: usize,
    /// Grasps compared with it.
    pub compared_with_rays: usize,
    /// `partial`, `brute`, `ellipsoid`, `q1-partial`, `partial-fc`, `brute-fc`,
    /// `partial-rays`, `partial-rays-fc`, `q1-partial-fc`, in this order.
    pub methods: Vec<TimeRow>,
    /// The speed ratios.
    pub ratios: OwsRatios,
    /// (ellipsoid − exact) / exact over the force-closure grasps.
    pub ellipsoid_relative_error: Quantiles,
}

/// Why the OWS benchmark could not run.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum OwsBenchError {
    /// The mesh gives no object wrench space.
    Space(OwsError),
    /// Reducing the disturbances to their hull's vertices failed.
    Reduce(HullError),
    /// A grasp could not be sampled.
    Grasp(GraspError),
    /// A method failed on a grasp.
    Quality(QualityError),
}

impl fmt::Display for OwsBenchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OwsBenchError::Space(e) => write!(f, "{e}"),
            OwsBenchError::Reduce(e) => write!(f, "{e}"),
            OwsBenchError::Grasp(e) => write!(f, "{e}"),
            OwsBenchError::Quality(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for OwsBenchError {}

/// `method` on every grasp of `set`; `progress` hears of it under the method's `Debug` name.
fn evaluate(
    method: Method,
    set: &[Grasp],
    space: &ObjectWrenchSpace,
    progress: Progress<'_>,
) -> Result<Vec<Evaluation>, OwsBenchError> {
    let mut evaluator =
        Evaluator::new(Metric::Ows, method, Some(space)).map_err(OwsBenchError::Quality)?;
    let label = method.name();
    progress(label, 0, set.len());
    let results = set
        .iter()
        .enumerate()
        .map(|(i, g)| {
            let q = evaluator.evaluate(g);
            progress(label, i + 1, set.len());
            q
        })
        .collect::<Result<_, _>>()
        .map_err(OwsBenchError::Quality);
    if results.is_err() {
        // The phase ended early: close it.
        progress(label, set.len(), set.len());
    }
    results
}

/// Runs the benchmark on `mesh` (named `name` in the report). The space and its ellipsoid are
/// prepared first and timed apart (once per object); the partial method runs first, so that the
/// others cannot warm caches for it. `progress` hears of each Q_OWS method's run.
///
/// ```
/// use pqhull_cli::bench::ows::{OwsConfig, run};
/// use pqhull::grasp::FrictionModel;
/// use pqhull::mesh::Mesh;
///
/// let object = Mesh::cuboid([0.3, 0.2, 0.1])?;
/// let config = OwsConfig {
///     grasps: 4, brute_grasps: 2, rays_grasps: 1, contacts: 4,
///     friction: FrictionModel::try_new(0.5, 4)?, reduce: false, seed: 1,
/// };
/// let report = run(&object, "a box", &config, &mut |_, _, _| {})?;
/// assert_eq!((report.disagreements, report.compared_with_brute), (0, 2));
/// assert_eq!(report.methods[0].method, "partial");
/// assert_eq!(report.to_json()["mesh"], "a box");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`OwsBenchError`] when the mesh gives no wrench space, a grasp cannot be sampled (e.g. no
/// contacts), or a method fails on a grasp.
pub fn run(
    mesh: &Mesh,
    name: &str,
    config: &OwsConfig,
    progress: Progress<'_>,
) -> Result<OwsReport, OwsBenchError> {
    let started = Instant::now();
    let mut space =
        ObjectWrenchSpace::from_mesh(mesh, config.friction).map_err(OwsBenchError::Space)?;
    if config.reduce {
        space
            .reduce_to_hull_vertices()
            .map_err(OwsBenchError::Reduce)?;
    }
    let prepare_ms = started.elapsed().as_secs_f64() * 1e3;
    let started = Instant::now();
    let ellipsoid_ready = space.ellipsoid().is_ok();
    let ellipsoid_ms = started.elapsed().as_secs_f64() * 1e3;

    let grasps = surface_grasps(
        mesh,
        &space,
        config.seed,
        config.grasps,
        config.contacts,
        config.friction,
    )
    .map_err(OwsBenchError::Grasp)?;

    let partial = evaluate(Method::Partial, &grasps, &space, &mut *progress)?;
    let mut q1 =
        Evaluator::new(Metric::Q1, Method::Partial, None).map_err(OwsBenchError::Quality)?;
    let mut q1_times = grasps
        .iter()
        .map(|g| q1.evaluate(g).map(|q| micros(q.stats.elapsed)))
        .collect::<Result<Vec<_>, _>>()
        .map_err(OwsBenchError::Quality)?;
    let brute_set = &grasps[..config.brute_grasps.min(grasps.len())];
    let brute = evaluate(Method::Full, brute_set, &space, &mut *progress)?;
    let rays_set = &grasps[..config.rays_grasps.min(grasps.len())];
    let rays = evaluate(Method::PartialRays, rays_set, &space, &mut *progress)?;
    let ellipsoid = evaluate(Method::Ellipsoid, &grasps, &space, &mut *progress)?;

    let disagree = |other: &[Evaluation]| {
        partial
            .iter()
            .zip(other)
            .filter(|(p, b)| match (p.value, b.value) {
                (Some(x), Some(y)) => (x - y).abs() > 1e-9 * y.max(1e-4),
                (x, y) => x.is_some() != y.is_some(),
            })
            .count()
    };
    let mut errors: Vec<f64> = partial
        .iter()
        .zip(&ellipsoid)
        .filter_map(|(p, e)| Some(relative_error(e.value?, p.value?)))
        .collect();

    // Times over the grasps the partial method found force closure.
    let closure_times = |results: &[Evaluation]| -> Vec<f64> {
        results
            .iter()
            .zip(&partial)
            .filter(|(_, p)| p.force_closure)
            .map(|(q, _)| micros(q.stats.elapsed))
            .collect()
    };
    let times = |results: &[Evaluation]| -> Vec<f64> {
        results.iter().map(|q| micros(q.stats.elapsed)).collect()
    };
    let mut q1_closure: Vec<f64> = q1_times
        .iter()
        .zip(&partial)
        .filter(|(_, p)| p.force_closure)
        .map(|(&t, _)| t)
        .collect();
    let methods = vec![
        TimeRow::new("partial", &mut times(&partial)),
        TimeRow::new("brute", &mut times(&brute)),
        TimeRow::new("ellipsoid", &mut times(&ellipsoid)),
        TimeRow::new("q1-partial", &mut q1_times),
        TimeRow::new("partial-fc", &mut closure_times(&partial)),
        TimeRow::new("brute-fc", &mut closure_times(&brute)),
        TimeRow::new("partial-rays", &mut times(&rays)),
        TimeRow::new("partial-rays-fc", &mut closure_times(&rays)),
        TimeRow::new("q1-partial-fc", &mut q1_closure),
    ];
    // Partial's medians on each slower method's subset, for like-for-like ratios.
    let partial_median = |subset: &[Evaluation]| median(&mut times(&partial[..subset.len()]));
    let partial_closure_median =
        |subset: &[Evaluation]| median(&mut closure_times(&partial[..subset.len()]));
    let m = |i: usize| methods[i].median_us;
    let ratios = OwsRatios {
        brute_over_partial: m(1) / partial_median(&brute),
        brute_over_partial_force_closure: m(5) / partial_closure_median(&brute),
        partial_over_q1: m(0) / m(3),
        partial_over_q1_force_closure: m(4) / m(8),
        rays_over_partial: m(6) / partial_median(&rays),
        rays_over_partial_force_closure: m(7) / partial_closure_median(&rays),
    };
    Ok(OwsReport {
        mesh: name.to_string(),
        vertices: mesh.vertices().len(),
        disturbances: space.len(),
        space: space.describe(),
        prepare_ms,
        ellipsoid_ms,
        ellipsoid_ready,
        grasps: config.grasps,
        contacts: config.contacts,
        edges: config.friction.cone_edges(),
        friction: config.friction.friction(),
        seed: config.seed,
        force_closure: partial.iter().filter(|q| q.force_closure).count(),
        disagreements: disagree(&brute),
        compared_with_brute: brute.len(),
        rays_disagreements: disagree(&rays),
        compared_with_rays: rays.len(),
        methods,
        ratios,
        ellipsoid_relative_error: Quantiles::of(&mut errors),
    })
}

impl OwsReport {
    /// The report as `pqh bench ows --json` gives it.
    pub fn to_json(&self) -> Value {
        let r = &self.ratios;
        let e = &self.ellipsoid_relative_error;
        json!({
            "mesh": self.mesh,
            "vertices": self.vertices,
            "disturbances": self.disturbances,
            "space": self.space,
            "prepare_ms": self.prepare_ms,
            "ellipsoid_ms": self.ellipsoid_ready.then_some(self.ellipsoid_ms),
            "contacts": self.contacts,
            "edges": self.edges,
            "friction": self.friction,
            "seed": self.seed,
            "force_closure": self.force_closure,
            "disagreements": self.disagreements,
            "compared_with_brute": self.compared_with_brute,
            "rays_disagreements": self.rays_disagreements,
            "compared_with_rays": self.compared_with_rays,
            "methods": self.methods.iter().map(|row| json!({
                "method": row.method,
                "grasps": row.grasps,
                "mean_us": row.mean_us,
                "median_us": row.median_us,
            })).collect::<Vec<_>>(),
            "ratios": {
                "brute_over_partial": r.brute_over_partial,
                "brute_over_partial_force_closure": r.brute_over_partial_force_closure,
                "partial_over_q1": r.partial_over_q1,
                "partial_over_q1_force_closure": r.partial_over_q1_force_closure,
                "rays_over_partial": r.rays_over_partial,
                "rays_over_partial_force_closure": r.rays_over_partial_force_closure,
            },
            "ellipsoid_relative_error": {
                "min": e.min, "q25": e.q25, "median": e.median, "q75": e.q75, "max": e.max,
                "count": e.count,
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subsets_and_errors() {
        let object = Mesh::cuboid([0.3, 0.2, 0.1]).unwrap();
        let config = OwsConfig {
            grasps: 5,
            brute_grasps: 9,
            rays_grasps: 0,
            contacts: 3,
            friction: FrictionModel::try_new(0.5, 4).unwrap(),
            reduce: true,
            seed: 4,
        };
        let mut phases = Vec::new();
        let report = run(&object, "box", &config, &mut |label, done, total| {
            if done == total {
                phases.push(label.to_string())
            }
        })
        .unwrap();
        assert_eq!(phases, ["partial", "full", "partial-rays", "ellipsoid"]);
        assert_eq!(report.compared_with_brute, 5); // at most the grasps there are
        assert_eq!(report.compared_with_rays, 0);
        assert!(report.methods[6].median_us.is_nan()); // no partial-rays grasp
        assert_eq!(report.methods.len(), 9);
        assert_eq!(report.disagreements, 0);
        let json = report.to_json();
        assert!(json["ratios"]["rays_over_partial"].is_null()); // NaN
        assert_eq!(json["edges"], 4);
        let none = OwsConfig {
            contacts: 0,
            ..config
        };
        assert!(matches!(
            run(&object, "box", &none, &mut |_, _, _| {}),
            Err(OwsBenchError::Grasp(_))
        ));
    }
}
