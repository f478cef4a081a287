//! Traces of strategy runs (`pqhull::viz`): replaying the events rebuilds the hull, tracing changes
//! nothing, the stop reason matches the result; and `pqh trace` (errors, no network in the page).

use pqhull::geometry::Rng;
use pqhull::hull::{Event, Trace};
use pqhull::rbox::{Family, generate};
use pqhull::strategy::{DistanceResult, OwsResult, PointSource};
use pqhull::viz::{VizError, html, svg, trace_json};
use pqhull::{ClosestToOrigin, FacetId, FarthestPoint, Hull, OwsInflation, Stats, Strategy};
use std::collections::BTreeSet;
use std::path::PathBuf;
use std::process::{Command, Output};

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
    assert!(ows.is_force_closure());
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
    assert!(!not_closure.is_force_closure());
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

// ---- the `pqh trace` command ----------------------------------------------------------------

fn pqh(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(args)
        .output()
        .expect("run pqh")
}

fn temp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("trace-tests");
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Exit status 2 (or `code`) and one `pqh: ` line on stderr containing `needle`.
fn assert_error(o: &Output, code: i32, needle: &str) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(code), "stderr: {err}");
    assert!(
        err.starts_with("pqh: ") && err.lines().count() == 1,
        "stderr: {err:?}"
    );
    assert!(err.contains(needle), "stderr {err:?} lacks {needle:?}");
}

#[test]
fn malformed_inputs_and_options_are_cli_errors() {
    let out = temp("unused.html");
    let out = out.to_str().unwrap();
    let bad = temp("bad.txt");
    std::fs::write(&bad, "0 0\n1 0\n1 x\n").unwrap();
    let o = pqh(&[
        "trace",
        bad.to_str().unwrap(),
        "--strategy",
        "farthest",
        "--output",
        out,
    ]);
    assert_error(&o, 2, "line 3");

    let four = temp("four.txt");
    std::fs::write(&four, "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n").unwrap();
    let o = pqh(&[
        "trace",
        four.to_str().unwrap(),
        "--strategy",
        "farthest",
        "--output",
        out,
    ]);
    assert_error(&o, 2, "2-D and 3-D");

    let line = temp("line.txt");
    std::fs::write(&line, "0 0\n1 1\n2 2\n3 3\n").unwrap();
    let o = pqh(&[
        "trace",
        line.to_str().unwrap(),
        "--strategy",
        "closest",
        "--output",
        out,
    ]);
    assert_error(&o, 1, "line.txt");

    let usage: [&[&str]; 6] = [
        &["trace", "--strategy", "farthest", "--output", out],
        &[
            "trace",
            "x.txt",
            "--family",
            "cube",
            "--strategy",
            "farthest",
            "--output",
            out,
        ],
        &[
            "trace",
            "--family",
            "cube",
            "--strategy",
            "farthest",
            "--query",
            "0,0",
            "--output",
            out,
        ],
        &[
            "trace",
            "--family",
            "nope",
            "--strategy",
            "farthest",
            "--output",
            out,
        ],
        &[
            "trace",
            "--family",
            "cube",
            "--dimension",
            "5",
            "--strategy",
            "ows",
            "--output",
            out,
        ],
        &[
            "trace",
            "--family",
            "cube",
            "--strategy",
            "closest",
            "--query",
            "1,2",
            "--output",
            out,
        ],
    ];
    for args in usage {
        let o = pqh(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(
            stderr(&o).starts_with("pqh: ") || stderr(&o).contains("error:"),
            "{args:?}"
        );
    }
    let o = pqh(&[
        "trace",
        "--family",
        "cube",
        "--dimension",
        "3",
        "--strategy",
        "farthest",
        "--svg-dir",
        out,
        "--output",
        out,
    ]);
    assert_error(&o, 2, "2-D");
}

/// The page must load nothing: no URL of any scheme but inline data, no external script, style
/// sheet, image or font.
fn assert_no_network(page: &str) {
    let lower = page.to_lowercase();
    for needle in [
        "http://",
        "https://",
        "src=",
        "<link",
        "url(",
        "@import",
        "//cdn",
        "fetch(",
        "xmlhttprequest",
    ] {
        assert!(!lower.contains(needle), "the page contains {needle:?}");
    }
}

#[test]
fn pages_are_self_contained_and_svgs_are_written() {
    let html_path = temp("two-d.html");
    let svg_dir = temp("svg");
    let _ = std::fs::remove_dir_all(&svg_dir);
    let o = pqh(&[
        "trace",
        "--family",
        "sphere",
        "--points",
        "25",
        "--dimension",
        "2",
        "--seed",
        "3",
        "--strategy",
        "closest",
        "--query",
        "0.8,0.1",
        "--compare",
        "ows",
        "--output",
        html_path.to_str().unwrap(),
        "--svg-dir",
        svg_dir.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("(query outside)") && stdout.contains("smallest inflation factor"),
        "{stdout}"
    );
    let page = std::fs::read_to_string(&html_path).unwrap();
    assert_no_network(&page);
    // The embedded data is the traces' JSON, one panel per strategy.
    let start = page.find("id=\"pqhull-data\">").unwrap() + "id=\"pqhull-data\">".len();
    let end = start + page[start..].find("</script>").unwrap();
    let data: serde_json::Value = serde_json::from_str(&page[start..end]).unwrap();
    let panels = data["panels"].as_array().unwrap();
    assert_eq!(panels.len(), 2);
    assert_eq!(panels[0]["trace"]["strategy"], "ClosestToOrigin");
    assert_eq!(panels[1]["trace"]["strategy"], "OwsInflation");
    let files: BTreeSet<String> = std::fs::read_dir(&svg_dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    for (k, panel) in panels.iter().enumerate() {
        let name = ["closest-to-origin", "ows-inflation"][k];
        let steps = panel["trace"]["events"].as_array().unwrap().len();
        let count = files.iter().filter(|f| f.starts_with(name)).count();
        assert_eq!(count, steps, "{name}: one SVG per step");
        let first = std::fs::read_to_string(svg_dir.join(format!("{name}-0000.svg"))).unwrap();
        assert!(first.starts_with("<svg") && first.contains("initial simplex"));
    }

    // A 3-D page from a points file, through standard naming of the library too.
    let points = temp("cube3.txt");
    let text: String = generate::<3>(&Family::UniformCube, 30, 4)
        .iter()
        .map(|p| format!("{} {} {}\n", p[0], p[1], p[2]))
        .collect();
    std::fs::write(&points, text).unwrap();
    let out = temp("three-d.html");
    let o = pqh(&[
        "trace",
        points.to_str().unwrap(),
        "--strategy",
        "farthest",
        "--output",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_no_network(&std::fs::read_to_string(&out).unwrap());
}

#[test]
fn titles_and_text_are_escaped() {
    let points = generate::<2>(&Family::UniformCube, 20, 1);
    let (_, (), trace) = Hull::try_with_strategy_traced(&points, FarthestPoint::new()).unwrap();
    let page = html::trace_page("<script>alert(1)</script>", &[&trace]).unwrap();
    assert!(!page.contains("<script>alert(1)"));
    assert!(page.contains("&lt;script&gt;alert(1)"));
    let mut evil = trace.clone();
    evil.context.strategy = "</script><script>alert(2)</script>".into();
    let page = html::trace_page("t", &[&evil]).unwrap();
    assert!(!page.contains("</script><script>alert(2)"));
}
