//! Reading: criterion's medians (`<group>/<variant>/new/estimates.json`) and the records the
//! benchmarks leave beside them (`kinematics-robots.tsv`, `kinematics-build.tsv`,
//! `kinematics-paired.tsv`, `kinematics-ik.tsv`, and `benches/ik-geo`'s `kinematics-ik-geo.tsv`), the compiler's
//! operation counts of each robot, and the machine. Everything the report prints comes from here
//! as plain data ([`Run`], [`Row`], [`Ik`]); the other modules only format it, so they know
//! nothing of files and can be tested on values written in the test.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Any failure reading the results: a robot file, its parse or its compilation.
pub type Result<T> = std::result::Result<T, Box<dyn std::error::Error>>;

/// One robot's row of one run.
#[derive(Clone)]
pub struct Row {
    /// The benchmark's group name (`ur5`).
    pub group: String,
    /// The description's file name under `robots/`.
    pub file: String,
    /// The tip the tip bodies compute.
    pub tip: String,
    /// Degrees of freedom.
    pub dof: usize,
    /// The link poses `link_poses` returns (every link but the root).
    pub links: usize,
    /// The compiler's operation counts of the tip pose (`sin_cos/mul/add`).
    pub ops: String,
    /// The same for all link poses.
    pub ops_all: String,
    /// The same for the tip's Jacobian (`LOCAL_WORLD_ALIGNED`) and for the pose with it.
    pub ops_jacobian: String,
    pub ops_pose_and_jacobian: String,
    /// Median ns per configuration (per call for single-configuration bodies), by variant.
    pub ns: BTreeMap<&'static str, f64>,
    /// Ratios timed in alternation by the benchmark (`kinematics-paired.tsv`), by pair name.
    pub paired: BTreeMap<String, f64>,
}

/// One build's results.
pub struct Run {
    /// `plain` or `native`, the directory it was read from.
    pub name: &'static str,
    /// The benchmark's build record: its label and the vector features it was compiled with.
    pub build: String,
    /// The directory it was read from.
    pub dir: PathBuf,
    pub rows: Vec<Row>,
}

/// Every variant the benchmark times, and how many configurations one call computes (criterion's
/// median is per call; the tables show it per configuration).
const VARIANTS: [(&str, f64); 41] = [
    ("generated_jacobian_f64", 1.0),
    ("generated_pose_and_jacobian_f64", 1.0),
    ("runtime_jacobian_f64", 1.0),
    ("k_jacobian_f64", 1.0),
    ("generated_twist_f64", 1.0),
    ("generated_pose_f64", 1.0),
    ("generated_pose_f32", 1.0),
    ("generated_position_f64", 1.0),
    ("generated_all_f64", 1.0),
    ("generated_all_f32", 1.0),
    ("std_pose_f64", 1.0),
    ("std_all_f64", 1.0),
    ("lanes_pose_f64x4", 4.0),
    ("scalar4_pose_f64", 4.0),
    ("lanes_pose_f32x8", 8.0),
    ("scalar8_pose_f32", 8.0),
    ("generated_batch1024_f64", 1024.0),
    ("batch1024_f64", 1024.0),
    ("generated_batch1024_f32", 1024.0),
    ("batch1024_f32", 1024.0),
    ("batch16384_f64", 16384.0),
    ("parallel_batch16384_f64", 16384.0),
    ("runtime_pose_f64", 1.0),
    ("runtime_all_f64", 1.0),
    ("k_all_f64", 1.0),
    ("k_pose_f64", 1.0),
    ("floor_f64", 1.0),
    ("floor_std_f64", 1.0),
    ("floor_f32", 1.0),
    ("floor_f64x4", 4.0),
    ("floor_f32x8", 8.0),
    ("floor_all_f64", 1.0),
    ("floor_std_all_f64", 1.0),
    ("galaw_all_f64", 1.0),
    ("galaw_all_f32", 1.0),
    ("baseline_pose_f64", 1.0),
    ("baseline_all_f64", 1.0),
    ("batch_columns1024_f64", 1024.0),
    ("batch_columns1024_f32", 1024.0),
    ("floor_batch1024_f64", 1024.0),
    ("floor_batch1024_f32", 1024.0),
];

