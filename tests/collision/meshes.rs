//! The sphere cover is conservative (issue 59): against parry3d-f64 on each link's own geometry
//! as the truth (the Panda's franka_description collision meshes as `TriMesh`es, read as the
//! derive reads them; the primitives arm's cylinders, capsule and box as parry's solids), on
//! random configurations within the limits in random scenes of tables, shelves and bins about the
//! base (as MotionBenchMaker sets them), no configuration whose geometry is more than 1e-9 m into
//! an obstacle is called free by the generated `collides`, and the spheres themselves meet every
//! obstacle the geometry meets. What the cover costs, the configurations the geometry leaves free
//! of every obstacle that the spheres do not, is printed, not judged. A module of the collision
//! tests, with their scenes' types and random stream.
//!
//! A mesh is a surface: parry finds where an obstacle meets it, not an obstacle wholly inside a
//! link's closed mesh. Such configurations (an obstacle's centre inside a mesh it does not touch,
//! by the mesh's winding number) are counted apart and judged neither way.

use std::f64::consts::{FRAC_PI_2, PI};
use std::path::Path;

use kinematics::collision::{BoxObstacle, CapsuleObstacle, CylinderObstacle, Environment, SphereObstacle};
use kinematics::model::KinematicTree;
use kinematics::model::collision::Shape as Geometry;
use kinematics::model::collision::mesh::PlacedTriangles;
use kinematics::runtime::fixed_isometry;
use kinematics::{Configurations, JointLimits, Kinematics, ReferenceFk};
use nalgebra::{Isometry3, Matrix3, Point3, Rotation3, Translation3, UnitQuaternion, Vector3};
use parry3d_f64::bounding_volume::{Aabb, BoundingVolume};
use parry3d_f64::math::{Pose, Rotation, Vector};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Capsule, Cuboid, Cylinder, Shape, TriMesh};

use super::{Obstacles, Stream, Ur5PrimitivesChecked};

/// The Panda with franka_description's collision meshes, covered by the derive's default.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda_meshes.urdf", collision(srdf = "robots/panda.srdf"))]
pub struct PandaMeshes;

/// Contact closer than this (m) either way is judged neither way.
const BAND: f64 = 1e-9;

