//! The fuzz targets as bounded, deterministic tests on stable (docs/fuzzing.md).
//!
//! Each target's body ([`bodies`], shared with `fuzz/fuzz_targets/`) runs on
//!
//! * every file in `fuzz/regressions/<target>/`: the crashes the fuzzers found (kept so they stay
//!   fixed) and a few hand-written seeds;
//! * a fixed stream of generated inputs: structured ones (text in the target's format with the
//!   awkward values the format allows) and mutants of the regression files (bit flips, insertions,
//!   deletions, splices), from a seeded generator, so every run tests the same inputs.
//!
//! A failure names the target and the input (the file, or the generated case's number and bytes).

use crate::support::fuzz_bodies as bodies;

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

/// Generated inputs per target (half structured, half mutants), chosen so that the whole file
/// runs in well under 30 s in release on 2 cores. The engine's inputs cost the most (exact
/// arithmetic on 8-D sets), so it gets fewer.
fn generated(target: &str) -> usize {
    if target == "engine" { 1000 } else { 1500 }
}

/// A small deterministic generator (SplitMix64).
struct Gen(u64);

impl Gen {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }

    fn chance(&mut self, one_in: usize) -> bool {
        self.below(one_in) == 0
    }
}

fn regressions_dir(target: &str) -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .join("fuzz/regressions")
        .join(target)
}

/// The regression inputs of `target`, sorted by name.
fn regressions(target: &str) -> Vec<(String, Vec<u8>)> {
    let dir = regressions_dir(target);
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|entry| {
            let path = entry.expect("directory entry").path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            let data = std::fs::read(&path).expect("read a regression input");
            (name, data)
        })
        .collect();
    files.sort();
    files
}

/// Runs `target` on `data`, turning a panic into one naming the input.
fn run(target: &str, what: &str, data: &[u8]) {
    if let Err(panic) = catch_unwind(AssertUnwindSafe(|| bodies::run(target, data))) {
        let message = panic
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| panic.downcast_ref::<&str>().copied())
            .unwrap_or("(non-string panic)");
        panic!(
            "fuzz target {target} failed on {what}: {message}\ninput ({} bytes): {:?}",
            data.len(),
            String::from_utf8_lossy(data)
        );
    }
}

/// Replays the regression inputs, then the generated stream.
fn fuzz_bounded(target: &str, structured: fn(&mut Gen) -> Vec<u8>) {
    let corpus = regressions(target);
    assert!(
        !corpus.is_empty(),
        "{} has no input: every target keeps at least its seeds",
        regressions_dir(target).display()
    );
    for (name, data) in &corpus {
        run(target, &format!("fuzz/regressions/{target}/{name}"), data);
    }
    let mut rng = Gen(0x5eed ^ target.len() as u64 ^ (target.as_bytes()[0] as u64) << 8);
    for case in 0..generated(target) {
        let data = if case % 2 == 0 {
            structured(&mut rng)
        } else {
            mutate(&mut rng, &corpus)
        };
        run(target, &format!("generated case {case}"), &data);
    }
}

/// A mutant of a corpus input: a few bit flips, insertions, deletions, duplications or a splice
/// with another input, as a fuzzer's mutator would.
fn mutate(rng: &mut Gen, corpus: &[(String, Vec<u8>)]) -> Vec<u8> {
    let mut data = rng.pick(corpus).1.clone();
    for _ in 0..1 + rng.below(4) {
        let len = data.len();
        match rng.below(6) {
            0 if len > 0 => {
                let i = rng.below(len);
                data[i] ^= 1 << rng.below(8);
            }
            1 => {
                let i = rng.below(len + 1);
                let byte = *rng.pick(b"0123456789 ,.-+eE\n\r#[]{}\":/\x00\xff");
                data.insert(i, byte);
            }
            2 if len > 0 => {
                let i = rng.below(len);
                let end = (i + 1 + rng.below(8)).min(len);
                data.drain(i..end);
            }
            3 if len > 0 => {
                let i = rng.below(len);
                let end = (i + 1 + rng.below(16)).min(len);
                let copy = data[i..end].to_vec();
                let at = rng.below(len + 1);
                data.splice(at..at, copy);
            }
            4 => {
                let other = &rng.pick(corpus).1;
                let cut = rng.below(data.len() + 1);
                let from = rng.below(other.len() + 1);
                data.truncate(cut);
                data.extend_from_slice(&other[from..]);
            }
            _ if len > 0 => {
                let i = rng.below(len);
                data[i] = rng.next() as u8;
            }
            _ => data.push(rng.next() as u8),
        }
    }
    data
}

