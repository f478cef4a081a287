//! `pqh reproduce --size smoke`: every figure's files exist, each plot is well-formed SVG whose
//! markers are exactly the finite numbers of the columns it plots, the derived tables follow from
//! the per-grasp ones, and the summary carries the paper's figures beside ours.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

/// A CSV file as columns (an empty cell is NaN).
fn read_csv(path: &Path) -> BTreeMap<String, Vec<f64>> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .expect("a header")
        .split(',')
        .map(String::from)
        .collect();
    let mut columns: BTreeMap<String, Vec<f64>> =
        header.iter().map(|h| (h.clone(), Vec::new())).collect();
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells.len(), header.len(), "{}: {line}", path.display());
        for (h, c) in header.iter().zip(cells) {
            let v = if c.is_empty() {
                f64::NAN
            } else {
                c.parse().unwrap_or(f64::NAN)
            };
            columns.get_mut(h).unwrap().push(v);
        }
    }
    columns
}

/// Checks that `svg` is one well-formed element tree rooted at `<svg>` (tags balanced and
/// properly nested; comments, declarations and self-closing tags allowed).
fn assert_well_formed(svg: &str, name: &str) {
    let body = svg.trim();
    let body = match body.strip_prefix("<?xml") {
        Some(rest) => &rest[rest.find("?>").expect("end of the XML declaration") + 2..],
        None => body,
    };
    assert!(
        body.trim_start().starts_with("<svg"),
        "{name}: does not start with <svg"
    );
    let mut stack: Vec<String> = Vec::new();
    let mut rest = body;
    while let Some(open) = rest.find('<') {
        rest = &rest[open + 1..];
        if let Some(comment) = rest.strip_prefix("!--") {
            rest = &comment[comment.find("-->").expect("closed comment") + 3..];
            continue;
        }
        let close = rest
            .find('>')
            .unwrap_or_else(|| panic!("{name}: unclosed tag"));
        let tag = &rest[..close];
        rest = &rest[close + 1..];
        if let Some(end) = tag.strip_prefix('/') {
            let top = stack
                .pop()
                .unwrap_or_else(|| panic!("{name}: </{end}> closes nothing"));
            assert_eq!(top, end.trim(), "{name}: </{end}> closes <{top}>");
        } else if !tag.ends_with('/') && !tag.starts_with('!') && !tag.starts_with('?') {
            let element = tag.split_whitespace().next().unwrap_or("").to_string();
            stack.push(element);
        }
        if stack.is_empty() {
            assert!(
                rest.trim().is_empty(),
                "{name}: content after the root element"
            );
            return;
        }
    }
    panic!("{name}: elements left open: {stack:?}");
}

/// Plotted points of `ys` against `xs`: both finite, and positive where the axis is logarithmic.
fn plotted(xs: &[f64], ys: &[f64], log_x: bool, log_y: bool) -> usize {
    xs.iter()
        .zip(ys)
        .filter(|(x, y)| {
            x.is_finite() && y.is_finite() && (!log_x || **x > 0.0) && (!log_y || **y > 0.0)
        })
        .count()
}

fn circles(svg: &str) -> usize {
    svg.matches("<circle").count()
}

