//! The pose generated code returns.

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

/// Agreement required of generated `f64` code against the runtime reference, as a pose deviation
/// (`Pose::deviation`, with the `nalgebra` feature): translations within this times the reach,
/// rotation entries within this. Every agreement check (tests, `kinematics check`, the examples,
/// the benchmark's check mode) uses this one value.
pub const AGREEMENT_TOLERANCE: f64 = 1e-12;

/// Agreement required of generated `f32` code, as a deviation of its poses widened to `f64`
/// (single precision carries about 7 significant digits, and errors grow along a chain).
pub const AGREEMENT_TOLERANCE_F32: f64 = 1e-5;
