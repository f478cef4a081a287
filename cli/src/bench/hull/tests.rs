use super::*;
use crate::bench::workloads::{BAR_FRICTION, bar_grasps};
use pqhull::grasp::FrictionModel;

#[test]
fn filters_select_and_refuse() {
    let config = HullBenchConfig {
        preset: Preset::Quick,
        families: vec!["grid".into(), "wrenches".into()],
        dimensions: vec![6],
        ..HullBenchConfig::default()
    };
    let names: Vec<String> = config.cases().unwrap().iter().map(Case::name).collect();
    assert_eq!(names, ["grid-m3", "wrenches-4x8"]);
    let bad = |c: HullBenchConfig| c.cases().unwrap_err();
    assert_eq!(
        bad(HullBenchConfig {
            families: vec!["cubes".into()],
            ..config.clone()
        }),
        HullBenchError::UnknownFamily("cubes".into())
    );
    assert_eq!(
        bad(HullBenchConfig {
            dimensions: vec![9],
            ..config.clone()
        }),
        HullBenchError::Dimension(9)
    );
    assert_eq!(
        bad(HullBenchConfig {
            dimensions: vec![1],
            ..config.clone()
        }),
        HullBenchError::Dimension(1)
    );
    assert_eq!(
        bad(HullBenchConfig {
            dimensions: vec![3],
            families: vec!["minkowski".into()],
            ..config.clone()
        }),
        HullBenchError::NoCases
    );
    assert_eq!(
        bad(HullBenchConfig {
            repeats: 0,
            ..config
        }),
        HullBenchError::Repeats(0)
    );
}

/// 2-D, 7-D and 8-D run only when asked, with every `rbox` family and a grid, and no grasp
/// workload (those are 6-D); by default the suite stays in 3-D to 6-D.
#[test]
fn the_extra_dimensions_run_only_when_asked() {
    assert!(
        cases(Preset::Standard)
            .iter()
            .all(|c| DIMENSIONS.contains(&c.dimension))
    );
    let config = HullBenchConfig {
        preset: Preset::Quick,
        dimensions: vec![8, 2, 7],
        ..HullBenchConfig::default()
    };
    let extra = config.cases().unwrap();
    // In the suite's order: the `rbox` families dimension by dimension, then the grids.
    let dims: Vec<usize> = extra.iter().map(|c| c.dimension).collect();
    let n = Family::ALL.len();
    assert!(
        dims[..3 * n].is_sorted() && dims[3 * n..] == [2, 7, 8],
        "{dims:?}"
    );
    for d in EXTRA_DIMENSIONS {
        let names: Vec<String> = extra
            .iter()
            .filter(|c| c.dimension == d)
            .map(Case::name)
            .collect();
        assert_eq!(names.len(), Family::ALL.len() + 1, "{d}-D: {names:?}");
        assert!(names.last().unwrap().starts_with("grid-m"), "{names:?}");
    }
    assert!(
        extra
            .iter()
            .all(|c| c.family() != "wrenches" && c.family() != "minkowski")
    );
    // One of them measured: pqhull's hull of the 8-D grid (its corners), checked.
    let one = HullBenchConfig {
        families: vec!["grid".into()],
        dimensions: vec![8],
        repeats: 1,
        ..config
    };
    let report = run(&one, &mut |_, _, _| {}).unwrap();
    assert_eq!(report.rows.len(), 1);
    let pqhull = report.rows[0].pqhull.as_ref().unwrap();
    assert_eq!(pqhull.vertices, 256);
    assert_eq!(pqhull.check, Ok(()));
}

#[test]
fn every_family_name_has_cases() {
    let all = cases(Preset::Quick);
    for name in FAMILY_NAMES {
        assert!(all.iter().any(|c| c.family() == name), "{name}");
    }
}

#[test]
fn minkowski_sum_is_every_choice() {
    let friction = FrictionModel::try_new(BAR_FRICTION, 3).unwrap();
    let grasp = &bar_grasps(2, 1, 2, friction)[0];
    let sum = minkowski_sum(grasp);
    let w = grasp.wrenches();
    assert_eq!(sum.len(), 9);
    for (i, p) in sum.iter().enumerate() {
        let (a, b) = (w[i / 3], w[3 + i % 3]);
        assert_eq!(*p, std::array::from_fn(|c| a[c] + b[c]));
    }
}
