//! 2-D traces as static SVG pictures, one per step.
//!
//! Each picture stands alone (no script, no external reference): the hull after the step's
//! event, coloured as in the HTML viewer ([`html`](super::html)), with the event's description
//! as a caption. Made for documents and for looking at a run without a browser.

use super::VizError;
use super::scene::escape;
use crate::hull::{Event, Replay, Trace};
use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;

const WIDTH: f64 = 640.0;
const HEIGHT: f64 = 560.0;
/// Room under the drawing for the caption.
const CAPTION: f64 = 90.0;

/// One SVG document per event of a 2-D trace: picture `k` shows the hull after event `k`.
///
/// ```
/// use pqhull::{FarthestPoint, Hull};
/// let points = pqhull::rbox::generate::<2>(&pqhull::rbox::Family::UniformCube, 20, 2);
/// let (_, (), trace) = Hull::try_with_strategy_traced(&points, FarthestPoint::new())?;
/// let pictures = pqhull::viz::svg::trace_svgs(&trace)?;
/// assert_eq!(pictures.len(), trace.events.len());
/// assert!(pictures.iter().all(|s| s.starts_with("<svg") && s.ends_with("</svg>\n")));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`VizError::Dimension`] unless D is 2; [`VizError::Empty`] for a trace without events.
pub fn trace_svgs<const D: usize>(trace: &Trace<D>) -> Result<Vec<String>, VizError> {
    if D != 2 {
        return Err(VizError::Dimension {
            dimension: D,
            supported: "2-D",
        });
    }
    if trace.events.is_empty() {
        return Err(VizError::Empty);
    }
    let frame = Frame::new(trace);
    let mut replay = trace.replay();
    let mut state = Carry::default();
    let mut pictures = Vec::with_capacity(trace.events.len());
    while let Some(event) = replay.step() {
        state.update(event);
        pictures.push(frame.draw(trace, &replay, event, &state));
    }
    Ok(pictures)
}

/// What persists between events: the latest marked point and inflation factor, the points not
/// inserted yet.
#[derive(Default)]
struct Carry {
    mark: Option<[f64; 2]>,
    factor: Option<f64>,
    inserted: HashSet<usize>,
    /// Vertices of every facet seen so far, by serial (removed facets are drawn dashed).
    seen: HashMap<u64, Vec<usize>>,
}

impl Carry {
    fn update<const D: usize>(&mut self, event: &Event<D>) {
        match event {
            Event::Note { point: Some(p), .. } => self.mark = Some([p[0], p[1]]),
            Event::Chose { key: Some(k), .. }
                if k.name == "inflation factor" && k.value.is_finite() =>
            {
                self.factor = Some(k.value);
            }
            Event::Inserted { point, .. } => {
                self.inserted.insert(*point);
            }
            Event::Initial { facets: new } | Event::Expanded { created: new, .. } => {
                for f in new {
                    self.seen.insert(f.serial, f.vertices.to_vec());
                }
            }
            _ => {}
        }
    }
}

/// The mapping from the trace's coordinates to the picture, fixed for every step.
struct Frame {
    centre: [f64; 2],
    scale: f64,
    /// Points inserted during the run (hidden until inserted).
    late: HashSet<usize>,
    longest_disturbance: f64,
}

