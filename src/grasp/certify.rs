//! Values on the caller's own wrenches, certified from a hull of nearby (snapped) points.
//!
//! The metrics search on wrenches snapped to a grid on which every friction pyramid is exactly
//! planar ([`super::snap`]): there the exact hull sees the true, degenerate structure and is fast.
//! The caller's wrenches — computed the natural way in `f64` — differ from the snapped ones by up
//! to `δ` ≈ 6·10⁻⁸ of their size, and so would the metric. This module turns the hull found on
//! the snapped points into a rigorous bracket `[low, high]` of the metric on the *raw* points;
//! when the bracket is narrower than the promised accuracy, its midpoint is reported, otherwise
//! the caller falls back to the exact engine on the raw points.
//!
//! # The argument
//!
//! Let `P` be a hull (partial or full) of snapped points with the origin strictly inside, `S` its
//! boundary: a closed simplicial surface. Give each vertex `s` of `S` its raw point `r(s)`, a
//! point of the raw set's hull `H` within `δ` of `s`, and let `S_t` be the surface with vertices
//! `(1 − t)·s + t·r(s)`. Every point of a simplex of `S_t` is within `δ` of the snapped simplex,
//! so when every snapped simplex keeps the origin farther than `δ`, no `S_t` passes through the
//! origin and the origin's winding number about `S_1` is that about `S_0`: one. A point whose
//! winding number is not zero lies in the convex hull of the surface's vertices (outside it, a
//! plane separates it from the whole surface), so every point joined to the origin by a path
//! that misses `S_1` lies in `H`.
//!
//! * **Q1** (`g(u) = |u|`): for a raw simplex `F` and any direction `u`, every point `x` of `F`
//!   has `|x| ≥ u·x / |u| ≥ min_j u·r_j / |u|`. So the ball of radius `low = min_F min_j u_F·r_j
//!   / |u_F|` misses `S_1`, lies in `H`, and `Q1 ≥ low`. Any unit `u` gives `Q1 ≤ h_H(u)`, the
//!   support function of the raw set: `high = min over tried u of h(u)/|u|`.
//! * **Q_OWS** (`g(u) = max_d −u·d` over the disturbances `d`): the segment from the origin to
//!   `−ρ·d` misses `F` when `ρ·g(u_F) < min_j u_F·r_j`; with `low = min_F min_j u_F·r_j / g(u_F)`
//!   every such segment for `ρ ≤ low` lies in `H`, so `Q_OWS ≥ low`; and `Q_OWS ≤ h(u)/g(u)` for
//!   every `u` with `g(u) > 0` (the largest `ρ` with `−ρ·d ∈ H` for the `d` attaining `g(u)`).
//!
//! `u_F` may be any direction: only the bracket's width depends on how well it fits the raw
//! simplex. Each facet is first bounded cheaply through its snapped vertices (`u_F·r ≥ u_F·s −
//! δ|u_F|`); only facets whose cheap bound is below the running minimum get the raw simplex's
//! own normal, which brings the bracket to the rounding of a few dot products. Every dot product
//! carries its rounding bound (γ₆ ≤ 6.7·10⁻¹⁶ of `Σ|a_c b_c|`), so `low` and `high` are rigorous.

use crate::geometry::min_norm_point;
use crate::hull::{FacetId, Hull};
use crate::predicates::exact_cofactor_direction;

/// Rounding of a six-term dot product, relative to `Σ|a_c·b_c|`: γ₆ = 6u/(1 − 6u) ≤ 6.7·10⁻¹⁶,
/// u = 2⁻⁵³ (Higham, *Accuracy and Stability of Numerical Algorithms*, §3.1), rounded up to
/// cover the rounding of `Σ|a_c·b_c|` itself.
const DOT_ROUNDING: f64 = 1e-15;

/// Absolute slack for products that underflow (six terms, each off by at most 2⁻¹⁰⁷⁴).
const UNDERFLOW: f64 = 6.0 * 4.9e-324;

/// `a·b` and a bound on its rounding error.
pub(in crate::grasp) fn dot_with_error(a: &[f64; 6], b: &[f64; 6]) -> (f64, f64) {
    let mut sum = 0.0;
    let mut magnitude = 0.0;
    for (x, y) in a.iter().zip(b) {
        sum += x * y;
        magnitude += (x * y).abs();
    }
    (sum, DOT_ROUNDING * magnitude + UNDERFLOW)
}

