//! Bad files: every one an error naming the file, never a panic (mesh-loader's panics caught).

#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use std::path::Path;

use common::*;
use kinematics_meshes::{MeshFileError, read_mesh};

/// A deterministic byte stream (xorshift), so a failure is reproducible.
fn noise(seed: u64, len: usize) -> Vec<u8> {
    let mut x = seed | 1;
    (0..len)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x as u8
        })
        .collect()
}

fn read_error(path: &Path) -> MeshFileError {
    let error = read_mesh(path).expect_err(&format!("{} was read", path.display()));
    let message = error.to_string();
    assert!(message.contains(&path.display().to_string()), "the message does not name the file: {message}");
    assert_eq!(error.path(), path);
    error
}

#[test]
fn truncated_binary_stl_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    // A header claiming 1000 triangles, then 10 bytes.
    let mut bytes = vec![0u8; 80];
    bytes.extend(1000u32.to_le_bytes());
    bytes.extend([7u8; 10]);
    let path = dir.path().join("short.stl");
    write(&path, &bytes);
    assert!(matches!(read_error(&path), MeshFileError::Corrupt { format: "STL", .. }));

    // Cut at a triangle's end: mesh-loader alone would read the one triangle there is.
    let mut cut = binary_stl(&cube(1.0));
    cut[80..84].copy_from_slice(&1000u32.to_le_bytes());
    let path = dir.path().join("cut.stl");
    write(&path, &cut);
    let message = read_error(&path).to_string();
    assert!(message.contains("header says 1000 triangles and it holds 12"), "{message}");
}

#[test]
fn empty_files_are_errors() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["empty.stl", "empty.dae", "empty.obj"] {
        let path = dir.path().join(name);
        write(&path, b"");
        read_error(&path);
    }
}

#[test]
fn random_bytes_are_errors_not_panics() {
    let dir = tempfile::tempdir().unwrap();
    for extension in ["stl", "dae", "obj"] {
        for (seed, len) in [(1, 3), (2, 84), (3, 134), (4, 1000), (5, 5000)] {
            let path = dir.path().join(format!("noise-{seed}.{extension}"));
            write(&path, noise(seed, len));
            read_error(&path);
        }
    }
}

#[test]
fn truncations_of_valid_files_never_panic() {
    let dir = tempfile::tempdir().unwrap();
    let nodes = r##"<node><translate>1 2 3</translate><instance_geometry url="#cube"/></node>"##;
    let files: [(&str, Vec<u8>); 4] = [
        ("cube.stl", binary_stl(&cube(1.0))),
        ("tetra.stl", ascii_stl(&tetrahedron()).into_bytes()),
        ("cube.obj", cube_obj().as_bytes().to_vec()),
        ("cube.dae", collada(1.0, r#"<unit meter="0.01"/>"#, &visual_scene(nodes)).into_bytes()),
    ];
    for (name, bytes) in files {
        let path = dir.path().join(name);
        for len in (0..bytes.len()).step_by(7) {
            write(&path, &bytes[..len]);
            // Each prefix is read or refused; a panic would fail the test.
            let _ = read_mesh(&path);
        }
        write(&path, &bytes);
        read_mesh(&path).unwrap();
    }
}

#[test]
fn collada_index_past_the_positions_is_caught() {
    // mesh-loader indexes the positions with the `<p>` values unchecked
    // (`src/collada/instance.rs`, `build_mesh`): the panic is caught.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad-index.dae");
    let text = collada(1.0, "", &visual_scene(r##"<node><instance_geometry url="#cube"/></node>"##))
        .replace("<p>0 1 2 ", "<p>0 1 9999 ");
    write(&path, text);
    let error = read_error(&path);
    assert!(matches!(error, MeshFileError::ReaderFailed { format: "Collada", .. }), "{error:?}");
    assert!(error.to_string().contains("the mesh reader failed on it"), "{error}");
}

#[test]
fn collada_scene_errors_name_what_is_wrong() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (r##"<node><instance_geometry url="#nothing"/></node>"##, "geometry `nothing`"),
        (r##"<node><instance_geometry url="other.dae#cube"/></node>"##, "refers to another file"),
        (r##"<node><rotate>0 0 0 90</rotate><instance_geometry url="#cube"/></node>"##, "degenerate"),
        (r##"<node><scale>1 1</scale><instance_geometry url="#cube"/></node>"##, "not 3 finite numbers"),
        (r##"<node><skew>45 0 1 0 1 0 0</skew><instance_geometry url="#cube"/></node>"##, "<skew>"),
        (r##"<node id="loop"><instance_node url="#loop"/></node>"##, "nest deeper"),
    ];
    for (i, (nodes, expected)) in cases.into_iter().enumerate() {
        let path = dir.path().join(format!("scene-{i}.dae"));
        write(&path, collada(1.0, "", &visual_scene(nodes)));
        let message = read_error(&path).to_string();
        assert!(message.contains(expected), "{message}");
    }
    let path = dir.path().join("unit.dae");
    write(&path, collada(1.0, r#"<unit meter="-1"/>"#, ""));
    assert!(read_error(&path).to_string().contains("not a positive number"));
}

#[test]
fn zero_area_triangles_are_no_triangles() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("flat.stl");
    write(&path, ascii_stl(&[[[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]]));
    let error = read_error(&path);
    assert!(matches!(error, MeshFileError::NoTriangles { triangles: 1, .. }), "{error:?}");
    assert!(error.to_string().contains("has no triangles of non-zero area"), "{error}");

    let path = dir.path().join("none.obj");
    write(&path, "v 0 0 0\nv 1 0 0\n");
    assert_eq!(read_error(&path).to_string(), format!("`{}` has no triangles", path.display()));
}

#[test]
fn non_finite_vertex_is_invalid() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("nan.stl");
    let mut triangles = tetrahedron();
    triangles[3][2][1] = f32::NAN;
    write(&path, binary_stl(&triangles));
    assert!(matches!(read_error(&path), MeshFileError::Invalid { .. }));
}

#[test]
fn missing_unreadable_and_unknown_files_are_errors() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("missing.stl");
    assert!(matches!(read_error(&missing), MeshFileError::Io { .. }));
    // A folder is no file.
    assert!(matches!(read_error(dir.path()), MeshFileError::Io { .. }));
    let ply = dir.path().join("cube.ply");
    write(&ply, "ply\nformat ascii 1.0\n");
    assert!(matches!(read_error(&ply), MeshFileError::UnknownFormat { .. }));
}
