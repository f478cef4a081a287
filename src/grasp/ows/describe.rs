//! A one-line description of an object wrench space, for people: what the grasps are measured
//! against.

use super::{ObjectWrenchSpace, SpaceOrigin};
use crate::mesh::CentreKind;

impl ObjectWrenchSpace {
    /// One line saying what the space is: for a mesh, its disturbances and torque frame (and the
    /// vertices left out for want of a normal); for a task wrench space, its size. `pqh grasp`
    /// prints it as a note and `pqh bench ows` reports it.
    ///
    /// ```
    /// use pqhull::grasp::FrictionModel;
    /// use pqhull::grasp::ows::ObjectWrenchSpace;
    /// use pqhull::mesh::Mesh;
    ///
    /// let cube = Mesh::cuboid([0.5, 0.5, 0.5])?;
    /// let space = ObjectWrenchSpace::from_mesh(&cube, FrictionModel::try_new(0.5, 4)?)?;
    /// assert!(space.describe().starts_with("object wrench space: "));
    /// assert!(space.describe().contains("torque reference centre of mass ("));
    /// let task = ObjectWrenchSpace::from_disturbances(vec![[1.0, 0.0, 0.0, 0.0, 0.0, 0.0]])?;
    /// assert_eq!(task.describe(), "task wrench space: 1 disturbances");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn describe(&self) -> String {
        match self.origin() {
            SpaceOrigin::Mesh {
                centre_of_mass: c,
                centre_kind,
                characteristic_length,
                ..
            } => format!(
                "object wrench space: {} disturbances; torque reference {} ({}, {}, {}), torque \
                 scale {}{}",
                self.len(),
                match centre_kind {
                    CentreKind::Volume => "centre of mass",
                    CentreKind::SurfaceCentroid => "surface centroid (open mesh)",
                },
                short(c[0]),
                short(c[1]),
                short(c[2]),
                short(*characteristic_length),
                match self.vertices_without_normal() {
                    0 => String::new(),
                    n => format!("; {n} vertices without a normal left out"),
                }
            ),
            SpaceOrigin::Given => format!("task wrench space: {} disturbances", self.len()),
        }
    }
}

/// `x` to six decimals in the everyday range, else six significant digits with an exponent
/// (`{:.6}` writes 1e-200 as 0.000000, and Rust's `Display` writes 1e200 as 201 digits).
fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e16).contains(&x.abs()) {
        format!("{x:.6}")
    } else {
        format!("{x:.5e}")
    }
}

#[cfg(test)]
mod tests {
    use super::short;

    #[test]
    fn exponents_outside_the_everyday_range() {
        assert_eq!(short(1e-200), "1.00000e-200");
        assert_eq!(short(-0.5), "-0.500000");
        assert_eq!(short(2e17), "2.00000e17");
    }
}
