//! The dynamics tests' shared helpers: the thesis model, a maneuver run to
//! rows of f64, and the independent quasi-static reference (virtual work of
//! all weights, from the thesis data only).

use crane_model::data::crane::CraneData;
use crane_model::structure::modal::{MeshRefinement, THESIS_BASIS};
use crane_model::multibody::ThesisModel;
use crane_model::data::profile::RampShape;
use crane_model::sim::simulation::{Direction, Maneuver, SimulationOptions};
use crane_model::Real;
use std::f64::consts::PI;

use super::{dims_at, hollow};

pub fn model() -> ThesisModel<f64> {
    ThesisModel::<f64>::build(
        &CraneData::coles_mobile_930(),
        MeshRefinement::THESIS,
        &THESIS_BASIS,
    )
    .expect("thesis model")
}

/// One output sample, in f64.
#[derive(Debug, Clone, Copy)]
pub struct Row {
    pub t: f64,
    pub angle: f64,
    pub force: f64,
    pub swing: f64,
    pub tip: f64,
    pub violation: f64,
}

pub fn run<T: Real>(model: &ThesisModel<T>, m: &Maneuver, opts: &SimulationOptions) -> Vec<Row> {
    let mut rows = Vec::new();
    model
        .simulate(m, opts, |s| {
            rows.push(Row {
                t: s.t_s.to_f64(),
                angle: s.boom_angle_rad.to_f64(),
                force: s.reactions.piston_force_n.to_f64(),
                swing: s.swing_rad.to_f64(),
                tip: s.deflection_m[2].to_f64(),
                violation: s.constraint_violation.to_f64(),
            });
            true
        })
        .expect("simulation");
    rows
}

pub fn maneuver(load: f64, duration: f64, shape: RampShape, dir: Direction) -> Maneuver {
    Maneuver::thesis(load, duration, shape, dir).expect("thesis maneuver")
}

/// The piston force of the model at rest at boom angle θ (static equilibrium state).
pub fn model_static_force(model: &ThesisModel<f64>, th: f64, load: f64) -> (f64, f64) {
    let act = model.actuator_at(th, 0.0);
    let free = model.equilibrium_state(th, load).expect("equilibrium");
    let ev = model.evaluate(act, load, &free).expect("evaluate");
    let s = model.sample(&ev, 0.0, 0).expect("sample");
    (s.reactions.piston_force_n, s.deflection_m[2])
}

/// Linear interpolation of the force at boom angle `deg` (monotone angle during an up maneuver).
pub fn at_angle(rows: &[Row], deg: f64) -> f64 {
    let th = deg.to_radians();
    let i = rows
        .iter()
        .position(|r| r.angle >= th)
        .expect("angle reached");
    let (a, b) = (rows[i - 1], rows[i]);
    a.force + (th - a.angle) / (b.angle - a.angle) * (b.force - a.force)
}

pub fn max_relative_gap(a: &[Row], b: &[Row]) -> (f64, f64) {
    assert_eq!(a.len(), b.len());
    let mut worst = (0.0f64, 0.0);
    for (x, y) in a.iter().zip(b.iter()) {
        assert!((x.t - y.t).abs() < 1e-4);
        let rel = (x.force - y.force).abs() / y.force.abs();
        if rel > worst.0 {
            worst = (rel, y.t);
        }
    }
    worst
}

// ---------------------------------------------------------------------------
// The independent quasi-static reference: virtual work of all weights.
// ---------------------------------------------------------------------------

/// The crane's weights and geometry, from the thesis data only (SPEC §2).
pub struct QuasiStatic {
    pub crane: CraneData,
    /// Stations along the boom (m from A0), area and EI there.
    pub x: Vec<f64>,
    pub area: Vec<f64>,
    pub ei: Vec<f64>,
    /// Boom mass and first moment about A0 (kg, kg·m).
    pub boom_mass: f64,
    pub boom_first_moment: f64,
}

