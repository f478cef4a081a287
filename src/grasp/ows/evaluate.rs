//! Evaluating Q_OWS: the partial hull (PQHOWS), brute force, and Borst et al.'s ellipsoid.

use super::ObjectWrenchSpace;
use crate::geometry::vector::dot;
use crate::geometry::{Gjk, SupportIndex};
use crate::grasp::Grasp;
use crate::grasp::certify::{BracketScratch, Disturbances, candidates};
use crate::grasp::evaluation::Evaluation;
use crate::grasp::flatness::Flatness;
use crate::grasp::pipeline::{self, Buffers, Expansion, WrenchSet, build_hull};
use crate::grasp::quality::ties::on_other_planes;
use crate::grasp::quality::{
    Explicit, FORCE_CLOSURE_EPSILON, Method, Metric, QualityError, check_wrenches, find_or_make,
    q1_quality_of_wrenches,
};
use crate::grasp::snap::{SnappedCones, pyramid_labels, snapped_union};
use crate::hull::{FacetId, Hull, HullError};
use crate::predicates::Sign;
use crate::strategy::{OwsInflation, Stats, exact_factor, factor_lower_bound};
use std::time::Instant;

/// Q_OWS of one grasp inside the grasp layer; what callers get is its [`Evaluation`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::grasp) struct OwsQuality {
    /// Whether the grasp wrench space holds the origin strictly inside (decided exactly).
    pub force_closure: bool,
    /// Q_OWS (the ellipsoid method's approximation of it); `None` when not force closure.
    pub value: Option<f64>,
    /// The disturbance whose inflation decides the value (exact methods only).
    pub deciding_disturbance: Option<usize>,
    /// Whether another facet, on another plane, gives the value too (within 1e−9 of it, plus
    /// the snapping's share on a snapped hull): Q_OWS is then a minimum of two smooth
    /// functions of the grasp, not differentiable ([`ows_gradient`](crate::grasp::ows_gradient)
    /// says so). Seen on the hull the value came from, by the partial hull (a partial hull's tie
    /// is the full hull's, as for Q1's `Quality::tied`) and by brute force; `false` for
    /// `PartialRays` (kept as published) and the ellipsoid.
    pub tied: bool,
    /// Work done by the grasp's hull (the ellipsoid method: by its Q1 hull).
    pub stats: Stats,
}

impl OwsQuality {
    /// The caller's view: its [`Evaluation`] as `metric` (Q_OWS or wrench resistance) by
    /// `method`.
    pub(in crate::grasp) fn into_evaluation(self, metric: Metric, method: Method) -> Evaluation {
        let mut evaluation =
            Evaluation::new(metric, method, self.force_closure, self.value, self.stats)
                .with_tie(self.tied);
        evaluation.deciding_disturbance = self.deciding_disturbance;
        evaluation
    }
}

/// `(approximate − exact) / exact`: negative when the approximation underestimates.
pub fn relative_error(approximate: f64, exact: f64) -> f64 {
    (approximate - exact) / exact
}

/// Evaluates Q_OWS by one method over many grasps, reusing its wrench buffer: the engine behind
/// [`Evaluator`](crate::grasp::Evaluator) for Q_OWS and wrench resistance.
#[derive(Clone, Debug, Default)]
pub(in crate::grasp) struct OwsEvaluator {
    method: Method,
    wrenches: Vec<[f64; 6]>,
    /// The snapped cone generators behind `wrenches`.
    cones: SnappedCones,
    /// The contact of every wrench (its friction pyramid, an exact flat for the hull engine).
    pyramids: Vec<u32>,
    buffers: OwsBuffers,
}

/// What an [`OwsEvaluator`] reuses from grasp to grasp.
#[derive(Clone, Debug, Default)]
struct OwsBuffers {
    /// The grasp hull's arena.
    hull: Option<Hull<6>>,
    /// GJK's corral, for grasps it settles without a hull.
    gjk: Gjk<6>,
    /// The partial method's strategy, parked between grasps (its queue and scratch).
    inflation: OwsInflation<'static, 6>,
    /// The certificate's scratch.
    bracket: BracketScratch,
    /// The slab test's workspace.
    flatness: Flatness,
    /// Q1's buffers, for the verdict when the OWS certificate cannot decide.
    q1: Buffers,
}

