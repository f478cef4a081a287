//! Seeded point-set generators in the style of Qhull's `rbox`.
//!
//! Every test, benchmark and the `pqh` command-line tool draws its synthetic inputs from these
//! families, so that a failure seen in one place can be reproduced anywhere from the triple
//! `(family, n, seed)`. The families cover the easy case (uniform points), and the inputs that break
//! hull codes that decide with floating tolerances: cospherical points, coplanar corners and face
//! centres, points exactly on facets, thin shells, flat lenses, integer lattices, nearly coincident
//! clusters, exact duplicates, and faces coplanar only up to rounding.
//!
//! | family | `rbox` | points returned | geometry |
//! | --- | --- | --- | --- |
//! | [`Family::UniformCube`] | `rbox n` | `n` | uniform in `[−0.5, 0.5)^D` |
//! | [`Family::SphereSurface`] | `rbox s` | `n` | on the sphere of radius 0.5 around the origin |
//! | [`Family::CubeCornersDiamond`] | `rbox c D` | `2^D + 2D + n` | cube corners, face centres, `n` points in the cube |
//! | [`Family::Simplex`] | `rbox x` | `D + 1 + n` | simplex vertices, `n` points in it (many on its boundary) |
//! | [`Family::ThinShell`] | `rbox s W` | `n` | sphere of radius 0.5 with relative radial noise |
//! | [`Family::NarrowLens`] | `rbox L` | `n` | on the boundary of the intersection of two large balls |
//! | [`Family::IntegerLattice`] | `rbox M` | `n` | small integer coordinates |
//! | [`Family::Clusters`] | `rbox C` | `n` | tight clusters of nearly coincident points |
//! | [`Family::ManyDuplicates`] | — | `n` | a few points, each repeated several times |
//! | [`Family::TiltedFaces`] | `rbox W0`, turned | `n` | on the faces of a rotated cube, rounded |
//!
//! [`point_count`] gives the exact count. For `n ≥ 2D + 2` every family is full-dimensional
//! (affine rank `D`) — with probability one for the continuous families, by construction for the
//! others (see each variant). The generators work for any `D ≥ 1`; the hull engine needs
//! `2 ≤ D ≤ 8`.
//!
//! ```
//! use pqhull::rbox::{generate, Family};
//!
//! let points = generate::<3>(&Family::SphereSurface, 100, 7);
//! assert_eq!(points.len(), 100);
//! assert_eq!(points, generate::<3>(&"sphere".parse().unwrap(), 100, 7));
//! ```

use std::fmt;
use std::str::FromStr;

use crate::geometry::Rng;

