//! Stages 3–6 of a step: accelerations, Lagrange multipliers, reactions, and the
//! thesis's augmented solve (eq. 2.68) that the reduced solve is checked against.

use crate::structure::dense::Square;
use crate::multibody::{
    Configuration, CraneModel, FreeCoordinates, FullSystem, ReducedEquations, RigidMotion,
    CONSTRAINTS, MAX_COORDS,
};
use crate::data::profile::ActuatorMotion;
use crate::{ModelError, Real};
use nalgebra::{SMatrix, SVector, Vector2};

/// Capacity of the augmented system (M + 15 coordinates + 14 multipliers).
pub const MAX_AUGMENTED: usize = MAX_COORDS + CONSTRAINTS;

/// Index of the prescribed-motion constraint: its multiplier is the piston force.
pub const PRESCRIBED_MOTION: usize = 13;

/// One evaluation of the equations of motion at a state.
#[derive(Debug, Clone, Copy)]
pub struct Evaluation<T: Real, const M: usize> {
    /// Positions and velocities of every body.
    pub config: Configuration<T, M>,
    /// The projected equations.
    pub equations: ReducedEquations<T, M>,
    /// η̈.
    pub eta_accel: SVector<T, M>,
    /// θ̈5.
    pub swing_accel: T,
}

/// Forces of the crane on the chassis and the rear-jack reaction (thesis §4.3.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reactions<T: Real> {
    /// Piston force F (N): the multiplier of the prescribed-motion constraint, positive
    /// when the oil pushes the piston out (compression of the cylinder).
    pub piston_force_n: T,
    /// Force of bodies 1 and 2 on the chassis at A0 (N).
    pub boom_foot_n: Vector2<T>,
    /// Force of body 4 on the chassis at B0 (N).
    pub cylinder_foot_n: Vector2<T>,
    /// Ground reaction on the rear jacks F_A (N, eq. 4.2); the crane tips at F_A ≤ 0.
    pub jack_reaction_n: T,
    /// F_A·A: the moment about the tipping line that keeps the crane down (N·m,
    /// the listing's `FJK`), independent of the assumed jack base A.
    pub stabilizing_moment_nm: T,
}

impl<T: Real, const M: usize> CraneModel<T, M> {
    /// Stages 1–3: kinematics, projected equations and their solve.
    pub fn evaluate(
        &self,
        act: ActuatorMotion<T>,
        load_kg: T,
        free: &FreeCoordinates<T, M>,
    ) -> Result<Evaluation<T, M>, ModelError> {
        self.evaluate_at(&self.rigid_motion(act, load_kg)?, free)
    }

    /// Stages 1b–3 with the time-only kinematics already computed.
    pub fn evaluate_at(
        &self,
        rigid: &RigidMotion<T>,
        free: &FreeCoordinates<T, M>,
    ) -> Result<Evaluation<T, M>, ModelError> {
        let config = self.configure(rigid, free);
        let equations = self.reduced_equations(&config);
        let (eta_accel, swing_accel) = equations.solve()?;
        Ok(Evaluation {
            config,
            equations,
            eta_accel,
            swing_accel,
        })
    }

    /// The full acceleration vector ẏ of eq. 2.68 from the free accelerations.
    pub fn full_accelerations(&self, ev: &Evaluation<T, M>) -> [T; MAX_COORDS] {
        let mut acc = [T::zero(); MAX_COORDS];
        let mech = &ev.config.mech;
        let bodies = [
            (1usize, &mech.boom),
            (2, &mech.lug),
            (3, &mech.rod),
            (4, &mech.cylinder),
        ];
        for (k, b) in bodies {
            let i = Self::body_index(k);
            acc[i] = b.acceleration.x;
            acc[i + 1] = b.acceleration.y;
            acc[i + 2] = b.angular_acceleration;
        }
        for k in 0..M {
            acc[3 + k] = ev.eta_accel[k];
        }
        let i5 = Self::body_index(5);
        let tip =
            ev.equations.tip_accel_known + ev.config.rot * (ev.config.tip_modes * ev.eta_accel);
        acc[i5] = tip.x;
        acc[i5 + 1] = tip.y;
        acc[i5 + 2] = ev.swing_accel;
        acc
    }

