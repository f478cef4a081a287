//! How much memory a full 3-D hull takes: the points of `examples/sphere_points` (the same `n`
//! and seed give the same points), built with `Hull::try_new`, with the process's resident set
//! before and after (Linux `/proc/self/status`; "n/a" elsewhere) and the size of the facet arena.
//! The reference for `pqh hull`'s peak memory in docs/benchmarks.md (issue 12).
//!
//! ```sh
//! cargo run --release --example hull_footprint -- 1000000
//! ```
//!
//! Arguments: number of points (default 1000000), seed (default 20240601).

use pqhull::rbox::{Family, generate};
use pqhull::{Facet, Hull};

/// A `kB` line of `/proc/self/status` (`VmRSS`, `VmHWM`), in MB (2^20 bytes, as the other
/// figures).
fn status_mb(key: &str) -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(key))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb / 1024.0)
}

fn show(value: Option<f64>) -> String {
    value.map_or_else(|| "n/a".to_string(), |mb| format!("{mb:.0} MB"))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number = |i: usize, default: u64| -> u64 {
        args.get(i).map_or(default, |a| {
            a.parse().unwrap_or_else(|_| {
                eprintln!("usage: hull_footprint [points] [seed]");
                std::process::exit(2);
            })
        })
    };
    let n = number(0, 1_000_000) as usize;
    let seed = number(1, 20_240_601);
    let points: Vec<[f64; 3]> = generate::<3>(&Family::SphereSurface, n, seed)
        .into_iter()
        .map(|p| p.map(|x| 2.0 * x))
        .collect();
    let before = status_mb("VmRSS:");
    let hull = Hull::try_new(&points).expect("a full-dimensional sphere");
    let after = status_mb("VmRSS:");
    let peak = status_mb("VmHWM:");
    let slots = hull.facets().last().map_or(0, |(id, _)| id.index() + 1);
    let facet_bytes = std::mem::size_of::<Facet<3>>();
    println!(
        "{n} points on the unit sphere (seed {seed}): {} vertices, {} facets, {} facets created",
        hull.vertex_indices().len(),
        hull.facet_count(),
        hull.stats().facets_created
    );
    println!(
        "facet arena: {slots} slots × {facet_bytes} B = {:.0} MB; points: {:.0} MB (the caller's \
         and the hull's copy)",
        (slots * facet_bytes) as f64 / (1 << 20) as f64,
        (2 * n * std::mem::size_of::<[f64; 3]>()) as f64 / (1 << 20) as f64
    );
    println!(
        "resident: {} with the points, {} with the hull too (hull: {}); peak {}",
        show(before),
        show(after),
        show(after.zip(before).map(|(a, b)| a - b)),
        show(peak)
    );
}
