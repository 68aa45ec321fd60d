//! Rust tokens through `quote`: one function per compiled request.

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

use super::schedule::{Item, Schedule};
use crate::request::Compiled;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};

/// How to emit a function.
#[derive(Debug, Clone)]
pub struct EmitOptions {
    /// The function's name.
    pub name: String,
    /// Path of the crate that provides `Real` and `Pose` (default `::kinematics`).
    pub krate: TokenStream,
}

impl EmitOptions {
    /// A function `name` using `::kinematics`.
    pub fn named(name: &str) -> Self {
        EmitOptions { name: name.to_owned(), krate: quote!(::kinematics) }
    }
}

struct Writer<'a> {
    g: &'a ExprGraph,
    schedule: &'a Schedule,
}

impl Writer<'_> {
    fn ident(name: &str) -> Ident {
        Ident::new(name, Span::call_site())
    }

    fn constant(x: f64) -> TokenStream {
        let lit = Literal::f64_unsuffixed(x.abs());
        if x < 0.0 { quote!(T::from_f64(-#lit)) } else { quote!(T::from_f64(#lit)) }
    }

    /// The expression for `id`: its name if bound, else written out.
    fn expr(&self, id: ExprId) -> TokenStream {
        if let Some(name) = self.schedule.bound.get(&id) {
            let name = Self::ident(name);
            return quote!(#name);
        }
        self.define(id)
    }

    /// The expression for `id` written out (the right-hand side of its binding).
    fn define(&self, id: ExprId) -> TokenStream {
        let g = self.g;
        match g.node(id) {
            Node::Const(c) => Self::constant(c.value()),
            Node::Var(i) => {
                let q = format_ident!("q{}", i as usize + 1);
                quote!(#q)
            }
            Node::Sin(a) => {
                let name = Self::ident(&self.schedule.names.sin(a));
                quote!(#name)
            }
            Node::Cos(a) => {
                let name = Self::ident(&self.schedule.names.cos(a));
                quote!(#name)
            }
            Node::Neg(a) => {
                let inner = self.operand(a);
                quote!(-#inner)
            }
            Node::Add(a, b) => {
                let (na, ia) = g.unneg(a);
                let (nb, ib) = g.unneg(b);
                match (na, nb) {
                    (false, true) => {
                        let (x, y) = (self.expr(a), self.operand_of_sub(ib));
                        quote!(#x - #y)
                    }
                    (true, false) => {
                        let (x, y) = (self.expr(b), self.operand_of_sub(ia));
                        quote!(#x - #y)
                    }
                    _ => {
                        let (x, y) = (self.expr(a), self.expr(b));
                        quote!(#x + #y)
                    }
                }
            }
            Node::Mul(a, b) => {
                let (a, b) = if g.as_const(b).is_some() { (b, a) } else { (a, b) };
                let (x, y) = (self.operand(a), self.operand(b));
                quote!(#x * #y)
            }
        }
    }

    fn is_inline_sum(&self, id: ExprId) -> bool {
        !self.schedule.bound.contains_key(&id) && matches!(self.g.node(id), Node::Add(..) | Node::Neg(..))
    }

    /// An operand of `*` or unary `-`: inline sums and negations get parentheses.
    fn operand(&self, id: ExprId) -> TokenStream {
        let e = self.expr(id);
        if self.is_inline_sum(id) { quote!((#e)) } else { e }
    }

    /// The right operand of `-`: inline sums get parentheses.
    fn operand_of_sub(&self, id: ExprId) -> TokenStream {
        let e = self.expr(id);
        if !self.schedule.bound.contains_key(&id) && matches!(self.g.node(id), Node::Add(..)) {
            quote!((#e))
        } else {
            e
        }
    }

    fn pose(&self, outputs: &[ExprId], krate: &TokenStream) -> TokenStream {
        let e: Vec<TokenStream> = outputs.iter().map(|&id| self.expr(id)).collect();
        if e.len() == 3 {
            let [x, y, z] = [&e[0], &e[1], &e[2]];
            return quote!([#x, #y, #z]);
        }
        let (r, p) = e.split_at(9);
        let (r0, r1, r2) = (&r[0..3], &r[3..6], &r[6..9]);
        quote! {
            #krate::Pose {
                rotation: [[#(#r0),*], [#(#r1),*], [#(#r2),*]],
                translation: [#(#p),*],
            }
        }
    }
}

/// One function computing every frame of `compiled`, generic over `T: Real`.
///
/// One frame returns a `Pose<T>` (or `[T; 3]` for positions only); several return an array of them,
/// in request order.
pub fn emit_function(compiled: &Compiled, options: &EmitOptions) -> TokenStream {
    let g = compiled.graph();
    let outputs = compiled.outputs();
    let schedule = Schedule::new(g, &outputs);
    let w = Writer { g, schedule: &schedule };
    let krate = &options.krate;
    let n = compiled.dof();
    let n_lit = Literal::usize_unsuffixed(n);
    let vars: Vec<TokenStream> = (0..n)
        .map(|i| {
            if schedule.used_vars.contains(&i) {
                let q = format_ident!("q{}", i + 1);
                quote!(#q)
            } else {
                quote!(_)
            }
        })
        .collect();
    let unpack = if n == 0 { quote!(let _ = q;) } else { quote!(let [#(#vars),*] = *q;) };
    let mut body = Vec::new();
    for item in &schedule.items {
        body.push(match item {
            Item::SinCos(angle) => {
                let s = Writer::ident(&schedule.names.sin(*angle));
                let c = Writer::ident(&schedule.names.cos(*angle));
                let a = w.operand(*angle);
                quote!(let (#s, #c) = #a.sin_cos();)
            }
            Item::Let(id, name) => {
                let name = Writer::ident(name);
                let e = w.define(*id);
                quote!(let #name = #e;)
            }
        });
    }
    let per_frame = if compiled.position_only { 3 } else { 12 };
    let frames: Vec<TokenStream> = outputs.chunks(per_frame).map(|o| w.pose(o, krate)).collect();
    let one = if compiled.position_only { quote!([T; 3]) } else { quote!(#krate::Pose<T>) };
    let (ret, value) = if frames.len() == 1 {
        (one, frames[0].clone())
    } else {
        let m = Literal::usize_unsuffixed(frames.len());
        (quote!([#one; #m]), quote!([#(#frames),*]))
    };
    let name = Writer::ident(&options.name);
    let docs = doc_lines(compiled);
    quote! {
        #(#[doc = #docs])*
        #[inline]
        #[allow(clippy::approx_constant)] // a robot's own decimals may resemble pi; they are kept as given
        pub fn #name<T: #krate::Real>(q: &[T; #n_lit]) -> #ret {
            #unpack
            #(#body)*
            #value
        }
    }
}

fn doc_lines(compiled: &Compiled) -> Vec<String> {
    let what = if compiled.position_only { "Position" } else { "Pose" };
    let frames: Vec<String> = compiled.frames().iter().map(|f| format!("`{}`", f.link)).collect();
    let mut docs = vec![
        format!(" {what} of {} in frame `{}` of robot `{}`.", frames.join(", "), compiled.base, compiled.robot),
        String::new(),
    ];
    let joints: Vec<String> =
        compiled.dof_names.iter().enumerate().map(|(i, name)| format!("`q[{i}]` = `{name}`")).collect();
    docs.push(format!(" Joints: {}.", if joints.is_empty() { "none".to_owned() } else { joints.join(", ") }));
    docs.push(String::new());
    docs.push(format!(" Cost: {}.", compiled.op_count()));
    docs
}

/// A formatted Rust source file holding one function (`prettyplease`).
pub fn emit_module_source(compiled: &Compiled, options: &EmitOptions) -> Result<String, syn::Error> {
    let tokens = emit_function(compiled, options);
    let file: syn::File = syn::parse2(tokens)?;
    Ok(prettyplease::unparse(&file))
}
