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
//! **The cover** ([`cover`]): every element of a link (meshes and primitives alike) cut into small
//! convex pieces, grouped under a few spheres that hold every piece whole, by construction; a
//! budget of spheres per link, an overshoot, or both decide how many.
//!
//! **What is here.** `Shape` (sphere, box, cylinder, capsule, ellipsoid, mesh, placed by its
//! origin) is read by the URDF and MJCF readers and the urdf-rs conversion alike, its sizes
//! checked by validation naming the link and the line; a mesh's triangles come from the caller
//! ([`KinematicTree::load_meshes`]: the model reads no files); `link_spheres` gives every sphere
//! of a robot in one fixed order; `rigid_bodies` and `collision_pairs` are the pair rule. Each
//! link's bounding sphere is the compiler's (`collision_layout`).

pub mod cover;
pub mod fixed;
pub mod grid;
pub mod mesh;
mod vec3;

use std::collections::BTreeSet;
use std::sync::Arc;

pub use cover::{Cover, CoverFault, CoverReport, DEFAULT_OVERSHOOT, DEFAULT_SPHERES, LinkCover, MAX_SPHERES_PER_LINK};
pub use fixed::{FixedPair, ON_AXIS, fixed_apart_pairs};
pub use grid::{CellState, PairGrid, pair_grids};
pub use mesh::{MeshFault, TriangleMesh};

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
    /// An ellipsoid of semi-axes `radii` along x, y, z, centred (MJCF's `ellipsoid`).
    Ellipsoid {
        /// Semi-axes (m).
        radii: [f64; 3],
    },
    /// `<mesh filename scale>`: its triangles once the caller has read the file
    /// ([`KinematicTree::load_meshes`]).
    Mesh {
        /// The file as written.
        filename: String,
        /// Scale along x, y, z.
        scale: [f64; 3],
        /// The triangles in the file's units (the scale not applied), once read.
        loaded: Option<Arc<TriangleMesh>>,
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
            Shape::Ellipsoid { .. } => "ellipsoid",
            Shape::Mesh { .. } => "mesh",
        }
    }

    /// What is wrong with its sizes, if anything: every length must be finite and positive (a
    /// capsule's length may be zero: a sphere), a mesh's scale finite and positive (a mirrored
    /// mesh is refused: its triangles' winding, and so its inside, would turn over).
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
            Shape::Ellipsoid { radii } => {
                ["x", "y", "z"].iter().zip(radii).find_map(|(axis, &x)| length(&format!("size {axis}"), x, false))
            }
            Shape::Mesh { scale, .. } => scale
                .iter()
                .any(|s| !(s.is_finite() && *s > 0.0))
                .then(|| format!("<mesh scale> is {scale:?} (must be finite and positive)")),
        }
    }

    /// How far `p` (in the shape's frame) lies inside the shape: positive inside, negative
    /// outside, the distance to the surface either way for a sphere, capsule and (outside) box;
    /// for a box inside and a cylinder anywhere a lower bound where exactness costs more, and for
    /// an ellipsoid a lower bound everywhere (what the cover's overshoot bound and the tests
    /// need). `None` for a mesh (its depth is [`mesh::PlacedTriangles::depth`]).
    pub fn depth(&self, p: [f64; 3]) -> Option<f64> {
        Some(match *self {
            Shape::Sphere { radius } => radius - norm(p),
            Shape::Capsule { radius, length } => {
                let z = p[2].clamp(-length / 2.0, length / 2.0);
                radius - norm([p[0], p[1], p[2] - z])
            }
            Shape::Box { size } => box_depth(size.map(|s| s / 2.0), p),
            Shape::Cylinder { radius, length } => cylinder_depth(radius, length / 2.0, p),
            Shape::Ellipsoid { radii } => ellipsoid_depth(radii, p),
            Shape::Mesh { .. } => return None,
        })
    }
}

