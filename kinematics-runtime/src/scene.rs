//! A scene file's obstacles as the core's obstacle types: what a compiled robot's `collides`
//! takes (through [`SceneObstacles::environment`]) and what the reference checks
//! ([`SceneObstacles::reference`]).
//!
//! `SceneObstacles` is what the facade's `load_scene` returns.

use kinematics_core::collision::{
    BoxObstacle, CapsuleObstacle, CylinderObstacle, Environment, ObstacleError, SphereObstacle,
};
use kinematics_model::collision::Shape;
use kinematics_model::scene::Scene;

use crate::collision::ReferenceObstacles;

/// A scene's obstacles, by kind, each with its name (in the order of its kind's list).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SceneObstacles {
    /// The spheres.
    pub spheres: Vec<SphereObstacle>,
    /// The capsules.
    pub capsules: Vec<CapsuleObstacle>,
    /// The cylinders.
    pub cylinders: Vec<CylinderObstacle>,
    /// The boxes.
    pub boxes: Vec<BoxObstacle>,
    /// Every obstacle's name, by kind in the order above.
    pub names: Vec<String>,
}

impl SceneObstacles {
    /// The obstacles of `scene`: each shape at its pose (a cylinder's or capsule's axis is its
    /// frame's z axis, its ends half its length either side of its centre, as in URDF).
    pub fn from_scene(scene: &Scene) -> Self {
        let mut out = SceneObstacles::default();
        let mut names: [Vec<String>; 4] = Default::default();
        for obstacle in &scene.obstacles {
            let kind = match obstacle.shape {
                Shape::Sphere { .. } => 0,
                Shape::Capsule { .. } => 1,
                Shape::Cylinder { .. } => 2,
                Shape::Box { .. } => 3,
                // The scene reader has no mesh or ellipsoid: a scene's shapes are the four above.
                Shape::Mesh { .. } | Shape::Ellipsoid { .. } => continue,
            };
            out.push(String::new(), obstacle.xyz, obstacle.rpy, obstacle.shape.clone());
            names[kind].push(obstacle.name.clone());
        }
        out.names = names.concat();
        out
    }

    /// Adds an obstacle named `name`: `shape` (a sphere, box, cylinder or capsule, as a scene
    /// file's entry gives it: full edge lengths, a cylinder's or capsule's axis along its frame's
    /// z axis) centred at `xyz` and turned by `rpy` (m and rad, URDF's fixed-axis order), at the
    /// end of its kind's list. Its numbers are checked as [`Environment::new`] checks them (an
    /// error names its kind and its index in that list, and nothing is added); a mesh or an
    /// ellipsoid is refused as a size that is not one. This is how a planner keeps an owned, growing set of
    /// obstacles and borrows an [`Environment`] of it per query.
    ///
    /// ```
    /// use kinematics_model::collision::Shape;
    /// use kinematics_runtime::SceneObstacles;
    /// let mut scene = SceneObstacles::default();
    /// scene.add("table", [0.6, 0.0, -0.05], [0.0; 3], Shape::Box { size: [0.8, 1.4, 0.1] })?;
    /// scene.add("bottle", [0.5, 0.2, 0.1], [0.0; 3], Shape::Cylinder { radius: 0.04, length: 0.2 })?;
    /// assert!(scene.add("bad", [0.0; 3], [0.0; 3], Shape::Sphere { radius: -1.0 }).is_err());
    /// assert_eq!((scene.len(), scene.environment()?.len()), (2, 2));
    /// # Ok::<(), kinematics_core::collision::ObstacleError>(())
    /// ```
    pub fn add(
        &mut self,
        name: impl Into<String>,
        xyz: [f64; 3],
        rpy: [f64; 3],
        shape: Shape,
    ) -> Result<&mut Self, ObstacleError> {
        let (kind, index, before) = match shape {
            Shape::Sphere { .. } => ("sphere", self.spheres.len(), 0),
            Shape::Capsule { .. } => ("capsule", self.capsules.len(), self.spheres.len()),
            Shape::Cylinder { .. } => ("cylinder", self.cylinders.len(), self.spheres.len() + self.capsules.len()),
            Shape::Box { .. } => {
                ("box", self.boxes.len(), self.spheres.len() + self.capsules.len() + self.cylinders.len())
            }
            Shape::Mesh { .. } => return Err(ObstacleError::BadSize { kind: "mesh", index: 0 }),
            Shape::Ellipsoid { .. } => return Err(ObstacleError::BadSize { kind: "ellipsoid", index: 0 }),
        };
        let mut one = SceneObstacles::default();
        one.push(String::new(), xyz, rpy, shape);
        one.environment().map_err(|error| match error {
            ObstacleError::NonFinite { .. } => ObstacleError::NonFinite { kind, index },
            ObstacleError::BadSize { .. } | ObstacleError::TooMany { .. } => ObstacleError::BadSize { kind, index },
        })?;
        let (spheres, capsules, cylinders, boxes) = (one.spheres, one.capsules, one.cylinders, one.boxes);
        self.spheres.extend(spheres);
        self.capsules.extend(capsules);
        self.cylinders.extend(cylinders);
        self.boxes.extend(boxes);
        self.names.insert(before + index, name.into());
        Ok(self)
    }

