//! The roxmltree reader gives the very tree the urdf-rs reader gave, for every URDF in `robots/`.

use kinematics_model::{
    Angle, Description, Element, FixedTransform, JointDescription, JointTypeDescription, KinematicTree,
    LimitsDescription, MimicDescription,
};

fn parse_with_urdf_rs(text: &str) -> Description {
    let robot = urdf_rs::read_from_string(text).unwrap();
    Description {
        name: robot.name.clone(),
        links: robot.links.iter().map(|l| l.name.clone()).collect(),
        joints: robot.joints.iter().map(joint).collect(),
    }
}

fn joint(j: &urdf_rs::Joint) -> JointDescription {
    let kind = match j.joint_type {
        urdf_rs::JointType::Revolute => JointTypeDescription::Revolute,
        urdf_rs::JointType::Continuous => JointTypeDescription::Continuous,
        urdf_rs::JointType::Prismatic => JointTypeDescription::Prismatic,
        urdf_rs::JointType::Fixed => JointTypeDescription::Fixed,
        urdf_rs::JointType::Floating => JointTypeDescription::Floating,
        urdf_rs::JointType::Planar => JointTypeDescription::Planar,
        urdf_rs::JointType::Spherical => JointTypeDescription::Spherical,
    };
    let rpy = j.origin.rpy.0.map(Angle::Radians);
    let limited = matches!(kind, JointTypeDescription::Revolute | JointTypeDescription::Prismatic);
    JointDescription {
        name: j.name.clone(),
        element: Element::Joint(j.name.clone()),
        kind,
        parent: j.parent.link.clone(),
        child: j.child.link.clone(),
        origin: FixedTransform::from_xyz_rpy(j.origin.xyz.0, rpy),
        after_motion: FixedTransform::identity(),
        axis: j.axis.xyz.0,
        limits: limited.then_some(LimitsDescription {
            lower: j.limit.lower,
            upper: j.limit.upper,
            velocity: Some(j.limit.velocity),
            effort: Some(j.limit.effort),
        }),
        mimic: j.mimic.as_ref().map(|m| MimicDescription {
            joint: m.joint.clone(),
            multiplier: m.multiplier.unwrap_or(1.0),
            offset: m.offset.unwrap_or(0.0),
        }),
    }
}

#[test]
fn every_robot_reads_as_urdf_rs_read_it() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "urdf") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let old = KinematicTree::from_description(&parse_with_urdf_rs(&text)).unwrap();
        let new = KinematicTree::from_description(&kinematics_model::urdf::parse_urdf(&text).unwrap()).unwrap();
        assert_eq!(old, new, "{}", path.display());
        count += 1;
    }
    assert!(count >= 10, "{count}");
}
