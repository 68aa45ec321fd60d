//! Each build's sections of the summary: median ns per call (f64 unless marked), lanes and
//! batches per configuration, ratios of the medians, the paired ratios (the figures to quote),
//! and the tip velocities of the robots that have them.

use std::fmt::Write as _;
use std::path::PathBuf;

use super::{fmt, paired, table};
use crate::read::{DISPATCH_PAIR, Row, Run, dispatch_ns, ratio};

/// One build's sections, appended to `s`.
pub fn run_sections(s: &mut String, run: &Run) {
    heading(s, run);
    medians_section(s, run);
    lanes_section(s, run);
    ratios_section(s, run);
    paired_section(s, run);
    velocity_section(s, run);
    let _ = writeln!(s);
}

/// The build's title and where its figures come from.
fn heading(s: &mut String, run: &Run) {
    let title = if run.name == "plain" { "Plain build" } else { "Native build (`-C target-cpu=native`)" };
    // The directory relative to the workspace (`target/criterion`), never the machine's own path.
    let dir = run.dir.components().rev().take_while(|c| c.as_os_str() != "..").collect::<Vec<_>>();
    let dir: PathBuf = dir.into_iter().rev().collect();
    let _ = writeln!(s, "## {title}\n\nFrom `{}` ({}).\n", dir.display(), run.build);
}

/// The medians' columns after the robot's own (DoF, tip, op counts): (column, benchmark variant).
const MEDIANS: [(&str, &str); 20] = [
    ("pose", "generated_pose_f64"),
    ("baseline pose", "baseline_pose_f64"),
    ("std pose", "std_pose_f64"),
    ("pose f32", "generated_pose_f32"),
    ("position", "generated_position_f64"),
    ("all links", "generated_all_f64"),
    ("baseline all", "baseline_all_f64"),
    ("std all", "std_all_f64"),
    ("all f32", "generated_all_f32"),
    ("runtime pose", "runtime_pose_f64"),
    ("runtime all", "runtime_all_f64"),
    ("k all", "k_all_f64"),
    ("k pose", "k_pose_f64"),
    ("galaw all", "galaw_all_f64"),
    ("galaw all f32", "galaw_all_f32"),
    ("floor", "floor_f64"),
    ("floor std", "floor_std_f64"),
    ("floor f32", "floor_f32"),
    ("floor all", "floor_all_f64"),
    ("floor std all", "floor_std_all_f64"),
];

/// Median ns per call of every variant, with the robot's op counts and links.
fn medians_section(s: &mut String, run: &Run) {
    let _ = writeln!(s, "### Median ns per call (f64 unless marked)\n");
    let _ = writeln!(
        s,
        "`pose`, `pose f32`, `position`, `all links` and `all f32` are the generated functions, each dispatched at run\n\
         time to the widest instruction set the CPU has (AVX-512, else AVX2, else the build's own); `baseline pose` and\n\
         `baseline all` are the same bodies not dispatched (`tip_pose_generic::<f64>`, `link_poses_generic::<f64>`),\n\
         compiled for the build's own instruction set (x86-64 baseline in a plain build, this CPU's in a native one).\n\
         `all links` times `let poses = link_poses(q); black_box(&poses)`. `std pose` and `std all` are the robot derived\n\
         with `trig = \"std\"`; `runtime`, `k` and galaw are the peers, `floor ...` the trigonometry floors (see the Notes).\n\
         `links` is how many poses `link_poses` returns, and `all links per link` the `all links` median over it.\n"
    );
    let own = ["DoF", "tip", "ops (sin_cos/mul/add)", "all-links ops"];
    let columns: Vec<&str> =
        own.into_iter().chain(MEDIANS.iter().map(|m| m.0)).chain(["links", "all links per link"]).collect();
    table(s, &run.rows, &columns, |r, i| match i {
        0 => format!("{} (`{}`)", r.dof, r.file),
        1 => r.tip.clone(),
        2 => r.ops.clone(),
        3 => r.ops_all.clone(),
        i if i == columns.len() - 2 => r.links.to_string(),
        // No link but the base: nothing to divide by, so no figure (n/a).
        i if i == columns.len() - 1 => {
            fmt(r.ns.get("generated_all_f64").filter(|_| r.links > 0).map(|ns| ns / r.links as f64))
        }
        i => fmt(r.ns.get(MEDIANS[i - own.len()].1).copied()),
    });
}

