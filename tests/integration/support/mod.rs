//! Test-only helpers shared by the integration tests (`mod support;`).
//!
//! Independent of the hull engine on purpose: results computed here are the reference the engine
//! is checked against.
#![allow(dead_code)]

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
