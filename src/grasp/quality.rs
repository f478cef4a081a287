//! Grasp quality: the Ferrari–Canny metrics Q1 and Q∞, exactly, by a partial hull.
//!
//! # Definitions (the crate's grasp conventions)
//!
//! * **Q1**: the signed distance from the origin to the boundary of CH(∪ w_ij), the union of every
//!   contact's cone-edge wrenches. Positive ⇔ force closure. A grasp that is not force closure
//!   gets −(distance from the origin to the hull), 0 on the boundary — also when the wrenches do
//!   not span 6-D (two hard-finger contacts: rank 5), which is never an error.
//! * **Q∞**: the same over the Minkowski sum ⊕_i {w_i1 … w_ik} (k^m points, never materialised by
//!   the partial method: "is anything beyond this facet?" is answered from the support function —
//!   the support point of a Minkowski sum is the sum of each contact's support point). GraspIt!'s
//!   variant adds the zero wrench to every contact's set ([`Metric::QInf`] `with_zero_wrench`).
//!
//! # Exactness
//!
//! The metrics are evaluated on the wrenches *snapped* to a grid on which every friction pyramid
//! is exactly planar ([`Grasp::snapped_wrenches_into`]; relative change < 6·10⁻⁸ of the largest
//! coordinate). On that set, every inside/outside decision is an exact predicate, so
//! `force_closure` is exact and the partial method returns the full hull's answer (the same
//! facet's plane distance when force closure; the nearest point of the hull otherwise). Values
//! are floating point: the distance to an exactly chosen facet (relative error ~1e−15), or the
//! nearest point by Wolfe's algorithm (~1e−13) when the grasp is not force closure.
//!
//! Before any hull, the partial method runs GJK on the wrenches' support function: when it finds
//! a separating plane with a margin above rounding, and the plane's distance within 1e−13
//! relative of a point of the hull, the grasp is certified not force closure and that distance is
//! the answer, found from support points alone (each a scan of the wrenches) instead of a hull's
//! inserted points, exact orientation tests and new facets (measured in docs/benchmarks.md,
//! "Issue 3 closed", against the partial hull of the runs before it). Force-closure grasps,
//! and origins within rounding of the boundary, go on to the exact partial hull.
//!
//! ```
//! use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric};
//!
//! // Four fingers on the unit cube [−½, ½]³, two pairs of opposite faces.
//! let contacts = vec![
//!     Contact::try_new([-0.5, 0.1, 0.0], [1.0, 0.0, 0.0], None)?,
//!     Contact::try_new([0.5, -0.1, 0.0], [-1.0, 0.0, 0.0], None)?,
//!     Contact::try_new([0.0, -0.5, 0.2], [0.0, 1.0, 0.0], None)?,
//!     Contact::try_new([0.1, 0.5, -0.2], [0.0, -1.0, 0.0], None)?,
//! ];
//! let grasp = Grasp::builder(contacts, FrictionModel::try_new(0.5, 8)?)
//!     .torque_scale(0.75_f64.sqrt())
//!     .build()?;
//!
//! let mut partial = Evaluator::new(Metric::Q1, Method::Partial, None)?;
//! let mut full = Evaluator::new(Metric::Q1, Method::Full, None)?;
//! let (a, b) = (partial.evaluate(&grasp)?, full.evaluate(&grasp)?);
//! let (a_value, b_value) = (a.value.unwrap(), b.value.unwrap());
//! assert!(a.force_closure && a_value > 0.0);
//! assert!((a_value - b_value).abs() <= 1e-12 * b_value);
//! assert!(a.stats.facets_created < b.stats.facets_created);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::Grasp;
use super::certify::BracketScratch;
use super::evaluation::{Evaluation, MAX_DECIDING};
use super::pipeline::{self, Buffers, Expansion};
use super::snap::{SnappedCones, pyramid_labels, snapped_union};
use crate::Hull;
use crate::geometry::{
    GJK_ITERATIONS, GJK_TOUCHING, Gjk, GjkVerdict, largest_norm, min_norm_point,
    min_norm_point_accurate,
};
use crate::predicates::times_power_of_two;
use crate::strategy::Stats;
use std::time::Instant;

