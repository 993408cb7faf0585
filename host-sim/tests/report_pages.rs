//! The pages `crane-sim replay LOG --report DIR` and `crane-sim report --out
//! DIR` write: every file they reference exists inside DIR (they open
//! offline, nothing from the network), every figure is there as SVG and as a
//! real PNG, and the replay page shows what the replay printed.
use std::path::{Path, PathBuf};

mod common;
use common::{bin, example};

/// Every `src="…"` and `href="…"` of a page.
fn references(html: &str) -> Vec<String> {
    let mut refs = Vec::new();
    for attr in ["src=\"", "href=\""] {
        let mut rest = html;
        while let Some(i) = rest.find(attr) {
            rest = &rest[i + attr.len()..];
            let end = rest.find('"').expect("closed attribute");
            refs.push(rest[..end].to_string());
            rest = &rest[end..];
        }
    }
    refs
}

/// Checks a page and every page it links to; returns the files referenced.
fn check_page(page: &Path, seen: &mut Vec<PathBuf>) {
    let html = std::fs::read_to_string(page).unwrap_or_else(|e| panic!("{}: {e}", page.display()));
    assert!(!html.contains("http:") && !html.contains("https:") && !html.contains("//"), "{} reaches out of its directory: {html}", page.display());
    let dir = page.parent().unwrap();
    for r in references(&html) {
        if let Some(anchor) = r.strip_prefix('#') {
            let id = format!("id=\"{anchor}\"");
            assert!(html.contains(&id), "{}: anchor {r} has no target", page.display());
            continue;
        }
        assert!(!r.starts_with('/') && !r.contains(".."), "{}: {r} is not inside the report", page.display());
        let target = dir.join(&r);
        assert!(target.is_file(), "{}: references {r}, which does not exist", page.display());
        if r.ends_with(".png") {
            let bytes = std::fs::read(&target).unwrap();
            assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{r} is not a PNG");
        }
        if r.ends_with(".html") && !seen.contains(&target) {
            seen.push(target.clone());
            check_page(&target, seen);
        }
        seen.push(target);
    }
}

#[test]
fn replay_report_page_references_only_files_that_exist() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("overload report");
    let out = bin()
        .arg("replay")
        .arg(example("overload_lowering.csv"))
        .arg("--calibration")
        .arg(example("cal.json"))
        .arg("--report")
        .arg(&out_dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
    // Short replay, stderr not a terminal: no progress bar, nothing else.
    assert!(out.stderr.is_empty(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    let page = out_dir.join("index.html");
    let mut seen = Vec::new();
    check_page(&page, &mut seen);
    for stem in ["signals", "load", "utilization"] {
        for ext in ["svg", "png"] {
            let f = out_dir.join(format!("{stem}.{ext}"));
            assert!(seen.contains(&f), "{stem}.{ext} not referenced by the page");
        }
    }
    assert!(seen.contains(&out_dir.join("samples.csv")));
    // The events the timeline printed are the page's events.
    let html = std::fs::read_to_string(&page).unwrap();
    let timeline = String::from_utf8_lossy(&out.stdout);
    for line in timeline.lines().filter(|l| l.starts_with("t=")) {
        let t = line.trim_start_matches("t=").split(' ').next().unwrap();
        let state = line.split(' ').nth(2).unwrap();
        assert!(html.contains(&format!("<td>{t}</td><td class=\"l {state}\">{state}</td>")), "event {line} not on the page");
    }
    // One row per sample, with the true load of the log.
    let csv = std::fs::read_to_string(out_dir.join("samples.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 601);
    assert!(csv.lines().nth(1).unwrap().contains(",8000.0,"));
    // The figures have axes with units and legends.
    let svg = std::fs::read_to_string(out_dir.join("utilization.svg")).unwrap();
    for text in ["utilization (%)", "time (s)", "90 %: WARNING", "100 %: OVERLOAD", "OVERLOAD"] {
        assert!(svg.contains(text), "utilization.svg lacks {text:?}");
    }
}

#[test]
fn replay_report_of_an_unreadable_log_keeps_what_was_read() {
    let dir = tempfile::tempdir().unwrap();
    let out = bin().arg("replay").arg(example("malformed.csv")).arg("--report").arg(dir.path()).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let html = std::fs::read_to_string(dir.path().join("index.html")).unwrap();
    assert!(html.contains("line 104"), "the page names the bad line");
    let csv = std::fs::read_to_string(dir.path().join("samples.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 100);
}

#[test]
fn full_report_pages_reference_only_files_that_exist() {
    let dir = tempfile::tempdir().unwrap();
    let out = bin().args(["report", "--out"]).arg(dir.path()).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let mut seen = Vec::new();
    check_page(&dir.path().join("index.html"), &mut seen);
    // The limiter on the example logs, each with its own page.
    for name in ["safe_lift", "overload_lowering", "wire_break"] {
        assert!(seen.contains(&dir.path().join("limiter").join(name).join("index.html")), "no page for {name}");
    }
    assert!(seen.contains(&dir.path().join("chart.png")) && seen.contains(&dir.path().join("chart.svg")));
}
