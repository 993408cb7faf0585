//! The page of `crane-sim replay LOG --report DIR` (and of the limiter section
//! of `crane-sim report`): the replay's figures, each as SVG and PNG, its
//! events and its per-sample CSV, in one directory that opens offline.
//!
//! Files written into DIR: `index.html`, `signals.{svg,png}` (p1, p2 and the
//! angle as recorded), `load.{svg,png}` (load as read, true load when the log
//! has it, rated load), `utilization.{svg,png}` (utilization with the 90 % and
//! 100 % lines, the state as coloured bands) and `samples.csv`. The page
//! references nothing else: no network, no file outside DIR.

use crate::plot::{write_svg_and_png, Band, HLine, Panel, Series, PALETTE};
use anyhow::{Context as _, Result};
use moment_limiter::cycle::StepReport;
use moment_limiter::tools::log_format::{LogError, Record};
use moment_limiter::tools::replay::{ReplayEvent, ReplaySummary};
use moment_limiter::state_machine::LimiterState;
use plotters::style::RGBColor;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::Path;

/// Most points a figure's curve gets; longer replays keep each bucket's
/// minimum and maximum, so no peak is lost.
const MAX_PLOT_POINTS: usize = 4000;

/// The states in band order, with their colours.
const STATES: [(LimiterState, &str, RGBColor); 4] = [
    (LimiterState::Normal, "NORMAL", RGBColor(44, 160, 44)),
    (LimiterState::Warning, "WARNING", RGBColor(255, 165, 0)),
    (LimiterState::Overload, "OVERLOAD", RGBColor(214, 39, 40)),
    (LimiterState::Fault, "FAULT", RGBColor(120, 60, 160)),
];

/// One replayed sample: what the log said and what the limiter made of it.
#[derive(Debug, Clone, Copy)]
pub struct ReplaySample {
    /// Time (s).
    pub t_s: f64,
    /// p1 as recorded (bar).
    pub p1_bar: f32,
    /// p2 as recorded (bar).
    pub p2_bar: f32,
    /// Boom angle as recorded (deg).
    pub angle_deg: f32,
    /// True load from the log (kg), if it has the column.
    pub true_load_kg: Option<f32>,
    /// Load as read by the limiter (kg), if it could estimate one.
    pub load_kg: Option<f32>,
    /// Rated load (kg), if computed.
    pub rated_load_kg: Option<f32>,
    /// Utilization (fraction), if computed.
    pub utilization: Option<f32>,
    /// State after the sample.
    pub state: LimiterState,
}

/// Everything a replay page shows, collected sample by sample.
#[derive(Debug, Default)]
pub struct ReplayRecording {
    /// Every sample, in order.
    pub samples: Vec<ReplaySample>,
}

impl ReplayRecording {
    /// Keeps one replayed sample.
    pub fn push(&mut self, record: &Record<f32>, report: &StepReport<f32>) {
        let f = &record.frame;
        self.samples.push(ReplaySample {
            t_s: record.t_us as f64 * 1e-6,
            p1_bar: f.p1_bar,
            p2_bar: f.p2_bar,
            angle_deg: f.boom_angle_deg,
            true_load_kg: record.true_load_kg,
            load_kg: report.estimate.map(|e| e.load_kg),
            rated_load_kg: report.estimate.map(|e| e.rated_load_kg),
            utilization: report.estimate.map(|e| e.utilization),
            state: report.state,
        });
    }
}

/// What the page says about where the replay came from.
pub struct ReplaySource<'a> {
    /// The log's name as the user gave it.
    pub log: &'a str,
    /// The calibration file used, if any.
    pub calibration: Option<&'a str>,
}

