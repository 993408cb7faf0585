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
}
