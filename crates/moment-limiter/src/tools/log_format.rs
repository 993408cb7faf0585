//! The sensor log format of SPEC §5, parsed one line at a time (no heap).
//!
//! ```text
//! # comment lines start with '#'
//! t_s,p1_bar,p2_bar,boom_angle_deg,true_load_kg
//! 0.00,61.2,5.1,40.02,3300
//! ```
//! - UTF-8; a byte-order mark before the header and `\r\n` endings are accepted.
//! - `#` lines and blank lines are skipped (but counted in line numbers).
//! - The first other line is the header. It must name `t_s`, `p1_bar`,
//!   `p2_bar` and `boom_angle_deg`, in any order; `true_load_kg` is optional;
//!   other columns are allowed and ignored. Names are case-sensitive.
//! - Each data row has exactly as many fields as the header. Fields are
//!   decimal numbers (surrounding spaces allowed). A field or column name
//!   may be wrapped in double quotes, as spreadsheets and CSV writers quote
//!   (`"t_s","p1_bar"`); a quoted field holds no comma (a log's numbers
//!   have decimal points). `t_s` must be finite and
//!   never decrease. A sensor value written as `NaN` or `inf` is read as such
//!   and becomes a sensor FAULT in the limiter, like any out-of-range value;
//!   text that is not a number is a format error. `true_load_kg` may be empty.
//!
//! Errors name the 1-based line (comments and header counted) and the field.
//!
//! ## Time
//!
//! `t_s` is read **exactly**, from its decimal digits (an optional sign, an
//! optional exponent), to whole microseconds: digits beyond the microsecond
//! are rounded, half away from zero; the time may be anywhere within
//! ±9.2·10¹² s. It is never converted through a float, so a log whose times
//! are shifted by any whole number of microseconds (40 h, 463 days, across
//! the limiter clock's 2³² µs wrap) replays to the same events at the same
//! samples. [`Record::t_us`] keeps the exact time (for printing);
//! [`Frame::t`] is the limiter's wrapping tick ([`crate::clock`]), the
//! exact differences of the log's times, except that a step of 2³¹ µs
//! (35.8 min) or more is handed to the limiter as 2³¹ − 1 µs, a gap it
//! faults on like any gap over 50 ms (the 32-bit clock could otherwise not
//! tell a gap of k × 71.6 min from none).
//!
//! **Which time errors are the file's and which the limiter's.** A time that
//! is not a number, not finite, out of range or **earlier than the previous
//! row's** is a malformed file (SPEC §5): an error naming the line; the replay
//! stops there. A time **equal to the previous row's** (a stalled clock,
//! duplicate samples) or a **gap** between rows is data: it is what the
//! controller would have lived through, so it goes to the limiter, which
//! FAULTs and cuts exactly as on the board ([`crate::clock`]); the replay
//! shows the FAULT at that sample and exits 2, never 0.
//! The firmware reads the log line by line through semihosting and calls
//! [`LogParser::feed_line`] on each; the host does the same.

use core::fmt;

use crane_model::Real;

use crate::clock::{Ticks, BACKWARDS_FROM_US};
use crate::io::Frame;

/// Most columns a header may have.
pub const MAX_COLUMNS: usize = 16;

/// Name of the time column.
pub const T_S: &str = "t_s";
/// Name of the piston-side pressure column.
pub const P1_BAR: &str = "p1_bar";
/// Name of the rod-side pressure column.
pub const P2_BAR: &str = "p2_bar";
/// Name of the boom angle column.
pub const BOOM_ANGLE_DEG: &str = "boom_angle_deg";
/// Name of the optional true-load column.
pub const TRUE_LOAD_KG: &str = "true_load_kg";

/// What a header column holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Column {
    Time,
    P1,
    P2,
    Angle,
    TrueLoad,
    Ignored,
}

impl Column {
    fn from_name(name: &str) -> Self {
        match name {
            T_S => Column::Time,
            P1_BAR => Column::P1,
            P2_BAR => Column::P2,
            BOOM_ANGLE_DEG => Column::Angle,
            TRUE_LOAD_KG => Column::TrueLoad,
            _ => Column::Ignored,
        }
    }
    fn name(self) -> &'static str {
        match self {
            Column::Time => T_S,
            Column::P1 => P1_BAR,
            Column::P2 => P2_BAR,
            Column::Angle => BOOM_ANGLE_DEG,
            Column::TrueLoad => TRUE_LOAD_KG,
            Column::Ignored => "(ignored column)",
        }
    }
}

