//! The penetration depth of two convex polytopes: the signed distance from the origin to the
//! boundary of their Minkowski difference `A ⊖ B = {a − b}`, found by the partial hull grown
//! toward the origin over that difference, implicitly (never materialised).
//!
//! For convex `C = A ⊖ B` the signed distance from the origin to `∂C` is `min_{|u|=1} h_C(u)`,
//! `h_C(u) = max_a u·a − min_b u·b`: positive when the interiors of `A` and `B` overlap (the
//! length of the smallest translation of `B` that separates them), negative when they are
//! disjoint (minus their distance), zero when they touch. It is what physics engines' EPA
//! computes in 3-D and in floating point; here it is [`ClosestToOrigin`] over a
//! [`MinkowskiSum`] of `A` and `−B`, in any dimension 2 to 8, with GJK first for separated
//! bodies.

use super::{ClosestToOrigin, DistanceResult, MinkowskiSum, SourceError, Stats};
use crate::geometry::vector::{dot, norm};
use crate::geometry::{GJK_ITERATIONS, GJK_TOUCHING, Gjk, GjkVerdict, Support};
use crate::geometry::{Rng, min_norm_point, min_norm_point_exact};
use crate::hull::{Hull, HullError};
use crate::predicates::lowest_bit_exponent;
use std::fmt;
use std::time::Instant;

/// One of the two bodies of [`penetration_depth`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Body {
    /// The first argument, `a`.
    A,
    /// The second argument, `b`.
    B,
}

impl fmt::Display for Body {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Body::A => "a",
            Body::B => "b",
        })
    }
}

/// How the two bodies lie, as the exact answer on the caller's vertices decides it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Relation {
    /// Their interiors overlap: the depth is positive.
    Overlapping,
    /// They touch: the depth is within [`Penetration::rounding`] of zero (exactly zero when the
    /// differences `a − b` are exact in `f64`, as they are for integer and most dyadic input),
    /// so its sign cannot be told from the differences computed in floating point.
    Touching,
    /// They are disjoint: the depth is negative.
    Separated,
}

/// What [`penetration_depth`] finds.
#[derive(Clone, Debug, PartialEq)]
pub struct Penetration<const D: usize> {
    /// Signed: the length of the smallest translation that separates the interiors (positive,
    /// overlapping), or minus the distance between the bodies (negative, disjoint).
    ///
    /// Within `1e−12` of itself or `2e−15` of [`scale`](Self::scale) of the exact value on the
    /// caller's vertices: it is the exact engine's answer on the differences `fl(a − b)`, each
    /// within [`rounding`](Self::rounding) of the true one.
    pub depth: f64,
    /// Unit: translating `b` by `depth · direction` (or `a` by the opposite) makes the bodies
    /// touch. Overlapping, the outward normal of the difference's facet nearest the origin (`b`
    /// is pushed along it); disjoint, from the nearest point of `a` toward the nearest point of
    /// `b` (the depth is negative: `b` moves back along it by the distance).
    pub direction: [f64; D],
    /// How they lie.
    pub relation: Relation,
    /// A bound on `|fl(a − b) − (a − b)|` over every pair of vertices (and so on how far the
    /// depth of the computed differences can be from the exact one): 0 when every difference
    /// is exact in `f64`, else half an ulp of the largest difference.
    pub rounding: f64,
    /// A bound on the norm of every difference `a − b`: the size the accuracy is measured in.
    pub scale: f64,
    /// Work done by the partial hull (zero when GJK decided: separated bodies need no hull).
    pub stats: Stats,
}

impl<const D: usize> Penetration<D> {
    /// `depth · direction`: the translation of `b` that makes the bodies touch.
    ///
    /// ```
    /// use pqhull::strategy::penetration_depth;
    /// let a = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    /// let b = [[1.5, 0.5], [3.0, 0.5], [3.0, 1.5], [1.5, 1.5]];
    /// let p = penetration_depth(&a, &b)?;
    /// assert_eq!(p.translation(), [0.5, 0.0]); // push b right by 0.5
    /// # Ok::<(), pqhull::strategy::PenetrationError<2>>(())
    /// ```
    pub fn translation(&self) -> [f64; D] {
        self.direction.map(|c| self.depth * c)
    }
}

