//! What agreement means: deterministic test configurations, the robot's reach, the distance
//! between two poses, and the compiled expressions of every link against the runtime reference.

use kinematics::ReferenceFk;
use kinematics::model::KinematicTree;
use kinematics_compiler::{Request, compile};
use nalgebra::Isometry3;

use crate::error::CliError;

/// Agreement required of compiled code: translations within this times the reach, rotation
/// entries within this.
pub const TOLERANCE: f64 = 1e-12;

/// The special angles every joint takes now and then (and all joints at once first).
const SPECIAL: [f64; 5] =
    [0.0, std::f64::consts::FRAC_PI_2, -std::f64::consts::FRAC_PI_2, std::f64::consts::PI, -std::f64::consts::PI];

/// A deterministic stream of configurations (splitmix64, fixed seed): first every joint at each
/// special angle in turn, then per joint a special angle a quarter of the time, a value up to 1
/// beyond the limits a quarter of the time, and a value within them otherwise.
pub struct Configurations {
    state: u64,
    ranges: Vec<(f64, f64)>,
    count: usize,
}

impl Configurations {
    /// The configurations of `tree`; continuous joints range over [-pi, pi].
    pub fn new(tree: &KinematicTree) -> Self {
        let pi = std::f64::consts::PI;
        let ranges = tree.dof_limits().iter().map(|l| l.map_or((-pi, pi), |l| (l.lower, l.upper))).collect();
        Configurations { state: 0x6b69_6e65_6d61_7469, ranges, count: 0 }
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

    fn next(&mut self) -> Option<Vec<f64>> {
        let n = self.count;
        self.count += 1;
        if let Some(&angle) = SPECIAL.get(n) {
            return Some(vec![angle; self.ranges.len()]);
        }
        let mut q = Vec::with_capacity(self.ranges.len());
        for i in 0..self.ranges.len() {
            let (lo, hi) = self.ranges[i];
            let value = match self.next_u64() % 4 {
                0 => SPECIAL[(self.next_u64() % 5) as usize],
                1 => lo - 1.0 + self.unit() * (hi - lo + 2.0),
                _ => lo + self.unit() * (hi - lo),
            };
            q.push(value);
        }
        Some(q)
    }
}

/// The larger of the translation difference over `reach` and the largest rotation-entry
/// difference, between 12 pose entries (rotation row-major, translation) and an isometry.
pub fn distance(entries: &[f64; 12], reference: &Isometry3<f64>, reach: f64) -> f64 {
    kinematics::Pose::from_entries(entries).deviation(reference, reach)
}

/// The 12 entries of a generated pose.
pub fn entries(pose: &kinematics::Pose<f64>) -> [f64; 12] {
    let [r0, r1, r2] = pose.rotation;
    let t = pose.translation;
    [r0[0], r0[1], r0[2], r1[0], r1[1], r1[2], r2[0], r2[1], r2[2], t[0], t[1], t[2]]
}

/// The largest error of one link over all configurations.
pub struct FrameError {
    /// The link.
    pub link: String,
    /// Its largest error relative to reach (see [`distance`]).
    pub error: f64,
}

/// Compiles every link's pose in the root frame and evaluates the expressions (no Rust compiled)
/// against the runtime reference on `samples` configurations: the largest error per link.
pub fn check_graph(tree: &KinematicTree, file: &str, samples: usize) -> Result<Vec<FrameError>, CliError> {
    let compiled =
        compile(tree, &Request::all_links()).map_err(|source| CliError::Compile { file: file.to_owned(), source })?;
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let ids: Vec<usize> = compiled.frames().iter().map(|f| tree.link_id(&f.link).map_or(0, |id| id.0)).collect();
    let mut worst = vec![0.0f64; ids.len()];
    for q in Configurations::new(tree).take(samples) {
        let reference = fk.link_poses(&q).map_err(|source| CliError::Runtime { file: file.to_owned(), source })?;
        for ((frame, &id), worst) in compiled.eval(&q).iter().zip(&ids).zip(&mut worst) {
            let d = distance(frame, &reference[id], reach);
            // NaN counts as the largest error there is.
            *worst = if d.is_nan() { f64::INFINITY } else { worst.max(d) };
        }
    }
    Ok(compiled.frames().iter().zip(worst).map(|(f, error)| FrameError { link: f.link.clone(), error }).collect())
}

/// The frame with the largest error, as the error `check` fails with if it is past tolerance.
pub fn verdict(file: &str, errors: &[FrameError]) -> Result<(), CliError> {
    match errors.iter().max_by(|a, b| a.error.total_cmp(&b.error)) {
        Some(worst) if worst.error > TOLERANCE => Err(CliError::Disagrees {
            file: file.to_owned(),
            link: worst.link.clone(),
            error: worst.error,
            tolerance: TOLERANCE,
        }),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn configurations_start_with_the_special_angles_and_repeat() {
        let tree = kinematics::model::parse_source(
            "planar_2r.toml",
            "convention = \"standard\"\n[[joints]]\nname = \"a\"\na = 1.0\nlower = -1.0\nupper = 1.0\n[[joints]]\nname = \"b\"\na = 1.0\n",
        )
        .unwrap();
        let first: Vec<Vec<f64>> = Configurations::new(&tree).take(200).collect();
        assert_eq!(first[..5].iter().map(|q| q[0]).collect::<Vec<_>>(), SPECIAL);
        assert_eq!(first, Configurations::new(&tree).take(200).collect::<Vec<_>>());
        assert!(first.iter().all(|q| q.len() == 2 && (-2.0..=2.0).contains(&q[0]) || SPECIAL.contains(&q[0])));
        assert!(first[5..].iter().any(|q| q[0] > 1.0) && first[5..].iter().any(|q| q[0].abs() < 1.0 && q[0] != 0.0));
    }

    #[test]
    fn errors_past_the_tolerance_fail_naming_the_worst_link() {
        let frame = |link: &str, error| FrameError { link: link.to_owned(), error };
        assert!(verdict("arm.urdf", &[frame("a", 1e-15), frame("b", TOLERANCE)]).is_ok());
        let failed = verdict("arm.urdf", &[frame("a", 3e-9), frame("b", f64::INFINITY), frame("c", 0.0)]);
        assert_eq!(
            failed.map_err(|e| e.to_string()),
            Err("arm.urdf: link `b`: the compiled pose is off by inf x reach (tolerance 1e-12)".to_owned())
        );
    }
}
