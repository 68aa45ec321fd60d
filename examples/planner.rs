//! A motion planner on the compiled collision checks (issue 31, point 6): RRT-Connect for VAMP's
//! spherized Panda among the obstacles of a scene file, every edge of its trees and of its
//! shortcuts checked by `Panda::motion_collides_any` (whether the straight motion in joint space
//! collides at a resolution, in lanes, the first pack with a hit ending it), not only the
//! configurations it reaches.
//!
//! ```text
//! cargo run --release --example planner -- [--scene FILE]... [--start q1,..,q7 --goal q1,..,q7]
//!     [--seed N] [--trials N [--detours]] [--resolution RAD | --states-per-unit N] [--range RAD]
//!     [--samples N] [--shortcuts N] [--path-out FILE]
//! ```
//!
//! With a start and a goal (or without them, a default pair in the default scene,
//! `scenes/table_shelves.toml`, from the table to the shelf's lower compartment, whose straight
//! motion collides), it prints the plan, the checks it made and the time it took; `--path-out`
//! writes the plan one configuration per line, which `kinematics draw robots/panda_spherized.urdf
//! --path FILE --scene SCENE` draws. With `--trials N` it plans between N random free start-goal
//! pairs per scene (the same seed, the same pairs and plans) and prints the quantiles of the
//! planning time.
//!
//! Why not the `rrt` crate (openrr's, 0.7.0, read for this): its `dual_rrt_connect` checks each
//! new configuration through an `is_free(&[f64])` closure, never the edge that reaches it, so a
//! motion check has no place in it; the path it returns joins the parents of the two vertices
//! where the trees met (`get_until_root` leaves the vertex itself out), an edge that was never
//! checked; and its `smooth_path` draws from `rand::thread_rng()`, so no seed repeats a run. The
//! search below is Kuffner and LaValle's RRT-Connect (ICRA 2000) as their paper gives it, with
//! edges checked as motions and the usual random shortcutting after it.
//!
//! Its chance comes from the runtime's seeded `Configurations` (one seed, one plan). Its tests run
//! under `cargo test` (`test = true`): plans re-checked edge by edge by `motion_collides` and by
//! the runtime reference.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use std::fmt;
use std::time::{Duration, Instant};

use kinematics::collision::{Environment, Motion, Resolution};
use kinematics::{Configurations, JointLimits, Kinematics, KinematicsError};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda_spherized.urdf", collision(srdf = "robots/panda.srdf"))]
struct Panda;

/// The Panda's degrees of freedom.
const DOF: usize = 7;

/// A configuration.
type Q = [f64; DOF];

/// The scene planned in when none is named, relative to the repository.
const DEFAULT_SCENE: &str = "scenes/table_shelves.toml";

/// The default query in the default scene: the hand low over the table's front edge, between its
/// boxes, and the hand in the shelf's lower compartment; their straight motion collides.
const DEFAULT_START: Q = [-0.07, 0.23, -0.25, -1.94, 0.09, 2.11, 0.49];
const DEFAULT_GOAL: Q = [0.37, 0.81, 0.64, -2.09, -0.35, 3.4, 0.94];

/// How a search runs.
#[derive(Clone, Copy, Debug)]
struct Settings {
    /// How finely a motion is checked: the largest joint step between checked configurations
    /// (`--resolution`, radians) or the configurations per radian of joint-space distance
    /// (`--states-per-unit`, as VAMP and OMPL count).
    resolution: Resolution,
    /// The longest edge an extension adds (Euclidean in joint space, radians).
    range: f64,
    /// How many random samples the search draws before it gives up.
    samples: usize,
    /// How many random shortcuts are tried on a path found.
    shortcuts: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings { resolution: Resolution::JointStep(0.05), range: 1.0, samples: 20_000, shortcuts: 50 }
    }
}

/// The checks a search made: every one a `motion_collides` call.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Checks {
    /// Motions checked.
    motions: usize,
    /// Of them, found colliding.
    colliding: usize,
    /// Configurations of the free motions (every one of them is checked; a colliding motion's
    /// search stops early, so its count is not known here).
    free_configurations: usize,
}

