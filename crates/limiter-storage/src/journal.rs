//! A power-cut-safe journal of small records on NOR flash, in two banks.
//!
//! The flash range is split into two equal banks (each a whole number of
//! erase pages). One bank is active: the valid bank header with the higher
//! sequence number. Records are only ever appended to it; a record is
//! written body first, header last, so it exists only once it is complete:
//!
//! ```text
//! bank:   [seq u32][!seq u32] record record ... 0xFF...
//! record: [key u8][len u16][check u8] [crc32 u32] [data, padded to 4 bytes]
//!          ^ written last               ^ over key, len and data
//! ```
//!
//! When the active bank is full, or holds the remains of a write that a power
//! cut interrupted, the live records are *compacted* into the other bank:
//! erase it, copy the records to keep (the latest of each key, or the newest
//! half of the log), write its header with the next sequence number *last*.
//! Until that header is complete the old bank stays active and intact; after
//! it, the new bank holds everything. The old bank is left as it is (the next
//! compaction erases it), so nothing is ever erased that is still needed.
//!
//! Every case a power cut can leave is read safely:
//! - cut while writing a record's body: its header is still erased; the
//!   record does not exist, the previous value is read; the bank is marked
//!   dirty (written bytes after the end) and the next append compacts first;
//! - cut while writing a record's header: the check byte does not match (or,
//!   if it does, the body was already complete); a bad header ends the log;
//! - cut while erasing or filling the other bank: its header is erased or
//!   older, the active bank is unchanged;
//! - cut while writing the new bank's header: it does not validate, unless
//!   every byte the bank needs was already written.
//!
//! Bit rot is caught by the record CRC (a bad record is skipped, the previous
//! one of its key is read) and the header checks. All loops are bounded by
//! the bank size.

use crate::crc::Crc32;
use core::ops::Range;
use embedded_storage::nor_flash::NorFlash;

/// The flash operations the journal needs, object-safe so the journal is
/// compiled once (small code) whatever the flash type; every
/// `embedded-storage` [`NorFlash`] is one.
pub trait Flash {
    /// Reads `buf.len()` bytes at offset `at`.
    fn read(&mut self, at: u32, buf: &mut [u8]) -> Result<(), JournalError>;
    /// Programs `buf` at offset `at` (aligned to the write size).
    fn write(&mut self, at: u32, buf: &[u8]) -> Result<(), JournalError>;
    /// Erases the pages of `from..to` (aligned to the erase size).
    fn erase(&mut self, from: u32, to: u32) -> Result<(), JournalError>;
    /// (read size, write size, erase size) in bytes.
    fn geometry(&self) -> (usize, usize, usize);
}

impl<F: NorFlash> Flash for F {
    fn read(&mut self, at: u32, buf: &mut [u8]) -> Result<(), JournalError> {
        embedded_storage::nor_flash::ReadNorFlash::read(self, at, buf)
            .map_err(|_| JournalError::Flash)
    }
    fn write(&mut self, at: u32, buf: &[u8]) -> Result<(), JournalError> {
        NorFlash::write(self, at, buf).map_err(|_| JournalError::Flash)
    }
    fn erase(&mut self, from: u32, to: u32) -> Result<(), JournalError> {
        NorFlash::erase(self, from, to).map_err(|_| JournalError::Flash)
    }
    fn geometry(&self) -> (usize, usize, usize) {
        (F::READ_SIZE, F::WRITE_SIZE, F::ERASE_SIZE)
    }
}

/// Why a journal operation failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JournalError {
    /// The flash driver reported an error.
    Flash,
    /// Written flash without a valid bank header: nothing can be trusted.
    Corrupted,
    /// The record does not fit even in an empty bank, or a buffer is too small.
    TooBig,
    /// The bank is full of records that must be kept.
    Full,
    /// The range or the flash geometry cannot hold two banks.
    Geometry,
    /// The append needs an erase (a full or dirty bank, or no journal yet),
    /// and the caller did not allow one ([`Journal::append_without_erase`]).
    NeedsErase,
}

/// Which records compaction keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Keep {
    /// The latest valid record of each key (a key-value store).
    LatestPerKey,
    /// The newest records filling at most half a bank (a log).
    NewestHalf,
}

/// Keys are 0..MAX_KEYS (a bounded table in compaction).
pub const MAX_KEYS: usize = 8;

