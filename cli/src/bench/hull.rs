//! The hull suite (what `pqh bench hull` runs): pqhull's full hull against Qhull on the same
//! points, case by case, in one run — `rbox` families in 3 to 6 dimensions, integer grids, and
//! grasp wrench sets (raw wrenches and materialised Minkowski sums).
//!
//! Every input is generated here, seeded; nothing is read from disk. Each case is timed as
//! pqhull's call (best of [`HullBenchConfig::repeats`] runs, wall clock, one thread) and as
//! `qhull_baseline::qhull_facet_count` on the same points (Qhull's
//! defaults plus `Qt`: all of Qhull's work; cargo feature `qhull`), the two runs interleaved.
//! Untimed, once: the vertex counts of both hulls
//! ([`Hull::vertex_indices`], `qhull_baseline::qhull_stats`) and
//! [`Hull::check`] on pqhull's.
//!
//! | workload | points | pqhull's timed call |
//! | --- | --- | --- |
//! | [`Workload::Rbox`] | [`rbox::generate`] of a family | [`Hull::try_new`] |
//! | [`Workload::Grid`] | `{0, …, m − 1}^D` | [`Hull::try_new`] |
//! | [`Workload::Wrenches`] | [`Grasp::wrenches`] of a force-closure bar grasp | [`Hull::try_new`]; [`gws_volume`] |
//! | [`Workload::Minkowski`] | the raw Minkowski sum of a force-closure bar grasp's contacts, materialised | [`Hull::try_new`]; Q∞ by [`Method::Full`] |
//!
//! Q∞ is the plain variant (no zero wrench: `Metric::QInf { with_zero_wrench: false }`), the sum of
//! the cone-edge sets alone, whose materialised sum (`k^m` points, not `(k + 1)^m`) is the set
//! Qhull and the `hull` row get: `Σ_i w_i(j_i)` of the raw wrenches, summed in contact order.
//! [`Method::Full`] materialises the *snapped* sum itself and hulls it with the exact engine, then
//! certifies the value on the raw sum, or (origin outside) runs GJK on the raw sum
//! (docs/ARCHITECTURE.md). The grasps are the first of [`bar_grasps`](super::workloads::bar_grasps)
//! whose Q1 (partial method, untimed) is force closure, and for a sum also whose sum spans 6-D with
//! room to spare (three contacts on faces of one axis give a flat sum: Qhull refuses it, the full
//! method settles it without a hull). Plain Q∞ of three contacts on the bar is never force closure
//! — three unit normal forces on a box's faces balance only with a tangential force as large as a
//! normal one, beyond μ = 0.5 — so its row is the full method on a grasp that is not force closure:
//! the whole snapped sum is hulled, then GJK measures the distance. A report says when no candidate
//! qualified ([`CaseRow::force_closure`]).
//!
//! Times are wall clock on whatever else the machine is doing: compare rows of one run.

use super::Progress;
#[cfg(feature = "qhull")]
use super::stats::first_line;
use pqhull::grasp::metrics::gws_volume;
use pqhull::grasp::{Evaluator, Grasp, Method, Metric};
use pqhull::hull::Hull;
use pqhull::rbox::{self, Family};
use std::fmt;
use std::time::Instant;

mod inputs;
mod report;
pub use inputs::{grasp_for, grasp_points, grid, minkowski_sum};
pub use report::{CaseRow, HullBenchReport, PqhullColumns, QhullColumns};

/// The most timed runs per case ([`HullBenchConfig::repeats`]).
pub const MAX_REPEATS: usize = 1000;

/// The dimensions the suite runs by default.
pub const DIMENSIONS: [usize; 4] = [3, 4, 5, 6];

/// The engine's other dimensions, whose `rbox` families and grids run only when asked for
/// ([`HullBenchConfig::dimensions`]): the issue's targets are set in [`DIMENSIONS`], and these
/// show the engine's range against Qhull's by the same command.
pub const EXTRA_DIMENSIONS: [usize; 3] = [2, 7, 8];

