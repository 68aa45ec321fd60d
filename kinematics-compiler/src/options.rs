//! The options of one compiled robot, written once: what the derive's keys, the build API's calls
//! and the CLI's flags all set ([`Options`]), the rules between them (one function each, every
//! fault naming its [`OptionKey`]), and the choices written as words (`trig`, `ik`) with their
//! names and a "did you mean" ([`Choice`]).
//!
//! A front end fills an [`Options`], calls [`Options::check`] against the loaded tree, and maps
//! each [`OptionFault`]'s key to where the user wrote it: the derive to the key's span, the build
//! API to its method, the CLI to its flag. Only a [`Checked`] robot can be emitted
//! ([`crate::robot::emit_robot`]), and it carries what the checks found (the inverse kinematics'
//! plan), so nothing is worked out twice.
//!
//! `Options` is everything a compiled robot can be asked for. The rules (one function each): links
//! the robot has, none listed twice, `links` not empty, `jacobians` needs a tip, a scalar type,
//! `ik`'s one tip, a robot without a floating or spherical joint and a covered chain,
//! `floating_base`'s new names. Every front end maps an `OptionKey` exhaustively to its span, call
//! or flag. The `Checked` robot holds the IK plan, so `classify` runs once. `Choice` lists are read
//! with `choose`'s "did you mean".

use crate::dynamics::DynamicsRequest;
use kinematics_model::collision::{
    CollisionPairs, CoverError, FixedPair, LinkSphere, PairGrid, fixed_apart_pairs, link_spheres, pair_grids,
    sphere_pairs,
};
pub use kinematics_model::collision::{Cover, Meshes};
use kinematics_model::srdf::Srdf;
use kinematics_model::{ExactAngles, FLOATING_BASE_JOINT, KinematicTree, UnknownLink};

use crate::CompileError;
pub use crate::emit::Trig;
use crate::ik::IkPlan;

/// Which scalar types get typed functions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Scalars {
    /// `f64` functions (`tip_pose`).
    pub f64: bool,
    /// `f32` functions (`tip_pose_f32`).
    pub f32: bool,
}

impl Default for Scalars {
    fn default() -> Self {
        Scalars { f64: true, f32: false }
    }
}

/// Which inverse kinematics to emit (of the one tip).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum IkMode {
    /// None.
    #[default]
    Off,
    /// The closed form of the tip's family (`tip_ik`, `tip_ik_nearest`, `tip_ik_within_limits`,
    /// `IK_FAMILY`) and beside it the numeric solver (`tip_ik_numeric`); a chain no family covers
    /// is a fault naming why.
    ClosedForm {
        /// For a seven-joint arm, the joint whose value `tip_ik` takes as an input.
        free: Option<String>,
    },
    /// The numeric solver only (`tip_ik_numeric`, `tip_ik_numeric_with`), for any chain.
    Numeric,
}

/// The kinds of inverse kinematics a word can name (`ik = "numeric"`, `--ik numeric`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IkKind {
    /// The closed form of the tip's family, and the numeric solver.
    ClosedForm,
    /// The numeric solver only.
    Numeric,
}

/// Everything a compiled robot can be asked for. The description itself, and how a front end
/// names the generated type and reaches the `kinematics` crate, are the front end's.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Options {
    /// The frame poses are expressed in (default: the root link).
    pub base: Option<String>,
    /// Tip links: one gives `tip_pose`, several `tip_poses`.
    pub tips: Vec<String>,
    /// The links `link_poses` (and `link_positions`, `LINK_NAMES`) return, in this order; `None`
    /// for every link but the base. An empty list is a fault, not every link.
    pub links: Option<Vec<String>>,
    /// Also emit position-only functions.
    pub positions: bool,
    /// Also emit the tips' velocities (needs a tip).
    pub jacobians: bool,
    /// Also emit inverse kinematics of the tip (needs exactly one tip).
    pub ik: IkMode,
    /// A free-flying root: the new root link's name, joined to the description's root by the
    /// floating joint [`FLOATING_BASE_JOINT`].
    pub floating_base: Option<String>,
    /// Scalar types (at least one).
    pub scalars: Scalars,
    /// Which sine and cosine the code calls.
    pub trig: Trig,
    /// The exactness policy the description is read with.
    pub exact_angles: ExactAngles,
    /// Also emit collision checking: the robot's geometry as spheres.
    pub collision: Option<CollisionOptions>,
    /// Also emit the dynamics from the links' inertias, under this gravity.
    pub dynamics: Option<DynamicsRequest>,
}

