//! The library's layers import only downward: a top-level module of `src/` may name (in code or in
//! doc links) only modules of lower layers, never one of its own layer or above. The layers are
//! read from the table in docs/ARCHITECTURE.md, so the drawing there is the rule enforced here;
//! every top-level module of `src/` must appear in it.
//!
//! A small tokenizer (a literal is one token, so its braces and quotes cannot derail the rest) and
//! a use-tree reader that follows each group to its *matching* brace find every path. A path names
//! a top-level module when, resolved from the crate root, it starts with that module
//! (`crate::viz`, `super::super::viz` two levels down, `c::viz` after `use crate::{self as c}`)
//! or with a name lib.rs imports from it (`crate::Hull` names `hull`).
//!
//! Unit-test modules (`#[cfg(test)] mod …`, `tests.rs`) are exempt: tests may build their inputs
//! from anything (e.g. `rbox`'s point families).

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Module name → layer, from the block of docs/ARCHITECTURE.md that starts with `layer  modules`.
fn layers() -> BTreeMap<String, usize> {
    let doc = fs::read_to_string(root().join("docs/ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let mut lines = doc.lines().skip_while(|l| !l.starts_with("layer  modules"));
    assert!(lines.next().is_some(), "no `layer  modules` table");
    let mut table = BTreeMap::new();
    for line in lines.take_while(|l| !l.starts_with("```")) {
        // `  6    grasp, mesh    what it holds`: a number, then modules up to a run of spaces;
        // a line without a number continues the description above it.
        let (number, rest) = line.trim_start().split_once(' ').unwrap_or_default();
        let Ok(layer) = number.parse() else { continue };
        let modules = rest.trim_start().split("  ").next().unwrap_or("");
        for module in modules.split(',').map(|m| m.trim().to_string()) {
            let twice = table.insert(module.clone(), layer).is_some();
            assert!(!twice, "{module} is listed twice");
        }
    }
    assert!(table.len() > 5, "the layer table is too short: {table:?}");
    table
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    /// Identifiers, keywords, numbers, `$crate`.
    Ident(String),
    /// `::`
    Sep,
    Punct(char),
    /// A string or char literal: its text names nothing and its braces are not the code's.
    Lit,
    /// A comment, as the paths written in it (doc links: ``[`x`](crate::viz::x)``).
    Doc(Vec<Vec<String>>),
}

/// The tokens of a source text, each with its line.
fn tokenize(text: &str) -> Vec<(usize, Tok)> {
    let c: Vec<char> = text.chars().collect();
    let at = |k: usize| c.get(k).copied().unwrap_or('\0');
    let word = |ch: char| ch.is_alphanumeric() || ch == '_';
    let find = |from: usize, ch: char| (from..c.len()).find(|&k| c[k] == ch).unwrap_or(c.len());
    let doc = |from: usize, end: usize| {
        let text: String = c[from..end].iter().collect();
        (end, Some(Tok::Doc(comment_paths(&text))))
    };
    let (mut i, mut line, mut out) = (0, 1, Vec::new());
    while i < c.len() {
        let (end, tok) = match (c[i], at(i + 1), at(i + 2)) {
            (ch, ..) if ch.is_whitespace() => (i + 1, None),
            ('/', '/', _) => doc(i, find(i, '\n')),
            ('/', '*', _) => doc(i, block_comment_end(&c, i)),
            ('"', ..) => (string_end(&c, i + 1, 0, false), Some(Tok::Lit)),
            // `'\''`, `'{'`; any other `'` starts a lifetime or a label, left as punctuation.
            ('\'', '\\', _) => ((find(i + 3, '\'') + 1).min(c.len()), Some(Tok::Lit)),
            ('\'', _, '\'') => (i + 3, Some(Tok::Lit)),
            (':', ':', _) => (i + 2, Some(Tok::Sep)),
            (ch, next, _) if word(ch) || (ch == '$' && word(next)) => {
                let end = (i + 1..=c.len()).find(|&k| !word(at(k))).unwrap_or(c.len());
                let w: String = c[i..end].iter().collect();
                // Raw strings (`r"…"`, `br#"…"#`): no escapes, closed by `"` and as many `#`s.
                // `b"…"` is the word `b`, then an ordinary literal.
                let hashes = c[end..].iter().take_while(|&&h| h == '#').count();
                let start = end + hashes + 1;
                match matches!(w.as_str(), "r" | "br" | "cr") && at(start - 1) == '"' {
                    true => (string_end(&c, start, hashes, true), Some(Tok::Lit)),
                    false => (end, Some(Tok::Ident(w))),
                }
            }
            (ch, ..) => (i + 1, Some(Tok::Punct(ch))),
        };
        out.extend(tok.map(|tok| (line, tok)));
        line += c[i..end].iter().filter(|&&ch| ch == '\n').count();
        i = end;
    }
    out
}

/// The index after the block comment at `i`: block comments nest (`/* a /* b */ still a */`).
fn block_comment_end(c: &[char], mut i: usize) -> usize {
    let mut depth = 0;
    while i + 1 < c.len() {
        match (c[i], c[i + 1]) {
            ('/', '*') => (depth, i) = (depth + 1, i + 2),
            ('*', '/') if depth == 1 => return i + 2,
            ('*', '/') => (depth, i) = (depth - 1, i + 2),
            _ => i += 1,
        }
    }
    c.len()
}

/// The index after a string literal whose text starts at `i`; a raw one (where `\` escapes
/// nothing) closes with `"` and `hashes` `#`s.
fn string_end(c: &[char], mut i: usize, hashes: usize, raw: bool) -> usize {
    while i < c.len() {
        let closes = || c[i + 1..].iter().take_while(|&&h| h == '#').count() >= hashes;
        match c[i] {
            '\\' if !raw => i += 2,
            '"' if closes() => return i + 1 + hashes,
            _ => i += 1,
        }
    }
    c.len()
}

/// Every run of word characters and `::` that holds a `::`, split into segments.
fn comment_paths(text: &str) -> Vec<Vec<String>> {
    let path_char = |ch: char| ch.is_alphanumeric() || matches!(ch, '_' | ':' | '$');
    let runs = text.split(|ch| !path_char(ch)).filter(|r| r.contains("::"));
    let paths = runs.map(|r| r.split("::").map(String::from).collect());
    paths.collect()
}

/// A path: its line, where it leads from the crate root, how it was written, and the name it
/// binds if it is a leaf of a `use` tree (its alias, else its last segment).
struct Written {
    line: usize,
    path: Vec<String>,
    text: String,
    binds: Option<String>,
}

#[derive(Default)]
struct Scanner {
    t: Vec<(usize, Tok)>,
    i: usize,
    /// The module the cursor is in: the file's, then any inline `mod name {`.
    scope: Vec<String>,
    /// The file's other names for the crate root (`use crate::{self as c}`), declared before use.
    roots: BTreeSet<String>,
    out: Vec<Written>,
}

impl Scanner {
    fn tok(&self, k: usize) -> Option<&Tok> {
        self.t.get(self.i + k).map(|t| &t.1)
    }
    fn is(&self, k: usize, tok: Tok) -> bool {
        self.tok(k) == Some(&tok)
    }
    fn ident(&self, k: usize) -> Option<String> {
        match self.tok(k) {
            Some(Tok::Ident(w)) => Some(w.clone()),
            _ => None,
        }
    }

    /// Records a path, resolved: `crate` and the root's other names start at the root, anything
    /// else in the module written in. `super` climbs from there (out of the top-level module
    /// after as many as its depth; above the root is not Rust), and a bare path (`use quality::X`,
    /// `std::…`) stays inside, where it names nothing another module could be blamed for.
    fn record(&mut self, line: usize, written: Vec<String>, binds: Option<String>) {
        let first = written.first().map_or("", String::as_str);
        let from_root = matches!(first, "crate" | "$crate") || self.roots.contains(first);
        let mut path = if from_root {
            Vec::new()
        } else {
            self.scope.clone()
        };
        for segment in &written[usize::from(from_root)..] {
            match segment.as_str() {
                "super" if path.pop().is_none() => return, // the guard climbs
                "super" | "self" => {} // `self`: leading, or `{self}`, the module reached so far
                _ => path.push(segment.clone()),
            }
        }
        if let (Some(name), true) = (&binds, path.is_empty()) {
            self.roots.insert(name.clone());
        }
        let text = written.join("::");
        self.out.push(Written {
            line,
            path,
            text,
            binds,
        });
    }

    /// Moves past the bracketed group at the cursor (an attribute, a test module's body).
    fn skip_group(&mut self) {
        let mut depth = 0;
        while let Some(tok) = self.tok(0) {
            depth += match tok {
                Tok::Punct('{' | '[' | '(') => 1,
                Tok::Punct('}' | ']' | ')') => -1,
                _ => 0,
            };
            self.i += 1;
            if depth == 0 {
                break;
            }
        }
    }

    /// Reads the use tree at the cursor (a plain path is a tree without a group), recording each
    /// leaf as `prefix` and its own segments. A group ends at its matching brace, not the first
    /// one, and each of its items may be a group again: hence the recursion.
    fn tree(&mut self, mut prefix: Vec<String>, in_use: bool) {
        let line = self.t.get(self.i).map_or(0, |t| t.0);
        loop {
            match self.tok(0).cloned() {
                Some(Tok::Doc(paths)) => {
                    // A comment, in a group too, names what its paths name as they are written.
                    self.i += 1;
                    return paths.into_iter().for_each(|p| self.record(line, p, None));
                }
                Some(Tok::Ident(w)) if w != "as" => prefix.push(w),
                Some(Tok::Punct('*')) => prefix.push("*".into()),
                Some(Tok::Punct('{')) => {
                    self.i += 1;
                    while !matches!(self.tok(0), None | Some(Tok::Punct('}'))) {
                        let before = self.i;
                        self.tree(prefix.clone(), in_use);
                        if self.is(0, Tok::Punct(',')) || self.i == before {
                            self.i += 1;
                        }
                    }
                    self.i += 1;
                    return;
                }
                _ => break,
            }
            self.i += 1;
            if !self.is(0, Tok::Sep) {
                break;
            }
            self.i += 1; // `::`, then a segment, a group, a glob, or (in code) `<…>`
        }
        let mut binds = prefix.iter().rev().find(|s| *s != "self").cloned();
        if self.ident(0).as_deref() == Some("as") {
            binds = self.ident(1);
            self.i += 2;
        }
        self.record(line, prefix, binds.filter(|_| in_use));
    }
}

/// Every path a source text writes, in module `scope`.
fn scan(text: &str, scope: &[String]) -> Vec<Written> {
    let mut s = Scanner::default();
    (s.t, s.scope) = (tokenize(text), scope.to_vec());
    let cfg_test: Vec<Tok> = tokenize("#[cfg(test)]").into_iter().map(|t| t.1).collect();
    // The brace depth, and the depth at which each open inline `mod name {` began.
    let (mut depth, mut inline) = (0, Vec::new());
    while let Some(tok) = s.tok(0).cloned() {
        if (0..cfg_test.len()).all(|k| s.tok(k) == Some(&cfg_test[k])) {
            // `#[cfg(test)]`, more attributes or comments, then `mod`: a unit-test module, exempt.
            // Any other item is read as usual.
            s.i += cfg_test.len();
            while s.is(0, Tok::Punct('#')) || matches!(s.tok(0), Some(Tok::Doc(_))) {
                s.i += usize::from(s.is(0, Tok::Punct('#')));
                s.skip_group();
            }
            if s.ident(0).as_deref() == Some("mod") && s.is(2, Tok::Punct('{')) {
                s.i += 2;
                s.skip_group();
            }
            continue;
        }
        match tok {
            Tok::Ident(w) if w == "use" => {
                s.i += 1;
                s.tree(Vec::new(), true);
            }
            Tok::Ident(w) if w == "mod" && s.is(2, Tok::Punct('{')) => {
                s.scope.push(s.ident(1).unwrap_or_default());
                inline.push(depth);
                depth += 1;
                s.i += 3;
            }
            Tok::Ident(_) if s.is(1, Tok::Sep) => s.tree(Vec::new(), false),
            Tok::Doc(_) => s.tree(Vec::new(), false),
            Tok::Punct('{') => {
                depth += 1;
                s.i += 1;
            }
            Tok::Punct('}') => {
                depth -= 1;
                if inline.last() == Some(&depth) {
                    inline.pop();
                    s.scope.pop();
                }
                s.i += 1;
            }
            _ => s.i += 1,
        }
    }
    s.out
}

/// Root name → the module it comes from, from lib.rs's `use` items (`pub use hull::{Hull, …};`):
/// `crate::Hull` names `hull` as surely as `crate::hull::Hull` does. Private imports count too:
/// the root's child modules can reach them.
fn reexports(lib: &str, layers: &BTreeMap<String, usize>) -> BTreeMap<String, String> {
    let mut map = BTreeMap::new();
    for w in scan(lib, &[]) {
        let (Some(name), Some(module)) = (w.binds, w.path.first()) else {
            continue;
        };
        if layers.contains_key(module) {
            assert!(name != "*", "lib.rs glob-imports {}", w.text);
            map.insert(name, module.clone());
        }
    }
    map
}

/// The layers, and lib.rs's root imports: what sources are checked against.
struct Crate {
    layers: BTreeMap<String, usize>,
    reexports: BTreeMap<String, String>,
}

impl Crate {
    fn new(layers: BTreeMap<String, usize>) -> Crate {
        let lib = fs::read_to_string(root().join("src/lib.rs")).expect("src/lib.rs");
        let reexports = reexports(&lib, &layers);
        Crate { layers, reexports }
    }

    /// (line, top-level module, path as written) for each path of `text` naming one; the module
    /// is `*` for a glob of the crate root, which names them all.
    fn named(&self, scope: &[String], text: &str) -> Vec<(usize, String, String)> {
        let name = |w: Written| {
            let first = w.path.first()?;
            let module = match self.reexports.get(first) {
                _ if self.layers.contains_key(first) || first == "*" => first,
                reexport => reexport?,
            };
            Some((w.line, module.clone(), w.text))
        };
        scan(text, scope).into_iter().filter_map(name).collect()
    }
}

/// Every file under `dir` but the root's lib.rs and bin/, with its module path
/// (`grasp/quality/minkowski.rs` → grasp, quality, minkowski; a `mod.rs` is its directory's).
fn source_files(dir: &Path, scope: &[String], out: &mut Vec<(PathBuf, Vec<String>)>) {
    let entries = fs::read_dir(dir).expect("a source directory");
    let mut paths: Vec<PathBuf> = entries.map(|e| e.expect("an entry").path()).collect();
    paths.sort();
    for path in paths {
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let inner = [scope, std::slice::from_ref(&name)].concat();
        if path.is_dir() && !(scope.is_empty() && name == "bin") {
            source_files(&path, &inner, out);
        } else if path.extension().is_some_and(|e| e == "rs") && inner != ["lib"] {
            out.push((path, if name == "mod" { scope.to_vec() } else { inner }));
        }
    }
}

#[test]
fn modules_import_only_lower_layers() {
    let krate = Crate::new(layers());
    let mut files = Vec::new();
    source_files(&root().join("src"), &[], &mut files);
    let (mut violations, mut seen) = (Vec::new(), 0);
    for (path, scope) in &files {
        let file = path.strip_prefix(root()).unwrap_or(path).display();
        let module = &scope[0];
        let Some(&layer) = krate.layers.get(module) else {
            violations.push(format!("{file}: module `{module}` has no layer"));
            continue;
        };
        if path.ends_with("tests.rs") {
            continue;
        }
        let text = fs::read_to_string(path).expect("a readable source");
        for (line, named, written) in krate.named(scope, &text) {
            let other = krate.layers.get(&named).copied(); // `None`: `*`, every layer
            seen += usize::from(named != *module);
            if named == *module || other.is_some_and(|other| other < layer) {
                continue;
            }
            let other = other.map_or("every layer".into(), |other| format!("layer {other}"));
            let here = format!("{file}:{line}: module `{module}` (layer {layer})");
            violations.push(format!("{here} names `{named}` ({other}) via `{written}`"));
        }
    }
    // A table entry with no module behind it is a stale drawing of the layers.
    for module in krate.layers.keys() {
        if !files.iter().any(|(_, scope)| &scope[0] == module) {
            violations.push(format!(
                "docs/ARCHITECTURE.md: `{module}` is in the layer table but not in src/"
            ));
        }
    }
    // A scanner that sees nothing passes everything: src/ names lower modules hundreds of times.
    assert!(seen > 100, "only {seen} names of other modules found");
    violations.dedup();
    let report = violations.join("\n");
    assert!(report.is_empty(), "layering violations:\n{report}");
}

/// Each evasion, planted: `module | source text | the modules it names, repeats dropped`.
const PLANTED: &[&str] = &[
    // A group is read to its matching brace: what follows a nested group is seen.
    "mesh | use crate::{hull::{Hull}, viz}; | hull viz",
    "mesh | use crate::{a::{b::{C, D}}, grasp::{x}}; | grasp",
    // A root re-export names the module lib.rs takes it from.
    "mesh | use crate::{Hull}; | hull",
    "mesh | fn f() -> crate::ClosestToOrigin { todo!() } | strategy",
    "mesh | use crate::{Hull, OwsInflation}; | hull strategy",
    // `super` climbs from the module written in; past the root it is not Rust and names nothing.
    "grasp::quality::minkowski | use super::super::super::viz::Scene; | viz",
    "grasp::quality::minkowski | let h = super::super::super::Hull::new(); | hull",
    "grasp::quality::minkowski | use super::{super::super::plan::Plan}; | plan",
    "grasp::quality::minkowski | use super::super::metrics; use self::x; | grasp",
    "grasp::quality::minkowski | use super::super::super::super::viz; | ",
    "grasp | mod inner {\n    use super::super::viz;\n}\nuse super::plan; | viz plan",
    // Doc links name modules.
    "mesh | /// See [`x`](crate::viz::x).\nfn f() {} | viz",
    "mesh::io | //! Drawn by [`Scene`](super::super::viz::Scene). | viz",
    "mesh | /** [`Plan`][crate::plan::Plan] /* nested */ */ | plan",
    // Other names for the crate root.
    "mesh | use crate::{self as c};\nfn f() { c::viz::draw() } | viz",
    "mesh | macro_rules! m { () => { $crate::viz::draw() } } | viz",
    "mesh | use crate::*; | *",
    MULTI_LINE,
    // Literals name nothing, and their braces and quotes do not derail what follows.
    r###"mesh | let s = "crate::viz \" {"; let r = r#"crate::{plan} "{"#; let c = '{';
        let q = '\''; fn f<'a>(x: &'a str) {} use crate::{hull::Hull, grasp}; | hull grasp"###,
    // A test module is exempt, to its real closing brace, but not what follows it.
    "mesh | #[cfg(test)]\n// its tests\n#[allow(unused)]\nmod tests {\n    \
        fn f() { let _ = '}'; } /* a /* } */ } */\n    use crate::viz;\n}\nuse crate::plan; | plan",
];

/// A multi-line group with comments, braces in them.
const MULTI_LINE: &str =
    "mesh | use crate::{\n    // the engine }\n    hull::{Hull, /* } */ Facet},
    /* { */ grasp::{\n        x, // }\n    },\n}; | hull grasp";

#[test]
fn the_scanner_catches_each_planted_evasion() {
    // A fixed layer table (this test must not move with the doc), and lib.rs's real imports.
    let t: Vec<&str> = "geometry 0 hull 2 strategy 3 mesh 5 grasp 6 plan 7 viz 8"
        .split(' ')
        .collect();
    let layers = t.chunks(2).map(|w| (w[0].into(), w[1].parse().unwrap()));
    let krate = Crate::new(layers.collect());
    let named = |case: &'static str| {
        let (module, rest) = case.split_once(" | ").unwrap();
        let (text, want) = rest.rsplit_once(" | ").unwrap();
        let scope: Vec<String> = module.split("::").map(String::from).collect();
        (krate.named(&scope, text), want)
    };
    for case in PLANTED {
        let (named, want) = named(case);
        let mut names: Vec<&str> = named.iter().map(|n| n.1.as_str()).collect();
        names.dedup();
        let want: Vec<&str> = want.split_whitespace().collect();
        assert_eq!(names, want, "{case}");
    }
    // The lines reported are the leaves' (`x` of `grasp::{x}` is on line 5).
    let lines: Vec<usize> = named(MULTI_LINE).0.iter().map(|n| n.0).collect();
    assert_eq!(lines, [3, 3, 5]);
    // lib.rs is read by the same tree reader: nested groups, `self`, aliases.
    let lib = "pub use hull::{a::{B, c::D}, E as F};\npub use crate::strategy::{self as s};";
    let lib: Vec<_> = reexports(lib, &krate.layers).into_iter().collect();
    let want: Vec<&str> = "B hull D hull F hull s strategy".split(' ').collect();
    let want: Vec<_> = want.chunks(2).map(|w| (w[0].into(), w[1].into())).collect();
    assert_eq!(lib, want);
}
