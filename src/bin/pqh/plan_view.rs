//! The HTML view of a plan: the best grasp by Q1 beside the best by OWS (the seed's Fig. 10).

use crate::error::CliError;
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::mesh::Mesh;
use pqhull::plan::{PlanConfig, PlanReport};
use std::path::{Path, PathBuf};

/// Writes the view to `path`; returns the path written.
pub fn write(
    _path: &Path,
    _mesh: &Mesh,
    _name: &str,
    _space: &ObjectWrenchSpace,
    _config: &PlanConfig,
    _report: &PlanReport,
) -> Result<PathBuf, CliError> {
    Err(CliError::Usage("--output is not built yet".into()))
}
