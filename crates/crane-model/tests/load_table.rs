//! The controller's load table against the full multibody model it is
//! generated from (issue 13): at most 0.2 % on the load and on the rated load
//! anywhere in 0–90°, between the knots included (the load below 90°, where
//! it is observable at all).

use crane_model::loads::load_model::{Affine, BoomState, HookLoadModel};
use crane_model::loads::load_table::{self, column, thesis_load_table, THESIS_LOAD_TABLE};
use crane_model::multibody::CraneModel;

/// The bound of issue 13 on the load and the rated load.
const BOUND: f64 = 0.002;

fn full() -> CraneModel<f64, 4> {
    load_table::thesis_full_model().expect("full model")
}

/// Angles every 0.05° over the table, −1.5…90° (ten between two knots, on
/// the knots too).
fn angles_deg() -> impl Iterator<Item = f64> {
    (-30..=1800).map(|i| i as f64 * 0.05)
}

/// The rated load as `Capacity::standard()` computes it from F_A (safety
/// factor 1.5, structural limit 10 t, no chart).
fn rated_kg(jack: Affine<f64>) -> f64 {
    let tip = if jack.at_zero <= 0.0 {
        Some(0.0)
    } else if jack.per_kg < 0.0 {
        Some(-jack.at_zero / jack.per_kg)
    } else {
        None
    };
    tip.map_or(10_000.0, |t| (t / 1.5).min(10_000.0))
}

#[test]
fn load_table_is_not_stale() {
    let fresh = load_table::generate(&full()).expect("generate");
    assert!(fresh == THESIS_LOAD_TABLE, "stale: rerun the export_load_table example");
}

#[test]
fn load_read_through_the_table_is_within_0_2_percent_of_the_full_model() {
    let (model, table) = (full(), thesis_load_table());
    let mut worst = (0.0f64, 0.0, 0.0);
    // At 90° the load's arm, and with it the piston force's slope in W, is
    // zero: no model can read the load there (the limiter FAULTs).
    for deg in angles_deg().filter(|d| *d < 90.0) {
        let rad = deg.to_radians();
        let exact = model.load_responses(BoomState { angle_rad: rad, rate_rad_s: 0.0 }).expect("model").piston_force;
        let tab = table.piston_force_n(BoomState { angle_rad: rad as f32, rate_rad_s: 0.0 }).expect("table");
        for w in [300.0, 1000.0, 2000.0, 3300.0, 5000.0, 8000.0, 10_000.0] {
            let force = exact.at(w);
            let read = tab.solve(force as f32).expect("observable") as f64;
            let err = (read - w).abs() / w;
            if err > worst.0 {
                worst = (err, deg, w);
            }
        }
    }
    println!("load: worst relative error {:.4} % at {:.2}°, {} kg", worst.0 * 100.0, worst.1, worst.2);
    assert!(worst.0 <= BOUND, "load error {:.4} % at {:.2}° with {} kg", worst.0 * 100.0, worst.1, worst.2);
}

#[test]
fn boom_inertia_through_the_table_is_within_0_2_percent_of_the_full_model() {
    let (model, table) = (full(), thesis_load_table());
    let mut worst = (0.0f64, 0.0);
    for deg in angles_deg() {
        let exact = model.piston_force_per_boom_accel(deg.to_radians()).expect("model");
        let tab = table.piston_force_per_boom_accel(deg.to_radians() as f32).expect("table") as f64;
        let err = (tab - exact).abs() / exact.abs();
        if err > worst.0 {
            worst = (err, deg);
        }
    }
    println!("inertia: worst relative error {:.4} % at {:.2}°", worst.0 * 100.0, worst.1);
    assert!(worst.0 <= BOUND, "inertia error {:.4} % at {:.2}°", worst.0 * 100.0, worst.1);
}

#[test]
fn rated_load_through_the_table_is_within_0_2_percent_of_the_full_model_at_rest_and_moving() {
    let (model, table) = (full(), thesis_load_table());
    let mut worst = (0.0f64, 0.0, 0.0);
    for deg in angles_deg() {
        for rate in [-0.1, -0.05, 0.0, 0.05, 0.1] {
            let boom = BoomState { angle_rad: deg.to_radians(), rate_rad_s: rate };
            let exact = rated_kg(model.jack_reaction_n(boom).expect("model"));
            let boom32 = BoomState { angle_rad: boom.angle_rad as f32, rate_rad_s: rate as f32 };
            let jack = table.jack_reaction_n(boom32).expect("table");
            let tab = rated_kg(Affine { at_zero: jack.at_zero as f64, per_kg: jack.per_kg as f64 });
            // Relative to the rating, with 1 kg of slack where it is near zero.
            let err = (tab - exact).abs() / exact.max(1.0 / BOUND);
            if err > worst.0 {
                worst = (err, deg, rate);
            }
        }
    }
    println!("rated load: worst relative error {:.4} % at {:.2}°, {} rad/s", worst.0 * 100.0, worst.1, worst.2);
    assert!(worst.0 <= BOUND, "rated-load error {:.4} % at {:.2}°, {} rad/s", worst.0 * 100.0, worst.1, worst.2);
}

#[test]
fn radius_and_tangent_through_the_table_match_eq_4_3() {
    let (model, table) = (full(), thesis_load_table());
    for deg in angles_deg().filter(|d| *d < 89.0) {
        let rad = deg.to_radians();
        let r = table.radius_m(rad as f32) as f64;
        assert!((r - model.radius_m(rad)).abs() < 1e-3, "{deg}°: {r}");
        let terms = table.cycle_terms(crane_model::loads::load_model::CycleQuery {
            force_angle_rad: rad as f32,
            now: BoomState { angle_rad: rad as f32, rate_rad_s: 0.0 },
        });
        let tan = terms.load.expect("load terms").tan_angle as f64;
        assert!((tan - rad.tan()).abs() <= 1e-4 * (1.0 + rad.tan()), "{deg}°: {tan}");
    }
}

#[test]
fn outside_the_knots_the_table_refuses() {
    let table = thesis_load_table();
    for deg in [-1.51f32, -5.0, 90.01, 95.0, f32::NAN, f32::INFINITY] {
        assert!(table.row_at(deg.to_radians()).is_err(), "{deg}");
    }
    for deg in [-1.5f32, 0.0, 90.0] {
        assert!(table.row_at(deg.to_radians()).is_ok(), "{deg}");
    }
    assert_eq!(core::mem::size_of_val(table.rows()), 184 * column::COUNT * 4);
}
