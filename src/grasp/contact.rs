//! [`Contact`]: where a finger touches the object and which way it pushes.

use super::GraspError;
use crate::geometry::vector::{cross, dot, is_finite, normalize, scale, sub};

/// A given tangent is rejected as parallel to the normal when the sine of the angle between them
/// is below this value (its component orthogonal to the normal is less than this fraction of its
/// length): the tangent direction would then be mostly rounding error.
pub const TANGENT_PARALLEL_TOLERANCE: f64 = 1e-6;

/// One contact of a grasp: position p, unit **inward** normal n (the direction the finger pushes)
/// and unit tangent t orthogonal to n, from which the friction-cone edges are measured (see
/// [`FrictionModel`](super::FrictionModel) and the [module docs](super)).
///
/// Built with [`Contact::try_new`], which validates and normalises its input, so every `Contact`
/// satisfies: all coordinates finite, |n| = 1, |t| = 1 and t ⟂ n (to rounding).
///
/// A contact is a hard finger unless given a torsion ([`Contact::with_torsion`]): a soft finger,
/// which also resists torsion about its normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    position: [f64; 3],
    normal: [f64; 3],
    tangent: [f64; 3],
    tangent_given: bool,
    /// The given tangent, normalised, before it was made orthogonal to the normal (zero when
    /// none was given): what the tangent is re-derived from when the normal moves (the
    /// metrics' gradients).
    tangent_input: [f64; 3],
    torsion: f64,
}

impl Contact {
    /// A contact at `position` pushing along `normal`, with cone edges measured from `tangent`.
    ///
    /// * `normal` is the **inward** normal — the direction the finger pushes into the object. Any
    ///   finite non-zero vector is accepted and normalised to unit length.
    /// * `tangent`, when given, may be any finite non-zero vector not parallel to the normal: its
    ///   component along the normal is removed (Gram–Schmidt) and the result normalised to unit
    ///   length.
    /// * When `tangent` is `None`, the default is deterministic: with e_a the coordinate axis
    ///   least aligned with the normal (the smallest |n_a|, the lowest index on ties),
    ///   t = (n × e_a) / |n × e_a|. See [`Contact::default_tangent`].
    ///
    /// # Errors
    ///
    /// Checked in this order, the first failure is returned (with `contact: None`; attach the
    /// index with [`GraspError::at_contact`]):
    /// [`GraspError::NonFinitePosition`], [`GraspError::NonFiniteNormal`],
    /// [`GraspError::ZeroNormal`], [`GraspError::NonFiniteTangent`], [`GraspError::ZeroTangent`],
    /// [`GraspError::TangentParallelToNormal`] (sine of the angle below
    /// [`TANGENT_PARALLEL_TOLERANCE`]).
    pub fn try_new(
        position: [f64; 3],
        normal: [f64; 3],
        tangent: Option<[f64; 3]>,
    ) -> Result<Contact, GraspError> {
        if !is_finite(position) {
            return Err(GraspError::NonFinitePosition { contact: None });
        }
        if !is_finite(normal) {
            return Err(GraspError::NonFiniteNormal { contact: None });
        }
        let normal = normalize(normal).ok_or(GraspError::ZeroNormal { contact: None })?;
        let mut tangent_input = [0.0; 3];
        let (tangent, tangent_given) = match tangent {
            None => (Contact::default_tangent(normal), false),
            Some(t) => {
                if !is_finite(t) {
                    return Err(GraspError::NonFiniteTangent { contact: None });
                }
                let t = normalize(t).ok_or(GraspError::ZeroTangent { contact: None })?;
                tangent_input = t;
                // Gram–Schmidt, twice ("twice is enough") so the result is orthogonal to
                // rounding even when t is close to n.
                let r = sub(t, scale(normal, dot(t, normal)));
                let r = sub(r, scale(normal, dot(r, normal)));
                // |t| = 1, so |r| is the sine of the angle between t and n.
                if dot(r, r).sqrt() < TANGENT_PARALLEL_TOLERANCE {
                    return Err(GraspError::TangentParallelToNormal { contact: None });
                }
                let r =
                    normalize(r).ok_or(GraspError::TangentParallelToNormal { contact: None })?;
                (r, true)
            }
        };
        Ok(Contact {
            position,
            normal,
            tangent,
            tangent_given,
            tangent_input,
            torsion: 0.0,
        })
    }