impl OwsEvaluator {
    /// An evaluator using `method`.
    pub(in crate::grasp) fn new(method: Method) -> Self {
        OwsEvaluator {
            method,
            wrenches: Vec::new(),
            cones: SnappedCones::default(),
            pyramids: Vec::new(),
            buffers: OwsBuffers::default(),
        }
    }

    /// Q_OWS of `grasp` against `space`. The grasp's wrenches are snapped as for Q1 (see
    /// [`Grasp::snapped_wrenches_into`]); for a space built from a mesh the grasp must use the
    /// mesh's torque frame ([`ObjectWrenchSpace::frame`]).
    ///
    /// # Errors
    /// [`QualityError::TorqueFrameMismatch`] when the grasp's torque reference or scale differ
    /// from the space's; [`QualityError::NonFiniteWrench`]; [`QualityError::Ellipsoid`] when the
    /// ellipsoid method meets disturbances spanning fewer than six dimensions.
    pub(in crate::grasp) fn evaluate(
        &mut self,
        grasp: &Grasp,
        space: &ObjectWrenchSpace,
    ) -> Result<OwsQuality, QualityError> {
        if let Some((c, rho)) = space.torque_frame()
            && (grasp.torque_reference() != c || grasp.torque_scale() != rho)
        {
            return Err(QualityError::TorqueFrameMismatch {
                grasp: (grasp.torque_reference(), grasp.torque_scale()),
                space: (c, rho),
            });
        }
        let started = Instant::now();
        // As `Grasp::snapped_wrenches_into`, in this evaluator's buffers.
        self.cones.fill(grasp);
        check_wrenches(&self.cones.raw)?;
        if !self.cones.is_finite() {
            return Err(QualityError::NonFiniteWrench);
        }
        snapped_union(&self.cones, &mut self.wrenches);
        let edges = grasp.friction().cone_edges();
        pyramid_labels(self.cones.contacts(), edges, &mut self.pyramids);
        let delta = self.cones.delta.iter().fold(0.0, |m: f64, &d| m.max(d));
        let mut set = Explicit::snapped(&self.cones.raw, &self.wrenches, &self.pyramids, delta);
        let mut quality = ows_with(&mut set, space, self.method, &mut self.buffers, started)?;
        quality.stats.elapsed = started.elapsed();
        Ok(quality)
    }
}

/// Q_OWS of an explicit grasp wrench set (exact on exactly these numbers) against `space`.
///
/// # Errors
/// [`QualityError::NonFiniteWrench`] for a NaN or infinite coordinate;
/// [`QualityError::WrenchTooLarge`] above
/// [`MAX_WRENCH_COORDINATE`](crate::grasp::quality::MAX_WRENCH_COORDINATE); [`QualityError::Ellipsoid`].
pub fn ows_of_wrenches(
    wrenches: &[[f64; 6]],
    space: &ObjectWrenchSpace,
    method: Method,
) -> Result<Evaluation, QualityError> {
    let started = Instant::now();
    let mut set = Explicit::raw(wrenches);
    let mut quality = ows_with(&mut set, space, method, &mut OwsBuffers::default(), started)?;
    quality.stats.elapsed = started.elapsed();
    Ok(quality.into_evaluation(Metric::Ows, method))
}

fn not_force_closure(stats: Stats) -> OwsQuality {
    OwsQuality {
        force_closure: false,
        value: None,
        deciding_disturbance: None,
        tied: false,
        stats,
    }
}

