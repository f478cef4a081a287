//! Grasps as JSON: the format `pqh grasp` takes, and the lines it writes.
//!
//! A grasp is one JSON object
//!
//! ```text
//! {"contacts": [{"position": [x, y, z], "normal": [x, y, z], "tangent": [x, y, z]?,
//!                "torsion": gamma?}, ...],
//!  "friction": mu, "cone_edges": k, "torque_reference": [x, y, z]?, "torque_scale": rho?}
//! ```
//!
//! with inward normals (the direction the finger pushes) and `?` marking optional fields (see
//! [`Contact::try_new`], [`Contact::with_torsion`] for `"torsion"`, a soft finger's torsional
//! friction times its patch radius, absent or 0 for a hard finger, [`FrictionModel::try_new`] and [`GraspBuilder`](super::GraspBuilder) for
//! what each accepts). `cone_edges` is a whole number (`8.0` counts).
//!
//! A document holds one grasp, a JSON array of grasps, or JSON Lines (one grasp per line).
//! [`split_grasps`] cuts a document into one JSON value per grasp, and [`parse_grasp`] reads one
//! value. Both report every problem as a [`GraspJsonError`] for that grasp alone, so one bad grasp
//! (a number out of `f64`'s range, a missing field) does not hide the others.
//!
//! ```
//! use pqhull::grasp::json::{parse_grasp, split_grasps};
//!
//! let text = r#"
//! {"contacts": [{"position": [-1, 0, 0], "normal": [1, 0, 0]}], "friction": 0.5, "cone_edges": 8}
//! {"contacts": [], "friction": 0.5, "cone_edges": 8}
//! not a grasp
//! "#;
//! let grasps: Vec<_> = split_grasps(text)
//!     .into_iter()
//!     .map(|value| value.and_then(|v| parse_grasp(&v)))
//!     .collect();
//! assert_eq!(grasps.len(), 3);
//! assert_eq!(grasps[0].as_ref().unwrap().friction().cone_edges(), 8);
//! assert_eq!(
//!     grasps[1].as_ref().unwrap_err().to_string(),
//!     "a grasp needs at least one contact"
//! );
//! assert!(grasps[2].as_ref().unwrap_err().to_string().starts_with("line 4: not JSON: "));
//! ```
//!
//! The writers go the other way: [`write_grasp`] gives the object [`parse_grasp`] reads back,
//! and [`quality_line`] / [`error_line`] the result line `pqh grasp` prints for each grasp.

mod write;

pub use write::{error_line, quality_line, write_contact, write_grasp};

use std::fmt;

use serde_json::Value;

use super::{
    Contact, FrictionModel, Grasp, GraspError, MAX_CONE_EDGES, MAX_CONTACTS, MIN_CONE_EDGES,
};

/// Why one grasp of a JSON document could not be read. The [`Display`](fmt::Display) form names
/// the field (and the contact) at fault; it is the error text `pqh grasp` prints.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum GraspJsonError {
    /// The grasp's text is not JSON.
    NotJson {
        /// The 1-based line of a JSON Lines document (`None` for an array element or a whole
        /// document).
        line: Option<usize>,
        /// The object key whose value is a number out of `f64`'s range, when that is the problem
        /// and the key can be found.
        field: Option<String>,
        /// The JSON parser's message.
        message: String,
    },
    /// The value is not a JSON object.
    NotAnObject,
    /// No `"contacts"` array.
    MissingContacts,
    /// A contact lacks a required field.
    MissingContactField {
        /// The contact's index.
        contact: usize,
        /// The field (`"position"` or `"normal"`).
        field: &'static str,
    },
    /// A vector field is not an array of 3 numbers.
    NotAVector {
        /// The field: `"contact 2 normal"`, `"torque_reference"`, …
        field: String,
    },
    /// An element of a vector field is not a number.
    NotANumber {
        /// The field, as in [`GraspJsonError::NotAVector`].
        field: String,
        /// The offending element, as JSON.
        value: String,
    },
    /// No `"friction"`, or it is not a number.
    MissingFriction,
    /// No `"cone_edges"`.
    MissingConeEdges,
    /// `"cone_edges"` is a number above [`MAX_CONE_EDGES`] that is not a whole number `u64` holds.
    TooManyConeEdges {
        /// The value, as JSON.
        value: String,
    },
    /// `"cone_edges"` is not a whole number (a fraction, a negative number, a string, …).
    ConeEdgesNotWhole {
        /// The value, as JSON.
        value: String,
    },
    /// `"torque_scale"` is not a number.
    TorqueScaleNotANumber,
    /// The values were read but do not make a grasp: a contact (with its index), the friction
    /// model or the grasp itself is invalid.
    Grasp(GraspError),
}

