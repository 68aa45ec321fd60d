//! The sphere cover: a link's collision geometry (meshes and primitives alike) made into a few
//! spheres that contain all of it, by construction.
//!
//! **Pieces.** Each element of a link is cut into small convex pieces, each known by a few points
//! and balls whose convex hull contains it: a mesh's triangles (their corners); a box's cells
//! (their corners); a cylinder's wedges (the axis at both ends, the arc's ends, and where the
//! arc's end tangents meet); a capsule's slices (the balls at both ends of the slice: their hull
//! is the slice); an ellipsoid's cells of its bounding box that reach it (their corners); a
//! sphere (itself). A sphere that contains a piece's points and balls contains its hull, since a
//! ball is convex; so a sphere made to hold every point and ball of some pieces holds those pieces
//! whole. That is the whole of the guarantee, and it holds whatever centre is chosen: the radius
//! is the farthest point's distance, measured, not estimated.
//!
//! **Groups.** The link's pieces start as one group under one sphere (the smallest ball about the
//! pieces' points and ball centres, by Welzl's move-to-front algorithm, then widened to reach
//! every ball). Each sphere's *overshoot bound* is `R - depth(c)`: every point of the sphere lies
//! within `R` of its centre `c`, and the ball of radius `depth(c)` about `c` lies inside the
//! geometry, so no point of the sphere is farther than `R - depth(c)` from the geometry (where
//! `c` lies outside, `depth` is minus its distance). The group with the largest bound is split in
//! two (the best of halving its pieces across the three axes and its longest diameter, then
//! refined by two-means), until the link has its budget of spheres, or every bound is within the
//! overshoot asked for, whichever comes first. A group of one piece has the piece cut smaller
//! first (a triangle into four, a cell or slice into two), so any overshoot can be reached.
//! Everything is in a fixed order: the same geometry gives the same spheres on every run.
//!
//! **What is covered.** Every point of every primitive (the solid), and every point of every
//! triangle of a mesh (the surface; for a closed mesh the solid follows unless an obstacle lies
//! wholly inside the link). Spheres written as `<sphere>` are kept as they are where a link has
//! nothing else.

use std::collections::{BTreeMap, BTreeSet};

use super::mesh::PlacedTriangles;
use super::vec3::{add, cross, distance, dot, norm, scale, sub};
use super::{Collision, Shape, Sphere};

/// How a link's geometry becomes spheres: a budget, an overshoot, or both (whichever is reached
/// first ends the cover). At least one is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cover {
    /// At most this many spheres per link (`spheres`; at least one).
    pub spheres: Option<usize>,
    /// Stop splitting once no sphere's overshoot bound exceeds this (`sphere_cover`, metres).
    pub overshoot: Option<f64>,
}

/// The sphere budget per link when neither is given.
pub const DEFAULT_SPHERES: usize = 10;

/// The overshoot at which the default cover stops before its budget: 1 cm.
pub const DEFAULT_OVERSHOOT: f64 = 0.01;

/// The most spheres a link's cover may take when only an overshoot is given: past it the
/// overshoot is refused as out of reach, not quietly exceeded.
pub const MAX_SPHERES_PER_LINK: usize = 1000;

impl Default for Cover {
    fn default() -> Self {
        Cover { spheres: Some(DEFAULT_SPHERES), overshoot: Some(DEFAULT_OVERSHOOT) }
    }
}

impl Cover {
    /// A budget of `n` spheres per link, with the least overshoot the method finds.
    pub fn spheres(n: usize) -> Self {
        Cover { spheres: Some(n), overshoot: None }
    }

    /// The fewest spheres the method finds with no overshoot beyond `d` metres.
    pub fn overshoot(d: f64) -> Self {
        Cover { spheres: None, overshoot: Some(d) }
    }

    /// What is wrong with it, if anything: a budget of zero, an overshoot that is not a finite
    /// positive length, or neither given.
    pub fn fault(&self) -> Option<String> {
        match (self.spheres, self.overshoot) {
            (None, None) => Some("give a sphere budget (`spheres`) or an overshoot (`sphere_cover`)".into()),
            (Some(0), _) => Some("`spheres` is 0 (must be at least 1)".into()),
            (_, Some(d)) if !(d.is_finite() && d > 0.0) => {
                Some(format!("`sphere_cover` is {d} (must be a finite positive length in metres)"))
            }
            _ => None,
        }
    }
}

/// One link's cover: its spheres in the link's frame and each one's overshoot bound.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkCover {
    /// The spheres, in the link's frame.
    pub spheres: Vec<Sphere>,
    /// Each sphere's overshoot bound (metres): no point of it lies farther from the geometry.
    pub bounds: Vec<f64>,
}

/// Why a link's geometry could not be covered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CoverFault {
    /// A mesh whose triangles were not loaded.
    #[error("<collision> is a mesh (`{0}`) whose file was not read")]
    MeshNotLoaded(String),
    /// The overshoot needs more spheres than [`MAX_SPHERES_PER_LINK`].
    #[error(
        "`sphere_cover` {overshoot} needs more than {MAX_SPHERES_PER_LINK} spheres on this link (at {MAX_SPHERES_PER_LINK} the largest overshoot is {reached:.4} m): give a larger `sphere_cover` or a budget `spheres`"
    )]
    TooManySpheres {
        /// The overshoot asked for.
        overshoot: f64,
        /// The largest bound at the cap.
        reached: f64,
    },
}

/// A link's geometry as the cover reads it: each element's origin, and the queries of how deep a
/// point lies.
pub(crate) struct Geometry<'a> {
    elements: &'a [Collision],
    /// Each mesh element's triangles in the link's frame (`None` for a primitive).
    meshes: Vec<Option<PlacedTriangles>>,
    /// The centre of the smallest ball about the whole link (set once its pieces are cut).
    core: [f64; 3],
    /// Cylinders that are capsules as written ([`Geometry::written_capsules`]), with the radius of
    /// a capsule inside the three elements and of one holding them.
    capsules: BTreeMap<usize, WrittenCapsule>,
    /// The end spheres those capsules absorb.
    absorbed: BTreeSet<usize>,
}

