//! Targets: the speed targets, each stated for a build (`plain`, `native`, or `any`),
//! with the figure measured in that build's results and whether it is met; then the inverse
//! kinematics targets. A target that has no figure yet says `not measured` (or `n/a`), never met.
//! NaN is the worst figure of all and meets no bound.

use std::fmt::Write as _;

use crate::read::{Ik, Row, Run, ik_geo_cell, ratio};

/// One of the targets, as a figure measured in one run.
struct Target {
    what: &'static str,
    /// `native`, `plain` or `any`: the build the target is stated for.
    build: &'static str,
    /// The measured figure, and whether it meets the target.
    measure: fn(&[Row]) -> Option<(String, bool)>,
}

/// The worst (`lowest` when higher is better, else highest) of pair `name` over the robots that
/// have it, with that robot: `None` when no robot has it.
fn worst_paired(rows: &[Row], name: &str, lowest: bool) -> Option<(f64, String)> {
    let mut worst: Option<(f64, String)> = None;
    for r in rows {
        let Some(&v) = r.paired.get(name) else { continue };
        // NaN is the worst of all: once found, it stays.
        let replace = match &worst {
            None => true,
            Some((w, _)) => !w.is_nan() && (v.is_nan() || if lowest { v < *w } else { v > *w }),
        };
        if replace {
            worst = Some((v, r.group.clone()));
        }
    }
    worst
}

/// [`every_robot`] over the UR5, the Panda and the iiwa 14 only (the robots the velocity targets
/// name; the others are in the tables).
fn named_robots(rows: &[Row], name: &str, bound: f64, lowest: bool) -> Option<(String, bool)> {
    let named: Vec<Row> =
        rows.iter().filter(|r| ["ur5", "panda", "iiwa14"].contains(&r.group.as_str())).cloned().collect();
    every_robot(&named, name, bound, lowest)
}

fn ur5(rows: &[Row]) -> Option<&Row> {
    rows.iter().find(|r| r.group == "ur5")
}

/// A figure at least `bound`, NaN failing.
fn at_least(v: f64, bound: f64) -> bool {
    v.is_finite() && v >= bound
}

/// A figure at most `bound`, NaN failing.
fn at_most(v: f64, bound: f64) -> bool {
    v.is_finite() && v <= bound
}

/// "the worst robot's figure (robot)", met when every robot meets `bound` (`lowest`: at least).
fn every_robot(rows: &[Row], name: &str, bound: f64, lowest: bool) -> Option<(String, bool)> {
    let (v, robot) = worst_paired(rows, name, lowest)?;
    let count = rows.iter().filter(|r| r.paired.contains_key(name)).count();
    let met = if lowest { at_least(v, bound) } else { at_most(v, bound) };
    Some((format!("worst {v:.2} ({robot}; {count} robots, paired)"), met))
}

