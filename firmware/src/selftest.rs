//! The power-up self-test, run while the outputs are cut; the limiter is not
//! started unless every check passes.
//!
//! Checks common to both builds (this module):
//! 1. **RAM**: a March C- test (⇕w0; ⇑r0,w1; ⇑r1,w0; ⇓r0,w1; ⇓r1,w0; ⇕r0 with
//!    all-zero and all-one words: stuck-at, transition, address-decoder and
//!    inter-word coupling faults) over all the RAM between the end of the
//!    static data (`_stack_end`) and 1 KiB below the current stack pointer:
//!    the stack's unused part, ~110 KiB of the 128 KiB. Static data and the top
//!    of the stack in use are not tested.
//! 2. **Image**: the CRC-32 of the flash image against the stamp written after
//!    linking (`limiter_storage::image`, `stamp-image`).
//! 3. **Model**: the crane model the limiter uses, evaluated at reference
//!    points and compared with values computed on the host
//!    (`model_reference.rs`).
//!
//! The board adds output readback and sensor plausibility (`board.rs`).
//! The duration is measured with SysTick (core clock cycles on the board;
//! under `qemu-system-arm -icount shift=0`, converted to instructions by
//! `scripts/firmware-budgets.sh`).
#![allow(unsafe_code)] // Raw RAM and flash access for the March test and the image CRC.

use core::fmt;
use cortex_m::peripheral::{syst::SystClkSource, SYST};
use limiter_storage::image::{self, ImageError, STAMP_LEN};

/// The image checksum stamp, filled in by `stamp-image` after linking.
#[used]
#[link_section = ".rodata.image_stamp"]
static IMAGE_STAMP: [u8; STAMP_LEN] = image::UNSTAMPED_STAMP;

extern "C" {
    static _stack_end: u32;
    static _flash_image_start: u8;
    static _flash_image_end: u8;
}

/// Which check failed (codes as in the event log: `EventKind::SelfTestFailed`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "qemu", allow(dead_code))] // outputs and sensors: board only
pub enum Failure {
    /// RAM word at this address failed the March test.
    Ram {
        /// Address of the failing word (0: no region to test).
        address: u32,
    },
    /// The image checksum check failed.
    Image(ImageError),
    /// The model disagrees with the reference at this point.
    Model {
        /// Index into `model_reference::REFERENCE`.
        point: u32,
    },
    /// An output pin reads back other than commanded (board).
    Outputs {
        /// GPIO bits that differ.
        mismatch: u32,
    },
    /// A sensor's first reading is out of range or unreadable (board).
    Sensors {
        /// Channel number (0 p1, 1 p2, 2 boom angle).
        channel: u8,
    },
}

#[cfg_attr(feature = "qemu", allow(dead_code))] // the board's event log and defmt
impl Failure {
    /// One-byte code for the event log.
    pub fn code(&self) -> u8 {
        match self {
            Failure::Ram { .. } => 1,
            Failure::Image(_) => 2,
            Failure::Model { .. } => 3,
            Failure::Outputs { .. } => 4,
            Failure::Sensors { .. } => 5,
        }
    }

    /// The failure's detail as a number (address, CRC computed, point, pins,
    /// channel), for logs without `core::fmt`.
    pub fn detail(&self) -> u32 {
        match *self {
            Failure::Ram { address } => address,
            Failure::Image(ImageError::Mismatch { computed, .. }) => computed,
            Failure::Image(ImageError::BadLength { length }) => length,
            Failure::Image(_) => 0,
            Failure::Model { point } => point,
            Failure::Outputs { mismatch } => mismatch,
            Failure::Sensors { channel } => u32::from(channel),
        }
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::Ram { address } => write!(f, "RAM: March C- failed at 0x{address:08x}"),
            Failure::Image(e) => write!(f, "image: {e}"),
            Failure::Model { point } => {
                write!(f, "model: disagrees with its reference at point {point}")
            }
            Failure::Outputs { mismatch } => {
                write!(f, "outputs: pins 0x{mismatch:x} read back wrong")
            }
            Failure::Sensors { channel } => {
                write!(f, "sensors: channel {channel} implausible at power-up")
            }
        }
    }
}

/// The image check's outcome when it did not fail.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageStatus {
    /// Stamped and verified.
    Verified(image::Verified),
    /// Not stamped: accepted only where the caller allows it (QEMU).
    NotStamped,
}

/// What the common checks found (printed by the QEMU build; the board logs
/// only the duration, to save flash).
#[derive(Debug, Clone, Copy)]
#[cfg_attr(feature = "board", allow(dead_code))]
pub struct Report {
    /// Bytes of RAM March-tested.
    pub ram_bytes: u32,
    /// The image check.
    pub image: ImageStatus,
    /// Model reference points checked.
    pub model_points: u32,
}

/// Runs the common checks. `allow_unstamped`: whether an image without a
/// checksum stamp passes (QEMU development images) or fails (the board).
pub fn run_common(allow_unstamped: bool) -> Result<Report, Failure> {
    let ram_bytes = ram_test()?;
    let image = match check_image() {
        Ok(v) => ImageStatus::Verified(v),
        Err(ImageError::NotStamped) if allow_unstamped => ImageStatus::NotStamped,
        Err(e) => return Err(Failure::Image(e)),
    };
    let model = crate::model::hook_load_model();
    let model_points = crate::model_reference::check(&model)
        .map_err(|i| Failure::Model { point: i as u32 })? as u32;
    Ok(Report {
        ram_bytes,
        image,
        model_points,
    })
}

