//! Numbers for people: decimals in the everyday range, an exponent outside it (Rust's `Display`
//! writes 1e200 as 201 digits, and `{:.6}` writes 1e-200 as 0.000000); and the one way a report
//! reaches standard output (its JSON line, or its table).

use std::io::{BufWriter, StdoutLock, Write};

/// The buffered standard output a report's table is printed to.
pub type Out = BufWriter<StdoutLock<'static>>;

/// Writes a report to standard output: one JSON line when `json`, else what `table` prints.
pub fn write_report(
    json: bool,
    to_json: impl FnOnce() -> serde_json::Value,
    table: impl FnOnce(&mut Out) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let mut out = BufWriter::new(std::io::stdout().lock());
    if json {
        writeln!(out, "{}", to_json())?;
    } else {
        table(&mut out)?;
    }
    out.flush()
}

/// Whether `x` reads well as a plain decimal.
fn everyday(x: f64) -> bool {
    x == 0.0 || !x.is_finite() || (1e-4..1e16).contains(&x.abs())
}

/// `x` with its shortest round-trip digits.
pub fn number(x: f64) -> String {
    if everyday(x) {
        x.to_string()
    } else {
        format!("{x:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn exponents_outside_the_everyday_range() {
        assert_eq!(number(1e200), "1e200");
        assert_eq!(number(-2.5e-300), "-2.5e-300");
        assert_eq!(number(0.125), "0.125");
    }
}