/// What the test needs of a derived robot.
struct Derived<const N: usize, const S: usize> {
    /// Its description, from the repository's root (its meshes are read from beside it).
    urdf: &'static str,
    reference: ReferenceFk,
    base: &'static str,
    limits: &'static [JointLimits],
    collides: fn(&[f64; N], &Environment<'_>) -> bool,
    self_collides: fn(&[f64; N]) -> bool,
    centers: fn(&[f64; N]) -> [[f64; 3]; S],
    radii: [f64; S],
    links: [&'static str; S],
}

/// One `<collision>` element as parry holds it.
struct Part {
    link: usize,
    /// Its shape's frame in its link's (a cylinder's turned from parry's y axis to the URDF's z).
    origin: Isometry3<f64>,
    shape: Box<dyn Shape>,
    /// A mesh's triangles in that frame (scaled) with their bounding box, for the inside test;
    /// `None` for a solid.
    surface: Option<(PlacedTriangles, Aabb)>,
}

/// Every collision element of `tree` (its meshes loaded) as a parry shape.
fn parts(tree: &KinematicTree) -> Vec<Part> {
    let mut out = Vec::new();
    for (link, l) in tree.links().iter().enumerate() {
        for c in &l.collisions {
            let origin = fixed_isometry(&c.origin);
            let (origin, shape, surface): (_, Box<dyn Shape>, _) = match &c.shape {
                Geometry::Mesh { loaded: Some(mesh), scale, .. } => {
                    let vertex = |v: &[f64; 3]| [v[0] * scale[0], v[1] * scale[1], v[2] * scale[2]];
                    let vertices: Vec<Vector> = mesh.vertices().iter().map(|v| vector(vertex(v))).collect();
                    let trimesh = TriMesh::new(vertices, mesh.triangles().to_vec()).unwrap();
                    let aabb = trimesh.local_aabb();
                    let corners = mesh.corners().map(|t| t.map(|v| vertex(&v))).collect();
                    (origin, Box::new(trimesh), Some((PlacedTriangles::new(corners), aabb)))
                }
                Geometry::Mesh { filename, loaded: None, .. } => panic!("{}: {filename} was not read", l.name),
                Geometry::Sphere { radius } => (origin, Box::new(Ball::new(*radius)), None),
                Geometry::Box { size } => (origin, Box::new(Cuboid::new(vector(size.map(|s| s / 2.0)))), None),
                Geometry::Cylinder { radius, length } => {
                    let y_to_z = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_2);
                    (origin * y_to_z, Box::new(Cylinder::new(length / 2.0, *radius)), None)
                }
                Geometry::Capsule { radius, length } => (origin, Box::new(Capsule::new_z(length / 2.0, *radius)), None),
                Geometry::Ellipsoid { .. } => panic!("{}: no ellipsoid in these robots", l.name),
            };
            out.push(Part { link, origin, shape, surface });
        }
    }
    out
}

/// An obstacle as parry holds it, by this test's own reading of the core's types; the same grown
/// by `BAND` every way (holding every point within `BAND` of it), and a point of it (its centre)
/// for the inside test.
struct Solid {
    at: Isometry3<f64>,
    shape: Box<dyn Shape>,
    grown: Box<dyn Shape>,
    center: Point3<f64>,
}

fn solids(o: &Obstacles) -> Vec<Solid> {
    let point = |p: [f64; 3]| Point3::new(p[0], p[1], p[2]);
    let mut out: Vec<Solid> = Vec::new();
    for s in &o.spheres {
        let at = Isometry3::translation(s.center[0], s.center[1], s.center[2]);
        let (shape, grown) = (Box::new(Ball::new(s.radius)), Box::new(Ball::new(s.radius + BAND)));
        out.push(Solid { at, shape, grown, center: point(s.center) });
    }
    for c in &o.capsules {
        let capsule = |radius| Box::new(Capsule::new(vector(c.a), vector(c.b), radius));
        let (shape, grown) = (capsule(c.radius), capsule(c.radius + BAND));
        let center = nalgebra::center(&point(c.a), &point(c.b));
        out.push(Solid { at: Isometry3::identity(), shape, grown, center });
    }
    for c in &o.cylinders {
        let (a, b) = (point(c.a), point(c.b));
        let axis = b - a;
        // parry's cylinder stands on its y axis: turned onto the segment.
        let turn = UnitQuaternion::rotation_between(&Vector3::y(), &axis)
            .unwrap_or_else(|| UnitQuaternion::from_axis_angle(&Vector3::x_axis(), PI));
        let center = nalgebra::center(&a, &b);
        let at = Isometry3::from_parts(Translation3::from(center.coords), turn);
        let half = axis.norm() / 2.0;
        let (shape, grown) =
            (Box::new(Cylinder::new(half, c.radius)), Box::new(Cylinder::new(half + BAND, c.radius + BAND)));
        out.push(Solid { at, shape, grown, center });
    }
    for b in &o.boxes {
        // Row `i` of `rotation` is the box's axis `i`: the columns of its frame.
        let axes = b.rotation.map(|r| Vector3::new(r[0], r[1], r[2]));
        let turn = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix(&Matrix3::from_columns(&axes)));
        let center = point(b.center);
        let at = Isometry3::from_parts(Translation3::from(center.coords), turn);
        let cuboid = |grow: f64| Box::new(Cuboid::new(vector(b.half_extents.map(|h| h + grow))));
        out.push(Solid { at, shape: cuboid(0.0), grown: cuboid(BAND), center });
    }
    out
}

fn vector(v: [f64; 3]) -> Vector {
    Vector::new(v[0], v[1], v[2])
}

fn pose(iso: &Isometry3<f64>) -> Pose {
    let (t, r) = (iso.translation.vector, iso.rotation);
    Pose::from_parts(Vector::new(t.x, t.y, t.z), Rotation::from_xyzw(r.i, r.j, r.k, r.w))
}

