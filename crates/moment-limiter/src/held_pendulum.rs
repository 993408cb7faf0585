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
//! integrated with the symplectic Euler rule in sub-steps of at most
//! [`MAX_SUB_STEP_S`] (one per cycle at 100 Hz), at most [`MAX_SUB_STEPS`]
//! per call.

use crane_model::Real;

/// The largest swing the observer follows (rad, 60°); beyond, or on a
/// non-finite state, it restarts with the load hanging still.
const MAX_SWING_RAD: f64 = 1.047;

/// Longest sub-step of the pendulum's integration (s). The symplectic Euler
/// rule runs a free pendulum at (2/h)·asin(ω·h/2) instead of ω: with the
/// shortest rope of the bank (3 m, ω = 1.81 rad/s) and h = 10 ms that is
/// 1.4e-5 fast, 1.2 ms of phase over an hour-long swing, far below the 12 %
/// between neighbouring ropes of the bank. At 100 Hz one sub-step per cycle.
pub const MAX_SUB_STEP_S: f64 = 0.010;

/// Most sub-steps per update (a 4 s gap at [`MAX_SUB_STEP_S`]; a longer gap
/// takes longer sub-steps, still stable while ω·h < 2).
pub const MAX_SUB_STEPS: u32 = 400;

/// What every pendulum on one boom needs from the boom's motion over an
/// update, computed once for a bank of them ([`BoomTip::new`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoomTip<T> {
    /// The tip's horizontal acceleration ẍ_C (m/s²).
    pub accel_x: T,
    /// The tip's vertical acceleration ÿ_C (m/s²).
    pub accel_y: T,
    /// tan θ of the boom angle.
    pub tan_angle: T,
    /// Number of sub-steps (≥ 1) and their length h (s, ≥ 0).
    pub sub_steps: u32,
    /// Length of each sub-step (s).
    pub h_s: T,
}

impl<T: Real> BoomTip<T> {
    /// The tip's motion for a boom of `boom_length_m` whose angle has
    /// (sin θ, cos θ) = `trig`, with rate and acceleration (rad/s, rad/s²)
    /// held over a step of `dt_s` (a non-finite or negative step counts 0).
    pub fn new((s, c): (T, T), boom_length_m: T, rate_rad_s: T, accel_rad_s2: T, dt_s: T) -> Self {
        let w2 = rate_rad_s * rate_rad_s;
        let dt = if dt_s.is_finite() && dt_s > T::lit(0.0) {
            dt_s
        } else {
            T::lit(0.0)
        };
        // The count by a bounded loop (no libm ceil in the cycle); at
        // 100 Hz it stops at once.
        let sub = T::lit(MAX_SUB_STEP_S);
        let mut n = 1u32;
        while n < MAX_SUB_STEPS && T::from_count(n) * sub < dt {
            n += 1;
        }
        Self {
            accel_x: -boom_length_m * (s * accel_rad_s2 + c * w2),
            accel_y: boom_length_m * (c * accel_rad_s2 - s * w2),
            tan_angle: s / c,
            sub_steps: n,
            h_s: dt / T::from_count(n),
        }
    }
}

/// The pendulum state of one hanging length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeldPendulum<T> {
    length_m: T,
    /// 1/l and 1/g: the update multiplies (a bank of ten ropes updates 100
    /// times a second, and a division costs several multiplications).
    inv_length: T,
    inv_gravity: T,
    boom_length_m: T,
    gravity_m_s2: T,
    /// (φ, φ̇); `None` before the first update.
    state: Option<(T, T)>,
    /// (sin φ, cos φ) of `state`'s φ, kept because the next update's first
    /// sub-step and [`Self::tan_swing`] need them again: at 100 Hz one
    /// evaluation per update.
    trig: (T, T),
    factor: T,
}

impl<T: Real> HeldPendulum<T> {
    /// A load hanging still on a rope of `length_m` from the tip of a boom
    /// of `boom_length_m`, gravity `gravity_m_s2`.
    pub fn new(length_m: T, boom_length_m: T, gravity_m_s2: T) -> Self {
        Self {
            length_m,
            inv_length: T::lit(1.0) / length_m,
            inv_gravity: T::lit(1.0) / gravity_m_s2,
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
        let tip = BoomTip::new(angle_rad.sin_cos_own(), self.boom_length_m, rate_rad_s, accel_rad_s2, dt_s);
        self.update_with(&tip)
    }

    /// [`Self::update`] with the boom's motion given as its tip's
    /// ([`BoomTip`]), which a bank of pendulums on one boom computes once
    /// for all.
    pub fn update_with(&mut self, tip: &BoomTip<T>) -> T {
        let (g, inv_l, h) = (self.gravity_m_s2, self.inv_length, tip.h_s);
        let (ax, ay) = (tip.accel_x, tip.accel_y);
        let (mut phi, mut phi_dot) = self.state.unwrap_or((T::lit(0.0), T::lit(0.0)));
        // sin φ and cos φ of the state φ are kept from the previous update.
        let (mut sp, mut cp) = if self.state.is_some() { self.trig } else { phi.sin_cos_own() };
        let mut k = 0u32;
        while k < tip.sub_steps {
            if k > 0 {
                (sp, cp) = phi.sin_cos_own();
            }
            let acc = -(g * sp + ax * cp + ay * sp) * inv_l;
            phi_dot += acc * h;
            phi += phi_dot * h;
            k += 1;
        }
        if !(phi.is_finite() && phi_dot.is_finite() && phi.abs() <= T::lit(MAX_SWING_RAD)) {
            (phi, phi_dot) = (T::lit(0.0), T::lit(0.0));
        }
        self.state = Some((phi, phi_dot));
        let (sp, cp) = phi.sin_cos_own();
        self.trig = (sp, cp);
        let tension = g * cp - ax * sp + ay * cp + self.length_m * phi_dot * phi_dot;
        self.factor = tension * self.inv_gravity * (cp + tip.tan_angle * sp);
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
