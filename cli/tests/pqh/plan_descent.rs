//! The descent planner (`pqhull::plan::plan_descent`) on the seed paper's five Table 1 objects:
//! every planned grasp at least as good as its start, and the planner's best at least as good as
//! the random sampler's for the same number of metric evaluations.

use pqhull::grasp::FrictionModel;
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::quality::{Method, Metric};
use pqhull::plan::{DescentConfig, PlanConfig, plan, plan_descent};
use pqhull_cli::object::table1_objects;

/// Runs the descent planner and the sampler with the descent's evaluation count on every object,
/// by `metric`: every planned grasp is at least as good as its start; when `must_beat`, the
/// descent's best is at least the sampler's on every object. Returns how many objects it beat
/// the sampler on.
fn against_the_sampler(
    metric: Metric,
    starts: usize,
    evaluations: usize,
    screen: usize,
    edges: usize,
    must_beat: bool,
) -> usize {
    let mut beaten = 0;
    let friction = FrictionModel::try_new(0.5, edges).unwrap();
    for (name, mesh) in table1_objects() {
        let space =
            (metric == Metric::Ows).then(|| ObjectWrenchSpace::from_mesh(&mesh, friction).unwrap());
        let config = DescentConfig {
            starts,
            evaluations,
            screen,
            seed: 11,
            ..DescentConfig::new(4, friction, metric)
        };
        let descent = plan_descent(&mesh, space.as_ref(), &config, Method::Partial).unwrap();
        for p in &descent.planned {
            assert!(
                (p.force_closure, p.value) >= (p.start_force_closure, p.start_value),
                "{name}: start {} went from {:?} to {:?}",
                p.start,
                (p.start_force_closure, p.start_value),
                (p.force_closure, p.value)
            );
            assert!(p.evaluations <= evaluations);
        }
        let sampled = plan(
            &mesh,
            space.as_ref(),
            &PlanConfig {
                contacts: 4,
                samples: descent.evaluations,
                friction,
                metric,
                seed: 12,
            },
            Method::Partial,
        )
        .unwrap();
        let best = descent.best().map(|b| b.value);
        let sampled_best = sampled.best.as_ref().map(|b| b.value);
        eprintln!(
            "{name}: {metric}: descent {best:?} ({} evaluations, {} force closure) vs sampler {sampled_best:?}",
            descent.evaluations,
            descent.force_closure()
        );
        beaten += usize::from(best.is_some() && best >= sampled_best);
        assert!(
            !must_beat || best.is_some() && best >= sampled_best,
            "{name}: descent's best {best:?} below the sampler's {sampled_best:?} over {} evaluations",
            descent.evaluations
        );
    }
    beaten
}

#[test]
fn the_descent_planner_beats_the_sampler_by_q1_on_the_five_objects() {
    assert_eq!(against_the_sampler(Metric::Q1, 6, 40, 1, 8, true), 5);
}

/// By Q_OWS, climbing from the sampler's starts alone (`screen` 1) loses to the sampler on the
/// cube and the teapot (0.165 against 0.188 and 0.122 against 0.155): Q_OWS ties among
/// disturbances at most grasps, and its climbs stop at those kinks soon after they start, so
/// where a climb starts matters. With each start (and each restart after a climb stops with
/// evaluations left) the best of SCREEN random candidates, out of the same evaluation budget,
/// the planner beats the sampler on all five (0.215, 0.472, 0.289, 0.241 and 0.193 against
/// 0.188, 0.391, 0.185, 0.186 and 0.155 here, in the order of `table1_objects`).
#[test]
fn the_descent_planner_beats_the_sampler_by_q_ows_on_the_five_objects() {
    const SCREEN: usize = 12;
    assert_eq!(against_the_sampler(Metric::Ows, 4, 120, SCREEN, 6, true), 5);
}