impl fmt::Display for GraspJsonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GraspJsonError::NotJson {
                line,
                field,
                message,
            } => {
                if let Some(line) = line {
                    write!(f, "line {line}: ")?;
                }
                match field {
                    Some(field) => {
                        write!(f, "\"{field}\": {message}")?;
                        if field == "cone_edges" {
                            write!(
                                f,
                                " (expected a whole number from {MIN_CONE_EDGES} to \
                                 {MAX_CONE_EDGES})"
                            )?;
                        }
                        Ok(())
                    }
                    None => write!(f, "not JSON: {message}"),
                }
            }
            GraspJsonError::NotAnObject => write!(f, "a grasp must be a JSON object"),
            GraspJsonError::MissingContacts => write!(f, "missing \"contacts\" array"),
            GraspJsonError::MissingContactField { contact, field } => {
                write!(f, "contact {contact}: missing \"{field}\"")
            }
            GraspJsonError::NotAVector { field } => {
                write!(f, "{field}: expected an array of 3 numbers")
            }
            GraspJsonError::NotANumber { field, value } => {
                write!(f, "{field}: {value} is not a number")
            }
            GraspJsonError::MissingFriction => write!(f, "missing or non-numeric \"friction\""),
            GraspJsonError::MissingConeEdges => write!(f, "missing \"cone_edges\""),
            GraspJsonError::TooManyConeEdges { value } => write!(
                f,
                "\"cone_edges\": {value} friction-cone edges are too many (at most \
                 {MAX_CONE_EDGES})"
            ),
            GraspJsonError::ConeEdgesNotWhole { value } => write!(
                f,
                "\"cone_edges\": {value} is not a whole number from {MIN_CONE_EDGES} to \
                 {MAX_CONE_EDGES}"
            ),
            GraspJsonError::TorqueScaleNotANumber => write!(f, "\"torque_scale\" is not a number"),
            GraspJsonError::Grasp(e) => match e {
                GraspError::TooManyContacts { .. } => write!(f, "\"contacts\": {e}"),
                GraspError::TooFewConeEdges { .. } | GraspError::TooManyConeEdges { .. } => {
                    write!(f, "\"cone_edges\": {e}")
                }
                _ => write!(f, "{e}"),
            },
        }
    }
}

impl std::error::Error for GraspJsonError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            GraspJsonError::Grasp(e) => Some(e),
            _ => None,
        }
    }
}

impl From<GraspError> for GraspJsonError {
    fn from(e: GraspError) -> Self {
        GraspJsonError::Grasp(e)
    }
}

