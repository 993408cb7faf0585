//! Load swing: why the horizontal pull of a swinging hook load matters to
//! the limiter, and the geometry the rope bank's pendulums share.
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
//! ## Where it is predicted
//!
//! The swing is not measured; the rope bank of [`crate::static_load`]
//! predicts it for every rope it considers, each a large-angle pendulum
//! driven by the tip's measured motion ([`crate::held_pendulum`]: the held
//! ropes of constant length, and the paid-out rope whose length is the
//! tip's height less the clearance, [`SwingGeometry::paid_out_length_m`]).
//! This module holds the geometry they share.
//!
//! The prediction is open loop: it knows nothing of swing caused otherwise
//! (slewing, wind, a load lifted off the ground while swinging), and like
//! the thesis model it is undamped, so an error persists. These limits are
//! stated in `docs/limiter.md` and belong to the certification argument:
//! the bank removes the swing the luffing motion itself causes, which is
//! what the thesis maneuvers show.

use crane_model::Real;

/// The most a load's pendulum is lengthened by the boom's give (m): the
/// COLES 930's tip gives 0.34 m at 80° under 12 t; a weighing far above
/// the chart (a fault's) must not detune the pendulums further.
pub const MAX_GIVE_M: f64 = 0.5;

/// Geometry the rope pendulums need (COLES Mobile 930 in [`SwingGeometry::coles_930`]).
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
    /// The boom tip's static compliance across the boom (m/N): how far the
    /// tip gives under a swinging load's pull, which lengthens the load's
    /// pendulum ([`Self::give_m`]).
    pub tip_compliance_m_per_n: T,
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
            tip_compliance_m_per_n: T::lit(f64::from(
                crane_model::loads::thesis_modes::THESIS_MODES_F32.tip_compliance_across_m_per_n(),
            )),
        }
    }

    /// `true` when all values are finite and the lengths and g positive.
    pub fn is_valid(&self) -> bool {
        let pos = |x: T| x.is_finite() && x > T::lit(0.0);
        pos(self.boom_length_m)
            && self.foot_height_m.is_finite()
            && self.load_clearance_m.is_finite()
            && pos(self.gravity_m_s2)
            && self.tip_compliance_m_per_n.is_finite()
            && self.tip_compliance_m_per_n >= T::lit(0.0)
    }

    /// Height of the tip C above the ground at boom angle `angle_rad` (m).
    pub fn tip_height_m(&self, angle_rad: T) -> T {
        let (sin, _) = angle_rad.sin_cos_own();
        self.foot_height_m + self.boom_length_m * sin
    }

    /// How much longer than its rope a load of `load_kg` swings at a boom
    /// angle θ of sin θ = `sin_angle` (m), its tip giving (see
    /// [`crate::held_pendulum`], "The boom's give"): c·sin²θ·g·W, c the tip's
    /// compliance across the boom, sin θ the part of a horizontal pull across
    /// it and again the horizontal part of the tip's move. No load or a
    /// non-finite one gives nothing; at most [`MAX_GIVE_M`].
    pub fn give_m(&self, sin_angle: T, load_kg: T) -> T {
        self.tip_move_m(sin_angle, sin_angle, load_kg)
    }

    /// How far out the tip moves when a hook load of `load_kg` hangs from
    /// it at a boom angle θ of (sin θ, cos θ) = `(sin_angle, cos_angle)` (m):
    /// c·g·W·cos θ·sin θ, the load's pull across the boom (g·W·cos θ) on the
    /// tip's compliance c across it, of which the horizontal part is sin θ
    /// (see [`crate::static_load`], "A lift-off: the boom's give swings the
    /// load"). No load or a non-finite one moves nothing; at most
    /// [`MAX_GIVE_M`].
    pub fn tip_shift_m(&self, (sin_angle, cos_angle): (T, T), load_kg: T) -> T {
        self.tip_move_m(sin_angle, cos_angle, load_kg)
    }

    /// c·a·b·g·W (m): how far the tip moves horizontally under a load W on
    /// its compliance c across the boom, a·b the geometry (sin²θ for the
    /// give's horizontal pull, sin θ·cos θ for the shift's vertical load).
    /// No move or a non-finite one is none; at most [`MAX_GIVE_M`].
    // Never inlined: its two inlined copies (give, shift) took 0.09 KB
    // more of the board's 64 KiB flash than one function.
    #[inline(never)]
    fn tip_move_m(&self, a: T, b: T, load_kg: T) -> T {
        let moved = self.tip_compliance_m_per_n * a * b * self.gravity_m_s2 * load_kg;
        if moved.is_finite() && moved > T::lit(0.0) {
            moved.min(T::lit(MAX_GIVE_M))
        } else {
            T::lit(0.0)
        }
    }

    /// The paid-out rope's hanging length at boom angle `angle_rad` (m):
    /// the tip's height less the clearance, at least 0.5 m.
    pub fn paid_out_length_m(&self, angle_rad: T) -> T {
        (self.tip_height_m(angle_rad) - self.load_clearance_m).max(T::lit(0.5))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_give_grows_with_the_load_and_the_angle_and_is_bounded() {
        let g = SwingGeometry::<f64>::coles_930();
        let give = |deg: f64, kg: f64| g.give_m(deg.to_radians().sin(), kg);
        // 3.01e-6 m/N across the boom: at 70°, sin²θ·g = 8.66 m/s², so
        // 11 t lengthens the pendulum by 0.287 m (2.66 mm per kN of load).
        assert!((give(70.0, 11_000.0) - 0.287).abs() < 0.002, "{}", give(70.0, 11_000.0));
        assert!((give(40.0, 11_000.0) / give(80.0, 11_000.0) - (40f64.to_radians().sin() / 80f64.to_radians().sin()).powi(2)).abs() < 1e-12);
        assert_eq!(give(0.0, 11_000.0), 0.0);
        for bad in [0.0, -5_000.0, f64::NAN, f64::INFINITY] {
            assert_eq!(give(70.0, bad), 0.0, "{bad}");
        }
        assert_eq!(give(80.0, 1.0e6), MAX_GIVE_M);
    }

    #[test]
    fn the_tip_moves_out_under_a_load_by_the_same_compliance() {
        let g = SwingGeometry::<f64>::coles_930();
        let shift = |deg: f64, kg: f64| g.tip_shift_m(deg.to_radians().sin_cos(), kg);
        // 9 t at 80°: 3.01e-6 m/N × 9.81 × sin 80° cos 80° × 9000 = 4.55 cm;
        // the simulator's tip deflection grows by 4.6 cm (`crane-sim simulate
        // --from-deg 80 --lift-off-s 0.3 --load-kg 9000 --rope held
        // --rope-length-m 3`, node 13).
        assert!((shift(80.0, 9_000.0) - 0.0455).abs() < 0.0005, "{}", shift(80.0, 9_000.0));
        // One compliance across the boom: a horizontal pull's give is the
        // vertical load's shift times tan θ.
        for deg in [20.0f64, 45.0, 70.0] {
            let (s, c) = deg.to_radians().sin_cos();
            assert!((shift(deg, 5_000.0) * s / c - g.give_m(s, 5_000.0)).abs() < 1e-12, "{deg}");
        }
        for bad in [0.0, -5_000.0, f64::NAN, f64::INFINITY] {
            assert_eq!(shift(60.0, bad), 0.0, "{bad}");
        }
        assert_eq!(shift(45.0, 1.0e6), MAX_GIVE_M);
    }
}
