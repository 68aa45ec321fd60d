//! The scalar trait generated code is written against.
//!
//! Generated functions are generic over [`Real`], so one body serves `f64`, `f32`, the SIMD lane
//! types ([`F64x4`](crate::F64x4), [`F32x8`](crate::F32x8)) and any number type a user brings
//! (dual numbers for derivatives, intervals). It asks only what the code uses: `+ - * /`,
//! negation, constants and sines and cosines (division only normalises a floating joint's
//! quaternion). No ordering, no `'static`, no conversion back to `f64`: a
//! packed lane type cannot honestly give those.
//!
//! `Real` asks for `Copy`, `+ - *`, negation, `from_f64`, `sin_cos` and `sin_cos_many` (the angles
//! of a function computed together): nothing a lane type cannot give. `BLOCK_MARKS` and
//! `block_mark` (where a lane type ends a block of long straight-line code) have defaults that
//! ignore the marks. With `std`, `StdTrig` gives the platform's `sin_cos`, for `trig = "std"`.

use core::ops::{Add, Div, Mul, Neg, Sub};

use crate::trig;

/// The arithmetic generated forward kinematics needs: `+ - * /`, negation, constants and `sin_cos`.
///
/// ```
/// use kinematics_core::Real;
/// fn double<T: Real>(x: T) -> T { T::from_f64(2.0) * x }
/// assert_eq!(double(1.5f32), 3.0);
/// let (s, c) = Real::sin_cos(0.5f64);
/// assert!((s - 0.479425538604203).abs() < 1e-15 && (c - 0.8775825618903728).abs() < 1e-15);
/// let (sines, cosines) = f64::sin_cos_many([0.0, 0.5]);
/// assert_eq!((sines[1], cosines[1]), (s, c));
/// ```
pub trait Real:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Neg<Output = Self>
{
    /// A constant of the robot (rounded to nearest for `f32`).
    fn from_f64(x: f64) -> Self;

    /// `(sin x, cos x)`.
    fn sin_cos(self) -> (Self, Self);

    /// The sines and the cosines of `N` angles, computed together.
    ///
    /// Generated code asks for every angle of a pose in one call, so a type can compute them side
    /// by side (for `f64` and `f32`, packed into SIMD registers). The default calls
    /// [`Real::sin_cos`] on each.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_many<const N: usize>(x: [Self; N]) -> ([Self; N], [Self; N]) {
        let mut sines = x;
        let mut cosines = x;
        for i in 0..N {
            (sines[i], cosines[i]) = x[i].sin_cos();
        }
        (sines, cosines)
    }

    /// How many of straight-line code's block marks make one block for this type: `None` (the
    /// default, and `f64`'s and `f32`'s) ignores the marks.
    ///
    /// Generated bodies of many statements (poses, Jacobians, sphere centres) call [`Real::block_mark`] about
    /// every [`BLOCK_MARK_OPS`] operations. A lane type's operations are written out lane by lane,
    /// which LLVM's SLP vectorizer turns into vector instructions, and it schedules one block
    /// of code at a time within a budget: a block of a few thousand lane operations exceeds it, and
    /// then runs in scalar pieces. A branch every few hundred operations keeps each block within
    /// the budget (see [`Real::block_mark`]).
    const BLOCK_MARKS: Option<usize> = None;

    /// Block mark `mark` (numbered from 1) of straight-line code: every
    /// [`BLOCK_MARKS`](Real::BLOCK_MARKS)-th ends the block there, by a branch on a value the
    /// optimiser cannot see (always false). It computes nothing; the values stay in registers.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn block_mark(mark: usize) {
        if let Some(every) = Self::BLOCK_MARKS
            && mark.is_multiple_of(every)
        {
            end_block();
        }
    }
}

/// About how many operations generated straight-line code puts between two block marks
/// ([`Real::block_mark`]): a mark follows the first statement that reaches it.
pub const BLOCK_MARK_OPS: usize = 75;

