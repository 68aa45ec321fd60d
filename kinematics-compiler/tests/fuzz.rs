//! Fuzz-style property tests of the loader and the compiler together: structured random
//! descriptions (URDF trees and DH tables, with random numbers including extreme ones) go through
//! `parse_source`, and whatever loads through `compile` (every link, tips, positions, another base)
//! and the robot emission (`robot::emit_robot`, the derive's path). Nothing may panic, and emitted
//! code holds finite constants only (no `inf`, no `NaN` in the tokens).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::panic::catch_unwind;

use kinematics_compiler::emit::{EmitOptions, emit_function};
use kinematics_compiler::options::{Options, Scalars};
use kinematics_compiler::robot::{RobotSpec, emit_robot};
use kinematics_compiler::{Request, compile};
use kinematics_model::parse_source;
use proc_macro2::TokenStream;
use proptest::prelude::*;
use proptest::test_runner::Config;
use quote::quote;

/// A token of emitted code that is not a finite number. `f64::INFINITY` is allowed where
/// `infinite_limits` (a robot's `JOINT_LIMITS` gives continuous joints infinite limits).
fn non_finite_token(code: &str, infinite_limits: bool) -> Option<String> {
    code.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.'))
        .find(|t| {
            let t = t.trim_end_matches("f64").trim_end_matches("f32");
            t.eq_ignore_ascii_case("inf")
                || t.eq_ignore_ascii_case("nan")
                || (!infinite_limits && (t.eq_ignore_ascii_case("infinity") || t == "NEG_INFINITY"))
        })
        .map(str::to_owned)
}

/// Everything the compiler does with a description: every link, each leaf alone and as
/// positions, all leaves from the last link, and the whole robot emitted. Returns the emitted code.
fn compile_everything(label: &str, text: &str) -> Result<Vec<String>, String> {
    let tree = parse_source(label, text).map_err(|e| e.to_string())?;
    let mut code = Vec::new();
    let leaves: Vec<String> = tree.leaves().map(|l| tree.link(l).name.clone()).collect();
    let last = tree.links().last().map(|l| l.name.clone()).unwrap();
    let mut requests = vec![Request::all_links(), Request::all_links().positions_only()];
    if let Some(leaf) = leaves.first() {
        requests.push(Request::tip(leaf));
        requests.push(Request::tip(leaf).positions_only().with_base(&last));
    }
    for request in &requests {
        let compiled = compile(&tree, request).map_err(|e| format!("compile: {e}"))?;
        code.push(emit_function(&compiled, &EmitOptions::named("fk")).to_string());
    }
    let options = Options {
        tips: leaves,
        positions: true,
        jacobians: true,
        scalars: Scalars { f64: true, f32: true },
        ..Options::default()
    };
    let spec = RobotSpec {
        robot: options.check(&tree).map_err(|e| format!("emit_robot: options refused: {e}"))?,
        krate: quote!(::kinematics),
        source_label: label.to_owned(),
        source_text: quote!(""),
        source_files: None,
        impl_generics: TokenStream::new(),
        where_clause: TokenStream::new(),
    };
    let ty: TokenStream = quote!(Fuzz);
    code.push(emit_robot(&ty, &spec).map_err(|e| format!("emit_robot: {e}"))?.to_string());
    Ok(code)
}

