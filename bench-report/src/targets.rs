//! Targets: the issues' speed targets, each stated for a build (`plain`, `native`, `any`, the plain
//! build judged with the native one listed beside it, or the two builds together), with the
//! figure measured in that build's results and whether it is met; then the inverse kinematics
//! targets. A target that has no figure yet says `not measured` (or `n/a`), never met. NaN is the
//! worst figure of all and meets no bound. A figure with no stated bound is reported, not judged.

use std::fmt::Write as _;

use crate::read::{DISPATCH_PAIR, Ik, IkGeoRow, Row, Run, dispatch_ns, plain_over_native, ratio};

/// A measured figure as the table shows it, and whether it meets the target; `None` when it was
/// not measured.
type Judged = Option<(String, bool)>;

/// How a target's figure is measured.
enum Measure {
    /// From one build's rows.
    One(fn(&[Row]) -> Judged),
    /// From one build's rows, with no bound to meet: the figure only.
    Report(fn(&[Row]) -> Option<String>),
    /// From the plain build's rows (first) and the native build's together.
    Builds(fn(&[Row], &[Row]) -> Judged),
}

/// One of the issues' targets.
struct Target {
    what: &'static str,
    /// The build the target is stated for.
    build: Build,
    measure: Measure,
}

/// The build a target is stated for.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Build {
    /// The plain build alone.
    Plain,
    /// The native build (`-C target-cpu=native`) alone.
    Native,
    /// Every build that was run, each judged.
    Any,
    /// The plain build judged, the native build's figure listed beside it (not judged).
    NativeListed,
    /// The plain build against the native one: a [`Measure::Builds`] target, one line.
    PlainOverNative,
}

impl Build {
    /// The table's lines for this target: the runs it reads, as the `build` column names them.
    fn lines(self) -> &'static [&'static str] {
        match self {
            Build::Plain => &["plain"],
            Build::Native => &["native"],
            Build::Any | Build::NativeListed => &["plain", "native"],
            Build::PlainOverNative => &["plain / native"],
        }
    }
}

/// A stated bound on a figure. NaN and infinities meet none.
#[derive(Clone, Copy)]
enum Bound {
    /// Higher is better: at least this.
    AtLeast(f64),
    /// Lower is better: at most this.
    AtMost(f64),
}

impl Bound {
    fn met(self, v: f64) -> bool {
        v.is_finite()
            && match self {
                Bound::AtLeast(bound) => v >= bound,
                Bound::AtMost(bound) => v <= bound,
            }
    }

    /// Whether the worst figure is the lowest.
    fn lowest_is_worst(self) -> bool {
        matches!(self, Bound::AtLeast(_))
    }
}

/// The worst (`lowest` when higher is better, else highest) of `figures` (value, robot): `None`
/// when there are none. NaN is the worst of all: once found, it stays.
fn worst(figures: impl IntoIterator<Item = (f64, String)>, lowest: bool) -> Option<(f64, String)> {
    let mut worst: Option<(f64, String)> = None;
    for (v, robot) in figures {
        let replace = match &worst {
            None => true,
            Some((w, _)) => !w.is_nan() && (v.is_nan() || if lowest { v < *w } else { v > *w }),
        };
        if replace {
            worst = Some((v, robot));
        }
    }
    worst
}

/// The worst of pair `name` over the robots that have it, with that robot (see [`worst`]).
fn worst_paired(rows: &[Row], name: &str, lowest: bool) -> Option<(f64, String)> {
    worst(rows.iter().filter_map(|r| Some((*r.paired.get(name)?, r.group.clone()))), lowest)
}

/// [`every_robot`] over the UR5, the Panda and the iiwa 14 only (the robots the velocity targets
/// name; the others are in the tables).
fn named_robots(rows: &[Row], name: &str, bound: Bound) -> Option<(String, bool)> {
    let named: Vec<Row> =
        rows.iter().filter(|r| ["ur5", "panda", "iiwa14"].contains(&r.group.as_str())).cloned().collect();
    every_robot(&named, name, bound)
}

