//! A generic 3-D scene — coloured triangles, points, segments and text labels — and the
//! self-contained HTML page that shows it with mouse rotation (the viewer behind
//! [`trace_page`](super::html::trace_page)).
//!
//! The page is one file: the scene is embedded as JSON and drawn by an inline script on a canvas
//! (painter's order, flat shading, no WebGL, no network). Drag to rotate, wheel to zoom; a scene
//! with several frames gets a step slider, and several panels are shown side by side with one
//! shared viewpoint. For tests and scripts the page records script errors in the `data-errors`
//! attribute of `<html>` (empty when all is well), sets `data-ready="1"` once drawn, and reads
//! `#step=K` (or `#step=K1,K2` per panel, `last` for the last frame), `yaw=` and `pitch=`
//! (radians) from the URL fragment, e.g. `page.html#step=3&yaw=0.5&pitch=0.3`.
//!
//! ```
//! use pqhull::viz::scene::{Color, Panel, Scene, scene_page};
//!
//! // A tetrahedron with a contact point, its normal and a label.
//! let v = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
//! let mut scene = Scene::new("a tetrahedron and one contact");
//! for [a, b, c] in [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]] {
//!     scene.triangle([v[a], v[b], v[c]], Color::rgb(150, 180, 220).with_alpha(0.8));
//! }
//! // A contact point, its inward normal as a segment, and a label.
//! let (p, n) = ([0.3, 0.3, 0.4], [-0.577, -0.577, -0.577]);
//! let tip = [p[0] + 0.2 * n[0], p[1] + 0.2 * n[1], p[2] + 0.2 * n[2]];
//! scene
//!     .point(p, Color::RED, 5.0)
//!     .segment(p, tip, Color::GREEN, 2.0)
//!     .label(p, "contact 1", Color::BLACK);
//! let page = scene.to_html("one grasp");
//! assert!(page.contains("contact 1") && !page.contains("http"));
//! // Several frames (a slider) and several panels side by side:
//! let page = scene_page("candidates", &[Panel::new("grasp A", vec![scene.clone(), scene])]);
//! assert!(page.contains("grasp A"));
//! ```

use serde_json::{Value, json};
use std::fmt::Write as _;

/// An RGBA colour: 8-bit channels and an opacity in [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Color {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
    /// Opacity, 0 (transparent) to 1 (opaque).
    pub a: f64,
}

impl Color {
    /// Black.
    pub const BLACK: Color = Color::rgb(0, 0, 0);
    /// A strong red.
    pub const RED: Color = Color::rgb(215, 45, 60);
    /// A strong green.
    pub const GREEN: Color = Color::rgb(40, 160, 70);
    /// A strong blue.
    pub const BLUE: Color = Color::rgb(40, 90, 200);
    /// A mid grey.
    pub const GREY: Color = Color::rgb(150, 150, 150);

    /// An opaque colour.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Self {
        Color { r, g, b, a: 1.0 }
    }

    /// The same colour with opacity `a` (clamped to [0, 1]).
    pub fn with_alpha(self, a: f64) -> Self {
        Color {
            a: if a.is_nan() { 1.0 } else { a.clamp(0.0, 1.0) },
            ..self
        }
    }

    fn to_json(self) -> Value {
        json!([self.r, self.g, self.b, self.a])
    }
}

/// A filled triangle (shaded by its orientation to a fixed light, both sides alike).
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle {
    /// Its corners.
    pub corners: [[f64; 3]; 3],
    /// Its colour (use an opacity below 1 to see what is behind).
    pub color: Color,
}

/// A point drawn as a disc of a fixed size on screen.
#[derive(Clone, Debug, PartialEq)]
pub struct Marker {
    /// Where.
    pub position: [f64; 3],
    /// Its colour.
    pub color: Color,
    /// Radius in CSS pixels.
    pub radius: f64,
}

/// A line segment.
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    /// One end.
    pub from: [f64; 3],
    /// The other end.
    pub to: [f64; 3],
    /// Its colour.
    pub color: Color,
    /// Width in CSS pixels.
    pub width: f64,
}

/// A text label next to a point (drawn on top of everything).
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The point it labels.
    pub position: [f64; 3],
    /// The text.
    pub text: String,
    /// Its colour.
    pub color: Color,
}

