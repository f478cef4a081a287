//! The default object (the mesh a plan or a benchmark uses when it is given none) and the seed
//! paper's five Table 1 objects.

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

/// The OBJ text of the Utah teapot (open: no bottom; data/meshes/README.md), compiled in for
/// `pqh reproduce table1` as the default object is.
const TEAPOT_OBJ: &str = include_str!("../../data/meshes/teapot.obj");

/// The C shape's outline in the xy plane (metres): a 0.12 × 0.12 square with a 0.08 × 0.04 notch
/// cut from the middle of its +x side, leaving three 0.04-wide bars. Extruded 0.04 along z.
pub const C_SHAPE_OUTLINE: [[f64; 2]; 8] = [
    [0.0, 0.0],
    [0.12, 0.0],
    [0.12, 0.04],
    [0.04, 0.04],
    [0.04, 0.08],
    [0.12, 0.08],
    [0.12, 0.12],
    [0.0, 0.12],
];

/// The joystick's profile, `(r, z)` in metres, turned about the z axis in 32 segments: a base
/// disc of radius 0.06 and height 0.02, a stick of radius 0.008 up to z = 0.12, and a knob, a
/// cylinder of radius 0.016 from z = 0.12 to 0.15.
pub const JOYSTICK_PROFILE: [[f64; 2]; 8] = [
    [0.0, 0.0],
    [0.06, 0.0],
    [0.06, 0.02],
    [0.008, 0.02],
    [0.008, 0.12],
    [0.016, 0.12],
    [0.016, 0.15],
    [0.0, 0.15],
];

/// The five objects of the seed paper's Table 1, named as its rows are: a cube (0.08 m sides), a
/// sphere (radius 0.05 m, 16 rings × 32 segments), a C shape ([`C_SHAPE_OUTLINE`]), a joystick
/// ([`JOYSTICK_PROFILE`]: a base and a stick, one solid of revolution) and the Utah teapot. The
/// paper does not give its objects' shapes or sizes; these are documented stand-ins.
///
/// ```
/// let objects = pqhull_cli::object::table1_objects();
/// let names: Vec<_> = objects.iter().map(|(name, _)| *name).collect();
/// assert_eq!(names, ["Cube", "Sphere", "C shape", "Joystick", "Teapot"]);
/// assert!(objects[..4].iter().all(|(_, mesh)| mesh.is_closed()));
/// ```
pub fn table1_objects() -> Vec<(&'static str, Mesh)> {
    let built = "a built-in Table 1 object is a valid mesh";
    vec![
        ("Cube", Mesh::cuboid([0.04; 3]).expect(built)),
        ("Sphere", Mesh::uv_sphere(0.05, 16, 32).expect(built)),
        (
            "C shape",
            Mesh::extrude(&C_SHAPE_OUTLINE, 0.04).expect(built),
        ),
        ("Joystick", Mesh::lathe(&JOYSTICK_PROFILE, 32).expect(built)),
        (
            "Teapot",
            Mesh::from_obj_reader(TEAPOT_OBJ.as_bytes(), "built-in teapot.obj").expect(built),
        ),
    ]
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
