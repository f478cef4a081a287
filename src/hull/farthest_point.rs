//! `FarthestPoint`: plain QuickHull, run to completion.

use super::{FacetId, Hull, Step, Strategy, TraceContext, TraceReason};
use std::cmp::Reverse;
use std::collections::{BinaryHeap, VecDeque};

/// Plain QuickHull to completion: every facet with a non-empty outside set is expanded with its
/// farthest point until no outside set remains. The result is the full hull, and the baseline every
/// partial strategy is measured against.
///
/// A build from the initial simplex runs in up to two phases: the first keeps facets whose
/// plane holds the new point (cheap on boxes, grids and lattices, whose faces hold many points),
/// and only if that left a vertex that is not an extreme point, decided exactly, a second builds
/// again on the extreme vertices. Either way the vertices are the input's extreme points
/// (docs/ARCHITECTURE.md, "A full build in two phases").
///
/// ```
/// use pqhull::{FarthestPoint, Hull};
/// let points = [[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [1.0, 1.0]];
/// let (hull, ()) = Hull::try_with_strategy(&points, FarthestPoint::new())?;
/// assert_eq!(hull.vertex_indices(), vec![0, 1, 2]);
/// assert!((hull.volume() - 6.0).abs() < 1e-12);
/// # Ok::<(), pqhull::HullError>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct FarthestPoint {
    /// Facets with outside points, in 3-D and up: the one whose farthest point is farthest
    /// expanded first (ties: the oldest). Against the oldest first (breadth first, as Qhull's
    /// facet list, itself 5–30 % fewer facets than depth first), this cut the instructions of
    /// `pqh bench hull`'s 3-D to 6-D rows by up to two thirds (the 6-D lattice), most by 7–24 %,
    /// a few (the 3-D tilted faces and corners, the 6-D simplex) by under 1 %
    /// (docs/benchmarks.md, "the farthest pending facet first"): the far points, expanded
    /// first, put the near ones inside before they are moved again.
    pending: BinaryHeap<Pending>,
    /// Facets with outside points, in 2-D: the oldest first (breadth first). There the order
    /// changed no row's work by more than 0.2 % but the heap's cost, which is not small beside
    /// an expansion of two new edges (the 2-D sphere, every point a vertex: 6.5 % more
    /// instructions). Each with its serial, as in `pending`.
    oldest_first: VecDeque<(u64, FacetId)>,
    /// Whether the first step (which starts the build's first phase) has run.
    begun: bool,
}

/// A pending facet: the distance of its farthest outside point (the bits of a non-negative
/// `f64`, which order as the numbers do), its serial reversed (so that of equal distances the
/// oldest comes first, and so that an entry whose slot was since reused is known), its id.
type Pending = (u64, Reverse<u64>, FacetId);

impl FarthestPoint {
    /// A new full-hull strategy.
    pub fn new() -> Self {
        Self::default()
    }

    /// Queues facet `id` if it has outside points, keyed by the farthest one's distance (the
    /// orientation value the partition kept, times the facet's inverse norm: no point is read).
    fn queue<const D: usize>(&mut self, hull: &Hull<D>, id: FacetId) {
        let facet = hull.facet(id);
        if facet.outside_len() == 0 {
            return;
        }
        if D == 2 {
            self.oldest_first.push_back((facet.serial, id));
            return;
        }
        // Every facet with outside points is queued (the build is complete only when none is
        // left), whether or not its farthest point is known: unknown, it orders as the
        // nearest, and so does a NaN (an infinite inverse norm times zero).
        let distance = facet
            .farthest
            .map_or(0.0, |(_, value)| value * facet.inv_norm);
        let key = if distance > 0.0 {
            distance.to_bits()
        } else {
            0
        };
        self.pending.push((key, Reverse(facet.serial), id));
    }

    /// The next pending facet and its serial when queued.
    fn next<const D: usize>(&mut self) -> Option<(u64, FacetId)> {
        if D == 2 {
            self.oldest_first.pop_front()
        } else {
            self.pending
                .pop()
                .map(|(_, Reverse(serial), id)| (serial, id))
        }
    }

    /// Queues every live facet with outside points.
    fn queue_all<const D: usize>(&mut self, hull: &Hull<D>) {
        for (id, _) in hull.facets() {
            self.queue(hull, id);
        }
    }
}

impl<const D: usize> Strategy<D> for FarthestPoint {
    type Output = ();

    fn start(&mut self, hull: &Hull<D>) {
        self.pending.clear();
        self.oldest_first.clear();
        self.begun = false;
        self.queue_all(hull);
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        if !self.begun {
            self.begun = true;
            hull.begin_full_build();
        }
        while let Some((serial, id)) = self.next::<D>() {
            // A removed facet, or its slot reused by another (queued under its own key).
            if !hull.is_current(id, serial) {
                continue;
            }
            if hull.is_tracing() {
                trace_choice(hull, id);
            }
            if hull.expand(id) {
                for &created in hull.last_created() {
                    self.queue(hull, created);
                }
                return Step::Continue;
            }
        }
        // The first phase kept coplanar facets: the second builds on its vertices (`coplanar.rs`).
        if hull.end_first_phase() {
            self.queue_all(hull);
            return Step::Continue;
        }
        hull.trace_stop(None, FarthestReason::Complete);
        Step::Stop
    }

    fn finish(self, _hull: &Hull<D>) -> Self::Output {}

    fn trace_context(&self) -> TraceContext<D> {
        TraceContext {
            strategy: "FarthestPoint".to_string(),
            ..TraceContext::default()
        }
    }
}

/// Records the choice of `id` if it is about to be expanded (live, with outside points); stale
/// and emptied ids are skipped silently, as the strategy skips them.
fn trace_choice<const D: usize>(hull: &mut Hull<D>, id: FacetId) {
    let facet = hull.facet(id);
    if let Some(p) = facet.farthest_point().filter(|_| facet.is_alive()) {
        let distance = hull.signed_distance(id, &hull.point(p));
        hull.trace_choice(id, FarthestReason::Farthest { distance });
    }
}

/// The steps of [`FarthestPoint`] a trace records ([`TraceReason`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FarthestReason {
    /// The pending facet whose farthest outside point is the farthest of all (of equal
    /// distances, the oldest facet): that point is added.
    Farthest {
        /// That point's floating-point distance beyond the facet's plane.
        distance: f64,
    },
    /// No outside set remains: the hull is complete.
    Complete,
}

impl TraceReason for FarthestReason {
    fn code(&self) -> &'static str {
        match self {
            FarthestReason::Farthest { .. } => "farthest-pending",
            FarthestReason::Complete => "complete",
        }
    }

    fn describe(&self) -> String {
        match self {
            FarthestReason::Farthest { .. } => "pending facet whose farthest outside point is \
                                                the farthest of all; that point is added"
                .to_string(),
            FarthestReason::Complete => {
                "no outside set remains: every point is inside, the hull is complete".to_string()
            }
        }
    }

    fn key(&self) -> Option<(&'static str, f64)> {
        match self {
            FarthestReason::Farthest { distance } => {
                Some(("distance of its farthest outside point", *distance))
            }
            FarthestReason::Complete => None,
        }
    }
}
