//! [`GraspError`]: what is wrong with a contact, a friction model or a grasp.

use std::fmt;

/// Why a [`Contact`](super::Contact), [`FrictionModel`](super::FrictionModel) or
/// [`Grasp`](super::Grasp) could not be built.
///
/// Contact variants carry `contact: Option<usize>`: `None` when the contact was built on its own
/// with [`Contact::try_new`](super::Contact::try_new), `Some(i)` once the caller (a parser, a grasp
/// generator) has attached the index with [`GraspError::at_contact`].
///
/// Non-exhaustive: more limits may be added.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum GraspError {
    /// A contact position has a NaN or infinite coordinate.
    NonFinitePosition {
        /// Index of the contact, if known.
        contact: Option<usize>,
    },
    /// A contact normal has a NaN or infinite coordinate.
    NonFiniteNormal {
        /// Index of the contact, if known.
        contact: Option<usize>,
    },
    /// A contact normal is the zero vector, so it has no direction.
    ZeroNormal {
        /// Index of the contact, if known.
        contact: Option<usize>,
    },
    /// A contact tangent has a NaN or infinite coordinate.
    NonFiniteTangent {
        /// Index of the contact, if known.
        contact: Option<usize>,
    },
    /// A contact tangent is the zero vector, so it has no direction.
    ZeroTangent {
        /// Index of the contact, if known.
        contact: Option<usize>,
    },
    /// A contact tangent is parallel (or nearly so, see
    /// [`TANGENT_PARALLEL_TOLERANCE`](super::TANGENT_PARALLEL_TOLERANCE)) to the normal, so it
    /// fixes no direction in the tangent plane.
    TangentParallelToNormal {
        /// Index of the contact, if known.
        contact: Option<usize>,
    },
    /// A soft contact's torsion γ is negative, NaN or infinite.
    InvalidTorsion {
        /// Index of the contact, if known.
        contact: Option<usize>,
        /// The torsion given.
        torsion: f64,
    },
    /// The friction coefficient μ is negative, NaN or infinite.
    InvalidFriction {
        /// The coefficient given.
        friction: f64,
    },
    /// Fewer than 3 friction-cone edges: the pyramid would not be a cone.
    TooFewConeEdges {
        /// The number of edges given.
        cone_edges: usize,
    },
    /// More friction-cone edges than [`MAX_CONE_EDGES`](super::MAX_CONE_EDGES).
    TooManyConeEdges {
        /// The number of edges given.
        cone_edges: usize,
        /// The limit, [`MAX_CONE_EDGES`](super::MAX_CONE_EDGES).
        max: usize,
    },
    /// A grasp needs at least one contact.
    NoContacts,
    /// More contacts than [`MAX_CONTACTS`](super::MAX_CONTACTS).
    TooManyContacts {
        /// The number of contacts given.
        contacts: usize,
        /// The limit, [`MAX_CONTACTS`](super::MAX_CONTACTS).
        max: usize,
    },
    /// The torque reference point has a NaN or infinite coordinate.
    NonFiniteTorqueReference,
    /// The torque scale ρ is not a finite number greater than zero.
    InvalidTorqueScale {
        /// The scale given.
        torque_scale: f64,
    },
}

impl GraspError {
    /// The same error, naming contact `index` (a no-op for errors that are not about a contact).
    ///
    /// ```
    /// use pqhull::grasp::{Contact, GraspError};
    ///
    /// let err = Contact::try_new([0.0; 3], [0.0; 3], None).unwrap_err().at_contact(2);
    /// assert_eq!(err, GraspError::ZeroNormal { contact: Some(2) });
    /// assert_eq!(err.to_string(), "contact 2: the normal is the zero vector");
    /// ```
    #[must_use]
    pub fn at_contact(mut self, index: usize) -> Self {
        if let Some(slot) = self.contact_slot() {
            *slot = Some(index);
        }
        self
    }

    /// The index of the contact this error is about, when it is about a contact and the index is
    /// known.
    pub fn contact(&self) -> Option<usize> {
        match *self {
            GraspError::NonFinitePosition { contact }
            | GraspError::NonFiniteNormal { contact }
            | GraspError::ZeroNormal { contact }
            | GraspError::NonFiniteTangent { contact }
            | GraspError::ZeroTangent { contact }
            | GraspError::TangentParallelToNormal { contact }
            | GraspError::InvalidTorsion { contact, .. } => contact,
            _ => None,
        }
    }

    /// Whether this error is about one contact (whose index may or may not be known).
    pub fn is_about_contact(&self) -> bool {
        matches!(
            self,
            GraspError::NonFinitePosition { .. }
                | GraspError::NonFiniteNormal { .. }
                | GraspError::ZeroNormal { .. }
                | GraspError::NonFiniteTangent { .. }
                | GraspError::ZeroTangent { .. }
                | GraspError::TangentParallelToNormal { .. }
                | GraspError::InvalidTorsion { .. }
        )
    }

