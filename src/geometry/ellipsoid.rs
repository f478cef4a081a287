//! Minimum-volume ellipsoids centred at the origin (Borst et al.'s OWS approximation).
//!
//! Borst, Fischer & Hirzinger ("Grasp planning: how to choose a suitable task wrench space",
//! ICRA 2004) approximate a task or object wrench space — a point set P ⊂ R⁶ — by an enclosing
//! ellipsoid E centred at the origin, map wrench space linearly so that E becomes the unit ball,
//! and take the Ferrari–Canny Q1 of the mapped grasp wrench space as an approximation of the
//! object-wrench-space metric. [`CentredEllipsoid`] is the ellipsoid part, in any dimension `D`:
//! [`CentredEllipsoid::try_enclosing`] computes it, [`CentredEllipsoid::map`] (or the matrix
//! [`CentredEllipsoid::factor`]) is the linear map. Because E always contains every point of P,
//! a metric computed on the mapped spaces bounds the exact one from below.
//!
//! The linear algebra (Cholesky factorisations, triangular inverses, solves, eigenvalues for the
//! rank test) is [`faer`]'s.

use std::fmt;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::{
    LltRegularization, cholesky_in_place, cholesky_in_place_scratch,
};
use faer::linalg::solvers::Solve;
use faer::linalg::triangular_inverse::invert_lower_triangular;
use faer::{Mat, Par, Side};

use super::vector::dot;

/// A reasonable default for the `tolerance` of [`CentredEllipsoid::try_enclosing`]: the volume is
/// then within a factor `(1 + 1e−7)^(D/2)` (about `1 + 3e−7` in 6-D) of the minimum.
pub const DEFAULT_TOLERANCE: f64 = 1e-7;

/// The most Khachiyan / Todd–Yıldırım steps [`CentredEllipsoid::try_enclosing`] takes before it
/// gives up with [`EllipsoidError::NoConvergence`].
pub const MAX_ITERATIONS: usize = 100_000;

/// The numerical-rank threshold: an eigenvalue of the points' mean second-moment matrix
/// `(1/n) Σ x_i x_iᵀ` counts towards the rank only above `RANK_TOLERANCE` times the largest. So a
/// set whose root-mean-square extent in some direction is below `10⁻⁶` of that in another is
/// [`EllipsoidError::RankDeficient`] — also when a far outlier dominates the mean (then `f64`
/// could not resolve the other directions of the iteration's matrices either).
pub const RANK_TOLERANCE: f64 = 1e-12;

/// The slack of [`CentredEllipsoid::contains`]: `x` is contained when `xᵀ A x ≤ 1 + CONTAINMENT_SLACK`.
///
/// The input points themselves need no slack: each has `gauge ≤ 1` exactly as computed.
pub const CONTAINMENT_SLACK: f64 = 1e-12;

/// First-order steps (rank-one updates) between two refactorisations from scratch.
const REFRESH_INTERVAL: usize = 50;
/// The most Newton steps after each refactorisation.
const NEWTON_STEPS: usize = 8;
/// Smallest accepted denominator `1 − τ + τ g` of a rank-one update (> 0 in exact arithmetic).
const DENOMINATOR_FLOOR: f64 = 1e-12;

