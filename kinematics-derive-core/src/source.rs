//! Reading the description the attribute names and loading it through the model's one loader
//! (`kinematics_model::Source::load`), with errors spanned on the key.
//!
//! The file is read relative to `CARGO_MANIFEST_DIR`.

use std::path::PathBuf;

use darling::Error;
use darling::util::SpannedValue;
use kinematics_compiler::options::floating_base_clash;
use kinematics_model::{ExactAngles, KinematicTree, LoadError, LoadErrorKind, Source, SourceFormat, SourceKind};
use proc_macro2::{Span, TokenStream};
use quote::quote;

use crate::inline_dh::{InlineDh, LABEL};
use crate::options::{DhSource, SourceOptions};

/// A description, read and validated.
pub struct Loaded {
    /// The validated tree.
    pub tree: KinematicTree,
    /// The name `reference()` parses the text under (the file as the user wrote it, with an
    /// extension naming the format when it has none).
    pub label: String,
    /// The description as the user wrote it, for messages (the path, or `inline DH table`).
    pub written: String,
    /// An expression of type `&'static str` with the text, which also makes the crate rebuild when
    /// the file changes (`include_str!` of its absolute path).
    pub text_expr: TokenStream,
    /// The description file's absolute path (`None` for an inline table): where its meshes'
    /// relative paths start.
    pub path: Option<PathBuf>,
    /// For an MJCF file that names others (`<include>`, `<model file>`), the expression of type
    /// `&'static [(&'static str, &'static str)]` holding each (path as written,
    /// `include_str!` of it), for `reference()`; `None` when it names none.
    pub files_expr: Option<TokenStream>,
}

/// Reads the description and checks the tree (the options against it are the compiler's rules).
pub fn read(options: &SourceOptions<'_>) -> darling::Result<Loaded> {
    let policy = (options.exact_angles, options.floating_base.as_ref());
    let loaded = match (options.urdf, options.mjcf, options.dh) {
        (Some(path), None, None) => from_file(path, SourceKind::Urdf, policy)?,
        (None, Some(path), None) => from_file(path, SourceKind::Mjcf, policy)?,
        (None, None, Some(dh)) => match dh.as_ref() {
            DhSource::File(path) => from_file(&SpannedValue::new(path.clone(), dh.span()), SourceKind::Dh, policy)?,
            DhSource::Inline(table) => from_inline(table, dh.span(), policy)?,
        },
        (None, None, None) => {
            return Err(Error::custom(
                "name the robot's description: `urdf = \"path\"`, `mjcf = \"path\"`, `dh = \"path\"` or an inline `dh(...)` table",
            )
            .with_span(options.ident));
        }
        (urdf, mjcf, dh) => {
            // The second key written is the fault (darling reads them in this order).
            let span = match (urdf, mjcf) {
                (Some(_), Some(m)) => m.span(),
                _ => dh.map_or_else(|| options.ident.span(), |d| d.span()),
            };
            return Err(Error::custom("give one description: `urdf`, `mjcf` or `dh`, not several").with_span(&span));
        }
    };
    Ok(loaded)
}

/// The exactness policy, and the free-flying root's link name if `floating_base` was given.
type Policy<'a> = (ExactAngles, Option<&'a SpannedValue<String>>);

/// Loads `source`, with a free-flying root when asked: the new root link and its joint must not
/// clash with the description's names (the compiler's rule; a clash is an error on the
/// `floating_base` key).
fn load(
    source: &Source,
    (exact_angles, floating): Policy<'_>,
    span: Span,
    read: kinematics_model::mjcf::ReadFile<'_>,
) -> darling::Result<KinematicTree> {
    let tree = source.load_reading(exact_angles, None, read).map_err(|e| spanned(&e, span))?;
    let Some(link) = floating else { return Ok(tree) };
    if let Some(fault) = floating_base_clash(&tree, link.as_ref()) {
        return Err(Error::custom(format!("{}: {fault}", source.label)).with_span(&link.span()));
    }
    source.load_reading(exact_angles, Some(link.as_ref()), read).map_err(|e| spanned(&e, span))
}

