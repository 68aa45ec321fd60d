//! Reading the description the attribute names and loading it through the model's one loader
//! (`kinematics_model::Source::load`), with errors spanned on the key.

use std::path::PathBuf;

use darling::Error;
use darling::util::SpannedValue;
use kinematics_model::{ExactAngles, KinematicTree, LoadError, LoadErrorKind, Source, SourceFormat, SourceKind};
use proc_macro2::{Span, TokenStream};
use quote::quote;

use crate::inline_dh::{InlineDh, LABEL};
use crate::options::{DhSource, KinematicsInput};

/// A description, read and validated.
pub struct Loaded {
    /// The validated tree.
    pub tree: KinematicTree,
    /// The name `reference()` parses the text under (the file as the user wrote it, with an
    /// extension naming the format when it has none).
    pub label: String,
    /// An expression of type `&'static str` with the text, which also makes the crate rebuild when
    /// the file changes (`include_str!` of its absolute path).
    pub text_expr: TokenStream,
}

/// Reads the description, checks the tree, base and tips; all faults together.
pub fn load(options: &KinematicsInput) -> darling::Result<Loaded> {
    let exact_angles = options.exact_angles();
    let loaded = match (&options.urdf, &options.dh) {
        (Some(path), None) => from_file(path, SourceKind::Urdf, exact_angles)?,
        (None, Some(dh)) => match dh.as_ref() {
            DhSource::File(path) => {
                from_file(&SpannedValue::new(path.clone(), dh.span()), SourceKind::Dh, exact_angles)?
            }
            DhSource::Inline(table) => from_inline(table, dh.span(), exact_angles)?,
        },
        (Some(_), Some(dh)) => {
            return Err(Error::custom("give one description: `urdf` or `dh`, not both").with_span(&dh.span()));
        }
        (None, None) => {
            return Err(Error::custom(
                "name the robot's description: `urdf = \"path\"`, `dh = \"path\"` or an inline `dh(...)` table",
            )
            .with_span(&options.ident));
        }
    };
    let mut errors = Error::accumulator();
    let mut links: Vec<(&'static str, SpannedValue<String>)> =
        options.base.iter().map(|b| ("base", b.clone())).collect();
    links.extend(options.tips().into_iter().map(|t| ("tip", t)));
    for (role, link) in &links {
        if let Err(e) = loaded.tree.find_link(role, link) {
            errors.push(Error::custom(format!("{}: {e}", loaded.label)).with_span(&link.span()));
        }
    }
    errors.finish_with(loaded)
}

fn from_file(path: &SpannedValue<String>, kind: SourceKind, exact_angles: ExactAngles) -> darling::Result<Loaded> {
    let span = path.span();
    let label = path.as_ref().clone();
    let root = std::env::var("CARGO_MANIFEST_DIR").map(PathBuf::from).unwrap_or_default();
    let absolute = root.join(&label);
    let bytes =
        std::fs::read(&absolute).map_err(|e| spanned(&LoadError::new(label.clone(), LoadErrorKind::Io(e)), span))?;
    let source = Source::from_bytes(label, kind, bytes).map_err(|e| spanned(&e, span))?;
    let tree = source.load(exact_angles).map_err(|e| spanned(&e, span))?;
    let absolute = absolute.to_string_lossy().into_owned();
    Ok(Loaded { tree, label: source.file_name(), text_expr: quote!(include_str!(#absolute)) })
}

fn from_inline(table: &InlineDh, span: Span, exact_angles: ExactAngles) -> darling::Result<Loaded> {
    let table = table.to_table().map_err(|e| e.with_span(&span))?;
    // The table as the DH file it stands for: loaded by the one loader, and the text
    // `reference()` parses, so both read the very same robot.
    let text = table.to_toml().map_err(|e| spanned(&LoadError::new(LABEL, e), span))?;
    let tree =
        Source::new(SourceFormat::DhToml, LABEL, text.clone()).load(exact_angles).map_err(|e| spanned(&e, span))?;
    Ok(Loaded { tree, label: "inline_dh.toml".to_owned(), text_expr: quote!(#text) })
}

/// A load error as compile errors on `span`: one per broken model rule, so all are shown.
fn spanned(error: &LoadError, span: Span) -> Error {
    match error.model_errors() {
        Some(errors) => Error::multiple(
            errors.errors().iter().map(|e| Error::custom(format!("{}: {e}", error.file)).with_span(&span)).collect(),
        ),
        None => Error::custom(error.to_string()).with_span(&span),
    }
}

impl std::fmt::Debug for Loaded {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Loaded").field("label", &self.label).finish_non_exhaustive()
    }
}
