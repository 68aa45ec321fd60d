//! Held objects: spheres attached to one of a compiled robot's links at run time (an object in the
//! gripper), given in that link's frame, and what a check is run against ([`World`]): an
//! [`Environment`]'s obstacles alone, or those and a held object ([`Holding`]).
//!
//! A held object moves with its link. A check tests its spheres against the obstacles and
//! against the spheres of every link of the robot except the links on the holding link's rigid
//! body (links joined to it by fixed joints, which hold it by design) and the links the user
//! says it touches (the fingers around it, MoveIt's `touch_links`). The robot's own checks
//! (obstacles, self pairs) are unchanged.
//!
//! No heap: the object's spheres are the caller's slice, and which links it is not tested
//! against is a bit set of a size the compiled robot chooses (`W` words of 64 links each).
//!
//! `Held` is made from the generated `HoldTables` (each link's carrier and fixed pose) and checked
//! against the obstacles and the links off its body.

use core::marker::PhantomData;

use crate::real::square_root as sqrt;

use super::obstacles::{Environment, SphereObstacle, Vec3};
use super::verdicts::{CheckLanes, Flags, Until};
use crate::pose::Pose;

/// What a compiled robot's `collides` checks it against: the obstacles of an [`Environment`],
/// and perhaps an object it holds ([`Holding`]). Implemented by `Environment` (for every robot)
/// and by `Holding<'_, R>` (for robot `R`'s own held objects only, so an object held by one
/// robot's link cannot be handed to another's check). Sealed: these two are all there is.
pub trait World<R>: sealed::Sealed {
    /// The obstacles.
    fn environment(&self) -> &Environment<'_>;
    /// The held object, if any, as the checks read it.
    fn held(&self) -> Option<HeldObject<'_>>;
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Environment<'_> {}
    impl<R, const W: usize> Sealed for super::Holding<'_, R, W> {}
}

impl<R> World<R> for Environment<'_> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn environment(&self) -> &Environment<'_> {
        self
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn held(&self) -> Option<HeldObject<'_>> {
        None
    }
}

/// Obstacles and an object robot `R` holds: what `collides` and `motion_collides` take to check
/// the robot carrying it. Made by [`Environment::holding`].
#[derive(Debug, Clone, Copy)]
pub struct Holding<'a, R, const W: usize = 1> {
    environment: &'a Environment<'a>,
    held: &'a Held<'a, R, W>,
}

impl<R, const W: usize> World<R> for Holding<'_, R, W> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn environment(&self) -> &Environment<'_> {
        self.environment
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn held(&self) -> Option<HeldObject<'_>> {
        Some(self.held.object())
    }
}

impl<'a> Environment<'a> {
    /// These obstacles, and `held`, an object robot `R` holds (from the robot's generated `hold`).
    pub fn holding<R, const W: usize>(&'a self, held: &'a Held<'a, R, W>) -> Holding<'a, R, W> {
        Holding { environment: self, held }
    }
}

/// An object held by a link of robot `R`: its spheres (in the holding link's frame), where that
/// link sits on the links the checks place, and the links it is not tested against. Made by the
/// robot's generated `hold(link, spheres, touching)`, which checks every argument.
#[derive(Debug, Clone, Copy)]
pub struct Held<'a, R, const W: usize = 1> {
    carrier: usize,
    offset: Pose<f64>,
    spheres: &'a [SphereObstacle],
    bound: (Vec3, f64),
    skip: [u64; W],
    robot: PhantomData<fn() -> R>,
}

impl<R, const W: usize> Held<'_, R, W> {
    /// What the checks read.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn object(&self) -> HeldObject<'_> {
        HeldObject {
            carrier: self.carrier,
            offset: &self.offset,
            spheres: self.spheres,
            bound: self.bound,
            skip: &self.skip,
        }
    }

    /// The object's spheres, in the holding link's frame.
    pub fn spheres(&self) -> &[SphereObstacle] {
        self.spheres
    }

    /// The smallest sphere the check knows to hold every sphere of the object (centre in the
    /// holding link's frame, radius): what it tests before the object's spheres.
    pub fn bound(&self) -> (Vec3, f64) {
        let (c, r) = self.bound;
        (self.offset.inverse_place(c), r)
    }
}

