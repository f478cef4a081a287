//! Certificates that a small Gram matrix is positive definite with room to spare.

use std::cmp::Ordering;

/// Whether `gram − shift·I` is positive definite as far as a floating-point Cholesky
/// factorisation can tell: the factorisation runs to the end with positive pivots (a NaN pivot
/// fails). Only the lower triangle of `gram` is read.
///
/// What success proves: the computed factor `L` satisfies `LLᵀ = gram − shift·I + E` with
/// `‖E‖₂ ≤ γ_{D+1}·tr(gram)` (Cholesky's backward error; the trace bounds `‖|L||Lᵀ|‖`), so the
/// smallest eigenvalue of `gram` is at least `shift − γ_{D+1}·tr(gram)`. Callers choose `shift`
/// with that margin and the rounding of their own Gram matrix in it.
///
/// A D × D factorisation written out (D ≤ 8): faer's needs a workspace and a dispatch that cost
/// more than the few dozen products here, on paths run once per vertex or per grasp.
///
/// ```
/// use pqhull::geometry::gram::positive_definite_after_shift;
/// let gram = [[2.0, 0.0], [1.0, 2.0]]; // eigenvalues 1 and 3 (lower triangle read)
/// assert!(positive_definite_after_shift(&gram, 0.9));
/// assert!(!positive_definite_after_shift(&gram, 1.1));
/// ```
pub fn positive_definite_after_shift<const D: usize>(gram: &[[f64; D]; D], shift: f64) -> bool {
    let mut l = [[0.0f64; D]; D];
    for j in 0..D {
        let (done, rest) = l.split_at_mut(j + 1);
        let row = &mut done[j];
        let d = gram[j][j] - shift - row[..j].iter().map(|x| x * x).sum::<f64>();
        if d.partial_cmp(&0.0) != Some(Ordering::Greater) {
            return false;
        }
        let pivot = d.sqrt();
        row[j] = pivot;
        for (offset, below) in rest.iter_mut().enumerate() {
            let dot: f64 = below[..j].iter().zip(&row[..j]).map(|(a, b)| a * b).sum();
            below[j] = (gram[j + 1 + offset][j] - dot) / pivot;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::positive_definite_after_shift;

    /// Against the eigenvalues of diagonal and rotated 2 × 2 and 3 × 3 matrices.
    #[test]
    fn decides_by_the_smallest_eigenvalue() {
        let diagonal = [[3.0, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 0.0, 7.0]];
        assert!(positive_definite_after_shift(&diagonal, 0.49));
        assert!(!positive_definite_after_shift(&diagonal, 0.51));
        // [[1, a], [a, 1]] has eigenvalues 1 ± a.
        let a = 0.75;
        let rotated = [[1.0, a], [a, 1.0]];
        assert!(positive_definite_after_shift(&rotated, 0.24));
        assert!(!positive_definite_after_shift(&rotated, 0.26));
        // Singular (rank one) and NaN: never.
        assert!(!positive_definite_after_shift(
            &[[1.0, 1.0], [1.0, 1.0]],
            1e-12
        ));
        assert!(!positive_definite_after_shift(
            &[[f64::NAN, 0.0], [0.0, 1.0]],
            0.0
        ));
    }
}
