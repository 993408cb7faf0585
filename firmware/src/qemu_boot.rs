//! Start-up of the QEMU build, before the replay: the power-up self-test
//! (RAM, image checksum, model; QEMU has no outputs or sensors to check) with
//! the simulated outputs cut, and the firmware-only test switches.
//!
//! - A failed self-test prints `self-test failed: <check>: <why>` and the
//!   outputs' state on stderr and exits [`EXIT_FAULT`]; the replay never runs.
//! - An image without a checksum stamp (a plain `cargo build`/`cargo run`)
//!   passes here, reported as `image=not-stamped`: development images must
//!   keep running under QEMU. The board refuses it (`board.rs`).
//! - `--self-test` prints `self-test: passed ram=<bytes>B image=<crc32:...|
//!   not-stamped> model=<n>/<n> ticks=<T> image_ticks=<T_crc>
//!   calibration_ticks=<C> calibration_instructions=<I>` on stderr (instructions = T·I/C under
//!   `-icount shift=0`; `scripts/firmware-budgets.sh` does that).
//! - `--trigger-hardfault` energises the simulated permit relays (as a limiter
//!   in NORMAL would), prints them, and executes an undefined instruction: the
//!   HardFault handler must cut the outputs and report them
//!   (`tests/firmware_failsafe.rs`).

use crate::selftest::{self, ImageStatus};
use crate::sim_outputs::{self, SimOutputs};
use core::fmt::Write;
use cortex_m::peripheral::SYST;
use moment_limiter::io::{OutputCommand, Outputs};

/// Exit status of a firmware fault or a failed self-test: 2, the FAULT status
/// of the replay exit codes (the outputs were cut).
pub const EXIT_FAULT: u8 = 2;

/// Loops of the calibration delay (2n + 2 instructions).
const CALIBRATION_LOOPS: u32 = 100_000;

/// Runs the self-test and the test switches; returns only if the replay may run.
pub fn boot(syst: &mut SYST) {
    sim_outputs::cut_now();
    // No reset cause to act on under QEMU (no RCC model, no watchdog); the
    // record is still consumed so the handlers' path is the board's.
    let _ = crate::fault::take_record();

    let mut cmdline_buf = [0u8; 512];
    let cmdline = crate::qemu::semihosting::command_line(&mut cmdline_buf).unwrap_or("");
    let report_wanted = cmdline.split_ascii_whitespace().any(|w| w == "--self-test");
    let hardfault_wanted = cmdline
        .split_ascii_whitespace()
        .any(|w| w == "--trigger-hardfault");

    let (result, ticks) = selftest::measure(syst, || selftest::run_common(true));
    let mut err = crate::qemu::semihosting::HostWriter::stderr();
    let report = match result {
        Ok(report) => report,
        Err(failure) => {
            let _ = write!(err, "self-test failed: {failure}; outputs: ");
            let _ = sim_outputs::describe(&mut err);
            let _ = writeln!(err);
            err.flush();
            crate::qemu::semihosting::exit(EXIT_FAULT)
        }
    };
    if report_wanted {
        let ((), calibration_ticks) =
            selftest::measure(syst, || cortex_m::asm::delay(CALIBRATION_LOOPS));
        // The image CRC alone (again), so the board's duration can be derived
        // from its smaller image.
        let (_, image_ticks) = selftest::measure(syst, selftest::check_image);
        let _ = write!(err, "self-test: passed ram={}B image=", report.ram_bytes);
        let _ = match report.image {
            ImageStatus::Verified(v) => write!(err, "crc32:{:08x}/{}B", v.crc, v.length),
            ImageStatus::NotStamped => write!(err, "not-stamped"),
        };
        let _ = writeln!(
            err,
            " model={}/{} ticks={} image_ticks={} calibration_ticks={} calibration_instructions={}",
            report.model_points,
            crate::model_reference::REFERENCE.len(),
            ticks,
            image_ticks,
            calibration_ticks,
            2 * CALIBRATION_LOOPS + 2
        );
        err.flush();
    }

    if hardfault_wanted {
        let _ = SimOutputs.apply(OutputCommand::default());
        let _ = write!(err, "outputs before the fault: ");
        let _ = sim_outputs::describe(&mut err);
        let _ = writeln!(err);
        err.flush();
        // UsageFault (undefined instruction), escalated to HardFault because
        // the configurable faults are not enabled.
        cortex_m::asm::udf();
    }
}
