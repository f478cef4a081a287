//! A bounding-volume hierarchy over a mesh's triangles that answers nearest-surface-point queries
//! with exactly the brute force's answers ([`Mesh::nearest_surface_point`]), for a planner that
//! asks on every move of every contact.
//!
//! Written here rather than taken from a crate: the library takes no dependency for it. The
//! well-kept spatial crates (parry, bvh, rstar) bring their own mesh, point and scalar types and
//! their own point–triangle code, whose rounding differs from `nearest_on_triangle`'s — and the
//! point here is to return the brute force's answer bit for bit, which only the same arithmetic
//! on the same corners gives. A median-split tree over the triangles' boxes is a page of code.

use super::nearest::nearest_on_triangle;
use super::{Mesh, SurfacePoint};
use crate::geometry::vector::{cross, dot, norm, sub};

/// The most triangles in a leaf.
const LEAF: usize = 4;

/// The pruning margin's safety factor times ε (see [`SurfaceIndex`]'s "Exactness"). On slivers
/// (the test `the_margin_covers_rounding_on_slivers`) no computed point ever came out nearer the
/// query than its triangle's box: the margin is insurance, and costs next to nothing.
const MARGIN: f64 = 4096.0 * f64::EPSILON;

/// The deepest a median-split tree over fewer than 2³² triangles gets, with room to spare: the
/// traversal's stack holds at most one entry per level plus one.
const MAX_DEPTH: usize = 64;

/// A node of the tree: a box, the largest shape factor of its triangles, and where its triangles
/// or its children are.
#[derive(Clone, Copy, Debug)]
struct Node {
    lo: [f64; 3],
    hi: [f64; 3],
    /// The largest `S = L⁵/|n|³` of the node's triangles (`L` the longest edge, `|n|` twice the
    /// area): how far rounding can carry a computed nearest point out of the triangle, per unit
    /// of `ε·R²` (see [`SurfaceIndex`]).
    shape: f64,
    /// A leaf: the first of its triangles in `corners`; otherwise the second child (the first is
    /// the next node).
    index: u32,
    /// A leaf: how many triangles it has (at least 1); otherwise 0.
    count: u32,
}

/// A query structure for the surface point nearest a given point, built once per mesh: the
/// answers of [`Mesh::nearest_surface_point`] (the same triangle, position and normal, bit for
/// bit), visiting a few boxes and triangles instead of every triangle.
///
/// The triangles with an inward normal (the non-degenerate ones, the only ones the brute force
/// can return) are held in a bounding-volume hierarchy: axis-aligned boxes, split at the median
/// of the triangles' centroids along the longest axis, down to leaves of at most four triangles,
/// the nodes in one flat `Vec`. A query descends depth first, the nearer child first, and skips
/// a box whose distance exceeds the best squared distance found so far. Building costs
/// O(n log n) for n triangles (1.5 to 2 ms for the teapot's 6,320 on a slow shared machine,
/// where one brute-force search costs 0.2 ms) and about 120 bytes per triangle; a query near
/// the surface, under 2 µs there.
///
/// ```
/// use pqhull::mesh::{Mesh, SurfaceIndex};
/// let sphere = Mesh::uv_sphere(1.0, 16, 32)?;
/// let index = SurfaceIndex::new(&sphere);
/// for p in [[0.3, 2.0, -0.1], [0.0, 0.0, 0.5], [0.1, 0.2, 0.95]] {
///     assert_eq!(index.nearest(p), sphere.nearest_surface_point(p));
/// }
/// assert_eq!(index.nearest([f64::NAN, 0.0, 0.0]), None);
/// # Ok::<(), pqhull::mesh::MeshError>(())
/// ```
///
/// # Exactness
///
/// The brute force keeps, in mesh order, the first triangle with a normal and then any later one
/// whose squared distance is strictly smaller: the first triangle in index order with the least
/// squared distance (a NaN distance, possible only when a computation overflows, is never
/// smaller; the first triangle is kept even then). The index computes each triangle's point with
/// the same function on the same corners, keeps the least `(squared distance, index)` in that
/// order, starts from the same first triangle, and skips a box only when every triangle in it
/// must come out strictly farther than the best so far — so triangles that tie are visited and
/// the lowest index wins, as in the brute force.
///
/// "Must come out farther" accounts for rounding: a computed nearest point is the triangle's up
/// to rounding, and the box's distance is deflated by a margin `E = C·ε·(R²·S + R₁ + M)` before
/// it is compared: `R` (`R₁`) the largest Euclidean (Manhattan) distance from the query to the
/// box's corners, `M` the largest coordinate magnitude of the mesh and the query, `S = L⁵/|n|³`
/// the largest shape factor of the box's triangles (`L` the longest edge, `|n|` twice the area)
/// and `C = 4096`. At a vertex or an edge the computed point is within a few units in the last
/// place of `M` of the triangle; inside the face its barycentric weights come from differences
/// of products, whose rounding — up to `ε·R²·L²/|n|²` relative to the weights, times `L/sinθ ≤
/// L³/|n|` in position near a corner — is what `R²·S` bounds. Boxes of slivers (large `S`) are
/// visited more often; a box whose margin overflows (or is NaN) is always visited. This bound is
/// a first-order error analysis with a wide safety factor, not a proof; the tests check it on
/// random slivers at many scales (where no computed point ever fell nearer than its box) and
/// check the answers bit for bit on thousands of queries against every mesh they use.
#[derive(Clone, Debug)]
pub struct SurfaceIndex<'m> {
    mesh: &'m Mesh,
    nodes: Vec<Node>,
    /// The corners of the triangles with a normal, in leaf order, copied from the mesh.
    corners: Vec<[[f64; 3]; 3]>,
    /// Their indices in [`Mesh::triangles`].
    ids: Vec<u32>,
    /// The first triangle with a normal, in mesh order: the brute force's first candidate.
    first: Option<u32>,
    /// The largest coordinate magnitude of the mesh's vertices.
    magnitude: f64,
}

