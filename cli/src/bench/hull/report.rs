//! The suite's report: one row per (case, timed call), its table and its JSON ([`super`]).

use super::{Case, Preset, Timed};
use crate::bench::stats::ratio;
use serde_json::{Value, json};

/// Qhull's figures of one row.
#[derive(Clone, Debug, PartialEq)]
pub struct QhullColumns {
    /// Best wall time of `qhull_baseline::qhull_facet_count`, ms.
    pub ms: f64,
    /// Vertices of Qhull's hull (`qhull_baseline::qhull_stats`, untimed).
    pub vertices: usize,
    /// Facets of Qhull's triangulated hull.
    pub facets: usize,
}

/// pqhull's figures of one row.
#[derive(Clone, Debug, PartialEq)]
pub struct PqhullColumns {
    /// Best wall time of the timed call ([`Timed`]), ms.
    pub ms: f64,
    /// Vertices of [`Hull::try_new`](pqhull::Hull::try_new)'s hull of the row's points (untimed; for the metric rows,
    /// the hull of the same points as the `hull` row).
    pub vertices: usize,
    /// Its facets.
    pub facets: usize,
    /// [`Hull::check`](pqhull::Hull::check) of that hull, run once, untimed: `Ok`, or the violation's message.
    pub check: Result<(), String>,
    /// Wall time of that check, ms.
    pub check_ms: f64,
    /// The metric of a metric row (the volume, or Q∞); `None` for a `hull` row.
    pub value: Option<f64>,
}

/// One timed call on one case's points.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseRow {
    /// The case.
    pub case: Case,
    /// The call timed for pqhull.
    pub timed: Timed,
    /// Number of points.
    pub points: usize,
    /// For the grasp workloads, whether the chosen grasp's Q1 is force closure (false: none of
    /// [`GRASP_CANDIDATES`](super::GRASP_CANDIDATES) is, the first was taken); `None` otherwise. A Q∞ row's own verdict
    /// is the sign of its [`PqhullColumns::value`].
    pub force_closure: Option<bool>,
    /// pqhull's figures, or its error.
    pub pqhull: Result<PqhullColumns, String>,
    /// Qhull's figures, or its error; `None` without the `qhull` feature.
    pub qhull: Option<Result<QhullColumns, String>>,
}

impl CaseRow {
    /// The row's label: the case's name, with `/volume` or `/qinf-full` for a metric row
    /// (`/hull` too when the case has several rows).
    pub fn label(&self) -> String {
        if self.case.timed().len() > 1 {
            format!("{}/{}", self.case.name(), self.timed.name())
        } else {
            self.case.name()
        }
    }

    /// Qhull's time over pqhull's, when both ran.
    pub fn ratio(&self) -> Option<f64> {
        match (&self.pqhull, &self.qhull) {
            (Ok(p), Some(Ok(q))) => Some(ratio(q.ms, p.ms)),
            _ => None,
        }
    }

    /// Whether pqhull's hull passed [`Hull::check`](pqhull::Hull::check).
    pub fn check_passed(&self) -> bool {
        self.pqhull.as_ref().is_ok_and(|p| p.check.is_ok())
    }

    /// The row as `pqh bench hull --json` gives it.
    pub fn to_json(&self) -> Value {
        let finite = |x: f64| x.is_finite().then_some(x);
        let mut row = json!({
            "case": self.label(),
            "family": self.case.family(),
            "timed": self.timed.name(),
            "dimension": self.case.dimension,
            "points": self.points,
            "random": self.case.is_random(),
            "force_closure": self.force_closure,
            "ratio": self.ratio().and_then(finite),
        });
        match &self.pqhull {
            Ok(p) => {
                row["pqhull_ms"] = json!(finite(p.ms));
                row["pqhull_vertices"] = json!(p.vertices);
                row["pqhull_facets"] = json!(p.facets);
                row["check"] = json!(p.check.is_ok());
                row["check_error"] = json!(p.check.as_ref().err());
                row["check_ms"] = json!(finite(p.check_ms));
                row["value"] = json!(p.value.and_then(finite));
            }
            Err(e) => {
                row["pqhull_ms"] = Value::Null;
                row["pqhull_error"] = json!(e);
                row["check"] = json!(false);
            }
        }
        match &self.qhull {
            Some(Ok(q)) => {
                row["qhull_ms"] = json!(finite(q.ms));
                row["qhull_vertices"] = json!(q.vertices);
                row["qhull_facets"] = json!(q.facets);
            }
            Some(Err(e)) => {
                row["qhull_ms"] = Value::Null;
                row["qhull_error"] = json!(e);
            }
            None => {}
        }
        row
    }
}

/// The whole suite.
#[derive(Clone, Debug, PartialEq)]
pub struct HullBenchReport {
    /// The sizes.
    pub preset: Preset,
    /// Timed runs per call.
    pub repeats: usize,
    /// The inputs' seed.
    pub seed: u64,
    /// Whether Qhull was measured (the crate's `qhull` feature).
    pub qhull_available: bool,
    /// One row per (case, timed call), in order.
    pub rows: Vec<CaseRow>,
}

impl HullBenchReport {
    /// The smallest Qhull/pqhull ratio over the rows `keep` selects, with its row.
    fn min_ratio_where(&self, keep: impl Fn(&CaseRow) -> bool) -> Option<(f64, &CaseRow)> {
        self.rows
            .iter()
            .filter(|r| keep(r))
            .filter_map(|r| r.ratio().map(|x| (x, r)))
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }

    /// The smallest Qhull/pqhull ratio over all rows, with its row (`None` without Qhull).
    pub fn min_ratio(&self) -> Option<(f64, &CaseRow)> {
        self.min_ratio_where(|_| true)
    }

    /// The smallest ratio over the random cases (`cube`, `sphere`: [`Case::is_random`]).
    pub fn min_random_ratio(&self) -> Option<(f64, &CaseRow)> {
        self.min_ratio_where(|r| r.case.is_random())
    }

    /// Rows where pqhull failed or its hull failed [`Hull::check`](pqhull::Hull::check).
    pub fn failures(&self) -> usize {
        self.rows.iter().filter(|r| !r.check_passed()).count()
    }

    /// The report as `pqh bench hull --json` gives it.
    pub fn to_json(&self) -> Value {
        let summary = |m: Option<(f64, &CaseRow)>| match m {
            Some((x, row)) if x.is_finite() => json!({ "ratio": x, "case": row.label(),
                "dimension": row.case.dimension }),
            _ => Value::Null,
        };
        json!({
            "benchmark": "hull",
            "preset": self.preset.name(),
            "repeats": self.repeats,
            "seed": self.seed,
            "qhull": self.qhull_available,
            "failures": self.failures(),
            "min_ratio": summary(self.min_ratio()),
            "min_random_ratio": summary(self.min_random_ratio()),
            "rows": self.rows.iter().map(CaseRow::to_json).collect::<Vec<_>>(),
        })
    }
}
