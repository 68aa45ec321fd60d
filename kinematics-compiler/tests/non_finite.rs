//! Constants that are each finite can compose into infinity (issue 13: `generate` and the derive
//! panicked in `Literal::f64_unsuffixed`). Compiling and emitting such a robot is an error naming
//! the link whose pose holds the constant, never a panic and never code computing infinities.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_compiler::options::{Options, Scalars};
use kinematics_compiler::robot::{RobotSpec, emit_robot};
use kinematics_compiler::{CompileError, Request, compile};
use quote::quote;

/// Two fixed offsets of 1e308 in a row: `link b` is at 2e308 = infinity.
const FAR: &str = r#"<robot name="far">
  <link name="base"/> <link name="a"/> <link name="b"/> <link name="c"/>
  <joint name="ja" type="fixed"><parent link="base"/><child link="a"/><origin xyz="1e308 0 0"/></joint>
  <joint name="jb" type="fixed"><parent link="a"/><child link="b"/><origin xyz="1e308 0 0"/></joint>
  <joint name="jc" type="continuous"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/></joint>
</robot>"#;

/// Mimic multipliers of 1e200 along a chain: `j3` turns 1e400 = infinity times `j1`.
const MIMIC: &str = r#"<robot name="mimic">
  <link name="base"/> <link name="l1"/> <link name="l2"/> <link name="l3"/>
  <joint name="j1" type="continuous"><parent link="base"/><child link="l1"/><axis xyz="0 0 1"/></joint>
  <joint name="j2" type="continuous"><parent link="l1"/><child link="l2"/><axis xyz="0 0 1"/>
    <mimic joint="j1" multiplier="1e200"/></joint>
  <joint name="j3" type="continuous"><parent link="l2"/><child link="l3"/><axis xyz="1 0 0"/>
    <origin xyz="1 0 0"/><mimic joint="j2" multiplier="1e200"/></joint>
</robot>"#;

/// Offsets as large as the model accepts (their reach, 1.6e308, is finite), opposite signs: the
/// compiler composes them without overflow.
const LARGEST: &str = r#"<robot name="largest">
  <link name="base"/> <link name="a"/> <link name="b"/>
  <joint name="ja" type="fixed"><parent link="base"/><child link="a"/><origin xyz="8e307 0 0"/></joint>
  <joint name="jb" type="continuous"><parent link="a"/><child link="b"/><origin xyz="-8e307 0 0"/>
    <axis xyz="0 0 1"/></joint>
</robot>"#;

/// Tips, positions, Jacobians and both scalars: every function a robot can get but IK.
fn options(tree: &kinematics_model::KinematicTree) -> Options {
    Options {
        tips: vec![tree.links().last().unwrap().name.clone()],
        positions: true,
        jacobians: true,
        scalars: Scalars { f64: true, f32: true },
        ..Options::default()
    }
}

fn spec<'a>(tree: &'a kinematics_model::KinematicTree, options: &'a Options) -> RobotSpec<'a> {
    RobotSpec {
        robot: options.check(tree).unwrap(),
        krate: quote!(::kinematics),
        source_label: "x.urdf".to_owned(),
        source_text: quote!(""),
        source_files: None,
        impl_generics: quote!(),
        where_clause: quote!(),
    }
}

/// Loads `text` and, if the model accepts it, compiles every link and emits the robot: the model's
/// refusal, or the compiler's errors (which must name the link if there are any).
fn outcome(text: &str) -> Result<Vec<CompileError>, kinematics_model::LoadError> {
    let tree = kinematics_model::parse_source("x.urdf", text)?;
    let mut errors = Vec::new();
    for link in tree.links().iter().skip(1) {
        for request in [Request::tip(&link.name), Request::tip(&link.name).positions_only()] {
            errors.extend(compile(&tree, &request).err());
        }
    }
    errors.extend(compile(&tree, &Request::all_links()).err());
    let options = options(&tree);
    errors.extend(emit_robot(&quote!(Robot), &spec(&tree, &options)).err());
    Ok(errors)
}

fn assert_names(errors: &[CompileError], link: &str) {
    assert!(!errors.is_empty(), "no error for a pose at infinity");
    for e in errors {
        match e {
            CompileError::NonFiniteConstant { link: named, value, .. } => {
                assert!(!value.is_finite(), "{e}");
                assert!(named == link, "{e}: expected link `{link}`");
            }
            other => panic!("unexpected error: {other}"),
        }
    }
}

/// The model refuses these descriptions itself (the reach and mimic rules); the compiler's check is
/// the backstop behind them. Either way the answer is an error naming where, never code.
#[test]
fn offsets_that_overflow_name_the_link() {
    match outcome(FAR) {
        Err(refused) => assert_eq!(
            refused.to_string(),
            "x.urdf: joint `jb`: the robot's reach (every fixed offset and prismatic stroke laid end to end) is not a finite number from this joint on"
        ),
        Ok(errors) => {
            // `b` is the first link at infinity; `c` hangs below it, and every request names the first.
            assert_eq!(errors.len(), 6, "{errors:?}");
            assert_names(&errors[..2], "b");
            assert_names(&errors[2..4], "c");
            assert_names(&errors[4..], "b");
            assert_eq!(
                errors[0].to_string(),
                "robot `far`: link `b`: the constants of its pose are not all finite numbers (one is inf): \
             the description's numbers overflow when composed"
            );
        }
    }
}

#[test]
fn mimic_multipliers_that_overflow_name_the_link() {
    match outcome(MIMIC) {
        Err(refused) => assert!(refused.to_string().starts_with("x.urdf: joint `j3`: "), "{refused}"),
        Ok(errors) => {
            assert_eq!(errors.len(), 4, "{errors:?}");
            assert_names(&errors[..2], "l3");
            assert_names(&errors[2..], "l3");
        }
    }
}

#[test]
fn the_largest_finite_offsets_compile() {
    let errors = outcome(LARGEST).unwrap();
    assert!(errors.is_empty(), "{errors:?}");
}
