//! The constrained flexible multibody model of the crane (thesis ch. 2–3, SPEC §3).
//!
//! Five bodies in absolute coordinates: the flexible boom (x1, y1, θ1, η1..ηM),
//! the lug rod, the piston rod, the cylinder and the rope with its load (x, y, θ
//! each): M + 15 coordinates, 14 constraints, M + 1 degrees of freedom.
//!
//! A step reads as named stages, as MuJoCo's `mj_forward` does:
//! [`CraneModel::kinematics`] (positions and velocities of every body at this
//! configuration) → [`CraneModel::reduced_equations`] (mass matrix and forces of the
//! free coordinates: velocity terms, gravity, stiffness, damping) → solve
//! ([`ReducedEquations::solve`]) → [`CraneModel::full_system`] (the generalized mass
//! matrix M, forces and constraint Jacobian B of eq. 2.68) → multipliers
//! ([`crate::multibody::dynamics`]) → reactions.

pub mod bodies;
mod boom;
pub mod layout;
pub mod dynamics;
pub mod mechanism;
pub mod rope;
pub mod statics;

use crate::multibody::bodies::{CylinderMass, Pendulum, RigidMass};
use crate::data::crane::CraneData;
use crate::structure::dense::Square;
use crate::multibody::boom::{subtract_elastic, BoomModal};
use crate::multibody::layout::{coordinate_count, mode_index};
use crate::multibody::mechanism::{perp, unit, MechanismGeometry, MechanismMotion};
use crate::structure::modal::{BoomModes, MeshRefinement, ModalAnalysis};
use crate::data::profile::ActuatorMotion;
use crate::multibody::rope::{RopeChoice, RopeMode};
use crate::{ModelError, Real};
use nalgebra::{Matrix2, SMatrix, SVector, Vector2};

/// Number of constraints (thesis §3.3.1, one dependent equation dropped).
pub const CONSTRAINTS: usize = 14;
/// Most generalized coordinates (8 modes + 15, [`layout`]).
pub const MAX_COORDS: usize = coordinate_count(crate::structure::modal::MAX_MODES);

/// The crane model: constant data only (thesis's time-invariant matrices, §2.6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CraneModel<T: Real, const M: usize> {
    /// The crane description it was built from.
    pub crane: CraneData,
    /// Pins and lengths of the mechanism.
    pub geometry: MechanismGeometry<T>,
    /// The boom's time-invariant modal data.
    pub modes: BoomModes<T, M>,
    /// Body 2, the lug rod, about A0.
    pub lug: RigidMass<T>,
    /// Body 3, the piston rod, about the piston B.
    pub rod: RigidMass<T>,
    /// Body 4, the cylinder with its oil, about B0.
    pub cylinder: CylinderMass<T>,
    /// Rope mass per metre of hanging length (kg/m).
    pub rope_kg_per_m: T,
    /// Height of the load above the ground (m).
    pub load_clearance_m: T,
    /// Gravitational acceleration (m/s²).
    pub gravity_m_s2: T,
    /// How the rope's hanging length behaves (SPEC §3, the rope two ways).
    pub rope: RopeMode<T>,
}

/// The thesis's model: 12 elements, the 4-mode basis, in f64 or f32.
pub type ThesisModel<T> = CraneModel<T, 4>;

impl<T: Real, const M: usize> CraneModel<T, M> {
    /// A model of `crane` with precomputed modes.
    pub fn new(crane: &CraneData, modes: BoomModes<T, M>) -> Self {
        let r =
            |rod: &crate::data::crane::RodData| RigidMass::rod(rod.mass_kg(), rod.length_m, rod.radius_m);
        CraneModel {
            crane: *crane,
            geometry: MechanismGeometry::new(crane),
            modes,
            lug: r(&crane.lug_rod),
            rod: r(&crane.piston_rod),
            cylinder: CylinderMass::new(crane),
            rope_kg_per_m: T::lit(crane.rope.mass_per_m_kg),
            load_clearance_m: T::lit(crane.rope.load_clearance_m),
            gravity_m_s2: T::lit(crane.gravity_m_s2),
            rope: RopeMode::Thesis,
        }
    }

    /// This model with the rope in `mode` (everything else shared).
    pub fn with_rope(&self, mode: RopeMode<T>) -> Self {
        CraneModel { rope: mode, ..*self }
    }

