//! End-to-end tests of the `pqh` binary: documented output and error behaviour.

use crate::support::run::{file, pqh};
use serde_json::Value;
use std::path::PathBuf;
use std::process::Output;

const SQUARE: &str = "\
# the square [-1, 1]^2 and an interior point
-1 -1
1, -1
1 1   # top right
-1,1

0.2 0.1
";

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).expect("utf-8 stdout")
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).expect("utf-8 stderr")
}

fn json(o: &Output) -> Value {
    assert!(
        o.status.success(),
        "pqh failed: {:?}\n{}",
        o.status,
        stderr(o)
    );
    serde_json::from_str(&stdout(o)).expect("stdout is one JSON object")
}

fn usizes(v: &Value) -> Vec<usize> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_u64().expect("integer") as usize)
        .collect()
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

/// Asserts the run failed with `code`, printing exactly one `pqh: ` line on stderr and nothing on
/// stdout; returns that line.
fn one_line_error(o: &Output, code: i32) -> String {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(code), "stderr: {err}");
    assert!(o.stdout.is_empty(), "stdout: {}", stdout(o));
    assert_eq!(err.lines().count(), 1, "stderr: {err}");
    assert!(err.starts_with("pqh: "), "stderr: {err}");
    err.trim_end().to_string()
}

#[test]
fn square_full_hull_json() {
    let path = file("square.txt", SQUARE);
    let v = json(&pqh(&["hull", "--json", path.to_str().unwrap()], None));
    assert_eq!(v["dimension"], 2);
    assert_eq!(v["points"], 5);
    assert_eq!(v["strategy"], "farthest-point");
    assert_eq!(usizes(&v["vertices"]), vec![0, 1, 2, 3]);
    assert!((v["volume"].as_f64().unwrap() - 4.0).abs() < 1e-12);
    assert!(v.get("origin_distance").is_none());
    let facets = v["facets"].as_array().unwrap();
    assert_eq!(facets.len(), 4);
    for (i, f) in facets.iter().enumerate() {
        let verts = usizes(&f["vertices"]);
        assert_eq!(verts.len(), 2);
        let normal = floats(&f["normal"]);
        assert!((normal.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-12);
        assert!((f["offset"].as_f64().unwrap() - 1.0).abs() < 1e-12);
        // Neighbours are positions in the list, and the relation is symmetric.
        for n in usizes(&f["neighbors"]) {
            assert!(usizes(&facets[n]["neighbors"]).contains(&i));
        }
    }
    let stats = &v["stats"];
    for key in [
        "points_processed",
        "facets_created",
        "expansions",
        "elapsed_us",
    ] {
        assert!(stats[key].is_u64(), "stats.{key}: {stats}");
    }
    assert!(stats["points_processed"].as_u64().unwrap() >= 4);
}

#[test]
fn square_human_output() {
    let path = file("square-human.txt", SQUARE);
    let o = pqh(&["hull", path.to_str().unwrap()], None);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("dimension        2"), "{out}");
    assert!(out.contains("points           5"), "{out}");
    assert!(out.contains("vertices         4: 0 1 2 3"), "{out}");
    assert!(out.contains("facets           4"), "{out}");
    assert!(out.contains("volume           4"), "{out}");
    assert!(out.contains("points processed"), "{out}");
}

#[test]
fn cube_3d_with_coplanar_points() {
    // Corners of the unit cube plus face centres (coplanar with the faces) and the centre.
    let mut text = String::new();
    for i in 0..8 {
        text += &format!("{} {} {}\n", i & 1, i >> 1 & 1, i >> 2 & 1);
    }
    text += "0.5 0.5 0\n0.5 0.5 1\n0 0.5 0.5\n1 0.5 0.5\n0.5 0 0.5\n0.5 1 0.5\n0.5 0.5 0.5\n";
    let v = json(&pqh(&["hull", "--json"], Some(&text)));
    assert_eq!(v["dimension"], 3);
    assert_eq!(usizes(&v["vertices"]), (0..8).collect::<Vec<_>>());
    assert!((v["volume"].as_f64().unwrap() - 1.0).abs() < 1e-12);
    assert_eq!(v["facets"].as_array().unwrap().len(), 12);
}

