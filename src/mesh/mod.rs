//! Triangle meshes: loading (OBJ, STL), mass properties and surface normals.
//!
//! A [`Mesh`] is a list of vertices and a list of triangles (vertex-index triples), validated
//! once by [`Mesh::try_new`] (or a loader: [`Mesh::load`], [`Mesh::from_obj_reader`],
//! [`Mesh::from_stl_reader`]; or a generator: [`Mesh::cuboid`], [`Mesh::uv_sphere`]). It gives
//! what the object-wrench-space metric and a grasp planner need from an object:
//!
//! * [`Mesh::mass_properties`]: the centre of mass `c` (of the enclosed solid when the mesh is
//!   closed, of the surface otherwise — [`CentreKind`] says which), the volume, the surface area,
//!   and the characteristic length ρ = the largest distance from `c` to a vertex (GraspIt!'s
//!   torque scale);
//! * unit **inward** normals, per face ([`Mesh::face_normal_inward`]) and per vertex
//!   ([`Mesh::vertex_normals_inward`]): the direction a finger pushes, as the grasp module's
//!   contacts expect;
//! * area-weighted random surface points with their inward normals ([`Mesh::sample_surface`]).
//!
//! ## Conventions
//!
//! * **Winding.** Triangles are taken to be counter-clockwise seen from outside (the OBJ and STL
//!   convention), so `(b − a) × (c − a)` points out. A closed mesh whose signed volume comes out
//!   negative is wound the other way throughout; it is detected ([`Mesh::winding_reversed`]) and
//!   every normal is flipped, so normals point inward either way. An open mesh has no inside: its
//!   winding is trusted as given.
//! * **Degenerate triangles** — a repeated vertex index, or three collinear corners — are
//!   allowed and contribute nothing: no area, no volume, no normal, never sampled. Triangles with
//!   a repeated index also take no part in the edge [`Topology`]. A mesh made only of degenerate
//!   triangles is rejected ([`MeshError::ZeroArea`]).
//! * **Closed** ([`Mesh::is_closed`]) means every edge is shared by exactly two triangles that
//!   traverse it in opposite directions.
//!
//! ```
//! use pqhull::mesh::{CentreKind, Mesh};
//! use pqhull::geometry::Rng;
//!
//! // A 2 × 1 × 1 box around the origin.
//! let mesh = Mesh::cuboid([1.0, 0.5, 0.5])?;
//! assert!(mesh.is_closed());
//! let mass = mesh.mass_properties();
//! assert_eq!(mass.centre_kind, CentreKind::Volume);
//! assert!((mass.volume.unwrap() - 2.0).abs() < 1e-12);
//! assert!((mass.characteristic_length - 1.5f64.sqrt()).abs() < 1e-12);
//!
//! // Surface points for a grasp planner, with the direction a finger would push.
//! let mut rng = Rng::new(7);
//! for p in mesh.sample_surface(&mut rng, 10) {
//!     // On a box around the origin, inward means towards the centre.
//!     let towards_centre: f64 = (0..3).map(|i| -p.position[i] * p.inward_normal[i]).sum();
//!     assert!(towards_centre > 0.0);
//! }
//! # Ok::<(), pqhull::mesh::MeshError>(())
//! ```

mod error;
#[cfg(feature = "mesh")]
mod io;
mod mass;
mod nearest;
mod sample;
mod shapes;
mod solids;
mod surface_index;
mod topology;

pub use error::MeshError;
pub use mass::{CentreKind, MassProperties};
pub use sample::{SurfacePoint, SurfaceSampler};
pub use solids::MAX_PROFILE_POINTS;
pub use surface_index::SurfaceIndex;
pub use topology::Topology;

use crate::geometry::vector::{cross, norm, normalize, scale, sub};
use mass::Frame;

/// A 3-vector.
type V3 = [f64; 3];

