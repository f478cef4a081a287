//! Criterion benchmarks of the grasp metrics (placeholder until written).
fn main() {}
