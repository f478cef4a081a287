//! Fuzz target `mesh_stl`: its body is `mesh_stl` in tests/support/fuzz_bodies.rs, shared with the
//! bounded replay on stable (tests/fuzz_bounded.rs).
#![no_main]

#[path = "../../tests/support/fuzz_bodies.rs"]
mod bodies;

libfuzzer_sys::fuzz_target!(|data: &[u8]| bodies::mesh_stl(data));
