//! A ball tree answering support queries `max_p v·p` over a fixed point set.

use super::vector::{dot, sub};

/// Leaves hold at most this many points: small enough that a leaf's ball is tight, large enough
/// that the tree is shallow (measured on object wrench spaces of 50,000 six-dimensional points:
/// 16–32 is the flat optimum).
const LEAF: usize = 24;

/// The support function of a finite point set, `h(v) = max_p v·p`, answered by branch and bound
/// over a ball tree instead of a scan of every point.
///
/// Hand-written rather than taken from a crate: spatial-index crates answer nearest-neighbour
/// and range queries, not the maximum of a linear function, and this one is forty lines.
///
/// The answer is the exact maximum of the floating-point dot products, except that a point whose
/// dot product exceeds the answer by less than about 10⁻¹² of `|v|·(|centre| + radius)` of its
/// ball may be missed (pruning bounds carry that slack against rounding the other way).
///
/// ```
/// use pqhull::geometry::SupportIndex;
/// let points: Vec<[f64; 2]> = (0..100)
///     .map(|i| {
///         let t = i as f64 * 0.0628;
///         [t.cos(), 2.0 * t.sin()]
///     })
///     .collect();
/// let index = SupportIndex::new(&points);
/// let (value, at) = index.support(&[0.0, 1.0]).unwrap();
/// let best = points.iter().map(|p| p[1]).fold(f64::MIN, f64::max);
/// assert_eq!(value, best);
/// assert_eq!(points[at][1], best);
/// ```
#[derive(Clone, Debug, Default)]
pub struct SupportIndex<const D: usize> {
    /// Points reordered so that every node covers a contiguous range.
    points: Vec<[f64; D]>,
    /// Original index of each reordered point.
    original: Vec<u32>,
    /// Reordered position of each original point (the inverse of `original`).
    position: Vec<u32>,
    nodes: Vec<Node<D>>,
}

#[derive(Clone, Debug)]
struct Node<const D: usize> {
    centre: [f64; D],
    /// Rounded up: every point of the node lies within it of the centre.
    radius: f64,
    /// |centre|, for the rounding slack of the bound.
    centre_norm: f64,
    /// The node's bounding box.
    lo: [f64; D],
    hi: [f64; D],
    start: u32,
    end: u32,
    /// Children (indices into `nodes`), or `None` for a leaf.
    children: Option<(u32, u32)>,
}