impl Frame {
    fn new<const D: usize>(trace: &Trace<D>) -> Self {
        let mut all: Vec<[f64; 2]> = trace.points.iter().map(|p| [p[0], p[1]]).collect();
        all.extend(trace.context.query.map(|q| [q[0], q[1]]));
        if !trace.context.disturbances.is_empty() {
            all.push([0.0, 0.0]);
        }
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in all.iter().filter(|p| p.iter().all(|x| x.is_finite())) {
            for c in 0..2 {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
        if lo[0] > hi[0] {
            (lo, hi) = ([-1.0; 2], [1.0; 2]);
        }
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-300);
        let longest_disturbance = trace
            .context
            .disturbances
            .iter()
            .map(|d| d[0].hypot(d[1]))
            .fold(0.0, f64::max);
        Frame {
            centre: [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])],
            scale: 0.9 * WIDTH.min(HEIGHT - CAPTION) / span,
            late: trace
                .events
                .iter()
                .filter_map(|e| match e {
                    Event::Inserted { point, .. } => Some(*point),
                    _ => None,
                })
                .collect(),
            longest_disturbance,
        }
    }

    fn at(&self, p: [f64; 2]) -> (f64, f64) {
        (
            WIDTH / 2.0 + self.scale * (p[0] - self.centre[0]),
            (HEIGHT - CAPTION) / 2.0 - self.scale * (p[1] - self.centre[1]),
        )
    }

    fn draw<const D: usize>(
        &self,
        trace: &Trace<D>,
        replay: &Replay<'_, D>,
        event: &Event<D>,
        carry: &Carry,
    ) -> String {
        let xy = |i: usize| [trace.points[i][0], trace.points[i][1]];
        let focus = match event {
            Event::Chose { facet, .. }
            | Event::Claimed { facet, .. }
            | Event::Inserted { facet, .. } => Some(*facet),
            _ => None,
        };
        let stop = match event {
            Event::Stop { facet, .. } => *facet,
            _ => None,
        };
        let created: HashSet<u64> = match event {
            Event::Expanded { created, .. } => created.iter().map(|f| f.serial).collect(),
            _ => HashSet::new(),
        };
        let added = match event {
            Event::Expanded { point, .. } | Event::Inserted { point, .. } => Some(*point),
            _ => None,
        };
        let mut svg = String::new();
        let _ = writeln!(
            svg,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH}\" height=\"{HEIGHT}\" \
             viewBox=\"0 0 {WIDTH} {HEIGHT}\" font-family=\"sans-serif\">\n\
             <rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>"
        );
        // The polygon, filled: the facets are its edges, in no particular order, so fan from the
        // vertices' mean (inside, the hull being convex) one triangle per edge.
        let vertices = replay.vertices();
        let n = vertices.len().max(1) as f64;
        let mean = vertices
            .iter()
            .fold([0.0; 2], |m, &v| [m[0] + xy(v)[0] / n, m[1] + xy(v)[1] / n]);
        let (mx, my) = self.at(mean);
        for f in replay.facets() {
            let ((ax, ay), (bx, by)) = (self.at(xy(f.vertices[0])), self.at(xy(f.vertices[1])));
            let _ = writeln!(
                svg,
                "<polygon points=\"{mx:.2},{my:.2} {ax:.2},{ay:.2} {bx:.2},{by:.2}\" fill=\"#e2ecf7\" stroke=\"#e2ecf7\"/>"
            );
        }
        let mut outside = HashSet::new();
        let mut focus_outside = HashSet::new();
        for f in replay.facets() {
            outside.extend(f.outside.iter().copied());
            if Some(f.serial) == focus {
                focus_outside.extend(f.outside.iter().copied());
            }
            let (color, width) = if Some(f.serial) == focus {
                ("#ff8c00", 4.5)
            } else if Some(f.serial) == stop {
                ("#d72d3c", 4.5)
            } else if created.contains(&f.serial) {
                ("#46b95f", 4.5)
            } else {
                ("#96b6da", 2.0)
            };
            self.line(
                &mut svg,
                xy(f.vertices[0]),
                xy(f.vertices[1]),
                color,
                width,
                false,
            );
        }
        if let Event::Expanded { removed, .. } = event {
            for edge in removed.iter().filter_map(|s| carry.seen.get(s)) {
                self.line(&mut svg, xy(edge[0]), xy(edge[1]), "#c82828", 1.5, true);
            }
        }
        let is_vertex: HashSet<usize> = vertices.iter().copied().collect();
        for i in
            (0..trace.points.len()).filter(|i| !self.late.contains(i) || carry.inserted.contains(i))
        {
            let (color, r) = if Some(i) == added {
                ("#00963c", 6.5)
            } else if focus_outside.contains(&i) {
                ("#ff7800", 4.5)
            } else if outside.contains(&i) {
                ("#dc3232", 3.5)
            } else if is_vertex.contains(&i) {
                ("#1e3c78", 3.5)
            } else {
                ("#a5a5a5", 2.5)
            };
            self.dot(&mut svg, xy(i), color, r);
        }
        if let Some(p) = added {
            self.text(&mut svg, xy(p), &format!("p{p}"), "#00963c");
        }
        if let Some(q) = trace.context.query {
            let q = [q[0], q[1]];
            if let Some(x) = carry.mark {
                self.line(&mut svg, q, x, "#8200aa", 1.5, true);
                self.dot(&mut svg, x, "#000", 5.0);
                self.text(&mut svg, x, "x", "#000");
            }
            self.dot(&mut svg, q, "#8200aa", 6.0);
            self.text(&mut svg, q, "q", "#8200aa");
        }
        let disturbances = &trace.context.disturbances;
        if !disturbances.is_empty() {
            let s = carry.factor.unwrap_or_else(|| {
                0.3 * WIDTH.min(HEIGHT - CAPTION)
                    / self.scale
                    / self.longest_disturbance.max(1e-300)
            });
            for d in disturbances {
                let end = [-s * d[0], -s * d[1]];
                self.line(&mut svg, [0.0, 0.0], end, "#008c8c", 1.5, false);
                self.dot(&mut svg, end, "#008c8c", 3.0);
            }
            self.dot(&mut svg, [0.0, 0.0], "#000", 4.0);
        }
        let caption = describe(event);
        let status = format!(
            "step {} / {} \u{2014} {} facets, {} vertices, {} point(s) in outside sets",
            replay.position() - 1,
            trace.events.len() - 1,
            replay.facets().count(),
            vertices.len(),
            outside.len()
        );
        for (k, line) in wrap(&caption, 95).iter().chain([&status]).enumerate() {
            let _ = writeln!(
                svg,
                "<text x=\"10\" y=\"{:.0}\" font-size=\"13\" fill=\"#222\">{}</text>",
                HEIGHT - CAPTION + 16.0 + 17.0 * k as f64,
                escape(line)
            );
        }
        svg.push_str("</svg>\n");
        svg
    }

    fn line(
        &self,
        svg: &mut String,
        a: [f64; 2],
        b: [f64; 2],
        color: &str,
        width: f64,
        dashed: bool,
    ) {
        let ((ax, ay), (bx, by)) = (self.at(a), self.at(b));
        let dash = if dashed {
            " stroke-dasharray=\"5 4\""
        } else {
            ""
        };
        let _ = writeln!(
            svg,
            "<line x1=\"{ax:.2}\" y1=\"{ay:.2}\" x2=\"{bx:.2}\" y2=\"{by:.2}\" stroke=\"{color}\" \
             stroke-width=\"{width}\" stroke-linecap=\"round\"{dash}/>"
        );
    }

    fn dot(&self, svg: &mut String, p: [f64; 2], color: &str, r: f64) {
        let (x, y) = self.at(p);
        let _ = writeln!(
            svg,
            "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"{r}\" fill=\"{color}\" stroke=\"#fff\"/>"
        );
    }

    fn text(&self, svg: &mut String, p: [f64; 2], text: &str, color: &str) {
        let (x, y) = self.at(p);
        let _ = writeln!(
            svg,
            "<text x=\"{:.2}\" y=\"{:.2}\" font-size=\"13\" font-weight=\"bold\" fill=\"{color}\" \
             stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">{}</text>",
            x + 7.0,
            y - 7.0,
            escape(text)
        );
    }
}