/// The robot's straight motions checked in one environment, counted.
struct Checker<'a> {
    environment: &'a Environment<'a>,
    resolution: Resolution,
    checks: Checks,
}

impl Checker<'_> {
    /// Whether the straight motion `from -> to` is free, checked by `motion_collides_any` (the
    /// yes/no answer: the first pack with a hit ends it).
    fn free(&mut self, from: &Q, to: &Q) -> Result<bool, KinematicsError> {
        self.checks.motions += 1;
        if Panda::motion_collides_any(from, to, self.environment, self.resolution)? {
            self.checks.colliding += 1;
            return Ok(false);
        }
        self.checks.free_configurations += Motion::new(Panda::ROBOT, *from, *to, self.resolution)?.steps() + 1;
        Ok(true)
    }
}

/// One tree of RRT-Connect, rooted at the start or at the goal.
struct Tree {
    /// Its configurations; the root first.
    nodes: Vec<Q>,
    /// Each configuration's parent (the root's is itself).
    parents: Vec<usize>,
    /// Whether the root is the start: edges are checked in the direction the path runs, from the
    /// start's side, so the returned path's edges are the very motions checked.
    from_start: bool,
}

/// What an extension did.
enum Extend {
    /// The motion collides: nothing added.
    Trapped,
    /// A configuration `range` towards the target added (its index).
    Advanced(usize),
    /// The target itself added (its index).
    Reached(usize),
}

fn distance(a: &Q, b: &Q) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum::<f64>().sqrt()
}

impl Tree {
    fn new(root: Q, from_start: bool) -> Self {
        Tree { nodes: vec![root], parents: vec![0], from_start }
    }

    /// The configuration nearest `q` (a scan: the trees hold hundreds, not millions).
    fn nearest(&self, q: &Q) -> usize {
        let mut best = (0, f64::INFINITY);
        for (i, node) in self.nodes.iter().enumerate() {
            let d = distance(node, q);
            if d < best.1 {
                best = (i, d);
            }
        }
        best.0
    }

    /// Grows from configuration `from` towards `target` by at most `range`, if that motion is
    /// free.
    fn steer(&mut self, from: usize, target: &Q, range: f64, checker: &mut Checker) -> Result<Extend, KinematicsError> {
        let q = self.nodes[from];
        let d = distance(&q, target);
        let (new, reached) = if d <= range {
            (*target, true)
        } else {
            (std::array::from_fn(|j| q[j] + (target[j] - q[j]) * (range / d)), false)
        };
        let free = if self.from_start { checker.free(&q, &new)? } else { checker.free(&new, &q)? };
        if !free {
            return Ok(Extend::Trapped);
        }
        self.nodes.push(new);
        self.parents.push(from);
        let index = self.nodes.len() - 1;
        Ok(if reached { Extend::Reached(index) } else { Extend::Advanced(index) })
    }

    /// EXTEND: one step from the nearest configuration towards `target`.
    fn extend(&mut self, target: &Q, range: f64, checker: &mut Checker) -> Result<Extend, KinematicsError> {
        self.steer(self.nearest(target), target, range, checker)
    }

    /// CONNECT: steps towards `target` until it is reached or a motion collides, each from the
    /// configuration the last step added (the nearest to the target, as the paper observes).
    fn connect(&mut self, target: &Q, range: f64, checker: &mut Checker) -> Result<Extend, KinematicsError> {
        let mut status = self.extend(target, range, checker)?;
        while let Extend::Advanced(last) = status {
            status = self.steer(last, target, range, checker)?;
        }
        Ok(status)
    }

    /// The configurations from `index` up to the root.
    fn to_root(&self, mut index: usize) -> Vec<Q> {
        let mut path = vec![self.nodes[index]];
        while self.parents[index] != index {
            index = self.parents[index];
            path.push(self.nodes[index]);
        }
        path
    }
}

/// Uniform fractions in [0, 1), `K` at a time, from the runtime's seeded stream (the planner's
/// only source of chance, so a seed repeats a run).
fn fractions<const K: usize>(seed: u64) -> Configurations {
    Configurations::within(&[JointLimits { lower: 0.0, upper: 1.0 }; K]).seeded(seed).uniform()
}