impl<const D: usize> SupportIndex<D> {
    /// Builds the tree over `points` (O(n log n)).
    pub fn new(points: &[[f64; D]]) -> Self {
        let mut index = SupportIndex {
            points: points.to_vec(),
            original: (0..points.len() as u32).collect(),
            position: Vec::new(),
            nodes: Vec::new(),
        };
        if !points.is_empty() {
            index.build(0, points.len());
        }
        index.position = vec![0; points.len()];
        for (at, &i) in index.original.iter().enumerate() {
            index.position[i as usize] = at as u32;
        }
        index
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether there are no points.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Point `index` (in the order given to [`new`](Self::new)).
    ///
    /// # Panics
    /// If `index >= self.len()`.
    pub fn point(&self, index: usize) -> [f64; D] {
        self.points[self.position[index] as usize]
    }

    /// The points in the order they were given.
    pub fn points_in_input_order(&self) -> Vec<[f64; D]> {
        let mut points = vec![[0.0; D]; self.points.len()];
        for (p, &i) in self.points.iter().zip(&self.original) {
            points[i as usize] = *p;
        }
        points
    }

    /// Builds the node covering `start..end` and its subtree; returns its index.
    fn build(&mut self, start: usize, end: usize) -> u32 {
        let slice = &self.points[start..end];
        let mut lo = [f64::INFINITY; D];
        let mut hi = [f64::NEG_INFINITY; D];
        for p in slice {
            for c in 0..D {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
        let centre: [f64; D] = std::array::from_fn(|c| 0.5 * (lo[c] + hi[c]));
        let radius = slice
            .iter()
            .map(|p| dot(sub(*p, centre), sub(*p, centre)).sqrt())
            .fold(0.0, f64::max)
            * (1.0 + 1e-12);
        let id = self.nodes.len() as u32;
        self.nodes.push(Node {
            centre,
            radius,
            centre_norm: dot(centre, centre).sqrt(),
            lo,
            hi,
            start: start as u32,
            end: end as u32,
            children: None,
        });
        if end - start > LEAF {
            // Split at the median of the widest coordinate.
            let axis = (0..D)
                .max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b])))
                .unwrap_or(0);
            let mid = start + (end - start) / 2;
            let mut order: Vec<usize> = (start..end).collect();
            order.select_nth_unstable_by(mid - start, |&a, &b| {
                self.points[a][axis].total_cmp(&self.points[b][axis])
            });
            let points: Vec<[f64; D]> = order.iter().map(|&i| self.points[i]).collect();
            let original: Vec<u32> = order.iter().map(|&i| self.original[i]).collect();
            self.points[start..end].copy_from_slice(&points);
            self.original[start..end].copy_from_slice(&original);
            let left = self.build(start, mid);
            let right = self.build(mid, end);
            self.nodes[id as usize].children = Some((left, right));
        }
        id
    }

    /// An upper bound of `v·p` over node `n`'s points.
    fn bound(&self, n: u32, v: &[f64; D], v_norm: f64) -> f64 {
        let node = &self.nodes[n as usize];
        let reach = v_norm * node.radius;
        let slack = 1e-12 * (v_norm * node.centre_norm + reach);
        let ball = dot(*v, node.centre) + reach;
        let corner: f64 = (0..D)
            .map(|c| {
                if v[c] >= 0.0 {
                    v[c] * node.hi[c]
                } else {
                    v[c] * node.lo[c]
                }
            })
            .sum();
        ball.min(corner) + slack
    }

    /// An upper bound on the norm of every point (the root ball's reach); 0 for an empty set.
    pub fn norm_bound(&self) -> f64 {
        self.nodes
            .first()
            .map_or(0.0, |root| (root.centre_norm + root.radius) * (1.0 + 1e-15))
    }

    /// A cheap upper bound on [`support`](Self::support)`(v)`'s value: the largest ball-and-box
    /// bound over the tree's nodes `depth` levels down (at most 2^depth nodes; depth ≤ 8), each
    /// node's bound capped by its ancestors' (so the bound never grows with depth).
    /// `f64::NEG_INFINITY` for an empty set.
    ///
    /// ```
    /// use pqhull::geometry::SupportIndex;
    /// let points: Vec<[f64; 2]> = (0..500).map(|i| [(i as f64).cos(), (i as f64).sin()]).collect();
    /// let index = SupportIndex::new(&points);
    /// let v = [0.3, -0.8];
    /// let (value, _) = index.support(&v).unwrap();
    /// assert!(index.upper_bound(&v, 3) >= value);
    /// ```
    pub fn upper_bound(&self, v: &[f64; D], depth: usize) -> f64 {
        if self.points.is_empty() {
            return f64::NEG_INFINITY;
        }
        let v_norm = dot(*v, *v).sqrt();
        let mut best = f64::NEG_INFINITY;
        // (node, level, the smallest bound on the path from the root: a parent's bound holds for
        // its children's points too, and a child's ball can reach beyond its parent's).
        let mut stack = [(0u32, 0usize, f64::INFINITY); 10];
        let mut len = 1;
        let depth = depth.min(8);
        while len > 0 {
            len -= 1;
            let (n, level, above) = stack[len];
            let bound = self.bound(n, v, v_norm).min(above);
            match self.nodes[n as usize].children {
                Some((left, right)) if level < depth => {
                    stack[len] = (left, level + 1, bound);
                    stack[len + 1] = (right, level + 1, bound);
                    len += 2;
                }
                _ => best = best.max(bound),
            }
        }
        best
    }

    /// `max_p v·p` and the (original) index of a point attaining it; `None` for an empty set.
    pub fn support(&self, v: &[f64; D]) -> Option<(f64, usize)> {
        self.support_near(v, None)
    }

    /// [`support`](Self::support), starting from point `hint` (an original index) as the best so
    /// far: the same answer, found sooner when the hint is nearly as good — as the support point
    /// of a neighbouring direction is, for a strategy querying the normals of adjacent facets
    /// one after another. A hint out of range is ignored.
    ///
    /// ```
    /// use pqhull::geometry::SupportIndex;
    /// let points = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.7, 0.7]];
    /// let index = SupportIndex::new(&points);
    /// assert_eq!(index.support_near(&[1.0, 1.0], Some(0)), index.support(&[1.0, 1.0]));
    /// assert_eq!(index.support_near(&[1.0, 1.0], Some(9)), Some((1.4, 3)));
    /// ```
    pub fn support_near(&self, v: &[f64; D], hint: Option<usize>) -> Option<(f64, usize)> {
        if self.points.is_empty() {
            return None;
        }
        let v_norm = dot(*v, *v).sqrt();
        let mut best = (f64::NEG_INFINITY, 0usize);
        if let Some(&at) = hint.and_then(|h| self.position.get(h)) {
            best = (
                dot(*v, self.points[at as usize]),
                self.original[at as usize] as usize,
            );
        }
        // Depth-first, the child with the larger bound first. Median splits make the tree at most
        // 33 levels deep for a u32-indexed set, and each level leaves one sibling waiting, so a
        // fixed array holds the stack: a query allocates nothing (it runs once per new facet).
        let mut stack = [(0u32, 0.0f64); 40];
        let mut len = 1;
        stack[0] = (0, self.bound(0, v, v_norm));
        while len > 0 {
            len -= 1;
            let (n, bound) = stack[len];
            if bound <= best.0 {
                continue;
            }
            let node = &self.nodes[n as usize];
            match node.children {
                None => {
                    for i in node.start as usize..node.end as usize {
                        let value = dot(*v, self.points[i]);
                        if value > best.0 {
                            best = (value, self.original[i] as usize);
                        }
                    }
                }
                Some((left, right)) => {
                    // A parent's bound holds for its children's points too.
                    let (bl, br) = (
                        self.bound(left, v, v_norm).min(bound),
                        self.bound(right, v, v_norm).min(bound),
                    );
                    let (first, second) = if bl > br {
                        ((right, br), (left, bl))
                    } else {
                        ((left, bl), (right, br))
                    };
                    stack[len] = first;
                    stack[len + 1] = second;
                    len += 2;
                }
            }
        }
        Some(best)
    }
}