/// Candidate grasps searched for a force-closure one ([`Workload::Wrenches`],
/// [`Workload::Minkowski`]).
pub const GRASP_CANDIDATES: usize = 500;

/// The names [`HullBenchConfig::families`] accepts: the `rbox` families' ([`Family::name`]),
/// then `grid`, `wrenches` and `minkowski`.
pub const FAMILY_NAMES: [&str; 13] = [
    "cube",
    "sphere",
    "corners",
    "simplex",
    "shell",
    "lens",
    "lattice",
    "clusters",
    "duplicates",
    "tilted",
    "grid",
    "wrenches",
    "minkowski",
];

/// The sizes of the cases.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Preset {
    /// Sizes long enough to time reliably, yet short enough to run the whole suite in one sitting
    /// (the times they give: docs/benchmarks.md, "Hull suite against Qhull").
    #[default]
    Standard,
    /// Small sizes, for tests: a twentieth of the standard point counts (at least 60), smaller
    /// grids, fewer cone edges.
    Quick,
}

impl Preset {
    /// `standard` or `quick`.
    pub fn name(self) -> &'static str {
        match self {
            Preset::Standard => "standard",
            Preset::Quick => "quick",
        }
    }
}

/// What points a case hulls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Workload {
    /// [`rbox::generate`]`(family, n, seed)`: [`rbox::point_count`] points.
    Rbox {
        /// The family, with its default parameters.
        family: Family,
        /// Its `n`.
        n: usize,
    },
    /// Every point of `{0, …, side − 1}^D`, in odometer order (last coordinate fastest).
    Grid {
        /// `m`, the number of values per coordinate.
        side: usize,
    },
    /// The raw wrenches ([`Grasp::wrenches`]) of a force-closure random grasp on the GWS
    /// benchmark's bar ([`bar_grasps`](super::workloads::bar_grasps), μ =
    /// [`BAR_FRICTION`](super::workloads::BAR_FRICTION)): `contacts · edges` points in 6-D.
    Wrenches {
        /// Contacts of the grasp.
        contacts: usize,
        /// Cone edges per contact.
        edges: usize,
    },
    /// The materialised Minkowski sum ([`minkowski_sum`]: plain, no zero wrench) of the contact
    /// wrench sets of a random bar grasp whose Q1 is force closure and whose sum spans 6-D with
    /// room to spare: `edges^contacts` points.
    Minkowski {
        /// Contacts of the grasp.
        contacts: usize,
        /// Cone edges per contact.
        edges: usize,
    },
}

/// The call timed for pqhull.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Timed {
    /// [`Hull::try_new`] on the points.
    Hull,
    /// [`gws_volume`] of the grasp (the full hull of its raw wrenches, then its volume).
    Volume,
    /// Q∞ (plain) by [`Method::Full`]: an [`Evaluator`] made and run on the grasp.
    QInfFull,
}

impl Timed {
    /// `hull`, `volume` or `qinf-full`.
    pub fn name(self) -> &'static str {
        match self {
            Timed::Hull => "hull",
            Timed::Volume => "volume",
            Timed::QInfFull => "qinf-full",
        }
    }
}

/// One input of the suite, in one dimension; its rows are [`Case::timed`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Case {
    /// The points.
    pub workload: Workload,
    /// Their dimension (6 for the grasp workloads).
    pub dimension: usize,
}

