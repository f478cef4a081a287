//! `FarthestPoint`: plain QuickHull, run to completion.

use super::{FacetId, Hull, Step, Strategy, TraceContext, TraceReason};

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
    /// Facets that may still have outside points (stale ids are skipped), expanded oldest first:
    /// breadth-first order (as Qhull's facet list) creates 5–30 % fewer facets than depth-first
    /// in 3-D to 6-D (measured with `examples/compare_qhull.rs`).
    pending: std::collections::VecDeque<FacetId>,
    /// Whether the first step (which starts the build's first phase) has run.
    begun: bool,
}

impl FarthestPoint {
    /// A new full-hull strategy.
    pub fn new() -> Self {
        Self::default()
    }
}

impl<const D: usize> Strategy<D> for FarthestPoint {
    type Output = ();

    fn start(&mut self, hull: &Hull<D>) {
        self.pending.clear();
        self.begun = false;
        self.pending.extend(
            hull.facets()
                .filter(|(_, f)| f.outside_len() > 0)
                .map(|(id, _)| id),
        );
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        // A stale id (its slot since reused) is harmless here: any live facet with outside points
        // is a valid facet to expand.
        if !self.begun {
            self.begun = true;
            hull.begin_full_build();
        }
        while let Some(id) = self.pending.pop_front() {
            if hull.is_tracing() {
                trace_choice(hull, id);
            }
            if hull.expand(id) {
                self.pending.extend(
                    hull.last_created()
                        .iter()
                        .copied()
                        .filter(|&c| hull.facet(c).outside_len() > 0),
                );
                return Step::Continue;
            }
        }
        // The first phase kept coplanar facets: the second builds on its vertices (`coplanar.rs`).
        if hull.end_first_phase() {
            self.pending.extend(
                hull.facets()
                    .filter(|(_, f)| f.outside_len() > 0)
                    .map(|(id, _)| id),
            );
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
        hull.trace_choice(id, FarthestReason::Oldest { distance });
    }
}

/// The steps of [`FarthestPoint`] a trace records ([`TraceReason`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FarthestReason {
    /// The oldest pending facet with outside points (breadth first): its farthest outside
    /// point is added.
    Oldest {
        /// That point's floating-point distance beyond the facet's plane.
        distance: f64,
    },
    /// No outside set remains: the hull is complete.
    Complete,
}

impl TraceReason for FarthestReason {
    fn code(&self) -> &'static str {
        match self {
            FarthestReason::Oldest { .. } => "oldest-pending",
            FarthestReason::Complete => "complete",
        }
    }

    fn describe(&self) -> String {
        match self {
            FarthestReason::Oldest { .. } => "oldest pending facet with outside points \
                                              (breadth-first); its farthest outside point is added"
                .to_string(),
            FarthestReason::Complete => {
                "no outside set remains: every point is inside, the hull is complete".to_string()
            }
        }
    }

    fn key(&self) -> Option<(&'static str, f64)> {
        match self {
            FarthestReason::Oldest { distance } => {
                Some(("distance of its farthest outside point", *distance))
            }
            FarthestReason::Complete => None,
        }
    }
}
