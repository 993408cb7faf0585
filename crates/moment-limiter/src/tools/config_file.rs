//! The calibration file (`CAL.json`): its schema, its one reader and its
//! writer, `no_std` and without a heap, shared by `crane-sim` and the
//! firmware (SPEC §4.9) so the two cannot disagree about a file.
//!
//! ## Schema, version 5 (versions 1–4 still read)
//!
//! One JSON object; **every key is required, no other key is allowed**, each
//! value is a JSON number within the bounds below (finite; the bounds are
//! physical: a value beyond one is a broken sensor or a bad calibration run,
//! not something to correct for):
//!
//! | key | unit | bounds | why |
//! |---|---|---|---|
//! | `version` | — | 5 (or 4, 3, 2, 1) | the schema version of the file |
//! | `friction_up_n` | N | 0 … 40 000 | constant part a of the cylinder's seal friction luffing up: ≤ 5 % of the 831 kN the cylinder exerts at 200 bar |
//! | `friction_down_n` | N | 0 … 40 000 | the same, luffing down |
//! | `force_offset_n` | N | −25 000 … 25 000 | zero-load force offset: ≤ 3 % of 831 kN (both transducers' ±2 % zero tolerance, 16.6 kN, plus the model's error at W = 0) |
//! | `p1_offset_bar` | bar | −4 … 4 | zero of the piston-side transducer: ±2 % of its 200 bar span (beyond it the range check already calls the sensor faulty) |
//! | `p2_offset_bar` | bar | −4 … 4 | the same, rod side |
//! | `angle_offset_deg` | ° | −5 … 5 | zero of the pendulum: the 5° margin of its −5°…95° range |
//! | `friction_up_per_force` | — | 0 … 0.2 | pressure-proportional part b of the seal friction luffing up (friction = a + b·\|F\|, [`crate::load_estimate`]): a seal taking a fifth of the force is worn out |
//! | `friction_down_per_force` | — | 0 … 0.2 | the same, luffing down |
//! | `angle_sensor_lag_s` | s | 0 … 0.5 | the angle sensor's lag behind the boom (first-order equivalent, [`crate::calibration`]; a pendulum's 2ζ/ω_n): half a second misreads a 10 s move by 4°, a broken or badly mounted sensor |
//! | `friction_up_per_rate` | N·s/rad | 0 … 400 000 | the part c of the friction luffing up that grows with the boom's rate ω (friction = a + b·\|F\| + c·\|ω\|, [`crate::load_estimate`]): 40 kN, the constant part's bound, at 0.1 rad/s (a 10 s luff over 57°) |
//! | `friction_down_per_rate` | N·s/rad | 0 … 400 000 | the same, luffing down |
//! | `seal_release_up_s` | s | 0.01 … 60 | the time constant with which the seals release a raise's friction once the boom is still ([`crate::seal_release`]), counted from when the limiter sees the stop: from seals that let go at once to seals that stay stuck for a minute (after a lowering the limiter keeps its configured one) |
//!
//! **Version 1** files (written before the seal law) have the first six
//! keys only and read as b = 0 (constant friction per direction), exactly
//! as they were applied before; a version-1 file that holds a `*_per_force`
//! key is refused (that key is not in version 1). **Version 2** files
//! (written before the lag was learned) have the first eight keys and read
//! with no lag ([`Calibration::angle_sensor_lag_s`] `None`): the limiter
//! aligns with its configured lag, exactly as it did when they were
//! written. **Version 3** files (written before the friction's part that
//! grows with the rate was learned) have the first nine keys and read as
//! c = 0, the friction they were applied with. **Version 4** files (written
//! before the seals' release was learned) have the first eleven keys and
//! read with no release time ([`Calibration::seal_release_up_s`] `None`): the
//! limiter takes friction off with its configured one, as it did when they
//! were written. A key a file's version does not have is refused. The
//! writer writes version 5; a calibration without a lag is written with the
//! standard configuration's lag ([`crate::cycle::DEFAULT_ANGLE_SENSOR_LAG_S`],
//! what the limiter used for it), one without a release time with the
//! standard configuration's ([`crate::cycle::DEFAULT_SEAL_RELEASE_S`]).
//!
//! A file is refused with an error that names the key and, for a value out
//! of bounds, the bound and its reason: an empty object, an array, a value of
//! the wrong type, a missing, unknown or repeated key, a value out of bounds,
//! an unsupported version. A file without `version` that holds calibration
//! keys is one written before the schema (by an older `crane-sim calibrate`,
//! with informational keys such as `samples_up`): its error says to run
//! `crane-sim calibrate` again or to add `"version": 1` and remove the other
//! keys after checking the values.
//!
//! JSON accepted: RFC 8259 objects, numbers, strings, `true`/`false`/`null`,
//! arrays and objects nested at most [`MAX_DEPTH`] deep (only to name a
//! wrong type), a UTF-8 byte-order mark. The writer
//! ([`write_calibration_json`]) writes every key, one per line, with the
//! shortest decimal that reads back to the same `f64`.

use core::fmt::{self, Write};

use crane_model::Real;

use crate::load_estimate::Calibration;

/// The schema version the writer writes (the reader also reads
/// [`CALIBRATION_VERSION_1`], [`CALIBRATION_VERSION_2`],
/// [`CALIBRATION_VERSION_3`] and [`CALIBRATION_VERSION_4`]).
pub const CALIBRATION_VERSION: u32 = 5;

/// The fourth schema version: the friction per unit rate, no seals'
/// release time (the first [`V4_KEYS`] keys of [`CALIBRATION_KEYS`]).
pub const CALIBRATION_VERSION_4: u32 = 4;

/// Number of keys of schema version 4 (the first ones of [`CALIBRATION_KEYS`]).
pub const V4_KEYS: usize = 11;

/// The third schema version: the seal law and the lag, no friction per
/// unit rate (the first [`V3_KEYS`] keys of [`CALIBRATION_KEYS`]).
pub const CALIBRATION_VERSION_3: u32 = 3;

