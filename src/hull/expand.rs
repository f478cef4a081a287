//! One QuickHull expansion: visible facets, horizon, cone of new facets, repartition.

use super::coplanar::Phase;
use super::facet::FacetId;
use super::planes::NO_SLOT;
use super::{Hull, Partition};
use crate::geometry::vector::dot;
use crate::predicates::Sign;

/// Buffers reused across expansions so that steady-state expansion does not allocate.
#[derive(Clone, Debug, Default)]
pub(in crate::hull) struct Scratch<const D: usize> {
    /// Facets visible from the new point (removed by the expansion).
    pub(in crate::hull) removed: Vec<FacetId>,
    /// Facets created by the expansion.
    pub(in crate::hull) created: Vec<FacetId>,
    /// (visible facet, index of the horizon ridge in it).
    horizon: Vec<(FacetId, usize)>,
    /// Ridges of the cone to pair up: (order-independent hash of the ridge's vertices, new facet,
    /// its neighbour slot).
    ridges: Vec<(u64, FacetId, u32)>,
    /// Open-addressing table of indices into `ridges`, for pairing.
    table: Vec<u32>,
    /// Points of removed outside sets awaiting reassignment.
    pub(in crate::hull) orphans: Vec<u32>,
    /// Per input point, whether it was a vertex of a facet kept with the new point on its plane
    /// during a full build's first phase (see `coplanar.rs`).
    pub(in crate::hull) suspect: Vec<bool>,
    /// The buffers of the vertices' examination at the end of a first phase.
    pub(in crate::hull) examination: super::coplanar::Examination<D>,
    /// One created facet of each coplanar region (see `repartition`); the created facets with
    /// their region keys, or with their planes' distances from the query of
    /// `Partition::NearestFirst`.
    representatives: Vec<FacetId>,
    regions: Vec<(u64, FacetId)>,
    keyed: Vec<(f64, FacetId)>,
    stack: Vec<FacetId>,
    /// The facets around one facet, breadth first, for [`StrategyHooks::claim_beyond`](crate::hull::StrategyHooks::claim_beyond).
    ring: Vec<FacetId>,
    /// Each input's first copy, and the buffers that find it (`repeats.rs`).
    pub(in crate::hull) repeats: super::repeats::Repeats,
    /// The points' residuals while the initial simplex is chosen (`build::initial_simplex`).
    pub(in crate::hull) residuals: Vec<[f64; D]>,
    /// Tests only: ridge keys that collide all the time, so that the confirming pairing pass
    /// runs.
    #[cfg(test)]
    pub(in crate::hull) colliding_shares: bool,
    /// Tests only: full builds remove coplanar facets from the start, as before the two phases
    /// (see `coplanar.rs`), to compare the work.
    #[cfg(test)]
    pub(in crate::hull) plain_coplanar: bool,
    /// Tests only: how many pairings fell back to the confirming pass.
    #[cfg(test)]
    pub(in crate::hull) confirming_passes: usize,
}

/// The most facets [`StrategyHooks::claim_beyond`](crate::hull::StrategyHooks::claim_beyond) searches around a facet before it scans them all: a
/// few rings in 6-D, a hundredth of a large hull's arena.
pub(in crate::hull) const RING_FACETS: usize = 1024;

/// The most input points per dimension for which
/// [`StrategyHooks::expand_to_support`](crate::hull::StrategyHooks::expand_to_support) scans them
/// all (`D` multiply-adds each, about what one new facet's plane costs per 25 points in 6-D);
/// above it the expansion takes the facet's own farthest point, as a plain expansion does.
pub const SUPPORT_SCAN_POINTS: usize = 256;

