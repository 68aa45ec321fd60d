//! URI resolution: the order of the package folders, the ROS crawl, paths, and what an
//! unresolved URI says.

#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use std::path::{Path, PathBuf};

use common::write;
use kinematics_meshes::{Packages, Resolver, UnresolvedKind};

const URI: &str = "package://robot/meshes/m.stl";

/// One copy of `robot/meshes/m.stl` in each kind of place, and the description inside the one
/// found by walking up.
struct Places {
    _dir: tempfile::TempDir,
    root: PathBuf,
}

impl Places {
    fn new() -> Places {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path().to_path_buf();
        for folder in ["user/robot", "ros/robot", "ament/share/robot", "tree/robot"] {
            write(&root.join(folder).join("meshes/m.stl"), folder);
        }
        Places { _dir: dir, root }
    }

    fn description(&self) -> PathBuf {
        self.root.join("tree/robot/urdf/robot.urdf")
    }

    fn packages(&self) -> Packages {
        Packages::new().with("robot", self.root.join("user/robot"))
    }

    fn env(&self, folder: &str) -> Option<String> {
        Some(self.root.join(folder).to_string_lossy().into_owned())
    }

    fn found(&self, resolver: &Resolver) -> PathBuf {
        let path = resolver.resolve(URI).unwrap();
        path.strip_prefix(&self.root).unwrap().to_path_buf()
    }
}

#[test]
fn user_mapping_beats_ros_package_path() {
    let p = Places::new();
    let resolver = Resolver::with_env(&p.description(), &p.packages(), p.env("ros"), p.env("ament"));
    assert_eq!(p.found(&resolver), Path::new("user/robot/meshes/m.stl"));
}

#[test]
fn ros_package_path_beats_ament_prefix_path() {
    let p = Places::new();
    let resolver = Resolver::with_env(&p.description(), &Packages::new(), p.env("ros"), p.env("ament"));
    assert_eq!(p.found(&resolver), Path::new("ros/robot/meshes/m.stl"));
}

#[test]
fn ament_prefix_path_beats_the_folders_above_the_description() {
    let p = Places::new();
    let resolver = Resolver::with_env(&p.description(), &Packages::new(), None, p.env("ament"));
    assert_eq!(p.found(&resolver), Path::new("ament/share/robot/meshes/m.stl"));
}

#[test]
fn a_folder_above_the_description_is_the_last_resort() {
    let p = Places::new();
    let resolver = Resolver::with_env(&p.description(), &Packages::new(), None, None);
    assert_eq!(p.found(&resolver), Path::new("tree/robot/meshes/m.stl"));
    // A mapping to a folder without the file falls through to the next place.
    let elsewhere = Packages::new().with("robot", p.root.join("nowhere"));
    let resolver = Resolver::with_env(&p.description(), &elsewhere, p.env("empty"), None);
    assert_eq!(p.found(&resolver), Path::new("tree/robot/meshes/m.stl"));
}

#[test]
fn ros_package_path_is_searched_below_each_entry() {
    let dir = tempfile::tempdir().unwrap();
    let ws = dir.path().join("ws");
    let package = |folder: &str, mesh: bool| {
        let folder = ws.join(folder);
        write(&folder.join("package.xml"), "<package/>");
        if mesh {
            write(&folder.join("meshes/m.stl"), "");
        }
    };
    // Found: a package three levels down; of two, the first in sorted order.
    package("src/b_group/robot", true);
    package("src/a_group/robot", true);
    // Not found: hidden, too deep, ignored, inside another package, or no `package.xml`.
    package(".hidden/robot", true);
    package("1/2/3/4/robot", true);
    package("skipped/robot", true);
    write(&ws.join("skipped/CATKIN_IGNORE"), "");
    package("outer", false);
    package("outer/robot", true);
    write(&ws.join("plain/robot/meshes/m.stl"), "");

    let description = dir.path().join("elsewhere/robot.urdf");
    let ros = Some(ws.to_string_lossy().into_owned());
    let resolver = Resolver::with_env(&description, &Packages::new(), ros.clone(), None);
    assert_eq!(resolver.resolve(URI).unwrap(), ws.join("src/a_group/robot/meshes/m.stl"));

    // A file no copy holds: every package folder found is listed, in order, and no other.
    let error = resolver.resolve("package://robot/meshes/missing.stl").unwrap_err();
    let below_ws: Vec<&Path> = error.looked.iter().filter_map(|p| p.strip_prefix(&ws).ok()).collect();
    assert_eq!(
        below_ws,
        [
            Path::new("robot/meshes/missing.stl"),
            Path::new("src/a_group/robot/meshes/missing.stl"),
            Path::new("src/b_group/robot/meshes/missing.stl"),
        ]
    );

    // An entry that is itself the package.
    let entry = Some(ws.join("src/b_group/robot").to_string_lossy().into_owned());
    let resolver = Resolver::with_env(&description, &Packages::new(), entry, None);
    assert_eq!(resolver.resolve(URI).unwrap(), ws.join("src/b_group/robot/meshes/m.stl"));
}

