//! What the `fk` and `ik` benchmarks share: how a run is told from check mode, criterion's
//! settings, and the directory the records for `bench-report` go to. Each benchmark keeps its own
//! robots, inputs and bodies (their random configurations come from different generators on
//! purpose: changing either would change what is timed).
//!
//! `collision` uses it too: measuring or check mode, criterion's settings and filter, the results
//! directory, and the paired timing (`paired_ratio`).

use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use criterion::Criterion;

/// Whether this run measures: `cargo bench` passes `--bench`; `cargo test` runs the benchmark
/// without it, and every body then runs once and is checked instead.
pub fn measuring() -> bool {
    std::env::args().any(|a| a == "--bench")
}

/// Criterion with the given warm-up and measurement times, 30 samples, then the command line's
/// own options (a filter, `--save-baseline`, ...).
pub fn criterion(warm_up: Duration, measurement: Duration) -> Criterion {
    Criterion::default().warm_up_time(warm_up).measurement_time(measurement).sample_size(30).configure_from_args()
}

/// Criterion's results directory (`$CARGO_TARGET_DIR/criterion`, else `target/criterion`), where
/// the benchmarks leave the records `bench-report` reads beside criterion's own.
pub fn criterion_dir() -> PathBuf {
    std::env::var("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|_| Path::new(env!("CARGO_MANIFEST_DIR")).join("target"))
        .join("criterion")
}

/// The time of `numerator` over the time of `denominator`, measured in alternation: `rounds`
/// rounds (odd), each timing both on the same `calls` inputs back to back, which goes first
/// alternating, and the median of the rounds' ratios. Round `r` takes the inputs from `r * calls`
/// on (modulo `inputs`), so rounds of fewer calls than inputs still cover them all. Criterion's
/// medians come from different seconds of a shared machine whose speed drifts; these ratios do
/// not.
pub fn paired_ratio<A, B>(
    rounds: usize,
    calls: usize,
    inputs: usize,
    mut numerator: impl FnMut(usize) -> A,
    mut denominator: impl FnMut(usize) -> B,
) -> f64 {
    let time = |f: &mut dyn FnMut(usize), first: usize| {
        let start = Instant::now();
        for k in first..first + calls {
            f(black_box(k % inputs));
        }
        start.elapsed().as_secs_f64()
    };
    let mut num = |i: usize| {
        black_box(numerator(i));
    };
    let mut den = |i: usize| {
        black_box(denominator(i));
    };
    let mut ratios: Vec<f64> = (0..rounds)
        .map(|round| {
            let first = round * calls % inputs;
            if round % 2 == 0 {
                let n = time(&mut num, first);
                n / time(&mut den, first)
            } else {
                let d = time(&mut den, first);
                time(&mut num, first) / d
            }
        })
        .collect();
    ratios.sort_by(f64::total_cmp);
    ratios[rounds / 2]
}

/// Criterion's filter, if it was given one: the first argument that is neither a flag nor the
/// value of a flag that takes one.
pub static FILTER: std::sync::LazyLock<Option<String>> = std::sync::LazyLock::new(|| {
    const TAKES_VALUE: [&str; 16] = [
        "--save-baseline",
        "--baseline",
        "--baseline-lenient",
        "--load-baseline",
        "--sample-size",
        "--warm-up-time",
        "--measurement-time",
        "--nresamples",
        "--noise-threshold",
        "--confidence-level",
        "--significance-level",
        "--profile-time",
        "--plotting-backend",
        "--output-format",
        "--color",
        "--format",
    ];
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        if TAKES_VALUE.contains(&arg.as_str()) {
            args.next();
        } else if !arg.starts_with('-') {
            return Some(arg);
        }
    }
    None
});

/// Whether a pair named `id` (`robot/numerator/denominator`) is timed in this run: always without
/// a filter, else when the filter is part of its name (criterion's filters are regular
/// expressions; a plain robot name such as `ur5` selects the same robots both ways).
pub fn selected(id: &str) -> bool {
    FILTER.as_deref().is_none_or(|filter| id.contains(filter))
}