impl Case {
    /// The family name the filter matches ([`FAMILY_NAMES`]).
    pub fn family(&self) -> &'static str {
        match self.workload {
            Workload::Rbox { family, .. } => family.name(),
            Workload::Grid { .. } => "grid",
            Workload::Wrenches { .. } => "wrenches",
            Workload::Minkowski { .. } => "minkowski",
        }
    }

    /// The case's name in the table: the family, with the grid's side or the grasp's size
    /// (`grid-m20`, `wrenches-4x16`, `minkowski-3x8`).
    pub fn name(&self) -> String {
        match self.workload {
            Workload::Rbox { family, .. } => family.name().to_string(),
            Workload::Grid { side } => format!("grid-m{side}"),
            Workload::Wrenches { contacts, edges } => format!("wrenches-{contacts}x{edges}"),
            Workload::Minkowski { contacts, edges } => format!("minkowski-{contacts}x{edges}"),
        }
    }

    /// The calls timed on its points, one row each.
    pub fn timed(&self) -> &'static [Timed] {
        match self.workload {
            Workload::Rbox { .. } | Workload::Grid { .. } => &[Timed::Hull],
            Workload::Wrenches { .. } => &[Timed::Hull, Timed::Volume],
            Workload::Minkowski { .. } => &[Timed::QInfFull, Timed::Hull],
        }
    }

    /// Whether the points are random in general position (`cube`, `sphere`): the summary's
    /// second minimum is over these.
    pub fn is_random(&self) -> bool {
        matches!(
            self.workload,
            Workload::Rbox {
                family: Family::UniformCube | Family::SphereSurface,
                ..
            }
        )
    }
}

/// `rbox`'s `n` for `family` in dimension `d` (2 to 8) under `preset`: for the standard preset,
/// sizes that keep each case long enough to time and the suite short, smaller as the hulls'
/// facets multiply with the dimension (the lattice and the clusters grow fastest with it; the
/// simplex's hull is three to nine points at any size; the times are in docs/benchmarks.md, "Hull
/// suite against Qhull"), the quick preset a twentieth of them (at least 60).
fn rbox_n(preset: Preset, family: &Family, d: usize) -> usize {
    // By dimension, 2-D to 8-D.
    let by_dimension: [usize; 7] = match family {
        Family::UniformCube => [1_000_000, 100_000, 10_000, 5_000, 500, 300, 120],
        Family::SphereSurface | Family::ThinShell { .. } | Family::NarrowLens { .. } => {
            [20_000, 20_000, 5_000, 1_000, 300, 120, 60]
        }
        Family::CubeCornersDiamond | Family::ManyDuplicates { .. } => {
            [1_000_000, 100_000, 10_000, 5_000, 2_000, 1_000, 500]
        }
        Family::Simplex => [1_000_000, 100_000, 50_000, 50_000, 50_000, 50_000, 50_000],
        Family::IntegerLattice { .. } => [1_000_000, 100_000, 10_000, 5_000, 250, 120, 80],
        Family::Clusters { .. } => [1_000_000, 100_000, 10_000, 2_000, 200, 100, 60],
        Family::TiltedFaces => [200_000, 100_000, 20_000, 5_000, 1_000, 300, 120],
    };
    let standard = by_dimension[d.clamp(2, 8) - 2];
    match preset {
        Preset::Standard => standard,
        Preset::Quick => (standard / 20).max(60),
    }
}

/// The grid's side in dimension `d`.
fn grid_side(preset: Preset, d: usize) -> usize {
    match (preset, d) {
        (Preset::Standard, 2) => 1000,
        (Preset::Quick, 2) => 50,
        (Preset::Quick, 7 | 8) => 2,
        (Preset::Standard, 7) => 3,
        (Preset::Standard, 8) => 2,
        (Preset::Standard, 3) => 20,
        (Preset::Standard, 4) => 8,
        (Preset::Standard, 5) => 5,
        (Preset::Standard, _) => 4,
        (Preset::Quick, 3) => 6,
        (Preset::Quick, 4) => 4,
        (Preset::Quick, _) => 3,
    }
}

