//! Traces as self-contained HTML pages: a step slider per run, mouse rotation in 3-D, runs side
//! by side.
//!
//! The page embeds each [`Trace`]'s JSON ([`trace_json`](super::trace_json)) and the viewer of
//! [`scene`](super::scene), which replays the events in the browser: at step `k` it shows the
//! hull after event `k` — the chosen facet in orange, the facets an expansion created in green
//! (the removed ones dashed red), the deciding facet of the stop in red, points in some outside
//! set in red (those of the chosen facet in orange), hull vertices in dark blue, other points in
//! grey, the point just added in green, the query point `q` (and the nearest point `x` found so
//! far) in purple, and for `OwsInflation` the disturbance rays `−r·d` at the latest inflation
//! factor `r` in teal. The caption says what happened and why (the strategy's reason and key).
//! The page's test hooks are those of [`scene`](super::scene).

use super::VizError;
use super::scene::{escape, page};
use crate::hull::{Event, Trace};
use serde_json::json;

/// Legend entries: (colour as CSS, meaning). Keep in step with `COLORS` in viewer.js.
const LEGEND: [(&str, &str); 10] = [
    ("rgb(165,195,230)", "facet"),
    ("rgb(255,140,0)", "chosen facet / its outside points"),
    ("rgb(70,185,95)", "created facets"),
    ("rgb(215,45,60)", "deciding facet at the stop"),
    ("rgb(220,50,50)", "points in outside sets"),
    ("rgb(30,60,120)", "hull vertices"),
    ("rgb(165,165,165)", "points inside"),
    ("rgb(0,150,60)", "point just added"),
    ("rgb(130,0,170)", "query point q"),
    ("rgb(0,140,140)", "disturbance rays \u{2212}r\u{b7}d"),
];

/// A self-contained HTML page titled `title` showing each trace in its own panel, side by side
/// (two traces of the same input compare two strategies; one viewpoint for all).
///
/// ```
/// use pqhull::{ClosestToOrigin, FarthestPoint, Hull};
/// use pqhull::viz::html::trace_page;
/// let points = pqhull::rbox::generate::<2>(&pqhull::rbox::Family::SphereSurface, 30, 1);
/// let (_, _, full) = Hull::try_with_strategy_traced(&points, FarthestPoint::new())?;
/// let (_, _, partial) = Hull::try_with_strategy_traced(&points, ClosestToOrigin::new())?;
/// let page = trace_page("full vs partial", &[&full, &partial])?;
/// assert!(page.contains("FarthestPoint") && page.contains("ClosestToOrigin"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`VizError::Dimension`] unless D is 2 or 3; [`VizError::Empty`] for no trace or a trace
/// without events.
pub fn trace_page<const D: usize>(title: &str, traces: &[&Trace<D>]) -> Result<String, VizError> {
    if D != 2 && D != 3 {
        return Err(VizError::Dimension {
            dimension: D,
            supported: "2-D and 3-D",
        });
    }
    if traces.is_empty() || traces.iter().any(|t| t.events.is_empty()) {
        return Err(VizError::Empty);
    }
    let panels: Vec<_> = traces
        .iter()
        .map(|t| json!({"title": panel_title(t), "trace": super::trace_json(t)}))
        .collect();
    let mut legend = String::new();
    for (color, meaning) in LEGEND {
        legend.push_str(&format!(
            "<span class=\"sw\" style=\"background:{color}\"></span>{}",
            escape(meaning)
        ));
    }
    Ok(page(title, &json!({ "panels": panels }), &legend))
}

/// "Strategy — n points, e expansions, f facets created".
pub(in crate::viz) fn panel_title<const D: usize>(trace: &Trace<D>) -> String {
    let expansions = trace
        .events
        .iter()
        .filter(|e| matches!(e, Event::Expanded { .. }))
        .count();
    let created: usize = trace
        .events
        .iter()
        .map(|e| match e {
            Event::Initial { facets } => facets.len(),
            Event::Expanded { created, .. } => created.len(),
            _ => 0,
        })
        .sum();
    format!(
        "{} \u{2014} {} points, {expansions} expansions, {created} facets created",
        trace.context.strategy,
        trace.points.len()
    )
}
