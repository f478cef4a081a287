//! A profiling target: `Hull::try_new` on one of `pqh bench hull`'s `rbox` families alone, run
//! over and over, so that `perf record` sees only the build (the bench also runs Qhull and,
//! untimed, `Hull::check`).
//!
//! ```sh
//! cargo build --release -p pqhull-cli --example profile_rbox
//! perf record -e cpu-clock -g ./target/release/examples/profile_rbox corners 6 2000 20
//! perf report --no-children
//! ```
//!
//! Arguments: the family (`pqhull::rbox::Family`'s names: `cube`, `sphere`, `corners`,
//! `lattice`, `clusters`, …), the dimension (2 to 8), `rbox`'s `n` and the rounds (5); the seed
//! is the suite's (1), so `corners 6 2000` is the suite's 6-D corners row. Prints the best and
//! mean time per build and the last build's work: its `Stats` (a build that ran a second phase,
//! `hull/coplanar.rs`, processed 2(D + 1) points beyond its expansions), final facets and
//! vertices; built with `--features qhull`, Qhull's final and created facets too.

use pqhull::hull::Hull;
use pqhull::rbox::{self, Family};
use std::time::Instant;

fn run<const D: usize>(family: &Family, n: usize, rounds: usize) {
    let points = rbox::generate::<D>(family, n, 1);
    let (mut best, mut total, mut work) = (f64::INFINITY, 0.0, String::new());
    for _ in 0..rounds {
        let started = Instant::now();
        work = match Hull::try_new(&points) {
            Ok(h) => format!(
                "{:?}, {} facets, {} vertices in the end",
                h.stats(),
                h.facet_count(),
                h.vertex_indices().len()
            ),
            Err(e) => e.to_string(),
        };
        let ms = started.elapsed().as_secs_f64() * 1e3;
        best = best.min(ms);
        total += ms;
    }
    println!(
        "{family} {D}-D ({} points): best {best:.3} ms, mean {:.3} ms over {rounds}",
        points.len(),
        total / rounds as f64
    );
    println!("{work}");
    // Qhull's counts on the same points (built with `--features qhull`), untimed.
    #[cfg(feature = "qhull")]
    match pqhull::qhull_baseline::qhull_stats(&points) {
        Ok(q) => println!(
            "qhull: {} facets in the end, about {} created, {} vertices",
            q.facets, q.facets_created, q.vertices
        ),
        Err(e) => println!("qhull: {e}"),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: profile_rbox FAMILY DIMENSION(2-8) N [ROUNDS]";
    let fail = |message: String| -> ! {
        eprintln!("{usage}: {message}");
        std::process::exit(2);
    };
    let family: Family = match args.first().map(|s| s.parse()) {
        Some(Ok(family)) => family,
        Some(Err(e)) => fail(format!("{e}")),
        None => fail("no family".to_string()),
    };
    let number = |i: usize, default: Option<usize>| -> usize {
        match (args.get(i), default) {
            (Some(s), _) => s
                .parse()
                .unwrap_or_else(|_| fail(format!("not a number: {s}"))),
            (None, Some(d)) => d,
            (None, None) => fail("missing argument".to_string()),
        }
    };
    let (dimension, n, rounds) = (number(1, None), number(2, None), number(3, Some(5)).max(1));
    match dimension {
        2 => run::<2>(&family, n, rounds),
        3 => run::<3>(&family, n, rounds),
        4 => run::<4>(&family, n, rounds),
        5 => run::<5>(&family, n, rounds),
        6 => run::<6>(&family, n, rounds),
        7 => run::<7>(&family, n, rounds),
        8 => run::<8>(&family, n, rounds),
        d => fail(format!("dimension {d} is not 2 to 8")),
    }
}
