//! The panic handler: outputs to the cut-off state first, then report and stop.
//!
//! A panic in the firmware is a bug; the limiter's control path is written not
//! to panic. If one happens anyway the moment-increasing motions must be cut at
//! once: on the board the relay pins are driven to de-energise the permit relays
//! (see `limiter_drivers::outputs`), the alarm is switched on, and the MCU then
//! spins without feeding the independent watchdog, which resets it; during and
//! after the reset the pins float and the relays' pull-downs keep them
//! de-energised (cut). The panic is recorded in the RAM fault record
//! (`fault`), so the next start-up latches the outputs cut until acknowledged.
//! Under QEMU the simulated outputs are cut; the panic is reported on
//! stderr and QEMU exits with status 101 (Rust's panic status).

use core::panic::PanicInfo;

#[panic_handler]
fn panic(info: &PanicInfo) -> ! {
    cortex_m::interrupt::disable();
    crate::platform::cut_outputs_now();
    crate::fault::record(limiter_storage::latch::FaultKind::Panic, 0);
    // The location only: formatting the message needs core::fmt, 2 KB of the
    // board's 64 KiB flash budget. (The QEMU build prints the whole message.)
    match info.location() {
        Some(l) => defmt::error!("panic at {=str}:{=u32}", l.file(), l.line()),
        None => defmt::error!("panic"),
    }
    crate::platform::halt_after_panic(info)
}