/// Bounds on |u| (relative rounding of a square root of a six-term sum of squares < 1e−15).
fn norm_bounds(u: &[f64; 6]) -> (f64, f64) {
    let n = u.iter().map(|x| x * x).sum::<f64>().sqrt();
    (n * (1.0 - 1e-15), n * (1.0 + 1e-15))
}

/// The function `g` whose ratio `h(u)/g(u)` the metric minimises (see the module docs).
pub(in crate::grasp) trait Gauge {
    /// An upper bound on `g(u)`, as cheap as possible (every facet asks).
    fn upper_cheap(&mut self, u: &[f64; 6]) -> f64;
    /// A tight upper bound on `g(u)`.
    fn upper(&mut self, u: &[f64; 6]) -> f64;
    /// A tight lower bound on `g(u)`.
    fn lower(&mut self, u: &[f64; 6]) -> f64;
}

/// Q1: `g(u) = |u|`, the disturbances of the unit ball.
pub(in crate::grasp) struct UnitBall;

impl Gauge for UnitBall {
    fn upper_cheap(&mut self, u: &[f64; 6]) -> f64 {
        norm_bounds(u).1
    }
    fn upper(&mut self, u: &[f64; 6]) -> f64 {
        norm_bounds(u).1
    }
    fn lower(&mut self, u: &[f64; 6]) -> f64 {
        norm_bounds(u).0
    }
}

/// Q_OWS: `g(u) = max_d −u·d` over the disturbances of a support index.
pub(in crate::grasp) struct Disturbances<'a> {
    pub(in crate::grasp) index: &'a crate::geometry::SupportIndex<6>,
}

impl Disturbances<'_> {
    /// The float support value of `−u` and a bound on the rounding of every dot product.
    fn support(&self, u: &[f64; 6]) -> Option<(f64, f64)> {
        let minus = u.map(|c| -c);
        let (value, _) = self.index.support(&minus)?;
        let error = DOT_ROUNDING * norm_bounds(u).1 * self.index.norm_bound() + UNDERFLOW;
        Some((value, error))
    }
}

impl Gauge for Disturbances<'_> {
    fn upper_cheap(&mut self, u: &[f64; 6]) -> f64 {
        // The ball tree's bound carries a 1e−12 relative slack, covering its rounding.
        self.index.upper_bound(&u.map(|c| -c), 5)
    }
    fn upper(&mut self, u: &[f64; 6]) -> f64 {
        self.support(u).map_or(f64::INFINITY, |(v, e)| v + e)
    }
    fn lower(&mut self, u: &[f64; 6]) -> f64 {
        self.support(u).map_or(f64::NEG_INFINITY, |(v, e)| v - e)
    }
}

/// A rigorous bracket of a metric on the raw points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::grasp) struct Bracket {
    /// A lower bound on the metric.
    pub(in crate::grasp) low: f64,
    /// An upper bound on the metric.
    pub(in crate::grasp) high: f64,
    /// The facet whose raw simplex gave `high`.
    pub(in crate::grasp) facet: FacetId,
}

impl Bracket {
    /// The midpoint, when the bracket is within the accuracy the metrics promise: `1e−12`
    /// relative, or `1e−14·scale` for values near zero (half of each, to leave room for the
    /// reference's own rounding).
    pub(in crate::grasp) fn value_within(&self, scale: f64) -> Option<f64> {
        let width = self.high - self.low;
        let allowed = (5e-13 * self.high.abs()).max(5e-15 * scale);
        (width >= 0.0 && width <= allowed).then_some(0.5 * (self.low + self.high))
    }
}

/// What the bracket needs of the raw point set.
pub(in crate::grasp) struct RawSide<R, H> {
    /// The raw point of hull input `v`, as computed in floating point (`None` when unknown: the
    /// facet then keeps its cheap bound).
    pub(in crate::grasp) point: R,
    /// A bound on the distance between [`point`](Self::point)'s result and the true raw point
    /// (0 when the raw point *is* the float value, as the caller's wrenches are).
    pub(in crate::grasp) error: f64,
    /// A bound on the distance between every snapped hull input and its true raw point.
    pub(in crate::grasp) delta: f64,
    /// The raw set's support function: `max_w u·w` and a bound on its rounding error.
    pub(in crate::grasp) support: H,
}

/// Scratch reused from one bracket to the next.
#[derive(Clone, Debug, Default)]
pub(in crate::grasp) struct BracketScratch {
    cheap: Vec<(f64, FacetId)>,
    /// The facets the last bracket bounded from their raw simplices, with those bounds (at
    /// least their cheap ones), and how many of `cheap` that was.
    bounded: Vec<(f64, FacetId)>,
    processed: usize,
}

