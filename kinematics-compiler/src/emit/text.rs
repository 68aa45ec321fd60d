//! Expressions as plain text (`c1 + c12 + 0.5*c123`) and as LaTeX.
//!
//! The graph shares subexpressions; a tree written out in full repeats them, and along a chain of
//! joints that doubles the text with every joint. [`text_listing`] and [`latex_listing`] therefore
//! print a subexpression that is used more than once, and whose text would be longer than
//! [`INLINE_BUDGET`], once, as a named temporary (`t1 = ...`), and use the name wherever it is
//! needed: every node is then written out in full at most once, apart from short shared pieces,
//! so the text is linear in the size of the graph. Small robots have no such temporaries (the
//! UR5's pose prints as it always did).
//!
//! `INLINE_BUDGET` is 64 bytes.

use super::names::Names;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};

#[derive(Clone, Copy, PartialEq)]
enum Style {
    Text,
    Latex,
}

/// A shared subexpression whose plain text is longer than this many bytes is printed once, as a
/// temporary, instead of wherever it is used (in LaTeX too: both forms name the same ones).
pub const INLINE_BUDGET: usize = 64;

/// Expressions written with shared subexpressions named once: the temporaries, in the order they
/// must be read (each uses only earlier ones), then the expressions asked for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Listing {
    /// `(name, expression)`: `("t1", "c1*c2 - s1*s2")`, or `("t_{1}", ...)` in LaTeX.
    pub temporaries: Vec<(String, String)>,
    /// The expressions asked for, in order.
    pub entries: Vec<String>,
}

/// An expression as text, with textbook names for sines and cosines, written out in full (use
/// [`text_listing`] for expressions that may share large subexpressions).
pub fn text(g: &ExprGraph, names: &Names, id: ExprId) -> String {
    Writer::inline(g, names, Style::Text).write(id)
}

/// An expression as LaTeX (`c_{1} + 0.5 \, c_{123}`), written out in full.
pub fn latex(g: &ExprGraph, names: &Names, id: ExprId) -> String {
    Writer::inline(g, names, Style::Latex).write(id)
}

/// `outputs` as text, shared subexpressions longer than [`INLINE_BUDGET`] named `t1, t2, ...`.
pub fn text_listing(g: &ExprGraph, names: &Names, outputs: &[ExprId]) -> Listing {
    listing(g, names, outputs, Style::Text)
}

/// `outputs` as LaTeX, shared subexpressions longer than [`INLINE_BUDGET`] named `t_{1}, ...`.
pub fn latex_listing(g: &ExprGraph, names: &Names, outputs: &[ExprId]) -> Listing {
    listing(g, names, outputs, Style::Latex)
}

/// The operands a node's text writes out (mirroring [`Writer::write`]): a sum with a negated
/// operand writes the operand under the negation, as a subtraction.
fn operands(g: &ExprGraph, id: ExprId) -> Vec<ExprId> {
    match g.node(id) {
        Node::Sin(_) | Node::Cos(_) => Vec::new(),
        Node::Add(a, b) => {
            let (na, ia) = g.unneg(a);
            let (nb, ib) = g.unneg(b);
            match (na, nb) {
                (false, true) => vec![a, ib],
                (true, false) => vec![b, ia],
                _ => vec![a, b],
            }
        }
        node => node.operands().collect(),
    }
}

fn listing(g: &ExprGraph, names: &Names, outputs: &[ExprId], style: Style) -> Listing {
    // Uses of each node written out: one per operand slot of a parent that is written, one per
    // output. Parents are younger than their operands, so one pass from the youngest node down
    // sees every parent of a node before the node itself.
    let mut uses = vec![0usize; g.len()];
    let mut written = vec![false; g.len()];
    for &id in outputs {
        uses[id.index()] += 1;
        written[id.index()] = true;
    }
    for index in (0..g.len()).rev() {
        if !written[index] {
            continue;
        }
        for operand in operands(g, g.id(index)) {
            uses[operand.index()] += 1;
            written[operand.index()] = true;
        }
    }
    // From the oldest node up: the length of each node's text (saturating; operands named by a
    // temporary count the name), and whether it becomes a temporary. Decided on the plain text,
    // so that the LaTeX form has the same temporaries.
    let mut measure = Writer::inline(g, names, Style::Text);
    let mut length = vec![0usize; g.len()];
    let mut chosen = Vec::new();
    for index in 0..g.len() {
        if !written[index] {
            continue;
        }
        let id = g.id(index);
        length[index] = measure.length(id, &length);
        let compound =
            !matches!(g.node(id), Node::Const(_) | Node::Var(_) | Node::Input(_) | Node::Sin(_) | Node::Cos(_));
        if compound && uses[index] > 1 && length[index] > INLINE_BUDGET {
            measure.temporary[index] = Some(format!("t{}", chosen.len() + 1));
            chosen.push(id);
        }
    }
    let mut writer = Writer::inline(g, names, style);
    let mut temporaries = Vec::new();
    for (i, &id) in chosen.iter().enumerate() {
        let name = match style {
            Style::Text => format!("t{}", i + 1),
            Style::Latex => format!("t_{{{}}}", i + 1),
        };
        writer.temporary[id.index()] = Some(name.clone());
        temporaries.push((id, name));
    }
    let temporaries = temporaries.into_iter().map(|(id, name)| (name, writer.define(id))).collect();
    let entries = outputs.iter().map(|&id| writer.write(id)).collect();
    Listing { temporaries, entries }
}

