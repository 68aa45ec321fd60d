//! Reading well-formed files: each format, and Collada's units and placements.

#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::*;
use kinematics_meshes::read_mesh;

#[test]
fn ascii_stl_tetrahedron_is_read() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("tetra.stl");
    write(&path, ascii_stl(&tetrahedron()));
    let mesh = read_mesh(&path).unwrap();
    assert_eq!(mesh.triangles().len(), 4);
    // mesh-loader gives each triangle its own corners; equal ones are shared.
    assert_eq!(mesh.vertices().len(), 4);
    assert!((volume(&mesh) - 1.0 / 6.0).abs() < 1e-12);
}

#[test]
fn binary_stl_cube_is_read_with_shared_vertices() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cube.stl");
    write(&path, binary_stl(&cube(1.0)));
    let mesh = read_mesh(&path).unwrap();
    assert_eq!((mesh.triangles().len(), mesh.vertices().len()), (12, 8));
    assert!((volume(&mesh) - 1.0).abs() < 1e-12);
}

#[test]
fn binary_stl_whose_header_starts_with_solid_is_binary() {
    // Some exporters write `solid NAME` into a binary header: the ASCII reading fails and the
    // binary one is taken.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("solid.stl");
    let mut bytes = binary_stl(&cube(2.0));
    bytes[..11].copy_from_slice(b"solid cube ");
    write(&path, bytes);
    let mesh = read_mesh(&path).unwrap();
    assert!((volume(&mesh) - 8.0).abs() < 1e-12);
}

#[test]
fn format_is_told_by_content_without_extension_and_by_extension_in_any_case() {
    let dir = tempfile::tempdir().unwrap();
    let bare = dir.path().join("tetra");
    write(&bare, ascii_stl(&tetrahedron()));
    assert_eq!(read_mesh(&bare).unwrap().triangles().len(), 4);
    let upper = dir.path().join("CUBE.Stl");
    write(&upper, binary_stl(&cube(1.0)));
    assert_eq!(read_mesh(&upper).unwrap().triangles().len(), 12);
    let dae = dir.path().join("cube.xml");
    write(&dae, collada(1.0, "", &visual_scene(r##"<node><instance_geometry url="#cube"/></node>"##)));
    assert_eq!(read_mesh(&dae).unwrap().triangles().len(), 12);
}

#[test]
fn obj_quads_are_split_into_triangles_and_materials_are_not_read() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cube.obj");
    // `mtllib missing.mtl`: materials are no collision matter, and not opened.
    write(&path, cube_obj());
    let mesh = read_mesh(&path).unwrap();
    assert_eq!((mesh.triangles().len(), mesh.vertices().len()), (12, 8));
    assert!((volume(&mesh) - 1.0).abs() < 1e-12);
}

#[test]
fn collada_unit_and_nested_transforms_are_applied_parent_first() {
    // A 100 mm cube, in a millimetre file, placed by a parent node (1000 mm along x, turned 90
    // degrees about z) and a child node (500 mm up). `up_axis` is left alone.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cube.dae");
    let nodes = r##"<node id="parent"><translate>1000 0 0</translate><rotate>0 0 1 90</rotate>
        <node id="child"><translate>0 0 500</translate><instance_geometry url="#cube"/></node></node>"##;
    write(
        &path,
        collada(100.0, r#"<unit meter="0.001" name="millimetre"/><up_axis>Y_UP</up_axis>"#, &visual_scene(nodes)),
    );
    let mesh = read_mesh(&path).unwrap();
    // (x, y, z) mm -> (1000 - y, x, 500 + z) mm -> metres.
    let (lo, hi) = bounds(&mesh);
    assert_close(lo, [0.9, 0.0, 0.5]);
    assert_close(hi, [1.0, 0.1, 0.6]);
    assert!((volume(&mesh) - 0.001).abs() < 1e-9);
}

#[test]
fn collada_geometry_placed_twice_is_read_twice() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("two.dae");
    let nodes = r##"<node><instance_geometry url="#cube"/></node>
        <node><translate>3 0 0</translate><instance_geometry url="#cube"/></node>"##;
    write(&path, collada(1.0, "", &visual_scene(nodes)));
    let mesh = read_mesh(&path).unwrap();
    assert_eq!(mesh.triangles().len(), 24);
    assert!((volume(&mesh) - 2.0).abs() < 1e-12);
    assert_close(bounds(&mesh).1, [4.0, 1.0, 1.0]);
}

#[test]
fn collada_mirror_keeps_the_outside_out() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("mirror.dae");
    let nodes = r##"<node><scale>-1 1 1</scale><instance_geometry url="#cube"/></node>"##;
    write(&path, collada(1.0, "", &visual_scene(nodes)));
    let mesh = read_mesh(&path).unwrap();
    assert_close(bounds(&mesh).0, [-1.0, 0.0, 0.0]);
    assert!((volume(&mesh) - 1.0).abs() < 1e-12, "{}", volume(&mesh));
}

#[test]
fn collada_matrix_and_instance_node_are_followed() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("library.dae");
    let library = r##"<library_nodes><node id="part"><matrix>1 0 0 0  0 1 0 0  0 0 1 2  0 0 0 1</matrix>
        <instance_geometry url="#cube"/></node></library_nodes>"##;
    let scene = visual_scene(r##"<node><translate>0 5 0</translate><instance_node url="#part"/></node>"##);
    write(&path, collada(1.0, "", &format!("{library}\n{scene}")));
    let mesh = read_mesh(&path).unwrap();
    assert_close(bounds(&mesh).0, [0.0, 5.0, 2.0]);
}

#[test]
fn collada_without_a_scene_takes_every_geometry_in_its_unit() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bare.dae");
    write(&path, collada(1.0, r#"<unit meter="0,5"/>"#, ""));
    let mesh = read_mesh(&path).unwrap();
    assert!((volume(&mesh) - 0.125).abs() < 1e-12);
}