/// Number of keys of schema version 3 (the first ones of [`CALIBRATION_KEYS`]).
pub const V3_KEYS: usize = 9;

/// The second schema version: the seal law, no lag (the first [`V2_KEYS`]
/// keys of [`CALIBRATION_KEYS`]).
pub const CALIBRATION_VERSION_2: u32 = 2;

/// Number of keys of schema version 2 (the first ones of [`CALIBRATION_KEYS`]).
pub const V2_KEYS: usize = 8;

/// Number of keys of schema version 5.
pub const KEY_COUNT: usize = 12;

/// Every schema version the reader reads, oldest first.
pub const CALIBRATION_VERSIONS: [u32; 5] =
    [CALIBRATION_VERSION_1, CALIBRATION_VERSION_2, CALIBRATION_VERSION_3, CALIBRATION_VERSION_4, CALIBRATION_VERSION];

/// The first schema version: constant friction per direction (the first
/// [`V1_KEYS`] keys of [`CALIBRATION_KEYS`]).
pub const CALIBRATION_VERSION_1: u32 = 1;

/// Number of keys of schema version 1 (the first ones of [`CALIBRATION_KEYS`]).
pub const V1_KEYS: usize = 6;

/// Deepest nesting of arrays and objects skipped inside a value.
pub const MAX_DEPTH: usize = 8;

/// The key of the schema version.
pub const VERSION_KEY: &str = "version";

/// One value of the schema: its key, unit and physical bounds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KeySpec {
    /// The JSON key.
    pub key: &'static str,
    /// Unit of the value.
    pub unit: &'static str,
    /// Smallest allowed value.
    pub min: f64,
    /// Largest allowed value.
    pub max: f64,
    /// Where the bounds come from (printed with a refusal).
    pub why: &'static str,
}

/// The values of schema version 5 (the first [`V1_KEYS`] are version 1's,
/// the first [`V2_KEYS`] version 2's, the first [`V3_KEYS`] version 3's,
/// the first [`V4_KEYS`] version 4's, in their order; see the module doc
/// for the reasons). The one bound table: the JSON reader, the writer and
/// the firmware's blob all check against it.
pub const CALIBRATION_KEYS: [KeySpec; KEY_COUNT] = [
    KeySpec {
        key: "friction_up_n",
        unit: "N",
        min: 0.0,
        max: 40_000.0,
        why: "5 % of the cylinder's 831 kN at 200 bar",
    },
    KeySpec {
        key: "friction_down_n",
        unit: "N",
        min: 0.0,
        max: 40_000.0,
        why: "5 % of the cylinder's 831 kN at 200 bar",
    },
    KeySpec {
        key: "force_offset_n",
        unit: "N",
        min: -25_000.0,
        max: 25_000.0,
        why: "3 % of the cylinder's 831 kN: transducer zero tolerance plus model error",
    },
    KeySpec {
        key: "p1_offset_bar",
        unit: "bar",
        min: -4.0,
        max: 4.0,
        why: "2 % of the 200 bar transducer span",
    },
    KeySpec {
        key: "p2_offset_bar",
        unit: "bar",
        min: -4.0,
        max: 4.0,
        why: "2 % of the 200 bar transducer span",
    },
    KeySpec {
        key: "angle_offset_deg",
        unit: "deg",
        min: -5.0,
        max: 5.0,
        why: "the pendulum's 5 degree range margin",
    },
    KeySpec {
        key: "friction_up_per_force",
        unit: "N/N",
        min: 0.0,
        max: crate::load_estimate::MAX_PER_FORCE,
        why: "a seal taking a fifth of the piston force is worn out",
    },
    KeySpec {
        key: "friction_down_per_force",
        unit: "N/N",
        min: 0.0,
        max: crate::load_estimate::MAX_PER_FORCE,
        why: "a seal taking a fifth of the piston force is worn out",
    },
    KeySpec {
        key: "angle_sensor_lag_s",
        unit: "s",
        min: 0.0,
        max: crate::load_estimate::MAX_ANGLE_SENSOR_LAG_S,
        why: "a sensor lagging half a second misreads a 10 s move by 4 degrees",
    },
    KeySpec {
        key: "friction_up_per_rate",
        unit: "N*s/rad",
        min: 0.0,
        max: crate::load_estimate::MAX_PER_RATE_N_S,
        why: "40 kN, the constant part's bound, at 0.1 rad/s (a 10 s luff over 57 degrees)",
    },
    KeySpec {
        key: "friction_down_per_rate",
        unit: "N*s/rad",
        min: 0.0,
        max: crate::load_estimate::MAX_PER_RATE_N_S,
        why: "40 kN, the constant part's bound, at 0.1 rad/s (a 10 s luff over 57 degrees)",
    },
    KeySpec {
        key: "seal_release_up_s",
        unit: "s",
        min: crate::load_estimate::MIN_SEAL_RELEASE_S,
        max: crate::load_estimate::MAX_SEAL_RELEASE_S,
        why: "from seals that let go at once to seals stuck for a minute",
    },
];

/// Longest unknown key kept for the error message (longer ones are cut).
pub const KEY_ECHO_LEN: usize = 40;

