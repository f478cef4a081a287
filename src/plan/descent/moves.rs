//! The moves of a climb ([`super`]): gradients projected on the contacts' tangent planes, the
//! least-norm direction of a bundle, and a step put back on the surface.

use crate::geometry::vector::{dot, norm, scale, sub};
use crate::grasp::{Contact, Gradient, Grasp, GraspError};
use crate::mesh::SurfaceIndex;
use crate::plan::PlanError;

/// The position gradient of every contact of `grasp`, projected on its tangent plane, flat.
pub(super) fn tangential(grasp: &Grasp, g: &Gradient) -> Vec<f64> {
    let flat: Vec<f64> = g.positions.iter().flatten().copied().collect();
    tangential_of(grasp, &flat)
}

/// `v` (three numbers per contact) projected on each contact's tangent plane.
pub(super) fn tangential_of(grasp: &Grasp, v: &[f64]) -> Vec<f64> {
    grasp
        .contacts()
        .iter()
        .zip(v.chunks_exact(3))
        .flat_map(|(c, g)| {
            let g = [g[0], g[1], g[2]];
            sub(g, scale(c.normal(), dot(g, c.normal())))
        })
        .collect()
}

/// The largest contact's share of a move (three numbers per contact).
pub(super) fn largest_move(v: &[f64]) -> f64 {
    v.chunks_exact(3)
        .map(|g| norm([g[0], g[1], g[2]]))
        .fold(0.0, f64::max)
}

/// The point of the convex hull of `vectors` nearest the origin, by Frank–Wolfe on their Gram
/// matrix (a handful of vectors: a direction, not a reported number, needs no more precision).
pub(super) fn least_norm(vectors: &[Vec<f64>]) -> Vec<f64> {
    let n = vectors.len();
    let gram: Vec<Vec<f64>> = vectors
        .iter()
        .map(|a| {
            vectors
                .iter()
                .map(|b| a.iter().zip(b).map(|(x, y)| x * y).sum())
                .collect()
        })
        .collect();
    let mut weights = vec![0.0; n];
    if let Some(w) = weights.last_mut() {
        *w = 1.0;
    }
    for _ in 0..200 {
        let gw: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| gram[i][j] * weights[j]).sum())
            .collect();
        let Some(v) = (0..n).min_by(|&a, &b| gw[a].total_cmp(&gw[b])) else {
            break;
        };
        // Move toward vertex v: minimise |(1 − γ)x + γ·g_v|² over γ ∈ [0, 1].
        let xx: f64 = (0..n).map(|i| weights[i] * gw[i]).sum();
        let (xv, vv) = (gw[v], gram[v][v]);
        let curvature = xx - 2.0 * xv + vv;
        if curvature.is_nan() || curvature <= 0.0 || xx - xv <= 1e-15 * xx {
            break;
        }
        let gamma = ((xx - xv) / curvature).clamp(0.0, 1.0);
        for (i, w) in weights.iter_mut().enumerate() {
            *w = (1.0 - gamma) * *w + if i == v { gamma } else { 0.0 };
        }
    }
    let dim = vectors.first().map_or(0, Vec::len);
    (0..dim)
        .map(|k| vectors.iter().zip(&weights).map(|(v, w)| w * v[k]).sum())
        .collect()
}

/// `grasp` with contact `i` moved by `factor · direction[i]` and put back on the surface, or
/// `None` when no contact moved. `surface` answers as [`Mesh::nearest_surface_point`](crate::mesh::Mesh::nearest_surface_point) does.
pub(super) fn step_on_surface(
    surface: &SurfaceIndex<'_>,
    grasp: &Grasp,
    direction: &[f64],
    factor: f64,
) -> Result<Option<Grasp>, PlanError> {
    let mut any = false;
    let mut contacts = Vec::with_capacity(grasp.contact_count());
    for (i, (c, g)) in grasp
        .contacts()
        .iter()
        .zip(direction.chunks_exact(3))
        .enumerate()
    {
        let target: [f64; 3] = std::array::from_fn(|k| c.position()[k] + factor * g[k]);
        let landed =
            surface
                .nearest(target)
                .ok_or(PlanError::Grasp(GraspError::NonFinitePosition {
                    contact: Some(i),
                }))?;
        any |= landed.position != c.position();
        contacts.push(Contact::try_new(
            landed.position,
            landed.inward_normal,
            None,
        )?);
    }
    if !any {
        return Ok(None);
    }
    let built = Grasp::builder(contacts, grasp.friction())
        .torque_reference(grasp.torque_reference())
        .torque_scale(grasp.torque_scale())
        .build()?;
    Ok(Some(built))
}