#[test]
fn every_figure_has_data_a_plot_drawn_from_it_and_the_paper_beside_it() {
    let dir = tempfile_dir();
    let status = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(["reproduce", "--size", "smoke", "--quiet", "--output-dir"])
        .arg(&dir)
        .output()
        .expect("pqh runs");
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let svg = |name: &str| {
        let text = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
        assert_well_formed(&text, name);
        text
    };
    let csv = |name: &str| read_csv(&dir.join(format!("{name}.csv")));

    // Fig. 6: three panels of four methods against the grasp number, log y.
    let fig6 = csv("fig6");
    let mut expected = 0;
    for m in ["quickhull", "pqhgws", "pqhull", "qhull"] {
        for q in ["points", "facets", "us"] {
            expected += plotted(&fig6["grasp"], &fig6[&format!("{m}_{q}")], false, true);
        }
    }
    assert_eq!(circles(&svg("fig6")), expected, "fig6");
    for column in [
        "pqhgws_points",
        "pqhgws_facets",
        "pqhgws_us",
        "pqhull_us",
        "quickhull_us",
    ] {
        let ran = fig6[column].iter().filter(|v| !v.is_nan()).count();
        let expected = if column.starts_with("quickhull") {
            3
        } else {
            6
        };
        assert_eq!(ran, expected, "fig6 {column}: the smoke size's grasps");
        assert_eq!(
            plotted(&fig6["grasp"], &fig6[column], false, true),
            ran,
            "fig6 {column}"
        );
    }
    // Built with Qhull (as CI is), its baseline ran on the smoke size's 3 grasps (or failed on
    // them, which the summary counts): the comparison below is not silently empty.
    if cfg!(feature = "qhull") {
        let ran = fig6["qhull_us"].iter().filter(|v| !v.is_nan()).count();
        assert_eq!(ran, 3, "fig6: Qhull's baseline did not run");
    }
    // QuickHull and PQHGWS give the same Q1 on the grasps both ran (the same verdicts, values to
    // rounding), and so does Qhull where it ran.
    for other in ["quickhull", "qhull"] {
        for (i, (&a, &b)) in fig6["pqhgws_q1"]
            .iter()
            .zip(&fig6[&format!("{other}_q1")])
            .enumerate()
        {
            if fig6[&format!("{other}_us")][i].is_nan() {
                continue;
            }
            assert_eq!(
                a.is_nan(),
                b.is_nan(),
                "fig6 grasp {i}: verdicts of pqhgws and {other}"
            );
            if !a.is_nan() {
                assert!(
                    (a - b).abs() <= 1e-9 * b,
                    "fig6 grasp {i}: {a} vs {other} {b}"
                );
            }
        }
    }

    // Fig. 7: the ratio table follows from the per-grasp table.
    let (fig7, ratios) = (csv("fig7"), csv("fig7_ratios"));
    for (r, &k) in ratios["k"].iter().enumerate() {
        let rows: Vec<usize> = (0..fig7["k"].len())
            .filter(|&i| fig7["k"][i] == k)
            .collect();
        for (q, column) in [("points", "points"), ("facets", "facets"), ("time", "us")] {
            let both: Vec<usize> = rows
                .iter()
                .copied()
                .filter(|&i| !fig7[&format!("quickhull_{column}")][i].is_nan())
                .collect();
            let mean = |c: &str| both.iter().map(|&i| fig7[c][i]).sum::<f64>() / both.len() as f64;
            let ratio = mean(&format!("quickhull_{column}")) / mean(&format!("pqhgws_{column}"));
            let written = ratios[&format!("{q}_ratio_pqhgws")][r];
            assert!(
                (ratio - written).abs() <= 1e-12 * ratio,
                "k = {k}, {q}: {ratio} vs {written}"
            );
        }
    }
    let mut expected = 0;
    for who in ["pqhgws", "pqhull"] {
        for q in ["points", "facets", "time"] {
            expected += plotted(
                &ratios["k"],
                &ratios[&format!("{q}_ratio_{who}")],
                false,
                true,
            );
        }
    }
    assert_eq!(circles(&svg("fig7")), expected, "fig7");

    // Fig. 8: four methods' times.
    let fig8 = csv("fig8");
    let expected: usize = ["pqhows", "pqhull", "brute", "ellipsoid"]
        .iter()
        .map(|m| plotted(&fig8["grasp"], &fig8[&format!("{m}_us")], false, true))
        .sum();
    assert_eq!(circles(&svg("fig8")), expected, "fig8");

    // Fig. 9: one error per force-closure grasp, never above zero.
    let fig9 = csv("fig9");
    assert_eq!(
        circles(&svg("fig9")),
        plotted(&fig9["grasp"], &fig9["relative_error"], false, false)
    );
    for (i, &e) in fig9["relative_error"].iter().enumerate() {
        let recomputed = (fig9["ellipsoid_ows"][i] - fig9["exact_ows"][i]) / fig9["exact_ows"][i];
        assert_eq!(e, recomputed, "fig9 row {i}");
        assert!(e <= 0.0, "fig9 row {i}: the ellipsoid overestimated");
    }

    // Fig. 10: every force-closure sample, plus the two best marked again.
    let fig10 = csv("fig10");
    let both = plotted(&fig10["q1"], &fig10["ows"], false, false);
    let marked = fig10["q1_best"]
        .iter()
        .chain(&fig10["ows_best"])
        .filter(|&&m| m == 1.0)
        .count();
    assert_eq!(circles(&svg("fig10")), both + marked, "fig10");
    // In every sample set, the marked grasp is the set's best by its metric.
    for (flag, metric) in [("q1_best", "q1"), ("ows_best", "ows")] {
        for (i, &m) in fig10[flag].iter().enumerate() {
            if m != 1.0 {
                continue;
            }
            let seed = fig10["seed"][i];
            for j in (0..fig10["seed"].len()).filter(|&j| fig10["seed"][j] == seed) {
                let v = fig10[metric][j];
                assert!(
                    v.is_nan() || v <= fig10[metric][i],
                    "fig10 {metric}: sample {j} beats the marked {i}"
                );
            }
        }
    }

    // Fig. 12: each metric by each method, per sample; partial and full agree.
    let fig12 = csv("fig12");
    let expected: usize = ["q1_partial", "q1_full", "ows_partial", "ows_full"]
        .iter()
        .map(|m| plotted(&fig12["sample"], &fig12[&format!("{m}_us")], false, true))
        .sum();
    assert_eq!(circles(&svg("fig12")), expected, "fig12");
    for metric in ["q1", "ows"] {
        let (p, f) = (
            &fig12[&format!("{metric}_partial_value")],
            &fig12[&format!("{metric}_full_value")],
        );
        for (i, (&a, &b)) in p.iter().zip(f).enumerate() {
            assert_eq!(a.is_nan(), b.is_nan(), "fig12 {metric} sample {i}");
            if !a.is_nan() {
                assert!(
                    (a - b).abs() <= 1e-9 * b.abs(),
                    "fig12 {metric} sample {i}: {a} vs {b}"
                );
            }
        }
    }

    // Table 1: five objects, both methods timed, the paper's ratios beside ours.
    let table1 = csv("table1");
    assert_eq!(table1["object"].len(), 5, "table1 rows");
    for column in [
        "evaluation_speedup",
        "planning_speedup",
        "paper_evaluation_speedup",
    ] {
        assert!(
            table1[column].iter().all(|&r| r.is_finite() && r > 0.0),
            "table1 {column}: {:?}",
            table1[column]
        );
    }
    assert!(table1["best_q1_partial"].iter().any(|v| v.is_finite()));

    let summary = std::fs::read_to_string(dir.join("summary.md")).unwrap();
    for paper in ["≈ 6×", "≈ 70×", "≈ 40×", "19–39×", "25.26×"] {
        assert!(
            summary.contains(paper),
            "summary.md lacks the paper's {paper}"
        );
    }
    assert!(!summary.contains("DIFFER"), "{summary}");
    for figure in ["fig6", "fig7", "fig8", "fig9", "fig10", "fig12", "table1"] {
        assert!(
            summary.contains(&format!("## {figure} ")),
            "summary.md lacks {figure}"
        );
        assert!(
            svg(figure).contains("paper:"),
            "{figure}.svg has no paper figure in its caption"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_unknown_figure_is_a_usage_error() {
    let out = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(["reproduce", "fig11", "--output-dir"])
        .arg(tempfile_dir())
        .output()
        .expect("pqh runs");
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("unknown figure 'fig11'"), "{stderr}");
}

fn tempfile_dir() -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "pqh-reproduce-{}-{:?}",
        std::process::id(),
        std::thread::current().id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn docs_paper_shows_every_figure_and_the_tables_its_command_wrote() {
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let doc = std::fs::read_to_string(root.join("docs/paper.md")).unwrap();
    let summary = std::fs::read_to_string(root.join("docs/paper/summary.md")).unwrap();
    for line in summary
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| quantity"))
    {
        assert!(
            doc.contains(line),
            "docs/paper.md lacks the row the command wrote: {line}"
        );
    }
    for figure in ["fig6", "fig7", "fig8", "fig9", "fig10", "fig12", "table1"] {
        assert!(
            doc.contains(&format!("(paper/{figure}.svg)")),
            "docs/paper.md shows no {figure}"
        );
        let svg = std::fs::read_to_string(root.join(format!("docs/paper/{figure}.svg"))).unwrap();
        assert_well_formed(&svg, figure);
        assert!(root.join(format!("docs/paper/{figure}.csv")).exists());
    }
}
