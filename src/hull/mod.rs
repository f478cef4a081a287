//! The QuickHull engine: facet arena, initial simplex, horizon, outside sets, expansion, checker.
//!
//! The engine knows topology and predicates, never a strategy's goal. A [`Strategy`] drives it
//! through [`StrategyHooks::expand`] (add the farthest point beyond a facet), [`StrategyHooks::expand_with`] (add a
//! chosen point) and [`StrategyHooks::claim_beyond`] (make sure a facet's outside set holds every remaining
//! point beyond it), and stops when it likes.
//!
//! # Invariants kept between expansions
//!
//! * Live facets form a closed, consistently oriented simplicial (D−1)-manifold: neighbour `i` of
//!   facet `F` is live and has `F` as a neighbour, and they share all vertices but `F`'s vertex `i`.
//! * Every input point that is not a hull vertex is either in exactly one outside set — of a facet
//!   it lies strictly beyond — or lies weakly inside every live facet.
//! * Every "beyond" decision is an exact orientation sign ([`crate::predicates`]).
//!
//! Points are copied and scaled by a power of two so that every coordinate lies in [−1, 1]
//! (exact: the orientation signs are unchanged), which keeps the fast floating-point filter of the
//! predicates valid. Normals, offsets, distances and volumes are reported in the caller's units.

mod build;
mod check;
mod coplanar;
mod error;
mod expand;
mod facet;
mod farthest_point;
mod hooks;
mod incremental;
mod locate;
mod planes;
mod record;
mod repeats;
mod strategy;
mod trace;
mod volume;

pub use build::{MAX_DIMENSION, MIN_DIMENSION};
pub use error::{HullError, InvariantViolation};
pub use expand::SUPPORT_SCAN_POINTS;
pub use facet::{Facet, FacetId};
pub use farthest_point::{FarthestPoint, FarthestReason};
pub use hooks::{Partition, StrategyHooks};
pub use record::{Event, FacetSnapshot, Key, Replay, Trace, TraceContext, TraceReason};
pub use strategy::{ReusableStrategy, Stats, Step, Strategy};

use crate::geometry::vector::norm;
use crate::predicates::{ExactGrid, Sign};

/// No declared flat (see [`Hull::rebuild_with_flats`]).
pub const NO_FLAT: u32 = u32::MAX;
use std::time::Instant;

/// A convex hull in dimension `D` (2 ≤ D ≤ 8), full or partial depending on the strategy that grew
/// it.
///
/// ```
/// use pqhull::Hull;
/// let cube: Vec<[f64; 3]> = (0..8)
///     .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64])
///     .chain([[0.5, 0.5, 0.5]])
///     .collect();
/// let hull = Hull::try_new(&cube)?;
/// assert_eq!(hull.vertex_indices(), (0..8).collect::<Vec<_>>());
/// assert_eq!(hull.facet_count(), 12); // two triangles per square face
/// assert!((hull.volume() - 1.0).abs() < 1e-12);
/// hull.check()?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct Hull<const D: usize> {
    /// Input points scaled by `scale` (a power of two), so that |coordinate| ≤ 1.
    points: Vec<[f64; D]>,
    scale: f64,
    /// `1 / scale`, exact (a power of two) unless it overflows (`scale` = 2^−1024, for input
    /// near `f64::MAX`): multiplying by it is dividing by `scale`, bit for bit, without a
    /// division's latency on every new facet (see `unscale`).
    inv_scale: f64,
    facets: Vec<Facet<D>>,
    /// Tombstoned slots, reusable by later expansions.
    free: Vec<FacetId>,
    /// The facets' hyperplanes, one per coplanar region.
    planes: planes::Planes<D>,
    live: usize,
    next_serial: u64,
    epoch: u32,
    /// A point inside the initial simplex (internal coordinates), reference for volumes.
    interior: [f64; D],
    stats: Stats,
    started: Instant,
    scratch: expand::Scratch<D>,
    /// Per input point, the declared affine flat holding it ([`NO_FLAT`] for none); empty when
    /// nothing was declared (see [`Hull::rebuild_with_flats`]).
    flat_of: Vec<u32>,
    /// The dimension of every declared flat.
    flat_dim: usize,
    /// When every point lies on one coarse power-of-two grid, the proof that the filter's value
    /// is exact for every side test among them ([`ExactGrid`]); `None` otherwise.
    grid: Option<ExactGrid<D>>,
    /// Whether every point is in `[−1, 1]^D` (as the scale makes them, unless scaling would not
    /// have been exact): a new facet's plane then need not check its vertices again
    /// ([`FacetPlane::new_in_range`](crate::predicates::FacetPlane::new_in_range)).
    in_box: bool,
    /// Which new facet an outside point goes to ([`StrategyHooks::set_partition`]).
    partition: Partition<D>,
    /// The initial simplex the next build starts from, when a caller knows a better one than the
    /// greedy choice ([`Hull::start_next_build_from`]); taken by the build.
    start: Option<[usize; build::MAX_SIMPLEX]>,
    /// The run being recorded, if any ([`Hull::try_with_strategy_traced`]); `None` costs each
    /// trace hook one branch.
    trace: Option<Box<Trace<D>>>,
    /// Whether a facet whose plane holds the new point exactly stays (see
    /// [`keep_coplanar_facets`](Self::keep_coplanar_facets)) in every build, its vertex set
    /// left as it is; `false` for every public build (a full one keeps them in a first phase
    /// only, `coplanar.rs`).
    keep_coplanar: bool,
    /// Where the build under way is in a full build's phases (see `coplanar.rs`); a build
    /// keeps coplanar facets when `keep_coplanar` is set or in either phase.
    phase: coplanar::Phase,
    /// Whether the first phase has kept a facet whose plane held the new point.
    kept_in_first_phase: bool,
}

