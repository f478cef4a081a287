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
            dimensions: vec![7],
            ..config.clone()
        }),
        HullBenchError::Dimension(7)
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
