//! A figure's plot, as SVG, drawn with `plotters` from the figure's own tables: every
//! per-grasp number in a plotted column is one marker (a `<circle>`), so the file's data and the
//! plot are the same numbers. The caption carries the paper's figure beside ours.
//!
//! SVG only: PNG would need a rasterising backend and a font file shipped with the crate.

use super::{Figure, FigureId, ReproduceError, Table};
use plotters::coord::Shift;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;

/// Width of a plot and height of its panels, pixels (the caption band comes on top).
pub const SIZE: (u32, u32) = (1400, 450);

/// The colours of the series, in order.
const COLOURS: [RGBColor; 6] = [
    RGBColor(0x1f, 0x77, 0xb4),
    RGBColor(0xd6, 0x27, 0x28),
    RGBColor(0x2c, 0xa0, 0x2c),
    RGBColor(0x94, 0x67, 0xbd),
    RGBColor(0xff, 0x7f, 0x0e),
    RGBColor(0x8c, 0x56, 0x4b),
];

/// One data series: its legend name, its (x, y) points (NaN coordinates are left out), and
/// whether consecutive points are joined by a line (markers are always drawn).
pub struct Series {
    /// Legend name.
    pub name: String,
    /// The points.
    pub points: Vec<(f64, f64)>,
    /// Join the points with a line.
    pub line: bool,
}

/// One panel: a chart of several series.
pub struct Panel {
    /// Its caption.
    pub title: String,
    /// The x axis.
    pub x_label: String,
    /// The y axis.
    pub y_label: String,
    /// Logarithmic x axis.
    pub log_x: bool,
    /// Logarithmic y axis.
    pub log_y: bool,
    /// The data.
    pub series: Vec<Series>,
}

impl Panel {
    /// Whether `p` can be drawn: positive on a logarithmic axis.
    fn shows(&self, p: (f64, f64)) -> bool {
        (!self.log_x || p.0 > 0.0) && (!self.log_y || p.1 > 0.0)
    }
}

impl Series {
    fn finite(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.points
            .iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
    }
}

/// A series from two columns of `table` (rows where either is NaN are left out).
///
/// # Panics
/// If a column is missing (a bug: the figure's own table).
pub fn columns(table: &Table, name: &str, x: &str, y: &str, line: bool) -> Series {
    let (xs, ys) = (
        table.column(x).unwrap_or_else(|| panic!("column {x}")),
        table.column(y).unwrap_or_else(|| panic!("column {y}")),
    );
    Series {
        name: name.to_string(),
        points: xs.iter().copied().zip(ys.iter().copied()).collect(),
        line,
    }
}

/// The range of `values` padded for a chart, in log space when `log`.
fn range(values: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    let (mut lo, mut hi) = values
        .filter(|v| v.is_finite() && (!log || *v > 0.0))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return if log { (1.0, 10.0) } else { (0.0, 1.0) };
    }
    if log {
        lo /= 1.5;
        hi *= 1.5;
    } else {
        let pad = ((hi - lo) * 0.05)
            .max(hi.abs().max(lo.abs()) * 1e-3)
            .max(1e-12);
        lo -= pad;
        hi += pad;
    }
    (lo, hi)
}

fn failed(e: impl std::fmt::Display) -> ReproduceError {
    ReproduceError::Plot(e.to_string())
}

/// A tick label: short, without trailing zeros (`0.5`, `20`, `1e5`).
fn tick(v: f64) -> String {
    if v == 0.0 {
        return "0".to_string();
    }
    if v.abs() >= 1e5 || v.abs() < 1e-3 {
        return format!("{v:.0e}");
    }
    let text = format!("{v:.3}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Draws `panel` into `area` on the given coordinate ranges.
fn chart<DB, X, Y>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    x: X,
    y: Y,
) -> Result<(), ReproduceError>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let hidden: usize = panel
        .series
        .iter()
        .map(|s| s.finite().filter(|&p| !panel.shows(p)).count())
        .sum();
    let title = if hidden == 0 {
        panel.title.clone()
    } else {
        format!(
            "{} ({hidden} zero or negative values not shown on the log axis)",
            panel.title
        )
    };
    let mut chart = ChartBuilder::on(area)
        .caption(&title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)
        .map_err(failed)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .draw()
        .map_err(failed)?;
    for (i, series) in panel.series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        let points: Vec<(f64, f64)> = series.finite().filter(|&p| panel.shows(p)).collect();
        if series.line {
            chart
                .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
                .map_err(failed)?;
        }
        chart
            .draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled())))
            .map_err(failed)?
            .label(series.name.as_str())
            .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], colour.filled()));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(failed)?;
    Ok(())
}

