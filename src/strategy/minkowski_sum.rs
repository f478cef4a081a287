//! The Minkowski sum of explicit point sets as an implicit [`PointSource`]: a partial hull grows
//! over `S_0 ⊕ S_1 ⊕ …` through its support function, never materialising the product.

use super::PointSource;
use crate::geometry::Support;
use crate::geometry::vector::dot;
use crate::hull::{FacetId, Hull};
use crate::predicates::Sign;

/// The point set `{fl(s_0 + s_1 + …) : s_i ∈ S_i}` — each sum taken left to right in `f64` —
/// given by its sets, for [`ClosestToOrigin::with_source`](super::ClosestToOrigin::with_source).
/// A facet's point beyond is found from each set's support values with a slack covering the
/// facet normal's error and every rounding, then decided by the exact predicate, so "nothing
/// beyond" is exact for these points (the [`PointSource`] contract).
///
/// With two sets `A` and `−B` the points are the differences `fl(a − b)`: the set whose
/// signed distance from the origin is the penetration depth of `A` and `B`
/// ([`penetration_depth`](super::penetration_depth) builds on this).
///
/// ```
/// use pqhull::geometry::Support;
/// use pqhull::strategy::MinkowskiSum;
/// use pqhull::{ClosestToOrigin, Hull};
/// // The square [−1, 1]² as the sum of two segments.
/// let mut sum = MinkowskiSum::new(vec![
///     vec![[-1.0, 0.0], [1.0, 0.0]],
///     vec![[0.0, -1.0], [0.0, 1.0]],
/// ]);
/// assert_eq!(sum.support_point(&[1.0, 2.0]), Some([1.0, 1.0]));
/// // Seeded with its extreme points along the axes (as the contract asks), the partial hull
/// // finds the distance from (0.5, 0) to the square's boundary.
/// let seeds = [[1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]];
/// let strategy = ClosestToOrigin::with_source([0.5, 0.0], sum);
/// let (_, result) = Hull::try_with_strategy(&seeds, strategy)?;
/// assert!((result?.signed_distance - 0.5).abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct MinkowskiSum<const D: usize> {
    sets: Vec<Vec<[f64; D]>>,
    /// Per set: its largest point norm (the score slack's scale).
    sizes: Vec<f64>,
    /// Per set: (score, index) of the candidates for the facet being asked about.
    candidates: Vec<Vec<(f64, usize)>>,
    /// The odometer over tied candidates.
    position: Vec<usize>,
    /// The tuple behind the last point handed out.
    last: Vec<usize>,
}

impl<const D: usize> MinkowskiSum<D> {
    /// The sum of `sets`, each a non-empty list of finite points (not checked here: an empty
    /// set makes the sum empty, and [`support_point`](Support::support_point) then `None`).
    pub fn new(sets: Vec<Vec<[f64; D]>>) -> Self {
        let mut sum = Self::default();
        sum.refill(sets.len(), |i, set| set.extend_from_slice(&sets[i]));
        sum
    }

    /// Refills the sum in place with `count` sets, `fill(i, set)` writing set `i` into a cleared
    /// buffer: no allocation once the buffers have grown.
    pub fn refill(&mut self, count: usize, mut fill: impl FnMut(usize, &mut Vec<[f64; D]>)) {
        self.sets.resize_with(count, Vec::new);
        for (i, set) in self.sets.iter_mut().enumerate() {
            set.clear();
            fill(i, set);
        }
        self.sizes.clear();
        self.sizes.extend(
            self.sets
                .iter()
                .map(|set| set.iter().map(|&p| dot(p, p)).fold(0.0, f64::max).sqrt()),
        );
        self.candidates.resize_with(count, Vec::new);
    }

    /// The summed sets.
    pub fn sets(&self) -> &[Vec<[f64; D]>] {
        &self.sets
    }

    /// The index, in each set, of the summands of the last point handed out (by
    /// [`support_point`](Support::support_point) or [`PointSource::beyond`]).
    pub fn last_tuple(&self) -> &[usize] {
        &self.last
    }

    /// `fl(Σ_i sets[i][choice[i]])`, left to right.
    ///
    /// # Panics
    /// If an index is out of its set's range.
    pub fn sum_of(&self, choice: impl IntoIterator<Item = usize>) -> [f64; D] {
        sum(&self.sets, choice)
    }
}

