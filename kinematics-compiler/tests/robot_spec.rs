//! What `emit_robot` writes around the compiled functions: the reference parses the description
//! with the tree's own exactness policy, and the user's generics go on the impls.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_compiler::options::Options;
use kinematics_compiler::robot::{RobotSpec, emit_robot};
use kinematics_model::{ExactAngles, KinematicTree};
use quote::quote;

const ARM: &str = r#"<robot name="arm">
  <link name="base"/> <link name="upper"/> <link name="tool"/>
  <joint name="shoulder" type="continuous"><parent link="base"/><child link="upper"/><axis xyz="0 0 1"/>
    <origin rpy="3.14159265359 0 0"/></joint>
  <joint name="elbow" type="continuous"><parent link="upper"/><child link="tool"/><axis xyz="0 1 0"/>
    <origin xyz="1 0 0"/></joint>
</robot>"#;

/// The options every test here emits with: the tool's pose.
fn options() -> Options {
    Options { tips: vec!["tool".to_owned()], ..Options::default() }
}

fn spec<'a>(tree: &'a KinematicTree, options: &'a Options) -> RobotSpec<'a> {
    RobotSpec {
        robot: options.check(tree).unwrap(),
        krate: quote!(::kinematics),
        source_label: "arm.urdf".to_owned(),
        source_text: quote!("text"),
        source_files: None,
        impl_generics: quote!(),
        where_clause: quote!(),
    }
}

/// The tokens of `reference()`'s body.
fn reference_call(tokens: &str) -> &str {
    let start = tokens.find("parse_source_with").expect("reference() parses with a policy");
    &tokens[start..start + tokens[start..].find(')').unwrap() + 1]
}

#[test]
fn reference_loads_with_the_trees_policy() {
    let off = kinematics_model::parse_source_with("arm.urdf", ARM, ExactAngles::Off).unwrap();
    let tokens = emit_robot(&quote!(Arm), &spec(&off, &options())).unwrap().to_string();
    assert_eq!(
        reference_call(&tokens),
        "parse_source_with (\"arm.urdf\" , \"text\" , :: kinematics :: __private :: ExactAngles :: Off)"
    );
    let on = kinematics_model::parse_source_with("arm.urdf", ARM, ExactAngles::Within(1e-9)).unwrap();
    let tokens = emit_robot(&quote!(Arm), &spec(&on, &options())).unwrap().to_string();
    assert_eq!(
        reference_call(&tokens),
        "parse_source_with (\"arm.urdf\" , \"text\" , :: kinematics :: __private :: ExactAngles :: Within (0.000000001f64)"
    );
}

#[test]
fn generics_go_on_both_impls_and_nowhere_else() {
    let tree = kinematics_model::parse_source("arm.urdf", ARM).unwrap();
    let options = options();
    let mut spec = spec(&tree, &options);
    spec.impl_generics = quote!(<'a, T: Clone, const N: usize>);
    spec.where_clause = quote!(where T: Default);
    let tokens = emit_robot(&quote!(Arm<'a, T, N>), &spec).unwrap().to_string();
    let generics = "impl < 'a , T : Clone , const N : usize >";
    assert!(tokens.contains(&format!("{generics} Arm < 'a , T , N > where T : Default {{")), "{tokens}");
    assert!(
        tokens.contains(&format!(
            "{generics} :: kinematics :: __private :: Kinematics for Arm < 'a , T , N > where T : Default {{"
        )),
        "{tokens}"
    );
    assert!(
        tokens.contains(&format!(
            "{generics} :: kinematics :: __private :: ReferenceModel for Arm < 'a , T , N > where T : Default {{"
        )),
        "{tokens}"
    );
    assert_eq!(tokens.matches("const N").count(), 3, "{tokens}");
    // The user's `T` is in scope in the inherent impl: the `*_generic` functions take another name.
    assert!(tokens.contains("pub fn tip_pose_generic < S : :: kinematics :: __private :: Real >"), "{tokens}");
    // All of it in one anonymous block, the generic functions free in it.
    assert!(tokens.starts_with("const _ : () = {"), "{tokens}");
    assert!(tokens.contains("fn generic_tip_poses < T : :: kinematics :: __private :: Real >"), "{tokens}");
}
