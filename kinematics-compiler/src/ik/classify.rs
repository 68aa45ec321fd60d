//! Which closed-form family solves a chain, decided at compile time from its zero-configuration
//! geometry: each family's relations ([`super::families`]) checked in turn and applied, which
//! axes are parallel and which meet, exactly where the description is exact
//! (quarter turns give exact zeros) or within [`PARALLEL_TOLERANCE`] and [`MEET_TOLERANCE`] times
//! the chain's reach. A family's solver assumes its parallel axes are exactly parallel, so within
//! tolerance the plan writes the later axis as the earlier one (with its sign); the pose errors
//! every solution carries show what that costs.
//!
//! Offsets along an axis do not change the robot (a point may slide along its axis line), so the
//! plan places the points of meeting axes at their common point: a spherical wrist's three points
//! at the wrist centre (`p45 = p56 = 0`), a UR's last two at theirs (`p56 = 0`), and so on.
//!
//! A distance joint in line with its offsets is refused. Every six-joint plan is then run through
//! its own solver on eight sample poses of the arm and taken only if it finds at least six of them
//! (the check that catches an arm degenerate for a family in ways no relation of two axes shows).
//! With a free joint, only families whose relations keep to one side of it are tried, checked at
//! five of its angles. Chains of two to four joints are tried as planar arms. The result is an
//! `IkPlan` with its `IkGeometry` (a six-joint family with its geometry and free joint, or a
//! planar arm), or `NoIkFamily` with every family's reason.

use kinematics_model::{JointKind, KinematicTree};

use kinematics_core::ik::Arm6;
use kinematics_core::ik::vector::{cross, dot, norm_squared, rotate_cs, sub};

use super::families::{IkFamily, Relation, SixFamily};
use super::geometry::{M3, V3, ZeroConfiguration, zero_configuration};
use crate::error::{CompileError, NoIkFamily};

/// Axes whose directions differ by less than this (the sine of the angle between them) are
/// parallel.
pub const PARALLEL_TOLERANCE: f64 = 1e-12;

/// Axes that pass closer than this times the chain's reach meet.
pub const MEET_TOLERANCE: f64 = 1e-12;

/// A change of the geometry below this (radians, or times the reach) is rounding of its
/// computation, which leaves the solutions within rounding of the arm as written: such a plan is
/// not [`IkPlan::made_exact`].
const PLAN_ROUNDING: f64 = 1e-15;

/// The joint of a seven-joint arm whose value is given, so that the other six are solved in
/// closed form.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeJoint {
    /// Joint name.
    pub name: String,
    /// Its entry of `q` (and its place among the chain's seven moving joints).
    pub index: usize,
    /// Its unit axis at `q = 0`.
    pub axis: V3,
    /// A point on it.
    pub point: V3,
}

/// How to solve a chain in closed form: the family and the geometry its solver takes.
#[derive(Debug, Clone, PartialEq)]
pub struct IkPlan {
    /// The base link.
    pub base: String,
    /// The tip link.
    pub tip: String,
    /// The joints solved, base first (for a six-joint family their entries of `q` are `0..6`, or
    /// `0..7` less the free joint's; for a planar arm, `q` itself).
    pub joints: Vec<String>,
    /// The family and the geometry its solver takes.
    pub geometry: IkGeometry,
    /// The chain's reach (the scale of its distances).
    pub reach: f64,
    /// What the plan changed of the description's geometry (points moved along their axes,
    /// axes within tolerance made parallel), for `kinematics inspect` and `expr --ik`.
    pub notes: Vec<String>,
    /// Whether the geometry the family solves differs from the description's (an axis within
    /// tolerance made parallel to another, or a common point of axes that pass within tolerance
    /// of each other off one of them): its solutions then miss the arm as written by about what
    /// was changed, and `tip_ik` refines every one of them (points moved along their own axes
    /// change nothing).
    pub made_exact: bool,
}