/// Why [`penetration_depth`] could not answer. Each variant names the body and the vertex.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum PenetrationError<const D: usize> {
    /// A body has no vertex.
    Empty {
        /// Which.
        body: Body,
    },
    /// A vertex has a NaN or infinite coordinate.
    NonFinite {
        /// Which body.
        body: Body,
        /// The vertex's index.
        index: usize,
        /// The coordinate's index.
        coordinate: usize,
    },
    /// A difference `a − b` overflows `f64` along `coordinate` (the bodies' extents along it
    /// are finite, but more than `f64::MAX` apart).
    DifferenceOverflow {
        /// The coordinate.
        coordinate: usize,
    },
    /// The differences lie (within rounding) in a hyperplane through or next to the origin —
    /// bodies whose difference is flat, e.g. two polygons in one plane of 3-D — and there are
    /// more pairs than the flat case materialises ([`FLAT_PAIRS_LIMIT`]).
    FlatTooLarge {
        /// `|a| · |b|`.
        pairs: usize,
    },
    /// The difference's support function broke the partial hull's source contract: a bug,
    /// reported rather than hidden.
    Source(SourceError<D>),
    /// The hull engine refused the seeds: a bug, reported rather than hidden.
    Hull(HullError),
}

impl<const D: usize> fmt::Display for PenetrationError<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PenetrationError::Empty { body } => write!(f, "body {body} has no vertex"),
            PenetrationError::NonFinite {
                body,
                index,
                coordinate,
            } => write!(
                f,
                "vertex {index} of body {body} has a NaN or infinite coordinate (coordinate \
                 {coordinate})"
            ),
            PenetrationError::DifferenceOverflow { coordinate } => write!(
                f,
                "the bodies are more than f64::MAX apart along coordinate {coordinate}: their \
                 differences overflow"
            ),
            PenetrationError::FlatTooLarge { pairs } => write!(
                f,
                "the bodies' difference is flat (it spans fewer than {D} dimensions) and touches \
                 or nearly touches the origin; its {pairs} vertex pairs are more than the flat \
                 case materialises ({FLAT_PAIRS_LIMIT})"
            ),
            PenetrationError::Source(e) => write!(f, "internal error: {e}"),
            PenetrationError::Hull(e) => write!(f, "internal error: {e}"),
        }
    }
}

impl<const D: usize> std::error::Error for PenetrationError<D> {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PenetrationError::Source(e) => Some(e),
            PenetrationError::Hull(e) => Some(e),
            _ => None,
        }
    }
}

/// The most vertex pairs the flat case (a difference spanning fewer than D dimensions, within
/// rounding of the origin) materialises for its exact affine rank and Wolfe's exact nearest
/// point: 2^16, whose time (two coplanar 256-gons in 3-D) docs/limits.md gives; both grow
/// faster than the pairs.
pub const FLAT_PAIRS_LIMIT: usize = 1 << 16;