/// How many descriptions loaded and compiled (so a strategy that never loads shows).
static LOADED: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// Loads and compiles `text`: no panic; emitted code with finite constants only. With `huge`
/// (numbers near the top of the `f64` range), a compile error naming the link whose constants
/// compose into infinity is an answer too: finite numbers of a valid tree can overflow when
/// multiplied out (a mimic multiplier of 1e100 times a lever arm of 1e300), and the compiler's
/// check of every constant is the mechanism that catches them all.
fn check(label: &str, text: &str, huge: bool) -> Result<(), TestCaseError> {
    let result = catch_unwind(|| compile_everything(label, text));
    if let Ok(Ok(_)) = &result {
        LOADED.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    }
    match result {
        Err(_) => Err(TestCaseError::fail(format!("panicked on {label}:\n{text}"))),
        Ok(Ok(code)) => {
            let robot = code.len() - 1;
            for (i, c) in code.iter().enumerate() {
                if let Some(t) = non_finite_token(c, i == robot) {
                    return Err(TestCaseError::fail(format!("`{t}` in the code emitted for {label}:\n{text}")));
                }
            }
            Ok(())
        }
        // A load error is an answer; a compile error on a loaded tree is not allowed (the
        // compiler's only errors are requests naming links the robot does not have).
        Ok(Err(e)) if huge && e.contains("the constants of its pose are not all finite numbers") => Ok(()),
        Ok(Err(e)) if e.starts_with("compile") || e.starts_with("emit_robot") => {
            Err(TestCaseError::fail(format!("{e} on a robot that loaded: {label}:\n{text}")))
        }
        Ok(Err(_)) => Ok(()),
    }
}

/// Numbers as text: ordinary values mostly, and now and then extreme ones. With `huge`, values
/// near the top of the `f64` range, which may compose into infinity along a chain.
fn number(huge: bool) -> BoxedStrategy<String> {
    let mut extreme = vec![
        "0",
        "-0",
        "1e-308",
        "5e-324",
        "2.2250738585072014e-308",
        "1e100",
        "-1e100",
        "1e17",
        "-1e17",
        "1e16",
        "3.14159265359",
        "1.57079632679",
        "-1.57079632679",
        "1.5708",
        "6.28318530718",
        "1e-9",
        "123456789.123",
    ];
    if huge {
        extreme.extend([
            "1e308",
            "-1e308",
            "1.7976931348623157e308",
            "1e200",
            "-1e200",
            "1e300",
            "8.98846567431158e307",
        ]);
    }
    let moderate = (-3.0..3.0f64).prop_map(|x| format!("{x:?}"));
    let bad = prop::sample::select(vec!["NaN", "inf", "-inf", "1e400", "abc", ""]).prop_map(str::to_owned);
    // Bad values are rare: one in a description is enough to stop it loading.
    prop_oneof![
        80 => moderate,
        20 => prop::sample::select(extreme).prop_map(str::to_owned),
        1 => bad,
    ]
    .boxed()
}

/// One URDF joint: (parent index, type, xyz, rpy, axis, limits, mimic (source, multiplier, offset)).
type JointSpec = (usize, usize, [String; 3], [String; 3], [String; 3], [String; 2], Option<(usize, String, String)>);

fn joint_spec(i: usize, huge: bool) -> impl Strategy<Value = JointSpec> {
    let n = || number(huge);
    let axis = prop_oneof![
        3 => prop::sample::select(vec!["0 0 1", "1 0 0", "0 -1 0"]).prop_map(|a| {
            let mut p = a.split(' ').map(str::to_owned);
            [(); 3].map(|()| p.next().unwrap())
        }),
        1 => [n(), n(), n()],
    ];
    (
        0..=i,
        0..4usize,
        [n(), n(), n()],
        [n(), n(), n()],
        axis,
        [n(), n()].prop_map(ordered),
        prop::option::weighted(0.3, (0..=i, n(), n())),
    )
}

/// Two limits, lower first when both are numbers (a reversed pair is an error, not a fuzz case).
fn ordered([a, b]: [String; 2]) -> [String; 2] {
    match (a.trim_matches('"').parse::<f64>(), b.trim_matches('"').parse::<f64>()) {
        (Ok(x), Ok(y)) if x > y => [b, a],
        _ => [a, b],
    }
}