/// An ellipsoid centred at the origin, `E = { x : xᵀ A x ≤ 1 }` with `A = RᵀR` symmetric positive
/// definite, built by [`CentredEllipsoid::try_enclosing`] as the (approximately) minimum-volume
/// such ellipsoid enclosing a point set — equivalently, the minimum-volume enclosing ellipsoid of
/// the symmetric set `±points`.
///
/// # Algorithm
///
/// The dual problem (Todd, *Minimum-Volume Ellipsoids: Theory and Algorithms*, SIAM 2016, the
/// central case) maximises `ln det M(u)`, `M(u) = Σ u_i x_i x_iᵀ`, over the unit simplex; at the
/// optimum `E = { x : xᵀ M(u)⁻¹ x ≤ D }`. With `g_i = x_iᵀ M⁻¹ x_i`:
///
/// * Start: `u_i = 1/n` if that already meets the tolerance (the cube's corners, the
///   cross-polytope); otherwise `1/D` on `D` points chosen by pivoted Gram–Schmidt on the
///   points whitened by the uniform `M` (a Kumar–Yıldırım-style start: interior points then
///   never carry weight that must be removed one step at a time).
/// * First-order steps, exact line search (Khachiyan 1996): towards the point `j` with the
///   largest `g_j`, `τ = (g_j − D) / (D (g_j − 1))`; or, when the smallest `g_k` over the
///   support is further below `D` than `g_j` is above, the Todd–Yıldırım "away" step
///   (Discrete Appl. Math. 155, 2007) from `k`, dropping it when the line search would make
///   `u_k` negative. `M⁻¹` and the `g_i` are updated by Sherman–Morrison in `O(D)` per point,
///   without allocation; every 50 steps `M` is rebuilt and refactorised (Cholesky) from scratch.
/// * Newton steps: after each refactorisation, up to 8 Newton steps on the support for the
///   weights (see `Solver::newton`). First-order steps alone crawl when many points lie close to
///   the optimal ellipsoid (100,000 steps were not enough for 10,000 points on a 6-D sphere);
///   with them it takes a few hundred.
/// * Active set (as in Sun & Freund, Oper. Res. 52, 2004): all this runs on a working set — the
///   starting points and the `4D² + 16` points farthest out under uniform weights; when it has
///   converged there, the worst points of the whole set still beyond the tolerance join it, until
///   none is. A step then costs `O(working set · D)`, and a round `O(n D²)`.
///
/// It stops when `max_i g_i ≤ D (1 + tolerance)` over all points, on freshly factorised values.
/// The result is `A = M⁻¹ / max_i g_i`, which touches the farthest point, shrunk by a few units
/// in the last place if needed so that every input point has `gauge ≤ 1` as computed by
/// [`CentredEllipsoid::gauge`]. The iteration is invariant under linear maps of the input (the
/// rank test is not), so the points `T x_i` give `A' = T⁻ᵀ A T⁻¹` up to rounding.
///
/// # Guarantee
///
/// Every input point is contained, whatever the tolerance. The volume is within a factor
/// `(1 + ε)^(D/2)` of the minimum, `ε = tolerance` (Todd 2016, ε-primal feasibility; Kumar &
/// Yıldırım, J. Optim. Theory Appl. 126, 2005, for the non-central case). Proof: for any
/// enclosing `{xᵀ H x ≤ 1}` and any `u` in the simplex, `tr(H M(u)) = Σ u_i x_iᵀ H x_i ≤ 1`, so by
/// the AM–GM inequality on the eigenvalues `det(H M) ≤ D^−D`, i.e. the volume is at least
/// `vol(B) det(D M)^{1/2}`; the result has volume `vol(B) det(g_max M)^{1/2}` with
/// `g_max ≤ D (1 + ε)`. The bound actually certified, `(D/2) ln(g_max / D)`, is
/// [`CentredEllipsoid::log_volume_gap_bound`] (often far below the tolerance, thanks to the
/// Newton steps). A volume that close does not make the matrix as close: near the optimum the
/// volume is flat, so entries may differ from the minimal one's by `O(√ε)`.
///
/// Coordinates are first scaled by a power of two (exactly), so the result does not depend on the
/// units and neither huge nor tiny coordinates overflow.
///
/// # Example
///
/// ```
/// use pqhull::geometry::ellipsoid::CentredEllipsoid;
///
/// // Two corners of the square [−1, 1]² (with their mirror images, all four) and two points
/// // inside: the centred minimum-volume ellipsoid is the disc of radius √2, A = I / 2.
/// let points = [[1.0, 1.0], [1.0, -1.0], [0.3, 0.2], [-0.5, 0.9]];
/// let e = CentredEllipsoid::try_enclosing(&points, 1e-10)?;
/// let a = e.matrix();
/// assert!((a[0][0] - 0.5).abs() < 1e-4 && (a[1][1] - 0.5).abs() < 1e-4 && a[0][1].abs() < 1e-4);
///
/// assert!(points.iter().all(|p| e.contains(p) && e.gauge(p) <= 1.0));
/// assert!((e.gauge(&[1.0, -1.0]) - 1.0).abs() < 1e-12); // a corner is on the boundary
/// let y = e.map(&[1.0, 1.0]); // R x: the ellipsoid onto the unit disc
/// assert!((y[0].hypot(y[1]) - 1.0).abs() < 1e-12);
/// assert!(e.log_volume_gap_bound() <= 1e-10);
/// # Ok::<(), pqhull::geometry::ellipsoid::EllipsoidError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CentredEllipsoid<const D: usize> {
    /// Lower-triangular `R̃` of the scaled problem: `R = scale · R̃`, `A = RᵀR`.
    factor: [[f64; D]; D],
    /// The power of two the coordinates were multiplied by.
    scale: f64,
    iterations: usize,
    log_gap: f64,
}