fn from_file(path: &SpannedValue<String>, kind: SourceKind, policy: Policy<'_>) -> darling::Result<Loaded> {
    let span = path.span();
    let label = path.as_ref().clone();
    let root = std::env::var("CARGO_MANIFEST_DIR").map(PathBuf::from).unwrap_or_default();
    let absolute = root.join(&label);
    let bytes =
        std::fs::read(&absolute).map_err(|e| spanned(&LoadError::new(label.clone(), LoadErrorKind::Io(e)), span))?;
    let source = Source::from_bytes(label, kind, bytes).map_err(|e| spanned(&e, span))?;
    // MJCF's `<include>` and `<model file>` paths are relative to the main file's directory;
    // each file read is embedded by `include_str!`, so editing it rebuilds the crate too.
    let dir = absolute.parent().map(std::path::Path::to_path_buf).unwrap_or_default();
    let files = std::cell::RefCell::new(Vec::new());
    let read = |file: &str| {
        let path = dir.join(file);
        let text = std::fs::read_to_string(&path).map_err(|e| e.to_string())?;
        files.borrow_mut().push((file.to_owned(), path.to_string_lossy().into_owned()));
        Ok(text)
    };
    let tree = load(&source, policy, span, &read)?;
    let files = files.into_inner();
    let files_expr = (!files.is_empty()).then(|| {
        let (written, paths): (Vec<_>, Vec<_>) = files.into_iter().unzip();
        quote!(&[#((#written, include_str!(#paths))),*])
    });
    let path = Some(absolute.clone());
    let absolute = absolute.to_string_lossy().into_owned();
    let text_expr = quote!(include_str!(#absolute));
    Ok(Loaded { tree, label: source.file_name(), written: source.label, text_expr, path, files_expr })
}

fn from_inline(table: &InlineDh, span: Span, policy: Policy<'_>) -> darling::Result<Loaded> {
    let table = table.to_table().map_err(|e| e.with_span(&span))?;
    // The table as the DH file it stands for: loaded by the one loader, and the text
    // `reference()` parses, so both read the very same robot.
    let text = table.to_toml().map_err(|e| spanned(&LoadError::new(LABEL, e), span))?;
    let no_files = |_: &str| Err(String::new());
    let tree = load(&Source::new(SourceFormat::DhToml, LABEL, text.clone()), policy, span, &no_files)?;
    let (label, written) = ("inline_dh.toml".to_owned(), LABEL.to_owned());
    Ok(Loaded { tree, label, written, text_expr: quote!(#text), path: None, files_expr: None })
}

/// The SRDF at `path` (relative to `CARGO_MANIFEST_DIR`), parsed, and an item that makes the
/// crate rebuild when it changes (an `include_bytes!` of its absolute path); a file that cannot be
/// read or parsed is an error on the key naming the file (and the line).
pub fn read_srdf(path: &SpannedValue<String>) -> darling::Result<(kinematics_model::srdf::Srdf, TokenStream)> {
    let label = path.as_ref().clone();
    let root = std::env::var("CARGO_MANIFEST_DIR").map(PathBuf::from).unwrap_or_default();
    let absolute = root.join(&label);
    let text = std::fs::read_to_string(&absolute)
        .map_err(|e| spanned(&LoadError::new(label.clone(), LoadErrorKind::Io(e)), path.span()))?;
    let mut srdf = kinematics_model::srdf::parse_srdf(&text)
        .map_err(|e| spanned(&LoadError::new(label.clone(), e), path.span()))?;
    srdf.file = label;
    let absolute = absolute.to_string_lossy().into_owned();
    Ok((
        srdf,
        quote!(
            const _: &[u8] = include_bytes!(#absolute);
        ),
    ))
}

/// Reads the triangles of every mesh of `loaded`'s collision geometry (`package://` and relative
/// paths resolved from the description's folder, `packages` relative to `CARGO_MANIFEST_DIR`
/// first), and an item per file that makes the crate rebuild when it changes. A mesh that cannot
/// be found or read is an error on `span` naming the description, the link, the URI and why.
pub fn read_meshes(
    loaded: &mut Loaded,
    packages: Option<&std::collections::BTreeMap<String, String>>,
    span: Span,
) -> darling::Result<TokenStream> {
    let root = std::env::var("CARGO_MANIFEST_DIR").map(PathBuf::from).unwrap_or_default();
    let mut given = kinematics_meshes::Packages::new();
    for (name, path) in packages.into_iter().flatten() {
        given.insert(name.clone(), root.join(path));
    }
    let description = loaded.path.clone().unwrap_or_else(|| root.join(&loaded.label));
    let resolver = kinematics_meshes::Resolver::new(&description, &given);
    let files = kinematics_meshes::load_tree_meshes(&mut loaded.tree, &resolver)
        .map_err(|e| Error::custom(format!("{}: {e}", loaded.written)).with_span(&span))?;
    let files = files.iter().map(|f| f.to_string_lossy().into_owned());
    Ok(quote!(#(const _: &[u8] = include_bytes!(#files);)*))
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

#[cfg(test)]
mod tests {
    use darling::FromDeriveInput;
    use quote::quote;

    use crate::options::KinematicsInput;

    /// A fixed joint turned by pi as ROS spells it (2e-13 rad off), then a revolute joint.
    const ROS_PI: &str = r#"<robot name="r"><link name="a"/><link name="b"/><link name="c"/>
      <joint name="flip" type="fixed"><parent link="a"/><child link="b"/><origin rpy="3.14159265359 0 0"/></joint>
      <joint name="turn" type="continuous"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/></joint></robot>"#;

    fn load(attribute: proc_macro2::TokenStream) -> darling::Result<super::Loaded> {
        let input: syn::DeriveInput = syn::parse2(quote!(
            #[kinematics(#attribute)]
            struct Robot;
        ))
        .unwrap();
        let options = KinematicsInput::from_derive_input(&input)?;
        let loaded = super::read(&options.source())?;
        let mut errors = darling::Error::accumulator();
        let checked = options.options(&mut errors);
        if let Err(rejected) = checked.check(&loaded.tree) {
            for fault in rejected.faults {
                errors.push(darling::Error::custom(format!("{}: {fault}", loaded.written)));
            }
        }
        errors.finish_with(loaded)
    }

    /// The number of angles the loaded tree recognised as exact.
    fn recognised(attribute: proc_macro2::TokenStream) -> usize {
        load(attribute).unwrap().tree.recognised_angles().len()
    }

    #[test]
    fn exact_angles_key_sets_the_policy() {
        let dir = std::env::temp_dir().join(format!("kinematics-derive-core-exact-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("ros_pi.urdf");
        std::fs::write(&file, ROS_PI).unwrap();
        // An absolute path: joined to CARGO_MANIFEST_DIR, it stays itself.
        let path = file.to_string_lossy().into_owned();
        assert_eq!(recognised(quote!(urdf = #path)), 1);
        assert_eq!(recognised(quote!(urdf = #path, exact_angles = true)), 1);
        assert_eq!(recognised(quote!(urdf = #path, exact_angles = false)), 0);
        // The inline table goes through the same loader.
        let dh = quote!(dh(convention = "standard", row("j", 0.0, 1.57079632679, 0.0, 0.0)));
        assert_eq!(recognised(quote!(#dh)), 1);
        assert_eq!(recognised(quote!(#dh, exact_angles = false)), 0);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn exact_angles_must_be_a_bool() {
        for value in [quote!("no"), quote!(0), quote!(off)] {
            let error = load(quote!(dh(convention = "standard", row("j", 0.0, 0.0, 0.0, 0.0)), exact_angles = #value));
            assert!(error.is_err(), "{value}");
        }
    }

    #[test]
    fn base_and_tips_are_looked_up_by_the_model() {
        let dh = quote!(dh(convention = "standard", row("j", 1.0, 0.0, 0.0, 0.0)));
        let messages: Vec<String> = load(quote!(#dh, base = "bsae", tips("link1", "lnk1", "gripper")))
            .unwrap_err()
            .into_iter()
            .map(|e| e.to_string())
            .collect();
        assert_eq!(
            messages,
            [
                "inline DH table: base link `bsae` does not exist; did you mean `base`?",
                "inline DH table: tip link `lnk1` does not exist; did you mean `link1`?",
                "inline DH table: tip link `gripper` does not exist",
            ]
        );
    }
}
