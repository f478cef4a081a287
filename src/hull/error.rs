//! Errors of hull construction and of the invariant checker.

use std::fmt;

/// Why a hull could not be built. Every variant says what was wrong and where.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum HullError {
    /// The dimension is outside the supported range 2..=8.
    DimensionOutOfRange {
        /// The dimension asked for.
        dimension: usize,
    },
    /// Fewer than D + 1 points: no full-dimensional hull exists.
    TooFewPoints {
        /// Points needed (D + 1).
        needed: usize,
        /// Points given.
        got: usize,
    },
    /// More points than vertex ids (`u32`) can address.
    TooManyPoints {
        /// The largest supported count.
        max: usize,
        /// Points given.
        got: usize,
    },
    /// A NaN or infinite coordinate.
    NonFinite {
        /// Index of the offending point.
        index: usize,
        /// Which of its coordinates.
        coordinate: usize,
    },
    /// The points lie in an affine subspace of dimension `rank` < D.
    AffinelyDependent {
        /// The affine rank of the input (0 for a single repeated point, 1 for collinear, …).
        rank: usize,
        /// The dimension D.
        dimension: usize,
    },
    /// [`Hull::rebuild_with_flats`](crate::Hull::rebuild_with_flats) was given a flat dimension
    /// outside `1..D`.
    FlatDimension {
        /// The flat dimension given.
        flat_dim: usize,
        /// The dimension D.
        dimension: usize,
    },
    /// [`Hull::rebuild_with_flats`](crate::Hull::rebuild_with_flats) was given more flat labels
    /// than points.
    TooManyFlatLabels {
        /// Labels given.
        labels: usize,
        /// Points given.
        points: usize,
    },
    /// The points declared in one flat span more than the declared flat dimension (exact rank).
    NotInFlat {
        /// The flat's label.
        flat: u32,
        /// A point of it outside the flat spanned by the points before it.
        index: usize,
        /// The declared flat dimension.
        flat_dim: usize,
    },
}

impl fmt::Display for HullError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            HullError::DimensionOutOfRange { dimension } => {
                write!(f, "dimension {dimension} is not supported (2 to 8)")
            }
            HullError::TooFewPoints { needed, got } => write!(
                f,
                "too few points: a full-dimensional hull needs at least {needed}, got {got}"
            ),
            HullError::TooManyPoints { max, got } => {
                write!(f, "too many points: at most {max} are supported, got {got}")
            }
            HullError::NonFinite { index, coordinate } => write!(
                f,
                "point {index} has a NaN or infinite coordinate (coordinate {coordinate})"
            ),
            HullError::AffinelyDependent { rank, dimension } => write!(
                f,
                "the points are affinely dependent: they span an affine subspace of dimension \
                 {rank}, not {dimension}"
            ),
            HullError::FlatDimension {
                flat_dim,
                dimension,
            } => write!(
                f,
                "declared flats must have dimension 1 to {}, got {flat_dim}",
                dimension - 1
            ),
            HullError::TooManyFlatLabels { labels, points } => write!(
                f,
                "{labels} flat labels for {points} points: at most one label per point"
            ),
            HullError::NotInFlat {
                flat,
                index,
                flat_dim,
            } => write!(
                f,
                "point {index} is declared in flat {flat}, but the points declared there span \
                 more than {flat_dim} dimensions with it"
            ),
        }
    }
}

impl std::error::Error for HullError {}

/// A broken hull invariant, found by [`Hull::check`](crate::Hull::check).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InvariantViolation {
    /// What is wrong, naming the facets or points involved.
    pub message: String,
}

impl fmt::Display for InvariantViolation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "hull invariant violated: {}", self.message)
    }
}

impl std::error::Error for InvariantViolation {}
