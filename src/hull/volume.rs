//! The volume and the surface area of a hull, in the caller's units.

use super::Hull;
use crate::predicates::{FacetPlane, times_power_of_two};

/// Below this (in the hull's internal coordinates, where every coordinate is at most 1), the sum
/// of cone volumes from the facets' cofactors may have lost digits to underflow: the volume is
/// then recomputed with every axis scaled to unit extent.
const SMALLEST_SAFE_SUM: f64 = 1e-250;

impl<const D: usize> Hull<D> {
    /// Volume of the current hull, in the caller's units (partial hulls have smaller volume).
    ///
    /// Computed as the sum of signed cone volumes from an interior point, using each facet's
    /// cofactor vector, so it costs one dot product per facet. When the points' extents differ
    /// so much between axes that those cones underflow (a set 10^80 long in three directions and
    /// of unit size in the others, say), each cone is recomputed as a determinant with every axis
    /// scaled by its own power of two. A volume beyond `f64::MAX` is `+∞`, one below the smallest
    /// subnormal is 0 (as for any `f64` result out of range); never NaN.
    pub fn volume(&self) -> f64 {
        let mut sum = 0.0;
        for (id, facet) in self.facets() {
            // Orientation value of (facet, interior) is −D!·(cone volume). A facet that shares
            // its region's plane computes its own cofactors here: the shared plane's value is
            // the founder's cone, not this simplex's.
            let value = if self.exact_plane_of(id).1 == &facet.vertices {
                facet.filter.evaluate(&self.interior).0
            } else {
                FacetPlane::new(&self.coords(&facet.vertices))
                    .evaluate(&self.interior)
                    .0
            };
            sum -= value;
        }
        // Every cone volume is non-negative, so a sum that overflowed (to ∞, or NaN from ∞ − ∞
        // of rounded cone volumes) stands for a volume beyond f64::MAX.
        if !sum.is_finite() {
            return f64::INFINITY;
        }
        if sum < SMALLEST_SAFE_SUM {
            return self.volume_by_axis_scaled_determinants();
        }
        self.to_caller_volume(sum, 0)
    }

    /// The area of the current hull's boundary (its facets' (D − 1)-dimensional volumes
    /// summed), in the caller's units: the perimeter in 2-D, as scipy's `ConvexHull.area`.
    ///
    /// Each facet's measure is the product of the lengths its edges from one vertex keep once
    /// made orthogonal (Gram–Schmidt, twice, in the hull's scaled coordinates), over (D − 1)!:
    /// accurate to a few ulps per facet, thin facets included (a Gram determinant would square
    /// their condition). Floating point, like the volume; `+∞` beyond `f64::MAX`.
    ///
    /// ```
    /// use pqhull::Hull;
    /// let cube: Vec<[f64; 3]> = (0..8)
    ///     .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64])
    ///     .collect();
    /// assert!((Hull::try_new(&cube)?.area() - 6.0).abs() < 1e-14);
    /// let triangle = [[0.0, 0.0], [3.0, 0.0], [0.0, 4.0]];
    /// assert!((Hull::try_new(&triangle)?.area() - 12.0).abs() < 1e-14);
    /// # Ok::<(), pqhull::HullError>(())
    /// ```
    pub fn area(&self) -> f64 {
        let mut sum = 0.0;
        for (_, facet) in self.facets() {
            let vertices = facet.vertices();
            let origin = self.points[vertices[0]];
            // The orthonormalised directions so far, and the product of the residuals' lengths.
            let mut basis = [[0.0; D]; D];
            let mut measure = 1.0;
            for (k, &v) in vertices[1..].iter().enumerate() {
                let mut r: [f64; D] = std::array::from_fn(|a| self.points[v][a] - origin[a]);
                for _ in 0..2 {
                    for b in &basis[..k] {
                        let c: f64 = r.iter().zip(b).map(|(x, y)| x * y).sum();
                        for (x, y) in r.iter_mut().zip(b) {
                            *x -= c * y;
                        }
                    }
                }
                let length = r.iter().map(|x| x * x).sum::<f64>().sqrt();
                measure *= length;
                if length > 0.0 {
                    basis[k] = r.map(|x| x / length);
                }
            }
            sum += measure;
        }
        let factorial: f64 = (1..D).map(|k| k as f64).product();
        let s = self.scale.log2().round() as i32;
        times_power_of_two(sum / factorial, -(D as i32 - 1) * s)
    }

