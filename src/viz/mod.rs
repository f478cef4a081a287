//! Visual debugging: recorded traces of a strategy's run and their SVG / HTML renderings.
//!
//! * [`Trace`] — what [`Hull::try_with_strategy_traced`](crate::Hull::try_with_strategy_traced)
//!   records: the initial simplex, each facet a strategy chose and why, each point added with the
//!   facets removed and created, and the stop with the certificate that allowed it. Recording is
//!   off unless asked for, and then costs nothing but one branch per hook (see
//!   [`Hull::trace_choice`](crate::Hull::trace_choice)). [`Trace::replay`] rebuilds the hull
//!   after any event; [`Trace::to_json`] serialises it.
//! * [`html::trace_page`] — a self-contained HTML page (inline script, no network) drawing one
//!   or two traces step by step on a canvas, with a step slider and, in 3-D, mouse rotation.
//! * [`svg::trace_svgs`] — one static SVG picture per step of a 2-D trace.
//! * [`scene`] — the 3-D viewer itself, for any scene of coloured triangles, points, segments
//!   and labels ([`scene::scene_page`]).
//!
//! ```
//! use pqhull::{ClosestToOrigin, Hull};
//! use pqhull::viz::html;
//!
//! let points = pqhull::rbox::generate::<3>(&pqhull::rbox::Family::SphereSurface, 60, 3);
//! let (_, result, trace) =
//!     Hull::try_with_strategy_traced(&points, ClosestToOrigin::towards([0.1, 0.0, 0.2]))?;
//! assert!(result.is_inside());
//! let page = html::trace_page("sphere, 60 points", &[&trace])?;
//! assert!(page.starts_with("<!DOCTYPE html>") && !page.contains("https://"));
//! // std::fs::write("trace.html", page)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod html;
pub mod scene;
pub mod svg;
mod trace;

pub use trace::{Event, FacetSnapshot, Key, Replay, Trace, TraceContext};

use std::fmt;

/// Text for a trace, built only when a run is traced: a `&'static str` (free to pass), or a
/// closure returning a `String`, called only when tracing (so `format!` costs nothing on an
/// untraced run). Taken by [`Hull::trace_choice`](crate::Hull::trace_choice),
/// [`Hull::trace_note`](crate::Hull::trace_note) and [`Hull::trace_stop`](crate::Hull::trace_stop).
pub trait TraceText {
    /// The text.
    fn into_text(self) -> String;
}

impl TraceText for &'static str {
    fn into_text(self) -> String {
        self.to_string()
    }
}

impl<F: FnOnce() -> String> TraceText for F {
    fn into_text(self) -> String {
        self()
    }
}

/// Why a trace cannot be drawn.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VizError {
    /// The renderer draws only these dimensions.
    Dimension {
        /// The trace's dimension.
        dimension: usize,
        /// The dimensions the renderer draws.
        supported: &'static str,
    },
    /// There is nothing to draw (no trace, or one without events).
    Empty,
}

impl fmt::Display for VizError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            VizError::Dimension {
                dimension,
                supported,
            } => write!(
                f,
                "cannot draw a {dimension}-D trace: this renderer draws {supported} traces"
            ),
            VizError::Empty => f.write_str("nothing to draw: no trace, or a trace without events"),
        }
    }
}

impl std::error::Error for VizError {}
