//! The controller's crane model: the limiter's terms tabulated over the boom
//! angle ([`LoadTable`], data in `load_table_data.rs`).
//!
//! Everything the limiter asks the model depends on the boom angle θ1, the
//! hook load W and (for the rating) the boom's rate ω. At rest every term is
//! an exact quadratic in W (the boom's sag grows with W; [`Quadratic`]), and
//! the rate enters the jack reaction only through the velocity terms of the
//! equations of motion, which are quadratic in the velocities: with the free
//! coordinates at rest, F_A(θ1, ω, W) = F_A,rest(θ1, W) + ω²·F_A,ω²(θ1, W).
//! So a table over θ1 alone holds them all: each row stores the coefficients
//! at one angle, computed on the host in f64 by the full multibody model
//! ([`CraneModel::load_responses`] and its reactions) and stored as f32; a
//! query interpolates the rows around the angle with a cubic (Catmull–Rom;
//! linear interpolation missed the 0.2 % bound on the load near 90°, where
//! the piston force's slope in W vanishes and magnifies the error of its
//! value at W = 0).
//!
//! A cycle then costs two row interpolations and one quadratic root instead
//! of six evaluations of the multibody equations, and the controller never
//! runs (or links) the multibody code. The table's error against the full
//! model is held by the test `tests/load_table.rs`: at most 0.2 % on the load
//! and on the rated load anywhere in 0–90° (between the knots included).
//!
//! A term the limiter needs later is one more column: an index in
//! [`column`](mod@column), one line in [`LoadTable::row_at`]'s generator
//! ([`generate_row`]) and a field of [`crate::loads::load_model::CycleTerms`].

use crate::loads::load_model::{
    Affine, BoomState, CapacityTerms, CycleQuery, CycleTerms, HookLoadModel, LoadTerms, Quadratic,
};
use crate::multibody::CraneModel;
use crate::ModelError;

include!("load_table_data.rs");

/// The columns of a row: what each of its numbers is.
pub mod column {
    /// Piston force at rest (N) at W = 0.
    pub const PISTON_AT_ZERO: usize = 0;
    /// Piston force at rest, slope per kg at W = 0 (N/kg).
    pub const PISTON_PER_KG: usize = 1;
    /// Piston force at rest, curvature (N/kg²).
    pub const PISTON_PER_KG2: usize = 2;
    /// Piston force per unit boom angular acceleration (N·s²/rad).
    pub const PER_BOOM_ACCEL: usize = 3;
    /// Rear-jack reaction F_A at rest (N) at W = 0.
    pub const JACK_AT_ZERO: usize = 4;
    /// F_A at rest, slope per kg (N/kg).
    pub const JACK_PER_KG: usize = 5;
    /// F_A at rest, curvature (N/kg²).
    pub const JACK_PER_KG2: usize = 6;
    /// F_A per ω² (N·s²/rad²) at W = 0.
    pub const JACK_RATE2_AT_ZERO: usize = 7;
    /// F_A per ω², slope per kg.
    pub const JACK_RATE2_PER_KG: usize = 8;
    /// F_A per ω², curvature.
    pub const JACK_RATE2_PER_KG2: usize = 9;
    /// Hook radius R (m, eq. 4.3).
    pub const RADIUS: usize = 10;
    /// Number of columns. (tan θ1 is no column: the cycle computes it from
    /// the angle, [`crate::Real::sin_cos_own`], which the pendulums link
    /// anyway; as two columns it took 1 472 B of the controller's flash.)
    pub const COUNT: usize = 11;
}

/// One row: the columns of [`column`](mod@column) at one boom angle.
pub type Row = [f32; column::COUNT];

/// First knot of the table (degrees): the model reaches down to −1.63°
/// (below, the rope's hanging length ends), and a boom resting on its
/// support reads a little below 0°.
pub const FIRST_DEG: f64 = -1.5;
/// Knot spacing (degrees).
pub const STEP_DEG: f64 = 0.5;
/// Number of knots: −1.5°, −1°, …, 90° (the cylinder's full stroke).
pub const KNOTS: usize = 184;

