//! `crane-sim chart`: the lifting-capacity chart (thesis §4.3.2, Fig. 4.23, SPEC §5).

use crate::model::thesis_model;
use crate::plot::{check_figure_path, write_figure, HLine, Panel, Series, PALETTE};
use crate::rating::{limiter_capacity, rated_at, rating_model};
use anyhow::{bail, Result};
use crane_model::loads::load_model::HookLoadModel;
use moment_limiter::capacity::Capacity;
use crane_model::sim::simulation::SimulationOptions;
use rayon::prelude::*;
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The hook loads the thesis ran to tipping (listing `IJK` loop; 3300 kg twice).
pub const THESIS_LOADS_KG: [f64; 7] = [3300.0, 3300.0, 4400.0, 6225.0, 10200.0, 13650.0, 15000.0];

/// Arguments of `crane-sim chart`.
#[derive(clap::Args, Debug)]
#[command(after_help = "Rows: radius_m,boom_angle_deg,tipping_load_kg,rated_load_kg. The rated load is the \
limiter's own (tipping load / safety factor, capped by the crane's structural limit of 10 000 kg), \
at rest. See docs/cli.md and docs/limiter.md.")]
pub struct ChartArgs {
    /// Safety factor on the tipping load.
    #[arg(long, default_value_t = 1.5)]
    safety_factor: f64,
    /// Print one JSON object instead of tables.
    #[arg(long)]
    json: bool,
    /// Draw the tipping load, the rated load and the cap against radius, with
    /// the thesis loads marked: PNG if FILE ends in .png, SVG if in .svg.
    #[arg(long, value_name = "FILE")]
    plot: Option<PathBuf>,
    /// Boom angle step of the table (deg).
    #[arg(long, default_value_t = 1.0)]
    step_deg: f64,
    /// Lowest boom angle of the table (deg). Below about 1° the boom's sag moves
    /// the hook out faster than eq. 4.3's radius shrinks, so the chart starts at 5°.
    #[arg(long, default_value_t = 5.0)]
    min_deg: f64,
    /// Rows at these hook radii (m) instead of the angle grid (repeatable).
    #[arg(long = "radius", value_name = "M")]
    radii: Vec<f64>,
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
    /// Rated load (kg): the limiter's, [`crate::rating::rated_at`].
    pub rated_load_kg: f64,
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
    structural_limit_kg: f64,
    rows: Vec<ChartRow>,
    thesis_loads: Vec<TippingRow>,
}

/// Tipping loads above this (kg) are shown as unbounded (`-`, `null`).
const UNBOUNDED_KG: f64 = 1e9;

/// One row at a boom angle (deg), from the one rating function.
pub fn chart_row<M: HookLoadModel<f32>>(model: &M, capacity: &Capacity<f32>, deg: f64) -> Result<ChartRow> {
    let r = rated_at(model, capacity, (deg as f32).to_radians())?;
    let tip = r.tipping_load_kg.map(f64::from).filter(|w| *w < UNBOUNDED_KG);
    Ok(ChartRow { radius_m: r.radius_m.into(), boom_angle_deg: deg, tipping_load_kg: tip, rated_load_kg: r.rated_load_kg.into() })
}

/// The chart over boom angles, `min_deg` to 80° by `step_deg`.
pub fn chart_rows(safety_factor: f64, min_deg: f64, step_deg: f64) -> Result<Vec<ChartRow>> {
    let capacity = limiter_capacity(safety_factor)?;
    let n = ((80.0 - min_deg) / step_deg + 1e-9).floor() as usize;
    (0..=n)
        .into_par_iter()
        .map(|i| chart_row(&rating_model(), &capacity, min_deg + i as f64 * step_deg))
        .collect()
}

