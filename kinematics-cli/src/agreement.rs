//! What agreement means: deterministic test configurations (the runtime's `Configurations`), the
//! robot's reach, the distance between two poses, and the compiled expressions of every link
//! against the runtime reference.
//!
//! This is what `check` and `demo` share: the pose distance is `Pose::deviation`, the tolerance the
//! runtime's `AGREEMENT_TOLERANCE`, and a sample count at least 1.

pub use kinematics::Configurations;
use kinematics::ReferenceFk;
use kinematics::model::KinematicTree;
use kinematics_compiler::{Request, compile};
use nalgebra::Isometry3;

use crate::error::CliError;

/// Agreement required of compiled code: the runtime's one tolerance of every agreement check
/// (translations within this times the reach, rotation entries within this).
pub const TOLERANCE: f64 = kinematics::AGREEMENT_TOLERANCE;

/// A sample count from the command line: at least 1, since checking no configuration checks
/// nothing (and passing such a check would be a silent wrong answer).
pub fn sample_count(text: &str) -> Result<usize, String> {
    match text.parse::<usize>() {
        Ok(0) => Err("at least one configuration is needed: 0 checks nothing".to_owned()),
        Ok(n) => Ok(n),
        Err(e) => Err(e.to_string()),
    }
}

/// Folds `d` into the largest so far; a NaN (which `f64::max` would drop) counts as infinitely far.
pub fn worst_of(worst: f64, d: f64) -> f64 {
    if d.is_nan() {
        f64::INFINITY
    } else if d > worst {
        d
    } else {
        worst
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
///
/// The configurations are split into one run of consecutive ones per core, each run in a thread
/// of its own; the largest errors do not depend on the split.
///
/// On a terminal, stderr shows a spinner while the compiler works (it reports no progress of its
/// own) and then a bar over the configurations; elsewhere nothing.
pub fn check_graph(tree: &KinematicTree, file: &str, samples: usize) -> Result<Vec<FrameError>, CliError> {
    let spinner = crate::progress::spinner("compiling every link's pose");
    let compiled = compile(tree, &Request::all_links());
    spinner.finish_and_clear();
    let compiled = compiled.map_err(|source| CliError::compile(file, source))?;
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let ids: Vec<usize> = compiled
        .frames()
        .iter()
        .map(|f| fk.link_id(&f.link).map(|id| id.0))
        .collect::<Result<_, _>>()
        .map_err(|source| CliError::Runtime { file: file.to_owned(), source })?;
    let bar = crate::progress::bar(samples as u64, "checking configurations");
    // Configurations `start..end` of the sequence: each frame's largest error over them.
    let run = |(start, end): (usize, usize)| -> Result<Vec<f64>, CliError> {
        let mut worst = vec![0.0f64; ids.len()];
        let mut evaluator = compiled.evaluator();
        for q in Configurations::new(tree).skip(start).take(end - start) {
            let reference = fk.link_poses(&q).map_err(|source| CliError::Runtime { file: file.to_owned(), source })?;
            for ((frame, &id), worst) in evaluator.eval(&q).iter().zip(&ids).zip(&mut worst) {
                *worst = worst_of(*worst, distance(frame, &reference[id], reach));
            }
            bar.inc(1);
        }
        Ok(worst)
    };
    let threads = std::thread::available_parallelism().map_or(1, std::num::NonZero::get).min(samples);
    let runs: Vec<(usize, usize)> =
        (0..threads).map(|k| (k * samples / threads, (k + 1) * samples / threads)).collect();
    let results: Vec<Result<Vec<f64>, CliError>> = std::thread::scope(|scope| {
        let handles: Vec<_> = runs.iter().map(|&range| scope.spawn(move || run(range))).collect();
        #[allow(clippy::expect_used, reason = "invariant: a run returns its error rather than panicking")]
        handles.into_iter().map(|h| h.join().expect("a run of configurations does not panic")).collect()
    });
    bar.finish_and_clear();
    let mut worst = vec![0.0f64; ids.len()];
    for result in results {
        for (w, e) in worst.iter_mut().zip(result?) {
            *w = worst_of(*w, e);
        }
    }
    Ok(compiled.frames().iter().zip(worst).map(|(f, error)| FrameError { link: f.link.clone(), error }).collect())
}

/// The frame with the largest error, as the error `check` fails with if it is past tolerance (or
/// not a number); a check of no frame at all fails too, since it checked nothing.
pub fn verdict(file: &str, errors: &[FrameError]) -> Result<(), CliError> {
    match errors.iter().max_by(|a, b| a.error.total_cmp(&b.error)) {
        // A NaN error fails as well.
        Some(worst) if worst.error.is_nan() || worst.error > TOLERANCE => Err(CliError::Disagrees {
            file: file.to_owned(),
            link: worst.link.clone(),
            error: worst.error,
            tolerance: TOLERANCE,
        }),
        Some(_) => Ok(()),
        None => Err(CliError::NothingToCheck { file: file.to_owned() }),
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
        let failed = verdict("arm.urdf", &[frame("a", 0.0), frame("b", f64::NAN)]);
        assert!(failed.is_err_and(|e| e.to_string().contains("link `b`")));
        assert!(verdict("arm.urdf", &[]).is_err_and(|e| e.to_string().contains("nothing to check")));
    }

    #[test]
    fn nan_is_the_worst_error_and_stays_so() {
        assert_eq!(worst_of(0.0, 1e-15), 1e-15);
        assert_eq!(worst_of(1e-15, 0.0), 1e-15);
        assert_eq!(worst_of(1e-15, f64::NAN), f64::INFINITY);
        assert_eq!(worst_of(f64::INFINITY, 0.5), f64::INFINITY);
    }

    #[test]
    fn zero_samples_are_refused() {
        assert_eq!(sample_count("10"), Ok(10));
        assert!(sample_count("0").is_err());
        assert!(sample_count("-1").is_err());
    }
}
