//! urdf-rs interop (feature `urdf-rs`): a robot that urdf-rs has read, as `k` and openrr hand it
//! around (`urdf_rs::Robot`), into the [`Description`] the built-in reader would give, and from
//! there through the same validation and exactness policy into a [`KinematicTree`].
//!
//! The joint is assembled by the built-in reader's own code (`urdf::UrdfJoint`), validation is
//! [`KinematicTree::from_description_with`], the path [`crate::Source::load`] takes. The
//! exactness policy judges an angle's `f64`, and urdf-rs parses every number with
//! `f64::from_str` after trimming spaces, as the built-in reader does, so the same decimal gives
//! the same angle and the same verdict (`tests/urdf_rs_parity.rs` checks every URDF in the
//! repository both ways, with the policy on and off).
//!
//! What urdf-rs does not keep, the conversion cannot report: [`Description::from_urdf_rs`] lists it.
//!
//! The feature is off by default; the facade's `urdf-rs` feature forwards to it. It takes the
//! `urdf_rs::Robot` of urdf-rs 0.9, the version `k` 0.32 uses, through `Description::from_urdf_rs`
//! and `KinematicTree::from_urdf_rs(robot, ExactAngles)`. Errors name the joint without a line, and
//! a moving joint whose limits are urdf-rs's all-zero stand-in for a missing `<limit>` is refused.
//! A link without `<inertial>` comes from urdf-rs with a massless one, which the model reads as
//! none, as it reads a written zero mass with a zero tensor. `tests/urdf_rs_parity.rs` requires
//! equal trees from both readers (trees do not compare lines), or the same refusal.

use urdf_rs::{JointLimit, JointType};

use crate::angle::Angle;
use crate::collision::{Collision, Shape};
use crate::description::{
    CollisionDescription, Description, InertialDescription, JointDescription, JointTypeDescription, LimitsDescription,
    MimicDescription,
};
use crate::error::{Element, LoadErrorKind};
use crate::exactness::ExactAngles;
use crate::inertia::Inertial;
use crate::transform::FixedTransform;
use crate::tree::KinematicTree;
use crate::urdf::{UrdfJoint, needs_limit};

impl Description {
    /// The description of a robot urdf-rs has read: what [`crate::urdf::parse_urdf`] gives for
    /// the same file (no model rule is checked yet). Faults urdf-rs leaves to the reader are
    /// [`LoadErrorKind::Value`] errors naming the joint.
    ///
    /// What urdf-rs does not keep, the conversion cannot report:
    ///
    /// - errors name the joint (or the robot) but no line;
    /// - a revolute or prismatic joint without `<limit>` reads as limits all zero (lower, upper,
    ///   effort, velocity): such a joint is refused, as the built-in reader refuses the missing
    ///   element (a written all-zero limit, which no moving joint means, is refused with it);
    /// - a `<limit>` without `effort` reads as effort 0, which cannot be told from a written 0, so it
    ///   is kept (the built-in reader refuses the missing attribute; no kinematics uses the effort);
    /// - a robot without a `name` reads as the empty name: refused;
    /// - a word that is no number inside `xyz` or `rpy` is skipped by urdf-rs (`"1 x 0 0"` reads as
    ///   `1 0 0`), where the built-in reader refuses the attribute; after reading nothing shows it;
    /// - an `<origin quat_xyzw>` becomes `rpy` in a URDF 1.1 file (so the rotation is kept, where
    ///   the built-in reader refuses the attribute) and is ignored in a 1.0 file, as urdfdom does;
    /// - a link without `<inertial>` reads as urdf-rs's default, mass 0 and a zero tensor at the
    ///   link's origin, which cannot be told from such a written `<inertial>`; the model reads
    ///   both as a massless link (no inertial), so nothing is lost.
    ///
    /// Where URDF itself gives a default (no `<origin>`, no `<axis>`, no mimic `multiplier` or
    /// `offset`), urdf-rs and the built-in reader give the same one.
    ///
    /// ```
    /// use kinematics_model::{Description, KinematicTree, urdf_rs};
    /// let robot = urdf_rs::read_from_string(r#"<robot name="r"><link name="a"/><link name="b"/>
    ///   <joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint></robot>"#)?;
    /// // urdf-rs reads the missing <limit> as zeros; the model refuses the joint, by name.
    /// let error = Description::from_urdf_rs(&robot).unwrap_err();
    /// assert!(error.to_string().starts_with("joint `j`: a revolute joint needs a <limit> element"));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[cfg_attr(docsrs, doc(cfg(feature = "urdf-rs")))]
    pub fn from_urdf_rs(robot: &urdf_rs::Robot) -> Result<Description, LoadErrorKind> {
        if robot.name.is_empty() {
            return Err(LoadErrorKind::Value {
                element: Element::Robot,
                message: "<robot> needs a `name` attribute (urdf-rs reads a missing one as empty)".to_owned(),
            });
        }
        Ok(Description {
            name: robot.name.clone(),
            links: robot.links.iter().map(|l| l.name.clone()).collect(),
            joints: robot.joints.iter().map(joint).collect::<Result<_, _>>()?,
            collisions: robot.links.iter().flat_map(collisions).collect(),
            ignored: Vec::new(),
            excluded_pairs: Vec::new(),
            inertials: robot.links.iter().map(inertial).collect(),
            inertia_from_geometry: Vec::new(),
        })
    }
}

