//! The names of what is computed ([`Metric`]) and how ([`Method`]): one vocabulary for the
//! evaluators, the planner, `pqh` and the Python package, read by [`FromStr`] and written by
//! [`Display`](fmt::Display).

use std::fmt;
use std::str::FromStr;

/// A grasp-quality metric: the one vocabulary of the evaluator, the planner, `pqh` and Python.
///
/// [`Evaluator`](crate::grasp::Evaluator) computes every one of them and gives every one the same
/// result, an [`Evaluation`](crate::grasp::Evaluation), so a planner ranks grasps by any metric
/// through one call.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[non_exhaustive]
pub enum Metric {
    /// Ferrari–Canny Q1 over the union of the contact wrenches.
    #[default]
    Q1,
    /// Ferrari–Canny Q∞ over the Minkowski sum of the contacts' wrench sets.
    QInf {
        /// GraspIt!'s variant: the zero wrench joins every contact's set.
        with_zero_wrench: bool,
    },
    /// The object-wrench-space metric Q_OWS: needs the object's
    /// [`ObjectWrenchSpace`](crate::grasp::ows::ObjectWrenchSpace), given to
    /// [`Evaluator::new`](crate::grasp::Evaluator::new).
    Ows,
    /// Wrench resistance: the largest t such that the grasp resists `−t·wrench` (Q_OWS with
    /// this one disturbance).
    Resist {
        /// The wrench, in the grasp's torque units (torque divided by the torque scale).
        wrench: [f64; 6],
    },
    /// The volume of the grasp wrench space (always from the full hull: a volume needs every
    /// facet).
    Volume,
    /// The smallest singular value of the grasp matrix
    /// ([`grasp_matrix`](crate::grasp::metrics::grasp_matrix)).
    SigmaMin,
    /// The isotropy index σ_min / σ_max of the grasp matrix (0 when σ_max is 0).
    Isotropy,
    /// Q1 of the true circular friction cones, bracketed: the k-edge pyramids inscribed in the
    /// cones give a lower bound, those circumscribed about them (rim scaled by 1/cos(π/k)) an
    /// upper bound, both by the method's hulls
    /// ([`Evaluation::bracket`](crate::grasp::Evaluation::bracket); the value is the inscribed
    /// pyramids' Q1, as [`Metric::Q1`]).
    ConeBracket,
}

impl Metric {
    /// The name `pqh` uses for it (`q1`, `qinf`, `qinf0` with the zero wrench, `ows`, `resist`,
    /// `volume`, `sigma-min`, `isotropy`).
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
            Metric::Resist { .. } => "resist",
            Metric::Volume => "volume",
            Metric::SigmaMin => "sigma-min",
            Metric::Isotropy => "isotropy",
            Metric::ConeBracket => "cone-bracket",
        }
    }
}

impl Metric {
    /// The names [`FromStr`] reads: every metric without a parameter (`resist` needs its
    /// wrench: build [`Metric::Resist`] directly).
    pub const NAMES: [&'static str; 8] = [
        "q1",
        "qinf",
        "qinf0",
        "ows",
        "volume",
        "sigma-min",
        "isotropy",
        "cone-bracket",
    ];
}

/// `"qinf0"` is Q∞ with the zero wrench in every contact's set.
///
/// ```
/// use pqhull::grasp::quality::Metric;
/// assert_eq!("qinf0".parse(), Ok(Metric::QInf { with_zero_wrench: true }));
/// assert_eq!(Metric::SigmaMin.to_string(), "sigma-min");
/// let err = "resist".parse::<Metric>().unwrap_err();
/// assert!(err.to_string().contains("wrench"));
/// ```
impl FromStr for Metric {
    type Err = NameError;

    fn from_str(name: &str) -> Result<Self, NameError> {
        Ok(match name {
            "q1" => Metric::Q1,
            "qinf" => Metric::QInf {
                with_zero_wrench: false,
            },
            "qinf0" => Metric::QInf {
                with_zero_wrench: true,
            },
            "ows" => Metric::Ows,
            "volume" => Metric::Volume,
            "sigma-min" => Metric::SigmaMin,
            "isotropy" => Metric::Isotropy,
            "cone-bracket" => Metric::ConeBracket,
            "resist" => return Err(NameError::NeedsWrench),
            _ => return Err(NameError::unknown("metric", name, &Metric::NAMES)),
        })
    }
}

