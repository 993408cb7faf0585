//! The seals' breakaway at the start of a raise: the force the cylinder's
//! seals hold before the boom is seen to move.
//!
//! A raise begins with the valve opening: the pressure under the piston
//! climbs by the seals' up-friction F_up(F) = a + b·|F| (the calibration's
//! law at no rate, [`crate::load_estimate::Calibration::sliding_n`]) as the
//! boom begins to creep. The angle sensor shows the creep only after its
//! lag, and the [direction detector](crate::load_estimate::DirectionDetector)
//! calls it a raise only once the filtered rate has passed 0.15 °/s, or
//! stayed over 0.05 °/s for 0.25 s. In a slow start (a ramp of 1–2 s to
//! 0.1–0.2 °/s) that is about a second, and in it the friction read as load:
//! with seals of 5 kN + 0.037·|F| the reading rose 6.9 % and a load at a
//! true utilization of 0.903 was cut (campaign seed 28 #4991). The rope
//! bank's averages, raised at once at rest, also took the rise up and held
//! it into the raise (1.087 × the load once the raise was seen, seed 12
//! #7607). Such starts were 7 of the 9 early OVERLOADs of seeds 1–33.
//!
//! The rise alone cannot tell the seals from a load: every load taken up
//! starts as a small rise. A breakaway starts from a boom at rest whose
//! seals have released (the last motion's friction share under 1 %), with
//! no swing in the force ([`crate::static_load::StaticLoadBank::force_swings`]:
//! a slow swing's trough can look calm, and the angle's noise hides the
//! boom's give in its rise), and whose force is **calm**: it has stayed
//! within a range of [`CALM`]·F_up for [`CALM_S`]; the highest force of
//! that range, F_calm, is the force before the valve opened, and its noise
//! no rise. Let ΔF = F − F_calm and
//! ω̇ the filtered rate (°/s). The rise is the seals' only
//!
//! - **while it is no more than they can hold, and holds**:
//!   ΔF ≤ [`BAND`]·F_up (the learned law is the seals' within its residual;
//!   a lift-off's rise passes the band long before it nears the rated
//!   load, and from then on all of it is load), the force has not fallen
//!   under the calm, and for no longer than [`RISE_S`] (a raise is seen
//!   within it; a load added stays);
//! - **once the angle shows the boom rising**: the filtered rate is over
//!   [`RISING_DEG_S`] (over a still boom's noise) with the filtered angle
//!   above where it was at the calm's end (a load taken up bends the boom
//!   and squeezes the oil, which lowers it; a swinging load's pull bends it
//!   as its force rises, and its calm is at the trough, where the boom
//!   is bent least).
//!
//! What the estimate takes out of the force is then H = clamp(ΔF, 0, F_up)
//! ([`Breakaway::update`]); once the direction detector sees the raise,
//! the sliding friction replaces it. While H is taken out, the rope bank
//! sets its averages to the weighing ([`crate::static_load`]): raised at
//! once at rest, they took the rise up before the angle showed it, and
//! would carry it into the raise. Whatever ends a rise (past the band,
//! fallen under the calm, or stayed) ends the calm too: the force must be calm again
//! before the next. Before any calibration F_up is 0 and nothing changes.
//!
//! The angle shows the rise late (campaign seed 12 #7607: the filtered
//! rate passed 0.03 °/s 0.8 s after the force began to rise, with 4.9 % of
//! the load's reading in it), so the reading still peaks before H is taken
//! out: the 7 early raises peak at estimated u 0.984–1.002 (from 1.002–1.014,
//! at true u 0.902–0.911). A share of H growing with the rate from 0 took
//! them to 0.957–0.980, but the angle's noise (±0.02 °/s) then held a
//! share of a slow swing's rise (a load swinging on a long rope after
//! power-up) and of a lift-off's settling tail, and broke the weighing by
//! the mean over one swing period.
//!
//! What it costs: a load added at rest by no more than the band (with the
//! campaign's seals, whose F_up is 4–7 % of the force, 8–14 %) while the
//! angle reads a rise is read low by up to F_up, for as long as the angle
//! reads it, at most [`RISE_S`]. The 110 % lift-off taken up at 80°, whose
//! jerk shows 0.08 °/s upward for 0.25 s, rises past the band before it
//! nears the cut.

use crane_model::Real;

/// The filtered rate (°/s, upward) over which the boom is seen rising: the
/// filtered rate's noise at a still boom stays under it.
pub const RISING_DEG_S: f64 = 0.03;

