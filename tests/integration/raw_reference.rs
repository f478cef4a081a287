//! Q1, Q∞ and Q_OWS against an independent reference computed on the grasp's *raw* wrenches —
//! exactly `Grasp::wrenches()`, f = n + μ(cos θ_j t + sin θ_j (n × t)), w = [f; (p − c) × f / ρ] in
//! f64 — not on any internally perturbed (snapped) copy of them.
//!
//! The contract checked (see `support/raw_reference.rs` for how the reference is computed):
//!
//! * value within 1e-12 relative of the reference, or 1e-14 × scale absolutely near zero (scale:
//!   the largest raw wrench norm for Q1 and Q_OWS; for Q∞ the sum over contacts of each
//!   contact's largest raw wrench norm);
//! * `force_closure == (value ≥ ε × scale)` with ε = `FORCE_CLOSURE_EPSILON` = 1e-12; physically
//!   degenerate grasps (two contacts, contacts on one line, coinciding contacts) never are;
//! * Q_OWS: the verdict of Q1; its value (force closure only) within 1e-12 relative of
//!   min over disturbances d and facets with n·(−d) > 0 of offset / n·(−d) (computed exactly, as
//!   the linear program max r s.t. −r·d ∈ hull); the ellipsoid method's verdict equals the exact
//!   one.
//! * verdict checks are skipped when the reference lies within 1e-13·scale of ε·scale (the
//!   reference is trusted to that band; in practice it is good to ~1e-16·scale).
//!
//! Families: 300 seeded grasps (2–5 contacts on an ellipsoid, a box, a cylinder; k = 6–12;
//! μ ∈ [0.2, 1]) for Q1 and Q_OWS (50 random disturbances each); 60 for Q∞ (sums small enough to
//! materialise, ≤ 1300 points; the full method on one grasp per shape, today's full Q∞ taking
//! seconds); 350 physically degenerate grasps; 60 near-boundary grasps (a dozen base grasps
//! bisected in μ or in one contact's position to Q1 ≈ ±1e-9, ±1e-11 and +5e-13 × scale, the
//! last a boundary grasp); the near-boundary cylinder case file.
//!
//! Each test collects every failed check, prints a summary (max / median relative error per
//! metric and method, verdict counts) with `eprintln!`, and fails at the end if anything failed.
//! Run with `cargo test --release --features qhull --test raw_reference -- --nocapture`.
#![cfg(feature = "qhull")]

use crate::support::raw_reference::{
    FORCE_CLOSURE_EPSILON, Report, Shape, check_formula, check_ows, check_q1, check_qinf,
    cylinder_case, degenerate_grasps, evaluate, expected_verdict, hull_reference, minkowski_scale,
    near_boundary_family, note_references, random_disturbances, random_grasp, seed, union_scale,
};
use pqhull::geometry::Rng;
use pqhull::grasp::{FrictionModel, Method, Metric};

/// Disturbances per task wrench space.
const DISTURBANCES: usize = 50;

// ---------------------------------------------------------------------------------------------
// 1. Seeded grasps on an ellipsoid, a box and a cylinder

/// Grasps per shape for Q1 / Q_OWS.
const RANDOM_PER_SHAPE: u64 = 100;

#[test]
fn random_grasps_q1_and_ows() {
    let mut report = Report::default();
    let mut refs = Vec::new();
    for (s, shape) in Shape::ALL.into_iter().enumerate() {
        for i in 0..RANDOM_PER_SHAPE {
            let mut rng = Rng::new(seed(&[1, s as u64, i]));
            let m = 2 + rng.index(4);
            let k = 6 + rng.index(7);
            let mu = rng.uniform_in(0.2, 1.0);
            let friction = FrictionModel::try_new(mu, k).unwrap();
            let grasp = random_grasp(&mut rng, shape, m, friction);
            let case = format!("{} #{i} (m = {m}, k = {k}, μ = {mu:.3})", shape.name());
            check_formula(&mut report, &case, &grasp);
            let w = grasp.wrenches();
            let r = report.time("reference Q1", || hull_reference(&w, union_scale(&w)));
            let degenerate = m == 2;
            check_q1(&mut report, &case, &grasp, &r, degenerate);
            let disturbances = random_disturbances(&mut rng, DISTURBANCES);
            check_ows(&mut report, &case, &grasp, &disturbances, &r, degenerate);
            refs.push(r);
        }
    }
    note_references(&mut report, "Q1 union", &refs);
    report
        .finish("1. random grasps: Q1 (Partial, Full) and Q_OWS (Partial, BruteForce, Ellipsoid)");
}

