//! The low-pass filter used on the piston force and on the boom angle.
//!
//! `n` identical first-order stages in series (n = 1…[`MAX_STAGES`]),
//! discretised exactly for the actual time step:
//! `y += (1 − e^(−Δt/τ))·(x − y)` per stage, τ = 1/(2π·f_c). A filter told
//! its nominal period P ([`LowPass::with_period_s`], as the limiter's are)
//! keeps that step at P and, at any other step, the gain Δt/(Λ + Δt) that
//! lags a ramp by the same Λ as at P: uneven steps (a jittering clock, a
//! gap bridged in sub-steps) then do not make the lag, and so the
//! differences of the output, wobble.
//!
//! Why this filter and not a sharper one:
//! - its impulse response is never negative, so it **never overshoots** (no
//!   false alarm from a step) and it is **monotone**: a higher input history
//!   never gives a lower output. That is what makes "more load never lowers
//!   the utilization" hold sample by sample;
//! - it has unit gain at DC: a sustained overload is never hidden, only
//!   delayed by the group delay n·τ (a ramp is followed with that constant
//!   lag);
//! - it is stable for any time step, so replayed logs at other rates than
//!   100 Hz are filtered correctly.
//!
//! The limiter runs the force and the angle through the same filter, so the
//! two stay aligned in time whatever the cut-off, and takes the angle's rate
//! and acceleration as differences of the filtered angle (see
//! [`crate::cycle::LimiterConfig::standard`] for the chosen 4 stages at
//! 1.2 Hz: delay 0.53 s; gain 0.014 at 3.3 Hz and 0.007 at 4 Hz, where the
//! loaded and the unloaded boom's first bending oscillation are).

use crane_model::Real;

/// e^x for small x ≥ 0 by its cubic Taylor polynomial, 1 + x + x²/2 + x³/6:
/// no libm exp in the cycle for the stages whose time step is not cached
/// (relative error below 1e-9 at x = 0.05, i.e. dt = 10 ms, τ ≥ 0.2 s); at
/// least 1 for every x ≥ 0, so e^(−x) ≈ 1/`exp_taylor3(x)` is in (0, 1].
pub fn exp_taylor3<T: Real>(x: T) -> T {
    T::lit(1.0) + x * (T::lit(1.0) + x * (T::lit(0.5) + x / T::lit(6.0)))
}

/// The gain 1 − e^(−x) of a first-order stage for x = dt/τ ≥ 0, with
/// [`exp_taylor3`]: in [0, 1) for every x ≥ 0.
pub fn stage_gain<T: Real>(x: T) -> T {
    T::lit(1.0) - T::lit(1.0) / exp_taylor3(x)
}

/// Most stages a [`LowPass`] can have.
pub const MAX_STAGES: usize = 4;

/// A critically damped low-pass of `n` first-order stages.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LowPass<T> {
    tau_s: T,
    stage_count: usize,
    /// `stage_count` as a `T`, converted once (a run-time integer-to-float
    /// conversion through `T::lit` goes through f64: soft float on the M4F).
    stages_t: T,
    /// The exponentials of the last time step: a cycle at the same period
    /// reuses them instead of recomputing e^(−Δt/τ).
    step: Option<Step<T>>,
    /// Outputs of the stages; `None` until the first sample.
    stages: Option<[T; MAX_STAGES]>,
    /// The nominal period P (s) and each stage's lag behind a ramp at it,
    /// Λ = P/(e^(P/τ) − 1), kept at every other step (see [`Self::with_period_s`]).
    nominal: Option<(T, T)>,
}

/// What a time step Δt costs to know: the gain 1 − e^(−Δt/τ) of a stage and
/// the filter's delay for samples Δt apart.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Step<T> {
    dt_s: T,
    gain: T,
    delay_s: T,
}

