//! Load-swing observer: the horizontal pull of a swinging hook load on the
//! boom tip, predicted from the measured boom motion.
//!
//! ## Why the limiter needs it
//!
//! Luffing moves the boom tip sideways; the load, hanging from a rope of
//! 15–20 m, lags behind and swings at its pendulum frequency √(g/l)
//! (0.11–0.13 Hz, a 7–9 s period). The rope then pulls the tip with a
//! horizontal force W·g·tan φ besides the weight W·g (φ: rope angle from the
//! vertical, positive outward). About the boom foot A0 that force has the arm
//! of the tip height, L·sin θ, where the weight has L·cos θ, so the piston
//! force carries an extra W·g·tan φ·L·sin θ/arm = per_kg·W·tan θ·tan φ, i.e. the
//! quasi-static inversion reads the load too high by the factor
//! (1 + tan θ·tan φ). Measured on the flexible model (no sensor error, true
//! angle, between t1 and t2): the swing of a thesis maneuver reaches 1.4–2.6°
//! (30 s) and 4.5–8° (10 s), and the quasi-static inversion of the simulated
//! piston force is off by −21 %…+8 % (30 s) and −54 %…+17 % (10 s). No
//! low-pass can remove a 0.12 Hz term without delaying an overload by seconds,
//! so the limiter predicts it instead.
//!
//! ## The observer
//!
//! The load's horizontal position x_L follows the tip's, x_C, as an undamped
//! pendulum of the present hanging length l (small angles; the hoist keeps the
//! load at a fixed clearance above the ground, so l = y_A0 + L·sin θ − h):
//!
//! ẍ_L = −(g/l)·(x_L − x_C),  tan φ ≈ (x_L − x_C)/l,
//!
//! driven by x_C = L·cos θ from the measured (lag-compensated) boom angle. It
//! needs no derivative of the noisy angle: the tip position enters as a
//! position. It is integrated with the symplectic Euler rule in sub-steps of at
//! most 5 ms (ω·h < 0.005: no numerical damping or growth worth speaking of).
//!
//! It is open loop: it starts with the load hanging still (power-up, and after
//! a sensor fault interrupted the angle, [`SwingObserver::reset`]) and
//! knows nothing of swing caused otherwise (slewing, wind, a load lifted off
//! the ground while swinging). Like the model it is undamped, so a
//! prediction error persists until the next reset; the correction is clamped
//! to |tan φ| ≤ 0.5 (27°; it was 0.2 while this observer was the only one:
//! now it is one hypothesis of [`crate::static_load`], chosen only while its
//! load stays the steadiest). These limits are stated in the crate's README and
//! belong to the certification argument: the observer removes the swing the
//! luffing motion itself causes, which is what the thesis maneuvers show.

use crane_model::Real;

/// Geometry the observer needs (COLES Mobile 930 in [`SwingGeometry::coles_930`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwingGeometry<T> {
    /// Boom length from the foot pin A0 to the tip C (m).
    pub boom_length_m: T,
    /// Height of the foot pin A0 above the ground (m).
    pub foot_height_m: T,
    /// Height at which the hoist keeps the load above the ground (m).
    pub load_clearance_m: T,
    /// Gravity (m/s²).
    pub gravity_m_s2: T,
}

impl<T: Real> SwingGeometry<T> {
    /// The thesis crane: L = 19.5 m, A0 2.57 m high, load 1 m above ground.
    pub fn coles_930() -> Self {
        let crane = crane_model::CraneData::coles_mobile_930();
        Self {
            boom_length_m: T::lit(crane.boom.length_m()),
            foot_height_m: T::lit(crane.boom_foot[1]),
            load_clearance_m: T::lit(crane.rope.load_clearance_m),
            gravity_m_s2: T::lit(crane.gravity_m_s2),
        }
    }

    /// `true` when all values are finite and the lengths and g positive.
    pub fn is_valid(&self) -> bool {
        let pos = |x: T| x.is_finite() && x > T::lit(0.0);
        pos(self.boom_length_m)
            && self.foot_height_m.is_finite()
            && self.load_clearance_m.is_finite()
            && pos(self.gravity_m_s2)
    }

    /// Tip position relative to A0 (horizontal) and hanging length (m).
    /// Height of the tip C above the ground at boom angle `angle_rad` (m).
    pub fn tip_height_m(&self, angle_rad: T) -> T {
        let (sin, _) = angle_rad.sin_cos_own();
        self.foot_height_m + self.boom_length_m * sin
    }

