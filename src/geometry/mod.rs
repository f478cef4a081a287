//! The geometric kernel under the engine and every consumer: vectors, the minimum-norm point of a
//! point set (Wolfe), GJK on a support function, the support-function ball tree, the enclosing
//! ellipsoid, and the seeded random-number generator.
//!
//! Nothing here knows a hull: these are the numerical building blocks the engine's strategies and
//! the grasp layer share, kept in one place so that each exists once.
//!
//! ```
//! use pqhull::geometry::{min_norm_point, vector::norm};
//! // The point of the segment from (1, −1) to (1, 1) nearest the origin is (1, 0).
//! let points = [[1.0, -1.0], [1.0, 1.0]];
//! let nearest = min_norm_point(points.len(), |i| points[i], &[0.0, 0.0]);
//! assert!((nearest.distance - 1.0).abs() < 1e-15);
//! assert!(norm([nearest.point[0] - 1.0, nearest.point[1]]) < 1e-15);
//! ```

pub mod ellipsoid;
pub(crate) mod exact_int;
mod gjk;
pub mod gram;
mod nearest;
mod rng;
mod support;
mod support_index;
pub mod vector;

pub use ellipsoid::{CentredEllipsoid, EllipsoidError};
pub use gjk::{GJK_ITERATIONS, GJK_TOUCHING, Gjk, GjkVerdict};
pub(crate) use nearest::origin_weights;
pub use nearest::{
    FAR, Nearest, min_norm_point, min_norm_point_accurate, min_norm_point_exact,
    nearest_face_in_simplex, nearest_in_simplex, rescaled,
};
pub use rng::Rng;
pub use support::{Support, SupportFn, largest_norm};
pub use support_index::SupportIndex;