/// [`ows_inner`], with a value beyond `f64::MAX` (disturbances tiny beside the grasp's wrenches,
/// say 1e−310 against 1) an error rather than +∞, which JSON would print as null.
fn ows_with(
    set: &mut Explicit<'_>,
    space: &ObjectWrenchSpace,
    method: Method,
    buffers: &mut OwsBuffers,
    started: Instant,
) -> Result<OwsQuality, QualityError> {
    let quality = ows_inner(set, space, method, buffers, started)?;
    match quality.value {
        Some(v) if !v.is_finite() => Err(QualityError::OwsValueOverflow),
        _ => Ok(quality),
    }
}

/// Q_OWS by the grasp cascade's steps ([`pipeline`]) with the
/// disturbances' gauge: the separation and slab tests of the wrench set (no value: not force
/// closure); the search on the snapped wrenches, certified on the raw ones by the same bracket
/// as Q1's; failing that, Q1's cascade for the verdict, then the search on the caller's own
/// numbers.
fn ows_inner(
    set: &mut Explicit<'_>,
    space: &ObjectWrenchSpace,
    method: Method,
    buffers: &mut OwsBuffers,
    started: Instant,
) -> Result<OwsQuality, QualityError> {
    if !method.supports(Metric::Ows) {
        return Err(QualityError::UnsupportedMethod {
            method,
            metric: Metric::Ows,
        });
    }
    let raw = set.raw_wrenches();
    check_wrenches(raw)?;
    if raw.is_empty() {
        return Ok(not_force_closure(Stats::default()));
    }
    // A grasp GJK certifies not force closure has no OWS value: no hull needed. (Not for
    // `PartialRays`, kept as published for comparison.)
    if method == Method::Partial && set.separated(&mut buffers.gjk, started).is_some() {
        return Ok(not_force_closure(Stats::default()));
    }
    // Wrenches within rounding of a hyperplane through the origin: Q1 at most the slab's
    // half-width, far below the force-closure band (see `grasp::flatness`).
    if set.is_flat(&mut buffers.flatness) {
        return Ok(not_force_closure(Stats::default()));
    }
    if method == Method::Ellipsoid {
        return ellipsoid(raw, space);
    }
    if let Some((snapped, pyramids)) = set.snapped_copy() {
        // The search on the snapped wrenches, its answer certified on the raw ones.
        set.start_hull(&mut buffers.hull);
        let found = search(snapped, Some(pyramids), space, method, buffers)?;
        if let Some(quality) = found
            && let Some(hull) = buffers.hull.as_ref()
            && let Some((value, tied)) = certify_ows(set, hull, space, &mut buffers.bracket)
        {
            return Ok(OwsQuality {
                value: Some(value),
                tied,
                ..quality
            });
        }
    }
    // Force closure under the band from Q1 (certified on the snapped search when there is one:
    // the exact engine alone builds slivers on boundary grasps), then the search on exactly
    // the caller's numbers.
    let q1 = match set.snapped_copy() {
        Some(_) => pipeline::evaluate(set, Expansion::Partial, &mut buffers.q1, started)?,
        // In the wrenches' own unit, as Q1 of an explicit set is evaluated.
        None => q1_quality_of_wrenches(raw, Method::Partial)?,
    };
    if !q1.force_closure {
        return Ok(not_force_closure(q1.stats));
    }
    match search(raw, None, space, method, buffers)? {
        Some(quality) => Ok(quality),
        // The exact engine says the origin is not strictly inside, which Q1 contradicts only
        // within rounding of the band: no value to give.
        None => Ok(not_force_closure(q1.stats)),
    }
}

