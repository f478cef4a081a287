//! Q∞ over the Minkowski sum ⊕_i W_i, implicitly (support function) or materialised.

use super::{
    Quality, QualityError, certified_outside, degenerate, holds_the_origin_well, nearest_hull,
    no_hull_stats,
};
use crate::geometry::vector::dot;
use crate::geometry::{GJK_ITERATIONS, GJK_TOUCHING, Gjk, GjkVerdict, Support, SupportFn};
use crate::grasp::certify::support_with_error;
use crate::grasp::flatness::{FLAT, Flatness};
use crate::grasp::pipeline::{Built, Expansion, WrenchSet};
use crate::grasp::snap::SnappedCones;
use crate::strategy::{ClosestToOrigin, MinkowskiSum, PointSource, SourceError, Stats};
use crate::{FacetId, Hull, HullError};
use std::time::Instant;

/// The most Minkowski points the full and Qhull methods materialise (2^20: 4 contacts × 32 edges).
pub const MINKOWSKI_MATERIALISE_LIMIT: usize = 1 << 20;

/// Refills `sets` with the per-contact wrench sets (with the zero wrench if asked), reusing
/// their buffers: the snapped wrenches, or the caller's raw ones when `raw` (see [`fill_set`]).
fn fill_sets(
    sets: &mut Vec<Vec<[f64; 6]>>,
    cones: &SnappedCones,
    with_zero_wrench: bool,
    raw: bool,
) {
    sets.resize_with(cones.distinct_contacts(), Vec::new);
    for (c, set) in sets.iter_mut().enumerate() {
        set.clear();
        fill_set(set, cones, c, with_zero_wrench, raw);
    }
}

/// Appends contact `c`'s wrench set to `set`: the snapped wrenches, or the caller's raw ones
/// when `raw`, each scaled by the contact's multiplicity (r copies of a convex set sum to r
/// times it; see [`snap`](crate::grasp::snap)), and the zero wrench if asked. A soft contact's
/// set is the union of its two pyramids (2k wrenches): one summand, since one finger exerts
/// one force and one torsional moment.
fn fill_set(
    set: &mut Vec<[f64; 6]>,
    cones: &SnappedCones,
    c: usize,
    with_zero_wrench: bool,
    raw: bool,
) {
    let k = cones.edges();
    let r = f64::from(cones.multiplicity[c]);
    let scaled = |w: [f64; 6]| w.map(|x| r * x);
    for p in cones.pyramids_of(c) {
        if raw {
            set.extend(cones.raw[p * k..(p + 1) * k].iter().map(|&w| scaled(w)));
        } else {
            set.extend((0..k).map(|j| scaled(cones.wrench(p, j))));
        }
    }
    if with_zero_wrench {
        set.push([0.0; 6]);
    }
}

/// The number of Minkowski points of `sets` (the product of their sizes), `None` above
/// `usize::MAX`.
fn tuple_count(sets: &[Vec<[f64; 6]>]) -> Option<usize> {
    sets.iter()
        .try_fold(1usize, |n, set| n.checked_mul(set.len()))
}

/// The raw side of a Minkowski sum for [`certify::bracket`](crate::grasp::certify::bracket): `δ` (the distance between a
/// snapped Minkowski point as computed and the exact sum of the same raw wrenches) and the
/// rounding of a raw sum computed in `f64`.
fn raw_bounds(cones: &SnappedCones, raw_sets: &[Vec<[f64; 6]>]) -> (f64, f64) {
    // m counts every contact of the grasp: a merged contact's scaling r·w rounds once more.
    let m: f64 = cones.multiplicity.iter().map(|&r| f64::from(r)).sum();
    // A contact's δ: the largest of its pyramids'.
    let scaled_delta: f64 = (0..cones.distinct_contacts())
        .map(|c| {
            let delta = cones
                .pyramids_of(c)
                .map(|p| cones.delta[p])
                .fold(0.0, f64::max);
            delta * f64::from(cones.multiplicity[c])
        })
        .sum();
    let sizes: f64 = raw_scale(raw_sets);
    // A left-to-right sum of m vectors: each coordinate is off by at most γ_(m−1)·Σ|w_ic|, so
    // the error vector by at most γ_m·Σ|w_i| (γ_m ≤ 1.2e−16·m for small m).
    let error = 1.2e-16 * m * sizes * (1.0 + 1e-15);
    // Snapped sums are exact up to 10 contacts (see `snap`); beyond, they round like raw ones
    // (their sizes are within δ of the raw sizes), which δ must then cover.
    let snapped_rounding = if m > 10.0 {
        1.2e-16 * m * (sizes + scaled_delta) * (1.0 + 1e-15)
    } else {
        0.0
    };
    ((scaled_delta + snapped_rounding) * (1.0 + 1e-15), error)
}

