//! Qhull as a baseline (cargo feature `qhull`).
//!
//! A deliberately small API over the [`qhull`](https://crates.io/crates/qhull) crate (Rust
//! bindings that compile Qhull's own C sources), used by the cross-check tests
//! (`tests/qhull_crosscheck.rs`), the benchmarks (`benches/hull.rs`) and
//! `examples/compare_qhull.rs` to compare [`Hull`](crate::Hull) with the reference
//! implementation everybody else uses (GraspIt!, Dex-Net and scipy all call Qhull).
//!
//! * [`qhull_full_hull`] — the full convex hull: vertex indices, facets (normal and offset in
//!   Qhull's convention) and volume.
//! * [`qhull_origin_distance`] — the Ferrari–Canny style "distance from the origin to the hull",
//!   computed the way Qhull users compute it: the minimum over facets of `−offset`.
//! * [`qhull_facet_count`] — just build the hull and count its facets (the cheapest call that
//!   still runs all of Qhull; what the benchmarks time).
//! * [`qhull_stats`] — facet and vertex counts, and how many facets Qhull created on the way.
//!
//! # Options
//!
//! Qhull runs with its default convex-hull options (those of `qconvex`: merged facets `C-0`
//! below 5-D, `Qx` from 5-D on) plus `Qt` (triangulated output), so every facet reported here is
//! a simplex of `D` vertices, like pqhull's. Qhull is *not* exact: it decides "is this point
//! above this facet?" with floating-point distances and a tolerance, and merges facets that are
//! nearly coplanar. On general-position input the two hulls agree; on degenerate input
//! (cospherical, coplanar, nearly coincident points) Qhull may drop or keep borderline vertices.
//!
//! # Qhull's plane convention
//!
//! A Qhull facet's hyperplane is `normal · x + offset = 0` with a unit outward `normal`; points
//! inside the hull have `normal · x + offset ≤ 0`. (pqhull writes `normal · x ≤ offset`, so
//! pqhull's offset is the *negated* Qhull offset.)
//!
//! ```
//! use pqhull::qhull_baseline::{qhull_full_hull, qhull_origin_distance};
//!
//! let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.2, 0.1]];
//! let hull = qhull_full_hull(&square)?;
//! assert_eq!(hull.vertices, vec![0, 1, 2, 3]);
//! assert!((hull.volume - 4.0).abs() < 1e-12);
//! assert!((qhull_origin_distance(&square)? - 1.0).abs() < 1e-12);
//! # Ok::<(), pqhull::qhull_baseline::QhullError>(())
//! ```

use qhull::{Qh, QhError};
use std::fmt;

/// One facet of a [`QhullHull`]: a simplex of `D` input points.
#[derive(Clone, Debug, PartialEq)]
pub struct QhullFacet {
    /// Input indices of the facet's `D` vertices (Qhull's order, not sorted, not oriented).
    pub vertices: Vec<usize>,
    /// Qhull's unit outward normal (`D` numbers).
    pub normal: Vec<f64>,
    /// Qhull's offset: the hyperplane is `normal · x + offset = 0`, inside is `≤ 0`. For a hull
    /// that contains the origin, `−offset` is the distance from the origin to the plane.
    pub offset: f64,
}

/// The full convex hull as computed by Qhull (see [`qhull_full_hull`]).
#[derive(Clone, Debug, PartialEq)]
pub struct QhullHull {
    /// Sorted input indices of the hull's vertices.
    pub vertices: Vec<usize>,
    /// The facets of Qhull's triangulated output (`Qt`). Facets that Qhull merged (nearly
    /// coplanar) appear as several simplices sharing one hyperplane.
    pub facets: Vec<QhullFacet>,
    /// Volume (area in 2-D) of the hull: the sum over facets of the volume of the simplex spanned
    /// by the facet and the centroid of the hull's vertices, computed here in `f64` (Qhull's
    /// own `FA` total is not exposed by the bindings).
    pub volume: f64,
}