impl QuasiStatic {
    pub fn new() -> Self {
        let crane = CraneData::coles_mobile_930();
        let b = crane.boom;
        // Fine grid with a node at G (where the taper changes) and at A.
        let n = 19_500;
        let x: Vec<f64> = (0..=n)
            .map(|i| b.length_m() * i as f64 / n as f64)
            .collect();
        let (mut area, mut ei) = (Vec::new(), Vec::new());
        for &xi in &x {
            let (a, i) = hollow(dims_at(&b, xi), b.wall_m);
            area.push(a);
            ei.push(b.youngs_modulus_pa * i);
        }
        // Trapezoid on 1 mm spacing (G at x = 2 m is a grid node; A(x) is smooth on each side).
        let (mut m, mut s) = (0.0, 0.0);
        for k in 0..n {
            let h = x[k + 1] - x[k];
            m += 0.5 * h * (area[k] + area[k + 1]);
            s += 0.5 * h * (area[k] * x[k] + area[k + 1] * x[k + 1]);
        }
        let rho = b.density_kg_m3;
        QuasiStatic {
            crane,
            x,
            area,
            ei,
            boom_mass: rho * m,
            boom_first_moment: rho * s,
        }
    }

    pub fn gamma(&self) -> f64 {
        (self.crane.lug_offset_m / self.crane.lug_rod.length_m).asin()
    }

    /// Cylinder pin D and actuator length s = |D − B0| (B0 to D) at boom angle θ.
    pub fn pin_d(&self, th: f64) -> [f64; 2] {
        let (a0, l2) = (self.crane.boom_foot, self.crane.lug_rod.length_m);
        let th2 = th - self.gamma();
        [a0[0] + l2 * th2.cos(), a0[1] + l2 * th2.sin()]
    }

    pub fn actuator_length(&self, th: f64) -> f64 {
        let (d, b0) = (self.pin_d(th), self.crane.cylinder_foot);
        (d[0] - b0[0]).hypot(d[1] - b0[1])
    }

    /// Hanging rope length: tip height minus the load's 1 m clearance.
    pub fn rope_length(&self, th: f64) -> f64 {
        let c = &self.crane;
        c.boom_foot[1] + c.boom.length_m() * th.sin() - c.rope.load_clearance_m
    }

    /// Rope and hook load (kg) at boom angle θ.
    pub fn hanging_mass(&self, th: f64, load: f64) -> f64 {
        load + self.crane.rope.mass_per_m_kg * self.rope_length(th)
    }

    /// Transverse static deflection v(x) of the boom (body frame, + toward the boom's
    /// upper side) under its own weight and the hanging weight at C, by double
    /// integration of M/EI along the overhang A–C clamped at A (the frame's boundary
    /// conditions). The part A0–A (pinned at A0, clamped at A, 5.8 m of the stiffest
    /// section) sags by ~2e-5 m and is left rigid. Returns (∫ρA·v dx, v_C).
    pub fn sag(&self, th: f64, load: f64) -> (f64, f64) {
        let c = &self.crane;
        let g = c.gravity_m_s2;
        let rho = c.boom.density_kg_m3;
        let n = self.x.len() - 1;
        let ia = self
            .x
            .iter()
            .position(|&x| x >= c.boom.foot_to_lug_m - 1e-12)
            .expect("A on the grid");
        // Transverse loads: q = −ρA·g·cosθ per metre, P = −m5·g·cosθ at C.
        let q: Vec<f64> = self.area.iter().map(|a| -rho * a * g * th.cos()).collect();
        let p = -self.hanging_mass(th, load) * g * th.cos();
        // Shear and bending moment from the tip inward: V' = −q, M' = −V, M(L) = 0, V(L) = P.
        let (mut v_sh, mut mom) = (vec![0.0; n + 1], vec![0.0; n + 1]);
        v_sh[n] = p;
        for k in (ia..n).rev() {
            let h = self.x[k + 1] - self.x[k];
            v_sh[k] = v_sh[k + 1] + 0.5 * h * (q[k] + q[k + 1]);
            mom[k] = mom[k + 1] + 0.5 * h * (v_sh[k] + v_sh[k + 1]);
        }
        // v'' = M/EI with v = v' = 0 at A.
        let (mut slope, mut v) = (0.0, 0.0);
        let mut integral = 0.0;
        for k in ia..n {
            let h = self.x[k + 1] - self.x[k];
            let s_next = slope + 0.5 * h * (mom[k] / self.ei[k] + mom[k + 1] / self.ei[k + 1]);
            let v_next = v + 0.5 * h * (slope + s_next);
            integral += 0.5 * h * rho * (self.area[k] * v + self.area[k + 1] * v_next);
            slope = s_next;
            v = v_next;
        }
        (integral, v)
    }

