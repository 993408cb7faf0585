//! A second formulation of the crane, for testing the limiter in a world
//! that shares none of the simulator's dynamics: a rigid mechanism written
//! from Lagrange's equation for its one degree of freedom, with the load a
//! point mass on a pendulum integrated here.
//!
//! The simulator (`crane_model`) is a flexible multibody model whose piston
//! force is a Lagrange multiplier of an augmented system; the limiter's load
//! model is built from that same code. A mistake they share (a body's
//! inertia, the tip's kinematics, the rope's pull) would pass every test
//! run on the simulator's logs. Here the piston force of a move comes from
//! elsewhere:
//!
//! - the weights' moment ∂V/∂θ of boom, lug rod, piston rod, tube and oil
//!   from the independent virtual-work reference of `crane-model`'s tests
//!   (`QuasiStatic`: the thesis data only, the boom's section by the
//!   shoelace formulas), the boom rigid;
//! - the mechanism's generalized inertia J(θ) = Σ mᵢ·|∂rᵢ/∂θ|² + Iᵢ·(∂αᵢ/∂θ)²
//!   from the same geometry (boom ρ∫A·x² dx about A0, lug rod and tube as
//!   uniform rods about their pins, the piston rod sliding and turning with
//!   the cylinder's axis, the oil as the reference places it);
//! - Lagrange's equation for the prescribed angle θ(t):
//!   F·s′(θ) = J(θ)·θ̈ + ½·J′(θ)·θ̇² + ∂V/∂θ − Q_load, Q_load = f_C·∂C/∂θ,
//!   s the actuator's length and f_C the rope's pull on the tip C;
//! - the load a point mass m on a rope of length l from C, at angle φ from
//!   the vertical (positive outward): l·φ̈ = −g·sin φ − C̈ₓ·cos φ − C̈ᵧ·sin φ
//!   − 2·l̇·φ̇, its acceleration a = C̈ + l̈·e + 2·l̇·φ̇·e⊥ + l·(φ̈·e⊥ − φ̇²·e)
//!   with e = (sin φ, −cos φ), e⊥ = (cos φ, sin φ), and f_C = m·((0, −g) − a).
//!   Held, l is constant; paid out, the winch keeps the load at its
//!   clearance: l = y_C − clearance, l̇ = ẏ_C, l̈ = ÿ_C.
//!
//! Only the prescribed angle θ(t), the piston's speed and the hook load of
//! a lift-off are taken from the simulator's samples (kinematics, not
//! dynamics); the piston force and the swing are replaced. The boom does
//! not bend, so this world has none of the simulator's 3–4 Hz oscillation
//! and none of its bounce on the boom's bending: what it checks is the
//! rigid-body part, the inertia of the load riding with the tip, and the
//! swing, which the limiter must not read as load.

#[path = "../../../crates/crane-model/tests/common/mod.rs"]
mod reference;

use crane_model::data::profile::{RampShape, StrokeProfile};
use crane_model::sim::simulation::Sample;
use reference::dynamics::QuasiStatic;

/// How the rope's hanging length behaves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Hanging {
    /// Paid out to keep the load this high above the ground (m).
    PaidOut { clearance_m: f64 },
    /// Held at this length (m).
    Held { length_m: f64 },
    /// Luffed and hoisted at once: `length_m` at the start, and while the
    /// boom moves (from the first sample whose angle differs from the
    /// first one to the last that differs from the last one) the winch
    /// takes the hook up by `by_m` (negative: lets it down) at a trapezoidal
    /// speed, ramps of [`winch_ramp_s`] at each end; held before and after.
    Winched { length_m: f64, by_m: f64 },
}

/// The winch's ramp for a move of `move_s` (s): 1 s, at most a quarter of
/// the move.
fn winch_ramp_s(move_s: f64) -> f64 {
    (move_s / 4.0).min(1.0)
}

