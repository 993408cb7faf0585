//! The persisted settings and the event log, on NOR flash.
//!
//! Two separate flash ranges ([`Layout`]), each split into two banks of whole
//! erase pages, each a [`Journal`] (see `journal` for the
//! format and why an update survives a power cut at any step):
//!
//! - **settings**: records keyed by [`Key`]; the latest record of a key is its
//!   value. The calibration and the configuration are opaque blobs with a
//!   version (their schema belongs to whoever reads them): 8 header bytes
//!   (version u16, length u16, CRC-32 of the bytes) followed by at most
//!   [`BLOB_MAX`] bytes (the calibration's bytes are the 60-byte blob of
//!   [`crate::calibration_blob`], stored under version
//!   [`crate::calibration_blob::BLOB_FORMAT`]). The fault latch and the boot
//!   counter are small values under their own keys. Compaction keeps the
//!   latest record of each key.
//! - **events**: 16-byte [`EventRecord`]s; when a bank is full the newest half
//!   is moved to the other bank and the oldest events are dropped. During
//!   operation the board appends only without erasing
//!   ([`Store::append_event_without_erase`], after [`Store::reserve_events`]
//!   at start-up; see [`crate::event_queue`]).
//!
//! Every record carries a CRC-32 (key, length, data) checked on every read, and
//! blobs carry their own CRC-32 too: a record that fails either is never
//! returned (the previous value of its key is). `tests/power_cut.rs` cuts the
//! power at every single flash write and erase of an update and checks that
//! the old or the new value is read afterwards, never garbage.
//!
//! (`sequential-storage` was used first; its map and queue made the board
//! image 14 KB larger and broke the 64 KiB flash budget, so this crate has its
//! own two-bank journal, about 3 KB, proven by the same tests.)

use crate::crc::crc32;
use crate::event::{EventRecord, RECORD_LEN};
use crate::journal::{Flash, Journal, JournalError, Keep};
use crate::latch::{LatchState, LATCH_LEN};
use core::ops::Range;

/// Where the two stores live, as offsets in the flash device.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Layout {
    /// The settings journal (≥ 2 erase pages, page aligned).
    pub settings: Range<u32>,
    /// The event log journal (≥ 2 erase pages, page aligned).
    pub events: Range<u32>,
}

/// Keys of the settings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum Key {
    /// Sensor and friction calibration (opaque blob).
    Calibration = 1,
    /// Limiter configuration (opaque blob).
    Configuration = 2,
    /// The fault latch ([`LatchState`]).
    Latch = 3,
    /// Number of boots (u32), numbers the event records.
    BootCount = 4,
}

/// Largest blob in bytes.
pub const BLOB_MAX: usize = 1024;
const BLOB_HEADER: usize = 8;
/// The one key of the event journal.
const EVENT_KEY: u8 = 0;

/// Why a store operation failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StoreError {
    /// The flash driver reported an error.
    Flash,
    /// Written flash without a valid journal: nothing there can be trusted
    /// (the next write starts the journal afresh).
    Corrupted,
    /// No room left (the settings range is too small for its values).
    Full,
    /// The layout does not fit the flash geometry (banks of whole erase pages).
    Geometry,
    /// A blob larger than [`BLOB_MAX`], or a buffer too small for it.
    TooBig,
    /// A blob whose own CRC-32 or header does not match its bytes.
    BadBlob,
    /// The write needs a flash erase, which the caller did not allow
    /// ([`Store::append_event_without_erase`]).
    NeedsErase,
}

impl core::fmt::Display for StoreError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            StoreError::Flash => "flash driver error",
            StoreError::Corrupted => "persisted data corrupted",
            StoreError::Full => "flash store full",
            StoreError::TooBig => "blob too large",
            StoreError::BadBlob => "blob checksum mismatch",
            StoreError::Geometry => "flash layout does not fit the flash",
            StoreError::NeedsErase => "the write needs a flash erase",
        })
    }
}