/// Why a calibration file was refused.
#[derive(Debug, Clone, PartialEq)]
pub enum CalibrationFileError {
    /// Not JSON (or not the JSON this reader takes) at this byte offset.
    Syntax {
        /// 0-based byte offset.
        at: usize,
        /// What was expected.
        expected: &'static str,
    },
    /// The file holds no object: an array, a number, a string…
    NotAnObject,
    /// A required key is absent.
    MissingKey(&'static str),
    /// A key the schema does not have (cut to [`KEY_ECHO_LEN`] bytes).
    UnknownKey(heapless::String<KEY_ECHO_LEN>),
    /// A key of a later version in a file that says an earlier one.
    NotInVersion {
        /// The key.
        key: &'static str,
        /// The version the file says.
        version: u32,
    },
    /// A key is given twice.
    DuplicateKey(&'static str),
    /// The value of this key is not a JSON number.
    NotANumber(&'static str),
    /// The value is outside its bounds.
    OutOfBounds {
        /// The key and its bounds.
        spec: KeySpec,
        /// The value found.
        value: f64,
    },
    /// `version` is not one this reader knows.
    UnsupportedVersion(f64),
    /// No `version`, but calibration keys: a file from before the schema.
    PreSchemaFile,
    /// Not JSON but a sensor log: it starts with a `#` comment or the log's
    /// `t_s,` header (a log given where the calibration goes).
    SensorLog,
}

impl fmt::Display for CalibrationFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use CalibrationFileError as E;
        match self {
            E::Syntax { at, expected } => write!(f, "not valid JSON at byte {at}: {expected}"),
            E::NotAnObject => f.write_str("expected one JSON object `{...}` of calibration keys"),
            E::SensorLog => f.write_str(
                "this is a sensor log (CSV), not a calibration file: that is the JSON `crane-sim calibrate` writes (docs/calibration.md)",
            ),
            E::MissingKey(k) => write!(f, "key `{k}` is missing (every key is required)"),
            E::UnknownKey(k) => write!(f, "key `{k}` is not in the calibration schema"),
            E::NotInVersion { key, version } => write!(
                f,
                "key `{key}` is not in calibration schema version {version}: set \"{VERSION_KEY}\": \
                 {CALIBRATION_VERSION} (and give every key of version {CALIBRATION_VERSION})"
            ),
            E::DuplicateKey(k) => write!(f, "key `{k}` is given twice"),
            E::NotANumber(k) => write!(f, "key `{k}` must be a number"),
            E::OutOfBounds { spec, value } => write!(
                f,
                "key `{}` = {} is outside {} ... {} {} ({})",
                spec.key,
                Shown(*value),
                spec.min,
                spec.max,
                spec.unit,
                spec.why
            ),
            E::UnsupportedVersion(v) => write!(
                f,
                "key `{VERSION_KEY}` = {}: this reader knows versions \
                 {CALIBRATION_VERSION_1}, {CALIBRATION_VERSION_2}, {CALIBRATION_VERSION_3}, {CALIBRATION_VERSION_4} and {CALIBRATION_VERSION}",
                Shown(*v)
            ),
            E::PreSchemaFile => write!(
                f,
                "key `{VERSION_KEY}` is missing: the file predates calibration schema \
                 {CALIBRATION_VERSION_1}; run `crane-sim calibrate` again, or check the values, \
                 add \"{VERSION_KEY}\": {CALIBRATION_VERSION_1} and remove the keys the schema \
                 does not have"
            ),
        }
    }
}

/// A value as an error message shows it: as written where that is short,
/// in exponent form far from 1 (`1e308`, not its 309 digits).
struct Shown(f64);

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = self.0.abs();
        if a == 0.0 || !a.is_finite() || (1e-4..1e9).contains(&a) {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:e}", self.0)
        }
    }
}

/// Reads a calibration file (the bytes of `CAL.json`) against the schema
/// (version 5; version 4 read without a seals' release time, version 3
/// also as c = 0, version 2 also without a lag, version 1 also as b = 0).
pub fn parse_calibration<T: Real>(text: &[u8]) -> Result<Calibration<T>, CalibrationFileError> {
    read_object(text).map(|(v, keys)| calibration_from_values(&v, keys)).map_err(|e| match e {
        CalibrationFileError::Syntax { at: 0, .. } if looks_like_log(text) => CalibrationFileError::SensorLog,
        e => e,
    })
}

/// Whether `text` starts (after a byte-order mark and blanks) like a sensor
/// log: a `#` comment or the `t_s,` header.
fn looks_like_log(text: &[u8]) -> bool {
    let text = text.strip_prefix("\u{feff}".as_bytes()).unwrap_or(text);
    let start = text.iter().position(|b| !b.is_ascii_whitespace()).unwrap_or(text.len());
    let rest = text.get(start..).unwrap_or(&[]);
    rest.starts_with(b"#") || rest.starts_with(b"t_s,")
}

/// The number of keys of a schema version, if the reader knows it.
pub fn keys_of_version(version: u32) -> Option<usize> {
    match version {
        CALIBRATION_VERSION_1 => Some(V1_KEYS),
        CALIBRATION_VERSION_2 => Some(V2_KEYS),
        CALIBRATION_VERSION_3 => Some(V3_KEYS),
        CALIBRATION_VERSION_4 => Some(V4_KEYS),
        CALIBRATION_VERSION => Some(KEY_COUNT),
        _ => None,
    }
}

/// The calibration of the values of [`CALIBRATION_KEYS`], in its order
/// (checked by the caller), converted to `T`; only the first `keys` are
/// the file's (its version's), the others take what that version meant:
/// b = 0 (version 1), no lag (versions 1 and 2), c = 0 (versions 1–3) and
/// no seals' release time (versions 1–4).
pub fn calibration_from_values<T: Real>(values: &[f64; KEY_COUNT], keys: usize) -> Calibration<T> {
    // One conversion of the whole array: on the board each T::lit is a
    // soft-float f64 -> f32 call, and eleven inlined ones took 104 B of flash.
    let [fu, fd, fo, p1, p2, a, bu, bd, lag, cu, cd, release] = values.map(T::lit);
    let zero = T::lit(0.0);
    let (bu, bd) = if keys > V1_KEYS { (bu, bd) } else { (zero, zero) };
    let (cu, cd) = if keys > V3_KEYS { (cu, cd) } else { (zero, zero) };
    Calibration {
        friction_up_n: fu,
        friction_down_n: fd,
        friction_up_per_force: bu,
        friction_down_per_force: bd,
        friction_up_per_rate: cu,
        friction_down_per_rate: cd,
        force_offset_n: fo,
        p1_offset_bar: p1,
        p2_offset_bar: p2,
        angle_offset_deg: a,
        angle_sensor_lag_s: (keys > V2_KEYS).then_some(lag),
        seal_release_up_s: (keys > V4_KEYS).then_some(release),
    }
}

