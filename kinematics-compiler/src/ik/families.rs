//! The closed-form families as data, one named entry each (egg's habit with its rewrite rules):
//! its name, the relations of the six axes it needs, in the order [`mod@super::classify`] checks
//! and applies them, the joint whose angle subproblem 3 finds from a distance, its solver in
//! `kinematics-core` (the path generated code calls and the function the compiler runs on sample
//! poses), its capacity and its subproblems. The classifier, the emitter, `kinematics ik` and
//! `kinematics expr` read these, and the guide's family table is held equal to them by a test.
//!
//! Adding a six-joint family is a variant of [`SixFamily`], its entry here and its arm in
//! [`SixFamily::facts`], each checked by the compiler (an exhaustive match).

use kinematics_core::Pose;
use kinematics_core::ik::branch::Composer;
use kinematics_core::ik::{self, Arm6, IkSolutions};

use super::closed_form::Builder;

/// A closed-form family: a six-joint one, or the planar arms'.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IkFamily {
    /// A six-joint arm (or the six of a seven-joint arm with one joint given).
    Six(SixFamily),
    /// Two or three revolute joints about parallel axes, at most one prismatic joint along them:
    /// planar 2R and 3R arms, the SCARA.
    Planar,
}

/// A six-joint family (IK-Geo's decompositions, and the Stanford arm's).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SixFamily {
    /// Axes 4, 5, 6 meet (a spherical wrist) and axes 2, 3 are parallel: PUMA 560, IRB 120.
    SphericalTwoParallel,
    /// A spherical wrist and axes 1, 2 meet.
    SphericalFirstTwoIntersecting,
    /// A spherical wrist and axes 2, 3 meet.
    SphericalLastTwoIntersecting,
    /// Axes 2, 3, 4 parallel and axes 5, 6 meet: the UR family.
    ThreeParallelTwoIntersecting,
    /// A spherical wrist, axes 1 and 2 meeting and joint 3 prismatic: the Stanford arm.
    SphericalPrismaticThird,
    /// A spherical wrist, no two of axes 1, 2, 3 parallel or meeting: the general case.
    Spherical,
    /// Axes 2, 3, 4 parallel, axes 5 and 6 not meeting.
    ThreeParallel,
}

/// A relation of the six axes (0-based) a family needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Relation {
    /// Axes 4, 5 and 6 meet in one point (a spherical wrist): the three points placed there.
    Wrist,
    /// The axes are parallel: the second written as the first (with its sign).
    Parallel(usize, usize),
    /// The axes are not parallel (the subproblems dividing by their cross product need it).
    NotParallel(usize, usize),
    /// The axes meet in one point: both points placed there.
    Meet(usize, usize),
}

impl Relation {
    /// The pairs of axes it relates.
    pub fn pairs(self) -> impl Iterator<Item = (usize, usize)> {
        let pairs = match self {
            Relation::Wrist => [Some((3, 4)), Some((4, 5)), Some((3, 5))],
            Relation::Parallel(i, j) | Relation::NotParallel(i, j) | Relation::Meet(i, j) => [Some((i, j)), None, None],
        };
        pairs.into_iter().flatten()
    }
}

/// The joint whose angle subproblem 3 finds from a distance, and the offsets beside it
/// (`(from, to)`: between the points on those axes), each of which must cross its axis: one in
/// line with it makes the arm degenerate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DistanceRule {
    /// The joint (0-based).
    pub joint: usize,
    /// The offsets, by the axes their points are on.
    pub sides: &'static [(usize, usize)],
}

/// A six-joint family's solver in `kinematics-core`.
pub type SixSolver = fn(&Arm6, &Pose<f64>) -> IkSolutions<6, 8>;

/// A family's solver in `kinematics-core`: the function, and its name, which generated code calls
/// under `kinematics::__private::ik` (both from one spelling, by the `solver!` macro here).
#[derive(Debug, Clone, Copy)]
pub struct Solver {
    /// The function's name.
    pub path: &'static str,
    /// The function, which the compiler runs.
    pub function: SixSolver,
}