/// The rigid crane: the reference's geometry and weights, and the boom's
/// moment of inertia about A0.
pub struct RigidCrane {
    qs: QuasiStatic,
    boom_inertia_kg_m2: f64,
}

/// The step of the central differences in θ (rad).
const H: f64 = 1e-5;

impl RigidCrane {
    /// The thesis crane, from its data alone.
    pub fn new() -> Self {
        let qs = QuasiStatic::new();
        let rho = qs.crane.boom.density_kg_m3;
        // ρ∫A(x)·x² dx by trapezoids on the reference's 1 mm stations.
        let boom_inertia_kg_m2 = rho
            * qs.x
                .windows(2)
                .zip(qs.area.windows(2))
                .map(|(x, a)| 0.5 * (x[1] - x[0]) * (a[0] * x[0] * x[0] + a[1] * x[1] * x[1]))
                .sum::<f64>();
        RigidCrane { qs, boom_inertia_kg_m2 }
    }

    /// The boom's length A0 → C (m).
    pub fn boom_length_m(&self) -> f64 {
        self.qs.crane.boom.length_m()
    }

    /// The rope's mass per metre (kg/m).
    pub fn rope_kg_per_m(&self) -> f64 {
        self.qs.crane.rope.mass_per_m_kg
    }

    /// The tip C of the rigid boom at θ (m; ground at y = 0).
    pub fn tip(&self, th: f64) -> [f64; 2] {
        let a0 = self.qs.crane.boom_foot;
        let l = self.boom_length_m();
        [a0[0] + l * th.cos(), a0[1] + l * th.sin()]
    }

    /// The cylinder's axis B0 → D: its length s and angle ψ.
    fn cylinder(&self, th: f64) -> (f64, f64) {
        let (d, b0) = (self.qs.pin_d(th), self.qs.crane.cylinder_foot);
        let (dx, dy) = (d[0] - b0[0], d[1] - b0[1]);
        (dx.hypot(dy), dy.atan2(dx))
    }

    /// The cylinder's length s and its rates s′(θ) = ds/dθ (m/rad) and
    /// ψ′(θ) = dψ/dθ, by central differences.
    fn cylinder_slopes(&self, th: f64) -> (f64, f64, f64) {
        let ((s_hi, psi_hi), (s_lo, psi_lo)) = (self.cylinder(th + H), self.cylinder(th - H));
        (self.cylinder(th).0, (s_hi - s_lo) / (2.0 * H), (psi_hi - psi_lo) / (2.0 * H))
    }

    /// The generalized inertia J(θ) (kg·m²): twice the kinetic energy at
    /// θ̇ = 1 rad/s.
    fn inertia(&self, th: f64) -> f64 {
        let c = &self.qs.crane;
        let (s, ds, dpsi) = self.cylinder_slopes(th);
        // Lug rod: a uniform rod turning with the boom about A0.
        let lug = &c.lug_rod;
        let mut j = self.boom_inertia_kg_m2 + lug.mass_kg() * lug.length_m * lug.length_m / 3.0;
        // Piston rod: its centre s − L3/2 from B0 on the axis, sliding at ṡ
        // and turning at ψ̇; its own inertia about the centre m·L3²/12.
        let rod = &c.piston_rod;
        let r_rod = s - rod.length_m / 2.0;
        j += rod.mass_kg() * (ds * ds + r_rod * r_rod * dpsi * dpsi) + rod.mass_kg() * rod.length_m * rod.length_m / 12.0 * dpsi * dpsi;
        // Tube: a uniform rod turning about B0.
        let cy = &c.cylinder;
        j += cy.tube_mass_kg * cy.length_m * cy.length_m / 3.0 * dpsi * dpsi;
        // Oil, where the reference puts it: the bore's column from B0 to the
        // piston (centre a/2, moving at ȧ/2), the annulus's beyond it.
        let a = s - rod.length_m;
        let bore = std::f64::consts::PI * cy.bore_radius_m * cy.bore_radius_m;
        let annulus = bore - std::f64::consts::PI * rod.radius_m * rod.radius_m;
        let oil_bore = cy.oil_density_kg_m3 * bore * a;
        let oil_annulus = cy.oil_density_kg_m3 * annulus * (cy.inner_length_m - cy.piston_thickness_m - a);
        let (r_bore, r_annulus) = (a / 2.0, (a + cy.piston_thickness_m + cy.inner_length_m) / 2.0);
        j += oil_bore * (ds * ds / 4.0 + r_bore * r_bore * dpsi * dpsi);
        j += oil_annulus * (ds * ds / 4.0 + r_annulus * r_annulus * dpsi * dpsi);
        j
    }