/// A planned path and how it was found.
#[derive(Debug)]
struct Plan {
    /// From the start to the goal, each edge a free straight motion.
    path: Vec<Q>,
    /// The path as the search found it, before shortcutting.
    found: usize,
    /// Whether the straight motion from start to goal was free (no search).
    direct: bool,
    /// Samples the search drew.
    samples: usize,
    /// Configurations in the two trees.
    nodes: usize,
    /// The search's time and checks.
    search: Duration,
    search_checks: Checks,
    /// Shortcutting's time and checks.
    shortcut: Duration,
    shortcut_checks: Checks,
}

/// Why no plan came.
#[derive(Debug)]
enum PlanError {
    /// The start or the goal collides.
    Colliding(&'static str, Q),
    /// A setting is not a positive finite number (or a count is zero).
    Setting(&'static str, f64),
    /// The check refused its input.
    Check(KinematicsError),
}

impl fmt::Display for PlanError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlanError::Colliding(which, q) => write!(f, "the {which} configuration {q:?} collides"),
            PlanError::Setting(name, value) => write!(f, "`--{name}` is {value} (must be positive and finite)"),
            PlanError::Check(e) => write!(f, "{e}"),
        }
    }
}

impl From<KinematicsError> for PlanError {
    fn from(e: KinematicsError) -> Self {
        PlanError::Check(e)
    }
}

/// RRT-Connect from `start` to `goal` (tried first as one straight motion), then shortcutting;
/// `None` when `settings.samples` samples found no path. Deterministic for a seed.
fn plan(
    start: &Q,
    goal: &Q,
    environment: &Environment,
    settings: Settings,
    seed: u64,
) -> Result<Option<Plan>, PlanError> {
    let resolution = match settings.resolution {
        Resolution::JointStep(step) => ("resolution", step),
        Resolution::StatesPerUnit(states) => ("states-per-unit", states),
    };
    for (name, value) in [resolution, ("range", settings.range)] {
        if !(value.is_finite() && value > 0.0) {
            return Err(PlanError::Setting(name, value));
        }
    }
    let mut checker = Checker { environment, resolution: settings.resolution, checks: Checks::default() };
    let clock = Instant::now();
    for (which, q) in [("start", start), ("goal", goal)] {
        if Panda::collides(q, environment) {
            return Err(PlanError::Colliding(which, *q));
        }
    }
    let mut samples = Configurations::within(&Panda::JOINT_LIMITS).seeded(seed).uniform();
    let (mut a, mut b) = (Tree::new(*start, true), Tree::new(*goal, false));
    let mut drawn = 0;
    let found = if checker.free(start, goal)? {
        Some(vec![*start, *goal])
    } else {
        let mut found = None;
        while drawn < settings.samples && found.is_none() {
            drawn += 1;
            let sample: Q = samples.next_array().ok_or(PlanError::Setting("samples", f64::NAN))?;
            if let Extend::Advanced(new) | Extend::Reached(new) = a.extend(&sample, settings.range, &mut checker)? {
                let target = a.nodes[new];
                if let Extend::Reached(met) = b.connect(&target, settings.range, &mut checker)? {
                    // `b` reached `target` itself: the two vertices are one configuration.
                    let mut path = a.to_root(new);
                    path.reverse();
                    path.extend(b.to_root(met).into_iter().skip(1));
                    if !a.from_start {
                        path.reverse();
                    }
                    found = Some(path);
                }
            }
            std::mem::swap(&mut a, &mut b);
        }
        found
    };
    let search = clock.elapsed();
    let search_checks = checker.checks;
    let Some(mut path) = found else { return Ok(None) };
    let found = path.len();
    // Shortcutting: two random vertices at least two apart joined by their straight motion when it
    // is free, the vertices between dropped; a pair found colliding is not checked again while the
    // path stays as it is, and shortcutting ends when every pair has been.
    let clock = Instant::now();
    checker.checks = Checks::default();
    let mut picks = fractions::<2>(seed);
    let mut tried: Vec<(usize, usize)> = Vec::new();
    for _ in 0..settings.shortcuts {
        let n = path.len();
        if n < 3 || tried.len() == (n - 1) * (n - 2) / 2 {
            break;
        }
        let [u, v]: [f64; 2] = picks.next_array().ok_or(PlanError::Setting("shortcuts", f64::NAN))?;
        let i = ((u * (n - 2) as f64) as usize).min(n - 3);
        let j = (i + 2 + (v * (n - i - 2) as f64) as usize).min(n - 1);
        if tried.contains(&(i, j)) {
            continue;
        }
        if checker.free(&path[i], &path[j])? {
            path.drain(i + 1..j);
            tried.clear();
        } else {
            tried.push((i, j));
        }
    }
    Ok(Some(Plan {
        path,
        found,
        direct: drawn == 0,
        samples: drawn,
        nodes: a.nodes.len() + b.nodes.len(),
        search,
        search_checks,
        shortcut: clock.elapsed(),
        shortcut_checks: checker.checks,
    }))
}

