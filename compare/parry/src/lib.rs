//! The pairs of 3-D convex bodies on which `pqhull::strategy::penetration_depth` is compared
//! with parry3d's GJK/EPA (issue 27), and the reference they are checked against.
//!
//! parry is a dev-dependency only: the example `table` (`cargo run --release -p
//! pqhull-parry-compare --example table`) prints the markdown table of docs/benchmarks.md, the
//! bench `penetration` (`cargo bench -p pqhull-parry-compare`) times a few of the same pairs
//! with criterion. This library only builds the pairs (fixed seeds) and the geometry of the
//! reference, so that both use the same input.
//!
//! Every pair is placed from a *touching* position along a direction `u`: `B` is translated so
//! that its lowest vertex along `u` coincides with `A`'s highest, so the plane through that
//! shared point orthogonal to `u` separates them and the exact depth is 0. From there `B` is
//! moved by `−δ·u` (overlapping, `h_{A⊖B}(u) = δ`, so the depth is at most `δ`) or by `+δ·u`
//! (separated: exactly `δ` apart, the shared points being `δ` apart and the slab between the
//! two planes `δ` wide).

use pqhull::geometry::Rng;

/// A point in 3-D.
pub type Point = [f64; 3];

/// Two bodies (their points; the hulls are what is compared) and what is known of their depth.
#[derive(Clone, Debug)]
pub struct Pair {
    /// The family, e.g. "sphere 100 + 100".
    pub family: String,
    /// How they lie, e.g. "deep", "touching", "coplanar faces, shift (0.25, 0, 0)".
    pub config: String,
    /// The first body.
    pub a: Vec<Point>,
    /// The second body.
    pub b: Vec<Point>,
    /// The exact depth when it follows from the construction (axis-aligned boxes: from the
    /// coordinates' extents; separated pairs: the construction's gap), computed in `f64`.
    pub analytic: Option<f64>,
}

/// `n` points uniform on the unit sphere, from `seed`.
pub fn sphere(n: usize, seed: u64) -> Vec<Point> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let v = rng.unit_vector(3);
            [v[0], v[1], v[2]]
        })
        .collect()
}

/// The unit cube `[0, 1]³`: its 8 corners and, with `grid ≥ 2`, a `grid × grid` lattice on
/// every face (`grid³ − (grid − 2)³` points, most of them coplanar non-vertices).
pub fn cube(grid: usize) -> Vec<Point> {
    let g = grid.max(2);
    let t = |i: usize| i as f64 / (g - 1) as f64;
    let mut points = Vec::new();
    for i in 0..g {
        for j in 0..g {
            for k in 0..g {
                let on_face = [i, j, k].iter().any(|&c| c == 0 || c == g - 1);
                if on_face {
                    points.push([t(i), t(j), t(k)]);
                }
            }
        }
    }
    points
}

fn dot(p: Point, q: Point) -> f64 {
    p[0] * q[0] + p[1] * q[1] + p[2] * q[2]
}

/// `b` translated to touch `a` from the side `u` points to (see the crate's documentation),
/// then moved by `offset · u`: its vertex lowest along `u` lands exactly on `a`'s highest
/// when `offset` is 0 (each point is moved as `(p − low) + high`).
pub fn placed(a: &[Point], b: &[Point], u: Point, offset: f64) -> Vec<Point> {
    let high = *a
        .iter()
        .max_by(|p, q| dot(**p, u).total_cmp(&dot(**q, u)))
        .expect("a is not empty");
    let low = *b
        .iter()
        .min_by(|p, q| dot(**p, u).total_cmp(&dot(**q, u)))
        .expect("b is not empty");
    let target: Point = std::array::from_fn(|c| high[c] + offset * u[c]);
    b.iter()
        .map(|p| std::array::from_fn(|c| (p[c] - low[c]) + target[c]))
        .collect()
}

/// `points` translated by `shift`.
pub fn shifted(points: &[Point], shift: Point) -> Vec<Point> {
    points
        .iter()
        .map(|p| std::array::from_fn(|c| p[c] + shift[c]))
        .collect()
}