/// The boom angle (deg) that puts the hook at `radius_m`, by bisection on the
/// model's own radius (eq. 4.3) between 0° and 80°.
pub fn angle_at_radius(radius_m: f64) -> Result<f64> {
    let model = rating_model();
    let r = |deg: f64| f64::from(model.radius_m((deg as f32).to_radians()));
    let (mut lo, mut hi) = (0.0f64, 80.0f64);
    if !(radius_m <= r(lo) && radius_m >= r(hi)) {
        bail!("--radius {radius_m} m is outside the chart ({:.2}–{:.2} m, boom 80°–0°)", r(hi), r(lo));
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if r(mid) > radius_m {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
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

/// The lifting-capacity figure of `chart --plot` and `report`: tipping load,
/// rated load (the limiter's) and the structural cap against radius, with the
/// thesis loads at their quasi-static and dynamic tipping radii.
pub fn chart_figure(path: &Path, rows: &[ChartRow], thesis: &[TippingRow], safety_factor: f64, cap_kg: f64) -> Result<()> {
    // Above 40 t the tipping curve of a steep boom runs off any useful scale.
    let shown = |w: f64| (w < 40e3).then_some(w / 1e3);
    let tipping: Vec<(f64, f64)> = rows.iter().filter_map(|r| r.tipping_load_kg.and_then(shown).map(|w| (r.radius_m, w))).collect();
    let uncapped: Vec<(f64, f64)> = rows.iter().filter_map(|r| r.tipping_load_kg.map(|w| w / safety_factor).and_then(shown).map(|w| (r.radius_m, w))).collect();
    let rated: Vec<(f64, f64)> = rows.iter().map(|r| (r.radius_m, r.rated_load_kg / 1e3)).collect();
    let qs: Vec<(f64, f64)> = thesis.iter().filter_map(|t| t.quasi_static_radius_m.map(|r| (r, t.load_kg / 1e3))).collect();
    let dy: Vec<(f64, f64)> = thesis.iter().filter_map(|t| t.dynamic_radius_m.map(|r| (r, t.load_kg / 1e3))).collect();
    let title = format!("Lifting capacity of the COLES Mobile 930 (Fig. 4.23), safety factor {safety_factor}");
    let tip_label = "tipping load (F_A = 0, at rest)";
    let sf_label = format!("tipping load / {safety_factor}");
    let cap_label = format!("structural limit {:.0} t", cap_kg / 1e3);
    let mut panel = Panel::new(
        &title,
        "hook radius R = 19.5 cos θ1 − 1.83 (m)",
        "load on the hook (t)",
        vec![
            Series::line(tip_label, &tipping).color(PALETTE[1]),
            Series::line(&sf_label, &uncapped).color(PALETTE[0]).dashed(),
            Series::line("rated load (what the limiter uses)", &rated).color(PALETTE[0]),
            Series::markers("thesis loads: tipping at rest", &qs).color(PALETTE[4]),
            Series::markers("thesis loads: tipping lowering in 30 s", &dy).color(PALETTE[5]),
        ],
    );
    panel.hlines.push(HLine { y: cap_kg / 1e3, label: &cap_label, color: PALETTE[3] });
    panel.y_range = Some((0.0, 40.0));
    write_figure(path, &[panel])
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
    if let Some(path) = &args.plot {
        check_figure_path(path)?;
    }
    let capacity = limiter_capacity(args.safety_factor)?;
    let rows = if args.radii.is_empty() {
        chart_rows(args.safety_factor, args.min_deg, args.step_deg)?
    } else {
        let model = rating_model();
        args.radii.iter().map(|&r| chart_row(&model, &capacity, angle_at_radius(r)?)).collect::<Result<Vec<_>>>()?
    };
    let thesis = thesis_tipping()?;
    if let Some(path) = &args.plot {
        chart_figure(path, &rows, &thesis, args.safety_factor, capacity.max_rated_kg.into())?;
    }
    let mut out = crate::stdout::stdout();
    if args.json {
        let report = ChartReport { safety_factor: args.safety_factor, structural_limit_kg: capacity.max_rated_kg.into(), rows, thesis_loads: thesis };
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
        out.flush()?;
        return Ok(0);
    }
    writeln!(out, "radius_m,boom_angle_deg,tipping_load_kg,rated_load_kg")?;
    for r in &rows {
        writeln!(out, "{:.3},{:.1},{},{:.1}", r.radius_m, r.boom_angle_deg, fmt(r.tipping_load_kg, 1), r.rated_load_kg)?;
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
