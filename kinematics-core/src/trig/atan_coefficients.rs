//! Constants of the atan2 kernel: the OUTPUT of `atan_coefficients.py` beside this file, unedited.
//!
//! Regenerate with `python3 kinematics-core/src/trig/atan_coefficients.py >
//! kinematics-core/src/trig/atan_coefficients.rs` (mpmath 1.3.0); see that script for the derivation.

/// tan(pi/8) rounded to f64: the bound of the reduced argument.
pub const TAN_PI_8: f64 = 0.41421356237309503;
/// pi/4 as hi + lo: the nearest f64, then the rest.
pub const FRAC_PI_4_LO: f64 = 3.061616997868383e-17;
/// pi/2 as hi + lo: the nearest f64, then the rest.
pub const FRAC_PI_2_LO: f64 = 6.123233995736766e-17;
/// pi as hi + lo: the nearest f64, then the rest.
pub const PI_LO: f64 = 1.2246467991473532e-16;

/// Minimax coefficients of atan(u) = u + u^3 * A(u^2), lowest power first, on |u| <= tan(pi/8) (1 + 1e-6),
/// error relative to atan(u). Error of the unrounded fit: 2.41e-18;
/// with the coefficients rounded to f64 (one at a time, the rest refitted): 1.44e-18.
pub const ATAN_F64: [f64; 11] = [
    -0.3333333333333327,
    0.199999999999692,
    -0.1428571428146211,
    0.11111110836893913,
    -0.09090899096416682,
    0.07692081417820142,
    -0.06663322111200895,
    0.058493425584146455,
    -0.05045360554538685,
    0.03820797675899835,
    -0.018054557918147262,
];
