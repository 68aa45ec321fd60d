//! The per-value steps of our sin/cos: the branch-free fast paths (Cody-Waite reduction, minimax
//! kernels, quadrant by bit masks) for f64 and for f32 (each in its own type), their bounds, and
//! the slow path (libm) for values beyond them. Every function here is written so that a loop
//! over lanes of it has no branch and auto-vectorises.

use super::coefficients::{
    COS_F32, COS_F64, FRAC_2_PI, FRAC_2_PI_F32, PIO2_1, PIO2_2, PIO2_3, PIO2_4, PIO2_F32_1, PIO2_F32_2, PIO2_F32_3,
    SIN_F32, SIN_F64,
};

/// The fast path is exact in its range reduction for |x| <= 2^20 (about 1.05e6 rad): there the
/// quadrant count |k| < 2^20 and every `k * PIO2_n` with a 33-bit part is exact. Beyond it (and for
/// NaN and infinities) the values are recomputed by the slow path (`sin_cos_slow`).
pub const FAST_BOUND: f64 = 1_048_576.0;

/// The f32 fast path's bound, 2^8 rad: there the quadrant count |k| <= 163 < 2^8 and every
/// `k * PIO2_F32_n` with a 16-bit part is exact in f32. Beyond it (about 41 turns, and for NaN and
/// infinities) the values are recomputed by the slow path, in f64.
pub const FAST_BOUND_F32: f32 = 256.0;

/// 1.5 * 2^23, [`ROUNDING_MAGIC`] for f32: adding it to a value below 2^22 in magnitude rounds
/// that value to the nearest integer, whose low bits are then the sum's.
const ROUNDING_MAGIC_F32: f32 = 12_582_912.0;

/// 1.5 * 2^52: adding it to a value below 2^51 in magnitude rounds that value to the nearest
/// integer (ties to even), which then sits in the low bits of the sum's mantissa, in two's
/// complement for negative values.
const ROUNDING_MAGIC: f64 = 6_755_399_441_055_744.0;

/// `c[0] + z * (c[1] + z * (...))`, Horner, no fused multiply-add (bit-identical on any target).
/// Starts from the last coefficient: a start at 0.0 would cost a multiply LLVM may not drop.
#[cfg_attr(not(debug_assertions), inline(always))]
fn horner<const D: usize>(coefficients: &[f64; D], z: f64) -> f64 {
    let mut acc = coefficients[D - 1];
    let mut i = D - 1;
    while i > 0 {
        i -= 1;
        acc = acc * z + coefficients[i];
    }
    acc
}

/// The quadrant count k (as an f64 integer) and its bits (k mod 4 in the low two) for `x`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn quadrant(x: f64) -> (f64, u64) {
    let shifted = x * FRAC_2_PI + ROUNDING_MAGIC;
    (shifted - ROUNDING_MAGIC, shifted.to_bits())
}

/// `x - k * pi/2` as an unevaluated sum `hi + lo` (|lo| <= half an ulp of hi, up to roundings
/// of order 2^-100): the f64 kernels add `lo`'s first-order effect, which keeps them within one
/// ulp where a single f64 with three roundings reached two (measured at |x| ~ 9e3).
#[cfg_attr(not(debug_assertions), inline(always))]
fn reduce_double(x: f64, k: f64) -> (f64, f64) {
    let t = x - k * PIO2_1; // exact, as above
    let w = k * PIO2_2; // exact
    let r1 = t - w;
    // Knuth's TwoSum: the exact rounding error of t - w, whatever their magnitudes.
    let w_rounded = t - r1;
    let t_rounded = r1 + w_rounded;
    let e1 = (t - t_rounded) + (w_rounded - w);
    // The rest is tiny (|k * PIO2_3| < 2.2e-15): its roundings are of order 2^-53 of it.
    // Written as a negated difference (the same value) so that x = -0 gives lo = -0 and hi = -0:
    // `e1 - (...)` would be +0 there and turn hi into +0.
    let lo = -((k * PIO2_3 + k * PIO2_4) - e1);
    let hi = r1 + lo;
    (hi, lo - (hi - r1))
}