#[test]
fn closest_to_origin_on_the_square() {
    let path = file("square-closest.txt", SQUARE);
    let p = path.to_str().unwrap();
    let v = json(&pqh(
        &["hull", "--strategy", "closest-to-origin", "--json", p],
        None,
    ));
    assert_eq!(v["strategy"], "closest-to-origin");
    assert!((v["origin_distance"].as_f64().unwrap() - 1.0).abs() < 1e-12);
    assert!(v.get("volume").is_none());
    let facet = usizes(&v["closest_facet"]);
    assert_eq!(facet.len(), 2);
    assert!(facet.iter().all(|&i| i < 4), "{facet:?}");
    let nearest = floats(&v["nearest_point"]);
    assert!((nearest.iter().map(|x| x.abs()).fold(0.0, f64::max) - 1.0).abs() < 1e-12);

    // A query point off centre: the right edge (vertices 1 and 2) is nearest.
    let v = json(&pqh(
        &[
            "hull",
            "--strategy",
            "closest-to-origin",
            "--origin",
            "0.5,0",
            "--json",
            p,
        ],
        None,
    ));
    assert!((v["origin_distance"].as_f64().unwrap() - 0.5).abs() < 1e-12);
    let mut facet = usizes(&v["closest_facet"]);
    facet.sort();
    assert_eq!(facet, vec![1, 2]);
    let nearest = floats(&v["nearest_point"]);
    assert!((nearest[0] - 1.0).abs() < 1e-12 && nearest[1].abs() < 1e-12);

    // Outside: negative distance; negative coordinates need no '='.
    let v = json(&pqh(
        &[
            "hull",
            "--strategy",
            "closest-to-origin",
            "--origin",
            "-3,0",
            "--json",
            p,
        ],
        None,
    ));
    assert!((v["origin_distance"].as_f64().unwrap() + 2.0).abs() < 1e-12);
    let mut facet = usizes(&v["closest_facet"]);
    facet.sort();
    assert_eq!(facet, vec![0, 3]);
}

#[test]
fn closest_to_origin_human_output() {
    let o = pqh(&["hull", "--strategy", "closest-to-origin"], Some(SQUARE));
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("signed distance  1 (inside)"), "{out}");
    assert!(out.contains("closest facet"), "{out}");
}

#[test]
fn stdin_input() {
    let path = file("square-stdin.txt", SQUARE);
    let from_file = json(&pqh(&["hull", "--json", path.to_str().unwrap()], None));
    for args in [&["hull", "--json", "-"][..], &["hull", "--json"][..]] {
        let v = json(&pqh(args, Some(SQUARE)));
        assert_eq!(v["vertices"], from_file["vertices"]);
        assert_eq!(v["facets"], from_file["facets"]);
        assert_eq!(v["volume"], from_file["volume"]);
    }
}

#[test]
fn ragged_rows_name_the_line() {
    let path = file("ragged.txt", "# comment\n0 0 0\n1 0 0\n\n0 1\n0 0 1\n");
    let o = pqh(&["hull", path.to_str().unwrap()], None);
    let err = one_line_error(&o, 2);
    assert!(err.contains("ragged.txt"), "{err}");
    assert!(
        err.contains("line 5: expected 3 coordinates (from line 2), found 2"),
        "{err}"
    );
}

#[test]
fn nan_names_the_line() {
    let o = pqh(&["hull"], Some("0 0\n1 0\n0 NaN\n1 1\n"));
    let err = one_line_error(&o, 2);
    assert!(err.contains("line 3"), "{err}");
    assert!(err.contains("NaN"), "{err}");
}

#[test]
fn not_a_number_names_line_and_token() {
    let o = pqh(&["hull"], Some("0 0\n1 0\n0 1\n1 one\n"));
    let err = one_line_error(&o, 2);
    assert!(err.contains("line 4") && err.contains("'one'"), "{err}");
}

