//! The expansion itself: it depends on the description file (so edits rebuild the user's crate),
//! and no attribute, however malformed, makes it panic.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use proptest::prelude::*;
use quote::quote;

#[test]
fn expansion_includes_the_description_so_edits_trigger_a_rebuild() {
    // rustc records files read by `include_str!` as dependencies of the crate: cargo rebuilds it
    // when one changes. The expansion must carry the file's absolute path in one.
    let out = kinematics_derive_core::expand(quote! {
        #[kinematics(dh = "../robots/planar_2r.toml", tip = "link2")]
        struct Arm;
    })
    .to_string();
    let absolute = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots/planar_2r.toml");
    let expected = format!("include_str ! ({:?})", absolute.to_string_lossy());
    assert!(out.contains(&expected), "no `{expected}` in the expansion:\n{out}");
    assert!(!out.contains("compile_error"), "{out}");
}

#[test]
fn inline_tables_need_no_file() {
    let out = kinematics_derive_core::expand(quote! {
        #[kinematics(dh(convention = "standard", joint(name = "j1", a = 1.0)))]
        struct Arm;
    })
    .to_string();
    assert!(!out.contains("include_str") && !out.contains("compile_error"), "{out}");
}

fn fragment() -> impl Strategy<Value = String> {
    prop::sample::select(vec![
        "urdf = \"../robots/ur5.urdf\"",
        "dh = \"../robots/ur5.toml\"",
        "dh(convention = \"standard\", joint(name = \"a\", a = 1.0))",
        "dh(convention = \"modified\", joint(name = \"a\", alpha = \"pi/\"), joint(a = 1))",
        "dh(joint())",
        "dh(convention = 5)",
        "tip = \"tool0\"",
        "tip = \"nowhere\"",
        "tips(\"a\", 5, b)",
        "base = \"base\"",
        "base",
        "positions",
        "positions = 3",
        "scalars(f32)",
        "scalars()",
        "scalars(\"f64\")",
        "crate = \"my_kinematics\"",
        "urdf = \"/\"",
        "urdf = \"\"",
        "dh = \"../robots\"",
        "= =",
        "urdf",
        "dh(",
        ")",
    ])
    .prop_map(str::to_owned)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn never_panics(parts in proptest::collection::vec(fragment(), 0..5)) {
        let attribute = parts.join(", ");
        let input = format!("#[kinematics({attribute})] struct Robot;");
        // Some inputs are not even tokens (unbalanced parentheses); those never reach the macro.
        if let Ok(tokens) = input.parse::<proc_macro2::TokenStream>() {
            let _ = kinematics_derive_core::expand(tokens);
        }
    }
}
