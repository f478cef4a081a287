//! The hooks a strategy drives the engine with, apart from what a user of a hull calls.
//!
//! A [`Strategy`](super::Strategy) grows the hull through these ([`StrategyHooks::expand`],
//! [`StrategyHooks::claim_beyond`], …), reads the engine's state and the facets' exact planes
//! through them, and explains its choices to a trace. They are a trait, implemented by [`Hull`]
//! alone (sealed), so that `Hull`'s own methods are the ones a user of a hull needs: a
//! strategy's author writes `use pqhull::hull::StrategyHooks;`. The built-in strategies use
//! exactly these, so a strategy written outside the crate runs at their cost
//! (examples/custom_strategy.rs).

use super::{FacetId, Hull, TraceReason};

/// Where an expansion puts each outside point of the facets it removes: in the outside set of
/// one new facet it lies strictly beyond (exactly decided), chosen as follows. Every choice
/// gives the same hull and the same answers; they differ in the work (see
/// [`StrategyHooks::set_partition`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Partition<const D: usize> {
    /// The new facet it lies farthest beyond (Qhull's option `Qf`): every new facet tested.
    Farthest,
    /// The first new facet found to hold it, in creation order (Qhull's default): testing
    /// stops there.
    FirstFound,
    /// The first found, the new facets tried in order of their planes' distance from this
    /// point (the caller's coordinates), nearest first: a strategy that grows the hull
    /// towards a query inside it keeps the points beyond the facets near the query in their
    /// outside sets, at the cost of one sort of the new facets per expansion.
    NearestFirst([f64; D]),
}

mod sealed {
    /// Only [`Hull`](crate::Hull) implements the hooks: the engine's invariants depend on them.
    pub trait Sealed {}
}

impl<const D: usize> sealed::Sealed for Hull<D> {}

/// The hooks a [`Strategy`](super::Strategy) drives the engine with. See the module
/// documentation; implemented by [`Hull`] only.
///
/// ```
/// use pqhull::Hull;
/// use pqhull::hull::StrategyHooks;
///
/// let points = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [0.4, 0.4]];
/// let mut hull = Hull::try_new(&points)?;
/// // Every facet of a full hull is current, and nothing lies beyond it.
/// let (id, facet) = hull.facets().next().unwrap();
/// let serial = facet.serial();
/// assert!(hull.is_current(id, serial));
/// assert!(!hull.claim_beyond(id));
/// # Ok::<(), pqhull::HullError>(())
/// ```
pub trait StrategyHooks<const D: usize>: sealed::Sealed {
    // Growing the hull.
    /// Adds the point farthest beyond facet `id` to the hull: the farthest of its outside set,
    /// or, when other facets share its hyperplane exactly (a coplanar region, as on boxes and
    /// lattices), the farthest of all their outside sets (every one of them is beyond the same
    /// plane, and the expansion removes them all).
    ///
    /// Returns `false` (and changes nothing) when the facet is not live or its outside set is
    /// empty. Afterwards [`StrategyHooks::last_removed`] and [`StrategyHooks::last_created`] list what changed.
    fn expand(&mut self, id: FacetId) -> bool;