/// Why Qhull could not build a hull.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum QhullError {
    /// Qhull needs a dimension of at least 2.
    DimensionTooLow {
        /// The dimension asked for.
        dimension: usize,
    },
    /// Fewer than `D + 1` points.
    TooFewPoints {
        /// Number of points given.
        count: usize,
        /// Number of points needed (`D + 1`).
        needed: usize,
    },
    /// A NaN or infinite coordinate (Qhull does not check for these itself).
    NonFinite {
        /// Index of the first offending point.
        index: usize,
    },
    /// Qhull reported an error, e.g. `QH6154` for input that is flat (spans fewer than `D`
    /// dimensions).
    Qhull {
        /// Qhull's error code (e.g. 6154).
        code: i32,
        /// Qhull's message, if it wrote one.
        message: String,
    },
    /// Qhull returned a vertex whose coordinates are not one of the input points (should not
    /// happen without options that create points, such as `Qz` or `QJ`).
    ForeignVertex,
}

impl fmt::Display for QhullError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            QhullError::DimensionTooLow { dimension } => {
                write!(f, "Qhull needs dimension >= 2, got {dimension}")
            }
            QhullError::TooFewPoints { count, needed } => {
                write!(f, "Qhull needs at least {needed} points, got {count}")
            }
            QhullError::NonFinite { index } => {
                write!(f, "point {index} has a NaN or infinite coordinate")
            }
            QhullError::Qhull { code, message } => {
                write!(f, "Qhull error QH{code}: {}", message.trim())
            }
            QhullError::ForeignVertex => {
                write!(f, "Qhull returned a vertex that is not an input point")
            }
        }
    }
}

impl std::error::Error for QhullError {}

impl From<QhError<'_>> for QhullError {
    fn from(error: QhError<'_>) -> Self {
        QhullError::Qhull {
            code: error.kind.error_code(),
            message: error.error_message.unwrap_or_default(),
        }
    }
}

/// How Qhull handles its precision problems: the options of a run (see [`qhull_full_hull_with`]).
///
/// Qhull decides in `f64` with tolerances, so on nearly degenerate input it must do something
/// about facets it cannot orient reliably. Its manual's answers are merging nearly coplanar
/// facets (the default), joggling the input (`QJ`) and neither (`Q0`, which these bindings
/// cannot pass: they check options as `qconvex` does, which hides it). None of them is exact:
/// on the grasp layer's raw Minkowski sums each answers with facets that are not facets of the
/// hull of the caller's points (docs/benchmarks.md, "Qhull's three answers").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum QhullOptions {
    /// Qhull's defaults plus `Qt` (what every function of this module without `_with` runs, and
    /// what scipy's `ConvexHull` runs): nearly coplanar facets merged (`C-0`, `Qx` from 5-D
    /// on), the merged facets reported as simplices.
    #[default]
    Merged,
    /// `QJ`: every coordinate joggled by a random amount (30,000 times Qhull's estimate of its
    /// rounding error, ten times more on each retry: 2.1e−9 on the raw 3 × 6 grasp sum after
    /// two, as Qhull's program reports; Qhull's seed is fixed, so every run joggles alike), so
    /// that no merging is needed: a simplicial hull of *other* points.
    Joggled,
}

impl QhullOptions {
    /// The option words passed to Qhull.
    pub fn words(self) -> &'static [&'static str] {
        match self {
            QhullOptions::Merged => &["Qt"],
            QhullOptions::Joggled => &["QJ"],
        }
    }
}

/// Checks what Qhull does not, then runs Qhull (default options plus `Qt`, stderr captured).
fn run_qhull<const D: usize>(points: &[[f64; D]]) -> Result<Qh<'static>, QhullError> {
    run_qhull_with(points, QhullOptions::Merged)
}

/// [`run_qhull`] with `options`.
fn run_qhull_with<const D: usize>(
    points: &[[f64; D]],
    options: QhullOptions,
) -> Result<Qh<'static>, QhullError> {
    if D < 2 {
        return Err(QhullError::DimensionTooLow { dimension: D });
    }
    if points.len() < D + 1 {
        return Err(QhullError::TooFewPoints {
            count: points.len(),
            needed: D + 1,
        });
    }
    if let Some(index) = points.iter().position(|p| p.iter().any(|x| !x.is_finite())) {
        return Err(QhullError::NonFinite { index });
    }
    let builder = Qh::builder()
        .compute(true)
        .capture_stderr(true)
        .qhull_args(options.words())
        .expect("static option words without NUL");
    Ok(builder.build_from_iter(points.iter().copied())?)
}

