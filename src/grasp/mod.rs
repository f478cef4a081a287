//! The grasp model: contacts, friction cones and contact wrenches.
//!
//! This module turns a grasp — a few fingertip contacts on an object with Coulomb friction — into
//! the 6-D wrench point sets whose convex hulls define the Ferrari–Canny grasp quality metrics.
//! (The metrics themselves, Q1 and Q∞, are built on these sets and [`Hull`](crate::Hull).)
//!
//! # Grasp conventions
//!
//! * Contact i: position p_i, unit **inward** normal n_i (the direction the finger pushes),
//!   optional unit tangent t_i. Friction coefficient μ, k cone edges.
//! * Edge j of contact i: f_ij = n_i + μ (cos(2πj/k) t_i + sin(2πj/k) (n_i × t_i)) — normal
//!   component 1 (Ferrari–Canny, GraspIt!, Dex-Net). When t_i is not given, a documented
//!   deterministic default ([`Contact::default_tangent`]: the normalised cross product of n_i with
//!   the coordinate axis least aligned with it).
//! * Wrench: w_ij = [f_ij ; (p_i − c) × f_ij / ρ] with torque reference c (default origin; with a
//!   mesh, its centre of mass) and torque scale ρ (default 1; with a mesh, the largest distance
//!   from c to a mesh vertex, as GraspIt! does).
//! * Q1 is computed over the union ∪_ij w_ij ([`Grasp::wrenches`], m·k points, contact-major);
//!   Q∞ over the Minkowski sum ⊕_i {w_i1 … w_ik}, which has k^m points
//!   ([`Grasp::minkowski_count`]) and is never materialised here.
//!
//! Input is validated once, when a [`Contact`], [`FrictionModel`] or [`Grasp`] is built
//! ([`GraspError`] says what was wrong and, for contacts, which one); a built value always holds
//! finite coordinates, unit normals and unit tangents orthogonal to them. Grasps written as JSON
//! (the format `pqh grasp` reads) are read by [`json`].
//!
//! # Example
//!
//! A two-finger grasp on the unit cube [−½, ½]³, pinching it along x:
//!
//! ```
//! use pqhull::grasp::{Contact, FrictionModel, Grasp};
//!
//! let contacts = vec![
//!     // On the face x = −½ the finger pushes in +x; on x = +½ it pushes in −x.
//!     Contact::try_new([-0.5, 0.0, 0.0], [1.0, 0.0, 0.0], None)?,
//!     Contact::try_new([0.5, 0.0, 0.0], [-1.0, 0.0, 0.0], None)?,
//! ];
//! let friction = FrictionModel::try_new(0.5, 8)?; // μ = 0.5, k = 8
//! let grasp = Grasp::builder(contacts, friction)
//!     .torque_reference([0.0, 0.0, 0.0]) // the cube's centre of mass
//!     .torque_scale(0.75_f64.sqrt())     // the distance from it to a corner
//!     .build()?;
//!
//! let wrenches = grasp.wrenches(); // the Q1 point set: 2 contacts × 8 edges
//! assert_eq!(wrenches.len(), 16);
//! assert_eq!(grasp.minkowski_count(), Some(64)); // the Q∞ set would have 8² points
//!
//! // Every edge pushes with normal component 1.
//! assert!(wrenches[..8].iter().all(|w| (w[0] - 1.0).abs() < 1e-15));
//! assert!(wrenches[8..].iter().all(|w| (w[0] + 1.0).abs() < 1e-15));
//!
//! // Batch evaluation reuses one buffer per worker instead of allocating per grasp.
//! let mut buffer = Vec::new();
//! grasp.wrenches_into(&mut buffer);
//! assert_eq!(buffer, wrenches);
//! # Ok::<(), pqhull::grasp::GraspError>(())
//! ```

mod certify;
mod contact;
mod error;
mod evaluation;
mod evaluator;
mod flatness;
mod friction;
mod gradient;
pub mod json;
pub mod metrics;
pub mod ows;
mod pipeline;
pub mod quality;
mod random;
mod snap;
mod threads;
mod wrench;

pub use contact::{Contact, TANGENT_PARALLEL_TOLERANCE};
pub use error::GraspError;
pub use evaluation::{Bracket, Evaluation};
pub use evaluator::{Evaluator, evaluate_batch};
pub use friction::{FrictionModel, MAX_CONE_EDGES, MIN_CONE_EDGES};
pub use gradient::{Gradient, GradientError, ows_gradient, q1_gradient, qinf_gradient};
pub use quality::{Method, Metric, QualityError};
#[cfg(feature = "parallel")]
pub use threads::thread_pool;
pub use threads::{MAX_THREADS, ThreadsError, check_threads, with_threads};

use crate::geometry::vector::is_finite;

/// The most contacts a [`Grasp`] accepts: 256.
///
/// Why this bound: grasps have a few contacts (a hand's fingertips and phalanges, a few dozen for
/// whole-arm grasps or contact patches sampled as points); 256 leaves room for all of them. With
/// [`MAX_CONE_EDGES`] it bounds a grasp's Q1 wrench set to 256 · 1024 = 262,144 points (12.6 MB);
/// the partial method still evaluates Q1 of such a grasp (time and memory at both limits in
/// docs/limits.md). Q∞'s
/// Minkowski sum has k^m points and is never materialised by the partial method, but its time
/// grows quickly with m: this bound does not make Q∞ of hundreds of contacts fast.
pub const MAX_CONTACTS: usize = 256;

