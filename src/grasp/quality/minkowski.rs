//! Q∞ over the Minkowski sum ⊕_i W_i, implicitly (support function) or materialised.

use super::separation::{GJK_ITERATIONS, Gjk, TOUCHING, Verdict};
use super::{Quality, QualityError, degenerate, no_hull_stats};
use crate::grasp::snap::SnappedCones;
use crate::hull::dot;
use crate::predicates::Sign;
use crate::strategy::{ClosestToOrigin, PointSource};
use crate::{FacetId, Hull, HullError};
use std::time::Instant;

/// The most Minkowski points the full and Qhull methods materialise (2^20: 4 contacts × 32 edges).
pub const MINKOWSKI_MATERIALISE_LIMIT: usize = 1 << 20;

/// Refills `sets` with the per-contact wrench sets (with the zero wrench if asked), reusing
/// their buffers.
fn fill_sets(sets: &mut Vec<Vec<[f64; 6]>>, cones: &SnappedCones, with_zero_wrench: bool) {
    let contacts = cones.generators.len();
    sets.resize_with(contacts, Vec::new);
    for (i, set) in sets.iter_mut().enumerate() {
        set.clear();
        set.extend((0..cones.angles.len()).map(|j| cones.wrench(i, j)));
        if with_zero_wrench {
            set.push([0.0; 6]);
        }
    }
}

/// Σ_i sets[i][choice[i]], left to right (exact for snapped wrenches and up to 10 contacts).
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
    out: &mut Vec<[f64; 6]>,
) -> Result<(), QualityError> {
    let mut sets = Vec::new();
    fill_sets(&mut sets, cones, with_zero_wrench);
    let per = sets.first().map_or(0, Vec::len);
    let count = u32::try_from(sets.len())
        .ok()
        .and_then(|m| per.checked_pow(m));
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
            if choice[i] < per {
                break;
            }
            choice[i] = 0;
        }
    }
}

/// The Minkowski sum answered through its support function; refilled per grasp in place.
#[derive(Clone, Debug, Default)]
pub(super) struct MinkowskiSource {
    sets: Vec<Vec<[f64; 6]>>,
    /// Per contact: the largest wrench norm (for the score slack), computed once per grasp.
    sizes: Vec<f64>,
    /// Per contact: (score, edge) of the candidates for the current facet.
    candidates: Vec<Vec<(f64, usize)>>,
    choice: Vec<usize>,
    /// The odometer over tied candidates in [`PointSource::beyond`].
    position: Vec<usize>,
    /// Whether the last contact-set entry is the zero wrench.
    with_zero_wrench: bool,
}

impl MinkowskiSource {
    /// The sum for `cones`' grasp.
    fn fill(&mut self, cones: &SnappedCones, with_zero_wrench: bool) {
        fill_sets(&mut self.sets, cones, with_zero_wrench);
        self.with_zero_wrench = with_zero_wrench;
        self.sizes.clear();
        self.sizes.extend(
            self.sets
                .iter()
                .map(|set| set.iter().map(|w| dot(w, w).sqrt()).fold(0.0, f64::max)),
        );
        self.candidates.resize_with(self.sets.len(), Vec::new);
    }

    /// A bound on the norm of every point of the sum.
    fn scale(&self) -> f64 {
        self.sizes.iter().sum()
    }

    /// The support point of the union of the contacts' cone edges (no zero wrench): the hull
    /// whose force closure Q∞ with the zero wrench shares.
    fn union_support(&self, direction: &[f64; 6]) -> [f64; 6] {
        let zero = usize::from(self.with_zero_wrench);
        let mut best = (f64::NEG_INFINITY, [0.0; 6]);
        for w in self.sets.iter().flat_map(|set| &set[..set.len() - zero]) {
            let height = dot(direction, w);
            if height > best.0 {
                best = (height, *w);
            }
        }
        best.1
    }

    /// Each contact's support edge for `direction`, into `self.choice`.
    fn support_choice(&mut self, direction: &[f64; 6]) {
        self.choice.clear();
        self.choice.extend(self.sets.iter().map(|set| {
            (0..set.len())
                .max_by(|&a, &b| dot(direction, &set[a]).total_cmp(&dot(direction, &set[b])))
                .expect("a contact has cone edges")
        }));
    }
}