/// A triangle as the build sorts it: small, since the median selections move it about (its
/// centroid in `f32`: where the tree splits decides only its speed, not its answers).
#[derive(Clone, Copy)]
struct Item {
    centroid: [f32; 3],
    id: u32,
}

/// The box and shape factor covering both.
fn union(
    (lo, hi, shape): ([f64; 3], [f64; 3], f64),
    (other_lo, other_hi, other_shape): ([f64; 3], [f64; 3], f64),
) -> ([f64; 3], [f64; 3], f64) {
    (
        std::array::from_fn(|k| lo[k].min(other_lo[k])),
        std::array::from_fn(|k| hi[k].max(other_hi[k])),
        // Not `f64::max`, which would drop a NaN: a factor whose `L⁵` and `|n|³` both overflow
        // (or both underflow) is NaN, and its boxes must stay always visited.
        if other_shape.is_nan() || other_shape > shape {
            other_shape
        } else {
            shape
        },
    )
}

impl<'m> SurfaceIndex<'m> {
    /// The index of `mesh`'s surface (its triangles with an inward normal,
    /// [`Mesh::face_normal_inward`]).
    ///
    /// Cannot fail: a [`Mesh`] has at most [`MAX_TRIANGLES`](super::MAX_TRIANGLES) triangles,
    /// so each has a `u32` handle.
    pub fn new(mesh: &'m Mesh) -> Self {
        let ids: Vec<u32> = (0..mesh.triangles.len())
            .filter(|&t| mesh.face_normal_inward(t).is_some())
            .map(|t| u32::try_from(t).expect("a Mesh has at most MAX_TRIANGLES triangles"))
            .collect();
        let mut items: Vec<Item> = ids
            .iter()
            .map(|&id| {
                let [a, b, c] = mesh.triangles[id as usize].map(|i| mesh.vertices[i as usize]);
                Item {
                    centroid: std::array::from_fn(|k| ((a[k] + b[k] + c[k]) / 3.0) as f32),
                    id,
                }
            })
            .collect();
        let magnitude = mesh
            .vertices
            .iter()
            .flatten()
            .fold(0.0, |m: f64, x| m.max(x.abs()));
        let mut index = SurfaceIndex {
            mesh,
            nodes: Vec::with_capacity(2 * items.len().div_ceil(LEAF)),
            corners: Vec::with_capacity(items.len()),
            ids: Vec::with_capacity(items.len()),
            first: ids.first().copied(),
            magnitude,
        };
        if !items.is_empty() {
            index.build(&mut items);
        }
        index
    }

