//! `kinematics collision-pairs FILE [--samples N] [--seed S] [-o FILE.srdf]`: the link pairs a
//! self-collision check can leave out, as an SRDF of `<disable_collisions>`, the way MoveIt's
//! setup assistant builds its self-collision matrix (its `computeDefaultCollisions`, whose
//! reasons the file keeps): bodies joined by one joint (`Adjacent`), pairs touching at the
//! default configuration (`Default`: every joint at zero, or at its nearest limit), pairs touching
//! in at least a fraction of the samples (`Always`, MoveIt's default 0.95), and pairs touching in
//! none of them (`Never`). Pairs are those the compiled check would test without an SRDF plus the
//! adjacent ones: links with geometry on different rigid bodies, each covered by spheres as the
//! derive covers it (meshes left out); two links touch where two of their spheres do.
//!
//! The samples are uniform within the joint limits, from a seeded stream: the same seed writes
//! the same file. `Never` is a sampling judgement, as in MoveIt: a pair that touches only in a
//! corner no sample reached is disabled; more samples make that less likely.
//!
//! Two links touch when their spheres, placed by the runtime reference's `sphere_centers`, do.

use std::collections::BTreeMap;
use std::io::Write;

use kinematics::Configurations;
use kinematics::model::collision::{LinkSphere, collision_pairs, link_spheres, sphere_pairs};
use kinematics::model::{KinematicTree, LinkId};

use crate::error::CliError;

/// Arguments of `collision-pairs`.
#[derive(clap::Args)]
pub struct Args {
    /// A description with collision geometry: URDF (.urdf, .xml), MJCF (.xml, .mjcf).
    file: String,
    /// Random configurations to sample (MoveIt's setup assistant offers 10,000).
    #[arg(long, default_value_t = 10_000)]
    samples: usize,
    /// The seed of the samples: the same seed writes the same file.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// The fraction of samples a pair must touch in to be disabled as always touching.
    #[arg(long, value_name = "FRACTION", default_value_t = 0.95)]
    always: f64,
    /// How the geometry becomes spheres, as the derive's `collision(...)`, and where meshes are.
    #[command(flatten)]
    cover: crate::cover::CoverArgs,
    /// Write to this file (atomically) instead of standard output.
    #[arg(short, long)]
    output: Option<std::path::PathBuf>,
}

/// Why a pair is disabled, as MoveIt's setup assistant writes it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Reason {
    Adjacent,
    Default,
    Always,
    Never,
}

impl Reason {
    fn name(self) -> &'static str {
        match self {
            Reason::Adjacent => "Adjacent",
            Reason::Default => "Default",
            Reason::Always => "Always",
            Reason::Never => "Never",
        }
    }
}

/// Writes the SRDF of `args.file`'s disabled pairs.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    if args.samples == 0 {
        return Err(CliError::Usage("`--samples`: at least one configuration is needed".into()));
    }
    if !(args.always > 0.0 && args.always <= 1.0) {
        return Err(CliError::Usage(format!("`--always`: {} is no fraction in (0, 1]", args.always)));
    }
    let cover = args.cover.cover()?;
    let mut tree = crate::robot::load(&args.file)?;
    args.cover.read_meshes(&mut tree, &args.file)?;
    let spheres =
        link_spheres(&tree, &cover, args.cover.meshes()).map_err(|e| CliError::Usage(format!("{}: {e}", args.file)))?;
    if spheres.is_empty() {
        return Err(CliError::Usage(format!("{}: no collision geometry to pair", args.file)));
    }
    let disabled = disabled_pairs(&tree, &spheres, args)?;
    crate::error::deliver(&srdf(&tree, &disabled, args, &cover), args.output.as_deref(), &args.file, out)
}

