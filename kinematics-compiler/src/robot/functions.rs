//! Batches and lanes: from one generic body, the functions on the type (a typed one per scalar,
//! a batch per scalar over slices in SIMD lanes, and the `_generic` one for any `Real`), with the
//! signatures [`super::surface`] renders.
//!
//! Per computation: the typed functions, each calling its body through the core's `dispatch`; a
//! `_generic` one for any `Real` (not dispatched); and `_batch` and `_batch_columns` ones over
//! slices (`F64x4` lanes, `F64x8` under AVX-512, and `F32x8` on every CPU, through the core's `batch_wide`
//! and `batch_columns`). A computation that also takes the joint rates (twists, inverse dynamics,
//! nonlinear effects, forward dynamics) has a `_batch` over a slice per argument (the core's
//! `batch_inputs`, and `dynamics::accelerations_batch` for forward dynamics) and no columns.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::Context;
use super::surface::{Form, Output, ScalarType};
use crate::emit::emit_function;
use crate::request::Compiled;

/// The output so far: the generic bodies (free functions in the block) and the items of the
/// type's `impl`, each in the order emitted.
#[derive(Default)]
pub(super) struct Functions {
    /// The generic bodies.
    pub(super) generic: Vec<TokenStream>,
    /// The constants and functions of the type's `impl`.
    pub(super) typed: Vec<TokenStream>,
}

impl Functions {
    /// `compiled` as the generic body `name`.
    pub(super) fn body(&mut self, cx: &Context<'_>, compiled: &Compiled, name: &str) {
        self.generic.push(emit_function(compiled, &cx.body_options(name)));
    }

    /// The functions of `output` on the type, calling its generic body with `q` (and `qd`);
    /// `doc` says what the value is.
    pub(super) fn on_type(&mut self, cx: &Context<'_>, output: Output, doc: &str) {
        let p = &cx.p;
        let n_lit = cx.render.dof();
        let g = format_ident!("{}", output.body(cx.one));
        let rates = output.takes_rates();
        let arguments = output.arguments();
        let forward = output.is_forward();
        for (form, signature) in cx.render.functions(output, cx.one) {
            let sig = signature.tokens();
            let item = match form {
                // Forward dynamics refuses a singular mass matrix (a pivot of its factorisation
                // that vanishes) rather than return what dividing by it gives.
                Form::Typed(ScalarType { t, .. }) if forward => {
                    let one_doc = format!("{doc} (`{t}`).");
                    quote! {
                        #[doc = #one_doc]
                        #[inline]
                        #[allow(clippy::redundant_closure)]
                        #sig {
                            let (qdd, pivots) = #p::dispatch(#[inline(always)] || #g(#arguments));
                            #p::dynamics::accelerations_checked(Self::ROBOT, &Self::VELOCITY_NAMES, qdd, pivots)
                        }
                    }
                }
                Form::Typed(ScalarType { t, .. }) if rates => {
                    let one_doc = format!("{doc} (`{t}`).");
                    quote! {
                        #[doc = #one_doc]
                        #[inline]
                        #[allow(clippy::redundant_closure)]
                        #sig { #p::dispatch(#[inline(always)] || #g(#arguments)) }
                    }
                }
                // Dispatched: compiled for AVX-512, AVX2 and the baseline, the best the CPU has
                // run (`__private::dispatch`). A closure, `#[inline(always)]`, rather than the
                // function itself: a function item is called through a shim that is not inlined
                // into the dispatched function, which then runs without the instruction set it
                // was compiled for (measured). The same holds for the batches below.
                Form::Typed(ScalarType { t, .. }) => {
                    let one = format!("{doc} (`{t}`).");
                    quote! {
                        #[doc = #one]
                        #[inline]
                        #[allow(clippy::redundant_closure)]
                        #sig { #p::dispatch(#[inline(always)] || #g(q)) }
                    }
                }
                Form::Batch(scalar) if rates => rate_batch(cx, output, &scalar, &sig, &g),
                Form::Batch(scalar) => {
                    let ScalarType { suffix, lanes, wide, .. } = &scalar;
                    let typed = format_ident!("{}{suffix}", output.name(cx.one));
                    let lanes_doc = scalar.lanes_doc();
                    let many = format!(
                        "[`Self::{typed}`] for every configuration of `qs`, into `out` (one each), in SIMD lanes \
                         ({lanes_doc}). An `out` of another length than `qs` is an error, and nothing is written."
                    );
                    quote! {
                        #[doc = #many]
                        #[inline]
                        #[allow(clippy::redundant_closure)]
                        #sig {
                            #p::batch_wide::<#lanes, #wide, #n_lit, _, _>(
                                Self::ROBOT, qs, out, #[inline(always)] |q| #g(q), #[inline(always)] |q| #g(q),
                            )
                        }
                    }
                }
                Form::Columns(ScalarType { suffix, lanes, wide, .. }) => {
                    let batch = format_ident!("{}_batch{suffix}", output.name(cx.one));
                    let columns_doc = format!(
                        "[`Self::{batch}`] on configurations given column-wise, as planners keep them: \
                         `columns[j][i]` is joint `j`'s value (in the order of `JOINT_NAMES`) in configuration \
                         `i`, into `out` (one each). Packing lanes from columns is a contiguous load, not a \
                         transpose. A column of another length than `out` is an error naming its joint, and \
                         nothing is written."
                    );
                    quote! {
                        #[doc = #columns_doc]
                        #[inline]
                        #[allow(clippy::redundant_closure)]
                        #sig {
                            #p::batch_columns::<#lanes, #wide, #n_lit, _, _>(
                                Self::ROBOT, &Self::JOINT_NAMES, columns, out,
                                #[inline(always)] |q| #g(q), #[inline(always)] |q| #g(q),
                            )
                        }
                    }
                }
                Form::Generic if rates => {
                    let doc = format!("{doc}, for any scalar type.");
                    quote! {
                        #[doc = #doc]
                        #[inline]
                        #sig { #g(#arguments) }
                    }
                }
                Form::Generic => {
                    let doc = format!(
                        "{doc}, for any scalar type: the lane types `F64x4`, `F64x8`, `F32x8` and `F32x16` (four to \
                         sixteen configurations per call), dual numbers, or a type of your own. Not dispatched (it \
                         runs with the instruction set of your build): wrap a loop of calls in \
                         `kinematics::dispatch` to run it with the widest set the CPU has, once for the whole loop."
                    );
                    quote! {
                        #[doc = #doc]
                        #[inline]
                        #sig { #g(q) }
                    }
                }
            };
            self.typed.push(item);
        }
    }
}

