//! Test-only: a parser of the text [`steps_text`] and [`expr_text`] write, and the `check` helpers
//! the passes' unit tests are written with (`check(&MERGE_ROTATIONS, "Rz(q1) Rz(q2)", "Rz(q1 + q2)")`).
//!
//! The parser builds through the graph's smart constructors, so `q1 - q1` reads as `0`; the text a
//! test expects is what the printer writes.

use kinematics_model::Angle;

use super::{ChainPass, ExprPass, Options};
use crate::symbolic::angle::LinearAngle;
use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::step::{SignedPerm, Step, expr_text, steps_text};
use crate::symbolic::transform::SymTransform;

/// Runs `pass` with the default options on the chain `input` and compares the chain's text.
#[track_caller]
pub fn check(pass: &ChainPass, input: &str, expected: &str) {
    check_with(pass, Options::default(), input, expected);
}

/// Runs `pass` with `options` on the chain `input` and compares the chain's text.
#[track_caller]
pub fn check_with(pass: &ChainPass, options: Options, input: &str, expected: &str) {
    let mut g = ExprGraph::new();
    let steps = parse_steps(&mut g, input);
    let output = (pass.run)(&mut g, steps, options);
    assert_eq!(steps_text(&g, &output), expected, "`{}` on `{input}`", pass.name);
}

/// Runs the expression pass on the poses `input` and compares their text (see [`frame_text`]).
#[track_caller]
pub fn check_frames(pass: &ExprPass, position_only: bool, input: &[&str], expected: &[&str]) {
    let mut g = ExprGraph::new();
    let mut frames: Vec<SymTransform> = input.iter().map(|text| parse_frame(&mut g, text)).collect();
    (pass.run)(&mut g, &mut frames, &mut [], position_only);
    let output: Vec<String> = frames.iter().map(|t| frame_text(&g, t)).collect();
    assert_eq!(output, expected, "`{}` on {input:?}", pass.name);
}

/// A pose as `[r00, r01, ..., r22; p0, p1, p2]` (rotation row-major), or `[p0, p1, p2]` when the
/// rotation is the identity.
pub fn frame_text(g: &ExprGraph, t: &SymTransform) -> String {
    let p = t.p.map(|x| expr_text(g, x)).join(", ");
    let identity = (0..3).all(|i| (0..3).all(|j| g.is_const(t.r[i][j], if i == j { 1.0 } else { 0.0 })));
    if identity {
        return format!("[{p}]");
    }
    let r: Vec<String> = t.r.iter().flatten().map(|&x| expr_text(g, x)).collect();
    format!("[{}; {p}]", r.join(", "))
}

fn parse_frame(g: &mut ExprGraph, text: &str) -> SymTransform {
    let inner = text.strip_prefix('[').and_then(|t| t.strip_suffix(']')).expect("a pose in brackets");
    let mut t = SymTransform::identity(g);
    let p = match inner.split_once("; ") {
        None => inner,
        Some((r, p)) => {
            let r = split_top(r, ", ");
            assert_eq!(r.len(), 9, "nine rotation entries in `{text}`");
            for (k, entry) in r.iter().enumerate() {
                t.r[k / 3][k % 3] = parse_expr(g, entry);
            }
            p
        }
    };
    let p = split_top(p, ", ");
    assert_eq!(p.len(), 3, "three translation entries in `{text}`");
    t.p = std::array::from_fn(|i| parse_expr(g, p[i]));
    t
}

/// Splits at `separator` outside parentheses and brackets.
fn split_top<'a>(text: &'a str, separator: &str) -> Vec<&'a str> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'(' | b'[' => depth += 1,
            b')' | b']' => depth -= 1,
            _ if depth == 0 && text[i..].starts_with(separator) => {
                parts.push(&text[start..i]);
                i += separator.len();
                start = i;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    parts.push(&text[start..]);
    parts
}

/// Parses a chain written as [`steps_text`] writes it.
pub fn parse_steps(g: &mut ExprGraph, text: &str) -> Vec<Step> {
    if text == "I" {
        return Vec::new();
    }
    split_top(text, " ").into_iter().map(|step| parse_step(g, step)).collect()
}

fn inside<'a>(text: &'a str, prefix: &str) -> &'a str {
    text.strip_prefix(prefix).and_then(|t| t.strip_suffix(')')).unwrap_or_else(|| panic!("`{text}`: {prefix}...)"))
}

