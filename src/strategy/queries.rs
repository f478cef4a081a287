//! Many queries against one point set, answered from shared partial hulls: each query resumes
//! [`ClosestToOrigin`] on the hull the previous ones left, so the hull grows only as far as the
//! queries need and no query rebuilds it; [`distances_to_boundary`] runs one such hull per
//! worker thread.

use super::{ClosestToOrigin, DistanceResult, Step, Strategy};
use crate::hull::{Hull, HullError};
use std::fmt;

/// Why a distance query could not be answered.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum QueryError {
    /// The points admit no hull.
    Hull(HullError),
    /// Query `index` has a NaN or infinite coordinate.
    NonFiniteQuery {
        /// The query's index.
        index: usize,
        /// The coordinate's index.
        coordinate: usize,
    },
}

impl fmt::Display for QueryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            QueryError::Hull(e) => write!(f, "{e}"),
            QueryError::NonFiniteQuery { index, coordinate } => write!(
                f,
                "query {index} has a NaN or infinite coordinate (coordinate {coordinate})"
            ),
        }
    }
}

impl std::error::Error for QueryError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            QueryError::Hull(e) => Some(e),
            QueryError::NonFiniteQuery { .. } => None,
        }
    }
}

impl From<HullError> for QueryError {
    fn from(e: HullError) -> Self {
        QueryError::Hull(e)
    }
}

/// Stops at once: the initial simplex, for queries to grow from.
struct Initial;

impl<const D: usize> Strategy<D> for Initial {
    type Output = ();
    fn start(&mut self, _: &Hull<D>) {}
    fn step(&mut self, _: &mut Hull<D>) -> Step {
        Step::Stop
    }
    fn finish(self, _: &Hull<D>) {}
}

/// Signed distances from many query points to the boundary of one point set's hull, from one
/// partial hull kept between queries ([`Hull::resume_with_strategy`]). Each answer is what
/// [`ClosestToOrigin::towards`] gives from scratch — exact sign, the same accuracy — and the
/// hull only grows: queries near each other, or many of them, share most of the work.
///
/// ```
/// use pqhull::strategy::BoundaryDistances;
/// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.2, 0.3]];
/// let mut distances = BoundaryDistances::new(&square)?;
/// assert!((distances.distance([0.0, 0.0])?.signed_distance - 1.0).abs() < 1e-15);
/// assert!((distances.distance([3.0, 0.0])?.signed_distance + 2.0).abs() < 1e-15);
/// assert_eq!(distances.distance([1.0, 0.5])?.signed_distance, 0.0); // on the boundary
/// # Ok::<(), pqhull::strategy::QueryError>(())
/// ```
#[derive(Clone, Debug)]
pub struct BoundaryDistances<const D: usize> {
    hull: Hull<D>,
    /// The points, for a query answered from a fresh partial hull.
    points: Vec<[f64; D]>,
    /// The storage of those fresh hulls, reused.
    scratch: Hull<D>,
    /// The facets one query's own partial hull creates: the first query's (it grows the shared
    /// hull from the initial simplex, as a fresh run would), then those of the fresh runs.
    fresh_facets: Option<usize>,
}

/// The shared hull is resumed while its live facets are at most this many times what one
/// query's own partial hull creates; beyond, the query gets a fresh partial hull. Resuming keys
/// every live facet (cheap per facet), a fresh run creates and tests its facets (dear per
/// facet). Measured (`cargo bench -p pqhull-cli --bench hull -- queries`): the shared hull won
/// at a ratio of 18 (5-D cube, 4× faster than fresh hulls) and lost at 72 (6-D sphere, 3×
/// slower). The choice only steers the work: both give the same answer.
const SHARED_TO_FRESH_FACETS: usize = 32;

impl<const D: usize> BoundaryDistances<D> {
    /// The initial simplex of `points`, for queries to grow from.
    ///
    /// # Errors
    /// [`QueryError::Hull`] when the points admit no hull (as [`Hull::try_new`]).
    pub fn new(points: &[[f64; D]]) -> Result<Self, QueryError> {
        let (hull, ()) = Hull::try_with_strategy(points, Initial)?;
        Ok(BoundaryDistances {
            hull,
            points: points.to_vec(),
            scratch: Hull::empty(),
            fresh_facets: None,
        })
    }

