//! Shared helpers for the cross-crate tests: where the workspace is, how to
//! run cargo in it, and whether QEMU is there (a missing QEMU skips a test on
//! a developer's machine and fails it in CI).

use std::path::{Path, PathBuf};
use std::process::Command;

/// The firmware's target triple (Cortex-M4F, hard float).
pub const TARGET: &str = "thumbv7em-none-eabihf";

/// The workspace root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ is in the workspace root")
        .to_path_buf()
}

/// `true` when running in CI (`CI` set, and not to `false` or `0`).
pub fn in_ci() -> bool {
    std::env::var_os("CI").is_some_and(|v| !v.is_empty() && v != "false" && v != "0")
}

/// `true` when `qemu-system-arm` runs.
pub fn qemu_present() -> bool {
    Command::new("qemu-system-arm")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// `true` when QEMU is there. Without it: a failure in CI, otherwise a
/// message on stderr naming `test` and `false` (the caller returns: skipped).
pub fn need_qemu(test: &str) -> bool {
    if qemu_present() {
        return true;
    }
    assert!(
        !in_ci(),
        "qemu-system-arm is missing in CI: run scripts/install-test-deps.sh first"
    );
    eprintln!(
        "SKIPPED {test}: qemu-system-arm not found (run scripts/install-test-deps.sh); \
         never skipped when CI is set"
    );
    false
}

/// `cargo` (the one running the tests) in the workspace root.
pub fn cargo() -> Command {
    let mut c = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    c.current_dir(root());
    c
}
