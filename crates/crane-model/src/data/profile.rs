//! The prescribed motion of the luffing cylinder (thesis §3.3.1 f, eqs. 3.47–3.49).
//!
//! The piston moves relative to the cylinder with a velocity that rises from zero
//! to v0 in t1, stays at v0 until t2 and falls back to zero at t3, with a linear
//! (eq. 3.48) or cycloidal (eq. 3.47) ramp. v0 is chosen so the stroke takes the
//! boom from its start angle to its end angle in t3. Positions, velocities and
//! accelerations are closed forms, so the integrator never integrates the profile.

use crate::Real;

/// The shape of the acceleration and deceleration ramps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RampShape {
    /// Velocity linear in time (eq. 3.48): the acceleration jumps at 0, t1, t2, t3.
    Linear,
    /// Cycloidal (eq. 3.47, whose acceleration is v0/t1·(1 − cos 2πt/t1)): smooth.
    Cycloidal,
}

/// The actuator extension and its first two time derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ActuatorMotion<T> {
    /// Position a of the piston B from the cylinder foot pin B0 along the cylinder (m).
    pub extension_m: T,
    /// da/dt (m/s).
    pub rate_m_s: T,
    /// d²a/dt² (m/s²).
    pub accel_m_s2: T,
}

/// A velocity profile from `start_m` to `end_m` of extension.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrokeProfile<T> {
    /// Ramp shape.
    pub shape: RampShape,
    /// End of the acceleration ramp t1 (s).
    pub t1_s: T,
    /// Start of the deceleration ramp t2 (s).
    pub t2_s: T,
    /// End of the motion t3 (s).
    pub t3_s: T,
    /// Extension at t = 0 (m).
    pub start_m: T,
    /// Extension at t ≥ t3 (m).
    pub end_m: T,
}

impl<T: Real> StrokeProfile<T> {
    /// The constant velocity v0: both ramp shapes average v0/2 over their ramps, so
    /// v0 = stroke / (t1/2 + (t2 − t1) + (t3 − t2)/2) (listing `VZERO`).
    pub fn v0_m_s(&self) -> T {
        let half = T::lit(0.5);
        (self.end_m - self.start_m)
            / (half * self.t1_s + (self.t2_s - self.t1_s) + half * (self.t3_s - self.t2_s))
    }

    /// Position, velocity and acceleration at time `t_s`.
    pub fn at(&self, t_s: T) -> ActuatorMotion<T> {
        let v0 = self.v0_m_s();
        let (t1, t2, t3) = (self.t1_s, self.t2_s, self.t3_s);
        let tau2pi = T::two_pi();
        let half = T::lit(0.5);
        // Distance covered by a ramp of duration d after time τ into it (0 ≤ τ ≤ d),
        // and its velocity and acceleration, for a rising ramp 0 → v0.
        let ramp = |tau: T, d: T| -> (T, T, T) {
            match self.shape {
                RampShape::Linear => (v0 * tau * tau * half / d, v0 * tau / d, v0 / d),
                RampShape::Cycloidal => {
                    let w = tau2pi / d;
                    let k = d / tau2pi;
                    (
                        v0 / d * (tau * tau * half + k * k * ((w * tau).cos() - T::one())),
                        v0 / d * (tau - k * (w * tau).sin()),
                        v0 / d * (T::one() - (w * tau).cos()),
                    )
                }
            }
        };
        let (x, v, a) = if t_s <= T::zero() {
            (T::zero(), T::zero(), T::zero())
        } else if t_s <= t1 {
            ramp(t_s, t1)
        } else if t_s <= t2 {
            (v0 * t1 * half + v0 * (t_s - t1), v0, T::zero())
        } else {
            let d = t3 - t2;
            let tau = if t_s < t3 { t_s - t2 } else { d };
            // Deceleration mirrors the rising ramp: v = v0 − ramp velocity.
            let (xr, vr, ar) = ramp(tau, d);
            let x = v0 * t1 * half + v0 * (t2 - t1) + v0 * tau - xr;
            if t_s < t3 {
                (x, v0 - vr, -ar)
            } else {
                (x, T::zero(), T::zero())
            }
        };
        ActuatorMotion {
            extension_m: self.start_m + x,
            rate_m_s: v,
            accel_m_s2: a,
        }
    }
}
