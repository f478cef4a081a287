//! Traces of strategy runs (`pqhull::viz`): replaying the events rebuilds the hull, tracing changes
//! nothing, the stop reason matches the result; and `pqh trace` (errors, no network in the page).

use pqhull::geometry::Rng;
use pqhull::hull::{Event, Trace};
use pqhull::rbox::{Family, generate};
use pqhull::strategy::{DistanceResult, OwsResult, PointSource};
use pqhull::viz::{VizError, html, svg, trace_json};
use pqhull::{ClosestToOrigin, FacetId, FarthestPoint, Hull, OwsInflation, Stats, Strategy};

/// Live facets as (oriented vertices, sorted outside set), sorted.
type Facets<const D: usize> = Vec<([usize; D], Vec<usize>)>;

fn hull_facets<const D: usize>(hull: &Hull<D>) -> Facets<D> {
    let mut facets: Facets<D> = hull
        .facets()
        .map(|(_, f)| {
            let mut outside: Vec<usize> = f.outside_set().collect();
            outside.sort_unstable();
            (f.vertices(), outside)
        })
        .collect();
    facets.sort();
    facets
}

fn replayed_facets<const D: usize>(trace: &Trace<D>) -> Facets<D> {
    let mut facets: Facets<D> = trace
        .final_facets()
        .into_iter()
        .map(|mut f| {
            f.outside.sort_unstable();
            (f.vertices, f.outside)
        })
        .collect();
    facets.sort();
    facets
}

/// Counters without the wall time.
fn work(stats: Stats) -> (usize, usize, usize) {
    (
        stats.points_processed,
        stats.facets_created,
        stats.expansions,
    )
}

/// Runs `strategy` traced and untraced; checks that the replay rebuilds the final hull (vertices
/// in the same oriented order, the same outside sets), that the events account for the work
/// counters, and that both runs built the same hull. Returns both outputs and the trace.
fn traced_run<const D: usize, S: Strategy<D> + Clone>(
    points: &[[f64; D]],
    strategy: S,
) -> (S::Output, S::Output, Trace<D>) {
    let (plain_hull, plain) = Hull::try_with_strategy(points, strategy.clone()).expect("hull");
    let (hull, output, trace) = Hull::try_with_strategy_traced(points, strategy).expect("hull");
    assert_eq!(
        hull_facets(&hull),
        replayed_facets(&trace),
        "replay differs from the hull"
    );
    assert_eq!(
        hull_facets(&hull),
        hull_facets(&plain_hull),
        "tracing changed the hull"
    );
    assert_eq!(
        work(hull.stats()),
        work(plain_hull.stats()),
        "tracing changed the work"
    );
    assert_eq!(trace.points.len(), hull.point_count());
    assert!(matches!(trace.events.first(), Some(Event::Initial { .. })));
    assert!(matches!(trace.events.last(), Some(Event::Stop { .. })));
    let stops = trace
        .events
        .iter()
        .filter(|e| matches!(e, Event::Stop { .. }))
        .count();
    assert_eq!(stops, 1, "exactly one stop");
    let mut created = 0;
    let mut expansions = 0;
    let mut replay = trace.replay();
    while let Some(event) = replay.step() {
        match event {
            Event::Initial { facets } => created += facets.len(),
            Event::Expanded {
                created: c, point, ..
            } => {
                created += c.len();
                expansions += 1;
                // The added point is a vertex of every facet created.
                assert!(c.iter().all(|f| f.vertices.contains(point)));
            }
            Event::Chose { facet, .. } => {
                assert!(
                    replay.facet(*facet).is_some(),
                    "chose a facet that is not live"
                )
            }
            _ => {}
        }
    }
    assert_eq!(replay.vertices(), hull.vertex_indices());
    assert_eq!(
        (created, expansions),
        (hull.stats().facets_created, hull.stats().expansions)
    );
    let json = trace_json(&trace);
    assert_eq!(json["dimension"], D);
    assert_eq!(
        json["events"].as_array().map(Vec::len),
        Some(trace.events.len())
    );
    (plain, output, trace)
}

fn same_distance<const D: usize>(a: &DistanceResult<D>, b: &DistanceResult<D>) {
    assert_eq!(a.signed_distance, b.signed_distance);
    assert_eq!(a.closest_facet_vertices, b.closest_facet_vertices);
    assert_eq!(a.nearest_point, b.nearest_point);
    assert_eq!(work(a.stats), work(b.stats));
}

