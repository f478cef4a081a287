//! Writes a points file of `n` points uniform on the unit sphere in 3-D (every point a hull
//! vertex), for measuring `pqh hull` on large inputs (docs/benchmarks.md, issue 12).
//!
//! ```sh
//! cargo run --release --example sphere_points -- 1000000 > sphere-1e6.txt
//! ```
//!
//! Arguments: number of points (default 1000000), seed (default 20240601). The points are
//! `pqhull::rbox`'s `SphereSurface` family (radius 0.5) scaled by 2, which is exact; each
//! coordinate is written in the shortest form that reads back to the same `f64`.

use pqhull::rbox::{Family, generate};
use std::io::Write;

fn main() -> std::io::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number = |i: usize, default: u64| -> u64 {
        args.get(i).map_or(default, |a| {
            a.parse().unwrap_or_else(|_| {
                eprintln!("usage: sphere_points [points] [seed]");
                std::process::exit(2);
            })
        })
    };
    let n = number(0, 1_000_000) as usize;
    let seed = number(1, 20_240_601);
    let points = generate::<3>(&Family::SphereSurface, n, seed);
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    for p in &points {
        writeln!(out, "{} {} {}", 2.0 * p[0], 2.0 * p[1], 2.0 * p[2])?;
    }
    out.flush()
}