/// The forward kinematics targets, in the order the table shows them.
const TARGETS: [Target; 16] = [
    Target {
        what: "UR5, Panda, iiwa: pose + Jacobian of the tip at most 1.6x the pose alone (paired)",
        build: "any",
        measure: |rows| named_robots(rows, "generated_pose_and_jacobian_f64/generated_pose_f64", 1.6, false),
    },
    Target {
        what: "UR5, Panda, iiwa: pose + Jacobian at least 8x faster than the runtime Jacobian (paired)",
        build: "any",
        measure: |rows| named_robots(rows, "runtime_jacobian_f64/generated_pose_and_jacobian_f64", 8.0, true),
    },
    Target {
        what: "UR5, Panda, iiwa: the twist cheaper than forming J and multiplying (paired ratio > 1)",
        build: "any",
        measure: |rows| named_robots(rows, "jacobian_times_qd_f64/generated_twist_f64", 1.0, true),
    },
    Target {
        what: "UR5 pose f64 scalar >= 2.5x faster than the std-trig pose (paired), native",
        build: "native",
        measure: |rows| {
            let v = *ur5(rows)?.paired.get("std_pose_f64/generated_pose_f64")?;
            Some((format!("{v:.2}x"), at_least(v, 2.5)))
        },
    },
    Target {
        what: "UR5 pose f64 scalar >= 2x faster than the std-trig pose (paired), plain build",
        build: "plain",
        measure: |rows| {
            let v = *ur5(rows)?.paired.get("std_pose_f64/generated_pose_f64")?;
            Some((format!("{v:.2}x"), at_least(v, 2.0)))
        },
    },
    Target {
        what: "all link poses f64, every robot: >= 6x faster than `k` (URDF robots)",
        build: "any",
        measure: |rows| every_robot(rows, "k_all_f64/generated_all_f64", 6.0, true),
    },
    Target {
        what: "all link poses f64, every robot: >= 3x faster than galaw (URDF robots)",
        build: "any",
        measure: |rows| every_robot(rows, "galaw_all_f64/generated_all_f64", 3.0, true),
    },
    Target {
        what: "all link poses f64, every robot: >= 4x faster than the runtime",
        build: "any",
        measure: |rows| every_robot(rows, "runtime_all_f64/generated_all_f64", 4.0, true),
    },
    Target {
        what: "batch of 1,024 UR5 poses f64: <= 16 ns per configuration (criterion median), native",
        build: "native",
        measure: |rows| {
            let v = *ur5(rows)?.ns.get("batch1024_f64")?;
            Some((format!("{v:.2} ns"), at_most(v, 16.0)))
        },
    },
    Target {
        what: "batch of 1,024 UR5 poses f32: <= 8 ns per configuration (criterion median), native",
        build: "native",
        measure: |rows| {
            let v = *ur5(rows)?.ns.get("batch1024_f32")?;
            Some((format!("{v:.2} ns"), at_most(v, 8.0)))
        },
    },
    Target {
        what: "rayon on 2 cores >= 1.8x over one thread (UR5, 16,384 configurations, paired)",
        build: "any",
        measure: |rows| {
            let v = *ur5(rows)?.paired.get("batch16384_f64/parallel_batch16384_f64")?;
            Some((format!("{v:.2}x"), at_least(v, 1.8)))
        },
    },
    Target {
        what: "every body within 1.3x of the new floor: pose f64 / floor",
        build: "any",
        measure: |rows| every_robot(rows, "generated_pose_f64/floor_f64", 1.3, false),
    },
    Target {
        what: "every body within 1.3x of the new floor: all links f64 / floor all",
        build: "any",
        measure: |rows| every_robot(rows, "generated_all_f64/floor_all_f64", 1.3, false),
    },
    Target {
        what: "every body within 1.3x of the new floor: pose f32 / floor f32",
        build: "any",
        measure: |rows| every_robot(rows, "generated_pose_f32/floor_f32", 1.3, false),
    },
    Target {
        what: "every body within 1.3x of the new floor: lanes f64x4 and f32x8 / their floors",
        build: "any",
        measure: |rows| {
            let (a, ra) = every_robot(rows, "lanes_pose_f64x4/floor_f64x4", 1.3, false)?;
            let (b, rb) = every_robot(rows, "lanes_pose_f32x8/floor_f32x8", 1.3, false)?;
            Some((format!("f64x4 {a}; f32x8 {b}"), ra && rb))
        },
    },
    Target {
        what: "f32 about twice as fast as f64 in lanes (read as >= 1.8x per configuration, paired, UR5)",
        build: "any",
        measure: |rows| {
            let r = ur5(rows)?;
            let lanes = *r.paired.get("lanes_pose_f64x4/lanes_pose_f32x8")?;
            let batch = *r.paired.get("batch1024_f64/batch1024_f32")?;
            Some((format!("lanes {lanes:.2}x, batches {batch:.2}x"), at_least(lanes, 1.8) && at_least(batch, 1.8)))
        },
    },
];

/// The targets table, appended to `s`: one line per target and build it applies to.
pub fn targets(s: &mut String, runs: &[Run]) {
    let _ = writeln!(s, "## Targets\n");
    let _ = writeln!(
        s,
        "The issue's targets, each from the build it names (`any`: every build that was run), with the figure\n\
         measured and whether it is met. Ratios are paired (above); the batch figures are criterion medians per\n\
         configuration. `not measured` means that build (or that body) has no results yet.\n"
    );
    let _ = writeln!(s, "| target | build | measured | met |");
    let _ = writeln!(s, "|---|---|---|---|");
    for target in &TARGETS {
        let wanted: Vec<&'static str> =
            if target.build == "any" { vec!["plain", "native"] } else { vec![target.build] };
        for build in wanted {
            let (figure, met) = match runs.iter().find(|r| r.name == build).and_then(|r| (target.measure)(&r.rows)) {
                Some((figure, met)) => (figure, if met { "yes" } else { "**no**" }),
                None => ("not measured".to_owned(), "-"),
            };
            let _ = writeln!(s, "| {} | {build} | {figure} | {met} |", target.what);
        }
    }
}