impl PointSource<6> for MinkowskiSource {
    /// Exact: a tuple strictly beyond the facet has, for every contact, a score within `gap` of
    /// that contact's best (see below), so testing every such tuple exactly misses none.
    fn beyond(&mut self, hull: &Hull<6>, id: FacetId) -> Option<[f64; 6]> {
        let facet = hull.facet(id);
        let normal = facet.normal();
        let offset = facet.offset();
        // Slack per contact covering the (precise, 1e−11 relative) normal's error and the
        // rounding of the scores, and the same for the offset.
        let mut best_total = 0.0;
        let mut slack = 1e-10 * offset.abs();
        for ((set, candidates), &size) in
            self.sets.iter().zip(&mut self.candidates).zip(&self.sizes)
        {
            candidates.clear();
            candidates.extend(set.iter().enumerate().map(|(j, w)| (dot(&normal, w), j)));
            let best = candidates
                .iter()
                .map(|c| c.0)
                .fold(f64::NEG_INFINITY, f64::max);
            best_total += best;
            slack += 1e-10 * size;
        }
        // Any tuple beyond satisfies Σ score > offset − slack, hence score_i > best_i − gap.
        let gap = best_total - offset + slack;
        if gap < 0.0 {
            return None;
        }
        for candidates in &mut self.candidates {
            let best = candidates
                .iter()
                .map(|c| c.0)
                .fold(f64::NEG_INFINITY, f64::max);
            candidates.retain(|c| c.0 >= best - gap);
            candidates.sort_unstable_by(|a, b| b.0.total_cmp(&a.0));
        }
        // The best tuple first; when it is clearly beyond, no enumeration is needed.
        self.choice.clear();
        self.choice.extend(self.candidates.iter().map(|c| c[0].1));
        let top = sum(&self.sets, self.choice.iter().copied());
        if hull.side_of(id, &top) == Sign::Positive {
            return Some(top);
        }
        // Near a true facet of the sum: enumerate the (few) tied tuples exactly.
        let mut position = std::mem::take(&mut self.position);
        position.clear();
        position.resize(self.sets.len(), 0);
        let found = 'odometer: loop {
            let mut i = position.len();
            loop {
                if i == 0 {
                    break 'odometer None;
                }
                i -= 1;
                position[i] += 1;
                if position[i] < self.candidates[i].len() {
                    break;
                }
                position[i] = 0;
            }
            let point = sum(
                &self.sets,
                position.iter().zip(&self.candidates).map(|(&p, c)| c[p].1),
            );
            if hull.side_of(id, &point) == Sign::Positive {
                break Some(point);
            }
        };
        self.position = position;
        found
    }

    fn support(&mut self, direction: &[f64; 6]) -> Option<[f64; 6]> {
        self.support_choice(direction);
        Some(sum(&self.sets, self.choice.iter().copied()))
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
    gjk: Gjk,
    hull: Option<Hull<6>>,
}

impl Default for MinkowskiBuffers {
    fn default() -> Self {
        MinkowskiBuffers {
            nearest: ClosestToOrigin::with_source([0.0; 6], MinkowskiSource::default()),
            seeds: Vec::new(),
            gjk: Gjk::default(),
            hull: None,
        }
    }
}

/// Q∞ of the grasp behind `cones` by the partial hull over the implicit Minkowski sum.
///
/// In order, each step only when the previous one cannot decide:
/// 1. with the zero wrench, GJK on the *union* of the cone edges: a certified separation means
///    the grasp is not force closure, and then Q∞ = 0 exactly (the origin, a point of the sum,
///    is on its boundary: the two hulls have the same force closure);
/// 2. GJK on the sum's support function: a certified separation gives −distance;
/// 3. the exact partial hull, seeded with the sum's support points along 42 fixed directions;
/// 4. a sum spanning fewer than six dimensions (no hull) is not force closure: its distance by
///    GJK, or by Wolfe's algorithm over the materialised sum should GJK not converge.
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
    } = buffers;
    let source = nearest.source_mut();
    source.fill(cones, with_zero_wrench);
    if with_zero_wrench {
        let scale = source.sizes.iter().fold(0.0, |m: f64, &s| m.max(s));
        let start = [source.union_support(&[1.0, 0.0, 0.0, 0.0, 0.0, 0.0])];
        let verdict = gjk.run(
            |v| source.union_support(v),
            scale,
            &start,
            GJK_ITERATIONS,
            TOUCHING,
        );
        if let Verdict::Separated { inserted, .. } = verdict {
            let origin = std::iter::once([0.0; 6]);
            return Ok(Quality::new(
                0.0,
                origin,
                no_hull_stats(1 + inserted, started),
            ));
        }
    }
    seeds.clear();
    for d in &SEED_DIRECTIONS {
        let p = source.support(d).expect("a contact has cone edges");
        if !seeds.contains(&p) {
            seeds.push(p);
        }
    }
    let scale = source.scale();
    let support = |v: &[f64; 6]| source.support(v).expect("a contact has cone edges");
    if let Verdict::Separated { distance, inserted } =
        gjk.run(support, scale, seeds, GJK_ITERATIONS, TOUCHING)
    {
        let stats = no_hull_stats(seeds.len() + inserted, started);
        return Ok(Quality::new(-distance, gjk.face().iter().copied(), stats));
    }
    let h = hull.get_or_insert_with(Hull::empty);
    match h.rebuild_with_strategy(seeds, &mut *nearest) {
        Ok(result) => Ok(Quality::new(
            result.signed_distance,
            result.closest_facet_vertices.iter().map(|&v| h.point(v)),
            result.stats,
        )),
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => flat_sum(
            cones,
            with_zero_wrench,
            nearest.source_mut(),
            seeds,
            gjk,
            started,
        ),
        Err(e) => unreachable!("snapped wrenches are finite: {e}"),
    }
}

/// −(distance from the origin) of a sum spanning fewer than six dimensions, never force closure:
/// GJK run to convergence (the origin may lie in the sum, so it must not stop at "touching");
/// should it not converge, Wolfe's algorithm over the materialised sum, when that fits.
fn flat_sum(
    cones: &SnappedCones,
    with_zero_wrench: bool,
    source: &mut MinkowskiSource,
    seeds: &[[f64; 6]],
    gjk: &mut Gjk,
    started: Instant,
) -> Result<Quality, QualityError> {
    let scale = source.scale();
    let support = |v: &[f64; 6]| source.support(v).expect("a contact has cone edges");
    match gjk.run(support, scale, seeds, 16 * GJK_ITERATIONS, 0.0) {
        Verdict::Separated { distance, inserted }
        | Verdict::Touching { distance, inserted }
        | Verdict::Stalled { distance, inserted } => Ok(Quality::new(
            0.0 - distance,
            gjk.face().iter().copied(),
            no_hull_stats(seeds.len() + inserted, started),
        )),
        Verdict::Undecided => {
            let mut all = Vec::new();
            materialise(cones, with_zero_wrench, &mut all)?;
            let mut quality = degenerate(&all, started);
            quality.stats = no_hull_stats(all.len(), started);
            Ok(quality)
        }
    }
}