/// A held object as a check reads it, for any robot: built only from a [`Held`].
#[derive(Debug, Clone, Copy)]
pub struct HeldObject<'a> {
    /// The link (its index among the links the checks place) on the holding link's rigid body.
    carrier: usize,
    /// The holding link's pose in the carrier's frame.
    offset: &'a Pose<f64>,
    /// The spheres, in the holding link's frame.
    spheres: &'a [SphereObstacle],
    /// Their bounding sphere, in the carrier's frame.
    bound: (Vec3, f64),
    /// Bit `k` set: the object is not tested against the checks' link `k`.
    skip: &'a [u64],
}

/// How a link is carried: the index (among the links the checks place) of the first link with
/// spheres on its rigid body, and the link's pose in that link's frame.
pub type Carried = (usize, Pose<f64>);

/// Where a compiled robot's links sit for held objects, as its generated code holds them.
#[derive(Debug, Clone, Copy)]
pub struct HoldTables {
    /// The robot's name, for errors.
    pub robot: &'static str,
    /// Every link of the robot, in tree order: its name and, if its rigid body carries spheres,
    /// the first link with spheres there (its index among the links the checks place) and the
    /// link's pose in that link's frame.
    pub frames: &'static [(&'static str, Option<Carried>)],
    /// Each link the checks place (the links with spheres, in their order): its name and its
    /// rigid body (the index in `frames` of the body's first link).
    pub links: &'static [(&'static str, usize)],
}

/// Which argument of `hold` names a link.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HeldLink {
    /// The link holding the object.
    Holding,
    /// Entry `i` of the links it touches.
    Touching(usize),
}

impl core::fmt::Display for HeldLink {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            HeldLink::Holding => f.write_str("the holding link"),
            HeldLink::Touching(i) => write!(f, "touching link {i}"),
        }
    }
}

/// Why `hold` refused an object.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum HeldError {
    /// A link name the robot does not have.
    UnknownLink {
        /// Robot name.
        robot: &'static str,
        /// Which argument named it.
        which: HeldLink,
    },
    /// A holding link whose rigid body carries no collision sphere: the checks compute no pose
    /// there to carry the object.
    NoGeometry {
        /// Robot name.
        robot: &'static str,
        /// The link.
        link: &'static str,
    },
    /// A touching link with no collision sphere: nothing of it is tested against the object.
    NotChecked {
        /// Robot name.
        robot: &'static str,
        /// The link.
        link: &'static str,
    },
    /// A sphere of the object with a NaN or infinite number, or a radius that is not positive.
    BadSphere {
        /// Robot name.
        robot: &'static str,
        /// Its index.
        index: usize,
        /// `true`: a number is not finite; `false`: its radius is not positive.
        not_finite: bool,
    },
}

