//! `kinematics draw FILE --q ... [--scene SCENE] [-o robot.svg]`: a picture of the robot at a
//! configuration, so a user can see that the robot they loaded is the one they meant: its links,
//! its joints' axes, its collision spheres (when it has `<collision>` geometry) over the geometry
//! they cover, and the obstacles of a scene file. With `--path PATH` instead of `--q`, a path of
//! configurations (`path.rs`, as the planner example writes it): the robot in full at its last
//! configuration, faded at the others, and the trace of its deepest link along the straight
//! motions between them.
//!
//! The collision geometry (`geometry.rs`) is every link's `<collision>` elements placed at the
//! configuration (the link's pose composed with the element's origin), shaded faintly under the
//! spheres, so a part the spheres miss shows grey outside the orange: a primitive (box, cylinder,
//! capsule, sphere, ellipsoid) as its outline (the convex hull of projected points of its
//! surface), a mesh as the outline of the region its projected triangles cover on a grid of half
//! pixels (`silhouette.rs`; the Panda's eleven meshes, 38 000 triangles, take some 30 kB in three
//! views). Meshes are drawn when they are read: not with `--skip-meshes`, nor when one is missing.
//!
//! The numbers come from the runtime reference (`ReferenceFk::link_poses` and `sphere_centers`,
//! the numbers `fk` prints); `svg.rs` projects them into three orthographic views and writes the
//! SVG by hand.

mod geometry;
mod path;
mod silhouette;
mod svg;

use std::io::Write;

use kinematics::ReferenceFk;
use kinematics::model::collision::{LinkSphere, link_spheres};
use kinematics::model::{JointKind, KinematicTree};
use nalgebra::Vector3;

use crate::error::CliError;

/// Arguments of `draw`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml), MJCF file (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
    #[command(flatten)]
    configuration: crate::robot::ConfigurationArgs,
    /// A path to draw instead of `--q`: a file of configurations, one a line, values comma-separated
    /// (radians, metres; `#` starts a comment line), as the planner example's `--path-out` writes.
    /// The robot is drawn in full at the last, faded at the others, with its deepest link's trace.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["q", "degrees"])]
    path: Option<String>,
    /// Write the SVG to this file (atomically) instead of standard output.
    #[arg(short, long)]
    output: Option<std::path::PathBuf>,
    /// A scene file (.toml or .json) whose obstacles are drawn with the robot.
    #[arg(long, value_name = "FILE")]
    scene: Option<String>,
    /// How the collision geometry becomes the spheres drawn, and where meshes are.
    #[command(flatten)]
    cover: crate::cover::CoverArgs,
}

/// Draws the robot and prints or writes the SVG.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let file = &args.file;
    let cover = args.cover.cover()?;
    let mut tree = crate::robot::load(file)?;
    // A mesh not found spoils only the spheres: the robot is drawn without them, and the reason
    // is printed on standard error. The meshes' triangles are drawn only when all were read.
    let (covered, meshes) = match args.cover.read_meshes(&mut tree, file) {
        Ok(()) => (
            link_spheres(&tree, &cover, args.cover.meshes()).map_err(|e| CliError::Usage(format!("{file}: {e}")))?,
            true,
        ),
        Err(error) => {
            eprintln!("no collision spheres drawn: {error}");
            (Vec::new(), false)
        }
    };
    let fk = ReferenceFk::new(tree);
    let path = match &args.path {
        Some(path) => Some(path::read(path, fk.tree())?),
        None => None,
    };
    let q = match path.as_ref().and_then(|p| p.last()) {
        Some(last) => last.clone(),
        None => args.configuration.resolve(fk.tree()),
    };
    let mut scene =
        Scene::new(&fk, &q, &covered, meshes).map_err(|source| CliError::Runtime { file: file.clone(), source })?;
    if let Some(path) = &path {
        scene.add_path(&fk, path).map_err(|source| CliError::Runtime { file: file.clone(), source })?;
    }
    if let Some(path) = &args.scene {
        let obstacles = kinematics::read_scene(path)?;
        scene.obstacles = obstacles.obstacles.iter().map(Obstacle::of).collect();
    }
    let text = svg::render(&scene);
    match &args.output {
        Some(path) => kinematics_build::write_atomic(path, &text).map_err(|source| CliError::Write {
            file: file.clone(),
            path: path.display().to_string(),
            source,
        })?,
        None => write!(out, "{text}")?,
    }
    Ok(())
}

