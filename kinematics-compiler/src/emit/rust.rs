//! Rust tokens through `quote`: one function per compiled request.
//!
//! Rust is built as tokens with `quote`, never text parsed back. `straight_line` gives the
//! statements of any graph with named inputs, for the IK's bodies; `emit_points` the sphere
//! centres. Generic bodies are `#[inline(always)]` into their typed callers, so arrays of poses are
//! stored where the caller keeps them rather than copied there.

use kinematics_core::BLOCK_MARK_OPS;
use proc_macro2::{Delimiter, Group, Ident, Literal, Punct, Spacing, Span, TokenStream};
use quote::{ToTokens as _, TokenStreamExt as _, format_ident, quote};

use super::chunks::function;
use super::schedule::{Item, Schedule};
use crate::dynamics::{CompiledDynamics, DynamicsFunction};
use crate::request::{Compiled, VelocityForm};
use crate::stats::OpCount;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};

/// Which sine and cosine generated code calls.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Trig {
    /// Ours (`kinematics_core::trig`, through `Real`): every angle of a function in one
    /// `sin_cos_many` call, computed side by side in SIMD lanes. The default.
    #[default]
    Fast,
    /// The platform's (`StdTrig::sin_cos_std`, std's `sin_cos`), one call per angle. Needs the
    /// facade's `std` feature.
    Std,
}

impl Trig {
    /// The bound on the generated functions' scalar type, `private` being the path of the
    /// facade's private module.
    pub fn bound(self, private: &TokenStream) -> TokenStream {
        match self {
            Trig::Fast => quote!(#private::Real),
            Trig::Std => quote!(#private::Real + #private::StdTrig),
        }
    }
}

/// How to emit a function.
#[derive(Debug, Clone)]
pub struct EmitOptions {
    /// The function's name.
    pub name: String,
    /// Path of the module generated code takes `Real`, `Pose` and the sine and cosine from:
    /// the facade's private module (default `::kinematics::__private`), which re-exports
    /// `kinematics_core`.
    pub private: TokenStream,
    /// Whether the function is `pub`.
    pub public: bool,
    /// Which sine and cosine the function calls.
    pub trig: Trig,
}

impl EmitOptions {
    /// A public function `name` using `::kinematics::__private` and our sin/cos.
    pub fn named(name: &str) -> Self {
        EmitOptions { name: name.to_owned(), private: quote!(::kinematics::__private), public: true, trig: Trig::Fast }
    }
}

/// Writes expressions as tokens into one stream (each token once: linear in the size of the code).
/// The recursion follows expressions written inline, which the schedule keeps at most
/// [`INLINE_DEPTH_LIMIT`](super::schedule::INLINE_DEPTH_LIMIT) levels deep.
struct Writer<'a> {
    g: &'a ExprGraph,
    schedule: &'a Schedule,
    private: &'a TokenStream,
    /// Entries of `q` and of `qd`: variables from `q.0` on are joint rates (`qd1`, ...), from
    /// `q.0 + q.1` on floating and spherical joints' rotations (`rot1_11`, ...).
    sizes: (usize, usize),
    /// The names of the inputs ([`Node::Input`]), by index.
    inputs: &'a [Ident],
}

/// The block marks of one body: `T::block_mark(1);`, `T::block_mark(2);`, ... about every
/// [`BLOCK_MARK_OPS`] operations (the core's `Real::block_mark` says why: a lane type ends a block
/// at every few marks, so that LLVM's vectorizer schedules each block whole).
#[derive(Default, Clone, Copy)]
struct Marks {
    /// Operations since the last mark.
    ops: usize,
    /// Marks written.
    written: usize,
}

impl Marks {
    /// Of statements of `ops` operations each, written after the marks so far: the last one a
    /// mark would follow, if any.
    fn last_followed(self, ops: &[usize]) -> Option<usize> {
        let mut marks = self;
        let mut last = None;
        for (k, &n) in ops.iter().enumerate() {
            if marks.count(n) {
                last = Some(k);
            }
        }
        last
    }

    /// Counts a statement of `ops` operations: whether a mark follows it.
    fn count(&mut self, ops: usize) -> bool {
        self.ops += ops;
        if self.ops >= BLOCK_MARK_OPS {
            self.ops = 0;
            self.written += 1;
            true
        } else {
            false
        }
    }