fn number(text: &str) -> f64 {
    text.parse().unwrap_or_else(|_| panic!("`{text}` is not a number"))
}

fn parse_step(g: &mut ExprGraph, text: &str) -> Step {
    if text.starts_with("T(") {
        let v = split_top(inside(text, "T("), ", ");
        assert_eq!(v.len(), 3, "`{text}`");
        return Step::Translate(std::array::from_fn(|i| parse_expr(g, v[i])));
    }
    if text.starts_with("P(") {
        let entries = split_top(inside(text, "P("), ", ");
        assert_eq!(entries.len(), 3, "`{text}`");
        let mut m = [[0.0; 3]; 3];
        for (i, entry) in entries.iter().enumerate() {
            let (sign, name) = match entry.strip_prefix('-') {
                Some(name) => (-1.0, name),
                None => (1.0, *entry),
            };
            m[i][axis_index(name)] = sign;
        }
        return Step::Permute(SignedPerm::from_matrix(m).unwrap_or_else(|| panic!("`{text}` is no permutation")));
    }
    if text.starts_with("C(") {
        let rows = split_top(inside(text, "C("), "; ");
        assert_eq!(rows.len(), 3, "`{text}`");
        let rows: Vec<Vec<f64>> =
            rows.iter().map(|row| split_top(row, ", ").into_iter().map(number).collect()).collect();
        return Step::ConstRotate(std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j])));
    }
    let rest = text.strip_prefix('R').unwrap_or_else(|| panic!("`{text}` is no step"));
    let (axis, angle) = if let Some(rest) = rest.strip_prefix('[') {
        let (axis, angle) = rest.split_once("](").unwrap_or_else(|| panic!("`{text}`"));
        let axis = split_top(axis, ", ");
        assert_eq!(axis.len(), 3, "`{text}`");
        (std::array::from_fn(|i| number(axis[i])), angle)
    } else {
        let (sign, rest) = match rest.strip_prefix('-') {
            Some(rest) => (-1.0, rest),
            None => (1.0, rest),
        };
        let (name, angle) = rest.split_once('(').unwrap_or_else(|| panic!("`{text}`"));
        let mut axis = [0.0; 3];
        axis[axis_index(name)] = sign;
        (axis, angle)
    };
    let angle = angle.strip_suffix(')').unwrap_or_else(|| panic!("`{text}`"));
    Step::Rotate { axis, angle: parse_angle(angle) }
}

fn axis_index(name: &str) -> usize {
    match name {
        "x" => 0,
        "y" => 1,
        "z" => 2,
        _ => panic!("`{name}` is no axis"),
    }
}

/// Parses an angle written as [`LinearAngle`]'s display writes it (`q1 + 2*q3 - pi/2 + 0.3`).
pub fn parse_angle(text: &str) -> LinearAngle {
    let (mut negative, mut rest) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text),
    };
    let mut angle = LinearAngle::constant(Angle::ZERO);
    loop {
        let next = [rest.find(" + "), rest.find(" - ")].into_iter().flatten().min();
        let (term, tail) = match next {
            Some(i) => (&rest[..i], Some(&rest[i..])),
            None => (rest, None),
        };
        let term = if let Some((k, var)) = term.split_once('q').map(|(k, var)| (k.strip_suffix('*'), var)) {
            let k = k.map_or(1.0, number);
            let dof: usize = var.parse().unwrap_or_else(|_| panic!("`{term}`"));
            LinearAngle::joint(dof - 1, if negative { -k } else { k }, 0.0)
        } else if term.contains("pi") {
            let signed = if negative { format!("-{term}") } else { term.to_owned() };
            LinearAngle::constant(Angle::parse_exact(&signed).unwrap_or_else(|| panic!("`{term}`")))
        } else {
            let x = number(term);
            LinearAngle::constant(Angle::Radians(if negative { -x } else { x }))
        };
        angle = angle.plus(&term);
        match tail {
            None => return angle,
            Some(tail) => {
                negative = tail.starts_with(" -");
                rest = &tail[3..];
            }
        }
    }
}

/// Parses an expression written as [`expr_text`] writes it, through the smart constructors.
pub fn parse_expr(g: &mut ExprGraph, text: &str) -> ExprId {
    let mut parser = Parser { text: text.as_bytes(), at: 0 };
    let id = parser.sum(g);
    parser.skip_spaces();
    assert_eq!(parser.at, text.len(), "trailing text in `{text}`");
    id
}