fn number(x: f64) -> String {
    format!("{x}")
}

/// Writes expressions, naming the nodes that have a temporary.
struct Writer<'a> {
    g: &'a ExprGraph,
    names: &'a Names,
    style: Style,
    /// The temporary's name of each node that has one.
    temporary: Vec<Option<String>>,
}

impl<'a> Writer<'a> {
    /// A writer with no temporaries: every expression in full.
    fn inline(g: &'a ExprGraph, names: &'a Names, style: Style) -> Self {
        Writer { g, names, style, temporary: vec![None; g.len()] }
    }

    /// The text of `id`: its temporary's name if it has one.
    fn write(&self, id: ExprId) -> String {
        let mut out = String::new();
        self.push(&mut out, id);
        out
    }

    /// The text defining `id` (a temporary): the node written out, its operands by name.
    fn define(&self, id: ExprId) -> String {
        let mut out = String::new();
        self.push_node(&mut out, id);
        out
    }

    fn push(&self, out: &mut String, id: ExprId) {
        match &self.temporary[id.index()] {
            Some(name) => out.push_str(name),
            None => self.push_node(out, id),
        }
    }

    fn push_node(&self, out: &mut String, id: ExprId) {
        let (g, names, style) = (self.g, self.names, self.style);
        match g.node(id) {
            Node::Const(c) => out.push_str(&number(c.value())),
            Node::Var(i) => {
                let (letters, index) = names.var(i as usize);
                match style {
                    Style::Text => out.push_str(&format!("{letters}{index}")),
                    Style::Latex => out.push_str(&format!("{letters}_{{{index}}}")),
                }
            }
            Node::Sin(a) => out.push_str(&trig(names.sin(a), style)),
            Node::Cos(a) => out.push_str(&trig(names.cos(a), style)),
            Node::Neg(a) => {
                out.push('-');
                self.factor(out, a);
            }
            Node::Add(a, b) => {
                let (na, ia) = g.unneg(a);
                let (nb, ib) = g.unneg(b);
                match (na, nb) {
                    (false, true) => {
                        self.push(out, a);
                        out.push_str(" - ");
                        self.term(out, ib);
                    }
                    (true, false) => {
                        self.push(out, b);
                        out.push_str(" - ");
                        self.term(out, ia);
                    }
                    _ => {
                        self.push(out, a);
                        out.push_str(" + ");
                        self.push(out, b);
                    }
                }
            }
            Node::Mul(a, b) => {
                // Constant factors first: `0.5*c123`.
                let (a, b) = if g.as_const(b).is_some() { (b, a) } else { (a, b) };
                self.factor(out, a);
                out.push_str(match style {
                    Style::Text => "*",
                    Style::Latex => " \\, ",
                });
                self.factor(out, b);
            }
            Node::Input(i) => out.push_str(&input(i, style)),
            Node::Div(a, b) => {
                self.factor(out, a);
                out.push('/');
                self.wrapped(out, b, self.wraps_divisor(b));
            }
            Node::Sqrt(_) | Node::Atan2(..) | Node::IfPositive(..) => {
                let node = g.node(id);
                out.push_str(call(node, style).0);
                for (k, operand) in node.operands().enumerate() {
                    if k > 0 {
                        out.push_str(", ");
                    }
                    self.push(out, operand);
                }
                out.push_str(call(node, style).1);
            }
        }
    }

