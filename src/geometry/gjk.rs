//! GJK on a support function: certifies that the origin lies outside a wrench set's hull, with
//! its distance, before any hull is built.
//!
//! A grasp that is not force closure needs only the distance from the origin to the hull, and a
//! partial hull finds it slowly: the hull must grow over the set's boundary until the nearest
//! point is certain (up to 10⁵ inserted points for a Q∞ Minkowski sum, each paying exact
//! orientation tests and new facets; measured in docs/benchmarks.md, "Issue 3 closed"). GJK
//! answers it from support points alone, and its verdict "outside" comes
//! with a certificate; only grasps it cannot separate (force closure, or within rounding of the
//! boundary) go on to the exact partial hull.

use super::Support;
use super::nearest::{min_norm_point, solve};
use super::vector::dot;

/// Iterations of [`Gjk::run`] before it leaves the question to the partial hull.
pub const GJK_ITERATIONS: usize = 64;

/// A point of the set within this fraction of the set's size from the origin is "touching".
pub const GJK_TOUCHING: f64 = 1e-12;

/// What [`Gjk::run`] found; the face it names is in [`Gjk::face`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GjkVerdict {
    /// Certified: the origin is outside, at `distance` from the point of the set spanned by the
    /// face.
    Separated {
        /// Distance from the origin to the set.
        distance: f64,
        /// Support points inserted.
        inserted: usize,
    },
    /// A point of the set (spanned by the face) within `touching · scale` of the origin: inside,
    /// or on the boundary, or just outside.
    Touching {
        /// Distance from the origin to the face's nearest point.
        distance: f64,
        /// Support points inserted.
        inserted: usize,
    },
    /// No progress in floating point, without a certificate: `distance` is the nearest point
    /// Wolfe's algorithm converged to (as accurate as Wolfe's algorithm over every point).
    Stalled {
        /// Distance from the origin to the face's nearest point.
        distance: f64,
        /// Support points inserted.
        inserted: usize,
    },
    /// None of these within the iteration budget.
    Undecided,
}

/// GJK's reusable state: the corral (the current simplex) and the face of the last verdict.
#[derive(Clone, Debug)]
pub struct Gjk<const D: usize> {
    corral: Vec<[f64; D]>,
    next: Vec<[f64; D]>,
}

impl<const D: usize> Default for Gjk<D> {
    fn default() -> Self {
        Self {
            corral: Vec::new(),
            next: Vec::new(),
        }
    }
}

impl<const D: usize> Gjk<D> {
    /// The points spanning the nearest point of the last [`run`](Self::run) (its final corral
    /// face); empty after [`GjkVerdict::Undecided`].
    pub fn face(&self) -> &[[f64; D]] {
        &self.corral
    }

