//! Soft-finger contacts: torsion γ adds ±γ n to every edge's torque. Checked against the explicit
//! soft wrench set (Qhull with the feature, our full hull always), the hard model as γ → 0 (the
//! value moves by at most γ/ρ), monotonicity, two soft contacts in force closure, Q∞ against the
//! Minkowski sum written out here, and the JSON field.

use crate::support::{BAR_FRICTION, bar_grasps};
use pqhull::grasp::json::{parse_grasp, write_grasp};
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::quality::{q1, q1_of_wrenches};
use pqhull::grasp::{
    Contact, Evaluation, Evaluator, FrictionModel, Grasp, GraspError, Method, Metric,
};

fn soft(grasp: &Grasp, torsion: f64) -> Grasp {
    let contacts = grasp
        .contacts()
        .iter()
        .map(|c| c.with_torsion(torsion).unwrap())
        .collect();
    Grasp::builder(contacts, grasp.friction())
        .torque_reference(grasp.torque_reference())
        .torque_scale(grasp.torque_scale())
        .build()
        .unwrap()
}

fn grasps() -> Vec<Grasp> {
    bar_grasps(21, 80, 4, FrictionModel::try_new(BAR_FRICTION, 6).unwrap())
}

#[test]
fn soft_wrenches_are_the_documented_formula() {
    let g = soft(&grasps()[0], 0.05);
    let w = g.wrenches();
    let k = 6;
    assert_eq!(w.len(), 4 * 2 * k);
    let hard = grasps()[0].wrenches();
    let rho = g.torque_scale();
    for (i, c) in g.contacts().iter().enumerate() {
        for j in 0..k {
            let (plus, minus, h) = (w[i * 2 * k + j], w[i * 2 * k + k + j], hard[i * k + j]);
            for a in 0..3 {
                assert_eq!(plus[a], h[a]);
                assert_eq!(minus[a], h[a]);
                let twist = 0.05 * c.normal()[a] / rho;
                assert!((plus[3 + a] - h[3 + a] - twist).abs() < 1e-15);
                assert!((minus[3 + a] - h[3 + a] + twist).abs() < 1e-15);
            }
        }
    }
}

#[test]
fn soft_q1_equals_the_hull_of_the_explicit_soft_wrenches() {
    let mut closure = 0;
    for (i, hard) in grasps().iter().enumerate() {
        let g = soft(hard, 0.02);
        let ours = q1(&g).unwrap();
        let reference = q1_of_wrenches(&g.wrenches(), Method::Full).unwrap();
        assert_eq!(ours.force_closure, reference.force_closure, "grasp {i}");
        let tol = 1e-12 * reference.value.unwrap().abs() + 1e-14 * reference.scale.unwrap();
        assert!(
            (ours.value.unwrap() - reference.value.unwrap()).abs() <= 2.0 * tol,
            "grasp {i}: {} vs {}",
            ours.value.unwrap(),
            reference.value.unwrap()
        );
        closure += usize::from(ours.force_closure);
    }
    assert!(closure > 10, "only {closure} force-closure soft grasps");
}

/// The same against Qhull's hull of the explicit soft wrenches (feature `qhull`; without it a
/// stand-in in tests/without_qhull.rs is listed as skipped).
#[cfg(feature = "qhull")]
#[test]
fn soft_q1_equals_qhull_on_the_explicit_soft_wrenches() {
    let mut compared = 0;
    for (i, hard) in grasps().iter().enumerate() {
        let g = soft(hard, 0.02);
        let ours = q1(&g).unwrap();
        if ours.force_closure {
            let qhull = pqhull::qhull_baseline::qhull_origin_distance(&g.wrenches()).unwrap();
            assert!(
                (ours.value.unwrap() - qhull).abs() <= 1e-9 * qhull,
                "grasp {i}: {} vs Qhull {qhull}",
                ours.value.unwrap()
            );
            compared += 1;
        }
    }
    assert!(compared > 10, "only {compared} force-closure soft grasps");
}

#[test]
fn the_soft_value_tends_to_the_hard_one_and_never_falls_below_it() {
    for (i, hard) in grasps().iter().enumerate() {
        let h = q1(hard).unwrap();
        assert_eq!(
            q1(&soft(hard, 0.0)).unwrap().value.unwrap(),
            h.value.unwrap(),
            "grasp {i}: γ = 0 is hard"
        );
        for gamma in [1e-2, 1e-4, 1e-7] {
            let s = q1(&soft(hard, gamma)).unwrap();
            // Each hard wrench is the midpoint of its two soft ones: the soft hull contains the
            // hard one. And each soft wrench is within γ/ρ of a hard one.
            let slack = 1e-12 * h.value.unwrap().abs() + 1e-14 * h.scale.unwrap();
            assert!(
                s.value.unwrap() >= h.value.unwrap() - slack,
                "grasp {i}, γ = {gamma}: {} < {}",
                s.value.unwrap(),
                h.value.unwrap()
            );
            let bound = gamma / hard.torque_scale() * (1.0 + 1e-9) + 2.0 * slack;
            assert!(
                s.value.unwrap() - h.value.unwrap() <= bound,
                "grasp {i}, γ = {gamma}: moved {}",
                s.value.unwrap() - h.value.unwrap()
            );
        }
    }
}

