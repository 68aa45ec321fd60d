//! What the compiler emits for small robots, pinned as snapshots so a reviewer sees every change.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use kinematics_compiler::emit::{EmitOptions, emit_module_source};
use kinematics_compiler::{Request, compile};
use kinematics_model::JacobianFrame;

fn source(file: &str, request: &Request, name: &str) -> String {
    let compiled = compile(&common::robot(file), request).unwrap();
    emit_module_source(&compiled, &EmitOptions::named(name)).unwrap()
}

#[test]
fn planar_3r_tip() {
    insta::assert_snapshot!(source("planar_3r.toml", &Request::tip("link3"), "link3_pose"));
}

#[test]
fn planar_3r_tip_position() {
    insta::assert_snapshot!(source("planar_3r.toml", &Request::tip("link3").positions_only(), "link3_position"));
}

#[test]
fn ur5_dh_flange() {
    insta::assert_snapshot!(source("ur5.toml", &Request::tip("wrist_3_link"), "flange_pose"));
}

#[test]
fn ur5_urdf_tool0() {
    insta::assert_snapshot!(source("ur5.urdf", &Request::tip("tool0").with_base("base"), "tool0_pose"));
}

#[test]
fn seed_tree_all_links() {
    insta::assert_snapshot!(source("seed_tree.urdf", &Request::all_links(), "all_links"));
}

#[test]
fn planar_3r_pose_and_jacobian() {
    let request = Request::tip("link3").pose_and_jacobian(JacobianFrame::LocalWorldAligned);
    insta::assert_snapshot!(source("planar_3r.toml", &request, "link3_pose_and_jacobian"));
}

#[test]
fn planar_3r_jacobian_local() {
    insta::assert_snapshot!(source(
        "planar_3r.toml",
        &Request::tip("link3").jacobian(JacobianFrame::Local),
        "link3_jacobian_local"
    ));
}

#[test]
fn planar_3r_twist() {
    let request = Request::tip("link3").twist(JacobianFrame::LocalWorldAligned);
    insta::assert_snapshot!(source("planar_3r.toml", &request, "link3_twist"));
}

#[test]
fn ur5_urdf_tool0_jacobian() {
    let request = Request::tip("tool0").jacobian(JacobianFrame::LocalWorldAligned);
    insta::assert_snapshot!(source("ur5.urdf", &request, "tool0_jacobian"));
}

#[test]
fn output_is_byte_identical_across_runs() {
    for file in ["planar_3r.toml", "ur5.urdf", "seed_tree.urdf"] {
        let first = source(file, &Request::all_links(), "all_links");
        for _ in 0..3 {
            assert_eq!(source(file, &Request::all_links(), "all_links"), first, "{file}");
        }
    }
    let jacobian = |tip: &str| Request::tip(tip).pose_and_jacobian(JacobianFrame::Local);
    let first = source("ur5.urdf", &jacobian("tool0"), "tool0");
    for _ in 0..3 {
        assert_eq!(source("ur5.urdf", &jacobian("tool0"), "tool0"), first, "ur5 Jacobian");
    }
}

/// Every angle's sine and cosine come from one call (`T::sin_cos_many`, computed side by side in
/// SIMD lanes), before the arithmetic: the only bindings written before it are those an angle is
/// computed from. Checked on every robot's link poses.
#[test]
fn one_sin_cos_call_for_every_angle_comes_first() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots");
    let mut checked = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let file = entry.unwrap().file_name().into_string().unwrap();
        if kinematics_model::SourceFormat::from_file_name(&file).is_none() {
            continue;
        }
        let text = source(&file, &Request::all_links(), "all_links");
        // The body as written (a body with block marks is also written in chunks for debug
        // builds, after `#[cfg(debug_assertions)]`: the same statements).
        let text = text.split("#[cfg(debug_assertions)]").next().expect("a split has a first piece").to_owned();
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        // Every angle in one call: `let ([s1, ..], [c1, ..]) = T::sin_cos_many([q1, ..]);`
        // (one `Real::sin_cos` for a single angle), written over one or more lines.
        let is_call = |l: &str| l.contains("T::sin_cos_many(") || l.contains("Real::sin_cos(");
        assert_eq!(lines.iter().filter(|l| is_call(l)).count(), 1, "{file}: not one call for every angle\n{text}");
        let start = lines.iter().position(|l| is_call(l)).unwrap();
        let end = start + lines[start..].iter().position(|l| l.ends_with(");")).unwrap();
        let call = lines[start..=end].join(" ");
        for line in &lines[..start] {
            let Some(name) = line.strip_prefix("let ").and_then(|l| l.split(" =").next()) else { continue };
            if name.starts_with('t') {
                let feeds_angle = call.split(|ch: char| !ch.is_alphanumeric()).any(|w| w == name);
                assert!(feeds_angle, "{file}: `{line}` is computed before the sin_cos call and is no angle");
            }
        }
        checked += 1;
    }
    assert!(checked >= 12, "only {checked} robots found");
}

