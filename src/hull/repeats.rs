//! Repeated input points: only the first copy of a point (its smallest index) ever enters an
//! outside set or names a vertex.
//!
//! A copy is never beyond a hull holding the first (equal points are on the same side of every
//! plane), so the hull is the same without it, and the time does not grow with repetition:
//! copies would otherwise follow the first through every outside-set redistribution.
//!
//! Copies are looked up only among the points beyond the initial simplex, once it has
//! partitioned them. A copy of a point inside the simplex is inside too and costs its side
//! tests, as any inside point. Equal points get equal decisions from the partition (the same
//! tests, in the same order, on the same coordinates), so every copy of a point beyond the
//! simplex is in its first copy's outside set, after it. The simplex's own vertices are named
//! by their first copies from the same pass (a copy of a vertex is on the simplex). Hashing
//! every input point instead, before the partition, was about a quarter of the time of a 2-D
//! hull of 1,000,000 uniform points (a random probe into a table of millions of slots per
//! point), and about half of those points fall inside the first triangle. (Before the table, a
//! sort of (hash, index) pairs was a fifth of the hull of 100,000 uniform 3-D points, and a sort
//! of the points themselves a quarter.)

use super::{FacetId, Hull};

/// An empty slot of the table: no input index, since inputs are indexed by `u32` below it.
const EMPTY_SLOT: u32 = u32::MAX;

/// The table's smallest size; it doubles whenever it would be more than two thirds full.
const MIN_SLOTS: usize = 1 << 10;

/// First copies among the points looked up, and the later copies found.
///
/// Written by hand, not `std::collections::HashMap`: the key is a point of the hull's own
/// array, found by index, which std's map cannot look up without storing the coordinates again
/// (16 to 64 bytes a point instead of 4).
#[derive(Clone, Debug, Default)]
pub(in crate::hull) struct Repeats {
    /// Open-addressing table of first copies keyed by a hash of their coordinates (linear
    /// probing), at most two thirds full.
    table: Vec<u32>,
    /// Occupied slots.
    len: usize,
    /// One bit per input point, set for the later copies found; empty until one is.
    later: Vec<u64>,
}

impl Repeats {
    /// Forgets every point, keeping the buffers, and sizes the table for `expected` first
    /// copies (at most two thirds full then; it grows if more come).
    pub(in crate::hull) fn reset(&mut self, expected: usize) {
        let size = (expected + expected / 2).next_power_of_two().max(MIN_SLOTS);
        self.table.clear();
        self.table.resize(size, EMPTY_SLOT);
        self.len = 0;
        self.later.clear();
    }

    /// The first copy of `points[i]` among the points looked up so far, if there is one (then
    /// `i` is recorded as a later copy); otherwise `i` is recorded as a first copy. Equal points
    /// must be looked up in increasing index order, so that the copy found is the first.
    pub(in crate::hull) fn earlier_copy<const D: usize>(
        &mut self,
        i: u32,
        points: &[[f64; D]],
    ) -> Option<u32> {
        if 3 * (self.len + 1) > 2 * self.table.len() {
            self.grow(points);
        }
        let p = &points[i as usize];
        let mask = self.table.len() - 1;
        let mut slot = slot_hash(p) as usize & mask;
        loop {
            let a = self.table[slot];
            if a == EMPTY_SLOT {
                self.table[slot] = i;
                self.len += 1;
                return None;
            }
            if points[a as usize] == *p {
                debug_assert!(a < i);
                if self.later.is_empty() {
                    self.later.resize(points.len().div_ceil(64), 0);
                }
                self.later[i as usize / 64] |= 1 << (i % 64);
                return Some(a);
            }
            slot = (slot + 1) & mask;
        }
    }

    /// Whether input `i` was found to be a later copy of another.
    pub(in crate::hull) fn is_later_copy(&self, i: usize) -> bool {
        self.later
            .get(i / 64)
            .is_some_and(|&word| word & (1 << (i % 64)) != 0)
    }