fn urdf(huge: bool) -> impl Strategy<Value = String> {
    (1..=8usize).prop_flat_map(move |n| (0..n).map(|i| joint_spec(i, huge)).collect::<Vec<_>>()).prop_map(|specs| {
        let mut text = String::from("<robot name=\"fuzz\"><link name=\"l0\"/>");
        for (k, (parent, kind, xyz, rpy, axis, limits, mimic)) in specs.iter().enumerate() {
            let kind = ["revolute", "continuous", "prismatic", "fixed"][*kind];
            let mimic = match mimic {
                Some((source, m, o)) if *source < k => format!("<mimic joint=\"j{source}\" multiplier=\"{m}\" offset=\"{o}\"/>"),
                _ => String::new(),
            };
            text += &format!(
                "<link name=\"l{c}\"/><joint name=\"j{k}\" type=\"{kind}\"><parent link=\"l{parent}\"/><child link=\"l{c}\"/>\
                 <origin xyz=\"{}\" rpy=\"{}\"/><axis xyz=\"{}\"/><limit lower=\"{}\" upper=\"{}\" effort=\"1\" velocity=\"1\"/>{mimic}</joint>",
                xyz.join(" "),
                rpy.join(" "),
                axis.join(" "),
                limits[0],
                limits[1],
                c = k + 1,
            );
        }
        text + "</robot>"
    })
}

/// A DH table in TOML: numbers in every column, exact strings now and then.
fn dh(huge: bool) -> impl Strategy<Value = String> {
    let value = move || {
        prop_oneof![
            3 => number(huge),
            1 => prop::sample::select(vec!["\"pi/2\"", "\"-pi\"", "\"3*pi/2\"", "\"1e300*pi\"", "\"pi/0\"", "\"0\""]).prop_map(str::to_owned),
        ]
    };
    let row = move || {
        (
            number(huge),
            value(),
            number(huge),
            value(),
            value(),
            any::<bool>(),
            prop::option::of([value(), value()].prop_map(ordered)),
        )
    };
    (any::<bool>(), prop::collection::vec(row(), 1..8), prop::option::of([number(huge), number(huge), number(huge)]))
        .prop_map(|(modified, rows, tool)| {
            let mut text = format!("convention = \"{}\"\n", if modified { "modified" } else { "standard" });
            if let Some(xyz) = tool {
                text += &format!("[tool]\nxyz = [{}]\nrpy = [\"pi/2\", 0.0, 0.0]\n", xyz.join(", "));
            }
            for (i, (a, alpha, d, theta, offset, prismatic, limits)) in rows.iter().enumerate() {
                text += &format!("[[joints]]\nname = \"q{i}\"\na = {a}\nalpha = {alpha}\nd = {d}\ntheta = {theta}\n");
                if *prismatic {
                    // A prismatic row's offset and limits are lengths: numbers only.
                    text += "type = \"prismatic\"\n";
                } else {
                    text += &format!("offset = {offset}\n");
                }
                if let Some([lo, hi]) = limits.as_ref().filter(|l| !*prismatic || !l.iter().any(|v| v.starts_with('"')))
                {
                    text += &format!("lower = {lo}\nupper = {hi}\n");
                }
            }
            text
        })
}

proptest! {
    #![proptest_config(Config { cases: 400, failure_persistence: None, ..Config::default() })]

    /// Random trees with numbers as large as 1e100 and as small as the smallest subnormal.
    #[test]
    fn random_urdf_trees_load_compile_and_emit_without_panic(text in urdf(false)) {
        check("fuzz.urdf", &text, false)?;
    }

    #[test]
    fn random_dh_tables_load_compile_and_emit_without_panic(text in dh(false)) {
        check("fuzz.toml", &text, false)?;
    }
}

proptest! {
    #![proptest_config(Config { cases: 400, failure_persistence: None, ..Config::default() })]

    /// The same with numbers near the top of the `f64` range, which compose into infinity.
    #[test]
    fn random_urdf_trees_with_huge_numbers_load_compile_and_emit_without_panic(text in urdf(true)) {
        check("fuzz.urdf", &text, true)?;
    }

    #[test]
    fn random_dh_tables_with_huge_numbers_load_compile_and_emit_without_panic(text in dh(true)) {
        check("fuzz.toml", &text, true)?;
    }
}