/// The [`Solver`] of the core function `name`: its name and the function from one spelling.
macro_rules! solver {
    ($name:ident) => {
        Solver { path: stringify!($name), function: ik::$name }
    };
}

/// What the compiler knows of one six-joint family.
#[derive(Debug, Clone, Copy)]
pub struct SixFacts {
    /// A stable name (`kinematics inspect`, the generated `IK_FAMILY`).
    pub name: &'static str,
    /// The relations it needs, in the order they are checked (the first that fails is the reason
    /// given).
    pub relations: &'static [Relation],
    /// The distance subproblem 3 solves, where it has one.
    pub distance: Option<DistanceRule>,
    /// Its solver in `kinematics-core`.
    pub solver: Solver,
    /// Its branch, written once in `kinematics_core::ik::branch` (where the solver runs it in
    /// lanes), which the compiler builds as expressions and emits as `tip_ik`'s straight-line body;
    /// `None` for a family whose first step is a quartic (generated code calls its solver).
    pub(crate) branch: Option<Composer<Builder>>,
    /// Whether a plan is tried on sample poses of the arm before it is taken (`Arm6::pose` turns
    /// every joint, so not for a prismatic one: the Stanford family's tests are structural).
    pub tried_on_samples: bool,
    /// The subproblems it is composed of, in order (IK-Geo's numbering: 1 a rotation onto a
    /// vector, 2 two rotations, 3 a rotation to a distance, 4 a rotation to a height, 5 three
    /// rotations of a point, 6 two angles from two heights; 5 and 6 solve a quartic).
    pub subproblems: &'static str,
}

/// The distance of `|p23 + rot(h3, q3) p34|`: joint 3 between the offsets on either side.
const ELBOW: DistanceRule = DistanceRule { joint: 2, sides: &[(1, 2), (2, 3)] };

const THREE_PARALLEL_TWO_INTERSECTING: SixFacts = SixFacts {
    name: "axes 2, 3, 4 parallel, axes 5 and 6 meet",
    relations: &[
        Relation::Parallel(1, 2),
        Relation::Parallel(1, 3),
        Relation::NotParallel(0, 1),
        Relation::NotParallel(4, 1),
        Relation::Meet(4, 5),
    ],
    distance: Some(ELBOW),
    solver: solver!(three_parallel_two_intersecting),
    branch: Some(ik::branch::three_parallel_two_intersecting::<Builder>),
    tried_on_samples: true,
    subproblems: "q1 by SP4, q5 by SP4, q6 by SP1, q2+q3+q4 by SP1, q3 by SP3, q2 by SP1, q4 by difference",
};

const SPHERICAL_TWO_PARALLEL: SixFacts = SixFacts {
    name: "spherical wrist, axes 2 and 3 parallel",
    relations: &[Relation::Wrist, Relation::Parallel(1, 2), Relation::NotParallel(0, 1)],
    distance: Some(ELBOW),
    solver: solver!(spherical_two_parallel),
    branch: Some(ik::branch::spherical_two_parallel::<Builder>),
    tried_on_samples: true,
    subproblems: "q1 by SP4, q3 by SP3, q2 by SP1; wrist: q5 by SP4, q4, q6 by SP1",
};

const SPHERICAL_FIRST_TWO_INTERSECTING: SixFacts = SixFacts {
    name: "spherical wrist, axes 1 and 2 meet",
    relations: &[Relation::Wrist, Relation::Meet(0, 1)],
    distance: Some(ELBOW),
    solver: solver!(spherical_first_two_intersecting),
    branch: Some(ik::branch::spherical_first_two_intersecting::<Builder>),
    tried_on_samples: true,
    subproblems: "q3 by SP3, q1, q2 by SP2; wrist: q5 by SP4, q4, q6 by SP1",
};

