//! Issue 4: tipping and the lifting capacity (thesis §4.3.2, eqs. 4.2–4.3).
use crane_model::loads::load_model::BoomState;
use crane_model::structure::modal::{MeshRefinement, THESIS_BASIS};
use crane_model::multibody::ThesisModel;
use crane_model::sim::simulation::SimulationOptions;
use crane_model::CraneData;
use nalgebra::Vector2;

fn model() -> ThesisModel<f64> {
    ThesisModel::<f64>::build(&CraneData::coles_mobile_930(), MeshRefinement::THESIS, &THESIS_BASIS).expect("model")
}

/// F_A·A from the moment balance of all weights about the tipping line, computed
/// from body positions without any multiplier.
fn jack_reaction_from_weights(m: &ThesisModel<f64>, angle: f64, load: f64) -> f64 {
    let crane = CraneData::coles_mobile_930();
    let g = crane.gravity_m_s2;
    let xt = crane.chassis.tipping_line_x_m;
    let free = m.equilibrium_state(angle, load).expect("equilibrium");
    let cfg = m.kinematics(m.actuator_at(angle, 0.0), load, &free).expect("kinematics");
    let mech = &cfg.mech;
    let moment = |mass: f64, x: f64| mass * g * (xt - x);
    // Boom: first moment T·(A·e0 + A·χ·η) about A0.
    let mut first = Vector2::new(m.modes.first_moment_rest[0], m.modes.first_moment_rest[1]);
    for k in 0..4 {
        first += Vector2::new(m.modes.first_moment_modes[0][k], m.modes.first_moment_modes[1][k]) * free.eta[k];
    }
    let boom_x = crane.boom_foot[0] + (cfg.rot * first).x / m.modes.mass_kg;
    let lug = crane.lug_rod;
    let lug_x = crane.boom_foot[0] + 0.5 * lug.length_m * mech.lug.angle.cos();
    let rod = crane.piston_rod;
    let rod_x = mech.rod.position.x + 0.5 * rod.length_m * mech.rod.angle.cos();
    let cyl_x = crane.cylinder_foot[0] + cfg.cylinder.first_moment_kg_m / cfg.cylinder.mass_kg * mech.cylinder.angle.cos();
    let hanging_x = cfg.tip_position.x; // rope and load hang straight below C
    let total = crane.chassis.weight_n * crane.chassis.weight_arm_m
        + moment(m.modes.mass_kg, boom_x)
        + moment(lug.mass_kg(), lug_x)
        + moment(rod.mass_kg(), rod_x)
        + moment(cfg.cylinder.mass_kg, cyl_x)
        + moment(cfg.pendulum.mass_kg, hanging_x);
    total / crane.chassis.jack_base_m
}

#[test]
fn jack_reaction_from_multipliers_equals_global_moment_balance() {
    let m = model();
    for deg in [30.0f64, 45.0, 55.0, 65.0, 78.0] {
        for load in [0.0, 3300.0, 8000.0] {
            let angle = deg.to_radians();
            let from_lambda = m.reactions_at_rest(angle, load).expect("reactions").jack_reaction_n;
            let from_weights = jack_reaction_from_weights(&m, angle, load);
            let rel = (from_lambda - from_weights).abs() / from_weights.abs();
            // Eq. 4.2 from the ground-pin multipliers = moment balance of all weights, at rest.
            assert!(rel < 1e-6, "{deg}° {load} kg: multipliers {from_lambda} N, weights {from_weights} N, rel {rel:e}");
        }
    }
}

#[test]
fn closed_form_tipping_load_zeroes_the_jack_reaction() {
    let m = model();
    let chassis = CraneData::coles_mobile_930().chassis.weight_n;
    for deg in [10.0f64, 30.0, 45.0, 60.0, 70.0] {
        let tp = m.tipping_load_at_rest(deg.to_radians()).expect("tipping");
        let fa = m.reactions_at_rest(deg.to_radians(), tp.tipping_load_kg).expect("reactions").jack_reaction_n;
        // Loaded with W_tip, the crane is exactly on the point of tipping: F_A = 0.
        assert!(fa.abs() < 1e-6 * chassis, "{deg}°: W_tip {} kg leaves F_A = {fa} N", tp.tipping_load_kg);
        // And the affine map the limiter gets has the same root.
        let r = m.load_responses(BoomState { angle_rad: deg.to_radians(), rate_rad_s: 0.0 }).expect("responses");
        let root = -r.jack_reaction.at_zero / r.jack_reaction.per_kg;
        assert!((root / tp.tipping_load_kg - 1.0).abs() < 1e-9, "{deg}°: affine root {root}");
    }
}

