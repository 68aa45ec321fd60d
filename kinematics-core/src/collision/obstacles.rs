//! Obstacles at run time: sphere, capsule, cylinder and oriented box, each tested against a sphere
//! by squared distances on any lane type, and `Environment`, borrowed slices of them refusing NaN,
//! infinities and sizes that are not positive. `SphereQuery` is how a check asks other obstacles (a
//! point cloud) about a sphere; an `Environment` takes one with `with_query`.

use crate::real::square_root as sqrt;

use super::verdicts::{CheckLanes, Flags};

/// A point or vector.
pub type Vec3 = [f64; 3];

/// A sphere obstacle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereObstacle {
    /// Centre (m).
    pub center: Vec3,
    /// Radius (m).
    pub radius: f64,
}

/// A capsule obstacle: the points within `radius` of the segment from `a` to `b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapsuleObstacle {
    /// One end of the axis segment.
    pub a: Vec3,
    /// The other end.
    pub b: Vec3,
    /// Radius (m).
    pub radius: f64,
}

/// A solid cylinder obstacle: `radius` about the segment from `a` to `b` (flat caps).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderObstacle {
    /// The centre of one cap.
    pub a: Vec3,
    /// The centre of the other.
    pub b: Vec3,
    /// Radius (m).
    pub radius: f64,
}

/// An oriented box obstacle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoxObstacle {
    /// Centre (m).
    pub center: Vec3,
    /// The box's axes as the rows of a rotation (row `i` is its axis `i` in the world), so a world
    /// vector `v` has box coordinates `rotation * v`: the transpose of the rotation a pose or
    /// [`BoxObstacle::from_pose`] takes (whose columns are the axes), kept so because the test
    /// turns each sphere's centre into the box's frame. Build boxes with
    /// [`BoxObstacle::from_xyz_rpy`] or [`BoxObstacle::from_pose`] rather than by this field.
    pub rotation: [Vec3; 3],
    /// Half the edge lengths along its axes (m).
    pub half_extents: Vec3,
}

impl BoxObstacle {
    /// A box of `size` (edge lengths) centred at `translation` and turned by the rotation whose
    /// rows are `rotation_rows` (a [`crate::Pose`]'s layout: world axes of the box frame as
    /// columns, so the box's axis `j` is column `j`).
    pub fn from_pose(rotation_rows: [Vec3; 3], translation: Vec3, size: Vec3) -> Self {
        // The box's axis `j` is column `j` of the pose's rotation: row `j` of its transpose.
        let rotation = [0, 1, 2].map(|j| [0, 1, 2].map(|i| rotation_rows[i][j]));
        BoxObstacle { center: translation, rotation, half_extents: size.map(|s| s / 2.0) }
    }

    /// A box of `size` (full edge lengths, as URDF, MoveIt and scene files give them) centred at
    /// `xyz` and turned by roll, pitch and yaw `rpy` (radians, URDF's fixed-axis order: about x,
    /// then y, then z of the world).
    ///
    /// ```
    /// use kinematics_core::collision::{BoxObstacle, Environment};
    /// // A 1 m x 0.2 m x 0.1 m board, its long side turned from x to y.
    /// let board = [BoxObstacle::from_xyz_rpy([0.5, 0.0, 0.3], [0.0, 0.0, core::f64::consts::FRAC_PI_2], [1.0, 0.2, 0.1])];
    /// let env = Environment::new(&[], &[], &[], &board)?;
    /// assert!(env.hits([0.5, 0.45, 0.3], 0.01) && !env.hits([0.95, 0.0, 0.3], 0.01));
    /// # Ok::<(), kinematics_core::collision::ObstacleError>(())
    /// ```
    pub fn from_xyz_rpy(xyz: Vec3, rpy: Vec3, size: Vec3) -> Self {
        BoxObstacle::from_pose(crate::Pose::from_rpy(rpy, xyz).rotation, xyz, size)
    }

    /// A box of `size` (full edge lengths) centred at `center`, its edges along the world's axes.
    pub fn axis_aligned(center: Vec3, size: Vec3) -> Self {
        BoxObstacle::from_xyz_rpy(center, [0.0; 3], size)
    }
}

/// The ends of a segment of `length` along the z axis of the frame at `xyz` turned by `rpy`
/// (URDF's cylinders and capsules), half the length either side of `xyz`.
fn ends_along_z(xyz: Vec3, rpy: Vec3, length: f64) -> (Vec3, Vec3) {
    let r = crate::Pose::from_rpy(rpy, xyz).rotation;
    let half = [r[0][2] * length / 2.0, r[1][2] * length / 2.0, r[2][2] * length / 2.0];
    (sub(xyz, half), [xyz[0] + half[0], xyz[1] + half[1], xyz[2] + half[2]])
}

impl CapsuleObstacle {
    /// A capsule of `radius` whose axis segment, `length` long (the flat part, its round ends
    /// beyond it, as URDF and scene files give it), lies along the z axis of the frame at `xyz`
    /// turned by `rpy` (radians, URDF's fixed-axis order), centred on `xyz`.
    ///
    /// ```
    /// use kinematics_core::collision::CapsuleObstacle;
    /// let upright = CapsuleObstacle::from_xyz_rpy([1.0, 0.0, 0.5], [0.0; 3], 0.1, 0.4);
    /// assert_eq!((upright.a, upright.b), ([1.0, 0.0, 0.3], [1.0, 0.0, 0.7]));
    /// ```
    pub fn from_xyz_rpy(xyz: Vec3, rpy: Vec3, radius: f64, length: f64) -> Self {
        let (a, b) = ends_along_z(xyz, rpy, length);
        CapsuleObstacle { a, b, radius }
    }
}