    /// Potential energy of all bodies at boom angle θ with every mass (the oil in the
    /// cylinder, the hanging rope) and the boom's elastic shape frozen at their values
    /// at θ0: the virtual work of the weights the model applies (the winch pays out
    /// rope so the load stays 1 m above ground; the rope and load weight acts at C).
    pub fn frozen_potential(&self, th: f64, th0: f64, load: f64, sag: (f64, f64)) -> f64 {
        let c = &self.crane;
        let g = c.gravity_m_s2;
        let (a0, b0) = (c.boom_foot, c.cylinder_foot);
        let (s_th, c_th) = (th.sin(), th.cos());
        // Body 1: y = A0y + x·sinθ + v(x)·cosθ.
        let mut v = g * (self.boom_mass * a0[1] + self.boom_first_moment * s_th + sag.0 * c_th);
        // Body 2: uniform rod from A0 at θ − γ.
        let lug = &c.lug_rod;
        v += lug.mass_kg() * g * (a0[1] + lug.length_m / 2.0 * (th - self.gamma()).sin());
        // Axis of the cylinder from B0 to D.
        let d = self.pin_d(th);
        let s = self.actuator_length(th);
        let e4y = (d[1] - b0[1]) / s;
        // Body 3: piston rod of length L3 ending at D, on the cylinder axis.
        let rod = &c.piston_rod;
        v += rod.mass_kg() * g * (d[1] - rod.length_m / 2.0 * e4y);
        // Body 4: tube (centre at half its length from B0) and the oil at stroke a(θ0):
        // bore side from B0 to the piston, annulus side from the piston's far face to the inner end.
        let cy = &c.cylinder;
        let a = self.actuator_length(th0) - rod.length_m;
        let bore = PI * cy.bore_radius_m * cy.bore_radius_m;
        let annulus = bore - PI * rod.radius_m * rod.radius_m;
        let oil_bore = cy.oil_density_kg_m3 * bore * a;
        let rod_side = cy.inner_length_m - cy.piston_thickness_m - a;
        let oil_annulus = cy.oil_density_kg_m3 * annulus * rod_side;
        let first = cy.tube_mass_kg * cy.length_m / 2.0
            + oil_bore * a / 2.0
            + oil_annulus * (a + cy.piston_thickness_m + cy.inner_length_m) / 2.0;
        v += g * first * e4y;
        // Body 5: rope and load (mass at θ0) hanging from the deflected tip C.
        let yc = a0[1] + c.boom.length_m() * s_th + sag.1 * c_th;
        v += self.hanging_mass(th0, load) * g * yc;
        v
    }

    /// Quasi-static piston force F = (∂V/∂θ)/(ds/dθ) (N, positive pushing the boom up),
    /// by central differences; `elastic` includes the boom's static sag.
    pub fn piston_force(&self, th: f64, load: f64, elastic: bool) -> f64 {
        let sag = if elastic {
            self.sag(th, load)
        } else {
            (0.0, 0.0)
        };
        let h = 1e-5;
        let dv = self.frozen_potential(th + h, th, load, sag)
            - self.frozen_potential(th - h, th, load, sag);
        let ds = self.actuator_length(th + h) - self.actuator_length(th - h);
        dv / ds
    }
}
