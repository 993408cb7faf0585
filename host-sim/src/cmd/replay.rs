//! `crane-sim replay LOG.csv [--calibration CAL.json] [--json] [--trace FILE.csv]`
//!
//! Runs a recorded sensor log (SPEC §5) through the limiter core, the same
//! `moment_limiter::tools::replay::Replay` the firmware runs, in `f32`, and prints
//! with the same formatters, so the output is the firmware's.
//!
//! Output: without `--json`, one timeline line per state change as it happens
//! (the first sample gives the initial state), then a summary line; with
//! `--json`, one JSON object at the end. `--trace` writes one CSV row per
//! sample: `t_s,load_kg,rated_load_kg,utilization,state`.
//!
//! Exit codes: 0 the log was read to its end and never entered OVERLOAD or
//! FAULT; 2 it entered OVERLOAD or FAULT at least once (a clock fault, see
//! `moment_limiter::clock`, included); 1 the input (log or calibration)
//! could not be read or was refused, or a write error. A closed stdout
//! (`| head -1`) is not an error: printing stops quietly and the replay runs
//! on, so the exit code still says 0 or 2 (`crate::stdout`).
//!
//! The calibration file is read with the limiter's own reader
//! (`moment_limiter::tools::config_file`, the firmware's too). Without
//! `--calibration` a note goes to stderr and the JSON says
//! `"calibrated":false`.
//!
//! A malformed log: the replay stops at the first bad line; everything
//! replayed before it is kept and printed (timeline lines and summary, or the
//! JSON object with `"complete":false` and `"error"`; the trace file holds
//! every replayed sample), then the error naming the line and field goes to
//! stderr and the exit code is 1, even if an OVERLOAD or FAULT was seen before.

use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Write as _};
use std::path::{Path, PathBuf};

use anyhow::Context as _;
use crane_model::loads::load_model::HookLoadModel;
use moment_limiter::tools::config_file;
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::load_estimate::Calibration;
use moment_limiter::tools::log_format::{LogError, LogErrorKind, LogParser, Record};
use moment_limiter::tools::replay::{self, Replay, ReplayEvent};

/// Arguments of `crane-sim replay`.
#[derive(clap::Args, Debug)]
pub struct ReplayArgs {
    /// Sensor log: CSV with `t_s,p1_bar,p2_bar,boom_angle_deg` [and `true_load_kg`].
    pub log: PathBuf,
    /// Calibration from `crane-sim calibrate` (friction per direction, offsets).
    #[arg(long)]
    pub calibration: Option<PathBuf>,
    /// Print one JSON object instead of the timeline.
    #[arg(long)]
    pub json: bool,
    /// Write a per-sample CSV trace `t_s,load_kg,rated_load_kg,utilization,state`.
    #[arg(long)]
    pub trace: Option<PathBuf>,
    /// Write an HTML page with the replay's figures (SVG and PNG), its events
    /// and every sample into DIR (created if missing; opens offline).
    #[arg(long, value_name = "DIR")]
    pub report: Option<PathBuf>,
}

/// The crane model the host tools (replay, calibrate) run the limiter on.
/// The single place to change it.
///
/// It is the controller's model, in `f32` with the same precomputed modal
/// constants the firmware is built with, so `crane-sim replay` and the firmware
/// run the same arithmetic and their timelines agree sample for sample.
pub fn crane_load_model() -> impl HookLoadModel<f32> {
    crane_model::loads::thesis_modes::thesis_load_model_f32()
}

/// Reads and checks a calibration file with the limiter's own reader
/// (`moment_limiter::tools::config_file`, the one the firmware uses): every key
/// required, unknown keys refused, every value within its physical bounds.
pub fn load_calibration<T: crane_model::Real>(path: &Path) -> anyhow::Result<Calibration<T>> {
    let bytes = std::fs::read(path)
        .with_context(|| format!("cannot read calibration {}", path.display()))?;
    config_file::parse_calibration(&bytes)
        .map_err(|e| anyhow::anyhow!("calibration {} refused: {e}", path.display()))
}