/// How a part meets an obstacle.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Meeting {
    /// More than `BAND` apart.
    Apart,
    /// The obstacle's surface meets the part more than `BAND` deep (parry's contact depth, m).
    Into(f64),
    /// Within `BAND` of touching.
    Band,
    /// Apart from a mesh's surface, with the obstacle's centre inside the mesh.
    Enclosed,
}

/// How `part`, placed at `at` (in the base's frame), meets `solid`. By intersection tests (parry's
/// distance between a mesh and an obstacle is several times slower): apart where the part misses
/// the obstacle grown by `BAND`, into it as deep as parry's contact says where it meets the
/// obstacle itself.
fn meet(part: &Part, at: &Isometry3<f64>, aabb: &Aabb, solid: &Solid) -> Meeting {
    let (p1, p2) = (pose(at), pose(&solid.at));
    if !aabb.intersects(&solid.grown.compute_aabb(&p2)) {
        return Meeting::Apart;
    }
    let one = part.shape.as_ref();
    let meets = |two: &dyn Shape| query::intersection_test(&p1, one, &p2, two).unwrap().intersecting;
    if !meets(solid.grown.as_ref()) {
        if let Some((surface, bounds)) = &part.surface {
            let local = at.inverse() * solid.center;
            let inside = bounds.contains_local_point(vector(local.coords.into()))
                && surface.winding(local.coords.into()).abs() >= 0.5;
            if inside {
                return Meeting::Enclosed;
            }
        }
        return Meeting::Apart;
    }
    if !meets(solid.shape.as_ref()) {
        return Meeting::Band;
    }
    match query::contact(&p1, one, &p2, solid.shape.as_ref(), 0.0).unwrap() {
        Some(contact) if contact.dist < -BAND => Meeting::Into(-contact.dist),
        _ => Meeting::Band,
    }
}

/// The signed distance (m) from the ball at `center` of `radius` to `solid`: parry's distance
/// where apart, less its contact's depth where they overlap.
fn ball_gap(center: [f64; 3], radius: f64, solid: &Solid) -> f64 {
    let (at, ball, p2) = (Pose::from_translation(vector(center)), Ball::new(radius), pose(&solid.at));
    let apart = query::distance(&at, &ball, &p2, solid.shape.as_ref()).unwrap().distance;
    if apart > 0.0 {
        return apart;
    }
    query::contact(&at, &ball, &p2, solid.shape.as_ref(), 0.0).unwrap().map_or(0.0, |c| c.dist.min(0.0))
}

