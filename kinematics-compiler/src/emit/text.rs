//! Expressions as plain text (`c1 + c12 + 0.5*c123`) and as LaTeX.

use super::names::Names;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};

#[derive(Clone, Copy)]
enum Style {
    Text,
    Latex,
}

/// An expression as text, with textbook names for sines and cosines.
pub fn text(g: &ExprGraph, names: &Names, id: ExprId) -> String {
    render(g, names, id, Style::Text)
}

/// An expression as LaTeX (`c_{1} + 0.5 \, c_{123}`).
pub fn latex(g: &ExprGraph, names: &Names, id: ExprId) -> String {
    render(g, names, id, Style::Latex)
}

fn number(x: f64) -> String {
    format!("{x}")
}

fn render(g: &ExprGraph, names: &Names, id: ExprId, style: Style) -> String {
    match g.node(id) {
        Node::Const(c) => number(c.value()),
        Node::Var(i) => match style {
            Style::Text => format!("q{}", i + 1),
            Style::Latex => format!("q_{{{}}}", i + 1),
        },
        Node::Sin(a) => trig(names.sin(a), style),
        Node::Cos(a) => trig(names.cos(a), style),
        Node::Neg(a) => format!("-{}", factor(g, names, a, style)),
        Node::Add(a, b) => {
            let (na, ia) = g.unneg(a);
            let (nb, ib) = g.unneg(b);
            match (na, nb) {
                (false, true) => format!("{} - {}", render(g, names, a, style), term(g, names, ib, style)),
                (true, false) => format!("{} - {}", render(g, names, b, style), term(g, names, ia, style)),
                _ => format!("{} + {}", render(g, names, a, style), render(g, names, b, style)),
            }
        }
        Node::Mul(a, b) => {
            // Constant factors first: `0.5*c123`.
            let (a, b) = if g.as_const(b).is_some() { (b, a) } else { (a, b) };
            let join = match style {
                Style::Text => "*",
                Style::Latex => " \\, ",
            };
            format!("{}{join}{}", factor(g, names, a, style), factor(g, names, b, style))
        }
    }
}

fn trig(name: String, style: Style) -> String {
    match style {
        Style::Text => name,
        Style::Latex => format!("{}_{{{}}}", &name[..1], &name[1..]),
    }
}

/// An operand of a product or negation: sums and negative numbers get parentheses.
fn factor(g: &ExprGraph, names: &Names, id: ExprId, style: Style) -> String {
    let s = render(g, names, id, style);
    let wrap = match g.node(id) {
        Node::Add(..) | Node::Neg(..) => true,
        Node::Const(c) => c.value() < 0.0,
        _ => false,
    };
    if wrap { paren(s, style) } else { s }
}

/// A subtrahend: sums get parentheses.
fn term(g: &ExprGraph, names: &Names, id: ExprId, style: Style) -> String {
    let s = render(g, names, id, style);
    if matches!(g.node(id), Node::Add(..)) { paren(s, style) } else { s }
}

fn paren(s: String, style: Style) -> String {
    match style {
        Style::Text => format!("({s})"),
        Style::Latex => format!("\\left({s}\\right)"),
    }
}