    /// Stage 5: the Lagrange multipliers λ from Bᵀλ = Q + f + f_s + f_d − M·ẏ
    /// (eq. 2.68, first row), solved on the 14 dependent coordinates.
    pub fn multipliers(
        &self,
        ev: &Evaluation<T, M>,
    ) -> Result<(FullSystem<T>, [T; CONSTRAINTS]), ModelError> {
        let sys = self.full_system(&ev.config)?;
        let acc = self.full_accelerations(ev);
        let m_acc = sys.mass.mul_vec(&acc);
        let dep = Self::dependent_indices();
        let bt = SMatrix::<T, CONSTRAINTS, CONSTRAINTS>::from_fn(|r, c| sys.jacobian[c][dep[r]]);
        let rhs = SVector::<T, CONSTRAINTS>::from_fn(|r, _| sys.force[dep[r]] - m_acc[dep[r]]);
        let lambda = bt
            .lu()
            .solve(&rhs)
            .ok_or(ModelError::Singular("constraint Jacobian (dependent part)"))?;
        let mut out = [T::zero(); CONSTRAINTS];
        for (o, l) in out.iter_mut().zip(lambda.iter()) {
            *o = *l;
        }
        Ok((sys, out))
    }

    /// Stage 6: the reactions from the multipliers (the constraint force on a body is
    /// −Bᵀλ, eq. 2.60, so the crane pushes the chassis with +λ at its ground pins).
    pub fn reactions(&self, lambda: &[T; CONSTRAINTS]) -> Reactions<T> {
        let ch = &self.crane.chassis;
        let xt = T::lit(ch.tipping_line_x_m);
        let moment = |at: Vector2<T>, f: Vector2<T>| (at.x - xt) * f.y - at.y * f.x;
        let boom_foot_n = Vector2::new(lambda[0] + lambda[2], lambda[1] + lambda[3]);
        let cylinder_foot_n = Vector2::new(lambda[4], lambda[5]);
        let stabilizing = moment(self.geometry.boom_foot, boom_foot_n)
            + moment(self.geometry.cylinder_foot, cylinder_foot_n)
            + T::lit(ch.weight_n * ch.weight_arm_m);
        Reactions {
            piston_force_n: -lambda[crate::multibody::dynamics::PRESCRIBED_MOTION],
            boom_foot_n,
            cylinder_foot_n,
            jack_reaction_n: stabilizing / T::lit(ch.jack_base_m),
            stabilizing_moment_nm: stabilizing,
        }
    }

