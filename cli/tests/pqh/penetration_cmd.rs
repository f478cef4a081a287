//! `pqh penetration`: the library's answer, printed; bad bodies refused with a clear line.

use crate::support::run::{file, pqh};

fn square(x: f64, y: f64, size: f64) -> String {
    format!(
        "{x} {y}\n{} {y}\n{} {}\n{x} {}\n",
        x + size,
        x + size,
        y + size,
        y + size
    )
}

fn json_of(output: &std::process::Output) -> serde_json::Value {
    assert!(
        output.status.success(),
        "pqh failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("stdout is one JSON object")
}

/// Exact integer squares: overlapping by 1 (depth 1, pushed along +x), 1 apart (−1), sharing an
/// edge (0, touching); the answers are the library's, field by field.
#[test]
fn penetration_of_squares_from_files_and_stdin() {
    let a = file("pen-a.txt", &square(0.0, 0.0, 4.0));
    let a = a.to_str().unwrap();
    for (b, depth, relation) in [
        (square(3.0, 1.0, 2.0), 1.0, "overlapping"),
        (square(5.0, 1.0, 2.0), -1.0, "separated"),
        (square(4.0, 1.0, 2.0), 0.0, "touching"),
    ] {
        let path = file(&format!("pen-b-{relation}.txt"), &b);
        let json = json_of(&pqh(
            &["penetration", a, path.to_str().unwrap(), "--json"],
            None,
        ));
        assert_eq!(json["depth"].as_f64(), Some(depth), "{json}");
        assert_eq!(json["relation"], relation, "{json}");
        assert_eq!(
            json["rounding"].as_f64(),
            Some(0.0),
            "integers: exact differences"
        );
        if depth != 0.0 {
            assert_eq!(json["direction"], serde_json::json!([1.0, 0.0]), "{json}");
            assert_eq!(
                json["translation"],
                serde_json::json!([depth, 0.0]),
                "{json}"
            );
        }
        // B from standard input: the same answer.
        let piped = json_of(&pqh(&["penetration", a, "-", "--json"], Some(&b)));
        assert_eq!(piped["depth"], json["depth"]);
    }
    let human = pqh(&["penetration", a, a], None);
    let text = String::from_utf8_lossy(&human.stdout);
    assert!(
        text.contains("relation:    overlapping") && text.contains("depth:       4"),
        "{text}"
    );
}

#[test]
fn bad_bodies_are_one_error_line() {
    let a = file("pen-bad-a.txt", &square(0.0, 0.0, 1.0));
    let a = a.to_str().unwrap();
    let three = file("pen-bad-3d.txt", "0 0 0\n1 0 0\n0 1 0\n");
    let nine = file("pen-bad-9d.txt", "0 0 0 0 0 0 0 0 0\n");
    for (args, needle) in [
        (
            vec!["penetration", a, three.to_str().unwrap()],
            "has dimension 2 but",
        ),
        (
            vec!["penetration", "-", "-"],
            "cannot both be standard input",
        ),
        (
            vec![
                "penetration",
                nine.to_str().unwrap(),
                nine.to_str().unwrap(),
            ],
            "dimensions 2 to 8",
        ),
        (
            vec!["penetration", a, "/nonexistent/b.txt"],
            "/nonexistent/b.txt",
        ),
    ] {
        let output = pqh(&args, None);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.starts_with("pqh: error: ")
                && stderr.contains(needle)
                && stderr.lines().count() == 1,
            "{args:?}: {stderr}"
        );
    }
}
