//! The seam between the engine and the strategies that drive it: [`Strategy`], [`Step`],
//! [`Stats`] and [`ReusableStrategy`]. The engine owns the trait; strategies live above it.

use super::Hull;
use super::record::TraceContext;
use std::time::Duration;

/// Work counters every strategy reports (the seed paper's evaluation measures).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Points added to the hull (initial simplex included; in 2-D, the initial polygon of the
    /// axis extremes, which is the initial hull there: see docs/ARCHITECTURE.md). A full build
    /// that ran a second phase (on the extreme points, after a first that kept coplanar facets:
    /// see [`FarthestPoint`](crate::FarthestPoint)) counts both phases' points, as every other
    /// counter does.
    pub points_processed: usize,
    /// Facets (hyperplanes) created, initial simplex (in 2-D, initial polygon) included.
    pub facets_created: usize,
    /// Expansions (one point added each), after the initial simplex or polygon.
    pub expansions: usize,
    /// Wall time from the start of the build to the end of the strategy.
    pub elapsed: Duration,
}

/// The work of two runs together (every counter and the time summed): what a metric built on
/// two hulls reports.
///
/// ```
/// use pqhull::Stats;
/// let a = Stats { points_processed: 7, facets_created: 12, expansions: 0, ..Stats::default() };
/// let b = Stats { points_processed: 9, facets_created: 20, expansions: 2, ..Stats::default() };
/// assert_eq!((a + b).facets_created, 32);
/// ```
impl std::ops::Add for Stats {
    type Output = Stats;

    fn add(self, other: Stats) -> Stats {
        Stats {
            points_processed: self.points_processed + other.points_processed,
            facets_created: self.facets_created + other.facets_created,
            expansions: self.expansions + other.expansions,
            elapsed: self.elapsed + other.elapsed,
        }
    }
}

/// Whether the engine should keep expanding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Call [`Strategy::step`] again.
    Continue,
    /// Stop; the engine then calls [`Strategy::finish`].
    Stop,
}

/// A stateful expansion strategy.
pub trait Strategy<const D: usize> {
    /// What the strategy produces.
    type Output;
    /// Called once the initial simplex exists.
    fn start(&mut self, hull: &Hull<D>);
    /// Expand (through [`StrategyHooks::expand`](crate::hull::StrategyHooks::expand)) or stop.
    fn step(&mut self, hull: &mut Hull<D>) -> Step;
    /// Produce the result.
    fn finish(self, hull: &Hull<D>) -> Self::Output;
    /// Whether the engine should make every live facet's normal precise before
    /// [`finish`](Self::finish) ([`Hull::refine_normals`](crate::Hull::refine_normals)). Default `true`; a partial strategy
    /// that refines the facets it reports (through its `&mut Hull`) can skip the rest.
    fn refines_all_normals(&self) -> bool {
        true
    }
    /// Whether each outside point should go to the candidate facet it lies farthest beyond
    /// (Qhull's option `Qf`) rather than to the first one found to hold it. Default `false`: any
    /// facet a point is strictly beyond keeps the engine's invariants, and stopping at the first
    /// halves the partition's tests; the full hull ([`FarthestPoint`](crate::FarthestPoint))
    /// takes the default. A partial strategy that grows the hull through the facets of its
    /// choice, each by its farthest point, keeps points nearer the facet they see most of, and
    /// reaches its certificate in fewer expansions with `true` (the built-in partial strategies
    /// return it). Asked once, before the initial partition.
    fn partitions_to_farthest(&self) -> bool {
        false
    }
    /// What a trace of this strategy's run should show beside the hull (its name, query point,
    /// disturbances); asked once by [`Hull::try_with_strategy_traced`], never on an untraced
    /// run. Default: nothing (the engine names the strategy after its type).
    ///
    /// A strategy explains itself in a trace through [`StrategyHooks::trace_choice`](crate::hull::StrategyHooks::trace_choice),
    /// [`StrategyHooks::trace_note`](crate::hull::StrategyHooks::trace_note) and [`StrategyHooks::trace_stop`](crate::hull::StrategyHooks::trace_stop); the engine records the rest.
    fn trace_context(&self) -> TraceContext<D> {
        TraceContext::default()
    }
}

/// A strategy whose result can be read from a borrow: then `&mut` of it is a strategy too, which
/// runs the same way and keeps the strategy's buffers (queues, scratch) for the next run — with
/// [`Hull::rebuild_with_strategy`](crate::Hull::rebuild_with_strategy), evaluating many point sets
/// allocates nothing in steady state. `start` must reset everything a run depends on.
///
/// ```
/// use pqhull::{ClosestToOrigin, Hull};
/// let mut strategy = ClosestToOrigin::new();
/// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
/// let (mut hull, first) = Hull::try_with_strategy(&square, &mut strategy)?;
/// let shifted = square.map(|p| [p[0] + 0.5, p[1]]);
/// let second = hull.rebuild_with_strategy(&shifted, &mut strategy)?;
/// assert!((first.signed_distance - 1.0).abs() < 1e-15);
/// assert!((second.signed_distance - 0.5).abs() < 1e-15);
/// # Ok::<(), pqhull::HullError>(())
/// ```
pub trait ReusableStrategy<const D: usize>: Strategy<D> {
    /// The result of the run that just stopped (what [`Strategy::finish`] returns).
    fn output(&self, hull: &Hull<D>) -> Self::Output;
}

impl<const D: usize, T: ReusableStrategy<D>> Strategy<D> for &mut T {
    type Output = T::Output;

    fn start(&mut self, hull: &Hull<D>) {
        (**self).start(hull);
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        (**self).step(hull)
    }

    fn finish(self, hull: &Hull<D>) -> Self::Output {
        self.output(hull)
    }

    fn refines_all_normals(&self) -> bool {
        (**self).refines_all_normals()
    }
    fn partitions_to_farthest(&self) -> bool {
        (**self).partitions_to_farthest()
    }

    fn trace_context(&self) -> TraceContext<D> {
        (**self).trace_context()
    }
}
