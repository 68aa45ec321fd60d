//! Run-time choice of instruction set: every generated function runs the best body the CPU has.
//!
//! A plain `cargo build --release` targets baseline x86-64 (SSE2: two `f64` to a register, no
//! AVX), and almost nobody builds with `-C target-cpu=native`. [`dispatch`] compiles the code it is
//! given once per instruction set pulp knows (x86-64-v4 with AVX-512, x86-64-v3 with AVX2 and FMA,
//! and the baseline) and runs the best one the CPU reports, read from the standard library's
//! feature cache (a few loads and tests per call). A build whose target already has AVX-512 (such
//! as `-C target-cpu=native` on such a CPU) calls the code in place; one with AVX2 only still asks
//! at run time whether AVX-512 is there.
//! Without the `dispatch` feature (as in a `no_std` build) the code runs as compiled.
//!
//! **Results do not depend on the body chosen.** Rust never contracts `a * b + c` into a fused
//! multiply-add on its own (LLVM's `fp-contract` is off for Rust), so enabling FMA changes the
//! instructions available, not the arithmetic: every body rounds the same operations in the same
//! order, and the generated functions give bit-identical results on every x86-64 CPU and build.
//! `tests/dispatch.rs` holds the dispatched bodies to the baseline ones bit for bit.
//!
//! The code must reach the dispatched function inlined: a closure marked `#[inline(always)]` calling
//! `#[inline(always)]` bodies (generated bodies are). A function item passed by name goes through a
//! call shim that is not inlined into pulp's `#[target_feature]` function, which then runs the
//! baseline code it calls (measured in `batch`).
//!
//! Every generated typed function calls `dispatch` with its body. The `dispatch` feature is on with
//! the facade's `std`.

/// Runs `f` compiled for the best instruction set the CPU has (see the module doc).
///
/// ```
/// use kinematics_core::{dispatch, Real};
/// let q = [0.3_f64, -1.2];
/// let x = dispatch(#[inline(always)] || {
///     let (s, c) = f64::sin_cos_many(q);
///     s[0] * c[1]
/// });
/// let (s, c) = f64::sin_cos_many(q);
/// assert_eq!(x, s[0] * c[1]); // bit for bit
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn dispatch<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(all(feature = "dispatch", not(target_feature = "avx512f")))]
    {
        pulp::Arch::new().dispatch(Call(f))
    }
    // A build whose target already has AVX-512 (`-C target-cpu=native` here) has nothing wider to
    // choose: the body is called in place, inlined like any other code. Through pulp it would be
    // a call LLVM keeps out of line (measured: the UR5's all links 0.82x the inlined body).
    #[cfg(any(not(feature = "dispatch"), target_feature = "avx512f"))]
    {
        f()
    }
}

/// `f` as pulp's operation: `with_simd` is `#[inline(always)]`, so `f` is compiled inside each
/// `#[target_feature]` function pulp instantiates.
#[cfg(all(feature = "dispatch", not(target_feature = "avx512f")))]
struct Call<F>(F);

#[cfg(all(feature = "dispatch", not(target_feature = "avx512f")))]
impl<R, F: FnOnce() -> R> pulp::WithSimd for Call<F> {
    type Output = R;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn with_simd<S: pulp::Simd>(self, _: S) -> R {
        (self.0)()
    }
}

/// Which body [`dispatch`] runs on this CPU, for reports: `"x86-64-v4 (AVX-512)"`,
/// `"x86-64-v3 (AVX2, FMA)"` or `"baseline"` (also without the `dispatch` feature, and on
/// targets pulp has no wider set for).
pub fn dispatched_level() -> &'static str {
    #[cfg(all(feature = "dispatch", target_arch = "x86_64"))]
    {
        match pulp::Arch::new() {
            pulp::Arch::V4(_) => "x86-64-v4 (AVX-512)",
            pulp::Arch::V3(_) => "x86-64-v3 (AVX2, FMA)",
            _ => "baseline",
        }
    }
    #[cfg(not(all(feature = "dispatch", target_arch = "x86_64")))]
    {
        "baseline"
    }
}
