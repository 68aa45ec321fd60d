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
use nalgebra::Vector3;

use crate::collision::ReferenceObstacles;
use crate::fk::fixed_isometry;

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
            let pose = fixed_isometry(&obstacle.origin());
            let center = pose.translation.vector;
            let point = |v: Vector3<f64>| [v[0], v[1], v[2]];
            let ends = |length: f64| {
                let half = pose.rotation * Vector3::z() * (length / 2.0);
                (point(center - half), point(center + half))
            };
            let name = obstacle.name.clone();
            match obstacle.shape {
                Shape::Sphere { radius } => {
                    out.spheres.push(SphereObstacle { center: point(center), radius });
                    names[0].push(name);
                }
                Shape::Capsule { radius, length } => {
                    let (a, b) = ends(length);
                    out.capsules.push(CapsuleObstacle { a, b, radius });
                    names[1].push(name);
                }
                Shape::Cylinder { radius, length } => {
                    let (a, b) = ends(length);
                    out.cylinders.push(CylinderObstacle { a, b, radius });
                    names[2].push(name);
                }
                Shape::Box { size } => {
                    let m = pose.rotation.to_rotation_matrix();
                    let rows = [0, 1, 2].map(|i| [m[(i, 0)], m[(i, 1)], m[(i, 2)]]);
                    out.boxes.push(BoxObstacle::from_pose(rows, point(center), size));
                    names[3].push(name);
                }
                // The scene reader has no mesh: a scene's shapes are the four above.
                Shape::Mesh { .. } => {}
            }
        }
        out.names = names.concat();
        out
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
