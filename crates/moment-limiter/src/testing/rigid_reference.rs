//! A rigid, quasi-static stand-in for the crane model.
//!
//! **Not the product's model.** The limiter is meant to run on the flexible
//! multibody model of `crane-model`; until that is wired in, this closed form
//! lets the limiter, its tests, the example logs and `crane-sim replay` run.
//! It uses the geometry of SPEC §2 (pins A0, B0, the lug A0–D, the tipping line
//! and the chassis weight) with a rigid boom of assumed mass and centre of
//! mass, massless cylinder and rope, and no dynamics (the rate is ignored).
//!
//! Moments about the boom foot A0 give the piston force:
//! F·((D − A0) × û) = g·cos θ·(m_boom·r_cg + W·L), û the unit vector B0→D;
//! moments about the front jack (the tipping line) give the rear-jack reaction:
//! F_A·s = G_chassis·(x_f − x_ch) + m_boom·g·(x_f − x_cg) − W·g·(x_C − x_f).

use crane_model::loads::load_model::{Affine, BoomState, HookLoadModel, Quadratic};
use crane_model::{ModelError, Real};

/// Parameters of the rigid stand-in (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidCrane<T> {
    /// Boom foot pin A0 (x, y), m.
    pub a0: (T, T),
    /// Cylinder foot pin B0 (x, y), m.
    pub b0: (T, T),
    /// Boom length A0→C (m).
    pub boom_length_m: T,
    /// Length of the lug A0–D (m).
    pub lug_length_m: T,
    /// Angle of the lug below the boom axis (rad).
    pub lug_angle_rad: T,
    /// Boom mass (kg) — assumed, not from the thesis.
    pub boom_mass_kg: T,
    /// Distance A0 → boom centre of mass along the boom (m) — assumed.
    pub boom_cg_m: T,
    /// Chassis weight (N) and its x (m).
    pub chassis_weight_n: T,
    /// x of the chassis weight (m).
    pub chassis_x_m: T,
    /// x of the tipping line, the front jack (m).
    pub front_jack_x_m: T,
    /// Distance between front and rear jack (m) — assumed.
    pub jack_spacing_m: T,
    /// Gravity (m/s²).
    pub gravity: T,
}

impl<T: Real> RigidCrane<T> {
    /// SPEC §2 geometry with an assumed 2 500 kg boom whose centre of mass is
    /// 7.5 m from A0, and a 5 m jack spacing.
    pub fn coles_930() -> Self {
        Self {
            a0: (T::lit(2.775), T::lit(2.57)),
            b0: (T::lit(5.125), T::lit(1.765)),
            boom_length_m: T::lit(19.5),
            lug_length_m: T::lit(5.85),
            lug_angle_rad: T::lit(0.096_731_98),
            boom_mass_kg: T::lit(2500.0),
            boom_cg_m: T::lit(7.5),
            chassis_weight_n: T::lit(222_792.772),
            chassis_x_m: T::lit(3.18),
            front_jack_x_m: T::lit(7.305),
            jack_spacing_m: T::lit(5.0),
            gravity: T::lit(9.81),
        }
    }

    /// Lever arm (m) of the cylinder force about A0 at boom angle θ.
    fn cylinder_arm_m(&self, angle_rad: T) -> Result<T, ModelError> {
        let phi = angle_rad - self.lug_angle_rad;
        let dx = self.lug_length_m * phi.cos();
        let dy = self.lug_length_m * phi.sin();
        let (ux, uy) = (self.a0.0 + dx - self.b0.0, self.a0.1 + dy - self.b0.1);
        let len = (ux * ux + uy * uy).sqrt();
        if !len.is_finite() || len <= T::lit(1e-6) {
            return Err(ModelError::Singular("cylinder length"));
        }
        let arm = (dx * uy - dy * ux) / len;
        if arm > T::lit(1e-3) {
            Ok(arm)
        } else {
            Err(ModelError::OutOfReach)
        }
    }
}

impl<T: Real> HookLoadModel<T> for RigidCrane<T> {
    fn piston_force_n(&self, boom: BoomState<T>) -> Result<Quadratic<T>, ModelError> {
        let arm = self.cylinder_arm_m(boom.angle_rad)?;
        let gc = self.gravity * boom.angle_rad.cos() / arm;
        Ok(Quadratic::linear(Affine {
            at_zero: gc * self.boom_mass_kg * self.boom_cg_m,
            per_kg: gc * self.boom_length_m,
        }))
    }

    /// A uniform boom of the stand-in's mass and length: m·L²/3 about A0.
    fn piston_force_per_boom_accel(&self, boom_angle_rad: T) -> Result<T, ModelError> {
        let arm = self.cylinder_arm_m(boom_angle_rad)?;
        Ok(self.boom_mass_kg * self.boom_length_m * self.boom_length_m / (T::lit(3.0) * arm))
    }

    fn jack_reaction_n(&self, boom: BoomState<T>) -> Result<Affine<T>, ModelError> {
        let c = boom.angle_rad.cos();
        let x_cg = self.a0.0 + self.boom_cg_m * c;
        let x_tip = self.a0.0 + self.boom_length_m * c;
        let xf = self.front_jack_x_m;
        Ok(Affine {
            at_zero: (self.chassis_weight_n * (xf - self.chassis_x_m)
                + self.boom_mass_kg * self.gravity * (xf - x_cg))
                / self.jack_spacing_m,
            per_kg: -self.gravity * (x_tip - xf) / self.jack_spacing_m,
        })
    }

    fn radius_m(&self, boom_angle_rad: T) -> T {
        T::lit(19.5) * boom_angle_rad.cos() - T::lit(1.83)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(deg: f64) -> BoomState<f64> {
        BoomState {
            angle_rad: deg.to_radians(),
            rate_rad_s: 0.0,
        }
    }

    #[test]
    fn plausible_numbers() {
        let m = RigidCrane::<f64>::coles_930();
        // 3.3 t at 45°: some tens of bar on a Ø230 piston, positive force.
        let f = m.piston_force_n(at(45.0)).unwrap().at(3300.0);
        let p1_bar = f / (core::f64::consts::PI * 0.115 * 0.115) / 1e5;
        assert!((30.0..120.0).contains(&p1_bar), "{p1_bar}");
        // Tipping load falls as the boom is lowered.
        let tip = |deg: f64| {
            let j = m.jack_reaction_n(at(deg)).unwrap();
            -j.at_zero / j.per_kg
        };
        assert!(tip(40.0) < tip(50.0) && tip(50.0) < tip(60.0));
        // At 80° the hook is inside the tipping line: the load cannot tip it.
        assert!(m.jack_reaction_n(at(80.0)).unwrap().per_kg > 0.0);
    }
}
