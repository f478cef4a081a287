//! `pqh trace`: a strategy's run, step by step, as a self-contained HTML page.

use crate::error::CliError;
use clap::Args;

pub const LONG_ABOUT: &str = "Renders a strategy's run step by step (not built yet).";

#[derive(Debug, Args)]
pub struct TraceArgs {}

pub fn run(_args: &TraceArgs) -> Result<(), CliError> {
    Err(CliError::Usage("pqh trace is not built yet".into()))
}
