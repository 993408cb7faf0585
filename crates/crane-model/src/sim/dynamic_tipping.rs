//! The thesis's dynamic tipping search (§4.3.2): the boom lowered at the
//! cycloidal profile's speed until the rear-jack reaction F_A crosses zero.
//! It runs the simulator, so it lives here and not with the static tipping
//! load of [`crate::loads::tipping`], which the limiter's path uses.

use crate::data::profile::RampShape;
use crate::multibody::CraneModel;
use crate::sim::simulation::{Direction, Maneuver, SimulationOptions};
use crate::{ModelError, Real};

impl<T: Real, const M: usize> CraneModel<T, M> {
    /// The thesis's dynamic tipping search (§4.3.2): lower the boom from 80° with the
    /// 30 s cycloidal profile's speed, carrying `load_kg`, until F_A ≤ 0. Returns the
    /// boom angle (rad) at the zero crossing, or `None` if it reaches `lowest_deg`.
    pub fn dynamic_tipping_angle(&self, load_kg: f64, lowest_deg: f64, options: &SimulationOptions) -> Result<Option<T>, ModelError> {
        let thesis = Maneuver::thesis(load_kg, 30.0, RampShape::Cycloidal, Direction::Down)?;
        let v0 = self.stroke(&thesis).v0_m_s().to_f64().abs();
        let a_hi = self.geometry.extension_at_angle(T::lit(80f64.to_radians())).to_f64();
        let a_lo = self.geometry.extension_at_angle(T::lit(lowest_deg.to_radians())).to_f64();
        let ramp = thesis.t1_s;
        let t3 = (a_hi - a_lo).abs() / v0 + ramp;
        let maneuver = Maneuver { t1_s: ramp, t2_s: t3 - ramp, t3_s: t3, low_angle_deg: lowest_deg, high_angle_deg: 80.0, settle_s: 0.0, ..thesis };
        let mut previous: Option<(T, T)> = None;
        let mut found = None;
        self.simulate(&maneuver, options, |s| {
            let (angle, fa) = (s.boom_angle_rad, s.reactions.jack_reaction_n);
            if fa <= T::zero() {
                found = Some(match previous {
                    Some((a0, f0)) if f0 > T::zero() => a0 + (angle - a0) * f0 / (f0 - fa),
                    _ => angle,
                });
                return false;
            }
            previous = Some((angle, fa));
            true
        })?;
        Ok(found)
    }
}
