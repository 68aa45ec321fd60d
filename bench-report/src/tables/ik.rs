//! The inverse kinematics section: the medians of `cargo bench --bench ik` (closed forms: every
//! solution, the nearest, the compiled body on eight, four and one lanes, the pose on lanes, the
//! run-time family function; the compiled bodies' operation counts; the numeric solver and `k`'s
//! Jacobian IK with their success rates) and the paired table `benches/ik-geo/RESULTS.md` that
//! `bash benches/ik-geo/run.sh` writes (IK-Geo's crate on the same poses). The IK targets follow
//! it, from `crate::targets::ik_targets`.

use std::fmt::Write as _;

use super::fmt;
use crate::read::{IK_GEO_RECORD, Ik, IkGeoRow};

/// The line the inverse kinematics part starts with (after a blank line).
pub const IK_HEADING: &str = "\n## Inverse kinematics (plain build)\n";

/// The section's heading and tables, or a line saying the IK benchmark has no results. `machine`
/// is where it ran (`bench-report --ik` keeps forward kinematics sections measured elsewhere).
pub fn ik_section(ik: Option<&Ik>, machine: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{IK_HEADING}\n\
         From `cargo bench --bench ik` (criterion medians, ns per call; random configurations within the limits,\n\
         their poses as targets) and `bash benches/ik-geo/run.sh` (IK-Geo's Rust crate `ik-geo` 0.1.2 on the same\n\
         geometry and poses, timed in pairs; its own crate, since it builds nlopt with cmake), then\n\
         `cargo run -p bench-report -- --ik`. Machine: {machine}.\n"
    );
    let Some(ik) = ik else {
        let _ = writeln!(s, "No results: run `cargo bench --bench ik`.");
        return s;
    };
    let _ = writeln!(
        s,
        "| robot | every solution (`tip_ik`) | nearest (`tip_ik_nearest`) | compiled body, 8 lanes | 4 lanes, 2 calls | \
         scalar, 8 calls | pose at q, 8 lanes | run-time family function |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|");
    for r in &ik.closed {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} |",
            r.name,
            fmt(r.all),
            fmt(r.nearest),
            fmt(r.lanes8),
            fmt(r.lanes4),
            fmt(r.scalar),
            fmt(r.pose8),
            fmt(r.solver)
        );
    }
    let _ = writeln!(
        s,
        "\nPaired ratios (timed in alternation, the median of the rounds' ratios): the nearest solution against\n\
         all, the scalar loop and the four-lane body against the eight-lane one, and the run-time family function\n\
         against the compiled `tip_ik`; for the IRB 120 read with its half turns as written, its `tip_ik` (every\n\
         solution refined) against the exactly written IRB 120's on the same targets.\n\n\
         | robot | nearest / all | scalar / 8 lanes | 4 lanes / 8 lanes | family function / `tip_ik` | refined / exactly written |\n|---|---|---|---|---|---|"
    );
    for r in &ik.closed {
        let pair = |name: &str| r.paired.get(name).map_or("n/a".to_owned(), |v| format!("{v:.2}"));
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} |",
            r.name,
            pair("nearest/all"),
            pair("branches-scalar/branches-f64x8"),
            pair("branches-f64x4/branches-f64x8"),
            pair("solver/all"),
            pair("all/exactly-written-all")
        );
    }
    let _ = writeln!(
        s,
        "\n`tip_ik` is the compiled body on eight lanes, then every solution's pose at the cosines and sines the\n\
         body computed (no `sin_cos`), its errors against the target, and the eight solutions unpacked; the\n\
         quartic families' `tip_ik` calls the run-time family function instead. The run-time family function is\n\
         timed dispatched, as generated code calls it; for the other families it runs the same branch as the\n\
         compiled body (written once, `kinematics::ik::branch`) on numbers in eight lanes, with the arm's\n\
         geometry as values rather than folded constants, and measures nothing. The UR family's body has a pass\n\
         at the wrist's singularity (where `q6 = 0` leaves the elbow out of reach): `tip_ik` runs the body\n\
         without it, and the whole body only when a lane comes back singular and not exact; `compiled body`\n\
         above times the whole body (`tip_ik_branch_generic`). `pose at q` is what the measure would cost with\n\
         `sin_cos`. Every exact solution farther than 1e-14 x reach from its target is then refined in lanes on\n\
         the generated pose and Jacobian: every solution of the IRB 120 read with its half turns as written\n\
         (`tests/arms/irb120_half_turns.urdf`, measured by its pose and Jacobian, one step in every lane and the\n\
         pose again: `IkSolutions::from_lanes_refined`), and quartic families' solutions near their singularity\n\
         (`IkSolutions::refined`); the other arms' solutions are within rounding and cost a comparison each. Operations per\n\
         branch (one per lane),\n\
         `sin_cos/mul/add/div/sqrt/atan2/select`, from `kinematics expr --ik`:\n\n\
         | robot | body `tip_ik` runs | whole body, with the singular pass | measure |\n|---|---|---|---|"
    );
    for r in &ik.closed {
        if let Some(ops) = &r.ops {
            let whole = ops.with_pass.as_deref().unwrap_or("the same");
            let _ = writeln!(s, "| {} | {} | {whole} | {} |", r.name, ops.body, ops.measure);
        }
    }
    let _ = writeln!(
        s,
        "\n| robot | numeric solve | k Jacobian IK | k / ours (paired) | converged to 1e-10 (ours) | converged (k, same tolerance) |\n\
         |---|---|---|---|---|---|"
    );
    for robot in &ik.numeric {
        let (ours, k) = (robot.ours, robot.k);
        let rate = |n: f64, of: f64| format!("{:.1}% ({n:.0} of {of:.0})", 100.0 * n / of);
        let (ours_rate, k_rate) =
            robot.success.map_or(("n/a".to_owned(), "n/a".to_owned()), |(o, k, n)| (rate(o, n), rate(k, n)));
        let us = |x: Option<f64>| x.map_or("n/a".to_owned(), |v| format!("{:.1} us", v / 1000.0));
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {ours_rate} | {k_rate} |",
            robot.name,
            us(ours),
            us(k),
            robot.paired.map_or("n/a".to_owned(), |v| format!("{v:.2}"))
        );
    }
    ik_geo_table(&mut s, &ik.ik_geo);
    s
}