/// A scene about the base as MotionBenchMaker's are (kind 0 a table with objects on it, 1 a
/// shelf with cans on its boards, 2 a bin under a bar with a pole beside it), turned to a random
/// side, its boards a few centimetres thick, within about 0.9 m of the base.
fn scene(stream: &mut Stream, kind: usize) -> Obstacles {
    let mut o = Obstacles { spheres: Vec::new(), capsules: Vec::new(), cylinders: Vec::new(), boxes: Vec::new() };
    let yaw = stream.within(PI);
    let (c, s) = (yaw.cos(), yaw.sin());
    // A point of the scene's own frame (x away from the base) in the base's.
    let at = move |x: f64, y: f64, z: f64| [c * x - s * y, s * x + c * y, z];
    let board = |o: &mut Obstacles, x: f64, y: f64, z: f64, size: [f64; 3]| {
        o.boxes.push(BoxObstacle::from_xyz_rpy(at(x, y, z), [0.0, 0.0, yaw], size));
    };
    let span = |stream: &mut Stream, lo: f64, hi: f64| lo + (hi - lo) * stream.next();
    match kind {
        0 => {
            let (near, depth, width) = (span(stream, 0.25, 0.45), span(stream, 0.35, 0.5), span(stream, 0.6, 1.2));
            let (top, thick) = (span(stream, 0.0, 0.45), span(stream, 0.03, 0.05));
            board(&mut o, near + depth / 2.0, 0.0, top - thick / 2.0, [depth, width, thick]);
            for item in 0..5 {
                let x = span(stream, near + 0.05, near + depth - 0.05);
                let y = span(stream, -width / 2.0 + 0.05, width / 2.0 - 0.05);
                let turn = stream.within(PI);
                match item % 4 {
                    0 => {
                        let (radius, height) = (span(stream, 0.03, 0.05), span(stream, 0.08, 0.25));
                        o.cylinders.push(CylinderObstacle::from_xyz_rpy(
                            at(x, y, top + height / 2.0),
                            [0.0; 3],
                            radius,
                            height,
                        ));
                    }
                    1 => {
                        let size = [span(stream, 0.05, 0.12), span(stream, 0.05, 0.12), span(stream, 0.05, 0.2)];
                        o.boxes.push(BoxObstacle::from_xyz_rpy(at(x, y, top + size[2] / 2.0), [0.0, 0.0, turn], size));
                    }
                    2 => {
                        let radius = span(stream, 0.03, 0.06);
                        o.spheres.push(SphereObstacle { center: at(x, y, top + radius), radius });
                    }
                    _ => {
                        let (radius, length) = (span(stream, 0.02, 0.04), span(stream, 0.1, 0.2));
                        o.capsules.push(CapsuleObstacle::from_xyz_rpy(
                            at(x, y, top + radius),
                            [FRAC_PI_2, 0.0, turn],
                            radius,
                            length,
                        ));
                    }
                }
            }
        }
        1 => {
            let (near, depth, width) = (span(stream, 0.45, 0.65), span(stream, 0.3, 0.4), span(stream, 0.6, 1.0));
            let (height, thick) = (span(stream, 0.9, 1.3), span(stream, 0.02, 0.03));
            let x = near + depth / 2.0;
            for side in [-1.0, 1.0] {
                board(&mut o, x, side * width / 2.0, height / 2.0, [depth, thick, height]);
            }
            board(&mut o, near + depth, 0.0, height / 2.0, [thick, width, height]);
            let (first, boards) = (span(stream, 0.05, 0.3), 3 + usize::from(stream.next() < 0.5));
            let gap = (height - first) / boards as f64;
            for k in 0..boards {
                let z = first + gap * k as f64;
                board(&mut o, x, 0.0, z, [depth, width, thick]);
                let (radius, tall) = (span(stream, 0.03, 0.045), span(stream, 0.1, 0.2).min(gap - 0.05));
                let y = span(stream, -width / 2.0 + 0.06, width / 2.0 - 0.06);
                let z = z + thick / 2.0 + tall / 2.0;
                o.cylinders.push(CylinderObstacle::from_xyz_rpy(at(x, y, z), [0.0; 3], radius, tall));
            }
        }
        _ => {
            let (near, side, bottom) = (span(stream, 0.35, 0.55), span(stream, 0.3, 0.45), span(stream, 0.05, 0.4));
            let (wall, thick) = (span(stream, 0.1, 0.25), span(stream, 0.02, 0.04));
            let x = near + side / 2.0;
            board(&mut o, x, 0.0, bottom - thick / 2.0, [side, side, thick]);
            for d in [-1.0, 1.0] {
                board(&mut o, x + d * side / 2.0, 0.0, bottom + wall / 2.0, [thick, side, wall]);
                board(&mut o, x, d * side / 2.0, bottom + wall / 2.0, [side, thick, wall]);
            }
            let (radius, z) = (span(stream, 0.02, 0.04), span(stream, 0.6, 1.0));
            let length = span(stream, 0.8, 1.4);
            o.capsules.push(CapsuleObstacle::from_xyz_rpy(at(x, 0.0, z), [FRAC_PI_2, 0.0, yaw], radius, length));
            let (angle, distance) = (yaw + span(stream, 0.8, 2.0), span(stream, 0.35, 0.7));
            let (radius, pole) = (span(stream, 0.03, 0.06), span(stream, 0.8, 1.2));
            let foot = [distance * angle.cos(), distance * angle.sin(), pole / 2.0];
            o.cylinders.push(CylinderObstacle::from_xyz_rpy(foot, [0.0; 3], radius, pole));
            let radius = span(stream, 0.04, 0.08);
            o.spheres.push(SphereObstacle { center: at(x, stream.within(0.3), z - 0.25), radius });
        }
    }
    o
}

