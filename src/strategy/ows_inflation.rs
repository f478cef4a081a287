//! `OwsInflation`: the PQHOWS algorithm (Liu & Carpin, Algorithm 2), made exact.

use super::reasons::InflationReason;
use super::{Queued, ReusableStrategy, Stats, Step, Strategy};
use crate::geometry::SupportIndex;
use crate::geometry::vector::dot;
use crate::hull::TraceContext;
use crate::hull::{FacetId, Hull};
use crate::predicates::Sign;
use std::collections::BinaryHeap;

/// Grows the hull until it can tell how far a set of *disturbances* can be inflated before the
/// hull stops resisting them: the largest `r` such that `−r·d` lies in the full hull for every
/// disturbance `d` — the object-wrench-space grasp metric when the hull's points are a grasp's
/// wrenches and the disturbances are the object's wrench space (the grasp layer's `grasp::ows`).
///
/// # Sign
///
/// A disturbance `d` is a wrench applied *to* the object (a push on its surface); the grasp
/// resists it by producing the opposite wrench `−d`. So the ray that matters for `d` starts at the
/// origin and points along `u = −d`, and its *inflation factor* against a facet with unit outward
/// normal `n` and offset `o > 0` is `r = o / (n·u)` (where `n·u > 0`): `−r·d` lies on that facet's
/// plane. The answer is the smallest inflation factor over all disturbances, each taken at the
/// facet its ray leaves the hull through.
///
/// # How it decides
///
/// 1. Grow the hull until the origin is strictly inside it (exact orientation signs). If a facet
///    with the origin on or beyond its plane has no point beyond it, its plane supports the full
///    hull: the origin is not strictly inside, so the set is not force closure and there is no
///    number ([`OwsResult::value`] is `None`).
/// 2. Assign every disturbance to the facet its ray leaves through (the facet with the smallest
///    inflation factor); queue every facet by the smallest factor of its disturbances.
/// 3. Pop the smallest. If no point lies beyond that facet (after [`StrategyHooks::claim_beyond`](crate::hull::StrategyHooks::claim_beyond)), its plane
///    supports the full hull, so the full hull's factor for that disturbance equals the partial
///    one; every other disturbance's partial factor is at least as large, and the full hull
///    contains the partial one, so full factors are larger still: the popped factor is the answer.
///    Otherwise expand the facet and move the disturbances of the removed facets to the new facets
///    (the only facets their rays can now leave through).
///
/// Facets are ordered by lower bounds of their floating-point inflation factors, and the answer
/// is the factor of the exact plane of the facet that stops the search: a few ulps however close
/// the origin is to that plane. Every combinatorial decision is exact.
///
/// # Two bookkeepings, one answer
///
/// [`OwsInflation::with_rays`] is Algorithm 2 as published: every disturbance is assigned to a facet,
/// which costs a pass over all of them against the first hull's facets and a reassignment at each
/// expansion — O(disturbances × facets), dominant for an object wrench space of tens of thousands
/// of disturbances. [`OwsInflation::new`] keys each facet instead by the smallest factor of
/// *any* disturbance against its plane, `offset / h(−n)` with `h` the support function of the
/// disturbances, answered by a [`SupportIndex`] in far fewer than one dot product per
/// disturbance (lazily: a facet waits under a lower bound of its key, from the top of the tree,
/// until that bound reaches the top of the queue). The two keys differ only on facets that are
/// not the minimum: the smallest key is
/// the same facet and the same number in both (`min_F offset_F / h(−n_F)` is the largest `r`
/// with `−r·d` inside the partial hull for every `d`, which is also the smallest factor of any
/// disturbance at its exit facet), so both expand the same facets and stop with the same value.
///
/// ```
/// use pqhull::Hull;
/// use pqhull::strategy::OwsInflation;
///
/// // The square [−1, 1]² resists the disturbances (1, 0) and (1, 1) up to r = 1.
/// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.3, 0.2]];
/// let disturbances = [[1.0, 0.0], [1.0, 1.0]];
/// let (_, result) = Hull::try_with_strategy(&square, OwsInflation::with_rays(&disturbances))?;
/// assert!((result.value.unwrap() - 1.0).abs() < 1e-12);
/// // Doubling every disturbance halves the answer.
/// let doubled = [[2.0, 0.0], [2.0, 2.0]];
/// let (_, result) = Hull::try_with_strategy(&square, OwsInflation::with_rays(&doubled))?;
/// assert!((result.value.unwrap() - 0.5).abs() < 1e-12);
/// // A triangle with the origin on its boundary is not force closure: no value.
/// let triangle = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
/// let (_, result) = Hull::try_with_strategy(&triangle, OwsInflation::with_rays(&disturbances))?;
/// assert_eq!(result.value, None);
/// # Ok::<(), pqhull::HullError>(())
/// ```
#[derive(Clone, Debug)]
pub struct OwsInflation<'a, const D: usize> {
    disturbances: Disturbances<'a, D>,
    phase: Phase,
    queue: BinaryHeap<Entry>,
    /// Disturbance indices assigned to each facet slot, valid while `owner[slot]` is the facet's
    /// serial.
    assigned: Vec<Vec<u32>>,
    owner: Vec<u64>,
    orphans: Vec<u32>,
    /// Older facets that received disturbances in a fallback search, to queue again.
    requeue: Vec<FacetId>,
    /// The facets an expansion created (scratch).
    created: Vec<FacetId>,
    /// The last support point found ([`key_exactly`](Self::key_exactly)'s first incumbent).
    hint: Option<usize>,
    answer: Option<(f64, FacetId, usize)>,
}

