//! The calibration's stored form on the board: a fixed-size binary blob the
//! host makes from a validated `CAL.json` (`calibration-image`, a host tool
//! of this crate) and the board decodes at start-up, instead of parsing JSON
//! on the board (the JSON reader made the board image 71.5 KB, over its
//! 64 KiB flash budget; this decoder is a few hundred bytes).
//!
//! ## Format, version [`BLOB_FORMAT`] = 5 (108 bytes, little-endian)
//!
//! | bytes | holds |
//! |---|---|
//! | 0–3 | magic `LMLC` |
//! | 4–5 | blob format version, [`BLOB_FORMAT`] |
//! | 6–7 | calibration schema version, [`CALIBRATION_VERSION`] |
//! | 8–103 | the twelve values of [`CALIBRATION_KEYS`], in its order, each an `f64` (the last, the seals' release time) |
//! | 104–107 | CRC-32 ([`crate::crc`]) of bytes 0–103 |
//!
//! **Format 4** (100 bytes: schema version 4, the first eleven values, CRC
//! at 96–99), what boards calibrated before the seals' release was learned
//! hold, is still decoded, without a release time (the board takes friction
//! off with its configured one, as it did); **format 3** (84 bytes: schema version 3, the first nine values, CRC at
//! 80–83), what boards calibrated before the friction per unit rate was
//! learned hold, is still decoded, as c = 0 (the friction it was applied
//! with); **format 2** (76 bytes: schema version 2, the first eight values, CRC
//! at 72–75), what boards calibrated before the lag was learned hold, is
//! still decoded, without a lag (the board aligns with its configured
//! lag, as it did); **format 1** (60 bytes: schema version 1, the first
//! six values, CRC at 56–59), from before the seal law, too, as the
//! constant friction it was (b = 0): a board keeps its calibration across
//! a firmware update. The encoder writes format 5 only.
//!
//! Values are stored as the `f64` the JSON reader read, so a blob decodes to
//! exactly the calibration the JSON file gives, in `f64` on the host and, by
//! the same `T::lit` conversion, in `f32` on the board.
//!
//! The decoder checks, in this order: the length, the magic, the CRC, the
//! two versions, then every value against the **schema's own bound table**
//! ([`check_calibration`], the check the JSON reader makes; no bound is
//! written here). Any failure is a [`CalibrationBlobError`] whose
//! [`CalibrationBlobError::code`] the board records in its event log; the
//! board then grants no motion.

use crate::crc::crc32;
use crane_model::Real;
use moment_limiter::tools::config_file::{
    calibration_from_values, calibration_values, check_calibration, CalibrationFileError,
    CALIBRATION_KEYS, CALIBRATION_VERSION, CALIBRATION_VERSION_1, CALIBRATION_VERSION_2,
    CALIBRATION_VERSION_3, CALIBRATION_VERSION_4, V1_KEYS, V2_KEYS, V3_KEYS, V4_KEYS,
};
use moment_limiter::load_estimate::Calibration;

/// Magic at the start of a calibration blob.
pub const BLOB_MAGIC: [u8; 4] = *b"LMLC";
/// The blob format the encoder writes (the decoder also reads
/// [`BLOB_FORMAT_1`], [`BLOB_FORMAT_2`], [`BLOB_FORMAT_3`] and
/// [`BLOB_FORMAT_4`]).
pub const BLOB_FORMAT: u16 = 5;
/// The first blob format: schema version 1, six values.
pub const BLOB_FORMAT_1: u16 = 1;
/// The second blob format: schema version 2, eight values (no lag).
pub const BLOB_FORMAT_2: u16 = 2;
/// The third blob format: schema version 3, nine values (no friction per
/// unit rate).
pub const BLOB_FORMAT_3: u16 = 3;
/// The fourth blob format: schema version 4, eleven values (no seals'
/// release time).
pub const BLOB_FORMAT_4: u16 = 4;
/// Bytes of a calibration blob (format 5).
pub const BLOB_LEN: usize = 8 + 8 * CALIBRATION_KEYS.len() + 4;
/// Bytes of a format-1 blob.
pub const BLOB_LEN_1: usize = 8 + 8 * V1_KEYS + 4;
/// Bytes of a format-2 blob.
pub const BLOB_LEN_2: usize = 8 + 8 * V2_KEYS + 4;
/// Bytes of a format-3 blob.
pub const BLOB_LEN_3: usize = 8 + 8 * V3_KEYS + 4;
/// Bytes of a format-4 blob.
pub const BLOB_LEN_4: usize = 8 + 8 * V4_KEYS + 4;
const VALUES_AT: usize = 8;
const CRC_AT: usize = BLOB_LEN - 4;

