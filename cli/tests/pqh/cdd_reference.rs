//! pqhull's exact hull against an independent exact one, cddlib's (`scdd_gmp`, GMP rationals),
//! on the caller's data where Qhull is no reference: the raw grasp sets of `pqh bench hull`,
//! whose contacts' wrenches are coplanar only up to rounding (docs/benchmarks.md, "An exact
//! reference: cddlib"), and on degenerate families (a grid, clusters, a lattice, cube corners, a
//! thin shell, the faces of a rotated cube). The comparison is `pqhull_cli::bench::cdd::compare`: every input point
//! evaluated exactly against every one of cddlib's inequalities, every simplex of pqhull's hull
//! on one of cddlib's facets, every such facet holding a simplex.
//!
//! They need cddlib's programs, so they are `#[ignore]`d: the README's test command lists them
//! as skipped, and CI (which installs `libcdd-tools`) runs them with `--run-ignored all`, where a
//! missing program is a failure. `PQHULL_SCDD` names another `scdd_gmp`.

use pqhull::Hull;
use pqhull_cli::bench::cdd::{Agreement, compare, run_scdd, scdd_program};
use pqhull_cli::bench::hull::grasp_points;
use std::path::PathBuf;

/// pqhull's hull of `points` (checked) and cddlib's compared; asserts that they agree.
fn same_as_cddlib<const D: usize>(points: &[[f64; D]], name: &str) -> Agreement {
    let hull = Hull::try_new(points).unwrap();
    hull.check().unwrap();
    let scratch = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cdd-tests")
        .join(name);
    let reference = run_scdd(points, &scdd_program(), &scratch).unwrap_or_else(|e| panic!("{e}"));
    let agreement = compare(&hull, points, &reference);
    assert!(agreement.agrees(), "{name}: {agreement:?}");
    agreement
}

/// The suite's grasp set agrees with cddlib, and Qhull's triangulated answer (with the `qhull`
/// feature) has fewer simplices than the exact hull has facet hyperplanes: it cannot be the
/// exact hull, whose every facet holds at least one simplex of any triangulation.
fn grasp_set_agrees_with_cddlib(contacts: usize, edges: usize, full_sum: bool, name: &str) {
    let (_, force_closure, points) = grasp_points(1, contacts, edges, full_sum);
    assert!(force_closure);
    let agreement = same_as_cddlib(&points, name);
    // Non-simplicial facets: the flat ridges of the raw sets are real.
    assert!(agreement.simplices > agreement.cdd_facets, "{agreement:?}");
    qhull_is_not_the_exact_hull(&points, &agreement, name);
}

/// With the `qhull` feature: Qhull's triangulated answer on `points` has fewer simplices than
/// cddlib's exact hull has facet hyperplanes, so it cannot be the exact hull, whose every facet
/// holds at least one simplex of any triangulation. Without the feature, nothing to compare.
#[cfg_attr(not(feature = "qhull"), allow(unused_variables))]
fn qhull_is_not_the_exact_hull<const D: usize>(
    points: &[[f64; D]],
    agreement: &Agreement,
    name: &str,
) {
    #[cfg(feature = "qhull")]
    {
        let qhull = pqhull::qhull_baseline::qhull_facet_count(points).unwrap();
        assert!(
            qhull < agreement.cdd_facets,
            "{name}: Qhull {qhull} simplices, the exact hull {} facets",
            agreement.cdd_facets
        );
    }
}

#[test]
#[ignore = "needs cddlib's scdd_gmp (apt-get install libcdd-tools; .ci/run installs it)"]
fn cddlib_and_pqhull_give_the_same_raw_minkowski_sum() {
    // 3 contacts × 4 edges: 64 points, 3,413 facets; cddlib takes about 7 s.
    grasp_set_agrees_with_cddlib(3, 4, true, "minkowski-3x4");
}

#[test]
#[ignore = "needs cddlib's scdd_gmp (apt-get install libcdd-tools; .ci/run installs it)"]
fn cddlib_and_pqhull_give_the_same_raw_wrench_hull() {
    // 4 contacts × 8 edges: 32 points, 1,192 facets; cddlib takes about 2 s.
    grasp_set_agrees_with_cddlib(4, 8, false, "wrenches-4x8");
}

#[test]
#[ignore = "needs cddlib's scdd_gmp (apt-get install libcdd-tools; .ci/run installs it)"]
fn cddlib_and_pqhull_agree_on_degenerate_families() {
    use pqhull::rbox::{Family, generate};
    // The grid where Qhull reports a vertex that is not one (docs/benchmarks.md): the 5-cube.
    let grid = pqhull_cli::bench::hull::grid::<5>(5);
    assert_eq!(same_as_cddlib(&grid, "grid-5d").cdd_facets, 10);
    // Tight clusters, where Qhull drops extreme points (tests/qhull_crosscheck.rs).
    let clusters = Family::Clusters {
        clusters: 0,
        spread: 1e-12,
    };
    same_as_cddlib(&generate::<3>(&clusters, 400, 1), "clusters-3d");
    let lattice = Family::IntegerLattice { half_width: 3 };
    same_as_cddlib(&generate::<4>(&lattice, 1000, 1), "lattice-4d");
    // Corners, face centres and inside points: the 6-cube.
    let corners = generate::<6>(&Family::CubeCornersDiamond, 20, 1);
    assert_eq!(same_as_cddlib(&corners, "corners-6d").cdd_facets, 12);
    let shell = Family::ThinShell { width: 1e-13 };
    same_as_cddlib(&generate::<4>(&shell, 200, 1), "shell-4d");
    // The faces of a rotated cube, coplanar only up to rounding: the exact hull has a vertex
    // for every face point that rounding put outside, and Qhull (with the `qhull` feature)
    // merges each face into far fewer simplices than the exact hull has facets.
    fn tilted<const D: usize>(n: usize, name: &str) {
        let points = generate::<D>(&Family::TiltedFaces, n, 1);
        let agreement = same_as_cddlib(&points, name);
        // Far more facets than the cube's 2D: the faces are not flat.
        assert!(agreement.cdd_facets > 10 * D, "{name}: {agreement:?}");
        qhull_is_not_the_exact_hull(&points, &agreement, name);
    }
    tilted::<3>(400, "tilted-3d");
    tilted::<4>(200, "tilted-4d");
}
