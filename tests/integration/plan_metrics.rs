//! `plan` ranks by every metric: its best grasp is the force-closure sample with the largest
//! value, the value computed here grasp by grasp with the metric's own call (each of which
//! `tests/metrics.rs` checks against an independent reference), over `plan::samples` — the
//! planner's sample sequence.

use pqhull::grasp::metrics::{grasp_matrix_singular_values, gws_volume};
use pqhull::grasp::quality::q1;
use pqhull::grasp::{Evaluation, Evaluator, FrictionModel, Grasp, Method, Metric, QualityError};
use pqhull::mesh::Mesh;
use pqhull::plan::{
    DescentConfig, MAX_EVALUATIONS, MAX_SCREEN, MAX_STARTS, PlanConfig, PlanError, StepRule, plan,
    plan_descent, samples,
};

/// Gravity at the centre of mass, in the object's torque frame.
const GRAVITY: [f64; 6] = [0.0, 0.0, -1.0, 0.0, 0.0, 0.0];

fn object() -> Mesh {
    Mesh::uv_sphere(0.3, 6, 12).expect("a sphere")
}

fn config(metric: Metric) -> PlanConfig {
    PlanConfig {
        contacts: 3,
        samples: 40,
        friction: FrictionModel::try_new(0.5, 6).expect("valid friction"),
        metric,
        seed: 11,
    }
}

/// Wrench resistance of `wrench` by `method` (what `metrics::resist` was).
fn resist(grasp: &Grasp, wrench: [f64; 6], method: Method) -> Result<Evaluation, QualityError> {
    Evaluator::new(Metric::Resist { wrench }, method, None)?.evaluate(grasp)
}

/// A metric's value of one grasp, by its own call.
type Value = Box<dyn Fn(&Grasp) -> Option<f64>>;

/// The best (sample, value) among force-closure samples, each value by `value`.
fn best_by(metric: Metric, value: impl Fn(&Grasp) -> Option<f64>) -> (usize, f64) {
    let object = object();
    let c = config(metric);
    let mut best: Option<(usize, f64)> = None;
    for (i, g) in samples(&object, None, c.contacts, c.friction, c.seed)
        .take(c.samples)
        .enumerate()
    {
        let g = g.expect("a valid sample");
        let closure = match metric {
            // Q_OWS-like metrics decide force closure themselves.
            Metric::Resist { .. } => resist(&g, GRAVITY, Method::Partial).unwrap().force_closure,
            _ => q1(&g).unwrap().force_closure,
        };
        if let (true, Some(v)) = (closure, value(&g))
            && best.is_none_or(|(_, b)| v > b)
        {
            best = Some((i, v));
        }
    }
    best.expect("some sample is force closure")
}

#[test]
fn the_plan_keeps_the_best_force_closure_sample_by_every_metric() {
    let cases: [(Metric, Value); 5] = [
        (
            Metric::Q1,
            Box::new(|g| Some(q1(g).unwrap().value.unwrap())),
        ),
        (
            Metric::Resist { wrench: GRAVITY },
            Box::new(|g| resist(g, GRAVITY, Method::Partial).unwrap().value),
        ),
        (Metric::Volume, Box::new(|g| Some(gws_volume(g).unwrap()))),
        (
            Metric::SigmaMin,
            Box::new(|g| Some(grasp_matrix_singular_values(g).unwrap()[5])),
        ),
        (
            Metric::Isotropy,
            Box::new(|g| {
                // σ_min / σ_max, 0 when σ_max is 0 (what `GraspMatrix::isotropy` was).
                let s = grasp_matrix_singular_values(g).unwrap();
                Some(if s[0] > 0.0 { s[5] / s[0] } else { 0.0 })
            }),
        ),
    ];
    let mut chosen = Vec::new();
    for (metric, value) in cases {
        let (sample, expected) = best_by(metric, value);
        for method in [Method::Partial, Method::Full] {
            let report = plan(&object(), None, &config(metric), method).expect("a plan");
            let best = report.best.expect("a best grasp");
            assert_eq!(
                best.sample,
                sample,
                "{} by {}",
                metric.name(),
                method.name()
            );
            // Q1 by the full hull agrees with the partial one to its promised 1e−12; the
            // others compute the value one way.
            assert!(
                (best.value - expected).abs() <= 1e-12 * expected.abs(),
                "{} by {}: {} vs {expected}",
                metric.name(),
                method.name(),
                best.value
            );
        }
        chosen.push(sample);
    }
    // The metrics disagree on some best grasp: ranking really follows the metric asked for.
    chosen.sort_unstable();
    chosen.dedup();
    assert!(chosen.len() > 1, "every metric chose the same sample");
}

