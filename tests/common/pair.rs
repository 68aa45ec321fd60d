//! Two descriptions of one robot whose frames attach to the same bodies: the fixed transform
//! relating each pair of same-body frames, and the check that it stays fixed.

use super::{AGREEMENT_TOLERANCE, assert_pose_eq};
use kinematics::ReferenceFk;
use nalgebra::Isometry3;

/// Two descriptions of one robot and the links whose frames are attached to the same body.
pub struct Pair {
    pub a: ReferenceFk,
    pub a_base: &'static str,
    pub b: ReferenceFk,
    pub b_base: &'static str,
    /// (link in a, link in b, the fixed transform X with pose_a * X = pose_b).
    pub links: Vec<(&'static str, &'static str, Isometry3<f64>)>,
}

impl Pair {
    /// Checks `pose_a(q) * X = pose_b(q)` for every linked pair, poses taken relative to each
    /// description's base link.
    pub fn check(&self, q: &[f64]) {
        for (la, lb, x) in &self.links {
            let pa = self.a.relative_pose(q, self.a_base, la).unwrap();
            let pb = self.b.relative_pose(q, self.b_base, lb).unwrap();
            assert_pose_eq(&(pa * x), &pb, AGREEMENT_TOLERANCE, &format!("{la} vs {lb} at q = {q:?}"));
        }
    }

    /// The fixed transform found for the pair (`la`, `lb`).
    pub fn relation(&self, la: &str, lb: &str) -> Isometry3<f64> {
        self.links.iter().find(|(a, b, _)| *a == la && *b == lb).map(|(_, _, x)| *x).unwrap()
    }
}

/// The fixed transforms relating each link's frame in `a` to its frame in `b`, read off at q = 0;
/// the property tests then show they stay fixed at every other configuration.
pub fn related_at_zero(
    a: ReferenceFk,
    a_base: &'static str,
    b: ReferenceFk,
    b_base: &'static str,
    links: &[(&'static str, &'static str)],
) -> Pair {
    assert_eq!(a.tree().dof_names(), b.tree().dof_names(), "the two descriptions order their joints alike");
    let zero = vec![0.0; a.tree().dof()];
    let links = links
        .iter()
        .map(|&(la, lb)| {
            let pa = a.relative_pose(&zero, a_base, la).unwrap();
            let pb = b.relative_pose(&zero, b_base, lb).unwrap();
            (la, lb, pa.inverse() * pb)
        })
        .collect();
    Pair { a, a_base, b, b_base, links }
}
