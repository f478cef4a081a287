//! Input validation, scaling and the initial simplex.

use super::Stats;
use super::expand::Scratch;
use super::facet::MAX_FLATS;
use super::facet::{Facet, FacetId};
use super::planes::NO_SLOT;
use super::{Hull, HullError, NO_FLAT, Partition};
use crate::geometry::vector::{dot, norm, sub};
use crate::predicates::{
    ExactGrid, FacetPlane, Sign, affinely_independent_subset, in_box, orientation,
};
use std::time::Instant;

/// The smallest dimension the engine builds hulls in ([`HullError::DimensionOutOfRange`] below).
pub const MIN_DIMENSION: usize = 2;

/// The largest dimension the engine builds hulls in (the initial simplex's fixed-size arrays
/// are sized for it).
pub const MAX_DIMENSION: usize = 8;

/// Slots of the initial simplex: its D + 1 vertices at the largest dimension.
pub(in crate::hull) const MAX_SIMPLEX: usize = MAX_DIMENSION + 1;

impl<const D: usize> Hull<D> {
    /// Validates the input, scales it, builds the initial simplex and the first outside sets.
    pub(in crate::hull) fn try_initial(
        input: &[[f64; D]],
        partition_farthest: bool,
    ) -> Result<Self, HullError> {
        let mut hull = Self::empty();
        hull.initialise(input, partition_farthest)?;
        Ok(hull)
    }

    /// A hull with no point and no facet: storage for
    /// [`rebuild_with_strategy`](Self::rebuild_with_strategy) to fill, so that a loop over many
    /// point sets allocates its buffers once.
    pub fn empty() -> Self {
        Hull {
            points: Vec::new(),
            scale: 1.0,
            inv_scale: 1.0,
            facets: Vec::new(),
            free: Vec::new(),
            planes: Default::default(),
            live: 0,
            next_serial: 0,
            epoch: 0,
            interior: [0.0; D],
            stats: Stats::default(),
            started: Instant::now(),
            scratch: Scratch::default(),
            flat_of: Vec::new(),
            flat_dim: 0,
            grid: None,
            in_box: true,
            partition: Partition::FirstFound,
            start: None,
            trace: None,
            keep_coplanar: false,
            phase: super::coplanar::Phase::None,
            kept_in_first_phase: false,
        }
    }

    /// [`try_initial`](Self::try_initial) into this hull's storage: every facet slot is freed (its
    /// outside-set buffer kept for reuse) and the point buffer refilled, so rebuilding a hull of a
    /// similar size allocates nothing. On error the hull is left empty (no live facet).
    /// `partition_farthest`: see [`Strategy::partitions_to_farthest`](super::Strategy).
    pub(in crate::hull) fn initialise(
        &mut self,
        input: &[[f64; D]],
        partition_farthest: bool,
    ) -> Result<(), HullError> {
        self.started = Instant::now();
        self.partition = if partition_farthest {
            Partition::Farthest
        } else {
            Partition::FirstFound
        };
        let start = self.start.take();
        self.free_every_facet();
        self.next_serial = 0;
        self.epoch = 0;
        self.stats = Stats::default();
        self.trace = None;
        self.phase = super::coplanar::Phase::None;
        self.kept_in_first_phase = false;
        self.points.clear();
        if !(MIN_DIMENSION..=MAX_DIMENSION).contains(&D) {
            return Err(HullError::DimensionOutOfRange { dimension: D });
        }
        // One pass over the input for its finiteness and both ends of its magnitudes.
        let extent = Extent::of(input);
        if !extent.finite
            && let Some((index, coordinate)) = first_non_finite(input)
        {
            return Err(HullError::NonFinite { index, coordinate });
        }
        if input.len() < D + 1 {
            return Err(HullError::TooFewPoints {
                needed: D + 1,
                got: input.len(),
            });
        }
        if input.len() > u32::MAX as usize {
            // Vertices are stored as u32 to halve the facet arena's index traffic.
            return Err(HullError::TooManyPoints {
                max: u32::MAX as usize,
                got: input.len(),
            });
        }
        let scale = extent.exact_power_of_two_scale();
        self.scale = scale;
        self.inv_scale = 1.0 / scale;
        self.points
            .extend(input.iter().map(|p| p.map(|x| x * scale)));
        self.grid = ExactGrid::of(&self.points);
        // Scaling by a power of two is exact and monotone (or not done): the largest scaled
        // magnitude is the largest magnitude scaled, so no pass over the points is needed.
        self.in_box = extent.max_abs * scale <= 1.0;
        debug_assert_eq!(self.in_box, self.points.iter().all(in_box));
        super::repeats::mark_repeats(&self.points, &mut self.scratch.repeats);
        let chosen = start;
        let (mut simplex, extremes) = match chosen.filter(|s| independent(&self.points, &s[..=D])) {
            Some(simplex) => (simplex, None),
            None => initial_simplex(&self.points, &mut self.scratch.residuals)?,
        };
        // Its vertices are distinct points: name each by its first copy, as every vertex is.
        for s in &mut simplex[..=D] {
            *s = self.scratch.repeats.first_copy(*s).unwrap_or(*s);
        }
        let simplex = &simplex[..=D];
        let mut all = self.found(simplex);
        self.stats.points_processed = D + 1;
        // The initial hull's vertices (the simplex's, then the extreme points added) and facets.
        let mut vertices = [u32::MAX; MAX_SIMPLEX];
        for (v, &s) in vertices.iter_mut().zip(simplex) {
            *v = s as u32;
        }
        let (mut count, mut added) = (D + 1, D + 1);
        if let Some(extremes) = extremes.filter(|_| D == 2) {
            (count, added) = self.widen_to_extremes(&extremes[..2 * D], &mut vertices, &mut all);
        }
        let all = &all[..count];
        // The vertices alone (the slots past them would be tested for every point).
        let vertices = &vertices[..added];
        for p in 0..self.points.len() as u32 {
            if !vertices.contains(&p) && self.scratch.repeats.is_first_copy(p as usize) {
                self.assign(p, all);
            }
        }
        Ok(())
    }

