//! The firmware fails safe (issue 12, item 5):
//!
//! - a HardFault triggered on purpose in the QEMU build cuts the outputs
//!   before anything else (the QEMU build's outputs record the commanded state
//!   in RAM; the handler cuts them and prints that state over semihosting);
//! - the power-up self-test passes on a clean image (stamped or, under QEMU
//!   only, unstamped) and fails, with the outputs kept cut, on an image whose
//!   stamped checksum is wrong or whose code was altered after stamping;
//! - the model reference table the self-test compares against is what the
//!   shipped model computes on the host in `f32`.
//!
//! The power-cut tests of the persisted settings are in
//! `crates/limiter-storage/tests/power_cut.rs` (host, mock flash).
//!
//! Needs `qemu-system-arm`, the `thumbv7em-none-eabihf` target and
//! `arm-none-eabi-objcopy` (`scripts/install-test-deps.sh`); without QEMU the
//! QEMU tests skip with a message unless `CI` is set.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

#[path = "../firmware/src/model_reference.rs"]
#[allow(dead_code)]
mod model_reference;

use crane_tests::{cargo, need_qemu, root, TARGET};

/// The QEMU image, built once (`cargo build --release`, a no-op when fresh),
/// and the stamp tool.
fn firmware() -> &'static PathBuf {
    static ELF: OnceLock<PathBuf> = OnceLock::new();
    ELF.get_or_init(|| {
        let status = cargo()
            .args(["build", "--release", "-p", "firmware", "--target", TARGET])
            .status()
            .expect("cargo runs");
        assert!(status.success(), "firmware build failed");
        let status = cargo()
            .args([
                "build",
                "--release",
                "-p",
                "limiter-storage",
                "--bin",
                "stamp-image",
            ])
            .status()
            .expect("cargo runs");
        assert!(status.success(), "stamp-image build failed");
        root()
            .join("target")
            .join(TARGET)
            .join("release")
            .join("firmware")
    })
}

