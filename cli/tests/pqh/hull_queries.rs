//! `pqh hull`'s answers where the library's were once wrong: a near-boundary grasp's wrenches
//! (tests/data/, against the exact reference of the library's regression test), far queries and
//! distances beyond `f64`'s range.

use crate::support::library::cases::{CYLINDER, read_points, reference, scale};
use crate::support::run::{file, pqh};

#[test]
fn near_boundary_cylinder_6d_cli() {
    let path = crate::support::library::data_file(CYLINDER);
    let points = read_points::<6>(CYLINDER);
    let scale = scale(&points);
    let expected = reference(&points);
    let output = pqh(
        &["hull", "--strategy", "closest-to-origin", &path, "--json"],
        None,
    );
    assert!(
        output.status.success(),
        "pqh failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let json: serde_json::Value =
        serde_json::from_slice(&output.stdout).expect("stdout is one JSON object");
    let got = json["origin_distance"]
        .as_f64()
        .expect("origin_distance is a number");
    assert!(got < 0.0, "origin_distance {got:e}: the origin is outside");
    assert!(
        got.abs() <= 1e-15 * scale,
        "origin_distance {got:e} is not tiny"
    );
    assert!(
        (got - expected).abs() <= 1e-12 * expected.abs(),
        "origin_distance {got:e}, exact {expected:e}"
    );
}

/// `pqh hull --query` prints the exact nearest point.
#[test]
fn cli_prints_the_nearest_point_of_a_far_query() {
    let square = file("far-square.txt", "-1 -1\n1 -1\n1 1\n-1 1\n");
    let out = pqh(
        &[
            "hull",
            square.to_str().unwrap(),
            "--strategy",
            "closest-to-origin",
            "--json",
            "--query=0,1e170",
        ],
        None,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(value["nearest_point"], serde_json::json!([0.0, 1.0]));
    assert_eq!(value["origin_distance"].as_f64(), Some(-1e170));
}

/// `pqh hull` at the edges of the range: text output with exponents, not 200-digit numbers;
/// a distance beyond f64::MAX a clear error in JSON (exit 2), never `null`.
#[test]
fn cli_far_queries() {
    let dir = std::env::temp_dir().join(format!("pqh-far-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let square = dir.join("square.txt");
    std::fs::write(&square, "0 0\n1 0\n1 1\n0 1\n").unwrap();
    let pqh = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_pqh"))
            .args(args)
            .arg(&square)
            .output()
            .unwrap()
    };
    let text = pqh(&[
        "hull",
        "--strategy",
        "closest-to-origin",
        "--origin=1e200,0.5",
    ]);
    let stdout = String::from_utf8(text.stdout).unwrap();
    assert!(text.status.success(), "{stdout}");
    assert!(
        stdout.contains("signed distance  -1e200 (outside)"),
        "{stdout}"
    );
    let json = pqh(&[
        "hull",
        "--json",
        "--strategy",
        "closest-to-origin",
        "--origin=1e200,0.5",
    ]);
    let value: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(value["origin_distance"].as_f64(), Some(-1e200));
    let beyond = pqh(&[
        "hull",
        "--json",
        "--strategy",
        "closest-to-origin",
        "--origin=-1.7e308,-1.7e308",
    ]);
    let stderr = String::from_utf8(beyond.stderr).unwrap();
    assert_eq!(beyond.status.code(), Some(2), "{stderr}");
    assert!(beyond.stdout.is_empty());
    assert!(
        stderr.starts_with("pqh: error:") && stderr.contains("exceeds the largest f64"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