impl<const D: usize> CentredEllipsoid<D> {
    /// The (approximately) minimum-volume ellipsoid centred at the origin enclosing every point of
    /// `points`, to within a volume factor `(1 + tolerance)^(D/2)` (see the [type docs](Self)).
    ///
    /// `tolerance` is the relative excess `max_i x_iᵀ M⁻¹ x_i / D − 1` at which the iteration
    /// stops; [`DEFAULT_TOLERANCE`] is a good choice, and values below about `1e−13` may not be
    /// reachable in floating point. The cost is `O(n D²)` per round over all `n` points, with the
    /// steps in between on the much smaller working set (see the [type docs](Self)).
    ///
    /// # Errors
    ///
    /// * [`EllipsoidError::InvalidTolerance`] when `tolerance` is not finite and positive;
    /// * [`EllipsoidError::TooFewPoints`] with fewer than `D` points;
    /// * [`EllipsoidError::NonFinite`] naming the first point with a NaN or infinite coordinate;
    /// * [`EllipsoidError::RankDeficient`] when the points do not span `D` dimensions (to within
    ///   [`RANK_TOLERANCE`]): no centred ellipsoid of finite volume encloses them;
    /// * [`EllipsoidError::NoConvergence`] after [`MAX_ITERATIONS`] steps;
    /// * [`EllipsoidError::NumericalFailure`] if the weighted second-moment matrix stops being
    ///   numerically positive definite (nearly flat inputs just above the rank threshold).
    pub fn try_enclosing(points: &[[f64; D]], tolerance: f64) -> Result<Self, EllipsoidError> {
        const { assert!(D >= 1, "the dimension D must be at least 1") };
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(EllipsoidError::InvalidTolerance { tolerance });
        }
        if points.len() < D {
            return Err(EllipsoidError::TooFewPoints {
                points: points.len(),
                required: D,
            });
        }
        let mut largest = 0.0_f64;
        for (index, p) in points.iter().enumerate() {
            if let Some(coordinate) = p.iter().position(|c| !c.is_finite()) {
                return Err(EllipsoidError::NonFinite { index, coordinate });
            }
            largest = p.iter().fold(largest, |m, c| m.max(c.abs()));
        }
        // An exact power of two bringing the largest coordinate into [1, 2).
        let exponent = (largest.log2().floor() as i32).clamp(-1020, 1020);
        let scale = 2.0_f64.powi(-exponent);
        let xs: Vec<[f64; D]> = points.iter().map(|p| p.map(|c| c * scale)).collect();
        let rank = if largest > 0.0 {
            numerical_rank(&xs)?
        } else {
            0
        };
        if rank < D {
            return Err(EllipsoidError::RankDeficient { rank, dimension: D });
        }

        let mut solver = Solver::new(&xs);
        let iterations = solver.solve(tolerance)?;
        let (factor, log_gap) = solver.finish(iterations)?;
        Ok(CentredEllipsoid {
            factor,
            scale,
            iterations,
            log_gap,
        })
    }

    /// Whether `x` is in the ellipsoid: `xᵀ A x ≤ 1 +` [`CONTAINMENT_SLACK`]. Every point given to
    /// [`try_enclosing`](Self::try_enclosing) is contained. `false` for a NaN coordinate.
    pub fn contains(&self, x: &[f64; D]) -> bool {
        self.gauge_squared(x) <= 1.0 + CONTAINMENT_SLACK
    }

    /// The gauge (Minkowski functional) `sqrt(xᵀ A x) = |R x|`: below 1 inside, 1 on the
    /// boundary, `t` for `t` times a boundary point.
    pub fn gauge(&self, x: &[f64; D]) -> f64 {
        self.gauge_squared(x).sqrt()
    }

    /// `R x`, the linear map sending the ellipsoid onto the unit ball (`|R x| = gauge(x)`).
    /// This is the map Borst et al. apply to both wrench spaces.
    pub fn map(&self, x: &[f64; D]) -> [f64; D] {
        lower_times(&self.factor, &x.map(|c| c * self.scale))
    }

    /// The lower-triangular matrix `R` of [`map`](Self::map), `A = RᵀR` (so `R⁻¹` is the
    /// Cholesky factor of `A⁻¹`). Overflows only for coordinates all below about `1e−300`.
    pub fn factor(&self) -> [[f64; D]; D] {
        self.factor.map(|row| row.map(|r| r * self.scale))
    }

    /// The matrix `A` of `E = { x : xᵀ A x ≤ 1 }` (symmetric positive definite, `RᵀR` rounded).
    /// Its entries scale like `1/length²`, so they overflow for coordinates below about `1e−150`;
    /// [`gauge`](Self::gauge), [`map`](Self::map) and the volumes do not.
    pub fn matrix(&self) -> [[f64; D]; D] {
        let s2 = self.scale * self.scale;
        std::array::from_fn(|a| {
            std::array::from_fn(|b| {
                let r = &self.factor;
                (a.max(b)..D).map(|k| r[k][a] * r[k][b]).sum::<f64>() * s2
            })
        })
    }

    /// `ln(vol E / vol B)`, with `B` the unit ball: `−½ ln det A`.
    pub fn log_volume_ratio_to_ball(&self) -> f64 {
        let log_det_r: f64 = (0..D).map(|k| self.factor[k][k].ln()).sum();
        -log_det_r - D as f64 * self.scale.ln()
    }

    /// `ln vol E` (natural logarithm, so it neither overflows nor underflows).
    pub fn log_volume(&self) -> f64 {
        log_unit_ball_volume(D) + self.log_volume_ratio_to_ball()
    }

    /// A certified bound on `ln(vol E / vol E_min)`, `E_min` the exact minimum-volume centred
    /// ellipsoid: `(D/2) ln(g_max / D)` at the end (and the final shrink, a few ulps), so at most
    /// `(D/2) ln(1 + tolerance)`; see "Guarantee" on the type.
    pub fn log_volume_gap_bound(&self) -> f64 {
        self.log_gap
    }

    /// The number of first-order (Khachiyan / Todd–Yıldırım) steps taken, Newton steps not
    /// counted; 0 if the starting weights were already within the tolerance.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    fn gauge_squared(&self, x: &[f64; D]) -> f64 {
        gauge_squared(&self.factor, &x.map(|c| c * self.scale))
    }
}