    /// Stage 5 for the piston force alone (inverse dynamics along the actuator):
    /// with y_a the velocities of all coordinates for a unit actuator rate at fixed
    /// modes and swing (it satisfies every constraint but the prescribed motion, whose
    /// row gives B₁₄·y_a = 1), y_aᵀ·Bᵀλ = λ₁₄, so from eq. 2.68
    /// F = −λ₁₄ = y_aᵀ·(M·ẏ − (Q + f + f_s + f_d)): one power balance over the five
    /// bodies, without the full mass matrix or the 14×14 solve of
    /// [`Self::multipliers`]. Equal to the multiplier to rounding (tested).
    pub fn piston_force_along_actuator_n(&self, ev: &Evaluation<T, M>) -> Result<T, ModelError> {
        let cfg = &ev.config;
        let mech = &cfg.mech;
        let act = mech.actuator;
        let unit = self.geometry.motion(ActuatorMotion { extension_m: act.extension_m, rate_m_s: T::one(), accel_m_s2: T::zero() })?;
        let g = Vector2::new(T::zero(), -self.gravity_m_s2);
        let two = T::lit(2.0);
        let m = &self.modes;
        let jmat = nalgebra::Matrix2::new(T::zero(), -T::one(), T::one(), T::zero());
        // Body 1 (eqs. 3.1–3.11): rows x1, y1, θ1 of M·ẏ − forces.
        let b1 = &mech.boom;
        let (w1, al1) = (b1.angular_velocity, b1.angular_acceleration);
        let d = SMatrix::<T, 2, M>::from_fn(|r, c| m.first_moment_modes[r][c]);
        let skew = SMatrix::<T, M, M>::from_fn(|r, c| m.skew_modes[r][c]);
        let first = Vector2::new(m.first_moment_rest[0], m.first_moment_rest[1]) + d * cfg.eta;
        let coupling = SVector::<T, M>::from_column_slice(&m.inertia_coupling) + cfg.eta;
        let inertia = m.inertia_rest + two * SVector::<T, M>::from_column_slice(&m.inertia_coupling).dot(&cfg.eta) + cfg.eta.dot(&cfg.eta);
        let h = SVector::<T, M>::from_column_slice(&m.skew_rest) + skew * cfg.eta;
        let tj_first = cfg.rot * (jmat * first);
        let td = cfg.rot * d;
        let q_r = cfg.rot * first * (w1 * w1) - cfg.rot * (jmat * (d * cfg.eta_rate)) * (two * w1);
        let q_th = -(two * w1) * coupling.dot(&cfg.eta_rate);
        let r1 = b1.acceleration * m.mass_kg + tj_first * al1 + td * ev.eta_accel - (g * m.mass_kg + q_r);
        let t1 = tj_first.dot(&b1.acceleration) + inertia * al1 + h.dot(&ev.eta_accel) - (tj_first.dot(&g) + q_th);
        let mut power = unit.boom.velocity.dot(&r1) + unit.boom.angular_velocity * t1;
        // Rigid bodies 2–4 (eqs. 3.12–3.16).
        let rigid = [(&mech.lug, &unit.lug, self.lug), (&mech.rod, &unit.rod, self.rod), (&mech.cylinder, &unit.cylinder, cfg.cylinder)];
        for (b, u, mass) in rigid {
            let (e, n) = (b.axis, b.normal());
            let (w, al, s) = (b.angular_velocity, b.angular_acceleration, mass.first_moment_kg_m);
            let fr = b.acceleration * mass.mass_kg + n * (s * al) - (g * mass.mass_kg + e * (s * w * w));
            let ft = s * n.dot(&b.acceleration) + mass.inertia_kg_m2 * al - s * n.dot(&g);
            power += u.velocity.dot(&fr) + u.angular_velocity * ft;
        }
        // Body 5 at C: moves with the tip (θ5 held), so only its translation rows.
        let p = &cfg.pendulum;
        let e5 = cfg.swing_axis;
        let n5 = Vector2::new(-e5.y, e5.x);
        let w5 = cfg.swing_rate;
        let acc5 = ev.equations.tip_accel_known + cfg.rot * (cfg.tip_modes * ev.eta_accel);
        let f5 = g * p.mass_kg
            + e5 * (p.first_moment_kg_m * w5 * w5 - p.first_moment_per_m * p.length_accel_m_s2)
            - n5 * (two * p.first_moment_per_m * p.length_rate_m_s * w5);
        let r5 = acc5 * p.mass_kg + n5 * (p.first_moment_kg_m * ev.swing_accel) - f5;
        let v5 = unit.boom.velocity + cfg.rot * (jmat * cfg.tip_body) * unit.boom.angular_velocity;
        power += v5.dot(&r5);
        if !power.is_finite() {
            return Err(ModelError::NotFinite("piston force"));
        }
        Ok(power)
    }

    /// The rope force at C from the revolute-at-C multipliers (rows 11–12): the pin
    /// pushes body 5 with λ_C, so the tension along the rope (pulling the load
    /// towards C, opposite to the rope axis e5) is −λ_C·e5.
    pub fn rope_tension_n(&self, lambda: &[T; CONSTRAINTS], swing_axis: Vector2<T>) -> T {
        let l = Vector2::new(lambda[11], lambda[12]);
        -l.dot(&swing_axis)
    }

    /// The thesis's way (eq. 2.68): one solve of the augmented system
    /// [M Bᵀ; B 0]·[ẏ; λ] = [Q + f + f_s + f_d; γ] for accelerations and multipliers.
    pub fn solve_augmented(
        &self,
        cfg: &Configuration<T, M>,
    ) -> Result<([T; MAX_COORDS], [T; CONSTRAINTS]), ModelError> {
        let sys = self.full_system(cfg)?;
        let n = sys.n;
        let mut a = Square::<T, MAX_AUGMENTED>::zeros(n + CONSTRAINTS)?;
        let mut rhs = [T::zero(); MAX_AUGMENTED];
        for i in 0..n {
            for j in 0..n {
                a.set(i, j, sys.mass.get(i, j));
            }
            rhs[i] = sys.force[i];
        }
        for (c, row) in sys.jacobian.iter().enumerate() {
            for (j, &b) in row.iter().enumerate().take(n) {
                a.set(n + c, j, b);
                a.set(j, n + c, b);
            }
            rhs[n + c] = sys.gamma[c];
        }
        let x = a.solve(&rhs)?;
        let mut acc = [T::zero(); MAX_COORDS];
        acc[..n].copy_from_slice(&x[..n]);
        let mut lambda = [T::zero(); CONSTRAINTS];
        lambda.copy_from_slice(&x[n..n + CONSTRAINTS]);
        Ok((acc, lambda))
    }
}