/// One picture: what to draw and a caption shown under it. Everything is depth-sorted together
/// (painter's order), so markers and segments hide behind nearer opaque triangles.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    /// Shown under the picture.
    pub caption: String,
    /// Filled triangles.
    pub triangles: Vec<Triangle>,
    /// Points.
    pub points: Vec<Marker>,
    /// Segments.
    pub segments: Vec<Segment>,
    /// Labels.
    pub labels: Vec<Label>,
}

impl Scene {
    /// An empty scene with a caption.
    pub fn new(caption: impl Into<String>) -> Self {
        Scene {
            caption: caption.into(),
            ..Scene::default()
        }
    }

    /// Adds a triangle.
    pub fn triangle(&mut self, corners: [[f64; 3]; 3], color: Color) -> &mut Self {
        self.triangles.push(Triangle { corners, color });
        self
    }

    /// Adds a point of `radius` pixels.
    pub fn point(&mut self, position: [f64; 3], color: Color, radius: f64) -> &mut Self {
        self.points.push(Marker {
            position,
            color,
            radius,
        });
        self
    }

    /// Adds a segment of `width` pixels.
    pub fn segment(&mut self, from: [f64; 3], to: [f64; 3], color: Color, width: f64) -> &mut Self {
        self.segments.push(Segment {
            from,
            to,
            color,
            width,
        });
        self
    }

    /// Adds a label.
    pub fn label(
        &mut self,
        position: [f64; 3],
        text: impl Into<String>,
        color: Color,
    ) -> &mut Self {
        self.labels.push(Label {
            position,
            text: text.into(),
            color,
        });
        self
    }

    /// This scene alone as a self-contained HTML page titled `title`.
    pub fn to_html(&self, title: &str) -> String {
        scene_page(title, &[Panel::new("", vec![self.clone()])])
    }

    /// The scene as the viewer reads it: a palette of colours and compact arrays that index
    /// it (a mesh of thousands of triangles in a few colours stays small). Non-finite
    /// coordinates become null.
    fn to_json(&self) -> Value {
        let mut palette: Vec<Color> = Vec::new();
        let mut index = |c: Color| match palette.iter().position(|&p| p == c) {
            Some(i) => i,
            None => {
                palette.push(c);
                palette.len() - 1
            }
        };
        let triangles: Vec<Value> = self
            .triangles
            .iter()
            .map(|t| {
                let mut row: Vec<Value> = t.corners.iter().flatten().map(|&x| json!(x)).collect();
                row.push(json!(index(t.color)));
                Value::Array(row)
            })
            .collect();
        let points: Vec<Value> = self
            .points
            .iter()
            .map(|m| {
                let [x, y, z] = m.position;
                json!([x, y, z, index(m.color), m.radius])
            })
            .collect();
        let segments: Vec<Value> = self
            .segments
            .iter()
            .map(|s| {
                let ([a, b, c], [d, e, f]) = (s.from, s.to);
                json!([a, b, c, d, e, f, index(s.color), s.width])
            })
            .collect();
        let labels: Vec<Value> = self
            .labels
            .iter()
            .map(|l| {
                let [x, y, z] = l.position;
                json!([x, y, z, l.text, index(l.color)])
            })
            .collect();
        json!({
            "caption": self.caption,
            "colors": palette.into_iter().map(Color::to_json).collect::<Vec<_>>(),
            "triangles": triangles,
            "points": points,
            "segments": segments,
            "labels": labels,
        })
    }
}

/// A titled sequence of scenes shown in one canvas with a step slider (no slider for one
/// scene).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Panel {
    /// Shown above the canvas (may be empty).
    pub title: String,
    /// The frames, in slider order.
    pub frames: Vec<Scene>,
}

impl Panel {
    /// A panel of `frames`.
    pub fn new(title: impl Into<String>, frames: Vec<Scene>) -> Self {
        Panel {
            title: title.into(),
            frames,
        }
    }
}

/// A self-contained HTML page titled `title` showing `panels` side by side (drag to rotate, one
/// viewpoint for all). A panel without frames shows an empty scene.
pub fn scene_page(title: &str, panels: &[Panel]) -> String {
    scene_page_with_note(title, panels, "")
}