/// Runs one chunk of generated straight-line code, `f`: a call of its own in a debug build
/// (`debug_assertions`), always inlined otherwise.
///
/// Why: without optimisation every `let` and every temporary of a function keeps its own stack
/// slot for the whole call, and an always-inlined callee's slots join its caller's. A robot's
/// body of thousands of lane operations (each slot 32 to 64 bytes) then needed megabytes of a
/// debug build's stack, more than a test thread has. A generated body's form for debug builds
/// puts each stretch between two block marks ([`BLOCK_MARK_OPS`]) in a closure run by `chunk`,
/// which returns what the stretch binds: only one stretch's slots are live at a time. (The form
/// for optimised builds is the statements as written, without chunks.)
///
/// ```
/// use kinematics_core::chunk;
/// let a = 1.5_f64;
/// let (b, c) = chunk(|| {
///     let b = a * a;
///     let c = b + a;
///     (b, c)
/// });
/// assert_eq!((b, c), (2.25, 3.75));
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn chunk<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// Ends the basic block: a branch LLVM cannot fold (its condition is a `black_box`), whose taken
/// side it cannot remove (another `black_box`). Measured in a scratch harness (the Panda's 59
/// sphere centres, 526 operations, in a dispatched loop over 1,024 configurations, AVX2): a
/// `black_box` alone, without the branch, left the centres in eight `f32` lanes at 141 ns a
/// configuration; with the branch, 38 ns.
#[cfg_attr(not(debug_assertions), inline(always))]
fn end_block() {
    if core::hint::black_box(false) {
        core::hint::black_box(0_u8);
    }
}

/// The hardware's square root: std's `f64::sqrt`, which LLVM turns into one instruction, encoded
/// for the instruction set of the body it lands in (a loop over lanes, one packed instruction);
/// without `std`, libm's (the same correctly rounded value), which libm writes in assembly as the
/// legacy SSE2 `sqrtsd`. Every square root in this crate goes through here: inside a body
/// dispatched to AVX2 or AVX-512 that legacy instruction is the baseline code the dispatch is
/// there to avoid (on some Intel cores, SSE code after AVX-512 pays on every instruction), and
/// without `std` nothing is dispatched.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn square_root(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        std::primitive::f64::sqrt(x)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrt(x)
    }
}

/// [`square_root`] for `f32`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn square_root_f32(x: f32) -> f32 {
    #[cfg(feature = "std")]
    {
        std::primitive::f32::sqrt(x)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrtf(x)
    }
}

impl Real for f64 {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos(self) -> (Self, Self) {
        trig::sin_cos_f64(self)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_many<const N: usize>(x: [Self; N]) -> ([Self; N], [Self; N]) {
        trig::sin_cos_f64_lanes(x)
    }
}

impl Real for f32 {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn from_f64(x: f64) -> Self {
        x as f32
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos(self) -> (Self, Self) {
        trig::sin_cos_f32(self)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_many<const N: usize>(x: [Self; N]) -> ([Self; N], [Self; N]) {
        trig::sin_cos_f32_lanes(x)
    }
}

/// The platform's own `sin_cos` (std, on Linux glibc's), for code generated with `trig = "std"`.
///
/// Our routines ([`crate::trig`]) are the default; this is the choice for users who want the
/// platform's library, e.g. to compare against it. Lane types call it lane by lane.
#[cfg(feature = "std")]
#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
pub trait StdTrig: Real {
    /// `(sin x, cos x)` by the standard library.
    fn sin_cos_std(self) -> (Self, Self);
}

#[cfg(feature = "std")]
impl StdTrig for f64 {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_std(self) -> (Self, Self) {
        std::primitive::f64::sin_cos(self)
    }
}

#[cfg(feature = "std")]
impl StdTrig for f32 {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sin_cos_std(self) -> (Self, Self) {
        std::primitive::f32::sin_cos(self)
    }
}
