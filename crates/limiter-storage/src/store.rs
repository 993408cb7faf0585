//! The persisted settings and the event log, on NOR flash.
//!
//! Two separate flash ranges ([`Layout`]), each at least two erase pages:
//!
//! - **settings**: a `sequential-storage` map from a one-byte [`Key`] to a
//!   value. The calibration and the configuration are opaque blobs with a
//!   version (their schema belongs to whoever reads them): 8 header bytes
//!   (version u16, length u16, CRC-32 of the bytes) followed by at most
//!   [`BLOB_MAX`] bytes. The fault latch and the boot counter are small values
//!   under their own keys.
//! - **events**: a `sequential-storage` queue of 16-byte
//!   [`EventRecord`]s; when it is full the oldest page is dropped.
//!
//! Power-cut safety comes from how `sequential-storage` writes: a new value is
//! appended after the old one (never written over it), its header and a CRC
//! are written so that a torn item is recognised and skipped, and pages are
//! erased only after their live items were copied on. A cut at any write or
//! erase leaves either the old or the new value readable, never a mix; the
//! next operation repairs a half-written page (its `run_with_auto_repair`).
//! `tests/power_cut.rs` cuts the power at every single step of an update and
//! checks exactly that. Our own CRC inside the blob is a second, end-to-end
//! check: a blob whose bytes do not match it is refused, not used.

use crate::blocking::{run, Blocking, WouldBlock};
use crate::crc::crc32;
use crate::event::{EventRecord, RECORD_LEN};
use crate::latch::{LatchState, LATCH_LEN};
use core::ops::Range;
use embedded_storage::nor_flash::NorFlash;
use sequential_storage::cache::NoCache;
use sequential_storage::{map, queue};

/// Where the two stores live, as offsets in the flash device.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Layout {
    /// The settings map (≥ 2 erase pages, page aligned).
    pub settings: Range<u32>,
    /// The event queue (≥ 2 erase pages, page aligned).
    pub events: Range<u32>,
}

/// Keys of the settings map.
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
/// Working buffer: key, blob header and blob, rounded up for flash words.
const BUF_LEN: usize = BLOB_MAX + BLOB_HEADER + 32;
/// Upper bound on the events read back (a full queue of the largest range we
/// configure holds fewer); keeps the read loop bounded.
const MAX_EVENTS: usize = 1 << 16;

/// Why a store operation failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StoreError {
    /// The flash driver reported an error.
    Flash,
    /// The stored data is inconsistent beyond repair: erase the range.
    Corrupted,
    /// No room left (the settings range is too small for its values).
    Full,
    /// A blob larger than [`BLOB_MAX`], or a buffer too small for it.
    TooBig,
    /// A blob whose own CRC-32 or header does not match its bytes.
    BadBlob,
    /// Internal: a flash future did not complete (cannot happen with blocking flash).
    WouldBlock,
}

impl core::fmt::Display for StoreError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            StoreError::Flash => "flash driver error",
            StoreError::Corrupted => "persisted data corrupted",
            StoreError::Full => "flash store full",
            StoreError::TooBig => "blob too large",
            StoreError::BadBlob => "blob checksum mismatch",
            StoreError::WouldBlock => "flash operation did not complete",
        })
    }
}

impl From<WouldBlock> for StoreError {
    fn from(_: WouldBlock) -> Self {
        StoreError::WouldBlock
    }
}