    /// In the plane, the initial triangle widened to the polygon of the axis-extreme points
    /// (Akl and Toussaint's quadrilateral), before any other point is assigned, so that the
    /// first partition is against the polygon's edges: each extreme point that lies strictly
    /// beyond an edge (exactly decided) is added as an expansion would add it, with nothing to
    /// repartition. Returns how many facets `all` then holds (the live ones, at most
    /// [`MAX_SIMPLEX`]) and how many vertices `vertices` holds (the triangle's first, then the
    /// points added); the polygon is the initial hull, so its points count as processed and
    /// not as expansions (a trace starts from it).
    ///
    /// Why: on points near the sides of a turned square (the suite's `tilted` family), the
    /// triangle's third edge crosses the square, and the expansion at the fourth corner
    /// repartitioned half of the input; on random input in a square, the same half.
    fn widen_to_extremes(
        &mut self,
        extremes: &[usize],
        vertices: &mut [u32; MAX_SIMPLEX],
        all: &mut [FacetId; MAX_SIMPLEX],
    ) -> (usize, usize) {
        let mut count = D + 1;
        let mut added = D + 1;
        for &e in extremes {
            let e = self.scratch.repeats.first_copy(e).unwrap_or(e) as u32;
            if vertices.contains(&e) || added == MAX_SIMPLEX {
                continue;
            }
            let Some(&beyond) = all[..count]
                .iter()
                .find(|&&id| self.side_of_index(id, e) == Sign::Positive)
            else {
                continue;
            };
            self.facets[beyond.index()].outside.push(e);
            let created = self.stats.facets_created;
            if !self.expand_with(beyond, e as usize) {
                // Not reached (`beyond` is live and holds `e`); `e` is then left to the partition.
                self.facets[beyond.index()].outside.clear();
                continue;
            }
            // As if the polygon had been made at once: its facets created, no expansion.
            self.stats.expansions -= 1;
            self.stats.facets_created =
                created + self.scratch.created.len() - self.scratch.removed.len();
            vertices[added] = e;
            added += 1;
            // The live facets, in slot order (at most one more than before, in the plane).
            count = 0;
            for (i, f) in self.facets.iter().enumerate() {
                if f.alive && count < MAX_SIMPLEX {
                    all[count] = FacetId(i as u32);
                    count += 1;
                }
            }
        }
        (count, added)
    }

    /// Frees every facet slot and plane, keeping each slot's outside-set buffer (emptied) for
    /// reuse. The slots are freed in descending order, so that they are reused from slot 0 up,
    /// as in a fresh arena (same ids for the same input).
    pub(in crate::hull) fn free_every_facet(&mut self) {
        self.free.clear();
        self.planes.clear();
        for i in (0..self.facets.len()).rev() {
            self.facets[i].alive = false;
            self.facets[i].outside.clear();
            self.free.push(FacetId(i as u32));
        }
        self.live = 0;
    }

    /// Makes the initial simplex on the input points `simplex` (D + 1 affinely independent
    /// indices, first copies) the hull: its D + 1 facets, outward, linked, with empty outside
    /// sets, in the first free slots. Returns the facets' ids (the first D + 1 entries).
    pub(in crate::hull) fn found(&mut self, simplex: &[usize]) -> [FacetId; MAX_SIMPLEX] {
        let mut interior = [0.0; D];
        for &s in simplex {
            for (c, x) in interior.iter_mut().zip(&self.points[s]) {
                *c += x / (D + 1) as f64;
            }
        }
        self.interior = interior;

        // Facet k is opposite simplex vertex k; its neighbour across the ridge opposite simplex
        // vertex j is facet j. A rebuilt arena hands out slots 0, 1, … in order, as a fresh one.
        let first = self.free.last().map_or(self.facets.len(), |id| id.index());
        for k in 0..=D {
            let mut vertices = [0u32; D];
            let mut neighbors = [FacetId::NONE; D];
            for (slot, j) in (0..=D).filter(|&j| j != k).enumerate() {
                vertices[slot] = simplex[j] as u32;
                neighbors[slot] = FacetId((first + j) as u32);
            }
            let coords = self.coords(&vertices);
            if orientation(&coords, &self.points[simplex[k]]) == Sign::Positive {
                vertices.swap(0, 1);
                neighbors.swap(0, 1);
            }
            let id = self.push_facet(vertices, neighbors, None);
            debug_assert_eq!(id.index(), first + k);
        }
        std::array::from_fn(|k| FacetId((first + k) as u32))
    }