    /// ∂V/∂θ of the mechanism's own weights (N·m): the reference's
    /// potential without its body 5 (the rope and load, whose pull this
    /// world applies at C itself).
    pub fn weight_moment(&self, th: f64) -> f64 {
        let g = self.qs.crane.gravity_m_s2;
        let body5 = |t: f64| self.qs.hanging_mass(th, 0.0) * g * self.tip(t)[1];
        let v = |t: f64| self.qs.frozen_potential(t, th, 0.0, (0.0, 0.0)) - body5(t);
        (v(th + H) - v(th - H)) / (2.0 * H)
    }

    /// The piston force (N) that moves the boom at θ, θ̇, θ̈ with the rope
    /// pulling the tip with `tip_force` (N).
    pub fn piston_force(&self, th: f64, thd: f64, thdd: f64, tip_force: [f64; 2]) -> f64 {
        let l = self.boom_length_m();
        let dj = (self.inertia(th + H) - self.inertia(th - H)) / (2.0 * H);
        let q_load = tip_force[0] * (-l * th.sin()) + tip_force[1] * (l * th.cos());
        (self.inertia(th) * thdd + 0.5 * dj * thd * thd + self.weight_moment(th) - q_load) / self.cylinder_slopes(th).1
    }

    /// The reference's quasi-static piston force with the paid-out rope and
    /// `load_kg` (N): of a rigid boom, to check [`Self::piston_force`] at
    /// rest, or with the boom's static sag (the reference's beam) as the
    /// flexible model has it.
    pub fn reference_static_force(&self, th: f64, load_kg: f64, sag: bool) -> f64 {
        self.qs.piston_force(th, load_kg, sag)
    }

