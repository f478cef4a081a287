//! Every repository path named in README.md, CHANGELOG.md and the Markdown under docs/ exists, so
//! moving a file without updating the prose that points at it fails here.
//!
//! What counts as a path (see [`extract`]):
//! - a Markdown link's target, `[text](target)` or `![alt](target)`, resolved from the directory
//!   of the document that holds it (as GitHub renders it); `http…`/`mailto:` targets and targets
//!   that climb above the workspace root are skipped;
//! - any other token (split at whitespace, backticks, brackets, parentheses, quotes, `|` and `=`)
//!   that starts with a top-level directory ([`DIRS`]) or is a top-level file ([`FILES`]), read
//!   from the workspace root; a leading `./` is dropped and `../…` is skipped, since such paths
//!   (`../shared/meshes/…`) name directories beside the repository, not in it.
//!
//! Fenced code blocks are scanned too (commands name real files), but not for links. A token loses
//! its `#anchor`, its `:line` or `::item` suffix and trailing `.,;:)!?`. A token with a glob or a
//! placeholder (`*`, `{`, `<`, `…`, `$`) is checked only up to the last `/` before it:
//! `fuzz/regressions/<target>/` checks `fuzz/regressions/`. A path exists if it is a file or a
//! directory (`src/grasp/` is fine). [`GENERATED`] lists the few named paths that tools create at
//! run time and git ignores.

use std::fs;
use std::path::Path;

/// The workspace's top-level directories: a token starting with one of them is a path.
const DIRS: &[&str] = &[
    "src/",
    "tests/",
    "cli/",
    "python/",
    "docs/",
    "examples/",
    "benches/",
    "data/",
    "fuzz/",
    ".ci/",
];
/// Top-level files, named bare.
const FILES: &[&str] = &[
    "README.md",
    "CHANGELOG.md",
    "Cargo.toml",
    "Cargo.lock",
    "LICENSE-MIT",
    "LICENSE-APACHE",
];
/// Named in the docs but written at run time, so absent from a fresh checkout.
const GENERATED: &[&str] = &[
    // cargo-fuzz writes crashing inputs here (ignored by fuzz/.gitignore); docs/fuzzing.md says so.
    "fuzz/artifacts/",
];

/// A path named by a document: 1-based line and the path relative to the workspace root.
#[derive(Debug, PartialEq)]
struct Named {
    line: usize,
    path: String,
}

/// Cuts an anchor, a `:line`/`::item` suffix, trailing punctuation, and a glob's or placeholder's
/// tail after its last literal `/`.
fn clean(token: &str) -> &str {
    let end = token.find(['#', ':']).unwrap_or(token.len());
    let path = token[..end].trim_end_matches(['.', ',', ';', ')', '!', '?']);
    match path.find(['*', '{', '<', '…', '$']) {
        Some(at) => &path[..path[..at].rfind('/').map_or(0, |slash| slash + 1)],
        None => path,
    }
}

/// `target` resolved from the directory `base` (relative to the root, `""` for the root itself),
/// or `None` if it climbs out of the workspace.
fn resolve(base: &str, target: &str) -> Option<String> {
    let mut parts: Vec<&str> = base.split('/').filter(|p| !p.is_empty()).collect();
    for part in target.split('/') {
        match part {
            "" | "." => {}
            ".." => {
                parts.pop()?;
            }
            part => parts.push(part),
        }
    }
    Some(parts.join("/"))
}

/// A link target as a root-relative path, if it is a path at all.
fn link_path(base: &str, target: &str) -> Option<String> {
    if target.contains("://") || target.starts_with("mailto:") {
        return None;
    }
    let path = clean(target);
    if path.is_empty() {
        return None; // `#anchor` within the same document
    }
    resolve(base, path)
}

/// A plain token as a root-relative path, if it names one.
fn token_path(token: &str) -> Option<&str> {
    let token = token.trim_start_matches('*'); // `**bold**` emphasis
    let token = token.strip_prefix("./").unwrap_or(token);
    let path = clean(token);
    let named = DIRS.iter().any(|dir| path.starts_with(dir)) || FILES.contains(&path);
    named.then_some(path)
}

