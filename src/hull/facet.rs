//! Facets: simplices with neighbour links, stored in the hull's arena.

use crate::geometry::vector::dot;
use crate::predicates::FacetPlane;

/// A handle to a facet in a [`Hull`](crate::Hull)'s arena.
///
/// Ids are slot indices. When an expansion removes a facet its slot is tombstoned and may be reused
/// by a facet created in a *later* expansion, so a strategy that keeps ids across expansions should
/// also keep the facet's [`serial`](Facet::serial) and compare it (see
/// [`StrategyHooks::is_current`](crate::hull::StrategyHooks::is_current)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FacetId(pub(in crate::hull) u32);

impl FacetId {
    /// The slot index in the arena.
    pub fn index(self) -> usize {
        self.0 as usize
    }

    /// Placeholder for a neighbour link not yet made.
    pub(in crate::hull) const NONE: FacetId = FacetId(u32::MAX);
}

/// At most this many declared flats, each of dimension ≥ 1 (so with ≥ 2 vertices), fit in the
/// D ≤ 8 vertices of one facet.
pub(in crate::hull) const MAX_FLATS: usize = 4;

/// A simplicial facet of a hull: D vertices, D neighbours, an outward plane.
///
/// Neighbour `i` is the facet across the ridge opposite vertex `i`. The vertex order is oriented:
/// the exact orientation determinant of `(vertices, p)` is positive exactly when `p` lies strictly
/// beyond the facet.
#[derive(Clone, Debug)]
pub struct Facet<const D: usize> {
    pub(in crate::hull) vertices: [u32; D],
    pub(in crate::hull) neighbors: [FacetId; D],
    /// The slot of its coplanar region's shared plane in the hull's arena (`hull/planes.rs`),
    /// or `NO_SLOT` while the facet is alone in its region: facets with the same slot span the
    /// same hyperplane, exactly. The slot holds the exact-arithmetic cache of the region and the
    /// vertices its plane was built from.
    pub(in crate::hull) plane: u32,
    /// The plane's floating-point part, in the facet so that the filter (the common case) reads
    /// nothing else: the facet's own plane, or a copy of its region's (whose exact cache then
    /// stays empty: the slot's serves).
    pub(in crate::hull) filter: FacetPlane<D>,
    /// 1 / |cofactors| of that plane: turns an orientation value into a distance (internal units).
    pub(in crate::hull) inv_norm: f64,
    /// Unit outward normal.
    pub(in crate::hull) normal: [f64; D],
    /// Whether `normal` is certified to a relative 1e−11 (else it is the floating-point normal of
    /// a facet whose cofactors cancelled, refined on demand by `StrategyHooks::refine_normal`).
    pub(in crate::hull) precise: bool,
    /// Offset in the caller's coordinates.
    pub(in crate::hull) offset: f64,
    /// Declared flats (see `Hull::rebuild_with_flats`) that this facet's hyperplane contains,
    /// padded with `NO_FLAT`.
    pub(in crate::hull) flats: [u32; MAX_FLATS],
    /// Input indices of the points assigned to this facet (each strictly beyond it).
    pub(in crate::hull) outside: Vec<u32>,
    /// Position in `outside` of the point farthest beyond, with its orientation value.
    pub(in crate::hull) farthest: Option<(u32, f64)>,
    pub(in crate::hull) alive: bool,
    pub(in crate::hull) serial: u64,
    /// Visit epoch and verdict of the last horizon search that looked at this facet: `visible`
    /// when the new point is on or beyond it, `touching` when exactly on its plane.
    pub(in crate::hull) mark: u32,
    pub(in crate::hull) visible: bool,
    pub(in crate::hull) touching: bool,
}

impl<const D: usize> Facet<D> {
    /// Vertices as input indices, in oriented order.
    pub fn vertices(&self) -> [usize; D] {
        self.vertices.map(|v| v as usize)
    }

    /// Neighbours; neighbour `i` is opposite vertex `i`.
    pub fn neighbors(&self) -> [FacetId; D] {
        self.neighbors
    }

    /// Unit outward normal, computed in floating point from the exact vertex coordinates.
    ///
    /// Accurate to a relative 1e−11 when [`normal_is_precise`](Self::normal_is_precise) — always
    /// for hulls built with [`FarthestPoint`](crate::FarthestPoint) and after
    /// [`Hull::refine_normals`](crate::Hull::refine_normals). A partial strategy refines only the facets it reports, so other
    /// facets of a partial hull may carry the plain floating-point normal of a thin facet (whose
    /// cofactors cancel), which can be off by more.
    pub fn normal(&self) -> [f64; D] {
        self.normal
    }

    /// Whether [`normal`](Self::normal) and [`offset`](Self::offset) are certified to a relative
    /// 1e−11 (see [`Hull::refine_normals`](crate::Hull::refine_normals)).
    pub fn normal_is_precise(&self) -> bool {
        self.precise
    }

    /// Offset: points inside satisfy `normal · x <= offset` (up to rounding of the normal).
    pub fn offset(&self) -> f64 {
        self.offset
    }

    /// Signed distance of `x` beyond the facet's plane (positive outside), in the caller's units.
    pub fn signed_distance(&self, x: &[f64; D]) -> f64 {
        dot(self.normal, *x) - self.offset
    }

    /// How many input points are assigned to this facet's outside set.
    pub fn outside_len(&self) -> usize {
        self.outside.len()
    }

    /// Input indices of the points assigned to this facet (each strictly beyond it).
    pub fn outside_set(&self) -> impl Iterator<Item = usize> + '_ {
        self.outside.iter().map(|&p| p as usize)
    }

    /// The input index of the point farthest beyond this facet, if any.
    pub fn farthest_point(&self) -> Option<usize> {
        self.farthest
            .map(|(slot, _)| self.outside[slot as usize] as usize)
    }

    /// Creation number, unique over the life of the hull (ids are reused, serials are not).
    pub fn serial(&self) -> u64 {
        self.serial
    }

    /// The declared flats (see [`Hull::rebuild_with_flats`](crate::Hull::rebuild_with_flats))
    /// this facet contains.
    pub fn contained_flats(&self) -> impl Iterator<Item = u32> + '_ {
        self.flats.iter().copied().filter(|&g| g != super::NO_FLAT)
    }

    /// Whether the facet is part of the current hull.
    pub fn is_alive(&self) -> bool {
        self.alive
    }
}
