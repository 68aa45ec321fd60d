//! Collision spheres at run time, the reference's own way: each sphere's centre in the root frame
//! as the link's pose (the reference's forward kinematics), then the `<collision>` element's origin
//! (as an nalgebra isometry), applied to the cover's centre. Shares nothing with the compiler but
//! the model's list of spheres.

use kinematics_model::collision::LinkSphere;
use nalgebra::Point3;

use crate::error::RuntimeError;
use crate::fk::{ReferenceFk, fixed_isometry};

impl ReferenceFk {
    /// The centres of `spheres` (the model's
    /// [`link_spheres`](kinematics_model::collision::link_spheres), in its order) at `q`, in the
    /// root frame.
    pub fn sphere_centers(&self, q: &[f64], spheres: &[LinkSphere]) -> Result<Vec<Point3<f64>>, RuntimeError> {
        let poses = self.link_poses(q)?;
        Ok(spheres
            .iter()
            .map(|s| {
                let origin = fixed_isometry(&self.tree().link(s.link).collisions[s.collision].origin);
                poses[s.link.0] * origin * Point3::from(s.sphere.center)
            })
            .collect())
    }
}
