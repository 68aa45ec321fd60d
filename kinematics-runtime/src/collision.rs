//! Collision spheres at run time, the reference's own way: each sphere's centre in the root frame
//! as the link's pose (the reference's forward kinematics), then the `<collision>` element's origin
//! (as an nalgebra isometry), applied to the cover's centre. Shares nothing with the compiler but
//! the model's selections: the spheres, and the sphere pairs held apart for good that the
//! clearance leaves out.
//!
//! `ReferenceFk::sphere_centers` gives each sphere's centre; the signed distances of
//! `obstacle_distance`, `self_distance` (and `measured_self_distances`, less the pairs held apart
//! for good, for the clearance) and a held object's `held_distances` are parry3d-f64's
//! (`ReferenceObstacles`: the core's obstacles as parry shapes, by the reference's own reading of
//! them).

use std::collections::BTreeSet;

use kinematics_model::collision::{FixedPair, LinkSphere};
use nalgebra::Point3;

use crate::error::RuntimeError;
use crate::fk::ReferenceFk;

impl ReferenceFk {
    /// The centres of `spheres` (the model's
    /// [`link_spheres`](kinematics_model::collision::link_spheres), in its order) at `q`, in the
    /// root frame.
    pub fn sphere_centers(&self, q: &[f64], spheres: &[LinkSphere]) -> Result<Vec<Point3<f64>>, RuntimeError> {
        let poses = self.link_poses(q)?;
        Ok(spheres.iter().map(|s| poses[s.link.0] * Point3::from(s.sphere.center)).collect())
    }
}

use kinematics_core::collision::{BoxObstacle, CapsuleObstacle, CylinderObstacle, SphereObstacle};
use kinematics_model::LinkId;
use parry3d_f64::math::{Matrix, Pose, Rotation, Vector};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Capsule, Cuboid, Cylinder, Shape};

/// Obstacles as the reference checks them: each a parry shape at its pose, built from the core's
/// obstacle types by the reference's own reading of them (a cylinder is parry's, along its y axis,
/// turned onto the segment; a box is parry's cuboid turned by the box's axes).
pub struct ReferenceObstacles {
    shapes: Vec<(Pose, Box<dyn Shape>)>,
}

impl std::fmt::Debug for ReferenceObstacles {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ReferenceObstacles").field("count", &self.shapes.len()).finish()
    }
}

fn vector(v: [f64; 3]) -> Vector {
    Vector::new(v[0], v[1], v[2])
}

impl ReferenceObstacles {
    /// The reference's shapes of these obstacles (every kind, any order).
    pub fn new(
        spheres: &[SphereObstacle],
        capsules: &[CapsuleObstacle],
        cylinders: &[CylinderObstacle],
        boxes: &[BoxObstacle],
    ) -> Self {
        let mut shapes: Vec<(Pose, Box<dyn Shape>)> = Vec::new();
        for s in spheres {
            shapes.push((Pose::from_translation(vector(s.center)), Box::new(Ball::new(s.radius))));
        }
        for c in capsules {
            shapes.push((Pose::IDENTITY, Box::new(Capsule::new(vector(c.a), vector(c.b), c.radius))));
        }
        for c in cylinders {
            let (a, b) = (vector(c.a), vector(c.b));
            let axis = b - a;
            let rotation = Rotation::from_rotation_arc(Vector::Y, axis.normalize());
            let pose = Pose::from_parts((a + b) * 0.5, rotation);
            shapes.push((pose, Box::new(Cylinder::new(axis.length() / 2.0, c.radius))));
        }
        for b in boxes {
            // The box's axis `i` is row `i` of its rotation: the columns of its frame's matrix.
            let frame = Matrix::from_cols(vector(b.rotation[0]), vector(b.rotation[1]), vector(b.rotation[2]));
            let pose = Pose::from_parts(vector(b.center), Rotation::from_mat3(&frame));
            shapes.push((pose, Box::new(Cuboid::new(vector(b.half_extents)))));
        }
        ReferenceObstacles { shapes }
    }

