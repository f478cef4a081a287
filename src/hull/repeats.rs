//! Repeated input points: each point's first copy (the smallest index of a point equal to it), so
//! that only first copies enter outside sets.
//!
//! A copy is never beyond a hull holding its first (equal points are on the same side of every
//! plane), so the hull is the same without it, and the time does not grow with repetition
//! (copies would otherwise follow the first through every outside-set redistribution; a 6-D
//! cloud listed 10 times took 7× as long as once).
//!
//! Equal points are found by hashing. A small input is searched with one open-addressing table,
//! in cache. A large one, in steps that read memory at random over the whole input only for
//! points that are not repeats of recent ones:
//! - in index order, each point is compared with the last point of its hash in a small table of
//!   recent points (so that input made of a few points repeated many times, as lattices, is
//!   nearly all done at once, with every point it reads in cache);
//! - the others' hashes are scattered into buckets by their top bits (a counting sort, in index
//!   order within each bucket), and each bucket is searched with its own open-addressing table,
//!   small enough to stay in cache.
//!
//! One table over every point, as before, missed the cache on nearly every probe once the input
//! outgrew it (docs/benchmarks.md, "Issue 24: the input read in fewer, cheaper passes").
//! Written by hand: a `HashMap` of coordinates would be that one table, with more per entry.

/// The most points searched with one table, in one pass: its table (twice as many 4-byte
/// entries, 1 MiB) fits in a core's second-level cache, so buckets would only add passes.
const ONE_TABLE_POINTS: usize = 1 << 17;

/// The number of points a bucket holds on average: its table (twice as many 8-byte entries) is
/// 64 KiB, within a core's second-level cache.
const BUCKET_POINTS: usize = 4096;

/// The most buckets, as a power of two: 2^12 buckets of [`BUCKET_POINTS`] cover 16 million
/// points; above that the buckets grow, and their tables with them.
const MAX_BUCKET_BITS: u32 = 12;

/// The entries of the table of recent points: 32 KiB, within a core's first-level cache.
const RECENT: usize = 4096;

/// An empty table entry: none has it, since inputs are indexed by `u32` below `u32::MAX`.
const EMPTY: u64 = u64::MAX;

/// The high half of an entry: 32 bits of its point's hash (the bucket is the top bits, the slot
/// in the bucket's table the low bits). The low half is the point's index.
const TAG: u64 = !(u32::MAX as u64);

/// The buffers of [`mark_repeats`], kept from build to build so that rebuilding allocates
/// nothing.
#[derive(Clone, Debug, Default)]
pub(in crate::hull) struct Repeats {
    /// Each point's index if it is a first copy, else an earlier copy of it (whose own entry
    /// leads on to the first: see [`Repeats::first_copy`]).
    earlier: Vec<u32>,
    /// The table of recent points (hash tag and index, by the hash's low bits).
    recent: Vec<u64>,
    /// The entries (hash tag and index) of the points not found in the table of recent points,
    /// bucket by bucket.
    bucketed: Vec<u64>,
    /// Where each bucket starts in `bucketed` (one more than the buckets), and where its next
    /// entry goes while they are scattered.
    starts: Vec<usize>,
    cursors: Vec<usize>,
    /// One bucket's open-addressing table.
    table: Vec<u64>,
    /// The table of a small input (indices alone).
    small: Vec<u32>,
}

