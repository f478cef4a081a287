//! An independent exact reference for full hulls where Qhull is not one: cddlib (Fukuda's
//! double description method in GMP rationals; the program `scdd_gmp` of Debian's
//! `libcdd-tools`), run on the caller's points written out as exact rationals.
//!
//! cddlib answers with the hull's facets as inequalities `b + a·x ≥ 0`, one per facet
//! hyperplane (a face of many coplanar points is one row), and nothing else; pqhull's hull is
//! simplicial. [`compare`] matches them without computing a hyperplane of pqhull's: every one
//! of cddlib's inequalities is evaluated exactly (integers) at every input point, which must
//! all satisfy it, and its zero set is the facet's points; then every simplex of pqhull's hull
//! must have its D vertices in one such zero set, and every one of cddlib's facets must hold
//! at least one simplex. With [`Hull::check`](pqhull::Hull::check) (a closed surface of
//! simplices, each locally convex), that makes the two hulls the same polytope: each simplex
//! spans a facet hyperplane of cddlib's (its D vertices are affinely independent), and no facet
//! is missing.
//!
//! This is slow by design (cddlib's exact arithmetic takes minutes on hulls pqhull builds in a
//! fraction of a second): a reference for tests and for `cli/examples/compare_cdd.rs`, which times
//! the two side by side on the raw Minkowski sums of `pqh bench hull` (docs/benchmarks.md,
//! "An exact reference: cddlib").
//!
//! ```no_run
//! use pqhull::Hull;
//! use pqhull_cli::bench::cdd::{compare, run_scdd, scdd_program};
//!
//! let points = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [0.5, 0.5]];
//! let reference = run_scdd(&points, &scdd_program(), &std::env::temp_dir())?;
//! let agreement = compare(&Hull::try_new(&points)?, &points, &reference);
//! assert!(agreement.agrees());
//! assert_eq!(reference.facets.len(), 4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use pqhull::Hull;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// cddlib's answer: the hull's facets, each as the integer inequality `b + a·x ≥ 0`
/// (`[b, a_1, …, a_D]`, denominators cleared), and the program's wall time.
#[derive(Clone, Debug)]
pub struct CddHull {
    /// One row per facet hyperplane.
    pub facets: Vec<Vec<BigInt>>,
    /// Wall time of the `scdd_gmp` process (writing its input and reading its output aside).
    pub elapsed: Duration,
}

/// What went wrong running cddlib.
#[derive(Debug)]
pub enum CddError {
    /// The program could not be started (not installed: `apt-get install libcdd-tools`).
    Start(PathBuf, std::io::Error),
    /// Reading or writing its files.
    Io(PathBuf, std::io::Error),
    /// It ran but failed, with its output.
    Failed(String),
    /// Its output is not an H-representation of a full-dimensional hull, as read.
    Output(String),
}

impl std::fmt::Display for CddError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CddError::Start(path, e) => write!(
                f,
                "cannot run {} ({e}): install cddlib's programs (apt-get install libcdd-tools)",
                path.display()
            ),
            CddError::Io(path, e) => write!(f, "{}: {e}", path.display()),
            CddError::Failed(output) => write!(f, "scdd_gmp failed: {output}"),
            CddError::Output(what) => write!(f, "scdd_gmp's output: {what}"),
        }
    }
}

impl std::error::Error for CddError {}

/// The `scdd_gmp` to run: the environment variable `PQHULL_SCDD` if set, else `scdd_gmp` on the
/// `PATH`.
pub fn scdd_program() -> PathBuf {
    std::env::var_os("PQHULL_SCDD").map_or_else(|| PathBuf::from("scdd_gmp"), PathBuf::from)
}

/// Writes `points` as a cddlib V-representation (`V-representation`, `begin`, `n D+1 rational`,
/// rows `1 x_1 … x_D`, `end`) to `path`, each coordinate as the exact rational it is: the input
/// of `scdd_gmp`, and of the CGAL comparison `compare/cgal/hull.cpp`.
///
/// # Errors
/// [`CddError::Io`] when the file cannot be written.
///
/// # Panics
/// If a coordinate is not finite.
pub fn write_ext<const D: usize>(points: &[[f64; D]], path: &Path) -> Result<(), CddError> {
    let mut text = format!(
        "V-representation\nbegin\n {} {} rational\n",
        points.len(),
        D + 1
    );
    for p in points {
        text.push_str(" 1");
        for &x in p {
            let exact = BigRational::from_float(x).expect("a finite coordinate");
            let _ = write!(text, " {exact}");
        }
        text.push('\n');
    }
    text.push_str("end\n");
    std::fs::write(path, text).map_err(|e| CddError::Io(path.to_path_buf(), e))
}