/// Numbers as a text format may write them: ordinary, extreme, subnormal, signed zeros, out of
/// range, not numbers at all.
const NUMBERS: &[&str] = &[
    "0",
    "1",
    "-1",
    "2",
    "0.5",
    "-0.25",
    "-0",
    "-0.0",
    ".5",
    "+2",
    "3.",
    "1e3",
    "1E-3",
    "1e308",
    "-1.7976931348623157e308",
    "2.2250738585072014e-308",
    "5e-324",
    "-4.9e-324",
    "1e-320",
    "1e400",
    "-1e400",
    "1e-400",
    "123456789012345678901234567890",
    "18446744073709551616",
    "0.1",
    "nan",
    "inf",
    "-infinity",
    "x",
    "0x10",
    "1,5",
    "",
];

fn number(rng: &mut Gen) -> String {
    if rng.chance(3) {
        // A random finite value, printed exactly.
        let x = f64::from_bits(rng.next());
        if x.is_finite() {
            return format!("{x:?}");
        }
    }
    rng.pick(NUMBERS).to_string()
}

/// Between coordinates: the format's separators, and an empty field.
const SEPARATORS: [&str; 6] = [" ", ",", ", ", "\t", " , ", ",,"];

/// Line ends, and a Unicode line separator (not one to the format).
const LINE_ENDS: [&str; 5] = ["\n", "\n", "\r\n", "\r", "\u{2028}"];

fn points_text(rng: &mut Gen) -> Vec<u8> {
    let mut text = String::new();
    if rng.chance(10) {
        text.push('\u{feff}');
    }
    let d = 1 + rng.below(8);
    for _ in 0..rng.below(30) {
        match rng.below(12) {
            0 => text.push_str("# a comment"),
            1 => {}
            _ => {
                // Mostly the first row's length; sometimes not.
                let len = if rng.chance(8) { rng.below(10) } else { d };
                for i in 0..len {
                    if i > 0 {
                        let separator: &&str = rng.pick(&SEPARATORS);
                        text.push_str(separator);
                    }
                    text.push_str(&number(rng));
                }
                if rng.chance(6) {
                    text.push_str(" # trailing");
                }
            }
        }
        let end: &&str = rng.pick(&LINE_ENDS);
        text.push_str(end);
    }
    text.into_bytes()
}

fn vector(rng: &mut Gen) -> String {
    match rng.below(12) {
        0 => "[1, 2]".into(),
        1 => "\"x\"".into(),
        2 => format!("[{}, \"y\", 0]", number(rng)),
        3 => "[0, 0, 0]".into(),
        _ => {
            let c: Vec<String> = (0..3)
                .map(|_| {
                    if rng.chance(2) {
                        format!("{}", rng.below(5) as f64 - 2.0)
                    } else {
                        json_number(rng)
                    }
                })
                .collect();
            format!("[{}]", c.join(", "))
        }
    }
}

/// A number as JSON may write it (no bare `nan`, `.5` or `+2`, which are not JSON: those only
/// sometimes).
fn json_number(rng: &mut Gen) -> String {
    let n = number(rng);
    let valid_json = !n.is_empty()
        && !n.starts_with('.')
        && !n.starts_with('+')
        && !n.ends_with('.')
        && n.parse::<f64>().is_ok()
        && !n.contains("inf")
        && !n.contains("nan");
    if valid_json || rng.chance(10) {
        n
    } else {
        "0.5".into()
    }
}

fn grasp_object(rng: &mut Gen) -> String {
    let mut fields = Vec::new();
    if !rng.chance(20) {
        let contacts: Vec<String> = (0..rng.below(5))
            .map(|_| {
                let mut c = Vec::new();
                if !rng.chance(20) {
                    c.push(format!("\"position\": {}", vector(rng)));
                }
                if !rng.chance(20) {
                    c.push(format!("\"normal\": {}", vector(rng)));
                }
                if rng.chance(3) {
                    c.push(format!("\"tangent\": {}", vector(rng)));
                }
                if rng.chance(3) {
                    let torsion = rng.pick(&["0", "0.01", "0.2", "-0.1", "1e300", "null"]);
                    c.push(format!("\"torsion\": {torsion}"));
                }
                format!("{{{}}}", c.join(", "))
            })
            .collect();
        fields.push(format!("\"contacts\": [{}]", contacts.join(", ")));
    }
    if !rng.chance(20) {
        let mu = if rng.chance(2) {
            "0.5".to_string()
        } else {
            json_number(rng)
        };
        fields.push(format!("\"friction\": {mu}"));
    }
    if !rng.chance(20) {
        let k = rng.pick(&[
            "3",
            "4",
            "8",
            "8.0",
            "2",
            "0",
            "-1",
            "4.5",
            "1024",
            "1025",
            "1e30",
            "\"4\"",
            "1e400",
            "18446744073709551616",
            "null",
        ]);
        fields.push(format!("\"cone_edges\": {k}"));
    }
    if rng.chance(4) {
        fields.push(format!("\"torque_reference\": {}", vector(rng)));
    }
    if rng.chance(4) {
        fields.push(format!("\"torque_scale\": {}", json_number(rng)));
    }
    format!("{{{}}}", fields.join(", "))
}