    /// GJK on the support function of `set` (a point of the set maximising `direction · p`),
    /// from the points `seeds` of the set. `scale` bounds the norm of every point of the set;
    /// `touching` (a fraction of it, 0 to never stop there) is how close to the origin a point
    /// counts as touching it.
    ///
    /// The verdict "outside" ([`GjkVerdict::Separated`]) is certified by a separating plane:
    /// `v·p ≤ h(v) < 0` for every point `p` of the set, with `h(v)` the support value of the
    /// direction `v` from the current nearest point toward the origin, and a margin above the
    /// rounding of `h`. The distance is the length of a point of the set (an upper bound) within a
    /// relative `1e−13` of the plane's distance (a lower bound); when Wolfe's algorithm stalls,
    /// within `1e−13` relative plus `1e−15·scale` (the partial hull's own outside certificate
    /// allows `1e−12` of the set's extent).
    ///
    /// Allocates nothing once its buffers have grown to the seeds' count.
    pub fn run<S: Support<D> + ?Sized>(
        &mut self,
        set: &mut S,
        scale: f64,
        seeds: &[[f64; D]],
        iterations: usize,
        touching: f64,
    ) -> GjkVerdict {
        self.corral.clear();
        self.corral.extend_from_slice(seeds);
        let mut previous = f64::INFINITY;
        for inserted in 0..iterations {
            let nearest = min_norm_point(self.corral.len(), |i| self.corral[i], &[0.0; D]);
            let x = nearest.point;
            let distance = nearest.distance;
            // The face spanning x, kept in `next` until the verdict or the next corral.
            self.next.clear();
            self.next
                .extend(nearest.support().iter().map(|&i| self.corral[i]));
            if distance <= touching * scale {
                std::mem::swap(&mut self.corral, &mut self.next);
                return GjkVerdict::Touching { distance, inserted };
            }
            let v = x.map(|c| -c);
            let Some(s) = set.support_point(&v) else {
                break;
            };
            let inserted = inserted + 1;
            let height = dot(v, s); // h(v) = max over the set of v·p
            // A separating plane needs a margin above the rounding of h (each summed term carries
            // ~1e−16 of the set's size); without one, s is GJK's next corral point.
            if certified(height, distance, scale, 0.0) {
                std::mem::swap(&mut self.corral, &mut self.next);
                return GjkVerdict::Separated { distance, inserted };
            }
            if self.next.contains(&s) || distance >= previous {
                // No progress in floating point (s is in the face, or a tie with a point of it
                // brought it back). The face is usually the right one, and only the certificate
                // is loose: its gap grows as |error of x along the face| / distance², and x, a
                // combination of points much larger than itself, carries their rounding. One
                // projection step makes x orthogonal to the face to working precision; then the
                // certificate is checked once more.
                std::mem::swap(&mut self.corral, &mut self.next);
                let x = orthogonal_to_face(&self.corral, x);
                let refined = dot(x, x).sqrt();
                let v = x.map(|c| -c);
                let Some(s) = set.support_point(&v) else {
                    break;
                };
                let height = dot(v, s);
                // Wolfe's algorithm can improve no further: the gap may also be a tiny fraction
                // of the set's size (an origin within 1e−8 of the boundary, whose distance has
                // few significant digits anyway).
                return if refined > 0.0 && certified(height, refined, scale, STALL_FLOOR) {
                    GjkVerdict::Separated {
                        distance: refined,
                        inserted,
                    }
                } else {
                    GjkVerdict::Stalled { distance, inserted }
                };
            }
            self.next.push(s);
            std::mem::swap(&mut self.corral, &mut self.next);
            previous = distance;
        }
        self.corral.clear();
        GjkVerdict::Undecided
    }
}

/// The absolute floor, as a fraction of the set's size, of the distance certificate at a stall:
/// a thousandth of the partial hull's own outside certificate (`1e−12` of the point set's
/// extent).
const STALL_FLOOR: f64 = 1e-15;

/// Whether the plane normal to `v` (|v| = `distance`, toward the origin from a point of the set
/// at that distance) with support value `height` separates the origin with a margin above the
/// rounding of `height`, and lies within `1e−13·distance + floor·scale` of that point.
fn certified(height: f64, distance: f64, scale: f64, floor: f64) -> bool {
    // The plane's distance from the origin, −h/|v|, is a lower bound on the set's.
    let gap = distance + height / distance;
    height < -1e-12 * scale * distance && gap <= 1e-13 * distance + floor * scale
}

/// `x`, a point of the affine hull of `face`, moved within it to be orthogonal to it: one step
/// `x − E·(EᵀE)⁻¹·Eᵀx` with `E` the face's edge vectors from its first point (unchanged when the
/// face is a single point or its Gram matrix is singular).
fn orthogonal_to_face<const D: usize>(face: &[[f64; D]], x: [f64; D]) -> [f64; D] {
    let Some((base, rest)) = face.split_first() else {
        return x;
    };
    let k = rest.len().min(8);
    let mut edges = [[0.0; D]; 8];
    for (e, p) in edges.iter_mut().zip(rest) {
        *e = std::array::from_fn(|c| p[c] - base[c]);
    }
    let mut gram = [[0.0; 8]; 8];
    let mut residual = [0.0; 8];
    for r in 0..k {
        for c in 0..k {
            gram[r][c] = dot(edges[r], edges[c]);
        }
        residual[r] = dot(edges[r], x);
    }
    let Some(correction) = solve(&gram, &residual, k) else {
        return x;
    };
    let mut moved = x;
    for (e, &c) in edges[..k].iter().zip(&correction) {
        for (m, &ec) in moved.iter_mut().zip(e) {
            *m -= c * ec;
        }
    }
    moved
}
