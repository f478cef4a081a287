//! `pqh grasp --metric resist|volume|sigma-min|isotropy` and `--cone-bracket`: the same line
//! shape as every metric, resist equal to `--metric ows --disturbances` with that one row, and
//! options that would be ignored refused.

use serde_json::Value;
use std::process::Command;

fn pqh(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(args)
        .output()
        .expect("pqh runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn lines(stdout: &str) -> Vec<Value> {
    stdout
        .lines()
        .map(|l| serde_json::from_str(l).expect("a JSON line"))
        .collect()
}

const SAMPLE: &str = concat!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/.."),
    "/data/grasps/sample.jsonl"
);

#[test]
fn resist_equals_ows_with_that_single_disturbance() {
    let dir = std::env::temp_dir().join(format!("pqh-cli-metrics-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let rows = dir.join("gravity.txt");
    std::fs::write(&rows, "0.1, -0.2, -1, 0.05, 0, 0.02\n").unwrap();
    let (ok, resist, err) = pqh(&[
        "grasp",
        "--quiet",
        "--metric",
        "resist",
        "--wrench",
        "0.1,-0.2,-1,0.05,0,0.02",
        SAMPLE,
    ]);
    assert!(ok, "{err}");
    let (ok, ows, err) = pqh(&[
        "grasp",
        "--quiet",
        "--metric",
        "ows",
        "--disturbances",
        rows.to_str().unwrap(),
        SAMPLE,
    ]);
    assert!(ok, "{err}");
    let (a, b) = (lines(&resist), lines(&ows));
    assert_eq!(a.len(), 4);
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x["quality"], y["quality"]);
        assert_eq!(x["force_closure"], y["force_closure"]);
    }
    assert!(a.iter().any(|l| l["quality"].is_f64()));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_metric_has_the_same_line_shape_and_the_bracket_holds_q1() {
    let (_, q1, _) = pqh(&["grasp", "--quiet", SAMPLE]);
    let q1 = lines(&q1);
    for metric in ["volume", "sigma-min", "isotropy"] {
        let (ok, out, err) = pqh(&["grasp", "--quiet", "--metric", metric, SAMPLE]);
        assert!(ok, "{metric}: {err}");
        for (line, reference) in lines(&out).iter().zip(&q1) {
            for key in ["index", "force_closure", "quality", "stats"] {
                assert!(line.get(key).is_some(), "{metric}: no {key} in {line}");
            }
            assert!(line["quality"].as_f64().unwrap() >= 0.0, "{metric}: {line}");
            assert_eq!(
                line["force_closure"], reference["force_closure"],
                "{metric}"
            );
        }
    }
    let (ok, out, err) = pqh(&["grasp", "--quiet", "--cone-bracket", SAMPLE]);
    assert!(ok, "{err}");
    for (line, reference) in lines(&out).iter().zip(&q1) {
        assert_eq!(line["quality"], reference["quality"]);
        let b = line["bracket"].as_array().expect("a bracket");
        let (low, high) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
        let q = line["quality"].as_f64().unwrap();
        assert!(low <= q && q <= high, "{line}");
    }
}

#[test]
fn options_that_would_be_ignored_are_refused() {
    for (args, message) in [
        (&["--metric", "resist"][..], "needs --wrench"),
        (&["--metric", "resist", "--wrench", "1,2,3"], "6 numbers"),
        (
            &["--wrench", "0,0,-1,0,0,0"],
            "--wrench is for --metric resist",
        ),
        (
            &["--metric", "qinf", "--cone-bracket"],
            "--cone-bracket is for --metric q1",
        ),
        (
            &["--metric", "volume", "--method", "partial-rays"],
            "--metric volume takes --method partial, full, qhull",
        ),
        (
            &["--metric", "resist", "--wrench", "0,0,0,0,0,0"],
            "the wrench to resist is zero",
        ),
    ] {
        let mut all = vec!["grasp"];
        all.extend_from_slice(args);
        all.push(SAMPLE);
        let (ok, _, err) = pqh(&all);
        assert!(!ok && err.contains(message), "{args:?}: {err}");
    }
}

#[test]
fn for_the_volume_and_grasp_matrix_metrics_the_method_decides_the_verdict_only() {
    let (_, full_q1, _) = pqh(&["grasp", "--quiet", "--method", "full", SAMPLE]);
    let full_q1 = lines(&full_q1);
    for metric in ["volume", "isotropy"] {
        let (_, partial, _) = pqh(&["grasp", "--quiet", "--metric", metric, SAMPLE]);
        let (ok, full, err) = pqh(&[
            "grasp", "--quiet", "--metric", metric, "--method", "full", SAMPLE,
        ]);
        assert!(ok, "{err}");
        for ((p, f), q) in lines(&partial).iter().zip(&lines(&full)).zip(&full_q1) {
            assert_eq!(p["quality"], f["quality"], "{metric}");
            assert_eq!(f["force_closure"], q["force_closure"], "{metric}");
        }
    }
}

/// `--gradient`: each line carries the library's gradient of its Q1, field by field; other
/// metrics refuse the option.
#[test]
fn gradient_lines_are_the_librarys_gradient() {
    use pqhull::grasp::json::parse_grasp;
    use pqhull::grasp::{Evaluator, Method, Metric};
    let grasp = r#"{"contacts":[
        {"position":[0.9,0.1,0.2],"normal":[-0.9,-0.1,-0.2]},
        {"position":[-0.8,0.3,0.1],"normal":[0.8,-0.3,-0.1],"tangent":[0.1,1.0,0.3]},
        {"position":[0.2,-0.9,0.3],"normal":[-0.2,0.9,-0.3]},
        {"position":[0.1,0.2,-0.95],"normal":[-0.1,-0.2,0.95],"torsion":0.02}],
        "friction":0.6,"cone_edges":6}"#
        .replace('\n', " ");
    let path = crate::support::run::file("gradient-grasp.json", &grasp);
    let (ok, stdout, stderr) = pqh(&["grasp", path.to_str().unwrap(), "--gradient", "--quiet"]);
    assert!(ok, "{stderr}");
    let line = &lines(&stdout)[0];
    let parsed = parse_grasp(&serde_json::from_str(&grasp).unwrap()).unwrap();
    let quality = Evaluator::new(Metric::Q1, Method::Partial, None)
        .unwrap()
        .evaluate(&parsed)
        .unwrap();
    let expected = pqhull::grasp::q1_gradient(&parsed, &quality).unwrap();
    assert_eq!(line["quality"].as_f64(), Some(quality.value.unwrap()));
    let gradient = &line["gradient"];
    assert_eq!(gradient["positions"], serde_json::json!(expected.positions));
    assert_eq!(gradient["normals"], serde_json::json!(expected.normals));
    assert_eq!(gradient["friction"].as_f64(), Some(expected.friction));
    assert_eq!(gradient["differentiable"], expected.differentiable);
    assert!(expected.differentiable, "a generic grasp: {gradient}");
    // Q∞ too, with the library's Q∞ gradient; the other metrics refuse the option.
    let (ok, stdout, stderr) = pqh(&[
        "grasp",
        path.to_str().unwrap(),
        "--gradient",
        "--metric",
        "qinf",
        "--quiet",
    ]);
    assert!(ok, "{stderr}");
    let metric = Metric::QInf {
        with_zero_wrench: false,
    };
    let qinf = Evaluator::new(metric, Method::Partial, None)
        .unwrap()
        .evaluate(&parsed)
        .unwrap();
    let expected = pqhull::grasp::qinf_gradient(&parsed, &qinf).unwrap();
    assert_eq!(
        lines(&stdout)[0]["gradient"]["positions"],
        serde_json::json!(expected.positions)
    );
    // Q_OWS against a task wrench space, by the library's gradient; the ellipsoid refuses.
    let rows = "0 0 -1 0 0 0\n0.3 0 0 0 0.1 0\n0 0.2 0.1 0.05 0 0\n";
    let space_path = crate::support::run::file("gradient-disturbances.txt", rows);
    let space = pqhull::grasp::ows::ObjectWrenchSpace::from_disturbances(vec![
        [0.0, 0.0, -1.0, 0.0, 0.0, 0.0],
        [0.3, 0.0, 0.0, 0.0, 0.1, 0.0],
        [0.0, 0.2, 0.1, 0.05, 0.0, 0.0],
    ])
    .unwrap();
    let ows = Evaluator::new(Metric::Ows, Method::Partial, Some(&space))
        .unwrap()
        .evaluate(&parsed)
        .unwrap();
    let expected = pqhull::grasp::ows_gradient(&parsed, &space, &ows).expect("force closure");
    let ows_args = [
        "grasp",
        path.to_str().unwrap(),
        "--gradient",
        "--metric",
        "ows",
        "--disturbances",
        space_path.to_str().unwrap(),
        "--quiet",
    ];
    let (ok, stdout, stderr) = pqh(&ows_args);
    assert!(ok, "{stderr}");
    assert_eq!(
        lines(&stdout)[0]["gradient"]["normals"],
        serde_json::json!(expected.normals)
    );
    let mut ellipsoid = ows_args.to_vec();
    ellipsoid.extend(["--method", "ellipsoid"]);
    let (ok, _, stderr) = pqh(&ellipsoid);
    assert!(
        !ok && stderr.contains("--gradient needs an exact method"),
        "{stderr}"
    );
    let (ok, _, stderr) = pqh(&[
        "grasp",
        path.to_str().unwrap(),
        "--gradient",
        "--metric",
        "volume",
    ]);
    assert!(
        !ok && stderr.contains("--gradient is computed for --metric q1, qinf and ows"),
        "{stderr}"
    );
}