/// The support function of the sum of `sets`: Σ_i max_j u·w_ij, with a rounding bound.
fn sum_support_with_error(sets: &[Vec<[f64; 6]>], u: &[f64; 6]) -> (f64, f64) {
    let (mut total, mut error, mut magnitude) = (0.0, 0.0, 0.0);
    for set in sets {
        let (h, e) = support_with_error(set, u);
        total += h;
        error += e;
        magnitude += h.abs();
    }
    (
        total,
        error + 1.2e-16 * sets.len() as f64 * magnitude + 1e-300,
    )
}

/// The support point of the sum of `sets` (each contact's own support point, summed).
fn sum_support(sets: &[Vec<[f64; 6]>], direction: &[f64; 6]) -> [f64; 6] {
    let mut total = [0.0; 6];
    for set in sets {
        let w = Support::support_point(&mut &set[..], direction).expect("a non-empty set");
        for (t, x) in total.iter_mut().zip(&w) {
            *t += x;
        }
    }
    total
}

/// `Σ_i sets[i][choice[i]]`, left to right (exact for snapped wrenches and up to 10 contacts,
/// counted with multiplicity).
fn sum(sets: &[Vec<[f64; 6]>], choice: impl Iterator<Item = usize>) -> [f64; 6] {
    let mut total = [0.0; 6];
    for (set, j) in sets.iter().zip(choice) {
        for (t, w) in total.iter_mut().zip(&set[j]) {
            *t += w;
        }
    }
    total
}

/// Writes every Minkowski point into `out` (odometer order: contact 0 varies slowest).
pub(super) fn materialise(
    cones: &SnappedCones,
    with_zero_wrench: bool,
    raw: bool,
    out: &mut Vec<[f64; 6]>,
) -> Result<(), QualityError> {
    let mut sets = Vec::new();
    fill_sets(&mut sets, cones, with_zero_wrench, raw);
    let count = tuple_count(&sets);
    match count {
        Some(n) if n <= MINKOWSKI_MATERIALISE_LIMIT => {}
        _ => return Err(QualityError::MinkowskiTooLarge { points: count }),
    }
    out.clear();
    let mut choice = vec![0usize; sets.len()];
    loop {
        out.push(sum(&sets, choice.iter().copied()));
        let mut i = sets.len();
        loop {
            if i == 0 {
                return Ok(());
            }
            i -= 1;
            choice[i] += 1;
            if choice[i] < sets[i].len() {
                break;
            }
            choice[i] = 0;
        }
    }
}

/// The Minkowski sum answered through its support function; refilled per grasp in place. The
/// search itself is the strategy layer's [`MinkowskiSum`] (its exact "beyond"); this adds the
/// grasp's bookkeeping: the raw sets and the tuple behind every point handed out.
#[derive(Clone, Debug, Default)]
pub(super) struct MinkowskiSource {
    sum: MinkowskiSum<6>,
    /// Whether the last contact-set entry is the zero wrench.
    with_zero_wrench: bool,
    /// The caller's raw wrench sets (with the zero wrench if asked), whatever `sum` holds.
    raw_sets: Vec<Vec<[f64; 6]>>,
    /// Every point handed out (seeds and insertions), and its tuple (`contacts` entries each in
    /// `tuples`): how a hull vertex finds its raw point for the certificate.
    log: Vec<[f64; 6]>,
    tuples: Vec<usize>,
}

impl MinkowskiSource {
    /// The sum for `cones`' grasp, over the snapped wrenches or, when `raw`, the raw ones.
    fn fill(&mut self, cones: &SnappedCones, with_zero_wrench: bool, raw: bool) {
        self.sum.refill(cones.distinct_contacts(), |c, set| {
            fill_set(set, cones, c, with_zero_wrench, raw);
        });
        fill_sets(&mut self.raw_sets, cones, with_zero_wrench, true);
        self.log.clear();
        self.tuples.clear();
        self.with_zero_wrench = with_zero_wrench;
    }

