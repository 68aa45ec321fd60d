//! The section comparing the two builds: per robot, the plain build's median of each figure in
//! [`ACROSS_BUILDS`] beside the native build's and their ratio. The medians come from two separate
//! runs, minutes apart on a shared machine, so the ratios are not paired and the text says so.

use std::fmt::Write as _;

use super::{fmt, table};
use crate::read::{ACROSS_BUILDS, Row, Run, plain_over_native};

/// The "Plain against native" section, appended to `s`: the table when both builds were run, else
/// a line naming the run that is missing.
pub fn plain_against_native(s: &mut String, runs: &[Run]) {
    let _ = writeln!(s, "## Plain against native\n");
    let run = |name| runs.iter().find(|r| r.name == name);
    let (plain, native) = match (run("plain"), run("native")) {
        (Some(plain), Some(native)) => (plain, native),
        (plain, _) => {
            let missing = if plain.is_none() { "plain" } else { "native" };
            let _ = writeln!(s, "Needs both runs: the {missing} build has no results yet (commands above).\n");
            return;
        }
    };
    let _ = writeln!(
        s,
        "What a plain x86-64 build (generated functions dispatched at run time) gives against a build for this CPU\n\
         (`-C target-cpu=native`): per robot and figure, the plain build's criterion median, the native build's, and\n\
         plain / native (1.0: the plain build is as fast; above 1: slower). The figures are ns per call: `pose`\n\
         (`tip_pose`), `all links` (`link_poses`, black-boxed), `Jacobian` (`tip_jacobian`, `LOCAL_WORLD_ALIGNED`,\n\
         URDF robots only); and ns per configuration: `batch f64` and `batch f32` (`tip_pose_batch` and\n\
         `tip_pose_batch_f32` of 1,024). These ratios are of medians from two separate runs, not paired: the\n\
         machine's speed drifts between the runs, so they are noisier than the paired ratios (tens of percent are\n\
         possible); read a few percent either way as equal.\n"
    );
    // The plain run's robots in its order, then any the native run alone has.
    let mut rows: Vec<Row> = plain.rows.clone();
    rows.extend(native.rows.iter().filter(|n| !plain.rows.iter().any(|p| p.group == n.group)).cloned());
    let columns: Vec<String> = ACROSS_BUILDS
        .iter()
        .flat_map(|(what, _)| [format!("{what} plain"), format!("{what} native"), format!("{what} plain / native")])
        .collect();
    let columns: Vec<&str> = columns.iter().map(String::as_str).collect();
    let median = |rows: &[Row], group: &str, variant: &str| {
        rows.iter().find(|r| r.group == group).and_then(|r| r.ns.get(variant).copied())
    };
    table(s, &rows, &columns, |r, i| {
        let (_, variant) = ACROSS_BUILDS[i / 3];
        match i % 3 {
            0 => fmt(median(&plain.rows, &r.group, variant)),
            1 => fmt(median(&native.rows, &r.group, variant)),
            _ => plain_over_native(&plain.rows, &native.rows, &r.group, variant)
                .map_or("n/a".to_owned(), |v| format!("{v:.2}")),
        }
    });
    let _ = writeln!(s);
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;
    use crate::read::test_row;

    fn run(name: &'static str, rows: Vec<Row>) -> Run {
        Run { name, build: String::new(), dir: PathBuf::new(), rows }
    }

    #[test]
    fn without_both_runs_the_section_names_the_missing_one() {
        for (runs, missing) in [(vec![run("plain", vec![])], "native"), (vec![run("native", vec![])], "plain")] {
            let mut s = String::new();
            plain_against_native(&mut s, &runs);
            assert!(s.starts_with("## Plain against native\n"), "{s}");
            assert!(s.contains(&format!("the {missing} build has no results yet")), "{s}");
            assert!(!s.contains("| robot |"), "{s}");
        }
    }

    #[test]
    fn a_row_has_plain_native_and_their_ratio_per_figure() {
        let plain = vec![
            test_row(
                "ur5",
                &[("generated_pose_f64", 44.0), ("batch1024_f32", 6.0), ("generated_jacobian_f64", 50.0)],
                &[],
            ),
            test_row("scara", &[("generated_pose_f64", 20.0)], &[]),
        ];
        let native = vec![
            test_row("ur5", &[("generated_pose_f64", 40.0), ("batch1024_f32", 5.0)], &[]),
            test_row("quadruped", &[("generated_pose_f64", 25.0)], &[]),
        ];
        let mut s = String::new();
        plain_against_native(&mut s, &[run("plain", plain), run("native", native)]);
        assert!(s.contains("| robot | pose plain | pose native | pose plain / native | all links plain |"), "{s}");
        assert!(s.contains("not paired"), "{s}");
        // The Jacobian was not run natively: n/a; batch f32 is per configuration as read.
        let na = "n/a | n/a | n/a";
        assert!(
            s.contains(&format!("| ur5 | 44 | 40 | 1.10 | {na} | 50 | n/a | n/a | {na} | 6.00 | 5.00 | 1.20 |\n")),
            "{s}"
        );
        // A robot of one run only: its figures, no ratio; plain's robots first.
        assert!(s.contains("| scara | 20 | n/a | n/a |"), "{s}");
        assert!(s.contains("| quadruped | n/a | 25 | n/a |"), "{s}");
        assert!(s.find("| scara |") < s.find("| quadruped |"));
    }
}
