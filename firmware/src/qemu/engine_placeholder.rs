//! PLACEHOLDER for `moment_limiter::replay` (being written by another session):
//! just enough of a replay engine to exercise the QEMU plumbing (semihosting
//! file reading, output, exit codes, budgets). It parses `t_s,p1_bar,p2_bar,
//! boom_angle_deg` rows and flags out-of-range readings as FAULT; it has no load
//! estimate. Replaced by the limiter crate's engine and formatting functions as
//! soon as they exist; nothing outside `qemu::replay` uses it.

use core::fmt::{self, Write};

/// Limiter state (placeholder).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum State {
    /// No alarm.
    Normal,
    /// Sensor fault.
    Fault,
}

impl State {
    fn name(self) -> &'static str {
        match self {
            State::Normal => "NORMAL",
            State::Fault => "FAULT",
        }
    }
}

/// A state change (placeholder).
#[derive(Debug, Clone, Copy)]
pub struct Event {
    /// Sample index (0-based).
    pub sample: u32,
    /// Time (s).
    pub t_s: f32,
    /// New state.
    pub state: State,
}

/// A malformed line (placeholder).
#[derive(Debug, Clone, Copy)]
pub struct LineError {
    /// 1-based line number.
    pub line: u32,
    /// What is wrong.
    pub what: &'static str,
}

impl fmt::Display for LineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.what)
    }
}

/// The placeholder engine.
#[derive(Debug)]
pub struct Replay {
    line: u32,
    header_seen: bool,
    samples: u32,
    state: State,
    entered_alarm: bool,
}

impl Replay {
    /// A fresh replay.
    pub fn new() -> Self {
        Replay {
            line: 0,
            header_seen: false,
            samples: 0,
            state: State::Normal,
            entered_alarm: false,
        }
    }

    /// Feeds one line of the log; returns a state change if there was one.
    pub fn push_line(&mut self, text: &str) -> Result<Option<Event>, LineError> {
        self.line += 1;
        let text = text.trim();
        if text.is_empty() || text.starts_with('#') {
            return Ok(None);
        }
        if !self.header_seen {
            self.header_seen = true;
            return if text.starts_with("t_s,p1_bar,p2_bar,boom_angle_deg") {
                Ok(None)
            } else {
                Err(LineError {
                    line: self.line,
                    what: "bad header",
                })
            };
        }
        let mut fields = text.split(',');
        let mut v = [0f32; 4];
        for x in v.iter_mut() {
            *x = fields
                .next()
                .and_then(|s| s.trim().parse().ok())
                .ok_or(LineError {
                    line: self.line,
                    what: "missing or non-numeric field",
                })?;
        }
        let sample = self.samples;
        self.samples += 1;
        let in_range = (-4.0..=210.0).contains(&v[1])
            && (-4.0..=210.0).contains(&v[2])
            && (-5.0..=95.0).contains(&v[3]);
        let state = if in_range {
            State::Normal
        } else {
            State::Fault
        };
        if state != self.state {
            self.state = state;
            self.entered_alarm |= state == State::Fault;
            return Ok(Some(Event {
                sample,
                t_s: v[0],
                state,
            }));
        }
        Ok(None)
    }

    /// Exit code: 2 if FAULT was entered, else 0.
    pub fn exit_code(&self) -> u8 {
        if self.entered_alarm {
            2
        } else {
            0
        }
    }

    /// Writes one timeline line.
    pub fn write_event(w: &mut impl Write, e: &Event) -> fmt::Result {
        writeln!(
            w,
            "{:>10.3} s  sample {:>6}  {}",
            e.t_s,
            e.sample,
            e.state.name()
        )
    }

    /// Writes the summary (text or JSON).
    pub fn write_summary(&self, w: &mut impl Write, json: bool) -> fmt::Result {
        if json {
            writeln!(
                w,
                "{{\"samples\":{},\"final_state\":\"{}\",\"placeholder\":true}}",
                self.samples,
                self.state.name()
            )
        } else {
            writeln!(
                w,
                "samples {}  final state {}",
                self.samples,
                self.state.name()
            )
        }
    }
}
