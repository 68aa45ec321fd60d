//! Step 9 of `kinematics demo`: collision, on the built-in spherized Panda in the tabletop scene
//! whatever robot the other steps show (this binary holds that robot's generated checks, see
//! `panda.rs`). Its cover; the verdicts of the generated `Panda::collides` judged by the runtime
//! reference's distances; the check timed four ways (the reference, the generated link poses
//! with a hand loop, `collides` one configuration at a time and in batches). For a FILE the user
//! gave, its own geometry is then checked against the reference, untimed, as `kinematics check
//! --collision` does.

use std::hint::black_box;
use std::io::Write;

use kinematics::collision::Environment;
use kinematics::model::KinematicTree;

use super::{Args, per_call, thousands};
use crate::agreement::Configurations;
use crate::collision::{BAND, Counts, Judged, Reference, Setup};
use crate::error::CliError;
use crate::hand_loop::HandLoop;
use crate::panda::{self, Panda};

/// The most configurations judged against the runtime reference.
const SAMPLES: usize = 10_000;

/// The configurations timed, and the length of the batches.
const BATCH: usize = 1_024;

/// Runs the step.
pub(super) fn run(args: &Args, out: &mut dyn Write, tree: &KinematicTree, file: &str) -> Result<(), CliError> {
    writeln!(out, "\n9. Collision, on the spherized Panda ({}, {}) in {}\n", panda::FILE, panda::SRDF, panda::SCENE)?;
    let (panda_tree, setup) = panda::setup()?;
    #[allow(clippy::expect_used, reason = "invariant: the built-in Panda has spheres and its setup a scene")]
    let (reference, obstacles) = (
        Reference::new(&panda_tree, panda::FILE, &setup)?.expect("the built-in Panda has spheres"),
        &setup.scene.as_ref().expect("the built-in setup has a scene").1,
    );
    let environment = obstacles.environment().map_err(|e| CliError::Usage(format!("{}: {e}", panda::SCENE)))?;
    writeln!(out, "  {}", reference.summary(&setup))?;
    judged(args, out, &panda_tree, &reference, &environment)?;

    // The naive way, on the same poses: it must give the same verdicts before it is timed.
    #[allow(clippy::expect_used, reason = "invariant: the reference's spheres are the built-in Panda's")]
    let hand = HandLoop::new(&panda_tree, &reference.spheres, &reference.pairs, obstacles)
        .expect("the reference's spheres are the built-in Panda's");
    let qs: Vec<[f64; Panda::DOF]> = Configurations::new(&panda_tree).take(BATCH).map(|q| panda_array(&q)).collect();
    let verdicts: Vec<bool> = qs.iter().map(|q| Panda::collides(q, &environment)).collect();
    let mut differing = Vec::new();
    for (q, &verdict) in qs.iter().zip(&verdicts) {
        if hand.collides(q) != verdict {
            differing.push((q.to_vec(), reference.nearest(q)?, verdict));
        }
    }
    writeln!(
        out,
        "  the hand loop below against Panda::collides on {} configurations: {} differing\n",
        thousands(qs.len()),
        differing.len()
    )?;
    disagreements(out, &differing)?;
    writeln!(
        out,
        "  Timing, ns per configuration on those {} ({} colliding; a check may stop at its first hit):",
        thousands(qs.len()),
        thousands(verdicts.iter().filter(|&&v| v).count())
    )?;
    timing(args, out, &reference, &hand, &environment, &qs)?;

    if args.file.is_some() && tree != &panda_tree {
        let scene = Some((panda::SCENE, obstacles.clone()));
        // The user's meshes are not read here (`check --collision` reads them).
        let meshes = kinematics::model::collision::Meshes::Skip;
        own_geometry(args, out, tree, file, &Setup { cover: setup.cover, meshes, srdf: None, scene })?;
    }
    Ok(())
}

/// The verdicts of the generated `Panda::collides` on the first `--samples` configurations (at
/// most [`SAMPLES`]), judged by the reference's distances as `check --collision` judges them.
fn judged(
    args: &Args,
    out: &mut dyn Write,
    tree: &KinematicTree,
    reference: &Reference,
    environment: &Environment<'_>,
) -> Result<(), CliError> {
    let samples = args.samples.clamp(1, SAMPLES);
    let (mut counts, mut disagreeing) = (Counts::default(), Vec::new());
    let bar = crate::progress::bar(samples as u64, "checking collisions");
    for q in Configurations::new(tree).take(samples) {
        let distance = reference.nearest(&q)?;
        let verdict = Panda::collides(&panda_array(&q), environment);
        let judged = crate::collision::judge(distance, verdict);
        if judged == Judged::Disagrees {
            disagreeing.push((q, distance, verdict));
        }
        counts.add(judged);
        bar.inc(1);
    }
    bar.finish_and_clear();
    writeln!(
        out,
        "  generated Panda::collides against the runtime reference (parry3d-f64 distances), {} configurations:\n  \
         {} colliding and {} free as the reference says, {} within {BAND:e} m of contact (not judged), {} disagreeing",
        thousands(samples),
        thousands(counts.colliding),
        thousands(counts.free),
        thousands(counts.banded),
        thousands(counts.disagreeing)
    )?;
    disagreements(out, &disagreeing)
}

