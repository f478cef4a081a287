//! Test-only helpers shared by the integration tests (`mod support;`).
//!
//! Independent of the hull engine on purpose: results computed here are the reference the engine
//! is checked against.
#![allow(dead_code)]

pub mod min_norm;

#[allow(unused_imports)]
pub use min_norm::min_norm_point;

/// Converts fixed-size points to the `Vec<Vec<f64>>` form the helpers take.
pub fn points_as_vecs<const D: usize>(p: &[[f64; D]]) -> Vec<Vec<f64>> {
    p.iter().map(|x| x.to_vec()).collect()
}