impl StoreError {
    /// A short name (for logs without `core::fmt`).
    pub fn as_str(&self) -> &'static str {
        match self {
            StoreError::Flash => "flash",
            StoreError::Corrupted => "corrupted",
            StoreError::Full => "full",
            StoreError::TooBig => "too big",
            StoreError::BadBlob => "bad blob",
            StoreError::Geometry => "geometry",
            StoreError::NeedsErase => "needs erase",
        }
    }
}

impl From<JournalError> for StoreError {
    fn from(e: JournalError) -> Self {
        match e {
            JournalError::Flash => StoreError::Flash,
            JournalError::Corrupted => StoreError::Corrupted,
            JournalError::TooBig => StoreError::TooBig,
            JournalError::Full => StoreError::Full,
            JournalError::Geometry => StoreError::Geometry,
            JournalError::NeedsErase => StoreError::NeedsErase,
        }
    }
}

/// A versioned blob read back from flash.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Blob<'a> {
    /// Version of the blob's format, as stored.
    pub version: u16,
    /// The blob's bytes (checked against their CRC-32).
    pub bytes: &'a [u8],
}

/// The persisted store on a NOR flash (any `embedded-storage` `NorFlash`, or
/// another [`Flash`]).
pub struct Store<F> {
    flash: F,
    settings: Journal,
    events: Journal,
}

impl<F: Flash> Store<F> {
    /// A store over `flash` in the ranges of `layout`. Nothing is read or
    /// written until asked.
    pub fn new(flash: F, layout: Layout) -> Self {
        Store {
            flash,
            settings: Journal::new(layout.settings, Keep::LatestPerKey),
            events: Journal::new(layout.events, Keep::NewestHalf),
        }
    }

    /// The flash (tests inspect it while the store is in use).
    pub fn flash(&self) -> &F {
        &self.flash
    }

    /// Gives the flash back (tests inspect it).
    pub fn into_flash(self) -> F {
        self.flash
    }

    /// Reads the latest value of `key` into `out`: its length, or `None`.
    // Never inlined: generic, it is compiled in the caller's crate (the
    // firmware's start-up), where its three inlined copies took 0.32 KB
    // more of the board's 64 KiB flash than one function.
    #[inline(never)]
    fn fetch_raw(&mut self, key: Key, out: &mut [u8]) -> Result<Option<usize>, StoreError> {
        let Some(r) = self.settings.latest(&mut self.flash, key as u8)? else {
            return Ok(None);
        };
        Ok(Some(Journal::read_data(&mut self.flash, r, out)?))
    }

    fn store_raw(&mut self, key: Key, value: &[u8]) -> Result<(), StoreError> {
        Ok(self.settings.append(&mut self.flash, key as u8, value)?)
    }

