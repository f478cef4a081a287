//! Growing a built hull by new points: incremental hulls.
//!
//! QuickHull's state between expansions is already what an incremental hull needs: live facets
//! and, for every point not yet inside, an outside set. New points are tested against the live
//! facets (exactly), those beyond one join its outside set, and a strategy runs again from
//! there — [`FarthestPoint`] to the full hull, or a partial strategy resuming its search. A new
//! point inside the hull costs its side tests and nothing more.

use super::build::first_non_finite;
use super::{FacetId, FarthestPoint, Hull, HullError, Partition, Strategy};
use crate::predicates::{Sign, in_box};
use std::ops::Range;
use std::time::Instant;

impl<const D: usize> Hull<D> {
    /// Adds `points` to the hull's input and grows the hull to the convex hull of all its points,
    /// old and new: the same hull [`Hull::try_new`] builds from all of them (the same vertices
    /// and facets; facet ids, facet order and the work counters differ). Returns the new points'
    /// indices, which follow the old ones.
    ///
    /// The work is what the new points change: each is tested against the live facets (exact
    /// tests), and the ones beyond the hull are added by QuickHull as in a fresh build. On a
    /// partial hull (a strategy stopped early) the points it had not added yet are added too,
    /// so the result is the full hull. One case rebuilds from all the points instead: a new
    /// coordinate larger in magnitude than [`coordinate_bound`](super::StrategyHooks::coordinate_bound)
    /// (the range the hull's exact arithmetic is scaled for), or one the scaling would round.
    ///
    /// ```
    /// use pqhull::Hull;
    /// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    /// let mut hull = Hull::try_new(&square)?;
    /// // An inside point changes nothing; (0.5, -0.5) replaces the bottom edge by two.
    /// let added = hull.add_points(&[[0.5, 0.5], [0.5, -0.5]])?;
    /// assert_eq!(added, 4..6);
    /// assert_eq!(hull.vertex_indices(), vec![0, 1, 2, 3, 5]);
    /// assert!((hull.volume() - 1.25).abs() < 1e-15);
    /// hull.check()?;
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`HullError::NonFinite`] for a NaN or infinite coordinate (its index counts the old
    /// points), [`HullError::TooManyPoints`] beyond `u32::MAX` points in all, and, for a hull
    /// with no facets ([`Hull::empty`], or a failed rebuild), what [`Hull::try_new`] gives for
    /// all the points. The hull is unchanged by an error, except an empty one.
    pub fn add_points(&mut self, points: &[[f64; D]]) -> Result<Range<usize>, HullError> {
        self.add_points_with_strategy(points, FarthestPoint::new())
            .map(|(added, ())| added)
    }

    /// As [`add_points`](Self::add_points), then lets `strategy` expand the hull from its
    /// current state (instead of [`FarthestPoint`]): a partial strategy resumes its search with
    /// the new points in play. `ClosestToOrigin` on a
    /// partial hull grown by new points gives the distance it gives on all the points.
    ///
    /// ```
    /// use pqhull::{ClosestToOrigin, Hull};
    /// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    /// let (mut hull, before) = Hull::try_with_strategy(&square, ClosestToOrigin::new())?;
    /// assert!((before.signed_distance - 1.0).abs() < 1e-15);
    /// // A wider square around it: the origin is 2 from its boundary.
    /// let wide = square.map(|p| p.map(|x| 2.0 * x));
    /// let (_, after) = hull.add_points_with_strategy(&wide, ClosestToOrigin::new())?;
    /// assert!((after.signed_distance - 2.0).abs() < 1e-15);
    /// hull.check()?;
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`add_points`](Self::add_points).
    pub fn add_points_with_strategy<S: Strategy<D>>(
        &mut self,
        points: &[[f64; D]],
        strategy: S,
    ) -> Result<(Range<usize>, S::Output), HullError> {
        let old = self.points.len();
        if let Some((index, coordinate)) = first_non_finite(points) {
            return Err(HullError::NonFinite {
                index: old + index,
                coordinate,
            });
        }
        let total = old + points.len();
        if total > u32::MAX as usize {
            // Vertices are stored as u32 (see `initialise`).
            return Err(HullError::TooManyPoints {
                max: u32::MAX as usize,
                got: total,
            });
        }
        if self.live == 0 || !points.iter().all(|p| self.fits(p)) {
            // A coordinate beyond the scaled range (or no hull yet): every point again, scaled
            // anew. Exact, and the same hull; only the work is a rebuild's.
            let mut all: Vec<[f64; D]> = (0..old).map(|i| self.point(i)).collect();
            all.extend_from_slice(points);
            self.initialise(&all, strategy.partitions_to_farthest())?;
            return Ok((old..total, self.run_in_place(strategy)));
        }
        self.trace = None;
        self.partition = if strategy.partitions_to_farthest() {
            Partition::Farthest
        } else {
            Partition::FirstFound
        };
        // The work counters keep counting; the elapsed time covers every call.
        self.started = Instant::now()
            .checked_sub(self.stats.elapsed)
            .unwrap_or_else(Instant::now);
        // A walk locates each new point (see `locate`); one scan of every live facet (the
        // locator's own check, or a point's fallback) costs what a single point's scan does.
        let mut locator = if points.len() > 1 {
            self.locator()
        } else {
            None
        };
        let mut live: Vec<FacetId> = Vec::new();
        for p in points {
            let scaled = p.map(|x| x * self.scale);
            if self.grid.is_some_and(|grid| !grid.contains(&scaled)) {
                self.grid = None; // the certificate covered the old points alone
            }
            let index = self.points.len() as u32;
            self.in_box &= in_box(&scaled);
            self.points.push(scaled);
            let located = locator
                .as_mut()
                .and_then(|locator| self.locate(locator, &scaled));
            match located {
                Some((id, Sign::Positive)) => {
                    let facet = &self.facets[id.index()];
                    let value = facet.filter.value(&scaled).max(0.0);
                    self.push_outside(index, Some((id, value * facet.inv_norm, value)));
                }
                Some(_) => {} // in conv(centre ∪ facet): inside the hull
                None => {
                    if live.is_empty() {
                        live.extend(self.facets().map(|(id, _)| id));
                    }
                    self.assign(index, &live);
                }
            }
        }
        Ok((old..total, self.run_in_place(strategy)))
    }

    /// Lets `strategy` expand this hull from its current state, as if the hull were the one it
    /// had built so far: a partial hull left by one query grows further for another, and a full
    /// hull answers at once. `ClosestToOrigin` resumed on any hull of the points (partial or
    /// full) gives the distance it gives from scratch.
    ///
    /// ```
    /// use pqhull::{ClosestToOrigin, Hull};
    /// let points = pqhull::rbox::generate::<3>(&pqhull::rbox::Family::UniformCube, 500, 1);
    /// let (mut hull, first) = Hull::try_with_strategy(&points, ClosestToOrigin::new())?;
    /// let grown = hull.stats().points_processed;
    /// let second = hull.resume_with_strategy(ClosestToOrigin::towards([0.45, 0.0, 0.0]))?;
    /// let (_, fresh) = Hull::try_with_strategy(&points, ClosestToOrigin::towards([0.45, 0.0, 0.0]))?;
    /// assert_eq!(second.signed_distance, fresh.signed_distance);
    /// assert!(hull.stats().points_processed >= grown); // the hull only grows
    /// # let _ = first;
    /// # Ok::<(), pqhull::HullError>(())
    /// ```
    ///
    /// # Errors
    /// Only for a hull with no facets ([`Hull::empty`], or a failed rebuild): what
    /// [`Hull::try_new`] gives for its points.
    pub fn resume_with_strategy<S: Strategy<D>>(
        &mut self,
        strategy: S,
    ) -> Result<S::Output, HullError> {
        self.add_points_with_strategy(&[], strategy)
            .map(|(_, output)| output)
    }

    /// Whether `p` (caller's units) scales exactly into the range the hull's arithmetic works
    /// in: every coordinate within ±1 once scaled, and none rounded by the scaling.
    fn fits(&self, p: &[f64; D]) -> bool {
        p.iter().all(|&x| {
            let y = x * self.scale;
            y.abs() <= 1.0 && y / self.scale == x
        })
    }
}