/// The signed penetration depth of the convex hulls of `a` and `b` (their vertices, or any
/// points whose hulls they are), with the direction that separates them.
///
/// In order: GJK on the difference's support function, whose certified separation gives
/// minus the distance; otherwise [`ClosestToOrigin`] over the implicit difference
/// ([`MinkowskiSum`] of `a` and `−b`), seeded with its support points along the axes, the
/// diagonals `e_i ± e_j` and a few fixed pseudo-random directions. The work is that of the
/// facets near the origin, not of the `|a|·|b|` differences.
///
/// ```
/// use pqhull::strategy::{Relation, penetration_depth};
/// // Two unit cubes, the second shifted by (0.75, 0.1, 0.2): they overlap by 0.25 along x.
/// let cube: Vec<[f64; 3]> = (0..8)
///     .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64])
///     .collect();
/// let shifted: Vec<[f64; 3]> =
///     cube.iter().map(|p| [p[0] + 0.75, p[1] + 0.1, p[2] + 0.2]).collect();
/// let p = penetration_depth(&cube, &shifted)?;
/// assert_eq!(p.relation, Relation::Overlapping);
/// assert_eq!(p.depth, 0.25);
/// assert_eq!(p.translation(), [0.25, 0.0, 0.0]);
/// // Moved apart by 2 along y: disjoint, 0.9 apart.
/// let apart: Vec<[f64; 3]> = shifted.iter().map(|p| [p[0], p[1] + 2.0, p[2]]).collect();
/// let q = penetration_depth(&cube, &apart)?;
/// assert_eq!(q.relation, Relation::Separated);
/// assert!((q.depth + 1.1).abs() < 1e-15);
/// # Ok::<(), pqhull::strategy::PenetrationError<3>>(())
/// ```
///
/// # Errors
/// [`PenetrationError`]: an empty body, a vertex with a NaN or infinite coordinate, bodies so
/// far apart that their differences overflow, or a flat difference near the origin with more
/// than [`FLAT_PAIRS_LIMIT`] pairs. Checked before any work.
pub fn penetration_depth<const D: usize>(
    a: &[[f64; D]],
    b: &[[f64; D]],
) -> Result<Penetration<D>, PenetrationError<D>> {
    let started = Instant::now();
    check_body(a, Body::A)?;
    check_body(b, Body::B)?;
    let (scale, rounding) = difference_bounds(a, b)?;
    let mut sum = MinkowskiSum::<D>::default();
    sum.refill(2, |i, set| {
        if i == 0 {
            set.extend_from_slice(a);
        } else {
            set.extend(b.iter().map(|p| p.map(|c| -c)));
        }
    });
    let seeds = seed_points(&mut sum);
    let answer = |depth: f64, direction: [f64; D], stats: Stats| {
        let mut stats = stats;
        stats.elapsed = started.elapsed();
        let depth = if depth == 0.0 { 0.0 } else { depth }; // no −0
        Penetration {
            depth,
            direction,
            relation: relation(depth, rounding, scale),
            rounding,
            scale,
            stats,
        }
    };

    // Separated bodies: GJK's certified plane, no hull.
    let mut gjk = Gjk::<D>::default();
    if let GjkVerdict::Separated { .. } =
        gjk.run(&mut sum, scale, &seeds, GJK_ITERATIONS, GJK_TOUCHING)
    {
        // GJK's face holds a point of the difference within 1e−13 of the distance (its
        // certificate): its nearest point, exactly.
        let face = gjk.face();
        let nearest = min_norm_point(face.len(), |i| face[i], &[0.0; D]);
        let slack = 1e-12 * nearest.distance + 1e-15 * scale;
        if let Some((depth, direction)) = exact_nearest(face, nearest.distance, slack) {
            return Ok(answer(depth, direction, Stats::default()));
        }
    }

    let strategy = ClosestToOrigin::with_source([0.0; D], sum);
    match Hull::try_with_strategy(&seeds, strategy) {
        Ok((hull, Ok(result))) => {
            let (depth, direction) = refined(&hull, &result);
            Ok(answer(depth, direction, result.stats))
        }
        Ok((_, Err(e))) => Err(PenetrationError::Source(e)),
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
            let (depth, direction, stats) = flat(a, b)?;
            Ok(answer(depth, direction, stats))
        }
        Err(e) => Err(PenetrationError::Hull(e)),
    }
}

/// The depth and direction from [`ClosestToOrigin`]'s answer, its last ulps made exact: inside,
/// the deciding facet's distance from the exact determinant and cofactors (a few ulps, where the
/// plane's floating-point offset carries the rounding of its vertices' size); outside, Wolfe's
/// algorithm in exact arithmetic over the deciding facet's D vertices (which hold the nearest
/// point), rounded once — kept only when it agrees with the floating-point answer to the latter's
/// accuracy, as it must.
fn refined<const D: usize>(hull: &Hull<D>, result: &DistanceResult<D>) -> (f64, [f64; D]) {
    let depth = result.signed_distance;
    let facet = result.closest_facet;
    if depth > 0.0 {
        let exact = hull
            .exact_signed_distance(facet, &[0.0; D])
            .map_or(depth, |d| -d);
        let depth = if exact > 0.0 { exact } else { depth };
        return (depth, hull.facet(facet).normal());
    }
    if depth == 0.0 {
        return (0.0, hull.facet(facet).normal());
    }
    let vertices = result.closest_facet_vertices.map(|v| hull.point(v));
    let slack = 1e-12 * depth.abs() + 1e-15 * hull.coordinate_bound();
    exact_nearest(&vertices, -depth, slack)
        .unwrap_or((depth, unit(result.nearest_point.map(|c| -c))))
}

/// Minus the distance from the origin to `conv(face)` and the direction toward the face's
/// nearest point from it, by Wolfe's algorithm in exact arithmetic (rounded once), when that
/// distance is positive and within `slack` of `rough` (the floating-point distance it refines).
fn exact_nearest<const D: usize>(
    face: &[[f64; D]],
    rough: f64,
    slack: f64,
) -> Option<(f64, [f64; D])> {
    if face.is_empty() {
        return None;
    }
    let nearest = min_norm_point_exact(face.len(), |i| face[i], &[0.0; D], &[]);
    let agrees = (nearest.distance - rough).abs() <= slack;
    (agrees && nearest.distance > 0.0).then(|| (-nearest.distance, unit(nearest.point.map(|c| -c))))
}