/// Why [`CentredEllipsoid::try_enclosing`] failed.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum EllipsoidError {
    /// Fewer than `D` points cannot span `D` dimensions.
    TooFewPoints {
        /// The number of points given.
        points: usize,
        /// The number needed at least (the dimension `D`).
        required: usize,
    },
    /// A point has a NaN or infinite coordinate.
    NonFinite {
        /// Index of the first such point.
        index: usize,
        /// Index of its first non-finite coordinate.
        coordinate: usize,
    },
    /// The points do not span the whole space, so every enclosing centred ellipsoid is unbounded.
    RankDeficient {
        /// The numerical rank of the points (see [`RANK_TOLERANCE`]).
        rank: usize,
        /// The dimension `D`.
        dimension: usize,
    },
    /// The tolerance is not a finite number greater than zero.
    InvalidTolerance {
        /// The tolerance given.
        tolerance: f64,
    },
    /// The tolerance was not reached within [`MAX_ITERATIONS`] steps.
    NoConvergence {
        /// The number of steps taken.
        iterations: usize,
        /// The excess `max_i x_iᵀ M⁻¹ x_i / D − 1` reached (the tolerance it was compared with).
        excess: f64,
    },
    /// The weighted second-moment matrix lost positive definiteness in floating point.
    NumericalFailure {
        /// The step at which it happened.
        iteration: usize,
    },
}

impl fmt::Display for EllipsoidError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EllipsoidError::TooFewPoints { points, required } => write!(
                f,
                "too few points for an enclosing ellipsoid: {points} given, at least {required} \
                 needed to span {required} dimensions"
            ),
            EllipsoidError::NonFinite { index, coordinate } => write!(
                f,
                "point {index} has a NaN or infinite coordinate (coordinate {coordinate})"
            ),
            EllipsoidError::RankDeficient { rank, dimension } => write!(
                f,
                "the points span only {rank} of {dimension} dimensions (numerical rank), so no \
                 ellipsoid centred at the origin of finite volume encloses them"
            ),
            EllipsoidError::InvalidTolerance { tolerance } => write!(
                f,
                "the ellipsoid tolerance must be a finite number greater than 0, got {tolerance}"
            ),
            EllipsoidError::NoConvergence { iterations, excess } => write!(
                f,
                "the minimum-volume ellipsoid iteration did not reach the tolerance in \
                 {iterations} steps (relative excess still {excess:e})"
            ),
            EllipsoidError::NumericalFailure { iteration } => write!(
                f,
                "the weighted second-moment matrix became numerically singular at step \
                 {iteration} (the points are nearly flat)"
            ),
        }
    }
}

impl std::error::Error for EllipsoidError {}

/// The numerical rank of the (scaled) points: eigenvalues of `(1/n) Σ x xᵀ` above
/// [`RANK_TOLERANCE`] times the largest.
fn numerical_rank<const D: usize>(xs: &[[f64; D]]) -> Result<usize, EllipsoidError> {
    let weight = 1.0 / xs.len() as f64;
    let m = second_moment(xs, |_| weight);
    let eigenvalues = Mat::from_fn(D, D, |a, b| m[a.max(b)][a.min(b)])
        .self_adjoint_eigenvalues(Side::Lower)
        .map_err(|_| EllipsoidError::NumericalFailure { iteration: 0 })?;
    let largest = eigenvalues.iter().fold(0.0_f64, |m, &l| m.max(l));
    Ok(eigenvalues
        .iter()
        .filter(|&&l| largest > 0.0 && l > RANK_TOLERANCE * largest)
        .count())
}