/// The signed penetration depth of two axis-aligned boxes given by points, from their extents
/// alone: the least overlap over the axes when every axis overlaps, else minus the norm of the
/// gaps.
pub fn box_depth(a: &[Point], b: &[Point]) -> f64 {
    let extent = |points: &[Point], k: usize| {
        points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[k]), hi.max(p[k]))
            })
    };
    let mut overlap = f64::INFINITY;
    let mut gaps = 0.0;
    for k in 0..3 {
        let (a_lo, a_hi) = extent(a, k);
        let (b_lo, b_hi) = extent(b, k);
        let o = (a_hi - b_lo).min(b_hi - a_lo);
        overlap = overlap.min(o);
        if o < 0.0 {
            gaps += o * o;
        }
    }
    if gaps > 0.0 {
        -f64::sqrt(gaps)
    } else {
        overlap
    }
}

/// The direction every sphere pair is placed along: a fixed pseudo-random unit vector.
pub fn sphere_direction() -> Point {
    let v = Rng::new(0x27_0c0ffee).unit_vector(3);
    [v[0], v[1], v[2]]
}

/// The pairs of the table: random points on spheres of 20, 100 and 1000 vertices each (size 2,
/// the diameter) deep, slightly overlapping (`2e−6`), touching, separated (0.2) and identical;
/// the unit cube (size 1, corners only, and with a 10 × 10 lattice on each face) deep, slightly
/// overlapping (`1e−6`), touching, separated (0.1), shifted along axes only (coplanar faces)
/// and identical; a 2 × 1 × 0.5 box against the unit cube.
pub fn pairs() -> Vec<Pair> {
    let mut out = Vec::new();
    let mut push = |family: &str, config: &str, a: &[Point], b: Vec<Point>, analytic| {
        out.push(Pair {
            family: family.to_string(),
            config: config.to_string(),
            a: a.to_vec(),
            b,
            analytic,
        });
    };
    let u = sphere_direction();
    for (n, seed) in [(20, 20), (100, 100), (1000, 1000)] {
        let family = format!("sphere {n} + {n}");
        let a = sphere(n, seed);
        let b0 = sphere(n, seed + 1);
        for (config, offset, analytic) in [
            ("deep", -0.5, None),
            ("slight (2e-6)", -2e-6, None),
            ("touching", 0.0, Some(0.0)),
            ("separated (0.2)", 0.2, Some(-0.2)),
        ] {
            push(&family, config, &a, placed(&a, &b0, u, offset), analytic);
        }
        push(&family, "identical", &a, a.clone(), None);
    }
    // Axis-aligned boxes; tangential shifts dyadic.
    let generic = [
        ("deep", [0.75, 0.125, 0.25]),
        ("slight (1e-6)", [1.0 - 1e-6, 0.125, 0.25]),
        ("touching", [1.0, 0.125, 0.25]),
        ("separated (0.1)", [1.1, 0.125, 0.25]),
        ("coplanar faces, shift (0.5, 0, 0)", [0.5, 0.0, 0.0]),
    ];
    let corners = cube(2);
    let mut cube_configs = generic.to_vec();
    cube_configs.extend([
        ("coplanar faces, shift (0.25, 0, 0)", [0.25, 0.0, 0.0]),
        ("identical", [0.0, 0.0, 0.0]),
        ("nearly identical, shift (1e-9, 0, 0)", [1e-9, 0.0, 0.0]),
    ]);
    let grid = cube(10);
    let mut grid_configs = generic.to_vec();
    grid_configs.push(("identical", [0.0, 0.0, 0.0]));
    let slab: Vec<Point> = corners
        .iter()
        .map(|p| [2.0 * p[0], p[1], 0.5 * p[2]])
        .collect();
    let slab_configs = [
        ("deep", [0.5, 0.125, 0.25]),
        ("coplanar faces, shift (-0.5, 0, 0)", [-0.5, 0.0, 0.0]),
        ("shift (-0.625, -0.875, -0.875)", [-0.625, -0.875, -0.875]),
    ];
    for (family, a, b, configs) in [
        ("cube 8 + 8", &corners, &corners, &cube_configs[..]),
        (
            "cube, 10x10 face grids, 488 + 488",
            &grid,
            &grid,
            &grid_configs[..],
        ),
        (
            "box 2x1x0.5 + cube, 8 + 8",
            &slab,
            &corners,
            &slab_configs[..],
        ),
    ] {
        for &(config, shift) in configs {
            let b = shifted(b, shift);
            let analytic = Some(box_depth(a, &b));
            push(family, config, a, b, analytic);
        }
    }
    out
}

