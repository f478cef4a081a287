//! End-to-end tests of `pqh plan` and `pqh demo` (the planner demo).

use crate::support::run::temp;
use serde_json::Value;
use std::path::PathBuf;
use std::process::Output;

fn pqh(args: &[&str]) -> Output {
    crate::support::run::pqh(args, None)
}

/// A bar [−0.5, 0.5] × [−0.2, 0.2] × [−0.1, 0.1], counter-clockwise seen from outside.
fn bar_obj() -> PathBuf {
    let path = temp("bar.obj");
    crate::support::run::write_atomically(
        &path,
        "v -0.5 -0.2 -0.1\nv 0.5 -0.2 -0.1\nv 0.5 0.2 -0.1\nv -0.5 0.2 -0.1\n\
         v -0.5 -0.2 0.1\nv 0.5 -0.2 0.1\nv 0.5 0.2 0.1\nv -0.5 0.2 0.1\n\
         f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n\
         f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n",
    );
    path
}

#[test]
fn plan_partial_and_full_pick_the_same_best_grasp() {
    let bar = bar_obj();
    for metric in ["q1", "ows"] {
        let out = pqh(&[
            "plan",
            "--mesh",
            bar.to_str().unwrap(),
            "--samples",
            "40",
            "--metric",
            metric,
            "--json",
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let report: Value = serde_json::from_slice(&out.stdout).expect("JSON");
        assert_eq!(report["same_best"], true, "{metric}");
        assert_eq!(report["comparison"], "same", "{metric}");
        assert!(report["comparison_note"].is_null(), "{metric}");
        let (partial, full) = (&report["partial"], &report["full"]);
        assert_eq!(partial["samples"], 40);
        assert_eq!(partial["force_closure"], full["force_closure"], "{metric}");
        assert!(partial["force_closure"].as_u64().unwrap() > 0, "{metric}");
        let (a, b) = (
            partial["best"]["value"].as_f64().unwrap(),
            full["best"]["value"].as_f64().unwrap(),
        );
        assert!((a - b).abs() <= 1e-9 * b, "{metric}: {a} vs {b}");
        assert_eq!(partial["best"]["contacts"].as_array().unwrap().len(), 4);
        // The partial hulls do less work.
        assert!(
            partial["facets_created"].as_u64().unwrap() < full["facets_created"].as_u64().unwrap()
        );
    }
}

#[test]
fn plan_ranks_by_resistance_and_the_grasp_matrix_metrics() {
    let bar = bar_obj();
    for args in [
        &["--metric", "resist", "--wrench", "0,0,-1,0,0,0"][..],
        &["--metric", "isotropy"],
        &["--metric", "volume"],
    ] {
        let mut all = vec!["plan", "--mesh", bar.to_str().unwrap(), "--samples", "30"];
        all.extend_from_slice(args);
        all.push("--json");
        let out = pqh(&all);
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let report: Value = serde_json::from_slice(&out.stdout).expect("JSON");
        assert_eq!(report["metric"], args[1]);
        assert_eq!(report["same_best"], true, "{args:?}");
        assert!(report["partial"]["best"]["value"].as_f64().unwrap() > 0.0);
    }
    let out = pqh(&["plan", "--metric", "q1", "--wrench", "0,0,-1,0,0,0"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--wrench is for --metric resist"));
}

/// The reported bug: with no force-closure grasp in the compared samples (`pqh plan --metric
/// qinf` compares only the first 2 by default) the plan printed a time ratio and "same best
/// grasp: yes". One contact is never force closure, so here neither run finds a grasp: the
/// comparison must say there is nothing to compare, in the table and in JSON.
#[test]
fn plan_with_nothing_to_compare_says_so() {
    let bar = bar_obj();
    for metric in ["q1", "qinf"] {
        let args = [
            "plan",
            "--mesh",
            bar.to_str().unwrap(),
            "--contacts",
            "1",
            "--samples",
            "6",
            "--full-samples",
            "3",
            "--metric",
            metric,
        ];
        let out = pqh(&[&args[..], &["--json"]].concat());
        assert!(
            out.status.success(),
            "{metric}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let report: Value = serde_json::from_slice(&out.stdout).expect("JSON");
        assert_eq!(report["comparison"], "nothing_to_compare", "{metric}");
        assert!(report["same_best"].is_null(), "{metric}: {report}");
        assert!(report["quality_speedup"].is_null(), "{metric}: {report}");
        let note = report["comparison_note"].as_str().unwrap();
        assert!(
            note.contains("nothing to compare") && note.contains('3'),
            "{note}"
        );
        assert!(report["full"]["best"].is_null() && report["partial"]["best"].is_null());

        let out = pqh(&args);
        assert!(out.status.success(), "{metric}");
        let table = String::from_utf8_lossy(&out.stdout);
        assert!(table.contains("nothing to compare"), "{metric}: {table}");
        assert!(
            !table.contains("same best grasp") && !table.contains("full / partial"),
            "{metric}: {table}"
        );
    }
}

#[test]
fn plan_writes_a_self_contained_view() {
    let bar = bar_obj();
    let page = temp("view.html");
    let out = pqh(&[
        "plan",
        "--mesh",
        bar.to_str().unwrap(),
        "--samples",
        "30",
        "--full-samples",
        "0",
        "--output",
        page.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let html = std::fs::read_to_string(&page).expect("the view was written");
    assert!(html.contains("best by Q1") && html.contains("best by OWS"));
    assert!(
        !html.contains("http://") && !html.contains("https://"),
        "no network"
    );
}

#[test]
fn plan_rejects_bad_arguments() {
    for (args, message) in [
        (vec!["plan", "--samples", "0"], "at least 1"),
        (vec!["plan", "--friction=-1"], "--friction"),
        (vec!["plan", "--mesh", "/nonexistent/x.obj"], "x.obj"),
    ] {
        let out = pqh(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
}

#[test]
fn demo_agrees_and_writes_its_view() {
    let page = temp("demo.html");
    let out = pqh(&[
        "demo",
        "--samples",
        "40",
        "--full-samples",
        "8",
        "--output",
        page.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let metrics = report["metrics"].as_array().unwrap();
    assert_eq!(metrics.len(), 2);
    for m in metrics {
        assert_eq!(m["same_best"], true, "{m}");
        assert!(m["quality_speedup"].as_f64().unwrap() > 0.0);
    }
    assert!(
        std::fs::read_to_string(&page)
            .unwrap()
            .contains("best by OWS")
    );
}

#[test]
fn demo_on_its_defaults_shows_two_different_grasps_and_how_they_differ() {
    // The default samples and seed (the full-hull check on two samples only, to keep it short).
    let page = temp("demo-defaults.html");
    let out = pqh(&[
        "demo",
        "--full-samples",
        "2",
        "--output",
        page.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(report["bests_differ"], true, "{report}");
    let [by_q1, by_ows] = [0, 1].map(|i| &report["metrics"][i]["partial"]["best"]);
    assert_ne!(by_q1["sample"], by_ows["sample"]);
    let note = report["note"].as_str().unwrap();
    assert!(note.starts_with("The two grasps differ."), "{note}");
    // Each grasp's value under the other metric is in the note, and is no better than that
    // metric's own best (each best is the largest over the same samples).
    let number_after = |key: &str, from: &str| -> f64 {
        let rest = &from[from.find(key).unwrap_or_else(|| panic!("{key} in {from}")) + key.len()..];
        rest.split([' ', ';', '(']).next().unwrap().parse().unwrap()
    };
    let (q1_part, ows_part) = note.split_once("; the OWS-best").unwrap();
    let ows_of_q1_best = number_after("Q_OWS = ", q1_part);
    let q1_of_ows_best = number_after("Q1 = ", ows_part);
    let q1_best = by_q1["value"].as_f64().unwrap();
    let ows_best = by_ows["value"].as_f64().unwrap();
    assert!(ows_of_q1_best <= ows_best + 5e-5, "{note}");
    assert!(q1_of_ows_best <= q1_best + 5e-5, "{note}");
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(html.contains("The two grasps differ."));
}

#[test]
fn demo_from_an_empty_directory_uses_the_built_in_object() {
    // No data/ or ../shared beside it: the default object must come from the binary itself.
    let dir = std::env::temp_dir().join(format!("pqh-demo-empty-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "{dir:?} is not empty"
    );
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(["demo", "--samples", "20", "--full-samples", "4"])
        .current_dir(&dir)
        .output()
        .expect("run pqh demo");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("on built-in spot.obj (2930 vertices"),
        "not the shipped object: {stdout}"
    );
    let page = std::fs::read_to_string(dir.join("pqh-demo.html")).expect("pqh-demo.html written");
    assert!(page.contains("best by OWS"));
    std::fs::remove_dir_all(&dir).ok();
}

/// Whether `p` lies on the bar's surface (one coordinate at its half-extent, the others within).
fn on_the_bar(p: &[f64]) -> bool {
    let half = [0.5, 0.2, 0.1];
    let inside = p.iter().zip(half).all(|(x, h)| x.abs() <= h + 1e-12);
    let on_a_face = p
        .iter()
        .zip(half)
        .any(|(x, h)| (x.abs() - h).abs() <= 1e-12);
    inside && on_a_face
}

/// `pqh plan --mesh BAR --planner descent --starts 3 ARGS --json`, which must succeed: its
/// report.
fn plan_descent_on_the_bar(args: &[&str]) -> Value {
    let bar = bar_obj();
    let mut all = vec![
        "plan",
        "--mesh",
        bar.to_str().unwrap(),
        "--planner",
        "descent",
        "--starts",
        "3",
        "--json",
    ];
    all.extend_from_slice(args);
    let out = pqh(&all);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

#[test]
fn plan_descent_climbs_and_writes_a_grasp_pqh_grasp_reads() {
    let report = plan_descent_on_the_bar(&["--evaluations", "20"]);
    assert_eq!(report["planner"], "descent");
    assert_eq!(report["metric"], "q1");
    for method in ["partial", "full"] {
        let run = &report[method];
        assert_eq!(run["starts"], 3, "{method}");
        let evaluations = run["evaluations"].as_u64().unwrap();
        assert!((3..=60).contains(&evaluations), "{method}: {evaluations}");
        let best = &run["best"];
        let value = best["value"].as_f64().expect("a force-closure best");
        assert!(value > 0.0, "{method}: {value}");
        if let Some(start) = best["start_value"].as_f64() {
            assert!(value >= start, "{method}: {value} below its start {start}");
        }
        assert!(best["evaluations"].as_u64().unwrap() <= 20, "{method}");
        // The planned grasp is on the surface, with the inward normals of its faces, and
        // `pqh grasp` reads it back to the value the planner reported.
        let grasp = &best["grasp"];
        let contacts = grasp["contacts"].as_array().unwrap();
        assert_eq!(contacts.len(), 4);
        for c in contacts {
            let p: Vec<f64> = serde_json::from_value(c["position"].clone()).unwrap();
            let n: Vec<f64> = serde_json::from_value(c["normal"].clone()).unwrap();
            assert!(on_the_bar(&p), "{method}: {p:?} is off the bar");
            let axis = n.iter().position(|x| x.abs() > 0.5).unwrap();
            assert!(
                n[axis] * p[axis] < 0.0,
                "{method}: {n:?} is not inward at {p:?}"
            );
        }
        let line = serde_json::to_string(grasp).unwrap();
        let again = crate::support::run::pqh(&["grasp", "-", "--method", method], Some(&line));
        assert!(again.status.success());
        let evaluated: Value = serde_json::from_slice(&again.stdout).unwrap();
        let q = evaluated["quality"].as_f64().unwrap();
        assert!(
            (q - value).abs() <= 1e-12 * value,
            "{method}: {q} vs {value}"
        );
    }
    assert!(report["quality_speedup"].as_f64().unwrap() > 0.0);
    assert!(report["same_best"].is_boolean());
}

#[test]
fn plan_descent_refuses_what_it_cannot_do() {
    let bar = bar_obj();
    let mesh = bar.to_str().unwrap();
    for (args, says) in [
        (&["--metric", "volume"][..], "--planner descent climbs"),
        (
            &["--output", "x.html"],
            "--output draws the sampler's plans",
        ),
        (&["--evaluations", "1"], "--evaluations"),
        (&["--starts", "0"], "--starts"),
        (&["--starts", "100001"], "--starts"),
        (&["--screen", "0"], "--screen"),
        (&["--screen", "10001"], "--screen"),
    ] {
        let mut all = vec!["plan", "--mesh", mesh, "--planner", "descent"];
        all.extend_from_slice(args);
        let out = pqh(&all);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(says), "{args:?}: {stderr}");
    }
}

/// `--screen` reaches the planner: screened runs spend their evaluations (all but a few) and
/// end elsewhere (on the bar, higher: 0.311 against 0.170 here).
#[test]
fn plan_descent_screens_its_starts() {
    let spent = |screen: &str| {
        let report = plan_descent_on_the_bar(&[
            "--evaluations",
            "30",
            "--screen",
            screen,
            "--full-samples",
            "0",
        ]);
        let run = &report["partial"];
        let best = run["best"]["value"].as_f64().expect("a force-closure best");
        (run["evaluations"].as_u64().unwrap(), best)
    };
    let (plain, screened) = (spent("1"), spent("6"));
    assert!(
        screened.0 >= 3 * 28,
        "screened runs used {} of 90",
        screened.0
    );
    assert!(
        screened.1 > plain.1,
        "{plain:?} unscreened against {screened:?}"
    );
}
