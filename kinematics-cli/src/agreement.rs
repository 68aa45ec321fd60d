//! What agreement means: deterministic test configurations (the runtime's `Configurations`), the
//! robot's reach, the distance between two poses, and the compiled expressions of every link
//! against the runtime reference.

pub use kinematics::Configurations;
use kinematics::ReferenceFk;
use kinematics::model::KinematicTree;
use kinematics_compiler::{Request, compile};
use nalgebra::Isometry3;

use crate::error::CliError;

/// Agreement required of compiled code: translations within this times the reach, rotation
/// entries within this.
pub const TOLERANCE: f64 = 1e-12;

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