    /// The signed distance from `query` to the boundary (positive inside), growing the shared
    /// hull as far as this query needs — or from a fresh partial hull once the shared one holds
    /// far more facets (32 times) than a query's own partial hull creates. The result's `stats`
    /// count the work of the hull it was answered from.
    ///
    /// # Errors
    /// [`QueryError::NonFiniteQuery`] (index 0) for a NaN or infinite coordinate.
    pub fn distance(&mut self, query: [f64; D]) -> Result<DistanceResult<D>, QueryError> {
        check_query(0, &query)?;
        let strategy = ClosestToOrigin::towards(query);
        let Some(fresh) = self.fresh_facets else {
            let answer = self.hull.resume_with_strategy(strategy)?;
            self.fresh_facets = Some(answer.stats.facets_created.max(1));
            return Ok(answer);
        };
        if self.hull.facet_count() > SHARED_TO_FRESH_FACETS * fresh {
            let answer = self.scratch.rebuild_with_strategy(&self.points, strategy)?;
            // A running mean, weighted toward the recent runs.
            self.fresh_facets = Some((fresh + answer.stats.facets_created.max(1)).div_ceil(2));
            return Ok(answer);
        }
        Ok(self.hull.resume_with_strategy(strategy)?)
    }

    /// The hull as the queries so far have left it (a partial hull of the points).
    pub fn hull(&self) -> &Hull<D> {
        &self.hull
    }
}

fn check_query<const D: usize>(index: usize, query: &[f64; D]) -> Result<(), QueryError> {
    match query.iter().position(|x| !x.is_finite()) {
        Some(coordinate) => Err(QueryError::NonFiniteQuery { index, coordinate }),
        None => Ok(()),
    }
}

/// The signed distance from each of `queries` to the boundary of the hull of `points`, in
/// order. With the `parallel` feature (a default) the queries are cut into one run of
/// consecutive queries per worker of rayon's current pool, each run answered from its own
/// shared partial hull ([`BoundaryDistances`]); without it, one run. Every answer is the one
/// [`ClosestToOrigin::towards`] gives alone, whatever the cut.
///
/// ```
/// use pqhull::strategy::distances_to_boundary;
/// let points = pqhull::rbox::generate::<4>(&pqhull::rbox::Family::UniformCube, 1000, 3);
/// let queries = [[0.0; 4], [0.1, 0.0, 0.0, 0.0], [2.0, 0.0, 0.0, 0.0]];
/// let answers = distances_to_boundary(&points, &queries)?;
/// assert!(answers[0].signed_distance > 0.0 && answers[2].signed_distance < 0.0);
/// # Ok::<(), pqhull::strategy::QueryError>(())
/// ```
///
/// # Errors
/// [`QueryError::Hull`] when the points admit no hull, [`QueryError::NonFiniteQuery`] naming
/// the first query with a NaN or infinite coordinate (checked before any work).
pub fn distances_to_boundary<const D: usize>(
    points: &[[f64; D]],
    queries: &[[f64; D]],
) -> Result<Vec<DistanceResult<D>>, QueryError> {
    for (index, query) in queries.iter().enumerate() {
        check_query(index, query)?;
    }
    let first = BoundaryDistances::new(points)?;
    let run = |mut distances: BoundaryDistances<D>, run: &[[f64; D]]| {
        run.iter()
            .map(|&q| distances.distance(q))
            .collect::<Result<Vec<_>, _>>()
    };
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        let workers = rayon::current_num_threads().max(1);
        let size = queries.len().div_ceil(workers).max(1);
        let runs: Vec<Vec<DistanceResult<D>>> = queries
            .par_chunks(size)
            .map(|chunk| run(first.clone(), chunk))
            .collect::<Result<_, _>>()?;
        Ok(runs.into_iter().flatten().collect())
    }
    #[cfg(not(feature = "parallel"))]
    {
        run(first, queries)
    }
}
