//! Measures the accuracy of kinematics-core's sin/cos against a reference, range by range, for the
//! contract test (`tests/contract.rs`, a fixed-seed sample) and the full sweep (`src/main.rs`).
//!
//! The reference is the platform's `f64::sin` / `f64::cos` (glibc on our Linux targets). The glibc
//! manual's "Errors in Math Functions" table lists 1 ulp as the largest known error of `sin` and
//! `cos` in double on x86_64, so an f64 result we measure `d` ulps from it is within `d + 1` ulps of
//! the true value (and `max_abs + 1 ulp` in absolute terms). For f32 the reference is the same f64
//! value, and errors are measured in f32 ulps against the unrounded f64 value, whose own error
//! (2^-29 f32 ulp) is far below what the figures show.

use rayon::prelude::*;

/// Points are drawn in blocks of this many, each from its own seed, so the sample is the same
/// whatever the number of threads.
const BLOCK: u64 = 1 << 16;

/// SplitMix64: a small, fixed, well-mixed generator, so that samples are reproducible without a
/// dependency.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from `seed`.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1) with 53 random bits.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// How a range's points are drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sampling {
    /// Uniform in [-limit, limit].
    Uniform(f64),
    /// Random sign, exponent uniform in [lowest, highest) (IEEE binades, -1075 for subnormals),
    /// random mantissa: every binade equally often.
    Binades(i32, i32),
}

/// A named set of inputs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// As printed in the table.
    pub name: &'static str,
    /// How the points are drawn.
    pub sampling: Sampling,
}

/// The ranges of the table, f64 inputs: the contract's ([-pi, pi], up to 1e4), then wider.
pub const RANGES_F64: [Range; 7] = [
    Range { name: "[-pi, pi]", sampling: Sampling::Uniform(core::f64::consts::PI) },
    Range { name: "[-100, 100]", sampling: Sampling::Uniform(100.0) },
    Range { name: "[-1e4, 1e4]", sampling: Sampling::Uniform(1e4) },
    Range { name: "[-2^20, 2^20] (fast bound)", sampling: Sampling::Uniform(1_048_576.0) },
    Range { name: "|x| < 1, all binades", sampling: Sampling::Binades(-1075, 0) },
    Range { name: "1 <= |x| < 2^20, all binades", sampling: Sampling::Binades(0, 20) },
    Range { name: "2^20 <= |x| < 2^1024 (slow path)", sampling: Sampling::Binades(20, 1024) },
];

/// The ranges for f32 inputs (drawn as f64, rounded to f32). The f32 fast path ends at 2^8
/// (`FAST_BOUND_F32`); [`exhaustive_f32`] measures every f32 below it.
pub const RANGES_F32: [Range; 7] = [
    Range { name: "[-pi, pi]", sampling: Sampling::Uniform(core::f64::consts::PI) },
    Range { name: "[-100, 100]", sampling: Sampling::Uniform(100.0) },
    Range { name: "[-256, 256] (fast bound)", sampling: Sampling::Uniform(256.0) },
    Range { name: "[-1e4, 1e4]", sampling: Sampling::Uniform(1e4) },
    Range { name: "|x| < 1, all binades", sampling: Sampling::Binades(-150, 0) },
    Range { name: "1 <= |x| < 2^8, all binades", sampling: Sampling::Binades(0, 8) },
    Range { name: "2^8 <= |x| < 2^128 (slow path)", sampling: Sampling::Binades(8, 128) },
];

impl Sampling {
    /// One point.
    pub fn draw(self, rng: &mut SplitMix64) -> f64 {
        match self {
            Sampling::Uniform(limit) => (2.0 * rng.unit() - 1.0) * limit,
            Sampling::Binades(lowest, highest) => {
                let bits = rng.next_u64();
                let span = (highest - lowest) as u64;
                let exponent = lowest + ((bits >> 1) % span) as i32;
                let mantissa = rng.next_u64() >> 12;
                let sign = (bits & 1) << 63;
                let magnitude = if exponent < -1022 {
                    // Subnormal binade: mantissa alone, below 2^-1022.
                    f64::from_bits(mantissa >> ((-1022 - exponent) as u32).min(52))
                } else {
                    f64::from_bits((((exponent + 1023) as u64) << 52) | mantissa)
                };
                f64::from_bits(magnitude.to_bits() | sign)
            }
        }
    }
}

