//! Ties between deciding facets: another facet of the hull, on another plane, as near the
//! origin as the one that decides the value. Q1 (and Q∞) is the minimum of the facets'
//! distances, so at a tie it is the minimum of two smooth functions of the grasp, not
//! differentiable; the gradient reads this flag ([`Quality::tied`](super::Quality::tied)).
//!
//! Why the hull suffices: where the origin is inside, the hull's support function is smallest
//! exactly at the normals of the facets at the least distance. A partial hull contains fewer
//! points than the full one, so its support is nowhere larger, and at its stop the deciding
//! facet is certain: a tie of the full hull is a facet of the partial one at the same
//! distance. A facet of the partial hull that is that near but would still grow is a near tie,
//! flagged too (the gradient may then say "not differentiable" where it is: the safe side).

use crate::geometry::vector::{norm, sub};
use crate::{FacetId, Hull};

/// Unit normals farther apart than this are of different planes. A face split into several
/// simplices (a friction pyramid's rim lies on one 2-flat) shares one plane; normals of the
/// caller's raw wrenches, coplanar only to rounding, differ by ~1e−16 over the thinness of the
/// simplex, and a genuinely other facet at the same distance differs by far more.
pub(super) const DIFFERENT_PLANE: f64 = 1e-6;

/// Whether a facet among `candidates` (of `hull`) other than `deciding` (the origin inside),
/// with a normal more than [`DIFFERENT_PLANE`] from its normal, lies within `band` of its
/// distance from the origin, both measured on `hull` (which may be of snapped wrenches: `band`
/// then covers the snapping too). One pass over the candidates with floating-point bounds. A precise facet's normal and
/// distance (within 1e−11 of the exact ones, far inside `band` and [`DIFFERENT_PLANE`]) are
/// used as they are; a thin facet's exact ones are computed only when it is within the band.
pub(in crate::grasp) fn tied(
    hull: &Hull<6>,
    deciding: FacetId,
    band: f64,
    candidates: impl Iterator<Item = FacetId>,
) -> bool {
    let origin = [0.0; 6];
    let distance_of = |id: FacetId| {
        let exact = match hull.facet(id).normal_is_precise() {
            true => None,
            false => hull.exact_signed_distance(id, &origin),
        };
        -exact.unwrap_or_else(|| hull.signed_distance(id, &origin))
    };
    let value = distance_of(deciding);
    let mut own: Option<[f64; 6]> = None;
    for id in candidates {
        if id == deciding {
            continue;
        }
        // A lower bound on this facet's distance (−∞ when its plane says nothing: checked).
        let nearest = -hull.distance_upper_bound(id, &origin);
        if nearest > value + band {
            continue;
        }
        if (distance_of(id) - value).abs() > band {
            continue;
        }
        let u = *own.get_or_insert_with(|| normal_of(hull, deciding));
        if norm(sub(normal_of(hull, id), u)) > DIFFERENT_PLANE {
            return true;
        }
    }
    false
}

/// Facet `id`'s unit normal: its own when precise (within 1e−11 of the exact one), else from
/// its exact plane.
fn normal_of(hull: &Hull<6>, id: FacetId) -> [f64; 6] {
    match hull.facet(id).normal_is_precise() {
        true => hull.facet(id).normal(),
        false => hull.exact_normal(id),
    }
}

/// Whether facets `a` and `b` of `hull` lie on different planes (normals more than
/// [`DIFFERENT_PLANE`] apart).
pub(in crate::grasp) fn on_other_planes(hull: &Hull<6>, a: FacetId, b: FacetId) -> bool {
    norm(sub(normal_of(hull, a), normal_of(hull, b))) > DIFFERENT_PLANE
}
