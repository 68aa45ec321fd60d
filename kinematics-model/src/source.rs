//! The one front end: a description's text with its format and the name the user knows it by
//! ([`Source`]), and the one path from it to a validated tree ([`Source::load`]).
//!
//! Every entry point (the `kinematics::load` facade, the build API, the derive, the command line)
//! reads the file's bytes, builds a [`Source`] and calls [`Source::load`] with its exactness
//! policy; none of them picks a format or parses on its own. The format is chosen here, in
//! [`SourceFormat::choose`]: from the file name's extension, or as the caller's kind says; a
//! `.xml` file is URDF or MJCF as its root element (`<robot>` or `<mujoco>`) says
//! ([`SourceFormat::detect`]). An MJCF file may name others (`<include>`, `<model file>`): the
//! caller reads them ([`Source::load_reading`] takes a [`ReadFile`]), since this crate does no IO.
//!
//! `Source::load(ExactAngles)` and `load_reading` are the one loader the facade, the build API, the
//! derive and the CLI call (the last three with a reader of files relative to the description's
//! directory); generated `reference()` functions read the files embedded beside the text
//! (`parse_source_files`).

use crate::description::Description;
use crate::error::{LoadError, LoadErrorKind};
use crate::exactness::ExactAngles;
use crate::mjcf::ReadFile;
use crate::tree::KinematicTree;

/// The description formats this crate reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SourceFormat {
    /// URDF (XML).
    Urdf,
    /// MJCF, MuJoCo's XML ([`crate::mjcf`]).
    Mjcf,
    /// DH table in TOML.
    DhToml,
    /// DH table in JSON.
    DhJson,
}

/// What the caller knows of a file's format before looking at its name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SourceKind {
    /// Nothing: the extension decides (`.urdf`, `.xml` (URDF or MJCF by its root element),
    /// `.mjcf`, `.toml`, `.json`; anything else is refused).
    #[default]
    ByExtension,
    /// A URDF document, whatever its name.
    Urdf,
    /// An MJCF document, whatever its name.
    Mjcf,
    /// A DH table: JSON if the name ends in `.json`, TOML otherwise.
    Dh,
}

impl SourceFormat {
    /// The format a file name's extension names: `.urdf`, `.mjcf`, `.toml`, `.json`, and
    /// `.xml` as URDF (whose text may say MJCF instead: [`SourceFormat::detect`]).
    pub fn from_file_name(name: &str) -> Option<Self> {
        let ext = name.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase())?;
        match ext.as_str() {
            "urdf" | "xml" => Some(Self::Urdf),
            "mjcf" => Some(Self::Mjcf),
            "toml" => Some(Self::DhToml),
            "json" => Some(Self::DhJson),
            _ => None,
        }
    }

    /// The format of the file `name` of kind `kind` (the one place a format is chosen).
    ///
    /// ```
    /// use kinematics_model::{SourceFormat, SourceKind};
    /// assert_eq!(SourceFormat::choose("arm.xml", SourceKind::ByExtension), Some(SourceFormat::Urdf));
    /// assert_eq!(SourceFormat::choose("arm.xacro", SourceKind::ByExtension), None);
    /// assert_eq!(SourceFormat::choose("arm.xacro", SourceKind::Urdf), Some(SourceFormat::Urdf));
    /// assert_eq!(SourceFormat::choose("arm.JSON", SourceKind::Dh), Some(SourceFormat::DhJson));
    /// assert_eq!(SourceFormat::choose("arm.table", SourceKind::Dh), Some(SourceFormat::DhToml));
    /// ```
    pub fn choose(name: &str, kind: SourceKind) -> Option<Self> {
        match kind {
            SourceKind::ByExtension => Self::from_file_name(name),
            SourceKind::Urdf => Some(Self::Urdf),
            SourceKind::Mjcf => Some(Self::Mjcf),
            SourceKind::Dh if Self::from_file_name(name) == Some(Self::DhJson) => Some(Self::DhJson),
            SourceKind::Dh => Some(Self::DhToml),
        }
    }

    /// [`SourceFormat::choose`], then for a `.xml` file chosen by its extension, the format its
    /// root element names: `<mujoco>` is MJCF, anything else stays URDF (whose reader then says
    /// what is wrong).
    ///
    /// ```
    /// use kinematics_model::{SourceFormat, SourceKind};
    /// let mjcf = "<?xml version=\"1.0\"?>\n<!-- arm -->\n<mujoco model=\"arm\"/>";
    /// assert_eq!(SourceFormat::detect("arm.xml", SourceKind::ByExtension, mjcf), Some(SourceFormat::Mjcf));
    /// assert_eq!(SourceFormat::detect("arm.xml", SourceKind::ByExtension, "<robot/>"), Some(SourceFormat::Urdf));
    /// // An explicit kind is obeyed (the URDF reader then refuses `<mujoco>` by name).
    /// assert_eq!(SourceFormat::detect("arm.xml", SourceKind::Urdf, mjcf), Some(SourceFormat::Urdf));
    /// ```
    pub fn detect(name: &str, kind: SourceKind, text: &str) -> Option<Self> {
        let chosen = Self::choose(name, kind)?;
        let xml = name.rsplit_once('.').is_some_and(|(_, e)| e.eq_ignore_ascii_case("xml"));
        if kind == SourceKind::ByExtension && xml && root_element(text) == Some("mujoco") {
            return Some(Self::Mjcf);
        }
        Some(chosen)
    }

    /// The extension naming this format (`urdf`, `mjcf`, `toml`, `json`).
    pub fn extension(self) -> &'static str {
        match self {
            Self::Urdf => "urdf",
            Self::Mjcf => "mjcf",
            Self::DhToml => "toml",
            Self::DhJson => "json",
        }
    }

    /// Parses `text` in this format into a description (an MJCF file that names another file is
    /// an error here: [`SourceFormat::parse_reading`]).
    pub fn parse(self, text: &str) -> Result<Description, LoadErrorKind> {
        match self {
            Self::Mjcf => crate::mjcf::parse_mjcf(text),
            other => other.parse_reading(text, &|_| Err(String::new())),
        }
    }

    /// [`SourceFormat::parse`], reading the files an MJCF document names through `read`.
    pub fn parse_reading(self, text: &str, read: ReadFile<'_>) -> Result<Description, LoadErrorKind> {
        match self {
            Self::Urdf => crate::urdf::parse_urdf(text),
            Self::Mjcf => crate::mjcf::parse_mjcf_with(text, read),
            Self::DhToml => crate::dh::parse_dh_toml(text)?.to_description(),
            Self::DhJson => crate::dh::parse_dh_json(text)?.to_description(),
        }
    }
}

