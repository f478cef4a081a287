//! Expansion strategies: what to expand next, and when to stop.
//!
//! A [`Strategy`] is a stateful value the engine consults: [`start`](Strategy::start) once the
//! initial simplex exists, then [`step`](Strategy::step) until it returns [`Step::Stop`] — each
//! step typically names a facet to [`expand`](crate::hull::StrategyHooks::expand) and reads
//! [`last_removed`](crate::hull::StrategyHooks::last_removed) /
//! [`last_created`](crate::hull::StrategyHooks::last_created) to update its own queue — and
//! finally [`finish`](Strategy::finish) to produce its result. The engine never knows a
//! strategy's goal. The hooks a strategy drives the engine with are the trait
//! [`StrategyHooks`](crate::hull::StrategyHooks), apart from `Hull`'s own methods (what a user of
//! a hull calls).
//!
//! ```
//! use pqhull::hull::StrategyHooks; // expand, last_created, ...: the hooks a strategy uses
//! use pqhull::{Hull, Strategy};
//! use pqhull::Step;
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

mod closest_to_origin;
mod complete;
mod minkowski_sum;
mod ows_inflation;
mod penetration;
mod queries;
mod reasons;

pub use crate::hull::{FarthestPoint, ReusableStrategy, Stats, Step, Strategy};
pub use closest_to_origin::{ClosestToOrigin, DistanceResult, NoSource, PointSource, SourceError};
pub use complete::Complete;
pub use minkowski_sum::MinkowskiSum;
pub use ows_inflation::{OwsInflation, OwsResult, inflation_factor};
pub use ows_inflation::{exact_factor, factor_lower_bound};
pub use penetration::penetration_depth;
pub use penetration::{Body, FLAT_PAIRS_LIMIT, Penetration, PenetrationError, Relation};
pub use queries::{BoundaryDistances, QueryError, distances_to_boundary};
pub use reasons::{InflationReason, NearestReason};

/// A facet waiting in a strategy's priority queue (`BinaryHeap`, a max-heap): the largest `key`
/// first, ties to the older facet (smaller serial) so the order is deterministic. `serial` tells
/// an entry whose facet was since removed (its slot possibly reused) from a live one
/// ([`StrategyHooks::is_current`](crate::hull::StrategyHooks::is_current)); `data` is whatever the strategy keeps with it. The built-in strategies
/// queue their facets with it; `examples/custom_strategy.rs` shows one written outside the crate.
///
/// ```
/// use pqhull::hull::StrategyHooks;
/// use pqhull::strategy::Queued;
/// use pqhull::Hull;
/// use std::collections::BinaryHeap;
/// let hull = Hull::try_new(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])?;
/// let mut queue: BinaryHeap<_> = hull
///     .facets()
///     .map(|(id, f)| Queued { key: f.offset(), id, serial: f.serial(), data: () })
///     .collect();
/// let top = queue.pop().unwrap();
/// assert!(hull.is_current(top.id, top.serial));
/// assert_eq!(top.key, hull.facets().map(|(_, f)| f.offset()).fold(f64::MIN, f64::max));
/// # Ok::<(), pqhull::HullError>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Queued<T> {
    /// The priority: the largest first (compared with `total_cmp`).
    pub key: f64,
    /// The facet.
    pub id: crate::hull::FacetId,
    /// The facet's [`serial`](crate::Facet::serial) when queued.
    pub serial: u64,
    /// What the strategy keeps with the entry.
    pub data: T,
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
