//! Every fault of one derive is reported, each once, and the output keeps a stub of the impls so
//! no fault cascades (issue 13); the user's generics go on the impls as written.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use quote::quote;

fn expand(input: proc_macro2::TokenStream) -> String {
    kinematics_derive_core::expand(input).to_string()
}

/// The messages of the `compile_error!`s in an expansion.
fn errors(out: &str) -> Vec<String> {
    out.split("compile_error ! {")
        .skip(1)
        .map(|rest| {
            let start = rest.find('"').unwrap() + 1;
            let end = start + rest[start..].find("\" }").unwrap();
            rest[start..end].to_owned()
        })
        .collect()
}

#[test]
fn link_faults_and_option_faults_are_reported_together() {
    let out = expand(quote! {
        #[kinematics(dh = "../robots/planar_2r.toml", base = "bsae", tip = "link9", scalars(f16))]
        struct Arm;
    });
    let errors = errors(&out);
    assert_eq!(errors.len(), 4, "{errors:#?}");
    // The attribute's own faults first, then the compiler's rules in their order.
    assert_eq!(errors[0], "expected `f64` or `f32`");
    assert!(errors[1].contains("base link `bsae` does not exist"), "{errors:#?}");
    assert!(errors[2].contains("tip link `link9` does not exist"), "{errors:#?}");
    assert!(errors[3].ends_with("name at least one scalar type: `f64`, `f32` or both"), "{errors:#?}");
}

#[test]
fn a_fault_leaves_a_stub_with_the_names_the_attribute_implies() {
    let out = expand(quote! {
        #[kinematics(dh = "../robots/planar_2r.toml", tips("link1", "link9"), positions, scalars(f32))]
        struct Arm;
    });
    assert_eq!(errors(&out).len(), 1, "{out}");
    for expected in [
        "impl :: kinematics :: __private :: Kinematics for Arm",
        "pub fn tip_poses_f32",
        "pub fn tip_positions_f32",
        "pub fn link_poses_f32",
        "pub fn reference",
    ] {
        assert!(out.contains(expected), "no `{expected}` in {out}");
    }
    for absent in ["fn tip_pose_f32", "fn tip_poses <", "fn tip_poses(", "fn tip_pose <", "fn tip_pose("] {
        assert!(!out.contains(absent), "`{absent}` in {out}");
    }
}

#[test]
fn a_key_darling_cannot_read_does_not_hide_the_descriptions_faults() {
    // `positions = "yes"` fails the whole attribute; the file and the tip are still checked.
    let out = expand(quote! {
        #[kinematics(dh = "../robots/planar_2r.toml", tip = "link9", positions = "yes")]
        struct Arm;
    });
    let found = errors(&out);
    assert_eq!(found.len(), 2, "{found:#?}");
    assert!(found.iter().any(|e| e.contains("tip link `link9` does not exist")), "{found:#?}");
    let out = expand(quote! {
        #[kinematics(urdf = "no_such_robot.urdf", scalars = "f64")]
        struct Arm;
    });
    let found = errors(&out);
    assert_eq!(found.len(), 2, "{found:#?}");
    assert!(found.iter().any(|e| e.starts_with("no_such_robot.urdf: cannot read the file")), "{found:#?}");
    // A misspelt description key is one fault, not two.
    let out = expand(quote! {
        #[kinematics(dhh = "../robots/planar_2r.toml")]
        struct Arm;
    });
    assert_eq!(errors(&out).len(), 1, "{out}");
}

#[test]
fn a_wrong_link_name_leaves_a_stub_with_the_robots_sizes() {
    // The description reads; only the tip is wrong: the stub knows the robot has 2 degrees of
    // freedom and 2 links below the base, so `let [a, b] = Arm::link_poses(&q)` type-checks.
    let out = expand(quote! {
        #[kinematics(dh = "../robots/planar_2r.toml", tip = "link9")]
        struct Arm;
    });
    assert_eq!(errors(&out).len(), 1, "{out}");
    assert!(out.contains("pub const DOF : usize = 2 ;"), "{out}");
    assert!(out.contains("pub const JOINT_NAMES : [& 'static str ; 2] = [\"\" ; 2] ;"), "{out}");
    assert!(
        out.contains("pub fn link_poses (q : & [f64 ; 2]) -> [:: kinematics :: __private :: Pose < f64 > ; 2]"),
        "{out}"
    );
}

#[test]
fn an_unreadable_attribute_still_leaves_a_stub() {
    let out = expand(quote! {
        #[kinematics(dh = "../robots/planar_2r.toml", tip = "link2", positions = "yes", crate = "kin")]
        struct Arm<T>(T);
    });
    assert!(!errors(&out).is_empty(), "{out}");
    assert!(out.contains("impl < T > kin :: __private :: Kinematics for Arm < T >"), "{out}");
    // The description loaded: the robot's own lengths.
    assert!(out.contains("pub fn tip_pose (q : & [f64 ; 2])"), "{out}");
    assert!(out.contains("pub fn tip_position (q : & [f64 ; 2])"), "{out}");
}

#[test]
fn constants_that_overflow_are_an_error_on_the_struct_not_a_panic() {
    let out = expand(quote! {
        #[kinematics(urdf = "tests/fixtures/far.urdf", tip = "b")]
        struct Far;
    });
    let errors = errors(&out);
    // The model may come to refuse the file itself; either way it is an error, not a panic.
    assert_eq!(errors.len(), 1, "{errors:#?}");
    assert!(errors[0].starts_with("tests/fixtures/far.urdf: "), "{errors:#?}");
    assert!(out.contains("impl :: kinematics :: __private :: Kinematics for Far"), "{out}");
}

#[test]
fn generics_are_written_on_the_impls() {
    let out = expand(quote! {
        #[kinematics(dh = "../robots/planar_2r.toml", tip = "link2")]
        struct Arm<'a, T: Clone, const N: usize> where T: Default { r: &'a [T; N] }
    });
    assert!(errors(&out).is_empty(), "{out}");
    let generics = "impl < 'a , T : Clone , const N : usize >";
    assert!(out.contains(&format!("{generics} Arm < 'a , T , N > where T : Default")), "{out}");
    assert!(out.contains(&format!(
        "{generics} :: kinematics :: __private :: Kinematics for Arm < 'a , T , N > where T : Default"
    )));
}