impl<T: Real> LowPass<T> {
    /// A filter of `stages` stages (clamped to 1…[`MAX_STAGES`]), each with
    /// cut-off `cutoff_hz` (must be > 0).
    pub fn new(cutoff_hz: T, stages: usize) -> Self {
        let stage_count = stages.clamp(1, MAX_STAGES);
        Self {
            tau_s: T::lit(1.0) / (T::two_pi() * cutoff_hz),
            stage_count,
            stages_t: T::lit(stage_count as f64),
            step: None,
            stages: None,
            nominal: None,
        }
    }

    /// The same filter for samples that should come every `period_s` but
    /// may not (a logger's jittering clock, a gap bridged in sub-steps).
    /// At the period each stage is the exact one, y += (1 − e^(−P/τ))·(x − y),
    /// which lags a ramp by Λ = P/(e^(P/τ) − 1) ≈ τ − P/2. At any other
    /// step Δt the exact stage would lag by Δt/(e^(Δt/τ) − 1), so the lag
    /// would wobble with uneven steps, and so would the differences of the
    /// output (a lowering's rate and acceleration, and with them the rated
    /// load's angle: a log stamped ±3 ms off its grid was cut 0.26 s late).
    /// There the stage's gain is Δt/(Λ + Δt) instead (the implicit Euler
    /// step of a stage of time constant Λ): it lags a ramp by exactly Λ for
    /// every Δt, and equals the exact gain at Δt = P. In (0, 1) for every
    /// Δt > 0: stable, no overshoot, monotone.
    pub fn with_period_s(self, period_s: T) -> Self {
        let x = period_s / self.tau_s;
        let nominal = (period_s > T::lit(0.0) && x.is_finite()).then(|| (period_s, period_s / (x.exp() - T::lit(1.0))));
        Self { nominal, ..self }
    }

    /// The step's exponentials, from the cache when Δt is the last one's.
    fn step_for(&self, dt_s: T) -> Step<T> {
        match self.step {
            Some(step) if step.dt_s == dt_s => step,
            _ => {
                let x = dt_s / self.tau_s;
                if let Some((period_s, lag_s)) = self.nominal {
                    // Within a millionth of the period: the period (a
                    // period converted to seconds otherwise than the step;
                    // the limiter's are alike, `ClockConfig::period_s`).
                    if (dt_s - period_s).abs() > period_s * T::lit(1e-6) {
                        let gain = if dt_s > T::lit(0.0) { dt_s / (lag_s + dt_s) } else { T::lit(0.0) };
                        return Step { dt_s, gain, delay_s: self.stages_t * lag_s };
                    }
                }
                let delay_s = if x > T::lit(1e-6) && x.is_finite() {
                    self.stages_t * dt_s / (x.exp() - T::lit(1.0))
                } else {
                    self.stages_t * self.tau_s
                };
                Step { dt_s, gain: T::lit(1.0) - (-x).exp(), delay_s }
            }
        }
    }

    /// Low-frequency group delay (s) for samples `dt_s` apart: the lag behind
    /// a ramp, n·Δt/(e^(Δt/τ) − 1) for the discretised stages (n·τ − n·Δt/2
    /// to second order; n·τ as Δt → 0); with a nominal period P
    /// ([`Self::with_period_s`]), n·Λ = n·P/(e^(P/τ) − 1) at every step.
    pub fn delay_s(&self, dt_s: T) -> T {
        self.step_for(dt_s).delay_s
    }

    /// Forgets the state: the next sample starts the filter at that value.
    pub fn reset(&mut self) {
        self.stages = None;
    }

    /// Feeds `x`, taken `dt_s` after the previous sample; returns the output.
    /// The first sample after construction or [`reset`](Self::reset) is
    /// returned unchanged (the filter starts settled at it).
    pub fn update(&mut self, x: T, dt_s: T) -> T {
        let stages = match self.stages {
            None => [x; MAX_STAGES],
            Some(mut st) => {
                let dt = if dt_s > T::lit(0.0) {
                    dt_s
                } else {
                    T::lit(0.0)
                };
                let step = self.step_for(dt);
                self.step = Some(step);
                let a = step.gain;
                let mut input = x;
                for s in st.iter_mut().take(self.stage_count) {
                    *s += a * (input - *s);
                    input = *s;
                }
                st
            }
        };
        self.stages = Some(stages);
        self.output().unwrap_or(x)
    }

