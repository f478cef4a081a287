//! The object wrench space metric (Strandberg & Wahlberg; PQHOWS of Liu & Carpin).
//!
//! A grasp is good for an object when it can resist every disturbance the object is likely to
//! meet. The *object wrench space* (OWS) is the set of wrenches that unit disturbance forces,
//! applied anywhere on the object's surface within a friction cone, exert about the object's
//! centre of mass. The metric is
//!
//! > Q_OWS = max { r : −r·d ∈ GWS for every disturbance wrench d },
//!
//! where GWS = CH(∪ w_ij) is the grasp wrench space of Q1 (the grasp resists `d` by producing
//! `−d`). It is scale invariant (disturbances and grasp share the object's torque frame) and
//! shape aware, and it is defined for force-closure grasps only: a grasp whose GWS does not hold
//! the origin strictly inside gets "not force closure" and no number.
//!
//! # Conventions
//!
//! * Torque frame: the object's centre of mass `c` ([`MassProperties`](crate::mesh::MassProperties),
//!   the surface centroid for an open mesh) and characteristic length ρ (largest distance from `c`
//!   to a vertex), for the disturbances *and* for every grasp evaluated against them
//!   ([`ObjectWrenchSpace::frame`] builds the grasp in that frame).
//! * Disturbances (the seed paper's Eq. 6, discretised; [`ObjectWrenchSpace::from_mesh`]): for
//!   every triangle, with `n` its own unit inward normal and `t` its first edge `v1 − v0`
//!   projected onto the plane normal to `n` and normalised, the unit forces `e` are the normal
//!   push `n` and the `k` rim edges `unit(n + μ(cos θ_j t + sin θ_j (n × t)))`, θ_j = 2πj/k; at
//!   each of the triangle's three corners `v` they give the wrenches `[e ; (v − c) × e / ρ]`.
//!   Exactly equal wrenches are kept once. Degenerate triangles (no normal) are left out and
//!   counted ([`ObjectWrenchSpace::triangles_skipped`]), as are the vertices that are a corner
//!   of no other triangle ([`ObjectWrenchSpace::vertices_without_normal`]).
//! * A task wrench space — any other finite set of 6-D disturbances, in the grasps' torque units —
//!   can be given instead ([`ObjectWrenchSpace::from_disturbances`]).
//!
//! # Worked example
//!
//! A GWS that is the cube [−2, 2]⁶ (its gauge is |u|_∞ / 2) against the disturbances
//! d₁ = (1, 0, 0, 0, 0, 0) and d₂ = (0.5, 0, 0, 0, 0, 4): the grasp must produce −r·d₁ and −r·d₂,
//! which stay inside the cube up to r = 2 / 1 and r = 2 / 4 respectively, so Q_OWS = 0.5, decided
//! by d₂.
//!
//! ```
//! use pqhull::grasp::ows::{ObjectWrenchSpace, ows_of_wrenches};
//! use pqhull::grasp::quality::Method;
//!
//! let cube: Vec<[f64; 6]> = (0..64)
//!     .map(|i| std::array::from_fn(|c| if i >> c & 1 == 1 { 2.0 } else { -2.0 }))
//!     .collect();
//! let space = ObjectWrenchSpace::from_disturbances(vec![
//!     [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
//!     [0.5, 0.0, 0.0, 0.0, 0.0, 4.0],
//! ])?;
//! for method in [Method::Partial, Method::Full] {
//!     let quality = ows_of_wrenches(&cube, &space, method)?;
//!     assert!(quality.force_closure);
//!     assert!((quality.value.unwrap() - 0.5).abs() < 1e-15);
//!     assert_eq!(quality.deciding_disturbance, Some(1));
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod describe;
mod evaluate;
mod space;

pub(in crate::grasp) use evaluate::{OwsEvaluator, evaluate_ows_batch};
pub use evaluate::{ows_of_wrenches, relative_error};
pub use space::{ELLIPSOID_TOLERANCE, MAX_DISTURBANCES, ObjectWrenchSpace, OwsError, SpaceOrigin};
