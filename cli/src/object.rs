//! The default object: the mesh a plan (or a benchmark) uses when it is given none.

use pqhull::mesh::Mesh;

/// The name the default object goes by in reports.
pub const DEFAULT_OBJECT_NAME: &str = "built-in spot.obj";

/// The OBJ text of the default object, compiled into the crate so that the default works from
/// any working directory (and in a published crate, which ships this one mesh).
const DEFAULT_OBJECT_OBJ: &str = include_str!("../../data/meshes/spot.obj");

/// The default object: Keenan Crane's cow "spot" (2930 vertices, 5856 triangles, a closed
/// surface; CC0, see data/meshes/README.md in the repository), named [`DEFAULT_OBJECT_NAME`].
///
/// ```
/// use pqhull_cli::object::{DEFAULT_OBJECT_NAME, default_object};
/// let spot = default_object();
/// assert_eq!(spot.vertices().len(), 2930);
/// assert_eq!(DEFAULT_OBJECT_NAME, "built-in spot.obj");
/// ```
pub fn default_object() -> Mesh {
    Mesh::from_obj_reader(DEFAULT_OBJECT_OBJ.as_bytes(), DEFAULT_OBJECT_NAME)
        .expect("the built-in spot.obj is a valid triangle mesh")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_object_is_a_closed_mesh() {
        let spot = default_object();
        assert_eq!(spot.triangles().len(), 5856);
        let mass = spot.mass_properties();
        assert!(mass.volume.is_some_and(|v| v > 0.0), "{mass:?}");
    }
}