impl<const D: usize> Hull<D> {
    /// The full convex hull of `points` (QuickHull with [`FarthestPoint`]).
    ///
    /// # Errors
    /// [`HullError`] for a dimension outside 2..=8, fewer than D + 1 points, a NaN or infinite
    /// coordinate (with its index), or points spanning fewer than D dimensions (with the rank).
    pub fn try_new(points: &[[f64; D]]) -> Result<Self, HullError> {
        Self::try_with_strategy(points, FarthestPoint::new()).map(|(hull, _)| hull)
    }

    /// Builds the initial simplex, then lets `strategy` expand the hull until it stops.
    ///
    /// Returns the (possibly partial) hull and the strategy's output.
    ///
    /// # Errors
    /// As [`Hull::try_new`].
    pub fn try_with_strategy<S: Strategy<D>>(
        points: &[[f64; D]],
        strategy: S,
    ) -> Result<(Self, S::Output), HullError> {
        Ok(Self::try_initial(points, strategy.partitions_to_farthest())?.run(strategy))
    }

    /// Runs `strategy` on a hull holding its initial simplex (traced or not).
    fn run<S: Strategy<D>>(mut self, strategy: S) -> (Self, S::Output) {
        let output = self.run_in_place(strategy);
        (self, output)
    }

    fn run_in_place<S: Strategy<D>>(&mut self, mut strategy: S) -> S::Output {
        strategy.start(self);
        while strategy.step(self) == Step::Continue {}
        // A full build's phases end with the run: points added later are added the default
        // way (or kept, when asked for every build).
        self.phase = coplanar::Phase::None;
        if strategy.refines_all_normals() {
            self.refine_normals();
        }
        self.stats.elapsed = self.started.elapsed();
        strategy.finish(self)
    }