/// The facets of the last [`bracket`] call whose lower bound is at most `limit`: every facet
/// that may be as near as `limit` under that call's gauge (the bounds from the raw simplices
/// where it computed them, else the cheap ones).
pub(in crate::grasp) fn candidates(
    scratch: &BracketScratch,
    limit: f64,
) -> impl Iterator<Item = FacetId> + '_ {
    let bounded = scratch.bounded.iter().filter(move |(low, _)| *low <= limit);
    // Not sorted beyond what the bracket looked at (see `next_sorted`): filtered, not cut.
    let rest = scratch.cheap[scratch.processed..]
        .iter()
        .filter(move |(low, _)| *low <= limit);
    bounded.chain(rest).map(|&(_, id)| id)
}

/// The bracket of the metric `gauge` on the raw points from `hull`, built on the snapped points,
/// which must hold the origin strictly inside; `None` when the snapped surface passes within `δ`
/// of the origin (the argument needs the origin farther away) or no raw simplex gives an upper
/// bound.
pub(in crate::grasp) fn bracket<R, H, G>(
    hull: &Hull<6>,
    raw: &mut RawSide<R, H>,
    gauge: &mut G,
    scratch: &mut BracketScratch,
) -> Option<Bracket>
where
    R: FnMut(usize) -> Option<[f64; 6]>,
    H: FnMut(&[f64; 6]) -> (f64, f64),
    G: Gauge,
{
    let cheap = &mut scratch.cheap;
    cheap.clear();
    for (id, facet) in hull.facets() {
        let u = facet.normal();
        let (_, u_high) = norm_bounds(&u);
        let mut nearest = f64::INFINITY;
        for v in facet.vertices() {
            let (height, error) = dot_with_error(&u, &hull.point(v));
            nearest = nearest.min(height - error);
        }
        // The snapped simplex lies at least `nearest / |u|` from the origin: it must exceed δ.
        let margin = nearest - raw.delta * u_high;
        if margin.is_nan() || margin <= 0.0 {
            return None;
        }
        let g = gauge.upper_cheap(&u);
        let low = if g > 0.0 { margin / g } else { f64::INFINITY };
        cheap.push((low, id));
    }
    let mut low = f64::INFINITY;
    let mut best: Option<(f64, FacetId)> = None;
    scratch.bounded.clear();
    scratch.processed = cheap.len();
    let mut sorted = 0;
    for index in 0..cheap.len() {
        if index == sorted {
            sorted = next_sorted(cheap, index);
        }
        let (cheap_low, id) = cheap[index];
        if cheap_low >= low {
            scratch.processed = index;
            break; // every remaining facet's bound is at least this one's
        }
        let mut facet_low = cheap_low;
        if let Some(points) = raw_simplex(hull, id, &mut raw.point) {
            // The raw simplex's own normal: tight for a well-shaped simplex.
            let own = own_normal(hull, id, &points);
            let mut own_low = f64::NEG_INFINITY;
            if let Some(u) = own {
                let (bound, high) = along(&u, &points, raw, gauge);
                own_low = bound;
                facet_low = facet_low.max(bound);
                if let Some(high) = high
                    && best.is_none_or(|(b, _)| high < b)
                {
                    best = Some((high, id));
                }
            }
            // A sliver's own plane is tilted by its vertices' perturbation (on a flat face of
            // the hull, split into thin simplices, it can be far from the face's plane): the
            // direction of its point nearest the origin bounds it as tightly as the face's
            // normal would.
            if own_low <= cheap_low {
                let nearest = min_norm_point(6, |i| points[i], &[0.0; 6]);
                if nearest.distance > 0.0 {
                    let (bound, high) = along(&nearest.point, &points, raw, gauge);
                    facet_low = facet_low.max(bound);
                    if let Some(high) = high
                        && best.is_none_or(|(b, _)| high < b)
                    {
                        best = Some((high, id));
                    }
                }
            }
        }
        low = low.min(facet_low);
        scratch.bounded.push((facet_low, id));
    }
    // Rounding of the divisions above (half an ulp each): nudge `low` down.
    let low = low * (1.0 - 2e-16);
    let (high, facet) = best?;
    Some(Bracket { low, high, facet })
}

/// How many facets [`bracket`] puts in order at a time: it nearly always stops within the
/// first few (the bound of the nearest facet is already above the next ones' cheap bounds).
const SORTED_CHUNK: usize = 8;

