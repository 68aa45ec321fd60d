//! The inverse kinematics section: the medians of `cargo bench --bench ik` (closed forms: every
//! solution, the nearest, the family solver alone; the numeric solver and `k`'s Jacobian IK with
//! their success rates) and the paired table `benches/ik-geo/RESULTS.md` that
//! `bash benches/ik-geo/run.sh` writes (IK-Geo's crate on the same poses). The IK targets follow
//! it, from `crate::targets::ik_targets`.

use std::fmt::Write as _;

use super::fmt;
use crate::read::{Ik, ratio};

/// The section's heading and tables, or a line saying the IK benchmark has no results.
pub fn ik_section(ik: Option<&Ik>) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\n## Inverse kinematics (plain build)\n\n\
         From `cargo bench --bench ik` (criterion medians, ns per call; random configurations within the limits,\n\
         their poses as targets) and `bash benches/ik-geo/run.sh` (IK-Geo's Rust crate `ik-geo` 0.1.2 on the same\n\
         geometry and poses, timed in pairs; its own crate, since it builds nlopt with cmake).\n"
    );
    let Some(ik) = ik else {
        let _ = writeln!(s, "No results: run `cargo bench --bench ik`.");
        return s;
    };
    let _ = writeln!(
        s,
        "| robot | every solution (`tip_ik`) | nearest (`tip_ik_nearest`) | family solver alone | nearest / all |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|");
    for robot in &ik.closed {
        let (all, nearest, solver) = (robot.all, robot.nearest, robot.solver);
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} |",
            robot.name,
            fmt(all),
            fmt(nearest),
            fmt(solver),
            fmt(ratio(nearest, all))
        );
    }
    let _ = writeln!(
        s,
        "\nThe difference between `tip_ik` and the solver is measuring each solution's errors with the generated\n\
         forward kinematics (eight poses).\n\n\
         | robot | numeric solve | k Jacobian IK | k / ours | converged to 1e-10 (ours) | converged (k, same tolerance) |\n\
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
            fmt(ratio(k, ours))
        );
    }
    if ik.ik_geo.is_empty() {
        let _ = writeln!(s, "\nNo ik-geo results: run `bash benches/ik-geo/run.sh`.");
    } else {
        let _ = writeln!(s, "\nAgainst `ik-geo` (from `benches/ik-geo/RESULTS.md`, paired):\n\n{}", ik.ik_geo);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::read::{ClosedIk, NumericIk};

    #[test]
    fn without_results_the_section_says_which_command_to_run() {
        let s = ik_section(None);
        assert!(s.starts_with("\n## Inverse kinematics (plain build)\n"));
        assert!(s.ends_with("\nNo results: run `cargo bench --bench ik`.\n"));
    }

    #[test]
    fn closed_and_numeric_rows() {
        let ik = Ik {
            closed: vec![ClosedIk { name: "UR5", all: Some(400.0), nearest: Some(440.0), solver: Some(300.0) }],
            numeric: vec![NumericIk {
                name: "Panda",
                ours: Some(25_000.0),
                k: None,
                success: Some((499.0, 300.0, 500.0)),
            }],
            ik_geo: String::new(),
        };
        let s = ik_section(Some(&ik));
        assert!(s.contains("\n| UR5 | 400 | 440 | 300 | 1.10 |\n"), "{s}");
        assert!(s.contains("\n| Panda | 25.0 us | n/a | n/a | 99.8% (499 of 500) | 60.0% (300 of 500) |\n"), "{s}");
        assert!(s.ends_with("\nNo ik-geo results: run `bash benches/ik-geo/run.sh`.\n"), "{s}");
    }
}