impl CylinderObstacle {
    /// A solid cylinder of `radius` and `length` along the z axis of the frame at `xyz` turned by
    /// `rpy` (radians, URDF's fixed-axis order), centred on `xyz`, as URDF and scene files give
    /// it.
    pub fn from_xyz_rpy(xyz: Vec3, rpy: Vec3, radius: f64, length: f64) -> Self {
        let (a, b) = ends_along_z(xyz, rpy, length);
        CylinderObstacle { a, b, radius }
    }
}

/// Why obstacles cannot make an environment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ObstacleError {
    /// An obstacle with a NaN or infinite number (its kind and index in its slice).
    NonFinite {
        /// `sphere`, `capsule`, `cylinder` or `box`.
        kind: &'static str,
        /// Its index.
        index: usize,
    },
    /// An obstacle with a negative or zero size, or a box whose rotation is not one.
    BadSize {
        /// `sphere`, `capsule`, `cylinder` or `box`.
        kind: &'static str,
        /// Its index.
        index: usize,
    },
    /// More obstacles of a kind than an index can hold (a point cloud's k-d tree numbers its
    /// points in 32 bits).
    TooMany {
        /// `point`.
        kind: &'static str,
        /// How many were given.
        count: usize,
    },
}

impl core::fmt::Display for ObstacleError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            ObstacleError::NonFinite { kind, index } => {
                write!(f, "{kind} obstacle {index} has a number that is not finite (it would never collide)")
            }
            ObstacleError::BadSize { kind, index } => write!(
                f,
                "{kind} obstacle {index} has a size that is not positive (or, for a box, a rotation that is not one)"
            ),
            ObstacleError::TooMany { kind, count } => {
                write!(f, "{count} {kind} obstacles are more than the index holds")
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for ObstacleError {}

/// The obstacles a robot is checked against: slices the caller owns. Build it with
/// [`Environment::new`], which refuses a NaN, an infinity or a size that is not positive; an
/// empty environment is allowed (only the robot itself can then collide).
#[derive(Debug, Clone, Copy, Default)]
pub struct Environment<'a> {
    pub(super) spheres: &'a [SphereObstacle],
    pub(super) capsules: &'a [CapsuleObstacle],
    pub(super) cylinders: &'a [CylinderObstacle],
    pub(super) boxes: &'a [BoxObstacle],
    pub(super) query: Option<&'a dyn SphereQuery>,
    /// The box, its axes the world's, holding every obstacle of the four slices (`None` when
    /// they are empty): a check tests each link's bounding sphere against it first and skips
    /// the obstacles for a link no lane brings near it.
    pub(super) extent: Option<Extent>,
}

/// A box, its axes the world's, holding obstacles: its centre and half extents, padded by
/// 1e-5 of its largest coordinate plus 1e-5 m, far beyond the rounding of an `f32` test, so a
/// sphere it misses misses every obstacle inside it in every lane type's arithmetic. Obstacles
/// near `f64`'s largest values overflow it to infinities or NaN, which every test counts as
/// touching: the obstacles are then asked, never skipped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Extent {
    pub(super) center: Vec3,
    pub(super) half: Vec3,
}

impl Extent {
    /// A box, its axes the world's, holding every obstacle, padded; `None` for none. It holds
    /// each obstacle's own box: a sphere's, and a capsule's ends, give or take the radius (the
    /// smallest boxes); a cylinder's ends too (its caps lie within the radius of its ends on
    /// every axis, a box a little larger than the smallest); a turned box reaches
    /// `sum_k |axis_k[i]| half_k` from its centre along world axis `i` (its corners: the
    /// smallest). Numbers the environment checked are finite, so no NaN reaches the minima.
    fn of(
        spheres: &[SphereObstacle],
        capsules: &[CapsuleObstacle],
        cylinders: &[CylinderObstacle],
        boxes: &[BoxObstacle],
    ) -> Option<Self> {
        // `None` only for no obstacles: a check then skips the four slices (there is nothing
        // in them to skip).
        if spheres.is_empty() && capsules.is_empty() && cylinders.is_empty() && boxes.is_empty() {
            return None;
        }
        let mut lower = [f64::INFINITY; 3];
        let mut upper = [f64::NEG_INFINITY; 3];
        let mut hold = |center: Vec3, reach: Vec3| {
            for i in 0..3 {
                lower[i] = lower[i].min(center[i] - reach[i]);
                upper[i] = upper[i].max(center[i] + reach[i]);
            }
        };
        for s in spheres {
            hold(s.center, [s.radius; 3]);
        }
        for (a, b, radius) in
            capsules.iter().map(|c| (c.a, c.b, c.radius)).chain(cylinders.iter().map(|c| (c.a, c.b, c.radius)))
        {
            hold(a, [radius; 3]);
            hold(b, [radius; 3]);
        }
        for b in boxes {
            let reach = [0, 1, 2].map(|i| (0..3).map(|k| b.rotation[k][i].abs() * b.half_extents[k]).sum());
            hold(b.center, reach);
        }
        let largest = lower.iter().chain(&upper).fold(0.0_f64, |m, x| m.max(x.abs()));
        let pad = 1e-5 * largest + 1e-5;
        // Halved before they are added: `lower + upper` overflows near `f64`'s largest values
        // (two ends at -1.5e308 gave a centre of minus infinity, and a box that held nothing).
        Some(Extent {
            center: [0, 1, 2].map(|i| 0.5 * lower[i] + 0.5 * upper[i]),
            half: [0, 1, 2].map(|i| (0.5 * upper[i] - 0.5 * lower[i]) + pad),
        })
    }