/// The full convex hull of `points`, computed by Qhull (default options plus `Qt`).
///
/// # Errors
///
/// [`QhullError`] for `D < 2`, fewer than `D + 1` points, a NaN or infinite coordinate, or an
/// error reported by Qhull (flat input is `QH6154`).
///
/// ```
/// use pqhull::qhull_baseline::qhull_full_hull;
///
/// let tetrahedron = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let hull = qhull_full_hull(&tetrahedron)?;
/// assert_eq!(hull.vertices, vec![0, 1, 2, 3]);
/// assert_eq!(hull.facets.len(), 4);
/// assert!((hull.volume - 1.0 / 6.0).abs() < 1e-15);
/// // Every input point satisfies normal · x + offset ≤ 0 (up to rounding).
/// for facet in &hull.facets {
///     for p in &tetrahedron {
///         let d: f64 = facet.normal.iter().zip(p).map(|(n, x)| n * x).sum::<f64>() + facet.offset;
///         assert!(d <= 1e-12);
///     }
/// }
/// # Ok::<(), pqhull::qhull_baseline::QhullError>(())
/// ```
pub fn qhull_full_hull<const D: usize>(points: &[[f64; D]]) -> Result<QhullHull, QhullError> {
    qhull_full_hull_with(points, QhullOptions::Merged)
}

/// [`qhull_full_hull`] with Qhull's `options` (see [`QhullOptions`]).
///
/// # Errors
///
/// As [`qhull_full_hull`].
///
/// ```
/// use pqhull::qhull_baseline::{QhullOptions, qhull_full_hull_with};
///
/// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.2, 0.1]];
/// for options in [QhullOptions::Merged, QhullOptions::Joggled] {
///     assert_eq!(qhull_full_hull_with(&square, options)?.vertices, vec![0, 1, 2, 3]);
/// }
/// # Ok::<(), pqhull::qhull_baseline::QhullError>(())
/// ```
pub fn qhull_full_hull_with<const D: usize>(
    points: &[[f64; D]],
    options: QhullOptions,
) -> Result<QhullHull, QhullError> {
    let qh = run_qhull_with(points, options)?;

    let mut vertices = qh
        .vertices()
        .map(|v| v.index(&qh).ok_or(QhullError::ForeignVertex))
        .collect::<Result<Vec<_>, _>>()?;
    vertices.sort_unstable();
    vertices.dedup();

    let mut facets = Vec::new();
    for facet in qh.facets() {
        let facet_vertices = match facet.vertices() {
            Some(set) => set
                .iter()
                .map(|v| v.index(&qh).ok_or(QhullError::ForeignVertex))
                .collect::<Result<Vec<_>, _>>()?,
            None => Vec::new(),
        };
        facets.push(QhullFacet {
            vertices: facet_vertices,
            normal: facet.normal().map(<[f64]>::to_vec).unwrap_or_default(),
            offset: facet.offset(),
        });
    }

    let volume = simplicial_volume(points, &vertices, &facets);
    Ok(QhullHull {
        vertices,
        facets,
        volume,
    })
}