/// Min/max decimation to at most about [`MAX_PLOT_POINTS`] points; a `NaN`
/// (no value) is kept so the curve breaks there.
fn decimate(points: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    if points.len() <= MAX_PLOT_POINTS {
        return points;
    }
    let per = points.len().div_ceil(MAX_PLOT_POINTS / 2);
    let mut out = Vec::with_capacity(MAX_PLOT_POINTS + 2);
    for chunk in points.chunks(per) {
        if chunk.iter().any(|p| p.1.is_nan()) {
            out.push((chunk[0].0, f64::NAN));
            continue;
        }
        let lo = chunk.iter().copied().fold((0.0, f64::INFINITY), |a, p| if p.1 < a.1 { p } else { a });
        let hi = chunk.iter().copied().fold((0.0, f64::NEG_INFINITY), |a, p| if p.1 > a.1 { p } else { a });
        if lo.0 <= hi.0 {
            out.extend([lo, hi]);
        } else {
            out.extend([hi, lo]);
        }
    }
    out
}

fn series(samples: &[ReplaySample], f: impl Fn(&ReplaySample) -> Option<f32>) -> Vec<(f64, f64)> {
    decimate(samples.iter().map(|s| (s.t_s, f(s).map_or(f64::NAN, f64::from))).collect())
}

/// The runs of equal state as bands along time.
fn state_bands(samples: &[ReplaySample]) -> Vec<Band> {
    let kind = |s: LimiterState| STATES.iter().position(|(st, _, _)| *st == s).unwrap_or(0);
    let mut bands: Vec<Band> = Vec::new();
    for (i, s) in samples.iter().enumerate() {
        let t_end = samples.get(i + 1).map_or(s.t_s, |n| n.t_s);
        match bands.last_mut() {
            Some(b) if b.kind == kind(s.state) => b.x1 = t_end,
            _ => bands.push(Band { x0: s.t_s, x1: t_end, kind: kind(s.state) }),
        }
    }
    bands
}

fn write_figures(dir: &Path, samples: &[ReplaySample]) -> Result<()> {
    let t = "time (s)";
    let p1 = series(samples, |s| Some(s.p1_bar));
    let p2 = series(samples, |s| Some(s.p2_bar));
    let angle = series(samples, |s| Some(s.angle_deg));
    let pressures = Panel::new(
        "Cylinder pressures as recorded",
        t,
        "pressure (bar)",
        vec![Series::line("p1 (piston side)", &p1).color(PALETTE[0]), Series::line("p2 (rod side)", &p2).color(PALETTE[5])],
    );
    let angles = Panel::new("Boom angle as recorded", t, "boom angle θ1 (deg)", vec![Series::line("pendulum angle", &angle).color(PALETTE[4])]);
    write_svg_and_png(dir, "signals", &[pressures, angles])?;

    let to_t = |x: Option<f32>| x.map(|v| v / 1e3);
    let load = series(samples, |s| to_t(s.load_kg));
    let rated = series(samples, |s| to_t(s.rated_load_kg));
    let truth = series(samples, |s| to_t(s.true_load_kg));
    let mut curves = vec![Series::line("rated load", &rated).color(PALETTE[1]), Series::line("load as read by the limiter", &load).color(PALETTE[0])];
    if samples.iter().any(|s| s.true_load_kg.is_some()) {
        curves.push(Series::line("true load (from the log)", &truth).color(PALETTE[3]).dashed());
    }
    // From zero, so the gap between load and rated load reads true to scale.
    let top_t = [&load, &rated, &truth].iter().flat_map(|c| c.iter().map(|p| p.1)).filter(|y| y.is_finite()).fold(1.0f64, f64::max);
    let mut panel = Panel::new("Hook load and rated load", t, "load on the hook (t)", curves);
    panel.y_range = Some((0.0, top_t * 1.1));
    write_svg_and_png(dir, "load", &[panel])?;

    // Utilization in %: up to the highest seen, but clipped at 300 % (the
    // limiter reports up to 1000 % when the rated load is near zero, which
    // would flatten everything else); the title says when it is clipped.
    let max_u = samples.iter().filter_map(|s| s.utilization).fold(0.0f32, f32::max) * 100.0;
    let top = max_u.clamp(110.0, 300.0) * 1.05;
    let util = series(samples, |s| s.utilization.map(|u| (u * 100.0).min(top)));
    let title = if max_u * 1.05 > top {
        format!("Utilization (load as read / rated load) and the limiter's state — clipped at {top:.0} % (max {max_u:.0} %)")
    } else {
        "Utilization (load as read / rated load) and the limiter's state".to_string()
    };
    let mut panel = Panel::new(
        &title,
        t,
        "utilization (%)",
        vec![Series::line("utilization", &util).color(PALETTE[3])],
    );
    panel.hlines = vec![
        HLine { y: 90.0, label: "90 %: WARNING", color: RGBColor(230, 140, 0) },
        HLine { y: 100.0, label: "100 %: OVERLOAD", color: RGBColor(200, 0, 0) },
    ];
    panel.bands = state_bands(samples);
    panel.band_kinds = STATES.iter().map(|&(_, name, color)| (name, color)).collect();
    panel.y_range = Some((0.0, f64::from(top)));
    write_svg_and_png(dir, "utilization", &[panel])
}