    /// Doubles the table (at least to its smallest size) and reinserts the first copies: their
    /// coordinates are distinct, so their order does not matter.
    fn grow<const D: usize>(&mut self, points: &[[f64; D]]) {
        let size = (2 * self.table.len()).max(MIN_SLOTS);
        let old = std::mem::replace(&mut self.table, vec![EMPTY_SLOT; size]);
        let mask = size - 1;
        for a in old.into_iter().filter(|&a| a != EMPTY_SLOT) {
            let mut slot = slot_hash(&points[a as usize]) as usize & mask;
            while self.table[slot] != EMPTY_SLOT {
                slot = (slot + 1) & mask;
            }
            self.table[slot] = a;
        }
    }
}

impl<const D: usize> Hull<D> {
    /// Records `p`, a point the initial partition left inside the simplex `simplex`, as the
    /// first copy of the vertices it equals and precedes (`first[k]` for `simplex[k]`). Called
    /// in increasing `p`, so the first copy recorded is the smallest.
    pub(in crate::hull) fn note_vertex_copy(
        &self,
        p: usize,
        simplex: &[usize],
        first: &mut [usize],
    ) {
        let point = &self.points[p];
        for (f, &s) in first.iter_mut().zip(simplex) {
            if *f == s && p < s && self.points[s] == *point {
                *f = p;
            }
        }
    }

    /// Names the initial simplex's vertices by their first copies (`first[k]` for `simplex[k]`)
    /// in its facets `all`. The facets' planes stay as they are (the copies' coordinates are
    /// equal); their declared flats are read again from the new names.
    pub(in crate::hull) fn name_simplex_by_first_copies(
        &mut self,
        simplex: &[usize],
        first: &[usize],
        all: &[FacetId],
    ) {
        if simplex == first {
            return;
        }
        for &id in all {
            let mut vertices = self.facets[id.index()].vertices;
            for v in &mut vertices {
                if let Some(k) = simplex.iter().position(|&s| s == *v as usize) {
                    *v = first[k] as u32;
                }
            }
            let flats = self.flats_within(&vertices);
            let facet = &mut self.facets[id.index()];
            facet.vertices = vertices;
            facet.flats = flats;
        }
    }

    /// Drops every later copy of a point from the outside sets of `facets` (the initial
    /// simplex's, just partitioned), keeping each set's order and its farthest point (a first
    /// copy: a copy comes after it with the same value, and only a larger value displaces it).
    pub(in crate::hull) fn drop_repeats_beyond(&mut self, facets: &[FacetId]) {
        let total = facets
            .iter()
            .map(|id| self.facets[id.index()].outside.len())
            .sum();
        let Hull {
            facets: arena,
            points,
            scratch,
            ..
        } = self;
        let repeats = &mut scratch.repeats;
        repeats.reset(total);
        for &id in facets {
            let facet = &mut arena[id.index()];
            let before = facet.outside.len();
            let farthest = facet
                .farthest
                .map(|(slot, value)| (facet.outside[slot as usize], value));
            facet
                .outside
                .retain(|&p| repeats.earlier_copy(p, points).is_none());
            if facet.outside.len() != before {
                facet.farthest = farthest.and_then(|(p, value)| {
                    let slot = facet.outside.iter().position(|&q| q == p)?;
                    Some((slot as u32, value))
                });
            }
        }
        // Unreachable by the argument above; recomputed exactly rather than trusted.
        for &id in facets {
            let facet = &self.facets[id.index()];
            if facet.farthest.is_none() && !facet.outside.is_empty() {
                self.refresh_farthest(id);
            }
        }
    }
}