/// A closed form's body (one branch, for any `IkReal` scalar) and its measure, as the derive emits
/// them beside the robot's other functions.
fn ik_source(file: &str, tip: &str) -> String {
    let tree = common::robot(file);
    let base = tree.link(tree.root()).name.clone();
    let plan = kinematics_compiler::ik::classify(&tree, &base, tip).unwrap();
    let body = kinematics_compiler::ik::IkBody::of(&plan).expect("a composed family");
    let private = quote::quote!(::kinematics::__private);
    let mut tokens = kinematics_compiler::ik::emit::emit_branch_body(
        &body,
        &private,
        kinematics_compiler::ik::emit::BRANCH_BODY,
        " One branch.",
    );
    let pose = compile(&tree, &Request::tip(tip).with_base(&base)).unwrap();
    if let Some(measure) = kinematics_compiler::ik::Measure::of(&pose) {
        tokens.extend(kinematics_compiler::ik::measure::emit_measure(&measure, &private, tip, &base));
    }
    prettyplease::unparse(&syn::parse2(tokens).unwrap())
}

#[test]
fn ur5_urdf_ik_branch_and_measure() {
    insta::assert_snapshot!(ik_source("ur5.urdf", "tool0"));
}

#[test]
fn stanford_arm_ik_branch_and_measure() {
    insta::assert_snapshot!(ik_source("stanford_arm.toml", "link6"));
}

