//! Integer time (SPEC §4.7): the limiter's clock is a wrapping tick count,
//! never an absolute floating-point time.
//!
//! ## Why integers
//!
//! An `f32` absolute time loses its resolution as it grows: after 36 h a
//! 10 ms step is a third of an ULP and one cycle in three sees a zero step; a
//! log shifted by 463 days alarmed 7.6 s later than the same log at t = 0. So
//! time is a [`Ticks`] value (1 tick = 1 µs, a `u32` that wraps every
//! 2³² µs ≈ 71.6 min) and only **differences** are used, taken with
//! `wrapping_sub`: the wrap is harmless, and it happens every 72 minutes in
//! the field, so the code path that crosses it is exercised every hour
//! rather than hidden for a year. Every `f32`/`f64` time step the filters see
//! is computed from that integer difference, so a crane that has run for a
//! year computes exactly what one just switched on computes.
//!
//! ## The rules of the clock (checked each cycle by [`Clock::advance`])
//!
//! Let Δ = now − previous (wrapping, in µs) and P the nominal period
//! ([`ClockConfig::period_us`], 10 ms):
//! - Δ = 0: the clock **stalled** (or the same sample came twice): FAULT.
//! - Δ > [`ClockConfig::max_gap_periods`] × P (5 × 10 ms = 50 ms): a **gap**:
//!   FAULT. The limiter cannot vouch for what it did not see (an overload
//!   may have come and gone, and the filters would jump).
//! - Δ ≥ 2³¹ µs is a clock that went **backwards** (on the board: a counter
//!   that was reset or corrupted): FAULT.
//!
//! After a gap or a backwards step the new time becomes the reference, the
//! signal chain restarts settled on the next good sample, and the state
//! machine's FAULT recovery time (1 s of good cycles) runs as after any fault.
//! The first cycle has no previous time and a step of 0.
//!
//! Recorded logs carry decimal seconds; [`crate::tools::log_format`] converts them to
//! microseconds exactly (from the digits, never through a float) and then to
//! ticks with the same wrapping, so a log replayed with its times shifted by
//! any whole number of microseconds gives the same events at the same samples.

use crane_model::Real;

/// Ticks per second: 1 tick = 1 µs.
pub const TICKS_PER_SECOND: u32 = 1_000_000;

/// Steps of 2³¹ µs (35.8 min) or more are read as the clock going backwards.
pub const BACKWARDS_FROM_US: u32 = 1 << 31;

/// A point in time on the limiter's wrapping microsecond clock.
///
/// Only differences ([`Ticks::since`]) mean anything; the absolute value
/// wraps every 2³² µs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Ticks(pub u32);

impl Ticks {
    /// The tick `us` microseconds after tick 0 (wrapping).
    pub const fn from_micros(us: u32) -> Self {
        Ticks(us)
    }

    /// The tick `ms` milliseconds after tick 0 (wrapping).
    pub const fn from_millis(ms: u32) -> Self {
        Ticks(ms.wrapping_mul(1000))
    }

    /// The tick of control cycle `n` for a period of `period_us` (wrapping):
    /// what the board passes each cycle.
    pub const fn from_cycle(n: u32, period_us: u32) -> Self {
        Ticks(n.wrapping_mul(period_us))
    }

    /// The raw microsecond count (wrapping).
    pub const fn micros(self) -> u32 {
        self.0
    }

    /// This tick plus `us` microseconds (wrapping).
    pub const fn wrapping_add_micros(self, us: u32) -> Self {
        Ticks(self.0.wrapping_add(us))
    }

    /// Microseconds from `earlier` to `self`, wrap-safe.
    pub const fn since(self, earlier: Ticks) -> u32 {
        self.0.wrapping_sub(earlier.0)
    }
}

/// What is wrong with the time of a cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ClockFault {
    /// The time did not advance (Δ = 0).
    Stalled,
    /// The time advanced by more than the allowed gap (µs, < 2³¹).
    Gap {
        /// The step (µs).
        elapsed_us: u32,
    },
    /// The time went backwards (Δ ≥ 2³¹ µs, wrapping).
    Backwards,
}

impl ClockFault {
    /// The time that passed (s): a gap's step; none for a stalled clock or
    /// one that went backwards, whose step cannot be told.
    pub fn elapsed_s<T: Real>(&self) -> T {
        match self {
            ClockFault::Gap { elapsed_us } => micros_as_seconds(*elapsed_us),
            ClockFault::Stalled | ClockFault::Backwards => T::lit(0.0),
        }
    }
}

impl core::fmt::Display for ClockFault {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            ClockFault::Stalled => f.write_str("clock stalled (time did not advance)"),
            ClockFault::Gap { elapsed_us } => {
                write!(f, "time gap of ")?;
                write_micros_as_seconds(f, i64::from(*elapsed_us))?;
                // The longest step the clock can tell (a log's longer gaps
                // are handed over as this one, see `log_format`).
                f.write_str(if *elapsed_us >= BACKWARDS_FROM_US - 1 {
                    " s or more"
                } else {
                    " s"
                })
            }
            ClockFault::Backwards => f.write_str("clock went backwards"),
        }
    }
}

