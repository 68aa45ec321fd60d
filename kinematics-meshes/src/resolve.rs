//! URI resolution: which file a `<mesh filename>` names, given the description's folder, the
//! user's packages and the ROS environment.

use std::ffi::OsString;
use std::path::{Component, Path, PathBuf};

use crate::packages::Packages;
use crate::ros;
use crate::unresolved::{Unresolved, UnresolvedKind};

/// How mesh URIs are resolved: the description file's folder, the user's [`Packages`], and the
/// environment (`ROS_PACKAGE_PATH`, `AMENT_PREFIX_PATH`), read once when it is made.
///
/// **`package://NAME/REST`**: the first of these files that exists wins:
/// 1. `FOLDER/REST` for each folder the user gave for `NAME` ([`Packages`]), in order;
/// 2. for each entry of `ROS_PACKAGE_PATH`: `ENTRY/NAME/REST`, then `PKG/REST` for every folder
///    `PKG` named `NAME` holding a `package.xml` found below the entry (ROS 1 searches these
///    entries recursively: here at most 4 levels down, hidden folders and folders holding
///    `CATKIN_IGNORE` or `COLCON_IGNORE` skipped, no descent into a package, in sorted order);
/// 3. for each prefix of `AMENT_PREFIX_PATH` (ROS 2): `PREFIX/share/NAME/REST`;
/// 4. `DIR/NAME/REST` for `DIR` the description's folder and each folder above it, up to the root
///    (a package checked out beside, or holding, the description).
///
/// **`file://PATH`** and a plain path: absolute as written, relative from the description's folder.
/// Any other scheme (`http://`, `model://`) is refused. Resolution only finds the file; reading
/// it is [`read_mesh`](crate::read_mesh).
///
/// ```
/// use kinematics_meshes::{Packages, Resolver};
///
/// // A package `arm_description` with a mesh, and the URDF inside it.
/// let root = std::env::temp_dir().join(format!("kinematics-meshes-doc-{}", std::process::id()));
/// std::fs::create_dir_all(root.join("arm_description/meshes"))?;
/// std::fs::create_dir_all(root.join("arm_description/urdf"))?;
/// let mesh = root.join("arm_description/meshes/base.stl");
/// std::fs::write(&mesh, "solid base\nendsolid base\n")?;
///
/// // No environment: the package is found as a folder above the description.
/// let description = root.join("arm_description/urdf/arm.urdf");
/// let resolver = Resolver::with_env(&description, &Packages::new(), None, None);
/// assert_eq!(resolver.resolve("package://arm_description/meshes/base.stl")?, mesh);
/// assert_eq!(resolver.resolve("../meshes/base.stl")?, mesh);
///
/// // A package nowhere to be found: the error lists every place looked.
/// let error = resolver.resolve("package://gripper/meshes/finger.stl").unwrap_err();
/// assert!(error.to_string().contains("--package gripper=PATH"));
/// std::fs::remove_dir_all(&root)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Resolver {
    /// The description's folder, absolute and without `.` or `..` (the ancestor rule walks it).
    folder: PathBuf,
    packages: Packages,
    ros_package_path: Vec<PathBuf>,
    ament_prefix_path: Vec<PathBuf>,
}

impl Resolver {
    /// The resolver for the description file at `description` (relative URIs and the folders
    /// above start from its folder), with the user's `packages` and `ROS_PACKAGE_PATH` and
    /// `AMENT_PREFIX_PATH` as the environment has them now.
    pub fn new(description: &Path, packages: &Packages) -> Self {
        Self::build(description, packages, std::env::var_os("ROS_PACKAGE_PATH"), std::env::var_os("AMENT_PREFIX_PATH"))
    }

    /// [`new`](Self::new) with the two variables given rather than read (for tests, and front
    /// ends that take them from elsewhere); `None` is unset. Each is a list of folders joined as
    /// the platform joins `PATH` (`:` on Unix).
    pub fn with_env(
        description: &Path,
        packages: &Packages,
        ros_package_path: Option<String>,
        ament_prefix_path: Option<String>,
    ) -> Self {
        Self::build(description, packages, ros_package_path.map(OsString::from), ament_prefix_path.map(OsString::from))
    }