/// A link's collision geometry as the built-in reader gives it (no line: urdf-rs keeps none).
fn collisions(link: &urdf_rs::Link) -> Vec<CollisionDescription> {
    link.collision
        .iter()
        .map(|c| {
            let (xyz, rpy) = (c.origin.xyz.0, c.origin.rpy.0);
            let shape = match &c.geometry {
                urdf_rs::Geometry::Sphere { radius } => Shape::Sphere { radius: *radius },
                urdf_rs::Geometry::Box { size } => Shape::Box { size: size.0 },
                urdf_rs::Geometry::Cylinder { radius, length } => Shape::Cylinder { radius: *radius, length: *length },
                urdf_rs::Geometry::Capsule { radius, length } => Shape::Capsule { radius: *radius, length: *length },
                urdf_rs::Geometry::Mesh { filename, scale } => {
                    Shape::Mesh { filename: filename.clone(), scale: scale.map_or([1.0; 3], |s| s.0), loaded: None }
                }
            };
            CollisionDescription {
                link: link.name.clone(),
                line: None,
                collision: Collision { origin: FixedTransform::from_xyz_rpy(xyz, rpy.map(Angle::Radians)), shape },
            }
        })
        .collect()
}

/// A link's mass and inertia as urdf-rs gives them (no line: urdf-rs keeps none).
///
/// urdf-rs cannot tell a link without `<inertial>`: `urdf_rs::Link::inertial` is no `Option`
/// but a field read with `#[serde(default)]`, so a missing element is `Inertial::default()`
/// (mass 0, a zero tensor, at the link's origin), the same value as a written all-zero
/// `<inertial>`. The conversion takes what it gives, and the model reads a zero mass with a zero
/// tensor as no inertial, as it reads the built-in reader's missing one (a massless link). Inside an `<inertial>`, urdf-rs requires `<mass value>` and all six `<inertia>`
/// entries and refuses a second `<inertial>` ("duplicate field"), as urdfdom and the built-in
/// reader do.
fn inertial(link: &urdf_rs::Link) -> InertialDescription {
    let i = &link.inertial;
    let (xyz, rpy) = (i.origin.xyz.0, i.origin.rpy.0);
    let t = &i.inertia;
    InertialDescription {
        link: link.name.clone(),
        line: None,
        inertial: Inertial {
            mass: i.mass.value,
            origin: FixedTransform::from_xyz_rpy(xyz, rpy.map(Angle::Radians)),
            inertia: [t.ixx, t.ixy, t.ixz, t.iyy, t.iyz, t.izz],
        },
    }
}

impl KinematicTree {
    /// The validated tree of a robot urdf-rs has read, with the exactness policy
    /// `exact_angles`: [`Description::from_urdf_rs`], then the rules and the policy of
    /// [`KinematicTree::from_description_with`], as [`crate::Source::load`] does for a file.
    /// Model faults come as [`LoadErrorKind::Model`], naming the joint or link (no line).
    ///
    /// A user of `k` compiles the robot already loaded; the tree is the one the built-in reader
    /// gives for the same file:
    ///
    /// ```
    /// use kinematics_model::{ExactAngles, KinematicTree, parse_source, urdf_rs};
    /// let file = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/ur5_ros.urdf");
    /// let robot = urdf_rs::read_file(file)?;
    /// let tree = KinematicTree::from_urdf_rs(&robot, ExactAngles::default())?;
    /// assert_eq!(tree, parse_source("ur5_ros.urdf", &std::fs::read_to_string(file)?)?);
    /// // xacro's decimal pi is read as exact, as the built-in reader reads it.
    /// assert!(!tree.recognised_angles().is_empty());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[cfg_attr(docsrs, doc(cfg(feature = "urdf-rs")))]
    pub fn from_urdf_rs(robot: &urdf_rs::Robot, exact_angles: ExactAngles) -> Result<KinematicTree, LoadErrorKind> {
        let description = Description::from_urdf_rs(robot)?;
        KinematicTree::from_description_with(&description, exact_angles).map_err(LoadErrorKind::Model)
    }
}

