//! Exact orientation predicates in any dimension D (2 ≤ D ≤ 8).
//!
//! SPEC (to be replaced by real docs): see the helper brief.

/// The sign of an orientation determinant.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// Strictly negative.
    Negative,
    /// Exactly zero.
    Zero,
    /// Strictly positive.
    Positive,
}

/// Exact sign of `det[v1 − v0; …; v(D−1) − v0; p − v0]`.
pub fn orientation<const D: usize>(vertices: &[[f64; D]; D], p: &[f64; D]) -> Sign {
    let _ = (vertices, p);
    todo!()
}

/// The hyperplane through D points, cached for fast exact side tests.
#[derive(Clone, Debug)]
pub struct FacetPlane<const D: usize> {
    base: [f64; D],
    cofactors: [f64; D],
    error: [f64; D],
}

impl<const D: usize> FacetPlane<D> {
    /// Caches the plane through `vertices`.
    pub fn new(vertices: &[[f64; D]; D]) -> Self {
        let _ = vertices;
        todo!()
    }

    /// Approximate orientation determinant of (vertices, p) and a certified bound on its error.
    pub fn evaluate(&self, p: &[f64; D]) -> (f64, f64) {
        let _ = (p, &self.base, &self.error);
        todo!()
    }

    /// The exact sign of `orientation(vertices, p)`.
    pub fn side(&self, p: &[f64; D], vertices: impl FnOnce() -> [[f64; D]; D]) -> Sign {
        let _ = (p, vertices);
        todo!()
    }

    /// The cofactor vector (an unnormalised normal, pointing to the positive side).
    pub fn cofactors(&self) -> &[f64; D] {
        &self.cofactors
    }
}

/// Indices of a maximal affinely independent subset of `points`, found with exact arithmetic.
pub fn affinely_independent_subset<const D: usize>(points: &[[f64; D]]) -> Vec<usize> {
    let _ = points;
    todo!()
}