/// A hash of a point's coordinates (−0 read as 0, so that equal points hash alike): FxHash's
/// multiply-rotate, then SplitMix64's finaliser, so that structured input (grids, whose
/// coordinates differ in few bits) does not cluster in the table.
fn slot_hash<const D: usize>(p: &[f64; D]) -> u64 {
    let mut z = p.iter().fold(0u64, |h, &x| {
        (h.rotate_left(5) ^ (x + 0.0).to_bits()).wrapping_mul(0x517c_c1b7_2722_0a95)
    });
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::Repeats;
    use crate::geometry::Rng;

    /// Against a brute force: on points drawn from a few values (many repeats, signed zeros
    /// among them), looked up in index order, the first copy found is the smallest equal index,
    /// every later copy is recorded, and the table grows through several sizes.
    #[test]
    fn first_copies_are_the_smallest_equal_indices() {
        let mut rng = Rng::new(7);
        let values = [0.0, -0.0, 1.0, 0.5, -2.0, 3.25];
        for n in [1usize, 5, 300, 5_000] {
            let points: Vec<[f64; 3]> = (0..n)
                .map(|_| std::array::from_fn(|_| values[rng.index(values.len())]))
                .collect();
            let mut repeats = Repeats::default();
            repeats.reset(0);
            for i in 0..n {
                let brute = points[..i].iter().position(|q| *q == points[i]);
                let found = repeats.earlier_copy(i as u32, &points);
                assert_eq!(found.map(|a| a as usize), brute, "n={n} i={i}");
            }
            for i in 0..n {
                let later = points[..i].contains(&points[i]);
                assert_eq!(repeats.is_later_copy(i), later, "n={n} i={i}");
            }
            assert!(!repeats.is_later_copy(n));
        }
    }

    /// Distinct points (no copy at all) through many doublings: none is taken for a copy.
    #[test]
    fn distinct_points_are_all_first_copies() {
        let points: Vec<[f64; 2]> = (0..20_000).map(|i| [i as f64, -(i as f64) * 0.5]).collect();
        let mut repeats = Repeats::default();
        repeats.reset(0);
        for i in 0..points.len() {
            assert_eq!(repeats.earlier_copy(i as u32, &points), None);
        }
        assert!(2 * repeats.table.len() >= 3 * points.len());
        assert_eq!(repeats.len, points.len());
    }

    /// The initial simplex takes the last of equal highest points on an axis (as `max_by`
    /// does): here the last copy of (2, 0). It is named by its first copy all the same, and
    /// copies of points beyond the simplex, of points inside it and of its vertices are all
    /// kept out of the hull, whose check passes (it skips only the copies it was told of).
    #[test]
    fn the_simplex_and_every_vertex_are_named_by_first_copies() {
        use crate::Hull;
        // The first triangle is (−4, 0), (4, 0), (0, 5): the x extremes, then the point
        // farthest from their line; (0, −1) is beyond it, (0, 1) inside.
        let mut points = vec![[4.0, 0.0], [-4.0, 0.0], [0.0, 5.0], [0.0, -1.0], [0.0, 1.0]];
        // Copies: of the point beyond, of the inside point, of the three simplex vertices.
        points.extend([[0.0, -1.0], [0.0, 1.0], [-4.0, 0.0], [0.0, 5.0], [4.0, 0.0]]);
        let hull = Hull::try_new(&points).unwrap();
        hull.check().unwrap();
        let mut vertices = hull.vertex_indices();
        vertices.sort_unstable();
        assert_eq!(vertices, vec![0, 1, 2, 3]);
        assert!(
            hull.is_repeat(5),
            "the copy of (0, −1), beyond the first triangle"
        );
        assert!(
            !hull.is_repeat(6),
            "an inside point's copy is not looked up"
        );
        assert!((5..10).all(|i| !vertices.contains(&i)));
        // After the first partition alone, the point beyond is in an outside set, its copy not.
        let mut started = Hull::empty();
        started.initialise(&points, false).unwrap();
        let outside: Vec<usize> = started
            .facets()
            .flat_map(|(_, f)| f.outside_set())
            .collect();
        assert_eq!(outside, vec![3]);
    }
}