/// A family of point sets. [`Family::ALL`] lists every family with its default parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Family {
    /// `n` points uniform in the cube `[−0.5, 0.5)^D`.
    UniformCube,
    /// `n` points uniform on the sphere of radius 0.5 around the origin: all of them are hull
    /// vertices, and in exact arithmetic all are cospherical (each lies at radius 0.5 to within a
    /// few units in the last place).
    SphereSurface,
    /// The `2^D` corners of `[−0.5, 0.5]^D` (bit `i` of the corner number set ⇔ coordinate `i` is
    /// `+0.5`), then the `2D` "diamond" points `+0.5·e_i, −0.5·e_i` (for `i = 0, 1, …`: the centres
    /// of the cube's faces, coplanar with the face corners), then `n` points uniform in the cube.
    /// `2^D + 2D + n` points; the hull is the cube with its `2^D` corners as the only vertices,
    /// every face is coplanar with 2^(D−1) + 1 input points.
    CubeCornersDiamond,
    /// The `D + 1` vertices of a simplex, `v_0 = (−1, …, −1)` and `v_i = (D + 1)·e_i − (1, …, 1)`
    /// (a scaled standard simplex centred on the origin, integer coordinates), then `n` points in
    /// the closed simplex. The points are on a dyadic grid (multiples of `2^−20`), so that they
    /// are exactly representable and exactly inside: cycling through four kinds, point `j` is
    /// random inside (`j % 4 ∈ {0, 3}`), random on a facet (`j % 4 == 1`: one barycentric weight
    /// is exactly 0), or the midpoint of an edge (`j % 4 == 2`). `D + 1 + n` points; the hull's
    /// vertices are exactly the first `D + 1`.
    Simplex,
    /// `n` points on the sphere of radius 0.5 whose radius is perturbed by a relative amount
    /// uniform in `[−width, width]`: `|x| = 0.5·(1 + δ)`, `|δ| ≤ width` (up to rounding). The
    /// default `width` is `1e−13` (like `rbox s W1e-13`, but relative).
    ThinShell {
        /// Relative radial noise, `≥ 0`.
        width: f64,
    },
    /// `n` points on the boundary of a flat lens: the intersection of two balls of radius
    /// `radius`, whose bounding spheres meet in the rim `x_{D−1} = 0, |x| = 0.5`. With
    /// `c = sqrt(radius² − 0.25)`, a point is `(p, ±(sqrt(radius² − |p|²) − c))` for `p` uniform in
    /// the `(D−1)`-ball of radius 0.5: even-numbered points on the upper cap (on the sphere of
    /// centre `(0, …, 0, −c)`), odd-numbered ones on the lower cap (centre `(0, …, 0, +c)`). The
    /// lens is `2·(radius − c)` thick (0.025 for the default `radius` 10). This is our reading of
    /// `rbox L`: nearly flat, with a sharp rim where the caps meet at a small angle.
    NarrowLens {
        /// Radius of the two balls, `> 0.5`; the larger, the flatter.
        radius: f64,
    },
    /// `n` points with integer coordinates in `[−half_width, half_width]^D` (like `rbox M`:
    /// many collinear, coplanar and duplicate points). The first `D + 1` points are a unit lattice
    /// simplex `p, p + e_0, …, p + e_{D−1}` at a random lattice point `p` (so the set is
    /// full-dimensional as soon as `n ≥ D + 1`); the rest are uniform lattice points.
    IntegerLattice {
        /// Half the side of the box, `≥ 1` (default 3: 7^D lattice points).
        half_width: u32,
    },
    /// `n` points in tight clusters: point `j` belongs to cluster `j % k` and is its centre (uniform
    /// in `[−0.5, 0.5)^D`) plus an offset uniform in `[−spread, spread)` in each coordinate.
    Clusters {
        /// Number of clusters `k`; 0 (the default) means `D + 1`.
        clusters: usize,
        /// Half-width of each cluster, per coordinate (default `1e−12`).
        spread: f64,
    },
    /// `n` points drawn from `m = max(ceil(n / copies), min(n, D + 1))` distinct points uniform in
    /// `[−0.5, 0.5)^D`: point `j` is an exact copy of distinct point `j % m` (so copies are not
    /// adjacent). With at least `D + 1` distinct points the set is full-dimensional.
    ManyDuplicates {
        /// How many times each point appears (about), `≥ 1` (default 4).
        copies: usize,
    },
    /// `n` points uniform on the faces of the cube `[−0.5, 0.5]^D` (a face chosen uniformly, the
    /// other coordinates uniform: `rbox W0`), then turned by one rotation drawn from the seed
    /// (Gram–Schmidt on a matrix of normal deviates, computed before the points) and rounded.
    /// The points of one face are coplanar only up to that rounding, a few units in the last
    /// place either side of its hyperplane: a box in a general pose, densely sampled, as a CAD
    /// model's surface is. The exact hull's vertices are the face points that rounding put
    /// outside (hundreds in 3-D), not the cube's corners, which are not in the set; a hull code
    /// that decides with a tolerance merges each face into one.
    TiltedFaces,
}