const BANK_HEADER: u32 = 8;
const RECORD_HEADER: u32 = 8;
const ERASED: u32 = 0xFFFF_FFFF;
const CHUNK: usize = 64;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Active {
    bank: u32,
    seq: u32,
    /// Offset in the bank of the first free byte.
    end: u32,
    /// Written bytes after `end` (an interrupted write): compact before appending.
    dirty: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Opened {
    Empty,
    Corrupt,
    Active(Active),
}

/// A record found in the active bank.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RecordRef {
    /// Absolute flash offset of the record header.
    pub at: u32,
    /// Its key.
    pub key: u8,
    /// Bytes of data.
    pub len: u16,
}

impl RecordRef {
    fn data_at(&self) -> u32 {
        self.at + RECORD_HEADER
    }
    fn size(&self) -> u32 {
        RECORD_HEADER + pad4(u32::from(self.len))
    }
}

fn pad4(n: u32) -> u32 {
    (n + 3) & !3
}

fn header_word(key: u8, len: u16) -> u32 {
    let [lo, hi] = len.to_le_bytes();
    let check = key ^ lo ^ hi ^ 0xA5;
    u32::from_le_bytes([key, lo, hi, check])
}

fn decode_header(word: u32) -> Option<(u8, u16)> {
    let [key, lo, hi, check] = word.to_le_bytes();
    (check == key ^ lo ^ hi ^ 0xA5).then(|| (key, u16::from_le_bytes([lo, hi])))
}

/// A journal over `range` of a flash device.
#[derive(Debug, Clone)]
pub struct Journal {
    range: Range<u32>,
    keep: Keep,
    state: Option<Opened>,
}

impl Journal {
    /// A journal in `range` (split into two banks), nothing read yet.
    pub const fn new(range: Range<u32>, keep: Keep) -> Self {
        Journal {
            range,
            keep,
            state: None,
        }
    }

    fn bank_len(&self, flash: &dyn Flash) -> Result<u32, JournalError> {
        let len = self
            .range
            .end
            .checked_sub(self.range.start)
            .ok_or(JournalError::Geometry)?;
        let bank = len / 2;
        let (read, write, erase) = flash.geometry();
        let erase = erase as u32;
        let aligned = erase > 0
            && bank >= erase
            && bank % erase == 0
            && self.range.start % erase == 0
            && write > 0
            && read > 0
            && 4 % write == 0
            && 4 % read == 0;
        if aligned {
            Ok(bank)
        } else {
            Err(JournalError::Geometry)
        }
    }

    fn bank_start(&self, flash: &dyn Flash, bank: u32) -> Result<u32, JournalError> {
        Ok(self.range.start + bank * self.bank_len(flash)?)
    }

    fn read_word(flash: &mut dyn Flash, at: u32) -> Result<u32, JournalError> {
        let mut b = [0u8; 4];
        flash.read(at, &mut b)?;
        Ok(u32::from_le_bytes(b))
    }

    fn bank_seq(&self, flash: &mut dyn Flash, bank: u32) -> Result<Option<u32>, JournalError> {
        let at = self.bank_start(flash, bank)?;
        let seq = Self::read_word(flash, at)?;
        let check = Self::read_word(flash, at + 4)?;
        Ok((check == !seq && seq != ERASED).then_some(seq))
    }

    fn erased_from(flash: &mut dyn Flash, from: u32, to: u32) -> Result<bool, JournalError> {
        let mut buf = [0u8; CHUNK];
        let mut at = from;
        while at < to {
            let n = ((to - at) as usize).min(CHUNK);
            let chunk = buf.get_mut(..n).ok_or(JournalError::Flash)?;
            flash.read(at, chunk)?;
            if chunk.iter().any(|&b| b != 0xFF) {
                return Ok(false);
            }
            at += n as u32;
        }
        Ok(true)
    }