/// Writes a signed microsecond count as seconds with 3 decimals, rounded to
/// the nearest millisecond (halves away from zero), from integers only.
pub fn write_micros_as_seconds<W: core::fmt::Write>(w: &mut W, us: i64) -> core::fmt::Result {
    let magnitude = us.unsigned_abs().saturating_add(500) / 1000;
    let sign = if us < 0 && magnitude > 0 { "-" } else { "" };
    write!(w, "{sign}{}.{:03}", magnitude / 1000, magnitude % 1000)
}

/// `us` microseconds in seconds: integer to float on the FPU, then one
/// correctly rounded division (no f64: soft float on the controller).
fn micros_as_seconds<T: Real>(us: u32) -> T {
    T::from_count(us) / T::from_count(TICKS_PER_SECOND)
}

/// The clock's rules (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ClockConfig {
    /// Nominal control period (µs): 10 000 (100 Hz).
    pub period_us: u32,
    /// Longest allowed step, in periods: 5 (50 ms at 100 Hz).
    pub max_gap_periods: u32,
}

impl ClockConfig {
    /// 100 Hz, gaps of more than 5 periods (50 ms) are faults.
    pub const fn standard() -> Self {
        Self {
            period_us: 10_000,
            max_gap_periods: 5,
        }
    }

    /// The nominal period in seconds, converted as [`Clock::advance`]
    /// converts a step, so a step of one period is this value exactly.
    pub fn period_s<T: Real>(&self) -> T {
        micros_as_seconds(self.period_us)
    }

    /// Longest allowed step (µs), or `None` if it does not fit the clock.
    pub const fn max_gap_us(&self) -> Option<u32> {
        self.period_us.checked_mul(self.max_gap_periods)
    }

    /// `true` when the period is positive and the longest step is at least
    /// one period and shorter than 2³¹ µs.
    pub fn is_valid(&self) -> bool {
        self.period_us > 0
            && self.max_gap_periods >= 1
            && self.max_gap_us().is_some_and(|g| g < BACKWARDS_FROM_US)
    }
}

/// The limiter's clock: the previous time, and the last step in seconds
/// (cached: it is converted to a float only when the step changes, which on
/// the board is once).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clock<T> {
    config: ClockConfig,
    last: Option<Ticks>,
    step: (u32, T),
}

impl<T: Real> Clock<T> {
    /// A clock before its first cycle.
    pub fn new(config: ClockConfig) -> Self {
        Self {
            config,
            last: None,
            step: (0, T::lit(0.0)),
        }
    }

    /// Advances to `now`; returns the step in seconds (0 on the first call),
    /// or why the time cannot be trusted. The reference time becomes `now`
    /// in every case (see the module doc).
    pub fn advance(&mut self, now: Ticks) -> Result<T, ClockFault> {
        let Some(last) = self.last.replace(now) else {
            return Ok(T::lit(0.0));
        };
        let elapsed_us = now.since(last);
        let max_gap = self.config.max_gap_us().unwrap_or(0);
        if elapsed_us == 0 {
            Err(ClockFault::Stalled)
        } else if elapsed_us >= BACKWARDS_FROM_US {
            Err(ClockFault::Backwards)
        } else if elapsed_us > max_gap {
            Err(ClockFault::Gap { elapsed_us })
        } else {
            if self.step.0 != elapsed_us {
                self.step = (elapsed_us, micros_as_seconds(elapsed_us));
            }
            Ok(self.step.1)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn clock() -> Clock<f32> {
        Clock::new(ClockConfig::standard())
    }

    #[test]
    fn steps_are_exact_differences_across_the_wrap() {
        let mut c = clock();
        let start = Ticks(u32::MAX - 15_000);
        assert_eq!(c.advance(start), Ok(0.0));
        let mut t = start;
        for _ in 0..4 {
            t = t.wrapping_add_micros(10_000);
            assert_eq!(c.advance(t), Ok(0.01));
        }
        assert!(t.micros() < start.micros(), "the test crossed the wrap");
    }

    #[test]
    fn stall_gap_and_backwards_are_faults() {
        let mut c = clock();
        c.advance(Ticks(1_000_000)).unwrap();
        assert_eq!(c.advance(Ticks(1_000_000)), Err(ClockFault::Stalled));
        assert_eq!(c.advance(Ticks(1_050_000)), Ok(0.05)); // 5 periods: allowed
        assert_eq!(
            c.advance(Ticks(1_100_001)),
            Err(ClockFault::Gap { elapsed_us: 50_001 })
        );
        assert_eq!(c.advance(Ticks(1_090_000)), Err(ClockFault::Backwards));
        // The new time is the reference again.
        assert_eq!(c.advance(Ticks(1_100_000)), Ok(0.01));
    }

    #[test]
    fn micros_print_as_rounded_seconds() {
        let s = |us| {
            let mut t = String::new();
            write_micros_as_seconds(&mut t, us).unwrap();
            t
        };
        assert_eq!(s(0), "0.000");
        assert_eq!(s(6_000_000), "6.000");
        assert_eq!(s(1_234_500), "1.235");
        assert_eq!(s(-20_000), "-0.020");
        assert_eq!(s(-400), "0.000");
        assert_eq!(s(40_003_200_010_000), "40003200.010");
    }
}
