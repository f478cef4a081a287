//! `pqh grasp` against the raw-wrench reference of tests/raw_reference.rs: a few dozen grasps
//! (random ones on an ellipsoid, a box and a cylinder; physically degenerate ones; near-boundary
//! ones at Q1 ≈ ±1e-9, ±1e-11, +5e-13 × scale; the near-boundary cylinder case) as JSON Lines, one
//! output line per grasp, for `--metric q1`, `--metric qinf` (with and without `--zero-wrench`)
//! and `--metric ows --disturbances FILE`, by every exact method (the ellipsoid method: verdict
//! only).
//!
//! The reference is computed on the grasp *as the CLI reads it*: the JSON line parsed by
//! serde_json and built with `Contact::try_new`, exactly as `pqh grasp` does; the summary says
//! how many grasps the JSON round trip changed at all. Same contract and tolerances as
//! tests/raw_reference.rs (see `support/raw_reference.rs`).
//!
//! Run with `cargo test --release --features qhull --test cli_raw_reference -- --nocapture`.
#![cfg(feature = "qhull")]

use crate::support::library::raw_reference::{
    FULL_QINF_LIMIT, HullReference, Report, Shape, check_formula, cylinder_case_path,
    degenerate_grasps, grasp_from_json, grasp_to_json, hull_reference, judge, judge_ows,
    near_boundary_family, note_references, ows_reference_for, qinf_reference, random_disturbances,
    random_grasp, seed, union_scale,
};
use crate::support::run::file;
use pqhull::geometry::Rng;
use pqhull::grasp::{FrictionModel, Grasp};
use serde_json::Value;
use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// One grasp of the CLI run, as the CLI reads it, with its references.
struct Entry {
    case: String,
    line: String,
    degenerate: bool,
    q1: HullReference,
    ows: Option<f64>,
    /// Q∞ without and with the zero wrench: (Minkowski points, reference).
    qinf: [Option<(usize, HullReference)>; 2],
}

/// The grasps: (case, grasp, physically degenerate).
fn grasps() -> Vec<(String, Grasp, bool)> {
    let mut out = Vec::new();
    for i in 0..16u64 {
        let mut rng = Rng::new(seed(&[20, i]));
        let shape = Shape::ALL[i as usize % 3];
        let m = 2 + i as usize % 3;
        let k = 6 + rng.index(3);
        let mu = rng.uniform_in(0.2, 1.0);
        let friction = FrictionModel::try_new(mu, k).unwrap();
        let g = random_grasp(&mut rng, shape, m, friction);
        let case = format!("{} #{i} (m = {m}, k = {k}, μ = {mu:.3})", shape.name());
        out.push((case, g, m == 2));
    }
    for (i, (case, g)) in degenerate_grasps().into_iter().enumerate() {
        if i % 60 == 7 {
            out.push((case, g, true));
        }
    }
    for index in [0, 8] {
        for (case, g, _) in near_boundary_family(index) {
            out.push((case, g, false));
        }
    }
    let text = std::fs::read_to_string(cylinder_case_path()).expect("read the case file");
    let case = grasp_from_json(&serde_json::from_str(&text).unwrap());
    out.push(("near-boundary-cylinder-grasp.json".into(), case, false));
    out
}

fn entries(report: &mut Report, disturbances: &[[f64; 6]]) -> Vec<Entry> {
    let mut changed = 0;
    let mut numbers = (0, 0); // (numbers not read back bit for bit, numbers)
    let all = grasps();
    let count = all.len();
    let entries = all
        .into_iter()
        .map(|(case, original, degenerate)| {
            let line = grasp_to_json(&original).to_string();
            let parsed: Value = serde_json::from_str(&line).unwrap();
            let written = grasp_to_json(&original);
            for (a, b) in flat_numbers(&written).iter().zip(flat_numbers(&parsed)) {
                numbers.1 += 1;
                if a.to_bits() != b.to_bits() {
                    numbers.0 += 1;
                }
            }
            let grasp = grasp_from_json(&parsed);
            if grasp.wrenches() != original.wrenches() {
                changed += 1;
            }
            check_formula(report, &case, &grasp);
            let w = grasp.wrenches();
            let q1 = hull_reference(&w, union_scale(&w));
            let ows = ows_reference_for(&grasp, &q1, disturbances, degenerate);
            let qinf = [false, true].map(|z| qinf_reference(&grasp, z));
            Entry {
                case,
                line,
                degenerate,
                q1,
                ows,
                qinf,
            }
        })
        .collect();
    report.note(format!(
        "JSON round trip: {} of {} numbers read back other than written (serde_json's float \
         parsing); {changed} of {count} grasps have other wrenches once rebuilt (Contact::try_new \
         renormalises the normal and the tangent); the references are of the grasps as the CLI \
         reads them",
        numbers.0, numbers.1
    ));
    entries
}