/// One vertex's share of a ridge's hash: a ridge hashes to the wrapping sum of its vertices'
/// shares, so that the D − 1 ridges of a new facet cost one share each (the facet's sum less the
/// vertex opposite), with no sort. A sum of plain multiples would collide on vertex sets of
/// equal sum; the xor-shift and second multiply (SplitMix64's finaliser) spread each index over
/// all 64 bits. A collision is caught (a key met a third time) and the pairing redone with every
/// hit confirmed on the vertices: see [`Hull::pair_ridges_by`].
#[inline]
fn vertex_share(v: u32) -> u64 {
    let mut z = u64::from(v).wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Whether a pairing pass confirms each key match on the facets' vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Confirm {
    /// Never: a key met a third time (a hash collision) fails the pass instead.
    OnCollision,
    /// At every key match (the pass after a failed one).
    Always,
}

/// The flag an unconfirmed pairing pass sets on a ridge's neighbour slot once it is paired.
const PAIRED: u32 = 1 << 31;

/// Whether the ridge of facet `a` opposite its vertex `ja` is the ridge of facet `b` opposite
/// `jb`: every other vertex of `a` is a vertex of `b` other than `jb` (both have D distinct
/// vertices, so the D − 1 sets are then equal).
#[inline]
fn same_ridge<const D: usize>(a: &[u32; D], ja: usize, b: &[u32; D], jb: usize) -> bool {
    // Counted without branches (the hash has almost always matched): each vertex of `a` but
    // `ja` equals at most one of `b` (distinct vertices), so D − 1 matches mean equal ridges.
    let mut matches = 0;
    for (m, &x) in a.iter().enumerate() {
        for (n, &y) in b.iter().enumerate() {
            matches += usize::from((m != ja) & (n != jb) & (x == y));
        }
    }
    matches == D - 1
}

impl<const D: usize> Hull<D> {
    /// The engine's side of [`StrategyHooks::expand`](crate::hull::StrategyHooks::expand).
    pub(crate) fn expand(&mut self, id: FacetId) -> bool {
        let Some(facet) = self.facets.get(id.index()).filter(|f| f.alive) else {
            return false;
        };
        let Some((slot, _)) = facet.farthest else {
            return false;
        };
        let mut point = facet.outside[slot as usize] as usize;
        let mut from = id;
        if facet.plane != NO_SLOT {
            // The farthest point beyond the whole coplanar region: its facets' outside sets
            // split the points beyond one plane by where each was first found, and the
            // farthest of one facet's alone was often an interior point, later swallowed (most
            // of the cube corners' gain in docs/benchmarks.md, "A full build in two phases").
            // The walk covers the facets of the region linked to this one through neighbours;
            // any point it finds is beyond the same plane, so the choice is only an order.
            let region = self.region(id);
            let mut best = facet.filter.value(&self.points[point]);
            self.epoch = self.epoch.wrapping_add(1);
            let epoch = self.epoch;
            let mut stack = std::mem::take(&mut self.scratch.stack);
            stack.clear();
            stack.push(id);
            self.facets[id.index()].mark = epoch;
            while let Some(f) = stack.pop() {
                let facet = &self.facets[f.index()];
                if let Some((s, _)) = facet.farthest {
                    let q = facet.outside[s as usize] as usize;
                    let v = facet.filter.value(&self.points[q]);
                    if v > best {
                        best = v;
                        point = q;
                        from = f;
                    }
                }
                for n in self.facets[f.index()].neighbors {
                    if self.facets[n.index()].mark != epoch && self.region(n) == region {
                        self.facets[n.index()].mark = epoch;
                        stack.push(n);
                    }
                }
            }
            self.scratch.stack = stack;
        }
        self.expand_with(from, point)
    }

