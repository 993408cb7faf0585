//! The calibration's stored form on the target (issue 12 item 5, the board
//! applies its stored calibration): `calibration-image --blob` makes the blob
//! from a validated `CAL.json`; the QEMU image decodes it with the board's
//! start-up code (`--calibration-blob`) and replays every example log exactly
//! as with the JSON file; a corrupt, foreign or out-of-bounds blob is refused
//! with exit 1 and the reason, as the board refuses to grant motion.
//!
//! Needs `qemu-system-arm` (`scripts/install-test-deps.sh`); without it the
//! test skips with a message unless `CI` is set.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use crane_tests::{cargo, need_qemu, root, TARGET};
use limiter_storage::calibration_blob::{BLOB_FORMAT, BLOB_LEN, BLOB_MAGIC};
use limiter_storage::crc::crc32;

/// The QEMU image and the host tool, built once.
fn built() -> &'static (PathBuf, PathBuf) {
    static BUILT: OnceLock<(PathBuf, PathBuf)> = OnceLock::new();
    BUILT.get_or_init(|| {
        for args in [
            &["build", "--release", "-p", "firmware", "--target", TARGET][..],
            &[
                "build",
                "--release",
                "-p",
                "limiter-storage",
                "--bin",
                "calibration-image",
            ][..],
        ] {
            let status = cargo().args(args).status().expect("cargo runs");
            assert!(status.success(), "cargo {args:?} failed");
        }
        (
            root().join("target").join(TARGET).join("release/firmware"),
            root().join("target/release/calibration-image"),
        )
    })
}

fn dir() -> PathBuf {
    let d = root().join("target").join("calibration-blob-test");
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

struct Run {
    stdout: String,
    stderr: String,
    code: i32,
}

fn qemu(args: &[&str]) -> Run {
    let out = Command::new(root().join("scripts/qemu-runner.sh"))
        .arg(&built().0)
        .args(args)
        .env("QEMU_TIMEOUT", "120")
        .current_dir(root())
        .output()
        .expect("qemu-runner runs");
    Run {
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        code: out.status.code().unwrap_or(-1),
    }
}

fn make_blob(cal_json: &Path, out: &Path) -> std::process::Output {
    Command::new(&built().1)
        .arg(cal_json)
        .arg(out)
        .arg("--blob")
        .output()
        .expect("calibration-image runs")
}

fn example_logs() -> Vec<PathBuf> {
    let mut logs: Vec<PathBuf> = std::fs::read_dir(root().join("examples/logs"))
        .expect("examples/logs")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "csv"))
        .collect();
    logs.sort();
    assert!(logs.len() >= 3, "example logs missing");
    logs
}

#[test]
fn the_blob_replays_exactly_like_the_json_it_was_made_from() {
    if !need_qemu("firmware_calibration_blob") {
        return;
    }
    let cal = root().join("examples/logs/cal.json");
    let blob = dir().join("cal.bin");
    let made = make_blob(&cal, &blob);
    assert!(
        made.status.success(),
        "{}",
        String::from_utf8_lossy(&made.stderr)
    );
    assert_eq!(std::fs::read(&blob).unwrap().len(), BLOB_LEN);
    let (cal, blob) = (cal.display().to_string(), blob.display().to_string());
    let mut differs_from_uncalibrated = 0;
    for log in example_logs() {
        let log = log.display().to_string();
        let json = qemu(&[&log, "--calibration", &cal, "--json"]);
        let from_blob = qemu(&[&log, "--calibration-blob", &blob, "--json"]);
        assert_eq!(json.code, from_blob.code, "{log}: exit codes differ");
        assert_eq!(
            json.stdout, from_blob.stdout,
            "{log}: JSON and blob replays differ"
        );
        assert_eq!(json.stderr, from_blob.stderr, "{log}: messages differ");
        if json.code == 1 {
            // malformed.csv: the log itself is refused, with either.
            continue;
        }
        assert!(
            from_blob.stdout.contains("\"calibrated\":true"),
            "{}",
            from_blob.stdout
        );
        let none = qemu(&[&log, "--json"]);
        if none
            .stdout
            .replace("\"calibrated\":false", "\"calibrated\":true")
            != json.stdout
        {
            differs_from_uncalibrated += 1;
        }
    }
    // The calibration is applied, not just read: it changes what the limiter sees.
    assert!(
        differs_from_uncalibrated > 0,
        "the calibration changed no replay"
    );
}