/// Checks a calibration against the schema's bounds (what the reader
/// checks): `crane-sim calibrate` refuses to write a file the reader would
/// refuse.
pub fn check_calibration(cal: &Calibration<f64>) -> Result<(), CalibrationFileError> {
    for (spec, value) in CALIBRATION_KEYS.iter().zip(calibration_values(cal)) {
        check_bounds(spec, value)?;
    }
    Ok(())
}

/// Writes `cal` as a schema-version-5 file (one key per line, trailing
/// newline). Call [`check_calibration`] first: this writes any value.
pub fn write_calibration_json<W: Write>(w: &mut W, cal: &Calibration<f64>) -> fmt::Result {
    write!(w, "{{\n  \"{VERSION_KEY}\": {CALIBRATION_VERSION}")?;
    for (spec, value) in CALIBRATION_KEYS.iter().zip(calibration_values(cal)) {
        // `{:?}` prints the shortest decimal that reads back to the same f64,
        // and always with a '.' or an exponent.
        write!(w, ",\n  \"{}\": {:?}", spec.key, value)?;
    }
    w.write_str("\n}\n")
}

/// The values of `cal` in the order of [`CALIBRATION_KEYS`] (no lag: the
/// standard configuration's, [`crate::cycle::DEFAULT_ANGLE_SENSOR_LAG_S`];
/// no release time: [`crate::cycle::DEFAULT_SEAL_RELEASE_S`]).
pub fn calibration_values(cal: &Calibration<f64>) -> [f64; KEY_COUNT] {
    [
        cal.friction_up_n,
        cal.friction_down_n,
        cal.force_offset_n,
        cal.p1_offset_bar,
        cal.p2_offset_bar,
        cal.angle_offset_deg,
        cal.friction_up_per_force,
        cal.friction_down_per_force,
        cal.angle_sensor_lag_s
            .unwrap_or(crate::cycle::DEFAULT_ANGLE_SENSOR_LAG_S),
        cal.friction_up_per_rate,
        cal.friction_down_per_rate,
        cal.seal_release_up_s.unwrap_or(crate::cycle::DEFAULT_SEAL_RELEASE_S),
    ]
}

// Not inlined: the board image checks all twelve bounds in a loop the
// compiler unrolls, and each inlined copy built its own error (1.6 KB).
#[inline(never)]
fn check_bounds(spec: &KeySpec, value: f64) -> Result<(), CalibrationFileError> {
    if value.is_finite() && value >= spec.min && value <= spec.max {
        Ok(())
    } else {
        Err(CalibrationFileError::OutOfBounds { spec: *spec, value })
    }
}

/// What a member's value turned out to be.
enum Value {
    Number(f64),
    Other,
}

/// The first error of each kind found while scanning the whole object; the
/// most telling one is reported (version before unknown keys before values
/// before missing keys), so an old file gets the upgrade message.
#[derive(Default)]
struct Findings {
    version: Option<f64>,
    version_error: Option<CalibrationFileError>,
    unknown: Option<CalibrationFileError>,
    value_error: Option<CalibrationFileError>,
    values: [Option<f64>; KEY_COUNT],
}

/// The values and how many keys the file's version has.
fn read_object(text: &[u8]) -> Result<([f64; KEY_COUNT], usize), CalibrationFileError> {
    let mut c = Cursor {
        s: text.strip_prefix("\u{feff}".as_bytes()).unwrap_or(text),
        i: 0,
    };
    match c.peek() {
        Some(b'{') => c.i += 1,
        None => return Err(c.syntax("a JSON object, found an empty file")),
        Some(_) => {
            // Tell "not an object" from "not JSON at all".
            c.skip_value(0)?;
            return Err(CalibrationFileError::NotAnObject);
        }
    }
    let mut found = Findings::default();
    if c.peek() == Some(b'}') {
        c.i += 1;
    } else {
        loop {
            let key = c.string()?;
            c.expect(b':', "':' after the key")?;
            let value = c.value()?;
            found.member(key, value)?;
            match c.peek() {
                Some(b',') => c.i += 1,
                Some(b'}') => {
                    c.i += 1;
                    break;
                }
                _ => return Err(c.syntax("',' or '}' after a member")),
            }
        }
    }
    if c.peek().is_some() {
        return Err(c.syntax("the end of the file after the object"));
    }
    found.finish()
}

impl Findings {
    fn member(&mut self, key: &[u8], value: Value) -> Result<(), CalibrationFileError> {
        use CalibrationFileError as E;
        if key == VERSION_KEY.as_bytes() {
            if self.version.is_some() {
                return Err(E::DuplicateKey(VERSION_KEY));
            }
            let v = match value {
                Value::Number(v) => v,
                Value::Other => {
                    self.version_error.get_or_insert(E::NotANumber(VERSION_KEY));
                    f64::NAN
                }
            };
            self.version = Some(v);
            if CALIBRATION_VERSIONS.iter().any(|k| v == f64::from(*k)) {
                return Ok(());
            }
            if !v.is_nan() {
                self.version_error.get_or_insert(E::UnsupportedVersion(v));
            }
            return Ok(());
        }
        let Some((slot, spec)) = CALIBRATION_KEYS
            .iter()
            .position(|s| s.key.as_bytes() == key)
            .and_then(|k| Some((self.values.get_mut(k)?, CALIBRATION_KEYS.get(k)?)))
        else {
            if self.unknown.is_none() {
                let mut echo = heapless::String::new();
                for ch in core::str::from_utf8(key).unwrap_or("(not UTF-8)").chars() {
                    if echo.push(ch).is_err() {
                        break;
                    }
                }
                self.unknown = Some(E::UnknownKey(echo));
            }
            return Ok(());
        };
        if slot.is_some() {
            return Err(E::DuplicateKey(spec.key));
        }
        match value {
            Value::Number(v) => {
                *slot = Some(v);
                if let Err(e) = check_bounds(spec, v) {
                    self.value_error.get_or_insert(e);
                }
            }
            Value::Other => {
                *slot = Some(f64::NAN);
                self.value_error.get_or_insert(E::NotANumber(spec.key));
            }
        }
        Ok(())
    }

