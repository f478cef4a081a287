//! Qhull's three answers to its precision problems — merged facets (its default, and scipy's),
//! joggled input (`QJ`) and no merging (`Q0`) — on the suite's raw Minkowski sums and raw
//! wrench sets, beside pqhull's exact hull: each engine's time (best of the rounds), its facet
//! count, and, untimed, how many of Qhull's facets are not facets of the exact hull of the
//! caller's points (an input point strictly beyond, or a flat simplex through the centroid; exact
//! orientation: `pqhull_cli::bench::perturb`). docs/benchmarks.md, "Qhull's three answers".
//!
//! ```sh
//! cargo build --release -p pqhull-cli --features qhull --example qhull_options
//! ./target/release/examples/qhull_options 3
//! ```
//!
//! Argument: rounds (3).

use pqhull::Hull;
use pqhull_cli::bench::hull::grasp_points;
use pqhull_cli::bench::stats::{best_of, first_line, numeric_args};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [rounds] = numeric_args(&args, 0, [3]).unwrap_or_else(|e| {
        eprintln!("usage: qhull_options [rounds]: {e}");
        std::process::exit(2);
    });
    println!("best of {rounds}; wrong = Qhull's facets that are not facets of the exact hull");
    println!(
        "{:<18} {:>6} {:>10} {:>7} {:<9} {:>10} {:>7} {:>7} {:>6}",
        "set", "points", "pqhull ms", "facets", "qhull", "qhull ms", "facets", "wrong", "q/pq"
    );
    // (name, contacts, edges, materialised sum)
    let sets = [
        ("raw sum 3x4", 3, 4, true),
        ("raw sum 3x6", 3, 6, true),
        ("raw sum 3x8", 3, 8, true),
        ("raw wrenches 4x8", 4, 8, false),
        ("raw wrenches 4x16", 4, 16, false),
        ("raw wrenches 4x32", 4, 32, false),
    ];
    for (name, contacts, edges, sum) in sets {
        let (_, _, points) = grasp_points(1, contacts, edges, sum);
        let mut built = None;
        let ms = best_of(rounds, || built = Some(Hull::try_new(&points))).as_secs_f64() * 1e3;
        let facets = match built.expect("at least one round") {
            Ok(hull) => hull.facet_count().to_string(),
            Err(e) => format!("error: {e}"),
        };
        let lead = format!("{name:<18} {:>6} {ms:>10.1} {facets:>7}", points.len());
        qhull_rows(&lead, &points, rounds, ms);
    }
}

/// One line per Qhull option set, each led by `lead` (the set and pqhull's columns).
#[cfg(feature = "qhull")]
fn qhull_rows(lead: &str, points: &[[f64; 6]], rounds: usize, pqhull_ms: f64) {
    use pqhull::qhull_baseline::{QhullOptions, qhull_stats_with};
    use pqhull_cli::bench::perturb::qhull_wrong_facets_with;
    for (label, options) in [
        ("merged", QhullOptions::Merged),
        ("QJ", QhullOptions::Joggled),
    ] {
        let mut run = None;
        let ms =
            best_of(rounds, || run = Some(qhull_stats_with(points, options))).as_secs_f64() * 1e3;
        match run.expect("at least one round") {
            Ok(q) => {
                // Untimed, on a further run: a joggled run draws the same joggle (Qhull's seed
                // is fixed), so the facets counted are the ones timed.
                let wrong = qhull_wrong_facets_with(points, options)
                    .map_or_else(|_| "-".to_string(), |(wrong, _)| wrong.to_string());
                println!(
                    "{lead} {label:<9} {ms:>10.1} {:>7} {wrong:>7} {:>6.2}",
                    q.facets,
                    ms / pqhull_ms
                );
            }
            Err(e) => println!(
                "{lead} {label:<9} fails: {}",
                first_line(&e.to_string(), 90)
            ),
        }
    }
    unmerged_row(lead, points, rounds, pqhull_ms);
}

#[cfg(not(feature = "qhull"))]
fn qhull_rows(lead: &str, points: &[[f64; 6]], rounds: usize, pqhull_ms: f64) {
    println!("{lead}  (Qhull library: build with --features qhull)");
    unmerged_row(lead, points, rounds, pqhull_ms);
}

/// Qhull with `Q0` (no merging), which the `qhull` crate's bindings cannot pass: Qhull's own
/// program (`apt-get install qhull-bin`) on the points written out exactly (Rust's shortest
/// round-trip decimals, which `strtod` reads back to the same doubles). Its time is the one it
/// reports, "CPU seconds to compute hull (after input)", best of `rounds`.
fn unmerged_row(lead: &str, points: &[[f64; 6]], rounds: usize, pqhull_ms: f64) {
    let label = "Q0";
    let mut text = format!("6\n{}\n", points.len());
    for p in points {
        let line: Vec<String> = p.iter().map(|x| format!("{x:e}")).collect();
        text.push_str(&line.join(" "));
        text.push('\n');
    }
    let run = |words: &[&str]| -> Result<String, String> {
        use std::io::Write;
        use std::process::{Command, Stdio};
        let mut child = Command::new("qhull")
            .args(words)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("qhull program: {e} (apt-get install qhull-bin)"))?;
        let mut stdin = child.stdin.take().ok_or("qhull program: no stdin")?;
        stdin
            .write_all(text.as_bytes())
            .map_err(|e| e.to_string())?;
        drop(stdin);
        let output = child.wait_with_output().map_err(|e| e.to_string())?;
        if output.status.success() {
            // The summary (`s`) goes to stderr, the listing (`i`) to stdout.
            let mut all = String::from_utf8_lossy(&output.stdout).into_owned();
            all.push_str(&String::from_utf8_lossy(&output.stderr));
            Ok(all)
        } else {
            Err(first_line(&String::from_utf8_lossy(&output.stderr), 90))
        }
    };
    let mut best = f64::INFINITY;
    for _ in 0..rounds.max(1) {
        match run(&["Q0", "Qt", "s"]) {
            Ok(summary) => {
                let seconds = summary
                    .lines()
                    .find_map(|l| l.split("(after input):").nth(1))
                    .and_then(|s| s.trim().parse::<f64>().ok());
                match seconds {
                    Some(s) => best = best.min(s * 1e3),
                    None => return println!("{lead} {label:<9} no time in Qhull's summary"),
                }
            }
            Err(e) => return println!("{lead} {label:<9} fails: {e}"),
        }
    }
    // The facets, on a further run (`i`: a count, then one line of vertex indices per facet).
    match run(&["Q0", "Qt", "i"]) {
        Ok(listing) => {
            let count: usize = listing
                .lines()
                .next()
                .and_then(|l| l.trim().parse().ok())
                .unwrap_or(0);
            let facets: Vec<Vec<usize>> = listing
                .lines()
                .skip(1)
                .take(count)
                .map(|l| {
                    l.split_whitespace()
                        .filter_map(|w| w.parse().ok())
                        .collect()
                })
                .collect();
            let slices: Vec<&[usize]> = facets.iter().map(Vec::as_slice).collect();
            let wrong = pqhull_cli::bench::perturb::wrong_facets(points, &slices);
            println!(
                "{lead} {label:<9} {best:>10.1} {:>7} {wrong:>7} {:>6.2}",
                facets.len(),
                best / pqhull_ms
            );
        }
        Err(e) => println!("{lead} {label:<9} fails: {e}"),
    }
}