#[test]
fn two_soft_fingers_can_hold_what_two_hard_ones_cannot() {
    let friction = FrictionModel::try_new(0.5, 8).unwrap();
    let pinch = |torsion: f64| {
        let contacts = vec![
            Contact::try_new([-0.5, 0.0, 0.0], [1.0, 0.0, 0.0], None)
                .unwrap()
                .with_torsion(torsion)
                .unwrap(),
            Contact::try_new([0.5, 0.0, 0.0], [-1.0, 0.0, 0.0], None)
                .unwrap()
                .with_torsion(torsion)
                .unwrap(),
        ];
        Grasp::builder(contacts, friction).build().unwrap()
    };
    let hard = q1(&pinch(0.0)).unwrap();
    assert!(
        !hard.force_closure,
        "two hard fingers cannot resist torsion about their axis"
    );
    let soft = q1(&pinch(0.05)).unwrap();
    assert!(soft.force_closure && soft.value.unwrap() > 0.0, "{soft:?}");
}

#[test]
fn soft_ows_partial_equals_brute_force() {
    let space = ObjectWrenchSpace::from_disturbances(
        (0..40)
            .map(|i| {
                let a = i as f64 * 0.7;
                [
                    a.sin(),
                    a.cos(),
                    (2.0 * a).sin(),
                    0.3 * a.cos(),
                    0.2 * (3.0 * a).sin(),
                    0.1,
                ]
            })
            .collect(),
    )
    .unwrap();
    let mut compared = 0;
    for hard in grasps().iter().take(40) {
        let g = soft(hard, 0.03);
        let p = Evaluator::new(Metric::Ows, Method::Partial, Some(&space))
            .unwrap()
            .evaluate(&g)
            .unwrap();
        let b = Evaluator::new(Metric::Ows, Method::Full, Some(&space))
            .unwrap()
            .evaluate(&g)
            .unwrap();
        assert_eq!(p.force_closure, b.force_closure);
        if let (Some(x), Some(y)) = (p.value, b.value) {
            assert!((x - y).abs() <= 1e-9 * y, "{x} vs {y}");
            compared += 1;
        }
    }
    assert!(compared > 5);
}

/// Three fingers pushing toward the centre of a ball of radius 0.1 from random directions
/// (μ = 0.8, 4-edge cones: force closure is common, and the written-out sums stay small), the
/// first `soft_contacts` of them soft (γ = 0.003, ρ = 0.1).
fn qinf_grasps(count: usize, soft_contacts: usize) -> Vec<Grasp> {
    let mut rng = pqhull::geometry::Rng::new(17);
    let friction = FrictionModel::try_new(0.8, 4).unwrap();
    (0..count)
        .map(|_| {
            let contacts = (0..3)
                .map(|i| {
                    let d: [f64; 3] = std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0));
                    let norm = d.iter().map(|x| x * x).sum::<f64>().sqrt();
                    let n = d.map(|x| -x / norm);
                    let torsion = if i < soft_contacts { 0.003 } else { 0.0 };
                    Contact::try_new(n.map(|x| -0.1 * x), n, None)
                        .unwrap()
                        .with_torsion(torsion)
                        .unwrap()
                })
                .collect();
            Grasp::builder(contacts, friction)
                .torque_scale(0.1)
                .build()
                .unwrap()
        })
        .collect()
}

/// The Minkowski sum written out here from the explicit wrenches ([`Grasp::wrenches`], checked
/// against the formula above): one wrench of each contact's set (2k for a soft contact, k for a
/// hard one; with the zero wrench when asked), every combination.
fn explicit_minkowski_sum(g: &Grasp, with_zero_wrench: bool) -> Vec<[f64; 6]> {
    let all = g.wrenches();
    let k = g.friction().cone_edges();
    let mut sets = Vec::new();
    let mut at = 0;
    for c in g.contacts() {
        let n = if c.is_soft() { 2 * k } else { k };
        let mut set = all[at..at + n].to_vec();
        if with_zero_wrench {
            set.push([0.0; 6]);
        }
        sets.push(set);
        at += n;
    }
    crate::support::grasps::sum_of_sets(&sets)
}

fn qinf(g: &Grasp, with_zero_wrench: bool, method: Method) -> Evaluation {
    Evaluator::new(Metric::QInf { with_zero_wrench }, method, None)
        .unwrap()
        .evaluate(g)
        .unwrap()
}

