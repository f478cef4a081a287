//! A recorded run (the model `viz` renders): the events a strategy and the engine emit, and
//! their replay.

use std::collections::BTreeMap;

/// A facet as it was when recorded: its serial (unique over the run), its oriented vertices
/// (input indices) and its outside set.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FacetSnapshot<const D: usize> {
    /// [`Facet::serial`](crate::Facet::serial): events name facets by serial, because facet
    /// ids are slots that later expansions reuse.
    pub serial: u64,
    /// Oriented vertices, as [`Facet::vertices`](crate::Facet::vertices).
    pub vertices: [usize; D],
    /// Input indices of the points in the facet's outside set (each strictly beyond it), in the
    /// engine's order.
    pub outside: Vec<usize>,
}

/// The number a strategy ordered its choice by, with what it measures.
#[derive(Clone, Debug, PartialEq)]
pub struct Key {
    /// What the number is, e.g. `"inflation factor"`.
    pub name: String,
    /// Its value (floating point, caller's units).
    pub value: f64,
}

/// One step of a run.
#[derive(Clone, Debug, PartialEq)]
pub enum Event<const D: usize> {
    /// The initial simplex: D + 1 facets and the first outside sets. Always the first event;
    /// a full build whose first phase left vertices that are not extreme starts again on the
    /// extreme ones with a second (after a [`Event::Note`] coded `second-phase`), which
    /// replaces every facet.
    Initial {
        /// The simplex's facets.
        facets: Vec<FacetSnapshot<D>>,
    },
    /// The strategy picked a facet to work on, and says why.
    Chose {
        /// The facet's serial.
        facet: u64,
        /// Its vertices (so that the event reads on its own).
        vertices: [usize; D],
        /// Why this facet, in words, e.g. `"smallest inflation factor"`.
        reason: String,
        /// The kind of reason, stable for programs ([`TraceReason::code`]).
        code: &'static str,
        /// The number the choice was ordered by, if any.
        key: Option<Key>,
    },
    /// [`StrategyHooks::claim_beyond`](crate::hull::StrategyHooks::claim_beyond) moved points from other outside sets
    /// into this facet's (recorded only when it moved any).
    Claimed {
        /// The claiming facet's serial.
        facet: u64,
        /// The points moved, in the order they were claimed.
        points: Vec<usize>,
    },
    /// A point that was not in the input (an implicit source, [`insert_beyond`](
    /// super::StrategyHooks::insert_beyond)) joined the points; an [`Event::Expanded`] adding it follows.
    Inserted {
        /// The facet it lies beyond.
        facet: u64,
        /// Its new input index.
        point: usize,
        /// Its coordinates (caller's units).
        coordinates: [f64; D],
    },
    /// A point was added to the hull: the facets it saw were removed and a cone of new facets
    /// created; the removed facets' outside points went to the new ones.
    Expanded {
        /// The facet whose outside set held the point.
        facet: u64,
        /// The point added (input index).
        point: usize,
        /// Serials of the removed facets (all facets weakly visible from the point).
        removed: Vec<u64>,
        /// The new facets, with their outside sets.
        created: Vec<FacetSnapshot<D>>,
    },
    /// Something the strategy wants to say that is not a choice (a change of phase), with a
    /// point to mark if it has one (e.g. the nearest point found so far).
    Note {
        /// The message.
        text: String,
        /// The kind of note, stable for programs ([`TraceReason::code`]).
        code: &'static str,
        /// A point to mark (caller's units).
        point: Option<[f64; D]>,
    },
    /// The strategy stopped. Always the last event.
    Stop {
        /// Why it could stop: the certificate it holds.
        reason: String,
        /// The kind of stop, stable for programs ([`TraceReason::code`]).
        code: &'static str,
        /// The deciding facet's serial, when there is one.
        facet: Option<u64>,
    },
}

