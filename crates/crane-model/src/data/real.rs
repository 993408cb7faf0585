//! The float type the model is generic over: `f32` on the MCU, `f64` on the host.

/// A real scalar the model can run on. Implemented for `f32` and `f64`.
///
/// It is nalgebra's [`nalgebra::RealField`] (which brings `sin`, `sqrt`, … through
/// `libm` in `no_std`) plus `Copy`, and a lossless-enough conversion from `f64`
/// literals so crane data can be written once in SI units.
pub trait Real: nalgebra::RealField + Copy {
    /// Converts an `f64` constant (crane data, tolerances) to this type.
    fn lit(x: f64) -> Self;
    /// Converts to `f64` for reporting.
    fn to_f64(self) -> f64;
    /// √self, correctly rounded: for `f32` the FPU's `vsqrt.f32` on the
    /// controller ([`fpu_math::sqrt`]), never a software routine, and the same
    /// bits on the host. What the control cycle calls.
    fn sqrt_ieee(self) -> Self;
    /// (sin, cos) computed in this type's own precision: for `f32` a
    /// polynomial in f32 ([`sin_cos_f32`]), never libm's `sinf`/`cosf`, which
    /// run f64 kernels (soft float on the Cortex-M4F). What the control cycle
    /// calls.
    fn sin_cos_own(self) -> (Self, Self);
    /// Converts a run-time integer (a time step in µs, a count): the FPU's
    /// `vcvt` for `f32`, never through `f64` (soft float on the controller).
    /// Exact below 2²⁴ for `f32`, always for `f64`.
    fn from_count(x: u32) -> Self;
    /// Converts to a count, toward zero and saturating (NaN gives 0), as
    /// `as u32` does: the FPU's `vcvt` for `f32`, never through `f64` (soft
    /// float on the controller).
    fn to_count(self) -> u32;
}

impl Real for f64 {
    #[inline(always)]
    fn lit(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline(always)]
    fn sqrt_ieee(self) -> Self {
        nalgebra::ComplexField::sqrt(self)
    }
    #[inline(always)]
    fn sin_cos_own(self) -> (Self, Self) {
        nalgebra::ComplexField::sin_cos(self)
    }
    #[inline(always)]
    fn from_count(x: u32) -> Self {
        f64::from(x)
    }
    #[inline(always)]
    fn to_count(self) -> u32 {
        self as u32
    }
}

impl Real for f32 {
    #[inline(always)]
    fn lit(x: f64) -> Self {
        x as f32
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        self as f64
    }
    #[inline(always)]
    fn sqrt_ieee(self) -> Self {
        fpu_math::sqrt(self)
    }
    #[inline(always)]
    fn sin_cos_own(self) -> (Self, Self) {
        sin_cos_f32(self)
    }
    #[inline(always)]
    fn from_count(x: u32) -> Self {
        x as f32
    }
    #[inline(always)]
    fn to_count(self) -> u32 {
        self as u32
    }
}

/// (sin x, cos x) in f32 arithmetic only: x reduced by the nearest multiple
/// k of π/2 in two steps (Cody–Waite: π/2 split so k·PIO2_HI is exact for
/// |k| < 2¹²), then Cephes' minimax polynomials on |r| ≤ π/4 (error below
/// 1 ulp there) and the quadrant's sign swap. Absolute error ≤ 2.4e-7 for
/// |x| ≤ 100 (test `sin_cos_f32_matches_f64`); the boom's angle stays within
/// ±2 rad. Non-finite x gives NaN.
// Never inlined: link-time optimisation had inlined its 248 bytes at every
// call of the limiter's pendulum code, 2.3 KB of the board's 64 KiB flash
// budget; one copy costs the cycle ~24 instructions more (call, return and
// moves; max 8 982 -> 9 005, scripts/firmware-budgets.sh). Same arithmetic,
// same results.
#[inline(never)]
pub fn sin_cos_f32(x: f32) -> (f32, f32) {
    const FRAC_2_PI: f32 = core::f32::consts::FRAC_2_PI;
    // π/2 with its f32 mantissa cut to 12 bits (0x3fc90000), and the rest.
    const PIO2_HI: f32 = 1.570_312_5;
    const PIO2_LO: f32 = 4.838_268e-4;
    let q = x * FRAC_2_PI;
    // Round to nearest: `as` truncates toward zero and saturates (NaN → 0). The
    // half is given q's sign without a branch: the swing's angle changes sign
    // every half period, and a mispredicted branch here cost more than the
    // polynomials (the estimator calls this ~40 times a cycle).
    let k = (q + 0.5f32.copysign(q)) as i32;
    let kf = k as f32;
    let r = (x - kf * PIO2_HI) - kf * PIO2_LO;
    let z = r * r;
    let s = r + r * z * (-1.666_665_5e-1 + z * (8.332_161e-3 + z * -1.951_529_6e-4));
    let c = 1.0 - 0.5 * z + z * z * (4.166_664_6e-2 + z * (-1.388_731_6e-3 + z * 2.443_315_7e-5));
    let (s, c) = if x.is_finite() { (s, c) } else { (f32::NAN, f32::NAN) };
    // The quadrant's swap and signs as two selects (k & 3 = 1: (c, −s);
    // 2: (−s, −c); 3: both, (−c, s)).
    let (s, c) = if k & 1 == 0 { (s, c) } else { (c, -s) };
    if k & 2 == 0 { (s, c) } else { (-s, -c) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sin_cos_f32_matches_f64() {
        let mut worst = 0.0f64;
        for i in -200_000..=200_000 {
            let x = i as f32 * 5e-4;
            let (s, c) = sin_cos_f32(x);
            let xd = x as f64;
            worst = worst.max((s as f64 - xd.sin()).abs()).max((c as f64 - xd.cos()).abs());
        }
        assert!(worst <= 2.4e-7, "worst {worst:e}");
        assert!(sin_cos_f32(f32::NAN).0.is_nan() && sin_cos_f32(f32::INFINITY).1.is_nan());
        assert_eq!(sin_cos_f32(0.0), (0.0, 1.0));
    }

    #[test]
    fn sqrt_ieee_is_the_correctly_rounded_root() {
        for x in [2.0f32, 0.3, 1e6, 7.0] {
            assert_eq!(x.sqrt_ieee(), x.sqrt());
        }
        assert_eq!(2.0f64.sqrt_ieee(), 2.0f64.sqrt());
    }
}