/// How a robot's collision geometry becomes spheres, and which links are checked against which.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CollisionOptions {
    /// How each link's geometry becomes spheres: a budget per link (`spheres`), an overshoot
    /// (`sphere_cover`, metres), or both; [`Cover::default`] unless given.
    pub cover: Cover,
    /// What to do with meshes: covered (the default; their triangles read by the front end) or
    /// left out.
    pub meshes: Meshes,
    /// An SRDF's disabled pairs (MoveIt's `<disable_collisions>`), read by the front end.
    pub srdf: Option<Srdf>,
}

/// An option, as the fault it caused names it. Each front end maps it to where the user wrote it
/// (exhaustively: a new option is a compile error in every front end until it is mapped).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OptionKey {
    /// `base`.
    Base,
    /// The tip with this index in [`Options::tips`].
    Tip(usize),
    /// The entry with this index in [`Options::links`].
    Link(usize),
    /// `links` as a whole.
    Links,
    /// `positions`.
    Positions,
    /// `jacobians`.
    Jacobians,
    /// `ik` (its kind or its free joint).
    Ik,
    /// `floating_base`.
    FloatingBase,
    /// `scalars`.
    Scalars,
    /// `trig`.
    Trig,
    /// `exact_angles`.
    ExactAngles,
    /// `collision` (its geometry, its meshes).
    Collision,
    /// `collision`'s `sphere_cover`.
    SphereCover,
    /// `collision`'s `spheres`.
    Spheres,
    /// `collision`'s `srdf`.
    Srdf,
    /// `dynamics` (the robot's inertias).
    Dynamics,
    /// `dynamics`' `gravity`.
    Gravity,
    /// The link with this index in `dynamics`' `forces` ([`DynamicsRequest::forces`]).
    ForceLink(usize),
}

impl OptionKey {
    /// The option's name, as the derive's key and the guide spell it.
    pub fn name(self) -> &'static str {
        match self {
            OptionKey::Base => "base",
            OptionKey::Tip(_) => "tip",
            OptionKey::Link(_) | OptionKey::Links => "links",
            OptionKey::Positions => "positions",
            OptionKey::Jacobians => "jacobians",
            OptionKey::Ik => "ik",
            OptionKey::FloatingBase => "floating_base",
            OptionKey::Scalars => "scalars",
            OptionKey::Trig => "trig",
            OptionKey::ExactAngles => "exact_angles",
            OptionKey::Collision => "collision",
            OptionKey::SphereCover => "sphere_cover",
            OptionKey::Spheres => "spheres",
            OptionKey::Srdf => "srdf",
            OptionKey::Dynamics => "dynamics",
            OptionKey::Gravity => "gravity",
            OptionKey::ForceLink(_) => "forces",
        }
    }
}

/// One broken rule, and the option that broke it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind}")]
pub struct OptionFault {
    /// The option to point at.
    pub key: OptionKey,
    /// What is wrong.
    pub kind: FaultKind,
}

