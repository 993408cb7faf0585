//! Reads a `crane-sim calibrate` file (CAL.json) without a heap.
//!
//! PROVISIONAL: the host's calibration file format is not fixed yet. This reads a
//! flat JSON object and takes the numeric members named like the fields of
//! `moment_limiter::load_estimate::Calibration` (`friction_up_n`,
//! `friction_down_n`, `force_offset_n`, `p1_offset_bar`, `p2_offset_bar`,
//! `angle_offset_deg`); missing ones are 0, other members (strings, numbers,
//! booleans, null, and nested objects/arrays such as metadata) are skipped. If
//! moment-limiter gains a no_std reader for the file, use it instead so host and
//! firmware cannot disagree.

use core::fmt;
use moment_limiter::load_estimate::Calibration;

/// Why the calibration file was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CalibrationFileError(&'static str);

impl fmt::Display for CalibrationFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "bad calibration file: {}", self.0)
    }
}

struct Cursor<'a> {
    s: &'a [u8],
    i: usize,
}

impl<'a> Cursor<'a> {
    fn ws(&mut self) {
        while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }
    fn peek(&mut self) -> Option<u8> {
        self.ws();
        self.s.get(self.i).copied()
    }
    fn expect(&mut self, c: u8, what: &'static str) -> Result<(), CalibrationFileError> {
        if self.peek() == Some(c) {
            self.i += 1;
            Ok(())
        } else {
            Err(CalibrationFileError(what))
        }
    }
    /// A string without escapes is returned; one with escapes is skipped (`None`).
    fn string(&mut self) -> Result<Option<&'a str>, CalibrationFileError> {
        self.expect(b'"', "expected a string")?;
        let start = self.i;
        let mut escaped = false;
        while let Some(&c) = self.s.get(self.i) {
            self.i += 1;
            match c {
                b'\\' => {
                    escaped = true;
                    self.i += 1;
                }
                b'"' => {
                    let raw = &self.s[start..self.i - 1];
                    return Ok(if escaped {
                        None
                    } else {
                        core::str::from_utf8(raw).ok()
                    });
                }
                _ => {}
            }
        }
        Err(CalibrationFileError("unterminated string"))
    }
    fn scalar(&mut self) -> &'a str {
        self.ws();
        let start = self.i;
        while let Some(&c) = self.s.get(self.i) {
            if c == b',' || c == b'}' || c == b']' || c.is_ascii_whitespace() {
                break;
            }
            self.i += 1;
        }
        core::str::from_utf8(&self.s[start..self.i]).unwrap_or("")
    }
    /// Skips any JSON value (bounded nesting).
    fn skip_value(&mut self, depth: u8) -> Result<(), CalibrationFileError> {
        if depth > 8 {
            return Err(CalibrationFileError("nested too deep"));
        }
        match self.peek() {
            Some(b'"') => self.string().map(|_| ()),
            Some(open @ (b'{' | b'[')) => {
                let close = if open == b'{' { b'}' } else { b']' };
                self.i += 1;
                if self.peek() == Some(close) {
                    self.i += 1;
                    return Ok(());
                }
                loop {
                    if open == b'{' {
                        self.string()?;
                        self.expect(b':', "expected ':'")?;
                    }
                    self.skip_value(depth + 1)?;
                    match self.peek() {
                        Some(b',') => self.i += 1,
                        Some(c) if c == close => {
                            self.i += 1;
                            return Ok(());
                        }
                        _ => return Err(CalibrationFileError("expected ',' or a closing bracket")),
                    }
                }
            }
            Some(_) => {
                if self.scalar().is_empty() {
                    Err(CalibrationFileError("expected a value"))
                } else {
                    Ok(())
                }
            }
            None => Err(CalibrationFileError("unexpected end")),
        }
    }
}

/// Parses the calibration file.
pub fn parse(text: &[u8]) -> Result<Calibration<f32>, CalibrationFileError> {
    let mut cal = Calibration::<f32>::none();
    let mut c = Cursor { s: text, i: 0 };
    if text.starts_with("\u{feff}".as_bytes()) {
        c.i = 3;
    }
    c.expect(b'{', "expected a JSON object")?;
    if c.peek() == Some(b'}') {
        c.i += 1;
    } else {
        loop {
            let key = c.string()?;
            c.expect(b':', "expected ':'")?;
            let slot = match key {
                Some("friction_up_n") => Some(&mut cal.friction_up_n),
                Some("friction_down_n") => Some(&mut cal.friction_down_n),
                Some("force_offset_n") => Some(&mut cal.force_offset_n),
                Some("p1_offset_bar") => Some(&mut cal.p1_offset_bar),
                Some("p2_offset_bar") => Some(&mut cal.p2_offset_bar),
                Some("angle_offset_deg") => Some(&mut cal.angle_offset_deg),
                _ => None,
            };
            match slot {
                Some(slot) => {
                    let v: f64 = c
                        .scalar()
                        .parse()
                        .map_err(|_| CalibrationFileError("a calibration value is not a number"))?;
                    // The host parses f64 and the limiter converts with `Real::lit`.
                    *slot = v as f32;
                }
                None => c.skip_value(0)?,
            }
            match c.peek() {
                Some(b',') => c.i += 1,
                Some(b'}') => {
                    c.i += 1;
                    break;
                }
                _ => return Err(CalibrationFileError("expected ',' or '}'")),
            }
        }
    }
    if c.peek().is_some() {
        return Err(CalibrationFileError("trailing characters after the object"));
    }
    if !cal.is_valid() {
        return Err(CalibrationFileError(
            "values not finite or negative friction",
        ));
    }
    Ok(cal)
}