fn ur5(rows: &[Row]) -> Option<&Row> {
    rows.iter().find(|r| r.group == "ur5")
}

/// "the worst robot's figure (robot)", met when every robot meets `bound`.
fn every_robot(rows: &[Row], name: &str, bound: Bound) -> Option<(String, bool)> {
    let (v, robot) = worst_paired(rows, name, bound.lowest_is_worst())?;
    let count = rows.iter().filter(|r| r.paired.contains_key(name)).count();
    Some((format!("worst {v:.2} ({robot}; {count} robots, paired)"), bound.met(v)))
}

/// Robot `group`'s plain median of `variant` over its native median (two runs, not paired), at
/// most `bound`, NaN failing.
fn within_native(plain: &[Row], native: &[Row], group: &str, variant: &str, bound: f64) -> Option<(String, bool)> {
    let median = |rows: &[Row]| rows.iter().find(|r| r.group == group)?.ns.get(variant).copied();
    let (p, n) = (median(plain)?, median(native)?);
    let v = p / n;
    Some((format!("{v:.2} ({p:.1} ns / {n:.1} ns, medians of two runs)"), Bound::AtMost(bound).met(v)))
}

/// The worst (highest) plain median of `variant` over the native median among the robots both
/// runs timed, at most `bound`, NaN failing.
fn every_robot_within_native(plain: &[Row], native: &[Row], variant: &str, bound: f64) -> Option<(String, bool)> {
    let ratios: Vec<(f64, String)> = plain
        .iter()
        .filter_map(|r| Some((plain_over_native(plain, native, &r.group, variant)?, r.group.clone())))
        .collect();
    let count = ratios.len();
    let (v, robot) = worst(ratios, false)?;
    Some((format!("worst {v:.2} ({robot}; {count} robots, medians of two runs)"), Bound::AtMost(bound).met(v)))
}

/// The dispatch pair and the cost per call it gives ([`dispatch_ns`]) of every robot that has it,
/// the smallest robot of the run (fewest degrees of freedom, the first of equals) named first, or
/// said to be not measured: `None` when no robot has the pair.
fn dispatch_cost(rows: &[Row]) -> Option<String> {
    let measured: Vec<(&Row, f64)> = rows.iter().filter_map(|r| Some((r, *r.paired.get(DISPATCH_PAIR)?))).collect();
    if measured.is_empty() {
        return None;
    }
    let smallest = rows.iter().min_by_key(|r| r.dof)?;
    let figure = |r: &Row, v: f64| {
        let ns = dispatch_ns(r).map_or("n/a".to_owned(), |ns| format!("{ns:.2} ns"));
        format!("{v:.2}x, {ns}")
    };
    let others: Vec<String> = measured
        .iter()
        .filter(|(r, _)| r.group != smallest.group)
        .map(|&(r, v)| format!("{} {}", r.group, figure(r, v)))
        .collect();
    let others = if others.is_empty() { "none".to_owned() } else { others.join("; ") };
    let first = smallest.paired.get(DISPATCH_PAIR).map_or("not measured".to_owned(), |&v| figure(smallest, v));
    Some(format!("smallest: {} ({} DoF) {first}; others: {others}", smallest.group, smallest.dof))
}

