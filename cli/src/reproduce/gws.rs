//! Fig. 6 and Fig. 7: Q1 of random grasps on a bar by PQHGWS (the partial hull) against
//! QuickHull (the full hull, then its nearest facet), counting points processed and hyperplanes
//! (facets) created, and timing each grasp.
//!
//! Four methods run on the same grasps ([`bar_grasps`], 4 contacts, μ = 0.5):
//!
//! * `quickhull` — the paper's baseline: the full hull of the grasp's wrenches by QuickHull
//!   ([`FarthestPoint`](pqhull::FarthestPoint)), then Q1 as the smallest facet-plane distance when the origin is inside;
//! * `pqhgws` — the paper's algorithm as published: the partial hull grown toward the origin
//!   ([`ClosestToOrigin`]) on the wrenches, nothing before it;
//! * `pqhull` — this crate's default ([`Evaluator`] with [`Method::Partial`]): a GJK pre-check
//!   settles most grasps that are not force closure without a hull, and the partial hull runs on
//!   snapped wrenches with the answer certified on the caller's;
//! * `qhull` — Qhull's full hull (feature `qhull`), for a reference outside this crate.

use super::{
    Comparison, Figure, FigureId, PAPER_NOT_QUOTED, Progress, ReproduceError, Size, Table,
};
use crate::bench::stats::{mean, micros};
use crate::bench::workloads::{BAR_FRICTION, BAR_HALF_EXTENTS, bar_grasps};
use pqhull::geometry::largest_norm;
use pqhull::grasp::quality::is_force_closure;
use pqhull::grasp::{Evaluator, FrictionModel, Grasp, Method, Metric};
use pqhull::{ClosestToOrigin, Hull, HullError};
use std::time::Instant;

/// Contacts per grasp.
pub const CONTACTS: usize = 4;
/// Grasps of Fig. 6 (the paper's count).
pub const GRASPS: usize = 200;
/// Cone edges of Fig. 6: the k at which this project has compared its ratios with the paper's.
pub const FIG6_EDGES: usize = 32;
/// The methods, in the tables' column order.
pub const METHODS: [&str; 4] = ["quickhull", "pqhgws", "pqhull", "qhull"];

/// Grasps for the fast methods and for the full-hull baselines at `size`.
fn counts(size: Size) -> (usize, usize) {
    match size {
        Size::Smoke => (6, 3),
        Size::Default => (GRASPS, 20),
        Size::Full => (GRASPS, GRASPS),
    }
}

/// One method's per-grasp measurements over a set; NaN where it did not run (or, for the value,
/// where the grasp is not force closure by that method).
#[derive(Clone, Debug, Default)]
struct Run {
    /// Grasps whose wrenches the method could not hull (fewer than six dimensions).
    flat: usize,
    /// Qhull's failures, `grasp i: its message's first line`.
    failed: Vec<String>,
    points: Vec<f64>,
    facets: Vec<f64>,
    time_us: Vec<f64>,
    value: Vec<f64>,
}

impl Run {
    fn skipped(&mut self) {
        self.record(f64::NAN, f64::NAN, f64::NAN, f64::NAN);
    }

    fn record(&mut self, points: f64, facets: f64, time_us: f64, value: f64) {
        self.points.push(points);
        self.facets.push(facets);
        self.time_us.push(time_us);
        self.value.push(value);
    }
}

/// One grasp's measurement: (points, facets, µs, Q1 or NaN when not force closure); `None` when
/// the method cannot build a hull of the wrenches (they span fewer than six dimensions: the
/// published algorithms stop there; pqhull's default evaluates such grasps, Q1 ≤ 0).
type Measurement = Option<(f64, f64, f64, f64)>;

/// A hull error: `None` for a flat wrench set, else the message.
fn flat(e: HullError) -> Result<Measurement, String> {
    match e {
        HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. } => Ok(None),
        e => Err(e.to_string()),
    }
}

