//! `cargo run -p bench-report`: reads criterion's results of `cargo bench --bench fk` for the plain
//! build (`target/criterion`) and for the native build (`target/native/criterion`, from the same
//! command with `RUSTFLAGS="-C target-cpu=native" CARGO_TARGET_DIR=target/native`), whichever exist:
//! the medians in `<robot>/<variant>/new/estimates.json`, the robot list (`kinematics-robots.tsv`),
//! the build record (`kinematics-build.tsv`) and the paired ratios (`kinematics-paired.tsv`) the
//! benchmark writes. It writes `benches/SUMMARY.md` (per build and robot: median ns per call or per
//! configuration, the ratios, the operation counts, the machine and the commands; then the issue's
//! targets, each with its measured figure and whether it is met) and `benches/ratios.svg` (the
//! ratios as bars). Nothing here is typed in by hand.

mod ik;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

type Result<T> = std::result::Result<T, Box<dyn std::error::Error>>;

/// One robot's row of one run.
#[derive(Clone)]
struct Row {
    group: String,
    file: String,
    tip: String,
    dof: usize,
    ops: String,
    /// The same for all link poses.
    ops_all: String,
    /// The same for the tip's Jacobian (`LOCAL_WORLD_ALIGNED`) and for the pose with it.
    ops_jacobian: String,
    ops_pose_and_jacobian: String,
    /// Median ns per configuration (per call for single-configuration bodies), by variant.
    ns: BTreeMap<&'static str, f64>,
    /// Ratios timed in alternation by the benchmark (`kinematics-paired.tsv`), by pair name.
    paired: BTreeMap<String, f64>,
}

/// One build's results.
struct Run {
    /// `plain` or `native`, the directory it was read from.
    name: &'static str,
    /// The benchmark's build record: its label and the vector features it was compiled with.
    build: String,
    dir: PathBuf,
    rows: Vec<Row>,
}

/// Every variant the benchmark times, and how many configurations one call computes (criterion's
/// median is per call; the tables show it per configuration).
const VARIANTS: [(&str, f64); 35] = [
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
];

fn median_ns(criterion: &Path, group: &str, variant: &str) -> Option<f64> {
    let path = criterion.join(group).join(variant).join("new/estimates.json");
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    json["median"]["point_estimate"].as_f64()
}

fn machine() -> String {
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
    format!("{model}, {cores} cores, {rustc}")
}

fn fmt(x: Option<f64>) -> String {
    x.map_or("n/a".to_owned(), |v| if v < 10.0 { format!("{v:.2}") } else { format!("{v:.0}") })
}

fn ratio(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    Some(a? / b?)
}

/// Reads one build's results from `criterion` (its robot list, medians, pairs and build record),
/// or `None` when that build was never benchmarked.
fn read_run(root: &Path, name: &'static str, criterion: PathBuf) -> Result<Option<Run>> {
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

fn run() -> Result<()> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let target = root.join("target");
    let mut runs = Vec::new();
    for (name, dir) in [("plain", target.join("criterion")), ("native", target.join("native/criterion"))] {
        runs.extend(read_run(&root, name, dir)?);
    }
    if runs.is_empty() {
        return Err(format!(
            "no benchmark results in {} or {}: run `cargo bench --bench fk` first (see benches/SUMMARY.md)",
            target.join("criterion").display(),
            target.join("native/criterion").display()
        )
        .into());
    }
    let ik = ik::section(&root, &target.join("criterion"));
    std::fs::write(root.join("benches/SUMMARY.md"), summary(&runs) + &ik)?;
    // The bars show the plain build, the one every user gets, when it was run.
    std::fs::write(root.join("benches/ratios.svg"), svg(&runs[0]))?;
    let names: Vec<&str> = runs.iter().map(|r| r.name).collect();
    println!("wrote benches/SUMMARY.md and benches/ratios.svg from the {} run(s)", names.join(" and "));
    Ok(())
}

