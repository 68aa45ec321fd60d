//! Mass and inertia: what a link's `<inertial>` says (URDF; MJCF's `<inertial>`), as written, and
//! the rules a rigid body's inertia keeps.
//!
//! An [`Inertial`] holds the mass, the frame of the centre of mass in the link's frame (its
//! `<origin>`, angles as written: they only place constants) and the rotational inertia about the
//! centre of mass in that frame's axes, as the file writes it. Nothing is rotated or lumped here:
//! the compiler and the runtime reference each do that their own way, as they place collision
//! geometry.
//!
//! The rules ([`Inertial::fault`]) are checked where dynamics are asked for, not when a robot is
//! loaded: a description whose inertias break them still gives its kinematics. They are those of
//! a physical rigid body: a finite mass, zero or more (a zero mass with a zero tensor is a
//! massless link; real descriptions have both); a finite, symmetric (by construction: six
//! entries) and positive semi-definite tensor whose principal moments keep the triangle
//! inequality (each at most the sum of the other two), which every body of non-negative density
//! does. Real descriptions break the last (a link of a PR2 description does), which is why the
//! caller may take a tensor as written.

use crate::transform::FixedTransform;

/// A link's mass and inertia, as written.
#[derive(Debug, Clone, PartialEq)]
pub struct Inertial {
    /// Mass (kg).
    pub mass: f64,
    /// The centre of mass's frame in the link's frame (`<inertial><origin xyz rpy>`; MJCF's
    /// `pos` and orientation).
    pub origin: FixedTransform,
    /// The rotational inertia about the centre of mass, in `origin`'s axes (kg m^2):
    /// `[ixx, ixy, ixz, iyy, iyz, izz]`, the products as URDF writes them (the tensor's
    /// off-diagonal entries, not their negatives).
    pub inertia: [f64; 6],
}

/// What makes an inertia no rigid body's.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InertiaFault {
    /// A NaN or infinite mass or tensor entry.
    #[error("its mass or inertia is not finite ({0})")]
    NotFinite(String),
    /// A negative mass.
    #[error("its mass is {0} kg (must be zero or more)")]
    NegativeMass(f64),
    /// A tensor with a negative principal moment.
    #[error("its inertia tensor is not positive semi-definite (principal moments {0:?} kg m^2)")]
    NotPositive([f64; 3]),
    /// Principal moments breaking the triangle inequality.
    #[error(
        "its inertia's principal moments {0:?} kg m^2 break the triangle inequality (each must be at most the sum of the other two), as no rigid body's do"
    )]
    Triangle([f64; 3]),
    /// A mass of zero with a tensor that is not zero (the converse, a mass with a zero tensor,
    /// is a point mass, and allowed).
    #[error("its mass is zero but its inertia tensor is not")]
    MasslessWithInertia,
}

/// Why a link's mass cannot be taken for dynamics, as every front end and the runtime reference
/// report it ([`crate::KinematicTree::inertia_refusals`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InertiaRefusal {
    /// Its `<inertial>` is no rigid body's ([`Inertial::fault`]).
    #[error("the <inertial> of link `{link}`{}: {fault}", at_line(*.line))]
    Fault {
        /// The link.
        link: String,
        /// The line of its `<inertial>`, when read from a file.
        line: Option<usize>,
        /// What is wrong with it.
        #[source]
        fault: InertiaFault,
    },
    /// It has no `<inertial>` and its description leaves its mass to its geometry (an MJCF body
    /// whose inertia MuJoCo would infer from its geoms), which the dynamics do not infer.
    #[error(
        "link `{link}` has no <inertial> and leaves its mass to be inferred from its geometry, which the dynamics do not do: give it an <inertial>"
    )]
    FromGeometry {
        /// The link.
        link: String,
    },
}

/// ` (line N)`, or nothing.
fn at_line(line: Option<usize>) -> String {
    line.map(|l| format!(" (line {l})")).unwrap_or_default()
}

/// How far (relative to the largest principal moment) a moment may fall below zero, or beyond
/// the sum of the other two, by the rounding of the written digits and still be taken: a thin rod's
/// written tensor sits on the triangle inequality's edge.
pub const INERTIA_TOLERANCE: f64 = 1e-9;

impl Inertial {
    /// A massless link's: zero mass, zero tensor, at the link's origin.
    pub fn massless() -> Self {
        Inertial { mass: 0.0, origin: FixedTransform::identity(), inertia: [0.0; 6] }
    }

    /// The tensor as a symmetric matrix, rows first, in `origin`'s axes.
    pub fn matrix(&self) -> [[f64; 3]; 3] {
        let [xx, xy, xz, yy, yz, zz] = self.inertia;
        [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]
    }

    /// The tensor's principal moments, smallest first (the eigenvalues of a symmetric 3x3
    /// matrix, by the trigonometric closed form).
    pub fn principal_moments(&self) -> [f64; 3] {
        symmetric_eigenvalues(self.matrix())
    }

