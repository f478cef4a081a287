//! The one front door of the grasp metrics, `pqhull::grasp::{Evaluator, evaluate_batch}`, and
//! its one result, `Evaluation`: the cone bracket is two Q1 evaluations (the inscribed and the
//! circumscribed pyramids, each widened by its accuracy); every metric of the vocabulary goes
//! through the evaluator and the batch call alike, which echo the metric and method asked for;
//! the errors new to `QualityError` give their wrapped error as `source`; a wrench space is
//! taken by Q_OWS and refused for every other metric.

use crate::support::grasps::{random_disturbances, with_friction_model};
use crate::support::{BAR_FRICTION, bar_grasps};
use pqhull::geometry::{EllipsoidError, Rng};
use pqhull::grasp::metrics::circumscribed;
use pqhull::grasp::ows::{ObjectWrenchSpace, OwsError};
use pqhull::grasp::quality::q1;
use pqhull::grasp::{
    Evaluation, Evaluator, FrictionModel, GraspError, Method, Metric, QualityError, evaluate_batch,
};
use std::error::Error;

/// The methods of Q1 and the metrics built on it.
fn hull_methods() -> Vec<Method> {
    vec![
        Method::Partial,
        Method::Full,
        #[cfg(feature = "qhull")]
        Method::Qhull,
    ]
}

/// Every metric of the vocabulary: those `Metric::NAMES` reads, and wrench resistance (which
/// needs its wrench).
fn vocabulary() -> Vec<Metric> {
    let mut metrics: Vec<Metric> = Metric::NAMES
        .iter()
        .map(|name| name.parse().expect("a name of the vocabulary"))
        .collect();
    metrics.push(Metric::Resist {
        wrench: [0.0, 0.0, -1.0, 0.1, 0.0, 0.0],
    });
    metrics
}

/// The accuracy promised for a Q1 value: 1e−12 relative, or 1e−14 of the wrench scale near 0.
fn accuracy(q1: &Evaluation) -> f64 {
    (1e-12 * q1.value.unwrap().abs()).max(1e-14 * q1.scale.unwrap())
}

/// A disturbance set of 12 random wrenches (spanning the six dimensions).
fn space(seed: u64) -> ObjectWrenchSpace {
    let mut rng = Rng::new(seed);
    ObjectWrenchSpace::from_disturbances(random_disturbances(&mut rng, 12)).unwrap()
}

#[test]
fn the_cone_bracket_is_q1_of_the_inscribed_and_the_circumscribed_pyramids() {
    let friction = FrictionModel::try_new(BAR_FRICTION, 6).unwrap();
    let outer_friction = circumscribed(friction).unwrap();
    assert_eq!(outer_friction.cone_edges(), 6);
    assert!(outer_friction.friction() > friction.friction());
    let grasps = bar_grasps(31, 24, 4, friction);
    let (mut closure, mut evaluated) = (0, 0);
    for method in hull_methods() {
        let mut cones = Evaluator::new(Metric::ConeBracket, method, None).unwrap();
        let mut q1 = Evaluator::new(Metric::Q1, method, None).unwrap();
        for (i, grasp) in grasps.iter().enumerate() {
            let what = format!("{method:?}, grasp {i}");
            let evaluation = cones.evaluate(grasp).unwrap();
            let inscribed = q1.evaluate(grasp).unwrap();
            let outer = q1
                .evaluate(&with_friction_model(grasp, outer_friction))
                .unwrap();
            assert_eq!(
                (evaluation.metric, evaluation.method),
                (Metric::ConeBracket, method),
                "{what}"
            );
            // The value is Q1 of the inscribed pyramids, with Q1's verdict and deciding wrenches.
            let value = evaluation.value.unwrap();
            assert_eq!(value, inscribed.value.unwrap(), "{what}");
            assert_eq!(evaluation.force_closure, inscribed.force_closure, "{what}");
            assert_eq!(evaluation.scale, inscribed.scale, "{what}");
            assert_eq!(
                evaluation.deciding_wrenches(),
                inscribed.deciding_wrenches(),
                "{what}"
            );
            assert_eq!(evaluation.deciding_disturbance, None, "{what}");
            // The bracket: the inscribed Q1 minus its accuracy, the circumscribed Q1 plus its.
            let bracket = evaluation.bracket.expect("a bracket");
            assert!(
                bracket.low <= value && value <= bracket.high,
                "{what}: {} ≤ {value} ≤ {}",
                bracket.low,
                bracket.high
            );
            assert!(bracket.contains(value), "{what}");
            assert_eq!(bracket.low, value - accuracy(&inscribed), "{what}");
            assert_eq!(
                bracket.high,
                outer.value.unwrap() + accuracy(&outer),
                "{what}"
            );
            // Both hulls' work is counted.
            assert!(
                evaluation.stats.points_processed >= inscribed.stats.points_processed,
                "{what}"
            );
            closure += usize::from(evaluation.force_closure);
            evaluated += 1;
        }
    }
    assert!(
        closure > 0 && closure < evaluated,
        "both kinds: {closure} force closure of {evaluated}"
    );
    // The bracket of every other metric is None.
    let q1 = Evaluator::new(Metric::Q1, Method::Partial, None)
        .unwrap()
        .evaluate(&grasps[0])
        .unwrap();
    assert_eq!(q1.bracket, None);
}