    /// The rope mode of `choice` for a run starting at boom angle `start_rad`:
    /// a held rope without a length gets the one that puts the load at the
    /// clearance above the ground at the start.
    pub fn rope_for(&self, choice: RopeChoice, start_rad: T) -> Result<RopeMode<T>, ModelError> {
        match choice {
            RopeChoice::Thesis => Ok(RopeMode::Thesis),
            RopeChoice::Held { length_m: Some(l) } => {
                if !(l > 0.0 && l.is_finite()) {
                    return Err(ModelError::InvalidParameter("held rope length must be a finite number > 0 m"));
                }
                Ok(RopeMode::Held { length_m: T::lit(l) })
            }
            RopeChoice::Held { length_m: None } => {
                Ok(RopeMode::Held { length_m: self.clearance_length_m(start_rad)? })
            }
        }
    }

    /// The hanging length that puts the load at the clearance above the ground with
    /// the rigid boom at `angle_rad` (thesis assumption vi): y_C − clearance.
    pub fn clearance_length_m(&self, angle_rad: T) -> Result<T, ModelError> {
        let l = self.geometry.boom_foot.y + self.modes.length_m * angle_rad.sin() - self.load_clearance_m;
        if !(l > T::zero()) {
            return Err(ModelError::OutOfReach);
        }
        Ok(l)
    }

    /// The hanging length at rest at `angle_rad` in this model's rope mode.
    pub fn hanging_length_m(&self, angle_rad: T) -> Result<T, ModelError> {
        match self.rope {
            RopeMode::Thesis => self.clearance_length_m(angle_rad),
            RopeMode::Held { length_m } => Ok(length_m),
        }
    }

    /// Builds the modes of `crane` with `basis` and the given mesh. The structural
    /// analysis (FE assembly and eigen-solve) always runs in f64 and is then cast
    /// to `T`: K's eigenvalues span 1.7·10⁷, beyond f32's 7 digits (an f32 solve
    /// misses the first bending frequency by 3.5 %), and the thesis does this
    /// part once, in advance, anyway (§2.6).
    pub fn build(crane: &CraneData, refinement: MeshRefinement, basis: &[crate::structure::modal::ModeChoice; M]) -> Result<Self, ModelError> {
        let analysis = ModalAnalysis::<f64>::new(crane, refinement)?;
        let modes = analysis.reduce(basis, crane.boom.damping_ratio)?;
        Ok(Self::new(crane, modes.cast::<T>()))
    }

    /// Body 5 at this instant: in [`RopeMode::Thesis`] the rope length that keeps the
    /// load at its clearance below the rigid tip, with its time derivatives; in
    /// [`RopeMode::Held`] the constant length.
    fn pendulum(
        &self,
        boom: &crate::multibody::mechanism::BodyMotion<T>,
        load_kg: T,
    ) -> Result<Pendulum<T>, ModelError> {
        if let RopeMode::Held { length_m } = self.rope {
            // Winch braked: constant length, L̇ = L̈ = 0.
            return Pendulum::new(self.rope_kg_per_m, load_kg, length_m, T::zero(), T::zero());
        }
        let (c, s) = (boom.axis.x, boom.axis.y);
        let (w, al) = (boom.angular_velocity, boom.angular_acceleration);
        let lc = self.modes.length_m;
        let l = boom.position.y + lc * s - self.load_clearance_m;
        Pendulum::new(
            self.rope_kg_per_m,
            load_kg,
            l,
            lc * c * w,
            lc * (c * al - s * w * w),
        )
    }

    /// Stage 1a, the part of the kinematics that depends on time only: bodies 1–4
    /// from the actuator, the rope length, the oil in the cylinder. Computed once
    /// per time step and shared by every Newton iteration.
    pub fn rigid_motion(
        &self,
        act: ActuatorMotion<T>,
        load_kg: T,
    ) -> Result<RigidMotion<T>, ModelError> {
        let mech = self.geometry.motion(act)?;
        let pendulum = self.pendulum(&mech.boom, load_kg)?;
        let cylinder = self.cylinder.at_extension(act.extension_m)?;
        let e1 = mech.boom.axis;
        let rot = Matrix2::new(e1.x, -e1.y, e1.y, e1.x);
        Ok(RigidMotion { mech, pendulum, cylinder, rot, load_kg })
    }

