//! `ClosestToOrigin`: the PQHGWS algorithm (Liu & Carpin, Algorithm 1), made exact.

use super::nearest::{min_norm_point, nearest_in_simplex};
use super::{Queued, ReusableStrategy, Stats, Step, Strategy};
use crate::hull::{FacetId, Hull, dot};
use crate::predicates::Sign;
use crate::viz::TraceContext;
use std::collections::BinaryHeap;

/// Grows the hull toward a query point (default: the origin) and stops as soon as the facet nearest
/// that point is certain, returning the signed distance from the point to the boundary of the
/// *full* hull — positive inside, negative outside — without building the full hull.
///
/// # How it decides
///
/// Facets wait in a priority queue keyed by how far the query point lies beyond their plane. The
/// strategy pops the top facet; if any point lies strictly beyond it (its outside set, after
/// [`Hull::claim_beyond`]), the facet is expanded and its replacements queued. Otherwise the facet's
/// plane supports *every* input point, and:
///
/// * **query inside** (checked exactly against every live facet): the partial hull `P` is inside the
///   full hull `H`, so dist(q, ∂H) ≥ dist(q, ∂P) = distance to this facet's plane, and this plane is
///   a supporting plane of `H`, so the two are equal. The answer is exact up to the rounding of one
///   dot product.
/// * **query outside**: the distance to a facet's plane (the seed paper's Definition 8) is only a
///   lower bound on the distance to the hull — equal only when the foot of the perpendicular lands
///   inside the facet. Instead the strategy takes the point `x` of `P` nearest `q` (exhaustively over
///   the faces of the facets `q` can see) and checks the supporting hyperplane through `x` normal
///   to `q − x`: if no remaining point lies beyond it, `x` is the nearest point of `H` too (every
///   point of `H` is a convex combination of points behind that plane). Otherwise the point farthest
///   beyond it is added — a GJK-like step — and the search repeats.
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
#[derive(Clone, Debug)]
pub struct ClosestToOrigin<const D: usize, S: PointSource<D> = NoSource> {
    query: [f64; D],
    source: S,
    queue: BinaryHeap<Entry>,
    phase: Phase,
    answer: Option<(f64, FacetId, [f64; D])>,
    /// Scratch for the outside phase: facets the query sees, and their vertices.
    seen: Vec<FacetId>,
    seen_vertices: Vec<usize>,
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
    /// inside, negative outside, zero on the boundary. The sign is decided exactly (a point
    /// strictly inside but within rounding of a facet gets `f64::MIN_POSITIVE`); the magnitude is
    /// floating point. Outside, the nearest-point certificate is floating point too (see the type's
    /// docs).
    pub signed_distance: f64,
    /// The deciding facet: its plane is nearest the query point (inside) or it holds the nearest
    /// point (outside). A facet of the partial hull, and (up to the triangulation of coplanar
    /// facets) of the full hull.
    pub closest_facet: FacetId,
    /// The deciding facet's vertices (input indices).
    pub closest_facet_vertices: [usize; D],
    /// The point of the hull boundary nearest the query point.
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

/// Points that are not in the hull's input but belong to the set whose hull is sought — an
/// implicit set, such as the Q∞ Minkowski sum, answered through its support function.
///
/// [`ClosestToOrigin::with_source`] asks it before declaring a facet certain, so "nothing
/// beyond" covers the implicit points too. The hull's input must contain the set's extreme points
/// along every coordinate axis (see [`Hull::insert_beyond`]).
///
/// ```
/// use pqhull::strategy::PointSource;
/// use pqhull::{ClosestToOrigin, FacetId, Hull};
///
/// /// The square [−1, 1]² given by its corners, of which the input holds only three.
/// struct Corners;
/// impl PointSource<2> for Corners {
///     fn beyond(&mut self, hull: &Hull<2>, id: FacetId) -> Option<[f64; 2]> {
///         let n = hull.facet(id).normal();
///         let corner = [n[0].signum(), n[1].signum()];
///         (hull.facet(id).signed_distance(&corner) > 1e-12).then_some(corner)
///     }
///     fn support(&mut self, d: &[f64; 2]) -> Option<[f64; 2]> {
///         Some([d[0].signum(), d[1].signum()])
///     }
/// }
/// let input = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]];
/// let strategy = ClosestToOrigin::with_source([0.5, 0.0], Corners);
/// let (_, result) = Hull::try_with_strategy(&input, strategy)?;
/// // The triangle alone would give 0.25/√2 ≈ 0.18; the square gives 0.5.
/// assert!((result.signed_distance - 0.5).abs() < 1e-12);
/// # Ok::<(), pqhull::HullError>(())
/// ```
pub trait PointSource<const D: usize> {
    /// A point of the implicit set strictly beyond facet `id` of `hull` (by the exact
    /// [`Hull::side_of`]), or `None` only when there is none.
    fn beyond(&mut self, hull: &Hull<D>, id: FacetId) -> Option<[f64; D]>;
    /// A point of the implicit set maximising `direction · p` (floating point is enough: the
    /// strategy checks it), or `None` for an empty set.
    fn support(&mut self, direction: &[f64; D]) -> Option<[f64; D]>;
}

/// No implicit points: the hull's input is the whole set.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoSource;

impl<const D: usize> PointSource<D> for NoSource {
    fn beyond(&mut self, _: &Hull<D>, _: FacetId) -> Option<[f64; D]> {
        None
    }
    fn support(&mut self, _: &[f64; D]) -> Option<[f64; D]> {
        None
    }
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
        Self::with_source(query, NoSource)
    }
}

