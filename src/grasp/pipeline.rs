//! The one certified evaluation of Q1 and Q∞: a cascade over a [`WrenchSet`], run once for
//! every set and method.
//!
//! Each step runs only when the ones before it cannot decide:
//!
//! 1. **Separation** (the partial method first; the full method after its snapped hull's
//!    certificate): GJK on the raw set's support function. A certified separation means the
//!    grasp is not force closure and gives −(the distance), from support points alone. When GJK
//!    cannot separate, its final simplex may start the hull of step 3 (`Explicit`).
//! 2. **Flatness**: a raw set within [`FLAT`](super::flatness::FLAT) of a hyperplane through the
//!    origin is not force closure; its value comes from the set's own nearest-point routine.
//! 3. **The snapped hull** (partial or full), when the set has a snapped copy: when it holds the
//!    origin strictly inside, the rigorous bracket of [`certify`] on the raw set
//!    gives the value when narrow enough.
//! 4. **The boundary case**: the origin within `δ` of the snapped surface. The raw simplex of the
//!    snapped hull's nearest facet bounds the value from above, the set's outside bound from
//!    below; when both are within [`BOUNDARY`] of the scale, their midpoint is the value.
//! 5. **The exact hull of the raw set** (partial or full): its exact answer; a raw set with no
//!    hull (fewer than six dimensions) is flat and answered as in step 2.
//!
//! The full method is the same cascade with full hulls in steps 3 and 5, so it is exact by the
//! same argument as the partial one; it builds its snapped hull before the separation test so
//! that its cost is a full hull's on every grasp (it is the baseline the partial method is
//! measured against). What differs between the explicit union (Q1), the implicit Minkowski sum
//! (Q∞, partial) and the materialised sum (Q∞, full) is only how each step reaches the points:
//! the [`WrenchSet`] methods.
//!
//! Q_OWS (`grasp/ows/evaluate.rs`) runs the same steps on the same [`Explicit`] set with the
//! disturbances' gauge in place of the unit ball: steps 1 and 2 through the set's methods (no
//! value: not force closure), step 3 with its own search (`OwsInflation`, or brute force) certified
//! by [`bracket_on`], and, when that cannot decide, this cascade for Q1's verdict before its
//! search on the raw wrenches. Its inner value type (`OwsQuality`: `None` when not force
//! closure) is not [`Quality`], which is why it is not one more [`WrenchSet`] caller of
//! [`evaluate`]; both become the one [`Evaluation`](super::Evaluation) at the front door
//! ([`Evaluator`](super::Evaluator)).
//!
//! [`Explicit`]: super::quality::Explicit

use super::certify::{self, Bracket, BracketScratch, Gauge, RawSide, UnitBall, bracket};
use super::flatness::Flatness;
use super::quality::{Quality, QualityError};
use crate::geometry::Gjk;
use crate::strategy::{ClosestToOrigin, DistanceResult};
use crate::{FacetId, Hull, HullError, Strategy};
use std::time::Instant;

/// A boundary grasp's value is settled without the exact engine when its upper and lower bounds
/// are each within this fraction of the scale: their midpoint is then within it of the exact
/// value, half the `1e−14·scale` the metrics promise near zero. (The exact engine on the raw
/// set builds slivers there, facets the floating-point filter cannot decide: far slower than
/// the two bounds, docs/benchmarks.md, "Issue 11".)
pub(in crate::grasp) const BOUNDARY: f64 = 5e-15;

/// How much of the hull a method grows in the cascade's hull steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(in crate::grasp) enum Expansion {
    /// Until the facet nearest the origin is certain ([`ClosestToOrigin`]).
    Partial,
    /// The whole hull, then the nearest facet on it ([`Complete`](crate::strategy::Complete)).
    Full,
}

/// A hull the cascade built, with the nearest-facet search's answer on it; `None` when the
/// points have no hull (fewer than six dimensions, or a snapped hull that failed).
pub(in crate::grasp) type Built<'h> = Option<(&'h Hull<6>, DistanceResult<6>)>;

