//! A static certificate that the floating-point evaluation of every orientation determinant over
//! a point set is exact: lattices, cube corners, snapped or dyadic data with few significant bits.

use super::exact::lowest_bit_exponent;

/// 2^52: integers of magnitude below it are exact in `f64`, with a factor-two margin.
const TWO_52: f64 = 4_503_599_627_370_496.0;

/// The point set's common power-of-two grid and per-axis ranges, when they prove that
/// [`FacetPlane::value`](super::FacetPlane::value) is the *exact* determinant for every facet
/// whose vertices, and every query point, lie in the set's box on that grid.
///
/// # Why
/// Let every coordinate be an integer multiple of `2^g` and axis `j` span `S_j` grid units
/// (`max_j − min_j`). Every entry of a difference row `v_k − v0` or `p − v0` is then an integer
/// number of units of magnitude at most `S_j` in column `j`. The cofactor dynamic programme and
/// the final dot product only form sums of products of such entries; every partial sum is bounded
/// by the permanent of the matrix of magnitudes, at most `D! · Π_j max(S_j, 1)` units of
/// `2^(g·D)`. When that bound is below 2^52 every intermediate is an integer exactly
/// representable in `f64`, so no operation rounds (products of fewer entries are multiples of a
/// coarser unit and bounded by the same permanent). Coordinates in `[−1, 1]` give `g ≤ 0`, and
/// `g·D ≥ −1000` keeps every unit a normal number (no underflow).
///
/// Checking this costs one pass over the input (less when the bound fails early: see [`of`](Self::of)); in exchange, every side test on such input is a
/// D-term dot product and a sign, with no error bound and no fallback, which is where exactly
/// degenerate input (points on facet planes, whose determinants vanish) spent its time.
///
/// ```
/// use pqhull::predicates::{ExactGrid, FacetPlane, Sign};
/// // The corners and the centre of the unit square, scaled into [−1, 1].
/// let points = [[0.0, 0.0], [0.5, 0.0], [0.5, 0.5], [0.0, 0.5], [0.25, 0.25]];
/// let grid = ExactGrid::of(&points).expect("coarse dyadic grid");
/// assert!(grid.contains(&[0.25, 0.5]));
/// assert!(!grid.contains(&[0.1, 0.5])); // not a multiple of the grid step
/// let plane = FacetPlane::new(&[points[0], points[2]]);
/// assert_eq!(plane.value(&points[4]), 0.0); // exactly on the diagonal
/// assert_eq!(plane.side_on_grid(&points[1]), Sign::Negative);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactGrid<const D: usize> {
    /// The grid step's exponent `g` (every coordinate is a multiple of 2^g).
    exponent: i32,
    low: [f64; D],
    high: [f64; D],
}

impl<const D: usize> ExactGrid<D> {
    /// The certificate for `points`, or `None` when the bound above does not hold (or a
    /// coordinate is outside `[−1, 1]`, not finite, or the set is empty).
    pub fn of(points: &[[f64; D]]) -> Option<Self> {
        let first = points.first()?;
        let (mut low, mut high) = (*first, *first);
        let mut exponent = i32::MAX;
        for (i, p) in points.iter().enumerate() {
            // Later points only lower the exponent and widen the spans, so a bound already too
            // large stays so: raw floating-point input (lowest bits near 2^−53) is turned away
            // after the first block instead of a pass over every coordinate.
            if i % 64 == 63 && exponent != i32::MAX {
                let so_far = ExactGrid {
                    exponent,
                    low,
                    high,
                };
                if !so_far.holds() {
                    return None;
                }
            }
            for (j, &x) in p.iter().enumerate() {
                if x.is_nan() || x.abs() > 1.0 {
                    return None;
                }
                if x != 0.0 {
                    exponent = exponent.min(lowest_bit_exponent(x));
                }
                low[j] = low[j].min(x);
                high[j] = high[j].max(x);
            }
        }
        if exponent == i32::MAX {
            exponent = 0; // every coordinate is zero
        }
        let grid = ExactGrid {
            exponent,
            low,
            high,
        };
        grid.holds().then_some(grid)
    }

    /// Whether the permanent bound is below 2^52 units and the unit is a normal number.
    fn holds(&self) -> bool {
        if self.exponent.saturating_mul(D as i32) < -1000 {
            return false;
        }
        let step = 2f64.powi(self.exponent);
        let mut bound = 1.0f64;
        for j in 0..D {
            // (high − low) is exact: both are multiples of the step within [−1, 1].
            let span = ((self.high[j] - self.low[j]) / step).max(1.0);
            bound *= span * (j + 1) as f64; // accumulates D! · Π S_j
        }
        bound < TWO_52
    }

    /// Whether `p` lies on the grid and within the set's box, so that the certificate covers
    /// side tests of `p` against facets of the set.
    pub fn contains(&self, p: &[f64; D]) -> bool {
        p.iter().enumerate().all(|(j, &x)| {
            x >= self.low[j]
                && x <= self.high[j]
                && (x == 0.0 || lowest_bit_exponent(x) >= self.exponent)
        })
    }
}
