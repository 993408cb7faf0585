//! # limiter-storage
//!
//! What the load moment limiter keeps through a power cut, and how it proves
//! its own image is intact:
//!
//! - [`store`]: the configuration and calibration (opaque, versioned byte blobs
//!   with a CRC-32), the fault latch, and the event log (fixed-size
//!   [`event::EventRecord`]s), on any `embedded-storage` [`NorFlash`], each in
//!   a two-bank [`journal`] whose every update is power-cut safe (an
//!   interrupted write or erase leaves the previous value readable);
//! - [`calibration_blob`]: the calibration's fixed-size binary stored form,
//!   checked against the calibration schema's own bounds on decoding;
//! - [`event_queue`]: the RAM queue of events recorded during operation,
//!   written to flash only while no motion is granted;
//! - [`crc`]: CRC-32 (IEEE 802.3, the zlib one), used for blobs and the image;
//! - [`image`]: the image checksum stamp written after linking
//!   (`stamp-image`, a host tool in this crate) and its verification at power-up;
//! - [`latch`]: reset causes, the fault record the exception handlers leave in
//!   RAM, and the operator's acknowledgement that releases a latched fault.
//!
//! `no_std`, no heap, no panics: every failure is a typed error.
//!
//! [`NorFlash`]: embedded_storage::nor_flash::NorFlash
#![cfg_attr(not(test), no_std)]

pub mod calibration_blob;
pub mod crc;
pub mod event;
pub mod event_queue;
pub mod image;
pub mod journal;
pub mod latch;
pub mod store;

/// Copies `src` into `dst` from index `at`, as far as `dst` reaches: the
/// panic-free `dst[at..at + src.len()].copy_from_slice(src)` (callers pass
/// ranges that fit; nothing here can panic if one did not).
pub(crate) fn put(dst: &mut [u8], at: usize, src: &[u8]) {
    for (d, s) in dst.iter_mut().skip(at).zip(src) {
        *d = *s;
    }
}
