//! Test helpers shared by the crane-model test files: the boom's section
//! from the thesis data alone (shoelace formulas on the octagon's vertices,
//! independent of `section.rs`, which subtracts corner triangles from a
//! rectangle).
#![allow(dead_code)]

use crane_model::data::crane::BoomData;
use crane_model::data::section::OctagonDims;

/// Area and second moment (about the horizontal centroidal axis) of a convex
/// polygon by the shoelace formulas: A = ½Σ(xᵢyᵢ₊₁ − xᵢ₊₁yᵢ),
/// I_x = 1/12·Σ(xᵢyᵢ₊₁ − xᵢ₊₁yᵢ)(yᵢ² + yᵢyᵢ₊₁ + yᵢ₊₁²). Independent of section.rs,
/// which subtracts corner triangles from a rectangle.
fn polygon(v: &[(f64, f64)]) -> (f64, f64) {
    let (mut a, mut ix) = (0.0, 0.0);
    for i in 0..v.len() {
        let (x0, y0) = v[i];
        let (x1, y1) = v[(i + 1) % v.len()];
        let cross = x0 * y1 - x1 * y0;
        a += cross / 2.0;
        ix += cross * (y0 * y0 + y0 * y1 + y1 * y1) / 12.0;
    }
    (a, ix)
}

/// The octagon of thesis Fig. 3.3 with flats e (top/bottom), f (sides) and 45°
/// chamfers c, centred on the origin: height 2c·sin45° + f, width 2c·cos45° + e.
fn octagon(e: f64, c: f64, f: f64) -> (f64, f64) {
    let a = c * core::f64::consts::FRAC_1_SQRT_2;
    let (w, h) = (2.0 * a + e, 2.0 * a + f);
    polygon(&[
        (e / 2.0, h / 2.0),
        (-e / 2.0, h / 2.0),
        (-w / 2.0, f / 2.0),
        (-w / 2.0, -f / 2.0),
        (-e / 2.0, -h / 2.0),
        (e / 2.0, -h / 2.0),
        (w / 2.0, -f / 2.0),
        (w / 2.0, f / 2.0),
    ])
}

/// The hollow section: the inner octagon's edges are each shorter by 2t·tan 22.5°.
pub fn hollow(d: OctagonDims, t: f64) -> (f64, f64) {
    let cut = 2.0 * t * (22.5f64.to_radians()).tan();
    let (ao, io) = octagon(d.e_m, d.c_m, d.f_m);
    let (ai, ii) = octagon(d.e_m - cut, d.c_m - cut, d.f_m - cut);
    (ao - ai, io - ii)
}

/// Outer dimensions at x from A0, linear A0→G and G→C (thesis §3.2).
pub fn dims_at(b: &BoomData, x: f64) -> OctagonDims {
    let lerp = |p: OctagonDims, q: OctagonDims, s: f64| OctagonDims {
        e_m: p.e_m + (q.e_m - p.e_m) * s,
        c_m: p.c_m + (q.c_m - p.c_m) * s,
        f_m: p.f_m + (q.f_m - p.f_m) * s,
    };
    if x <= b.foot_to_g_m {
        lerp(b.section_at_foot, b.section_at_g, x / b.foot_to_g_m)
    } else {
        lerp(
            b.section_at_g,
            b.section_at_tip,
            (x - b.foot_to_g_m) / b.g_to_tip_m,
        )
    }
}