/// Every case of `preset`, in the order they run: the `rbox` families dimension by dimension,
/// the grids, then the grasp workloads.
///
/// ```
/// use pqhull_cli::bench::hull::{Preset, cases};
/// let all = cases(Preset::Quick);
/// assert_eq!(all[0].name(), "cube");
/// assert!(all.iter().any(|c| c.name() == "wrenches-4x8"));
/// ```
pub fn cases(preset: Preset) -> Vec<Case> {
    cases_in(preset, &DIMENSIONS)
}

/// [`cases`] in `dimensions` (any of [`DIMENSIONS`] and [`EXTRA_DIMENSIONS`], run in increasing
/// order): the `rbox` families and the grids in each, and the grasp workloads if 6 is among them.
fn cases_in(preset: Preset, dimensions: &[usize]) -> Vec<Case> {
    let mut dimensions = dimensions.to_vec();
    dimensions.sort_unstable();
    dimensions.dedup();
    let mut out = Vec::new();
    for &d in &dimensions {
        for family in Family::ALL {
            out.push(Case {
                workload: Workload::Rbox {
                    family,
                    n: rbox_n(preset, &family, d),
                },
                dimension: d,
            });
        }
    }
    for &d in &dimensions {
        out.push(Case {
            workload: Workload::Grid {
                side: grid_side(preset, d),
            },
            dimension: d,
        });
    }
    if !dimensions.contains(&6) {
        return out;
    }
    let (wrench_edges, sum_edges): (&[usize], &[usize]) = match preset {
        Preset::Standard => (&[8, 16, 32], &[6, 8]),
        Preset::Quick => (&[8], &[4]),
    };
    for &edges in wrench_edges {
        out.push(Case {
            workload: Workload::Wrenches { contacts: 4, edges },
            dimension: 6,
        });
    }
    for &edges in sum_edges {
        out.push(Case {
            workload: Workload::Minkowski { contacts: 3, edges },
            dimension: 6,
        });
    }
    out
}

/// What to measure.
#[derive(Clone, Debug, PartialEq)]
pub struct HullBenchConfig {
    /// The sizes.
    pub preset: Preset,
    /// Only the cases of these families ([`FAMILY_NAMES`]); empty: all.
    pub families: Vec<String>,
    /// Only the cases in these dimensions ([`DIMENSIONS`]); empty: all.
    pub dimensions: Vec<usize>,
    /// Timed runs of each call, the best reported (1 to [`MAX_REPEATS`]).
    pub repeats: usize,
    /// Seed of every generated input.
    pub seed: u64,
}

impl Default for HullBenchConfig {
    /// `pqh bench hull`'s defaults: every case of the standard preset, best of 3, seed 1.
    fn default() -> Self {
        HullBenchConfig {
            preset: Preset::Standard,
            families: Vec::new(),
            dimensions: Vec::new(),
            repeats: 3,
            seed: 1,
        }
    }
}

impl HullBenchConfig {
    /// The cases this configuration runs, in order.
    ///
    /// # Errors
    /// As [`run`], before any measurement.
    pub fn cases(&self) -> Result<Vec<Case>, HullBenchError> {
        if !(1..=MAX_REPEATS).contains(&self.repeats) {
            return Err(HullBenchError::Repeats(self.repeats));
        }
        if let Some(name) = self
            .families
            .iter()
            .find(|f| !FAMILY_NAMES.contains(&f.as_str()))
        {
            return Err(HullBenchError::UnknownFamily(name.clone()));
        }
        if let Some(&d) = self
            .dimensions
            .iter()
            .find(|d| !DIMENSIONS.contains(d) && !EXTRA_DIMENSIONS.contains(d))
        {
            return Err(HullBenchError::Dimension(d));
        }
        let dimensions: &[usize] = if self.dimensions.is_empty() {
            &DIMENSIONS
        } else {
            &self.dimensions
        };
        let selected: Vec<Case> = cases_in(self.preset, dimensions)
            .into_iter()
            .filter(|c| self.families.is_empty() || self.families.iter().any(|f| f == c.family()))
            .collect();
        if selected.is_empty() {
            return Err(HullBenchError::NoCases);
        }
        Ok(selected)
    }
}

