//! How a body is run: timed by criterion (`cargo bench`), or once and checked (`cargo test`); and
//! the paired ratios, two bodies timed in alternation, which a shared machine whose speed drifts
//! over minutes cannot skew the way it skews two criterion medians taken seconds apart. The pairs
//! are collected here and written next to criterion's results for `bench-report`.
//!
//! The pairs go to `target/criterion/kinematics-paired.tsv`; a filtered run replaces only the pairs
//! it timed.

use std::hint::black_box;

use criterion::{BenchmarkGroup, measurement::WallTime};

use crate::inputs::INPUTS;

/// How one benchmark is run: measured by criterion, or once and checked (`cargo test`).
pub enum Mode<'a, 'c> {
    /// Criterion's group, and the robot's name for the paired ratios.
    Measure(&'a mut BenchmarkGroup<'c, WallTime>, &'static str),
    /// Every body once; the areas check what the bodies compute.
    Check,
}

impl Mode<'_, '_> {
    /// Times `f` (called with an input index) as benchmark `name` of the group, or calls it once.
    pub fn run<R>(&mut self, name: &str, mut f: impl FnMut(usize) -> R) {
        match self {
            Mode::Measure(group, _) => {
                let mut i = 0usize;
                group.bench_function(name, |b| {
                    b.iter(|| {
                        i = (i + 1) % INPUTS;
                        black_box(f(black_box(i)))
                    })
                });
            }
            Mode::Check => {
                black_box(f(0));
            }
        }
    }

    /// The time of `numerator` over the time of `denominator`, measured in alternation: 201 rounds,
    /// each timing both on the same 2,000 inputs back to back (which goes first alternates), and
    /// the median of the rounds' ratios. Criterion's medians come from different seconds of a
    /// shared machine whose speed drifts; these ratios do not. Recorded for `bench-report`.
    pub fn pair<A, B>(&mut self, name: &str, numerator: impl FnMut(usize) -> A, denominator: impl FnMut(usize) -> B) {
        self.pair_calls(name, 2000, numerator, denominator);
    }

    /// [`Mode::pair`] with `calls` calls of each per round: fewer for bodies that take a batch per
    /// call, so a round stays about a millisecond.
    pub fn pair_calls<A, B>(
        &mut self,
        name: &str,
        calls: usize,
        mut numerator: impl FnMut(usize) -> A,
        mut denominator: impl FnMut(usize) -> B,
    ) {
        let Mode::Measure(_, robot) = self else { return };
        if !crate::common::selected(&format!("{robot}/{name}")) {
            return; // a filtered run times the pairs of the robots it selects only
        }
        const ROUNDS: usize = 201;
        let median = crate::common::paired_ratio(ROUNDS, calls, INPUTS, &mut numerator, &mut denominator);
        println!("{robot}/{name}: paired ratio {median:.3} (median of {ROUNDS} alternating rounds)");
        // A poisoned lock means another body panicked (the run fails anyway); its pairs are still
        // whole strings, so keep them rather than drop this one.
        PAIRED.lock().unwrap_or_else(std::sync::PoisonError::into_inner).push(format!("{robot}\t{name}\t{median}\n"));
    }
}

/// Paired ratios of this run, written next to criterion's results for `bench-report`.
pub static PAIRED: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
