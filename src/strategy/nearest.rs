//! The point of a simplex nearest a query point, by exhaustive face enumeration.
//!
//! A facet has at most 8 vertices, so trying every face (≤ 255) and keeping the nearest
//! projection that falls inside its face is cheap, needs no iteration or tolerance tuning, and is
//! easy to trust — which matters more here than speed: it only runs for query points outside the
//! hull, on the few facets that can be nearest.

use crate::hull::dot;

/// Nearest point of the simplex spanned by `vertices[..count]` to `query`, and its distance.
pub(crate) fn nearest_in_simplex<const D: usize>(
    vertices: &[[f64; D]],
    query: &[f64; D],
) -> ([f64; D], f64) {
    let count = vertices.len();
    debug_assert!((1..=D.max(1) + 1).contains(&count));
    let full = (1u32 << count) - 1;
    // The projection onto the whole simplex's affine hull, when it lands inside, is the answer.
    if let Some(hit) = project_onto_face(vertices, full, query) {
        return hit;
    }
    let mut best: Option<([f64; D], f64)> = None;
    for mask in 1..full {
        if let Some((x, d)) = project_onto_face(vertices, mask, query)
            && best.is_none_or(|(_, b)| d < b)
        {
            best = Some((x, d));
        }
    }
    best.expect("single vertices always project onto themselves")
}

/// Orthogonal projection of `query` onto the affine hull of the vertices in `mask`, if it lies in
/// their simplex (barycentric coordinates ≥ −1e−12) and the face is not degenerate.
fn project_onto_face<const D: usize>(
    vertices: &[[f64; D]],
    mask: u32,
    query: &[f64; D],
) -> Option<([f64; D], f64)> {
    let mut members = [0usize; 9];
    let mut m = 0;
    for (i, _) in vertices.iter().enumerate() {
        if mask & (1 << i) != 0 {
            members[m] = i;
            m += 1;
        }
    }
    let base = vertices[members[0]];
    let k = m - 1;
    // Edge vectors and the normal equations G μ = Wᵀ(q − base), solved by Gaussian elimination.
    let mut edges = [[0.0; D]; 8];
    for (e, &idx) in edges.iter_mut().zip(&members[1..m]) {
        *e = std::array::from_fn(|c| vertices[idx][c] - base[c]);
    }
    let rhs_vec: [f64; D] = std::array::from_fn(|c| query[c] - base[c]);
    let mut a = [[0.0; 9]; 8];
    for r in 0..k {
        for c in 0..k {
            a[r][c] = dot(&edges[r], &edges[c]);
        }
        a[r][k] = dot(&edges[r], &rhs_vec);
    }
    let scale = (0..k).map(|r| a[r][r]).fold(0.0f64, f64::max);
    for col in 0..k {
        let pivot = (col..k).max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))?;
        if a[pivot][col].abs() <= 1e-13 * scale {
            return None; // degenerate face: its lower faces are tried separately
        }
        a.swap(col, pivot);
        let pivot_row = a[col];
        for row in a.iter_mut().take(k).skip(col + 1) {
            let factor = row[col] / pivot_row[col];
            for (x, y) in row[col..=k].iter_mut().zip(&pivot_row[col..=k]) {
                *x -= factor * y;
            }
        }
    }
    let mut mu = [0.0; 8];
    for r in (0..k).rev() {
        let tail: f64 = (r + 1..k).map(|c| a[r][c] * mu[c]).sum();
        mu[r] = (a[r][k] - tail) / a[r][r];
    }
    let first = 1.0 - mu[..k].iter().sum::<f64>();
    if first < -1e-12 || mu[..k].iter().any(|&w| w < -1e-12) {
        return None;
    }
    let mut x = base;
    for (e, &w) in edges[..k].iter().zip(&mu[..k]) {
        for (xc, ec) in x.iter_mut().zip(e) {
            *xc += w * ec;
        }
    }
    let d = dot(
        &std::array::from_fn::<f64, D, _>(|c| query[c] - x[c]),
        &std::array::from_fn::<f64, D, _>(|c| query[c] - x[c]),
    )
    .sqrt();
    Some((x, d))
}

#[cfg(test)]
mod tests {
    use super::nearest_in_simplex;

    #[test]
    fn triangle_in_3d_regions() {
        let t = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
        // Above the interior: projection.
        let (x, d) = nearest_in_simplex(&t, &[0.5, 0.5, 3.0]);
        assert_eq!((x, d), ([0.5, 0.5, 0.0], 3.0));
        // Beyond the hypotenuse: its midpoint region.
        let (x, d) = nearest_in_simplex(&t, &[2.0, 2.0, 0.0]);
        assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
        assert!((d - 2f64.sqrt()).abs() < 1e-15);
        // Behind a vertex.
        let (x, d) = nearest_in_simplex(&t, &[-1.0, -1.0, 0.0]);
        assert_eq!(x, [0.0, 0.0, 0.0]);
        assert!((d - 2f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn segment_in_2d() {
        let s = [[0.0, 0.0], [4.0, 0.0]];
        assert_eq!(nearest_in_simplex(&s, &[1.0, 3.0]), ([1.0, 0.0], 3.0));
        assert_eq!(nearest_in_simplex(&s, &[7.0, 4.0]), ([4.0, 0.0], 5.0));
    }
}