/// Why the suite could not run.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum HullBenchError {
    /// `repeats` outside 1 to [`MAX_REPEATS`].
    Repeats(usize),
    /// A family name not in [`FAMILY_NAMES`].
    UnknownFamily(String),
    /// A dimension in neither [`DIMENSIONS`] nor [`EXTRA_DIMENSIONS`].
    Dimension(usize),
    /// The filters leave no case.
    NoCases,
}

impl fmt::Display for HullBenchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HullBenchError::Repeats(n) => {
                write!(f, "repeats must be 1 to {MAX_REPEATS}, got {n}")
            }
            HullBenchError::UnknownFamily(name) => write!(
                f,
                "unknown family '{name}' (known: {})",
                FAMILY_NAMES.join(", ")
            ),
            HullBenchError::Dimension(d) => write!(
                f,
                "the hull suite has no case in dimension {d} (it has {:?} by default, and {:?} \
                 when asked)",
                DIMENSIONS, EXTRA_DIMENSIONS
            ),
            HullBenchError::NoCases => {
                write!(f, "no case matches the family and dimension filters")
            }
        }
    }
}

impl std::error::Error for HullBenchError {}

/// Runs the suite. `progress` hears of each case (label `cases`).
///
/// ```
/// use pqhull_cli::bench::hull::{HullBenchConfig, Preset, run};
/// let config = HullBenchConfig {
///     preset: Preset::Quick,
///     families: vec!["cube".into(), "grid".into()],
///     dimensions: vec![3],
///     repeats: 1,
///     ..HullBenchConfig::default()
/// };
/// let report = run(&config, &mut |_, _, _| {})?;
/// assert_eq!(report.rows.len(), 2);
/// assert!(report.rows.iter().all(|r| r.check_passed()));
/// assert_eq!(report.to_json()["benchmark"], "hull");
/// # Ok::<(), pqhull_cli::bench::hull::HullBenchError>(())
/// ```
///
/// # Errors
/// [`HullBenchError`] for a configuration that selects nothing or is out of range, before any
/// measurement. A call that fails on some case (pqhull's or Qhull's) is reported in its row.
pub fn run(
    config: &HullBenchConfig,
    progress: Progress<'_>,
) -> Result<HullBenchReport, HullBenchError> {
    let selected = config.cases()?;
    let mut rows = Vec::new();
    progress("cases", 0, selected.len());
    for (i, case) in selected.iter().enumerate() {
        rows.extend(measure_case(case, config));
        progress("cases", i + 1, selected.len());
    }
    Ok(HullBenchReport {
        preset: config.preset,
        repeats: config.repeats,
        seed: config.seed,
        qhull_available: cfg!(feature = "qhull"),
        rows,
    })
}

