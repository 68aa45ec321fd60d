//! Writing a file all at once: a temporary file beside it, then a rename.
//!
//! `write_atomic`: a `tempfile` in the same directory, given 0666 less the umask, then a rename;
//! unchanged contents are not rewritten.

use std::io::Write as _;
use std::path::Path;

/// Writes `contents` to `path` atomically: into a temporary file in the same directory, flushed,
/// then renamed over `path`. On any error the temporary file is removed, so `path` holds either its
/// old contents or the new ones, never half of them. An existing file with the same contents is
/// left untouched (its modification time too, so cargo does not rebuild for nothing). The file
/// gets ordinary permissions, as any file the user creates (`0o666` less the umask: `0o644`
/// usually), not the owner-only ones of a temporary file.
///
/// ```
/// let path = std::env::temp_dir().join(format!("kinematics-write-doc-{}.rs", std::process::id()));
/// kinematics_build::write_atomic(&path, "pub fn f() {}\n")?;
/// assert_eq!(std::fs::read_to_string(&path)?, "pub fn f() {}\n");
/// # std::fs::remove_file(&path)?;
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn write_atomic(path: &Path, contents: &str) -> std::io::Result<()> {
    if std::fs::read(path).is_ok_and(|old| old == contents.as_bytes()) {
        return Ok(());
    }
    let dir = match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    let prefix = format!(".{}.", path.file_name().map(|n| n.to_string_lossy()).unwrap_or_default());
    // Dropping the temporary file on an error path deletes it.
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    // The mode is given to `open`, which takes the umask off, as for any new file.
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    let mut file = builder.tempfile_in(dir)?;
    file.write_all(contents.as_bytes())?;
    file.as_file().sync_all()?;
    file.persist(path).map_err(|e| e.error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::write_atomic;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("kinematics-build-write-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn entries(dir: &std::path::Path) -> Vec<String> {
        let mut names: Vec<String> =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        names
    }

    #[test]
    fn replaces_the_file_and_leaves_nothing_else() {
        let dir = scratch("replace");
        let path = dir.join("fk.rs");
        write_atomic(&path, "old").unwrap();
        write_atomic(&path, "new").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new");
        assert_eq!(entries(&dir), ["fk.rs"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_failed_write_leaves_no_file_behind() {
        let dir = scratch("fail");
        // The target is a directory: the rename fails after the temporary file was written.
        let target = dir.join("occupied");
        std::fs::create_dir_all(target.join("inside")).unwrap();
        assert!(write_atomic(&target, "text").is_err());
        assert_eq!(entries(&dir), ["occupied"]);
        // A missing directory fails before anything is written.
        assert!(write_atomic(&dir.join("missing").join("fk.rs"), "text").is_err());
        assert_eq!(entries(&dir), ["occupied"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