/// The seeds span fewer than D dimensions: the difference itself may (bodies whose difference
/// is flat, such as two polygons in one plane of 3-D), so every difference is materialised and
/// its hull is taken; when that is flat too, the interiors cannot overlap and the depth is
/// minus the distance to the origin, by Wolfe's algorithm in exact arithmetic.
fn flat<const D: usize>(
    a: &[[f64; D]],
    b: &[[f64; D]],
) -> Result<(f64, [f64; D], Stats), PenetrationError<D>> {
    let pairs = a.len().saturating_mul(b.len());
    if pairs > FLAT_PAIRS_LIMIT {
        return Err(PenetrationError::FlatTooLarge { pairs });
    }
    let differences: Vec<[f64; D]> = a
        .iter()
        .flat_map(|p| b.iter().map(move |q| std::array::from_fn(|c| p[c] - q[c])))
        .collect();
    match Hull::try_with_strategy(&differences, ClosestToOrigin::new()) {
        Ok((hull, result)) => {
            let (depth, direction) = refined(&hull, &result);
            Ok((depth, direction, result.stats))
        }
        Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
            let nearest =
                min_norm_point_exact(differences.len(), |i| differences[i], &[0.0; D], &[]);
            let mut direction = unit(nearest.point.map(|c| -c));
            if nearest.distance == 0.0 {
                // Touching: any direction out of the flat separates; the first axis the
                // differences do not span is not needed — a normal of the flat will do.
                direction = flat_normal(&differences);
            }
            Ok((-nearest.distance, direction, Stats::default()))
        }
        Err(e) => Err(PenetrationError::Hull(e)),
    }
}

/// A unit vector orthogonal (to rounding) to the affine hull of flat `points`: the axis least
/// in the span of their edges, orthogonalised against them (modified Gram–Schmidt, twice).
fn flat_normal<const D: usize>(points: &[[f64; D]]) -> [f64; D] {
    let base = points[0];
    let mut basis: Vec<[f64; D]> = Vec::with_capacity(D);
    for p in points {
        let mut e: [f64; D] = std::array::from_fn(|c| p[c] - base[c]);
        let size = norm(e);
        for _ in 0..2 {
            for f in &basis {
                let along = dot(e, *f);
                e = std::array::from_fn(|c| e[c] - along * f[c]);
            }
        }
        let n = norm(e);
        if n > 1e-9 * size && n > 0.0 && basis.len() < D - 1 {
            basis.push(e.map(|c| c / n));
        }
    }
    let weight = |axis: usize| basis.iter().map(|e| e[axis] * e[axis]).sum::<f64>();
    let axis = (0..D)
        .min_by(|&x, &y| weight(x).total_cmp(&weight(y)))
        .expect("D ≥ 2");
    let mut normal = [0.0; D];
    normal[axis] = 1.0;
    for _ in 0..2 {
        for f in &basis {
            let along = dot(normal, *f);
            normal = std::array::from_fn(|c| normal[c] - along * f[c]);
        }
    }
    unit(normal)
}

fn unit<const D: usize>(v: [f64; D]) -> [f64; D] {
    let n = norm(v);
    if n > 0.0 && n.is_finite() {
        v.map(|c| c / n)
    } else {
        let mut e = [0.0; D];
        e[0] = 1.0;
        e
    }
}

fn check_body<const D: usize>(points: &[[f64; D]], body: Body) -> Result<(), PenetrationError<D>> {
    if points.is_empty() {
        return Err(PenetrationError::Empty { body });
    }
    for (index, p) in points.iter().enumerate() {
        if let Some(coordinate) = p.iter().position(|x| !x.is_finite()) {
            return Err(PenetrationError::NonFinite {
                body,
                index,
                coordinate,
            });
        }
    }
    Ok(())
}