/// Cuts a document into one JSON value per grasp: a JSON array gives its elements, one JSON
/// value gives itself, and anything else is read as JSON Lines (blank lines skipped).
///
/// An array element or a line that is not JSON becomes a [`GraspJsonError::NotJson`] entry at
/// its index (naming the line for JSON Lines); an object spread over several lines that is not
/// JSON is one entry. Whitespace-only input gives no entry.
///
/// ```
/// use pqhull::grasp::json::{GraspJsonError, split_grasps};
///
/// let values = split_grasps(r#"[{"a": 1}, {"b": 1e999}, 3]"#);
/// assert_eq!(values.len(), 3);
/// assert_eq!(values[2], Ok(serde_json::json!(3)));
/// // A number out of f64's range names its field.
/// let err = values[1].as_ref().unwrap_err();
/// assert!(matches!(err, GraspJsonError::NotJson { field: Some(f), .. } if f == "b"));
/// assert!(err.to_string().starts_with("\"b\": number out of range"));
/// assert!(split_grasps(" \n ").is_empty());
/// ```
pub fn split_grasps(text: &str) -> Vec<Result<Value, GraspJsonError>> {
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Vec::new();
    }
    if trimmed.starts_with('[')
        && let Some(elements) = array_elements(trimmed)
    {
        return elements
            .into_iter()
            .map(|e| serde_json::from_str(e).map_err(|err| not_json(e, None, &err)))
            .collect();
    }
    match serde_json::from_str::<Value>(text) {
        Ok(value) => return vec![Ok(value)],
        // One object over several lines (not JSON Lines): one entry.
        Err(err) if trimmed.starts_with('{') && value_end(trimmed) == Some(trimmed.len()) => {
            return vec![Err(not_json(trimmed, None, &err))];
        }
        Err(_) => {}
    }
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(n, l)| serde_json::from_str(l).map_err(|e| not_json(l, Some(n + 1), &e)))
        .collect()
}

/// The bytes of JSON `text` outside string literals, with their offsets: the brackets and commas
/// that give its structure (string contents, escapes included, are skipped).
fn structural(text: &str) -> impl Iterator<Item = (usize, u8)> + '_ {
    let (mut in_string, mut escaped) = (false, false);
    text.bytes().enumerate().filter(move |&(_, b)| {
        if in_string {
            match b {
                _ if escaped => escaped = false,
                b'\\' => escaped = true,
                b'"' => in_string = false,
                _ => {}
            }
            return false;
        }
        in_string = b == b'"';
        !in_string
    })
}

/// The byte offset just after the JSON value (object or array) that `text` starts with, found by
/// matching brackets outside strings; `None` if they never balance.
fn value_end(text: &str) -> Option<usize> {
    let mut depth = 0usize;
    for (i, b) in structural(text) {
        match b {
            b'[' | b'{' => depth += 1,
            b']' | b'}' => {
                depth = depth.checked_sub(1)?;
                if depth == 0 {
                    return Some(i + 1);
                }
            }
            _ => {}
        }
    }
    None
}

