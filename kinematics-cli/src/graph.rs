//! `kinematics graph FILE`: the tree as Graphviz DOT, as ROS's `urdf_to_graphviz` draws it.

use std::io::Write;

use kinematics::model::{JointMotion, KinematicTree};

use crate::error::CliError;

/// Arguments of `graph`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml), MJCF file (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
}

/// Prints the DOT graph (render with `dot -Tpdf`).
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let tree = crate::robot::load(&args.file)?;
    write!(out, "{}", dot(&tree))?;
    Ok(())
}

/// A DOT string literal.
fn quoted(text: &str) -> String {
    format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\"").replace('\n', "\\n"))
}

/// Links as boxes, joints as edges from parent to child labelled with the joint's name and type
/// (and its DoF index or mimic source).
pub fn dot(tree: &KinematicTree) -> String {
    let mut out = format!("digraph {} {{\n", quoted(tree.name()));
    out +=
        "  rankdir=TB;\n  node [shape=box, fontname=\"Helvetica\"];\n  edge [fontname=\"Helvetica\", fontsize=10];\n";
    for link in tree.links() {
        out += &format!("  {};\n", quoted(&link.name));
    }
    for joint in tree.joints() {
        let value = match joint.motion {
            JointMotion::Fixed => String::new(),
            JointMotion::Dof(i) => format!(" {}", crate::inspect::entries(i, joint.kind.positions()).trim_start()),
            JointMotion::Mimic { source, .. } => format!(" mimics {}", tree.joint(source).name),
        };
        let label = format!("{}\n{}{value}", joint.name, joint.kind.name());
        out += &format!(
            "  {} -> {} [label={}];\n",
            quoted(&tree.link(joint.parent).name),
            quoted(&tree.link(joint.child).name),
            quoted(&label)
        );
    }
    out += "}\n";
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn names_are_quoted() {
        assert_eq!(super::quoted("Sonar/Left \"x\"\\"), "\"Sonar/Left \\\"x\\\"\\\\\"");
        assert_eq!(super::quoted("a\nb"), "\"a\\nb\"");
    }
}
