//! `Complete`: the full hull, then another strategy's answer read off it.

use crate::hull::{FarthestPoint, Hull, Step, Strategy, TraceContext};

/// Builds the full hull ([`FarthestPoint`]), then runs `S` on it and returns `S`'s output.
///
/// On a complete hull a partial strategy has nothing left to add (no facet has outside points),
/// so it certifies at once, through the same exact tests it uses on a partial hull: the full
/// method of a metric is then the partial method's answer on the full hull, exact by the same
/// argument, rather than a second computation of the same quantity. (`S` may still add the
/// implicit points of a [`PointSource`](super::PointSource), which no full hull of the explicit
/// points contains.)
///
/// ```
/// use pqhull::strategy::Complete;
/// use pqhull::{ClosestToOrigin, Hull};
/// let square = [[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0], [2.0, 2.0]];
/// let (hull, full) = Hull::try_with_strategy(&square, Complete::new(ClosestToOrigin::new()))?;
/// let (_, partial) = Hull::try_with_strategy(&square, ClosestToOrigin::new())?;
/// // The origin is outside: its nearest point is the corner (1, 1), at distance √2.
/// assert_eq!(full.signed_distance, -(2f64.sqrt()));
/// assert_eq!(full.signed_distance, partial.signed_distance);
/// assert_eq!(hull.facet_count(), 4); // the whole square
/// # Ok::<(), pqhull::HullError>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct Complete<S> {
    full: FarthestPoint,
    inner: S,
    /// Whether the full hull is done and `inner` started.
    inner_started: bool,
}

impl<S> Complete<S> {
    /// The full hull, then `inner`.
    pub fn new(inner: S) -> Self {
        Complete {
            full: FarthestPoint::new(),
            inner,
            inner_started: false,
        }
    }
}

impl<const D: usize, S: Strategy<D>> Strategy<D> for Complete<S> {
    type Output = S::Output;

    fn start(&mut self, hull: &Hull<D>) {
        Strategy::<D>::start(&mut self.full, hull);
        self.inner_started = false;
    }

    fn step(&mut self, hull: &mut Hull<D>) -> Step {
        if !self.inner_started {
            if Strategy::<D>::step(&mut self.full, hull) == Step::Continue {
                return Step::Continue;
            }
            self.inner_started = true;
            self.inner.start(hull);
        }
        self.inner.step(hull)
    }

    fn finish(self, hull: &Hull<D>) -> Self::Output {
        self.inner.finish(hull)
    }

    fn refines_all_normals(&self) -> bool {
        self.inner.refines_all_normals()
    }

    // `partitions_to_farthest`: the default, as for `FarthestPoint` (every point is added).

    fn trace_context(&self) -> TraceContext<D> {
        let inner = self.inner.trace_context();
        TraceContext {
            strategy: format!("Complete({})", inner.strategy),
            ..inner
        }
    }
}