/// The IK targets, as a table: IK-Geo over ours for the closed forms (from the ik-geo
/// table), nearest over all, and the numeric solver's speed over `k`'s and its success rate.
pub fn ik_targets(ik: &Ik) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "### IK targets\n\n| target | measured | met |\n|---|---|---|");
    let mut target = |what: &str, measured: Option<f64>, bound: f64, at_least: bool| {
        let met = measured.map(|m| if at_least { m >= bound } else { m <= bound });
        // Two decimals: a success rate of 99.8% must not read as 100.
        let shown = measured.map_or("n/a".to_owned(), |v| format!("{v:.2}"));
        let _ = writeln!(s, "| {what} | {shown} | {} |", met.map_or("n/a", |m| if m { "yes" } else { "no" }));
    };
    for (robot, bound) in [("UR5", 4.0), ("IRB 120", 4.0), ("PUMA 560", 4.0)] {
        target(&format!("{robot}: ik-geo / our solver >= {bound}"), ik_geo_cell(&ik.ik_geo, robot, 4), bound, true);
        target(
            &format!("{robot}: ik-geo / our tip_ik (with errors) >= {bound}"),
            ik_geo_cell(&ik.ik_geo, robot, 3),
            bound,
            true,
        );
    }
    for robot in &ik.closed {
        target(&format!("{}: nearest / all <= 1.2", robot.name), ratio(robot.nearest, robot.all), 1.2, false);
    }
    for robot in &ik.numeric {
        target(&format!("{}: k / ours per solve >= 10", robot.name), ratio(robot.k, robot.ours), 10.0, true);
        let converged = robot.success.map(|(o, _, n)| 100.0 * o / n);
        target(&format!("{}: converged to 1e-10, % >= 99.5", robot.name), converged, 99.5, true);
    }
    s
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;
    use crate::read::{ClosedIk, NumericIk, test_row};

    const PAIR: &str = "k_all_f64/generated_all_f64";

    #[test]
    fn the_worst_robot_is_the_lowest_or_the_highest_and_nan_is_worst_of_all() {
        let rows = [test_row("a", &[], &[(PAIR, 7.0)]), test_row("b", &[], &[(PAIR, 5.0)]), test_row("c", &[], &[])];
        assert_eq!(worst_paired(&rows, PAIR, true), Some((5.0, "b".to_owned())));
        assert_eq!(worst_paired(&rows, PAIR, false), Some((7.0, "a".to_owned())));
        assert_eq!(worst_paired(&rows, "x/y", true), None);
        for order in [[0, 1], [1, 0]] {
            let with_nan = [test_row("n", &[], &[(PAIR, f64::NAN)]), test_row("b", &[], &[(PAIR, 5.0)])];
            let rows = order.map(|i| with_nan[i].clone());
            let (v, robot) = worst_paired(&rows, PAIR, true).unwrap();
            assert!(v.is_nan() && robot == "n", "{order:?}");
        }
    }

    #[test]
    fn every_robot_must_meet_the_bound() {
        let rows = [test_row("a", &[], &[(PAIR, 7.0)]), test_row("b", &[], &[(PAIR, 5.0)])];
        assert_eq!(every_robot(&rows, PAIR, 5.0, true), Some(("worst 5.00 (b; 2 robots, paired)".to_owned(), true)));
        assert_eq!(every_robot(&rows, PAIR, 6.0, true).map(|(_, met)| met), Some(false));
        assert_eq!(every_robot(&rows, PAIR, 7.0, false).map(|(_, met)| met), Some(true));
        assert!(!at_least(f64::NAN, 0.0) && !at_most(f64::NAN, 1e300));
        // Named robots only: "b" is not one of them.
        let named = [test_row("ur5", &[], &[(PAIR, 7.0)]), test_row("b", &[], &[(PAIR, 1.0)])];
        assert_eq!(named_robots(&named, PAIR, 6.0, true).map(|(_, met)| met), Some(true));
    }

    #[test]
    fn a_target_is_read_from_the_build_it_names() {
        let run = |name| Run {
            name,
            build: String::new(),
            dir: PathBuf::new(),
            rows: vec![test_row("ur5", &[("batch1024_f64", 12.0)], &[("std_pose_f64/generated_pose_f64", 2.2)])],
        };
        let mut s = String::new();
        targets(&mut s, &[run("plain")]);
        assert!(s.contains("| UR5 pose f64 scalar >= 2x faster than the std-trig pose (paired), plain build | plain | 2.20x | yes |\n"), "{s}");
        assert!(s.contains("native | not measured | - |\n"), "{s}");
        // Not met on the native build (2.5x wanted); the batch target is.
        let mut s = String::new();
        targets(&mut s, &[run("native")]);
        assert!(s.contains("(paired), native | native | 2.20x | **no** |\n"), "{s}");
        assert!(s.contains("native | native | 12.00 ns | yes |\n"), "{s}");
    }

    #[test]
    fn ik_targets_show_two_decimals_and_n_a_without_a_figure() {
        let ik = Ik {
            closed: vec![ClosedIk { name: "UR5", all: Some(400.0), nearest: Some(500.0), solver: None }],
            numeric: vec![NumericIk {
                name: "Panda",
                ours: Some(1.0),
                k: Some(20.0),
                success: Some((499.0, 1.0, 500.0)),
            }],
            ik_geo: "| UR5 | 1 | 2 | 3 | 4.5 | 3.9 |\n".to_owned(),
        };
        let s = ik_targets(&ik);
        assert!(s.contains("| UR5: ik-geo / our solver >= 4 | 3.90 | no |\n"), "{s}");
        assert!(s.contains("| UR5: ik-geo / our tip_ik (with errors) >= 4 | 4.50 | yes |\n"), "{s}");
        assert!(s.contains("| IRB 120: ik-geo / our solver >= 4 | n/a | n/a |\n"), "{s}");
        assert!(s.contains("| UR5: nearest / all <= 1.2 | 1.25 | no |\n"), "{s}");
        assert!(s.contains("| Panda: k / ours per solve >= 10 | 20.00 | yes |\n"), "{s}");
        assert!(s.contains("| Panda: converged to 1e-10, % >= 99.5 | 99.80 | yes |\n"), "{s}");
    }
}