/// Criterion's median, in ns per call, of benchmark `variant` of group `group`, if it was run.
pub fn median_ns(criterion: &Path, group: &str, variant: &str) -> Option<f64> {
    let path = criterion.join(group).join(variant).join("new/estimates.json");
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    json["median"]["point_estimate"].as_f64()
}

/// The CPU, its cores and the compiler, for the summary's header.
pub fn machine() -> String {
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines().find(|l| l.starts_with("model name")).map(|l| l.split(':').nth(1).unwrap_or("").trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".to_owned());
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(0);
    let rustc = std::process::Command::new("rustc")
        .arg("-V")
        .output()
        .ok()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_owned())
        .unwrap_or_default();
    let widest = std::fs::read_to_string("/proc/cpuinfo").ok().map_or("", |s| {
        let flags = s.lines().find(|l| l.starts_with("flags")).unwrap_or("");
        let has = |flag: &str| flags.split_whitespace().any(|f| f == flag);
        if has("avx512f") {
            " with AVX-512"
        } else if has("avx2") {
            " with AVX2 (no AVX-512)"
        } else {
            ""
        }
    });
    format!("{model}{widest}, {cores} cores, {rustc}")
}

/// `a / b`, when both were measured.
pub fn ratio(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    Some(a? / b?)
}

/// The pair that times what dispatch costs: 64 dispatched `tip_pose` calls against one dispatch
/// around 64 calls of the same body.
pub const DISPATCH_PAIR: &str = "dispatch_each_pose_f64/dispatch_once_pose_f64";

/// What one dispatch costs, in ns per call: the dispatch pair's ratio over one, times the
/// dispatched pose's median (64 calls each pay it, against one: (ratio - 1) is the cost as a share
/// of a call). `None` unless both were measured; NaN stays NaN.
pub fn dispatch_ns(row: &Row) -> Option<f64> {
    let ratio = row.paired.get(DISPATCH_PAIR)?;
    Some((ratio - 1.0) * row.ns.get("generated_pose_f64")?)
}

/// The figures compared between the plain and the native build, as (column, variant): each a
/// criterion median per call or per configuration.
pub const ACROSS_BUILDS: [(&str, &str); 5] = [
    ("pose", "generated_pose_f64"),
    ("all links", "generated_all_f64"),
    ("Jacobian", "generated_jacobian_f64"),
    ("batch f64", "batch1024_f64"),
    ("batch f32", "batch1024_f32"),
];

/// The plain build's median of `variant` over the native build's, for robot `group` (from two
/// separate runs, so not paired): `None` unless both runs timed it.
pub fn plain_over_native(plain: &[Row], native: &[Row], group: &str, variant: &str) -> Option<f64> {
    let median = |rows: &[Row]| rows.iter().find(|r| r.group == group)?.ns.get(variant).copied();
    ratio(median(plain), median(native))
}

