//! Reading point sets from text: one point per line.
//!
//! The format, as written by hand, by spreadsheets and by Qhull's `rbox` (without its header):
//!
//! * one point per line; its coordinates are separated by commas and/or whitespace
//!   (`1.5, -2, 3e-4`, `1.5 -2 3e-4` and `1.5,-2 , 3e-4` are the same point);
//! * `#` starts a comment, on its own line or after a point;
//! * blank lines (and comment-only lines) are ignored; `\n`, `\r\n` and lone `\r` (old Mac)
//!   line endings all work, and line numbers count each;
//! * the dimension is the number of coordinates on the first data row; every other row must have
//!   as many;
//! * numbers are Rust `f64` literals (`1`, `-0.5`, `.5`, `1e-3`, `+2`); `nan`, `inf` and numbers
//!   that overflow to infinity are rejected.
//!
//! Every error names the (1-based) line it was found on.
//!
//! ```
//! use pqhull_cli::points_file::parse_points;
//!
//! let table = parse_points("# unit square\n0 0\n1, 0\n1 1  # top right\n\n0,1\n").unwrap();
//! assert_eq!(table.dimension(), 2);
//! assert_eq!(table.len(), 4);
//! assert_eq!(table.row(2), &[1.0, 1.0]);
//! assert_eq!(table.line(2), 4);
//! assert_eq!(table.to_arrays::<2>().unwrap()[3], [0.0, 1.0]);
//!
//! let err = parse_points("0 0 0\n1 1\n").unwrap_err();
//! assert_eq!(err.to_string(), "line 2: expected 3 coordinates (from line 1), found 2");
//! ```

use std::fmt;
use std::str::FromStr;

/// A parsed point set: `len()` rows of `dimension()` coordinates, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct PointTable {
    dimension: usize,
    coords: Vec<f64>,
    lines: Vec<usize>,
}

impl PointTable {
    /// Number of coordinates of each point (at least 1).
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    /// Whether there are no points (never true for a table returned by [`parse_points`]).
    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
    }

    /// All coordinates, row-major: point `i` is `coords()[i * dimension() .. (i + 1) * dimension()]`.
    pub fn coords(&self) -> &[f64] {
        &self.coords
    }

    /// The coordinates of point `i`.
    ///
    /// # Panics
    ///
    /// If `i >= len()`.
    pub fn row(&self, i: usize) -> &[f64] {
        &self.coords[i * self.dimension..(i + 1) * self.dimension]
    }

    /// The points in order.
    pub fn rows(&self) -> impl ExactSizeIterator<Item = &[f64]> + '_ {
        self.coords.chunks_exact(self.dimension)
    }

    /// The (1-based) source line of point `i`.
    ///
    /// # Panics
    ///
    /// If `i >= len()`.
    pub fn line(&self, i: usize) -> usize {
        self.lines[i]
    }

    /// The source line of every point.
    pub fn lines(&self) -> &[usize] {
        &self.lines
    }

    /// The points as fixed-size arrays, or `None` when `D` is not [`PointTable::dimension`].
    pub fn to_arrays<const D: usize>(&self) -> Option<Vec<[f64; D]>> {
        (D == self.dimension).then(|| {
            self.rows()
                .map(|row| std::array::from_fn(|i| row[i]))
                .collect()
        })
    }
}

/// Why a points file could not be read. Every variant but [`ParseError::Empty`] carries the
/// 1-based line number.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ParseError {
    /// The input has no data rows (only blank lines and comments, or nothing).
    Empty,
    /// A row has a different number of coordinates than the first one.
    WrongLength {
        /// The offending line.
        line: usize,
        /// The number of coordinates of the first row.
        expected: usize,
        /// The line of the first row.
        first_line: usize,
        /// The number of coordinates on this line.
        found: usize,
    },
    /// A field between commas is empty (`1,,2` or a trailing comma).
    EmptyField {
        /// The offending line.
        line: usize,
        /// 1-based position of the empty field on the line.
        column: usize,
    },
    /// A token is not a number.
    NotANumber {
        /// The offending line.
        line: usize,
        /// 1-based coordinate position of the token on the line.
        column: usize,
        /// The token as written.
        token: String,
    },
    /// A coordinate is NaN or infinite (written so, or overflowing `f64`).
    NonFinite {
        /// The offending line.
        line: usize,
        /// 1-based coordinate position on the line.
        column: usize,
        /// The token as written.
        token: String,
    },
}