    /// The same rigid motion with another hook load (rope length unchanged).
    pub fn with_load(&self, rigid: &RigidMotion<T>, load_kg: T) -> Result<RigidMotion<T>, ModelError> {
        let p = &rigid.pendulum;
        let pendulum = Pendulum::new(self.rope_kg_per_m, load_kg, p.length_m, p.length_rate_m_s, p.length_accel_m_s2)?;
        Ok(RigidMotion { pendulum, load_kg, ..*rigid })
    }

    /// The same rigid motion with the held rope's hanging length, its rate and
    /// acceleration set by a hoist (m, m/s, m/s²; the hook load unchanged).
    pub fn with_length(&self, rigid: &RigidMotion<T>, length: ActuatorMotion<T>) -> Result<RigidMotion<T>, ModelError> {
        let pendulum = Pendulum::new(self.rope_kg_per_m, rigid.load_kg, length.extension_m, length.rate_m_s, length.accel_m_s2)?;
        Ok(RigidMotion { pendulum, ..*rigid })
    }

    /// Stage 1b: every body's position and velocity given the free coordinates.
    pub fn configure(
        &self,
        rigid: &RigidMotion<T>,
        free: &FreeCoordinates<T, M>,
    ) -> Configuration<T, M> {
        let zero = Vector2::zeros();
        let mut cfg = Configuration {
            mech: rigid.mech,
            pendulum: rigid.pendulum,
            cylinder: rigid.cylinder,
            eta: SVector::zeros(),
            eta_rate: SVector::zeros(),
            rot: rigid.rot,
            tip_modes: SMatrix::<T, 2, M>::from_fn(|r, c| self.modes.tip_modes[r][c]),
            tip_body: zero,
            tip_position: zero,
            tip_velocity: zero,
            swing_rad: free.swing_rad,
            swing_axis: zero,
            swing_rate: free.swing_rate,
            load_kg: rigid.load_kg,
        };
        self.reconfigure(&mut cfg, free);
        cfg
    }

    /// Stage 1b again for other free coordinates at the same instant: only the
    /// parts that depend on them change (the Newton iteration's trial states share
    /// one rigid motion, so they need not copy it again).
    pub fn reconfigure(&self, cfg: &mut Configuration<T, M>, free: &FreeCoordinates<T, M>) {
        let eta = SVector::<T, M>::from_column_slice(&free.eta);
        let eta_rate = SVector::<T, M>::from_column_slice(&free.eta_rate);
        let tip_body = Vector2::new(self.modes.length_m, T::zero()) + cfg.tip_modes * eta;
        let w1 = cfg.mech.boom.angular_velocity;
        cfg.tip_position = cfg.mech.boom.position + cfg.rot * tip_body;
        cfg.tip_velocity =
            cfg.rot * (perp(tip_body) * w1 + cfg.tip_modes * eta_rate);
        cfg.tip_body = tip_body;
        cfg.eta = eta;
        cfg.eta_rate = eta_rate;
        cfg.swing_rad = free.swing_rad;
        cfg.swing_axis = unit(free.swing_rad);
        cfg.swing_rate = free.swing_rate;
    }

    /// Stage 1, kinematics: every body's position and velocity for actuator motion
    /// `act`, hook load, and the free coordinates (modes and swing) with their rates.
    pub fn kinematics(
        &self,
        act: ActuatorMotion<T>,
        load_kg: T,
        free: &FreeCoordinates<T, M>,
    ) -> Result<Configuration<T, M>, ModelError> {
        Ok(self.configure(&self.rigid_motion(act, load_kg)?, free))
    }

