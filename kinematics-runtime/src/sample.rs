//! Deterministic configurations for checking generated code against this reference.
//!
//! Agreement is worth most where code goes wrong: at the special angles (0, +-pi/2, +-pi, where a
//! quarter-turn simplification or a sign shows) and beyond the limits (which generated code must
//! not assume). The stream below mixes both with uniform values, from a fixed seed, so a failure
//! reproduces and two runs compare the same numbers.

use std::f64::consts::{FRAC_PI_2, PI};

use kinematics_model::KinematicTree;

use kinematics_core::JointLimits;

/// The special angles every joint takes now and then (and all joints at once first).
pub const SPECIAL_ANGLES: [f64; 5] = [0.0, FRAC_PI_2, -FRAC_PI_2, PI, -PI];

/// A deterministic stream of configurations (splitmix64, fixed seed): first every joint at each
/// of the [`SPECIAL_ANGLES`] in turn, then per joint a special angle a quarter of the time, a value
/// up to 1 beyond the limits a quarter of the time, and a value within them otherwise. Continuous
/// joints range over [-pi, pi], and so does every entry of a planar, spherical or floating joint; a
/// floating or spherical joint's quaternion that has no length to normalise (all four entries
/// zero, as in the first configuration) is the identity `(0, 0, 0, 1)` instead, since the
/// reference refuses it.
///
/// ```
/// use kinematics_runtime::{Configurations, JointLimits};
/// let limits = [JointLimits { lower: -1.0, upper: 1.0 }, JointLimits { lower: f64::NEG_INFINITY, upper: f64::INFINITY }];
/// let first: Vec<Vec<f64>> = Configurations::within(&limits).take(100).collect();
/// assert_eq!(first[1], vec![std::f64::consts::FRAC_PI_2; 2]);
/// assert!(first.iter().all(|q| (-2.0..=2.0).contains(&q[0]) || q[0].abs() == std::f64::consts::PI));
/// assert_eq!(first, Configurations::within(&limits).take(100).collect::<Vec<_>>());
/// ```
#[derive(Debug, Clone)]
pub struct Configurations {
    state: u64,
    ranges: Vec<(f64, f64)>,
    count: usize,
    /// Where each floating or spherical joint's quaternion starts in `q`.
    quaternions: Vec<usize>,
    /// Within the limits only ([`Configurations::uniform`]).
    uniform: bool,
}

/// The range of a joint without limits (a continuous joint; documented above).
const UNLIMITED: (f64, f64) = (-PI, PI);

/// The range a joint's values are drawn from: its limits when both are finite, otherwise (a side
/// unlimited) the range of a joint without limits, as the model's reach assumes.
fn range((lower, upper): (f64, f64)) -> (f64, f64) {
    if lower.is_finite() && upper.is_finite() { (lower, upper) } else { UNLIMITED }
}

/// The value a fraction `u` in [0, 1) of the way from `lo - margin` to `hi + margin`, without
/// overflowing when the width does (limits near `f64::MAX`).
fn between(lo: f64, hi: f64, margin: f64, u: f64) -> f64 {
    let width = hi - lo + 2.0 * margin;
    if width.is_finite() { lo - margin + u * width } else { (lo - margin) * (1.0 - u) + (hi + margin) * u }
}

impl Configurations {
    /// The configurations of a robot's degrees of freedom, in the tree's order.
    pub fn new(tree: &KinematicTree) -> Self {
        let mut configurations = Self::from_ranges(
            tree.dof_limits().iter().map(|l| range(l.map(|l| (l.lower, l.upper)).unwrap_or(UNLIMITED))).collect(),
        );
        configurations.quaternions = tree.quaternion_entries();
        configurations
    }

    /// The configurations of a compiled robot, from its `JOINT_LIMITS`.
    pub fn within(limits: &[JointLimits]) -> Self {
        Self::from_ranges(limits.iter().map(|l| range((l.lower, l.upper))).collect())
    }

    /// The same kind of configurations from another stream: seed 0 is the default stream, and
    /// each seed gives its own sequence, the same on every run (after the special angles, which
    /// every stream but a [`uniform`](Self::uniform) one starts with).
    ///
    /// ```
    /// use kinematics_runtime::{Configurations, JointLimits};
    /// let limits = [JointLimits { lower: -1.0, upper: 1.0 }];
    /// let take = |c: Configurations| c.uniform().take(5).collect::<Vec<_>>();
    /// assert_eq!(take(Configurations::within(&limits).seeded(0)), take(Configurations::within(&limits)));
    /// assert_ne!(take(Configurations::within(&limits).seeded(7)), take(Configurations::within(&limits)));
    /// assert_eq!(take(Configurations::within(&limits).seeded(7)), take(Configurations::within(&limits).seeded(7)));
    /// ```
    pub fn seeded(mut self, seed: u64) -> Self {
        // Seeds a splitmix64 stream: consecutive seeds start far apart in it.
        self.state ^= seed.wrapping_mul(0xd1b5_4a32_d192_ed03);
        self
    }

    /// Uniform within the limits only: no special angles, nothing beyond the limits (a side
    /// without a limit over [-pi, pi], as above): the space the robot moves in, as a planner or a
    /// self-collision matrix samples it.
    ///
    /// ```
    /// use kinematics_runtime::{Configurations, JointLimits};
    /// let limits = [JointLimits { lower: 0.5, upper: 1.0 }];
    /// assert!(Configurations::within(&limits).uniform().take(1000).all(|q| (0.5..1.0).contains(&q[0])));
    /// ```
    pub fn uniform(mut self) -> Self {
        self.uniform = true;
        self
    }