    fn open(&mut self, flash: &mut dyn Flash) -> Result<Opened, JournalError> {
        if let Some(s) = self.state {
            return Ok(s);
        }
        let bank_len = self.bank_len(flash)?;
        let seqs = [self.bank_seq(flash, 0)?, self.bank_seq(flash, 1)?];
        let opened = match seqs {
            [None, None] => {
                // No valid bank header. A format cut short (bank erase or
                // header write) leaves no record behind: records are written
                // only under a complete header. Written records without one
                // mean the header itself was damaged.
                let mut empty = true;
                for bank in 0..2 {
                    let at = self.bank_start(flash, bank)? + BANK_HEADER;
                    empty &= Self::erased_from(flash, at, at + 2 * RECORD_HEADER)?;
                }
                if empty {
                    Opened::Empty
                } else {
                    Opened::Corrupt
                }
            }
            [Some(a), Some(b)] if b > a => self.scan_end(flash, 1, b, bank_len)?,
            [Some(a), _] => self.scan_end(flash, 0, a, bank_len)?,
            [None, Some(b)] => self.scan_end(flash, 1, b, bank_len)?,
        };
        self.state = Some(opened);
        Ok(opened)
    }

    fn scan_end(
        &self,
        flash: &mut dyn Flash,
        bank: u32,
        seq: u32,
        bank_len: u32,
    ) -> Result<Opened, JournalError> {
        let start = self.bank_start(flash, bank)?;
        let mut end = BANK_HEADER;
        let mut dirty = false;
        while end + RECORD_HEADER <= bank_len {
            let word = Self::read_word(flash, start + end)?;
            if word == ERASED {
                dirty = !Self::erased_from(flash, start + end, start + bank_len)?;
                break;
            }
            match decode_header(word) {
                Some((_, len)) if end + RECORD_HEADER + pad4(u32::from(len)) <= bank_len => {
                    end += RECORD_HEADER + pad4(u32::from(len));
                }
                _ => {
                    dirty = true;
                    break;
                }
            }
        }
        Ok(Opened::Active(Active {
            bank,
            seq,
            end,
            dirty,
        }))
    }

    /// Calls `each` with every record of the active bank whose header is valid,
    /// oldest first (CRC not yet checked: see [`Journal::crc_ok`]).
    pub fn for_each(
        &mut self,
        flash: &mut dyn Flash,
        mut each: impl FnMut(&mut dyn Flash, RecordRef) -> Result<(), JournalError>,
    ) -> Result<(), JournalError> {
        let active = match self.open(flash)? {
            Opened::Empty => return Ok(()),
            Opened::Corrupt => return Err(JournalError::Corrupted),
            Opened::Active(a) => a,
        };
        let start = self.bank_start(flash, active.bank)?;
        let mut at = BANK_HEADER;
        while at < active.end {
            let word = Self::read_word(flash, start + at)?;
            let (key, len) = decode_header(word).ok_or(JournalError::Corrupted)?;
            let r = RecordRef {
                at: start + at,
                key,
                len,
            };
            each(flash, r)?;
            at += r.size();
        }
        Ok(())
    }

    /// Whether the record's CRC matches its key, length and data.
    pub fn crc_ok(flash: &mut dyn Flash, r: RecordRef) -> Result<bool, JournalError> {
        let stored = Self::read_word(flash, r.at + 4)?;
        let mut crc = Crc32::new();
        let [lo, hi] = r.len.to_le_bytes();
        crc.update(&[r.key, lo, hi]);
        let mut buf = [0u8; CHUNK];
        let mut done = 0u32;
        let len = u32::from(r.len);
        while done < len {
            let n = ((len - done) as usize).min(CHUNK);
            let chunk = buf.get_mut(..n).ok_or(JournalError::Flash)?;
            flash.read(r.data_at() + done, chunk)?;
            crc.update(chunk);
            done += n as u32;
        }
        Ok(crc.finish() == stored)
    }

    /// Reads a record's data into `out` (its length must fit).
    pub fn read_data(
        flash: &mut dyn Flash,
        r: RecordRef,
        out: &mut [u8],
    ) -> Result<usize, JournalError> {
        let n = usize::from(r.len);
        let dst = out.get_mut(..n).ok_or(JournalError::TooBig)?;
        // Read in words: READ_SIZE may be up to 4.
        let whole = n & !3;
        if let Some(head) = dst.get_mut(..whole) {
            flash.read(r.data_at(), head)?;
        }
        if whole < n {
            let mut last = [0u8; 4];
            flash.read(r.data_at() + whole as u32, &mut last)?;
            for (d, s) in dst.iter_mut().skip(whole).zip(last) {
                *d = s;
            }
        }
        Ok(n)
    }