/// The commands that produce the results, as SUMMARY.md states them.
const COMMANDS: &str = "```sh
# plain build (x86-64 baseline), results in target/criterion (about 10 minutes on 2 cores)
KINEMATICS_BENCH_BUILD=baseline cargo bench --bench fk
# native build, kept apart in target/native/criterion
KINEMATICS_BENCH_BUILD=native RUSTFLAGS=\"-C target-cpu=native\" CARGO_TARGET_DIR=target/native cargo bench --bench fk
# this file and ratios.svg, from whichever of the two exist
cargo run -p bench-report
```";

fn summary(runs: &[Run]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# Benchmark summary\n");
    let _ = writeln!(
        s,
        "Generated by `cargo run -p bench-report` from the results of `cargo bench --bench fk` (criterion medians;\n\
         HTML plots in `target/criterion/report/index.html`). Machine: {}. Shared and noisy: read the paired\n\
         ratios, not the nanoseconds. A plain and a native build are separate runs, each in its own target\n\
         directory:\n\n{COMMANDS}\n\n\
         A filtered run (`cargo bench --bench fk -- ur5`) replaces only its robots' figures; the others stay\n\
         from the last run that timed them.\n",
        machine()
    );
    for run in runs {
        run_sections(&mut s, run);
    }
    targets(&mut s, runs);
    let _ = writeln!(
        s,
        "\n## Notes\n\n\
         `floor` is the new trigonometry floor: our sin/cos alone, every angle of the function in one `sin_cos_many`\n\
         call, as the generated code calls it (as many angles as the compiler counts `sin_cos` pairs); `floor std` is\n\
         std's `sin_cos` once per angle, as code derived with `trig = \"std\"` calls it. `std pose` and `std all` are the\n\
         same robot derived with `trig = \"std\"`. Lanes (`F64x4`, `F32x8`) evaluate `tip_pose_generic` on four or eight\n\
         configurations per call and are shown per configuration, beside as many scalar calls on the same\n\
         configurations; batches are `tip_pose_batch` / `tip_pose_batch_f32` (lanes inside) against the scalar loop,\n\
         per configuration; rayon is `parallel::batch` over 16,384 configurations against `tip_pose_batch` on one\n\
         thread.\n\
         `k` and galaw read URDF only: DH robots have no figures for them. `k` orders its joints its own way; its inputs\n\
         are the same values, so it does the same amount of work. galaw's code is its own generator's output for our\n\
         URDFs (`benches/galaw/regenerate.sh`, galaw 0.3.0); galaw has no mimic joints, so it gets one command per moving\n\
         joint, each set to the value our model gives that joint (the benchmark's check mode asserts its poses agree)."
    );
    s
}

/// The value of pair `name` in `row`, two decimals, or n/a.
fn paired(row: &Row, name: &str) -> String {
    row.paired.get(name).map_or("n/a".to_owned(), |v| format!("{v:.2}"))
}

/// Writes a table: a header row of `columns` and one row per robot of `cell(row, column)`.
fn table(s: &mut String, rows: &[Row], columns: &[&str], cell: impl Fn(&Row, usize) -> String) {
    let _ = writeln!(s, "| robot | {} |", columns.join(" | "));
    let _ = writeln!(s, "|---|{}", "---|".repeat(columns.len()));
    for r in rows {
        let cells: Vec<String> = (0..columns.len()).map(|i| cell(r, i)).collect();
        let _ = writeln!(s, "| {} | {} |", r.group, cells.join(" | "));
    }
}