/// Q_OWS of the wrench set `w` by `method` (partial or brute force), with the hull left in
/// `buffers.hull`: the quality when the origin is strictly inside.
fn search(
    w: &[[f64; 6]],
    pyramids: Option<&[u32]>,
    space: &ObjectWrenchSpace,
    method: Method,
    buffers: &mut OwsBuffers,
) -> Result<Option<OwsQuality>, QualityError> {
    // Ties on the caller's own wrenches only: on snapped ones the certified value's bracket
    // looks for them (`certify_ows`), and this pass would be wasted on the hot path.
    let ties = pyramids.is_none().then(|| space.support_index());
    let result = match method {
        Method::Partial => {
            let parked = std::mem::take(&mut buffers.inflation);
            let mut strategy = parked.rebind_index(space.support_index());
            let result = partial(w, pyramids, &mut strategy, &mut buffers.hull, ties);
            buffers.inflation = strategy.park();
            result
        }
        Method::PartialRays => partial(
            w,
            pyramids,
            OwsInflation::with_rays(space.disturbances()),
            &mut buffers.hull,
            None,
        ),
        Method::Full => brute_force(w, pyramids, space, &mut buffers.hull),
        // Refused by `ows_inner` before any hull is built.
        Method::Ellipsoid | Method::Qhull => {
            return Err(QualityError::UnsupportedMethod {
                method,
                metric: Metric::Ows,
            });
        }
    };
    Ok(result?.filter(|q| q.force_closure))
}

/// Q_OWS of the raw wrenches from `hull`, the snapped wrenches' hull holding the origin strictly
/// inside, when the certified bracket is narrow enough and the surface keeps the raw Q1 above
/// the force-closure band (see [`crate::grasp::certify`]); and whether another facet ties with
/// the deciding one ([`OwsQuality::tied`]).
fn certify_ows(
    set: &Explicit<'_>,
    hull: &Hull<6>,
    space: &ObjectWrenchSpace,
    scratch: &mut BracketScratch,
) -> Option<(f64, bool)> {
    let mut gauge = Disturbances {
        index: space.support_index(),
    };
    let widen = FORCE_CLOSURE_EPSILON * set.scale();
    let b = pipeline::bracket_on(set, hull, &mut gauge, widen, scratch)?;
    let (delta, _) = set.raw_bounds();
    let value = b.value_within(b.high.abs())?;
    // Snapping moves a facet's distance by up to δ, its factor by δ/g (g the disturbances'
    // rate against it): relative `2δ/distance` between two facets, on top of the band.
    let distance = -hull.signed_distance(b.facet, &[0.0; 6]);
    let slack = 2.0 * delta / distance;
    let limit = b.high * (1.0 + 2.0 * (TIE_BAND + slack));
    let index = space.support_index();
    let tied = tied_factor(hull, b.facet, slack, candidates(scratch, limit), index);
    Some((value, tied))
}

/// Whether a facet among `candidates`, on another plane than `deciding`, has an exact factor
/// (see [`exact_factor`]) within `TIE_BAND + slack` (relative) of `deciding`'s on `hull`, the
/// disturbances' support answered by `index`. A precise facet (normal and offset within 1e−11
/// of the exact ones) is screened first by the ball tree's cheap bound, then by its
/// floating-point factor: the exact planes are computed only for the few that may tie.
fn tied_factor(
    hull: &Hull<6>,
    deciding: FacetId,
    slack: f64,
    mut candidates: impl Iterator<Item = FacetId>,
    index: &SupportIndex<6>,
) -> bool {
    let support = |toward: &[f64; 6]| index.support(toward);
    let Some((own, _)) = exact_factor(hull, deciding, support) else {
        return false;
    };
    // The screens' own slack: 1e−9 covers the floating-point factors' error.
    let limit = own * (1.0 + TIE_BAND + slack);
    let screen = limit * (1.0 + 1e-9);
    candidates.any(|id| {
        if id == deciding {
            return false;
        }
        let facet = hull.facet(id);
        if facet.normal_is_precise() {
            let toward = facet.normal().map(|c| -c);
            if facet.offset() > screen * index.upper_bound(&toward, CHEAP_DEPTH) {
                return false;
            }
            match support(&toward) {
                Some((h, _)) if h > 0.0 && facet.offset() <= screen * h => {}
                _ => return false,
            }
        }
        on_other_planes(hull, id, deciding)
            && exact_factor(hull, id, support).is_some_and(|(f, _)| f <= limit)
    })
}

