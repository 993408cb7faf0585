//! Every exception that means "the firmware stopped working" cuts the outputs
//! before it does anything else, records why in RAM that survives the reset,
//! then waits for the independent watchdog to reset the MCU.
//!
//! Handlers: `HardFault` (MemManage, BusFault and UsageFault are not enabled
//! in SHCSR, so they escalate to HardFault), `NonMaskableInt`, and
//! `DefaultHandler` (any interrupt or exception without its own handler: none
//! is expected, the control loop polls its timer). The panic handler
//! (`panic.rs`) does the same with [`FaultKind::Panic`].
//!
//! The record is four words in `.uninit` (not zeroed or initialised by
//! cortex-m-rt's start-up code, below the stack): after the watchdog reset the
//! board's start-up reads it with `RCC_CSR` (`limiter_storage::latch::
//! reset_cause`), clears it, and latches the outputs cut until the operator
//! acknowledges. After a power cut RAM is random; the record's magic and check
//! word make a false record practically impossible, and a power-on reset
//! ignores it anyway.
#![allow(unsafe_code)] // Exception handlers, and volatile access to the .uninit record.

use core::mem::MaybeUninit;
use cortex_m_rt::{exception, ExceptionFrame};
use limiter_storage::latch::{FaultKind, FaultRecord};

#[link_section = ".uninit.FAULT_RECORD"]
static mut FAULT_RECORD: MaybeUninit<[u32; 4]> = MaybeUninit::uninit();

fn record_words() -> *mut u32 {
    core::ptr::addr_of_mut!(FAULT_RECORD).cast::<u32>()
}

/// Writes the fault record (called from the handlers, after the cut).
pub fn record(kind: FaultKind, detail: u32) {
    let words = FaultRecord { kind, detail }.encode();
    for (i, w) in words.iter().enumerate() {
        // SAFETY: FAULT_RECORD is four aligned words of RAM owned by this
        // module; `i < 4`. Volatile so the write is not elided before the reset.
        unsafe { core::ptr::write_volatile(record_words().add(i), *w) };
    }
}

/// Reads the record left by the previous run and clears it, so it is used
/// for one reset only.
pub fn take_record() -> [u32; 4] {
    let mut words = [0u32; 4];
    for (i, w) in words.iter_mut().enumerate() {
        // SAFETY: as in `record`; the words may hold any bit pattern (random
        // after power-on), which a u32 can; `FaultRecord::decode` validates it.
        unsafe {
            *w = core::ptr::read_volatile(record_words().add(i));
            core::ptr::write_volatile(record_words().add(i), 0);
        }
    }
    words
}

/// The common path of every fault: cut, record, report, wait for the reset.
fn fail(kind: FaultKind, detail: u32) -> ! {
    cortex_m::interrupt::disable();
    crate::platform::cut_outputs_now();
    record(kind, detail);
    crate::platform::halt_after_fault(kind, detail)
}

/// HardFault: the faulting instruction's address is recorded.
#[exception]
unsafe fn HardFault(frame: &ExceptionFrame) -> ! {
    // The cut comes first; reading the frame afterwards.
    crate::platform::cut_outputs_now();
    fail(FaultKind::HardFault, frame.pc())
}

/// NMI (the clock security system on the STM32F405): no recovery attempted.
#[exception]
unsafe fn NonMaskableInt() {
    crate::platform::cut_outputs_now();
    fail(FaultKind::NonMaskableInt, 0)
}

/// Any exception or interrupt without a handler: none is enabled on purpose.
#[exception]
unsafe fn DefaultHandler(irqn: i16) {
    crate::platform::cut_outputs_now();
    fail(FaultKind::UnexpectedInterrupt, irqn as u32)
}
