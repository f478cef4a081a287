//! End-to-end tests of `pqh grasp --metric ows` (the object wrench space metric).

use crate::support::run::file;
use serde_json::Value;
use std::process::Output;

/// `pqh` with `stdin`.
fn pqh(args: &[&str], stdin: &str) -> Output {
    crate::support::run::pqh(args, Some(stdin))
}

fn lines(output: &Output) -> Vec<Value> {
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).expect("JSON line"))
        .collect()
}

/// The cube [−1, 1]³ grasped at the centres of its x and y faces, tangents along z (see
/// tests/ows.rs for the hand derivation of its value against the disturbances below).
const FOUR_FACES: &str = r#"{"contacts":[
  {"position":[-1,0,0],"normal":[1,0,0],"tangent":[0,0,1]},
  {"position":[1,0,0],"normal":[-1,0,0],"tangent":[0,0,1]},
  {"position":[0,-1,0],"normal":[0,1,0],"tangent":[0,0,1]},
  {"position":[0,1,0],"normal":[0,-1,0],"tangent":[0,0,1]}],
  "friction":0.5,"cone_edges":8}"#;

const PINCH: &str = r#"{"contacts":[
  {"position":[-1,0,0],"normal":[1,0,0]},{"position":[1,0,0],"normal":[-1,0,0]}],
  "friction":0.5,"cone_edges":8}"#;

/// A force along +x, a force along +z, twice a unit torque about z: Q_OWS = μ/2 = 0.25.
const TASK: &str = "# fx fy fz tx ty tz\n1 0 0 0 0 0\n0,0,1,0,0,0\n0 0 0 0 0 2\n";

/// The cube [−1, 1]³, counter-clockwise seen from outside.
const CUBE_OBJ: &str = "\
v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1
f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8
";