    /// The engine's side of [`StrategyHooks::expand_to_support`](crate::hull::StrategyHooks::expand_to_support).
    ///
    /// The scan reads every input point's value against the facet's plane (the filter's
    /// floating-point part, a choice only) and proves the winner beyond exactly. The winner may
    /// sit in another facet's outside set, which the partition chose by another rule; that
    /// facet has the point strictly beyond it, so the expansion removes it (the facets a point
    /// sees on a convex hull are connected, and the search starts at `id`, which it sees), and
    /// the repartition drops the point from the orphans as the new apex.
    pub(crate) fn expand_to_support(&mut self, id: FacetId) -> bool {
        let Some(facet) = self.facets.get(id.index()).filter(|f| f.alive) else {
            return false;
        };
        let Some((slot, _)) = facet.farthest else {
            return false;
        };
        if self.points.len() > SUPPORT_SCAN_POINTS * D {
            return self.expand(id);
        }
        let own = facet.outside[slot as usize];
        let plane = &facet.filter;
        let mut best = plane.value(&self.points[own as usize]);
        let mut winner = own;
        for (q, x) in self.points.iter().enumerate() {
            let value = plane.value(x);
            if value > best {
                best = value;
                winner = q as u32;
            }
        }
        if winner != own && self.side_of_index(id, winner) != Sign::Positive {
            winner = own; // the filter's value misled by rounding: nothing is lost
        } else if winner != own && !self.facets[id.index()].outside.contains(&winner) {
            if self.trace.is_some() {
                self.record_claim(id, vec![winner as usize]);
            }
            self.facets[id.index()].outside.push(winner);
        }
        self.expand_with(id, winner as usize)
    }

    /// The engine's side of [`StrategyHooks::expand_with`](crate::hull::StrategyHooks::expand_with).
    pub(crate) fn expand_with(&mut self, id: FacetId, point: usize) -> bool {
        let Some(facet) = self.facets.get_mut(id.index()).filter(|f| f.alive) else {
            return false;
        };
        let Some(slot) = facet.outside.iter().position(|&p| p as usize == point) else {
            return false;
        };
        facet.outside.swap_remove(slot);
        let p = point as u32;
        self.collect_visible(id, p);
        self.build_cone(p);
        self.repartition(p);
        self.stats.expansions += 1;
        self.stats.points_processed += 1;
        if self.trace.is_some() {
            self.record_expansion(id, p);
        }
        true
    }

    /// The engine's side of [`StrategyHooks::insert_beyond`](crate::hull::StrategyHooks::insert_beyond).
    pub(crate) fn insert_beyond(&mut self, id: FacetId, point: [f64; D]) -> Option<usize> {
        if !self.facets.get(id.index()).is_some_and(|f| f.alive) {
            return None;
        }
        let scaled = point.map(|x| x * self.scale);
        if !scaled.iter().all(|x| x.abs() <= 1.0) || self.side(id, &scaled) != Sign::Positive {
            return None;
        }
        let index = u32::try_from(self.points.len()).ok()?;
        if self.grid.is_some_and(|grid| !grid.contains(&scaled)) {
            self.grid = None; // the certificate covered the input alone
        }
        self.points.push(scaled);
        if self.trace.is_some() {
            self.record_insertion(id, index as usize, point);
        }
        self.facets[id.index()].outside.push(index);
        self.expand_with(id, index as usize);
        Some(index as usize)
    }

    /// The engine's side of [`StrategyHooks::last_removed`](crate::hull::StrategyHooks::last_removed).
    pub(crate) fn last_removed(&self) -> &[FacetId] {
        &self.scratch.removed
    }

    /// The engine's side of [`StrategyHooks::last_created`](crate::hull::StrategyHooks::last_created).
    pub(crate) fn last_created(&self) -> &[FacetId] {
        &self.scratch.created
    }