/// The calm force's range (× F_up): a still boom's filtered force (noise,
/// the tail of a lift-off settling) stays within it.
pub const CALM: f64 = 0.5;

/// How long the force must be calm (s) before a rise can be the seals'.
pub const CALM_S: f64 = 1.0;

/// The largest rise (× F_up) still taken as the seals'. Not 1: the learned
/// law is the seals' only within its residual, and a raise begun as a
/// lift-off settles measures its rise from the lift-off's tail (1.45 F_up
/// at seed 17 #8203).
pub const BAND: f64 = 2.0;

/// How long a rise over the calm may stay the seals' (s): a slow start's
/// raise is seen within about 1.5 s of its rise.
pub const RISE_S: f64 = 2.5;

/// The seals' breakaway detector (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Breakaway<T> {
    /// The force's range while it is being found calm, and once calm (N);
    /// meaningless until `seen`.
    low_n: T,
    high_n: T,
    seen: bool,
    /// How long the force has stayed within [`CALM`]·F_up (s), up to
    /// [`CALM_S`].
    calm_s: T,
    /// How long the force has been over the calm's range (s).
    rise_s: T,
    /// The filtered angle at the end of the calm (°).
    calm_angle_deg: T,
}

impl<T: Real> Default for Breakaway<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> Breakaway<T> {
    /// A detector that has seen no calm force.
    pub fn new() -> Self {
        let zero = T::lit(0.0);
        Self { low_n: zero, high_n: zero, seen: false, calm_s: zero, rise_s: zero, calm_angle_deg: zero }
    }

    /// Forgets the forces seen (the boom moved, or the filters restarted).
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// A new calm, from the force `force_n`. (Not inlined: its three calls
    /// cost the controller's flash.)
    #[inline(never)]
    fn restart_at(&mut self, force_n: T) {
        *self = Self { low_n: force_n, high_n: force_n, seen: true, ..Self::new() };
    }

