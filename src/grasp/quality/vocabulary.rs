//! The names of what is computed ([`Metric`]) and how ([`Method`]): one vocabulary for the
//! evaluators, the planner and `pqh`.

/// A grasp-quality metric: the one vocabulary of the evaluators, the planner and `pqh`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Metric {
    /// Ferrari–Canny Q1 over the union of the contact wrenches ([`Evaluator`](super::Evaluator)).
    #[default]
    Q1,
    /// Ferrari–Canny Q∞ over the Minkowski sum of the contacts' wrench sets ([`Evaluator`](super::Evaluator)).
    QInf {
        /// GraspIt!'s variant: the zero wrench joins every contact's set.
        with_zero_wrench: bool,
    },
    /// The object-wrench-space metric Q_OWS: needs the object's
    /// [`ObjectWrenchSpace`](crate::grasp::ows::ObjectWrenchSpace), so it is evaluated by
    /// [`OwsEvaluator`](crate::grasp::ows::OwsEvaluator), not by [`Evaluator`](super::Evaluator).
    Ows,
}

impl Metric {
    /// The name `pqh` uses for it (`q1`, `qinf`, `qinf0` with the zero wrench, `ows`).
    pub fn name(self) -> &'static str {
        match self {
            Metric::Q1 => "q1",
            Metric::QInf {
                with_zero_wrench: false,
            } => "qinf",
            Metric::QInf {
                with_zero_wrench: true,
            } => "qinf0",
            Metric::Ows => "ows",
        }
    }
}

/// How a metric is computed. Every metric takes [`Partial`](Method::Partial) (the default) and
/// [`Full`](Method::Full); the others belong to some metrics only, and the rest give
/// [`QualityError::UnsupportedMethod`](super::QualityError::UnsupportedMethod).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Method {
    /// The partial hull (Q1, Q∞: `ClosestToOrigin`, PQHGWS; Q_OWS: `OwsInflation`, PQHOWS):
    /// stops as soon as the answer is certain. Exact.
    #[default]
    Partial,
    /// The full hull with this crate's engine, then the answer from all its facets (for Q_OWS,
    /// every disturbance against every facet: the seed paper's brute force). Exact, the reference.
    Full,
    /// Q1 and Q∞ only: the full hull by Qhull, for comparison. Needs the crate's `qhull` feature,
    /// else [`QualityError::QhullUnavailable`](super::QualityError::QhullUnavailable).
    Qhull,
    /// Q_OWS only: the partial hull with every disturbance assigned to the facet its ray leaves
    /// through, as the seed paper's Algorithm 2 is published
    /// ([`OwsInflation::with_rays`](crate::strategy::OwsInflation::with_rays)). Exact, slower
    /// on large disturbance sets; kept to compare with.
    PartialRays,
    /// Q_OWS only: Borst et al.'s approximation. The wrench space is mapped so that the
    /// disturbances' enclosing ellipsoid becomes the unit ball, then Q1 of the mapped grasp is
    /// taken. Never larger than the exact value, and not exact.
    Ellipsoid,
}

impl Method {
    /// The name `pqh` uses for it.
    pub fn name(self) -> &'static str {
        match self {
            Method::Partial => "partial",
            Method::Full => "full",
            Method::Qhull => "qhull",
            Method::PartialRays => "partial-rays",
            Method::Ellipsoid => "ellipsoid",
        }
    }

    /// Whether `metric` can be computed this way.
    pub fn supports(self, metric: Metric) -> bool {
        match self {
            Method::Partial | Method::Full => true,
            Method::Qhull => metric != Metric::Ows,
            Method::PartialRays | Method::Ellipsoid => metric == Metric::Ows,
        }
    }
}
