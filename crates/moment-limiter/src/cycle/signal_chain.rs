//! Stages 1–2 of the cycle: counts to checked readings, the piston force, the
//! filters, the rate, acceleration and direction, the swing correction, and the
//! restart of all of them after a bad cycle.

use crane_model::loads::load_model::{BoomState, HookLoadModel};
use crane_model::Real;

use super::{readings, Limiter, Readings, ReadingsFault, MAX_GAP_STEPS, PAUSE_GAP_S};
use crate::checks::{FaultKind, SensorFault};
use crate::filter::exp_taylor3;
use crate::io::{Channel, Measurement, SensorInputs};
use crate::load_estimate::Direction;
use crate::piston_force::piston_force_n;
use crate::units::{BoomAngle, PressureBar};


/// Angle and rate `horizon_s` ahead of a filtered (angle, rate,
/// acceleration): constant acceleration, except that a decelerating boom is
/// taken to stop where it would come to rest rather than to turn round (the
/// end of a move: extrapolating the rate alone ran a boom that was stopping
/// at 40° on to 37°, and its rating down by 7 %).
fn extrapolate<T: Real>(angle: T, rate: T, accel: T, horizon_s: T) -> (T, T) {
    let zero = T::lit(0.0);
    let half = T::lit(0.5);
    let rate_end = rate + accel * horizon_s;
    if rate * accel < zero && rate * rate_end <= zero {
        // Stops within the horizon, at rate²/(2·|accel|) from here.
        (angle - rate * rate * half / accel, zero)
    } else {
        (
            angle + (rate + half * accel * horizon_s) * horizon_s,
            rate_end,
        )
    }
}

impl<T: Real, M: HookLoadModel<T>> Limiter<T, M> {
    /// The three readings of one cycle (see [`ReadingsFault`]).
    pub(super) fn read_counts<S: SensorInputs>(&self, inputs: &mut S) -> Result<Readings<T>, ReadingsFault<T>> {
        let conv = &self.config.conversion;
        let fault = |channel: Channel| move |kind: FaultKind| SensorFault { channel, kind };
        let read = |inputs: &mut S, channel: Channel| {
            inputs.read_counts(channel).map_err(|e| SensorFault {
                channel,
                kind: FaultKind::Input(e),
            })
        };
        // Every channel is read each cycle: the angle goes on through a
        // pressure's fault (see `interrupt_signal_chain_keeping`).
        let p1 = read(inputs, Channel::PistonSidePressure).and_then(|c| {
            conv.pressure(&conv.p1, c)
                .map_err(fault(Channel::PistonSidePressure))
        });
        let p2 = read(inputs, Channel::RodSidePressure).and_then(|c| {
            conv.pressure(&conv.p2, c)
                .map_err(fault(Channel::RodSidePressure))
        });
        let a = read(inputs, Channel::BoomAngle)
            .and_then(|c| conv.boom_angle(c).map_err(fault(Channel::BoomAngle)));
        readings(p1, p2, a)
    }

    /// A bad cycle: no faulty value ever reaches the filters. The chain
    /// pauses; at the next good sample it resumes, or restarts after a long
    /// gap (see [`PAUSE_GAP_S`]).
    pub(super) fn interrupt_signal_chain(&mut self) {
        self.interrupt_signal_chain_keeping(None, T::lit(0.0));
    }

