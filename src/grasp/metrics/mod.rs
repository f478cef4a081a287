//! The grasp model's other quantities, which the [`Evaluator`](crate::grasp::Evaluator)'s
//! metrics beyond Q1, Q∞ and Q_OWS are built on:
//!
//! * [`circumscribed`] — the friction model whose pyramids circumscribe the circular cones
//!   ([`Metric::ConeBracket`](crate::grasp::Metric::ConeBracket));
//! * [`gws_volume`] — the volume of the grasp wrench space (the full hull: a volume needs every
//!   facet, so there is no partial shortcut; [`Metric::Volume`](crate::grasp::Metric::Volume));
//! * [`grasp_matrix`] and [`grasp_matrix_singular_values`] — the grasp matrix and its singular
//!   values ([`Metric::SigmaMin`](crate::grasp::Metric::SigmaMin),
//!   [`Metric::Isotropy`](crate::grasp::Metric::Isotropy)).
//!
//! ```
//! use pqhull::grasp::metrics::{grasp_matrix_singular_values, gws_volume};
//! use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric};
//!
//! // Three fingers around a ball of radius 0.1, pushing toward its centre.
//! let contacts = [[1.0, 0.0, 0.0], [-0.5, 0.8, 0.0], [-0.5, -0.8, 0.3]]
//!     .map(|d: [f64; 3]| {
//!         let n = d.map(|x| -x / d.iter().map(|y| y * y).sum::<f64>().sqrt());
//!         Contact::try_new(n.map(|x| -0.1 * x), n, None).unwrap()
//!     });
//! let grasp = Grasp::builder(contacts.to_vec(), FrictionModel::try_new(0.6, 8)?)
//!     .torque_scale(0.1)
//!     .build()?;
//! let sigma = grasp_matrix_singular_values(&grasp)?;
//! let isotropy = Evaluator::new(Metric::Isotropy, Method::Partial, None)?.evaluate(&grasp)?;
//! assert_eq!(isotropy.value, Some(sigma[5] / sigma[0]));
//! let volume = Evaluator::new(Metric::Volume, Method::Partial, None)?.evaluate(&grasp)?;
//! assert_eq!(volume.value, Some(gws_volume(&grasp)?));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::quality::QualityError;
use super::{FrictionModel, Grasp, GraspError};
use crate::geometry::vector::cross;
use crate::hull::{FarthestPoint, Hull, HullError, Stats, Step, Strategy};
use std::f64::consts::PI;
use std::time::Instant;

/// The friction model whose k-edge pyramid circumscribes `friction`'s cone: the same k, μ
/// divided by cos(π/k), rounded up (by 4 ulps, more than the rounding of the division and of the
/// cosine) so that the pyramid still contains the cone.
///
/// # Errors
/// [`GraspError::InvalidFriction`] if μ / cos(π/k) overflows.
pub fn circumscribed(friction: FrictionModel) -> Result<FrictionModel, GraspError> {
    let k = friction.cone_edges();
    let mu = friction.friction() / (PI / k as f64).cos() * (1.0 + 4.0 * f64::EPSILON);
    FrictionModel::try_new(mu, k)
}

/// The volume of the grasp wrench space (the hull of the Q1 wrenches), from the full hull: a
/// volume needs every facet, so no partial hull can give it. 0 for wrenches spanning fewer than
/// six dimensions: a lower-dimensional set has no volume. A set flat only in exact arithmetic
/// (two contacts: their wrenches have no moment about the line through them) is, once computed,
/// usually full-dimensional by its rounding, and gets a volume of that order (2.5e−20 for the
/// pinch in `tests/metrics.rs`), which is the exact answer for those wrenches, up to the
/// floating-point volume sum.
///
/// # Errors
/// [`QualityError::Hull`] for non-finite wrenches (a torque scale far too small);
/// [`QualityError::VolumeOverflow`] for a volume beyond `f64::MAX`.
pub fn gws_volume(grasp: &Grasp) -> Result<f64, QualityError> {
    Ok(volume_and_work(grasp)?.0)
}

