//! defmt transport for the QEMU build: frames go to the host's stderr through
//! semihosting. stdout is kept for the replay's text, which must match
//! `crane-sim replay` byte for byte. With the default `DEFMT_LOG=error` nothing
//! is emitted unless something goes wrong; decode with
//! `defmt-print -e target/thumbv7em-none-eabihf/release/firmware < stderr.bin`.
#![allow(unsafe_code)] // defmt's `Logger` is an unsafe trait; see the SAFETY notes.

use core::sync::atomic::{AtomicBool, AtomicIsize, Ordering};
use cortex_m_semihosting::{nr, syscall};

#[defmt::global_logger]
struct Logger;

static TAKEN: AtomicBool = AtomicBool::new(false);
static HANDLE: AtomicIsize = AtomicIsize::new(-1);
static mut RESTORE: critical_section::RestoreState = critical_section::RestoreState::invalid();
static mut ENCODER: defmt::Encoder = defmt::Encoder::new();

fn write_frame_bytes(bytes: &[u8]) {
    let mut handle = HANDLE.load(Ordering::Relaxed);
    if handle < 0 {
        const TT: &[u8] = b":tt\0";
        // SAFETY: SYS_OPEN reads the NUL-terminated name ":tt"; mode "a" is stderr.
        handle = unsafe { syscall!(OPEN, TT.as_ptr(), nr::open::W_APPEND, TT.len() - 1) } as isize;
        HANDLE.store(handle, Ordering::Relaxed);
    }
    if handle >= 0 {
        // SAFETY: SYS_WRITE reads `bytes.len()` bytes from `bytes`.
        unsafe {
            syscall!(WRITE, handle as usize, bytes.as_ptr(), bytes.len());
        }
    }
}

// SAFETY: `acquire` takes a critical section (single core: interrupts off) and
// refuses re-entry, so `ENCODER` and `RESTORE` are only touched by one context
// between `acquire` and `release`, as the `Logger` contract requires.
unsafe impl defmt::Logger for Logger {
    fn acquire() {
        // SAFETY: paired with `critical_section::release` in `release`.
        let restore = unsafe { critical_section::acquire() };
        if TAKEN.swap(true, Ordering::Relaxed) {
            // Re-entrant logging (from a panic inside the logger): drop the frame.
            // SAFETY: releases the section acquired just above.
            unsafe { critical_section::release(restore) };
            return;
        }
        // SAFETY: inside the critical section, no other access (see above).
        unsafe {
            RESTORE = restore;
            (*core::ptr::addr_of_mut!(ENCODER)).start_frame(write_frame_bytes);
        }
    }

    unsafe fn flush() {}

    unsafe fn release() {
        // SAFETY: called after `acquire` in the same critical section.
        unsafe {
            (*core::ptr::addr_of_mut!(ENCODER)).end_frame(write_frame_bytes);
            TAKEN.store(false, Ordering::Relaxed);
            critical_section::release(RESTORE);
        }
    }

    unsafe fn write(bytes: &[u8]) {
        // SAFETY: called between `acquire` and `release`.
        unsafe { (*core::ptr::addr_of_mut!(ENCODER)).write(bytes, write_frame_bytes) }
    }
}
