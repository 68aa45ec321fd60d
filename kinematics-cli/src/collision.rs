//! The collision checks of `check` and `demo`: the core's checks (`CollisionTables`, what a
//! generated `collides` and `self_collides` run) on the compiled link poses, against the runtime
//! reference's signed distances (parry3d-f64 on its own sphere centres), configuration by
//! configuration. No Rust is compiled: the tables are built here from the model as the compiler
//! writes them, and the poses are the compiled expressions evaluated. `demo` holds the built-in
//! Panda's generated `collides` to the same [`Reference`] and judges it by the same [`judge`].

use std::collections::BTreeSet;

use kinematics::collision::{CollisionTables, PairGrid};
use kinematics::model::collision::{
    Cover, LinkSphere, Meshes, fixed_apart_pairs, link_spheres, pair_grids, sphere_pairs,
};
use kinematics::model::{KinematicTree, LinkId};
use kinematics::runtime::ReferenceObstacles;
use kinematics::{Pose, ReferenceFk, SceneObstacles};
use kinematics_compiler::collision_layout::CollisionLayout;
use kinematics_compiler::{Request, compile};

use crate::agreement::Configurations;
use crate::error::CliError;

/// Configurations within this distance of contact (m) are counted, not judged: there the two
/// computations may round either way.
pub const BAND: f64 = 1e-9;

