//! The ridge census (`pqhull_cli::bench::census`): bins against a truth built into the test,
//! and the raw Minkowski sum's census (issue 24's argument for that family: docs/benchmarks.md,
//! "Why the raw sums stay below 1.0").

use pqhull::Hull;
use pqhull_cli::bench::census::{RidgeCensus, ridge_census};
use pqhull_cli::bench::hull::{grasp_for, minkowski_sum};

/// A unit square whose corner (1, 1) is lifted by `lift`, over an apex below it: the top's two
/// triangles meet at a ridge whose determinant is `±lift` with rows of lengths 1, √2 and 1
/// (Hadamard ratio `lift/√2`); the four sides' ridges have ratios near 1.
fn lifted_square(lift: f64) -> RidgeCensus {
    let points = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, lift],
        [0.5, 0.5, -1.0],
    ];
    let hull = Hull::try_new(&points).unwrap();
    let census = ridge_census(&hull);
    assert_eq!(census.ridges, 3 * hull.facet_count() / 2);
    assert_eq!(
        census.zero + census.below_double_double + census.below_double + census.above_double,
        census.ridges
    );
    census
}

#[test]
fn the_census_bins_a_ridge_by_its_known_ratio() {
    let flat = lifted_square(0.0);
    assert_eq!(
        (flat.zero, flat.below_double, flat.below_double_double),
        (1, 0, 0)
    );
    let thin = lifted_square(2f64.powi(-80));
    assert_eq!(
        (thin.zero, thin.below_double, thin.below_double_double),
        (0, 1, 0)
    );
    // ⌊log2(2^−80/√2)⌋ = −81.
    assert_eq!(thin.smallest_log2, -81);
    let thinner = lifted_square(2f64.powi(-120));
    assert_eq!(
        (
            thinner.zero,
            thinner.below_double,
            thinner.below_double_double
        ),
        (0, 0, 1)
    );
    assert_eq!(thinner.smallest_log2, -121);
    assert_eq!(thinner.facets_beyond_double, 2);
    let plain = lifted_square(0.25);
    assert_eq!(plain.above_double, plain.ridges);
}

/// The suite's raw sum of 3 contacts × 6 edges: most of its exact hull's ridges are decided by
/// determinants below double-double's unit roundoff of their rows' product, or exactly zero.
#[test]
fn a_raw_minkowski_sum_is_certified_beyond_double_double() {
    let (grasp, found) = grasp_for(1, 3, 6, true);
    assert!(found, "the suite's grasp");
    let hull = Hull::try_new(&minkowski_sum(&grasp)).unwrap();
    let census = ridge_census(&hull);
    eprintln!("{} facets: {census:?}", hull.facet_count());
    assert_eq!(census.ridges, 3 * hull.facet_count());
    assert!(census.zero > 0);
    assert!(census.below_double_double > census.above_double);
    assert!(census.smallest_log2 < -106);
}