/// `(sin x, cos x)` from the kernels' `(sin r, cos r)`: sin(r + k pi/2) is sin r, cos r, -sin r,
/// -cos r for k mod 4 = 0..3, and cos(r + k pi/2) is cos r, -sin r, -cos r, sin r. Swaps and sign
/// flips are bit masks, so lanes never branch.
#[cfg_attr(not(debug_assertions), inline(always))]
fn place_in_quadrant(quadrant: u64, sin_r: f64, cos_r: f64) -> (f64, f64) {
    let swap = (quadrant & 1).wrapping_neg();
    let (s, c) = (sin_r.to_bits(), cos_r.to_bits());
    let sin_bits = (s & !swap) | (c & swap);
    let cos_bits = (c & !swap) | (s & swap);
    let sin_sign = (quadrant & 2) << 62;
    let cos_sign = (quadrant.wrapping_add(1) & 2) << 62;
    (f64::from_bits(sin_bits ^ sin_sign), f64::from_bits(cos_bits ^ cos_sign))
}

/// `magnitude` with the sign of `sign`. sin(r) has the sign of r on [-pi/4, pi/4], and this keeps
/// sin(-0) = -0, which `r + (r * z) * S` alone would turn into +0 (the correction is +0 there).
#[cfg_attr(not(debug_assertions), inline(always))]
fn with_sign_of(magnitude: f64, sign: f64) -> f64 {
    const SIGN: u64 = 1 << 63;
    f64::from_bits((magnitude.to_bits() & !SIGN) | (sign.to_bits() & SIGN))
}

/// Branch-free f64 sin and cos, right for |x| <= [`FAST_BOUND`]; NaN or garbage beyond it.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn sin_cos_fast_f64(x: f64) -> (f64, f64) {
    let (k, quadrant) = quadrant(x);
    let (r, r_lo) = reduce_double(x, k);
    let z = r * r;
    let half_z = 0.5 * z;
    // sin(r + lo) = sin r + lo cos r + O(lo^2), and cos r ~ 1 - z/2 is all lo (<= 2^-53 r) needs.
    let sin_tail = (r * z) * horner(&SIN_F64, z) + r_lo * (1.0 - half_z);
    let sin_r = with_sign_of(r + sin_tail, r);
    // 1 - z/2 loses up to half an ulp of a value near 0.7; the rounding error of that subtraction
    // is recovered exactly by (1 - w) - z/2 (Sterbenz; z/2 <= 0.31) and added back with the tail,
    // as is cos(r + lo) - cos r ~ -lo r.
    let w = 1.0 - half_z;
    let cos_r = w + (((1.0 - w) - half_z) + ((z * z) * horner(&COS_F64, z) - r * r_lo));
    place_in_quadrant(quadrant, sin_r, cos_r)
}

/// `x - k * pi/2` in f32 as an unevaluated sum `hi + lo`, for |x| <= [`FAST_BOUND_F32`]:
/// `x - k * PIO2_F32_1` is exact (the product is; Sterbenz once k != 0), `k * PIO2_F32_2` is
/// exact, and the rounding error of their difference is recovered (Fast2Sum) and carried with the
/// third part's product into `lo`. Every part is positive, so -0 stays -0: each step subtracts a
/// +0 from it, and the last sum is written as a difference for the same reason.
#[cfg_attr(not(debug_assertions), inline(always))]
fn reduce_f32(x: f32, k: f32) -> (f32, f32) {
    let t = x - k * PIO2_F32_1;
    let w = k * PIO2_F32_2;
    let r1 = t - w;
    let e1 = (t - r1) - w;
    let minus_lo = k * PIO2_F32_3 - e1;
    let hi = r1 - minus_lo;
    (hi, (r1 - hi) - minus_lo)
}

/// [`place_in_quadrant`] for f32.
#[cfg_attr(not(debug_assertions), inline(always))]
fn place_in_quadrant_f32(quadrant: u32, sin_r: f32, cos_r: f32) -> (f32, f32) {
    let swap = (quadrant & 1).wrapping_neg();
    let (s, c) = (sin_r.to_bits(), cos_r.to_bits());
    let sin_bits = (s & !swap) | (c & swap);
    let cos_bits = (c & !swap) | (s & swap);
    let sin_sign = (quadrant & 2) << 30;
    let cos_sign = (quadrant.wrapping_add(1) & 2) << 30;
    (f32::from_bits(sin_bits ^ sin_sign), f32::from_bits(cos_bits ^ cos_sign))
}

/// `c[0] + z * (c[1] + z * c[2])` in f32 (the f32 kernels' three coefficients).
#[cfg_attr(not(debug_assertions), inline(always))]
fn horner_f32(coefficients: &[f32; 3], z: f32) -> f32 {
    (coefficients[2] * z + coefficients[1]) * z + coefficients[0]
}