fn same_ows<const D: usize>(a: &OwsResult<D>, b: &OwsResult<D>) {
    assert_eq!(a.value, b.value);
    assert_eq!(a.deciding_facet_vertices, b.deciding_facet_vertices);
    assert_eq!(a.deciding_disturbance, b.deciding_disturbance);
    assert_eq!(work(a.stats), work(b.stats));
}

fn directions<const D: usize>(count: usize, seed: u64) -> Vec<[f64; D]> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| {
            let u = rng.unit_vector(D);
            std::array::from_fn(|i| u[i])
        })
        .collect()
}

/// Every strategy on one point set (whose hull contains the origin): farthest, closest from
/// inside and from outside, OWS in force closure, and OWS on the set moved off the origin.
fn every_strategy<const D: usize>(points: &[[f64; D]], seed: u64) {
    let (_, (), trace) = traced_run(points, FarthestPoint::new());
    assert!(
        trace
            .stop_reason()
            .unwrap()
            .contains("the hull is complete")
    );
    assert_eq!(trace.context.strategy, "FarthestPoint");

    let (plain, inside, trace) = traced_run(points, ClosestToOrigin::new());
    same_distance(&plain, &inside);
    assert!(inside.is_inside());
    assert!(trace.stop_reason().unwrap().contains("(query inside)"));
    assert_eq!(trace.context.query, Some([0.0; D]));

    let extent = points.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let far: [f64; D] = std::array::from_fn(|i| if i == 0 { 3.0 * extent } else { 0.3 * extent });
    let (plain, outside, trace) = traced_run(points, ClosestToOrigin::towards(far));
    same_distance(&plain, &outside);
    assert!(outside.signed_distance < 0.0);
    assert!(trace.stop_reason().unwrap().contains("(query outside)"));
    // The outside phase marks its nearest points; the last is the answer.
    let last_mark = trace.events.iter().rev().find_map(|e| match e {
        Event::Note { point: Some(x), .. } => Some(*x),
        _ => None,
    });
    assert_eq!(last_mark, Some(outside.nearest_point));

    let disturbances = directions::<D>(3 * D, seed);
    let (plain, ows, trace) = traced_run(points, OwsInflation::with_rays(&disturbances));
    same_ows(&plain, &ows);
    assert!(ows.value.is_some());
    assert!(
        trace
            .stop_reason()
            .unwrap()
            .contains("smallest inflation factor")
    );
    assert_eq!(trace.context.disturbances, disturbances);

    let index = pqhull::geometry::SupportIndex::new(&disturbances);
    let (_, indexed, trace) = traced_run(points, OwsInflation::new(&index));
    assert_eq!(indexed.value, ows.value);
    assert_eq!(
        trace.context.disturbances, disturbances,
        "input order restored"
    );

    let moved: Vec<[f64; D]> = points
        .iter()
        .map(|p| std::array::from_fn(|i| if i == 0 { p[i] + 3.0 * extent } else { p[i] }))
        .collect();
    let (plain, not_closure, trace) = traced_run(&moved, OwsInflation::with_rays(&disturbances));
    same_ows(&plain, &not_closure);
    assert!(not_closure.value.is_none());
    assert!(trace.stop_reason().unwrap().contains("not force closure"));
}

#[test]
fn two_d_traces_replay_to_the_hull() {
    every_strategy(&generate::<2>(&Family::UniformCube, 300, 1), 11);
    every_strategy(&generate::<2>(&Family::SphereSurface, 100, 2), 12);
    every_strategy(
        &generate::<2>(&Family::IntegerLattice { half_width: 3 }, 120, 3),
        13,
    );
}

#[test]
fn three_d_traces_replay_to_the_hull() {
    every_strategy(&generate::<3>(&Family::SphereSurface, 300, 4), 14);
    every_strategy(&generate::<3>(&Family::CubeCornersDiamond, 100, 5), 15);
    every_strategy(
        &generate::<3>(&Family::IntegerLattice { half_width: 2 }, 200, 6),
        16,
    );
}

#[test]
fn six_d_traces_replay_to_the_hull() {
    every_strategy(&generate::<6>(&Family::SphereSurface, 250, 7), 17);
    every_strategy(&generate::<6>(&Family::UniformCube, 400, 8), 18);
}