    /// This contact as a soft finger with torsion γ ≥ 0, a length: the torsional friction
    /// coefficient times the contact patch's radius (the linearised soft-finger model of
    /// GraspIt! and of Ciocarlie, Lackner and Allen, "Soft finger model with adaptive contact
    /// geometry for grasping and manipulation tasks", 2007). With torsion, each friction-cone
    /// edge f_j pairs with the two torsional moments ±γ n: the contact contributes the 2k
    /// wrenches [f_j; ((p − c) × f_j ± γ n) / ρ] (see [`Grasp::wrenches`](super::Grasp::wrenches)).
    /// γ = 0 is the hard finger.
    ///
    /// ```
    /// use pqhull::grasp::Contact;
    /// let c = Contact::try_new([0.0; 3], [0.0, 0.0, 1.0], None)?.with_torsion(0.01)?;
    /// assert_eq!(c.torsion(), 0.01);
    /// assert!(Contact::try_new([0.0; 3], [0.0, 0.0, 1.0], None)?.with_torsion(-1.0).is_err());
    /// # Ok::<(), pqhull::grasp::GraspError>(())
    /// ```
    ///
    /// # Errors
    /// [`GraspError::InvalidTorsion`] for a negative, NaN or infinite γ.
    pub fn with_torsion(mut self, torsion: f64) -> Result<Contact, GraspError> {
        if !torsion.is_finite() || torsion < 0.0 {
            return Err(GraspError::InvalidTorsion {
                contact: None,
                torsion,
            });
        }
        self.torsion = torsion;
        Ok(self)
    }

    /// The torsion γ (0 for a hard finger).
    pub fn torsion(&self) -> f64 {
        self.torsion
    }

    /// Whether this is a soft finger (γ > 0).
    pub fn is_soft(&self) -> bool {
        self.torsion > 0.0
    }

    /// The tangent used when none is given, for a unit `normal`: (n × e_a) / |n × e_a| where e_a
    /// is the coordinate axis least aligned with n (the smallest |n_a|; the lowest index a on
    /// ties). It depends on n only, so it is deterministic, and it is unit and orthogonal to n.
    ///
    /// ```
    /// use pqhull::grasp::Contact;
    ///
    /// // n = e_z: the least aligned axis is e_x (tie with e_y, lowest index), e_z × e_x = e_y.
    /// assert_eq!(Contact::default_tangent([0.0, 0.0, 1.0]), [0.0, 1.0, 0.0]);
    /// ```
    pub fn default_tangent(normal: [f64; 3]) -> [f64; 3] {
        let mut a = 0;
        for i in 1..3 {
            if normal[i].abs() < normal[a].abs() {
                a = i;
            }
        }
        let mut e = [0.0; 3];
        e[a] = 1.0;
        // |n × e_a| ≥ sqrt(2/3) for a unit n, so this never divides by zero.
        normalize(cross(normal, e)).unwrap_or(e)
    }

    /// The position p, as given.
    pub fn position(&self) -> [f64; 3] {
        self.position
    }

    /// The unit inward normal n (the direction the finger pushes).
    pub fn normal(&self) -> [f64; 3] {
        self.normal
    }

    /// The unit tangent t, orthogonal to n: the given one after Gram–Schmidt, or the default.
    pub fn tangent(&self) -> [f64; 3] {
        self.tangent
    }

    /// The unit vector n × t, completing the right-handed frame (t, n × t, n).
    pub fn bitangent(&self) -> [f64; 3] {
        cross(self.normal, self.tangent)
    }

    /// Whether the tangent was given to [`Contact::try_new`] (`false`: the default was used).
    pub fn tangent_given(&self) -> bool {
        self.tangent_given
    }

