//! Constants of the sin/cos kernels: the OUTPUT of `coefficients.py` beside this file, unedited.
//!
//! Regenerate with `python3 kinematics-core/src/trig/coefficients.py >
//! kinematics-core/src/trig/coefficients.rs` (mpmath 1.3.0); see that script for the derivation.

/// 2/pi rounded to f64 (0.6366197723675814, bits 0x3fe45f306dc9c883: core's constant, which
/// clippy wants by name); `x * FRAC_2_PI` picks the quadrant count k.
pub const FRAC_2_PI: f64 = core::f64::consts::FRAC_2_PI;
/// The bits of 2/pi rounded to f64, as computed here; a unit test holds core's constant to it.
#[cfg(test)]
pub const FRAC_2_PI_BITS: u64 = 0x3fe45f306dc9c883;
/// pi/2 to 33 significant bits: `k * PIO2_1` is exact for |k| < 2^20.
pub const PIO2_1: f64 = 1.5707963267341256;
/// The next 33 bits of pi/2.
pub const PIO2_2: f64 = 6.077100506303966e-11;
/// The next 33 bits of pi/2.
pub const PIO2_3: f64 = 2.0222662487111665e-21;
/// The rest of pi/2 rounded to f64; pi/2 - (PIO2_1 + .. + PIO2_4) = 7.4e-49.
pub const PIO2_4: f64 = 8.4784276603689e-32;

/// Minimax coefficients of sin(r) = r + r^3 * S(r^2), f64 kernel, lowest power first, on r in [0, pi/4 (1 + 1e-6)],
/// error relative to sin(r). Error of the unrounded fit: 6.48e-18;
/// with the coefficients rounded to f64 (one at a time, the rest refitted): 4.14e-18.
pub const SIN_F64: [f64; 6] = [
    -0.16666666666666644,
    0.008333333333324427,
    -0.00019841269831058294,
    2.7557314048238113e-06,
    -2.505080567817782e-08,
    1.5899208343540428e-10,
];

/// Minimax coefficients of cos(r) = 1 - r^2/2 + r^4 * C(r^2), f64 kernel, lowest power first, on r in [0, pi/4 (1 + 1e-6)],
/// error relative to cos(r). Error of the unrounded fit: 1.96e-19;
/// with the coefficients rounded to f64 (one at a time, the rest refitted): 9.13e-20.
pub const COS_F64: [f64; 6] = [
    0.04166666666666665,
    -0.0013888888888881456,
    2.480158729341848e-05,
    -2.7557315353987485e-07,
    2.0875845378075817e-09,
    -1.136539623495634e-11,
];

/// 2/pi rounded to f32 (6.3661975e-1, bits 0x3f22f983: core's constant);
/// `x * FRAC_2_PI_F32` picks the f32 routines' quadrant count k.
pub const FRAC_2_PI_F32: f32 = core::f32::consts::FRAC_2_PI;
/// The bits of 2/pi rounded to f32, as computed here; a unit test holds core's constant to it.
#[cfg(test)]
pub const FRAC_2_PI_F32_BITS: u32 = 0x3f22f983;
/// pi/2 rounded down to 16 significant bits: `k * PIO2_F32_1` is exact in f32 for |k| < 2^8.
pub const PIO2_F32_1: f32 = 1.5707703;
/// The next 16 bits of pi/2, rounded down.
pub const PIO2_F32_2: f32 = 2.6063062e-5;
/// The rest of pi/2 rounded to f32; pi/2 - (PIO2_F32_1 + .. + PIO2_F32_3) = -1.22e-18.
pub const PIO2_F32_3: f32 = 6.0771006e-11;

/// Minimax coefficients of sin(r) = r + r^3 * S(r^2), f32 kernel (evaluated in f32), lowest power first, on r in
/// [0, pi/4 (1 + 1e-4)], error relative to sin(r). Error of the unrounded fit: 6.48e-9;
/// with the coefficients rounded to f32 (one at a time, the rest refitted): 3.97e-9.
pub const SIN_F32: [f32; 3] = [
    -1.6666655e-1,
    8.332189e-3,
    -1.9518285e-4,
];

/// Minimax coefficients of cos(r) = 1 - r^2/2 + r^4 * C(r^2), f32 kernel (evaluated in f32), lowest power first, on r in
/// [0, pi/4 (1 + 1e-4)], error relative to cos(r). Error of the unrounded fit: 2.62e-10;
/// with the coefficients rounded to f32 (one at a time, the rest refitted): 1.84e-10.
pub const COS_F32: [f32; 3] = [
    4.1666653e-2,
    -1.3887612e-3,
    2.4462202e-5,
];
