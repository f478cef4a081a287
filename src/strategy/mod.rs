//! Expansion strategies: what to expand next, and when to stop.
//!
//! STUB — API under construction.

use crate::hull::Hull;
use std::time::Duration;

mod closest_to_origin;
mod farthest_point;
mod nearest;

pub use closest_to_origin::{ClosestToOrigin, DistanceResult};
pub use farthest_point::FarthestPoint;

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
}
