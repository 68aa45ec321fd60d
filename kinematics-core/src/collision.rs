//! Collision checking at run time, for generated code: obstacles (spheres, capsules, cylinders,
//! oriented boxes), an environment borrowing slices of them, and the checks a compiled robot's
//! `collides` and `self_collides` run on its sphere centres and the tables the compiler wrote.
//!
//! No heap: an [`Environment`] borrows the caller's slices. A NaN or infinite obstacle never makes
//! a configuration free: [`Environment::new`] refuses it (and a negative or zero size), so a
//! check never meets one. Touching counts as colliding. The answer does not depend on the order
//! of the obstacles: every obstacle is tested until one is hit.

use libm::sqrt;

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
    /// vector `v` has box coordinates `rotation * v`.
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
    spheres: &'a [SphereObstacle],
    capsules: &'a [CapsuleObstacle],
    cylinders: &'a [CylinderObstacle],
    boxes: &'a [BoxObstacle],
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
        Ok(Environment { spheres, capsules, cylinders, boxes })
    }

    /// No obstacles.
    pub const fn empty() -> Self {
        Environment { spheres: &[], capsules: &[], cylinders: &[], boxes: &[] }
    }

    /// How many obstacles.
    pub fn len(&self) -> usize {
        self.spheres.len() + self.capsules.len() + self.cylinders.len() + self.boxes.len()
    }

    /// Whether there is none.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether the sphere of `center` and `radius` touches or overlaps any obstacle. A centre
    /// with a NaN or infinite coordinate (a configuration that is not finite) touches every
    /// obstacle: it is never free.
    #[inline]
    pub fn hits(&self, center: Vec3, radius: f64) -> bool {
        // A NaN distance is a hit.
        let within = |d: f64| d <= radius || d.is_nan();
        (!finite(&center) && !self.is_empty())
            || self.spheres.iter().any(|s| within(sphere_distance(s, center)))
            || self.capsules.iter().any(|c| within(capsule_distance(c, center)))
            || self.cylinders.iter().any(|c| within(cylinder_distance(c, center)))
            || self.boxes.iter().any(|b| within(box_distance(b, center)))
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

/// Distance from `p` to the sphere obstacle's surface (negative inside).
fn sphere_distance(s: &SphereObstacle, p: Vec3) -> f64 {
    let d = sub(p, s.center);
    sqrt(dot(d, d)) - s.radius
}

/// `p`'s offset from the segment `a`..`b`: the parameter of its nearest point, clamped, and the
/// squared distance to it.
fn segment_distance_squared(a: Vec3, b: Vec3, p: Vec3) -> f64 {
    let (ab, ap) = (sub(b, a), sub(p, a));
    let length = dot(ab, ab);
    let t = if length > 0.0 { (dot(ap, ab) / length).clamp(0.0, 1.0) } else { 0.0 };
    let nearest = [a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]];
    let d = sub(p, nearest);
    dot(d, d)
}

/// Distance from `p` to the capsule obstacle's surface (negative inside).
fn capsule_distance(c: &CapsuleObstacle, p: Vec3) -> f64 {
    sqrt(segment_distance_squared(c.a, c.b, p)) - c.radius
}

/// Distance from `p` to the solid cylinder (zero inside).
fn cylinder_distance(c: &CylinderObstacle, p: Vec3) -> f64 {
    let (axis, ap) = (sub(c.b, c.a), sub(p, c.a));
    let length = sqrt(dot(axis, axis));
    let along = dot(ap, axis) / length;
    let radial = sqrt((dot(ap, ap) - along * along).max(0.0));
    let over_radius = (radial - c.radius).max(0.0);
    let over_axis = (-along).max(along - length).max(0.0);
    sqrt(over_radius * over_radius + over_axis * over_axis)
}

/// Distance from `p` to the solid box (zero inside).
fn box_distance(b: &BoxObstacle, p: Vec3) -> f64 {
    let d = sub(p, b.center);
    let mut sum = 0.0;
    for i in 0..3 {
        let over = (dot(b.rotation[i], d).abs() - b.half_extents[i]).max(0.0);
        sum += over * over;
    }
    sqrt(sum)
}