/// Lanes and batches: (column, benchmark variant).
const LANES: [(&str, &str); 16] = [
    ("lanes f64x4", "lanes_pose_f64x4"),
    ("4 scalar calls", "scalar4_pose_f64"),
    ("floor f64x4", "floor_f64x4"),
    ("lanes f32x8", "lanes_pose_f32x8"),
    ("8 scalar f32 calls", "scalar8_pose_f32"),
    ("floor f32x8", "floor_f32x8"),
    ("batch f64", "batch1024_f64"),
    ("batch columns f64", "batch_columns1024_f64"),
    ("floor batch f64", "floor_batch1024_f64"),
    ("scalar loop f64", "generated_batch1024_f64"),
    ("batch f32", "batch1024_f32"),
    ("batch columns f32", "batch_columns1024_f32"),
    ("floor batch f32", "floor_batch1024_f32"),
    ("scalar loop f32", "generated_batch1024_f32"),
    ("16,384 one thread", "batch16384_f64"),
    ("16,384 rayon", "parallel_batch16384_f64"),
];

/// Lanes and batches: median ns per configuration.
fn lanes_section(s: &mut String, run: &Run) {
    let _ = writeln!(s, "\n### Lanes and batches: median ns per configuration (tip pose)\n");
    let _ = writeln!(
        s,
        "Lanes: one `tip_pose_generic` call on four (`F64x4`) or eight (`F32x8`) configurations inside\n\
         `kinematics::dispatch`, beside as many scalar calls and the lane type's floor. Batches of 1,024: `batch` is\n\
         `tip_pose_batch` (rows, one array per configuration), `batch columns` is `tip_pose_batch_columns` (one slice\n\
         per joint), `scalar loop` the loop of `tip_pose` calls, and `floor batch` the batch's lane floor: the sin/cos\n\
         alone of its 1,024 configurations in the lanes the batch runs on this CPU (`F64x8` with AVX-512, else `F64x4`;\n\
         `F32x8` on every CPU). Rayon: `parallel::batch` of 16,384 against `tip_pose_batch` on one thread.\n"
    );
    let columns: Vec<&str> = LANES.iter().map(|l| l.0).collect();
    table(s, &run.rows, &columns, |r, i| fmt(r.ns.get(LANES[i].1).copied()));
}

/// Ratios of the medians, and the pose's time beyond the trigonometry floor.
fn ratios_section(s: &mut String, run: &Run) {
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
}