#[test]
fn soft_qinf_equals_the_hull_of_the_explicit_minkowski_sum() {
    let mut closure = 0;
    for soft_contacts in [1, 3] {
        for (i, g) in qinf_grasps(8, soft_contacts).iter().enumerate() {
            for zero in [false, true] {
                let sum = explicit_minkowski_sum(g, zero);
                assert_eq!(Some(sum.len()), g.minkowski_points(zero));
                let reference = q1_of_wrenches(&sum, Method::Full).unwrap();
                // The full method hulls the same sum again: once, on the smallest, is enough
                // (our exact engine is slow on these degenerate sums: docs/benchmarks.md).
                let methods = if soft_contacts == 1 && !zero {
                    &[Method::Partial, Method::Full][..]
                } else {
                    &[Method::Partial]
                };
                for &method in methods {
                    let ours = qinf(g, zero, method);
                    assert_eq!(ours.force_closure, reference.force_closure, "grasp {i}");
                    let tol = 1e-12 * reference.value.unwrap().abs() + 1e-14 * ours.scale.unwrap();
                    assert!(
                        (ours.value.unwrap() - reference.value.unwrap()).abs() <= 2.0 * tol,
                        "{soft_contacts} soft, grasp {i}, zero {zero}, {}: {} vs {}",
                        method.name(),
                        ours.value.unwrap(),
                        reference.value.unwrap()
                    );
                }
                closure += usize::from(reference.force_closure);
            }
        }
    }
    assert!(closure > 3, "only {closure} force-closure sums");
}

/// The same against Qhull's hull of the explicit sum (feature `qhull`; without it a stand-in in
/// tests/without_qhull.rs is listed as skipped).
#[cfg(feature = "qhull")]
#[test]
fn soft_qinf_equals_qhull_on_the_explicit_minkowski_sum() {
    let mut compared = 0;
    for (i, g) in qinf_grasps(30, 3).iter().enumerate() {
        for zero in [false, true] {
            let ours = qinf(g, zero, Method::Partial);
            if ours.force_closure {
                let sum = explicit_minkowski_sum(g, zero);
                let qhull = pqhull::qhull_baseline::qhull_origin_distance(&sum).unwrap();
                assert!(
                    (ours.value.unwrap() - qhull).abs() <= 1e-9 * qhull,
                    "grasp {i}, zero {zero}: {} vs Qhull {qhull}",
                    ours.value.unwrap()
                );
                compared += 1;
            }
        }
    }
    assert!(compared > 3, "only {compared} force-closure soft sums");
}

#[test]
fn soft_qinf_tends_to_the_hard_value_and_never_falls_below_it() {
    for (i, hard) in qinf_grasps(30, 0).iter().enumerate() {
        let h = qinf(hard, false, Method::Partial);
        assert_eq!(
            qinf(&soft(hard, 0.0), false, Method::Partial)
                .value
                .unwrap(),
            h.value.unwrap()
        );
        for gamma in [1e-3, 1e-6] {
            let s = qinf(&soft(hard, gamma), false, Method::Partial);
            // Each contact's hard set lies in its soft one, which lies within γ/ρ of it: the sum
            // of m = 3 contacts moves by at most 3γ/ρ.
            let slack = 1e-12 * h.value.unwrap().abs() + 1e-14 * h.scale.unwrap();
            assert!(
                s.value.unwrap() >= h.value.unwrap() - 2.0 * slack,
                "grasp {i}, γ = {gamma}"
            );
            let bound = 3.0 * gamma / hard.torque_scale() * (1.0 + 1e-9) + 2.0 * slack;
            assert!(
                s.value.unwrap() - h.value.unwrap() <= bound,
                "grasp {i}, γ = {gamma}"
            );
        }
    }
}

#[test]
fn torsion_in_json_reads_back_and_bad_values_name_the_contact() {
    let g = soft(&grasps()[1], 0.025);
    let back = parse_grasp(&write_grasp(&g)).unwrap();
    assert_eq!(back.contacts()[2].torsion(), 0.025);
    assert_eq!(
        q1(&back).unwrap().value.unwrap(),
        q1(&g).unwrap().value.unwrap()
    );
    let mut value = write_grasp(&g);
    value["contacts"][3]["torsion"] = serde_json::json!(-1.0);
    let err = parse_grasp(&value).unwrap_err().to_string();
    assert!(
        err.contains("contact 3") && err.contains("torsion"),
        "{err}"
    );
    let hard = Contact::try_new([0.0; 3], [0.0, 0.0, 1.0], None).unwrap();
    assert!(matches!(
        hard.with_torsion(f64::NAN),
        Err(GraspError::InvalidTorsion { .. })
    ));
    assert!(!hard.is_soft() && hard.with_torsion(0.0).map(|c| c.is_soft()) == Ok(false));
}