/// Opens a log file; a directory is refused by name (reading one fails with
/// an error that says nothing of it).
pub fn open_log(path: &Path) -> anyhow::Result<File> {
    if path.is_dir() {
        anyhow::bail!("cannot open log {}: it is a directory, not a log file", path.display());
    }
    File::open(path).with_context(|| format!("cannot open log {}", path.display()))
}

/// Whether `bytes` start with a UTF-16 byte-order mark (either order).
pub fn starts_as_utf16(bytes: &[u8]) -> bool {
    bytes.starts_with(&[0xff, 0xfe]) || bytes.starts_with(&[0xfe, 0xff])
}

/// Reads one line (without `\n`) as UTF-8; `Ok(None)` at the end.
pub fn read_line<R: BufRead>(
    reader: &mut R,
    buf: &mut Vec<u8>,
) -> Result<Option<String>, LogErrorKind> {
    buf.clear();
    match reader.read_until(b'\n', buf) {
        Ok(0) => Ok(None),
        Ok(_) => {
            if buf.last() == Some(&b'\n') {
                buf.pop();
            }
            String::from_utf8(std::mem::take(buf)).map(Some).map_err(|e| {
                if starts_as_utf16(e.as_bytes()) {
                    LogErrorKind::Utf16
                } else {
                    LogErrorKind::NotUtf8
                }
            })
        }
        Err(_) => Err(LogErrorKind::Unreadable),
    }
}

/// The limiter `crane-sim replay` runs (the controller's model and
/// configuration, with `calibration` if given), in a fresh [`Replay`].
pub fn new_replay(
    calibration: Option<Calibration<f32>>,
) -> anyhow::Result<Replay<f32, impl HookLoadModel<f32>>> {
    let mut config = LimiterConfig::standard();
    let calibrated = calibration.is_some();
    if let Some(cal) = calibration {
        config.calibration = cal;
    }
    let limiter = Limiter::new(crane_load_model(), config).map_err(|e| anyhow::anyhow!("{e}"))?;
    Ok(Replay::new(limiter, calibrated))
}

/// Reads a log to its end or its first bad line, handing every data record
/// to `on_record` and every line's length in bytes to `on_line`; returns
/// why it stopped early, if it did (the error names the line and field).
/// `on_record`'s own errors (an output that cannot be written) end it at once.
pub fn for_each_record<R: BufRead>(
    reader: &mut R,
    mut on_line: impl FnMut(usize),
    mut on_record: impl FnMut(&Record<f32>) -> anyhow::Result<()>,
) -> anyhow::Result<Option<LogError>> {
    let mut parser = LogParser::<f32>::new();
    if reader.fill_buf().is_ok_and(starts_as_utf16) {
        return Ok(Some(parser.reject_next_line(LogErrorKind::Utf16)));
    }
    // One buffer for every line: a replay's cost is mostly reading the text.
    let mut line = String::new();
    Ok(loop {
        line.clear();
        match reader.read_line(&mut line) {
            Ok(0) => break parser.finish().err(),
            Ok(n) => on_line(n),
            Err(e) if e.kind() == std::io::ErrorKind::InvalidData => {
                break Some(parser.reject_next_line(LogErrorKind::NotUtf8))
            }
            Err(_) => break Some(parser.reject_next_line(LogErrorKind::Unreadable)),
        }
        if line.ends_with('\n') {
            line.pop();
        }
        match parser.feed_line(&line) {
            Ok(Some(record)) => on_record(&record)?,
            Ok(None) => {}
            Err(e) => break Some(e),
        }
    })
}

/// Records per batch handed from the reading thread to the limiter's in
/// [`for_each_record_pipelined`]: large enough that the hand-over costs
/// nothing per record, small enough (40 KB) to stay in cache.
const BATCH_RECORDS: usize = 1024;

/// Batches in flight between the two threads (a bounded channel: a slow
/// limiter holds the reader back instead of filling memory with the log).
const BATCHES_IN_FLIGHT: usize = 8;

/// What the reading thread hands over.
enum Parsed {
    /// Data records in log order, and the bytes of the lines they came from.
    Records(Vec<Record<f32>>, usize),
    /// The log ended: [`for_each_record`]'s answer (after every record).
    End(anyhow::Result<Option<LogError>>),
}