/// A copy of the firmware image in a fresh temporary file, stamped if asked.
fn image_copy(name: &str, stamped: bool) -> PathBuf {
    let dir = root().join("target").join("firmware-failsafe-test");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::copy(firmware(), &path).expect("copy the image");
    if stamped {
        let out = Command::new(root().join("target/release/stamp-image"))
            .arg(&path)
            .output()
            .expect("stamp-image runs");
        assert!(
            out.status.success(),
            "stamp-image failed: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    path
}

struct Run {
    stdout: String,
    stderr: String,
    code: i32,
}

fn qemu(elf: &Path, args: &[&str]) -> Run {
    let out = Command::new(root().join("scripts/qemu-runner.sh"))
        .arg(elf)
        .args(args)
        .env("QEMU_TIMEOUT", "60")
        .current_dir(root())
        .output()
        .expect("qemu-runner runs");
    Run {
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        code: out.status.code().unwrap_or(-1),
    }
}

fn smoke_log() -> String {
    root()
        .join("tests/data/qemu_smoke.csv")
        .display()
        .to_string()
}

/// Finds the stamp (by its magic) in an ELF file: offset of the magic.
fn stamp_offset(elf: &[u8]) -> usize {
    let magic = limiter_storage::image::STAMP_MAGIC;
    let hits: Vec<usize> = elf
        .windows(magic.len())
        .enumerate()
        .filter(|(_, w)| *w == magic)
        .map(|(i, _)| i)
        .collect();
    assert_eq!(hits.len(), 1, "the stamp magic must occur once in the ELF");
    hits[0]
}

#[test]
fn hardfault_cuts_the_outputs_first() {
    if !need_qemu("firmware_failsafe") {
        return;
    }
    let r = qemu(firmware(), &[&smoke_log(), "--trigger-hardfault"]);
    // Before the fault the simulated limiter granted motion (permit relays
    // energised): the handler, not start-up code, must have cut them.
    assert!(
        r.stderr.contains(
            "outputs before the fault: permit-boom-down=energised permit-hoist-up=energised"
        ),
        "the test did not energise the permits first; stderr:\n{}",
        r.stderr
    );
    assert!(
        r.stderr.contains("HardFault")
            && r.stderr
                .contains("outputs: permit-boom-down=cut permit-hoist-up=cut warning=on alarm=on"),
        "HardFault did not report the outputs cut; stderr:\n{}",
        r.stderr
    );
    assert!(
        r.stdout.is_empty(),
        "no replay output after a fault: {}",
        r.stdout
    );
    assert_eq!(
        r.code, 2,
        "a firmware fault exits 2 (FAULT); stderr:\n{}",
        r.stderr
    );
}

#[test]
fn self_test_passes_on_a_clean_stamped_image_and_replay_is_unchanged() {
    if !need_qemu("firmware_failsafe") {
        return;
    }
    let elf = image_copy("stamped.elf", true);
    let r = qemu(&elf, &[&smoke_log(), "--self-test"]);
    let plain = qemu(firmware(), &[&smoke_log()]);
    // The smoke log ends in a sensor FAULT: exit 2 from the replay itself.
    assert_eq!(r.code, plain.code, "stderr:\n{}", r.stderr);
    let line = r
        .stderr
        .lines()
        .find(|l| l.starts_with("self-test: passed"))
        .unwrap_or_else(|| panic!("no self-test line; stderr:\n{}", r.stderr));
    assert!(line.contains("image=crc32:"), "{line}");
    assert!(line.contains(&format!("model={}/{}", 4, 4)), "{line}");
    assert!(
        r.stdout.contains("final_state="),
        "the replay ran: {}",
        r.stdout
    );
    assert_eq!(
        r.stdout, plain.stdout,
        "the stamped image replays like the plain one"
    );
}

#[test]
fn unstamped_qemu_image_runs_and_says_so() {
    if !need_qemu("firmware_failsafe") {
        return;
    }
    let r = qemu(firmware(), &[&smoke_log(), "--self-test"]);
    assert!(
        r.stdout.contains("final_state="),
        "the replay ran: {}",
        r.stdout
    );
    assert!(
        r.stderr.contains("self-test: passed") && r.stderr.contains("image=not-stamped"),
        "stderr:\n{}",
        r.stderr
    );
}

#[test]
fn self_test_fails_on_a_wrong_stamped_checksum() {
    if !need_qemu("firmware_failsafe") {
        return;
    }
    let elf = image_copy("bad-crc.elf", true);
    let mut bytes = std::fs::read(&elf).unwrap();
    let at = stamp_offset(&bytes);
    bytes[at + 12] ^= 0x01; // the stamped CRC
    std::fs::write(&elf, &bytes).unwrap();
    let r = qemu(&elf, &[&smoke_log()]);
    assert!(
        r.stderr
            .contains("self-test failed: image: image checksum mismatch"),
        "stderr:\n{}",
        r.stderr
    );
    assert!(
        r.stderr
            .contains("outputs: permit-boom-down=cut permit-hoist-up=cut"),
        "{}",
        r.stderr
    );
    assert!(
        r.stdout.is_empty(),
        "the limiter must not run: {}",
        r.stdout
    );
    assert_eq!(r.code, 2);
}

#[test]
fn self_test_fails_on_code_altered_after_stamping() {
    if !need_qemu("firmware_failsafe") {
        return;
    }
    let elf = image_copy("bad-code.elf", true);
    let mut bytes = std::fs::read(&elf).unwrap();
    // Alter one byte of the stamp's neighbourhood that is part of the image
    // but not of the stamp: the 8 bytes of magic are covered by the CRC, and
    // a changed magic is a missing stamp; alter the byte right after instead.
    let at = stamp_offset(&bytes) + limiter_storage::image::STAMP_LEN;
    bytes[at] ^= 0x80;
    std::fs::write(&elf, &bytes).unwrap();
    let r = qemu(&elf, &[&smoke_log()]);
    assert!(
        r.stderr
            .contains("self-test failed: image: image checksum mismatch"),
        "stderr:\n{}",
        r.stderr
    );
    assert_eq!(r.code, 2);
}

#[test]
fn model_reference_table_matches_the_shipped_model() {
    // The model behind firmware/src/model.rs::hook_load_model(); keep these two
    // in step (see firmware/README.md, "The model seam").
    let model = crane_model::loads::thesis_modes::thesis_load_model_f32();
    let mut table = String::new();
    let mut all_agree = true;
    for p in &model_reference::REFERENCE {
        let (f, j) = model_reference::evaluate(&model, p)
            .expect("the model evaluates at the reference points");
        all_agree &= model_reference::agrees(f, p.piston_force_n)
            && model_reference::agrees(j, p.jack_reaction_n);
        table += &format!(
            "    ModelPoint {{ angle_deg: {:?}, rate_rad_s: {:?}, load_kg: {:?}, piston_force_n: {:?}, jack_reaction_n: {:?} }},\n",
            p.angle_deg, p.rate_rad_s, p.load_kg, f, j
        );
    }
    assert!(
        all_agree,
        "firmware/src/model_reference.rs is stale; the model now gives:\n{table}"
    );
    // The check itself refuses a perturbed model value.
    let p = model_reference::REFERENCE[1];
    assert!(!model_reference::agrees(
        p.piston_force_n * 1.001,
        p.piston_force_n
    ));
    assert!(!model_reference::agrees(f32::NAN, p.piston_force_n));
    assert_eq!(
        model_reference::check(&model),
        Ok(model_reference::REFERENCE.len())
    );
}