    /// Stage 2: the equations of motion projected on the free coordinates.
    ///
    /// Every other coordinate is a known function of time and of the modes (see
    /// [`crate::multibody::mechanism`]), so with ÿ = N·z̈ + c the constrained equations
    /// M·ÿ + Bᵀλ = Q + f + f_s + f_d (eq. 2.68, B·N = 0) become
    /// (NᵀMN)·z̈ = Nᵀ(Q + f + f_s + f_d − M·c): M + 1 equations instead of M + 29.
    pub fn reduced_equations(&self, cfg: &Configuration<T, M>) -> ReducedEquations<T, M> {
        let g = Vector2::new(T::zero(), -self.gravity_m_s2);
        let m = &self.modes;
        let b1 = &cfg.mech.boom;
        let (w1, al1) = (b1.angular_velocity, b1.angular_acceleration);
        let two = T::lit(2.0);
        let BoomModal { d, skew, coupling, h } = BoomModal::new(m, &cfg.eta);
        // Body 1, η rows: gravity (eq. 2.51), velocity terms Q_η (eq. 3.11), stiffness
        // (eq. 2.52), damping (eq. 2.53), minus the inertia of the prescribed rotation.
        let mut f_eta = d.transpose() * (cfg.rot.transpose() * g) + coupling * (w1 * w1)
            - skew * cfg.eta_rate * (two * w1)
            - h * al1;
        subtract_elastic(m, &mut f_eta, &cfg.eta, &cfg.eta_rate);
        // Body 5 through the tip C: R̈5 = c5 + T·χ_C·η̈.
        let p = &cfg.pendulum;
        let e5 = cfg.swing_axis;
        let n5 = perp(e5);
        let w5 = cfg.swing_rate;
        let tj_tip = cfg.rot * perp(cfg.tip_body);
        let tip_modes_world = cfg.rot * cfg.tip_modes;
        let c5 = tj_tip * al1 - cfg.rot * cfg.tip_body * (w1 * w1)
            + (cfg.rot * perp(cfg.tip_modes * cfg.eta_rate)) * (two * w1);
        let (f5_r, f5_th) = p.applied_forces(g, e5, n5, w5);
        let r5 = f5_r - c5 * p.mass_kg;
        f_eta += tip_modes_world.transpose() * r5;
        let f_swing = f5_th - p.first_moment_kg_m * n5.dot(&c5);
        let a =
            SMatrix::<T, M, M>::identity() + cfg.tip_modes.transpose() * cfg.tip_modes * p.mass_kg;
        let b = tip_modes_world.transpose() * (n5 * p.first_moment_kg_m);
        ReducedEquations {
            mass: Block2 {
                a,
                b,
                c: p.inertia_kg_m2,
            },
            force_eta: f_eta,
            force_swing: f_swing,
            tip_accel_known: c5,
        }
    }

