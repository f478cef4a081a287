//! Grasp quality metrics: known answers, invariances, partial = full on many random grasps, Q∞
//! implicit = materialised, batch order.

use crate::support::grasps::{minkowski_points, random_bar_grasp};
use pqhull::geometry::Rng;
use pqhull::grasp::quality::q1_of_wrenches;
use pqhull::grasp::{
    Contact, Evaluation, Evaluator, FrictionModel, Grasp, Method, Metric, evaluate_batch,
};

fn axis_wrenches() -> Vec<[f64; 6]> {
    let mut w = Vec::new();
    for i in 0..6 {
        for s in [1.0, -1.0] {
            let mut e = [0.0; 6];
            e[i] = s;
            w.push(e);
        }
    }
    w
}

fn methods() -> Vec<Method> {
    vec![
        Method::Partial,
        Method::Full,
        #[cfg(feature = "qhull")]
        Method::Qhull,
    ]
}

#[test]
fn cross_polytope_cube_and_a_missing_direction() {
    for method in methods() {
        let q = q1_of_wrenches(&axis_wrenches(), method).unwrap();
        assert!(q.force_closure, "{method:?}");
        assert!(
            (q.value.unwrap() - 1.0 / 6f64.sqrt()).abs() < 1e-14,
            "{method:?}: {}",
            q.value.unwrap()
        );
        assert_eq!(q.deciding_wrenches().len(), 6);

        let cube: Vec<[f64; 6]> = (0..64)
            .map(|b| std::array::from_fn(|c| if b >> c & 1 == 1 { 1.0 } else { -1.0 }))
            .collect();
        let q = q1_of_wrenches(&cube, method).unwrap();
        assert!(
            q.force_closure && (q.value.unwrap() - 1.0).abs() < 1e-14,
            "{method:?}: {}",
            q.value.unwrap()
        );

        // Without −e_6 the origin lies on the facet x_6 = 0: zero, not force closure.
        let mut w = axis_wrenches();
        w.retain(|e| e[5] != -1.0);
        let q = q1_of_wrenches(&w, method).unwrap();
        assert!(!q.force_closure, "{method:?}");
        assert_eq!(q.value.unwrap(), 0.0, "{method:?}");
    }
}

/// Force closure must match exactly; values to 1e−12 relative. Near zero the floor is 1e−2 of the
/// wrench size (the wrenches here have norm ≈ 1): a plane distance is a dot product whose rounding
/// is ~1e−16 of the wrenches, not of the value, and coplanar facets triangulated with different
/// base vertices round differently (seen: 5.1176912800714e−4 vs …8006e−4, 1.5e−15 apart).
fn agree(a: &Evaluation, b: &Evaluation, what: &str) {
    assert_eq!(a.force_closure, b.force_closure, "{what}: {a:?} vs {b:?}");
    let (x, y) = (a.value.unwrap(), b.value.unwrap());
    let scale = x.abs().max(y.abs()).max(1e-300);
    assert!(
        (x - y).abs() <= 1e-12 * scale.max(1e-2),
        "{what}: {x} vs {y}"
    );
}

/// `metric` of `grasp` by the partial and by the full method, fresh evaluators.
fn partial_and_full(metric: Metric, grasp: &Grasp) -> (Evaluation, Evaluation) {
    let by = |method| {
        Evaluator::new(metric, method, None)
            .unwrap()
            .evaluate(grasp)
            .unwrap()
    };
    (by(Method::Partial), by(Method::Full))
}

#[test]
fn two_antipodal_hard_fingers_are_not_force_closure() {
    // Frictionless-ish pinch: rank 5 at most; a finite negative value, no error.
    let contacts = vec![
        Contact::try_new([-0.5, 0.0, 0.0], [1.0, 0.0, 0.0], None).unwrap(),
        Contact::try_new([0.5, 0.0, 0.0], [-1.0, 0.0, 0.0], None).unwrap(),
    ];
    let grasp = Grasp::builder(contacts, FrictionModel::try_new(0.5, 8).unwrap())
        .build()
        .unwrap();
    for method in methods() {
        let q = Evaluator::new(Metric::Q1, method, None)
            .unwrap()
            .evaluate(&grasp)
            .unwrap();
        assert!(!q.force_closure, "{method:?}");
        assert!(
            q.value.unwrap().is_finite() && q.value.unwrap() <= 0.0,
            "{method:?}: {}",
            q.value.unwrap()
        );
    }
}

