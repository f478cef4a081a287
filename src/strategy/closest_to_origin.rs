//! `ClosestToOrigin`: the PQHGWS algorithm (Liu & Carpin, Algorithm 1), made exact.

use super::reasons::NearestReason;
use super::{Queued, ReusableStrategy, Stats, Step, Strategy};
use crate::geometry::vector::{dot, norm};
use crate::geometry::{min_norm_point, min_norm_point_accurate, min_norm_point_exact, rescaled};
use crate::hull::{FacetId, Hull, Partition, StrategyHooks, TraceContext};
use crate::predicates::Sign;
use std::collections::BinaryHeap;

mod source;
use source::Implicit;
pub use source::{NoSource, PointSource, SourceError};

/// Grows the hull toward a query point (default: the origin) and stops as soon as the facet nearest
/// that point is certain, returning the signed distance from the point to the boundary of the
/// *full* hull — positive inside, negative outside — without building the full hull.
///
/// # How it decides
///
/// Facets wait in a priority queue keyed by how far the query point lies beyond their plane. The
/// strategy pops the top facet; if any point lies strictly beyond it (its outside set, after
/// [`StrategyHooks::claim_beyond`]), the facet is expanded and its replacements queued. Otherwise the facet's
/// plane supports *every* input point, and:
///
/// * **query inside** (checked exactly against every live facet): the partial hull `P` is inside the
///   full hull `H`, so dist(q, ∂H) ≥ dist(q, ∂P) = distance to this facet's plane, and this plane is
///   a supporting plane of `H`, so the two are equal. The answer is exact up to the rounding of one
///   dot product; within about 1e−10 of the input's size of the boundary, where that rounding
///   would dominate, it is the exact determinant divided by the exact cofactors' norm (and the
///   facets about as near are settled too, so a query exactly on the boundary gets exactly 0).
/// * **query outside**: the distance to a facet's plane (the facet-offset rule) is only a
///   lower bound on the distance to the hull — equal only when the foot of the perpendicular lands
///   inside the facet. Instead the strategy takes the point `x` of `P` nearest `q` (Wolfe's
///   algorithm over the vertices of the facets `q` sees, decided exactly, with an accurate
///   residual `q − x`) and checks the supporting hyperplane through `x` normal to `q − x`: if no
///   remaining point lies beyond it, `x` is the nearest point of `H` too (every point of `H` is a
///   convex combination of points behind that plane). Otherwise the point farthest beyond it is
///   added — a GJK-like step — and the search repeats.
///
/// ```
/// use pqhull::{ClosestToOrigin, Hull};
/// // A triangle containing the origin: nearest side at distance 1.
/// let points = [[-2.0, -1.0], [3.0, -1.0], [0.0, 4.0]];
/// let (_, inside) = Hull::try_with_strategy(&points, ClosestToOrigin::new())?;
/// assert!((inside.signed_distance - 1.0).abs() < 1e-12);
/// // The same triangle seen from (0, −3): outside, nearest point (0, −1).
/// let (_, outside) = Hull::try_with_strategy(&points, ClosestToOrigin::towards([0.0, -3.0]))?;
/// assert!((outside.signed_distance + 2.0).abs() < 1e-12);
/// assert!((outside.nearest_point[1] + 1.0).abs() < 1e-12);
/// # Ok::<(), pqhull::HullError>(())
/// ```
///
/// # Output
///
/// Without a point source ([`new`](Self::new), [`towards`](Self::towards)) the run gives a
/// [`DistanceResult`]. With one ([`with_source`](Self::with_source)) it gives
/// `Result<DistanceResult, SourceError>`: a source that breaks [`PointSource`]'s contract — a
/// point not strictly beyond the facet it was asked about, or outside the hull's coordinate
/// range — stops the run with a [`SourceError`] naming the facet and the point (the partial
/// hull is left valid, without that point).
#[derive(Clone, Debug)]
pub struct ClosestToOrigin<const D: usize, S = NoSource> {
    query: [f64; D],
    source: S,
    queue: BinaryHeap<Entry>,
    phase: Phase,
    answer: Option<(f64, FacetId, [f64; D])>,
    /// The contract the source broke, which stopped the run.
    error: Option<SourceError<D>>,
    /// Scratch: the facets the query sees (outside phase) or that are about as near as the
    /// deciding one (inside, near the boundary), and the seen facets' vertices.
    seen: Vec<FacetId>,
    seen_vertices: Vec<usize>,
    /// Whether this run has switched the engine to [`Partition::NearestFirst`] (see
    /// `step_nearest`).
    nearest_first: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Looking for the facet nearest the query point (or one that proves it outside).
    Nearest,
    /// The query point is outside the full hull; refining the nearest point.
    Outside,
    Done,
}