    /// Records `point`, the sum of the tuple [`MinkowskiSum::last_tuple`] names.
    fn record(&mut self, point: [f64; 6]) {
        self.log.push(point);
        self.tuples.extend_from_slice(self.sum.last_tuple());
    }

    /// The raw sum (in `f64`) of the tuple behind `point`, a point this source handed out.
    fn raw_point(&self, point: &[f64; 6]) -> Option<[f64; 6]> {
        let m = self.raw_sets.len();
        let i = self.log.iter().position(|p| p == point)?;
        Some(sum(
            &self.raw_sets,
            self.tuples[i * m..(i + 1) * m].iter().copied(),
        ))
    }

    /// The sum of each contact's largest raw wrench norm: the scale of the force-closure band.
    fn raw_scale(&self) -> f64 {
        raw_scale(&self.raw_sets)
    }
}

impl PointSource<6> for MinkowskiSource {
    /// [`MinkowskiSum`]'s exact answer, recorded.
    fn beyond(&mut self, hull: &Hull<6>, id: FacetId) -> Option<[f64; 6]> {
        let point = self.sum.beyond(hull, id)?;
        self.record(point);
        Some(point)
    }
}

impl Support<6> for MinkowskiSource {
    fn support_point(&mut self, direction: &[f64; 6]) -> Option<[f64; 6]> {
        let point = self.sum.support_point(direction)?;
        self.record(point);
        Some(point)
    }
}

/// Fixed directions that seed the partial hull: ± every axis (so the hull's coordinate range
/// covers every Minkowski point) and the 2·15 diagonals e_a ± e_b.
const SEED_DIRECTIONS: [[f64; 6]; 42] = {
    let mut directions = [[0.0; 6]; 42];
    let mut n = 0;
    let mut a = 0;
    while a < 6 {
        directions[n][a] = 1.0;
        directions[n + 1][a] = -1.0;
        n += 2;
        let mut b = a + 1;
        while b < 6 {
            directions[n][a] = 1.0;
            directions[n][b] = 1.0;
            directions[n + 1][a] = 1.0;
            directions[n + 1][b] = -1.0;
            n += 2;
            b += 1;
        }
        a += 1;
    }
    directions
};

/// What a Q∞ evaluation by the partial method reuses from grasp to grasp: the implicit source
/// (inside the strategy, with its queue) and the seeds.
#[derive(Clone, Debug)]
pub(super) struct MinkowskiSearch {
    nearest: ClosestToOrigin<6, MinkowskiSource>,
    seeds: Vec<[f64; 6]>,
    /// The raw sum points GJK's support function handed out, and their tuples (`m` each).
    seen: Vec<[f64; 6]>,
    seen_tuples: Vec<usize>,
    /// The tuples of GJK's final simplex (7·`m`), when it holds the origin well: the snapped
    /// hull's start (see `Explicit::start_hull`); empty otherwise.
    start: Vec<usize>,
}

impl Default for MinkowskiSearch {
    fn default() -> Self {
        MinkowskiSearch {
            nearest: ClosestToOrigin::with_source([0.0; 6], MinkowskiSource::default()),
            seeds: Vec::new(),
            seen: Vec::new(),
            seen_tuples: Vec::new(),
            start: Vec::new(),
        }
    }
}

/// The sum over contacts of the largest wrench norm of `sets`.
fn raw_scale(sets: &[Vec<[f64; 6]>]) -> f64 {
    sets.iter()
        .map(|set| set.iter().map(|w| dot(*w, *w).sqrt()).fold(0.0, f64::max))
        .sum()
}

/// 42 support points of the sum of `sets` along [`SEED_DIRECTIONS`], without repeats.
fn seed_points(seeds: &mut Vec<[f64; 6]>, mut support: impl FnMut(&[f64; 6]) -> [f64; 6]) {
    seeds.clear();
    for d in &SEED_DIRECTIONS {
        let p = support(d);
        if !seeds.contains(&p) {
            seeds.push(p);
        }
    }
}

