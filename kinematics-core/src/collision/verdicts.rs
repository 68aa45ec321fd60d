//! Verdicts on lanes: [`LaneMask`], one bit per configuration of a lane type; [`Flags`], the same
//! kept in the lanes' shape while a check runs; and [`CheckLanes`], the comparisons and clamps a
//! collision check needs on `f64`, `f32` and the lane types.
//!
//! A comparison answers with flags, not a `bool`, so a check on eight configurations keeps eight
//! verdicts; the check loops end early when no configuration is left undecided.
//! Comparisons count NaN as a hit ([`CheckLanes::not_above`] is `!(a > b)`, true when either side
//! is NaN), and a configuration with a non-finite entry is marked colliding before any test runs.

use core::ops::{BitAnd, BitOr, Not};

use crate::lanes::{F32x8, F32x16, F64x4, F64x8, LaneValue, Lanes};
use crate::real::Real;

/// One verdict per lane: bit `i` is lane `i`'s (set: colliding). At most 32 lanes.
///
/// ```
/// use kinematics_core::collision::LaneMask;
/// let m = LaneMask::from_bits(0b0101);
/// assert!(m.lane(0) && !m.lane(1) && m.lane(2));
/// assert_eq!(m.count(), 2);
/// assert!(m.any() && !m.is_full(4) && LaneMask::full(4).is_full(4));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub struct LaneMask(u32);

impl LaneMask {
    /// No lane set.
    pub const NONE: LaneMask = LaneMask(0);

    /// The mask of these bits.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn from_bits(bits: u32) -> Self {
        LaneMask(bits)
    }

    /// Every one of `width` lanes set (`width <= 32`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn full(width: usize) -> Self {
        LaneMask(if width >= 32 { u32::MAX } else { (1u32 << width) - 1 })
    }

    /// The bits.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn bits(self) -> u32 {
        self.0
    }

    /// Lane `i`'s verdict.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn lane(self, i: usize) -> bool {
        i < 32 && (self.0 >> i) & 1 == 1
    }

    /// Whether some lane is set.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn any(self) -> bool {
        self.0 != 0
    }

    /// Whether every one of `width` lanes is set.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn is_full(self, width: usize) -> bool {
        self.0 == LaneMask::full(width).0
    }

    /// How many lanes are set.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn count(self) -> u32 {
        self.0.count_ones()
    }

    /// The lanes set here and not in `other`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn and_not(self, other: LaneMask) -> Self {
        LaneMask(self.0 & !other.0)
    }
}

impl BitOr for LaneMask {
    type Output = Self;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn bitor(self, rhs: Self) -> Self {
        LaneMask(self.0 | rhs.0)
    }
}

impl BitAnd for LaneMask {
    type Output = Self;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn bitand(self, rhs: Self) -> Self {
        LaneMask(self.0 & rhs.0)
    }
}

impl Not for LaneMask {
    type Output = Self;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn not(self) -> Self {
        LaneMask(!self.0)
    }
}

/// A mask is a value of every lane type: lane `i` of it is the `bool` of configuration `i`, so
/// the batches ([`crate::batch_wide`]) write a check's verdicts into a `&mut [bool]`.
impl<L: Lanes> LaneValue<L> for LaneMask {
    type Scalar = bool;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn lane(&self, i: usize) -> bool {
        LaneMask::lane(*self, i)
    }
}

/// Lane-wise flags, as a check combines them: one per lane, kept in the lanes' own shape (a
/// vector of all-ones or all-zeros words, the shape a lane comparison yields) so that LLVM keeps
/// every step in vector registers; [`Flags::bits`] packs them into a [`LaneMask`] once, at the end.
/// (Packing every comparison into bits as it is made scatters the lanes' arithmetic: measured
/// twice as slow on AVX-512.)
pub trait Flags: Copy + BitOr<Output = Self> + BitAnd<Output = Self> {
    /// No lane set.
    const NONE: Self;
    /// Whether some lane is set.
    fn any(self) -> bool;
    /// Whether every lane is set.
    fn all(self) -> bool;
    /// The lanes set here and not in `other`.
    fn and_not(self, other: Self) -> Self;
    /// Lane `i`'s flag as bit `i`.
    fn bits(self) -> LaneMask;
    /// The flags of the lanes set in `mask` (bits beyond the lanes ignored).
    fn from_mask(mask: LaneMask) -> Self;
}