#[test]
fn task_wrench_space_value_matches_the_hand_derivation() {
    let task = file("task.csv", TASK);
    let input = format!("[{FOUR_FACES},{PINCH}]");
    for method in ["partial", "brute"] {
        let out = pqh(
            &[
                "grasp",
                "--metric",
                "ows",
                "--disturbances",
                task.to_str().unwrap(),
                "--method",
                method,
            ],
            &input,
        );
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let lines = lines(&out);
        assert_eq!(lines.len(), 2);
        assert_eq!(lines[0]["index"], 0);
        assert_eq!(lines[0]["force_closure"], true);
        let q = lines[0]["quality"].as_f64().unwrap();
        assert!((q - 0.25).abs() < 1e-6, "{method}: {q}");
        // The pinch is not force closure: no number.
        assert_eq!(lines[1]["force_closure"], false);
        assert!(lines[1]["quality"].is_null());
        assert!(String::from_utf8_lossy(&out.stderr).contains("task wrench space: 3 disturbances"));
    }
    // The ellipsoid needs disturbances spanning 6-D: three do not, an error line says so.
    let out = pqh(
        &[
            "grasp",
            "--metric",
            "ows",
            "--disturbances",
            task.to_str().unwrap(),
            "--method",
            "ellipsoid",
        ],
        FOUR_FACES,
    );
    assert!(out.status.success());
    let error = lines(&out)[0]["error"].as_str().unwrap().to_string();
    assert!(error.contains("ellipsoid"), "{error}");
    // With small pushes ±0.1 e_i added (each resisted up to r ≥ 5), the value is still 0.25 and
    // the ellipsoid method gives a lower bound.
    let mut spanning = TASK.to_string();
    for i in 0..6 {
        for s in [0.1, -0.1] {
            let row: Vec<String> = (0..6)
                .map(|c| if c == i { s.to_string() } else { "0".into() })
                .collect();
            spanning += &(row.join(" ") + "\n");
        }
    }
    let task = file("task-spanning.csv", &spanning);
    let out = pqh(
        &[
            "grasp",
            "--metric",
            "ows",
            "--disturbances",
            task.to_str().unwrap(),
        ],
        FOUR_FACES,
    );
    let exact = lines(&out)[0]["quality"].as_f64().unwrap();
    assert!((exact - 0.25).abs() < 1e-6, "{exact}");
    let out = pqh(
        &[
            "grasp",
            "--metric",
            "ows",
            "--disturbances",
            task.to_str().unwrap(),
            "--method",
            "ellipsoid",
        ],
        FOUR_FACES,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let q = lines(&out)[0]["quality"].as_f64().unwrap();
    assert!(q > 0.0 && q <= 0.25 * (1.0 + 1e-6), "{q}");
}

#[test]
fn mesh_frame_is_applied_and_a_conflicting_frame_is_an_error_line() {
    let cube = file("cube.obj", CUBE_OBJ);
    let with_frame = FOUR_FACES.replace(
        "\"cone_edges\":8}",
        "\"cone_edges\":8,\"torque_reference\":[0,0,0]}",
    );
    let input = format!(
        "{}\n{}\n",
        FOUR_FACES.replace('\n', ""),
        with_frame.replace('\n', "")
    );
    let out = pqh(
        &["grasp", "--metric", "ows", "--mesh", cube.to_str().unwrap()],
        &input,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines = lines(&out);
    assert_eq!(lines.len(), 2);
    assert_eq!(lines[0]["force_closure"], true);
    assert!(lines[0]["quality"].as_f64().unwrap() > 0.0);
    assert!(lines[0]["stats"]["points_processed"].as_u64().is_some());
    assert_eq!(lines[1]["index"], 1);
    assert!(lines[1]["error"].as_str().unwrap().contains("torque frame"));
    let stderr = String::from_utf8_lossy(&out.stderr);
    // Eq. 6 with the first grasp's cone (μ = 0.5, 8 edges): per face 4 corner pushes and
    // 2 triangles × 3 corners × 8 rim edges. (Each face's diagonal triangle has its rim one step
    // of 2π/8 from its side triangle's: the same directions up to rounding, which on this mesh
    // leaves no two exactly equal, so nothing merges; tests/ows_eq6.rs compares the set itself.)
    assert!(
        stderr.contains(&format!("{} disturbances", 6 * (4 + 2 * 3 * 8))),
        "{stderr}"
    );
    assert!(stderr.contains("centre of mass"), "{stderr}");
}

/// The reported bug: the ellipsoid method said `"force_closure": true, "quality": 2.2e-308` for a
/// two-finger pinch (rank-5 wrenches, mapped to a sliver holding the origin within rounding).
/// Its verdict is now the grasp's own, as partial and brute force decide it.
#[test]
fn ellipsoid_method_does_not_call_a_pinch_force_closure() {
    let cube = file("cube-pinch.obj", CUBE_OBJ);
    for method in ["partial", "brute", "ellipsoid"] {
        let out = pqh(
            &[
                "grasp",
                "--metric",
                "ows",
                "--mesh",
                cube.to_str().unwrap(),
                "--method",
                method,
            ],
            PINCH,
        );
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let lines = lines(&out);
        assert_eq!(lines[0]["force_closure"], false, "{method}: {}", lines[0]);
        assert!(lines[0]["quality"].is_null(), "{method}: {}", lines[0]);
    }
}

#[test]
fn usage_and_input_errors_are_reported() {
    let cube = file("cube-errors.obj", CUBE_OBJ);
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["grasp", "--metric", "ows"], "needs --mesh"),
        (
            vec!["grasp", "--metric", "q1", "--mesh", cube.to_str().unwrap()],
            "for --metric ows",
        ),
        (
            vec![
                "grasp",
                "--metric",
                "ows",
                "--mesh",
                cube.to_str().unwrap(),
                "--method",
                "qhull",
            ],
            "--metric ows takes --method partial, full, partial-rays, ellipsoid, not qhull",
        ),
        (
            vec!["grasp", "--method", "ellipsoid"],
            "--metric q1 takes --method partial, full, qhull, not ellipsoid",
        ),
    ];
    for (args, message) in cases {
        let out = pqh(&args, FOUR_FACES);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
    let five = file("five.csv", "1 2 3 4 5\n");
    let out = pqh(
        &[
            "grasp",
            "--metric",
            "ows",
            "--disturbances",
            five.to_str().unwrap(),
        ],
        FOUR_FACES,
    );
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("five.csv") && stderr.contains("6 coordinates"),
        "{stderr}"
    );

    let quad = file(
        "quad.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",
    );
    let out = pqh(
        &["grasp", "--metric", "ows", "--mesh", quad.to_str().unwrap()],
        FOUR_FACES,
    );
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("quad.obj"), "{stderr}");
}

