//! The exact compile error of every way a derive can be wrong (trybuild; `.stderr` beside each case).
//! Regenerate on purpose with `TRYBUILD=overwrite cargo test --test ui` and read the diff.

#[test]
fn derive_errors() {
    let cases = trybuild::TestCases::new();
    cases.compile_fail("tests/ui/*.rs");
    // A faulty derive with code using the struct: only the derive's errors, no cascade.
    cases.compile_fail("tests/ui/cascade/*.rs");
}
