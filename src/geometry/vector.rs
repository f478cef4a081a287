//! Vectors as plain arrays `[f64; D]`, passed by value (they are `Copy` and at most 64 bytes): the
//! one set of helpers every layer uses, so that `scale` means `a·s` everywhere.

/// `a + b`.
#[inline]
pub fn add<const D: usize>(a: [f64; D], b: [f64; D]) -> [f64; D] {
    std::array::from_fn(|i| a[i] + b[i])
}

/// `a − b`.
#[inline]
pub fn sub<const D: usize>(a: [f64; D], b: [f64; D]) -> [f64; D] {
    std::array::from_fn(|i| a[i] - b[i])
}

/// `a·s`.
#[inline]
pub fn scale<const D: usize>(a: [f64; D], s: f64) -> [f64; D] {
    a.map(|x| x * s)
}

/// `a · b`, summed in coordinate order.
#[inline]
pub fn dot<const D: usize>(a: [f64; D], b: [f64; D]) -> f64 {
    a.iter().zip(&b).map(|(x, y)| x * y).sum()
}

/// `a × b` (right-handed).
///
/// ```
/// use pqhull::geometry::vector::cross;
/// assert_eq!(cross([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]), [0.0, 0.0, 1.0]);
/// ```
#[inline]
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Whether every coordinate is finite.
#[inline]
pub fn is_finite<const D: usize>(a: [f64; D]) -> bool {
    a.iter().all(|x| x.is_finite())
}

/// The Euclidean norm of `v` without overflow or underflow of the squares: the plain
/// `sqrt(v·v)` when the squares are in range, else computed in units of the largest coordinate.
/// A non-finite coordinate gives its absolute value (∞ or NaN).
///
/// ```
/// use pqhull::geometry::vector::norm;
/// assert_eq!(norm([3.0, 4.0]), 5.0);
/// assert_eq!(norm([3e-300, 4e-300]), 5e-300); // the squares would underflow
/// assert_eq!(norm([3e300, 4e300]), 5e300); // or overflow
/// ```
#[inline]
pub fn norm<const D: usize>(v: [f64; D]) -> f64 {
    let squares = dot(v, v);
    if (1e-280..=1e280).contains(&squares) {
        // The common case, and a hot one (every new facet): no square that matters was lost.
        return squares.sqrt();
    }
    let largest = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if largest == 0.0 || !largest.is_finite() {
        return largest;
    }
    largest
        * v.iter()
            .map(|x| (x / largest) * (x / largest))
            .sum::<f64>()
            .sqrt()
}

/// `a / |a|` for a finite `a`, or `None` when `a` is zero or not finite. Tiny (subnormal) and huge
/// finite vectors normalise without underflow or overflow.
///
/// ```
/// use pqhull::geometry::vector::normalize;
/// assert_eq!(normalize([0.0, 1e-310, 0.0]), Some([0.0, 1.0, 0.0]));
/// assert_eq!(normalize([0.0; 3]), None);
/// ```
pub fn normalize<const D: usize>(a: [f64; D]) -> Option<[f64; D]> {
    if !is_finite(a) {
        return None;
    }
    let m = a.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if m == 0.0 {
        return None;
    }
    // Divide (rather than multiply by 1/m, which overflows for a subnormal m).
    let w = a.map(|x| x / m);
    Some(scale(w, 1.0 / norm(w)))
}

/// Neumaier's compensated sum: the error is about one rounding of the result plus `n·ε²·Σ|x|`,
/// instead of `n·ε·Σ|x|` for a plain running sum.
///
/// ```
/// use pqhull::geometry::vector::Sum;
/// let mut s = Sum::default();
/// for x in [1.0, 1e100, 1.0, -1e100] {
///     s.add(x);
/// }
/// assert_eq!(s.value(), 2.0);
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Sum {
    sum: f64,
    compensation: f64,
}

impl Sum {
    /// Adds `x`.
    pub fn add(&mut self, x: f64) {
        let t = self.sum + x;
        if self.sum.abs() >= x.abs() {
            self.compensation += (self.sum - t) + x;
        } else {
            self.compensation += (x - t) + self.sum;
        }
        self.sum = t;
    }

    /// The sum so far.
    pub fn value(&self) -> f64 {
        self.sum + self.compensation
    }
}

/// A [`Sum`] per coordinate.
#[derive(Clone, Copy, Debug)]
pub struct VectorSum<const D: usize>([Sum; D]);

impl<const D: usize> Default for VectorSum<D> {
    fn default() -> Self {
        Self([Sum::default(); D])
    }
}

impl<const D: usize> VectorSum<D> {
    /// Adds `v`.
    pub fn add(&mut self, v: [f64; D]) {
        for (s, x) in self.0.iter_mut().zip(v) {
            s.add(x);
        }
    }

    /// The sum so far.
    pub fn value(&self) -> [f64; D] {
        std::array::from_fn(|i| self.0[i].value())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn helpers_agree_with_hand_computation() {
        assert_eq!(add([1.0, 2.0], [3.0, 4.0]), [4.0, 6.0]);
        assert_eq!(sub([1.0, 2.0], [3.0, 5.0]), [-2.0, -3.0]);
        assert_eq!(scale([1.0, -2.0], 3.0), [3.0, -6.0]);
        assert_eq!(dot([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]), 32.0);
        assert_eq!(cross([0.0, 1.0, 0.0], [0.0, 0.0, 1.0]), [1.0, 0.0, 0.0]);
        assert!(!is_finite([1.0, f64::NAN]));
        assert_eq!(normalize([f64::INFINITY, 0.0]), None);
        assert_eq!(norm([0.0, f64::INFINITY]), f64::INFINITY);
    }

    #[test]
    fn compensated_sum_keeps_what_a_plain_sum_loses() {
        let (mut s, mut plain) = (VectorSum::<2>::default(), [0.0; 2]);
        for x in [1.0, 1e100, 1.0, -1e100] {
            s.add([x, -x]);
            plain = add(plain, [x, -x]);
        }
        assert_eq!(s.value(), [2.0, -2.0]);
        assert_eq!(plain, [0.0, 0.0]);
    }
}
