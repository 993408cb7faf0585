//! Maneuver files (`--maneuver FILE`, `docs/maneuvers.md`): a session of segments
//! (hold, luff, lift-off, hoist) at a fixed slew, in TOML or JSON, read into a
//! [`crane_model::sim::simulation::Program`].
//!
//! Every key is checked: unknown keys are refused, and a value out of range is
//! reported with the segment it belongs to.

use crate::choices::{self, ProfileArg, RopeArg};
use anyhow::{bail, Context, Result};
use crane_model::data::profile::RampShape;
use crane_model::multibody::rope::RopeChoice;
use crane_model::sim::simulation::{Program, Segment};
use serde::Deserialize;
use std::path::Path;

/// The file's top level.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ManeuverFile {
    /// Boom angle at the start (deg).
    pub start_deg: f64,
    /// Hook load hanging at the start (kg); 0 (the default) before a lift-off.
    #[serde(default)]
    pub load_kg: f64,
    /// `thesis` (default) or `held`.
    #[serde(default)]
    pub rope: Option<String>,
    /// Hanging length of a held rope (m); default: the load 1 m up at the start.
    #[serde(default)]
    pub rope_length_m: Option<f64>,
    /// The segments, in order.
    #[serde(rename = "segment", alias = "segments")]
    pub segments: Vec<SegmentSpec>,
}

/// One segment as written in the file.
#[derive(Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SegmentSpec {
    /// The boom at rest.
    Hold {
        /// Duration (s).
        duration_s: f64,
    },
    /// A luffing move.
    Luff {
        /// End angle (deg).
        to_deg: f64,
        /// Duration (s, ≥ 2).
        duration_s: f64,
        /// Acceleration and deceleration ramp (s); default [`default_ramp_s`].
        #[serde(default)]
        ramp_s: Option<f64>,
        /// `linear` or `cycloidal` (default).
        #[serde(default)]
        profile: Option<String>,
    },
    /// The hoist takes the load off the ground.
    LiftOff {
        /// Duration of the take-up (s).
        duration_s: f64,
        /// Hook load once lifted (kg).
        load_kg: f64,
    },
    /// The winch hoists the hanging load (a held rope; negative `by_m`
    /// lets it down), the boom still.
    Hoist {
        /// How far the load goes up (m; negative: down).
        by_m: f64,
        /// Duration (s).
        duration_s: f64,
        /// Acceleration and deceleration ramp (s); default a tenth of the
        /// duration, at most 1 s.
        #[serde(default)]
        ramp_s: Option<f64>,
        /// `linear` (default: a winch's constant acceleration) or `cycloidal`.
        #[serde(default)]
        profile: Option<String>,
    },
}

/// The default ramp of a luff of `duration_s`: the thesis's 1.5 s for 30 s moves
/// and 1 s for 10 s moves; 1.5 s for moves of 20 s or more, 1 s from 10 s to 20 s,
/// a tenth of the duration below 10 s.
pub fn default_ramp_s(duration_s: f64) -> f64 {
    if duration_s >= 20.0 {
        1.5
    } else if duration_s >= 10.0 {
        1.0
    } else {
        duration_s / 10.0
    }
}

/// Parses a ramp shape name (the command line's `--profile` values).
pub fn shape(name: &str) -> Result<RampShape> {
    choices::parse::<ProfileArg>("profile", name).map(RampShape::from)
}

/// The rope from its name (the command line's `--rope` values; default
/// `thesis`) and optional length.
pub fn rope(name: Option<&str>, length_m: Option<f64>) -> Result<RopeChoice> {
    let rope = match name {
        None => RopeArg::Thesis,
        Some(name) => choices::parse::<RopeArg>("rope", name)?,
    };
    rope.choice(length_m)
}

impl ManeuverFile {
    /// Reads a `.toml` or `.json` file (by extension; anything else is tried as TOML).
    pub fn read(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).with_context(|| format!("cannot read maneuver file {}", path.display()))?;
        let json = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("json"));
        if json {
            serde_json::from_str(&text).with_context(|| format!("{}: not a valid maneuver (JSON)", path.display()))
        } else {
            toml::from_str(&text).with_context(|| format!("{}: not a valid maneuver (TOML)", path.display()))
        }
    }

    /// The program, with `rope_override` (from the command line) replacing the file's rope.
    pub fn program(&self, rope_override: Option<RopeChoice>) -> Result<Program> {
        let rope = match rope_override {
            Some(r) => r,
            None => rope(self.rope.as_deref(), self.rope_length_m)?,
        };
        let mut p = Program::new(self.start_deg, self.load_kg, rope).map_err(|e| anyhow::anyhow!("start: {e}"))?;
        for (i, s) in self.segments.iter().enumerate() {
            let seg = match s {
                SegmentSpec::Hold { duration_s } => Segment::Hold { duration_s: *duration_s },
                SegmentSpec::Luff { to_deg, duration_s, ramp_s, profile } => {
                    let ramp = ramp_s.unwrap_or_else(|| default_ramp_s(*duration_s));
                    let shape = shape(profile.as_deref().unwrap_or("cycloidal")).with_context(|| format!("segment {}", i + 1))?;
                    Segment::Luff { to_deg: *to_deg, shape, t1_s: ramp, t2_s: duration_s - ramp, t3_s: *duration_s }
                }
                SegmentSpec::LiftOff { duration_s, load_kg } => Segment::LiftOff { duration_s: *duration_s, load_kg: *load_kg },
                SegmentSpec::Hoist { by_m, duration_s, ramp_s, profile } => {
                    let ramp = ramp_s.unwrap_or_else(|| (duration_s / 10.0).min(1.0));
                    let shape = shape(profile.as_deref().unwrap_or("linear")).with_context(|| format!("segment {}", i + 1))?;
                    Segment::Hoist { by_m: *by_m, duration_s: *duration_s, ramp_s: ramp, shape }
                }
            };
            p.push(seg).map_err(|e| anyhow::anyhow!("segment {} ({s:?}): {e}", i + 1))?;
        }
        if p.segments().is_empty() {
            bail!("a maneuver needs at least one segment");
        }
        Ok(p)
    }
}
