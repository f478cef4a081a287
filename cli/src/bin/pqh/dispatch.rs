//! The one place a run-time dimension becomes a const generic.

/// Evaluates `$body` with `$D` a `const usize` equal to `$dimension`, for each dimension listed
/// (2 to 8 when none is listed), or `$fallback` with `$other` bound to any other value:
///
/// ```ignore
/// with_dimension!(table.dimension(), |D| job.run::<D>(), else |d| Err(unsupported(d)))
/// with_dimension!(input.dimension, [2, 3], |D| trace::<D>(args), else |d| Err(unsupported(d)))
/// ```
macro_rules! with_dimension {
    ($dimension:expr, |$D:ident| $body:expr, else |$other:pat_param| $fallback:expr) => {
        with_dimension!($dimension, [2, 3, 4, 5, 6, 7, 8], |$D| $body, else |$other| $fallback)
    };
    ($dimension:expr, [$($n:literal),+], |$D:ident| $body:expr, else |$other:pat_param| $fallback:expr) => {
        match $dimension {
            $($n => {
                const $D: usize = $n;
                $body
            })+
            $other => $fallback,
        }
    };
}

pub(crate) use with_dimension;