/// A grasp: m ≥ 1 contacts sharing one friction model, a torque reference point c and a torque
/// scale ρ (see the [module docs](self) for the conventions).
///
/// Build it with [`Grasp::builder`] (defaults c = origin, ρ = 1).
#[derive(Clone, Debug, PartialEq)]
pub struct Grasp {
    contacts: Vec<Contact>,
    friction: FrictionModel,
    torque_reference: [f64; 3],
    torque_scale: f64,
}

impl Grasp {
    /// The one way to make a grasp: a builder starting from the defaults c = origin, ρ = 1
    /// ([`GraspBuilder::torque_reference`], [`GraspBuilder::torque_scale`]), checked by
    /// [`GraspBuilder::build`].
    pub fn builder(contacts: Vec<Contact>, friction: FrictionModel) -> GraspBuilder {
        GraspBuilder {
            contacts,
            friction,
            torque_reference: [0.0; 3],
            torque_scale: 1.0,
        }
    }

    /// The contacts, in the order given.
    pub fn contacts(&self) -> &[Contact] {
        &self.contacts
    }

    /// How many points Q∞'s Minkowski sum has when written out, `(k + z)^m` (k cone edges, z = 1
    /// with the zero wrench, m contacts; a soft contact's factor is 2k + z), or `None` beyond
    /// `usize`: what the full and Qhull
    /// methods materialise and hull (the partial method never does). A guide to their cost.
    ///
    /// ```
    /// use pqhull::grasp::{Contact, FrictionModel, Grasp};
    /// let c = |x: f64| Contact::try_new([x, 0.0, 0.0], [-x, 0.0, 0.0], None);
    /// let grasp = Grasp::builder(vec![c(1.0)?, c(-1.0)?], FrictionModel::try_new(0.5, 8)?).build()?;
    /// assert_eq!(grasp.minkowski_points(false), Some(64));
    /// assert_eq!(grasp.minkowski_points(true), Some(81));
    /// # Ok::<(), pqhull::grasp::GraspError>(())
    /// ```
    pub fn minkowski_points(&self, with_zero_wrench: bool) -> Option<usize> {
        let k = self.friction.cone_edges();
        self.contacts.iter().try_fold(1usize, |n, c| {
            let set = if c.is_soft() { 2 * k } else { k };
            n.checked_mul(set + usize::from(with_zero_wrench))
        })
    }

    /// The number of contacts m (1 ≤ m ≤ [`MAX_CONTACTS`]).
    pub fn contact_count(&self) -> usize {
        self.contacts.len()
    }

    /// The friction model shared by all contacts.
    pub fn friction(&self) -> FrictionModel {
        self.friction
    }

    /// The torque reference point c.
    pub fn torque_reference(&self) -> [f64; 3] {
        self.torque_reference
    }

    /// The torque scale ρ (finite, > 0).
    pub fn torque_scale(&self) -> f64 {
        self.torque_scale
    }
}

/// Builds a [`Grasp`], from [`Grasp::builder`].
#[derive(Clone, Debug)]
#[must_use = "a builder does nothing until `build` is called"]
pub struct GraspBuilder {
    contacts: Vec<Contact>,
    friction: FrictionModel,
    torque_reference: [f64; 3],
    torque_scale: f64,
}

impl GraspBuilder {
    /// Sets the torque reference point c (default: the origin; with a mesh, its centre of mass).
    pub fn torque_reference(mut self, c: [f64; 3]) -> Self {
        self.torque_reference = c;
        self
    }

    /// Sets the torque scale ρ (default 1; with a mesh, the largest distance from c to a mesh
    /// vertex, as GraspIt! does). Torques are divided by ρ.
    pub fn torque_scale(mut self, rho: f64) -> Self {
        self.torque_scale = rho;
        self
    }

    /// The grasp.
    ///
    /// # Errors
    ///
    /// [`GraspError::NoContacts`] when there are no contacts,
    /// [`GraspError::TooManyContacts`] when there are more than [`MAX_CONTACTS`],
    /// [`GraspError::NonFiniteTorqueReference`] when c has a NaN or infinite coordinate,
    /// [`GraspError::InvalidTorqueScale`] when ρ is not finite or not greater than 0.
    pub fn build(self) -> Result<Grasp, GraspError> {
        if self.contacts.is_empty() {
            return Err(GraspError::NoContacts);
        }
        if self.contacts.len() > MAX_CONTACTS {
            return Err(GraspError::TooManyContacts {
                contacts: self.contacts.len(),
                max: MAX_CONTACTS,
            });
        }
        if !is_finite(self.torque_reference) {
            return Err(GraspError::NonFiniteTorqueReference);
        }
        if !(self.torque_scale.is_finite() && self.torque_scale > 0.0) {
            return Err(GraspError::InvalidTorqueScale {
                torque_scale: self.torque_scale,
            });
        }
        Ok(Grasp {
            contacts: self.contacts,
            friction: self.friction,
            torque_reference: self.torque_reference,
            torque_scale: self.torque_scale,
        })
    }
}

/// `f` over `items`, results in input order: on all cores (rayon's current pool) with the
/// `parallel` feature, else on this thread. The batch evaluators' one switch between the two.
pub(in crate::grasp) fn map_in_order<T: Sync, R: Send>(
    items: &[T],
    f: impl Fn(&T) -> R + Sync + Send,
) -> Vec<R> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        items.par_iter().map(f).collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        items.iter().map(f).collect()
    }
}