    /// A bad cycle whose angle reading `angle` is good (a pressure's fault):
    /// the angle's side of the chain goes on `dt_s` after the last cycle, so
    /// the rope bank's pendulums swing with the boom through the gap (see
    /// [`PAUSE_GAP_S`]); the force's side pauses as for any bad cycle. Only
    /// while every bad cycle of the gap had its angle: one without breaks it,
    /// and the gap ends as any other.
    pub(super) fn interrupt_signal_chain_keeping(&mut self, angle: Option<BoomAngle<T>>, dt_s: T) {
        if !self.interrupted {
            // A new gap: the angle's side can go on only from a good sample.
            self.angle_kept = self.last_good.is_some();
            self.angle_gap_s = None;
        }
        let angle_deg = angle.map(|a| a.degrees() - self.config.calibration.angle_offset_deg);
        // The monitor's rate check, which it cannot make on a gap's
        // readings: a jump no boom makes would kick every pendulum.
        let limits = self.config.plausibility.angle;
        let credible = match (angle_deg, self.last_good) {
            (Some(a), Some((_, last))) => !limits.exceeds_rate(a - last, dt_s, self.config.clock.period_s()),
            _ => false,
        };
        match angle_deg {
            Some(angle_deg) if self.angle_kept && credible && dt_s > T::lit(0.0) => {
                let held_n = self.force_filter.output().unwrap_or(T::lit(0.0));
                let step = self.angle_step(angle_deg, dt_s, (held_n, held_n));
                self.advance_bank(step, dt_s);
                if let Some((force, _)) = self.last_good {
                    self.last_good = Some((force, angle_deg));
                }
                self.angle_gap_s = Some(T::lit(0.0));
            }
            _ => {
                self.angle_kept = false;
                self.angle_gap_s = self.angle_gap_s.map(|g| g + dt_s);
            }
        }
        self.negative_load.reset();
        self.monitor.break_rate_history();
        self.interrupted = true;
    }

    /// After a gap longer than [`PAUSE_GAP_S`] the filters restart settled
    /// on the next good sample, and the bank's averages start afresh.
    fn restart_filters(&mut self) {
        self.restart_force_filters();
        self.angle_restarted = true;
        self.angle_filter.reset();
        self.direction.filters_restarted();
        self.previous_angle_deg = None;
        self.previous_rate_deg_s = None;
        self.previous_dt_s = T::lit(0.0);
        self.moving_for_s = T::lit(0.0);
    }

    /// The force's side of [`Self::restart_filters`] alone, after a long gap
    /// whose angle the chain kept: the angle filter, the rate and the
    /// pendulums are the boom's own.
    fn restart_force_filters(&mut self) {
        self.since_restart_s = Some(T::lit(0.0));
        self.angle_restarted = false;
        if let Some(l) = self.force_lag.as_mut() {
            l.reset();
        }
        self.force_filter.reset();
        self.force_still_filter.reset();
        self.breakaway.reset();
    }

