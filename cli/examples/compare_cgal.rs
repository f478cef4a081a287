//! pqhull's exact hull beside CGAL's exact d-dimensional triangulation (`compare/cgal/hull.cpp`,
//! built by hand: its header gives the commands) and, with `--features qhull`, Qhull, on the
//! grasp sets of `pqh bench hull`, where Qhull's answer is not the exact hull, and on generic
//! input for scale: the engines' times side by side, each the best of the same rounds.
//!
//! ```sh
//! cargo build --release -p pqhull-cli --features qhull --example compare_cgal
//! g++ -O3 -DNDEBUG -std=c++17 -I/usr/include/eigen3 -DCGAL_EIGEN3_ENABLED \
//!     -o cgal_hull compare/cgal/hull.cpp -lgmpxx -lgmp -lmpfr
//! PQHULL_CGAL=$PWD/cgal_hull ./target/release/examples/compare_cgal minkowski 6
//! PQHULL_CGAL=$PWD/cgal_hull ./target/release/examples/compare_cgal wrenches 8
//! PQHULL_CGAL=$PWD/cgal_hull ./target/release/examples/compare_cgal sphere 300
//! ```
//!
//! Arguments: the set (`minkowski`: the raw sum of 3 contacts; `wrenches`: the raw wrenches of
//! 4; or, for generic input beside them, the `rbox` families `sphere` and `cube` in 6-D, seed 1),
//! cone edges or points (6), rounds (3). `PQHULL_CGAL` names the CGAL program (default `cgal_hull` on the
//! `PATH`); it reads the points as exact rationals (`pqhull_cli::bench::cdd::write_ext`).

use pqhull::Hull;
use pqhull::rbox::{self, Family};
use pqhull_cli::bench::cdd::write_ext;
use pqhull_cli::bench::hull::grasp_points;
use pqhull_cli::bench::stats::{best_of, numeric_args};
use std::path::PathBuf;
use std::process::Command;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: compare_cgal minkowski|wrenches [edges] [rounds], \
                 or compare_cgal sphere|cube [points] [rounds]";
    let [size, rounds] = numeric_args(&args, 1, [6, 3]).unwrap_or_else(|e| {
        eprintln!("{usage}: {e}");
        std::process::exit(2);
    });
    let rounds = rounds.max(1);
    let set = args.first().map_or("", String::as_str);
    let (label, points): (String, Vec<[f64; 6]>) = match set {
        "minkowski" | "wrenches" => {
            let (contacts, full_sum) = if set == "minkowski" {
                (3, true)
            } else {
                (4, false)
            };
            let (_, _, points) = grasp_points(1, contacts, size, full_sum);
            (format!("{set} {contacts}x{size}"), points)
        }
        "sphere" | "cube" => {
            let family = if set == "sphere" {
                Family::SphereSurface
            } else {
                Family::UniformCube
            };
            (format!("{set} 6-D"), rbox::generate::<6>(&family, size, 1))
        }
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    };
    let mut hull = None;
    let pqhull_time = best_of(rounds, || {
        hull = Some(Hull::try_new(&points).expect("a 6-D hull"))
    });
    let hull = hull.expect("built");
    hull.check().expect("Hull::check");
    println!(
        "{label} ({} points)\npqhull Hull::try_new (best of {rounds}) {:.3} ms: \
         {} hull simplices, {} vertices",
        points.len(),
        pqhull_time.as_secs_f64() * 1e3,
        hull.facets().count(),
        hull.vertex_indices().len()
    );
    #[cfg(feature = "qhull")]
    {
        let mut facets = None;
        let qhull_time = best_of(rounds, || {
            facets = Some(pqhull::qhull_baseline::qhull_facet_count(&points))
        });
        match facets.expect("run") {
            Ok(n) => println!(
                "Qhull qhull_facet_count (best of {rounds}) {:.3} ms: {n} triangulated facets{}",
                qhull_time.as_secs_f64() * 1e3,
                if set == "minkowski" || set == "wrenches" {
                    " (merged: not the exact hull, docs/benchmarks.md)"
                } else {
                    ""
                }
            ),
            Err(e) => println!("Qhull: {e}"),
        }
    }
    let scratch = std::env::temp_dir().join(format!("pqhull-compare-cgal-{}", std::process::id()));
    let input = scratch.join("points.ext");
    if let Err(e) = std::fs::create_dir_all(&scratch)
        .map_err(|e| e.to_string())
        .and_then(|()| write_ext(&points, &input).map_err(|e| e.to_string()))
    {
        eprintln!("{e}");
        std::process::exit(1);
    }
    let program =
        std::env::var_os("PQHULL_CGAL").map_or_else(|| PathBuf::from("cgal_hull"), PathBuf::from);
    let run = Command::new(&program)
        .arg(&input)
        .arg(rounds.to_string())
        .output();
    let _ = std::fs::remove_dir_all(&scratch);
    match run {
        Ok(out) if out.status.success() => print!("{}", String::from_utf8_lossy(&out.stdout)),
        Ok(out) => {
            eprintln!(
                "{} failed: {}",
                program.display(),
                String::from_utf8_lossy(&out.stderr)
            );
            std::process::exit(1);
        }
        Err(e) => {
            eprintln!(
                "cannot run {} ({e}): build compare/cgal/hull.cpp (its header) and name it \
                 with PQHULL_CGAL",
                program.display()
            );
            std::process::exit(1);
        }
    }
}