/// What the command line asks.
#[derive(Debug)]
struct Args {
    scenes: Vec<String>,
    start: Option<Q>,
    goal: Option<Q>,
    seed: u64,
    trials: Option<usize>,
    detours: bool,
    settings: Settings,
    path_out: Option<String>,
}

const USAGE: &str = "usage: planner [--scene FILE]... [--start q1,..,q7 --goal q1,..,q7] [--seed N] [--trials N [--detours]] \
                     [--resolution RAD | --states-per-unit N] [--range RAD] [--samples N] [--shortcuts N] \
                     [--path-out FILE]";

/// A configuration from `--start` or `--goal`: seven finite values within the Panda's limits.
fn configuration(flag: &str, text: &str) -> Result<Q, String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>().map_err(|_| format!("`{flag}`: `{v}` is not a number")))
        .collect::<Result<_, _>>()?;
    let q: Q = values
        .as_slice()
        .try_into()
        .map_err(|_| format!("`{flag}` has {} values; the Panda has {DOF} joints", values.len()))?;
    for (j, (&value, limits)) in q.iter().zip(Panda::JOINT_LIMITS).enumerate() {
        let name = Panda::JOINT_NAMES[j];
        if !value.is_finite() {
            return Err(format!("`{flag}`: joint `{name}` (q[{j}]) is {value}, not a finite number"));
        }
        if !(limits.lower..=limits.upper).contains(&value) {
            return Err(format!(
                "`{flag}`: joint `{name}` (q[{j}]) is {value}, outside its limits [{}, {}]",
                limits.lower, limits.upper
            ));
        }
    }
    Ok(q)
}

fn number<T: std::str::FromStr>(flag: &str, text: &str) -> Result<T, String> {
    text.parse().map_err(|_| format!("`{flag}`: `{text}` is not a valid value"))
}

fn parse(arguments: impl IntoIterator<Item = String>) -> Result<Args, String> {
    let mut args = Args {
        scenes: Vec::new(),
        start: None,
        goal: None,
        seed: 0,
        trials: None,
        detours: false,
        settings: Settings::default(),
        path_out: None,
    };
    let mut arguments = arguments.into_iter();
    while let Some(argument) = arguments.next() {
        let (flag, inline) = match argument.split_once('=') {
            Some((flag, value)) if flag.starts_with("--") => (flag.to_owned(), Some(value.to_owned())),
            _ => (argument.clone(), None),
        };
        if flag == "--help" || flag == "-h" {
            return Err(USAGE.to_owned());
        }
        if flag == "--detours" {
            args.detours = true;
            continue;
        }
        let value = match inline.or_else(|| arguments.next()) {
            Some(value) => value,
            None => return Err(format!("`{flag}` needs a value\n{USAGE}")),
        };
        match flag.as_str() {
            "--scene" => args.scenes.push(value),
            "--start" => args.start = Some(configuration("--start", &value)?),
            "--goal" => args.goal = Some(configuration("--goal", &value)?),
            "--seed" => args.seed = number(&flag, &value)?,
            "--trials" => args.trials = Some(number(&flag, &value)?),
            "--resolution" => args.settings.resolution = Resolution::JointStep(number(&flag, &value)?),
            "--states-per-unit" => args.settings.resolution = Resolution::StatesPerUnit(number(&flag, &value)?),
            "--range" => args.settings.range = number(&flag, &value)?,
            "--samples" => args.settings.samples = number(&flag, &value)?,
            "--shortcuts" => args.settings.shortcuts = number(&flag, &value)?,
            "--path-out" => args.path_out = Some(value),
            _ => return Err(format!("unknown argument `{flag}`\n{USAGE}")),
        }
    }
    if args.start.is_some() != args.goal.is_some() {
        return Err("`--start` and `--goal` go together".to_owned());
    }
    if args.trials.is_some() && (args.start.is_some() || args.path_out.is_some()) {
        return Err("`--trials` draws its own start-goal pairs and writes no path".to_owned());
    }
    if args.detours && args.trials.is_none() {
        return Err("`--detours` chooses the pairs of `--trials`".to_owned());
    }
    if args.trials == Some(0) {
        return Err("`--trials` is 0".to_owned());
    }
    if args.trials.is_none() && args.scenes.len() > 1 {
        return Err("one query plans in one scene: give one `--scene` (several go with `--trials`)".to_owned());
    }
    Ok(args)
}

