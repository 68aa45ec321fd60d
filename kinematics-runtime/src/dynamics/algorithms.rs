//! The recursive algorithms on checked inputs: the recursive Newton-Euler algorithm (Featherstone
//! §5.3, Table 5.1), the composite-rigid-body algorithm (§6.2, Table 6.2) and forward dynamics by
//! the mass matrix's Cholesky factorisation (ch. 6), with the singular case named.

use nalgebra::{DMatrix, DVector, Matrix6, Vector3};

use super::ReferenceDynamics;
use super::joint::JointAt;
use super::spatial::{Spatial, cross_force, cross_motion, spatial};

/// Eigenvalues of the mass matrix at or below this fraction of its largest are taken as zero: the
/// velocities along their eigenvectors move no mass. Far above the rounding of the eigenvalues
/// (about `n * f64::EPSILON` of the largest), far below any real robot's ratio.
pub(super) const SINGULAR_RATIO: f64 = 1e-12;

impl ReferenceDynamics {
    fn joints_at(&self, q: &[f64]) -> Vec<JointAt> {
        (0..self.fk.tree().joints().len()).map(|i| self.joint_at(i, q)).collect()
    }

    /// RNEA: the generalized forces that give accelerations `a` at `(q, v)` under gravity, each
    /// link's motion and force in its own coordinates, gravity as the root's acceleration `-g`,
    /// with `external` forces on links (each link's index and its spatial force in its own
    /// coordinates, moment first).
    pub(super) fn rnea(&self, q: &[f64], v: &[f64], a: &[f64], external: &[(usize, Spatial)]) -> Vec<f64> {
        let tree = self.fk.tree();
        let joints = self.joints_at(q);
        let links = tree.links().len();
        let mut velocity = vec![Spatial::zeros(); links];
        let mut acceleration = vec![Spatial::zeros(); links];
        acceleration[tree.root().0] = spatial(Vector3::zeros(), -self.gravity);
        let mut force = vec![Spatial::zeros(); links];
        // Outward: velocities and accelerations, parents first; each body's force from Newton
        // and Euler's equations, `f = I a + v x* I v`.
        for (joint, at) in tree.joints().iter().zip(&joints) {
            let (parent, child) = (joint.parent.0, joint.child.0);
            let v_joint = at.times(v);
            velocity[child] = at.x.motion(&velocity[parent]) + v_joint;
            acceleration[child] = at.x.motion(&acceleration[parent])
                + at.times(a)
                + at.velocity_product(v)
                + cross_motion(&velocity[child], &v_joint);
            let inertia = &self.inertias[child];
            force[child] = inertia * acceleration[child] + cross_force(&velocity[child], &(inertia * velocity[child]));
        }
        // What the world exerts on a link, the joints need not (Table 5.1's `f_i - f_i^x`).
        for (link, applied) in external {
            force[*link] -= applied;
        }
        // Inward: each joint's generalized force `S^T f`, its child's force passed to the parent.
        let mut tau = vec![0.0; tree.velocity_dof()];
        for (joint, at) in tree.joints().iter().zip(&joints).rev() {
            let child = force[joint.child.0];
            for (k, s) in &at.columns {
                tau[*k] += s.dot(&child);
            }
            force[joint.parent.0] += at.x.force_to_parent(&child);
        }
        tau
    }

    /// CRBA: the mass matrix, from each joint's composite inertia (its child and everything
    /// below), its columns' forces carried up to every joint above.
    pub(super) fn crba(&self, q: &[f64]) -> DMatrix<f64> {
        let tree = self.fk.tree();
        let joints = self.joints_at(q);
        let mut composite: Vec<Matrix6<f64>> = self.inertias.clone();
        for (joint, at) in tree.joints().iter().zip(&joints).rev() {
            let up = at.x.inertia_to_parent(&composite[joint.child.0]);
            composite[joint.parent.0] += up;
        }
        let n = tree.velocity_dof();
        let mut m = DMatrix::zeros(n, n);
        for (i, joint) in tree.joints().iter().enumerate() {
            for (row, s) in &joints[i].columns {
                let mut f = composite[joint.child.0] * s;
                for (column, other) in &joints[i].columns {
                    m[(*row, *column)] += other.dot(&f);
                }
                // Up the tree: the same force on every joint above, in its child's coordinates.
                let mut below = i;
                while let Some(above) = tree.link(tree.joints()[below].parent).parent_joint {
                    f = joints[below].x.force_to_parent(&f);
                    below = above.0;
                    for (column, other) in &joints[below].columns {
                        let h = other.dot(&f);
                        m[(*row, *column)] += h;
                        m[(*column, *row)] += h;
                    }
                }
            }
        }
        // Symmetric in exact arithmetic; made so in floating point.
        (&m + m.transpose()) * 0.5
    }

    /// The velocities the mass matrix `m` cannot determine: those with a component along an
    /// eigenvector whose eigenvalue is zero (at most [`SINGULAR_RATIO`] of the largest).
    pub(super) fn undetermined(&self, m: &DMatrix<f64>) -> Vec<usize> {
        // (nalgebra's decomposition refuses an empty matrix: a robot with no velocities.)
        if m.is_empty() {
            return Vec::new();
        }
        let eigen = m.clone().symmetric_eigen();
        let largest = eigen.eigenvalues.iter().fold(0.0_f64, |l, e| l.max(e.abs()));
        let null: Vec<usize> = (0..m.nrows()).filter(|&k| eigen.eigenvalues[k] <= SINGULAR_RATIO * largest).collect();
        (0..m.nrows())
            .filter(|&row| {
                // The squared length of unit vector `row`'s projection on the null space.
                let weight: f64 = null.iter().map(|&k| eigen.eigenvectors[(row, k)].powi(2)).sum();
                weight > 1e-12
            })
            .collect()
    }

    /// `M a = tau - h`, solved by Cholesky; `Err` with the undetermined velocities when `M` is
    /// singular.
    pub(super) fn solve(&self, m: DMatrix<f64>, rhs: Vec<f64>) -> Result<Vec<f64>, Vec<usize>> {
        let undetermined = self.undetermined(&m);
        if !undetermined.is_empty() {
            return Err(undetermined);
        }
        match m.cholesky() {
            Some(cholesky) => Ok(cholesky.solve(&DVector::from_vec(rhs)).iter().copied().collect()),
            // Positive eigenvalues but no factorisation: the smallest pivot lost to rounding.
            None => Err((0..rhs.len()).collect()),
        }
    }
}