/// [`for_each_record`] with the text read and parsed on a second thread
/// while this one runs `on_record`: reading the text costs about half of
/// what the limiter does per sample, so on two cores a long log replays
/// at the limiter's own pace. The records reach `on_record` in log order
/// and the answer is the same as [`for_each_record`]'s (an error of
/// `on_record` ends it at once; the reader then stops at its next batch).
pub fn for_each_record_pipelined<R: BufRead + Send>(
    reader: &mut R,
    mut on_line: impl FnMut(usize),
    mut on_record: impl FnMut(&Record<f32>) -> anyhow::Result<()>,
) -> anyhow::Result<Option<LogError>> {
    let (tx, rx) = std::sync::mpsc::sync_channel::<Parsed>(BATCHES_IN_FLIGHT);
    std::thread::scope(|scope| {
        scope.spawn(move || {
            let bytes = std::cell::Cell::new(0usize);
            let mut batch = Vec::with_capacity(BATCH_RECORDS);
            let end = for_each_record(
                reader,
                |n| bytes.set(bytes.get() + n),
                |record| {
                    batch.push(*record);
                    if batch.len() == BATCH_RECORDS {
                        let full = std::mem::replace(&mut batch, Vec::with_capacity(BATCH_RECORDS));
                        // A closed channel: the limiter's side stopped on an error of its own.
                        tx.send(Parsed::Records(full, bytes.replace(0)))
                            .map_err(|_| anyhow::anyhow!("replay stopped"))?;
                    }
                    Ok(())
                },
            );
            // Whatever the limiter's side still takes: the last records, then the end.
            let _ = tx.send(Parsed::Records(batch, bytes.get()));
            let _ = tx.send(Parsed::End(end));
        });
        // `rx` is dropped on every way out, which releases a reader blocked on a full channel.
        for parsed in rx {
            match parsed {
                Parsed::Records(records, bytes) => {
                    on_line(bytes);
                    for record in &records {
                        on_record(record)?;
                    }
                }
                Parsed::End(end) => return end,
            }
        }
        Err(anyhow::anyhow!("the log's reading thread stopped without an answer"))
    })
}

/// The spread of a log's sample spacing, short of the gaps the limiter
/// faults on: a logger that stamps samples as it receives them jitters, and
/// such a log replays a few samples off the evenly stamped one
/// (docs/log-format.md, "Uneven timestamps").
#[derive(Debug, Default)]
struct Spacing {
    last_us: Option<i64>,
    /// Shortest and longest step (µs) of those within the gap bound.
    range_us: Option<(i64, i64)>,
    /// Steps beyond the gap bound, and the shortest of them (µs).
    gaps: u64,
    shortest_gap_us: Option<i64>,
}

impl Spacing {
    /// Spread (µs) above which a replay says so: 2 ms, a fifth of the
    /// 100 Hz period.
    const NOTE_ABOVE_US: i64 = 2_000;

    /// The longest step the replay's clock takes as no gap (µs).
    const GAP_BOUND_US: i64 = match moment_limiter::clock::ClockConfig::standard().max_gap_us() {
        Some(us) => us as i64,
        None => i64::MAX,
    };

    fn add(&mut self, t_us: i64) {
        if let Some(last) = self.last_us.replace(t_us) {
            let step = t_us - last;
            if step > 0 && step <= Self::GAP_BOUND_US {
                self.range_us = Some(self.range_us.map_or((step, step), |(lo, hi)| (lo.min(step), hi.max(step))));
            } else if step > Self::GAP_BOUND_US {
                self.gaps += 1;
                self.shortest_gap_us = Some(self.shortest_gap_us.map_or(step, |s| s.min(step)));
            }
        }
    }

    /// What to tell the user when every step forward is a gap the limiter
    /// faults on: a `t_s` column written in milliseconds (a 50 Hz log's
    /// 20 ms read as 20 s) replays as one FAULT from its second sample on.
    fn milliseconds_hint(&self) -> Option<String> {
        let shortest = self.shortest_gap_us?;
        // No step within the bound: every step forward was a gap.
        (self.range_us.is_none() && self.gaps >= 2).then(|| {
            format!(
                "every step between the log's samples is a gap the limiter faults on (the shortest {:.3} s; more \
                 than {:.3} s is a gap). If t_s holds milliseconds, divide it by 1000 (docs/log-format.md)",
                shortest as f64 / 1e6,
                Self::GAP_BOUND_US as f64 / 1e6
            )
        })
    }