/// Puts the smallest [`SORTED_CHUNK`] bounds of `cheap[from..]` in order at `from` (every
/// later one at least as large) and returns where the sorted prefix now ends: a selection and
/// a sort of a few, where sorting every facet (several hundred at 4 × 32) cost more than the
/// bounds the bracket then looked at.
fn next_sorted(cheap: &mut [(f64, FacetId)], from: usize) -> usize {
    let rest = &mut cheap[from..];
    let end = SORTED_CHUNK.min(rest.len());
    if end < rest.len() {
        rest.select_nth_unstable_by(end - 1, |a, b| a.0.total_cmp(&b.0));
    }
    rest[..end].sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    from + end
}

/// An upper bound on the metric of the raw points from facet `id` of the snapped hull: the
/// support along its raw simplex's own normal (or, failing that, the facet's), through the
/// gauge. For a *boundary* grasp — the origin within `δ` of the snapped surface, where
/// [`bracket`] has no lower bound — the raw points lie within rounding of a supporting
/// hyperplane through the origin, and this bound is tiny: with a lower bound from elsewhere
/// (0 for a set holding the origin, −GJK's distance otherwise) it pins the value.
pub(in crate::grasp) fn upper_bound_at<R, H, G>(
    hull: &Hull<6>,
    id: FacetId,
    raw: &mut RawSide<R, H>,
    gauge: &mut G,
) -> Option<f64>
where
    R: FnMut(usize) -> Option<[f64; 6]>,
    H: FnMut(&[f64; 6]) -> (f64, f64),
    G: Gauge,
{
    let points = raw_simplex(hull, id, &mut raw.point);
    let own = points.and_then(|p| own_normal(hull, id, &p));
    // `along`'s lower bound (the only use of the points) is not needed here.
    let points = points.unwrap_or_default();
    let mut high: Option<f64> = None;
    for u in own.into_iter().chain([hull.facet(id).normal()]) {
        if let (_, Some(h)) = along(&u, &points, raw, gauge) {
            high = Some(high.map_or(h, |b: f64| b.min(h)));
        }
    }
    high
}

/// The raw points of facet `id`'s vertices, when every one is known.
fn raw_simplex<R>(hull: &Hull<6>, id: FacetId, point: &mut R) -> Option<[[f64; 6]; 6]>
where
    R: FnMut(usize) -> Option<[f64; 6]>,
{
    let vertices = hull.facet(id).vertices();
    let mut points = [[0.0; 6]; 6];
    for (p, &v) in points.iter_mut().zip(&vertices) {
        *p = point(v)?;
    }
    Some(points)
}

/// The normal of the raw simplex on `points` (floating point, or from the exact cofactors for a
/// thin one), oriented as facet `id`'s.
fn own_normal(hull: &Hull<6>, id: FacetId, points: &[[f64; 6]; 6]) -> Option<[f64; 6]> {
    let u = hyperplane_normal(points).or_else(|| exact_normal(points))?;
    let outward = dot_with_error(&u, &hull.facet(id).normal()).0 >= 0.0;
    Some(if outward { u } else { u.map(|c| -c) })
}

/// The bounds direction `u` (pointing away from the origin) gives for the raw simplex on
/// `points`: a lower bound on the metric past that simplex, `(min_j u·r_j − error) / g⁺(u)`
/// (`−∞` when not positive), and, when the gauge is positive along `u`, the upper bound
/// `(h(u) + error) / g⁻(u)` on the metric itself. Rigorous for any `u`: every dot product carries
/// its rounding bound.
fn along<R, H, G>(
    u: &[f64; 6],
    points: &[[f64; 6]; 6],
    raw: &mut RawSide<R, H>,
    gauge: &mut G,
) -> (f64, Option<f64>)
where
    H: FnMut(&[f64; 6]) -> (f64, f64),
    G: Gauge,
{
    let (_, u_high) = norm_bounds(u);
    let mut nearest = f64::INFINITY;
    for p in points {
        let (height, error) = dot_with_error(u, p);
        nearest = nearest.min(height - error);
    }
    let margin = nearest - raw.error * u_high;
    let g = gauge.upper(u);
    let low = if margin > 0.0 {
        if g > 0.0 { margin / g } else { f64::INFINITY }
    } else {
        f64::NEG_INFINITY
    };
    let g_low = gauge.lower(u);
    let high = (g_low > 0.0).then(|| {
        let (h, error) = (raw.support)(u);
        // The division rounds by half an ulp: nudge up.
        (h + error) / g_low * (1.0 + 2e-16)
    });
    (low, high)
}