/// Depth of the ball-tree nodes whose bound screens a facet in [`tied_factor`] (as the
/// certification's cheap bound).
const CHEAP_DEPTH: usize = 5;

/// Another facet's factor within this fraction of the value is a tie ([`OwsQuality::tied`]),
/// as for Q1 (`Quality::tied`).
const TIE_BAND: f64 = 1e-9;

/// Q_OWS by the partial hull of `wrenches` (the caller's, or snapped ones), with ties looked
/// for among its facets when `support` (the disturbances' support) is given.
fn partial<S: crate::Strategy<6, Output = crate::strategy::OwsResult<6>>>(
    wrenches: &[[f64; 6]],
    pyramids: Option<&[u32]>,
    strategy: S,
    hull: &mut Option<Hull<6>>,
    ties: Option<&SupportIndex<6>>,
) -> Result<Option<OwsQuality>, QualityError> {
    match build_hull(hull, wrenches, pyramids, strategy, false) {
        Ok((h, result)) => Ok(Some(OwsQuality {
            // The strategy has a value exactly when the origin is strictly inside the hull.
            force_closure: result.value.is_some(),
            value: result.value,
            deciding_disturbance: result.deciding_disturbance,
            // A partial hull's facets are nowhere beyond the full hull's, and its deciding
            // facet is certain: a tie of the full hull is one of its facets (as for Q1).
            tied: match (ties, result.deciding_facet) {
                (Some(index), Some(facet)) if result.value.is_some_and(f64::is_finite) => {
                    tied_factor(h, facet, 0.0, h.facets().map(|(id, _)| id), index)
                }
                _ => false,
            },
            stats: result.stats,
        })),
        // Wrenches spanning fewer than six dimensions cannot hold the origin in their interior.
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => Ok(None),
        Err(e) => Err(QualityError::Hull(e)),
    }
}

fn brute_force(
    wrenches: &[[f64; 6]],
    pyramids: Option<&[u32]>,
    space: &ObjectWrenchSpace,
    hull: &mut Option<Hull<6>>,
) -> Result<Option<OwsQuality>, QualityError> {
    let hull = match build_hull(hull, wrenches, pyramids, crate::FarthestPoint::new(), false) {
        Ok((hull, ())) => hull,
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
            return Ok(None);
        }
        Err(e) => return Err(QualityError::Hull(e)),
    };
    let stats = hull.stats();
    let origin = [0.0; 6];
    if hull
        .facets()
        .any(|(id, _)| hull.side_of(id, &origin) != Sign::Negative)
    {
        return Ok(Some(not_force_closure(stats)));
    }
    // eq. 8–9: each disturbance's ray leaves through the facet with the smallest factor, so the
    // answer is the smallest factor of any disturbance against any facet. The floating-point
    // factors only order the facets (by lower bounds); the answer is the smallest key from an
    // exact plane, taken once no other facet's lower bound is below it.
    let disturbances = space.disturbances();
    let reach = disturbances
        .iter()
        .map(|d| dot(*d, *d).sqrt())
        .fold(0.0, f64::max);
    let largest_rate = |n: &[f64; 6]| {
        disturbances
            .iter()
            .enumerate()
            .map(|(i, d)| (-dot(*n, *d), i))
            .max_by(|a, b| a.0.total_cmp(&b.0))
    };
    let mut bounds: Vec<(f64, FacetId)> = hull
        .facets()
        .filter_map(|(id, facet)| {
            let (rate, _) = largest_rate(&facet.normal())?;
            factor_lower_bound(hull, facet.offset(), rate, reach).map(|low| (low, id))
        })
        .collect();
    bounds.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut best: Option<(f64, usize)> = None;
    // Every exact factor within the tie band of the best so far, with its facet.
    let mut near: Vec<(f64, FacetId)> = Vec::new();
    for (low, id) in bounds {
        if best.is_some_and(|(b, _)| low > b * (1.0 + TIE_BAND)) {
            break;
        }
        // `toward` is −n: the largest rate is max_d (−n)·d.
        let exact = exact_factor(hull, id, |toward| {
            disturbances
                .iter()
                .enumerate()
                .map(|(i, d)| (dot(*toward, *d), i))
                .max_by(|a, b| a.0.total_cmp(&b.0))
        });
        if let Some((r, i)) = exact {
            near.push((r, id));
            if best.is_none_or(|(b, _)| r < b) {
                best = Some((r, i));
            }
        }
    }
    let value = best.map_or(f64::INFINITY, |(r, _)| r);
    let within = |r: f64| r <= value * (1.0 + TIE_BAND);
    let deciding = near.iter().find(|(r, _)| *r == value).map(|&(_, id)| id);
    let tied = deciding.is_some_and(|d| {
        near.iter()
            .any(|&(r, id)| id != d && within(r) && on_other_planes(hull, id, d))
    });
    Ok(Some(OwsQuality {
        force_closure: true,
        value: Some(value),
        deciding_disturbance: best.map(|(_, i)| i),
        tied,
        stats,
    }))
}

