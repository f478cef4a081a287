//! [`FrictionModel`]: Coulomb friction linearised as a k-edge pyramid.

use std::f64::consts::PI;

use super::{Contact, GraspError};
use crate::geometry::vector::{add, scale};

/// The most friction-cone edges a [`FrictionModel`] accepts: 1024.
///
/// Why this bound: a k-edge pyramid inscribed in the friction cone misses it by at most
/// 1 − cos(π/k) of the cone's radius, 4.7·10⁻⁶ at k = 1024 — far below the precision to which any
/// friction coefficient is known, so more edges change no answer that matters. Every set built from
/// a model grows with k: a grasp's Q1 wrench set has m·k points, its Q∞ Minkowski sum k^m, and the
/// object wrench space of a mesh 3·(k + 1) disturbances per triangle (about 148 KB per triangle at
/// the limit). Without a bound, one grasp asking for 10¹² edges would try to allocate terabytes and
/// abort the process. At the limit a 4-contact grasp has 4,096 Q1 wrenches; docs/limits.md
/// measures Q1 by the partial method there.
pub const MAX_CONE_EDGES: usize = 1024;

/// The fewest friction-cone edges a [`FrictionModel`] accepts: 3 (fewer span no cone).
pub const MIN_CONE_EDGES: usize = 3;

/// Coulomb friction with coefficient μ, linearised by k cone edges.
///
/// Edge j (0 ≤ j < k) of a contact with unit inward normal n and unit tangent t is
///
/// f_j = n + μ (cos(2πj/k) t + sin(2πj/k) (n × t)),
///
/// with normal component exactly 1 (the convention of Ferrari–Canny, GraspIt! and Dex-Net): the
/// edges lie on the cone of half-angle atan μ around n, and the pyramid they span is inscribed in
/// it. With μ = 0 every edge is n (a frictionless point contact).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionModel {
    friction: f64,
    cone_edges: usize,
}

impl FrictionModel {
    /// A friction model with coefficient `friction` (μ) and `cone_edges` (k) edges.
    ///
    /// # Errors
    ///
    /// [`GraspError::InvalidFriction`] when μ is negative, NaN or infinite;
    /// [`GraspError::TooFewConeEdges`] when k < [`MIN_CONE_EDGES`] (3);
    /// [`GraspError::TooManyConeEdges`] when k > [`MAX_CONE_EDGES`] (1024). Nothing is allocated
    /// either way.
    ///
    /// ```
    /// use pqhull::grasp::{FrictionModel, GraspError, MAX_CONE_EDGES};
    ///
    /// assert!(FrictionModel::try_new(0.5, MAX_CONE_EDGES).is_ok());
    /// let err = FrictionModel::try_new(0.5, 1_000_000_000_000).unwrap_err();
    /// assert!(matches!(err, GraspError::TooManyConeEdges { max: MAX_CONE_EDGES, .. }));
    /// assert!(err.to_string().contains("at most 1024"));
    /// ```
    pub fn try_new(friction: f64, cone_edges: usize) -> Result<FrictionModel, GraspError> {
        if !friction.is_finite() || friction < 0.0 {
            return Err(GraspError::InvalidFriction { friction });
        }
        if cone_edges < MIN_CONE_EDGES {
            return Err(GraspError::TooFewConeEdges { cone_edges });
        }
        if cone_edges > MAX_CONE_EDGES {
            return Err(GraspError::TooManyConeEdges {
                cone_edges,
                max: MAX_CONE_EDGES,
            });
        }
        Ok(FrictionModel {
            friction,
            cone_edges,
        })
    }

    /// The friction coefficient μ (≥ 0).
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// The number of cone edges k ([`MIN_CONE_EDGES`] ≤ k ≤ [`MAX_CONE_EDGES`]).
    pub fn cone_edges(&self) -> usize {
        self.cone_edges
    }