impl<'a> Geometry<'a> {
    /// The geometry of `elements`, meshes left out where `skip_meshes` (an unloaded mesh is an
    /// error otherwise).
    pub(crate) fn new(elements: &'a [Collision], skip_meshes: bool) -> Result<Self, CoverFault> {
        let mut meshes = Vec::with_capacity(elements.len());
        for e in elements {
            meshes.push(match &e.shape {
                Shape::Mesh { loaded: Some(mesh), scale: s, .. } if !skip_meshes => Some(PlacedTriangles::new(
                    mesh.corners()
                        .map(|t| t.map(|v| e.origin.apply([v[0] * s[0], v[1] * s[1], v[2] * s[2]])))
                        .collect(),
                )),
                Shape::Mesh { filename, .. } if !skip_meshes => {
                    return Err(CoverFault::MeshNotLoaded(filename.clone()));
                }
                _ => None,
            });
        }
        let mut geometry =
            Geometry { elements, meshes, core: [0.0; 3], capsules: BTreeMap::new(), absorbed: BTreeSet::new() };
        (geometry.capsules, geometry.absorbed) = geometry.written_capsules();
        Ok(geometry)
    }

    /// Whether an element takes part (a mesh left out does not).
    fn takes_part(&self, k: usize) -> bool {
        !matches!(self.elements[k].shape, Shape::Mesh { .. }) || self.meshes[k].is_some()
    }

    /// A lower bound of how deep `p` (in the link's frame) lies in the union of the elements:
    /// the deepest of the elements' own depths (exact for meshes, spheres, capsules, boxes and
    /// cylinders outside; a lower bound inside a box or cylinder and for an ellipsoid).
    pub(crate) fn depth(&self, p: [f64; 3]) -> f64 {
        let mut deepest = f64::NEG_INFINITY;
        for (k, e) in self.elements.iter().enumerate() {
            let d = match &self.meshes[k] {
                Some(mesh) => mesh.depth(p),
                // A written capsule's depth, of the capsule inside its three elements.
                None if self.capsules.contains_key(&k) => {
                    #[allow(clippy::expect_used, reason = "invariant: a capsule's depth is defined")]
                    let d = self.capsules[&k].inner.depth(e.origin.apply_inverse(p)).expect("a capsule's depth");
                    d
                }
                None if self.takes_part(k) => {
                    #[allow(clippy::expect_used, reason = "invariant: only a mesh has no depth, and meshes are `Some`")]
                    let d = e.shape.depth(e.origin.apply_inverse(p)).expect("a primitive's depth is defined");
                    d
                }
                None => continue,
            };
            deepest = deepest.max(d);
        }
        deepest
    }

    /// The sum of the elements' volumes (a closed mesh's enclosed volume; overlaps counted twice).
    pub(crate) fn volume(&self) -> f64 {
        use std::f64::consts::PI;
        (0..self.elements.len())
            .filter(|&k| self.takes_part(k))
            .map(|k| match (&self.elements[k].shape, &self.meshes[k]) {
                (_, Some(mesh)) => mesh.volume(),
                (Shape::Sphere { radius }, _) => 4.0 / 3.0 * PI * radius.powi(3),
                (Shape::Box { size }, _) => size[0] * size[1] * size[2],
                (Shape::Cylinder { radius, length }, _) => PI * radius * radius * length,
                (Shape::Capsule { radius, length }, _) => PI * radius * radius * (length + 4.0 / 3.0 * radius),
                (Shape::Ellipsoid { radii }, _) => 4.0 / 3.0 * PI * radii[0] * radii[1] * radii[2],
                (Shape::Mesh { .. }, None) => 0.0,
            })
            .sum()
    }

    /// The pieces every element is cut into at first.
    fn pieces(&self) -> Vec<Piece> {
        let (capsules, absorbed) = (&self.capsules, &self.absorbed);
        let mut out = Vec::new();
        for (k, e) in self.elements.iter().enumerate() {
            if let Some(mesh) = &self.meshes[k] {
                out.extend(mesh.triangles().iter().map(|t| Piece::Triangle(*t)));
                continue;
            }
            if absorbed.contains(&k) {
                continue;
            }
            let shape = capsules.get(&k).map_or_else(|| e.shape.clone(), |c| c.outer.clone());
            match shape {
                Shape::Sphere { radius } => out.push(Piece::Ball { center: e.origin.apply([0.0; 3]), radius }),
                Shape::Capsule { radius, length } => {
                    let n = slices(length, radius / 2.0);
                    out.extend((0..n).map(|i| Piece::CapsulePart {
                        radius,
                        z: (fraction(-length / 2.0, length, i, n), fraction(-length / 2.0, length, i + 1, n)),
                        element: k,
                    }));
                }
                Shape::Cylinder { radius, length } => {
                    let n = slices(length, radius / 2.0);
                    for i in 0..n {
                        for w in 0..WEDGES {
                            let tau = std::f64::consts::TAU;
                            out.push(Piece::Wedge {
                                radii: (0.0, radius),
                                angles: (fraction(0.0, tau, w, WEDGES), fraction(0.0, tau, w + 1, WEDGES)),
                                z: (fraction(-length / 2.0, length, i, n), fraction(-length / 2.0, length, i + 1, n)),
                                element: k,
                            });
                        }
                    }
                }
                Shape::Box { size } => {
                    let smallest = size[0].min(size[1]).min(size[2]);
                    let n = size.map(|s| slices(s, smallest / 2.0).min(16));
                    cells(&mut out, size.map(|s| s / 2.0), n, k, Clip::Box);
                }
                Shape::Ellipsoid { radii } => cells(&mut out, radii, [8; 3], k, Clip::Ellipsoid(radii)),
                Shape::Mesh { .. } => {}
            }
        }
        out
    }
}