    /// After a statement of `ops` operations: a mark if they bring the count to the spacing.
    fn after(&mut self, ops: usize, out: &mut TokenStream) {
        if self.count(ops) {
            let mark = Literal::usize_unsuffixed(self.written);
            out.extend(quote!(T::block_mark(#mark);));
        }
    }
}

/// The name of the graph's variable `i` (`sizes`: the lengths of `q` and `qd`): a joint position
/// `q1`, a joint rate `qd1`, or the entry (row 1, column 2) of the first floating or spherical
/// joint's rotation, `rot1_12`.
fn var_ident(i: usize, (dof, velocities): (usize, usize)) -> Ident {
    if i < dof {
        format_ident!("q{}", i + 1)
    } else if i < dof + velocities {
        format_ident!("qd{}", i - dof + 1)
    } else {
        let k = i - dof - velocities;
        format_ident!("rot{}_{}{}", k / 9 + 1, k % 9 / 3 + 1, k % 3 + 1)
    }
}

fn ident(name: &str) -> Ident {
    Ident::new(name, Span::call_site())
}

fn punct(out: &mut TokenStream, op: char) {
    out.append(Punct::new(op, Spacing::Alone));
}

fn group(out: &mut TokenStream, delimiter: Delimiter, inner: TokenStream) {
    out.append(Group::new(delimiter, inner));
}

/// A number as tokens: a literal when finite. [`compile`](crate::compile) rejects poses with
/// constants that are not finite, so the other arms are never taken; they write the value itself
/// rather than panic (as `Literal::f64_unsuffixed` would) or write another number.
fn magnitude(x: f64, out: &mut TokenStream) {
    if x.is_finite() {
        out.append(Literal::f64_unsuffixed(x.abs()));
    } else if x.is_nan() {
        out.extend(quote!(::core::primitive::f64::NAN));
    } else {
        out.extend(quote!(::core::primitive::f64::INFINITY));
    }
}

impl Writer<'_> {
    /// `T::from_f64(x)`.
    fn constant(x: f64, out: &mut TokenStream) {
        out.extend(quote!(T::from_f64));
        let mut arg = TokenStream::new();
        if x < 0.0 {
            punct(&mut arg, '-');
        }
        magnitude(x, &mut arg);
        group(out, Delimiter::Parenthesis, arg);
    }

    /// The expression for `id`: its name if bound, else written out.
    fn expr(&self, id: ExprId, out: &mut TokenStream) {
        match self.schedule.bound.get(&id) {
            Some(name) => out.append(ident(name)),
            None => self.define(id, out),
        }
    }

    /// The expression for `id` written out (the right-hand side of its binding).
    fn define(&self, id: ExprId, out: &mut TokenStream) {
        let g = self.g;
        match g.node(id) {
            Node::Const(c) => Self::constant(c.value(), out),
            Node::Var(i) => out.append(var_ident(i as usize, self.sizes)),
            Node::Sin(a) => out.append(ident(&self.schedule.names.sin(a))),
            Node::Cos(a) => out.append(ident(&self.schedule.names.cos(a))),
            Node::Neg(a) => {
                punct(out, '-');
                self.operand(a, out);
            }
            Node::Add(a, b) => {
                let (na, ia) = g.unneg(a);
                let (nb, ib) = g.unneg(b);
                match (na, nb) {
                    (false, true) => {
                        self.expr(a, out);
                        punct(out, '-');
                        self.operand_of_sub(ib, out);
                    }
                    (true, false) => {
                        self.expr(b, out);
                        punct(out, '-');
                        self.operand_of_sub(ia, out);
                    }
                    _ => {
                        self.expr(a, out);
                        punct(out, '+');
                        // `a + (x + y)` is not `a + x + y`, which Rust reads as `(a + x) + y`: in
                        // floating point they round differently, and the code must compute what
                        // the graph says (the evaluator's value, bit for bit).
                        let wrap = self.inline(b) && matches!(g.node(b), Node::Add(..));
                        self.wrapped(b, wrap, out);
                    }
                }
            }
            Node::Mul(a, b) => {
                let (a, b) = if g.as_const(b).is_some() { (b, a) } else { (a, b) };
                self.operand(a, out);
                punct(out, '*');
                // `a * (x * y)` likewise.
                let wrap = self.inline(b)
                    && matches!(g.node(b), Node::Add(..) | Node::Neg(..) | Node::Div(..) | Node::Mul(..));
                self.wrapped(b, wrap, out);
            }
            Node::Input(i) => out.append(self.input(i)),
            Node::Div(a, b) => {
                self.operand(a, out);
                punct(out, '/');
                let wrap = self.inline(b)
                    && matches!(g.node(b), Node::Add(..) | Node::Neg(..) | Node::Mul(..) | Node::Div(..));
                self.wrapped(b, wrap, out);
            }
            Node::Sqrt(a) => self.call("sqrt", &[a], out),
            Node::Atan2(y, x) => self.call("atan2", &[y, x], out),
            Node::IfPositive(c, a, b) => self.call("if_positive", &[c, a, b], out),
        }
    }

    /// The name of input `i`.
    #[allow(clippy::expect_used, reason = "an invariant of the caller, named in the message")]
    fn input(&self, i: u32) -> Ident {
        // Whoever builds a graph with inputs names them all (`straight_line`'s `inputs`).
        self.inputs.get(i as usize).cloned().expect("every input of an emitted graph has a name")
    }

    /// `T::name(a, b)`: a function of `IkReal`, which the bound on `T` brings.
    fn call(&self, name: &str, operands: &[ExprId], out: &mut TokenStream) {
        out.extend(quote!(T::));
        out.append(ident(name));
        let mut arguments = TokenStream::new();
        for (k, &a) in operands.iter().enumerate() {
            if k > 0 {
                punct(&mut arguments, ',');
            }
            self.expr(a, &mut arguments);
        }
        group(out, Delimiter::Parenthesis, arguments);
    }

    /// The operations `define(id)` writes: its own and those of the operands it writes out (a
    /// negation folded into a difference counted as one), what a block mark's spacing counts.
    fn ops_written(&self, id: ExprId) -> usize {
        let g = self.g;
        let operand = |a: ExprId| if self.inline(a) { self.ops_written(a) } else { 0 };
        match g.node(id) {
            Node::Const(_) | Node::Var(_) | Node::Sin(_) | Node::Cos(_) | Node::Input(_) => 0,
            // As `define` writes it: one negated operand folded into a difference, otherwise a sum
            // of the operands as they are (a negation written out counting one).
            Node::Add(a, b) => match (g.unneg(a), g.unneg(b)) {
                ((false, _), (true, b)) => 1 + operand(a) + operand(b),
                ((true, a), (false, _)) => 1 + operand(a) + operand(b),
                _ => 1 + operand(a) + operand(b),
            },
            Node::Neg(a) | Node::Sqrt(a) => 1 + operand(a),
            Node::Mul(a, b) | Node::Div(a, b) | Node::Atan2(a, b) => 1 + operand(a) + operand(b),
            Node::IfPositive(c, a, b) => 1 + operand(c) + operand(a) + operand(b),
        }
    }

    fn inline(&self, id: ExprId) -> bool {
        !self.schedule.bound.contains_key(&id)
    }

    /// An operand of `*`, `/` or unary `-`: inline sums, negations and quotients get parentheses
    /// (`a * (b / c)` is not `a * b / c`, which Rust reads as `(a * b) / c`).
    fn operand(&self, id: ExprId, out: &mut TokenStream) {
        let wrap = self.inline(id) && matches!(self.g.node(id), Node::Add(..) | Node::Neg(..) | Node::Div(..));
        self.wrapped(id, wrap, out);
    }

    /// The right operand of `-`: inline sums get parentheses.
    fn operand_of_sub(&self, id: ExprId, out: &mut TokenStream) {
        let wrap = self.inline(id) && matches!(self.g.node(id), Node::Add(..));
        self.wrapped(id, wrap, out);
    }

    fn wrapped(&self, id: ExprId, wrap: bool, out: &mut TokenStream) {
        if wrap {
            let mut inner = TokenStream::new();
            self.expr(id, &mut inner);
            group(out, Delimiter::Parenthesis, inner);
        } else {
            self.expr(id, out);
        }
    }

    /// `[a, b, c]`.
    fn list(&self, ids: &[ExprId], out: &mut TokenStream) {
        let mut inner = TokenStream::new();
        for (k, &id) in ids.iter().enumerate() {
            if k > 0 {
                punct(&mut inner, ',');
            }
            self.expr(id, &mut inner);
        }
        group(out, Delimiter::Bracket, inner);
    }

    /// A frame's value: `[x, y, z]` for a position, else `krate::Pose { rotation, translation }`.
    fn pose(&self, outputs: &[ExprId], out: &mut TokenStream) {
        if outputs.len() == 3 {
            return self.list(outputs, out);
        }
        let mut rows = TokenStream::new();
        for row in 0..3 {
            if row > 0 {
                punct(&mut rows, ',');
            }
            self.list(&outputs[3 * row..3 * row + 3], &mut rows);
        }
        let mut translation = TokenStream::new();
        self.list(&outputs[9..12], &mut translation);
        let private = self.private;
        out.extend(quote!(#private::Pose { rotation: [#rows], translation: #translation }));
    }

    /// A Jacobian's entries (`rows` rows of [`Writer::dof`] entries, row-major) as
    /// `[[..; dof]; rows]`, or a twist's (`[..; rows]`).
    fn velocity(&self, entries: &[ExprId], rows: usize, form: VelocityForm, out: &mut TokenStream) {
        match form {
            VelocityForm::Twist => self.list(entries, out),
            VelocityForm::Jacobian => {
                let mut inner = TokenStream::new();
                let width = self.sizes.1;
                for r in 0..rows {
                    if r > 0 {
                        punct(&mut inner, ',');
                    }
                    self.list(&entries[r * width..(r + 1) * width], &mut inner);
                }
                group(out, Delimiter::Bracket, inner);
            }
        }
    }

    /// An angle as the argument of a call or an entry of an array (no parentheses needed).
    fn angle(&self, angle: ExprId) -> TokenStream {
        let mut value = TokenStream::new();
        self.expr(angle, &mut value);
        value
    }

    /// The names a call's results are bound to: `s1`, or `_` for a sine no output uses.
    fn sin_cos_names(&self, angle: ExprId) -> (TokenStream, TokenStream) {
        let name = |used: bool, name: String| if used { ident(&name).into_token_stream() } else { quote!(_) };
        let names = &self.schedule.names;
        (
            name(self.schedule.sines.contains(&angle), names.sin(angle)),
            name(self.schedule.cosines.contains(&angle), names.cos(angle)),
        )
    }

    /// The sines and cosines of `angles` (consecutive in the schedule): with our trig one call for
    /// all of them, `let ([s1, s2], [c1, c2]) = T::sin_cos_many([q1, q2]);`, so they are computed
    /// side by side; with std trig one `sin_cos_std` call each.
    fn sin_cos(&self, angles: &[ExprId], trig: Trig, out: &mut TokenStream) {
        let private = self.private;
        let (sines, cosines): (Vec<TokenStream>, Vec<TokenStream>) =
            angles.iter().map(|&a| self.sin_cos_names(a)).unzip();
        let values: Vec<TokenStream> = angles.iter().map(|&a| self.angle(a)).collect();
        match (trig, angles) {
            (Trig::Std, _) => {
                for ((s, c), value) in sines.iter().zip(&cosines).zip(&values) {
                    out.extend(quote!(let (#s, #c) = #private::StdTrig::sin_cos_std(#value);));
                }
            }
            (Trig::Fast, [_]) => {
                let (s, c, value) = (&sines[0], &cosines[0], &values[0]);
                out.extend(quote!(let (#s, #c) = #private::Real::sin_cos(#value);));
            }
            (Trig::Fast, _) => {
                out.extend(quote!(let ([#(#sines),*], [#(#cosines),*]) = T::sin_cos_many([#(#values),*]);));
            }
        }
    }

    /// The body's statements; with `marks`, a block mark after the first statement that brings
    /// the operations since the last one to [`BLOCK_MARK_OPS`].
    fn items(&self, trig: Trig, marks: Option<&mut Marks>, out: &mut TokenStream) {
        let mut marks = marks;
        let items = &self.schedule.items;
        let mut k = 0;
        while k < items.len() {
            match &items[k] {
                Item::SinCos(_) => {
                    let mut angles = Vec::new();
                    while let Some(Item::SinCos(angle)) = items.get(k) {
                        angles.push(*angle);
                        k += 1;
                    }
                    self.sin_cos(&angles, trig, out);
                }
                Item::Let(id, name) => {
                    let name = ident(name);
                    let mut value = TokenStream::new();
                    self.define(*id, &mut value);
                    out.extend(quote!(let #name = #value;));
                    if let Some(marks) = marks.as_deref_mut() {
                        marks.after(self.ops_written(*id), out);
                    }
                    k += 1;
                }
            }
        }
    }
}

/// One function computing every frame of `compiled`, generic over `T: Real`.
///
/// One tip returns a `Pose<T>` (or `[T; 3]` for positions only); with a velocity, its Jacobian
/// `[[T; DOF]; 6]` (`[[T; DOF]; 3]` for positions) or its twist `[T; 6]` (`[T; 3]`), and with
/// both the pair `(pose, jacobian)`. Several tips, or every link, return an array of them in
/// request order (see [`Compiled::returns_array`]). A twist takes the joint rates `qd` beside `q`.
/// The scalar type parameter is the function's own `T`, so the function may stand anywhere but
/// inside a generic item whose own parameter is called `T` ([`crate::robot::emit_robot`] puts it
/// in a block of its own).
pub fn emit_function(compiled: &Compiled, options: &EmitOptions) -> TokenStream {
    let g = compiled.graph();
    let outputs = compiled.outputs();
    let schedule = Schedule::new(g, &outputs);
    let private = &options.private;
    let (n, nv) = (compiled.dof(), compiled.velocity_dof());
    let w = Writer { g, schedule: &schedule, private, sizes: (n, nv), inputs: &[] };
    let n_lit = Literal::usize_unsuffixed(n);
    let nv_lit = Literal::usize_unsuffixed(nv);
    let twist = compiled.velocity.is_some_and(|v| v.form == VelocityForm::Twist);
    let mut marks = Marks::default();
    let mut body = prologue(&compiled.quaternions, &w, twist, options.trig, Some(&mut marks));
    let layout = Layout::of(compiled);
    let array = compiled.returns_array();
    let per_frame = layout.per_frame();
    // Most of a body's operations may sit in its returned value (a pose's rows, a Jacobian's
    // columns written out), so the marks run on through it: its entries up to the last one a
    // mark follows are bound in turn (`frame0_0`, ... for frame 0's entries, those that compute
    // something), and the value names them. Entries, not whole frames: a bound `Pose` of lanes is
    // moved into the returned array, which LLVM left as copies (all link poses of the PUMA 560 in
    // `F64x8` lanes 1.16 times as long).
    // An entry another one repeats (a negation written out in both) is counted once.
    let mut seen = std::collections::BTreeSet::new();
    let ops: Vec<usize> =
        outputs.iter().map(|&id| if w.inline(id) && seen.insert(id) { w.ops_written(id) } else { 0 }).collect();
    let bound = marks.last_followed(&ops[..ops.len().saturating_sub(1)]).map_or(0, |k| k + 1);
    let mut named = schedule.clone();
    for (k, &id) in outputs.iter().enumerate().take(bound) {
        if ops[k] > 0 && !named.bound.contains_key(&id) {
            let name = format!("frame{}_{}", k / per_frame, k % per_frame);
            let (name_ident, mut entry) = (ident(&name), TokenStream::new());
            w.define(id, &mut entry);
            body.extend(quote!(let #name_ident = #entry;));
            named.bound.insert(id, name);
        }
        marks.after(ops[k], &mut body);
    }
    let w = Writer { schedule: &named, ..w };
    let mut value = TokenStream::new();
    for k in 0..compiled.frames().len() {
        if k > 0 {
            punct(&mut value, ',');
        }
        layout.value(&w, &outputs[k * per_frame..(k + 1) * per_frame], &mut value);
    }
    if array {
        let mut list = TokenStream::new();
        group(&mut list, Delimiter::Bracket, value);
        value = list;
    }
    body.extend(value);
    let one = layout.ty(private, &nv_lit);
    let ret = if array {
        let m = Literal::usize_unsuffixed(compiled.frames().len());
        quote!([#one; #m])
    } else {
        one
    };
    let name = Ident::new(&options.name, Span::call_site());
    let docs = doc_lines(compiled);
    let vis = if options.public { quote!(pub) } else { quote!() };
    let bound = options.trig.bound(private);
    let params = if twist { quote!(q: &[T; #n_lit], qd: &[T; #nv_lit]) } else { quote!(q: &[T; #n_lit]) };
    // Always inlined (in an optimised build) into its (small, `#[inline]`) typed callers: a
    // function returning an array of poses writes them to a temporary and the caller copies them
    // where they belong (a 576-byte `memcpy` for a 6-link arm, measured at about a tenth of the
    // PUMA 560's all-link time); inlined, the poses are stored where the caller keeps them.
    let attrs = quote! {
        #(#[doc = #docs])*
        #[allow(clippy::approx_constant)] // a robot's own decimals may resemble pi; they are kept as given
    };
    function(attrs, quote!(#vis fn #name<T: #bound>(#params) -> #ret), body, private)
}

/// The statements every body opens with: `q` (and with `rates` `qd`) unpacked into the variables
/// the schedule uses, each floating or spherical joint's rotation from its quaternion, then the sines and
/// cosines and every `let` of the schedule.
fn prologue(quaternions: &[usize], w: &Writer<'_>, rates: bool, trig: Trig, marks: Option<&mut Marks>) -> TokenStream {
    let (schedule, private) = (w.schedule, w.private);
    let (n, nv) = w.sizes;
    let mut body = TokenStream::new();
    let mut inputs = vec![(quote!(q), 0, n)];
    if rates {
        inputs.push((quote!(qd), n, nv));
    }
    for &(ref input, first, len) in &inputs {
        if len == 0 {
            body.extend(quote!(let _ = #input;));
        } else {
            let vars = (first..first + len).map(|i| {
                if schedule.used_vars.contains(&i) { var_ident(i, (n, nv)).into_token_stream() } else { quote!(_) }
            });
            body.extend(quote!(let [#(#vars),*] = *#input;));
        }
    }
    // Each floating or spherical joint's rotation, from its quaternion in `q`, before anything
    // uses it.
    for (k, &start) in quaternions.iter().enumerate() {
        let first = n + nv + 9 * k;
        if !(first..first + 9).any(|i| schedule.used_vars.contains(&i)) {
            continue;
        }
        let rows = (0..3).map(|r| {
            let entries = (0..3).map(|c| {
                let i = first + 3 * r + c;
                if schedule.used_vars.contains(&i) { var_ident(i, (n, nv)).into_token_stream() } else { quote!(_) }
            });
            quote!([#(#entries),*])
        });
        let [x, y, z, qw] = [start, start + 1, start + 2, start + 3].map(Literal::usize_unsuffixed);
        body.extend(quote!(let [#(#rows),*] = #private::quaternion_matrix(q[#x], q[#y], q[#z], q[#qw]);));
    }
    w.items(trig, marks, &mut body);
    body
}

/// One function, generic over `T: Real`, computing `points` (each three expressions of
/// `compiled`'s graph, typically points fixed in its frames' links) from `q`, returning
/// `[[T; 3]; points.len()]`: only what the points need of the frames is computed.
pub fn emit_points(compiled: &Compiled, points: &[[ExprId; 3]], options: &EmitOptions, doc: &str) -> TokenStream {
    let g = compiled.graph();
    let outputs: Vec<ExprId> = points.iter().flatten().copied().collect();
    let schedule = Schedule::new(g, &outputs);
    let private = &options.private;
    let n = compiled.dof();
    let w = Writer { g, schedule: &schedule, private, sizes: (n, compiled.velocity_dof()), inputs: &[] };
    let mut marks = Marks::default();
    let mut body = prologue(&compiled.quaternions, &w, false, options.trig, Some(&mut marks));
    // Each point bound in turn (`center_0`, ...), so that the marks run on through them.
    let mut names = Vec::with_capacity(points.len());
    for (k, point) in points.iter().enumerate() {
        let mut entries = TokenStream::new();
        for (i, &id) in point.iter().enumerate() {
            if i > 0 {
                punct(&mut entries, ',');
            }
            w.expr(id, &mut entries);
        }
        let name = format_ident!("center_{k}");
        body.extend(quote!(let #name = [#entries];));
        marks.after(point.iter().map(|&id| if w.inline(id) { w.ops_written(id) } else { 0 }).sum(), &mut body);
        names.push(name);
    }
    body.extend(quote!([#(#names),*]));
    let (n_lit, m) = (Literal::usize_unsuffixed(n), Literal::usize_unsuffixed(points.len()));
    let name = Ident::new(&options.name, Span::call_site());
    let vis = if options.public { quote!(pub) } else { quote!() };
    let bound = options.trig.bound(private);
    let cost = format!(" Cost: {}.", OpCount::of(g, outputs.iter().copied()));
    let attrs = quote! {
        #[doc = #doc]
        #[doc = ""]
        #[doc = #cost]
        #[allow(clippy::approx_constant)] // a robot's own decimals may resemble pi; they are kept as given
    };
    function(attrs, quote!(#vis fn #name<T: #bound>(q: &[T; #n_lit]) -> [[T; 3]; #m]), body, private)
}

/// One function computing a compiled function of the dynamics, generic over `T: Real`: `q` (and,
/// for a function of the rates, `qd`; for inverse or forward dynamics the accelerations `qdd` or
/// the forces `tau`) in, one value per velocity out (`[T; NV]`), the mass matrix `[[T; NV]; NV]`,
/// or for forward dynamics the accelerations and the factorisation's pivots `([T; NV], [T; NV])`
/// (the caller refuses a pivot that is not positive).
pub fn emit_dynamics(compiled: &CompiledDynamics, options: &EmitOptions, doc: &str) -> TokenStream {
    let g = compiled.graph();
    let outputs = compiled.outputs();
    let schedule = Schedule::new(g, outputs);
    let private = &options.private;
    let (n, nv) = (compiled.dof(), compiled.velocity_dof());
    let kind = compiled.function;
    let input = kind.input();
    let mut input_names: Vec<Ident> = match input {
        Some(name) => (1..=nv).map(|i| format_ident!("{name}{i}")).collect(),
        None => Vec::new(),
    };
    // The external forces' inputs follow: per link its force then its moment.
    let forces = kind.takes_forces().then_some(compiled.forces.len());
    let first_force = input_names.len();
    for link in 1..=forces.unwrap_or(0) {
        input_names.extend(["fx", "fy", "fz", "nx", "ny", "nz"].map(|c| format_ident!("{c}{link}")));
    }
    let w = Writer { g, schedule: &schedule, private, sizes: (n, nv), inputs: &input_names };
    let mut marks = Marks::default();
    let rates = kind.takes_rates();
    let mut body = TokenStream::new();
    if let Some(name) = input {
        let argument = format_ident!("{name}");
        if nv == 0 {
            body.extend(quote!(let _ = #argument;));
        } else {
            let names = input_names[..first_force]
                .iter()
                .enumerate()
                .map(|(i, name)| if schedule.used_inputs.contains(&i) { name.into_token_stream() } else { quote!(_) });
            body.extend(quote!(let [#(#names),*] = *#argument;));
        }
    }
    if let Some(k) = forces {
        if k == 0 {
            body.extend(quote!(let _ = forces;));
        } else {
            let names: Vec<TokenStream> = (first_force..input_names.len())
                .map(|i| if schedule.used_inputs.contains(&i) { input_names[i].to_token_stream() } else { quote!(_) })
                .collect();
            let links = names.chunks(6).map(|link| quote!([#(#link),*]));
            body.extend(quote!(let [#(#links),*] = *forces;));
        }
    }
    body.extend(prologue(&compiled.quaternions, &w, rates, options.trig, Some(&mut marks)));
    // Each value written out is bound in turn (`value_0`, ...), so that the marks run on through
    // them (a debug build's chunks then hold the whole body).
    let values: Vec<TokenStream> = outputs
        .iter()
        .enumerate()
        .map(|(k, &id)| {
            let mut value = TokenStream::new();
            w.expr(id, &mut value);
            let ops = if w.inline(id) { w.ops_written(id) } else { 0 };
            if ops == 0 {
                return value;
            }
            let name = format_ident!("value_{k}");
            body.extend(quote!(let #name = #value;));
            marks.after(ops, &mut body);
            name.into_token_stream()
        })
        .collect();
    let nv_lit = Literal::usize_unsuffixed(nv);
    let (value, ret) = match kind {
        DynamicsFunction::MassMatrix => {
            let rows = values.chunks(nv.max(1)).take(nv).map(|row| quote!([#(#row),*]));
            (quote!([#(#rows),*]), quote!([[T; #nv_lit]; #nv_lit]))
        }
        _ if kind.is_forward() => {
            let (accelerations, pivots) = values.split_at(nv);
            (quote!(([#(#accelerations),*], [#(#pivots),*])), quote!(([T; #nv_lit], [T; #nv_lit])))
        }
        _ => (quote!([#(#values),*]), quote!([T; #nv_lit])),
    };
    body.extend(value);
    let n_lit = Literal::usize_unsuffixed(n);
    let mut params = quote!(q: &[T; #n_lit]);
    if rates {
        params.extend(quote!(, qd: &[T; #nv_lit]));
    }
    if let Some(name) = input {
        let argument = format_ident!("{name}");
        params.extend(quote!(, #argument: &[T; #nv_lit]));
    }
    if let Some(k) = forces {
        let k = Literal::usize_unsuffixed(k);
        params.extend(quote!(, forces: &[[T; 6]; #k]));
    }
    let name = Ident::new(&options.name, Span::call_site());
    let vis = if options.public { quote!(pub) } else { quote!() };
    let bound = options.trig.bound(private);
    let cost = format!(" Cost: {}.", compiled.op_count());
    let attrs = quote! {
        #[doc = #doc]
        #[doc = ""]
        #[doc = #cost]
        #[allow(clippy::approx_constant)] // a robot's own decimals may resemble pi; they are kept as given
    };
    function(attrs, quote!(#vis fn #name<T: #bound>(#params) -> #ret), body, private)
}

/// Straight-line code for a graph of inputs (no joint variables): [`straight_line`]'s result.
#[derive(Debug, Clone)]
pub struct StraightLine {
    /// The `let` statements, in order.
    pub statements: TokenStream,
    /// Each output's expression (a name, or written out), in the order asked.
    pub outputs: Vec<TokenStream>,
    /// The joint variables the code reads.
    pub used_vars: std::collections::BTreeSet<usize>,
    /// The inputs the code reads.
    pub used_inputs: std::collections::BTreeSet<usize>,
}

/// The statements computing `outputs` of `g`, scheduled as every generated function is (shared
/// nodes bound once, nothing nested deeper than [`INLINE_DEPTH_LIMIT`](super::INLINE_DEPTH_LIMIT)),
/// with input `i` read from the variable `inputs[i]` and the joint variables (if any) from `q1 ..
/// q{dof}`, for the caller to wrap in a function whose scalar type is `T`. Square roots, `atan2`
/// and selects are `T::sqrt`, `T::atan2` and `T::if_positive` (`IkReal`'s), so a graph with them
/// needs `T` bound by it.
pub fn straight_line(
    g: &ExprGraph,
    outputs: &[ExprId],
    dof: usize,
    inputs: &[Ident],
    private: &TokenStream,
) -> StraightLine {
    let schedule = Schedule::new(g, outputs);
    let w = Writer { g, schedule: &schedule, private, sizes: (dof, 0), inputs };
    let mut statements = TokenStream::new();
    w.items(Trig::Fast, None, &mut statements);
    let outputs = outputs
        .iter()
        .map(|&id| {
            let mut value = TokenStream::new();
            w.expr(id, &mut value);
            value
        })
        .collect();
    StraightLine {
        statements,
        outputs,
        used_vars: schedule.used_vars.clone(),
        used_inputs: schedule.used_inputs.clone(),
    }
}

/// What one frame's value is made of: its pose (or position), its velocity, or both.
struct Layout {
    /// Entries of the pose part: 12, 3, or 0 when the pose is not an output.
    pose: usize,
    /// The velocity's form and rows (6, or 3 for positions only), if any.
    velocity: Option<(VelocityForm, usize)>,
    /// Columns of a Jacobian.
    velocities: usize,
}

impl Layout {
    fn of(compiled: &Compiled) -> Self {
        let rows = if compiled.position_only { 3 } else { 6 };
        let pose = match (compiled.has_pose(), compiled.position_only) {
            (false, _) => 0,
            (true, true) => 3,
            (true, false) => 12,
        };
        Layout { pose, velocity: compiled.velocity.map(|v| (v.form, rows)), velocities: compiled.velocity_dof() }
    }

    fn velocity_len(&self) -> usize {
        match self.velocity {
            None => 0,
            Some((VelocityForm::Jacobian, rows)) => rows * self.velocities,
            Some((VelocityForm::Twist, rows)) => rows,
        }
    }

    fn per_frame(&self) -> usize {
        self.pose + self.velocity_len()
    }

    /// The frame's value from its outputs.
    fn value(&self, w: &Writer<'_>, frame: &[ExprId], out: &mut TokenStream) {
        let mut pose = TokenStream::new();
        if self.pose > 0 {
            w.pose(&frame[..self.pose], &mut pose);
        }
        let Some((form, rows)) = self.velocity else {
            out.extend(pose);
            return;
        };
        let mut velocity = TokenStream::new();
        w.velocity(&frame[self.pose..], rows, form, &mut velocity);
        if self.pose > 0 {
            out.extend(quote!((#pose, #velocity)));
        } else {
            out.extend(velocity);
        }
    }

    /// The type of one frame's value.
    fn ty(&self, private: &TokenStream, n: &Literal) -> TokenStream {
        let pose = match self.pose {
            3 => quote!([T; 3]),
            _ => quote!(#private::Pose<T>),
        };
        let velocity = self.velocity.map(|(form, rows)| {
            let rows = Literal::usize_unsuffixed(rows);
            match form {
                VelocityForm::Jacobian => quote!([[T; #n]; #rows]),
                VelocityForm::Twist => quote!([T; #rows]),
            }
        });
        match (self.pose, velocity) {
            (_, None) => pose,
            (0, Some(velocity)) => velocity,
            (_, Some(velocity)) => quote!((#pose, #velocity)),
        }
    }
}

fn doc_lines(compiled: &Compiled) -> Vec<String> {
    let what = if compiled.position_only { "Position" } else { "Pose" };
    let what = match compiled.velocity {
        None => what.to_owned(),
        Some(v) => {
            let rows = if compiled.position_only { "linear rows of the " } else { "" };
            let form = match v.form {
                VelocityForm::Jacobian => {
                    format!("{rows}geometric Jacobian ({}, rows linear then angular)", v.frame.name())
                }
                VelocityForm::Twist => format!("{rows}twist `J * qd` ({}, linear then angular)", v.frame.name()),
            };
            if v.with_pose { format!("{what} and {form}") } else { capitalise(&form) }
        }
    };
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

fn capitalise(text: &str) -> String {
    let mut chars = text.chars();
    chars.next().map(|c| c.to_uppercase().chain(chars).collect()).unwrap_or_default()
}

/// A formatted Rust source file holding one function (`prettyplease`).
pub fn emit_module_source(compiled: &Compiled, options: &EmitOptions) -> Result<String, syn::Error> {
    let tokens = emit_function(compiled, options);
    let file: syn::File = syn::parse2(tokens)?;
    Ok(prettyplease::unparse(&file))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The expression of one output of `g`, its inputs named `x0, x1, ...`.
    fn written(g: &ExprGraph, output: ExprId, inputs: usize) -> String {
        let names: Vec<Ident> = (0..inputs).map(|i| format_ident!("x{i}")).collect();
        let line = straight_line(g, &[output], 0, &names, &quote!(p));
        line.outputs[0].to_string()
    }

    /// A sum or product nested on the right is written with its parentheses: Rust reads `a + b + c`
    /// as `(a + b) + c`, which rounds differently from `a + (b + c)`, and the code must compute
    /// what the graph says (the evaluator's value, bit for bit).
    #[test]
    fn right_nested_sums_and_products_keep_their_parentheses() {
        let mut g = ExprGraph::default();
        let [x0, x1, x2] = [0, 1, 2].map(|i| g.input(i));
        // Operands are ordered by id: the inner node, made last, lands on the right.
        let inner = g.add(x1, x2);
        let sum = g.add(x0, inner);
        assert_eq!(written(&g, sum, 3), "x0 + (x1 + x2)");
        let inner = g.mul(x1, x2);
        let product = g.mul(x0, inner);
        assert_eq!(written(&g, product, 3), "x0 * (x1 * x2)");
        // Nested on the left, none are needed.
        let left = g.add(x0, x1);
        let later = g.input(3);
        let sum = g.add(left, later);
        assert_eq!(written(&g, sum, 4), "x0 + x1 + x3");
        // Why it matters: with a = 1, b = 1e16, c = -1e16 the graph's a + (b + c) is 1, and
        // (a + b) + c is 0 (1e16 + 1 rounds to 1e16).
        let values = [1.0, 1e16, -1e16];
        let mut cache = Vec::new();
        let mut h = ExprGraph::default();
        let [a, b, c] = [0, 1, 2].map(|i| h.input(i));
        let bc = h.add(b, c);
        let abc = h.add(a, bc);
        assert_eq!(written(&h, abc, 3), "x0 + (x1 + x2)");
        assert_eq!(h.eval_with_inputs(abc, &[], &values, &mut cache), 1.0);
        assert_eq!(std::hint::black_box(1.0f64) + 1e16 + -1e16, 0.0);
    }
}