/// The family and the geometry its solver takes: a six-joint family with six-joint geometry, or
/// a planar arm (no other combination can be written).
#[derive(Debug, Clone, PartialEq)]
pub enum IkGeometry {
    /// A six-joint arm (`kinematics_core::ik::Arm6`, or `FreeArm6` with a free joint).
    Six {
        /// Its family.
        family: SixFamily,
        /// Its geometry.
        arm: Box<SixGeometry>,
        /// The seventh joint whose value is an input, for a seven-joint arm.
        free: Option<FreeJoint>,
    },
    /// A planar arm (`kinematics_core::ik::PlanarArm`).
    Planar(PlanarGeometry),
}

/// A six-joint arm at `q = 0` in IK-Geo's form.
#[derive(Debug, Clone, PartialEq)]
pub struct SixGeometry {
    /// Unit axes `h1..h6` in the base frame.
    pub axes: [V3; 6],
    /// `p01, p12, ..., p56, p6T` between the chosen points on the axes.
    pub offsets: [V3; 7],
    /// The tip's rotation at `q = 0`.
    pub tool_rotation: M3,
    /// The points chosen on the axes (`offsets` are their differences).
    pub points: [V3; 6],
    /// The tip's origin at `q = 0`.
    pub tip_point: V3,
}

/// A planar arm at `q = 0`: the common axis direction and, per joint of `q`, how it moves.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarGeometry {
    /// The unit direction every axis is parallel to.
    pub axis: V3,
    /// Per entry of `q`: `Some(point)` for a revolute joint (a point on its axis) or `None` for
    /// the prismatic one, with the sign of its axis against `axis`.
    pub joints: Vec<(f64, Option<V3>)>,
    /// The tip's origin at `q = 0`.
    pub tip_point: V3,
    /// The tip's rotation at `q = 0`.
    pub tool_rotation: M3,
}

impl SixGeometry {
    /// The arm as the core's solvers take it.
    pub fn arm(&self) -> Arm6 {
        Arm6 { axes: self.axes, offsets: self.offsets, tool_rotation: self.tool_rotation }
    }
}

impl IkPlan {
    /// The family.
    pub fn family(&self) -> IkFamily {
        match &self.geometry {
            IkGeometry::Six { family, .. } => IkFamily::Six(*family),
            IkGeometry::Planar(_) => IkFamily::Planar,
        }
    }

    /// The six-joint geometry, if the family is a six-joint one.
    pub fn six(&self) -> Option<&SixGeometry> {
        match &self.geometry {
            IkGeometry::Six { arm, .. } => Some(arm),
            IkGeometry::Planar(_) => None,
        }
    }

    /// The free joint, for a seven-joint arm.
    pub fn free(&self) -> Option<&FreeJoint> {
        match &self.geometry {
            IkGeometry::Six { free, .. } => free.as_ref(),
            IkGeometry::Planar(_) => None,
        }
    }
}

fn norm(a: V3) -> f64 {
    norm_squared(a).sqrt()
}

/// The six axes as lines, with the tolerances of this chain.
struct Lines<'a> {
    zero: &'a ZeroConfiguration,
    meet_tolerance: f64,
}

