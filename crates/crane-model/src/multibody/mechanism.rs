//! Closed-form kinematics of the rigid mechanism: boom (as a reference frame),
//! lug rod, piston rod and cylinder, from the actuator's extension (thesis §3.3,
//! Fig. 3.4, eq. 3.41).
//!
//! With the boom's modes clamped at A (no transverse displacement or rotation
//! there), the boom's reference angle is the lug rod's angle plus γ whatever the
//! deformation; so bodies 1–4 follow from the actuator alone, and only the tip C,
//! and with it the rope, moves with the modes. This is what lets the integrator
//! carry just the modes and the load swing while every constraint holds exactly.

use crate::data::profile::ActuatorMotion;
use crate::{ModelError, Real};
use nalgebra::Vector2;

/// Position, velocity and acceleration of a rigid body's reference point and angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyMotion<T: Real> {
    /// Reference point (m).
    pub position: Vector2<T>,
    /// Angle of the body axis from horizontal (rad).
    pub angle: T,
    /// Velocity of the reference point (m/s).
    pub velocity: Vector2<T>,
    /// Angular velocity (rad/s).
    pub angular_velocity: T,
    /// Acceleration of the reference point (m/s²).
    pub acceleration: Vector2<T>,
    /// Angular acceleration (rad/s²).
    pub angular_acceleration: T,
    /// Unit vector along the body axis, (cos θ, sin θ), computed once: trigonometry
    /// is the costliest arithmetic on the controller.
    pub axis: Vector2<T>,
}

impl<T: Real> BodyMotion<T> {
    /// Unit vector normal to the axis, (−sin θ, cos θ).
    #[inline]
    pub fn normal(&self) -> Vector2<T> {
        Vector2::new(-self.axis.y, self.axis.x)
    }
}

/// The mechanism's geometry, converted once to the model's float type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MechanismGeometry<T: Real> {
    /// Boom foot pin A0 (m).
    pub boom_foot: Vector2<T>,
    /// Cylinder foot pin B0 (m).
    pub cylinder_foot: Vector2<T>,
    /// Lug rod length A0D (m).
    pub lug_length_m: T,
    /// Angle γ between boom axis and lug rod (rad).
    pub lug_angle_rad: T,
    /// Piston rod length BD (m).
    pub rod_length_m: T,
    /// (cos γ, sin γ).
    pub lug_rotation: Vector2<T>,
    /// Direction angle of A0 − B0 (rad) and its unit vector.
    pub base_angle_rad: T,
    /// Unit vector of A0 − B0.
    pub base_axis: Vector2<T>,
}

/// Unit vector at angle `a`.
#[inline]
pub fn unit<T: Real>(a: T) -> Vector2<T> {
    Vector2::new(a.cos(), a.sin())
}

/// Unit vector at angle `a` + 90°.
#[inline]
pub fn normal<T: Real>(a: T) -> Vector2<T> {
    Vector2::new(-a.sin(), a.cos())
}

/// Bodies 1–4 at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MechanismMotion<T: Real> {
    /// Body 1's reference frame: origin at A0, angle θ1 of the undeformed boom axis.
    pub boom: BodyMotion<T>,
    /// Body 2, the lug rod A0–D, reference at A0.
    pub lug: BodyMotion<T>,
    /// Body 3, the piston rod, reference at the piston B, axis toward D.
    pub rod: BodyMotion<T>,
    /// Body 4, the cylinder, reference at B0, axis toward D.
    pub cylinder: BodyMotion<T>,
    /// The actuator motion it was computed from.
    pub actuator: ActuatorMotion<T>,
}

impl<T: Real> MechanismGeometry<T> {
    /// From the crane data.
    pub fn new(crane: &crate::CraneData) -> Self {
        let (dx, dy) = (crane.boom_foot[0] - crane.cylinder_foot[0], crane.boom_foot[1] - crane.cylinder_foot[1]);
        let base = libm::atan2(dy, dx);
        let gamma = crane.lug_angle_rad();
        MechanismGeometry {
            boom_foot: Vector2::new(T::lit(crane.boom_foot[0]), T::lit(crane.boom_foot[1])),
            cylinder_foot: Vector2::new(T::lit(crane.cylinder_foot[0]), T::lit(crane.cylinder_foot[1])),
            lug_length_m: T::lit(crane.lug_rod.length_m),
            lug_angle_rad: T::lit(gamma),
            rod_length_m: T::lit(crane.piston_rod.length_m),
            lug_rotation: Vector2::new(T::lit(libm::cos(gamma)), T::lit(libm::sin(gamma))),
            base_angle_rad: T::lit(base),
            base_axis: Vector2::new(T::lit(libm::cos(base)), T::lit(libm::sin(base))),
        }
    }