impl core::fmt::Display for HeldError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            HeldError::UnknownLink { robot, which } => {
                write!(f, "robot `{robot}`: {which} is not a link of the robot (`LINK_NAMES` lists them)")
            }
            HeldError::NoGeometry { robot, link } => write!(
                f,
                "robot `{robot}`: link `{link}` cannot hold an object: no link of its rigid body has collision \
                 spheres, so the checks compute no pose there"
            ),
            HeldError::NotChecked { robot, link } => write!(
                f,
                "robot `{robot}`: link `{link}` has no collision spheres, so it cannot be left out of the held \
                 object's checks (name the links of its body that have spheres)"
            ),
            HeldError::BadSphere { robot, index, not_finite: true } => {
                write!(f, "robot `{robot}`: held sphere {index} has a number that is not finite")
            }
            HeldError::BadSphere { robot, index, not_finite: false } => {
                write!(f, "robot `{robot}`: held sphere {index} has a radius that is not positive")
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for HeldError {}

impl HoldTables {
    /// The object of `spheres` (centres in `link`'s frame) held by `link`, not tested against the
    /// links of `link`'s rigid body nor against `touching`. A robot's generated `hold` calls
    /// this on its tables; `W` words hold one bit per link the checks place.
    ///
    /// ```
    /// use kinematics_core::collision::{Held, HeldError, HoldTables, SphereObstacle};
    /// use kinematics_core::Pose;
    /// const IDENTITY: Pose<f64> =
    ///     Pose { rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], translation: [0.0; 3] };
    /// let tables = HoldTables {
    ///     robot: "two",
    ///     frames: &[("base", None), ("arm", Some((0, IDENTITY))), ("hand", Some((1, IDENTITY)))],
    ///     links: &[("arm", 1), ("hand", 2)],
    /// };
    /// let ball = [SphereObstacle { center: [0.0, 0.0, 0.1], radius: 0.05 }];
    /// let held: Held<'_, ()> = tables.hold("hand", &ball, &[])?;
    /// assert_eq!(held.spheres().len(), 1);
    /// assert!(matches!(tables.hold::<(), 1>("base", &ball, &[]), Err(HeldError::NoGeometry { .. })));
    /// assert!(matches!(tables.hold::<(), 1>("palm", &ball, &[]), Err(HeldError::UnknownLink { .. })));
    /// # Ok::<(), HeldError>(())
    /// ```
    pub fn hold<'a, R, const W: usize>(
        &self,
        link: &str,
        spheres: &'a [SphereObstacle],
        touching: &[&str],
    ) -> Result<Held<'a, R, W>, HeldError> {
        let robot = self.robot;
        let frame =
            |name: &str, which| self.frames.iter().find(|f| f.0 == name).ok_or(HeldError::UnknownLink { robot, which });
        let &(holder, place) = frame(link, HeldLink::Holding)?;
        let (carrier, offset) = place.ok_or(HeldError::NoGeometry { robot, link: holder })?;
        for (index, s) in spheres.iter().enumerate() {
            let finite = s.center.iter().chain([&s.radius]).all(|x| x.is_finite());
            if !finite || s.radius <= 0.0 {
                return Err(HeldError::BadSphere { robot, index, not_finite: !finite });
            }
        }
        let mut skip = [0u64; W];
        let mut leave_out = |k: usize| {
            #[allow(clippy::expect_used, reason = "invariant: the generated `hold` sizes `W` for its links")]
            let word = skip.get_mut(k / 64).expect("`W` words hold a bit per link the checks place");
            *word |= 1 << (k % 64);
        };
        let body = self.links[carrier].1;
        for (k, &(_, b)) in self.links.iter().enumerate() {
            if b == body {
                leave_out(k);
            }
        }
        for (i, name) in touching.iter().enumerate() {
            let &(touched, _) = frame(name, HeldLink::Touching(i))?;
            let k =
                self.links.iter().position(|l| l.0 == touched).ok_or(HeldError::NotChecked { robot, link: touched })?;
            leave_out(k);
        }
        let placed = |s: &SphereObstacle| (offset.place(s.center), s.radius);
        Ok(Held { carrier, offset, spheres, bound: enclosing(spheres.iter().map(placed)), skip, robot: PhantomData })
    }
}

/// A sphere holding every one of `balls` (centre, radius): about the middle of their centres'
/// box, as far as the farthest reaches. Not the smallest, but tight enough for a bound, and the
/// same on every run. No balls: a point at the origin of radius zero (nothing is tested).
fn enclosing(balls: impl Iterator<Item = (Vec3, f64)> + Clone) -> (Vec3, f64) {
    let (mut low, mut high) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for (c, _) in balls.clone() {
        for i in 0..3 {
            low[i] = low[i].min(c[i]);
            high[i] = high[i].max(c[i]);
        }
    }
    if low[0] > high[0] {
        return ([0.0; 3], 0.0);
    }
    // Halved before they are added, as the environment's extent is: `low + high` can overflow.
    let middle = [0, 1, 2].map(|i| 0.5 * low[i] + 0.5 * high[i]);
    let reach = balls
        .map(|(c, r)| {
            let d = [c[0] - middle[0], c[1] - middle[1], c[2] - middle[2]];
            sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + r
        })
        .fold(0.0, f64::max);
    // Rounding in the check's own placement can move a sphere by an ulp or so of the reach:
    // a relative margin keeps the bound holding every sphere there too.
    (middle, reach * (1.0 + 1e-12))
}

