//! Wrench sets within rounding of a hyperplane through the origin: never force closure, and
//! answered without a hull.
//!
//! Contacts whose wrenches span fewer than six dimensions — two contacts, contacts on one line,
//! contacts at one or two points — can never be force closure. Their wrenches, computed in
//! floating point, are rank-deficient only up to rounding, and an exact hull of them is a sliver
//! of thousands of facets, more as the cone edges grow (and Q∞ hulls a Minkowski sum of k^m such
//! points): far more work than the slab test below, one 6 × 6 eigenproblem and two passes over
//! the wrenches (measured: docs/ARCHITECTURE.md, CHANGELOG.md).
//!
//! A slab certifies such a set up front. If every wrench `w` has `|u·w| ≤ τ` for a unit `u`, the
//! hull lies in the slab, so no ball of radius above `τ` around the origin fits in it: Q1 lies in
//! `[−dist(0, hull), τ]` (and the Minkowski sum of `m` such sets lies in the slab of half-width
//! `m·τ`). When `τ` is a tiny fraction of the set's scale ([`FLAT`]), the metric is `−dist(0, hull)`
//! to within `τ`, far inside the accuracy the metrics promise, and the verdict is "not force
//! closure" — which GJK or Wolfe's algorithm answers from the points alone.
//!
//! The slab's direction is the eigenvector of the smallest eigenvalue of the Gram matrix
//! `Σ w wᵀ` (faer's symmetric eigensolver, in a workspace kept between grasps); `τ` is then
//! measured on the wrenches with a rounding bound, so it holds whatever the eigenvector's
//! accuracy.

use crate::geometry::gram::positive_definite_after_shift;
use faer::diag::Diag;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::evd::{ComputeEigenvectors, self_adjoint_evd, self_adjoint_evd_scratch};
use faer::{Mat, Par};

/// A wrench set whose slab half-width is at most this fraction of its scale (the largest wrench
/// norm; for a Minkowski sum, of the sum's) is answered as flat: the value is then within this
/// (plus Wolfe's 1e−15) of the exact one, inside the `1e−14·scale` the metrics promise near zero,
/// and far below the force-closure band
/// ([`FORCE_CLOSURE_EPSILON`](crate::grasp::quality::FORCE_CLOSURE_EPSILON) = 1e−12). It
/// cannot be much smaller: the rounding bound of a six-term dot product alone is `6.7e−16·|w|`,
/// so even exactly collinear contacts measure a slab of about 1e−15 of their scale.
pub(in crate::grasp) const FLAT: f64 = 4e-15;

/// `γ₆ = 6u / (1 − 6u)`: the relative rounding bound of a six-term dot product.
const GAMMA_6: f64 = 6.0 * f64::EPSILON / 2.0 / (1.0 - 6.0 * f64::EPSILON / 2.0);

/// The slab test's reusable workspace (faer's eigensolver scratch and matrices).
pub(in crate::grasp) struct Flatness {
    gram: Mat<f64>,
    vectors: Mat<f64>,
    values: Diag<f64>,
    memory: MemBuffer,
}

impl Default for Flatness {
    fn default() -> Self {
        Flatness {
            gram: Mat::zeros(6, 6),
            vectors: Mat::zeros(6, 6),
            values: Diag::zeros(6),
            memory: MemBuffer::new(self_adjoint_evd_scratch::<f64>(
                6,
                ComputeEigenvectors::Yes,
                Par::Seq,
                Default::default(),
            )),
        }
    }
}

/// What [`Flatness::gram`] found.
enum Gram {
    /// No point, or all at the origin.
    Empty,
    /// A coordinate is not finite.
    NotFinite,
    /// The Gram matrix of `count` points, scaled by `unit`.
    Scaled { unit: f64, count: usize },
}

/// A fresh workspace: there is nothing in one worth copying.
impl Clone for Flatness {
    fn clone(&self) -> Self {
        Flatness::default()
    }
}

impl std::fmt::Debug for Flatness {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Flatness")
    }
}

impl Flatness {
    /// Whether a slab `{x : |u·x| ≤ limit}` through the origin (`u` a unit vector) holds every
    /// point of `points`: `slab(points) <= limit` (the test-only rigorous half-width), the same answer, but without
    /// the eigensolver for a set that is certainly far from flat (a force-closure grasp's, the
    /// common case): a Cholesky factorisation of the Gram matrix less a shift proves that every
    /// slab holding the points is more than twice `limit` wide.
    pub(in crate::grasp) fn within(
        &mut self,
        points: impl Iterator<Item = [f64; 6]> + Clone,
        limit: f64,
    ) -> bool {
        match self.gram(points.clone()) {
            Gram::Empty => return 0.0 <= limit,
            Gram::NotFinite => return false,
            Gram::Scaled { unit, count } if self.far_from_flat(limit * unit, count) => {
                return false;
            }
            Gram::Scaled { .. } => {}
        }
        self.thinnest(points) <= limit
    }