    /// The latest record of `key` whose CRC is good.
    pub fn latest(
        &mut self,
        flash: &mut dyn Flash,
        key: u8,
    ) -> Result<Option<RecordRef>, JournalError> {
        let mut found = None;
        self.for_each(flash, |flash, r| {
            if r.key == key && Self::crc_ok(flash, r)? {
                found = Some(r);
            }
            Ok(())
        })?;
        Ok(found)
    }

    /// Writes a record at `at` (absolute): body first, header last.
    fn write_record(
        flash: &mut dyn Flash,
        at: u32,
        key: u8,
        data: &[u8],
    ) -> Result<(), JournalError> {
        let len = u16::try_from(data.len()).map_err(|_| JournalError::TooBig)?;
        let mut crc = Crc32::new();
        let [lo, hi] = len.to_le_bytes();
        crc.update(&[key, lo, hi]);
        crc.update(data);
        let w = |f: &mut dyn Flash, at: u32, b: &[u8]| f.write(at, b);
        w(flash, at + 4, &crc.finish().to_le_bytes())?;
        let whole = data.len() & !3;
        let (head, tail) = data.split_at(whole);
        if !head.is_empty() {
            w(flash, at + RECORD_HEADER, head)?;
        }
        if !tail.is_empty() {
            let mut last = [0xFFu8; 4];
            for (d, s) in last.iter_mut().zip(tail) {
                *d = *s;
            }
            w(flash, at + RECORD_HEADER + whole as u32, &last)?;
        }
        w(flash, at, &header_word(key, len).to_le_bytes())
    }

    /// Copies record `r` to `at` (absolute), header last.
    fn copy_record(flash: &mut dyn Flash, r: RecordRef, at: u32) -> Result<(), JournalError> {
        let mut buf = [0u8; CHUNK];
        let body = 4 + pad4(u32::from(r.len));
        let mut done = 0;
        while done < body {
            let n = ((body - done) as usize).min(CHUNK);
            let chunk = buf.get_mut(..n).ok_or(JournalError::Flash)?;
            flash.read(r.at + 4 + done, chunk)?;
            flash.write(at + 4 + done, chunk)?;
            done += n as u32;
        }
        flash.write(at, &header_word(r.key, r.len).to_le_bytes())
    }

    fn write_bank_header(
        &self,
        flash: &mut dyn Flash,
        bank: u32,
        seq: u32,
    ) -> Result<(), JournalError> {
        let at = self.bank_start(flash, bank)?;
        let mut h = [0u8; 8];
        crate::put(&mut h, 0, &seq.to_le_bytes());
        crate::put(&mut h, 4, &(!seq).to_le_bytes());
        flash.write(at, &h)
    }

    fn erase_bank(&self, flash: &mut dyn Flash, bank: u32) -> Result<(), JournalError> {
        let at = self.bank_start(flash, bank)?;
        flash.erase(at, at + self.bank_len(flash)?)
    }

    /// Moves the records to keep into the other bank and makes it active.
    fn compact(&mut self, flash: &mut dyn Flash, from: Active) -> Result<Active, JournalError> {
        let bank_len = self.bank_len(flash)?;
        let to = 1 - from.bank;
        let to_start = self.bank_start(flash, to)?;
        self.erase_bank(flash, to)?;
        // Which records to keep.
        let mut latest: [Option<RecordRef>; MAX_KEYS] = [None; MAX_KEYS];
        let mut valid = 0u32;
        let keep = self.keep;
        self.state = Some(Opened::Active(from));
        self.for_each(flash, |flash, r| {
            if Self::crc_ok(flash, r)? {
                valid += 1;
                if let Some(slot) = latest.get_mut(usize::from(r.key)) {
                    *slot = Some(r);
                }
            }
            Ok(())
        })?;
        let mut end = BANK_HEADER;
        match keep {
            Keep::LatestPerKey => {
                for r in latest.into_iter().flatten() {
                    if end + r.size() > bank_len {
                        return Err(JournalError::Full);
                    }
                    Self::copy_record(flash, r, to_start + end)?;
                    end += r.size();
                }
            }
            Keep::NewestHalf => {
                // Records are fixed size in a log; keep as many of the newest as
                // fill half the bank.
                let mut size = 0;
                self.for_each(flash, |_, r| {
                    size = r.size();
                    Ok(())
                })?;
                let room = ((bank_len - BANK_HEADER) / 2)
                    .checked_div(size)
                    .unwrap_or(0);
                let skip = valid.saturating_sub(room);
                let mut index = 0u32;
                self.for_each(flash, |flash, r| {
                    if Self::crc_ok(flash, r)? {
                        if index >= skip && end + r.size() <= bank_len {
                            Self::copy_record(flash, r, to_start + end)?;
                            end += r.size();
                        }
                        index += 1;
                    }
                    Ok(())
                })?;
            }
        }
        let seq = from.seq.checked_add(1).ok_or(JournalError::Full)?;
        self.write_bank_header(flash, to, seq)?;
        Ok(Active {
            bank: to,
            seq,
            end,
            dirty: false,
        })
    }

