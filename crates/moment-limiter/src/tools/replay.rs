//! Replay of a recorded log through the limiter, and its printed output.
//!
//! [`Replay`] feeds [`Record`]s into a [`Limiter`] (the same code the firmware
//! runs, through [`Limiter::step_frame`]) and turns state changes into
//! [`ReplayEvent`]s; the first sample always gives one (the initial state).
//! The formatting functions write into any [`core::fmt::Write`], so the host
//! and the firmware (over semihosting) print byte-identical text by
//! construction.
//!
//! Output formats (numbers: time 3 decimals, utilization 4, loads 1):
//! - timeline line: `t=12.340 s OVERLOAD utilization=1.0123 load_kg=8123.4 sample=1234`
//!   and for FAULT a trailing ` fault="p1 out of range"`; unknown values are `-`;
//! - summary line: `samples=3000 max_utilization=0.8120 final_state=NORMAL`;
//! - JSON: one object `{"samples":…,"max_utilization":…,"final_state":"…",
//!   "calibrated":true,"complete":true,"error":null,"events":[{"t_s":…,"state":"…",
//!   "utilization":…,"load_kg":…,"sample":…,"fault":null},…]}`; unknown
//!   numbers are `null`; `complete` is false and `error` the message when the
//!   log could not be read to its end; `calibrated` is false when the replay
//!   ran without a calibration file (friction and offsets taken as zero);
//! - trace CSV: `t_s,load_kg,rated_load_kg,utilization,state`, empty cells
//!   where unknown.
//!
//! Times are printed from the log's exact microseconds
//! ([`crate::tools::log_format`]), rounded to the millisecond with integer
//! arithmetic, so they are right at any offset (a float would print a time
//! 463 days into a log to the nearest 4 s).

use core::fmt::{self, Write};

use crane_model::loads::load_model::HookLoadModel;
use crane_model::Real;

use crate::clock::write_micros_as_seconds;
use crate::cycle::{Limiter, StepReport};
use crate::fault::Fault;
use crate::tools::log_format::{LogError, Record};
use crate::state_machine::LimiterState;

/// What a replay without a calibration says on stderr (host and firmware).
pub const UNCALIBRATED_NOTE: &str = "note: no --calibration given: cylinder friction and sensor offsets are taken as zero (uncalibrated; \"calibrated\":false in --json)";

/// A change of state during a replay.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReplayEvent<T> {
    /// 0-based index of the sample.
    pub sample: u32,
    /// Line of the log it came from.
    pub line: u32,
    /// Time of the log row, exactly (µs).
    pub t_us: i64,
    /// State entered.
    pub state: LimiterState,
    /// Utilization, if known.
    pub utilization: Option<T>,
    /// Estimated load (kg), if known.
    pub load_kg: Option<T>,
    /// Cause, for FAULT.
    pub fault: Option<Fault>,
}

/// Totals of a replay so far.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReplaySummary<T> {
    /// Samples replayed.
    pub samples: u32,
    /// Highest utilization seen, if any was computed.
    pub max_utilization: Option<T>,
    /// State after the last sample (`None` before the first).
    pub final_state: Option<LimiterState>,
    /// `true` if OVERLOAD or FAULT was entered at least once.
    pub entered_cut_state: bool,
    /// `false` when the replay runs without a calibration (friction and
    /// offsets zero): printed in the JSON so no one mistakes it for a
    /// calibrated result.
    pub calibrated: bool,
}

impl<T> ReplaySummary<T> {
    /// Exit code of `crane-sim replay` for a log read to its end: 2 if it
    /// entered OVERLOAD or FAULT, else 0. (1, unreadable input, is the
    /// reader's to give.)
    pub fn exit_code(&self) -> u8 {
        if self.entered_cut_state {
            2
        } else {
            0
        }
    }
}

/// A replay in progress.
#[derive(Debug, Clone)]
pub struct Replay<T, M> {
    limiter: Limiter<T, M>,
    summary: ReplaySummary<T>,
}

impl<T: Real, M: HookLoadModel<T>> Replay<T, M> {
    /// Starts a replay on a fresh limiter; `calibrated` says whether its
    /// configuration holds a calibration read from a file.
    pub fn new(limiter: Limiter<T, M>, calibrated: bool) -> Self {
        Self {
            limiter,
            summary: ReplaySummary {
                samples: 0,
                max_utilization: None,
                final_state: None,
                entered_cut_state: false,
                calibrated,
            },
        }
    }

    /// Runs one record; returns the cycle's report and the event if the state changed.
    pub fn feed(&mut self, record: &Record<T>) -> (StepReport<T>, Option<ReplayEvent<T>>) {
        let report = self.limiter.step_frame(&record.frame);
        let s = &mut self.summary;
        let event = (s.final_state != Some(report.state)).then(|| ReplayEvent {
            sample: s.samples,
            line: record.line,
            t_us: record.t_us,
            state: report.state,
            utilization: report.estimate.map(|e| e.utilization),
            load_kg: report.estimate.map(|e| e.load_kg),
            fault: report.fault,
        });
        if let Some(u) = report.estimate.map(|e| e.utilization) {
            s.max_utilization = Some(s.max_utilization.map_or(u, |m| m.max(u)));
        }
        s.entered_cut_state |= report.state.cuts();
        s.final_state = Some(report.state);
        s.samples = s.samples.saturating_add(1);
        (report, event)
    }

    /// Totals so far.
    pub fn summary(&self) -> ReplaySummary<T> {
        self.summary
    }

