//! A load on a held rope of constant length, as a full (large-angle)
//! pendulum hanging from the moving boom tip: its swing and the force its
//! rope puts on the tip ([`crate::static_load`]'s held-rope hypotheses).
//!
//! The tip C = (x_C, y_C) = L·(cos θ, sin θ) from the boom foot (rigid boom;
//! x outward), the load at C + l·(sin φ, −cos φ) (φ from the vertical,
//! positive outward), rope tension T. Newton for the load, projected across
//! and along the rope:
//!
//! l·φ̈ = −g·sin φ − ẍ_C·cos φ − ÿ_C·sin φ,
//! T/m = g·cos φ − ẍ_C·sin φ + ÿ_C·cos φ + l·φ̇²,
//!
//! with ẍ_C = −L·(sin θ·θ̈ + cos θ·θ̇²), ÿ_C = L·(cos θ·θ̈ − sin θ·θ̇²). The
//! rope pulls the tip with T·(sin φ, −cos φ); about the boom foot its
//! moment is that of a hanging weight m·g times
//!
//! factor = (T/(m·g))·(cos φ + tan θ·sin φ),
//!
//! which is 1 for a load hanging still and includes the load riding up and
//! down with the tip (ÿ_C) and the swing's twice-per-period pull (at 25° of
//! swing T·cos φ varies by ±19 %, which the small-angle model misses). It is
//! integrated with the symplectic Euler rule in sub-steps of at most 5 ms,
//! at most 400 per call (a 2 s gap; longer gaps take longer, still stable,
//! sub-steps while ω·h < 2).

use crane_model::Real;

/// The largest swing the observer follows (rad, 60°); beyond, or on a
/// non-finite state, it restarts with the load hanging still.
const MAX_SWING_RAD: f64 = 1.047;

/// The pendulum state of one hanging length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeldPendulum<T> {
    length_m: T,
    boom_length_m: T,
    gravity_m_s2: T,
    /// (φ, φ̇); `None` before the first update.
    state: Option<(T, T)>,
    /// (sin φ, cos φ) of `state`'s φ, kept because the next update's first
    /// sub-step and [`Self::tan_swing`] need them again (a bank of ten ropes
    /// calls this 100 times a second: the trigonometry is its main cost).
    trig: (T, T),
    factor: T,
}

impl<T: Real> HeldPendulum<T> {
    /// A load hanging still on a rope of `length_m` from the tip of a boom
    /// of `boom_length_m`, gravity `gravity_m_s2`.
    pub fn new(length_m: T, boom_length_m: T, gravity_m_s2: T) -> Self {
        Self {
            length_m,
            boom_length_m,
            gravity_m_s2,
            state: None,
            trig: (T::lit(0.0), T::lit(1.0)),
            factor: T::lit(1.0),
        }
    }

    /// The hanging length (m).
    pub fn length_m(&self) -> T {
        self.length_m
    }

    /// Forgets the swing.
    pub fn reset(&mut self) {
        self.state = None;
        self.trig = (T::lit(0.0), T::lit(1.0));
        self.factor = T::lit(1.0);
    }

    /// tan φ now.
    pub fn tan_swing(&self) -> T {
        // Own-precision trigonometry (no libm in the cycle); |φ| ≤ 60°.
        self.state.map_or(T::lit(0.0), |_| self.trig.0 / self.trig.1)
    }

    /// The factor of the load's pull on the cylinder now (see the module doc).
    pub fn factor(&self) -> T {
        self.factor
    }

    /// Advances by `dt_s` with the boom at angle, rate and acceleration
    /// (rad, rad/s, rad/s²) held over the step; returns the factor.
    pub fn update(&mut self, angle_rad: T, rate_rad_s: T, accel_rad_s2: T, dt_s: T) -> T {
        // Own-precision trigonometry: libm's f32 sin/cos run f64 kernels.
        self.update_at(angle_rad.sin_cos_own(), rate_rad_s, accel_rad_s2, dt_s)
    }