    /// `sum` (D! times a volume in internal coordinates, further multiplied by `2^extra`) in
    /// the caller's units. The scale is a power of two, so the conversion is exact unless it
    /// leaves `f64`'s range; it is applied in steps that cannot overflow or underflow early.
    fn to_caller_volume(&self, sum: f64, extra: i32) -> f64 {
        let factorial: f64 = (1..=D).map(|k| k as f64).product();
        // scale = 2^s: dividing by scale^D is multiplying by 2^(−D·s).
        let s = self.scale.log2().round() as i32;
        times_power_of_two(sum / factorial, -(D as i32) * s - extra)
    }

    /// The volume with each axis a scaled by a power of two 2^(e_a) that brings the points'
    /// extent along it to about 1: each facet's cone is a D × D determinant (Gaussian elimination
    /// with partial pivoting), and the total is divided by 2^(Σ e_a) at the end.
    fn volume_by_axis_scaled_determinants(&self) -> f64 {
        let mut exponents = [0i32; D];
        for (a, e) in exponents.iter_mut().enumerate() {
            let extent = self
                .points
                .iter()
                .map(|p| (p[a] - self.interior[a]).abs())
                .fold(0.0, f64::max);
            if extent > 0.0 {
                *e = -(extent.log2().floor() as i32);
            }
        }
        let mut sum = 0.0;
        for (_, facet) in self.facets() {
            let mut m = [[0.0; D]; D];
            for (row, &v) in m.iter_mut().zip(&facet.vertices()) {
                for (a, x) in row.iter_mut().enumerate() {
                    *x = times_power_of_two(self.points[v][a] - self.interior[a], exponents[a]);
                }
            }
            sum += determinant(m).abs();
        }
        if !sum.is_finite() {
            return f64::INFINITY;
        }
        self.to_caller_volume(sum, exponents.iter().sum())
    }
}

/// The determinant of `m` by Gaussian elimination with partial pivoting (rounded; for volumes,
/// not for predicates).
fn determinant<const D: usize>(mut m: [[f64; D]; D]) -> f64 {
    let mut det = 1.0;
    for c in 0..D {
        let pivot = (c..D)
            .max_by(|&i, &j| m[i][c].abs().total_cmp(&m[j][c].abs()))
            .unwrap_or(c);
        if m[pivot][c] == 0.0 {
            return 0.0;
        }
        if pivot != c {
            m.swap(pivot, c);
            det = -det;
        }
        det *= m[c][c];
        let (top, rest) = m.split_at_mut(c + 1);
        let pivot_row = &top[c];
        for row in rest {
            let f = row[c] / pivot_row[c];
            for (x, p) in row[c..].iter_mut().zip(&pivot_row[c..]) {
                *x -= f * p;
            }
        }
    }
    det
}

#[cfg(test)]
mod tests {
    use super::determinant;
    use crate::Hull;

    #[test]
    fn determinants_of_small_matrices() {
        assert_eq!(determinant([[2.0, 0.0], [0.0, 3.0]]), 6.0);
        assert_eq!(determinant([[0.0, 1.0], [1.0, 0.0]]), -1.0);
        assert_eq!(determinant([[1.0, 2.0], [2.0, 4.0]]), 0.0);
    }

    /// Boxes 2^260 and 2^340 long in three directions and 1 wide in the other three. In the
    /// hull's internal coordinates (scaled so that the largest coordinate is 1) the first's cones
    /// are 2^−780 and its scale^6 underflows (the volume came out +∞); the second's cones
    /// underflow themselves (the sum once came out as −5e−324 and the volume as NaN, found by the
    /// grasp fuzz body on the GWS volume of a grasp with a lever arm of 10^80).
    #[test]
    fn boxes_of_wildly_different_extents_have_their_volume() {
        for e in [260, 340] {
            let long = 2f64.powi(e);
            let extent = [long, long, long, 1.0, 1.0, 1.0];
            let corners: Vec<[f64; 6]> = (0..64u32)
                .map(|bits| {
                    std::array::from_fn(|a| if bits >> a & 1 == 1 { extent[a] } else { 0.0 })
                })
                .collect();
            let hull = Hull::try_new(&corners).unwrap();
            let volume = hull.volume();
            let exact = long * long * long;
            assert!(
                (volume - exact).abs() <= 1e-12 * exact,
                "2^{e}: {volume:e} vs {exact:e}"
            );
        }
    }

    #[test]
    fn ordinary_volumes_are_unchanged() {
        let corners: Vec<[f64; 3]> = (0..8u32)
            .map(|bits| std::array::from_fn(|a| if bits >> a & 1 == 1 { 2.0 } else { -1.0 }))
            .collect();
        assert!((Hull::try_new(&corners).unwrap().volume() - 27.0).abs() < 1e-12);
    }
}
