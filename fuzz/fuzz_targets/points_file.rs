//! Fuzz target `points_file`: its body is `points_file` in tests/support/fuzz_bodies.rs, shared with the
//! bounded replay on stable (tests/fuzz_bounded.rs).
#![no_main]

#[path = "../../tests/support/fuzz_bodies.rs"]
mod bodies;

libfuzzer_sys::fuzz_target!(|data: &[u8]| bodies::points_file(data));
