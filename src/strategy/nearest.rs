//! The point of a convex hull nearest a query point: Wolfe's minimum-norm-point algorithm.
//!
//! P. Wolfe, "Finding the nearest point in a polytope", Mathematical Programming 11 (1976)
//! 128–149. It keeps a "corral" of at most D + 1 affinely independent points and the current
//! point `x` in their convex hull; a major cycle adds the point that most violates the optimality
//! test `(p − x)·(q − x) ≤ 0`, minor cycles move to the nearest point of the corral's affine hull
//! (or toward it until a weight vanishes, dropping that point). It works on any number of points
//! — a partial hull's vertices, or a wrench set too degenerate to have a hull — in a handful of
//! iterations, and allocates nothing. Floating point: the result is accurate to about 1e−13
//! relative to the size of the point set on well-conditioned input; callers that need a
//! certificate check the supporting hyperplane themselves.

use crate::hull::dot;

/// Optimality tolerance: stop when `|x|² − min_j x·p_j ≤ TOL·M·|x|` (`M` = largest `|p_j − q|`).
const TOL: f64 = 1e-14;

/// Relative pivot size below which a corral is taken as affinely dependent.
const SINGULAR: f64 = 1e-13;

/// The nearest point and the (at most D + 1) input points whose convex hull holds it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Nearest<const D: usize> {
    pub(crate) point: [f64; D],
    pub(crate) distance: f64,
    support: [usize; 9],
    support_len: usize,
}

impl<const D: usize> Nearest<D> {
    /// Indices (into the caller's point numbering) of the points spanning the nearest face.
    pub(crate) fn support(&self) -> &[usize] {
        &self.support[..self.support_len]
    }
}

/// The point of `conv{point(0), …, point(count − 1)}` nearest `query`.
///
/// # Panics
/// If `count == 0`.
pub(crate) fn min_norm_point<const D: usize>(
    count: usize,
    point: impl Fn(usize) -> [f64; D],
    query: &[f64; D],
) -> Nearest<D> {
    assert!(count > 0, "min_norm_point: no points");
    // Points relative to the query, which becomes the origin.
    let rel = |i: usize| -> [f64; D] {
        let p = point(i);
        std::array::from_fn(|c| p[c] - query[c])
    };
    let mut largest = 0.0f64;
    let mut first = (f64::INFINITY, 0);
    for i in 0..count {
        let p = rel(i);
        let n2 = dot(&p, &p);
        largest = largest.max(n2);
        if n2 < first.0 {
            first = (n2, i);
        }
    }
    let largest = largest.sqrt();
    let mut corral = [0usize; 9];
    let mut cp = [[0.0; D]; 9]; // corral points, relative
    let mut weights = [0.0; 9];
    let mut len = 1;
    corral[0] = first.1;
    cp[0] = rel(first.1);
    weights[0] = 1.0;
    let mut x = cp[0];

    for _ in 0..100 * (count + D + 1) {
        let xx = dot(&x, &x);
        if xx == 0.0 {
            break;
        }
        let (j, xpj) = (0..count)
            .map(|j| (j, dot(&x, &rel(j))))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .expect("count > 0");
        if xx - xpj <= TOL * largest * xx.sqrt() || corral[..len].contains(&j) || len > D {
            break;
        }
        corral[len] = j;
        cp[len] = rel(j);
        weights[len] = 0.0;
        len += 1;
        loop {
            let Some(alpha) = affine_minimiser(&cp[..len]) else {
                // Numerically dependent corral: keep the last good point.
                len -= 1;
                return finish(query, x, corral, len);
            };
            if alpha[..len].iter().all(|&a| a > 0.0) {
                weights = alpha;
                x = combination(&cp[..len], &weights);
                break;
            }
            // Walk from the weights toward alpha until the first one reaches zero.
            let mut theta = 1.0f64;
            let mut hit = 0;
            for i in 0..len {
                let (l, a) = (weights[i], alpha[i]);
                if a <= 0.0 {
                    let t = if l - a > 0.0 { l / (l - a) } else { 0.0 };
                    if t < theta {
                        theta = t;
                        hit = i;
                    }
                }
            }
            for i in 0..len {
                weights[i] = (1.0 - theta) * weights[i] + theta * alpha[i];
            }
            weights[hit] = 0.0;
            let mut kept = 0;
            for i in 0..len {
                if weights[i] > 0.0 {
                    corral[kept] = corral[i];
                    cp[kept] = cp[i];
                    weights[kept] = weights[i];
                    kept += 1;
                }
            }
            len = kept;
            let total: f64 = weights[..len].iter().sum();
            weights[..len].iter_mut().for_each(|w| *w /= total);
            x = combination(&cp[..len], &weights);
            if len == 1 {
                break;
            }
        }
    }
    finish(query, x, corral, len)
}

fn finish<const D: usize>(
    query: &[f64; D],
    x: [f64; D],
    support: [usize; 9],
    len: usize,
) -> Nearest<D> {
    Nearest {
        point: std::array::from_fn(|c| x[c] + query[c]),
        distance: dot(&x, &x).sqrt(),
        support,
        support_len: len,
    }
}

fn combination<const D: usize>(points: &[[f64; D]], weights: &[f64; 9]) -> [f64; D] {
    let mut x = [0.0; D];
    for (p, &w) in points.iter().zip(weights) {
        for (xc, pc) in x.iter_mut().zip(p) {
            *xc += w * pc;
        }
    }
    x
}