fn run_sections(s: &mut String, run: &Run) {
    let title = if run.name == "plain" { "Plain build" } else { "Native build (`-C target-cpu=native`)" };
    // The directory relative to the workspace (`target/criterion`), never the machine's own path.
    let dir = run.dir.components().rev().take_while(|c| c.as_os_str() != "..").collect::<Vec<_>>();
    let dir: PathBuf = dir.into_iter().rev().collect();
    let _ = writeln!(s, "## {title}\n\nFrom `{}` ({}).\n", dir.display(), run.build);
    let _ = writeln!(s, "### Median ns per call (f64 unless marked)\n");
    let columns = [
        "DoF",
        "tip",
        "ops (sin_cos/mul/add)",
        "all-links ops",
        "pose",
        "std pose",
        "pose f32",
        "position",
        "all links",
        "std all",
        "all f32",
        "runtime pose",
        "runtime all",
        "k all",
        "k pose",
        "galaw all",
        "galaw all f32",
        "floor",
        "floor std",
        "floor f32",
        "floor all",
        "floor std all",
    ];
    let variants = [
        "generated_pose_f64",
        "std_pose_f64",
        "generated_pose_f32",
        "generated_position_f64",
        "generated_all_f64",
        "std_all_f64",
        "generated_all_f32",
        "runtime_pose_f64",
        "runtime_all_f64",
        "k_all_f64",
        "k_pose_f64",
        "galaw_all_f64",
        "galaw_all_f32",
        "floor_f64",
        "floor_std_f64",
        "floor_f32",
        "floor_all_f64",
        "floor_std_all_f64",
    ];
    table(s, &run.rows, &columns, |r, i| match i {
        0 => format!("{} (`{}`)", r.dof, r.file),
        1 => r.tip.clone(),
        2 => r.ops.clone(),
        3 => r.ops_all.clone(),
        i => fmt(r.ns.get(variants[i - 4]).copied()),
    });
    let _ = writeln!(s, "\n### Lanes and batches: median ns per configuration (tip pose)\n");
    let columns = [
        "lanes f64x4",
        "4 scalar calls",
        "floor f64x4",
        "lanes f32x8",
        "8 scalar f32 calls",
        "floor f32x8",
        "batch f64",
        "scalar loop f64",
        "batch f32",
        "scalar loop f32",
        "16,384 one thread",
        "16,384 rayon",
    ];
    let variants = [
        "lanes_pose_f64x4",
        "scalar4_pose_f64",
        "floor_f64x4",
        "lanes_pose_f32x8",
        "scalar8_pose_f32",
        "floor_f32x8",
        "batch1024_f64",
        "generated_batch1024_f64",
        "batch1024_f32",
        "generated_batch1024_f32",
        "batch16384_f64",
        "parallel_batch16384_f64",
    ];
    table(s, &run.rows, &columns, |r, i| fmt(r.ns.get(variants[i]).copied()));
    let _ = writeln!(s, "\n### Ratios of the medians\n");
    let _ = writeln!(
        s,
        "Speed-ups are the other contender's time over the generated code's (higher is better); `pose / floor` is the\n\
         generated pose's time over the trigonometry floor (1.0 would be nothing but the `sin_cos` calls); `trig share` is\n\
         floor / pose, the part of the pose's time spent in `sin_cos`, and `rest` the pose's time beyond the floor (ns);\n\
         `f64 / f32` is the pose's f64 time over its f32 time; `k all / galaw all` places galaw against `k` as its\n\
         authors compare them.\n"
    );
    let pairs: [(&str, &str, &str); 12] = [
        ("std pose / pose", "std_pose_f64", "generated_pose_f64"),
        ("runtime all / generated all", "runtime_all_f64", "generated_all_f64"),
        ("k all / generated all", "k_all_f64", "generated_all_f64"),
        ("galaw all / generated all", "galaw_all_f64", "generated_all_f64"),
        ("k all / galaw all", "k_all_f64", "galaw_all_f64"),
        ("k pose / generated pose", "k_pose_f64", "generated_pose_f64"),
        ("pose / floor", "generated_pose_f64", "floor_f64"),
        ("position / pose", "generated_position_f64", "generated_pose_f64"),
        ("trig share", "floor_f64", "generated_pose_f64"),
        ("f64 / f32", "generated_pose_f64", "generated_pose_f32"),
        ("all f64 / all f32", "generated_all_f64", "generated_all_f32"),
        ("batch f64 / batch f32", "batch1024_f64", "batch1024_f32"),
    ];
    let mut columns: Vec<&str> = pairs.iter().map(|p| p.0).collect();
    columns.insert(9, "rest");
    table(s, &run.rows, &columns, |r, i| {
        let n = |k: &str| r.ns.get(k).copied();
        let x = |v: Option<f64>| v.map_or("n/a".to_owned(), |v| format!("{v:.2}"));
        match i {
            9 => fmt(n("generated_pose_f64").zip(n("floor_f64")).map(|(p, f)| p - f)),
            i => {
                let (_, a, b) = pairs[if i > 9 { i - 1 } else { i }];
                x(ratio(n(a), n(b)))
            }
        }
    });
    let _ = writeln!(s, "\n### Paired ratios\n");
    let _ = writeln!(
        s,
        "The medians above come from different seconds of a shared machine whose speed drifts, so ratios of them move\n\
         by tens of percent between runs. These are timed in alternation instead: 201 rounds, each running both\n\
         contenders back to back (2,000 calls each; 8 calls of a 1,024-batch; 2 calls of a 16,384-batch; which goes\n\
         first alternates), and the median of the rounds' ratios. They are the figures to quote. `floor all` is the\n\
         trigonometry floor of all link poses (every `sin_cos` pair the all-links code calls); `runtime all / floor all`\n\
         and `k all / floor all` are therefore the largest speed-ups over the runtime and over `k` that any code calling\n\
         our `sin_cos` could show, and `all / floor all` how far the generated code is from them. `floor std / floor` is\n\
         what our sin/cos gives over std's on the same angles.\n"
    );
    let names = [
        ("std pose / pose", "std_pose_f64/generated_pose_f64"),
        ("std all / all", "std_all_f64/generated_all_f64"),
        ("runtime all / generated all", "runtime_all_f64/generated_all_f64"),
        ("k all / generated all", "k_all_f64/generated_all_f64"),
        ("galaw all / generated all", "galaw_all_f64/generated_all_f64"),
        ("pose / floor", "generated_pose_f64/floor_f64"),
        ("all / floor all", "generated_all_f64/floor_all_f64"),
        ("pose f32 / floor f32", "generated_pose_f32/floor_f32"),
        ("floor std / floor", "floor_std_f64/floor_f64"),
        ("floor std all / floor all", "floor_std_all_f64/floor_all_f64"),
        ("std pose / floor std", "std_pose_f64/floor_std_f64"),
        ("position / pose", "generated_position_f64/generated_pose_f64"),
        ("runtime all / floor all (bound)", "runtime_all_f64/floor_all_f64"),
        ("k all / floor all (bound)", "k_all_f64/floor_all_f64"),
    ];
    let columns: Vec<&str> = names.iter().map(|n| n.0).collect();
    table(s, &run.rows, &columns, |r, i| paired(r, names[i].1));
    let _ = writeln!(
        s,
        "\nLanes and batches, paired (per configuration: `4 scalar / lanes` is four `tip_pose` calls over one\n\
         `tip_pose_generic::<F64x4>` call on the same four configurations; `f64x4 / f32x8` is two `F64x4` calls over one\n\
         `F32x8` call, eight configurations each side):\n"
    );
    let names = [
        ("4 scalar / lanes f64x4", "scalar4_pose_f64/lanes_pose_f64x4"),
        ("8 scalar / lanes f32x8", "scalar8_pose_f32/lanes_pose_f32x8"),
        ("lanes f64x4 / floor f64x4", "lanes_pose_f64x4/floor_f64x4"),
        ("lanes f32x8 / floor f32x8", "lanes_pose_f32x8/floor_f32x8"),
        ("f64x4 / f32x8", "lanes_pose_f64x4/lanes_pose_f32x8"),
        ("scalar loop / batch f64", "generated_batch1024_f64/batch1024_f64"),
        ("scalar loop / batch f32", "generated_batch1024_f32/batch1024_f32"),
        ("batch f64 / batch f32", "batch1024_f64/batch1024_f32"),
        ("one thread / rayon", "batch16384_f64/parallel_batch16384_f64"),
    ];
    let columns: Vec<&str> = names.iter().map(|n| n.0).collect();
    table(s, &run.rows, &columns, |r, i| paired(r, names[i].1));
    velocity_section(s, run);
    let _ = writeln!(s);
}

