//! SIMD lane types: several configurations side by side in one value, on stable Rust.
//!
//! [`F64x4`] holds four `f64`, [`F32x8`] eight `f32`; [`F64x8`] and [`F32x16`], twice as many, fill
//! an AVX-512 register (the generated batches take `F64x8` where the CPU has AVX-512; `f32` stays in
//! [`F32x8`], measured faster, see the guide's Lanes page). They are plain arrays with lane-wise
//! arithmetic written out lane by lane, which LLVM turns into packed instructions (AVX2
//! `ymm` registers with `-C target-cpu=native` on a machine that has them, pairs of SSE2 `xmm`
//! registers on baseline x86-64); their sines and cosines are [`crate::trig`]'s lane routines. They
//! implement [`Real`], so the very code generated for `f64` evaluates four (or eight)
//! configurations per call:
//!
//! ```
//! use kinematics_core::{F64x4, Real};
//! // Any function generic over `Real`, such as a derived robot's `tip_pose_generic`:
//! fn planar_2r_x<T: Real>(q: &[T; 2]) -> T {
//!     let (sines, cosines) = T::sin_cos_many([q[0], q[0] + q[1]]);
//!     let _ = sines;
//!     cosines[0] + cosines[1]
//! }
//! let q = [F64x4::new([0.0, 0.5, 1.0, 1.5]), F64x4::splat(0.25)];
//! let x = planar_2r_x(&q);
//! for lane in 0..4 {
//!     assert_eq!(x.lane(lane), planar_2r_x(&[q[0].lane(lane), q[1].lane(lane)]));
//! }
//! ```
//!
//! The `Lanes` and `LaneValue` traits describe them to the batch drivers and the checks.

use core::ops::{Add, Div, Mul, Neg, Sub};

use crate::pose::Pose;
use crate::real::Real;
use crate::trig;

/// A type of several scalar lanes, each an independent value.
pub trait Lanes: Real {
    /// The type of one lane.
    type Scalar: Copy;
    /// How many lanes.
    const LANES: usize;
    /// The value whose lane `i` is `f(i)`.
    fn from_fn(f: impl FnMut(usize) -> Self::Scalar) -> Self;
    /// Lane `i` (`i < LANES`). By reference: a value in memory gives its lane by one load,
    /// where a copy of it would be stored again first (measured in the batches' unpacking).
    fn lane(&self, i: usize) -> Self::Scalar;
}

/// A value made of lanes (a number, a pose, an array of them) from which one lane's value can be
/// taken: the outputs of generated code evaluated on a lane type.
pub trait LaneValue<L: Lanes> {
    /// The same value for one lane (`Pose<f64>` for `Pose<F64x4>`).
    type Scalar;
    /// Lane `i`.
    fn lane(&self, i: usize) -> Self::Scalar;
    /// Lanes `0..out.len()` into `out` (`out.len() <= L::LANES`), entry by entry: what a batch
    /// writes for each pack. The default takes each lane's whole value ([`LaneValue::lane`]);
    /// arrays and poses write each entry of every lane in place, read from the value where it
    /// lies, so no lane's value is built whole and then copied (measured on the Panda's batches
    /// in `F32x16` lanes: all link poses 2.4x faster, the sphere centres 1.4x).
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn write_lanes(&self, out: &mut [Self::Scalar]) {
        for (i, slot) in out.iter_mut().enumerate() {
            self.write_lane(i, slot);
        }
    }
    /// Lane `i` into `out`, entry by entry where the value has entries.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn write_lane(&self, i: usize, out: &mut Self::Scalar) {
        *out = self.lane(i);
    }
}

// No `array::map` or `array::from_fn` below, nor in anything a batch runs: they are calls LLVM
// does not always inline, and a batch dispatched to AVX2 (`batch`) must be one function, or the
// calls run without AVX2 (measured: batches slower than the scalar loop).

