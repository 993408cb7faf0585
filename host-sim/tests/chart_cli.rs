//! `crane-sim chart` as a user runs it: the rated load is the limiter's (tipping
//! load / safety factor, never above the crane's structural limit), it falls with
//! the radius, it is the number the replayed limiter trips on, and `--plot`
//! writes a real PNG or SVG by the file's extension.
use std::path::Path;
use std::process::Output;

mod common;
use common::bin;

fn chart_json(extra: &[&str]) -> serde_json::Value {
    let out = bin().args(["chart", "--json"]).args(extra).output().expect("runs");
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("json")
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn chart_rated_is_tipping_over_safety_factor_capped_and_falls_with_radius() {
    let j = chart_json(&["--safety-factor", "1.5"]);
    let cap = f(&j["structural_limit_kg"]);
    assert_eq!(cap, 10_000.0, "the COLES Mobile 930 is a 10 t crane");
    let rows = j["rows"].as_array().expect("rows");
    assert!(rows.len() >= 70, "the chart covers 5°..80° by 1°");
    let mut by_radius: Vec<(f64, f64)> = Vec::new();
    let mut capped = 0;
    for r in rows {
        let w = f(&r["rated_load_kg"]);
        // Never above the cap, wherever the tipping load is.
        assert!(w <= cap, "rated {w} kg above the {cap} kg cap at {r}");
        match r["tipping_load_kg"].as_f64() {
            // Rated load is the tipping load divided by the safety factor, in
            // the limiter's f32, exactly, unless the cap is lower.
            Some(t) => assert_eq!(w, f64::from((t as f32 / 1.5).min(cap as f32)), "{r}"),
            None => assert_eq!(w, cap, "no tipping load: the cap rates it ({r})"),
        }
        if w == cap {
            capped += 1;
        }
        by_radius.push((f(&r["radius_m"]), w));
    }
    // The steep half of the chart would rate 11–198 t by tipping alone.
    assert!(capped >= 20 && capped < rows.len() - 20, "{capped} rows at the cap");
    by_radius.sort_by(|a, b| a.0.total_cmp(&b.0));
    for pair in by_radius.windows(2) {
        // Further out, less capacity (Fig. 4.23): strictly below the cap.
        if pair[0].1 < cap {
            assert!(pair[1].1 < pair[0].1, "rated load rises from {:?} to {:?}", pair[0], pair[1]);
        } else {
            assert!(pair[1].1 <= pair[0].1, "rated load rises from {:?} to {:?}", pair[0], pair[1]);
        }
    }
}

#[test]
fn chart_at_radii_gives_the_rows_there() {
    let j = chart_json(&["--radius", "4", "--radius", "12", "--radius", "16"]);
    let rows = j["rows"].as_array().expect("rows");
    let radii: Vec<f64> = rows.iter().map(|r| f(&r["radius_m"])).collect();
    for (got, want) in radii.iter().zip([4.0, 12.0, 16.0]) {
        assert!((got - want).abs() < 1e-3, "row at {got} m for --radius {want}");
    }
    let rated: Vec<f64> = rows.iter().map(|r| f(&r["rated_load_kg"])).collect();
    assert_eq!(rated[0], 10_000.0, "4 m is inside the capped part of the chart");
    assert!(rated[1] > rated[2] && rated[2] > 1000.0, "{rated:?}");
    let out = bin().args(["chart", "--radius", "30"]).output().expect("runs");
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("outside the chart"));
}

/// A log of the boom standing still at `deg` (constant readings, 100 Hz, 3 s).
fn still_log(dir: &Path, deg: f64) -> std::path::PathBuf {
    let path = dir.join(format!("still_{deg}.csv"));
    let mut s = String::from("# boom still\nt_s,p1_bar,p2_bar,boom_angle_deg\n");
    for i in 0..300 {
        s.push_str(&format!("{:.3},80.000,3.000,{deg:.3}\n", i as f64 * 0.01));
    }
    std::fs::write(&path, s).unwrap();
    path
}

/// The chart's rated load is the replayed limiter's `--trace` rated load at
/// the same angle, to 0.1 % (angles all below the cap, where the model
/// decides). The logs hold the boom still, so the angle the
/// limiter rates at (its filtered reading, extrapolated by its rate) is the
/// chart's angle exactly; while luffing it rates with the same function at
/// its extrapolated angle (see `src/rating.rs`).
#[test]
fn chart_rated_equals_the_limiters_trace_rated_load() {
    let dir = tempfile::tempdir().unwrap();
    let j = chart_json(&[]);
    let rows = j["rows"].as_array().expect("rows");
    for deg in [20.0, 35.0, 45.0, 55.0] {
        let row = rows.iter().find(|r| f(&r["boom_angle_deg"]) == deg).expect("row at the angle");
        let chart = f(&row["rated_load_kg"]);
        let log = still_log(dir.path(), deg);
        let trace = dir.path().join(format!("trace_{deg}.csv"));
        let out = bin().arg("replay").arg(&log).arg("--trace").arg(&trace).output().expect("runs");
        assert!(matches!(out.status.code(), Some(0 | 2)), "{}", String::from_utf8_lossy(&out.stderr));
        let text = std::fs::read_to_string(&trace).unwrap();
        let mut compared = 0;
        for line in text.lines().skip(1) {
            let cells: Vec<&str> = line.split(',').collect();
            let Ok(rated) = cells[2].parse::<f64>() else { continue };
            assert!(
                (rated - chart).abs() <= 1e-3 * chart,
                "at {deg}°: trace rates {rated} kg, chart {chart} kg ({line})"
            );
            compared += 1;
        }
        assert!(compared >= 250, "only {compared} rated samples at {deg}°");
    }
}

fn plot(file: &Path) -> Output {
    bin().args(["chart", "--plot"]).arg(file).output().expect("runs")
}

#[test]
fn chart_plot_png_is_a_real_png() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("chart.png");
    let out = plot(&file);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let bytes = std::fs::read(&file).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    let decoder = png::Decoder::new(std::io::Cursor::new(&bytes));
    let mut reader = decoder.read_info().expect("PNG header");
    let mut pixels = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut pixels).expect("PNG data decodes");
    assert_eq!((info.width, info.height), (1000, 400));
    // Something is drawn: not one colour, and a good share not white.
    let px = info.line_size / info.width as usize;
    let non_white = pixels.chunks(px).filter(|p| p.iter().take(3).any(|&c| c < 200)).count();
    let total = (info.width * info.height) as usize;
    assert!(non_white > total / 100 && non_white < total / 2, "{non_white} of {total} pixels drawn");
}

#[test]
fn chart_plot_svg_is_svg_and_other_extensions_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("chart.SVG");
    let out = plot(&svg);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("<svg") && text.contains("rated load") && text.contains("structural limit 10 t"));
    let bad = dir.path().join("chart.jpg");
    let out = plot(&bad);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains(".svg or .png"));
    assert!(!bad.exists());
}