impl fmt::Display for Metric {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A name [`Metric`] or [`Method`] does not read.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum NameError {
    /// Not a name of the vocabulary.
    Unknown {
        /// `"metric"` or `"method"`.
        kind: &'static str,
        /// The name given.
        name: String,
        /// The names accepted.
        expected: &'static [&'static str],
    },
    /// `resist`: wrench resistance needs the wrench to resist ([`Metric::Resist`]).
    NeedsWrench,
}

impl NameError {
    fn unknown(kind: &'static str, name: &str, expected: &'static [&'static str]) -> Self {
        NameError::Unknown {
            kind,
            name: name.to_string(),
            expected,
        }
    }
}

impl fmt::Display for NameError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NameError::Unknown {
                kind,
                name,
                expected,
            } => write!(f, "unknown {kind} {name:?}: one of {}", expected.join(", ")),
            NameError::NeedsWrench => {
                f.write_str("metric resist needs the wrench to resist (fx, fy, fz, tx, ty, tz)")
            }
        }
    }
}

impl std::error::Error for NameError {}

/// How a metric is computed. Every metric takes [`Partial`](Method::Partial) (the default) and
/// [`Full`](Method::Full) (for the volume and the grasp-matrix metrics, the method computes only
/// the force-closure verdict, Q1's: see [`Evaluator`](crate::grasp::Evaluator)); the others
/// belong to some metrics only, and the rest give
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
    /// Q1, Q∞ and the cone bracket (and the verdicts of the volume and grasp-matrix metrics)
    /// only: the full hull
    /// by Qhull, for comparison. Needs the crate's `qhull` feature, else
    /// [`QualityError::QhullUnavailable`](super::QualityError::QhullUnavailable).
    Qhull,
    /// Q_OWS and wrench resistance only: the partial hull with every disturbance assigned to the
    /// facet its ray leaves through, as the seed paper's Algorithm 2 is published
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

    /// Every method, in the order `pqh` lists them.
    pub const ALL: [Method; 5] = [
        Method::Partial,
        Method::Full,
        Method::Qhull,
        Method::PartialRays,
        Method::Ellipsoid,
    ];

    /// Their names, in the same order ([`FromStr`] also reads `brute` for
    /// [`Full`](Method::Full), the seed paper's name for Q_OWS by every facet).
    pub const NAMES: [&'static str; 5] = ["partial", "full", "qhull", "partial-rays", "ellipsoid"];

    /// Whether `metric` can be computed this way.
    pub fn supports(self, metric: Metric) -> bool {
        match self {
            Method::Partial | Method::Full => true,
            Method::Qhull => !matches!(metric, Metric::Ows | Metric::Resist { .. }),
            Method::PartialRays => matches!(metric, Metric::Ows | Metric::Resist { .. }),
            // No ellipsoid encloses a single disturbance: not for Resist.
            Method::Ellipsoid => metric == Metric::Ows,
        }
    }
}

/// ```
/// use pqhull::grasp::quality::Method;
/// assert_eq!("partial-rays".parse(), Ok(Method::PartialRays));
/// assert_eq!("brute".parse(), Ok(Method::Full));
/// assert_eq!(Method::Ellipsoid.to_string(), "ellipsoid");
/// assert!("fast".parse::<Method>().unwrap_err().to_string().contains("partial, full"));
/// ```
impl FromStr for Method {
    type Err = NameError;

    fn from_str(name: &str) -> Result<Self, NameError> {
        if name == "brute" {
            return Ok(Method::Full);
        }
        Method::ALL
            .into_iter()
            .find(|m| m.name() == name)
            .ok_or_else(|| NameError::unknown("method", name, &Method::NAMES))
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_reads_back() {
        for method in Method::ALL {
            assert_eq!(method.to_string().parse(), Ok(method));
        }
        assert_eq!(Method::ALL.map(Method::name), Method::NAMES);
        for name in Metric::NAMES {
            let metric: Metric = name.parse().unwrap();
            assert_eq!(metric.to_string(), name);
        }
        let resist = Metric::Resist { wrench: [1.0; 6] };
        assert_eq!(
            resist.to_string().parse::<Metric>(),
            Err(NameError::NeedsWrench)
        );
    }
}