#[test]
fn refused_calibration_files_and_blobs_exit_1_naming_the_reason() {
    if !need_qemu("firmware_calibration_blob") {
        return;
    }
    let d = dir();
    let log = root()
        .join("examples/logs/overload_lowering.csv")
        .display()
        .to_string();
    // The tool refuses a file the schema refuses, naming the key.
    let bad_json = d.join("bad.json");
    std::fs::write(
        &bad_json,
        moment_limiter::tools::config_file::hostile::with("p1_offset_bar", Some("50")),
    )
    .unwrap();
    let out = make_blob(&bad_json, &d.join("never.bin"));
    assert_eq!(out.status.code(), Some(1));
    let msg = String::from_utf8_lossy(&out.stderr);
    assert!(msg.contains("`p1_offset_bar` = 50 is outside"), "{msg}");
    assert!(!d.join("never.bin").exists(), "a refused file made a blob");

    let good = {
        let p = d.join("good.bin");
        assert!(make_blob(&root().join("examples/logs/cal.json"), &p)
            .status
            .success());
        std::fs::read(p).unwrap()
    };
    let with_crc = |mut body: Vec<u8>| {
        body.truncate(BLOB_LEN - 4);
        let crc = crc32(&body);
        body.extend_from_slice(&crc.to_le_bytes());
        body
    };
    let mut flipped = good.clone();
    flipped[20] ^= 0x04;
    let mut schema6 = good.clone();
    schema6[6] = 6;
    let mut format6 = good.clone();
    format6[4..6].copy_from_slice(&(BLOB_FORMAT + 1).to_le_bytes());
    let mut p1_50 = good.clone();
    p1_50[8 + 3 * 8..8 + 4 * 8].copy_from_slice(&50.0f64.to_le_bytes());
    let mut nan = good.clone();
    nan[8..16].copy_from_slice(&f64::NAN.to_le_bytes());
    let mut long = good.clone();
    long.push(0);
    let (short, longer) = (format!("wrong length ({} bytes", BLOB_LEN - 1), format!("wrong length ({} bytes", BLOB_LEN + 1));
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("bit flip", flipped, "CRC mismatch"),
        (
            "truncated",
            good[..BLOB_LEN - 1].to_vec(),
            &short,
        ),
        ("one byte long", long, &longer),
        ("empty", Vec::new(), "wrong length (0 bytes"),
        (
            "erased flash",
            vec![0xFF; BLOB_LEN],
            "not a calibration blob",
        ),
        (
            "the JSON file itself",
            std::fs::read(root().join("examples/logs/cal.json")).unwrap(),
            "wrong length",
        ),
        (
            "schema version 6",
            with_crc(schema6),
            "unknown calibration schema version 6",
        ),
        (
            "format 6",
            with_crc(format6),
            "unknown calibration blob format 6",
        ),
        (
            "p1_offset_bar = 50",
            with_crc(p1_50),
            "`p1_offset_bar` = 50 is outside -4 ... 4 bar",
        ),
        (
            "friction_up_n = NaN",
            with_crc(nan),
            "`friction_up_n` = NaN is outside",
        ),
    ];
    assert_eq!(&good[..4], &BLOB_MAGIC);
    for (name, bytes, expect) in cases {
        let path = d.join(format!("{}.bin", name.replace(' ', "_")));
        std::fs::write(&path, &bytes).unwrap();
        let r = qemu(&[&log, "--calibration-blob", &path.display().to_string()]);
        assert_eq!(r.code, 1, "{name}: exit {}; stderr:\n{}", r.code, r.stderr);
        assert!(
            r.stdout.is_empty(),
            "{name}: replayed anyway:\n{}",
            r.stdout
        );
        assert!(
            r.stderr.contains("refused") && r.stderr.contains(expect),
            "{name}: stderr lacks `{expect}`:\n{}",
            r.stderr
        );
    }
}