    /// Whether input `p` equals an input with a smaller index (so never enters an outside set).
    pub(in crate::hull) fn is_repeat(&self, p: usize) -> bool {
        self.scratch
            .repeats
            .first_copy(p)
            .is_some_and(|first| first != p)
    }

    /// `x / scale`: back in the caller's units.
    #[inline]
    fn unscale(&self, x: f64) -> f64 {
        if self.inv_scale.is_finite() {
            x * self.inv_scale
        } else {
            x / self.scale
        }
    }

    pub(in crate::hull) fn coords(&self, vertices: &[u32; D]) -> [[f64; D]; D] {
        let mut coords = [[0.0; D]; D];
        for (to, &v) in coords.iter_mut().zip(vertices) {
            *to = self.points[v as usize];
        }
        coords
    }

    /// The engine's side of [`StrategyHooks::refine_normal`](crate::hull::StrategyHooks::refine_normal).
    pub(crate) fn refine_normal(&mut self, id: FacetId) {
        let facet = &self.facets[id.index()];
        if facet.precise {
            return;
        }
        let normal = self.exact_normal(id);
        let offset = self.unscale(dot(normal, self.points[facet.vertices[0] as usize]));
        let facet = &mut self.facets[id.index()];
        facet.normal = normal;
        facet.offset = offset;
        facet.precise = true;
    }

    /// The engine's side of [`StrategyHooks::exact_normal`](crate::hull::StrategyHooks::exact_normal).
    pub(crate) fn exact_normal(&self, id: FacetId) -> [f64; D] {
        let (plane, vertices) = self.exact_plane_of(id);
        let exact = plane.refined_normal_direction(&self.coords(vertices));
        let length = norm(exact);
        exact.map(|c| c / length)
    }

    /// Creates a facet, reusing a tombstoned slot when possible. With `region` (a facet whose
    /// hyperplane the new one lies in, exactly), it shares that facet's plane, normal and offset;
    /// otherwise its plane and normal are computed here.
    pub(in crate::hull) fn push_facet(
        &mut self,
        vertices: [u32; D],
        neighbors: [FacetId; D],
        region: Option<FacetId>,
    ) -> FacetId {
        let (plane, filter, inv_norm, normal, precise, offset) = match region {
            Some(same) => {
                let slot = self.share_plane(same);
                let f = &self.facets[same.index()];
                let filter = f.filter.clone_uncached();
                (slot, filter, f.inv_norm, f.normal, f.precise, f.offset)
            }
            None => self.new_plane(vertices),
        };
        let flats = self.flats_within(&vertices);
        let serial = self.next_serial;
        self.next_serial += 1;
        self.stats.facets_created += 1;
        self.live += 1;
        let fresh = |outside: Vec<u32>| Facet {
            vertices,
            neighbors,
            plane,
            filter,
            inv_norm,
            normal,
            precise,
            offset,
            flats,
            outside,
            farthest: None,
            alive: true,
            serial,
            mark: 0,
            visible: false,
            touching: false,
        };
        match self.free.pop() {
            Some(id) => {
                let slot = &mut self.facets[id.index()];
                let mut outside = std::mem::take(&mut slot.outside);
                outside.clear();
                *slot = fresh(outside);
                id
            }
            None => {
                self.facets.push(fresh(Vec::new()));
                FacetId((self.facets.len() - 1) as u32)
            }
        }
    }

