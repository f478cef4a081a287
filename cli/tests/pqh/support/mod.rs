//! Helpers of the `pqh` tests: running the binary ([`run`]), the fuzz targets' bodies
//! ([`fuzz_bodies`], shared with fuzz/) and the library tests' own references ([`library`],
//! the one support module of tests/integration/, mounted here rather than copied).
#![allow(dead_code)]

pub mod fuzz_bodies;
#[path = "../../../../tests/integration/support/mod.rs"]
pub mod library;
pub mod run;
