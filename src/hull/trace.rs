//! Recording a run ([`Trace`]): the engine's hooks and the ones strategies call.
//!
//! The hull holds `Option<Box<Trace>>`, `None` unless the run was started with
//! [`Hull::try_with_strategy_traced`]. Every hook starts with `if let Some(..)`/`is_some()` on
//! that field, the recording itself is out of line (`#[cold]`), and strategies pass their
//! explanations as typed values put into words only when tracing ([`TraceReason`]), so an
//! untraced run pays one predictable branch per hook and builds no string. The box keeps
//! the field one pointer wide, so `Hull` barely grows.

use super::{Event, FacetId, FacetSnapshot, Hull, HullError, Key, Strategy, Trace, TraceReason};

impl<const D: usize> Hull<D> {
    /// As [`Hull::try_with_strategy`], and also returns the [`Trace`] of the run: the initial
    /// simplex, every choice the strategy explained, every point added (with the facets removed
    /// and created), and the stop with its reason.
    ///
    /// The hull and the output are the same as without tracing (the same facets, the same
    /// statistics but for `elapsed`, which includes the recording).
    ///
    /// ```
    /// use pqhull::{Hull, OwsInflation};
    /// use pqhull::hull::Event;
    /// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.3, 0.2]];
    /// let disturbances = [[1.0, 0.0], [1.0, 1.0]];
    /// let (_, result, trace) =
    ///     Hull::try_with_strategy_traced(&square, OwsInflation::with_rays(&disturbances))?;
    /// assert!((result.value.unwrap() - 1.0).abs() < 1e-12);
    /// assert_eq!(trace.context.strategy, "OwsInflation");
    /// assert_eq!(trace.context.disturbances, disturbances);
    /// let expansions = trace.events.iter().filter(|e| matches!(e, Event::Expanded { .. })).count();
    /// assert_eq!(expansions, result.stats.expansions);
    /// assert!(trace.stop_reason().unwrap().contains("smallest inflation factor"));
    /// # Ok::<(), pqhull::HullError>(())
    /// ```
    ///
    /// # Errors
    /// As [`Hull::try_new`].
    pub fn try_with_strategy_traced<S: Strategy<D>>(
        points: &[[f64; D]],
        strategy: S,
    ) -> Result<(Self, S::Output, Trace<D>), HullError> {
        let mut hull = Self::try_initial(points, strategy.partitions_to_farthest())?;
        let mut context = strategy.trace_context();
        if context.strategy.is_empty() {
            let name = std::any::type_name::<S>();
            // "crate::module::Name<Params>" → "Name<Params>"
            let base = name.split('<').next().unwrap_or(name);
            let start = base.rfind("::").map_or(0, |i| i + 2);
            context.strategy = name[start..].to_string();
        }
        let facets = hull.facets().map(|(id, _)| hull.snapshot(id)).collect();
        hull.trace = Some(Box::new(Trace {
            points: Vec::new(),
            context,
            events: vec![Event::Initial { facets }],
        }));
        let (mut hull, output) = hull.run(strategy);
        let mut trace = *hull
            .trace
            .take()
            .expect("the trace stays in place during the run");
        if !matches!(trace.events.last(), Some(Event::Stop { .. })) {
            trace.events.push(Event::Stop {
                reason: "the strategy stopped (it gave no reason)".to_string(),
                code: "no-reason",
                facet: None,
            });
        }
        trace.points = (0..hull.point_count()).map(|i| hull.point(i)).collect();
        Ok((hull, output, trace))
    }

    /// The engine's side of [`StrategyHooks::is_tracing`](crate::hull::StrategyHooks::is_tracing).
    pub(crate) fn is_tracing(&self) -> bool {
        self.trace.is_some()
    }

    /// The engine's side of [`StrategyHooks::trace_choice`](crate::hull::StrategyHooks::trace_choice).
    pub(crate) fn trace_choice(&mut self, id: FacetId, reason: impl TraceReason) {
        if self.trace.is_some() {
            self.record_choice(id, &reason);
        }
    }