/// Why a stored calibration blob was refused.
#[derive(Debug, Clone, PartialEq)]
pub enum CalibrationBlobError {
    /// No calibration is stored at all.
    Missing,
    /// The store could not be read (flash error, corrupt journal, or the
    /// store's own CRC-32 of the blob failed).
    Unreadable,
    /// Not [`BLOB_LEN`] (format 5), [`BLOB_LEN_4`], [`BLOB_LEN_3`],
    /// [`BLOB_LEN_2`] nor [`BLOB_LEN_1`] bytes.
    Length(usize),
    /// The magic is not [`BLOB_MAGIC`].
    Magic,
    /// The CRC-32 does not match the bytes.
    Crc,
    /// A blob format this decoder does not know.
    Format(u16),
    /// A calibration schema version this firmware does not know.
    SchemaVersion(u16),
    /// A value outside the schema's bounds (or not finite).
    OutOfBounds(CalibrationFileError),
}

impl CalibrationBlobError {
    /// A one-byte code for the event log (`detail` of
    /// [`crate::event::EventKind::CalibrationRefused`]).
    pub fn code(&self) -> u8 {
        match self {
            CalibrationBlobError::Missing => 1,
            CalibrationBlobError::Unreadable => 2,
            CalibrationBlobError::Length(_) => 3,
            CalibrationBlobError::Magic => 4,
            CalibrationBlobError::Crc => 5,
            CalibrationBlobError::Format(_) => 6,
            CalibrationBlobError::SchemaVersion(_) => 7,
            CalibrationBlobError::OutOfBounds(_) => 8,
        }
    }

    /// A number that says more (the `value` of the event): the length, the
    /// version found, or the index in [`CALIBRATION_KEYS`] of the key out of
    /// bounds; 0 otherwise.
    pub fn detail(&self) -> u32 {
        match self {
            CalibrationBlobError::Length(n) => u32::try_from(*n).unwrap_or(u32::MAX),
            CalibrationBlobError::Format(v) | CalibrationBlobError::SchemaVersion(v) => {
                u32::from(*v)
            }
            CalibrationBlobError::OutOfBounds(CalibrationFileError::OutOfBounds {
                spec, ..
            }) => CALIBRATION_KEYS
                .iter()
                .position(|s| s.key == spec.key)
                .map_or(u32::MAX, |i| i as u32),
            _ => 0,
        }
    }

    /// A short reason (for logs without `core::fmt`).
    pub fn as_str(&self) -> &'static str {
        match self {
            CalibrationBlobError::Missing => "no calibration stored",
            CalibrationBlobError::Unreadable => "calibration unreadable",
            CalibrationBlobError::Length(_) => "calibration blob of the wrong length",
            CalibrationBlobError::Magic => "not a calibration blob",
            CalibrationBlobError::Crc => "calibration blob CRC mismatch",
            CalibrationBlobError::Format(_) => "unknown calibration blob format",
            CalibrationBlobError::SchemaVersion(_) => "unknown calibration schema version",
            CalibrationBlobError::OutOfBounds(_) => "calibration value out of bounds",
        }
    }
}

impl core::fmt::Display for CalibrationBlobError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            CalibrationBlobError::Length(n) => {
                write!(
                    f,
                    "{} ({n} bytes, not {BLOB_LEN}, {BLOB_LEN_4}, {BLOB_LEN_3}, {BLOB_LEN_2} nor {BLOB_LEN_1})",
                    self.as_str()
                )
            }
            CalibrationBlobError::Format(v) => {
                write!(
                    f,
                    "{} {v} (this firmware reads {BLOB_FORMAT_1}, {BLOB_FORMAT_2}, {BLOB_FORMAT_3}, {BLOB_FORMAT_4} and {BLOB_FORMAT})",
                    self.as_str()
                )
            }
            CalibrationBlobError::SchemaVersion(v) => {
                write!(
                    f,
                    "{} {v} (this firmware reads {CALIBRATION_VERSION_1}, {CALIBRATION_VERSION_2}, {CALIBRATION_VERSION_3}, {CALIBRATION_VERSION_4} and {CALIBRATION_VERSION})",
                    self.as_str()
                )
            }
            CalibrationBlobError::OutOfBounds(e) => write!(f, "{e}"),
            _ => f.write_str(self.as_str()),
        }
    }
}

/// The blob of a calibration, after checking it against the schema's
/// bounds (a calibration the board would refuse is never encoded).
pub fn encode_calibration(cal: &Calibration<f64>) -> Result<[u8; BLOB_LEN], CalibrationBlobError> {
    check_calibration(cal).map_err(CalibrationBlobError::OutOfBounds)?;
    let mut b = [0u8; BLOB_LEN];
    crate::put(&mut b, 0, &BLOB_MAGIC);
    crate::put(&mut b, 4, &BLOB_FORMAT.to_le_bytes());
    // The schema version is 5: it fits 16 bits with room to spare.
    crate::put(&mut b, 6, &(CALIBRATION_VERSION as u16).to_le_bytes());
    for (i, v) in calibration_values(cal).iter().enumerate() {
        crate::put(&mut b, VALUES_AT + 8 * i, &v.to_le_bytes());
    }
    let crc = crc32(b.get(..CRC_AT).unwrap_or_default());
    crate::put(&mut b, CRC_AT, &crc.to_le_bytes());
    Ok(b)
}