/// The most triangles a [`Mesh`] holds: `u32::MAX` (2³² − 1), so that every triangle has a
/// `u32` handle (the [`SurfaceIndex`]'s nodes hold them).
pub const MAX_TRIANGLES: usize = u32::MAX as usize;

/// A validated triangle mesh. See the [module documentation](self) for the conventions.
///
/// A mesh is immutable: its topology and mass properties are computed once, when it is built.
#[derive(Clone, Debug)]
pub struct Mesh {
    vertices: Vec<[f64; 3]>,
    triangles: Vec<[u32; 3]>,
    frame: Frame,
    topology: Topology,
    mass: MassProperties,
    /// `+1`, or `−1` when the mesh is closed with a negative signed volume.
    orientation: f64,
}

/// Relative size below which an area-weighted sum of face normals is taken as cancelled (see
/// [`Mesh::vertex_normals_inward`]).
const NORMAL_CANCELLED: f64 = 1e-9;

impl Mesh {
    /// Builds a mesh from vertex coordinates and triangles (indices into `vertices`, counter-
    /// clockwise seen from outside; see the module documentation for the winding and
    /// degenerate-triangle conventions).
    ///
    /// Vertices that no triangle uses are kept (they count for ρ, see [`MassProperties`]).
    ///
    /// # Errors
    ///
    /// * [`MeshError::Empty`] if there are no vertices or no triangles;
    /// * [`MeshError::TooManyTriangles`] beyond [`MAX_TRIANGLES`];
    /// * [`MeshError::NonFiniteVertex`] naming the first vertex with a NaN or infinite coordinate;
    /// * [`MeshError::IndexOutOfRange`] naming the first triangle that refers to a missing vertex;
    /// * [`MeshError::ZeroArea`] if every triangle is degenerate.
    pub fn try_new(vertices: Vec<[f64; 3]>, triangles: Vec<[u32; 3]>) -> Result<Mesh, MeshError> {
        Mesh::try_new_named(vertices, triangles, None)
    }