/// A lower bound of how deep `p` lies in the centred ellipsoid of semi-axes `radii`: with `u` the
/// point in the unit ball's coordinates (`p / radii`), inside, the ball of radius `1 - |u|` about
/// `u` lies in the unit ball, and the map back shrinks it by at most the least semi-axis; outside,
/// the point `p / |u|` lies on the ellipsoid, `|p| (1 - 1 / |u|)` away.
fn ellipsoid_depth(radii: [f64; 3], p: [f64; 3]) -> f64 {
    let u = norm([0, 1, 2].map(|i| p[i] / radii[i]));
    if u <= 1.0 { (1.0 - u) * radii[0].min(radii[1]).min(radii[2]) } else { -norm(p) * (1.0 - 1.0 / u) }
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

/// What to do with mesh geometry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Meshes {
    /// Meshes are covered like any geometry (the default); one whose file was not read is an
    /// error naming its link and file.
    #[default]
    Read,
    /// Meshes are left out (the robot's other geometry is checked; a spherized URDF has none).
    Skip,
}

/// One sphere of a robot's cover: its link, and the sphere in the link's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkSphere {
    /// The link.
    pub link: LinkId,
    /// The sphere, in the link's frame.
    pub sphere: Sphere,
}

/// A link whose geometry could not be covered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("link `{link}`: {fault}")]
pub struct CoverError {
    /// The link.
    pub link: String,
    /// What went wrong.
    pub fault: CoverFault,
}

/// Every sphere of `tree`'s collision geometry under `cover` (which must have no
/// [`Cover::fault`]): links in tree order, each link's spheres in the cover's order. This order is
/// the robot's sphere order everywhere (generated code, the reference).
pub fn link_spheres(tree: &KinematicTree, cover: &Cover, meshes: Meshes) -> Result<Vec<LinkSphere>, CoverError> {
    let mut out = Vec::new();
    for (i, link) in link_covers(tree, cover, meshes)? {
        out.extend(link.spheres.into_iter().map(|sphere| LinkSphere { link: i, sphere }));
    }
    Ok(out)
}

/// Each link's cover, for the links with geometry (in tree order).
pub fn link_covers(
    tree: &KinematicTree,
    cover: &Cover,
    meshes: Meshes,
) -> Result<Vec<(LinkId, LinkCover)>, CoverError> {
    let mut out = Vec::new();
    for (i, link) in tree.links().iter().enumerate() {
        let fault = |fault| CoverError { link: link.name.clone(), fault };
        let mut geometry = cover::Geometry::new(&link.collisions, meshes == Meshes::Skip).map_err(fault)?;
        if let Some(c) = cover::cover_link(&mut geometry, cover).map_err(fault)? {
            out.push((LinkId(i), c));
        }
    }
    Ok(out)
}

/// What `cover` (one link's, from [`link_covers`]) costs against the link's geometry: its
/// overshoot (the bound and a sampled measure) and its volume against the geometry's.
/// A mesh not read is the error, as [`link_covers`] gives it.
pub fn cover_report(
    tree: &KinematicTree,
    link: LinkId,
    cover: &LinkCover,
    meshes: Meshes,
) -> Result<CoverReport, CoverError> {
    let link = tree.link(link);
    let geometry = cover::Geometry::new(&link.collisions, meshes == Meshes::Skip)
        .map_err(|fault| CoverError { link: link.name.clone(), fault })?;
    Ok(cover::report(&geometry, cover))
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
/// without them, less the links of adjacent bodies; and either way less the pairs the
/// description itself rules out ([`KinematicTree::excluded_pairs`]: an MJCF
/// `<contact><exclude>`, or geoms whose `contype` and `conaffinity` never meet).
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
    let excluded = tree.excluded_link_pairs();
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
            if !skip && !excluded.contains(&(LinkId(a), LinkId(b))) {
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
        assert!(Shape::Ellipsoid { radii: [0.1, 0.0, 0.1] }.fault().is_some());
        for scale in [[1.0, 0.0, 1.0], [1.0, -1.0, 1.0], [f64::NAN, 1.0, 1.0]] {
            let mesh = Shape::Mesh { filename: "a".into(), scale, loaded: None };
            assert!(mesh.fault().is_some(), "{scale:?}");
        }
    }

    #[test]
    fn the_ellipsoid_depth_bounds_hold() {
        let radii = [0.3, 0.2, 0.1];
        let shape = Shape::Ellipsoid { radii };
        assert!((shape.depth([0.0; 3]).unwrap() - 0.1).abs() < 1e-15);
        // On the surface: zero; outside along an axis: the exact distance.
        assert!(shape.depth([0.3, 0.0, 0.0]).unwrap().abs() < 1e-15);
        assert!((shape.depth([0.0, 0.5, 0.0]).unwrap() + 0.3).abs() < 1e-15);
    }
}
