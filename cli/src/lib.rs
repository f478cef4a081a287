//! # pqhull-cli — the application around the `pqhull` library
//!
//! The `pqh` binary's library half: what the command-line tool measures and reproduces, kept out
//! of the `pqhull` library so that a library user gets neither clap, indicatif nor plotters.
//!
//! * [`bench`](mod@bench) — the benchmark harness behind `pqh bench` and `pqh compare`;
//! * [`reproduce`] — the seed paper's experiments behind `pqh reproduce`;
//! * [`points_file`] — the points-file format `pqh hull` reads;
//! * [`object`] — the built-in object (Keenan Crane's spot.obj) of `pqh demo` and `pqh plan`.
#![forbid(unsafe_code)]

pub mod bench;
pub mod object;
pub mod points_file;
pub mod reproduce;