/// `q1` when it is force closure under the library's band ([`is_force_closure`] for the
/// wrenches' scale), else NaN: the published algorithms have no band, but a grasp degenerate in
/// exact arithmetic computes to Q1 ≈ ±1e−17 and must get the same verdict from every method.
fn banded(q1: f64, w: &[[f64; 6]]) -> f64 {
    if is_force_closure(q1, largest_norm(w)) {
        q1
    } else {
        f64::NAN
    }
}

/// The paper's QuickHull on `w`.
fn quickhull(w: &[[f64; 6]]) -> Result<Measurement, String> {
    let started = Instant::now();
    let hull = match Hull::try_new(w) {
        Ok(hull) => hull,
        Err(e) => return flat(e),
    };
    let nearest = hull
        .facets()
        .map(|(id, _)| -hull.signed_distance(id, &[0.0; 6]))
        .fold(f64::INFINITY, f64::min);
    let elapsed = micros(started.elapsed());
    let stats = hull.stats();
    let value = banded(nearest, w);
    Ok(Some((
        stats.points_processed as f64,
        stats.facets_created as f64,
        elapsed,
        value,
    )))
}

/// PQHGWS as published on `w`.
fn pqhgws(w: &[[f64; 6]]) -> Result<Measurement, String> {
    let started = Instant::now();
    let result = match Hull::try_with_strategy(w, ClosestToOrigin::new()) {
        Ok((_, result)) => result,
        Err(e) => return flat(e),
    };
    let elapsed = micros(started.elapsed());
    let value = banded(result.signed_distance, w);
    Ok(Some((
        result.stats.points_processed as f64,
        result.stats.facets_created as f64,
        elapsed,
        value,
    )))
}

/// The evaluator's Q1 by its method.
fn evaluated(evaluator: &mut Evaluator<'_>, grasp: &Grasp) -> Result<Measurement, String> {
    let q = evaluator.evaluate(grasp).map_err(|e| e.to_string())?;
    let value = match q.value {
        Some(value) if q.force_closure => value,
        _ => f64::NAN,
    };
    Ok(Some((
        q.stats.points_processed as f64,
        q.stats.facets_created as f64,
        micros(q.stats.elapsed),
        value,
    )))
}

/// Every method on `set`; the baselines on the first `baseline` grasps. `progress` hears of each
/// method under a label carrying `k`.
fn measure(
    set: &[Grasp],
    baseline: usize,
    k: usize,
    progress: Progress<'_>,
) -> Result<Vec<Run>, ReproduceError> {
    let wrenches: Vec<Vec<[f64; 6]>> = set.iter().map(Grasp::wrenches).collect();
    let q1 = |method| Evaluator::new(Metric::Q1, method, None).expect("Q1 takes every hull method");
    let (mut partial, mut qhull) = (q1(Method::Partial), q1(Method::Qhull));
    let mut runs = vec![Run::default(); METHODS.len()];
    for (m, run) in runs.iter_mut().enumerate() {
        let name = METHODS[m];
        let label = format!("{name}, k = {k}");
        let n = match name {
            "quickhull" | "qhull" => baseline.min(set.len()),
            _ => set.len(),
        };
        if name == "qhull" && !cfg!(feature = "qhull") {
            (0..set.len()).for_each(|_| run.skipped());
            continue;
        }
        progress(&label, 0, n);
        for (i, grasp) in set.iter().enumerate() {
            if i >= n {
                run.skipped();
                continue;
            }
            let measured = match name {
                "quickhull" => quickhull(&wrenches[i]),
                "pqhgws" => pqhgws(&wrenches[i]),
                "pqhull" => evaluated(&mut partial, grasp),
                _ => evaluated(&mut qhull, grasp),
            };
            match measured {
                Ok(Some((points, facets, time_us, value))) => {
                    run.record(points, facets, time_us, value)
                }
                Ok(None) => {
                    run.skipped();
                    run.flat += 1;
                }
                // Qhull's topology errors on nearly flat wrench sets are its own limits, and a
                // result of the comparison: counted, not fatal.
                Err(e) if name == "qhull" => {
                    let short: String = e.chars().take(90).filter(|&c| c != '|').collect();
                    run.failed.push(format!("grasp {i}: {short}…"));
                    run.skipped();
                }
                Err(e) => {
                    return Err(ReproduceError::Experiment(format!(
                        "{name}, k = {k}, grasp {i}: {e}"
                    )));
                }
            }
            progress(&label, i + 1, n);
        }
    }
    Ok(runs)
}

