//! Mass properties: centre of mass, volume, surface area and characteristic length.
//!
//! All sums run in a *local frame*: coordinates relative to the bounding-box centre, multiplied by
//! the power of two that brings the largest half-extent into (0.5, 1] (as far as the normal range
//! of `f64` allows). The scaling is exact; the shift means the products are formed from
//! coordinates of the size of the object rather than of its distance from the origin, which
//! removes the cancellation a far-away object would otherwise suffer; and every term is O(1)
//! whatever the mesh's units, so nothing overflows or underflows before the results are converted
//! back. The sums themselves are compensated (Neumaier).

use crate::geometry::vector::{Sum, VectorSum, add, cross, dot, norm, scale, sub};

type V3 = [f64; 3];

/// What [`MassProperties::centre_of_mass`] is the centre of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CentreKind {
    /// The centroid of the enclosed solid (uniform density). Only for a closed, consistently
    /// oriented mesh ([`Mesh::is_closed`](super::Mesh::is_closed)) that encloses a non-negligible
    /// volume.
    Volume,
    /// The area-weighted centroid of the surface (a uniform thin shell): the fallback for an open
    /// mesh, or a closed one whose enclosed volume is negligible (see
    /// [`Mesh::mass_properties`](super::Mesh::mass_properties)).
    SurfaceCentroid,
}

/// Mass properties of a [`Mesh`](super::Mesh), in the mesh's own units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassProperties {
    /// The centre of mass (of the solid or of the surface, see `centre_kind`): the default torque
    /// reference `c` of the grasp metrics.
    pub centre_of_mass: [f64; 3],
    /// Whether `centre_of_mass` is the solid's or the surface's centroid.
    pub centre_kind: CentreKind,
    /// The enclosed volume (positive whatever the winding), when `centre_kind` is
    /// [`CentreKind::Volume`]; `None` otherwise.
    pub volume: Option<f64>,
    /// The total area of the triangles.
    pub surface_area: f64,
    /// ρ: the largest distance from `centre_of_mass` to a vertex (every entry of
    /// [`Mesh::vertices`](super::Mesh::vertices)) — GraspIt!'s torque scale.
    pub characteristic_length: f64,
}

/// `|V| ≤ VOLUME_NEGLIGIBLE · Σ|V_t|` (signed tetrahedron volumes `V_t` from the bounding-box
/// centre) means the enclosed volume is lost in cancellation: the rounding error of the sum is
/// below `1e−15 · Σ|V_t|`, so this leaves five orders of magnitude of margin. A closed surface
/// thinner than about `1e−10` of its size (a two-sided sheet) falls back to the surface centroid.
pub(in crate::mesh) const VOLUME_NEGLIGIBLE: f64 = 1e-10;

/// The exact power of two `2^n`, for `−1022 ≤ n ≤ 1023`.
fn pow2(n: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&n));
    f64::from_bits(((n + 1023) as u64) << 52)
}

/// The local frame: `local(p) = p · scale − origin · scale`, with `scale` a power of two.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::mesh) struct Frame {
    origin: V3,
    origin_scaled: V3,
    scale: f64,
    inv_scale: f64,
}

impl Frame {
    /// The frame of a non-empty set of finite vertices.
    pub(in crate::mesh) fn new(vertices: &[[f64; 3]]) -> Frame {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for v in vertices {
            for i in 0..3 {
                lo[i] = lo[i].min(v[i]);
                hi[i] = hi[i].max(v[i]);
            }
        }
        // Halving first keeps both the centre and the half-extent finite for any finite input.
        let origin: V3 = std::array::from_fn(|i| lo[i] / 2.0 + hi[i] / 2.0);
        let half = (0..3)
            .map(|i| hi[i] / 2.0 - lo[i] / 2.0)
            .fold(0.0, f64::max);
        let k = if half > 0.0 && half.is_finite() {
            (half.log2().ceil() as i32).clamp(-1022, 1022)
        } else {
            0
        };
        let scale = pow2(-k);
        Frame {
            origin,
            origin_scaled: crate::geometry::vector::scale(origin, scale),
            scale,
            inv_scale: pow2(k),
        }
    }

    /// `p` in local coordinates.
    pub(in crate::mesh) fn local(&self, p: V3) -> V3 {
        std::array::from_fn(|i| p[i] * self.scale - self.origin_scaled[i])
    }

    /// A local point back in the mesh's coordinates.
    pub(in crate::mesh) fn global(&self, q: V3) -> V3 {
        add(self.origin, scale(q, self.inv_scale))
    }

    /// A local length in the mesh's units.
    pub(in crate::mesh) fn length(&self, l: f64) -> f64 {
        l * self.inv_scale
    }

    /// A local area in the mesh's units.
    pub(in crate::mesh) fn area(&self, a: f64) -> f64 {
        a * self.inv_scale * self.inv_scale
    }
}