fn write_samples_csv(dir: &Path, samples: &[ReplaySample]) -> Result<()> {
    let path = dir.join("samples.csv");
    let mut w = std::io::BufWriter::new(std::fs::File::create(&path).with_context(|| format!("cannot create {}", path.display()))?);
    writeln!(w, "t_s,p1_bar,p2_bar,boom_angle_deg,true_load_kg,load_kg,rated_load_kg,utilization,state")?;
    let opt = |x: Option<f32>, d: usize| x.map(|v| format!("{v:.d$}")).unwrap_or_default();
    for s in samples {
        writeln!(
            w,
            "{:.3},{:.3},{:.3},{:.3},{},{},{},{},{}",
            s.t_s,
            s.p1_bar,
            s.p2_bar,
            s.angle_deg,
            opt(s.true_load_kg, 1),
            opt(s.load_kg, 1),
            opt(s.rated_load_kg, 1),
            opt(s.utilization, 4),
            s.state.as_str()
        )?;
    }
    w.flush()?;
    Ok(())
}

/// Escapes text for HTML.
pub fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The CSS of every page `crane-sim` writes (inline: the pages work offline).
pub const PAGE_STYLE: &str = "body{font-family:sans-serif;max-width:1040px;margin:auto;padding:0 12px;color:#222}\
table{border-collapse:collapse;margin:8px 0}td,th{border:1px solid #999;padding:3px 8px;text-align:right}\
th{background:#eee}td.l,th.l{text-align:left}img{width:100%;height:auto;border:1px solid #ddd}\
.NORMAL{background:#dff0d8}.WARNING{background:#fff0c0}.OVERLOAD{background:#f8c8c8}.FAULT{background:#e4d4f0}\
.err{background:#f8c8c8;padding:6px;border:1px solid #c00}figure{margin:16px 0}figcaption{font-size:90%;color:#555}";

