//! Fuzz-style property tests of the loader: arbitrary bytes, arbitrary UTF-8 and mutations of the
//! real robot files in `robots/` (truncations, deleted and duplicated lines, numbers replaced by
//! huge, tiny, NaN, negative or garbage values, names replaced by empty or 70,000-byte strings)
//! go through `parse_source` as `.urdf`, `.mjcf`, `.toml` and `.json`. Whatever the input, loading returns
//! a tree or an error, never panics; a tree it returns holds finite numbers only (limits may be
//! infinite, never NaN).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::panic::catch_unwind;

use kinematics_model::{Elementary, KinematicTree, parse_source};
use proptest::prelude::*;
use proptest::test_runner::Config;

const LABELS: [&str; 4] = ["fuzz.urdf", "fuzz.mjcf", "fuzz.toml", "fuzz.json"];

/// Every number a tree holds is finite (the model's invariant; later stages rely on it); limits
/// may be infinite (unbounded, as written), never NaN.
fn finite(tree: &KinematicTree) -> bool {
    tree.joints().iter().all(|j| {
        let steps = j.origin.steps().iter().chain(j.after_motion.steps());
        let numbers_ok = steps.into_iter().all(|s| match s {
            Elementary::Translation(v) => v.iter().all(|x| x.is_finite()),
            Elementary::Rotation(_, angle) => angle.radians().is_finite(),
        });
        numbers_ok
            && j.axis.iter().all(|x| x.is_finite())
            && j.limits.is_none_or(|l| !(l.lower.is_nan() || l.upper.is_nan()))
    })
}

/// Loads `text` under `label`: no panic, and a tree only with finite numbers.
fn load(label: &str, text: &str) -> Result<(), TestCaseError> {
    match catch_unwind(|| parse_source(label, text).map(|tree| finite(&tree))) {
        Err(_) => {
            Err(TestCaseError::fail(format!("parse_source panicked on {label} ({} bytes): {text:?}", text.len())))
        }
        Ok(Ok(false)) => {
            Err(TestCaseError::fail(format!("{label}: a tree with a number that is not finite from {text:?}")))
        }
        Ok(_) => Ok(()),
    }
}

fn robot_files() -> Vec<(String, String)> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots");
    let mut files: Vec<(String, String)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "urdf" || e == "xml" || e == "toml" || e == "json"))
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    files.sort();
    assert!(files.len() >= 8, "robots/ holds the robots");
    files
}

/// Values a number in a description may be replaced by.
const NUMBERS: [&str; 24] = [
    "1e308",
    "-1e308",
    "1.8e308",
    "1e-308",
    "5e-324",
    "-0",
    "0",
    "NaN",
    "nan",
    "inf",
    "-inf",
    "infinity",
    "1e200",
    "-1e200",
    "1e17",
    "-3.14159265359",
    "1.57079632679",
    "x",
    "",
    "--1",
    "1e",
    "0x10",
    "1_000",
    "１",
];

/// Values a name may be replaced by.
fn name_replacement(k: usize) -> String {
    match k % 4 {
        0 => String::new(),
        1 => "n".repeat(70_000),
        2 => "ü\u{0}\"<>&".to_owned(),
        _ => " ".to_owned(),
    }
}

/// One mutation of a file's text.
#[derive(Debug, Clone)]
enum Mutation {
    Truncate(usize),
    DeleteLine(usize),
    DuplicateLine(usize),
    ReplaceNumber(usize, usize),
    ReplaceName(usize, usize),
    SwapLines(usize, usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        1 => any::<usize>().prop_map(Mutation::Truncate),
        1 => any::<usize>().prop_map(Mutation::DeleteLine),
        1 => any::<usize>().prop_map(Mutation::DuplicateLine),
        3 => (any::<usize>(), 0..NUMBERS.len()).prop_map(|(at, n)| Mutation::ReplaceNumber(at, n)),
        2 => (any::<usize>(), 0..4usize).prop_map(|(at, n)| Mutation::ReplaceName(at, n)),
        1 => (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
    ]
}

/// Byte ranges of the numbers in `text` (a digit run with sign, point and exponent).
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit() && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'));
        if starts {
            let start = if i > 0 && b[i - 1] == b'-' { i - 1 } else { i };
            while i < b.len() && (b[i].is_ascii_digit() || matches!(b[i], b'.' | b'e' | b'E' | b'-' | b'+')) {
                i += 1;
            }
            out.push((start, i));
        } else {
            i += 1;
        }
    }
    out
}

/// Byte ranges of quoted names: `name="..."`, `link="..."`, `joint="..."`, `name = "..."`.
fn names(text: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for key in ["name=\"", "link=\"", "joint=\"", "name = \"", "link = \"", "base_link = \"", "\"name\": \""] {
        let mut from = 0;
        while let Some(at) = text[from..].find(key) {
            let start = from + at + key.len();
            match text[start..].find('"') {
                Some(len) => out.push((start, start + len)),
                None => break,
            }
            from = start;
        }
    }
    out.sort();
    out
}