    fn finish(self) -> Result<([f64; KEY_COUNT], usize), CalibrationFileError> {
        use CalibrationFileError as E;
        let Some(version) = self.version else {
            return Err(if self.values.iter().any(Option::is_some) {
                E::PreSchemaFile
            } else {
                E::MissingKey(VERSION_KEY)
            });
        };
        if let Some(e) = self.version_error.or(self.unknown) {
            return Err(e);
        }
        // A known version (else `version_error` above).
        let (version, keys) = CALIBRATION_VERSIONS
            .iter()
            .find(|k| version == f64::from(**k))
            .and_then(|k| Some((*k, keys_of_version(*k)?)))
            .ok_or(E::UnsupportedVersion(version))?;
        // The keys a version did not have are not in its files.
        for (v, spec) in self.values.iter().zip(CALIBRATION_KEYS.iter()).skip(keys) {
            if v.is_some() {
                return Err(E::NotInVersion { key: spec.key, version });
            }
        }
        if let Some(e) = self.value_error {
            return Err(e);
        }
        let mut out = [0.0; KEY_COUNT];
        for (k, ((o, v), spec)) in out
            .iter_mut()
            .zip(self.values)
            .zip(CALIBRATION_KEYS.iter())
            .enumerate()
        {
            *o = match v {
                Some(v) => v,
                // Not in this version: its meaning is `calibration_from_values`'s.
                None if k >= keys => 0.0,
                None => return Err(E::MissingKey(spec.key)),
            };
        }
        Ok((out, keys))
    }
}

struct Cursor<'a> {
    s: &'a [u8],
    i: usize,
}

impl<'a> Cursor<'a> {
    fn syntax(&self, expected: &'static str) -> CalibrationFileError {
        CalibrationFileError::Syntax {
            at: self.i,
            expected,
        }
    }

    fn peek(&mut self) -> Option<u8> {
        while self.s.get(self.i).is_some_and(|b| b" \t\r\n".contains(b)) {
            self.i += 1;
        }
        self.s.get(self.i).copied()
    }

    fn expect(&mut self, c: u8, expected: &'static str) -> Result<(), CalibrationFileError> {
        if self.peek() == Some(c) {
            self.i += 1;
            Ok(())
        } else {
            Err(self.syntax(expected))
        }
    }

    /// A string's raw bytes between the quotes (escapes kept as written: a
    /// key with escapes is then simply not a schema key).
    fn string(&mut self) -> Result<&'a [u8], CalibrationFileError> {
        self.expect(b'"', "a string in double quotes")?;
        let start = self.i;
        loop {
            match self.s.get(self.i) {
                None => return Err(self.syntax("the closing '\"' of a string")),
                Some(b'\\') => self.i += 2,
                Some(b'"') => {
                    let raw = self.s.get(start..self.i).unwrap_or_default();
                    self.i += 1;
                    return Ok(raw);
                }
                Some(b) if *b < 0x20 => return Err(self.syntax("no control character in a string")),
                Some(_) => self.i += 1,
            }
        }
    }

    /// A JSON number (RFC 8259 grammar), or another value skipped.
    fn value(&mut self) -> Result<Value, CalibrationFileError> {
        match self.peek() {
            Some(b'-' | b'0'..=b'9') => self.number().map(Value::Number),
            _ => self.skip_value(0).map(|()| Value::Other),
        }
    }

    fn number(&mut self) -> Result<f64, CalibrationFileError> {
        let start = self.i;
        let digits = |c: &mut Self| {
            let from = c.i;
            while c.s.get(c.i).is_some_and(u8::is_ascii_digit) {
                c.i += 1;
            }
            c.i > from
        };
        if self.s.get(self.i) == Some(&b'-') {
            self.i += 1;
        }
        let leading_zero = self.s.get(self.i) == Some(&b'0');
        if !digits(self) {
            return Err(self.syntax("a digit"));
        }
        if leading_zero && self.i - start > 1 + usize::from(self.s.get(start) == Some(&b'-')) {
            return Err(self.syntax("no leading zero in a number"));
        }
        if self.s.get(self.i) == Some(&b'.') {
            self.i += 1;
            if !digits(self) {
                return Err(self.syntax("a digit after '.'"));
            }
        }
        if matches!(self.s.get(self.i), Some(b'e' | b'E')) {
            self.i += 1;
            if matches!(self.s.get(self.i), Some(b'+' | b'-')) {
                self.i += 1;
            }
            if !digits(self) {
                return Err(self.syntax("a digit in the exponent"));
            }
        }
        self.s
            .get(start..self.i)
            .and_then(|b| core::str::from_utf8(b).ok())
            .and_then(|t| t.parse::<f64>().ok())
            .ok_or(CalibrationFileError::Syntax {
                at: start,
                expected: "a number",
            })
    }

    /// Skips any JSON value, nested at most [`MAX_DEPTH`] deep.
    fn skip_value(&mut self, depth: usize) -> Result<(), CalibrationFileError> {
        if depth > MAX_DEPTH {
            return Err(self.syntax("less nesting"));
        }
        match self.peek() {
            Some(b'"') => self.string().map(|_| ()),
            Some(b'-' | b'0'..=b'9') => self.number().map(|_| ()),
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
                        self.expect(b':', "':' after the key")?;
                    }
                    self.skip_value(depth + 1)?;
                    match self.peek() {
                        Some(b',') => self.i += 1,
                        Some(c) if c == close => {
                            self.i += 1;
                            return Ok(());
                        }
                        _ => return Err(self.syntax("',' or a closing bracket")),
                    }
                }
            }
            _ => {
                for word in ["true", "false", "null"] {
                    if self.s.get(self.i..).is_some_and(|r| r.starts_with(word.as_bytes())) {
                        self.i += word.len();
                        return Ok(());
                    }
                }
                Err(self.syntax("a JSON value"))
            }
        }
    }
}

