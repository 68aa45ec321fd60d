//! The logic of `#[derive(Kinematics)]`, as a plain library so it can be tested and benchmarked
//! without a compiler: parse the `#[kinematics(...)]` attribute ([`options`]), read and validate
//! the description (the private `source` module), compile it and emit the robot's impls (through
//! `kinematics_compiler::robot`). Every fault becomes a spanned `compile_error!`, all of them at
//! once (darling's accumulator); nothing panics. With any fault, the output also holds a stub of
//! what the derive would have defined (the private `fallback` module), so the user sees the real errors rather than
//! a cascade of "no function `tip_pose`" and "trait `Kinematics` not implemented".
//! The `kinematics-derive` proc-macro crate is a shim over [`expand`].

mod fallback;
mod inline_dh;
pub mod options;
mod source;

use darling::FromDeriveInput;
use proc_macro2::TokenStream;
use quote::quote;

use kinematics_compiler::robot::{IkMode, RobotSpec, emit_robot};
use options::KinematicsInput;

/// Expands `#[derive(Kinematics)]` on `input`: the impls, or the errors as `compile_error!`s
/// beside a stub of the impls.
pub fn expand(input: TokenStream) -> TokenStream {
    let input: syn::DeriveInput = match syn::parse2(input) {
        Ok(input) => input,
        Err(e) => return e.to_compile_error(),
    };
    let mut errors = darling::Error::accumulator();
    let (options, known, robot) = match KinematicsInput::from_derive_input(&input) {
        Ok(options) => {
            let (known, robot) = expand_options(&options, &mut errors);
            (Some(options), known, robot)
        }
        Err(e) => {
            errors.push(e);
            // A key darling cannot read fails the whole attribute; the description may still be
            // readable, and its faults belong beside that key's (the stub gets its sizes too).
            let loaded = match options::DescriptionKeys::from_derive_input(&input) {
                Ok(keys) if keys.names_a_description() => read_and_check(&keys.source(), &mut errors).0,
                _ => None,
            };
            (None, loaded.as_ref().map(known), None)
        }
    };
    match (errors.finish(), robot) {
        (Ok(()), Some(robot)) => robot,
        (result, _) => {
            // No robot means a fault was recorded; if none was, say so rather than emit a stub
            // that compiles into functions that never return.
            let errors = match result {
                Err(errors) => errors.write_errors(),
                Ok(()) => quote!(::core::compile_error!(
                    "kinematics derive: internal error: no code and no fault (the derive's invariant broke; please report)"
                );),
            };
            let stub = fallback::stub(&input, options.as_ref(), known);
            quote!(#errors #stub)
        }
    }
}

/// Reads the description and checks the links asked for, each fault into `errors`: the robot if
/// it could be read (so the stub knows its sizes even when a link name is wrong), and whether the
/// links are all there.
fn read_and_check(
    options: &options::SourceOptions<'_>,
    errors: &mut darling::error::Accumulator,
) -> (Option<source::Loaded>, bool) {
    let loaded = errors.handle(source::read(options));
    let links_ok = loaded.as_ref().is_some_and(|l| errors.handle(source::check_links(l, options)).is_some());
    (loaded, links_ok)
}

/// Why `ik` cannot be emitted for this robot and these options, if it cannot: not exactly one
/// tip, or a chain no closed-form family covers.
fn ik_fault(options: &KinematicsInput, mode: &IkMode, loaded: &source::Loaded) -> Option<String> {
    let tips = options.tips();
    let tree = &loaded.tree;
    let base = options.keys.base.as_ref().map_or_else(|| tree.link(tree.root()).name.clone(), |b| b.as_ref().clone());
    if tree.dof() != tree.velocity_dof() {
        return Some("`ik` of a robot with a floating joint is not supported yet".to_owned());
    }
    match tips.as_slice() {
        [_] if *mode == IkMode::Numeric => None,
        [tip] => {
            let free = match mode {
                IkMode::ClosedForm { free } => free.as_deref(),
                _ => None,
            };
            kinematics_compiler::ik::classify_with(tree, &base, tip.as_ref(), free).err().map(|e| e.to_string())
        }
        _ => Some(format!(
            "`ik` needs exactly one `tip = \"link\"`: the inverse kinematics is the tip's ({} tips given)",
            tips.len()
        )),
    }
}

/// What the stub needs to know of a loaded robot.
fn known(loaded: &source::Loaded) -> fallback::Known {
    fallback::Known {
        dof: loaded.tree.dof(),
        velocities: loaded.tree.velocity_dof(),
        links: loaded.tree.links().len().saturating_sub(1),
    }
}

/// Loads the description, checks the options and emits the robot, gathering every fault in
/// `errors` (the load errors and the option errors side by side): the robot if there was none,
/// and what is known of it for the stub otherwise.
fn expand_options(
    options: &KinematicsInput,
    errors: &mut darling::error::Accumulator,
) -> (Option<fallback::Known>, Option<TokenStream>) {
    let (loaded, links_ok) = read_and_check(&options.source(), errors);
    let scalars = errors.handle(options.output().scalars());
    if options.output().jacobians.is_present() && options.tips().is_empty() {
        errors.push(
            darling::Error::custom(
                "`jacobians` needs `tip = \"link\"` or `tips(...)`: the Jacobians are the tips' (add the link whose \
                 velocity you want)",
            )
            .with_span(&options.output().jacobians.span()),
        );
        return (loaded.as_ref().map(known), None);
    }
    let ik = errors.handle(options.output().ik_mode());
    if let (Some(mode), Some(key), true, Some(loaded)) = (&ik, &options.output().ik, links_ok, &loaded)
        && let Some(fault) = ik_fault(options, mode, loaded)
    {
        errors.push(darling::Error::custom(format!("{}: {fault}", loaded.label)).with_span(&key.span()));
        return (Some(known(loaded)), None);
    }
    let trig = errors.handle(options.output().trig());
    let known = loaded.as_ref().map(known);
    let (Some(loaded), Some(scalars), Some(trig), Some(ik), true) = (loaded, scalars, trig, ik, links_ok) else {
        return (known, None);
    };
    let krate = match &options.output().krate {
        Some(path) => quote!(#path),
        None => quote!(::kinematics),
    };
    let ident = &options.ident;
    let (impl_generics, ty_generics, where_clause) = options.generics.split_for_impl();
    let spec = RobotSpec {
        tree: &loaded.tree,
        base: options.keys.base.as_ref().map(|b| b.as_ref().clone()),
        tips: options.tips().into_iter().map(|t| t.as_ref().clone()).collect(),
        links: options.keys.links().into_iter().map(|l| l.as_ref().clone()).collect(),
        positions: options.output().positions,
        jacobians: options.output().jacobians.is_present(),
        ik,
        floating_base: options.source().floating_base.map(|f| f.as_ref().clone()),
        scalars,
        krate,
        trig,
        source_label: loaded.label.clone(),
        source_text: loaded.text_expr.clone(),
        impl_generics: quote!(#impl_generics),
        where_clause: quote!(#where_clause),
    };
    let emitted = emit_robot(&quote!(#ident #ty_generics), &spec)
        .map_err(|e| darling::Error::custom(format!("{}: {e}", loaded.label)).with_span(ident));
    (known, errors.handle(emitted))
}