impl Pose<f64> {
    /// `p` (a point in the frame the pose is expressed in) in the pose's own frame: `R^T (p - t)`.
    fn inverse_place(&self, p: Vec3) -> Vec3 {
        let (r, t) = (&self.rotation, &self.translation);
        let d = [p[0] - t[0], p[1] - t[1], p[2] - t[2]];
        [0, 1, 2].map(|j| r[0][j] * d[0] + r[1][j] * d[1] + r[2][j] * d[2])
    }
}

impl<L: CheckLanes> Pose<L> {
    /// This pose, then `fixed` (a constant pose in this pose's frame).
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn then_fixed(&self, fixed: &Pose<f64>) -> Pose<L> {
        // Written out, not as closures: a closure is a function of its own, which LLVM left a
        // call from the dispatched checks, running outside their instruction set.
        let (r, f) = (&self.rotation, &fixed.rotation);
        let mut rotation = self.rotation;
        for (i, row) in rotation.iter_mut().enumerate() {
            for (j, entry) in row.iter_mut().enumerate() {
                *entry =
                    r[i][0] * L::from_f64(f[0][j]) + r[i][1] * L::from_f64(f[1][j]) + r[i][2] * L::from_f64(f[2][j]);
            }
        }
        Pose { rotation, translation: self.place(fixed.translation) }
    }
}

impl HeldObject<'_> {
    /// `hit` and the lanes where the object, carried by the robot's links at `poses`, touches an
    /// obstacle of `env` or a link of the robot it is tested against (`links`: each link's
    /// groups and bounding sphere; `groups`, `centers`, `radii` as the tables hold them).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub(super) fn hits<L: CheckLanes, G: Until>(
        &self,
        tables: &super::CollisionTables<'_>,
        poses: &[Pose<L>],
        env: &Environment<'_>,
        mut hit: L::Flags,
    ) -> L::Flags {
        if self.spheres.is_empty() || G::done(hit) {
            return hit;
        }
        let carrier = &poses[self.carrier];
        let bound = (carrier.place(self.bound.0), L::from_f64(self.bound.1));
        let pose = carrier.then_fixed(self.offset);
        // Against the obstacles: the bound, then each sphere where it hits.
        let near = env.hits_lanes(&bound.0, bound.1).and_not(hit);
        if near.any() {
            for s in self.spheres {
                hit = hit | (env.hits_lanes(&pose.place(s.center), L::from_f64(s.radius)) & near);
                if G::settled(near, hit) {
                    break;
                }
            }
        }
        // Against the robot's links: each link's bound against the object's, then each sphere of
        // the object against the link's bound, its groups' and their spheres.
        for (k, &(g0, g1, link_center, link_radius)) in tables.links.iter().enumerate() {
            if G::done(hit) {
                return hit;
            }
            if self.skip[k / 64] >> (k % 64) & 1 == 1 {
                continue;
            }
            let link_bound = (poses[k].place(link_center), L::from_f64(link_radius));
            let near = super::tables::touch(&bound.0, bound.1, &link_bound.0, link_bound.1).and_not(hit);
            if !near.any() {
                continue;
            }
            'object: for s in self.spheres {
                let (center, radius) = (pose.place(s.center), L::from_f64(s.radius));
                let close = super::tables::touch(&center, radius, &link_bound.0, link_bound.1) & near;
                if !close.any() {
                    continue;
                }
                for &(s0, s1, group_center, group_radius) in &tables.groups[g0..g1] {
                    let group = poses[k].place(group_center);
                    let close_g = super::tables::touch(&center, radius, &group, L::from_f64(group_radius)) & close;
                    if !close_g.any() {
                        continue;
                    }
                    for t in s0..s1 {
                        let other = poses[k].place(tables.centers[t]);
                        hit = hit
                            | (super::tables::touch(&center, radius, &other, L::from_f64(tables.radii[t])) & close_g);
                        if G::settled(near, hit) {
                            break 'object;
                        }
                    }
                }
            }
        }
        hit
    }
}
