//! The exact compile error of every way a derive can be wrong (trybuild; `.stderr` beside each case),
//! and what must compile (`pass/`).
//! Regenerate on purpose with `TRYBUILD=overwrite cargo test -p kinematics-ui-tests` and read the diff.

#[test]
fn derive_errors() {
    let cases = trybuild::TestCases::new();
    cases.compile_fail("tests/ui/*.rs");
    // A faulty derive with code using the struct: only the derive's errors, no cascade.
    cases.compile_fail("tests/ui/cascade/*.rs");
    // What must compile: user items named like the generated code's locals.
    cases.pass("tests/ui/pass/*.rs");
}
