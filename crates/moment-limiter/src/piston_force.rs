//! Piston force of the luffing cylinder from the two chamber pressures.
//!
//! Thesis eq. 4.1: F = p1·A − p2·(A − A_s), with the bore area A = π·0.115² m²
//! (Ø230 mm) and the rod area A_s = π·0.09² m² (Ø180 mm); pressures in Pa.
//! F > 0 pushes the boom up. Filtering is done by [`crate::filter::LowPass`]
//! in the limiter, after this conversion (the equation is linear, so filtering
//! the force or the pressures is the same).

use crane_model::Real;

use crate::units::PressureBar;

/// Bore radius of the luffing cylinder (m).
pub const BORE_RADIUS_M: f64 = 0.115;
/// Piston-rod radius (m).
pub const ROD_RADIUS_M: f64 = 0.09;

/// Piston (bore) area A (m²).
pub fn piston_area_m2<T: Real>() -> T {
    T::pi() * T::lit(BORE_RADIUS_M) * T::lit(BORE_RADIUS_M)
}

/// Annulus area A − A_s on the rod side (m²).
pub fn annulus_area_m2<T: Real>() -> T {
    piston_area_m2::<T>() - T::pi() * T::lit(ROD_RADIUS_M) * T::lit(ROD_RADIUS_M)
}

/// Piston force F (N) of eq. 4.1 from checked pressures, after subtracting
/// per-transducer zero offsets (bar, from the calibration).
pub fn piston_force_n<T: Real>(
    p1: PressureBar<T>,
    p2: PressureBar<T>,
    p1_offset_bar: T,
    p2_offset_bar: T,
) -> T {
    let pa = T::lit(crate::units::PA_PER_BAR);
    (p1.bar() - p1_offset_bar) * pa * piston_area_m2::<T>()
        - (p2.bar() - p2_offset_bar) * pa * annulus_area_m2::<T>()
}

/// The piston-side pressure (bar) that produces force `force_n` with rod-side
/// pressure `p2_bar` (inverse of eq. 4.1; for tests and log synthesis).
pub fn p1_bar_for_force<T: Real>(force_n: T, p2_bar: T) -> T {
    let pa = T::lit(crate::units::PA_PER_BAR);
    (force_n + p2_bar * pa * annulus_area_m2::<T>()) / (pa * piston_area_m2::<T>())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eq_4_1_by_hand() {
        // 100 bar on the piston side, 10 bar on the rod side.
        let f = piston_force_n(
            PressureBar::new(100.0_f64).unwrap(),
            PressureBar::new(10.0).unwrap(),
            0.0,
            0.0,
        );
        let a = core::f64::consts::PI * 0.115 * 0.115; // 0.041548 m²
        let a_s = core::f64::consts::PI * 0.09 * 0.09; // 0.025447 m²
        let expected = 100.0e5 * a - 10.0e5 * (a - a_s);
        assert!((f - expected).abs() < 1e-6);
        assert!((f - 399_379.0).abs() < 10.0, "{f}");
        assert!((p1_bar_for_force(f, 10.0) - 100.0).abs() < 1e-9);
    }
}