/// Hook load (kg) of the second and third evaluation of each quadratic fit.
const FIT_LOAD_KG: f64 = 5000.0;
/// Boom rate (rad/s) at which the ω² column is measured (about the fastest
/// luffing of the thesis's manoeuvres).
const FIT_RATE_RAD_S: f64 = 0.1;

/// The quadratic in W through (0, f0), (w1, f1), (2·w1, f2).
fn fit(w1: f64, f0: f64, f1: f64, f2: f64) -> Quadratic<f64> {
    let c = (f2 - 2.0 * f1 + f0) / (2.0 * w1 * w1);
    Quadratic { at_zero: f0, per_kg: (f1 - f0) / w1 - c * w1, per_kg2: c }
}

/// One row of the table from the full model, in f64 (the generator; host only
/// in practice: it runs the multibody equations nine times).
pub fn generate_row<const M: usize>(model: &CraneModel<f64, M>, angle_rad: f64) -> Result<[f64; column::COUNT], ModelError> {
    let at_rest = BoomState { angle_rad, rate_rad_s: 0.0 };
    let piston = model.load_responses(at_rest)?.piston_force;
    let jack = |rate_rad_s: f64| -> Result<Quadratic<f64>, ModelError> {
        let boom = BoomState { angle_rad, rate_rad_s };
        let at = |w: f64| -> Result<f64, ModelError> {
            let free = model.equilibrium_state(angle_rad, w)?;
            Ok(model.quasi_static_reactions(boom, w, &free)?.jack_reaction_n)
        };
        Ok(fit(FIT_LOAD_KG, at(0.0)?, at(FIT_LOAD_KG)?, at(2.0 * FIT_LOAD_KG)?))
    };
    let rest = jack(0.0)?;
    let per_rate2 = jack(FIT_RATE_RAD_S)?.plus(&rest.scaled(-1.0)).scaled(1.0 / (FIT_RATE_RAD_S * FIT_RATE_RAD_S));
    let mut row = [0.0; column::COUNT];
    let mut set = |i: usize, v: f64| {
        if let Some(x) = row.get_mut(i) {
            *x = v;
        }
    };
    use column::*;
    set(PISTON_AT_ZERO, piston.at_zero);
    set(PISTON_PER_KG, piston.per_kg);
    set(PISTON_PER_KG2, piston.per_kg2);
    set(PER_BOOM_ACCEL, model.piston_force_per_boom_accel(angle_rad)?);
    set(JACK_AT_ZERO, rest.at_zero);
    set(JACK_PER_KG, rest.per_kg);
    set(JACK_PER_KG2, rest.per_kg2);
    set(JACK_RATE2_AT_ZERO, per_rate2.at_zero);
    set(JACK_RATE2_PER_KG, per_rate2.per_kg);
    set(JACK_RATE2_PER_KG2, per_rate2.per_kg2);
    set(RADIUS, model.radius_m(angle_rad));
    Ok(row)
}

/// The full model the table is generated from and tested against: the COLES
/// Mobile 930 with its modes computed afresh, all in f64.
pub fn thesis_full_model() -> Result<CraneModel<f64, 4>, ModelError> {
    let modes = crate::loads::thesis_modes::compute_thesis_modes_f64()?;
    Ok(CraneModel::new(&crate::CraneData::coles_mobile_930(), modes))
}

/// The whole table from the full model, rounded to f32.
pub fn generate<const M: usize>(model: &CraneModel<f64, M>) -> Result<[Row; KNOTS], ModelError> {
    let mut rows = [[0.0f32; column::COUNT]; KNOTS];
    for (k, row) in rows.iter_mut().enumerate() {
        let deg = FIRST_DEG + STEP_DEG * k as f64;
        let r = generate_row(model, deg.to_radians())?;
        for (x, v) in row.iter_mut().zip(r) {
            *x = v as f32;
        }
    }
    Ok(rows)
}

