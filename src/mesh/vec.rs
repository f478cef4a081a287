//! Small 3-vector helpers and a compensated sum, private to the mesh module.

pub(crate) type V3 = [f64; 3];

pub(crate) fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub(crate) fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

pub(crate) fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(crate) fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// `a / |a|`, or `None` when `|a|` is zero (or not finite).
pub(crate) fn normalized(a: V3) -> Option<V3> {
    let n = norm(a);
    (n > 0.0 && n.is_finite()).then(|| scale(a, 1.0 / n))
}

/// Neumaier's compensated sum: the error is about one rounding of the result plus `n·ε²·Σ|x|`,
/// instead of `n·ε·Σ|x|` for a plain running sum.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Sum {
    sum: f64,
    compensation: f64,
}

impl Sum {
    pub(crate) fn add(&mut self, x: f64) {
        let t = self.sum + x;
        if self.sum.abs() >= x.abs() {
            self.compensation += (self.sum - t) + x;
        } else {
            self.compensation += (x - t) + self.sum;
        }
        self.sum = t;
    }

    pub(crate) fn value(&self) -> f64 {
        self.sum + self.compensation
    }
}

/// Three [`Sum`]s, one per coordinate.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Sum3([Sum; 3]);

impl Sum3 {
    pub(crate) fn add(&mut self, v: V3) {
        for (s, x) in self.0.iter_mut().zip(v) {
            s.add(x);
        }
    }

    pub(crate) fn value(&self) -> V3 {
        [self.0[0].value(), self.0[1].value(), self.0[2].value()]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compensated_sum_keeps_what_a_plain_sum_loses() {
        let mut s = Sum::default();
        let mut plain = 0.0;
        for x in [1.0, 1e100, 1.0, -1e100] {
            s.add(x);
            plain += x;
        }
        assert_eq!(s.value(), 2.0);
        assert_eq!(plain, 0.0);
    }

    #[test]
    fn cross_follows_the_right_hand_rule() {
        assert_eq!(cross([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]), [0.0, 0.0, 1.0]);
        assert_eq!(normalized([0.0, 0.0, 0.0]), None);
        let n = normalized([0.0, 3.0, 4.0]).unwrap();
        assert!((n[1] - 0.6).abs() < 1e-15 && (n[2] - 0.8).abs() < 1e-15);
    }
}
