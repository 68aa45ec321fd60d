//! The arithmetic a compiled closed form needs beyond [`Real`]: square roots, `atan2` and a
//! select, for `f64` and for the `f64` lane types.
//!
//! The compiler emits a family's solution as one straight-line body generic over [`IkReal`],
//! evaluating one branch; the branch is chosen by signs passed in as values (`+1` or `-1` per
//! binary choice: which root of the first subproblem, of the second, of the third). Called with
//! [`F64x8`] and [`BRANCH_SIGNS_8`], the body computes all eight branches side by side, one per
//! lane, with no branch in the code: an equation without a real solution in one lane selects its
//! least-squares answer there and flags it, while the other lanes go on.
//!
//! ```
//! use kinematics_core::ik::{BRANCH_SIGNS_8, IkReal};
//! use kinematics_core::{F64x8, Real};
//! // The two angles whose cosine is 0.5, as a compiled body writes them: the sign picks the root.
//! fn root<T: IkReal>(sign: T) -> T {
//!     let sine = T::sqrt(T::from_f64(0.75));
//!     T::atan2(sign * sine, T::from_f64(0.5))
//! }
//! let angles = root(BRANCH_SIGNS_8[2]);
//! assert!((angles.lane(0) - core::f64::consts::FRAC_PI_3).abs() < 1e-15);
//! assert!((angles.lane(1) + core::f64::consts::FRAC_PI_3).abs() < 1e-15);
//! assert_eq!(angles.lane(1).to_bits(), root(-1.0f64).to_bits());
//! ```
//!
//! `IkReal` is implemented for `f64`, `F64x4` and `F64x8`, every lane bit for bit the scalar's
//! (square root, our `atan2`, a lane-wise select). `IkBranch` is what a compiled body returns;
//! `BRANCH_SIGNS_8` are the branch signs as lanes.

use crate::lanes::{F64x4, F64x8};
use crate::real::{Real, square_root};
use crate::trig;

/// What compiled closed-form inverse kinematics computes with: [`Real`] and a square root, our
/// `atan2` ([`trig::atan2`], within 2 ulp of libm's) and a lane-wise select. Every lane of a lane
/// type gives bit for bit what `f64` gives for that lane's values.
pub trait IkReal: Real {
    /// The square root (correctly rounded; NaN below zero, which compiled bodies never take: they
    /// clamp first).
    fn sqrt(self) -> Self;
    /// `atan2(self, x)`: the angle of `(x, self)` in `[-pi, pi]`.
    fn atan2(self, x: Self) -> Self;
    /// `then` where `self > 0`, else `otherwise`, lane by lane (a select, not a branch).
    fn if_positive(self, then: Self, otherwise: Self) -> Self;
}

