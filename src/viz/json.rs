//! Traces as JSON: what the HTML page embeds and `pqh trace --json` writes.

use crate::hull::{Event, FacetSnapshot, Trace};
use serde_json::{Value, json};

/// The trace as one JSON object: `dimension`, `strategy`, `points`, `query` (or null),
/// `disturbances`, `events`. Each event is an object whose `kind` is `initial`, `chose`,
/// `claimed`, `inserted`, `expanded`, `note` or `stop`, with the variant's fields under the
/// same names (facet snapshots as `{serial, vertices, outside}`, keys as `{name, value}`;
/// non-finite numbers become null).
pub fn trace_json<const D: usize>(trace: &Trace<D>) -> Value {
    json!({
        "dimension": D,
        "strategy": trace.context.strategy,
        "points": trace.points.iter().map(|p| p.to_vec()).collect::<Vec<_>>(),
        "query": trace.context.query.map(|q| q.to_vec()),
        "disturbances": trace.context.disturbances.iter().map(|d| d.to_vec()).collect::<Vec<_>>(),
        "events": trace.events.iter().map(event_json).collect::<Vec<_>>(),
    })
}

fn snapshot_json<const D: usize>(f: &FacetSnapshot<D>) -> Value {
    json!({"serial": f.serial, "vertices": f.vertices.to_vec(), "outside": f.outside})
}

fn event_json<const D: usize>(event: &Event<D>) -> Value {
    match event {
        Event::Initial { facets } => json!({
            "kind": "initial",
            "facets": facets.iter().map(snapshot_json).collect::<Vec<_>>(),
        }),
        Event::Chose {
            facet,
            vertices,
            reason,
            code,
            key,
        } => json!({
            "kind": "chose",
            "facet": facet,
            "vertices": vertices.to_vec(),
            "reason": reason,
            "code": code,
            "key": key.as_ref().map(|k| json!({"name": k.name, "value": k.value})),
        }),
        Event::Claimed { facet, points } => {
            json!({"kind": "claimed", "facet": facet, "points": points})
        }
        Event::Inserted {
            facet,
            point,
            coordinates,
        } => json!({
            "kind": "inserted",
            "facet": facet,
            "point": point,
            "coordinates": coordinates.to_vec(),
        }),
        Event::Expanded {
            facet,
            point,
            removed,
            created,
        } => json!({
            "kind": "expanded",
            "facet": facet,
            "point": point,
            "removed": removed,
            "created": created.iter().map(snapshot_json).collect::<Vec<_>>(),
        }),
        Event::Note { text, code, point } => json!({
            "kind": "note",
            "text": text,
            "code": code,
            "point": point.map(|p| p.to_vec()),
        }),
        Event::Stop {
            reason,
            code,
            facet,
        } => json!({"kind": "stop", "reason": reason, "code": code, "facet": facet}),
    }
}