/// Writes a table as the Rust constant `name` (the generator example's output).
pub fn write_const<W: core::fmt::Write>(rows: &[Row; KNOTS], name: &str, out: &mut W) -> core::fmt::Result {
    writeln!(out, "/// The limiter's terms at {KNOTS} boom angles, {FIRST_DEG}° + k·{STEP_DEG}°; columns in [`column`](mod@column).")?;
    writeln!(out, "pub const {name}: [Row; KNOTS] = [")?;
    for row in rows {
        write!(out, "    [")?;
        for x in row {
            // `{:?}` prints the shortest decimal that reads back to the same f32.
            write!(out, "{x:?}, ")?;
        }
        writeln!(out, "],")?;
    }
    writeln!(out, "];")
}

/// The limiter's crane model on the controller: rows of [`column`](mod@column)s at knots
/// `STEP_DEG` apart, interpolated by a cubic, and tan θ1 from the angle
/// ([`crate::Real::sin_cos_own`]; f32, no libm, no multibody code). Angles
/// outside the knots are out of reach (a FAULT).
#[derive(Debug, Clone, Copy)]
pub struct LoadTable {
    rows: &'static [Row; KNOTS],
    first_rad: f32,
    knots_per_rad: f32,
}

/// The COLES Mobile 930's table ([`THESIS_LOAD_TABLE`]).
pub fn thesis_load_table() -> LoadTable {
    LoadTable::new(&THESIS_LOAD_TABLE)
}

impl LoadTable {
    /// A table over the knots `FIRST_DEG + k·STEP_DEG`.
    pub const fn new(rows: &'static [Row; KNOTS]) -> Self {
        LoadTable {
            rows,
            first_rad: (FIRST_DEG * core::f64::consts::PI / 180.0) as f32,
            knots_per_rad: (180.0 / (core::f64::consts::PI * STEP_DEG)) as f32,
        }
    }

    /// The rows.
    pub fn rows(&self) -> &'static [Row; KNOTS] {
        self.rows
    }

    /// The row at boom angle `angle_rad`: the cubic Hermite interpolant
    /// through the two knots around it, with the slopes of the neighbouring
    /// knots' central differences (Catmull–Rom; at the first and last
    /// interval the missing neighbour continues the quadratic through the
    /// three end knots).
    /// `OutOfReach` outside the knots or for NaN.
    pub fn row_at(&self, angle_rad: f32) -> Result<Row, ModelError> {
        let u = (angle_rad - self.first_rad) * self.knots_per_rad;
        let last = (KNOTS - 1) as f32;
        if !(u >= 0.0 && u <= last) {
            return Err(ModelError::OutOfReach);
        }
        // 0 ≤ u ≤ KNOTS − 1: the cast is exact truncation; the last knot
        // belongs to the last interval.
        let i = (u as usize).min(KNOTS - 2);
        let t = u - i as f32;
        // Catmull–Rom as weights on the four knots around: the same four
        // numbers for every column. At the ends of the table the knot beyond
        // is the quadratic through the three end knots continued
        // (y₋₁ = 3·(y₀ − y₁) + y₂), folded into the weights.
        let (t2, t3) = (t * t, t * t * t);
        let w = [
            -0.5 * t + t2 - 0.5 * t3,
            1.0 - 2.5 * t2 + 1.5 * t3,
            0.5 * t + 2.0 * t2 - 1.5 * t3,
            -0.5 * t2 + 0.5 * t3,
        ];
        let (knots, w) = if i == 0 {
            ([i, i + 1, i + 2, i + 2], [w[1] + 3.0 * w[0], w[2] - 3.0 * w[0], w[3] + w[0], 0.0])
        } else if i + 2 >= KNOTS {
            ([i - 1, i, i + 1, i + 1], [w[0] + w[3], w[1] - 3.0 * w[3], w[2] + 3.0 * w[3], 0.0])
        } else {
            ([i - 1, i, i + 1, i + 2], w)
        };
        let mut row = [0.0f32; column::COUNT];
        for (k, wk) in knots.iter().zip(w) {
            let Some(r) = self.rows.get(*k) else {
                return Err(ModelError::OutOfReach);
            };
            for (out, y) in row.iter_mut().zip(r) {
                *out += wk * y;
            }
        }
        Ok(row)
    }
}