/// `fl(Σ_i sets[i][choice[i]])`, left to right.
fn sum<const D: usize>(
    sets: &[Vec<[f64; D]>],
    choice: impl IntoIterator<Item = usize>,
) -> [f64; D] {
    let mut total = [0.0; D];
    for (set, j) in sets.iter().zip(choice) {
        for (t, x) in total.iter_mut().zip(&set[j]) {
            *t += x;
        }
    }
    total
}

impl<const D: usize> Support<D> for MinkowskiSum<D> {
    /// Each set's support point (the first of ties), summed.
    fn support_point(&mut self, direction: &[f64; D]) -> Option<[f64; D]> {
        self.last.clear();
        for set in &self.sets {
            let best = (0..set.len()).map(|j| (dot(*direction, set[j]), j)).fold(
                None,
                |best: Option<(f64, usize)>, c| match best {
                    Some(b) if b.0 >= c.0 => Some(b),
                    _ => Some(c),
                },
            )?;
            self.last.push(best.1);
        }
        Some(sum(&self.sets, self.last.iter().copied()))
    }
}

impl<const D: usize> PointSource<D> for MinkowskiSum<D> {
    /// Exact: a point strictly beyond the facet has, in every set, a summand whose score is
    /// within `gap` of that set's best (below), so testing every such tuple exactly misses none.
    fn beyond(&mut self, hull: &Hull<D>, id: FacetId) -> Option<[f64; D]> {
        let facet = hull.facet(id);
        // A precise normal is within 1e−11 relative of the exact one; a partial hull's other
        // facets may carry a thin facet's rough normal, so take the exact direction then.
        let (normal, offset) = if facet.normal_is_precise() {
            (facet.normal(), facet.offset())
        } else {
            let n = hull.exact_normal(id);
            let offset = facet
                .vertices()
                .iter()
                .map(|&v| dot(n, hull.point(v)))
                .fold(f64::NEG_INFINITY, f64::max);
            (n, offset)
        };
        // The slack covers the normal's error (1e−11 of each summand's size), the rounding of
        // the scores and of the sum (a few ulps of the sizes) and the offset's error.
        let mut best_total = 0.0;
        let mut slack = 1e-10 * offset.abs();
        for ((set, candidates), &size) in
            self.sets.iter().zip(&mut self.candidates).zip(&self.sizes)
        {
            candidates.clear();
            candidates.extend(set.iter().enumerate().map(|(j, p)| (dot(normal, *p), j)));
            let best = candidates
                .iter()
                .map(|c| c.0)
                .fold(f64::NEG_INFINITY, f64::max);
            best_total += best;
            slack += 1e-10 * size;
        }
        // A point beyond has Σ score > offset − slack, hence score_i > best_i − gap in each set.
        let gap = best_total - offset + slack;
        if gap.is_nan() || gap < 0.0 {
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
        let mut position = std::mem::take(&mut self.position);
        position.clear();
        position.resize(self.sets.len(), 0);
        let found = loop {
            let choice = position.iter().zip(&self.candidates).map(|(&p, c)| c[p].1);
            let point = sum(&self.sets, choice);
            if hull.side_of(id, &point) == Sign::Positive {
                break Some(point);
            }
            // Next tuple of the (few) near-ties, odometer order.
            let mut i = position.len();
            let advanced = loop {
                if i == 0 {
                    break false;
                }
                i -= 1;
                position[i] += 1;
                if position[i] < self.candidates[i].len() {
                    break true;
                }
                position[i] = 0;
            };
            if !advanced {
                break None;
            }
        };
        if found.is_some() {
            self.last.clear();
            self.last
                .extend(position.iter().zip(&self.candidates).map(|(&p, c)| c[p].1));
        }
        self.position = position;
        found
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn support_point_sums_each_sets_support() {
        let mut sum = MinkowskiSum::new(vec![
            vec![[0.0, 0.0], [2.0, 0.0]],
            vec![[0.0, 1.0], [0.0, -3.0]],
        ]);
        assert_eq!(sum.support_point(&[1.0, -1.0]), Some([2.0, -3.0]));
        assert_eq!(sum.last_tuple(), &[1, 1]);
        let mut empty = MinkowskiSum::<2>::new(vec![vec![[1.0, 1.0]], vec![]]);
        assert_eq!(empty.support_point(&[1.0, 0.0]), None);
    }
}
