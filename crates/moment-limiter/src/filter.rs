//! The low-pass filter used on the piston force and on the boom angle.
//!
//! `n` identical first-order stages in series (n = 1…[`MAX_STAGES`]),
//! discretised exactly for the actual time step:
//! `y += (1 − e^(−Δt/τ))·(x − y)` per stage, τ = 1/(2π·f_c).
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
/// least 1 for every x ≥ 0, so e^(−x) ≈ 1/[`exp_taylor3`](x) is in (0, 1].
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
        }
    }

    /// The step's exponentials, from the cache when Δt is the last one's.
    fn step_for(&self, dt_s: T) -> Step<T> {
        match self.step {
            Some(step) if step.dt_s == dt_s => step,
            _ => {
                let x = dt_s / self.tau_s;
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
    /// to second order; n·τ as Δt → 0).
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
