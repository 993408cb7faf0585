//! Utilization → NORMAL / WARNING / OVERLOAD / FAULT, with hysteresis and
//! debounce (SPEC §4.5).
//!
//! Three independent latches, combined by precedence
//! FAULT > OVERLOAD > WARNING > NORMAL:
//!
//! | latch | sets when | for at least | clears when | for at least |
//! |---|---|---|---|---|
//! | warning | u ≥ 0.90 | 0.05 s | u < 0.85 | 0.3 s |
//! | overload | u ≥ 1.00 | 0.05 s | u < 0.95 | 0.5 s |
//! | fault | any fault in the cycle | 0 (first bad cycle) | no fault | 1.0 s |
//!
//! (defaults of [`Thresholds::standard`]). "For at least" is measured from the
//! first cycle in which the condition holds, so at 100 Hz the overload latch
//! sets on the 6th consecutive cycle with u ≥ 1, 50 ms after the first.
//! Faults have no debounce: one bad reading cuts (fail-safe). The overload
//! latch also sets the warning latch, so leaving OVERLOAD passes through
//! WARNING unless the load is already below 0.85. The utilization latches
//! hold their value while a fault makes u unknown, so a fault cannot be used
//! to skip the overload hysteresis. A provisional utilization
//! ([`CycleInput::Provisional`]: a load swinging at rest that the limiter
//! cannot weigh yet, [`crate::static_load`]) sets the latches but does not
//! clear the overload latch.
//!
//! Outputs per state: NORMAL nothing; WARNING the amber lamp; OVERLOAD and
//! FAULT lamp, alarm, and cut of boom-down and hoist-up
//! ([`OutputCommand::FAIL_SAFE`]).

use crane_model::Real;

use crate::io::OutputCommand;

/// The limiter's state as seen by the operator and in logs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum LimiterState {
    /// Below the warning threshold.
    Normal,
    /// Near the rated load: warning lamp.
    Warning,
    /// At or above the rated load: alarm and cut-off.
    Overload,
    /// A sensor, the model or the outputs failed: alarm and cut-off.
    Fault,
}

impl LimiterState {
    /// Upper-case name used by the CLI and the JSON summary.
    pub fn as_str(self) -> &'static str {
        match self {
            LimiterState::Normal => "NORMAL",
            LimiterState::Warning => "WARNING",
            LimiterState::Overload => "OVERLOAD",
            LimiterState::Fault => "FAULT",
        }
    }

    /// The outputs commanded in this state.
    pub fn command(self) -> OutputCommand {
        match self {
            LimiterState::Normal => OutputCommand::default(),
            LimiterState::Warning => OutputCommand {
                warning_lamp: true,
                ..OutputCommand::default()
            },
            LimiterState::Overload | LimiterState::Fault => OutputCommand::FAIL_SAFE,
        }
    }

    /// `true` for the states that cut the moment-increasing motions.
    pub fn cuts(self) -> bool {
        matches!(self, LimiterState::Overload | LimiterState::Fault)
    }
}

/// Thresholds (utilization fractions) and times (s) of the state machine.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thresholds<T> {
    /// u at or above which the warning latch sets.
    pub warning_enter: T,
    /// u below which the warning latch clears.
    pub warning_exit: T,
    /// u at or above which the overload latch sets.
    pub overload_enter: T,
    /// u below which the overload latch clears.
    pub overload_exit: T,
    /// Debounce of the warning and overload latches (s).
    pub enter_debounce_s: T,
    /// Time u must stay below `warning_exit` to clear the warning (s).
    pub warning_exit_s: T,
    /// Time u must stay below `overload_exit` to clear the overload (s).
    pub overload_exit_s: T,
    /// Time without any fault before FAULT clears (s).
    pub fault_recovery_s: T,
}

impl<T: Real> Thresholds<T> {
    /// The defaults in the module doc.
    pub fn standard() -> Self {
        Self {
            warning_enter: T::lit(0.90),
            warning_exit: T::lit(0.85),
            overload_enter: T::lit(1.00),
            overload_exit: T::lit(0.95),
            enter_debounce_s: T::lit(0.05),
            warning_exit_s: T::lit(0.3),
            overload_exit_s: T::lit(0.5),
            fault_recovery_s: T::lit(1.0),
        }
    }