impl<const D: usize, S: PointSource<D>> ClosestToOrigin<D, S> {
    /// Toward `query`, over the hull's input *and* the implicit points of `source`.
    pub fn with_source(query: [f64; D], source: S) -> Self {
        Self {
            query,
            source,
            queue: BinaryHeap::new(),
            phase: Phase::Nearest,
            answer: None,
            seen: Vec::new(),
            seen_vertices: Vec::new(),
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
        let expanded = match point {
            Some(p) => hull.expand_with(id, p),
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
            hull.trace_choice(
                id,
                Some(("distance of the query beyond the plane", entry.key)),
                || {
                    if entry.key > 0.0 {
                        "the query lies farthest beyond this facet's plane"
                    } else {
                        "nearest plane to the query (the query is beneath every queued plane)"
                    }
                    .to_string()
                },
            );
            if hull.facet(id).outside_len() > 0 || hull.claim_beyond(id) {
                self.expand(hull, id, None);
                return Step::Continue;
            }
            if let Some(point) = self.source.beyond(hull, id) {
                let inserted = hull.insert_beyond(id, point);
                assert!(
                    inserted.is_some(),
                    "PointSource::beyond returned a point not strictly beyond the facet, or out of \
                     the hull's coordinate range"
                );
                self.enqueue_created(hull);
                return Step::Continue;
            }
            // Nothing lies beyond `id`: its plane supports the full hull.
            let query_side = hull.side_of(id, &self.query);
            if query_side == Sign::Positive {
                hull.trace_note(
                    None,
                    "nothing lies beyond this facet and the query is strictly beyond it: the \
                     query is outside the full hull; searching for the nearest point",
                );
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
                    let key = hull.signed_distance(g, &self.query);
                    hull.trace_choice(
                        g,
                        Some(("distance of the query beyond the plane", key)),
                        "the query is strictly beyond this facet (exact test): it is not yet \
                         inside the partial hull",
                    );
                }
                if hull.facet(g).outside_len() > 0 || hull.claim_beyond(g) {
                    self.expand(hull, g, None);
                } else {
                    hull.trace_note(
                        None,
                        "nothing lies beyond that facet: the query is outside the full hull; \
                         searching for the nearest point",
                    );
                    self.phase = Phase::Outside;
                }
                return Step::Continue;
            }
            let facet = hull.facet(id);
            let distance = if query_side == Sign::Zero {
                0.0
            } else {
                // Strictly inside by the exact test; keep the sign even when the query is closer
                // to the plane than the rounding of the floating-point distance can resolve.
                (-facet.signed_distance(&self.query)).max(f64::MIN_POSITIVE)
            };
            let normal = facet.normal();
            let foot = std::array::from_fn(|c| self.query[c] + distance * normal[c]);
            self.answer = Some((distance, id, foot));
            self.phase = Phase::Done;
            hull.trace_stop(Some(id), || {
                let side = if query_side == Sign::Zero {
                    "query on the boundary"
                } else {
                    "query inside"
                };
                format!(
                    "nothing lies beyond the nearest facet and the query is inside every facet: \
                     distance {distance} certified ({side})"
                )
            });
            return Step::Stop;
        }
        unreachable!("a hull always has live facets, each queued when created")
    }