/// What [`ClosestToOrigin`] finds.
#[derive(Clone, Debug, PartialEq)]
pub struct DistanceResult<const D: usize> {
    /// Signed Euclidean distance from the query point to the boundary of the full hull: positive
    /// inside, negative outside, exactly zero on the boundary; the sign is decided exactly.
    ///
    /// Outside, the magnitude is accurate to 1e−12 of itself or 1e−15 of the input's size (its
    /// largest point norm), whichever is larger, however close the query is (Wolfe's nearest point
    /// with an accurate residual). Inside, it is the distance to the deciding facet's plane: within
    /// about 1e−10 of the input's size, the exact determinant over the exact cofactors' norm
    /// (a few ulps); farther in, floating point, as accurate as the facet's normal (certified to
    /// 1e−11 relative, usually a few ulps). A distance below the smallest subnormal `f64` — only
    /// for inputs themselves near the subnormal range — is rounded up to it, keeping the sign.
    /// The outside certificate is floating point (see the type's docs).
    pub signed_distance: f64,
    /// The deciding facet: its plane is nearest the query point (inside) or it holds the nearest
    /// point (outside). A facet of the partial hull, and (up to the triangulation of coplanar
    /// facets) of the full hull.
    pub closest_facet: FacetId,
    /// The deciding facet's vertices (input indices).
    pub closest_facet_vertices: [usize; D],
    /// The point of the hull boundary nearest the query point. For a query with a coordinate
    /// beyond twice the input's [`coordinate_bound`](crate::hull::StrategyHooks::coordinate_bound), the exact one
    /// rounded to the nearest `f64` in each coordinate (so a point of the hull to half an ulp);
    /// nearer, to a few ulps of the query's and the input's coordinates.
    pub nearest_point: [f64; D],
    /// Work done by the partial hull.
    pub stats: Stats,
}

impl<const D: usize> DistanceResult<D> {
    /// Whether the query point lies strictly inside the hull.
    pub fn is_inside(&self) -> bool {
        self.signed_distance > 0.0
    }
}

/// Whether every coordinate of `point` is finite and at most `bound` in magnitude (the range
/// [`StrategyHooks::insert_beyond`] accepts).
fn in_range<const D: usize>(point: &[f64; D], bound: f64) -> bool {
    point.iter().all(|x| x.abs() <= bound)
}

impl<const D: usize> Default for ClosestToOrigin<D> {
    fn default() -> Self {
        Self::towards([0.0; D])
    }
}

impl<const D: usize> ClosestToOrigin<D> {
    /// Toward the origin (the Ferrari–Canny metric's query point).
    pub fn new() -> Self {
        Self::default()
    }

    /// Toward `query` (caller's units).
    pub fn towards(query: [f64; D]) -> Self {
        Self::build(query, NoSource)
    }
}

impl<const D: usize, S: PointSource<D>> ClosestToOrigin<D, S> {
    /// Toward `query`, over the hull's input *and* the implicit points of `source`. The run's
    /// output is then a `Result`: [`SourceError`] when `source` breaks [`PointSource`]'s
    /// contract.
    pub fn with_source(query: [f64; D], source: S) -> Self {
        Self::build(query, source)
    }
}