/// The lower triangle of `Σ w(i) x_i x_iᵀ` (terms with `w(i) = 0` skipped).
fn second_moment<const D: usize>(xs: &[[f64; D]], w: impl Fn(usize) -> f64) -> [[f64; D]; D] {
    let mut m = [[0.0; D]; D];
    for (i, x) in xs.iter().enumerate() {
        let wi = w(i);
        if wi > 0.0 {
            for (a, row) in m.iter_mut().enumerate() {
                let wx = wi * x[a];
                for (entry, xb) in row.iter_mut().zip(x).take(a + 1) {
                    *entry += wx * xb;
                }
            }
        }
    }
    m
}

/// `L y` for lower-triangular `L`.
fn lower_times<const D: usize>(l: &[[f64; D]; D], y: &[f64; D]) -> [f64; D] {
    std::array::from_fn(|a| l[a].iter().zip(y).take(a + 1).map(|(l, y)| l * y).sum())
}

/// `|L y|²` for lower-triangular `L`.
fn gauge_squared<const D: usize>(l: &[[f64; D]; D], y: &[f64; D]) -> f64 {
    lower_times(l, y).iter().map(|v| v * v).sum()
}

/// The index and value of the largest item (the first of equals; `(0, −∞)` if none).
fn argmax(values: impl Iterator<Item = f64>) -> (usize, f64) {
    let first_largest = |best: (usize, f64), (i, v)| if v > best.1 { (i, v) } else { best };
    values
        .enumerate()
        .fold((0, f64::NEG_INFINITY), first_largest)
}

/// `ln vol(B_D)` by the recurrence `ω_D = ω_{D−2} · 2π / D` (`ω_0 = 1`, `ω_1 = 2`).
fn log_unit_ball_volume(d: usize) -> f64 {
    let start = if d.is_multiple_of(2) {
        0.0
    } else {
        2.0_f64.ln()
    };
    let step = |log: f64, k: usize| log + (2.0 * std::f64::consts::PI / k as f64).ln();
    (2 + d % 2..=d).step_by(2).fold(start, step)
}

/// The iteration state (see "Algorithm" on [`CentredEllipsoid`]): the working set with its
/// weights `u_i` and `g_i`, which points are in it, `M⁻¹`, `L⁻¹`, and faer workspaces.
struct Solver<'a, const D: usize> {
    points: &'a [[f64; D]],
    active: Vec<[f64; D]>,
    u: Vec<f64>,
    g: Vec<f64>,
    member: Vec<bool>,
    m_inv: [[f64; D]; D],
    /// `L⁻¹` (lower triangular) of the last factorisation `M = L Lᵀ`.
    l_inv: [[f64; D]; D],
    work: Mat<f64>,
    inverse: Mat<f64>,
    memory: MemBuffer,
}

/// Size of the initial working set beyond the greedy points; also the most points added per
/// round. Sets of at most twice this size are worked on whole.
const fn added_per_round(d: usize) -> usize {
    4 * d * d + 16
}

impl<'a, const D: usize> Solver<'a, D> {
    fn new(points: &'a [[f64; D]]) -> Self {
        Solver {
            points,
            active: Vec::new(),
            u: Vec::new(),
            g: Vec::new(),
            member: vec![false; points.len()],
            m_inv: [[0.0; D]; D],
            l_inv: [[0.0; D]; D],
            work: Mat::zeros(D, D),
            inverse: Mat::zeros(D, D),
            memory: MemBuffer::new(cholesky_in_place_scratch::<f64>(
                D,
                Par::Seq,
                Default::default(),
            )),
        }
    }

    /// Factorises `M` (its lower triangle) with faer and sets `L⁻¹` and `M⁻¹`; `false` if `M` is
    /// not numerically positive definite.
    fn factorise(&mut self, m: &[[f64; D]; D]) -> bool {
        for (a, row) in m.iter().enumerate() {
            for (b, &v) in row.iter().enumerate().take(a + 1) {
                self.work[(a, b)] = v;
                self.work[(b, a)] = v;
            }
        }
        let stack = MemStack::new(&mut self.memory);
        let params = Default::default();
        let regularization = LltRegularization::default();
        if cholesky_in_place(self.work.as_mut(), regularization, Par::Seq, stack, params).is_err() {
            return false;
        }
        invert_lower_triangular(self.inverse.as_mut(), self.work.as_ref(), Par::Seq);
        for (a, row) in self.l_inv.iter_mut().enumerate() {
            for (b, entry) in row.iter_mut().enumerate() {
                *entry = if b <= a { self.inverse[(a, b)] } else { 0.0 };
            }
        }
        let l = &self.l_inv;
        self.m_inv = std::array::from_fn(|a| {
            std::array::from_fn(|b| (a.max(b)..D).map(|k| l[k][a] * l[k][b]).sum())
        });
        self.l_inv.iter().flatten().all(|v| v.is_finite())
    }