/// Test data: a valid file and a table of hostile ones, shared by the tests
/// of this reader, of `crane-sim replay` and of the firmware under QEMU, so
/// all three are held to the same verdicts.
#[cfg(any(test, feature = "std"))]
#[doc(hidden)]
pub mod hostile {
    use super::CALIBRATION_KEYS;

    /// A valid file of schema version 5 (the base the hostile cases alter).
    pub const GOOD: &str = r#"{"version": 5, "friction_up_n": 10011.5, "friction_down_n": 9000,
        "force_offset_n": -1932.4, "p1_offset_bar": 0.5, "p2_offset_bar": -0.25,
        "angle_offset_deg": 0.0, "friction_up_per_force": 0.025,
        "friction_down_per_force": 0.0125, "angle_sensor_lag_s": 0.2,
        "friction_up_per_rate": 120000, "friction_down_per_rate": 80000.5,
        "seal_release_up_s": 0.15}"#;

    /// A valid file of schema version 4 (the friction per unit rate, no
    /// seals' release time: read with the configured one).
    pub const GOOD_V4: &str = r#"{"version": 4, "friction_up_n": 10011.5, "friction_down_n": 9000,
        "force_offset_n": -1932.4, "p1_offset_bar": 0.5, "p2_offset_bar": -0.25,
        "angle_offset_deg": 0.0, "friction_up_per_force": 0.025,
        "friction_down_per_force": 0.0125, "angle_sensor_lag_s": 0.2,
        "friction_up_per_rate": 120000, "friction_down_per_rate": 80000.5}"#;

    /// A valid file of schema version 3 (the seal law and the lag, no
    /// friction per unit rate: read as c = 0).
    pub const GOOD_V3: &str = r#"{"version": 3, "friction_up_n": 10011.5, "friction_down_n": 9000,
        "force_offset_n": -1932.4, "p1_offset_bar": 0.5, "p2_offset_bar": -0.25,
        "angle_offset_deg": 0.0, "friction_up_per_force": 0.025,
        "friction_down_per_force": 0.0125, "angle_sensor_lag_s": 0.2}"#;

    /// A valid file of schema version 2 (the seal law, no lag: read with
    /// the configured lag).
    pub const GOOD_V2: &str = r#"{"version": 2, "friction_up_n": 10011.5, "friction_down_n": 9000,
        "force_offset_n": -1932.4, "p1_offset_bar": 0.5, "p2_offset_bar": -0.25,
        "angle_offset_deg": 0.0, "friction_up_per_force": 0.025,
        "friction_down_per_force": 0.0125}"#;

    /// A valid file of schema version 1 (constant friction; read as b = 0).
    pub const GOOD_V1: &str = r#"{"version": 1, "friction_up_n": 10011.5, "friction_down_n": 9000,
        "force_offset_n": -1932.4, "p1_offset_bar": 0.5, "p2_offset_bar": -0.25,
        "angle_offset_deg": 0.0}"#;

    /// Replaces the value of `key` in GOOD (or removes the member with `None`).
    pub fn with(key: &str, value: Option<&str>) -> String {
        let start = GOOD.find(&format!("\"{key}\"")).unwrap();
        let end = start + GOOD[start..].find([',', '}']).unwrap();
        match value {
            Some(v) => format!("{}\"{key}\": {v}{}", &GOOD[..start], &GOOD[end..]),
            None => {
                // Drop the member and the comma after it (or before it, if last).
                let rest = &GOOD[end..];
                if let Some(r) = rest.strip_prefix(',') {
                    format!("{}{}", &GOOD[..start], r)
                } else {
                    let head = GOOD[..start].trim_end();
                    format!("{}{}", head.strip_suffix(',').unwrap(), rest)
                }
            }
        }
    }

    /// The hostile table: (name, file text, what the refusal must say); every
    /// entry must be refused, naming the key at fault.
    pub fn cases() -> Vec<(String, String, &'static str)> {
        let mut cases: Vec<(String, String, &'static str)> = vec![
            ("empty object".into(), "{}".into(), "`version` is missing"),
            ("array".into(), "[1,2,3]".into(), "one JSON object"),
            ("empty file".into(), "".into(), "empty file"),
            ("not JSON".into(), "friction_up_n = 3".into(), "not valid JSON"),
            ("a sensor log".into(), "# crane-sim synth\nt_s,p1_bar,p2_bar,boom_angle_deg\n0,1,2,3\n".into(), "this is a sensor log (CSV)"),
            ("a log without comments".into(), "t_s,p1_bar,p2_bar,boom_angle_deg\n0,1,2,3\n".into(), "this is a sensor log (CSV)"),
            ("trailing garbage".into(), format!("{GOOD} x"), "not valid JSON"),
            (
                "unknown key".into(),
                GOOD.replace("\"angle_offset_deg\"", "\"angle_ofset_deg\""),
                "`angle_ofset_deg` is not in the calibration schema",
            ),
            (
                "duplicate key".into(),
                GOOD.replace("\"p2_offset_bar\"", "\"p1_offset_bar\""),
                "`p1_offset_bar` is given twice",
            ),
            (
                "version 6".into(),
                with("version", Some("6")),
                "`version` = 6: this reader knows versions 1, 2, 3, 4 and 5",
            ),
            (
                "version 2.5".into(),
                with("version", Some("2.5")),
                "`version` = 2.5: this reader knows versions 1, 2, 3, 4 and 5",
            ),
            (
                "version 4 with the release key".into(),
                with("version", Some("4")),
                "`seal_release_up_s` is not in calibration schema version 4",
            ),
            (
                "version 4 without version 4's keys".into(),
                GOOD_V4.replace(", \"friction_down_per_rate\": 80000.5", ""),
                "`friction_down_per_rate` is missing",
            ),
            (
                "version 3 with a rate key".into(),
                with("version", Some("3")).replace(",\n        \"seal_release_up_s\": 0.15", ""),
                "`friction_up_per_rate` is not in calibration schema version 3",
            ),
            (
                "version 3 without version 3's keys".into(),
                GOOD_V3.replace(", \"angle_sensor_lag_s\": 0.2", ""),
                "`angle_sensor_lag_s` is missing",
            ),
            (
                "version 2 with the lag key".into(),
                with("version", Some("2")),
                "`angle_sensor_lag_s` is not in calibration schema version 2",
            ),
            (
                "version 2 without version 2's keys".into(),
                GOOD_V2.replace(",\n        \"friction_down_per_force\": 0.0125", ""),
                "`friction_down_per_force` is missing",
            ),
            (
                "version 1 with a seal-law key".into(),
                with("version", Some("1")),
                "`friction_up_per_force` is not in calibration schema version 1",
            ),
            (
                "version 1 without version 1's keys".into(),
                GOOD_V1.replace("\"p2_offset_bar\": -0.25,", ""),
                "`p2_offset_bar` is missing",
            ),
            (
                "version as a string".into(),
                with("version", Some("\"1\"")),
                "`version` must be a number",
            ),
            (
                "pre-schema file (no version)".into(),
                with("version", None),
                "predates calibration schema 1",
            ),
        ];
        for spec in CALIBRATION_KEYS {
            let k = spec.key;
            cases.push((format!("{k} missing"), with(k, None), "is missing"));
            for (what, v) in [
                ("a string", "\"10\""),
                ("null", "null"),
                ("true", "true"),
                ("an array", "[1]"),
                ("an object", "{\"a\": 1}"),
            ] {
                cases.push((format!("{k} is {what}"), with(k, Some(v)), "must be a number"));
            }
            let over = format!("{}", spec.max + 1.0);
            let under = format!("{}", spec.min - 1.0);
            cases.push((format!("{k} above its bound"), with(k, Some(&over)), "is outside"));
            cases.push((format!("{k} below its bound"), with(k, Some(&under)), "is outside"));
            cases.push((format!("{k} = 1e999"), with(k, Some("1e999")), "is outside"));
        }
        cases.push((
            "angle_sensor_lag_s = 0.6 (a broken sensor)".into(),
            with("angle_sensor_lag_s", Some("0.6")),
            "key `angle_sensor_lag_s` = 0.6 is outside 0 ... 0.5 s",
        ));
        cases.push((
            "p1_offset_bar = 50 (the issue's case)".into(),
            with("p1_offset_bar", Some("50")),
            "key `p1_offset_bar` = 50 is outside -4 ... 4 bar (2 % of the 200 bar transducer span)",
        ));
        // Shown in exponent form, not as the 309 digits of 1e308.
        cases.push((
            "angle_sensor_lag_s = 1e308".into(),
            with("angle_sensor_lag_s", Some("1e308")),
            "key `angle_sensor_lag_s` = 1e308 is outside 0 ... 0.5 s",
        ));
        cases.push(("version = 1e300".into(), with("version", Some("1e300")), "key `version` = 1e300: this reader"));
        cases
    }

}

