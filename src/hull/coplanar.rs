//! A full build in two phases: coplanar facets kept, then the extreme points alone.
//!
//! A facet whose hyperplane holds the new point exactly counts as visible by default: removed
//! and coned again from the new point, which is what keeps a point inside a flat face out of
//! the vertices. On input with large exactly coplanar faces — cube corners with points on the
//! faces, grids, lattices — every point added on a face then removes and cones again the whole
//! region of that face: the 6-D grid {0, …, 3}^6 created ten times the facets of its hull.
//!
//! [`FarthestPoint`](super::FarthestPoint) therefore builds in up to two phases. The first keeps
//! such facets (as [`Hull::keep_coplanar_facets`] does for the grasp layer): the result is the
//! right polytope, every facet in one of its facets' hyperplanes, but points on its faces may be
//! vertices. When the first phase never kept a facet, it was the default build, decision for
//! decision, and it is the result. Otherwise the vertices that may have stopped being extreme
//! are examined, exactly ([`Hull::non_extreme`]). If all are extreme, the first phase's hull is
//! the result. If not, the hull is built again on the extreme vertices alone: every other input
//! point lies in their hull, so this second hull is the convex hull of the input, and since all
//! its points are extreme it keeps coplanar facets too, with the extreme points as its only
//! vertices. Every decision of both phases is exact.

use super::{FacetId, Hull};
use crate::geometry::gram::positive_definite_after_shift;
use crate::predicates::Sign;

/// Where a build is in a full build's phases.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(in crate::hull) enum Phase {
    /// Not in a full build's phases: coplanar facets go, unless `Hull::keep_coplanar_facets`.
    None,
    /// Coplanar facets kept, their vertices marked as suspects.
    First,
    /// On the extreme points alone: coplanar facets kept.
    Second,
}

impl<const D: usize> Hull<D> {
    /// Starts a full build's first phase (coplanar facets kept), when this is a build from its
    /// initial simplex (not points added to a built hull) that nothing else asked to keep them.
    /// Called by [`FarthestPoint`](super::FarthestPoint) before its first
    /// expansion.
    pub(in crate::hull) fn begin_full_build(&mut self) {
        #[cfg(test)]
        if self.scratch.plain_coplanar {
            return;
        }
        if !self.keep_coplanar && self.stats.expansions == 0 {
            self.phase = Phase::First;
            self.scratch.suspect.clear();
            self.scratch.suspect.resize(self.points.len(), false);
        }
    }

    /// Ends a full build's first phase, once no outside set is left. When a coplanar facet was
    /// kept and some vertex is not an extreme point (decided exactly: [`Self::non_extreme`]),
    /// starts the second phase on the extreme vertices alone (every facet and plane freed, their
    /// initial simplex built and the others assigned to it) and returns `true`; otherwise the
    /// hull is the result and it returns `false`.
    pub(in crate::hull) fn end_first_phase(&mut self) -> bool {
        if self.phase != Phase::First {
            return false;
        }
        // Unless the second phase starts below, the build is over.
        self.phase = Phase::None;
        if !self.kept_in_first_phase {
            return false;
        }
        let mut candidates = std::mem::take(&mut self.scratch.orphans);
        candidates.clear();
        let mut buffers = std::mem::take(&mut self.scratch.examination);
        let removed = self.non_extreme(&mut candidates, &mut buffers);
        // The extreme points span the polytope, so a simplex exists among them; were it not
        // found, the first phase's hull (the right polytope) would stay.
        let simplex = (removed > 0).then(|| {
            buffers.coordinates.clear();
            buffers
                .coordinates
                .extend(candidates.iter().map(|&p| self.points[p as usize]));
            super::build::initial_simplex(&buffers.coordinates, &mut self.scratch.residuals)
                .ok()
                .map(|(simplex, _)| simplex)
        });
        self.scratch.examination = buffers;
        let Some(Some(local)) = simplex else {
            self.scratch.orphans = candidates;
            return false;
        };
        let simplex: [usize; super::build::MAX_SIMPLEX] =
            std::array::from_fn(|k| candidates[local[k.min(D)]] as usize);
        self.free_every_facet();
        // Every point of the second phase is extreme, so a kept coplanar facet can no longer
        // leave a point that is not one among the vertices: it keeps them too.
        self.phase = Phase::Second;
        let simplex = &simplex[..=D];
        let all = self.found(simplex);
        let all = &all[..=D];
        self.stats.points_processed += D + 1;
        for &p in &candidates {
            if !simplex.contains(&(p as usize)) {
                self.assign(p, all);
            }
        }
        if self.trace.is_some() {
            self.record_second_phase(removed, candidates.len());
        }
        self.scratch.orphans = candidates;
        true
    }