/// Column `i` of a row (NaN, never a panic, for an index past the end).
fn get(row: &Row, i: usize) -> f32 {
    row.get(i).copied().unwrap_or(f32::NAN)
}

fn quadratic(row: &Row, at_zero: usize, per_kg: usize, per_kg2: usize) -> Quadratic<f32> {
    Quadratic { at_zero: get(row, at_zero), per_kg: get(row, per_kg), per_kg2: get(row, per_kg2) }
}

/// F_A (N) at a boom state from a row: the rest quadratic plus ω² times the
/// rate's.
fn jack_quadratic(row: &Row, rate_rad_s: f32) -> Quadratic<f32> {
    use column::*;
    let rest = quadratic(row, JACK_AT_ZERO, JACK_PER_KG, JACK_PER_KG2);
    let per_rate2 = quadratic(row, JACK_RATE2_AT_ZERO, JACK_RATE2_PER_KG, JACK_RATE2_PER_KG2);
    rest.plus(&per_rate2.scaled(rate_rad_s * rate_rad_s))
}

impl LoadTable {
    fn load_terms(&self, angle_rad: f32) -> Result<LoadTerms<f32>, ModelError> {
        use column::*;
        let row = self.row_at(angle_rad)?;
        Ok(LoadTerms {
            piston_force: quadratic(&row, PISTON_AT_ZERO, PISTON_PER_KG, PISTON_PER_KG2),
            piston_force_per_boom_accel: get(&row, PER_BOOM_ACCEL),
            tan_angle: {
                let (sin, cos) = crate::Real::sin_cos_own(angle_rad);
                sin / cos
            },
        })
    }

    fn capacity_terms(&self, boom: BoomState<f32>) -> Result<CapacityTerms<f32>, ModelError> {
        let row = self.row_at(boom.angle_rad)?;
        Ok(CapacityTerms {
            jack_reaction: jack_quadratic(&row, boom.rate_rad_s).tipping_secant(),
            radius_m: get(&row, column::RADIUS),
        })
    }
}

impl HookLoadModel<f32> for LoadTable {
    /// Two row interpolations and one quadratic root.
    fn cycle_terms(&self, query: CycleQuery<f32>) -> CycleTerms<f32> {
        CycleTerms { load: self.load_terms(query.force_angle_rad), capacity: self.capacity_terms(query.now) }
    }

    /// The piston force at rest (the table holds no rate term for it: the
    /// limiter asks for it at rest only, see `moment_limiter::load_estimate`).
    fn piston_force_n(&self, boom: BoomState<f32>) -> Result<Quadratic<f32>, ModelError> {
        Ok(self.load_terms(boom.angle_rad)?.piston_force)
    }

    fn piston_force_per_boom_accel(&self, boom_angle_rad: f32) -> Result<f32, ModelError> {
        Ok(self.load_terms(boom_angle_rad)?.piston_force_per_boom_accel)
    }

    fn jack_reaction_n(&self, boom: BoomState<f32>) -> Result<Affine<f32>, ModelError> {
        Ok(self.capacity_terms(boom)?.jack_reaction)
    }

    /// NaN outside the table (the rating refuses a non-finite radius).
    fn radius_m(&self, boom_angle_rad: f32) -> f32 {
        self.row_at(boom_angle_rad).map_or(f32::NAN, |row| get(&row, column::RADIUS))
    }
}

