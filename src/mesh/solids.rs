//! Closed solids from 2-D profiles: a solid of revolution ([`Mesh::lathe`]) and a prism over a
//! simple polygon ([`Mesh::extrude`]), for objects such as the seed paper's C shape and joystick.

use std::f64::consts::TAU;

use super::{Mesh, MeshError};

/// The most profile or outline points accepted: ear clipping is quadratic in them, and no
/// modelled object needs more.
pub const MAX_PROFILE_POINTS: usize = 4096;

fn invalid(name: &'static str, value: String, expected: &'static str) -> MeshError {
    MeshError::InvalidParameter {
        name,
        value,
        expected,
    }
}

fn check_points(name: &'static str, points: &[[f64; 2]], at_least: usize) -> Result<(), MeshError> {
    if points.len() < at_least || points.len() > MAX_PROFILE_POINTS {
        return Err(invalid(
            name,
            format!("{} points", points.len()),
            "between 3 and 4096 points",
        ));
    }
    if let Some(p) = points
        .iter()
        .find(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(invalid(name, format!("{p:?}"), "finite coordinates"));
    }
    Ok(())
}

/// Twice the signed area of triangle `abc` (positive when counter-clockwise).
fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Triangles of a counter-clockwise simple polygon by ear clipping (indices into `outline`), or
/// `None` when no ear is found (the polygon is not simple).
///
/// Written here rather than taken from a crate: it is only the caps of [`Mesh::extrude`], for
/// outlines of a few dozen points, and a quadratic clipper is forty lines.
fn ear_clip(outline: &[[f64; 2]]) -> Option<Vec<[usize; 3]>> {
    let mut left: Vec<usize> = (0..outline.len()).collect();
    let mut triangles = Vec::with_capacity(outline.len().saturating_sub(2));
    while left.len() > 3 {
        let n = left.len();
        let ear = (0..n).find(|&i| {
            let (a, b, c) = (left[(i + n - 1) % n], left[i], left[(i + 1) % n]);
            let (pa, pb, pc) = (outline[a], outline[b], outline[c]);
            orient(pa, pb, pc) > 0.0
                && left.iter().all(|&j| {
                    j == a
                        || j == b
                        || j == c
                        || !(orient(pa, pb, outline[j]) >= 0.0
                            && orient(pb, pc, outline[j]) >= 0.0
                            && orient(pc, pa, outline[j]) >= 0.0)
                })
        })?;
        triangles.push([left[(ear + n - 1) % n], left[ear], left[(ear + 1) % n]]);
        left.remove(ear);
    }
    (orient(outline[left[0]], outline[left[1]], outline[left[2]]) > 0.0)
        .then(|| triangles.push([left[0], left[1], left[2]]))?;
    Some(triangles)
}

