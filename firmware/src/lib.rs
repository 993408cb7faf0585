//! # firmware
//!
//! The load moment limiter on an STM32F405RG (Cortex-M4F, 1 MiB flash, 128 KiB
//! RAM), in two builds of this one crate selected by a cargo feature:
//!
//! - `qemu` (default): runs on `qemu-system-arm -machine netduinoplus2` and
//!   replays a sensor log from the host through semihosting, through the same
//!   limiter code, printing what `crane-sim replay` prints ([`qemu`]).
//! - `board`: the real controller: stm32f4xx-hal clocks, the SPI ADC
//!   (`limiter_drivers::Mcp3208`), the four outputs
//!   (`limiter_drivers::AlarmOutputs`), a 100 Hz timer-driven control loop and
//!   the independent watchdog (`board`). Hardware initialisation lives in
//!   `board::init`, separate from the per-cycle logic.
//!
//! Layers, top to bottom: this crate wires hardware and chooses the model
//! ([`model::hook_load_model`], the one seam for the precomputed reduced crane
//! model) → `moment-limiter` (conversion, checks, load estimate, states, replay,
//! formatting) → `crane-model` (`HookLoadModel`) ; `limiter-drivers` implements
//! the limiter's `SensorInputs`/`Outputs` over embedded-hal 1.0.
//!
//! Failing safe: a panic (`panic`) and every fault exception (`fault`) cut the
//! outputs first, record why in RAM that survives the reset, and wait for the
//! watchdog; the board reads the reset cause at start-up and keeps the outputs
//! cut after a fault or watchdog reset until an operator acknowledges
//! (`board`); a power-up self-test (`selftest`) must pass before the limiter
//! runs. No heap anywhere.
//!
//! The crate is this library and two thin binaries that hold only the entry
//! point: `src/bin/qemu.rs` (binary `firmware`, feature `qemu`) and
//! `src/bin/board.rs` (binary `firmware-board`, feature `board`).
//!
//! On a host target (e.g. `cargo check --workspace`) the library is empty and
//! the binaries are stubs that say to build for `thumbv7em-none-eabihf`: the
//! firmware is only meaningful on the MCU, and this keeps workspace-wide host
//! commands working.
#![cfg_attr(target_os = "none", no_std)]
// cortex-m-rt's `#[exception]` expands to `#[export_name]` items, which the
// unsafe_code lint flags; modules that need `unsafe` say why.
#![allow(unsafe_code)]

#[cfg(all(feature = "qemu", feature = "board"))]
compile_error!(
    "choose one of the features `qemu` and `board` (use --no-default-features --features board)"
);
#[cfg(not(any(feature = "qemu", feature = "board")))]
compile_error!("choose one of the features `qemu` (default) and `board`");

#[cfg(target_os = "none")]
use cortex_m as _; // critical-section implementation for defmt

#[cfg(target_os = "none")]
mod fault;
#[cfg(target_os = "none")]
pub mod model;
#[cfg(target_os = "none")]
pub mod model_reference;
#[cfg(target_os = "none")]
mod panic;
#[cfg(target_os = "none")]
mod selftest;

#[cfg(feature = "board")]
#[cfg(target_os = "none")]
pub mod board;
#[cfg(feature = "qemu")]
#[cfg(target_os = "none")]
mod defmt_semihosting;
#[cfg(feature = "qemu")]
#[cfg(target_os = "none")]
pub mod qemu;
#[cfg(feature = "qemu")]
#[cfg(target_os = "none")]
mod sim_outputs;

/// Per-build hooks the panic and fault handlers need.
#[cfg(target_os = "none")]
mod platform {
    #[cfg(feature = "board")]
    pub use crate::board::{cut_outputs_now, halt_after_fault, halt_after_panic};

    /// Under QEMU the outputs are the simulated pins (`sim_outputs`).
    #[cfg(feature = "qemu")]
    pub fn cut_outputs_now() {
        crate::sim_outputs::cut_now();
    }

    /// Under QEMU: report on stderr and exit with status 101.
    #[cfg(feature = "qemu")]
    pub fn halt_after_panic(info: &core::panic::PanicInfo) -> ! {
        use core::fmt::Write;
        let mut err = crate::qemu::semihosting::HostWriter::stderr();
        let _ = writeln!(err, "firmware panicked: {info}");
        err.flush();
        crate::qemu::semihosting::exit(101)
    }

    /// Under QEMU (no watchdog model): report the fault and the outputs' state
    /// on stderr, and exit 2, the FAULT status.
    #[cfg(feature = "qemu")]
    pub fn halt_after_fault(kind: limiter_storage::latch::FaultKind, detail: u32) -> ! {
        use core::fmt::Write;
        let mut err = crate::qemu::semihosting::HostWriter::stderr();
        let _ = write!(
            err,
            "firmware fault: {} (0x{detail:08x}); outputs: ",
            kind.as_str()
        );
        let _ = crate::sim_outputs::describe(&mut err);
        let _ = writeln!(err);
        err.flush();
        crate::qemu::semihosting::exit(crate::qemu_boot::EXIT_FAULT)
    }
}

#[cfg(feature = "qemu")]
#[cfg(target_os = "none")]
pub mod qemu_boot;