impl Lines<'_> {
    fn axis(&self, i: usize) -> V3 {
        self.zero.joints[i].axis
    }

    fn point(&self, i: usize) -> V3 {
        self.zero.joints[i].point
    }

    /// The sine of the angle between axes `i` and `j` (0-based).
    fn angle_sine(&self, i: usize, j: usize) -> f64 {
        norm(cross(self.axis(i), self.axis(j)))
    }

    /// Axes `i` and `j` are parallel, or why not.
    fn parallel(&self, i: usize, j: usize) -> Result<(), String> {
        let sine = self.angle_sine(i, j);
        if sine <= PARALLEL_TOLERANCE {
            Ok(())
        } else {
            Err(format!("axes {} and {} are not parallel: {:.4} rad apart", i + 1, j + 1, sine.min(1.0).asin()))
        }
    }

    /// Where axes `i` and `j` meet, or why they do not (parallel axes never meet here: either
    /// they are apart or they are one line, and either way no point is fixed).
    fn meet(&self, i: usize, j: usize) -> Result<V3, String> {
        let (a, b) = (self.axis(i), self.axis(j));
        let n = cross(a, b);
        let n2 = dot(n, n);
        if n2.sqrt() <= PARALLEL_TOLERANCE {
            return Err(format!("axes {} and {} are parallel, so they do not meet in one point", i + 1, j + 1));
        }
        let d = sub(self.point(j), self.point(i));
        let gap = dot(d, n).abs() / n2.sqrt();
        if gap > self.meet_tolerance {
            return Err(format!("axes {} and {} do not meet: closest distance {gap:.4} m", i + 1, j + 1));
        }
        // The closest points of the two lines, and their midpoint.
        let ti = dot(cross(d, b), n) / n2;
        let tj = dot(cross(d, a), n) / n2;
        let pi = [0, 1, 2].map(|k| self.point(i)[k] + ti * a[k]);
        let pj = [0, 1, 2].map(|k| self.point(j)[k] + tj * b[k]);
        Ok([0, 1, 2].map(|k| 0.5 * (pi[k] + pj[k])))
    }

    /// The point where axes 4, 5, 6 meet, or why they do not.
    fn wrist_centre(&self) -> Result<V3, String> {
        let centre = self.meet(3, 4)?;
        self.meet(4, 5)?;
        let gap = norm(cross(sub(centre, self.point(5)), self.axis(5)));
        if gap > self.meet_tolerance {
            return Err(format!("axes 4, 5, 6 do not meet: axis 6 passes {gap:.4} m from where 4 and 5 meet"));
        }
        Ok(centre)
    }
}

/// The closed-form plan for the chain from `base` to `tip`, or the error saying why no family
/// covers it (every family's reason).
pub fn classify(tree: &KinematicTree, base: &str, tip: &str) -> Result<IkPlan, CompileError> {
    classify_with(tree, base, tip, None)
}

/// Angles of the free joint at which a seven-joint arm's family is checked: a relation of two
/// axes on opposite sides of the free joint is a trigonometric polynomial of degree at most 2 in
/// its angle, so five distinct angles would decide it; families whose relations all keep to one
/// side (the only ones taken) hold at every angle, and these samples check that too.
const FREE_SAMPLES: [f64; 5] = [0.0, 0.9, 2.1, 3.3, 4.6];