/// One joint, by the built-in reader's rules.
fn joint(j: &urdf_rs::Joint) -> Result<JointDescription, LoadErrorKind> {
    let kind = match j.joint_type {
        JointType::Revolute => JointTypeDescription::Revolute,
        JointType::Continuous => JointTypeDescription::Continuous,
        JointType::Prismatic => JointTypeDescription::Prismatic,
        JointType::Fixed => JointTypeDescription::Fixed,
        JointType::Floating => JointTypeDescription::Floating,
        JointType::Planar => JointTypeDescription::Planar,
        JointType::Spherical => JointTypeDescription::Spherical,
    };
    if needs_limit(kind) && reads_as_missing(&j.limit) {
        return Err(LoadErrorKind::Value {
            element: Element::Joint(j.name.clone()),
            message: format!(
                "a {} joint needs a <limit> element (with `effort` and `velocity`); urdf-rs reads a missing one as all zeros, which this joint has",
                kind.name()
            ),
        });
    }
    let limit = &j.limit;
    Ok(UrdfJoint {
        name: j.name.clone(),
        kind,
        parent: j.parent.link.clone(),
        child: j.child.link.clone(),
        xyz: j.origin.xyz.0,
        rpy: j.origin.rpy.0,
        axis: j.axis.xyz.0,
        limit: Some(LimitsDescription {
            lower: limit.lower,
            upper: limit.upper,
            velocity: Some(limit.velocity),
            effort: Some(limit.effort),
        }),
        // URDF's defaults (urdfdom's), which urdf-rs leaves to the reader as `None`.
        mimic: j.mimic.as_ref().map(|m| MimicDescription {
            joint: m.joint.clone(),
            multiplier: m.multiplier.unwrap_or(1.0),
            offset: m.offset.unwrap_or(0.0),
        }),
    }
    .description())
}

/// Whether `limit` is what urdf-rs gives a joint without `<limit>` (its `Default`: every field 0).
fn reads_as_missing(limit: &JointLimit) -> bool {
    let missing = JointLimit::default();
    [limit.lower, limit.upper, limit.effort, limit.velocity]
        == [missing.lower, missing.upper, missing.effort, missing.velocity]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn robot(joint: &str) -> urdf_rs::Robot {
        let text = format!(
            r#"<robot name="arm"><link name="base"/><link name="upper"/>
            <joint name="elbow" {joint}<parent link="base"/><child link="upper"/></joint></robot>"#
        );
        urdf_rs::read_from_string(&text).unwrap_or_else(|e| panic!("urdf-rs reads {text}: {e}"))
    }

    fn error(joint: &str) -> String {
        match KinematicTree::from_urdf_rs(&robot(joint), ExactAngles::default()) {
            Ok(_) => panic!("{joint} is accepted"),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn a_zero_axis_is_refused_naming_the_joint_without_a_line() {
        let message = error(r#"type="continuous"><axis xyz="0 0 0"/>"#);
        assert_eq!(message, "joint `elbow`: axis is zero");
    }

    #[test]
    fn a_missing_limit_is_refused_naming_the_joint_without_a_line() {
        for kind in ["revolute", "prismatic"] {
            assert_eq!(
                error(&format!(r#"type="{kind}">"#)),
                format!(
                    "joint `elbow`: a {kind} joint needs a <limit> element (with `effort` and `velocity`); urdf-rs reads a missing one as all zeros, which this joint has"
                )
            );
        }
        // A continuous joint needs none, and one limit that is not all zero is kept.
        assert!(KinematicTree::from_urdf_rs(&robot(r#"type="continuous">"#), ExactAngles::default()).is_ok());
        let tree =
            KinematicTree::from_urdf_rs(&robot(r#"type="revolute"><limit velocity="1"/>"#), ExactAngles::default())
                .unwrap_or_else(|e| panic!("{e}"));
        let elbow = tree.joint_by_name("elbow").unwrap_or_else(|| panic!("no elbow"));
        assert_eq!((elbow.velocity_limit, elbow.effort_limit), (Some(1.0), Some(0.0)));
    }

    #[test]
    fn a_robot_without_a_name_is_refused() {
        let robot = urdf_rs::read_from_string(r#"<robot><link name="base"/></robot>"#)
            .unwrap_or_else(|e| panic!("urdf-rs reads it: {e}"));
        let message = Description::from_urdf_rs(&robot).unwrap_err().to_string();
        assert_eq!(message, "robot: <robot> needs a `name` attribute (urdf-rs reads a missing one as empty)");
    }

    #[test]
    fn model_faults_come_through_with_every_joint_named() {
        let text = r#"<robot name="arm"><link name="base"/><link name="a"/>
            <joint name="j1" type="continuous"><parent link="base"/><child link="a"/><axis xyz="0 0 0"/></joint>
            <joint name="j2" type="revolute"><parent link="base"/><child link="b"/>
              <limit lower="1" upper="-1" effort="1" velocity="1"/></joint></robot>"#;
        let robot = urdf_rs::read_from_string(text).unwrap_or_else(|e| panic!("{e}"));
        let message = KinematicTree::from_urdf_rs(&robot, ExactAngles::default()).unwrap_err().to_string();
        assert_eq!(
            message,
            "joint `j1`: axis is zero; joint `j2`: lower limit 1 is greater than upper limit -1; \
             joint `j2`: child link `b` does not exist"
        );
    }
}
