//! The one spelling of each named choice of a maneuver (ramp profile,
//! direction, initial state, rope): the command line's values and the
//! maneuver file's (docs/cli.md, docs/maneuvers.md) are read through these
//! enums, so a name cannot be accepted in one place and refused in the other.

use anyhow::{bail, Result};
use clap::ValueEnum;
use crane_model::data::profile::{Direction, RampShape};
use crane_model::multibody::rope::RopeChoice;
use crane_model::sim::simulation::InitialState;

/// Ramp shape on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum ProfileArg {
    /// Linear acceleration and deceleration (eq. 3.48).
    Linear,
    /// Cycloidal acceleration and deceleration (eq. 3.47).
    Cycloidal,
}

/// Direction on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum DirectionArg {
    /// 40° → 80°.
    Up,
    /// 80° → 40°.
    Down,
}

/// Initial state on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum InitialArg {
    /// Static deflection projected in the energy norm (the reduced model's equilibrium).
    Equilibrium,
    /// The listing's Euclidean least-squares projection.
    Listing,
}

/// Rope mode on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum RopeArg {
    /// Paid out to keep the load 1 m above the ground (thesis assumption vi).
    Thesis,
    /// Constant hanging length, the winch braked (SPEC §3).
    Held,
}

/// Reads `name` as one of `E`'s values, exactly as the command line spells
/// them; the error names `what` and every accepted value.
pub fn parse<E: ValueEnum>(what: &str, name: &str) -> Result<E> {
    if let Ok(value) = E::from_str(name, false) {
        return Ok(value);
    }
    let names: Vec<String> = E::value_variants()
        .iter()
        .filter_map(|v| v.to_possible_value().map(|p| format!("`{}`", p.get_name())))
        .collect();
    let accepted = match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        Some((last, _)) => last.clone(),
        None => String::new(),
    };
    bail!("{what} must be {accepted}, got `{name}`")
}

impl From<ProfileArg> for RampShape {
    fn from(p: ProfileArg) -> Self {
        match p {
            ProfileArg::Linear => RampShape::Linear,
            ProfileArg::Cycloidal => RampShape::Cycloidal,
        }
    }
}

impl From<DirectionArg> for Direction {
    fn from(d: DirectionArg) -> Self {
        match d {
            DirectionArg::Up => Direction::Up,
            DirectionArg::Down => Direction::Down,
        }
    }
}

impl From<InitialArg> for InitialState {
    fn from(i: InitialArg) -> Self {
        match i {
            InitialArg::Equilibrium => InitialState::Equilibrium,
            InitialArg::Listing => InitialState::ListingProjection,
        }
    }
}

impl RopeArg {
    /// The rope this name asks for, with an optional held length (m): a
    /// length applies to the held rope only and must be a number > 0.
    pub fn choice(self, length_m: Option<f64>) -> Result<RopeChoice> {
        match (self, length_m) {
            (RopeArg::Thesis, None) => Ok(RopeChoice::Thesis),
            (RopeArg::Thesis, Some(_)) => bail!("a rope length applies to the held rope only (rope = \"held\")"),
            (RopeArg::Held, l) => {
                if let Some(l) = l {
                    if !(l > 0.0 && l.is_finite()) {
                        bail!("rope length must be a number > 0 m, got {l}");
                    }
                }
                Ok(RopeChoice::Held { length_m: l })
            }
        }
    }
}