/// [`classify`], or with `free` (a joint of a seven-joint chain) given as an input: the other six
/// solved in closed form for any value of it.
pub fn classify_with(tree: &KinematicTree, base: &str, tip: &str, free: Option<&str>) -> Result<IkPlan, CompileError> {
    let robot = tree.name().to_owned();
    let none = |reason: String| {
        CompileError::NoIkFamily(Box::new(NoIkFamily {
            robot: robot.clone(),
            base: base.to_owned(),
            tip: tip.to_owned(),
            reason,
        }))
    };
    let chain = tree.chain(base, tip).map_err(|source| CompileError::Model { robot: robot.clone(), source })?;
    let zero = zero_configuration(tree, &chain).map_err(|joints| {
        let what: Vec<String> = joints.iter().map(|j| format!("joint `{}` {}", j.joint, j.why)).collect();
        none(format!("{}; the closed forms take independent revolute joints only", what.join(", ")))
    })?;
    let moving = zero.joints.len();
    if free.is_none() && (2..=4).contains(&moving) {
        if tree.dof() != moving {
            return Err(none(format!(
                "the robot has {} degrees of freedom and the chain moves {moving} of them; the closed forms solve a \
                 robot's whole q",
                tree.dof()
            )));
        }
        return planar(&zero)
            .map(|(geometry, notes)| IkPlan {
                base: base.to_owned(),
                tip: tip.to_owned(),
                joints: zero.joints.iter().map(|j| j.name.clone()).collect(),
                geometry: IkGeometry::Planar(geometry),
                reach: zero.reach,
                notes,
                // A planar arm's solutions reach what it can; they are not refined.
                made_exact: false,
            })
            .map_err(|reason| none(format!("{}: {reason}", IkFamily::Planar.name())));
    }
    let slides: Vec<usize> = (0..moving).filter(|&i| zero.joints[i].kind == JointKind::Prismatic).collect();
    if free.is_none() && moving == 6 && slides == [2] && tree.dof() == 6 {
        let lines = Lines { zero: &zero, meet_tolerance: MEET_TOLERANCE * zero.reach };
        let family = SixFamily::SphericalPrismaticThird;
        return match plan(&lines, family) {
            Ok((points, parallel_to)) => Ok(finish(base, tip, &zero, family, points, parallel_to, None)),
            Err(Fault::Wrist(reason) | Fault::Arm(reason)) => Err(none(format!("{}: {reason}", family.facts().name))),
        };
    }
    if let Some(j) = zero.joints.iter().find(|j| j.kind == JointKind::Prismatic) {
        return Err(none(format!("joint `{}` is prismatic; the closed forms take six revolute joints", j.name)));
    }
    let (expected, what) = if free.is_some() { (7, "seven, one of them free") } else { (6, "six") };
    if moving != expected {
        let hint = if moving == 7 && free.is_none() { " (name one joint free: `ik(free = \"joint\")`)" } else { "" };
        return Err(none(format!("the chain has {moving} moving joints; the closed forms solve {what}{hint}")));
    }
    if tree.dof() != moving {
        return Err(none(format!(
            "the robot has {} degrees of freedom and the chain moves {moving} of them; the closed forms solve a robot's whole q",
            tree.dof()
        )));
    }
    let Some(free) = free else {
        let lines = Lines { zero: &zero, meet_tolerance: MEET_TOLERANCE * zero.reach };
        let mut reasons = Vec::new();
        for family in SixFamily::REVOLUTE {
            match plan(&lines, family) {
                Ok((points, parallel_to)) => {
                    let plan = finish(base, tip, &zero, family, points, parallel_to, None);
                    match solves_samples(family, &plan) {
                        Ok(()) => return Ok(plan),
                        Err(reason) => note(&mut reasons, family, Fault::Arm(reason)),
                    }
                }
                Err(fault) => note(&mut reasons, family, fault),
            }
        }
        return Err(none(reasons.join("; ")));
    };
    let Some(index) = zero.joints.iter().position(|j| j.name == free) else {
        let names: Vec<String> = zero.joints.iter().map(|j| format!("`{}`", j.name)).collect();
        return Err(none(format!("`{free}` is not a moving joint of the chain (those are {})", names.join(", "))));
    };
    let samples: Vec<ZeroConfiguration> =
        FREE_SAMPLES.iter().map(|&angle| without_turned(&zero, index, angle)).collect();
    let mut reasons = Vec::new();
    'families: for family in SixFamily::REVOLUTE {
        if let Some((i, j)) = family.pairs().find(|&(i, j)| (i < index) != (j < index)) {
            reasons.push(format!(
                "{}: it relates axes {} and {} of the six, on either side of the free joint",
                family.facts().name,
                i + 1,
                j + 1
            ));
            continue;
        }
        let mut found = None;
        for sample in &samples {
            let lines = Lines { zero: sample, meet_tolerance: MEET_TOLERANCE * zero.reach };
            match plan(&lines, family) {
                Ok(placement) => found = found.or(Some(placement)),
                Err(fault) => {
                    note(&mut reasons, family, fault);
                    continue 'families;
                }
            }
        }
        #[allow(clippy::expect_used, reason = "an invariant of the loop above, named in the message")]
        let (points, parallel_to) = found.expect("every sample's plan succeeded, and there are samples");
        let joint = &zero.joints[index];
        let free = FreeJoint { name: joint.name.clone(), index, axis: joint.axis, point: joint.point };
        let plan = finish(base, tip, &samples[0], family, points, parallel_to, Some(free));
        match solves_samples(family, &plan) {
            Ok(()) => return Ok(plan),
            Err(reason) => note(&mut reasons, family, Fault::Arm(reason)),
        }
    }
    Err(none(reasons.join("; ")))
}

