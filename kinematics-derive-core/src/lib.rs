//! The logic of `#[derive(Kinematics)]`, as a plain library so it can be tested and benchmarked
//! without a compiler: parse the `#[kinematics(...)]` attribute ([`options`]), read and validate
//! the description (the private `source` module), compile it and emit the robot's impls (through
//! `kinematics_compiler::robot`). Every fault becomes a spanned `compile_error!`, all of them at
//! once (darling's accumulator); nothing panics. With any fault, the output also holds a stub of
//! what the derive would have defined (the private `fallback` module), so the user sees the real errors rather than
//! a cascade of "no function `tip_pose`" and "trait `Kinematics` not implemented".
//! The `kinematics-derive` proc-macro crate is a shim over [`expand`].
//!
//! `expand` gathers every fault; the options' faults come from the compiler's rules.

mod fallback;
mod inline_dh;
pub mod options;
mod source;

use darling::FromDeriveInput;
use darling::util::SpannedValue;
use proc_macro2::{Span, TokenStream};
use quote::quote;

use fallback::Implied;
use kinematics_compiler::options::{OptionKey, Options, Rejected};
use kinematics_compiler::robot::{RobotSpec, emit_robot};
use options::KinematicsInput;

/// Expands `#[derive(Kinematics)]` on `input`: the impls, or the errors as `compile_error!`s
/// beside a stub of the impls.
pub fn expand(input: TokenStream) -> TokenStream {
    let input: syn::DeriveInput = match syn::parse2(input) {
        Ok(input) => input,
        Err(e) => return e.to_compile_error(),
    };
    let mut errors = darling::Error::accumulator();
    let (options, implied, robot) = match KinematicsInput::from_derive_input(&input) {
        Ok(options) => {
            let (implied, robot) = expand_options(&options, &mut errors);
            (Some(options), implied, robot)
        }
        Err(e) => {
            errors.push(e);
            // A key darling cannot read fails the whole attribute; the description may still be
            // readable, and its faults (and those of the links it names) belong beside that
            // key's (the stub gets its sizes too).
            let implied = Implied::from_attributes(&input);
            let implied = match options::DescriptionKeys::from_derive_input(&input) {
                Ok(keys) if keys.names_a_description() => match errors.handle(source::read(&keys.source())) {
                    Some(loaded) => {
                        let options = keys.options();
                        if let Err(rejected) = options.check(&loaded.tree) {
                            report(&rejected, &loaded, &mut errors, |key| keys.span_of(key));
                        }
                        implied.with_robot(&loaded.tree)
                    }
                    None => implied,
                },
                _ => implied,
            };
            (None, implied, None)
        }
    };
    match (errors.finish(), robot) {
        (Ok(()), Some(robot)) => robot,
        (result, _) => {
            // No robot means a fault was recorded; if none was, say so rather than emit a stub
            // that compiles into functions that never return.
            let mut errors = match result {
                Err(errors) => errors.into_iter().map(darling::Error::write_errors).collect(),
                Ok(()) => Vec::new(),
            }
            .into_iter();
            // The first error is the stub's unknown length (which reports it); the rest stand
            // beside the stub.
            let first = errors.next().unwrap_or_else(|| {
                quote!(::core::compile_error!(
                    "kinematics derive: internal error: no code and no fault (the derive's invariant broke; please report)"
                ))
            });
            let stub = fallback::stub(&input, options.as_ref(), &implied, first);
            quote!(#stub #(#errors)*)
        }
    }
}

/// Every fault of `rejected` into `errors`, each on the span `span_of` gives its option and
/// naming the description.
fn report(
    rejected: &Rejected,
    loaded: &source::Loaded,
    errors: &mut darling::error::Accumulator,
    span_of: impl Fn(OptionKey) -> Span,
) {
    for fault in &rejected.faults {
        errors.push(darling::Error::custom(format!("{}: {fault}", loaded.written)).with_span(&span_of(fault.key)));
    }
}

/// Loads the description, checks the options against it (the compiler's rules) and emits the
/// robot, gathering every fault in `errors` (the load errors and the option faults side by side):
/// the robot if there was none, and what the stub needs otherwise.
fn expand_options(
    options: &KinematicsInput,
    errors: &mut darling::error::Accumulator,
) -> (Implied, Option<TokenStream>) {
    let loaded = errors.handle(source::read(&options.source()));
    let mut robot_options: Options = options.options(errors);
    // The SRDF's pairs, read here (the compiler does no IO); its faults beside the others.
    let mut rebuild = TokenStream::new();
    if let (Some(path), Some(collision)) = (options.output().srdf(), robot_options.collision.as_mut())
        && let Some((srdf, include)) = errors.handle(source::read_srdf(path))
    {
        collision.srdf = Some(srdf);
        rebuild = include;
    }
    let implied = Implied::from_options(robot_options.clone());
    let Some(loaded) = loaded else {
        // The rules that need no robot still speak.
        for fault in robot_options.check_alone() {
            errors.push(darling::Error::custom(fault.to_string()).with_span(&options.span_of(fault.key)));
        }
        return (implied, None);
    };
    let mut loaded = loaded;
    if let Some(collision) = robot_options.collision.as_ref()
        && collision.meshes == kinematics_compiler::options::Meshes::Read
    {
        let packages = options.output().packages();
        let span = packages.map_or_else(|| options.span_of(OptionKey::Collision), SpannedValue::span);
        match errors.handle(source::read_meshes(&mut loaded, packages.map(AsRef::as_ref), span)) {
            Some(include) => rebuild.extend(include),
            None => return (implied, None),
        }
    }
    let implied = implied.with_robot(&loaded.tree);
    let checked = match robot_options.check(&loaded.tree) {
        Ok(checked) => checked,
        Err(rejected) => {
            report(&rejected, &loaded, errors, |key| options.span_of(key));
            return (implied.with_plan(rejected.ik_plan), None);
        }
    };
    let krate = match &options.output().krate {
        Some(path) => quote!(#path),
        None => quote!(::kinematics),
    };
    let ident = &options.ident;
    let (impl_generics, ty_generics, where_clause) = options.generics.split_for_impl();
    let spec = RobotSpec {
        robot: checked,
        krate,
        source_label: loaded.label.clone(),
        source_text: loaded.text_expr.clone(),
        source_files: loaded.files_expr.clone(),
        impl_generics: quote!(#impl_generics),
        where_clause: quote!(#where_clause),
    };
    let emitted = emit_robot(&quote!(#ident #ty_generics), &spec)
        .map(|robot| quote!(#robot #rebuild))
        .map_err(|e| darling::Error::custom(format!("{}: {e}", loaded.label)).with_span(ident));
    (implied, errors.handle(emitted))
}
