//! Rated load at the present boom state (thesis §4.3, SPEC §4.4).
//!
//! The rear-jack reaction is affine in the hook load, F_A(W) = at_zero +
//! per_kg·W, with per_kg < 0 (load takes weight off the rear jack). The crane
//! tips when F_A reaches zero, so the tipping load is one division:
//! W_tip = −at_zero / per_kg (0 if the crane would tip unloaded). When the
//! hook is inside the tipping line (steep boom) per_kg ≥ 0: no load can tip
//! the crane and W_tip is unbounded. The rated load is
//! min(W_tip / safety factor, structural limit, chart(R)): safety factor 1.5
//! (SPEC §2), structural limit 10 000 kg (the COLES Mobile 930 is a 10 t
//! crane, SPEC §1), and the optional manufacturer chart interpolated on the
//! hook radius.

use crane_model::loads::load_model::{BoomState, CapacityTerms, HookLoadModel};
use crane_model::{ModelError, Real};

/// Most points a manufacturer chart may have.
pub const CHART_CAPACITY: usize = 32;

/// Why a [`ChartTable`] could not be built.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChartError {
    /// Fewer than one or more than [`CHART_CAPACITY`] points.
    Size,
    /// A radius or load is negative or not finite.
    InvalidValue,
    /// Radii are not strictly increasing.
    NotIncreasing,
}

/// A manufacturer load chart: rated load (kg) against hook radius (m).
///
/// Between points the load is interpolated linearly. Below the smallest
/// radius the first point's load applies; beyond the largest radius the rated
/// load is zero (lifting outside the chart is not allowed).
#[derive(Debug, Clone, PartialEq)]
pub struct ChartTable<T> {
    points: heapless::Vec<(T, T), CHART_CAPACITY>,
}

impl<T: Real> ChartTable<T> {
    /// Builds a chart from `(radius_m, rated_kg)` points, checking them.
    pub fn from_points(points: &[(T, T)]) -> Result<Self, ChartError> {
        let mut v = heapless::Vec::new();
        let mut last_radius: Option<T> = None;
        for &(r, w) in points {
            if !(r.is_finite() && w.is_finite() && r >= T::lit(0.0) && w >= T::lit(0.0)) {
                return Err(ChartError::InvalidValue);
            }
            if last_radius.is_some_and(|last| r <= last) {
                return Err(ChartError::NotIncreasing);
            }
            last_radius = Some(r);
            v.push((r, w)).map_err(|_| ChartError::Size)?;
        }
        if v.is_empty() {
            return Err(ChartError::Size);
        }
        Ok(Self { points: v })
    }

    /// Rated load (kg) at `radius_m` (see the type doc for the ends).
    pub fn rated_kg(&self, radius_m: T) -> T {
        let mut prev: Option<(T, T)> = None;
        for &(r, w) in self.points.iter() {
            if radius_m <= r {
                return match prev {
                    None => w,
                    Some((r0, w0)) => w0 + (w - w0) * (radius_m - r0) / (r - r0),
                };
            }
            prev = Some((r, w));
        }
        T::lit(0.0)
    }
}

/// Why no rated load could be computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CapacityError {
    /// The model could not be evaluated at this state.
    Model(ModelError),
    /// The jack reaction is not finite.
    NotObservable,
}

/// The rated load and what it came from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rating<T> {
    /// Load (kg) at which the rear-jack reaction reaches zero; `None` when no
    /// load can tip the crane at this state.
    pub tipping_load_kg: Option<T>,
    /// Rated load (kg): tipping / safety factor, capped by the chart.
    pub rated_load_kg: T,
    /// Hook radius (m).
    pub radius_m: T,
}

/// Capacity settings.
#[derive(Debug, Clone, PartialEq)]
pub struct Capacity<T> {
    /// Tipping load / rated load (≥ 1). SPEC: 1.5.
    pub safety_factor: T,
    /// Structural limit of the crane (kg): the rated load never exceeds it.
    pub max_rated_kg: T,
    /// Optional manufacturer chart that caps the rated load.
    pub chart: Option<ChartTable<T>>,
}

impl<T: Real> Capacity<T> {
    /// Safety factor 1.5, structural limit 10 000 kg, no chart.
    pub fn standard() -> Self {
        Self {
            safety_factor: T::lit(1.5),
            max_rated_kg: T::lit(10_000.0),
            chart: None,
        }
    }

    /// `true` when the safety factor is finite and at least 1 and the
    /// structural limit finite and not negative.
    pub fn is_valid(&self) -> bool {
        self.safety_factor.is_finite()
            && self.safety_factor >= T::lit(1.0)
            && self.max_rated_kg.is_finite()
            && self.max_rated_kg >= T::lit(0.0)
    }

    /// The rating at a boom state, asking `model` (the charts and tools;
    /// the control cycle has the terms already and calls
    /// [`rating_from`](Self::rating_from)).
    pub fn rating<M: HookLoadModel<T>>(
        &self,
        model: &M,
        boom: BoomState<T>,
    ) -> Result<Rating<T>, CapacityError> {
        let jack_reaction = model.jack_reaction_n(boom).map_err(CapacityError::Model)?;
        self.rating_from(&CapacityTerms {
            jack_reaction,
            radius_m: model.radius_m(boom.angle_rad),
        })
    }

    /// The rating from the model's terms at the boom state
    /// ([`crane_model::loads::load_model::CycleTerms::capacity`]).
    pub fn rating_from(&self, terms: &CapacityTerms<T>) -> Result<Rating<T>, CapacityError> {
        let jack = terms.jack_reaction;
        if !(jack.per_kg.is_finite() && jack.at_zero.is_finite()) {
            return Err(CapacityError::NotObservable);
        }
        let tip = if jack.at_zero <= T::lit(0.0) {
            Some(T::lit(0.0))
        } else if jack.per_kg < T::lit(0.0) {
            Some(-jack.at_zero / jack.per_kg)
        } else {
            None
        };
        let radius_m = terms.radius_m;
        if !radius_m.is_finite() {
            return Err(CapacityError::NotObservable);
        }
        let mut rated = match tip {
            Some(tip) => (tip / self.safety_factor).min(self.max_rated_kg),
            None => self.max_rated_kg,
        };
        if let Some(chart) = &self.chart {
            rated = rated.min(chart.rated_kg(radius_m));
        }
        Ok(Rating {
            tipping_load_kg: tip,
            rated_load_kg: rated,
            radius_m,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chart_interpolates_and_refuses_outside() {
        let c =
            ChartTable::from_points(&[(3.0_f64, 10000.0), (5.0, 6000.0), (10.0, 2000.0)]).unwrap();
        assert_eq!(c.rated_kg(2.0), 10000.0);
        assert_eq!(c.rated_kg(4.0), 8000.0);
        assert_eq!(c.rated_kg(7.5), 4000.0);
        assert_eq!(c.rated_kg(10.0), 2000.0);
        assert_eq!(c.rated_kg(10.1), 0.0);
        assert_eq!(
            ChartTable::from_points(&[(3.0_f64, 1.0), (3.0, 1.0)]),
            Err(ChartError::NotIncreasing)
        );
        assert_eq!(ChartTable::<f64>::from_points(&[]), Err(ChartError::Size));
    }
}