    /// The note for stderr, when the steps spread by more than
    /// [`Self::NOTE_ABOVE_US`].
    fn note(&self) -> Option<String> {
        let (lo, hi) = self.range_us?;
        (hi - lo > Self::NOTE_ABOVE_US).then(|| {
            format!(
                "note: the samples are {:.1} to {:.1} ms apart. If the timestamps jitter around an even grid (a \
                 logger stamping samples as it receives them), the events can move by a few samples against the \
                 evenly stamped log (docs/log-format.md, \"Uneven timestamps\").",
                lo as f64 / 1e3,
                hi as f64 / 1e3
            )
        })
    }
}

/// The span of a log's boom angles, to name a column written in radians:
/// read as degrees it puts the boom within 1.75° of horizontal all along
/// (90° is 1.57 rad), where the load's pressure reads as a far lighter load
/// (a lowering from 75° to 40° with 8 t on the hook replays as NORMAL at
/// u 0.04–0.37 instead of OVERLOAD).
#[derive(Debug, Default)]
pub(crate) struct AngleSpan {
    range_deg: Option<(f64, f64)>,
}

impl AngleSpan {
    /// The largest |angle| (°) of a log that looks like radians: the
    /// crane's highest angle, 90°, is 1.571 rad, and the reading's noise
    /// and offset add a little.
    const RADIANS_BELOW_DEG: f64 = 1.75;

    pub(crate) fn add(&mut self, deg: f64) {
        if deg.is_finite() {
            self.range_deg = Some(self.range_deg.map_or((deg, deg), |(lo, hi)| (lo.min(deg), hi.max(deg))));
        }
    }

    /// What to tell the user when every angle lies within
    /// ±[`Self::RADIANS_BELOW_DEG`] of horizontal.
    pub(crate) fn radians_hint(&self) -> Option<String> {
        let (lo, hi) = self.range_deg?;
        (lo >= -Self::RADIANS_BELOW_DEG && hi <= Self::RADIANS_BELOW_DEG).then(|| {
            format!(
                "every boom_angle_deg of the log lies between {lo:.2} and {hi:.2}: the boom within {:.2}° of horizontal all \
                 along. If the column holds radians, convert it to degrees (× 57.296): read as degrees, a load's \
                 pressure reads as a far lighter load",
                Self::RADIANS_BELOW_DEG
            )
        })
    }
}

/// The mean pressures of a log, to name p1 and p2 swapped: the boom hangs
/// on the piston side, so p1 reads far above p2 on average (a load lowered
/// from 75° to 40° reads p1 ≈ 100 bar against p2 ≈ 4 bar). Swapped, the
/// force reads negative and the replay FAULTs ("load estimate implausibly
/// negative") without saying why.
#[derive(Debug, Default)]
pub(crate) struct PressureMeans {
    p1_sum: f64,
    p2_sum: f64,
    n: u32,
}

impl PressureMeans {
    /// Adds one sample; a reading that is no number (NaN, inf) is a sensor
    /// fault, not a pressure, and is left out.
    pub(crate) fn add(&mut self, p1_bar: f64, p2_bar: f64) {
        if p1_bar.is_finite() && p2_bar.is_finite() {
            self.p1_sum += p1_bar;
            self.p2_sum += p2_bar;
            self.n += 1;
        }
    }

    /// What to tell the user when p2 reads at least as high as p1 on
    /// average.
    pub(crate) fn swapped_hint(&self) -> Option<String> {
        let n = f64::from(self.n);
        let (p1, p2) = (self.p1_sum / n, self.p2_sum / n);
        (self.n > 0 && p1 <= p2).then(|| {
            format!(
                "p1 (piston side) reads {p1:.1} bar on average and p2 (rod side) {p2:.1} bar: the boom hangs on the \
                 piston side, so p1_bar and p2_bar look swapped (check the wiring or the log's columns)"
            )
        })
    }
}

