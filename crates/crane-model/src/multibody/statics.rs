//! States at rest: the thesis's initial state and the model's exact equilibrium.

use crate::multibody::mechanism::unit;
use crate::multibody::{CraneModel, FreeCoordinates};
use crate::data::profile::ActuatorMotion;
use crate::{ModelError, Real};
use nalgebra::{Matrix2, SMatrix, SVector, Vector2};

/// Load swing angle of a rope hanging straight down (rad).
pub fn hanging<T: Real>() -> T {
    -T::frac_pi_2()
}

impl<T: Real, const M: usize> CraneModel<T, M> {
    /// The actuator motion that holds the boom at angle θ1 turning at `rate` (rad/s)
    /// with no angular acceleration.
    pub fn actuator_at(&self, boom_angle_rad: T, boom_rate_rad_s: T) -> ActuatorMotion<T> {
        ActuatorMotion {
            extension_m: self.geometry.extension_at_angle(boom_angle_rad),
            rate_m_s: self.geometry.extension_per_radian(boom_angle_rad) * boom_rate_rad_s,
            accel_m_s2: T::zero(),
        }
    }

    /// Gravity per unit mass and the weight of rope and load at C, in the boom frame.
    fn body_loads(&self, boom_angle_rad: T, load_kg: T) -> Result<(Vector2<T>, Vector2<T>), ModelError> {
        let g_body = rotation(boom_angle_rad).transpose() * Vector2::new(T::zero(), -self.gravity_m_s2);
        Ok((g_body, self.tip_weight_body(boom_angle_rad, load_kg)?))
    }

    fn tip_weight_body(&self, boom_angle_rad: T, load_kg: T) -> Result<Vector2<T>, ModelError> {
        let l = self.hanging_length_m(boom_angle_rad)?;
        let w = (load_kg + self.rope_kg_per_m * l) * self.gravity_m_s2;
        Ok(rotation(boom_angle_rad).transpose() * Vector2::new(T::zero(), -w))
    }

    /// The listing's initial state: the finite-element static deflection under the
    /// boom's weight and the weight of rope and load at C, projected on the modes by
    /// Euclidean least squares, η = (χᵀχ)⁻¹χᵀα; rope hanging; velocities zero.
    ///
    /// The Euclidean norm mixes metres and radians and leaves the modes off their
    /// equilibrium (by 4 % in the longitudinal mode at 3.3 t), which starts an
    /// 84 Hz oscillation of the piston force that no crane shows. Kept to
    /// reproduce the listing; [`Self::equilibrium_state`] is the default.
    pub fn listing_initial_state(
        &self,
        boom_angle_rad: T,
        load_kg: T,
    ) -> Result<FreeCoordinates<T, M>, ModelError> {
        let (g_body, tip) = self.body_loads(boom_angle_rad, load_kg)?;
        let mut eta = [T::zero(); M];
        for (k, e) in eta.iter_mut().enumerate() {
            let (sg, st) = (&self.modes.static_gravity[k], &self.modes.static_tip[k]);
            *e = sg[0] * g_body.x + sg[1] * g_body.y + st[0] * tip.x + st[1] * tip.y;
        }
        Ok(at_rest(eta))
    }

    /// [`Self::equilibrium_state`] for an already computed rigid motion (no trigonometry).
    pub fn equilibrium_state_at(&self, rigid: &crate::multibody::RigidMotion<T>) -> FreeCoordinates<T, M> {
        let g = Vector2::new(T::zero(), -self.gravity_m_s2);
        let g_body = rigid.rot.transpose() * g;
        let tip = rigid.rot.transpose() * g * rigid.pendulum.mass_kg;
        self.equilibrium_from_body_loads(g_body, tip)
    }

    fn equilibrium_from_body_loads(&self, g_body: Vector2<T>, tip: Vector2<T>) -> FreeCoordinates<T, M> {
        let d = SMatrix::<T, 2, M>::from_fn(|r, c| self.modes.first_moment_modes[r][c]);
        let tip_modes = SMatrix::<T, 2, M>::from_fn(|r, c| self.modes.tip_modes[r][c]);
        let f: SVector<T, M> = d.transpose() * g_body + tip_modes.transpose() * tip;
        let mut eta = [T::zero(); M];
        for (k, e) in eta.iter_mut().enumerate() {
            let w = self.modes.omega_rad_s[k];
            *e = f[k] / (w * w);
        }
        at_rest(eta)
    }

    /// The thesis's initial state (SPEC §3) with the projection done in the energy
    /// norm: the static deflection α under the boom's weight and the weight of rope
    /// and load at C, projected on the modes by least squares in ‖·‖_K, which is
    /// η = (χᵀKχ)⁻¹χᵀKα = diag(ω⁻²)·χᵀf: exactly the reduced model's static
    /// equilibrium, diag(ω²)·η = Dᵀ·Tᵀ·g + χ_Cᵀ·Tᵀ·(m5·g). Rope hanging, nothing moving.
    pub fn equilibrium_state(
        &self,
        boom_angle_rad: T,
        load_kg: T,
    ) -> Result<FreeCoordinates<T, M>, ModelError> {
        let (g_body, tip) = self.body_loads(boom_angle_rad, load_kg)?;
        Ok(self.equilibrium_from_body_loads(g_body, tip))
    }
}

/// Modes at `eta`, rope hanging, nothing moving.
fn at_rest<T: Real, const M: usize>(eta: [T; M]) -> FreeCoordinates<T, M> {
    FreeCoordinates { eta, eta_rate: [T::zero(); M], swing_rad: hanging(), swing_rate: T::zero() }
}

/// T(θ): rotation from the body frame to the plane.
pub fn rotation<T: Real>(angle: T) -> Matrix2<T> {
    let e = unit(angle);
    Matrix2::new(e.x, -e.y, e.y, e.x)
}