/// The check timed on `qs` four ways, inputs precomputed and results through `black_box`.
fn timing(
    args: &Args,
    out: &mut dyn Write,
    reference: &Reference,
    hand: &HandLoop,
    environment: &Environment<'_>,
    qs: &[[f64; Panda::DOF]],
) -> Result<(), CliError> {
    out.flush()?;
    let n = qs.len();
    let singles: Vec<Vec<f64>> = qs.iter().map(|q| q.to_vec()).collect();
    let by_reference = per_call((args.evaluations / 100).max(1), |i| {
        let _ = black_box(reference.nearest(black_box(&singles[i % n])));
    });
    let by_hand = per_call((args.evaluations / 10).max(1), |i| {
        black_box(hand.collides(black_box(&qs[i % n])));
    });
    let generated = per_call(args.evaluations, |i| {
        black_box(Panda::collides(black_box(&qs[i % n]), environment));
    });
    let batches = (args.evaluations / n).max(1);
    let mut verdicts = vec![false; n];
    let batch = per_call(batches, |_| {
        let _ = black_box(Panda::collides_batch(black_box(qs), environment, &mut verdicts));
    }) / n as f64;
    let qs32: Vec<[f32; Panda::DOF]> = qs.iter().map(|q| q.map(|x| x as f32)).collect();
    let batch32 = per_call(batches, |_| {
        let _ = black_box(Panda::collides_batch_f32(black_box(&qs32), environment, &mut verdicts));
    }) / n as f64;
    let faster = |t: f64| {
        let (reference, hand) = (by_reference / t.max(1e-3), by_hand / t.max(1e-3));
        format!("{t:>9.1} ns ({reference:.0}x faster than the reference, {hand:.1}x than the hand loop)")
    };
    let batch_of = |name: &str| format!("generated code, Panda::{name}, {} a call:", thousands(n));
    for (label, time) in [
        ("runtime reference, every distance (parry3d-f64):".to_owned(), format!("{by_reference:>9.1} ns")),
        (
            "the naive way: Panda::link_poses and a hand loop:".to_owned(),
            format!("{by_hand:>9.1} ns ({:.0}x faster than the reference)", by_reference / by_hand.max(1e-3)),
        ),
        ("generated code, Panda::collides:".to_owned(), faster(generated)),
        (batch_of("collides_batch"), faster(batch)),
        (batch_of("collides_batch_f32"), faster(batch32)),
    ] {
        writeln!(out, "  {label:<58}{time}")?;
    }
    if cfg!(debug_assertions) {
        writeln!(out, "  (a debug build: run with `cargo run --release` for representative numbers)")?;
    }
    Ok(())
}

/// The user's robot: its own `<collision>` geometry against the reference in the demo's scene.
fn own_geometry(
    args: &Args,
    out: &mut dyn Write,
    tree: &KinematicTree,
    file: &str,
    setup: &Setup<'_>,
) -> Result<(), CliError> {
    writeln!(out, "\n  {file}, its own <collision> geometry against the reference in {} (not timed):", panda::SCENE)?;
    let samples = args.samples.clamp(1, 1_000);
    match crate::collision::check(tree, file, samples, setup)? {
        Some(report) => {
            for line in crate::collision::text(&report, samples).lines() {
                writeln!(out, "  {line}")?;
            }
        }
        None => writeln!(out, "  no <collision> geometry the cover reads (meshes are not read)")?,
    }
    Ok(())
}

/// A configuration of the built-in Panda as the array its functions take.
fn panda_array(q: &[f64]) -> [f64; Panda::DOF] {
    #[allow(clippy::expect_used, reason = "invariant: the Panda's configurations have its DoF")]
    q.try_into().expect("the built-in Panda's configurations have its DoF")
}

/// Up to five configurations whose verdicts differ, each with the reference's distance.
fn disagreements(out: &mut dyn Write, differing: &[(Vec<f64>, f64, bool)]) -> Result<(), CliError> {
    for (q, distance, verdict) in differing.iter().take(5) {
        let q = q.iter().map(|x| format!("{x:.4}")).collect::<Vec<_>>().join(", ");
        writeln!(out, "    q = [{q}]: Panda::collides says {verdict}, the reference's distance is {distance:.3e} m")?;
    }
    Ok(())
}