/// What the test saw of a robot.
#[derive(Debug, Default)]
struct Tally {
    configurations: usize,
    /// The geometry more than `BAND` into an obstacle.
    hits: usize,
    /// Of those, called free by `collides` (must stay 0).
    called_free: usize,
    /// The geometry more than `BAND` from every obstacle.
    free: usize,
    /// Of those, the spheres more than `BAND` into an obstacle: the cover's price.
    price: usize,
    /// Of the free ones, those `self_collides` calls colliding (not judged here).
    free_but_self: usize,
    /// Every configuration the spheres put more than `BAND` into an obstacle.
    cover_hits: usize,
    /// The geometry within `BAND` of an obstacle.
    banded: usize,
    /// An obstacle inside a mesh it does not touch.
    enclosed: usize,
    /// Verdicts of `collides` held to the spheres' own distances (where `self_collides` is false).
    spheres_judged: usize,
    /// The shallowest overlap of geometry caught (m).
    shallowest: f64,
    /// The spheres' least overlap with an obstacle the geometry overlaps (m).
    least_cover: f64,
    /// Configurations at the edge of contact (bisected from a free one to a hit).
    edges: usize,
    /// Of those, how many within 1e-7 m of contact.
    edges_close: usize,
    /// The deepest of their overlaps, and the spheres' least overlap there (m).
    edge_depth: f64,
    edge_cover: f64,
}

/// Halvings of the way from a free configuration to a hit: the last hit is within a few
/// nanometres of the contact's edge.
const HALVINGS: usize = 32;