/// The tip velocities of the arms that have them: medians, and paired ratios.
fn velocity_section(s: &mut String, run: &Run) {
    let rows: Vec<Row> = run.rows.iter().filter(|r| r.paired.contains_key(VELOCITY_PAIRS[0].1)).cloned().collect();
    if rows.is_empty() {
        return;
    }
    let _ = writeln!(
        s,
        "\nTip velocities, f64 (`J`: the generated geometric Jacobian, `LOCAL_WORLD_ALIGNED`; `pose + J`:\n\
         `tip_pose_and_jacobian`; `runtime J`: `ReferenceFk::jacobian`; `k J`: `k::jacobian` of its serial chain;\n\
         `twist`: `tip_twist`, against `tip_jacobian` and the product by the rates written by hand). Op counts,\n\
         medians in ns, then paired ratios:\n"
    );
    let _ = writeln!(s, "Op counts (`sin_cos` pairs / multiplications / additions):\n");
    let columns = ["pose", "J", "pose + J"];
    table(s, &rows, &columns, |r, i| [&r.ops, &r.ops_jacobian, &r.ops_pose_and_jacobian][i].clone());
    let _ = writeln!(s);
    let medians = [
        ("J", "generated_jacobian_f64"),
        ("pose + J", "generated_pose_and_jacobian_f64"),
        ("runtime J", "runtime_jacobian_f64"),
        ("k J", "k_jacobian_f64"),
        ("twist", "generated_twist_f64"),
    ];
    let columns: Vec<&str> = medians.iter().map(|m| m.0).collect();
    table(s, &rows, &columns, |r, i| fmt(r.ns.get(medians[i].1).copied()));
    let _ = writeln!(s);
    let columns: Vec<&str> = VELOCITY_PAIRS.iter().map(|p| p.0).collect();
    table(s, &rows, &columns, |r, i| paired(r, VELOCITY_PAIRS[i].1));
}