mod error;
mod explicit;
mod minkowski;
pub(in crate::grasp) mod ties;
mod vocabulary;
pub use error::QualityError;
pub(in crate::grasp) use explicit::Explicit;
pub(in crate::grasp) use explicit::{holds_the_origin_well, nearest_hull};
pub use minkowski::MINKOWSKI_MATERIALISE_LIMIT;
pub use vocabulary::{Method, Metric, NameError};

/// Another facet within this fraction of the wrench scale of the value is a tie
/// ([`Evaluation::tied`]): the gradients' tolerance, far above the value's accuracy (1e−12).
const TIE_BAND: f64 = 1e-9;

/// The result of one evaluation of Q1 or Q∞ inside the grasp layer (a value that is always a
/// number); what callers get is its [`Evaluation`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::grasp) struct Quality {
    /// Whether the grasp is force closure: `value ≥ FORCE_CLOSURE_EPSILON · scale`, decided on
    /// the certified value (see [`FORCE_CLOSURE_EPSILON`]). A grasp whose value lies below the
    /// band — on the boundary within rounding, or rank-deficient — is not.
    pub force_closure: bool,
    /// The metric on the caller's wrenches: the distance from the origin to the nearest facet
    /// when the origin is inside, else −(distance from the origin to the hull), 0 on the
    /// boundary. Within `1e−12` relative, or `1e−14 · scale` near zero, of the exact value.
    pub value: f64,
    /// The wrench scale the force-closure band is relative to: the largest norm of the raw
    /// wrenches (Q1), or the sum over contacts of each contact's largest (Q∞: a bound on the
    /// norm of every Minkowski point).
    pub scale: f64,
    deciding: [[f64; 6]; MAX_DECIDING],
    deciding_len: usize,
    tied: bool,
    /// Work done (for the full methods: the whole hull).
    pub stats: Stats,
}

impl Quality {
    /// The caller's view of this quality: its [`Evaluation`] as `metric` by `method`.
    pub(in crate::grasp) fn into_evaluation(self, metric: Metric, method: Method) -> Evaluation {
        let mut evaluation = Evaluation::new(
            metric,
            method,
            self.force_closure,
            Some(self.value),
            self.stats,
        )
        .with_deciding(self.deciding_wrenches().iter().copied())
        .with_tie(self.tied);
        evaluation.scale = Some(self.scale);
        evaluation
    }

    /// The wrenches that decide the value: the vertices of the nearest facet when force closure;
    /// otherwise the wrenches spanning the face that holds the hull's point nearest the origin.
    pub fn deciding_wrenches(&self) -> &[[f64; 6]] {
        &self.deciding[..self.deciding_len]
    }

    /// This quality, flagged as tied when another facet of `hull` is (see [`Evaluation::tied`]);
    /// `facet` decides the value, `scale` is the wrench scale and `delta` bounds the distance
    /// between `hull`'s points and the caller's wrenches (0 for a hull of the caller's own).
    /// `bracketed`: the scratch of the bracket that certified the value on `hull`, whose
    /// per-facet lower bounds name the only facets that can tie; without it, every facet is
    /// looked at.
    pub(in crate::grasp) fn with_ties(
        mut self,
        hull: &Hull<6>,
        facet: crate::FacetId,
        scale: f64,
        delta: f64,
        bracketed: Option<&BracketScratch>,
    ) -> Self {
        let band = TIE_BAND * scale + 2.0 * delta;
        self.tied = self.value > 0.0
            && match bracketed {
                Some(scratch) => {
                    let limit = self.value + band;
                    ties::tied(
                        hull,
                        facet,
                        band,
                        super::certify::candidates(scratch, limit),
                    )
                }
                None => ties::tied(hull, facet, band, hull.facets().map(|(id, _)| id)),
            };
        self
    }

    /// A value not yet banded: [`banded`](Self::banded) sets the scale and the verdict.
    pub(in crate::grasp) fn new(
        value: f64,
        deciding: impl Iterator<Item = [f64; 6]>,
        stats: Stats,
    ) -> Self {
        let mut quality = Quality {
            force_closure: value > 0.0,
            value,
            scale: 0.0,
            deciding: [[0.0; 6]; MAX_DECIDING],
            deciding_len: 0,
            tied: false,
            stats,
        };
        for w in deciding.take(MAX_DECIDING) {
            quality.deciding[quality.deciding_len] = w;
            quality.deciding_len += 1;
        }
        quality
    }