    /// Replaces the piston force and the swing of the simulator's `samples`
    /// by this world's, for the same prescribed angle, piston speed and
    /// hook load, with the rope `hanging`. The load starts hanging still.
    pub fn replace_forces(&self, samples: &mut [Sample<f64>], hanging: Hanging) {
        let n = samples.len();
        if n < 3 {
            return;
        }
        let g = self.qs.crane.gravity_m_s2;
        let len = self.boom_length_m();
        // θ̇, θ̈ of the prescribed angle by central differences (one-sided
        // at the ends, where the boom is at rest).
        let th: Vec<f64> = samples.iter().map(|s| s.boom_angle_rad).collect();
        let t: Vec<f64> = samples.iter().map(|s| s.t_s).collect();
        let mut thd = vec![0.0; n];
        let mut thdd = vec![0.0; n];
        for i in 1..n - 1 {
            let (h0, h1) = (t[i] - t[i - 1], t[i + 1] - t[i]);
            thd[i] = (th[i + 1] - th[i - 1]) / (h0 + h1);
            thdd[i] = 2.0 * ((th[i + 1] - th[i]) / h1 - (th[i] - th[i - 1]) / h0) / (h0 + h1);
        }
        // The winch's travel over the samples where the boom moves, as a
        // stroke of 0 → 1 with linear ramps; none without a move.
        let first_moving = (0..n).find(|&i| (th[i] - th[0]).abs() > 1e-9).map_or(0.0, |i| t[i.saturating_sub(1)]);
        let last_moving = (0..n).rev().find(|&i| (th[i] - th[n - 1]).abs() > 1e-9).map_or(0.0, |i| t[(i + 1).min(n - 1)]);
        let move_s = last_moving - first_moving;
        let ramp = winch_ramp_s(move_s);
        let winch = (move_s > 0.0).then_some(StrokeProfile { shape: RampShape::Linear, t1_s: ramp, t2_s: move_s - ramp, t3_s: move_s, start_m: 0.0, end_m: 1.0 });
        // The tip's and the rope's kinematics at (t, θ, θ̇, θ̈).
        let kin = |time: f64, th: f64, thd: f64, thdd: f64| {
            let (s, c) = th.sin_cos();
            let tip = self.tip(th);
            let tip_v = [-len * s * thd, len * c * thd];
            let tip_a = [-len * (s * thdd + c * thd * thd), len * (c * thdd - s * thd * thd)];
            let (l, ld, ldd) = match hanging {
                Hanging::Held { length_m } => (length_m, 0.0, 0.0),
                Hanging::PaidOut { clearance_m } => (tip[1] - clearance_m, tip_v[1], tip_a[1]),
                Hanging::Winched { length_m, by_m } => match winch.map(|w| w.at(time - first_moving)) {
                    Some(m) => (length_m - by_m * m.extension_m, -by_m * m.rate_m_s, -by_m * m.accel_m_s2),
                    None => (length_m, 0.0, 0.0),
                },
            };
            (tip_a, l, ld, ldd)
        };
        let phi_dd = |phi: f64, phid: f64, (tip_a, l, ld, _): ([f64; 2], f64, f64, f64)| {
            (-g * phi.sin() - tip_a[0] * phi.cos() - tip_a[1] * phi.sin() - 2.0 * ld * phid) / l
        };
        let (mut phi, mut phid) = (0.0f64, 0.0f64);
        const SUB: usize = 10;
        for i in 0..n {
            if i > 0 {
                // RK4 over the step, the kinematics linear between samples.
                let dt = t[i] - t[i - 1];
                let at = |f: f64| kin(t[i - 1] + f * dt, th[i - 1] + f * (th[i] - th[i - 1]), thd[i - 1] + f * (thd[i] - thd[i - 1]), thdd[i - 1] + f * (thdd[i] - thdd[i - 1]));
                let h = dt / SUB as f64;
                for k in 0..SUB {
                    let f0 = k as f64 / SUB as f64;
                    let (fa, fb) = (f0 + 0.5 / SUB as f64, f0 + 1.0 / SUB as f64);
                    let (ka, kb, kc) = (at(f0), at(fa), at(fb));
                    let k1 = (phid, phi_dd(phi, phid, ka));
                    let k2 = (phid + 0.5 * h * k1.1, phi_dd(phi + 0.5 * h * k1.0, phid + 0.5 * h * k1.1, kb));
                    let k3 = (phid + 0.5 * h * k2.1, phi_dd(phi + 0.5 * h * k2.0, phid + 0.5 * h * k2.1, kb));
                    let k4 = (phid + h * k3.1, phi_dd(phi + h * k3.0, phid + h * k3.1, kc));
                    phi += h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
                    phid += h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
                }
            }
            let k = kin(t[i], th[i], thd[i], thdd[i]);
            let (tip_a, l, ld, ldd) = k;
            let pdd = phi_dd(phi, phid, k);
            let (e, ep) = ([phi.sin(), -phi.cos()], [phi.cos(), phi.sin()]);
            let acc = [0, 1].map(|j| tip_a[j] + ldd * e[j] + 2.0 * ld * phid * ep[j] + l * (pdd * ep[j] - phid * phid * e[j]));
            let m = samples[i].hook_load_kg + self.rope_kg_per_m() * l;
            let pull = [-m * acc[0], m * (-g - acc[1])];
            let x = &mut samples[i];
            x.reactions.piston_force_n = self.piston_force(th[i], thd[i], thdd[i], pull);
            x.swing_rad = phi;
        }
    }
}