impl Family {
    /// Default `width` of [`Family::ThinShell`].
    pub const DEFAULT_SHELL_WIDTH: f64 = 1e-13;
    /// Default `radius` of [`Family::NarrowLens`].
    pub const DEFAULT_LENS_RADIUS: f64 = 10.0;
    /// Default `half_width` of [`Family::IntegerLattice`].
    pub const DEFAULT_LATTICE_HALF_WIDTH: u32 = 3;
    /// Default `spread` of [`Family::Clusters`].
    pub const DEFAULT_CLUSTER_SPREAD: f64 = 1e-12;
    /// Default `copies` of [`Family::ManyDuplicates`].
    pub const DEFAULT_COPIES: usize = 4;

    /// Every family, with its default parameters, in a fixed order.
    pub const ALL: [Family; 10] = [
        Family::UniformCube,
        Family::SphereSurface,
        Family::CubeCornersDiamond,
        Family::Simplex,
        Family::ThinShell {
            width: Self::DEFAULT_SHELL_WIDTH,
        },
        Family::NarrowLens {
            radius: Self::DEFAULT_LENS_RADIUS,
        },
        Family::IntegerLattice {
            half_width: Self::DEFAULT_LATTICE_HALF_WIDTH,
        },
        Family::Clusters {
            clusters: 0,
            spread: Self::DEFAULT_CLUSTER_SPREAD,
        },
        Family::ManyDuplicates {
            copies: Self::DEFAULT_COPIES,
        },
        Family::TiltedFaces,
    ];

    /// The short name used by [`FromStr`] and [`fmt::Display`]: `cube`, `sphere`, `corners`,
    /// `simplex`, `shell`, `lens`, `lattice`, `clusters`, `duplicates` or `tilted`.
    pub fn name(&self) -> &'static str {
        match self {
            Family::UniformCube => "cube",
            Family::SphereSurface => "sphere",
            Family::CubeCornersDiamond => "corners",
            Family::Simplex => "simplex",
            Family::ThinShell { .. } => "shell",
            Family::NarrowLens { .. } => "lens",
            Family::IntegerLattice { .. } => "lattice",
            Family::Clusters { .. } => "clusters",
            Family::ManyDuplicates { .. } => "duplicates",
            Family::TiltedFaces => "tilted",
        }
    }

    /// The family of that name with its default parameters.
    fn default_named(name: &str) -> Option<Family> {
        Self::ALL.into_iter().find(|f| f.name() == name)
    }

    /// Checks the parameters; `Err` names the problem.
    fn validate(&self) -> Result<(), String> {
        match *self {
            Family::ThinShell { width } if !(width.is_finite() && width >= 0.0) => {
                Err(format!("shell width must be finite and >= 0, got {width}"))
            }
            Family::NarrowLens { radius } if !(radius.is_finite() && radius > 0.5) => Err(format!(
                "lens radius must be finite and > 0.5, got {radius}"
            )),
            Family::IntegerLattice { half_width: 0 } => {
                Err("lattice half width must be >= 1".to_string())
            }
            Family::Clusters { spread, .. } if !(spread.is_finite() && spread >= 0.0) => Err(
                format!("cluster spread must be finite and >= 0, got {spread}"),
            ),
            Family::ManyDuplicates { copies: 0 } => {
                Err("duplicates copies must be >= 1".to_string())
            }
            _ => Ok(()),
        }
    }
}

impl fmt::Display for Family {
    /// The name, followed by `:parameters` when they differ from the defaults, in the syntax
    /// [`FromStr`] accepts (`shell:1e-10`, `clusters:5,1e-9`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())?;
        if Self::default_named(self.name()) == Some(*self) {
            return Ok(());
        }
        match *self {
            Family::ThinShell { width } => write!(f, ":{width:e}"),
            Family::NarrowLens { radius } => write!(f, ":{radius}"),
            Family::IntegerLattice { half_width } => write!(f, ":{half_width}"),
            Family::Clusters { clusters, spread } => write!(f, ":{clusters},{spread:e}"),
            Family::ManyDuplicates { copies } => write!(f, ":{copies}"),
            _ => Ok(()),
        }
    }
}

