//! `crane-sim chart`: the lifting-capacity chart (thesis §4.3.2, Fig. 4.23, SPEC §5).

use crate::model::thesis_model;
use crate::plot::{write_svg, Panel, Series};
use anyhow::{bail, Result};
use crane_model::simulation::SimulationOptions;
use rayon::prelude::*;
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;

/// The hook loads the thesis ran to tipping (listing `IJK` loop; 3300 kg twice).
pub const THESIS_LOADS_KG: [f64; 7] = [3300.0, 3300.0, 4400.0, 6225.0, 10200.0, 13650.0, 15000.0];

/// Arguments of `crane-sim chart`.
#[derive(clap::Args, Debug)]
pub struct ChartArgs {
    /// Safety factor on the tipping load.
    #[arg(long, default_value_t = 1.5)]
    safety_factor: f64,
    /// Print one JSON object instead of tables.
    #[arg(long)]
    json: bool,
    /// Draw rated load against radius (SVG), with the tipping loads and the thesis loads marked.
    #[arg(long)]
    plot: Option<PathBuf>,
    /// Boom angle step of the table (deg).
    #[arg(long, default_value_t = 1.0)]
    step_deg: f64,
    /// Lowest boom angle of the table (deg). Below about 1° the boom's sag moves
    /// the hook out faster than eq. 4.3's radius shrinks, so the chart starts at 5°.
    #[arg(long, default_value_t = 5.0)]
    min_deg: f64,
}

/// One row of the chart.
#[derive(Serialize, Clone, Copy, Debug)]
pub struct ChartRow {
    /// Hook radius (m).
    pub radius_m: f64,
    /// Boom angle (deg).
    pub boom_angle_deg: f64,
    /// Load at which F_A = 0 (kg); `null` where the load is behind the tipping line.
    pub tipping_load_kg: Option<f64>,
    /// Tipping load / safety factor (kg).
    pub rated_load_kg: Option<f64>,
}

/// Tipping of one thesis load, both ways.
#[derive(Serialize, Clone, Copy, Debug)]
pub struct TippingRow {
    /// Hook load (kg).
    pub load_kg: f64,
    /// Quasi-static tipping angle (deg).
    pub quasi_static_angle_deg: Option<f64>,
    /// Its radius (m).
    pub quasi_static_radius_m: Option<f64>,
    /// Angle where F_A reached 0 while lowering at the thesis's 30 s speed (deg).
    pub dynamic_angle_deg: Option<f64>,
    /// Its radius (m).
    pub dynamic_radius_m: Option<f64>,
}

#[derive(Serialize)]
struct ChartReport {
    safety_factor: f64,
    rows: Vec<ChartRow>,
    thesis_loads: Vec<TippingRow>,
}

/// The quasi-static chart over boom angles.
pub fn chart_rows(safety_factor: f64, min_deg: f64, step_deg: f64) -> Result<Vec<ChartRow>> {
    let model = thesis_model()?;
    let n = ((80.0 - min_deg) / step_deg).floor() as usize;
    (0..=n)
        .into_par_iter()
        .map(|i| {
            let deg = min_deg + i as f64 * step_deg;
            let tp = model.tipping_load_at_rest(deg.to_radians()).map_err(|e| anyhow::anyhow!("{e}"))?;
            let tip = (tp.tipping_load_kg < 1e9).then_some(tp.tipping_load_kg);
            Ok(ChartRow { radius_m: tp.radius_m, boom_angle_deg: deg, tipping_load_kg: tip, rated_load_kg: tip.map(|w| w / safety_factor) })
        })
        .collect()
}

