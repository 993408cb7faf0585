//! The rope, two ways (SPEC §3): how body 5's hanging length behaves while the boom
//! moves.
//!
//! * [`RopeMode::Thesis`] — the thesis's assumption vi: the winch pays rope out or
//!   in so the load stays a fixed clearance above the ground. The hanging length is
//!   L(t) = y_C,rigid(θ1) − clearance with its rates L̇, L̈, so the load never moves
//!   vertically with the boom's rigid rotation. The default of the twelve thesis cases.
//! * [`RopeMode::Held`] — the winch is braked: L is constant (L̇ = L̈ = 0), so the
//!   load rides up and down with the tip C, its inertia loads the boom in every
//!   ramp, it bounces with the boom's bending and swings with the period of L.
//!
//! Both come from the same multibody equations (body 5 is a pendulum pinned at C,
//! [`crate::multibody::bodies::Pendulum`]); the piston force and F_A are multipliers in both.

use crate::Real;

/// How the hanging length of the rope behaves, in the model's float type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RopeMode<T> {
    /// Paid out to keep the load at the crane's clearance above the ground (thesis
    /// assumption vi).
    Thesis,
    /// Constant hanging length (m), the winch braked.
    Held {
        /// Hanging length from C to the load (m).
        length_m: T,
    },
}

/// The rope of a maneuver as a user states it (f64, resolved per run by
/// [`crate::multibody::CraneModel::rope_for`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RopeChoice {
    /// [`RopeMode::Thesis`].
    Thesis,
    /// [`RopeMode::Held`] with this length (m), or, if `None`, the length that puts
    /// the load at the crane's clearance (1 m) above the ground at the start angle.
    Held {
        /// Hanging length (m); `None`: clearance at the start.
        length_m: Option<f64>,
    },
}

impl<T: Real> RopeMode<T> {
    /// True for [`RopeMode::Held`].
    pub fn is_held(&self) -> bool {
        matches!(self, RopeMode::Held { .. })
    }
}