    fn build(
        description: &Path,
        packages: &Packages,
        ros_package_path: Option<OsString>,
        ament_prefix_path: Option<OsString>,
    ) -> Self {
        // Every folder absolute (from the current folder, now), so that every file found is: a
        // derive's `include_bytes!` and a build script's `rerun-if-changed` need that.
        let absolute = |p: &Path| normalise(&std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf()));
        let split = |list: Option<OsString>| -> Vec<PathBuf> {
            // An empty entry (`a::b`, a trailing `:`) names no folder.
            list.map(|l| {
                std::env::split_paths(&l).filter(|p| !p.as_os_str().is_empty()).map(|p| absolute(&p)).collect()
            })
            .unwrap_or_default()
        };
        let folder = description.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        Resolver {
            folder: absolute(folder),
            packages: packages.iter().map(|(name, path)| (name, absolute(path))).collect(),
            ros_package_path: split(ros_package_path),
            ament_prefix_path: split(ament_prefix_path),
        }
    }

    /// The description's folder (absolute): where relative URIs start.
    pub fn folder(&self) -> &Path {
        &self.folder
    }

    /// The file `uri` names (an absolute path, without `.` or `..`), or an error listing every
    /// place looked (see [`Resolver`] for the order).
    pub fn resolve(&self, uri: &str) -> Result<PathBuf, Unresolved> {
        let fail = |kind, looked| Unresolved { uri: uri.to_owned(), kind, looked };
        if let Some(after) = uri.strip_prefix("package://") {
            let Some((name, rest)) = after.split_once('/').filter(|(n, r)| !n.is_empty() && !r.is_empty()) else {
                return Err(fail(UnresolvedKind::Malformed { expected: "package://NAME/PATH" }, Vec::new()));
            };
            let mut looked = Vec::new();
            return match self.find_in_package(name, rest.trim_start_matches('/'), &mut looked) {
                Some(path) => Ok(path),
                None => {
                    let environment = !(self.ros_package_path.is_empty() && self.ament_prefix_path.is_empty());
                    Err(fail(UnresolvedKind::Package { name: name.to_owned(), environment }, looked))
                }
            };
        }
        let path = match uri.strip_prefix("file://") {
            // `file://localhost/a` is `file:///a`.
            Some(after) => after.strip_prefix("localhost").filter(|a| a.starts_with('/')).unwrap_or(after),
            None => match uri.split_once("://") {
                Some((scheme, _)) if is_scheme(scheme) => {
                    return Err(fail(UnresolvedKind::Scheme { scheme: scheme.to_owned() }, Vec::new()));
                }
                _ => uri,
            },
        };
        if path.is_empty() {
            return Err(fail(UnresolvedKind::Malformed { expected: "a file name" }, Vec::new()));
        }
        let path = normalise(&self.folder.join(path));
        if path.is_file() { Ok(path) } else { Err(fail(UnresolvedKind::NoFile, vec![path])) }
    }

    /// The first `FOLDER/rest` that is a file, `FOLDER` running through package `name`'s
    /// candidate folders in order; every file tried is added to `looked`. The ROS search below an
    /// entry runs only when the entry's own `NAME` folder lacks the file, so a sourced workspace
    /// costs a walk only for packages that are not where they usually are.
    fn find_in_package(&self, name: &str, rest: &str, looked: &mut Vec<PathBuf>) -> Option<PathBuf> {
        let mut try_folder = |folder: &Path| {
            let file = normalise(&folder.join(rest));
            let found = file.is_file();
            looked.push(file.clone());
            found.then_some(file)
        };
        if let Some(file) = self.packages.folders(name).find_map(&mut try_folder) {
            return Some(file);
        }
        for entry in &self.ros_package_path {
            let direct = entry.join(name);
            if let Some(file) = try_folder(&direct) {
                return Some(file);
            }
            let mut below = ros::packages_named(entry, name).into_iter().filter(|p| *p != direct);
            if let Some(file) = below.find_map(|p| try_folder(&p)) {
                return Some(file);
            }
        }
        if let Some(file) = self.ament_prefix_path.iter().find_map(|p| try_folder(&p.join("share").join(name))) {
            return Some(file);
        }
        self.folder.ancestors().find_map(|dir| try_folder(&dir.join(name)))
    }
}

/// Whether `s` is a URI scheme (RFC 3986: a letter, then letters, digits, `+`, `-`, `.`; more than
/// one character, since `C:` is a Windows drive), so that a path holding `://` further on is still
/// a path.
fn is_scheme(s: &str) -> bool {
    let mut chars = s.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || matches!(c, '+' | '-' | '.'))
        && s.len() > 1
}

/// `path` without `.` and with `..` taken lexically: the folders above `a/b/../c` are `a` and
/// the root, not `a/b`, and `urdf/../meshes/m.stl` and `meshes/m.stl` are one file to
/// [`load_tree_meshes`](crate::load_tree_meshes). (Lexical, not `canonicalize`: a description
/// reached through a symlinked folder keeps the folders it was named by, which is where a user
/// looks for its packages.)
fn normalise(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for component in path.components() {
        match component {
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            other => out.push(other),
        }
    }
    out
}