    /// [`Mesh::try_new`], with the source name the loaders put in their errors.
    pub(in crate::mesh) fn try_new_named(
        vertices: Vec<[f64; 3]>,
        triangles: Vec<[u32; 3]>,
        source_name: Option<&str>,
    ) -> Result<Mesh, MeshError> {
        let source_name = || source_name.map(str::to_owned);
        if vertices.is_empty() || triangles.is_empty() {
            return Err(MeshError::Empty {
                source_name: source_name(),
                vertices: vertices.len(),
                triangles: triangles.len(),
            });
        }
        if triangles.len() > MAX_TRIANGLES {
            return Err(MeshError::TooManyTriangles {
                source_name: source_name(),
                triangles: triangles.len(),
                max: MAX_TRIANGLES,
            });
        }
        if let Some(vertex) = vertices
            .iter()
            .position(|v| v.iter().any(|x| !x.is_finite()))
        {
            return Err(MeshError::NonFiniteVertex {
                source_name: source_name(),
                vertex,
                coordinates: vertices[vertex],
            });
        }
        for (triangle, t) in triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= vertices.len()) {
                return Err(MeshError::IndexOutOfRange {
                    source_name: source_name(),
                    triangle,
                    index,
                    vertex_count: vertices.len(),
                });
            }
        }
        let frame = Frame::new(&vertices);
        let topology = Topology::of(&triangles);
        let Some(mass) = mass::compute(&vertices, &triangles, &frame, topology.is_closed()) else {
            return Err(MeshError::ZeroArea {
                source_name: source_name(),
                triangles: triangles.len(),
            });
        };
        Ok(Mesh {
            vertices,
            triangles,
            frame,
            topology,
            mass: mass.properties,
            orientation: mass.orientation,
        })
    }

    /// The vertex coordinates.
    pub fn vertices(&self) -> &[[f64; 3]] {
        &self.vertices
    }

    /// The triangles, as indices into [`Mesh::vertices`].
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// How the triangles share their edges (boundary, misoriented and non-manifold edge counts).
    pub fn topology(&self) -> Topology {
        self.topology
    }

    /// `true` when the surface is closed and consistently oriented: every edge is shared by
    /// exactly two triangles traversing it in opposite directions ([`Topology::is_closed`]).
    pub fn is_closed(&self) -> bool {
        self.topology.is_closed()
    }

    /// `true` when the mesh is closed and wound clockwise seen from outside (negative signed
    /// volume). The normals this type returns are flipped accordingly, so they point inward
    /// either way. Always `false` for an open mesh, whose winding is trusted.
    pub fn winding_reversed(&self) -> bool {
        self.orientation < 0.0
    }

    /// Centre of mass, volume, surface area and characteristic length ρ (computed when the mesh
    /// was built).
    ///
    /// For a closed mesh ([`Mesh::is_closed`]) the centre is the centroid of the enclosed solid,
    /// from signed tetrahedra on the bounding-box centre, and the volume is reported positive
    /// whatever the winding. The solid is used unless its signed volume `V` is negligible:
    /// `|V| ≤ 1e−10 · Σ|V_t|` over the tetrahedra, i.e. lost in cancellation (a two-sided sheet).
    /// Otherwise — and always for an open mesh — the centre is the area-weighted centroid of the
    /// surface, `volume` is `None` and `centre_kind` is [`CentreKind::SurfaceCentroid`].
    ///
    /// All sums are compensated and run relative to the bounding-box centre in power-of-two-scaled
    /// coordinates, so the centre is accurate to a few units in the last place of the mesh's
    /// extent wherever the mesh sits. Area and volume are converted back to the mesh's units at
    /// the end and may overflow to infinity if they are beyond the range of `f64`.
    pub fn mass_properties(&self) -> MassProperties {
        self.mass
    }

    /// `(b − a) × (c − a)` of triangle `t` in local coordinates (twice its area, pointing out for
    /// the declared winding).
    fn local_cross(&self, t: [u32; 3]) -> V3 {
        let [a, b, c] = t.map(|i| self.frame.local(self.vertices[i as usize]));
        cross(sub(b, a), sub(c, a))
    }

    /// The area of triangle `t` (0 for a degenerate one), or `None` if there is no triangle `t`.
    pub fn triangle_area(&self, t: usize) -> Option<f64> {
        let tri = *self.triangles.get(t)?;
        Some(self.frame.area(norm(self.local_cross(tri)) / 2.0))
    }

    /// The unit inward normal of triangle `t`: `−(b − a) × (c − a)` normalised, flipped when
    /// [`Mesh::winding_reversed`]. `None` if there is no triangle `t` or it is degenerate (zero
    /// area).
    pub fn face_normal_inward(&self, t: usize) -> Option<[f64; 3]> {
        let tri = *self.triangles.get(t)?;
        normalize(scale(self.local_cross(tri), -self.orientation))
    }

    /// Per-vertex unit inward normals: the area-weighted sum of the adjacent faces' normals,
    /// pointing into the object (see [`Mesh::face_normal_inward`]).
    ///
    /// A vertex gets `None` — nothing is invented — when no non-degenerate triangle uses it, or
    /// when its adjacent face normals cancel: the length of their area-weighted sum is at most
    /// `1e−9` times the sum of their lengths (the tip of a two-sided sheet, say), so its direction
    /// would be rounding noise.
    pub fn vertex_normals_inward(&self) -> Vec<Option<[f64; 3]>> {
        let mut sums = vec![[0.0; 3]; self.vertices.len()];
        let mut magnitudes = vec![0.0; self.vertices.len()];
        for &t in &self.triangles {
            if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
                continue;
            }
            let n = self.local_cross(t);
            let length = norm(n);
            if length == 0.0 {
                continue;
            }
            for i in t {
                let s = &mut sums[i as usize];
                *s = [s[0] + n[0], s[1] + n[1], s[2] + n[2]];
                magnitudes[i as usize] += length;
            }
        }
        sums.iter()
            .zip(&magnitudes)
            .map(|(&s, &m)| {
                if m > 0.0 && norm(s) > NORMAL_CANCELLED * m {
                    normalize(scale(s, -self.orientation))
                } else {
                    None
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetrahedron() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let t = vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
        (v, t)
    }

    #[test]
    fn a_tetrahedron_has_its_textbook_mass_properties() {
        let (v, t) = tetrahedron();
        let m = Mesh::try_new(v, t).unwrap();
        assert!(m.is_closed() && !m.winding_reversed());
        let p = m.mass_properties();
        assert!((p.volume.unwrap() - 1.0 / 6.0).abs() < 1e-15);
        for c in p.centre_of_mass {
            assert!((c - 0.25).abs() < 1e-15);
        }
        assert_eq!(m.face_normal_inward(0), Some([0.0, 0.0, 1.0]));
        assert_eq!(m.face_normal_inward(4), None);
        assert!((m.triangle_area(2).unwrap() - 3f64.sqrt() / 2.0).abs() < 1e-15);
    }

    #[test]
    fn degenerate_triangles_contribute_nothing() {
        let (mut v, mut t) = tetrahedron();
        v.push([0.5, 0.0, 0.0]); // on edge 0–1
        t.push([0, 1, 4]); // collinear corners
        t.push([2, 2, 3]); // repeated index
        let m = Mesh::try_new(v, t).unwrap();
        assert_eq!(m.topology().degenerate_triangles, 1);
        assert!(!m.is_closed()); // the collinear triangle still uses edge 0–1 a third time
        assert_eq!(m.face_normal_inward(4), None);
        assert_eq!(m.face_normal_inward(5), None);
        assert_eq!(m.triangle_area(5), Some(0.0));
        assert_eq!(m.vertex_normals_inward()[4], None);
        let area = m.mass_properties().surface_area;
        assert!((area - (1.5 + 3f64.sqrt() / 2.0)).abs() < 1e-15);
    }

    #[test]
    fn a_two_sided_triangle_is_closed_but_encloses_nothing() {
        let v = vec![[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [0.0, 3.0, 0.0]];
        let m = Mesh::try_new(v, vec![[0, 1, 2], [0, 2, 1]]).unwrap();
        assert!(m.is_closed());
        let p = m.mass_properties();
        assert_eq!(p.centre_kind, CentreKind::SurfaceCentroid);
        assert_eq!(p.volume, None);
        assert_eq!(p.centre_of_mass, [1.0, 1.0, 0.0]);
        assert_eq!(m.vertex_normals_inward(), vec![None; 3]);
    }

    #[test]
    fn validation_names_the_culprit() {
        let (mut v, t) = tetrahedron();
        v[2][1] = f64::NAN;
        assert!(matches!(
            Mesh::try_new(v, t.clone()),
            Err(MeshError::NonFiniteVertex { vertex: 2, .. })
        ));
        let (v, _) = tetrahedron();
        assert!(matches!(
            Mesh::try_new(v.clone(), vec![]),
            Err(MeshError::Empty {
                triangles: 0,
                vertices: 4,
                ..
            })
        ));
        assert!(matches!(
            Mesh::try_new(v.clone(), vec![[0, 0, 1], [1, 2, 2]]),
            Err(MeshError::ZeroArea { triangles: 2, .. })
        ));
        let e = Mesh::try_new(v, vec![[0, 1, 2], [0, 1, 4]]).unwrap_err();
        assert!(matches!(
            e,
            MeshError::IndexOutOfRange {
                triangle: 1,
                index: 4,
                vertex_count: 4,
                ..
            }
        ));
        assert_eq!(
            e.to_string(),
            "mesh: triangle 1 refers to vertex 4, but there are only 4 vertices"
        );
    }
}