/// The claim on one robot: `scenes` scenes of `each` configurations from `seed`.
fn conservative<const N: usize, const S: usize>(robot: &Derived<N, S>, seed: u64, scenes: usize, each: usize) -> Tally {
    let mut tree = robot.reference.tree().clone();
    let urdf = Path::new(env!("CARGO_MANIFEST_DIR")).join(robot.urdf);
    let packages = kinematics_meshes::Packages::new();
    kinematics_meshes::load_tree_meshes(&mut tree, &kinematics_meshes::Resolver::new(&urdf, &packages)).unwrap();
    let parts = parts(&tree);
    assert!(!parts.is_empty(), "{}: no geometry", robot.urdf);
    // Every link with geometry has spheres.
    for part in &parts {
        let link = tree.links()[part.link].name.as_str();
        assert!(robot.links.contains(&link), "{}: {link} has geometry and no spheres", robot.urdf);
    }
    let base = tree.links().iter().position(|l| l.name == robot.base).unwrap();
    // Each part at `q` in the base's frame, with its bounding box there.
    let place = |q: &[f64; N]| -> Vec<(Isometry3<f64>, Aabb)> {
        let poses = robot.reference.link_poses(q).unwrap();
        let from_base = poses[base].inverse();
        parts
            .iter()
            .map(|part| {
                let at = from_base * poses[part.link] * part.origin;
                (at, part.shape.compute_aabb(&pose(&at)))
            })
            .collect()
    };
    // The spheres' signed distance to each obstacle at `q`.
    let cover = |q: &[f64; N], solids: &[Solid]| -> Vec<f64> {
        let centers = (robot.centers)(q);
        let gap = |solid| {
            centers.iter().zip(&robot.radii).map(|(c, &r)| ball_gap(*c, r, solid)).fold(f64::INFINITY, f64::min)
        };
        solids.iter().map(gap).collect()
    };
    let mut stream = Stream(seed);
    let mut tally =
        Tally { shallowest: f64::INFINITY, least_cover: f64::INFINITY, edge_cover: f64::INFINITY, ..Tally::default() };
    for round in 0..scenes {
        let o = scene(&mut stream, round % 3);
        let env = Environment::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes).unwrap();
        let solids = solids(&o);
        let configurations = Configurations::within(robot.limits).seeded(seed * 1000 + round as u64).uniform();
        let mut last_free: Option<[f64; N]> = None;
        for q in configurations.take(each) {
            let q: [f64; N] = q.try_into().unwrap();
            let placed = place(&q);
            let mut meetings = vec![Meeting::Apart; solids.len()];
            let mut deepest: Option<(usize, usize, f64)> = None;
            for (p, (part, (at, aabb))) in parts.iter().zip(&placed).enumerate() {
                for (k, solid) in solids.iter().enumerate() {
                    let m = meet(part, at, aabb, solid);
                    meetings[k] = match (meetings[k], m) {
                        (Meeting::Into(a), Meeting::Into(b)) => Meeting::Into(a.max(b)),
                        (Meeting::Into(a), _) | (_, Meeting::Into(a)) => Meeting::Into(a),
                        (Meeting::Enclosed, _) | (_, Meeting::Enclosed) => Meeting::Enclosed,
                        (Meeting::Band, _) | (_, Meeting::Band) => Meeting::Band,
                        _ => Meeting::Apart,
                    };
                    if let Meeting::Into(depth) = m
                        && deepest.is_none_or(|(_, _, d)| depth > d)
                    {
                        deepest = Some((p, k, depth));
                    }
                }
            }
            let gaps = cover(&q, &solids);
            let nearest = gaps.iter().copied().fold(f64::INFINITY, f64::min);
            let (collides, itself) = ((robot.collides)(&q, &env), (robot.self_collides)(&q));
            tally.configurations += 1;
            tally.cover_hits += usize::from(nearest < -BAND);
            // The generated check against the spheres' own distances, where only obstacles decide.
            if !itself && nearest.abs() > BAND {
                assert_eq!(collides, nearest < 0.0, "{}: collides at {q:?}: the spheres' gap {nearest:e}", robot.urdf);
                tally.spheres_judged += 1;
            }
            if let Some((p, k, depth)) = deepest {
                tally.hits += 1;
                tally.called_free += usize::from(!collides);
                let link = &tree.links()[parts[p].link].name;
                assert!(collides, "{}: {link} {depth:e} m into obstacle {k} at {q:?}, called free", robot.urdf);
                tally.shallowest = tally.shallowest.min(depth);
                for (k, m) in meetings.iter().enumerate() {
                    if let Meeting::Into(depth) = *m {
                        let gap = gaps[k];
                        assert!(
                            gap < 0.0,
                            "{}: at {q:?} the geometry is {depth:e} m into obstacle {k}, the spheres {gap:e} m from it",
                            robot.urdf
                        );
                        tally.least_cover = tally.least_cover.min(-gap);
                    }
                }
                // The edge of this contact, on the way from the last free configuration: the part
                // barely into the obstacle, which the spheres must still meet. Halved by parry's
                // intersection test (quick), then stepped back in by doubling steps to the first
                // configuration its contact puts more than `BAND` deep.
                if let Some(free) = last_free {
                    let (part, solid) = (&parts[p], &solids[k]);
                    let touching = |q: &[f64; N]| {
                        let at = pose(&place(q)[p].0);
                        query::intersection_test(&at, part.shape.as_ref(), &pose(&solid.at), solid.shape.as_ref())
                            .unwrap()
                            .intersecting
                    };
                    let (mut out, mut inside) = (free, q);
                    for _ in 0..HALVINGS {
                        let middle: [f64; N] = std::array::from_fn(|j| 0.5 * (out[j] + inside[j]));
                        if touching(&middle) { inside = middle } else { out = middle }
                    }
                    let edge = (0..=HALVINGS).rev().find_map(|halvings| {
                        let t = 0.5_f64.powi(halvings as i32);
                        let q: [f64; N] = std::array::from_fn(|j| inside[j] + t * (q[j] - inside[j]));
                        let (at, aabb) = &place(&q)[p];
                        match meet(part, at, aabb, solid) {
                            Meeting::Into(depth) => Some((q, depth)),
                            _ => None,
                        }
                    });
                    let (edge, edge_depth) = edge.unwrap_or((q, depth));
                    let gap = cover(&edge, &solids)[k];
                    assert!(
                        (robot.collides)(&edge, &env) && gap < 0.0,
                        "{}: {link} {edge_depth:e} m into obstacle {k} at {edge:?}, the spheres {gap:e} m from it",
                        robot.urdf
                    );
                    tally.edges += 1;
                    tally.edges_close += usize::from(edge_depth <= 1e-7);
                    tally.edge_depth = tally.edge_depth.max(edge_depth);
                    tally.edge_cover = tally.edge_cover.min(-gap);
                }
            } else if meetings.contains(&Meeting::Enclosed) {
                tally.enclosed += 1;
            } else if meetings.iter().all(|m| *m == Meeting::Apart) {
                tally.free += 1;
                tally.price += usize::from(nearest < -BAND);
                tally.free_but_self += usize::from(itself);
                last_free = Some(q);
            } else {
                tally.banded += 1;
            }
        }
    }
    let share = |n: usize, of: usize| 100.0 * n as f64 / of.max(1) as f64;
    let t = &tally;
    eprintln!(
        "{}: {} configurations in {scenes} scenes, {S} spheres\n  \
         geometry more than {BAND:e} m into an obstacle: {} (called free: {}); shallowest {:.3e} m; the spheres' \
         least overlap with an obstacle it meets {:.3e} m\n  \
         at a contact's edge: {} ({} within 1e-7 m of contact, all within {:.3e} m); the spheres' least overlap \
         there {:.3e} m\n  \
         geometry free of every obstacle: {}; the cover's price: {} of them colliding with an obstacle ({:.1} %; \
         {:.1} % of the {} the spheres put into one) ({} self-colliding, not judged)\n  \
         neither: {} within {BAND:e} m of contact, {} with an obstacle inside a mesh; {} verdicts of `collides` \
         held to the spheres' own distances",
        robot.urdf,
        t.configurations,
        t.hits,
        t.called_free,
        t.shallowest,
        t.least_cover,
        t.edges,
        t.edges_close,
        t.edge_depth,
        t.edge_cover,
        t.free,
        t.price,
        share(t.price, t.free),
        share(t.price, t.cover_hits),
        t.cover_hits,
        t.free_but_self,
        t.banded,
        t.enclosed,
        t.spheres_judged,
    );
    tally
}

