//! Every mesh of a parsed URDF loaded through `load_tree_meshes`.

#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use std::path::PathBuf;

use common::*;
use kinematics_meshes::{Packages, Resolver, load, load_tree_meshes};
use kinematics_model::collision::Shape;

/// An arm whose links use `package://` meshes of all three formats, one file twice (once by a
/// relative path), and a primitive.
const URDF: &str = r#"<robot name="arm">
  <link name="base">
    <collision><geometry><mesh filename="package://arm_description/meshes/base.stl"/></geometry></collision>
    <collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <link name="upper">
    <collision><geometry><mesh filename="package://arm_description/meshes/upper.dae" scale="2 2 2"/></geometry></collision>
  </link>
  <link name="hand">
    <collision><geometry><mesh filename="package://arm_description/meshes/hand.obj"/></geometry></collision>
    <collision><geometry><mesh filename="../meshes/base.stl"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="wrist" type="continuous">
    <parent link="upper"/><child link="hand"/><origin xyz="0 0 0.5"/><axis xyz="0 1 0"/>
  </joint>
</robot>"#;

/// The package `arm_description` under a temporary folder: its meshes, and where its URDF would
/// be (the file itself is not needed: the tree is parsed from the text).
fn package() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let package = dir.path().join("src/arm_description");
    write(&package.join("meshes/base.stl"), binary_stl(&cube(0.2)));
    let nodes = r##"<node><translate>0 0 100</translate><instance_geometry url="#cube"/></node>"##;
    write(&package.join("meshes/upper.dae"), collada(100.0, r#"<unit meter="0.001"/>"#, &visual_scene(nodes)));
    write(&package.join("meshes/hand.obj"), cube_obj());
    (dir, package)
}

#[test]
fn load_tree_meshes_loads_every_package_mesh() {
    let (_dir, package) = package();
    let description = package.join("urdf/arm.urdf");
    let mut tree = kinematics_model::parse_source("arm.urdf", URDF).unwrap();
    // Found above the description: no mapping, no environment.
    let resolver = Resolver::with_env(&description, &Packages::new(), None, None);
    let files = load_tree_meshes(&mut tree, &resolver).unwrap();
    // In the order first read; `../meshes/base.stl` is the same file, listed once.
    let meshes = package.join("meshes");
    assert_eq!(files, [meshes.join("base.stl"), meshes.join("upper.dae"), meshes.join("hand.obj")]);

    let mut loaded = 0;
    for link in tree.links() {
        for collision in &link.collisions {
            if let Shape::Mesh { loaded: mesh, filename, .. } = &collision.shape {
                let mesh = mesh.as_ref().unwrap_or_else(|| panic!("{filename} of {} not loaded", link.name));
                assert!(volume(mesh) > 0.0, "{filename}");
                loaded += 1;
            }
        }
    }
    assert_eq!(loaded, 4);

    // The Collada mesh in metres (the `<mesh scale>` is the model's to apply, not the file's).
    let (_, upper) = load(&resolver, "package://arm_description/meshes/upper.dae").unwrap();
    let (lo, hi) = bounds(&upper);
    assert_close(lo, [0.0, 0.0, 0.1]);
    assert_close(hi, [0.1, 0.1, 0.2]);
}

#[test]
fn load_tree_meshes_with_a_mapping_reads_through_it() {
    let (_dir, package) = package();
    // The description elsewhere: only the mapping finds the package.
    let description = package.parent().unwrap().parent().unwrap().join("other/arm.urdf");
    let mut tree = kinematics_model::parse_source(
        "arm.urdf",
        &URDF.replace("../meshes/base.stl", "package://arm_description/meshes/base.stl"),
    )
    .unwrap();
    let packages = Packages::new().with("arm_description", &package);
    let files = load_tree_meshes(&mut tree, &Resolver::with_env(&description, &packages, None, None)).unwrap();
    assert_eq!(files.len(), 3);
}

#[test]
fn a_mesh_not_found_is_an_error_listing_the_places_looked() {
    let (dir, _package) = package();
    let mut tree = kinematics_model::parse_source("arm.urdf", URDF).unwrap();
    let resolver = Resolver::with_env(&dir.path().join("other/arm.urdf"), &Packages::new(), None, None);
    let error = load_tree_meshes(&mut tree, &resolver).unwrap_err();
    assert_eq!((error.link.as_str(), error.filename.as_str()), ("base", "package://arm_description/meshes/base.stl"));
    // The reason is the whole resolution error.
    let expected = resolver.resolve(&error.filename).unwrap_err().to_string();
    assert_eq!(error.reason, expected);
    assert!(error.reason.contains(&dir.path().join("other/arm_description/meshes/base.stl").display().to_string()));
    assert!(error.reason.contains("--package arm_description=PATH"));
}

#[test]
fn a_bad_mesh_file_is_an_error_naming_the_file_found() {
    let (_dir, package) = package();
    write(&package.join("meshes/upper.dae"), "<COLLADA");
    let mut tree = kinematics_model::parse_source("arm.urdf", URDF).unwrap();
    let resolver = Resolver::with_env(&package.join("urdf/arm.urdf"), &Packages::new(), None, None);
    let error = load_tree_meshes(&mut tree, &resolver).unwrap_err();
    assert_eq!(error.link, "upper");
    let path = package.join("meshes/upper.dae");
    assert!(
        error.reason.starts_with(&format!("`{}` is not a valid Collada file: ", path.display())),
        "{}",
        error.reason
    );
}
