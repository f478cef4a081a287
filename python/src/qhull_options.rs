//! The `qhull_options` string of `ConvexHull`, as scipy.spatial.ConvexHull takes it.
//!
//! The hull is exact, so the options with which Qhull copes with its own rounding (merging,
//! joggling, thresholds, the order it processes points in) have nothing to tune: they are
//! accepted and ignored. `Qc` and `Qi` fill `coplanar`, `QGn` / `QG-n` fill `good`. Anything
//! else (options that change the answer: scaling, rotation, Delaunay options, other good-facet
//! rules, the qhull program's print and output formats) is refused with a message naming it.

/// What a `qhull_options` string asks of the hull.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// `Qc`: list the input points on the boundary that are not vertices in `coplanar`.
    pub coplanar: bool,
    /// `Qi`: list the input points strictly inside the hull in `coplanar`.
    pub interior: bool,
    /// `QGn` / `QG-n`.
    pub good: Option<Good>,
    /// Whether `good` is reported: scipy fills it when an option contains `QG`.
    pub report_good: bool,
    /// Options scipy refuses in incremental mode (`Qbb`), as given.
    pub not_incremental: Vec<String>,
}

/// `QGn` (`visible`) or `QG-n`: point `point` is left out of the hull, and a facet is good when
/// it is visible from the point (strictly beyond its plane), or for `QG-n` when it is not.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Good {
    /// The point's index in `points`.
    pub point: usize,
    /// `QGn` (true) or `QG-n` (false).
    pub visible: bool,
}

/// Parses `text` (options separated by white space); an error names the offending option.
pub fn parse(text: &str) -> Result<Options, String> {
    let mut options = Options::default();
    for token in text.split_whitespace() {
        parse_token(token, &mut options)?;
        if token.contains("QG") {
            options.report_good = true;
        }
    }
    Ok(options)
}

/// Why an option that Qhull knows is refused.
fn refused(token: &str, why: &str) -> String {
    format!("qhull_options: '{token}' is not supported by pqhull.ConvexHull: {why}")
}

fn parse_token(token: &str, options: &mut Options) -> Result<(), String> {
    let mut chars = token.chars();
    let Some(first) = chars.next() else {
        return Ok(());
    };
    let rest = chars.as_str();
    match first {
        'Q' => parse_q(token, rest, options),
        // Tv: verify the output; Tc: check frequently. Nothing to verify in an exact hull.
        'T' if rest == "v" || rest == "c" => Ok(()),
        'T' => Err(refused(
            token,
            "Qhull's trace and statistics options have no counterpart (Tv and Tc are accepted)",
        )),
        // Pp: no precision warnings; Po: output despite precision errors. There are none.
        'P' if rest == "p" || rest == "o" => Ok(()),
        'P' => Err(refused(
            token,
            "it selects what the qhull program prints (Pp and Po are accepted)",
        )),
        // Precision thresholds: centrum and angle merging (C-n, Cn, A-n, An), maximum roundoff
        // (En), random roundoff (Rn), coplanar, visible and outside distances (Un, Vn, Wn).
        'C' | 'A' | 'E' | 'R' | 'U' | 'V' | 'W' => match number(rest) {
            Some(("", _)) => Ok(()),
            _ => Err(format!(
                "qhull_options: '{token}' needs a number after '{first}' (as Qhull's '{first}n')"
            )),
        },
        // FA: compute the total area and volume (always done).
        'F' if rest == "A" => Ok(()),
        'F' | 'G' | 'f' | 'i' | 'm' | 'n' | 'o' | 'p' | 's' => Err(refused(
            token,
            "an output format of the qhull program; the attributes are the output",
        )),
        'd' | 'v' | 'H' => Err(refused(
            token,
            "another Qhull mode (Delaunay, Voronoi or halfspaces)",
        )),
        _ => Err(format!("qhull_options: unknown Qhull option '{token}'")),
    }
}