/// How a joint's axis is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AxisStyle {
    /// Rotation about the axis (revolute, continuous).
    Revolute,
    /// Translation along the axis.
    Prismatic,
    /// Motion in the plane normal to the axis; the normal is drawn.
    Planar,
}

impl AxisStyle {
    /// The style of a joint kind; `None` for joints with no one axis to draw (fixed, floating,
    /// spherical).
    fn of(kind: JointKind) -> Option<Self> {
        match kind {
            JointKind::Revolute | JointKind::Continuous => Some(AxisStyle::Revolute),
            JointKind::Prismatic => Some(AxisStyle::Prismatic),
            JointKind::Planar => Some(AxisStyle::Planar),
            JointKind::Fixed | JointKind::Floating | JointKind::Spherical => None,
        }
    }

    /// The CSS class (and legend word).
    pub fn class(self) -> &'static str {
        match self {
            AxisStyle::Revolute => "revolute",
            AxisStyle::Prismatic => "prismatic",
            AxisStyle::Planar => "planar",
        }
    }
}

/// A link's origin in the root frame.
pub struct LinkMark {
    /// The link's name.
    pub name: String,
    /// Its origin (metres, root frame).
    pub origin: [f64; 3],
}

/// A joint: the segment it draws from its parent link's origin to its child's, and its axis.
pub struct JointMark {
    /// The joint's name.
    pub name: String,
    /// Its URDF kind name.
    pub kind: &'static str,
    /// The child link's name.
    pub child: String,
    /// The points of the link's segment: the parent link's origin, the joint frame's origin after
    /// the motion when it is elsewhere (a standard DH row's constants come after the motion), and
    /// the child link's origin.
    pub points: Vec<[f64; 3]>,
    /// Where the axis is drawn (the joint frame's origin after the motion) and its unit direction
    /// in the root frame, with its style; `None` for fixed and floating joints.
    pub axis: Option<([f64; 3], [f64; 3], AxisStyle)>,
}

/// A collision sphere at the configuration drawn.
pub struct Ball {
    /// Its link's name.
    pub link: String,
    /// Its centre (metres, root frame).
    pub center: [f64; 3],
    /// Its radius.
    pub radius: f64,
}

/// An obstacle as drawn: its outline in every view.
pub struct Obstacle {
    /// Its name.
    pub name: String,
    /// Its shape, placed.
    pub shape: ObstacleShape,
}

/// An obstacle's shape, placed in the root frame.
pub enum ObstacleShape {
    /// A sphere: a circle in every view.
    Sphere {
        /// Centre.
        center: [f64; 3],
        /// Radius.
        radius: f64,
    },
    /// A cylinder or capsule: its axis drawn as thick as it is wide (round ends for a capsule).
    Round {
        /// One end of the axis.
        a: [f64; 3],
        /// The other.
        b: [f64; 3],
        /// Radius.
        radius: f64,
        /// Whether the ends are hemispheres.
        capsule: bool,
    },
    /// A box: its twelve edges.
    Box {
        /// Its eight corners (bit `k` of the index picks the sign along the box's axis `k`).
        corners: [[f64; 3]; 8],
    },
}