    /// A rigorous half-width `τ` of a slab `{x : |u·x| ≤ τ}` (`u` a unit vector) holding every
    /// point of `points`: the thinnest through the origin, up to the eigensolver's accuracy.
    /// `+∞` when the eigensolver fails or a point is not finite; 0 for no points.
    #[cfg(test)]
    fn slab(&mut self, points: impl Iterator<Item = [f64; 6]> + Clone) -> f64 {
        match self.gram(points.clone()) {
            Gram::Empty => 0.0,
            Gram::NotFinite => f64::INFINITY,
            Gram::Scaled { .. } => self.thinnest(points),
        }
    }

    /// Fills `gram` with the Gram matrix `Σ w wᵀ` of the points divided by their largest
    /// coordinate rounded up to a power of two (`unit` is its inverse): the eigenvectors are the
    /// same, and tiny or huge wrenches neither underflow nor overflow.
    fn gram(&mut self, points: impl Iterator<Item = [f64; 6]> + Clone) -> Gram {
        let mut largest = 0.0f64;
        for x in points.clone().flatten() {
            if !x.is_finite() {
                return Gram::NotFinite;
            }
            largest = largest.max(x.abs());
        }
        if largest == 0.0 {
            return Gram::Empty;
        }
        let unit = 2f64.powi(-largest.log2().ceil() as i32);
        self.gram.fill(0.0);
        let mut count = 0usize;
        for w in points {
            count += 1;
            let w = w.map(|x| x * unit);
            for (a, &x) in w.iter().enumerate() {
                for (b, &y) in w.iter().enumerate().take(a + 1) {
                    self.gram[(a, b)] += x * y;
                }
            }
        }
        for a in 0..6 {
            for b in 0..a {
                self.gram[(b, a)] = self.gram[(a, b)];
            }
        }
        Gram::Scaled { unit, count }
    }

    /// Whether the `count` points behind `gram` certainly lie in no slab through the origin of
    /// half-width `2·limit` (in the scaled units), proved by a Cholesky factorisation of
    /// `gram − t·I` that succeeds.
    ///
    /// Why that proves it: success means `gram − t·I + E` is positive definite, with Cholesky's
    /// backward error `‖E‖₂ ≤ γ₇·tr` (`tr` the trace, which bounds `‖|L||Lᵀ|‖`); the computed
    /// Gram matrix is within `γ_N·tr` of the exact one (`N = count` products summed per entry).
    /// So the exact smallest eigenvalue is at least `t − (γ₇ + γ_N)·tr ≥ 4N·limit²`, and for every
    /// unit `u`, `max_w (u·w)² ≥ Σ_w (u·w)² / N ≥ 4·limit²` (see
    /// [`positive_definite_after_shift`]).
    fn far_from_flat(&self, limit: f64, count: usize) -> bool {
        let n = count as f64;
        let trace: f64 = (0..6).map(|a| self.gram[(a, a)]).sum();
        let u = f64::EPSILON / 2.0;
        // (γ₇ + γ_N) with room for the shift's own rounding and the trace's.
        let rounding = 2.0 * (n + 16.0) * u * trace;
        let shift = 4.0 * n * limit * limit + rounding;
        if !(shift.is_finite() && shift < trace) {
            return false;
        }
        let gram: [[f64; 6]; 6] =
            std::array::from_fn(|a| std::array::from_fn(|b| self.gram[(a, b)]));
        positive_definite_after_shift(&gram, shift)
    }