    /// In lanes, for a check.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub(super) fn prepare<L: CheckLanes>(&self) -> AlignedBox<L> {
        AlignedBox { center: splat(self.center), half: splat(self.half) }
    }
}

/// Obstacles a check asks about one sphere at a time, behind an index of their own: a point
/// cloud in a k-d tree ([`PointCloud`](crate::collision::PointCloud), with `std`), or a map of
/// the user's. Given to an environment by [`Environment::with_query`]; a check asks it about each
/// link's bounding sphere, then that link's spheres where the bound touches, one lane at a time.
pub trait SphereQuery: core::fmt::Debug + Sync {
    /// Whether the sphere of `center` and `radius` touches or overlaps an obstacle (touching
    /// counts). `center` is finite and `radius` positive.
    fn touches(&self, center: Vec3, radius: f64) -> bool;
    /// The signed distance from `center` to the nearest obstacle's surface (negative inside one)
    /// and its gradient with respect to `center` (the unit vector away from that obstacle, or
    /// zero where it is not defined), when some obstacle is nearer than `limit`; `None` when
    /// none is. `center` is finite and `limit` positive (perhaps infinite). What `clearance` and
    /// `proximity_cost` ask.
    fn nearest(&self, center: Vec3, limit: f64) -> Option<(f64, Vec3)>;
    /// How many obstacles.
    fn len(&self) -> usize;
    /// Whether there is none.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// The lanes of `asked` where the sphere of `center` and `radius` touches an obstacle of `query`,
/// asked one lane at a time.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn query_lanes<L: CheckLanes>(
    query: &dyn SphereQuery,
    center: &[L; 3],
    radius: L,
    asked: super::LaneMask,
) -> L::Flags {
    let mut touched = 0u32;
    for i in 0..L::WIDTH {
        if asked.lane(i) {
            let c = [center[0].lane_f64(i), center[1].lane_f64(i), center[2].lane_f64(i)];
            touched |= u32::from(query.touches(c, radius.lane_f64(i))) << i;
        }
    }
    L::Flags::from_mask(super::LaneMask::from_bits(touched))
}

fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

impl<'a> Environment<'a> {
    /// The environment of these obstacles, each checked: finite numbers, positive sizes (a
    /// capsule's or cylinder's axis may not be zero for a cylinder), a box's rotation
    /// orthonormal to 1e-9.
    pub fn new(
        spheres: &'a [SphereObstacle],
        capsules: &'a [CapsuleObstacle],
        cylinders: &'a [CylinderObstacle],
        boxes: &'a [BoxObstacle],
    ) -> Result<Self, ObstacleError> {
        for (index, s) in spheres.iter().enumerate() {
            check(&[s.center[0], s.center[1], s.center[2], s.radius], s.radius > 0.0, "sphere", index)?;
        }
        for (index, c) in capsules.iter().enumerate() {
            let numbers = [c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2], c.radius];
            check(&numbers, c.radius > 0.0, "capsule", index)?;
        }
        for (index, c) in cylinders.iter().enumerate() {
            let numbers = [c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2], c.radius];
            let axis = sub(c.b, c.a);
            check(&numbers, c.radius > 0.0 && dot(axis, axis) > 0.0, "cylinder", index)?;
        }
        for (index, b) in boxes.iter().enumerate() {
            let mut numbers = [0.0; 15];
            numbers[..3].copy_from_slice(&b.center);
            numbers[3..6].copy_from_slice(&b.half_extents);
            for (i, row) in b.rotation.iter().enumerate() {
                numbers[6 + 3 * i..9 + 3 * i].copy_from_slice(row);
            }
            let orthonormal = (0..3).all(|i| {
                (0..3).all(|j| {
                    let expected = if i == j { 1.0 } else { 0.0 };
                    (dot(b.rotation[i], b.rotation[j]) - expected).abs() <= 1e-9
                })
            });
            check(&numbers, b.half_extents.iter().all(|&h| h > 0.0) && orthonormal, "box", index)?;
        }
        let extent = Extent::of(spheres, capsules, cylinders, boxes);
        Ok(Environment { spheres, capsules, cylinders, boxes, query: None, extent })
    }

    /// No obstacles.
    pub const fn empty() -> Self {
        Environment { spheres: &[], capsules: &[], cylinders: &[], boxes: &[], query: None, extent: None }
    }

    /// These obstacles and those of `query` (a point cloud's index, say), which every check then
    /// asks too (one in place of any given before).
    pub fn with_query(self, query: &'a dyn SphereQuery) -> Self {
        Environment { query: Some(query), ..self }
    }

    /// How many obstacles (a query's as it counts them).
    pub fn len(&self) -> usize {
        let queried = self.query.map_or(0, SphereQuery::len);
        self.spheres.len() + self.capsules.len() + self.cylinders.len() + self.boxes.len() + queried
    }

    /// Whether there is none.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether the sphere of `center` and `radius` touches or overlaps any obstacle. A centre
    /// with a NaN or infinite coordinate (a configuration that is not finite) touches every
    /// obstacle: it is never free.
    ///
    /// ```
    /// use kinematics_core::collision::{Environment, SphereObstacle};
    /// let ball = [SphereObstacle { center: [1.0, 0.0, 0.0], radius: 0.5 }];
    /// let env = Environment::new(&ball, &[], &[], &[])?;
    /// assert!(env.hits([0.0; 3], 0.5) && !env.hits([0.0; 3], 0.49));
    /// assert!(env.hits([f64::NAN, 0.0, 0.0], 0.1));
    /// # Ok::<(), kinematics_core::collision::ObstacleError>(())
    /// ```
    #[inline]
    pub fn hits(&self, center: Vec3, radius: f64) -> bool {
        (!finite(&center) && !self.is_empty()) || self.hits_lanes(&center, radius)
    }

    /// [`Environment::hits`] on lanes: the lanes where the sphere touches an obstacle. The
    /// centre's lanes must be finite (a NaN coordinate counts as a hit; an infinite one does not).
    /// The obstacles are asked only where the sphere touches, on some lane, the box along the
    /// world's axes holding them all (worked out by [`Environment::new`]).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn hits_lanes<L: CheckLanes>(&self, center: &[L; 3], radius: L) -> L::Flags {
        let mut hit = L::Flags::NONE;
        if let Some(extent) = self.extent
            && extent.prepare::<L>().hits(center, radius).any()
        {
            hit = self.shapes_hit(center, radius);
        }
        if let Some(query) = self.query {
            hit = hit | query_lanes(query, center, radius, !hit.bits());
        }
        hit
    }

    /// The lanes where the sphere touches one of the four slices' obstacles.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn shapes_hit<L: CheckLanes>(&self, center: &[L; 3], radius: L) -> L::Flags {
        let mut hit = L::Flags::NONE;
        // Each loop ends when every lane is hit. Besides saving work, the exit keeps LLVM from
        // vectorizing across obstacles (a reduction it would otherwise pack, scattering each
        // lane's arithmetic into broadcasts): the lanes are the vectors.
        for s in self.spheres {
            hit = hit | s.hits(center, radius);
            if hit.all() {
                return hit;
            }
        }
        for c in self.capsules {
            hit = hit | c.hits(center, radius);
            if hit.all() {
                return hit;
            }
        }
        for c in self.cylinders {
            hit = hit | c.hits(center, radius);
            if hit.all() {
                return hit;
            }
        }
        for b in self.boxes {
            hit = hit | b.hits(center, radius);
            if hit.all() {
                return hit;
            }
        }
        hit
    }
}

