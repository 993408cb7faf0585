//! The event log's record: 16 bytes, fixed size, so the log is a plain queue
//! and its worst-case size is known. The journal adds a CRC-32 to every
//! record it stores; a record that fails it is never returned.

/// What happened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum EventKind {
    /// The controller started; `detail` is the [`crate::latch::ResetCause`] code.
    Boot = 1,
    /// A fault reset latched the outputs cut; `detail` is the reset cause code,
    /// `value` the number of latched resets so far.
    FaultLatched = 2,
    /// The operator acknowledged a latched fault (acknowledge input held).
    Acknowledged = 3,
    /// The power-up self-test passed; `value` its duration in core clock cycles.
    SelfTestPassed = 4,
    /// The power-up self-test failed; `detail` the check that failed
    /// (1 RAM, 2 image, 3 model, 4 outputs, 5 sensors).
    SelfTestFailed = 5,
    /// New calibration stored; `value` its blob version.
    CalibrationStored = 6,
    /// The persisted settings could not be read (corrupt or unreadable flash).
    StorageError = 7,
    /// The stored calibration was decoded and applied; `value` its CRC-32.
    CalibrationApplied = 8,
    /// The stored calibration was refused, so no motion is granted;
    /// `detail` the reason
    /// ([`crate::calibration_blob::CalibrationBlobError::code`]: 1 missing,
    /// 2 unreadable, 3 length, 4 magic, 5 CRC, 6 format, 7 schema version,
    /// 8 out of bounds), `value` its detail (the key's index for 8).
    CalibrationRefused = 9,
    /// The limiter changed state during operation; `detail` the new state
    /// (0 NORMAL, 1 WARNING, 2 OVERLOAD, 3 FAULT), `value` the fault class
    /// in its low byte (see [`crate::event_queue::fault_code`]) and the
    /// utilization in ‰ in its upper 16 bits (0xFFFF unknown).
    StateChanged = 10,
    /// Events recorded during operation but dropped because the RAM queue
    /// was full (see [`crate::event_queue`]); `value` how many.
    EventsDropped = 11,
}

impl EventKind {
    /// The kind for a stored code, if it is one.
    pub fn from_code(code: u8) -> Option<Self> {
        Some(match code {
            1 => EventKind::Boot,
            2 => EventKind::FaultLatched,
            3 => EventKind::Acknowledged,
            4 => EventKind::SelfTestPassed,
            5 => EventKind::SelfTestFailed,
            6 => EventKind::CalibrationStored,
            7 => EventKind::StorageError,
            8 => EventKind::CalibrationApplied,
            9 => EventKind::CalibrationRefused,
            10 => EventKind::StateChanged,
            11 => EventKind::EventsDropped,
            _ => return None,
        })
    }
}

/// One event of the log.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EventRecord {
    /// Boot number (persisted counter) when it happened.
    pub boot: u32,
    /// What happened.
    pub kind: EventKind,
    /// Kind-specific code.
    pub detail: u8,
    /// Kind-specific value.
    pub value: u32,
    /// Milliseconds since this boot.
    pub uptime_ms: u32,
}

/// Bytes of one encoded record.
pub const RECORD_LEN: usize = 16;

impl EventRecord {
    /// The record's bytes (little-endian; byte 6–7 reserved, zero).
    pub fn encode(&self) -> [u8; RECORD_LEN] {
        let mut b = [0u8; RECORD_LEN];
        crate::put(&mut b, 0, &self.boot.to_le_bytes());
        b[4] = self.kind as u8;
        b[5] = self.detail;
        crate::put(&mut b, 8, &self.value.to_le_bytes());
        crate::put(&mut b, 12, &self.uptime_ms.to_le_bytes());
        b
    }

    /// A record from its bytes; `None` if the length or the kind is wrong.
    pub fn decode(bytes: &[u8]) -> Option<Self> {
        let b: &[u8; RECORD_LEN] = bytes.try_into().ok()?;
        let [b0, b1, b2, b3, kind, detail, _, _, v0, v1, v2, v3, u0, u1, u2, u3] = *b;
        Some(EventRecord {
            boot: u32::from_le_bytes([b0, b1, b2, b3]),
            kind: EventKind::from_code(kind)?,
            detail,
            value: u32::from_le_bytes([v0, v1, v2, v3]),
            uptime_ms: u32::from_le_bytes([u0, u1, u2, u3]),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_refusals() {
        let r = EventRecord {
            boot: 7,
            kind: EventKind::FaultLatched,
            detail: 9,
            value: 0xDEAD_BEEF,
            uptime_ms: 1234,
        };
        assert_eq!(EventRecord::decode(&r.encode()), Some(r));
        let mut bad = r.encode();
        bad[4] = 0;
        assert_eq!(EventRecord::decode(&bad), None);
        assert_eq!(EventRecord::decode(&r.encode()[..15]), None);
    }
}