    /// The generalized coordinates, velocities, mass matrix M, forces
    /// Q + f + f_s + f_d, constraint Jacobian B and the right side γ = −Ḃy + ġ of
    /// B·ẏ = γ (eqs. 2.59, 2.67, 2.68), over all M + 15 coordinates.
    pub fn full_system(&self, cfg: &Configuration<T, M>) -> Result<FullSystem<T>, ModelError> {
        let n = Self::COORDS;
        let mut sys = FullSystem {
            n,
            position: [T::zero(); MAX_COORDS],
            velocity: [T::zero(); MAX_COORDS],
            mass: Square::zeros(n)?,
            force: [T::zero(); MAX_COORDS],
            jacobian: [[T::zero(); MAX_COORDS]; CONSTRAINTS],
            gamma: [T::zero(); CONSTRAINTS],
            residual: [T::zero(); CONSTRAINTS],
        };
        let g = Vector2::new(T::zero(), -self.gravity_m_s2);
        let two = T::lit(2.0);
        let m = &self.modes;
        let mech = &cfg.mech;
        // ---- Body 1 (flexible): eqs. 3.1–3.11.
        let b1 = &mech.boom;
        let (th1, w1) = (b1.angle, b1.angular_velocity);
        let terms = self.boom_terms(cfg);
        let BoomModal { d, skew, coupling, h } = terms.modal;
        let (inertia, tj_first, td) = (terms.inertia, terms.tj_first, terms.td);
        sys.set_body(0, b1.position, th1, b1.velocity, w1);
        for k in 0..M {
            sys.position[mode_index(k)] = cfg.eta[k];
            sys.velocity[mode_index(k)] = cfg.eta_rate[k];
        }
        for i in 0..2 {
            sys.mass.set(i, i, m.mass_kg);
            sys.mass.set(i, 2, tj_first[i]);
            sys.mass.set(2, i, tj_first[i]);
            for k in 0..M {
                sys.mass.set(i, mode_index(k), td[(i, k)]);
                sys.mass.set(mode_index(k), i, td[(i, k)]);
            }
        }
        sys.mass.set(2, 2, inertia);
        for k in 0..M {
            sys.mass.set(2, mode_index(k), h[k]);
            sys.mass.set(mode_index(k), 2, h[k]);
            sys.mass.set(mode_index(k), mode_index(k), T::one());
        }
        let mut q_eta = coupling * (w1 * w1) - skew * cfg.eta_rate * (two * w1);
        subtract_elastic(m, &mut q_eta, &cfg.eta, &cfg.eta_rate);
        let f_r = g * m.mass_kg + terms.q_r;
        let f_eta = q_eta + d.transpose() * (cfg.rot.transpose() * g);
        sys.force[0] = f_r.x;
        sys.force[1] = f_r.y;
        sys.force[2] = tj_first.dot(&g) + terms.q_th;
        for k in 0..M {
            sys.force[mode_index(k)] = f_eta[k];
        }
        // ---- Rigid bodies 2–4 (eqs. 3.12–3.16).
        let rigid = [
            (2usize, &mech.lug, self.lug),
            (3, &mech.rod, self.rod),
            (4, &mech.cylinder, cfg.cylinder),
        ];
        for (body, motion, mass) in rigid {
            let base = Self::body_index(body);
            sys.set_body(
                base,
                motion.position,
                motion.angle,
                motion.velocity,
                motion.angular_velocity,
            );
            let (e, nrm) = (motion.axis, motion.normal());
            sys.add_rigid_mass(
                base,
                mass.mass_kg,
                nrm * mass.first_moment_kg_m,
                mass.inertia_kg_m2,
            );
            let (f, torque) = mass.applied_forces(g, e, nrm, motion.angular_velocity);
            sys.force[base] = f.x;
            sys.force[base + 1] = f.y;
            sys.force[base + 2] = torque;
        }
        // ---- Body 5: rope and load, length L(t) (see `reduced_equations`).
        let base5 = Self::body_index(5);
        let p = &cfg.pendulum;
        let (th5, w5) = (cfg.swing_rad, cfg.swing_rate);
        let (e5, n5) = (cfg.swing_axis, perp(cfg.swing_axis));
        sys.set_body(base5, cfg.tip_position, th5, cfg.tip_velocity, w5);
        sys.add_rigid_mass(base5, p.mass_kg, n5 * p.first_moment_kg_m, p.inertia_kg_m2);
        let (f5, torque5) = p.applied_forces(g, e5, n5, w5);
        sys.force[base5] = f5.x;
        sys.force[base5 + 1] = f5.y;
        sys.force[base5 + 2] = torque5;
        self.constraints(cfg, &mut sys);
        Ok(sys)
    }

