//! Locating a new point against a built hull by a walk over the facets, instead of a scan of all
//! of them: what makes [`Hull::add_points`] cost what the new points change.
//!
//! Seen from a point `c` strictly inside the hull, the facets' cones `c + cone(F − c)` tile
//! space, and the ray from `c` through a new point `p` leaves the hull through the facet whose
//! cone holds `p`. That facet settles `p` exactly: if `p` is strictly beyond it, it joins its
//! outside set (any facet it is beyond keeps the engine's invariant); otherwise `p` lies in
//! `conv(c ∪ F)`, inside the hull, weakly beneath every facet, and needs no outside set.
//!
//! The facet is found by a walk: `p` is in `F`'s cone exactly when, for every vertex `v_i` of
//! `F`, `c` is not strictly beyond the hyperplane through `F` with `v_i` replaced by `p` (Cramer's
//! rule on `p − c = Σ λ_i (v_i − c)`: that orientation has the sign of `λ_i` times the sign
//! `c` has against `F` itself, which is negative); when it is, the walk crosses to neighbour `i`,
//! opposite `v_i`. Every test is exact (a filtered [`FacetPlane`] with its exact fallback). A
//! walk that always takes the first such neighbour can cycle in a triangulation that is not
//! Delaunay, so the neighbour tried first is chosen at random (Devillers, Pion and Teillaud,
//! "Walking in a triangulation", 2002: the stochastic walk ends with probability one); a walk
//! longer than the facet count falls back on the scan, which is always right.

use super::{FacetId, Hull};
use crate::predicates::{FacetPlane, Sign};

/// The state of the walks of one [`Hull::add_points`] call: the interior point they start their
/// rays from, where the last walk ended, and the random choice of the first neighbour tried.
#[derive(Clone, Debug)]
pub(in crate::hull) struct Locator<const D: usize> {
    /// Strictly inside every live facet (checked exactly), in the hull's internal coordinates.
    centre: [f64; D],
    start: FacetId,
    state: u64,
}

impl<const D: usize> Hull<D> {
    /// A locator for this hull: the mean of its vertices, when that is strictly beneath every
    /// live facet (checked exactly, as one point's scan costs); `None` otherwise (a sliver hull
    /// whose rounded mean is not strictly inside), and then points are located by the scan.
    pub(in crate::hull) fn locator(&self) -> Option<Locator<D>> {
        let vertices = self.vertex_indices();
        if vertices.is_empty() {
            return None;
        }
        let mut sum = [0.0; D];
        for &v in &vertices {
            for (s, x) in sum.iter_mut().zip(&self.points[v]) {
                *s += x;
            }
        }
        let centre = sum.map(|s| s / vertices.len() as f64);
        let mut start = None;
        for (id, _) in self.facets() {
            if self.side(id, &centre) != Sign::Negative {
                return None;
            }
            start.get_or_insert(id);
        }
        Some(Locator {
            centre,
            start: start?,
            state: 0x9e37_79b9_7f4a_7c15,
        })
    }

    /// The facet whose cone from the locator's centre holds `p` (internal coordinates) and the
    /// exact side of `p` against it; `None` when the walk grew longer than the facet count.
    pub(in crate::hull) fn locate(
        &self,
        locator: &mut Locator<D>,
        p: &[f64; D],
    ) -> Option<(FacetId, Sign)> {
        let mut current = locator.start;
        if !self.facets[current.index()].alive {
            current = self.facets().next()?.0;
        }
        for _ in 0..=self.live {
            let facet = &self.facets[current.index()];
            let vertices = facet.vertices.map(|v| self.points[v as usize]);
            // xorshift64: which vertex is tried first.
            locator.state ^= locator.state << 13;
            locator.state ^= locator.state >> 7;
            locator.state ^= locator.state << 17;
            let first = (locator.state % D as u64) as usize;
            let mut next = None;
            for k in 0..D {
                let i = (first + k) % D;
                let mut replaced = vertices;
                replaced[i] = *p;
                let plane = FacetPlane::new(&replaced);
                if plane.side(&locator.centre, || replaced) == Sign::Positive {
                    next = Some(facet.neighbors[i]);
                    break;
                }
            }
            match next {
                Some(n) => current = n,
                None => {
                    locator.start = current;
                    return Some((current, self.side(current, p)));
                }
            }
        }
        None
    }
}