    /// The mesh this indexes.
    pub fn mesh(&self) -> &'m Mesh {
        self.mesh
    }

    /// Appends the subtree over `items` (pre-order: a node, its first subtree, its second) and
    /// returns its node's box and shape factor.
    fn build(&mut self, items: &mut [Item]) -> ([f64; 3], [f64; 3], f64) {
        let at = self.nodes.len();
        self.nodes.push(Node {
            lo: [0.0; 3],
            hi: [0.0; 3],
            shape: 0.0,
            index: 0,
            count: 0,
        });
        let (lo, hi, shape) = if items.len() <= LEAF {
            self.nodes[at].index = self.corners.len() as u32;
            self.nodes[at].count = items.len() as u32;
            let mut bounds = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3], 0.0);
            for item in items.iter() {
                let tri = self.mesh.triangles[item.id as usize];
                let corners @ [a, b, c] = tri.map(|i| self.mesh.vertices[i as usize]);
                let longest = [sub(b, a), sub(c, b), sub(a, c)]
                    .map(norm)
                    .into_iter()
                    .fold(0.0, f64::max);
                let n = norm(cross(sub(b, a), sub(c, a)));
                let lo = std::array::from_fn(|k| a[k].min(b[k]).min(c[k]));
                let hi = std::array::from_fn(|k| a[k].max(b[k]).max(c[k]));
                // Infinite for a triangle too thin for its area to be computed here: then every
                // box holding it is always visited.
                bounds = union(bounds, (lo, hi, longest.powi(5) / n.powi(3)));
                self.corners.push(corners);
                self.ids.push(item.id);
            }
            bounds
        } else {
            // The longest axis of the centroids' box; the median by count, so that the tree
            // stays balanced whatever the centroids (equal ones included).
            let (mut c_lo, mut c_hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
            for item in items.iter() {
                for k in 0..3 {
                    c_lo[k] = c_lo[k].min(item.centroid[k]);
                    c_hi[k] = c_hi[k].max(item.centroid[k]);
                }
            }
            let axis = (0..3)
                .max_by(|&i, &j| (c_hi[i] - c_lo[i]).total_cmp(&(c_hi[j] - c_lo[j])))
                .unwrap_or(0);
            let mid = items.len() / 2;
            items.select_nth_unstable_by(mid, |x, y| x.centroid[axis].total_cmp(&y.centroid[axis]));
            let (first, second) = items.split_at_mut(mid);
            let bounds = self.build(first);
            self.nodes[at].index = self.nodes.len() as u32;
            union(bounds, self.build(second))
        };
        let node = &mut self.nodes[at];
        (node.lo, node.hi, node.shape) = (lo, hi, shape);
        (lo, hi, shape)
    }

    /// A lower bound on the squared distance any triangle of `node` can come out at from `p`
    /// (`magnitude` the largest coordinate magnitude of the mesh and `p`): the squared distance to
    /// the box grown by the rounding margin (zero when the margin overflows or is NaN).
    // `k` indexes the query, the box's corners and the margin together.
    #[allow(clippy::needless_range_loop)]
    fn bound(node: &Node, p: [f64; 3], magnitude: f64) -> f64 {
        let mut far2 = 0.0;
        let mut far1 = 0.0;
        for k in 0..3 {
            let far = (p[k] - node.lo[k]).abs().max((p[k] - node.hi[k]).abs());
            far2 += far * far;
            far1 += far;
        }
        let margin = MARGIN * (far2 * node.shape + far1 + magnitude);
        let mut gap2 = 0.0;
        for k in 0..3 {
            // `f64::max` ignores a NaN: a NaN margin (∞·0) gives no gap, the box is visited.
            let gap = (node.lo[k] - margin - p[k])
                .max(p[k] - node.hi[k] - margin)
                .max(0.0);
            gap2 += gap * gap;
        }
        gap2
    }

    /// The point of the surface nearest `p`, with its triangle's inward normal: exactly
    /// [`Mesh::nearest_surface_point`]'s answer (see [Exactness](SurfaceIndex#exactness)).
    ///
    /// Returns `None` when `p` has a coordinate that is not finite (or the mesh has no triangle
    /// with a normal, which a validated mesh always has).
    pub fn nearest(&self, p: [f64; 3]) -> Option<SurfacePoint> {
        if !p.iter().all(|x| x.is_finite()) {
            return None;
        }
        let first = self.first?;
        let distance = |q: [f64; 3]| {
            let d = sub(q, p);
            dot(d, d)
        };
        // The brute force's first candidate, kept whatever its distance.
        let [a, b, c] = self.mesh.triangles[first as usize].map(|i| self.mesh.vertices[i as usize]);
        let q = nearest_on_triangle(p, a, b, c);
        let mut best = (distance(q), first, q);
        if !best.0.is_nan() {
            let magnitude = p.iter().fold(self.magnitude, |m, x| m.max(x.abs()));
            let mut stack = [(0u32, 0.0f64); MAX_DEPTH];
            stack[0] = (0, Self::bound(&self.nodes[0], p, magnitude));
            let mut len = 1;
            while len > 0 {
                len -= 1;
                let (at, bound) = stack[len];
                // `>`: a box that may hold a tie is visited, so that the lower index wins.
                if bound > best.0 {
                    continue;
                }
                let node = &self.nodes[at as usize];
                if node.count > 0 {
                    let start = node.index as usize;
                    for j in start..start + node.count as usize {
                        let [a, b, c] = self.corners[j];
                        let q = nearest_on_triangle(p, a, b, c);
                        let d = distance(q);
                        let id = self.ids[j];
                        if d < best.0 || (d == best.0 && id < best.1) {
                            best = (d, id, q);
                        }
                    }
                    continue;
                }
                let children = [at + 1, node.index];
                let bounds =
                    children.map(|child| Self::bound(&self.nodes[child as usize], p, magnitude));
                // The nearer child on top, so that it is searched first.
                let order = if bounds[0] <= bounds[1] {
                    [1, 0]
                } else {
                    [0, 1]
                };
                for i in order {
                    if bounds[i].is_nan() || bounds[i] <= best.0 {
                        stack[len] = (children[i], bounds[i]);
                        len += 1;
                    }
                }
            }
        }
        let (_, triangle, position) = best;
        let triangle = triangle as usize;
        Some(SurfacePoint {
            position,
            inward_normal: self.mesh.face_normal_inward(triangle).unwrap_or([0.0; 3]),
            triangle,
        })
    }
}

