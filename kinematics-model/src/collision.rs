//! Collision geometry: what a link's `<collision>` elements say (a primitive or a mesh, placed by
//! an origin in the link's frame), the rule each shape must keep, the spheres that cover a
//! primitive, and which links are checked against which (rigid bodies and pairs).
//!
//! Everything here is in a shape's own frame or about the tree's topology: placing a sphere in
//! its link's frame (the element's origin) is transform math, which the compiler and the runtime
//! reference each do their own way. One selection carries points through the tree's fixed
//! transforms, and both read it as they read the pairs: the sphere pairs held apart for good
//! ([`fixed`]), which the distances leave out.
//!
//! **The cover.** A sphere is itself. A capsule (URDF/SDF: a cylinder of `length` between the
//! centres of two hemispherical caps of its `radius`, along z) is covered by spheres centred on
//! its axis segment, both ends included, spaced evenly and at most `2 h` apart with
//! `h = sqrt(2 r d + d^2)`, each of radius `sqrt(r^2 + h^2)`: each contains the capsule's slab
//! within `h` of its centre and the end ones the caps, and since a ball of radius `r` about any
//! point of the segment lies in the capsule, no point of a sphere is farther than `d` from it. A
//! box (`size`, centred) and a cylinder (`radius`, `length` along z, centred) are covered by
//! subdividing their bounding box: a cell whose part of the shape a sphere about the cell's centre
//! contains with an overshoot of at most `d` is taken, a cell that misses the shape is dropped,
//! any other is halved across its longest side (the overshoot of a sphere of radius `R` whose
//! centre lies `e` inside the shape is at most `R - e`: every point of it is within `R - e` of the
//! ball of radius `e` about the centre, which the shape contains). The cover is deterministic and
//! contains every point of the shape; `d` is the largest overshoot, the key `sphere_cover`.
//!
//! **What is here.** `Shape` (sphere, box, cylinder, capsule, mesh, placed by its origin) is read
//! by the URDF reader and the urdf-rs conversion alike, its sizes checked by validation naming the
//! link and the line; the cover is taken in each shape's own frame (capsules and cylinders on their
//! axis, the rest by subdivision; every point contained, the overshoot at most the `sphere_cover`
//! given); `link_spheres` gives every sphere of a robot in one fixed order, a mesh refused or
//! skipped; `rigid_bodies` and `collision_pairs` are the pair rule. Each link's bounding sphere is
//! the compiler's (`collision_layout`).

pub mod fixed;
pub mod grid;

use std::collections::BTreeSet;

pub use fixed::{FixedPair, ON_AXIS, fixed_apart_pairs};
pub use grid::{CellState, PairGrid, pair_grids};

use crate::transform::FixedTransform;
use crate::tree::{KinematicTree, LinkId};

/// A collision shape in its own frame (URDF's `<geometry>`).
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// `<sphere radius>`, centred.
    Sphere {
        /// Radius (m).
        radius: f64,
    },
    /// `<box size="x y z">`, centred.
    Box {
        /// Edge lengths along x, y, z (m).
        size: [f64; 3],
    },
    /// `<cylinder radius length>`, centred, its axis along z.
    Cylinder {
        /// Radius (m).
        radius: f64,
        /// Length along z (m).
        length: f64,
    },
    /// `<capsule radius length>`: the points within `radius` of the segment of `length` along z,
    /// centred.
    Capsule {
        /// Radius (m).
        radius: f64,
        /// Length of the segment between the caps' centres (m).
        length: f64,
    },
    /// `<mesh filename scale>`: not read (no file IO here); refused where spheres are asked for,
    /// unless meshes are left out.
    Mesh {
        /// The file as written.
        filename: String,
        /// Scale along x, y, z.
        scale: [f64; 3],
    },
}