/// The finiteness check sees what it must.
#[test]
fn non_finite_tokens_are_found() {
    assert_eq!(non_finite_token("T::from_f64(inf) * x", true), Some("inf".to_owned()));
    assert_eq!(non_finite_token("let a = NaNf64;", true), Some("NaNf64".to_owned()));
    assert_eq!(non_finite_token("T::from_f64(f64::INFINITY)", false), Some("INFINITY".to_owned()));
    assert_eq!(non_finite_token("upper: f64::INFINITY", true), None);
    assert_eq!(non_finite_token("T::from_f64(1.5e300) + info", false), None);
}

/// Most random descriptions load, so the compiler is what gets fuzzed.
#[test]
fn most_random_descriptions_load() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let (mut urdf_ok, mut dh_ok) = (0, 0);
    for _ in 0..200 {
        let u = urdf(false).new_tree(&mut runner).unwrap().current();
        urdf_ok += usize::from(parse_source("fuzz.urdf", &u).is_ok());
        let d = dh(false).new_tree(&mut runner).unwrap().current();
        dh_ok += usize::from(parse_source("fuzz.toml", &d).is_ok());
    }
    println!("loaded: {urdf_ok} of 200 URDF trees, {dh_ok} of 200 DH tables");
    assert!(urdf_ok >= 60 && dh_ok >= 60, "loaded: {urdf_ok} of 200 URDF trees, {dh_ok} of 200 DH tables");
}

/// A joint of a hand-written regression case: `(name, type, parent, child, xyz, mimic)`.
fn urdf_of(joints: &[(&str, &str, &str, &str, &str, &str)]) -> String {
    let mut links: Vec<&str> = vec!["l0"];
    let mut text = String::from("<robot name=\"regression\">");
    for (name, kind, parent, child, xyz, mimic) in joints {
        for l in [parent, child] {
            if !links.contains(l) {
                links.push(l);
            }
        }
        text += &format!(
            "<joint name=\"{name}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"{child}\"/><origin xyz=\"{xyz}\"/>\
             <axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>{mimic}</joint>"
        );
    }
    let links: String = links.iter().map(|l| format!("<link name=\"{l}\"/>")).collect();
    text.replacen("<robot name=\"regression\">", &format!("<robot name=\"regression\">{links}"), 1) + "</robot>"
}

/// The case is refused by the model with an error (its composed numbers overflow: the reach
/// and mimic rules) or loads, compiles and emits without a panic and with finite constants.
fn assert_no_panic(label: &str, text: &str) {
    if parse_source(label, text).is_err() {
        return;
    }
    if let Err(e) = check(label, text, false) {
        panic!("{e}");
    }
}

/// Issue 13, defect 4: two fixed joints at x = 1e308 put the second link at 2e308.
#[test]
fn regression_two_fixed_joints_at_1e308() {
    let text = urdf_of(&[
        ("a", "fixed", "l0", "l1", "1e308 0 0", ""),
        ("b", "fixed", "l1", "l2", "1e308 0 0", ""),
        ("c", "revolute", "l2", "l3", "0 0 0", ""),
    ]);
    assert_no_panic("fixed_1e308.urdf", &text);
}

/// Found by the fuzz test (minimised): two branches at +MAX and -1e308; the pose of one in the
/// other's frame is 2.8e308 away.
#[test]
fn regression_branches_at_both_ends_of_the_range() {
    let text = urdf_of(&[
        ("a", "revolute", "l0", "l1", "1.7976931348623157e308 0 0", ""),
        ("b", "revolute", "l0", "l2", "-1e308 0 0", ""),
    ]);
    assert_no_panic("branches_max.urdf", &text);
}

/// Issue 13, defect 4: mimic multipliers of 1e200 along a chain (1e200 * 1e200 overflows).
#[test]
fn regression_mimic_multipliers_of_1e200_along_a_chain() {
    let text = urdf_of(&[
        ("a", "continuous", "l0", "l1", "0 0 0", ""),
        ("b", "continuous", "l1", "l2", "0 0 0", "<mimic joint=\"a\" multiplier=\"1e200\"/>"),
        ("c", "continuous", "l2", "l3", "0 0 0", "<mimic joint=\"b\" multiplier=\"1e200\"/>"),
        ("d", "continuous", "l3", "l4", "1 0 0", ""),
    ]);
    assert_no_panic("mimic_1e200.urdf", &text);
}

