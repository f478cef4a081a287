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
    /// A rigorous half-width `τ` of a slab `{x : |u·x| ≤ τ}` (`u` a unit vector) holding every
    /// point of `points`: the thinnest through the origin, up to the eigensolver's accuracy.
    /// `+∞` when the eigensolver fails or a point is not finite; 0 for no points.
    pub(in crate::grasp) fn slab(&mut self, points: impl Iterator<Item = [f64; 6]> + Clone) -> f64 {
        // The Gram matrix of the points divided by their largest coordinate (a power of two):
        // the eigenvector is the same, and tiny or huge wrenches neither underflow nor overflow.
        let mut largest = 0.0f64;
        for x in points.clone().flatten() {
            if !x.is_finite() {
                return f64::INFINITY;
            }
            largest = largest.max(x.abs());
        }
        if largest == 0.0 {
            return 0.0;
        }
        let unit = 2f64.powi(-largest.log2().ceil() as i32);
        self.gram.fill(0.0);
        for w in points.clone() {
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