    /// The present output, if any sample has been fed.
    pub fn output(&self) -> Option<T> {
        let last = self.stage_count.checked_sub(1)?;
        self.stages.and_then(|st| st.get(last).copied())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_never_overshoots_and_settles() {
        let mut f = LowPass::new(3.0_f64, 2);
        f.update(0.0, 0.01);
        let mut y = 0.0;
        for _ in 0..200 {
            y = f.update(1.0, 0.01);
            assert!(y <= 1.0);
        }
        assert!((y - 1.0).abs() < 1e-6);
    }

    #[test]
    fn ramp_lag_is_the_documented_delay() {
        let mut f = LowPass::new(3.0_f64, 2);
        let mut y = 0.0;
        for k in 0..1000 {
            y = f.update(f64::from(k) * 0.01, 0.01);
        }
        let lag = 9.99 - y; // input slope is 1 per second
        assert!(
            (lag - f.delay_s(0.01)).abs() < 1e-9,
            "lag {lag} vs {}",
            f.delay_s(0.01)
        );
    }

    #[test]
    fn four_stages_lag_a_ramp_by_four_tau() {
        let mut f = LowPass::new(2.0_f64, 4);
        let mut y = 0.0;
        for k in 0..1000 {
            y = f.update(f64::from(k) * 0.01, 0.01);
        }
        let tau = 1.0 / (2.0 * core::f64::consts::PI * 2.0);
        assert!((f.delay_s(0.0) - 4.0 * tau).abs() < 1e-12);
        assert!(
            (9.99 - y - f.delay_s(0.01)).abs() < 1e-9,
            "lag {}",
            9.99 - y
        );
        assert!((f.delay_s(0.01) - (4.0 * tau - 0.02)).abs() < 1e-3);
    }

    /// With a nominal period, a ramp sampled 0.2–19.8 ms apart is followed
    /// with the lag it has at the period, so the output's differences are
    /// the ramp's slope (the exact stage at each step read it 0.949–1.030 of
    /// itself); at the period itself the stage is the exact one, bit for bit.
    #[test]
    fn with_a_period_uneven_steps_keep_the_lag_and_even_ones_are_unchanged() {
        let mut f = LowPass::new(1.2_f64, 4).with_period_s(0.01);
        let (mut t, mut seed, mut prev, mut worst) = (0.0, 12345u32, None::<(f64, f64)>, 0.0f64);
        for k in 0..3000 {
            seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
            let dt = 0.0002 + 0.0196 * f64::from(seed >> 16) / 65_536.0;
            t += dt;
            let y = f.update(2.0 * t, dt);
            if let (Some((t0, y0)), true) = (prev, k > 300) {
                worst = worst.max(((y - y0) / (t - t0) - 2.0).abs());
                assert!((2.0 * t - y - 2.0 * f.delay_s(dt)).abs() < 1e-6, "lag at {t}");
            }
            prev = Some((t, y));
        }
        assert!(worst < 1e-6, "slope off by {worst}");
        let (mut a, mut b) = (LowPass::new(1.2_f64, 4), LowPass::new(1.2_f64, 4).with_period_s(0.01));
        for k in 0..500 {
            let x = (f64::from(k) * 0.37).sin() * 100.0 + f64::from(k);
            assert_eq!(a.update(x, 0.01).to_bits(), b.update(x, 0.01).to_bits(), "sample {k}");
        }
        assert_eq!(a.delay_s(0.01), b.delay_s(0.01));
    }

    #[test]
    fn oscillation_at_5_hz_is_attenuated() {
        let mut f = LowPass::new(3.0_f64, 2);
        let mut peak: f64 = 0.0;
        for k in 0..1000 {
            let t = f64::from(k) * 0.01;
            let y = f.update((2.0 * core::f64::consts::PI * 5.0 * t).sin(), 0.01);
            if t > 5.0 {
                peak = peak.max(y.abs());
            }
        }
        assert!(peak < 0.3, "{peak}");
    }
}
