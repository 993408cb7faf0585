//! `crane-sim calibrate` (issue 11 item 2): the friction per direction and
//! the offset it learns from unloaded runs against the ones synthesized, and
//! the runs it refuses with a clear error and exit 1.

mod common;

use common::{bin, text};
use std::path::{Path, PathBuf};

/// An unloaded 10 s cycloidal run of `direction` with 1 s at rest before it.
fn unloaded(dir: &Path, direction: &str, extra: &[&str]) -> PathBuf {
    let log = dir.join(format!("unloaded_{direction}_{}.csv", extra.len()));
    let out = bin()
        .args(["synth", "--load-kg", "0", "--duration", "10", "--profile", "cycloidal", "--rate-hz", "100", "--hold-s", "1"])
        .args(["--direction", direction, "--seed", if direction == "up" { "1" } else { "2" }])
        .args(extra)
        .arg("--out")
        .arg(&log)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    log
}

fn calibrate(logs: &[&Path], out: &Path) -> std::process::Output {
    bin().arg("calibrate").args(logs).arg("--out").arg(out).output().unwrap()
}

fn key(json: &serde_json::Value, k: &str) -> f64 {
    json[k].as_f64().unwrap_or_else(|| panic!("{k} in {json}"))
}

#[test]
fn learns_the_friction_of_each_direction_and_the_offset_at_rest() {
    let dir = tempfile::tempdir().unwrap();
    // synth's default crane: 12 kN up, 8 kN down, no offsets.
    let (up, down) = (unloaded(dir.path(), "up", &[]), unloaded(dir.path(), "down", &[]));
    let cal = dir.path().join("cal.json");
    let out = calibrate(&[&up, &down], &cal);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&cal).unwrap()).unwrap();
    let (fu, fd, off) = (key(&j, "friction_up_n"), key(&j, "friction_down_n"), key(&j, "force_offset_n"));
    println!("learned up {fu:.0} N, down {fd:.0} N, offset {off:.0} N (synthesized 12000 / 8000 / 0)");
    // Per direction, not the symmetric split (10 kN each, offset +2 kN).
    assert!((fu - 12_000.0).abs() < 600.0, "up {fu}");
    assert!((fd - 8_000.0).abs() < 600.0, "down {fd}");
    assert!(off.abs() < 600.0, "offset {off}");
}

#[test]
fn refuses_swapped_pressures_a_load_and_a_missing_direction() {
    let dir = tempfile::tempdir().unwrap();
    let (up, down) = (unloaded(dir.path(), "up", &[]), unloaded(dir.path(), "down", &[]));
    let cal = dir.path().join("cal.json");

    // p1 and p2 swapped in the up run.
    let swapped = dir.path().join("swapped.csv");
    let body: String = std::fs::read_to_string(&up)
        .unwrap()
        .lines()
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            if l.starts_with('#') || f.len() < 4 || f[0] == "t_s" {
                format!("{l}\n")
            } else {
                format!("{},{},{},{}\n", f[0], f[2], f[1], f[3..].join(","))
            }
        })
        .collect();
    std::fs::write(&swapped, body).unwrap();
    let out = calibrate(&[&swapped, &down], &cal);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("look swapped"), "{}", text(&out.stderr));

    // A load on the "unloaded" runs (the true-load column blanked to 0, as a
    // recorder without it would give).
    let mut loaded = Vec::new();
    for direction in ["up", "down"] {
        let log = dir.path().join(format!("loaded_{direction}.csv"));
        let out = bin()
            .args(["synth", "--load-kg", "800", "--duration", "10", "--rate-hz", "100", "--hold-s", "1", "--direction", direction, "--out"])
            .arg(&log)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let body: String = std::fs::read_to_string(&log)
            .unwrap()
            .lines()
            .map(|l| {
                let f: Vec<&str> = l.split(',').collect();
                if l.starts_with('#') || f.len() != 5 || f[0] == "t_s" {
                    format!("{l}\n")
                } else {
                    format!("{},0\n", f[..4].join(","))
                }
            })
            .collect();
        std::fs::write(&log, body).unwrap();
        loaded.push(log);
    }
    let out = calibrate(&[&loaded[0], &loaded[1]], &cal);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(err.contains("empty hook") && err.contains("kg on the hook"), "{err}");

    // Only the up run: too little motion down.
    let out = calibrate(&[&up], &cal);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(err.contains("too few samples moving down"), "{err}");
    assert!(!cal.exists(), "nothing is written when refused");
}
