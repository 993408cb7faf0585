//! The event log's record: 16 bytes, fixed size, so the log is a plain queue
//! and its worst-case size is known. `sequential-storage` adds a CRC-32 to
//! every item it stores; a record that fails it is never returned.

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