fn grasp_text(rng: &mut Gen) -> Vec<u8> {
    let grasps: Vec<String> = (0..1 + rng.below(4)).map(|_| grasp_object(rng)).collect();
    let mut text = match rng.below(3) {
        0 => format!("[{}]", grasps.join(",\n")),
        1 => grasps.join("\n"),
        _ => grasps[0].replace(", ", ",\n"),
    };
    if rng.chance(8) {
        let cut = rng.below(text.len() + 1);
        text.truncate(cut);
    }
    text.into_bytes()
}

fn obj_text(rng: &mut Gen) -> Vec<u8> {
    let mut text = String::new();
    let vertices = rng.below(8);
    for _ in 0..vertices {
        let c: Vec<String> = (0..3)
            .map(|_| {
                if rng.chance(2) {
                    rng.below(3).to_string()
                } else {
                    number(rng)
                }
            })
            .collect();
        text.push_str(&format!("v {}\n", c.join(" ")));
    }
    for _ in 0..rng.below(8) {
        match rng.below(10) {
            0 => text.push_str("o part\n"),
            1 => text.push_str("g group\n"),
            2 => text.push_str("vn 0 0 1\nvt 0.5 0.5\n"),
            3 => text.push_str("mtllib missing.mtl\nusemtl x\n"),
            4 => text.push_str(&format!("l 1 {}\n", 1 + rng.below(vertices + 2))),
            _ => {
                let arity = if rng.chance(5) { 1 + rng.below(5) } else { 3 };
                let index = |rng: &mut Gen| -> String {
                    match rng.below(8) {
                        0 => format!("-{}", 1 + rng.below(vertices + 1)),
                        1 => "0".into(),
                        2 => format!("{}/1/1", 1 + rng.below(vertices + 1)),
                        _ => (1 + rng.below(vertices + 1)).to_string(),
                    }
                };
                let f: Vec<String> = (0..arity).map(|_| index(rng)).collect();
                text.push_str(&format!("f {}\n", f.join(" ")));
            }
        }
    }
    text.into_bytes()
}

/// An STL value: mostly small integers (so corners are shared), sometimes anything.
fn stl_value(rng: &mut Gen) -> f32 {
    if rng.chance(4) {
        f32::from_bits(rng.next() as u32)
    } else {
        rng.below(3) as f32 - 1.0
    }
}

fn stl_bytes(rng: &mut Gen) -> Vec<u8> {
    let triangles = rng.below(8);
    if rng.chance(2) {
        let mut text = String::from("solid fuzz\n");
        for _ in 0..triangles {
            text.push_str("facet normal 0 0 1\nouter loop\n");
            for _ in 0..if rng.chance(8) { 2 } else { 3 } {
                let c: Vec<String> = (0..3)
                    .map(|_| {
                        if rng.chance(3) {
                            number(rng)
                        } else {
                            stl_value(rng).to_string()
                        }
                    })
                    .collect();
                text.push_str(&format!("vertex {}\n", c.join(" ")));
            }
            text.push_str("endloop\nendfacet\n");
        }
        if !rng.chance(8) {
            text.push_str("endsolid fuzz\n");
        }
        text.into_bytes()
    } else {
        let mut data = vec![b' '; 80];
        let count = if rng.chance(6) {
            rng.next() as u32
        } else {
            triangles as u32
        };
        data.extend_from_slice(&count.to_le_bytes());
        for _ in 0..triangles {
            for _ in 0..12 {
                data.extend_from_slice(&stl_value(rng).to_le_bytes());
            }
            data.extend_from_slice(&[0, 0]);
        }
        if rng.chance(6) {
            let cut = rng.below(data.len() + 1);
            data.truncate(cut);
        }
        data
    }
}