    /// The eigensolver's slab for the Gram matrix in `gram`, measured on `points`.
    fn thinnest(&mut self, points: impl Iterator<Item = [f64; 6]>) -> f64 {
        let stack = MemStack::new(&mut self.memory);
        if self_adjoint_evd(
            self.gram.as_ref(),
            self.values.as_mut(),
            Some(self.vectors.as_mut()),
            Par::Seq,
            stack,
            Default::default(),
        )
        .is_err()
        {
            return f64::INFINITY;
        }
        // Eigenvalues come in nondecreasing order: the first vector spans the thinnest direction.
        let mut u: [f64; 6] = std::array::from_fn(|a| self.vectors[(a, 0)]);
        let length = u.iter().map(|x| x * x).sum::<f64>().sqrt();
        if length.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return f64::INFINITY;
        }
        u.iter_mut().for_each(|x| *x /= length);
        let mut tau = 0.0f64;
        for w in points {
            let (value, magnitude) = u
                .iter()
                .zip(&w)
                .fold((0.0, 0.0), |(s, m), (x, y)| (s + x * y, m + (x * y).abs()));
            tau = tau.max(value.abs() + GAMMA_6 * magnitude);
        }
        // The last factor covers the rounding of that bound and `u`'s norm (within 1e−15 of 1).
        tau * (1.0 + 4e-15)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rank_five_sets_are_thin_and_full_rank_sets_are_not() {
        // Six unit axes and their negatives: full rank, every slab has half-width 1.
        let full: Vec<[f64; 6]> = (0..12)
            .map(|i| {
                std::array::from_fn(|a| {
                    if a == i % 6 {
                        1.0 - 2.0 * (i / 6) as f64
                    } else {
                        0.0
                    }
                })
            })
            .collect();
        let mut flatness = Flatness::default();
        assert!(flatness.slab(full.iter().copied()) >= 1.0 - 1e-12);
        // Points with a zero last coordinate after a rotation: rank five up to rounding.
        let c = 0.6f64;
        let s = 0.8f64;
        let thin: Vec<[f64; 6]> = (0..40)
            .map(|i| {
                let t = i as f64 * 0.37;
                let (x, y) = (t.sin(), (1.3 * t).cos());
                // (x, 0) rotated in the (4, 5) plane, with four other coordinates.
                [t.cos(), (2.0 * t).sin(), (0.5 * t).cos(), y, c * x, s * x]
            })
            .map(|mut w| {
                // Make the set lie in the hyperplane s·w4 − c·w5 = 0.
                w[5] = w[4] * s / c;
                w
            })
            .collect();
        let tau = flatness.slab(thin.iter().copied());
        assert!(tau < 1e-14, "{tau:e}");
        // Every point does lie within τ of the slab's hyperplane: checked through the exact
        // normal of that hyperplane, (0, 0, 0, 0, s, −c).
        for w in &thin {
            assert!((s * w[4] - c * w[5]).abs() <= 1e-15);
        }
    }

    #[test]
    fn within_answers_as_the_slab_does_and_skips_the_eigensolver_only_far_from_flat() {
        let mut flatness = Flatness::default();
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for case in 0..40 {
            // Full-rank sets, then sets squeezed toward the hyperplane w5 = 0 by 1e−3 … 1e−17.
            let squeeze = if case < 10 {
                1.0
            } else {
                10f64.powi(-(case % 15) - 3)
            };
            let points: Vec<[f64; 6]> = (0..24)
                .map(|_| {
                    let mut w: [f64; 6] = std::array::from_fn(|_| next());
                    w[5] *= squeeze;
                    w
                })
                .collect();
            let tau = flatness.slab(points.iter().copied());
            for limit in [
                tau * 0.5,
                tau * 0.999,
                tau,
                tau * 1.001,
                tau * 2.0,
                1e-15,
                0.3,
            ] {
                assert_eq!(
                    flatness.within(points.iter().copied(), limit),
                    tau <= limit,
                    "case {case}, τ = {tau:e}, limit = {limit:e}"
                );
            }
            // The certificate fires for the full-rank sets at the metrics' threshold, never for
            // a set within twice the limit of a slab.
            let Gram::Scaled { unit, count } = flatness.gram(points.iter().copied()) else {
                panic!("finite points")
            };
            if case < 10 {
                assert!(flatness.far_from_flat(FLAT * unit, count), "case {case}");
            }
            assert!(
                !flatness.far_from_flat(tau * unit / 2.0, count),
                "case {case}"
            );
        }
    }

    #[test]
    fn one_point_is_flat_and_non_finite_points_are_not() {
        let mut flatness = Flatness::default();
        let a = [[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]];
        let first = flatness.slab(a.iter().copied());
        let second = flatness.slab(a.iter().copied());
        assert_eq!(first, second);
        assert!(first <= 1e-14 * 10.0);
        assert_eq!(flatness.slab(std::iter::empty()), 0.0);
        assert_eq!(flatness.slab([[f64::NAN; 6]].into_iter()), f64::INFINITY);
    }
}