    fn contact_slot(&mut self) -> Option<&mut Option<usize>> {
        match self {
            GraspError::NonFinitePosition { contact }
            | GraspError::NonFiniteNormal { contact }
            | GraspError::ZeroNormal { contact }
            | GraspError::NonFiniteTangent { contact }
            | GraspError::ZeroTangent { contact }
            | GraspError::TangentParallelToNormal { contact }
            | GraspError::InvalidTorsion { contact, .. } => Some(contact),
            _ => None,
        }
    }
}

impl fmt::Display for GraspError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_about_contact() {
            match self.contact() {
                Some(i) => write!(f, "contact {i}: ")?,
                None => write!(f, "contact: ")?,
            }
        }
        match *self {
            GraspError::NonFinitePosition { .. } => {
                write!(f, "the position has a NaN or infinite coordinate")
            }
            GraspError::NonFiniteNormal { .. } => {
                write!(f, "the normal has a NaN or infinite coordinate")
            }
            GraspError::ZeroNormal { .. } => write!(f, "the normal is the zero vector"),
            GraspError::NonFiniteTangent { .. } => {
                write!(f, "the tangent has a NaN or infinite coordinate")
            }
            GraspError::ZeroTangent { .. } => write!(f, "the tangent is the zero vector"),
            GraspError::TangentParallelToNormal { .. } => {
                write!(f, "the tangent is parallel to the normal")
            }
            GraspError::InvalidTorsion { torsion, .. } => write!(
                f,
                "torsion {torsion} is invalid (must be finite and at least 0)"
            ),
            GraspError::InvalidFriction { friction } => write!(
                f,
                "friction coefficient {friction} is invalid (must be finite and at least 0)"
            ),
            GraspError::TooFewConeEdges { cone_edges } => write!(
                f,
                "{cone_edges} friction-cone edges are too few (at least 3 are needed)"
            ),
            GraspError::TooManyConeEdges { cone_edges, max } => write!(
                f,
                "{cone_edges} friction-cone edges are too many (at most {max}: more change no \
                 answer and would only cost memory)"
            ),
            GraspError::NoContacts => write!(f, "a grasp needs at least one contact"),
            GraspError::TooManyContacts { contacts, max } => write!(
                f,
                "{contacts} contacts are too many for one grasp (at most {max})"
            ),
            GraspError::NonFiniteTorqueReference => {
                write!(
                    f,
                    "the torque reference point has a NaN or infinite coordinate"
                )
            }
            GraspError::InvalidTorqueScale { torque_scale } => write!(
                f,
                "torque scale {torque_scale} is invalid (must be finite and greater than 0)"
            ),
        }
    }
}

impl std::error::Error for GraspError {}

#[cfg(test)]
mod tests {
    use super::*;

    fn all() -> Vec<GraspError> {
        vec![
            GraspError::NonFinitePosition { contact: None },
            GraspError::NonFiniteNormal { contact: None },
            GraspError::ZeroNormal { contact: None },
            GraspError::NonFiniteTangent { contact: None },
            GraspError::ZeroTangent { contact: None },
            GraspError::TangentParallelToNormal { contact: None },
            GraspError::InvalidFriction { friction: -0.5 },
            GraspError::TooFewConeEdges { cone_edges: 2 },
            GraspError::NoContacts,
            GraspError::NonFiniteTorqueReference,
            GraspError::InvalidTorqueScale { torque_scale: 0.0 },
            GraspError::TooManyConeEdges {
                cone_edges: 5000,
                max: 1024,
            },
            GraspError::TooManyContacts {
                contacts: 300,
                max: 256,
            },
        ]
    }

    #[test]
    fn display_names_the_problem_and_the_contact() {
        for e in all() {
            let plain = e.to_string();
            let indexed = e.clone().at_contact(7);
            if e.is_about_contact() {
                assert!(plain.starts_with("contact: "), "{plain}");
                assert_eq!(e.contact(), None);
                assert_eq!(indexed.contact(), Some(7));
                assert!(indexed.to_string().starts_with("contact 7: "), "{indexed}");
            } else {
                assert_eq!(indexed, e, "at_contact must not change {e:?}");
                assert!(!plain.contains("contact 7"));
            }
            let boxed: Box<dyn std::error::Error> = Box::new(e);
            assert!(!boxed.to_string().is_empty());
        }
        assert!(all()[6].to_string().contains("-0.5"));
        assert!(all()[7].to_string().contains('2'));
        assert!(all()[11].to_string().contains("5000") && all()[11].to_string().contains("1024"));
        assert!(all()[12].to_string().contains("300") && all()[12].to_string().contains("256"));
        assert_eq!(
            GraspError::ZeroTangent { contact: Some(3) }.to_string(),
            "contact 3: the tangent is the zero vector"
        );
    }
}