/// Writes the page and its files into `dir` (created if missing).
pub fn write_replay_report(
    dir: &Path,
    source: &ReplaySource,
    recording: &ReplayRecording,
    events: &[ReplayEvent<f32>],
    summary: &ReplaySummary<f32>,
    error: Option<&LogError>,
) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let samples = &recording.samples;
    write_figures(dir, samples)?;
    write_samples_csv(dir, samples)?;

    let mut h = String::new();
    let log = html_escape(source.log);
    let _ = write!(
        h,
        "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>Replay of {log}</title><style>{PAGE_STYLE}</style></head><body>\
         <h1>Replay of <code>{log}</code></h1>\
         <p>Every sample of the log run through the load moment limiter (the controller's code and its f32 model). \
         WARNING from 90 % utilization, OVERLOAD from 100 %, FAULT when a sensor, the model or an output fails; \
         OVERLOAD and FAULT cut the moment-increasing motions (boom down, hoist up).</p>"
    );
    let first_cut = events.iter().find(|e| e.state.cuts());
    let verdict = match (error, first_cut) {
        (Some(_), _) => "the log could not be read to its end (exit 1)".to_string(),
        (None, Some(e)) => format!("entered {} at {:.3} s: motions cut (exit 2)", e.state.as_str(), e.t_us as f64 * 1e-6),
        (None, None) => "never entered OVERLOAD or FAULT (exit 0)".to_string(),
    };
    let first = samples.first().map_or(0.0, |s| s.t_s);
    let last = samples.last().map_or(0.0, |s| s.t_s);
    let _ = write!(
        h,
        "<table><tr><th class=\"l\">samples</th><td>{}</td></tr><tr><th class=\"l\">time</th><td>{first:.3} – {last:.3} s</td></tr>\
         <tr><th class=\"l\">max utilization</th><td>{}</td></tr><tr><th class=\"l\">final state</th><td class=\"{fs}\">{fs}</td></tr>\
         <tr><th class=\"l\">calibration</th><td>{}</td></tr><tr><th class=\"l\">result</th><td>{verdict}</td></tr></table>",
        summary.samples,
        summary.max_utilization.map_or("–".into(), |u| format!("{:.1} %", u * 100.0)),
        source.calibration.map_or("none (no friction removed)".into(), |c| format!("<code>{}</code>", html_escape(c))),
        fs = summary.final_state.map_or("–", LimiterState::as_str),
    );
    if let Some(e) = error {
        let _ = write!(h, "<p class=\"err\">Stopped at {}: everything before it is shown.</p>", html_escape(&e.to_string()));
    }
    h.push_str("<h2>Events</h2><table><tr><th>time (s)</th><th class=\"l\">state entered</th><th>utilization (%)</th><th>load as read (kg)</th><th>sample</th><th class=\"l\">fault</th></tr>");
    let num = |x: Option<f32>, scale: f32, d: usize| x.map_or("–".into(), |v| format!("{:.d$}", v * scale));
    for e in events {
        let st = e.state.as_str();
        let fault = e.fault.map(|f| html_escape(&f.to_string())).unwrap_or_default();
        let _ = write!(
            h,
            "<tr><td>{:.3}</td><td class=\"l {st}\">{st}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"l\">{fault}</td></tr>",
            e.t_us as f64 * 1e-6,
            num(e.utilization, 100.0, 1),
            num(e.load_kg, 1.0, 0),
            e.sample
        );
    }
    h.push_str("</table>");
    for (stem, caption) in [
        ("utilization", "Utilization with the 90 % (WARNING) and 100 % (OVERLOAD) lines; the background is the state the limiter was in."),
        ("load", "The hook load as the limiter reads it (×1.05, SAE J376), the true load when the log has it, and the rated load at the boom's angle (tipping load / 1.5, at most the crane's 10 t)."),
        ("signals", "The sensor signals exactly as recorded in the log."),
    ] {
        let _ = write!(
            h,
            "<figure><img src=\"{stem}.svg\" alt=\"{stem}\"><figcaption>{caption} <a href=\"{stem}.png\">PNG</a> · <a href=\"{stem}.svg\">SVG</a></figcaption></figure>"
        );
    }
    h.push_str("<p>Every sample: <a href=\"samples.csv\">samples.csv</a> (the log's signals and the limiter's load, rated load, utilization and state).</p></body></html>\n");
    let path = dir.join("index.html");
    std::fs::write(&path, h).with_context(|| format!("cannot write {}", path.display()))?;
    Ok(())
}

/// A finished replay: what the page shows.
pub struct ReplayOutcome {
    /// Every sample.
    pub recording: ReplayRecording,
    /// The state changes.
    pub events: Vec<ReplayEvent<f32>>,
    /// Totals.
    pub summary: ReplaySummary<f32>,
    /// Why the log was not read to its end, if it was not.
    pub error: Option<LogError>,
}

/// Replays a log file through the limiter exactly as `crane-sim replay`
/// does (the same set-up, calibration loader and log reader), silently.
pub fn replay_file(log: &Path, calibration: Option<&Path>) -> Result<ReplayOutcome> {
    use crate::cmd::replay::{for_each_record, load_calibration, new_replay};

    let file = crate::cmd::replay::open_log(log)?;
    let mut replay = new_replay(calibration.map(load_calibration).transpose()?)?;
    let mut recording = ReplayRecording::default();
    let mut events = Vec::new();
    let error = for_each_record(&mut std::io::BufReader::new(file), |_| {}, |record| {
        let (report, event) = replay.feed(record);
        recording.push(record, &report);
        events.extend(event);
        Ok(())
    })?;
    Ok(ReplayOutcome { recording, events, summary: replay.summary(), error })
}