/// The full hull (`FarthestPoint`) without the final refinement of thin facets' normals:
/// [`Hull::volume`] reads each facet's cofactors at the interior point, never its normal, so the
/// volume is the same to the bit, and on raw wrench sets, where half the facets are thin, the
/// refinement was a fifth of the build (docs/benchmarks.md, "Off-grid points on the exact
/// plane").
struct VolumeHull(FarthestPoint);

impl Strategy<6> for VolumeHull {
    type Output = ();

    fn start(&mut self, hull: &Hull<6>) {
        Strategy::<6>::start(&mut self.0, hull);
    }

    fn step(&mut self, hull: &mut Hull<6>) -> Step {
        self.0.step(hull)
    }

    fn finish(self, _hull: &Hull<6>) {}

    fn refines_all_normals(&self) -> bool {
        false
    }

    fn partitions_to_farthest(&self) -> bool {
        Strategy::<6>::partitions_to_farthest(&self.0)
    }
}

/// [`gws_volume`] and the full hull's work.
pub(in crate::grasp) fn volume_and_work(grasp: &Grasp) -> Result<(f64, Stats), QualityError> {
    let started = Instant::now();
    match Hull::try_with_strategy(&grasp.wrenches(), VolumeHull(FarthestPoint::new())) {
        Ok((hull, ())) => {
            let volume = hull.volume();
            if volume == f64::INFINITY {
                return Err(QualityError::VolumeOverflow);
            }
            let mut stats = hull.stats();
            stats.elapsed = started.elapsed();
            Ok((volume, stats))
        }
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
            let stats = Stats {
                elapsed: started.elapsed(),
                ..Stats::default()
            };
            Ok((0.0, stats))
        }
        Err(e) => Err(QualityError::Hull(e)),
    }
}

/// The grasp matrix G as its columns: contact i's force along axis a maps to the wrench
/// `[e_a; (p_i − c) × e_a / ρ]`, in the grasp's torque frame (the same map as
/// [`Grasp::wrenches`]); a soft contact adds a fourth column, its torsional moment about the
/// normal, `[0; n_i / ρ]`. Its singular values do not depend on the frame chosen at each contact.
pub fn grasp_matrix(grasp: &Grasp) -> Vec<[f64; 6]> {
    let (c, rho) = (grasp.torque_reference(), grasp.torque_scale());
    let mut columns = Vec::with_capacity(3 * grasp.contact_count());
    for contact in grasp.contacts() {
        let p = contact.position();
        let r = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
        for a in 0..3 {
            let mut e = [0.0; 3];
            e[a] = 1.0;
            let t = cross(r, e);
            columns.push([e[0], e[1], e[2], t[0] / rho, t[1] / rho, t[2] / rho]);
        }
        if contact.is_soft() {
            let n = contact.normal();
            columns.push([0.0, 0.0, 0.0, n[0] / rho, n[1] / rho, n[2] / rho]);
        }
    }
    columns
}

/// The grasp matrix's singular values ([`grasp_matrix`]), largest first, by faer's SVD; six of
/// them (zeros beyond 3m for a single contact). σ_6, the smallest, is how weakly the grasp's
/// contact forces reach the worst direction of wrench space: near 0 (within about 1e−15 · σ_1 of
/// it) for a rank-deficient matrix, as two contacts cannot act about the line through them.
///
/// # Errors
/// [`QualityError::SvdNoConvergence`] if the decomposition does not converge (not seen on
/// finite input).
pub fn grasp_matrix_singular_values(grasp: &Grasp) -> Result<[f64; 6], QualityError> {
    let columns = grasp_matrix(grasp);
    let g = faer::Mat::from_fn(6, columns.len(), |i, j| columns[j][i]);
    let values = g
        .as_ref()
        .singular_values()
        .map_err(|_| QualityError::SvdNoConvergence)?;
    let mut singular_values = [0.0; 6];
    for (s, v) in singular_values.iter_mut().zip(values) {
        *s = v;
    }
    Ok(singular_values)
}
