//! Fig. 8 and Fig. 9: Q_OWS (the object wrench space metric, the paper's Eq. 6) of random
//! surface grasps of the built-in object by PQHOWS against brute force and the ellipsoid method,
//! and the ellipsoid's error.
//!
//! Methods, on the same grasps (4 contacts by area on spot's surface, μ = 0.5, k = 8 for the
//! grasps and for the object wrench space):
//!
//! * `pqhows` — Algorithm 2 as published ([`Method::PartialRays`]);
//! * `pqhull` — this crate's default ([`Method::Partial`]: the same inflation, the disturbances'
//!   support answered by a ball tree);
//! * `brute` — the full grasp hull, then every disturbance against every facet
//!   ([`Method::Full`]);
//! * `ellipsoid` — Borst et al.'s approximation ([`Method::Ellipsoid`]).

use super::{
    Comparison, Figure, FigureId, PAPER_NOT_QUOTED, Progress, ReproduceError, Size, Table,
};
use crate::bench::stats::{median, micros};
use crate::bench::workloads::surface_grasps;
use crate::object::{DEFAULT_OBJECT_NAME, default_object};
use pqhull::grasp::ows::{ObjectWrenchSpace, relative_error};
use pqhull::grasp::{Evaluator, FrictionModel, Method, Metric};

/// Contacts per grasp.
pub const CONTACTS: usize = 4;
/// Cone edges of the grasps and of the object wrench space.
pub const EDGES: usize = 8;
/// Friction coefficient of both.
pub const FRICTION: f64 = 0.5;
/// The methods, in the tables' column order.
pub const METHODS: [(&str, Method); 4] = [
    ("pqhows", Method::PartialRays),
    ("pqhull", Method::Partial),
    ("brute", Method::Full),
    ("ellipsoid", Method::Ellipsoid),
];

/// Grasps for the fast methods, and for brute force and the published algorithm, at `size`.
fn counts(size: Size) -> (usize, usize) {
    match size {
        Size::Smoke => (6, 2),
        Size::Default => (200, 20),
        Size::Full => (200, 200),
    }
}

/// Per method: µs per grasp and Q_OWS (NaN where it did not run, or not force closure); and the
/// verdicts of the default method.
struct Measured {
    grasps: usize,
    slow: usize,
    disturbances: usize,
    times: Vec<Vec<f64>>,
    values: Vec<Vec<f64>>,
    force_closure: Vec<bool>,
}

fn measure(
    size: Size,
    seed: u64,
    methods: &[usize],
    progress: Progress<'_>,
) -> Result<Measured, ReproduceError> {
    let (grasps, slow) = counts(size);
    let fail = |e: String| ReproduceError::Experiment(e);
    let mesh = default_object();
    let friction = FrictionModel::try_new(FRICTION, EDGES).map_err(|e| fail(e.to_string()))?;
    let space = ObjectWrenchSpace::from_mesh(&mesh, friction).map_err(|e| fail(e.to_string()))?;
    let set = surface_grasps(&mesh, &space, seed, grasps, CONTACTS, friction)
        .map_err(|e| fail(e.to_string()))?;
    let mut times = vec![vec![f64::NAN; grasps]; METHODS.len()];
    let mut values = vec![vec![f64::NAN; grasps]; METHODS.len()];
    let mut force_closure = vec![false; grasps];
    for &m in methods {
        let (name, method) = METHODS[m];
        let n = match method {
            Method::PartialRays | Method::Full => slow.min(grasps),
            _ => grasps,
        };
        let mut evaluator = Evaluator::new(Metric::Ows, method, Some(&space))
            .map_err(|e| fail(format!("{name}: {e}")))?;
        progress(name, 0, n);
        for (i, grasp) in set.iter().take(n).enumerate() {
            let q = evaluator
                .evaluate(grasp)
                .map_err(|e| fail(format!("{name}, grasp {i}: {e}")))?;
            times[m][i] = micros(q.stats.elapsed);
            values[m][i] = q.value.unwrap_or(f64::NAN);
            if method == Method::Partial {
                force_closure[i] = q.force_closure;
            }
            progress(name, i + 1, n);
        }
    }
    Ok(Measured {
        grasps,
        slow,
        disturbances: space.len(),
        times,
        values,
        force_closure,
    })
}

fn differences(m: &Measured, slow_methods: bool) -> Vec<String> {
    let slow = if slow_methods {
        format!(
            "; brute force and the published algorithm on the first {}",
            m.slow
        )
    } else {
        String::new()
    };
    vec![
        format!(
            "Object: {DEFAULT_OBJECT_NAME} ({} disturbances at k = {EDGES}, μ = {FRICTION}); {} grasps of {CONTACTS} contacts by area on its surface{slow}.",
            m.disturbances, m.grasps
        ),
        "Every exact method here decides orientations exactly; brute force is this crate's full hull, not the paper's implementation.".to_string(),
        "Times are wall clock on this machine (see docs/paper.md for which).".to_string(),
    ]
}

/// The median of the finite entries of `v[..n]`.
fn median_of_first(v: &[f64], n: usize) -> f64 {
    let mut finite: Vec<f64> = v[..n.min(v.len())]
        .iter()
        .copied()
        .filter(|x| !x.is_nan())
        .collect();
    median(&mut finite)
}