#[test]
fn unsupported_dimensions() {
    let o = pqh(&["hull"], Some("0\n1\n2\n"));
    let err = one_line_error(&o, 2);
    assert!(err.contains("dimension 1"), "{err}");
    let nine = "0 0 0 0 0 0 0 0 1\n".repeat(12);
    let err = one_line_error(&pqh(&["hull"], Some(&nine)), 2);
    assert!(err.contains("dimension 9"), "{err}");
}

#[test]
fn empty_input() {
    let err = one_line_error(&pqh(&["hull"], Some("# nothing\n\n")), 2);
    assert!(err.contains("no points"), "{err}");
}

#[test]
fn collinear_points_are_a_geometry_error() {
    let o = pqh(&["hull"], Some("0 0\n1 1\n2 2\n3 3\n"));
    let err = one_line_error(&o, 1);
    assert!(err.contains("affinely dependent"), "{err}");
}

#[test]
fn too_few_points_is_a_geometry_error() {
    let err = one_line_error(&pqh(&["hull", "--json"], Some("0 0\n1 0\n")), 1);
    assert!(err.contains("too few points"), "{err}");
}

#[test]
fn missing_file() {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli-does-not-exist.txt");
    let o = pqh(&["hull", path.to_str().unwrap()], None);
    let err = one_line_error(&o, 2);
    assert!(err.contains("cli-does-not-exist.txt"), "{err}");
}

#[test]
fn origin_errors() {
    // Wrong dimension.
    let o = pqh(
        &[
            "hull",
            "--strategy",
            "closest-to-origin",
            "--origin",
            "1,2,3",
        ],
        Some(SQUARE),
    );
    let err = one_line_error(&o, 2);
    assert!(
        err.contains("--query") && err.contains("dimension 2"),
        "{err}"
    );
    // Not a number.
    let o = pqh(
        &["hull", "--strategy", "closest-to-origin", "--origin", "1,x"],
        Some(SQUARE),
    );
    let err = one_line_error(&o, 2);
    assert!(err.contains("'x'"), "{err}");
    // Only meaningful for closest-to-origin.
    let err = one_line_error(&pqh(&["hull", "--origin", "0,0"], Some(SQUARE)), 2);
    assert!(err.contains("closest-to-origin"), "{err}");
}

#[test]
fn bad_strategy_is_a_usage_error() {
    let o = pqh(&["hull", "--strategy", "nearest"], Some(SQUARE));
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("nearest"));
}

#[test]
fn help_explains_the_tool_and_exit_status() {
    let o = pqh(&["--help"], None);
    assert!(o.status.success());
    let out = stdout(&o);
    assert!(out.contains("convex hull"), "{out}");
    assert!(out.contains("Exit status"), "{out}");
    assert!(out.contains("hull"), "{out}");
    let o = pqh(&["hull", "--help"], None);
    assert!(o.status.success());
    let out = stdout(&o);
    for word in [
        "--strategy",
        "closest-to-origin",
        "--origin",
        "--json",
        "Exit status",
    ] {
        assert!(out.contains(word), "missing {word}: {out}");
    }
}

#[test]
fn compare_full_and_partial_hull_agree() {
    let o = pqh(
        &["compare", "--points", "200", "--dimension", "4", "--json"],
        None,
    );
    let v = json(&o);
    assert_eq!(v["dimension"], 4);
    assert_eq!(v["agree"], true);
    let sets = v["sets"].as_array().expect("sets");
    assert!(sets.len() >= 2, "{v}");
    for set in sets {
        let name = set["name"].as_str().expect("name");
        // The sphere and cube sets are centred on the origin: it is inside.
        assert_eq!(set["origin_inside"], true, "{name}");
        let full = set["full"]["signed_distance"].as_f64().expect("full");
        let partial = set["partial"]["signed_distance"].as_f64().expect("partial");
        assert!(full > 0.0 && partial > 0.0, "{name}: {full} {partial}");
        assert!(
            (full - partial).abs() <= 1e-9,
            "{name}: {full} vs {partial}"
        );
        assert!(set["difference"].as_f64().expect("difference") <= 1e-9);
        let created = |s: &str| set[s]["facets_created"].as_u64().expect("facets_created");
        assert!(created("partial") <= created("full"), "{name}: {set}");
    }
}

