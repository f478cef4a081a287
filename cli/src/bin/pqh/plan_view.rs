//! Writes the HTML view of a plan (`pqhull::viz::plan_scene`) for `pqh plan --output` and
//! `pqh demo`.

use crate::error::CliError;
use pqhull::mesh::Mesh;
use pqhull::plan::PlanConfig;
use pqhull::viz::plan_scene::{MetricBest, plan_page};
use std::path::{Path, PathBuf};

/// Writes the view of `bests` to `path`; returns the path written.
///
/// # Errors
/// An unwritable path.
pub fn write(
    path: &Path,
    mesh: &Mesh,
    name: &str,
    config: &PlanConfig,
    bests: &[MetricBest; 2],
) -> Result<PathBuf, CliError> {
    let page = plan_page(mesh, name, config, bests);
    std::fs::write(path, page)
        .map_err(|e| CliError::Input(format!("cannot write {}: {e}", path.display())))?;
    Ok(path.to_path_buf())
}