fn u16_at(b: &[u8], at: usize) -> u16 {
    let mut w = [0u8; 2];
    for (d, s) in w.iter_mut().zip(b.iter().skip(at)) {
        *d = *s;
    }
    u16::from_le_bytes(w)
}

/// Decodes and checks a blob of format 5, 4, 3, 2 or 1 (see the module doc for the
/// order of the checks), and converts the values to `T` as the JSON reader
/// does.
pub fn decode_calibration<T: Real>(bytes: &[u8]) -> Result<Calibration<T>, CalibrationBlobError> {
    // The length says the format; the format field must agree with it.
    let (keys, expected_format, schema_version) = match bytes.len() {
        BLOB_LEN => (CALIBRATION_KEYS.len(), BLOB_FORMAT, CALIBRATION_VERSION),
        BLOB_LEN_4 => (V4_KEYS, BLOB_FORMAT_4, CALIBRATION_VERSION_4),
        BLOB_LEN_3 => (V3_KEYS, BLOB_FORMAT_3, CALIBRATION_VERSION_3),
        BLOB_LEN_2 => (V2_KEYS, BLOB_FORMAT_2, CALIBRATION_VERSION_2),
        BLOB_LEN_1 => (V1_KEYS, BLOB_FORMAT_1, CALIBRATION_VERSION_1),
        n => return Err(CalibrationBlobError::Length(n)),
    };
    let b = bytes;
    if b.get(..4) != Some(&BLOB_MAGIC[..]) {
        return Err(CalibrationBlobError::Magic);
    }
    let crc_at = b.len().saturating_sub(4);
    let (body, crc) = b.split_at(crc_at);
    let mut stored = [0u8; 4];
    crate::put(&mut stored, 0, crc);
    if crc32(body) != u32::from_le_bytes(stored) {
        return Err(CalibrationBlobError::Crc);
    }
    let format = u16_at(b, 4);
    if format != expected_format {
        return Err(CalibrationBlobError::Format(format));
    }
    let schema = u16_at(b, 6);
    if u32::from(schema) != schema_version {
        return Err(CalibrationBlobError::SchemaVersion(schema));
    }
    // Format 1 holds no seal-law share (b = 0, the constant friction it
    // was), formats 1 and 2 no lag (the configured one), formats 1–3 no
    // friction per unit rate (c = 0), formats 1–4 no seals' release time
    // (the configured one).
    let v: [f64; CALIBRATION_KEYS.len()] = core::array::from_fn(|i| {
        let mut w = [0u8; 8];
        if i < keys {
            for (d, s) in w.iter_mut().zip(b.iter().skip(VALUES_AT + 8 * i)) {
                *d = *s;
            }
        }
        f64::from_le_bytes(w)
    });
    let cal: Calibration<f64> = calibration_from_values(&v, keys);
    check_calibration(&cal).map_err(CalibrationBlobError::OutOfBounds)?;
    Ok(calibration_from_values(&v, keys))
}

/// Stores a calibration blob under [`crate::store::Key::Calibration`] with
/// the store version [`BLOB_FORMAT`] (checked again on reading).
pub fn store_calibration<F: crate::journal::Flash>(
    store: &mut crate::store::Store<F>,
    cal: &Calibration<f64>,
) -> Result<(), StoreCalibrationError> {
    let blob = encode_calibration(cal).map_err(StoreCalibrationError::Refused)?;
    store
        .write_blob(crate::store::Key::Calibration, BLOB_FORMAT, &blob)
        .map_err(StoreCalibrationError::Store)
}

/// Why [`store_calibration`] did not store.
#[derive(Debug, Clone, PartialEq)]
pub enum StoreCalibrationError {
    /// The calibration is out of the schema's bounds.
    Refused(CalibrationBlobError),
    /// The store failed.
    Store(crate::store::StoreError),
}

/// Reads the stored calibration and decodes it: what the board applies
/// (with the blob's CRC-32, which identifies it in the event log), or why it
/// refuses to grant motion.
pub fn load_calibration<T: Real, F: crate::journal::Flash>(
    store: &mut crate::store::Store<F>,
) -> Result<(Calibration<T>, u32), CalibrationBlobError> {
    let mut buf = [0u8; BLOB_LEN];
    match store.read_blob(crate::store::Key::Calibration, &mut buf) {
        Ok(None) => Err(CalibrationBlobError::Missing),
        // A stored blob longer than a calibration does not fit `buf`.
        Err(crate::store::StoreError::TooBig) => Err(CalibrationBlobError::Length(BLOB_LEN + 1)),
        Err(crate::store::StoreError::BadBlob) => Err(CalibrationBlobError::Crc),
        Err(_) => Err(CalibrationBlobError::Unreadable),
        Ok(Some(blob))
            if ![BLOB_FORMAT, BLOB_FORMAT_4, BLOB_FORMAT_3, BLOB_FORMAT_2, BLOB_FORMAT_1].contains(&blob.version) =>
        {
            Err(CalibrationBlobError::Format(blob.version))
        }
        Ok(Some(blob)) => {
            let cal = decode_calibration(blob.bytes)?;
            Ok((cal, crc32(blob.bytes)))
        }
    }
}