/// Q∞'s wrench set for the partial method: the implicit Minkowski sum, answered through its
/// support function (never materialised). The cascade's steps ([`pipeline`](crate::grasp::pipeline)) on it:
/// 1. with the zero wrench, GJK on the *union* of the raw cone edges: a certified separation
///    means the grasp is not force closure, and then Q∞ = 0 exactly (the origin, a point of the
///    sum, is on its boundary: the two hulls have the same force closure); then GJK on the raw
///    sum's support function, seeded with its support points along 42 fixed directions;
/// 2. contacts whose raw wrenches lie within a slab through the origin thin enough that the sum
///    is within [`FLAT`] of its scale of a hyperplane ([`crate::grasp::flatness`]: two contacts,
///    contacts on a line or at one or two points) are not force closure: −distance by GJK run to
///    convergence, exactly 0 with the zero wrench (the origin is then a point of the flat sum);
/// 3. the exact partial hull of the *snapped* sum, seeded as GJK, certified on the raw sum;
/// 4. with the zero wrench, a boundary grasp's value lies in [0, the upper bound along the raw
///    simplex of the nearest facet];
/// 5. the exact partial hull of the raw sum (points summed in `f64`, within `1e−15` of the scale
///    of the exact sums); a raw sum spanning fewer than six dimensions is flat, as in step 2.
pub(super) struct ImplicitSum<'a> {
    cones: &'a SnappedCones,
    with_zero_wrench: bool,
    search: &'a mut MinkowskiSearch,
    scale: f64,
}

impl<'a> ImplicitSum<'a> {
    /// The sum of `cones`' contact sets (with the zero wrench if asked), in `search`'s buffers.
    pub(super) fn new(
        cones: &'a SnappedCones,
        with_zero_wrench: bool,
        search: &'a mut MinkowskiSearch,
    ) -> Self {
        // A start found for another grasp's sets must not outlive it.
        search.start.clear();
        let source = search.nearest.source_mut();
        source.fill(cones, with_zero_wrench, false);
        let scale = source.raw_scale();
        ImplicitSum {
            cones,
            with_zero_wrench,
            search,
            scale,
        }
    }

    fn raw_sets(&self) -> &[Vec<[f64; 6]>] {
        &self.search.nearest.source().raw_sets
    }

    /// The partial hull of the sum the source holds, seeded from its own support points; with
    /// `start`, also from the points of GJK's final simplex's tuples, which it starts from.
    fn hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        start: bool,
    ) -> Result<Result<Built<'h>, SourceError<6>>, HullError> {
        let MinkowskiSearch {
            nearest,
            seeds,
            start: tuples,
            ..
        } = &mut *self.search;
        let source = nearest.source_mut();
        seed_points(seeds, |d| {
            source.support_point(d).expect("a contact has cone edges")
        });
        let h = hull.get_or_insert_with(Hull::empty);
        let m = source.raw_sets.len();
        if start && m > 0 && tuples.len() == 7 * m {
            let mut simplex = [0usize; 7];
            for (s, tuple) in simplex.iter_mut().zip(tuples.chunks_exact(m)) {
                let point = source.sum.sum_of(tuple.iter().copied());
                source.log.push(point);
                source.tuples.extend_from_slice(tuple);
                *s = seeds.iter().position(|q| *q == point).unwrap_or_else(|| {
                    seeds.push(point);
                    seeds.len() - 1
                });
            }
            h.start_next_build_from(&simplex);
        }
        match h.rebuild_with_strategy(seeds, &mut *nearest) {
            Ok(Ok(result)) => Ok(Ok(Some((h, result)))),
            Ok(Err(e)) => Ok(Err(e)),
            Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
                Ok(Ok(None))
            }
            Err(e) => Err(e),
        }
    }
}