    /// Reads the blob under `key` into `out`; `Ok(None)` if none was ever stored.
    pub fn read_blob<'o>(
        &mut self,
        key: Key,
        out: &'o mut [u8],
    ) -> Result<Option<Blob<'o>>, StoreError> {
        let mut raw = [0u8; BLOB_HEADER + BLOB_MAX];
        let Some(n) = self.fetch_raw(key, &mut raw)? else {
            return Ok(None);
        };
        let raw = raw.get(..n).ok_or(StoreError::BadBlob)?;
        let (header, bytes) = raw
            .split_first_chunk::<BLOB_HEADER>()
            .ok_or(StoreError::BadBlob)?;
        let [v0, v1, l0, l1, c0, c1, c2, c3] = *header;
        let version = u16::from_le_bytes([v0, v1]);
        let len = usize::from(u16::from_le_bytes([l0, l1]));
        let crc = u32::from_le_bytes([c0, c1, c2, c3]);
        let bytes = bytes.get(..len).ok_or(StoreError::BadBlob)?;
        if crc32(bytes) != crc {
            return Err(StoreError::BadBlob);
        }
        let out = out.get_mut(..len).ok_or(StoreError::TooBig)?;
        crate::put(out, 0, bytes);
        Ok(Some(Blob {
            version,
            bytes: out,
        }))
    }

    /// Stores `bytes` with `version` under `key`; the previous blob stays the
    /// value until the new one is completely written.
    pub fn write_blob(&mut self, key: Key, version: u16, bytes: &[u8]) -> Result<(), StoreError> {
        let len = u16::try_from(bytes.len())
            .ok()
            .filter(|&l| usize::from(l) <= BLOB_MAX)
            .ok_or(StoreError::TooBig)?;
        let mut item = [0u8; BLOB_HEADER + BLOB_MAX];
        crate::put(&mut item, 0, &version.to_le_bytes());
        crate::put(&mut item, 2, &len.to_le_bytes());
        crate::put(&mut item, 4, &crc32(bytes).to_le_bytes());
        let end = BLOB_HEADER + bytes.len();
        crate::put(&mut item, BLOB_HEADER, bytes);
        self.store_raw(key, item.get(..end).ok_or(StoreError::TooBig)?)
    }

    /// The persisted fault latch; an unwritten latch reads as not active.
    pub fn latch(&mut self) -> Result<LatchState, StoreError> {
        let mut raw = [0u8; LATCH_LEN];
        Ok(match self.fetch_raw(Key::Latch, &mut raw) {
            Ok(Some(n)) => LatchState::decode(raw.get(..n).unwrap_or(&[])),
            Ok(None) => LatchState::default(),
            // A value longer than a latch is not a latch: read as latched.
            Err(StoreError::TooBig) => LatchState::decode(&[]),
            Err(e) => return Err(e),
        })
    }

    /// Persists the fault latch.
    pub fn set_latch(&mut self, state: LatchState) -> Result<(), StoreError> {
        self.store_raw(Key::Latch, &state.encode())
    }

    /// Increments and returns the persisted boot counter (1 on first boot).
    pub fn next_boot(&mut self) -> Result<u32, StoreError> {
        let mut raw = [0u8; 4];
        let previous = match self.fetch_raw(Key::BootCount, &mut raw)? {
            Some(4) => u32::from_le_bytes(raw),
            Some(_) => return Err(StoreError::BadBlob),
            None => 0,
        };
        let boot = previous.saturating_add(1);
        self.store_raw(Key::BootCount, &boot.to_le_bytes())?;
        Ok(boot)
    }

    /// Appends an event; when the log is full the oldest events are dropped.
    pub fn append_event(&mut self, event: &EventRecord) -> Result<(), StoreError> {
        Ok(self
            .events
            .append(&mut self.flash, EVENT_KEY, &event.encode())?)
    }

    /// Appends an event only if no flash erase is needed (see
    /// [`Journal::append_without_erase`]): what the board does while it runs.
    pub fn append_event_without_erase(&mut self, event: &EventRecord) -> Result<(), StoreError> {
        Ok(self
            .events
            .append_without_erase(&mut self.flash, EVENT_KEY, &event.encode())?)
    }

    /// Makes room for `records` events without any erase later (erasing and
    /// compacting now if needed): the board calls it at start-up, before the
    /// watchdog runs, so the events of the run that follows need no erase.
    /// At most half the event bank can be reserved (compaction keeps the
    /// newest half).
    pub fn reserve_events(&mut self, records: u32) -> Result<(), StoreError> {
        let bytes = records.saturating_mul(Journal::record_size(RECORD_LEN));
        Ok(self.events.reserve(&mut self.flash, bytes)?)
    }

    /// Calls `each` with every stored event, oldest first; returns how many.
    /// A record whose CRC fails, or that does not decode (an unknown kind,
    /// written by a newer firmware), is skipped and not counted.
    pub fn for_each_event(
        &mut self,
        mut each: impl FnMut(EventRecord),
    ) -> Result<usize, StoreError> {
        let mut n = 0;
        self.events.for_each(&mut self.flash, |flash, r| {
            if usize::from(r.len) == RECORD_LEN && Journal::crc_ok(flash, r)? {
                let mut buf = [0u8; RECORD_LEN];
                Journal::read_data(flash, r, &mut buf)?;
                if let Some(record) = EventRecord::decode(&buf) {
                    each(record);
                    n += 1;
                }
            }
            Ok(())
        })?;
        Ok(n)
    }
}
