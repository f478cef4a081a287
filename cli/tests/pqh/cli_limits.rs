//! Hostile and extreme input to `pqh` (issue 12): sizes beyond the documented limits are refused
//! with one clear error before anything is allocated, a bad grasp in a batch gets its own error
//! line, and exit statuses and messages follow docs/limits.md. Every input is built here; no test
//! allocates more than a few megabytes or runs more than a moment.

use crate::support::run::{file, pqh, temp};
use pqhull::grasp::{MAX_CONE_EDGES, MAX_CONTACTS};
use pqhull::plan::MAX_SAMPLES;
use serde_json::Value;
use std::process::{Command, Output, Stdio};

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Asserts the run failed with `code` and printed exactly one `pqh: error: ` line on stderr;
/// returns it.
fn one_error_line(o: &Output, code: i32) -> String {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(code), "stderr: {err}");
    assert_eq!(err.lines().count(), 1, "stderr: {err:?}");
    assert!(err.starts_with("pqh: error: "), "stderr: {err:?}");
    err.trim_end().to_string()
}

/// [`one_error_line`], and nothing on stdout.
fn only_error(o: &Output, code: i32) -> String {
    let line = one_error_line(o, code);
    assert!(o.stdout.is_empty(), "stdout: {}", stdout(o));
    line
}

/// One JSON value per stdout line.
fn json_lines(o: &Output) -> Vec<Value> {
    stdout(o)
        .lines()
        .map(|l| serde_json::from_str(l).expect("each line is JSON"))
        .collect()
}

/// Four contacts pinching a box, with `cone_edges` written as given (any JSON text).
fn grasp_with_edges(cone_edges: &str) -> String {
    format!(
        "{{\"contacts\":[{{\"position\":[-0.5,0.1,0],\"normal\":[1,0,0]}},\
         {{\"position\":[0.5,-0.1,0],\"normal\":[-1,0,0]}},\
         {{\"position\":[0,-0.5,0.2],\"normal\":[0,1,0]}},\
         {{\"position\":[0.1,0.5,-0.2],\"normal\":[0,-1,0]}}],\
         \"friction\":0.5,\"cone_edges\":{cone_edges}}}"
    )
}

/// The batch of the issue: a good grasp, then every kind of bad `cone_edges`, then a good one.
const EDGES: [&str; 9] = [
    "8",
    "1e12",
    "-3",
    "2.5",
    "1e400",
    "18446744073709551615",
    "1025",
    "\"8\"",
    "16",
];

/// Checks the output lines of the [`EDGES`] batch: the good grasps evaluated, every bad one an
/// error naming the field and the limit.
fn check_edges_batch(o: &Output) {
    assert!(o.status.success(), "{}", stderr(o));
    let lines = json_lines(o);
    assert_eq!(lines.len(), EDGES.len());
    for (i, (line, edges)) in lines.iter().zip(EDGES).enumerate() {
        assert_eq!(line["index"], i);
        if edges == "8" || edges == "16" {
            assert_eq!(line["force_closure"], true, "{line}");
            assert!(line["quality"].as_f64().unwrap() > 0.0, "{line}");
        } else {
            let error = line["error"].as_str().expect("an error line");
            assert!(error.contains("\"cone_edges\""), "{edges}: {error}");
            assert!(
                error.contains(&MAX_CONE_EDGES.to_string()),
                "{edges}: {error}"
            );
        }
    }
}

#[test]
fn bad_cone_edges_in_json_lines_get_their_own_error_lines() {
    let batch: Vec<String> = EDGES.iter().map(|e| grasp_with_edges(e)).collect();
    let o = pqh(&["grasp", "--threads", "1"], Some(&batch.join("\n")));
    check_edges_batch(&o);
    let lines = json_lines(&o);
    assert!(
        lines[1]["error"].as_str().unwrap().contains("too many"),
        "{}",
        lines[1]
    );
    assert!(
        lines[2]["error"]
            .as_str()
            .unwrap()
            .contains("not a whole number"),
        "{}",
        lines[2]
    );
}

#[test]
fn bad_cone_edges_in_a_json_array_get_their_own_error_lines() {
    // One line, so a number out of f64's range cannot be isolated by lines: the array is split
    // into its elements.
    let batch: Vec<String> = EDGES.iter().map(|e| grasp_with_edges(e)).collect();
    let o = pqh(&["grasp"], Some(&format!("[{}]", batch.join(","))));
    check_edges_batch(&o);
    // Pretty-printed over several lines, too.
    let o = pqh(
        &["grasp"],
        Some(&format!("[\n  {}\n]\n", batch.join(",\n  "))),
    );
    check_edges_batch(&o);
}