/// A description to load: its format, the name the user knows it by, and its text.
///
/// ```
/// use kinematics_model::{ExactAngles, Source, SourceKind};
///
/// let urdf = r#"<robot name="r"><link name="a"/><link name="b"/>
///   <joint name="j" type="fixed"><parent link="a"/><child link="b"/>
///     <origin rpy="3.14159265359 0 0"/></joint></robot>"#;
/// let source = Source::from_file_name("robots/r.urdf", SourceKind::ByExtension, urdf)?;
/// assert_eq!(source.load(ExactAngles::default())?.recognised_angles().len(), 1);
/// assert!(source.load(ExactAngles::Off)?.recognised_angles().is_empty());
/// # Ok::<(), kinematics_model::LoadError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Source {
    /// The format the text is in.
    pub format: SourceFormat,
    /// The file as the user wrote it (names it in every error).
    pub label: String,
    /// The description.
    pub text: String,
}

impl Source {
    /// A source whose format is given.
    pub fn new(format: SourceFormat, label: impl Into<String>, text: impl Into<String>) -> Self {
        Source { format, label: label.into(), text: text.into() }
    }

    /// A source whose format [`SourceFormat::choose`] picks from `label` and `kind`; an
    /// unknown extension is [`LoadErrorKind::UnknownFormat`].
    pub fn from_file_name(
        label: impl Into<String>,
        kind: SourceKind,
        text: impl Into<String>,
    ) -> Result<Self, LoadError> {
        let (label, text) = (label.into(), text.into());
        match SourceFormat::detect(&label, kind, &text) {
            Some(format) => Ok(Source { format, label, text }),
            None => Err(LoadError::new(label, LoadErrorKind::UnknownFormat)),
        }
    }

    /// A source from a file's bytes: the format as [`SourceFormat::choose`] picks it from `label`
    /// and `kind`; the bytes must be UTF-8 (the line of the first stray byte is reported).
    pub fn from_bytes(label: impl Into<String>, kind: SourceKind, bytes: Vec<u8>) -> Result<Self, LoadError> {
        let label = label.into();
        if SourceFormat::choose(&label, kind).is_none() {
            return Err(LoadError::new(label, LoadErrorKind::UnknownFormat));
        }
        match String::from_utf8(bytes) {
            Ok(text) => Self::from_file_name(label, kind, text),
            Err(e) => {
                let valid = e.utf8_error().valid_up_to();
                let line = e.as_bytes()[..valid].iter().filter(|&&b| b == b'\n').count() + 1;
                let message = "the text is not UTF-8".to_owned();
                Err(LoadError::new(label, LoadErrorKind::Syntax { line: Some(line), message }))
            }
        }
    }

