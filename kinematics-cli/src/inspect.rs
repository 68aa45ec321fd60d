//! `kinematics inspect FILE`: the tree as text.

use std::io::Write;

use kinematics::model::{JointMotion, KinematicTree, LinkId};

use crate::error::CliError;

/// Arguments of `inspect`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml) or DH table (.toml, .json).
    file: String,
}

/// Prints the tree of `args.file`.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let tree = crate::robot::load(&args.file)?;
    write!(out, "{}", describe(&tree))?;
    Ok(())
}

/// A number in at most 6 decimals, without trailing zeros (`1`, `-0.5`, `0.707107`).
pub fn short(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.') } else { &s };
    if s == "-0" { "0".to_owned() } else { s.to_owned() }
}

/// The tree: counts, links, one line per joint (type, parent -> child, axis, limits, where its
/// value comes from), the DoF order, and the chain from the root to each leaf.
pub fn describe(tree: &KinematicTree) -> String {
    let mut out = format!(
        "robot `{}`: {} links, {} joints, {} degrees of freedom\n",
        tree.name(),
        tree.links().len(),
        tree.joints().len(),
        tree.dof()
    );
    out += &format!("root link: {}\n", tree.link(tree.root()).name);
    let links: Vec<&str> = tree.links().iter().map(|l| l.name.as_str()).collect();
    out += &format!("links (depth-first from the root): {}\n", links.join(", "));
    out += "joints (depth-first from the root):\n";
    let name_width = tree.joints().iter().map(|j| j.name.len()).max().unwrap_or(0);
    let edges: Vec<String> =
        tree.joints().iter().map(|j| format!("{} -> {}", tree.link(j.parent).name, tree.link(j.child).name)).collect();
    let edge_width = edges.iter().map(String::len).max().unwrap_or(0);
    for (joint, edge) in tree.joints().iter().zip(&edges) {
        let mut line = format!("  {:<name_width$}  {:<10} {:<edge_width$}", joint.name, joint.kind.name(), edge);
        if joint.kind.name() != "fixed" {
            let [x, y, z] = joint.axis.map(short);
            line += &format!("  axis ({x}, {y}, {z})");
        }
        if let Some(l) = joint.limits {
            line += &format!("  limits [{}, {}]", short(l.lower), short(l.upper));
        }
        match joint.motion {
            JointMotion::Fixed => {}
            JointMotion::Dof(i) => line += &format!("  q[{i}]"),
            JointMotion::Mimic { source, dof, multiplier, offset } => {
                line += &format!(
                    "  mimics {} = {} * q[{dof}] + {}",
                    tree.joint(source).name,
                    short(multiplier),
                    short(offset)
                );
            }
        }
        out += line.trim_end();
        out.push('\n');
    }
    let dofs: Vec<String> = tree.dof_names().iter().enumerate().map(|(i, n)| format!("q[{i}] {n}")).collect();
    out += &format!("DoF order: {}\n", if dofs.is_empty() { "none".to_owned() } else { dofs.join(", ") });
    out += "chains from the root to each leaf:\n";
    for (index, link) in tree.links().iter().enumerate() {
        if !link.child_joints.is_empty() || link.parent_joint.is_none() {
            continue;
        }
        let path = tree.path_from_root(LinkId(index));
        let mut names = vec![tree.link(tree.root()).name.as_str()];
        names.extend(path.iter().map(|&j| tree.link(tree.joint(j).child).name.as_str()));
        let root = &tree.link(tree.root()).name;
        let dofs = tree.chain(root, &link.name).map(|c| tree.chain_dofs(&c)).unwrap_or_default();
        let dofs: Vec<String> = dofs.iter().map(|i| format!("q[{i}]")).collect();
        out += &format!(
            "  {}: {} joint{}, DoF {}: {}\n",
            link.name,
            path.len(),
            if path.len() == 1 { "" } else { "s" },
            if dofs.is_empty() { "none".to_owned() } else { dofs.join(" ") },
            names.join(" -> ")
        );
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn numbers_are_short() {
        for (x, expected) in
            [(1.0, "1"), (-0.5, "-0.5"), (0.0, "0"), (-0.0, "0"), (1.0 / 3.0, "0.333333"), (-1e-9, "0")]
        {
            assert_eq!(super::short(x), expected, "{x}");
        }
    }
}
