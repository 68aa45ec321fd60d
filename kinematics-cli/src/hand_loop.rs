//! The naive way to check collisions, which `kinematics demo` times against the generated
//! `Panda::collides`: every link's pose from the generated `Panda::link_poses`, then plain loops
//! that place every sphere by its link's pose and test it against every obstacle, then every
//! sphere pair of the self-collision pairs, the first hit ending the check. No bounding spheres,
//! no grids, no lanes: what one writes with the poses alone. Touching counts as colliding, as in
//! `collides`.

use kinematics::SceneObstacles;
use kinematics::model::collision::LinkSphere;
use kinematics::model::{KinematicTree, LinkId};

use crate::panda::Panda;

/// How many spheres the Panda has.
const SPHERES: usize = Panda::SPHERE_RADII.len();

/// The hand-written check: spheres, pairs and obstacles, read once.
pub struct HandLoop {
    /// Per sphere: its link's index in `Panda::LINK_NAMES` (`None` for the base, whose pose is the
    /// identity), its centre in the link's frame and its radius.
    spheres: Vec<(Option<usize>, [f64; 3], f64)>,
    /// Every pair of spheres on the links of a self-collision pair (indices into `spheres`).
    pairs: Vec<(usize, usize)>,
    /// The scene.
    obstacles: SceneObstacles,
}

impl HandLoop {
    /// The check of the built-in Panda's `spheres` (the model's, in its order), its link `pairs`
    /// and `obstacles`; `None` if these are not the Panda's spheres (another count, or a link
    /// that `Panda::link_poses` does not return).
    pub fn new(
        tree: &KinematicTree,
        spheres: &[LinkSphere],
        pairs: &[(LinkId, LinkId)],
        obstacles: &SceneObstacles,
    ) -> Option<Self> {
        if spheres.len() != SPHERES {
            return None;
        }
        let placed = spheres
            .iter()
            .map(|s| {
                let link = tree.link(s.link);
                let index = if s.link == tree.root() {
                    None
                } else {
                    Some(Panda::LINK_NAMES.iter().position(|name| *name == link.name)?)
                };
                Some((index, s.sphere.center, s.sphere.radius))
            })
            .collect::<Option<Vec<_>>>()?;
        let mut sphere_pairs = Vec::new();
        for &(a, b) in pairs {
            for (i, _) in spheres.iter().enumerate().filter(|(_, s)| s.link == a) {
                for (j, _) in spheres.iter().enumerate().filter(|(_, s)| s.link == b) {
                    sphere_pairs.push((i, j));
                }
            }
        }
        Some(HandLoop { spheres: placed, pairs: sphere_pairs, obstacles: obstacles.clone() })
    }

    /// Whether the Panda at `q` touches an obstacle or itself.
    pub fn collides(&self, q: &[f64; Panda::DOF]) -> bool {
        let poses = Panda::link_poses(q);
        let mut centers = [[0.0; 3]; SPHERES];
        for (center, &(link, local, _)) in centers.iter_mut().zip(&self.spheres) {
            *center = match link {
                Some(i) => poses[i].place(local),
                None => local,
            };
        }
        let o = &self.obstacles;
        for (&c, &(_, _, r)) in centers.iter().zip(&self.spheres) {
            if o.spheres.iter().any(|s| norm2(sub(c, s.center)) <= (r + s.radius).powi(2))
                || o.capsules.iter().any(|k| norm2(sub(c, nearest_on_segment(c, k.a, k.b))) <= (r + k.radius).powi(2))
                || o.cylinders.iter().any(|k| cylinder_gap2(c, k.a, k.b, k.radius) <= r * r)
                || o.boxes.iter().any(|b| box_gap2(c, b.center, &b.rotation, b.half_extents) <= r * r)
            {
                return true;
            }
        }
        self.pairs
            .iter()
            .any(|&(a, b)| norm2(sub(centers[a], centers[b])) <= (self.spheres[a].2 + self.spheres[b].2).powi(2))
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm2(a: [f64; 3]) -> f64 {
    dot(a, a)
}

/// The point of the segment from `a` to `b` nearest `p`.
fn nearest_on_segment(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    let ab = sub(b, a);
    let length2 = norm2(ab);
    let t = if length2 > 0.0 { (dot(sub(p, a), ab) / length2).clamp(0.0, 1.0) } else { 0.0 };
    [a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]]
}

/// The squared distance from `p` to the solid cylinder of `radius` about the segment `a`-`b`
/// (zero inside).
fn cylinder_gap2(p: [f64; 3], a: [f64; 3], b: [f64; 3], radius: f64) -> f64 {
    let (ab, ap) = (sub(b, a), sub(p, a));
    let length = norm2(ab).sqrt();
    let along = dot(ap, ab) / length;
    let across = (norm2(ap) - along * along).max(0.0).sqrt();
    let beyond_caps = (-along).max(along - length).max(0.0);
    let beyond_side = (across - radius).max(0.0);
    beyond_caps * beyond_caps + beyond_side * beyond_side
}

/// The squared distance from `p` to the box at `center` with axes the rows of `rotation` and
/// half-extents `half` (zero inside).
fn box_gap2(p: [f64; 3], center: [f64; 3], rotation: &[[f64; 3]; 3], half: [f64; 3]) -> f64 {
    let d = sub(p, center);
    (0..3).map(|i| (dot(rotation[i], d).abs() - half[i]).max(0.0).powi(2)).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each distance of the hand loop's geometry, against one worked by hand (the demo's scene
    /// holds boxes only, so its own run covers no other shape).
    #[test]
    fn gaps_are_the_distances_to_the_shapes() {
        let close = |got: f64, expected: f64, what: &str| assert!((got - expected).abs() < 1e-12, "{what}: {got}");
        // A segment and a cylinder of radius 1 along z from 0 to 2.
        let (a, b) = ([0.0, 0.0, 0.0], [0.0, 0.0, 2.0]);
        for (p, segment, cylinder) in [
            ([0.0, 0.0, 1.0], 0.0, 0.0),             // on the axis
            ([0.5, 0.0, 1.5], 0.5, 0.0),             // inside
            ([3.0, 0.0, 1.0], 3.0, 2.0),             // beside
            ([0.0, 0.0, -2.0], 2.0, 2.0),            // below a cap
            ([4.0, 0.0, 5.0], 5.0, 18.0_f64.sqrt()), // beyond the rim: 3 out, 3 up
        ] {
            close(norm2(sub(p, nearest_on_segment(p, a, b))).sqrt(), segment, &format!("segment at {p:?}"));
            close(cylinder_gap2(p, a, b, 1.0).sqrt(), cylinder, &format!("cylinder at {p:?}"));
        }
        // A box turned a quarter about z: its first axis is the world's y.
        let rotation = [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
        let (center, half) = ([1.0, 1.0, 0.0], [2.0, 0.5, 0.5]);
        for (p, gap) in [
            ([1.0, 1.0, 0.0], 0.0),            // its centre
            ([1.0, 3.5, 0.0], 0.5),            // past its long side, along the world's y
            ([2.0, 1.0, 0.0], 0.5),            // past its short side, along the world's x
            ([2.5, 4.0, 1.5], 3.0_f64.sqrt()), // past a corner by 1 each way
        ] {
            close(box_gap2(p, center, &rotation, half).sqrt(), gap, &format!("box at {p:?}"));
        }
    }
}
