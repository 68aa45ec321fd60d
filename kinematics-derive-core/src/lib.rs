//! The logic of `#[derive(Kinematics)]`, as a plain library so it can be tested and benchmarked
//! without a compiler: parse the `#[kinematics(...)]` attribute ([`options`]), read and validate
//! the description ([`source`]), compile it and emit the robot's impls (through
//! `kinematics_compiler::robot`). Every fault becomes a spanned `compile_error!`; nothing panics.
//! The `kinematics-derive` proc-macro crate is a shim over [`expand`].

mod inline_dh;
pub mod options;
mod source;

use darling::FromDeriveInput;
use proc_macro2::TokenStream;
use quote::quote;

use kinematics_compiler::robot::{RobotSpec, emit_robot};
use options::KinematicsInput;

/// Expands `#[derive(Kinematics)]` on `input`: the impls, or the errors as `compile_error!`s.
pub fn expand(input: TokenStream) -> TokenStream {
    let input: syn::DeriveInput = match syn::parse2(input) {
        Ok(input) => input,
        Err(e) => return e.to_compile_error(),
    };
    match expand_input(&input) {
        Ok(tokens) => tokens,
        Err(errors) => errors.write_errors(),
    }
}

fn expand_input(input: &syn::DeriveInput) -> darling::Result<TokenStream> {
    let options = KinematicsInput::from_derive_input(input)?;
    let loaded = source::load(&options)?;
    let krate = match &options.krate {
        Some(path) => quote!(#path),
        None => quote!(::kinematics),
    };
    let ident = &options.ident;
    let (impl_generics, ty_generics, where_clause) = options.generics.split_for_impl();
    let self_ty = quote!(#ident #ty_generics);
    let spec = RobotSpec {
        tree: &loaded.tree,
        base: options.base.as_ref().map(|b| b.as_ref().clone()),
        tips: options.tips().into_iter().map(|t| t.as_ref().clone()).collect(),
        positions: options.positions,
        scalars: options.scalars()?,
        krate: krate.clone(),
        source_label: loaded.label.clone(),
        source_text: loaded.text_expr.clone(),
        exact_angles: loaded.tree.exact_angles(),
    };
    let robot = emit_robot(&self_ty, &spec).map_err(|e| darling::Error::custom(format!("{}: {e}", loaded.label)))?;
    // `emit_robot` writes `impl Type`; generic structs need their parameters on the impls.
    let robot = if options.generics.params.is_empty() {
        robot
    } else {
        add_generics(robot, &quote!(#impl_generics), &quote!(#where_clause))
    };
    Ok(quote! {
        const _: () = {
            #robot
        };
    })
}

/// Puts `impl<...>` parameters and the where clause on the emitted impls.
fn add_generics(tokens: TokenStream, impl_generics: &TokenStream, where_clause: &TokenStream) -> TokenStream {
    let file: syn::File = match syn::parse2(tokens.clone()) {
        Ok(file) => file,
        Err(_) => return tokens,
    };
    let items = file.items.into_iter().map(|item| match item {
        syn::Item::Impl(mut imp) => {
            if let Ok(generics) = syn::parse2::<syn::Generics>(impl_generics.clone()) {
                imp.generics.params = generics.params;
            }
            if let Ok(clause) = syn::parse2::<syn::WhereClause>(where_clause.clone()) {
                imp.generics.where_clause = Some(clause);
            }
            quote!(#imp)
        }
        other => quote!(#other),
    });
    quote!(#(#items)*)
}