/// What is wrong with the options (messages name the option, lower-case, no final period).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FaultKind {
    /// A base, tip or listed link the robot does not have (with "did you mean").
    #[error(transparent)]
    UnknownLink(UnknownLink),
    /// A link listed twice in `links`.
    #[error("link `{link}` is listed twice in `links`")]
    DuplicateLink {
        /// The link.
        link: String,
    },
    /// `links` with no link in it.
    #[error("`links` lists no link: name at least one, or leave the option out for every link")]
    EmptyLinks,
    /// `jacobians` with no tip.
    #[error("`jacobians` needs a tip: the Jacobians are the tips' (add the link whose velocity you want)")]
    JacobiansWithoutTip,
    /// `floating_base` naming a link, or adding a joint, the description already has.
    #[error(
        "`floating_base` adds a root link `{link}` and a floating joint `{FLOATING_BASE_JOINT}`, but the description \
         already has a {clash} (give the new root link another name)"
    )]
    FloatingBaseClash {
        /// The new root link asked for.
        link: String,
        /// What clashes (``link `world` ``).
        clash: String,
    },
    /// No scalar type at all.
    #[error("name at least one scalar type: `f64`, `f32` or both")]
    NoScalar,
    /// `ik` with other than one tip.
    #[error("`ik` needs exactly one tip: the inverse kinematics is the tip's ({tips} tips given)")]
    IkTips {
        /// How many tips were given.
        tips: usize,
    },
    /// `ik` of a robot with a floating or spherical joint (a quaternion in `q`, four entries
    /// against three velocities).
    #[error("`ik` of a robot with a {kind} joint (`{joint}`, a quaternion in `q`) is not supported yet")]
    IkQuaternionJoint {
        /// The first such joint, in tree order.
        joint: String,
        /// Its kind (`floating` or `spherical`).
        kind: &'static str,
    },
    /// `ik` of a chain no closed-form family covers (every family's reason), or whose free joint
    /// is not in it.
    #[error("{0}")]
    NoIkFamily(Box<CompileError>),
    /// A link whose geometry could not be covered (a mesh not read, an overshoot out of reach).
    #[error(transparent)]
    Cover(CoverError),
    /// `sphere_cover` that is no positive finite length.
    #[error("`sphere_cover` is {0} (must be a finite positive length in metres)")]
    SphereCover(f64),
    /// `spheres` of zero.
    #[error("`spheres` is 0 (must be at least one sphere per link)")]
    Spheres,
    /// `collision` of a robot with no collision geometry (or only meshes, left out).
    #[error("`collision` of a robot with no collision geometry: no link has a <collision> element the check can read")]
    NoGeometry,
    /// An SRDF whose disabled pairs name a link the robot does not have.
    #[error("{0}")]
    Srdf(String),
    /// `dynamics` of a robot whose inertias break a rigid body's rules, or whose mass is left to
    /// its geometry (the link and the line named).
    #[error("{0}")]
    Dynamics(Box<CompileError>),
    /// `dynamics` of a robot none of whose links has an inertia.
    #[error("`dynamics` of a robot with no mass: no link has an <inertial> (a link without one is massless)")]
    NoMass,
    /// `gravity` that is not a finite vector.
    #[error("`gravity` is {0:?} (must be three finite numbers, m/s^2 in the root link's frame)")]
    Gravity([f64; 3]),
    /// A link of `forces` that cannot take an external force.
    #[error(transparent)]
    ForceLink(crate::dynamics::ForceLinkFault),
}

/// Options that passed every rule against their robot: the only thing
/// [`crate::robot::emit_robot`] takes, holding what the rules found.
#[derive(Debug, Clone)]
pub struct Checked<'a> {
    tree: &'a KinematicTree,
    options: &'a Options,
    base: String,
    ik: CheckedIk,
    collision: Option<CollisionPlan>,
}

/// A robot's collision geometry as the check uses it: every sphere, in the robot's sphere order,
/// the link pairs its self-collision check tests, and the sphere pairs among them held apart for
/// good, which the distances leave out.
#[derive(Debug, Clone, PartialEq)]
pub struct CollisionPlan {
    /// The spheres.
    pub spheres: Vec<LinkSphere>,
    /// The pairs.
    pub pairs: CollisionPairs,
    /// The sphere pairs of `pairs` whose distance no joint changes (the model's
    /// `fixed_apart_pairs`).
    pub fixed: Vec<FixedPair>,
    /// The grids deciding the pairs one or two joints move (the model's `pair_grids`).
    pub grids: Vec<PairGrid>,
}

/// The inverse kinematics a checked robot gets.
#[derive(Debug, Clone)]
pub enum CheckedIk {
    /// None.
    Off,
    /// The closed form of `plan` (its tip is the one tip), and the numeric solver.
    ClosedForm(Box<IkPlan>),
    /// The numeric solver only, of the one tip.
    Numeric,
}

impl<'a> Checked<'a> {
    /// The robot.
    pub fn tree(&self) -> &'a KinematicTree {
        self.tree
    }

    /// The options.
    pub fn options(&self) -> &'a Options {
        self.options
    }

    /// The base link: the one given, or the root.
    pub fn base(&self) -> &str {
        &self.base
    }

    /// The inverse kinematics asked for, with its plan.
    pub fn ik(&self) -> &CheckedIk {
        &self.ik
    }

    /// The collision geometry, when `collision` is asked for.
    pub fn collision(&self) -> Option<&CollisionPlan> {
        self.collision.as_ref()
    }

    /// The links `link_poses` returns as the options list them (empty for every link).
    pub fn listed_links(&self) -> &'a [String] {
        self.options.links.as_deref().unwrap_or_default()
    }
}