/// The operations `expr` writes: its sums, differences, products, quotients and negations, not
/// counting calls (`T::from_f64(-0.5)` is a constant; the sines and cosines are no arithmetic).
fn written_ops(expr: &syn::Expr) -> usize {
    use syn::Expr;
    match expr {
        Expr::Binary(b) => 1 + written_ops(&b.left) + written_ops(&b.right),
        Expr::Unary(u) if matches!(u.op, syn::UnOp::Neg(_)) => 1 + written_ops(&u.expr),
        Expr::Unary(u) if matches!(u.op, syn::UnOp::Deref(_)) => 0, // `*q`, unpacked
        Expr::Paren(p) => written_ops(&p.expr),
        Expr::Array(a) => a.elems.iter().map(written_ops).sum(),
        Expr::Tuple(t) => t.elems.iter().map(written_ops).sum(),
        Expr::Struct(s) => s.fields.iter().map(|f| written_ops(&f.expr)).sum(),
        Expr::Path(_) | Expr::Lit(_) | Expr::Call(_) | Expr::MethodCall(_) => 0,
        Expr::Field(_) => 0, // `chunk_0.4`, a value a chunk returned
        other => panic!("an expression the emitter does not write: {}", quote::quote!(#other)),
    }
}

/// The marks of one emitted function (`T::block_mark(n);`, their numbers in order), after
/// checking where each stands: a mark follows the first statement that brings the operations
/// since the previous mark to `BLOCK_MARK_OPS`, and what follows the last mark (statements and
/// the returned value) is shorter than the spacing.
fn checked_marks(source: &str, what: &str) -> Vec<usize> {
    let file: syn::File = syn::parse_str(source).unwrap();
    // A body with marks is two functions, as written and in chunks (for debug builds): the same
    // marks in the same places.
    let mut each = file.items.iter().map(|item| {
        let syn::Item::Fn(function) = item else { panic!("{what}: functions only") };
        let (mut marks, mut since, mut last) = (Vec::new(), 0, 0);
        walk_marks(&function.block.stmts, what, &mut marks, &mut since, &mut last);
        assert!(since < kinematics_core::BLOCK_MARK_OPS, "{what}: {since} operations after the last mark");
        assert_eq!(marks, (1..=marks.len()).collect::<Vec<_>>(), "{what}: numbered in order");
        marks
    });
    let marks = each.next().unwrap_or_else(|| panic!("{what}: no function"));
    assert!(each.all(|other| other == marks), "{what}: both forms carry the same marks");
    marks
}

/// The statements of a body, in order, the statements of each chunk's closure (`chunk(|| { .. })`,
/// as a `let chunk_0 = ...;` or a statement) in place of the chunk: the marks as
/// [`checked_marks`] checks them.
fn walk_marks(stmts: &[syn::Stmt], what: &str, marks: &mut Vec<usize>, since: &mut usize, last: &mut usize) {
    let spacing = kinematics_core::BLOCK_MARK_OPS;
    // A chunk's closure: `private::chunk(|| { .. })`.
    let chunk = |expr: &syn::Expr| -> Option<Vec<syn::Stmt>> {
        let syn::Expr::Call(call) = expr else { return None };
        let callee = &call.func;
        if !quote::quote!(#callee).to_string().ends_with(":: chunk") {
            return None;
        }
        let Some(syn::Expr::Closure(closure)) = call.args.first() else { panic!("{what}: a chunk runs a closure") };
        let syn::Expr::Block(block) = &*closure.body else { panic!("{what}: a chunk's closure is a block") };
        Some(block.block.stmts.clone())
    };
    for stmt in stmts {
        match stmt {
            syn::Stmt::Local(local) => match local.init.as_ref().and_then(|init| chunk(&init.expr)) {
                Some(inner) => walk_marks(&inner, what, marks, since, last),
                None => {
                    *last = local.init.as_ref().map_or(0, |init| written_ops(&init.expr));
                    *since += *last;
                }
            },
            syn::Stmt::Expr(expr, Some(_)) if chunk(expr).is_some() => {
                walk_marks(&chunk(expr).expect("the guard found a chunk"), what, marks, since, last);
            }
            syn::Stmt::Expr(syn::Expr::Call(call), Some(_)) => {
                let callee = quote::quote!(#call).to_string();
                assert!(callee.starts_with("T :: block_mark"), "{what}: {callee}");
                let syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Int(n), .. }) = &call.args[0] else {
                    panic!("{what}: a numbered mark")
                };
                marks.push(n.base10_parse::<usize>().unwrap());
                assert!(*since >= spacing && *since - *last < spacing, "{what}: mark {n} after {since} operations");
                *since = 0;
            }
            // A chunk's value, the tuple of what it returns, computes nothing.
            syn::Stmt::Expr(syn::Expr::Tuple(_), None) => {}
            syn::Stmt::Expr(value, None) => *since += written_ops(value),
            other => panic!("{what}: a statement the emitter does not write: {}", quote::quote!(#other)),
        }
    }
}

/// Points fixed in links (as the sphere centres are) carry block marks, `T::block_mark(1);` on,
/// numbered in order, one after the first statement that reaches `BLOCK_MARK_OPS` operations
/// since the last.
#[test]
fn points_carry_block_marks_about_every_block_mark_ops() {
    let mut compiled = compile(&common::robot("ur5.toml"), &Request::all_links()).unwrap();
    let places: Vec<(usize, [f64; 3])> = (0..compiled.frames().len())
        .flat_map(|f| [(f, [0.1, 0.0, 0.02]), (f, [0.0, -0.05, 0.1]), (f, [0.03, 0.07, -0.2])])
        .collect();
    let points = compiled.points(&places);
    let outputs: Vec<_> = points.iter().flatten().copied().collect();
    let cost = kinematics_compiler::OpCount::of(compiled.graph(), outputs.iter().copied());
    let options = EmitOptions::named("centers");
    let text = kinematics_compiler::emit::emit_points(&compiled, &points, &options, " Points.").to_string();
    let marks = checked_marks(&text, "the points");
    assert!(marks.len() >= 3, "{} operations, {} marks", cost.mul + cost.add, marks.len());
}

/// Poses and Jacobians carry block marks the same way, through their returned values too: a
/// Jacobian's operations sit mostly in its entries, a tree's in its links' poses.
#[test]
fn poses_and_jacobians_carry_block_marks_through_their_values() {
    let bodies = [
        ("humanoid.urdf", Request::all_links(), "the humanoid's link poses"),
        ("dual_arm_torso.urdf", Request::all_links(), "the dual-arm torso's link poses"),
        (
            "gen3.urdf",
            Request::tip("end_effector_link").jacobian(JacobianFrame::LocalWorldAligned),
            "the Gen3's Jacobian",
        ),
    ];
    for (file, request, what) in bodies {
        let compiled = compile(&common::robot(file), &request).unwrap();
        let text = emit_module_source(&compiled, &EmitOptions::named("body")).unwrap();
        let marks = checked_marks(&text, what);
        assert!(marks.len() >= 2, "{what}: {} marks", marks.len());
    }
}

/// A body shorter than `BLOCK_MARK_OPS` carries none.
#[test]
fn short_bodies_carry_no_marks() {
    for (file, tip) in [("planar_3r.toml", "link3"), ("ur5.toml", "wrist_3_link")] {
        let compiled = compile(&common::robot(file), &Request::tip(tip)).unwrap();
        assert!(compiled.op_count().mul + compiled.op_count().add < kinematics_core::BLOCK_MARK_OPS);
        let text = emit_module_source(&compiled, &EmitOptions::named("body")).unwrap();
        assert!(checked_marks(&text, file).is_empty(), "{file}: {text}");
    }
}
