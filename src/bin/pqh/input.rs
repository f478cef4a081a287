//! Reading points files (or standard input).

use crate::error::CliError;
use pqhull::points_file::{PointTable, parse_points};
use std::io::Read;
use std::path::Path;

/// Where points come from: a file, or standard input for `-` or no path.
pub struct Source<'a> {
    path: Option<&'a Path>,
}

impl<'a> Source<'a> {
    /// `None` or `-` is standard input.
    pub fn new(path: Option<&'a Path>) -> Self {
        Self {
            path: path.filter(|p| p.as_os_str() != "-"),
        }
    }

    /// The name used in messages: the path, or `<stdin>`.
    pub fn name(&self) -> String {
        match self.path {
            Some(p) => p.display().to_string(),
            None => "<stdin>".to_string(),
        }
    }

    /// Reads and parses the points; errors name the source (and the line).
    pub fn read_points(&self) -> Result<PointTable, CliError> {
        let text = match self.path {
            Some(path) => std::fs::read_to_string(path),
            None => {
                let mut text = String::new();
                std::io::stdin().read_to_string(&mut text).map(|_| text)
            }
        }
        .map_err(|e| CliError::Input(format!("{}: cannot read: {e}", self.name())))?;
        parse_points(&text).map_err(|e| CliError::Input(format!("{}: {e}", self.name())))
    }
}

/// Parses a point given on the command line (`x,y,...`, commas and/or spaces).
pub fn parse_point(option: &str, text: &str) -> Result<Vec<f64>, CliError> {
    let usage = |m: String| CliError::Usage(format!("{option}: {m}"));
    let coords = text
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(|t| match t.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            Ok(_) => Err(usage(format!("'{t}' is not finite"))),
            Err(_) => Err(usage(format!("'{t}' is not a number"))),
        })
        .collect::<Result<Vec<_>, _>>()?;
    if coords.is_empty() {
        return Err(usage("no coordinates given".to_string()));
    }
    Ok(coords)
}