    /// A new plane through `vertices` in the arena, with the facet's unit normal, whether it is
    /// precise, and its offset.
    #[allow(clippy::type_complexity)]
    fn new_plane(&mut self, vertices: [u32; D]) -> (u32, FacetPlane<D>, f64, [f64; D], bool, f64) {
        let coords = self.coords(&vertices);
        let plane = FacetPlane::new_in_range(&coords, self.in_box);
        // Without overflow or underflow of the squares: the cofactors of a wide-ranging input
        // (one axis 1e40 times the others, in 6-D) are products of D − 1 small coordinates, whose
        // squares underflowed to give NaN normals.
        let inv_norm = 1.0 / norm(*plane.cofactors());
        let largest = plane.cofactors().iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let error = plane
            .cofactor_errors()
            .iter()
            .fold(0.0f64, |m, e| m.max(*e));
        // When the floating-point cofactors cancel (a thin facet), the normal is refined from the
        // exact cofactors only when someone needs it precise (`refine_normal`): most such facets
        // are transient, and the queue orders of the strategies only need approximate distances.
        // Cofactors near the subnormal range have lost bits that their error bound (itself
        // rounded there) need not show: they too are refined.
        let mut precise = error <= 1e-11 * largest && largest >= MIN_PRECISE_COFACTOR;
        let mut normal = plane.cofactors().map(|c| c * inv_norm);
        if !(largest.is_finite() && error.is_finite() && inv_norm > 0.0 && inv_norm.is_finite()) {
            // Cofactors that overflow (coordinates too large and too spread to be scaled
            // exactly, so left unscaled): the exact direction now, as nothing else can give one.
            let exact = plane.exact_normal_direction(&coords);
            let length = norm(exact);
            normal = exact.map(|c| c / length);
            precise = true;
        }
        let offset = self.unscale(dot(normal, coords[0]));
        (NO_SLOT, plane, inv_norm, normal, precise, offset)
    }

    /// The slot of facet `same`'s region plane, with one more user, made now (from the facet's
    /// own plane and vertices) if the facet was alone in its region.
    fn share_plane(&mut self, same: FacetId) -> u32 {
        let f = &self.facets[same.index()];
        if f.plane == NO_SLOT {
            // A clone of an exact cache already built allocates; it is the rare case (the
            // founder's filter failed before any facet joined it).
            let slot = self.planes.add(f.filter.clone(), f.vertices);
            self.facets[same.index()].plane = slot;
        }
        let slot = self.facets[same.index()].plane;
        self.planes.share(slot);
        slot
    }

    /// The plane whose exact cache serves facet `id`, and the vertices it was built from: the
    /// facet's own, or its region's shared plane.
    #[inline]
    pub(in crate::hull) fn exact_plane_of(&self, id: FacetId) -> (&FacetPlane<D>, &[u32; D]) {
        let facet = &self.facets[id.index()];
        if facet.plane == NO_SLOT {
            (&facet.filter, &facet.vertices)
        } else {
            let shared = self.planes.get(facet.plane);
            (&shared.plane, &shared.vertices)
        }
    }

    /// A key equal for two live facets exactly when they are in the same coplanar region.
    #[inline]
    pub(in crate::hull) fn region(&self, id: FacetId) -> u64 {
        match self.facets[id.index()].plane {
            NO_SLOT => (1 << 32) | u64::from(id.0),
            slot => u64::from(slot),
        }
    }

    /// Puts point `p` in the outside set of a candidate it lies strictly beyond (exactly decided):
    /// the first one the filter proves (the farthest when the strategy asks for it), the
    /// farthest on certified-grid input (where a test is a dot product and the farthest keeps
    /// non-extreme grid points out of the hull), else the first the exact path proves; or
    /// nowhere if it lies weakly inside every candidate. Returns whether it was assigned.
    pub(in crate::hull) fn assign(&mut self, p: u32, candidates: &[FacetId]) -> bool {
        let point = self.points[p as usize];
        let mut best: Option<(FacetId, f64, f64)> = None;
        let mut undecided = false;
        if self.grid.is_some() {
            // The value is the exact determinant (see `ExactGrid`): no bound, no fallback.
            for &id in candidates {
                let facet = &self.facets[id.index()];
                let value = facet.filter.value(&point);
                if value > 0.0 {
                    let distance = value * facet.inv_norm;
                    if best.is_none_or(|(_, d, _)| distance > d) {
                        best = Some((id, distance, value));
                    }
                }
            }
            return self.push_outside(p, best);
        }
        // The box test once for all candidates, and not at all when every point is in the box
        // (internal points are, but for the rare input that could not be scaled into it).
        let boxed = self.in_box || in_box(&point);
        // The point's declared flat, once for all candidates (none but in `rebuild_with_flats`).
        let flat = match self.flat_of.get(p as usize) {
            Some(&flat) if flat != NO_FLAT => Some(flat),
            _ => None,
        };
        // The candidates left undecided, in order (the first `OPEN`; past them the exact pass
        // asks the filter again): the exact pass tests only those. Kept off the common path
        // (a position counter in the loop cost the 3-D cube 6 % more instructions).
        const OPEN: usize = 8;
        let mut open = [FacetId::NONE; OPEN];
        // The first one's filter value, which its exact test takes rather than compute again
        // (a second undecided candidate is rare; an array of values cost the 3-D cube 0.7 %
        // more instructions, to initialise).
        let mut first_value = 0.0;
        let mut opened = 0;
        for &id in candidates {
            let facet = &self.facets[id.index()];
            if flat.is_some_and(|flat| facet.flats.contains(&flat)) {
                continue; // exactly on the plane
            }
            let (value, bound) = if boxed {
                facet.filter.evaluate_in_box(&point)
            } else {
                facet.filter.evaluate(&point)
            };
            if value > bound {
                let distance = value * facet.inv_norm;
                // Unless the strategy asks for the farthest, the first facet the point is
                // certainly beyond takes it (Qhull's default too): testing every candidate
                // doubled the partition's cost on input whose points mostly end up inside, as
                // cube corners with interior points.
                if self.partition != Partition::Farthest {
                    return self.push_outside(p, Some((id, distance, value)));
                }
                if best.is_none_or(|(_, d, _)| distance > d) {
                    best = Some((id, distance, value));
                }
            } else if value >= -bound || value.is_nan() {
                // Undecided unless certainly behind: also when the value is NaN (coordinates so
                // large, unscalable, that the floating-point products overflow).
                undecided = true;
                if opened == 0 {
                    first_value = value;
                }
                if opened < OPEN {
                    open[opened] = id;
                }
                opened += 1;
            }
        }
        if best.is_none() && undecided {
            // Only the exact path can tell; the first facet it puts the point beyond will do.
            if opened == 1 {
                // The common case (one undecided candidate) calls the exact stages from here:
                // one call fewer per test on nearly coplanar input.
                best = self.beyond_exactly(open[0], first_value, &point);
            } else {
                let open = (opened <= OPEN).then_some(&open[..opened.min(OPEN)]);
                best = self.first_beyond_exactly(&point, open, first_value, candidates);
            }
        }
        self.push_outside(p, best)
    }