/// The planar family's geometry: two or three revolute joints whose axes are parallel to the
/// first's, at most one prismatic joint along them, and arms that are not degenerate (each link
/// of the two-link problem has a length across the axis); or why not.
fn planar(zero: &ZeroConfiguration) -> Result<(PlanarGeometry, Vec<String>), String> {
    let revolute: Vec<usize> =
        (0..zero.joints.len()).filter(|&i| zero.joints[i].kind != JointKind::Prismatic).collect();
    let prismatic = zero.joints.len() - revolute.len();
    if !(2..=3).contains(&revolute.len()) || prismatic > 1 {
        return Err(format!(
            "it takes two or three revolute joints and at most one prismatic joint; the chain has {} and {prismatic}",
            revolute.len()
        ));
    }
    let h = zero.joints[revolute[0]].axis;
    let mut notes = Vec::new();
    let mut joints = Vec::new();
    for (i, joint) in zero.joints.iter().enumerate() {
        let sine = norm(cross(h, joint.axis));
        if sine > PARALLEL_TOLERANCE {
            return Err(format!("axes 1 and {} are not parallel: {:.4} rad apart", i + 1, sine.min(1.0).asin()));
        }
        if sine != 0.0 {
            notes.push(format!("axis {} taken as parallel to axis 1 ({sine:.1e} rad apart)", i + 1));
        }
        let sign = if dot(h, joint.axis) < 0.0 { -1.0 } else { 1.0 };
        joints.push((sign, (joint.kind != JointKind::Prismatic).then_some(joint.point)));
    }
    // The two-link problem: the point the first two joints place (the third's axis, or the tip)
    // must be off the second axis, and the second axis off the first.
    let carried = if revolute.len() == 3 { zero.joints[revolute[2]].point } else { zero.tip_point };
    let (o1, o2) = (zero.joints[revolute[0]].point, zero.joints[revolute[1]].point);
    let tolerance = MEET_TOLERANCE * zero.reach;
    if norm(cross(h, sub(o2, o1))) <= tolerance || norm(cross(h, sub(carried, o2))) <= tolerance {
        return Err("a link of the two-link problem has no length across the axes (a degenerate arm)".to_owned());
    }
    Ok((PlanarGeometry { axis: h, joints, tip_point: zero.tip_point, tool_rotation: zero.tip_rotation }, notes))
}

/// A family's fault among the reasons, the wrist's once.
fn note(reasons: &mut Vec<String>, family: SixFamily, fault: Fault) {
    match fault {
        // The wrist is every spherical family's first test: its fault is told once.
        Fault::Wrist(reason) => {
            let told = format!("spherical wrist: {reason}");
            if !reasons.contains(&told) {
                reasons.push(told);
            }
        }
        Fault::Arm(reason) => reasons.push(format!("{}: {reason}", family.facts().name)),
    }
}

/// The chain without joint `index`, everything after it turned by `angle` about its axis.
fn without_turned(zero: &ZeroConfiguration, index: usize, angle: f64) -> ZeroConfiguration {
    let free = &zero.joints[index];
    let (s, c) = angle.sin_cos();
    let turn = |v: V3| rotate_cs(free.axis, c, s, v);
    let turn_point = |p: V3| {
        let d = turn(sub(p, free.point));
        [0, 1, 2].map(|i| free.point[i] + d[i])
    };
    let mut joints = Vec::with_capacity(zero.joints.len() - 1);
    for (i, joint) in zero.joints.iter().enumerate() {
        if i == index {
            continue;
        }
        let mut joint = joint.clone();
        if i > index {
            joint.axis = turn(joint.axis);
            joint.point = turn_point(joint.point);
        }
        joints.push(joint);
    }
    let r = &zero.tip_rotation;
    let columns = [0, 1, 2].map(|j| turn([r[0][j], r[1][j], r[2][j]]));
    ZeroConfiguration {
        joints,
        tip_rotation: [0, 1, 2].map(|i| [columns[0][i], columns[1][i], columns[2][i]]),
        tip_point: turn_point(zero.tip_point),
        reach: zero.reach,
    }
}