#[cfg(test)]
mod tests {
    use super::hostile::{cases as hostile_cases, with, GOOD};
    use super::*;

    #[test]
    fn a_good_file_reads_and_the_writer_round_trips() {
        let c = parse_calibration::<f64>(GOOD.as_bytes()).unwrap();
        assert_eq!(c.friction_up_n, 10011.5);
        assert_eq!(c.force_offset_n, -1932.4);
        assert_eq!(c.p2_offset_bar, -0.25);
        let mut text = String::new();
        write_calibration_json(&mut text, &c).unwrap();
        assert_eq!(parse_calibration::<f64>(text.as_bytes()).unwrap(), c);
        assert!(text.starts_with("{\n  \"version\": 5,\n"), "{text}");
        assert_eq!(c.friction_up_per_force, 0.025);
        assert_eq!(c.angle_sensor_lag_s, Some(0.2));
        assert_eq!(c.seal_release_up_s, Some(0.15));
        assert_eq!((c.friction_up_per_rate, c.friction_down_per_rate), (120_000.0, 80_000.5));
        // BOM and f32.
        let bom = format!("\u{feff}{GOOD}");
        let c32 = parse_calibration::<f32>(bom.as_bytes()).unwrap();
        assert_eq!(c32.friction_up_n, 10011.5_f32);
        assert_eq!(c32.angle_sensor_lag_s, Some(0.2_f32));
    }

    /// A version-4 file (before the seals' release was learned) reads
    /// without a release time: the limiter takes friction off with its
    /// configured one, as it did. Written again, it is a version-5 file
    /// with that time.
    #[test]
    fn a_version_4_file_reads_without_a_release_time() {
        use super::hostile::GOOD_V4;
        let c4 = parse_calibration::<f64>(GOOD_V4.as_bytes()).unwrap();
        let c5 = parse_calibration::<f64>(GOOD.as_bytes()).unwrap();
        assert_eq!(c4, Calibration { seal_release_up_s: None, ..c5 });
        use crate::load_estimate::{Direction, Friction};
        let after_raise = Friction::Static { last_moving: Some(Direction::Up) };
        let after_lowering = Friction::Static { last_moving: Some(Direction::Down) };
        let config = crate::cycle::LimiterConfig { calibration: c4, ..crate::cycle::LimiterConfig::standard() };
        assert_eq!(config.effective_seal_release_s(after_raise), crate::cycle::DEFAULT_SEAL_RELEASE_S);
        let config = crate::cycle::LimiterConfig { calibration: c5, ..config };
        assert_eq!(config.effective_seal_release_s(after_raise), 0.15);
        // After a lowering the configured one (see crate::seal_release).
        assert_eq!(config.effective_seal_release_s(after_lowering), crate::cycle::DEFAULT_SEAL_RELEASE_S);
        let mut text = String::new();
        write_calibration_json(&mut text, &c4).unwrap();
        assert!(text.contains("\"seal_release_up_s\": 0.5") && text.starts_with("{\n  \"version\": 5,\n"), "{text}");
        assert_eq!(parse_calibration::<f64>(text.as_bytes()).unwrap(), Calibration { seal_release_up_s: Some(0.5), ..c4 });
    }