    /// [`assign`](Self::assign)'s exact pass but for its common case, out of line: the first of
    /// the undecided candidates `open` (all of `candidates` that the filter leaves undecided
    /// when `None`) that `point` is exactly beyond. `first_value` is the filter's value at the
    /// first undecided candidate. Why out of line: inlined, it lengthened the loop over the
    /// candidates, which the filter decides on most input (the 3-D cube took 0.8 % more
    /// instructions than before the value was handed on, out of line 1.2 % fewer; cachegrind,
    /// `profile_rbox cube 3 100000 1`).
    #[inline(never)]
    fn first_beyond_exactly(
        &self,
        point: &[f64; D],
        open: Option<&[FacetId]>,
        first_value: f64,
        candidates: &[FacetId],
    ) -> Option<(FacetId, f64, f64)> {
        let beyond = |id: FacetId, value: f64| self.beyond_exactly(id, value, point);
        match open {
            Some(open) => open.iter().enumerate().find_map(|(k, &id)| {
                let value = if k == 0 {
                    first_value
                } else {
                    self.facets[id.index()].filter.value(point)
                };
                beyond(id, value)
            }),
            None => candidates.iter().find_map(|&id| {
                let (value, bound) = self.facets[id.index()].filter.evaluate(point);
                if value.abs() <= bound || value.is_nan() {
                    beyond(id, value)
                } else {
                    None
                }
            }),
        }
    }

    /// `assign`'s choice of facet `id` (with `point`'s distance and value) if `point` is exactly
    /// beyond it, the filter having left it undecided with `value`.
    #[inline]
    fn beyond_exactly(
        &self,
        id: FacetId,
        value: f64,
        point: &[f64; D],
    ) -> Option<(FacetId, f64, f64)> {
        (self.side_undecided_at(id, value, point) == Sign::Positive).then(|| {
            let facet = &self.facets[id.index()];
            (id, value * facet.inv_norm, value.max(0.0))
        })
    }

    /// Puts `p` in the outside set of `best`'s facet (with its orientation value), if any.
    pub(in crate::hull) fn push_outside(
        &mut self,
        p: u32,
        best: Option<(FacetId, f64, f64)>,
    ) -> bool {
        let Some((id, _, value)) = best else {
            return false;
        };
        let facet = &mut self.facets[id.index()];
        let slot = facet.outside.len() as u32;
        facet.outside.push(p);
        if facet.farthest.is_none_or(|(_, v)| value > v) {
            facet.farthest = Some((slot, value));
        }
        true
    }

    /// Exact side of internal point `x` relative to facet `id`.
    pub(in crate::hull) fn side(&self, id: FacetId, x: &[f64; D]) -> Sign {
        match self.facets[id.index()].filter.filter_sign(x) {
            Some(sign) => sign,
            None => self.side_undecided(id, x),
        }
    }

    /// [`side`](Self::side) of a point the filter left undecided against facet `id`: the exact
    /// stages alone, on the shared plane (its cache serves the whole coplanar region; its
    /// filter is the facet's, so it would be undecided there too).
    fn side_undecided(&self, id: FacetId, x: &[f64; D]) -> Sign {
        let (plane, vertices) = self.exact_plane_of(id);
        plane.side_undecided(x, || self.coords(vertices))
    }

    /// [`side_undecided`](Self::side_undecided) given `value`, the facet's own filter value at
    /// `x`: passed on when the facet's plane is its own, computed on the shared plane otherwise.
    #[inline]
    fn side_undecided_at(&self, id: FacetId, value: f64, x: &[f64; D]) -> Sign {
        let facet = &self.facets[id.index()];
        if facet.plane == NO_SLOT {
            facet
                .filter
                .side_undecided_at(value, x, || self.coords(&facet.vertices))
        } else {
            self.side_undecided(id, x)
        }
    }