/// Quasi-static tipping angle of a load: bisection on the angle of W_tip(θ) = W.
pub fn quasi_static_tipping_angle(load_kg: f64) -> Result<Option<f64>> {
    let model = thesis_model()?;
    let w = |deg: f64| -> Result<f64> { Ok(model.tipping_load_at_rest(deg.to_radians()).map_err(|e| anyhow::anyhow!("{e}"))?.tipping_load_kg) };
    let (mut lo, mut hi) = (0.0f64, 80.0f64);
    if w(lo)? >= load_kg {
        return Ok(None);
    }
    if w(hi)? < load_kg {
        return Ok(Some(hi));
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if w(mid)? < load_kg {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Some(0.5 * (lo + hi)))
}

/// Both tipping angles of each thesis load.
pub fn thesis_tipping() -> Result<Vec<TippingRow>> {
    let model = thesis_model()?;
    let radius = |deg: f64| 19.5 * deg.to_radians().cos() - 1.83;
    let mut loads: Vec<f64> = THESIS_LOADS_KG.to_vec();
    loads.dedup();
    loads
        .par_iter()
        .map(|&w| {
            let qs = quasi_static_tipping_angle(w)?;
            let options = SimulationOptions::for_type::<f64>();
            let dynamic = model.dynamic_tipping_angle(w, 1.0, &options).map_err(|e| anyhow::anyhow!("{e}"))?.map(|a| a.to_degrees());
            Ok(TippingRow {
                load_kg: w,
                quasi_static_angle_deg: qs,
                quasi_static_radius_m: qs.map(radius),
                dynamic_angle_deg: dynamic,
                dynamic_radius_m: dynamic.map(radius),
            })
        })
        .collect()
}

fn fmt(x: Option<f64>, prec: usize) -> String {
    x.map(|v| format!("{v:.prec$}")).unwrap_or_else(|| "-".into())
}

/// Runs the subcommand; returns the exit code.
pub fn run(args: ChartArgs) -> Result<u8> {
    if !(args.safety_factor >= 1.0 && args.safety_factor.is_finite()) {
        bail!("--safety-factor must be a number ≥ 1, got {}", args.safety_factor);
    }
    if !(args.step_deg >= 0.1 && args.step_deg <= 10.0) {
        bail!("--step-deg must be in [0.1, 10]");
    }
    if !(args.min_deg >= 0.0 && args.min_deg < 80.0) {
        bail!("--min-deg must be in [0, 80)");
    }
    let rows = chart_rows(args.safety_factor, args.min_deg, args.step_deg)?;
    let thesis = thesis_tipping()?;
    if let Some(path) = &args.plot {
        let rated: Vec<(f64, f64)> = rows.iter().filter_map(|r| r.rated_load_kg.map(|w| (r.radius_m, w / 1e3))).filter(|p| p.1 < 40.0).collect();
        let tipping: Vec<(f64, f64)> = rows.iter().filter_map(|r| r.tipping_load_kg.map(|w| (r.radius_m, w / 1e3))).filter(|p| p.1 < 60.0).collect();
        let qs: Vec<(f64, f64)> = thesis.iter().filter_map(|t| t.quasi_static_radius_m.map(|r| (r, t.load_kg / 1e3))).collect();
        let dy: Vec<(f64, f64)> = thesis.iter().filter_map(|t| t.dynamic_radius_m.map(|r| (r, t.load_kg / 1e3))).collect();
        let rated_pts: Vec<(f64, f64)> = thesis.iter().filter_map(|t| t.dynamic_radius_m.map(|r| (r, t.load_kg / args.safety_factor / 1e3))).collect();
        let title = format!("Lifting capacity of the COLES Mobile 930 (safety factor {})", args.safety_factor);
        write_svg(
            path,
            &[Panel {
                title: &title,
                x_label: "radius R = 19.5 cos θ1 − 1.83 (m)",
                y_label: "load on the hook (t)",
                series: vec![
                    Series { label: "rated load (quasi-static)", points: &rated, markers: false },
                    Series { label: "tipping load (quasi-static)", points: &tipping, markers: false },
                    Series { label: "thesis loads: quasi-static tipping", points: &qs, markers: true },
                    Series { label: "thesis loads: dynamic tipping (30 s lowering)", points: &dy, markers: true },
                    Series { label: "thesis loads / safety factor at dynamic tipping radius", points: &rated_pts, markers: true },
                ],
            }],
        )?;
    }
    let mut out = crate::stdout::stdout();
    if args.json {
        let report = ChartReport { safety_factor: args.safety_factor, rows, thesis_loads: thesis };
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
        out.flush()?;
        return Ok(0);
    }
    writeln!(out, "radius_m,boom_angle_deg,tipping_load_kg,rated_load_kg")?;
    for r in &rows {
        writeln!(out, "{:.3},{:.1},{},{}", r.radius_m, r.boom_angle_deg, fmt(r.tipping_load_kg, 1), fmt(r.rated_load_kg, 1))?;
    }
    writeln!(out)?;
    writeln!(out, "# Tipping of the thesis loads: quasi-static (at rest) and dynamic (lowering from 80° at the 30 s speed)")?;
    writeln!(out, "# load_kg,quasi_static_angle_deg,quasi_static_radius_m,dynamic_angle_deg,dynamic_radius_m")?;
    for t in &thesis {
        writeln!(
            out,
            "# {:.0},{},{},{},{}",
            t.load_kg,
            fmt(t.quasi_static_angle_deg, 2),
            fmt(t.quasi_static_radius_m, 3),
            fmt(t.dynamic_angle_deg, 2),
            fmt(t.dynamic_radius_m, 3)
        )?;
    }
    out.flush()?;
    Ok(0)
}
