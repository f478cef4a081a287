//! `pqh trace`: its errors, its pages and pictures.

use pqhull::rbox::{Family, generate};
use pqhull::viz::html;
use pqhull::{FarthestPoint, Hull};
use std::collections::BTreeSet;
use std::path::PathBuf;
use std::process::{Command, Output};

// ---- the `pqh trace` command ----------------------------------------------------------------

fn pqh(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(args)
        .output()
        .expect("run pqh")
}

fn temp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("trace-tests");
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Exit status 2 (or `code`) and one `pqh: ` line on stderr containing `needle`.
fn assert_error(o: &Output, code: i32, needle: &str) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(code), "stderr: {err}");
    assert!(
        err.starts_with("pqh: ") && err.lines().count() == 1,
        "stderr: {err:?}"
    );
    assert!(err.contains(needle), "stderr {err:?} lacks {needle:?}");
}

#[test]
fn malformed_inputs_and_options_are_cli_errors() {
    let out = temp("unused.html");
    let out = out.to_str().unwrap();
    let bad = temp("bad.txt");
    std::fs::write(&bad, "0 0\n1 0\n1 x\n").unwrap();
    let o = pqh(&[
        "trace",
        bad.to_str().unwrap(),
        "--strategy",
        "farthest",
        "--output",
        out,
    ]);
    assert_error(&o, 2, "line 3");

    let four = temp("four.txt");
    std::fs::write(&four, "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n").unwrap();
    let o = pqh(&[
        "trace",
        four.to_str().unwrap(),
        "--strategy",
        "farthest",
        "--output",
        out,
    ]);
    assert_error(&o, 2, "2-D and 3-D");

    let line = temp("line.txt");
    std::fs::write(&line, "0 0\n1 1\n2 2\n3 3\n").unwrap();
    let o = pqh(&[
        "trace",
        line.to_str().unwrap(),
        "--strategy",
        "closest",
        "--output",
        out,
    ]);
    assert_error(&o, 1, "line.txt");

    let usage: [&[&str]; 6] = [
        &["trace", "--strategy", "farthest", "--output", out],
        &[
            "trace",
            "x.txt",
            "--family",
            "cube",
            "--strategy",
            "farthest",
            "--output",
            out,
        ],
        &[
            "trace",
            "--family",
            "cube",
            "--strategy",
            "farthest",
            "--query",
            "0,0",
            "--output",
            out,
        ],
        &[
            "trace",
            "--family",
            "nope",
            "--strategy",
            "farthest",
            "--output",
            out,
        ],
        &[
            "trace",
            "--family",
            "cube",
            "--dimension",
            "5",
            "--strategy",
            "ows",
            "--output",
            out,
        ],
        &[
            "trace",
            "--family",
            "cube",
            "--strategy",
            "closest",
            "--query",
            "1,2",
            "--output",
            out,
        ],
    ];
    for args in usage {
        let o = pqh(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(
            stderr(&o).starts_with("pqh: ") || stderr(&o).contains("error:"),
            "{args:?}"
        );
    }
    let o = pqh(&[
        "trace",
        "--family",
        "cube",
        "--dimension",
        "3",
        "--strategy",
        "farthest",
        "--svg-dir",
        out,
        "--output",
        out,
    ]);
    assert_error(&o, 2, "2-D");
}

/// The page must load nothing: no URL of any scheme but inline data, no external script, style
/// sheet, image or font.
fn assert_no_network(page: &str) {
    let lower = page.to_lowercase();
    for needle in [
        "http://",
        "https://",
        "src=",
        "<link",
        "url(",
        "@import",
        "//cdn",
        "fetch(",
        "xmlhttprequest",
    ] {
        assert!(!lower.contains(needle), "the page contains {needle:?}");
    }
}

#[test]
fn pages_are_self_contained_and_svgs_are_written() {
    let html_path = temp("two-d.html");
    let svg_dir = temp("svg");
    let _ = std::fs::remove_dir_all(&svg_dir);
    let o = pqh(&[
        "trace",
        "--family",
        "sphere",
        "--points",
        "25",
        "--dimension",
        "2",
        "--seed",
        "3",
        "--strategy",
        "closest",
        "--query",
        "0.8,0.1",
        "--compare",
        "ows",
        "--output",
        html_path.to_str().unwrap(),
        "--svg-dir",
        svg_dir.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("(query outside)") && stdout.contains("smallest inflation factor"),
        "{stdout}"
    );
    let page = std::fs::read_to_string(&html_path).unwrap();
    assert_no_network(&page);
    // The embedded data is the traces' JSON, one panel per strategy.
    let start = page.find("id=\"pqhull-data\">").unwrap() + "id=\"pqhull-data\">".len();
    let end = start + page[start..].find("</script>").unwrap();
    let data: serde_json::Value = serde_json::from_str(&page[start..end]).unwrap();
    let panels = data["panels"].as_array().unwrap();
    assert_eq!(panels.len(), 2);
    assert_eq!(panels[0]["trace"]["strategy"], "ClosestToOrigin");
    assert_eq!(panels[1]["trace"]["strategy"], "OwsInflation");
    let files: BTreeSet<String> = std::fs::read_dir(&svg_dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    for (k, panel) in panels.iter().enumerate() {
        let name = ["closest-to-origin", "ows-inflation"][k];
        let steps = panel["trace"]["events"].as_array().unwrap().len();
        let count = files.iter().filter(|f| f.starts_with(name)).count();
        assert_eq!(count, steps, "{name}: one SVG per step");
        let first = std::fs::read_to_string(svg_dir.join(format!("{name}-0000.svg"))).unwrap();
        assert!(first.starts_with("<svg") && first.contains("initial simplex"));
    }

    // A 3-D page from a points file, through standard naming of the library too.
    let points = temp("cube3.txt");
    let text: String = generate::<3>(&Family::UniformCube, 30, 4)
        .iter()
        .map(|p| format!("{} {} {}\n", p[0], p[1], p[2]))
        .collect();
    std::fs::write(&points, text).unwrap();
    let out = temp("three-d.html");
    let o = pqh(&[
        "trace",
        points.to_str().unwrap(),
        "--strategy",
        "farthest",
        "--output",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_no_network(&std::fs::read_to_string(&out).unwrap());
}

#[test]
fn titles_and_text_are_escaped() {
    let points = generate::<2>(&Family::UniformCube, 20, 1);
    let (_, (), trace) = Hull::try_with_strategy_traced(&points, FarthestPoint::new()).unwrap();
    let page = html::trace_page("<script>alert(1)</script>", &[&trace]).unwrap();
    assert!(!page.contains("<script>alert(1)"));
    assert!(page.contains("&lt;script&gt;alert(1)"));
    let mut evil = trace.clone();
    evil.context.strategy = "</script><script>alert(2)</script>".into();
    let page = html::trace_page("t", &[&evil]).unwrap();
    assert!(!page.contains("</script><script>alert(2)"));
}