/// Why options were refused: every fault (never empty), and the inverse kinematics' plan when it
/// was found all the same (so the derive's stub has its real types).
#[derive(Debug, Clone)]
pub struct Rejected {
    /// Every broken rule, in the order of [`Options::check`]'s rules.
    pub faults: Vec<OptionFault>,
    /// The plan, if `ik` asked for a closed form and the chain has one.
    pub ik_plan: Option<Box<IkPlan>>,
}

impl std::fmt::Display for Rejected {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let faults: Vec<String> = self.faults.iter().map(|fault| format!("`{}`: {fault}", fault.key.name())).collect();
        write!(f, "{}", faults.join("; "))
    }
}

impl std::error::Error for Rejected {}

impl Options {
    /// Runs every rule that needs no robot: the faults a front end can report even when the
    /// description did not load.
    pub fn check_alone(&self) -> Vec<OptionFault> {
        [links_not_empty(self), jacobians_need_a_tip(self), some_scalar(self), sphere_cover_positive(self)]
            .into_iter()
            .flatten()
            .collect()
    }

    /// Runs every rule against `tree` (loaded with [`Options::floating_base`] when it is set):
    /// the checked robot, or every fault.
    pub fn check<'a>(&'a self, tree: &'a KinematicTree) -> Result<Checked<'a>, Rejected> {
        let mut faults = known_links(self, tree);
        faults.extend(links_unique(self));
        faults.extend(self.check_alone());
        // The inverse kinematics is judged only on links that exist.
        let ik = if faults.iter().any(|f| matches!(f.kind, FaultKind::UnknownLink(_))) {
            None
        } else {
            match ik_applies(self, tree) {
                Ok(ik) => Some(ik),
                Err(fault) => {
                    faults.push(fault);
                    None
                }
            }
        };
        let collision = match collision_applies(self, tree) {
            Ok(plan) => plan,
            Err(fault) => {
                faults.push(fault);
                None
            }
        };
        faults.extend(dynamics_applies(self, tree));
        let base = self.base.clone().unwrap_or_else(|| tree.link(tree.root()).name.clone());
        match ik {
            Some(ik) if faults.is_empty() => Ok(Checked { tree, options: self, base, ik, collision }),
            ik => Err(Rejected {
                faults,
                ik_plan: match ik {
                    Some(CheckedIk::ClosedForm(plan)) => Some(plan),
                    _ => None,
                },
            }),
        }
    }
}

/// Rule: the base, every tip and every listed link are links of the robot.
fn known_links(options: &Options, tree: &KinematicTree) -> Vec<OptionFault> {
    let base = options.base.iter().map(|b| (OptionKey::Base, "base", b));
    let tips = options.tips.iter().enumerate().map(|(i, t)| (OptionKey::Tip(i), "tip", t));
    let listed = options.links.iter().flatten().enumerate().map(|(i, l)| (OptionKey::Link(i), "listed", l));
    base.chain(tips)
        .chain(listed)
        .filter_map(|(key, role, link)| {
            tree.find_link(role, link).err().map(|e| OptionFault { key, kind: FaultKind::UnknownLink(e) })
        })
        .collect()
}

/// Rule: no link is listed twice in `links` (the second is the fault).
fn links_unique(options: &Options) -> Vec<OptionFault> {
    let links = options.links.as_deref().unwrap_or_default();
    links
        .iter()
        .enumerate()
        .filter(|(i, link)| links[..*i].contains(link))
        .map(|(i, link)| OptionFault { key: OptionKey::Link(i), kind: FaultKind::DuplicateLink { link: link.clone() } })
        .collect()
}

/// Rule: `links`, when given, lists at least one link (an empty list would be a robot without
/// link poses; leaving the option out means every link).
fn links_not_empty(options: &Options) -> Option<OptionFault> {
    options
        .links
        .as_ref()
        .is_some_and(Vec::is_empty)
        .then_some(OptionFault { key: OptionKey::Links, kind: FaultKind::EmptyLinks })
}

/// Rule: `jacobians` needs a tip (the Jacobians are the tips').
fn jacobians_need_a_tip(options: &Options) -> Option<OptionFault> {
    (options.jacobians && options.tips.is_empty())
        .then_some(OptionFault { key: OptionKey::Jacobians, kind: FaultKind::JacobiansWithoutTip })
}

/// Rule: at least one scalar type.
fn some_scalar(options: &Options) -> Option<OptionFault> {
    (!options.scalars.f64 && !options.scalars.f32)
        .then_some(OptionFault { key: OptionKey::Scalars, kind: FaultKind::NoScalar })
}