fn check(numbers: &[f64], sizes_ok: bool, kind: &'static str, index: usize) -> Result<(), ObstacleError> {
    if !finite(numbers) {
        return Err(ObstacleError::NonFinite { kind, index });
    }
    if !sizes_ok {
        return Err(ObstacleError::BadSize { kind, index });
    }
    Ok(())
}

/// An obstacle a sphere can be tested against, on any [`CheckLanes`] type: prepared once per
/// check as constants of the lane type, then tested against each sphere.
pub(crate) trait Obstacle {
    /// Calls `visit` with the obstacle's constants in lanes (converted once: a check tests every
    /// link against it). Each kind of prepared obstacle is its own type, so the tests a visitor
    /// runs are compiled for it alone, with no branch on the kind inside them.
    fn prepare<L: CheckLanes, V: Visit<L>>(&self, visit: &mut V);

    /// The lanes where the sphere of `center` and `radius` touches the obstacle.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn hits<L: CheckLanes>(&self, center: &[L; 3], radius: L) -> L::Flags {
        let mut one = One { center, radius, hit: L::Flags::NONE };
        self.prepare(&mut one);
        one.hit
    }
}

/// What a check does with a prepared obstacle.
pub(crate) trait Visit<L: CheckLanes> {
    /// Tests with `obstacle`.
    fn visit<P: Prepared<L>>(&mut self, obstacle: &P);
}

/// A prepared obstacle: the lanes where a sphere touches it. Centres must be finite (the checks
/// mark configurations that are not before testing); a NaN distance would count as a hit.
pub(crate) trait Prepared<L: CheckLanes>: super::distance::Measure<L> {
    /// The lanes where the sphere of `center` and `radius` touches the obstacle.
    fn hits(&self, center: &[L; 3], radius: L) -> L::Flags;
}

/// One sphere against one obstacle.
struct One<'a, L: CheckLanes> {
    center: &'a [L; 3],
    radius: L,
    hit: L::Flags,
}

impl<L: CheckLanes> Visit<L> for One<'_, L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn visit<P: Prepared<L>>(&mut self, obstacle: &P) {
        self.hit = obstacle.hits(self.center, self.radius);
    }
}

#[cfg_attr(not(debug_assertions), inline(always))]
fn splat<L: CheckLanes>(v: Vec3) -> [L; 3] {
    [L::from_f64(v[0]), L::from_f64(v[1]), L::from_f64(v[2])]
}

#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn lane_dot<L: CheckLanes>(a: &[L; 3], b: &[L; 3]) -> L {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn lane_sub<L: CheckLanes>(a: &[L; 3], b: &[L; 3]) -> [L; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

// Every test compares squared distances: no square root per lane.

/// A sphere obstacle in lanes.
pub(crate) struct PreparedSphere<L> {
    pub(super) center: [L; 3],
    pub(super) radius: L,
}

impl Obstacle for SphereObstacle {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn prepare<L: CheckLanes, V: Visit<L>>(&self, visit: &mut V) {
        visit.visit(&PreparedSphere { center: splat::<L>(self.center), radius: L::from_f64(self.radius) });
    }
}