/// A bound on the norm of every difference (the scale) and on the rounding of every difference
/// computed in `f64` (0 when each is exact).
///
/// Per coordinate, `|a_k − b_k| ≤ m_k = max(max a_k − min b_k, max b_k − min a_k)`, and
/// `fl(x)` is within half an ulp of `x`, at most `2^−53·|x|`. Every difference is exact when
/// every coordinate `k` of both bodies is a multiple of one power of two `2^e_k` and the span
/// of the coordinate is below `2^(52 + e_k)`: the difference is then a multiple of `2^e_k` below
/// `2^53` of them.
fn difference_bounds<const D: usize>(
    a: &[[f64; D]],
    b: &[[f64; D]],
) -> Result<(f64, f64), PenetrationError<D>> {
    let extent = |points: &[[f64; D]], k: usize| {
        points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[k]), hi.max(p[k]))
            })
    };
    let mut squares = 0.0f64;
    let mut exact = true;
    let mut largest = 0.0f64;
    for k in 0..D {
        let (a_lo, a_hi) = extent(a, k);
        let (b_lo, b_hi) = extent(b, k);
        let m = (a_hi - b_lo).max(b_hi - a_lo);
        if !m.is_finite() {
            return Err(PenetrationError::DifferenceOverflow { coordinate: k });
        }
        // Rounded up: the bound must hold for the true differences.
        let m = m * (1.0 + f64::EPSILON);
        largest = largest.max(m);
        squares += m * m;
        let exponent = a
            .iter()
            .chain(b)
            .map(|p| p[k])
            .filter(|&x| x != 0.0)
            .map(lowest_bit_exponent)
            .min();
        if let Some(e) = exponent {
            let span = a_hi.max(b_hi) - a_lo.min(b_lo);
            exact &= e > -1000 && span < 2f64.powi(52 + e.min(971));
        }
    }
    let scale = if squares.is_finite() {
        squares.sqrt() * (1.0 + f64::EPSILON)
    } else {
        largest * (D as f64).sqrt() * (1.0 + f64::EPSILON)
    };
    let rounding = if exact {
        0.0
    } else {
        scale * f64::EPSILON * 0.5 * (1.0 + f64::EPSILON)
    };
    Ok((scale, rounding))
}

/// The relation the depth defends: its sign when farther from zero than the rounding of the
/// differences plus the depth's own accuracy on them, touching otherwise.
fn relation(depth: f64, rounding: f64, scale: f64) -> Relation {
    let band = if rounding == 0.0 {
        0.0 // exact differences: the engine's sign is exact
    } else {
        rounding + 1e-12 * depth.abs() + 2e-15 * scale
    };
    if depth > band {
        Relation::Overlapping
    } else if depth < -band {
        Relation::Separated
    } else {
        Relation::Touching
    }
}

/// Pseudo-random seed directions beside the axes and diagonals, so that a difference with few
/// vertices is rarely missed by every seed (a flat seed set sends the run to the materialising
/// fallback).
const RANDOM_SEEDS: usize = 8;

/// Support points of the difference along ± every axis (so the hull's coordinate range covers
/// every difference: rounding is monotone, so the extreme difference along an axis is the
/// difference of the extremes), the diagonals `e_i ± e_j` and [`RANDOM_SEEDS`] fixed
/// directions, without repeats.
fn seed_points<const D: usize>(sum: &mut MinkowskiSum<D>) -> Vec<[f64; D]> {
    let mut seeds: Vec<[f64; D]> = Vec::with_capacity(2 * D * D + RANDOM_SEEDS);
    let mut add = |sum: &mut MinkowskiSum<D>, direction: [f64; D]| {
        if let Some(p) = sum.support_point(&direction)
            && !seeds.contains(&p)
        {
            seeds.push(p);
        }
    };
    for i in 0..D {
        for sign in [1.0, -1.0] {
            let mut e = [0.0; D];
            e[i] = sign;
            add(sum, e);
        }
        for j in i + 1..D {
            for sign in [1.0, -1.0] {
                let mut e = [0.0; D];
                e[i] = 1.0;
                e[j] = sign;
                add(sum, e);
                add(sum, e.map(|c| -c));
            }
        }
    }
    let mut rng = Rng::new(0x5eed_0fde_97a3);
    for _ in 0..RANDOM_SEEDS {
        let direction: [f64; D] = std::array::from_fn(|_| rng.normal());
        add(sum, direction);
    }
    seeds
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_differences_are_recognised() {
        let a = [[0.0, 1.0], [3.0, 0.5]];
        let b = [[0.25, -2.0]];
        assert_eq!(difference_bounds(&a, &b).unwrap().1, 0.0);
        let c = [[0.1, 1.0], [3.0, 0.5]];
        assert!(difference_bounds(&c, &b).unwrap().1 > 0.0);
        let far = [[f64::MAX, 0.0]];
        let near = [[-f64::MAX, 0.0]];
        assert_eq!(
            difference_bounds(&far, &near),
            Err(PenetrationError::DifferenceOverflow { coordinate: 0 })
        );
    }
}