    /// The engine's side of [`StrategyHooks::claim_beyond`](crate::hull::StrategyHooks::claim_beyond).
    pub(crate) fn claim_beyond(&mut self, id: FacetId) -> bool {
        if !self.facets.get(id.index()).is_some_and(|f| f.alive) {
            return false;
        }
        let mut claimed = std::mem::take(&mut self.facets[id.index()].outside);
        let own = claimed.len();
        // Ring by ring around the facet (breadth first, marked with a fresh epoch), stopping
        // after the first ring that yields a point, or after RING_FACETS facets.
        self.epoch = self.epoch.wrapping_add(1);
        let epoch = self.epoch;
        self.facets[id.index()].mark = epoch;
        let mut ring = std::mem::take(&mut self.scratch.ring);
        ring.clear();
        ring.push(id);
        let (mut start, mut visited) = (0, 0);
        while start < ring.len() && claimed.len() == own && visited < RING_FACETS {
            let end = ring.len();
            for i in start..end {
                let neighbors = self.facets[ring[i].index()].neighbors;
                for n in neighbors.into_iter().filter(|&n| n != FacetId::NONE) {
                    let facet = &mut self.facets[n.index()];
                    if facet.alive && facet.mark != epoch {
                        facet.mark = epoch;
                        ring.push(n);
                        self.claim_from(id, n.index(), &mut claimed);
                        visited += 1;
                    }
                }
            }
            start = end;
        }
        self.scratch.ring = ring;
        if claimed.len() == own {
            for other in 0..self.facets.len() {
                if self.facets[other].mark != epoch {
                    self.claim_from(id, other, &mut claimed);
                }
            }
        }
        if self.trace.is_some() && claimed.len() > own {
            let moved = claimed[own..].iter().map(|&p| p as usize).collect();
            self.record_claim(id, moved);
        }
        self.facets[id.index()].outside = claimed;
        self.refresh_farthest(id);
        !self.facets[id.index()].outside.is_empty()
    }

    /// Moves the points of facet `other`'s outside set that lie strictly beyond facet `id` into
    /// `claimed`.
    fn claim_from(&mut self, id: FacetId, other: usize, claimed: &mut Vec<u32>) {
        if !self.facets[other].alive || self.facets[other].outside.is_empty() {
            return;
        }
        let mut outside = std::mem::take(&mut self.facets[other].outside);
        let before = outside.len();
        outside.retain(|&p| {
            let beyond = self.side_of_index(id, p) == Sign::Positive;
            if beyond {
                claimed.push(p);
            }
            !beyond
        });
        let changed = outside.len() != before;
        self.facets[other].outside = outside;
        if changed {
            self.refresh_farthest(FacetId(other as u32));
        }
    }

    /// Recomputes which point of a facet's outside set lies farthest beyond it.
    pub(in crate::hull) fn refresh_farthest(&mut self, id: FacetId) {
        let facet = &self.facets[id.index()];
        let mut best: Option<(u32, f64)> = None;
        for (slot, &p) in facet.outside.iter().enumerate() {
            let (value, _) = facet.filter.evaluate(&self.points[p as usize]);
            if best.is_none_or(|(_, v)| value > v) {
                best = Some((slot as u32, value));
            }
        }
        self.facets[id.index()].farthest = best;
    }