    /// Renormalises `u`, rebuilds and factorises `M`, and recomputes every `g_i` of the working
    /// set, then returns [`scan`](Self::scan).
    fn reset(&mut self, iteration: usize) -> Result<(usize, usize), EllipsoidError> {
        let total: f64 = self.u.iter().sum();
        self.u.iter_mut().for_each(|w| *w /= total);
        let u = &self.u;
        let m = second_moment(&self.active, |i| u[i]);
        if !self.factorise(&m) {
            return Err(EllipsoidError::NumericalFailure { iteration });
        }
        for (g, x) in self.g.iter_mut().zip(&self.active) {
            *g = gauge_squared(&self.l_inv, x);
        }
        Ok(self.scan())
    }

    /// The index of the largest `g_i`, and of the smallest among the weighted points.
    fn scan(&self) -> (usize, usize) {
        let weighted = self.g.iter().zip(&self.u);
        let minus_g = weighted.map(|(&g, &w)| if w > 0.0 { -g } else { f64::NEG_INFINITY });
        (argmax(self.g.iter().copied()).0, argmax(minus_g).0)
    }

    /// Adds `points[i]` to the working set with weight `w`.
    fn enlist(&mut self, i: usize, w: f64) {
        self.member[i] = true;
        self.active.push(self.points[i]);
        self.u.push(w);
        self.g.push(0.0);
    }

    /// The starting weights: uniform on every point if they already meet the tolerance
    /// (symmetric configurations such as the cube's corners); otherwise `1/D` on `D` points
    /// chosen greedily by pivoted Gram–Schmidt — largest residual first — on the points whitened
    /// by the uniform second-moment matrix, which makes the choice, and so the whole iteration,
    /// invariant under linear maps of the input. Starting on few points spares the drop steps
    /// that would remove every interior point's weight one at a time.
    fn initialise(&mut self, tolerance: f64) -> Result<(), EllipsoidError> {
        let n = self.points.len();
        let weight = 1.0 / n as f64;
        if !self.factorise(&second_moment(self.points, |_| weight)) {
            return Err(EllipsoidError::NumericalFailure { iteration: 0 });
        }
        let mut residuals: Vec<[f64; D]> = self
            .points
            .iter()
            .map(|x| lower_times(&self.l_inv, x))
            .collect();
        let g0: Vec<f64> = residuals.iter().map(|y| dot(*y, *y)).collect();
        if g0.iter().all(|&g| g <= D as f64 * (1.0 + tolerance)) {
            (0..n).for_each(|i| self.enlist(i, weight));
            return Ok(());
        }
        let mut chosen = [0; D];
        for slot in &mut chosen {
            let (pivot, norm2) = argmax(residuals.iter().map(|r| dot(*r, *r)));
            if norm2 <= 0.0 || self.member[pivot] {
                return Err(EllipsoidError::NumericalFailure { iteration: 0 });
            }
            self.enlist(pivot, 1.0 / D as f64);
            *slot = pivot;
            let q = residuals[pivot].map(|c| c / norm2.sqrt());
            for r in &mut residuals {
                let t = dot(q, *r);
                r.iter_mut().zip(&q).for_each(|(c, qc)| *c -= t * qc);
            }
        }
        let extra = added_per_round(D);
        let mut order: Vec<usize> = (0..n).filter(|i| !chosen.contains(i)).collect();
        if order.len() > 2 * extra {
            order.select_nth_unstable_by(extra - 1, |&a, &b| g0[b].total_cmp(&g0[a]));
            order.truncate(extra);
        }
        order.into_iter().for_each(|i| self.enlist(i, 0.0));
        Ok(())
    }

    /// Adds the points outside the working set with `g_i > D (1 + tolerance)` under the current
    /// factorisation (the worst [`added_per_round`] of them); returns how many.
    fn add_violators(&mut self, tolerance: f64) -> usize {
        let threshold = D as f64 * (1.0 + tolerance);
        let mut violators: Vec<(f64, usize)> = (self.points.iter().enumerate())
            .filter(|&(i, _)| !self.member[i])
            .map(|(i, x)| (gauge_squared(&self.l_inv, x), i))
            .filter(|&(g, _)| g > threshold)
            .collect();
        let limit = added_per_round(D);
        if violators.len() > limit {
            violators.select_nth_unstable_by(limit - 1, |a, b| b.0.total_cmp(&a.0));
            violators.truncate(limit);
        }
        violators.iter().for_each(|&(_, i)| self.enlist(i, 0.0));
        violators.len()
    }

    /// Iterates on working sets until `max g ≤ D (1 + tolerance)` over all points, on freshly
    /// factorised values; returns the number of steps. On success, `l_inv` is fresh.
    fn solve(&mut self, tolerance: f64) -> Result<usize, EllipsoidError> {
        self.initialise(tolerance)?;
        let mut iterations = 0;
        loop {
            iterations = self.run(tolerance, iterations)?;
            if self.add_violators(tolerance) == 0 {
                return Ok(iterations);
            }
        }
    }

