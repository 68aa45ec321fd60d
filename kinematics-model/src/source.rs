//! Choosing the front end from a file name, and the one-call path from text to a tree.

use crate::description::Description;
use crate::error::{LoadError, LoadErrorKind};
use crate::exactness::ExactAngles;
use crate::tree::KinematicTree;

/// The description formats this crate reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SourceFormat {
    /// URDF (XML).
    Urdf,
    /// DH table in TOML.
    DhToml,
    /// DH table in JSON.
    DhJson,
}

impl SourceFormat {
    /// The format a file name's extension names: `.urdf`/`.xml`, `.toml`, `.json`.
    pub fn from_file_name(name: &str) -> Option<Self> {
        let ext = name.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase())?;
        match ext.as_str() {
            "urdf" | "xml" => Some(Self::Urdf),
            "toml" => Some(Self::DhToml),
            "json" => Some(Self::DhJson),
            _ => None,
        }
    }

    /// Parses `text` in this format into a description.
    pub fn parse(self, text: &str) -> Result<Description, LoadErrorKind> {
        match self {
            Self::Urdf => crate::urdf::parse_urdf(text),
            Self::DhToml => crate::dh::parse_dh_toml(text)?.to_description(),
            Self::DhJson => crate::dh::parse_dh_json(text)?.to_description(),
        }
    }
}

/// Parses and validates a description; `file` names it in errors and picks the format by extension.
///
/// The caller reads the file (this crate does no IO), so `file` is whatever the user should see.
pub fn parse_source(file: &str, text: &str) -> Result<KinematicTree, LoadError> {
    parse_source_with(file, text, ExactAngles::default())
}

/// [`parse_source`] with the exactness policy `exact_angles`.
pub fn parse_source_with(file: &str, text: &str, exact_angles: ExactAngles) -> Result<KinematicTree, LoadError> {
    let error = |kind| LoadError::new(file, kind);
    let format = SourceFormat::from_file_name(file).ok_or_else(|| error(LoadErrorKind::UnknownFormat))?;
    let description = format.parse(text).map_err(error)?;
    KinematicTree::from_description_with(&description, exact_angles).map_err(|e| error(LoadErrorKind::Model(e)))
}
