//! Switched on while the boom moves: no weighing until it stops.
//!
//! The limiter weighs a load in motion from what it learned before the move:
//! the rope bank starts each move from the weighing at rest, and its
//! pendulums swing with the moves they have seen ([`crate::static_load`]). A
//! limiter switched on in the middle of a move (a power cut, a brown-out or a
//! watchdog reset during a lowering, or a log whose recording starts mid-move)
//! has neither. Its filters start settled on the first reading, so their
//! start-up reads as an acceleration the force never had, and the bank takes
//! the load hanging still while it swings from the move's start. Switched on
//! 1–10 s into a 15 s lowering from 80° to 20° (`host-sim` test
//! `switched_on_during_a_lowering`, 112 cases), it read as little as −0.11
//! of the load at its first reading and 0.09 of it 0.3 s later; 24 cases
//! left a true u over 1.05 uncut (for up to 0.86 s, first cut at up to
//! 1.157), 47 were cut before 1/1.1 (from 0.62).
//!
//! So the cycle watches the raw angle for [`WATCH_S`] after power-up. If its
//! smoothed value (one stage of gain [`SMOOTHING`] a reading) strays more than
//! [`STILL_DEG`] from the mean of its first [`REFERENCE_READINGS`] readings in
//! [`STRAYS`] readings in a row (a boom moving at 0.8 °/s or more), the
//! limiter was
//! switched on in motion and reports [`crate::fault::Fault::StartedMoving`]
//! (FAULT: boom-down and hoist-up cut, the moment-reducing motions free) until
//! the boom has been still for [`STOPPED_S`]. Then the bank starts afresh, as
//! if switched on at rest there. Noise is no move: on the simulator's noisiest
//! angle sensor (0.05° and 0.0275° steps) the difference of the two is about
//! 0.032°, a sixth of [`STILL_DEG`] (compared with the first reading alone, a
//! first reading 0.2° off made a still boom's lift-off a FAULT, campaign seed
//! 1 #5830). A boom that starts moving within the watch
//! has moved less than that (a 1 s ramp to 7.5 °/s moves 0.02° in its first
//! 0.2 s) and counts as switched on at rest, as it was.

use crane_model::Real;

/// How long after power-up the raw angle is watched (s).
pub const WATCH_S: f64 = 0.3;

/// How far the raw angle may stray from its first reading within
/// [`WATCH_S`] for the boom to count as still at power-up (°).
pub const STILL_DEG: f64 = 0.2;

/// Readings in a row beyond [`STILL_DEG`] that make a move.
pub const STRAYS: u8 = 3;

/// Readings whose mean is the angle at power-up.
pub const REFERENCE_READINGS: u8 = 5;

/// Gain a reading of the smoothed angle compared with it (a first-order
/// stage of about 3 readings: its noise is 0.42 of a reading's).
pub const SMOOTHING: f64 = 0.3;

/// How long the boom must be still (the limiter's direction of motion:
/// Still) before a limiter switched on in motion weighs (s).
pub const STOPPED_S: f64 = 1.0;

/// Where the power-up check stands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum PowerUp<T> {
    /// Watching the raw angle: the sum of its first readings (°) and their
    /// count, its smoothed value (°), the time watched (s) and the readings
    /// in a row beyond [`STILL_DEG`].
    Watching { sum_deg: T, readings: u8, smoothed_deg: Option<T>, watched_s: T, strays: u8 },
    /// Switched on in motion: how long the boom has been still since (s).
    InMotion { still_s: T },
    /// The limiter weighs as usual.
    Done,
}

/// What [`PowerUp::update`] found this cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum PowerUpCheck {
    /// Switched on in motion and not stopped yet: no weighing.
    InMotion,
    /// It stopped this cycle: the rope bank starts afresh.
    Stopped,
    /// Nothing to do.
    Clear,
}

impl<T: Real> PowerUp<T> {
    /// A limiter just switched on.
    pub(super) fn new() -> Self {
        PowerUp::Watching { sum_deg: T::lit(0.0), readings: 0, smoothed_deg: None, watched_s: T::lit(0.0), strays: 0 }
    }

