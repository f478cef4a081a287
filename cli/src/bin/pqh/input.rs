//! Reading points files (or standard input) and meshes.

use crate::error::CliError;
use pqhull::mesh::Mesh;
use pqhull_cli::object::{DEFAULT_OBJECT_NAME, default_object};
use pqhull_cli::points_file::{PointTable, ReadError, read_points};
use std::path::Path;

/// The object of `--mesh` and a name for it: the file, or the library's default object.
pub fn object(mesh: Option<&Path>) -> Result<(Mesh, String), CliError> {
    match mesh {
        Some(path) => Mesh::load(path)
            .map(|m| (m, path.display().to_string()))
            .map_err(|e| CliError::Input(e.to_string())),
        None => Ok((default_object(), DEFAULT_OBJECT_NAME.to_string())),
    }
}

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

    /// Reads and parses the points a line at a time (the text is never held whole); errors name
    /// the source (and the line).
    pub fn read_points(&self) -> Result<PointTable, CliError> {
        match self.path {
            Some(path) => std::fs::File::open(path)
                .map_err(ReadError::Io)
                .and_then(|file| read_points(std::io::BufReader::new(file))),
            None => read_points(std::io::stdin().lock()),
        }
        .map_err(|e| CliError::Input(format!("{}: {e}", self.name())))
    }
}

/// Parses a point given on the command line (`x,y,...`: fields separated by commas, and/or
/// coordinates by whitespace, as in a points file). An empty field (`1,,2`, a trailing comma) is
/// an error naming it, not skipped.
pub fn parse_point(option: &str, text: &str) -> Result<Vec<f64>, CliError> {
    let usage = |m: String| CliError::Usage(format!("{option}: {m}"));
    let mut coords = Vec::new();
    if text.trim().is_empty() {
        return Err(usage("no coordinates given".to_string()));
    }
    for (index, field) in text.split(',').enumerate() {
        let field = field.trim();
        if field.is_empty() {
            return Err(usage(format!(
                "field {} of '{text}' is empty (two commas in a row, or a comma at an end?)",
                index + 1
            )));
        }
        for t in field.split_whitespace() {
            match t.parse::<f64>() {
                Ok(x) if x.is_finite() => coords.push(x),
                Ok(_) => return Err(usage(format!("'{t}' is not finite"))),
                Err(_) => return Err(usage(format!("'{t}' is not a number"))),
            }
        }
    }
    Ok(coords)
}

#[cfg(test)]
mod tests {
    use super::parse_point;

    #[test]
    fn points_on_the_command_line() {
        assert_eq!(parse_point("--origin", "1,-2").unwrap(), vec![1.0, -2.0]);
        assert_eq!(
            parse_point("--origin", " 1 2, 3 ").unwrap(),
            vec![1.0, 2.0, 3.0]
        );
        for (text, needle) in [
            ("1,,2", "field 2"),
            ("1,2,", "field 3"),
            (",1", "field 1"),
            ("", "no coordinates"),
            ("1,x", "'x'"),
            ("1,inf", "not finite"),
        ] {
            let err = parse_point("--origin", text).unwrap_err().to_string();
            assert!(
                err.starts_with("--origin: ") && err.contains(needle),
                "{text}: {err}"
            );
        }
    }
}
