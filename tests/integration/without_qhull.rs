//! Stand-ins for the checks against Qhull when the crate is built without the `qhull` feature
//! (whose bindings need libclang): the README's test command then lists each of them as skipped,
//! instead of the cross-checks silently not existing. Built with the feature (as CI does), this
//! file is empty and the real tests run; asked to run without it (`--run-ignored all`), each
//! stand-in fails.
#![cfg(not(feature = "qhull"))]

macro_rules! needs_qhull {
    ($($name:ident: $what:literal),* $(,)?) => {$(
        #[test]
        #[ignore = "needs the `qhull` feature (libclang): --features qhull --run-ignored all (CI does)"]
        fn $name() {
            panic!(concat!($what, " needs the `qhull` feature: cargo nextest run --features qhull"));
        }
    )*};
}

needs_qhull! {
    qhull_crosscheck: "tests/integration/qhull_crosscheck.rs (5 hull and distance cross-checks against Qhull, and Qhull's tight clusters)",
    ows_eq6: "tests/integration/ows_eq6.rs (3 Q_OWS checks against Qhull's full hulls)",
    raw_reference: "tests/integration/raw_reference.rs (6 metric checks against Qhull on the raw wrenches)",
    cli_raw_reference: "cli/tests/pqh/cli_raw_reference.rs (pqh grasp against Qhull)",
    perturbed_sum: "cli/tests/pqh/perturbed_sum.rs (Qhull's answers on the raw and perturbed Minkowski sums, judged exactly)",
    grasp_quality_qhull_comparisons: "the Method::Qhull comparisons inside tests/integration/grasp_quality.rs",
    metrics_resistance_and_volume_equal_qhull: "tests/integration/metrics.rs (wrench resistance and GWS volume against Qhull)",
    soft_q1_equals_qhull_on_the_explicit_soft_wrenches: "tests/integration/soft.rs (soft-finger Q1 against Qhull)",
    soft_qinf_equals_qhull_on_the_explicit_minkowski_sum: "tests/integration/soft.rs (soft-finger Q∞ against Qhull)",
}
