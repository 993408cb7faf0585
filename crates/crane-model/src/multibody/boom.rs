//! Body 1, the flexible boom: its configuration-dependent inertia and velocity
//! terms (thesis eqs. 3.1–3.11), written once for the three places that need
//! them: the reduced equations, the full system of eq. 2.68 and the piston
//! force along the actuator ([`crate::multibody::dynamics`]).

use crate::multibody::mechanism::perp;
use crate::multibody::{Configuration, CraneModel};
use crate::structure::modal::BoomModes;
use crate::Real;
use nalgebra::{SMatrix, SVector, Vector2};

/// The boom's modal terms at the modal coordinates η.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BoomModal<T: Real, const M: usize> {
    /// A·χ (eq. 3.4): first moment per unit modal coordinate, body frame.
    pub d: SMatrix<T, 2, M>,
    /// χᵀ·AA·χ (eqs. 3.6, 3.11).
    pub skew: SMatrix<T, M, M>,
    /// χᵀ·M_αα·e0 + η (eqs. 3.5, 3.10, 3.11): the rotation's centrifugal coupling.
    pub coupling: SVector<T, M>,
    /// h = χᵀ·AA·q: the rotation–deformation coupling M_θη (eq. 3.6).
    pub h: SVector<T, M>,
}

impl<T: Real, const M: usize> BoomModal<T, M> {
    /// The terms at modal coordinates `eta`.
    #[inline]
    pub fn new(m: &BoomModes<T, M>, eta: &SVector<T, M>) -> Self {
        let d = SMatrix::<T, 2, M>::from_fn(|r, c| m.first_moment_modes[r][c]);
        let skew = SMatrix::<T, M, M>::from_fn(|r, c| m.skew_modes[r][c]);
        let coupling = SVector::<T, M>::from_column_slice(&m.inertia_coupling) + eta;
        let h = SVector::<T, M>::from_column_slice(&m.skew_rest) + skew * eta;
        BoomModal { d, skew, coupling, h }
    }
}

/// Subtracts the modal stiffness (eq. 2.52) and damping (eq. 2.53) forces
/// ω²·η + (α + β·ω²)·η̇ from the η rows `f`.
#[inline]
pub(crate) fn subtract_elastic<T: Real, const M: usize>(m: &BoomModes<T, M>, f: &mut SVector<T, M>, eta: &SVector<T, M>, eta_rate: &SVector<T, M>) {
    for k in 0..M {
        let wk = m.omega_rad_s[k];
        f[k] -= wk * wk * eta[k] + m.damping[k] * eta_rate[k];
    }
}

/// Everything of body 1's rows x1, y1, θ1 at one configuration.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BoomTerms<T: Real, const M: usize> {
    /// The modal terms.
    pub modal: BoomModal<T, M>,
    /// qᵀ·M_αα·q: rotary inertia of the deformed boom about A0 (eq. 3.5).
    pub inertia: T,
    /// T·J·A·q: the translation–rotation coupling M_Rθ (eq. 3.3).
    pub tj_first: Vector2<T>,
    /// T·A·χ: the translation–deformation coupling M_Rη (eq. 3.4).
    pub td: SMatrix<T, 2, M>,
    /// Velocity terms of the x1, y1 rows (eq. 3.9).
    pub q_r: Vector2<T>,
    /// Velocity term of the θ1 row (eq. 3.10).
    pub q_th: T,
}

impl<T: Real, const M: usize> CraneModel<T, M> {
    /// Body 1's terms at configuration `cfg`.
    #[inline]
    pub(crate) fn boom_terms(&self, cfg: &Configuration<T, M>) -> BoomTerms<T, M> {
        let m = &self.modes;
        let two = T::lit(2.0);
        let w1 = cfg.mech.boom.angular_velocity;
        let modal = BoomModal::new(m, &cfg.eta);
        let d = modal.d;
        let first = Vector2::new(m.first_moment_rest[0], m.first_moment_rest[1]) + d * cfg.eta;
        let coupling_rest = SVector::<T, M>::from_column_slice(&m.inertia_coupling);
        let inertia = m.inertia_rest + two * coupling_rest.dot(&cfg.eta) + cfg.eta.dot(&cfg.eta);
        let tj_first = cfg.rot * perp(first);
        let td = cfg.rot * d;
        let q_r = cfg.rot * first * (w1 * w1) - cfg.rot * perp(d * cfg.eta_rate) * (two * w1);
        let q_th = -(two * w1) * modal.coupling.dot(&cfg.eta_rate);
        BoomTerms { modal, inertia, tj_first, td, q_r, q_th }
    }
}
