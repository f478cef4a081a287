//! `ClosestToOrigin`: the PQHGWS algorithm (Liu & Carpin, Algorithm 1), made exact.

use super::nearest::nearest_in_simplex;
use super::{Stats, Step, Strategy};
use crate::hull::{FacetId, Hull, dot};
use crate::predicates::Sign;
use std::cmp::Ordering;
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
pub struct ClosestToOrigin<const D: usize> {
    query: [f64; D],
    queue: BinaryHeap<Entry>,
    phase: Phase,
    answer: Option<(f64, FacetId, [f64; D])>,
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
        Self {
            query,
            queue: BinaryHeap::new(),
            phase: Phase::Nearest,
            answer: None,
        }
    }

    fn enqueue(&mut self, hull: &Hull<D>, id: FacetId) {
        let facet = hull.facet(id);
        self.queue.push(Entry {
            beyond: facet.signed_distance(&self.query),
            id,
            serial: facet.serial(),
        });
    }

    fn expand(&mut self, hull: &mut Hull<D>, id: FacetId, point: Option<usize>) {
        let expanded = match point {
            Some(p) => hull.expand_with(id, p),
            None => hull.expand(id),
        };
        debug_assert!(expanded, "only facets with outside points are expanded");
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
            if hull.facet(id).outside_len() > 0 || hull.claim_beyond(id) {
                self.expand(hull, id, None);
                return Step::Continue;
            }
            // Nothing lies beyond `id`: its plane supports the full hull.
            let query_side = hull.side_of(id, &self.query);
            if query_side == Sign::Positive {
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
                if hull.facet(g).outside_len() > 0 || hull.claim_beyond(g) {
                    self.expand(hull, g, None);
                } else {
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
            return Step::Stop;
        }
        unreachable!("a hull always has live facets, each queued when created")
    }

    /// One step of the outside phase: nearest point of the partial hull, then its certificate.
    fn step_outside(&mut self, hull: &mut Hull<D>) -> Step {
        let (x, id, distance) = self.nearest_point(hull);
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
        match best {
            Some((_, g, p)) => {
                self.expand(hull, g, Some(p));
                Step::Continue
            }
            None => {
                self.answer = Some((-distance, id, x));
                self.phase = Phase::Done;
                Step::Stop
            }
        }
    }

    /// The point of the partial hull nearest the (outside) query point.
    fn nearest_point(&self, hull: &Hull<D>) -> ([f64; D], FacetId, f64) {
        let mut candidates: Vec<(f64, FacetId)> = hull
            .facets()
            .map(|(id, f)| (f.signed_distance(&self.query), id))
            .filter(|&(beyond, _)| beyond > 0.0)
            .collect();
        if candidates.is_empty() {
            // Rounding hid every facet the query sees: it is within rounding of the boundary.
            let (beyond, id) = hull
                .facets()
                .map(|(id, f)| (f.signed_distance(&self.query), id))
                .max_by(|a, b| a.0.total_cmp(&b.0))
                .expect("a hull has facets");
            candidates.push((beyond, id));
        }
        // Distance to a facet's plane bounds the distance to the facet from below.
        candidates.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let mut best: Option<([f64; D], FacetId, f64)> = None;
        for (plane_distance, id) in candidates {
            if best.is_some_and(|(_, _, d)| plane_distance >= d) {
                break;
            }
            let vertices = hull.facet(id).vertices().map(|v| hull.point(v));
            let (x, d) = nearest_in_simplex(&vertices, &self.query);
            if best.is_none_or(|(_, _, b)| d < b) {
                best = Some((x, id, d));
            }
        }
        best.expect("at least one candidate facet")
    }
}

impl<const D: usize> Strategy<D> for ClosestToOrigin<D> {
    type Output = DistanceResult<D>;

    fn start(&mut self, hull: &Hull<D>) {
        self.queue.clear();
        self.phase = Phase::Nearest;
        self.answer = None;
        let ids: Vec<FacetId> = hull.facets().map(|(id, _)| id).collect();
        for id in ids {
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

    fn finish(self, hull: &Hull<D>) -> Self::Output {
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

/// A queued facet, ordered by how far the query lies beyond its plane (largest first).
#[derive(Clone, Copy, Debug)]
struct Entry {
    beyond: f64,
    id: FacetId,
    serial: u64,
}

impl PartialEq for Entry {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        self.beyond
            .total_cmp(&other.beyond)
            .then(other.serial.cmp(&self.serial))
    }
}
