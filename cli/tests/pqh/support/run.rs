//! Running the `pqh` binary from the CLI tests (included with `#[path]` by each of them).

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

/// Runs `pqh` with `args`, feeding `stdin` (empty if `None`).
pub fn pqh(args: &[&str], stdin: Option<&str>) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn pqh");
    let mut input = child.stdin.take().expect("stdin");
    // pqh may exit (on a usage error) before reading its input: a closed pipe is fine.
    if let Err(e) = input.write_all(stdin.unwrap_or("").as_bytes()) {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "write stdin: {e}");
    }
    drop(input);
    child.wait_with_output().expect("wait for pqh")
}

/// A path for `name`, unique to this test binary.
pub fn temp(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("{}-{name}", env!("CARGO_CRATE_NAME")))
}

/// Writes `contents` to [`temp`]`(name)` and returns its path.
pub fn file(name: &str, contents: &str) -> PathBuf {
    let path = temp(name);
    write_atomically(&path, contents);
    path
}

/// Writes `contents` to `path` through a file of this process's own, renamed into place: tests
/// of one binary run in parallel processes (nextest), and one writing a shared input while
/// another reads it let the reader see it truncated ("mesh is empty").
pub fn write_atomically(path: &std::path::Path, contents: &str) {
    let staging = path.with_extension(format!("{}.partial", std::process::id()));
    std::fs::write(&staging, contents).expect("write test input");
    std::fs::rename(&staging, path).expect("move test input into place");
}
