//! The straight-line body of a composed closed form ([`IkBody`]): one branch for any `IkReal`
//! scalar, so that `F64x8` evaluates the eight branches side by side in its lanes. The robot's
//! inverse kinematics functions that call it (or the run time's family solver) are written with
//! the other output kinds, in `robot::ik`.
//!
//! The body is emitted as the generic function `generic_tip_ik_branch`.

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

use super::closed_form::{FIRST_SIGN, IkBody};
use crate::emit::straight_line;

/// The name of the generic body of a compiled closed form (one branch per evaluation).
pub const BRANCH_BODY: &str = "generic_tip_ik_branch";

/// The name of the same body without its pass at the wrist's singularity ([`IkBody::regular`]),
/// which `tip_ik` runs first.
pub const REGULAR_BODY: &str = "generic_tip_ik_branch_regular";

/// The body's inputs as the generated code names them: `r11 .. r33`, `px, py, pz`, `sign1 ..
/// sign3`.
fn input_names() -> Vec<Ident> {
    let mut names: Vec<Ident> = (0..9usize).map(|k| format_ident!("r{}{}", k / 3 + 1, k % 3 + 1)).collect();
    names.extend(["px", "py", "pz"].map(|n| Ident::new(n, Span::call_site())));
    names.extend((1..=3usize).map(|k| format_ident!("sign{k}")));
    names
}

/// The generic body of `body`: one branch of the closed form, for any `IkReal` scalar, the
/// branch picked by `signs`.
pub fn emit_branch_body(body: &IkBody, private: &TokenStream, name: &str, doc: &str) -> TokenStream {
    let p = private;
    let names = input_names();
    let line = straight_line(body.graph(), &body.outputs(), 0, &names, p);
    let bind = |k: usize| {
        let name = &names[k];
        if line.used_inputs.contains(&k) { quote!(#name) } else { quote!(_) }
    };
    let rows = (0..3).map(|i| {
        let entries = (0..3).map(|j| bind(3 * i + j));
        quote!([#(#entries),*])
    });
    let translation = (9..12).map(bind);
    let signs = (FIRST_SIGN..FIRST_SIGN + 3).map(bind);
    let statements = &line.statements;
    let dof = body.dof();
    let (q, cos, sin) = (&line.outputs[..dof], &line.outputs[dof..2 * dof], &line.outputs[2 * dof..3 * dof]);
    let (exact, singular) = (&line.outputs[3 * dof], &line.outputs[3 * dof + 1]);
    let n = Literal::usize_unsuffixed(dof);
    let name = Ident::new(name, Span::call_site());
    let cost = format!(" Cost per branch: {}.", body.op_count());
    quote! {
        #[doc = #doc]
        #[doc = ""]
        #[doc = #cost]
        #[allow(clippy::inline_always)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        #[allow(clippy::approx_constant)] // a robot's own decimals may resemble pi; they are kept as given
        pub fn #name<T: #p::ik::IkReal>(target: &#p::Pose<T>, signs: &[T; 3]) -> #p::ik::IkBranch<T, #n> {
            let [#(#rows),*] = target.rotation;
            let [#(#translation),*] = target.translation;
            let [#(#signs),*] = *signs;
            #statements
            #p::ik::IkBranch { q: [#(#q),*], cos: [#(#cos),*], sin: [#(#sin),*], exact: #exact, singular: #singular }
        }
    }
}