/// An input of the engine target, written in the grammar its decoder reads (see `decode` in
/// cli/tests/pqh/support/fuzz_bodies.rs): D, the point count, the set's scale, then per point a
/// duplicate, a point on a line through two earlier ones, or coordinates (each a copy of an
/// earlier point's, a small integer times the scale, zero, a fraction, or — in a quarter of the
/// sets, the *wide* ones — an extreme power of two, a subnormal or any bit pattern), then the
/// query. Wide sets are kept small in high dimensions, where they take exact arithmetic on
/// integers of thousands of bits (see `max_wide_points`).
fn engine_bytes(rng: &mut Gen) -> Vec<u8> {
    let d = 2 + rng.below(7);
    let wide = rng.chance(4);
    let most = if wide && d >= 6 {
        d + 2
    } else {
        bodies::max_points(d)
    };
    let n = rng.below(most + 1);
    let mut out = vec![(d - 2) as u8, n as u8];
    if rng.chance(2) {
        out.extend([0, rng.next() as u8]);
    } else {
        out.push(2);
        out.extend((rng.below(2098) as u16).to_le_bytes());
    }
    let coordinates = |rng: &mut Gen, out: &mut Vec<u8>| {
        for _ in 0..d {
            let op = match rng.below(if wide { 10 } else { 7 }) {
                0 => 0,
                1 | 2 => 2,
                3 => 4,
                4..=6 => 8,
                7 => 5,
                8 => 6,
                _ => 7,
            };
            out.push(op);
            let payload = match op {
                0 | 2 => 1,
                8 => 2,
                5 => 3,
                4 => 0,
                _ => 8,
            };
            out.extend((0..payload).map(|_| rng.next() as u8));
        }
    };
    for i in 0..n {
        match rng.below(8) {
            0 if i >= 1 => out.extend([0, rng.next() as u8]),
            1 if i >= 2 => out.extend([1, rng.next() as u8, rng.next() as u8, rng.next() as u8]),
            _ => {
                out.push(2);
                coordinates(rng, &mut out);
            }
        }
    }
    match rng.below(4) {
        0 => out.push(0),
        1 if n > 0 => out.extend([1, rng.next() as u8]),
        _ => {
            out.push(2);
            coordinates(rng, &mut out);
        }
    }
    out
}

#[test]
fn points_file() {
    fuzz_bounded("points_file", points_text);
}

#[test]
fn grasp_json() {
    fuzz_bounded("grasp_json", grasp_text);
}

#[test]
fn mesh_obj() {
    fuzz_bounded("mesh_obj", obj_text);
}

#[test]
fn mesh_stl() {
    fuzz_bounded("mesh_stl", stl_bytes);
}

#[test]
fn engine() {
    fuzz_bounded("engine", engine_bytes);
}

/// Every target has its regression directory, its cargo-fuzz target file with the shared body,
/// and its `[[bin]]` in fuzz/Cargo.toml, and nothing else is there.
#[test]
fn the_fuzz_crate_runs_every_body() {
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join("fuzz");
    let manifest = std::fs::read_to_string(root.join("Cargo.toml")).expect("fuzz/Cargo.toml");
    let mut targets: Vec<String> = std::fs::read_dir(root.join("fuzz_targets"))
        .expect("fuzz/fuzz_targets")
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    targets.sort();
    let mut expected: Vec<String> = bodies::TARGETS.iter().map(|t| format!("{t}.rs")).collect();
    expected.sort();
    assert_eq!(targets, expected);
    for target in bodies::TARGETS {
        let source = std::fs::read_to_string(root.join(format!("fuzz_targets/{target}.rs")))
            .expect("target source");
        assert!(
            source.contains("#[path = \"../../cli/tests/pqh/support/fuzz_bodies.rs\"]")
                && source.contains(&format!("bodies::{target}(data)")),
            "fuzz/fuzz_targets/{target}.rs must run the shared body `{target}`"
        );
        assert!(
            manifest.contains(&format!(
                "name = \"{target}\"\npath = \"fuzz_targets/{target}.rs\""
            )),
            "fuzz/Cargo.toml has no [[bin]] for {target}"
        );
        assert!(
            regressions_dir(target).is_dir(),
            "no regressions for {target}"
        );
    }
    let mut dirs: Vec<String> = std::fs::read_dir(root.join("regressions"))
        .expect("fuzz/regressions")
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    dirs.sort();
    let mut names: Vec<String> = bodies::TARGETS.iter().map(|t| t.to_string()).collect();
    names.sort();
    assert_eq!(
        dirs, names,
        "fuzz/regressions holds one directory per target"
    );
}