    /// The 14 constraints (thesis §3.3.1; SPEC §2 for the prescribed motion):
    /// rows of B, the acceleration right side γ and the position residual Φ.
    fn constraints(&self, cfg: &Configuration<T, M>, sys: &mut FullSystem<T>) {
        let two = T::lit(2.0);
        let (b2, b3, b4, b5) = (Self::body_index(2), Self::body_index(3), Self::body_index(4), Self::body_index(5));
        let x = |s: &FullSystem<T>, i: usize| Vector2::new(s.position[i], s.position[i + 1]);
        let v = |s: &FullSystem<T>, i: usize| Vector2::new(s.velocity[i], s.velocity[i + 1]);
        let a0 = self.geometry.boom_foot;
        let b0 = self.geometry.cylinder_foot;
        // 1–4: the pins of bodies 1 and 2 at A0; 5–6: the pin of body 4 at B0.
        let pins = [
            (0usize, 0usize, a0.x),
            (1, 1, a0.y),
            (2, b2, a0.x),
            (3, b2 + 1, a0.y),
            (4, b4, b0.x),
            (5, b4 + 1, b0.y),
        ];
        for (row, col, target) in pins {
            sys.jacobian[row][col] = T::one();
            sys.residual[row] = sys.position[col] - target;
        }
        // 7: the boom is fixed to the lug rod at A: θ1 + ψ_A·η − θ2 − γ = 0 (eq. 3.31).
        sys.jacobian[6][2] = T::one();
        let mut lug_rot = T::zero();
        for k in 0..M {
            sys.jacobian[6][mode_index(k)] = self.modes.lug_rotation_modes[k];
            lug_rot += self.modes.lug_rotation_modes[k] * cfg.eta[k];
        }
        sys.jacobian[6][b2 + 2] = -T::one();
        sys.residual[6] =
            sys.position[2] + lug_rot - sys.position[b2 + 2] - self.geometry.lug_angle_rad;
        // 8–9: revolute at D: R2 + L2·e2 − R3 − L3·e3 = 0 (eq. 3.32).
        let (l2, l3) = (self.geometry.lug_length_m, self.geometry.rod_length_m);
        let th3 = sys.position[b3 + 2];
        let (w2, w3) = (sys.velocity[b2 + 2], sys.velocity[b3 + 2]);
        let mech = &cfg.mech;
        let (e2, n2, e3, n3) = (mech.lug.axis, mech.lug.normal(), mech.rod.axis, mech.rod.normal());
        let phi_d = x(sys, b2) + e2 * l2 - x(sys, b3) - e3 * l3;
        let gam_d = e2 * (l2 * w2 * w2) - e3 * (l3 * w3 * w3);
        for i in 0..2 {
            let row = 7 + i;
            sys.jacobian[row][b2 + i] = T::one();
            sys.jacobian[row][b2 + 2] = n2[i] * l2;
            sys.jacobian[row][b3 + i] = -T::one();
            sys.jacobian[row][b3 + 2] = -n3[i] * l3;
            sys.gamma[row] = gam_d[i];
            sys.residual[row] = phi_d[i];
        }
        // 10: slider at B, normal direction: n4·(R3 − R4) = 0 (eq. 3.35).
        // 14: prescribed motion, relative: e4·(R3 − R4) − a(t) = 0 (eq. 3.49, SPEC §2).
        let th4 = sys.position[b4 + 2];
        let w4 = sys.velocity[b4 + 2];
        let (e4, n4) = (cfg.mech.cylinder.axis, cfg.mech.cylinder.normal());
        let dr = x(sys, b3) - x(sys, b4);
        let dv = v(sys, b3) - v(sys, b4);
        for i in 0..2 {
            sys.jacobian[9][b3 + i] = n4[i];
            sys.jacobian[9][b4 + i] = -n4[i];
            sys.jacobian[13][b3 + i] = e4[i];
            sys.jacobian[13][b4 + i] = -e4[i];
        }
        sys.jacobian[9][b4 + 2] = -e4.dot(&dr);
        sys.gamma[9] = two * w4 * e4.dot(&dv) + w4 * w4 * n4.dot(&dr);
        sys.residual[9] = n4.dot(&dr);
        sys.jacobian[13][b4 + 2] = n4.dot(&dr);
        sys.gamma[13] =
            cfg.mech.actuator.accel_m_s2 - two * w4 * n4.dot(&dv) + w4 * w4 * e4.dot(&dr);
        sys.residual[13] = e4.dot(&dr) - cfg.mech.actuator.extension_m;
        // 11: equal angles of piston rod and cylinder (eq. 3.43).
        sys.jacobian[10][b3 + 2] = T::one();
        sys.jacobian[10][b4 + 2] = -T::one();
        sys.residual[10] = th3 - th4;
        // 12–13: revolute at C: R1 + T1·(x_C + χ_C·η) − R5 = 0 (eq. 3.44).
        let w1 = sys.velocity[2];
        let tj_tip = cfg.rot * perp(cfg.tip_body);
        let t_modes = cfg.rot * cfg.tip_modes;
        let gam_c = cfg.rot * cfg.tip_body * (w1 * w1)
            - cfg.rot * perp(cfg.tip_modes * cfg.eta_rate) * (two * w1);
        let phi_c = x(sys, 0) + cfg.rot * cfg.tip_body - x(sys, b5);
        for i in 0..2 {
            let row = 11 + i;
            sys.jacobian[row][i] = T::one();
            sys.jacobian[row][2] = tj_tip[i];
            for k in 0..M {
                sys.jacobian[row][mode_index(k)] = t_modes[(i, k)];
            }
            sys.jacobian[row][b5 + i] = -T::one();
            sys.gamma[row] = gam_c[i];
            sys.residual[row] = phi_c[i];
        }
    }

    /// Number of generalized coordinates, M + 15 ([`layout`]).
    pub const COORDS: usize = coordinate_count(M);