/// Grasps per shape for Q∞.
const QINF_PER_SHAPE: u64 = 20;

#[test]
fn random_grasps_qinf() {
    let mut report = Report::default();
    for (s, shape) in Shape::ALL.into_iter().enumerate() {
        for i in 0..QINF_PER_SHAPE {
            let mut rng = Rng::new(seed(&[2, s as u64, i]));
            // Sums small enough for a materialised reference (k^m ≤ 1296; with the zero wrench
            // the reference of a grasp that is not force closure is exactly 0 at any size).
            // The first grasp of each shape also goes through the full method (m = 3, k = 6: 216
            // and 343 points); two-contact sums (≤ 144 points) do without the zero wrench.
            let m = if i == 0 { 3 } else { 2 + rng.index(3) };
            let k = match m {
                _ if i == 0 => 6,
                2 => 6 + rng.index(7),
                3 => 6 + rng.index(3),
                _ => 6,
            };
            let mu = rng.uniform_in(0.2, 1.0);
            let friction = FrictionModel::try_new(mu, k).unwrap();
            let grasp = random_grasp(&mut rng, shape, m, friction);
            let case = format!("{} #{i} (m = {m}, k = {k}, μ = {mu:.3})", shape.name());
            for with_zero in [false, true] {
                let full = i == 0 || (m == 2 && !with_zero);
                check_qinf(&mut report, &case, &grasp, with_zero, m == 2, full);
            }
        }
    }
    report.finish("1. random grasps: Q∞ and Q∞ with the zero wrench (Partial, Full)");
}

// ---------------------------------------------------------------------------------------------
// 2. Physically degenerate grasps: never force closure

#[test]
fn degenerate_grasps_are_never_force_closure() {
    let mut report = Report::default();
    let mut refs = Vec::new();
    for (i, (case, grasp)) in degenerate_grasps().into_iter().enumerate() {
        check_formula(&mut report, &case, &grasp);
        let w = grasp.wrenches();
        let r = report.time("reference Q1", || hull_reference(&w, union_scale(&w)));
        check_q1(&mut report, &case, &grasp, &r, true);
        let mut rng = Rng::new(seed(&[7, i as u64]));
        let disturbances = random_disturbances(&mut rng, DISTURBANCES);
        check_ows(&mut report, &case, &grasp, &disturbances, &r, true);
        // Q∞ on every fourth (the verdict alone where the sum is too large to materialise).
        if i % 4 == 0 {
            for with_zero in [false, true] {
                let full = grasp.contact_count() == 2 && !with_zero;
                check_qinf(&mut report, &case, &grasp, with_zero, true, full);
            }
        }
        refs.push(r);
    }
    note_references(&mut report, "degenerate Q1 union", &refs);
    report.finish("2. degenerate grasps (two contacts, antipodal, collinear, coinciding)");
}

// ---------------------------------------------------------------------------------------------
// 3. Near-boundary grasps from both sides