impl ParseError {
    /// The 1-based line of the error (`None` for [`ParseError::Empty`]).
    pub fn line(&self) -> Option<usize> {
        match self {
            ParseError::Empty => None,
            ParseError::WrongLength { line, .. }
            | ParseError::EmptyField { line, .. }
            | ParseError::NotANumber { line, .. }
            | ParseError::NonFinite { line, .. } => Some(*line),
        }
    }
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParseError::Empty => write!(f, "no points: the input has no data rows"),
            ParseError::WrongLength {
                line,
                expected,
                first_line,
                found,
            } => write!(
                f,
                "line {line}: expected {expected} coordinates (from line {first_line}), found {found}"
            ),
            ParseError::EmptyField { line, column } => {
                write!(
                    f,
                    "line {line}: field {column} is empty (two commas in a row?)"
                )
            }
            ParseError::NotANumber {
                line,
                column,
                token,
            } => write!(
                f,
                "line {line}: coordinate {column} '{token}' is not a number"
            ),
            ParseError::NonFinite {
                line,
                column,
                token,
            } => write!(
                f,
                "line {line}: coordinate {column} '{token}' is not finite (NaN or infinite)"
            ),
        }
    }
}

impl std::error::Error for ParseError {}

/// Parses a points file (see the [module documentation](self) for the format).
pub fn parse_points(text: &str) -> Result<PointTable, ParseError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut parser = Parser::default();
    for chunk in text.split('\n') {
        parser.chunk(chunk)?;
    }
    parser.finish()
}

/// Why a points stream could not be read by [`read_points`].
#[derive(Debug)]
#[non_exhaustive]
pub enum ReadError {
    /// Reading failed, or the input is not UTF-8 (as [`std::io::Read::read_to_string`] reports
    /// it).
    Io(std::io::Error),
    /// The input was read but is not a valid points file.
    Parse(ParseError),
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Io(e) => write!(f, "cannot read: {e}"),
            ReadError::Parse(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for ReadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ReadError::Io(e) => Some(e),
            ReadError::Parse(e) => Some(e),
        }
    }
}

/// Reads and parses a points file from `reader` one line at a time, without holding the text:
/// memory is the table plus the longest line.
///
/// The outcome is that of reading the whole input into a `String` and calling [`parse_points`]:
/// the same table, the same [`ParseError`] (first error, same line numbers), and an I/O error
/// anywhere in the input — invalid UTF-8 included — wins over a parse error, so after a parse
/// error the rest of the input is still read (and checked, not stored).
///
/// ```
/// use pqhull_cli::points_file::{ReadError, read_points};
///
/// let table = read_points("0 0\r\n1, 0\n0 1 # apex\n".as_bytes()).unwrap();
/// assert_eq!((table.dimension(), table.len()), (2, 3));
///
/// let err = read_points("0 0\n1\n".as_bytes()).unwrap_err();
/// assert!(matches!(err, ReadError::Parse(_)));
/// assert_eq!(err.to_string(), "line 2: expected 2 coordinates (from line 1), found 1");
///
/// let err = read_points(&b"0 0\n1 x\n\xff\n"[..]).unwrap_err();
/// assert!(matches!(err, ReadError::Io(_)));
/// assert_eq!(err.to_string(), "cannot read: stream did not contain valid UTF-8");
/// ```
///
/// # Errors
/// [`ReadError::Io`] when reading fails or the input is not UTF-8, else [`ReadError::Parse`].
pub fn read_points<R: std::io::BufRead>(mut reader: R) -> Result<PointTable, ReadError> {
    let mut parser = Parser::default();
    let mut failed: Option<ParseError> = None;
    let mut buffer = Vec::new();
    let mut first = true;
    loop {
        buffer.clear();
        if reader
            .read_until(b'\n', &mut buffer)
            .map_err(ReadError::Io)?
            == 0
        {
            break;
        }
        let bytes = buffer.strip_suffix(b"\n").unwrap_or(&buffer);
        // `\n` never occurs inside a multi-byte character, so the input is UTF-8 exactly when
        // every chunk is.
        let chunk = std::str::from_utf8(bytes).map_err(|_| {
            ReadError::Io(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                "stream did not contain valid UTF-8",
            ))
        })?;
        let chunk = if std::mem::take(&mut first) {
            chunk.strip_prefix('\u{feff}').unwrap_or(chunk)
        } else {
            chunk
        };
        if failed.is_none()
            && let Err(e) = parser.chunk(chunk)
        {
            failed = Some(e);
        }
    }
    match failed {
        Some(e) => Err(ReadError::Parse(e)),
        None => parser.finish().map_err(ReadError::Parse),
    }
}