    /// Depth-first search from `start` over facets that `p` lies beyond or on (exactly decided).
    ///
    /// Facets with `p` on their plane count as visible unless the build keeps them:
    /// removing them keeps every hull vertex an extreme point, and the cone over the horizon is
    /// still non-degenerate because a horizon facet has `p` strictly beneath it. Kept, they are
    /// counted, and in a full build's first phase their vertices marked as suspects
    /// (`coplanar.rs`).
    fn collect_visible(&mut self, start: FacetId, p: u32) {
        self.epoch = self.epoch.wrapping_add(1);
        let epoch = self.epoch;
        let keeping = self.keep_coplanar || self.phase != Phase::None;
        let first_phase = self.phase == Phase::First;
        let scratch = &mut self.scratch;
        scratch.removed.clear();
        scratch.horizon.clear();
        scratch.stack.clear();
        scratch.stack.push(start);
        let f = &mut self.facets[start.index()];
        f.mark = epoch;
        f.visible = true;
        f.touching = false; // `p` is strictly beyond the facet it was taken from
        while let Some(id) = self.scratch.stack.pop() {
            self.scratch.removed.push(id);
            let region = self.region(id);
            let touching = self.facets[id.index()].touching;
            for i in 0..D {
                let n = self.facets[id.index()].neighbors[i];
                let neighbor = &self.facets[n.index()];
                let visible = if neighbor.mark == epoch {
                    neighbor.visible
                } else {
                    // A neighbour in the same coplanar region spans the same hyperplane: `p`
                    // is on the same side of it, with no test.
                    let sign = if self.region(n) == region {
                        if touching { Sign::Zero } else { Sign::Positive }
                    } else {
                        self.side_of_index(n, p)
                    };
                    // A facet whose plane holds `p` goes with the visible ones unless kept
                    // (`Hull::keep_coplanar_facets`).
                    let visible = if keeping {
                        if sign == Sign::Zero && first_phase {
                            self.kept_in_first_phase = true;
                            // Its vertices may stop being extreme (see `coplanar.rs`).
                            for v in self.facets[n.index()].vertices {
                                if let Some(s) = self.scratch.suspect.get_mut(v as usize) {
                                    *s = true;
                                }
                            }
                        }
                        sign == Sign::Positive
                    } else {
                        sign != Sign::Negative
                    };
                    let neighbor = &mut self.facets[n.index()];
                    neighbor.mark = epoch;
                    neighbor.visible = visible;
                    neighbor.touching = sign == Sign::Zero;
                    if visible {
                        self.scratch.stack.push(n);
                    }
                    visible
                };
                if !visible {
                    self.scratch.horizon.push((id, i));
                }
            }
        }
    }

    /// Creates one facet per horizon ridge, joined to `p`, and links the cone.
    fn build_cone(&mut self, p: u32) {
        self.scratch.created.clear();
        self.scratch.ridges.clear();
        for h in 0..self.scratch.horizon.len() {
            let (visible, i) = self.scratch.horizon[h];
            let old = &self.facets[visible.index()];
            let outer = old.neighbors[i];
            // Same vertex order with vertex i replaced by p: the new facet inherits the removed
            // facet's orientation of the shared ridge, so it is outward (see ARCHITECTURE.md).
            let mut vertices = old.vertices;
            vertices[i] = p;
            let mut neighbors = [FacetId::NONE; D];
            neighbors[i] = outer;
            // With `p` on the removed facet's plane, the new facet lies in that hyperplane; with
            // `p` on the plane of a kept neighbour (tested in `collect_visible`, so marked in
            // this epoch), in that one.
            let kept = &self.facets[outer.index()];
            let region = if old.touching {
                Some(visible)
            } else if kept.touching && kept.mark == self.epoch {
                Some(outer)
            } else {
                None
            };
            let new = self.push_facet(vertices, neighbors, region);
            self.scratch.created.push(new);
            let back = self.facets[outer.index()]
                .neighbors
                .iter()
                .position(|&n| n == visible)
                .expect("horizon neighbour links back to the visible facet");
            self.facets[outer.index()].neighbors[back] = new;
            // The ridge opposite vertex j ≠ i contains p; it is keyed by its other D − 2 vertices.
            #[cfg(test)]
            let shares = vertices.map(|v| match self.scratch.colliding_shares {
                true => u64::from(v % 3), // collisions on every other ridge, for the tests
                false => vertex_share(v),
            });
            #[cfg(not(test))]
            let shares = vertices.map(vertex_share);
            let total = (0..D)
                .filter(|&m| m != i)
                .fold(0u64, |h, m| h.wrapping_add(shares[m]));
            for j in (0..D).filter(|&j| j != i) {
                let key = total.wrapping_sub(shares[j]);
                self.scratch.ridges.push((key, new, j as u32));
            }
        }
        self.pair_ridges();
    }

    /// Links the new facets across the ridges they share, through an open-addressing hash table
    /// (a sort of the keys cost a quarter of the full hull's time in 5-D and 6-D).
    fn pair_ridges(&mut self) {
        if !self.pair_ridges_by(Confirm::OnCollision) {
            for ridge in &mut self.scratch.ridges {
                ridge.2 &= !PAIRED;
            }
            #[cfg(test)]
            {
                self.scratch.confirming_passes += 1;
            }
            self.pair_ridges_by(Confirm::Always);
        }
    }