impl<const D: usize, S> ClosestToOrigin<D, S> {
    fn build(query: [f64; D], source: S) -> Self {
        Self {
            query,
            source,
            queue: BinaryHeap::new(),
            phase: Phase::Nearest,
            answer: None,
            error: None,
            seen: Vec::new(),
            seen_vertices: Vec::new(),
            nearest_first: false,
        }
    }

    /// The implicit point source, to refill it between runs of a reused strategy (see the
    /// `&mut ClosestToOrigin` impl of [`Strategy`]).
    ///
    /// ```
    /// use pqhull::strategy::NoSource;
    /// use pqhull::ClosestToOrigin;
    /// let mut strategy = ClosestToOrigin::<2>::new();
    /// let _: &mut NoSource = strategy.source_mut();
    /// ```
    pub fn source_mut(&mut self) -> &mut S {
        &mut self.source
    }

    /// The implicit point source, to read what it recorded of the last run.
    pub fn source(&self) -> &S {
        &self.source
    }
}

impl<const D: usize, S: Implicit<D>> ClosestToOrigin<D, S> {
    /// Queues facet `id` keyed by how far the query lies beyond it — for a facet whose normal is
    /// not precise, a certified upper bound, so that no facet is popped later than it should be;
    /// its exact key is computed when it reaches the top.
    fn enqueue(&mut self, hull: &Hull<D>, id: FacetId) {
        self.queue.push(Entry {
            key: hull.distance_upper_bound(id, &self.query),
            id,
            serial: hull.facet(id).serial(),
            data: (),
        });
    }

    fn expand(&mut self, hull: &mut Hull<D>, id: FacetId, point: Option<usize>) {
        // Once the query is inside, by the facet's support point among all the points (fewer
        // facets for force-closure Q1 at 4 × 32: 531 instead of 606 per ellipsoid grasp);
        // before, by its own farthest point (the support point made more facets on grasps that
        // are not force closure, whose search ends outside).
        let expanded = match point {
            Some(p) => hull.expand_with(id, p),
            None if self.nearest_first => hull.expand_to_support(id),
            None => hull.expand(id),
        };
        debug_assert!(expanded, "only facets with outside points are expanded");
        self.enqueue_created(hull);
    }

    fn enqueue_created(&mut self, hull: &Hull<D>) {
        for i in 0..hull.last_created().len() {
            let created = hull.last_created()[i];
            self.enqueue(hull, created);
        }
    }

