//! Helpers shared by the CLI test binaries of `host-sim/tests`: the built
//! `crane-sim`, the example logs, a replay run and its output.
// Each test binary compiles this module and uses only some of it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `crane-sim` binary cargo built for these tests.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_crane-sim"))
}

/// A file of `examples/logs`.
pub fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../examples/logs")
        .join(name)
}

/// `crane-sim replay LOG EXTRA...`, run to its end.
pub fn replay(log: &Path, extra: &[&str]) -> Output {
    bin()
        .arg("replay")
        .arg(log)
        .args(extra)
        .output()
        .expect("run crane-sim")
}

/// Bytes of an output as text (lossy).
pub fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// stdout parsed as one JSON value.
pub fn json(out: &Output) -> serde_json::Value {
    serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("bad JSON ({e}): {}", text(&out.stdout)))
}
