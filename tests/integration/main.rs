//! The library's integration tests, one binary with a module per theme (a binary per file linked
//! the whole library 20 times). Helpers and references shared by several modules are in
//! [`support`]; tests/allocation.rs is apart because it installs a counting global allocator.

mod support;

mod cases;
mod custom_strategy;
mod degenerate;
mod docs_paths;
mod ellipsoid;
mod evaluation;
mod extreme_scales;
mod far_query;
mod full_method_exact;
mod gradient;
mod grasp_quality;
mod hull_known;
mod hull_properties;
mod incremental;
mod layers;
mod mesh;
mod metrics;
mod min_norm_reference;
mod monotone_chain;
mod near_boundary;
mod ows;
mod ows_eq6;
mod penetration;
mod plan_metrics;
mod point_source;
mod qhull_crosscheck;
mod queries;
mod raw_reference;
mod soft;
mod trace;
mod without_qhull;
