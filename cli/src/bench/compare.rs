//! Full hull against partial hull on the seeded point sets of [`workloads`](super::workloads):
//! the distance from the origin to the hull boundary both ways, their agreement, and the work
//! each did (what `pqh compare` shows).

use super::stats::ratio;
use super::workloads::{PointSet, point_sets, wrench_set};
use pqhull::hull::{FarthestPoint, Hull, HullError, Stats};
use pqhull::predicates::Sign;
use pqhull::strategy::ClosestToOrigin;
use serde_json::{Value, json};
use std::fmt;

/// Two answers agree when they differ by at most this much.
pub const TOLERANCE: f64 = 1e-9;

/// The full hull's view of the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FullAnswer {
    /// Strictly inside: min over facets of −signed_distance(origin).
    Inside(f64),
    /// On a facet's plane and inside every other one (exact): distance 0.
    Boundary,
    /// Strictly beyond some facet of the full hull (exact test): not force closure.
    Outside,
}

/// One point set, both strategies.
#[derive(Clone, Debug, PartialEq)]
pub struct CompareRow {
    /// The set's name ([`PointSet::name`]).
    pub name: &'static str,
    /// What the set is.
    pub description: String,
    /// Its number of points.
    pub points: usize,
    /// Where the full hull puts the origin.
    pub full: FullAnswer,
    /// The full hull's work.
    pub full_stats: Stats,
    /// The partial hull's signed distance (negative outside).
    pub partial: f64,
    /// The partial hull's work.
    pub partial_stats: Stats,
}

impl CompareRow {
    /// Where the origin is relative to the full hull (decided exactly): `inside`, `boundary` or
    /// `outside`.
    pub fn origin(&self) -> &'static str {
        match self.full {
            FullAnswer::Boundary => "boundary",
            FullAnswer::Inside(_) => "inside",
            FullAnswer::Outside => "outside",
        }
    }

    /// The full hull's distance, when the origin is not outside.
    pub fn full_distance(&self) -> Option<f64> {
        match self.full {
            FullAnswer::Inside(d) => Some(d),
            FullAnswer::Boundary => Some(0.0),
            FullAnswer::Outside => None,
        }
    }

    /// |full − partial| when the origin is not outside.
    pub fn difference(&self) -> Option<f64> {
        self.full_distance().map(|d| (d - self.partial).abs())
    }

    /// Whether the two strategies agree: the same distance within [`TOLERANCE`] (inside), or
    /// both outside.
    pub fn agrees(&self) -> bool {
        match self.difference() {
            Some(difference) => difference <= TOLERANCE,
            None => self.partial < 0.0,
        }
    }

    /// full / partial wall time (infinite when the partial hull's time rounds to zero).
    pub fn time_speedup(&self) -> f64 {
        ratio(ms(&self.full_stats), ms(&self.partial_stats))
    }

    /// full / partial facets created.
    pub fn facets_speedup(&self) -> f64 {
        ratio(
            self.full_stats.facets_created as f64,
            self.partial_stats.facets_created as f64,
        )
    }

    /// full / partial points processed.
    pub fn points_speedup(&self) -> f64 {
        ratio(
            self.full_stats.points_processed as f64,
            self.partial_stats.points_processed as f64,
        )
    }
}

/// Milliseconds of work in `stats`.
pub fn ms(stats: &Stats) -> f64 {
    stats.elapsed.as_secs_f64() * 1e3
}

/// Runs both strategies on `points`: the full hull ([`FarthestPoint`], the origin's side of
/// every facet decided exactly) and the partial hull grown toward the origin
/// ([`ClosestToOrigin`]).
///
/// ```
/// use pqhull_cli::bench::compare::compare;
/// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
/// let row = compare("square", "a square".into(), &square)?;
/// assert_eq!(row.origin(), "inside");
/// assert!(row.agrees() && (row.partial - 1.0).abs() < 1e-12);
/// # Ok::<(), pqhull::HullError>(())
/// ```
///
/// # Errors
/// [`HullError`] when the points admit no hull.
pub fn compare<const D: usize>(
    name: &'static str,
    description: String,
    points: &[[f64; D]],
) -> Result<CompareRow, HullError> {
    let origin = [0.0; D];
    let (full, ()) = Hull::try_with_strategy(points, FarthestPoint::new())?;
    let sides: Vec<Sign> = full
        .facets()
        .map(|(id, _)| full.side_of(id, &origin))
        .collect();
    let answer = if sides.contains(&Sign::Positive) {
        FullAnswer::Outside
    } else if sides.contains(&Sign::Zero) {
        FullAnswer::Boundary
    } else {
        let depth = full
            .facets()
            .map(|(_, f)| -f.signed_distance(&origin))
            .fold(f64::INFINITY, f64::min);
        FullAnswer::Inside(depth)
    };
    let (_, partial) = Hull::try_with_strategy(points, ClosestToOrigin::new())?;
    Ok(CompareRow {
        name,
        description,
        points: points.len(),
        full: answer,
        full_stats: full.stats(),
        partial: partial.signed_distance,
        partial_stats: partial.stats,
    })
}