    /// Iterates on the working set until `max g ≤ D (1 + tolerance)` there, on freshly
    /// factorised values; returns the step count, continued from `steps`.
    fn run(&mut self, tolerance: f64, mut steps: usize) -> Result<usize, EllipsoidError> {
        let d = D as f64;
        let (mut j, mut k) = self.reset(steps)?;
        let (mut fresh, mut since_refresh) = (true, 0);
        loop {
            let excess = self.g[j] / d - 1.0;
            if excess <= tolerance && fresh {
                return Ok(steps);
            }
            if excess > tolerance && steps >= MAX_ITERATIONS {
                return Err(EllipsoidError::NoConvergence {
                    iterations: steps,
                    excess,
                });
            }
            let (uk, gk) = (self.u[k], self.g[k]);
            let deficit = if uk > 0.0 && uk < 1.0 {
                1.0 - gk / d
            } else {
                0.0
            };
            let (index, tau, drop) = if excess >= deficit {
                let gj = self.g[j];
                (j, (gj - d) / (d * (gj - 1.0)), false)
            } else {
                // Away step: the line search, or removing k from the support if that is nearer.
                let limit = -uk / (1.0 - uk);
                let optimum = if gk > 1.0 {
                    (gk - d) / (d * (gk - 1.0))
                } else {
                    f64::NEG_INFINITY
                };
                if optimum > limit {
                    (k, optimum, false)
                } else {
                    (k, limit, true)
                }
            };
            let x = &self.active[index];
            let v: [f64; D] = std::array::from_fn(|a| dot(self.m_inv[a], *x));
            let denominator = 1.0 - tau + tau * dot(*x, v);
            let usable = tau.is_finite() && denominator > DENOMINATOR_FLOOR;
            if excess <= tolerance || !usable {
                // About to stop, or to step, on drifted values: decide again on fresh ones.
                if fresh {
                    return Err(EllipsoidError::NumericalFailure { iteration: steps });
                }
                (j, k) = self.reset(steps)?;
                (fresh, since_refresh) = (true, 0);
                continue;
            }

            // M ← (1 − τ) M + τ x xᵀ, by Sherman–Morrison on M⁻¹ and on every g_i.
            steps += 1;
            let coefficient = tau / denominator;
            let (keep, grow) = (1.0 - tau, 1.0 / (1.0 - tau));
            for (row, va) in self.m_inv.iter_mut().zip(&v) {
                for (entry, vb) in row.iter_mut().zip(&v) {
                    *entry = (*entry - coefficient * va * vb) * grow;
                }
            }
            let working = self
                .active
                .iter()
                .zip(self.g.iter_mut())
                .zip(self.u.iter_mut());
            for (i, ((x, g), w)) in working.enumerate() {
                let h = dot(*x, v);
                *g = (*g - coefficient * h * h) * grow;
                *w *= keep;
                if i == index {
                    *w = if drop { 0.0 } else { *w + tau };
                }
            }
            (j, k) = self.scan();
            fresh = false;
            since_refresh += 1;
            if since_refresh >= REFRESH_INTERVAL {
                (j, k) = self.reset(steps)?;
                for _ in 0..NEWTON_STEPS {
                    if !self.newton() {
                        break;
                    }
                    (j, k) = self.reset(steps)?;
                }
                (fresh, since_refresh) = (true, 0);
            }
        }
    }