    /// One step of the outside phase: nearest point of the partial hull, then its certificate.
    fn step_outside(&mut self, hull: &mut Hull<D>) -> Step {
        let (x, id, distance) = self.nearest_point(hull);
        hull.trace_note(
            Some(x),
            "nearest point of the partial hull to the query: does anything lie beyond the \
             supporting plane through it?",
        );
        let direction: [f64; D] = std::array::from_fn(|c| self.query[c] - x[c]);
        let level = dot(&direction, &x);
        let mut best: Option<(f64, FacetId, usize)> = None;
        for (g, facet) in hull.facets() {
            for p in facet.outside_set() {
                let height = dot(&direction, &hull.point(p));
                if height > level && best.is_none_or(|(h, _, _)| height > h) {
                    best = Some((height, g, p));
                }
            }
        }
        if best.is_none()
            && let Some(s) = self.source.support(&direction)
            && dot(&direction, &s) > level
        {
            // An implicit point beyond the certificate plane: it is outside the partial hull, so
            // some facet sees it.
            let seen = hull
                .facets()
                .map(|(g, _)| g)
                .find(|&g| hull.side_of(g, &s) == Sign::Positive);
            if let Some(g) = seen
                && hull.insert_beyond(g, s).is_some()
            {
                self.enqueue_created(hull);
                return Step::Continue;
            }
        }
        match best {
            Some((height, g, p)) => {
                let key = (
                    "height of the point beyond the supporting plane",
                    height - level,
                );
                hull.trace_choice(g, Some(key), || {
                    format!(
                        "holds point {p}, the farthest beyond the supporting plane through the \
                         nearest point: it is added"
                    )
                });
                self.expand(hull, g, Some(p));
                Step::Continue
            }
            None => {
                self.answer = Some((-distance, id, x));
                self.phase = Phase::Done;
                hull.trace_stop(Some(id), || {
                    format!(
                        "nothing lies beyond the supporting plane through the nearest point: \
                         distance {distance} certified (query outside)"
                    )
                });
                Step::Stop
            }
        }
    }