#[cfg(test)]
#[allow(clippy::needless_range_loop)] // the tests index coordinates of several arrays together
mod tests {
    use super::*;
    use crate::geometry::Rng;

    /// `true` when both answers are the same bit for bit (a NaN position included).
    fn same(a: Option<SurfacePoint>, b: Option<SurfacePoint>) -> bool {
        let bits = |v: [f64; 3]| v.map(f64::to_bits);
        match (a, b) {
            (None, None) => true,
            (Some(a), Some(b)) => {
                a.triangle == b.triangle
                    && bits(a.position) == bits(b.position)
                    && bits(a.inward_normal) == bits(b.inward_normal)
            }
            _ => false,
        }
    }

    /// Query points for `mesh`: its vertices, points on its edges (their ends, midpoints and
    /// random points), centroids, those pushed along the normals, random points in and around
    /// its box and far from it, each of the first few twice.
    fn queries(mesh: &Mesh, rng: &mut Rng, random: usize) -> Vec<[f64; 3]> {
        let v = &mesh.vertices;
        let mut points: Vec<[f64; 3]> = v.clone();
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for p in v {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let size = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
        for (t, tri) in mesh.triangles.iter().enumerate().take(400) {
            let [a, b, c] = tri.map(|i| v[i as usize]);
            let s = rng.uniform();
            points.push(std::array::from_fn(|k| (a[k] + b[k]) / 2.0));
            points.push(std::array::from_fn(|k| a[k] + s * (c[k] - a[k])));
            let centroid: [f64; 3] = std::array::from_fn(|k| (a[k] + b[k] + c[k]) / 3.0);
            points.push(centroid);
            if let Some(n) = mesh.face_normal_inward(t) {
                let h = size * (rng.uniform() - 0.5) * 0.2;
                points.push(std::array::from_fn(|k| centroid[k] + h * n[k]));
            }
        }
        for i in 0..random {
            // Near the surface mostly, some in the box, some far (up to 1000 sizes away).
            let spread = match i % 4 {
                0 | 1 => 0.05,
                2 => 1.0,
                _ => 10f64.powf(3.0 * rng.uniform()),
            };
            let base = match i % 4 {
                0 | 1 => v[rng.index(v.len())],
                _ => std::array::from_fn(|k| (lo[k] + hi[k]) / 2.0),
            };
            points.push(std::array::from_fn(|k| {
                base[k] + spread * size * (2.0 * rng.uniform() - 1.0)
            }));
        }
        let repeated: Vec<[f64; 3]> = points.iter().take(50).copied().collect();
        points.extend(repeated);
        points
    }

    fn check(mesh: &Mesh, seed: u64, random: usize) {
        let index = SurfaceIndex::new(mesh);
        let mut rng = Rng::new(seed);
        for p in queries(mesh, &mut rng, random) {
            let (got, want) = (index.nearest(p), mesh.nearest_surface_point(p));
            assert!(same(got, want), "{p:?}: {got:?} vs {want:?}");
        }
    }

    #[test]
    fn agrees_with_the_brute_force_on_generated_shapes() {
        let vase = [
            [0.0, 0.0],
            [1.0, 0.0],
            [1.4, 0.8],
            [0.6, 1.6],
            [0.9, 2.5],
            [0.0, 2.5],
        ];
        let c_shape = [
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [3.0, 2.0],
            [3.0, 3.0],
            [0.0, 3.0],
        ];
        let meshes = [
            Mesh::cuboid([1.0, 0.5, 0.25]).unwrap(),
            Mesh::cuboid([1e-3, 2e-3, 3e-3]).unwrap(),
            Mesh::uv_sphere(1.0, 12, 24).unwrap(),
            Mesh::uv_sphere(1e4, 40, 80).unwrap(),
            Mesh::lathe(&vase, 48).unwrap(),
            Mesh::extrude(&c_shape, 0.5).unwrap(),
        ];
        for (i, mesh) in meshes.iter().enumerate() {
            check(mesh, 100 + i as u64, 3000);
        }
    }

    #[test]
    fn ties_go_to_the_lowest_index_and_degenerate_triangles_are_skipped() {
        // A cuboid whose triangles are all listed twice (exact ties everywhere), plus degenerate
        // ones in front: a repeated index and collinear corners, the nearest if they counted.
        let cube = Mesh::cuboid([1.0; 3]).unwrap();
        let mut vertices = cube.vertices.clone();
        vertices.push([2.0, 0.0, 0.0]);
        vertices.push([3.0, 0.0, 0.0]);
        let n = vertices.len() as u32;
        let mut triangles = vec![[n - 2, n - 2, n - 1], [n - 2, n - 1, n - 1], [0, 0, 1]];
        vertices.push([2.5, 0.0, 0.0]);
        triangles.push([n - 2, n, n - 1]);
        triangles.extend(cube.triangles.iter().copied());
        triangles.extend(cube.triangles.iter().copied());
        let mesh = Mesh::try_new(vertices, triangles).unwrap();
        let index = SurfaceIndex::new(&mesh);
        let s = index.nearest([2.4, 0.0, 0.0]).unwrap();
        assert!(s.triangle >= 4 && s.triangle < 4 + 12, "{s:?}");
        check(&mesh, 7, 3000);
    }

    #[test]
    fn huge_and_non_finite_queries() {
        let meshes = [
            Mesh::uv_sphere(1.0, 8, 16).unwrap(),
            Mesh::cuboid([1e150, 1.0, 1e-150]).unwrap(),
        ];
        for mesh in &meshes {
            let index = SurfaceIndex::new(mesh);
            for x in [1e100, 1e154, 1e160, 1e200, 1e300, f64::MAX] {
                for p in [[x, 0.1, 0.2], [-x, x, 0.3], [0.5, x / 3.0, -x]] {
                    let (got, want) = (index.nearest(p), mesh.nearest_surface_point(p));
                    assert!(same(got, want), "{p:?}: {got:?} vs {want:?}");
                }
            }
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                assert_eq!(index.nearest([0.0, bad, 0.0]), None);
            }
        }
    }