#[test]
fn tipping_load_decreases_as_the_radius_grows() {
    let m = model();
    let mut last = f64::INFINITY;
    let mut last_r = f64::NEG_INFINITY;
    // From 80° down to 5°, the chart's range: below ~1° the hook's true radius
    // (with the boom's sag, |v|·sin θ outward) shrinks while eq. 4.3's does not.
    for i in (10..=160).rev() {
        let deg = i as f64 * 0.5;
        let tp = m.tipping_load_at_rest(deg.to_radians()).expect("tipping");
        assert!(tp.radius_m > last_r, "radius grows as the boom comes down");
        // Lifting capacity falls monotonically with the radius (Fig. 4.23).
        assert!(tp.tipping_load_kg < last, "{deg}°: {} kg not below {last} kg", tp.tipping_load_kg);
        last = tp.tipping_load_kg;
        last_r = tp.radius_m;
    }
}

#[test]
fn dynamic_tipping_is_never_on_the_unsafe_side() {
    let m = model();
    let options = SimulationOptions::for_type::<f64>();
    for load in [6225.0f64, 10200.0, 13650.0, 15000.0] {
        let dynamic = m.dynamic_tipping_angle(load, 1.0, &options).expect("run").expect("tips").to_degrees();
        // Quasi-static tipping angle by bisection on the closed-form W_tip(θ).
        let (mut lo, mut hi) = (0.0f64, 80.0f64);
        for _ in 0..50 {
            let mid = 0.5 * (lo + hi);
            if m.tipping_load_at_rest(mid.to_radians()).expect("tipping").tipping_load_kg < load {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let quasi = 0.5 * (lo + hi);
        println!("{load} kg: quasi-static {quasi:.2}°, dynamic {dynamic:.2}°, difference {:.2}°", dynamic - quasi);
        // Lowering, the crane must not get further out than the static chart says by more than 0.5°.
        assert!(dynamic >= quasi - 0.5, "{load} kg: dynamic {dynamic}° below quasi-static {quasi}°");
        // The difference is the swing the 1.5 s start ramp gives the load (no rope damping):
        // a few degrees at most at these radii.
        assert!(dynamic - quasi < 3.0, "{load} kg: difference {}° too large for the swing", dynamic - quasi);
    }
}

/// The inertia term the limiter subtracts (J/(da/dθ1)) against the full
/// multipliers: the piston force at W = 0 with the actuator accelerating the boom
/// at α, minus the force at α = 0, over α. Held at a fixed swing angle, the
/// pendulum would be carried along with the tip, which a hanging rope is not
/// (the limiter's swing observer accounts for it), so the rope's mass is set to
/// next to zero here. Two independent routes: kinetic energy of the mechanism
/// (the closed form) vs the Lagrange multiplier of the full 19-coordinate system.
#[test]
fn inertia_term_matches_the_multipliers() {
    use crane_model::loads::load_model::HookLoadModel;
    use crane_model::data::profile::ActuatorMotion;
    let m = ThesisModel { rope_kg_per_m: 1e-6, ..model() }; // 0 would make the swing singular
    for deg in [40.0f64, 50.0, 60.0, 70.0, 80.0] {
        let th = deg.to_radians();
        let free = m.equilibrium_state(th, 0.0).expect("equilibrium");
        let force = |alpha: f64| {
            let act = ActuatorMotion { accel_m_s2: m.geometry.extension_per_radian(th) * alpha, ..m.actuator_at(th, 0.0) };
            let mut ev = m.evaluate(act, 0.0, &free).expect("evaluate");
            ev.eta_accel = nalgebra::SVector::zeros();
            ev.swing_accel = 0.0;
            let (_, lambda) = m.multipliers(&ev).expect("multipliers");
            m.reactions(&lambda).piston_force_n
        };
        let alpha = 0.1;
        let from_multipliers = (force(alpha) - force(0.0)) / alpha;
        let closed_form = m.piston_force_per_boom_accel(th).expect("inertia");
        let rel = closed_form / from_multipliers - 1.0;
        println!("{deg}°: {from_multipliers:.0} N/(rad/s²) from the multipliers, {closed_form:.0} closed form ({rel:+.2e})");
        assert!(rel.abs() < 1e-4, "{deg}°: {rel}");
    }
}

/// The quadratic piston force is exact: solving it for W gives back the load the
/// multipliers were computed with, at rest with the boom at its static deflection
/// for that load, across the loads and angles of the chart.
#[test]
fn quadratic_piston_force_inverts_to_the_true_load() {
    use crane_model::loads::load_model::HookLoadModel;
    let m = model();
    let mut worst: f64 = 0.0;
    for deg in [20.0f64, 40.0, 60.0, 80.0] {
        let th = deg.to_radians();
        let f = m.piston_force_n(BoomState { angle_rad: th, rate_rad_s: 0.0 }).expect("force");
        for load in [500.0, 3300.0, 8000.0, 15000.0] {
            let measured = m.reactions_at_rest(th, load).expect("reactions").piston_force_n;
            let w = f.solve(measured).expect("solvable");
            worst = worst.max((w / load - 1.0).abs());
        }
    }
    println!("worst relative error of the inverted load: {worst:.1e}");
    assert!(worst < 1e-6, "{worst}");
}