#[test]
fn too_many_contacts_is_a_per_grasp_error() {
    let contact = "{\"position\":[0.1,0,0],\"normal\":[-1,0,0]}";
    let many = vec![contact; MAX_CONTACTS + 1].join(",");
    let bad = format!("{{\"contacts\":[{many}],\"friction\":0.5,\"cone_edges\":4}}");
    let o = pqh(
        &["grasp"],
        Some(&format!("{bad}\n{}\n", grasp_with_edges("4"))),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let lines = json_lines(&o);
    let error = lines[0]["error"].as_str().expect("an error line");
    assert!(
        error.contains("contacts") && error.contains(&MAX_CONTACTS.to_string()),
        "{error}"
    );
    assert_eq!(lines[1]["force_closure"], true);
}

#[test]
fn input_without_a_readable_grasp_is_an_error() {
    for input in ["", "  \n\n", "[]"] {
        let err = only_error(&pqh(&["grasp"], Some(input)), 2);
        assert!(err.contains("no grasp"), "{input:?}: {err}");
    }
    // Every grasp malformed: the error lines, then exit 2.
    let o = pqh(&["grasp"], Some("garbage\n{\"contacts\":[]}\n"));
    let err = one_error_line(&o, 2);
    assert!(err.contains("none of the 2 grasps"), "{err}");
    let lines = json_lines(&o);
    assert_eq!(lines.len(), 2);
    assert!(lines.iter().all(|l| l["error"].is_string()), "{lines:?}");
    // One readable grasp is enough for success.
    let o = pqh(
        &["grasp"],
        Some(&format!("garbage\n{}\n", grasp_with_edges("4"))),
    );
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn thread_counts_are_bounded() {
    for (threads, needle) in [("10000", "at most 256"), ("0", "at least 1")] {
        let o = pqh(
            &["grasp", "--threads", threads],
            Some(&grasp_with_edges("4")),
        );
        let err = only_error(&o, 2);
        assert!(err.contains("--threads") && err.contains(needle), "{err}");
    }
    let err = only_error(&pqh(&["bench", "gws", "--threads", "1,300"], None), 2);
    assert!(
        err.contains("--threads") && err.contains("at most 256"),
        "{err}"
    );
}

#[test]
fn size_options_are_refused_before_any_work() {
    let huge = "18446744073709551616"; // u64::MAX + 1
    let edges_limit = MAX_CONE_EDGES.to_string();
    let contacts_limit = MAX_CONTACTS.to_string();
    let samples_limit = MAX_SAMPLES.to_string();
    let cases: Vec<(Vec<&str>, &str, &str)> = vec![
        (
            vec!["plan", "--edges", "1000000000000"],
            "--edges",
            &edges_limit,
        ),
        (vec!["plan", "--edges", huge], "--edges", &edges_limit),
        (
            vec!["plan", "--contacts", "100000"],
            "--contacts",
            &contacts_limit,
        ),
        (
            vec!["plan", "--samples", "10000000"],
            "--samples",
            &samples_limit,
        ),
        (vec!["plan", "--edges=-3"], "--edges", "whole number"),
        (vec!["plan", "--edges", "2.5"], "--edges", "whole number"),
        (
            vec!["bench", "gws", "--edges", "4,100000000"],
            "--edges",
            &edges_limit,
        ),
        (
            vec!["bench", "gws", "--contacts", "1000"],
            "--contacts",
            &contacts_limit,
        ),
        (vec!["bench", "gws", "--grasps", huge], "--grasps", "100000"),
        (
            vec!["bench", "ows", "--edges", "1000000000000"],
            "--edges",
            &edges_limit,
        ),
        (
            vec!["bench", "ows", "--grasps", "100000000"],
            "--grasps",
            "100000",
        ),
        (
            vec!["demo", "--samples", "100000000"],
            "--samples",
            &samples_limit,
        ),
        (
            vec!["grasp", "--metric", "ows", "--ows-edges", huge],
            "--ows-edges",
            &edges_limit,
        ),
    ];
    for (args, option, limit) in cases {
        let o = pqh(&args, Some(&grasp_with_edges("4")));
        let err = only_error(&o, 2);
        assert!(
            err.contains(option) && err.contains(limit),
            "{args:?}: {err}"
        );
    }
}

#[test]
fn limits_are_in_the_help() {
    let o = pqh(&["grasp", "--help"], None);
    assert!(o.status.success());
    let help = stdout(&o);
    for needle in [
        MAX_CONE_EDGES.to_string(),
        MAX_CONTACTS.to_string(),
        "limits".into(),
    ] {
        assert!(help.contains(&needle), "missing {needle}: {help}");
    }
    for (args, needle) in [
        (vec!["plan", "--help"], MAX_SAMPLES.to_string()),
        (vec!["plan", "--help"], MAX_CONE_EDGES.to_string()),
        (vec!["demo", "--help"], MAX_SAMPLES.to_string()),
        (vec!["bench", "gws", "--help"], MAX_CONTACTS.to_string()),
        (vec!["bench", "ows", "--help"], MAX_CONE_EDGES.to_string()),
    ] {
        let o = pqh(&args, None);
        assert!(o.status.success(), "{args:?}");
        assert!(stdout(&o).contains(&needle), "{args:?} lacks {needle}");
    }
    let o = pqh(&["--help"], None);
    assert!(stdout(&o).contains("pqh: error: ") && stdout(&o).contains("docs/limits.md"));
}

#[test]
fn usage_errors_are_one_line_with_a_hint() {
    for (args, needle, hint) in [
        (
            vec!["hull", "--strategy", "nearest"],
            "nearest",
            "pqh hull --help",
        ),
        (
            vec!["hull", "--no-such-option"],
            "--no-such-option",
            "pqh hull --help",
        ),
        (vec![], "subcommand", "pqh --help"),
        (vec!["bench"], "subcommand", "pqh bench --help"),
        (vec!["frobnicate"], "frobnicate", "pqh --help"),
        (
            vec!["bench", "gws", "--edges", "x"],
            "--edges",
            "pqh bench gws --help",
        ),
    ] {
        let err = only_error(&pqh(&args, None), 2);
        assert!(
            err.contains(needle) && err.contains(hint),
            "{args:?}: {err}"
        );
    }
    // Help and version still succeed, on stdout.
    for args in [vec!["--version"], vec!["hull", "--help"], vec!["help"]] {
        let o = pqh(&args, None);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        assert!(!o.stdout.is_empty() && o.stderr.is_empty(), "{args:?}");
    }
}

#[test]
fn exit_statuses_follow_the_table() {
    // 1: the points admit no hull.
    let err = only_error(&pqh(&["hull"], Some("0 0\n1 1\n2 2\n")), 1);
    assert!(err.contains("affinely dependent"), "{err}");
    // 2: input error.
    let err = only_error(&pqh(&["hull"], Some("0 0\n1 x\n")), 2);
    assert!(err.contains("line 2"), "{err}");
    // 2: usage error.
    let err = only_error(
        &pqh(
            &["hull", "--strategy", "closest-to-origin", "--origin=1,,2"],
            Some("0 0\n1 0\n0 1\n"),
        ),
        2,
    );
    assert!(err.contains("--query") && err.contains("field 2"), "{err}");
}

#[test]
fn lone_carriage_returns_end_lines() {
    let o = pqh(
        &["hull", "--json"],
        Some("-1 -1\r1 -1\r1 1\r-1 1\r0.2 0.1\r"),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(
        (v["dimension"].clone(), v["points"].clone()),
        (2.into(), 5.into())
    );
    assert!((v["volume"].as_f64().unwrap() - 4.0).abs() < 1e-12);
    // Line numbers count them.
    let err = only_error(&pqh(&["hull"], Some("0 0\r1 0\r1 x\r")), 2);
    assert!(err.contains("line 3"), "{err}");
}

/// Runs `pqh args` with its stdout's reading end closed at once: every write gets a broken pipe.
fn with_closed_stdout(args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn pqh");
    drop(child.stdout.take());
    child.wait_with_output().expect("wait for pqh")
}

/// A regular octahedron of radius 0.5 (8 outward triangles), as OBJ.
const OCTAHEDRON: &str = "\
v 0.5 0 0\nv -0.5 0 0\nv 0 0.5 0\nv 0 -0.5 0\nv 0 0 0.5\nv 0 0 -0.5
f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6
";

#[test]
fn broken_pipes_end_quietly() {
    let page = temp("pipe-demo.html");
    let mesh = file("octahedron.obj", OCTAHEDRON);
    for args in [
        vec![
            "bench",
            "ows",
            "--mesh",
            mesh.to_str().unwrap(),
            "--edges",
            "4",
            "--grasps",
            "2",
            "--brute-grasps",
            "1",
            "--rays-grasps",
            "1",
        ],
        vec![
            "bench",
            "gws",
            "--grasps",
            "2",
            "--edges",
            "4",
            "--batch-rounds",
            "0",
        ],
        // Still printed with println! (demo_cmd.rs): caught by the panic hook.
        vec![
            "demo",
            "--samples",
            "3",
            "--full-samples",
            "1",
            "--output",
            page.to_str().unwrap(),
        ],
    ] {
        let o = with_closed_stdout(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        assert!(o.stderr.is_empty(), "{args:?}: {}", stderr(&o));
    }
}

#[test]
fn write_errors_exit_2() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        eprintln!("no /dev/full on this system: nothing to check");
        return;
    };
    let square = file("square.txt", "0 0\n1 0\n1 1\n0 1\n");
    let page = temp("full-demo.html");
    for args in [
        vec!["hull", square.to_str().unwrap()],
        vec![
            "bench",
            "gws",
            "--grasps",
            "2",
            "--edges",
            "4",
            "--batch-rounds",
            "0",
        ],
        vec![
            "demo",
            "--samples",
            "3",
            "--full-samples",
            "1",
            "--output",
            page.to_str().unwrap(),
        ],
    ] {
        let o = Command::new(env!("CARGO_BIN_EXE_pqh"))
            .args(&args)
            .stdin(Stdio::null())
            .stdout(full.try_clone().expect("dup /dev/full"))
            .stderr(Stdio::piped())
            .output()
            .expect("run pqh");
        let err = one_error_line(&o, 2);
        assert!(err.contains("cannot write output"), "{args:?}: {err}");
    }
}

#[test]
fn demo_fails_when_its_view_cannot_be_written() {
    let o = pqh(
        &[
            "demo",
            "--samples",
            "3",
            "--full-samples",
            "1",
            "--output",
            "/nonexistent-pqh-dir/x.html",
        ],
        None,
    );
    let err = one_error_line(&o, 2);
    assert!(err.contains("x.html"), "{err}");
}

#[test]
fn notes_on_stderr_are_not_errors() {
    // Six unit disturbances: a task wrench space.
    let mut rows = String::new();
    for axis in 0..6 {
        let row: Vec<&str> = (0..6)
            .map(|i| if i == axis { "0.1" } else { "0" })
            .collect();
        rows.push_str(&row.join(" "));
        rows.push('\n');
    }
    let task = file("task.txt", &rows);
    let o = pqh(
        &[
            "grasp",
            "--metric",
            "ows",
            "--disturbances",
            task.to_str().unwrap(),
        ],
        Some(&grasp_with_edges("8")),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(!err.is_empty());
    for line in err.lines() {
        assert!(line.starts_with("pqh: note: "), "{line}");
    }
}

#[test]
fn full_qinf_of_a_large_minkowski_sum_needs_force() {
    // Two antipodal contacts × 65 edges: 4,225 Minkowski points (> 4,096), quick to hull.
    let grasp = r#"{"contacts":[{"position":[1,0,0],"normal":[-1,0,0]},{"position":[-1,0,0],"normal":[1,0,0]}],"friction":0.5,"cone_edges":65}"#;
    let refused = pqh(
        &["grasp", "--metric", "qinf", "--method", "full"],
        Some(grasp),
    );
    assert_eq!(refused.status.code(), Some(2));
    let err = String::from_utf8_lossy(&refused.stderr);
    assert!(
        err.contains("grasp 0") && err.contains("4225 Minkowski points") && err.contains("--force"),
        "{err}"
    );
    assert!(
        refused.stdout.is_empty(),
        "nothing evaluated before the refusal"
    );
    let forced = pqh(
        &["grasp", "--metric", "qinf", "--method", "full", "--force"],
        Some(grasp),
    );
    assert!(
        forced.status.success(),
        "{}",
        String::from_utf8_lossy(&forced.stderr)
    );
    let partial = pqh(&["grasp", "--metric", "qinf"], Some(grasp));
    let value = |o: &std::process::Output| -> serde_json::Value {
        serde_json::from_slice::<serde_json::Value>(&o.stdout).unwrap()["quality"].clone()
    };
    assert_eq!(value(&forced), value(&partial));
    // The partial method and Q1 never need it.
    assert!(
        pqh(
            &["grasp", "--metric", "q1", "--method", "full"],
            Some(grasp)
        )
        .status
        .success()
    );
}

#[test]
fn a_method_a_metric_does_not_take_is_a_usage_error() {
    let grasp = r#"{"contacts":[{"position":[1,0,0],"normal":[-1,0,0]},{"position":[-1,0,0],"normal":[1,0,0]}],"friction":0.5,"cone_edges":8}"#;
    let o = pqh(
        &["grasp", "--metric", "q1", "--method", "ellipsoid"],
        Some(grasp),
    );
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("--metric q1 takes --method partial, full, qhull, not ellipsoid"),
        "{err}"
    );
    // bench gws lists only the methods that compute Q1.
    let help = String::from_utf8(pqh(&["bench", "gws", "-h"], None).stdout).unwrap();
    let methods = help
        .lines()
        .find(|l| l.contains("--methods"))
        .unwrap()
        .to_string();
    assert!(
        methods.contains("[possible values: partial, full, qhull]"),
        "{methods}"
    );
}