/// Runs cddlib's `program` (`scdd_gmp`, or a path to it) on `points`, each coordinate written
/// as the exact rational it is, in a file `points.ext` under `scratch`, and reads the facets it
/// writes to `points.ine`.
///
/// # Errors
/// [`CddError`] when the program is missing or fails, or its output cannot be read as the
/// facets of a full-dimensional hull.
///
/// # Panics
/// If a coordinate is not finite.
pub fn run_scdd<const D: usize>(
    points: &[[f64; D]],
    program: &Path,
    scratch: &Path,
) -> Result<CddHull, CddError> {
    std::fs::create_dir_all(scratch).map_err(|e| CddError::Io(scratch.to_path_buf(), e))?;
    let input = scratch.join("points.ext");
    let output = scratch.join("points.ine");
    write_ext(points, &input)?;
    // A stale answer must not pass for this one.
    let _ = std::fs::remove_file(&output);
    let started = Instant::now();
    let run = Command::new(program)
        .arg("points.ext")
        .current_dir(scratch)
        .output()
        .map_err(|e| CddError::Start(program.to_path_buf(), e))?;
    let elapsed = started.elapsed();
    if !run.status.success() {
        return Err(CddError::Failed(format!(
            "{}{}",
            String::from_utf8_lossy(&run.stdout),
            String::from_utf8_lossy(&run.stderr)
        )));
    }
    let text = std::fs::read_to_string(&output).map_err(|e| CddError::Io(output.clone(), e))?;
    Ok(CddHull {
        facets: parse_inequalities(&text, D + 1)?,
        elapsed,
    })
}

