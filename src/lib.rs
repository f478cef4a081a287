//! # pqhull — partial convex hulls in any fixed dimension
//!
//! `pqhull` builds convex hulls in dimension `D` (2 ≤ D ≤ 8, a const generic) with QuickHull, where
//! the order of expansion and the moment to stop are decided by a pluggable [`Strategy`]. Running the
//! engine to completion ([`FarthestPoint`]) gives the full hull; stopping as soon as the facet nearest
//! a query point is certain ([`ClosestToOrigin`]) gives the signed distance from that point to the
//! hull boundary — the Ferrari–Canny grasp metric — at a fraction of the cost.
//!
//! Every combinatorial decision ("is this point strictly beyond this facet?") is made with an exact
//! orientation predicate ([`predicates`]), so degenerate input (duplicates, coplanar and cospherical
//! points, integer lattices, nearly coincident clusters) never corrupts the hull.
//!
//! ```
//! use pqhull::{Hull, ClosestToOrigin};
//!
//! // The unit square around the origin, plus an interior point.
//! let points = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.2, 0.1]];
//! let hull = Hull::try_new(&points)?;
//! assert_eq!(hull.vertex_indices().len(), 4);
//! assert!((hull.volume() - 4.0).abs() < 1e-12);
//!
//! // Distance from the origin to the boundary, computed from a partial hull.
//! let (_partial, result) = Hull::try_with_strategy(&points, ClosestToOrigin::new())?;
//! assert!((result.signed_distance - 1.0).abs() < 1e-12);
//! # Ok::<(), pqhull::HullError>(())
//! ```
// `deny`, not `forbid`: three calls are allowed, each a run-time dispatch to a version of an
// expansion compiled with target features the processor was just found to have (their
// intrinsics take no pointer and need no `unsafe`; the results are the same to the last bit):
// the double-double plane's, with fused multiply-adds and AVX (predicates/double_double.rs,
// `dd_minors`; in 6-D its four-lane form, `double_double/lanes.rs`), the same plane's side
// test with fused products (`DdPlane::evaluate_then`), and the `f64` filter's, with AVX
// (predicates/minors.rs, `tracked_minors`). Measured: the raw wrench hull at 4 × 16 took 11 %
// less time with the fused products and 6.4 % fewer instructions again with the lanes; the 6-D
// sphere 17.7 % fewer instructions with the filter's minors in AVX; the side test's fused
// products: docs/benchmarks.md, "Nearly coplanar faces". Nothing else may be unsafe.
#![deny(unsafe_code)]

pub mod geometry;
pub mod grasp;
pub mod hull;
pub mod mesh;
pub mod plan;
pub mod predicates;
pub mod rbox;
pub mod strategy;
pub mod viz;

pub use hull::{
    Facet, FacetId, FarthestPoint, Hull, HullError, InvariantViolation, ReusableStrategy, Stats,
    Step, Strategy,
};
pub use strategy::{ClosestToOrigin, OwsInflation};

/// The README's examples, compiled and run as doctests so they cannot rot.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
#[cfg(feature = "qhull")]
pub mod qhull_baseline;