impl Shape {
    /// Its name as URDF writes it.
    pub fn name(&self) -> &'static str {
        match self {
            Shape::Sphere { .. } => "sphere",
            Shape::Box { .. } => "box",
            Shape::Cylinder { .. } => "cylinder",
            Shape::Capsule { .. } => "capsule",
            Shape::Mesh { .. } => "mesh",
        }
    }

    /// What is wrong with its sizes, if anything: every length must be finite and positive (a
    /// capsule's length may be zero: a sphere), a mesh's scale finite and not zero.
    pub fn fault(&self) -> Option<String> {
        let length = |what: &str, x: f64, zero_ok: bool| {
            let ok = x.is_finite() && (x > 0.0 || (zero_ok && x == 0.0));
            (!ok).then(|| {
                let must = if zero_ok { "a finite length, zero or more" } else { "a finite positive length" };
                format!("<{} {what}> is {x} (must be {must})", self.name())
            })
        };
        match self {
            Shape::Sphere { radius } => length("radius", *radius, false),
            Shape::Box { size } => {
                ["x", "y", "z"].iter().zip(size).find_map(|(axis, &x)| length(&format!("size {axis}"), x, false))
            }
            Shape::Cylinder { radius, length: l } => {
                length("radius", *radius, false).or_else(|| length("length", *l, false))
            }
            Shape::Capsule { radius, length: l } => {
                length("radius", *radius, false).or_else(|| length("length", *l, true))
            }
            Shape::Mesh { scale, .. } => scale
                .iter()
                .any(|s| !s.is_finite() || *s == 0.0)
                .then(|| format!("<mesh scale> is {scale:?} (must be finite and not zero)")),
        }
    }

    /// Spheres containing every point of the shape, none reaching farther than `overshoot` from
    /// it (see the module doc); `None` for a mesh. `overshoot` must be finite and positive.
    pub fn cover(&self, overshoot: f64) -> Option<Vec<Sphere>> {
        let d = overshoot;
        Some(match *self {
            Shape::Sphere { radius } => vec![Sphere { center: [0.0; 3], radius }],
            Shape::Capsule { radius, length } => capsule(radius, length, d),
            Shape::Box { size } => {
                let half = size.map(|s| s / 2.0);
                subdivide(&|p| box_depth(half, p), &|lo, hi| box_reach(half, lo, hi), (half.map(|h| -h), half), d)
            }
            Shape::Cylinder { radius, length } => cylinder(radius, length, d),
            Shape::Mesh { .. } => return None,
        })
    }

    /// How far `p` (in the shape's frame) lies inside the shape: positive inside, negative
    /// outside, the distance to the surface either way for a sphere, capsule and (outside) box;
    /// for a box inside and a cylinder anywhere a lower bound where exactness costs more
    /// (what the cover's overshoot bound and the tests need). `None` for a mesh.
    pub fn depth(&self, p: [f64; 3]) -> Option<f64> {
        Some(match *self {
            Shape::Sphere { radius } => radius - norm(p),
            Shape::Capsule { radius, length } => {
                let z = p[2].clamp(-length / 2.0, length / 2.0);
                radius - norm([p[0], p[1], p[2] - z])
            }
            Shape::Box { size } => box_depth(size.map(|s| s / 2.0), p),
            Shape::Cylinder { radius, length } => cylinder_depth(radius, length / 2.0, p),
            Shape::Mesh { .. } => return None,
        })
    }
}

/// A sphere: its centre (in its shape's frame) and radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    /// Centre (m).
    pub center: [f64; 3],
    /// Radius (m).
    pub radius: f64,
}

/// One `<collision>` element of a link.
#[derive(Debug, Clone, PartialEq)]
pub struct Collision {
    /// The shape's frame in the link's frame (`<origin xyz rpy>`; its angles as written: they
    /// only place constants, so the exactness policy leaves them be).
    pub origin: FixedTransform,
    /// The shape.
    pub shape: Shape,
}