impl<L: CheckLanes> Prepared<L> for PreparedSphere<L> {
    /// Centres within the sum of the radii.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn hits(&self, center: &[L; 3], radius: L) -> L::Flags {
        let d = lane_sub(center, &self.center);
        let reach = radius + self.radius;
        lane_dot(&d, &d).not_above(reach * reach)
    }
}

/// A capsule obstacle in lanes: one end, the axis, the axis's inverse squared length.
pub(crate) struct PreparedCapsule<L> {
    pub(super) a: [L; 3],
    pub(super) axis: [L; 3],
    pub(super) inverse: L,
    pub(super) radius: L,
}

impl Obstacle for CapsuleObstacle {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn prepare<L: CheckLanes, V: Visit<L>>(&self, visit: &mut V) {
        let axis = sub(self.b, self.a);
        let length = dot(axis, axis);
        // A capsule of zero length is a sphere about `a`: every parameter is 0.
        let inverse = if length > 0.0 { 1.0 / length } else { 0.0 };
        visit.visit(&PreparedCapsule {
            a: splat::<L>(self.a),
            axis: splat(axis),
            inverse: L::from_f64(inverse),
            radius: L::from_f64(self.radius),
        });
    }
}

impl<L: CheckLanes> Prepared<L> for PreparedCapsule<L> {
    /// The centre within the sum of the radii of the axis segment's nearest point.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn hits(&self, center: &[L; 3], radius: L) -> L::Flags {
        let ab = &self.axis;
        let ap = lane_sub(center, &self.a);
        let (zero, one) = (L::from_f64(0.0), L::from_f64(1.0));
        let t = (lane_dot(&ap, ab) * self.inverse).max(zero).min(one);
        let d = [ap[0] - ab[0] * t, ap[1] - ab[1] * t, ap[2] - ab[2] * t];
        let reach = radius + self.radius;
        lane_dot(&d, &d).not_above(reach * reach)
    }
}

/// A cylinder obstacle in lanes: one cap's centre, the unit axis, the length, `R`, `R^2` and `4 R^2`.
pub(crate) struct PreparedCylinder<L> {
    pub(super) a: [L; 3],
    pub(super) unit: [L; 3],
    pub(super) length: L,
    pub(super) radius: L,
    pub(super) radius_squared: L,
    pub(super) four_radius_squared: L,
}

impl Obstacle for CylinderObstacle {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn prepare<L: CheckLanes, V: Visit<L>>(&self, visit: &mut V) {
        let axis = sub(self.b, self.a);
        // Positive: `Environment::new` refuses a cylinder without an axis.
        let length = sqrt(dot(axis, axis));
        visit.visit(&PreparedCylinder {
            a: splat::<L>(self.a),
            unit: splat([axis[0] / length, axis[1] / length, axis[2] / length]),
            length: L::from_f64(length),
            radius: L::from_f64(self.radius),
            radius_squared: L::from_f64(self.radius * self.radius),
            four_radius_squared: L::from_f64(4.0 * self.radius * self.radius),
        });
    }
}

impl<L: CheckLanes> Prepared<L> for PreparedCylinder<L> {
    /// With `rho` the centre's distance from the axis, `over` its distance beyond the nearer cap
    /// (0 between the caps) and `R` the cylinder's radius, the sphere of radius `r` touches when
    /// `max(rho - R, 0)^2 + over^2 <= r^2`. With `u = r^2 - over^2`, that is `u >= 0` and
    /// `rho <= R + sqrt(u)`, which squares (both sides non-negative) to
    /// `rho^2 - R^2 - u <= 2 R sqrt(u)`: true when the left side is not positive, and otherwise
    /// exactly when its square is at most `4 R^2 u`. No root is taken.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn hits(&self, center: &[L; 3], radius: L) -> L::Flags {
        let ap = lane_sub(center, &self.a);
        let along = lane_dot(&ap, &self.unit);
        let rho_squared = lane_dot(&ap, &ap) - along * along;
        let zero = L::from_f64(0.0);
        let over = (-along).max(along - self.length).max(zero);
        let u = radius * radius - over * over;
        let left = rho_squared - self.radius_squared - u;
        (-u).not_above(zero) & (left.not_above(zero) | (left * left).not_above(self.four_radius_squared * u))
    }
}

/// A box obstacle whose axes are the world's, in lanes: its centre and half extents.
pub(crate) struct AlignedBox<L> {
    pub(super) center: [L; 3],
    pub(super) half: [L; 3],
}

/// A turned box obstacle in lanes: its centre, its axes (rows), its half extents.
pub(crate) struct TurnedBox<L> {
    pub(super) center: [L; 3],
    pub(super) rows: [[L; 3]; 3],
    pub(super) half: [L; 3],
}

