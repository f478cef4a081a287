//! Numbers for people: decimals in the everyday range, an exponent outside it (Rust's `Display`
//! writes 1e200 as 201 digits, and `{:.6}` writes 1e-200 as 0.000000).

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