    /// One step of the search for the nearest facet.
    fn step_nearest(&mut self, hull: &mut Hull<D>) -> Step {
        while let Some(entry) = self.queue.pop() {
            if !hull.is_current(entry.id, entry.serial) {
                continue;
            }
            let id = entry.id;
            if !hull.facet(id).normal_is_precise() {
                hull.refine_normal(id);
                self.enqueue(hull, id);
                continue;
            }
            if !self.nearest_first && entry.key < 0.0 {
                // The largest upper bound of the query's height over a live facet is negative:
                // the query is strictly inside the partial hull, and stays so. From now on the
                // points of removed facets go to the first new facet holding them, nearest the
                // query first: they stay beyond the facets the search is about, and testing
                // stops at the first. Only the work changes (ARCHITECTURE.md, "Partition"):
                // against the farthest facet, force-closure Q1 at 4 × 32 creates a quarter
                // fewer facets (`profile_q1`).
                hull.set_partition(Partition::NearestFirst(self.query));
                self.nearest_first = true;
            }
            hull.trace_choice(
                id,
                NearestReason::<D>::Nearest {
                    distance: entry.key,
                },
            );
            if self.grow_beyond(hull, id) {
                return Step::Continue;
            }
            // Nothing lies beyond `id`: its plane supports the full hull.
            let query_side = hull.side_of(id, &self.query);
            if query_side == Sign::Positive {
                hull.trace_note(None, NearestReason::<D>::Outside);
                self.phase = Phase::Outside;
                return Step::Continue;
            }
            // The queue order is floating point; make sure the query is inside the partial hull.
            let beyond = hull
                .facets()
                .map(|(g, _)| g)
                .find(|&g| hull.side_of(g, &self.query) == Sign::Positive);
            if let Some(g) = beyond {
                self.queue.push(entry);
                if hull.is_tracing() {
                    let distance = hull.signed_distance(g, &self.query);
                    hull.trace_choice(g, NearestReason::<D>::QueryBeyond { distance });
                }
                if hull.facet(g).outside_len() > 0 || hull.claim_beyond(g) {
                    self.expand(hull, g, None);
                } else {
                    hull.trace_note(None, NearestReason::<D>::Outside);
                    self.phase = Phase::Outside;
                }
                return Step::Continue;
            }
            let float = -hull.facet(id).signed_distance(&self.query);
            let near = NEAR_BOUNDARY * hull.coordinate_bound();
            let (distance, id) = if query_side == Sign::Zero {
                (0.0, id)
            } else if float > near {
                (float, id)
            } else {
                match self.near_boundary(hull, id, float + near) {
                    Some(found) => found,
                    None => {
                        // An about equally near facet still had points beyond it: one was added.
                        self.queue.push(entry);
                        return Step::Continue;
                    }
                }
            };
            let query_side = if distance == 0.0 {
                Sign::Zero
            } else {
                query_side
            };
            let normal = hull.facet(id).normal();
            let foot = std::array::from_fn(|c| self.query[c] + distance * normal[c]);
            self.answer = Some((distance, id, foot));
            self.phase = Phase::Done;
            hull.trace_stop(
                Some(id),
                NearestReason::<D>::InsideCertified {
                    distance,
                    on_boundary: query_side == Sign::Zero,
                },
            );
            return Step::Stop;
        }
        unreachable!("a hull always has live facets, each queued when created")
    }

    /// The inside answer when the query is within `band` (about 1e−10 of the input's size) of the
    /// plane of `id`, the facet the queue popped: the distances of the other facets' planes are
    /// then as uncertain as their differences, so every facet that may be as near is settled
    /// first — expanded if anything lies beyond it (then `None`: the search goes on), else measured
    /// exactly — and the nearest is returned, 0 for a facet through the query.
    ///
    /// Each such facet has nothing beyond it, so its plane supports the full hull: the smallest
    /// exact distance is the answer, as for the popped facet alone far from the boundary.
    fn near_boundary(
        &mut self,
        hull: &mut Hull<D>,
        id: FacetId,
        band: f64,
    ) -> Option<(f64, FacetId)> {
        let query = self.query;
        self.seen.clear();
        for (g, _) in hull.facets() {
            if g != id && hull.distance_upper_bound(g, &query) >= -band {
                self.seen.push(g);
            }
        }
        let inside_distance = |hull: &Hull<D>, g: FacetId| {
            -hull
                .exact_signed_distance(g, &query)
                .unwrap_or_else(|| hull.signed_distance(g, &query))
        };
        let mut best = (inside_distance(hull, id), id);
        let mut on_boundary = false;
        for i in 0..self.seen.len() {
            let g = self.seen[i];
            if self.grow_beyond(hull, g) {
                return None;
            }
            // The query is weakly inside every facet (checked exactly by the caller).
            if hull.side_of(g, &query) == Sign::Zero {
                best = (0.0, g);
                on_boundary = true;
                break;
            }
            let distance = inside_distance(hull, g);
            if distance < best.0 {
                best = (distance, g);
            }
        }
        hull.refine_normal(best.1);
        if best.0 <= 0.0 && !on_boundary {
            // Strictly inside, nearer than the smallest subnormal: round up, keep the sign.
            best.0 = f64::from_bits(1);
        }
        Some(best)
    }