impl Obstacle for BoxObstacle {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn prepare<L: CheckLanes, V: Visit<L>>(&self, visit: &mut V) {
        const WORLD: [Vec3; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let (center, half) = (splat::<L>(self.center), splat::<L>(self.half_extents));
        // Axes exactly the world's (most scenes' boxes): the box coordinates are the offset's,
        // and the nine products a turned box needs are skipped.
        if self.rotation == WORLD {
            visit.visit(&AlignedBox { center, half });
        } else {
            let [x, y, z] = self.rotation;
            visit.visit(&TurnedBox { center, rows: [splat(x), splat(y), splat(z)], half });
        }
    }
}

/// Within `radius` of the box of half extents `half`, `local` being the centre's offset in the
/// box's frame: the squared distance to the box (the coordinates beyond the half extents) within
/// the radius squared.
#[cfg_attr(not(debug_assertions), inline(always))]
fn box_hits<L: CheckLanes>(local: [L; 3], half: &[L; 3], radius: L) -> L::Flags {
    let zero = L::from_f64(0.0);
    let mut sum = zero;
    for i in 0..3 {
        let over = (local[i].abs() - half[i]).max(zero);
        sum = sum + over * over;
    }
    sum.not_above(radius * radius)
}

impl<L: CheckLanes> Prepared<L> for AlignedBox<L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn hits(&self, center: &[L; 3], radius: L) -> L::Flags {
        box_hits(lane_sub(center, &self.center), &self.half, radius)
    }
}

impl<L: CheckLanes> Prepared<L> for TurnedBox<L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn hits(&self, center: &[L; 3], radius: L) -> L::Flags {
        let d = lane_sub(center, &self.center);
        let rows = &self.rows;
        box_hits([lane_dot(&rows[0], &d), lane_dot(&rows[1], &d), lane_dot(&rows[2], &d)], &self.half, radius)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix;
    use std::{vec, vec::Vec};

    fn point(rng: &mut SplitMix, scale: f64) -> Vec3 {
        [0; 3].map(|_| scale * (2.0 * rng.next() - 1.0))
    }

    /// A unit vector `u` and two more making a right-handed orthonormal frame with it.
    fn frame(rng: &mut SplitMix) -> [Vec3; 3] {
        let u = loop {
            let v = point(rng, 1.0);
            let n = sqrt(dot(v, v));
            if n > 0.1 {
                break v.map(|x| x / n);
            }
        };
        let helper = if u[0].abs() < 0.9 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
        let cross =
            |a: Vec3, b: Vec3| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        let v = cross(u, helper);
        let n = sqrt(dot(v, v));
        let v = v.map(|x| x / n);
        [u, v, cross(u, v)]
    }

    /// Random obstacles of every kind (boxes turned and not), and points of each on its
    /// surface where it reaches farthest: a sphere's poles, a capsule's ends pushed out along
    /// each axis, a cylinder's cap rims, a box's corners.
    fn obstacles_and_extremes(rng: &mut SplitMix) -> Obstacles {
        let (mut spheres, mut capsules, mut cylinders, mut boxes, mut extremes) =
            (vec![], vec![], vec![], vec![], vec![]);
        let axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let poles = axes.iter().flat_map(|e| [e.map(|x| x), e.map(|x| -x)]).collect::<Vec<Vec3>>();
        let add = |c: Vec3, d: Vec3, k: f64| [c[0] + k * d[0], c[1] + k * d[1], c[2] + k * d[2]];
        for _ in 0..1 + (rng.next() * 3.0) as usize {
            let s = SphereObstacle { center: point(rng, 2.0), radius: 0.05 + rng.next() };
            extremes.extend(poles.iter().map(|&e| add(s.center, e, s.radius)));
            spheres.push(s);
        }
        for _ in 0..1 + (rng.next() * 3.0) as usize {
            let c = CapsuleObstacle { a: point(rng, 2.0), b: point(rng, 2.0), radius: 0.05 + rng.next() };
            extremes.extend(poles.iter().flat_map(|&e| [add(c.a, e, c.radius), add(c.b, e, c.radius)]));
            capsules.push(c);
        }
        for _ in 0..1 + (rng.next() * 3.0) as usize {
            let [u, v, w] = frame(rng);
            let (a, radius) = (point(rng, 2.0), 0.05 + rng.next());
            let b = add(a, u, 0.1 + rng.next());
            for k in 0..64 {
                let t = k as f64 * core::f64::consts::TAU / 64.0;
                let rim = [0, 1, 2].map(|i| radius * (t.cos() * v[i] + t.sin() * w[i]));
                extremes.extend([add(a, rim, 1.0), add(b, rim, 1.0)]);
            }
            cylinders.push(CylinderObstacle { a, b, radius });
        }
        for turned in [false, true] {
            let rotation = if turned { frame(rng) } else { axes };
            let b = BoxObstacle { center: point(rng, 2.0), rotation, half_extents: [0; 3].map(|_| 0.05 + rng.next()) };
            for corner in 0..8 {
                let signs = [0, 1, 2].map(|k| if corner >> k & 1 == 1 { 1.0 } else { -1.0 });
                let offset = [0, 1, 2].map(|i| (0..3).map(|k| signs[k] * b.half_extents[k] * b.rotation[k][i]).sum());
                extremes.push(add(b.center, offset, 1.0));
            }
            boxes.push(b);
        }
        Obstacles { spheres, capsules, cylinders, boxes, extremes }
    }

    /// Obstacles of every kind, and points where they reach farthest.
    struct Obstacles {
        spheres: Vec<SphereObstacle>,
        capsules: Vec<CapsuleObstacle>,
        cylinders: Vec<CylinderObstacle>,
        boxes: Vec<BoxObstacle>,
        extremes: Vec<Vec3>,
    }

