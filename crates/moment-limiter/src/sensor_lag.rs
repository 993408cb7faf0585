//! Learning the angle sensor's lag from the calibration runs
//! (`crane-sim calibrate`).
//!
//! The limiter lines force and angle up in time by putting the angle
//! sensor's lag τ on the force too (a first-order lag; see
//! [`crate::cycle::Limiter`] "Time alignment"). With a sensor that lags by
//! τ_s while the limiter assumes τ, the model is evaluated at an angle that
//! is (τ_s − τ)·θ̇ behind the force's, and the residual of a steady sample
//! carries
//!
//! ΔF ≈ ∂F_model/∂θ · θ̇ · (τ_s − τ).
//!
//! Like friction it changes sign with the direction of motion, but it
//! scales with ∂F/∂θ (the boom's weight moment: ∝ sin θ over the lever's
//! change), not with 1 and F as the seal law a + b·|F| does; over a 40°–80°
//! run the two have different shapes (a 1° angle error at 60° is several kN
//! on the empty boom). So the residual left by the best seal-law lines is
//! smallest at τ = τ_s.
//!
//! Over a steady run alone the two are hard to tell apart: on a 10 s
//! 40°–80° run the steady samples span 20°, over which ∂F/∂θ is nearly a
//! straight line in F, and the best lines' rms residual changed by 1 %
//! between lags of 0 and 0.5 s. The **ramps** show it: there the rate
//! changes while the force, and so the friction, hardly does, and the lag
//! error leaves a residual ∝ θ̇ that no friction law takes up (the same
//! runs' rms residual, ramps included, was 470 N at the true 0.3 s lag and
//! 1.2 kN at the default 0.111 s).
//!
//! **The search.** The learner's samples do not depend on τ (rate,
//! acceleration and direction come from the angle alone), only their
//! forces do. [`fit_lag`] runs the calibration runs through the limiter's
//! own signal chain once per candidate lag on a grid of [`LAG_STEP_S`]
//! from 0 to [`MAX_ANGLE_SENSOR_LAG_S`], takes for each the sum of squared
//! residuals S(τ) of the best straight line r = c + β·F per direction over
//! the moving samples of
//! [`crate::calibration::SteadyMotion::lag_search`], ramps included
//! ([`crate::calibration::CalibrationLearner::line_ssr`]: the seal law
//! with the offset free, so the lag has to be told from friction by shape
//! alone), and refines the grid's minimum by the parabola through it and
//! its neighbours: S(τ) ≈ S₀ + k·(τ − τ*)². The lag found is the
//! *first-order equivalent* of the sensor: for the oil-damped pendulum
//! (x'' = ω_n²(θ − x) − 2ζω_n·x') close to its steady-rate lag 2ζ/ω_n
//! (2 Hz, ζ = 0.7: 0.111 s; learned 0.09–0.10 s, its ramp response
//! being a little quicker than a first-order lag's).
//!
//! `crane-sim calibrate` searches over the unloaded runs only: in a
//! known-load run's ramps the load's swing and bounce, which the model does
//! not know, dominate the residual (a 3 t test weight luffed in 30 s moved
//! the minimum to the 0.5 s bound).
//!
//! Measured on synthesized unloaded 10 s cycloidal runs 40°↔80° (100 Hz,
//! both friction laws; `host-sim/tests/calibration_cli.rs`): first-order
//! lags 0.05 / 0.1 / 0.2 / 0.3 s learned as 0.04 / 0.09 / 0.20 / 0.30 s.
//! 30 s runs (1.3 °/s) show too little: the lag is reported not
//! observable and the default kept.
//!
//! **When it is not observable.** With little motion, a short angle span,
//! or a fit that other effects dominate, S(τ) is flat: a lag error leaves a
//! residual below the noise. The lag is taken only if moving [`LAG_PROBE_S`]
//! away from τ* raises the fit's rms residual by at least
//! [`MIN_RMS_RISE`], and τ* is not at the grid's upper end (a lag beyond the
//! schema's bound is a broken sensor, not a calibration); otherwise
//! [`LagFit::lag_s`] is the configured default and [`LagFit::observable`]
//! is `false`, which `crane-sim calibrate` prints.

use crane_model::Real;

pub use crate::load_estimate::MAX_ANGLE_SENSOR_LAG_S;

/// Spacing of the candidate lags (s).
pub const LAG_STEP_S: f64 = 0.025;

/// Number of candidate lags: 0, [`LAG_STEP_S`], … [`MAX_ANGLE_SENSOR_LAG_S`].
pub const LAG_CANDIDATES: usize = 21;

/// How far from the best lag the observability test probes (s).
pub const LAG_PROBE_S: f64 = 0.05;

/// Least relative rise of the rms residual [`LAG_PROBE_S`] away from the
/// best lag for the lag to be observable (–).
pub const MIN_RMS_RISE: f64 = 0.05;

/// The lag learned and how well the runs show it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LagFit<T> {
    /// The lag the calibration takes (s): `best_s` if observable, else the
    /// default given to [`fit_lag`].
    pub lag_s: T,
    /// The minimum of the residual curve (s).
    pub best_s: T,
    /// `true`: the residual curve is steep enough around `best_s`.
    pub observable: bool,
    /// Relative rise of the rms residual [`LAG_PROBE_S`] away from
    /// `best_s` (–; 0.1 = 10 %).
    pub rms_rise: T,
    /// Rms residual of the seal-law lines at `best_s` (N).
    pub rms_n: T,
    /// Rms residual at the default lag (N).
    pub rms_at_default_n: T,
}

