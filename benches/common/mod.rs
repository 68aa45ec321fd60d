//! What the `fk` and `ik` benchmarks share: how a run is told from check mode, criterion's
//! settings, and the directory the records for `bench-report` go to. Each benchmark keeps its own
//! robots, inputs and bodies (their random configurations come from different generators on
//! purpose: changing either would change what is timed).

use std::path::{Path, PathBuf};
use std::time::Duration;

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