    /// Exact side of input point `p` relative to facet `id`: [`side`](Self::side), or `Zero` at
    /// once when the facet contains the declared flat holding `p`.
    pub(in crate::hull) fn side_of_index(&self, id: FacetId, p: u32) -> Sign {
        let facet = &self.facets[id.index()];
        if self.on_its_flat(facet, p) {
            return Sign::Zero;
        }
        let point = &self.points[p as usize];
        if self.grid.is_some() {
            // Every vertex and `p` are input points, all on the certified grid.
            return facet.filter.side_on_grid(point);
        }
        self.side(id, point)
    }

    /// Whether input point `p` lies in a declared flat that `facet`'s hyperplane contains.
    #[inline]
    fn on_its_flat(&self, facet: &Facet<D>, p: u32) -> bool {
        match self.flat_of.get(p as usize) {
            Some(&flat) if flat != NO_FLAT => facet.flats.contains(&flat),
            _ => false,
        }
    }

    /// The declared flats with at least `flat_dim + 1` points among `vertices` (so, the vertices
    /// being affinely independent, contained in their hyperplane), padded with [`NO_FLAT`].
    fn flats_within(&self, vertices: &[u32; D]) -> [u32; MAX_FLATS] {
        let mut flats = [NO_FLAT; MAX_FLATS];
        if self.flat_of.is_empty() {
            return flats;
        }
        // Each vertex's flat read once (the counts below read each up to D times).
        let ids = vertices.map(|v| self.flat_of.get(v as usize).copied().unwrap_or(NO_FLAT));
        let mut found = 0;
        for (i, &f) in ids.iter().enumerate() {
            // Count each flat once, at its first vertex.
            if f == NO_FLAT || ids[..i].contains(&f) {
                continue;
            }
            let members = ids[i..].iter().filter(|&&g| g == f).count();
            if members > self.flat_dim && found < MAX_FLATS {
                flats[found] = f;
                found += 1;
            }
        }
        flats
    }
}

/// The smallest largest-cofactor trusted without refinement: about 2^−897, far above the
/// subnormals (below 2^−1022) where the products and their error bounds lose bits.
const MIN_PRECISE_COFACTOR: f64 = 1e-270;

pub(in crate::hull) fn first_non_finite<const D: usize>(
    points: &[[f64; D]],
) -> Option<(usize, usize)> {
    points
        .iter()
        .enumerate()
        .find_map(|(i, p)| p.iter().position(|x| !x.is_finite()).map(|c| (i, c)))
}

/// The magnitudes of an input's coordinates, found in one pass.
struct Extent {
    /// Whether every coordinate is finite.
    finite: bool,
    /// The largest magnitude (meaningful when `finite`).
    max_abs: f64,
    /// The smallest non-zero magnitude (infinite when every coordinate is zero).
    min_abs: f64,
}

impl Extent {
    /// One pass over the coordinates' bits, in independent lanes: with the sign bit cleared, a
    /// finite `f64`'s bits order as its magnitude does, infinities and NaNs above them all, so
    /// integer maxima and minima find both ends and the non-finite values at once, without the
    /// chain of dependent comparisons per coordinate of the pass before, on which `perf
    /// annotate` put 18 % of `Hull::try_new`'s own samples on the 2-D clusters of 1,000,000
    /// points (docs/benchmarks.md, "Issue 24: the input read in fewer, cheaper passes").
    fn of<const D: usize>(points: &[[f64; D]]) -> Self {
        const LANES: usize = 8;
        const MAGNITUDE: u64 = !(1 << 63);
        let flat = points.as_flattened();
        let mut high = [0u64; LANES];
        // The bits less one, so that zero (wrapping to the largest) never is the minimum.
        let mut low = [u64::MAX; LANES];
        let chunks = flat.chunks_exact(LANES);
        let rest = chunks.remainder();
        for chunk in chunks {
            for k in 0..LANES {
                let a = chunk[k].to_bits() & MAGNITUDE;
                high[k] = high[k].max(a);
                low[k] = low[k].min(a.wrapping_sub(1));
            }
        }
        for (k, &x) in rest.iter().enumerate() {
            let a = x.to_bits() & MAGNITUDE;
            high[k] = high[k].max(a);
            low[k] = low[k].min(a.wrapping_sub(1));
        }
        let high = high.into_iter().max().unwrap_or(0);
        let low = low.into_iter().min().unwrap_or(u64::MAX);
        Extent {
            finite: high < f64::INFINITY.to_bits(),
            max_abs: f64::from_bits(high),
            // Every coordinate zero: no smallest non-zero magnitude.
            min_abs: if low == u64::MAX {
                f64::INFINITY
            } else {
                f64::from_bits(low + 1)
            },
        }
    }