    fn from_ranges(ranges: Vec<(f64, f64)>) -> Self {
        Configurations { state: 0x6b69_6e65_6d61_7469, ranges, count: 0, quaternions: Vec::new(), uniform: false }
    }

    /// The next configuration as an array (for the generated functions, which take `&[f64; N]`),
    /// or `None` if `N` is not the number of degrees of freedom.
    pub fn next_array<const N: usize>(&mut self) -> Option<[f64; N]> {
        self.next()?.try_into().ok()
    }

    fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

impl Iterator for Configurations {
    type Item = Vec<f64>;

    /// Never `None`: the stream is endless.
    fn next(&mut self) -> Option<Vec<f64>> {
        let n = self.count;
        self.count += 1;
        let mut q = match SPECIAL_ANGLES.get(n) {
            Some(&angle) if !self.uniform => vec![angle; self.ranges.len()],
            _ if self.uniform => {
                let mut q = Vec::with_capacity(self.ranges.len());
                for i in 0..self.ranges.len() {
                    let (lo, hi) = self.ranges[i];
                    q.push(between(lo, hi, 0.0, self.unit()));
                }
                q
            }
            _ => {
                let mut q = Vec::with_capacity(self.ranges.len());
                for i in 0..self.ranges.len() {
                    let (lo, hi) = self.ranges[i];
                    let value = match self.next_u64() % 4 {
                        0 => SPECIAL_ANGLES[(self.next_u64() % 5) as usize],
                        1 => between(lo, hi, 1.0, self.unit()),
                        _ => between(lo, hi, 0.0, self.unit()),
                    };
                    q.push(value);
                }
                q
            }
        };
        for &start in &self.quaternions {
            let quaternion = &mut q[start..start + 4];
            if !quaternion.iter().map(|v| v * v).sum::<f64>().is_normal() {
                quaternion.copy_from_slice(&[0.0, 0.0, 0.0, 1.0]);
            }
        }
        Some(q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn configurations_start_with_the_special_angles_and_repeat() {
        let tree = kinematics_model::parse_source(
            "planar_2r.toml",
            "convention = \"standard\"\n[[joints]]\nname = \"a\"\na = 1.0\nlower = -1.0\nupper = 1.0\n[[joints]]\nname = \"b\"\na = 1.0\n",
        )
        .unwrap();
        let first: Vec<Vec<f64>> = Configurations::new(&tree).take(200).collect();
        assert_eq!(first[..5].iter().map(|q| q[0]).collect::<Vec<_>>(), SPECIAL_ANGLES);
        assert_eq!(first, Configurations::new(&tree).take(200).collect::<Vec<_>>());
        assert!(first.iter().all(|q| q.len() == 2 && (-2.0..=2.0).contains(&q[0]) || SPECIAL_ANGLES.contains(&q[0])));
        assert!(first[5..].iter().any(|q| q[0] > 1.0) && first[5..].iter().any(|q| q[0].abs() < 1.0 && q[0] != 0.0));
        // A continuous joint ranges over [-pi, pi] (+-1 beyond).
        assert!(first.iter().all(|q| q[1].abs() <= PI + 1.0));
    }

    #[test]
    fn half_unlimited_and_huge_limits_give_finite_values() {
        // Prismatic joints: one side unlimited (the range of an unlimited joint), and limits whose
        // width overflows.
        let tree = kinematics_model::parse_source(
            "slides.urdf",
            "<robot name=\"slides\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>\
             <joint name=\"half\" type=\"prismatic\"><parent link=\"a\"/><child link=\"b\"/><axis xyz=\"1 0 0\"/>\
             <limit lower=\"-inf\" upper=\"0.5\" effort=\"1\" velocity=\"1\"/></joint>\
             <joint name=\"huge\" type=\"revolute\"><parent link=\"b\"/><child link=\"c\"/><axis xyz=\"1 0 0\"/>\
             <limit lower=\"-1e308\" upper=\"1e308\" effort=\"1\" velocity=\"1\"/></joint></robot>",
        )
        .unwrap();
        let qs: Vec<Vec<f64>> = Configurations::new(&tree).take(2000).collect();
        assert!(qs.iter().flatten().all(|v| v.is_finite()));
        assert!(qs.iter().all(|q| q[0].abs() <= PI + 1.0));
        assert!(qs.iter().any(|q| q[1].abs() > 1e300));
        let limits =
            [JointLimits { lower: f64::NEG_INFINITY, upper: 0.5 }, JointLimits { lower: -1e308, upper: 1e308 }];
        assert_eq!(Configurations::within(&limits).take(2000).collect::<Vec<_>>(), qs);
    }

    #[test]
    fn the_tree_and_its_compiled_limits_give_the_same_stream() {
        let limits =
            [JointLimits { lower: -1.0, upper: 1.0 }, JointLimits { lower: f64::NEG_INFINITY, upper: f64::INFINITY }];
        let tree = kinematics_model::parse_source(
            "planar_2r.toml",
            "convention = \"standard\"\n[[joints]]\nname = \"a\"\na = 1.0\nlower = -1.0\nupper = 1.0\n[[joints]]\nname = \"b\"\na = 1.0\n",
        )
        .unwrap();
        let mut within = Configurations::within(&limits);
        for q in Configurations::new(&tree).take(100) {
            assert_eq!(within.next_array::<2>(), Some([q[0], q[1]]));
        }
        assert_eq!(Configurations::within(&limits).next_array::<3>(), None);
    }
}
