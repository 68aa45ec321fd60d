//! Batches and lanes: from one generic body, the functions on the type (a typed one per scalar,
//! a batch per scalar over slices in SIMD lanes, and the `_generic` one for any `Real`).

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::Context;
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

/// The type of a function's value for a scalar type.
pub(super) type Returns<'r> = &'r dyn Fn(&TokenStream) -> TokenStream;

impl Functions {
    /// `compiled` as the generic body `name`.
    pub(super) fn body(&mut self, cx: &Context<'_>, compiled: &Compiled, name: &str) {
        self.generic.push(emit_function(compiled, &cx.body_options(name)));
    }

    /// The functions on the type calling the generic body `generic_name` with `q`: `name` and its
    /// batch per scalar, and `name_generic`; `ret` gives the value's type for a scalar, `doc` says
    /// what the value is.
    pub(super) fn on_type(&mut self, cx: &Context<'_>, name: &str, generic_name: &str, ret: Returns<'_>, doc: String) {
        let (p, n_lit) = (&cx.p, &cx.n_lit);
        let g = format_ident!("{generic_name}");
        for (suffix, t, lanes, wide) in &cx.scalars {
            let f = format_ident!("{name}{suffix}");
            let r = ret(t);
            let one = format!("{doc} (`{t}`).");
            // Dispatched: compiled for AVX-512, AVX2 and the baseline, the best the CPU has run
            // (`__private::dispatch`). A closure, `#[inline(always)]`, rather than the function
            // itself: a function item is called through a shim that is not inlined into the
            // dispatched function, which then runs without the instruction set it was compiled
            // for (measured). The same holds for the batches below.
            self.typed.push(quote! {
                #[doc = #one]
                #[inline]
                #[allow(clippy::redundant_closure)]
                pub fn #f(q: &[#t; #n_lit]) -> #r { #p::dispatch(#[inline(always)] || #g(q)) }
            });
            let (narrow, wide_count, lanes_name, wide_name) =
                if suffix.is_empty() { (4, 8, "F64x4", "F64x8") } else { (8, 16, "F32x8", "F32x16") };
            let batch = format_ident!("{name}_batch{suffix}");
            let many = format!(
                "[`Self::{f}`] for every configuration of `qs`, into `out` (one each), {narrow} at a time in \
                 SIMD lanes (`{lanes_name}`; {wide_count} in `{wide_name}` where the CPU has AVX-512). An \
                 `out` of another length than `qs` is an error, and nothing is written."
            );
            self.typed.push(quote! {
                #[doc = #many]
                #[inline]
                #[allow(clippy::redundant_closure)]
                pub fn #batch(qs: &[[#t; #n_lit]], out: &mut [#r]) -> ::core::result::Result<(), #p::KinematicsError> {
                    #p::batch_wide::<#lanes, #wide, #n_lit, _, _>(
                        Self::ROBOT, qs, out, #[inline(always)] |q| #g(q), #[inline(always)] |q| #g(q),
                    )
                }
            });
            let columns = format_ident!("{name}_batch_columns{suffix}");
            let columns_doc = format!(
                "[`Self::{batch}`] on configurations given column-wise, as planners keep them: \
                 `columns[j][i]` is joint `j`'s value (in the order of `JOINT_NAMES`) in configuration \
                 `i`, into `out` (one each). Packing lanes from columns is a contiguous load, not a \
                 transpose. A column of another length than `out` is an error naming its joint, and \
                 nothing is written."
            );
            self.typed.push(quote! {
                #[doc = #columns_doc]
                #[inline]
                #[allow(clippy::redundant_closure)]
                pub fn #columns(columns: [&[#t]; #n_lit], out: &mut [#r]) -> ::core::result::Result<(), #p::KinematicsError> {
                    #p::batch_columns::<#lanes, #wide, #n_lit, _, _>(
                        Self::ROBOT, &Self::JOINT_NAMES, columns, out,
                        #[inline(always)] |q| #g(q), #[inline(always)] |q| #g(q),
                    )
                }
            });
        }
        let f = format_ident!("{name}_generic");
        let (scalar, bound) = (&cx.scalar, &cx.bound);
        let r = ret(scalar);
        let doc = format!(
            "{doc}, for any scalar type: the lane types `F64x4`, `F64x8`, `F32x8` and `F32x16` (four to sixteen \
             configurations per call), dual numbers, or a type of your own. Not dispatched (it runs with the \
             instruction set of your build): wrap a loop of calls in `kinematics::dispatch` to run it with the \
             widest set the CPU has, once for the whole loop."
        );
        self.typed.push(quote! {
            #[doc = #doc]
            #[inline]
            pub fn #f<#scalar: #bound>(q: &[#scalar; #n_lit]) -> #r { #g(q) }
        });
    }

    /// The functions on the type calling the generic body `generic_name` with `q` and the joint
    /// rates `qd`: `name` per scalar and `name_generic` (no batch).
    pub(super) fn on_type_with_rates(
        &mut self,
        cx: &Context<'_>,
        name: &str,
        generic_name: &str,
        ret: Returns<'_>,
        doc: &str,
    ) {
        let (p, n_lit, nv_lit) = (&cx.p, &cx.n_lit, &cx.nv_lit);
        let g = format_ident!("{generic_name}");
        for (suffix, t, ..) in &cx.scalars {
            let f = format_ident!("{name}{suffix}");
            let r = ret(t);
            let one_doc = format!("{doc} (`{t}`).");
            self.typed.push(quote! {
                #[doc = #one_doc]
                #[inline]
                #[allow(clippy::redundant_closure)]
                pub fn #f(q: &[#t; #n_lit], qd: &[#t; #nv_lit]) -> #r { #p::dispatch(#[inline(always)] || #g(q, qd)) }
            });
        }
        let f = format_ident!("{name}_generic");
        let (scalar, bound) = (&cx.scalar, &cx.bound);
        let r = ret(scalar);
        let doc = format!("{doc}, for any scalar type.");
        self.typed.push(quote! {
            #[doc = #doc]
            #[inline]
            pub fn #f<#scalar: #bound>(q: &[#scalar; #n_lit], qd: &[#scalar; #nv_lit]) -> #r { #g(q, qd) }
        });
    }
}