    /// The power of two that brings the largest coordinate into [0.5, 1), if scaling by it is exact
    /// for every coordinate; otherwise 1 (the predicates then skip their filter and stay exact).
    fn exact_power_of_two_scale(&self) -> f64 {
        let (max_abs, min_abs) = (self.max_abs, self.min_abs);
        if max_abs == 0.0 {
            return 1.0;
        }
        // frexp: max_abs = m · 2^e with m in [0.5, 1); scale = 2^−e, built in two halves so that
        // neither factor overflows or underflows.
        let mut e = 0i32;
        let mut m = max_abs;
        while m >= 1.0 {
            m *= 0.5;
            e += 1;
        }
        while m < 0.5 {
            m *= 2.0;
            e -= 1;
        }
        let half = -e / 2;
        let scale = 2f64.powi(half) * 2f64.powi(-e - half);
        if !scale.is_finite() || scale == 0.0 {
            return 1.0;
        }
        // Multiplying by a power of two is exact unless the result leaves the normal range.
        if min_abs * scale >= f64::MIN_POSITIVE {
            scale
        } else {
            1.0
        }
    }
}

/// Chooses D + 1 affinely independent points spanning a large simplex: the two extreme points
/// farthest apart along the axes, then repeatedly the point farthest from the affine hull of those
/// chosen. Floating point only picks candidates; the result is verified with the exact predicate,
/// and exact rank computation takes over when the greedy choice is flat.
///
/// The first D + 1 entries are the simplex ([`MAX_SIMPLEX`] slots). Fixed arrays, not vectors,
/// and `residuals` (the hull's scratch, one vector per point) keeps its capacity: a rebuilt hull
/// (one per grasp in a batch) allocates nothing here.
pub(in crate::hull) fn initial_simplex<const D: usize>(
    points: &[[f64; D]],
    residuals: &mut Vec<[f64; D]>,
) -> Result<([usize; MAX_SIMPLEX], Option<Extremes>), HullError> {
    if let Some((simplex, extremes)) = greedy_simplex(points, residuals) {
        let mut vertices = [[0.0; D]; D];
        for (v, &s) in vertices.iter_mut().zip(&simplex) {
            *v = points[s];
        }
        if orientation(&vertices, &points[simplex[D]]) != Sign::Zero {
            return Ok((simplex, Some(extremes)));
        }
    }
    let independent = affinely_independent_subset(points);
    if independent.len() < D + 1 {
        return Err(HullError::AffinelyDependent {
            rank: independent.len().saturating_sub(1),
            dimension: D,
        });
    }
    let mut simplex = [0; MAX_SIMPLEX];
    simplex[..=D].copy_from_slice(&independent[..=D]);
    Ok((simplex, None))
}

/// The lowest and the highest point along each axis ([`axis_extremes`]).
pub(in crate::hull) type Extremes = [usize; 2 * MAX_DIMENSION];

/// Whether the points `simplex` (D + 1 indices into `points`) are in range and affinely
/// independent, exactly.
fn independent<const D: usize>(points: &[[f64; D]], simplex: &[usize]) -> bool {
    if simplex.iter().any(|&s| s >= points.len()) {
        return false;
    }
    let mut vertices = [[0.0; D]; D];
    for (v, &s) in vertices.iter_mut().zip(simplex) {
        *v = points[s];
    }
    orientation(&vertices, &points[simplex[D]]) != Sign::Zero
}