    /// One good reading: the raw boom angle (°), whether the limiter's
    /// direction of motion is Still, and the step (s).
    pub(super) fn update(&mut self, angle_deg: T, still: bool, dt_s: T) -> PowerUpCheck {
        match *self {
            PowerUp::Watching { sum_deg, readings, smoothed_deg, watched_s, strays } => {
                let watched_s = watched_s + dt_s;
                let smoothed = smoothed_deg.map_or(angle_deg, |s| s + T::lit(SMOOTHING) * (angle_deg - s));
                let (sum_deg, readings) = if readings < REFERENCE_READINGS { (sum_deg + angle_deg, readings + 1) } else { (sum_deg, readings) };
                let strays = if readings < REFERENCE_READINGS {
                    0
                } else if (smoothed - sum_deg / T::lit(f64::from(REFERENCE_READINGS))).abs() > T::lit(STILL_DEG) {
                    strays.saturating_add(1)
                } else {
                    0
                };
                if strays >= STRAYS {
                    *self = PowerUp::InMotion { still_s: T::lit(0.0) };
                    return PowerUpCheck::InMotion;
                }
                *self = if watched_s >= T::lit(WATCH_S) {
                    PowerUp::Done
                } else {
                    PowerUp::Watching { sum_deg, readings, smoothed_deg: Some(smoothed), watched_s, strays }
                };
                PowerUpCheck::Clear
            }
            PowerUp::InMotion { still_s } => {
                let still_s = if still { still_s + dt_s } else { T::lit(0.0) };
                if still_s >= T::lit(STOPPED_S) {
                    *self = PowerUp::Done;
                    PowerUpCheck::Stopped
                } else {
                    *self = PowerUp::InMotion { still_s };
                    PowerUpCheck::InMotion
                }
            }
            PowerUp::Done => PowerUpCheck::Clear,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_still_start_is_clear_and_a_moving_one_waits_for_the_stop() {
        // A step that sums exactly (1/64 s).
        let dt = 1.0 / 64.0;
        // Still, the first reading 0.25° off and then ±0.1° of noise: clear,
        // and done after the watch.
        let mut p = PowerUp::<f64>::new();
        for k in 0..40 {
            let noise = match k {
                0 => 0.25,
                _ if k % 2 == 0 => 0.1,
                _ => -0.1,
            };
            assert_eq!(p.update(40.0 + noise, true, dt), PowerUpCheck::Clear);
        }
        assert_eq!(p, PowerUp::Done);
        // A move starting after the watch changes nothing.
        assert_eq!(p.update(45.0, false, dt), PowerUpCheck::Clear);

        // Lowering at 2 °/s (1/32° a step): in motion within the watch, once
        // the angle has strayed more than 0.2°, until still for 1 s.
        let mut p = PowerUp::<f64>::new();
        let checks: Vec<_> = (0..20).map(|k| p.update(60.0 - f64::from(k) / 32.0, false, dt)).collect();
        // The reference is the mean of the first five (60 − 2/32°); the
        // smoothed angle lags the ramp by 7/3 readings, so it is 0.2° past
        // the reference from the 11th reading, and the third in a row is
        // the 13th.
        assert_eq!(checks.iter().position(|c| *c == PowerUpCheck::InMotion), Some(13));
        for _ in 0..63 {
            assert_eq!(p.update(50.0, true, dt), PowerUpCheck::InMotion);
        }
        // A flicker of motion starts the wait again.
        assert_eq!(p.update(50.0, false, dt), PowerUpCheck::InMotion);
        for _ in 0..63 {
            assert_eq!(p.update(50.0, true, dt), PowerUpCheck::InMotion);
        }
        assert_eq!(p.update(50.0, true, dt), PowerUpCheck::Stopped);
        assert_eq!(p.update(50.0, false, dt), PowerUpCheck::Clear);
    }
}
