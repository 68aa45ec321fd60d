//! The derive's compile errors, pinned: `tests/ui.rs` compiles every case under `tests/ui/` with
//! trybuild and compares its errors with the `.stderr` beside it. The crate holds no code: it exists
//! so that trybuild, which builds each case against the dependencies of the crate that runs it,
//! builds the facade alone and not the root package's benchmark and test dependencies.
//!
//! Under the root package, trybuild rebuilt criterion, `k`, mjcf-rs and the build API as well.
//! Cases under `tests/ui/pass/` must compile.
