//! Area-weighted random points on a mesh's surface, for grasp planners.

use super::Mesh;
use crate::geometry::Rng;
use crate::geometry::vector::norm;

/// A point on the surface of a [`Mesh`], with the direction a finger placed there would push.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// The point, inside (or on the border of) triangle `triangle`.
    pub position: [f64; 3],
    /// The unit inward normal of that triangle ([`Mesh::face_normal_inward`]).
    pub inward_normal: [f64; 3],
    /// The index of the triangle in [`Mesh::triangles`].
    pub triangle: usize,
}

/// Draws points uniformly distributed over the area of a mesh's surface.
///
/// Building the sampler costs one pass over the triangles (their areas and prefix sums); each
/// sample then costs a binary search and three uniform deviates, so keep the sampler when drawing
/// points one at a time. [`Mesh::sample_surface`] draws a batch.
///
/// A triangle is chosen with probability proportional to its area (degenerate triangles are
/// never chosen), then a point uniform in it: with `u, v` uniform in `[0, 1)` and `s = √u`, the
/// point `(1 − s)·a + s(1 − v)·b + s·v·c` is uniform over the triangle `abc`.
#[derive(Clone, Debug)]
pub struct SurfaceSampler<'a> {
    mesh: &'a Mesh,
    /// Triangles with positive area, in mesh order.
    triangles: Vec<usize>,
    /// Their inward unit normals.
    normals: Vec<[f64; 3]>,
    /// `cumulative[i]` = Σ over `triangles[..=i]` of twice the area (in local units).
    cumulative: Vec<f64>,
}

impl<'a> SurfaceSampler<'a> {
    /// A sampler over the surface of `mesh`.
    pub fn new(mesh: &'a Mesh) -> Self {
        let mut triangles = Vec::new();
        let mut normals = Vec::new();
        let mut cumulative = Vec::new();
        let mut total = 0.0;
        for (t, &tri) in mesh.triangles.iter().enumerate() {
            if tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] {
                continue;
            }
            let twice_area = norm(mesh.local_cross(tri));
            let Some(normal) = mesh.face_normal_inward(t) else {
                continue;
            };
            if twice_area > 0.0 {
                total += twice_area;
                triangles.push(t);
                normals.push(normal);
                cumulative.push(total);
            }
        }
        // Mesh construction rejects a surface of zero area, so at least one triangle is here.
        debug_assert!(!triangles.is_empty());
        SurfaceSampler {
            mesh,
            triangles,
            normals,
            cumulative,
        }
    }

    /// One random surface point.
    pub fn sample(&self, rng: &mut Rng) -> SurfacePoint {
        let last = self.triangles.len().saturating_sub(1);
        let total = self.cumulative.last().copied().unwrap_or(0.0);
        let target = rng.uniform() * total;
        // The first triangle whose cumulative area exceeds the target: each is hit with
        // probability (its area) / total. `min` guards against `target` rounding up to `total`.
        let k = self.cumulative.partition_point(|&c| c <= target).min(last);
        let t = self.triangles.get(k).copied().unwrap_or(0);
        let [a, b, c] = self.mesh.triangles[t].map(|i| self.mesh.vertices[i as usize]);
        let s = rng.uniform().sqrt();
        let v = rng.uniform();
        let (wa, wb, wc) = (1.0 - s, s * (1.0 - v), s * v);
        SurfacePoint {
            position: std::array::from_fn(|i| wa * a[i] + wb * b[i] + wc * c[i]),
            inward_normal: self.normals.get(k).copied().unwrap_or([0.0; 3]),
            triangle: t,
        }
    }
}

impl Mesh {
    /// `count` random points uniformly distributed over the surface area, each with its
    /// triangle's unit inward normal (see [`SurfaceSampler`] for the method). The same `rng`
    /// state gives the same points.
    pub fn sample_surface(&self, rng: &mut Rng, count: usize) -> Vec<SurfacePoint> {
        let sampler = SurfaceSampler::new(self);
        (0..count).map(|_| sampler.sample(rng)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degenerate_triangles_are_never_sampled() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [2.0, 0.0, 0.0],
        ];
        // Triangle 0 is collinear, 1 has a repeated index, 2 is the only one with area.
        let m = Mesh::try_new(v, vec![[0, 1, 3], [0, 0, 2], [0, 1, 2]]).unwrap();
        let mut rng = Rng::new(1);
        let points = m.sample_surface(&mut rng, 200);
        assert!(points.iter().all(|p| p.triangle == 2));
        assert!(points.iter().all(|p| p.inward_normal == [0.0, 0.0, -1.0]));
    }

    #[test]
    fn the_same_seed_gives_the_same_points() {
        let m = Mesh::cuboid([1.0, 2.0, 3.0]).unwrap();
        let a = m.sample_surface(&mut Rng::new(5), 50);
        let b = m.sample_surface(&mut Rng::new(5), 50);
        assert_eq!(a, b);
        assert!(m.sample_surface(&mut Rng::new(5), 0).is_empty());
    }
}