/// Finds, for each of `points`, the smallest index of a point equal to it (itself if none is
/// smaller), for [`Repeats::first_copy`] and [`Repeats::is_first_copy`]. Points are equal as
/// `f64`s compare (−0 equals 0).
pub(in crate::hull) fn mark_repeats<const D: usize>(points: &[[f64; D]], repeats: &mut Repeats) {
    let n = points.len();
    let Repeats {
        earlier,
        recent,
        bucketed,
        starts,
        cursors,
        table,
        small,
    } = repeats;
    earlier.clear();
    earlier.extend(0..n as u32);
    if n <= ONE_TABLE_POINTS {
        search_small(points, earlier, small);
        return;
    }
    recent.clear();
    recent.resize(RECENT, EMPTY);
    // Buckets of about `BUCKET_POINTS`.
    let bits = (n / BUCKET_POINTS)
        .next_power_of_two()
        .trailing_zeros()
        .min(MAX_BUCKET_BITS);
    let bucket = |entry: u64| ((entry >> 32) >> (32 - bits)) as usize;
    starts.clear();
    starts.resize((1 << bits) + 1, 0);
    // First pass: the repeats of recent points, and the buckets' sizes.
    for (i, p) in points.iter().enumerate() {
        let hash = mixed_point_hash(p);
        let last = &mut recent[hash as usize % RECENT];
        if *last != EMPTY && *last & TAG == hash & TAG && points[*last as u32 as usize] == *p {
            earlier[i] = *last as u32;
            continue;
        }
        *last = (hash & TAG) | i as u64;
        starts[bucket(hash) + 1] += 1;
    }
    for b in 1..starts.len() {
        starts[b] += starts[b - 1];
    }
    // Second pass: the others' entries, bucket by bucket, in index order in each (the first
    // copy first). The hashes are computed again rather than kept: a buffer of them would be
    // one more fresh allocation per build, whose page faults cost more than the hashing.
    bucketed.clear();
    bucketed.resize(starts[starts.len() - 1], 0);
    cursors.clone_from(starts);
    for (i, p) in points.iter().enumerate() {
        if earlier[i] as usize == i {
            let entry = (mixed_point_hash(p) & TAG) | i as u64;
            let b = bucket(entry);
            bucketed[cursors[b]] = entry;
            cursors[b] += 1;
        }
    }
    for b in 0..starts.len() - 1 {
        let run = &bucketed[starts[b]..starts[b + 1]];
        search(run.iter().copied(), run.len(), points, earlier, table);
    }
}

/// Finds each point's first copy with one open-addressing table of indices alone, filled in
/// index order: a small input's (the table as before the buckets). Its entries are half the
/// size of [`search`]'s, which keep the hash's tag: each probe of an occupied slot reads a
/// point, but at this size the points are in cache too, and a fresh build pays a page fault for
/// each page of a table it allocates. Measured, not argued: with the tagged table in its place,
/// `pqh bench hull --dimensions 3 --families cube` read the 3-D cube at 1.56, 1.57 and 1.66
/// against 1.78, 1.91 and 1.80 with this one, the runs alternated (pqhull 10.8–11.4 ms
/// against 9.1–9.4 ms); the suite's random rows need 1.5.
fn search_small<const D: usize>(points: &[[f64; D]], earlier: &mut [u32], table: &mut Vec<u32>) {
    // At most half full: short probe runs.
    let size = (2 * points.len()).next_power_of_two().max(2);
    let mask = size - 1;
    table.clear();
    table.resize(size, u32::MAX);
    for (i, p) in points.iter().enumerate() {
        let mut slot = mixed_point_hash(p) as usize & mask;
        loop {
            let first = table[slot];
            if first == u32::MAX {
                table[slot] = i as u32;
                break;
            }
            if points[first as usize] == *p {
                earlier[i] = first;
                break;
            }
            slot = (slot + 1) & mask;
        }
    }
}

/// Finds, among the points of `entries` (in index order; `len` of them), each one's first copy,
/// with an open-addressing table: one bucket.
fn search<const D: usize>(
    entries: impl Iterator<Item = u64>,
    len: usize,
    points: &[[f64; D]],
    earlier: &mut [u32],
    table: &mut Vec<u64>,
) {
    // At most half full: short probe runs.
    let size = (2 * len).next_power_of_two().max(2);
    let mask = size - 1;
    table.clear();
    table.resize(size, EMPTY);
    for entry in entries {
        let i = entry as u32;
        let mut slot = (entry >> 32) as usize & mask;
        loop {
            let stored = table[slot];
            if stored == EMPTY {
                table[slot] = entry;
                break;
            }
            let first = stored as u32;
            if stored & TAG == entry & TAG && points[first as usize] == points[i as usize] {
                earlier[i as usize] = first;
                break;
            }
            slot = (slot + 1) & mask;
        }
    }
}