/// Signed distance from the origin to the hull of `points`, the way Qhull users compute the
/// Ferrari–Canny metric (GraspIt!, Dex-Net, `scipy.spatial.ConvexHull(...).equations`):
/// `min over facets of −offset`, Qhull's offset being the value of `normal · x + offset` at the
/// origin.
///
/// * **Origin inside:** every `−offset` is positive and the minimum is the Euclidean distance
///   from the origin to the boundary (the facet planes of a convex polytope containing a point
///   are exactly as near as its boundary).
/// * **Origin outside:** the result is negative: minus the largest distance by which the origin
///   lies beyond any facet *plane*. This is the facet-plane convention Qhull users apply, **not**
///   the Euclidean distance from the origin to the hull: its magnitude can be smaller than the
///   true distance (when the foot of the perpendicular falls outside that facet). pqhull's
///   `ClosestToOrigin` strategy returns the true Euclidean distance instead.
/// * **Origin on the boundary:** 0 up to rounding (Qhull is not exact).
///
/// # Errors
///
/// As [`qhull_full_hull`]. Flat (lower-rank) wrench sets are a Qhull error here, while pqhull
/// rejects them with a typed [`HullError`](crate::HullError).
///
/// ```
/// use pqhull::qhull_baseline::qhull_origin_distance;
///
/// // A triangle around the origin: nearest side y = −1 at distance 1.
/// let inside = [[-2.0, -1.0], [3.0, -1.0], [0.0, 4.0]];
/// assert!((qhull_origin_distance(&inside)? - 1.0).abs() < 1e-12);
///
/// // The origin outside, nearest the corner (1, 1): the Euclidean distance is √2, but the
/// // origin lies only 1 beyond the planes x = 1 and y = 1, so the facet-plane value is −1.
/// let outside = [[1.0, 1.0], [3.0, 1.0], [1.0, 3.0]];
/// assert!((qhull_origin_distance(&outside)? + 1.0).abs() < 1e-12);
/// # Ok::<(), pqhull::qhull_baseline::QhullError>(())
/// ```
pub fn qhull_origin_distance<const D: usize>(points: &[[f64; D]]) -> Result<f64, QhullError> {
    let qh = run_qhull(points)?;
    // Inside: min(−offset) = distance to the nearest plane. Outside: min(−offset) =
    // −max(offset) = −(largest distance beyond a facet plane). One formula for both.
    Ok(qh
        .facets()
        .map(|f| -f.offset())
        .fold(f64::INFINITY, f64::min))
}

/// Builds the hull with Qhull (same options as [`qhull_full_hull`]) and returns only its number
/// of (triangulated) facets: all of Qhull's work, none of the extraction. This is what the
/// benchmarks time against [`Hull::try_new`](crate::Hull::try_new).
///
/// # Errors
///
/// As [`qhull_full_hull`].
///
/// ```
/// use pqhull::qhull_baseline::qhull_facet_count;
/// let cube: Vec<[f64; 3]> = (0..8)
///     .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64])
///     .collect();
/// assert_eq!(qhull_facet_count(&cube)?, 12); // 6 squares, 2 triangles each
/// # Ok::<(), pqhull::qhull_baseline::QhullError>(())
/// ```
pub fn qhull_facet_count<const D: usize>(points: &[[f64; D]]) -> Result<usize, QhullError> {
    let qh = run_qhull(points)?;
    Ok(qh.num_facets())
}

/// Size counters of a Qhull run (see [`qhull_stats`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QhullStats {
    /// Facets of the final (triangulated) hull.
    pub facets: usize,
    /// Vertices of the final hull.
    pub vertices: usize,
    /// Largest facet id in the final hull. Qhull numbers facets sequentially as it creates them,
    /// so this is (up to the handful created by `Qt` triangulation and merging at the end) the
    /// number of facets Qhull created while building the hull — comparable with pqhull's
    /// [`Stats::facets_created`](crate::Stats::facets_created).
    pub facets_created: usize,
}

/// Builds the hull with Qhull (same options as [`qhull_full_hull`]) and returns its size
/// counters, to compare the work Qhull does with pqhull's [`Stats`](crate::Stats).
///
/// # Errors
///
/// As [`qhull_full_hull`].
///
/// ```
/// use pqhull::qhull_baseline::qhull_stats;
/// let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.2, 0.1]];
/// let stats = qhull_stats(&square)?;
/// assert_eq!((stats.facets, stats.vertices), (4, 4));
/// assert!(stats.facets_created >= 4);
/// # Ok::<(), pqhull::qhull_baseline::QhullError>(())
/// ```
pub fn qhull_stats<const D: usize>(points: &[[f64; D]]) -> Result<QhullStats, QhullError> {
    qhull_stats_with(points, QhullOptions::Merged)
}