/// The issues' forward kinematics targets, in the order the table shows them: the previous
/// issue's, then issue 22's (native speed from a plain build).
const TARGETS: [Target; 27] = [
    Target {
        what: "UR5, Panda, iiwa: pose + Jacobian of the tip at most 1.6x the pose alone (paired)",
        build: Build::Any,
        measure: Measure::One(|rows| {
            named_robots(rows, "generated_pose_and_jacobian_f64/generated_pose_f64", Bound::AtMost(1.6))
        }),
    },
    Target {
        what: "UR5, Panda, iiwa: pose + Jacobian at least 8x faster than the runtime Jacobian (paired)",
        build: Build::Any,
        measure: Measure::One(|rows| {
            named_robots(rows, "runtime_jacobian_f64/generated_pose_and_jacobian_f64", Bound::AtLeast(8.0))
        }),
    },
    Target {
        what: "UR5, Panda, iiwa: the twist cheaper than forming J and multiplying (paired ratio > 1)",
        build: Build::Any,
        measure: Measure::One(|rows| {
            named_robots(rows, "jacobian_times_qd_f64/generated_twist_f64", Bound::AtLeast(1.0))
        }),
    },
    Target {
        what: "UR5 pose f64 scalar >= 2.5x faster than the std-trig pose (paired), native",
        build: Build::Native,
        measure: Measure::One(|rows| {
            let v = *ur5(rows)?.paired.get("std_pose_f64/generated_pose_f64")?;
            Some((format!("{v:.2}x"), Bound::AtLeast(2.5).met(v)))
        }),
    },
    Target {
        what: "UR5 pose f64 scalar >= 2x faster than the std-trig pose (paired), plain build",
        build: Build::Plain,
        measure: Measure::One(|rows| {
            let v = *ur5(rows)?.paired.get("std_pose_f64/generated_pose_f64")?;
            Some((format!("{v:.2}x"), Bound::AtLeast(2.0).met(v)))
        }),
    },
    Target {
        what: "all link poses f64, every robot: >= 6x faster than `k` (URDF robots)",
        build: Build::Any,
        measure: Measure::One(|rows| every_robot(rows, "k_all_f64/generated_all_f64", Bound::AtLeast(6.0))),
    },
    Target {
        what: "all link poses f64, every robot: >= 3x faster than galaw (URDF robots)",
        build: Build::Any,
        measure: Measure::One(|rows| every_robot(rows, "galaw_all_f64/generated_all_f64", Bound::AtLeast(3.0))),
    },
    Target {
        what: "all link poses f64, every robot: >= 4x faster than the runtime",
        build: Build::Any,
        measure: Measure::One(|rows| every_robot(rows, "runtime_all_f64/generated_all_f64", Bound::AtLeast(4.0))),
    },
    Target {
        what: "batch of 1,024 UR5 poses f64: <= 16 ns per configuration (criterion median), native",
        build: Build::Native,
        measure: Measure::One(|rows| {
            let v = *ur5(rows)?.ns.get("batch1024_f64")?;
            Some((format!("{v:.2} ns"), Bound::AtMost(16.0).met(v)))
        }),
    },
    Target {
        what: "batch of 1,024 UR5 poses f32: <= 8 ns per configuration (criterion median), native",
        build: Build::Native,
        measure: Measure::One(|rows| {
            let v = *ur5(rows)?.ns.get("batch1024_f32")?;
            Some((format!("{v:.2} ns"), Bound::AtMost(8.0).met(v)))
        }),
    },
    Target {
        what: "rayon on 2 cores >= 1.8x over one thread (UR5, 16,384 configurations, paired)",
        build: Build::Any,
        measure: Measure::One(|rows| {
            let v = *ur5(rows)?.paired.get("batch16384_f64/parallel_batch16384_f64")?;
            Some((format!("{v:.2}x"), Bound::AtLeast(1.8).met(v)))
        }),
    },
    Target {
        what: "every body within 1.3x of the new floor: pose f64 / floor",
        build: Build::Any,
        measure: Measure::One(|rows| every_robot(rows, "generated_pose_f64/floor_f64", Bound::AtMost(1.3))),
    },
    Target {
        what: "every body within 1.3x of the new floor: all links f64 / floor all",
        build: Build::Any,
        measure: Measure::One(|rows| every_robot(rows, "generated_all_f64/floor_all_f64", Bound::AtMost(1.3))),
    },
    Target {
        what: "every body within 1.3x of the new floor: pose f32 / floor f32",
        build: Build::Any,
        measure: Measure::One(|rows| every_robot(rows, "generated_pose_f32/floor_f32", Bound::AtMost(1.3))),
    },
    Target {
        what: "every body within 1.3x of the new floor: lanes f64x4 and f32x8 / their floors",
        build: Build::Any,
        measure: Measure::One(|rows| {
            let (a, ra) = every_robot(rows, "lanes_pose_f64x4/floor_f64x4", Bound::AtMost(1.3))?;
            let (b, rb) = every_robot(rows, "lanes_pose_f32x8/floor_f32x8", Bound::AtMost(1.3))?;
            Some((format!("f64x4 {a}; f32x8 {b}"), ra && rb))
        }),
    },
    Target {
        what: "f32 about twice as fast as f64 in lanes (read as >= 1.8x per configuration, paired, UR5)",
        build: Build::Any,
        measure: Measure::One(|rows| {
            let r = ur5(rows)?;
            let lanes = *r.paired.get("lanes_pose_f64x4/lanes_pose_f32x8")?;
            let batch = *r.paired.get("batch1024_f64/batch1024_f32")?;
            Some((
                format!("lanes {lanes:.2}x, batches {batch:.2}x"),
                Bound::AtLeast(1.8).met(lanes) && Bound::AtLeast(1.8).met(batch),
            ))
        }),
    },
    Target {
        what: "issue 22: UR5 pose f64, plain build within 1.1x of native (plain median / native median)",
        build: Build::PlainOverNative,
        measure: Measure::Builds(|plain, native| within_native(plain, native, "ur5", "generated_pose_f64", 1.1)),
    },
    Target {
        what: "issue 22: Panda pose f64, plain build within 1.1x of native (plain median / native median)",
        build: Build::PlainOverNative,
        measure: Measure::Builds(|plain, native| within_native(plain, native, "panda", "generated_pose_f64", 1.1)),
    },
    Target {
        what: "issue 22: Panda Jacobian f64, plain build within 1.1x of native (plain median / native median)",
        build: Build::PlainOverNative,
        measure: Measure::Builds(|plain, native| within_native(plain, native, "panda", "generated_jacobian_f64", 1.1)),
    },
    Target {
        what: "issue 22: all link poses f64, every robot: plain build within 1.1x of native (plain median / native median)",
        build: Build::PlainOverNative,
        measure: Measure::Builds(|plain, native| every_robot_within_native(plain, native, "generated_all_f64", 1.1)),
    },
    Target {
        what: "issue 22: all link poses f64, every robot: >= 2.2x faster than galaw's generated code (paired, URDF robots)",
        build: Build::NativeListed,
        measure: Measure::One(|rows| every_robot(rows, "galaw_all_f64/generated_all_f64", Bound::AtLeast(2.2))),
    },
    Target {
        what: "issue 22: all link poses f64, every robot: >= 7x faster than `k` (paired, URDF robots)",
        build: Build::NativeListed,
        measure: Measure::One(|rows| every_robot(rows, "k_all_f64/generated_all_f64", Bound::AtLeast(7.0))),
    },
    Target {
        what: "issue 22: batch of 1,024 UR5 poses f64: <= 12 ns per configuration (criterion median), plain build",
        build: Build::Plain,
        measure: Measure::One(|rows| {
            let v = *ur5(rows)?.ns.get("batch1024_f64")?;
            Some((format!("{v:.2} ns"), Bound::AtMost(12.0).met(v)))
        }),
    },
    Target {
        what: "issue 22: batch of 1,024 UR5 poses f32: <= 6 ns per configuration (criterion median), plain build",
        build: Build::Plain,
        measure: Measure::One(|rows| {
            let v = *ur5(rows)?.ns.get("batch1024_f32")?;
            Some((format!("{v:.2} ns"), Bound::AtMost(6.0).met(v)))
        }),
    },
    Target {
        what: "issue 22: every robot's batch f64 within 1.2x of its lane floor (paired)",
        build: Build::Any,
        measure: Measure::One(|rows| every_robot(rows, "batch1024_f64/floor_batch1024_f64", Bound::AtMost(1.2))),
    },
    Target {
        what: "issue 22: every robot's batch f32 within 1.2x of its lane floor (paired)",
        build: Build::Any,
        measure: Measure::One(|rows| every_robot(rows, "batch1024_f32/floor_batch1024_f32", Bound::AtMost(1.2))),
    },
    Target {
        what: "issue 22: dispatch cost, kept small (reported: `dispatch each / once`, paired, and ns per call)",
        build: Build::Any,
        measure: Measure::Report(dispatch_cost),
    },
];