/// Whether two evaluations of one grasp say the same (everything but the time and work counters).
fn assert_same(a: &Evaluation, b: &Evaluation, what: &str) {
    assert_eq!(a.metric, b.metric, "{what}");
    assert_eq!(a.method, b.method, "{what}");
    assert_eq!(a.force_closure, b.force_closure, "{what}");
    assert_eq!(a.value, b.value, "{what}");
    assert_eq!(a.scale, b.scale, "{what}");
    assert_eq!(a.bracket, b.bracket, "{what}");
    assert_eq!(a.deciding_disturbance, b.deciding_disturbance, "{what}");
    assert_eq!(a.deciding_wrenches(), b.deciding_wrenches(), "{what}");
    assert_eq!(a.tied(), b.tied(), "{what}");
}

#[test]
fn every_metric_goes_through_the_evaluator_and_the_batch_alike() {
    let friction = FrictionModel::try_new(BAR_FRICTION, 4).unwrap();
    // Three contacts, k = 4: Q∞'s sum has 64 points (125 with the zero wrench), which the full
    // and Qhull methods materialise.
    let grasps = bar_grasps(32, 12, 3, friction);
    let space = space(33);
    let (mut pairs, mut refused) = (0, 0);
    let mut values = 0;
    for metric in vocabulary() {
        let is_ows = matches!(metric, Metric::Ows | Metric::Resist { .. });
        for method in Method::ALL {
            let space = (metric == Metric::Ows).then_some(&space);
            if !method.supports(metric) {
                let refusal = QualityError::UnsupportedMethod { method, metric };
                assert_eq!(Evaluator::new(metric, method, space).unwrap_err(), refusal);
                assert_eq!(
                    evaluate_batch(&grasps, metric, method, space).unwrap_err(),
                    refusal
                );
                refused += 1;
                continue;
            }
            if cfg!(not(feature = "qhull")) && method == Method::Qhull {
                continue;
            }
            let mut evaluator = Evaluator::new(metric, method, space).unwrap();
            assert_eq!((evaluator.metric(), evaluator.method()), (metric, method));
            let batch = evaluate_batch(&grasps, metric, method, space).unwrap();
            assert_eq!(batch.len(), grasps.len());
            let mut answered = 0;
            for (i, (grasp, from_batch)) in grasps.iter().zip(&batch).enumerate() {
                let what = format!("{metric} by {method}, grasp {i}");
                match (evaluator.evaluate(grasp), from_batch) {
                    (Ok(one), Ok(from_batch)) => {
                        assert_same(&one, from_batch, &what);
                        // The metric and method asked for are echoed.
                        assert_eq!((one.metric, one.method), (metric, method), "{what}");
                        // A value except for Q_OWS and resistance of a grasp that is not force
                        // closure; a scale except for those two; a bracket for the cone bracket.
                        if is_ows {
                            assert_eq!(one.value.is_some(), one.force_closure, "{what}");
                            assert_eq!(one.scale, None, "{what}");
                        } else {
                            assert!(one.value.is_some_and(f64::is_finite), "{what}");
                            assert!(one.scale.is_some_and(|s| s > 0.0), "{what}");
                        }
                        assert_eq!(
                            one.bracket.is_some(),
                            metric == Metric::ConeBracket,
                            "{what}"
                        );
                        values += usize::from(one.value.is_some());
                        answered += 1;
                    }
                    (Err(one), Err(from_batch)) => assert_eq!(&one, from_batch, "{what}"),
                    (one, from_batch) => panic!("{what}: {one:?} one by one, {from_batch:?}"),
                }
            }
            // The ellipsoid may find no usable ellipsoid for a grasp; every other pair answers
            // every grasp.
            if method != Method::Ellipsoid {
                assert_eq!(answered, grasps.len(), "{metric} by {method}");
            }
            pairs += 1;
        }
    }
    let qhull_pairs = if cfg!(feature = "qhull") { 7 } else { 0 };
    // Partial and full for all nine; Qhull for seven; partial-rays for two; the ellipsoid for one.
    assert_eq!(pairs, 9 * 2 + qhull_pairs + 2 + 1);
    assert_eq!(refused, 9 * 5 - (9 * 2 + 7 + 2 + 1));
    assert!(values > 0);
}