    /// Appends a record; the previous record of the same key stays readable
    /// until this one is complete.
    pub fn append(
        &mut self,
        flash: &mut dyn Flash,
        key: u8,
        data: &[u8],
    ) -> Result<(), JournalError> {
        self.append_with(flash, key, data, true)
    }

    /// Appends a record only if that needs no erase: only program
    /// operations (tens of µs per word), never a sector erase (which stalls
    /// the CPU for up to 2 s on the STM32F4). `Err(NeedsErase)`, with
    /// nothing written, when the active bank is full, dirty or missing.
    pub fn append_without_erase(
        &mut self,
        flash: &mut dyn Flash,
        key: u8,
        data: &[u8],
    ) -> Result<(), JournalError> {
        self.append_with(flash, key, data, false)
    }

    /// Makes sure `bytes` of records (headers and padding included) can be
    /// appended without an erase: formats an empty or corrupt journal, and
    /// compacts a dirty bank or one with less room. Erases only when needed.
    pub fn reserve(&mut self, flash: &mut dyn Flash, bytes: u32) -> Result<(), JournalError> {
        let bank_len = self.bank_len(flash)?;
        let opened = self.open(flash)?;
        self.state = None;
        let mut active = match opened {
            Opened::Active(a) => a,
            Opened::Empty | Opened::Corrupt => {
                self.erase_bank(flash, 0)?;
                self.write_bank_header(flash, 0, 1)?;
                Active {
                    bank: 0,
                    seq: 1,
                    end: BANK_HEADER,
                    dirty: false,
                }
            }
        };
        if active.dirty || active.end.saturating_add(bytes) > bank_len {
            active = self.compact(flash, active)?;
        }
        self.state = Some(Opened::Active(active));
        Ok(())
    }

    /// Bytes one record of `len` data bytes takes in a bank.
    pub fn record_size(len: usize) -> u32 {
        RECORD_HEADER + pad4(u32::try_from(len).unwrap_or(u32::MAX - 3))
    }

    fn append_with(
        &mut self,
        flash: &mut dyn Flash,
        key: u8,
        data: &[u8],
        may_erase: bool,
    ) -> Result<(), JournalError> {
        if usize::from(key) >= MAX_KEYS {
            return Err(JournalError::TooBig);
        }
        let bank_len = self.bank_len(flash)?;
        let need =
            RECORD_HEADER + pad4(u32::try_from(data.len()).map_err(|_| JournalError::TooBig)?);
        if BANK_HEADER + need > bank_len {
            return Err(JournalError::TooBig);
        }
        // Any failure below leaves the cached state unknown: re-read next time.
        let opened = self.open(flash)?;
        let needs_erase = match opened {
            Opened::Active(a) => a.dirty || a.end + need > bank_len,
            Opened::Empty | Opened::Corrupt => true,
        };
        if needs_erase && !may_erase {
            return Err(JournalError::NeedsErase);
        }
        self.state = None;
        let mut active = match opened {
            Opened::Active(a) => a,
            Opened::Empty | Opened::Corrupt => {
                self.erase_bank(flash, 0)?;
                self.write_bank_header(flash, 0, 1)?;
                Active {
                    bank: 0,
                    seq: 1,
                    end: BANK_HEADER,
                    dirty: false,
                }
            }
        };
        if active.dirty || active.end + need > bank_len {
            active = self.compact(flash, active)?;
            self.state = None;
            if active.end + need > bank_len {
                return Err(JournalError::Full);
            }
        }
        let at = self.bank_start(flash, active.bank)? + active.end;
        Self::write_record(flash, at, key, data)?;
        active.end += need;
        self.state = Some(Opened::Active(active));
        Ok(())
    }
}