const GRASPS: &str = r#"{"contacts":[{"position":[-0.5,0.1,0],"normal":[1,0,0]},{"position":[0.5,-0.1,0],"normal":[-1,0,0]},{"position":[0,-0.2,0.05],"normal":[0,1,0]},{"position":[0.1,0.2,-0.05],"normal":[0,-1,0]}],"friction":0.5,"cone_edges":8,"torque_scale":0.55}
{"contacts":[{"position":[0,0,0],"normal":[0,0,0]}],"friction":0.5,"cone_edges":8}
not json
{"contacts":[{"position":[-0.5,0,0],"normal":[1,0,0]},{"position":[0.5,0,0],"normal":[-1,0,0]}],"friction":0.5,"cone_edges":8}"#;

#[test]
fn grasp_lines_in_input_order_with_errors_named() {
    for method in ["partial", "full"] {
        let out = pqh(
            &["grasp", "--method", method, "--threads", "2", "-"],
            Some(GRASPS),
        );
        assert!(out.status.success(), "{}", stderr(&out));
        let lines: Vec<Value> = stdout(&out)
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        assert_eq!(lines.len(), 4);
        for (i, line) in lines.iter().enumerate() {
            assert_eq!(line["index"], i);
        }
        assert_eq!(lines[0]["force_closure"], true);
        assert!(lines[0]["quality"].as_f64().unwrap() > 0.0);
        assert!(lines[0]["stats"]["facets_created"].as_u64().unwrap() > 0);
        assert!(lines[1]["error"].as_str().unwrap().contains("contact 0"));
        assert!(lines[2]["error"].as_str().unwrap().contains("line 3"));
        assert_eq!(lines[3]["force_closure"], false);
        assert!(lines[3]["quality"].as_f64().unwrap() <= 0.0);
    }
    // Partial and full agree on the force-closure grasp; so does Q∞ by both.
    let small = GRASPS.replace("\"cone_edges\":8", "\"cone_edges\":4");
    let value = |args: &[&str]| -> f64 {
        let out = pqh(args, Some(&small));
        let first: Value = serde_json::from_str(stdout(&out).lines().next().unwrap()).unwrap();
        first["quality"].as_f64().unwrap()
    };
    let (a, b) = (
        value(&["grasp", "-"]),
        value(&["grasp", "--method", "full", "-"]),
    );
    assert!((a - b).abs() <= 1e-12 * b);
    let (a, b) = (
        value(&["grasp", "--metric", "qinf", "-"]),
        value(&["grasp", "--metric", "qinf", "--method", "full", "-"]),
    );
    assert!((a - b).abs() <= 1e-12 * b);
}