/// The comparison with ik-geo, from its record (see `benches/ik-geo/RESULTS.md` for how it is
/// timed and what agrees).
fn ik_geo_table(s: &mut String, rows: &[IkGeoRow]) {
    if rows.is_empty() {
        let _ = writeln!(s, "\nNo ik-geo results: run `bash benches/ik-geo/run.sh`.");
        return;
    }
    let _ = writeln!(
        s,
        "\nAgainst `ik-geo` (from `benches/ik-geo/run.sh`'s record, `{IK_GEO_RECORD}`; medians, then paired \
         ratios):\n\n\
         | robot | ik-geo ns | ours tip_ik ns | ours solver ns | ik-geo / tip_ik | ik-geo / solver | exact solutions \
         equal on N poses |\n|---|---:|---:|---:|---:|---:|---:|"
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {:.0} | {:.0} | {:.0} | {:.2} | {:.2} | {} / {} |",
            r.robot, r.ik_geo_ns, r.tip_ik_ns, r.solver_ns, r.over_tip_ik, r.over_solver, r.equal, r.poses
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::read::{ClosedIk, IkOps, NumericIk};

    #[test]
    fn without_results_the_section_says_which_command_to_run() {
        let s = ik_section(None, "a machine");
        assert!(s.starts_with("\n## Inverse kinematics (plain build)\n"));
        assert!(s.ends_with("\nNo results: run `cargo bench --bench ik`.\n"));
    }

    #[test]
    fn closed_and_numeric_rows() {
        let ik = Ik {
            closed: vec![ClosedIk {
                name: "UR5",
                all: Some(400.0),
                nearest: Some(440.0),
                solver: Some(300.0),
                lanes8: Some(200.0),
                lanes4: None,
                scalar: Some(800.0),
                pose8: Some(250.0),
                ops: Some(IkOps {
                    body: "0/1/2/3/4/5/6".to_owned(),
                    with_pass: Some("0/2/3/4/5/6/7".to_owned()),
                    measure: "0/7/8/0/0/0/0".to_owned(),
                }),
                paired: [("nearest/all".to_owned(), 1.1), ("all/exactly-written-all".to_owned(), 2.345)]
                    .into_iter()
                    .collect(),
            }],
            numeric: vec![NumericIk {
                name: "Panda",
                ours: Some(25_000.0),
                k: None,
                success: Some((499.0, 300.0, 500.0)),
                paired: None,
            }],
            ik_geo: Vec::new(),
        };
        let s = ik_section(Some(&ik), "a machine");
        assert!(s.contains("\n| UR5 | 400 | 440 | 200 | n/a | 800 | 250 | 300 |\n"), "{s}");
        assert!(s.contains("\n| UR5 | 1.10 | n/a | n/a | n/a | 2.35 |\n"), "{s}");
        assert!(s.contains("\n| UR5 | 0/1/2/3/4/5/6 | 0/2/3/4/5/6/7 | 0/7/8/0/0/0/0 |\n"), "{s}");
        assert!(s.contains("\n| Panda | 25.0 us | n/a | n/a | 99.8% (499 of 500) | 60.0% (300 of 500) |\n"), "{s}");
        assert!(s.ends_with("\nNo ik-geo results: run `bash benches/ik-geo/run.sh`.\n"), "{s}");
    }
}