/// Rule: `ik` has exactly one tip, a robot without a floating or spherical joint, and for the closed form a
/// chain some family covers (the plan is kept for emission).
fn ik_applies(options: &Options, tree: &KinematicTree) -> Result<CheckedIk, OptionFault> {
    let fault = |kind| OptionFault { key: OptionKey::Ik, kind };
    let free = match &options.ik {
        IkMode::Off => return Ok(CheckedIk::Off),
        IkMode::ClosedForm { free } => free.as_deref(),
        IkMode::Numeric => None,
    };
    let [tip] = options.tips.as_slice() else {
        return Err(fault(FaultKind::IkTips { tips: options.tips.len() }));
    };
    if let Some(joint) = tree.quaternion_joints().next().map(|j| tree.joint(j)) {
        return Err(fault(FaultKind::IkQuaternionJoint { joint: joint.name.clone(), kind: joint.kind.name() }));
    }
    if options.ik == IkMode::Numeric {
        return Ok(CheckedIk::Numeric);
    }
    let base = options.base.clone().unwrap_or_else(|| tree.link(tree.root()).name.clone());
    crate::ik::classify_with(tree, &base, tip, free)
        .map(|plan| CheckedIk::ClosedForm(Box::new(plan)))
        .map_err(|e| fault(FaultKind::NoIkFamily(Box::new(e))))
}

/// Rule: the sphere budget is at least one and the overshoot a finite positive length.
fn sphere_cover_positive(options: &Options) -> Option<OptionFault> {
    let cover = options.collision.as_ref()?.cover;
    if cover.spheres == Some(0) {
        return Some(OptionFault { key: OptionKey::Spheres, kind: FaultKind::Spheres });
    }
    let d = cover.overshoot?;
    (!(d.is_finite() && d > 0.0))
        .then_some(OptionFault { key: OptionKey::SphereCover, kind: FaultKind::SphereCover(d) })
}

/// Rule: `collision` needs geometry the cover can read (a mesh is refused unless meshes are left
/// out) and an SRDF naming links of the robot; the spheres and pairs are kept for emission.
fn collision_applies(options: &Options, tree: &KinematicTree) -> Result<Option<CollisionPlan>, OptionFault> {
    let Some(collision) = &options.collision else { return Ok(None) };
    let fault = |kind| OptionFault { key: OptionKey::Collision, kind };
    if sphere_cover_positive(options).is_some() {
        // Reported by `check_alone`.
        return Ok(None);
    }
    let spheres = link_spheres(tree, &collision.cover, collision.meshes).map_err(|e| fault(FaultKind::Cover(e)))?;
    if spheres.is_empty() {
        return Err(fault(FaultKind::NoGeometry));
    }
    let disabled = match &collision.srdf {
        Some(srdf) => {
            let srdf_fault =
                |e| OptionFault { key: OptionKey::Srdf, kind: FaultKind::Srdf(format!("{}: {e}", srdf.file)) };
            Some(srdf.disabled_pairs(tree).map_err(srdf_fault)?)
        }
        None => None,
    };
    let pairs = sphere_pairs(tree, &spheres, disabled.as_ref());
    let fixed = fixed_apart_pairs(tree, &spheres, &pairs.pairs);
    let grids = pair_grids(tree, &spheres, &pairs.pairs);
    Ok(Some(CollisionPlan { spheres, pairs, fixed, grids }))
}

/// Rule: `dynamics` needs a finite gravity, a link with mass, inertias that keep a rigid body's
/// rules (the triangle inequality unless taken as written) with none left to geometry, and
/// `forces` naming links of the robot, each once, each below a moving joint: every link at fault
/// is reported, not only the first.
fn dynamics_applies(options: &Options, tree: &KinematicTree) -> Vec<OptionFault> {
    let Some(request) = options.dynamics.as_ref() else { return Vec::new() };
    let mut faults = Vec::new();
    if request.gravity.iter().any(|x| !x.is_finite()) {
        faults.push(OptionFault { key: OptionKey::Gravity, kind: FaultKind::Gravity(request.gravity) });
    }
    let fault = |kind| OptionFault { key: OptionKey::Dynamics, kind };
    faults.extend(
        crate::dynamics::link_faults(tree, request).into_iter().map(|e| fault(FaultKind::Dynamics(Box::new(e)))),
    );
    if tree.links().iter().all(|l| l.inertial.is_none()) {
        faults.push(fault(FaultKind::NoMass));
    }
    faults.extend(
        crate::dynamics::force_link_faults(tree, request)
            .into_iter()
            .map(|(i, e)| OptionFault { key: OptionKey::ForceLink(i), kind: FaultKind::ForceLink(e) }),
    );
    faults
}