#[test]
fn bench_gws_json_reports_ratios_and_agreement() {
    let out = pqh(
        &[
            "bench",
            "gws",
            "--grasps",
            "6",
            "--full-grasps",
            "3",
            "--edges",
            "4,6",
            "--json",
        ],
        None,
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let report = json(&out);
    let results = report["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    for r in results {
        assert_eq!(r["disagreements"], 0);
        let methods = r["methods"].as_array().unwrap();
        assert_eq!(methods[0]["method"], "partial");
        assert_eq!(methods[1]["method"], "full");
        assert!(methods[1]["facets_ratio_vs_partial"].as_f64().unwrap() >= 1.0);
    }
}

#[test]
fn bench_gws_on_the_ellipsoid_agrees_across_methods() {
    // Qhull on the caller's raw wrenches is the independent reference (the `qhull` feature, which
    // CI builds); our full hull a consistency check beside it.
    let methods = if cfg!(feature = "qhull") {
        "partial,full,qhull"
    } else {
        "partial,full"
    };
    let run = |object: &str| {
        let out = pqh(
            &[
                "bench",
                "gws",
                "--object",
                object,
                "--methods",
                methods,
                "--grasps",
                "40",
                "--full-grasps",
                "40",
                "--edges",
                "6",
                "--qinf-max-edges",
                "0",
                "--batch-rounds",
                "0",
                "--json",
            ],
            None,
        );
        assert!(out.status.success(), "{}", stderr(&out));
        json(&out)
    };
    let (ellipsoid, bar) = (run("ellipsoid"), run("bar"));
    assert_eq!(ellipsoid["object"], "ellipsoid");
    assert_eq!(bar["object"], "bar");
    let r = &ellipsoid["results"][0];
    // Every method agrees with the partial one on every grasp (Qhull included, where built),
    // and some grasps are force closure.
    assert_eq!(r["disagreements"], 0);
    let evaluated = r["methods"].as_array().unwrap();
    assert_eq!(evaluated.len(), methods.split(',').count());
    assert!(evaluated.iter().all(|m| m["errors"] == 0), "{r}");
    let partial = &r["methods"][0];
    assert_eq!(partial["method"], "partial");
    assert!(partial["force_closure"].as_u64().unwrap() > 0, "{partial}");
    // Other grasps than the bar's (the work counters, unlike the times, are deterministic).
    let work = |row: &serde_json::Value| {
        (
            row["mean_facets_created"].clone(),
            row["mean_points_processed"].clone(),
        )
    };
    assert_ne!(work(partial), work(&bar["results"][0]["methods"][0]));
    let bad = pqh(&["bench", "gws", "--object", "sphere"], None);
    assert_eq!(bad.status.code(), Some(2), "{}", stderr(&bad));
}

#[test]
fn bench_gws_json_reports_qinf_and_batch_throughput() {
    let out = pqh(
        &[
            "bench",
            "gws",
            "--grasps",
            "4",
            "--full-grasps",
            "1",
            "--edges",
            "4",
            "--methods",
            "full,partial",
            "--threads",
            "1,2",
            "--batch-rounds",
            "1",
            "--json",
        ],
        None,
    );
    let report = json(&out);
    assert_eq!(usizes(&report["threads"]), [1, 2]);
    let results = report["results"].as_array().unwrap();
    assert_eq!(results.len(), 1);
    let r = &results[0];
    assert_eq!(r["disagreements"], 0);
    // Partial runs first whatever the order of --methods.
    let methods = r["methods"].as_array().unwrap();
    assert_eq!(methods[0]["method"], "partial");
    assert_eq!(methods[1]["method"], "full");
    // Q∞ (k = 4 ≤ 32): both variants by default, zero-wrench first, on every grasp.
    let qinf = r["qinf"].as_array().unwrap();
    let variants: Vec<&str> = qinf
        .iter()
        .map(|q| q["variant"].as_str().unwrap())
        .collect();
    assert_eq!(variants, ["zero-wrench", "plain"]);
    for q in qinf {
        assert_eq!(q["method"], "partial");
        assert_eq!(q["grasps"], 4);
        assert_eq!(q["errors"], 0);
        let (median, max) = (
            q["median_us"].as_f64().unwrap(),
            q["max_us"].as_f64().unwrap(),
        );
        assert!(0.0 < median && median <= max);
    }
    // With the zero wrench, Q∞ is force closure exactly when Q1 is.
    assert_eq!(qinf[0]["force_closure"], methods[0]["force_closure"]);
    // Batch: one entry per pool size, results identical to the sequential ones.
    let batch = r["batch"].as_array().unwrap();
    assert_eq!(batch.len(), 2);
    for (b, threads) in batch.iter().zip([1, 2]) {
        assert_eq!(b["threads"], threads);
        assert_eq!(b["grasps"], 4);
        assert_eq!(b["mismatches"], 0);
        assert!(b["grasps_per_s"].as_f64().unwrap() > 0.0);
        assert!(b["speedup_vs_1_thread"].as_f64().unwrap() > 0.0);
        // Four tiny grasps are far below the default 200 ms per round: many passes.
        assert!(b["passes"].as_u64().unwrap() > 1, "{b}");
    }
    assert_eq!(batch[0]["speedup_vs_1_thread"], 1.0);
}

#[test]
fn bench_gws_tables_and_switches() {
    let args = ["bench", "gws", "--grasps", "2", "--full-grasps", "0"];
    // --qinf-max-edges 0 and --batch-rounds 0 leave the Q1 table alone.
    let out = pqh(
        &[
            &args[..],
            &[
                "--edges",
                "4",
                "--qinf-max-edges",
                "0",
                "--batch-rounds",
                "0",
            ],
        ]
        .concat(),
        None,
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let text = stdout(&out);
    assert!(
        text.contains("GWS Q1") && text.contains("partial"),
        "{text}"
    );
    assert!(!text.contains("Q-inf") && !text.contains("Batch"), "{text}");
    // Only k ≤ --qinf-max-edges gets Q∞ rows; --qinf picks the variants.
    let out = pqh(
        &[
            &args[..],
            &[
                "--edges",
                "4,6",
                "--qinf-max-edges",
                "4",
                "--qinf",
                "zero-wrench",
            ],
            &["--threads", "1", "--batch-min-ms", "0", "--json"],
        ]
        .concat(),
        None,
    );
    let report = json(&out);
    let results = report["results"].as_array().unwrap();
    assert_eq!(results[0]["qinf"].as_array().unwrap().len(), 1);
    assert_eq!(results[0]["qinf"][0]["variant"], "zero-wrench");
    assert!(results[1]["qinf"].as_array().unwrap().is_empty());
    assert_eq!(results[0]["methods"].as_array().unwrap().len(), 1); // --full-grasps 0
    assert_eq!(results[1]["batch"].as_array().unwrap().len(), 1);
    assert_eq!(results[1]["batch"][0]["passes"], 1); // --batch-min-ms 0: single passes
    // A pool of 0 threads is a usage error.
    let out = pqh(&[&args[..], &["--threads", "1,0"]].concat(), None);
    assert!(one_line_error(&out, 2).contains("--threads"));
}

/// Every float of a grasp is read as Rust's own parser reads it (serde_json's default parser
/// misreads about one 17-digit float in twelve by an ulp), so the quality `pqh grasp` prints is the
/// library's on the very numbers written, bit for bit.
#[test]
fn grasp_floats_are_read_exactly() {
    use pqhull::geometry::Rng;
    use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric};
    let mut rng = Rng::new(0x5eed);
    let mut lines = String::new();
    let mut expected = Vec::new();
    let mut evaluator = Evaluator::new(Metric::Q1, Method::Partial, None).unwrap();
    for _ in 0..12 {
        let mut contacts = Vec::new();
        let mut written = Vec::new();
        while contacts.len() < 4 {
            let p: [f64; 3] = std::array::from_fn(|_| rng.uniform_in(-0.3, 0.3));
            let n: [f64; 3] = std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0));
            let length = n.iter().map(|x| x * x).sum::<f64>().sqrt();
            let n = n.map(|x| x / length);
            if let Ok(c) = Contact::try_new(p, n, None) {
                contacts.push(c);
                written.push(format!("{{\"position\":{p:?},\"normal\":{n:?}}}"));
            }
        }
        let mu = rng.uniform_in(0.3, 0.9);
        let c: [f64; 3] = std::array::from_fn(|_| rng.uniform_in(-0.1, 0.1));
        let rho = rng.uniform_in(0.2, 1.0);
        let friction = FrictionModel::try_new(mu, 8).unwrap();
        let grasp = Grasp::builder(contacts, friction)
            .torque_reference(c)
            .torque_scale(rho)
            .build()
            .unwrap();
        expected.push(evaluator.evaluate(&grasp).unwrap().value.unwrap());
        lines.push_str(&format!(
            "{{\"contacts\":[{}],\"friction\":{mu:?},\"cone_edges\":8,\"torque_reference\":{c:?},\
             \"torque_scale\":{rho:?}}}\n",
            written.join(",")
        ));
    }
    let out = pqh(&["grasp", "-"], Some(&lines));
    assert!(out.status.success(), "{}", stderr(&out));
    let got: Vec<f64> = stdout(&out)
        .lines()
        .map(|l| {
            serde_json::from_str::<Value>(l).unwrap()["quality"]
                .as_f64()
                .unwrap()
        })
        .collect();
    assert_eq!(got.len(), expected.len());
    for (i, (g, e)) in got.iter().zip(&expected).enumerate() {
        assert_eq!(
            g.to_bits(),
            e.to_bits(),
            "grasp {i}: pqh {g:e}, library {e:e}"
        );
    }
}

