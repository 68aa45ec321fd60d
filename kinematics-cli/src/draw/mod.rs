//! `kinematics draw FILE --q ... [-o robot.svg]`: a picture of the robot at a configuration, so a
//! user can see that the robot they loaded is the one they meant.
//!
//! The geometry comes from the runtime reference (`ReferenceFk::link_poses`, the numbers `fk`
//! prints); `svg.rs` projects it into three orthographic views and writes the SVG by hand.

mod svg;

use std::io::Write;

use kinematics::ReferenceFk;
use kinematics::model::{JointKind, KinematicTree};
use nalgebra::Vector3;

use crate::error::CliError;

/// Arguments of `draw`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml) or DH table (.toml, .json).
    file: String,
    #[command(flatten)]
    configuration: crate::robot::ConfigurationArgs,
    /// Write the SVG to this file (atomically) instead of standard output.
    #[arg(short, long)]
    output: Option<std::path::PathBuf>,
}

/// Draws the robot and prints or writes the SVG.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let file = &args.file;
    let fk = ReferenceFk::new(crate::robot::load(file)?);
    let q = args.configuration.resolve(fk.tree());
    let scene = Scene::new(&fk, &q).map_err(|source| CliError::Runtime { file: file.clone(), source })?;
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
    /// The style of a joint kind; `None` for joints with no one axis to draw (fixed, floating).
    fn of(kind: JointKind) -> Option<Self> {
        match kind {
            JointKind::Revolute | JointKind::Continuous => Some(AxisStyle::Revolute),
            JointKind::Prismatic => Some(AxisStyle::Prismatic),
            JointKind::Planar => Some(AxisStyle::Planar),
            JointKind::Fixed | JointKind::Floating => None,
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

/// What is drawn: every link's origin and every joint, in the tree's order.
pub struct Scene {
    /// The robot's name.
    pub robot: String,
    /// The configuration drawn (radians, metres).
    pub q: Vec<f64>,
    /// The links, in the tree's link order.
    pub links: Vec<LinkMark>,
    /// The joints, in the tree's joint order.
    pub joints: Vec<JointMark>,
}

fn array(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

impl Scene {
    /// The robot at `q` by the runtime reference (which refuses a wrong count or a value that is
    /// not a finite number).
    pub fn new(fk: &ReferenceFk, q: &[f64]) -> Result<Self, kinematics::RuntimeError> {
        let tree: &KinematicTree = fk.tree();
        let poses = fk.link_poses(q)?;
        let links = tree
            .links()
            .iter()
            .zip(&poses)
            .map(|(link, pose)| LinkMark { name: link.name.clone(), origin: array(&pose.translation.vector) })
            .collect();
        let joints = tree
            .joints()
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
            .collect();
        Ok(Scene { robot: tree.name().to_owned(), q: q.to_vec(), links, joints })
    }
}
