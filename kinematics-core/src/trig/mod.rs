//! Our own sin/cos (placeholder: libm until the branch-free kernels land).

/// `(sin x, cos x)` for `f64`.
#[inline(always)]
pub fn sin_cos_f64(x: f64) -> (f64, f64) {
    (libm::sin(x), libm::cos(x))
}

/// `(sin x, cos x)` for `f32`.
#[inline(always)]
pub fn sin_cos_f32(x: f32) -> (f32, f32) {
    (libm::sinf(x), libm::cosf(x))
}

/// Sines and cosines of `N` values at once.
#[inline(always)]
pub fn sin_cos_f64_lanes<const N: usize>(x: [f64; N]) -> ([f64; N], [f64; N]) {
    let mut s = [0.0; N];
    let mut c = [0.0; N];
    for i in 0..N {
        (s[i], c[i]) = sin_cos_f64(x[i]);
    }
    (s, c)
}

/// Sines and cosines of `N` values at once.
#[inline(always)]
pub fn sin_cos_f32_lanes<const N: usize>(x: [f32; N]) -> ([f32; N], [f32; N]) {
    let mut s = [0.0; N];
    let mut c = [0.0; N];
    for i in 0..N {
        (s[i], c[i]) = sin_cos_f32(x[i]);
    }
    (s, c)
}