/// What the cascade needs of a wrench set: the caller's raw wrenches (the numbers every value
/// is exact on), optionally a snapped copy to search on, and the set's own routines for the
/// steps that depend on how its points are held.
pub(in crate::grasp) trait WrenchSet {
    /// The wrench scale: the force-closure band and the accuracy promised near zero are
    /// relative to it.
    fn scale(&self) -> f64;
    /// Step 1: the quality when the raw set is certified not to hold the origin (GJK).
    fn separated(&mut self, gjk: &mut Gjk<6>, started: Instant) -> Option<Quality>;
    /// Step 2: whether the raw set is flat (within rounding of a hyperplane through the origin).
    fn is_flat(&mut self, flatness: &mut Flatness) -> bool;
    /// The value of a flat raw set (step 2, and step 5 when the raw set has no hull).
    ///
    /// # Errors
    /// As the set's evaluation.
    fn flat_value(&mut self, gjk: &mut Gjk<6>, started: Instant) -> Result<Quality, QualityError>;
    /// Step 3: the hull of the snapped copy grown by `expansion` in `hull`'s arena (`nearest`:
    /// the reused strategy for sets held as points). `Ok(None)` when there is no snapped copy or
    /// it has no hull.
    ///
    /// # Errors
    /// When the snapped copy cannot be made (too many points to materialise).
    fn snapped_hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        nearest: &mut ClosestToOrigin<6>,
        expansion: Expansion,
    ) -> Result<Built<'h>, QualityError>;
    /// Step 5: the exact hull of the raw set grown by `expansion`; `Ok(None)` when it has none.
    ///
    /// # Errors
    /// When the raw set cannot be made, or the engine refuses it for a reason other than its
    /// being flat.
    fn raw_hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        nearest: &mut ClosestToOrigin<6>,
        expansion: Expansion,
    ) -> Result<Built<'h>, QualityError>;
    /// The raw wrench behind input `v` of the last hull built (snapped or raw), as computed in
    /// floating point; `None` when unknown.
    fn raw_point(&self, hull: &Hull<6>, v: usize) -> Option<[f64; 6]>;
    /// `(δ, error)`: a bound on the distance between every snapped hull input and its true raw
    /// point, and one on the distance between [`raw_point`](Self::raw_point)'s result and the
    /// true raw point (0 when the raw points are the caller's numbers).
    fn raw_bounds(&self) -> (f64, f64);
    /// The raw set's support function, `max u·w`, and a bound on its rounding.
    fn raw_support(&self, u: &[f64; 6]) -> (f64, f64);
    /// Step 4's lower bound: a quality whose value is at most the metric (at most 0: −(an upper
    /// bound on the distance from the origin to the raw hull)), with the wrenches deciding it;
    /// `None` when the set has none cheaper than its exact hull.
    fn outside_bound(&mut self) -> Option<Quality>;
}

/// The cascade's reusable state: the hull's arena, the explicit sets' partial strategy, GJK's
/// corral, the bracket's scratch and the slab test's workspace.
#[derive(Clone, Debug, Default)]
pub(in crate::grasp) struct Buffers {
    pub(in crate::grasp) hull: Option<Hull<6>>,
    pub(in crate::grasp) nearest: ClosestToOrigin<6>,
    pub(in crate::grasp) gjk: Gjk<6>,
    pub(in crate::grasp) bracket: BracketScratch,
    pub(in crate::grasp) flatness: Flatness,
}

/// The hull of `points` grown by `strategy`, in `hull`'s arena. `flats`, when given, names the
/// contact of every point: each contact's points must lie *exactly* in one 2-D affine plane, as
/// snapped friction pyramids do (see [`Hull::rebuild_with_flats`]). `keep_coplanar`: see
/// `Hull::keep_coplanar_facets` (only for a hull read for its facets' planes alone).
///
/// # Errors
/// As [`Hull::rebuild_with_strategy`].
pub(in crate::grasp) fn build_hull<'h, S: Strategy<6>>(
    hull: &'h mut Option<Hull<6>>,
    points: &[[f64; 6]],
    flats: Option<&[u32]>,
    strategy: S,
    keep_coplanar: bool,
) -> Result<(&'h Hull<6>, S::Output), HullError> {
    let h = hull.get_or_insert_with(Hull::empty);
    h.keep_coplanar_facets(keep_coplanar);
    let output = match flats {
        Some(contact_of) => h.rebuild_with_trusted_flats(points, contact_of, 2, strategy)?,
        None => h.rebuild_with_strategy(points, strategy)?,
    };
    Ok((h, output))
}

/// The metric of `set` by the cascade (see the [module docs](self)), banded under the set's
/// scale; `started` is when the evaluation began (for the stats of steps that build no hull).
///
/// # Errors
/// As the set's steps.
pub(in crate::grasp) fn evaluate<W: WrenchSet>(
    set: &mut W,
    expansion: Expansion,
    buffers: &mut Buffers,
    started: Instant,
) -> Result<Quality, QualityError> {
    let scale = set.scale();
    let quality = cascade(set, expansion, buffers, started)?;
    Ok(quality.banded(scale))
}

