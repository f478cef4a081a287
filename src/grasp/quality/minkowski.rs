//! Q∞ over the Minkowski sum ⊕_i W_i, implicitly (support function) or materialised.

use super::separation::{GJK_ITERATIONS, Gjk, gjk};
use super::{Quality, QualityError, degenerate, no_hull_stats};
use crate::grasp::snap::SnappedCones;
use crate::hull::dot;
use crate::predicates::Sign;
use crate::strategy::{ClosestToOrigin, PointSource, Stats};
use crate::{FacetId, Hull, HullError};
use std::time::Instant;

/// The most Minkowski points the full and Qhull methods materialise (2^20: 4 contacts × 32 edges).
pub const MINKOWSKI_MATERIALISE_LIMIT: usize = 1 << 20;

/// Per-contact wrench sets (with the zero wrench if asked).
fn contact_sets(cones: &SnappedCones, with_zero_wrench: bool) -> Vec<Vec<[f64; 6]>> {
    (0..cones.generators.len())
        .map(|i| {
            let mut set: Vec<[f64; 6]> = (0..cones.angles.len())
                .map(|j| cones.wrench(i, j))
                .collect();
            if with_zero_wrench {
                set.push([0.0; 6]);
            }
            set
        })
        .collect()
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
    let sets = contact_sets(cones, with_zero_wrench);
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

/// The Minkowski sum answered through its support function.
struct MinkowskiSource {
    sets: Vec<Vec<[f64; 6]>>,
    /// Per contact: the largest wrench norm (for the score slack), computed once per grasp.
    sizes: Vec<f64>,
    /// Per contact: (score, edge) of the candidates for the current facet.
    candidates: Vec<Vec<(f64, usize)>>,
    choice: Vec<usize>,
}

impl MinkowskiSource {
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
        let mut position = vec![0usize; self.sets.len()];
        loop {
            let mut i = position.len();
            loop {
                if i == 0 {
                    return None;
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
                return Some(point);
            }
        }
    }

    fn support(&mut self, direction: &[f64; 6]) -> Option<[f64; 6]> {
        self.support_choice(direction);
        Some(sum(&self.sets, self.choice.iter().copied()))
    }
}

/// Fixed directions that seed the partial hull: ± every axis (so the hull's coordinate range
/// covers every Minkowski point) and the 2·15 diagonals e_a ± e_b.
fn seed_directions() -> Vec<[f64; 6]> {
    let mut directions = Vec::new();
    for a in 0..6 {
        for sign in [1.0, -1.0] {
            let mut d = [0.0; 6];
            d[a] = sign;
            directions.push(d);
        }
        for b in a + 1..6 {
            for sign in [1.0, -1.0] {
                let mut d = [0.0; 6];
                d[a] = 1.0;
                d[b] = sign;
                directions.push(d);
            }
        }
    }
    directions
}

/// The implicit sum of `sets`.
fn minkowski_source(sets: Vec<Vec<[f64; 6]>>) -> MinkowskiSource {
    MinkowskiSource {
        sizes: sets
            .iter()
            .map(|set| set.iter().map(|w| dot(w, w).sqrt()).fold(0.0, f64::max))
            .collect(),
        candidates: vec![Vec::new(); sets.len()],
        choice: Vec::new(),
        sets,
    }
}

/// When the origin lies clearly outside the sum: its distance and the support points spanning
/// the nearest face, without building a hull, whose growth over the sum's finely faceted
/// boundary costs up to 10⁵ inserted points there. `None` when the origin is inside, within
/// rounding of the boundary, or not separated within [`GJK_ITERATIONS`] (see [`gjk`] for the
/// certificate).
fn outside_by_gjk(
    source: &mut MinkowskiSource,
    seeds: &[[f64; 6]],
) -> Option<(f64, Vec<[f64; 6]>, usize)> {
    match minkowski_gjk(source, seeds, GJK_ITERATIONS) {
        Gjk::Separated {
            distance,
            face,
            inserted,
        } => Some((distance, face, inserted)),
        Gjk::Touching { .. } | Gjk::Undecided => None,
    }
}

/// [`gjk`] over the sum's support function; its points are bounded by the sum of the contacts'
/// largest norms.
fn minkowski_gjk(source: &mut MinkowskiSource, seeds: &[[f64; 6]], iterations: usize) -> Gjk {
    let scale: f64 = source.sizes.iter().sum();
    gjk(
        |v| source.support(v).expect("a contact has cone edges"),
        scale,
        seeds,
        iterations,
    )
}

pub(super) fn partial(
    cones: &SnappedCones,
    with_zero_wrench: bool,
) -> Result<Quality, QualityError> {
    let started = Instant::now();
    let mut source = minkowski_source(contact_sets(cones, with_zero_wrench));
    let mut seeds: Vec<[f64; 6]> = Vec::new();
    for d in seed_directions() {
        let p = source.support(&d).expect("non-empty");
        if !seeds.contains(&p) {
            seeds.push(p);
        }
    }
    if let Some((distance, face, inserted)) = outside_by_gjk(&mut source, &seeds) {
        let stats = Stats {
            points_processed: seeds.len() + inserted,
            facets_created: 0,
            expansions: 0,
            elapsed: started.elapsed(),
        };
        return Ok(Quality::new(-distance, face.into_iter(), stats));
    }
    let strategy = ClosestToOrigin::with_source([0.0; 6], source);
    match Hull::try_with_strategy(&seeds, strategy) {
        Ok((hull, result)) => Ok(Quality::new(
            result.signed_distance,
            result.closest_facet_vertices.iter().map(|&v| hull.point(v)),
            result.stats,
        )),
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
            // The sum spans fewer than 6 dimensions: not force closure; its distance from the
            // materialised set (flat sums are small: a rank-deficient grasp's edges).
            let mut all = Vec::new();
            match materialise(cones, with_zero_wrench, &mut all) {
                Ok(()) => {
                    let mut quality = degenerate(&all, started);
                    quality.stats = no_hull_stats(all.len(), started);
                    Ok(quality)
                }
                // Too many to materialise: the origin is within rounding of the flat sum (else
                // GJK would have separated it), so its distance is 0 up to rounding; GJK with a
                // larger budget says which face holds the touching point.
                Err(too_large @ QualityError::MinkowskiTooLarge { .. }) => {
                    let mut source = minkowski_source(contact_sets(cones, with_zero_wrench));
                    match minkowski_gjk(&mut source, &seeds, 16 * GJK_ITERATIONS) {
                        Gjk::Separated {
                            distance,
                            face,
                            inserted,
                        } => Ok(Quality::new(
                            -distance,
                            face.into_iter(),
                            no_hull_stats(seeds.len() + inserted, started),
                        )),
                        Gjk::Touching { face, inserted } => Ok(Quality::new(
                            0.0,
                            face.into_iter(),
                            no_hull_stats(seeds.len() + inserted, started),
                        )),
                        Gjk::Undecided => Err(too_large),
                    }
                }
                Err(e) => Err(e),
            }
        }
        Err(e) => unreachable!("snapped wrenches are finite: {e}"),
    }
}