impl Geometry<'_> {
    /// Capsules written the way URDF must write them, a `<cylinder>` and a `<sphere>` of its
    /// radius centred on each end (franka_description's self-collision model): each such cylinder
    /// with two capsule radii, and the spheres it absorbs. Where the spheres' radii and centres
    /// differ from the cylinder's (by at most [`WRITTEN_CAPSULE`]), the outer capsule grows by the
    /// difference, so it holds the three elements whole, and the inner one shrinks by it, so the
    /// elements hold it: its pieces are cut along the segment, as a capsule's are, rather than
    /// into wedges and two uncut balls, and depths are the inner capsule's (lower bounds).
    fn written_capsules(&self) -> (BTreeMap<usize, WrittenCapsule>, BTreeSet<usize>) {
        let (mut capsules, mut absorbed) = (BTreeMap::new(), BTreeSet::new());
        for (k, e) in self.elements.iter().enumerate() {
            let Shape::Cylinder { radius, length } = e.shape else { continue };
            let (mut shrunk, mut grown) = (radius, radius);
            let mut ends = Vec::new();
            for z in [-length / 2.0, length / 2.0] {
                let end = e.origin.apply([0.0, 0.0, z]);
                let found = self.elements.iter().enumerate().find_map(|(i, s)| match s.shape {
                    Shape::Sphere { radius: r } if !absorbed.contains(&i) && !ends.contains(&i) => {
                        let off = distance(s.origin.apply([0.0; 3]), end);
                        (off <= WRITTEN_CAPSULE && (r - radius).abs() <= WRITTEN_CAPSULE).then_some((i, r, off))
                    }
                    _ => None,
                });
                let Some((i, r, off)) = found else { break };
                ends.push(i);
                grown = grown.max(r + off);
                shrunk = shrunk.min(r - off);
            }
            if let [a, b] = ends[..] {
                let (inner, outer) =
                    (Shape::Capsule { radius: shrunk, length }, Shape::Capsule { radius: grown, length });
                capsules.insert(k, WrittenCapsule { inner, outer });
                absorbed.extend([a, b]);
            }
        }
        (capsules, absorbed)
    }
}

/// Corners of the polygon about a capsule slice's cut face: they lie `1 / cos(pi / 32) - 1`,
/// half a percent of the radius, beyond the circle.
const RING: usize = 32;

/// A capsule written as a cylinder and two end spheres: one capsule its elements hold (for depths)
/// and one that holds them (for pieces).
struct WrittenCapsule {
    inner: Shape,
    outer: Shape,
}

/// How far (m) a written capsule's end sphere may lie from the cylinder's end, or its radius
/// differ from the cylinder's, and still be read as one capsule (the capsule grows by it).
const WRITTEN_CAPSULE: f64 = 1e-9;

/// Wedges a cylinder's slice is cut into at first: the arc's tangent corners then lie
/// `1 / cos(pi / 32) - 1`, half a percent, beyond the radius.
const WEDGES: usize = 32;

/// How many slices of at most `step` a length takes (at least one, at most 64).
fn slices(length: f64, step: f64) -> usize {
    // Finite positive sizes (validated); `as` saturates.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let n = (length / step).ceil() as usize;
    n.clamp(1, 64)
}

/// The `i`-th of `n` even steps of `length` from `start`.
fn fraction(start: f64, length: f64, i: usize, n: usize) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let t = i as f64 / n as f64;
    start + length * t
}

/// The cells of an `n` grid over the box of half-extents `half`, those that reach the shape.
fn cells(out: &mut Vec<Piece>, half: [f64; 3], n: [usize; 3], element: usize, clip: Clip) {
    for i in 0..n[0] {
        for j in 0..n[1] {
            for k in 0..n[2] {
                let idx = [i, j, k];
                let lo = [0, 1, 2].map(|a| fraction(-half[a], 2.0 * half[a], idx[a], n[a]));
                let hi = [0, 1, 2].map(|a| fraction(-half[a], 2.0 * half[a], idx[a] + 1, n[a]));
                if clip.reaches(lo, hi) {
                    out.push(Piece::Cell { lo, hi, element, clip });
                }
            }
        }
    }
}

/// Which shape a cell is cut from (a cell of an ellipsoid may reach past it).
#[derive(Debug, Clone, Copy)]
enum Clip {
    Box,
    Ellipsoid([f64; 3]),
}

impl Clip {
    /// Whether the cell `[lo, hi]` reaches the shape.
    fn reaches(self, lo: [f64; 3], hi: [f64; 3]) -> bool {
        match self {
            Clip::Box => true,
            Clip::Ellipsoid(r) => {
                // The cell's point nearest the centre, in the unit ball's coordinates.
                let q = [0, 1, 2].map(|a| 0.0_f64.clamp(lo[a], hi[a]) / r[a]);
                dot(q, q) <= 1.0
            }
        }
    }
}

/// A piece of a link's geometry: element-frame pieces name their element, whose origin places
/// them in the link's frame.
#[derive(Debug, Clone, Copy)]
enum Piece {
    /// A mesh triangle, in the link's frame.
    Triangle([[f64; 3]; 3]),
    /// A cell of a box or an ellipsoid's bounding box.
    Cell { lo: [f64; 3], hi: [f64; 3], element: usize, clip: Clip },
    /// The part of a cylinder between two radii, two angles and two heights.
    Wedge { radii: (f64, f64), angles: (f64, f64), z: (f64, f64), element: usize },
    /// The part of a capsule between two heights of its segment.
    CapsulePart { radius: f64, z: (f64, f64), element: usize },
    /// A `<sphere>`, in the link's frame.
    Ball { center: [f64; 3], radius: f64 },
}

impl Piece {
    /// Points and balls (in the link's frame) whose convex hull contains the piece.
    fn support(&self, elements: &[Collision], points: &mut Vec<[f64; 3]>, balls: &mut Vec<([f64; 3], f64)>) {
        match *self {
            Piece::Triangle(t) => points.extend(t),
            Piece::Cell { lo, hi, element, .. } => {
                let origin = &elements[element].origin;
                points.extend(
                    (0..8).map(|i| origin.apply([0, 1, 2].map(|a| if (i >> a) & 1 == 1 { hi[a] } else { lo[a] }))),
                );
            }
            Piece::Wedge { radii: (inner, outer), angles: (a0, a1), z: (z0, z1), element } => {
                // The inner arc bulges away from its chord, towards the outer one: its ends
                // suffice. The outer arc lies within its ends and where their tangents meet.
                let origin = &elements[element].origin;
                let half = (a1 - a0) / 2.0;
                let corner = outer / half.cos();
                let arc = [(a0, inner), (a1, inner), (a0, outer), (a1, outer), (a0 + half, corner)];
                for z in [z0, z1] {
                    points.extend(arc.iter().map(|&(a, r)| origin.apply([r * a.cos(), r * a.sin(), z])));
                }
            }
            Piece::CapsulePart { radius, z: (z0, z1), element } => {
                // Between its ends a capsule is a cylinder: a slice's cut faces are discs, held
                // by the polygon about each; only at the capsule's own ends is there a cap, the
                // ball about the end.
                let e = &elements[element];
                let half = match e.shape {
                    Shape::Capsule { length, .. } | Shape::Cylinder { length, .. } => length / 2.0,
                    _ => f64::INFINITY,
                };
                let corner = radius / (std::f64::consts::PI / RING as f64).cos();
                for z in [z0, z1] {
                    if z <= -half || z >= half {
                        balls.push((e.origin.apply([0.0, 0.0, z]), radius));
                    } else {
                        points.extend((0..RING).map(|i| {
                            let a = std::f64::consts::TAU * i as f64 / RING as f64;
                            e.origin.apply([corner * a.cos(), corner * a.sin(), z])
                        }));
                    }
                }
            }
            Piece::Ball { center, radius } => balls.push((center, radius)),
        }
    }

