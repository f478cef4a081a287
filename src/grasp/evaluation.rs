//! The one result type of the grasp metrics: [`Evaluation`].

use super::quality::{Method, Metric};
use crate::hull::Stats;

/// Up to seven wrenches decide a value: a facet's six, or the points spanning a nearest face.
pub(in crate::grasp) const MAX_DECIDING: usize = 7;

/// An interval proven to hold an exact value that no finite computation gives (see
/// [`Evaluation::bracket`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bracket {
    /// The lower bound.
    pub low: f64,
    /// The upper bound (≥ `low`).
    pub high: f64,
}

impl Bracket {
    /// Whether `x` lies in the bracket, ends included.
    pub fn contains(&self, x: f64) -> bool {
        self.low <= x && x <= self.high
    }
}

/// One grasp's evaluation by any [`Metric`] and [`Method`]: what
/// [`Evaluator::evaluate`](super::Evaluator::evaluate), [`evaluate_batch`](super::evaluate_batch)
/// and the one-call conveniences ([`q1`](super::quality::q1), [`q_inf`](super::quality::q_inf),
/// [`q1_of_wrenches`](super::quality::q1_of_wrenches),
/// [`ows_of_wrenches`](super::ows::ows_of_wrenches)) return.
///
/// ```
/// use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric};
///
/// let contacts = [[1.0, 0.1, 0.0], [-1.0, 0.0, 0.2], [0.1, 1.0, 0.0], [0.0, -1.0, -0.1]]
///     .map(|p| Contact::try_new(p, p.map(|x| -x), None).unwrap());
/// let grasp = Grasp::builder(contacts.to_vec(), FrictionModel::try_new(0.5, 8)?).build()?;
/// let q1 = Evaluator::new(Metric::Q1, Method::Partial, None)?.evaluate(&grasp)?;
/// assert!(q1.force_closure && q1.value.unwrap() > 0.0);
/// assert_eq!(q1.deciding_wrenches().len(), 6); // the nearest facet's vertices
/// let cones = Evaluator::new(Metric::ConeBracket, Method::Partial, None)?.evaluate(&grasp)?;
/// let bracket = cones.bracket.unwrap(); // Q1 of the circular cones lies within
/// assert!(bracket.low <= q1.value.unwrap() && q1.value.unwrap() <= bracket.high);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Evaluation {
    /// The metric evaluated.
    pub metric: Metric,
    /// The method used.
    pub method: Method,
    /// Whether the grasp is force closure. Q1 and Q∞ decide it on their certified value under
    /// the band [`FORCE_CLOSURE_EPSILON`](super::quality::FORCE_CLOSURE_EPSILON) · `scale`;
    /// Q_OWS and wrench resistance exactly (the origin strictly inside the grasp wrench space);
    /// the volume, the grasp-matrix metrics and the cone bracket by Q1 beside them, by the
    /// evaluator's method.
    pub force_closure: bool,
    /// The metric's value on the caller's wrenches (Q1 and Q∞: within `1e−12` relative, or
    /// `1e−14 · scale` near zero, of the exact value; the ellipsoid method's Q_OWS is an
    /// approximation by design). `None` only where the metric is undefined: Q_OWS and wrench
    /// resistance of a grasp that is not force closure (no multiple of the disturbances is
    /// resisted, not even zero times them).
    pub value: Option<f64>,
    /// The wrench scale the force-closure band is relative to: the largest norm of the raw
    /// wrenches (Q1, and the verdict of the volume, grasp-matrix and cone-bracket metrics), or
    /// the sum over contacts of each contact's largest (Q∞). `None` for Q_OWS and wrench
    /// resistance, whose verdict is exact, with no band.
    pub scale: Option<f64>,
    /// For [`Metric::ConeBracket`]: the interval proven to hold Q1 of the true circular friction
    /// cones (from the pyramids inscribed in them and those circumscribed about them, each
    /// widened by its value's accuracy); `value` is then the inscribed pyramids' Q1. `None` for
    /// every other metric, whose value is itself the answer.
    pub bracket: Option<Bracket>,
    /// Q_OWS and wrench resistance by an exact method: the index of the disturbance whose
    /// inflation decides the value (`None` otherwise).
    pub deciding_disturbance: Option<usize>,
    deciding: [[f64; 6]; MAX_DECIDING],
    deciding_len: usize,
    tied: bool,
    /// Work done (for the full methods: the whole hull; for metrics built on two hulls, both).
    pub stats: Stats,
}

impl Evaluation {
    /// An evaluation with no deciding wrench, no bracket and no tie.
    pub(in crate::grasp) fn new(
        metric: Metric,
        method: Method,
        force_closure: bool,
        value: Option<f64>,
        stats: Stats,
    ) -> Self {
        Evaluation {
            metric,
            method,
            force_closure,
            value,
            scale: None,
            bracket: None,
            deciding_disturbance: None,
            deciding: [[0.0; 6]; MAX_DECIDING],
            deciding_len: 0,
            tied: false,
            stats,
        }
    }

    /// This evaluation with `deciding` as its deciding wrenches (the first [`MAX_DECIDING`]).
    pub(in crate::grasp) fn with_deciding(
        mut self,
        deciding: impl IntoIterator<Item = [f64; 6]>,
    ) -> Self {
        self.deciding_len = 0;
        for w in deciding.into_iter().take(MAX_DECIDING) {
            self.deciding[self.deciding_len] = w;
            self.deciding_len += 1;
        }
        self
    }

    /// This evaluation, flagged tied or not (see [`tied`](Self::tied)).
    pub(in crate::grasp) fn with_tie(mut self, tied: bool) -> Self {
        self.tied = tied;
        self
    }

    /// The wrenches that decide the value (Q1 and Q∞, and the cone bracket's inscribed Q1): the
    /// vertices of the nearest facet when force closure; otherwise the wrenches spanning the face
    /// that holds the hull's point nearest the origin. Empty for the other metrics.
    pub fn deciding_wrenches(&self) -> &[[f64; 6]] {
        &self.deciding[..self.deciding_len]
    }

    /// Whether another facet, on another plane, decides the value too (within 1e−9 of the
    /// scale, plus the snapping's share on a snapped hull): the value is then a minimum of two
    /// smooth functions of the grasp, not differentiable (the gradients say so). Seen on the hull
    /// the value came from, partial or full (a partial hull's tie is the full hull's); a near tie
    /// with a facet of a partial hull that would still grow is flagged too. Always `false` when
    /// the origin is not inside (the nearest point of a convex set is unique), for
    /// [`Method::PartialRays`] (kept as published), the ellipsoid, and the metrics that are not
    /// a distance or an inflation factor.
    pub fn tied(&self) -> bool {
        self.tied
    }
}