/// The rows of one case.
fn measure_case(case: &Case, config: &HullBenchConfig) -> Vec<CaseRow> {
    let (seed, repeats) = (config.seed, config.repeats);
    match (case.workload, case.dimension) {
        (Workload::Rbox { family, n }, 2) => {
            points_row(case, &rbox::generate::<2>(&family, n, seed), repeats)
        }
        (Workload::Rbox { family, n }, 3) => {
            points_row(case, &rbox::generate::<3>(&family, n, seed), repeats)
        }
        (Workload::Rbox { family, n }, 4) => {
            points_row(case, &rbox::generate::<4>(&family, n, seed), repeats)
        }
        (Workload::Rbox { family, n }, 5) => {
            points_row(case, &rbox::generate::<5>(&family, n, seed), repeats)
        }
        (Workload::Rbox { family, n }, 6) => {
            points_row(case, &rbox::generate::<6>(&family, n, seed), repeats)
        }
        (Workload::Rbox { family, n }, 7) => {
            points_row(case, &rbox::generate::<7>(&family, n, seed), repeats)
        }
        // 8-D (`cases_in` makes no other).
        (Workload::Rbox { family, n }, _) => {
            points_row(case, &rbox::generate::<8>(&family, n, seed), repeats)
        }
        (Workload::Grid { side }, 2) => points_row(case, &grid::<2>(side), repeats),
        (Workload::Grid { side }, 3) => points_row(case, &grid::<3>(side), repeats),
        (Workload::Grid { side }, 4) => points_row(case, &grid::<4>(side), repeats),
        (Workload::Grid { side }, 5) => points_row(case, &grid::<5>(side), repeats),
        (Workload::Grid { side }, 6) => points_row(case, &grid::<6>(side), repeats),
        (Workload::Grid { side }, 7) => points_row(case, &grid::<7>(side), repeats),
        (Workload::Grid { side }, _) => points_row(case, &grid::<8>(side), repeats),
        (Workload::Wrenches { contacts, edges }, _) => {
            let (grasp, closure) = grasp_for(seed, contacts, edges, false);
            grasp_rows(case, &grasp, closure, &grasp.wrenches(), repeats)
        }
        (Workload::Minkowski { contacts, edges }, _) => {
            let (grasp, closure) = grasp_for(seed, contacts, edges, true);
            grasp_rows(case, &grasp, closure, &minkowski_sum(&grasp), repeats)
        }
    }
}

/// Milliseconds since `started`.
fn ms_since(started: Instant) -> f64 {
    started.elapsed().as_secs_f64() * 1e3
}

/// The untimed figures of `Hull::try_new(points)`: vertices, facets, the check and its time.
fn hull_figures<const D: usize>(points: &[[f64; D]]) -> Figures {
    let hull = Hull::try_new(points).map_err(|e| e.to_string())?;
    let started = Instant::now();
    let check = hull.check().map_err(|e| e.to_string());
    let check_ms = ms_since(started);
    Ok((
        hull.vertex_indices().len(),
        hull.facet_count(),
        check,
        check_ms,
    ))
}

/// pqhull's best time (ms) and the value of its last run, or its error.
type PqhullTimes = Result<(f64, Option<f64>), String>;

/// Qhull's figures of a row, or its error.
type QhullResult = Result<QhullColumns, String>;

/// Best-of-`repeats` times of `pqhull` and of Qhull on `points`, runs interleaved (pqhull
/// first); the value of pqhull's last run; and Qhull's untimed counts.
fn time_both<const D: usize>(
    points: &[[f64; D]],
    repeats: usize,
    mut pqhull: impl FnMut() -> Result<Option<f64>, String>,
) -> (PqhullTimes, Option<QhullResult>) {
    let mut best = f64::INFINITY;
    let mut value = None;
    let mut failed = None;
    let mut qhull_best = f64::INFINITY;
    let mut qhull_failed: Option<String> = None;
    for _ in 0..repeats {
        let started = Instant::now();
        let result = std::hint::black_box(pqhull());
        let ms = ms_since(started);
        match result {
            Ok(v) => {
                best = best.min(ms);
                value = v;
            }
            Err(e) => failed = Some(e),
        }
        if cfg!(feature = "qhull") && qhull_failed.is_none() {
            match qhull_time(points) {
                Ok(ms) => qhull_best = qhull_best.min(ms),
                Err(e) => qhull_failed = Some(e),
            }
        }
    }
    let pqhull = match failed {
        Some(e) => Err(e),
        None => Ok((best, value)),
    };
    let qhull = cfg!(feature = "qhull").then(|| match qhull_failed {
        Some(e) => Err(e),
        None => qhull_counts(points).map(|(vertices, facets)| QhullColumns {
            ms: qhull_best,
            vertices,
            facets,
        }),
    });
    (pqhull, qhull)
}