fn greedy_simplex<const D: usize>(
    points: &[[f64; D]],
    residuals: &mut Vec<[f64; D]>,
) -> Option<([usize; MAX_SIMPLEX], Extremes)> {
    if points.is_empty() {
        return None;
    }
    let all_extremes = axis_extremes(points);
    let extremes = &all_extremes[..2 * D];
    let mut best = (0.0, 0, 0);
    for (i, &a) in extremes.iter().enumerate() {
        for &b in &extremes[i + 1..] {
            let d = distance_squared(&points[a], &points[b]);
            if d > best.0 {
                best = (d, a, b);
            }
        }
    }
    if best.0 == 0.0 {
        return None;
    }
    let mut chosen = [0usize; MAX_SIMPLEX];
    chosen[0] = best.1;
    chosen[1] = best.2;
    // Orthonormal basis of the directions spanned so far (modified Gram–Schmidt).
    let mut basis = Basis::<D>::default();
    basis.push_direction(sub(points[best.2], points[best.1]));
    let origin = points[best.1];
    if D == 2 {
        // In the plane the initial triangle is widened to every extreme point before the first
        // partition (`Hull::widen_to_extremes`), so its third vertex is taken among them too,
        // the farthest from the line of the first two, without a pass over the input (unless
        // the extreme points are on one line).
        // Only those off that line, exactly: a rounded residual is not zero on the line of a
        // grid's diagonal, and a third vertex on it would send the build to the slow fallback.
        let mut line = [[0.0; D]; D];
        (line[0], line[1]) = (points[best.1], points[best.2]);
        let mut far = (0.0, usize::MAX);
        for &e in extremes {
            let r = basis.residual(sub(points[e], origin));
            let d = dot(r, r);
            if d > far.0 && orientation(&line, &points[e]) != Sign::Zero {
                far = (d, e);
            }
        }
        if far.1 != usize::MAX {
            chosen[2] = far.1;
            return Some((chosen, all_extremes));
        }
    }
    // Each point's residual is kept from pass to pass, and a pass projects out only the
    // directions added since the last: the operations of `Basis::residual` from scratch, in the
    // same order (`project_out`), so the same numbers, at O(D) per point and pass instead of
    // O(D·k). From scratch, the passes were 44 % of an 8-D build of 50,000 points in a simplex.
    // The first pass computes them (and keeps them only if a later pass will read them: not in
    // 2-D, whose one pass would only add the writes).
    residuals.clear();
    let keep = D > 2;
    if keep {
        residuals.reserve(points.len());
    }
    let mut projected = 0;
    for (pass, slot) in chosen[2..=D].iter_mut().enumerate() {
        let new = &basis.directions[projected..basis.len];
        projected = basis.len;
        let mut far = (0.0, usize::MAX);
        let mut consider = |i: usize, r: &mut [f64; D]| {
            for b in new {
                project_out(r, b);
            }
            let d = dot(*r, *r);
            if d > far.0 {
                far = (d, i);
            }
        };
        if pass == 0 {
            for (i, p) in points.iter().enumerate() {
                let mut r = sub(*p, origin);
                consider(i, &mut r);
                if keep {
                    residuals.push(r);
                }
            }
        } else {
            for (i, r) in residuals.iter_mut().enumerate() {
                consider(i, r);
            }
        }
        if far.1 == usize::MAX {
            return None;
        }
        *slot = far.1;
        basis.push_direction(sub(points[far.1], origin));
    }
    Some((chosen, all_extremes))
}

/// `v` minus its projection on the unit vector `b` (one step of modified Gram–Schmidt).
#[inline(always)]
fn project_out<const D: usize>(v: &mut [f64; D], b: &[f64; D]) {
    let c = dot(*b, *v);
    for (x, y) in v.iter_mut().zip(b) {
        *x -= c * y;
    }
}

/// An orthonormal basis of at most [`MAX_DIMENSION`] directions, in place.
struct Basis<const D: usize> {
    directions: [[f64; D]; MAX_DIMENSION],
    len: usize,
}

impl<const D: usize> Default for Basis<D> {
    fn default() -> Self {
        Basis {
            directions: [[0.0; D]; MAX_DIMENSION],
            len: 0,
        }
    }
}

impl<const D: usize> Basis<D> {
    /// `v` minus its projection on the basis.
    fn residual(&self, mut v: [f64; D]) -> [f64; D] {
        for b in &self.directions[..self.len] {
            project_out(&mut v, b);
        }
        v
    }

    /// Adds the normalised residual of `v`, if it is not zero.
    fn push_direction(&mut self, v: [f64; D]) {
        // Two passes of Gram–Schmidt keep the basis orthogonal to working precision.
        let r = self.residual(self.residual(v));
        let n = dot(r, r).sqrt();
        if n > 0.0 && self.len < self.directions.len() {
            self.directions[self.len] = r.map(|x| x / n);
            self.len += 1;
        }
    }
}

/// The lowest and the highest point along each axis (indices; `2·axis` the lowest, `2·axis + 1`
/// the highest), in one pass over the points: one pass per axis and bound read them 2D times, a
/// sixth of a 3-D build of 100,000 points in a cube. Ties go as `min_by` and `max_by` break them
/// under [`f64::total_cmp`]: the first lowest, the last highest.
fn axis_extremes<const D: usize>(points: &[[f64; D]]) -> Extremes {
    let mut low = [(i64::MAX, 0usize); MAX_DIMENSION];
    let mut high = [(i64::MIN, 0usize); MAX_DIMENSION];
    for (i, p) in points.iter().enumerate() {
        for ((&x, lo), hi) in p.iter().zip(&mut low).zip(&mut high) {
            let k = total_order_key(x);
            if k < lo.0 {
                *lo = (k, i);
            }
            if k >= hi.0 {
                *hi = (k, i);
            }
        }
    }
    let mut extremes = [0usize; 2 * MAX_DIMENSION];
    for axis in 0..D {
        extremes[2 * axis] = low[axis].1;
        extremes[2 * axis + 1] = high[axis].1;
    }
    extremes
}

/// `x` as an integer ordered as [`f64::total_cmp`] orders floats (the same transformation).
#[inline]
fn total_order_key(x: f64) -> i64 {
    let bits = x.to_bits() as i64;
    bits ^ (((bits >> 63) as u64) >> 1) as i64
}

fn distance_squared<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    let d = sub(*a, *b);
    dot(d, d)
}

#[cfg(test)]
mod tests;