/// What a strategy wants shown beside the hull: its name, its query point, its disturbances.
/// Returned by [`Strategy::trace_context`](crate::Strategy::trace_context).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TraceContext<const D: usize> {
    /// The strategy's name (the engine uses the type's name when this is empty).
    pub strategy: String,
    /// The query point (`ClosestToOrigin`).
    pub query: Option<[f64; D]>,
    /// Disturbances `d`, each resisted along the ray `−d` (`OwsInflation`).
    pub disturbances: Vec<[f64; D]>,
}

/// The record of one run of a strategy: the points, the strategy's context and every event, from
/// the initial simplex to the stop.
///
/// Recorded by [`Hull::try_with_strategy_traced`](crate::Hull::try_with_strategy_traced);
/// [`Trace::replay`] rebuilds the hull after any event; the `viz` module serialises and draws it.
///
/// ```
/// use pqhull::{ClosestToOrigin, Hull};
/// use pqhull::hull::Event;
///
/// let points = pqhull::rbox::generate::<2>(&pqhull::rbox::Family::UniformCube, 40, 7);
/// let (hull, result, trace) = Hull::try_with_strategy_traced(&points, ClosestToOrigin::new())?;
/// assert!(matches!(trace.events[0], Event::Initial { .. }));
/// let Some(Event::Stop { reason, .. }) = trace.events.last() else { panic!("no stop") };
/// assert!(result.is_inside() && reason.contains("(query inside)"));
/// // Replaying every event rebuilds the partial hull exactly.
/// let replayed: Vec<_> = trace.final_facets().into_iter().map(|f| f.vertices).collect();
/// let mut built: Vec<_> = hull.facets().map(|(_, f)| f.vertices()).collect();
/// built.sort();
/// let mut replayed = replayed;
/// replayed.sort();
/// assert_eq!(built, replayed);
/// # Ok::<(), pqhull::HullError>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Trace<const D: usize> {
    /// Every point, caller's units: the input, then any inserted points (in insertion order).
    pub points: Vec<[f64; D]>,
    /// The strategy's name, query point and disturbances.
    pub context: TraceContext<D>,
    /// The events, in order.
    pub events: Vec<Event<D>>,
}

impl<const D: usize> Trace<D> {
    /// A replay positioned before the first event.
    pub fn replay(&self) -> Replay<'_, D> {
        Replay {
            trace: self,
            next: 0,
            facets: BTreeMap::new(),
        }
    }

    /// The live facets after the last event (sorted by serial).
    pub fn final_facets(&self) -> Vec<FacetSnapshot<D>> {
        let mut replay = self.replay();
        while replay.step().is_some() {}
        replay.facets().cloned().collect()
    }

    /// The stop event's reason, if the trace has one.
    pub fn stop_reason(&self) -> Option<&str> {
        self.events.iter().rev().find_map(|e| match e {
            Event::Stop { reason, .. } => Some(reason.as_str()),
            _ => None,
        })
    }
}

/// Replays a [`Trace`] event by event, keeping the live facets and their outside sets.
///
/// The state after event `k` is what the engine held at that moment: after an
/// [`Event::Expanded`] the removed facets are gone and the created ones live; after an
/// [`Event::Claimed`] the claimed points have moved.
///
/// ```
/// use pqhull::{FarthestPoint, Hull};
/// let points = [[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [1.0, 1.0], [5.0, 5.0]];
/// let (_, (), trace) = Hull::try_with_strategy_traced(&points, FarthestPoint::new())?;
/// let mut replay = trace.replay();
/// replay.step(); // the initial triangle, with one hull vertex still outside it
/// assert_eq!(replay.facets().count(), 3);
/// assert_eq!(replay.outside_points().len(), 1);
/// while replay.step().is_some() {}
/// assert_eq!(replay.vertices(), vec![0, 1, 2, 4]);
/// assert!(replay.outside_points().is_empty());
/// # Ok::<(), pqhull::HullError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Replay<'a, const D: usize> {
    trace: &'a Trace<D>,
    next: usize,
    facets: BTreeMap<u64, FacetSnapshot<D>>,
}