/// Why a family name did not parse.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseFamilyError {
    input: String,
    reason: String,
}

impl fmt::Display for ParseFamilyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invalid point family '{}': {}", self.input, self.reason)
    }
}

impl std::error::Error for ParseFamilyError {}

impl FromStr for Family {
    type Err = ParseFamilyError;

    /// Parses `name` or `name:parameters` (case-insensitive name): `cube`, `sphere`, `corners`,
    /// `simplex`, `shell[:width]`, `lens[:radius]`, `lattice[:half_width]`,
    /// `clusters[:count[,spread]]`, `duplicates[:copies]`, `tilted`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let err = |reason: String| ParseFamilyError {
            input: s.to_string(),
            reason,
        };
        let (name, params) = match s.trim().split_once(':') {
            Some((name, params)) => (name, Some(params)),
            None => (s.trim(), None),
        };
        let name = name.trim().to_ascii_lowercase();
        let family = Self::default_named(&name).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.iter().map(Family::name).collect();
            err(format!(
                "unknown name; expected one of {}",
                names.join(", ")
            ))
        })?;
        let Some(params) = params else {
            return Ok(family);
        };
        let params: Vec<&str> = params.split(',').map(str::trim).collect();
        let float = |t: &str| {
            t.parse::<f64>()
                .map_err(|_| err(format!("'{t}' is not a number")))
        };
        let int = |t: &str| {
            t.parse::<usize>()
                .map_err(|_| err(format!("'{t}' is not a non-negative integer")))
        };
        let arity = |max: usize| {
            if params.len() > max {
                Err(err(format!(
                    "{name} takes at most {max} parameter(s), got {}",
                    params.len()
                )))
            } else {
                Ok(())
            }
        };
        let family = match family {
            Family::ThinShell { .. } => {
                arity(1)?;
                Family::ThinShell {
                    width: float(params[0])?,
                }
            }
            Family::NarrowLens { .. } => {
                arity(1)?;
                Family::NarrowLens {
                    radius: float(params[0])?,
                }
            }
            Family::IntegerLattice { .. } => {
                arity(1)?;
                let half_width = u32::try_from(int(params[0])?)
                    .map_err(|_| err("lattice half width is too large".to_string()))?;
                Family::IntegerLattice { half_width }
            }
            Family::Clusters { spread, .. } => {
                arity(2)?;
                Family::Clusters {
                    clusters: int(params[0])?,
                    spread: match params.get(1) {
                        Some(t) => float(t)?,
                        None => spread,
                    },
                }
            }
            Family::ManyDuplicates { .. } => {
                arity(1)?;
                Family::ManyDuplicates {
                    copies: int(params[0])?,
                }
            }
            _ => return Err(err(format!("{name} takes no parameters"))),
        };
        family.validate().map_err(err)?;
        Ok(family)
    }
}

/// The exact number of points [`generate`] returns for this family, dimension and `n`.
pub fn point_count(family: &Family, dimension: usize, n: usize) -> usize {
    match family {
        Family::CubeCornersDiamond => (1usize << dimension) + 2 * dimension + n,
        Family::Simplex => dimension + 1 + n,
        _ => n,
    }
}

/// Generates the point set `(family, n, seed)` in dimension `D`.
///
/// Deterministic: the same arguments give the same points (see [`Rng`] for the fine print).
/// Returns [`point_count`]`(family, D, n)` points.
///
/// # Panics
///
/// If the family's parameters are out of range (see each variant; [`FromStr`] rejects them with
/// an error instead).
pub fn generate<const D: usize>(family: &Family, n: usize, seed: u64) -> Vec<[f64; D]> {
    generate_flat(family, D, n, seed)
        .chunks_exact(D.max(1))
        .map(|row| std::array::from_fn(|i| row[i]))
        .collect()
}

