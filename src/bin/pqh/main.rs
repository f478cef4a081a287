//! `pqh`: the pqhull command-line tool.
//!
//! Parsing, I/O and output only; every computation is a call into the `pqhull` library.

mod bench_cmd;
mod bench_ows;
mod compare_cmd;
mod demo_cmd;
mod error;
mod grasp_cmd;
mod hull_cmd;
mod input;
mod plan_cmd;
mod plan_view;
mod progress;
mod trace_cmd;

use clap::{Parser, Subcommand};
use error::CliError;
use std::process::ExitCode;

const EXIT_STATUS_HELP: &str = "\
Exit status:
  0  success
  1  the points admit no hull (too few, or affinely dependent: all on one line, plane, ...)
  2  usage or input error (bad option, unreadable file, malformed points file, unsupported
     dimension)

Errors are reported on stderr as one line starting with 'pqh: '.";

/// Exact convex hulls and partial hulls in 2 to 8 dimensions.
#[derive(Debug, Parser)]
#[command(
    name = "pqh",
    version,
    about = "Exact convex hulls and partial hulls (QuickHull) in 2 to 8 dimensions",
    long_about = "\
pqh builds convex hulls of point sets in 2 to 8 dimensions with an exact QuickHull engine
(pqhull). Besides the full hull it can grow a *partial* hull toward a query point and stop as soon
as the facet nearest that point is certain: the signed distance from the point to the hull
boundary, which is the Ferrari-Canny grasp quality metric when the points are contact wrenches
and the query is the origin.

Points files: one point per line, coordinates separated by commas and/or whitespace, '#' starts
a comment; the dimension is the number of coordinates on the first row.",
    after_help = EXIT_STATUS_HELP,
    propagate_version = true
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// No progress bars (they are shown only when stderr is a terminal anyway)
    #[arg(long, global = true)]
    quiet: bool,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Convex hull of a points file (full, or partial toward a query point)
    #[command(long_about = hull_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Hull(hull_cmd::HullArgs),
    /// Grasp quality (Q1, Q∞) of grasps given as JSON, one JSON line per grasp
    #[command(long_about = grasp_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Grasp(grasp_cmd::GraspArgs),
    /// Benchmarks: `pqh bench gws` compares every method on random grasps
    #[command(after_help = EXIT_STATUS_HELP)]
    Bench(bench_cmd::BenchArgs),
    /// A GraspIt!-like random grasp planner: partial vs full-hull quality evaluation
    #[command(long_about = plan_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Plan(plan_cmd::PlanArgs),
    /// A strategy's run, step by step, as a self-contained HTML page (2-D and 3-D)
    #[command(long_about = trace_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Trace(trace_cmd::TraceArgs),
    /// The demo: plan grasps on an object with partial vs full hulls, write the HTML view
    #[command(long_about = demo_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Demo(demo_cmd::DemoArgs),
    /// Full vs partial hull on built-in seeded point sets: agreement and speed-up
    #[command(long_about = compare_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Compare(compare_cmd::CompareArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    progress::set_quiet(cli.quiet);
    let result = match cli.command {
        Command::Hull(args) => hull_cmd::run(&args),
        Command::Demo(args) => demo_cmd::run(&args),
        Command::Compare(args) => compare_cmd::run(&args),
        Command::Grasp(args) => grasp_cmd::run(&args),
        Command::Bench(args) => bench_cmd::run(&args),
        Command::Trace(args) => trace_cmd::run(&args),
        Command::Plan(args) => plan_cmd::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(CliError::Output(e)) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(err) => {
            // One line, whatever the message contains.
            let message = err.to_string().replace(['\n', '\r'], " ");
            eprintln!("pqh: {message}");
            ExitCode::from(err.exit_code())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Cli;
    use clap::CommandFactory;

    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
