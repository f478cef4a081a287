//! The tests of the `pqh` binary and of the application library (`pqhull_cli`): one binary, a
//! module per command or theme. Helpers are in [`support`].

mod support;

mod browser;
mod cdd_reference;
mod cli;
mod cli_limits;
mod cli_metrics;
mod cli_ows;
mod cli_plan;
mod cli_raw_reference;
mod cli_stream;
mod fuzz_bounded;
mod hull_queries;
mod penetration_cmd;
mod perturbed_sum;
mod plan_descent;
mod reproduce;
mod ridge_census;
mod trace_cmd;