/// [`generate`] with the dimension chosen at run time: the points row-major in one vector
/// (`point_count(family, dimension, n) · dimension` numbers). Same points as
/// `generate::<dimension>`.
///
/// # Panics
///
/// As [`generate`]; also if `dimension` is 0 or above 62.
pub fn generate_flat(family: &Family, dimension: usize, n: usize, seed: u64) -> Vec<f64> {
    if let Err(reason) = family.validate() {
        panic!("rbox::generate: {reason}");
    }
    assert!(
        (1..=62).contains(&dimension),
        "rbox::generate: dimension must be in 1..=62, got {dimension}"
    );
    let d = dimension;
    let mut rng = Rng::new(seed);
    let mut out = Vec::with_capacity(point_count(family, d, n) * d);
    match *family {
        Family::UniformCube => {
            for _ in 0..n * d {
                out.push(rng.uniform() - 0.5);
            }
        }
        Family::SphereSurface => {
            for _ in 0..n {
                out.extend(rng.unit_vector(d).into_iter().map(|x| 0.5 * x));
            }
        }
        Family::ThinShell { width } => {
            for _ in 0..n {
                let r = 0.5 * (1.0 + width * rng.uniform_in(-1.0, 1.0));
                out.extend(rng.unit_vector(d).into_iter().map(|x| r * x));
            }
        }
        Family::CubeCornersDiamond => {
            for corner in 0..1usize << d {
                out.extend((0..d).map(|i| if corner >> i & 1 == 1 { 0.5 } else { -0.5 }));
            }
            for i in 0..d {
                for sign in [0.5, -0.5] {
                    out.extend((0..d).map(|j| if j == i { sign } else { 0.0 }));
                }
            }
            for _ in 0..n * d {
                out.push(rng.uniform() - 0.5);
            }
        }
        Family::Simplex => simplex(&mut rng, d, n, &mut out),
        Family::NarrowLens { radius } => {
            let c = (radius * radius - 0.25).sqrt();
            for j in 0..n {
                // p uniform in the (d−1)-ball of radius 0.5.
                let scale = 0.5 * rng.uniform().powf(1.0 / (d as f64 - 1.0).max(1.0));
                let p: Vec<f64> = if d > 1 {
                    rng.unit_vector(d - 1)
                        .into_iter()
                        .map(|x| scale * x)
                        .collect()
                } else {
                    Vec::new()
                };
                let p2: f64 = p.iter().map(|x| x * x).sum();
                let h = ((radius * radius - p2).sqrt() - c).max(0.0);
                out.extend(p);
                out.push(if j % 2 == 0 { h } else { -h });
            }
        }
        Family::IntegerLattice { half_width } => {
            let m = i64::from(half_width);
            let mut base = vec![0i64; d];
            for b in &mut base {
                *b = rng.below(2 * m as u64) as i64 - m; // in [−m, m − 1]
            }
            for j in 0..n {
                if j <= d {
                    out.extend((0..d).map(|i| (base[i] + i64::from(j == i + 1)) as f64));
                } else {
                    out.extend((0..d).map(|_| (rng.below(2 * m as u64 + 1) as i64 - m) as f64));
                }
            }
        }
        Family::Clusters { clusters, spread } => {
            let k = if clusters == 0 { d + 1 } else { clusters };
            let centres: Vec<f64> = (0..k * d).map(|_| rng.uniform() - 0.5).collect();
            for j in 0..n {
                let centre = &centres[(j % k) * d..(j % k + 1) * d];
                out.extend(
                    centre
                        .iter()
                        .map(|&c| c + spread * rng.uniform_in(-1.0, 1.0)),
                );
            }
        }
        Family::ManyDuplicates { copies } => {
            let m = n.div_ceil(copies).max(n.min(d + 1));
            let distinct: Vec<f64> = (0..m * d).map(|_| rng.uniform() - 0.5).collect();
            for j in 0..n {
                out.extend_from_slice(&distinct[(j % m) * d..(j % m + 1) * d]);
            }
        }
        Family::TiltedFaces => {
            let rotation = rotation(&mut rng, d);
            let mut p = vec![0.0; d];
            for _ in 0..n {
                for x in &mut p {
                    *x = rng.uniform() - 0.5;
                }
                let face = rng.index(d);
                p[face] = if rng.below(2) == 0 { -0.5 } else { 0.5 };
                for row in rotation.chunks_exact(d) {
                    out.push(row.iter().zip(&p).map(|(r, x)| r * x).sum());
                }
            }
        }
    }
    debug_assert_eq!(out.len(), point_count(family, d, n) * d);
    out
}