/// The targets table, appended to `s`: one line per target and build it applies to.
pub fn targets(s: &mut String, runs: &[Run]) {
    let _ = writeln!(s, "## Targets\n");
    let _ = writeln!(
        s,
        "The issues' targets (the previous issue's, then issue 22's), each from the build it names (`any`: every\n\
         build that was run, each judged; `plain, native listed`: the plain build judged, the native build's figure\n\
         listed beside it; `plain / native`: the plain build's criterion median over the native build's, two\n\
         separate runs, not paired, so noisier), with the figure measured and whether it is met. Other ratios are\n\
         paired (above); the batch figures are criterion medians per configuration. `report` marks a figure with\n\
         no stated bound. `not measured` means that build (or that body) has no results yet.\n"
    );
    let _ = writeln!(s, "| target | build | measured | met |");
    let _ = writeln!(s, "|---|---|---|---|");
    let rows = |name: &str| runs.iter().find(|r| r.name == name).map(|r| r.rows.as_slice());
    let not_measured = || ("not measured".to_owned(), "-");
    for target in &TARGETS {
        for &build in target.build.lines() {
            let judged = |m: Option<(String, bool)>| {
                m.map_or_else(not_measured, |(figure, met)| {
                    let listed = target.build == Build::NativeListed && build == "native";
                    (
                        figure,
                        match (met, listed) {
                            (true, false) => "yes",
                            (false, false) => "**no**",
                            (true, true) => "yes (listed)",
                            (false, true) => "no (listed)",
                        },
                    )
                })
            };
            let (figure, met) = match target.measure {
                Measure::One(measure) => judged(rows(build).and_then(measure)),
                Measure::Builds(measure) => judged(rows("plain").zip(rows("native")).and_then(|(p, n)| measure(p, n))),
                Measure::Report(measure) => {
                    rows(build).and_then(measure).map_or_else(not_measured, |figure| (figure, "report"))
                }
            };
            let _ = writeln!(s, "| {} | {build} | {figure} | {met} |", target.what);
        }
    }
}