/// How a queue entry is keyed. Every key is at most the facet's exact key (the smallest factor
/// of any disturbance against its exact plane), and only an [`Key::Exact`] entry on top is
/// taken as the answer: the answer is then at most every other facet's key, and it is computed
/// from the exact plane — a few ulps even when the origin is within rounding of the plane's
/// floating-point offset (a grasp near the force-closure boundary), where the floating-point
/// factor keeps no correct digit.
#[derive(Clone, Copy, Debug)]
enum Key {
    /// A lower bound from the top of the ball tree only (see `key_by_support`).
    Unkeyed,
    /// A lower bound from the floating-point plane (see [`factor_lower_bound`]), with the
    /// disturbance that attains the floating-point key.
    Bound(u32),
    /// The key from the exact plane (see [`exact_factor`]), with its disturbance.
    Exact(u32),
}

/// How far a precise facet's floating-point unit normal may be from the exact one (the
/// certificate of [`Facet::normal_is_precise`](crate::hull::Facet::normal_is_precise) is 1e−11;
/// twice that covers the rounding of the dot products as well).
const PLANE_TOLERANCE: f64 = 2e-11;

/// A lower bound on the exact inflation factor `offset / rate` of a ray of norm at most
/// `ray_norm` against a precise facet of `hull`, from the facet's floating-point `offset` and
/// `rate` (the ray's dot product with the floating-point normal, or an upper bound on it):
/// `None` when even the exact rate may not be positive (no factor).
///
/// The exact offset is within `PLANE_TOLERANCE·|v0|` of the floating-point one (`v0` the base
/// vertex, `|v0| ≤ √D·` the coordinate bound) and the exact rate within
/// `PLANE_TOLERANCE·ray_norm` of the computed one.
pub fn factor_lower_bound<const D: usize>(
    hull: &Hull<D>,
    offset: f64,
    rate: f64,
    ray_norm: f64,
) -> Option<f64> {
    let offset_error = PLANE_TOLERANCE * (D as f64).sqrt() * hull.coordinate_bound();
    let rate = rate + PLANE_TOLERANCE * ray_norm;
    // The last factor covers the rounding of the subtraction and the division.
    (rate > 0.0).then(|| (offset - offset_error).max(0.0) / rate * (1.0 - 1e-15))
}

