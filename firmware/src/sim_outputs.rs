//! The QEMU build's outputs: QEMU's netduinoplus2 has no GPIO model, so the
//! commanded state of the four outputs is kept in a RAM word instead, written
//! by the same paths that write the GPIO registers on the board (the limiter's
//! `Outputs`, the fault handlers' cut), and read back by the fault report and
//! the tests (`tests/firmware_failsafe.rs`).

use core::fmt::Write;
use core::sync::atomic::{AtomicU8, Ordering};
use moment_limiter::io::{OutputCommand, OutputError, Outputs};

const WARNING: u8 = 1 << 0;
const ALARM: u8 = 1 << 1;
const PERMIT_DOWN: u8 = 1 << 2;
const PERMIT_HOIST: u8 = 1 << 3;

/// The "pins", as on the board: permit bits high = relay energised = motion
/// allowed. Starts at 0: relays de-energised (cut), lamps off, as after reset.
static PINS: AtomicU8 = AtomicU8::new(0);

/// Drives the simulated pins to the cut-off state in one store (the board's
/// single BSRR write): permits de-energised, warning and alarm on.
pub fn cut_now() {
    PINS.store(WARNING | ALARM, Ordering::SeqCst);
}

/// The simulated output pins as the limiter's `Outputs`.
#[derive(Debug, Default)]
pub struct SimOutputs;

impl Outputs for SimOutputs {
    fn apply(&mut self, c: OutputCommand) -> Result<(), OutputError> {
        let mut pins = 0;
        if c.warning_lamp {
            pins |= WARNING;
        }
        if c.overload_alarm {
            pins |= ALARM;
        }
        if !c.cut_boom_down {
            pins |= PERMIT_DOWN;
        }
        if !c.cut_hoist_up {
            pins |= PERMIT_HOIST;
        }
        PINS.store(pins, Ordering::SeqCst);
        Ok(())
    }
}

/// Writes the pins' state as one line fragment, e.g.
/// `permit-boom-down=cut permit-hoist-up=cut warning=on alarm=on`.
pub fn describe(out: &mut impl Write) -> core::fmt::Result {
    let pins = PINS.load(Ordering::SeqCst);
    let relay = |bit| if pins & bit != 0 { "energised" } else { "cut" };
    let lamp = |bit| if pins & bit != 0 { "on" } else { "off" };
    write!(
        out,
        "permit-boom-down={} permit-hoist-up={} warning={} alarm={}",
        relay(PERMIT_DOWN),
        relay(PERMIT_HOIST),
        lamp(WARNING),
        lamp(ALARM)
    )
}