/// The letters after a `Q`: Qhull reads several in one word (`Qci`).
fn parse_q(token: &str, mut rest: &str, options: &mut Options) -> Result<(), String> {
    if rest.is_empty() {
        return Err(format!("qhull_options: unknown Qhull option '{token}'"));
    }
    while let Some(c) = rest.chars().next() {
        rest = &rest[c.len_utf8()..];
        match c {
            // Qt triangulated output (always), Qx exact pre-merges, Qs search all points for
            // the initial simplex, Qv test vertex neighbours, Qw allow warnings, Qf partition to
            // the farthest facet, Qm only points that widen the hull, Qr random order, Qa allow
            // any point count: how Qhull works or copes with rounding, not which hull it is.
            't' | 'x' | 's' | 'v' | 'w' | 'f' | 'm' | 'r' | 'a' => {}
            'c' => options.coplanar = true,
            'i' => options.interior = true,
            'b' if rest.starts_with('b') => {
                // Qbb scales the last coordinate for Delaunay's paraboloid.
                rest = &rest[1..];
                options.not_incremental.push("Qbb".to_string());
            }
            'b' | 'B' => {
                return Err(refused(
                    token,
                    "it scales the input, and Qhull then reports the hull of the scaled points \
                     (Qbb is accepted)",
                ));
            }
            'J' => {
                // Joggle (QJ, QJn): the exact hull is what the joggle approximates.
                if let Some((after, _)) = number(rest) {
                    rest = after;
                }
            }
            'G' => {
                let (visible, digits) = match rest.strip_prefix('-') {
                    Some(after) => (false, after),
                    None => (true, rest),
                };
                let end = digits
                    .find(|c: char| !c.is_ascii_digit())
                    .unwrap_or(digits.len());
                let point = digits[..end]
                    .parse::<usize>()
                    .map_err(|_| format!("qhull_options: '{token}' needs a point index (QGn)"))?;
                if options.good.is_some() {
                    return Err(format!(
                        "qhull_options: '{token}': a good point (QGn) is already given"
                    ));
                }
                options.good = Some(Good { point, visible });
                rest = &digits[end..];
            }
            '0'..='9' => {
                let digits = &format!("{c}{rest}");
                let end = digits
                    .find(|c: char| !c.is_ascii_digit())
                    .unwrap_or(digits.len());
                // Q0 to Q12 and Q14: Qhull's merging and partitioning switches.
                match digits[..end].parse::<u32>() {
                    Ok(0..=12 | 14) => rest = &rest[end - 1..],
                    _ => {
                        return Err(format!(
                            "qhull_options: unknown Qhull option 'Q{}' (in '{token}')",
                            &digits[..end]
                        ));
                    }
                }
            }
            'z' | 'u' => {
                return Err(refused(
                    token,
                    "a Delaunay option (scipy's ConvexHull refuses it too)",
                ));
            }
            'g' => return Err(refused(token, "Qhull would build only the good facets")),
            'V' => {
                return Err(refused(
                    token,
                    "good facets by vertex are not supported (QGn and QG-n are)",
                ));
            }
            'R' => return Err(refused(token, "it rotates the input at random")),
            _ => {
                return Err(format!(
                    "qhull_options: unknown Qhull option 'Q{c}' (in '{token}')"
                ));
            }
        }
    }
    Ok(())
}

/// A number at the start of `s` (Qhull's: sign, digits, fraction, exponent): what follows it
/// and its value.
fn number(s: &str) -> Option<(&str, f64)> {
    let bytes = s.as_bytes();
    let mut end = 0;
    if matches!(bytes.first(), Some(b'-' | b'+')) {
        end += 1;
    }
    let digits = |from: usize| {
        bytes[from..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count()
    };
    let whole = digits(end);
    end += whole;
    let mut fraction = 0;
    if bytes.get(end) == Some(&b'.') {
        fraction = digits(end + 1);
        end += 1 + fraction;
    }
    if whole + fraction == 0 {
        return None;
    }
    if matches!(bytes.get(end), Some(b'e' | b'E')) {
        let mut at = end + 1;
        if matches!(bytes.get(at), Some(b'-' | b'+')) {
            at += 1;
        }
        let exponent = digits(at);
        if exponent > 0 {
            end = at + exponent;
        }
    }
    s[..end].parse().ok().map(|value| (&s[end..], value))
}