    /// Whether the ball of `center` and `radius` touches or overlaps one of the shapes (parry's
    /// intersection test; a pair parry cannot test counts as touching).
    pub fn intersects(&self, center: [f64; 3], radius: f64) -> bool {
        let (at, ball) = (Pose::from_translation(vector(center)), Ball::new(radius));
        self.shapes.iter().any(|(pose, shape)| {
            query::intersection_test(&at, &ball, pose, shape.as_ref()).map_or(true, |i| i.intersecting)
        })
    }
}

/// The signed distance between a ball and a shape: parry's distance where they are apart, minus
/// the penetration depth of parry's contact where they touch or overlap.
fn signed_distance(ball_at: &Pose, ball: &Ball, pose: &Pose, shape: &dyn Shape) -> f64 {
    let apart = query::distance(ball_at, ball, pose, shape).map(|d| d.distance).unwrap_or(f64::NAN);
    if apart > 0.0 {
        return apart;
    }
    match query::contact(ball_at, ball, pose, shape, 0.0) {
        Ok(Some(contact)) => contact.dist.min(0.0),
        Ok(None) => 0.0,
        Err(_) => f64::NAN,
    }
}

impl ReferenceFk {
    /// The signed distance (m) of every sphere of `spheres` at `q` to every one of `obstacles`,
    /// sphere by sphere (negative: overlapping by that much; NaN where parry could not measure a
    /// pair, which no check may take for free).
    pub fn obstacle_distances(
        &self,
        q: &[f64],
        spheres: &[LinkSphere],
        obstacles: &ReferenceObstacles,
    ) -> Result<Vec<f64>, RuntimeError> {
        let centers = self.sphere_centers(q, spheres)?;
        let mut out = Vec::with_capacity(spheres.len() * obstacles.shapes.len());
        for (s, c) in spheres.iter().zip(&centers) {
            let at = Pose::from_translation(Vector::new(c.x, c.y, c.z));
            let ball = Ball::new(s.sphere.radius);
            for (pose, shape) in &obstacles.shapes {
                out.push(signed_distance(&at, &ball, pose, shape.as_ref()));
            }
        }
        Ok(out)
    }

    /// The smallest signed distance (m) between the robot's `spheres` at `q` and `obstacles`
    /// (negative: overlapping by that much; infinite with no obstacle; NaN if parry could not
    /// measure a pair).
    pub fn obstacle_distance(
        &self,
        q: &[f64],
        spheres: &[LinkSphere],
        obstacles: &ReferenceObstacles,
    ) -> Result<f64, RuntimeError> {
        Ok(least(&self.obstacle_distances(q, spheres, obstacles)?))
    }

    /// The signed distance (m) between every two spheres of the links of each pair in `pairs`
    /// at `q`, pair by pair.
    pub fn self_distances(
        &self,
        q: &[f64],
        spheres: &[LinkSphere],
        pairs: &[(LinkId, LinkId)],
    ) -> Result<Vec<f64>, RuntimeError> {
        self.pair_distances(q, spheres, pairs, &BTreeSet::new())
    }

    /// The signed distances the clearance measures between the links of each pair in `pairs` at
    /// `q`: as [`Self::self_distances`], less the sphere pairs `fixed` (held apart for good: the
    /// model's `fixed_apart_pairs` of these pairs), pair by pair.
    pub fn measured_self_distances(
        &self,
        q: &[f64],
        spheres: &[LinkSphere],
        pairs: &[(LinkId, LinkId)],
        fixed: &[FixedPair],
    ) -> Result<Vec<f64>, RuntimeError> {
        let fixed: BTreeSet<(usize, usize)> = fixed.iter().map(|f| (f.a, f.b)).collect();
        self.pair_distances(q, spheres, pairs, &fixed)
    }