#[test]
fn rotation_about_the_reference_point_and_torque_scale() {
    let mut rng = Rng::new(3);
    let mut checked = 0;
    while checked < 20 {
        let grasp = random_bar_grasp(&mut rng, 4, 8);
        let q = Evaluator::new(Metric::Q1, Method::Partial, None)
            .unwrap()
            .evaluate(&grasp)
            .unwrap();
        if !q.force_closure {
            continue;
        }
        checked += 1;
        // Rotate every contact by 90° about z (an exact rotation) around the reference (origin).
        let rot = |v: [f64; 3]| [-v[1], v[0], v[2]];
        let contacts: Vec<Contact> = grasp
            .contacts()
            .iter()
            .map(|c| {
                Contact::try_new(rot(c.position()), rot(c.normal()), Some(rot(c.tangent())))
                    .unwrap()
            })
            .collect();
        let rotated = Grasp::builder(contacts, grasp.friction())
            .torque_scale(grasp.torque_scale())
            .build()
            .unwrap();
        let r = Evaluator::new(Metric::Q1, Method::Partial, None)
            .unwrap()
            .evaluate(&rotated)
            .unwrap();
        assert!(
            (q.value.unwrap() - r.value.unwrap()).abs() <= 1e-6 * q.value.unwrap(),
            "{} vs {}",
            q.value.unwrap(),
            r.value.unwrap()
        );

        // Scaling positions and ρ together leaves every wrench, hence Q1, unchanged (exactly for
        // a power of two).
        let scaled_contacts: Vec<Contact> = grasp
            .contacts()
            .iter()
            .map(|c| {
                Contact::try_new(c.position().map(|x| x * 4.0), c.normal(), Some(c.tangent()))
                    .unwrap()
            })
            .collect();
        let scaled = Grasp::builder(scaled_contacts, grasp.friction())
            .torque_scale(grasp.torque_scale() * 4.0)
            .build()
            .unwrap();
        let s = Evaluator::new(Metric::Q1, Method::Partial, None)
            .unwrap()
            .evaluate(&scaled)
            .unwrap();
        assert_eq!(s.value.unwrap(), q.value.unwrap());

        // Doubling ρ halves every torque coordinate: Q1 is that of the mapped wrench set.
        let doubled = Grasp::builder(grasp.contacts().to_vec(), grasp.friction())
            .torque_scale(grasp.torque_scale() * 2.0)
            .build()
            .unwrap();
        // Halving is exact, so the doubled grasp's raw wrenches are exactly these.
        let w = grasp.wrenches();
        let mapped: Vec<[f64; 6]> = w
            .iter()
            .map(|x| std::array::from_fn(|c| if c < 3 { x[c] } else { x[c] / 2.0 }))
            .collect();
        let d = Evaluator::new(Metric::Q1, Method::Partial, None)
            .unwrap()
            .evaluate(&doubled)
            .unwrap();
        let expected = q1_of_wrenches(&mapped, Method::Full).unwrap();
        assert!(
            (d.value.unwrap() - expected.value.unwrap()).abs()
                <= 1e-12 * expected.value.unwrap().abs().max(1e-3),
            "{} vs {}",
            d.value.unwrap(),
            expected.value.unwrap()
        );
    }
}

