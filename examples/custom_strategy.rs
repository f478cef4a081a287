//! A strategy written outside the crate, from the public API alone: the support value
//! `h(u) = max_p u·p` of a point set in a direction `u`, from a partial hull.
//!
//! The hull grows toward `u`: each facet is keyed by the highest `u·p` among the points of its
//! outside set, and the facet with the highest key is expanded with that point. It stops when
//! the best hull vertex is at least every key. That is a proof, not a heuristic: every input
//! point is a hull vertex, or inside the hull (so below its best vertex, `u·x` being linear), or
//! in exactly one outside set (so at most that set's key). The answer is the same floating-point
//! maximum a scan of every point computes (`tests/integration/custom_strategy.rs` checks it against one),
//! after adding a handful of points to the hull instead of all of them.
//!
//! Run it: `cargo run --release --example custom_strategy`.

use pqhull::geometry::vector::dot;
// The hooks a strategy drives the engine with (expand, last_created, the trace, ...).
use pqhull::hull::{StrategyHooks, TraceReason};
use pqhull::strategy::Queued;
use pqhull::{Hull, HullError, Stats, Step, Strategy};
use std::collections::BinaryHeap;

/// The support value in direction `u`: grows the hull toward `u` until its best vertex is certain.
pub struct SupportValue<const D: usize> {
    u: [f64; D],
    /// Facets keyed by the highest `u·p` of their outside set; `data` is that point.
    queue: BinaryHeap<Queued<usize>>,
    /// The best hull vertex so far: `(u·p, p)`.
    best: (f64, usize),
}

/// Why [`SupportValue`] expands a facet, as a trace records it: its outside set holds the
/// highest point along `u` (of height `u·p`).
struct Highest {
    height: f64,
}

impl TraceReason for Highest {
    fn code(&self) -> &'static str {
        "highest"
    }

    fn describe(&self) -> String {
        "highest outside point along u".to_string()
    }

    fn key(&self) -> Option<(&'static str, f64)> {
        Some(("u·p", self.height))
    }
}

/// What [`SupportValue`] found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Support {
    /// `max_p u·p` over every input point.
    pub value: f64,
    /// An input point attaining it.
    pub point: usize,
    /// The engine's work counters.
    pub stats: Stats,
}

impl<const D: usize> SupportValue<D> {
    /// Toward `u`.
    pub fn new(u: [f64; D]) -> Self {
        Self {
            u,
            queue: BinaryHeap::new(),
            best: (f64::NEG_INFINITY, 0),
        }
    }

    /// Queues facet `id` keyed by its outside set's highest point along `u` (nothing if empty).
    fn queue(&mut self, hull: &Hull<D>, id: pqhull::FacetId) {
        let facet = hull.facet(id);
        let top = facet
            .outside_set()
            .map(|p| (dot(self.u, hull.point(p)), p))
            .max_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((key, point)) = top {
            let serial = facet.serial();
            self.queue.push(Queued {
                key,
                id,
                serial,
                data: point,
            });
        }
    }

    /// Counts point `p` as a hull vertex.
    fn saw_vertex(&mut self, hull: &Hull<D>, p: usize) {
        let value = dot(self.u, hull.point(p));
        if value > self.best.0 {
            self.best = (value, p);
        }
    }
}

impl<const D: usize> Strategy<D> for SupportValue<D> {
    type Output = Support;

    fn start(&mut self, hull: &Hull<D>) {
        self.queue.clear();
        self.best = (f64::NEG_INFINITY, 0);
        let ids: Vec<_> = hull.facets().map(|(id, _)| id).collect();
        for id in ids {
            for v in hull.facet(id).vertices() {
                self.saw_vertex(hull, v);
            }
            self.queue(hull, id);
        }
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        while let Some(top) = self.queue.pop() {
            if !hull.is_current(top.id, top.serial) {
                continue; // removed by an expansion since it was queued
            }
            if top.key <= self.best.0 {
                // The highest outside point is no higher than the best vertex: certain.
                self.queue.push(top);
                return Step::Stop;
            }
            hull.trace_choice(top.id, Highest { height: top.key });
            if hull.expand_with(top.id, top.data) {
                self.saw_vertex(hull, top.data);
                let created = hull.last_created().to_vec();
                for id in created {
                    self.queue(hull, id);
                }
            }
            return Step::Continue;
        }
        Step::Stop // no outside point left: the hull is complete
    }

    fn finish(self, hull: &Hull<D>) -> Support {
        Support {
            value: self.best.0,
            point: self.best.1,
            stats: hull.stats(),
        }
    }

    /// Only vertices are read, never normals: skip the engine's final normal refinement.
    fn refines_all_normals(&self) -> bool {
        false
    }
}

/// `h(u)` of `points`, by the partial hull.
///
/// # Errors
/// As [`Hull::try_new`] (too few points, non-finite coordinates, flat input).
pub fn support_value<const D: usize>(
    points: &[[f64; D]],
    u: [f64; D],
) -> Result<Support, HullError> {
    Hull::try_with_strategy(points, SupportValue::new(u)).map(|(_, support)| support)
}

#[allow(dead_code)] // a test includes this file as a module and calls the rest
fn main() -> Result<(), HullError> {
    let points = pqhull::rbox::generate::<4>(&pqhull::rbox::Family::SphereSurface, 20_000, 1);
    let u = [0.3, -0.2, 0.9, 0.1];
    let partial = support_value(&points, u)?;
    let full = Hull::try_new(&points)?.stats();
    let scan = points
        .iter()
        .map(|&p| dot(u, p))
        .fold(f64::NEG_INFINITY, f64::max);
    println!(
        "h(u) = {} at point #{} (a scan of every point: {scan})",
        partial.value, partial.point
    );
    println!(
        "points added to the hull: {} of {} (the full hull adds {}); facets created: {} (full: {})",
        partial.stats.points_processed,
        points.len(),
        full.points_processed,
        partial.stats.facets_created,
        full.facets_created
    );
    assert_eq!(partial.value, scan);
    Ok(())
}
