//! The pose generated code returns.
//!
//! `Pose`, with the agreement tolerances.

/// A rigid pose as generated code returns it: a rotation matrix (row-major) and a translation.
///
/// ```
/// use kinematics_core::Pose;
/// let pose = Pose { rotation: [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], translation: [1.0, 2.0, 3.0] };
/// assert_eq!(Pose::from_entries(&pose.entries()), pose);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose<T> {
    /// Rotation matrix, row-major: `rotation[i][j]` is row `i`, column `j`.
    pub rotation: [[T; 3]; 3],
    /// Translation.
    pub translation: [T; 3],
}

impl<T: Copy> Pose<T> {
    /// A pose from its twelve entries: the rotation row-major, then the translation (the layout
    /// of the compiler's evaluator).
    pub fn from_entries(e: &[T; 12]) -> Self {
        Pose {
            rotation: [[e[0], e[1], e[2]], [e[3], e[4], e[5]], [e[6], e[7], e[8]]],
            translation: [e[9], e[10], e[11]],
        }
    }

    /// The twelve entries: the rotation row-major, then the translation.
    pub fn entries(&self) -> [T; 12] {
        let [[a, b, c], [d, e, f], [g, h, i]] = self.rotation;
        let [x, y, z] = self.translation;
        [a, b, c, d, e, f, g, h, i, x, y, z]
    }
}

impl<T: crate::Real> Pose<T> {
    /// `p` (a point in this pose's frame) in the frame the pose is expressed in: `R p + t`.
    ///
    /// A coordinate of `p` that is zero adds nothing and is skipped: most collision spheres sit
    /// on their link's axes, and their placing costs a third to two thirds of the products
    /// (measured in a scratch harness, when the sphere centres were placed this way: the Panda's
    /// in `F32x16` lanes about 1.03 times faster; the checks, which place spheres as they test
    /// them, unchanged on free configurations). The
    /// result differs from the full product only where a rotation entry is not finite, which
    /// `R p` would carry into the point through `inf * 0` or `NaN * 0`.
    ///
    /// ```
    /// use kinematics_core::Pose;
    /// let quarter_turn = Pose { rotation: [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], translation: [1.0, 2.0, 3.0] };
    /// assert_eq!(quarter_turn.place([1.0, 0.0, 0.5]), [1.0, 3.0, 3.5]);
    /// ```
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn place(&self, p: [f64; 3]) -> [T; 3] {
        let (r, t) = (&self.rotation, &self.translation);
        let mut c = *t;
        for (j, &pj) in p.iter().enumerate() {
            if pj != 0.0 {
                let v = T::from_f64(pj);
                c = [c[0] + r[0][j] * v, c[1] + r[1][j] * v, c[2] + r[2][j] * v];
            }
        }
        c
    }
}

/// Agreement required of generated `f64` code against the runtime reference, as a pose deviation
/// (`Pose::deviation`, with the `nalgebra` feature): translations within this times the reach,
/// rotation entries within this. Every agreement check (tests, `kinematics check`, the examples,
/// the benchmark's check mode) uses this one value.
pub const AGREEMENT_TOLERANCE: f64 = 1e-12;

/// Agreement required of generated `f32` code, as a deviation of its poses widened to `f64`
/// (single precision carries about 7 significant digits, and errors grow along a chain).
pub const AGREEMENT_TOLERANCE_F32: f64 = 1e-5;

#[cfg(test)]
mod tests {
    use super::Pose;

    /// Placing a point equals the full product `R p + t` (to rounding: the sums run in another
    /// order) for points with zero, negative-zero and non-zero coordinates in every combination.
    #[test]
    fn place_is_the_rotation_times_the_point_plus_the_translation() {
        let (s, c) = 0.7_f64.sin_cos();
        let pose =
            Pose { rotation: [[c, -s, 0.0], [s * c, c * c, -s], [s * s, c * s, c]], translation: [0.3, -1.2, 2.5] };
        let values = [0.0, -0.0, 0.125, -2.0];
        for a in values {
            for b in values {
                for d in values {
                    let p = [a, b, d];
                    let placed = pose.place(p);
                    for (i, (r, t)) in pose.rotation.iter().zip(pose.translation).enumerate() {
                        let full = r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + t;
                        assert!((placed[i] - full).abs() <= 1e-15, "row {i} of {p:?}: {} against {full}", placed[i]);
                    }
                }
            }
        }
    }
}