/// The points on the axes a family needs (index by joint) and, for axes taken as parallel to an
/// earlier one, which.
type Placement = ([Option<V3>; 6], [Option<usize>; 6]);

/// Why a family does not apply: its wrist (shared by the spherical families) or the rest.
enum Fault {
    Wrist(String),
    Arm(String),
}

impl From<String> for Fault {
    fn from(reason: String) -> Self {
        Fault::Arm(reason)
    }
}

/// The family's relations checked on `lines`, in its order, and applied: the points of axes
/// that meet placed where they meet, the axes taken as parallel noted; or the first that fails.
fn plan(lines: &Lines<'_>, family: SixFamily) -> Result<Placement, Fault> {
    let mut points = [None; 6];
    let mut parallel_to = [None; 6];
    for relation in family.facts().relations {
        match *relation {
            Relation::Wrist => {
                let centre = lines.wrist_centre().map_err(Fault::Wrist)?;
                points[3] = Some(centre);
                points[4] = Some(centre);
                points[5] = Some(centre);
            }
            Relation::Parallel(i, j) => {
                lines.parallel(i, j)?;
                parallel_to[j] = Some(i);
            }
            Relation::NotParallel(i, j) => {
                if lines.angle_sine(i, j) <= PARALLEL_TOLERANCE {
                    return Err(Fault::Arm(format!("axes {} and {} are parallel", i + 1, j + 1)));
                }
            }
            Relation::Meet(i, j) => {
                let meet = lines.meet(i, j)?;
                points[i] = Some(meet);
                points[j] = Some(meet);
            }
        }
    }
    distance_depends_on_its_joint(lines, family, &points)?;
    Ok((points, parallel_to))
}

/// Rule: the joint whose angle subproblem 3 finds from a distance changes that distance: the
/// offsets on either side of it are not both along its axis (a line through the axis turns into
/// itself). Otherwise the arm is degenerate: the distance is fixed, so only poses at that
/// distance are reached, and those by a continuum of angles (the iiwa with its elbow held: its
/// shoulder and wrist axes each meet in a point, and the distance between the points never
/// changes).
fn distance_depends_on_its_joint(lines: &Lines<'_>, family: SixFamily, points: &[Option<V3>; 6]) -> Result<(), Fault> {
    // A family without the rule: a slide changes the distance whatever its direction, and
    // subproblem 5 ties all three joints (the trial on sample poses catches an arm it cannot solve).
    let Some(rule) = family.facts().distance else { return Ok(()) };
    let point = |i: usize| points[i].unwrap_or(lines.point(i));
    let across = |(from, to): (usize, usize)| norm(cross(lines.axis(rule.joint), sub(point(to), point(from))));
    if rule.sides.iter().any(|&side| across(side) <= lines.meet_tolerance) {
        return Err(Fault::Arm(format!(
            "axis {} is in line with the offset beside it, so turning it changes no distance (a degenerate arm: it \
             reaches only poses at one distance)",
            rule.joint + 1
        )));
    }
    Ok(())
}

/// Configurations at which [`solves_samples`] tries a plan: spread over every joint's turn, away
/// from the zero configuration (where wrists and elbows are often singular).
const SAMPLE_CONFIGURATIONS: [[f64; 6]; 8] = [
    [0.3, -1.2, 1.0, 0.4, -0.7, 2.0],
    [-2.1, 0.5, -0.8, 1.9, 1.3, -0.4],
    [1.4, 2.2, 0.6, -2.6, 0.9, 1.1],
    [-0.6, -0.3, 2.7, 0.8, -1.8, -2.9],
    [2.8, 1.1, -1.9, -0.5, 2.4, 0.2],
    [-1.5, -2.5, -0.2, 2.3, -0.4, 1.7],
    [0.9, 0.2, 1.6, -1.2, 1.6, -1.3],
    [-2.7, 1.8, -2.4, 0.1, -2.2, 2.6],
];