/// [`scene_page`] with `note`, plain text, shown under the panels (escaped here).
///
/// ```
/// use pqhull::viz::scene::{Panel, scene_page_with_note};
/// let page = scene_page_with_note("two views", &[Panel::new("a", vec![])], "a < b");
/// assert!(page.contains("a &lt; b"));
/// ```
pub fn scene_page_with_note(title: &str, panels: &[Panel], note: &str) -> String {
    let panels: Vec<Value> = panels
        .iter()
        .map(|p| {
            let frames: Vec<Value> = if p.frames.is_empty() {
                vec![Scene::default().to_json()]
            } else {
                p.frames.iter().map(Scene::to_json).collect()
            };
            json!({"title": p.title, "frames": frames})
        })
        .collect();
    page(title, &json!({ "panels": panels }), &escape(note))
}

/// Script run first: it records every script error (including a syntax error in the viewer) in
/// `<html data-errors>` and in a visible box, so that a headless browser's DOM dump shows it.
const ERROR_GUARD: &str = r#""use strict";
(function () {
  var root = document.documentElement;
  function record(message) {
    var previous = root.getAttribute("data-errors");
    root.setAttribute("data-errors", (previous ? previous + " | " : "") + message);
    var box = document.getElementById("pqhull-errors");
    if (box) { box.hidden = false; box.textContent = "Script error: " + root.getAttribute("data-errors"); }
  }
  window.onerror = function (message, source, line, column) { record(message + " (line " + line + ":" + column + ")"); };
  window.addEventListener("unhandledrejection", function (e) { record("unhandled rejection: " + e.reason); });
  window.pqhullRecordError = record;
})();"#;

const STYLE: &str = "\
body{font-family:sans-serif;margin:12px 16px;color:#222;background:#fafafa}\
h1{font-size:18px;margin:0 0 8px}h2{font-size:15px;margin:4px 0}\
#pqhull-panels{display:flex;gap:14px;align-items:flex-start}\
.panel{flex:1 1 0;min-width:0}\
canvas{width:100%;display:block;background:#fff;border:1px solid #ccd;cursor:grab;touch-action:none}\
.controls{display:flex;align-items:center;gap:6px;margin:6px 0}.controls input{flex:1}\
.counter{font-variant-numeric:tabular-nums;min-width:8em;text-align:right}\
.caption{margin:2px 0;min-height:2.4em;font-size:14px}.status{margin:2px 0;color:#555;font-size:13px}\
#pqhull-errors{background:#fdd;border:1px solid #c00;padding:6px;white-space:pre-wrap}\
.legend{font-size:13px;color:#333;margin-top:8px}\
.legend span.sw{display:inline-block;width:11px;height:11px;border-radius:2px;margin:0 4px 0 12px;vertical-align:-1px}\
.help{font-size:12px;color:#666}";

/// The page skeleton shared with the trace pages: `data` is `{"panels": [...]}` as the viewer
/// reads it (each panel `{title, frames}` or `{title, trace}`); `legend` is trusted HTML.
pub(in crate::viz) fn page(title: &str, data: &Value, legend: &str) -> String {
    // Inside <script>, only "</" can end the element early; JSON allows "\u003c" for "<".
    let json = data.to_string().replace('<', "\\u003c");
    let mut html = String::with_capacity(json.len() + 40_000);
    let title = escape(title);
    let _ = write!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\" data-errors=\"\" data-ready=\"0\">\n<head>\n\
         <meta charset=\"utf-8\">\n<title>{title}</title>\n<style>{STYLE}</style>\n\
         <script>{ERROR_GUARD}</script>\n</head>\n<body>\n<h1>{title}</h1>\n\
         <div id=\"pqhull-errors\" hidden></div>\n<div id=\"pqhull-panels\"></div>\n\
         <div class=\"legend\">{legend}</div>\n\
         <p class=\"help\">Drag to rotate (3-D), wheel to zoom; \u{2190}/\u{2192} step every \
         panel. URL fragment: #step=K (or K1,K2 per panel), &amp;yaw=, &amp;pitch=.</p>\n\
         <script type=\"application/json\" id=\"pqhull-data\">{json}</script>\n\
         <script>{}</script>\n</body>\n</html>\n",
        include_str!("viewer.js")
    );
    html
}

/// Escapes text for HTML element content and attribute values.
pub(in crate::viz) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}