/// Every pair of links with spheres on different bodies that the check can leave out, with why.
fn disabled_pairs(
    tree: &KinematicTree,
    spheres: &[LinkSphere],
    args: &Args,
) -> Result<BTreeMap<(LinkId, LinkId), Reason>, CliError> {
    let mut by_link: BTreeMap<LinkId, Vec<usize>> = BTreeMap::new();
    for (k, s) in spheres.iter().enumerate() {
        by_link.entry(s.link).or_default().push(k);
    }
    // Every pair on different bodies (an empty disabled set leaves them all), and those the
    // model's own rule keeps without an SRDF: the rest are the adjacent bodies' pairs.
    let every = collision_pairs(tree, &|l| by_link.contains_key(&l), Some(&Default::default())).pairs;
    let not_adjacent: std::collections::BTreeSet<_> = sphere_pairs(tree, spheres, None).pairs.into_iter().collect();
    let fk = kinematics::ReferenceFk::new(tree.clone());
    let runtime = |source| CliError::Runtime { file: args.file.clone(), source };
    let touching = |q: &[f64]| -> Result<Vec<bool>, CliError> {
        let centers = fk.sphere_centers(q, spheres).map_err(runtime)?;
        let touch = |s: usize, t: usize| {
            let reach = spheres[s].sphere.radius + spheres[t].sphere.radius;
            (centers[s] - centers[t]).norm_squared() <= reach * reach
        };
        Ok(every.iter().map(|(a, b)| by_link[a].iter().any(|&s| by_link[b].iter().any(|&t| touch(s, t)))).collect())
    };
    let at_default = touching(&default_configuration(tree))?;
    let mut counts = vec![0usize; every.len()];
    let bar = crate::progress::bar(args.samples as u64, "sampling configurations");
    for q in Configurations::new(tree).seeded(args.seed).uniform().take(args.samples) {
        for (count, touches) in counts.iter_mut().zip(touching(&q)?) {
            *count += usize::from(touches);
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let mut disabled = BTreeMap::new();
    for (k, &pair) in every.iter().enumerate() {
        let reason = if !not_adjacent.contains(&pair) {
            Reason::Adjacent
        } else if at_default[k] {
            Reason::Default
        } else if counts[k] as f64 >= args.always * args.samples as f64 {
            Reason::Always
        } else if counts[k] == 0 {
            Reason::Never
        } else {
            continue;
        };
        disabled.insert(pair, reason);
    }
    Ok(disabled)
}

/// Every joint at zero, or at its nearest limit where zero is outside them; a floating or
/// spherical joint's rotation the identity (MoveIt's default state does the same).
fn default_configuration(tree: &KinematicTree) -> Vec<f64> {
    let mut q: Vec<f64> =
        tree.dof_limits().iter().map(|l| l.map_or(0.0, |l| 0.0_f64.clamp(l.lower, l.upper))).collect();
    for start in tree.quaternion_entries() {
        // The quaternion (x, y, z, w).
        q[start + 3] = 1.0;
    }
    q
}

/// The SRDF text: a comment saying how it was made, then the pairs by link name.
fn srdf(
    tree: &KinematicTree,
    disabled: &BTreeMap<(LinkId, LinkId), Reason>,
    args: &Args,
    cover: &kinematics::model::collision::Cover,
) -> String {
    let mut pairs: Vec<(&str, &str, Reason)> = disabled
        .iter()
        .map(|(&(a, b), &reason)| {
            let (a, b) = (tree.link(a).name.as_str(), tree.link(b).name.as_str());
            (a.min(b), a.max(b), reason)
        })
        .collect();
    pairs.sort_unstable();
    let count = |reason: Reason| pairs.iter().filter(|p| p.2 == reason).count();
    let mut out = String::from("<?xml version=\"1.0\"?>\n");
    out += &format!(
        "<!-- The link pairs a self-collision check can leave out, written by `kinematics collision-pairs` from\n     \
         {} ({} samples within the limits, seed {}, always from {} of them, {}{}):\n     \
         {} adjacent, {} touching at the default configuration, {} always touching, {} never touching. -->\n",
        crate::convert::comment(&args.file),
        args.samples,
        args.seed,
        args.always,
        crate::cover::CoverArgs::describe(cover),
        if args.cover.skip_meshes { ", meshes left out" } else { "" },
        count(Reason::Adjacent),
        count(Reason::Default),
        count(Reason::Always),
        count(Reason::Never),
    );
    out += &format!("<robot name=\"{}\">\n", crate::convert::escape(tree.name()));
    for (a, b, reason) in pairs {
        out += &format!(
            "  <disable_collisions link1=\"{}\" link2=\"{}\" reason=\"{}\"/>\n",
            crate::convert::escape(a),
            crate::convert::escape(b),
            reason.name()
        );
    }
    out += "</robot>\n";
    out
}
