//! The one thread policy of batch evaluation: how many worker threads a caller may ask for, and
//! how a batch runs on them. `pqh grasp --threads`, `pqh bench gws`'s pools and Python's
//! `threads=` all go through here.

use std::fmt;

/// The most worker threads a batch may ask for.
///
/// Why this bound: a worker per core is all the work can use (the default is rayon's pool, one
/// per available core); 256 is more cores than the machines this runs on have, and every thread
/// costs a stack. Without a bound, asking for 10,000 threads started 10,000 OS threads.
pub const MAX_THREADS: usize = 256;

/// Why a pool of worker threads could not be had.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ThreadsError {
    /// The count is 0 or above [`MAX_THREADS`].
    OutOfRange {
        /// The count asked for.
        threads: usize,
    },
    /// The system would not start the threads.
    Start {
        /// The count asked for.
        threads: usize,
        /// What the thread pool said.
        message: String,
    },
}

impl fmt::Display for ThreadsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ThreadsError::OutOfRange { threads } => {
                write!(
                    f,
                    "{threads} worker threads asked for; the count must be 1 to {MAX_THREADS}"
                )
            }
            ThreadsError::Start { threads, message } => {
                write!(f, "cannot start {threads} threads: {message}")
            }
        }
    }
}

impl std::error::Error for ThreadsError {}

/// Checks a thread count against [`MAX_THREADS`] (and 0).
///
/// # Errors
/// [`ThreadsError::OutOfRange`].
pub fn check_threads(threads: usize) -> Result<usize, ThreadsError> {
    if (1..=MAX_THREADS).contains(&threads) {
        Ok(threads)
    } else {
        Err(ThreadsError::OutOfRange { threads })
    }
}

/// A pool of `threads` workers, for running several batches on it
/// ([`rayon::ThreadPool::install`]).
///
/// # Errors
/// [`ThreadsError`] for a count out of range or a pool the system cannot start.
#[cfg(feature = "parallel")]
pub fn thread_pool(threads: usize) -> Result<rayon::ThreadPool, ThreadsError> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(check_threads(threads)?)
        .build()
        .map_err(|e| ThreadsError::Start {
            threads,
            message: e.to_string(),
        })
}

/// Runs `work` — typically [`evaluate_batch`](super::evaluate_batch) — on `threads` workers, or on rayon's
/// current pool (all cores) for `None`. Without the `parallel` feature the batch functions run
/// on the calling thread whatever the count (which is still checked).
///
/// ```
/// use pqhull::grasp::{FrictionModel, Grasp, Method, Metric, evaluate_batch, with_threads};
/// use pqhull::geometry::Rng;
/// let mut rng = Rng::new(1);
/// let friction = FrictionModel::try_new(0.5, 8)?;
/// let grasps: Vec<Grasp> =
///     (0..20).map(|_| Grasp::random_on_box(&mut rng, [0.5, 0.2, 0.1], 4, friction)).collect();
/// let values = |threads| -> Result<Vec<(Option<f64>, bool)>, Box<dyn std::error::Error>> {
///     let batch =
///         with_threads(threads, || evaluate_batch(&grasps, Metric::Q1, Method::Partial, None))??;
///     Ok(batch.into_iter().map(|q| q.map(|q| (q.value, q.force_closure))).collect::<Result<_, _>>()?)
/// };
/// assert_eq!(values(Some(2))?, values(None)?); // the same values, whatever the pool
/// assert!(with_threads(Some(0), || ()).is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`ThreadsError`] for a count out of range or a pool the system cannot start.
pub fn with_threads<T: Send>(
    threads: Option<usize>,
    work: impl FnOnce() -> T + Send,
) -> Result<T, ThreadsError> {
    let Some(threads) = threads else {
        return Ok(work());
    };
    #[cfg(feature = "parallel")]
    {
        Ok(thread_pool(threads)?.install(work))
    }
    #[cfg(not(feature = "parallel"))]
    {
        check_threads(threads)?;
        Ok(work())
    }
}
