use pqhull::grasp::{Contact, FrictionModel, Grasp};
use pqhull::rbox::Rng;
use pqhull::{ClosestToOrigin, Hull};
use std::time::Instant;

fn random_grasp(rng: &mut Rng, k: usize) -> Grasp {
    let half = [0.5, 0.2, 0.1];
    let contacts = (0..4).map(|_| {
        let axis = (rng.uniform() * 3.0) as usize % 3;
        let sign = if rng.uniform() < 0.5 { -1.0 } else { 1.0 };
        let mut p = [0.0; 3];
        for c in 0..3 { p[c] = (rng.uniform() * 2.0 - 1.0) * half[c]; }
        p[axis] = sign * half[axis];
        let mut n = [0.0; 3];
        n[axis] = -sign;
        Contact::try_new(p, n, None).unwrap()
    }).collect();
    let rho = (half[0]*half[0]+half[1]*half[1]+half[2]*half[2]) as f64;
    Grasp::builder(contacts, FrictionModel::try_new(0.5, k).unwrap()).torque_scale(rho.sqrt()).build().unwrap()
}

fn main() {
    let k: usize = std::env::args().nth(1).map(|s| s.parse().unwrap()).unwrap_or(32);
    let n: usize = std::env::args().nth(2).map(|s| s.parse().unwrap()).unwrap_or(10);
    let mut rng = Rng::new(7);
    for _ in 0..n {
        let g = random_grasp(&mut rng, k);
        let w = if std::env::var("Q").is_ok() { quantized(&g, k) } else { g.wrenches() };
        let t = Instant::now();
        let full = if std::env::var("P").is_ok() { Hull::try_new(&[[0.0;6],[1.,0.,0.,0.,0.,0.],[0.,1.,0.,0.,0.,0.],[0.,0.,1.,0.,0.,0.],[0.,0.,0.,1.,0.,0.],[0.,0.,0.,0.,1.,0.],[0.,0.,0.,0.,0.,1.]]) } else { Hull::try_new(&w) };
        let tf = t.elapsed();
        let t = Instant::now();
        let part = Hull::try_with_strategy(&w, ClosestToOrigin::new());
        let tp = t.elapsed();
        match (full, part) {
            (Ok(f), Ok((_, r))) => println!("full {:>8.2?} facets_created {:>7} live {:>6} | partial {:>8.2?} pts {:>4} created {:>6} d={:.6e} ratio {:.1}",
                tf, f.stats().facets_created, f.facet_count(), tp, r.stats.points_processed, r.stats.facets_created, r.signed_distance, tf.as_secs_f64()/tp.as_secs_f64()),
            (a, b) => println!("err {:?} {:?}", a.err(), b.err()),
        }
    }
}

fn quantized(g: &Grasp, k: usize) -> Vec<[f64; 6]> {
    let b = 24;
    let mu = g.friction().friction();
    let mut terms = vec![];
    for c in g.contacts() {
        let r = c.position();
        let rho = g.torque_scale();
        let a = |f: [f64; 3]| -> [f64; 6] {
            let t = [r[1]*f[2]-r[2]*f[1], r[2]*f[0]-r[0]*f[2], r[0]*f[1]-r[1]*f[0]];
            [f[0], f[1], f[2], t[0]/rho, t[1]/rho, t[2]/rho]
        };
        let n = c.normal(); let t = c.tangent(); let bt = c.bitangent();
        terms.push([a(n), a(t.map(|x| x*mu)), a(bt.map(|x| x*mu))]);
    }
    let mut grid = [0.0f64; 6];
    for c in 0..6 {
        let m = terms.iter().flat_map(|t| t.iter().map(|w| w[c].abs())).fold(0.0, f64::max);
        let e = if m == 0.0 { 0 } else { m.log2().floor() as i32 + 1 };
        grid[c] = 2f64.powi(e - b);
    }
    let q = |x: f64, g: f64| (x / g).round() * g;
    let cg = 2f64.powi(-b);
    let mut out = vec![];
    for t in &terms {
        for j in 0..k {
            let (s, co) = (2.0 * std::f64::consts::PI * j as f64 / k as f64).sin_cos();
            let (s, co) = (q(s, cg), q(co, cg));
            out.push(std::array::from_fn(|c| q(t[0][c], grid[c]) + co * q(t[1][c], grid[c]) + s * q(t[2][c], grid[c])));
        }
    }
    out
}