#[test]
fn the_new_errors_give_their_wrapped_error_as_source() {
    let friction = FrictionModel::try_new(BAR_FRICTION, 6).unwrap();
    let grasps = bar_grasps(34, 20, 4, friction);
    // A zero wrench to resist: refused up front, the space's own error as the source.
    let zero = Metric::Resist { wrench: [0.0; 6] };
    let err = Evaluator::new(zero, Method::Partial, None).unwrap_err();
    assert!(matches!(err, QualityError::ResistedWrench(_)), "{err:?}");
    let source = err.source().expect("a source");
    assert_eq!(source.downcast_ref::<OwsError>(), Some(&OwsError::AllZero));
    assert!(err.to_string().contains("zero"), "{err}");
    assert_eq!(
        evaluate_batch(&grasps, zero, Method::Partial, None).unwrap_err(),
        err
    );
    // A non-finite one likewise.
    let nan = Metric::Resist {
        wrench: [0.0, f64::NAN, 0.0, 0.0, 0.0, 0.0],
    };
    let err = Evaluator::new(nan, Method::Full, None).unwrap_err();
    assert!(matches!(err, QualityError::ResistedWrench(_)), "{err:?}");
    let source = err.source().expect("a source");
    assert!(
        matches!(
            source.downcast_ref::<OwsError>(),
            Some(OwsError::NonFinite { .. })
        ),
        "{source}"
    );
    // The ellipsoid method on disturbances spanning three dimensions: no enclosing ellipsoid,
    // the ellipsoid's own error as the source. (Asked of a force-closure grasp: one that is not
    // may be settled before the ellipsoid is needed.)
    let flat = ObjectWrenchSpace::from_disturbances(vec![
        [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0, 0.0, 0.0],
        [0.0, -1.0, 0.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, -1.0, 0.0, 0.0, 0.0],
        [0.5, 0.5, 0.5, 0.0, 0.0, 0.0],
        [-0.5, -0.5, 0.5, 0.0, 0.0, 0.0],
    ])
    .unwrap();
    let grasp = grasps
        .iter()
        .find(|g| q1(g).unwrap().force_closure)
        .expect("a force-closure grasp");
    let mut ellipsoid = Evaluator::new(Metric::Ows, Method::Ellipsoid, Some(&flat)).unwrap();
    let err = ellipsoid.evaluate(grasp).unwrap_err();
    let QualityError::Ellipsoid(wrapped) = &err else {
        panic!("{err:?}");
    };
    assert!(
        matches!(
            wrapped,
            EllipsoidError::RankDeficient { rank, dimension: 6 } if *rank < 6
        ),
        "{wrapped:?}"
    );
    let source = err.source().expect("a source");
    assert_eq!(source.downcast_ref::<EllipsoidError>(), Some(wrapped));
    assert_eq!(
        err.to_string(),
        format!("no enclosing ellipsoid: {wrapped}")
    );
    // The batch call gives the grasp the same error.
    let batch = evaluate_batch(
        std::slice::from_ref(grasp),
        Metric::Ows,
        Method::Ellipsoid,
        Some(&flat),
    )
    .unwrap();
    assert_eq!(batch[0].as_ref().unwrap_err(), &err);
    // The circumscribed friction model of a coefficient near f64::MAX overflows: the grasp's
    // error is the source.
    let huge = FrictionModel::try_new(f64::MAX, 3).unwrap();
    let overflow = circumscribed(huge).unwrap_err();
    assert!(
        matches!(overflow, GraspError::InvalidFriction { .. }),
        "{overflow:?}"
    );
    let err = QualityError::CircumscribedFriction(overflow.clone());
    assert_eq!(
        err.source().expect("a source").downcast_ref::<GraspError>(),
        Some(&overflow)
    );
    // The errors without a cause have no source.
    for err in [
        QualityError::VolumeOverflow,
        QualityError::SvdNoConvergence,
        QualityError::EllipsoidBoundary { mapped_q1: 0.0 },
        QualityError::OwsNeedsWrenchSpace,
    ] {
        assert!(err.source().is_none(), "{err:?}");
    }
}