/// Bytes below the stack pointer left alone (the test's own frames).
const STACK_MARGIN: usize = 1024;

/// What the tested RAM is left holding: the stack paint under QEMU (so the
/// peak-stack measurement stays valid), zero on the board.
#[cfg(feature = "qemu")]
const REFILL: u32 = cortex_m_rt::STACK_PAINT_VALUE;
#[cfg(not(feature = "qemu"))]
const REFILL: u32 = 0;

fn ram_test() -> Result<u32, Failure> {
    let start = core::ptr::addr_of!(_stack_end) as usize;
    let sp = cortex_m::register::msp::read() as usize;
    let end = sp.saturating_sub(STACK_MARGIN) & !3;
    if end <= start {
        return Err(Failure::Ram { address: 0 });
    }
    let words = (end - start) / 4;
    // SAFETY: [start, end) lies between the end of the static data and 1 KiB
    // below the current stack pointer: RAM that nothing uses at this point
    // (no heap; the stack grows down from above `end`, and `march_c_minus`
    // is a leaf needing far less than the margin). It is restored afterwards.
    let r = unsafe { march_c_minus(start as *mut u32, words) };
    r.map(|()| (words * 4) as u32)
        .map_err(|address| Failure::Ram {
            address: address as u32,
        })
}

/// March C- over `words` words from `base`; the address of the first failing
/// word on failure. Leaves the region filled with [`REFILL`].
///
/// # Safety
/// `base..base + words` must be RAM that nothing else uses during the call.
unsafe fn march_c_minus(base: *mut u32, words: usize) -> Result<(), usize> {
    const ZERO: u32 = 0;
    const ONE: u32 = u32::MAX;
    const ANY: u32 = 0; // compare mask: accept any value
    const ALL: u32 = u32::MAX; // compare mask: all bits must match
                               // (ascending, compare mask, expected value, value written)
    const ELEMENTS: [(bool, u32, u32, u32); 6] = [
        (true, ANY, ZERO, ZERO), // ⇕ w0
        (true, ALL, ZERO, ONE),  // ⇑ r0 w1
        (true, ALL, ONE, ZERO),  // ⇑ r1 w0
        (false, ALL, ZERO, ONE), // ⇓ r0 w1
        (false, ALL, ONE, ZERO), // ⇓ r1 w0
        (true, ALL, ZERO, ZERO), // ⇕ r0 (writes back the 0 it read)
    ];
    let mut result = Ok(());
    for (up, mask, expect, write) in ELEMENTS {
        result = march_element(base, words, up, mask, expect, write);
        if result.is_err() {
            break;
        }
    }
    // Restore, whatever the test stopped at.
    let _ = march_element(base, words, true, ANY, 0, REFILL);
    result
}

/// One March element: for each word in the given direction, read and compare
/// the bits of `mask` with `expect`, then write `write`. Branch-free in the
/// loop body so the compiler keeps one small loop.
///
/// # Safety
/// As [`march_c_minus`].
#[inline(never)]
unsafe fn march_element(
    base: *mut u32,
    words: usize,
    up: bool,
    mask: u32,
    expect: u32,
    write: u32,
) -> Result<(), usize> {
    let (first, step): (isize, isize) = if up { (0, 1) } else { (words as isize - 1, -1) };
    for n in 0..words as isize {
        let p = base.offset(first + n * step);
        if (p.read_volatile() ^ expect) & mask != 0 {
            return Err(p as usize);
        }
        p.write_volatile(write);
    }
    Ok(())
}

/// Checks the flash image against its stamp.
pub fn check_image() -> Result<image::Verified, ImageError> {
    let start = core::ptr::addr_of!(_flash_image_start) as usize;
    let end = core::ptr::addr_of!(_flash_image_end) as usize;
    let stamp = core::ptr::addr_of!(IMAGE_STAMP) as usize;
    let offset = stamp.checked_sub(start).ok_or(ImageError::NoStamp)?;
    // SAFETY: [start, end) is the FLASH region of memory.x, always mapped and
    // readable, and never written while the firmware runs from it. The bytes
    // are read through a pointer made from a linker symbol, so the compiler
    // cannot substitute the stamp's compile-time value.
    let flash = unsafe { core::slice::from_raw_parts(start as *const u8, end - start) };
    image::verify(flash, offset)
}

/// SysTick as a stopwatch: core clock cycles (board) or ticks of QEMU's
/// virtual clock (instructions under `-icount shift=0`, about 6 per tick).
pub fn measure<R>(syst: &mut SYST, f: impl FnOnce() -> R) -> (R, u32) {
    const RELOAD: u32 = 0x00FF_FFFF;
    syst.disable_interrupt();
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(RELOAD);
    syst.clear_current();
    syst.enable_counter();
    // QEMU counts from the reload value only after the first wrap; bounded.
    let mut spins = 0u32;
    while !syst.has_wrapped() && spins < 100_000_000 {
        spins += 1;
    }
    let t0 = SYST::get_current();
    let r = f();
    let t1 = SYST::get_current();
    let wrapped = syst.has_wrapped();
    syst.disable_counter();
    // At most one wrap is counted: 16.7 M ticks, far more than the self-test.
    let ticks = if wrapped {
        t0 + (RELOAD + 1 - t1)
    } else {
        t0.wrapping_sub(t1)
    };
    (r, ticks)
}
