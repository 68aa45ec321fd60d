//! `cargo run -p bench-report`: reads criterion's results of `cargo bench --bench fk` (the medians
//! in `target/criterion/<robot>/<variant>/new/estimates.json`, and the robot list the benchmark
//! writes to `target/criterion/kinematics-robots.tsv`) and writes `benches/SUMMARY.md` (per robot:
//! median ns per call of each contender, the ratios, the operation counts, the machine and the
//! command) and `benches/ratios.svg` (the ratios as bars). Nothing here is typed in by hand.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

type Result<T> = std::result::Result<T, Box<dyn std::error::Error>>;

/// One robot's row.
struct Row {
    group: String,
    file: String,
    tip: String,
    dof: usize,
    ops: String,
    /// The same for all link poses.
    ops_all: String,
    ns: std::collections::BTreeMap<&'static str, f64>,
    /// Ratios timed in alternation by the benchmark (`kinematics-paired.tsv`), by pair name.
    paired: std::collections::BTreeMap<String, f64>,
}

const VARIANTS: [&str; 15] = [
    "generated_pose_f64",
    "generated_pose_f32",
    "generated_position_f64",
    "generated_all_f64",
    "generated_all_f32",
    "generated_batch1024_f64",
    "runtime_pose_f64",
    "runtime_all_f64",
    "k_all_f64",
    "k_pose_f64",
    "floor_f64",
    "floor_f32",
    "floor_all_f64",
    "galaw_all_f64",
    "galaw_all_f32",
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

fn run() -> Result<()> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let target = std::env::var("CARGO_TARGET_DIR").map(PathBuf::from).unwrap_or_else(|_| root.join("target"));
    let criterion = target.join("criterion");
    let manifest = std::fs::read_to_string(criterion.join("kinematics-robots.tsv")).map_err(|e| {
        format!("no benchmark results in {} ({e}): run `cargo bench --bench fk` first", criterion.display())
    })?;
    // Absent when the run was filtered or predates the pairs: the tables then say n/a.
    let paired_text = std::fs::read_to_string(criterion.join("kinematics-paired.tsv")).unwrap_or_default();
    let mut rows = Vec::new();
    for line in manifest.lines() {
        let [group, file, tip] = line.split('\t').collect::<Vec<_>>()[..] else { continue };
        let text = std::fs::read_to_string(root.join("robots").join(file))?;
        let tree = kinematics_model::parse_source(file, &text)?;
        let ops = kinematics_compiler::compile(&tree, &kinematics_compiler::Request::tip(tip))?.op_count();
        let ops_all = kinematics_compiler::compile(&tree, &kinematics_compiler::Request::all_links())?.op_count();
        let mut ns = std::collections::BTreeMap::new();
        for variant in VARIANTS {
            if let Some(v) = median_ns(&criterion, group, variant) {
                // The batch is timed per 1,024 configurations: report it per configuration.
                ns.insert(variant, if variant.contains("batch") { v / 1024.0 } else { v });
            }
        }
        rows.push(Row {
            group: group.to_owned(),
            file: file.to_owned(),
            tip: tip.to_owned(),
            dof: tree.dof(),
            ops: format!("{}/{}/{}", ops.sin_cos, ops.mul, ops.add),
            ops_all: format!("{}/{}/{}", ops_all.sin_cos, ops_all.mul, ops_all.add),
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
    let md = summary(&rows);
    std::fs::write(root.join("benches/SUMMARY.md"), md)?;
    std::fs::write(root.join("benches/ratios.svg"), svg(&rows))?;
    println!("wrote benches/SUMMARY.md and benches/ratios.svg from {} robots", rows.len());
    Ok(())
}

fn summary(rows: &[Row]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# Benchmark summary\n");
    let _ = writeln!(
        s,
        "Generated by `cargo run -p bench-report` from the results of `cargo bench --bench fk` (criterion medians;\n\
         HTML plots in `target/criterion/report/index.html`). Machine: {}. Shared and noisy: read the ratios, not\n\
         the nanoseconds.\n",
        machine()
    );
    let _ = writeln!(s, "## Median ns per call (f64 unless marked)\n");
    let _ = writeln!(
        s,
        "| robot | DoF | tip | ops (sin_cos/mul/add) | all-links ops | pose | pose f32 | position | all links | all f32 | batch, per config | runtime pose | runtime all | k all | k pose | galaw all | galaw all f32 | floor | floor f32 | floor all |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for r in rows {
        let g = |k: &str| fmt(r.ns.get(k).copied());
        let _ = writeln!(
            s,
            "| {} (`{}`) | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.group,
            r.file,
            r.dof,
            r.tip,
            r.ops,
            r.ops_all,
            g("generated_pose_f64"),
            g("generated_pose_f32"),
            g("generated_position_f64"),
            g("generated_all_f64"),
            g("generated_all_f32"),
            g("generated_batch1024_f64"),
            g("runtime_pose_f64"),
            g("runtime_all_f64"),
            g("k_all_f64"),
            g("k_pose_f64"),
            g("galaw_all_f64"),
            g("galaw_all_f32"),
            g("floor_f64"),
            g("floor_f32"),
            g("floor_all_f64"),
        );
    }
    let _ = writeln!(s, "\n## Ratios\n");
    let _ = writeln!(
        s,
        "Speed-ups are the other contender's time over the generated code's (higher is better); `pose / floor` is the\n\
         generated pose's time over the trigonometry floor (1.0 would be nothing but the `sin_cos` calls); `trig share` is\n\
         floor / pose, the part of the pose's time spent in `sin_cos`, and `rest` the pose's time beyond the floor (ns);\n\
         `f64 / f32` is the pose's f64 time over its f32 time; `k all / galaw all` places galaw against `k` as its\n\
         authors compare them.\n"
    );
    let _ = writeln!(
        s,
        "| robot | runtime all / generated all | k all / generated all | galaw all / generated all | k all / galaw all | k pose / generated pose | pose / floor | position / pose | trig share | rest | f64 / f32 | all f64 / all f32 |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|---|");
    for r in rows {
        let n = |k: &str| r.ns.get(k).copied();
        let x = |v: Option<f64>| v.map_or("n/a".to_owned(), |v| format!("{v:.2}"));
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.group,
            x(ratio(n("runtime_all_f64"), n("generated_all_f64"))),
            x(ratio(n("k_all_f64"), n("generated_all_f64"))),
            x(ratio(n("galaw_all_f64"), n("generated_all_f64"))),
            x(ratio(n("k_all_f64"), n("galaw_all_f64"))),
            x(ratio(n("k_pose_f64"), n("generated_pose_f64"))),
            x(ratio(n("generated_pose_f64"), n("floor_f64"))),
            x(ratio(n("generated_position_f64"), n("generated_pose_f64"))),
            x(ratio(n("floor_f64"), n("generated_pose_f64"))),
            fmt(n("generated_pose_f64").zip(n("floor_f64")).map(|(p, f)| p - f)),
            x(ratio(n("generated_pose_f64"), n("generated_pose_f32"))),
            x(ratio(n("generated_all_f64"), n("generated_all_f32"))),
        );
    }
    let _ = writeln!(s, "\n## Paired ratios\n");
    let _ = writeln!(
        s,
        "The medians above come from different seconds of a shared machine whose speed drifts, so ratios of them move\n\
         by tens of percent between runs. These are timed in alternation instead: 201 rounds, each running both\n\
         contenders 2,000 times back to back (which goes first alternates), and the median of the rounds' ratios.\n\
         They are the figures to quote. `floor all` is the trigonometry floor of all link poses (every `sin_cos`\n\
         pair the all-links code calls); `runtime all / floor all` and `k all / floor all` are therefore the largest\n\
         speed-ups over the runtime and over `k` that any code calling this `sin_cos` could show, and `all / floor all`\n\
         how far the generated code is from them.\n"
    );
    let _ = writeln!(
        s,
        "| robot | runtime all / generated all | k all / generated all | galaw all / generated all | pose / floor | position / pose | all / floor all | runtime all / floor all (bound) | k all / floor all (bound) |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|");
    for r in rows {
        let p = |k: &str| r.paired.get(k).map_or("n/a".to_owned(), |v| format!("{v:.2}"));
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.group,
            p("runtime_all_f64/generated_all_f64"),
            p("k_all_f64/generated_all_f64"),
            p("galaw_all_f64/generated_all_f64"),
            p("generated_pose_f64/floor_f64"),
            p("generated_position_f64/generated_pose_f64"),
            p("generated_all_f64/floor_all_f64"),
            p("runtime_all_f64/floor_all_f64"),
            p("k_all_f64/floor_all_f64"),
        );
    }
    let _ = writeln!(
        s,
        "\nWhy f32 is not twice as fast: the generated code is scalar, and on x86-64 a scalar f32 multiply or add costs\n\
         the same as an f64 one; only `sin_cos` is cheaper in f32 (`sinf`/`cosf`), so the gain is at most the trig share.\n\
         Where the pose sits near the floor, the next gain is a faster `sin_cos`, not fewer multiplications.\n\
         `k` and galaw read URDF only: DH robots have no figures for them. `k` orders its joints its own way; its inputs\n\
         are the same values, so it does the same amount of work. galaw's code is its own generator's output for our\n\
         URDFs (`benches/galaw/regenerate.sh`, galaw 0.3.0); galaw has no mimic joints, so it gets one command per moving\n\
         joint, each set to the value our model gives that joint (the benchmark's check mode asserts the tip agrees)."
    );
    s
}

fn svg(rows: &[Row]) -> String {
    let series: [(&str, &str, &str, &str); 5] = [
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
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"{left}\" y=\"20\" font-size=\"14\">Forward kinematics, f64: ratios (x) per robot, from benches/SUMMARY.md (paired where timed so)</text>\n",
        top + height + 70.0
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
