//! A small deterministic generator (splitmix64) for what the core draws from a fixed seed: the
//! numeric IK's restart configurations, and the test sweeps.

/// splitmix64: uniform `f64` in `[0, 1)` from a 64-bit state.
pub(crate) struct SplitMix(pub(crate) u64);

impl SplitMix {
    /// The next value in `[0, 1)`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) as f64 / 18_446_744_073_709_551_616.0
    }
}