/// What the collision check is run on: the cover, the SRDF's disabled pairs, the scene.
pub struct Setup<'a> {
    /// How the geometry becomes spheres.
    pub cover: Cover,
    /// Whether meshes (read into the tree beforehand) are covered or left out.
    pub meshes: Meshes,
    /// The SRDF file and its disabled pairs, if one was given.
    pub srdf: Option<(&'a str, BTreeSet<(LinkId, LinkId)>)>,
    /// The scene file and its obstacles, if one was given.
    pub scene: Option<(&'a str, SceneObstacles)>,
}

/// One check's counts.
#[derive(Debug, Default, Clone, Copy)]
pub struct Counts {
    /// Configurations the reference says collide, and the check agreed.
    pub colliding: usize,
    /// Configurations the reference says are free, and the check agreed.
    pub free: usize,
    /// Configurations within [`BAND`] of contact.
    pub banded: usize,
    /// Configurations whose verdict is not the reference's (`check` fails at the first).
    pub disagreeing: usize,
}

/// The collision check's report.
pub struct Report {
    /// The spheres, their links, the pairs.
    pub summary: String,
    /// `self_collides`'s counts.
    pub itself: Counts,
    /// `collides`'s counts, with a scene.
    pub obstacles: Option<Counts>,
}

/// The runtime reference's side of a check: the cover's spheres placed by the reference's own
/// link poses (nalgebra), and parry3d-f64's signed distances between the self-collision pairs'
/// spheres and from the spheres to the scene's obstacles.
pub struct Reference {
    fk: ReferenceFk,
    file: String,
    /// The cover's spheres, each on its link (the model's order).
    pub spheres: Vec<LinkSphere>,
    /// The self-collision pairs of links: every pair on different bodies, less the SRDF's.
    pub pairs: Vec<(LinkId, LinkId)>,
    obstacles: Option<ReferenceObstacles>,
}

impl Reference {
    /// The reference for `tree` as `setup` asks, or `None` if the robot has no geometry the cover
    /// reads. A link the cover cannot make is the error (an overshoot out of reach).
    pub fn new(tree: &KinematicTree, file: &str, setup: &Setup<'_>) -> Result<Option<Self>, CliError> {
        let spheres =
            link_spheres(tree, &setup.cover, setup.meshes).map_err(|e| CliError::Usage(format!("{file}: {e}")))?;
        if spheres.is_empty() {
            return Ok(None);
        }
        let pairs = sphere_pairs(tree, &spheres, setup.srdf.as_ref().map(|(_, d)| d)).pairs;
        Ok(Some(Reference {
            fk: ReferenceFk::new(tree.clone()),
            file: file.to_owned(),
            spheres,
            pairs,
            obstacles: setup.scene.as_ref().map(|(_, obstacles)| obstacles.reference()),
        }))
    }

    /// The smallest signed distance (m) between spheres of the self-collision pairs at `q`, and
    /// from any sphere to an obstacle (infinite without a scene); negative where they overlap.
    pub fn distances(&self, q: &[f64]) -> Result<(f64, f64), CliError> {
        let runtime = |source| CliError::Runtime { file: self.file.clone(), source };
        let itself = self.fk.self_distance(q, &self.spheres, &self.pairs).map_err(runtime)?;
        let obstacles = match &self.obstacles {
            Some(obstacles) => self.fk.obstacle_distance(q, &self.spheres, obstacles).map_err(runtime)?,
            None => f64::INFINITY,
        };
        Ok((itself, obstacles))
    }

    /// The distance `collides` is judged by: the nearer of the self pairs and the obstacles.
    pub fn nearest(&self, q: &[f64]) -> Result<f64, CliError> {
        let (itself, obstacles) = self.distances(q)?;
        Ok(nearer(itself, obstacles))
    }

    /// The spheres, their links and the pairs, with where the pairs and obstacles come from.
    pub fn summary(&self, setup: &Setup<'_>) -> String {
        let links: BTreeSet<LinkId> = self.spheres.iter().map(|s| s.link).collect();
        let pairs_from = match &setup.srdf {
            Some((srdf, _)) => format!("less the pairs {srdf} disables"),
            None => "less those of bodies joined by one joint, no SRDF given".to_owned(),
        };
        let scene = match &setup.scene {
            Some((path, obstacles)) => format!("; scene {path} ({} obstacles)", obstacles.len()),
            None => "; no scene given (`--scene FILE` checks `collides` too)".to_owned(),
        };
        format!(
            "{} on {} ({}), {} ({pairs_from}){scene}",
            counted(self.spheres.len(), "sphere"),
            counted(links.len(), "link"),
            crate::cover::CoverArgs::describe(&setup.cover),
            counted(self.pairs.len(), "self-collision pair")
        )
    }
}

/// The robot's collision geometry checked on `samples` configurations, or `None` if it has none
/// the cover reads (meshes are left out). A verdict that differs from the reference's outside
/// the band is the error returned.
pub fn check(tree: &KinematicTree, file: &str, samples: usize, setup: &Setup<'_>) -> Result<Option<Report>, CliError> {
    let Some(reference) = Reference::new(tree, file, setup)? else {
        return Ok(None);
    };
    let spheres = &reference.spheres;
    // The tables, as the compiler writes them: links with spheres in tree order, each with its
    // groups and bounding sphere; each group's spheres and bounding sphere; each sphere's centre
    // in its link's frame, in the checks' order.
    let layout = CollisionLayout::new(spheres);
    let links: Vec<(usize, usize, [f64; 3], f64)> =
        layout.link_groups.iter().zip(&layout.bounds).map(|(&(s, e), &(c, r))| (s, e, c, r)).collect();
    let centers: Vec<[f64; 3]> = layout.order.iter().map(|&k| layout.points[k].1).collect();
    let radii: Vec<f64> = layout.order.iter().map(|&k| spheres[k].sphere.radius).collect();
    let index = |l: LinkId| layout.links.iter().position(|&k| k == l);
    let pairs: Vec<(usize, usize)> =
        reference.pairs.iter().filter_map(|&(a, b)| Some((index(a)?, index(b)?))).collect();
    let fixed = layout.fixed_in_order(&fixed_apart_pairs(tree, spheres, &reference.pairs));
    // The grids as the compiler writes them: each cell's code packed, each pair by its index.
    let grids = pair_grids(tree, spheres, &reference.pairs);
    #[allow(clippy::expect_used, reason = "invariant: a grid decides checked pairs")]
    let decided: Vec<(Vec<u8>, Vec<usize>)> = grids
        .iter()
        .map(|g| {
            let index = |pair| reference.pairs.iter().position(|p| p == pair).expect("a grid decides checked pairs");
            (g.packed(), g.pairs.iter().map(index).collect())
        })
        .collect();
    let grids: Vec<PairGrid<'_>> = grids
        .iter()
        .zip(&decided)
        .map(|(g, (states, pairs))| PairGrid {
            dofs: g.dofs,
            lower: g.lower,
            scale: g.scale(),
            cells: g.cells,
            states,
            pairs,
        })
        .collect();
    let tables = CollisionTables {
        links: &links,
        groups: &layout.groups,
        centers: &centers,
        radii: &radii,
        pairs: &pairs,
        fixed: &fixed,
        grids: &grids,
    };

    let request = Request {
        base: Some(tree.link(tree.root()).name.clone()),
        tips: layout.links.iter().map(|&l| tree.link(l).name.clone()).collect(),
        position_only: false,
        velocity: None,
    };
    let compiled = compile(tree, &request).map_err(|source| CliError::compile(file, source))?;
    let environment = match &setup.scene {
        Some((_, obstacles)) => Some(obstacles.environment().map_err(|e| CliError::Usage(format!("the scene: {e}")))?),
        None => None,
    };
    let (mut itself, mut against) = (Counts::default(), Counts::default());
    let bar = crate::progress::bar(samples as u64, "checking collisions");
    for q in Configurations::new(tree).take(samples) {
        let poses: Vec<Pose<f64>> = compiled.eval(&q).iter().map(Pose::from_entries).collect();
        let (s, d) = reference.distances(&q)?;
        let verdict = tables.self_collides(&q, &poses).any();
        tally(&mut itself, s, verdict, file, "self_collides", &q)?;
        if let Some(env) = &environment {
            let verdict = tables.collides(&q, &poses, env, None).any();
            tally(&mut against, nearer(s, d), verdict, file, "collides", &q)?;
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    Ok(Some(Report { summary: reference.summary(setup), itself, obstacles: environment.map(|_| against) }))
}

/// The nearer of two signed distances; a NaN, which `min` would drop, stays a NaN and fails.
fn nearer(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() { f64::NAN } else { a.min(b) }
}

/// `n thing` or `n things`.
fn counted(n: usize, thing: &str) -> String {
    if n == 1 { format!("1 {thing}") } else { format!("{n} {thing}s") }
}

/// How a verdict stands against the reference's signed distance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Judged {
    /// Both say colliding.
    Colliding,
    /// Both say free.
    Free,
    /// Within [`BAND`] of contact: not judged.
    Banded,
    /// The verdict is not the reference's (or the reference could not measure).
    Disagrees,
}

/// Judges `verdict` (colliding or not) by the reference's signed `distance`.
pub fn judge(distance: f64, verdict: bool) -> Judged {
    if distance.is_nan() || (distance.abs() > BAND && verdict != (distance < 0.0)) {
        Judged::Disagrees
    } else if distance.abs() <= BAND {
        Judged::Banded
    } else if verdict {
        Judged::Colliding
    } else {
        Judged::Free
    }
}

impl Counts {
    /// Counts one judged verdict.
    pub fn add(&mut self, judged: Judged) {
        match judged {
            Judged::Colliding => self.colliding += 1,
            Judged::Free => self.free += 1,
            Judged::Banded => self.banded += 1,
            Judged::Disagrees => self.disagreeing += 1,
        }
    }
}

/// Counts one verdict against the reference's distance, or fails outside the band.
fn tally(
    counts: &mut Counts,
    distance: f64,
    verdict: bool,
    file: &str,
    check: &str,
    q: &[f64],
) -> Result<(), CliError> {
    let judged = judge(distance, verdict);
    if judged == Judged::Disagrees {
        return Err(CliError::CollisionDisagrees {
            file: file.to_owned(),
            check: check.to_owned(),
            q: q.to_vec(),
            distance,
            verdict,
        });
    }
    counts.add(judged);
    Ok(())
}

/// The report's lines.
pub fn text(report: &Report, samples: usize) -> String {
    let mut out = format!("collision: {}\n", report.summary);
    let line = |name: &str, c: &Counts| {
        format!(
            "  {name}: {} configurations, {} colliding, {} free, {} within {BAND:e} m of contact: every other verdict \
             as the reference's\n",
            samples, c.colliding, c.free, c.banded
        )
    };
    out += &line("self_collides", &report.itself);
    if let Some(c) = &report.obstacles {
        out += &line("collides (obstacles and self)", c);
    }
    out
}

/// Reads `--srdf` and `--scene` into a [`Setup`].
pub fn setup<'a>(
    tree: &KinematicTree,
    cover: &crate::cover::CoverArgs,
    srdf: Option<&'a str>,
    scene: Option<&'a str>,
) -> Result<Setup<'a>, CliError> {
    let (meshes, cover) = (cover.meshes(), cover.cover()?);
    let srdf = match srdf {
        Some(path) => Some((path, crate::robot::load_srdf(path, tree)?)),
        None => None,
    };
    let scene = match scene {
        Some(path) => Some((path, kinematics::load_scene(path)?)),
        None => None,
    };
    Ok(Setup { cover, meshes, srdf, scene })
}
