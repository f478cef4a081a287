//! `pqh`: the pqhull command-line tool.
//!
//! Parsing, I/O and output only; every computation is a call into the `pqhull` library.

// One file per command (`*_cmd.rs`, `bench_ows.rs`, `bench_hull.rs`); the others are helpers the commands share.
// A command file uses helpers only, never another command's file.
mod bench_cmd;
mod bench_hull;
mod bench_ows;
mod compare_cmd;
mod demo_cmd;
mod dispatch;
mod error;
mod format;
mod grasp_cmd;
mod hull_cmd;
mod input;
mod limits;
mod methods;
mod penetration_cmd;
mod plan_cmd;
mod plan_descent_cmd;
mod plan_view;
mod progress;
mod reproduce_cmd;
mod trace_cmd;

use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use error::CliError;
use std::process::ExitCode;

const EXIT_STATUS_HELP: &str = "\
Exit status:
  0  success (also when the reader of the output closes the pipe early)
  1  the points admit no hull (too few, or affinely dependent: all on one line, plane, ...), or
     pqh demo, plan or compare found a disagreement
  2  usage, input or output error (bad option, a size beyond its limit, unreadable or malformed
     input, unsupported dimension, no grasp in the input, output not writable)

An error is one line on stderr starting with 'pqh: error: '; other lines on stderr (notes) start
with 'pqh: note: '. Size limits and exit statuses: docs/limits.md.";

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
    /// Signed penetration depth of two convex polytopes (positive: overlap; negative: distance)
    #[command(long_about = penetration_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Penetration(penetration_cmd::PenetrationArgs),
    /// Grasp quality (Q1, Q∞, Q_OWS) of grasps given as JSON, one JSON line per grasp
    #[command(long_about = grasp_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Grasp(grasp_cmd::GraspArgs),
    /// Benchmarks: `pqh bench gws` compares every method on random grasps, `pqh bench hull`
    /// full hulls against Qhull
    #[command(after_help = EXIT_STATUS_HELP)]
    Bench(BenchArgs),
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
    /// The seed paper's figures re-run: per-grasp CSV, SVG plots, its numbers beside ours
    #[command(long_about = reproduce_cmd::LONG_ABOUT, after_help = EXIT_STATUS_HELP)]
    Reproduce(reproduce_cmd::ReproduceArgs),
}

#[derive(Debug, Args)]
struct BenchArgs {
    #[command(subcommand)]
    which: Which,
}

#[derive(Debug, Subcommand)]
enum Which {
    /// Random 4-contact grasps on a box, k = 4 … 64: Q1 partial vs full vs Qhull, Q∞, batch
    /// throughput on 1…n threads
    #[command(long_about = bench_cmd::GWS_LONG_ABOUT)]
    Gws(bench_cmd::GwsArgs),
    /// Q_OWS on random surface grasps of a mesh: partial vs brute force vs ellipsoid, vs Q1
    Ows(bench_ows::OwsArgs),
    /// Full hulls, pqhull vs Qhull: rbox families in 3-D to 6-D, integer grids, grasp wrench
    /// sets and Minkowski sums
    #[command(long_about = bench_hull::LONG_ABOUT)]
    Hull(bench_hull::HullArgs),
}

/// The command with every limit attached (see `limits`).
fn command() -> clap::Command {
    limits::with_demo_limits(Cli::command())
}

/// Prints clap's `error` as `pqh` reports errors: help and version on stdout with status 0;
/// anything else as one `pqh: error: ` line (clap's first paragraph, joined) with a hint to the
/// subcommand's `--help`, status 2.
fn clap_error(error: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(
        error.kind(),
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion
    ) {
        // Help and version go to stdout; a closed pipe is not an error.
        let _ = error.print();
        return ExitCode::SUCCESS;
    }
    let rendered = error.render().to_string();
    let first_paragraph: Vec<&str> = rendered
        .lines()
        .map(str::trim)
        .take_while(|l| !l.is_empty())
        .collect();
    let message = first_paragraph.join(" ");
    let message = message.strip_prefix("error: ").unwrap_or(&message);
    let message = if message.is_empty()
        || error.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    {
        "a subcommand is needed".to_string()
    } else {
        message.to_string()
    };
    eprintln!("pqh: error: {message}; try '{} --help'", invoked_command());
    ExitCode::from(2)
}

/// `pqh` and the subcommands named on the command line (`pqh bench gws`), for the `--help` hint.
fn invoked_command() -> String {
    let root = command();
    let mut current = &root;
    let mut path = vec!["pqh".to_string()];
    for arg in std::env::args_os().skip(1) {
        let Some(arg) = arg.to_str() else { continue };
        if let Some(sub) = current.find_subcommand(arg) {
            path.push(sub.get_name().to_string());
            current = sub;
        }
    }
    path.join(" ")
}

/// `println!` panics when stdout cannot be written (a closed pipe, a full disk). The commands
/// write through `writeln!` and report such errors themselves; this hook is the net for any
/// `println!` left: a closed pipe ends quietly (status 0), another write error is one
/// `pqh: error:` line with status 2, like every other output error.
fn catch_print_failures() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let payload = info.payload();
        let message = payload
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| payload.downcast_ref::<&str>().copied())
            .unwrap_or("");
        if let Some(reason) = message.strip_prefix("failed printing to stdout: ") {
            if reason.contains("Broken pipe") || reason.contains("os error 32") {
                std::process::exit(0);
            }
            eprintln!("pqh: error: cannot write output: {reason}");
            std::process::exit(2);
        }
        default(info)
    }));
}

fn main() -> ExitCode {
    catch_print_failures();
    let cli = match command()
        .try_get_matches()
        .and_then(|matches| Cli::from_arg_matches(&matches))
    {
        Ok(cli) => cli,
        Err(error) => return clap_error(&error),
    };
    progress::set_quiet(cli.quiet);
    let result = match cli.command {
        Command::Hull(args) => hull_cmd::run(&args),
        Command::Penetration(args) => penetration_cmd::run(&args),
        Command::Demo(args) => demo_cmd::run(&args),
        Command::Compare(args) => compare_cmd::run(&args),
        Command::Reproduce(args) => reproduce_cmd::run(&args),
        Command::Grasp(args) => grasp_cmd::run(&args),
        Command::Bench(BenchArgs {
            which: Which::Gws(args),
        }) => bench_cmd::run(&args),
        Command::Bench(BenchArgs {
            which: Which::Ows(args),
        }) => bench_ows::run(&args),
        Command::Bench(BenchArgs {
            which: Which::Hull(args),
        }) => bench_hull::run(&args),
        Command::Trace(args) => trace_cmd::run(&args),
        Command::Plan(args) => plan_cmd::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(CliError::Output(e)) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(err) => {
            // One line, whatever the message contains.
            let message = err.to_string().replace(['\n', '\r'], " ");
            eprintln!("pqh: error: {message}");
            ExitCode::from(err.exit_code())
        }
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn cli_definition_is_consistent() {
        super::command().debug_assert();
    }
}