/// Fig. 8: time per grasp of each method.
///
/// # Errors
/// [`ReproduceError::Experiment`] when a method fails on a grasp.
pub fn fig8(size: Size, seed: u64, progress: Progress<'_>) -> Result<Figure, ReproduceError> {
    let m = measure(size, seed, &[1, 0, 2, 3], progress)?;
    let [rays, ours, brute, ellipsoid] = [&m.times[0], &m.times[1], &m.times[2], &m.times[3]];
    let (pv, bv) = (&m.values[1], &m.values[2]);
    let mut worst: f64 = 0.0;
    let mut compared = 0;
    let mut verdicts = true;
    for i in 0..m.slow.min(m.grasps) {
        match (pv[i].is_nan(), bv[i].is_nan()) {
            (false, false) => {
                worst = worst.max((pv[i] - bv[i]).abs() / bv[i]);
                compared += 1;
            }
            (a, b) => verdicts &= a == b,
        }
    }
    let ratio = |a: &[f64], b: &[f64], n: usize| median_of_first(a, n) / median_of_first(b, n);
    let comparisons = vec![
        Comparison::new(
            "median time, brute force / PQHOWS as published",
            PAPER_NOT_QUOTED,
            format!("{:.1}×", ratio(brute, rays, m.slow)),
        ),
        Comparison::new(
            "median time, brute force / pqhull default",
            "— (not in the paper)",
            format!("{:.1}×", ratio(brute, ours, m.slow)),
        ),
        Comparison::new(
            "median time, ellipsoid / pqhull default",
            PAPER_NOT_QUOTED,
            format!("{:.2}×", ratio(ellipsoid, ours, m.grasps)),
        ),
        Comparison::new(
            "median µs per grasp: pqhows, pqhull, brute, ellipsoid",
            PAPER_NOT_QUOTED,
            format!(
                "{:.0}, {:.0}, {:.0}, {:.0}",
                median_of_first(rays, m.slow),
                median_of_first(ours, m.grasps),
                median_of_first(brute, m.slow),
                median_of_first(ellipsoid, m.grasps)
            ),
        ),
        Comparison::new(
            "Q_OWS agreement, pqhull vs brute force",
            PAPER_NOT_QUOTED,
            format!(
                "largest relative difference {worst:.1e} over {compared} force-closure grasps, verdicts {}",
                if verdicts { "identical" } else { "DIFFER" }
            ),
        ),
    ];
    let mut table = Table::new("fig8").numbers("grasp", (0..m.grasps).map(|i| i as f64).collect());
    table = table.numbers(
        "force_closure",
        m.force_closure
            .iter()
            .map(|&c| f64::from(u8::from(c)))
            .collect(),
    );
    for (k, (name, _)) in METHODS.iter().enumerate() {
        table = table
            .numbers(&format!("{name}_us"), m.times[k].clone())
            .numbers(&format!("{name}_ows"), m.values[k].clone());
    }
    Ok(Figure {
        id: FigureId::Fig8,
        title: format!(
            "PQHOWS against brute force and the ellipsoid method: {} grasps",
            m.grasps
        ),
        tables: vec![table],
        comparisons,
        differences: differences(&m, true),
    })
}

/// Fig. 9: the ellipsoid method's relative error against the exact Q_OWS, per force-closure
/// grasp.
///
/// # Errors
/// As [`fig8`].
pub fn fig9(size: Size, seed: u64, progress: Progress<'_>) -> Result<Figure, ReproduceError> {
    let m = measure(size, seed, &[1, 3], progress)?;
    let (exact, approximate) = (&m.values[1], &m.values[3]);
    let rows: Vec<usize> = (0..m.grasps)
        .filter(|&i| !exact[i].is_nan() && !approximate[i].is_nan())
        .collect();
    let errors: Vec<f64> = rows
        .iter()
        .map(|&i| relative_error(approximate[i], exact[i]))
        .collect();
    let mut sorted = errors.clone();
    sorted.sort_by(f64::total_cmp);
    let quantile = |q: f64| {
        if sorted.is_empty() {
            f64::NAN
        } else {
            sorted[((sorted.len() - 1) as f64 * q).round() as usize]
        }
    };
    let comparisons = vec![
        Comparison::new(
            "relative error (approx − exact) / exact: min, median, max",
            PAPER_NOT_QUOTED,
            format!(
                "{:.3}, {:.3}, {:.3} over {} force-closure grasps",
                quantile(0.0),
                quantile(0.5),
                quantile(1.0),
                errors.len()
            ),
        ),
        Comparison::new(
            "the ellipsoid never overestimates",
            "— (it contains every disturbance)",
            if errors.iter().all(|&e| e <= 0.0) {
                "yes: every error ≤ 0".to_string()
            } else {
                "NO: some error > 0".to_string()
            },
        ),
    ];
    let table = Table::new("fig9")
        .numbers("grasp", rows.iter().map(|&i| i as f64).collect())
        .numbers("exact_ows", rows.iter().map(|&i| exact[i]).collect())
        .numbers(
            "ellipsoid_ows",
            rows.iter().map(|&i| approximate[i]).collect(),
        )
        .numbers("relative_error", errors);
    Ok(Figure {
        id: FigureId::Fig9,
        title: "The ellipsoid method's relative error".to_string(),
        tables: vec![table],
        comparisons,
        differences: differences(&m, false),
    })
}