    /// Adds a point strictly beyond facet `id` — an input point (after
    /// [`StrategyHooks::claim_beyond`]) or one of the source's — and queues the new facets; `false` when
    /// nothing lies beyond it, so that its plane supports the full hull.
    fn grow_beyond(&mut self, hull: &mut Hull<D>, id: FacetId) -> bool {
        if hull.facet(id).outside_len() > 0 || hull.claim_beyond(id) {
            self.expand(hull, id, None);
            return true;
        }
        if let Some(point) = self.source.beyond(hull, id) {
            let facet_vertices = hull.facet(id).vertices();
            let bound = hull.coordinate_bound();
            let error = if !in_range(&point, bound) {
                SourceError::OutOfRange {
                    facet: id,
                    facet_vertices,
                    point,
                    bound,
                }
            } else {
                match hull.side_of(id, &point) {
                    Sign::Positive => match hull.insert_beyond(id, point) {
                        Some(_) => {
                            self.enqueue_created(hull);
                            return true;
                        }
                        None => SourceError::TooManyPoints { facet: id, point },
                    },
                    side => SourceError::NotBeyond {
                        facet: id,
                        facet_vertices,
                        point,
                        side,
                    },
                }
            };
            self.fail(hull, error);
            return true;
        }
        false
    }

    /// Stops the run on a broken source contract.
    fn fail(&mut self, hull: &mut Hull<D>, error: SourceError<D>) {
        if hull.is_tracing() {
            hull.trace_stop(None, NearestReason::<D>::Failed(error.clone()));
        }
        self.error = Some(error);
        self.phase = Phase::Done;
    }

    /// One step of the outside phase: nearest point of the partial hull, then its certificate.
    fn step_outside(&mut self, hull: &mut Hull<D>) -> Step {
        let closest = self.nearest_point(hull);
        let x = closest.point;
        hull.trace_note(Some(x), NearestReason::<D>::NearestPoint);
        // Heights along q − x measured from the query, where q − x is known accurately: the
        // supporting plane through x is at height −|q − x|². For a far query, measured from x
        // instead (the plane at height 0): p − q would lose every bit of p's offset from x.
        // Along q − x divided by a power of two (see `nearest_point`): exact in direction.
        let direction = rescaled(&closest.offset.map(|c| -c));
        let origin = if closest.far { x } else { self.query };
        let height = |p: [f64; D]| dot(direction, std::array::from_fn(|c| p[c] - origin[c]));
        let level = if closest.far {
            0.0
        } else {
            dot(direction, closest.offset)
        };
        let mut best: Option<(f64, FacetId, usize)> = None;
        for (g, facet) in hull.facets() {
            for p in facet.outside_set() {
                let height = height(hull.point(p));
                if height > level && best.is_none_or(|(h, _, _)| height > h) {
                    best = Some((height, g, p));
                }
            }
        }
        if best.is_none()
            && let Some(s) = self.source.support_point(&direction)
            && height(s) > level
        {
            let bound = hull.coordinate_bound();
            if !in_range(&s, bound) {
                let error = SourceError::SupportOutOfRange {
                    direction,
                    point: s,
                    bound,
                };
                self.fail(hull, error);
                return Step::Stop;
            }
            // An implicit point beyond the certificate plane: it is outside the partial hull, so
            // some facet sees it.
            let seen = hull
                .facets()
                .map(|(g, _)| g)
                .find(|&g| hull.side_of(g, &s) == Sign::Positive);
            if let Some(g) = seen {
                if hull.insert_beyond(g, s).is_some() {
                    self.enqueue_created(hull);
                    return Step::Continue;
                }
                self.fail(hull, SourceError::TooManyPoints { facet: g, point: s });
                return Step::Stop;
            }
        }
        match best {
            Some((height, g, p)) => {
                let height = height - level;
                hull.trace_choice(g, NearestReason::<D>::BeyondSupport { point: p, height });
                self.expand(hull, g, Some(p));
                Step::Continue
            }
            None => {
                let (distance, id, x) = self.outside_answer(hull, closest);
                self.answer = Some((-distance, id, x));
                self.phase = Phase::Done;
                hull.trace_stop(Some(id), NearestReason::<D>::OutsideCertified { distance });
                Step::Stop
            }
        }
    }