    /// The length of the text [`Writer::push_node`] writes for `id`, given the lengths of its
    /// operands' texts (`length`, by index; saturating).
    fn length(&self, id: ExprId, length: &[usize]) -> usize {
        let g = self.g;
        let operand = |x: ExprId| match &self.temporary[x.index()] {
            Some(name) => name.len(),
            None => length[x.index()],
        };
        let parens = match self.style {
            Style::Text => 2,
            Style::Latex => "\\left(\\right)".len(),
        };
        let factor = |x: ExprId| operand(x).saturating_add(if self.wraps_factor(x) { parens } else { 0 });
        let term = |x: ExprId| operand(x).saturating_add(if self.wraps_term(x) { parens } else { 0 });
        match g.node(id) {
            Node::Const(_) | Node::Var(_) | Node::Sin(_) | Node::Cos(_) => self.write(id).len(),
            Node::Neg(a) => 1usize.saturating_add(factor(a)),
            Node::Add(a, b) => {
                let (na, ia) = g.unneg(a);
                let (nb, ib) = g.unneg(b);
                let (first, second) = match (na, nb) {
                    (false, true) => (operand(a), term(ib)),
                    (true, false) => (operand(b), term(ia)),
                    _ => (operand(a), operand(b)),
                };
                first.saturating_add(3).saturating_add(second)
            }
            Node::Mul(a, b) => {
                let join = match self.style {
                    Style::Text => 1,
                    Style::Latex => " \\, ".len(),
                };
                factor(a).saturating_add(join).saturating_add(factor(b))
            }
            Node::Input(i) => input(i, self.style).len(),
            Node::Div(a, b) => {
                let divisor = operand(b).saturating_add(if self.wraps_divisor(b) { parens } else { 0 });
                factor(a).saturating_add(1).saturating_add(divisor)
            }
            node @ (Node::Sqrt(_) | Node::Atan2(..) | Node::IfPositive(..)) => {
                let (open, close) = call(node, self.style);
                let commas = 2 * node.operands().count().saturating_sub(1);
                node.operands().fold(open.len() + close.len() + commas, |total, x| total.saturating_add(operand(x)))
            }
        }
    }

    /// Whether a divisor gets parentheses: what a factor does, and products and quotients too.
    fn wraps_divisor(&self, id: ExprId) -> bool {
        self.wraps_factor(id)
            || (self.temporary[id.index()].is_none() && matches!(self.g.node(id), Node::Mul(..) | Node::Div(..)))
    }

    /// Whether an operand of a product or negation gets parentheses: sums and negative numbers do
    /// (a temporary's name is one symbol and needs none).
    fn wraps_factor(&self, id: ExprId) -> bool {
        self.temporary[id.index()].is_none()
            && match self.g.node(id) {
                Node::Add(..) | Node::Neg(..) => true,
                Node::Const(c) => c.value() < 0.0,
                _ => false,
            }
    }

    /// Whether a subtrahend gets parentheses: sums do.
    fn wraps_term(&self, id: ExprId) -> bool {
        self.temporary[id.index()].is_none() && matches!(self.g.node(id), Node::Add(..))
    }

    /// An operand of a product or negation.
    fn factor(&self, out: &mut String, id: ExprId) {
        self.wrapped(out, id, self.wraps_factor(id));
    }

    /// A subtrahend.
    fn term(&self, out: &mut String, id: ExprId) {
        self.wrapped(out, id, self.wraps_term(id));
    }

    fn wrapped(&self, out: &mut String, id: ExprId, wrap: bool) {
        if !wrap {
            return self.push(out, id);
        }
        out.push_str(match self.style {
            Style::Text => "(",
            Style::Latex => "\\left(",
        });
        self.push(out, id);
        out.push_str(match self.style {
            Style::Text => ")",
            Style::Latex => "\\right)",
        });
    }
}

/// An input's name: `in0`, `\mathrm{in}_{0}`.
fn input(index: u32, style: Style) -> String {
    match style {
        Style::Text => format!("in{index}"),
        Style::Latex => format!("\\mathrm{{in}}_{{{index}}}"),
    }
}

/// What opens and closes a function call's text (its operands between them, comma-separated).
fn call(node: Node, style: Style) -> (&'static str, &'static str) {
    match (node, style) {
        (Node::Sqrt(_), Style::Text) => ("sqrt(", ")"),
        (Node::Sqrt(_), Style::Latex) => ("\\sqrt{", "}"),
        (Node::Atan2(..), Style::Text) => ("atan2(", ")"),
        (Node::Atan2(..), Style::Latex) => ("\\operatorname{atan2}\\left(", "\\right)"),
        (_, Style::Text) => ("if_positive(", ")"),
        (_, Style::Latex) => ("\\operatorname{if}_{>0}\\left(", "\\right)"),
    }
}