    /// Stage 2: force, filters, rate and direction.
    pub(super) fn measure(
        &mut self,
        p1: PressureBar<T>,
        p2: PressureBar<T>,
        angle: BoomAngle<T>,
        dt_s: T,
    ) -> Measurement<T> {
        let cal = &self.config.calibration;
        let force = piston_force_n(p1, p2, cal.p1_offset_bar, cal.p2_offset_bar);
        let angle_deg = angle.degrees() - cal.angle_offset_deg;
        // The first good sample after bad ones: over a short gap (the
        // pressure spike of a heavy load's stop, 0.2–0.5 s) the chain goes
        // on through the gap on the straight line from the last good sample
        // to this one (it holds good samples only). Restarted settled on
        // this one sample, the filtered force sat at the spike's value (1.4 ×
        // the load after a stop at 6°); taken as one long step, the filtered
        // angle jumped to its new value at once, its acceleration came as
        // one spike (220 °/s²) and was missing after it while the force's
        // rise was not, and the stop read 1.14 × the load (OVERLOAD at true
        // u 0.906 and 0.873 as the fault ended).
        let mut dt_s = dt_s;
        // The step of the force's side when it differs (a gap whose angle
        // the chain kept: only the force waited).
        let mut force_dt_s = None;
        if core::mem::replace(&mut self.interrupted, false) {
            let gap_s = core::mem::replace(&mut self.gap_s, T::lit(0.0));
            let kept = core::mem::replace(&mut self.angle_kept, false);
            // The part of the gap the angle's side has not gone through yet:
            // all of it, unless it went on for a while and then stopped.
            let angle_gap_s = self.angle_gap_s.take();
            match (self.last_good, angle_gap_s) {
                (Some(from), _) if kept && gap_s <= T::lit(PAUSE_GAP_S) => {
                    force_dt_s = Some(self.fill_gap(from, (force, angle_deg), gap_s, dt_s, false));
                }
                _ if kept => self.restart_force_filters(),
                (_, Some(angle_gap_s)) => {
                    // The angle went on through part of the gap, then broke
                    // (a glitch, or its own fault): the two sides no longer
                    // share one time, and both start afresh; the swing goes
                    // on over the part the pendulums have not seen.
                    self.restart_filters();
                    dt_s += angle_gap_s;
                }
                (Some(from), None) if gap_s <= T::lit(PAUSE_GAP_S) => {
                    dt_s = self.fill_gap(from, (force, angle_deg), gap_s, dt_s, true);
                }
                _ => {
                    // The filters start afresh on this sample; the swing
                    // goes on over the gap.
                    self.restart_filters();
                    dt_s += gap_s;
                }
            }
        }
        self.last_good = Some((force, angle_deg));
        let force_f = self.force_step(force, force_dt_s.unwrap_or(dt_s));
        let filtered = self.angle_step(angle_deg, dt_s, force_f);
        let step = self.advance_bank(filtered, dt_s);
        let (angle_f, rate_f, accel_f) = (step.angle_deg, step.rate_deg_s, step.accel_deg_s2);
        // Time alignment (see the type's doc): the filtered force and the
        // filtered angle both stand for t − d − lag.
        let (now, rate_now) = extrapolate(
            angle_f,
            rate_f,
            accel_f,
            self.config.effective_angle_sensor_lag_s() + self.force_filter.delay_s(dt_s),
        );
        let to_rad = T::pi() / T::lit(180.0);
        Measurement {
            piston_force_n: step.force_n,
            force_still_n: step.force_still_n,
            boom_angle_deg: now,
            rate_deg_s: rate_f,
            accel_deg_s2: accel_f,
            moving_for_s: self.moving_for_s,
            direction: step.direction,
            friction: self.direction.friction(),
            static_friction_share: self.static_friction_share,
            boom: BoomState {
                angle_rad: angle_f * to_rad,
                rate_rad_s: rate_f * to_rad,
            },
            boom_now: BoomState {
                angle_rad: now * to_rad,
                rate_rad_s: rate_now * to_rad,
            },
            tan_swing: step.tan_swing,
        }
    }

    /// Runs the chain through a gap of `gap_s` (the bad cycles) before the
    /// sample `to` that came `dt_s` after the last bad one, on the straight
    /// line from the last good sample `from` (force N, angle °): sub-steps
    /// of the sample period, or of 1/[`MAX_GAP_STEPS`] of the interval when
    /// that is longer (a bounded loop). Only the force's side when the angle's
    /// went on through the gap (`with_angle` false). Returns the step left
    /// for `to`.
    fn fill_gap(&mut self, from: (T, T), to: (T, T), gap_s: T, dt_s: T, with_angle: bool) -> T {
        let total = gap_s + dt_s;
        if !(dt_s > T::lit(0.0) && total.is_finite()) {
            return total;
        }
        let h = dt_s.max(total / T::lit(MAX_GAP_STEPS as f64));
        let mut t = T::lit(0.0);
        for _ in 1..MAX_GAP_STEPS {
            // The last step (to the sample itself) is at least h/2 long.
            if t + h * T::lit(1.5) > total {
                break;
            }
            t += h;
            let s = t / total;
            let force_f = self.force_step(from.0 + s * (to.0 - from.0), h);
            if with_angle {
                let filtered = self.angle_step(from.1 + s * (to.1 - from.1), h, force_f);
                // The swing too: taken over the gap in one step with the
                // acceleration at its end, a held load raised to 66° read 1.10 ×
                // (campaign seed 3, #6036).
                self.advance_bank(filtered, h);
            }
        }
        total - t
    }