impl WrenchSet for ImplicitSum<'_> {
    fn scale(&self) -> f64 {
        self.scale
    }

    fn separated(&mut self, gjk: &mut Gjk<6>, started: Instant) -> Option<Quality> {
        if self.with_zero_wrench
            && let Some(quality) = union_separated(&self.cones.raw, gjk, started)
        {
            return Some(quality);
        }
        let MinkowskiSearch {
            nearest,
            seeds,
            seen,
            seen_tuples,
            start,
        } = &mut *self.search;
        let raw_sets = &nearest.source().raw_sets;
        if !self.with_zero_wrench {
            // Without the zero wrench, starting from GJK's simplex made more facets, not fewer
            // (docs/benchmarks.md, "Issue 25"): the plain support function, nothing recorded.
            let support = |v: &[f64; 6]| sum_support(raw_sets, v);
            return separated_sum(support, seeds, self.scale, gjk, started);
        }
        seen.clear();
        seen_tuples.clear();
        // The raw sum's support point, its tuple recorded (the same point as `sum_support`:
        // each contact's first maximiser, summed in order).
        let support = |d: &[f64; 6]| {
            let from = seen_tuples.len();
            seen_tuples.extend(raw_sets.iter().map(|set| first_maximiser(set, d)));
            let p = sum(raw_sets, seen_tuples[from..].iter().copied());
            seen.push(p);
            p
        };
        let quality = separated_sum(support, seeds, self.scale, gjk, started);
        start.clear();
        if quality.is_none() && holds_the_origin_well(gjk.face()) {
            let m = raw_sets.len();
            for p in gjk.face() {
                let Some(i) = seen.iter().position(|q| q == p) else {
                    start.clear();
                    break;
                };
                start.extend_from_slice(&seen_tuples[i * m..(i + 1) * m]);
            }
        }
        quality
    }

    fn is_flat(&mut self, flatness: &mut Flatness) -> bool {
        flat_contacts(self.raw_sets(), self.scale, flatness)
    }

    fn flat_value(&mut self, gjk: &mut Gjk<6>, started: Instant) -> Result<Quality, QualityError> {
        let MinkowskiSearch { nearest, seeds, .. } = &mut *self.search;
        let raw_sets = &nearest.source().raw_sets;
        let (cones, zero) = (self.cones, self.with_zero_wrench);
        flat_sum(cones, zero, raw_sets, self.scale, seeds, gjk, started)
    }

    fn snapped_hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        _: &mut ClosestToOrigin<6>,
        _: Expansion,
    ) -> Result<Built<'h>, QualityError> {
        // The source keeps its contract (its points are checked exactly, and within the seeds'
        // range); should it not, or should the engine refuse the snapped sum, the raw sum decides.
        Ok(self.hull(hull, true).ok().and_then(Result::ok).flatten())
    }

    fn raw_hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        _: &mut ClosestToOrigin<6>,
        _: Expansion,
    ) -> Result<Built<'h>, QualityError> {
        let source = self.search.nearest.source_mut();
        source.fill(self.cones, self.with_zero_wrench, true);
        match self.hull(hull, false) {
            Ok(Ok(built)) => Ok(built),
            // The source returns only points strictly beyond (exact test) and within its
            // seeds' range; a broken promise is reported, not assumed away.
            Ok(Err(e)) => Err(QualityError::Source(e)),
            Err(e) => Err(QualityError::Hull(e)),
        }
    }

    fn raw_point(&self, hull: &Hull<6>, v: usize) -> Option<[f64; 6]> {
        self.search.nearest.source().raw_point(&hull.point(v))
    }

    fn raw_bounds(&self) -> (f64, f64) {
        raw_bounds(self.cones, self.raw_sets())
    }

    fn raw_support(&self, u: &[f64; 6]) -> (f64, f64) {
        sum_support_with_error(self.raw_sets(), u)
    }

    fn outside_bound(&mut self) -> Option<Quality> {
        zero_wrench_bound(self.with_zero_wrench)
    }
}

/// With the zero wrench: when GJK certifies that the *union* of the raw cone edges `union` does
/// not hold the origin, the grasp is not force closure and Q∞ = 0 exactly (the origin, a point of
/// the sum, is on its boundary: the two hulls have the same force closure).
fn union_separated(union: &[[f64; 6]], gjk: &mut Gjk<6>, started: Instant) -> Option<Quality> {
    let (_, inserted) = certified_outside(union, gjk)?;
    let origin = std::iter::once([0.0; 6]);
    Some(Quality::new(
        0.0,
        origin,
        no_hull_stats(1 + inserted, started),
    ))
}

/// With the zero wrench, the origin is a point of the sum: Q∞ ≥ 0.
fn zero_wrench_bound(with_zero_wrench: bool) -> Option<Quality> {
    let origin = std::iter::once([0.0; 6]);
    with_zero_wrench.then(|| Quality::new(0.0, origin, Stats::default()))
}

/// The index of the first point of `set` maximising `d·p` (as the slices' [`Support`]).
fn first_maximiser(set: &[[f64; 6]], d: &[f64; 6]) -> usize {
    let mut best = (f64::NEG_INFINITY, 0);
    for (i, p) in set.iter().enumerate() {
        let height = dot(*d, *p);
        if height > best.0 || i == 0 {
            best = (height, i);
        }
    }
    best.1
}