    /// The verdict under the force-closure band for the wrench scale `scale`.
    pub(in crate::grasp) fn banded(mut self, scale: f64) -> Self {
        self.scale = scale;
        self.force_closure = is_force_closure(self.value, scale);
        self
    }

    /// This quality of wrenches divided by 2^`e` ([`WrenchUnit`]), for the caller's wrenches:
    /// value, scale and deciding wrenches times 2^`e` (the verdict is scale-free).
    fn in_caller_units(mut self, unit: WrenchUnit) -> Self {
        let up = |x: f64| times_power_of_two(x, unit.0);
        self.value = up(self.value);
        self.scale = up(self.scale);
        for w in &mut self.deciding[..self.deciding_len] {
            *w = w.map(up);
        }
        self
    }
}

/// Wrenches whose largest coordinate lies outside [2^−`UNIT_RANGE`, 2^`UNIT_RANGE`] are
/// evaluated divided by a power of two 2^e that brings it into [0.5, 1): an exact change of
/// units (bar bits below 2^−1022 of the largest coordinate), after which no norm, square or
/// tolerance of the metrics underflows. Wrenches of size 2^−900 had their scale, a norm, come
/// out 0 (their squares underflowed), and with it the force-closure band.
const UNIT_RANGE: i32 = 256;

/// The exponent e of the unit 2^e the wrenches are evaluated in (see [`UNIT_RANGE`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(in crate::grasp) struct WrenchUnit(pub(in crate::grasp) i32);

impl WrenchUnit {
    /// The unit for wrenches whose largest coordinate magnitude is `largest` (finite).
    pub(in crate::grasp) fn for_largest(largest: f64) -> Self {
        let range = 2f64.powi(UNIT_RANGE);
        if largest == 0.0 || (largest >= 1.0 / range && largest <= range) {
            return WrenchUnit(0);
        }
        // 2^(e−1) ≤ largest < 2^e, from the exponent bits (largest is normal here).
        let biased = ((largest.to_bits() >> 52) & 0x7ff) as i32;
        WrenchUnit(biased - 1022)
    }

    /// `x` in this unit: divided by 2^e.
    pub(in crate::grasp) fn down(self, x: f64) -> f64 {
        times_power_of_two(x, -self.0)
    }

    /// `w` in this unit.
    pub(in crate::grasp) fn apply(self, w: [f64; 6]) -> [f64; 6] {
        w.map(|x| self.down(x))
    }
}

/// The largest coordinate magnitude of `wrenches`.
fn largest_coordinate(wrenches: &[[f64; 6]]) -> f64 {
    wrenches
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()))
}

/// The width of the force-closure band, relative to the wrench scale: a grasp is force closure
/// when its value (Q1 or Q∞) is at least `FORCE_CLOSURE_EPSILON · scale`.
///
/// Why a band at all: the caller's wrenches carry the rounding of their own computation
/// (`~1e−16` of their size), so a grasp that is degenerate in exact arithmetic — two contacts,
/// contact points on one line, any wrench set of rank < 6 — computes to a set whose hull may hold
/// the origin by `1e−17`. No physical grasp resists disturbances that small: such a grasp is on
/// the boundary, and reported as not force closure, with its tiny value. Why `1e−12`: four
/// orders of magnitude above the rounding of the wrenches and of the values (`≤ 1e−15` of the
/// scale), so rounding never pushes a degenerate grasp over it; and far below any quality a
/// planner would keep (a grasp resisting `1e−12` of its own contact force).
pub const FORCE_CLOSURE_EPSILON: f64 = 1e-12;

/// Whether `value` is force closure under the band for `scale` (see [`FORCE_CLOSURE_EPSILON`]).
pub fn is_force_closure(value: f64, scale: f64) -> bool {
    value >= FORCE_CLOSURE_EPSILON * scale && value > 0.0
}