    /// The piece's length, the one its cuts shrink: a triangle's longest edge, a cell's longest
    /// side, a wedge's height or arc, a capsule slice's height; zero for a ball.
    fn length(&self) -> f64 {
        match *self {
            Piece::Triangle([a, b, c]) => distance(a, b).max(distance(b, c)).max(distance(c, a)),
            Piece::Cell { lo, hi, .. } => (0..3).map(|a| hi[a] - lo[a]).fold(0.0, f64::max),
            Piece::Wedge { radii: (inner, outer), angles: (a0, a1), z: (z0, z1), .. } => {
                (z1 - z0).max(outer * (a1 - a0)).max(outer - inner)
            }
            Piece::CapsulePart { z: (z0, z1), .. } => z1 - z0,
            Piece::Ball { .. } => 0.0,
        }
    }

    /// The piece cut in smaller pieces that together hold it, or `None` where it is as small as it
    /// gets (a ball, a capsule's end).
    fn split(&self) -> Option<Vec<Piece>> {
        Some(match *self {
            Piece::Triangle([a, b, c]) => {
                let mid = |p: [f64; 3], q: [f64; 3]| scale(add(p, q), 0.5);
                let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
                vec![
                    Piece::Triangle([a, ab, ca]),
                    Piece::Triangle([ab, b, bc]),
                    Piece::Triangle([ca, bc, c]),
                    Piece::Triangle([ab, bc, ca]),
                ]
            }
            Piece::Cell { lo, hi, element, clip } => {
                let axis = (0..3).fold(0, |best, a| if hi[a] - lo[a] > hi[best] - lo[best] { a } else { best });
                let mid = (lo[axis] + hi[axis]) / 2.0;
                let (mut upper_lo, mut lower_hi) = (lo, hi);
                upper_lo[axis] = mid;
                lower_hi[axis] = mid;
                [(lo, lower_hi), (upper_lo, hi)]
                    .into_iter()
                    .filter(|&(l, h)| clip.reaches(l, h))
                    .map(|(lo, hi)| Piece::Cell { lo, hi, element, clip })
                    .collect()
            }
            Piece::Wedge { radii: (inner, outer), angles: (a0, a1), z: (z0, z1), element } => {
                let wedge = |radii, angles, z| Piece::Wedge { radii, angles, z, element };
                let (height, arc, depth) = (z1 - z0, outer * (a1 - a0), outer - inner);
                if height >= arc && height >= depth {
                    let m = (z0 + z1) / 2.0;
                    vec![wedge((inner, outer), (a0, a1), (z0, m)), wedge((inner, outer), (a0, a1), (m, z1))]
                } else if arc >= depth {
                    let m = (a0 + a1) / 2.0;
                    vec![wedge((inner, outer), (a0, m), (z0, z1)), wedge((inner, outer), (m, a1), (z0, z1))]
                } else {
                    let m = (inner + outer) / 2.0;
                    vec![wedge((inner, m), (a0, a1), (z0, z1)), wedge((m, outer), (a0, a1), (z0, z1))]
                }
            }
            Piece::CapsulePart { radius, z: (z0, z1), element } => {
                if z1 <= z0 {
                    return None;
                }
                let m = (z0 + z1) / 2.0;
                vec![
                    Piece::CapsulePart { radius, z: (z0, m), element },
                    Piece::CapsulePart { radius, z: (m, z1), element },
                ]
            }
            Piece::Ball { .. } => return None,
        })
    }
}

/// Pieces under one sphere.
struct Group {
    pieces: Vec<usize>,
    sphere: Sphere,
    bound: f64,
    /// No split of it was found (all its pieces alike and none cut smaller): left as it is.
    settled: bool,
}

/// The cover of one link's `elements` (see the module doc); `None` when nothing takes part.
pub(crate) fn cover_link(geometry: &mut Geometry<'_>, cover: &Cover) -> Result<Option<LinkCover>, CoverFault> {
    let mut pieces = geometry.pieces();
    if pieces.is_empty() {
        return Ok(None);
    }
    if pieces.iter().all(|p| matches!(p, Piece::Ball { .. })) {
        // Spheres alone: kept as written.
        let spheres: Vec<Sphere> = pieces
            .iter()
            .map(|p| match *p {
                Piece::Ball { center, radius } => Sphere { center, radius },
                _ => unreachable!("every piece is a ball"),
            })
            .collect();
        let bounds = vec![0.0; spheres.len()];
        return Ok(Some(LinkCover { spheres, bounds }));
    }
    // No piece longer than an eighth of the link's size: a group's sphere then follows its
    // pieces, not a long triangle's or a whole box's extent.
    let all: Vec<usize> = (0..pieces.len()).collect();
    let whole = enclose(geometry.elements, &pieces, &all);
    geometry.core = whole.center;
    let whole = whole.radius;
    let geometry = &*geometry;
    let all = cut_larger_than(&mut pieces, all, whole / 4.0);
    let mut groups = vec![group(geometry, &pieces, all)];
    loop {
        let by_bound = |settled: bool| {
            (0..groups.len()).filter(|&g| settled || !groups[g].settled).fold(None, |best: Option<usize>, g| match best
            {
                Some(b) if groups[b].bound >= groups[g].bound => Some(b),
                _ => Some(g),
            })
        };
        #[allow(clippy::expect_used, reason = "invariant: groups start with one and only grow")]
        let worst = by_bound(true).expect("a cover has a group");
        let bound = groups[worst].bound;
        if cover.spheres.is_some_and(|n| groups.len() >= n) || cover.overshoot.is_some_and(|d| bound <= d) {
            break;
        }
        if cover.spheres.is_none() && (groups.len() >= MAX_SPHERES_PER_LINK || groups[worst].settled) {
            return Err(CoverFault::TooManySpheres { overshoot: cover.overshoot.unwrap_or(0.0), reached: bound });
        }
        // Under a budget, a group no split improves is left; the next worst is split instead.
        let Some(next) = by_bound(false) else { break };
        let members = std::mem::take(&mut groups[next].pieces);
        match split(geometry, &mut pieces, members, groups[next].sphere.radius) {
            Ok((a, b)) => {
                groups[next] = group(geometry, &pieces, a);
                groups.push(group(geometry, &pieces, b));
            }
            Err(members) => {
                groups[next].pieces = members;
                groups[next].settled = true;
            }
        }
    }
    let bounds = groups.iter().map(|g| g.bound).collect();
    Ok(Some(LinkCover { spheres: groups.into_iter().map(|g| g.sphere).collect(), bounds }))
}