    /// `Environment::hits` (which asks the extent first) and its lanes answer as every obstacle
    /// asked one by one, for spheres near the obstacles, far from them and astride the extent's
    /// sides; both answers come up often.
    #[test]
    fn the_environment_answers_as_its_obstacles_one_by_one() {
        let mut rng = SplitMix(0x6869_7473);
        let mut counts = [0; 2];
        for round in 0..200 {
            let Obstacles { spheres, capsules, cylinders, boxes, .. } = obstacles_and_extremes(&mut rng);
            let env = Environment::new(&spheres, &capsules, &cylinders, &boxes).unwrap();
            let every = |c: Vec3, r: f64| {
                spheres.iter().any(|o| o.hits(&c, r))
                    || capsules.iter().any(|o| o.hits(&c, r))
                    || cylinders.iter().any(|o| o.hits(&c, r))
                    || boxes.iter().any(|o| o.hits(&c, r))
            };
            for _ in 0..16 {
                let (centers, radii): ([Vec3; 4], [f64; 4]) =
                    (core::array::from_fn(|_| point(&mut rng, 3.0)), core::array::from_fn(|_| 0.01 + 1.5 * rng.next()));
                let lanes = env
                    .hits_lanes(&[0, 1, 2].map(|i| crate::F64x4::new(centers.map(|c| c[i]))), crate::F64x4::new(radii));
                for l in 0..4 {
                    let expected = every(centers[l], radii[l]);
                    assert_eq!(
                        env.hits(centers[l], radii[l]),
                        expected,
                        "round {round}: {:?} {}",
                        centers[l],
                        radii[l]
                    );
                    assert_eq!(lanes.bits().lane(l), expected, "round {round}, lane {l}");
                    counts[usize::from(expected)] += 1;
                }
            }
        }
        assert!(counts[0] > 2000 && counts[1] > 2000, "free and hit: {counts:?}");
        // Near `f64`'s largest values: obstacles whose ends, or whose box, overflow. The extent
        // (finite, or infinite where an end overflows) skips only what its obstacle misses.
        let far = [
            SphereObstacle { center: [1.5e308, 0.0, 0.0], radius: 1.5e308 },
            SphereObstacle { center: [-1.5e308, 0.0, 0.0], radius: 1.0 },
            SphereObstacle { center: [-1.5e308, 0.0, 0.0], radius: 1e308 },
            SphereObstacle { center: [0.0, 1.7e308, -1.7e308], radius: 2.0 },
        ];
        let points = [
            [0.0; 3],
            [1.5e308, 0.0, 0.0],
            [-1.5e308, 0.5, 0.0],
            [-1.5e308, 3.0, 0.0],
            [-0.5e308, 0.0, 0.0],
            [0.0, 1.7e308, -1.7e308],
            [1.0, 1.7e308, -1.7e308],
        ];
        for (k, obstacle) in far.iter().enumerate() {
            let env = Environment::new(core::slice::from_ref(obstacle), &[], &[], &[]).unwrap();
            for p in points {
                assert_eq!(env.hits(p, 1.5), obstacle.hits(&p, 1.5), "obstacle {k}, {p:?}");
            }
        }
        assert!(Environment::new(&far[1..2], &[], &[], &[]).unwrap().hits([-1.5e308, 0.5, 0.0], 1.0));
    }

    /// The box the checks test each link against first holds every point of every obstacle,
    /// with at most its padding to spare on a side some obstacle reaches exactly (every side,
    /// in environments of spheres and boxes alone); with no obstacle there is none.
    #[test]
    fn the_extent_holds_every_obstacle() {
        let mut rng = SplitMix(0x6578_7465_6e74);
        for round in 0..200 {
            let Obstacles { spheres, capsules, cylinders, boxes, extremes } = obstacles_and_extremes(&mut rng);
            let env = Environment::new(&spheres, &capsules, &cylinders, &boxes).unwrap();
            let Extent { center, half } = env.extent.expect("obstacles: an extent");
            for p in &extremes {
                for i in 0..3 {
                    assert!((p[i] - center[i]).abs() <= half[i], "round {round}: {p:?} outside on axis {i}");
                }
            }
            // Spheres and boxes give their exact reach: the padding is all that is left over.
            let env = Environment::new(&spheres, &[], &[], &boxes).unwrap();
            let Extent { center, half } = env.extent.unwrap();
            let largest = center.iter().zip(&half).fold(0.0_f64, |m, (c, h)| m.max(c.abs() + h));
            for i in 0..3 {
                for side in [-1.0, 1.0] {
                    let face = center[i] + side * half[i];
                    let nearest = extremes[..6 * spheres.len()]
                        .iter()
                        .chain(&extremes[extremes.len() - 16..])
                        .map(|p| (face - p[i]).abs())
                        .fold(f64::INFINITY, f64::min);
                    assert!(nearest <= 1e-5 * largest + 1e-5 + 1e-12, "round {round}: axis {i}, {nearest} to spare");
                }
            }
        }
        assert_eq!(Environment::empty().extent, None);
        assert_eq!(Environment::new(&[], &[], &[], &[]).unwrap().extent, None);
    }