    /// The engine's side of [`StrategyHooks::trace_note`](crate::hull::StrategyHooks::trace_note).
    pub(crate) fn trace_note(&mut self, point: Option<[f64; D]>, reason: impl TraceReason) {
        if let Some(trace) = &mut self.trace {
            trace.events.push(Event::Note {
                text: reason.describe(),
                code: reason.code(),
                point,
            });
        }
    }

    /// The engine's side of [`StrategyHooks::trace_stop`](crate::hull::StrategyHooks::trace_stop).
    pub(crate) fn trace_stop(&mut self, facet: Option<FacetId>, reason: impl TraceReason) {
        if self.trace.is_some() {
            let facet = facet.map(|id| self.facet(id).serial);
            if let Some(trace) = &mut self.trace {
                trace.events.push(Event::Stop {
                    reason: reason.describe(),
                    code: reason.code(),
                    facet,
                });
            }
        }
    }

    #[cold]
    fn record_choice(&mut self, id: FacetId, reason: &impl TraceReason) {
        let Some(facet) = self.facets.get(id.index()).filter(|f| f.alive) else {
            return;
        };
        let event = Event::Chose {
            facet: facet.serial,
            vertices: facet.vertices(),
            reason: reason.describe(),
            code: reason.code(),
            key: reason.key().map(|(name, value)| Key {
                name: name.to_string(),
                value,
            }),
        };
        if let Some(trace) = &mut self.trace {
            trace.events.push(event);
        }
    }

    /// When a full build's second phase starts (see `coplanar.rs`): a note saying why, then the
    /// new initial simplex, which a replay takes as a fresh start.
    #[cold]
    pub(super) fn record_second_phase(&mut self, removed: usize, extreme: usize) {
        let facets = self.facets().map(|(id, _)| self.snapshot(id)).collect();
        if let Some(trace) = &mut self.trace {
            trace.events.push(Event::Note {
                text: format!(
                    "first phase (coplanar facets kept) complete: {removed} of its vertices lie \
                     on a face and are not extreme; the hull again on the {extreme} extreme ones"
                ),
                code: "second-phase",
                point: None,
            });
            trace.events.push(Event::Initial { facets });
        }
    }

    fn snapshot(&self, id: FacetId) -> FacetSnapshot<D> {
        let facet = self.facet(id);
        FacetSnapshot {
            serial: facet.serial,
            vertices: facet.vertices(),
            outside: facet.outside_set().collect(),
        }
    }

    /// After an expansion of facet `id` by point `p`: the removed facets (tombstoned but not yet
    /// reused, so their serials are still readable) and the created ones with their new outside
    /// sets.
    #[cold]
    pub(super) fn record_expansion(&mut self, id: FacetId, p: u32) {
        let event = Event::Expanded {
            facet: self.facets[id.index()].serial,
            point: p as usize,
            removed: self
                .last_removed()
                .iter()
                .map(|&r| self.facets[r.index()].serial)
                .collect(),
            created: self
                .last_created()
                .iter()
                .map(|&c| self.snapshot(c))
                .collect(),
        };
        if let Some(trace) = &mut self.trace {
            trace.events.push(event);
        }
    }

    /// After [`StrategyHooks::claim_beyond`](crate::hull::StrategyHooks::claim_beyond) moved `points` into facet `id`'s outside set.
    #[cold]
    pub(super) fn record_claim(&mut self, id: FacetId, points: Vec<usize>) {
        let facet = self.facets[id.index()].serial;
        if let Some(trace) = &mut self.trace {
            trace.events.push(Event::Claimed { facet, points });
        }
    }

    /// Before [`StrategyHooks::insert_beyond`](crate::hull::StrategyHooks::insert_beyond) expands facet `id` with the new point `index`.
    #[cold]
    pub(super) fn record_insertion(&mut self, id: FacetId, index: usize, coordinates: [f64; D]) {
        let facet = self.facets[id.index()].serial;
        if let Some(trace) = &mut self.trace {
            trace.events.push(Event::Inserted {
                facet,
                point: index,
                coordinates,
            });
        }
    }
}
