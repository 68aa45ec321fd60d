//! Forward-mode dual numbers, and the Jacobian they give when run through a generated pose.
//!
//! A [`Dual`] carries a value and its derivatives along `N` directions. Generated functions are
//! generic over `kinematics::Real`, so a generated *pose* evaluated on duals yields the pose's
//! derivatives with no Jacobian code at all: a witness independent of the compiler's Jacobian and
//! of the runtime reference's. Written here from the definition: `(a + a' e)(b + b' e) = ab +
//! (a'b + ab') e`, `sin(a + a' e) = sin a + a' cos a e`.
//!
//! The duals are also a `CheckLanes` type of one lane (comparisons by the value), so
//! `tests/clearance_duals.rs` runs the generated clearance and proximity cost on them.

use std::ops::{Add, Div, Mul, Neg, Sub};

use kinematics::collision::CheckLanes;
use kinematics::{Pose, Real};

/// A number with its derivatives along `N` directions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dual<const N: usize> {
    /// The value.
    pub value: f64,
    /// Its derivative along each direction.
    pub grad: [f64; N],
}

impl<const N: usize> Dual<N> {
    /// A constant: every derivative zero.
    pub fn constant(value: f64) -> Self {
        Dual { value, grad: [0.0; N] }
    }
}

impl<const N: usize> Add for Dual<N> {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        Dual { value: self.value + rhs.value, grad: std::array::from_fn(|i| self.grad[i] + rhs.grad[i]) }
    }
}

impl<const N: usize> Sub for Dual<N> {
    type Output = Self;
    fn sub(self, rhs: Self) -> Self {
        Dual { value: self.value - rhs.value, grad: std::array::from_fn(|i| self.grad[i] - rhs.grad[i]) }
    }
}

impl<const N: usize> Mul for Dual<N> {
    type Output = Self;
    // The product rule: the derivative of a product is a sum.
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn mul(self, rhs: Self) -> Self {
        Dual {
            value: self.value * rhs.value,
            grad: std::array::from_fn(|i| self.grad[i] * rhs.value + self.value * rhs.grad[i]),
        }
    }
}

impl<const N: usize> Div for Dual<N> {
    type Output = Self;
    // The quotient rule: `(a/b)' = (a' - (a/b) b') / b`.
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn div(self, rhs: Self) -> Self {
        let value = self.value / rhs.value;
        Dual { value, grad: std::array::from_fn(|i| (self.grad[i] - value * rhs.grad[i]) / rhs.value) }
    }
}

impl<const N: usize> Neg for Dual<N> {
    type Output = Self;
    fn neg(self) -> Self {
        Dual { value: -self.value, grad: self.grad.map(|g| -g) }
    }
}

impl<const N: usize> Real for Dual<N> {
    fn from_f64(x: f64) -> Self {
        Dual::constant(x)
    }

    fn sin_cos(self) -> (Self, Self) {
        // The platform's sine and cosine: the values are compared with tolerances, not bits.
        let (s, c) = self.value.sin_cos();
        (Dual { value: s, grad: self.grad.map(|g| g * c) }, Dual { value: c, grad: self.grad.map(|g| -g * s) })
    }
}

/// For code generated with `trig = "std"`: the same sine and cosine (the platform's).
impl<const N: usize> kinematics::StdTrig for Dual<N> {
    fn sin_cos_std(self) -> (Self, Self) {
        self.sin_cos()
    }
}

/// One lane, as `f64` is: the collision scans on duals carry a distance's derivatives along
/// with its value, a witness to the gradients the scans take through the generated Jacobians.
/// Comparisons and selections go by the value, so a dual run takes the branches the `f64` run
/// takes (the same nearest pair). What the scans ask one lane at a time in `f64` (a point
/// cloud's nearest point, through [`CheckLanes::lane_f64`] and [`CheckLanes::from_lanes`]) comes
/// back a constant: its derivatives are lost.
impl<const N: usize> CheckLanes for Dual<N> {
    type Flags = bool;
    const WIDTH: usize = 1;

    fn max(self, other: Self) -> Self {
        if self.value > other.value { self } else { other }
    }

    fn min(self, other: Self) -> Self {
        if self.value < other.value { self } else { other }
    }

    fn abs(self) -> Self {
        if self.value < 0.0 { -self } else { self }
    }

    fn not_above(self, limit: Self) -> bool {
        self.value.partial_cmp(&limit.value) != Some(std::cmp::Ordering::Greater)
    }

    fn non_finite(self) -> bool {
        !self.value.is_finite()
    }

    fn lane_f64(self, _: usize) -> f64 {
        self.value
    }

    fn sqrt(self) -> Self {
        // `(sqrt a)' = a' / (2 sqrt a)`.
        let value = self.value.sqrt();
        Dual { value, grad: self.grad.map(|g| g / (2.0 * value)) }
    }

    fn select(flags: bool, then: Self, otherwise: Self) -> Self {
        if flags { then } else { otherwise }
    }

    fn from_lanes(mut f: impl FnMut(usize) -> f64) -> Self {
        Dual::constant(f(0))
    }
}

