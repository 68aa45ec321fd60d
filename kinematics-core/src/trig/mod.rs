//! Our own sin/cos for f64 and f32: branch-free, so that the lane functions auto-vectorise, and
//! bit-identical on every x86-64 target (no fused multiply-add). This module owns the public entry
//! points; `kernel` holds the per-value steps and `coefficients` the constants that
//! `coefficients.py` derives.
//!
//! (Design notes, accuracy and speed figures: see the end of this doc once measured.)

mod coefficients;
mod kernel;
#[cfg(test)]
mod tests;

pub use kernel::FAST_BOUND;

/// `(sin x, cos x)` for `f64`; see the module doc for the accuracy contract.
#[inline(always)]
pub fn sin_cos_f64(x: f64) -> (f64, f64) {
    let ([s], [c]) = sin_cos_f64_lanes([x]);
    (s, c)
}

/// `(sin x, cos x)` for `f32`; see the module doc for the accuracy contract.
#[inline(always)]
pub fn sin_cos_f32(x: f32) -> (f32, f32) {
    let ([s], [c]) = sin_cos_f32_lanes([x]);
    (s, c)
}

/// Sines and cosines of `N` independent values at once, bit for bit what [`sin_cos_f64`] gives
/// for each. The fast path runs on every lane (this loop auto-vectorises); then, in one rarely
/// taken branch, lanes beyond [`FAST_BOUND`] or not finite are computed again on the slow path.
#[inline(always)]
pub fn sin_cos_f64_lanes<const N: usize>(x: [f64; N]) -> ([f64; N], [f64; N]) {
    let mut s = [0.0; N];
    let mut c = [0.0; N];
    let mut all_fast = true;
    for i in 0..N {
        (s[i], c[i]) = kernel::sin_cos_fast_f64(x[i]);
        all_fast &= kernel::in_fast_range(x[i]);
    }
    if !all_fast {
        for i in 0..N {
            if !kernel::in_fast_range(x[i]) {
                (s[i], c[i]) = kernel::sin_cos_slow(x[i]);
            }
        }
    }
    (s, c)
}

/// Sines and cosines of `N` independent `f32` values at once, bit for bit what [`sin_cos_f32`]
/// gives for each; fast path on every lane, slow path only for lanes that need it.
#[inline(always)]
pub fn sin_cos_f32_lanes<const N: usize>(x: [f32; N]) -> ([f32; N], [f32; N]) {
    let mut s = [0.0; N];
    let mut c = [0.0; N];
    let mut all_fast = true;
    for i in 0..N {
        (s[i], c[i]) = kernel::sin_cos_fast_f32(x[i]);
        all_fast &= kernel::in_fast_range(f64::from(x[i]));
    }
    if !all_fast {
        for i in 0..N {
            let wide = f64::from(x[i]);
            if !kernel::in_fast_range(wide) {
                let (sw, cw) = kernel::sin_cos_slow(wide);
                // One rounding of libm's f64 result (itself within 1 ulp of f64): the f32 result
                // is within half an f32 ulp plus 2^-29 of one.
                (s[i], c[i]) = (sw as f32, cw as f32);
            }
        }
    }
    (s, c)
}
