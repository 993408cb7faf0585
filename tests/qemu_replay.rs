//! The firmware's QEMU build and `crane-sim replay` must tell the same story.
//!
//! Every example log (`examples/logs/*.csv`; the small logs in `tests/data/`
//! while there are none) is replayed twice: by the firmware image for the
//! STM32F405 running in `qemu-system-arm -machine netduinoplus2` (f32, the
//! board's code path), and by the host's `crane-sim replay`. The two event
//! timelines (which state is entered at which sample), the JSON summaries'
//! events and the exit codes must be identical.
//!
//! Needs `qemu-system-arm` and the `thumbv7em-none-eabihf` target
//! (`scripts/install-test-deps.sh`). Without QEMU the test is skipped with a
//! message, unless `CI` is set: in CI a missing QEMU is a failure.
//!
//! The firmware and `crane-sim` are built here with `cargo build --release`
//! (a no-op when fresh), into the shared `target/`.

use std::path::{Path, PathBuf};
use std::process::Command;

use crane_tests::{cargo, need_qemu, root, TARGET};

fn build(args: &[&str]) {
    let status = cargo()
        .arg("build")
        .arg("--release")
        .args(args)
        .status()
        .expect("cargo runs");
    assert!(status.success(), "cargo build --release {args:?} failed");
}

fn logs() -> Vec<PathBuf> {
    let list = |dir: &Path| -> Vec<PathBuf> {
        let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
            .map(|d| {
                d.filter_map(|e| e.ok().map(|e| e.path()))
                    .filter(|p| p.extension().is_some_and(|e| e == "csv"))
                    .collect()
            })
            .unwrap_or_default();
        v.sort();
        v
    };
    let examples = list(&root().join("examples/logs"));
    if examples.is_empty() {
        list(&root().join("tests/data"))
    } else {
        examples
    }
}

/// Stdout and exit code of one run.
struct Run {
    stdout: String,
    stderr: String,
    code: i32,
}

fn run(mut cmd: Command) -> Run {
    let out = cmd.output().expect("process starts");
    Run {
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        code: out.status.code().unwrap_or(-1),
    }
}

fn qemu(log: &Path, extra: &[&str]) -> Run {
    let mut c = Command::new(root().join("scripts/qemu-runner.sh"));
    c.arg(root().join("target").join(TARGET).join("release/firmware"))
        .arg(log)
        .args(extra)
        .env("QEMU_TIMEOUT", "120");
    run(c)
}

fn host(log: &Path, extra: &[&str]) -> Run {
    let mut c = Command::new(root().join("target/release/crane-sim"));
    c.arg("replay").arg(log).args(extra);
    run(c)
}

/// (sample, state) of each `t=… STATE … sample=N` timeline line.
fn timeline(text: &str) -> Vec<(u64, String)> {
    text.lines()
        .filter(|l| l.starts_with("t="))
        .map(|l| {
            let mut words = l.split_whitespace();
            let state = words.nth(2).unwrap_or_default().to_string();
            let sample = l
                .split_whitespace()
                .find_map(|w| w.strip_prefix("sample="))
                .and_then(|s| s.parse().ok())
                .unwrap_or_else(|| panic!("timeline line without sample=: {l}"));
            (sample, state)
        })
        .collect()
}

/// (sample, state) of each event of the JSON summary, and its other fields.
fn json_events(text: &str) -> (Vec<(u64, String)>, serde_json::Value) {
    let v: serde_json::Value = serde_json::from_str(text.trim())
        .unwrap_or_else(|e| panic!("not one JSON object ({e}): {text}"));
    let events = v["events"]
        .as_array()
        .unwrap_or_else(|| panic!("no events array: {text}"))
        .iter()
        .map(|e| {
            (
                e["sample"].as_u64().expect("event has a sample"),
                e["state"].as_str().expect("event has a state").to_string(),
            )
        })
        .collect();
    (events, v)
}

/// The calibration file next to the example logs, if there is one.
fn calibration_file() -> Option<PathBuf> {
    let cal = root().join("examples/logs/cal.json");
    cal.exists().then_some(cal)
}