/// Affine weights (summing to 1) of the point of the affine hull of `points` nearest the origin,
/// or `None` if the points are (numerically) affinely dependent. Normal equations on differences
/// from the first point, Gaussian elimination with partial pivoting, one refinement step.
fn affine_minimiser<const D: usize>(points: &[[f64; D]]) -> Option<[f64; 9]> {
    let base = points[0];
    let k = points.len() - 1;
    let mut edges = [[0.0; D]; 8];
    for (e, p) in edges.iter_mut().zip(&points[1..]) {
        *e = std::array::from_fn(|c| p[c] - base[c]);
    }
    let mut gram = [[0.0; 8]; 8];
    let mut rhs = [0.0; 8];
    for r in 0..k {
        for c in 0..k {
            gram[r][c] = dot(&edges[r], &edges[c]);
        }
        rhs[r] = -dot(&edges[r], &base);
    }
    let mut beta = solve(&gram, &rhs, k)?;
    let mut residual = [0.0; 8];
    for r in 0..k {
        residual[r] = rhs[r] - (0..k).map(|c| gram[r][c] * beta[c]).sum::<f64>();
    }
    if let Some(delta) = solve(&gram, &residual, k) {
        for r in 0..k {
            beta[r] += delta[r];
        }
    }
    let mut alpha = [0.0; 9];
    alpha[0] = 1.0 - beta[..k].iter().sum::<f64>();
    alpha[1..=k].copy_from_slice(&beta[..k]);
    Some(alpha)
}

/// Solves `a·x = b` (k × k); `None` if a pivot is below `SINGULAR` times the largest entry.
pub(crate) fn solve(a: &[[f64; 8]; 8], b: &[f64; 8], k: usize) -> Option<[f64; 8]> {
    let scale = (0..k)
        .flat_map(|r| a[r][..k].iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    if k > 0 && scale == 0.0 {
        return None;
    }
    let (mut m, mut x) = (*a, *b);
    for col in 0..k {
        let pivot = (col..k).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        if m[pivot][col].abs() <= SINGULAR * scale {
            return None;
        }
        m.swap(col, pivot);
        x.swap(col, pivot);
        for row in col + 1..k {
            let f = m[row][col] / m[col][col];
            if f != 0.0 {
                let pivot_row = m[col];
                for (target, &source) in m[row][col..k].iter_mut().zip(&pivot_row[col..k]) {
                    *target -= f * source;
                }
                x[row] -= f * x[col];
            }
        }
    }
    for row in (0..k).rev() {
        let tail: f64 = (row + 1..k).map(|c| m[row][c] * x[c]).sum();
        x[row] = (x[row] - tail) / m[row][row];
    }
    Some(x)
}

/// Exhaustive fallback for [`min_norm_point`], used when its result fails the optimality check on
/// ill-conditioned input (clusters of nearly coincident points): try every face of a simplex (at
/// most 255 for D = 8) and keep the nearest projection that falls inside its face.
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
    use super::{min_norm_point, nearest_in_simplex};

    fn nearest<const D: usize>(points: &[[f64; D]], q: [f64; D]) -> ([f64; D], f64) {
        let n = min_norm_point(points.len(), |i| points[i], &q);
        (n.point, n.distance)
    }

    #[test]
    fn triangle_in_3d_regions() {
        let t = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
        let (x, d) = nearest(&t, [0.5, 0.5, 3.0]);
        assert!((x[0] - 0.5).abs() < 1e-15 && (x[1] - 0.5).abs() < 1e-15 && x[2].abs() < 1e-15);
        assert!((d - 3.0).abs() < 1e-15);
        let (x, d) = nearest(&t, [2.0, 2.0, 0.0]);
        assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
        assert!((d - 2f64.sqrt()).abs() < 1e-15);
        let (x, d) = nearest(&t, [-1.0, -1.0, 0.0]);
        assert_eq!(x, [0.0, 0.0, 0.0]);
        assert!((d - 2f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn segment_and_inside_in_2d() {
        let s = [[0.0, 0.0], [4.0, 0.0]];
        let (x, d) = nearest(&s, [1.0, 3.0]);
        assert!((x[0] - 1.0).abs() < 1e-15 && x[1].abs() < 1e-15 && (d - 3.0).abs() < 1e-15);
        assert_eq!(nearest(&s, [7.0, 4.0]), ([4.0, 0.0], 5.0));
        let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
        assert_eq!(nearest(&square, [0.25, 0.5]).1, 0.0);
    }

    #[test]
    fn simplex_fallback_regions() {
        let t = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
        let (x, d) = nearest_in_simplex(&t, &[2.0, 2.0, 0.0]);
        assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
        assert!((d - 2f64.sqrt()).abs() < 1e-15);
        assert_eq!(
            nearest_in_simplex(&t, &[-1.0, -1.0, 0.0]).0,
            [0.0, 0.0, 0.0]
        );
    }

    #[test]
    fn support_spans_the_nearest_face() {
        // A square far from the query: the nearest point is on the edge x = 1.
        let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
        let n = min_norm_point(4, |i| square[i], &[3.0, 0.5]);
        let mut support = n.support().to_vec();
        support.sort();
        assert_eq!(support, vec![1, 2]);
        assert!((n.distance - 2.0).abs() < 1e-15);
    }
}