fn norm(p: [f64; 3]) -> f64 {
    (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()
}

/// The capsule's cover: spheres on its axis segment.
fn capsule(radius: f64, length: f64, d: f64) -> Vec<Sphere> {
    let h_max = (2.0 * radius * d + d * d).sqrt();
    // Intervals of at most 2 h_max between consecutive centres (at least one when there is a
    // segment); `as` saturates, and the sizes are finite.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss, clippy::cast_precision_loss)]
    let intervals = if length > 0.0 { (length / (2.0 * h_max)).ceil().max(1.0) as usize } else { 0 };
    if intervals == 0 {
        return vec![Sphere { center: [0.0; 3], radius }];
    }
    #[allow(clippy::cast_precision_loss)]
    let step = length / intervals as f64;
    let h = step / 2.0;
    let r = (radius * radius + h * h).sqrt();
    (0..=intervals)
        .map(|i| {
            #[allow(clippy::cast_precision_loss)]
            let z = -length / 2.0 + step * i as f64;
            Sphere { center: [0.0, 0.0, z], radius: r }
        })
        .collect()
}

/// The cylinder's cover: where it is longer than its diameter, spheres on its axis at least a
/// radius from the caps (each centre as deep as the radius, as a capsule's), and the two ends
/// beyond them by subdivision; a shorter one by subdivision alone.
fn cylinder(radius: f64, length: f64, d: f64) -> Vec<Sphere> {
    let half_z = length / 2.0;
    let depth = |p| cylinder_depth(radius, half_z, p);
    let reach = |lo, hi| cylinder_reach(radius, half_z, lo, hi);
    let whole = ([-radius, -radius, -half_z], [radius, radius, half_z]);
    let inner = half_z - radius;
    if inner < 0.0 {
        return subdivide(&depth, &reach, whole, d);
    }
    let h_max = (2.0 * radius * d + d * d).sqrt();
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss, clippy::cast_precision_loss)]
    let intervals = (2.0 * inner / (2.0 * h_max)).ceil() as usize;
    #[allow(clippy::cast_precision_loss)]
    let h = if intervals == 0 { h_max } else { inner / intervals as f64 };
    let r = (radius * radius + h * h).sqrt();
    let mut out: Vec<Sphere> = (0..=intervals)
        .map(|i| {
            #[allow(clippy::cast_precision_loss)]
            let z = -inner + 2.0 * h * i as f64;
            Sphere { center: [0.0, 0.0, z], radius: r }
        })
        .collect();
    // The axis spheres hold the slab |z| <= inner + h; the ends beyond it, if any, by subdivision.
    let covered = inner + h;
    if covered < half_z {
        out.extend(subdivide(&depth, &reach, ([-radius, -radius, -half_z], [radius, radius, -covered]), d));
        out.extend(subdivide(&depth, &reach, ([-radius, -radius, covered], [radius, radius, half_z]), d));
    }
    out
}

/// Depth of `p` in the centred box of half-extents `half`: the distance to the nearest face
/// inside (exact), minus the distance to the box outside (exact).
fn box_depth(half: [f64; 3], p: [f64; 3]) -> f64 {
    let q = [0, 1, 2].map(|i| p[i].abs() - half[i]);
    let outside = norm(q.map(|x| x.max(0.0)));
    if outside > 0.0 { -outside } else { -q[0].max(q[1]).max(q[2]) }
}

/// Depth of `p` in the centred cylinder of `radius` and half-length `half_z`: inside, the
/// distance to the nearest of the side and the caps (exact); outside, minus the distance (exact).
fn cylinder_depth(radius: f64, half_z: f64, p: [f64; 3]) -> f64 {
    let radial = (p[0] * p[0] + p[1] * p[1]).sqrt() - radius;
    let axial = p[2].abs() - half_z;
    let outside = (radial.max(0.0).powi(2) + axial.max(0.0).powi(2)).sqrt();
    if outside > 0.0 { -outside } else { -radial.max(axial) }
}

/// The farthest a point of the box's part of the cell `[lo, hi]` lies from the cell's centre, or
/// `None` when the cell misses the box.
fn box_reach(half: [f64; 3], lo: [f64; 3], hi: [f64; 3]) -> Option<f64> {
    let (a, b) = ([0, 1, 2].map(|i| lo[i].max(-half[i])), [0, 1, 2].map(|i| hi[i].min(half[i])));
    if (0..3).any(|i| a[i] > b[i]) {
        return None;
    }
    let c = [0, 1, 2].map(|i| (lo[i] + hi[i]) / 2.0);
    Some(norm([0, 1, 2].map(|i| (a[i] - c[i]).abs().max((b[i] - c[i]).abs()))))
}

/// [`box_reach`] for the cylinder: its part of the cell lies in the cell clipped to the cylinder's
/// bounding box (an upper bound of the reach), and the cell misses the cylinder when its nearest
/// point to the axis is farther than the radius.
fn cylinder_reach(radius: f64, half_z: f64, lo: [f64; 3], hi: [f64; 3]) -> Option<f64> {
    let nearest = [0, 1].map(|i| 0.0_f64.clamp(lo[i], hi[i]));
    if nearest[0].hypot(nearest[1]) > radius {
        return None;
    }
    box_reach([radius, radius, half_z], lo, hi)
}

/// Cells halved at most this many times along any side: past it the cell's sphere is taken as it
/// is (never reached for a cover of at least a millionth of the shape's size).
const MAX_DEPTH: usize = 60;

