//! The suite's generated inputs that are not `rbox` families: integer grids and the grasp
//! layer's wrench sets (raw wrenches, materialised Minkowski sums) of one seeded bar grasp.

use super::GRASP_CANDIDATES;
use crate::bench::workloads::{BAR_FRICTION, bar_grasps};
use pqhull::grasp::{Evaluator, FrictionModel, Grasp, Method, Metric};

/// Every point of `{0, …, side − 1}^D`, last coordinate fastest.
///
/// ```
/// use pqhull_cli::bench::hull::grid;
/// let g = grid::<2>(3);
/// assert_eq!(g.len(), 9);
/// assert_eq!((g[0], g[1], g[8]), ([0.0, 0.0], [0.0, 1.0], [2.0, 2.0]));
/// ```
pub fn grid<const D: usize>(side: usize) -> Vec<[f64; D]> {
    let count = (0..D).try_fold(1usize, |n, _| n.checked_mul(side));
    let count = count.expect("grid: side^D overflows usize");
    (0..count)
        .map(|mut i| {
            let mut p = [0.0; D];
            for x in p.iter_mut().rev() {
                *x = (i % side) as f64;
                i /= side;
            }
            p
        })
        .collect()
}

/// The materialised Minkowski sum of `grasp`'s contact wrench sets ([`Grasp::contact_wrenches`],
/// no zero wrench): one point per choice of one wrench per contact, `w_0(j_0) + w_1(j_1) + …`
/// summed in contact order, choices in odometer order (the last contact's fastest).
///
/// ```
/// use pqhull_cli::bench::hull::minkowski_sum;
/// use pqhull_cli::bench::workloads::{BAR_FRICTION, bar_grasps};
/// use pqhull::grasp::FrictionModel;
/// let friction = FrictionModel::try_new(BAR_FRICTION, 4)?;
/// let grasp = &bar_grasps(1, 1, 3, friction)[0];
/// let sum = minkowski_sum(grasp);
/// assert_eq!(Some(sum.len()), grasp.minkowski_points(false)); // 4^3
/// # Ok::<(), pqhull::grasp::GraspError>(())
/// ```
pub fn minkowski_sum(grasp: &Grasp) -> Vec<[f64; 6]> {
    let sets: Vec<Vec<[f64; 6]>> = (0..grasp.contact_count())
        .map(|i| {
            let mut set = vec![[0.0; 6]; grasp.contact_wrench_count(i)];
            grasp.contact_wrenches(i, &mut set);
            set
        })
        .collect();
    let mut out: Vec<[f64; 6]> = vec![[0.0; 6]];
    for set in &sets {
        out = out
            .iter()
            .flat_map(|partial| {
                set.iter()
                    .map(move |w| std::array::from_fn(|c| partial[c] + w[c]))
            })
            .collect();
    }
    out
}

/// The first of [`GRASP_CANDIDATES`] random bar grasps of `contacts` fingers and `edges` cone
/// edges whose Q1 (partial method) is force closure — and, with `full_sum`, whose plain
/// Minkowski sum spans 6-D (`sum_spans_6d`, private) — and `true`; the first grasp and `false` when
/// none is. Public for the profiling example (`cli/examples/profile_hull.rs`).
pub fn grasp_for(seed: u64, contacts: usize, edges: usize, full_sum: bool) -> (Grasp, bool) {
    let friction = FrictionModel::try_new(BAR_FRICTION, edges).expect("the suite's cone edges");
    let grasps = bar_grasps(seed, GRASP_CANDIDATES, contacts, friction);
    let mut evaluator =
        Evaluator::new(Metric::Q1, Method::Partial, None).expect("Q1 by the partial method");
    match grasps.iter().position(|g| {
        (!full_sum || sum_spans_6d(g)) && evaluator.evaluate(g).is_ok_and(|q| q.force_closure)
    }) {
        Some(i) => (grasps[i].clone(), true),
        None => (grasps[0].clone(), false),
    }
}

/// The point set of a grasp row of the suite: the raw wrenches of [`grasp_for`]'s grasp, or with
/// `full_sum` their materialised Minkowski sum ([`minkowski_sum`]); with the grasp and whether it
/// is force closure. Public for the examples that time or check one row alone.
pub fn grasp_points(
    seed: u64,
    contacts: usize,
    edges: usize,
    full_sum: bool,
) -> (Grasp, bool, Vec<[f64; 6]>) {
    let (grasp, closure) = grasp_for(seed, contacts, edges, full_sum);
    let points = if full_sum {
        minkowski_sum(&grasp)
    } else {
        grasp.wrenches()
    };
    (grasp, closure, points)
}

/// Whether the plain Minkowski sum of `grasp`'s contact wrench sets spans 6-D with room to
/// spare: the differences `w_i(j) − w_i(0)` (which span the sum's affine hull) have numerical
/// rank 6 by Gaussian elimination with complete pivoting, every pivot above `1e−6` of the first.
/// On the bar, three contacts on faces of one axis fail it exactly (every sum has the same force
/// along that axis), and some others within rounding: sets Qhull refuses as flat and the exact
/// engine hulls as slivers of rounding noise.
fn sum_spans_6d(grasp: &Grasp) -> bool {
    let mut rows: Vec<[f64; 6]> = Vec::new();
    for i in 0..grasp.contact_count() {
        let mut set = vec![[0.0; 6]; grasp.contact_wrench_count(i)];
        grasp.contact_wrenches(i, &mut set);
        rows.extend(
            set[1..]
                .iter()
                .map(|w| std::array::from_fn(|c| w[c] - set[0][c])),
        );
    }
    let mut cols: Vec<usize> = (0..6).collect();
    let mut first = 0.0;
    for step in 0..6 {
        let mut best = (0.0, step, 0);
        for (r, row) in rows.iter().enumerate().skip(step) {
            for (ci, &c) in cols.iter().enumerate().skip(step) {
                if row[c].abs() > best.0 {
                    best = (row[c].abs(), r, ci);
                }
            }
        }
        let (pivot, r, ci) = best;
        if step == 0 {
            first = pivot;
        }
        if pivot <= 1e-6 * first || pivot == 0.0 {
            return false;
        }
        rows.swap(step, r);
        cols.swap(step, ci);
        let (c, top) = (cols[step], rows[step]);
        for row in rows.iter_mut().skip(step + 1) {
            let factor = row[c] / top[c];
            for &k in &cols[step..] {
                row[k] -= factor * top[k];
            }
        }
    }
    true
}
