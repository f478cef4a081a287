//! Writes the HTML view of a plan (`pqhull::viz::plan_scene`) for `pqh plan --output` and
//! `pqh demo`.

use crate::error::CliError;
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::mesh::Mesh;
use pqhull::plan::{PlanConfig, PlanReport};
use pqhull::viz::plan_scene::plan_page;
use std::path::{Path, PathBuf};

/// Writes the view to `path`; returns the path written.
///
/// # Errors
/// A failed plan or an unwritable path.
pub fn write(
    path: &Path,
    mesh: &Mesh,
    name: &str,
    space: &ObjectWrenchSpace,
    config: &PlanConfig,
    report: &PlanReport,
) -> Result<PathBuf, CliError> {
    let page = plan_page(mesh, name, space, config, report)
        .map_err(|e| CliError::Geometry(e.to_string()))?;
    std::fs::write(path, page)
        .map_err(|e| CliError::Input(format!("cannot write {}: {e}", path.display())))?;
    Ok(path.to_path_buf())
}