/// The largest wrench coordinate the metrics accept. They are computed from squared norms and
/// products of them (GJK, Wolfe's algorithm, plane offsets), which overflow for wrenches far
/// below `f64::MAX` (measured: a friction coefficient of 1e160 gave NaN); 1e100 keeps a wide
/// margin. There is no lower limit: every force has norm at least 1 (its unit normal push).
/// Beyond it, [`QualityError::WrenchTooLarge`]: express the grasp in other units (positions,
/// torque scale) or with a smaller friction coefficient.
pub const MAX_WRENCH_COORDINATE: f64 = 1e100;

/// [`QualityError::NonFiniteWrench`] or [`QualityError::WrenchTooLarge`] for wrenches the
/// metrics cannot evaluate.
pub(in crate::grasp) fn check_wrenches(wrenches: &[[f64; 6]]) -> Result<(), QualityError> {
    let mut largest = 0.0f64;
    for &x in wrenches.iter().flatten() {
        if !x.is_finite() {
            return Err(QualityError::NonFiniteWrench);
        }
        largest = largest.max(x.abs());
    }
    if largest > MAX_WRENCH_COORDINATE {
        return Err(QualityError::WrenchTooLarge { largest });
    }
    Ok(())
}

/// Evaluates Q1 or Q∞ by one method over many grasps, reusing its buffers: the wrenches, the
/// hull's arena ([`Hull::rebuild_with_strategy`]), the partial strategy's queue, GJK's corral and,
/// for Q∞, the implicit Minkowski source. In steady state the only allocations left are the
/// exact-arithmetic caches of facets whose floating-point filter fails (one box each; about 19
/// per force-closure Q1 grasp at 4 × 32 edges, none for grasps GJK settles: `tests/allocation.rs`).
/// The engine behind [`Evaluator`](crate::grasp::Evaluator) for these two metrics.
#[derive(Clone, Debug)]
pub(in crate::grasp) struct HullEvaluator {
    metric: Metric,
    method: Method,
    cones: SnappedCones,
    /// The snapped wrenches (Q1) or Minkowski points (Q∞ by a full method).
    wrenches: Vec<[f64; 6]>,
    /// The contact of every wrench, when `wrenches` holds the snapped pyramids.
    pyramids: Vec<u32>,
    buffers: Buffers,
    minkowski: minkowski::MinkowskiSearch,
}

impl HullEvaluator {
    /// An evaluator for `metric` (Q1 or Q∞) by `method`.
    pub(in crate::grasp) fn new(metric: Metric, method: Method) -> Self {
        HullEvaluator {
            metric,
            method,
            cones: SnappedCones::default(),
            wrenches: Vec::new(),
            pyramids: Vec::new(),
            buffers: Buffers::default(),
            minkowski: minkowski::MinkowskiSearch::default(),
        }
    }