    /// `true` when exit < enter for both latches, warning ≤ overload, and all
    /// times are finite and not negative.
    pub fn is_valid(&self) -> bool {
        let time_ok = |t: T| t.is_finite() && t >= T::lit(0.0);
        self.warning_exit.is_finite()
            && self.warning_exit < self.warning_enter
            && self.warning_enter <= self.overload_enter
            && self.overload_exit < self.overload_enter
            && self.overload_enter.is_finite()
            && time_ok(self.enter_debounce_s)
            && time_ok(self.warning_exit_s)
            && time_ok(self.overload_exit_s)
            && time_ok(self.fault_recovery_s)
    }
}

/// Rounding allowance when comparing accumulated times (s).
const TIME_EPS_S: f64 = 1e-6;

/// A boolean that sets and clears only after its condition held for a time.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Latch<T> {
    active: bool,
    /// How long the condition to switch has held, `None` if it does not hold.
    held_s: Option<T>,
}

impl<T: Real> Latch<T> {
    const fn new(active: bool) -> Self {
        Self {
            active,
            held_s: None,
        }
    }

    /// Advances by one cycle `dt_s` long in which the condition to switch
    /// (set when inactive, clear when active) is `switch`.
    fn update(&mut self, switch: bool, dt_s: T, needed_s: T) {
        if !switch {
            self.held_s = None;
            return;
        }
        let held = match self.held_s {
            None => T::lit(0.0),
            Some(h) => h + dt_s,
        };
        if held + T::lit(TIME_EPS_S) >= needed_s {
            self.active = !self.active;
            self.held_s = None;
        } else {
            self.held_s = Some(held);
        }
    }
}

/// What one cycle tells the state machine.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CycleInput<T> {
    /// Readings were good; the utilization (W_est / W_rated).
    Utilization(T),
    /// Readings were good, but the utilization is not yet a weighing the
    /// limiter stands by (a load swinging at rest after a move, which no
    /// rope of the bank follows: [`crate::static_load::StaticLoad::provisional`]).
    /// It sets both latches as [`CycleInput::Utilization`] does and may
    /// clear the warning latch, but never the overload latch.
    Provisional(T),
    /// Something failed this cycle.
    Fault,
}

/// The state machine.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StateMachine<T> {
    thresholds: Thresholds<T>,
    warning: Latch<T>,
    overload: Latch<T>,
    fault: Latch<T>,
}

impl<T: Real> StateMachine<T> {
    /// A state machine in NORMAL with no history. (The limiter reports FAULT
    /// until its first cycle, the power-up self-test, has run.)
    pub fn new(thresholds: Thresholds<T>) -> Self {
        Self {
            thresholds,
            warning: Latch::new(false),
            overload: Latch::new(false),
            fault: Latch::new(false),
        }
    }

    /// The present state.
    pub fn state(&self) -> LimiterState {
        if self.fault.active {
            LimiterState::Fault
        } else if self.overload.active {
            LimiterState::Overload
        } else if self.warning.active {
            LimiterState::Warning
        } else {
            LimiterState::Normal
        }
    }