/// A compiled robot's collision tables, as its generated code holds them: each link with spheres
/// (its range of spheres and its bounding sphere's index among the centres), the spheres' radii,
/// and the link pairs its self-collision check tests.
#[derive(Debug, Clone, Copy)]
pub struct CollisionTables<'a> {
    /// Per link with spheres: its spheres `start..end` in the sphere order, and its bounding
    /// sphere's radius (its centre follows the spheres' in the centres array, in link order).
    pub links: &'a [(usize, usize, f64)],
    /// Each sphere's radius.
    pub radii: &'a [f64],
    /// The pairs of links (indices into `links`) the self-collision check tests.
    pub pairs: &'a [(usize, usize)],
}

impl CollisionTables<'_> {
    /// Whether the robot with these centres (the spheres', then the links' bounding spheres')
    /// touches an obstacle of `env`: each link's bounding sphere first, its spheres only where
    /// that hits; the first hit ends the check.
    pub fn collides(&self, centers: &[Vec3], env: &Environment<'_>) -> bool {
        let bounds = &centers[self.radii.len()..];
        self.links.iter().zip(bounds).any(|(&(start, end, radius), &bound)| {
            env.hits(bound, radius) && (start..end).any(|k| env.hits(centers[k], self.radii[k]))
        })
    }

    /// Whether two links of a checked pair touch: their bounding spheres first, then their
    /// spheres pair by pair; the first hit ends the check.
    pub fn self_collides(&self, centers: &[Vec3]) -> bool {
        let bounds = &centers[self.radii.len()..];
        // A NaN distance (a configuration that is not finite) is a touch.
        let touch = |a: Vec3, ra: f64, b: Vec3, rb: f64| {
            let d = sub(a, b);
            let squared = dot(d, d);
            squared <= (ra + rb) * (ra + rb) || squared.is_nan()
        };
        self.pairs.iter().any(|&(i, j)| {
            let ((sa, ea, ra), (sb, eb, rb)) = (self.links[i], self.links[j]);
            touch(bounds[i], ra, bounds[j], rb)
                && (sa..ea).any(|a| (sb..eb).any(|b| touch(centers[a], self.radii[a], centers[b], self.radii[b])))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_of_each_shape() {
        let s = SphereObstacle { center: [1.0, 0.0, 0.0], radius: 0.5 };
        assert_eq!(sphere_distance(&s, [3.0, 0.0, 0.0]), 1.5);
        let c = CapsuleObstacle { a: [0.0; 3], b: [0.0, 0.0, 2.0], radius: 0.5 };
        assert_eq!(capsule_distance(&c, [2.0, 0.0, 1.0]), 1.5);
        assert_eq!(capsule_distance(&c, [0.0, 0.0, 4.0]), 1.5);
        let y = CylinderObstacle { a: [0.0; 3], b: [0.0, 0.0, 2.0], radius: 0.5 };
        assert_eq!(cylinder_distance(&y, [2.0, 0.0, 1.0]), 1.5);
        assert_eq!(cylinder_distance(&y, [0.0, 0.0, 4.0]), 2.0);
        assert_eq!(cylinder_distance(&y, [0.0, 0.0, 1.0]), 0.0);
        assert!((cylinder_distance(&y, [3.5, 0.0, 6.0]) - 5.0).abs() < 1e-15);
        let b = BoxObstacle {
            center: [0.0; 3],
            rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            half_extents: [1.0, 2.0, 3.0],
        };
        assert_eq!(box_distance(&b, [4.0, 0.0, 0.0]), 3.0);
        assert_eq!(box_distance(&b, [4.0, 6.0, 0.0]), 5.0);
        assert_eq!(box_distance(&b, [0.5, 0.5, 0.5]), 0.0);
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
        let tables = CollisionTables { links: &[(0, 1, 0.1), (1, 2, 0.1)], radii: &[0.1, 0.1], pairs: &[(0, 1)] };
        let far = [[0.0; 3], [5.0, 0.0, 0.0], [0.0; 3], [5.0, 0.0, 0.0]];
        assert!(!tables.self_collides(&far));
        let nan = [[f64::NAN; 3], [5.0, 0.0, 0.0], [f64::NAN; 3], [5.0, 0.0, 0.0]];
        assert!(tables.self_collides(&nan));
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