    /// Adds the input point farthest beyond facet `id` among *all* the input points to the hull:
    /// the support point along the facet's normal, a vertex of the full hull, wherever the
    /// partition filed it (another facet's outside set, under [`Partition::FirstFound`] or
    /// [`Partition::NearestFirst`]). The scan costs `D` multiply-adds per input point, so it
    /// runs only for inputs of at most [`SUPPORT_SCAN_POINTS`](crate::hull::SUPPORT_SCAN_POINTS)
    /// `· D` points; above that, and when the scan's winner is not exactly beyond, this is
    /// [`expand`](Self::expand).
    ///
    /// Returns `false` (and changes nothing) when the facet is not live or its outside set is
    /// empty (call [`claim_beyond`](Self::claim_beyond) first to fill it).
    ///
    /// ```
    /// use pqhull::hull::{Partition, StrategyHooks};
    /// use pqhull::{Hull, Step, Strategy};
    ///
    /// /// The full hull, each point filed under the first facet found beyond it, each expansion
    /// /// by the support point of the first facet with outside points.
    /// struct SupportPoints;
    /// impl<const D: usize> Strategy<D> for SupportPoints {
    ///     type Output = ();
    ///     fn start(&mut self, _: &Hull<D>) {}
    ///     fn step(&mut self, hull: &mut Hull<D>) -> Step {
    ///         hull.set_partition(Partition::FirstFound);
    ///         let next = hull.facets().find(|(_, f)| f.outside_len() > 0);
    ///         match next.map(|(id, _)| id) {
    ///             Some(id) => {
    ///                 assert!(hull.expand_to_support(id));
    ///                 Step::Continue
    ///             }
    ///             None => Step::Stop,
    ///         }
    ///     }
    ///     fn finish(self, _: &Hull<D>) {}
    /// }
    /// let points = pqhull::rbox::generate::<4>(&pqhull::rbox::Family::UniformCube, 300, 5);
    /// let (hull, ()) = Hull::try_with_strategy(&points, SupportPoints)?;
    /// assert!(hull.check().is_ok());
    /// let mut vertices = hull.vertex_indices();
    /// let mut full = Hull::try_new(&points)?.vertex_indices();
    /// vertices.sort_unstable();
    /// full.sort_unstable();
    /// assert_eq!(vertices, full);
    /// # Ok::<(), pqhull::HullError>(())
    /// ```
    fn expand_to_support(&mut self, id: FacetId) -> bool;

    /// Adds input point `point`, which must be in facet `id`'s outside set, to the hull.
    ///
    /// Returns `false` (and changes nothing) when `id` is not live or `point` is not in its outside
    /// set.
    fn expand_with(&mut self, id: FacetId, point: usize) -> bool;

    /// Adds a point that was not part of the input — from an implicit point set, such as a
    /// Minkowski sum answered through its support function — to the hull, if it lies strictly
    /// beyond facet `id` (exact test). Returns its new input index, or `None` (nothing changed)
    /// when it is not beyond `id`, `id` is not live, or the point falls outside the coordinate
    /// range the hull's exact filter was scaled for (every coordinate must be within the input's
    /// largest magnitude, rounded up to a power of two: seed the input with the set's extreme
    /// points along every axis).
    fn insert_beyond(&mut self, id: FacetId, point: [f64; D]) -> Option<usize>;

    /// Moves into facet `id`'s outside set points of other outside sets that lie strictly beyond
    /// it: those in the nearest rings of facets around it that hold any (up to
    /// 1024 facets), else every one. Returns whether its outside set is now non-empty.
    ///
    /// Each point sits in one outside set only, so an empty set does not yet prove that nothing
    /// lies beyond a facet; after this call returns `false` it does. Strategies that stop on "no
    /// point beyond this facet" must call it. Its cost is one predicate per point of the rings'
    /// sets, and only when they hold nothing beyond, one per remaining outside point: scanning
    /// every set each time made the partial hull of cospherical points slower than the full one
    /// (the points beyond a new facet are nearly always a ring or two away).
    fn claim_beyond(&mut self, id: FacetId) -> bool;

    /// How the following expansions hand the outside points of the removed facets to the new
    /// ones (see [`Partition`]). Every choice keeps the engine's invariants; the run starts with
    /// [`Partition::Farthest`] or [`Partition::FirstFound`] as
    /// [`Strategy::partitions_to_farthest`](super::Strategy::partitions_to_farthest) says, and a
    /// strategy may change its mind once it knows more (the built-in `ClosestToOrigin` switches
    /// to [`Partition::NearestFirst`] once its query is inside the partial hull).
    /// On input the engine certifies as an exact grid the partition is always the farthest
    /// (a side test there is a dot product, and the farthest keeps grid points off the hull).
    ///
    /// ```
    /// use pqhull::hull::{Partition, StrategyHooks};
    /// use pqhull::{Hull, Step, Strategy};
    ///
    /// /// The full hull, expanding the first facet with outside points, each point handed to
    /// /// the facet it lies farthest beyond (Qhull's `Qf`).
    /// struct FirstFacetFarthestPoints;
    /// impl<const D: usize> Strategy<D> for FirstFacetFarthestPoints {
    ///     type Output = ();
    ///     fn start(&mut self, _: &Hull<D>) {}
    ///     fn step(&mut self, hull: &mut Hull<D>) -> Step {
    ///         hull.set_partition(Partition::Farthest);
    ///         let next = hull.facets().find(|(_, f)| f.outside_len() > 0);
    ///         match next.map(|(id, _)| id) {
    ///             Some(id) => {
    ///                 hull.expand(id);
    ///                 Step::Continue
    ///             }
    ///             None => Step::Stop,
    ///         }
    ///     }
    ///     fn finish(self, _: &Hull<D>) {}
    /// }
    /// let points = pqhull::rbox::generate::<3>(&pqhull::rbox::Family::UniformCube, 500, 3);
    /// let (hull, ()) = Hull::try_with_strategy(&points, FirstFacetFarthestPoints)?;
    /// assert!(hull.check().is_ok());
    /// let mut vertices = hull.vertex_indices();
    /// let mut full = Hull::try_new(&points)?.vertex_indices();
    /// vertices.sort_unstable();
    /// full.sort_unstable();
    /// assert_eq!(vertices, full);
    /// # Ok::<(), pqhull::HullError>(())
    /// ```
    fn set_partition(&mut self, partition: Partition<D>);

