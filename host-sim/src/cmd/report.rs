//! `crane-sim report --out DIR`: every figure as SVG plus an HTML page (SPEC §5).
//!
//! The page has the twelve thesis maneuvers, the lifting-capacity chart (the
//! same figure as `crane-sim chart --plot`) and the limiter replayed on the
//! example logs (each with its own page, as `crane-sim replay --report`).

use super::chart::{chart_figure, chart_rows, thesis_tipping};
use super::simulate::{csv_row, plot_run, run_maneuver, CSV_HEADER};
use crate::rating::limiter_capacity;
use crate::replay_report::{html_escape, replay_file, write_replay_report, ReplaySource, PAGE_STYLE};
use anyhow::{Context, Result};
use std::path::Path;
use crane_model::sim::simulation::{thesis_cases, SimulationOptions};
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
            plot_run(&args.out.join(format!("{name}.png")), name, &samples)?;
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
    let cap_kg: f64 = limiter_capacity(1.5)?.max_rated_kg.into();
    chart_figure(&args.out.join("chart.svg"), &chart, &tipping, 1.5, cap_kg)?;
    chart_figure(&args.out.join("chart.png"), &chart, &tipping, 1.5, cap_kg)?;
    let limiter_html = limiter_section(&args.out)?;
    bar.inc(1);
    bar.finish_and_clear();
    let mut html = String::from("<!doctype html><html><head><meta charset=\"utf-8\"><title>crane-sim report</title><style>");
    html.push_str(PAGE_STYLE);
    html.push_str("</style></head><body>\
        <h1>COLES Mobile 930: thesis maneuvers and lifting capacity</h1>\
        <p>Flexible multibody model (12 elements, 4 modes, Newmark h = 2 ms), Kılıçaslan 1997.</p>\
        <h2>Maneuvers</h2><table><tr><th>case</th><th>peak piston force (kN)</th><th>max |tip deflection| (mm)</th><th>min F_A (kN)</th></tr>");
    for r in &rows {
        let (name, peak, tip, fa) = r.as_ref().map_err(|e| anyhow::anyhow!("{e:#}"))?;
        let _ = write!(html, "<tr><td style=\"text-align:left\"><a href=\"#{name}\">{name}</a></td><td>{:.1}</td><td>{:.1}</td><td>{:.1}</td></tr>", peak / 1e3, tip * 1e3, fa / 1e3);
    }
    html.push_str("</table><h2>Lifting capacity</h2><p>The rated load is the limiter's own: tipping load / 1.5, capped by the crane's structural limit (10 t). <a href=\"chart.png\">PNG</a></p><img src=\"chart.svg\" alt=\"lifting capacity\"><table><tr><th>load (kg)</th><th>quasi-static angle (°)</th><th>radius (m)</th><th>dynamic angle (°)</th><th>radius (m)</th></tr>");
    let f = |x: Option<f64>| x.map(|v| format!("{v:.2}")).unwrap_or_else(|| "does not tip".into());
    for t in &tipping {
        let _ = write!(html, "<tr><td>{:.0}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>", t.load_kg, f(t.quasi_static_angle_deg), f(t.quasi_static_radius_m), f(t.dynamic_angle_deg), f(t.dynamic_radius_m));
    }
    html.push_str("</table>");
    html.push_str(&limiter_html);
    for (name, _) in &cases {
        let _ = write!(html, "<h2 id=\"{name}\">{name}</h2><p><a href=\"{name}.csv\">CSV</a> · <a href=\"{name}.png\">PNG</a></p><img src=\"{name}.svg\" alt=\"{name}\">");
    }
    html.push_str("</body></html>\n");
    std::fs::write(args.out.join("index.html"), html)?;
    {
        use std::io::Write as _;
        let mut out = crate::stdout::stdout();
        writeln!(out, "wrote {} (12 maneuvers, chart, limiter on {} example logs, index.html)", args.out.display(), EXAMPLE_LOGS.len())?;
        out.flush()?;
    }
    Ok(0)
}

/// The example logs of `examples/logs`, built into the binary so the report
/// works from an installed `crane-sim` anywhere: (name, what it is, text).
const EXAMPLE_LOGS: [(&str, &str, &str); 3] = [
    ("safe_lift", "3000 kg raised 40° → 80°", include_str!("../../../examples/logs/safe_lift.csv")),
    ("overload_lowering", "8000 kg lowered 75° → 40°", include_str!("../../../examples/logs/overload_lowering.csv")),
    ("wire_break", "the safe lift, p1 loop broken at 6 s", include_str!("../../../examples/logs/wire_break.csv")),
];

/// The calibration the example logs are replayed with (`examples/logs/cal.json`).
const EXAMPLE_CALIBRATION: &str = include_str!("../../../examples/logs/cal.json");

/// Replays each example log (with the example calibration) into
/// `out/limiter/NAME/` and returns the main page's section.
fn limiter_section(out: &Path) -> Result<String> {
    let dir = out.join("limiter");
    let logs = dir.join("logs");
    std::fs::create_dir_all(&logs).with_context(|| format!("cannot create {}", logs.display()))?;
    let cal = logs.join("cal.json");
    std::fs::write(&cal, EXAMPLE_CALIBRATION)?;
    let mut html = String::from(
        "<h2 id=\"limiter\">The limiter on the example logs</h2><p>Each log replayed through the limiter as \
         <code>crane-sim replay LOG --calibration cal.json --report DIR</code> does (the firmware's f32 model). \
         <a href=\"limiter/logs/cal.json\">cal.json</a></p><table><tr><th class=\"l\">log</th><th class=\"l\">what</th>\
         <th>max utilization (%)</th><th class=\"l\">first WARNING / OVERLOAD / FAULT (s)</th><th class=\"l\">final state</th><th class=\"l\">page</th></tr>",
    );
    let mut figures = String::new();
    for (name, what, text) in EXAMPLE_LOGS {
        let log = logs.join(format!("{name}.csv"));
        std::fs::write(&log, text)?;
        let outcome = replay_file(&log, Some(&cal))?;
        let source = ReplaySource { log: &format!("{name}.csv"), calibration: Some("cal.json") };
        write_replay_report(&dir.join(name), &source, &outcome.recording, &outcome.events, &outcome.summary, outcome.error.as_ref())?;
        let first = |state: &str| {
            outcome.events.iter().find(|e| e.state.as_str() == state).map_or("–".to_string(), |e| format!("{:.2}", e.t_us as f64 * 1e-6))
        };
        let final_state = outcome.summary.final_state.map_or("–", |s| s.as_str());
        let _ = write!(
            html,
            "<tr><td class=\"l\"><a href=\"limiter/logs/{name}.csv\">{name}.csv</a></td><td class=\"l\">{}</td><td>{}</td><td class=\"l\">{} / {} / {}</td>\
             <td class=\"l {final_state}\">{final_state}</td><td class=\"l\"><a href=\"limiter/{name}/index.html\">figures</a></td></tr>",
            html_escape(what),
            outcome.summary.max_utilization.map_or("–".into(), |u| format!("{:.1}", u * 100.0)),
            first("WARNING"),
            first("OVERLOAD"),
            first("FAULT"),
        );
        let _ = write!(figures, "<h3>{name}.csv: utilization and state</h3><img src=\"limiter/{name}/utilization.svg\" alt=\"{name} utilization\">");
    }
    html.push_str("</table>");
    html.push_str(&figures);
    Ok(html)
}