    fn scale_to_unit(v: [f64; 3]) -> [f64; 3] {
        let length = norm(v);
        v.map(|x| x / length)
    }

    /// Random triangles of every shape — slivers (needles and flat caps) at many scales and
    /// offsets — and queries near and far: how far rounding carries a computed point nearer
    /// than the triangle's box, relative to `ε·(R²·S + R₁ + M)`; the pruning margin is 4096 of
    /// these.
    #[test]
    fn the_margin_covers_rounding_on_slivers() {
        let mut rng = Rng::new(5);
        let mut worst: f64 = 0.0;
        for _ in 0..10_000 {
            let scale = 10f64.powf(rng.uniform_in(-6.0, 6.0));
            let offset: [f64; 3] = std::array::from_fn(|_| {
                scale * 10f64.powf(rng.uniform_in(-2.0, 4.0)) * rng.normal()
            });
            let a: [f64; 3] = std::array::from_fn(|_| rng.normal());
            let mut b: [f64; 3] = std::array::from_fn(|_| rng.normal());
            let mut c: [f64; 3] = std::array::from_fn(|_| rng.normal());
            let thin = 10f64.powf(rng.uniform_in(-12.0, 0.0));
            match rng.below(3) {
                // A needle: c near the line ab, between a and b.
                0 => {
                    let s = rng.uniform();
                    c = std::array::from_fn(|k| a[k] + s * (b[k] - a[k]) + thin * c[k]);
                }
                // A cap: c near the line ab, beyond b.
                1 => {
                    let s = 1.0 + 3.0 * rng.uniform();
                    c = std::array::from_fn(|k| a[k] + s * (b[k] - a[k]) + thin * c[k]);
                }
                // A short edge: b near a.
                _ => b = std::array::from_fn(|k| a[k] + thin * b[k]),
            }
            let [a, b, c] = [a, b, c].map(|v| std::array::from_fn(|k| offset[k] + scale * v[k]));
            let longest = [sub(b, a), sub(c, b), sub(a, c)]
                .map(norm)
                .into_iter()
                .fold(0.0, f64::max);
            let n = norm(cross(sub(b, a), sub(c, a)));
            if n == 0.0 {
                continue;
            }
            let node = Node {
                lo: std::array::from_fn(|k| a[k].min(b[k]).min(c[k])),
                hi: std::array::from_fn(|k| a[k].max(b[k]).max(c[k])),
                shape: longest.powi(5) / n.powi(3),
                index: 0,
                count: 1,
            };
            let normal = scale_to_unit(cross(sub(b, a), sub(c, a)));
            for _ in 0..50 {
                let away = scale * 10f64.powf(rng.uniform_in(-20.0, 3.0));
                let p: [f64; 3] = if rng.below(2) == 0 {
                    // Around a point of the triangle (or of its plane, beyond an edge).
                    let w = [rng.uniform(), rng.uniform(), rng.uniform()];
                    let s = w[0] + w[1] + w[2];
                    let x = if rng.below(2) == 0 {
                        1.0
                    } else {
                        rng.uniform_in(-3.0, 3.0)
                    };
                    let w = [x * w[0] / s, x * w[1] / s, 1.0 - x * (w[0] + w[1]) / s];
                    std::array::from_fn(|k| {
                        w[0] * a[k] + w[1] * b[k] + w[2] * c[k] + away * rng.normal()
                    })
                } else {
                    // Next to the line of an edge, inside or outside, near the plane: where
                    // the regions of the search meet.
                    let (e0, e1, e2) = [(a, b, c), (b, c, a), (c, a, b)][rng.index(3)];
                    let edge = sub(e1, e0);
                    let mut side = scale_to_unit(cross(normal, edge));
                    if dot(side, sub(e2, e0)) < 0.0 {
                        side = side.map(|x| -x);
                    }
                    let t = rng.uniform_in(-1.0, 2.0);
                    let across = scale * 10f64.powf(rng.uniform_in(-20.0, 0.0));
                    let across = if rng.below(2) == 0 { across } else { -across };
                    let height = away * rng.normal();
                    std::array::from_fn(|k| {
                        e0[k] + t * edge[k] + across * side[k] + height * normal[k]
                    })
                };
                let q = nearest_on_triangle(p, a, b, c);
                let d = sub(q, p);
                let computed = dot(d, d).sqrt();
                let mut far2 = 0.0;
                let mut far1 = 0.0;
                let mut gap2 = 0.0;
                for k in 0..3 {
                    let far = (p[k] - node.lo[k]).abs().max((p[k] - node.hi[k]).abs());
                    far2 += far * far;
                    far1 += far;
                    let gap = (node.lo[k] - p[k]).max(p[k] - node.hi[k]).max(0.0);
                    gap2 += gap * gap;
                }
                let magnitude = [a, b, c, p]
                    .iter()
                    .flatten()
                    .fold(0.0, |m: f64, x| m.max(x.abs()));
                let unit = f64::EPSILON * (far2 * node.shape + far1 + magnitude);
                worst = worst.max((gap2.sqrt() - computed) / unit);
                // The bound the index uses, with its margin.
                assert!(SurfaceIndex::bound(&node, p, magnitude) <= dot(d, d));
            }
        }
        eprintln!("worst excursion: {worst} units");
        assert!(worst < 4.0, "{worst}");
    }
}
