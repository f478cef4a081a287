//! Fuzz target `engine`: its body is `engine` in cli/tests/pqh/support/fuzz_bodies.rs, shared with the
//! bounded replay on stable (cli/tests/pqh/fuzz_bounded.rs).
#![no_main]

#[path = "../../cli/tests/pqh/support/fuzz_bodies.rs"]
mod bodies;

libfuzzer_sys::fuzz_target!(|data: &[u8]| bodies::engine(data));