    /// The force's side of one step on the piston force `force` (N, offsets
    /// removed), `dt_s` after its previous: the sensor lag and the filters.
    /// Returns the filtered force through the lag and without it (N).
    // Never inlined: its inlined copies (a good cycle, a filled gap, a
    // restart) took 0.15 KB more of the board's 64 KiB flash than one call.
    #[inline(never)]
    fn force_step(&mut self, force: T, dt_s: T) -> (T, T) {
        // Without the sensor's lag for a still boom (see crate::static_load).
        let force_still_f = self.force_still_filter.update(force, dt_s);
        // The force through the angle sensor's lag too: force, angle, rate
        // and acceleration then share one delay (see "Time alignment").
        let force = match self.force_lag.as_mut() {
            Some(l) => l.update(force, dt_s),
            None => force,
        };
        (self.force_filter.update(force, dt_s), force_still_f)
    }

    /// The angle's side of one step on the boom angle `angle_deg` (°, offset
    /// removed), `dt_s` after its previous: the filter, rate, acceleration,
    /// direction and the seals' release; the step returned carries the
    /// force's side `(force_f, force_still_f)` ([`Self::force_step`], or the
    /// held force through a gap), against whose filtered force the direction
    /// checks a creep.
    fn angle_step(&mut self, angle_deg: T, dt_s: T, (force_f, force_still_f): (T, T)) -> ChainStep<T> {
        let angle_f = self.angle_filter.update(angle_deg, dt_s);
        // Rate and acceleration as differences of the filtered angle: the
        // filter already removed the noise, and no further filter may delay
        // them behind the force (their inertia term is in the force now).
        let rate_f = match self.previous_angle_deg {
            Some(prev) if dt_s > T::lit(0.0) => (angle_f - prev) / dt_s,
            _ => self.previous_rate_deg_s.unwrap_or(T::lit(0.0)),
        };
        self.previous_angle_deg = Some(angle_f);
        // Each rate is the mean over its step, so two of them stand half of
        // each step apart: at uneven steps (a jittering logger's clock, 0.2
        // and 19.8 ms in a row) dividing by this step alone read the
        // acceleration up to 50 times too large. At even steps the same.
        let span_s = if self.previous_dt_s > T::lit(0.0) && self.previous_dt_s != dt_s {
            (dt_s + self.previous_dt_s) * T::lit(0.5)
        } else {
            dt_s
        };
        let accel_f = match self.previous_rate_deg_s {
            Some(prev) if span_s > T::lit(0.0) => (rate_f - prev) / span_s,
            _ => T::lit(0.0),
        };
        self.previous_rate_deg_s = Some(rate_f);
        self.previous_dt_s = dt_s;
        let previous_direction = self.direction.current();
        let direction = self.direction.update(rate_f, dt_s, force_f);
        self.moving_for_s = if direction == Direction::Still {
            T::lit(0.0)
        } else if direction == previous_direction {
            self.moving_for_s + dt_s
        } else {
            T::lit(0.0)
        };
        // The seals release at standstill (see crate::load_estimate).
        self.static_friction_share = if direction == Direction::Still {
            let last = self.direction.friction();
            self.static_friction_share / exp_taylor3(dt_s / self.config.effective_seal_release_s(last))
        } else {
            T::lit(1.0)
        };
        // A raise's start: the seals' part of the force (crate::breakaway).
        let cal = &self.config.calibration;
        let force = force_still_f - cal.force_offset_n;
        let up_friction_n = cal.sliding_n(Direction::Up, force, T::lit(0.0));
        let swinging = self.bank.as_ref().is_some_and(|b| b.force_swings());
        let released = direction == Direction::Still && self.static_friction_share < T::lit(0.01) && !swinging;
        self.seals_n = self.breakaway.update(force, released, (angle_f, rate_f), up_friction_n, dt_s);
        // A load rising from an empty hook: one filter stage fewer
        // (crate::static_load, "A lift-off: one stage fewer"). Its bounce is
        // watched in the first filter stage, less the offset and the seals'
        // breakaway as `assess` takes them off the still force, so that the
        // mean of its ring converts to a load as the still force does. A
        // steady load's rise must pass the seals' up-friction too: a raise's
        // start puts it in the force before the angle shows it.
        let lifting = match self.bank.as_mut() {
            Some(b) => {
                if self.seals_n > T::lit(0.0) {
                    b.raise_starts();
                }
                b.watch_lift(self.force_still_filter.first_stage().map(|f| f - cal.force_offset_n - self.seals_n), up_friction_n);
                b.lifting()
            }
            None => false,
        };
        ChainStep {
            force_n: force_f,
            force_still_n: if lifting { force_still_f + self.force_still_filter.last_stage_lead() } else { force_still_f },
            angle_deg: angle_f,
            rate_deg_s: rate_f,
            accel_deg_s2: accel_f,
            direction,
            tan_swing: T::lit(0.0),
        }
    }