/// Reads one build's results from `criterion` (its robot list, medians, pairs and build record),
/// or `None` when that build was never benchmarked.
pub fn read_run(root: &Path, name: &'static str, criterion: PathBuf) -> Result<Option<Run>> {
    let Ok(manifest) = std::fs::read_to_string(criterion.join("kinematics-robots.tsv")) else { return Ok(None) };
    // Absent when the run predates the pairs or the build record: the tables then say n/a.
    let paired_text = std::fs::read_to_string(criterion.join("kinematics-paired.tsv")).unwrap_or_default();
    let build = std::fs::read_to_string(criterion.join("kinematics-build.tsv"))
        .unwrap_or_default()
        .lines()
        .filter_map(|l| l.split_once('\t'))
        .map(|(k, v)| format!("{k}: {v}"))
        .collect::<Vec<_>>()
        .join("; ");
    let mut rows = Vec::new();
    for line in manifest.lines() {
        let [group, file, tip] = line.split('\t').collect::<Vec<_>>()[..] else { continue };
        let text = std::fs::read_to_string(root.join("robots").join(file))?;
        let tree = kinematics_model::parse_source(file, &text)?;
        let ops = kinematics_compiler::compile(&tree, &kinematics_compiler::Request::tip(tip))?.op_count();
        let ops_all = kinematics_compiler::compile(&tree, &kinematics_compiler::Request::all_links())?.op_count();
        let frame = kinematics_model::JacobianFrame::LocalWorldAligned;
        let ops_jacobian =
            kinematics_compiler::compile(&tree, &kinematics_compiler::Request::tip(tip).jacobian(frame))?.op_count();
        let ops_pose_and_jacobian =
            kinematics_compiler::compile(&tree, &kinematics_compiler::Request::tip(tip).pose_and_jacobian(frame))?
                .op_count();
        let mut ns = BTreeMap::new();
        for (variant, configurations) in VARIANTS {
            if let Some(v) = median_ns(&criterion, group, variant) {
                ns.insert(variant, v / configurations);
            }
        }
        rows.push(Row {
            group: group.to_owned(),
            file: file.to_owned(),
            tip: tip.to_owned(),
            dof: tree.dof(),
            links: tree.links().len().saturating_sub(1),
            ops: format!("{}/{}/{}", ops.sin_cos, ops.mul, ops.add),
            ops_all: format!("{}/{}/{}", ops_all.sin_cos, ops_all.mul, ops_all.add),
            ops_jacobian: format!("{}/{}/{}", ops_jacobian.sin_cos, ops_jacobian.mul, ops_jacobian.add),
            ops_pose_and_jacobian: format!(
                "{}/{}/{}",
                ops_pose_and_jacobian.sin_cos, ops_pose_and_jacobian.mul, ops_pose_and_jacobian.add
            ),
            ns,
            paired: paired_text
                .lines()
                .filter_map(|l| match l.split('\t').collect::<Vec<_>>()[..] {
                    [g, name, v] if g == group => Some((name.to_owned(), v.parse().ok()?)),
                    _ => None,
                })
                .collect(),
        });
    }
    let build = if build.is_empty() { "no build record".to_owned() } else { build };
    Ok(Some(Run { name, build, dir: criterion, rows }))
}