/// Draws `panels` side by side under a caption of `lines`, as an SVG document.
///
/// # Errors
/// [`ReproduceError::Plot`] when plotters fails.
pub fn svg(title: &str, lines: &[String], panels: &[Panel]) -> Result<String, ReproduceError> {
    let mut out = String::new();
    {
        let caption = 50 + 17 * lines.len() as u32;
        let size = (SIZE.0, SIZE.1 + caption);
        let root = SVGBackend::with_string(&mut out, size).into_drawing_area();
        root.fill(&WHITE).map_err(failed)?;
        let (top, bottom) = root.split_vertically(caption);
        top.draw(&Text::new(title, (20, 12), ("sans-serif", 22).into_font()))
            .map_err(failed)?;
        for (i, line) in lines.iter().enumerate() {
            let y = 44 + 17 * i as i32;
            top.draw(&Text::new(
                line.as_str(),
                (20, y),
                ("sans-serif", 14).into_font(),
            ))
            .map_err(failed)?;
        }
        let areas = bottom.split_evenly((1, panels.len().max(1)));
        for (area, panel) in areas.iter().zip(panels) {
            let xs = range(
                panel.series.iter().flat_map(|s| s.finite().map(|p| p.0)),
                panel.log_x,
            );
            let ys = range(
                panel.series.iter().flat_map(|s| s.finite().map(|p| p.1)),
                panel.log_y,
            );
            match (panel.log_x, panel.log_y) {
                (false, false) => chart(area, panel, xs.0..xs.1, ys.0..ys.1)?,
                (false, true) => chart(area, panel, xs.0..xs.1, (ys.0..ys.1).log_scale())?,
                (true, false) => chart(area, panel, (xs.0..xs.1).log_scale(), ys.0..ys.1)?,
                (true, true) => chart(
                    area,
                    panel,
                    (xs.0..xs.1).log_scale(),
                    (ys.0..ys.1).log_scale(),
                )?,
            }
        }
        root.present().map_err(failed)?;
    }
    Ok(out)
}

/// The caption lines of `figure`: paper against pqhull, one line per quantity.
fn caption(figure: &Figure) -> Vec<String> {
    figure
        .comparisons
        .iter()
        .map(|c| format!("{} — paper: {} · pqhull: {}", c.quantity, c.paper, c.pqhull))
        .collect()
}