    fn tip(&self, angle_rad: T) -> (T, T) {
        // Own-precision trigonometry: libm's f32 sin/cos run f64 kernels.
        let (sin, cos) = angle_rad.sin_cos_own();
        let x = self.boom_length_m * cos;
        let l = self.foot_height_m + self.boom_length_m * sin - self.load_clearance_m;
        (x, l.max(T::lit(0.5)))
    }
}

/// Largest |tan φ| the observer reports.
pub const MAX_TAN_SWING: f64 = 0.5;

/// The swing state: load position and velocity, last tip position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwingObserver<T> {
    geometry: SwingGeometry<T>,
    /// (x_L, ẋ_L, x_C, l) after the last update; `None` before the first.
    state: Option<(T, T, T, T)>,
}

impl<T: Real> SwingObserver<T> {
    /// An observer that will start with the load hanging still.
    pub fn new(geometry: SwingGeometry<T>) -> Self {
        Self {
            geometry,
            state: None,
        }
    }

    /// Forgets the swing: the next update starts with the load hanging still.
    pub fn reset(&mut self) {
        self.state = None;
    }

    /// Moves the tip to `angle_rad` at once, keeping the load's position and
    /// velocity relative to it (a restart of the filtered angle, not a move).
    pub fn rebase(&mut self, angle_rad: T) {
        if let Some((x, v, xc0, _)) = self.state {
            let (xc1, l1) = self.geometry.tip(angle_rad);
            self.state = Some((x + (xc1 - xc0), v, xc1, l1));
        }
    }

    /// Advances to boom angle `angle_rad`, `dt_s` after the previous update;
    /// returns tan φ (positive: load outward of the tip), clamped.
    pub fn update(&mut self, angle_rad: T, dt_s: T) -> T {
        let (xc1, l1) = self.geometry.tip(angle_rad);
        let g = self.geometry.gravity_m_s2;
        let (mut x, mut v) = match self.state {
            None => (xc1, T::lit(0.0)),
            Some((x, v, xc0, l0)) => {
                let dt = if dt_s > T::lit(0.0) && dt_s.is_finite() {
                    dt_s
                } else {
                    T::lit(0.0)
                };
                // Sub-steps of at most 5 ms, at most 200 (a 1 s gap).
                let n = (dt / T::lit(0.005))
                    .ceil()
                    .max(T::lit(1.0))
                    .min(T::lit(200.0));
                let h = dt / n;
                let (mut x, mut v) = (x, v);
                let mut k = T::lit(1.0);
                while k <= n {
                    let s = k / n;
                    let xc = xc0 + (xc1 - xc0) * s;
                    let l = l0 + (l1 - l0) * s;
                    v -= g / l * (x - xc) * h;
                    x += v * h;
                    k += T::lit(1.0);
                }
                (x, v)
            }
        };
        if !(x.is_finite() && v.is_finite()) {
            (x, v) = (xc1, T::lit(0.0));
        }
        self.state = Some((x, v, xc1, l1));
        let lim = T::lit(MAX_TAN_SWING);
        ((x - xc1) / l1).max(-lim).min(lim)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn still_boom_gives_no_swing_and_a_step_rings_at_the_pendulum_period() {
        let g = SwingGeometry::<f64>::coles_930();
        let mut o = SwingObserver::new(g);
        let a0 = 50f64.to_radians();
        for _ in 0..100 {
            assert_eq!(o.update(a0, 0.01), 0.0);
        }
        // Move the tip by 0.1 m at once: the load then swings about the new
        // tip position with amplitude 0.1 m and period 2π√(l/g).
        let a1 = ((g.boom_length_m * a0.cos() - 0.1) / g.boom_length_m).acos();
        let l = g.foot_height_m + g.boom_length_m * a1.sin() - g.load_clearance_m;
        let period = 2.0 * core::f64::consts::PI * (l / g.gravity_m_s2).sqrt();
        let mut prev = o.update(a1, 0.01);
        assert!((prev - 0.1 / l).abs() < 1e-3, "{prev}");
        let mut crossings = vec![];
        for k in 2..3000 {
            let t = f64::from(k) * 0.01;
            let p = o.update(a1, 0.01);
            assert!(p.abs() <= 0.1 / l * 1.001);
            if prev > 0.0 && p <= 0.0 || prev < 0.0 && p >= 0.0 {
                crossings.push(t);
            }
            prev = p;
        }
        let half = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
        assert!(
            (2.0 * half - period).abs() < 0.02,
            "{} vs {period}",
            2.0 * half
        );
    }
}
