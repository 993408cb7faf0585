//! Measurements for the budgets (scripts/firmware-budgets.sh): peak stack from
//! cortex-m-rt's `paint-stack`, and instructions per control cycle from SysTick
//! under `qemu-system-arm -icount shift=0` (DWT CYCCNT reads 0 under QEMU; with
//! `-icount` QEMU's virtual clock advances one tick per instruction, and SysTick,
//! clocked by the core, counts it). On a real chip the same code counts core
//! clock cycles instead.
#![allow(unsafe_code)] // Reads the linker's stack symbols and scans painted RAM (see SAFETY notes).

use cortex_m::peripheral::{syst::SystClkSource, SYST};

const RELOAD: u32 = 0x00FF_FFFF;

/// A SysTick-based counter of instructions (QEMU `-icount shift=0`) or cycles.
pub struct CycleCounter {
    syst: SYST,
}

impl CycleCounter {
    /// Starts SysTick free-running over its full 24-bit range and waits for its
    /// first reload (QEMU starts counting from the reload value only then).
    pub fn start(mut syst: SYST) -> Self {
        syst.disable_interrupt();
        syst.set_clock_source(SystClkSource::Core);
        syst.set_reload(RELOAD);
        syst.clear_current();
        syst.enable_counter();
        // At most one full period; bounded so a QEMU without SysTick cannot hang us.
        let mut spins = 0u32;
        while !syst.has_wrapped() && spins < 100_000_000 {
            spins += 1;
        }
        CycleCounter { syst }
    }

    /// Runs `f` and returns its result and the ticks it took (one wrap at most is
    /// accounted for: enough for up to 16.7 M instructions).
    #[inline(always)]
    pub fn measure<R>(&mut self, f: impl FnOnce() -> R) -> (R, u32) {
        let _ = self.syst.has_wrapped(); // clears COUNTFLAG
        let t0 = SYST::get_current();
        let r = f();
        let t1 = SYST::get_current();
        let wrapped = self.syst.has_wrapped();
        let ticks = if wrapped {
            t0 + (RELOAD + 1 - t1)
        } else {
            t0.wrapping_sub(t1)
        };
        (r, ticks)
    }
}

/// Statistics of per-cycle counts.
#[derive(Debug, Default, Clone, Copy)]
pub struct CycleStats {
    /// Number of cycles measured.
    pub count: u32,
    /// Largest count.
    pub max: u32,
    /// Sum of all counts (for the mean).
    pub total: u64,
}

impl CycleStats {
    /// Adds one measurement.
    pub fn add(&mut self, ticks: u32) {
        self.count += 1;
        self.max = self.max.max(ticks);
        self.total += u64::from(ticks);
    }

    /// Mean count, 0 if nothing was measured.
    pub fn mean(&self) -> u64 {
        if self.count == 0 {
            0
        } else {
            self.total / u64::from(self.count)
        }
    }
}

extern "C" {
    static _stack_start: u32;
    static _stack_end: u32;
}

/// The stack region: (lowest address, size in bytes).
pub fn stack_region() -> (usize, usize) {
    // Only the addresses of the linker-defined symbols are taken (no read).
    let (top, bottom) = (
        core::ptr::addr_of!(_stack_start) as usize,
        core::ptr::addr_of!(_stack_end) as usize,
    );
    (bottom, top - bottom)
}

/// Peak stack use in bytes since reset: the stack region was painted with
/// `STACK_PAINT_VALUE` by cortex-m-rt; the first word from the bottom that is no
/// longer painted marks the deepest point the stack reached.
pub fn peak_stack_bytes() -> usize {
    let (bottom, size) = stack_region();
    let words = size / 4;
    let mut untouched = 0;
    while untouched < words {
        // SAFETY: the address lies inside the stack region [_stack_end,
        // _stack_start), RAM that is always mapped and word aligned; the words
        // scanned here are below the current stack pointer (not in use), and a
        // volatile read does not let the compiler assume anything about them.
        let word = unsafe { core::ptr::read_volatile((bottom + untouched * 4) as *const u32) };
        if word != cortex_m_rt::STACK_PAINT_VALUE {
            break;
        }
        untouched += 1;
    }
    size - untouched * 4
}