    /// What breaks a rigid body's rules, if anything (see the module doc); `as_written` skips
    /// the triangle inequality alone (the tensor must still be positive semi-definite).
    pub fn fault(&self, as_written: bool) -> Option<InertiaFault> {
        let finite_origin = self.origin.steps().iter().all(|step| match step {
            crate::transform::Elementary::Translation(v) => v.iter().all(|x| x.is_finite()),
            crate::transform::Elementary::Rotation(_, angle) => angle.radians().is_finite(),
        });
        if !self.mass.is_finite() || self.inertia.iter().any(|x| !x.is_finite()) || !finite_origin {
            return Some(InertiaFault::NotFinite(format!("mass {}, inertia {:?}", self.mass, self.inertia)));
        }
        if self.mass < 0.0 {
            return Some(InertiaFault::NegativeMass(self.mass));
        }
        if self.mass == 0.0 && self.inertia.iter().any(|&x| x != 0.0) {
            return Some(InertiaFault::MasslessWithInertia);
        }
        let moments = self.principal_moments();
        let scale = moments[2].abs().max(f64::MIN_POSITIVE);
        if moments[0] < -INERTIA_TOLERANCE * scale {
            return Some(InertiaFault::NotPositive(moments));
        }
        if !as_written && moments[2] > moments[0] + moments[1] + INERTIA_TOLERANCE * scale {
            return Some(InertiaFault::Triangle(moments));
        }
        None
    }
}

/// The eigenvalues of a symmetric 3x3 matrix, smallest first: the trigonometric closed form
/// (Smith, "Eigenvalues of a symmetric 3x3 matrix", Communications of the ACM 4(4), 1961).
fn symmetric_eigenvalues(a: [[f64; 3]; 3]) -> [f64; 3] {
    let p1 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if p1 == 0.0 {
        let mut d = [a[0][0], a[1][1], a[2][2]];
        d.sort_by(f64::total_cmp);
        return d;
    }
    let q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    let p2 = (a[0][0] - q).powi(2) + (a[1][1] - q).powi(2) + (a[2][2] - q).powi(2) + 2.0 * p1;
    let p = (p2 / 6.0).sqrt();
    let b = |i: usize, j: usize| (a[i][j] - if i == j { q } else { 0.0 }) / p;
    let det = b(0, 0) * (b(1, 1) * b(2, 2) - b(1, 2) * b(2, 1)) - b(0, 1) * (b(1, 0) * b(2, 2) - b(1, 2) * b(2, 0))
        + b(0, 2) * (b(1, 0) * b(2, 1) - b(1, 1) * b(2, 0));
    let r = (det / 2.0).clamp(-1.0, 1.0);
    let phi = r.acos() / 3.0;
    let largest = q + 2.0 * p * phi.cos();
    let smallest = q + 2.0 * p * (phi + 2.0 * std::f64::consts::PI / 3.0).cos();
    let middle = 3.0 * q - largest - smallest;
    [smallest, middle, largest]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn body(mass: f64, inertia: [f64; 6]) -> Inertial {
        Inertial { mass, origin: FixedTransform::identity(), inertia }
    }

    #[test]
    fn principal_moments_of_a_diagonal_and_a_turned_tensor() {
        assert_eq!(body(1.0, [3.0, 0.0, 0.0, 1.0, 0.0, 2.0]).principal_moments(), [1.0, 2.0, 3.0]);
        // diag(1, 2, 3) turned by 45 degrees about z: [[1.5, -0.5, 0], [-0.5, 1.5, 0], [0, 0, 3]].
        let m = body(1.0, [1.5, -0.5, 0.0, 1.5, 0.0, 3.0]).principal_moments();
        for (got, want) in m.iter().zip([1.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-12, "{m:?}");
        }
    }

    #[test]
    fn the_rules_of_a_rigid_body() {
        // A solid box 1 x 2 x 3 m of 12 kg: m (b^2 + c^2) / 12 and so on.
        let solid = body(12.0, [13.0, 0.0, 0.0, 10.0, 0.0, 5.0]);
        assert_eq!(solid.fault(false), None);
        assert_eq!(Inertial::massless().fault(false), None);
        // A point mass: a mass, no tensor.
        assert_eq!(body(2.0, [0.0; 6]).fault(false), None);
        // A thin rod along z: (I, I, 0), on the triangle inequality's edge.
        assert_eq!(body(1.0, [0.1, 0.0, 0.0, 0.1, 0.0, 0.0]).fault(false), None);
        assert_eq!(body(-1.0, [1.0, 0.0, 0.0, 1.0, 0.0, 1.0]).fault(false), Some(InertiaFault::NegativeMass(-1.0)));
        assert!(matches!(body(f64::NAN, [1.0; 6]).fault(false), Some(InertiaFault::NotFinite(_))));
        assert_eq!(body(0.0, [1.0, 0.0, 0.0, 1.0, 0.0, 1.0]).fault(false), Some(InertiaFault::MasslessWithInertia));
        assert!(matches!(body(1.0, [1.0, 0.0, 0.0, -1.0, 0.0, 1.0]).fault(true), Some(InertiaFault::NotPositive(_))));
        // Off-diagonal products too large for the diagonal: an eigenvalue below zero.
        assert!(matches!(body(1.0, [1.0, 2.0, 0.0, 1.0, 0.0, 1.0]).fault(false), Some(InertiaFault::NotPositive(_))));
        let broken = body(1.0, [1.0, 0.0, 0.0, 1.0, 0.0, 3.0]);
        assert!(matches!(broken.fault(false), Some(InertiaFault::Triangle(_))));
        assert_eq!(broken.fault(true), None);
    }
}
