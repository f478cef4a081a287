//! The statistics the benchmarks report: medians, means, ratios and quantiles of timings.
//!
//! Empty inputs give NaN (or `None`), never a panic: a benchmark whose slow method was switched
//! off still reports the rest.

/// The median of `values`, sorting them in place (by [`f64::total_cmp`]); for an even count, the
/// upper of the two middle values (no averaging, so the median is a measured value). NaN when
/// empty.
///
/// ```
/// use pqhull_cli::bench::stats::median;
/// assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
/// assert_eq!(median(&mut [4.0, 1.0, 3.0, 2.0]), 3.0);
/// assert!(median(&mut []).is_nan());
/// ```
pub fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}

/// [`median`] of a copy of `values` (left in their order).
pub fn median_of(values: &[f64]) -> f64 {
    median(&mut values.to_vec())
}

/// The arithmetic mean; NaN when there are no values.
///
/// ```
/// use pqhull_cli::bench::stats::mean;
/// assert_eq!(mean([1.0, 2.0, 6.0].into_iter()), 3.0);
/// assert!(mean(std::iter::empty()).is_nan());
/// ```
pub fn mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = values.fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    sum / n as f64
}

/// The largest value, 0 when there is none (timings are never negative).
pub fn max_or_zero(values: &[f64]) -> f64 {
    values.iter().copied().fold(0.0, f64::max)
}

/// The smallest value, infinity when there is none.
pub fn min_or_infinity(values: &[f64]) -> f64 {
    values.iter().copied().fold(f64::INFINITY, f64::min)
}

/// `full / partial`, infinity when `partial` is not positive (a method that did no measurable
/// work is infinitely faster, not a division by zero).
///
/// ```
/// use pqhull_cli::bench::stats::ratio;
/// assert_eq!(ratio(6.0, 2.0), 3.0);
/// assert_eq!(ratio(1.0, 0.0), f64::INFINITY);
/// ```
pub fn ratio(full: f64, partial: f64) -> f64 {
    if partial > 0.0 {
        full / partial
    } else {
        f64::INFINITY
    }
}

/// The five-number summary of a sample: nearest-rank quantiles (no interpolation, so every
/// figure is a measured value); `None` when the sample is empty.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quantiles {
    /// The smallest value.
    pub min: Option<f64>,
    /// The value at a quarter of the sorted sample.
    pub q25: Option<f64>,
    /// The value at half of it.
    pub median: Option<f64>,
    /// The value at three quarters.
    pub q75: Option<f64>,
    /// The largest value.
    pub max: Option<f64>,
    /// The sample size.
    pub count: usize,
}

impl Quantiles {
    /// The quantiles of `values` (sorted in place). Quantile `q` is the element at
    /// `round((n − 1)·q)` of the sorted sample.
    ///
    /// ```
    /// use pqhull_cli::bench::stats::Quantiles;
    /// let q = Quantiles::of(&mut [5.0, 1.0, 4.0, 2.0, 3.0]);
    /// assert_eq!((q.min, q.q25, q.median, q.q75, q.max), (Some(1.0), Some(2.0), Some(3.0), Some(4.0), Some(5.0)));
    /// assert_eq!(Quantiles::of(&mut []).median, None);
    /// ```
    pub fn of(values: &mut [f64]) -> Quantiles {
        values.sort_by(f64::total_cmp);
        let at = |q: f64| {
            values
                .get(((values.len() as f64 - 1.0) * q).round() as usize)
                .copied()
        };
        Quantiles {
            min: at(0.0),
            q25: at(0.25),
            median: at(0.5),
            q75: at(0.75),
            max: at(1.0),
            count: values.len(),
        }
    }
}

/// Microseconds in a [`Duration`](std::time::Duration), as the reports give times.
pub fn micros(elapsed: std::time::Duration) -> f64 {
    elapsed.as_secs_f64() * 1e6
}

/// The first non-empty line of an error `message`, at most `limit` characters: Qhull's
/// messages run to pages, and their first line names the error.
///
/// ```
/// use pqhull_cli::bench::stats::first_line;
/// assert_eq!(first_line("\nQH6271 qhull topology error\nWhile executing: ...", 12), "QH6271 qhull");
/// assert_eq!(first_line("", 10), "");
/// ```
pub fn first_line(message: &str, limit: usize) -> String {
    let first = message.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    first.chars().take(limit).collect()
}

/// The shortest of `rounds` timed calls of `run` (at least one), as the comparison examples
/// report an engine's time.
pub fn best_of(rounds: usize, mut run: impl FnMut()) -> std::time::Duration {
    (0..rounds.max(1))
        .map(|_| {
            let started = std::time::Instant::now();
            run();
            started.elapsed()
        })
        .min()
        .unwrap_or_default()
}

/// The `N` optional numeric arguments `args[first..first + N]` of an example's command line,
/// each `defaults[i]` when absent.
///
/// # Errors
/// The first argument that is not a non-negative integer, named.
pub fn numeric_args<const N: usize>(
    args: &[String],
    first: usize,
    defaults: [usize; N],
) -> Result<[usize; N], String> {
    let mut values = defaults;
    for (i, value) in values.iter_mut().enumerate() {
        if let Some(s) = args.get(first + i) {
            *value = s.parse().map_err(|_| format!("not a number: {s}"))?;
        }
    }
    Ok(values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numeric_args_take_defaults_and_name_the_bad_one() {
        let args: Vec<String> = ["set", "7"].iter().map(|s| s.to_string()).collect();
        assert_eq!(numeric_args(&args, 1, [4, 3]), Ok([7, 3]));
        assert_eq!(numeric_args(&args, 2, [4]), Ok([4]));
        let bad: Vec<String> = ["set", "x1"].iter().map(|s| s.to_string()).collect();
        assert_eq!(
            numeric_args(&bad, 1, [4, 3]),
            Err("not a number: x1".to_string())
        );
    }

    #[test]
    fn best_of_runs_every_round_and_at_least_one() {
        let mut calls = 0;
        let _ = best_of(3, || calls += 1);
        assert_eq!(calls, 3);
        let _ = best_of(0, || calls += 1);
        assert_eq!(calls, 4);
    }

    #[test]
    fn empty_samples_give_nan_or_none() {
        assert!(median(&mut []).is_nan());
        assert!(mean(std::iter::empty()).is_nan());
        assert_eq!(max_or_zero(&[]), 0.0);
        assert_eq!(min_or_infinity(&[]), f64::INFINITY);
        let q = Quantiles::of(&mut []);
        assert_eq!(q.count, 0);
        assert!(q.min.is_none() && q.max.is_none());
    }

    #[test]
    fn median_of_leaves_its_input_alone() {
        let values = [3.0, 1.0, 2.0];
        assert_eq!(median_of(&values), 2.0);
        assert_eq!(values, [3.0, 1.0, 2.0]);
    }

    #[test]
    fn quantiles_are_measured_values() {
        let q = Quantiles::of(&mut [0.4, 0.1, 0.3, 0.2]);
        // round(3 · 0.25) = 1, round(1.5) = 2, round(2.25) = 2.
        assert_eq!(q.q25, Some(0.2));
        assert_eq!(q.median, Some(0.3));
        assert_eq!(q.q75, Some(0.3));
        assert_eq!(q.count, 4);
        assert_eq!(ratio(2.0, -1.0), f64::INFINITY);
        assert_eq!(micros(std::time::Duration::from_millis(2)), 2000.0);
    }
}