/// A `d × d` rotation, row-major: Gram–Schmidt (twice over, for orthogonality to rounding) on
/// rows of normal deviates, each row then made unit. A proper rotation or a reflection, as the
/// deviates fall: either turns the cube's faces into general position, which is all
/// [`Family::TiltedFaces`] needs.
fn rotation(rng: &mut Rng, d: usize) -> Vec<f64> {
    let mut rows: Vec<f64> = Vec::with_capacity(d * d);
    while rows.len() < d * d {
        let mut row: Vec<f64> = (0..d).map(|_| rng.normal()).collect();
        for _ in 0..2 {
            for done in rows.chunks_exact(d) {
                let along: f64 = done.iter().zip(&row).map(|(a, b)| a * b).sum();
                for (x, a) in row.iter_mut().zip(done) {
                    *x -= along * a;
                }
            }
        }
        let length = row.iter().map(|x| x * x).sum::<f64>().sqrt();
        // A row (nearly) in the span of the others has no direction left: draw it again.
        if length > 1e-3 {
            rows.extend(row.iter().map(|x| x / length));
        }
    }
    rows
}

/// [`Family::Simplex`]: vertices, then points on the grid `2^−20` of the simplex.
fn simplex(rng: &mut Rng, d: usize, n: usize, out: &mut Vec<f64>) {
    const GRID: i64 = 1 << 20;
    // In "standard" coordinates y = x + 1 the simplex is { y ≥ 0, Σ y ≤ D + 1 }; a point is an
    // integer vector k ≥ 0 with Σ k ≤ TOTAL and y = k / GRID (exact in f64).
    let total = (d as i64 + 1) * GRID;
    out.extend(std::iter::repeat_n(-1.0, d));
    for i in 0..d {
        out.extend((0..d).map(|j| if i == j { d as f64 } else { -1.0 }));
    }
    let mut k = vec![0i64; d + 1]; // k[0] is the slack weight of v_0
    for j in 0..n {
        k.iter_mut().for_each(|x| *x = 0);
        match j % 4 {
            2 => {
                // Midpoint of a random edge (v_a, v_b): half of TOTAL on each.
                let a = rng.index(d + 1);
                let b = (a + 1 + rng.index(d)) % (d + 1);
                k[a] += total / 2;
                k[b] += total / 2;
            }
            kind => {
                // Random barycentric weights (exponential spacings: uniform on the simplex).
                let w: Vec<f64> = (0..=d).map(|_| -(1.0 - rng.uniform()).ln()).collect();
                let zero = if kind == 1 {
                    Some(rng.index(d + 1))
                } else {
                    None
                };
                let sum: f64 = w
                    .iter()
                    .enumerate()
                    .filter(|&(i, _)| Some(i) != zero)
                    .map(|(_, w)| w)
                    .sum();
                for i in 0..=d {
                    if Some(i) != zero {
                        k[i] = (w[i] / sum * total as f64).floor() as i64;
                    }
                }
                // Rounding can only leave the sum a little short (or, in theory, over): put the
                // difference on a weight that is allowed to be non-zero.
                let target = (0..=d).find(|&i| Some(i) != zero).unwrap_or(0);
                k[target] += total - k.iter().sum::<i64>();
                if k[target] < 0 {
                    k[target] = 0;
                }
            }
        }
        out.extend(k[1..].iter().map(|&ki| ki as f64 / GRID as f64 - 1.0));
    }
}

#[cfg(test)]
mod tests;
