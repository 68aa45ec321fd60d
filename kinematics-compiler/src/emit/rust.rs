//! Rust tokens through `quote`: one function per compiled request.

use std::fmt::Write as _;

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

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
    /// Whether the function is `pub`.
    pub public: bool,
}

impl EmitOptions {
    /// A function `name` using `::kinematics`.
    pub fn named(name: &str) -> Self {
        EmitOptions { name: name.to_owned(), krate: quote!(::kinematics), public: true }
    }
}

/// Writes expressions as Rust source text into one buffer (linear in the size of the code, however
/// deeply the expressions nest); the text is parsed into tokens once at the end.
struct Writer<'a> {
    g: &'a ExprGraph,
    schedule: &'a Schedule,
    krate: String,
}

impl Writer<'_> {
    fn constant(x: f64, out: &mut String) {
        let lit = Literal::f64_unsuffixed(x.abs()).to_string();
        out.push_str(if x < 0.0 { "T::from_f64(-" } else { "T::from_f64(" });
        out.push_str(&lit);
        out.push(')');
    }

    /// The expression for `id`: its name if bound, else written out.
    fn expr(&self, id: ExprId, out: &mut String) {
        match self.schedule.bound.get(&id) {
            Some(name) => out.push_str(name),
            None => self.define(id, out),
        }
    }

    /// The expression for `id` written out (the right-hand side of its binding).
    fn define(&self, id: ExprId, out: &mut String) {
        let g = self.g;
        match g.node(id) {
            Node::Const(c) => Self::constant(c.value(), out),
            Node::Var(i) => {
                let _ = write!(out, "q{}", i as usize + 1);
            }
            Node::Sin(a) => out.push_str(&self.schedule.names.sin(a)),
            Node::Cos(a) => out.push_str(&self.schedule.names.cos(a)),
            Node::Neg(a) => {
                out.push('-');
                self.operand(a, out);
            }
            Node::Add(a, b) => {
                let (na, ia) = g.unneg(a);
                let (nb, ib) = g.unneg(b);
                match (na, nb) {
                    (false, true) => {
                        self.expr(a, out);
                        out.push_str(" - ");
                        self.operand_of_sub(ib, out);
                    }
                    (true, false) => {
                        self.expr(b, out);
                        out.push_str(" - ");
                        self.operand_of_sub(ia, out);
                    }
                    _ => {
                        self.expr(a, out);
                        out.push_str(" + ");
                        self.expr(b, out);
                    }
                }
            }
            Node::Mul(a, b) => {
                let (a, b) = if g.as_const(b).is_some() { (b, a) } else { (a, b) };
                self.operand(a, out);
                out.push_str(" * ");
                self.operand(b, out);
            }
        }
    }

    fn inline(&self, id: ExprId) -> bool {
        !self.schedule.bound.contains_key(&id)
    }

    /// An operand of `*` or unary `-`: inline sums and negations get parentheses.
    fn operand(&self, id: ExprId, out: &mut String) {
        let wrap = self.inline(id) && matches!(self.g.node(id), Node::Add(..) | Node::Neg(..));
        self.wrapped(id, wrap, out);
    }

    /// The right operand of `-`: inline sums get parentheses.
    fn operand_of_sub(&self, id: ExprId, out: &mut String) {
        let wrap = self.inline(id) && matches!(self.g.node(id), Node::Add(..));
        self.wrapped(id, wrap, out);
    }

    fn wrapped(&self, id: ExprId, wrap: bool, out: &mut String) {
        if wrap {
            out.push('(');
        }
        self.expr(id, out);
        if wrap {
            out.push(')');
        }
    }

    fn list(&self, ids: &[ExprId], out: &mut String) {
        out.push('[');
        for (k, &id) in ids.iter().enumerate() {
            if k > 0 {
                out.push_str(", ");
            }
            self.expr(id, out);
        }
        out.push(']');
    }

    fn pose(&self, outputs: &[ExprId], out: &mut String) {
        if outputs.len() == 3 {
            return self.list(outputs, out);
        }
        let _ = write!(out, "{}::Pose {{ rotation: [", self.krate);
        for row in 0..3 {
            if row > 0 {
                out.push_str(", ");
            }
            self.list(&outputs[3 * row..3 * row + 3], out);
        }
        out.push_str("], translation: ");
        self.list(&outputs[9..12], out);
        out.push_str(" }");
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
    let krate = &options.krate;
    let w = Writer { g, schedule: &schedule, krate: krate.to_string() };
    let n = compiled.dof();
    let n_lit = Literal::usize_unsuffixed(n);
    let mut code = String::new();
    if n == 0 {
        code.push_str("let _ = q;");
    } else {
        let vars: Vec<String> = (0..n)
            .map(|i| if schedule.used_vars.contains(&i) { format!("q{}", i + 1) } else { "_".to_owned() })
            .collect();
        let _ = write!(code, "let [{}] = *q;", vars.join(", "));
    }
    for item in &schedule.items {
        match item {
            Item::SinCos(angle) => {
                let _ = write!(code, "let ({}, {}) = ", schedule.names.sin(*angle), schedule.names.cos(*angle));
                // A method call binds tighter than any operator: parenthesise a written-out angle.
                let composite =
                    w.inline(*angle) && matches!(g.node(*angle), Node::Add(..) | Node::Mul(..) | Node::Neg(..));
                w.wrapped(*angle, composite, &mut code);
                code.push_str(".sin_cos();");
            }
            Item::Let(id, name) => {
                let _ = write!(code, "let {name} = ");
                w.define(*id, &mut code);
                code.push(';');
            }
        }
    }
    let per_frame = if compiled.position_only { 3 } else { 12 };
    let frames: Vec<&[ExprId]> = outputs.chunks(per_frame).collect();
    if frames.len() != 1 {
        code.push('[');
    }
    for (k, frame) in frames.iter().enumerate() {
        if k > 0 {
            code.push_str(", ");
        }
        w.pose(frame, &mut code);
    }
    if frames.len() != 1 {
        code.push(']');
    }
    // The text is built from our own identifiers, operators and literals, so it always parses.
    let body: TokenStream = code.parse().unwrap_or_default();
    let one = if compiled.position_only { quote!([T; 3]) } else { quote!(#krate::Pose<T>) };
    let ret = if frames.len() == 1 {
        one
    } else {
        let m = Literal::usize_unsuffixed(frames.len());
        quote!([#one; #m])
    };
    let name = Ident::new(&options.name, Span::call_site());
    let docs = doc_lines(compiled);
    let vis = if options.public { quote!(pub) } else { quote!() };
    quote! {
        #(#[doc = #docs])*
        // Always inlined into its (small, `#[inline]`) typed callers: a function returning an array
        // of poses writes them to a temporary and the caller copies them where they belong (a 576-byte
        // `memcpy` for a 6-link arm, measured at about a tenth of the PUMA 560's all-link time);
        // inlined, the poses are stored where the caller keeps them.
        #[allow(clippy::inline_always)]
        #[inline(always)]
        #[allow(clippy::approx_constant)] // a robot's own decimals may resemble pi; they are kept as given
        #vis fn #name<T: #krate::Real>(q: &[T; #n_lit]) -> #ret {
            #body
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