#[test]
fn partial_equals_full_on_ten_thousand_random_grasps() {
    let cases: usize = std::env::var("PQHULL_GRASP_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(10_000);
    let mut rng = Rng::new(20261122);
    let mut partial = Evaluator::new(Metric::Q1, Method::Partial, None).unwrap();
    let mut full = Evaluator::new(Metric::Q1, Method::Full, None).unwrap();
    let mut force_closure = 0;
    let mut by_gjk = 0;
    for case in 0..cases {
        let m = 2 + rng.index(3);
        let k = 3 + rng.index(4);
        let grasp = random_bar_grasp(&mut rng, m, k);
        let a = partial.evaluate(&grasp).unwrap();
        let b = full.evaluate(&grasp).unwrap();
        agree(&a, &b, &format!("case {case} (m = {m}, k = {k})"));
        force_closure += usize::from(a.force_closure);
        by_gjk += usize::from(!a.force_closure && a.stats.facets_created == 0);
    }
    // Both kinds are exercised.
    assert!(
        force_closure > cases / 20 && force_closure < cases - cases / 20,
        "{force_closure}"
    );
    // Most grasps that are not force closure were separated by GJK, with no hull.
    assert!(
        by_gjk > (cases - force_closure) / 2,
        "{by_gjk} of {} by GJK",
        cases - force_closure
    );
}

#[test]
#[ignore = "extended (about 100 s): --run-ignored all runs it, as CI does"]
fn q_inf_implicit_equals_materialised() {
    let mut rng = Rng::new(77);
    let mut force_closure = 0;
    let mut by_gjk = 0;
    // The full method's exact hull of a materialised sum is the slow side (up to 10^6 facets and
    // 17 s per grasp at m = 3, k = 8 with the zero wrench): sizes are kept to at most 5^4 points.
    for case in 0..16 {
        let (m, k) = [(3, 4), (3, 6), (4, 4), (3, 5)][case % 4];
        let grasp = random_bar_grasp(&mut rng, m, k);
        for with_zero_wrench in [false, true] {
            let metric = Metric::QInf { with_zero_wrench };
            let (a, b) = partial_and_full(metric, &grasp);
            agree(
                &a,
                &b,
                &format!("case {case} (m = {m}, k = {k}, zero {with_zero_wrench})"),
            );
            force_closure += usize::from(a.force_closure);
            // Separated by the support-function GJK, no hull built.
            by_gjk += usize::from(!a.force_closure && a.stats.facets_created == 0);
            if with_zero_wrench && !a.force_closure {
                // The origin, a point of the sum, is on its boundary.
                assert_eq!(
                    (a.value.unwrap(), b.value.unwrap()),
                    (0.0, 0.0),
                    "case {case}"
                );
            }
        }
    }
    assert!(force_closure > 0);
    assert!(by_gjk > 0, "the GJK path was not exercised");
}

#[test]
fn batch_keeps_input_order() {
    let mut rng = Rng::new(9);
    let grasps: Vec<Grasp> = (0..64).map(|_| random_bar_grasp(&mut rng, 4, 6)).collect();
    let batch = evaluate_batch(&grasps, Metric::Q1, Method::Partial, None).unwrap();
    let mut one = Evaluator::new(Metric::Q1, Method::Partial, None).unwrap();
    for (grasp, result) in grasps.iter().zip(&batch) {
        let expected = one.evaluate(grasp).unwrap();
        assert_eq!(
            result.as_ref().unwrap().value.unwrap(),
            expected.value.unwrap()
        );
    }
}

/// A flat Minkowski sum too large to materialise (an antipodal pinch, rank 5, at the largest cone
/// edge count, with the zero wrench: 1025² > 2²⁰ points): not force closure, answered by the slab
/// test and GJK instead of an error, by the partial and the full method alike; without the zero
/// wrench (1024² points) the same.
#[test]
fn q_inf_of_a_flat_sum_too_large_to_materialise() {
    let pinch = Grasp::builder(
        vec![
            Contact::try_new([-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], None).unwrap(),
            Contact::try_new([1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], None).unwrap(),
        ],
        FrictionModel::try_new(0.5, pqhull::grasp::MAX_CONE_EDGES).unwrap(),
    )
    .build()
    .unwrap();
    let by = |with_zero_wrench: bool, method: Method, grasp: &Grasp| {
        Evaluator::new(Metric::QInf { with_zero_wrench }, method, None)
            .unwrap()
            .evaluate(grasp)
    };
    for with_zero_wrench in [true, false] {
        let q = by(with_zero_wrench, Method::Partial, &pinch).unwrap();
        assert!(!q.force_closure);
        // The two cones' sum contains the origin's neighbourhood within the flat: distance 0.
        assert!(q.value.unwrap().abs() < 1e-9, "{}", q.value.unwrap());
        // The full method answers it from the slab test too, before materialising anything.
        let flat = by(with_zero_wrench, Method::Full, &pinch).unwrap();
        assert!(!flat.force_closure);
        assert!(
            (flat.value.unwrap() - q.value.unwrap()).abs() < 1e-9,
            "{} vs {}",
            flat.value.unwrap(),
            q.value.unwrap()
        );
    }
    // A sum that size which is not flat is still refused by the full method (128³ > 2²⁰).
    let tilted = Grasp::builder(
        vec![
            Contact::try_new([-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], None).unwrap(),
            Contact::try_new([1.0, 0.3, 0.0], [-1.0, 0.0, 0.0], None).unwrap(),
            Contact::try_new([0.0, 1.0, 0.2], [0.0, -1.0, 0.0], None).unwrap(),
        ],
        FrictionModel::try_new(0.5, 128).unwrap(),
    )
    .build()
    .unwrap();
    assert!(matches!(
        by(false, Method::Full, &tilted),
        Err(pqhull::grasp::quality::QualityError::MinkowskiTooLarge { .. })
    ));
}

/// Flat sums small enough to materialise: the partial method's GJK (no hull, nothing
/// materialised) agrees with Wolfe's algorithm over the full materialised sum, both for a pinch
/// whose flat sum holds the origin and for one that misses it.
#[test]
fn q_inf_of_flat_sums_agrees_with_the_materialised_sum() {
    let pinch = |offset: f64| {
        Grasp::builder(
            vec![
                Contact::try_new([-1.0, offset, 0.0], [1.0, 0.0, 0.0], None).unwrap(),
                Contact::try_new([1.0, 0.0, 0.0], [-1.0, 0.2, 0.0], None).unwrap(),
            ],
            FrictionModel::try_new(0.3, 12).unwrap(),
        )
        .build()
        .unwrap()
    };
    for offset in [0.0, 0.4] {
        for with_zero_wrench in [false, true] {
            let metric = Metric::QInf { with_zero_wrench };
            let grasp = pinch(offset);
            let (a, b) = partial_and_full(metric, &grasp);
            let what = format!("offset {offset}, zero {with_zero_wrench}");
            agree(&a, &b, &what);
            assert!(!a.force_closure, "{what}");
            assert_eq!(a.stats.facets_created, 0, "{what}: no hull");
            assert!(
                a.stats.points_processed < 144,
                "{what}: nothing materialised"
            );
        }
    }
}

/// Boundary grasps: 4 contacts on the axis-aligned faces of a bar with 32 edges, whose wrench
/// hull holds the origin within rounding (the seed-1 set of `pqh bench gws`). They are answered
/// from the snapped search's nearest facet and Wolfe's algorithm, not the exact engine (which
/// builds slivers there): the value must still be the exact engine's on the raw wrenches to the
/// `1e-14·scale` promised near zero, the verdict "not force closure", and Q∞ with the zero
/// wrench within [0, m·Q1] (up to the same accuracy).
#[test]
fn boundary_grasps_agree_with_the_exact_engine_on_the_raw_wrenches() {
    use pqhull::grasp::quality::q1_of_wrenches;
    let mut rng = Rng::new(1);
    let friction = FrictionModel::try_new(0.5, 32).unwrap();
    let set: Vec<Grasp> = (0..200)
        .map(|_| Grasp::random_on_box(&mut rng, [0.5, 0.2, 0.1], 4, friction))
        .collect();
    let mut q1 = Evaluator::new(Metric::Q1, Method::Partial, None).unwrap();
    let mut qinf = Evaluator::new(
        Metric::QInf {
            with_zero_wrench: true,
        },
        Method::Partial,
        None,
    )
    .unwrap();
    let mut boundary = 0;
    for (i, grasp) in set.iter().enumerate() {
        let wrenches = grasp.wrenches();
        let exact = q1_of_wrenches(&wrenches, Method::Partial).unwrap();
        let scale = exact.scale.unwrap();
        if exact.value.unwrap().abs() > 1e-12 * scale {
            continue;
        }
        boundary += 1;
        let a = q1.evaluate(grasp).unwrap();
        assert!(!a.force_closure, "grasp {i}");
        assert!(
            (a.value.unwrap() - exact.value.unwrap()).abs() <= 1e-14 * scale,
            "grasp {i}: {:e} vs exact {:e}",
            a.value.unwrap(),
            exact.value.unwrap()
        );
        let b = qinf.evaluate(grasp).unwrap();
        assert!(!b.force_closure, "grasp {i}");
        let m = grasp.contact_count() as f64;
        assert!(
            b.value.unwrap() >= -1e-14 * b.scale.unwrap()
                && b.value.unwrap() <= m * exact.value.unwrap().max(0.0) + 1e-14 * b.scale.unwrap(),
            "grasp {i}: Q∞+0 {:e}, Q1 {:e}",
            b.value.unwrap(),
            exact.value.unwrap()
        );
    }
    assert!(boundary >= 3, "{boundary} boundary grasps");
}

/// Wrenches too large for the metrics' squared norms are a clear error, never NaN or a null
/// quality (a friction coefficient of 1e160 used to print `"quality": null`); just below the
/// limit the partial and full methods still agree (a consistency check only: Qhull itself is
/// not reliable at coordinates of 1e99).
#[test]
fn huge_wrenches_are_an_error_and_large_ones_are_finite() {
    use pqhull::grasp::quality::{MAX_WRENCH_COORDINATE, QualityError};
    let contacts = vec![
        Contact::try_new([0.1, 0.0, 0.0], [-1.0, 0.0, 0.0], None).unwrap(),
        Contact::try_new([-0.1, 0.02, 0.0], [1.0, 0.0, 0.0], None).unwrap(),
        Contact::try_new([0.0, 0.1, 0.03], [0.0, -1.0, 0.0], None).unwrap(),
        Contact::try_new([0.02, -0.1, -0.02], [0.0, 1.0, 0.0], None).unwrap(),
    ];
    for (mu, ok) in [(1e160, false), (1e120, false), (1e99, true), (0.5, true)] {
        let grasp = Grasp::builder(contacts.clone(), FrictionModel::try_new(mu, 8).unwrap())
            .build()
            .unwrap();
        for metric in [
            Metric::Q1,
            Metric::QInf {
                with_zero_wrench: true,
            },
        ] {
            let q = Evaluator::new(metric, Method::Partial, None)
                .unwrap()
                .evaluate(&grasp);
            if !ok {
                assert!(
                    matches!(q, Err(QualityError::WrenchTooLarge { largest })
                        if largest > MAX_WRENCH_COORDINATE),
                    "μ = {mu:e}: {q:?}"
                );
                continue;
            }
            let q = q.unwrap();
            assert!(q.value.unwrap().is_finite(), "μ = {mu:e}: {q:?}");
            if metric != Metric::Q1 {
                continue; // the full Q∞ hull of 9^4 points takes minutes
            }
            let (a, b) = partial_and_full(metric, &grasp);
            assert!(b.value.unwrap().is_finite(), "μ = {mu:e}");
            assert_eq!(a.force_closure, b.force_closure, "μ = {mu:e}");
            assert!(
                (a.value.unwrap() - b.value.unwrap()).abs()
                    <= 1e-12 * a.value.unwrap().abs().max(1e-2 * a.scale.unwrap()),
                "μ = {mu:e}: {} vs {}",
                a.value.unwrap(),
                b.value.unwrap()
            );
        }
    }
}

/// `grasp` with its contacts listed as given by `copies` (indices into its contacts), in the
/// same torque frame.
fn with_contacts(grasp: &Grasp, copies: &[usize]) -> Grasp {
    let contacts = copies.iter().map(|&i| grasp.contacts()[i]).collect();
    Grasp::builder(contacts, grasp.friction())
        .torque_reference(grasp.torque_reference())
        .torque_scale(grasp.torque_scale())
        .build()
        .unwrap()
}

/// Issue 12, item 4: repeated contacts cost nothing. Q∞ of contacts each listed r times is r
/// times the value (r copies of a convex set sum to r times it), Q1 is unchanged (the union is),
/// and the work does not grow with r (before the merge, 4 contacts × 8 edges listed 3 times took
/// 8.6 s where once took 3 ms). A grasp with one contact repeated is checked against its
/// Minkowski sum written out in the test, with no merging.
#[test]
fn repeated_contacts_cost_nothing_and_scale_q_inf() {
    let mut rng = Rng::new(124);
    #[cfg(feature = "qhull")]
    let mut by_qhull = 0;
    for case in 0..6 {
        let base = random_bar_grasp(&mut rng, 4, 8);
        let q1 = Evaluator::new(Metric::Q1, Method::Partial, None)
            .unwrap()
            .evaluate(&base)
            .unwrap();
        for r in [2usize, 3] {
            let copies: Vec<usize> = (0..r).flat_map(|_| 0..4).collect();
            let repeated = with_contacts(&base, &copies);
            let q1_r = Evaluator::new(Metric::Q1, Method::Partial, None)
                .unwrap()
                .evaluate(&repeated)
                .unwrap();
            assert_eq!(
                q1_r.value.unwrap(),
                q1.value.unwrap(),
                "case {case}, r = {r}"
            );
            assert_eq!(q1_r.stats.facets_created, q1.stats.facets_created);
            for with_zero_wrench in [false, true] {
                let metric = Metric::QInf { with_zero_wrench };
                let once = Evaluator::new(metric, Method::Partial, None)
                    .unwrap()
                    .evaluate(&base)
                    .unwrap();
                let many = Evaluator::new(metric, Method::Partial, None)
                    .unwrap()
                    .evaluate(&repeated)
                    .unwrap();
                let what = format!("case {case}, r = {r}, zero {with_zero_wrench}");
                assert_eq!(once.force_closure, many.force_closure, "{what}");
                let expected = r as f64 * once.value.unwrap();
                assert!(
                    (many.value.unwrap() - expected).abs() <= 1e-12 * many.scale.unwrap(),
                    "{what}: {} vs {r} × {}",
                    many.value.unwrap(),
                    once.value.unwrap()
                );
                assert!(
                    many.stats.facets_created <= 2 * once.stats.facets_created + 64,
                    "{what}: {} facets for {}",
                    many.stats.facets_created,
                    once.stats.facets_created
                );
            }
        }
        // Contact 0 twice and two others once, k = 3: 3^4 (4^4 with the zero wrench) points,
        // whose exact full hull takes up to 1 s (k = 4: up to 10 s, the sum being degenerate).
        let small = random_bar_grasp(&mut rng, 3, 3);
        let mixed = with_contacts(&small, &[0, 1, 0, 2]);
        for with_zero_wrench in [false, true] {
            let metric = Metric::QInf { with_zero_wrench };
            let got = Evaluator::new(metric, Method::Partial, None)
                .unwrap()
                .evaluate(&mixed)
                .unwrap();
            let points = minkowski_points(&mixed, with_zero_wrench);
            let reference = q1_of_wrenches(&points, Method::Full).unwrap();
            agree(&got, &reference, &format!("mixed case {case}"));
            #[cfg(feature = "qhull")]
            if let Ok(qhull) = q1_of_wrenches(&points, Method::Qhull) {
                agree(&got, &qhull, &format!("mixed case {case}, Qhull"));
                by_qhull += 1;
            }
        }
    }
    // Qhull may refuse a sum it finds degenerate (QH6271); most it must take.
    #[cfg(feature = "qhull")]
    assert!(by_qhull >= 6, "Qhull answered {by_qhull} of 12");
}

/// The deciding wrenches of a force-closure Q1, by the partial and the full method, are the
/// nearest facet's vertices: six of the grasp's own wrenches, affinely independent, whose
/// hyperplane lies at the reported distance from the origin (its unit normal from Gram–Schmidt
/// on the simplex's edges: `support::simplex_normal`).
#[test]
fn deciding_wrenches_span_the_nearest_facet() {
    let dot = |a: &[f64; 6], b: &[f64; 6]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let mut rng = Rng::new(41);
    let mut checked = [0usize; 2];
    for _ in 0..150 {
        let grasp = random_bar_grasp(&mut rng, 4, 8);
        let wrenches = grasp.wrenches();
        for (slot, method) in [Method::Partial, Method::Full].into_iter().enumerate() {
            let q = Evaluator::new(Metric::Q1, method, None)
                .unwrap()
                .evaluate(&grasp)
                .unwrap();
            if !q.force_closure {
                continue;
            }
            let w = q.deciding_wrenches();
            assert_eq!(w.len(), 6, "{method:?}");
            for x in w {
                assert!(wrenches.contains(x), "{method:?}: {x:?} is not a wrench");
            }
            let (normal, shortest) = crate::support::simplex_normal(w);
            assert!(
                shortest > 1e-9,
                "{method:?}: the deciding wrenches are dependent"
            );
            let distance = dot(&normal, &w[0]).abs();
            let value = q.value.unwrap();
            assert!(
                (distance - value).abs() <= 1e-9 * q.scale.unwrap(),
                "{method:?}: the deciding wrenches' plane is {distance} away, the value {value}"
            );
            checked[slot] += 1;
        }
    }
    assert!(
        checked.iter().all(|&n| n >= 20),
        "{checked:?} force-closure grasps"
    );
}
