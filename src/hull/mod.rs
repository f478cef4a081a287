//! The QuickHull engine. STUB — API under construction.

use crate::strategy::{FarthestPoint, Stats, Strategy};
use std::fmt;

/// A typed handle to a facet in the hull's arena.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FacetId(pub(crate) u32);

impl FacetId {
    /// The slot index.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A simplicial facet.
#[derive(Clone, Debug)]
pub struct Facet<const D: usize> {
    vertices: [u32; D],
    neighbors: [FacetId; D],
    normal: [f64; D],
    offset: f64,
}

impl<const D: usize> Facet<D> {
    /// Vertices (input indices).
    pub fn vertices(&self) -> [usize; D] {
        self.vertices.map(|v| v as usize)
    }
    /// Neighbours; neighbour i is opposite vertex i.
    pub fn neighbors(&self) -> [FacetId; D] {
        self.neighbors
    }
    /// Unit outward normal.
    pub fn normal(&self) -> [f64; D] {
        self.normal
    }
    /// Offset: `normal · x <= offset` inside.
    pub fn offset(&self) -> f64 {
        self.offset
    }
}

/// Why a hull could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum HullError {
    /// D outside 2..=8.
    DimensionOutOfRange {
        /// The dimension asked for.
        dimension: usize,
    },
    /// Fewer than D + 1 points.
    TooFewPoints {
        /// Points needed.
        needed: usize,
        /// Points given.
        got: usize,
    },
    /// A NaN or infinite coordinate.
    NonFinite {
        /// Index of the point.
        index: usize,
        /// Which coordinate.
        coordinate: usize,
    },
    /// The points span fewer than D dimensions.
    AffinelyDependent {
        /// Their affine rank.
        rank: usize,
        /// The dimension D.
        dimension: usize,
    },
}

impl fmt::Display for HullError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self:?}")
    }
}
impl std::error::Error for HullError {}

/// A broken hull invariant, found by [`Hull::check`].
#[derive(Clone, Debug, PartialEq)]
pub struct InvariantViolation {
    /// What is wrong.
    pub message: String,
}

/// A (possibly partial) convex hull.
#[derive(Clone, Debug)]
pub struct Hull<const D: usize> {
    points: Vec<[f64; D]>,
    facets: Vec<Facet<D>>,
}

impl<const D: usize> Hull<D> {
    /// Full hull.
    pub fn try_new(points: &[[f64; D]]) -> Result<Self, HullError> {
        Self::try_with_strategy(points, FarthestPoint::new()).map(|(h, ())| h)
    }
    /// Hull grown by a strategy.
    pub fn try_with_strategy<S: Strategy<D>>(
        points: &[[f64; D]],
        strategy: S,
    ) -> Result<(Self, S::Output), HullError> {
        let _ = (points, strategy);
        todo!()
    }
    /// The input points.
    pub fn points(&self) -> &[[f64; D]] {
        &self.points
    }
    /// Sorted input indices of hull vertices.
    pub fn vertex_indices(&self) -> Vec<usize> {
        todo!()
    }
    /// Live facets.
    pub fn facets(&self) -> impl Iterator<Item = (FacetId, &Facet<D>)> + '_ {
        self.facets
            .iter()
            .enumerate()
            .map(|(i, f)| (FacetId(i as u32), f))
    }
    /// Number of live facets.
    pub fn facet_count(&self) -> usize {
        self.facets.len()
    }
    /// Volume.
    pub fn volume(&self) -> f64 {
        todo!()
    }
    /// Work counters.
    pub fn stats(&self) -> Stats {
        todo!()
    }
    /// Validator.
    pub fn check(&self) -> Result<(), InvariantViolation> {
        todo!()
    }
}
