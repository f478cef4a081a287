//! Benchmark workloads, their timing harness and statistics: what `pqh bench gws`,
//! `pqh bench ows`, `pqh bench hull` and `pqh compare` measure, as plain reports a program can
//! read (and `to_json` for the documents the CLI prints).
//!
//! * [`workloads`] — the seeded inputs: random grasps on a bar and on a mesh's surface, point
//!   sets on a sphere and in a cube, a grasp's wrench set.
//! * [`gws`] — Q1 by every method on the same grasps, Q∞ by the partial hull, batch throughput
//!   in thread pools of several sizes ([`batch`]).
//! * [`ows`] — Q_OWS by every method against Q1.
//! * [`compare`] — the full hull against the partial hull on the point sets.
//! * [`hull`] — the hull suite: pqhull's full hull against Qhull on `rbox` families, integer
//!   grids and grasp wrench sets.
//! * [`census`] — how hard a finished hull's ridges are to decide, in exact arithmetic.
//! * [`cdd`] — an independent exact reference: cddlib's facets of the same points.
//! * [`stats`] — medians, means, ratios and quantiles.
//!
//! Times are wall clock on whatever else the machine is doing: compare rows of one run. Long
//! runs report their progress through a [`Progress`] callback.
//!
//! ```
//! use pqhull_cli::bench::compare::compare_sets;
//! use pqhull_cli::bench::stats::median;
//!
//! let report = compare_sets::<3>(300, 7)?;
//! assert!(report.agrees());
//! let mut facets: Vec<f64> =
//!     report.rows.iter().map(|r| r.partial_stats.facets_created as f64).collect();
//! assert!(median(&mut facets) > 0.0);
//! # Ok::<(), pqhull_cli::bench::compare::CompareError>(())
//! ```

pub mod batch;
pub mod cdd;
pub mod census;
pub mod compare;
pub mod gws;
pub mod hull;
pub mod ows;
pub mod perturb;
pub mod runs;
pub mod stats;
pub mod workloads;

/// Progress of a long measurement: called with the current phase's label (a method's name),
/// the items done and the items in the phase — with 0 done when a phase starts, then after each
/// item. A command-line tool drives a progress bar with it; `&mut |_, _, _| {}` ignores it.
pub type Progress<'a> = &'a mut dyn FnMut(&str, usize, usize);
