//! Generated objects for tests, examples and benchmarks: a box and a UV sphere.

use std::f64::consts::{PI, TAU};

use super::{Mesh, MeshError};

impl Mesh {
    /// The box `[−hx, hx] × [−hy, hy] × [−hz, hz]` around the origin: 8 vertices, 12 triangles,
    /// counter-clockwise seen from outside.
    ///
    /// Vertex `i` has coordinate `k` equal to `+half_extents[k]` when bit `k` of `i` is set and
    /// `−half_extents[k]` otherwise. Each face is split along the diagonal from its
    /// lowest-numbered corner.
    ///
    /// # Errors
    ///
    /// [`MeshError::InvalidParameter`] unless every half extent is finite and positive.
    pub fn cuboid(half_extents: [f64; 3]) -> Result<Mesh, MeshError> {
        if let Some(&h) = half_extents.iter().find(|h| !(h.is_finite() && **h > 0.0)) {
            return Err(MeshError::InvalidParameter {
                name: "half extent",
                value: h.to_string(),
                expected: "a finite positive number",
            });
        }
        let vertices = (0..8)
            .map(|i| {
                std::array::from_fn(|k| half_extents[k] * if i >> k & 1 == 1 { 1.0 } else { -1.0 })
            })
            .collect();
        // Each face as a quad, counter-clockwise seen from outside.
        const QUADS: [[u32; 4]; 6] = [
            [0, 4, 6, 2], // −x
            [1, 3, 7, 5], // +x
            [0, 1, 5, 4], // −y
            [2, 6, 7, 3], // +y
            [0, 2, 3, 1], // −z
            [4, 5, 7, 6], // +z
        ];
        let triangles = QUADS
            .iter()
            .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
            .collect();
        Mesh::try_new(vertices, triangles)
    }

    /// A UV sphere of radius `radius` around the origin, with `rings` bands of latitude and
    /// `segments` meridians: closed, counter-clockwise seen from outside, every vertex at
    /// distance `radius` from the origin.
    ///
    /// Vertex 0 is the north pole `(0, 0, r)`, the last vertex the south pole; between them,
    /// ring `i = 1 … rings − 1` (polar angle `πi/rings`) has `segments` vertices at azimuths
    /// `2πj/segments`. There are `2 + (rings − 1)·segments` vertices and `2·segments·(rings − 1)`
    /// triangles. The polyhedron is convex and inscribed in the sphere, so its volume is below
    /// `4/3·πr³` and above that of the ball inscribed in it.
    ///
    /// # Errors
    ///
    /// [`MeshError::InvalidParameter`] unless `radius` is finite and positive, `rings ≥ 2`,
    /// `segments ≥ 3`, and the vertex count fits a `u32` index.
    pub fn uv_sphere(radius: f64, rings: usize, segments: usize) -> Result<Mesh, MeshError> {
        if !(radius.is_finite() && radius > 0.0) {
            return Err(MeshError::InvalidParameter {
                name: "radius",
                value: radius.to_string(),
                expected: "a finite positive number",
            });
        }
        if rings < 2 {
            return Err(MeshError::InvalidParameter {
                name: "rings",
                value: rings.to_string(),
                expected: "at least 2",
            });
        }
        if segments < 3 {
            return Err(MeshError::InvalidParameter {
                name: "segments",
                value: segments.to_string(),
                expected: "at least 3",
            });
        }
        let vertex_count = (rings - 1)
            .checked_mul(segments)
            .and_then(|n| n.checked_add(2))
            .filter(|&n| u32::try_from(n).is_ok());
        let Some(vertex_count) = vertex_count else {
            return Err(MeshError::InvalidParameter {
                name: "rings × segments",
                value: format!("{rings} × {segments}"),
                expected: "at most 2^32 − 3 vertices",
            });
        };
        let mut vertices = Vec::with_capacity(vertex_count);
        vertices.push([0.0, 0.0, radius]);
        for i in 1..rings {
            let theta = PI * i as f64 / rings as f64;
            let (sin_t, cos_t) = theta.sin_cos();
            for j in 0..segments {
                let phi = TAU * j as f64 / segments as f64;
                let (sin_p, cos_p) = phi.sin_cos();
                vertices.push([
                    radius * sin_t * cos_p,
                    radius * sin_t * sin_p,
                    radius * cos_t,
                ]);
            }
        }
        vertices.push([0.0, 0.0, -radius]);
        // Indices fit u32: checked above.
        let south = (vertex_count - 1) as u32;
        let ring = |i: usize, j: usize| (1 + (i - 1) * segments + j % segments) as u32;
        let mut triangles = Vec::with_capacity(2 * segments * (rings - 1));
        for j in 0..segments {
            triangles.push([0, ring(1, j), ring(1, j + 1)]);
        }
        for i in 1..rings - 1 {
            for j in 0..segments {
                let (a, b, c, d) = (
                    ring(i, j),
                    ring(i + 1, j),
                    ring(i + 1, j + 1),
                    ring(i, j + 1),
                );
                triangles.push([a, b, c]);
                triangles.push([a, c, d]);
            }
        }
        for j in 0..segments {
            triangles.push([ring(rings - 1, j), south, ring(rings - 1, j + 1)]);
        }
        Mesh::try_new(vertices, triangles)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_have_the_documented_sizes() {
        let c = Mesh::cuboid([1.0, 2.0, 3.0]).unwrap();
        assert_eq!((c.vertices().len(), c.triangles().len()), (8, 12));
        let s = Mesh::uv_sphere(1.0, 5, 7).unwrap();
        assert_eq!(s.vertices().len(), 2 + 4 * 7);
        assert_eq!(s.triangles().len(), 2 * 7 * 4);
        let s = Mesh::uv_sphere(1.0, 2, 3).unwrap(); // a triangular bipyramid
        assert!(s.is_closed());
    }

    #[test]
    fn bad_parameters_are_errors() {
        assert!(Mesh::cuboid([1.0, 0.0, 1.0]).is_err());
        assert!(Mesh::cuboid([1.0, f64::NAN, 1.0]).is_err());
        assert!(Mesh::cuboid([-1.0, 1.0, 1.0]).is_err());
        assert!(Mesh::uv_sphere(0.0, 4, 4).is_err());
        assert!(Mesh::uv_sphere(1.0, 1, 4).is_err());
        let e = Mesh::uv_sphere(1.0, 4, 2).unwrap_err();
        assert_eq!(e.to_string(), "invalid segments = 2: expected at least 3");
        assert!(Mesh::uv_sphere(1.0, usize::MAX, 4).is_err());
    }
}