    /// The force the seals hold now (N, ≥ 0), `dt_s` after the last
    /// update: `force_n` the filtered force (N), `released` whether the
    /// boom is still with the last motion's friction released (its share
    /// under 1 %: the force the seals release after a stop is no raise) and
    /// no swing in the force, the filtered angle and its rate (°, °/s), and
    /// `up_friction_n` F_up at this force.
    pub fn update(&mut self, force_n: T, released: bool, (angle_deg, rate_deg_s): (T, T), up_friction_n: T, dt_s: T) -> T {
        let zero = T::lit(0.0);
        let calm = T::lit(CALM) * up_friction_n;
        // (A force that is not a number compares false everywhere below,
        // and holds nothing.)
        if !(released && calm > zero) {
            self.reset();
            return zero;
        }
        if !self.seen {
            self.restart_at(force_n);
        }
        if self.calm_s < T::lit(CALM_S) {
            // Finding a calm: the range since it began.
            let (low, high) = (self.low_n.min(force_n), self.high_n.max(force_n));
            if high - low > calm {
                self.restart_at(force_n);
            } else {
                (self.low_n, self.high_n) = (low, high);
                self.calm_s += dt_s;
                self.calm_angle_deg = angle_deg;
            }
            return zero;
        }
        // Over the calm's highest: its noise is no rise.
        let rise = force_n - self.high_n;
        self.rise_s = if rise > zero { self.rise_s + dt_s } else { zero };
        if force_n < self.low_n - calm || rise > T::lit(BAND) * up_friction_n || self.rise_s > T::lit(RISE_S) {
            // Under the calm, past the seals, or a rise that stays: the next
            // breakaway starts from a new calm.
            self.restart_at(force_n);
            return zero;
        }
        if angle_deg > self.calm_angle_deg && rate_deg_s > T::lit(RISING_DEG_S) {
            rise.max(zero).min(up_friction_n)
        } else {
            zero
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DT: f64 = 0.01;

    /// `calm_s` seconds of a calm force of 300 kN (F_up 20 kN), then a rise
    /// of `rise` N over 1 s, the boom rising at `rate` °/s from the rise's
    /// middle on: what the seals hold at its end.
    fn held_after(calm_s: f64, rise: f64, rate: f64) -> f64 {
        let mut b = Breakaway::<f64>::new();
        for _ in 0..(calm_s / DT) as usize {
            assert_eq!(b.update(300e3, true, (40.0, 0.0), 20e3, DT), 0.0);
        }
        let (mut held, mut angle) = (0.0, 40.0);
        for k in 1..=100 {
            let s = f64::from(k) / 100.0;
            let r = if s > 0.5 { rate } else { 0.0 };
            angle += r * DT;
            held = b.update(300e3 + rise * s, true, (angle, r), 20e3, DT);
        }
        held
    }

    #[test]
    fn a_rise_from_a_calm_that_the_seals_can_hold_with_the_boom_rising_is_theirs() {
        assert!((held_after(2.0, 15e3, 0.05) - 15e3).abs() < 1e-6);
        // Up to the up-friction.
        assert!((held_after(2.0, 25e3, 0.05) - 20e3).abs() < 1e-6);
    }

    #[test]
    fn a_rise_beyond_the_seals_or_without_the_boom_rising_is_load() {
        assert_eq!(held_after(2.0, 45e3, 0.05), 0.0);
        // The rate within a still boom's noise, or the boom sinking.
        assert_eq!(held_after(2.0, 15e3, 0.025), 0.0);
        assert_eq!(held_after(2.0, 15e3, -0.05), 0.0);
        assert_eq!(held_after(2.0, 15e3, f64::NAN), 0.0);
    }

    #[test]
    fn nothing_without_a_calm_before_the_rise() {
        // Too short a calm (0.2 s, and the rise's first 0.67 s within the
        // calm's range).
        assert_eq!(held_after(0.2, 15e3, 0.05), 0.0);
        // A swinging load's force (±15 kN, periods of 2 s to 9 s): its pull
        // bends the boom, which lowers the angle as the force rises (by
        // up to 0.05 °/s). Its trough may look calm, but the boom is bent
        // least there: the angle stays under the calm's, nothing is held.
        for period in [2.0, 5.0, 9.0] {
            let mut b = Breakaway::<f64>::new();
            let w = 2.0 * core::f64::consts::PI / period;
            for k in 0..3000 {
                let t = f64::from(k) * DT;
                let f = 300e3 + 15e3 * (w * t).sin();
                // The angle: −0.05·cos integrated, the boom lowest at the crest.
                let (angle, rate) = (40.0 - 0.05 / w * (w * t).sin(), -0.05 * (w * t).cos());
                assert_eq!(b.update(f, true, (angle, rate), 20e3, DT), 0.0, "{period} s, {t} s");
            }
        }
        // Seals not released (a stop's, or a swing in the force), or a
        // moving boom: the calm starts again.
        let mut b = Breakaway::<f64>::new();
        for _ in 0..200 {
            b.update(300e3, true, (40.0, 0.0), 20e3, DT);
        }
        assert_eq!(b.update(310e3, false, (40.01, 0.05), 20e3, DT), 0.0);
        assert_eq!(b.update(310e3, true, (40.01, 0.05), 20e3, DT), 0.0);
        // A force that is not a number holds nothing.
        let mut b = Breakaway::<f64>::new();
        for _ in 0..200 {
            b.update(300e3, true, (40.0, 0.0), 20e3, DT);
        }
        assert_eq!(b.update(f64::NAN, true, (40.01, 0.05), 20e3, DT), 0.0);
        assert!((b.update(310e3, true, (40.01, 0.05), 20e3, DT) - 10e3).abs() < 1e-6);
        // Uncalibrated: no F_up.
        let mut b = Breakaway::<f64>::new();
        for _ in 0..200 {
            b.update(300e3, true, (40.0, 0.0), 0.0, DT);
        }
        assert_eq!(b.update(310e3, true, (40.01, 0.05), 0.0, DT), 0.0);
    }

    #[test]
    fn a_rise_that_stays_is_load_and_the_next_calm_starts_from_it() {
        let mut b = Breakaway::<f64>::new();
        for _ in 0..200 {
            b.update(300e3, true, (40.0, 0.0), 20e3, DT);
        }
        assert!((b.update(315e3, true, (40.01, 0.05), 20e3, DT) - 15e3).abs() < 1e-6);
        let mut held = 0.0;
        for _ in 0..((RISE_S + 0.1) / DT) as usize {
            held = b.update(315e3, true, (40.01, 0.05), 20e3, DT);
        }
        assert_eq!(held, 0.0);
        // Calm again at 315 kN: a rise of 10 kN from there.
        for _ in 0..200 {
            b.update(315e3, true, (40.0, 0.0), 20e3, DT);
        }
        assert!((b.update(325e3, true, (40.01, 0.05), 20e3, DT) - 10e3).abs() < 1e-6);
    }
}