/// GJK on the support function `support` of a Minkowski sum, from its support points along
/// [`SEED_DIRECTIONS`] (in `seeds`): the quality when the sum is certified not to hold the
/// origin.
fn separated_sum(
    mut support: impl FnMut(&[f64; 6]) -> [f64; 6],
    seeds: &mut Vec<[f64; 6]>,
    scale: f64,
    gjk: &mut Gjk<6>,
    started: Instant,
) -> Option<Quality> {
    seed_points(seeds, &mut support);
    match gjk.run(
        &mut SupportFn(support),
        scale,
        seeds,
        GJK_ITERATIONS,
        GJK_TOUCHING,
    ) {
        GjkVerdict::Separated { distance, inserted } => {
            let stats = no_hull_stats(seeds.len() + inserted, started);
            Some(Quality::new(-distance, gjk.face().iter().copied(), stats))
        }
        _ => None,
    }
}

/// Q∞'s wrench set for the full method: the Minkowski sum materialised (up to
/// [`MINKOWSKI_MATERIALISE_LIMIT`] points), snapped for the search and raw for the exact hull,
/// in the odometer order of [`materialise`].
pub(super) struct MaterialisedSum<'a> {
    cones: &'a SnappedCones,
    with_zero_wrench: bool,
    raw_sets: Vec<Vec<[f64; 6]>>,
    /// The materialised points: snapped, then raw once [`WrenchSet::raw_hull`] ran.
    out: &'a mut Vec<[f64; 6]>,
    out_is_raw: bool,
    seeds: Vec<[f64; 6]>,
    scale: f64,
}

impl<'a> MaterialisedSum<'a> {
    /// The sum of `cones`' contact sets (with the zero wrench if asked), materialised in `out`.
    pub(super) fn new(
        cones: &'a SnappedCones,
        with_zero_wrench: bool,
        out: &'a mut Vec<[f64; 6]>,
    ) -> Self {
        let mut raw_sets = Vec::new();
        fill_sets(&mut raw_sets, cones, with_zero_wrench, true);
        let scale = raw_scale(&raw_sets);
        MaterialisedSum {
            cones,
            with_zero_wrench,
            raw_sets,
            out,
            out_is_raw: false,
            seeds: Vec::new(),
            scale,
        }
    }
}

impl WrenchSet for MaterialisedSum<'_> {
    fn scale(&self) -> f64 {
        self.scale
    }

    fn separated(&mut self, gjk: &mut Gjk<6>, started: Instant) -> Option<Quality> {
        if self.with_zero_wrench
            && let Some(quality) = union_separated(&self.cones.raw, gjk, started)
        {
            return Some(quality);
        }
        let raw_sets = &self.raw_sets;
        let support = |v: &[f64; 6]| sum_support(raw_sets, v);
        separated_sum(support, &mut self.seeds, self.scale, gjk, started)
    }

    fn is_flat(&mut self, flatness: &mut Flatness) -> bool {
        flat_contacts(&self.raw_sets, self.scale, flatness)
    }

    fn flat_value(&mut self, gjk: &mut Gjk<6>, started: Instant) -> Result<Quality, QualityError> {
        if self.out_is_raw {
            // The raw sum, materialised and without a hull: Wolfe's algorithm over its points.
            return Ok(degenerate(self.out, started));
        }
        let (cones, zero) = (self.cones, self.with_zero_wrench);
        flat_sum(
            cones,
            zero,
            &self.raw_sets,
            self.scale,
            &mut self.seeds,
            gjk,
            started,
        )
    }

    fn snapped_hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        nearest: &mut ClosestToOrigin<6>,
        expansion: Expansion,
    ) -> Result<Built<'h>, QualityError> {
        materialise(self.cones, self.with_zero_wrench, false, self.out)?;
        self.out_is_raw = false;
        Ok(nearest_hull(hull, self.out, None, nearest, expansion).unwrap_or(None))
    }

    fn raw_hull<'h>(
        &mut self,
        hull: &'h mut Option<Hull<6>>,
        nearest: &mut ClosestToOrigin<6>,
        expansion: Expansion,
    ) -> Result<Built<'h>, QualityError> {
        materialise(self.cones, self.with_zero_wrench, true, self.out)?;
        self.out_is_raw = true;
        nearest_hull(hull, self.out, None, nearest, expansion).map_err(QualityError::Hull)
    }

    fn raw_point(&self, _: &Hull<6>, v: usize) -> Option<[f64; 6]> {
        // Point v of the odometer order: contact c's choice is digit c (most significant
        // first), in the mixed radix of the sets' sizes (a soft contact's set is twice a hard
        // one's).
        let m = self.raw_sets.len();
        let mut rest = v;
        let mut digits = [0usize; crate::grasp::MAX_CONTACTS];
        for c in (0..m).rev() {
            let size = self.raw_sets[c].len();
            digits[c] = rest % size;
            rest /= size;
        }
        (rest == 0).then(|| sum(&self.raw_sets, digits[..m].iter().copied()))
    }

    fn raw_bounds(&self) -> (f64, f64) {
        raw_bounds(self.cones, &self.raw_sets)
    }

    fn raw_support(&self, u: &[f64; 6]) -> (f64, f64) {
        sum_support_with_error(&self.raw_sets, u)
    }

    fn outside_bound(&mut self) -> Option<Quality> {
        zero_wrench_bound(self.with_zero_wrench)
    }
}