/// `members` with every piece longer than `limit` cut until none is (each cut halves a piece's
/// length at least), in a fixed order.
fn cut_larger_than(pieces: &mut Vec<Piece>, members: Vec<usize>, limit: f64) -> Vec<usize> {
    let mut out = Vec::with_capacity(members.len());
    let mut todo = members;
    todo.reverse();
    while let Some(m) = todo.pop() {
        if pieces[m].length() <= limit {
            out.push(m);
            continue;
        }
        match pieces[m].split() {
            Some(parts) => {
                pieces[m] = parts[0];
                let mut ids = vec![m];
                for part in &parts[1..] {
                    ids.push(pieces.len());
                    pieces.push(*part);
                }
                todo.extend(ids.into_iter().rev());
            }
            None => out.push(m),
        }
    }
    out
}

/// The group of `members` under its sphere, with its bound.
/// Its centre is the smallest ball's moved inwards where that lowers the bound (see [`deeper`]).
fn group(geometry: &Geometry<'_>, pieces: &[Piece], members: Vec<usize>) -> Group {
    let support = Support::gather(geometry.elements, pieces, &members);
    let (sphere, bound) = deeper(geometry, pieces, &members, &support, support.smallest_sphere());
    Group { pieces: members, sphere, bound, settled: false }
}

/// [`group`] without the search for a deeper centre: what the halvings are ranked by.
fn quick_bound(geometry: &Geometry<'_>, pieces: &[Piece], members: &[usize]) -> f64 {
    let sphere = enclose(geometry.elements, pieces, members);
    sphere.radius - geometry.depth(sphere.center)
}

/// The sphere about `members` whose centre gives the least bound among the smallest ball's and
/// points moved from it inwards: a patch of surface is held with less overshoot by a larger
/// sphere centred deeper (a flat patch of radius `a` by one at depth `e` with overshoot
/// `sqrt(a^2 + e^2) - e`). The directions tried are both ways along the patch's mean normal (its
/// triangles' area-weighted normals) and towards the centre of the whole link; the steps are
/// fractions and multiples of the radius. The radius is measured again at each centre, so every
/// candidate holds the pieces.
fn deeper(
    geometry: &Geometry<'_>,
    pieces: &[Piece],
    members: &[usize],
    support: &Support,
    first: Sphere,
) -> (Sphere, f64) {
    let mut normal = [0.0; 3];
    for &m in members {
        if let Piece::Triangle([a, b, c]) = pieces[m] {
            normal = add(normal, cross(sub(b, a), sub(c, a)));
        }
    }
    let reach = |c: [f64; 3]| support.reach(c);
    let mut best = (first, first.radius - geometry.depth(first.center));
    let mut directions = Vec::new();
    if norm(normal) > 0.0 {
        let n = scale(normal, 1.0 / norm(normal));
        directions.extend([n, scale(n, -1.0)]);
    }
    let to_core = sub(geometry.core, first.center);
    if norm(to_core) > 0.0 {
        directions.push(scale(to_core, 1.0 / norm(to_core)));
    }
    for direction in directions {
        for step in [0.125, 0.25, 0.5, 1.0, 2.0] {
            let center = add(first.center, scale(direction, step * first.radius));
            let radius = reach(center);
            let bound = radius - geometry.depth(center);
            if bound < best.1 {
                best = (Sphere { center, radius }, bound);
            }
        }
    }
    // Then a pattern search about the best: a step along each axis either way, halved when none
    // helps (an edge's patch is best held from off the middle, which no direction above finds).
    let mut step = first.radius / 4.0;
    for _ in 0..PATTERN_STEPS {
        let mut moved = false;
        for axis in 0..3 {
            for sign in [-1.0, 1.0] {
                let mut center = best.0.center;
                center[axis] += sign * step;
                let radius = reach(center);
                let bound = radius - geometry.depth(center);
                if bound < best.1 {
                    best = (Sphere { center, radius }, bound);
                    moved = true;
                }
            }
        }
        if !moved {
            step /= 2.0;
        }
    }
    best
}

/// Moves of the pattern search for a sphere's centre.
const PATTERN_STEPS: usize = 8;

/// The sphere about `members`: centred on the smallest ball of their points and ball centres,
/// its radius the farthest reach of any point or ball from that centre (so it holds them all,
/// whatever the centre).
fn enclose(elements: &[Collision], pieces: &[Piece], members: &[usize]) -> Sphere {
    Support::gather(elements, pieces, members).smallest_sphere()
}

/// The points and balls whose hulls contain a group's pieces (in the link's frame).
struct Support {
    points: Vec<[f64; 3]>,
    balls: Vec<([f64; 3], f64)>,
}

impl Support {
    /// Every member's support.
    fn gather(elements: &[Collision], pieces: &[Piece], members: &[usize]) -> Self {
        let (mut points, mut balls) = (Vec::new(), Vec::new());
        for &m in members {
            pieces[m].support(elements, &mut points, &mut balls);
        }
        Support { points, balls }
    }

    /// The farthest any point or ball reaches from `c`: the radius of the sphere about `c` that
    /// holds them all.
    fn reach(&self, c: [f64; 3]) -> f64 {
        self.points
            .iter()
            .map(|&p| distance(p, c))
            .chain(self.balls.iter().map(|&(b, r)| distance(b, c) + r))
            .fold(0.0, f64::max)
    }