/// The exact key of facet `id`: the origin's exact distance inside its plane (a few ulps, see
/// [`StrategyHooks::exact_signed_distance`](crate::hull::StrategyHooks::exact_signed_distance)) over `support(−n)`, the largest rate of any disturbance
/// against the exact plane's unit normal `n`, with that disturbance; `None` when no disturbance
/// reaches the plane.
pub fn exact_factor<const D: usize>(
    hull: &Hull<D>,
    id: FacetId,
    support: impl FnOnce(&[f64; D]) -> Option<(f64, usize)>,
) -> Option<(f64, usize)> {
    let toward = hull.exact_normal(id).map(|c| -c);
    let origin = [0.0; D];
    let offset = -hull
        .exact_signed_distance(id, &origin)
        .unwrap_or_else(|| hull.signed_distance(id, &origin));
    let (h, disturbance) = support(&toward)?;
    (h > 0.0).then(|| (offset.max(0.0) / h, disturbance))
}

/// Depth of the ball-tree nodes whose bounds give a facet's first, lower-bound key (at most 4
/// node bounds instead of a full support query).
const BOUND_DEPTH: usize = 2;

/// How facets are keyed (see the type's docs).
#[derive(Clone, Copy, Debug)]
enum Disturbances<'a, const D: usize> {
    /// Algorithm 2 as published: each disturbance assigned to the facet its ray leaves through.
    Rays(&'a [[f64; D]]),
    /// Each facet keyed through the support function.
    Support(&'a SupportIndex<D>),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Growing the hull until the origin is strictly inside.
    ContainOrigin,
    /// Inflating the disturbances.
    Inflate,
    /// Not force closure.
    Outside,
    Done,
}

/// What [`OwsInflation`] finds.
#[derive(Clone, Debug, PartialEq)]
pub struct OwsResult<const D: usize> {
    /// The largest `r` with `−r·d` in the full hull for every disturbance `d`; `None` when the
    /// origin is not strictly inside the full hull (not force closure). `f64::INFINITY` when every
    /// disturbance is the zero vector.
    pub value: Option<f64>,
    /// The facet the deciding disturbance's ray leaves through (when there is a finite value).
    pub deciding_facet: Option<FacetId>,
    /// That facet's vertices (input indices).
    pub deciding_facet_vertices: Option<[usize; D]>,
    /// The index of the deciding disturbance (the first one in input order among exact ties is
    /// not guaranteed).
    pub deciding_disturbance: Option<usize>,
    /// Work done by the partial hull.
    pub stats: Stats,
}

/// The inflation factor of ray `u` against a facet plane `normal · x = offset` whose offset is
/// positive (the origin inside): `offset / (normal · u)`, or `None` when the ray runs parallel to or
/// away from the plane. A non-positive offset (the origin within rounding of the plane) gives 0.
pub fn inflation_factor<const D: usize>(
    normal: &[f64; D],
    offset: f64,
    u: &[f64; D],
) -> Option<f64> {
    let rate = dot(*normal, *u);
    (rate > 0.0).then(|| offset.max(0.0) / rate)
}

impl<'a, const D: usize> OwsInflation<'a, D> {
    /// A strategy inflating the disturbances of `index` (each resisted by its opposite; see the
    /// type's docs), keying facets through their support function: the fast one, and the
    /// default everywhere.
    pub fn new(index: &'a SupportIndex<D>) -> Self {
        Self::with(Disturbances::Support(index))
    }

    /// The same answer with every disturbance assigned to the facet its ray leaves through, as
    /// the seed paper's Algorithm 2 is published: much slower on large disturbance sets, kept to
    /// compare with.
    pub fn with_rays(disturbances: &'a [[f64; D]]) -> Self {
        Self::with(Disturbances::Rays(disturbances))
    }

    /// This strategy's buffers (queue, assignments, scratch) under a new index, for the next
    /// run: evaluating many grasps against one object wrench space then allocates no new queue.
    pub fn rebind_index<'b>(self, index: &'b SupportIndex<D>) -> OwsInflation<'b, D> {
        self.rebind(Disturbances::Support(index))
    }

    /// This strategy's buffers with no disturbances (the [`Default`]), to keep between runs
    /// without borrowing anything.
    pub fn park(self) -> OwsInflation<'static, D> {
        self.rebind(Disturbances::Rays(&[]))
    }

    fn rebind<'b>(self, disturbances: Disturbances<'b, D>) -> OwsInflation<'b, D> {
        OwsInflation {
            disturbances,
            phase: Phase::ContainOrigin,
            queue: self.queue,
            assigned: self.assigned,
            owner: self.owner,
            orphans: self.orphans,
            requeue: self.requeue,
            created: self.created,
            hint: None,
            answer: None,
        }
    }

    fn with(disturbances: Disturbances<'a, D>) -> Self {
        OwsInflation {
            disturbances,
            phase: Phase::ContainOrigin,
            queue: BinaryHeap::new(),
            assigned: Vec::new(),
            owner: Vec::new(),
            orphans: Vec::new(),
            requeue: Vec::new(),
            created: Vec::new(),
            hint: None,
            answer: None,
        }
    }

    /// The ray of disturbance `i`: `−d_i`.
    fn ray(&self, i: u32) -> [f64; D] {
        match self.disturbances {
            Disturbances::Rays(d) => d[i as usize].map(|c| -c),
            Disturbances::Support(_) => unreachable!("rays are only followed in Rays mode"),
        }
    }

    /// Refines and queues `ids` by the support function, lazily: each facet first by a lower
    /// bound of its key, `offset / h⁺(−n)` with `h⁺ ≥ h` from the top of the ball tree; its exact
    /// key (the smallest factor of any disturbance against its plane) is computed only when that
    /// bound reaches the top of the queue ([`key_exactly`](Self::key_exactly)). An exact entry on
    /// top is then at most every other entry's bound, hence every other key: most facets never
    /// need a full support query.
    fn key_by_support(&mut self, hull: &mut Hull<D>, index: &SupportIndex<D>, ids: &[FacetId]) {
        for &id in ids {
            hull.refine_normal(id);
            let facet = hull.facet(id);
            let toward = facet.normal().map(|c| -c);
            let upper = index.upper_bound(&toward, BOUND_DEPTH);
            // h⁺ ≥ h: a lower bound of a lower bound. None: no disturbance reaches this plane.
            if let Some(factor) =
                factor_lower_bound(hull, facet.offset(), upper, index.norm_bound())
            {
                self.queue
                    .push(Entry::factored(factor, id, facet.serial(), Key::Unkeyed));
            }
        }
    }

    /// Queues facet `id` (current, normal refined) by a lower bound of its key from the full
    /// support query on its floating-point plane.
    fn key_exactly(&mut self, hull: &Hull<D>, index: &SupportIndex<D>, id: FacetId) {
        let facet = hull.facet(id);
        let toward = facet.normal().map(|c| -c);
        // Facets keyed one after another are often adjacent, with close normals: the last
        // support point is a good first incumbent for the branch and bound.
        let support = index.support_near(&toward, self.hint);
        self.hint = support.map(|(_, at)| at);
        if let Some((h, disturbance)) = support
            && let Some(factor) = factor_lower_bound(hull, facet.offset(), h, index.norm_bound())
        {
            self.queue.push(Entry::factored(
                factor,
                id,
                facet.serial(),
                Key::Bound(disturbance as u32),
            ));
        }
    }

    /// Facet `id`'s key from its exact plane, against every disturbance.
    fn exact_key(&self, hull: &Hull<D>, id: FacetId) -> Option<(f64, u32)> {
        let found = match self.disturbances {
            Disturbances::Support(index) => exact_factor(hull, id, |v| index.support(v)),
            Disturbances::Rays(d) => exact_factor(hull, id, |v| {
                d.iter()
                    .enumerate()
                    .map(|(i, d)| (dot(*v, *d), i))
                    .max_by(|a, b| a.0.total_cmp(&b.0))
            }),
        };
        found.map(|(factor, d)| (factor, d as u32))
    }

    /// Sets up the inflation phase over the live facets.
    fn begin_inflation(&mut self, hull: &mut Hull<D>) {
        self.phase = Phase::Inflate;
        // The live ids, in the buffer `after_expansion` uses (kept across runs).
        let mut live = std::mem::take(&mut self.created);
        live.clear();
        live.extend(hull.facets().map(|(id, _)| id));
        match self.disturbances {
            Disturbances::Rays(d) => {
                self.orphans.extend(0..d.len() as u32);
                self.assign(hull, &live);
            }
            Disturbances::Support(index) => self.key_by_support(hull, index, &live),
        }
        self.created = live;
    }

    /// After an expansion: re-key what changed.
    fn after_expansion(&mut self, hull: &mut Hull<D>) {
        // The created ids are copied out (the re-keying refines normals through `&mut Hull`)
        // into a buffer kept across expansions.
        let mut created = std::mem::take(&mut self.created);
        created.clear();
        created.extend_from_slice(hull.last_created());
        match self.disturbances {
            Disturbances::Rays(_) => {
                for k in 0..hull.last_removed().len() {
                    let removed = hull.last_removed()[k].index();
                    // A removed facet's slot is not reused within the same expansion, so its
                    // list still belongs to it; lists of facets never assigned anything are
                    // empty.
                    if removed < self.assigned.len() {
                        self.orphans.append(&mut self.assigned[removed]);
                        self.owner[removed] = u64::MAX;
                    }
                }
                self.assign(hull, &created);
            }
            Disturbances::Support(index) => self.key_by_support(hull, index, &created),
        }
        self.created = created;
    }

    /// Assigns every disturbance in `self.orphans` to the facet among `candidates` its ray leaves
    /// through, then queues each candidate that received any.
    fn assign(&mut self, hull: &mut Hull<D>, candidates: &[FacetId]) {
        for &id in candidates {
            // Inflation factors need certified normals.
            hull.refine_normal(id);
            let slot = id.index();
            if self.assigned.len() <= slot {
                self.assigned.resize_with(slot + 1, Vec::new);
                self.owner.resize(slot + 1, u64::MAX);
            }
            self.assigned[slot].clear();
            self.owner[slot] = hull.facet(id).serial();
        }
        for o in 0..self.orphans.len() {
            let i = self.orphans[o];
            let u = self.ray(i);
            let best = candidates
                .iter()
                .filter_map(|&id| {
                    let f = hull.facet(id);
                    inflation_factor(&f.normal(), f.offset(), &u).map(|r| (r, id))
                })
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let best = best.or_else(|| {
                // Rounding left the ray parallel to every new facet: it leaves through a facet
                // that shares the old exit point. Search them all.
                let live: Vec<FacetId> = hull.facets().map(|(id, _)| id).collect();
                live.into_iter()
                    .filter_map(|id| {
                        hull.refine_normal(id);
                        let f = hull.facet(id);
                        inflation_factor(&f.normal(), f.offset(), &u).map(|r| (r, id))
                    })
                    .min_by(|a, b| a.0.total_cmp(&b.0))
            });
            if let Some((_, id)) = best {
                if !candidates.contains(&id) {
                    self.requeue.push(id);
                }
                self.assigned[id.index()].push(i);
            }
            // No facet at all: the zero disturbance, which constrains nothing.
        }
        self.orphans.clear();
        for &id in candidates {
            self.enqueue(hull, id);
        }
        while let Some(id) = self.requeue.pop() {
            self.enqueue(hull, id);
        }
    }

    /// Queues facet `id` by the smallest inflation factor among its disturbances.
    fn enqueue(&mut self, hull: &Hull<D>, id: FacetId) {
        let facet = hull.facet(id);
        let slot = id.index();
        if self.owner.get(slot) != Some(&facet.serial()) {
            return;
        }
        let best = self.assigned[slot]
            .iter()
            .filter_map(|&i| {
                let u = self.ray(i);
                let rate = dot(facet.normal(), u);
                factor_lower_bound(hull, facet.offset(), rate, dot(u, u).sqrt()).map(|r| (r, i))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((factor, disturbance)) = best {
            self.queue.push(Entry::factored(
                factor,
                id,
                facet.serial(),
                Key::Bound(disturbance),
            ));
        }
    }

    fn step_contain_origin(&mut self, hull: &mut Hull<D>) -> Step {
        let origin = [0.0; D];
        let mut worst: Option<(f64, FacetId)> = None;
        for (id, facet) in hull.facets() {
            if hull.side_of(id, &origin) != Sign::Negative {
                let beyond = -facet.offset();
                if worst.is_none_or(|(b, _)| beyond > b) {
                    worst = Some((beyond, id));
                }
            }
        }
        let Some((beyond, id)) = worst else {
            hull.trace_note(Some(origin), InflationReason::OriginInside);
            self.begin_inflation(hull);
            return Step::Continue;
        };
        hull.trace_choice(id, InflationReason::OriginBeyond { distance: beyond });
        if hull.facet(id).outside_len() > 0 || hull.claim_beyond(id) {
            hull.expand(id);
            Step::Continue
        } else {
            // This facet's plane supports the full hull with the origin on or beyond it.
            self.phase = Phase::Outside;
            hull.trace_stop(Some(id), InflationReason::NotForceClosure);
            Step::Stop
        }
    }

    fn step_inflate(&mut self, hull: &mut Hull<D>) -> Step {
        while let Some(entry) = self.queue.pop() {
            if !hull.is_current(entry.id, entry.serial) {
                continue;
            }
            let id = entry.id;
            let (disturbance, exact) = match entry.data {
                Key::Unkeyed => {
                    if let Disturbances::Support(index) = self.disturbances {
                        self.key_exactly(hull, index, id);
                    }
                    continue;
                }
                Key::Bound(d) => (d, false),
                Key::Exact(d) => (d, true),
            };
            hull.trace_choice(
                id,
                InflationReason::Smallest {
                    disturbance: disturbance as usize,
                    factor: entry.factor(),
                },
            );
            if hull.facet(id).outside_len() > 0 || hull.claim_beyond(id) {
                hull.expand(id);
                self.after_expansion(hull);
                return Step::Continue;
            }
            if !exact {
                // This plane supports the full hull: its key from the exact plane goes back in
                // the queue, to be the answer if it is still the smallest.
                if let Some((factor, d)) = self.exact_key(hull, id) {
                    self.queue
                        .push(Entry::factored(factor, id, entry.serial, Key::Exact(d)));
                }
                continue;
            }
            self.answer = Some((entry.factor(), id, disturbance as usize));
            self.phase = Phase::Done;
            hull.trace_stop(
                Some(id),
                InflationReason::Certified {
                    disturbance: disturbance as usize,
                    value: entry.factor(),
                },
            );
            return Step::Stop;
        }
        // Every disturbance is zero: nothing to resist.
        self.phase = Phase::Done;
        hull.trace_stop(None, InflationReason::NoDisturbance);
        Step::Stop
    }
}

impl<const D: usize> Strategy<D> for OwsInflation<'_, D> {
    type Output = OwsResult<D>;

    fn start(&mut self, _hull: &Hull<D>) {
        self.phase = Phase::ContainOrigin;
        self.hint = None;
        self.queue.clear();
        self.assigned.iter_mut().for_each(Vec::clear);
        self.owner.iter_mut().for_each(|o| *o = u64::MAX);
        self.orphans.clear();
        self.answer = None;
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        match self.phase {
            Phase::ContainOrigin => self.step_contain_origin(hull),
            Phase::Inflate => self.step_inflate(hull),
            Phase::Outside | Phase::Done => Step::Stop,
        }
    }

    fn partitions_to_farthest(&self) -> bool {
        true
    }

    fn refines_all_normals(&self) -> bool {
        false // every facet whose factor is used was refined when its disturbances were assigned
    }

    fn trace_context(&self) -> TraceContext<D> {
        TraceContext {
            strategy: "OwsInflation".to_string(),
            query: None,
            disturbances: match self.disturbances {
                Disturbances::Rays(d) => d.to_vec(),
                Disturbances::Support(index) => index.points_in_input_order(),
            },
        }
    }

    fn finish(self, hull: &Hull<D>) -> OwsResult<D> {
        self.result(hull)
    }
}