#[test]
fn near_boundary_grasps_from_both_sides() {
    let mut report = Report::default();
    let mut refs = Vec::new();
    let grasps = report.time("bisection (reference Q1 per step)", || {
        (0..12).flat_map(near_boundary_family).collect::<Vec<_>>()
    });
    for (i, (case, grasp, r)) in grasps.into_iter().enumerate() {
        check_formula(&mut report, &case, &grasp);
        // The bisection's reference was of this very grasp.
        let w = grasp.wrenches();
        assert_eq!(r.value, hull_reference(&w, union_scale(&w)).value);
        let expected = expected_verdict(r.value, r.scale);
        report.note(format!(
            "{case}: expected force_closure {expected:?} (ε·scale = {:.1e})",
            FORCE_CLOSURE_EPSILON * r.scale
        ));
        check_q1(&mut report, &case, &grasp, &r, false);
        let mut rng = Rng::new(seed(&[10, i as u64]));
        let disturbances = random_disturbances(&mut rng, DISTURBANCES);
        check_ows(&mut report, &case, &grasp, &disturbances, &r, false);
        // Q∞ with the zero wrench has Q1's verdict and lies within [Q1, m·Q1]: near the boundary
        // too. Partial only; a reference for three contacts (7^3 = 343 points).
        if grasp.contact_count() == 3 {
            check_qinf(&mut report, &case, &grasp, true, false, false);
        }
        refs.push(r);
    }
    note_references(&mut report, "near-boundary Q1", &refs);
    report.finish("3. near-boundary grasps (Q1 ≈ ±1e-9, ±1e-11, +5e-13 × scale)");
}

// ---------------------------------------------------------------------------------------------
// 4. The near-boundary cylinder case

#[test]
fn force_closure_epsilon_is_the_contracts() {
    crate::support::raw_reference::check_epsilon();
}

#[test]
fn near_boundary_cylinder_case() {
    let grasp = cylinder_case();
    let mut report = Report::default();
    let case = "near-boundary-cylinder-grasp.json";
    check_formula(&mut report, case, &grasp);
    let w = grasp.wrenches();
    let scale = union_scale(&w);
    let r = hull_reference(&w, scale);
    report.note(format!(
        "reference Q1 = {:e} ({:e}·scale; Qhull: {}; Wolfe distance {:e})",
        r.value,
        r.value / scale,
        r.qhull_error
            .as_deref()
            .unwrap_or(if r.inside { "inside" } else { "outside" }),
        r.wolfe_distance
    ));
    assert!(
        r.value.abs() <= 1e-14 * scale,
        "the reference itself: |Q1| = {:e} > 1e-14·scale",
        r.value.abs()
    );
    for method in [Method::Partial, Method::Full] {
        let key = format!("Q1 {method:?}");
        match evaluate(Metric::Q1, method, &grasp) {
            Err(e) => report.error(&key, case, &e),
            Ok(q) => {
                let value = q.value.expect("Q1 has a value");
                report.note(format!(
                    "{key}: force_closure {}, value {value:e} ({:e}·scale)",
                    q.force_closure,
                    value / scale
                ));
                // |Q1| ≤ 1e-14·scale: the reference (~1e-16) is in the band, so the value check
                // is |got| ≤ 1e-14·scale.
                report.value(&key, case, value, 0.0, scale);
                report.verdict(&key, case, q.force_closure, Some(false), "|Q1| < ε·scale");
            }
        }
    }
    let mut rng = Rng::new(seed(&[11]));
    let disturbances = random_disturbances(&mut rng, DISTURBANCES);
    // Not "physically degenerate": expected not force closure because |Q1| < ε·scale.
    check_ows(&mut report, case, &grasp, &disturbances, &r, false);
    // Q∞ with the zero wrench shares Q1's (boundary) verdict: 9^4 = 6561 points, partial only.
    let metric = Metric::QInf {
        with_zero_wrench: true,
    };
    match evaluate(metric, Method::Partial, &grasp) {
        Err(e) => report.error("Qinf+0 Partial", case, &e),
        Ok(q) => {
            let scale = minkowski_scale(&grasp);
            report.note(format!(
                "Qinf+0 Partial: force_closure {}, value {:e}·scale",
                q.force_closure,
                q.value.expect("Q∞ has a value") / scale
            ));
            report.verdict(
                "Qinf+0 Partial",
                case,
                q.force_closure,
                Some(false),
                "Q1 is a boundary grasp",
            );
        }
    }
    report.finish("4. tests/data/near-boundary-cylinder-grasp.json");
}