    /// The sphere centred on the smallest ball of the points and ball centres, reaching them all.
    fn smallest_sphere(&self) -> Sphere {
        let mut centres: Vec<[f64; 3]> = self.points.iter().copied().chain(self.balls.iter().map(|b| b.0)).collect();
        let center = miniball_center(&mut centres);
        Sphere { center, radius: self.reach(center) }
    }
}

/// Splits a group's pieces in two: the best (least larger bound) of halving the pieces'
/// centroids at the middle of their spread along x, y, z and the direction of their longest
/// diameter, then moved towards the nearer half's centre while that helps. Pieces longer than a
/// quarter of the group's radius are cut first, so the halves follow the geometry's shape rather
/// than a long triangle's; the members come back when no piece can be cut and every halving leaves
/// one half empty.
fn split(
    geometry: &Geometry<'_>,
    pieces: &mut Vec<Piece>,
    members: Vec<usize>,
    radius: f64,
) -> Result<(Vec<usize>, Vec<usize>), Vec<usize>> {
    let mut members = cut_larger_than(pieces, members, radius / 4.0);
    for _ in 0..MAX_REFINES {
        if let Some((halves, _)) = best_halves(geometry, pieces, &members) {
            return Ok(halves);
        }
        let longest = members.iter().map(|&m| pieces[m].length()).fold(0.0, f64::max);
        let count = members.len();
        members = cut_larger_than(pieces, members, longest / 2.0);
        if members.len() == count {
            return Err(members);
        }
    }
    Err(members)
}

/// A group's pieces split in two.
type Halves = (Vec<usize>, Vec<usize>);

/// How many times a group's pieces may be cut smaller in one split (each halves the longest).
const MAX_REFINES: usize = 8;

/// The halving of [`split`] and its larger bound, or `None` when every direction leaves one half
/// empty.
fn best_halves(geometry: &Geometry<'_>, pieces: &[Piece], members: &[usize]) -> Option<(Halves, f64)> {
    if members.len() < 2 {
        return None;
    }
    let centroid = |m: usize| {
        let (mut points, mut balls) = (Vec::new(), Vec::new());
        pieces[m].support(geometry.elements, &mut points, &mut balls);
        let all: Vec<[f64; 3]> = points.into_iter().chain(balls.into_iter().map(|b| b.0)).collect();
        #[allow(clippy::cast_precision_loss)]
        let n = all.len() as f64;
        scale(all.iter().fold([0.0; 3], |s, &p| add(s, p)), 1.0 / n)
    };
    let centroids: Vec<[f64; 3]> = members.iter().map(|&m| centroid(m)).collect();
    let farthest = |from: [f64; 3]| {
        centroids.iter().copied().fold(from, |best, p| if distance(p, from) > distance(best, from) { p } else { best })
    };
    let a = farthest(centroids[0]);
    let b = farthest(a);
    let diameter = sub(b, a);
    let mut axes = vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    if norm(diameter) > 0.0 {
        axes.push(scale(diameter, 1.0 / norm(diameter)));
    }
    let worse =
        |(x, y): &(Vec<usize>, Vec<usize>)| quick_bound(geometry, pieces, x).max(quick_bound(geometry, pieces, y));
    let mut best: Option<(Halves, f64)> = None;
    for axis in axes {
        let along: Vec<f64> = centroids.iter().map(|&c| dot(c, axis)).collect();
        let (lo, hi) = along.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| (l.min(x), h.max(x)));
        let mid = (lo + hi) / 2.0;
        let mut halves: Halves = (Vec::new(), Vec::new());
        for (&m, &x) in members.iter().zip(&along) {
            if x < mid { halves.0.push(m) } else { halves.1.push(m) }
        }
        if halves.0.is_empty() || halves.1.is_empty() {
            continue;
        }
        let score = worse(&halves);
        if best.as_ref().is_none_or(|(_, s)| score < *s) {
            best = Some((halves, score));
        }
    }
    let (mut halves, mut score) = best?;
    // Two-means: each piece to the nearer of the halves' centres, kept while the bound improves.
    for _ in 0..4 {
        let (ca, cb) = (
            enclose(geometry.elements, pieces, &halves.0).center,
            enclose(geometry.elements, pieces, &halves.1).center,
        );
        let mut moved: Halves = (Vec::new(), Vec::new());
        for (&m, &c) in members.iter().zip(&centroids) {
            if distance(c, ca) <= distance(c, cb) { moved.0.push(m) } else { moved.1.push(m) }
        }
        if moved.0.is_empty() || moved.1.is_empty() || moved == halves {
            break;
        }
        let s = worse(&moved);
        if s >= score {
            break;
        }
        (halves, score) = (moved, s);
    }
    Some((halves, score))
}

/// The centre of the smallest ball holding `points` (Welzl's algorithm, move-to-front form after
/// Gärtner, "Fast and Robust Smallest Enclosing Balls", 1999), over the points in a fixed
/// pseudo-random order. Where rounding makes a support set degenerate, the centre is still some
/// point near the middle; the caller measures the radius, so containment never rests on it.
fn miniball_center(points: &mut [[f64; 3]]) -> [f64; 3] {
    // A fixed shuffle (splitmix64 on the index) makes the expected time linear.
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    for i in (1..points.len()).rev() {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        #[allow(clippy::cast_possible_truncation)]
        points.swap(i, (z % (i as u64 + 1)) as usize);
    }
    let mut support = Vec::with_capacity(4);
    let n = points.len();
    move_to_front(points, n, &mut support).0
}

/// The smallest ball of `points[..end]` with `support` on its boundary: its centre and squared
/// radius.
fn move_to_front(points: &mut [[f64; 3]], end: usize, support: &mut Vec<[f64; 3]>) -> ([f64; 3], f64) {
    let mut ball = ball_on(support);
    if support.len() == 4 {
        return ball;
    }
    for i in 0..end {
        let p = points[i];
        let d = sub(p, ball.0);
        if dot(d, d) > ball.1 * (1.0 + 1e-12) + 1e-30 {
            support.push(p);
            ball = move_to_front(points, i, support);
            support.pop();
            points[..=i].rotate_right(1);
        }
    }
    ball
}

