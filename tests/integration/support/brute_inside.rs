//! The exact distance from the origin to the boundary of the hull of integer points, by brute
//! force over every supporting hyperplane (no hull engine involved).

/// The determinant of an integer matrix (fraction-free Gaussian elimination, exact in i128 for
/// the small entries used here).
pub fn determinant(mut m: Vec<Vec<i128>>) -> i128 {
    let n = m.len();
    let mut sign = 1;
    let mut previous = 1i128;
    for k in 0..n {
        let Some(pivot) = (k..n).find(|&r| m[r][k] != 0) else {
            return 0;
        };
        if pivot != k {
            m.swap(pivot, k);
            sign = -sign;
        }
        for r in k + 1..n {
            for c in k + 1..n {
                m[r][c] = (m[r][c] * m[k][k] - m[r][k] * m[k][c]) / previous;
            }
            m[r][k] = 0;
        }
        previous = m[k][k];
    }
    sign * m[n - 1][n - 1]
}

/// A normal of the hyperplane through the integer points `p[subset[i]]` (D of them): the
/// cofactors of the rows `p_s − p_0` along a last row `e_k`; zero when they span no hyperplane.
pub fn integer_normal<const D: usize>(p: &[[i128; D]], subset: &[usize]) -> [i128; D] {
    let rows: Vec<[i128; D]> = subset[1..]
        .iter()
        .map(|&s| std::array::from_fn(|c| p[s][c] - p[subset[0]][c]))
        .collect();
    std::array::from_fn(|k| {
        let mut m: Vec<Vec<i128>> = rows.iter().map(|r| r.to_vec()).collect();
        let mut e = vec![0i128; D];
        e[k] = 1;
        m.push(e);
        determinant(m)
    })
}

/// The exact signed distance from the origin to the boundary of the hull of integer `points`
/// (full-dimensional), by brute force: for every D-subset spanning a hyperplane, its integer
/// normal (cofactors) and offset; a supporting hyperplane (every point on one side) with the
/// origin strictly on the points' side gives the distance `offset/|n|`, and the depth is the
/// smallest. The origin outside (some supporting plane has it strictly beyond) or on the
/// boundary gives `None` / `Some(0)`.
pub fn brute_force_inside<const D: usize>(points: &[[f64; D]]) -> Option<f64> {
    let p: Vec<[i128; D]> = points
        .iter()
        .map(|x| {
            x.map(|c| {
                assert_eq!(c, c.round(), "integer input");
                c as i128
            })
        })
        .collect();
    let n = p.len();
    let mut best: Option<f64> = None;
    let mut subset: Vec<usize> = (0..D).collect();
    loop {
        let normal = integer_normal(&p, &subset);
        if normal.iter().any(|&c| c != 0) {
            let dot = |x: &[i128; D]| (0..D).map(|c| normal[c] * x[c]).sum::<i128>();
            let offset = dot(&p[subset[0]]);
            let heights: Vec<i128> = p.iter().map(|x| dot(x) - offset).collect();
            let below = heights.iter().all(|&h| h <= 0);
            let above = heights.iter().all(|&h| h >= 0);
            if below || above {
                // Orient so the points satisfy n·x ≤ offset: the origin's margin is `offset`.
                let margin = if below { offset } else { -offset };
                if margin < 0 {
                    return None; // a supporting plane separates the origin
                }
                let length = (normal.iter().map(|&c| c * c).sum::<i128>() as f64).sqrt();
                let distance = margin as f64 / length;
                best = Some(best.map_or(distance, |b: f64| b.min(distance)));
            }
        }
        // Next subset in lexicographic order.
        let mut i = D;
        loop {
            if i == 0 {
                return best;
            }
            i -= 1;
            if subset[i] < n - D + i {
                subset[i] += 1;
                for j in i + 1..D {
                    subset[j] = subset[j - 1] + 1;
                }
                break;
            }
        }
    }
}