    /// `o` at distance `d` from `p`: a sphere there of radius a hair over `d` hits it, one a hair
    /// under does not (inside, `d` = 0, any radius hits); on `f64`, `f32` and lanes alike (lane 1
    /// far away, lane 2 a hair under).
    fn at_distance(o: &impl Obstacle, p: Vec3, d: f64) {
        let (over, under) = (d + 1e-9, d - 1e-9);
        assert!(o.hits(&p, over), "{p:?} at {d}: not hit by a sphere of {over}");
        assert!(d == 0.0 || !o.hits(&p, under), "{p:?} at {d}: hit by a sphere of {under}");
        let (over32, under32) = (d as f32 + 1e-5, d as f32 - 1e-5);
        assert!(o.hits(&p.map(|x| x as f32), over32), "{p:?} at {d} (f32)");
        assert!(d == 0.0 || !o.hits(&p.map(|x| x as f32), under32), "{p:?} at {d} (f32)");
        let lanes = p.map(|x| crate::F64x4::new([x, x + 100.0, x, x]));
        let radii = crate::F64x4::new([over, over, under, over]);
        let expected = if d == 0.0 { 0b1101 } else { 0b1001 };
        assert_eq!(o.hits(&lanes, radii).bits().bits(), expected, "{p:?} at {d} (lanes)");
    }

    #[test]
    fn each_shape_is_hit_exactly_within_its_distance() {
        let s = SphereObstacle { center: [1.0, 0.0, 0.0], radius: 0.5 };
        at_distance(&s, [3.0, 0.0, 0.0], 1.5);
        at_distance(&s, [1.0, 0.2, 0.0], 0.0);
        let c = CapsuleObstacle { a: [0.0; 3], b: [0.0, 0.0, 2.0], radius: 0.5 };
        at_distance(&c, [2.0, 0.0, 1.0], 1.5);
        at_distance(&c, [0.0, 0.0, 4.0], 1.5);
        at_distance(&c, [0.0, -3.0, -4.0], 4.5);
        let point = CapsuleObstacle { a: [1.0; 3], b: [1.0; 3], radius: 0.5 };
        at_distance(&point, [1.0, 1.0, 3.0], 1.5);
        let y = CylinderObstacle { a: [0.0; 3], b: [0.0, 0.0, 2.0], radius: 0.5 };
        at_distance(&y, [2.0, 0.0, 1.0], 1.5);
        at_distance(&y, [0.0, 0.0, 4.0], 2.0);
        at_distance(&y, [0.3, 0.0, 3.0], 1.0);
        at_distance(&y, [0.0, 0.0, 1.0], 0.0);
        at_distance(&y, [3.5, 0.0, 6.0], 5.0);
        at_distance(&y, [0.0, -1.1, -0.8], 1.0);
        let b = BoxObstacle {
            center: [0.0; 3],
            rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            half_extents: [1.0, 2.0, 3.0],
        };
        at_distance(&b, [4.0, 0.0, 0.0], 3.0);
        at_distance(&b, [4.0, 6.0, 0.0], 5.0);
        at_distance(&b, [0.5, 0.5, 0.5], 0.0);
        let turned =
            BoxObstacle::from_pose([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], [1.0; 3], [2.0, 4.0, 6.0]);
        // Turned a quarter about z: its 4 m edge lies along x.
        at_distance(&turned, [4.0, 1.0, 1.0], 1.0);
        at_distance(&turned, [1.0, 3.0, 1.0], 1.0);
    }

    #[test]
    fn bad_obstacles_are_refused() {
        let nan = [SphereObstacle { center: [f64::NAN, 0.0, 0.0], radius: 1.0 }];
        assert_eq!(
            Environment::new(&nan, &[], &[], &[]).unwrap_err(),
            ObstacleError::NonFinite { kind: "sphere", index: 0 }
        );
        let negative = [CapsuleObstacle { a: [0.0; 3], b: [1.0, 0.0, 0.0], radius: -1.0 }];
        assert_eq!(
            Environment::new(&[], &negative, &[], &[]).unwrap_err(),
            ObstacleError::BadSize { kind: "capsule", index: 0 }
        );
        let skew = [BoxObstacle {
            center: [0.0; 3],
            rotation: [[1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
            half_extents: [1.0; 3],
        }];
        assert!(Environment::new(&[], &[], &[], &skew).is_err());
        let flat = [CylinderObstacle { a: [0.0; 3], b: [0.0; 3], radius: 1.0 }];
        assert!(Environment::new(&[], &[], &flat, &[]).is_err());
        assert!(Environment::new(&[], &[], &[], &[]).unwrap().is_empty());
    }

    #[test]
    fn a_centre_that_is_not_finite_is_never_free() {
        let boxes = [BoxObstacle {
            center: [9.0; 3],
            rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            half_extents: [1.0; 3],
        }];
        let spheres = [SphereObstacle { center: [9.0; 3], radius: 1.0 }];
        let capsules = [CapsuleObstacle { a: [9.0; 3], b: [9.0, 9.0, 10.0], radius: 1.0 }];
        for env in [
            Environment::new(&[], &[], &[], &boxes).unwrap(),
            Environment::new(&spheres, &[], &[], &[]).unwrap(),
            Environment::new(&[], &capsules, &[], &[]).unwrap(),
        ] {
            assert!(!env.hits([0.0; 3], 0.1));
            for bad in [[f64::NAN, 0.0, 0.0], [0.0, f64::INFINITY, 0.0], [0.0, 0.0, f64::NEG_INFINITY]] {
                assert!(env.hits(bad, 0.1), "{bad:?}");
            }
        }
    }

    #[test]
    fn the_answer_does_not_depend_on_the_obstacles_order() {
        let far = SphereObstacle { center: [10.0, 0.0, 0.0], radius: 1.0 };
        let near = SphereObstacle { center: [0.0; 3], radius: 1.0 };
        for order in [[far, near], [near, far]] {
            assert!(Environment::new(&order, &[], &[], &[]).unwrap().hits([1.5, 0.0, 0.0], 0.6));
        }
    }
}
