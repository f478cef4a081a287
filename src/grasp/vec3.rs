//! Small 3-vector helpers (private to the grasp module).

/// a + b
pub(crate) fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// a − b
pub(crate) fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// s·a
pub(crate) fn scale(s: f64, a: [f64; 3]) -> [f64; 3] {
    [s * a[0], s * a[1], s * a[2]]
}

/// a · b
pub(crate) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// a × b
pub(crate) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Whether every coordinate is finite.
pub(crate) fn is_finite(a: [f64; 3]) -> bool {
    a.iter().all(|x| x.is_finite())
}

/// Euclidean length.
pub(crate) fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// `a / |a|` for a finite `a`, or `None` when `a` is exactly zero. The vector is first divided by
/// its largest absolute coordinate, so tiny (subnormal) and huge finite vectors normalise without
/// underflow or overflow.
pub(crate) fn normalize(a: [f64; 3]) -> Option<[f64; 3]> {
    let m = a.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if m == 0.0 {
        return None;
    }
    let w = [a[0] / m, a[1] / m, a[2] / m];
    Some(scale(1.0 / norm(w), w))
}