/// The smallest ball with every point of `support` (at most four) on its boundary; an empty one
/// (radius squared -1) for none. A degenerate set (collinear three, coplanar four) gives the ball
/// of its farthest pair.
fn ball_on(support: &[[f64; 3]]) -> ([f64; 3], f64) {
    let pair = |a: [f64; 3], b: [f64; 3]| {
        let c = scale(add(a, b), 0.5);
        let d = sub(a, c);
        (c, dot(d, d))
    };
    let farthest_pair = || {
        let mut best = (support[0], 0.0);
        for (i, &a) in support.iter().enumerate() {
            for &b in &support[i + 1..] {
                let ball = pair(a, b);
                if ball.1 > best.1 {
                    best = ball;
                }
            }
        }
        best
    };
    match *support {
        [] => ([0.0; 3], -1.0),
        [a] => (a, 0.0),
        [a, b] => pair(a, b),
        [a, b, c] => {
            let (ab, ac) = (sub(b, a), sub(c, a));
            let n = cross(ab, ac);
            let nn = dot(n, n);
            if nn <= 1e-30 * dot(ab, ab) * dot(ac, ac) {
                return farthest_pair();
            }
            let offset = scale(add(scale(cross(n, ab), dot(ac, ac)), scale(cross(ac, n), dot(ab, ab))), 0.5 / nn);
            (add(a, offset), dot(offset, offset))
        }
        [a, b, c, d, ..] => {
            let (ab, ac, ad) = (sub(b, a), sub(c, a), sub(d, a));
            let det = dot(ab, cross(ac, ad));
            let scale_ = (dot(ab, ab) * dot(ac, ac) * dot(ad, ad)).sqrt();
            if det.abs() <= 1e-12 * scale_ {
                return farthest_pair();
            }
            let offset = scale(
                add(
                    add(scale(cross(ac, ad), dot(ab, ab)), scale(cross(ad, ab), dot(ac, ac))),
                    scale(cross(ab, ac), dot(ad, ad)),
                ),
                0.5 / det,
            );
            (add(a, offset), dot(offset, offset))
        }
    }
}

/// What a link's cover costs in overshoot and volume, for `inspect` and the tests.
#[derive(Debug, Clone, PartialEq)]
pub struct CoverReport {
    /// Spheres.
    pub spheres: usize,
    /// The largest overshoot bound (what the cover guarantees).
    pub bound: f64,
    /// The largest distance of a sampled point of a sphere's surface beyond the geometry.
    pub beyond_max: f64,
    /// The mean of that distance over the samples (points inside the geometry count zero).
    pub beyond_mean: f64,
    /// The volume of the spheres' union, sampled on a grid.
    pub cover_volume: f64,
    /// The geometry's volume (the sum of its elements'; a mesh's as enclosed).
    pub geometry_volume: f64,
}

/// Points on a sphere's surface sampled for the report: a Fibonacci lattice of this many.
const SURFACE_SAMPLES: usize = 200;

/// Cells per side of the grid the cover's volume is sampled on.
const VOLUME_CELLS: usize = 40;

