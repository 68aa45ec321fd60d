//! The forward kinematics a compiled closed form measures its solutions with: the tip's pose as
//! the robot's generated code computes it (the same compiled graph, every product and sum), but
//! each joint's cosine and sine taken from the solver, which computed them on the way to the
//! angle (`q` is their `atan2`, within 2 ulp), instead of computed again. A sine or cosine of
//! a sum such as `q2 + q3` comes from the joints' by the angle-sum formulas.
//!
//! Recomputing them is most of a measure's cost: the UR5's six `sin_cos` in the lanes of eight
//! solutions take several times the products that follow. A chain whose angles are not sums and
//! differences of joint values (a mimic joint's multiple of one) has no such form, and is
//! measured at `q` with the pose's own function.
//!
//! `Measure` is this pose, with every joint's cosine and sine an input and angle sums by formula,
//! so the solutions are measured without `sin_cos`.

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

use crate::emit::straight_line;
use crate::request::Compiled;
use crate::simplify::{linear_form, sum_formula};
use crate::stats::{OpCount, reachable};
use crate::symbolic::graph::{ExprGraph, ExprId, Node};

/// The name of the generic function [`emit_measure`] writes for a pose.
pub const MEASURE_BODY: &str = "generic_tip_pose_from_cos_sin";

/// The name of the generic function [`emit_measure`] writes for a pose and its Jacobian.
pub const MEASURE_JACOBIAN_BODY: &str = "generic_tip_pose_and_jacobian_from_cos_sin";

/// The tip's pose (and, measured from a pose and Jacobian, its Jacobian) with every joint's
/// cosine and sine an input: cosine of joint `i` input `i`, its sine input `dof + i`; joint
/// values (a prismatic joint's) stay variables.
#[derive(Debug, Clone)]
pub struct Measure {
    graph: ExprGraph,
    outputs: Vec<ExprId>,
    dof: usize,
}

impl Measure {
    /// The measure of `compiled` (one tip's pose, or its pose and Jacobian), or `None` when an angle is no sum or difference
    /// of joint values plus a constant.
    pub fn of(compiled: &Compiled) -> Option<Measure> {
        let dof = compiled.dof();
        let mut g = compiled.graph().clone();
        let outputs = compiled.outputs();
        let nodes = reachable(&g, outputs.iter().copied());
        let mut new: Vec<Option<ExprId>> = vec![None; g.len()];
        let mut angles: std::collections::BTreeMap<ExprId, (ExprId, ExprId)> = std::collections::BTreeMap::new();
        for &id in &nodes {
            let rewritten = match g.node(id) {
                node @ (Node::Sin(angle) | Node::Cos(angle)) => {
                    let (sin, cos) = match angles.get(&angle) {
                        Some(&pair) => pair,
                        None => {
                            let pair = sin_cos_of(&mut g, angle, dof)?;
                            angles.insert(angle, pair);
                            pair
                        }
                    };
                    if matches!(node, Node::Sin(_)) { sin } else { cos }
                }
                node => g.rebuild(node, |a| new[a.index()].unwrap_or(a)),
            };
            new[id.index()] = Some(rewritten);
        }
        let outputs = outputs.iter().map(|o| new[o.index()].unwrap_or(*o)).collect();
        Some(Measure { graph: g, outputs, dof })
    }

    /// What it costs.
    pub fn op_count(&self) -> OpCount {
        OpCount::of(&self.graph, self.outputs.iter().copied())
    }
}

/// `(sin, cos)` of `angle` from the joints' inputs, or `None` if it is not `sum of +-q_i + k`.
/// The terms are added in joint order and the constant last, so `q2 + q3` is a step on the way
/// to `q2 + q3 + q4` and the graph shares it.
fn sin_cos_of(g: &mut ExprGraph, angle: ExprId, dof: usize) -> Option<(ExprId, ExprId)> {
    let (terms, constant) = linear_form(g, angle)?;
    if terms.iter().any(|&(i, k)| i >= dof || k.abs() != 1.0) {
        return None;
    }
    let mut sum: Option<(ExprId, ExprId)> = None;
    for (i, k) in terms {
        let (cos, sin) = (g.input(i), g.input(dof + i));
        let term = if k < 0.0 { (g.neg(sin), cos) } else { (sin, cos) };
        sum = Some(match sum {
            None => term,
            Some(so_far) => sum_formula(g, so_far, term),
        });
    }
    let constant_sc = {
        let k = g.constant(constant);
        (g.sin(k), g.cos(k))
    };
    Some(match sum {
        None => constant_sc,
        Some(so_far) if constant == 0.0 => so_far,
        Some(so_far) => sum_formula(g, so_far, constant_sc),
    })
}