/// Q∞ by Qhull (a baseline outside the cascade): Qhull's hull of the materialised raw sum.
pub(super) fn qhull(
    cones: &SnappedCones,
    with_zero_wrench: bool,
    out: &mut Vec<[f64; 6]>,
    started: Instant,
) -> Result<Quality, QualityError> {
    if !cfg!(feature = "qhull") {
        return Err(QualityError::QhullUnavailable);
    }
    let mut raw_sets = Vec::new();
    fill_sets(&mut raw_sets, cones, with_zero_wrench, true);
    let scale = raw_scale(&raw_sets);
    materialise(cones, with_zero_wrench, true, out)?;
    Ok(super::qhull_q1(out, started)?.banded(scale))
}

/// Whether the contacts' raw wrench sets (zero wrench or not) lie within a slab through the
/// origin thin enough that their Minkowski sum (a slab `m` times as wide) is within [`FLAT`] of
/// its scale of a hyperplane: never force closure, answered by [`flat_sum`] (see
/// [`flatness`](crate::grasp::flatness)).
fn flat_contacts(raw_sets: &[Vec<[f64; 6]>], scale: f64, flatness: &mut Flatness) -> bool {
    let limit = FLAT * scale / raw_sets.len().max(1) as f64;
    flatness.within(raw_sets.iter().flatten().copied(), limit)
}

/// −(distance from the origin) of a sum spanning fewer than six dimensions, never force closure:
/// GJK run to convergence on the support function of the sum of `raw_sets`, whose points have
/// norms below `scale` (the origin may lie in the sum, so it must not stop at "touching"),
/// seeded in `seeds`; should it not converge, Wolfe's algorithm over the materialised raw sum,
/// when that fits.
fn flat_sum(
    cones: &SnappedCones,
    with_zero_wrench: bool,
    raw_sets: &[Vec<[f64; 6]>],
    scale: f64,
    seeds: &mut Vec<[f64; 6]>,
    gjk: &mut Gjk<6>,
    started: Instant,
) -> Result<Quality, QualityError> {
    seed_points(seeds, |d| sum_support(raw_sets, d));
    let support = |v: &[f64; 6]| sum_support(raw_sets, v);
    if with_zero_wrench {
        // The origin is in the sum (every contact's zero wrench), which spans fewer than six
        // dimensions: it lies on the sum's boundary, at distance exactly 0.
        let origin = std::iter::once([0.0; 6]);
        return Ok(Quality::new(0.0, origin, no_hull_stats(0, started)));
    }
    match gjk.run(
        &mut SupportFn(support),
        scale,
        seeds,
        16 * GJK_ITERATIONS,
        0.0,
    ) {
        GjkVerdict::Separated { distance, inserted }
        | GjkVerdict::Touching { distance, inserted }
        | GjkVerdict::Stalled { distance, inserted } => Ok(Quality::new(
            0.0 - distance,
            gjk.face().iter().copied(),
            no_hull_stats(seeds.len() + inserted, started),
        )),
        GjkVerdict::Undecided => {
            let mut all = Vec::new();
            materialise(cones, with_zero_wrench, true, &mut all)?;
            let mut quality = degenerate(&all, started);
            quality.stats = no_hull_stats(all.len(), started);
            Ok(quality)
        }
    }
}
