//! Exact linear programming on `f64` data: the points scaled by one power of two to integers
//! ([`IntegerPoints`]) and the largest `r` with `−r·d` in their hull by an integer simplex
//! ([`exact_ray_exit`]): Q_OWS's exact reference, one disturbance at a time.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// `x = m · 2^e` with `m` odd (or 0).
pub fn decompose(x: f64) -> (i64, i32) {
    if x == 0.0 {
        return (0, 0);
    }
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    let fraction = (bits & ((1u64 << 52) - 1)) as i64;
    let (mut m, mut e) = if exponent == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1i64 << 52), exponent - 1075)
    };
    let tz = m.trailing_zeros() as i32;
    m >>= tz;
    e += tz;
    (if negative { -m } else { m }, e)
}

/// Points scaled by one power of two to integers: `points[i][c] = 2^shift · x`.
pub struct IntegerPoints {
    pub shift: i32,
    pub sets: Vec<Vec<[BigInt; 6]>>,
}

impl IntegerPoints {
    /// Every set scaled by the same power of two.
    pub fn new(sets: &[&[[f64; 6]]]) -> Self {
        let shift = sets
            .iter()
            .flat_map(|s| s.iter().flatten())
            .filter(|x| **x != 0.0)
            .map(|&x| -decompose(x).1)
            .max()
            .unwrap_or(0);
        let to_int = |x: f64| {
            let (m, e) = decompose(x);
            BigInt::from(m) << ((e + shift) as usize)
        };
        IntegerPoints {
            shift,
            sets: sets
                .iter()
                .map(|s| s.iter().map(|p| p.map(to_int)).collect())
                .collect(),
        }
    }
}

/// The largest r ≥ 0 with −r·d ∈ CH(points), exactly: the linear program
/// max r s.t. Σ λ_i p_i + r·d = 0, Σ λ_i = 1, λ ≥ 0, r ≥ 0, by the two-phase simplex method with
/// Bland's rule on an integer tableau (Edmonds' fraction-free pivoting: every entry is an integer,
/// the tableau's value is entries / `den`). `None` when the origin is not in the hull (phase 1
/// infeasible); the points and d must be scaled alike ([`IntegerPoints`]).
pub fn exact_ray_exit(points: &[[BigInt; 6]], d: &[BigInt; 6]) -> Option<BigRational> {
    let n = points.len();
    let rows = 7;
    let r_col = n;
    let artificial = n + 1;
    let cols = n + 1 + rows; // λ, r, artificials
    let rhs = cols;
    let zero = BigInt::zero();
    let one = BigInt::from(1);
    // Constraint rows.
    let mut t: Vec<Vec<BigInt>> = (0..rows)
        .map(|row| {
            let mut line = vec![zero.clone(); cols + 1];
            for (i, p) in points.iter().enumerate() {
                line[i] = if row < 6 { p[row].clone() } else { one.clone() };
            }
            line[r_col] = if row < 6 {
                d[row].clone()
            } else {
                zero.clone()
            };
            line[artificial + row] = one.clone();
            line[rhs] = if row == 6 { one.clone() } else { zero.clone() };
            line
        })
        .collect();
    let mut basis: Vec<usize> = (0..rows).map(|row| artificial + row).collect();
    let mut den = one.clone();
    // Phase 1: maximise −Σ artificials; the objective row holds (z_j − c_j) · den.
    let mut obj: Vec<BigInt> = (0..=cols)
        .map(|j| {
            if (artificial..cols).contains(&j) {
                zero.clone()
            } else {
                -t.iter().map(|line| &line[j]).sum::<BigInt>()
            }
        })
        .collect();

    fn pivot(
        t: &mut [Vec<BigInt>],
        obj: &mut [BigInt],
        den: &mut BigInt,
        basis: &mut [usize],
        p: usize,
        q: usize,
    ) {
        let pivot = t[p][q].clone();
        let row_p = t[p].clone();
        let update = |line: &mut [BigInt]| {
            let f = line[q].clone();
            for (x, y) in line.iter_mut().zip(&row_p) {
                *x = (&pivot * &*x - &f * y) / &*den;
            }
        };
        for (i, line) in t.iter_mut().enumerate() {
            if i != p {
                update(line);
            }
        }
        update(obj);
        *den = pivot;
        basis[p] = q;
        if den.is_negative() {
            // Keep den > 0 (the value is entries / den): negate everything.
            for line in t.iter_mut() {
                for x in line.iter_mut() {
                    *x = -&*x;
                }
            }
            for x in obj.iter_mut() {
                *x = -&*x;
            }
            *den = -&*den;
        }
    }

    // Bland's rule over the allowed columns until optimal; false when unbounded.
    let run = |t: &mut Vec<Vec<BigInt>>,
               obj: &mut Vec<BigInt>,
               den: &mut BigInt,
               basis: &mut Vec<usize>,
               allowed: usize|
     -> bool {
        for _ in 0..100_000 {
            let Some(q) = (0..allowed).find(|&j| obj[j].is_negative()) else {
                return true;
            };
            let mut best: Option<usize> = None;
            for i in 0..t.len() {
                if !t[i][q].is_positive() {
                    continue;
                }
                best = match best {
                    None => Some(i),
                    Some(b) => {
                        // t[i][rhs]/t[i][q] vs t[b][rhs]/t[b][q], both denominators positive.
                        let lhs = &t[i][rhs] * &t[b][q];
                        let rhs_b = &t[b][rhs] * &t[i][q];
                        if lhs < rhs_b || (lhs == rhs_b && basis[i] < basis[b]) {
                            Some(i)
                        } else {
                            Some(b)
                        }
                    }
                };
            }
            let Some(p) = best else {
                return false;
            };
            pivot(t, obj, den, basis, p, q);
        }
        panic!("exact simplex: no convergence");
    };
    run(&mut t, &mut obj, &mut den, &mut basis, cols);
    if !obj[rhs].is_zero() {
        return None; // Σ artificials > 0: the origin is not in the hull
    }
    // Drive the artificials out of the basis (degenerate pivots; the constraints have full row
    // rank when the points span 6-D).
    for row in 0..rows {
        if basis[row] >= artificial
            && let Some(q) = (0..artificial).find(|&j| !t[row][j].is_zero())
        {
            pivot(&mut t, &mut obj, &mut den, &mut basis, row, q);
        }
    }
    // Phase 2: maximise r, artificials barred.
    let mut obj: Vec<BigInt> = vec![zero.clone(); cols + 1];
    obj[r_col] = -den.clone();
    if let Some(row) = basis.iter().position(|&b| b == r_col) {
        for j in 0..=cols {
            obj[j] += &t[row][j];
        }
    }
    if !run(&mut t, &mut obj, &mut den, &mut basis, artificial) {
        panic!("exact simplex: r unbounded (the hull is bounded)");
    }
    Some(match basis.iter().position(|&b| b == r_col) {
        Some(row) => BigRational::new(t[row][rhs].clone(), den),
        None => BigRational::zero(),
    })
}