impl<'a, const D: usize> Replay<'a, D> {
    /// Applies the next event and returns it; `None` after the last.
    pub fn step(&mut self) -> Option<&'a Event<D>> {
        let event = self.trace.events.get(self.next)?;
        self.next += 1;
        match event {
            Event::Initial { facets } => {
                self.facets = facets.iter().map(|f| (f.serial, f.clone())).collect();
            }
            Event::Claimed { facet, points } => {
                // Claimed points came from other facets' outside sets.
                for f in self.facets.values_mut() {
                    if f.serial != *facet {
                        f.outside.retain(|p| !points.contains(p));
                    }
                }
                if let Some(f) = self.facets.get_mut(facet) {
                    f.outside.extend(points.iter().copied());
                }
            }
            Event::Expanded {
                removed, created, ..
            } => {
                for serial in removed {
                    self.facets.remove(serial);
                }
                for f in created {
                    self.facets.insert(f.serial, f.clone());
                }
            }
            Event::Chose { .. }
            | Event::Inserted { .. }
            | Event::Note { .. }
            | Event::Stop { .. } => {}
        }
        Some(event)
    }

    /// How many events have been applied.
    pub fn position(&self) -> usize {
        self.next
    }

    /// The live facets, by serial.
    pub fn facets(&self) -> impl Iterator<Item = &FacetSnapshot<D>> + '_ {
        self.facets.values()
    }

    /// The live facet with this serial.
    pub fn facet(&self, serial: u64) -> Option<&FacetSnapshot<D>> {
        self.facets.get(&serial)
    }

    /// Sorted vertices of the live facets.
    pub fn vertices(&self) -> Vec<usize> {
        let mut v: Vec<usize> = self.facets.values().flat_map(|f| f.vertices).collect();
        v.sort_unstable();
        v.dedup();
        v
    }

    /// Sorted points in some outside set.
    pub fn outside_points(&self) -> Vec<usize> {
        let mut v: Vec<usize> = self
            .facets
            .values()
            .flat_map(|f| f.outside.iter().copied())
            .collect();
        v.sort_unstable();
        v
    }
}

/// Why a strategy chose a facet, noted something or stopped: a typed value (each built-in
/// strategy has its own enum of reasons), turned into the trace's words only when the run is
/// traced, so an untraced run builds no string. Taken by
/// [`StrategyHooks::trace_choice`](super::StrategyHooks::trace_choice),
/// [`trace_note`](super::StrategyHooks::trace_note) and
/// [`trace_stop`](super::StrategyHooks::trace_stop).
///
/// A `&'static str` is a reason too (code `"text"`), for a quick strategy of one's own.
///
/// ```
/// use pqhull::hull::TraceReason;
///
/// /// Why a best-first strategy picked a facet.
/// enum Why {
///     Highest { height: f64 },
/// }
/// impl TraceReason for Why {
///     fn code(&self) -> &'static str {
///         "highest"
///     }
///     fn describe(&self) -> String {
///         let Why::Highest { height } = self;
///         format!("highest outside point ({height})")
///     }
///     fn key(&self) -> Option<(&'static str, f64)> {
///         let Why::Highest { height } = self;
///         Some(("height", *height))
///     }
/// }
/// assert_eq!(Why::Highest { height: 2.0 }.describe(), "highest outside point (2)");
/// assert_eq!("because".code(), "text");
/// ```
pub trait TraceReason {
    /// The kind of reason: a short identifier, stable across versions, for programs that read
    /// a trace (the words may change).
    fn code(&self) -> &'static str;
    /// The reason in words, as the trace shows it.
    fn describe(&self) -> String;
    /// For a choice, the number it was ordered by and what that number measures.
    fn key(&self) -> Option<(&'static str, f64)> {
        None
    }
}

impl TraceReason for &'static str {
    fn code(&self) -> &'static str {
        "text"
    }

    fn describe(&self) -> String {
        (*self).to_string()
    }
}