    /// Evaluates `grasp`: the exact metric on the caller's wrenches ([`Grasp::wrenches`]), found
    /// on snapped ones and certified on the raw ones (see the [module docs](self)).
    ///
    /// # Errors
    /// [`QualityError::NonFiniteWrench`] when the torque scale overflows the wrenches;
    /// [`QualityError::WrenchTooLarge`] above [`MAX_WRENCH_COORDINATE`];
    /// [`QualityError::MinkowskiTooLarge`] for Q∞ by a full method with too many points;
    /// `QualityError::Qhull` when Qhull fails (feature `qhull`).
    pub(in crate::grasp) fn evaluate(&mut self, grasp: &Grasp) -> Result<Quality, QualityError> {
        let started = Instant::now();
        if !self.method.supports(self.metric) {
            return Err(QualityError::UnsupportedMethod {
                method: self.method,
                metric: self.metric,
            });
        }
        self.cones.fill(grasp);
        // The caller's wrenches first: a finite one that is too large is named as such (its
        // snapped copy's distance to it may overflow, which would read as "not finite").
        check_wrenches(&self.cones.raw)?;
        if !self.cones.is_finite() {
            return Err(QualityError::NonFiniteWrench);
        }
        let unit = WrenchUnit::for_largest(largest_coordinate(&self.cones.raw));
        self.cones.rescale(unit);
        let mut quality = match self.metric {
            Metric::Q1 => {
                snapped_union(&self.cones, &mut self.wrenches);
                let edges = self.cones.edges();
                pyramid_labels(self.cones.contacts(), edges, &mut self.pyramids);
                let delta = self.cones.delta.iter().fold(0.0, |m: f64, &d| m.max(d));
                let raw = &self.cones.raw;
                let mut set = Explicit::snapped(raw, &self.wrenches, &self.pyramids, delta);
                match expansion(self.method, self.metric)? {
                    Some(e) => pipeline::evaluate(&mut set, e, &mut self.buffers, started)?,
                    None => qhull_q1(raw, started)?.banded(largest_norm(raw)),
                }
            }
            Metric::QInf { with_zero_wrench } => match expansion(self.method, self.metric)? {
                Some(Expansion::Partial) => {
                    let mut set = minkowski::ImplicitSum::new(
                        &self.cones,
                        with_zero_wrench,
                        &mut self.minkowski,
                    );
                    pipeline::evaluate(&mut set, Expansion::Partial, &mut self.buffers, started)?
                }
                Some(Expansion::Full) => {
                    let mut set = minkowski::MaterialisedSum::new(
                        &self.cones,
                        with_zero_wrench,
                        &mut self.wrenches,
                    );
                    pipeline::evaluate(&mut set, Expansion::Full, &mut self.buffers, started)?
                }
                None => {
                    minkowski::qhull(&self.cones, with_zero_wrench, &mut self.wrenches, started)?
                }
            },
            // `Evaluator` sends only Q1 and Q∞ here; the vocabulary's other metrics have no
            // hull of their own.
            metric => {
                return Err(QualityError::UnsupportedMethod {
                    method: self.method,
                    metric,
                });
            }
        };
        quality = quality.in_caller_units(unit);
        quality.stats.elapsed = started.elapsed();
        Ok(quality)
    }
}

/// Q1 of `grasp` by the partial hull: one grasp's
/// [`Evaluator::new(Metric::Q1, Method::Partial, None)`](crate::grasp::Evaluator::new).
///
/// # Errors
/// As [`Evaluator::evaluate`](crate::grasp::Evaluator::evaluate).
pub fn q1(grasp: &Grasp) -> Result<Evaluation, QualityError> {
    let metric = Metric::Q1;
    let quality = HullEvaluator::new(metric, Method::Partial).evaluate(grasp)?;
    Ok(quality.into_evaluation(metric, Method::Partial))
}

/// Q∞ of `grasp` (without the zero wrench) by the partial hull over the implicit Minkowski sum.
///
/// # Errors
/// As [`Evaluator::evaluate`](crate::grasp::Evaluator::evaluate).
pub fn q_inf(grasp: &Grasp) -> Result<Evaluation, QualityError> {
    let metric = Metric::QInf {
        with_zero_wrench: false,
    };
    let quality = HullEvaluator::new(metric, Method::Partial).evaluate(grasp)?;
    Ok(quality.into_evaluation(metric, Method::Partial))
}

/// Q1 of an explicit wrench set (not snapped: exact on exactly these numbers), by `method`.
///
/// ```
/// use pqhull::grasp::quality::{q1_of_wrenches, Method};
/// // ±e_i in 6-D: the cross-polytope, whose facets lie at distance 1/√6.
/// let mut w = Vec::new();
/// for i in 0..6 {
///     for s in [1.0, -1.0] {
///         let mut e = [0.0; 6];
///         e[i] = s;
///         w.push(e);
///     }
/// }
/// let q = q1_of_wrenches(&w, Method::Partial)?;
/// assert!(q.force_closure && (q.value.unwrap() - 1.0 / 6f64.sqrt()).abs() < 1e-15);
/// # Ok::<(), pqhull::grasp::quality::QualityError>(())
/// ```
///
/// # Errors
/// [`QualityError::NonFiniteWrench`] for a NaN or infinite coordinate;
/// [`QualityError::WrenchTooLarge`] above [`MAX_WRENCH_COORDINATE`]; `QualityError::Qhull`
/// for [`Method::Qhull`] (feature `qhull`) when Qhull fails, `QualityError::QhullUnavailable`
/// without the feature.
pub fn q1_of_wrenches(wrenches: &[[f64; 6]], method: Method) -> Result<Evaluation, QualityError> {
    Ok(q1_quality_of_wrenches(wrenches, method)?.into_evaluation(Metric::Q1, method))
}