#[test]
fn a_plan_refuses_what_its_metric_cannot_take() {
    let zero = config(Metric::Resist { wrench: [0.0; 6] });
    assert!(matches!(
        plan(&object(), None, &zero, Method::Partial),
        Err(PlanError::Quality(QualityError::ResistedWrench(_)))
    ));
    let by_qhull = config(Metric::Resist { wrench: GRAVITY });
    assert!(matches!(
        plan(&object(), None, &by_qhull, Method::Qhull),
        Err(PlanError::Quality(QualityError::UnsupportedMethod { .. }))
    ));
    assert!(matches!(
        plan(&object(), None, &config(Metric::Ows), Method::Partial),
        Err(PlanError::NoWrenchSpace)
    ));
}

#[test]
fn the_descent_planner_names_what_it_refuses_before_any_work() {
    let friction = FrictionModel::try_new(0.5, 6).expect("valid friction");
    let q1 = DescentConfig::new(3, friction, Metric::Q1);
    let refuse = |c: DescentConfig| plan_descent(&object(), None, &c, Method::Partial).unwrap_err();
    let e = refuse(DescentConfig {
        starts: MAX_STARTS + 1,
        ..q1
    });
    assert_eq!(
        e,
        PlanError::TooManyStarts {
            starts: MAX_STARTS + 1,
            max: MAX_STARTS
        }
    );
    assert!(e.to_string().contains("starts are too many"), "{e}");
    let e = refuse(DescentConfig {
        evaluations: MAX_EVALUATIONS + 1,
        ..q1
    });
    assert!(matches!(e, PlanError::TooManyEvaluations { .. }), "{e}");
    assert!(e.to_string().contains("evaluations per start"), "{e}");
    let e = refuse(DescentConfig {
        screen: MAX_SCREEN + 1,
        ..q1
    });
    assert_eq!(
        e,
        PlanError::TooManyScreened {
            screen: MAX_SCREEN + 1,
            max: MAX_SCREEN
        }
    );
    assert!(e.to_string().contains("candidates screened"), "{e}");
    for empty in [
        DescentConfig { screen: 0, ..q1 },
        DescentConfig { starts: 0, ..q1 },
        DescentConfig {
            evaluations: 0,
            ..q1
        },
        DescentConfig { contacts: 0, ..q1 },
    ] {
        assert_eq!(refuse(empty), PlanError::Empty);
    }
    let ows = DescentConfig {
        evaluations: 1,
        ..DescentConfig::new(3, friction, Metric::Ows)
    };
    assert_eq!(
        refuse(ows),
        PlanError::TooFewEvaluations {
            evaluations: 1,
            needed: 2
        }
    );
    let ows = DescentConfig::new(3, friction, Metric::Ows);
    assert_eq!(refuse(ows), PlanError::NoWrenchSpace);
    let volume = DescentConfig::new(3, friction, Metric::Volume);
    assert_eq!(refuse(volume), PlanError::NotClimbable(Metric::Volume));
    for step in [
        StepRule {
            min: 0.0,
            ..StepRule::default()
        },
        StepRule {
            initial: 0.9,
            ..StepRule::default()
        },
        StepRule {
            grow: 0.5,
            ..StepRule::default()
        },
        StepRule {
            max: f64::INFINITY,
            ..StepRule::default()
        },
        StepRule {
            initial: f64::NAN,
            ..StepRule::default()
        },
    ] {
        let e = refuse(DescentConfig { step, ..q1 });
        assert!(matches!(e, PlanError::StepRule(_)), "{step:?}: {e}");
    }
}