    /// Index of the first coordinate of body `k` (1..=5, [`layout`]).
    pub const fn body_index(k: usize) -> usize {
        layout::body_index(k, M)
    }

    /// The dependent coordinates (everything but the modes and the swing angle θ5).
    pub fn dependent_indices() -> [usize; CONSTRAINTS] {
        let b1 = Self::body_index(1);
        let (b2, b3, b4, b5) = (Self::body_index(2), Self::body_index(3), Self::body_index(4), Self::body_index(5));
        [
            b1,
            b1 + 1,
            b1 + 2,
            b2,
            b2 + 1,
            b2 + 2,
            b3,
            b3 + 1,
            b3 + 2,
            b4,
            b4 + 1,
            b4 + 2,
            b5,
            b5 + 1,
        ]
    }
}

/// The time-dependent, mode-independent part of a configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidMotion<T: Real> {
    /// Bodies 1–4.
    pub mech: MechanismMotion<T>,
    /// Body 5 mass properties and rope length.
    pub pendulum: Pendulum<T>,
    /// Body 4 with its oil.
    pub cylinder: RigidMass<T>,
    /// T(θ1).
    pub rot: Matrix2<T>,
    /// Hook load W (kg).
    pub load_kg: T,
}

/// The free coordinates the integrator carries: the modes and the load swing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeCoordinates<T, const M: usize> {
    /// Modal coordinates η.
    pub eta: [T; M],
    /// dη/dt.
    pub eta_rate: [T; M],
    /// Angle θ5 of the rope from horizontal (rad); −π/2 hangs straight down.
    pub swing_rad: T,
    /// dθ5/dt (rad/s).
    pub swing_rate: T,
}

/// Positions and velocities of every body at one instant (stage 1's output).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Configuration<T: Real, const M: usize> {
    /// Bodies 1–4.
    pub mech: MechanismMotion<T>,
    /// Body 5 mass properties and rope length.
    pub pendulum: Pendulum<T>,
    /// Body 4 mass properties with its oil.
    pub cylinder: RigidMass<T>,
    /// Modal coordinates.
    pub eta: SVector<T, M>,
    /// Modal rates.
    pub eta_rate: SVector<T, M>,
    /// Rotation of the boom frame T(θ1).
    pub rot: Matrix2<T>,
    /// χ_C: tip displacement per mode (body frame).
    pub tip_modes: SMatrix<T, 2, M>,
    /// Tip C in the boom frame: (x_C, 0) + χ_C·η.
    pub tip_body: Vector2<T>,
    /// Tip C in the plane (m).
    pub tip_position: Vector2<T>,
    /// Velocity of C (m/s).
    pub tip_velocity: Vector2<T>,
    /// θ5 (rad).
    pub swing_rad: T,
    /// (cos θ5, sin θ5).
    pub swing_axis: Vector2<T>,
    /// dθ5/dt (rad/s).
    pub swing_rate: T,
    /// Hook load W (kg).
    pub load_kg: T,
}

/// A 2×2 block matrix [[A, b], [bᵀ, c]] with A of size M: the mass matrix of the
/// free coordinates (modes, swing), solved by a Schur complement on the swing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Block2<T: Real, const M: usize> {
    /// Mode–mode block.
    pub a: SMatrix<T, M, M>,
    /// Mode–swing coupling.
    pub b: SVector<T, M>,
    /// Swing–swing term.
    pub c: T,
}

impl<T: Real, const M: usize> Block2<T, M> {
    /// Solves [[A, b], [bᵀ, c]]·[x; y] = [f; g].
    pub fn solve(&self, f: &SVector<T, M>, g: T) -> Result<(SVector<T, M>, T), ModelError> {
        self.factor()?.solve(f, g)
    }

    /// The factorization (Schur complement on the swing, then Cholesky), for
    /// solving several right sides with one matrix (the Newton iteration).
    pub fn factor(&self) -> Result<Block2Factor<T, M>, ModelError> {
        if !(self.c > T::zero()) {
            return Err(ModelError::Singular("swing inertia"));
        }
        let schur = self.a - self.b * self.b.transpose() / self.c;
        let chol = schur
            .cholesky()
            .ok_or(ModelError::Singular("reduced mass matrix"))?;
        Ok(Block2Factor { chol, b: self.b, c: self.c, inverse: None })
    }
}