fn cascade<W: WrenchSet>(
    set: &mut W,
    expansion: Expansion,
    buffers: &mut Buffers,
    started: Instant,
) -> Result<Quality, QualityError> {
    let Buffers {
        hull,
        nearest,
        gjk,
        bracket: scratch,
        flatness,
    } = buffers;
    if expansion == Expansion::Partial
        && let Some(quality) = set.separated(gjk, started)
    {
        return Ok(quality);
    }
    if set.is_flat(flatness) {
        return set.flat_value(gjk, started);
    }
    let snapped = set.snapped_hull(hull, nearest, expansion)?;
    if let Some((h, result)) = &snapped
        && result.signed_distance > 0.0
        && let Some(quality) = certified(set, h, scratch)
    {
        return Ok(quality);
    }
    if expansion == Expansion::Full
        && let Some(mut quality) = set.separated(gjk, started)
    {
        // The full hull's work, whichever step gives the value.
        if let Some((h, _)) = &snapped {
            quality.stats = h.stats();
        }
        return Ok(quality);
    }
    if let Some((h, result)) = &snapped
        && let Some(quality) = boundary(set, h, result.closest_facet)
    {
        return Ok(quality);
    }
    match set.raw_hull(hull, nearest, expansion)? {
        Some((h, result)) => {
            let deciding = result.closest_facet_vertices.iter();
            let deciding = deciding.filter_map(|&v| set.raw_point(h, v));
            let quality = Quality::new(result.signed_distance, deciding, result.stats);
            Ok(quality.with_ties(h, result.closest_facet, set.scale(), 0.0, None))
        }
        None => set.flat_value(gjk, started),
    }
}

/// The bracket's side of the raw set `$set` for the hull `$hull`, for [`certify`]'s functions.
/// `$widen` is added to `δ`.
macro_rules! raw_side {
    ($set:expr, $hull:expr, $widen:expr) => {{
        let (set, hull) = ($set, $hull);
        let (delta, error) = set.raw_bounds();
        RawSide {
            point: move |v: usize| set.raw_point(hull, v),
            error,
            delta: delta + $widen,
            support: move |u: &[f64; 6]| set.raw_support(u),
        }
    }};
}

/// The rigorous bracket of the metric of `gauge` on `set`'s raw points from `hull`, a hull of
/// its snapped copy holding the origin strictly inside ([`certify::bracket`]); `widen` is added
/// to the snapping bound `δ` (Q_OWS asks the surface to keep the raw Q1 above the force-closure
/// band too). The step-3 certificate of every metric: Q1 and Q∞ with the unit ball, Q_OWS with
/// the disturbances.
pub(in crate::grasp) fn bracket_on<W: WrenchSet, G: Gauge>(
    set: &W,
    hull: &Hull<6>,
    gauge: &mut G,
    widen: f64,
    scratch: &mut BracketScratch,
) -> Option<Bracket> {
    bracket(hull, &mut raw_side!(set, hull, widen), gauge, scratch)
}

/// Step 3: the metric of the raw set from `hull`, a snapped hull holding the origin strictly
/// inside, when the certified bracket is narrow enough.
fn certified<W: WrenchSet>(
    set: &W,
    hull: &Hull<6>,
    scratch: &mut BracketScratch,
) -> Option<Quality> {
    let b = bracket_on(set, hull, &mut UnitBall, 0.0, scratch)?;
    let scale = set.scale();
    let value = b.value_within(scale)?;
    let vertices = hull.facet(b.facet).vertices();
    let deciding = vertices.iter().filter_map(|&v| set.raw_point(hull, v));
    let quality = Quality::new(value, deciding, hull.stats());
    let (delta, error) = set.raw_bounds();
    Some(quality.with_ties(hull, b.facet, scale, delta + error, Some(&*scratch)))
}

/// Step 4: the value of a boundary grasp — the origin within `δ` of the snapped hull's facet
/// `id`, where the bracket has no lower bound — from the raw simplex of that facet (an upper
/// bound, [`certify::upper_bound_at`]) and the set's outside bound, when both are within
/// [`BOUNDARY`] of the scale: their midpoint, never force closure.
fn boundary<W: WrenchSet>(set: &mut W, hull: &Hull<6>, id: FacetId) -> Option<Quality> {
    let scale = set.scale();
    let high = certify::upper_bound_at(hull, id, &mut raw_side!(&*set, hull, 0.0), &mut UnitBall)?;
    if high > BOUNDARY * scale {
        return None;
    }
    let mut low = set.outside_bound()?;
    if -low.value > BOUNDARY * scale {
        return None;
    }
    low.value = 0.5 * (high.max(low.value) + low.value);
    low.stats = hull.stats();
    Some(low)
}