/// A point set that admits no hull.
#[derive(Clone, Debug, PartialEq)]
pub struct CompareError {
    /// The set's name.
    pub set: &'static str,
    /// Why.
    pub error: HullError,
}

impl fmt::Display for CompareError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.set, self.error)
    }
}

impl std::error::Error for CompareError {}

/// Every set of one comparison, in the order they were run.
#[derive(Clone, Debug, PartialEq)]
pub struct CompareReport {
    /// The dimension of the sphere and cube sets.
    pub dimension: usize,
    /// Points in each of them.
    pub points: usize,
    /// The seed of every set.
    pub seed: u64,
    /// One row per set.
    pub rows: Vec<CompareRow>,
}

impl CompareReport {
    /// Whether the strategies agree on every set.
    pub fn agrees(&self) -> bool {
        self.rows.iter().all(CompareRow::agrees)
    }

    /// The names of the sets where they disagree.
    pub fn disagreements(&self) -> Vec<&'static str> {
        self.rows
            .iter()
            .filter(|r| !r.agrees())
            .map(|r| r.name)
            .collect()
    }

    /// The report as `pqh compare --json` gives it.
    pub fn to_json(&self) -> Value {
        let sets: Vec<Value> = self.rows.iter().map(row_json).collect();
        json!({
            "dimension": self.dimension,
            "points": self.points,
            "seed": self.seed,
            "tolerance": TOLERANCE,
            "release_build": !cfg!(debug_assertions),
            "agree": self.agrees(),
            "sets": sets,
        })
    }
}

fn stats_json(stats: &Stats) -> Value {
    json!({
        "points_processed": stats.points_processed,
        "facets_created": stats.facets_created,
        "expansions": stats.expansions,
        "elapsed_us": u64::try_from(stats.elapsed.as_micros()).unwrap_or(u64::MAX),
    })
}

fn row_json(r: &CompareRow) -> Value {
    let mut full = stats_json(&r.full_stats);
    full["signed_distance"] = json!(r.full_distance());
    let mut partial = stats_json(&r.partial_stats);
    partial["signed_distance"] = json!(r.partial);
    json!({
        "name": r.name,
        "description": r.description,
        "points": r.points,
        "origin": r.origin(),
        "origin_inside": r.origin() == "inside",
        "full": full,
        "partial": partial,
        "difference": r.difference(),
        "agree": r.agrees(),
        "speedup": {
            "time": r.time_speedup(),
            "facets_created": r.facets_speedup(),
            "points_processed": r.points_speedup(),
        },
    })
}

/// Compares the strategies on the sphere and cube sets of `points` points in dimension `D`
/// ([`point_sets`]) and, in 6-D, on the grasp wrench set too ([`wrench_set`]).
///
/// ```
/// use pqhull_cli::bench::compare::compare_sets;
/// let report = compare_sets::<3>(200, 1)?;
/// assert_eq!(report.rows.len(), 2);
/// assert!(report.agrees());
/// assert_eq!(report.to_json()["sets"][0]["name"], "sphere");
/// # Ok::<(), pqhull_cli::bench::compare::CompareError>(())
/// ```
///
/// # Errors
/// [`CompareError`] naming the first set that admits no hull.
pub fn compare_sets<const D: usize>(
    points: usize,
    seed: u64,
) -> Result<CompareReport, CompareError> {
    let run = |set: PointSet<D>| {
        compare(set.name, set.description, &set.points).map_err(|error| CompareError {
            set: set.name,
            error,
        })
    };
    let mut rows = point_sets::<D>(points, seed)
        .into_iter()
        .map(run)
        .collect::<Result<Vec<_>, _>>()?;
    if D == 6 {
        let set = wrench_set(seed);
        rows.push(
            compare(set.name, set.description, &set.points).map_err(|error| CompareError {
                set: set.name,
                error,
            })?,
        );
    }
    Ok(CompareReport {
        dimension: D,
        points,
        seed,
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn six_dimensions_add_the_wrench_set() {
        let report = compare_sets::<6>(64, 3).unwrap();
        let names: Vec<&str> = report.rows.iter().map(|r| r.name).collect();
        assert_eq!(names, ["sphere", "cube", "wrenches"]);
        assert!(report.agrees(), "{:?}", report.disagreements());
        let json = report.to_json();
        assert_eq!(json["dimension"], 6);
        assert_eq!(json["sets"][2]["points"], 32);
    }

    #[test]
    fn outside_agrees_only_when_both_say_so() {
        let points = [[1.0, 1.0], [2.0, 1.0], [1.0, 2.0]];
        let row = compare("offset", "a triangle away from the origin".into(), &points).unwrap();
        assert_eq!(row.origin(), "outside");
        assert_eq!(row.difference(), None);
        assert!(row.agrees());
        let wrong = CompareRow {
            partial: 0.5,
            ..row
        };
        assert!(!wrong.agrees());
        let flat = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        assert!(compare("flat", String::new(), &flat).is_err());
    }
}