/// Borst et al.'s approximation: Q1 of the wrenches mapped so that the disturbances' ellipsoid
/// is the unit ball.
///
/// The force-closure verdict is the grasp's own, decided on its unmapped wrenches. The map is
/// linear and invertible, so in exact arithmetic it cannot move the origin into or out of the
/// hull's interior; in floating point it can: a rank-5 set (two antipodal hard fingers) maps to a
/// sliver of full rank that holds the origin within rounding, which Q1 of the mapped set called
/// force closure with the value `f64::MIN_POSITIVE`. So the mapped set only gives the number, and
/// only for a force-closure grasp; a mapped Q1 that is then no positive number is an error, never
/// a value.
fn ellipsoid(wrenches: &[[f64; 6]], space: &ObjectWrenchSpace) -> Result<OwsQuality, QualityError> {
    let ellipsoid = space
        .ellipsoid()
        .map_err(|e| QualityError::Ellipsoid(e.clone()))?;
    let own = q1_quality_of_wrenches(wrenches, Method::Partial)?;
    if !own.force_closure {
        return Ok(not_force_closure(own.stats));
    }
    let mapped: Vec<[f64; 6]> = wrenches.iter().map(|w| ellipsoid.map(w)).collect();
    let q1 = q1_quality_of_wrenches(&mapped, Method::Partial)?;
    // `MIN_POSITIVE` (or less) was Q1's stand-in for "strictly inside, within rounding of a
    // facet": not a measurement, whatever Q1's force-closure band says.
    if !(q1.force_closure && q1.value > f64::MIN_POSITIVE && q1.value.is_finite()) {
        return Err(QualityError::EllipsoidBoundary {
            mapped_q1: q1.value,
        });
    }
    // The work of both hulls: the verdict's and the value's.
    let stats = own.stats + q1.stats;
    Ok(OwsQuality {
        force_closure: true,
        value: Some(q1.value),
        deciding_disturbance: None,
        tied: false,
        stats,
    })
}

/// Q_OWS of every grasp against `space`, results in input order (on all cores with the
/// `parallel` feature, a default); the space is shared, not copied. Each worker thread keeps one
/// [`OwsEvaluator`] per method for the life of the thread, as the Q1 and Q∞ batch does.
pub(in crate::grasp) fn evaluate_ows_batch(
    grasps: &[Grasp],
    space: &ObjectWrenchSpace,
    method: Method,
) -> Vec<Result<OwsQuality, QualityError>> {
    crate::grasp::map_in_order(grasps, |grasp| {
        OWS_EVALUATORS.with_borrow_mut(|kept| {
            find_or_make(kept, |e| e.method == method, || OwsEvaluator::new(method))
                .evaluate(grasp, space)
        })
    })
}

thread_local! {
    /// The evaluators of [`evaluate_ows_batch`] on this thread, one per method used.
    static OWS_EVALUATORS: std::cell::RefCell<Vec<OwsEvaluator>> = const {
        std::cell::RefCell::new(Vec::new())
    };
}