/// The caption of an event (the same wording as the HTML viewer's).
fn describe<const D: usize>(event: &Event<D>) -> String {
    let join = |v: &[usize]| v.iter().map(usize::to_string).collect::<Vec<_>>().join(" ");
    match event {
        Event::Initial { facets } => format!("initial simplex: {} facets", facets.len()),
        Event::Chose {
            facet,
            vertices,
            reason,
            key,
            ..
        } => {
            let key = key
                .as_ref()
                .map(|k| format!("; {} = {:.6}", k.name, k.value))
                .unwrap_or_default();
            format!(
                "chose facet #{facet} (vertices {}): {reason}{key}",
                join(vertices)
            )
        }
        Event::Claimed { facet, points } => format!(
            "facet #{facet} claimed {} point(s) lying beyond it from other outside sets",
            points.len()
        ),
        Event::Inserted {
            facet,
            point,
            coordinates,
        } => {
            format!("implicit point {point} = {coordinates:?} inserted beyond facet #{facet}")
        }
        Event::Expanded {
            facet,
            point,
            removed,
            created,
        } => format!(
            "added point {point} beyond facet #{facet}: removed {} facet(s), created {}",
            removed.len(),
            created.len()
        ),
        Event::Note { text, .. } => text.clone(),
        Event::Stop { reason, .. } => format!("stop: {reason}"),
    }
}

/// Splits `text` into lines of at most about `width` characters, at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split(' ') {
        let last = lines.last_mut().expect("never empty");
        if !last.is_empty() && last.chars().count() + 1 + word.chars().count() > width {
            lines.push(word.to_string());
        } else {
            if !last.is_empty() {
                last.push(' ');
            }
            last.push_str(word);
        }
    }
    lines
}
