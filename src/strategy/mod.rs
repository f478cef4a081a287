//! Expansion strategies: what to expand next, and when to stop.
//!
//! A [`Strategy`] is a stateful value the engine consults: [`start`](Strategy::start) once the
//! initial simplex exists, then [`step`](Strategy::step) until it returns [`Step::Stop`] — each
//! step typically names a facet to [`Hull::expand`] and reads [`Hull::last_removed`] /
//! [`Hull::last_created`] to update its own queue — and finally [`finish`](Strategy::finish) to
//! produce its result. The engine never knows a strategy's goal.
//!
//! ```
//! use pqhull::{Hull, Strategy};
//! use pqhull::strategy::Step;
//!
//! /// Expands at most `budget` times, always the facet with the largest outside set.
//! struct Budget(usize);
//!
//! impl<const D: usize> Strategy<D> for Budget {
//!     type Output = usize; // facets in the partial hull
//!     fn start(&mut self, _hull: &Hull<D>) {}
//!     fn step(&mut self, hull: &mut Hull<D>) -> Step {
//!         let busiest = hull.facets().max_by_key(|(_, f)| f.outside_len()).map(|(id, _)| id);
//!         match busiest {
//!             Some(id) if self.0 > 0 && hull.expand(id) => {
//!                 self.0 -= 1;
//!                 Step::Continue
//!             }
//!             _ => Step::Stop,
//!         }
//!     }
//!     fn finish(self, hull: &Hull<D>) -> usize {
//!         hull.facet_count()
//!     }
//! }
//!
//! let points = pqhull::rbox::generate::<3>(&pqhull::rbox::Family::SphereSurface, 200, 1);
//! let (partial, facets) = Hull::try_with_strategy(&points, Budget(10))?;
//! assert_eq!(partial.stats().expansions, 10);
//! assert_eq!(facets, partial.facet_count());
//! partial.check()?; // partial hulls keep every invariant too
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::hull::Hull;
use std::time::Duration;

mod closest_to_origin;
mod farthest_point;
mod ows_inflation;

pub use closest_to_origin::{ClosestToOrigin, DistanceResult, NoSource, PointSource};
pub use farthest_point::FarthestPoint;
pub use ows_inflation::{OwsInflation, OwsResult, inflation_factor};
pub(crate) use ows_inflation::{exact_factor, factor_lower_bound};

/// Work counters every strategy reports (the seed paper's evaluation measures).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Points added to the hull (initial simplex included).
    pub points_processed: usize,
    /// Facets (hyperplanes) created, initial simplex included.
    pub facets_created: usize,
    /// Expansions (one point added each).
    pub expansions: usize,
    /// Wall time from the start of the build to the end of the strategy.
    pub elapsed: Duration,
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
    /// Expand (through [`Hull::expand`]) or stop.
    fn step(&mut self, hull: &mut Hull<D>) -> Step;
    /// Produce the result.
    fn finish(self, hull: &Hull<D>) -> Self::Output;
    /// Whether the engine should make every live facet's normal precise before
    /// [`finish`](Self::finish) ([`Hull::refine_normals`](crate::Hull::refine_normals)). Default `true`; a partial strategy
    /// that refines the facets it reports (through its `&mut Hull`) can skip the rest.
    fn refines_all_normals(&self) -> bool {
        true
    }
    /// What a trace of this strategy's run should show beside the hull (its name, query point,
    /// disturbances); asked once by [`Hull::try_with_strategy_traced`], never on an untraced
    /// run. Default: nothing (the engine names the strategy after its type).
    ///
    /// A strategy explains itself in a trace through [`Hull::trace_choice`],
    /// [`Hull::trace_note`] and [`Hull::trace_stop`]; the engine records the rest.
    fn trace_context(&self) -> crate::viz::TraceContext<D> {
        crate::viz::TraceContext::default()
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

    fn trace_context(&self) -> crate::viz::TraceContext<D> {
        (**self).trace_context()
    }
}

/// A facet waiting in a strategy's priority queue (`BinaryHeap`, a max-heap): the largest `key`
/// first, ties to the older facet (smaller serial) so the order is deterministic. `serial` tells
/// an entry whose facet was since removed (its slot possibly reused) from a live one; `data` is
/// whatever the strategy keeps with it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Queued<T> {
    pub(crate) key: f64,
    pub(crate) id: crate::hull::FacetId,
    pub(crate) serial: u64,
    pub(crate) data: T,
}

impl<T> PartialEq for Queued<T> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == std::cmp::Ordering::Equal
    }
}
impl<T> Eq for Queued<T> {}
impl<T> PartialOrd for Queued<T> {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl<T> Ord for Queued<T> {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.key
            .total_cmp(&other.key)
            .then(other.serial.cmp(&self.serial))
    }
}
