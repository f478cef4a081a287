//! `pqh hull --json` (written facet by facet since issue 12) against the library's hull: the same
//! vertices, facets, neighbours, planes and answers, whatever the order the facets are listed in,
//! and the document is exactly what serde_json prints for it (sorted keys, compact, shortest
//! round-trip floats).

use crate::support::run::{file, pqh};
use pqhull::rbox::{Family, generate};
use pqhull::{ClosestToOrigin, Hull};
use serde_json::Value;
use std::collections::HashMap;

fn usizes(v: &Value) -> Vec<usize> {
    v.as_array()
        .unwrap_or_else(|| panic!("not an array: {v}"))
        .iter()
        .map(|x| x.as_u64().expect("integer") as usize)
        .collect()
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("not an array: {v}"))
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

/// Writes `points` as a points file (shortest round-trip decimals, so the CLI reads exactly
/// these numbers) and returns its path.
fn points_file<const D: usize>(name: &str, points: &[[f64; D]]) -> String {
    let mut text = String::new();
    for p in points {
        let row: Vec<String> = p.iter().map(f64::to_string).collect();
        text += &row.join(" ");
        text.push('\n');
    }
    file(name, &text).to_str().unwrap().to_string()
}

/// Runs `pqh hull --json ARGS FILE`; checks that stdout is one JSON document followed by a
/// newline, byte for byte as serde_json prints the parsed value; returns the value.
fn hull_json(args: &[&str], path: &str) -> Value {
    let mut all = vec!["hull", "--json"];
    all.extend_from_slice(args);
    all.push(path);
    let o = pqh(&all, None);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{all:?}: {:?}\n{stderr}", o.status);
    assert!(stderr.is_empty(), "{all:?}: {stderr}");
    let text = String::from_utf8(o.stdout).expect("utf-8 stdout");
    let v: Value = serde_json::from_str(&text).expect("stdout is one JSON object");
    // serde_json's Map is a BTreeMap here (no `preserve_order`): keys come back sorted, as the
    // pre-streaming output (a serialised `Value`) had them.
    assert_eq!(text, serde_json::to_string(&v).unwrap() + "\n", "{all:?}");
    v
}

/// Checks the JSON hull `v` against the library's `hull`: vertex set, facet count, and every
/// facet's oriented vertices, plane and neighbours (matched by vertex list, not by position).
fn check_against<const D: usize>(v: &Value, hull: &Hull<D>) {
    assert_eq!(v["dimension"], D);
    assert_eq!(v["points"], hull.point_count());
    assert_eq!(usizes(&v["vertices"]), hull.vertex_indices());
    let facets = v["facets"].as_array().expect("facets");
    assert_eq!(facets.len(), hull.facet_count());

    let json_vertices: Vec<Vec<usize>> = facets.iter().map(|f| usizes(&f["vertices"])).collect();
    let library: HashMap<Vec<usize>, _> = hull
        .facets()
        .map(|(id, f)| (f.vertices().to_vec(), (id, f)))
        .collect();
    assert_eq!(
        library.len(),
        hull.facet_count(),
        "facets with equal vertices"
    );

    for (i, f) in facets.iter().enumerate() {
        let vertices = &json_vertices[i];
        assert_eq!(vertices.len(), D, "facet {i}");
        let (_, facet) = library
            .get(vertices)
            .unwrap_or_else(|| panic!("facet {i} {vertices:?} is not a facet of the hull"));
        // Written with shortest round-trip decimals and read back with float_roundtrip: exact.
        assert_eq!(floats(&f["normal"]), facet.normal().to_vec(), "facet {i}");
        assert_eq!(f["offset"].as_f64(), Some(facet.offset()), "facet {i}");

        let neighbors = usizes(&f["neighbors"]);
        assert_eq!(neighbors.len(), D, "facet {i}");
        for (k, &n) in neighbors.iter().enumerate() {
            assert!(n < facets.len(), "facet {i}: neighbour {n} out of range");
            assert!(
                usizes(&facets[n]["neighbors"]).contains(&i),
                "facet {i} has neighbour {n}, which does not have it"
            );
            // Neighbour k is across the ridge opposite vertex k, and is the library's neighbour k.
            let expected = hull.facet(facet.neighbors()[k]).vertices().to_vec();
            assert_eq!(json_vertices[n], expected, "facet {i}, neighbour {k}");
            for (j, vertex) in vertices.iter().enumerate() {
                assert_eq!(
                    json_vertices[n].contains(vertex),
                    j != k,
                    "facet {i}, neighbour {k}: vertex {vertex}"
                );
            }
        }
    }
}

