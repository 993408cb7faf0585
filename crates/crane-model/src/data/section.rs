//! The boom's cross-section: a hollow octagon with 45° chamfers (thesis §3.2, Fig. 3.3).
//!
//! The outer edges are e (top and bottom flats), f (the vertical side flats) and c
//! (the four chamfers at 45°). The section is 2·c·sin 45° + f high, the direction of
//! bending in the plane of the crane, and 2·c·cos 45° + e wide. The inner outline
//! is the outer one moved inwards by the wall t; each edge loses 2·t·tan 22.5°.
//! (The thesis text's formula for c_i has a sign slip; its listing's c_i agrees
//! with this geometry, and its e_i uses the chamfer width where it means e0.)

/// The outer edge lengths of an octagon section (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OctagonDims {
    /// e: the top and bottom flats.
    pub e_m: f64,
    /// c: each of the four 45° chamfers.
    pub c_m: f64,
    /// f: the vertical side flats.
    pub f_m: f64,
}

/// Area and second moment of area of a section about its horizontal centroidal axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionProperties {
    /// Area (m²).
    pub area_m2: f64,
    /// Second moment of area for bending in the plane of the crane (m⁴).
    pub second_moment_m4: f64,
}

impl OctagonDims {
    /// Linear interpolation between two sections, `s` in [0, 1].
    pub fn lerp(&self, other: &OctagonDims, s: f64) -> OctagonDims {
        OctagonDims {
            e_m: self.e_m + (other.e_m - self.e_m) * s,
            c_m: self.c_m + (other.c_m - self.c_m) * s,
            f_m: self.f_m + (other.f_m - self.f_m) * s,
        }
    }

    /// Height of the section (m): 2·c·sin 45° + f.
    pub fn height_m(&self) -> f64 {
        2.0 * self.c_m * core::f64::consts::FRAC_1_SQRT_2 + self.f_m
    }

    /// Width of the section (m): 2·c·cos 45° + e.
    pub fn width_m(&self) -> f64 {
        2.0 * self.c_m * core::f64::consts::FRAC_1_SQRT_2 + self.e_m
    }

    /// The solid octagon: a rectangle minus four right-angled corner triangles.
    pub fn solid(&self) -> SectionProperties {
        let leg = self.c_m * core::f64::consts::FRAC_1_SQRT_2;
        let (h, w) = (self.height_m(), self.width_m());
        let corner_area = 0.5 * leg * leg;
        // Each corner triangle's centroid sits f/2 + 2·leg/3 from the axis.
        let arm = 0.5 * self.f_m + 2.0 * leg / 3.0;
        let corner_own = leg * leg * leg * leg / 36.0;
        SectionProperties {
            area_m2: w * h - 4.0 * corner_area,
            second_moment_m4: w * h * h * h / 12.0 - 4.0 * (corner_own + corner_area * arm * arm),
        }
    }

    /// The outline moved inwards by a wall `t`: each edge shortens by 2·t·tan 22.5°.
    pub fn inset(&self, wall_m: f64) -> OctagonDims {
        let cut = 2.0 * wall_m * (core::f64::consts::SQRT_2 - 1.0);
        OctagonDims {
            e_m: self.e_m - cut,
            c_m: self.c_m - cut,
            f_m: self.f_m - cut,
        }
    }

    /// The hollow section with wall `t` (m).
    pub fn hollow(&self, wall_m: f64) -> SectionProperties {
        let (outer, inner) = (self.solid(), self.inset(wall_m).solid());
        SectionProperties {
            area_m2: outer.area_m2 - inner.area_m2,
            second_moment_m4: outer.second_moment_m4 - inner.second_moment_m4,
        }
    }
}

/// The outer dimensions of the boom at distance `x_m` from the foot pin A0:
/// linear from A0 to G and from G to C (thesis §3.2).
pub fn boom_dims_at(boom: &crate::data::crane::BoomData, x_m: f64) -> OctagonDims {
    if x_m <= boom.foot_to_g_m {
        boom.section_at_foot
            .lerp(&boom.section_at_g, (x_m / boom.foot_to_g_m).clamp(0.0, 1.0))
    } else {
        let s = ((x_m - boom.foot_to_g_m) / boom.g_to_tip_m).clamp(0.0, 1.0);
        boom.section_at_g.lerp(&boom.section_at_tip, s)
    }
}

/// The boom's hollow section at distance `x_m` from A0.
pub fn boom_section_at(boom: &crate::data::crane::BoomData, x_m: f64) -> SectionProperties {
    boom_dims_at(boom, x_m).hollow(boom.wall_m)
}
