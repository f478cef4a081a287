//! The surface point nearest a given point: how a planner puts a moved contact back on the
//! object.

use super::{Mesh, SurfacePoint};
use crate::geometry::vector::{add, dot, scale, sub};

/// The point of triangle `abc` nearest `p`, by the Voronoi regions of its vertices, edges and
/// face (Ericson, *Real-Time Collision Detection*, §5.1.5). [`SurfaceIndex`](super::SurfaceIndex)
/// calls it too, on the same corners in the same order, so that its answers are this search's
/// bit for bit.
pub(super) fn nearest_on_triangle(p: [f64; 3], a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> [f64; 3] {
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let (d1, d2) = (dot(ab, ap), dot(ac, ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = sub(p, b);
    let (d3, d4) = (dot(ab, bp), dot(ac, bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return add(a, scale(ab, d1 / (d1 - d3)));
    }
    let cp = sub(p, c);
    let (d5, d6) = (dot(ab, cp), dot(ac, cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return add(a, scale(ac, d2 / (d2 - d6)));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return add(b, scale(sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
    }
    let denom = 1.0 / (va + vb + vc);
    add(a, add(scale(ab, vb * denom), scale(ac, vc * denom)))
}

impl Mesh {
    /// The point of the surface nearest `p`, with its triangle's inward normal: where a planner
    /// that moved a contact off the surface puts it back. Degenerate triangles (no normal) are
    /// skipped; of equally near triangles (a point nearest an edge or a vertex) the first in
    /// mesh order is taken.
    ///
    /// This is the brute force, the reference: it visits every triangle, O(triangles) per call
    /// (about 25 µs for the teapot's 6,320). For many queries on one mesh — a planner's, on every
    /// move of every contact — build a [`SurfaceIndex`](super::SurfaceIndex) once: its
    /// [`nearest`](super::SurfaceIndex::nearest) gives the same answer, bit for bit, visiting a
    /// few boxes and triangles.
    ///
    /// ```
    /// use pqhull::mesh::Mesh;
    /// let cube = Mesh::cuboid([1.0; 3])?;
    /// let s = cube.nearest_surface_point([0.2, 0.1, 3.0]).unwrap();
    /// assert!(s.position.iter().zip([0.2, 0.1, 1.0]).all(|(x, y)| (x - y).abs() < 1e-12));
    /// assert_eq!(s.inward_normal, [0.0, 0.0, -1.0]);
    /// # Ok::<(), pqhull::mesh::MeshError>(())
    /// ```
    ///
    /// Returns `None` only when `p` has a coordinate that is not finite.
    pub fn nearest_surface_point(&self, p: [f64; 3]) -> Option<SurfacePoint> {
        if !p.iter().all(|x| x.is_finite()) {
            return None;
        }
        // The normal only of the winner: most of the cost of a triangle's normal is its square
        // root, and a planner calls this on every move.
        let mut best: Option<(f64, [f64; 3], usize)> = None;
        for (t, &tri) in self.triangles.iter().enumerate() {
            let [a, b, c] = tri.map(|i| self.vertices[i as usize]);
            let q = nearest_on_triangle(p, a, b, c);
            let d = sub(q, p);
            let distance = dot(d, d);
            if best.as_ref().is_none_or(|(b, _, _)| distance < *b)
                && self.face_normal_inward(t).is_some()
            {
                best = Some((distance, q, t));
            }
        }
        best.map(|(_, position, triangle)| SurfacePoint {
            position,
            inward_normal: self.face_normal_inward(triangle).unwrap_or([0.0; 3]),
            triangle,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_region_of_a_triangle() {
        let (a, b, c) = ([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]);
        for (p, want) in [
            ([-1.0, -1.0, 1.0], a),
            ([3.0, -1.0, 0.0], b),
            ([-1.0, 3.0, 2.0], c),
            ([1.0, -1.0, 0.0], [1.0, 0.0, 0.0]),
            ([-1.0, 1.0, 0.0], [0.0, 1.0, 0.0]),
            ([2.0, 2.0, 1.0], [1.0, 1.0, 0.0]),
            ([0.5, 0.5, 4.0], [0.5, 0.5, 0.0]),
        ] {
            assert_eq!(nearest_on_triangle(p, a, b, c), want, "{p:?}");
        }
    }

    #[test]
    fn the_nearest_point_of_a_sphere_mesh_is_on_it() {
        let sphere = Mesh::uv_sphere(1.0, 12, 24).unwrap();
        for p in [[3.0, 0.1, 0.2], [0.0, 0.0, 0.2], [-0.3, 0.9, -0.4]] {
            let s = sphere.nearest_surface_point(p).unwrap();
            let r = dot(s.position, s.position).sqrt();
            assert!(r <= 1.0 + 1e-12 && r > 0.95, "{r}");
            // The inward normal points back toward the centre.
            assert!(dot(s.inward_normal, s.position) < 0.0);
        }
        assert!(sphere.nearest_surface_point([f64::NAN, 0.0, 0.0]).is_none());
    }
}