    /// The limiter (its event log, its model).
    pub fn limiter(&self) -> &Limiter<T, M> {
        &self.limiter
    }
}

/// Writes `x` with `decimals` decimals, or `absent` if unknown or not finite.
fn number<W: Write, T: Real>(
    w: &mut W,
    x: Option<T>,
    decimals: usize,
    absent: &str,
) -> fmt::Result {
    match x.map(Real::to_f64) {
        Some(v) if v.is_finite() => write!(w, "{v:.decimals$}"),
        _ => w.write_str(absent),
    }
}

/// Writes `s` as a JSON string literal.
fn json_string<W: Write>(w: &mut W, s: &str) -> fmt::Result {
    w.write_char('"')?;
    for c in s.chars() {
        match c {
            '"' => w.write_str("\\\"")?,
            '\\' => w.write_str("\\\\")?,
            c if (c as u32) < 0x20 => write!(w, "\\u{:04x}", c as u32)?,
            c => w.write_char(c)?,
        }
    }
    w.write_char('"')
}

/// Adapts a `Display` into a JSON string literal without a buffer.
struct JsonEscaped<'a, W>(&'a mut W);

impl<W: Write> Write for JsonEscaped<'_, W> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        for c in s.chars() {
            match c {
                '"' => self.0.write_str("\\\"")?,
                '\\' => self.0.write_str("\\\\")?,
                c if (c as u32) < 0x20 => write!(self.0, "\\u{:04x}", c as u32)?,
                c => self.0.write_char(c)?,
            }
        }
        Ok(())
    }
}

fn json_display<W: Write, D: fmt::Display>(w: &mut W, d: &D) -> fmt::Result {
    w.write_char('"')?;
    write!(JsonEscaped(w), "{d}")?;
    w.write_char('"')
}

/// Writes one timeline line (with a trailing newline).
pub fn write_event_line<W: Write, T: Real>(w: &mut W, e: &ReplayEvent<T>) -> fmt::Result {
    w.write_str("t=")?;
    write_micros_as_seconds(w, e.t_us)?;
    write!(w, " s {} utilization=", e.state.as_str())?;
    number(w, e.utilization, 4, "-")?;
    w.write_str(" load_kg=")?;
    number(w, e.load_kg, 1, "-")?;
    write!(w, " sample={}", e.sample)?;
    if let Some(f) = &e.fault {
        write!(w, " fault=\"{f}\"")?;
    }
    w.write_char('\n')
}

/// Writes the summary line (with a trailing newline).
pub fn write_summary_line<W: Write, T: Real>(w: &mut W, s: &ReplaySummary<T>) -> fmt::Result {
    write!(w, "samples={} max_utilization=", s.samples)?;
    number(w, s.max_utilization, 4, "-")?;
    writeln!(
        w,
        " final_state={}",
        s.final_state.map_or("-", LimiterState::as_str)
    )
}

/// Writes the JSON summary (one object, trailing newline). `error` is the
/// reason the log was not read to its end, if it was not.
pub fn write_json<'a, W: Write, T: Real + 'a>(
    w: &mut W,
    s: &ReplaySummary<T>,
    events: impl IntoIterator<Item = &'a ReplayEvent<T>>,
    error: Option<&LogError>,
) -> fmt::Result {
    write!(w, "{{\"samples\":{},\"max_utilization\":", s.samples)?;
    number(w, s.max_utilization, 4, "null")?;
    w.write_str(",\"final_state\":")?;
    match s.final_state {
        Some(state) => json_string(w, state.as_str())?,
        None => w.write_str("null")?,
    }
    write!(
        w,
        ",\"calibrated\":{},\"complete\":{},\"error\":",
        s.calibrated,
        error.is_none()
    )?;
    match error {
        Some(e) => json_display(w, e)?,
        None => w.write_str("null")?,
    }
    w.write_str(",\"events\":[")?;
    for (i, e) in events.into_iter().enumerate() {
        if i > 0 {
            w.write_char(',')?;
        }
        w.write_str("{\"t_s\":")?;
        write_micros_as_seconds(w, e.t_us)?;
        w.write_str(",\"state\":")?;
        json_string(w, e.state.as_str())?;
        w.write_str(",\"utilization\":")?;
        number(w, e.utilization, 4, "null")?;
        w.write_str(",\"load_kg\":")?;
        number(w, e.load_kg, 1, "null")?;
        write!(w, ",\"sample\":{},\"fault\":", e.sample)?;
        match &e.fault {
            Some(f) => json_display(w, f)?,
            None => w.write_str("null")?,
        }
        w.write_char('}')?;
    }
    w.write_str("]}\n")
}

/// Writes the header of the `--trace` CSV.
pub fn write_trace_header<W: Write>(w: &mut W) -> fmt::Result {
    w.write_str("t_s,load_kg,rated_load_kg,utilization,state\n")
}

/// Writes one `--trace` row for the log row at `t_us` (exact, µs).
pub fn write_trace_line<W: Write, T: Real>(
    w: &mut W,
    t_us: i64,
    r: &StepReport<T>,
) -> fmt::Result {
    write_micros_as_seconds(w, t_us)?;
    w.write_char(',')?;
    number(w, r.estimate.map(|e| e.load_kg), 1, "")?;
    w.write_char(',')?;
    number(w, r.estimate.map(|e| e.rated_load_kg), 1, "")?;
    w.write_char(',')?;
    number(w, r.estimate.map(|e| e.utilization), 4, "")?;
    writeln!(w, ",{}", r.state.as_str())
}