/// The top-level elements of the JSON array `text` (which starts with `[`), as text, split at
/// the commas outside strings and nested values; `None` unless the array's brackets balance and
/// only whitespace follows it.
fn array_elements(text: &str) -> Option<Vec<&str>> {
    if value_end(text)? != text.len() || !text.ends_with(']') {
        return None;
    }
    let inner = &text[1..text.len() - 1];
    let mut elements = Vec::new();
    let mut depth = 0usize;
    let mut start = 0;
    for (i, b) in structural(inner) {
        match b {
            b'[' | b'{' => depth += 1,
            b']' | b'}' => depth = depth.saturating_sub(1),
            b',' if depth == 0 => {
                elements.push(inner[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    let last = inner[start..].trim();
    if !last.is_empty() || !elements.is_empty() {
        elements.push(last);
    }
    Some(elements)
}

/// serde_json's error on `text`, naming the field when a number is out of `f64`'s range
/// (serde_json cannot represent it, so the grasp never reaches [`parse_grasp`]).
fn not_json(text: &str, line: Option<usize>, err: &serde_json::Error) -> GraspJsonError {
    let message = err.to_string();
    let field = if message.starts_with("number out of range") {
        field_before(text, err.line(), err.column()).map(str::to_owned)
    } else {
        None
    };
    GraspJsonError::NotJson {
        line,
        field,
        message,
    }
}

/// The name of the object key whose value contains (1-based) `line`, `column` of `text`.
fn field_before(text: &str, line: usize, column: usize) -> Option<&str> {
    let line_start: usize = text
        .split_inclusive('\n')
        .take(line.checked_sub(1)?)
        .map(str::len)
        .sum();
    let mut offset = (line_start + column).min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let key = before[..before.rfind(':')?].trim_end().strip_suffix('"')?;
    Some(&key[key.rfind('"')? + 1..])
}

fn vec3(value: &Value, field: &str) -> Result<[f64; 3], GraspJsonError> {
    let items =
        value
            .as_array()
            .filter(|a| a.len() == 3)
            .ok_or_else(|| GraspJsonError::NotAVector {
                field: field.to_owned(),
            })?;
    let mut out = [0.0; 3];
    for (o, v) in out.iter_mut().zip(items) {
        *o = v.as_f64().ok_or_else(|| GraspJsonError::NotANumber {
            field: field.to_owned(),
            value: v.to_string(),
        })?;
    }
    Ok(out)
}

/// Reads one grasp from its JSON value (see the [module documentation](self) for the fields).
///
/// Checked in this order, the first problem is returned: the value is an object with a
/// `"contacts"` array of at most [`MAX_CONTACTS`] entries; each contact in turn (its fields, then
/// [`Contact::try_new`], the error naming the contact); `"friction"`; `"cone_edges"`, then
/// [`FrictionModel::try_new`]; `"torque_reference"`, `"torque_scale"`; then
/// [`GraspBuilder::build`](super::GraspBuilder::build).
///
/// ```
/// use pqhull::grasp::json::{GraspJsonError, parse_grasp};
/// use pqhull::grasp::GraspError;
/// use serde_json::json;
///
/// let grasp = parse_grasp(&json!({
///     "contacts": [
///         {"position": [-0.5, 0, 0], "normal": [1, 0, 0]},
///         {"position": [0.5, 0, 0], "normal": [-1, 0, 0], "tangent": [0, 0, 1]}
///     ],
///     "friction": 0.5, "cone_edges": 8.0, "torque_scale": 2
/// }))?;
/// assert_eq!(grasp.contact_count(), 2);
/// assert_eq!(grasp.torque_scale(), 2.0);
///
/// let bad = json!({"contacts": [{"position": [0, 0, 0], "normal": [0, 0, 0]}],
///                  "friction": 0.5, "cone_edges": 8});
/// let err = parse_grasp(&bad).unwrap_err();
/// assert_eq!(err, GraspJsonError::Grasp(GraspError::ZeroNormal { contact: Some(0) }));
/// assert_eq!(err.to_string(), "contact 0: the normal is the zero vector");
/// # Ok::<(), GraspJsonError>(())
/// ```
pub fn parse_grasp(value: &Value) -> Result<Grasp, GraspJsonError> {
    let object = value.as_object().ok_or(GraspJsonError::NotAnObject)?;
    let contacts = object
        .get("contacts")
        .and_then(Value::as_array)
        .ok_or(GraspJsonError::MissingContacts)?;
    if contacts.len() > MAX_CONTACTS {
        return Err(GraspError::TooManyContacts {
            contacts: contacts.len(),
            max: MAX_CONTACTS,
        }
        .into());
    }
    let mut parsed = Vec::with_capacity(contacts.len());
    for (i, c) in contacts.iter().enumerate() {
        let field = |name: &'static str| {
            c.get(name).ok_or(GraspJsonError::MissingContactField {
                contact: i,
                field: name,
            })
        };
        let position = vec3(field("position")?, &format!("contact {i} position"))?;
        let normal = vec3(field("normal")?, &format!("contact {i} normal"))?;
        let tangent = match c.get("tangent") {
            Some(t) => Some(vec3(t, &format!("contact {i} tangent"))?),
            None => None,
        };
        let mut contact =
            Contact::try_new(position, normal, tangent).map_err(|e| e.at_contact(i))?;
        if let Some(t) = c.get("torsion") {
            let torsion = t.as_f64().ok_or_else(|| GraspJsonError::NotANumber {
                field: format!("contact {i} torsion"),
                value: t.to_string(),
            })?;
            contact = contact.with_torsion(torsion).map_err(|e| e.at_contact(i))?;
        }
        parsed.push(contact);
    }
    let friction = object
        .get("friction")
        .and_then(Value::as_f64)
        .ok_or(GraspJsonError::MissingFriction)?;
    let edges = cone_edges(
        object
            .get("cone_edges")
            .ok_or(GraspJsonError::MissingConeEdges)?,
    )?;
    let model = FrictionModel::try_new(friction, edges)?;
    let mut builder = Grasp::builder(parsed, model);
    if let Some(c) = object.get("torque_reference") {
        builder = builder.torque_reference(vec3(c, "torque_reference")?);
    }
    if let Some(rho) = object.get("torque_scale") {
        let rho = rho.as_f64().ok_or(GraspJsonError::TorqueScaleNotANumber)?;
        builder = builder.torque_scale(rho);
    }
    Ok(builder.build()?)
}

/// The number of cone edges in `value`: a whole number (`8.0` counts). Too large a number is
/// an error naming the limit; otherwise the range is checked by [`FrictionModel::try_new`].
fn cone_edges(value: &Value) -> Result<usize, GraspJsonError> {
    if let Some(k) = value.as_u64() {
        return Ok(usize::try_from(k).unwrap_or(usize::MAX));
    }
    match value.as_f64() {
        Some(k) if k > MAX_CONE_EDGES as f64 => Err(GraspJsonError::TooManyConeEdges {
            value: value.to_string(),
        }),
        Some(k) if k >= 0.0 && k.fract() == 0.0 => Ok(k as usize),
        _ => Err(GraspJsonError::ConeEdgesNotWhole {
            value: value.to_string(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn grasp_with(field: &str, value: Value) -> Value {
        let mut g = json!({
            "contacts": [{"position": [0, 0, 0], "normal": [0, 0, 1]}],
            "friction": 0.5, "cone_edges": 4
        });
        g[field] = value;
        g
    }

    fn message(value: &Value) -> String {
        parse_grasp(value).unwrap_err().to_string()
    }

    #[test]
    fn every_message_names_its_field() {
        assert_eq!(message(&json!([1])), "a grasp must be a JSON object");
        assert_eq!(message(&json!({})), "missing \"contacts\" array");
        assert_eq!(
            message(&grasp_with("contacts", json!([{"normal": [0, 0, 1]}]))),
            "contact 0: missing \"position\""
        );
        assert_eq!(
            message(&grasp_with(
                "contacts",
                json!([{"position": [0, 0, 0], "normal": [0, 0, 1]}, {"position": [0, 0, 0]}])
            )),
            "contact 1: missing \"normal\""
        );
        assert_eq!(
            message(&grasp_with(
                "contacts",
                json!([{"position": [0, 0], "normal": [0, 0, 1]}])
            )),
            "contact 0 position: expected an array of 3 numbers"
        );
        assert_eq!(
            message(&grasp_with(
                "contacts",
                json!([{"position": [0, 0, 0], "normal": [0, 0, 1], "tangent": [0, "x", 0]}])
            )),
            "contact 0 tangent: \"x\" is not a number"
        );
        assert_eq!(
            message(&grasp_with("friction", json!("high"))),
            "missing or non-numeric \"friction\""
        );
        assert_eq!(
            message(&grasp_with("friction", json!(-1))),
            "friction coefficient -1 is invalid (must be finite and at least 0)"
        );
        let mut no_edges = grasp_with("friction", json!(0.5));
        no_edges.as_object_mut().unwrap().remove("cone_edges");
        assert_eq!(message(&no_edges), "missing \"cone_edges\"");
        assert_eq!(
            message(&grasp_with("cone_edges", json!(2))),
            "\"cone_edges\": 2 friction-cone edges are too few (at least 3 are needed)"
        );
        assert!(
            message(&grasp_with("cone_edges", json!(5000))).starts_with(
                "\"cone_edges\": 5000 friction-cone edges are too many (at most 1024:"
            )
        );
        assert_eq!(
            message(&grasp_with("cone_edges", json!(1e30))),
            "\"cone_edges\": 1e+30 friction-cone edges are too many (at most 1024)"
        );
        for bad in [json!(4.5), json!(-4), json!("4")] {
            assert_eq!(
                message(&grasp_with("cone_edges", bad.clone())),
                format!("\"cone_edges\": {bad} is not a whole number from 3 to 1024")
            );
        }
        assert_eq!(
            message(&grasp_with("torque_reference", json!([0, 0]))),
            "torque_reference: expected an array of 3 numbers"
        );
        assert_eq!(
            message(&grasp_with("torque_scale", json!(null))),
            "\"torque_scale\" is not a number"
        );
        assert_eq!(
            message(&grasp_with("torque_scale", json!(0))),
            "torque scale 0 is invalid (must be finite and greater than 0)"
        );
        assert_eq!(
            message(&grasp_with("contacts", json!([]))),
            "a grasp needs at least one contact"
        );
        let many = vec![json!({"position": [0, 0, 0], "normal": [0, 0, 1]}); MAX_CONTACTS + 1];
        assert_eq!(
            message(&grasp_with("contacts", Value::Array(many))),
            format!(
                "\"contacts\": 257 contacts are too many for one grasp (at most {MAX_CONTACTS})"
            )
        );
    }

    #[test]
    fn a_whole_float_is_a_cone_edge_count() {
        let g = parse_grasp(&grasp_with("cone_edges", json!(6.0))).unwrap();
        assert_eq!(g.friction().cone_edges(), 6);
    }

    #[test]
    fn the_three_document_shapes() {
        let one = r#"{"contacts": [], "friction": 1, "cone_edges": 4}"#;
        assert_eq!(split_grasps(one).len(), 1);
        let array = format!("[{one}, {one},\n {one}]");
        assert_eq!(split_grasps(&array).len(), 3);
        let lines = format!("{one}\n\n{one}\n");
        let values = split_grasps(&lines);
        assert_eq!(values.len(), 2);
        assert!(values.iter().all(Result::is_ok));
        // A broken multi-line object is one entry, not one per line.
        let broken = "{\n\"contacts\": [],\n\"friction\": x\n}";
        let values = split_grasps(broken);
        assert_eq!(values.len(), 1);
        assert!(matches!(
            &values[0],
            Err(GraspJsonError::NotJson { line: None, .. })
        ));
        // Brackets inside strings do not split.
        let values = split_grasps(r#"[{"a": "],["}, {"b": "\"]"}]"#);
        assert_eq!(values.len(), 2);
        assert!(values.iter().all(Result::is_ok));
    }

    #[test]
    fn an_out_of_range_number_names_its_field_and_line() {
        let values = split_grasps("{\"a\": 1}\n{\"cone_edges\": 1e400}\n");
        assert_eq!(values.len(), 2);
        let err = values[1].as_ref().unwrap_err();
        let text = err.to_string();
        assert!(
            text.starts_with("line 2: \"cone_edges\": number out of range"),
            "{text}"
        );
        assert!(
            text.ends_with("(expected a whole number from 3 to 1024)"),
            "{text}"
        );
        let values = split_grasps("{\"a\": 1}\n{\"friction\": -1e400}\n");
        let text = values[1].as_ref().unwrap_err().to_string();
        assert!(
            text.starts_with("line 2: \"friction\": number out of range"),
            "{text}"
        );
        assert!(!text.contains("expected"), "{text}");
    }

    #[test]
    fn the_grasp_error_is_the_source() {
        use std::error::Error;
        let err = parse_grasp(&grasp_with("friction", json!(-1))).unwrap_err();
        assert!(err.source().is_some());
        assert!(GraspJsonError::NotAnObject.source().is_none());
    }
}
