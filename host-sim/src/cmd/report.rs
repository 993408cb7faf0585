//! `crane-sim report --out DIR`: every figure as SVG plus an HTML page (SPEC §5).

use super::chart::{chart_rows, thesis_tipping};
use super::simulate::{csv_row, plot_run, run_maneuver, CSV_HEADER};
use crate::plot::{write_svg, Panel, Series};
use anyhow::{Context, Result};
use crane_model::simulation::{thesis_cases, SimulationOptions};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::fmt::Write as _;
use std::path::PathBuf;

/// Arguments of `crane-sim report`.
#[derive(clap::Args, Debug)]
pub struct ReportArgs {
    /// Directory to write the figures, CSVs and `index.html` into.
    #[arg(long)]
    out: PathBuf,
}

/// Runs the subcommand; returns the exit code.
pub fn run(args: ReportArgs) -> Result<u8> {
    std::fs::create_dir_all(&args.out).with_context(|| format!("cannot create {}", args.out.display()))?;
    let cases = thesis_cases();
    let bar = ProgressBar::new(cases.len() as u64 + 1);
    bar.set_style(ProgressStyle::with_template("{bar:30} {pos}/{len} {msg}").unwrap_or_else(|_| ProgressStyle::default_bar()));
    let options = SimulationOptions::for_type::<f64>();
    let rows: Vec<Result<(String, f64, f64, f64)>> = cases
        .par_iter()
        .map(|(name, m)| {
            let (samples, _) = run_maneuver(m, &options)?;
            let mut csv = String::from(CSV_HEADER);
            csv.push('\n');
            for s in &samples {
                csv.push_str(&csv_row(s));
                csv.push('\n');
            }
            std::fs::write(args.out.join(format!("{name}.csv")), csv)?;
            plot_run(&args.out.join(format!("{name}.svg")), name, &samples)?;
            bar.inc(1);
            bar.set_message(name.to_string());
            let peak = samples.iter().map(|s| s.reactions.piston_force_n).fold(f64::MIN, f64::max);
            let tip = samples.iter().map(|s| s.deflection_m[2].abs()).fold(0.0, f64::max);
            let fa = samples.iter().map(|s| s.reactions.jack_reaction_n).fold(f64::MAX, f64::min);
            Ok((name.to_string(), peak, tip, fa))
        })
        .collect();
    let chart = chart_rows(1.5, 5.0, 1.0)?;
    let tipping = thesis_tipping()?;
    let rated: Vec<(f64, f64)> = chart.iter().filter_map(|r| r.rated_load_kg.map(|w| (r.radius_m, w / 1e3))).filter(|p| p.1 < 40.0).collect();
    let dyn_pts: Vec<(f64, f64)> = tipping.iter().filter_map(|t| t.dynamic_radius_m.map(|r| (r, t.load_kg / 1e3))).collect();
    let qs_pts: Vec<(f64, f64)> = tipping.iter().filter_map(|t| t.quasi_static_radius_m.map(|r| (r, t.load_kg / 1e3))).collect();
    write_svg(
        &args.out.join("chart.svg"),
        &[Panel {
            title: "Lifting capacity (Fig. 4.23): rated load = tipping load / 1.5",
            x_label: "radius (m)",
            y_label: "load (t)",
            series: vec![
                Series { label: "rated load", points: &rated, markers: false },
                Series { label: "thesis loads, quasi-static tipping", points: &qs_pts, markers: true },
                Series { label: "thesis loads, dynamic tipping", points: &dyn_pts, markers: true },
            ],
        }],
    )?;
    bar.inc(1);
    bar.finish_and_clear();
    let mut html = String::from("<!doctype html><html><head><meta charset=\"utf-8\"><title>crane-sim report</title>\
        <style>body{font-family:sans-serif;max-width:960px;margin:auto}table{border-collapse:collapse}td,th{border:1px solid #999;padding:3px 8px;text-align:right}</style></head><body>\
        <h1>COLES Mobile 930: thesis maneuvers and lifting capacity</h1>\
        <p>Flexible multibody model (12 elements, 4 modes, Newmark h = 2 ms), Kılıçaslan 1997.</p>\
        <h2>Maneuvers</h2><table><tr><th>case</th><th>peak piston force (kN)</th><th>max |tip deflection| (mm)</th><th>min F_A (kN)</th></tr>");
    for r in &rows {
        let (name, peak, tip, fa) = r.as_ref().map_err(|e| anyhow::anyhow!("{e:#}"))?;
        let _ = write!(html, "<tr><td style=\"text-align:left\"><a href=\"#{name}\">{name}</a></td><td>{:.1}</td><td>{:.1}</td><td>{:.1}</td></tr>", peak / 1e3, tip * 1e3, fa / 1e3);
    }
    html.push_str("</table><h2>Lifting capacity</h2><img src=\"chart.svg\" width=\"900\"><table><tr><th>load (kg)</th><th>quasi-static angle (°)</th><th>radius (m)</th><th>dynamic angle (°)</th><th>radius (m)</th></tr>");
    let f = |x: Option<f64>| x.map(|v| format!("{v:.2}")).unwrap_or_else(|| "does not tip".into());
    for t in &tipping {
        let _ = write!(html, "<tr><td>{:.0}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>", t.load_kg, f(t.quasi_static_angle_deg), f(t.quasi_static_radius_m), f(t.dynamic_angle_deg), f(t.dynamic_radius_m));
    }
    html.push_str("</table>");
    for (name, _) in &cases {
        let _ = write!(html, "<h2 id=\"{name}\">{name}</h2><p><a href=\"{name}.csv\">CSV</a></p><img src=\"{name}.svg\" width=\"900\">");
    }
    html.push_str("</body></html>\n");
    std::fs::write(args.out.join("index.html"), html)?;
    {
        use std::io::Write as _;
        let mut out = crate::stdout::stdout();
        writeln!(out, "wrote {} (12 maneuvers, chart, index.html)", args.out.display())?;
        out.flush()?;
    }
    Ok(0)
}