/// The lag of the calibration runs (see the module doc): `ssr_at(τ)` runs
/// them through the signal chain with lag τ and returns the sum of squared
/// residuals of the seal-law lines and the number of samples
/// ([`crate::calibration::CalibrationLearner::line_ssr`]). Calls `ssr_at`
/// at most [`LAG_CANDIDATES`] + 2 times.
pub fn fit_lag<T: Real, E>(
    default_s: T,
    mut ssr_at: impl FnMut(T) -> Result<(T, u32), E>,
) -> Result<LagFit<T>, E> {
    let zero = T::lit(0.0);
    let h = T::lit(LAG_STEP_S);
    let mut s = [zero; LAG_CANDIDATES];
    let mut n = 1u32;
    for (i, slot) in s.iter_mut().enumerate() {
        let (ssr, count) = ssr_at(h * T::lit(i as f64))?;
        *slot = ssr;
        n = count.max(1);
    }
    let nn = T::lit(f64::from(n));
    let rms = |ssr: T| (ssr.max(zero) / nn).sqrt();
    let (mut i, mut s_min) = (0usize, T::lit(f64::INFINITY));
    for (k, v) in s.iter().enumerate() {
        if *v < s_min {
            (i, s_min) = (k, *v);
        }
    }
    let last = LAG_CANDIDATES - 1;
    // The parabola through the minimum and its neighbours (at an end, the
    // three nearest points).
    let c = i.clamp(1, last - 1);
    let (sl, sc, sr) = (
        s.get(c - 1).copied().unwrap_or(zero),
        s.get(c).copied().unwrap_or(zero),
        s.get(c + 1).copied().unwrap_or(zero),
    );
    let curv = sl - T::lit(2.0) * sc + sr;
    let tau_c = h * T::lit(c as f64);
    let mut best = if curv > zero {
        tau_c - h * (sr - sl) / (T::lit(2.0) * curv)
    } else {
        h * T::lit(i as f64)
    };
    best = best.max(zero).min(h * T::lit(last as f64));
    let (s_best, _) = ssr_at(best)?;
    if s_best > s_min || !s_best.is_finite() {
        best = h * T::lit(i as f64);
    }
    let s0 = s_best.min(s_min);
    // The curve LAG_PROBE_S either side, from the parabola: its second
    // difference over the grid is 2·k·h².
    let probe = T::lit(LAG_PROBE_S);
    let k = if curv > zero { curv / (T::lit(2.0) * h * h) } else { zero };
    let rise_ssr = |d: T| s0 + k * d * d;
    let rms0 = rms(s0);
    let rms_rise = if rms0 > zero {
        rms(rise_ssr(probe)) / rms0 - T::lit(1.0)
    } else {
        zero
    };
    let (s_default, _) = ssr_at(default_s)?;
    let observable = i < last && rms_rise >= T::lit(MIN_RMS_RISE) && best.is_finite();
    Ok(LagFit {
        lag_s: if observable { best } else { default_s },
        best_s: best,
        observable,
        rms_rise,
        rms_n: rms0,
        rms_at_default_n: rms(s_default),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_parabola_is_found_between_the_grid_points_and_a_flat_curve_keeps_the_default() {
        // S(τ) = 1e6·(1 + 400·(τ − 0.137)²) over 100 samples.
        let curve = |t: f64| Ok::<_, ()>((1e6 * (1.0 + 400.0 * (t - 0.137) * (t - 0.137)), 100));
        let f = fit_lag(0.111, curve).unwrap();
        assert!((f.best_s - 0.137).abs() < 1e-9 && f.observable, "{f:?}");
        assert_eq!(f.lag_s, f.best_s);
        // rms rises by sqrt(1 + 400·0.05²) − 1 = 41 %.
        assert!((f.rms_rise - (2.0f64.sqrt() - 1.0)).abs() < 1e-9, "{f:?}");
        // Flat within 1 %: not observable, the default kept.
        let flat = |t: f64| Ok::<_, ()>((1e6 * (1.0 + 1.0 * (t - 0.3) * (t - 0.3)), 100));
        let f = fit_lag(0.111, flat).unwrap();
        assert!(!f.observable && f.lag_s == 0.111, "{f:?}");
        // The minimum at the upper end: a broken sensor, not a calibration.
        let edge = |t: f64| Ok::<_, ()>((1e6 * (1.0 + 400.0 * (t - 0.7) * (t - 0.7)), 100));
        let f = fit_lag(0.111, edge).unwrap();
        assert!(!f.observable && f.lag_s == 0.111, "{f:?}");
        // Zero lag is a lag like any other (a potentiometer without damping).
        let none = |t: f64| Ok::<_, ()>((1e6 * (1.0 + 400.0 * t * t), 100));
        let f = fit_lag(0.111, none).unwrap();
        assert!(f.observable && f.lag_s.abs() < 1e-9, "{f:?}");
        // In f32 too.
        let c32 = |t: f32| Ok::<_, ()>((1e6 * (1.0 + 400.0 * (t - 0.2) * (t - 0.2)), 100));
        let f = fit_lag(0.111f32, c32).unwrap();
        assert!((f.lag_s - 0.2).abs() < 1e-3, "{f:?}");
    }
}