/// A robot in `robots/` with the base and tip of its chain: `(file, base, tip)`.
type RobotFile = (&'static str, &'static str, &'static str);

/// The closed-form robots of the IK benchmark: its group (`ik-<group>`), the summary's name (the
/// ik-geo table's too), and for a robot in `robots/` its file, base and tip (for the compiled
/// body's operation counts; the quartic families' made-up arms and the IRB 120 with inexact half
/// turns are in `tests/arms/`).
const CLOSED: [(&str, &str, Option<RobotFile>); 6] = [
    ("ur5", "UR5", Some(("ur5.urdf", "base_link", "tool0"))),
    ("irb120", "IRB 120", Some(("irb120.urdf", "base_link", "tool0"))),
    ("puma560", "PUMA 560", Some(("puma560.toml", "base", "link6"))),
    ("irb120-half-turns", "IRB 120, inexact half turns (refined)", None),
    ("skew-spherical", "skew spherical wrist (quartic)", None),
    ("offset-wrist-ur", "UR, wrist offset (quartic)", None),
];
/// The numeric robots.
const NUMERIC: [(&str, &str); 3] = [("panda", "Panda"), ("iiwa14", "iiwa 14"), ("ur5", "UR5")];

/// One closed-form robot's IK medians (ns per call) and operation counts.
#[derive(Default)]
pub struct ClosedIk {
    /// The summary's name (`UR5`).
    pub name: &'static str,
    /// Every solution (`tip_ik`).
    pub all: Option<f64>,
    /// The solution nearest a seed (`tip_ik_nearest`).
    pub nearest: Option<f64>,
    /// The run time's family function with the robot's geometry, without the errors' measure.
    pub solver: Option<f64>,
    /// The compiled body, all eight branches in one call on `F64x8`.
    pub lanes8: Option<f64>,
    /// The same in two calls on `F64x4`.
    pub lanes4: Option<f64>,
    /// The same in eight scalar calls.
    pub scalar: Option<f64>,
    /// The pose at `q` in the lanes of `F64x8` (measuring with `sin_cos` again).
    pub pose8: Option<f64>,
    /// The compiled body's operations per branch and the measure's (`kinematics expr --ik`).
    pub ops: Option<IkOps>,
    /// Paired ratios (`kinematics-ik-paired.tsv`): `nearest/all`, `branches-scalar/branches-f64x8`,
    /// `branches-f64x4/branches-f64x8`, `solver/all`.
    pub paired: BTreeMap<String, f64>,
}

/// A compiled closed form's operations per branch, as `sin_cos/mul/add/div/sqrt/atan2/select`.
pub struct IkOps {
    /// The body `tip_ik` runs first: without the pass at the wrist's singularity, where the
    /// family has one.
    pub body: String,
    /// The whole body (`tip_ik_branch_generic`), where it differs: with that pass.
    pub with_pass: Option<String>,
    /// The measure (each solution's pose at the solver's cosines and sines).
    pub measure: String,
}

/// One numeric robot's IK medians and success counts.
pub struct NumericIk {
    /// The summary's name (`Panda`).
    pub name: &'static str,
    /// Our numeric solve, ns per call.
    pub ours: Option<f64>,
    /// `k`'s Jacobian IK on the same targets and seeds, ns per call.
    pub k: Option<f64>,
    /// Converged solves, ours and `k`'s, of how many targets (`kinematics-ik.tsv`).
    pub success: Option<(f64, f64, f64)>,
    /// `k`'s solve over ours, timed in alternation (`k-jacobian-ik/numeric`).
    pub paired: Option<f64>,
}

/// The results of `cargo bench --bench ik` and of `benches/ik-geo/run.sh`.
pub struct Ik {
    /// The closed forms.
    pub closed: Vec<ClosedIk>,
    /// The numeric solver against `k`.
    pub numeric: Vec<NumericIk>,
    /// The comparison with ik-geo (`kinematics-ik-geo.tsv`, from `benches/ik-geo/run.sh`), one
    /// row per robot; empty when it was never run.
    pub ik_geo: Vec<IkGeoRow>,
}

/// One robot of the comparison with ik-geo, as `benches/ik-geo` records it: medians in ns per
/// call, paired ratios, and on how many poses both found the same number of exact solutions.
#[derive(Debug, Clone, PartialEq)]
pub struct IkGeoRow {
    /// The robot, as the comparison names it (`UR5`).
    pub robot: String,
    /// ik-geo's `ik`.
    pub ik_geo_ns: f64,
    /// Our `tip_ik`.
    pub tip_ik_ns: f64,
    /// Our solver alone.
    pub solver_ns: f64,
    /// ik-geo over `tip_ik`, paired.
    pub over_tip_ik: f64,
    /// ik-geo over the solver, paired.
    pub over_solver: f64,
    /// Poses with as many exact solutions on both sides.
    pub equal: usize,
    /// Poses compared.
    pub poses: usize,
}

/// The file `benches/ik-geo` writes in criterion's directory: one line per robot, tab-separated,
/// in [`IkGeoRow`]'s order.
pub const IK_GEO_RECORD: &str = "kinematics-ik-geo.tsv";

/// The rows of an ik-geo record; a line that does not parse is left out (and so is its robot).
pub fn ik_geo_rows(text: &str) -> Vec<IkGeoRow> {
    text.lines()
        .filter_map(|line| {
            let [robot, ik_geo, tip_ik, solver, over_tip_ik, over_solver, equal, poses] =
                line.split('\t').collect::<Vec<_>>()[..]
            else {
                return None;
            };
            Some(IkGeoRow {
                robot: robot.to_owned(),
                ik_geo_ns: ik_geo.parse().ok()?,
                tip_ik_ns: tip_ik.parse().ok()?,
                solver_ns: solver.parse().ok()?,
                over_tip_ik: over_tip_ik.parse().ok()?,
                over_solver: over_solver.parse().ok()?,
                equal: equal.parse().ok()?,
                poses: poses.parse().ok()?,
            })
        })
        .collect()
}

/// The IK results in `criterion` (with `benches/ik-geo`'s record, [`IK_GEO_RECORD`]), or `None`
/// when the IK benchmark was never run (no median for the UR5's `all`).
pub fn read_ik(root: &Path, criterion: &Path) -> Option<Ik> {
    median_ns(criterion, "ik-ur5", "all")?;
    let closed = CLOSED
        .into_iter()
        .map(|(group, name, robot)| {
            let g = format!("ik-{group}");
            let [all, nearest, solver, lanes8, lanes4, scalar, pose8] =
                ["all", "nearest", "solver", "branches-f64x8", "branches-f64x4", "branches-scalar", "pose-f64x8"]
                    .map(|v| median_ns(criterion, &g, v));
            let ops = robot.and_then(|(file, base, tip)| ik_op_counts(root, file, base, tip));
            let paired = ik_pairs(criterion, group);
            ClosedIk { name, all, nearest, solver, lanes8, lanes4, scalar, pose8, ops, paired }
        })
        .collect();
    let numeric = NUMERIC
        .into_iter()
        .map(|(group, name)| {
            let g = format!("ik-{group}");
            let (ours, k) = (median_ns(criterion, &g, "numeric"), median_ns(criterion, &g, "k-jacobian-ik"));
            let paired = ik_pairs(criterion, group).get("k-jacobian-ik/numeric").copied();
            NumericIk { name, ours, k, success: success(criterion, group), paired }
        })
        .collect();
    // Never run is no rows (the summary says so); a record that cannot be read is the same.
    let ik_geo =
        std::fs::read_to_string(criterion.join(IK_GEO_RECORD)).map_or_else(|_| Vec::new(), |t| ik_geo_rows(&t));
    Some(Ik { closed, numeric, ik_geo })
}

/// The compiled closed form's operations per branch and its measure's; `None` for a robot whose
/// closed form is not compiled (or that does not load).
fn ik_op_counts(root: &Path, file: &str, base: &str, tip: &str) -> Option<IkOps> {
    let text = std::fs::read_to_string(root.join("robots").join(file)).ok()?;
    let tree = kinematics_model::parse_source(file, &text).ok()?;
    let plan = kinematics_compiler::ik::classify(&tree, base, tip).ok()?;
    let body = kinematics_compiler::ik::IkBody::of(&plan)?;
    let pose = kinematics_compiler::compile(&tree, &kinematics_compiler::Request::tip(tip).with_base(base)).ok()?;
    let measure = kinematics_compiler::ik::Measure::of(&pose)?;
    let cells = |c: kinematics_compiler::OpCount| {
        format!("{}/{}/{}/{}/{}/{}/{}", c.sin_cos, c.mul, c.add, c.div, c.sqrt, c.atan2, c.select)
    };
    Some(match kinematics_compiler::ik::IkBody::regular(&plan) {
        Some(regular) => IkOps {
            body: cells(regular.op_count()),
            with_pass: Some(cells(body.op_count())),
            measure: cells(measure.op_count()),
        },
        None => IkOps { body: cells(body.op_count()), with_pass: None, measure: cells(measure.op_count()) },
    })
}

/// One robot's paired ratios from `kinematics-ik-paired.tsv` (`robot, pair, ratio`), by pair.
fn ik_pairs(criterion: &Path, robot: &str) -> BTreeMap<String, f64> {
    let text = std::fs::read_to_string(criterion.join("kinematics-ik-paired.tsv")).unwrap_or_default();
    text.lines()
        .filter_map(|line| match line.split('\t').collect::<Vec<_>>()[..] {
            [name, pair, ratio] if name == robot => Some((pair.to_owned(), ratio.parse().ok()?)),
            _ => None,
        })
        .collect()
}

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

/// A robot's row with the given medians and pairs, for the other modules' tests.
#[cfg(test)]
pub fn test_row(group: &str, ns: &[(&'static str, f64)], paired: &[(&str, f64)]) -> Row {
    Row {
        group: group.to_owned(),
        file: format!("{group}.urdf"),
        tip: "tool0".to_owned(),
        dof: 6,
        links: 7,
        ops: "6/1/2".to_owned(),
        ops_all: "6/3/4".to_owned(),
        ops_jacobian: "6/5/6".to_owned(),
        ops_pose_and_jacobian: "6/7/8".to_owned(),
        ns: ns.iter().copied().collect(),
        paired: paired.iter().map(|&(k, v)| (k.to_owned(), v)).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ratio_needs_both_figures() {
        assert_eq!(ratio(Some(3.0), Some(2.0)), Some(1.5));
        assert_eq!(ratio(None, Some(2.0)), None);
        assert_eq!(ratio(Some(3.0), None), None);
    }

    #[test]
    fn dispatch_cost_is_the_ratio_over_one_times_the_pose() {
        let row = test_row("ur5", &[("generated_pose_f64", 40.0)], &[(DISPATCH_PAIR, 1.05)]);
        assert!((dispatch_ns(&row).unwrap() - 2.0).abs() < 1e-12);
        // Either figure missing: none; a NaN ratio stays NaN.
        assert_eq!(dispatch_ns(&test_row("ur5", &[], &[(DISPATCH_PAIR, 1.05)])), None);
        assert_eq!(dispatch_ns(&test_row("ur5", &[("generated_pose_f64", 40.0)], &[])), None);
        let nan = test_row("ur5", &[("generated_pose_f64", 40.0)], &[(DISPATCH_PAIR, f64::NAN)]);
        assert!(dispatch_ns(&nan).unwrap().is_nan());
    }

    #[test]
    fn plain_over_native_needs_the_robot_in_both_runs() {
        let plain = [test_row("ur5", &[("generated_pose_f64", 33.0)], &[]), test_row("panda", &[], &[])];
        let native = [test_row("ur5", &[("generated_pose_f64", 30.0)], &[])];
        assert!((plain_over_native(&plain, &native, "ur5", "generated_pose_f64").unwrap() - 1.1).abs() < 1e-12);
        assert_eq!(plain_over_native(&plain, &native, "panda", "generated_pose_f64"), None);
        assert_eq!(plain_over_native(&plain, &native, "ur5", "generated_all_f64"), None);
        assert_eq!(plain_over_native(&plain, &[], "ur5", "generated_pose_f64"), None);
    }

    #[test]
    fn ik_geo_rows_are_read_by_field_and_bad_lines_left_out() {
        let text =
            "UR5\t2894.2\t591\t490\t4.9\t5.91\t256\t256\nIRB 120\t3090\t577\tx\t5.37\t8.66\t256\t256\nshort\t1\n";
        let rows = ik_geo_rows(text);
        assert_eq!(rows.len(), 1, "{rows:?}");
        let r = &rows[0];
        assert_eq!((r.robot.as_str(), r.ik_geo_ns, r.tip_ik_ns, r.solver_ns), ("UR5", 2894.2, 591.0, 490.0));
        assert_eq!((r.over_tip_ik, r.over_solver, r.equal, r.poses), (4.9, 5.91, 256, 256));
    }

    #[test]
    fn every_variant_is_named_once_with_a_positive_count() {
        for (i, (variant, configurations)) in VARIANTS.iter().enumerate() {
            assert!(*configurations >= 1.0, "{variant}");
            assert!(VARIANTS[..i].iter().all(|(v, _)| v != variant), "{variant} twice");
        }
    }
}