    /// Facets removed by the last expansion (their slots are tombstoned).
    fn last_removed(&self) -> &[FacetId];

    /// Facets created by the last expansion.
    fn last_created(&self) -> &[FacetId];

    // Reading the engine's state and the facets' exact planes.
    /// Whether `id` still names the facet created with `serial`.
    fn is_current(&self, id: FacetId, serial: u64) -> bool;

    /// Makes facet `id`'s normal and offset precise (exact cofactor direction) if they are not.
    fn refine_normal(&mut self, id: FacetId);

    /// The unit normal of facet `id` from its exact cofactors.
    fn exact_normal(&self, id: FacetId) -> [f64; D];

    /// A bound on the input's coordinates (caller's units): every coordinate is at most this in
    /// magnitude, and the largest is more than half of it (unless the input's magnitudes were too
    /// extreme to be scaled exactly).
    fn coordinate_bound(&self) -> f64;

    /// Signed distance of `x` (caller's units) beyond facet `id`'s plane from the exact
    /// determinant and the exact cofactors: a few ulps however close `x` is to the plane (see
    /// `FacetPlane::exact_distance`), or `None` when `x` cannot be scaled exactly (as in
    /// [`side_of`](Hull::side_of)).
    fn exact_signed_distance(&self, id: FacetId, x: &[f64; D]) -> Option<f64>;

    /// An upper bound on the exact signed distance of `x` beyond facet `id`'s plane: the
    /// floating-point distance when the facet's normal is precise, else a certified bound from the
    /// plane's error analysis (`+∞` when the floating-point cofactors say nothing).
    fn distance_upper_bound(&self, id: FacetId, x: &[f64; D]) -> f64;

    // The trace (recorded only by `Hull::try_with_strategy_traced`).
    /// Whether this run is being traced. Strategies may test it before computing something they
    /// only need for the trace.
    fn is_tracing(&self) -> bool;

    /// Records that the strategy picked facet `id` (an [`Event::Chose`](super::Event::Chose)),
    /// for `reason` (its words, its code and the number the choice was ordered by: see
    /// [`TraceReason`]). Does nothing when not tracing or when `id` is not live.
    ///
    /// ```
    /// use pqhull::hull::{StrategyHooks, TraceReason};
    /// use pqhull::{Hull, Step, Strategy};
    ///
    /// /// Why `Busiest` does what it does.
    /// enum Why {
    ///     Busiest { points: usize },
    ///     Done { facets: usize },
    /// }
    /// impl TraceReason for Why {
    ///     fn code(&self) -> &'static str {
    ///         match self {
    ///             Why::Busiest { .. } => "busiest",
    ///             Why::Done { .. } => "done",
    ///         }
    ///     }
    ///     fn describe(&self) -> String {
    ///         match self {
    ///             Why::Busiest { .. } => "busiest facet".to_string(),
    ///             Why::Done { facets } => format!("{facets} facets, none with outside points"),
    ///         }
    ///     }
    ///     fn key(&self) -> Option<(&'static str, f64)> {
    ///         match self {
    ///             Why::Busiest { points } => Some(("outside points", *points as f64)),
    ///             Why::Done { .. } => None,
    ///         }
    ///     }
    /// }
    ///
    /// /// Expands the facet with the most outside points, and says so.
    /// struct Busiest;
    /// impl<const D: usize> Strategy<D> for Busiest {
    ///     type Output = ();
    ///     fn start(&mut self, _: &Hull<D>) {}
    ///     fn step(&mut self, hull: &mut Hull<D>) -> Step {
    ///         let best = hull.facets().max_by_key(|(_, f)| f.outside_len());
    ///         match best.map(|(id, f)| (id, f.outside_len())) {
    ///             Some((id, points)) if points > 0 => {
    ///                 hull.trace_choice(id, Why::Busiest { points });
    ///                 hull.expand(id);
    ///                 Step::Continue
    ///             }
    ///             _ => {
    ///                 let facets = hull.facet_count();
    ///                 hull.trace_stop(None, Why::Done { facets });
    ///                 Step::Stop
    ///             }
    ///         }
    ///     }
    ///     fn finish(self, _: &Hull<D>) {}
    /// }
    /// let points = pqhull::rbox::generate::<3>(&pqhull::rbox::Family::UniformCube, 100, 1);
    /// let (_, (), trace) = Hull::try_with_strategy_traced(&points, Busiest)?;
    /// assert_eq!(trace.context.strategy, "Busiest");
    /// assert!(trace.stop_reason().unwrap().ends_with("none with outside points"));
    /// # Ok::<(), pqhull::HullError>(())
    /// ```
    fn trace_choice(&mut self, id: FacetId, reason: impl TraceReason);

