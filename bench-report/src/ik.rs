//! The inverse kinematics section of `benches/SUMMARY.md`: the medians of `cargo bench --bench
//! ik` (closed forms: every solution, the nearest, the family solver alone; the numeric solver
//! and `k`'s Jacobian IK with their success rates from `kinematics-ik.tsv`), the paired table
//! `benches/ik-geo/RESULTS.md` that `bash benches/ik-geo/run.sh` writes (IK-Geo's crate on the
//! same poses), and the IK targets against them.

use std::fmt::Write as _;
use std::path::Path;

use crate::{fmt, median_ns, ratio};

/// The closed-form robots of the benchmark, as it names its groups (`ik-<name>`).
const CLOSED: [(&str, &str); 3] = [("ur5", "UR5"), ("irb120", "IRB 120"), ("puma560", "PUMA 560")];
/// The numeric robots.
const NUMERIC: [(&str, &str); 2] = [("panda", "Panda"), ("iiwa14", "iiwa 14")];

/// One numeric robot's success counts (`robot, ours, k, targets`), as the benchmark wrote them.
fn success(criterion: &Path, robot: &str) -> Option<(f64, f64, f64)> {
    let text = std::fs::read_to_string(criterion.join("kinematics-ik.tsv")).ok()?;
    text.lines().find_map(|line| {
        let cells: Vec<&str> = line.split('\t').collect();
        match cells[..] {
            [name, ours, k, count] if name == robot => Some((ours.parse().ok()?, k.parse().ok()?, count.parse().ok()?)),
            _ => None,
        }
    })
}

/// A ratio cell of the ik-geo table for `robot` (column `column`, 0-based after the robot's name).
fn ik_geo_cell(table: &str, robot: &str, column: usize) -> Option<f64> {
    let line = table.lines().find(|l| l.starts_with(&format!("| {robot} |")))?;
    line.split('|').map(str::trim).filter(|c| !c.is_empty()).nth(column + 1)?.parse().ok()
}

/// The section, or a line saying which results are missing.
pub fn section(root: &Path, criterion: &Path) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\n## Inverse kinematics (plain build)\n\n\
         From `cargo bench --bench ik` (criterion medians, ns per call; random configurations within the limits,\n\
         their poses as targets) and `bash benches/ik-geo/run.sh` (IK-Geo's Rust crate `ik-geo` 0.1.2 on the same\n\
         geometry and poses, timed in pairs; its own crate, since it builds nlopt with cmake).\n"
    );
    if median_ns(criterion, "ik-ur5", "all").is_none() {
        let _ = writeln!(s, "No results: run `cargo bench --bench ik`.");
        return s;
    }
    let _ = writeln!(
        s,
        "| robot | every solution (`tip_ik`) | nearest (`tip_ik_nearest`) | family solver alone | nearest / all |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|");
    for (group, name) in CLOSED {
        let group = format!("ik-{group}");
        let [all, nearest, solver] = ["all", "nearest", "solver"].map(|v| median_ns(criterion, &group, v));
        let _ = writeln!(
            s,
            "| {name} | {} | {} | {} | {} |",
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
    for (group, name) in NUMERIC {
        let g = format!("ik-{group}");
        let (ours, k) = (median_ns(criterion, &g, "numeric"), median_ns(criterion, &g, "k-jacobian-ik"));
        let rate = |n: f64, of: f64| format!("{:.1}% ({n:.0} of {of:.0})", 100.0 * n / of);
        let (ours_rate, k_rate) = success(criterion, group)
            .map_or(("n/a".to_owned(), "n/a".to_owned()), |(o, k, n)| (rate(o, n), rate(k, n)));
        let us = |x: Option<f64>| x.map_or("n/a".to_owned(), |v| format!("{:.1} us", v / 1000.0));
        let _ = writeln!(s, "| {name} | {} | {} | {} | {ours_rate} | {k_rate} |", us(ours), us(k), fmt(ratio(k, ours)));
    }
    let ik_geo = std::fs::read_to_string(root.join("benches/ik-geo/RESULTS.md")).unwrap_or_default();
    let table: String = ik_geo.lines().filter(|l| l.starts_with('|')).map(|l| format!("{l}\n")).collect();
    if table.is_empty() {
        let _ = writeln!(s, "\nNo ik-geo results: run `bash benches/ik-geo/run.sh`.");
    } else {
        let _ = writeln!(s, "\nAgainst `ik-geo` (from `benches/ik-geo/RESULTS.md`, paired):\n\n{table}");
    }
    // The targets.
    let _ = writeln!(s, "### IK targets\n\n| target | measured | met |\n|---|---|---|");
    let mut target = |what: &str, measured: Option<f64>, bound: f64, at_least: bool| {
        let met = measured.map(|m| if at_least { m >= bound } else { m <= bound });
        // Two decimals: a success rate of 99.8% must not read as 100.
        let shown = measured.map_or("n/a".to_owned(), |v| format!("{v:.2}"));
        let _ = writeln!(s, "| {what} | {shown} | {} |", met.map_or("n/a", |m| if m { "yes" } else { "no" }));
    };
    for (robot, bound) in [("UR5", 4.0), ("IRB 120", 4.0), ("PUMA 560", 4.0)] {
        target(&format!("{robot}: ik-geo / our solver >= {bound}"), ik_geo_cell(&table, robot, 4), bound, true);
        target(
            &format!("{robot}: ik-geo / our tip_ik (with errors) >= {bound}"),
            ik_geo_cell(&table, robot, 3),
            bound,
            true,
        );
    }
    for (group, name) in CLOSED {
        let g = format!("ik-{group}");
        let nearest = ratio(median_ns(criterion, &g, "nearest"), median_ns(criterion, &g, "all"));
        target(&format!("{name}: nearest / all <= 1.2"), nearest, 1.2, false);
    }
    for (group, name) in NUMERIC {
        let g = format!("ik-{group}");
        let (ours, k) = (median_ns(criterion, &g, "numeric"), median_ns(criterion, &g, "k-jacobian-ik"));
        target(&format!("{name}: k / ours per solve >= 10"), ratio(k, ours), 10.0, true);
        let converged = success(criterion, group).map(|(o, _, n)| 100.0 * o / n);
        target(&format!("{name}: converged to 1e-10, % >= 99.5"), converged, 99.5, true);
    }
    s
}
