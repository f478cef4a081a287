//! Scratch.
use pqhull::hull::Hull;
use std::time::Instant;
fn run<const D: usize>(text: &str, rounds: usize) {
    let points: Vec<[f64; D]> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            std::array::from_fn(|i| v[i])
        })
        .collect();
    let mut best = f64::INFINITY;
    let mut work = String::new();
    for _ in 0..rounds {
        let t = Instant::now();
        let h = Hull::try_new(&points).unwrap();
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
        work = format!(
            "{:?} {} facets {} vertices",
            h.stats(),
            h.facet_count(),
            h.vertex_indices().len()
        );
    }
    println!("best {best:.3} ms; {work}");
    #[cfg(feature = "qhull")]
    {
        let mut best = f64::INFINITY;
        for _ in 0..rounds {
            let t = Instant::now();
            let c = pqhull::qhull_baseline::qhull_facet_count(&points).unwrap();
            best = best.min(t.elapsed().as_secs_f64() * 1e3);
            let _ = c;
        }
        println!(
            "qhull best {best:.3} ms {:?}",
            pqhull::qhull_baseline::qhull_stats(&points).map(|q| (
                q.facets,
                q.facets_created,
                q.vertices
            ))
        );
    }
}
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&a[1]).unwrap();
    let d = text.lines().next().unwrap().split_whitespace().count();
    let rounds = a.get(2).map(|r| r.parse().unwrap()).unwrap_or(5);
    match d {
        2 => run::<2>(&text, rounds),
        3 => run::<3>(&text, rounds),
        4 => run::<4>(&text, rounds),
        5 => run::<5>(&text, rounds),
        6 => run::<6>(&text, rounds),
        _ => panic!(),
    }
}