    /// One Newton step for `max ln det M(u)` over the current support `S = {i : u_i > 0}` with
    /// `Σ u = 1`: with `K = X_Sᵀ M⁻¹ X_S`, the Hessian is `−K∘K` and the gradient `g_S`, so the
    /// step is `Δ = Q⁻¹ (g − μ 1)`, `Q = K∘K + δI` (δ tiny, for supports larger than
    /// `D(D+1)/2`), `μ` such that `Σ Δ = 0` — an ascent direction. A ratio test keeps `u ≥ 0`
    /// (a weight reaching 0 leaves the support) and the step is halved until `ln det M` increases.
    /// The first-order steps find the support; this converges on it quadratically where they
    /// would crawl (points nearly all on the optimal ellipsoid). Needs fresh `l_inv` and `g`;
    /// returns whether `u` changed.
    fn newton(&mut self) -> bool {
        let support: Vec<usize> = (0..self.u.len()).filter(|&i| self.u[i] > 0.0).collect();
        let s = support.len();
        if s < 2 || s > 4 * D * (D + 1) {
            return false;
        }
        let y: Vec<[f64; D]> = support
            .iter()
            .map(|&i| lower_times(&self.l_inv, &self.active[i]))
            .collect();
        let mut q = Mat::from_fn(s, s, |a, b| dot(y[a], y[b]).powi(2));
        let delta = 1e-12 * (0..s).fold(0.0_f64, |m, a| m.max(q[(a, a)]));
        (0..s).for_each(|a| q[(a, a)] += delta);
        let Ok(llt) = q.llt(Side::Lower) else {
            return false;
        };
        let mut rhs = Mat::from_fn(s, 2, |a, c| if c == 0 { self.g[support[a]] } else { 1.0 });
        llt.solve_in_place(&mut rhs);
        let sums = [0, 1].map(|c| (0..s).map(|a| rhs[(a, c)]).sum::<f64>());
        let mu = sums[0] / sums[1];
        let step: Vec<f64> = (0..s).map(|a| rhs[(a, 0)] - mu * rhs[(a, 1)]).collect();
        let (mut t, mut blocking) = (1.0, None);
        for (a, &da) in step.iter().enumerate() {
            let ratio = -self.u[support[a]] / da;
            if da < 0.0 && ratio < t {
                (t, blocking) = (ratio, Some(a));
            }
        }
        let log_det = |l_inv: &[[f64; D]; D]| -2.0 * (0..D).map(|k| l_inv[k][k].ln()).sum::<f64>();
        let before = log_det(&self.l_inv);
        let old = (self.l_inv, self.m_inv);
        let mut trial = vec![0.0; self.u.len()];
        for _ in 0..20 {
            for (a, &i) in support.iter().enumerate() {
                trial[i] = if blocking == Some(a) {
                    0.0
                } else {
                    (self.u[i] + t * step[a]).max(0.0)
                };
            }
            let m = second_moment(&self.active, |i| trial[i]);
            if self.factorise(&m) && log_det(&self.l_inv) > before {
                support.iter().for_each(|&i| self.u[i] = trial[i]);
                return true;
            }
            (t, blocking) = (0.5 * t, None);
        }
        (self.l_inv, self.m_inv) = old;
        false
    }

    /// `R̃ = c L⁻¹` with `c = 1/sqrt(max g)` over all points, shrunk until every point has gauge
    /// ≤ 1 as computed; and the log-volume gap bound `−D ln c − (D/2) ln D`.
    fn finish(&self, iterations: usize) -> Result<([[f64; D]; D], f64), EllipsoidError> {
        let max_gauge = |r: &[[f64; D]; D]| {
            (self.points.iter()).fold(0.0_f64, |m, x| m.max(gauge_squared(r, x)))
        };
        let mut c = max_gauge(&self.l_inv).sqrt().recip();
        let mut r = self.l_inv.map(|row| row.map(|v| v * c));
        for _ in 0..8 {
            let q = max_gauge(&r);
            if q <= 1.0 {
                let d = D as f64;
                return Ok((r, (-d * c.ln() - 0.5 * d * d.ln()).max(0.0)));
            }
            let shrink = q.sqrt().recip() * (1.0 - 4.0 * f64::EPSILON);
            c *= shrink;
            r = r.map(|row| row.map(|v| v * shrink));
        }
        Err(EllipsoidError::NumericalFailure {
            iteration: iterations,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rbox::{Family, generate};

    #[test]
    fn helpers() {
        assert_eq!(argmax([1.0, 3.0, 3.0, f64::NAN, 2.0].into_iter()), (1, 3.0));
        assert_eq!(argmax(std::iter::empty()).0, 0);
        let pi = std::f64::consts::PI;
        assert!((log_unit_ball_volume(5) - (8.0 * pi * pi / 15.0).ln()).abs() < 1e-14);
        let l = [[2.0, 0.0], [1.0, 3.0]];
        assert_eq!(lower_times(&l, &[1.0, 1.0]), [2.0, 4.0]);
        assert_eq!(gauge_squared(&l, &[1.0, 1.0]), 20.0);
    }

    #[test]
    fn newton_steps_increase_log_det_and_keep_weights_in_the_simplex() {
        let points = generate::<4>(&Family::UniformCube, 60, 3);
        let mut solver = Solver::new(&points);
        solver.initialise(1e-9).unwrap();
        assert_eq!(solver.active.len(), 60); // a small set is worked on whole
        let n = solver.u.len() as f64;
        solver.u.iter_mut().for_each(|w| *w = 1.0 / n);
        solver.reset(0).unwrap();
        let log_det = |s: &Solver<4>| -2.0 * (0..4).map(|k| s.l_inv[k][k].ln()).sum::<f64>();
        let (mut last, mut steps) = (log_det(&solver), 0);
        while steps < 10 && solver.newton() {
            solver.reset(0).unwrap();
            assert!(log_det(&solver) > last);
            assert!(solver.u.iter().all(|&w| w >= 0.0));
            assert!((solver.u.iter().sum::<f64>() - 1.0).abs() < 1e-12);
            (last, steps) = (log_det(&solver), steps + 1);
        }
        assert!(steps > 0);
    }
}