fn joined(q: &Q) -> String {
    q.iter().map(|v| format!("{v:.4}")).collect::<Vec<_>>().join(", ")
}

/// A time in microseconds below a millisecond, else in milliseconds.
fn ms(d: Duration) -> String {
    let us = d.as_secs_f64() * 1e6;
    if us < 1e3 { format!("{us:.1} us") } else { format!("{:.2} ms", us / 1e3) }
}

/// The resolution as the command line gives it.
fn resolution_text(resolution: Resolution) -> String {
    match resolution {
        Resolution::JointStep(step) => format!("{step} rad a joint step"),
        Resolution::StatesPerUnit(states) => format!("{states} configurations per radian"),
    }
}

fn checks_text(c: &Checks) -> String {
    format!(
        "{} motions ({} free, {} colliding; {} configurations on the free ones)",
        c.motions,
        c.motions - c.colliding,
        c.colliding,
        c.free_configurations
    )
}

/// The scene file as named (the default relative to this repository, so it runs from anywhere).
fn load(scene: &str) -> Result<kinematics::SceneObstacles, String> {
    let path = if scene == DEFAULT_SCENE {
        format!("{}/{DEFAULT_SCENE}", env!("CARGO_MANIFEST_DIR"))
    } else {
        scene.to_owned()
    };
    kinematics::load_scene(path).map_err(|e| e.to_string())
}

/// One query: the plan, its checks and times, and the file `--path-out` names.
fn query(args: &Args) -> Result<(), String> {
    let scene_name = args.scenes.first().map_or(DEFAULT_SCENE, String::as_str);
    let scene = load(scene_name)?;
    let environment = scene.environment().map_err(|e| format!("{scene_name}: {e}"))?;
    let (start, goal) = (args.start.unwrap_or(DEFAULT_START), args.goal.unwrap_or(DEFAULT_GOAL));
    let s = args.settings;
    println!(
        "scene {scene_name}: {} obstacles; resolution {}, range {} rad, seed {}",
        scene.len(),
        resolution_text(s.resolution),
        s.range,
        args.seed
    );
    println!("start: {}\ngoal:  {}", joined(&start), joined(&goal));
    let Some(plan) = plan(&start, &goal, &environment, s, args.seed).map_err(|e| e.to_string())? else {
        return Err(format!("no path found within {} samples", s.samples));
    };
    if plan.direct {
        println!("the straight motion from start to goal is free");
    } else {
        println!(
            "search: {} sample{}, trees of {} configurations, a path of {} configurations",
            plan.samples,
            if plan.samples == 1 { "" } else { "s" },
            plan.nodes,
            plan.found
        );
    }
    println!("plan: {} configurations (radians)", plan.path.len());
    for (k, q) in plan.path.iter().enumerate() {
        println!("  {k:>3}: {}", joined(q));
    }
    println!("search: {}, {}", ms(plan.search), checks_text(&plan.search_checks));
    println!("shortcutting ({} tries): {}, {}", s.shortcuts, ms(plan.shortcut), checks_text(&plan.shortcut_checks));
    println!("planning time: {}", ms(plan.search + plan.shortcut));
    if let Some(out) = &args.path_out {
        let mut text = format!(
            "# {} configurations from start to goal, one per line, each edge a free straight motion\n\
             # robot {}, scene {scene_name}, resolution {}, seed {}\n",
            plan.path.len(),
            Panda::ROBOT,
            resolution_text(s.resolution),
            args.seed
        );
        for q in &plan.path {
            text.push_str(&q.iter().map(f64::to_string).collect::<Vec<_>>().join(","));
            text.push('\n');
        }
        std::fs::write(out, text).map_err(|e| format!("cannot write `{out}`: {e}"))?;
        println!("path written to {out}");
    }
    Ok(())
}