/// The `[possible values: …]` list of `--strategy` in a subcommand's help.
fn strategy_values(subcommand: &str) -> Vec<String> {
    let help = String::from_utf8(pqh(&[subcommand, "-h"], None).stdout).unwrap();
    let at = help.find("--strategy").expect("a --strategy option");
    let list = &help[at..];
    let start =
        list.find("[possible values: ").expect("possible values") + "[possible values: ".len();
    let end = start + list[start..].find(']').unwrap();
    list[start..end].split(", ").map(str::to_string).collect()
}

#[test]
fn hull_and_trace_share_strategy_names_and_the_query_flag() {
    let hull = strategy_values("hull");
    let trace = strategy_values("trace");
    assert_eq!(hull, ["farthest-point", "closest-to-origin"], "{hull:?}");
    assert_eq!(
        trace,
        ["farthest-point", "closest-to-origin", "ows-inflation"],
        "{trace:?}"
    );
    // The canonical names and every old spelling give the same answer.
    let run = |args: &[&str]| -> Value {
        let o = pqh(args, Some(SQUARE));
        assert!(
            o.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let mut v = json(&o);
        v["stats"]["elapsed_us"] = Value::Null; // the only field that may differ between runs
        v
    };
    let canonical = run(&[
        "hull",
        "--json",
        "--strategy",
        "closest-to-origin",
        "--query",
        "0.5,0",
    ]);
    let old = run(&[
        "hull",
        "--json",
        "--strategy",
        "closest-to-origin",
        "--origin",
        "0.5,0",
    ]);
    let short = run(&["hull", "--json", "--strategy", "closest", "--query=0.5,0"]);
    assert_eq!(canonical, old);
    assert_eq!(canonical, short);
    let full = run(&["hull", "--json", "--strategy", "full"]);
    assert_eq!(
        full,
        run(&["hull", "--json", "--strategy", "farthest-point"])
    );
    assert_eq!(full["strategy"], "farthest-point");
    // pqh trace takes the same names, the short ones, and --origin for --query.
    let dir = std::env::temp_dir().join(format!("pqh-names-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("t.html");
    let out = out.to_str().unwrap();
    for (strategy, extra) in [
        ("farthest-point", None),
        ("farthest", None),
        ("closest-to-origin", Some("--query=0.1,0.1")),
        ("closest", Some("--origin=0.1,0.1")),
        ("ows-inflation", None),
        ("ows", None),
    ] {
        let mut args = vec![
            "trace",
            "--family",
            "cube",
            "--points",
            "30",
            "--dimension",
            "2",
        ];
        args.extend(["--strategy", strategy, "--output", out]);
        args.extend(extra);
        let o = pqh(&args, None);
        assert!(
            o.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_sample_grasps_file_evaluates_by_every_metric() {
    let path =
        PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join("data/grasps/sample.jsonl");
    let path = path.to_str().unwrap();
    let lines = |args: &[&str]| -> Vec<Value> {
        let o = pqh(args, None);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        stdout(&o)
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect()
    };
    // (Q∞ by the full method would hull 8^4 and 16^3 Minkowski points here: a second or more a
    // grasp.)
    for (metric, method) in [("q1", "full"), ("qinf", "partial")] {
        let partial = lines(&["grasp", "--metric", metric, path]);
        let full = lines(&["grasp", "--metric", metric, "--method", method, path]);
        let closure: Vec<bool> = partial
            .iter()
            .map(|l| l["force_closure"].as_bool().unwrap())
            .collect();
        // A box grasp, an antipodal pinch (rank-deficient), a 3-finger grasp with tangents and a
        // torque frame, three fingers on one face.
        assert_eq!(closure, [true, false, true, false], "{metric}");
        for (p, f) in partial.iter().zip(&full) {
            assert_eq!(p["force_closure"], f["force_closure"], "{metric}");
            let (a, b) = (
                p["quality"].as_f64().unwrap(),
                f["quality"].as_f64().unwrap(),
            );
            assert!(
                (a - b).abs() <= 1e-12 * a.abs().max(1e-3),
                "{metric}: {a} vs {b}"
            );
        }
    }
    let ows = lines(&[
        "grasp",
        "--metric",
        "ows",
        "--mesh",
        &format!(
            "{}/data/meshes/woody.obj",
            concat!(env!("CARGO_MANIFEST_DIR"), "/..")
        ),
        path,
    ]);
    assert_eq!(ows.len(), 4);
}

#[test]
fn bench_hull_quick_json_has_every_case() {
    let out = pqh(
        &["bench", "hull", "--quick", "--repeats", "1", "--json"],
        None,
    );
    let report = json(&out);
    assert_eq!(report["benchmark"], "hull");
    assert_eq!(report["preset"], "quick");
    assert_eq!(report["qhull"], cfg!(feature = "qhull"));
    assert_eq!(report["failures"], 0);
    let rows = report["rows"].as_array().unwrap();
    let cases: Vec<(String, u64)> = rows
        .iter()
        .map(|r| {
            (
                r["case"].as_str().unwrap().to_string(),
                r["dimension"].as_u64().unwrap(),
            )
        })
        .collect();
    let mut expected = Vec::new();
    for d in 3..=6 {
        for family in [
            "cube",
            "sphere",
            "corners",
            "simplex",
            "shell",
            "lens",
            "lattice",
            "clusters",
            "duplicates",
            "tilted",
        ] {
            expected.push((family.to_string(), d));
        }
    }
    for (grid, d) in [
        ("grid-m6", 3),
        ("grid-m4", 4),
        ("grid-m3", 5),
        ("grid-m3", 6),
    ] {
        expected.push((grid.to_string(), d));
    }
    for case in [
        "wrenches-4x8/hull",
        "wrenches-4x8/volume",
        "minkowski-3x4/qinf-full",
        "minkowski-3x4/hull",
    ] {
        expected.push((case.to_string(), 6));
    }
    assert_eq!(cases, expected);
    for r in rows {
        let positive = |key: &str| r[key].as_f64().is_some_and(|x| x.is_finite() && x > 0.0);
        assert!(positive("pqhull_ms"), "{r}");
        assert_eq!(r["check"], true, "{r}");
        assert!(r["pqhull_vertices"].as_u64().unwrap() > 0, "{r}");
        if cfg!(feature = "qhull") {
            assert!(positive("qhull_ms"), "{r}");
            assert!(r["qhull_vertices"].as_u64().unwrap() > 0, "{r}");
        } else {
            assert!(r.get("qhull_ms").is_none(), "{r}");
        }
    }
    // The grasps were chosen force closure (Q1); the metric rows carry their values.
    for r in rows
        .iter()
        .filter(|r| r["family"] != "grid" && r["dimension"] == 6)
    {
        if r["timed"] != "hull" {
            assert!(r["value"].as_f64().is_some_and(f64::is_finite), "{r}");
            assert_eq!(r["force_closure"], true, "{r}");
        }
    }

    // The table: one line per row, the summary line with Qhull; filters pick the cases.
    let out = pqh(
        &[
            "bench",
            "hull",
            "--quick",
            "--repeats",
            "1",
            "--families",
            "simplex,grid",
            "--dimensions",
            "3",
        ],
        None,
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let text = stdout(&out);
    assert!(
        text.contains("simplex") && text.contains("grid-m6"),
        "{text}"
    );
    assert!(!text.lines().any(|l| l.starts_with("cube")), "{text}");
    assert_eq!(
        text.contains("min qhull/pqhull"),
        cfg!(feature = "qhull"),
        "{text}"
    );
    // Nothing selected, or an unknown family: usage errors.
    let out = pqh(
        &[
            "bench",
            "hull",
            "--families",
            "minkowski",
            "--dimensions",
            "3",
        ],
        None,
    );
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("no case matches"), "{}", stderr(&out));
    let out = pqh(&["bench", "hull", "--families", "cubes"], None);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
}