/// The cover of the part of a convex shape inside the box `[lo, hi]`, by subdivision (see the
/// module doc): `depth` says how far a point lies inside the shape, `reach` how far the shape's
/// part of a cell extends from the cell's centre (`None`: the cell misses it).
fn subdivide(
    depth: &dyn Fn([f64; 3]) -> f64,
    reach: &dyn Fn([f64; 3], [f64; 3]) -> Option<f64>,
    (lo, hi): ([f64; 3], [f64; 3]),
    d: f64,
) -> Vec<Sphere> {
    let mut out = Vec::new();
    let mut cells = vec![(lo, hi, 0usize)];
    while let Some((lo, hi, level)) = cells.pop() {
        let Some(radius) = reach(lo, hi) else { continue };
        let center = [0, 1, 2].map(|i| (lo[i] + hi[i]) / 2.0);
        if radius - depth(center) <= d || level >= MAX_DEPTH {
            out.push(Sphere { center, radius });
            continue;
        }
        let axis = (0..3).fold(0, |best, i| if hi[i] - lo[i] > hi[best] - lo[best] { i } else { best });
        let mid = center[axis];
        let (mut upper_lo, mut lower_hi) = (lo, hi);
        upper_lo[axis] = mid;
        lower_hi[axis] = mid;
        // The upper half pushed first, so the lower one is taken first: the order is fixed.
        cells.push((upper_lo, hi, level + 1));
        cells.push((lo, lower_hi, level + 1));
    }
    out
}

/// What to do with mesh geometry, which the cover cannot read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Meshes {
    /// A mesh is an error naming its link and file (the default: a mesh left out is a part of the
    /// robot no check sees).
    #[default]
    Refuse,
    /// Meshes are left out (the robot's other geometry is checked; a spherized URDF has none).
    Skip,
}

/// One sphere of a robot's cover: its link, which of the link's `<collision>` elements it covers
/// (its origin places the centre in the link's frame), and the sphere in that element's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkSphere {
    /// The link.
    pub link: LinkId,
    /// The index of the `<collision>` element in the link's list.
    pub collision: usize,
    /// The sphere, in the element's own frame.
    pub sphere: Sphere,
}

/// A mesh where spheres are asked for and meshes are not skipped.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "link `{link}`: <collision> is a mesh (`{filename}`), which is not read: give the link primitives or spheres (a spherized URDF), or leave meshes out"
)]
pub struct MeshRefused {
    /// The link.
    pub link: String,
    /// The mesh file as written.
    pub filename: String,
}

/// Every sphere of `tree`'s collision geometry covered with the largest overshoot `overshoot`
/// (finite and positive): links in tree order, each link's elements in order, each element's
/// cover in order. This order is the robot's sphere order everywhere (generated code, the
/// reference).
pub fn link_spheres(tree: &KinematicTree, overshoot: f64, meshes: Meshes) -> Result<Vec<LinkSphere>, MeshRefused> {
    let mut out = Vec::new();
    for (i, link) in tree.links().iter().enumerate() {
        for (k, collision) in link.collisions.iter().enumerate() {
            match (collision.shape.cover(overshoot), &collision.shape) {
                (Some(spheres), _) => {
                    out.extend(spheres.into_iter().map(|sphere| LinkSphere { link: LinkId(i), collision: k, sphere }));
                }
                (None, Shape::Mesh { filename, .. }) if meshes == Meshes::Refuse => {
                    return Err(MeshRefused { link: link.name.clone(), filename: filename.clone() });
                }
                (None, _) => {}
            }
        }
    }
    Ok(out)
}

/// The rigid bodies of `tree`: links joined by fixed joints only share a body. `body[link]` is
/// the index of the first link (in tree order) of its body.
pub fn rigid_bodies(tree: &KinematicTree) -> Vec<usize> {
    let mut body: Vec<usize> = (0..tree.links().len()).collect();
    // Links are in depth-first pre-order, so a link's parent comes first.
    for (i, link) in tree.links().iter().enumerate() {
        if let Some(j) = link.parent_joint {
            let joint = tree.joint(j);
            if joint.kind == crate::JointKind::Fixed {
                body[i] = body[joint.parent.0];
            }
        }
    }
    body
}

/// Which link pairs a robot's self-collision check tests.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CollisionPairs {
    /// The pairs, each `(a, b)` with `a < b` in tree order, sorted.
    pub pairs: Vec<(LinkId, LinkId)>,
    /// How the pairs were chosen, for messages and `inspect`.
    pub rule: PairRule,
}