impl Obstacle {
    /// A scene file's obstacle, placed.
    fn of(obstacle: &kinematics::model::scene::SceneObstacle) -> Self {
        use kinematics::model::collision::Shape;
        let pose = kinematics::runtime::fixed_isometry(&obstacle.origin());
        let place = |p: Vector3<f64>| array(&(pose * nalgebra::Point3::from(p)).coords);
        let axis = |length: f64| (place(Vector3::z() * (-length / 2.0)), place(Vector3::z() * (length / 2.0)));
        let shape = match obstacle.shape {
            Shape::Sphere { radius } => ObstacleShape::Sphere { center: place(Vector3::zeros()), radius },
            Shape::Cylinder { radius, length } => {
                let (a, b) = axis(length);
                ObstacleShape::Round { a, b, radius, capsule: false }
            }
            Shape::Capsule { radius, length } => {
                let (a, b) = axis(length);
                ObstacleShape::Round { a, b, radius, capsule: true }
            }
            Shape::Box { size } => ObstacleShape::Box {
                corners: std::array::from_fn(|k| {
                    let sign = |bit: usize| if k >> bit & 1 == 1 { 0.5 } else { -0.5 };
                    place(Vector3::new(sign(0) * size[0], sign(1) * size[1], sign(2) * size[2]))
                }),
            },
            // A scene file has no meshes or ellipsoids: its reader refuses every other key.
            Shape::Mesh { .. } | Shape::Ellipsoid { .. } => {
                ObstacleShape::Sphere { center: place(Vector3::zeros()), radius: 0.0 }
            }
        };
        Obstacle { name: obstacle.name.clone(), shape }
    }

    /// The points and radius that bound it, for the drawing's extent.
    fn extent(&self) -> Vec<([f64; 3], f64)> {
        match &self.shape {
            ObstacleShape::Sphere { center, radius } => vec![(*center, *radius)],
            ObstacleShape::Round { a, b, radius, .. } => vec![(*a, *radius), (*b, *radius)],
            ObstacleShape::Box { corners } => corners.iter().map(|&c| (c, 0.0)).collect(),
        }
    }
}

/// A configuration of a path, drawn faded: its joints' segments.
pub struct Ghost {
    /// Its place in the path (from 0).
    pub index: usize,
    /// Each joint's name and the points of its segment, as [`JointMark::points`].
    pub segments: Vec<(String, Vec<[f64; 3]>)>,
}

/// The path of a link's origin along a path's straight motions in joint space.
pub struct Trace {
    /// The link's name.
    pub link: String,
    /// Its origin at each configuration of the path and at [`TRACE_STEPS`] - 1 between each two.
    pub points: Vec<[f64; 3]>,
}

/// Each straight motion of a path is traced at this many equal steps.
pub const TRACE_STEPS: usize = 16;

/// What is drawn: every link's origin and every joint, in the tree's order, the collision
/// spheres over the collision geometry, and the obstacles; for a path, its other configurations
/// and the trace.
pub struct Scene {
    /// The robot's name.
    pub robot: String,
    /// The configuration drawn (radians, metres).
    pub q: Vec<f64>,
    /// The links, in the tree's link order.
    pub links: Vec<LinkMark>,
    /// The joints, in the tree's joint order.
    pub joints: Vec<JointMark>,
    /// The collision spheres, in the robot's sphere order.
    pub spheres: Vec<Ball>,
    /// The `<collision>` elements, placed: links in the tree's order, each link's in its order.
    pub solids: Vec<geometry::Solid>,
    /// How many mesh elements are not drawn (`--skip-meshes`, or a mesh not read).
    pub meshes_left_out: usize,
    /// The obstacles of the scene file, in its order.
    pub obstacles: Vec<Obstacle>,
    /// A path's configurations before the last (which `q` is), in its order; empty without a path.
    pub ghosts: Vec<Ghost>,
    /// The trace of a path; `None` without one.
    pub trace: Option<Trace>,
}

impl Scene {
    /// Every point drawn with the radius around it (0 for a point), for the drawing's extent.
    pub fn extent(&self) -> Vec<([f64; 3], f64)> {
        let mut out: Vec<([f64; 3], f64)> = self.links.iter().map(|l| (l.origin, 0.0)).collect();
        out.extend(self.joints.iter().flat_map(|j| j.points.iter().map(|&p| (p, 0.0))));
        out.extend(self.spheres.iter().map(|s| (s.center, s.radius)));
        out.extend(self.solids.iter().flat_map(|s| s.bounds().map(|p| (p, 0.0))));
        out.extend(self.obstacles.iter().flat_map(Obstacle::extent));
        out.extend(self.ghosts.iter().flat_map(|g| g.segments.iter().flat_map(|(_, p)| p.iter().map(|&p| (p, 0.0)))));
        out.extend(self.trace.iter().flat_map(|t| t.points.iter().map(|&p| (p, 0.0))));
        out
    }
}

