//! The ROS 1 package crawl: the folders named like a package, holding a `package.xml`, below a
//! `ROS_PACKAGE_PATH` entry.

use std::fs;
use std::path::{Path, PathBuf};

/// How many folders below an entry a package may sit (`ENTRY/a/b/c/NAME` is 4): deep enough for a
/// catkin workspace's `src/group/repository/package`, shallow enough that an entry pointing at a
/// home folder is not walked whole.
pub(crate) const MAX_DEPTH: usize = 4;

/// The folders named `name` that hold a `package.xml`, at most [`MAX_DEPTH`] below `entry` (the
/// entry itself if it is such a folder), in sorted order. As `rospack` crawls: hidden folders and
/// folders marked `CATKIN_IGNORE` or `COLCON_IGNORE` are skipped, and a package's own folders are
/// not searched for more packages. Unreadable folders are passed over: the error that matters is
/// the file not found, which lists where it was looked for.
pub(crate) fn packages_named(entry: &Path, name: &str) -> Vec<PathBuf> {
    let mut found = Vec::new();
    if is_package(entry) {
        if entry.file_name().is_some_and(|n| n == name) {
            found.push(entry.to_path_buf());
        }
        return found;
    }
    crawl(entry, name, 1, &mut found);
    found
}

fn crawl(dir: &Path, name: &str, depth: usize, found: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    let mut folders: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .filter(|e| !e.file_name().to_string_lossy().starts_with('.'))
        .map(|e| e.path())
        // `is_dir` follows symlinks, as rospack does; the depth bound ends any cycle.
        .filter(|p| p.is_dir())
        .collect();
    // Sorted, so that two packages of one name are found in the same order on every machine.
    folders.sort();
    for folder in folders {
        // As rospack: an ignore marker hides the folder, a package among it too.
        if is_ignored(&folder) {
            continue;
        }
        if is_package(&folder) {
            if folder.file_name().is_some_and(|n| n == name) {
                found.push(folder);
            }
        } else if depth < MAX_DEPTH {
            crawl(&folder, name, depth + 1, found);
        }
    }
}

fn is_package(folder: &Path) -> bool {
    folder.join("package.xml").is_file()
}

fn is_ignored(folder: &Path) -> bool {
    folder.join("CATKIN_IGNORE").exists() || folder.join("COLCON_IGNORE").exists()
}