impl Repeats {
    /// Whether input `i` is the first copy of its point (no smaller index holds an equal point).
    ///
    /// # Panics
    /// If `i` is not an index of the points last given to [`mark_repeats`].
    #[inline]
    pub(in crate::hull) fn is_first_copy(&self, i: usize) -> bool {
        self.earlier[i] as usize == i
    }

    /// The smallest index of a point equal to input `i`, or `None` if `i` is not an index of the
    /// points last given to [`mark_repeats`].
    pub(in crate::hull) fn first_copy(&self, i: usize) -> Option<usize> {
        let mut at = *self.earlier.get(i)? as usize;
        // Each step goes to a smaller index.
        while self.earlier[at] as usize != at {
            at = self.earlier[at] as usize;
        }
        Some(at)
    }
}

/// A hash of a point's coordinates (−0 read as 0, so that equal points hash alike): FxHash's
/// multiply-rotate, then SplitMix64's finaliser, so that structured input (grids, whose
/// coordinates differ in few bits) spreads over buckets and slots.
fn mixed_point_hash<const D: usize>(p: &[f64; D]) -> u64 {
    let mut z = p.iter().fold(0u64, |h, &x| {
        (h.rotate_left(5) ^ (x + 0.0).to_bits()).wrapping_mul(0x517c_c1b7_2722_0a95)
    });
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first copies against a brute force, with one table and with buckets (more than
    /// `ONE_TABLE_POINTS` points), with −0 and 0, and with every point equal.
    #[test]
    fn first_copies_are_the_smallest_equal_indices() {
        let mut rng = crate::geometry::Rng::new(3);
        let mut repeats = Repeats::default();
        for n in [
            1,
            7,
            300,
            ONE_TABLE_POINTS,
            ONE_TABLE_POINTS + 3 * BUCKET_POINTS + 17,
        ] {
            // About three copies of each point, scattered through the input; on small inputs,
            // few distinct values per coordinate too.
            let distinct = (n / 3).max(1);
            let values = if n < 1000 { 40 } else { 4000 };
            let pool: Vec<[f64; 2]> = (0..distinct)
                .map(|_| {
                    [
                        rng.index(values) as f64 - 20.0,
                        rng.index(values) as f64 - 20.0,
                    ]
                })
                .collect();
            let mut points: Vec<[f64; 2]> = (0..n).map(|_| pool[rng.index(distinct)]).collect();
            points[0] = [0.0, -0.0];
            if n > 1 {
                points[n - 1] = [-0.0, 0.0];
            }
            mark_repeats(&points, &mut repeats);
            // The brute force: the first index of each value, by a sort of (value, index).
            let mut order: Vec<usize> = (0..n).collect();
            let key = |p: &[f64; 2]| p.map(|x| (x + 0.0).to_bits());
            order.sort_by_key(|&i| (key(&points[i]), i));
            let mut expected = vec![0u32; n];
            let mut first = order[0];
            for &i in &order {
                if points[i] != points[first] {
                    first = i;
                }
                expected[i] = first as u32;
            }
            let found: Vec<u32> = (0..n)
                .map(|i| repeats.first_copy(i).unwrap() as u32)
                .collect();
            assert_eq!(found, expected, "n = {n}");
            for (i, &first) in expected.iter().enumerate() {
                assert_eq!(repeats.is_first_copy(i), first as usize == i, "n = {n}");
            }
            if n > 1 {
                assert_eq!(found[n - 1], 0, "−0 equals 0");
            }
            assert_eq!(repeats.first_copy(n), None);
        }
        let same = vec![[1.5, 2.5]; ONE_TABLE_POINTS + 1];
        mark_repeats(&same, &mut repeats);
        assert!((0..same.len()).all(|i| repeats.first_copy(i) == Some(0)));
    }
}