    /// The rope bank's swing advanced to the filtered step `step`, `dt_s`
    /// after its last advance; returns `step` with the paid-out rope's tan φ.
    fn advance_bank(&mut self, step: ChainStep<T>, dt_s: T) -> ChainStep<T> {
        let to_rad = T::pi() / T::lit(180.0);
        let settling = self.since_restart_s.is_some();
        let tan_swing = match self.bank.as_mut() {
            Some(b) => {
                if settling {
                    // The filters restarted at this reading: the swing goes
                    // on (the pendulums take the tip's acceleration, so
                    // the jump of the filtered angle does not kick them),
                    // the filters' start-up acceleration is not the
                    // boom's, and no average starts from a reading that is
                    // none yet.
                    b.restart_averages();
                }
                // After a restart of the force alone the angle filter ran on:
                // its acceleration is the boom's.
                let accel = if settling && self.angle_restarted { T::lit(0.0) } else { step.accel_deg_s2 * to_rad };
                b.advance(step.angle_deg * to_rad, step.rate_deg_s * to_rad, accel, dt_s)
            }
            None => T::lit(0.0),
        };
        ChainStep { tan_swing, ..step }
    }
}

/// What one step of the signal chain gives ([`Limiter::angle_step`],
/// [`Limiter::advance_bank`]).
#[derive(Debug, Clone, Copy)]
struct ChainStep<T> {
    /// Filtered piston force (N), through the sensor's lag.
    force_n: T,
    /// Filtered piston force (N), without the sensor's lag (through one
    /// stage fewer while a load rises from an empty hook).
    force_still_n: T,
    /// Filtered boom angle (°).
    angle_deg: T,
    /// Its rate (°/s) and acceleration (°/s²).
    rate_deg_s: T,
    accel_deg_s2: T,
    direction: Direction,
    /// The paid-out rope's tan φ (0 without the bank).
    tan_swing: T,
}

#[cfg(test)]
mod tests {
    use super::extrapolate;

    #[test]
    fn extrapolation_follows_the_acceleration_and_stops_a_stopping_boom() {
        // Steady lowering: a straight line.
        assert_eq!(extrapolate(50.0_f64, -5.0, 0.0, 0.5), (47.5, -5.0));
        // Speeding up: the parabola.
        let (a, r) = extrapolate(50.0_f64, -1.0, -2.0, 0.5);
        assert!((a - (50.0 - 0.5 - 0.25)).abs() < 1e-12 && (r + 2.0).abs() < 1e-12);
        // Slowing down, still moving at the horizon: the parabola.
        let (a, r) = extrapolate(50.0_f64, -5.0, 4.0, 0.5);
        assert!((a - (50.0 - 2.5 + 0.5)).abs() < 1e-12 && (r + 3.0).abs() < 1e-12);
        // Slowing down, stopped before the horizon: where it comes to rest
        // (−5 °/s at 8 °/s² stops in 0.625 s, 1.5625° further), not beyond.
        let (a, r) = extrapolate(50.0_f64, -5.0, 8.0, 1.0);
        assert!((a - (50.0 - 1.5625)).abs() < 1e-12 && r == 0.0);
        // The same raising.
        let (a, r) = extrapolate(50.0_f64, 5.0, -8.0, 1.0);
        assert!((a - (50.0 + 1.5625)).abs() < 1e-12 && r == 0.0);
    }
}