    /// The point of the partial hull nearest the (outside) query point, and a facet holding it.
    ///
    /// The nearest point lies on a facet the query sees, so it is the nearest point of the convex
    /// hull of those facets' vertices: Wolfe's algorithm on a few dozen points, then again from
    /// its answer with an accurate residual. "Sees" is the exact test: the floating-point
    /// distances of a partial hull's thin facets (whose normals are refined only when they are
    /// popped) can be wrong by far more than the distance of a query near the boundary, both
    /// ways, and a facet taken for seen that is not, or missed, changes the answer.
    fn nearest_point(&mut self, hull: &Hull<D>) -> Closest<D> {
        self.seen.clear();
        self.seen_vertices.clear();
        let mut farthest_plane: Option<(f64, FacetId)> = None;
        let mut farthest_seen: Option<(f64, FacetId)> = None;
        for (id, facet) in hull.facets() {
            let beyond = facet.signed_distance(&self.query);
            if farthest_plane.is_none_or(|(b, _)| beyond > b) {
                farthest_plane = Some((beyond, id));
            }
            if hull.side_of(id, &self.query) == Sign::Positive {
                if farthest_seen.is_none_or(|(b, _)| beyond > b) {
                    farthest_seen = Some((beyond, id));
                }
                self.seen.push(id);
                self.seen_vertices.extend(facet.vertices());
            }
        }
        let fallback = match farthest_seen {
            Some((_, id)) => id,
            None => {
                // Only for a query `side_of` cannot scale exactly (it then decides in floating
                // point, as here).
                let (_, id) = farthest_plane.expect("a hull has facets");
                self.seen.push(id);
                self.seen_vertices.extend(hull.facet(id).vertices());
                id
            }
        };
        self.seen_vertices.sort_unstable();
        self.seen_vertices.dedup();
        let vertices = &self.seen_vertices;
        let point = |i: usize| hull.point(vertices[i]);
        let holder = |support: &[usize]| {
            let support = support.iter().map(|&i| vertices[i]);
            self.seen.iter().copied().find(|&id| {
                let facet_vertices = hull.facet(id).vertices();
                support.clone().all(|v| facet_vertices.contains(&v))
            })
        };
        let bound = FAR_QUERY * hull.coordinate_bound();
        if self.query.iter().any(|c| c.abs() > bound) {
            let nearest = min_norm_point_exact(vertices.len(), point, &self.query, &[]);
            return Closest {
                point: nearest.point,
                offset: nearest.offset,
                facet: holder(nearest.support()).unwrap_or(fallback),
                distance: nearest.distance,
                far: true,
            };
        }
        let rough = min_norm_point(vertices.len(), point, &self.query);
        let nearest = min_norm_point_accurate(vertices.len(), point, &self.query, rough.support());
        // Wolfe's optimality test, redone here: no vertex may lie beyond the plane through the
        // answer normal to q − x, by more than the rounding of the test itself (q − x is accurate
        // to a few ulps, so the test is limited by the D-term dot products with v − q). Nearly
        // coincident points can make Wolfe's linear algebra fail; then try every face of every
        // facet the query sees instead.
        // q − x, and u = (q − x)/2^e with its largest coordinate in [0.5, 1): products with u
        // do not overflow for a far query (|q − x|² would from 1e155).
        let direction = nearest.offset.map(|c| -c);
        let unit = rescaled(&direction);
        let squared = dot(unit, direction);
        let mut reach = 0.0f64;
        let mut worst = f64::NEG_INFINITY;
        for &v in vertices {
            let p = hull.point(v);
            let from_query: [f64; D] = std::array::from_fn(|c| p[c] - self.query[c]);
            reach = reach.max(norm(from_query));
            // (q − x)·(v − x) = (q − x)·(v − q) + |q − x|², here divided by 2^e
            worst = worst.max(dot(unit, from_query) + squared);
        }
        let slack = 2.0 * (D as f64 + 4.0) * f64::EPSILON * dot(unit, unit).sqrt() * reach;
        let optimal = worst <= slack;
        if optimal {
            return Closest {
                point: nearest.point,
                offset: nearest.offset,
                facet: holder(nearest.support()).unwrap_or(fallback),
                distance: nearest.distance,
                far: false,
            };
        }
        // Wolfe's floating-point run failed its own test (nearly coincident points, or
        // coordinates of very different magnitudes — torques 1e8 times the forces — that its
        // linear algebra cannot resolve): the nearest point exactly, rounded once. Projecting on
        // faces in floating point instead (as before) dropped the faces whose pivots looked
        // negligible and answered 0.3 for a distance of 7e−17.
        let exact = min_norm_point_exact(vertices.len(), point, &self.query, nearest.support());
        Closest {
            point: exact.point,
            offset: exact.offset,
            facet: holder(exact.support()).unwrap_or(fallback),
            distance: exact.distance,
            far: false,
        }
    }