/// Both verdicts seen often enough for the claim to mean something.
fn seen_both(tally: &Tally) {
    assert!(tally.hits > 200 && tally.free > 200, "{tally:?}");
    assert!(tally.spheres_judged > 200 && tally.edges > 100, "{tally:?}");
}

#[test]
fn the_mesh_cover_is_conservative_panda() {
    let robot = Derived::<8, { PandaMeshes::SPHERE_RADII.len() }> {
        urdf: "robots/panda_meshes.urdf",
        reference: PandaMeshes::reference().unwrap(),
        base: PandaMeshes::BASE,
        limits: &PandaMeshes::JOINT_LIMITS,
        collides: |q, env| PandaMeshes::collides(q, env),
        self_collides: PandaMeshes::self_collides,
        centers: PandaMeshes::sphere_centers,
        radii: PandaMeshes::SPHERE_RADII,
        links: PandaMeshes::SPHERE_LINKS,
    };
    seen_both(&conservative(&robot, 59, 20, 200));
}

/// The primitives arm (its wrist links always touch without an SRDF, so `collides` is always
/// true: the spheres' own test carries the claim).
#[test]
fn the_primitive_cover_is_conservative_ur5() {
    let robot = Derived::<6, { Ur5PrimitivesChecked::SPHERE_RADII.len() }> {
        urdf: "robots/ur5_primitives.urdf",
        reference: Ur5PrimitivesChecked::reference().unwrap(),
        base: Ur5PrimitivesChecked::BASE,
        limits: &Ur5PrimitivesChecked::JOINT_LIMITS,
        collides: |q, env| Ur5PrimitivesChecked::collides(q, env),
        self_collides: Ur5PrimitivesChecked::self_collides,
        centers: Ur5PrimitivesChecked::sphere_centers,
        radii: Ur5PrimitivesChecked::SPHERE_RADII,
        links: Ur5PrimitivesChecked::SPHERE_LINKS,
    };
    let tally = conservative(&robot, 60, 20, 200);
    assert!(tally.hits > 200 && tally.free > 200 && tally.edges > 100, "{tally:?}");
}