    /// The point of the partial hull nearest the (outside) query point, and a facet holding it.
    ///
    /// The nearest point lies on a facet the query sees, so it is the nearest point of the convex
    /// hull of those facets' vertices: Wolfe's algorithm on a few dozen points.
    fn nearest_point(&mut self, hull: &Hull<D>) -> ([f64; D], FacetId, f64) {
        self.seen.clear();
        self.seen_vertices.clear();
        let mut farthest_plane: Option<(f64, FacetId)> = None;
        for (id, facet) in hull.facets() {
            let beyond = facet.signed_distance(&self.query);
            if farthest_plane.is_none_or(|(b, _)| beyond > b) {
                farthest_plane = Some((beyond, id));
            }
            if beyond > 0.0 {
                self.seen.push(id);
                self.seen_vertices.extend(facet.vertices());
            }
        }
        let (_, fallback) = farthest_plane.expect("a hull has facets");
        if self.seen.is_empty() {
            // Rounding hid every facet the query sees: it is within rounding of the boundary.
            self.seen.push(fallback);
            self.seen_vertices.extend(hull.facet(fallback).vertices());
        }
        self.seen_vertices.sort_unstable();
        self.seen_vertices.dedup();
        let vertices = &self.seen_vertices;
        let nearest = min_norm_point(vertices.len(), |i| hull.point(vertices[i]), &self.query);
        // Wolfe's optimality test, redone here with a tolerance: no vertex may lie beyond the
        // plane through the answer normal to q − x. Nearly coincident points can make its linear
        // algebra fail; then try every face of every facet the query sees instead.
        let x = nearest.point;
        let direction: [f64; D] = std::array::from_fn(|c| self.query[c] - x[c]);
        let level = dot(&direction, &x);
        let extent = vertices
            .iter()
            .map(|&v| dot(&hull.point(v), &hull.point(v)).sqrt())
            .fold(0.0, f64::max);
        let slack = 1e-12 * extent * dot(&direction, &direction).sqrt();
        let optimal = vertices
            .iter()
            .all(|&v| dot(&direction, &hull.point(v)) <= level + slack);
        if optimal {
            let support = nearest.support().iter().map(|&i| vertices[i]);
            let holder = self.seen.iter().copied().find(|&id| {
                let facet_vertices = hull.facet(id).vertices();
                support.clone().all(|v| facet_vertices.contains(&v))
            });
            return (x, holder.unwrap_or(fallback), nearest.distance);
        }
        let mut best: Option<([f64; D], FacetId, f64)> = None;
        for &id in &self.seen {
            let simplex = hull.facet(id).vertices().map(|v| hull.point(v));
            let (x, d) = nearest_in_simplex(&simplex, &self.query);
            if best.is_none_or(|(_, _, b)| d < b) {
                best = Some((x, id, d));
            }
        }
        best.expect("at least one facet is seen")
    }
}

impl<const D: usize, S: PointSource<D>> Strategy<D> for ClosestToOrigin<D, S> {
    type Output = DistanceResult<D>;

    fn start(&mut self, hull: &Hull<D>) {
        self.queue.clear();
        self.phase = Phase::Nearest;
        self.answer = None;
        for (id, _) in hull.facets() {
            self.enqueue(hull, id);
        }
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        match self.phase {
            Phase::Nearest => self.step_nearest(hull),
            Phase::Outside => self.step_outside(hull),
            Phase::Done => Step::Stop,
        }
    }

    fn refines_all_normals(&self) -> bool {
        false // only the deciding facet's normal is reported, and it is refined before use
    }

    fn trace_context(&self) -> TraceContext<D> {
        TraceContext {
            strategy: "ClosestToOrigin".to_string(),
            query: Some(self.query),
            disturbances: Vec::new(),
        }
    }

    fn finish(self, hull: &Hull<D>) -> Self::Output {
        self.result(hull)
    }
}

/// A borrowed `ClosestToOrigin` runs the same way and keeps its buffers (the facet queue, the
/// outside-phase scratch) for the next run (see [`ReusableStrategy`]'s example).
impl<const D: usize, S: PointSource<D>> ReusableStrategy<D> for ClosestToOrigin<D, S> {
    fn output(&self, hull: &Hull<D>) -> DistanceResult<D> {
        self.result(hull)
    }
}

impl<const D: usize, S: PointSource<D>> ClosestToOrigin<D, S> {
    /// The answer of the run that just stopped.
    fn result(&self, hull: &Hull<D>) -> DistanceResult<D> {
        let (signed_distance, closest_facet, nearest_point) =
            self.answer.expect("the strategy stops only with an answer");
        DistanceResult {
            signed_distance,
            closest_facet,
            closest_facet_vertices: hull.facet(closest_facet).vertices(),
            nearest_point,
            stats: hull.stats(),
        }
    }
}

/// A queued facet, keyed by how far the query lies beyond its plane (largest first).
type Entry = Queued<()>;