/// Mass properties plus what the mesh caches beside them.
pub(in crate::mesh) struct MassResult {
    pub(in crate::mesh) properties: MassProperties,
    /// `−1` when the mesh is closed and its signed volume negative (clockwise seen from outside),
    /// `+1` otherwise.
    pub(in crate::mesh) orientation: f64,
}

/// Mass properties of a mesh whose indices are valid; `None` when the total area is zero.
pub(in crate::mesh) fn compute(
    vertices: &[[f64; 3]],
    triangles: &[[u32; 3]],
    frame: &Frame,
    closed: bool,
) -> Option<MassResult> {
    let mut area2 = Sum::default(); // Σ 2·A_t
    let mut area_moment = VectorSum::<3>::default(); // Σ 2·A_t · (a + b + c)
    let mut volume6 = Sum::default(); // Σ 6·V_t
    let mut volume6_abs = Sum::default(); // Σ 6·|V_t|
    let mut volume_moment = VectorSum::<3>::default(); // Σ 6·V_t · (a + b + c)
    for t in triangles {
        if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            continue;
        }
        let [a, b, c] = t.map(|i| frame.local(vertices[i as usize]));
        let n = cross(sub(b, a), sub(c, a));
        let corners = add(add(a, b), c);
        let twice_area = norm(n);
        area2.add(twice_area);
        area_moment.add(scale(corners, twice_area));
        // a · ((b − a) × (c − a)) = a · (b × c): six times the signed volume of the tetrahedron
        // (local origin, a, b, c).
        let v6 = dot(a, n);
        volume6.add(v6);
        volume6_abs.add(v6.abs());
        volume_moment.add(scale(corners, v6));
    }
    let area2 = area2.value();
    if !(area2 > 0.0 && area2.is_finite()) {
        return None;
    }
    let v6 = volume6.value();
    let solid = closed && v6.abs() > VOLUME_NEGLIGIBLE * volume6_abs.value();
    let (centre_local, centre_kind, volume, orientation) = if solid {
        let centre = scale(volume_moment.value(), 1.0 / (4.0 * v6));
        let volume = frame.length(frame.length(frame.length(v6.abs() / 6.0)));
        (centre, CentreKind::Volume, Some(volume), v6.signum())
    } else {
        let centre = scale(area_moment.value(), 1.0 / (3.0 * area2));
        (centre, CentreKind::SurfaceCentroid, None, 1.0)
    };
    let rho_local = vertices
        .iter()
        .map(|&v| norm(sub(frame.local(v), centre_local)))
        .fold(0.0, f64::max);
    Some(MassResult {
        properties: MassProperties {
            centre_of_mass: frame.global(centre_local),
            centre_kind,
            volume,
            surface_area: frame.area(area2 / 2.0),
            characteristic_length: frame.length(rho_local),
        },
        orientation,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_frame_scales_by_a_power_of_two_around_the_box_centre() {
        let f = Frame::new(&[[1e6, 0.0, 0.0], [1e6 + 3.0, 1.0, -1.0]]);
        assert_eq!(f.origin, [1e6 + 1.5, 0.5, -0.5]);
        assert_eq!(f.scale, 0.5); // half-extent 1.5 → 2^1
        assert_eq!(f.local([1e6 + 3.0, 1.0, -1.0]), [0.75, 0.25, -0.25]);
        assert_eq!(f.global([0.75, 0.25, -0.25]), [1e6 + 3.0, 1.0, -1.0]);
    }

    #[test]
    fn the_frame_of_extreme_coordinates_stays_finite() {
        for v in [1e300, 1e-300, f64::MAX] {
            let f = Frame::new(&[[-v, 0.0, 0.0], [v, v, v]]);
            let q = f.local([v, v, v]);
            // |q| ≤ 1, unless the exponent's clamp to the normal range bites (f64::MAX).
            let bound = if v == f64::MAX { 4.0 } else { 1.0 };
            assert!(
                q.iter().all(|x| x.is_finite() && x.abs() <= bound),
                "{v}: {q:?}"
            );
        }
        let single = Frame::new(&[[2.0, 3.0, 4.0]]);
        assert_eq!(single.local([2.0, 3.0, 4.0]), [0.0; 3]);
    }

    #[test]
    fn a_far_away_tetrahedron_keeps_its_volume() {
        let o = 1e8;
        let v = [[o, o, o], [o + 1.0, o, o], [o, o + 1.0, o], [o, o, o + 1.0]];
        let t = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
        let m = compute(&v, &t, &Frame::new(&v), true).unwrap().properties;
        assert_eq!(m.centre_kind, CentreKind::Volume);
        assert!((m.volume.unwrap() - 1.0 / 6.0).abs() < 1e-15);
        for c in m.centre_of_mass {
            assert!((c - (o + 0.25)).abs() < 1e-7, "{c}");
        }
    }
}
