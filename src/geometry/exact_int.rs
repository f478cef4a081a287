//! Exact integer pieces shared by the exact predicates (`predicates::exact`) and the exact
//! minimum-norm point (`nearest::exact`): a finite `f64` as an odd integer times a power of two,
//! and the determinant of an integer matrix by Bareiss elimination. They sit in the lowest layer
//! so that both consumers use one copy (the predicates are a layer above the geometry).

use num_bigint::BigInt;
use num_traits::{One, Zero};

/// `x = m · 2^e` with `m` odd, or `None` for zero (either sign).
///
/// The caller checks that `x` is finite, each with its own message.
///
/// # Panics
/// In debug builds, if `x` is not finite (in release builds the result is meaningless).
pub(crate) fn odd_mantissa(x: f64) -> Option<(i64, i32)> {
    debug_assert!(x.is_finite(), "odd_mantissa: {x} is not finite");
    if x == 0.0 {
        return None;
    }
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = (bits & ((1u64 << 52) - 1)) as i64;
    let (mantissa, exponent) = if biased == 0 {
        (fraction, -1074) // subnormal
    } else {
        (fraction | (1i64 << 52), biased - 1075)
    };
    let zeros = mantissa.trailing_zeros();
    let mantissa = mantissa >> zeros;
    let signed = if bits >> 63 == 1 { -mantissa } else { mantissa };
    Some((signed, exponent + zeros as i32))
}

/// The exact determinant of a square integer matrix (the empty matrix's is 1), by Bareiss's
/// fraction-free elimination with row swaps: after step k every remaining entry is a
/// (k + 1) × (k + 1) minor, so each division by the previous pivot is exact.
pub(crate) fn bareiss_determinant(mut a: Vec<Vec<BigInt>>) -> BigInt {
    let n = a.len();
    if n == 0 {
        return BigInt::one();
    }
    let mut negate = false;
    let mut previous = BigInt::one();
    for k in 0..n - 1 {
        if a[k][k].is_zero() {
            let Some(row) = (k + 1..n).find(|&r| !a[r][k].is_zero()) else {
                return BigInt::zero();
            };
            a.swap(k, row);
            negate = !negate;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let value = &a[i][j] * &a[k][k] - &a[i][k] * &a[k][j];
                a[i][j] = value / &previous;
            }
        }
        previous = a[k][k].clone();
    }
    let det = a[n - 1][n - 1].clone();
    if negate { -det } else { det }
}

#[cfg(test)]
mod tests {
    use super::{bareiss_determinant, odd_mantissa};
    use num_bigint::BigInt;

    #[test]
    fn determinants_of_small_integer_matrices() {
        let m = |rows: &[&[i64]]| -> Vec<Vec<BigInt>> {
            rows.iter()
                .map(|r| r.iter().map(|&x| BigInt::from(x)).collect())
                .collect()
        };
        assert_eq!(bareiss_determinant(Vec::new()), BigInt::from(1));
        assert_eq!(bareiss_determinant(m(&[&[-7]])), BigInt::from(-7));
        assert_eq!(bareiss_determinant(m(&[&[2, 1], &[1, 3]])), BigInt::from(5));
        // A zero pivot: the rows are swapped, the sign flipped.
        assert_eq!(
            bareiss_determinant(m(&[&[0, 1, 2], &[1, 0, 3], &[4, -3, 8]])),
            BigInt::from(-2)
        );
        assert_eq!(bareiss_determinant(m(&[&[1, 2], &[2, 4]])), BigInt::from(0));
        assert_eq!(
            bareiss_determinant(m(&[&[0, 0], &[0, 5]])),
            BigInt::from(0),
            "a zero column"
        );
    }

    #[test]
    fn mantissas_are_odd_and_exact() {
        assert_eq!(odd_mantissa(0.0), None);
        assert_eq!(odd_mantissa(-0.0), None);
        assert_eq!(odd_mantissa(1.0), Some((1, 0)));
        assert_eq!(odd_mantissa(-6.0), Some((-3, 1)));
        assert_eq!(odd_mantissa(0.375), Some((3, -3)));
        assert_eq!(odd_mantissa(f64::from_bits(1)), Some((1, -1074)));
        let (m, e) = odd_mantissa(f64::MAX).unwrap();
        assert_eq!((m, e), ((1i64 << 53) - 1, 971));
        for x in [0.1, -1e300, 3.5e-310, -5e-324, 123456.789] {
            let (m, e) = odd_mantissa(x).unwrap();
            assert!(m % 2 != 0, "{x}: {m} is even");
            // 2^e in two exact halves: `powi` of a subnormal power goes through an overflowing
            // reciprocal.
            let half = e / 2;
            assert_eq!(m as f64 * 2f64.powi(half) * 2f64.powi(e - half), x, "{x}");
        }
    }
}
