//! The CLI's error type and exit codes.

use pqhull::grasp::GraspError;
use pqhull::plan::PlanError;
use std::fmt;

/// Everything that makes `pqh` fail. Each is reported as one `pqh: error: ` line on stderr.
#[derive(Debug)]
pub enum CliError {
    /// Bad option values (exit 2).
    Usage(String),
    /// The input could not be read or parsed, or is unsupported (exit 2).
    Input(String),
    /// The points admit no hull (exit 1).
    Geometry(String),
    /// Writing the output failed (exit 2; a closed pipe is not reported and exits 0).
    Output(std::io::Error),
}

impl CliError {
    /// The process exit status for this error.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Usage(_) | CliError::Input(_) | CliError::Output(_) => 2,
            CliError::Geometry(_) => 1,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Usage(m) | CliError::Input(m) | CliError::Geometry(m) => f.write_str(m),
            CliError::Output(e) => write!(f, "cannot write output: {e}"),
        }
    }
}

/// A plan that could not run: sizes beyond a limit are the options' fault (usage), anything else
/// the geometry's.
impl From<PlanError> for CliError {
    fn from(e: PlanError) -> Self {
        match e {
            PlanError::Empty
            | PlanError::TooManySamples { .. }
            | PlanError::TooManyStarts { .. }
            | PlanError::TooManyEvaluations { .. }
            | PlanError::TooFewEvaluations { .. }
            | PlanError::Grasp(GraspError::TooManyContacts { .. }) => {
                CliError::Usage(e.to_string())
            }
            _ => CliError::Geometry(e.to_string()),
        }
    }
}

impl From<std::io::Error> for CliError {
    fn from(e: std::io::Error) -> Self {
        CliError::Output(e)
    }
}
