//! pqhull's exact hull against an independent exact one, cddlib's (`scdd_gmp`: the double
//! description method in GMP rationals, `apt-get install libcdd-tools`), on the grasp sets of
//! `pqh bench hull`, where Qhull's answer is not exact: the two compared facet by facet
//! (`pqhull_cli::bench::cdd`), and the three engines' times side by side (Qhull's with
//! `--features qhull`).
//!
//! ```sh
//! cargo build --release -p pqhull-cli --features qhull --example compare_cdd
//! ./target/release/examples/compare_cdd minkowski 4     # 3 contacts × 4 edges: 64 points
//! ./target/release/examples/compare_cdd minkowski 6     # 216 points: about 4 minutes
//! ./target/release/examples/compare_cdd wrenches 8      # 4 contacts × 8 edges: 32 points
//! ```
//!
//! Arguments: the set (`minkowski`: the raw sum of 3 contacts; `wrenches`: the raw wrenches of
//! 4), cone edges, rounds for pqhull's and Qhull's best time (3; cddlib runs once).
//! `PQHULL_SCDD` names another `scdd_gmp`.

use pqhull::Hull;
use pqhull_cli::bench::cdd::{compare, run_scdd, scdd_program};
use pqhull_cli::bench::hull::grasp_points;
use pqhull_cli::bench::stats::{best_of, numeric_args};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: compare_cdd minkowski|wrenches [edges] [rounds]";
    let [edges, rounds] = numeric_args(&args, 1, [4, 3]).unwrap_or_else(|e| {
        eprintln!("{usage}: {e}");
        std::process::exit(2);
    });
    let rounds = rounds.max(1);
    let (contacts, full_sum) = match args.first().map(String::as_str) {
        Some("minkowski") => (3, true),
        Some("wrenches") => (4, false),
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    };
    let (_, _, points) = grasp_points(1, contacts, edges, full_sum);
    let mut hull = None;
    let pqhull_time = best_of(rounds, || {
        hull = Some(Hull::try_new(&points).expect("a 6-D hull"))
    });
    let hull = hull.expect("built");
    hull.check().expect("Hull::check");
    let scratch = std::env::temp_dir().join(format!("pqhull-compare-cdd-{}", std::process::id()));
    let reference = run_scdd(&points, &scdd_program(), &scratch).unwrap_or_else(|e| {
        eprintln!("{e}");
        std::process::exit(1);
    });
    let _ = std::fs::remove_dir_all(&scratch);
    let agreement = compare(&hull, &points, &reference);
    println!(
        "{} {contacts}x{edges} ({} points): cddlib {} facets, pqhull {} simplices; {}",
        args[0],
        points.len(),
        agreement.cdd_facets,
        agreement.simplices,
        if agreement.agrees() {
            "the same polytope".to_string()
        } else {
            format!("DIFFERENT: {agreement:?}")
        }
    );
    println!(
        "cddlib (scdd_gmp, one run) {:.1} ms; pqhull Hull::try_new (best of {rounds}) {:.3} ms",
        reference.elapsed.as_secs_f64() * 1e3,
        pqhull_time.as_secs_f64() * 1e3
    );
    #[cfg(feature = "qhull")]
    {
        let mut facets = None;
        let qhull_time = best_of(rounds, || {
            facets = Some(pqhull::qhull_baseline::qhull_facet_count(&points))
        });
        let verdict = match facets.expect("run") {
            // Each facet hyperplane of the exact hull holds at least one simplex of any
            // triangulation of it.
            Ok(n) if n < agreement.cdd_facets => format!(
                "{n} triangulated facets, fewer than the exact hull's {} facet hyperplanes: \
                 not the exact hull",
                agreement.cdd_facets
            ),
            Ok(n) => format!("{n} triangulated facets"),
            Err(e) => e.to_string(),
        };
        println!(
            "Qhull qhull_facet_count (best of {rounds}) {:.3} ms: {verdict}",
            qhull_time.as_secs_f64() * 1e3
        );
    }
    if !agreement.agrees() {
        std::process::exit(1);
    }
}
