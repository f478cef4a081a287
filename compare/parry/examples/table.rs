//! Prints the markdown table of docs/benchmarks.md, "Penetration depth against parry3d's EPA
//! (issue 27)": for every pair of `pqhull_parry_compare::pairs()`, the depth by pqhull, by
//! parry3d-f64 and by parry3d (f32), a reference (analytic, and Qhull on every difference
//! `a − b`), and the median time of each.
//!
//! `cargo run --release -p pqhull-parry-compare --example table`
//!
//! pqhull is timed on the raw points (it needs no preprocessing). parry's shapes are built once
//! per pair by `ConvexPolyhedron::from_convex_hull` (its own hull of the points); that build is
//! timed separately and is *not* in parry's query time, which is `query::contact` alone
//! (identity poses, prediction 10 so that separated pairs report their distance).

use pqhull::qhull_baseline::{qhull_full_hull, qhull_origin_distance};
use pqhull::strategy::{Relation, penetration_depth};
use pqhull_parry_compare::{Pair, differences, origin_triangle_distance, pairs};
use std::hint::black_box;
use std::time::{Duration, Instant};

#[path = "../shared/parry_adapter.rs"]
mod parry_adapter;
use parry_adapter::{parry32, parry64};

/// The median over batches of the mean time of one call: batches of at least ~0.3 ms, 5 to 101
/// of them within ~0.25 s.
fn median_time(mut f: impl FnMut()) -> Duration {
    let start = Instant::now();
    f();
    let once = start.elapsed().max(Duration::from_nanos(20));
    let per_batch = (300_000 / once.as_nanos()).clamp(1, 100_000) as u32;
    let batch = once * per_batch;
    let batches = (250_000_000 / batch.as_nanos().max(1)).clamp(5, 101) as usize;
    let mut times: Vec<Duration> = (0..batches)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..per_batch {
                f();
            }
            t.elapsed() / per_batch
        })
        .collect();
    times.sort();
    times[times.len() / 2]
}

fn time(d: Duration) -> String {
    let us = d.as_secs_f64() * 1e6;
    if us < 10.0 {
        format!("{us:.2} µs")
    } else if us < 1000.0 {
        format!("{us:.1} µs")
    } else {
        format!("{:.2} ms", us / 1000.0)
    }
}

fn diff(x: f64, y: f64) -> String {
    let d = x - y;
    if d == 0.0 {
        "0".to_string()
    } else {
        format!("{d:+.1e}")
    }
}

/// Qhull's hull of every difference: the signed distance from the origin to its boundary, as
/// the sign of Qhull's facet-plane value and the least distance to a (triangulated) facet.
fn qhull_reference(pair: &Pair) -> Result<f64, String> {
    let d = differences(&pair.a, &pair.b);
    let plane = qhull_origin_distance(&d).map_err(|e| e.to_string())?;
    let hull = qhull_full_hull(&d).map_err(|e| e.to_string())?;
    let nearest = hull
        .facets
        .iter()
        .filter(|f| f.vertices.len() == 3)
        .map(|f| origin_triangle_distance([d[f.vertices[0]], d[f.vertices[1]], d[f.vertices[2]]]))
        .fold(f64::INFINITY, f64::min);
    Ok(if plane >= 0.0 { nearest } else { -nearest })
}

fn main() {
    let started = Instant::now();
    println!(
        "| pair | config | analytic | Qhull on all a − b | pqhull depth | pqhull − ref | \
         parry3d-f64 depth | parry-f64 − pqhull | parry3d (f32) − pqhull | pqhull time | \
         parry-f64 query | parry-f32 query | parry-f64 hull build (both) |"
    );
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut notes = Vec::new();
    for pair in pairs() {
        let qhull = qhull_reference(&pair);
        let reference = pair.analytic.or(qhull.as_ref().ok().copied());

        let ours = penetration_depth(&pair.a, &pair.b);
        let (ours_depth, ours_text) = match &ours {
            Ok(p) => {
                let tag = match p.relation {
                    Relation::Overlapping => "",
                    Relation::Touching => " (touching)",
                    Relation::Separated => "",
                };
                (Some(p.depth), format!("{}{tag}", p.depth))
            }
            Err(e) => (None, format!("error: {e}")),
        };
        let ours_time = median_time(|| {
            black_box(penetration_depth(black_box(&pair.a), black_box(&pair.b)).ok());
        });

        let build64 = median_time(|| {
            black_box(parry64::shape(&pair.a));
            black_box(parry64::shape(&pair.b));
        });
        let shapes64 = parry64::shape(&pair.a).zip(parry64::shape(&pair.b));
        let shapes32 = parry32::shape(&pair.a).zip(parry32::shape(&pair.b));
        let (theirs, theirs_time) = match &shapes64 {
            Some((a, b)) => (
                Ok(parry64::depth(a, b)),
                Some(median_time(|| {
                    black_box(parry64::depth(black_box(a), black_box(b)));
                })),
            ),
            None => (Err(()), None),
        };
        let (theirs32, theirs32_time) = match &shapes32 {
            Some((a, b)) => (
                Ok(parry32::depth(a, b)),
                Some(median_time(|| {
                    black_box(parry32::depth(black_box(a), black_box(b)));
                })),
            ),
            None => (Err(()), None),
        };

        let show = |v: &Result<Option<f64>, ()>| match v {
            Ok(Some(x)) => x.to_string(),
            Ok(None) => "no contact".to_string(),
            Err(()) => "hull failed".to_string(),
        };
        let vs_ours = |v: &Result<Option<f64>, ()>| match (v, ours_depth) {
            (Ok(Some(x)), Some(o)) => diff(*x, o),
            _ => "—".to_string(),
        };
        let analytic = pair.analytic.map_or("—".to_string(), |x| x.to_string());
        let qhull_text = match &qhull {
            Ok(x) => x.to_string(),
            Err(e) => format!("error: {e}"),
        };
        let ours_vs_ref = match (ours_depth, reference) {
            (Some(o), Some(r)) => diff(o, r),
            _ => "—".to_string(),
        };
        let opt_time = |t: Option<Duration>| t.map_or("—".to_string(), time);
        println!(
            "| {} | {} | {analytic} | {qhull_text} | {ours_text} | {ours_vs_ref} | {} | {} | {} \
             | {} | {} | {} | {} |",
            pair.family,
            pair.config,
            show(&theirs),
            vs_ours(&theirs),
            vs_ours(&theirs32),
            time(ours_time),
            opt_time(theirs_time),
            opt_time(theirs32_time),
            time(build64),
        );
        if let (Ok(t), Some(r)) = (&theirs, reference) {
            let off = t.is_none_or(|t| (t - r).abs() > 1e-9 * (1.0 + r.abs()));
            if off {
                notes.push(format!(
                    "parry3d-f64 differs from the reference on {} {}: {} vs {r}",
                    pair.family,
                    pair.config,
                    show(&theirs)
                ));
            }
        }
        if let (Some(o), Some(r)) = (ours_depth, reference) {
            let scale = ours.as_ref().map_or(1.0, |p| p.scale);
            if (o - r).abs() > 1e-12 * r.abs() + 1e-14 * scale {
                notes.push(format!(
                    "pqhull differs from the reference on {} {}: {o} vs {r}",
                    pair.family, pair.config
                ));
            }
        }
    }
    println!();
    println!(
        "parry's query time excludes its hull build (last column, both bodies, f64); pqhull's \
         time is the whole call on the raw points. Medians over batches; total run {:.1} s.",
        started.elapsed().as_secs_f64()
    );
    for note in notes {
        println!("note: {note}");
    }
}