    /// The certified outside answer — distance, facet, nearest point — from the nearest point of
    /// the partial hull.
    ///
    /// Near the boundary (within about 1e−10 of the input's size), the exact distance to each
    /// seen facet's plane is a lower bound on it (the partial hull lies behind that plane), and
    /// the largest is taken when it is larger: it guards the last ulps of Wolfe's answer, and
    /// makes the magnitude strictly positive whatever the rounding, as the exact sign requires.
    fn outside_answer(&self, hull: &mut Hull<D>, closest: Closest<D>) -> (f64, FacetId, [f64; D]) {
        let mut answer = (closest.distance, closest.facet, closest.point);
        if closest.distance > NEAR_BOUNDARY * hull.coordinate_bound() {
            return answer;
        }
        let mut plane: Option<FacetId> = None;
        for &g in &self.seen {
            // Seen facets have the query strictly beyond: a positive exact distance.
            let distance = hull
                .exact_signed_distance(g, &self.query)
                .unwrap_or_else(|| hull.signed_distance(g, &self.query));
            if distance > answer.0 {
                answer.0 = distance;
                plane = Some(g);
            }
        }
        if let Some(g) = plane {
            hull.refine_normal(g);
            let normal = hull.facet(g).normal();
            answer.1 = g;
            answer.2 = std::array::from_fn(|c| self.query[c] - answer.0 * normal[c]);
        }
        if answer.0 <= 0.0 {
            // Nearer than the smallest subnormal: round up, keep the sign.
            answer.0 = f64::from_bits(1);
        }
        answer
    }
}

/// The point of the partial hull nearest an outside query, as [`ClosestToOrigin`]'s outside
/// phase finds it.
#[derive(Clone, Copy, Debug)]
struct Closest<const D: usize> {
    point: [f64; D],
    /// `point − query`, accurate even when tiny (the certificate's direction is its opposite).
    offset: [f64; D],
    /// A seen facet holding `point` (or the farthest seen one if none is found).
    facet: FacetId,
    distance: f64,
    /// The query is far from the hull ([`FAR_QUERY`]): `point` is exact (rounded once) and
    /// `offset` only relatively accurate, so heights are measured from `point`.
    far: bool,
}

/// A query with a coordinate beyond this many times the hull's coordinate bound is *far*: its
/// nearest point is computed exactly ([`min_norm_point_exact`]). Floating point would place it
/// only to an ulp of the query's coordinates (q + (x − q)) and, from about 2^10 times the hull's
/// extent, decide between the faces in rounding (with the square [−1, 1]² and q = (0, 10^170),
/// every vertex ties and the answer was (1, 0)).
const FAR_QUERY: f64 = 2.0;

/// Within this fraction of the input's coordinate bound of the boundary, the floating-point
/// distance to a plane (the rounding of its offset, about D ulps of the input's size, and of a
/// normal certified to 1e−11) no longer has the relative accuracy the result promises: distances
/// are then taken from the exact determinants. 2^-33 ≈ 1.2e−10.
const NEAR_BOUNDARY: f64 = 1.0 / (1u64 << 33) as f64;

