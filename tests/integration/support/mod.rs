//! Test-only helpers shared by the integration tests (`mod support;`).
//!
//! Independent of the hull engine on purpose: results computed here are the reference the engine
//! is checked against.
#![allow(dead_code)]

pub mod brute_inside;
pub mod cases;
pub mod exact_lp;
pub mod grasps;
pub mod min_norm;
#[cfg(feature = "qhull")]
pub mod raw_reference;

#[allow(unused_imports)]
pub use grasps::{BAR_FRICTION, bar_grasps};
#[allow(unused_imports)]
pub use min_norm::min_norm_point;

/// The unit normal of the hyperplane through six points of 6-D, by Gram–Schmidt on the edges
/// from the first (the axis with the largest part off their span, reduced and normalised), and
/// the shortest edge part met on the way (near zero when the points are affinely dependent).
pub fn simplex_normal(w: &[[f64; 6]]) -> ([f64; 6], f64) {
    let dot = |a: &[f64; 6], b: &[f64; 6]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let reduce = |mut v: [f64; 6], basis: &[[f64; 6]]| {
        for b in basis {
            let c = dot(&v, b);
            v.iter_mut().zip(b).for_each(|(x, y)| *x -= c * y);
        }
        v
    };
    let mut basis: Vec<[f64; 6]> = Vec::new();
    let mut shortest = f64::INFINITY;
    for p in &w[1..] {
        let edge: [f64; 6] = std::array::from_fn(|c| p[c] - w[0][c]);
        let v = reduce(edge, &basis);
        let l = dot(&v, &v).sqrt();
        shortest = shortest.min(l);
        basis.push(v.map(|x| x / l));
    }
    let normal = (0..6)
        .map(|k| {
            let mut e = [0.0; 6];
            e[k] = 1.0;
            reduce(e, &basis)
        })
        .max_by(|a, b| dot(a, a).total_cmp(&dot(b, b)))
        .unwrap_or([0.0; 6]);
    let length = dot(&normal, &normal).sqrt();
    (normal.map(|x| x / length), shortest)
}

/// The path of `tests/data/<name>` in the workspace, from the tests of either package (their
/// `CARGO_MANIFEST_DIR`s differ).
///
/// # Panics
/// If the file is missing: a test's data is part of the repository.
pub fn data_file(name: &str) -> String {
    let here = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    here.ancestors()
        .map(|dir| dir.join("tests/data").join(name))
        .find(|path| path.exists())
        .unwrap_or_else(|| panic!("tests/data/{name} is missing"))
        .to_string_lossy()
        .into_owned()
}

/// Converts fixed-size points to the `Vec<Vec<f64>>` form the helpers take.
pub fn points_as_vecs<const D: usize>(p: &[[f64; D]]) -> Vec<Vec<f64>> {
    p.iter().map(|x| x.to_vec()).collect()
}