/// The batch of a function of several inputs (`q` and the rates, and `qdd`, `tau` or `forces`): a
/// slice of each, packed together (`batch_inputs`); forward dynamics checks each configuration's
/// pivots as its typed function does (`accelerations_batch`).
fn rate_batch(
    cx: &Context<'_>,
    output: Output,
    scalar: &ScalarType,
    sig: &TokenStream,
    g: &proc_macro2::Ident,
) -> TokenStream {
    let p = &cx.p;
    let forward = output.is_forward();
    let ScalarType { suffix, lanes, wide, .. } = scalar;
    let typed = format_ident!("{}{suffix}", output.name(cx.one));
    let names = output.inputs();
    let arguments: Vec<_> = names.iter().map(|name| format_ident!("{name}")).collect();
    let slices: Vec<_> = names.iter().map(|name| Output::batch_name(name)).collect();
    let slice_idents = slices.iter().map(|slice| format_ident!("{slice}"));
    let inputs = quote!((#(#p::Input::new(#slices, #slice_idents)),*));
    let body = quote!(#[inline(always)] |(#(#arguments),*)| #g(#(#arguments),*));
    let listed = match slices.as_slice() {
        [rest @ .., last] => {
            format!("{} and `{last}`", rest.iter().map(|s| format!("`{s}`")).collect::<Vec<_>>().join(", "))
        }
        [] => String::new(),
    };
    let lanes_doc = scalar.lanes_doc();
    let mut many = format!(
        "[`Self::{typed}`] for every configuration, row `i` of {listed} into `out[i]`, in SIMD lanes \
             ({lanes_doc}). An input of another length than `out` is an error naming it, and nothing is \
             written."
    );
    let call = if forward {
        many.push_str(&format!(
            " Otherwise every configuration is computed and written: one that [`Self::{typed}`] \
                 refuses (a singular mass matrix, a value that is not finite) as NaN in every entry, and \
                 the error names the first of them and its index (`SingularMassMatrixInBatch`, \
                 `NotFiniteInBatch`); the others hold what [`Self::{typed}`] returns."
        ));
        let nv = cx.render.velocities();
        quote! {
            #p::dynamics::accelerations_batch::<#lanes, #wide, _, #nv>(
                Self::ROBOT, &Self::VELOCITY_NAMES, #inputs, out, #body, #body,
            )
        }
    } else {
        quote!(#p::batch_inputs::<#lanes, #wide, _, _, _>(Self::ROBOT, #inputs, out, #body, #body))
    };
    quote! {
        #[doc = #many]
        #[inline]
        #sig { #call }
    }
}