fn map_err<E>(e: sequential_storage::Error<E>) -> StoreError {
    match e {
        sequential_storage::Error::Storage { .. } => StoreError::Flash,
        sequential_storage::Error::FullStorage => StoreError::Full,
        sequential_storage::Error::Corrupted { .. } => StoreError::Corrupted,
        sequential_storage::Error::SerializationError(_) => StoreError::BadBlob,
        _ => StoreError::TooBig,
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

/// The persisted store on a blocking NOR flash.
pub struct Store<F> {
    flash: Blocking<F>,
    layout: Layout,
    buf: [u8; BUF_LEN],
}

impl<F: NorFlash> Store<F> {
    /// A store over `flash` in the ranges of `layout`. Nothing is read or
    /// written until asked.
    pub fn new(flash: F, layout: Layout) -> Self {
        Store {
            flash: Blocking(flash),
            layout,
            buf: [0; BUF_LEN],
        }
    }

    /// Gives the flash back (tests inspect it).
    pub fn into_flash(self) -> F {
        self.flash.0
    }

    fn fetch_raw(&mut self, key: Key) -> Result<Option<&[u8]>, StoreError> {
        let range = self.layout.settings.clone();
        let (flash, buf) = (&mut self.flash, &mut self.buf);
        run(async move {
            map::fetch_item::<u8, &[u8], _>(flash, range, &mut NoCache::new(), buf, &(key as u8))
                .await
        })?
        .map_err(map_err)
    }

    fn store_raw(&mut self, key: Key, value: &[u8]) -> Result<(), StoreError> {
        let range = self.layout.settings.clone();
        let (flash, buf) = (&mut self.flash, &mut self.buf);
        run(async move {
            map::store_item::<u8, &[u8], _>(
                flash,
                range,
                &mut NoCache::new(),
                buf,
                &(key as u8),
                &value,
            )
            .await
        })?
        .map_err(map_err)
    }

    /// Reads the blob under `key` into `out`; `Ok(None)` if none was ever stored.
    pub fn read_blob<'o>(
        &mut self,
        key: Key,
        out: &'o mut [u8],
    ) -> Result<Option<Blob<'o>>, StoreError> {
        let Some(raw) = self.fetch_raw(key)? else {
            return Ok(None);
        };
        let (header, bytes) = raw
            .split_at_checked(BLOB_HEADER)
            .ok_or(StoreError::BadBlob)?;
        let version = u16::from_le_bytes([header[0], header[1]]);
        let len = usize::from(u16::from_le_bytes([header[2], header[3]]));
        let crc = u32::from_le_bytes([header[4], header[5], header[6], header[7]]);
        let bytes = bytes.get(..len).ok_or(StoreError::BadBlob)?;
        if crc32(bytes) != crc {
            return Err(StoreError::BadBlob);
        }
        let out = out.get_mut(..len).ok_or(StoreError::TooBig)?;
        out.copy_from_slice(bytes);
        Ok(Some(Blob {
            version,
            bytes: out,
        }))
    }

    /// Stores `bytes` with `version` under `key`, replacing the previous blob
    /// only once the new one is completely written (see the module notes).
    pub fn write_blob(&mut self, key: Key, version: u16, bytes: &[u8]) -> Result<(), StoreError> {
        let len = u16::try_from(bytes.len())
            .ok()
            .filter(|&l| usize::from(l) <= BLOB_MAX)
            .ok_or(StoreError::TooBig)?;
        let mut item = [0u8; BLOB_HEADER + BLOB_MAX];
        item[0..2].copy_from_slice(&version.to_le_bytes());
        item[2..4].copy_from_slice(&len.to_le_bytes());
        item[4..8].copy_from_slice(&crc32(bytes).to_le_bytes());
        let end = BLOB_HEADER + bytes.len();
        item.get_mut(BLOB_HEADER..end)
            .ok_or(StoreError::TooBig)?
            .copy_from_slice(bytes);
        self.store_raw(key, item.get(..end).ok_or(StoreError::TooBig)?)
    }

    /// The persisted fault latch; an unwritten latch reads as not active.
    pub fn latch(&mut self) -> Result<LatchState, StoreError> {
        Ok(match self.fetch_raw(Key::Latch)? {
            Some(raw) => LatchState::decode(raw),
            None => LatchState::default(),
        })
    }

    /// Persists the fault latch.
    pub fn set_latch(&mut self, state: LatchState) -> Result<(), StoreError> {
        let bytes: [u8; LATCH_LEN] = state.encode();
        self.store_raw(Key::Latch, &bytes)
    }

    /// Increments and returns the persisted boot counter (1 on first boot).
    pub fn next_boot(&mut self) -> Result<u32, StoreError> {
        let previous = match self.fetch_raw(Key::BootCount)? {
            Some(&[a, b, c, d]) => u32::from_le_bytes([a, b, c, d]),
            Some(_) => return Err(StoreError::BadBlob),
            None => 0,
        };
        let boot = previous.saturating_add(1);
        self.store_raw(Key::BootCount, &boot.to_le_bytes())?;
        Ok(boot)
    }

    /// Appends an event; when the log is full the oldest events are dropped.
    pub fn append_event(&mut self, event: &EventRecord) -> Result<(), StoreError> {
        let range = self.layout.events.clone();
        let flash = &mut self.flash;
        let bytes = event.encode();
        run(async move { queue::push(flash, range, &mut NoCache::new(), &bytes, true).await })?
            .map_err(map_err)
    }

    /// Calls `each` with every stored event, oldest first; returns how many.
    /// A record whose CRC passed but that does not decode (an unknown kind,
    /// written by a newer firmware) is skipped and not counted.
    pub fn for_each_event(
        &mut self,
        mut each: impl FnMut(EventRecord),
    ) -> Result<usize, StoreError> {
        let range = self.layout.events.clone();
        let (flash, buf) = (&mut self.flash, &mut self.buf);
        run(async move {
            let mut cache = NoCache::new();
            let mut it = queue::iter(flash, range, &mut cache)
                .await
                .map_err(map_err)?;
            let mut n = 0;
            for _ in 0..MAX_EVENTS {
                let Some(entry) = it.next(buf).await.map_err(map_err)? else {
                    break;
                };
                if entry.len() == RECORD_LEN {
                    if let Some(record) = EventRecord::decode(&entry) {
                        each(record);
                        n += 1;
                    }
                }
            }
            Ok(n)
        })?
    }
}