/// The generic function computing the tip's pose (or its pose and Jacobian, `(Pose<T>, [[T; N]; 6])`,
/// where `measure` has one: [`MEASURE_JACOBIAN_BODY`], else [`MEASURE_BODY`]) from `q` (for
/// prismatic joints) and every joint's cosine and sine.
pub fn emit_measure(measure: &Measure, private: &TokenStream, tip: &str, base: &str) -> TokenStream {
    let p = private;
    let n = measure.dof;
    let mut names: Vec<Ident> = (1..=n).map(|i| format_ident!("c{}", i)).collect();
    names.extend((1..=n).map(|i| format_ident!("s{}", i)));
    let line = straight_line(&measure.graph, &measure.outputs, n, &names, p);
    let bind = |used: bool, name: &Ident| if used { quote!(#name) } else { quote!(_) };
    let qs = (0..n).map(|i| bind(line.used_vars.contains(&i), &format_ident!("q{}", i + 1)));
    let cosines = (0..n).map(|i| bind(line.used_inputs.contains(&i), &names[i]));
    let sines = (0..n).map(|i| bind(line.used_inputs.contains(&(n + i)), &names[n + i]));
    let statements = &line.statements;
    let o = &line.outputs;
    let (r0, r1, r2, t) = (&o[0..3], &o[3..6], &o[6..9], &o[9..12]);
    let pose = quote!(#p::Pose { rotation: [[#(#r0),*], [#(#r1),*], [#(#r2),*]], translation: [#(#t),*] });
    let n_lit = Literal::usize_unsuffixed(n);
    let (name, what, ty, value) = if o.len() == 12 {
        (MEASURE_BODY, "pose", quote!(#p::Pose<T>), pose)
    } else {
        assert_eq!(o.len(), 12 + 6 * n, "invariant: a measure is a pose, or a pose and its 6 x N Jacobian");
        let rows = o[12..].chunks(n).map(|row| quote!([#(#row),*]));
        (
            MEASURE_JACOBIAN_BODY,
            "pose and `LOCAL_WORLD_ALIGNED` Jacobian",
            quote!((#p::Pose<T>, [[T; #n_lit]; 6])),
            quote!((#pose, [#(#rows),*])),
        )
    };
    let name = Ident::new(name, Span::call_site());
    let doc = format!(
        " The {what} of `{tip}` in `{base}` from the joint values (a prismatic joint's) and every joint's \
         cosine and sine: the tip's {what} function with its sines and cosines given. Cost: {}.",
        measure.op_count()
    );
    quote! {
        #[doc = #doc]
        #[allow(clippy::inline_always)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        #[allow(clippy::approx_constant)] // a robot's own decimals may resemble pi; they are kept as given
        pub fn #name<T: #p::Real>(q: &[T; #n_lit], cos: &[T; #n_lit], sin: &[T; #n_lit]) -> #ty {
            let [#(#qs),*] = *q;
            let [#(#cosines),*] = *cos;
            let [#(#sines),*] = *sin;
            #statements
            #value
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::request::{Request, compile};

    fn robot(file: &str) -> kinematics_model::KinematicTree {
        let path = format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        kinematics_model::parse_source(file, &text).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The measure at the joints' own cosines and sines is the pose, to rounding, with no `sin_cos`.
    #[test]
    fn the_measure_is_the_pose() {
        for (file, tip) in [("ur5.urdf", "tool0"), ("irb120.urdf", "tool0"), ("stanford_arm.toml", "link6")] {
            let tree = robot(file);
            let compiled = compile(&tree, &Request::tip(tip)).expect("compiles");
            let measure = Measure::of(&compiled).expect("sums of joint values");
            assert_eq!(measure.op_count().sin_cos, 0, "{file}");
            let q: [f64; 6] = [0.3, -1.2, 0.7, 0.4, -0.7, 2.0];
            let mut inputs: Vec<f64> = q.iter().map(|x| x.cos()).collect();
            inputs.extend(q.iter().map(|x| x.sin()));
            let expected = compiled.eval(&q)[0];
            let mut values = Vec::new();
            for (k, &id) in measure.outputs.iter().enumerate() {
                let got = measure.graph.eval_with_inputs(id, &q, &inputs, &mut values);
                assert!((got - expected[k]).abs() < 1e-14, "{file} entry {k}: {got} against {}", expected[k]);
            }
        }
    }

    /// A mimic joint's angle (half another's: no formula gives its sine from the joint's) has no such form.
    #[test]
    fn a_multiple_of_a_joint_value_has_no_measure() {
        let urdf = r#"<robot name="m">
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <origin xyz="1 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/>
    <origin xyz="1 0 0"/><mimic joint="j1" multiplier="0.5"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>"#;
        let tree = kinematics_model::parse_source("m.urdf", urdf).expect("valid");
        let compiled = compile(&tree, &Request::tip("c")).expect("compiles");
        assert!(Measure::of(&compiled).is_none());
    }
}
