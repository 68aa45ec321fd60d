//! The user's package folders: where `package://NAME/...` is looked for first, before the ROS
//! environment and the folders above the description (see [`Resolver`](crate::Resolver)).

use std::path::{Path, PathBuf};

/// Where `package://NAME/...` is looked for, beside the defaults: the user's mapping from a
/// package name to its folder, in the order given.
///
/// A name may be given more than once; its folders are then tried in that order. A relative folder
/// is from the current directory when the [`Resolver`](crate::Resolver) is made: a front end whose
/// paths mean something else makes them absolute first (the derive, against the crate's manifest
/// folder).
///
/// ```
/// use kinematics_meshes::Packages;
///
/// let packages = Packages::new().with("ur_description", "/opt/ur/ur_description");
/// assert_eq!(packages.folders("ur_description").count(), 1);
/// let (name, path) = Packages::parse_pair("franka_description=vendor/franka").unwrap();
/// assert_eq!((name.as_str(), path.to_str()), ("franka_description", Some("vendor/franka")));
/// ```
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Packages {
    entries: Vec<(String, PathBuf)>,
}

impl Packages {
    /// No mapping: only the defaults are searched.
    pub fn new() -> Self {
        Self::default()
    }

    /// This mapping with `name` found in `path` (after any folder already given for `name`).
    #[must_use]
    pub fn with(mut self, name: impl Into<String>, path: impl Into<PathBuf>) -> Self {
        self.insert(name, path);
        self
    }

    /// Adds `name` found in `path` (after any folder already given for `name`).
    pub fn insert(&mut self, name: impl Into<String>, path: impl Into<PathBuf>) {
        self.entries.push((name.into(), path.into()));
    }

    /// Reads `NAME=PATH`, as the command line's `--package` gives it; the error says what is wrong
    /// (it fits clap's `value_parser`).
    pub fn parse_pair(s: &str) -> Result<(String, PathBuf), String> {
        let Some((name, path)) = s.split_once('=') else {
            return Err(format!("`{s}` is not NAME=PATH (no `=`)"));
        };
        let name = name.trim();
        if name.is_empty() {
            return Err(format!("`{s}` has no package name before `=`"));
        }
        // A package name is one folder name: `package://a/b/...` names package `a`.
        if name.contains(['/', '\\']) {
            return Err(format!("`{name}` is not a package name (it has a `/`)"));
        }
        if path.is_empty() {
            return Err(format!("`{s}` has no folder after `=`"));
        }
        Ok((name.to_owned(), PathBuf::from(path)))
    }

    /// The folders given for `name`, in order.
    pub fn folders<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Path> + 'a {
        self.entries.iter().filter(move |(n, _)| n == name).map(|(_, p)| p.as_path())
    }

    /// Every `(name, folder)` pair, in the order given.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &Path)> {
        self.entries.iter().map(|(n, p)| (n.as_str(), p.as_path()))
    }

    /// Whether no folder was given.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
}

impl<N: Into<String>, P: Into<PathBuf>> FromIterator<(N, P)> for Packages {
    fn from_iter<I: IntoIterator<Item = (N, P)>>(iter: I) -> Self {
        let mut packages = Packages::new();
        packages.extend(iter);
        packages
    }
}

impl<N: Into<String>, P: Into<PathBuf>> Extend<(N, P)> for Packages {
    fn extend<I: IntoIterator<Item = (N, P)>>(&mut self, iter: I) {
        for (name, path) in iter {
            self.insert(name, path);
        }
    }
}