/// A factored [`Block2`].
#[derive(Debug, Clone, Copy)]
pub struct Block2Factor<T: Real, const M: usize> {
    chol: nalgebra::linalg::Cholesky<T, nalgebra::Const<M>>,
    b: SVector<T, M>,
    c: T,
    inverse: Option<SMatrix<T, M, M>>,
}

impl<T: Real, const M: usize> Block2Factor<T, M> {
    /// The same factorization with the Schur complement's inverse formed once,
    /// for a matrix that solves many right sides (the fast Newton iteration keeps
    /// one over steps): each solve is then one M×M product instead of two
    /// triangular sweeps. Equal to rounding, not bit for bit, so the reference
    /// iteration does not use it.
    pub fn with_inverse(self) -> Self {
        Block2Factor { inverse: Some(self.chol.inverse()), ..self }
    }

    /// Solves [[A, b], [bᵀ, c]]·[x; y] = [f; g].
    pub fn solve(&self, f: &SVector<T, M>, g: T) -> Result<(SVector<T, M>, T), ModelError> {
        let rhs = f - self.b * (g / self.c);
        let x = match &self.inverse {
            Some(inv) => inv * rhs,
            None => self.chol.solve(&rhs),
        };
        let y = (g - self.b.dot(&x)) / self.c;
        if !(x.iter().all(|v| v.is_finite()) && y.is_finite()) {
            return Err(ModelError::NotFinite("reduced accelerations"));
        }
        Ok((x, y))
    }
}

/// The equations of motion of the free coordinates (stage 2's output).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReducedEquations<T: Real, const M: usize> {
    /// NᵀMN.
    pub mass: Block2<T, M>,
    /// Nᵀ(forces − M·c), mode rows.
    pub force_eta: SVector<T, M>,
    /// Nᵀ(forces − M·c), swing row.
    pub force_swing: T,
    /// Acceleration of C when η̈ = 0: c5.
    pub tip_accel_known: Vector2<T>,
}

impl<T: Real, const M: usize> ReducedEquations<T, M> {
    /// Accelerations (η̈, θ̈5).
    pub fn solve(&self) -> Result<(SVector<T, M>, T), ModelError> {
        self.mass.solve(&self.force_eta, self.force_swing)
    }
}

/// The whole system of eq. 2.68 at one instant, over `n` = M + 15 coordinates.
#[derive(Debug, Clone, Copy)]
pub struct FullSystem<T: Real> {
    /// Number of coordinates.
    pub n: usize,
    /// Generalized coordinates x.
    pub position: [T; MAX_COORDS],
    /// Generalized speeds y (ẋ; in 2-D the angular speeds are θ̇).
    pub velocity: [T; MAX_COORDS],
    /// Generalized mass matrix M (eq. 2.69).
    pub mass: Square<T, MAX_COORDS>,
    /// Q + f + f_s + f_d (eq. 2.68).
    pub force: [T; MAX_COORDS],
    /// Constraint Jacobian B (eq. 2.59).
    pub jacobian: [[T; MAX_COORDS]; CONSTRAINTS],
    /// γ = −Ḃy + ġ: right side of B·ẏ = γ (eq. 2.67).
    pub gamma: [T; CONSTRAINTS],
    /// Position-level constraint residual Φ (m or rad).
    pub residual: [T; CONSTRAINTS],
}

impl<T: Real> FullSystem<T> {
    fn set_body(&mut self, base: usize, r: Vector2<T>, th: T, v: Vector2<T>, w: T) {
        self.position[base] = r.x;
        self.position[base + 1] = r.y;
        self.position[base + 2] = th;
        self.velocity[base] = v.x;
        self.velocity[base + 1] = v.y;
        self.velocity[base + 2] = w;
    }

    fn add_rigid_mass(&mut self, base: usize, m: T, coupling: Vector2<T>, inertia: T) {
        self.mass.set(base, base, m);
        self.mass.set(base + 1, base + 1, m);
        for i in 0..2 {
            self.mass.set(base + i, base + 2, coupling[i]);
            self.mass.set(base + 2, base + i, coupling[i]);
        }
        self.mass.set(base + 2, base + 2, inertia);
    }

    /// Largest |Φ| over the constraints.
    pub fn max_violation(&self) -> T {
        self.residual.iter().fold(T::zero(), |m, r| m.max(r.abs()))
    }
}