/// How the pairs of links were chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairRule {
    /// Every pair of links with geometry on different rigid bodies, less an SRDF's disabled pairs.
    Srdf,
    /// No SRDF: every pair of links with geometry on different rigid bodies, less the pairs of
    /// bodies joined by one joint (adjacent bodies, which touch by design).
    Adjacent,
}

/// The pairs of links `tree`'s self-collision check tests: links with geometry (`has_geometry`)
/// on different rigid bodies, less the `disabled` pairs (an SRDF's `<disable_collisions>`) or,
/// without them, less the links of adjacent bodies.
pub fn collision_pairs(
    tree: &KinematicTree,
    has_geometry: &dyn Fn(LinkId) -> bool,
    disabled: Option<&BTreeSet<(LinkId, LinkId)>>,
) -> CollisionPairs {
    let body = rigid_bodies(tree);
    let adjacent: BTreeSet<(usize, usize)> = tree
        .joints()
        .iter()
        .filter(|j| j.kind != crate::JointKind::Fixed)
        .map(|j| {
            let (a, b) = (body[j.parent.0], body[j.child.0]);
            (a.min(b), a.max(b))
        })
        .collect();
    let links: Vec<usize> = (0..tree.links().len()).filter(|&i| has_geometry(LinkId(i))).collect();
    let mut pairs = Vec::new();
    for (k, &a) in links.iter().enumerate() {
        for &b in &links[k + 1..] {
            let (ba, bb) = (body[a], body[b]);
            if ba == bb {
                continue;
            }
            let skip = match disabled {
                Some(disabled) => disabled.contains(&(LinkId(a), LinkId(b))),
                None => adjacent.contains(&(ba.min(bb), ba.max(bb))),
            };
            if !skip {
                pairs.push((LinkId(a), LinkId(b)));
            }
        }
    }
    CollisionPairs { pairs, rule: if disabled.is_some() { PairRule::Srdf } else { PairRule::Adjacent } }
}

/// [`collision_pairs`] of the links that carry `spheres` (a link whose geometry is all meshes
/// left out has none, and is in no pair).
pub fn sphere_pairs(
    tree: &KinematicTree,
    spheres: &[LinkSphere],
    disabled: Option<&BTreeSet<(LinkId, LinkId)>>,
) -> CollisionPairs {
    let with: BTreeSet<LinkId> = spheres.iter().map(|s| s.link).collect();
    collision_pairs(tree, &|l| with.contains(&l), disabled)
}

#[cfg(test)]
mod tests {

    use super::*;

    /// Points on the shape's surface, densely: a grid over each face or a fine lattice of
    /// directions.
    fn surface(shape: &Shape) -> Vec<[f64; 3]> {
        let n = 40;
        let t = |i: usize| -1.0 + 2.0 * i as f64 / n as f64;
        let mut out = Vec::new();
        match *shape {
            Shape::Box { size } => {
                let h = size.map(|s| s / 2.0);
                for axis in 0..3 {
                    for sign in [-1.0, 1.0] {
                        for i in 0..=n {
                            for j in 0..=n {
                                let mut p = [0.0; 3];
                                p[axis] = sign * h[axis];
                                p[(axis + 1) % 3] = t(i) * h[(axis + 1) % 3];
                                p[(axis + 2) % 3] = t(j) * h[(axis + 2) % 3];
                                out.push(p);
                            }
                        }
                    }
                }
            }
            Shape::Cylinder { radius, length } => {
                for i in 0..=n {
                    let a = std::f64::consts::PI * t(i);
                    for j in 0..=n {
                        out.push([radius * a.cos(), radius * a.sin(), t(j) * length / 2.0]);
                        let rho = radius * (j as f64 / n as f64);
                        out.push([rho * a.cos(), rho * a.sin(), length / 2.0]);
                        out.push([rho * a.cos(), rho * a.sin(), -length / 2.0]);
                    }
                }
            }
            Shape::Capsule { .. } | Shape::Sphere { .. } => {
                let (radius, length) = match *shape {
                    Shape::Capsule { radius, length } => (radius, length),
                    Shape::Sphere { radius } => (radius, 0.0),
                    _ => unreachable!(),
                };
                for i in 0..=n {
                    let polar = std::f64::consts::PI * (i as f64 / n as f64);
                    for j in 0..=n {
                        let a = std::f64::consts::PI * t(j);
                        let v = [polar.sin() * a.cos(), polar.sin() * a.sin(), polar.cos()];
                        let z = if v[2] >= 0.0 { length / 2.0 } else { -length / 2.0 };
                        out.push([radius * v[0], radius * v[1], z + radius * v[2]]);
                        out.push([radius * a.cos(), radius * a.sin(), t(i) * length / 2.0]);
                    }
                }
            }
            _ => {}
        }
        out
    }

