//! The two parry builds behind one interface, for the table example and the criterion bench
//! (included by both with `#[path]`: parry is a dev-dependency, so the library half of this
//! package cannot hold it).

/// One parry build, f64 or f32: the shapes of a pair and the signed depth `−contact.dist`.
macro_rules! parry_adapter {
    ($name:ident, $krate:ident, $real:ty) => {
        pub mod $name {
            use $krate::math::{Pose, Vector};
            use $krate::query::contact;
            use $krate::shape::ConvexPolyhedron;

            pub fn shape(points: &[pqhull_parry_compare::Point]) -> Option<ConvexPolyhedron> {
                let v: Vec<Vector> = points
                    .iter()
                    .map(|p| Vector::new(p[0] as $real, p[1] as $real, p[2] as $real))
                    .collect();
                ConvexPolyhedron::from_convex_hull(&v)
            }

            /// `Some(−dist)`, or `None` when parry finds no contact (for an overlapping pair:
            /// EPA gave up).
            pub fn depth(a: &ConvexPolyhedron, b: &ConvexPolyhedron) -> Option<f64> {
                contact(&Pose::IDENTITY, a, &Pose::IDENTITY, b, 10.0)
                    .expect("convex polyhedra are supported")
                    .map(|c| -(c.dist as f64))
            }
        }
    };
}
parry_adapter!(parry64, parry3d_f64, f64);
parry_adapter!(parry32, parry3d, f32);