/// The state of a parse, fed one `\n`-separated chunk of the text at a time.
struct Parser {
    table: PointTable,
    /// The line of the first data row (0 before it).
    first_line: usize,
    /// Lines seen so far.
    line: usize,
    /// The current row's coordinates (reused).
    row: Vec<f64>,
}

impl Default for Parser {
    fn default() -> Self {
        Self {
            table: PointTable {
                dimension: 0,
                coords: Vec::new(),
                lines: Vec::new(),
            },
            first_line: 0,
            line: 0,
            row: Vec::new(),
        }
    }
}

impl Parser {
    /// Parses the text between two `\n` (or an end of the text), which holds one line or, with
    /// lone `\r` line endings, several.
    fn chunk(&mut self, chunk: &str) -> Result<(), ParseError> {
        // `\n` and `\r\n` end lines; so does a lone `\r`, which `str::lines` would leave inside
        // a line (whitespace to the number parser: every point on one row).
        for raw in chunk.strip_suffix('\r').unwrap_or(chunk).split('\r') {
            self.line += 1;
            self.parse_line(raw)?;
        }
        Ok(())
    }

    fn parse_line(&mut self, raw: &str) -> Result<(), ParseError> {
        let line = self.line;
        let data = raw.split_once('#').map_or(raw, |(data, _)| data).trim();
        if data.is_empty() {
            return Ok(());
        }
        let row = &mut self.row;
        row.clear();
        let mut column = 0;
        for field in data.split(',') {
            let field = field.trim();
            if field.is_empty() {
                return Err(ParseError::EmptyField {
                    line,
                    column: column + 1,
                });
            }
            for token in field.split_whitespace() {
                column += 1;
                let value: f64 = token.parse().map_err(|_| ParseError::NotANumber {
                    line,
                    column,
                    token: token.to_string(),
                })?;
                if !value.is_finite() {
                    return Err(ParseError::NonFinite {
                        line,
                        column,
                        token: token.to_string(),
                    });
                }
                row.push(value);
            }
        }
        let table = &mut self.table;
        if table.lines.is_empty() {
            table.dimension = row.len();
            self.first_line = line;
        } else if row.len() != table.dimension {
            return Err(ParseError::WrongLength {
                line,
                expected: table.dimension,
                first_line: self.first_line,
                found: row.len(),
            });
        }
        table.coords.extend_from_slice(row);
        table.lines.push(line);
        Ok(())
    }

    fn finish(self) -> Result<PointTable, ParseError> {
        if self.table.lines.is_empty() {
            return Err(ParseError::Empty);
        }
        Ok(self.table)
    }
}

impl FromStr for PointTable {
    type Err = ParseError;