/// The direction of the exact cofactors of the simplex on `points` (a few ulps per component),
/// for the thin simplices whose floating-point normal [`hyperplane_normal`] refuses: a sliver
/// facet of the snapped hull (a Minkowski sum's flat faces triangulate into many) whose raw
/// simplex still needs a precise normal, else its bound stays the cheap one, `δ` wide. `None`
/// when the points are exactly affinely dependent.
fn exact_normal(points: &[[f64; 6]; 6]) -> Option<[f64; 6]> {
    let u = exact_cofactor_direction(points);
    u.iter().any(|&c| c != 0.0).then_some(u)
}

/// A normal of the hyperplane through six points (not normalised), or `None` when they are
/// affinely dependent in floating point. Only the bracket's width depends on its accuracy: two
/// passes of modified Gram–Schmidt on the edge vectors, then the coordinate axis least in their
/// span, orthogonalised twice.
pub(in crate::grasp) fn hyperplane_normal(points: &[[f64; 6]; 6]) -> Option<[f64; 6]> {
    let base = points[0];
    let mut basis = [[0.0; 6]; 5];
    let scale = points
        .iter()
        .flat_map(|p| p.iter().zip(&base).map(|(a, b)| (a - b).abs()))
        .fold(0.0, f64::max);
    if !scale.is_finite() || scale <= 0.0 {
        return None;
    }
    for (i, e) in basis.iter_mut().enumerate() {
        *e = std::array::from_fn(|c| (points[i + 1][c] - base[c]) / scale);
    }
    for i in 0..5 {
        for _ in 0..2 {
            for j in 0..i {
                let (b, a) = basis.split_at_mut(i);
                project_out(&mut a[0], &b[j]);
            }
        }
        let n = basis[i].iter().map(|x| x * x).sum::<f64>().sqrt();
        if n.is_nan() || n <= 1e-13 {
            return None;
        }
        basis[i] = basis[i].map(|x| x / n);
    }
    // The axis with the least weight in the span.
    let axis = (0..6)
        .min_by(|&a, &b| {
            let weight = |c: usize| basis.iter().map(|e| e[c] * e[c]).sum::<f64>();
            weight(a).total_cmp(&weight(b))
        })
        .expect("six axes");
    let mut normal = [0.0; 6];
    normal[axis] = 1.0;
    for _ in 0..2 {
        for e in &basis {
            project_out(&mut normal, e);
        }
    }
    let n = normal.iter().map(|x| x * x).sum::<f64>().sqrt();
    (n > 0.1).then(|| normal.map(|x| x / n))
}

/// `v ← v − (v·e) e` for a unit `e`.
fn project_out(v: &mut [f64; 6], e: &[f64; 6]) {
    let along: f64 = v.iter().zip(e).map(|(a, b)| a * b).sum();
    for (x, y) in v.iter_mut().zip(e) {
        *x -= along * y;
    }
}

/// The support function of an explicit point set, `max_w u·w`, and its rounding bound.
pub(in crate::grasp) fn support_with_error(points: &[[f64; 6]], u: &[f64; 6]) -> (f64, f64) {
    let mut best = (f64::NEG_INFINITY, 0.0);
    for w in points {
        let (h, error) = dot_with_error(u, w);
        // The bound must cover the true maximum: keep the largest upper end's error.
        if h + error > best.0 + best.1 {
            best = (h, error);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hyperplane_normal_is_orthogonal_to_the_edges() {
        let points = [
            [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
        ];
        let n = hyperplane_normal(&points).unwrap();
        let expected = 1.0 / 6f64.sqrt();
        for c in n {
            assert!((c.abs() - expected).abs() < 1e-15, "{n:?}");
        }
        let mut flat = points;
        flat[5] = [0.5, 0.5, 0.0, 0.0, 0.0, 0.0];
        assert!(hyperplane_normal(&flat).is_none());
    }

    #[test]
    fn dot_error_bounds_the_exact_value() {
        // 0.1·3 + 0.2·(−1.5) in exact rationals is 0; the float sum must be within the bound.
        let a = [0.1, 0.2, 0.0, 0.0, 0.0, 0.0];
        let b = [3.0, -1.5, 0.0, 0.0, 0.0, 0.0];
        let (value, error) = dot_with_error(&a, &b);
        assert!(value.abs() <= error && error < 1e-15);
    }
}