/// No disturbances at all: nothing to resist, so a force-closure hull gets an infinite value
/// (and a hull without force closure none). Useful only as a strategy's parked state between
/// runs.
impl<const D: usize> Default for OwsInflation<'static, D> {
    fn default() -> Self {
        OwsInflation::with_rays(&[])
    }
}

/// A borrowed `OwsInflation` runs the same way and keeps its buffers (queue, assignments,
/// scratch) for the next run.
///
/// ```
/// use pqhull::Hull;
/// use pqhull::strategy::OwsInflation;
/// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
/// let disturbances = [[1.0, 0.0]];
/// let mut strategy = OwsInflation::with_rays(&disturbances);
/// let (mut hull, first) = Hull::try_with_strategy(&square, &mut strategy)?;
/// let wide = square.map(|p| [2.0 * p[0], p[1]]);
/// let second = hull.rebuild_with_strategy(&wide, &mut strategy)?;
/// assert!((first.value.unwrap() - 1.0).abs() < 1e-12);
/// assert!((second.value.unwrap() - 2.0).abs() < 1e-12);
/// # Ok::<(), pqhull::HullError>(())
/// ```
impl<const D: usize> ReusableStrategy<D> for OwsInflation<'_, D> {
    fn output(&self, hull: &Hull<D>) -> OwsResult<D> {
        self.result(hull)
    }
}

