//! Writing grasps and their qualities as JSON: the grasp format [`parse_grasp`](super::parse_grasp)
//! reads, and the result line `pqh grasp` prints for each grasp.

use serde_json::{Value, json};

use crate::grasp::{Contact, Grasp};
use crate::hull::Stats;

/// A contact as the grasp format writes it: `position` and `normal`, and `tangent` only when
/// one was given ([`Contact::tangent_given`]; the default one is derived from the normal again
/// when read).
///
/// ```
/// use pqhull::grasp::Contact;
/// use pqhull::grasp::json::write_contact;
/// let c = Contact::try_new([0.5, 0.0, 0.0], [-1.0, 0.0, 0.0], None)?;
/// assert_eq!(write_contact(&c).to_string(), r#"{"normal":[-1.0,0.0,0.0],"position":[0.5,0.0,0.0]}"#);
/// # Ok::<(), pqhull::grasp::GraspError>(())
/// ```
pub fn write_contact(contact: &Contact) -> Value {
    let mut value = json!({
        "position": contact.position(),
        "normal": contact.normal(),
    });
    if contact.tangent_given() {
        value["tangent"] = json!(contact.tangent());
    }
    if contact.is_soft() {
        value["torsion"] = json!(contact.torsion());
    }
    value
}

/// A grasp as one JSON object of the format [`parse_grasp`](super::parse_grasp) reads: its
/// contacts ([`write_contact`]), `friction` and `cone_edges`, and `torque_reference` and
/// `torque_scale` only when they differ from the defaults (the origin and 1), so that a grasp in
/// the default frame can still be put in a mesh's frame by `pqh grasp --mesh`.
///
/// Floats are written with their shortest round-trip digits: reading the object back gives the
/// same positions, friction and torque frame bit for bit; normals and tangents, already unit, are
/// normalised again when read, which may move them by an ulp.
///
/// ```
/// use pqhull::grasp::json::{parse_grasp, write_grasp};
/// use pqhull::grasp::{Contact, FrictionModel, Grasp};
///
/// let contacts = vec![
///     Contact::try_new([-0.5, 0.1, 0.0], [1.0, 0.0, 0.0], None)?,
///     Contact::try_new([0.5, 0.0, 0.2], [-1.0, 0.0, 0.0], Some([0.0, 0.0, 1.0]))?,
/// ];
/// let grasp = Grasp::builder(contacts, FrictionModel::try_new(0.4, 6)?)
///     .torque_scale(0.75)
///     .build()?;
/// let value = write_grasp(&grasp);
/// assert_eq!(value["cone_edges"], 6);
/// assert!(value.get("torque_reference").is_none()); // the default, left out
/// assert_eq!(parse_grasp(&value)?, grasp);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_grasp(grasp: &Grasp) -> Value {
    let friction = grasp.friction();
    let mut value = json!({
        "contacts": grasp.contacts().iter().map(write_contact).collect::<Vec<_>>(),
        "friction": friction.friction(),
        "cone_edges": friction.cone_edges(),
    });
    if grasp.torque_reference() != [0.0; 3] {
        value["torque_reference"] = json!(grasp.torque_reference());
    }
    if grasp.torque_scale() != 1.0 {
        value["torque_scale"] = json!(grasp.torque_scale());
    }
    value
}

/// The result line of grasp `index`:
/// `{"index", "force_closure", "quality", "stats": {"points_processed", "facets_created",
/// "elapsed_us"}}`, with `quality` null when the metric has no value (Q_OWS of a grasp that is not
/// force closure) and the time in (fractional) microseconds.
///
/// ```
/// use pqhull::grasp::json::quality_line;
/// use pqhull::grasp::quality::q1;
/// use pqhull::grasp::{Contact, FrictionModel, Grasp};
///
/// let grasp = Grasp::builder(
///     vec![Contact::try_new([0.0; 3], [0.0, 0.0, 1.0], None)?],
///     FrictionModel::try_new(0.5, 4)?,
/// ).build()?;
/// let q = q1(&grasp)?;
/// let line = quality_line(3, q.force_closure, q.value, &q.stats);
/// assert_eq!(line["index"], 3);
/// assert_eq!(line["force_closure"], false); // one finger cannot hold anything
/// assert!(line["stats"]["elapsed_us"].is_f64());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn quality_line(
    index: usize,
    force_closure: bool,
    quality: Option<f64>,
    stats: &Stats,
) -> Value {
    json!({
        "index": index,
        "force_closure": force_closure,
        "quality": quality,
        "stats": {
            "points_processed": stats.points_processed,
            "facets_created": stats.facets_created,
            "elapsed_us": stats.elapsed.as_secs_f64() * 1e6,
        }
    })
}

