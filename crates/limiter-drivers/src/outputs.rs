//! The alarm lamps and the cut-off relays over four embedded-hal 1.0 output pins.
//!
//! # Fail-safe polarity
//!
//! The two cut-off outputs drive **permit** relays in the hydraulic valve circuit:
//! the boom-down (respectively hoist-up) pilot valve only gets power through the
//! relay's closed contact, so
//!
//! * relay **energised** → motion **allowed**;
//! * relay **de-energised** → motion **cut**.
//!
//! Anything that removes power from the coil (the MCU held in reset, a pin left
//! floating by a watchdog reset, a broken wire, a blown fuse, this driver failing
//! part-way) therefore cuts the moment-increasing motions. `cut_* = true` in an
//! [`OutputCommand`] de-energises the relay.
//!
//! The warning lamp and the overload alarm are energised when on.
//!
//! [`Polarity`] says which pin level energises a coil (a low-side N-MOSFET driver
//! is [`Polarity::ActiveHigh`], the reference board; an inverting stage is
//! [`Polarity::ActiveLow`]). Board designers: put a pull resistor on each driver
//! input so a reset MCU (pins floating) leaves the relays de-energised.
//!
//! # Order of writes and failures
//!
//! [`AlarmOutputs::apply`] first de-energises the relays that must cut, then drives
//! the lamps, and energises a relay (allowing its motion) only last and only if
//! every write before it succeeded. If any pin write fails it makes a best-effort
//! attempt to put every output in the [`OutputCommand::FAIL_SAFE`] state (relays
//! de-energised, lamps on) and returns [`OutputError`]; the limiter then reports a
//! FAULT.

use embedded_hal::digital::OutputPin;
use moment_limiter::io::{OutputCommand, OutputError, Outputs};

/// Which pin level energises the coil or lamp behind a pin.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Polarity {
    /// Pin high energises (non-inverting driver, the reference board).
    #[default]
    ActiveHigh,
    /// Pin low energises (inverting driver).
    ActiveLow,
}

/// The four outputs of the limiter.
#[derive(Debug)]
pub struct AlarmOutputs<WARN, ALARM, DOWN, HOIST> {
    warning_lamp: WARN,
    overload_alarm: ALARM,
    permit_boom_down: DOWN,
    permit_hoist_up: HOIST,
    polarity: Polarity,
}

/// Drives `pin` so that its load is energised (`true`) or not.
fn drive<P: OutputPin>(
    pin: &mut P,
    polarity: Polarity,
    energised: bool,
) -> Result<(), OutputError> {
    let high = match polarity {
        Polarity::ActiveHigh => energised,
        Polarity::ActiveLow => !energised,
    };
    let result = if high { pin.set_high() } else { pin.set_low() };
    result.map_err(|_| OutputError)
}

impl<WARN, ALARM, DOWN, HOIST> AlarmOutputs<WARN, ALARM, DOWN, HOIST>
where
    WARN: OutputPin,
    ALARM: OutputPin,
    DOWN: OutputPin,
    HOIST: OutputPin,
{
    /// Takes the four pins and immediately drives them to
    /// [`OutputCommand::FAIL_SAFE`] (relays de-energised, lamps on): the limiter
    /// allows motion only after its first good cycle.
    pub fn new(
        warning_lamp: WARN,
        overload_alarm: ALARM,
        permit_boom_down: DOWN,
        permit_hoist_up: HOIST,
        polarity: Polarity,
    ) -> Result<Self, (Self, OutputError)> {
        let mut outputs = AlarmOutputs {
            warning_lamp,
            overload_alarm,
            permit_boom_down,
            permit_hoist_up,
            polarity,
        };
        match outputs.apply(OutputCommand::FAIL_SAFE) {
            Ok(()) => Ok(outputs),
            Err(e) => Err((outputs, e)),
        }
    }

    /// Gives the pins back (warning, alarm, permit boom-down, permit hoist-up).
    pub fn release(self) -> (WARN, ALARM, DOWN, HOIST) {
        (
            self.warning_lamp,
            self.overload_alarm,
            self.permit_boom_down,
            self.permit_hoist_up,
        )
    }

    /// Best effort: every output to the fail-safe state, ignoring further errors.
    fn force_fail_safe(&mut self) {
        let p = self.polarity;
        let _ = drive(&mut self.permit_boom_down, p, false);
        let _ = drive(&mut self.permit_hoist_up, p, false);
        let _ = drive(&mut self.overload_alarm, p, true);
        let _ = drive(&mut self.warning_lamp, p, true);
    }

    fn try_apply(&mut self, command: OutputCommand) -> Result<(), OutputError> {
        let p = self.polarity;
        // 1. Cut first: de-energise every relay whose motion must stop.
        if command.cut_boom_down {
            drive(&mut self.permit_boom_down, p, false)?;
        }
        if command.cut_hoist_up {
            drive(&mut self.permit_hoist_up, p, false)?;
        }
        // 2. Lamps.
        drive(&mut self.overload_alarm, p, command.overload_alarm)?;
        drive(&mut self.warning_lamp, p, command.warning_lamp)?;
        // 3. Allow motions last, only when everything above worked.
        if !command.cut_boom_down {
            drive(&mut self.permit_boom_down, p, true)?;
        }
        if !command.cut_hoist_up {
            drive(&mut self.permit_hoist_up, p, true)?;
        }
        Ok(())
    }
}