/// Branch-free f32 sin and cos, right for |x| <= [`FAST_BOUND_F32`]; computed in f32 throughout
/// (half the width of f64, so twice the values to a register), the steps of
/// [`sin_cos_fast_f64`]: the reduction carried as `hi + lo`, the kernels with `lo`'s first-order
/// effect, and `1 - z/2`'s rounding error added back. Every f32 in the range is within 0.8 ulp of
/// the true values (checked on each of them: `trig-accuracy --exhaustive`).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn sin_cos_fast_f32(x: f32) -> (f32, f32) {
    let shifted = x * FRAC_2_PI_F32 + ROUNDING_MAGIC_F32;
    let k = shifted - ROUNDING_MAGIC_F32;
    let (r, r_lo) = reduce_f32(x, k);
    let z = r * r;
    let half_z = 0.5 * z;
    let w = 1.0 - half_z;
    let sin_tail = (r * z) * horner_f32(&SIN_F32, z) + r_lo * w;
    let sin_r = with_sign_of_f32(r + sin_tail, r);
    let cos_r = w + (((1.0 - w) - half_z) + ((z * z) * horner_f32(&COS_F32, z) - r * r_lo));
    place_in_quadrant_f32(shifted.to_bits(), sin_r, cos_r)
}

/// [`with_sign_of`] for f32.
#[cfg_attr(not(debug_assertions), inline(always))]
fn with_sign_of_f32(magnitude: f32, sign: f32) -> f32 {
    const SIGN: u32 = 1 << 31;
    f32::from_bits((magnitude.to_bits() & !SIGN) | (sign.to_bits() & SIGN))
}

/// Whether the f64 fast path is right for `x`: false beyond the bound, for infinities and for NaN.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn in_fast_range(x: f64) -> bool {
    x.abs() <= FAST_BOUND
}

/// Whether the f32 fast path is right for `x`: false beyond its bound, for infinities and for NaN.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn in_fast_range_f32(x: f32) -> bool {
    x.abs() <= FAST_BOUND_F32
}

/// The slow path for values outside the fast range: libm's `sincos` (Payne-Hanek reduction for
/// large arguments, NaN for NaN and infinities). Kept out of line and cold so the fast path's
/// code stays small.
#[cold]
#[inline(never)]
pub fn sin_cos_slow(x: f64) -> (f64, f64) {
    libm::sincos(x)
}

/// A scalar type with a fast path and a slow path: what the lane loop (`sin_cos_lanes` in the
/// parent module) needs, so one loop serves `f64` and `f32`.
pub trait Kernel: Copy {
    /// Zero, the padding of a chunk's unused lanes.
    const ZERO: Self;
    /// The branch-free fast path ([`sin_cos_fast_f64`], [`sin_cos_fast_f32`]).
    fn sin_cos_fast(self) -> (Self, Self);
    /// Whether the fast path is right for this value ([`in_fast_range`]).
    fn in_fast_range(self) -> bool;
    /// The slow path ([`sin_cos_slow`]).
    fn sin_cos_slow(self) -> (Self, Self);
    /// The magnitude's bits, ordered as the magnitudes are (a NaN's above infinity's).
    fn magnitude_key(self) -> u64;
    /// [`FAST_BOUND`]'s key: the fast path is right exactly for values whose key is at most it.
    const BOUND_KEY: u64;
}

impl Kernel for f64 {
    const ZERO: Self = 0.0;
    const BOUND_KEY: u64 = FAST_BOUND.to_bits();

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn magnitude_key(self) -> u64 {
        self.to_bits() & !(1 << 63)
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_fast(self) -> (Self, Self) {
        sin_cos_fast_f64(self)
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn in_fast_range(self) -> bool {
        in_fast_range(self)
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_slow(self) -> (Self, Self) {
        sin_cos_slow(self)
    }
}

impl Kernel for f32 {
    const ZERO: Self = 0.0;
    const BOUND_KEY: u64 = FAST_BOUND_F32.to_bits() as u64;

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn magnitude_key(self) -> u64 {
        u64::from(self.to_bits() & !(1 << 31))
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_fast(self) -> (Self, Self) {
        sin_cos_fast_f32(self)
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn in_fast_range(self) -> bool {
        in_fast_range_f32(self)
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_slow(self) -> (Self, Self) {
        let (s, c) = sin_cos_slow(f64::from(self));
        // One rounding of libm's f64 result (itself within 1 ulp of f64): the f32 result is
        // within half an f32 ulp plus 2^-29 of one.
        (s as f32, c as f32)
    }
}