impl Flags for bool {
    const NONE: Self = false;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn any(self) -> bool {
        self
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn all(self) -> bool {
        self
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn and_not(self, other: Self) -> Self {
        self && !other
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn bits(self) -> LaneMask {
        LaneMask(u32::from(self))
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn from_mask(mask: LaneMask) -> Self {
        mask.lane(0)
    }
}

/// When a check on lanes may stop: [`EveryLane`] when every lane is colliding (each lane's own
/// verdict), [`AnyLane`] at the first hit on any lane (one verdict shared by the pack, as a
/// planner validating a motion or a batch of states wants it).
pub(crate) trait Until: Copy {
    /// Whether the check is done with these flags (set: colliding).
    fn done<F: Flags>(hit: F) -> bool;
    /// Whether a test of the lanes `near` is done: each of them hit, or the check itself done.
    fn settled<F: Flags>(near: F, hit: F) -> bool;
}

/// Every lane its own verdict: done when all of them collide.
#[derive(Debug, Clone, Copy)]
pub(crate) struct EveryLane;

impl Until for EveryLane {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn done<F: Flags>(hit: F) -> bool {
        hit.all()
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn settled<F: Flags>(near: F, hit: F) -> bool {
        !near.and_not(hit).any()
    }
}

/// One verdict for the pack: done at the first hit on any lane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AnyLane;

impl Until for AnyLane {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn done<F: Flags>(hit: F) -> bool {
        hit.any()
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn settled<F: Flags>(_: F, hit: F) -> bool {
        hit.any()
    }
}

/// What a collision check needs of a scalar or lane type beyond [`Real`]: lane-wise clamps and a
/// comparison answering with [`Flags`]. Implemented for `f64` and `f32` (one lane, a `bool`) and
/// for [`F64x4`], [`F64x8`], [`F32x8`] and [`F32x16`].
///
/// ```
/// use kinematics_core::collision::{CheckLanes, Flags};
/// use kinematics_core::F64x4;
/// let d = F64x4::new([0.5, 2.0, f64::NAN, 1.0]);
/// // Lanes 0, 2 (NaN counts as a hit) and 3 (touching) are within 1.
/// assert_eq!(d.not_above(F64x4::new([1.0; 4])).bits().bits(), 0b1101);
/// assert_eq!(F64x4::new([0.0, f64::INFINITY, 1.0, f64::NAN]).non_finite().bits().bits(), 0b1010);
/// ```
pub trait CheckLanes: Real {
    /// One flag per lane.
    type Flags: Flags;
    /// How many lanes (1 for `f64` and `f32`).
    const WIDTH: usize;
    /// The lane-wise larger of the two (`other` where `self` is NaN).
    fn max(self, other: Self) -> Self;
    /// The lane-wise smaller of the two (`other` where `self` is NaN).
    fn min(self, other: Self) -> Self;
    /// The lane-wise absolute value.
    fn abs(self) -> Self;
    /// The lanes where `self` is not above `limit`: `self <= limit`, or either is NaN.
    fn not_above(self, limit: Self) -> Self::Flags;
    /// The lanes holding a NaN or an infinity.
    fn non_finite(self) -> Self::Flags;
    /// Lane `i` (`i < WIDTH`) as an `f64`: for tests a check makes one lane at a time.
    fn lane_f64(self, i: usize) -> f64;
    /// The lane-wise square root (the hardware's with `std`, libm's without: both correctly
    /// rounded).
    fn sqrt(self) -> Self;
    /// `then` in the lanes of `flags`, `otherwise` in the others (a select, not a branch).
    fn select(flags: Self::Flags, then: Self, otherwise: Self) -> Self;
    /// The lanes `f(0)`, `f(1)`, ... (rounded to `f32` for the `f32` types): for what is asked
    /// one lane at a time.
    fn from_lanes(f: impl FnMut(usize) -> f64) -> Self;
}

// The square roots: the hardware's with `std`, libm's without.
use crate::real::{square_root as root64, square_root_f32 as root32};

macro_rules! scalar_check {
    ($t:ty, $root:ident) => {
        impl CheckLanes for $t {
            type Flags = bool;
            const WIDTH: usize = 1;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn max(self, other: Self) -> Self {
                if self > other { self } else { other }
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn min(self, other: Self) -> Self {
                if self < other { self } else { other }
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn abs(self) -> Self {
                if self < 0.0 { -self } else { self }
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn not_above(self, limit: Self) -> bool {
                // Not above: below, equal, or unordered (a NaN on either side).
                self.partial_cmp(&limit) != Some(core::cmp::Ordering::Greater)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn non_finite(self) -> bool {
                !self.is_finite()
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn lane_f64(self, _: usize) -> f64 {
                f64::from(self)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn sqrt(self) -> Self {
                $root(self)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn select(flags: bool, then: Self, otherwise: Self) -> Self {
                if flags { then } else { otherwise }
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            #[allow(clippy::cast_possible_truncation, reason = "f32 lanes take f32's rounding")]
            fn from_lanes(mut f: impl FnMut(usize) -> f64) -> Self {
                f(0) as $t
            }
        }
    };
}

scalar_check!(f64, root64);
scalar_check!(f32, root32);

// Written as loops over the lanes (no early exits, no calls) so LLVM packs each into one
// instruction of the width the function is compiled for.
macro_rules! lane_check {
    ($name:ident, $flags:ident, $word:ty, $signed:ty, $lanes:literal, $root:ident, $doc:literal) => {
        #[doc = $doc]
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        #[repr(C, align(64))]
        pub struct $flags([$word; $lanes]);

        impl BitOr for $flags {
            type Output = Self;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn bitor(self, rhs: Self) -> Self {
                let mut out = self.0;
                for i in 0..$lanes {
                    out[i] |= rhs.0[i];
                }
                $flags(out)
            }
        }

        impl BitAnd for $flags {
            type Output = Self;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn bitand(self, rhs: Self) -> Self {
                let mut out = self.0;
                for i in 0..$lanes {
                    out[i] &= rhs.0[i];
                }
                $flags(out)
            }
        }

        impl Flags for $flags {
            const NONE: Self = $flags([0; $lanes]);
            // Through the packed bits: an OR (AND) over the words instead became a chain of
            // shuffles in 4-lane pieces that LLVM then spread to the whole check's arithmetic
            // (measured: the Panda's obstacle check in F32x16 lanes took twice as long).
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn any(self) -> bool {
                self.bits().any()
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn all(self) -> bool {
                self.bits().is_full($lanes)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn and_not(self, other: Self) -> Self {
                let mut out = self.0;
                for i in 0..$lanes {
                    out[i] &= !other.0[i];
                }
                $flags(out)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn bits(self) -> LaneMask {
                // Each word is all ones or all zeros: its low bit is the flag. (Written as
                // `word != 0`, the packing made LLVM split the whole check's lanes into pieces:
                // measured 2x slower on AVX-512.)
                let mut bits = 0u32;
                for i in 0..$lanes {
                    bits |= ((self.0[i] & 1) as u32) << i;
                }
                LaneMask(bits)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn from_mask(mask: LaneMask) -> Self {
                let mut out = [0; $lanes];
                for i in 0..$lanes {
                    out[i] = if mask.lane(i) { <$word>::MAX } else { 0 };
                }
                $flags(out)
            }
        }

        impl CheckLanes for $name {
            type Flags = $flags;
            const WIDTH: usize = $lanes;
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn max(self, other: Self) -> Self {
                let mut out = other.0;
                for i in 0..$lanes {
                    if self.0[i] > other.0[i] {
                        out[i] = self.0[i];
                    }
                }
                $name(out)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn min(self, other: Self) -> Self {
                let mut out = other.0;
                for i in 0..$lanes {
                    if self.0[i] < other.0[i] {
                        out[i] = self.0[i];
                    }
                }
                $name(out)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn abs(self) -> Self {
                let mut out = self.0;
                for x in &mut out {
                    *x = x.abs();
                }
                $name(out)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn not_above(self, limit: Self) -> $flags {
                let mut out = [0; $lanes];
                for i in 0..$lanes {
                    out[i] = if self.0[i] > limit.0[i] { 0 } else { <$word>::MAX };
                }
                $flags(out)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn non_finite(self) -> $flags {
                let mut out = [0; $lanes];
                for i in 0..$lanes {
                    out[i] = if self.0[i].is_finite() { 0 } else { <$word>::MAX };
                }
                $flags(out)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn lane_f64(self, i: usize) -> f64 {
                f64::from(self.0[i])
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn sqrt(self) -> Self {
                let mut out = self.0;
                for x in &mut out {
                    *x = $root(*x);
                }
                $name(out)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn select(flags: $flags, then: Self, otherwise: Self) -> Self {
                let mut out = otherwise.0;
                for i in 0..$lanes {
                    if flags.0[i] & 1 == 1 {
                        out[i] = then.0[i];
                    }
                }
                $name(out)
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            #[allow(clippy::cast_possible_truncation, reason = "f32 lanes take f32's rounding")]
            fn from_lanes(mut f: impl FnMut(usize) -> f64) -> Self {
                let mut out = [0.0; $lanes];
                for (i, x) in out.iter_mut().enumerate() {
                    *x = f(i) as _;
                }
                $name(out)
            }
        }
    };
}

lane_check!(F64x4, Flags64x4, u64, i64, 4, root64, "The flags of [`F64x4`]'s lanes.");
lane_check!(F64x8, Flags64x8, u64, i64, 8, root64, "The flags of [`F64x8`]'s lanes.");
lane_check!(F32x8, Flags32x8, u32, i32, 8, root32, "The flags of [`F32x8`]'s lanes.");
lane_check!(F32x16, Flags32x16, u32, i32, 16, root32, "The flags of [`F32x16`]'s lanes.");

/// The lanes of `q` with a NaN or an infinite entry: configurations that are never free.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn non_finite<L: CheckLanes, const N: usize>(q: &[L; N]) -> L::Flags {
    non_finite_entries(q)
}

/// [`non_finite`] of a configuration given as a slice.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn non_finite_entries<L: CheckLanes>(q: &[L]) -> L::Flags {
    let mut bad = L::Flags::NONE;
    for x in q {
        bad = bad | x.non_finite();
    }
    bad
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_compare_as_their_scalars_do() {
        let a = [0.5, -2.0, f64::NAN, 1.0, 3.0, -0.0, f64::INFINITY, 7.0];
        let b = [1.0, -3.0, 0.0, 1.0, f64::NAN, 0.0, 1.0, 8.0];
        let (x, y) = (F64x8::new(a), F64x8::new(b));
        let m = x.not_above(y).bits();
        for i in 0..8 {
            assert_eq!(m.lane(i), a[i].not_above(b[i]), "lane {i}");
            assert_eq!(x.max(y).0[i].to_bits(), CheckLanes::max(a[i], b[i]).to_bits(), "max lane {i}");
            assert_eq!(x.min(y).0[i].to_bits(), CheckLanes::min(a[i], b[i]).to_bits(), "min lane {i}");
        }
        assert_eq!(F32x16::splat(-1.5).abs(), F32x16::splat(1.5));
        let q = [F64x4::new([0.0, 1.0, f64::NAN, 2.0]), F64x4::new([f64::INFINITY, 0.0, 0.0, 0.0])];
        assert_eq!(non_finite(&q).bits().bits(), 0b0101);
        let (some, none) =
            (F32x16::splat(0.0).not_above(F32x16::splat(1.0)), F32x16::splat(2.0).not_above(F32x16::splat(1.0)));
        assert!(some.all() && some.any() && !none.any() && !none.all() && (some & none) == Flags32x16::NONE);
        assert_eq!(some.and_not(none).bits(), LaneMask::full(16));
        assert!(LaneMask::full(32).is_full(32) && LaneMask::full(16).count() == 16);
        assert_eq!(Flags64x4::from_mask(LaneMask::from_bits(0b1_0110)).bits().bits(), 0b0110);
        assert_eq!(F32x8::from_fn(|i| i as f32).lane_f64(5), 5.0);
    }
}