/// Full hull and closest-to-origin (default origin, an interior and an exterior query point) of
/// `points`, each checked against the library.
fn check_both_strategies<const D: usize>(name: &str, points: &[[f64; D]]) {
    let path = points_file(name, points);

    let v = hull_json(&[], &path);
    let hull = Hull::try_new(points).expect("full hull");
    assert_eq!(v["strategy"], "farthest-point");
    check_against(&v, &hull);
    assert_eq!(v["volume"].as_f64(), Some(hull.volume()));
    let stats = hull.stats();
    assert_eq!(v["stats"]["points_processed"], stats.points_processed);
    assert_eq!(v["stats"]["facets_created"], stats.facets_created);
    assert_eq!(v["stats"]["expansions"], stats.expansions);
    assert!(v["stats"]["elapsed_us"].is_u64());
    assert!(v.get("origin_distance").is_none());

    let mut inside = [0.0; D];
    inside[0] = 0.05;
    let mut outside = [0.1; D];
    outside[0] = -4.0;
    for query in [None, Some(inside), Some(outside)] {
        let text: Option<String> = query.map(|q| {
            let parts: Vec<String> = q.iter().map(f64::to_string).collect();
            parts.join(",")
        });
        let mut args = vec!["--strategy", "closest-to-origin"];
        if let Some(text) = &text {
            args.extend(["--origin", text.as_str()]);
        }
        let v = hull_json(&args, &path);
        let q = query.unwrap_or([0.0; D]);
        let (partial, result) =
            Hull::try_with_strategy(points, ClosestToOrigin::towards(q)).expect("partial hull");
        assert_eq!(v["strategy"], "closest-to-origin");
        check_against(&v, &partial);
        assert!(v.get("volume").is_none());
        assert_eq!(floats(&v["origin"]), q.to_vec());
        assert_eq!(v["origin_distance"].as_f64(), Some(result.signed_distance));
        assert_eq!(floats(&v["nearest_point"]), result.nearest_point.to_vec());
        let closest = usizes(&v["closest_facet"]);
        assert_eq!(closest, result.closest_facet_vertices.to_vec());
        let index = v["closest_facet_index"].as_u64().expect("an index") as usize;
        assert_eq!(usizes(&v["facets"][index]["vertices"]), closest);
        assert_eq!(
            v["stats"]["points_processed"],
            result.stats.points_processed
        );
        assert_eq!(v["stats"]["facets_created"], result.stats.facets_created);
    }
}

#[test]
fn json_hull_agrees_with_the_library_2d() {
    check_both_strategies(
        "square-cloud-2d.txt",
        &generate::<2>(&Family::UniformCube, 300, 1),
    );
    check_both_strategies(
        "circle-2d.txt",
        &generate::<2>(&Family::SphereSurface, 100, 2),
    );
}

#[test]
fn json_hull_agrees_with_the_library_3d() {
    check_both_strategies(
        "sphere-3d.txt",
        &generate::<3>(&Family::SphereSurface, 400, 3),
    );
    // Coplanar corners and face centres: exact predicates, many tied facets.
    check_both_strategies(
        "corners-3d.txt",
        &generate::<3>(&Family::CubeCornersDiamond, 50, 4),
    );
}

#[test]
fn json_hull_agrees_with_the_library_6d() {
    check_both_strategies("cube-6d.txt", &generate::<6>(&Family::UniformCube, 120, 5));
}

#[test]
fn json_hull_agrees_with_the_library_8d() {
    check_both_strategies(
        "sphere-8d.txt",
        &generate::<8>(&Family::SphereSurface, 30, 6),
    );
}
