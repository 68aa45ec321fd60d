//! Where a compiled robot's collision spheres sit: the links that carry spheres (tree order),
//! each sphere's centre in its link's frame (its `<collision>` element's origin applied to the
//! cover's centre), and each link's bounding sphere there. The emitter writes its tables from
//! this layout, and `kinematics check` and `inspect` read the same one.

use kinematics_model::KinematicTree;
use kinematics_model::LinkId;
use kinematics_model::collision::LinkSphere;

use crate::error::CompileError;
use crate::ik::geometry::transform_point;
use crate::request::{Request, compile};
use crate::stats::OpCount;

/// The links with spheres, each sphere's place in its link's frame, and each link's bounding
/// sphere there.
#[derive(Debug, Clone, PartialEq)]
pub struct CollisionLayout {
    /// The links with spheres, in tree order.
    pub links: Vec<LinkId>,
    /// Per sphere (in the spheres' order): its link's position in `links` and its centre in the
    /// link's frame.
    pub points: Vec<(usize, [f64; 3])>,
    /// Per link of `links`: its bounding sphere's centre (link frame) and radius.
    pub bounds: Vec<([f64; 3], f64)>,
}

impl CollisionLayout {
    /// The layout of `spheres` (the model's `link_spheres` of `tree`).
    pub fn new(tree: &KinematicTree, spheres: &[LinkSphere]) -> Self {
        let mut links: Vec<LinkId> = spheres.iter().map(|s| s.link).collect();
        links.sort_unstable();
        links.dedup();
        let points: Vec<(usize, [f64; 3])> = spheres
            .iter()
            .map(|s| {
                #[allow(clippy::expect_used, reason = "invariant: every sphere's link is in `links`")]
                let frame = links.binary_search(&s.link).expect("the links are those of the spheres");
                let origin = &tree.link(s.link).collisions[s.collision].origin;
                (frame, transform_point(origin, s.sphere.center))
            })
            .collect();
        let bounds = (0..links.len())
            .map(|frame| {
                let balls: Vec<([f64; 3], f64)> = points
                    .iter()
                    .zip(spheres)
                    .filter(|((f, _), _)| *f == frame)
                    .map(|((_, p), s)| (*p, s.sphere.radius))
                    .collect();
                enclosing_sphere(&balls)
            })
            .collect();
        CollisionLayout { links, points, bounds }
    }

    /// What the generated code computes, in `base`'s frame: every sphere's centre
    /// (`sphere_centers`, each `R p + t` in the graph, only what the centres need of the poses),
    /// and the poses of the links with spheres (the collision checks' body, which places the
    /// spheres it tests itself).
    pub fn op_counts(&self, tree: &KinematicTree, base: &str) -> Result<(OpCount, OpCount), CompileError> {
        let request = Request {
            base: Some(base.to_owned()),
            tips: self.links.iter().map(|&l| tree.link(l).name.clone()).collect(),
            position_only: false,
            velocity: None,
        };
        let mut compiled = compile(tree, &request)?;
        let poses = compiled.op_count();
        let centers = compiled.points(&self.points);
        Ok((OpCount::of(compiled.graph(), centers.into_iter().flatten()), poses))
    }

    /// Each link's range of spheres (they come link by link, in the links' order).
    pub fn ranges(&self) -> Vec<(usize, usize)> {
        let mut start = 0;
        (0..self.links.len())
            .map(|f| {
                let count = self.points.iter().filter(|(g, _)| *g == f).count();
                start += count;
                (start - count, start)
            })
            .collect()
    }
}

/// A sphere containing every ball of `balls` (centre, radius; at least one), near the smallest:
/// Badoiu and Clarkson's iteration (step `k` moves the centre `1/(k+1)` of the way to the point of
/// the ball farthest from it), then the radius that contains every ball exactly. Deterministic.
///
/// ```
/// use kinematics_compiler::collision_layout::enclosing_sphere;
/// let (c, r) = enclosing_sphere(&[([0.0; 3], 1.0), ([4.0, 0.0, 0.0], 1.0)]);
/// assert!((r - 3.0).abs() < 0.05 && (c[0] - 2.0).abs() < 0.05);
/// ```
pub fn enclosing_sphere(balls: &[([f64; 3], f64)]) -> ([f64; 3], f64) {
    if let [only] = balls {
        return *only;
    }
    let reach = |c: [f64; 3], (p, r): ([f64; 3], f64)| distance(c, p) + r;
    #[allow(clippy::cast_precision_loss)]
    let mut c = [0, 1, 2].map(|i| balls.iter().map(|(p, _)| p[i]).sum::<f64>() / balls.len() as f64);
    for k in 1..=2000u32 {
        let Some(&(p, r)) = balls.iter().max_by(|a, b| reach(c, **a).total_cmp(&reach(c, **b))) else { break };
        let d = distance(c, p);
        let far = if d > 0.0 { [0, 1, 2].map(|i| p[i] + (p[i] - c[i]) / d * r) } else { [p[0] + r, p[1], p[2]] };
        let step = 1.0 / f64::from(k + 1);
        c = [0, 1, 2].map(|i| c[i] + (far[i] - c[i]) * step);
    }
    let radius = balls.iter().map(|&b| reach(c, b)).fold(0.0, f64::max);
    (c, radius)
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_enclosing_sphere_holds_every_ball_and_is_near_the_smallest() {
        // Two balls on a line: the smallest encloser is known exactly.
        let (c, r) = enclosing_sphere(&[([0.0; 3], 1.0), ([4.0, 0.0, 0.0], 1.0)]);
        assert!((r - 3.0).abs() < 0.05, "{c:?} {r}");
        let balls = [([0.0, 0.0, 0.0], 0.1), ([0.3, 0.1, 0.0], 0.05), ([0.1, 0.4, 0.2], 0.2), ([0.0, 0.0, 0.0], 0.3)];
        let (c, r) = enclosing_sphere(&balls);
        assert!(balls.iter().all(|&(p, q)| distance(c, p) + q <= r));
        assert_eq!(enclosing_sphere(&[([1.0, 2.0, 3.0], 0.5)]), ([1.0, 2.0, 3.0], 0.5));
    }
}