/// The line of grasp `index` that could not be read or evaluated: `{"index", "error"}`.
///
/// ```
/// use pqhull::grasp::json::error_line;
/// assert_eq!(error_line(2, "missing \"friction\"").to_string(), r#"{"error":"missing \"friction\"","index":2}"#);
/// ```
pub fn error_line(index: usize, message: &str) -> Value {
    json!({"index": index, "error": message})
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Rng;
    use crate::grasp::FrictionModel;
    use crate::grasp::json::{parse_grasp, split_grasps};

    /// Random grasps with and without tangents and torque frames, written as JSON Lines and read
    /// back: the same contacts.
    #[test]
    fn written_grasps_read_back_as_the_same_grasps() {
        let mut rng = Rng::new(11);
        let mut grasps = Vec::new();
        for i in 0..20 {
            let contacts = (0..1 + i % 5)
                .map(|_| {
                    let p: [f64; 3] = std::array::from_fn(|_| rng.uniform_in(-0.3, 0.3));
                    let n = rng.unit_vector(3);
                    let t = (i % 2 == 0).then(|| rng.unit_vector(3));
                    Contact::try_new(p, [n[0], n[1], n[2]], t.map(|t| [t[0], t[1], t[2]]))
                })
                .filter_map(Result::ok)
                .collect();
            let friction = FrictionModel::try_new(rng.uniform_in(0.1, 1.0), 3 + i).unwrap();
            let mut builder = Grasp::builder(contacts, friction);
            if i % 3 == 0 {
                builder = builder
                    .torque_reference(std::array::from_fn(|_| rng.uniform_in(-0.1, 0.1)))
                    .torque_scale(rng.uniform_in(0.2, 2.0));
            }
            grasps.push(builder.build().unwrap());
        }
        let text: String = grasps
            .iter()
            .map(|g| format!("{}\n", write_grasp(g)))
            .collect();
        let read: Vec<Grasp> = split_grasps(&text)
            .into_iter()
            .map(|v| parse_grasp(&v.unwrap()).unwrap())
            .collect();
        assert_eq!(read.len(), grasps.len());
        let close = |a: [f64; 3], b: [f64; 3]| a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-15);
        for (a, b) in grasps.iter().zip(&read) {
            assert_eq!(a.friction(), b.friction());
            assert_eq!(a.torque_reference(), b.torque_reference());
            assert_eq!(a.torque_scale(), b.torque_scale());
            assert_eq!(a.contact_count(), b.contact_count());
            for (c, d) in a.contacts().iter().zip(b.contacts()) {
                assert_eq!(c.position(), d.position());
                assert!(close(c.normal(), d.normal()), "{c:?} {d:?}");
                assert!(close(c.tangent(), d.tangent()), "{c:?} {d:?}");
                assert_eq!(c.tangent_given(), d.tangent_given());
            }
        }
    }

    #[test]
    fn lines_have_the_documented_keys() {
        let stats = Stats {
            points_processed: 7,
            facets_created: 12,
            expansions: 3,
            elapsed: std::time::Duration::from_micros(5),
        };
        assert_eq!(
            quality_line(0, true, Some(0.25), &stats).to_string(),
            r#"{"force_closure":true,"index":0,"quality":0.25,"stats":{"elapsed_us":5.0,"facets_created":12,"points_processed":7}}"#
        );
        assert_eq!(quality_line(1, false, None, &stats)["quality"], Value::Null);
        assert_eq!(
            error_line(4, "bad")["error"],
            Value::String("bad".to_string())
        );
    }
}