    /// One pairing pass; `false` (links possibly wrong, to be redone by a confirming pass) when
    /// an unconfirmed pass meets a key a third time or leaves a ridge unpaired.
    ///
    /// Why an unconfirmed pass that returns `true` is right: every cone ridge occurs in exactly
    /// two new facets (the horizon is a closed manifold), so its two entries share a key. Two
    /// different ridges with one key therefore put at least four entries on one probe path, and
    /// the third of them meets a slot already paired (slots are never emptied, so every entry
    /// with that key walks past the first one's slot). A pass that meets no paired slot and
    /// pairs every entry has paired each ridge with the only other entry of its key: its own.
    fn pair_ridges_by(&mut self, confirm: Confirm) -> bool {
        const EMPTY: u32 = u32::MAX;
        let scratch = &mut self.scratch;
        let capacity = (2 * scratch.ridges.len()).next_power_of_two().max(2);
        let mask = capacity - 1;
        scratch.table.clear();
        scratch.table.resize(capacity, EMPTY);
        let mut paired = 0;
        for r in 0..scratch.ridges.len() {
            let (key, a, ja) = scratch.ridges[r];
            let mut slot = (key >> 32) as usize & mask;
            loop {
                let other = scratch.table[slot];
                if other == EMPTY {
                    scratch.table[slot] = r as u32;
                    break;
                }
                let (other_key, b, jb) = scratch.ridges[other as usize];
                if other_key == key {
                    let matched = match confirm {
                        Confirm::OnCollision if jb & PAIRED != 0 => return false,
                        Confirm::OnCollision => true,
                        Confirm::Always => same_ridge(
                            &self.facets[a.index()].vertices,
                            ja as usize,
                            &self.facets[b.index()].vertices,
                            (jb & !PAIRED) as usize,
                        ),
                    };
                    if matched {
                        let jb = jb & !PAIRED;
                        self.facets[a.index()].neighbors[ja as usize] = b;
                        self.facets[b.index()].neighbors[jb as usize] = a;
                        if confirm == Confirm::OnCollision {
                            scratch.ridges[other as usize].2 |= PAIRED;
                        }
                        paired += 2;
                        break;
                    }
                }
                slot = (slot + 1) & mask;
            }
        }
        paired == scratch.ridges.len()
    }

    /// Tombstones the visible facets and reassigns their outside points, but `apex`, to the new
    /// facets.
    fn repartition(&mut self, apex: u32) {
        self.scratch.orphans.clear();
        for r in 0..self.scratch.removed.len() {
            let id = self.scratch.removed[r];
            let facet = &mut self.facets[id.index()];
            facet.alive = false;
            facet.farthest = None;
            if facet.plane != NO_SLOT {
                self.planes.release(facet.plane);
            }
            self.scratch.orphans.append(&mut facet.outside);
            self.free.push(id);
        }
        self.live -= self.scratch.removed.len();
        let orphans = std::mem::take(&mut self.scratch.orphans);
        // One candidate per coplanar region: a point's side of a hyperplane is the same for every
        // facet spanning it, so testing the others would repeat the same determinant.
        let mut representatives = std::mem::take(&mut self.scratch.representatives);
        representatives.clear();
        let created = &self.scratch.created;
        if let Partition::NearestFirst(query) = self.partition {
            // The first facet met of each shared plane (an epoch mark per plane), by the plane's
            // distance from the query: its offset less the query's height along the unit
            // normal (both in the caller's coordinates).
            self.planes.begin_visit();
            let mut keyed = std::mem::take(&mut self.scratch.keyed);
            keyed.clear();
            for &id in created {
                let f = &self.facets[id.index()];
                if f.plane == NO_SLOT || self.planes.first_visit(f.plane) {
                    keyed.push((f.offset - dot(f.normal, query), id));
                }
            }
            keyed.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
            representatives.extend(keyed.iter().map(|&(_, id)| id));
            self.scratch.keyed = keyed;
        } else if created
            .iter()
            .all(|id| self.facets[id.index()].plane == NO_SLOT)
        {
            // Each facet alone in its region (no shared plane): nothing to merge, no sort.
            representatives.extend_from_slice(created);
        } else {
            // Sorted by region (the shared planes first, then the facets alone by id): the
            // order matters to the work of the first-found partition, and this one is the
            // suite's best measured (in creation order, with the same one-per-region choice,
            // the 6-D cube corners took 1.5 to 2 times as long).
            let mut keyed = std::mem::take(&mut self.scratch.regions);
            keyed.clear();
            keyed.extend(created.iter().map(|&id| (self.region(id), id)));
            keyed.sort_unstable();
            keyed.dedup_by_key(|(region, _)| *region);
            representatives.extend(keyed.iter().map(|&(_, id)| id));
            self.scratch.regions = keyed;
        }
        // The apex is among the orphans when `expand_to_support` took it from another facet's
        // set; it is a vertex now, beyond no new facet.
        for &q in orphans.iter().filter(|&&q| q != apex) {
            self.assign(q, &representatives);
        }
        self.scratch.orphans = orphans;
        self.scratch.representatives = representatives;
    }
}