fn trig(name: String, style: Style) -> String {
    match style {
        Style::Text => name,
        Style::Latex => format!("{}_{{{}}}", &name[..1], &name[1..]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Request, compile};

    /// The text of every node reachable from the outputs, in bytes: temporaries and entries.
    fn size(listing: &Listing) -> usize {
        listing.temporaries.iter().map(|(n, t)| n.len() + t.len() + 4).sum::<usize>()
            + listing.entries.iter().map(String::len).sum::<usize>()
    }

    #[test]
    fn lengths_are_exact() {
        // The length the listing computes for every node is the length of its text in full.
        let tree = kinematics_model::synthetic::dh_chain(7);
        let compiled = compile(&tree, &Request::tip("link7")).unwrap();
        let g = compiled.graph();
        let names = Names::new(g, &compiled.outputs());
        for style in [Style::Text, Style::Latex] {
            let writer = Writer::inline(g, &names, style);
            let mut length = vec![0; g.len()];
            for index in 0..g.len() {
                let id = g.id(index);
                length[index] = writer.length(id, &length);
                assert_eq!(length[index], writer.write(id).len(), "{}", writer.write(id));
            }
        }
    }

    #[test]
    fn small_robots_print_without_temporaries_as_before() {
        let tree = kinematics_model::synthetic::dh_chain(6);
        let compiled = compile(&tree, &Request::tip("link6")).unwrap();
        let g = compiled.graph();
        let outputs = compiled.frame_outputs(0);
        let names = Names::new(g, &compiled.outputs());
        for (listing, style) in
            [(text_listing(g, &names, &outputs), Style::Text), (latex_listing(g, &names, &outputs), Style::Latex)]
        {
            assert!(listing.temporaries.is_empty(), "{listing:?}");
            let full: Vec<String> = outputs.iter().map(|&id| Writer::inline(g, &names, style).write(id)).collect();
            assert_eq!(listing.entries, full);
        }
    }

    /// issue 13: `expr` printed each entry as a tree, doubling with every joint (30 joints: 241 MB).
    #[test]
    fn a_1000_joint_chain_prints_in_linear_size() {
        for n in [40, 1000] {
            let tree = kinematics_model::synthetic::dh_chain(n);
            let compiled = compile(&tree, &Request::tip(&format!("link{n}"))).unwrap();
            let g = compiled.graph();
            let outputs = compiled.frame_outputs(0);
            let names = Names::new(g, &compiled.outputs());
            let nodes = crate::stats::reachable(g, outputs.iter().copied()).len();
            // Written out in full (as `text` does), the entries would be far past the bound.
            let inline = Writer::inline(g, &names, Style::Text);
            let mut length = vec![0; g.len()];
            for index in 0..g.len() {
                length[index] = inline.length(g.id(index), &length);
            }
            let full = outputs.iter().fold(0usize, |sum, id| sum.saturating_add(length[id.index()]));
            assert!(full > 200 * nodes, "{n} joints: {full} bytes in full");
            for listing in [text_listing(g, &names, &outputs), latex_listing(g, &names, &outputs)] {
                let bytes = size(&listing);
                assert!(bytes < 200 * nodes, "{n} joints: {bytes} bytes for {nodes} nodes");
                assert!(bytes < 4_000_000, "{n} joints: {bytes} bytes");
                assert!(!listing.temporaries.is_empty());
            }
        }
    }

    #[test]
    fn shared_subexpressions_past_the_budget_are_named_once() {
        // Along a chain of parallel-free joints, the text of the tip's x entry written in full
        // would double with every joint; with temporaries every temporary is defined before use.
        let tree = kinematics_model::synthetic::dh_chain(24);
        let compiled = compile(&tree, &Request::tip("link24")).unwrap();
        let g = compiled.graph();
        let names = Names::new(g, &compiled.outputs());
        let listing = text_listing(g, &names, &compiled.frame_outputs(0));
        for (i, (name, definition)) in listing.temporaries.iter().enumerate() {
            assert_eq!(name, &format!("t{}", i + 1));
            // Only earlier temporaries are used.
            for later in i + 1..=listing.temporaries.len() {
                let used = definition.split(|c: char| !c.is_alphanumeric()).any(|w| w == format!("t{later}"));
                assert!(!used, "{name} = {definition} uses t{later}");
            }
            assert!(!definition.is_empty());
        }
        // Every temporary is used at least twice, counting its uses in later temporaries and entries.
        for (name, _) in &listing.temporaries {
            let uses: usize = listing
                .temporaries
                .iter()
                .map(|(_, t)| t)
                .chain(&listing.entries)
                .map(|t| t.split(|c: char| !c.is_alphanumeric()).filter(|w| w == name).count())
                .sum();
            assert!(uses >= 2, "{name} is used {uses} times");
        }
    }
}