/// The rows of an H-representation of `columns` columns, each scaled to integers.
fn parse_inequalities(text: &str, columns: usize) -> Result<Vec<Vec<BigInt>>, CddError> {
    let mut lines = text.lines().map(str::trim);
    for line in lines.by_ref() {
        if line.starts_with("linearity") {
            return Err(CddError::Output(
                "equations (linearity): the points do not span the space".into(),
            ));
        }
        if line == "begin" {
            break;
        }
    }
    let size = lines
        .next()
        .ok_or_else(|| CddError::Output("no size line after `begin`".into()))?;
    let fields: Vec<&str> = size.split_whitespace().collect();
    let (Some(rows), Some(&cols)) = (
        fields.first().and_then(|r| r.parse::<usize>().ok()),
        fields.get(1),
    ) else {
        return Err(CddError::Output(format!("size line {size:?}")));
    };
    if cols != columns.to_string() {
        return Err(CddError::Output(format!(
            "{cols} columns, expected {columns}"
        )));
    }
    let mut facets = Vec::new();
    for line in lines.take_while(|l| *l != "end") {
        let row = line
            .split_whitespace()
            .map(|t| {
                t.parse::<BigRational>()
                    .map_err(|_| CddError::Output(format!("not a rational: {t:?}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        if row.len() != columns {
            return Err(CddError::Output(format!(
                "row {line:?}: not {columns} entries"
            )));
        }
        facets.push(integer_row(&row));
    }
    if facets.len() != rows {
        return Err(CddError::Output(format!(
            "{} rows, {rows} announced",
            facets.len()
        )));
    }
    Ok(facets)
}

/// `row` times the least common multiple of its denominators.
fn integer_row(row: &[BigRational]) -> Vec<BigInt> {
    let lcm = row.iter().fold(BigInt::one(), |l, r| l.lcm(r.denom()));
    row.iter().map(|r| r.numer() * (&lcm / r.denom())).collect()
}

/// How pqhull's hull and cddlib's facets compare (see the [module](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Agreement {
    /// cddlib's facets (hyperplanes).
    pub cdd_facets: usize,
    /// pqhull's facets (simplices).
    pub simplices: usize,
    /// (point, facet) pairs where an input point is strictly outside one of cddlib's
    /// inequalities (0 for a right answer of cddlib's).
    pub outside: usize,
    /// pqhull's simplices whose vertices lie on none of cddlib's facets.
    pub stray: usize,
    /// cddlib's facets that hold none of pqhull's simplices.
    pub missed: usize,
}

impl Agreement {
    /// Whether the two hulls are the same polytope (with [`Hull::check`] on pqhull's passing).
    pub fn agrees(&self) -> bool {
        self.outside == 0 && self.stray == 0 && self.missed == 0 && self.simplices > 0
    }
}

/// Compares `hull` (built on `points`) with cddlib's facets of the same points, exactly (see the
/// [module](self)).
///
/// # Panics
/// If a coordinate is not finite, or an inequality of `cdd` does not have `D + 1` entries.
pub fn compare<const D: usize>(hull: &Hull<D>, points: &[[f64; D]], cdd: &CddHull) -> Agreement {
    let scaled = integer_points(points);
    let mut agreement = Agreement {
        cdd_facets: cdd.facets.len(),
        ..Agreement::default()
    };
    // For each point, the facets of cddlib's whose hyperplane holds it.
    let mut on: Vec<Vec<u32>> = vec![Vec::new(); points.len()];
    for (f, row) in cdd.facets.iter().enumerate() {
        assert_eq!(row.len(), D + 1, "an inequality of cddlib's");
        let (b, a) = (&row[0], &row[1..]);
        // b + a·x with x = X / 2^shift: the sign of b·2^shift + a·X.
        let offset = b << scaled.shift;
        for (i, x) in scaled.points.iter().enumerate() {
            let value = a.iter().zip(x).fold(offset.clone(), |s, (a, x)| s + a * x);
            if value.is_zero() {
                on[i].push(f as u32);
            } else if value.is_negative() {
                agreement.outside += 1;
            }
        }
    }
    let mut held = vec![false; cdd.facets.len()];
    for (_, facet) in hull.facets() {
        agreement.simplices += 1;
        let vertices = facet.vertices();
        let shared = on[vertices[0]]
            .iter()
            .find(|f| vertices[1..].iter().all(|&v| on[v].contains(f)));
        match shared {
            Some(&f) => held[f as usize] = true,
            None => agreement.stray += 1,
        }
    }
    agreement.missed = held.iter().filter(|&&h| !h).count();
    agreement
}

/// The points as integers on one grid: `X = x · 2^shift`.
struct IntegerPoints<const D: usize> {
    points: Vec<[BigInt; D]>,
    shift: usize,
}

fn integer_points<const D: usize>(points: &[[f64; D]]) -> IntegerPoints<D> {
    let exact: Vec<[BigRational; D]> = points
        .iter()
        .map(|p| p.map(|x| BigRational::from_float(x).expect("a finite coordinate")))
        .collect();
    // Every finite f64 is m / 2^k with k ≥ 0 (k ≤ 1074): the largest k puts all on one grid.
    let shift = exact
        .iter()
        .flatten()
        .map(|r| r.denom().bits() as usize - 1)
        .max()
        .unwrap_or(0);
    let points = exact
        .iter()
        .map(|p| {
            std::array::from_fn(|j| {
                let r = &p[j];
                r.numer() * (BigInt::one() << (shift - (r.denom().bits() as usize - 1)))
            })
        })
        .collect();
    IntegerPoints { points, shift }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inequalities_are_read_with_their_denominators_cleared() {
        let text = "* comment\nH-representation\nbegin\n 2 3 rational\n 1/2 -1/3 0\n 0 1 1\nend\n";
        let rows = parse_inequalities(text, 3).unwrap();
        assert_eq!(rows[0], vec![3.into(), (-2).into(), 0.into()]);
        assert_eq!(rows[1], vec![0.into(), 1.into(), 1.into()]);
        assert!(parse_inequalities("begin\n 3 3 rational\n 1 2 3\nend\n", 3).is_err());
        assert!(parse_inequalities("linearity 1 1\nbegin\n", 3).is_err());
    }

    #[test]
    fn a_square_agrees_and_a_wrong_facet_is_caught() {
        let points = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [0.5, 0.25]];
        let hull = Hull::try_new(&points).unwrap();
        let row = |r: [i64; 3]| r.map(BigInt::from).to_vec();
        // x ≥ 0, y ≥ 0, 1 − x ≥ 0, 1 − y ≥ 0.
        let mut square = CddHull {
            facets: vec![
                row([0, 1, 0]),
                row([0, 0, 1]),
                row([1, -1, 0]),
                row([1, 0, -1]),
            ],
            elapsed: Duration::ZERO,
        };
        assert!(compare(&hull, &points, &square).agrees());
        // 1/2 − y ≥ 0 instead of 1 − y ≥ 0: two points outside, the top edge stray.
        square.facets[3] = row([1, 0, -2]);
        let a = compare(&hull, &points, &square);
        assert_eq!((a.outside, a.stray, a.missed), (2, 1, 1));
        // A facet too few.
        square.facets.pop();
        let a = compare(&hull, &points, &square);
        assert_eq!((a.outside, a.stray, a.missed), (0, 1, 0));
    }
}
