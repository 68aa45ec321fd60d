//! Emitted expressions nest no deeper than a fixed bound, however long the chain (issue 13: rustc
//! overflowed its stack compiling a derived 500-joint chain, whose expressions nested as deep as the
//! chain was long), and bounding them costs no operation: every graph node is written once.
//!
//! The synthetic industrial chain nests only about 10 levels even unbounded (its twists break the
//! angle sums every three joints); a planar chain, whose rotations all merge into sums
//! `q1 + ... + qk`, nested 504 levels deep at 500 joints before the bound.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_compiler::emit::{EmitOptions, MAX_EXPRESSION_DEPTH, emit_function};
use kinematics_compiler::{Compiled, OpCount, Request, compile};
use kinematics_model::synthetic;
use quote::quote;

/// What the emitted body contains: its deepest expression and its binary operators.
#[derive(Debug, Default)]
struct Measure {
    depth: usize,
    mul: usize,
    add: usize,
}

impl Measure {
    /// Walks `e` (one more level than `level`). Only the forms the emitter writes are expected;
    /// any other is a failure, so nothing goes uncounted.
    fn expr(&mut self, e: &syn::Expr, level: usize) {
        let level = level + 1;
        self.depth = self.depth.max(level);
        match e {
            syn::Expr::Binary(b) => {
                match b.op {
                    syn::BinOp::Mul(_) => self.mul += 1,
                    syn::BinOp::Add(_) | syn::BinOp::Sub(_) => self.add += 1,
                    _ => panic!("unexpected operator in `{}`", quote!(#b)),
                }
                self.expr(&b.left, level);
                self.expr(&b.right, level);
            }
            syn::Expr::Unary(u) => self.expr(&u.expr, level),
            syn::Expr::Paren(p) => self.expr(&p.expr, level),
            syn::Expr::Call(c) => {
                self.expr(&c.func, level);
                c.args.iter().for_each(|a| self.expr(a, level));
            }
            syn::Expr::MethodCall(m) => {
                self.expr(&m.receiver, level);
                m.args.iter().for_each(|a| self.expr(a, level));
            }
            syn::Expr::Array(a) => a.elems.iter().for_each(|x| self.expr(x, level)),
            syn::Expr::Struct(s) => s.fields.iter().for_each(|f| self.expr(&f.expr, level)),
            syn::Expr::Path(_) | syn::Expr::Lit(_) => {}
            // A chunk (`chunk(|| { ..; (a, b) })`, for debug builds' stack) and what it returned
            // read back (`chunk_0.1`): the closure's statements nest inside the call.
            syn::Expr::Closure(c) => self.expr(&c.body, level),
            syn::Expr::Block(b) => self.statements(&b.block.stmts, level),
            syn::Expr::Tuple(t) => t.elems.iter().for_each(|x| self.expr(x, level)),
            syn::Expr::Field(f) => self.expr(&f.base, level),
            other => panic!("unexpected expression `{}`", quote!(#other)),
        }
    }
}

impl Measure {
    /// Walks each statement's expression at `level`.
    fn statements(&mut self, stmts: &[syn::Stmt], level: usize) {
        for stmt in stmts {
            match stmt {
                syn::Stmt::Local(local) => self.expr(&local.init.as_ref().unwrap().expr, level),
                syn::Stmt::Expr(e, _) => self.expr(e, level),
                other => panic!("unexpected statement `{}`", quote!(#other)),
            }
        }
    }
}

/// Measures the function emitted for `compiled`, in a thread with a large stack: the syntax tree
/// of code without the bound is as deep as the chain, and so is the recursion that walks it. A
/// body with block marks is two functions (as written for optimised builds, in chunks for debug
/// builds): each must hold to the bound and write every operation once, and the deeper is
/// returned.
fn measure(compiled: Compiled) -> (Measure, OpCount) {
    std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(move || {
            let tokens = emit_function(&compiled, &EmitOptions::named("fk"));
            let file: syn::File = syn::parse2(tokens).unwrap();
            let ops = compiled.op_count();
            let mut deepest = Measure::default();
            for item in &file.items {
                let syn::Item::Fn(function) = item else { panic!("only functions") };
                let mut m = Measure::default();
                m.statements(&function.block.stmts, 0);
                assert_eq!((m.mul, m.add), (ops.mul, ops.add), "each form writes every operation once");
                if m.depth >= deepest.depth {
                    deepest = m;
                }
            }
            (deepest, ops)
        })
        .unwrap()
        .join()
        .unwrap()
}

#[test]
fn a_500_joint_chain_nests_no_deeper_than_the_bound() {
    let tree = synthetic::dh_chain(500);
    for request in [Request::tip("link500"), Request::all_links(), Request::tip("link500").positions_only()] {
        let compiled = compile(&tree, &request).unwrap();
        let (m, ops) = measure(compiled);
        println!("{request:?}: depth {}, {ops}", m.depth);
        assert!(m.depth <= MAX_EXPRESSION_DEPTH, "{request:?}: expressions nest {} deep", m.depth);
        // Each multiplication and addition of the graph is written exactly once.
        assert_eq!((m.mul, m.add), (ops.mul, ops.add), "{request:?}");
    }
}

#[test]
fn small_robots_are_within_the_bound_and_written_once() {
    for n in [1, 2, 6, 40] {
        let tree = synthetic::dh_chain(n);
        for request in [Request::tip(&format!("link{n}")), Request::all_links()] {
            let (m, ops) = measure(compile(&tree, &request).unwrap());
            assert!(m.depth <= MAX_EXPRESSION_DEPTH, "{n} joints, {request:?}: {}", m.depth);
            assert_eq!((m.mul, m.add), (ops.mul, ops.add), "{n} joints, {request:?}");
        }
    }
}

/// A planar chain of `n` joints (every twist zero: the rotations merge into angle sums
/// `q1 + ... + qk`), as a DH table.
fn planar_chain(n: usize) -> kinematics_model::KinematicTree {
    let mut toml = String::from("convention = \"standard\"\nname = \"planar\"\n");
    for i in 1..=n {
        toml.push_str(&format!("[[joints]]\nname = \"j{i}\"\na = {}\nd = {}\n", 0.1 + 0.001 * i as f64, 0.01));
    }
    kinematics_model::parse_source("planar.toml", &toml).unwrap()
}

#[test]
fn a_500_joint_planar_chain_nests_no_deeper_than_the_bound() {
    let tree = planar_chain(500);
    for request in [Request::tip("link500"), Request::tip("link500").positions_only()] {
        let (m, ops) = measure(compile(&tree, &request).unwrap());
        println!("planar {request:?}: depth {}, {ops}", m.depth);
        assert!(m.depth <= MAX_EXPRESSION_DEPTH, "{request:?}: expressions nest {} deep", m.depth);
        assert_eq!((m.mul, m.add), (ops.mul, ops.add), "{request:?}");
    }
}