/// The spacing of f64 values at `v`'s magnitude (the ulp of a result): 2^(e - 52) for a value in
/// [2^e, 2^(e+1)), 2^-1074 for subnormals and zero.
pub fn ulp_f64(v: f64) -> f64 {
    let exponent = ((v.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    pow2(exponent.max(-1022) - 52)
}

/// The spacing of f32 values at the f64 value `v`'s magnitude.
pub fn ulp_f32(v: f64) -> f64 {
    let exponent = ((v.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    pow2(exponent.max(-126) - 23)
}

fn pow2(e: i32) -> f64 {
    if e >= -1022 { f64::from_bits(((e + 1023) as u64) << 52) } else { f64::from_bits(1u64 << (e + 1074)) }
}

/// Worst errors seen over a set of points. NaN or infinite results count as infinite errors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Errors {
    /// Points measured.
    pub points: u64,
    /// Largest error of sin in ulps of the reference result.
    pub ulp_sin: f64,
    /// Largest error of cos in ulps.
    pub ulp_cos: f64,
    /// Largest absolute error of sin.
    pub abs_sin: f64,
    /// Largest absolute error of cos.
    pub abs_cos: f64,
    /// The input with the largest ulp error (of either).
    pub worst_x: f64,
}

impl Default for Errors {
    fn default() -> Self {
        Self { points: 0, ulp_sin: 0.0, ulp_cos: 0.0, abs_sin: 0.0, abs_cos: 0.0, worst_x: f64::NAN }
    }
}

/// `worst` raised to `e`; NaN raises it to infinity (f64::max would drop it).
fn raise(worst: &mut f64, e: f64) -> bool {
    let e = if e.is_nan() { f64::INFINITY } else { e };
    if e > *worst {
        *worst = e;
        true
    } else {
        false
    }
}

impl Errors {
    /// One point's errors, given the result under test and the reference (both as f64) and the
    /// ulp function of the result's precision.
    fn record(&mut self, x: f64, got: (f64, f64), want: (f64, f64), ulp: fn(f64) -> f64) {
        self.points += 1;
        let (ds, dc) = ((got.0 - want.0).abs(), (got.1 - want.1).abs());
        raise(&mut self.abs_sin, ds);
        raise(&mut self.abs_cos, dc);
        let worst = self.ulp_sin.max(self.ulp_cos);
        let a = raise(&mut self.ulp_sin, ds / ulp(want.0));
        let b = raise(&mut self.ulp_cos, dc / ulp(want.1));
        if (a || b) && self.ulp_sin.max(self.ulp_cos) > worst || self.worst_x.is_nan() {
            self.worst_x = x;
        }
    }

    /// The worst of both.
    pub fn merge(self, other: Self) -> Self {
        let pick_other = other.ulp_sin.max(other.ulp_cos) > self.ulp_sin.max(self.ulp_cos);
        Self {
            points: self.points + other.points,
            ulp_sin: self.ulp_sin.max(other.ulp_sin),
            ulp_cos: self.ulp_cos.max(other.ulp_cos),
            abs_sin: self.abs_sin.max(other.abs_sin),
            abs_cos: self.abs_cos.max(other.abs_cos),
            worst_x: if pick_other || self.worst_x.is_nan() { other.worst_x } else { self.worst_x },
        }
    }

    /// The largest ulp error, sin or cos.
    pub fn max_ulp(&self) -> f64 {
        self.ulp_sin.max(self.ulp_cos)
    }

    /// The largest absolute error, sin or cos.
    pub fn max_abs(&self) -> f64 {
        self.abs_sin.max(self.abs_cos)
    }
}

/// An implementation under test: eight values at once (the lane width both ours and wide handle).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Subject {
    /// kinematics-core's `sin_cos_*_lanes::<8>` (bit for bit its scalar function, a unit test there
    /// shows).
    Ours,
    /// wide 1.7.1's `f64x4::sin_cos` / `f32x8::sin_cos`.
    Wide,
}

fn eval_f64(subject: Subject, x: [f64; 8]) -> ([f64; 8], [f64; 8]) {
    match subject {
        Subject::Ours => kinematics_core::trig::sin_cos_f64_lanes(x),
        Subject::Wide => {
            let lo = wide::f64x4::from([x[0], x[1], x[2], x[3]]).sin_cos();
            let hi = wide::f64x4::from([x[4], x[5], x[6], x[7]]).sin_cos();
            let (ls, lc, hs, hc) = (lo.0.to_array(), lo.1.to_array(), hi.0.to_array(), hi.1.to_array());
            let join = |a: [f64; 4], b: [f64; 4]| [a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]];
            (join(ls, hs), join(lc, hc))
        }
    }
}

fn eval_f32(subject: Subject, x: [f32; 8]) -> ([f32; 8], [f32; 8]) {
    match subject {
        Subject::Ours => kinematics_core::trig::sin_cos_f32_lanes(x),
        Subject::Wide => {
            let (s, c) = wide::f32x8::from(x).sin_cos();
            (s.to_array(), c.to_array())
        }
    }
}

/// The f64 errors of `subject` on these inputs.
pub fn errors_f64(subject: Subject, inputs: &[f64]) -> Errors {
    let mut errors = Errors::default();
    for chunk in inputs.chunks(8) {
        let mut x = [0.0; 8];
        x[..chunk.len()].copy_from_slice(chunk);
        let (s, c) = eval_f64(subject, x);
        for i in 0..chunk.len() {
            let want = (x[i].sin(), x[i].cos());
            errors.record(x[i], (s[i], c[i]), want, ulp_f64);
        }
    }
    errors
}

/// The f32 errors of `subject` on these inputs.
pub fn errors_f32(subject: Subject, inputs: &[f32]) -> Errors {
    let mut errors = Errors::default();
    for chunk in inputs.chunks(8) {
        let mut x = [0.0; 8];
        x[..chunk.len()].copy_from_slice(chunk);
        let (s, c) = eval_f32(subject, x);
        for i in 0..chunk.len() {
            let wide = f64::from(x[i]);
            let want = (wide.sin(), wide.cos());
            errors.record(wide, (f64::from(s[i]), f64::from(c[i])), want, ulp_f32);
        }
    }
    errors
}

/// Measures `points` fixed-seed points of `range` in parallel blocks.
pub fn sweep_f64(subject: Subject, range: Range, points: u64, seed: u64) -> Errors {
    blocks(points)
        .into_par_iter()
        .map(|(block, len)| {
            let mut rng = SplitMix64::new(seed ^ block.wrapping_mul(0xd1b5_4a32_d192_ed03));
            let inputs: Vec<f64> = (0..len).map(|_| range.sampling.draw(&mut rng)).collect();
            errors_f64(subject, &inputs)
        })
        .reduce(Errors::default, Errors::merge)
}

/// Measures `points` fixed-seed points of `range` as f32 inputs.
pub fn sweep_f32(subject: Subject, range: Range, points: u64, seed: u64) -> Errors {
    blocks(points)
        .into_par_iter()
        .map(|(block, len)| {
            let mut rng = SplitMix64::new(seed ^ block.wrapping_mul(0xd1b5_4a32_d192_ed03));
            let inputs: Vec<f32> = (0..len).map(|_| range.sampling.draw(&mut rng) as f32).collect();
            errors_f32(subject, &inputs)
        })
        .reduce(Errors::default, Errors::merge)
}

/// Every f32 of magnitude from `low` to `high`, both signs (about 2.3e9 values from 0 to the f32
/// fast bound, 2^8), in parallel runs of bit patterns.
pub fn exhaustive_f32(subject: Subject, low: f32, high: f32) -> Errors {
    let bottom = u64::from(low.abs().to_bits());
    let top = u64::from(high.abs().to_bits());
    blocks(top + 1 - bottom)
        .into_par_iter()
        .map(|(block, len)| {
            let first = bottom + block * BLOCK;
            let inputs: Vec<f32> = (first..first + len)
                .flat_map(|bits| {
                    let magnitude = f32::from_bits(bits as u32);
                    [magnitude, -magnitude]
                })
                .collect();
            errors_f32(subject, &inputs)
        })
        .reduce(Errors::default, Errors::merge)
}

fn blocks(points: u64) -> Vec<(u64, u64)> {
    (0..points.div_ceil(BLOCK)).map(|b| (b, BLOCK.min(points - b * BLOCK))).collect()
}

/// Inputs where trouble hides: zeros, subnormals, multiples of pi/4 and pi/2 as f64 and their
/// neighbours, the fast bound and its neighbours, the largest finite value. (NaN and infinities
/// are checked apart: their reference is NaN.)
pub fn special_values_f64() -> Vec<f64> {
    let bound = kinematics_core::trig::FAST_BOUND;
    let mut v = vec![0.0, -0.0, f64::from_bits(1), f64::MIN_POSITIVE, f64::MIN_POSITIVE.next_down(), 1e-300, f64::MAX];
    v.extend([bound, bound.next_up(), bound.next_down(), 2.0 * bound, 1e22, 1e300]);
    let bound_f32 = kinematics_core::trig::FAST_BOUND_F32;
    v.extend([bound_f32, bound_f32.next_up(), bound_f32.next_down()].map(f64::from));
    for k in -4096..=4096 {
        for base in [f64::from(k) * core::f64::consts::FRAC_PI_4, f64::from(k) * core::f64::consts::FRAC_PI_2] {
            v.extend([base, base.next_up(), base.next_down()]);
        }
    }
    // Large multiples of pi/2, where the reduction cancels most.
    for k in [1e5, 3e5, 6.5e5, 667_000.0] {
        let base: f64 = k * core::f64::consts::FRAC_PI_2;
        v.extend([base, base.next_up(), base.next_down()]);
    }
    let negated: Vec<f64> = v.iter().map(|x| -x).collect();
    v.extend(negated);
    v
}