    /// Adds `shape` at `xyz` and `rpy` to its kind's list, unchecked, its name at the end of
    /// `names` (in file order; [`SceneObstacles::from_scene`] orders them by kind after).
    fn push(&mut self, name: String, xyz: [f64; 3], rpy: [f64; 3], shape: Shape) {
        match shape {
            Shape::Sphere { radius } => self.spheres.push(SphereObstacle { center: xyz, radius }),
            Shape::Capsule { radius, length } => {
                self.capsules.push(CapsuleObstacle::from_xyz_rpy(xyz, rpy, radius, length));
            }
            Shape::Cylinder { radius, length } => {
                self.cylinders.push(CylinderObstacle::from_xyz_rpy(xyz, rpy, radius, length));
            }
            Shape::Box { size } => self.boxes.push(BoxObstacle::from_xyz_rpy(xyz, rpy, size)),
            // The scene reader has neither, and `add` refuses both.
            Shape::Mesh { .. } | Shape::Ellipsoid { .. } => return,
        }
        self.names.push(name);
    }

    /// The environment a compiled robot's `collides` takes, borrowing these obstacles. Fails only
    /// where [`Environment::new`] does (a scene file's obstacles are already checked).
    pub fn environment(&self) -> Result<Environment<'_>, ObstacleError> {
        Environment::new(&self.spheres, &self.capsules, &self.cylinders, &self.boxes)
    }

    /// The reference's shapes of these obstacles (parry3d-f64).
    pub fn reference(&self) -> ReferenceObstacles {
        ReferenceObstacles::new(&self.spheres, &self.capsules, &self.cylinders, &self.boxes)
    }

    /// How many obstacles.
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// Whether there is none.
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kinematics_model::scene::{SceneFormat, parse_scene};

    #[test]
    fn shapes_land_where_the_file_puts_them() {
        let text = r#"
[[obstacle]]
name = "post"
xyz = [1.0, 2.0, 3.0]
rpy = [0.0, 1.5707963267948966, 0.0]
cylinder = { radius = 0.1, length = 2.0 }

[[obstacle]]
name = "crate"
xyz = [0.5, 0.0, 0.0]
rpy = [0.0, 0.0, 1.5707963267948966]
box = { size = [2.0, 4.0, 6.0] }
"#;
        let obstacles = SceneObstacles::from_scene(&parse_scene(text, SceneFormat::Toml).unwrap());
        // Pitched a quarter turn, the cylinder's axis runs along x.
        let c = obstacles.cylinders[0];
        for (got, want) in c.a.iter().chain(&c.b).zip([0.0, 2.0, 3.0, 2.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-15, "{c:?}");
        }
        // Yawed a quarter turn, the box's 4 m edge runs along x: x = 2.6 is 0.1 outside it.
        let env = obstacles.environment().unwrap();
        assert!(env.hits([2.6, 0.0, 0.0], 0.11) && !env.hits([2.6, 0.0, 0.0], 0.09));
        assert_eq!(obstacles.names, ["post", "crate"]);
    }
}