struct Parser<'a> {
    text: &'a [u8],
    at: usize,
}

impl Parser<'_> {
    fn skip_spaces(&mut self) {
        while self.text.get(self.at) == Some(&b' ') {
            self.at += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip_spaces();
        self.text.get(self.at).copied()
    }

    fn eat(&mut self, token: &str) -> bool {
        self.skip_spaces();
        if self.text[self.at..].starts_with(token.as_bytes()) {
            self.at += token.len();
            true
        } else {
            false
        }
    }

    fn sum(&mut self, g: &mut ExprGraph) -> ExprId {
        let mut sum = self.product(g);
        loop {
            if self.eat("+") {
                let term = self.product(g);
                sum = g.add(sum, term);
            } else if self.eat("-") {
                let term = self.product(g);
                sum = g.sub(sum, term);
            } else {
                return sum;
            }
        }
    }

    fn product(&mut self, g: &mut ExprGraph) -> ExprId {
        let mut product = self.unary(g);
        while self.eat("*") {
            let factor = self.unary(g);
            product = g.mul(product, factor);
        }
        product
    }

    fn unary(&mut self, g: &mut ExprGraph) -> ExprId {
        if self.eat("-") {
            let a = self.unary(g);
            return g.neg(a);
        }
        self.atom(g)
    }

    fn atom(&mut self, g: &mut ExprGraph) -> ExprId {
        if self.eat("(") {
            let inner = self.sum(g);
            assert!(self.eat(")"), "unclosed parenthesis at {}", self.at);
            return inner;
        }
        for (name, f) in [("sin(", ExprGraph::sin as fn(&mut ExprGraph, ExprId) -> ExprId), ("cos(", ExprGraph::cos)] {
            if self.eat(name) {
                let inner = self.sum(g);
                assert!(self.eat(")"), "unclosed {name} at {}", self.at);
                return f(g, inner);
            }
        }
        if self.eat("q") {
            let start = self.at;
            while self.text.get(self.at).is_some_and(u8::is_ascii_digit) {
                self.at += 1;
            }
            let index: usize = std::str::from_utf8(&self.text[start..self.at]).unwrap().parse().unwrap();
            return g.var(index - 1);
        }
        assert!(self.peek().is_some_and(|c| c.is_ascii_digit()), "no operand at {}", self.at);
        let start = self.at;
        while let Some(&c) = self.text.get(self.at) {
            let exponent_sign = (c == b'-' || c == b'+') && self.text[self.at - 1] == b'e';
            if !(c.is_ascii_digit() || c == b'.' || c == b'e' || exponent_sign) {
                break;
            }
            self.at += 1;
        }
        let value = number(std::str::from_utf8(&self.text[start..self.at]).unwrap());
        g.constant(value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The parser reads back what the printers write.
    #[test]
    fn text_round_trips() {
        let chains = [
            "I",
            "Rz(q1) T(0.5, 0, 0) Rz(q2 + pi/2) P(y, -x, z) C(1, 0, 0; 0, 0.8, -0.6; 0, 0.6, 0.8)",
            "R-x(-q1 + 2*q3 - 3*pi/2 - 0.3) R[0.6, 0, -0.8](0) T(q1*cos(q2 + 0.1), -(0.5*sin(q1) + q3), 6.123233995736766e-17)",
            "Ry(1.5707963267948966) T(q1 - 0.5, -(q1 + q2), q2*(q1*q3)) C(1, 0, 0; 0, 6.123233995736766e-17, -1; 0, 1, 6.123233995736766e-17)",
        ];
        for text in chains {
            let mut g = ExprGraph::new();
            let steps = parse_steps(&mut g, text);
            assert_eq!(steps_text(&g, &steps), text);
        }
    }

    /// The parser builds through the smart constructors and angles as linear forms.
    #[test]
    fn text_is_read_canonically() {
        let mut g = ExprGraph::new();
        let steps = parse_steps(&mut g, "T(q1 - q1, 2*3, -(-q2)) Rz(q1 + q2 - q1 + 0.25 + 0.25)");
        assert_eq!(steps_text(&g, &steps), "T(0, 6, q2) Rz(q2 + 0.5)");
        assert_eq!(parse_angle("-pi/2 + pi"), LinearAngle::constant(Angle::parse_exact("pi/2").unwrap()));
    }
}