/// The paths that the Markdown `text` of the document `doc` (root-relative) names, in order.
fn extract(doc: &str, text: &str) -> Vec<Named> {
    let base = doc.rsplit_once('/').map_or("", |(dir, _)| dir);
    let mut named = Vec::new();
    let mut fenced = false;
    for (index, line) in text.lines().enumerate() {
        let number = index + 1;
        let trimmed = line.trim_start();
        if trimmed.starts_with("```") || trimmed.starts_with("~~~") {
            fenced = !fenced;
            continue;
        }
        // Links first; their targets are then cut from the line so the token pass below does not
        // read a doc-relative target (`paper/fig6.svg`) as root-relative.
        let mut rest = String::new();
        let mut tail = line;
        while !fenced && let Some(at) = tail.find("](") {
            let after = &tail[at + 2..];
            let Some(close) = after.find(')') else { break };
            rest.push_str(&tail[..=at]);
            rest.push(' ');
            let target = after[..close].split_whitespace().next().unwrap_or("");
            if let Some(path) = link_path(base, target) {
                named.push(Named { line: number, path });
            }
            tail = &after[close + 1..];
        }
        rest.push_str(tail);
        let separators = |c: char| c.is_whitespace() || "`()[]\"'|=".contains(c);
        for token in rest.split(separators) {
            if token.starts_with("../") {
                continue; // outside the repository
            }
            if let Some(path) = token_path(token) {
                let path = path.to_owned();
                named.push(Named { line: number, path });
            }
        }
    }
    named
}

/// `doc:line → path` for every path that `text` names and `root` lacks.
fn missing(root: &Path, doc: &str, text: &str) -> Vec<String> {
    extract(doc, text)
        .into_iter()
        .filter(|n| !GENERATED.contains(&n.path.as_str()) && !root.join(&n.path).exists())
        .map(|n| format!("{doc}:{} → {}", n.line, n.path))
        .collect()
}

/// The Markdown files under `dir` (root-relative), recursively, sorted.
fn markdown_under(root: &Path, dir: &str, found: &mut Vec<String>) {
    let mut entries: Vec<_> = fs::read_dir(root.join(dir))
        .unwrap_or_else(|e| panic!("{dir}: {e}"))
        .map(|entry| entry.expect("directory entry"))
        .collect();
    entries.sort_by_key(fs::DirEntry::file_name);
    for entry in entries {
        let name = entry.file_name().into_string().expect("UTF-8 file name");
        let path = format!("{dir}/{name}");
        if entry.file_type().expect("file type").is_dir() {
            markdown_under(root, &path, found);
        } else if name.ends_with(".md") {
            found.push(path);
        }
    }
}

#[test]
fn every_path_named_in_the_docs_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut docs = vec!["README.md".to_owned(), "CHANGELOG.md".to_owned()];
    markdown_under(root, "docs", &mut docs);
    let mut absent = Vec::new();
    let mut checked = 0;
    for doc in &docs {
        let text = fs::read_to_string(root.join(doc)).unwrap_or_else(|e| panic!("{doc}: {e}"));
        checked += extract(doc, &text).len();
        absent.extend(missing(root, doc, &text));
    }
    // An extractor that found nothing would pass vacuously.
    assert!(checked > 0, "no paths found in {docs:?}");
    assert!(
        absent.is_empty(),
        "{} of the {checked} paths named in the docs do not exist:\n{}",
        absent.len(),
        absent.join("\n")
    );
}

#[test]
fn the_extractor_finds_backticked_linked_and_fenced_paths() {
    let text = "\
See `src/lib.rs`, then `tests/integration/main.rs:123`; and (docs/limits.md#scales).
Links: [limits](limits.md#scales), ![trace](images/trace-3d.png), [top](../README.md), [here](#x).
Skipped: `../shared/meshes/spot.obj`, [crate](https://example.org/src/lib.rs), src, `*.rs`.
Globs: `fuzz/fuzz_targets/*.rs` and fuzz/regressions/<target>/; bare CHANGELOG.md.
```sh
./target/release/pqh hull ./data/meshes/spot.obj --mesh=data/meshes/teapot.obj [x](not/a/link.md)
```
";
    let paths: Vec<(usize, &str)> = vec![
        (1, "src/lib.rs"),
        (1, "tests/integration/main.rs"),
        (1, "docs/limits.md"),
        (2, "docs/limits.md"),
        (2, "docs/images/trace-3d.png"),
        (2, "README.md"),
        (4, "fuzz/fuzz_targets/"),
        (4, "fuzz/regressions/"),
        (4, "CHANGELOG.md"),
        (6, "data/meshes/spot.obj"),
        (6, "data/meshes/teapot.obj"),
    ];
    let found = extract("docs/guide.md", text);
    let found: Vec<(usize, &str)> = found.iter().map(|n| (n.line, n.path.as_str())).collect();
    assert_eq!(found, paths);

    // And what is absent is reported with its document and line.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = "`src/lib.rs` is there,\nbut `src/no_such_module.rs:7` is not.\n";
    assert_eq!(
        missing(root, "docs/guide.md", text),
        ["docs/guide.md:2 → src/no_such_module.rs"]
    );
}
