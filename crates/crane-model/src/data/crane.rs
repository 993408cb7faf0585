//! The crane as data: every number of the COLES Mobile 930 in one place, with its
//! source in the thesis (S. Kılıçaslan, METU 1997: §3.2, the Appendix B listing)
//! or in SPEC §2 where the thesis is wrong or silent.
//!
//! SI units throughout. The plane of the crane has x horizontal toward the boom tip
//! and y up; the boom angle θ1 is measured from the horizontal.

use crate::data::section::OctagonDims;

/// A point in the plane of the crane (m).
pub type Point = [f64; 2];

/// Body 1, the boom: the only flexible body (thesis §3.2 "Body 1").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoomData {
    /// A0G: from the foot pin A0 to G, where the section is largest (2.0 m).
    pub foot_to_g_m: f64,
    /// GC: from G to the tip C (17.5 m).
    pub g_to_tip_m: f64,
    /// A0A: from the foot pin to A, where the cylinder lug is fixed (listing `AOA`).
    pub foot_to_lug_m: f64,
    /// Wall thickness t of the hollow octagon (20 mm).
    pub wall_m: f64,
    /// Outer edges of the section at A0 (listing: `BO1=0.45333` is e0 at A0, SPEC §2).
    pub section_at_foot: OctagonDims,
    /// Outer edges of the section at G.
    pub section_at_g: OctagonDims,
    /// Outer edges of the section at the tip C.
    pub section_at_tip: OctagonDims,
    /// Density (kg/m³) as the listing sets it (`RO=5750`).
    pub density_kg_m3: f64,
    /// Young's modulus (Pa): 2.0e11, steel (SPEC §2 explains the listing's 2.0e10).
    pub youngs_modulus_pa: f64,
    /// Rayleigh damping ratio ζ at the two lowest retained modes (2 %, thesis §4.3).
    pub damping_ratio: f64,
}

impl BoomData {
    /// Boom length A0C (m).
    pub fn length_m(&self) -> f64 {
        self.foot_to_g_m + self.g_to_tip_m
    }
}

/// A solid or hollow round rigid body along its axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RodData {
    /// Length along the body axis (m).
    pub length_m: f64,
    /// Outer radius (m).
    pub radius_m: f64,
    /// Density (kg/m³).
    pub density_kg_m3: f64,
}

impl RodData {
    /// Mass of a solid round rod (kg).
    pub fn mass_kg(&self) -> f64 {
        self.density_kg_m3 * core::f64::consts::PI * self.radius_m * self.radius_m * self.length_m
    }
}

/// Body 4, the luffing cylinder, and its hydraulics (thesis §3.2, §4.2, listing).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderData {
    /// Tube length (m), from the pin B0 (listing `AL4`).
    pub length_m: f64,
    /// Inner (bore) radius (m): Ø230 mm. The listing overwrites it with the outer 0.123 (SPEC §2).
    pub bore_radius_m: f64,
    /// Outer radius of the tube (m): Ø246 mm.
    pub outer_radius_m: f64,
    /// Tube mass without oil (kg, listing `AAM3`).
    pub tube_mass_kg: f64,
    /// Usable inner length L (m, listing `AAL4`).
    pub inner_length_m: f64,
    /// Piston ("spool") thickness L2 (m, listing `AAL2`).
    pub piston_thickness_m: f64,
    /// Hydraulic oil density (kg/m³, listing `ROF`).
    pub oil_density_kg_m3: f64,
    /// Span of the two pressure transducers (Pa): 20 MPa (thesis §4.2).
    pub transducer_span_pa: f64,
}

/// Body 5, the rope and the hook load (thesis §3.3 assumptions iv, vi, vii).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RopeData {
    /// Rope mass per metre of hanging length (kg/m): two falls of a Ø20 mm rope at
    /// 5124.789168 kg/m³ (listing `ROR=2*5124.789168`, `R5=0.01`).
    pub mass_per_m_kg: f64,
    /// Height of the load above the ground, held constant by paying out rope (`CODIS`).
    pub load_clearance_m: f64,
}

/// The chassis standing on its jacks (listing line `FJK=`, thesis eq. 4.2, SPEC §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChassisData {
    /// x of the tipping line: the front jacks (m).
    pub tipping_line_x_m: f64,
    /// Weight of the chassis (N).
    pub weight_n: f64,
    /// Horizontal distance of the chassis weight behind the tipping line (m).
    pub weight_arm_m: f64,
    /// Distance from the tipping line back to the rear jacks, A in eq. 4.2 (m).
    ///
    /// Not given by the thesis (its listing stops at F_A·A). We assume the chassis
    /// weight acts midway between the jacks, A = 2 × 4.125 m. Only the size of the
    /// reported F_A depends on it; its sign, the tipping angle and the tipping load
    /// do not.
    pub jack_base_m: f64,
    /// Horizontal offset of the slewing axis behind the boom foot used by the radius
    /// (eq. 4.3: R = 19.5·cos θ1 − 1.83 m).
    pub radius_offset_m: f64,
}