    /// [`try_with_strategy`](Self::try_with_strategy) for new `points`, in this hull's storage:
    /// the facet arena, the outside-set buffers, the point buffer and the expansion scratch are
    /// reused, so evaluating many similar point sets (a grasp planner's candidates) allocates
    /// nothing in steady state beyond what the strategy itself does — except one box per facet
    /// whose floating-point filter fails (its exact-arithmetic cache), which generic input never
    /// needs (`tests/allocation.rs`).
    ///
    /// ```
    /// use pqhull::{ClosestToOrigin, Hull};
    /// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    /// let (mut hull, first) = Hull::try_with_strategy(&square, ClosestToOrigin::new())?;
    /// let wide = square.map(|p| [3.0 * p[0], p[1]]);
    /// let second = hull.rebuild_with_strategy(&wide, ClosestToOrigin::new())?;
    /// assert!((first.signed_distance - 1.0).abs() < 1e-15);
    /// assert!((second.signed_distance - 1.0).abs() < 1e-15);
    /// assert_eq!(hull.facet_count(), 4);
    /// hull.check()?;
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`Hull::try_new`]; the hull is then left empty (no live facet) and can be rebuilt again.
    pub fn rebuild_with_strategy<S: Strategy<D>>(
        &mut self,
        points: &[[f64; D]],
        strategy: S,
    ) -> Result<S::Output, HullError> {
        self.flat_of.clear();
        self.initialise(points, strategy.partitions_to_farthest())?;
        Ok(self.run_in_place(strategy))
    }

    /// [`rebuild_with_strategy`](Self::rebuild_with_strategy) for points of which some are known
    /// to lie, *exactly*, in common affine flats of dimension `flat_dim`: `flat_of[i]` names the
    /// flat holding point `i` ([`NO_FLAT`] for none; missing entries count as none).
    ///
    /// A facet with `flat_dim + 1` vertices in one flat contains that flat (a facet's vertices
    /// are affinely independent, so those vertices span it), and every other point of the flat
    /// lies exactly on the facet's hyperplane: the engine then answers `Zero` without arithmetic.
    /// The friction pyramids of a grasp are such flats (`flat_dim` 2, made exact by snapping): a
    /// point of a pyramid tested against a facet through three of its edges is the common case in
    /// which the floating-point filter fails and exact arithmetic is needed.
    ///
    /// The claim is checked before anything is built: each flat's points must span at most
    /// `flat_dim` dimensions (exact rank, rational arithmetic: a cost per flat, paid once, that
    /// the grasp layer, which proves its flats by construction, skips).
    ///
    /// ```
    /// use pqhull::{FarthestPoint, Hull, HullError};
    /// // A square pyramid: the base's four corners lie in one 2-flat (label 0).
    /// let points = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.5, 0.5, 1.0]];
    /// let mut hull = Hull::empty();
    /// hull.rebuild_with_flats(&points, &[0, 0, 0, 0], 2, FarthestPoint::new())?;
    /// assert_eq!(hull.vertex_indices(), vec![0, 1, 2, 3, 4]);
    /// // The apex is not in the base's plane: the claim is refused.
    /// let wrong = hull.rebuild_with_flats(&points, &[0, 0, 0, 0, 0], 2, FarthestPoint::new());
    /// assert!(matches!(wrong, Err(HullError::NotInFlat { index: 4, .. })));
    /// # Ok::<(), HullError>(())
    /// ```
    ///
    /// # Errors
    /// As [`Hull::try_new`]; [`HullError::FlatDimension`] for `flat_dim` outside `1..D`,
    /// [`HullError::TooManyFlatLabels`] for more labels than points, and
    /// [`HullError::NotInFlat`] for a flat whose points span more than `flat_dim` dimensions.
    /// The hull is then left empty.
    pub fn rebuild_with_flats<S: Strategy<D>>(
        &mut self,
        points: &[[f64; D]],
        flat_of: &[u32],
        flat_dim: usize,
        strategy: S,
    ) -> Result<S::Output, HullError> {
        if let Err(error) = check_flats(points, flat_of, flat_dim) {
            self.flat_of.clear();
            // An empty point set leaves the hull empty (no live facet).
            let _ = self.initialise(&[], false);
            return Err(error);
        }
        self.rebuild_with_trusted_flats(points, flat_of, flat_dim, strategy)
    }

    /// [`rebuild_with_flats`](Self::rebuild_with_flats) without the check of the claim, for
    /// callers that prove it by construction (the grasp layer's snapped friction pyramids). A
    /// point declared in a flat it is not in exactly makes a wrong hull (never undefined
    /// behaviour); `flat_dim` must be in `1..D`.
    pub(crate) fn rebuild_with_trusted_flats<S: Strategy<D>>(
        &mut self,
        points: &[[f64; D]],
        flat_of: &[u32],
        flat_dim: usize,
        strategy: S,
    ) -> Result<S::Output, HullError> {
        if !(1..D).contains(&flat_dim) {
            return Err(HullError::FlatDimension {
                flat_dim,
                dimension: D,
            });
        }
        self.flat_of.clear();
        self.flat_of.extend_from_slice(flat_of);
        self.flat_dim = flat_dim;
        self.initialise(points, strategy.partitions_to_farthest())?;
        Ok(self.run_in_place(strategy))
    }

    /// Asks the next build (only) to start from the simplex on the input points `simplex`
    /// (D + 1 indices) instead of the greedy one: a caller that knows points around the query
    /// (the grasp layer: the simplex GJK ends with, which holds the origin) saves the partial
    /// strategy the expansions that would first bring the query inside. Ignored when the points
    /// are not affinely independent, exactly, or an index is out of range.
    pub(crate) fn start_next_build_from(&mut self, simplex: &[usize]) {
        self.start = (simplex.len() == D + 1).then(|| {
            let mut start = [0; build::MAX_SIMPLEX];
            start[..=D].copy_from_slice(simplex);
            start
        });
    }

    /// Whether the following builds keep a facet whose hyperplane holds the new point exactly,
    /// instead of removing it with the visible ones (the default), from start to end and with
    /// no second phase to prune the vertices (a public full build keeps them in a first phase
    /// only, then makes its vertices the extreme points: `coplanar.rs`).
    ///
    /// Why: a coplanar facet removed and coned again from the new point is what keeps points
    /// that are not extreme out of the vertices (a point inside a flat face stops being a vertex
    /// when a later point on that face is added). But on input with large exactly coplanar
    /// regions — the snapped Minkowski sum of Q∞ by the full method, a product of polygons
    /// whose every facet holds 2k² points — every point on a region's plane then removes and
    /// cones again the whole region: 1.74 million facets created for 512 points at 3 contacts ×
    /// 8 edges, against 52 thousand when the region stays (`cli/examples/profile_hull.rs`).
    /// Kept, the hull is the same polytope and every facet lies in one of its facets'
    /// hyperplanes (`Hull::check` holds), but a vertex may be a point on a face that is not
    /// extreme: for callers that read only facets' planes (a distance, a nearest facet), never
    /// the vertex set.
    pub(crate) fn keep_coplanar_facets(&mut self, keep: bool) {
        self.keep_coplanar = keep;
    }

    /// Makes every live facet's normal precise (see [`Facet::normal_is_precise`]): an exact
    /// cofactor computation for each thin facet a partial strategy left unrefined.
    pub fn refine_normals(&mut self) {
        for i in 0..self.facets.len() {
            if self.facets[i].alive {
                self.refine_normal(FacetId(i as u32));
            }
        }
    }

    /// The dimension D.
    pub fn dimension(&self) -> usize {
        D
    }

    /// Number of input points.
    pub fn point_count(&self) -> usize {
        self.points.len()
    }

    /// Input point `index`, in the caller's coordinates.
    ///
    /// # Panics
    /// If `index >= self.point_count()`.
    pub fn point(&self, index: usize) -> [f64; D] {
        self.points[index].map(|x| x / self.scale)
    }

    /// Sorted input indices of the hull's vertices.
    pub fn vertex_indices(&self) -> Vec<usize> {
        let mut seen = vec![false; self.points.len()];
        for (_, facet) in self.facets() {
            for &v in &facet.vertices {
                seen[v as usize] = true;
            }
        }
        seen.iter()
            .enumerate()
            .filter_map(|(i, &s)| s.then_some(i))
            .collect()
    }

    /// The live facets with their ids.
    pub fn facets(&self) -> impl Iterator<Item = (FacetId, &Facet<D>)> + '_ {
        self.facets
            .iter()
            .enumerate()
            .filter(|(_, f)| f.alive)
            .map(|(i, f)| (FacetId(i as u32), f))
    }

    /// Number of live facets.
    pub fn facet_count(&self) -> usize {
        self.live
    }

    /// The facet in slot `id` (live or tombstoned; see [`Facet::is_alive`]).
    ///
    /// # Panics
    /// If `id` was never issued by this hull.
    pub fn facet(&self, id: FacetId) -> &Facet<D> {
        &self.facets[id.index()]
    }

    /// The engine's side of [`StrategyHooks::is_current`].
    pub(crate) fn is_current(&self, id: FacetId, serial: u64) -> bool {
        self.facets
            .get(id.index())
            .is_some_and(|f| f.alive && f.serial == serial)
    }

    /// Whether any input point remains in some outside set (false once the hull is complete).
    pub fn has_outside_points(&self) -> bool {
        self.facets().any(|(_, f)| !f.outside.is_empty())
    }

    /// Work counters so far (`elapsed` is set when the strategy stops).
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// Exact side of `x` (caller's units) relative to facet `id`'s plane: [`Sign::Positive`] when
    /// strictly beyond.
    ///
    /// Exact whenever scaling `x` into the hull's internal coordinates is exact (always, unless `x`
    /// has coordinates more than ~10^300 times larger or smaller than the input's); otherwise the
    /// sign of the floating-point [`signed_distance`](Self::signed_distance).
    pub fn side_of(&self, id: FacetId, x: &[f64; D]) -> Sign {
        if let Some(scaled) = self.scaled_exactly(x) {
            self.side(id, &scaled)
        } else {
            match self.signed_distance(id, x) {
                d if d > 0.0 => Sign::Positive,
                d if d < 0.0 => Sign::Negative,
                _ => Sign::Zero,
            }
        }
    }

    /// `x` in the internal coordinates, if scaling it there is exact.
    fn scaled_exactly(&self, x: &[f64; D]) -> Option<[f64; D]> {
        let scaled = x.map(|c| c * self.scale);
        x.iter()
            .zip(&scaled)
            .all(|(&c, &s)| s.is_finite() && (c == 0.0 || s.abs() >= f64::MIN_POSITIVE))
            .then_some(scaled)
    }

    /// The engine's side of [`StrategyHooks::coordinate_bound`].
    pub(crate) fn coordinate_bound(&self) -> f64 {
        1.0 / self.scale
    }

    /// The engine's side of [`StrategyHooks::exact_signed_distance`].
    pub(crate) fn exact_signed_distance(&self, id: FacetId, x: &[f64; D]) -> Option<f64> {
        let scaled = self.scaled_exactly(x)?;
        let (plane, vertices) = self.exact_plane_of(id);
        let distance = plane.exact_distance(&self.coords(vertices), &scaled);
        Some(distance / self.scale)
    }

    /// The engine's side of [`StrategyHooks::distance_upper_bound`].
    pub(crate) fn distance_upper_bound(&self, id: FacetId, x: &[f64; D]) -> f64 {
        let facet = self.facet(id);
        if facet.precise {
            return facet.signed_distance(x);
        }
        let scaled = x.map(|c| c * self.scale);
        let plane = &facet.filter;
        let (value, bound) = plane.evaluate(&scaled);
        let cofactors = plane.cofactors();
        let errors = plane.cofactor_errors();
        let (length, error) = (norm(*cofactors), norm(*errors));
        if length.partial_cmp(&error) != Some(std::cmp::Ordering::Greater) || !bound.is_finite() {
            return f64::INFINITY;
        }
        let top = value + bound;
        let distance = if top >= 0.0 {
            top / (length - error)
        } else {
            top / (length + error)
        };
        // Cover the rounding of this very computation.
        (distance + distance.abs() * 1e-12) / self.scale
    }

    /// Signed distance of `x` (caller's units) beyond facet `id`'s plane, positive outside.
    pub fn signed_distance(&self, id: FacetId, x: &[f64; D]) -> f64 {
        self.facet(id).signed_distance(x)
    }
}