/// [`q1_of_wrenches`] as the grasp layer's own [`Quality`].
pub(in crate::grasp) fn q1_quality_of_wrenches(
    wrenches: &[[f64; 6]],
    method: Method,
) -> Result<Quality, QualityError> {
    check_wrenches(wrenches)?;
    let unit = WrenchUnit::for_largest(largest_coordinate(wrenches));
    if unit != WrenchUnit(0) {
        let scaled: Vec<[f64; 6]> = wrenches.iter().map(|&w| unit.apply(w)).collect();
        let quality = q1_quality_of_wrenches(&scaled, method)?;
        return Ok(quality.in_caller_units(unit));
    }
    if wrenches.is_empty() {
        return Ok(Quality::new(
            f64::NEG_INFINITY,
            std::iter::empty(),
            Stats::default(),
        ));
    }
    let started = Instant::now();
    let mut quality = match expansion(method, Metric::Q1)? {
        Some(e) => {
            let mut set = Explicit::raw(wrenches);
            pipeline::evaluate(&mut set, e, &mut Buffers::default(), started)?
        }
        None => qhull_q1(wrenches, started)?.banded(largest_norm(wrenches)),
    };
    quality.stats.elapsed = started.elapsed();
    Ok(quality)
}

/// Evaluates every grasp by Q1 or Q∞, results in input order: on all cores (rayon's current
/// pool) with the `parallel` feature (a default), else one after another.
///
/// Each worker thread keeps one [`HullEvaluator`] per (metric, method) for the life of the
/// thread, so its buffers and hull arena are reused across rayon's jobs and across batches: a
/// planner calling this in a loop allocates, per grasp, only what the evaluator does. (rayon's
/// `map_init` would make a fresh evaluator for every job it splits off, a cold arena each
/// time, which cost a quarter of the two-thread speed-up on batches of small grasps.)
pub(in crate::grasp) fn evaluate_hull_batch(
    grasps: &[Grasp],
    metric: Metric,
    method: Method,
) -> Vec<Result<Quality, QualityError>> {
    super::map_in_order(grasps, |grasp| {
        with_thread_evaluator(metric, method, |e| e.evaluate(grasp))
    })
}

thread_local! {
    /// The evaluators of [`evaluate_hull_batch`] on this thread, one per (metric, method) used.
    static EVALUATORS: std::cell::RefCell<Vec<HullEvaluator>> = const {
        std::cell::RefCell::new(Vec::new())
    };
}

/// Runs `f` with this thread's evaluator for `metric` and `method` (made on first use).
fn with_thread_evaluator<T>(
    metric: Metric,
    method: Method,
    f: impl FnOnce(&mut HullEvaluator) -> T,
) -> T {
    EVALUATORS.with_borrow_mut(|evaluators| {
        let evaluator = find_or_make(
            evaluators,
            |e| e.metric == metric && e.method == method,
            || HullEvaluator::new(metric, method),
        );
        f(evaluator)
    })
}

/// The entry of `kept` that `matches`, made by `make` and kept when there is none: the
/// per-thread evaluator registries of the batch functions.
pub(in crate::grasp) fn find_or_make<E>(
    kept: &mut Vec<E>,
    matches: impl Fn(&E) -> bool,
    make: impl FnOnce() -> E,
) -> &mut E {
    let i = match kept.iter().position(matches) {
        Some(i) => i,
        None => {
            kept.push(make());
            kept.len() - 1
        }
    };
    &mut kept[i]
}

/// Stats of work that built no hull (a degenerate wrench set).
pub(in crate::grasp) fn no_hull_stats(points: usize, started: Instant) -> Stats {
    Stats {
        points_processed: points,
        facets_created: 0,
        expansions: 0,
        elapsed: started.elapsed(),
    }
}