    /// Advances by one cycle, `dt_s` after the previous one.
    pub fn update(&mut self, dt_s: T, input: CycleInput<T>) -> LimiterState {
        let th = self.thresholds;
        match input {
            CycleInput::Fault => {
                // A fault sets at once and restarts the recovery time.
                self.fault.active = true;
                self.fault.held_s = None;
            }
            CycleInput::Utilization(u) | CycleInput::Provisional(u) => {
                if self.fault.active {
                    self.fault.update(true, dt_s, th.fault_recovery_s);
                }
                let firm = matches!(input, CycleInput::Utilization(_));
                let o_switch = if self.overload.active {
                    firm && u < th.overload_exit
                } else {
                    u >= th.overload_enter
                };
                self.overload.update(
                    o_switch,
                    dt_s,
                    if self.overload.active {
                        th.overload_exit_s
                    } else {
                        th.enter_debounce_s
                    },
                );
                let w_switch = if self.warning.active {
                    u < th.warning_exit
                } else {
                    u >= th.warning_enter
                };
                self.warning.update(
                    w_switch,
                    dt_s,
                    if self.warning.active {
                        th.warning_exit_s
                    } else {
                        th.enter_debounce_s
                    },
                );
                if self.overload.active {
                    self.warning = Latch::new(true);
                }
            }
        }
        self.state()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(sm: &mut StateMachine<f64>, u: f64, cycles: usize) -> LimiterState {
        let mut s = sm.state();
        for _ in 0..cycles {
            s = sm.update(0.01, CycleInput::Utilization(u));
        }
        s
    }

    #[test]
    fn overload_debounce_and_hysteresis() {
        let mut sm = StateMachine::new(Thresholds::standard());
        assert_eq!(run(&mut sm, 0.5, 10), LimiterState::Normal);
        assert_eq!(run(&mut sm, 1.01, 5), LimiterState::Normal); // 40 ms held
        assert_eq!(run(&mut sm, 1.01, 1), LimiterState::Overload); // 50 ms held
                                                                   // 0.96 is below 1.0 but above the 0.95 exit: stays.
        assert_eq!(run(&mut sm, 0.96, 500), LimiterState::Overload);
        assert_eq!(run(&mut sm, 0.94, 50), LimiterState::Overload); // 0.49 s
        assert_eq!(run(&mut sm, 0.94, 1), LimiterState::Warning); // 0.50 s
        assert_eq!(run(&mut sm, 0.5, 30), LimiterState::Warning);
        assert_eq!(run(&mut sm, 0.5, 1), LimiterState::Normal);
    }

    #[test]
    fn a_provisional_reading_sets_an_overload_but_does_not_clear_it() {
        let mut sm = StateMachine::new(Thresholds::standard());
        let mut run_p = |u: f64, n: usize| {
            let mut s = LimiterState::Normal;
            for _ in 0..n {
                s = sm.update(0.01, CycleInput::Provisional(u));
            }
            s
        };
        assert_eq!(run_p(0.5, 10), LimiterState::Normal);
        assert_eq!(run_p(1.01, 6), LimiterState::Overload);
        // Far below the exit for 10 s: still cut.
        assert_eq!(run_p(0.3, 1000), LimiterState::Overload);
        // A firm reading below the exit clears it as ever (after 0.5 s),
        // through WARNING.
        assert_eq!(run(&mut sm, 0.3, 50), LimiterState::Overload);
        assert_eq!(run(&mut sm, 0.3, 1), LimiterState::Warning);
        assert_eq!(run(&mut sm, 0.3, 30), LimiterState::Normal);
        // Without an overload, the warning comes and goes on it.
        let mut sm = StateMachine::new(Thresholds::standard());
        for _ in 0..6 {
            sm.update(0.01, CycleInput::Provisional(0.92));
        }
        assert_eq!(sm.state(), LimiterState::Warning);
        for _ in 0..31 {
            sm.update(0.01, CycleInput::Provisional(0.5));
        }
        assert_eq!(sm.state(), LimiterState::Normal);
    }

    #[test]
    fn fault_is_immediate_and_recovers_after_the_documented_time() {
        let mut sm = StateMachine::new(Thresholds::standard());
        run(&mut sm, 0.5, 10);
        assert_eq!(sm.update(0.01, CycleInput::Fault), LimiterState::Fault);
        assert_eq!(run(&mut sm, 0.5, 100), LimiterState::Fault); // 0.99 s clean
        assert_eq!(run(&mut sm, 0.5, 1), LimiterState::Normal); // 1.00 s clean
    }

    #[test]
    fn a_fault_does_not_skip_the_overload_hysteresis() {
        let mut sm = StateMachine::new(Thresholds::standard());
        run(&mut sm, 1.1, 10);
        assert_eq!(sm.update(0.01, CycleInput::Fault), LimiterState::Fault);
        // 0.97 ≥ 0.95: after the fault clears the overload is still latched.
        assert_eq!(run(&mut sm, 0.97, 101), LimiterState::Overload);
    }
}