    /// [`Self::update`] with the boom angle given by its (sin, cos), which a
    /// bank of pendulums on one boom computes once for all.
    pub fn update_at(&mut self, (s, c): (T, T), rate_rad_s: T, accel_rad_s2: T, dt_s: T) -> T {
        let (l, bl, g) = (self.length_m, self.boom_length_m, self.gravity_m_s2);
        let w2 = rate_rad_s * rate_rad_s;
        let ax = -bl * (s * accel_rad_s2 + c * w2);
        let ay = bl * (c * accel_rad_s2 - s * w2);
        let (mut phi, mut phi_dot) = self.state.unwrap_or((T::lit(0.0), T::lit(0.0)));
        let dt = if dt_s.is_finite() && dt_s > T::lit(0.0) {
            dt_s
        } else {
            T::lit(0.0)
        };
        // Sub-steps of at most 5 ms (two at 100 Hz), at most 400: the
        // count found by a bounded loop (no libm ceil in the cycle).
        let sub = T::lit(0.005);
        let mut n = T::lit(1.0);
        while n < T::lit(400.0) && n * sub < dt {
            n += T::lit(1.0);
        }
        let h = dt / n;
        let mut k = T::lit(1.0);
        // sin φ and cos φ of the state φ are kept from the previous update.
        let mut trig = if self.state.is_some() { self.trig } else { phi.sin_cos_own() };
        while k <= n {
            let (sp, cp) = if k > T::lit(1.0) { phi.sin_cos_own() } else { trig };
            let acc = -(g * sp + ax * cp + ay * sp) / l;
            phi_dot += acc * h;
            phi += phi_dot * h;
            k += T::lit(1.0);
        }
        if !(phi.is_finite() && phi_dot.is_finite() && phi.abs() <= T::lit(MAX_SWING_RAD)) {
            (phi, phi_dot) = (T::lit(0.0), T::lit(0.0));
        }
        self.state = Some((phi, phi_dot));
        trig = phi.sin_cos_own();
        self.trig = trig;
        let (sp, cp) = trig;
        let tension = g * cp - ax * sp + ay * cp + l * phi_dot * phi_dot;
        self.factor = tension / g * (cp + s / c * sp);
        self.factor
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hanging_still_the_factor_is_one_and_riding_up_adds_the_tip_acceleration() {
        let mut p = HeldPendulum::new(8.0_f64, 19.5, 9.81);
        let th = 40f64.to_radians();
        for _ in 0..100 {
            assert!((p.update(th, 0.0, 0.0, 0.01) - 1.0).abs() < 1e-12);
        }
        // First instant of an upward angular acceleration: the load is still
        // vertical, its weight grows by ÿ_C/g.
        let f = p.update(th, 0.0, 0.1, 1e-6);
        let expect = 1.0 + 19.5 * th.cos() * 0.1 / 9.81;
        assert!((f - expect).abs() < 1e-4, "{f} vs {expect}");
    }

    #[test]
    fn a_free_swing_keeps_its_period_and_pulls_twice_per_period() {
        // Released at 25° at a still boom at 0° (tan θ = 0): the factor is
        // T·cos φ/(m·g), cos²25° = 0.82 at the ends, 1 + 2(1 − cos 25°)
        // = 1.19 at the bottom.
        let l = 3.0_f64;
        let mut p = HeldPendulum::new(l, 19.5, 9.81);
        p.state = Some((25f64.to_radians(), 0.0));
        let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
        for _ in 0..1000 {
            let f = p.update(0.0, 0.0, 0.0, 0.01);
            lo = lo.min(f);
            hi = hi.max(f);
        }
        assert!((lo - 25f64.to_radians().cos().powi(2)).abs() < 0.01, "{lo}");
        assert!(
            (hi - (3.0 - 2.0 * 25f64.to_radians().cos())).abs() < 0.01,
            "{hi}"
        );
    }
}