impl<WARN, ALARM, DOWN, HOIST> Outputs for AlarmOutputs<WARN, ALARM, DOWN, HOIST>
where
    WARN: OutputPin,
    ALARM: OutputPin,
    DOWN: OutputPin,
    HOIST: OutputPin,
{
    fn apply(&mut self, command: OutputCommand) -> Result<(), OutputError> {
        let result = self.try_apply(command);
        if result.is_err() {
            self.force_fail_safe();
        }
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_hal_mock::eh1::digital::{Mock as PinMock, State, Transaction as T};
    use embedded_hal_mock::eh1::MockError;
    use std::io::ErrorKind;

    fn pin(states: &[State]) -> PinMock {
        let t: Vec<T> = states.iter().map(|s| T::set(*s)).collect();
        PinMock::new(&t)
    }

    fn done(outputs: AlarmOutputs<PinMock, PinMock, PinMock, PinMock>) {
        let (mut a, mut b, mut c, mut d) = outputs.release();
        a.done();
        b.done();
        c.done();
        d.done();
    }

    const NORMAL: OutputCommand = OutputCommand {
        warning_lamp: false,
        overload_alarm: false,
        cut_boom_down: false,
        cut_hoist_up: false,
    };

    #[test]
    fn starts_in_fail_safe_then_allows_motion_when_normal() {
        use State::{High, Low};
        let outputs = AlarmOutputs::new(
            pin(&[High, Low]),
            pin(&[High, Low]),
            pin(&[Low, High]),
            pin(&[Low, High]),
            Polarity::ActiveHigh,
        );
        let mut outputs = outputs.map_err(|_| ()).unwrap();
        assert_eq!(outputs.apply(NORMAL), Ok(()));
        done(outputs);
    }

    #[test]
    fn active_low_inverts_every_pin() {
        use State::{High, Low};
        let outputs = AlarmOutputs::new(
            pin(&[Low]),
            pin(&[Low]),
            pin(&[High]),
            pin(&[High]),
            Polarity::ActiveLow,
        );
        done(outputs.map_err(|_| ()).unwrap());
    }

    #[test]
    fn overload_cuts_before_lamps_and_keeps_reducing_motions() {
        use State::{High, Low};
        // FAIL_SAFE at construction, then an overload command.
        let outputs = AlarmOutputs::new(
            pin(&[High, High]),
            pin(&[High, High]),
            pin(&[Low, Low]),
            pin(&[Low, Low]),
            Polarity::ActiveHigh,
        );
        let mut outputs = outputs.map_err(|_| ()).unwrap();
        let overload = OutputCommand {
            warning_lamp: true,
            overload_alarm: true,
            cut_boom_down: true,
            cut_hoist_up: true,
        };
        assert_eq!(outputs.apply(overload), Ok(()));
        done(outputs);
    }

    #[test]
    fn a_failed_lamp_write_never_allows_motion_and_forces_the_cut() {
        use State::{High, Low};
        let outputs = AlarmOutputs::new(
            // FAIL_SAFE, then the forced fail-safe after the error.
            pin(&[High, High]),
            // FAIL_SAFE, then the failing write (Low), then the forced fail-safe.
            PinMock::new(&[
                T::set(High),
                T::set(Low).with_error(MockError::Io(ErrorKind::BrokenPipe)),
                T::set(High),
            ]),
            // FAIL_SAFE, then only the forced fail-safe: never energised.
            pin(&[Low, Low]),
            pin(&[Low, Low]),
            Polarity::ActiveHigh,
        );
        let mut outputs = outputs.map_err(|_| ()).unwrap();
        assert_eq!(outputs.apply(NORMAL), Err(OutputError));
        done(outputs);
    }

    #[test]
    fn a_failed_relay_write_de_energises_both_relays() {
        use State::{High, Low};
        let outputs = AlarmOutputs::new(
            pin(&[High, Low, High]),
            pin(&[High, Low, High]),
            // FAIL_SAFE, energise (allowed) ok, then forced de-energise.
            pin(&[Low, High, Low]),
            // FAIL_SAFE, energise fails, then forced de-energise.
            PinMock::new(&[
                T::set(Low),
                T::set(High).with_error(MockError::Io(ErrorKind::BrokenPipe)),
                T::set(Low),
            ]),
            Polarity::ActiveHigh,
        );
        let mut outputs = outputs.map_err(|_| ()).unwrap();
        assert_eq!(outputs.apply(NORMAL), Err(OutputError));
        done(outputs);
    }
}
