//! Visual debugging: recorded traces of a strategy's run and their SVG / HTML renderings.
//!
//! * [`Trace`](crate::hull::Trace) — what [`Hull::try_with_strategy_traced`](crate::Hull::try_with_strategy_traced)
//!   records: the initial simplex, each facet a strategy chose and why, each point added with the
//!   facets removed and created, and the stop with the certificate that allowed it. Recording is
//!   off unless asked for, and then costs nothing but one branch per hook (see
//!   [`StrategyHooks::trace_choice`](crate::hull::StrategyHooks::trace_choice)). [`Trace::replay`](crate::hull::Trace::replay) rebuilds the hull
//!   after any event; [`trace_json`] serialises it.
//! * [`html::trace_page`] — a self-contained HTML page (inline script, no network) drawing one
//!   or two traces step by step on a canvas, with a step slider and, in 3-D, mouse rotation.
//! * [`svg::trace_svgs`] — one static SVG picture per step of a 2-D trace.
//! * [`scene`] — the 3-D viewer itself, for any scene of coloured triangles, points, segments
//!   and labels ([`scene::scene_page`]).
//! * [`plan_scene`] — a plan's best grasps by Q1 and by Q_OWS side by side on the object
//!   ([`plan_scene::plan_page`]).
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
mod json;
pub mod plan_scene;
pub mod scene;
pub mod svg;

pub use json::trace_json;

use std::fmt;

/// Why a trace cannot be drawn.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
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