fn array(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

impl Scene {
    /// The robot at `q` by the runtime reference (which refuses a wrong count or a value that is
    /// not a finite number), with the collision spheres `covered` (the model's cover of its tree)
    /// and its collision geometry, meshes too where `meshes` (those whose triangles were read).
    pub fn new(
        fk: &ReferenceFk,
        q: &[f64],
        covered: &[LinkSphere],
        meshes: bool,
    ) -> Result<Self, kinematics::RuntimeError> {
        let tree: &KinematicTree = fk.tree();
        let poses = fk.link_poses(q)?;
        let links = tree
            .links()
            .iter()
            .zip(&poses)
            .map(|(link, pose)| LinkMark { name: link.name.clone(), origin: array(&pose.translation.vector) })
            .collect();
        let joints = joint_marks(tree, &poses);
        let (solids, meshes_left_out) = geometry::solids(tree, &poses, meshes);
        let spheres = fk
            .sphere_centers(q, covered)?
            .iter()
            .zip(covered)
            .map(|(center, s)| Ball {
                link: tree.link(s.link).name.clone(),
                center: array(&center.coords),
                radius: s.sphere.radius,
            })
            .collect();
        Ok(Scene {
            robot: tree.name().to_owned(),
            q: q.to_vec(),
            links,
            joints,
            spheres,
            solids,
            meshes_left_out,
            obstacles: Vec::new(),
            ghosts: Vec::new(),
            trace: None,
        })
    }

    /// A path whose last configuration is the one drawn: the others as ghosts, and the trace of
    /// the deepest link (`fk`'s robot, each configuration checked by the reference as in
    /// [`Scene::new`]).
    pub fn add_path(&mut self, fk: &ReferenceFk, path: &[Vec<f64>]) -> Result<(), kinematics::RuntimeError> {
        let tree = fk.tree();
        let tip = crate::robot::deepest_link(tree);
        let origin = |q: &[f64]| -> Result<[f64; 3], kinematics::RuntimeError> {
            Ok(array(&fk.link_poses(q)?[tip.0].translation.vector))
        };
        let mut points = vec![origin(&path[0])?];
        for (index, q) in path.iter().enumerate() {
            if index + 1 < path.len() {
                let poses = fk.link_poses(q)?;
                let segments = joint_marks(tree, &poses).into_iter().map(|j| (j.name, j.points)).collect();
                self.ghosts.push(Ghost { index, segments });
            }
            if let Some(previous) = index.checked_sub(1).map(|i| &path[i]) {
                for k in 1..=TRACE_STEPS {
                    let t = k as f64 / TRACE_STEPS as f64;
                    let between: Vec<f64> = previous.iter().zip(q).map(|(a, b)| (1.0 - t) * a + t * b).collect();
                    // The motion's end itself, not its rounding.
                    points.push(origin(if k == TRACE_STEPS { q } else { &between })?);
                }
            }
        }
        self.trace = Some(Trace { link: tree.link(tip).name.clone(), points });
        Ok(())
    }
}

/// Every joint's segment and axis at the link poses `poses` (the tree's link order).
fn joint_marks(tree: &KinematicTree, poses: &[nalgebra::Isometry3<f64>]) -> Vec<JointMark> {
    tree.joints()
        .iter()
        .map(|joint| {
            let child = poses[joint.child.0];
            // The joint frame after its motion: the child's pose less the constants after it.
            let moved = child * kinematics::runtime::fixed_isometry(&joint.after_motion).inverse();
            let (parent, at, end) = (
                array(&poses[joint.parent.0].translation.vector),
                array(&moved.translation.vector),
                array(&child.translation.vector),
            );
            let points = if at == end { vec![parent, end] } else { vec![parent, at, end] };
            let axis = AxisStyle::of(joint.kind).map(|style| {
                let direction = moved.rotation * Vector3::new(joint.axis[0], joint.axis[1], joint.axis[2]);
                (at, array(&direction), style)
            });
            JointMark {
                name: joint.name.clone(),
                kind: joint.kind.name(),
                child: tree.link(joint.child).name.clone(),
                points,
                axis,
            }
        })
        .collect()
}