#[cfg(test)]
mod tests {
    use super::SupportIndex;
    use crate::rbox::{Family, generate};

    #[test]
    fn support_equals_a_scan() {
        for (family, n) in [
            (Family::SphereSurface, 5000),
            (Family::UniformCube, 3000),
            (Family::CubeCornersDiamond, 64),
        ] {
            let points = generate::<6>(&family, n, 4);
            let index = SupportIndex::new(&points);
            let directions = generate::<6>(&Family::UniformCube, 300, 5);
            for v in &directions {
                let scan = points
                    .iter()
                    .map(|p| v.iter().zip(p).map(|(a, b)| a * b).sum::<f64>())
                    .fold(f64::NEG_INFINITY, f64::max);
                let (value, at) = index.support(v).unwrap();
                assert_eq!(value, scan, "{family}");
                let again: f64 = v.iter().zip(&points[at]).map(|(a, b)| a * b).sum();
                assert_eq!(again, value);
                // Any hint, good or bad, gives the same maximum.
                for hint in [0, at, n / 2, n - 1, n + 5] {
                    let (near, _) = index.support_near(v, Some(hint)).unwrap();
                    assert_eq!(near, scan, "{family}, hint {hint}");
                }
                // The cheap bound is a bound at every depth, and tightens with depth.
                let bounds: Vec<f64> = (0..=8).map(|d| index.upper_bound(v, d)).collect();
                assert!(
                    bounds.iter().all(|&b| b >= scan),
                    "{family}: {bounds:?} < {scan}"
                );
                assert!(
                    bounds.windows(2).all(|w| w[1] <= w[0]),
                    "{family}: {bounds:?}"
                );
            }
        }
        assert!(
            SupportIndex::<3>::new(&[])
                .support(&[1.0, 0.0, 0.0])
                .is_none()
        );
    }
}