/// What is wrong with the log.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LogErrorKind {
    /// The file has no header (it is empty or holds only comments).
    Empty,
    /// The header names no such required column.
    MissingColumn(&'static str),
    /// The header names this required column only in other letter case
    /// (`T_S`): names are case-sensitive.
    ColumnCase(&'static str),
    /// The header names this required column only with another unit or
    /// spelling (`t_ms`, `time`, `p1_psi`, `boom_angle_rad`).
    ColumnUnit(&'static str),
    /// The header holds no comma but this separator (`;` or a tab): a
    /// spreadsheet's export in a locale that writes decimal commas.
    WrongSeparator(char),
    /// The header names a column twice.
    DuplicateColumn(&'static str),
    /// The first line that is not a comment looks like data, not a header.
    NoHeader,
    /// The header has more than [`MAX_COLUMNS`] columns.
    TooManyColumns,
    /// The row ends before this field.
    MissingField(&'static str),
    /// The row has more fields than the header.
    TooManyFields,
    /// The row has more fields than the header, and every one too many is
    /// empty: the row ends with a comma.
    TrailingComma,
    /// The row has more fields than the header or a field that is not a
    /// number, writes no decimal point, and has a field that only a decimal
    /// comma explains (`0,05` splits into `0` and `05`; `"45,3"` is quoted): a
    /// spreadsheet's export in a locale that writes decimal commas.
    DecimalCommas,
    /// This field is empty.
    EmptyField(&'static str),
    /// A data row whose time is the word `t_s`: a second header, as where
    /// two logs were joined into one file.
    SecondHeader,
    /// The first line that is not a comment opens a JSON object or array:
    /// a calibration file given where the log goes.
    Json,
    /// This field is not a number.
    NotANumber(&'static str),
    /// The time is not finite.
    TimeNotFinite,
    /// The time is beyond ±9.2·10¹² s (it does not fit the exact clock).
    TimeOutOfRange,
    /// The time is earlier than the previous row's.
    TimeBackwards,
    /// The header is followed by no data row.
    NoSamples,
    /// The line is not valid UTF-8 (reported by the reader, which sees bytes).
    NotUtf8,
    /// The log starts with a UTF-16 byte-order mark (a spreadsheet's
    /// "Unicode text" export; reported by the reader).
    Utf16,
    /// The line could not be read at all (reported by the reader).
    Unreadable,
}

/// A log error, with the 1-based line it is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LogError {
    /// 1-based line number (comment and header lines counted).
    pub line: u32,
    /// What is wrong.
    pub kind: LogErrorKind,
}

impl fmt::Display for LogError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: ", self.line)?;
        match self.kind {
            LogErrorKind::Empty => f.write_str("empty log: no header line"),
            LogErrorKind::MissingColumn(c) => write!(f, "header has no column `{c}`"),
            LogErrorKind::ColumnCase(c) => write!(
                f,
                "header has no column `{c}`, only one that differs from it in letter case: column names are case-sensitive"
            ),
            LogErrorKind::ColumnUnit(c) => write!(
                f,
                "header has no column `{c}`, only one like it in another unit or spelling: a log has `{T_S}` in seconds, `{P1_BAR}` and `{P2_BAR}` in bar and `{BOOM_ANGLE_DEG}` in degrees (docs/log-format.md)"
            ),
            LogErrorKind::WrongSeparator(c) => write!(
                f,
                "header is separated by {}, not by commas: a log is comma-separated with decimal points (`{T_S},{P1_BAR},{P2_BAR},{BOOM_ANGLE_DEG}`; docs/log-format.md)",
                if c == '\t' { "tabs" } else { "`;`" }
            ),
            LogErrorKind::DuplicateColumn(c) => write!(f, "header names column `{c}` twice"),
            LogErrorKind::NoHeader => write!(
                f,
                "header required (`{T_S},{P1_BAR},{P2_BAR},{BOOM_ANGLE_DEG}`), found data"
            ),
            LogErrorKind::TooManyColumns => write!(f, "header has more than {MAX_COLUMNS} columns"),
            LogErrorKind::MissingField(c) => write!(f, "field `{c}` missing (row too short)"),
            LogErrorKind::TooManyFields => f.write_str("more fields than the header has columns"),
            LogErrorKind::Json => f.write_str(
                "this is JSON (a calibration file?), not a CSV sensor log (docs/log-format.md)",
            ),
            LogErrorKind::SecondHeader => f.write_str(
                "a second header: the file looks like two logs joined into one; replay each on its own",
            ),
            LogErrorKind::TrailingComma => f.write_str(
                "more fields than the header has columns: the row ends with a comma (the header does not)",
            ),
            LogErrorKind::DecimalCommas => f.write_str(
                "more fields than the header has columns: the numbers look written with decimal commas (`0,05`); a log writes decimal points (`0.05`) and separates fields with commas (docs/log-format.md)",
            ),
            LogErrorKind::EmptyField(c) => write!(f, "field `{c}` is empty"),
            LogErrorKind::NotANumber(c) => write!(f, "field `{c}` is not a number"),
            LogErrorKind::TimeNotFinite => write!(f, "field `{T_S}` is not a finite time"),
            LogErrorKind::TimeOutOfRange => {
                write!(f, "field `{T_S}` is out of range (beyond ±9.2e12 s)")
            }
            LogErrorKind::TimeBackwards => write!(f, "field `{T_S}` goes backwards in time"),
            LogErrorKind::NoSamples => f.write_str("no data rows after the header"),
            LogErrorKind::NotUtf8 => f.write_str("not valid UTF-8"),
            LogErrorKind::Utf16 => f.write_str(
                "the log is UTF-16 text (a spreadsheet's \"Unicode text\" export), not UTF-8: save it as CSV in UTF-8 (docs/log-format.md)",
            ),
            LogErrorKind::Unreadable => f.write_str("could not be read"),
        }
    }
}

/// One data row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Record<T> {
    /// 1-based line number of the row.
    pub line: u32,
    /// The row's time exactly as written, in microseconds (see "Time").
    pub t_us: i64,
    /// The sensor values.
    pub frame: Frame<T>,
    /// The true hook load (kg), if the log has it.
    pub true_load_kg: Option<T>,
}

/// A line-at-a-time parser of the log format.
#[derive(Debug, Clone)]
pub struct LogParser<T> {
    line: u32,
    columns: Option<heapless::Vec<Column, MAX_COLUMNS>>,
    /// Exact time (µs) and tick of the previous row.
    last: Option<(i64, Ticks)>,
    samples: u32,
    _values: core::marker::PhantomData<T>,
}

impl<T: Real> Default for LogParser<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> LogParser<T> {
    /// A parser before the first line.
    pub fn new() -> Self {
        Self {
            line: 0,
            columns: None,
            last: None,
            samples: 0,
            _values: core::marker::PhantomData,
        }
    }

    /// Number of lines fed so far (= the line number of the last one).
    pub fn line(&self) -> u32 {
        self.line
    }

    /// Number of data rows parsed so far.
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// An error on the line about to be fed (for a reader that could not
    /// decode or read it): counts the line and returns the error.
    pub fn reject_next_line(&mut self, kind: LogErrorKind) -> LogError {
        self.line = self.line.saturating_add(1);
        LogError {
            line: self.line,
            kind,
        }
    }

    /// Parses the next line (without its line ending; a trailing `\r` is
    /// removed). Returns the record for a data row, `None` for a comment,
    /// blank or header line.
    pub fn feed_line(&mut self, raw: &str) -> Result<Option<Record<T>>, LogError> {
        self.line = self.line.saturating_add(1);
        let line_no = self.line;
        let err = |kind| LogError {
            line: line_no,
            kind,
        };
        let mut text = raw.strip_suffix('\r').unwrap_or(raw);
        if self.columns.is_none() {
            text = text.strip_prefix('\u{feff}').unwrap_or(text);
        }
        let trimmed = text.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            return Ok(None);
        }
        let Some(columns) = &self.columns else {
            self.columns = Some(parse_header(trimmed).map_err(err)?);
            return Ok(None);
        };
        let mut fields = trimmed.split(',');
        let mut values: [Option<T>; 5] = [None; 5];
        let mut time_us = None;
        for &column in columns.iter() {
            let field = unquote(
                fields
                    .next()
                    .ok_or(err(LogErrorKind::MissingField(column.name())))?,
            );
            let slot = match column {
                Column::Time => values.get_mut(0),
                Column::P1 => values.get_mut(1),
                Column::P2 => values.get_mut(2),
                Column::Angle => values.get_mut(3),
                Column::TrueLoad if field.is_empty() => None,
                Column::TrueLoad => values.get_mut(4),
                Column::Ignored => None,
            };
            if let Some(slot) = slot {
                if field.is_empty() {
                    return Err(err(LogErrorKind::EmptyField(column.name())));
                }
                // `"45,3"` splits into `"45` and `3"`: name the decimal comma.
                let named = |kind| match kind {
                    LogErrorKind::NotANumber(_) if looks_decimal_comma(trimmed) => err(LogErrorKind::DecimalCommas),
                    kind => err(kind),
                };
                if column == Column::Time {
                    if field == T_S {
                        return Err(err(LogErrorKind::SecondHeader));
                    }
                    time_us = Some(parse_time_us(field).map_err(named)?);
                    continue;
                }
                let v: f64 = field
                    .parse()
                    .map_err(|_| named(LogErrorKind::NotANumber(column.name())))?;
                *slot = Some(T::lit(v));
            }
        }
        if let Some(extra) = fields.next() {
            let trailing = extra.trim().is_empty() && fields.all(|f| f.trim().is_empty());
            return Err(err(if trailing {
                LogErrorKind::TrailingComma
            } else if looks_decimal_comma(trimmed) {
                LogErrorKind::DecimalCommas
            } else {
                LogErrorKind::TooManyFields
            }));
        }
        let missing = |name| err(LogErrorKind::MissingField(name));
        let [_, p1, p2, angle, true_load] = values;
        let t_us = time_us.ok_or(missing(T_S))?;
        let frame = Frame {
            t: Ticks(0),
            p1_bar: p1.ok_or(missing(P1_BAR))?,
            p2_bar: p2.ok_or(missing(P2_BAR))?,
            boom_angle_deg: angle.ok_or(missing(BOOM_ANGLE_DEG))?,
        };
        let t = match self.last {
            None => Ticks(t_us as u32), // the low 32 bits: wrapping
            Some((last_us, last_tick)) => {
                let step = t_us
                    .checked_sub(last_us)
                    .filter(|d| *d >= 0)
                    .ok_or(err(LogErrorKind::TimeBackwards))?;
                let clamped = u32::try_from(step)
                    .unwrap_or(u32::MAX)
                    .min(BACKWARDS_FROM_US - 1);
                last_tick.wrapping_add_micros(clamped)
            }
        };
        self.last = Some((t_us, t));
        self.samples = self.samples.saturating_add(1);
        Ok(Some(Record {
            line: line_no,
            t_us,
            frame: Frame {
                t,
                ..frame
            },
            true_load_kg: true_load,
        }))
    }

    /// Call at the end of the input: an empty log or a header without rows is
    /// an error (on line 1, or on the line after the last).
    pub fn finish(&self) -> Result<(), LogError> {
        if self.columns.is_none() {
            Err(LogError {
                line: self.line.max(1),
                kind: LogErrorKind::Empty,
            })
        } else if self.samples == 0 {
            Err(LogError {
                line: self.line.saturating_add(1),
                kind: LogErrorKind::NoSamples,
            })
        } else {
            Ok(())
        }
    }
}

/// Reads a decimal time in seconds (`[+-]digits[.digits][e[+-]digits]`)
/// exactly, as whole microseconds, rounding the digits beyond the
/// microsecond half away from zero (see "Time" in the module doc).
pub fn parse_time_us(text: &str) -> Result<i64, LogErrorKind> {
    if text.parse::<f64>().is_ok_and(|v| !v.is_finite()) {
        return Err(LogErrorKind::TimeNotFinite);
    }
    let not_a_number = LogErrorKind::NotANumber(T_S);
    let (negative, body) = match text.as_bytes().first() {
        Some(b'-') => (true, text.get(1..).unwrap_or("")),
        Some(b'+') => (false, text.get(1..).unwrap_or("")),
        _ => (false, text),
    };
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => (
            body.get(..i).unwrap_or(""),
            body.get(i + 1..)
                .and_then(|e| e.parse::<i32>().ok())
                .ok_or(not_a_number)?,
        ),
        None => (body, 0),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let all_digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if (int.is_empty() && frac.is_empty()) || !all_digits(int) || !all_digits(frac) {
        return Err(not_a_number);
    }
    if !(-64..=64).contains(&exponent) {
        return Err(LogErrorKind::TimeOutOfRange);
    }
    // The digits int ++ frac with the point after `point` of them; the
    // microseconds are the digits before position point + 6, the next one
    // rounds.
    let point = i64::try_from(int.len()).unwrap_or(i64::MAX) + i64::from(exponent);
    let end = point + 6;
    let digit_at = |k: i64| -> u8 {
        usize::try_from(k)
            .ok()
            .and_then(|k| {
                if k < int.len() {
                    int.as_bytes().get(k)
                } else {
                    frac.as_bytes().get(k - int.len())
                }
            })
            .map_or(0, |b| b - b'0')
    };
    let mut us: i64 = 0;
    let mut k: i64 = 0;
    while k < end {
        // Leading zeros cannot overflow; beyond the written digits pad with 0.
        us = us
            .checked_mul(10)
            .and_then(|v| v.checked_add(i64::from(digit_at(k))))
            .ok_or(LogErrorKind::TimeOutOfRange)?;
        k += 1;
    }
    if digit_at(end) >= 5 {
        us = us.checked_add(1).ok_or(LogErrorKind::TimeOutOfRange)?;
    }
    Ok(if negative { -us } else { us })
}

/// Whether a row that has too many fields reads as numbers written with
/// decimal commas: no decimal point anywhere, and a field that starts with a
/// zero followed by a digit (the fraction of `0,05`) or a quoted field holding
/// a comma (`"45,3"`). A row of plain integers (`0,1,2,3,4,5`) is not one.
fn looks_decimal_comma(row: &str) -> bool {
    if row.contains('.') {
        return false;
    }
    let fraction = row.split(',').any(|f| {
        let b = f.trim().trim_matches('"').as_bytes();
        b.len() >= 2 && b.first() == Some(&b'0') && b.iter().all(u8::is_ascii_digit)
    });
    let quoted_comma = row
        .split('"')
        .skip(1)
        .step_by(2)
        .any(|inside| inside.contains(','));
    fraction || quoted_comma
}

/// A field without its surrounding spaces and, if it is wrapped in double
/// quotes, without them (and the spaces inside).
fn unquote(field: &str) -> &str {
    let field = field.trim();
    field
        .strip_prefix('"')
        .and_then(|f| f.strip_suffix('"'))
        .map_or(field, str::trim)
}

fn parse_header(text: &str) -> Result<heapless::Vec<Column, MAX_COLUMNS>, LogErrorKind> {
    if text.starts_with('{') || text.starts_with('[') {
        return Err(LogErrorKind::Json);
    }
    // A spreadsheet saved in a locale with decimal commas separates with `;`
    // (or tabs): say so rather than that `t_s` is missing.
    if !text.contains(',') {
        if let Some(sep) = [';', '\t'].into_iter().find(|c| text.contains(*c)) {
            return Err(LogErrorKind::WrongSeparator(sep));
        }
    }
    let mut columns = heapless::Vec::new();
    for name in text.split(',') {
        let name = unquote(name);
        if name.parse::<f64>().is_ok() {
            return Err(LogErrorKind::NoHeader);
        }
        let column = Column::from_name(name);
        if column != Column::Ignored && columns.contains(&column) {
            return Err(LogErrorKind::DuplicateColumn(column.name()));
        }
        columns
            .push(column)
            .map_err(|_| LogErrorKind::TooManyColumns)?;
    }
    for required in [Column::Time, Column::P1, Column::P2, Column::Angle] {
        if !columns.contains(&required) {
            let name = required.name();
            // `T_S` from a tool that writes headers in capitals: say so
            // rather than only that `t_s` is missing.
            let in_other_case = text.split(',').any(|n| unquote(n).eq_ignore_ascii_case(name));
            // `t_ms` or `boom_angle_rad`: say which units a log has.
            let stems: &[&str] = match required {
                Column::Time => &["t_", "time"],
                Column::P1 => &["p1"],
                Column::P2 => &["p2"],
                _ => &["boom_angle", "angle"],
            };
            let in_other_unit = text.split(',').any(|n| {
                let n = unquote(n).as_bytes();
                stems.iter().any(|s| n.get(..s.len()).is_some_and(|head| head.eq_ignore_ascii_case(s.as_bytes())))
            });
            return Err(if in_other_case {
                LogErrorKind::ColumnCase(name)
            } else if in_other_unit {
                LogErrorKind::ColumnUnit(name)
            } else {
                LogErrorKind::MissingColumn(name)
            });
        }
    }
    Ok(columns)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_all(text: &str) -> Result<Vec<Record<f64>>, LogError> {
        let mut p = LogParser::new();
        let mut out = Vec::new();
        for line in text.lines() {
            if let Some(r) = p.feed_line(line)? {
                out.push(r);
            }
        }
        p.finish()?;
        Ok(out)
    }

    #[test]
    fn a_semicolon_or_tab_separated_log_is_named_as_such() {
        for (text, sep) in [("t_s;p1_bar;p2_bar;boom_angle_deg\n0;1,5;2;45\n", ';'), ("t_s\tp1_bar\tp2_bar\tboom_angle_deg\n", '\t')] {
            let e = parse_all(text).unwrap_err();
            assert_eq!(e, LogError { line: 1, kind: LogErrorKind::WrongSeparator(sep) });
            let msg = e.to_string();
            assert!(msg.contains("not by commas") && msg.contains("decimal points"), "{msg}");
        }
        // A comma-separated header with a `;` in a column name is no such case.
        assert_eq!(
            parse_all("t_s,p1_bar,p2_bar,boom_angle_deg,note;x\n0,1,2,45,3\n").map(|r| r.len()),
            Ok(1)
        );
    }

    #[test]
    fn quoted_names_and_fields_are_read_without_their_quotes() {
        let r = parse_all("\"t_s\",\"p1_bar\", \" p2_bar \",boom_angle_deg,\"true_load_kg\"\n\"0.01\",\"60\",5, \"45.5\" ,\"\"\n").unwrap();
        assert_eq!(r.len(), 1);
        assert_eq!(
            r[0].frame,
            Frame {
                t: Ticks(10_000),
                p1_bar: 60.0,
                p2_bar: 5.0,
                boom_angle_deg: 45.5
            }
        );
        assert_eq!(r[0].true_load_kg, None);
        // Quotes do not make text a number, nor a decimal comma a point (and
        // the error says which it is).
        let e = parse_all("t_s,p1_bar,p2_bar,boom_angle_deg\n0,\"6,0\",5,45\n").unwrap_err();
        assert_eq!(e.kind, LogErrorKind::DecimalCommas);
        let e = parse_all("t_s,p1_bar,p2_bar,boom_angle_deg\n0,\"six\",5,45\n").unwrap_err();
        assert_eq!(e.kind, LogErrorKind::NotANumber(P1_BAR));
        let e = parse_all("\"T_S\",p1_bar,p2_bar,boom_angle_deg\n0,1,2,3\n").unwrap_err();
        assert_eq!(e.kind, LogErrorKind::ColumnCase(T_S));
    }

    /// A column in another unit or spelling is named as such, with the
    /// units a log has; an unrelated column is only missing.
    #[test]
    fn a_column_in_another_unit_is_named() {
        for (header, column) in [
            ("t_ms,p1_bar,p2_bar,boom_angle_deg", T_S),
            ("Time,p1_bar,p2_bar,boom_angle_deg", T_S),
            ("t_s,p1_psi,p2_bar,boom_angle_deg", P1_BAR),
            ("t_s,p1_bar,P2_MPa,boom_angle_deg", P2_BAR),
            ("t_s,p1_bar,p2_bar,boom_angle_rad", BOOM_ANGLE_DEG),
            ("t_s,p1_bar,p2_bar,angle", BOOM_ANGLE_DEG),
        ] {
            let e = parse_all(&format!("{header}\n0,1,2,3\n")).unwrap_err();
            assert_eq!((e.line, e.kind), (1, LogErrorKind::ColumnUnit(column)), "{header}");
            let msg = e.to_string();
            assert!(msg.contains("in seconds") && msg.contains("in degrees"), "{msg}");
        }
        let e = parse_all("seconds,p1_bar,p2_bar,boom_angle_deg\n0,1,2,3\n").unwrap_err();
        assert_eq!(e.kind, LogErrorKind::MissingColumn(T_S));
    }

    #[test]
    fn any_column_order_comments_and_optional_load() {
        let r = parse_all(
            "\u{feff}# a comment\r\nboom_angle_deg, t_s ,note,p2_bar,p1_bar\n\n45.0,0.0,x,5,60\n# c\n45.1,0.01,y,5.1,61\n",
        )
        .unwrap();
        assert_eq!(r.len(), 2);
        assert_eq!(r[1].line, 6);
        assert_eq!(
            r[1].frame,
            Frame {
                t: Ticks(10_000),
                p1_bar: 61.0,
                p2_bar: 5.1,
                boom_angle_deg: 45.1
            }
        );
        assert_eq!(r[1].true_load_kg, None);
    }

    #[test]
    fn errors_name_line_and_field() {
        let h = "t_s,p1_bar,p2_bar,boom_angle_deg,true_load_kg\n";
        let e = parse_all(&format!("# c\n{h}0,1,2,3,4\n0.1,abc,2,3,4\n")).unwrap_err();
        assert_eq!(
            e,
            LogError {
                line: 4,
                kind: LogErrorKind::NotANumber(P1_BAR)
            }
        );
        assert_eq!(e.to_string(), "line 4: field `p1_bar` is not a number");
        let e = parse_all(&format!("{h}0,1,2,3,4\n0.1,1,2\n")).unwrap_err();
        assert_eq!(
            e,
            LogError {
                line: 3,
                kind: LogErrorKind::MissingField(BOOM_ANGLE_DEG)
            }
        );
        let e = parse_all(&format!("{h}1,1,2,3,4\n0.5,1,2,3,4\n")).unwrap_err();
        assert_eq!(
            e,
            LogError {
                line: 3,
                kind: LogErrorKind::TimeBackwards
            }
        );
        let e = parse_all("t_s,p1_bar,boom_angle_deg\n0,1,2\n").unwrap_err();
        assert_eq!(
            e,
            LogError {
                line: 1,
                kind: LogErrorKind::MissingColumn(P2_BAR)
            }
        );
        let e = parse_all("# c\nT_S,P1_bar,p2_bar,boom_angle_deg\n0,1,2,3\n").unwrap_err();
        assert_eq!(
            e,
            LogError {
                line: 2,
                kind: LogErrorKind::ColumnCase(T_S)
            }
        );
        assert_eq!(
            e.to_string(),
            "line 2: header has no column `t_s`, only one that differs from it in letter case: column names are case-sensitive"
        );
        assert_eq!(
            parse_all("").unwrap_err(),
            LogError {
                line: 1,
                kind: LogErrorKind::Empty
            }
        );
        assert_eq!(parse_all("# only\n").unwrap_err().kind, LogErrorKind::Empty);
        assert_eq!(
            parse_all(h).unwrap_err(),
            LogError {
                line: 2,
                kind: LogErrorKind::NoSamples
            }
        );
        assert_eq!(
            parse_all("0,1,2,3\n").unwrap_err().kind,
            LogErrorKind::NoHeader
        );
        let e = parse_all(&format!("{h}0,1,2,3,4,5\n")).unwrap_err();
        assert_eq!(e.kind, LogErrorKind::TooManyFields);
        let e = parse_all(&format!("{h}0,1,2,3,4,\n")).unwrap_err();
        assert_eq!((e.line, e.kind), (2, LogErrorKind::TrailingComma));
        assert!(e.to_string().contains("ends with a comma"), "{e}");
        let e = parse_all(&format!("{h}0,1,2,3,4, ,\n")).unwrap_err();
        assert_eq!(e.kind, LogErrorKind::TrailingComma);
        // A calibration file given as the log.
        let e = parse_all("{\"version\": 3,\n\"friction_up_n\": 1}\n").unwrap_err();
        assert_eq!((e.line, e.kind), (1, LogErrorKind::Json));
        // Two logs joined: the second one's comment is skipped, its header
        // is named as what it is.
        let e = parse_all(&format!("{h}0,1,2,3,4\n# next log\n{h}0,1,2,3,4\n")).unwrap_err();
        assert_eq!((e.line, e.kind), (4, LogErrorKind::SecondHeader));
        assert!(e.to_string().contains("two logs joined"), "{e}");
        let e = parse_all(&format!("{h}0,1,2,3,4,,5\n")).unwrap_err();
        assert_eq!(e.kind, LogErrorKind::TooManyFields);
        let e = parse_all(&format!("{h}0,,2,3,4\n")).unwrap_err();
        assert_eq!(e.kind, LogErrorKind::EmptyField(P1_BAR));
    }

    #[test]
    fn a_row_with_decimal_commas_is_named_as_such() {
        let h = "t_s,p1_bar,p2_bar,boom_angle_deg\n";
        for row in ["0,05,60,5,4,2,45,3", "\"0,01\",\"60,5\",\"4,2\",\"45,3\"", "1,5,60,5,4,45,3,\"1,0\""] {
            let e = parse_all(&format!("{h}{row}\n")).unwrap_err();
            assert_eq!((e.line, e.kind), (2, LogErrorKind::DecimalCommas), "{row}");
            assert!(e.to_string().contains("decimal commas"), "{e}");
        }
        // Integers, or a row with a decimal point, have too many fields only.
        for row in ["0,1,2,3,4,5", "0.05,60,5,4,45", "0,05.5,60,4,45"] {
            assert_eq!(parse_all(&format!("{h}{row}\n")).unwrap_err().kind, LogErrorKind::TooManyFields, "{row}");
        }
    }

    #[test]
    fn time_is_read_exactly_to_the_microsecond() {
        let ok = |s: &str| parse_time_us(s).unwrap();
        assert_eq!(ok("0"), 0);
        assert_eq!(ok("0.01"), 10_000);
        assert_eq!(ok("144000.020"), 144_000_020_000);
        assert_eq!(ok("40003200.01"), 40_003_200_010_000);
        assert_eq!(ok("-1.5"), -1_500_000);
        assert_eq!(ok("+.5"), 500_000);
        assert_eq!(ok("7."), 7_000_000);
        assert_eq!(ok("1.5e-2"), 15_000);
        assert_eq!(ok("2E3"), 2_000_000_000);
        assert_eq!(ok("0.0000005"), 1); // half rounds away from zero
        assert_eq!(ok("0.00000049999"), 0);
        assert_eq!(ok("-0.0000005"), -1);
        assert_eq!(ok("9223372036854.775807"), i64::MAX);
        assert_eq!(ok("1e-30"), 0);
        for bad in ["", "-", ".", "1..2", "1e", "0x10", "1,5", "abc", "1 2", "e5"] {
            assert_eq!(
                parse_time_us(bad),
                Err(LogErrorKind::NotANumber(T_S)),
                "{bad:?}"
            );
        }
        assert_eq!(parse_time_us("inf"), Err(LogErrorKind::TimeNotFinite));
        assert_eq!(
            parse_time_us("9223372036854.775808"),
            Err(LogErrorKind::TimeOutOfRange)
        );
        assert_eq!(parse_time_us("1e65"), Err(LogErrorKind::TimeOutOfRange));
    }

    #[test]
    fn ticks_are_the_exact_differences_and_wrap() {
        let h = "t_s,p1_bar,p2_bar,boom_angle_deg\n";
        // 4294.967296 s = 2^32 µs: the clock wraps between the rows.
        let r = parse_all(&format!("{h}4294.957296,1,2,3\n4294.977296,1,2,3\n")).unwrap();
        assert_eq!(r[0].frame.t, Ticks(u32::MAX - 9_999));
        assert_eq!(r[1].frame.t.since(r[0].frame.t), 20_000);
        assert_eq!(r[1].t_us, 4_294_977_296);
        // A duplicate time is data (the limiter faults on it), not an error.
        let r = parse_all(&format!("{h}1,1,2,3\n1,1,2,3\n")).unwrap();
        assert_eq!(r[0].frame.t, r[1].frame.t);
        // A gap of exactly 2^32 µs must not look like no gap: clamped.
        let r = parse_all(&format!("{h}0,1,2,3\n4294.967296,1,2,3\n")).unwrap();
        assert_eq!(r[1].frame.t.since(r[0].frame.t), BACKWARDS_FROM_US - 1);
    }

    #[test]
    fn nan_sensor_value_is_data_but_nan_time_is_not() {
        let h = "t_s,p1_bar,p2_bar,boom_angle_deg\n";
        let r = parse_all(&format!("{h}0,NaN,2,3\n")).unwrap();
        assert!(r[0].frame.p1_bar.is_nan());
        assert_eq!(
            parse_all(&format!("{h}NaN,1,2,3\n")).unwrap_err().kind,
            LogErrorKind::TimeNotFinite
        );
    }
}