/// `runs` as a table: `grasp`, then `<method>_points`, `_facets`, `_us`, `_q1` per method, with
/// `k` first when given.
fn per_grasp_table(name: &str, k: Option<usize>, runs: &[Run]) -> Table {
    let n = runs[0].points.len();
    let mut table = Table::new(name);
    if let Some(k) = k {
        table = table.numbers("k", vec![k as f64; n]);
    }
    table = table.numbers("grasp", (0..n).map(|i| i as f64).collect());
    for (m, run) in runs.iter().enumerate() {
        let method = METHODS[m];
        table = table
            .numbers(&format!("{method}_points"), run.points.clone())
            .numbers(&format!("{method}_facets"), run.facets.clone())
            .numbers(&format!("{method}_us"), run.time_us.clone())
            .numbers(&format!("{method}_q1"), run.value.clone());
    }
    table
}

/// The ratio of `a`'s mean to `b`'s over the rows where both are numbers (NaN when none).
pub fn ratio_of_means(a: &[f64], b: &[f64]) -> f64 {
    let pairs: Vec<(f64, f64)> = a
        .iter()
        .zip(b)
        .filter(|(x, y)| !x.is_nan() && !y.is_nan())
        .map(|(&x, &y)| (x, y))
        .collect();
    mean(pairs.iter().map(|p| p.0)) / mean(pairs.iter().map(|p| p.1))
}

/// The largest relative difference between two methods' Q1 over the grasps both found force
/// closure, and whether they agree on force closure wherever both ran.
fn agreement(a: &Run, b: &Run) -> (f64, usize, bool) {
    let mut worst: f64 = 0.0;
    let mut compared = 0;
    let mut same_verdicts = true;
    for i in 0..a.value.len() {
        if a.time_us[i].is_nan() || b.time_us[i].is_nan() {
            continue;
        }
        let (x, y) = (a.value[i], b.value[i]);
        if x.is_nan() != y.is_nan() {
            same_verdicts = false;
        } else if !x.is_nan() {
            worst = worst.max((x - y).abs() / y.abs());
            compared += 1;
        }
    }
    (worst, compared, same_verdicts)
}

fn times(x: f64) -> String {
    if x.is_nan() {
        "not measured".to_string()
    } else {
        format!("{x:.1}×")
    }
}

fn differences(baseline: usize, grasps: usize) -> Vec<String> {
    vec![
        format!(
            "Grasps: {grasps} random {CONTACTS}-contact grasps on a {} × {} × {} bar, μ = {BAR_FRICTION}; the full-hull baselines on the first {baseline}.",
            2.0 * BAR_HALF_EXTENTS[0],
            2.0 * BAR_HALF_EXTENTS[1],
            2.0 * BAR_HALF_EXTENTS[2]
        ),
        "QuickHull is this crate's own engine run to completion (same predicates, same machine), not the paper's implementation; Qhull is the independent reference.".to_string(),
        "Every method here decides orientations exactly (the paper's used floating point), and every verdict uses this crate's force-closure band (Q1 ≥ 1e−12 × the wrench scale): a grasp degenerate in exact arithmetic computes to Q1 ≈ ±1e−17, and is on the boundary, not force closure.".to_string(),
        "`pqhull` is the default method: a GJK pre-check (most grasps that are not force closure end there, without a hull) and a partial hull on snapped wrenches certified on the caller's; `pqhgws` is the published algorithm alone.".to_string(),
        "Ratios are ratios of means over the grasps both methods ran; times are wall clock on this machine (see docs/paper.md for which).".to_string(),
    ]
}