/// The checks of [`Hull::rebuild_with_flats`]: the flat dimension, the labels' count, finite
/// coordinates, and each flat's exact affine rank.
fn check_flats<const D: usize>(
    points: &[[f64; D]],
    flat_of: &[u32],
    flat_dim: usize,
) -> Result<(), HullError> {
    if !(1..D).contains(&flat_dim) {
        return Err(HullError::FlatDimension {
            flat_dim,
            dimension: D,
        });
    }
    if flat_of.len() > points.len() {
        return Err(HullError::TooManyFlatLabels {
            labels: flat_of.len(),
            points: points.len(),
        });
    }
    if let Some((index, p)) = points
        .iter()
        .enumerate()
        .find(|(_, p)| p.iter().any(|x| !x.is_finite()))
    {
        let coordinate = p.iter().position(|x| !x.is_finite()).unwrap_or(0);
        return Err(HullError::NonFinite { index, coordinate });
    }
    let mut members: Vec<(u32, usize)> = flat_of
        .iter()
        .enumerate()
        .filter(|&(_, &f)| f != NO_FLAT)
        .map(|(i, &f)| (f, i))
        .collect();
    members.sort_unstable();
    for group in members.chunk_by(|a, b| a.0 == b.0) {
        let flat: Vec<[f64; D]> = group.iter().map(|&(_, i)| points[i]).collect();
        let independent = crate::predicates::affinely_independent_subset(&flat);
        if independent.len() > flat_dim + 1 {
            return Err(HullError::NotInFlat {
                flat: group[0].0,
                index: group[independent[flat_dim + 1]].1,
                flat_dim,
            });
        }
    }
    Ok(())
}