/// A full build whose first phase leaves points on faces as vertices starts again on the
/// extreme ones (`src/hull/coplanar.rs`): the trace records it as a note and a second initial
/// simplex, and still replays to the hull, the same as the untraced build's.
#[test]
fn a_second_phase_is_traced() {
    let points = generate::<3>(&Family::CubeCornersDiamond, 100, 1);
    let (_, (), trace) = traced_run(&points, FarthestPoint::new());
    let notes: Vec<usize> = (0..trace.events.len())
        .filter(|&i| {
            matches!(
                &trace.events[i],
                Event::Note {
                    code: "second-phase",
                    ..
                }
            )
        })
        .collect();
    assert_eq!(notes.len(), 1, "one second phase");
    assert!(matches!(trace.events[notes[0] + 1], Event::Initial { .. }));
    let mut replay = trace.replay();
    while replay.step().is_some() {}
    assert_eq!(replay.vertices().len(), 8, "the cube's corners");
}

/// The square [−1, 1]² given by its corners, of which the input holds three (as in the
/// `PointSource` docs): the fourth is inserted during the run.
#[derive(Clone)]
struct Corners;

impl PointSource<2> for Corners {
    fn beyond(&mut self, hull: &Hull<2>, id: FacetId) -> Option<[f64; 2]> {
        let n = hull.facet(id).normal();
        let corner = [n[0].signum(), n[1].signum()];
        (hull.facet(id).signed_distance(&corner) > 1e-12).then_some(corner)
    }
}

impl pqhull::geometry::Support<2> for Corners {
    fn support_point(&mut self, d: &[f64; 2]) -> Option<[f64; 2]> {
        Some([d[0].signum(), d[1].signum()])
    }
}

#[test]
fn implicit_points_are_recorded_as_insertions() {
    let input = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]];
    let (plain, result, trace) =
        traced_run(&input, ClosestToOrigin::with_source([0.5, 0.0], Corners));
    let (plain, result) = (plain.unwrap(), result.unwrap());
    same_distance(&plain, &result);
    assert!((result.signed_distance - 0.5).abs() < 1e-12);
    let inserted: Vec<_> = trace
        .events
        .iter()
        .filter_map(|e| match e {
            Event::Inserted {
                point, coordinates, ..
            } => Some((*point, *coordinates)),
            _ => None,
        })
        .collect();
    assert_eq!(inserted, vec![(3, [-1.0, 1.0])]);
    assert_eq!(trace.points[3], [-1.0, 1.0]);
    // The insertion is followed by the expansion that adds it.
    let at = trace
        .events
        .iter()
        .position(|e| matches!(e, Event::Inserted { .. }))
        .unwrap();
    assert!(matches!(
        trace.events[at + 1],
        Event::Expanded { point: 3, .. }
    ));
}

#[test]
fn claims_move_points_between_outside_sets() {
    // A point beyond several facets sits in one outside set only, so partial strategies claim
    // before they trust an empty set; the replay must move the claimed points too (checked by
    // `traced_run`). Make sure some run here claims something, or the check is idle.
    let mut claims = 0;
    for seed in 0..6 {
        for family in [
            Family::UniformCube,
            Family::IntegerLattice { half_width: 2 },
        ] {
            let points = generate::<3>(&family, 150, seed);
            for query in [[0.0; 3], [0.2, -0.1, 0.1], [4.0, 0.5, 0.25]] {
                let (_, _, trace) = traced_run(&points, ClosestToOrigin::towards(query));
                claims += trace
                    .events
                    .iter()
                    .filter(|e| matches!(e, Event::Claimed { .. }))
                    .count();
            }
        }
    }
    eprintln!("{claims} claims");
    assert!(claims > 0, "no run claimed anything");
}

#[test]
fn renderers_check_the_dimension() {
    let points = generate::<4>(&Family::UniformCube, 50, 1);
    let (_, (), trace) = Hull::try_with_strategy_traced(&points, FarthestPoint::new()).unwrap();
    assert!(matches!(
        html::trace_page("4-D", &[&trace]),
        Err(VizError::Dimension { dimension: 4, .. })
    ));
    assert!(matches!(
        svg::trace_svgs(&trace),
        Err(VizError::Dimension { .. })
    ));
    assert_eq!(html::trace_page::<2>("none", &[]), Err(VizError::Empty));
    let points = generate::<3>(&Family::UniformCube, 50, 1);
    let (_, (), trace) = Hull::try_with_strategy_traced(&points, FarthestPoint::new()).unwrap();
    assert!(
        svg::trace_svgs(&trace).is_err(),
        "SVG pictures are 2-D only"
    );
}
