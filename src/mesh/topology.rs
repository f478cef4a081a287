//! Edge topology: is the surface closed and consistently oriented?

use std::collections::HashMap;

/// How the triangles of a [`Mesh`](super::Mesh) share their edges.
///
/// Triangles with a repeated vertex index take no part (they are counted in
/// [`degenerate_triangles`](Topology::degenerate_triangles)); triangles with three distinct
/// indices but collinear corners do take part, since they still connect their edges.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Topology {
    /// Undirected edges (pairs of vertex indices) used by at least one triangle.
    pub edges: usize,
    /// Edges used by exactly one triangle: the border of a hole or of an open sheet.
    pub boundary_edges: usize,
    /// Edges used by exactly two triangles that traverse it in the same direction, so one of the
    /// two is wound the other way round.
    pub misoriented_edges: usize,
    /// Edges used by three or more triangles.
    pub non_manifold_edges: usize,
    /// Triangles with a repeated vertex index.
    pub degenerate_triangles: usize,
}

impl Topology {
    /// Counts the edges of `triangles` (whose indices are already known to be in range).
    pub(in crate::mesh) fn of(triangles: &[[u32; 3]]) -> Topology {
        // Undirected edge (low, high) → (uses low→high, uses high→low).
        let mut uses: HashMap<(u32, u32), (u32, u32)> = HashMap::with_capacity(triangles.len() * 2);
        let mut degenerate_triangles = 0;
        for t in triangles {
            if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
                degenerate_triangles += 1;
                continue;
            }
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                let entry = uses.entry((a.min(b), a.max(b))).or_default();
                if a < b {
                    entry.0 = entry.0.saturating_add(1);
                } else {
                    entry.1 = entry.1.saturating_add(1);
                }
            }
        }
        let mut topology = Topology {
            edges: uses.len(),
            degenerate_triangles,
            ..Topology::default()
        };
        for &(forward, backward) in uses.values() {
            match (forward, backward) {
                (1, 1) => {}
                (1, 0) | (0, 1) => topology.boundary_edges += 1,
                (2, 0) | (0, 2) => topology.misoriented_edges += 1,
                _ => topology.non_manifold_edges += 1,
            }
        }
        topology
    }

    /// `true` when the surface is closed and consistently oriented: every edge is shared by
    /// exactly two triangles that traverse it in opposite directions (so each directed edge occurs
    /// once), and there is at least one edge.
    ///
    /// Such a surface encloses a well-defined volume (possibly several disjoint pieces, possibly
    /// self-intersecting — that is not checked).
    pub fn is_closed(&self) -> bool {
        self.edges > 0
            && self.boundary_edges == 0
            && self.misoriented_edges == 0
            && self.non_manifold_edges == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TETRA: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];

    #[test]
    fn a_tetrahedron_is_closed() {
        let t = Topology::of(&TETRA);
        assert_eq!(t.edges, 6);
        assert!(t.is_closed(), "{t:?}");
    }

    #[test]
    fn a_missing_face_leaves_a_boundary() {
        let t = Topology::of(&TETRA[..3]);
        assert_eq!(t.boundary_edges, 3);
        assert!(!t.is_closed());
    }

    #[test]
    fn one_flipped_face_is_misoriented() {
        let mut tris = TETRA;
        tris[0] = [0, 1, 2];
        let t = Topology::of(&tris);
        assert_eq!(t.misoriented_edges, 3);
        assert!(!t.is_closed());
    }

    #[test]
    fn a_fin_is_non_manifold_and_degenerate_triangles_are_skipped() {
        let mut tris = TETRA.to_vec();
        tris.push([0, 1, 4]);
        tris.push([0, 0, 1]);
        let t = Topology::of(&tris);
        assert_eq!(t.non_manifold_edges, 1);
        assert_eq!(t.degenerate_triangles, 1);
        assert!(!t.is_closed());
    }
}
