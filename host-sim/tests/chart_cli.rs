//! `crane-sim chart --json`: rated = tipping / safety factor exactly, and the rated
//! load decreases as the radius grows over the whole chart.
use std::process::Command;

#[test]
fn chart_rated_is_tipping_over_safety_factor_and_falls_with_radius() {
    let out = Command::new(env!("CARGO_BIN_EXE_crane-sim")).args(["chart", "--json", "--safety-factor", "1.5"]).output().expect("runs");
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    let rows = j["rows"].as_array().expect("rows");
    assert!(rows.len() >= 70, "the chart covers 5°..80° by 1°");
    let mut by_radius: Vec<(f64, f64)> = Vec::new();
    for r in rows {
        if let (Some(t), Some(w)) = (r["tipping_load_kg"].as_f64(), r["rated_load_kg"].as_f64()) {
            // Rated load is the tipping load divided by the safety factor, exactly.
            assert_eq!(w, t / 1.5);
            by_radius.push((r["radius_m"].as_f64().expect("radius"), w));
        }
    }
    by_radius.sort_by(|a, b| a.0.total_cmp(&b.0));
    for pair in by_radius.windows(2) {
        // Further out, less capacity (Fig. 4.23).
        assert!(pair[1].1 < pair[0].1, "rated load rises from {:?} to {:?}", pair[0], pair[1]);
    }
}