/// Replays `log` on QEMU and on the host (text and `--json`) and asserts the
/// same state changes at the same samples and the same exit code.
fn compare(label: &str, log: &Path, extra: &[&str]) -> String {
    let (q, h) = (qemu(log, extra), host(log, extra));
    assert!(
        matches!(q.code, 0..=2),
        "{label}: QEMU replay failed (exit {}): {}",
        q.code,
        q.stderr
    );
    assert_eq!(
        q.code, h.code,
        "{label}: exit codes differ (QEMU {} vs host {}); QEMU stderr: {}; host stderr: {}",
        q.code, h.code, q.stderr, h.stderr
    );
    let (qt, ht) = (timeline(&q.stdout), timeline(&h.stdout));
    assert_eq!(
        qt, ht,
        "{label}: timelines differ\nQEMU:\n{}\nhost:\n{}",
        q.stdout, h.stdout
    );

    let json: Vec<&str> = extra.iter().copied().chain(["--json"]).collect();
    let (qj, hj) = (qemu(log, &json), host(log, &json));
    assert_eq!(qj.code, hj.code, "{label} --json: exit codes differ");
    let ((qe, qv), (he, hv)) = (json_events(&qj.stdout), json_events(&hj.stdout));
    assert_eq!(qe, he, "{label} --json: events differ");
    assert_eq!(qe, qt, "{label}: --json events and the timeline differ");
    for key in ["samples", "final_state", "complete", "calibrated"] {
        assert_eq!(qv[key], hv[key], "{label} --json: `{key}` differs");
    }
    // Without a calibration both say so on stderr, in the same words.
    let note = moment_limiter::tools::replay::UNCALIBRATED_NOTE;
    let calibrated = extra.iter().any(|a| a.starts_with("--calibration"));
    assert_eq!(
        q.stderr.contains(note),
        !calibrated,
        "{label}: QEMU stderr: {}",
        q.stderr
    );
    assert_eq!(
        h.stderr.contains(note),
        !calibrated,
        "{label}: host stderr: {}",
        h.stderr
    );
    assert_eq!(qv["calibrated"], calibrated, "{label}");
    let identical = q.stdout == h.stdout && qj.stdout == hj.stdout;
    format!(
        "{label}: {} state changes at the same samples, exit {} on both; printed output {}",
        qt.len(),
        q.code,
        if identical {
            "byte-identical"
        } else {
            "differs only in printed values"
        }
    )
}

#[test]
fn qemu_and_host_replays_give_identical_timelines() {
    if !need_qemu("qemu_replay") {
        return;
    }
    build(&["--target", TARGET, "-p", "firmware"]);
    build(&["-p", "host-sim"]);

    let logs = logs();
    assert!(!logs.is_empty(), "no logs to replay");
    let calibration = calibration_file();
    let mut report = Vec::new();
    for log in &logs {
        let name = log.file_name().unwrap().to_string_lossy().into_owned();
        let cal_args: Vec<String> = calibration
            .iter()
            .map(|c| format!("--calibration={}", c.display()))
            .collect();
        for extra in [Vec::new(), cal_args] {
            let extra: Vec<&str> = extra.iter().map(String::as_str).collect();
            let label = format!("{name} {}", extra.join(" "));
            report.push(compare(&label, log, &extra));
        }
    }
    for line in report {
        eprintln!("qemu_replay: {line}");
    }
}

/// The same replay in this (host) process, in `f32` like the MCU, with the
/// model the firmware uses (`firmware/src/model.rs`: keep the two in step).
fn in_process_f32(log: &Path, calibration: Option<&Path>) -> (String, i32) {
    use moment_limiter::cycle::{Limiter, LimiterConfig};
    use moment_limiter::tools::log_format::LogParser;
    use moment_limiter::tools::replay::{self, Replay};

    let mut config = LimiterConfig::<f32>::standard();
    if let Some(cal) = calibration {
        // The same reader the firmware uses.
        config.calibration =
            moment_limiter::tools::config_file::parse_calibration(&std::fs::read(cal).unwrap()).unwrap();
    }
    let mut replay = Replay::new(
        Limiter::new(crane_model::loads::thesis_modes::thesis_load_model_f32(), config).unwrap(),
        calibration.is_some(),
    );
    let mut parser = LogParser::<f32>::new();
    let mut out = String::new();
    let text = std::fs::read_to_string(log).unwrap();
    let mut error = None;
    for line in text.lines() {
        match parser.feed_line(line) {
            Ok(Some(record)) => {
                if let (_, Some(e)) = replay.feed(&record) {
                    replay::write_event_line(&mut out, &e).unwrap();
                }
            }
            Ok(None) => {}
            Err(e) => {
                error = Some(e);
                break;
            }
        }
    }
    let error = error.or_else(|| parser.finish().err());
    replay::write_summary_line(&mut out, &replay.summary()).unwrap();
    let code = if error.is_some() {
        1
    } else {
        i32::from(replay.summary().exit_code())
    };
    (out, code)
}

/// Stronger than the timeline check, and independent of `crane-sim`: the
/// Cortex-M4F under QEMU prints byte for byte what the same `f32` code prints
/// on the host (same parser, limiter, model and formatter).
#[test]
fn qemu_output_is_byte_identical_to_the_same_f32_code_on_the_host() {
    if !need_qemu("qemu_replay") {
        return;
    }
    build(&["--target", TARGET, "-p", "firmware"]);
    let calibration = calibration_file();
    for log in logs() {
        for cal in [None, calibration.as_deref()] {
            let extra: Vec<String> = cal
                .iter()
                .map(|c| format!("--calibration={}", c.display()))
                .collect();
            let extra: Vec<&str> = extra.iter().map(String::as_str).collect();
            let q = qemu(&log, &extra);
            let (expected, code) = in_process_f32(&log, cal);
            assert_eq!(
                q.stdout,
                expected,
                "{} {extra:?}: QEMU vs host f32 output",
                log.display()
            );
            assert_eq!(q.code, code, "{} {extra:?}: exit code", log.display());
        }
    }
}

