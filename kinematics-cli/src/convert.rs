//! `kinematics convert FILE -o robot.urdf`: the kinematics of a description (an MJCF file, a DH
//! table, a URDF) as URDF, so ROS tools can read it: links, joints with their types, origins,
//! axes, limits and mimic relations. Geometry, inertia and everything else are left out, and the
//! file says so in a comment.
//!
//! URDF writes a joint's fixed transform as one `<origin xyz rpy>` before the motion. The tree's
//! fixed transforms (products of elementary steps) are multiplied out with the runtime
//! reference's `fixed_isometry` and written as `xyz` and roll, pitch, yaw (numbers to the last
//! bit, which the exactness policy reads back as it read the original). A transform after the
//! motion (an MJCF hinge off its body's origin, a standard DH row's constants) has no place in a
//! URDF joint: the joint then moves a link `<joint>.frame`, to which the child is fixed by a
//! joint `<joint>.offset` carrying that transform.
//!
//! URDF has no spherical joint (an MJCF `ball`: its `spherical` type is not in the specification,
//! and no URDF joint takes a quaternion): a robot with one is refused, naming the joint, and
//! nothing is written.
//!
//! The refusal is `CliError::NotUrdf`.

use std::io::Write;

use kinematics::model::{FixedTransform, JointKind, JointMotion, KinematicTree};

use crate::error::CliError;

/// Arguments of `convert`.
#[derive(clap::Args)]
pub struct Args {
    /// A description: URDF (.urdf, .xml), MJCF (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
    /// Write to this file (atomically) instead of standard output.
    #[arg(short, long)]
    output: Option<std::path::PathBuf>,
}

/// Writes the URDF of `args.file`'s kinematics.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let tree = crate::robot::load(&args.file)?;
    let text = urdf(&tree, &args.file)?;
    crate::error::deliver(&text, args.output.as_deref(), &args.file, out)
}

/// The URDF text of `tree`'s kinematics; `file` names the source in the header comment and the
/// error. A spherical joint, which URDF cannot write, is [`CliError::NotUrdf`].
pub fn urdf(tree: &KinematicTree, file: &str) -> Result<String, CliError> {
    if let Some(joint) = tree.joints().iter().find(|j| j.kind == JointKind::Spherical) {
        return Err(CliError::NotUrdf { file: file.to_owned(), joint: joint.name.clone(), kind: joint.kind.name() });
    }
    let mut out = String::from("<?xml version=\"1.0\"?>\n");
    out += &format!(
        "<!-- The kinematics of {} as URDF, written by `kinematics convert`: links, joints, origins, axes,\n     \
         limits and mimic relations. Geometry, inertia, actuators and everything else the source says\n     \
         are left out. -->\n",
        comment(file)
    );
    for ignored in tree.ignored() {
        out += &format!("<!-- Not applied in the source: {} -->\n", comment(ignored));
    }
    out += &format!("<robot name=\"{}\">\n", escape(tree.name()));
    for link in tree.links() {
        out += &format!("  <link name=\"{}\"/>\n", escape(&link.name));
    }
    for joint in tree.joints() {
        let parent = &tree.link(joint.parent).name;
        let child = &tree.link(joint.child).name;
        let split = !joint.after_motion.is_identity();
        let moved = if split { format!("{}.frame", joint.name) } else { child.clone() };
        if split {
            out += &format!("  <link name=\"{}\"/>\n", escape(&moved));
        }
        out += &format!("  <joint name=\"{}\" type=\"{}\">\n", escape(&joint.name), kind(joint.kind, joint.limits));
        out += &format!("    <parent link=\"{}\"/>\n    <child link=\"{}\"/>\n", escape(parent), escape(&moved));
        out += &origin(&joint.origin);
        if !matches!(joint.kind, JointKind::Fixed | JointKind::Floating) {
            out += &format!("    <axis xyz=\"{}\"/>\n", numbers(&joint.axis));
        }
        if matches!(joint.kind, JointKind::Revolute | JointKind::Prismatic) {
            // URDF requires both; a source without them (MJCF) gets 0, which no kinematics uses.
            let (lower, upper) = joint.limits.map_or((f64::NEG_INFINITY, f64::INFINITY), |l| (l.lower, l.upper));
            out += &format!(
                "    <limit lower=\"{}\" upper=\"{}\" effort=\"{}\" velocity=\"{}\"/>\n",
                number(lower),
                number(upper),
                number(joint.effort_limit.unwrap_or(0.0)),
                number(joint.velocity_limit.unwrap_or(0.0))
            );
        }
        if let JointMotion::Mimic { source, multiplier, offset, .. } = joint.motion {
            out += &format!(
                "    <mimic joint=\"{}\" multiplier=\"{}\" offset=\"{}\"/>\n",
                escape(&tree.joint(source).name),
                number(multiplier),
                number(offset)
            );
        }
        out += "  </joint>\n";
        if split {
            out += &format!("  <joint name=\"{}.offset\" type=\"fixed\">\n", escape(&joint.name));
            out += &format!("    <parent link=\"{}\"/>\n    <child link=\"{}\"/>\n", escape(&moved), escape(child));
            out += &origin(&joint.after_motion);
            out += "  </joint>\n";
        }
    }
    out += "</robot>\n";
    Ok(out)
}

/// URDF's type name; a prismatic joint without limits is written with infinite ones.
fn kind(kind: JointKind, limits: Option<kinematics::model::Limits>) -> &'static str {
    match kind {
        JointKind::Revolute if limits.is_none() => "continuous",
        other => other.name(),
    }
}

/// `<origin xyz rpy>` of a fixed transform, multiplied out (nothing for the identity).
fn origin(transform: &FixedTransform) -> String {
    if transform.is_identity() {
        return String::new();
    }
    let iso = kinematics::runtime::fixed_isometry(transform);
    let (roll, pitch, yaw) = iso.rotation.euler_angles();
    let xyz: [f64; 3] = iso.translation.vector.into();
    format!("    <origin xyz=\"{}\" rpy=\"{}\"/>\n", numbers(&xyz), numbers(&[roll, pitch, yaw]))
}

/// A number as Rust prints it: the shortest text that reads back as the same `f64`.
fn number(x: f64) -> String {
    match x {
        f64::INFINITY => "inf".to_owned(),
        f64::NEG_INFINITY => "-inf".to_owned(),
        // -0 too (the pattern compares as `==` does): it reads back as 0 for every use here.
        0.0 => "0".to_owned(),
        x => format!("{x}"),
    }
}

fn numbers(v: &[f64]) -> String {
    v.iter().map(|&x| number(x)).collect::<Vec<_>>().join(" ")
}

/// A name as an XML attribute value.
pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('"', "&quot;").replace('<', "&lt;").replace('>', "&gt;")
}

/// Text inside an XML comment, which may not hold `--`: a space between every two dashes in a
/// row (`---` is `- - -`).
pub fn comment(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c == '-' && out.ends_with('-') {
            out.push(' ');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_comment_holds_no_double_dash() {
        assert_eq!(super::comment("a--b"), "a- -b");
        assert_eq!(super::comment("---"), "- - -");
        assert_eq!(super::comment("--spheres 8 -x"), "- -spheres 8 -x");
        for text in ["-", "----", "a-b--c---d", "--"] {
            assert!(!super::comment(text).contains("--"), "{text}");
        }
    }
}