/// One run of Qhull on `points`, timed, ms.
#[cfg(feature = "qhull")]
fn qhull_time<const D: usize>(points: &[[f64; D]]) -> Result<f64, String> {
    let started = Instant::now();
    let facets = pqhull::qhull_baseline::qhull_facet_count(std::hint::black_box(points));
    let ms = ms_since(started);
    facets
        .map(|_| ms)
        .map_err(|e| first_line(&e.to_string(), 200))
}

/// Without the `qhull` feature: never called (the rows have no Qhull columns).
#[cfg(not(feature = "qhull"))]
fn qhull_time<const D: usize>(_points: &[[f64; D]]) -> Result<f64, String> {
    Err("built without the qhull feature".to_string())
}

/// Qhull's vertex and facet counts (untimed).
#[cfg(feature = "qhull")]
fn qhull_counts<const D: usize>(points: &[[f64; D]]) -> Result<(usize, usize), String> {
    pqhull::qhull_baseline::qhull_stats(points)
        .map(|s| (s.vertices, s.facets))
        .map_err(|e| first_line(&e.to_string(), 200))
}

/// Without the `qhull` feature: never called.
#[cfg(not(feature = "qhull"))]
fn qhull_counts<const D: usize>(_points: &[[f64; D]]) -> Result<(usize, usize), String> {
    Err("built without the qhull feature".to_string())
}

/// The row of a point-set case: [`Hull::try_new`] against Qhull.
fn points_row<const D: usize>(case: &Case, points: &[[f64; D]], repeats: usize) -> Vec<CaseRow> {
    let (pqhull, qhull) = time_both(points, repeats, || {
        Hull::try_new(points)
            .map(|h| {
                std::hint::black_box(h.facet_count());
                None
            })
            .map_err(|e| e.to_string())
    });
    let figures = hull_figures(points);
    vec![row(
        case,
        Timed::Hull,
        points.len(),
        None,
        pqhull,
        qhull,
        &figures,
    )]
}

/// The rows of a grasp case: each of [`Case::timed`] against Qhull on `points`.
fn grasp_rows(
    case: &Case,
    grasp: &Grasp,
    force_closure: bool,
    points: &[[f64; 6]],
    repeats: usize,
) -> Vec<CaseRow> {
    let figures = hull_figures(points);
    case.timed()
        .iter()
        .map(|&timed| {
            let (pqhull, qhull) = time_both(points, repeats, || match timed {
                Timed::Hull => Hull::try_new(points)
                    .map(|h| {
                        std::hint::black_box(h.facet_count());
                        None
                    })
                    .map_err(|e| e.to_string()),
                Timed::Volume => gws_volume(grasp).map(Some).map_err(|e| e.to_string()),
                Timed::QInfFull => {
                    let metric = Metric::QInf {
                        with_zero_wrench: false,
                    };
                    Evaluator::new(metric, Method::Full, None)
                        .and_then(|mut evaluator| evaluator.evaluate(grasp))
                        .map(|q| q.value)
                        .map_err(|e| e.to_string())
                }
            });
            row(
                case,
                timed,
                points.len(),
                Some(force_closure),
                pqhull,
                qhull,
                &figures,
            )
        })
        .collect()
}

/// The untimed figures of a hull: vertices, facets, check, check time.
type Figures = Result<(usize, usize, Result<(), String>, f64), String>;

/// A row from its measurements.
fn row(
    case: &Case,
    timed: Timed,
    points: usize,
    force_closure: Option<bool>,
    pqhull: PqhullTimes,
    qhull: Option<QhullResult>,
    figures: &Figures,
) -> CaseRow {
    let pqhull = pqhull.and_then(|(ms, value)| {
        let (vertices, facets, check, check_ms) = figures.clone()?;
        Ok(PqhullColumns {
            ms,
            vertices,
            facets,
            check,
            check_ms,
            value,
        })
    });
    CaseRow {
        case: *case,
        timed,
        points,
        force_closure,
        pqhull,
        qhull,
    }
}

#[cfg(test)]
mod tests;
