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

/// `pqh hull --queries QFILE`: one JSON line per query, in order, each the answer `--query`
/// gives alone; a queries file of another dimension is a usage error.
#[test]
fn many_queries_are_the_single_queries() {
    let mut rng = pqhull::geometry::Rng::new(8);
    let points: String = (0..300)
        .map(|_| {
            let p: Vec<String> = (0..3)
                .map(|_| rng.uniform_in(-1.0, 1.0).to_string())
                .collect();
            p.join(" ") + "\n"
        })
        .collect();
    let queries: Vec<[f64; 3]> = (0..25)
        .map(|_| std::array::from_fn(|_| rng.uniform_in(-2.0, 2.0)))
        .collect();
    let text: String = queries
        .iter()
        .map(|q| format!("{} {} {}\n", q[0], q[1], q[2]))
        .collect();
    let points_file = file("many-queries-points.txt", &points);
    let queries_file = file("many-queries-queries.txt", &text);
    let (p, q) = (
        points_file.to_str().unwrap(),
        queries_file.to_str().unwrap(),
    );
    let out = pqh(&["hull", p, "--queries", q, "--json"], None);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<serde_json::Value> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).expect("a JSON line"))
        .collect();
    assert_eq!(lines.len(), queries.len());
    for (line, query) in lines.iter().zip(&queries) {
        let arg = format!("--query={},{},{}", query[0], query[1], query[2]);
        let alone = pqh(
            &["hull", p, "--strategy", "closest-to-origin", &arg, "--json"],
            None,
        );
        let alone: serde_json::Value = serde_json::from_slice(&alone.stdout).expect("JSON");
        assert_eq!(line["origin"], alone["origin"]);
        let (a, b) = (
            line["origin_distance"].as_f64().unwrap(),
            alone["origin_distance"].as_f64().unwrap(),
        );
        assert!((a - b).abs() <= 1e-12, "{query:?}: {a} against {b} alone");
        assert_eq!(a < 0.0, b < 0.0, "{query:?}");
    }
    let flat = file("many-queries-2d.txt", "0 0\n1 1\n");
    let out = pqh(&["hull", p, "--queries", flat.to_str().unwrap()], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("dimension 2"));
}