impl<const D: usize, S: Implicit<D>> ClosestToOrigin<D, S> {
    fn start_run(&mut self, hull: &Hull<D>) {
        self.queue.clear();
        self.phase = Phase::Nearest;
        self.nearest_first = false;
        self.answer = None;
        self.error = None;
        for (id, _) in hull.facets() {
            self.enqueue(hull, id);
        }
    }

    fn step_run(&mut self, hull: &mut Hull<D>) -> Step {
        match self.phase {
            Phase::Nearest => self.step_nearest(hull),
            Phase::Outside => self.step_outside(hull),
            Phase::Done => Step::Stop,
        }
    }

    fn context(&self) -> TraceContext<D> {
        TraceContext {
            strategy: "ClosestToOrigin".to_string(),
            query: Some(self.query),
            disturbances: Vec::new(),
        }
    }

    /// The answer of the run that just stopped, or the contract its source broke.
    fn result(&self, hull: &Hull<D>) -> Result<DistanceResult<D>, SourceError<D>> {
        if let Some(error) = &self.error {
            return Err(error.clone());
        }
        let (signed_distance, closest_facet, nearest_point) =
            self.answer.expect("the strategy stops only with an answer");
        Ok(DistanceResult {
            signed_distance,
            closest_facet,
            closest_facet_vertices: hull.facet(closest_facet).vertices(),
            nearest_point,
            stats: hull.stats(),
        })
    }
}

impl<const D: usize> ClosestToOrigin<D> {
    /// The answer of a run without a source, which cannot fail.
    fn plain_result(&self, hull: &Hull<D>) -> DistanceResult<D> {
        match self.result(hull) {
            Ok(result) => result,
            Err(error) => unreachable!("NoSource returns no point: {error}"),
        }
    }
}

/// Without a point source: the run cannot fail.
impl<const D: usize> Strategy<D> for ClosestToOrigin<D> {
    type Output = DistanceResult<D>;

    fn start(&mut self, hull: &Hull<D>) {
        self.start_run(hull);
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        self.step_run(hull)
    }

    fn partitions_to_farthest(&self) -> bool {
        true
    }

    fn refines_all_normals(&self) -> bool {
        false // only the deciding facet's normal is reported, and it is refined before use
    }

    fn trace_context(&self) -> TraceContext<D> {
        self.context()
    }

    fn finish(self, hull: &Hull<D>) -> Self::Output {
        self.plain_result(hull)
    }
}

/// With a point source: [`SourceError`] when the source breaks [`PointSource`]'s contract.
impl<const D: usize, S: PointSource<D>> Strategy<D> for ClosestToOrigin<D, S> {
    type Output = Result<DistanceResult<D>, SourceError<D>>;

    fn start(&mut self, hull: &Hull<D>) {
        self.start_run(hull);
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        self.step_run(hull)
    }

    fn partitions_to_farthest(&self) -> bool {
        true
    }

    fn refines_all_normals(&self) -> bool {
        false // only the deciding facet's normal is reported, and it is refined before use
    }

    fn trace_context(&self) -> TraceContext<D> {
        self.context()
    }

    fn finish(self, hull: &Hull<D>) -> Self::Output {
        self.result(hull)
    }
}

/// A borrowed `ClosestToOrigin` runs the same way and keeps its buffers (the facet queue, the
/// outside-phase scratch) for the next run (see [`ReusableStrategy`]'s example).
impl<const D: usize> ReusableStrategy<D> for ClosestToOrigin<D> {
    fn output(&self, hull: &Hull<D>) -> DistanceResult<D> {
        self.plain_result(hull)
    }
}

/// As without a source.
impl<const D: usize, S: PointSource<D>> ReusableStrategy<D> for ClosestToOrigin<D, S> {
    fn output(&self, hull: &Hull<D>) -> Self::Output {
        self.result(hull)
    }
}

/// A queued facet, keyed by how far the query lies beyond its plane (largest first).
type Entry = Queued<()>;