const SPHERICAL_LAST_TWO_INTERSECTING: SixFacts = SixFacts {
    name: "spherical wrist, axes 2 and 3 meet",
    relations: &[Relation::Wrist, Relation::Meet(1, 2)],
    // |rot(h1, -q1) v - p12| is the distance: only p12 is the robot's.
    distance: Some(DistanceRule { joint: 0, sides: &[(0, 1)] }),
    solver: solver!(spherical_last_two_intersecting),
    branch: Some(ik::branch::spherical_last_two_intersecting::<Builder>),
    tried_on_samples: true,
    subproblems: "q1 by SP3, q2, q3 by SP2; wrist: q5 by SP4, q4, q6 by SP1",
};

const SPHERICAL_PRISMATIC_THIRD: SixFacts = SixFacts {
    name: "spherical wrist, axes 1 and 2 meet, joint 3 prismatic",
    relations: &[Relation::Wrist, Relation::Meet(0, 1)],
    // A slide changes the distance whatever its direction (the quadratic has its roots).
    distance: None,
    solver: solver!(spherical_prismatic_third),
    branch: Some(ik::branch::spherical_prismatic_third::<Builder>),
    tried_on_samples: false,
    subproblems: "q3 from the wrist centre's distance (a quadratic), q1, q2 by SP2; wrist: q5 by SP4, q4, q6 by SP1",
};

const SPHERICAL: SixFacts = SixFacts {
    name: "spherical wrist",
    relations: &[Relation::Wrist],
    // Subproblem 5 ties all three; the trial on sample poses catches an arm it cannot solve.
    distance: None,
    solver: solver!(spherical),
    branch: None,
    tried_on_samples: true,
    subproblems: "q1, q2, q3 by SP5; wrist: q5 by SP4, q4, q6 by SP1",
};

const THREE_PARALLEL: SixFacts = SixFacts {
    name: "axes 2, 3, 4 parallel",
    relations: &[
        Relation::Parallel(1, 2),
        Relation::Parallel(1, 3),
        Relation::NotParallel(0, 1),
        Relation::NotParallel(4, 1),
    ],
    distance: Some(ELBOW),
    solver: solver!(three_parallel),
    branch: None,
    tried_on_samples: true,
    subproblems: "q1, q5 by SP6, q6 by SP1, q2+q3+q4 by SP1, q3 by SP3, q2 by SP1, q4 by difference",
};

/// The planar family's name.
const PLANAR_NAME: &str = "planar: revolute axes parallel, a prismatic joint along them at most";

/// The planar family's subproblems.
const PLANAR_SUBPROBLEMS: &str = "the slide from the height; the turn about the axis by SP1 (three revolute joints); \
                                  the elbow by SP3, the shoulder by SP1, the third by difference";

impl SixFamily {
    /// Every six-joint revolute family, in the order they are tried: the special cases (a
    /// quadratic first step, eight solutions at most) before the general ones they are special
    /// cases of (a quartic first step). (The Stanford family is tried on its own, for a chain
    /// whose third joint slides.)
    pub const REVOLUTE: [SixFamily; 6] = [
        SixFamily::ThreeParallelTwoIntersecting,
        SixFamily::SphericalTwoParallel,
        SixFamily::SphericalFirstTwoIntersecting,
        SixFamily::SphericalLastTwoIntersecting,
        SixFamily::Spherical,
        SixFamily::ThreeParallel,
    ];

