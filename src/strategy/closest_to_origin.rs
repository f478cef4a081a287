//! PQHGWS.
use super::{Stats, Step, Strategy};
use crate::hull::{FacetId, Hull};

/// Grows the hull toward a query point and stops when the nearest facet is certain.
#[derive(Clone, Debug)]
pub struct ClosestToOrigin<const D: usize> {
    query: [f64; D],
}

/// What [`ClosestToOrigin`] finds.
#[derive(Clone, Debug, PartialEq)]
pub struct DistanceResult<const D: usize> {
    /// Signed distance from the query point to the hull boundary: positive inside, negative outside.
    pub signed_distance: f64,
    /// The deciding facet.
    pub closest_facet: FacetId,
    /// Its vertices (input indices).
    pub closest_facet_vertices: [usize; D],
    /// The point of the hull boundary nearest the query point.
    pub nearest_point: [f64; D],
    /// Work done.
    pub stats: Stats,
}

impl<const D: usize> Default for ClosestToOrigin<D> {
    fn default() -> Self {
        Self { query: [0.0; D] }
    }
}

impl<const D: usize> ClosestToOrigin<D> {
    /// Toward the origin.
    pub fn new() -> Self {
        Self::default()
    }
    /// Toward `query`.
    pub fn towards(query: [f64; D]) -> Self {
        Self { query }
    }
}

impl<const D: usize> Strategy<D> for ClosestToOrigin<D> {
    type Output = DistanceResult<D>;
    fn start(&mut self, _hull: &Hull<D>) {}
    fn step(&mut self, _hull: &mut Hull<D>) -> Step {
        todo!()
    }
    fn finish(self, _hull: &Hull<D>) -> Self::Output {
        let _ = self.query;
        todo!()
    }
}