/// Rule: `floating_base`'s new root link and joint are names `plain` (the description loaded
/// without a floating base) does not have.
pub fn floating_base_clash(plain: &KinematicTree, link: &str) -> Option<OptionFault> {
    let clash = if plain.link_id(link).is_some() {
        format!("link `{link}`")
    } else {
        plain.joint_id(FLOATING_BASE_JOINT).map(|_| format!("joint `{FLOATING_BASE_JOINT}`"))?
    };
    Some(OptionFault {
        key: OptionKey::FloatingBase,
        kind: FaultKind::FloatingBaseClash { link: link.to_owned(), clash },
    })
}

/// An option whose value is one of a few words (`trig = "std"`, `ik = "numeric"`): the words, what
/// each means, and the value each stands for, written once for every front end.
pub trait Choice: Copy + PartialEq + 'static {
    /// The option (`trig`).
    const KEY: OptionKey;
    /// The word's own name in messages (`trig`, `meshes`).
    const NAME: &'static str;
    /// Each word, its value and what it means, the default first where there is one.
    const CHOICES: &'static [(&'static str, Self, &'static str)];

    /// The word for this value.
    fn word(self) -> &'static str {
        Self::CHOICES.iter().find(|(_, value, _)| *value == self).map_or("", |(word, ..)| word)
    }
}

impl Choice for Trig {
    const KEY: OptionKey = OptionKey::Trig;
    const NAME: &'static str = "trig";
    const CHOICES: &'static [(&'static str, Self, &'static str)] = &[
        ("fast", Trig::Fast, "our sin/cos, every angle in one call; the default"),
        ("std", Trig::Std, "the platform's, one call per angle"),
    ];
}

impl Choice for IkKind {
    const KEY: OptionKey = OptionKey::Ik;
    const NAME: &'static str = "ik";
    const CHOICES: &'static [(&'static str, Self, &'static str)] = &[
        ("closed_form", IkKind::ClosedForm, "the closed form of the tip's family, and the numeric solver"),
        ("numeric", IkKind::Numeric, "the numeric solver only, for any chain"),
    ];
}

impl Choice for Meshes {
    const KEY: OptionKey = OptionKey::Collision;
    const NAME: &'static str = "meshes";
    const CHOICES: &'static [(&'static str, Self, &'static str)] = &[
        ("read", Meshes::Read, "meshes are read and covered like any geometry; the default"),
        ("skip", Meshes::Skip, "meshes are left out of the check"),
    ];
}

/// A word that names none of an option's choices.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown {key} `{word}`{}: expected {expected}", suggestion.map(|s| format!(" (did you mean \"{s}\"?)")).unwrap_or_default())]
pub struct UnknownChoice {
    /// The option's name.
    pub key: &'static str,
    /// The word given.
    pub word: String,
    /// The closest choice, when the word looks like a typo of it.
    pub suggestion: Option<&'static str>,
    /// Every choice with what it means.
    pub expected: String,
}

/// The value `word` names among `C`'s choices.
///
/// ```
/// use kinematics_compiler::options::{choose, Trig};
/// assert_eq!(choose::<Trig>("std"), Ok(Trig::Std));
/// let wrong = choose::<Trig>("sdt").unwrap_err();
/// assert_eq!(wrong.suggestion, Some("std"));
/// assert!(wrong.to_string().starts_with("unknown trig `sdt` (did you mean \"std\"?): expected \"fast\""));
/// ```
pub fn choose<C: Choice>(word: &str) -> Result<C, UnknownChoice> {
    if let Some((_, value, _)) = C::CHOICES.iter().find(|(w, ..)| *w == word) {
        return Ok(*value);
    }
    let expected: Vec<String> = C::CHOICES.iter().map(|(w, _, what)| format!("\"{w}\" ({what})")).collect();
    Err(UnknownChoice {
        key: C::NAME,
        word: word.to_owned(),
        suggestion: kinematics_model::closest(word, C::CHOICES.iter().map(|(w, ..)| *w)),
        expected: expected.join(" or "),
    })
}
