//! # fpu-math
//!
//! The square root of an `f32` as the Cortex-M4F's FPU computes it.
//!
//! `core` has no `f32::sqrt` on stable Rust, and `libm::sqrtf` is a software
//! routine (about 300 instructions on the M4F; libm 0.2 has no ARM
//! specialisation, checked in the disassembly). On a target with a
//! single-precision FPU (`thumbv7em-none-eabihf`: hard-float ABI) this crate
//! emits the one `vsqrt.f32` instruction (14 cycles). IEEE 754 requires the
//! square root to be correctly rounded, and both `vsqrt.f32` and
//! `libm::sqrtf` are, so the host (which uses libm) and the controller get
//! bit-identical results.
#![no_std]
#![deny(unsafe_code)]

/// √x, correctly rounded (IEEE 754): NaN for x < 0 or NaN, +∞ for +∞.
#[cfg(all(target_arch = "arm", target_os = "none", target_abi = "eabihf"))]
#[inline(always)]
pub fn sqrt(x: f32) -> f32 {
    let bits: u32;
    // The `sreg` register class needs Rust's `vfp2` feature, which also means
    // double precision and is (rightly) off for the single-precision M4F, so
    // the value passes through a core register and s15 is saved around it.
    // SAFETY: the instructions read and write only s15 (restored) and the
    // two named core registers; the push/pop is balanced.
    #[allow(unsafe_code)]
    unsafe {
        core::arch::asm!(
            "vpush {{s15}}",
            "vmov s15, {x}",
            "vsqrt.f32 s15, s15",
            "vmov {bits}, s15",
            "vpop {{s15}}",
            bits = lateout(reg) bits,
            x = in(reg) x.to_bits(),
            options(pure, nomem, preserves_flags),
        );
    }
    f32::from_bits(bits)
}

/// √x, correctly rounded (IEEE 754): NaN for x < 0 or NaN, +∞ for +∞.
#[cfg(not(all(target_arch = "arm", target_os = "none", target_abi = "eabihf")))]
#[inline(always)]
pub fn sqrt(x: f32) -> f32 {
    libm::sqrtf(x)
}

#[cfg(test)]
mod tests {
    #[test]
    fn correctly_rounded_on_samples() {
        for &x in &[0.0f32, 1.0, 2.0, 4.0, 1e-30, 3.5e12, 0.1, 123.456] {
            let r = super::sqrt(x);
            // Correct rounding: no neighbour of r squares closer to x (in f64).
            let err = |y: f32| ((y as f64) * (y as f64) - x as f64).abs();
            let (lo, hi) = (f32::from_bits(r.to_bits().saturating_sub(1)), f32::from_bits(r.to_bits() + 1));
            assert!(err(r) <= err(lo) && err(r) <= err(hi), "{x}: {r}");
        }
        assert!(super::sqrt(-1.0).is_nan());
        assert!(super::sqrt(f32::NAN).is_nan());
        assert_eq!(super::sqrt(f32::INFINITY), f32::INFINITY);
    }
}