    /// Its entry.
    pub fn facts(self) -> &'static SixFacts {
        match self {
            SixFamily::ThreeParallelTwoIntersecting => &THREE_PARALLEL_TWO_INTERSECTING,
            SixFamily::SphericalTwoParallel => &SPHERICAL_TWO_PARALLEL,
            SixFamily::SphericalFirstTwoIntersecting => &SPHERICAL_FIRST_TWO_INTERSECTING,
            SixFamily::SphericalLastTwoIntersecting => &SPHERICAL_LAST_TWO_INTERSECTING,
            SixFamily::SphericalPrismaticThird => &SPHERICAL_PRISMATIC_THIRD,
            SixFamily::Spherical => &SPHERICAL,
            SixFamily::ThreeParallel => &THREE_PARALLEL,
        }
    }

    /// Every pair of axes (0-based, of the six) whose relation the family relies on.
    pub fn pairs(self) -> impl Iterator<Item = (usize, usize)> {
        self.facts().relations.iter().flat_map(|relation| relation.pairs())
    }
}

impl IkFamily {
    /// Every family: the six-joint ones (the revolute ones in the order they are tried, then the
    /// Stanford arm's), and the planar arms'.
    pub const ALL: [IkFamily; 8] = [
        IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting),
        IkFamily::Six(SixFamily::SphericalTwoParallel),
        IkFamily::Six(SixFamily::SphericalFirstTwoIntersecting),
        IkFamily::Six(SixFamily::SphericalLastTwoIntersecting),
        IkFamily::Six(SixFamily::Spherical),
        IkFamily::Six(SixFamily::ThreeParallel),
        IkFamily::Six(SixFamily::SphericalPrismaticThird),
        IkFamily::Planar,
    ];

    /// A stable name (`kinematics inspect`, the generated `IK_FAMILY`).
    pub fn name(self) -> &'static str {
        match self {
            IkFamily::Six(six) => six.facts().name,
            IkFamily::Planar => PLANAR_NAME,
        }
    }

    /// The core function that solves it (under `kinematics::__private::ik`; the planar family's
    /// is the method `PlanarArm::solve`).
    pub fn solver(self) -> &'static str {
        match self {
            IkFamily::Six(six) => six.facts().solver.path,
            IkFamily::Planar => "PlanarArm::solve",
        }
    }

    /// The subproblems it is composed of, in order (see [`SixFacts::subproblems`]).
    pub fn subproblems(self) -> &'static str {
        match self {
            IkFamily::Six(six) => six.facts().subproblems,
            IkFamily::Planar => PLANAR_SUBPROBLEMS,
        }
    }

    /// The most solutions a target can have: the capacity of the returned list.
    pub fn max_solutions(self) -> usize {
        match self {
            IkFamily::Six(_) => 8,
            IkFamily::Planar => 2,
        }
    }
}

impl From<SixFamily> for IkFamily {
    fn from(six: SixFamily) -> Self {
        IkFamily::Six(six)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pairs a family relies on, in its relations' order.
    #[test]
    fn a_family_relies_on_the_pairs_of_its_relations() {
        let pairs: Vec<(usize, usize)> = SixFamily::SphericalTwoParallel.pairs().collect();
        assert_eq!(pairs, [(3, 4), (4, 5), (3, 5), (1, 2), (0, 1)]);
        let pairs: Vec<(usize, usize)> = SixFamily::ThreeParallelTwoIntersecting.pairs().collect();
        assert_eq!(pairs, [(1, 2), (1, 3), (0, 1), (4, 1), (4, 5)]);
    }

    /// The guide's family table (`src/guide/inverse_kinematics.md`) has a row for every family,
    /// its name first and its subproblems last, as this table writes them.
    #[test]
    fn the_guide_lists_every_family_as_written_here() {
        let guide = include_str!("../../../src/guide/inverse_kinematics.md");
        let rows: Vec<&str> = guide.lines().filter(|l| l.starts_with("| ") && l.ends_with(" |")).collect();
        for family in IkFamily::ALL {
            let (name, subproblems) = (family.name(), family.subproblems());
            let row = rows.iter().find(|r| r.starts_with(&format!("| {name} |")));
            let row = row.unwrap_or_else(|| panic!("the guide's family table has no row for `{name}`"));
            assert!(row.ends_with(&format!("| {subproblems} |")), "the guide's row for `{name}`: {row}");
        }
    }
}