/// The report of `cover` over `geometry`.
pub(crate) fn report(geometry: &Geometry<'_>, cover: &LinkCover) -> CoverReport {
    let golden = std::f64::consts::PI * (3.0 - 5.0_f64.sqrt());
    let (mut max, mut sum, mut count) = (0.0_f64, 0.0, 0usize);
    for s in &cover.spheres {
        for i in 0..SURFACE_SAMPLES {
            let t = fraction(-1.0, 2.0, 2 * i + 1, 2 * SURFACE_SAMPLES);
            let r = (1.0 - t * t).sqrt();
            #[allow(clippy::cast_precision_loss)]
            let a = golden * i as f64;
            let p = add(s.center, scale([r * a.cos(), r * a.sin(), t], s.radius));
            let beyond = (-geometry.depth(p)).max(0.0);
            max = max.max(beyond);
            sum += beyond;
            count += 1;
        }
    }
    let lo = cover.spheres.iter().fold([f64::INFINITY; 3], |l, s| [0, 1, 2].map(|a| l[a].min(s.center[a] - s.radius)));
    let hi =
        cover.spheres.iter().fold([f64::NEG_INFINITY; 3], |h, s| [0, 1, 2].map(|a| h[a].max(s.center[a] + s.radius)));
    let mut inside = 0usize;
    for i in 0..VOLUME_CELLS {
        for j in 0..VOLUME_CELLS {
            for k in 0..VOLUME_CELLS {
                let idx = [i, j, k];
                let p = [0, 1, 2].map(|a| fraction(lo[a], hi[a] - lo[a], 2 * idx[a] + 1, 2 * VOLUME_CELLS));
                if cover.spheres.iter().any(|s| distance(p, s.center) <= s.radius) {
                    inside += 1;
                }
            }
        }
    }
    #[allow(clippy::cast_precision_loss)]
    let cell = (0..3).map(|a| (hi[a] - lo[a]) / VOLUME_CELLS as f64).product::<f64>();
    #[allow(clippy::cast_precision_loss)]
    let (cover_volume, beyond_mean) = (inside as f64 * cell, sum / count.max(1) as f64);
    CoverReport {
        spheres: cover.spheres.len(),
        bound: cover.bounds.iter().copied().fold(0.0, f64::max),
        beyond_max: max,
        beyond_mean,
        cover_volume,
        geometry_volume: geometry.volume(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::mesh::tests::box_mesh;
    use crate::transform::FixedTransform;
    use std::sync::Arc;

    fn element(shape: Shape) -> Collision {
        Collision { origin: crate::transform::FixedTransform::identity(), shape }
    }

    fn mesh(m: super::super::mesh::TriangleMesh) -> Shape {
        Shape::Mesh { filename: "made.stl".into(), scale: [1.0; 3], loaded: Some(Arc::new(m)) }
    }

    #[test]
    fn a_budget_is_kept_and_more_spheres_overshoot_less() {
        let elements = [element(mesh(box_mesh([0.05, 0.05, 0.3])))];
        let mut geometry = Geometry::new(&elements, false).unwrap();
        let mut bound = |n| {
            let cover = cover_link(&mut geometry, &Cover::spheres(n)).unwrap().unwrap();
            assert_eq!(cover.spheres.len(), n);
            cover.bounds.iter().copied().fold(0.0, f64::max)
        };
        let (one, sixteen) = (bound(1), bound(16));
        assert!(sixteen < one / 2.0, "16 spheres: {sixteen}, one: {one}");
    }

    #[test]
    fn an_overshoot_is_reached() {
        for shape in [
            Shape::Box { size: [0.2, 0.1, 0.05] },
            Shape::Cylinder { radius: 0.06, length: 0.3 },
            Shape::Capsule { radius: 0.05, length: 0.2 },
            Shape::Ellipsoid { radii: [0.1, 0.05, 0.03] },
        ] {
            let elements = [element(shape.clone())];
            let mut geometry = Geometry::new(&elements, false).unwrap();
            let cover = cover_link(&mut geometry, &Cover::overshoot(0.01)).unwrap().unwrap();
            assert!(cover.bounds.iter().all(|&b| b <= 0.01), "{shape:?}");
        }
    }

    #[test]
    fn spheres_alone_are_kept_as_written() {
        let elements = [element(Shape::Sphere { radius: 0.1 }), element(Shape::Sphere { radius: 0.2 })];
        let mut geometry = Geometry::new(&elements, false).unwrap();
        let cover = cover_link(&mut geometry, &Cover::spheres(1)).unwrap().unwrap();
        assert_eq!(cover.spheres.len(), 2);
    }

    #[test]
    fn the_smallest_ball_is_found() {
        let mut points = vec![[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 0.0, 0.9], [0.2, 0.2, 0.2]];
        let c = miniball_center(&mut points);
        assert!(norm(c) < 1e-12, "{c:?}");
        let mut tetra = vec![[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];
        assert!(norm(miniball_center(&mut tetra)) < 1e-12);
    }
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

    /// Every dense surface point of the primitive (and its centre) inside the cover, and the
    /// sampled overshoot within the bound, for budgets and overshoots alike.
    #[test]
    fn primitives_are_held_whole_within_the_bound() {
        let shapes = [
            Shape::Sphere { radius: 0.1 },
            Shape::Capsule { radius: 0.05, length: 0.3 },
            Shape::Capsule { radius: 0.05, length: 0.0 },
            Shape::Capsule { radius: 0.002, length: 0.5 },
            Shape::Box { size: [0.2, 0.1, 0.05] },
            Shape::Box { size: [0.5, 0.5, 0.01] },
            Shape::Cylinder { radius: 0.06, length: 0.2 },
            Shape::Cylinder { radius: 0.3, length: 0.02 },
        ];
        for shape in shapes {
            for cover in [Cover::spheres(1), Cover::spheres(5), Cover::overshoot(0.03), Cover::default()] {
                let elements = [element(shape.clone())];
                let mut geometry = Geometry::new(&elements, false).unwrap();
                let made = cover_link(&mut geometry, &cover).unwrap().unwrap();
                for p in surface(&shape).into_iter().chain([[0.0; 3]]) {
                    let inside = made.spheres.iter().any(|s| distance(p, s.center) <= s.radius * (1.0 + 1e-12));
                    assert!(inside, "{shape:?} {cover:?}: {p:?} is in no sphere");
                }
                let report = report(&geometry, &made);
                assert!(report.beyond_max <= report.bound + 1e-12, "{shape:?} {cover:?}: {report:?}");
                if let Some(d) = cover.overshoot.filter(|_| cover.spheres.is_none()) {
                    assert!(report.bound <= d, "{shape:?}: {report:?}");
                }
                assert_eq!(cover_link(&mut geometry, &cover).unwrap().unwrap(), made, "not deterministic");
            }
        }
    }

    /// A capsule written as a cylinder and a sphere on each end (as URDF must write one) is
    /// covered as the capsule is, the three elements held whole; a sphere off the end by more
    /// than [`WRITTEN_CAPSULE`] stays a sphere of its own, and is held too.
    #[test]
    fn a_capsule_written_as_a_cylinder_and_two_spheres_is_covered_as_one() {
        let (radius, length) = (0.09, 0.283);
        let placed =
            |shape: Shape, z: f64| Collision { origin: FixedTransform::identity().translate([0.1, 0.0, z]), shape };
        let capsule = [placed(Shape::Capsule { radius, length }, -0.19)];
        let written = |off: f64| {
            [
                placed(Shape::Cylinder { radius, length }, -0.19),
                placed(Shape::Sphere { radius }, -0.19 + length / 2.0 + off),
                placed(Shape::Sphere { radius }, -0.19 - length / 2.0),
            ]
        };
        for cover in [Cover::spheres(4), Cover::default(), Cover::overshoot(0.005)] {
            let of = |elements: &[Collision]| {
                let mut geometry = Geometry::new(elements, false).unwrap();
                cover_link(&mut geometry, &cover).unwrap().unwrap()
            };
            assert_eq!(of(&written(0.0)).spheres, of(&capsule).spheres, "{cover:?}");
            for off in [0.0, 1e-3] {
                let elements = written(off);
                let made = of(&elements);
                for e in &elements {
                    for p in surface(&e.shape) {
                        let p = e.origin.apply(p);
                        let inside = made.spheres.iter().any(|s| distance(p, s.center) <= s.radius * (1.0 + 1e-12));
                        assert!(inside, "{cover:?}, off {off}: {p:?} is in no sphere");
                    }
                }
            }
        }
    }

    #[test]
    fn a_mesh_s_faces_are_held_not_only_its_vertices() {
        let elements = [element(mesh(box_mesh([0.05, 0.05, 0.3])))];
        let mut geometry = Geometry::new(&elements, false).unwrap();
        for cover in [Cover::spheres(3), Cover::spheres(7), Cover::overshoot(0.02)] {
            let made = cover_link(&mut geometry, &cover).unwrap().unwrap();
            for t in geometry.meshes[0].as_ref().unwrap().triangles() {
                for i in 0..=20 {
                    for j in 0..=20 - i {
                        let (u, v) = (f64::from(i) / 20.0, f64::from(j) / 20.0);
                        let p = add(t[0], add(scale(sub(t[1], t[0]), u), scale(sub(t[2], t[0]), v)));
                        let inside = made.spheres.iter().any(|s| distance(p, s.center) <= s.radius * (1.0 + 1e-12));
                        assert!(inside, "{cover:?}: {p:?} is in no sphere");
                    }
                }
            }
            let report = report(&geometry, &made);
            assert!(report.beyond_max <= report.bound + 1e-12, "{report:?}");
        }
    }
}