    /// Same as [`parse_points`].
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        parse_points(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_line_ending() {
        for text in [
            "0 0\n1 0\n0 1\n",
            "0 0\r\n1 0\r\n0 1\r\n",
            "0 0\r1 0\r0 1\r",
            "0 0\r1 0\n0 1",
        ] {
            let t = parse_points(text).unwrap();
            assert_eq!((t.dimension(), t.len()), (2, 3), "{text:?}");
            assert_eq!(t.lines(), &[1, 2, 3], "{text:?}");
        }
        // Line numbers count lone-CR lines too.
        let err = parse_points("0 0\r1 0\r1 x\r").unwrap_err();
        assert_eq!(err.line(), Some(3));
        // A blank line in CR-LF is one blank line, not two.
        let t = parse_points("0 0\r\n\r\n1 1\r\n").unwrap();
        assert_eq!(t.lines(), &[1, 3]);
    }

    #[test]
    fn separators_comments_and_blank_lines() {
        let text = "\
# header comment
   # indented comment

1 2 3
4,5,6   # trailing comment
 7 ,\t8 , 9
10\t11    12

-1.5e2, +.5 , 3.
";
        let t = parse_points(text).unwrap();
        assert_eq!(t.dimension(), 3);
        assert_eq!(t.len(), 5);
        assert!(!t.is_empty());
        assert_eq!(t.lines(), &[4, 5, 6, 7, 9]);
        assert_eq!(t.row(1), &[4.0, 5.0, 6.0]);
        assert_eq!(t.row(2), &[7.0, 8.0, 9.0]);
        assert_eq!(t.row(4), &[-150.0, 0.5, 3.0]);
        assert_eq!(t.coords().len(), 15);
        assert_eq!(t.rows().len(), 5);
        assert_eq!(t.line(3), 7);
    }

    #[test]
    fn mixed_comma_and_space_on_one_line() {
        let t = parse_points("1 2, 3\n").unwrap();
        assert_eq!(t.row(0), &[1.0, 2.0, 3.0]);
    }

    #[test]
    fn crlf_and_bom_and_no_final_newline() {
        let t = parse_points("\u{feff}1,2\r\n# c\r\n3 4\r\n\r\n5 6").unwrap();
        assert_eq!(t.coords(), &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        assert_eq!(t.lines(), &[1, 3, 5]);
        // A lone CR (old Mac) at the end of a row is whitespace.
        let t = parse_points("1 2\r").unwrap();
        assert_eq!(t.coords(), &[1.0, 2.0]);
    }

    #[test]
    fn to_arrays_checks_the_dimension() {
        let t: PointTable = "1 2\n3 4\n".parse().unwrap();
        assert_eq!(t.to_arrays::<2>(), Some(vec![[1.0, 2.0], [3.0, 4.0]]));
        assert_eq!(t.to_arrays::<3>(), None);
    }

    #[test]
    fn one_dimensional_rows_are_fine_here() {
        let t = parse_points("1\n2\n").unwrap();
        assert_eq!(t.dimension(), 1);
    }

    #[test]
    fn wrong_length_names_both_lines() {
        let e = parse_points("# c\n\n1 2 3\n4 5 6\n\n7 8\n").unwrap_err();
        assert_eq!(
            e,
            ParseError::WrongLength {
                line: 6,
                expected: 3,
                first_line: 3,
                found: 2
            }
        );
        assert_eq!(e.line(), Some(6));
        assert_eq!(
            e.to_string(),
            "line 6: expected 3 coordinates (from line 3), found 2"
        );
        let e = parse_points("1 2\n3 4 5\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 2: expected 2 coordinates (from line 1), found 3"
        );
    }

    #[test]
    fn not_a_number_names_line_and_token() {
        let e = parse_points("1 2\n3 abc\n").unwrap_err();
        assert_eq!(
            e,
            ParseError::NotANumber {
                line: 2,
                column: 2,
                token: "abc".into()
            }
        );
        assert_eq!(e.to_string(), "line 2: coordinate 2 'abc' is not a number");
        // Semicolons are not separators.
        let e = parse_points("1;2\n").unwrap_err();
        assert!(e.to_string().contains("'1;2'"), "{e}");
        // Hex and thousands separators are not numbers.
        assert!(matches!(
            parse_points("0x10 1\n"),
            Err(ParseError::NotANumber { .. })
        ));
    }

    #[test]
    fn non_finite_values_are_rejected() {
        for (text, token) in [
            ("1 2\n3 nan\n", "nan"),
            ("1 2\n3 NaN\n", "NaN"),
            ("1 2\n3 inf\n", "inf"),
            ("1 2\n3 -infinity\n", "-infinity"),
            ("1 2\n3 1e400\n", "1e400"),
        ] {
            let e = parse_points(text).unwrap_err();
            assert_eq!(
                e,
                ParseError::NonFinite {
                    line: 2,
                    column: 2,
                    token: token.into()
                }
            );
            assert!(e.to_string().starts_with("line 2: "), "{e}");
        }
    }

    #[test]
    fn empty_fields_are_rejected() {
        let e = parse_points("1,,2\n").unwrap_err();
        assert_eq!(e, ParseError::EmptyField { line: 1, column: 2 });
        assert_eq!(e.line(), Some(1));
        let e = parse_points("0 0\n1,2,\n").unwrap_err();
        assert_eq!(e, ParseError::EmptyField { line: 2, column: 3 });
        assert!(e.to_string().starts_with("line 2: "));
    }

    #[test]
    fn empty_input_is_an_error() {
        for text in ["", "\n\n", "# only a comment\n   \n# another\r\n"] {
            let e = parse_points(text).unwrap_err();
            assert_eq!(e, ParseError::Empty);
            assert_eq!(e.line(), None);
            assert_eq!(e.to_string(), "no points: the input has no data rows");
        }
    }

    /// `read_points` on a stream gives exactly what `parse_points` gives on the whole text.
    #[test]
    fn reading_a_stream_is_parsing_the_text() {
        let texts = [
            "0 0\n1 0\n0 1\n",
            "0 0\r\n1 0\r\n0 1\r\n",
            "0 0\r1 0\r0 1\r",
            "0 0\r1 0\n0 1",
            "0 0\r\n\r\n1 1\r\n",
            "\u{feff}1,2\r\n# c\r\n3 4\r\n\r\n5 6",
            "1 2\r",
            "# c\n\n1 2 3\n4 5 6\n\n7 8\n",
            "0 0\r1 0\r1 x\r",
            "1 2\n3 abc\n",
            "1 2\n3 1e400\n",
            "0 0\n1,2,\n",
            "",
            "\n\n",
            "# only a comment\n   \n# another\r\n",
            "\u{feff}",
            "1 2\n\u{feff}3 4\n",
        ];
        for text in texts {
            let whole = parse_points(text);
            // A one-byte buffer splits every read, a large one reads everything at once.
            for capacity in [1, 3, 1 << 16] {
                let streamed =
                    read_points(std::io::BufReader::with_capacity(capacity, text.as_bytes()));
                match (&whole, streamed) {
                    (Ok(a), Ok(b)) => assert_eq!(*a, b, "{text:?}"),
                    (Err(a), Err(ReadError::Parse(b))) => assert_eq!(*a, b, "{text:?}"),
                    (a, b) => panic!("{text:?}: {a:?} but streamed {b:?}"),
                }
            }
        }
    }

    #[test]
    fn a_read_error_anywhere_wins_over_a_parse_error() {
        // Invalid UTF-8 after a parse error: the text could not have been read whole either.
        for bytes in [&b"0 0\n1 x\n\xff\n"[..], b"\xff 0\n", b"0 0\n1 1\n2 \xc3"] {
            let err = read_points(bytes).unwrap_err();
            assert!(
                matches!(&err, ReadError::Io(e) if e.kind() == std::io::ErrorKind::InvalidData),
                "{err:?}"
            );
            // The message is the standard library's for `read_to_string` on such input.
            let mut text = String::new();
            let std_err = std::io::Read::read_to_string(&mut &bytes[..], &mut text).unwrap_err();
            assert_eq!(err.to_string(), format!("cannot read: {std_err}"));
        }
        // An I/O error after some good lines and a bad one.
        struct Failing<'a>(&'a [u8]);
        impl std::io::Read for Failing<'_> {
            fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
                if self.0.is_empty() {
                    return Err(std::io::Error::other("disk on fire"));
                }
                std::io::Read::read(&mut self.0, buf)
            }
        }
        let err = read_points(std::io::BufReader::new(Failing(b"0 0\n1 x\n"))).unwrap_err();
        assert!(matches!(err, ReadError::Io(_)), "{err:?}");
        assert_eq!(err.to_string(), "cannot read: disk on fire");
        assert!(std::error::Error::source(&err).is_some());
        // A parse error is reported as itself.
        let err = read_points(&b"0 0\n1 x\n"[..]).unwrap_err();
        assert_eq!(err.to_string(), "line 2: coordinate 2 'x' is not a number");
    }

    #[test]
    fn error_trait_object() {
        let e: Box<dyn std::error::Error> = Box::new(ParseError::Empty);
        assert!(!e.to_string().is_empty());
    }
}
