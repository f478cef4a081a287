//! The library's layers import only downward: a module may name (`crate::…`, in code or in doc
//! links) only modules of lower layers, never a module of its own layer or of one above. The
//! layers are read from the table in docs/ARCHITECTURE.md, so the drawing there is the rule
//! enforced here; every top-level module of `src/` must appear in it.
//!
//! Unit-test modules (`#[cfg(test)] mod tests`, `tests.rs`) are exempt: tests may build their
//! inputs from anything (e.g. `rbox`'s point families).

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Module name → layer number, from the block of docs/ARCHITECTURE.md that starts with the line
/// `layer  modules`.
fn layers() -> BTreeMap<String, usize> {
    let doc =
        fs::read_to_string(root().join("docs/ARCHITECTURE.md")).expect("docs/ARCHITECTURE.md");
    let mut lines = doc.lines().skip_while(|l| !l.starts_with("layer  modules"));
    assert!(
        lines.next().is_some(),
        "no `layer  modules` table in docs/ARCHITECTURE.md"
    );
    let mut table = BTreeMap::new();
    for line in lines.take_while(|l| !l.starts_with("```")) {
        // `  6    grasp, mesh    what it holds`: a number, then modules up to a run of spaces.
        let line = line.trim_start();
        let Some((number, rest)) = line.split_once(char::is_whitespace) else {
            continue;
        };
        let Ok(layer) = number.parse::<usize>() else {
            continue; // a continuation line of the description
        };
        let modules = rest.trim_start();
        let modules = modules.split("  ").next().unwrap_or(modules);
        for module in modules.split(',') {
            let module = module.trim();
            assert!(
                table.insert(module.to_string(), layer).is_none(),
                "{module} is listed twice in the layer table"
            );
        }
    }
    assert!(table.len() > 5, "the layer table is too short: {table:?}");
    table
}

/// The top-level module a path under `src/` belongs to (`None` for lib.rs and the binaries).
fn module_of(path: &Path) -> Option<String> {
    let relative = path.strip_prefix(root().join("src")).ok()?;
    let first = relative.components().next()?.as_os_str().to_str()?;
    match first {
        "lib.rs" | "bin" => None,
        name => Some(name.trim_end_matches(".rs").to_string()),
    }
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).expect("readable source directory") {
        let path = entry.expect("directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Every module a source text names through `crate::name` or `use crate::{a, b::c}`.
fn named_modules(text: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find("crate::") {
        rest = &rest[at + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                names.push(item.trim().split("::").next().unwrap_or("").to_string());
            }
        } else {
            let end = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(rest.len());
            names.push(rest[..end].to_string());
        }
    }
    names
}

#[test]
fn modules_import_only_lower_layers() {
    let layers = layers();
    let mut files = Vec::new();
    rust_files(&root().join("src"), &mut files);
    let mut violations = Vec::new();
    for file in &files {
        let Some(module) = module_of(file) else {
            continue;
        };
        let Some(&layer) = layers.get(&module) else {
            violations.push(format!(
                "{}: module `{module}` is not in the layer table",
                file.display()
            ));
            continue;
        };
        if file.file_name().is_some_and(|n| n == "tests.rs") {
            continue;
        }
        let text = fs::read_to_string(file).expect("readable source");
        let code = text
            .split("#[cfg(test)]\nmod tests")
            .next()
            .unwrap_or(&text);
        for name in named_modules(code) {
            if name == module {
                continue;
            }
            // Items re-exported at the crate root name no module; they are checked where defined.
            let Some(&other) = layers.get(&name) else {
                continue;
            };
            if other >= layer {
                violations.push(format!(
                    "{}: `{module}` (layer {layer}) names `crate::{name}` (layer {other})",
                    file.display()
                ));
            }
        }
    }
    violations.sort();
    violations.dedup();
    assert!(
        violations.is_empty(),
        "layering violations:\n{}",
        violations.join("\n")
    );
}

#[test]
fn the_check_sees_a_violation() {
    // The scanner itself: a lower module naming a higher one is found, in code and in doc links.
    let names = named_modules("use crate::{hull::Hull, grasp};\n/// [`x`](crate::viz::x)\n");
    assert_eq!(names, ["hull", "grasp", "viz"]);
}