/// The value at quantile `p` of sorted values (nearest rank).
fn quantile<T: Copy>(sorted: &[T], p: f64) -> T {
    let rank = ((p * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len());
    sorted[rank - 1]
}

/// One solved query of `--trials`.
struct Solved {
    time: Duration,
    search: Duration,
    motions: usize,
    configurations: usize,
    direct: bool,
}

/// Quantiles of one group of solved queries.
fn summary(what: &str, solved: &[&Solved]) {
    if solved.is_empty() {
        return;
    }
    let mut times: Vec<Duration> = solved.iter().map(|s| s.time).collect();
    let mut searches: Vec<Duration> = solved.iter().map(|s| s.search).collect();
    let mut motions: Vec<usize> = solved.iter().map(|s| s.motions).collect();
    let mut lengths: Vec<usize> = solved.iter().map(|s| s.configurations).collect();
    times.sort();
    searches.sort();
    motions.sort_unstable();
    lengths.sort_unstable();
    let total: Duration = times.iter().sum();
    println!("  {what} ({}):", solved.len());
    for (name, v) in [("planning time (search and shortcutting)", &times), ("search alone", &searches)] {
        println!(
            "    {name}: median {}, 10% {}, 90% {}, max {}",
            ms(quantile(v, 0.5)),
            ms(quantile(v, 0.1)),
            ms(quantile(v, 0.9)),
            ms(quantile(v, 1.0))
        );
    }
    println!(
        "    motion checks per query: median {}, 90% {}, {:.1} us per check on average; configurations per path: \
         median {}",
        quantile(&motions, 0.5),
        quantile(&motions, 0.9),
        total.as_secs_f64() * 1e6 / motions.iter().sum::<usize>() as f64,
        quantile(&lengths, 0.5)
    );
}

/// `--trials N`: N random free start-goal pairs per scene (with `--detours`, only pairs whose
/// straight motion collides), each planned with its own seed.
fn trials(args: &Args, n: usize) -> Result<(), String> {
    let s = args.settings;
    let scenes: Vec<&str> =
        if args.scenes.is_empty() { vec![DEFAULT_SCENE] } else { args.scenes.iter().map(String::as_str).collect() };
    let kind =
        if args.detours { "free start-goal pairs whose straight motion collides" } else { "free start-goal pairs" };
    println!(
        "{n} random {kind} per scene (uniform within the limits), seed {}; resolution {}, range {} rad, at most {} \
         samples, {} shortcut tries",
        args.seed,
        resolution_text(s.resolution),
        s.range,
        s.samples,
        s.shortcuts
    );
    for name in scenes {
        let scene = load(name)?;
        let environment = scene.environment().map_err(|e| format!("{name}: {e}"))?;
        let mut draws = Configurations::within(&Panda::JOINT_LIMITS).seeded(args.seed).uniform();
        let mut free = || -> Result<Q, String> {
            loop {
                let q: Q = draws.next_array().ok_or("the Panda's limits are not seven")?;
                if !Panda::collides(&q, &environment) {
                    return Ok(q);
                }
            }
        };
        let mut pair = || -> Result<(Q, Q), String> {
            loop {
                let (start, goal) = (free()?, free()?);
                let straight = Panda::motion_collides(&start, &goal, &environment, s.resolution);
                if !args.detours || straight.map_err(|e| e.to_string())?.is_some() {
                    return Ok((start, goal));
                }
            }
        };
        let (mut solved, mut failed) = (Vec::new(), 0);
        for k in 0..n {
            let (start, goal) = pair()?;
            let seed = args.seed.wrapping_add(k as u64 + 1);
            match plan(&start, &goal, &environment, s, seed).map_err(|e| e.to_string())? {
                Some(plan) => solved.push(Solved {
                    time: plan.search + plan.shortcut,
                    search: plan.search,
                    motions: plan.search_checks.motions + plan.shortcut_checks.motions,
                    configurations: plan.path.len(),
                    direct: plan.direct,
                }),
                None => failed += 1,
            }
        }
        let direct = solved.iter().filter(|s| s.direct).count();
        println!(
            "{name} ({} obstacles): {} of {n} solved ({direct} by the straight motion), {failed} not within {} samples",
            scene.len(),
            solved.len(),
            s.samples
        );
        summary("every solved query", &solved.iter().collect::<Vec<_>>());
        if direct > 0 && direct < solved.len() {
            summary("the queries that needed a search", &solved.iter().filter(|s| !s.direct).collect::<Vec<_>>());
        }
    }
    Ok(())
}

fn main() {
    let result = parse(std::env::args().skip(1)).and_then(|args| match args.trials {
        Some(n) => trials(&args, n),
        None => query(&args),
    });
    if let Err(message) = result {
        eprintln!("error: {message}");
        std::process::exit(1);
    }
}

/// Run by `cargo test` (`test = true` in the manifest): plans checked edge by edge, by the compiled
/// motion check and by the runtime reference (parry3d-f64's distances at the same configurations).
#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

    use kinematics::model::collision::{Cover, Meshes, link_spheres, sphere_pairs};

    use super::*;

    /// Every edge of `path` from `start` to `goal`: free by `motion_collides`, and every one of its
    /// checked configurations farther than 1e-9 m from contact by the reference.
    fn check_path(path: &[Q], start: &Q, goal: &Q, scene: &kinematics::SceneObstacles, resolution: Resolution) {
        assert_eq!((path.first(), path.last()), (Some(start), Some(goal)));
        let environment = scene.environment().unwrap();
        let reference = Panda::reference().unwrap();
        let tree = reference.tree();
        let spheres = link_spheres(tree, &Cover::default(), Meshes::Read).unwrap();
        let srdf = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/robots/panda.srdf")).unwrap();
        let disabled = kinematics::model::srdf::parse_srdf(&srdf).unwrap().disabled_pairs(tree).unwrap();
        let pairs = sphere_pairs(tree, &spheres, Some(&disabled)).pairs;
        let obstacles = scene.reference();
        for edge in path.windows(2) {
            assert_eq!(Panda::motion_collides(&edge[0], &edge[1], &environment, resolution).unwrap(), None);
            let motion = Motion::new(Panda::ROBOT, edge[0], edge[1], resolution).unwrap();
            for k in 0..=motion.steps() {
                let q = motion.configuration(k);
                let d = reference.obstacle_distance(&q, &spheres, &obstacles).unwrap();
                let s = reference.self_distance(&q, &spheres, &pairs).unwrap();
                assert!(d > 1e-9 && s > 1e-9, "{q:?} on {edge:?}: obstacles {d} m, self {s} m");
            }
        }
    }

    #[test]
    fn the_default_query_takes_a_detour_every_edge_of_which_is_free() {
        let scene = load(DEFAULT_SCENE).unwrap();
        let environment = scene.environment().unwrap();
        let settings = Settings::default();
        let straight = Panda::motion_collides(&DEFAULT_START, &DEFAULT_GOAL, &environment, settings.resolution);
        assert!(straight.unwrap().is_some(), "the default query needs a detour");
        let plan = plan(&DEFAULT_START, &DEFAULT_GOAL, &environment, settings, 0).unwrap().unwrap();
        assert!(!plan.direct && plan.path.len() >= 3 && plan.path.len() <= plan.found);
        check_path(&plan.path, &DEFAULT_START, &DEFAULT_GOAL, &scene, settings.resolution);
        // The same seed, the same plan and the same checks.
        let again = super::plan(&DEFAULT_START, &DEFAULT_GOAL, &environment, settings, 0).unwrap().unwrap();
        assert_eq!(
            (again.path, again.search_checks, again.shortcut_checks),
            (plan.path, plan.search_checks, plan.shortcut_checks)
        );
    }

    #[test]
    fn random_detours_in_the_shelf_are_free_edge_by_edge() {
        let scene = load(&format!("{}/scenes/shelf.toml", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let environment = scene.environment().unwrap();
        // A joint step, and (the third plan) states per radian as VAMP counts them.
        let resolutions = [Resolution::JointStep(0.1), Resolution::JointStep(0.1), Resolution::StatesPerUnit(16.0)];
        let mut draws = Configurations::within(&Panda::JOINT_LIMITS).seeded(3).uniform();
        let mut free = || loop {
            let q: Q = draws.next_array().unwrap();
            if !Panda::collides(&q, &environment) {
                return q;
            }
        };
        let mut planned = 0;
        while planned < 3 {
            let settings = Settings { resolution: resolutions[planned as usize], ..Settings::default() };
            let (start, goal) = (free(), free());
            if Panda::motion_collides(&start, &goal, &environment, settings.resolution).unwrap().is_none() {
                continue;
            }
            let plan = plan(&start, &goal, &environment, settings, planned).unwrap().expect("a path");
            check_path(&plan.path, &start, &goal, &scene, settings.resolution);
            planned += 1;
        }
    }

    #[test]
    fn bad_input_is_refused_naming_it() {
        let args = |list: &[&str]| parse(list.iter().map(|s| (*s).to_owned()));
        let error = |list: &[&str]| args(list).unwrap_err();
        assert_eq!(
            error(&["--start", "0,0,0", "--goal", "0,0,0,-1,0,1,0"]),
            "`--start` has 3 values; the Panda has 7 joints"
        );
        assert_eq!(
            error(&["--start", "0,0,0,-1,0,NaN,0"]),
            "`--start`: joint `panda_joint6` (q[5]) is NaN, not a finite number"
        );
        assert!(
            error(&["--goal", "0,0,0,1,0,1,0"])
                .starts_with("`--goal`: joint `panda_joint4` (q[3]) is 1, outside its limits")
        );
        assert_eq!(error(&["--start", "0,x,0,-1,0,1,0"]), "`--start`: `x` is not a number");
        assert_eq!(error(&["--start", "0,0,0,-1,0,1,0"]), "`--start` and `--goal` go together");
        assert_eq!(error(&["--trials", "0"]), "`--trials` is 0");
        assert_eq!(error(&["--detours"]), "`--detours` chooses the pairs of `--trials`");
        assert!(error(&["--seed", "-1"]).starts_with("`--seed`: `-1` is not"));
        assert!(error(&["--frobnicate", "1"]).starts_with("unknown argument `--frobnicate`"));
        assert!(error(&["--scene"]).starts_with("`--scene` needs a value"));
        let scene = load(DEFAULT_SCENE).unwrap();
        let environment = scene.environment().unwrap();
        for (settings, message) in [
            (
                Settings { resolution: Resolution::JointStep(f64::NAN), ..Settings::default() },
                "`--resolution` is NaN (must be positive and finite)",
            ),
            (
                Settings { resolution: Resolution::StatesPerUnit(0.0), ..Settings::default() },
                "`--states-per-unit` is 0 (must be positive and finite)",
            ),
            (Settings { range: 0.0, ..Settings::default() }, "`--range` is 0 (must be positive and finite)"),
        ] {
            let refused = plan(&DEFAULT_START, &DEFAULT_GOAL, &environment, settings, 0).unwrap_err();
            assert_eq!(refused.to_string(), message);
        }
        let inside_the_table = [0.0, 1.5, 0.0, -0.5, 0.0, 1.0, 0.0];
        let refused = plan(&DEFAULT_START, &inside_the_table, &environment, Settings::default(), 0).unwrap_err();
        assert!(refused.to_string().starts_with("the goal configuration"), "{refused}");
        let given = args(&["--start=-0.5,0,0,-1,0,1,0", "--goal", "0,0,0,-1,0,1,0", "--seed=7"]).unwrap();
        assert_eq!((given.start.unwrap()[0], given.seed), (-0.5, 7));
    }
}