    /// A version-3 file (before the friction's part that grows with the
    /// rate) reads as c = 0, the friction it was applied with, and is
    /// written again as version 5 with c = 0 (and the standard release).
    #[test]
    fn a_version_3_file_reads_with_no_friction_per_rate() {
        use super::hostile::{GOOD_V3, GOOD_V4};
        let c3 = parse_calibration::<f64>(GOOD_V3.as_bytes()).unwrap();
        let c4 = parse_calibration::<f64>(GOOD_V4.as_bytes()).unwrap();
        assert_eq!(c3, Calibration { friction_up_per_rate: 0.0, friction_down_per_rate: 0.0, ..c4 });
        let mut text = String::new();
        write_calibration_json(&mut text, &c3).unwrap();
        assert!(text.contains("\"friction_up_per_rate\": 0.0") && text.starts_with("{\n  \"version\": 5,\n"), "{text}");
        assert_eq!(parse_calibration::<f64>(text.as_bytes()).unwrap(), Calibration { seal_release_up_s: Some(0.5), ..c3 });
    }

    #[test]
    fn a_version_2_file_reads_without_a_lag() {
        use super::hostile::{GOOD_V2, GOOD_V3};
        let c2 = parse_calibration::<f64>(GOOD_V2.as_bytes()).unwrap();
        let c3 = parse_calibration::<f64>(GOOD_V3.as_bytes()).unwrap();
        assert_eq!(c2, Calibration { angle_sensor_lag_s: None, ..c3 });
        // The limiter then aligns with its configured lag.
        let config = crate::cycle::LimiterConfig { calibration: c2, ..crate::cycle::LimiterConfig::standard() };
        assert_eq!(config.effective_angle_sensor_lag_s(), crate::cycle::DEFAULT_ANGLE_SENSOR_LAG_S);
        let config = crate::cycle::LimiterConfig { calibration: c3, ..config };
        assert_eq!(config.effective_angle_sensor_lag_s(), 0.2);
        // Re-written, it is a version-5 file with the standard lag.
        let mut text = String::new();
        write_calibration_json(&mut text, &c2).unwrap();
        let back = parse_calibration::<f64>(text.as_bytes()).unwrap();
        assert_eq!(
            back,
            Calibration {
                angle_sensor_lag_s: Some(crate::cycle::DEFAULT_ANGLE_SENSOR_LAG_S),
                seal_release_up_s: Some(crate::cycle::DEFAULT_SEAL_RELEASE_S),
                ..c2
            }
        );
    }

    #[test]
    fn every_hostile_file_is_refused_naming_the_key() {
        for (name, text, expect) in hostile_cases() {
            let e = parse_calibration::<f32>(text.as_bytes())
                .map(|_| ())
                .expect_err(&name);
            let msg = e.to_string();
            assert!(msg.contains(expect), "{name}: `{msg}` lacks `{expect}`\n{text}");
            // The key is named wherever one is at fault.
            for spec in CALIBRATION_KEYS {
                if name.starts_with(spec.key) {
                    assert!(msg.contains(&format!("`{}`", spec.key)), "{name}: {msg}");
                }
            }
        }
    }

    #[test]
    fn a_version_1_file_reads_as_constant_friction() {
        use super::hostile::{GOOD_V1, GOOD_V3};
        let c1 = parse_calibration::<f64>(GOOD_V1.as_bytes()).unwrap();
        let c2 = parse_calibration::<f64>(GOOD_V3.as_bytes()).unwrap();
        assert_eq!(c1.friction_up_per_force, 0.0);
        assert_eq!(c1.friction_down_per_force, 0.0);
        assert_eq!(
            c1,
            Calibration {
                friction_up_per_force: 0.0,
                friction_down_per_force: 0.0,
                angle_sensor_lag_s: None,
                ..c2
            }
        );
        // Re-written, it is a version-5 file with b = 0 and the standard lag.
        let mut text = String::new();
        write_calibration_json(&mut text, &c1).unwrap();
        assert!(text.contains("\"friction_up_per_force\": 0.0"), "{text}");
        assert_eq!(
            parse_calibration::<f64>(text.as_bytes()).unwrap(),
            Calibration {
                angle_sensor_lag_s: Some(crate::cycle::DEFAULT_ANGLE_SENSOR_LAG_S),
                seal_release_up_s: Some(crate::cycle::DEFAULT_SEAL_RELEASE_S),
                ..c1
            }
        );
    }

    #[test]
    fn the_shipped_example_reads() {
        let text = include_str!("../../../../examples/logs/cal.json");
        let c = parse_calibration::<f64>(text.as_bytes()).unwrap();
        assert!(check_calibration(&c).is_ok());
    }

    #[test]
    fn bounds_are_inclusive_and_non_numbers_are_syntax_errors() {
        for spec in CALIBRATION_KEYS {
            for v in [spec.min, spec.max] {
                let t = with(spec.key, Some(&format!("{v}")));
                assert!(parse_calibration::<f64>(t.as_bytes()).is_ok(), "{t}");
            }
        }
        for bad in ["NaN", "Infinity", "01", "1.", ".5", "+1", "- 1"] {
            let t = with("p1_offset_bar", Some(bad));
            assert!(
                matches!(
                    parse_calibration::<f64>(t.as_bytes()),
                    Err(CalibrationFileError::Syntax { .. })
                ),
                "{bad}"
            );
        }
    }
}
