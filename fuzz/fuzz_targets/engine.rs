//! Fuzz target `engine`: its body is `engine` in tests/support/fuzz_bodies.rs, shared with the
//! bounded replay on stable (tests/fuzz_bounded.rs).
#![no_main]

#[path = "../../tests/support/fuzz_bodies.rs"]
mod bodies;

libfuzzer_sys::fuzz_target!(|data: &[u8]| bodies::engine(data));