    /// The given tangent, normalised but not yet orthogonalised against the normal, when one
    /// was given.
    pub(in crate::grasp) fn tangent_input(&self) -> Option<[f64; 3]> {
        self.tangent_given.then_some(self.tangent_input)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::vector::norm;

    /// A deterministic spread of unit-ish directions (a tiny LCG; no test dependency needed).
    fn directions(count: usize) -> Vec<[f64; 3]> {
        let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let mut out = vec![
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [-1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, -1.0],
            [1.0, 1.0, 1.0],
            [-1.0, 1.0, 0.0],
        ];
        while out.len() < count {
            out.push([next(), next(), next()]);
        }
        out
    }

    fn assert_unit(v: [f64; 3]) {
        assert!((norm(v) - 1.0).abs() < 1e-15, "{v:?} is not unit");
    }

    #[test]
    fn normal_is_normalised() {
        let c = Contact::try_new([1.0, 2.0, 3.0], [0.0, 0.0, 2.0], None).unwrap();
        assert_eq!(c.normal(), [0.0, 0.0, 1.0]);
        assert_eq!(c.position(), [1.0, 2.0, 3.0]);
        // Subnormal and huge normals neither underflow nor overflow.
        let c = Contact::try_new([0.0; 3], [1e-310, 0.0, 0.0], None).unwrap();
        assert_eq!(c.normal(), [1.0, 0.0, 0.0]);
        let c = Contact::try_new([0.0; 3], [1e300, -1e300, 0.0], None).unwrap();
        assert_unit(c.normal());
        assert!((c.normal()[0] - 0.5f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn default_tangent_is_unit_orthogonal_and_deterministic() {
        for d in directions(200) {
            let c = Contact::try_new([0.0; 3], d, None).unwrap();
            let n = c.normal();
            let t = c.tangent();
            assert!(!c.tangent_given());
            assert_unit(t);
            assert!(dot(n, t).abs() < 1e-15, "n = {n:?}, t = {t:?}");
            assert_unit(c.bitangent());
            // Same input, same tangent, bit for bit; and it is the documented formula.
            let again = Contact::try_new([5.0; 3], d, None).unwrap();
            assert_eq!(again.tangent().map(f64::to_bits), t.map(f64::to_bits));
            assert_eq!(Contact::default_tangent(n), t);
        }
        // Documented values: least aligned axis, lowest index on ties.
        assert_eq!(Contact::default_tangent([1.0, 0.0, 0.0]), [0.0, 0.0, 1.0]); // e_x × e_y
        assert_eq!(Contact::default_tangent([0.0, 1.0, 0.0]), [0.0, 0.0, -1.0]); // e_y × e_x
        assert_eq!(Contact::default_tangent([0.0, 0.0, 1.0]), [0.0, 1.0, 0.0]); // e_z × e_x
        assert_eq!(Contact::default_tangent([0.0, 0.0, -1.0]), [0.0, -1.0, 0.0]);
    }

    #[test]
    fn given_tangent_is_orthogonalised_and_normalised() {
        let c = Contact::try_new([0.0; 3], [0.0, 0.0, 1.0], Some([3.0, 0.0, 7.0])).unwrap();
        assert!(c.tangent_given());
        assert_eq!(c.tangent(), [1.0, 0.0, 0.0]);
        assert_eq!(c.bitangent(), [0.0, 1.0, 0.0]);
        for (i, d) in directions(100).into_iter().enumerate() {
            let t = directions(101)[i + 1];
            let c = Contact::try_new([0.0; 3], d, Some(t)).unwrap();
            assert_unit(c.tangent());
            assert!(dot(c.normal(), c.tangent()).abs() < 1e-15);
            // Still in the half-plane of the given tangent.
            assert!(dot(c.tangent(), t) > 0.0);
        }
        // Close to the normal but not within the tolerance: accepted, and orthogonal.
        let c = Contact::try_new([0.0; 3], [0.0, 0.0, 1.0], Some([1e-4, 0.0, 1.0])).unwrap();
        assert_eq!(c.tangent(), [1.0, 0.0, 0.0]);
        let n = [1.0, 2.0, 3.0];
        let c = Contact::try_new([0.0; 3], n, Some([1.0 + 1e-5, 2.0, 3.0])).unwrap();
        assert!(dot(c.normal(), c.tangent()).abs() < 1e-15);
        assert_unit(c.tangent());
    }

    #[test]
    fn every_contact_error() {
        let ok = [0.0, 0.0, 1.0];
        let cases: [(Result<Contact, GraspError>, GraspError); 9] = [
            (
                Contact::try_new([f64::NAN, 0.0, 0.0], ok, None),
                GraspError::NonFinitePosition { contact: None },
            ),
            (
                Contact::try_new([0.0, f64::INFINITY, 0.0], ok, None),
                GraspError::NonFinitePosition { contact: None },
            ),
            (
                Contact::try_new([0.0; 3], [0.0, 0.0, f64::NAN], None),
                GraspError::NonFiniteNormal { contact: None },
            ),
            (
                Contact::try_new([0.0; 3], [f64::NEG_INFINITY, 0.0, 0.0], None),
                GraspError::NonFiniteNormal { contact: None },
            ),
            (
                Contact::try_new([0.0; 3], [0.0, -0.0, 0.0], None),
                GraspError::ZeroNormal { contact: None },
            ),
            (
                Contact::try_new([0.0; 3], ok, Some([f64::NAN, 1.0, 0.0])),
                GraspError::NonFiniteTangent { contact: None },
            ),
            (
                Contact::try_new([0.0; 3], ok, Some([0.0; 3])),
                GraspError::ZeroTangent { contact: None },
            ),
            (
                Contact::try_new([0.0; 3], ok, Some([0.0, 0.0, -3.0])),
                GraspError::TangentParallelToNormal { contact: None },
            ),
            (
                Contact::try_new([0.0; 3], ok, Some([1e-9, 0.0, 1.0])),
                GraspError::TangentParallelToNormal { contact: None },
            ),
        ];
        for (got, want) in cases {
            assert_eq!(got, Err(want));
        }
    }
}