/// Runs the subcommand; returns the exit code.
pub fn run(args: ReplayArgs) -> anyhow::Result<u8> {
    let file = open_log(&args.log)?;
    if let Some(dir) = &args.report {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create report directory {}", dir.display()))?;
    }
    let calibration = match &args.calibration {
        Some(path) => Some(load_calibration(path)?),
        None => {
            // The firmware prints the same note.
            eprintln!("{}", replay::UNCALIBRATED_NOTE);
            None
        }
    };
    let mut replay = new_replay(calibration)?;
    let mut trace = match &args.trace {
        Some(path) => {
            let mut w = BufWriter::new(
                File::create(path).with_context(|| format!("cannot create {}", path.display()))?,
            );
            let mut s = String::new();
            replay::write_trace_header(&mut s)?;
            w.write_all(s.as_bytes())?;
            Some(w)
        }
        None => None,
    };

    let mut events: Vec<ReplayEvent<f32>> = Vec::new();
    let mut progress = crate::progress::ReplayProgress::new(file.metadata().map_or(0, |m| m.len()));
    let mut recording = args.report.as_ref().map(|_| crate::replay_report::ReplayRecording::default());
    let mut reader = BufReader::new(file);
    // A closed stdout (`| head -1`) ends the printing quietly and the replay
    // goes on, so the exit code still says 0 or 2 (`crate::stdout`).
    let mut out = crate::stdout::stdout();
    let mut text = String::new();
    let mut spacing = Spacing::default();
    let mut angles = AngleSpan::default();
    let mut pressures = PressureMeans::default();

    let error = for_each_record_pipelined(
        &mut reader,
        |bytes| progress.advance(bytes),
        |record| {
            spacing.add(record.t_us);
            angles.add(f64::from(record.frame.boom_angle_deg));
            pressures.add(f64::from(record.frame.p1_bar), f64::from(record.frame.p2_bar));
            let (report, event) = replay.feed(record);
            if let Some(r) = recording.as_mut() {
                r.push(record, &report);
            }
            if let Some(w) = trace.as_mut() {
                text.clear();
                replay::write_trace_line(&mut text, record.t_us, &report)?;
                w.write_all(text.as_bytes())?;
            }
            if let Some(event) = event {
                if !args.json {
                    text.clear();
                    replay::write_event_line(&mut text, &event)?;
                    out.write_all(text.as_bytes())?;
                }
                events.push(event);
            }
            Ok(())
        },
    )?;

    progress.finish();
    if let Some(mut w) = trace {
        w.flush()?;
    }
    let summary = replay.summary();
    text.clear();
    if args.json {
        replay::write_json(&mut text, &summary, events.iter(), error.as_ref())?;
    } else {
        replay::write_summary_line(&mut text, &summary)?;
    }
    out.write_all(text.as_bytes())?;
    out.flush()?;
    // After the timeline, so the two streams do not interleave on a terminal.
    if let Some(note) = spacing.note() {
        eprintln!("{note}");
    }
    if let Some(hint) = angles.radians_hint() {
        eprintln!("warning: {hint}.");
    }
    if let Some(hint) = spacing.milliseconds_hint() {
        eprintln!("warning: {hint}.");
    }
    if let Some(hint) = pressures.swapped_hint() {
        eprintln!("warning: {hint}.");
    }
    let code = match &error {
        Some(e) => {
            eprintln!("error: {}: {e}", args.log.display());
            1
        }
        None => summary.exit_code(),
    };
    if let (Some(dir), Some(recording)) = (&args.report, &recording) {
        // After the timeline is out: a page that cannot be written must not
        // hide the alarm (exit 2 stays 2).
        let log = args.log.display().to_string();
        let calibration = args.calibration.as_ref().map(|c| c.display().to_string());
        let source = crate::replay_report::ReplaySource { log: &log, calibration: calibration.as_deref() };
        if let Err(e) = crate::replay_report::write_replay_report(dir, &source, recording, &events, &summary, error.as_ref()) {
            eprintln!("error: report {}: {e:#}", dir.display());
            return Ok(code.max(1));
        }
    }
    Ok(code)
}