impl<L: Lanes> LaneValue<L> for Pose<L> {
    type Scalar = Pose<L::Scalar>;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn lane(&self, i: usize) -> Self::Scalar {
        let r = &self.rotation;
        let t = &self.translation;
        Pose {
            rotation: [
                [r[0][0].lane(i), r[0][1].lane(i), r[0][2].lane(i)],
                [r[1][0].lane(i), r[1][1].lane(i), r[1][2].lane(i)],
                [r[2][0].lane(i), r[2][1].lane(i), r[2][2].lane(i)],
            ],
            translation: [t[0].lane(i), t[1].lane(i), t[2].lane(i)],
        }
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn write_lane(&self, i: usize, out: &mut Self::Scalar) {
        for row in 0..3 {
            for column in 0..3 {
                out.rotation[row][column] = self.rotation[row][column].lane(i);
            }
        }
        for axis in 0..3 {
            out.translation[axis] = self.translation[axis].lane(i);
        }
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn write_lanes(&self, out: &mut [Self::Scalar]) {
        // Entry by entry, each entry's lanes one after another.
        for row in 0..3 {
            for column in 0..3 {
                let entry = &self.rotation[row][column];
                for (i, pose) in out.iter_mut().enumerate() {
                    pose.rotation[row][column] = entry.lane(i);
                }
            }
        }
        for axis in 0..3 {
            let entry = &self.translation[axis];
            for (i, pose) in out.iter_mut().enumerate() {
                pose.translation[axis] = entry.lane(i);
            }
        }
    }
}

impl<L: Lanes, V: LaneValue<L>, const M: usize> LaneValue<L> for [V; M]
where
    V::Scalar: Copy,
{
    type Scalar = [V::Scalar; M];
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn lane(&self, i: usize) -> Self::Scalar {
        let Some(first) = self.first() else {
            // M = 0 (a robot with no link but its base): nothing to take.
            return core::array::from_fn(|k| self[k].lane(i));
        };
        let mut out = [first.lane(i); M];
        for k in 1..M {
            out[k] = self[k].lane(i);
        }
        out
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn write_lanes(&self, out: &mut [Self::Scalar]) {
        // Entry by entry, each entry's lanes one after another.
        for k in 0..M {
            for (i, slot) in out.iter_mut().enumerate() {
                self[k].write_lane(i, &mut slot[k]);
            }
        }
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn write_lane(&self, i: usize, out: &mut Self::Scalar) {
        for k in 0..M {
            self[k].write_lane(i, &mut out[k]);
        }
    }
}

/// A pose with its Jacobian (`tip_pose_and_jacobian`), or any pair of lane values.
impl<L: Lanes, A: LaneValue<L>, B: LaneValue<L>> LaneValue<L> for (A, B) {
    type Scalar = (A::Scalar, B::Scalar);
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn lane(&self, i: usize) -> Self::Scalar {
        (self.0.lane(i), self.1.lane(i))
    }
}

// The arithmetic is written out lane by lane (`[a[0] + b[0], a[1] + b[1], ...]`, the lane
// indices given), not as a loop over the lanes: a generated body is thousands of these operations
// in one function, and as loops each was a loop for LLVM's loop passes to rotate and unroll, which
// took most of an optimised build (a crate calling the spherized Panda's `collides_batch_f32`:
// 15.2 s, of which LLVM's loop rotation 6.5 s and full unrolling 3.7 s by `-Z llvm-time-trace`;
// 5.5 s written out). The straight-line lanes vectorize as the unrolled loops did.
macro_rules! lane_type {
    ($name:ident, $scalar:ident, $lanes:literal, [$($i:literal),*], $align:literal, $sin_cos:path, marks = $marks:literal, $doc:literal $(, many = $sin_cos_many:path)?) => {
        #[doc = $doc]
        #[derive(Debug, Clone, Copy, PartialEq)]
        #[repr(C, align($align))]
        pub struct $name(pub [$scalar; $lanes]);

        impl $name {
            /// The lanes given.
            #[cfg_attr(not(debug_assertions), inline(always))]
            pub const fn new(lanes: [$scalar; $lanes]) -> Self {
                $name(lanes)
            }
            /// Every lane `x`.
            #[cfg_attr(not(debug_assertions), inline(always))]
            pub const fn splat(x: $scalar) -> Self {
                $name([x; $lanes])
            }
            /// Lane `i`.
            #[cfg_attr(not(debug_assertions), inline(always))]
            pub const fn lane(self, i: usize) -> $scalar {
                self.0[i]
            }
            /// The lanes as an array.
            #[cfg_attr(not(debug_assertions), inline(always))]
            pub const fn to_array(self) -> [$scalar; $lanes] {
                self.0
            }
        }

        impl Add for $name {
            type Output = Self;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn add(self, rhs: Self) -> Self {
                let (a, b) = (self.0, rhs.0);
                $name([$(a[$i] + b[$i]),*])
            }
        }

        impl Sub for $name {
            type Output = Self;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn sub(self, rhs: Self) -> Self {
                let (a, b) = (self.0, rhs.0);
                $name([$(a[$i] - b[$i]),*])
            }
        }

        impl Mul for $name {
            type Output = Self;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn mul(self, rhs: Self) -> Self {
                let (a, b) = (self.0, rhs.0);
                $name([$(a[$i] * b[$i]),*])
            }
        }

        impl Div for $name {
            type Output = Self;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn div(self, rhs: Self) -> Self {
                let (a, b) = (self.0, rhs.0);
                $name([$(a[$i] / b[$i]),*])
            }
        }

        impl Neg for $name {
            type Output = Self;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn neg(self) -> Self {
                let a = self.0;
                $name([$(-a[$i]),*])
            }
        }

        impl Real for $name {
            const BLOCK_MARKS: Option<usize> = Some($marks);
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn from_f64(x: f64) -> Self {
                $name::splat(<$scalar as Real>::from_f64(x))
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn sin_cos(self) -> (Self, Self) {
                let (s, c) = $sin_cos(self.0);
                ($name(s), $name(c))
            }
            $(
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn sin_cos_many<const M: usize>(x: [Self; M]) -> ([Self; M], [Self; M]) {
                let (s, c) = $sin_cos_many(x.map(|v| v.0));
                (s.map($name), c.map($name))
            }
            )?
        }

        impl Lanes for $name {
            type Scalar = $scalar;
            const LANES: usize = $lanes;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn from_fn(mut f: impl FnMut(usize) -> $scalar) -> Self {
                let mut lanes = [0.0; $lanes];
                for (i, lane) in lanes.iter_mut().enumerate() {
                    *lane = f(i);
                }
                $name(lanes)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn lane(&self, i: usize) -> $scalar {
                self.0[i]
            }
        }

        impl LaneValue<$name> for $name {
            type Scalar = $scalar;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn lane(&self, i: usize) -> $scalar {
                self.0[i]
            }
        }

        #[cfg(feature = "std")]
        impl crate::real::StdTrig for $name {
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn sin_cos_std(self) -> (Self, Self) {
                let mut s = self.0;
                let mut c = self.0;
                for i in 0..$lanes {
                    (s[i], c[i]) = crate::real::StdTrig::sin_cos_std(self.0[i]);
                }
                ($name(s), $name(c))
            }
        }
    };
}

// Each type's block marks (`Real::BLOCK_MARKS`, a mark about every 75 operations), measured in a
// scratch harness on the Panda's 59 sphere centres (526 operations; a dispatched loop over 1,024
// configurations, AVX2 without AVX-512, 2026-11-28), ns a configuration against the body without
// marks: `F64x4` best without them (59; a block every 150 or 300 operations 75 and 68), so a block
// of 600; `F32x8` every 300 (38 against 140 without; 150 took 42); `F64x8` and `F32x16`, twice
// the lanes, every 150 (72 against 215, and 300 took 129; 44 to 58 against 230).
lane_type!(
    F64x4,
    f64,
    4,
    [0, 1, 2, 3],
    32,
    trig::sin_cos_f64_lanes,
    marks = 8,
    "Four `f64` lanes (one AVX2 register)."
);
lane_type!(
    F32x8,
    f32,
    8,
    [0, 1, 2, 3, 4, 5, 6, 7],
    32,
    trig::sin_cos_f32_lanes,
    marks = 4,
    "Eight `f32` lanes (one AVX2 register)."
);
lane_type!(
    F64x8,
    f64,
    8,
    [0, 1, 2, 3, 4, 5, 6, 7],
    64,
    trig::sin_cos_packed,
    marks = 2,
    "Eight `f64` lanes (one AVX-512 register; the batches use it where the CPU has AVX-512).",
    many = trig::sin_cos_packed_many
);
lane_type!(
    F32x16,
    f32,
    16,
    [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15],
    64,
    trig::sin_cos_packed,
    marks = 2,
    "Sixteen `f32` lanes (one AVX-512 register): the generated collision checks' batches and motions take `f32` \
     in them under AVX-512; the other batches keep `F32x8`, which LLVM vectorizes where it leaves many bodies on \
     sixteen lanes in scalar pieces (the guide's Lanes page).",
    many = trig::sin_cos_packed_many
);

#[cfg(test)]
mod tests {
    use super::*;

    /// Every lane type's sines and cosines of several values, whichever routine it takes, are each
    /// lane's scalar ones bit for bit, slow-path values (beyond the bound, NaN) among them.
    #[test]
    fn lane_sines_and_cosines_are_each_lanes_scalar_ones() {
        fn check<L, F>(scalar: F)
        where
            L: Lanes + Real,
            L::Scalar: Real + Into<f64>,
            F: Fn(L::Scalar) -> (L::Scalar, L::Scalar),
        {
            let values = [0.3, -2.5, 1e7, f64::NAN, -0.0, 100.0, 3.0, -1e4, f64::INFINITY];
            let x: [L; 3] =
                core::array::from_fn(|m| L::from_fn(|i| L::Scalar::from_f64(values[(4 * m + i) % values.len()])));
            let (s, c) = L::sin_cos_many(x);
            for m in 0..3 {
                for i in 0..L::LANES {
                    let (ss, sc) = scalar(x[m].lane(i));
                    let bits = |v: L::Scalar| v.into().to_bits();
                    assert_eq!((bits(s[m].lane(i)), bits(c[m].lane(i))), (bits(ss), bits(sc)));
                }
            }
        }
        check::<F64x4, _>(trig::sin_cos_f64);
        check::<F64x8, _>(trig::sin_cos_f64);
        check::<F32x8, _>(trig::sin_cos_f32);
        check::<F32x16, _>(trig::sin_cos_f32);
    }

    /// A pack's values written entry by entry (`write_lanes`, as the batches unpack them) are each
    /// lane's own value (`lane`), for poses, arrays of them, arrays of arrays, pairs and masks;
    /// a short output (the last pack of a batch) takes the first lanes and nothing past them.
    #[test]
    fn written_lanes_are_each_lanes_value() {
        let x = |k: usize| F32x16::from_fn(|i| (100 * k + i) as f32);
        let pose = |k: usize| Pose {
            rotation: [[x(k), x(k + 1), x(k + 2)], [x(k + 3), x(k + 4), x(k + 5)], [x(k + 6), x(k + 7), x(k + 8)]],
            translation: [x(k + 9), x(k + 10), x(k + 11)],
        };
        let poses = [pose(0), pose(20), pose(40)];
        let centers = [[x(1), x(2), x(3)], [x(4), x(5), x(6)]];
        let pair = (pose(7), x(9));
        for count in [16, 5, 1] {
            let zero = Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] };
            let mut out = [[zero; 3]; 16];
            poses.write_lanes(&mut out[..count]);
            let mut out_centers = [[[0.0_f32; 3]; 2]; 16];
            centers.write_lanes(&mut out_centers[..count]);
            let mut out_pair = [(zero, 0.0_f32); 16];
            pair.write_lanes(&mut out_pair[..count]);
            for i in 0..16 {
                let written = i < count;
                assert_eq!(out[i] == LaneValue::lane(&poses, i), written, "poses, lane {i} of {count}");
                assert_eq!(out_centers[i] == LaneValue::lane(&centers, i), written, "centres, lane {i} of {count}");
                assert_eq!(out_pair[i] == LaneValue::lane(&pair, i), written, "pair, lane {i} of {count}");
            }
            let mut one = zero;
            pose(3).write_lane(7, &mut one);
            assert_eq!(one, pose(3).lane(7));
            // A mask's lanes as verdicts; past the output's end, whatever was there stays.
            let mask = crate::collision::LaneMask::from_bits(0b1010_0110_0001_1011);
            for before in [false, true] {
                let mut verdicts = [before; 16];
                LaneValue::<F32x16>::write_lanes(&mask, &mut verdicts[..count]);
                for (i, &verdict) in verdicts.iter().enumerate() {
                    let expected = if i < count { mask.lane(i) } else { before };
                    assert_eq!(verdict, expected, "mask, lane {i} of {count}");
                }
            }
        }
    }
}