/// −(distance from the origin to CH(w)) for a set too degenerate for a hull: never force closure.
pub(in crate::grasp) fn degenerate(w: &[[f64; 6]], started: Instant) -> Quality {
    // The plain run's corral starts the accurate one: its residual in double-double keeps the
    // distance of an origin within rounding of the set (a flat set) to about 1e−30 of its size.
    let rough = min_norm_point(w.len(), |i| w[i], &[0.0; 6]);
    let nearest = min_norm_point_accurate(w.len(), |i| w[i], &[0.0; 6], rough.support());
    let support = nearest.support().iter().map(|&i| w[i]);
    Quality::new(-nearest.distance, support, no_hull_stats(w.len(), started))
}

/// When GJK certifies that the origin lies outside the hull of `w` (so the grasp is not force
/// closure): its distance, and the support points GJK inserted; the face spanning the nearest
/// point is then in `gjk.face()`. `None` when undecided (force closure, or too close to call).
pub(in crate::grasp) fn certified_outside(
    w: &[[f64; 6]],
    gjk: &mut Gjk<6>,
) -> Option<(f64, usize)> {
    let mut set = w;
    match gjk.run(
        &mut set,
        largest_norm(w),
        &w[..1],
        GJK_ITERATIONS,
        GJK_TOUCHING,
    ) {
        GjkVerdict::Separated { distance, inserted } => Some((distance, inserted)),
        _ => None,
    }
}

/// How the cascade grows its hulls for `method` ([`pipeline`]); `None` for Qhull, a baseline
/// outside it.
///
/// # Errors
/// [`QualityError::UnsupportedMethod`] for a method that does not compute `metric` (Q1 or Q∞).
fn expansion(method: Method, metric: Metric) -> Result<Option<Expansion>, QualityError> {
    match method {
        Method::Partial => Ok(Some(Expansion::Partial)),
        Method::Full => Ok(Some(Expansion::Full)),
        Method::Qhull => Ok(None),
        Method::PartialRays | Method::Ellipsoid => {
            Err(QualityError::UnsupportedMethod { method, metric })
        }
    }
}

#[cfg(not(feature = "qhull"))]
fn qhull_q1(_: &[[f64; 6]], _: Instant) -> Result<Quality, QualityError> {
    Err(QualityError::QhullUnavailable)
}

#[cfg(feature = "qhull")]
fn qhull_q1(w: &[[f64; 6]], started: Instant) -> Result<Quality, QualityError> {
    use crate::qhull_baseline::{QhullError, qhull_full_hull};
    let hull = match qhull_full_hull(w) {
        Ok(hull) => hull,
        // Too few points, or flat input (QH6154): no hull, a distance all the same.
        Err(QhullError::TooFewPoints { .. }) => return Ok(degenerate(w, started)),
        Err(QhullError::Qhull { code, message }) if code == 6154 || message.contains("QH6154") => {
            return Ok(degenerate(w, started));
        }
        Err(e) => return Err(QualityError::Qhull(e)),
    };
    let stats = Stats {
        points_processed: hull.vertices.len(),
        facets_created: hull.facets.len(),
        expansions: 0,
        elapsed: started.elapsed(),
    };
    // Qhull's planes are floating point: the origin is inside when every offset is negative.
    let nearest = hull
        .facets
        .iter()
        .min_by(|a, b| (-a.offset).total_cmp(&-b.offset))
        .expect("a hull has facets");
    if nearest.offset < 0.0 && hull.facets.iter().all(|f| f.offset < 0.0) {
        let deciding = nearest.vertices.iter().map(|&v| w[v]);
        let mut quality = Quality::new(-nearest.offset, deciding, stats);
        // Ties as on our hulls (see `ties`), from Qhull's floating-point planes.
        let band = TIE_BAND * largest_norm(w);
        quality.tied = hull.facets.iter().any(|f| {
            let apart: f64 = f
                .normal
                .iter()
                .zip(&nearest.normal)
                .map(|(a, b)| (a - b) * (a - b))
                .sum();
            (f.offset - nearest.offset).abs() <= band && apart.sqrt() > ties::DIFFERENT_PLANE
        });
        return Ok(quality);
    }
    let vertices = &hull.vertices;
    let point = min_norm_point(vertices.len(), |i| w[vertices[i]], &[0.0; 6]);
    let support = point.support().iter().map(|&i| w[vertices[i]]);
    Ok(Quality::new(-point.distance, support, stats))
}
