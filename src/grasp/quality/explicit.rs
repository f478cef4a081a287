//! Q1's wrench set for the cascade: the explicit union of the caller's wrenches, with or without
//! a snapped copy to search on.

use super::{Quality, QualityError, certified_outside, degenerate, no_hull_stats};
use crate::geometry::{Gjk, largest_norm, min_norm_point, min_norm_point_accurate};
use crate::grasp::certify::support_with_error;
use crate::grasp::flatness::{FLAT, Flatness};
use crate::grasp::pipeline::{Built, Expansion, WrenchSet, build_hull};
use crate::strategy::{ClosestToOrigin, Complete};
use crate::{Hull, HullError};
use std::time::Instant;

/// A Q1 wrench set: the caller's raw wrenches and, optionally, the snapped ones the search runs
/// on (same indexing), each contact's pyramid an exact 2-D flat, within `delta` of the raw ones.
pub(in crate::grasp) struct Explicit<'a> {
    raw: &'a [[f64; 6]],
    snapped: Option<Snapped<'a>>,
    scale: f64,
    /// The simplex GJK ended with when it could not separate (7 wrenches around the origin,
    /// indices into `raw`), for the hulls to start from.
    start: Option<[usize; 7]>,
}

/// The snapped wrenches, the contact of each (its pyramid, an exact flat) and `δ`.
#[derive(Clone, Copy)]
struct Snapped<'a> {
    points: &'a [[f64; 6]],
    pyramids: &'a [u32],
    delta: f64,
}

impl<'a> Explicit<'a> {
    /// The caller's wrenches `raw`, searched as they are (exact on exactly these numbers).
    pub(in crate::grasp) fn raw(raw: &'a [[f64; 6]]) -> Self {
        Explicit {
            raw,
            snapped: None,
            scale: largest_norm(raw),
            start: None,
        }
    }

    /// The caller's wrenches `raw`, searched on their snapped copy `snapped` (same indexing;
    /// `pyramids` names each wrench's contact; within `delta` of the raw ones).
    pub(in crate::grasp) fn snapped(
        raw: &'a [[f64; 6]],
        snapped: &'a [[f64; 6]],
        pyramids: &'a [u32],
        delta: f64,
    ) -> Self {
        Explicit {
            raw,
            snapped: Some(Snapped {
                points: snapped,
                pyramids,
                delta,
            }),
            scale: largest_norm(raw),
            start: None,
        }
    }
}

impl<'a> Explicit<'a> {
    /// The caller's wrenches.
    pub(in crate::grasp) fn raw_wrenches(&self) -> &'a [[f64; 6]] {
        self.raw
    }

    /// Asks the next build in `hull`'s arena to start from the simplex GJK ended with (seven
    /// wrenches around the origin), when [`WrenchSet::separated`] left one: a partial search
    /// then starts with the origin inside (measured: 20 % fewer facets for force-closure Q1 at
    /// 4 × 8 edges, 9 % at 4 × 32; `cli/examples/profile_q1.rs`).
    pub(in crate::grasp) fn start_hull(&self, hull: &mut Option<Hull<6>>) {
        if let Some(start) = &self.start {
            hull.get_or_insert_with(Hull::empty)
                .start_next_build_from(start);
        }
    }

    /// The snapped copy, when there is one: its points and the contact of each.
    pub(in crate::grasp) fn snapped_copy(&self) -> Option<(&'a [[f64; 6]], &'a [u32])> {
        self.snapped.map(|s| (s.points, s.pyramids))
    }
}

/// The hull of `points` grown by `expansion` in `hull`'s arena; `flats`, when given, names the
/// contact of every point, each contact's points lying *exactly* in one 2-D affine plane (see
/// [`build_hull`]). `Ok(None)` when the points span fewer than six dimensions.
pub(in crate::grasp) fn nearest_hull<'h>(
    hull: &'h mut Option<Hull<6>>,
    points: &[[f64; 6]],
    flats: Option<&[u32]>,
    nearest: &mut ClosestToOrigin<6>,
    expansion: Expansion,
) -> Result<Built<'h>, HullError> {
    // The full hull is read for its nearest facet alone: its coplanar facets may stay
    // (`Hull::keep_coplanar_facets`), which on a snapped Minkowski sum saves most of the build.
    // The partial hull keeps the default.
    let built = match expansion {
        Expansion::Partial => build_hull(hull, points, flats, nearest, false),
        Expansion::Full => build_hull(hull, points, flats, Complete::new(nearest), true),
    };
    match built {
        Ok(built) => Ok(Some(built)),
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => Ok(None),
        Err(e) => Err(e),
    }
}