/// A scratch directory under `target/` (paths without spaces or commas, as
/// the QEMU runner needs).
fn scratch(name: &str) -> PathBuf {
    let dir = root().join("target").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Copies `log` with every row's time shifted by `shift_us`, exactly.
fn shifted_copy(log: &Path, shift_us: i64, out: &Path) {
    let mut dst = String::new();
    let mut header = false;
    for line in std::fs::read_to_string(log).unwrap().lines() {
        if line.starts_with('#') || line.trim().is_empty() || !header {
            header |= !(line.starts_with('#') || line.trim().is_empty());
            dst.push_str(line);
        } else {
            let (t, rest) = line.split_once(',').unwrap();
            let us = moment_limiter::tools::log_format::parse_time_us(t).unwrap() + shift_us;
            let (sign, a) = (if us < 0 { "-" } else { "" }, us.unsigned_abs());
            dst.push_str(&format!(
                "{sign}{}.{:06},{rest}",
                a / 1_000_000,
                a % 1_000_000
            ));
        }
        dst.push('\n');
    }
    std::fs::write(out, dst).unwrap();
}

/// (sample, state, utilization, load, fault) of each JSON event: all but the time.
fn events_without_time(text: &str) -> Vec<String> {
    let (_, v) = json_events(text);
    v["events"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            format!(
                "{} {} {} {} {}",
                e["sample"], e["state"], e["utilization"], e["load_kg"], e["fault"]
            )
        })
        .collect()
}

/// Issue 12: the board's integer clock. The same logs shifted by 0, 40 h,
/// 463 days and across the 2³² µs wrap of the tick counter give the same
/// events at the same samples on the MCU (QEMU), identical to the host's.
#[test]
fn qemu_shifted_logs_give_identical_events() {
    if !need_qemu("qemu_replay") {
        return;
    }
    build(&["--target", TARGET, "-p", "firmware"]);
    build(&["-p", "host-sim"]);
    let dir = scratch("qemu-shifted-logs");
    let cal = calibration_file().map(|c| format!("--calibration={}", c.display()));
    let shifts: [(&str, i64); 4] = [
        ("0", 0),
        ("40 h", 144_000_000_000),
        ("463 days", 40_003_200_000_000),
        ("across the wrap", (1_i64 << 32) - 5_000_000),
    ];
    for name in ["overload_lowering.csv", "wire_break.csv"] {
        let log = root().join("examples/logs").join(name);
        if !log.exists() {
            continue;
        }
        let extra: Vec<&str> = cal.iter().map(String::as_str).chain(["--json"]).collect();
        let mut reference: Option<(Vec<String>, i32)> = None;
        for (label, shift) in shifts {
            let copy = dir.join(format!("{shift}_{name}"));
            shifted_copy(&log, shift, &copy);
            let (q, h) = (qemu(&copy, &extra), host(&copy, &extra));
            let (qe, he) = (
                events_without_time(&q.stdout),
                events_without_time(&h.stdout),
            );
            assert_eq!(qe, he, "{name} shifted by {label}: QEMU vs host");
            assert_eq!(q.code, h.code, "{name} shifted by {label}: exit codes");
            match &reference {
                None => reference = Some((qe, q.code)),
                Some((e0, c0)) => {
                    assert_eq!(&qe, e0, "{name} shifted by {label}: QEMU events moved");
                    assert_eq!(q.code, *c0, "{name} shifted by {label}");
                }
            }
        }
        eprintln!("qemu_replay: {name}: identical events at 0, 40 h, 463 days and across the wrap");
    }
}

/// Issue 12: the hostile calibration table through the firmware's reader
/// (the shared `moment_limiter::tools::config_file`) on the MCU: every file refused
/// with exit 1 and the same message as `crane-sim replay`.
#[test]
fn qemu_refuses_every_hostile_calibration_like_the_host() {
    if !need_qemu("qemu_replay") {
        return;
    }
    build(&["--target", TARGET, "-p", "firmware"]);
    build(&["-p", "host-sim"]);
    let dir = scratch("qemu-hostile-calibration");
    let log = logs().into_iter().next().expect("a log");
    let cases = moment_limiter::tools::config_file::hostile::cases();
    for (k, (name, content, expect)) in cases.iter().enumerate() {
        let cal = dir.join(format!("case{k}.json"));
        std::fs::write(&cal, content).unwrap();
        let arg = format!("--calibration={}", cal.display());
        let (q, h) = (qemu(&log, &[&arg]), host(&log, &[&arg]));
        assert_eq!(q.code, 1, "{name}: QEMU exit {}: {}", q.code, q.stderr);
        assert_eq!(h.code, 1, "{name}: host exit");
        assert!(
            q.stderr.contains(expect),
            "{name}: QEMU said `{}`",
            q.stderr
        );
        assert_eq!(
            q.stderr.trim(),
            h.stderr.trim(),
            "{name}: QEMU and host messages differ"
        );
        assert!(q.stdout.is_empty(), "{name}: the firmware replayed anyway");
    }
    eprintln!(
        "qemu_replay: {} hostile calibration files refused by QEMU and host alike",
        cases.len()
    );
}
