//! Mass properties of the rigid bodies 2–5 (thesis §3.2, §3.3 eqs. 3.12–3.16 and
//! assumptions i–vii), converted once to the model's float type.

use crate::data::crane::CraneData;
use crate::{ModelError, Real};

/// Mass, first moment and inertia of a rigid body about its reference point,
/// with its centre of mass on the body's x axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidMass<T> {
    /// Mass m (kg).
    pub mass_kg: T,
    /// First moment m·l about the reference point along the body axis (kg·m).
    pub first_moment_kg_m: T,
    /// Moment of inertia about the reference point (kg·m², eq. 3.14).
    pub inertia_kg_m2: T,
}

impl<T: Real> RigidMass<T> {
    /// A solid round rod of length `l`, radius `r`, referenced at one end.
    pub fn rod(mass_kg: f64, length_m: f64, radius_m: f64) -> Self {
        RigidMass {
            mass_kg: T::lit(mass_kg),
            first_moment_kg_m: T::lit(mass_kg * length_m / 2.0),
            inertia_kg_m2: T::lit(
                mass_kg * (length_m * length_m / 3.0 + radius_m * radius_m / 4.0),
            ),
        }
    }

    /// The sum of two bodies sharing a reference point and axis.
    pub fn plus(self, other: Self) -> Self {
        RigidMass {
            mass_kg: self.mass_kg + other.mass_kg,
            first_moment_kg_m: self.first_moment_kg_m + other.first_moment_kg_m,
            inertia_kg_m2: self.inertia_kg_m2 + other.inertia_kg_m2,
        }
    }

    /// A uniform line mass along the axis from `x0` to `x1` with transverse radius term `r2` = Σr²/4.
    fn segment(mass: T, x0: T, x1: T, radial_term: T) -> Self {
        let three = T::lit(3.0);
        RigidMass {
            mass_kg: mass,
            first_moment_kg_m: mass * (x0 + x1) * T::lit(0.5),
            inertia_kg_m2: mass * ((x0 * x0 + x0 * x1 + x1 * x1) / three + radial_term),
        }
    }
}

/// Body 4: the cylinder tube with the oil in it, whose mass depends on the stroke
/// (assumptions i–iii). Oil fills the bore from B0 to the piston and the annulus
/// between rod and bore from the piston to the head (the listing's volume).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderMass<T> {
    tube: RigidMass<T>,
    bore_area_m2: T,
    annulus_area_m2: T,
    bore_radius_m: T,
    rod_radius_m: T,
    inner_length_m: T,
    piston_thickness_m: T,
    oil_density_kg_m3: T,
}

impl<T: Real> CylinderMass<T> {
    /// From the crane data.
    pub fn new(crane: &CraneData) -> Self {
        let c = &crane.cylinder;
        let (ro, ri) = (c.outer_radius_m, c.bore_radius_m);
        let tube = RigidMass {
            mass_kg: T::lit(c.tube_mass_kg),
            first_moment_kg_m: T::lit(c.tube_mass_kg * c.length_m / 2.0),
            inertia_kg_m2: T::lit(
                c.tube_mass_kg * (c.length_m * c.length_m / 3.0 + (ro * ro + ri * ri) / 4.0),
            ),
        };
        CylinderMass {
            tube,
            bore_area_m2: T::lit(crane.piston_area_m2()),
            annulus_area_m2: T::lit(crane.piston_area_m2() - crane.rod_area_m2()),
            bore_radius_m: T::lit(ri),
            rod_radius_m: T::lit(crane.piston_rod.radius_m),
            inner_length_m: T::lit(c.inner_length_m),
            piston_thickness_m: T::lit(c.piston_thickness_m),
            oil_density_kg_m3: T::lit(c.oil_density_kg_m3),
        }
    }

    /// Tube plus oil with the piston at extension `a` (m from B0).
    pub fn at_extension(&self, a: T) -> Result<RigidMass<T>, ModelError> {
        let rod_side = self.inner_length_m - self.piston_thickness_m - a;
        if !(a >= T::zero() && rod_side >= T::zero()) {
            return Err(ModelError::OutOfReach);
        }
        let quarter = T::lit(0.25);
        let ri2 = self.bore_radius_m * self.bore_radius_m;
        let piston_side = RigidMass::segment(
            self.oil_density_kg_m3 * self.bore_area_m2 * a,
            T::zero(),
            a,
            quarter * ri2,
        );
        let start = a + self.piston_thickness_m;
        let rr2 = self.rod_radius_m * self.rod_radius_m;
        let annulus = RigidMass::segment(
            self.oil_density_kg_m3 * self.annulus_area_m2 * rod_side,
            start,
            start + rod_side,
            quarter * (ri2 + rr2),
        );
        Ok(self.tube.plus(piston_side).plus(annulus))
    }
}

/// Body 5 at one instant: rope and hook load hanging from C, of length L(t) set so
/// the load stays a fixed clearance above the ground (assumptions iv, vi, vii).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pendulum<T> {
    /// Hanging length L (m).
    pub length_m: T,
    /// dL/dt (m/s).
    pub length_rate_m_s: T,
    /// d²L/dt² (m/s²).
    pub length_accel_m_s2: T,
    /// Rope plus load (kg).
    pub mass_kg: T,
    /// First moment about C, Σ = (m_rope/2 + W)·L (kg·m).
    pub first_moment_kg_m: T,
    /// Inertia about C, (m_rope/3 + W)·L² (kg·m²).
    pub inertia_kg_m2: T,
    /// m_rope/2 + W (kg): dΣ/dL.
    pub first_moment_per_m: T,
    /// m_rope/3 + W (kg): I = this · L².
    pub inertia_per_m2: T,
}

impl<T: Real> Pendulum<T> {
    /// Rope of `rope_kg_per_m` and hook load `load_kg` hanging `l` metres.
    pub fn new(
        rope_kg_per_m: T,
        load_kg: T,
        l: T,
        l_rate: T,
        l_accel: T,
    ) -> Result<Self, ModelError> {
        if !(l > T::zero()) {
            return Err(ModelError::OutOfReach);
        }
        let rope = rope_kg_per_m * l;
        let c1 = rope * T::lit(0.5) + load_kg;
        let c2 = rope / T::lit(3.0) + load_kg;
        Ok(Pendulum {
            length_m: l,
            length_rate_m_s: l_rate,
            length_accel_m_s2: l_accel,
            mass_kg: rope + load_kg,
            first_moment_kg_m: c1 * l,
            inertia_kg_m2: c2 * l * l,
            first_moment_per_m: c1,
            inertia_per_m2: c2,
        })
    }
}