impl<const D: usize> OwsInflation<'_, D> {
    /// The answer of the run that just stopped.
    fn result(&self, hull: &Hull<D>) -> OwsResult<D> {
        let stats = hull.stats();
        match (self.phase, self.answer) {
            (Phase::Done, Some((value, id, disturbance))) => OwsResult {
                value: Some(value),
                deciding_facet: Some(id),
                deciding_facet_vertices: Some(hull.facet(id).vertices()),
                deciding_disturbance: Some(disturbance),
                stats,
            },
            (Phase::Done, None) => OwsResult {
                value: Some(f64::INFINITY),
                deciding_facet: None,
                deciding_facet_vertices: None,
                deciding_disturbance: None,
                stats,
            },
            _ => OwsResult {
                value: None,
                deciding_facet: None,
                deciding_facet_vertices: None,
                deciding_disturbance: None,
                stats,
            },
        }
    }
}

/// A queued facet keyed by minus (a lower bound of) its smallest inflation factor (so the
/// smallest factor is on top of the max-heap), with how it was keyed.
type Entry = Queued<Key>;

impl Entry {
    fn factored(factor: f64, id: FacetId, serial: u64, key: Key) -> Entry {
        Queued {
            key: -factor,
            id,
            serial,
            data: key,
        }
    }

    fn factor(&self) -> f64 {
        -self.key
    }
}