#[cfg(test)]
mod tests {
    use crate::geometry::Rng;
    use crate::{FarthestPoint, Hull};

    /// The hull of `points` with coplanar facets kept (`Hull::keep_coplanar_facets`), checked.
    fn kept<const D: usize>(points: &[[f64; D]]) -> Hull<D> {
        let mut hull = Hull::empty();
        hull.keep_coplanar_facets(true);
        hull.rebuild_with_strategy(points, FarthestPoint::new())
            .unwrap();
        hull.check().unwrap();
        hull
    }

    /// Every facet of `hull` lies in one of `planes` (unit normal, offset), every point of
    /// `extreme` is a vertex, and the volume is `volume`: the truth of an input whose hull the
    /// test knows.
    fn assert_is<const D: usize>(
        hull: &Hull<D>,
        planes: &[([f64; D], f64)],
        extreme: &[usize],
        volume: f64,
        what: &str,
    ) {
        for (id, facet) in hull.facets() {
            let (n, c) = (facet.normal(), facet.offset());
            assert!(
                planes.iter().any(|(m, d)| {
                    (c - d).abs() <= 1e-12 && n.iter().zip(m).all(|(a, b)| (a - b).abs() <= 1e-12)
                }),
                "{what}: facet {} in no face's plane: {n:?}, {c}",
                id.index()
            );
        }
        let vertices = hull.vertex_indices();
        for i in extreme {
            assert!(
                vertices.contains(i),
                "{what}: extreme point {i} is no vertex"
            );
        }
        assert!(
            (hull.volume() - volume).abs() <= 1e-12 * volume,
            "{what}: volume {} instead of {volume}",
            hull.volume()
        );
    }

    /// The cube [−1, 1]^D's facet planes.
    fn cube_planes<const D: usize>() -> Vec<([f64; D], f64)> {
        (0..2 * D)
            .map(|i| {
                let mut n = [0.0; D];
                n[i / 2] = if i % 2 == 0 { 1.0 } else { -1.0 };
                (n, 1.0)
            })
            .collect()
    }

