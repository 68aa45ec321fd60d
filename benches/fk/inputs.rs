//! The configurations every body is timed on, made before any timing: a fixed-seed xorshift
//! within each joint's limits, as `Vec<f64>` for the runtime and the peers, as arrays for the
//! generated functions (f64, and the same values rounded to f32), and packed into lanes.
//! Fixed seeds make every run time the same inputs, so runs compare.

/// Inputs cycled through in the timed loops (computed before timing).
pub const INPUTS: usize = 256;

/// Configurations within the limits (or +-pi for continuous joints), from a fixed seed.
pub fn inputs(limits: &[kinematics::JointLimits], count: usize) -> Vec<Vec<f64>> {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut uniform = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|_| {
            limits
                .iter()
                .map(|l| {
                    let (lo, hi) =
                        if l.lower.is_finite() && l.upper.is_finite() { (l.lower, l.upper) } else { (-3.1, 3.1) };
                    lo + (hi - lo) * uniform()
                })
                .collect()
        })
        .collect()
}

/// The configurations as the generated functions take them.
pub fn arrays<const N: usize>(qs: &[Vec<f64>]) -> Vec<[f64; N]> {
    qs.iter().map(|q| std::array::from_fn(|i| q[i])).collect()
}

/// The configurations rounded to f32, for the single-precision bodies.
pub fn arrays_f32<const N: usize>(qs: &[Vec<f64>]) -> Vec<[f32; N]> {
    qs.iter().map(|q| std::array::from_fn(|i| q[i] as f32)).collect()
}

/// `count` packs of lanes from `qs` (cycled): pack `i` holds configurations `(L * i + l) % len`.
pub fn packs<T: Copy, L: kinematics::Lanes<Scalar = T>, const N: usize>(qs: &[[T; N]], count: usize) -> Vec<[L; N]> {
    (0..count).map(|i| std::array::from_fn(|j| L::from_fn(|l| qs[(L::LANES * i + l) % qs.len()][j]))).collect()
}