impl IkReal for f64 {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sqrt(self) -> Self {
        square_root(self)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn atan2(self, x: Self) -> Self {
        trig::atan2(self, x)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn if_positive(self, then: Self, otherwise: Self) -> Self {
        if self > 0.0 { then } else { otherwise }
    }
}

// Lane by lane written out, not as loops (see `crate::lanes`).
macro_rules! ik_lanes {
    ($name:ident, [$($i:literal),*]) => {
        impl IkReal for $name {
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn sqrt(self) -> Self {
                let a = self.0;
                $name([$(square_root(a[$i])),*])
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn atan2(self, x: Self) -> Self {
                $name(trig::atan2_f64_lanes(self.0, x.0))
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn if_positive(self, then: Self, otherwise: Self) -> Self {
                let (x, a, b) = (self.0, then.0, otherwise.0);
                $name([$(if x[$i] > 0.0 { a[$i] } else { b[$i] }),*])
            }
        }
    };
}

ik_lanes!(F64x4, [0, 1, 2, 3]);
ik_lanes!(F64x8, [0, 1, 2, 3, 4, 5, 6, 7]);

/// One branch of a compiled closed form, as its generic body returns it (for a lane type, one
/// branch per lane): the joint values, each joint's cosine and sine (`1` and `0` for a prismatic
/// joint), and the flags as numbers (`1` true, `0` false).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkBranch<T, const N: usize> {
    /// Joint values (revolute angles in `(-pi, pi]`).
    pub q: [T; N],
    /// Each joint's cosine, as the solver computed it (`q` is the `atan2` of it and the sine).
    pub cos: [T; N],
    /// Each joint's sine.
    pub sin: [T; N],
    /// `1` where every equation had a real solution, else `0` (the least-squares best).
    pub exact: T,
    /// `1` where some joint was free (a singularity), else `0`.
    pub singular: T,
}

impl<L: crate::lanes::Lanes<Scalar = f64>, const N: usize> IkBranch<L, N> {
    /// Whether some lane is singular and not exact: a branch at a singularity whose equations
    /// missed, which a body's pass at that singularity may still solve (the generated `tip_ik`
    /// runs the full body again then).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn misses_at_a_singularity(&self) -> bool {
        let mut missed = false;
        for lane in 0..L::LANES {
            missed |= self.singular.lane(lane) == 1.0 && self.exact.lane(lane) != 1.0;
        }
        missed
    }
}

/// The branch signs of eight branches, one per lane of [`F64x8`]: lane `i` takes the first
/// choice's `+` root when bit 2 of `i` is clear, the second's when bit 1 is, the third's when bit 0
/// is, so the lanes run in the order of three nested loops over the roots, `+` first.
pub const BRANCH_SIGNS_8: [F64x8; 3] = [
    F64x8::new([1.0, 1.0, 1.0, 1.0, -1.0, -1.0, -1.0, -1.0]),
    F64x8::new([1.0, 1.0, -1.0, -1.0, 1.0, 1.0, -1.0, -1.0]),
    F64x8::new([1.0, -1.0, 1.0, -1.0, 1.0, -1.0, 1.0, -1.0]),
];

/// The branch signs of branch `index` (`0..8`, the lane order of [`BRANCH_SIGNS_8`]) as `f64`.
pub const fn branch_signs(index: usize) -> [f64; 3] {
    const fn sign(index: usize, bit: usize) -> f64 {
        if index & bit == 0 { 1.0 } else { -1.0 }
    }
    [sign(index, 4), sign(index, 2), sign(index, 1)]
}

/// Branches `4 * half .. 4 * half + 4` of [`BRANCH_SIGNS_8`] in the lanes of [`F64x4`] (`half`
/// 0 or 1): the eight branches in two calls.
pub const fn branch_signs_4(half: usize) -> [F64x4; 3] {
    let mut signs = [[0.0; 4]; 3];
    let mut lane = 0;
    while lane < 4 {
        let branch = branch_signs(4 * half + lane);
        let mut k = 0;
        while k < 3 {
            signs[k][lane] = branch[k];
            k += 1;
        }
        lane += 1;
    }
    [F64x4::new(signs[0]), F64x4::new(signs[1]), F64x4::new(signs[2])]
}

/// A target pose in every lane.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn splat_pose<L: crate::lanes::Lanes<Scalar = f64>>(pose: &crate::pose::Pose<f64>) -> crate::pose::Pose<L> {
    let r = &pose.rotation;
    let t = &pose.translation;
    let s = |x: f64| L::from_fn(|_| x);
    crate::pose::Pose {
        rotation: [
            [s(r[0][0]), s(r[0][1]), s(r[0][2])],
            [s(r[1][0]), s(r[1][1]), s(r[1][2])],
            [s(r[2][0]), s(r[2][1]), s(r[2][2])],
        ],
        translation: [s(t[0]), s(t[1]), s(t[2])],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn branch_signs_agree_in_every_form() {
        for branch in 0..8 {
            let signs = branch_signs(branch);
            let half = branch_signs_4(branch / 4);
            for k in 0..3 {
                assert_eq!(BRANCH_SIGNS_8[k].lane(branch), signs[k]);
                assert_eq!(half[k].lane(branch % 4), signs[k]);
            }
        }
    }

    #[test]
    fn lanes_are_the_scalar_bit_for_bit() {
        let values = [0.0, -0.0, 1e-300, 2.0, -3.5, 1e10, f64::INFINITY, 0.25];
        let y = F64x8::new(values);
        let x = F64x8::new([1.0, -1.0, -0.0, 2.0, 0.5, -1e-10, 3.0, -0.25]);
        let (roots, angles, picked) = (y.sqrt(), y.atan2(x), (y - F64x8::splat(1.0)).if_positive(y, x));
        for (i, &value) in values.iter().enumerate() {
            let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
            assert!(same(roots.lane(i), IkReal::sqrt(value)), "sqrt lane {i}");
            assert!(same(angles.lane(i), IkReal::atan2(value, x.lane(i))), "atan2 lane {i}");
            assert!(same(picked.lane(i), (value - 1.0).if_positive(value, x.lane(i))), "select lane {i}");
        }
    }
}
