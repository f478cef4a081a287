//! Fuzz target `grasp_json`: its body is `grasp_json` in tests/support/fuzz_bodies.rs, shared with the
//! bounded replay on stable (tests/fuzz_bounded.rs).
#![no_main]

#[path = "../../tests/support/fuzz_bodies.rs"]
mod bodies;

libfuzzer_sys::fuzz_target!(|data: &[u8]| bodies::grasp_json(data));