/// The least barycentric weight of the origin in GJK's final simplex for the hulls to start
/// from it ([`simplex_indices`]).
const START_WEIGHT: f64 = 1e-3;

/// Whether the seven points of `face` (GJK's final simplex) hold the origin with every
/// barycentric weight at least [`START_WEIGHT`]. Only such a simplex is a good start: one that
/// holds it by a hair (a grasp within rounding of the boundary, which GJK calls touching) starts
/// the search among slivers around the origin (measured at 4 × 32 edges: 2.2× the facets on the
/// grasps that are not force closure and reach the hull; at a weight of 1e−3, none lost).
pub(in crate::grasp) fn holds_the_origin_well(face: &[[f64; 6]]) -> bool {
    face.len() == 7
        && crate::geometry::origin_weights(face)
            .is_some_and(|w| w[..7].iter().all(|&w| w >= START_WEIGHT))
}

/// The indices in `points` of the seven points of `face` (a GJK simplex), when it has seven and
/// holds the origin with every barycentric weight at least [`START_WEIGHT`].
fn simplex_indices(points: &[[f64; 6]], face: &[[f64; 6]]) -> Option<[usize; 7]> {
    if face.len() != 7 {
        return None;
    }
    if !holds_the_origin_well(face) {
        return None;
    }
    let mut indices = [0; 7];
    for (i, p) in indices.iter_mut().zip(face) {
        *i = points.iter().position(|q| q == p)?;
    }
    Some(indices)
}

impl WrenchSet for Explicit<'_> {
    fn scale(&self) -> f64 {
        self.scale
    }

    fn separated(&mut self, gjk: &mut Gjk<6>, started: Instant) -> Option<Quality> {
        let Some((distance, inserted)) = certified_outside(self.raw, gjk) else {
            self.start = simplex_indices(self.raw, gjk.face());
            return None;
        };
        let stats = no_hull_stats(1 + inserted, started);
        Some(Quality::new(-distance, gjk.face().iter().copied(), stats))
    }

    fn is_flat(&mut self, flatness: &mut Flatness) -> bool {
        flatness.within(self.raw.iter().copied(), FLAT * self.scale)
    }

    fn flat_value(&mut self, _: &mut Gjk<6>, started: Instant) -> Result<Quality, QualityError> {
        Ok(degenerate(self.raw, started))
    }

    fn snapped_hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        nearest: &mut ClosestToOrigin<6>,
        expansion: Expansion,
    ) -> Result<Built<'h>, QualityError> {
        let Some(s) = self.snapped else {
            return Ok(None);
        };
        self.start_hull(hull);
        // A snapped hull the engine refuses leaves the raw one to decide.
        Ok(nearest_hull(hull, s.points, Some(s.pyramids), nearest, expansion).unwrap_or(None))
    }

    fn raw_hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        nearest: &mut ClosestToOrigin<6>,
        expansion: Expansion,
    ) -> Result<Built<'h>, QualityError> {
        nearest_hull(hull, self.raw, None, nearest, expansion).map_err(QualityError::Hull)
    }

    fn raw_point(&self, _: &Hull<6>, v: usize) -> Option<[f64; 6]> {
        self.raw.get(v).copied()
    }

    fn raw_bounds(&self) -> (f64, f64) {
        (self.snapped.map_or(0.0, |s| s.delta), 0.0)
    }

    fn raw_support(&self, u: &[f64; 6]) -> (f64, f64) {
        support_with_error(self.raw, u)
    }

    fn outside_bound(&mut self) -> Option<Quality> {
        // −(the distance from the origin to the hull), by Wolfe's algorithm with the accurate
        // residual (plain floating point leaves ~1e−14 of the scale here).
        let raw = self.raw;
        let rough = min_norm_point(raw.len(), |i| raw[i], &[0.0; 6]);
        let nearest = min_norm_point_accurate(raw.len(), |i| raw[i], &[0.0; 6], rough.support());
        // Its accuracy: 1e−15 of itself plus 1e−30 of the set's size; rounded up generously.
        let distance = nearest.distance * (1.0 + 1e-14) + 1e-28 * self.scale;
        let face = nearest.support().iter().map(|&i| raw[i]);
        Some(Quality::new(
            -distance,
            face,
            crate::strategy::Stats::default(),
        ))
    }
}