    /// Cube corners, points on the cube's faces and inside it: every face holds many points
    /// exactly, the case the kept facets are for; the hull is the cube whatever stays.
    fn cube_case<const D: usize>(seed: u64) {
        let mut rng = Rng::new(seed);
        let mut points: Vec<[f64; D]> = (0..1usize << D)
            .map(|i| std::array::from_fn(|c| if i >> c & 1 == 1 { 1.0 } else { -1.0 }))
            .collect();
        let corners: Vec<usize> = (0..points.len()).collect();
        for k in 0..300 {
            let mut p: [f64; D] = std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0));
            if k % 2 == 0 {
                // On a face: one coordinate at ±1.
                p[k % D] = if k % 4 == 0 { 1.0 } else { -1.0 };
            }
            points.push(p);
        }
        // Corners last as well as first, so that face points come in before some corners.
        points.rotate_left(1 << (D - 1));
        let corners: Vec<usize> = corners
            .iter()
            .map(|&i| (i + points.len() - (1 << (D - 1))) % points.len())
            .collect();
        let hull = kept(&points);
        assert_is(
            &hull,
            &cube_planes::<D>(),
            &corners,
            2f64.powi(D as i32),
            &format!("cube, D = {D}"),
        );
    }

    #[test]
    fn kept_coplanar_facets_give_the_cube() {
        cube_case::<3>(1);
        cube_case::<4>(2);
        cube_case::<5>(3);
        cube_case::<6>(4);
    }

    /// The Minkowski sum of three polygons in the coordinate planes (x0, x1), (x2, x3), (x4, x5)
    /// of 6-D, every point a sum of one vertex of each, on a dyadic grid so that the sums are
    /// exact: the product of the polygons, whose facets are an edge of one times the other two
    /// (2k² points each), and whose volume is the product of their areas.
    #[test]
    fn kept_coplanar_facets_give_a_product_of_polygons() {
        for k in [4usize, 6, 8] {
            // A regular k-gon's vertices rounded to multiples of 2^-20, each polygon turned.
            let polygon = |turn: f64| -> Vec<[f64; 2]> {
                (0..k)
                    .map(|j| {
                        let a = turn + std::f64::consts::TAU * j as f64 / k as f64;
                        [a.cos(), a.sin()].map(|x| (x * 1048576.0).round() / 1048576.0)
                    })
                    .collect()
            };
            let polygons = [polygon(0.1), polygon(0.7), polygon(1.9)];
            let mut points = Vec::new();
            for a in &polygons[0] {
                for b in &polygons[1] {
                    for c in &polygons[2] {
                        points.push([a[0], a[1], b[0], b[1], c[0], c[1]]);
                    }
                }
            }
            // Each polygon's area (shoelace) and its edges' outward planes in its two axes.
            let mut volume = 1.0;
            let mut planes = Vec::new();
            for (i, poly) in polygons.iter().enumerate() {
                let mut area = 0.0;
                for j in 0..k {
                    let (p, q) = (poly[j], poly[(j + 1) % k]);
                    area += 0.5 * (p[0] * q[1] - p[1] * q[0]);
                    let (ex, ey) = (q[0] - p[0], q[1] - p[1]);
                    let length = (ex * ex + ey * ey).sqrt();
                    let mut n = [0.0; 6];
                    n[2 * i] = ey / length;
                    n[2 * i + 1] = -ex / length;
                    planes.push((n, n[2 * i] * p[0] + n[2 * i + 1] * p[1]));
                }
                volume *= area;
            }
            let hull = kept(&points);
            let all: Vec<usize> = (0..points.len()).collect();
            assert_is(&hull, &planes, &all, volume, &format!("product, k = {k}"));
            // And far fewer facets created than when coplanar facets go.
            let mut plain = Hull::empty();
            plain.scratch.plain_coplanar = true;
            plain
                .rebuild_with_strategy(&points, FarthestPoint::new())
                .unwrap();
            assert!(
                hull.stats().facets_created < plain.stats().facets_created,
                "k = {k}: {} facets created kept, {} removed",
                hull.stats().facets_created,
                plain.stats().facets_created
            );
            // A public build keeps them in its first phase, and every point being extreme,
            // needs no second: the same work.
            let public = Hull::try_new(&points).unwrap();
            assert_eq!(public.stats().facets_created, hull.stats().facets_created);
            assert_eq!(public.vertex_indices(), all);
        }
    }
}