    /// The k edge forces f_j of `contact`'s friction pyramid, j = 0, 1, …, k − 1 (see the type
    /// docs). Allocates nothing.
    pub fn edges(&self, contact: &Contact) -> impl ExactSizeIterator<Item = [f64; 3]> + use<> {
        let n = contact.normal();
        let t = contact.tangent();
        let b = contact.bitangent();
        let mu = self.friction;
        let k = self.cone_edges;
        (0..k).map(move |j| {
            let (sin, cos) = (2.0 * PI * j as f64 / k as f64).sin_cos();
            add(n, scale(add(scale(t, cos), scale(b, sin)), mu))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::vector::{dot, norm, sub};

    fn contacts() -> Vec<Contact> {
        let dirs = [
            [0.0, 0.0, 1.0],
            [-1.0, 0.0, 0.0],
            [0.3, -0.4, 0.5],
            [-2.0, 1.0, 0.25],
            [1e-3, 1.0, -1e-3],
        ];
        let mut out: Vec<Contact> = dirs
            .iter()
            .map(|&n| Contact::try_new([0.1, 0.2, 0.3], n, None).unwrap())
            .collect();
        out.push(Contact::try_new([0.0; 3], [0.3, -0.4, 0.5], Some([1.0, 1.0, 0.0])).unwrap());
        out
    }

    #[test]
    fn validation() {
        for mu in [-0.1, -f64::MIN_POSITIVE, f64::NAN, f64::INFINITY] {
            let err = FrictionModel::try_new(mu, 8).unwrap_err();
            assert!(matches!(err, GraspError::InvalidFriction { .. }), "{mu}");
        }
        for k in [0, 1, 2] {
            assert_eq!(
                FrictionModel::try_new(0.5, k),
                Err(GraspError::TooFewConeEdges { cone_edges: k })
            );
        }
        let fm = FrictionModel::try_new(0.0, 3).unwrap();
        assert_eq!((fm.friction(), fm.cone_edges()), (0.0, 3));
    }

    #[test]
    fn cone_edges_are_bounded_before_anything_is_allocated() {
        let fm = FrictionModel::try_new(0.5, MAX_CONE_EDGES).unwrap();
        assert_eq!(fm.cone_edges(), MAX_CONE_EDGES);
        for k in [MAX_CONE_EDGES + 1, 1 << 40, usize::MAX] {
            let err = FrictionModel::try_new(0.5, k).unwrap_err();
            assert_eq!(
                err,
                GraspError::TooManyConeEdges {
                    cone_edges: k,
                    max: MAX_CONE_EDGES
                }
            );
            let message = err.to_string();
            assert!(
                message.contains(&k.to_string()) && message.contains("at most 1024"),
                "{message}"
            );
        }
        // μ is checked first, whatever k is.
        assert!(matches!(
            FrictionModel::try_new(f64::NAN, usize::MAX),
            Err(GraspError::InvalidFriction { .. })
        ));
    }

    #[test]
    fn edges_follow_the_conventions() {
        for mu in [0.0, 0.1, 0.5, 1.0, 2.5] {
            for k in [3, 4, 7, 8, 32, 64] {
                let fm = FrictionModel::try_new(mu, k).unwrap();
                for c in contacts() {
                    let n = c.normal();
                    let edges: Vec<_> = fm.edges(&c).collect();
                    assert_eq!(edges.len(), k);
                    assert_eq!(fm.edges(&c).len(), k);
                    // Edge 0 is n + μ t.
                    let e0 = add(n, scale(c.tangent(), mu));
                    assert!(norm(sub(edges[0], e0)) < 1e-15);
                    let mut sum = [0.0; 3];
                    for f in &edges {
                        // Normal component 1 (to rounding: n is unit and t ⟂ n only to rounding).
                        let along = dot(*f, n);
                        assert!(
                            (along - 1.0).abs() < 4.0 * f64::EPSILON * (1.0 + mu),
                            "{along}"
                        );
                        // On the cone of half-angle atan μ: tangential part has length μ.
                        let radial = norm(sub(*f, scale(n, along)));
                        assert!(
                            (radial - mu).abs() < 4.0 * f64::EPSILON * (1.0 + mu),
                            "{radial} vs {mu}"
                        );
                        let angle = radial.atan2(along);
                        assert!((angle - mu.atan()).abs() < 1e-15);
                        sum = add(sum, *f);
                    }
                    // The tangential parts cancel: the edges sum to k·n.
                    let err = norm(sub(sum, scale(n, k as f64)));
                    // Recursive summation of k terms of length ≤ 1 + μ: error ≤ k · ε · k(1 + μ).
                    let bound = f64::EPSILON * (k * k) as f64 * (1.0 + mu);
                    assert!(
                        err <= bound,
                        "k = {k}, μ = {mu}: sum off by {err} > {bound}"
                    );
                }
            }
        }
    }

    #[test]
    fn normal_component_is_exactly_one_for_axis_normals() {
        let fm = FrictionModel::try_new(0.7, 16).unwrap();
        for (axis, sign) in [(0, 1.0), (1, -1.0), (2, 1.0)] {
            let mut n = [0.0; 3];
            n[axis] = sign;
            let c = Contact::try_new([0.0; 3], n, None).unwrap();
            for f in fm.edges(&c) {
                assert_eq!(f[axis] * sign, 1.0);
            }
        }
    }

    #[test]
    fn frictionless_edges_are_the_normal() {
        let fm = FrictionModel::try_new(0.0, 5).unwrap();
        for c in contacts() {
            assert!(fm.edges(&c).all(|f| f == c.normal()));
        }
    }
}
