//! Where a compiled robot's collision spheres sit: the links that carry spheres (tree order),
//! each sphere's centre in its link's frame (its `<collision>` element's origin applied to the
//! cover's centre), each link's bounding sphere there, and the groups of a few neighbouring
//! spheres each link's are split into (each with its bounding sphere: a check tests a link, then
//! its groups, then their spheres). The emitter writes its tables from this layout, and
//! `kinematics check` and `inspect` read the same one.
//!
//! A group holds at most four spheres (`GROUP`); the self check tests by groups. Each link's
//! bounding sphere is found by `enclosing_sphere` (Badoiu and Clarkson's iteration towards the
//! smallest, then the radius that holds every sphere). The layout also says what the centres cost,
//! which `inspect` and `check` read too.

use kinematics_model::KinematicTree;
use kinematics_model::LinkId;
use kinematics_model::collision::{FixedPair, LinkSphere};

use crate::error::CompileError;
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
    /// The checks' order of the spheres: link by link, each link's group by group; entry `k` is
    /// the index (in the spheres' order) of the `k`-th sphere in the checks' order.
    pub order: Vec<usize>,
    /// Per link of `links`: the range of its groups in `groups`.
    pub link_groups: Vec<(usize, usize)>,
    /// Per group: the range of its spheres in the checks' order, and its bounding sphere's centre
    /// (link frame) and radius.
    pub groups: Vec<(usize, usize, [f64; 3], f64)>,
}

/// The most spheres a group holds: a link's spheres are halved across their widest extent until
/// each part has at most this many.
pub const GROUP: usize = 4;

/// `members` (indices into `balls`) halved across the widest extent of their centres (ties by
/// index, so the split is the same on every run) until each part has at most [`GROUP`].
fn split(members: Vec<usize>, balls: &[([f64; 3], f64)], out: &mut Vec<Vec<usize>>) {
    if members.len() <= GROUP {
        out.push(members);
        return;
    }
    let extent = |axis: usize| {
        let values = members.iter().map(|&m| balls[m].0[axis]);
        values.clone().fold(f64::NEG_INFINITY, f64::max) - values.fold(f64::INFINITY, f64::min)
    };
    #[allow(clippy::expect_used, reason = "invariant: 0..3 is not empty")]
    let axis = (0..3).max_by(|&a, &b| extent(a).total_cmp(&extent(b)).then(b.cmp(&a))).expect("three axes");
    let mut sorted = members;
    sorted.sort_by(|&a, &b| balls[a].0[axis].total_cmp(&balls[b].0[axis]).then(a.cmp(&b)));
    let upper = sorted.split_off(sorted.len() / 2);
    split(sorted, balls, out);
    split(upper, balls, out);
}

impl CollisionLayout {
    /// The layout of `spheres` (the model's `link_spheres`, centres in their links' frames).
    pub fn new(spheres: &[LinkSphere]) -> Self {
        let mut links: Vec<LinkId> = spheres.iter().map(|s| s.link).collect();
        links.sort_unstable();
        links.dedup();
        let points: Vec<(usize, [f64; 3])> = spheres
            .iter()
            .map(|s| {
                #[allow(clippy::expect_used, reason = "invariant: every sphere's link is in `links`")]
                let frame = links.binary_search(&s.link).expect("the links are those of the spheres");
                (frame, s.sphere.center)
            })
            .collect();
        let balls: Vec<([f64; 3], f64)> = points.iter().zip(spheres).map(|((_, p), s)| (*p, s.sphere.radius)).collect();
        let (mut bounds, mut order, mut link_groups, mut groups) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for frame in 0..links.len() {
            let members: Vec<usize> = (0..points.len()).filter(|&k| points[k].0 == frame).collect();
            let own: Vec<([f64; 3], f64)> = members.iter().map(|&k| balls[k]).collect();
            bounds.push(enclosing_sphere(&own));
            let mut parts = Vec::new();
            split(members, &balls, &mut parts);
            let first = groups.len();
            for part in parts {
                let (start, part_balls): (usize, Vec<([f64; 3], f64)>) =
                    (order.len(), part.iter().map(|&k| balls[k]).collect());
                order.extend(&part);
                let (center, radius) = enclosing_sphere(&part_balls);
                groups.push((start, order.len(), center, radius));
            }
            link_groups.push((first, groups.len()));
        }
        CollisionLayout { links, points, bounds, order, link_groups, groups }
    }