/// How the boom is meshed into beam elements (thesis §4.3, SPEC §3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MeshSpec {
    /// Elements between A0 and G (2 in the thesis), of equal length.
    pub elements_foot_to_g: usize,
    /// Elements between G and C (10 in the thesis). All but the last are
    /// (A0A − A0G)/2 long so that A falls on a node; the last takes the rest.
    pub elements_g_to_tip: usize,
}

/// The whole crane description: constant data only (the MuJoCo "model" side).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CraneData {
    /// Boom foot pin A0 (m): listing `Y(1)=2.775, Y(2)=2.57`.
    pub boom_foot: Point,
    /// Cylinder foot pin B0 (m): listing `Y(NNM+10)=5.125, Y(NNM+11)=1.765`.
    pub cylinder_foot: Point,
    /// Body 1.
    pub boom: BoomData,
    /// How body 1 is meshed.
    pub mesh: MeshSpec,
    /// Body 2: the rod A0–D, the boom's cylinder lug (listing `AL2, R2, RO2`).
    pub lug_rod: RodData,
    /// AD: offset of the cylinder pin D from the boom axis at A (m).
    pub lug_offset_m: f64,
    /// Body 3: the piston rod from the piston B to the pin D (listing `AL3, R3`).
    pub piston_rod: RodData,
    /// Body 4.
    pub cylinder: CylinderData,
    /// Body 5.
    pub rope: RopeData,
    /// The chassis and its jacks.
    pub chassis: ChassisData,
    /// Gravitational acceleration (m/s², listing `9.81`).
    pub gravity_m_s2: f64,
}

impl CraneData {
    /// The COLES Mobile 930 (10 t) of the thesis: the built-in crane.
    pub const fn coles_mobile_930() -> Self {
        CraneData {
            boom_foot: [2.775, 2.57],
            cylinder_foot: [5.125, 1.765],
            boom: BoomData {
                foot_to_g_m: 2.0,
                g_to_tip_m: 17.5,
                foot_to_lug_m: 5.822651887,
                wall_m: 0.020,
                section_at_foot: OctagonDims {
                    e_m: 0.45333,
                    c_m: 0.200,
                    f_m: 0.120,
                },
                section_at_g: OctagonDims {
                    e_m: 0.160,
                    c_m: 0.440,
                    f_m: 0.120,
                },
                section_at_tip: OctagonDims {
                    e_m: 0.160,
                    c_m: 0.20667,
                    f_m: 0.120,
                },
                density_kg_m3: 5750.0,
                youngs_modulus_pa: 2.0e11,
                damping_ratio: 0.02,
            },
            mesh: MeshSpec {
                elements_foot_to_g: 2,
                elements_g_to_tip: 10,
            },
            lug_rod: RodData {
                length_m: 5.85,
                radius_m: 0.025,
                density_kg_m3: 7850.0,
            },
            lug_offset_m: 0.565,
            piston_rod: RodData {
                length_m: 3.455,
                radius_m: 0.090,
                density_kg_m3: 7850.0,
            },
            cylinder: CylinderData {
                length_m: 3.44,
                bore_radius_m: 0.115,
                outer_radius_m: 0.123,
                tube_mass_kg: 161.5269215,
                inner_length_m: 3.42881781,
                piston_thickness_m: 0.02,
                oil_density_kg_m3: 891.0,
                transducer_span_pa: 20.0e6,
            },
            rope: RopeData {
                mass_per_m_kg: 2.0 * 5124.789168 * core::f64::consts::PI * 0.01 * 0.01,
                load_clearance_m: 1.0,
            },
            chassis: ChassisData {
                tipping_line_x_m: 7.305,
                weight_n: 222_792.772,
                weight_arm_m: 4.125,
                jack_base_m: 8.25,
                radius_offset_m: 1.83,
            },
            gravity_m_s2: 9.81,
        }
    }

    /// The angle γ between the boom axis and the lug rod A0–D: asin(AD / A0D) (rad).
    pub fn lug_angle_rad(&self) -> f64 {
        libm::asin(self.lug_offset_m / self.lug_rod.length_m)
    }

    /// Piston area A = π·r² of the bore (m², eq. 4.1).
    pub fn piston_area_m2(&self) -> f64 {
        core::f64::consts::PI * self.cylinder.bore_radius_m * self.cylinder.bore_radius_m
    }

    /// Rod area A_s (m², eq. 4.1).
    pub fn rod_area_m2(&self) -> f64 {
        core::f64::consts::PI * self.piston_rod.radius_m * self.piston_rod.radius_m
    }

    /// Hook radius R (m) at boom angle θ1 (eq. 4.3).
    pub fn radius_m(&self, boom_angle_rad: f64) -> f64 {
        self.boom.length_m() * libm::cos(boom_angle_rad) - self.chassis.radius_offset_m
    }
}

impl Default for CraneData {
    fn default() -> Self {
        Self::coles_mobile_930()
    }
}