/// Every number of a JSON value, in document order.
fn flat_numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Number(n) => vec![n.as_f64().unwrap()],
        Value::Array(items) => items.iter().flat_map(flat_numbers).collect(),
        Value::Object(map) => map.values().flat_map(flat_numbers).collect(),
        _ => Vec::new(),
    }
}

/// A whole `pqh grasp` run may take this long; after that each grasp is run on its own, with
/// [`LINE_TIMEOUT`], so that the grasps that hang are named and the others still checked.
const RUN_TIMEOUT: Duration = Duration::from_secs(120);
const LINE_TIMEOUT: Duration = Duration::from_secs(30);

/// Runs `pqh` with `args` (stdin empty) and waits at most `timeout`: its stdout and stderr, or
/// None when it had to be killed.
fn pqh_within(args: &[&str], timeout: Duration) -> Option<(bool, String, String)> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn pqh");
    let drain = |mut pipe: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = pipe.read_to_string(&mut text);
            text
        })
    };
    let stdout = drain(Box::new(child.stdout.take().expect("stdout")));
    let stderr = drain(Box::new(child.stderr.take().expect("stderr")));
    let started = Instant::now();
    loop {
        if let Some(status) = child.try_wait().expect("wait for pqh") {
            let out = stdout.join().expect("stdout");
            let err = stderr.join().expect("stderr");
            return Some((status.success(), out, err));
        }
        if started.elapsed() > timeout {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Runs `pqh grasp` on `lines`, returning one output object per input line, in order. When the
/// run takes longer than [`RUN_TIMEOUT`], every line is run on its own and the ones that take
/// longer than [`LINE_TIMEOUT`] get an error object ("timed out").
fn run(report: &mut Report, name: &str, lines: &[&str], args: &[&str]) -> Vec<Value> {
    let once = |name: &str, lines: &[&str], timeout: Duration| -> Option<Vec<Value>> {
        let path = file(name, &(lines.join("\n") + "\n"));
        let mut all = vec!["grasp", path.to_str().unwrap(), "--threads", "2"];
        all.extend_from_slice(args);
        let (success, out, err) = pqh_within(&all, timeout)?;
        assert!(success, "pqh {all:?}: {err}");
        let values: Vec<Value> = out
            .lines()
            .map(|l| serde_json::from_str(l).expect("a JSON line"))
            .collect();
        assert_eq!(values.len(), lines.len(), "pqh {all:?}: one line per grasp");
        for (i, v) in values.iter().enumerate() {
            assert_eq!(v["index"], i, "pqh {all:?}: input order");
        }
        Some(values)
    };
    if let Some(values) = once(name, lines, RUN_TIMEOUT) {
        return values;
    }
    report.note(format!(
        "pqh grasp {args:?} took longer than {RUN_TIMEOUT:?}: grasps run one by one"
    ));
    lines
        .iter()
        .enumerate()
        .map(|(i, line)| match once(&format!("{i}-{name}"), &[line], LINE_TIMEOUT) {
            Some(mut v) => v.remove(0),
            None => serde_json::json!({
                "index": i,
                "error": format!("pqh grasp timed out after {LINE_TIMEOUT:?} on this grasp alone"),
            }),
        })
        .collect()
}

/// (force_closure, quality) of an output line, or its error.
fn answer(v: &Value) -> Result<(bool, Option<f64>), String> {
    if let Some(e) = v.get("error") {
        return Err(e.as_str().unwrap_or_default().to_string());
    }
    let fc = v["force_closure"].as_bool().expect("force_closure");
    Ok((fc, v["quality"].as_f64()))
}

#[test]
fn pqh_grasp_against_the_raw_reference() {
    let mut report = Report::default();
    let mut rng = Rng::new(seed(&[21]));
    let disturbances = random_disturbances(&mut rng, 50);
    let started = std::time::Instant::now();
    let entries = entries(&mut report, &disturbances);
    report.note(format!(
        "{} grasps; references (with the near-boundary bisections) in {:.2} s",
        entries.len(),
        started.elapsed().as_secs_f64()
    ));
    let lines: Vec<&str> = entries.iter().map(|e| e.line.as_str()).collect();

    // Q1.
    for method in ["partial", "full"] {
        let key = format!("CLI q1 {method}");
        let started = Instant::now();
        let out = run(&mut report, "q1.jsonl", &lines, &["--method", method]);
        report.add_time(&key, started.elapsed());
        for (e, v) in entries.iter().zip(&out) {
            match answer(v) {
                Err(m) => report.error(&key, &e.case, &m),
                Ok((fc, value)) => {
                    let value = value.unwrap_or(f64::NAN);
                    judge(&mut report, &key, &e.case, fc, value, &e.q1, e.degenerate);
                }
            }
        }
    }

    // Q∞, both variants: partial on every grasp; full on a few small sums.
    for (z, zero) in [(0, false), (1, true)] {
        let variant = if zero { "qinf+0" } else { "qinf" };
        let extra: &[&str] = if zero { &["--zero-wrench"] } else { &[] };
        let full: Vec<usize> = (0..entries.len())
            .filter(|&i| {
                entries[i].qinf[z]
                    .as_ref()
                    .is_some_and(|(n, _)| *n <= FULL_QINF_LIMIT)
            })
            .take(5)
            .collect();
        for method in ["partial", "full"] {
            let chosen: Vec<usize> = if method == "full" {
                full.clone()
            } else {
                (0..entries.len()).collect()
            };
            let input: Vec<&str> = chosen.iter().map(|&i| lines[i]).collect();
            let key = format!("CLI {variant} {method}");
            let mut args = vec!["--metric", "qinf", "--method", method];
            args.extend_from_slice(extra);
            let started = Instant::now();
            let out = run(
                &mut report,
                &format!("{variant}-{method}.jsonl"),
                &input,
                &args,
            );
            report.add_time(&key, started.elapsed());
            for (&i, v) in chosen.iter().zip(&out) {
                let e = &entries[i];
                match (answer(v), &e.qinf[z]) {
                    (Err(m), _) => report.error(&key, &e.case, &m),
                    (Ok((fc, value)), Some((_, r))) => {
                        let value = value.unwrap_or(f64::NAN);
                        judge(&mut report, &key, &e.case, fc, value, r, e.degenerate);
                    }
                    (Ok((fc, _)), None) => {
                        let expected = e.degenerate.then_some(false);
                        report.verdict(&key, &e.case, fc, expected, "physically degenerate");
                    }
                }
            }
        }
    }

    // Q_OWS against a task wrench space.
    let text: String = disturbances
        .iter()
        .map(|d| d.map(|x| x.to_string()).join(", ") + "\n")
        .collect();
    let path = file("disturbances.csv", &text);
    for method in ["partial", "brute", "ellipsoid"] {
        let key = format!("CLI ows {method}");
        let args = [
            "--metric",
            "ows",
            "--disturbances",
            path.to_str().unwrap(),
            "--method",
            method,
        ];
        let started = Instant::now();
        let out = run(&mut report, &format!("ows-{method}.jsonl"), &lines, &args);
        report.add_time(&key, started.elapsed());
        for (e, v) in entries.iter().zip(&out) {
            match answer(v) {
                Err(m) if method == "ellipsoid" => report.soft_error(&key, &e.case, &m),
                Err(m) => report.error(&key, &e.case, &m),
                Ok((fc, value)) => judge_ows(
                    &mut report,
                    &key,
                    &e.case,
                    fc,
                    value,
                    &e.q1,
                    e.degenerate,
                    e.ows,
                    method == "ellipsoid",
                ),
            }
        }
    }
    let refs: Vec<HullReference> = entries.iter().map(|e| e.q1.clone()).collect();
    note_references(&mut report, "CLI Q1", &refs);
    report.finish("5. pqh grasp (JSON Lines) against the raw-wrench reference");
}