/// Numeric solves with a bound on their time (us a solve, the benchmark's median): issue 32's, a
/// tenth of the 200 us OptIK's SLSQP takes on the Panda by its own protocol.
const NUMERIC_SOLVE_BOUNDS: [(&str, f64); 1] = [("Panda", 20.0)];

/// The issue's IK targets, as a table: IK-Geo over ours for the closed forms (from the ik-geo
/// table), nearest over all, and the numeric solver's speed (where bounded), its speed over `k`'s
/// and its success rate.
pub fn ik_targets(ik: &Ik) -> String {
    let mut s = String::new();
    // A blank line first: the IK part's last table ends just before.
    let _ = writeln!(s, "\n### IK targets\n\n| target | measured | met |\n|---|---|---|");
    let mut target = |what: &str, measured: Option<f64>, bound: Bound| {
        let met = measured.map(|m| bound.met(m));
        // Two decimals: a success rate of 99.8% must not read as 100.
        let shown = measured.map_or("n/a".to_owned(), |v| format!("{v:.2}"));
        let _ = writeln!(s, "| {what} | {shown} | {} |", met.map_or("n/a", |m| if m { "yes" } else { "no" }));
    };
    for (robot, bound) in [("UR5", 4.0), ("IRB 120", 4.0), ("PUMA 560", 4.0)] {
        let row = ik.ik_geo.iter().find(|r| r.robot == robot);
        let least = Bound::AtLeast(bound);
        target(&format!("{robot}: ik-geo / our solver >= {bound}"), row.map(|r: &IkGeoRow| r.over_solver), least);
        target(&format!("{robot}: ik-geo / our tip_ik (with errors) >= {bound}"), row.map(|r| r.over_tip_ik), least);
    }
    // Paired ratios where the benchmark timed them, else the medians' ratio.
    for robot in &ik.closed {
        let nearest_over_all = robot.paired.get("nearest/all").copied().or(ratio(robot.nearest, robot.all));
        target(&format!("{}: nearest / all <= 1.2", robot.name), nearest_over_all, Bound::AtMost(1.2));
        if let Some(&refined) = robot.paired.get("all/exactly-written-all") {
            let what = format!("{}: tip_ik / exactly written tip_ik <= 1.25", robot.name);
            target(&what, Some(refined), Bound::AtMost(1.25));
        }
    }
    for robot in &ik.numeric {
        if let Some(&(_, bound)) = NUMERIC_SOLVE_BOUNDS.iter().find(|(name, _)| *name == robot.name) {
            let us = robot.ours.map(|ns| ns / 1000.0);
            target(&format!("{}: numeric solve <= {bound} us", robot.name), us, Bound::AtMost(bound));
        }
        let k_over_ours = robot.paired.or(ratio(robot.k, robot.ours));
        target(&format!("{}: k / ours per solve >= 10", robot.name), k_over_ours, Bound::AtLeast(10.0));
        let converged = robot.success.map(|(o, _, n)| 100.0 * o / n);
        target(&format!("{}: converged to 1e-10, % >= 99.5", robot.name), converged, Bound::AtLeast(99.5));
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
        assert_eq!(
            every_robot(&rows, PAIR, Bound::AtLeast(5.0)),
            Some(("worst 5.00 (b; 2 robots, paired)".to_owned(), true))
        );
        assert_eq!(every_robot(&rows, PAIR, Bound::AtLeast(6.0)).map(|(_, met)| met), Some(false));
        assert_eq!(every_robot(&rows, PAIR, Bound::AtMost(7.0)).map(|(_, met)| met), Some(true));
        assert!(!Bound::AtLeast(0.0).met(f64::NAN) && !Bound::AtMost(1e300).met(f64::NAN));
        assert!(!Bound::AtLeast(0.0).met(f64::INFINITY) && !Bound::AtMost(1e300).met(f64::NEG_INFINITY));
        // Named robots only: "b" is not one of them.
        let named = [test_row("ur5", &[], &[(PAIR, 7.0)]), test_row("b", &[], &[(PAIR, 1.0)])];
        assert_eq!(named_robots(&named, PAIR, Bound::AtLeast(6.0)).map(|(_, met)| met), Some(true));
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

    fn run(name: &'static str, rows: Vec<Row>) -> Run {
        Run { name, build: String::new(), dir: PathBuf::new(), rows }
    }

    /// The line of target `what` (its start) for `build` in the targets table of `runs`.
    fn line(runs: &[Run], what: &str, build: &str) -> String {
        let mut s = String::new();
        targets(&mut s, runs);
        let found = s.lines().find(|l| l.starts_with(&format!("| {what}")) && l.contains(&format!(" | {build} | ")));
        found.unwrap_or_else(|| panic!("no line for {what} ({build}) in\n{s}")).to_owned()
    }

    #[test]
    fn plain_against_native_needs_both_runs_names_the_worst_robot_and_nan_fails() {
        let plain = vec![
            test_row("ur5", &[("generated_pose_f64", 43.0), ("generated_all_f64", 50.0)], &[]),
            test_row("panda", &[("generated_pose_f64", 50.0), ("generated_jacobian_f64", 60.0)], &[]),
            test_row("humanoid", &[("generated_all_f64", 600.0)], &[]),
        ];
        let native = vec![
            test_row("ur5", &[("generated_pose_f64", 40.0), ("generated_all_f64", 49.0)], &[]),
            test_row("panda", &[("generated_pose_f64", f64::NAN), ("generated_jacobian_f64", 50.0)], &[]),
            test_row("humanoid", &[("generated_all_f64", 500.0)], &[]),
        ];
        let both = [run("plain", plain.clone()), run("native", native)];
        let ur5 = line(&both, "issue 22: UR5 pose f64", "plain / native");
        assert!(ur5.ends_with("| 1.07 (43.0 ns / 40.0 ns, medians of two runs) | yes |"), "{ur5}");
        assert!(line(&both, "issue 22: Panda pose f64", "plain / native").ends_with("| **no** |"));
        let jacobian = line(&both, "issue 22: Panda Jacobian f64", "plain / native");
        assert!(jacobian.ends_with("| 1.20 (60.0 ns / 50.0 ns, medians of two runs) | **no** |"), "{jacobian}");
        let all = line(&both, "issue 22: all link poses f64, every robot: plain build", "plain / native");
        assert!(all.ends_with("| worst 1.20 (humanoid; 2 robots, medians of two runs) | **no** |"), "{all}");
        // Without the native run, every one of them is not measured.
        let alone = [run("plain", plain)];
        for what in ["UR5 pose", "Panda pose", "Panda Jacobian", "all link poses f64, every robot: plain"] {
            let l = line(&alone, &format!("issue 22: {what}"), "plain / native");
            assert!(l.ends_with("| plain / native | not measured | - |"), "{l}");
        }
    }

    #[test]
    fn the_plain_build_is_judged_and_the_native_one_listed() {
        let rows = |galaw| vec![test_row("ur5", &[], &[("galaw_all_f64/generated_all_f64", galaw)])];
        let runs = [run("plain", rows(2.5)), run("native", rows(2.0))];
        let what = "issue 22: all link poses f64, every robot: >= 2.2x faster than galaw";
        assert!(line(&runs, what, "plain").ends_with("| plain | worst 2.50 (ur5; 1 robots, paired) | yes |"));
        assert!(line(&runs, what, "native").ends_with("| native | worst 2.00 (ur5; 1 robots, paired) | no (listed) |"));
        // NaN fails the plain build; the k target has no pair: not measured.
        let runs = [run("plain", rows(f64::NAN))];
        assert!(line(&runs, what, "plain").ends_with("| **no** |"));
        assert!(line(&runs, what, "native").ends_with("| native | not measured | - |"));
        let k = "issue 22: all link poses f64, every robot: >= 7x faster than `k`";
        assert!(line(&runs, k, "plain").ends_with("| plain | not measured | - |"));
    }

    #[test]
    fn issue_22_batches_per_configuration_and_against_their_lane_floor() {
        let ns = [("batch1024_f64", 11.5), ("batch1024_f32", 6.5)];
        let pairs = [("batch1024_f64/floor_batch1024_f64", 1.15), ("batch1024_f32/floor_batch1024_f32", f64::NAN)];
        let runs = [run("plain", vec![test_row("ur5", &ns, &pairs), test_row("scara", &[], &pairs[..1])])];
        let f64_line = line(&runs, "issue 22: batch of 1,024 UR5 poses f64: <= 12 ns", "plain");
        assert!(f64_line.ends_with("| plain | 11.50 ns | yes |"), "{f64_line}");
        let f32_line = line(&runs, "issue 22: batch of 1,024 UR5 poses f32: <= 6 ns", "plain");
        assert!(f32_line.ends_with("| plain | 6.50 ns | **no** |"), "{f32_line}");
        let floor = line(&runs, "issue 22: every robot's batch f64 within 1.2x", "plain");
        assert!(floor.ends_with("| worst 1.15 (ur5; 2 robots, paired) | yes |"), "{floor}");
        let floor = line(&runs, "issue 22: every robot's batch f32 within 1.2x", "plain");
        assert!(floor.ends_with("| worst NaN (ur5; 1 robots, paired) | **no** |"), "{floor}");
        assert!(line(&runs, "issue 22: every robot's batch f32", "native").ends_with("| not measured | - |"));
    }

    #[test]
    fn dispatch_cost_is_reported_for_every_robot_smallest_first() {
        let mut scara = test_row("scara", &[("generated_pose_f64", 20.0)], &[(DISPATCH_PAIR, 1.1)]);
        scara.dof = 4;
        let mut planar = test_row("planar_2r", &[], &[(DISPATCH_PAIR, 1.5)]);
        planar.dof = 2;
        let rows = vec![
            test_row("ur5", &[("generated_pose_f64", 40.0)], &[(DISPATCH_PAIR, 1.05)]),
            scara,
            planar.clone(),
            test_row("humanoid", &[("generated_pose_f64", 40.0)], &[]),
        ];
        let expected = "smallest: planar_2r (2 DoF) 1.50x, n/a; others: ur5 1.05x, 2.00 ns; scara 1.10x, 2.00 ns";
        assert_eq!(dispatch_cost(&rows).as_deref(), Some(expected));
        assert_eq!(dispatch_cost(&rows[3..]), None);
        // The smallest robot is named even when it lacks the pair.
        let mut small = rows[3].clone();
        small.dof = 1;
        let expected_small = "smallest: humanoid (1 DoF) not measured; others: ur5 1.05x, 2.00 ns";
        assert_eq!(dispatch_cost(&[rows[0].clone(), small]).as_deref(), Some(expected_small));
        assert_eq!(dispatch_cost(&[planar]).as_deref(), Some("smallest: planar_2r (2 DoF) 1.50x, n/a; others: none"));
        // Reported, never judged; not measured in a build without it.
        let what = "issue 22: dispatch cost";
        let runs = [run("native", rows)];
        assert!(line(&runs, what, "native").ends_with(&format!("| native | {expected} | report |")));
        assert!(line(&runs, what, "plain").ends_with("| plain | not measured | - |"));
    }

    #[test]
    fn ik_targets_show_two_decimals_and_n_a_without_a_figure() {
        let ik = Ik {
            closed: vec![
                ClosedIk { name: "UR5", all: Some(400.0), nearest: Some(500.0), ..ClosedIk::default() },
                ClosedIk {
                    name: "IRB 120, as written",
                    paired: [("all/exactly-written-all".to_owned(), 1.2)].into_iter().collect(),
                    ..ClosedIk::default()
                },
            ],
            numeric: vec![NumericIk {
                name: "Panda",
                ours: Some(25_000.0),
                k: Some(500_000.0),
                success: Some((499.0, 1.0, 500.0)),
                paired: None,
            }],
            ik_geo: crate::read::ik_geo_rows("UR5\t1\t2\t3\t4.5\t3.9\t256\t256\n"),
        };
        let s = ik_targets(&ik);
        assert!(s.contains("| UR5: ik-geo / our solver >= 4 | 3.90 | no |\n"), "{s}");
        assert!(s.contains("| UR5: ik-geo / our tip_ik (with errors) >= 4 | 4.50 | yes |\n"), "{s}");
        assert!(s.contains("| IRB 120: ik-geo / our solver >= 4 | n/a | n/a |\n"), "{s}");
        assert!(s.contains("| UR5: nearest / all <= 1.2 | 1.25 | no |\n"), "{s}");
        // The refinement's cost only where it was timed.
        assert!(s.contains("| IRB 120, as written: tip_ik / exactly written tip_ik <= 1.25 | 1.20 | yes |\n"), "{s}");
        assert!(!s.contains("UR5: tip_ik / exactly written"), "{s}");
        assert!(s.contains("| Panda: numeric solve <= 20 us | 25.00 | no |\n"), "{s}");
        assert!(s.contains("| Panda: k / ours per solve >= 10 | 20.00 | yes |\n"), "{s}");
        assert!(s.contains("| Panda: converged to 1e-10, % >= 99.5 | 99.80 | yes |\n"), "{s}");
    }
}