/// The paired ratios (the figures to quote): the contenders, then lanes and batches.
fn paired_section(s: &mut String, run: &Run) {
    let _ = writeln!(s, "\n### Paired ratios\n");
    let _ = writeln!(
        s,
        "The medians above come from different seconds of a shared machine whose speed drifts, so ratios of them move\n\
         by tens of percent between runs. These are timed in alternation instead: 201 rounds, each running both\n\
         contenders back to back (2,000 calls each; 8 calls of a 1,024-batch; 2 calls of a 16,384-batch; 32 calls of\n\
         the 64 poses of the dispatch pair; which goes first alternates), and the median of the rounds' ratios. They\n\
         are the figures to quote. `floor all` is the trigonometry floor of all link poses (every `sin_cos` pair the\n\
         all-links code calls); `runtime all / floor all` and `k all / floor all` are therefore the largest speed-ups\n\
         over the runtime and over `k` that any code calling our `sin_cos` could show, and `all / floor all` how far the\n\
         generated code is from them. `floor std / floor` is what our sin/cos gives over std's on the same angles.\n\
         `baseline pose / pose` and `baseline all / all` are the bodies not dispatched over the dispatched ones: what\n\
         dispatch gains in a plain build (about 1 in a native build, where both run the same instructions).\n\
         `dispatch each / once` is 64 dispatched `tip_pose` calls over one dispatch around 64 calls of the same body,\n\
         and `dispatch ns` the cost of one dispatch it gives: (ratio - 1) times the `pose` median, in ns per call (below\n\
         zero when the two are within noise).\n"
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
        ("baseline pose / pose", "baseline_pose_f64/generated_pose_f64"),
        ("baseline all / all", "baseline_all_f64/generated_all_f64"),
        ("dispatch each / once", DISPATCH_PAIR),
    ];
    let mut columns: Vec<&str> = names.iter().map(|n| n.0).collect();
    columns.push("dispatch ns");
    table(s, &run.rows, &columns, |r, i| match names.get(i) {
        Some(&(_, name)) => paired(r, name),
        None => fmt(dispatch_ns(r)),
    });
    let _ = writeln!(
        s,
        "\nLanes and batches, paired (per configuration: `4 scalar / lanes` is four `tip_pose` calls over one\n\
         `tip_pose_generic::<F64x4>` call on the same four configurations; `f64x4 / f32x8` is two `F64x4` calls over one\n\
         `F32x8` call, eight configurations each side; `batch / columns` is `tip_pose_batch` over\n\
         `tip_pose_batch_columns` on the same 1,024 configurations, above 1 when columns are faster; `batch / floor`\n\
         is the batch over its lane floor, 1.0 being nothing but the sin/cos in the batch's lanes):\n"
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
        ("batch f64 / columns f64", "batch1024_f64/batch_columns1024_f64"),
        ("batch f32 / columns f32", "batch1024_f32/batch_columns1024_f32"),
        ("batch f64 / floor batch f64", "batch1024_f64/floor_batch1024_f64"),
        ("batch f32 / floor batch f32", "batch1024_f32/floor_batch1024_f32"),
        ("one thread / rayon", "batch16384_f64/parallel_batch16384_f64"),
    ];
    let columns: Vec<&str> = names.iter().map(|n| n.0).collect();
    table(s, &run.rows, &columns, |r, i| paired(r, names[i].1));
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::read::test_row;

    #[test]
    fn issue_22_figures_have_columns_and_the_dispatch_cost_its_ns() {
        let ns = [("generated_pose_f64", 40.0), ("baseline_pose_f64", 52.0), ("floor_batch1024_f32", 3.25)];
        let pairs = [("baseline_all_f64/generated_all_f64", 1.3), (DISPATCH_PAIR, 1.05)];
        let run = Run {
            name: "plain",
            build: "build: baseline".to_owned(),
            dir: PathBuf::from("/somewhere/../target/criterion"),
            rows: vec![test_row("ur5", &ns, &pairs)],
        };
        let mut s = String::new();
        run_sections(&mut s, &run);
        assert!(s.contains("From `target/criterion` (build: baseline)."), "{s}");
        // Medians: pose beside its undispatched body; the batch floor f32 per configuration.
        assert!(s.contains("| all-links ops | pose | baseline pose | std pose |"), "{s}");
        assert!(s.contains("| 6/3/4 | 40 | 52 | n/a |"), "{s}");
        assert!(s.contains("| batch f32 | batch columns f32 | floor batch f32 | scalar loop f32 |"), "{s}");
        assert!(s.contains("| n/a | n/a | 3.25 | n/a | n/a | n/a |\n"), "{s}");
        // Paired: the baseline pairs, the dispatch pair and its cost, (1.05 - 1) * 40 ns.
        assert!(
            s.contains("| baseline pose / pose | baseline all / all | dispatch each / once | dispatch ns |"),
            "{s}"
        );
        assert!(s.contains("| n/a | 1.30 | 1.05 | 2.00 |\n"), "{s}");
        assert!(
            s.contains("| batch f64 / columns f64 | batch f32 / columns f32 | batch f64 / floor batch f64 |"),
            "{s}"
        );
    }
}