/// The velocity pairs the summary prints: (column, pair name).
const VELOCITY_PAIRS: [(&str, &str); 6] = [
    ("pose + J / pose", "generated_pose_and_jacobian_f64/generated_pose_f64"),
    ("J / pose", "generated_jacobian_f64/generated_pose_f64"),
    ("runtime J / pose + J", "runtime_jacobian_f64/generated_pose_and_jacobian_f64"),
    ("runtime J / J", "runtime_jacobian_f64/generated_jacobian_f64"),
    ("k J / pose + J", "k_jacobian_f64/generated_pose_and_jacobian_f64"),
    ("J then J*qd / twist", "jacobian_times_qd_f64/generated_twist_f64"),
];

/// One of the issue's targets, as a figure measured in one run.
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

fn targets(s: &mut String, runs: &[Run]) {
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

fn svg(run: &Run) -> String {
    let rows = &run.rows;
    let series: [(&str, &str, &str, &str); 6] = [
        ("std-trig pose / generated pose", "std_pose_f64", "generated_pose_f64", "#e15759"),
        ("runtime all / generated all", "runtime_all_f64", "generated_all_f64", "#4e79a7"),
        ("runtime all / trig floor of all (bound)", "runtime_all_f64", "floor_all_f64", "#a0cbe8"),
        ("k all / generated all", "k_all_f64", "generated_all_f64", "#f28e2b"),
        ("galaw all / generated all", "galaw_all_f64", "generated_all_f64", "#b07aa1"),
        ("pose / trig floor", "generated_pose_f64", "floor_f64", "#59a14f"),
    ];
    let values: Vec<Vec<Option<f64>>> = rows
        .iter()
        .map(|r| {
            series
                .iter()
                .map(|(_, a, b, _)| {
                    // The paired ratio where the benchmark timed one, else the ratio of the medians.
                    r.paired
                        .get(&format!("{a}/{b}"))
                        .copied()
                        .or_else(|| ratio(r.ns.get(a).copied(), r.ns.get(b).copied()))
                })
                .collect()
        })
        .collect();
    let max = values.iter().flatten().flatten().fold(1.0f64, |m, &v| m.max(v)).ceil();
    let (width, bar, gap, left, top, height) =
        (900.0, 14.0, 14.0, 130.0, 40.0, rows.len() as f64 * (series.len() as f64 * 14.0 + 14.0));
    let scale = (width - left - 40.0) / max;
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"{left}\" y=\"20\" font-size=\"14\">Forward kinematics, f64, {} build: ratios (x) per robot, from benches/SUMMARY.md (paired where timed so)</text>\n",
        top + height + 70.0,
        run.name
    );
    for (i, (r, vals)) in rows.iter().zip(&values).enumerate() {
        let y0 = top + i as f64 * (series.len() as f64 * bar + gap);
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
            left - 8.0,
            y0 + series.len() as f64 * bar / 2.0 + 4.0,
            r.group
        );
        for (j, v) in vals.iter().enumerate() {
            if let Some(v) = v {
                let y = y0 + j as f64 * bar;
                let _ = writeln!(
                    s,
                    "<rect x=\"{left}\" y=\"{y}\" width=\"{:.1}\" height=\"{}\" fill=\"{}\"/><text x=\"{:.1}\" y=\"{:.1}\" font-size=\"10\">{v:.1}</text>",
                    v * scale,
                    bar - 2.0,
                    series[j].3,
                    left + v * scale + 4.0,
                    y + bar - 4.0
                );
            }
        }
    }
    let axis_y = top + height + 5.0;
    for t in 0..=(max as usize) {
        let x = left + t as f64 * scale;
        let _ = writeln!(
            s,
            "<line x1=\"{x}\" y1=\"{top}\" x2=\"{x}\" y2=\"{axis_y}\" stroke=\"#ddd\"/><text x=\"{x}\" y=\"{}\" text-anchor=\"middle\" font-size=\"10\">{t}</text>",
            axis_y + 12.0
        );
    }
    for (j, (label, _, _, color)) in series.iter().enumerate() {
        // Three legend entries a row.
        let x = left + (j % 3) as f64 * 250.0;
        let y = axis_y + 28.0 + (j / 3) as f64 * 18.0;
        let _ = writeln!(
            s,
            "<rect x=\"{x}\" y=\"{}\" width=\"12\" height=\"12\" fill=\"{color}\"/><text x=\"{}\" y=\"{}\">{label}</text>",
            y - 10.0,
            x + 16.0,
            y
        );
    }
    s + "</svg>\n"
}