/// The geometric Jacobian (`LOCAL_WORLD_ALIGNED`: rows the derivative of the translation, then the
/// angular velocity `w` with `dR/dt = [w]x R`) of `pose` at `q` along each of the `V` directions
/// in `directions` (each a vector of `N` entries: how `q` moves per unit of that velocity), one
/// column each. The angular velocity is the skew part of `dR R^T`, averaged from both triangles.
///
/// ```
/// use kinematics::{Pose, Real};
/// use kinematics_checks::dual::{Dual, jacobian};
/// // A planar 2R arm with unit links, written by hand.
/// fn arm<T: Real>(q: &[T; 2]) -> Pose<T> {
///     let (s1, c1) = q[0].sin_cos();
///     let (s12, c12) = (q[0] + q[1]).sin_cos();
///     let (zero, one) = (T::from_f64(0.0), T::from_f64(1.0));
///     Pose { rotation: [[c12, -s12, zero], [s12, c12, zero], [zero, zero, one]], translation: [c1 + c12, s1 + s12, zero] }
/// }
/// let columns = jacobian::<2, 2>(|x| arm(x), &[0.0, std::f64::consts::FRAC_PI_2], &[vec![1.0, 0.0], vec![0.0, 1.0]]);
/// assert!((columns[0][0] + 1.0).abs() < 1e-15 && (columns[0][1] - 1.0).abs() < 1e-15);
/// assert!((columns[1][0] + 1.0).abs() < 1e-15 && (columns[1][5] - 1.0).abs() < 1e-15);
/// ```
///
/// # Panics
///
/// If `q` has other than `N` values or `directions` other than `V` vectors of `N` (a test's bug).
pub fn jacobian<const N: usize, const V: usize>(
    pose: impl Fn(&[Dual<V>; N]) -> Pose<Dual<V>>,
    q: &[f64],
    directions: &[Vec<f64>],
) -> Vec<[f64; 6]> {
    jacobians::<N, V, 1>(|x| [pose(x)], q, directions).remove(0)
}

/// [`jacobian`] for a function computing `K` poses at once (`tip_poses_generic`): one Jacobian
/// per pose.
///
/// # Panics
///
/// As [`jacobian`].
pub fn jacobians<const N: usize, const V: usize, const K: usize>(
    poses: impl Fn(&[Dual<V>; N]) -> [Pose<Dual<V>>; K],
    q: &[f64],
    directions: &[Vec<f64>],
) -> Vec<Vec<[f64; 6]>> {
    assert!(q.len() == N && directions.len() == V && directions.iter().all(|d| d.len() == N), "shapes");
    let x: [Dual<V>; N] =
        std::array::from_fn(|i| Dual { value: q[i], grad: std::array::from_fn(|v| directions[v][i]) });
    poses(&x).iter().map(columns).collect()
}

/// One column per direction: the translation's derivative, and `w` from `dR R^T`.
fn columns<const V: usize>(p: &Pose<Dual<V>>) -> Vec<[f64; 6]> {
    (0..V)
        .map(|v| {
            let r = |a: usize, b: usize| p.rotation[a][b].value;
            let dr = |a: usize, b: usize| p.rotation[a][b].grad[v];
            // M = dR R^T, skew for a rotation: w = (M21, M02, M10).
            let m = |a: usize, b: usize| (0..3).map(|k| dr(a, k) * r(b, k)).sum::<f64>();
            [
                p.translation[0].grad[v],
                p.translation[1].grad[v],
                p.translation[2].grad[v],
                (m(2, 1) - m(1, 2)) / 2.0,
                (m(0, 2) - m(2, 0)) / 2.0,
                (m(1, 0) - m(0, 1)) / 2.0,
            ]
        })
        .collect()
}

/// How `q` moves per unit of each velocity of `tree` at `q`: a joint's own entry for a velocity
/// of one entry; for a floating joint's linear velocities the child's axes (the columns of its
/// rotation) in its position entries, for a floating or spherical joint's angular ones
/// `quaternion * (e_k / 2, 0)` in its quaternion entries (the derivative of
/// `quaternion * exp(t e_k / 2)`, Pinocchio's free-flyer and spherical joint).
pub fn directions(tree: &kinematics::KinematicTree, q: &[f64]) -> Vec<Vec<f64>> {
    let n = tree.dof();
    let mut out = vec![vec![0.0; n]; tree.velocity_dof()];
    for (entry, column) in tree.velocity_of_entry().into_iter().enumerate() {
        if let Some(c) = column {
            out[c][entry] = 1.0;
        }
    }
    for joint in tree.quaternion_joints() {
        let kind = tree.joint(joint).kind;
        let (kinematics::model::JointMotion::Dof(s), Some(c), Some(offset)) =
            (tree.joint(joint).motion, tree.velocity_start(joint), kind.quaternion_offset())
        else {
            continue;
        };
        // A floating joint's position and linear velocities come first.
        let (s, c, translates) = (s + offset, c + offset, offset > 0);
        let [x, y, z, w] = [q[s], q[s + 1], q[s + 2], q[s + 3]];
        let rotation = kinematics::quaternion_matrix(x, y, z, w);
        for k in 0..3 {
            if translates {
                for a in 0..3 {
                    out[c - 3 + k][s - 3 + a] = rotation[a][k];
                }
            }
            // (x, y, z, w) * (e_k / 2, 0), Hamilton product, kept at the quaternion's length
            // (the rotation depends on its direction only).
            let mut e = [0.0; 3];
            e[k] = 0.5;
            let [bx, by, bz] = e;
            let product = [
                w * bx + y * bz - z * by,
                w * by - x * bz + z * bx,
                w * bz + x * by - y * bx,
                -x * bx - y * by - z * bz,
            ];
            out[c + k][s..s + 4].copy_from_slice(&product);
        }
    }
    out
}