    /// A name [`parse_source`] reads in this source's format: the label when its extension
    /// already names the format, else the label with that extension appended (`arm.table` as a
    /// DH table becomes `arm.table.toml`). Generated `reference()` functions parse under it.
    pub fn file_name(&self) -> String {
        match SourceFormat::detect(&self.label, SourceKind::ByExtension, &self.text) {
            Some(format) if format == self.format => self.label.clone(),
            _ => format!("{}.{}", self.label, self.format.extension()),
        }
    }

    /// Parses and validates the description with the exactness policy `exact_angles`: the one
    /// path from text to tree.
    pub fn load(&self, exact_angles: ExactAngles) -> Result<KinematicTree, LoadError> {
        self.load_with_floating_base(exact_angles, None)
    }

    /// [`Source::load`], with a free-flying root when `floating_base` names the new root link
    /// ([`crate::Description::with_floating_base`]).
    pub fn load_with_floating_base(
        &self,
        exact_angles: ExactAngles,
        floating_base: Option<&str>,
    ) -> Result<KinematicTree, LoadError> {
        let error = |kind| LoadError::new(self.label.clone(), kind);
        let description = self.format.parse(&self.text).map_err(error)?;
        self.validate(description, exact_angles, floating_base)
    }

    /// [`Source::load_with_floating_base`], reading the files an MJCF description names
    /// (`<include file>`, `<model file>`) through `read`, which gets each path as written.
    pub fn load_reading(
        &self,
        exact_angles: ExactAngles,
        floating_base: Option<&str>,
        read: ReadFile<'_>,
    ) -> Result<KinematicTree, LoadError> {
        let error = |kind| LoadError::new(self.label.clone(), kind);
        let description = self.format.parse_reading(&self.text, read).map_err(error)?;
        self.validate(description, exact_angles, floating_base)
    }

    fn validate(
        &self,
        mut description: Description,
        exact_angles: ExactAngles,
        floating_base: Option<&str>,
    ) -> Result<KinematicTree, LoadError> {
        let error = |kind| LoadError::new(self.label.clone(), kind);
        if let Some(link) = floating_base {
            description = description.with_floating_base(link);
        }
        KinematicTree::from_description_with(&description, exact_angles).map_err(|e| error(LoadErrorKind::Model(e)))
    }
}

/// Parses and validates a description; `file` names it in errors and picks the format by extension.
///
/// The caller reads the file (this crate does no IO), so `file` is whatever the user should see.
pub fn parse_source(file: &str, text: &str) -> Result<KinematicTree, LoadError> {
    parse_source_with(file, text, ExactAngles::default())
}

/// [`parse_source_with`] with a free-flying root named `floating_base`
/// ([`crate::Description::with_floating_base`]).
pub fn parse_source_floating(
    file: &str,
    text: &str,
    exact_angles: ExactAngles,
    floating_base: &str,
) -> Result<KinematicTree, LoadError> {
    Source::from_file_name(file, SourceKind::ByExtension, text)?
        .load_with_floating_base(exact_angles, Some(floating_base))
}

/// [`parse_source_with`] (or [`parse_source_floating`] when `floating_base` names a root) for a
/// description that names other files (an MJCF `<include>` or `<model file>`): `files` holds
/// each as (path as written, text), as generated `reference()` functions embed them.
pub fn parse_source_files(
    file: &str,
    text: &str,
    files: &[(&str, &str)],
    exact_angles: ExactAngles,
    floating_base: Option<&str>,
) -> Result<KinematicTree, LoadError> {
    let read = |path: &str| {
        files.iter().find(|(p, _)| *p == path).map(|(_, t)| (*t).to_owned()).ok_or_else(|| "not embedded".to_owned())
    };
    Source::from_file_name(file, SourceKind::ByExtension, text)?.load_reading(exact_angles, floating_base, &read)
}

/// [`parse_source`] with the exactness policy `exact_angles`.
pub fn parse_source_with(file: &str, text: &str, exact_angles: ExactAngles) -> Result<KinematicTree, LoadError> {
    Source::from_file_name(file, SourceKind::ByExtension, text)?.load(exact_angles)
}

/// The name of the first element of an XML text (after the declaration, comments, a doctype and
/// processing instructions), if the text begins as XML does.
fn root_element(text: &str) -> Option<&str> {
    let mut rest = text.trim_start_matches('\u{feff}').trim_start();
    loop {
        if let Some(after) = rest.strip_prefix("<!--") {
            rest = after.split_once("-->")?.1.trim_start();
        } else if rest.starts_with("<?") || rest.starts_with("<!") {
            rest = rest.split_once('>')?.1.trim_start();
        } else {
            let after = rest.strip_prefix('<')?;
            let end = after.find(|c: char| c.is_whitespace() || c == '>' || c == '/').unwrap_or(after.len());
            return Some(&after[..end]);
        }
    }
}
