//! Every method exact on the caller's own wrenches (issue 25), with torque scales from 1e−8 to
//! 1e8 and positions scaled by 1e−6 to 1e6:
//! - Q1 and Q∞ by the partial and the full method on grasps that are not force closure, against
//!   Wolfe's minimum-norm-point algorithm in rationals (`support/min_norm.rs`, written for the
//!   tests and knowing nothing of hulls): the value within 1e−12 relative, or 1e−14 of the
//!   scale, of −(the exact distance from the origin to the hull), and never force closure;
//! - Q_OWS by the partial, the ray-assignment and the full (brute-force) method, force closure
//!   or not, against an exact integer simplex per disturbance (`support/exact_lp.rs`): the
//!   verdict exact, the value within 1e−12 relative.
//!
//! The full method used to fail here (an outside distance from projections that dropped faces
//! with small pivots: −0.264 where the exact value is −0.140 on a cylinder grasp with torque
//! scale 1e−8).

use crate::support::grasps::minkowski_points;
use crate::support::min_norm::exact_min_norm_distance;
use pqhull::geometry::Rng;
use pqhull::grasp::{Contact, Evaluator, FrictionModel, Grasp, Method, Metric};
use pqhull::mesh::{Mesh, SurfaceSampler};

fn norm(w: &[f64; 6]) -> f64 {
    w.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// `grasp` with every position multiplied by `factor` and the torque scale `rho`.
fn reframed(grasp: &Grasp, factor: f64, rho: f64) -> Grasp {
    let contacts = grasp
        .contacts()
        .iter()
        .map(|c| {
            let p = c.position().map(|x| x * factor);
            Contact::try_new(p, c.normal(), Some(c.tangent())).expect("a valid contact")
        })
        .collect();
    Grasp::builder(contacts, grasp.friction())
        .torque_scale(rho)
        .build()
        .expect("a valid grasp")
}

/// Seeded grasps on a box and on a faceted sphere, 3 or 4 contacts, k and μ varied.
fn base_grasps(count: usize) -> Vec<Grasp> {
    let sphere = Mesh::uv_sphere(0.3, 6, 8).expect("a sphere");
    let sampler = SurfaceSampler::new(&sphere);
    let mut rng = Rng::new(25);
    (0..count)
        .map(|i| {
            let k = [3, 4, 6, 8][i % 4];
            let mu = rng.uniform_in(0.2, 1.0);
            let friction = FrictionModel::try_new(mu, k).expect("valid friction");
            let m = 3 + i % 2;
            if i % 2 == 0 {
                Grasp::random_on_box(&mut rng, [0.5, 0.2, 0.1], m, friction)
            } else {
                Grasp::random_on_surface(&mut rng, &sampler, m, friction).expect("a grasp")
            }
        })
        .collect()
}

/// What a full method must report beside its value.
#[derive(Clone, Copy, PartialEq)]
enum Work {
    /// The facets of the full hull it built.
    Hull,
    /// Anything (a set the slab test settles has no hull).
    Any,
}

/// Checks `metric` by `method` on `grasp` against `distance`, the exact distance from the origin
/// to the hull of the metric's wrench set (`scale`: the metric's); the failure, if any.
fn judge(
    grasp: &Grasp,
    (metric, method, work): (Metric, Method, Work),
    distance: f64,
    scale: f64,
    case: &str,
) -> Option<String> {
    let q = match Evaluator::new(metric, method, None).and_then(|mut e| e.evaluate(grasp)) {
        Ok(q) => q,
        Err(e) => return Some(format!("{case} {metric:?} {method:?}: error {e}")),
    };
    let want = -distance;
    let allowed = (1e-12 * distance).max(1e-14 * scale);
    // The full method builds the full hull whatever step then gives the value, and reports its
    // work (it used to report a GJK answer's counters: no facets).
    if method == Method::Full && work == Work::Hull && q.stats.facets_created == 0 {
        return Some(format!("{case} {metric:?} full: no facets reported"));
    }
    let value = q.value.expect("Q1 and Q∞ have a value");
    if (value - want).abs() > allowed || q.force_closure {
        return Some(format!(
            "{case} {metric:?} {method:?}: {value} (force closure {}), exact {want} (off {:.2e} \
             of the scale)",
            q.force_closure,
            (value - want).abs() / scale
        ));
    }
    None
}

#[test]
fn q1_of_every_method_is_exact_outside_at_every_scale() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for (g, base) in base_grasps(24).iter().enumerate() {
        for factor in [1e-6, 1.0, 1e6] {
            for rho in [1e-8, 1e-4, 1.0, 1e4, 1e8] {
                let grasp = reframed(base, factor, rho * factor);
                let w = grasp.wrenches();
                let points: Vec<Vec<f64>> = w.iter().map(|p| p.to_vec()).collect();
                let distance = exact_min_norm_distance(&points, &[0.0; 6]);
                if distance == 0.0 {
                    continue; // the origin in the hull: not this test's contract
                }
                let scale = w.iter().map(norm).fold(0.0, f64::max);
                let case = format!("grasp {g}, positions × {factor:e}, torque scale {rho:e}");
                for method in [Method::Partial, Method::Full] {
                    checked += 1;
                    // Three or four contacts: not flat, so the full method builds a hull.
                    let what = (Metric::Q1, method, Work::Hull);
                    failures.extend(judge(&grasp, what, distance, scale, &case));
                }
            }
        }
    }
    assert!(checked >= 200, "only {checked} evaluations outside");
    assert!(
        failures.is_empty(),
        "{} of {checked}:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn q_inf_of_every_method_is_exact_outside_at_every_scale() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for (g, base) in base_grasps(12).iter().enumerate() {
        if base.minkowski_points(false).is_none_or(|n| n > 512) {
            continue;
        }
        for (factor, rho) in [
            (1.0, 1e-8),
            (1.0, 1.0),
            (1.0, 1e8),
            (1e-6, 1e-6),
            (1e6, 1e6),
        ] {
            let grasp = reframed(base, factor, rho);
            let sum = minkowski_points(&grasp, false);
            let points: Vec<Vec<f64>> = sum.iter().map(|p| p.to_vec()).collect();
            let distance = exact_min_norm_distance(&points, &[0.0; 6]);
            if distance == 0.0 {
                continue;
            }
            // Q∞'s scale: the sum over contacts of each one's largest wrench norm.
            let k = grasp.friction().cone_edges();
            let scale: f64 = grasp
                .wrenches()
                .chunks(k)
                .map(|c| c.iter().map(norm).fold(0.0, f64::max))
                .sum();
            let case = format!("grasp {g}, positions × {factor:e}, torque scale {rho:e}");
            let metric = Metric::QInf {
                with_zero_wrench: false,
            };
            for method in [Method::Partial, Method::Full] {
                checked += 1;
                // Some sums are flat (the slab test settles them without a hull).
                let what = (metric, method, Work::Any);
                failures.extend(judge(&grasp, what, distance, scale, &case));
            }
        }
    }
    assert!(checked >= 20, "only {checked} evaluations outside");
    assert!(
        failures.is_empty(),
        "{} of {checked}:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// A contact at (0.2, 1e−310, 0) facing one on the x axis: every wrench is finite, and the
/// torque about x (`y·f_z`) is subnormal for every one of them. It was refused as "a wrench is
/// not finite" (the snapping grid of that column, 2^−1053, computed by `powi`, was 0). Both
/// methods now evaluate it, exactly: two opposed contacts are never force closure.
#[test]
fn subnormal_torques_are_evaluated_exactly() {
    let friction = FrictionModel::try_new(0.5, 6).expect("valid friction");
    let contacts = vec![
        Contact::try_new([0.2, 1e-310, 0.0], [-1.0, 0.0, 0.0], None).expect("a contact"),
        Contact::try_new([-0.2, 0.0, 0.0], [1.0, 0.0, 0.0], None).expect("a contact"),
    ];
    let grasp = Grasp::builder(contacts, friction).build().expect("a grasp");
    let w = grasp.wrenches();
    assert!(
        w.iter().any(|p| p[3] != 0.0) && w.iter().all(|p| p[3].abs() < 1e-300),
        "the torque column about x is subnormal: {w:?}"
    );
    let points: Vec<Vec<f64>> = w.iter().map(|p| p.to_vec()).collect();
    let distance = exact_min_norm_distance(&points, &[0.0; 6]);
    let scale = w.iter().map(norm).fold(0.0, f64::max);
    let sum: Vec<Vec<f64>> = minkowski_points(&grasp, false)
        .iter()
        .map(|p| p.to_vec())
        .collect();
    let sum_distance = exact_min_norm_distance(&sum, &[0.0; 6]);
    let sum_scale = 2.0 * scale;
    // Two opposed contacts: a flat set, which the slab test settles without a hull.
    let q_inf = Metric::QInf {
        with_zero_wrench: false,
    };
    let mut failures = Vec::new();
    for method in [Method::Partial, Method::Full] {
        let (q1, qinf) = ((Metric::Q1, method, Work::Any), (q_inf, method, Work::Any));
        failures.extend(judge(&grasp, q1, distance, scale, "subnormal"));
        failures.extend(judge(&grasp, qinf, sum_distance, sum_scale, "subnormal"));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Q_OWS by every exact method (the partial hull, the published ray assignment, the full hull's
/// brute force) against an exact reference on the caller's wrenches: for each disturbance `d`
/// the largest `r` with `−r·d` in their hull, by an exact integer simplex
/// (`support/exact_lp.rs`), the least of them; force closure exactly when every one is positive.
/// Torque scales 1e−8 to 1e8, positions × 1e−6 to 1e6; the value within 1e−12 relative.
#[test]
fn q_ows_of_every_method_is_exact_at_every_scale() {
    use crate::support::exact_lp::{IntegerPoints, exact_ray_exit};
    use crate::support::grasps::random_disturbances;
    use num_traits::ToPrimitive;
    use pqhull::grasp::ows::ObjectWrenchSpace;

    let mut rng = Rng::new(2026);
    let mut failures = Vec::new();
    let (mut checked, mut closures) = (0, 0);
    for (g, base) in base_grasps(12).iter().enumerate() {
        for (factor, rho) in [
            (1.0, 1e-8),
            (1.0, 1.0),
            (1.0, 1e8),
            (1e-6, 1e-6),
            (1e6, 1e6),
        ] {
            let grasp = reframed(base, factor, rho);
            let w = grasp.wrenches();
            let disturbances = random_disturbances(&mut rng, 6);
            let space = ObjectWrenchSpace::from_disturbances(disturbances.clone())
                .expect("valid disturbances");
            let integers = IntegerPoints::new(&[&w, &disturbances]);
            let exits: Vec<_> = integers.sets[1]
                .iter()
                .map(|d| exact_ray_exit(&integers.sets[0], d))
                .collect();
            // Strictly inside: every ray leaves at a positive distance.
            let exact = exits
                .iter()
                .map(|r| r.as_ref().filter(|r| num_traits::Signed::is_positive(*r)))
                .collect::<Option<Vec<_>>>()
                .map(|r| {
                    r.into_iter()
                        .min()
                        .expect("disturbances")
                        .to_f64()
                        .expect("finite")
                });
            closures += usize::from(exact.is_some());
            let case = format!("grasp {g}, positions × {factor:e}, torque scale {rho:e}");
            for method in [Method::Partial, Method::PartialRays, Method::Full] {
                checked += 1;
                let q = match Evaluator::new(Metric::Ows, method, Some(&space))
                    .and_then(|mut e| e.evaluate(&grasp))
                {
                    Ok(q) => q,
                    Err(e) => {
                        failures.push(format!("{case} {method:?}: error {e}"));
                        continue;
                    }
                };
                let right = match (q.value, exact) {
                    (None, None) => !q.force_closure,
                    (Some(got), Some(want)) => {
                        q.force_closure && (got - want).abs() <= 1e-12 * want
                    }
                    _ => false,
                };
                if !right {
                    failures.push(format!(
                        "{case} {method:?}: {:?} (force closure {}), exact {exact:?}",
                        q.value, q.force_closure
                    ));
                }
            }
        }
    }
    assert!(
        checked >= 150 && closures >= 10,
        "{checked} evaluations, {closures} closures"
    );
    assert!(
        failures.is_empty(),
        "{} of {checked}:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
