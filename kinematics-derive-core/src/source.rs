//! Reading and validating the description the attribute names, with errors spanned on the key.

use std::path::PathBuf;

use darling::Error;
use darling::util::SpannedValue;
use kinematics_model::{KinematicTree, SourceFormat};
use proc_macro2::{Span, TokenStream};
use quote::quote;

use crate::options::{DhSource, KinematicsInput};

/// A description, read and validated.
pub struct Loaded {
    /// The validated tree.
    pub tree: KinematicTree,
    /// The file as the user wrote it (for messages and for `reference()`).
    pub label: String,
    /// An expression of type `&'static str` with the text, which also makes the crate rebuild when
    /// the file changes (`include_str!` of its absolute path).
    pub text_expr: TokenStream,
}

/// Reads the description, checks the tree, base and tips; all faults together.
pub fn load(options: &KinematicsInput) -> darling::Result<Loaded> {
    let loaded = match (&options.urdf, &options.dh) {
        (Some(path), None) => from_file(path, SourceFormat::Urdf)?,
        (None, Some(dh)) => match dh.as_ref() {
            DhSource::File(path) => {
                let format = if path.to_ascii_lowercase().ends_with(".json") {
                    SourceFormat::DhJson
                } else {
                    SourceFormat::DhToml
                };
                from_file(&SpannedValue::new(path.clone(), dh.span()), format)?
            }
            DhSource::Inline(table) => from_inline(table, dh.span())?,
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
    let mut links: Vec<(&str, SpannedValue<String>)> = options.base.iter().map(|b| ("base", b.clone())).collect();
    links.extend(options.tips().into_iter().map(|t| ("tip", t)));
    for (what, link) in &links {
        if loaded.tree.link_id(link).is_none() {
            let hint = loaded.tree.suggest_link(link).map(|c| format!("; did you mean `{c}`?")).unwrap_or_default();
            errors.push(
                Error::custom(format!("{}: {what} link `{}` does not exist{hint}", loaded.label, link.as_ref()))
                    .with_span(&link.span()),
            );
        }
    }
    errors.finish_with(loaded)
}

fn from_file(path: &SpannedValue<String>, format: SourceFormat) -> darling::Result<Loaded> {
    let span = path.span();
    let label = path.as_ref().clone();
    let root = std::env::var("CARGO_MANIFEST_DIR").map(PathBuf::from).unwrap_or_default();
    let absolute = root.join(&label);
    let text = std::fs::read_to_string(&absolute)
        .map_err(|e| Error::custom(format!("cannot read `{label}`: {e}")).with_span(&span))?;
    let tree = parse(&label, &text, format, span)?;
    let absolute = absolute.to_string_lossy().into_owned();
    // `reference()` picks the format from the name: make sure the name says what this file is.
    let reference_label = match SourceFormat::from_file_name(&label) {
        Some(f) if f == format => label.clone(),
        _ => format!("{label}.{}", if format == SourceFormat::Urdf { "urdf" } else { "toml" }),
    };
    Ok(Loaded { tree, label: reference_label, text_expr: quote!(include_str!(#absolute)) })
}

fn from_inline(table: &crate::inline_dh::InlineDh, span: Span) -> darling::Result<Loaded> {
    let label = "inline DH table";
    let table = table.to_table().map_err(|e| e.with_span(&span))?;
    let description = table.to_description().map_err(|e| Error::custom(format!("{label}: {e}")).with_span(&span))?;
    let tree = KinematicTree::from_description(&description).map_err(|errors| {
        Error::multiple(
            errors.errors().iter().map(|e| Error::custom(format!("{label}: {e}")).with_span(&span)).collect(),
        )
    })?;
    let text = table.to_toml().map_err(|e| Error::custom(format!("{label}: {e}")).with_span(&span))?;
    Ok(Loaded { tree, label: "inline_dh.toml".to_owned(), text_expr: quote!(#text) })
}

fn parse(label: &str, text: &str, format: SourceFormat, span: Span) -> darling::Result<KinematicTree> {
    let error = |message: String| Error::custom(format!("{label}: {message}")).with_span(&span);
    let description = format.parse(text).map_err(|e| error(e.to_string()))?;
    KinematicTree::from_description(&description)
        .map_err(|errors| Error::multiple(errors.errors().iter().map(|e| error(e.to_string())).collect()))
}

impl std::fmt::Debug for Loaded {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Loaded").field("label", &self.label).finish_non_exhaustive()
    }
}