fn apply(text: &str, m: &Mutation) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let line = |k: usize| k % lines.len().max(1);
    match *m {
        Mutation::Truncate(at) => {
            let mut at = at % (text.len() + 1);
            while !text.is_char_boundary(at) {
                at -= 1;
            }
            text[..at].to_owned()
        }
        Mutation::DeleteLine(k) => {
            let k = line(k);
            lines.iter().enumerate().filter(|(i, _)| *i != k).map(|(_, l)| *l).collect::<Vec<_>>().join("\n")
        }
        Mutation::DuplicateLine(k) => {
            let k = line(k);
            let mut out: Vec<&str> = lines.clone();
            if !lines.is_empty() {
                out.insert(k, lines[k]);
            }
            out.join("\n")
        }
        Mutation::SwapLines(a, b) => {
            let mut out: Vec<&str> = lines.clone();
            if !lines.is_empty() {
                out.swap(line(a), line(b));
            }
            out.join("\n")
        }
        Mutation::ReplaceNumber(at, n) => {
            let spans = numbers(text);
            if spans.is_empty() {
                return text.to_owned();
            }
            let (s, e) = spans[at % spans.len()];
            format!("{}{}{}", &text[..s], NUMBERS[n], &text[e..])
        }
        Mutation::ReplaceName(at, n) => {
            let spans = names(text);
            if spans.is_empty() {
                return text.to_owned();
            }
            let (s, e) = spans[at % spans.len()];
            format!("{}{}{}", &text[..s], name_replacement(n), &text[e..])
        }
    }
}

proptest! {
    #![proptest_config(Config { cases: 600, failure_persistence: None, ..Config::default() })]

    #[test]
    fn arbitrary_bytes_never_panic_the_loader(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        let text = String::from_utf8_lossy(&bytes);
        for label in LABELS {
            load(label, &text)?;
        }
    }

    #[test]
    fn arbitrary_text_never_panics_the_loader(text in "\\PC{0,300}") {
        for label in LABELS {
            load(label, &text)?;
        }
    }

    /// Text made of the formats' own punctuation and keywords, which gets deeper into the parsers.
    #[test]
    fn format_like_text_never_panics_the_loader(
        parts in proptest::collection::vec(prop::sample::select(vec![
            "<robot name=\"r\">", "</robot>", "<link name=\"a\"/>", "<link name=\"b\">", "</link>", "<joint name=\"j\" type=\"revolute\">",
            "<joint name=\"j\" type=\"fixed\">", "</joint>", "<parent link=\"a\"/>", "<child link=\"b\"/>", "<origin xyz=\"1 2 3\" rpy=\"0 0 1e308\"/>",
            "<axis xyz=\"0 0 1e200\"/>", "<limit lower=\"1\" upper=\"-1\" effort=\"1\" velocity=\"1\"/>", "<mimic joint=\"j\" multiplier=\"1e300\"/>",
            "convention = \"standard\"\n", "[[joints]]\n", "name = \"j\"\n", "a = 1e308\n", "alpha = \"pi/0\"\n", "theta = \"1e400*pi\"\n",
            "offset = \"-pi/2\"\n", "lower = \"pi\"\nupper = \"-pi\"\n", "[tool]\n", "rpy = [\"pi\", 0.0, 1e308]\n", "type = \"prismatic\"\n",
            "{\"convention\": \"modified\", \"joints\": [",
            "<mujoco>", "</mujoco>", "<worldbody>", "</worldbody>", "<body name=\"b\" quat=\"0 0 0 1e-320\">", "</body>",
            "<joint name=\"h\" pos=\"1e308 0 0\" axis=\"0 0 1e-300\" ref=\"1e308\"/>", "<site name=\"s\" type=\"box\" fromto=\"0 0 0 0 0 1e-320\"/>",
            "<frame euler=\"1e308 0 nan\">", "</frame>", "<freejoint/>", "<compiler eulerseq=\"zYx\" angle=\"radian\"/>",
            "<equality><joint joint1=\"h\" joint2=\"h\" polycoef=\"inf 1e308 0 0 0\"/></equality>", "<default><joint range=\"1 -1\"/></default>", "{\"name\": \"j\", \"a\": 1e308}", "]}", ",", "\"", "=", "\n", "<", ">",
        ]), 0..24)
    ) {
        let text: String = parts.concat();
        for label in LABELS {
            load(label, &text)?;
        }
    }
}

proptest! {
    #![proptest_config(Config { cases: 1500, failure_persistence: None, ..Config::default() })]

    #[test]
    fn mutated_robot_files_never_panic_the_loader(
        file in 0..64usize,
        mutations in proptest::collection::vec(mutation(), 1..4),
    ) {
        let files = robot_files();
        let (name, text) = &files[file % files.len()];
        let mut text = text.clone();
        for m in &mutations {
            text = apply(&text, m);
        }
        // Under its own format's label, and under the others'.
        load(name, &text)?;
        for label in LABELS {
            load(label, &text)?;
        }
    }
}

/// The mutations do what they say (a mutation that changed nothing would test nothing).
#[test]
fn mutations_change_the_files() {
    let files = robot_files();
    let (_, ur5) = files.iter().find(|(n, _)| n == "ur5.urdf").unwrap();
    assert!(numbers(ur5).len() > 50 && names(ur5).len() > 20);
    let long = apply(ur5, &Mutation::ReplaceName(3, 1));
    assert_eq!(long.len(), ur5.len() + 70_000 - (names(ur5)[3].1 - names(ur5)[3].0));
    assert!(apply(ur5, &Mutation::ReplaceNumber(7, 7)).contains("NaN"));
    assert!(apply(ur5, &Mutation::Truncate(100)).len() == 100);
    assert!(apply(ur5, &Mutation::DeleteLine(5)).lines().count() < ur5.lines().count());
    for (name, text) in &files {
        assert!(parse_source(name, text).is_ok(), "{name} loads unmutated");
        assert!(parse_source(name, &apply(text, &Mutation::Truncate(text.len() / 2))).is_err(), "{name} cut in half");
    }
}