#[test]
fn unresolved_lists_every_place_looked_and_how_to_map_the_package() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let description = root.join("a/b/robot.urdf");
    let packages = Packages::new().with("robot", root.join("mine"));
    // Two ROS entries, an empty one between them skipped.
    let ros = std::env::join_paths([root.join("r1"), PathBuf::new(), root.join("r2")]).unwrap();
    let resolver = Resolver::with_env(
        &description,
        &packages,
        Some(ros.to_string_lossy().into_owned()),
        Some(root.join("p").to_string_lossy().into_owned()),
    );
    let error = resolver.resolve(URI).unwrap_err();
    assert_eq!(error.uri, URI);
    assert_eq!(error.kind, UnresolvedKind::Package { name: "robot".into(), environment: true });
    let rest = Path::new("robot/meshes/m.stl");
    let mut expected = vec![
        root.join("mine/meshes/m.stl"),
        root.join("r1").join(rest),
        root.join("r2").join(rest),
        root.join("p/share").join(rest),
    ];
    expected.extend(root.join("a/b").ancestors().map(|dir| dir.join(rest)));
    assert_eq!(error.looked, expected);
    let message = error.to_string();
    for path in &expected {
        assert!(message.contains(&path.display().to_string()), "{path:?} missing from: {message}");
    }
    for hint in [r#"packages(robot = "PATH")"#, r#".package("robot", "PATH")"#, "--package robot=PATH"] {
        assert!(message.contains(hint), "{hint} missing from: {message}");
    }
    assert!(!message.contains("are not set"));

    let bare = Resolver::with_env(&description, &Packages::new(), None, Some(String::new()));
    let message = bare.resolve(URI).unwrap_err().to_string();
    assert!(message.contains("(ROS_PACKAGE_PATH and AMENT_PREFIX_PATH are not set)"), "{message}");
}

#[test]
fn file_uris_and_paths_start_from_the_description_folder() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let mesh = root.join("robot/meshes/m.stl");
    write(&mesh, "");
    let resolver = Resolver::with_env(&root.join("robot/urdf/robot.urdf"), &Packages::new(), None, None);
    let absolute = mesh.to_string_lossy().into_owned();
    for uri in [
        format!("file://{absolute}"),
        "file://../meshes/m.stl".to_owned(),
        "../meshes/m.stl".to_owned(),
        "./../meshes/./m.stl".to_owned(),
        absolute.clone(),
    ] {
        assert_eq!(resolver.resolve(&uri).unwrap(), mesh, "{uri}");
    }

    let error = resolver.resolve("meshes/m.stl").unwrap_err();
    assert_eq!(error.kind, UnresolvedKind::NoFile);
    assert_eq!(error.looked, [root.join("robot/urdf/meshes/m.stl")]);
    assert!(error.to_string().contains("no such file"), "{error}");
    assert!(!error.to_string().contains("--package"), "{error}");
}

#[test]
fn a_description_named_without_a_folder_starts_from_the_current_one() {
    let resolver = Resolver::with_env(Path::new("robot.urdf"), &Packages::new(), None, None);
    assert_eq!(resolver.folder(), std::env::current_dir().unwrap());
    // The crate's own manifest, by a path relative to the test's working folder.
    assert_eq!(resolver.resolve("Cargo.toml").unwrap(), std::env::current_dir().unwrap().join("Cargo.toml"));
    // A relative package folder too: every file found is absolute.
    let resolver = Resolver::with_env(Path::new("robot.urdf"), &Packages::new().with("here", "./src/.."), None, None);
    assert_eq!(
        resolver.resolve("package://here/Cargo.toml").unwrap(),
        std::env::current_dir().unwrap().join("Cargo.toml")
    );
}

#[test]
fn other_schemes_and_malformed_uris_are_refused() {
    let resolver = Resolver::with_env(Path::new("/robots/robot.urdf"), &Packages::new(), None, None);
    for (uri, scheme) in [("http://example.com/m.stl", "http"), ("model://robot/meshes/m.dae", "model")] {
        let error = resolver.resolve(uri).unwrap_err();
        assert_eq!(error.kind, UnresolvedKind::Scheme { scheme: scheme.into() });
        assert!(error.looked.is_empty());
        assert!(error.to_string().contains(&format!("`{scheme}://` is not supported")), "{error}");
    }
    for uri in ["package://robot", "package:///meshes/m.stl", "package://robot/", ""] {
        let error = resolver.resolve(uri).unwrap_err();
        assert!(matches!(error.kind, UnresolvedKind::Malformed { .. }), "{uri}: {error:?}");
    }
}

#[test]
fn package_pairs_are_read_from_the_command_line_form() {
    assert_eq!(Packages::parse_pair("robot=/opt/robot"), Ok(("robot".to_owned(), PathBuf::from("/opt/robot"))));
    // Only the first `=` splits: a folder may hold one.
    assert_eq!(Packages::parse_pair("robot=a=b"), Ok(("robot".to_owned(), PathBuf::from("a=b"))));
    for bad in ["robot", "=/opt/robot", "robot=", "a/b=/opt"] {
        assert!(Packages::parse_pair(bad).is_err(), "{bad}");
    }
    let packages: Packages = [("a", "/x"), ("b", "/y"), ("a", "/z")].into_iter().collect();
    assert_eq!(packages.folders("a").collect::<Vec<_>>(), [Path::new("/x"), Path::new("/z")]);
    assert_eq!(packages.iter().count(), 3);
}
