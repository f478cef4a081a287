//! Q∞ over the Minkowski sum ⊕_i W_i, implicitly (support function) or materialised.

use super::{BOUNDARY, HullBuffers, Quality, QualityError, degenerate, full_q1, no_hull_stats};
use crate::geometry::vector::dot;
use crate::geometry::{GJK_ITERATIONS, GJK_TOUCHING, Gjk, GjkVerdict, Support, SupportFn};
use crate::grasp::certify::{self, RawSide, UnitBall, support_with_error};
use crate::grasp::flatness::{FLAT, Flatness};
use crate::grasp::snap::SnappedCones;
use crate::predicates::Sign;
use crate::strategy::{ClosestToOrigin, MinkowskiSum, PointSource};
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

/// The raw side of a Minkowski sum for [`certify::bracket`]: `δ` (the distance between a
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
    /// The caller's raw wrenches, unscaled: the union whose force closure the sum shares.
    union: Vec<[f64; 6]>,
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
        self.union.clear();
        self.union.extend_from_slice(&cones.raw);
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

    /// The support point of the union of the contacts' raw cone edges (no zero wrench): the
    /// hull whose force closure Q∞ with the zero wrench shares.
    fn raw_union_support(&self, direction: &[f64; 6]) -> [f64; 6] {
        let mut best = (f64::NEG_INFINITY, [0.0; 6]);
        for w in &self.union {
            let height = dot(*direction, *w);
            if height > best.0 {
                best = (height, *w);
            }
        }
        best.1
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
/// (inside the strategy, with its queue), the seeds, GJK's corral and the hull's arena.
#[derive(Clone, Debug)]
pub(super) struct MinkowskiBuffers {
    nearest: ClosestToOrigin<6, MinkowskiSource>,
    seeds: Vec<[f64; 6]>,
    gjk: Gjk<6>,
    hull: Option<Hull<6>>,
    bracket: certify::BracketScratch,
    flatness: Flatness,
}

impl Default for MinkowskiBuffers {
    fn default() -> Self {
        MinkowskiBuffers {
            nearest: ClosestToOrigin::with_source([0.0; 6], MinkowskiSource::default()),
            seeds: Vec::new(),
            gjk: Gjk::default(),
            hull: None,
            flatness: Flatness::default(),
            bracket: certify::BracketScratch::default(),
        }
    }
}

/// The sum over contacts of the largest wrench norm of `sets`.
fn raw_scale(sets: &[Vec<[f64; 6]>]) -> f64 {
    sets.iter()
        .map(|set| set.iter().map(|w| dot(*w, *w).sqrt()).fold(0.0, f64::max))
        .sum()
}

/// Q∞ of the raw sum from `hull`, a hull of snapped Minkowski points holding the origin strictly
/// inside, when the certified bracket is narrow enough; `raw_point` names the raw sum behind a
/// hull input.
fn certify_sum(
    hull: &Hull<6>,
    cones: &SnappedCones,
    raw_sets: &[Vec<[f64; 6]>],
    mut raw_point: impl FnMut(usize) -> Option<[f64; 6]>,
    scratch: &mut certify::BracketScratch,
) -> Option<Quality> {
    let (delta, error) = raw_bounds(cones, raw_sets);
    let mut side = RawSide {
        point: &mut raw_point,
        error,
        delta,
        support: |u: &[f64; 6]| sum_support_with_error(raw_sets, u),
    };
    let b = certify::bracket(hull, &mut side, &mut UnitBall, scratch)?;
    let scale = raw_scale(raw_sets);
    let value = b.value_within(scale)?;
    let vertices = hull.facet(b.facet).vertices();
    let deciding = vertices.iter().filter_map(|&v| raw_point(v));
    let quality = Quality::new(value, deciding, hull.stats());
    Some(
        quality
            .with_ties(hull, b.facet, scale, delta + error, Some(&*scratch))
            .banded(scale),
    )
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

/// Q∞ of the grasp behind `cones` by the partial hull over the implicit Minkowski sum.
///
/// In order, each step only when the previous one cannot decide:
/// 1. with the zero wrench, GJK on the *union* of the raw cone edges: a certified separation
///    means the grasp is not force closure, and then Q∞ = 0 exactly (the origin, a point of the
///    sum, is on its boundary: the two hulls have the same force closure);
/// 2. GJK on the raw sum's support function: a certified separation gives −distance;
/// 3. contacts whose raw wrenches lie within a slab through the origin thin enough that the sum
///    is within [`FLAT`] of its scale of a hyperplane ([`crate::grasp::flatness`]: two contacts,
///    contacts on a line or at one or two points) are not force closure: −distance by GJK run to
///    convergence, exactly 0 with the zero wrench (the origin is then a point of the flat sum);
/// 4. the exact partial hull of the *snapped* sum, seeded with its support points along 42 fixed
///    directions, its answer certified on the raw sum ([`certify`]);
/// 5. the exact partial hull of the raw sum (points summed in `f64`, within `1e−15` of the scale
///    of the exact sums), when the certificate cannot decide;
/// 6. a raw sum spanning fewer than six dimensions (no hull) is not force closure: its distance
///    by GJK, or by Wolfe's algorithm over the materialised sum should GJK not converge.
pub(super) fn partial(
    cones: &SnappedCones,
    with_zero_wrench: bool,
    buffers: &mut MinkowskiBuffers,
) -> Result<Quality, QualityError> {
    let started = Instant::now();
    let MinkowskiBuffers {
        nearest,
        seeds,
        gjk,
        hull,
        bracket,
        flatness,
    } = buffers;
    let source = nearest.source_mut();
    source.fill(cones, with_zero_wrench, false);
    let scale = source.raw_scale();
    if with_zero_wrench {
        let largest = source
            .union
            .iter()
            .fold(0.0, |m: f64, w| m.max(dot(*w, *w).sqrt()));
        let start = [source.raw_union_support(&[1.0, 0.0, 0.0, 0.0, 0.0, 0.0])];
        let verdict = gjk.run(
            &mut SupportFn(|v: &[f64; 6]| source.raw_union_support(v)),
            largest,
            &start,
            GJK_ITERATIONS,
            GJK_TOUCHING,
        );
        if let GjkVerdict::Separated { inserted, .. } = verdict {
            let origin = std::iter::once([0.0; 6]);
            let stats = no_hull_stats(1 + inserted, started);
            return Ok(Quality::new(0.0, origin, stats).banded(scale));
        }
    }
    seed_points(seeds, |d| sum_support(&source.raw_sets, d));
    let support = |v: &[f64; 6]| sum_support(&source.raw_sets, v);
    if let GjkVerdict::Separated { distance, inserted } = gjk.run(
        &mut SupportFn(support),
        scale,
        seeds,
        GJK_ITERATIONS,
        GJK_TOUCHING,
    ) {
        let stats = no_hull_stats(seeds.len() + inserted, started);
        let face = gjk.face().iter().copied();
        return Ok(Quality::new(-distance, face, stats).banded(scale));
    }
    if flat_contacts(&source.raw_sets, scale, flatness) {
        let q = flat_sum(cones, with_zero_wrench, support, scale, seeds, gjk, started)?;
        return Ok(q.banded(scale));
    }
    seed_points(seeds, |d| {
        source.support_point(d).expect("a contact has cone edges")
    });
    let h = hull.get_or_insert_with(Hull::empty);
    let snapped = h.rebuild_with_strategy(seeds, &mut *nearest);
    // The source keeps its contract (its points are checked exactly, and within the seeds'
    // range); should it not, the raw sum below decides.
    if let Ok(Ok(result)) = snapped {
        let source = nearest.source_mut();
        let raw_point = |v: usize| source.raw_point(&h.point(v));
        if result.signed_distance > 0.0
            && let Some(quality) = certify_sum(h, cones, &source.raw_sets, raw_point, bracket)
        {
            return Ok(quality);
        }
        // A boundary grasp with the zero wrench: the origin, a point of the sum, is within δ of
        // the snapped surface. The sum's value lies in [0, the upper bound along the raw simplex
        // of the nearest facet]; when that is within `BOUNDARY` of the scale, its midpoint is
        // the value to the accuracy promised near zero (the raw sum's exact hull would be
        // slivers, facets the floating-point filter cannot decide: docs/benchmarks.md, "Issue 11").
        if with_zero_wrench {
            let raw_point = |v: usize| source.raw_point(&h.point(v));
            let (delta, error) = raw_bounds(cones, &source.raw_sets);
            let raw_sets = &source.raw_sets;
            let mut side = RawSide {
                point: raw_point,
                error,
                delta,
                support: |u: &[f64; 6]| sum_support_with_error(raw_sets, u),
            };
            if let Some(high) =
                certify::upper_bound_at(h, result.closest_facet, &mut side, &mut UnitBall)
                && high <= BOUNDARY * scale
            {
                let origin = std::iter::once([0.0; 6]);
                return Ok(Quality::new(0.5 * high.max(0.0), origin, h.stats()).banded(scale));
            }
        }
    }
    // The exact engine on the raw sum.
    let source = nearest.source_mut();
    source.fill(cones, with_zero_wrench, true);
    seed_points(seeds, |d| {
        source.support_point(d).expect("a contact has cone edges")
    });
    match h.rebuild_with_strategy(seeds, &mut *nearest) {
        Ok(Ok(result)) => Ok(Quality::new(
            result.signed_distance,
            result.closest_facet_vertices.iter().map(|&v| h.point(v)),
            result.stats,
        )
        .with_ties(h, result.closest_facet, scale, 0.0, None)
        .banded(scale)),
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
            let source = nearest.source_mut();
            let support = |v: &[f64; 6]| sum_support(&source.raw_sets, v);
            let q = flat_sum(cones, with_zero_wrench, support, scale, seeds, gjk, started)?;
            Ok(q.banded(scale))
        }
        Err(e) => Err(QualityError::Hull(e)),
        // The source returns only points strictly beyond (exact test) and within its seeds'
        // range; a broken promise is reported, not assumed away.
        Ok(Err(e)) => Err(QualityError::Source(e)),
    }
}

/// Q∞ by a full method: the full hull of the materialised snapped sum, certified on the raw sum
/// when it holds the origin; otherwise GJK on the raw sum, then the full hull of the materialised
/// raw sum. `out` is the buffer for the materialised points.
pub(super) fn full(
    cones: &SnappedCones,
    with_zero_wrench: bool,
    method: super::Method,
    out: &mut Vec<[f64; 6]>,
    buffers: &mut HullBuffers,
    started: Instant,
) -> Result<Quality, QualityError> {
    let mut raw_sets = Vec::new();
    fill_sets(&mut raw_sets, cones, with_zero_wrench, true);
    let scale = raw_scale(&raw_sets);
    if method == super::Method::Qhull {
        if !cfg!(feature = "qhull") {
            return Err(QualityError::QhullUnavailable);
        }
        materialise(cones, with_zero_wrench, true, out)?;
        return Ok(super::qhull_q1(out, started)?.banded(scale));
    }
    let _ = method;
    if flat_contacts(&raw_sets, scale, &mut buffers.flatness) {
        let mut seeds = Vec::new();
        seed_points(&mut seeds, |d| sum_support(&raw_sets, d));
        let support = |v: &[f64; 6]| sum_support(&raw_sets, v);
        let q = flat_sum(
            cones,
            with_zero_wrench,
            support,
            scale,
            &seeds,
            &mut buffers.gjk,
            started,
        )?;
        return Ok(q.banded(scale));
    }
    materialise(cones, with_zero_wrench, false, out)?;
    let m = raw_sets.len();
    // Point i of the odometer order: contact c's choice is digit c (most significant first), in
    // the mixed radix of the sets' sizes (a soft contact's set is twice a hard one's).
    let tuple_sum = |i: usize| {
        let mut rest = i;
        let mut digits = [0usize; 64];
        for c in (0..m.min(64)).rev() {
            let size = raw_sets[c].len();
            digits[c] = rest % size;
            rest /= size;
        }
        Some(sum(&raw_sets, digits[..m.min(64)].iter().copied()))
    };
    let strategy = crate::FarthestPoint::new();
    let snapped = HullBuffers::build(&mut buffers.hull, out, None, strategy);
    // The full hull's work, reported by a GJK answer too (as for Q1's full method).
    let mut full_stats = None;
    if let Ok((h, ())) = snapped {
        full_stats = Some(h.stats());
        if h.facets()
            .all(|(id, _)| h.side_of(id, &[0.0; 6]) == Sign::Negative)
            && let Some(quality) = certify_sum(h, cones, &raw_sets, tuple_sum, &mut buffers.bracket)
        {
            return Ok(quality);
        }
    }
    let mut seeds = Vec::new();
    seed_points(&mut seeds, |d| sum_support(&raw_sets, d));
    let support = |v: &[f64; 6]| sum_support(&raw_sets, v);
    if let GjkVerdict::Separated { distance, inserted } = buffers.gjk.run(
        &mut SupportFn(support),
        scale,
        &seeds,
        GJK_ITERATIONS,
        GJK_TOUCHING,
    ) {
        let stats = full_stats.unwrap_or_else(|| no_hull_stats(seeds.len() + inserted, started));
        let face = buffers.gjk.face().iter().copied();
        return Ok(Quality::new(-distance, face, stats).banded(scale));
    }
    materialise(cones, with_zero_wrench, true, out)?;
    Ok(full_q1(out, None, started, buffers)?.banded(scale))
}

/// Whether the contacts' raw wrench sets (zero wrench or not) lie within a slab through the
/// origin thin enough that their Minkowski sum (a slab `m` times as wide) is within [`FLAT`] of
/// its scale of a hyperplane: never force closure, answered by [`flat_sum`] (see
/// [`flatness`](crate::grasp::flatness)).
fn flat_contacts(raw_sets: &[Vec<[f64; 6]>], scale: f64, flatness: &mut Flatness) -> bool {
    let tau = flatness.slab(raw_sets.iter().flatten().copied());
    raw_sets.len() as f64 * tau <= FLAT * scale
}

/// −(distance from the origin) of a sum spanning fewer than six dimensions, never force closure:
/// GJK run to convergence on the support function `support` of a sum whose points have norms
/// below `scale` (the origin may lie in the sum, so it must not stop at "touching"); should it
/// not converge, Wolfe's algorithm over the materialised raw sum, when that fits.
fn flat_sum(
    cones: &SnappedCones,
    with_zero_wrench: bool,
    support: impl FnMut(&[f64; 6]) -> [f64; 6],
    scale: f64,
    seeds: &[[f64; 6]],
    gjk: &mut Gjk<6>,
    started: Instant,
) -> Result<Quality, QualityError> {
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
