//! The object wrench space of a mesh is the seed paper's Eq. 6: per triangle, its own friction
//! cone at each of its three corners. Checked on a cube against sets and values built here
//! straight from the formulas, with Qhull (feature `qhull`) as the independent hull.
#![cfg(feature = "qhull")]

use pqhull::geometry::Rng;
use pqhull::grasp::ows::{ObjectWrenchSpace, ows_of_wrenches};
use pqhull::grasp::quality::q1_of_wrenches;
use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric};
use pqhull::mesh::Mesh;
use pqhull::qhull_baseline::{QhullError, qhull_full_hull};
use std::f64::consts::PI;

type V3 = [f64; 3];

/// Half extent of the test cube [−H, H]³: its centre of mass is the origin, ρ = √3·H.
const H: f64 = 0.5;

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(s: f64, a: V3) -> V3 {
    [s * a[0], s * a[1], s * a[2]]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn unit(a: V3) -> V3 {
    scale(1.0 / dot(a, a).sqrt(), a)
}

/// `[f ; (p − c) × f / ρ]`.
fn wrench(p: V3, f: V3, c: V3, rho: f64) -> [f64; 6] {
    let tau = cross(sub(p, c), f);
    [f[0], f[1], f[2], tau[0] / rho, tau[1] / rho, tau[2] / rho]
}

/// f_j = n + μ(cos θ_j t + sin θ_j (n × t)), θ_j = 2πj/k.
fn rim(n: V3, t: V3, mu: f64, k: usize) -> Vec<V3> {
    (0..k)
        .map(|j| {
            let theta = 2.0 * PI * j as f64 / k as f64;
            add(
                n,
                scale(
                    mu,
                    add(scale(theta.cos(), t), scale(theta.sin(), cross(n, t))),
                ),
            )
        })
        .collect()
}

fn max_abs_difference(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// Eq. 6 on the cube, from the formula: for every triangle of the mesh's triangulation (the
/// input), its inward normal and first-edge tangent computed here from the corner coordinates,
/// then the push and the k unit rim edges at each corner. Exactly equal wrenches kept once.
fn expected_disturbances(cube: &Mesh, mu: f64, k: usize) -> Vec<[f64; 6]> {
    let (c, rho) = ([0.0; 3], 3f64.sqrt() * H);
    let mut out: Vec<[f64; 6]> = Vec::new();
    for t in cube.triangles() {
        let [v0, v1, v2] = t.map(|i| cube.vertices()[i as usize]);
        // Counter-clockwise seen from outside: (v1 − v0) × (v2 − v0) points out.
        let n = unit(scale(-1.0, cross(sub(v1, v0), sub(v2, v0))));
        // On a face of the cube the inward normal is minus the face's axis.
        let centre = scale(1.0 / 3.0, add(add(v0, v1), v2));
        let axis = (0..3).max_by(|&a, &b| centre[a].abs().total_cmp(&centre[b].abs()));
        let axis = axis.unwrap();
        assert_eq!(n[axis], -centre[axis].signum(), "{t:?}: {n:?}");
        let e = sub(v1, v0);
        let tangent = unit(sub(e, scale(dot(e, n), n)));
        let mut forces = vec![n];
        forces.extend(rim(n, tangent, mu, k).into_iter().map(unit));
        for v in [v0, v1, v2] {
            for &f in &forces {
                let w = wrench(v, f, c, rho);
                if !out.contains(&w) {
                    out.push(w);
                }
            }
        }
    }
    out
}

/// Every wrench of `a` within `tolerance` (largest coordinate difference) of one of `b`.
fn assert_covered(a: &[[f64; 6]], b: &[[f64; 6]], tolerance: f64, what: &str) {
    for (i, w) in a.iter().enumerate() {
        let nearest = b
            .iter()
            .map(|x| max_abs_difference(w, x))
            .fold(f64::INFINITY, f64::min);
        assert!(
            nearest <= tolerance,
            "{what}: wrench {i} {w:?} is {nearest} away"
        );
    }
}

#[test]
fn cube_disturbances_are_the_per_triangle_cones_at_their_corners() {
    let cube = Mesh::cuboid([H; 3]).unwrap();
    assert_eq!((cube.vertices().len(), cube.triangles().len()), (8, 12));
    for mu in [0.3, 0.5] {
        for k in [3, 4, 6, 8] {
            let friction = FrictionModel::try_new(mu, k).unwrap();
            let space = ObjectWrenchSpace::from_mesh(&cube, friction).unwrap();
            let (c, rho) = space.torque_frame().unwrap();
            assert!(c.iter().all(|x| x.abs() < 1e-16), "{c:?}");
            assert!((rho - 3f64.sqrt() * H).abs() < 1e-15, "{rho}");
            assert_eq!(
                (space.triangles_skipped(), space.vertices_without_normal()),
                (0, 0)
            );
            let expected = expected_disturbances(&cube, mu, k);
            let what = format!("μ = {mu}, k = {k}");
            assert_covered(space.disturbances(), &expected, 1e-15, &what);
            assert_covered(&expected, space.disturbances(), 1e-15, &what);
            // The pushes: one per face and corner (a corner's three faces push differently).
            let pushes = expected
                .iter()
                .filter(|w| w[..3].iter().filter(|x| **x != 0.0).count() == 1)
                .count();
            assert_eq!(pushes, 6 * 4, "{what}");
            if k == 8 {
                // A face's diagonal triangle has its tangent 45° = one step of 2π/8 from its
                // side triangle's, so their rims coincide up to rounding, and which of them are
                // exactly equal depends on the last bit: compared as sets only.
                continue;
            }
            // Otherwise no two rims coincide: per face 4 pushes and 2 triangles × 3 corners × k
            // rim edges, and nothing else merges.
            assert_eq!(expected.len(), 6 * (4 + 2 * 3 * k), "{what}");
            assert_eq!(space.len(), expected.len(), "{what}");
        }
    }
}

/// Q_OWS straight from Eq. 6 and 8–9: the hull of the grasp's wrenches by Qhull, and for each
/// disturbance d the smallest offset / (n · (−d)) over the facets its ray −d leaves through.
/// `None` when the origin is not strictly inside (Qhull's planes: every offset negative, with a
/// margin, so that a borderline grasp is not compared).
fn brute_force_from_eq6(wrenches: &[[f64; 6]], disturbances: &[[f64; 6]]) -> Option<f64> {
    let hull = match qhull_full_hull(wrenches) {
        Ok(hull) => hull,
        // Flat wrench sets (QH6154: two antipodal contacts, say) hold no interior.
        Err(QhullError::Qhull { message, .. }) if message.contains("QH6154") => return None,
        Err(e) => panic!("qhull: {e}"),
    };
    // Qhull's plane: normal · x + offset = 0, inside ≤ 0; the distance from the origin is −offset.
    if hull.facets.iter().any(|f| f.offset > -1e-12) {
        return None;
    }
    let mut best = f64::INFINITY;
    for d in disturbances {
        for facet in &hull.facets {
            let along: f64 = facet.normal.iter().zip(d).map(|(n, x)| -n * x).sum();
            if along > 0.0 {
                best = best.min(-facet.offset / along);
            }
        }
    }
    Some(best)
}

/// Q_OWS of random grasps on the cube: the evaluator's partial and brute-force methods equal the
/// brute force written above from the formulas.
#[test]
fn cube_q_ows_equals_a_brute_force_from_the_formulas() {
    let cube = Mesh::cuboid([H; 3]).unwrap();
    let (mu, k) = (0.5, 6);
    let friction = FrictionModel::try_new(mu, k).unwrap();
    let space = ObjectWrenchSpace::from_mesh(&cube, friction).unwrap();
    let (c, rho) = space.torque_frame().unwrap();
    let mut partial = Evaluator::new(Metric::Ows, Method::Partial, Some(&space)).unwrap();
    let mut brute = Evaluator::new(Metric::Ows, Method::Full, Some(&space)).unwrap();
    let mut rng = Rng::new(6);
    let (mut compared, mut not_closure) = (0, 0);
    let mut worst = 0.0f64;
    for g in 0..200 {
        if compared >= 25 {
            break;
        }
        let grasp = space
            .frame(&Grasp::random_on_box(&mut rng, [H; 3], 4, friction))
            .unwrap();
        // The grasp's wrenches from the raw formula.
        let mut wrenches = Vec::new();
        for contact in grasp.contacts() {
            let (p, n, t) = (contact.position(), contact.normal(), contact.tangent());
            wrenches.extend(rim(n, t, mu, k).into_iter().map(|f| wrench(p, f, c, rho)));
        }
        assert_covered(&wrenches, &grasp.wrenches(), 1e-15, &format!("grasp {g}"));
        let a = partial.evaluate(&grasp).unwrap();
        let b = brute.evaluate(&grasp).unwrap();
        assert_eq!(a.force_closure, b.force_closure, "grasp {g}");
        let Some(expected) = brute_force_from_eq6(&wrenches, space.disturbances()) else {
            if !a.force_closure {
                not_closure += 1;
            }
            continue;
        };
        assert!(
            a.force_closure,
            "grasp {g}: Qhull holds the origin strictly inside"
        );
        // The evaluator searches on snapped wrenches and certifies on the caller's: the same
        // 1e-12 as on the raw wrenches directly.
        for (method, q) in [("partial", a), ("brute", b)] {
            let value = q.value.unwrap();
            worst = worst.max((value - expected).abs() / expected);
            assert!(
                (value - expected).abs() <= 1e-12 * expected,
                "grasp {g}, {method}: {value} vs Eq. 6 {expected}"
            );
        }
        // On exactly these wrenches the metric is exact, whatever the evaluator's snapping.
        let raw = ows_of_wrenches(&wrenches, &space, Method::Partial).unwrap();
        let value = raw.value.unwrap();
        assert!(
            (value - expected).abs() <= 1e-12 * expected,
            "grasp {g}, raw wrenches: {value} vs Eq. 6 {expected}"
        );
        compared += 1;
    }
    eprintln!(
        "{compared} grasps compared; largest relative difference of the evaluator: {worst:e}"
    );
    assert!(
        compared >= 20,
        "only {compared} force-closure grasps compared"
    );
    assert!(not_closure > 0, "no grasp that is not force closure met");
}

/// Two antipodal hard fingers: their wrenches span five dimensions (no torque about the axis
/// through them), so the grasp is not force closure. The ellipsoid method used to map them to a
/// sliver holding the origin within rounding and say "force closure, 2.2e−308".
#[test]
fn ellipsoid_method_keeps_the_grasps_own_verdict() {
    let cube = Mesh::cuboid([H; 3]).unwrap();
    let friction = FrictionModel::try_new(0.5, 8).unwrap();
    let space = ObjectWrenchSpace::from_mesh(&cube, friction).unwrap();
    let pinch = Grasp::builder(
        vec![
            Contact::try_new([-H, 0.0, 0.0], [1.0, 0.0, 0.0], None).unwrap(),
            Contact::try_new([H, 0.0, 0.0], [-1.0, 0.0, 0.0], None).unwrap(),
        ],
        friction,
    )
    .build()
    .unwrap();
    let pinch = space.frame(&pinch).unwrap();
    let own = q1_of_wrenches(&pinch.wrenches(), Method::Partial).unwrap();
    assert!(!own.force_closure);
    for method in [Method::Partial, Method::Full, Method::Ellipsoid] {
        let q = Evaluator::new(Metric::Ows, method, Some(&space))
            .unwrap()
            .evaluate(&pinch)
            .unwrap();
        assert!(!q.force_closure, "{method:?}");
        assert_eq!(q.value, None, "{method:?}");
        let q = ows_of_wrenches(&pinch.wrenches(), &space, method).unwrap();
        assert!(!q.force_closure && q.value.is_none(), "{method:?} (raw)");
    }
    // A force-closure grasp still gets its approximation: positive, never above the exact value.
    let mut rng = Rng::new(3);
    let mut seen = 0;
    for _ in 0..100 {
        let grasp = space
            .frame(&Grasp::random_on_box(&mut rng, [H; 3], 4, friction))
            .unwrap();
        let exact = Evaluator::new(Metric::Ows, Method::Partial, Some(&space))
            .unwrap()
            .evaluate(&grasp)
            .unwrap();
        let approx = Evaluator::new(Metric::Ows, Method::Ellipsoid, Some(&space))
            .unwrap()
            .evaluate(&grasp)
            .unwrap();
        assert_eq!(approx.force_closure, exact.force_closure);
        if let (Some(a), Some(e)) = (approx.value, exact.value) {
            assert!(a > f64::MIN_POSITIVE && a <= e * (1.0 + 1e-9), "{a} vs {e}");
            seen += 1;
        }
    }
    assert!(seen >= 10, "{seen} force-closure grasps");
}
