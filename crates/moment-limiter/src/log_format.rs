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
//!   decimal numbers (surrounding spaces allowed). `t_s` must be finite and
//!   never decrease. A sensor value written as `NaN` or `inf` is read as such
//!   and becomes a sensor FAULT in the limiter, like any out-of-range value;
//!   text that is not a number is a format error. `true_load_kg` may be empty.
//!
//! Errors name the 1-based line (comments and header counted) and the field.
//! The firmware reads the log line by line through semihosting and calls
//! [`LogParser::feed_line`] on each; the host does the same.

use core::fmt;

use crane_model::Real;

use crate::limiter::Frame;

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
    /// This field is empty.
    EmptyField(&'static str),
    /// This field is not a number.
    NotANumber(&'static str),
    /// The time is not finite.
    TimeNotFinite,
    /// The time is earlier than the previous row's.
    TimeBackwards,
    /// The header is followed by no data row.
    NoSamples,
    /// The line is not valid UTF-8 (reported by the reader, which sees bytes).
    NotUtf8,
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
            LogErrorKind::DuplicateColumn(c) => write!(f, "header names column `{c}` twice"),
            LogErrorKind::NoHeader => write!(
                f,
                "header required (`{T_S},{P1_BAR},{P2_BAR},{BOOM_ANGLE_DEG}`), found data"
            ),
            LogErrorKind::TooManyColumns => write!(f, "header has more than {MAX_COLUMNS} columns"),
            LogErrorKind::MissingField(c) => write!(f, "field `{c}` missing (row too short)"),
            LogErrorKind::TooManyFields => f.write_str("more fields than the header has columns"),
            LogErrorKind::EmptyField(c) => write!(f, "field `{c}` is empty"),
            LogErrorKind::NotANumber(c) => write!(f, "field `{c}` is not a number"),
            LogErrorKind::TimeNotFinite => write!(f, "field `{T_S}` is not a finite time"),
            LogErrorKind::TimeBackwards => write!(f, "field `{T_S}` goes backwards in time"),
            LogErrorKind::NoSamples => f.write_str("no data rows after the header"),
            LogErrorKind::NotUtf8 => f.write_str("not valid UTF-8"),
            LogErrorKind::Unreadable => f.write_str("could not be read"),
        }
    }
}

/// One data row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Record<T> {
    /// 1-based line number of the row.
    pub line: u32,
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
    last_t_s: Option<T>,
    samples: u32,
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
            last_t_s: None,
            samples: 0,
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
        for &column in columns.iter() {
            let field = fields
                .next()
                .ok_or(err(LogErrorKind::MissingField(column.name())))?
                .trim();
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
                let v: f64 = field
                    .parse()
                    .map_err(|_| err(LogErrorKind::NotANumber(column.name())))?;
                *slot = Some(T::lit(v));
            }
        }
        if fields.next().is_some() {
            return Err(err(LogErrorKind::TooManyFields));
        }
        let missing = |name| err(LogErrorKind::MissingField(name));
        let [t, p1, p2, angle, true_load] = values;
        let t_s = t.ok_or(missing(T_S))?;
        if !t_s.is_finite() {
            return Err(err(LogErrorKind::TimeNotFinite));
        }
        if self.last_t_s.is_some_and(|last| t_s < last) {
            return Err(err(LogErrorKind::TimeBackwards));
        }
        self.last_t_s = Some(t_s);
        self.samples = self.samples.saturating_add(1);
        Ok(Some(Record {
            line: line_no,
            frame: Frame {
                t_s,
                p1_bar: p1.ok_or(missing(P1_BAR))?,
                p2_bar: p2.ok_or(missing(P2_BAR))?,
                boom_angle_deg: angle.ok_or(missing(BOOM_ANGLE_DEG))?,
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

fn parse_header(text: &str) -> Result<heapless::Vec<Column, MAX_COLUMNS>, LogErrorKind> {
    let mut columns = heapless::Vec::new();
    for name in text.split(',') {
        let name = name.trim();
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
            return Err(LogErrorKind::MissingColumn(required.name()));
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
                t_s: 0.01,
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
        let e = parse_all(&format!("{h}0,,2,3,4\n")).unwrap_err();
        assert_eq!(e.kind, LogErrorKind::EmptyField(P1_BAR));
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