    /// Records a note (an [`Event::Note`](super::Event::Note)): a change of phase, say,
    /// optionally marking a point (caller's units).
    fn trace_note(&mut self, point: Option<[f64; D]>, reason: impl TraceReason);

    /// Records why the strategy stops (an [`Event::Stop`](super::Event::Stop)) and the deciding
    /// facet, if any.
    fn trace_stop(&mut self, facet: Option<FacetId>, reason: impl TraceReason);
}

impl<const D: usize> StrategyHooks<D> for Hull<D> {
    // Growing the hull.
    fn expand(&mut self, id: FacetId) -> bool {
        Hull::expand(self, id)
    }

    fn expand_to_support(&mut self, id: FacetId) -> bool {
        Hull::expand_to_support(self, id)
    }

    fn expand_with(&mut self, id: FacetId, point: usize) -> bool {
        Hull::expand_with(self, id, point)
    }

    fn insert_beyond(&mut self, id: FacetId, point: [f64; D]) -> Option<usize> {
        Hull::insert_beyond(self, id, point)
    }

    fn claim_beyond(&mut self, id: FacetId) -> bool {
        Hull::claim_beyond(self, id)
    }

    fn set_partition(&mut self, partition: Partition<D>) {
        self.partition = partition;
    }

    fn last_removed(&self) -> &[FacetId] {
        Hull::last_removed(self)
    }

    fn last_created(&self) -> &[FacetId] {
        Hull::last_created(self)
    }

    // Reading the engine's state and the facets' exact planes.
    fn is_current(&self, id: FacetId, serial: u64) -> bool {
        Hull::is_current(self, id, serial)
    }

    fn refine_normal(&mut self, id: FacetId) {
        Hull::refine_normal(self, id)
    }

    fn exact_normal(&self, id: FacetId) -> [f64; D] {
        Hull::exact_normal(self, id)
    }

    fn coordinate_bound(&self) -> f64 {
        Hull::coordinate_bound(self)
    }

    fn exact_signed_distance(&self, id: FacetId, x: &[f64; D]) -> Option<f64> {
        Hull::exact_signed_distance(self, id, x)
    }

    fn distance_upper_bound(&self, id: FacetId, x: &[f64; D]) -> f64 {
        Hull::distance_upper_bound(self, id, x)
    }

    // The trace (recorded only by `Hull::try_with_strategy_traced`).
    fn is_tracing(&self) -> bool {
        Hull::is_tracing(self)
    }

    fn trace_choice(&mut self, id: FacetId, reason: impl TraceReason) {
        Hull::trace_choice(self, id, reason)
    }

    fn trace_note(&mut self, point: Option<[f64; D]>, reason: impl TraceReason) {
        Hull::trace_note(self, point, reason)
    }

    fn trace_stop(&mut self, facet: Option<FacetId>, reason: impl TraceReason) {
        Hull::trace_stop(self, facet, reason)
    }
}