#[test]
fn bench_ows_reports_every_method_and_agreement() {
    let cube = file("cube-bench.obj", CUBE_OBJ);
    let out = pqh(
        &[
            "bench",
            "ows",
            "--mesh",
            cube.to_str().unwrap(),
            "--grasps",
            "30",
            "--brute-grasps",
            "10",
            "--edges",
            "4",
            "--json",
        ],
        "",
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: Value = serde_json::from_slice(&out.stdout).expect("one JSON document");
    // Eq. 6 at 4 edges: per face 4 corner pushes and 2 triangles × 3 corners × 4 rim edges.
    assert_eq!(report["disturbances"], 6 * (4 + 2 * 3 * 4));
    assert_eq!(report["compared_with_brute"], 10);
    assert_eq!(report["disagreements"], 0);
    assert_eq!(report["compared_with_rays"], 20);
    assert_eq!(report["rays_disagreements"], 0);
    let methods: Vec<&str> = report["methods"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["method"].as_str().unwrap())
        .collect();
    for m in [
        "partial",
        "brute",
        "ellipsoid",
        "q1-partial",
        "partial-rays",
        "q1-partial-fc",
    ] {
        assert!(methods.contains(&m), "{methods:?}");
    }
    let closure = report["force_closure"].as_u64().unwrap();
    assert_eq!(
        report["ellipsoid_relative_error"]["count"]
            .as_u64()
            .unwrap(),
        closure
    );
    // Some grasps are force closure (else the next check would be vacuous), and the ellipsoid's
    // value never exceeds the exact one.
    assert!(closure > 0);
    assert!(report["ellipsoid_relative_error"]["max"].as_f64().unwrap() <= 1e-9);
}

#[test]
fn options_that_would_be_ignored_are_errors() {
    for (args, message) in [
        (
            vec!["grasp", "--zero-wrench"],
            "--zero-wrench is for --metric qinf",
        ),
        (
            vec![
                "grasp",
                "--metric",
                "ows",
                "--disturbances",
                "x.csv",
                "--ows-edges",
                "4",
            ],
            "--ows-edges are for --metric ows --mesh",
        ),
    ] {
        let out = pqh(&args, FOUR_FACES);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
}

/// Issue 12, item 6: disturbances that are all the zero wrench leave Q_OWS unbounded. That was
/// `"force_closure": true, "quality": null`, while null means "not force closure"; it is now a
/// clear error (exit 2). A zero row among others constrains nothing and changes no value.
#[test]
fn all_zero_disturbances_are_an_error() {
    let zero = file("zero.csv", "0 0 0 0 0 0\n0,0,0,0,0,0\n");
    let out = pqh(
        &[
            "grasp",
            "--metric",
            "ows",
            "--disturbances",
            zero.to_str().unwrap(),
        ],
        FOUR_FACES,
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert!(
        stderr.starts_with("pqh: error:") && stderr.contains("zero wrench"),
        "{stderr}"
    );
    let with_zero = file("task_and_zero.csv", &format!("{TASK}0 0 0 0 0 0\n"));
    let task = file("task_only.csv", TASK);
    let value = |path: &std::path::Path| {
        let out = pqh(
            &[
                "grasp",
                "--metric",
                "ows",
                "--disturbances",
                path.to_str().unwrap(),
            ],
            FOUR_FACES,
        );
        lines(&out)[0]["quality"].as_f64().unwrap()
    };
    assert_eq!(value(&with_zero), value(&task));
}