    /// The sphere pairs held apart for good (the model's `fixed_apart_pairs`), each sphere by its
    /// place in the checks' order, the first first; sorted, as the distances look them up.
    pub fn fixed_in_order(&self, fixed: &[FixedPair]) -> Vec<(usize, usize)> {
        let place = |sphere: usize| {
            #[allow(clippy::expect_used, reason = "invariant: `order` is a permutation of the spheres")]
            let place = self.order.iter().position(|&k| k == sphere).expect("every sphere has a place in the order");
            place
        };
        let mut out: Vec<(usize, usize)> = fixed
            .iter()
            .map(|f| {
                let (a, b) = (place(f.a), place(f.b));
                (a.min(b), a.max(b))
            })
            .collect();
        out.sort_unstable();
        out
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
}

/// The 64-bit words a held object's set of links takes: one bit per link with spheres (the
/// model's `link_spheres`, each sphere naming its link).
pub fn held_words(spheres: &[LinkSphere]) -> usize {
    let links: std::collections::BTreeSet<LinkId> = spheres.iter().map(|s| s.link).collect();
    links.len().div_ceil(64).max(1)
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

#[cfg(test)]
mod layout_tests {
    use super::*;
    use kinematics_model::collision::{Cover, Meshes, link_spheres};

    /// On every robot of `robots/` with collision geometry: the checks' order is a permutation
    /// keeping each link's spheres together, the groups partition each link's spheres into parts
    /// of at most `GROUP`, and every bounding sphere (link, group) holds its spheres.
    #[test]
    fn groups_partition_each_links_spheres_and_their_bounds_hold_them() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots");
        let mut checked = 0;
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            let name = path.display().to_string();
            if kinematics_model::SourceFormat::from_file_name(&name).is_none() {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            let tree = kinematics_model::parse_source(&name, &text).unwrap();
            let Ok(spheres) = link_spheres(&tree, &Cover::default(), Meshes::Skip) else { continue };
            if spheres.is_empty() {
                continue;
            }
            let layout = CollisionLayout::new(&spheres);
            let mut sorted = layout.order.clone();
            sorted.sort_unstable();
            assert_eq!(sorted, (0..spheres.len()).collect::<Vec<_>>(), "{name}");
            let holds = |(c, r): ([f64; 3], f64), k: usize| {
                let (p, q) = (layout.points[k].1, spheres[k].sphere.radius);
                let d = ((p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2) + (p[2] - c[2]).powi(2)).sqrt();
                d + q <= r * (1.0 + 1e-12)
            };
            for (f, &(g0, g1)) in layout.link_groups.iter().enumerate() {
                let mut members = Vec::new();
                for &(s0, s1, c, r) in &layout.groups[g0..g1] {
                    assert!(s1 > s0 && s1 - s0 <= GROUP, "{name}");
                    for &k in &layout.order[s0..s1] {
                        assert_eq!(layout.points[k].0, f, "{name}: sphere {k} in another link's group");
                        assert!(holds((c, r), k) && holds(layout.bounds[f], k), "{name}: sphere {k}");
                        members.push(k);
                    }
                }
                let own = layout.points.iter().filter(|(g, _)| *g == f).count();
                assert_eq!(members.len(), own, "{name}: link {f}");
            }
            checked += 1;
        }
        assert!(checked >= 3, "{checked} robots with collision geometry");
    }
}