    /// The cover holds every surface point (and the centre) and overshoots by at most `d`
    /// (checked on points of each sphere's surface).
    fn check(shape: Shape, d: f64) -> usize {
        let spheres = shape.cover(d).unwrap();
        for p in surface(&shape).into_iter().chain([[0.0; 3]]) {
            let inside =
                spheres.iter().any(|s| norm([0, 1, 2].map(|i| p[i] - s.center[i])) <= s.radius * (1.0 + 1e-12));
            assert!(inside, "{shape:?}: {p:?} is in no sphere");
        }
        for s in &spheres {
            for i in 0..=12 {
                let polar = std::f64::consts::PI * i as f64 / 12.0;
                for j in 0..24 {
                    let a = std::f64::consts::TAU * j as f64 / 24.0;
                    let v = [polar.sin() * a.cos(), polar.sin() * a.sin(), polar.cos()];
                    let p = [0, 1, 2].map(|k| s.center[k] + s.radius * v[k]);
                    let out = -shape.depth(p).unwrap();
                    assert!(out <= d * (1.0 + 1e-9), "{shape:?}: a sphere reaches {out} beyond the shape (cover {d})");
                }
            }
        }
        spheres.len()
    }

    #[test]
    fn covers_hold_every_point_within_their_overshoot() {
        for d in [0.005, 0.01, 0.03] {
            check(Shape::Sphere { radius: 0.1 }, d);
            check(Shape::Capsule { radius: 0.05, length: 0.3 }, d);
            check(Shape::Capsule { radius: 0.05, length: 0.0 }, d);
            check(Shape::Capsule { radius: 0.002, length: 0.5 }, d);
            check(Shape::Box { size: [0.2, 0.1, 0.05] }, d);
            check(Shape::Box { size: [0.5, 0.5, 0.01] }, d);
            check(Shape::Cylinder { radius: 0.06, length: 0.2 }, d);
            check(Shape::Cylinder { radius: 0.3, length: 0.02 }, d);
        }
    }

    #[test]
    fn a_coarser_cover_takes_fewer_spheres() {
        let box_ = Shape::Box { size: [0.2, 0.1, 0.1] };
        assert!(check(box_.clone(), 0.03) < check(box_, 0.01));
        let capsule = Shape::Capsule { radius: 0.05, length: 0.3 };
        // h = sqrt(2 * 0.05 * 0.01 + 0.01^2) = 0.0332: 0.3 / 0.0663 = 4.5, so 5 intervals, 6 centres.
        assert_eq!(capsule.cover(0.01).unwrap().len(), 6);
        assert_eq!(Shape::Sphere { radius: 1.0 }.cover(0.01).unwrap().len(), 1);
    }

    #[test]
    fn covers_are_deterministic() {
        let shape = Shape::Cylinder { radius: 0.06, length: 0.2 };
        assert_eq!(shape.cover(0.01), shape.cover(0.01));
        assert!(Shape::Mesh { filename: "a.stl".into(), scale: [1.0; 3] }.cover(0.01).is_none());
    }

    #[test]
    fn bad_sizes_are_named() {
        assert_eq!(
            Shape::Sphere { radius: -0.1 }.fault().as_deref(),
            Some("<sphere radius> is -0.1 (must be a finite positive length)")
        );
        assert_eq!(
            Shape::Box { size: [0.1, 0.0, 0.1] }.fault().as_deref(),
            Some("<box size y> is 0 (must be a finite positive length)")
        );
        assert!(Shape::Cylinder { radius: 0.1, length: f64::NAN }.fault().is_some());
        assert!(Shape::Capsule { radius: 0.1, length: 0.0 }.fault().is_none());
        assert!(Shape::Capsule { radius: 0.1, length: -1.0 }.fault().is_some());
        assert!(Shape::Mesh { filename: "a".into(), scale: [1.0, 0.0, 1.0] }.fault().is_some());
    }
}