    /// The signed distances between every two spheres of the links of each pair in `pairs` at
    /// `q` but those of `skip` (sphere indices, the lesser first), pair by pair.
    fn pair_distances(
        &self,
        q: &[f64],
        spheres: &[LinkSphere],
        pairs: &[(LinkId, LinkId)],
        skip: &BTreeSet<(usize, usize)>,
    ) -> Result<Vec<f64>, RuntimeError> {
        let centers = self.sphere_centers(q, spheres)?;
        let at = |c: &Point3<f64>| Pose::from_translation(Vector::new(c.x, c.y, c.z));
        // Each link's spheres (indices, in the spheres' order), so that a pair walks its two links'
        // spheres alone rather than every sphere twice.
        let mut of_link = vec![Vec::new(); self.tree().links().len()];
        for (i, s) in spheres.iter().enumerate() {
            of_link[s.link.0].push(i);
        }
        let mut out = Vec::new();
        for &(a, b) in pairs {
            for &i in &of_link[a.0] {
                for &j in &of_link[b.0] {
                    if skip.contains(&(i.min(j), i.max(j))) {
                        continue;
                    }
                    let (sa, sb) = (&spheres[i], &spheres[j]);
                    let (ball_a, ball_b) = (Ball::new(sa.sphere.radius), Ball::new(sb.sphere.radius));
                    out.push(signed_distance(&at(&centers[i]), &ball_a, &at(&centers[j]), &ball_b));
                }
            }
        }
        Ok(out)
    }

    /// The smallest signed distance (m) between spheres of the links of each pair in `pairs` at
    /// `q` (infinite with no pair).
    pub fn self_distance(
        &self,
        q: &[f64],
        spheres: &[LinkSphere],
        pairs: &[(LinkId, LinkId)],
    ) -> Result<f64, RuntimeError> {
        Ok(least(&self.self_distances(q, spheres, pairs)?))
    }
}

/// The least of `distances` (infinite with none), NaN if one is.
fn least(distances: &[f64]) -> f64 {
    distances.iter().fold(f64::INFINITY, |least, &d| if d.is_nan() || least.is_nan() { f64::NAN } else { least.min(d) })
}

impl ReferenceFk {
    /// The smallest signed distances (m) of an object held by `link` at `q` (`held`: spheres with
    /// their centres in `link`'s frame): to `obstacles`, and to the robot's `spheres` on links
    /// other than those of `skip` (infinite where there is nothing to measure; NaN where parry
    /// could not measure a pair).
    pub fn held_distances(
        &self,
        q: &[f64],
        link: LinkId,
        held: &[SphereObstacle],
        spheres: &[LinkSphere],
        obstacles: &ReferenceObstacles,
        skip: &[LinkId],
    ) -> Result<(f64, f64), RuntimeError> {
        let pose = self.link_poses(q)?[link.0];
        let centers = self.sphere_centers(q, spheres)?;
        let (mut to_obstacles, mut to_robot) = (f64::INFINITY, f64::INFINITY);
        let least = |least: f64, d: f64| if d.is_nan() || least.is_nan() { f64::NAN } else { least.min(d) };
        for h in held {
            let c = pose * Point3::from(h.center);
            let (at, ball) = (Pose::from_translation(Vector::new(c.x, c.y, c.z)), Ball::new(h.radius));
            for (shape_pose, shape) in &obstacles.shapes {
                to_obstacles = least(to_obstacles, signed_distance(&at, &ball, shape_pose, shape.as_ref()));
            }
            for (s, other) in spheres.iter().zip(&centers).filter(|(s, _)| !skip.contains(&s.link)) {
                let other = Pose::from_translation(Vector::new(other.x, other.y, other.z));
                to_robot = least(to_robot, signed_distance(&at, &ball, &other, &Ball::new(s.sphere.radius)));
            }
        }
        Ok((to_obstacles, to_robot))
    }
}