    /// Writes into `extreme` the hull's vertices that are extreme points of the input, and
    /// returns how many vertices are not (points on a face of the polytope, left by the kept
    /// facets). Decided exactly, for every vertex `v`:
    ///
    /// * the live facets around `v` cover a neighbourhood of `v` on the polytope's boundary,
    ///   each inside one of its facets, so their hyperplanes are exactly the polytope's facet
    ///   hyperplanes through `v`;
    /// * `v` is extreme if and only if those hyperplanes meet in `v` alone, that is, if their
    ///   normals span R^D;
    /// * otherwise they meet in the smallest face holding `v`, of dimension one or more, which
    ///   the facets triangulate with `v` as a vertex: an edge of some facet around `v` then lies
    ///   in that face, and its other end lies on every one of those hyperplanes.
    ///
    /// Only a vertex of a facet kept with the new point on its plane can have stopped being
    /// extreme: a vertex stays one only through a facet around it that the expansion kept, and
    /// when a point makes it non-extreme every such facet holds that point on its plane (it lies
    /// in the face that the vertex is now inside of). A new point is always extreme, being
    /// strictly beyond the hull. So only these *suspects* are examined: first the normals of the
    /// precise facets around one (a floating-point certificate that they span R^D, with a margin
    /// far above their errors), then, if that fails, the exact test: `v` is not extreme exactly
    /// when one of its neighbours (the other vertices of the facets around it) lies on the plane
    /// of every facet around it — one exact side test per (neighbour, coplanar region), stopped
    /// at the first that is not zero.
    fn non_extreme(&self, extreme: &mut Vec<u32>, buffers: &mut Examination<D>) -> usize {
        let n = self.points.len();
        let suspect = &self.scratch.suspect;
        let is_suspect = |v: usize| suspect.get(v).copied().unwrap_or(true);
        let Examination {
            start,
            fill,
            around,
            vertex,
            regions,
            ..
        } = buffers;
        // The facets around each suspect vertex, as a compressed list: `start[v]..start[v + 1]`.
        start.clear();
        start.resize(n + 1, 0);
        vertex.clear();
        vertex.resize(n, false);
        for (_, facet) in self.facets() {
            for &v in &facet.vertices {
                vertex[v as usize] = true;
                if is_suspect(v as usize) {
                    start[v as usize + 1] += 1;
                }
            }
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        fill.clear();
        fill.extend_from_slice(start);
        around.clear();
        around.resize(start[n] as usize, FacetId::NONE);
        for (id, facet) in self.facets() {
            for &v in &facet.vertices {
                if is_suspect(v as usize) {
                    around[fill[v as usize] as usize] = id;
                    fill[v as usize] += 1;
                }
            }
        }
        // `fill[w] == v + 1` marks `w` as a neighbour of `v` already tried.
        fill.iter_mut().for_each(|f| *f = 0);
        let mut removed = 0;
        for v in 0..n {
            if !vertex[v] {
                continue;
            }
            let (a, b) = (start[v] as usize, start[v + 1] as usize);
            if a == b || self.normals_span(&around[a..b]) {
                extreme.push(v as u32); // not a suspect, or certified
                continue;
            }
            regions.clear();
            regions.extend(around[a..b].iter().map(|&f| (self.region(f), f)));
            regions.sort_unstable_by_key(|&(region, _)| region);
            regions.dedup_by_key(|(region, _)| *region);
            let mut on_a_face = false;
            'neighbours: for &f in &around[a..b] {
                for &w in &self.facets[f.index()].vertices {
                    if w as usize == v || fill[w as usize] == v as u32 + 1 {
                        continue;
                    }
                    fill[w as usize] = v as u32 + 1;
                    let on_every_plane = regions.iter().all(|&(_, g)| {
                        self.facets[g.index()].vertices.contains(&w)
                            || self.side_of_index(g, w) == Sign::Zero
                    });
                    if on_every_plane {
                        on_a_face = true;
                        break 'neighbours;
                    }
                }
            }
            if on_a_face {
                removed += 1;
            } else {
                extreme.push(v as u32);
            }
        }
        removed
    }

    /// Whether the unit normals of the precise facets among `facets` certainly span R^D (so a
    /// vertex they all hold is extreme): `G − μI` is positive definite, G = Σ nnᵀ over those k
    /// normals, μ = 10⁻⁶·k ([`positive_definite_after_shift`]). Why that is a proof:
    ///
    /// * success bounds the computed G's smallest eigenvalue below by μ − γ_{D+1}·k, and the
    ///   rounding of G's sums moves it by at most γ_k·k more: λ_min ≥ 0.9·10⁻⁶·k for any k
    ///   below 10⁹, so the matrix N of the computed normals has σ_min(N) ≥ 0.9·10⁻³·√k;
    /// * a precise normal is within 10⁻¹⁰ of the exact one (its cofactors' error bound is
    ///   10⁻¹¹ of the largest: `Facet::normal_is_precise`), so ‖N − N_exact‖₂ ≤ √k·10⁻¹⁰,
    ///   far below σ_min(N): the exact normals span R^D too.
    ///
    /// `false` says nothing (the exact test decides).
    fn normals_span(&self, facets: &[FacetId]) -> bool {
        let mut gram = [[0.0f64; D]; D];
        let mut k = 0.0;
        for &f in facets {
            let facet = &self.facets[f.index()];
            if !facet.precise {
                continue;
            }
            let m = facet.normal;
            for (row, &x) in gram.iter_mut().zip(&m) {
                for (entry, &y) in row.iter_mut().zip(&m) {
                    *entry += x * y;
                }
            }
            k += 1.0;
        }
        k > 0.0 && positive_definite_after_shift(&gram, 1e-6 * k)
    }
}

/// Buffers of [`Hull::end_first_phase`], kept between builds so that a loop of builds (the
/// GWS volume of a batch of grasps) allocates nothing for them in steady state.
#[derive(Clone, Debug, Default)]
pub(in crate::hull) struct Examination<const D: usize> {
    /// The facets around each suspect vertex: `around[start[v]..start[v + 1]]`.
    start: Vec<u32>,
    around: Vec<FacetId>,
    /// A cursor per vertex while `around` is filled, then the neighbour marks.
    fill: Vec<u32>,
    /// Whether each input point is a vertex.
    vertex: Vec<bool>,
    /// One facet per coplanar region around the vertex examined.
    regions: Vec<(u64, FacetId)>,
    /// The extreme vertices' coordinates, for their initial simplex.
    coordinates: Vec<[f64; D]>,
}