/// Fig. 6: every method on the bar grasps at k = [`FIG6_EDGES`].
///
/// # Errors
/// [`ReproduceError::Experiment`] when a method fails on a grasp.
pub fn fig6(size: Size, seed: u64, progress: Progress<'_>) -> Result<Figure, ReproduceError> {
    let (grasps, baseline) = counts(size);
    let friction = FrictionModel::try_new(BAR_FRICTION, FIG6_EDGES)
        .map_err(|e| ReproduceError::Experiment(e.to_string()))?;
    let set = bar_grasps(seed, grasps, CONTACTS, friction);
    let runs = measure(&set, baseline, FIG6_EDGES, progress)?;
    let [quick, plain, ours, qhull] = [&runs[0], &runs[1], &runs[2], &runs[3]];
    let (worst, compared, verdicts) = agreement(plain, quick);
    let (worst_ours, compared_ours, verdicts_ours) = agreement(ours, plain);
    let comparisons = vec![
        Comparison::new(
            "points processed, QuickHull / PQHGWS",
            "≈ 6×",
            times(ratio_of_means(&quick.points, &plain.points)),
        ),
        Comparison::new(
            "hyperplanes created, QuickHull / PQHGWS",
            "≈ 70×",
            times(ratio_of_means(&quick.facets, &plain.facets)),
        ),
        Comparison::new(
            "time, QuickHull / PQHGWS",
            "≈ 40×",
            times(ratio_of_means(&quick.time_us, &plain.time_us)),
        ),
        Comparison::new(
            "points processed, QuickHull / pqhull default",
            "— (not in the paper)",
            times(ratio_of_means(&quick.points, &ours.points)),
        ),
        Comparison::new(
            "hyperplanes created, QuickHull / pqhull default",
            "— (not in the paper)",
            times(ratio_of_means(&quick.facets, &ours.facets)),
        ),
        Comparison::new(
            "time, QuickHull / pqhull default",
            "— (not in the paper)",
            times(ratio_of_means(&quick.time_us, &ours.time_us)),
        ),
        Comparison::new(
            "hyperplanes created, Qhull / PQHGWS",
            "— (the paper did not run Qhull)",
            times(ratio_of_means(&qhull.facets, &plain.facets)),
        ),
        Comparison::new(
            "time, Qhull / pqhull default",
            "— (the paper did not run Qhull)",
            times(ratio_of_means(&qhull.time_us, &ours.time_us)),
        ),
        Comparison::new(
            "grasps whose wrenches span fewer than 6 dimensions",
            "— (the published algorithms need a full-dimensional set)",
            format!(
                "{} of {grasps}: PQHGWS as published and QuickHull cannot hull them (left out of their ratios); pqhull's default gives their Q1 ≤ 0",
                plain.flat
            ),
        ),
        Comparison::new(
            "grasps Qhull failed on",
            "— (the paper did not run Qhull)",
            if cfg!(feature = "qhull") {
                match qhull.failed.first() {
                    None => format!("none of {}", baseline.min(grasps)),
                    Some(first) => format!(
                        "{} of {} (left out of its ratios; first: {first})",
                        qhull.failed.len(),
                        baseline.min(grasps)
                    ),
                }
            } else {
                "not run (built without the qhull feature)".to_string()
            },
        ),
        Comparison::new(
            "Q1 agreement",
            PAPER_NOT_QUOTED,
            format!(
                "PQHGWS vs QuickHull: largest relative difference {worst:.1e} over {compared} force-closure grasps, verdicts {}; pqhull vs PQHGWS: {worst_ours:.1e} over {compared_ours}, verdicts {}",
                if verdicts { "identical" } else { "DIFFER" },
                if verdicts_ours { "identical" } else { "DIFFER" }
            ),
        ),
    ];
    Ok(Figure {
        id: FigureId::Fig6,
        title: format!(
            "PQHGWS against QuickHull: {grasps} bar grasps, {CONTACTS} contacts, k = {FIG6_EDGES}"
        ),
        tables: vec![per_grasp_table("fig6", None, &runs)],
        comparisons,
        differences: differences(baseline, grasps),
    })
}