/// Every difference `a − b`, computed in `f64`.
pub fn differences(a: &[Point], b: &[Point]) -> Vec<Point> {
    a.iter()
        .flat_map(|p| b.iter().map(move |q| std::array::from_fn(|c| p[c] - q[c])))
        .collect()
}

/// The distance from the origin to the triangle `t` (Ericson, *Real-Time Collision Detection*,
/// 5.1.5, in `f64`).
pub fn origin_triangle_distance(t: [Point; 3]) -> f64 {
    let sub = |p: Point, q: Point| -> Point { std::array::from_fn(|c| p[c] - q[c]) };
    let [a, b, c] = t;
    let p = [0.0; 3];
    let ab = sub(b, a);
    let ac = sub(c, a);
    let ap = sub(p, a);
    let d1 = dot(ab, ap);
    let d2 = dot(ac, ap);
    let closest = if d1 <= 0.0 && d2 <= 0.0 {
        a
    } else {
        let bp = sub(p, b);
        let d3 = dot(ab, bp);
        let d4 = dot(ac, bp);
        let cp = sub(p, c);
        let d5 = dot(ab, cp);
        let d6 = dot(ac, cp);
        let vc = d1 * d4 - d3 * d2;
        let vb = d5 * d2 - d1 * d6;
        let va = d3 * d6 - d5 * d4;
        let along =
            |o: Point, e: Point, s: f64| -> Point { std::array::from_fn(|k| o[k] + s * e[k]) };
        if d3 >= 0.0 && d4 <= d3 {
            b
        } else if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
            along(a, ab, d1 / (d1 - d3))
        } else if d6 >= 0.0 && d5 <= d6 {
            c
        } else if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
            along(a, ac, d2 / (d2 - d6))
        } else if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
            along(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)))
        } else {
            let denom = 1.0 / (va + vb + vc);
            let v = vb * denom;
            let w = vc * denom;
            std::array::from_fn(|k| a[k] + ab[k] * v + ac[k] * w)
        }
    };
    dot(closest, closest).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placement_touches_and_separates() {
        let a = sphere(20, 1);
        let b = sphere(20, 2);
        let u = sphere_direction();
        let t = placed(&a, &b, u, 0.0);
        let high = a.iter().map(|p| dot(*p, u)).fold(f64::MIN, f64::max);
        let low = t.iter().map(|p| dot(*p, u)).fold(f64::MAX, f64::min);
        assert!((high - low).abs() < 1e-15);
        assert!(a.iter().any(|p| t.contains(p)));
    }

    #[test]
    fn boxes_and_triangles() {
        let a = cube(2);
        assert_eq!(cube(10).len(), 488);
        assert_eq!(box_depth(&a, &shifted(&a, [0.75, 0.125, 0.25])), 0.25);
        assert_eq!(
            box_depth(&a, &shifted(&a, [2.0, 2.0, 0.0])),
            -f64::sqrt(2.0)
        );
        let t = [[1.0, -1.0, 2.0], [1.0, 1.0, 2.0], [-1.0, 0.0, 2.0]];
        assert_eq!(origin_triangle_distance(t), 2.0);
        let far = [[1.0, 1.0, 0.0], [2.0, 1.0, 0.0], [1.0, 2.0, 0.0]];
        assert_eq!(origin_triangle_distance(far), f64::sqrt(2.0));
    }
}
