//! Batches split across cores with rayon (feature `rayon`).

use kinematics_core::{KinematicsError, check_output};
use rayon::prelude::*;

/// Batches smaller than this run on the calling thread: below it, handing work to other threads
/// costs more than it saves.
pub const PARALLEL_THRESHOLD: usize = 4096;

/// Runs a batch function (a derived robot's `*_batch`, or any function of the same shape) over
/// `qs` into `out`, split into one contiguous piece per worker thread of rayon's pool (pieces a
/// multiple of 8 configurations long, so every piece but the last fills whole lanes). Batches
/// shorter than [`PARALLEL_THRESHOLD`] run on the calling thread.
///
/// ```
/// use kinematics::Kinematics;
///
/// #[derive(Kinematics)]
/// #[kinematics(urdf = "robots/ur5.urdf", tip = "tool0")]
/// struct Ur5;
///
/// let qs: Vec<[f64; 6]> = (0..10_000).map(|i| [i as f64 * 1e-3; 6]).collect();
/// let mut poses = vec![kinematics::Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; qs.len()];
/// kinematics::parallel::batch(&qs, &mut poses, Ur5::tip_pose_batch)?;
/// assert_eq!(poses[1234], Ur5::tip_pose(&qs[1234]));
/// # Ok::<(), kinematics::KinematicsError>(())
/// ```
pub fn batch<Q: Sync, O: Send>(
    qs: &[Q],
    out: &mut [O],
    f: impl Fn(&[Q], &mut [O]) -> Result<(), KinematicsError> + Sync,
) -> Result<(), KinematicsError> {
    check_output("(batch)", qs.len(), out.len())?;
    if qs.len() < PARALLEL_THRESHOLD {
        return f(qs, out);
    }
    let pieces = rayon::current_num_threads().max(1);
    let piece = qs.len().div_ceil(pieces).next_multiple_of(8);
    qs.par_chunks(piece).zip(out.par_chunks_mut(piece)).try_for_each(|(q, o)| f(q, o))
}