    /// Extension a (B0 to the piston B) at boom angle θ1 (listing `DISTANCEI`).
    pub fn extension_at_angle(&self, boom_angle_rad: T) -> T {
        let d = self.boom_foot + unit(boom_angle_rad - self.lug_angle_rad) * self.lug_length_m;
        (d - self.cylinder_foot).norm() - self.rod_length_m
    }

    /// d a / d θ1 at boom angle θ1: the lever of the cylinder about A0.
    pub fn extension_per_radian(&self, boom_angle_rad: T) -> T {
        let th2 = boom_angle_rad - self.lug_angle_rad;
        let d = self.boom_foot + unit(th2) * self.lug_length_m;
        let s = d - self.cylinder_foot;
        s.dot(&normal(th2)) * self.lug_length_m / s.norm()
    }

    /// The mechanism for a given actuator motion. Fails when the cylinder cannot
    /// reach (the triangle A0–B0–D does not close).
    pub fn motion(&self, act: ActuatorMotion<T>) -> Result<MechanismMotion<T>, ModelError> {
        let zero2 = Vector2::zeros();
        let l2 = self.lug_length_m;
        let s = act.extension_m + self.rod_length_m;
        let (sd, sdd) = (act.rate_m_s, act.accel_m_s2);
        // Triangle A0–B0–D: |d + L2·e(θ2)| = s with d = A0 − B0.
        let d = self.boom_foot - self.cylinder_foot;
        let dn = d.norm();
        let k = (s * s - dn * dn - l2 * l2) / (T::lit(2.0) * l2);
        let ratio = k / dn;
        if !(ratio.abs() < T::one()) {
            return Err(ModelError::OutOfReach);
        }
        // θ2 = φ_d − α with cos α = ratio: e2 from the angle-difference formula, so
        // the only trigonometric call is the acos that gives θ2's value.
        let sin_alpha = (T::one() - ratio * ratio).sqrt();
        let th2 = self.base_angle_rad - ratio.acos();
        let (bc, bs) = (self.base_axis.x, self.base_axis.y);
        let e2 = Vector2::new(bc * ratio + bs * sin_alpha, bs * ratio - bc * sin_alpha);
        let n2 = Vector2::new(-e2.y, e2.x);
        // s·ṡ = L2·(d·n2)·θ̇2, differentiated once more for θ̈2.
        let g = l2 * d.dot(&n2);
        if !(g.abs() > T::default_epsilon()) {
            return Err(ModelError::Singular("mechanism at a dead point"));
        }
        let w2 = s * sd / g;
        let al2 = (sd * sd + s * sdd + l2 * d.dot(&e2) * w2 * w2) / g;
        // D and the cylinder axis.
        let pd = self.boom_foot + e2 * l2;
        let vd = n2 * (l2 * w2);
        let ad = (n2 * al2 - e2 * (w2 * w2)) * l2;
        let axis = pd - self.cylinder_foot;
        let th4 = axis.y.atan2(axis.x);
        let e4 = axis / s;
        let n4 = Vector2::new(-e4.y, e4.x);
        let w4 = vd.dot(&n4) / s;
        let al4 = (ad.dot(&n4) - T::lit(2.0) * sd * w4) / s;
        let a = act.extension_m;
        let rod = BodyMotion {
            position: self.cylinder_foot + e4 * a,
            angle: th4,
            velocity: e4 * sd + n4 * (a * w4),
            angular_velocity: w4,
            acceleration: e4 * (sdd - a * w4 * w4) + n4 * (T::lit(2.0) * sd * w4 + a * al4),
            angular_acceleration: al4,
            axis: e4,
        };
        let fixed = |position: Vector2<T>, angle: T, w: T, al: T, axis: Vector2<T>| BodyMotion {
            position,
            angle,
            velocity: zero2,
            angular_velocity: w,
            acceleration: zero2,
            angular_acceleration: al,
            axis,
        };
        let (gc, gs) = (self.lug_rotation.x, self.lug_rotation.y);
        let e1 = Vector2::new(e2.x * gc - e2.y * gs, e2.x * gs + e2.y * gc);
        Ok(MechanismMotion {
            boom: fixed(self.boom_foot, th2 + self.lug_angle_rad, w2, al2, e1),
            lug: fixed(self.boom_foot, th2, w2, al2, e2),
            rod,
            cylinder: fixed(self.cylinder_foot, th4, w4, al4, e4),
            actuator: act,
        })
    }
}