/// Cone-edge counts of Fig. 7 at `size`, and the baselines' grasp count per k.
fn fig7_edges(size: Size) -> (Vec<usize>, usize, usize) {
    match size {
        Size::Smoke => (vec![4, 8], 6, 2),
        Size::Default => (vec![4, 8, 16, 32], GRASPS, 10),
        Size::Full => (vec![4, 8, 16, 32, 64], GRASPS, 20),
    }
}

/// Fig. 7: the ratios of Fig. 6 for several k.
///
/// # Errors
/// As [`fig6`].
pub fn fig7(size: Size, seed: u64, progress: Progress<'_>) -> Result<Figure, ReproduceError> {
    let (edges, grasps, baseline) = fig7_edges(size);
    let mut per_grasp: Option<Table> = None;
    let mut ratios: [Vec<f64>; 6] = Default::default();
    for &k in &edges {
        let friction = FrictionModel::try_new(BAR_FRICTION, k)
            .map_err(|e| ReproduceError::Experiment(e.to_string()))?;
        let set = bar_grasps(seed, grasps, CONTACTS, friction);
        let runs = measure(&set, baseline, k, &mut *progress)?;
        let (quick, plain, ours) = (&runs[0], &runs[1], &runs[2]);
        ratios[0].push(ratio_of_means(&quick.points, &plain.points));
        ratios[1].push(ratio_of_means(&quick.facets, &plain.facets));
        ratios[2].push(ratio_of_means(&quick.time_us, &plain.time_us));
        ratios[3].push(ratio_of_means(&quick.points, &ours.points));
        ratios[4].push(ratio_of_means(&quick.facets, &ours.facets));
        ratios[5].push(ratio_of_means(&quick.time_us, &ours.time_us));
        let table = per_grasp_table("fig7", Some(k), &runs);
        per_grasp = Some(match per_grasp {
            None => table,
            Some(mut all) => {
                for (column, more) in all.columns.iter_mut().zip(table.columns) {
                    match (column, more) {
                        (super::Column::Numbers(_, a), super::Column::Numbers(_, b)) => a.extend(b),
                        _ => unreachable!("the same numeric columns for every k"),
                    }
                }
                all
            }
        });
    }
    let [points, facets, time, points_ours, facets_ours, time_ours] = ratios;
    let last = edges.len() - 1;
    let summary = Table::new("fig7_ratios")
        .numbers("k", edges.iter().map(|&k| k as f64).collect())
        .numbers("points_ratio_pqhgws", points.clone())
        .numbers("facets_ratio_pqhgws", facets.clone())
        .numbers("time_ratio_pqhgws", time.clone())
        .numbers("points_ratio_pqhull", points_ours)
        .numbers("facets_ratio_pqhull", facets_ours)
        .numbers("time_ratio_pqhull", time_ours);
    let at = |v: &[f64]| {
        edges
            .iter()
            .zip(v)
            .map(|(k, r)| format!("k = {k}: {}", times(*r)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let grows = |v: &[f64]| v.windows(2).all(|w| w[1] >= w[0]);
    let comparisons = vec![
        Comparison::new(
            "points processed, QuickHull / PQHGWS",
            PAPER_NOT_QUOTED,
            at(&points),
        ),
        Comparison::new(
            "hyperplanes created, QuickHull / PQHGWS",
            PAPER_NOT_QUOTED,
            at(&facets),
        ),
        Comparison::new("time, QuickHull / PQHGWS", PAPER_NOT_QUOTED, at(&time)),
        Comparison::new(
            "every ratio grows with k",
            "— (the figure plots them against k)",
            if grows(&points) && grows(&facets) && grows(&time) {
                "yes".to_string()
            } else {
                format!("no (largest k: {})", times(time[last]))
            },
        ),
    ];
    let mut differences = differences(baseline, grasps);
    differences.insert(
        1,
        format!(
            "k = {}; each k draws the same grasp positions (same seed).",
            edges
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    Ok(Figure {
        id: FigureId::Fig7,
        title: "QuickHull / PQHGWS ratios as the cone edges grow".to_string(),
        tables: vec![per_grasp.expect("at least one k"), summary],
        comparisons,
        differences,
    })
}