/// Rule: a six-joint revolute family is taken only if its solver, run here on the plan's geometry,
/// finds the joint values of sample poses of this very arm (at least six of the eight
/// [`SAMPLE_CONFIGURATIONS`]: a sample may land near a singularity of a regular arm). The
/// families' structural tests (parallel, meeting) say when a decomposition applies; this says
/// that it is not degenerate for the arm at hand (a quartic family's equations can lose their
/// hold on an angle in ways no single relation of two axes shows).
fn solves_samples(family: SixFamily, plan: &IkPlan) -> Result<(), String> {
    let facts = family.facts();
    let Some(six) = plan.six().filter(|_| facts.tried_on_samples) else {
        return Ok(());
    };
    let solver = facts.solver.function;
    let arm = six.arm();
    let turn_apart = |a: f64, b: f64| {
        let d = (a - b).rem_euclid(std::f64::consts::TAU);
        d.min(std::f64::consts::TAU - d)
    };
    let recovered = SAMPLE_CONFIGURATIONS
        .iter()
        .filter(|q| {
            let target = arm.pose(q);
            solver(&arm, &target).exact().any(|s| s.q.iter().zip(q.iter()).all(|(&a, &b)| turn_apart(a, b) < 1e-6))
        })
        .count();
    if recovered * 4 < SAMPLE_CONFIGURATIONS.len() * 3 {
        return Err(format!(
            "its solver finds only {recovered} of {} sample configurations from their poses (a degenerate arm for \
             this family)",
            SAMPLE_CONFIGURATIONS.len()
        ));
    }
    Ok(())
}

fn finish(
    base: &str,
    tip: &str,
    zero: &ZeroConfiguration,
    family: SixFamily,
    points: [Option<V3>; 6],
    parallel_to: [Option<usize>; 6],
    free: Option<FreeJoint>,
) -> IkPlan {
    let mut notes = Vec::new();
    let mut axes = [[0.0; 3]; 6];
    for i in 0..6 {
        axes[i] = zero.joints[i].axis;
        if let Some(j) = parallel_to[i] {
            let sign = if dot(zero.joints[i].axis, zero.joints[j].axis) < 0.0 { -1.0 } else { 1.0 };
            let written = zero.joints[j].axis.map(|x| sign * x);
            if written != axes[i] {
                notes.push(format!(
                    "axis {} taken as parallel to axis {} ({:.1e} rad apart)",
                    i + 1,
                    j + 1,
                    norm(cross(axes[i], written)).min(1.0).asin()
                ));
            }
            axes[i] = written;
        }
    }
    let chosen: Vec<V3> = (0..6).map(|i| points[i].unwrap_or(zero.joints[i].point)).collect();
    // Changes past rounding: an axis turned, or a point moved off its written axis line.
    let rounding = |length_squared: f64| length_squared > PLAN_ROUNDING * PLAN_ROUNDING;
    let mut made_exact =
        axes.iter().zip(&zero.joints).any(|(axis, joint)| rounding(norm_squared(cross(*axis, joint.axis))));
    for i in 0..6 {
        let moved = dot(sub(chosen[i], zero.joints[i].point), axes[i]);
        let across = sub(sub(chosen[i], zero.joints[i].point), axes[i].map(|x| x * moved));
        made_exact |= rounding(norm_squared(across) / (zero.reach * zero.reach));
        if points[i].is_some() && moved != 0.0 {
            notes.push(format!(
                "point of axis {} (joint `{}`) moved {moved:+.6} m along it",
                i + 1,
                zero.joints[i].name
            ));
        }
    }
    let points = [0, 1, 2, 3, 4, 5].map(|i| chosen[i]);
    let arm = Arm6::from_points(axes, &points, zero.tip_point, zero.tip_rotation);
    IkPlan {
        base: base.to_owned(),
        tip: tip.to_owned(),
        joints: zero.joints.iter().map(|j| j.name.clone()).collect(),
        geometry: IkGeometry::Six {
            family,
            arm: Box::new(SixGeometry {
                axes,
                offsets: arm.offsets,
                tool_rotation: zero.tip_rotation,
                points,
                tip_point: zero.tip_point,
            }),
            free,
        },
        reach: zero.reach,
        notes,
        made_exact,
    }
}