/// The panels of `figure`, from its tables.
///
/// # Panics
/// If a table or column the figure always has is missing (a bug).
pub fn panels(figure: &Figure) -> Vec<Panel> {
    let t = |name: &str| figure.table(name).unwrap_or_else(|| panic!("table {name}"));
    let per_grasp = |table: &Table, suffix: &str, methods: &[&str]| -> Vec<Series> {
        methods
            .iter()
            .map(|m| columns(table, m, "grasp", &format!("{m}_{suffix}"), false))
            .collect()
    };
    let panel = |title: &str, x: &str, y: &str, log: (bool, bool), series| Panel {
        title: title.to_string(),
        x_label: x.to_string(),
        y_label: y.to_string(),
        log_x: log.0,
        log_y: log.1,
        series,
    };
    match figure.id {
        FigureId::Fig6 => {
            let table = t("fig6");
            let methods = super::gws::METHODS;
            vec![
                panel(
                    "points processed",
                    "grasp",
                    "points",
                    (false, true),
                    per_grasp(table, "points", &methods),
                ),
                panel(
                    "hyperplanes created",
                    "grasp",
                    "facets",
                    (false, true),
                    per_grasp(table, "facets", &methods),
                ),
                panel(
                    "time",
                    "grasp",
                    "µs",
                    (false, true),
                    per_grasp(table, "us", &methods),
                ),
            ]
        }
        FigureId::Fig7 => {
            let table = t("fig7_ratios");
            let ratios = |who: &str| -> Vec<Series> {
                ["points", "facets", "time"]
                    .iter()
                    .map(|q| columns(table, q, "k", &format!("{q}_ratio_{who}"), true))
                    .collect()
            };
            vec![
                panel(
                    "QuickHull / PQHGWS (published)",
                    "cone edges k",
                    "ratio",
                    (false, true),
                    ratios("pqhgws"),
                ),
                panel(
                    "QuickHull / pqhull default",
                    "cone edges k",
                    "ratio",
                    (false, true),
                    ratios("pqhull"),
                ),
            ]
        }
        FigureId::Fig8 => {
            let names: Vec<&str> = super::ows::METHODS.iter().map(|m| m.0).collect();
            vec![panel(
                "time per grasp",
                "grasp",
                "µs",
                (false, true),
                per_grasp(t("fig8"), "us", &names),
            )]
        }
        FigureId::Fig9 => vec![panel(
            "(ellipsoid − exact) / exact, force-closure grasps",
            "grasp",
            "relative error",
            (false, false),
            vec![columns(
                t("fig9"),
                "ellipsoid",
                "grasp",
                "relative_error",
                false,
            )],
        )],
        FigureId::Fig10 => {
            let table = t("fig10");
            let all = columns(table, "samples (force closure)", "q1", "ows", false);
            let chosen = |flag: &str, name: &str| {
                let marks = table.column(flag).expect("flag column");
                let mut s = columns(table, name, "q1", "ows", false);
                s.points = s
                    .points
                    .iter()
                    .zip(marks)
                    .map(|(&p, &m)| if m == 1.0 { p } else { (f64::NAN, f64::NAN) })
                    .collect();
                s
            };
            let (q1_best, ows_best) =
                (chosen("q1_best", "Q1-best"), chosen("ows_best", "OWS-best"));
            vec![panel(
                "Q_OWS against Q1",
                "Q1",
                "Q_OWS",
                (false, false),
                vec![all, q1_best, ows_best],
            )]
        }
        FigureId::Fig12 => {
            let table = t("fig12");
            let pair = |metric: &str| -> Vec<Series> {
                ["partial", "full"]
                    .iter()
                    .map(|m| columns(table, m, "sample", &format!("{metric}_{m}_us"), false))
                    .collect()
            };
            vec![
                panel(
                    "Q1: quality evaluation per sample",
                    "sample",
                    "µs",
                    (false, true),
                    pair("q1"),
                ),
                panel(
                    "Q_OWS: quality evaluation per sample",
                    "sample",
                    "µs",
                    (false, true),
                    pair("ows"),
                ),
            ]
        }
        FigureId::Table1 => {
            let table = t("table1");
            vec![
                panel(
                    "quality evaluation per planned grasp, full / partial",
                    "object (cube, sphere, C shape, joystick, teapot)",
                    "ratio",
                    (false, true),
                    vec![
                        columns(table, "pqhull", "object", "evaluation_speedup", false),
                        columns(table, "paper", "object", "paper_evaluation_speedup", false),
                    ],
                ),
                panel(
                    "planning per planned grasp, full / partial",
                    "object (cube, sphere, C shape, joystick, teapot)",
                    "ratio",
                    (false, true),
                    vec![columns(
                        table,
                        "pqhull",
                        "object",
                        "planning_speedup",
                        false,
                    )],
                ),
            ]
        }
    }
}

/// The figure's plot, as an SVG document.
///
/// # Errors
/// [`ReproduceError::Plot`] when plotters fails.
pub fn figure_svg(figure: &Figure) -> Result<String, ReproduceError> {
    svg(
        &format!("{}: {}", figure.id.name(), figure.title),
        &caption(figure),
        &panels(figure),
    )
}