impl Mesh {
    /// The solid swept by turning a profile about the z axis: `profile` lists `(r, z)` points
    /// from the axis back to the axis (the first and last have `r = 0`, the others `r > 0`),
    /// each interior point becoming a ring of `segments` vertices. Closed.
    ///
    /// ```
    /// use pqhull::mesh::Mesh;
    /// // A cylinder of radius 1 and height 2: 4 profile points.
    /// let cylinder = Mesh::lathe(&[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0], [0.0, 2.0]], 256)?;
    /// assert!(cylinder.is_closed());
    /// let volume = cylinder.mass_properties().volume.unwrap();
    /// assert!((volume - 2.0 * std::f64::consts::PI).abs() < 0.01);
    /// # Ok::<(), pqhull::mesh::MeshError>(())
    /// ```
    ///
    /// # Errors
    /// [`MeshError::InvalidParameter`] for fewer than 3 or more than [`MAX_PROFILE_POINTS`]
    /// points, a non-finite point, ends off the axis or an interior point on or across it, fewer
    /// than 3 or more than 65,536 segments.
    pub fn lathe(profile: &[[f64; 2]], segments: usize) -> Result<Mesh, MeshError> {
        check_points("profile", profile, 3)?;
        if !(3..=65_536).contains(&segments) {
            return Err(invalid(
                "segments",
                segments.to_string(),
                "between 3 and 65536",
            ));
        }
        let (first, last) = (profile[0], profile[profile.len() - 1]);
        if first[0] != 0.0 || last[0] != 0.0 {
            return Err(invalid(
                "profile ends",
                format!("{first:?} … {last:?}"),
                "r = 0 (on the axis)",
            ));
        }
        let rings = &profile[1..profile.len() - 1];
        if let Some(p) = rings
            .iter()
            .find(|p| p[0].partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater))
        {
            return Err(invalid(
                "profile point",
                format!("{p:?}"),
                "r > 0 between the ends",
            ));
        }
        let mut vertices = vec![[0.0, 0.0, first[1]]];
        for &[r, z] in rings {
            for j in 0..segments {
                let (s, c) = (TAU * j as f64 / segments as f64).sin_cos();
                vertices.push([r * c, r * s, z]);
            }
        }
        vertices.push([0.0, 0.0, last[1]]);
        // At most 4094 rings × 65536 segments + 2 < 2^32 vertices.
        let end = (vertices.len() - 1) as u32;
        let ring = |i: usize, j: usize| (1 + i * segments + j % segments) as u32;
        let mut triangles = Vec::with_capacity(2 * segments * rings.len());
        for j in 0..segments {
            triangles.push([0, ring(0, j + 1), ring(0, j)]);
        }
        for i in 0..rings.len() - 1 {
            for j in 0..segments {
                let (a, b, c, d) = (
                    ring(i, j),
                    ring(i, j + 1),
                    ring(i + 1, j + 1),
                    ring(i + 1, j),
                );
                triangles.push([a, b, c]);
                triangles.push([a, c, d]);
            }
        }
        for j in 0..segments {
            triangles.push([ring(rings.len() - 1, j), ring(rings.len() - 1, j + 1), end]);
        }
        // Mesh::try_new orients a closed mesh, whichever way the profile runs.
        Mesh::try_new(vertices, triangles)
    }

    /// The prism over a simple polygon: `outline` (in the xy plane, either orientation, no
    /// repeated closing point) swept from `z = 0` to `z = height`, its caps triangulated by ear
    /// clipping. Closed.
    ///
    /// ```
    /// use pqhull::mesh::Mesh;
    /// // A C shape: a 3 × 3 square with a 2 × 1 notch, 1 deep.
    /// let outline = [[0.0, 0.0], [3.0, 0.0], [3.0, 1.0], [1.0, 1.0],
    ///                [1.0, 2.0], [3.0, 2.0], [3.0, 3.0], [0.0, 3.0]];
    /// let c = Mesh::extrude(&outline, 1.0)?;
    /// assert!(c.is_closed());
    /// assert!((c.mass_properties().volume.unwrap() - 7.0).abs() < 1e-12);
    /// # Ok::<(), pqhull::mesh::MeshError>(())
    /// ```
    ///
    /// # Errors
    /// [`MeshError::InvalidParameter`] for fewer than 3 or more than [`MAX_PROFILE_POINTS`]
    /// points, a non-finite point, a height that is not finite and positive, or an outline that
    /// is not a simple polygon (no ear to clip).
    pub fn extrude(outline: &[[f64; 2]], height: f64) -> Result<Mesh, MeshError> {
        check_points("outline", outline, 3)?;
        if !(height.is_finite() && height > 0.0) {
            return Err(invalid(
                "height",
                height.to_string(),
                "a finite positive number",
            ));
        }
        let n = outline.len();
        let twice_area: f64 = (0..n)
            .map(|i| orient([0.0; 2], outline[i], outline[(i + 1) % n]))
            .sum();
        let mut ccw = outline.to_vec();
        if twice_area < 0.0 {
            ccw.reverse();
        }
        let caps = ear_clip(&ccw)
            .ok_or_else(|| invalid("outline", format!("{n} points"), "a simple polygon"))?;
        let mut vertices: Vec<[f64; 3]> = ccw.iter().map(|p| [p[0], p[1], 0.0]).collect();
        vertices.extend(ccw.iter().map(|p| [p[0], p[1], height]));
        let (bottom, top) = (|i: usize| i as u32, |i: usize| (n + i) as u32);
        let mut triangles = Vec::with_capacity(2 * caps.len() + 2 * n);
        for &[a, b, c] in &caps {
            triangles.push([bottom(a), bottom(c), bottom(b)]);
            triangles.push([top(a), top(b), top(c)]);
        }
        for i in 0..n {
            let j = (i + 1) % n;
            triangles.push([bottom(i), bottom(j), top(j)]);
            triangles.push([bottom(i), top(j), top(i)]);
        }
        Mesh::try_new(vertices, triangles)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_profiles_are_errors() {
        assert!(Mesh::lathe(&[[0.0, 0.0], [1.0, 0.0]], 8).is_err());
        assert!(Mesh::lathe(&[[0.5, 0.0], [1.0, 0.0], [0.0, 1.0]], 8).is_err());
        assert!(Mesh::lathe(&[[0.0, 0.0], [0.0, 0.5], [0.0, 1.0]], 8).is_err());
        assert!(Mesh::lathe(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], 2).is_err());
        assert!(Mesh::extrude(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], 0.0).is_err());
        assert!(Mesh::extrude(&[[0.0, 0.0], [f64::NAN, 0.0], [0.0, 1.0]], 1.0).is_err());
        // A bow tie is not simple.
        let bow = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(Mesh::extrude(&bow, 1.0).is_err());
    }

    #[test]
    fn an_extruded_clockwise_outline_is_the_same_solid() {
        let square = [[0.0, 0.0], [0.0, 2.0], [2.0, 2.0], [2.0, 0.0]];
        let m = Mesh::extrude(&square, 0.5).unwrap();
        assert!(m.is_closed());
        assert!((m.mass_properties().volume.unwrap() - 2.0).abs() < 1e-12);
        let c = m.mass_properties().centre_of_mass;
        assert!((c[0] - 1.0).abs() < 1e-12 && (c[2] - 0.25).abs() < 1e-12);
    }

    #[test]
    fn a_lathed_cone_has_its_volume() {
        let cone = Mesh::lathe(&[[0.0, 0.0], [1.0, 0.0], [0.0, 3.0]], 4096).unwrap();
        assert!(cone.is_closed());
        let v = cone.mass_properties().volume.unwrap();
        assert!((v - std::f64::consts::PI).abs() < 1e-5, "{v}");
    }
}