/// The DH form of the first case: a base 1e308 up and a row with `d = 1e308` along the same
/// axis (the joint's rotation about z leaves z alone, so the two add into one constant).
#[test]
fn regression_dh_base_and_offset_of_1e308() {
    let text = "convention = \"standard\"\n[base]\nxyz = [0.0, 0.0, 1e308]\n[[joints]]\nname = \"a\"\nd = 1e308\n[[joints]]\nname = \"b\"\na = 1.0\n";
    assert_no_panic("dh_1e308.toml", text);
}

/// Rows with `a = 1e308` whose sum is never a constant (each is turned by its joint) compile.
#[test]
fn dh_rows_with_a_of_1e308_compile() {
    let text = "convention = \"standard\"\n[[joints]]\nname = \"a\"\na = 1e308\n[[joints]]\nname = \"b\"\na = 1e308\n[[joints]]\nname = \"c\"\na = 1.0\n";
    assert_no_panic("dh_1e308.toml", text);
}

/// Found by `random_urdf_trees_with_huge_numbers_...`: each composed mimic multiplier finite
/// (1e308, 1.57e308), the Jacobian's lever arm times them not. The robot loads; the compiler
/// names the link whose constants overflow instead of emitting an infinity.
#[test]
fn mimic_rates_that_overflow_are_a_compile_error_naming_the_link() {
    let text = "<robot name=\"fuzz\"><link name=\"l0\"/><link name=\"l1\"/><joint name=\"j0\" type=\"revolute\"><parent link=\"l0\"/><child link=\"l1\"/><origin xyz=\"0.0 0.0 0.0\" rpy=\"0.0 0.0 0.0\"/><axis xyz=\"0 0 1\"/><limit lower=\"0.0\" upper=\"0.0\" effort=\"1\" velocity=\"1\"/></joint><link name=\"l2\"/><joint name=\"j1\" type=\"revolute\"><parent link=\"l0\"/><child link=\"l2\"/><origin xyz=\"0.0 0.0 0.0\" rpy=\"0.0 0.0 0.0\"/><axis xyz=\"0 0 1\"/><limit lower=\"0.0\" upper=\"0.0\" effort=\"1\" velocity=\"1\"/><mimic joint=\"j0\" multiplier=\"1e308\" offset=\"0.0\"/></joint><link name=\"l3\"/><joint name=\"j2\" type=\"revolute\"><parent link=\"l0\"/><child link=\"l3\"/><origin xyz=\"0.0 0.0 0.0\" rpy=\"0.0 0.0 0.0\"/><axis xyz=\"0 0 1\"/><limit lower=\"0.0\" upper=\"0.0\" effort=\"1\" velocity=\"1\"/></joint><link name=\"l4\"/><joint name=\"j3\" type=\"revolute\"><parent link=\"l0\"/><child link=\"l4\"/><origin xyz=\"0.0 0.0 0.0\" rpy=\"0.0 0.0 0.0\"/><axis xyz=\"1 0 0\"/><limit lower=\"0.0\" upper=\"0.0\" effort=\"1\" velocity=\"1\"/><mimic joint=\"j1\" multiplier=\"1.57079632679\" offset=\"0.0\"/></joint><link name=\"l5\"/><joint name=\"j4\" type=\"fixed\"><parent link=\"l4\"/><child link=\"l5\"/><origin xyz=\"0.0 0.0 -2.9574721043159227\" rpy=\"0.0 0.0 0.0\"/><axis xyz=\"0 0 1\"/><limit lower=\"0.0\" upper=\"0.0\" effort=\"1\" velocity=\"1\"/></joint></robot>";
    assert!(check("fuzz.urdf", text, true).is_ok());
    let error = compile_everything("fuzz.urdf", text).expect_err("the Jacobian's constants overflow");
    assert!(error.contains("link `l5`: the constants of its pose are not all finite numbers (one is inf)"), "{error}");
}