#[test]
fn a_wrench_space_is_taken_by_q_ows_and_refused_for_every_other_metric() {
    let friction = FrictionModel::try_new(BAR_FRICTION, 6).unwrap();
    let grasps = bar_grasps(35, 4, 3, friction);
    let space = space(36);
    let message = "Q_OWS needs the object's wrench space, and only Q_OWS takes one";
    for metric in vocabulary() {
        for method in [Method::Partial, Method::Full] {
            let what = format!("{metric} by {method}");
            let (given, missing) = (
                Evaluator::new(metric, method, Some(&space)),
                Evaluator::new(metric, method, None),
            );
            let (batch_given, batch_missing) = (
                evaluate_batch(&grasps, metric, method, Some(&space)),
                evaluate_batch(&grasps, metric, method, None),
            );
            if metric == Metric::Ows {
                assert!(given.is_ok() && batch_given.is_ok(), "{what}");
                let err = missing.unwrap_err();
                assert_eq!(err, QualityError::OwsNeedsWrenchSpace, "{what}");
                assert_eq!(err.to_string(), message);
                assert_eq!(batch_missing.unwrap_err(), err, "{what}");
            } else {
                let err = given.unwrap_err();
                assert_eq!(err, QualityError::OwsNeedsWrenchSpace, "{what}");
                assert_eq!(err.to_string(), message);
                assert_eq!(batch_given.unwrap_err(), err, "{what}");
                assert!(missing.is_ok() && batch_missing.is_ok(), "{what}");
            }
        }
    }
    // Without a space, Q_OWS is refused by every method that computes it.
    for method in [Method::PartialRays, Method::Ellipsoid] {
        assert_eq!(
            Evaluator::new(Metric::Ows, method, None).unwrap_err(),
            QualityError::OwsNeedsWrenchSpace
        );
    }
}