/// [`qhull_stats`] with Qhull's `options` (see [`QhullOptions`]).
///
/// # Errors
///
/// As [`qhull_full_hull_with`].
pub fn qhull_stats_with<const D: usize>(
    points: &[[f64; D]],
    options: QhullOptions,
) -> Result<QhullStats, QhullError> {
    let qh = run_qhull_with(points, options)?;
    Ok(QhullStats {
        facets: qh.num_facets(),
        vertices: qh.num_vertices(),
        facets_created: qh.facets().map(|f| f.id() as usize).max().unwrap_or(0),
    })
}

/// Sum over simplicial facets of |det(v_1 − c, …, v_D − c)| / D!, with `c` the centroid of the
/// hull's vertices (strictly inside a full-dimensional hull).
fn simplicial_volume<const D: usize>(
    points: &[[f64; D]],
    vertices: &[usize],
    facets: &[QhullFacet],
) -> f64 {
    if vertices.is_empty() {
        return 0.0;
    }
    let mut centre = [0.0; D];
    for &v in vertices {
        for (c, x) in centre.iter_mut().zip(&points[v]) {
            *c += x;
        }
    }
    let count = vertices.len() as f64;
    centre.iter_mut().for_each(|c| *c /= count);

    let mut sum = 0.0;
    let mut matrix = vec![0.0; D * D];
    for facet in facets.iter().filter(|f| f.vertices.len() == D) {
        for (row, &v) in facet.vertices.iter().enumerate() {
            for col in 0..D {
                matrix[row * D + col] = points[v][col] - centre[col];
            }
        }
        sum += determinant(&mut matrix, D).abs();
    }
    let factorial: f64 = (1..=D).map(|k| k as f64).product();
    sum / factorial
}

/// Determinant of the `n × n` row-major `matrix` (destroyed), Gaussian elimination with partial
/// pivoting.
fn determinant(matrix: &mut [f64], n: usize) -> f64 {
    let mut det = 1.0;
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&a, &b| {
                matrix[a * n + col]
                    .abs()
                    .total_cmp(&matrix[b * n + col].abs())
            })
            .unwrap_or(col);
        if matrix[pivot * n + col] == 0.0 {
            return 0.0;
        }
        if pivot != col {
            for k in 0..n {
                matrix.swap(pivot * n + k, col * n + k);
            }
            det = -det;
        }
        let p = matrix[col * n + col];
        det *= p;
        for row in col + 1..n {
            let factor = matrix[row * n + col] / p;
            if factor != 0.0 {
                for k in col..n {
                    matrix[row * n + k] -= factor * matrix[col * n + k];
                }
            }
        }
    }
    det
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn determinant_matches_known_values() {
        let mut m = vec![2.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 4.0];
        assert_eq!(determinant(&mut m, 3), 24.0);
        let mut swap = vec![0.0, 1.0, 1.0, 0.0];
        assert_eq!(determinant(&mut swap, 2), -1.0);
    }

    #[test]
    fn cube_volume_and_offsets() {
        let cube: Vec<[f64; 3]> = (0..8)
            .map(|i| {
                [
                    (i & 1) as f64 - 0.5,
                    ((i >> 1) & 1) as f64 - 0.5,
                    ((i >> 2) & 1) as f64 - 0.5,
                ]
            })
            .collect();
        let hull = qhull_full_hull(&cube).unwrap();
        assert_eq!(hull.vertices, (0..8).collect::<Vec<_>>());
        assert!((hull.volume - 1.0).abs() < 1e-12);
        for facet in &hull.facets {
            assert_eq!(facet.vertices.len(), 3);
            assert!((facet.offset + 0.5).abs() < 1e-12);
        }
        assert!((qhull_origin_distance(&cube).unwrap() - 0.5).abs() < 1e-12);
    }

    #[test]
    fn errors_are_typed() {
        assert_eq!(
            qhull_full_hull(&[[0.0, 0.0], [1.0, 0.0]]),
            Err(QhullError::TooFewPoints {
                count: 2,
                needed: 3
            })
        );
        assert_eq!(
            qhull_full_hull(&[[0.0, 0.0], [1.0, f64::NAN], [0.0, 1.0]]),
            Err(QhullError::NonFinite { index: 1 })
        );
        let flat = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]];
        match qhull_full_hull(&flat) {
            Err(QhullError::Qhull { .. }) => {}
            other => panic!("expected a Qhull error, got {other:?}"),
        }
    }
}
