//! `kinematics inspect FILE`: the tree as text.
//!
//! Then its links' masses (each link's mass, centre of mass and principal moments, and what breaks
//! a rigid body's rules), its collision geometry (shapes, spheres, bounding spheres, pairs, at a
//! cover and SRDF of the user's choice), and each leaf's closed-form inverse kinematics family.

use std::io::Write;

use kinematics::model::{Chain, ExactAngles, JointKind, JointMotion, KinematicTree};

use crate::error::CliError;

/// Arguments of `inspect`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml), MJCF file (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
    /// How the geometry becomes spheres, and where meshes are.
    #[command(flatten)]
    cover: crate::cover::CoverArgs,
    /// An SRDF whose disabled pairs the self-collision pairs leave out.
    #[arg(long, value_name = "FILE")]
    srdf: Option<String>,
    /// List every collision sphere (its centre in its link's frame and its radius).
    #[arg(long)]
    list_spheres: bool,
}

/// Prints the tree of `args.file`, then its collision geometry.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let cover = args.cover.cover()?;
    let mut tree = crate::robot::load(&args.file)?;
    // A mesh not found spoils only the collision part: the tree is listed, and the mesh's error
    // stands where the spheres would.
    let unread = args.cover.read_meshes(&mut tree, &args.file).err();
    write!(out, "{}", describe(&tree))?;
    write!(out, "{}", inertias(&tree))?;
    if let Some(error) = unread {
        writeln!(out, "collision geometry: not covered: {error}\n  (or leave meshes out: --skip-meshes)")?;
        return Ok(());
    }
    let srdf = match &args.srdf {
        Some(path) => Some((path.clone(), crate::robot::load_srdf(path, &tree)?)),
        None => None,
    };
    let view = CollisionView { cover, meshes: args.cover.meshes(), srdf: srdf.as_ref(), spheres: args.list_spheres };
    write!(out, "{}", collision(&tree, &view).map_err(|fault| CliError::Usage(format!("{}: {fault}", args.file)))?)?;
    Ok(())
}

/// How `inspect` shows collision geometry: at which cover, with which SRDF's disabled pairs,
/// and whether every sphere is listed.
pub struct CollisionView<'a> {
    /// How the geometry becomes spheres.
    pub cover: kinematics::model::collision::Cover,
    /// Whether meshes (read into the tree beforehand) are covered or left out.
    pub meshes: kinematics::model::collision::Meshes,
    /// The SRDF read, with its file name, and its disabled pairs.
    pub srdf: Option<&'a (String, std::collections::BTreeSet<(kinematics::model::LinkId, kinematics::model::LinkId)>)>,
    /// Whether to list every sphere.
    pub spheres: bool,
}

/// The links' collision geometry: each link's shapes, how many spheres cover them, what the
/// cover costs (its overshoot bound, the sampled overshoot of its spheres' surface, its volume
/// against the geometry's) and its bounding sphere (and with `spheres` each sphere), and the link
/// pairs a self-collision check tests; fixed joints whose mimic had nothing to do. A link the
/// cover cannot make is the error returned.
pub fn collision(tree: &KinematicTree, view: &CollisionView<'_>) -> Result<String, String> {
    use kinematics::model::collision::{LinkSphere, Meshes, link_covers};
    let mut out = String::new();
    if !tree.vacuous_mimics().is_empty() {
        out +=
            &format!("fixed joints whose mimic of a fixed joint does nothing: {}\n", tree.vacuous_mimics().join(", "));
    }
    let with: Vec<_> = tree.links().iter().filter(|l| !l.collisions.is_empty()).collect();
    if with.is_empty() {
        out += "collision geometry: none\n";
        return Ok(out);
    }
    let covers = link_covers(tree, &view.cover, view.meshes).map_err(|e| e.to_string())?;
    let spheres: Vec<LinkSphere> = covers
        .iter()
        .flat_map(|(link, c)| c.spheres.iter().map(|&sphere| LinkSphere { link: *link, sphere }))
        .collect();
    let layout = kinematics_compiler::collision_layout::CollisionLayout::new(&spheres);
    let count = |n: usize, thing: &str| if n == 1 { format!("1 {thing}") } else { format!("{n} {thing}s") };
    out += &format!(
        "collision geometry: {} on {}, {} ({}{})\n",
        count(with.iter().map(|l| l.collisions.len()).sum::<usize>(), "element"),
        count(with.len(), "link"),
        count(spheres.len(), "sphere"),
        crate::cover::CoverArgs::describe(&view.cover),
        if view.meshes == Meshes::Skip { "; meshes left out" } else { "" }
    );
    out += &link_lines(tree, view, &with, &covers, &spheres, &layout)?;
    let root = &tree.link(tree.root()).name;
    match layout.op_counts(tree, root) {
        Ok((centers, poses)) => {
            out += &format!("operations of `sphere_centers` in `{root}`: {centers}\n");
            out += &format!("operations of the links' poses the checks take: {poses}\n");
        }
        Err(e) => out += &format!("operations: not compiled ({e})\n"),
    }
    out += &pair_lines(tree, view, &spheres);
    Ok(out)
}

/// One line per link with geometry (its shapes, spheres and bounding sphere), one with its
/// cover's report, and with `view.spheres` each sphere.
fn link_lines(
    tree: &KinematicTree,
    view: &CollisionView<'_>,
    with: &[&kinematics::model::Link],
    covers: &[(kinematics::model::LinkId, kinematics::model::collision::LinkCover)],
    spheres: &[kinematics::model::collision::LinkSphere],
    layout: &kinematics_compiler::collision_layout::CollisionLayout,
) -> Result<String, String> {
    let mut out = String::new();
    let width = column_width(with.iter().map(|l| l.name.as_str()));
    let point = |p: [f64; 3]| format!("({}, {}, {})", short(p[0]), short(p[1]), short(p[2]));
    for link in with.iter().copied() {
        // Each kind once, with how many of it (meshes by file).
        let mut shapes: Vec<(String, usize)> = Vec::new();
        for c in &link.collisions {
            let name = match &c.shape {
                kinematics::model::collision::Shape::Mesh { filename, .. } => format!("mesh {filename}"),
                shape => shape.name().to_owned(),
            };
            match shapes.iter_mut().find(|(n, _)| *n == name) {
                Some((_, count)) => *count += 1,
                None => shapes.push((name, 1)),
            }
        }
        let shapes: Vec<String> =
            shapes.into_iter().map(|(n, k)| if k == 1 { n } else { format!("{k} x {n}") }).collect();
        let frame = layout.links.iter().position(|&l| tree.link(l).name == link.name);
        let own: Vec<usize> = (0..spheres.len()).filter(|&k| Some(layout.points[k].0) == frame).collect();
        let bound = match frame {
            Some(f) => format!("; bounding sphere {} m at {}", short(layout.bounds[f].1), point(layout.bounds[f].0)),
            None => String::new(),
        };
        let count = if own.len() == 1 { "1 sphere".to_owned() } else { format!("{} spheres", own.len()) };
        out += &format!("  {}  {count}: {}{bound}\n", pad(&link.name, width), shapes.join(", "));
        if let Some((id, c)) = covers.iter().find(|(l, _)| tree.link(*l).name == link.name) {
            let r = kinematics::model::collision::cover_report(tree, *id, c, view.meshes).map_err(|e| e.to_string())?;
            out += &format!(
                "  {}  overshoot at most {} m (sampled on the spheres: largest {} m, mean {} m); volume {} of the geometry's {} m^3\n",
                pad("", width),
                short(r.bound),
                short(r.beyond_max),
                short(r.beyond_mean),
                ratio(r.cover_volume, r.geometry_volume),
                short(r.geometry_volume),
            );
        }
        if view.spheres {
            for k in own {
                out += &format!("    {} m at {}\n", short(spheres[k].sphere.radius), point(layout.points[k].1));
            }
        }
    }
    Ok(out)
}

/// The self-collision pairs and their rule, the sphere pairs held apart for good, and the pairs
/// decided ahead of time by grids.
fn pair_lines(
    tree: &KinematicTree,
    view: &CollisionView<'_>,
    spheres: &[kinematics::model::collision::LinkSphere],
) -> String {
    use kinematics::model::collision::{fixed_apart_pairs, pair_grids, sphere_pairs};
    let mut out = String::new();
    let pairs = sphere_pairs(tree, spheres, view.srdf.map(|(_, disabled)| disabled));
    let mut rule = match view.srdf {
        Some((file, _)) => format!("less the pairs {file} disables"),
        None => "less those of bodies joined by one joint, no SRDF given".to_owned(),
    };
    for excluded in tree.excluded_pairs() {
        rule += &format!(", less {}-{} ({})", excluded.link1, excluded.link2, excluded.why);
    }
    let names: Vec<String> =
        pairs.pairs.iter().map(|&(a, b)| format!("{}-{}", tree.link(a).name, tree.link(b).name)).collect();
    out += &format!(
        "self-collision pairs: {} (links with spheres on different rigid bodies, {rule}): {}\n",
        pairs.pairs.len(),
        names.join(", ")
    );
    let fixed = fixed_apart_pairs(tree, spheres, &pairs.pairs);
    let sphere = |k: usize| {
        let link = &tree.link(spheres[k].link).name;
        let index = spheres[..k].iter().filter(|s| s.link == spheres[k].link).count();
        format!("{link} #{index}")
    };
    let held: Vec<String> =
        fixed.iter().map(|f| format!("{}-{} ({} m)", sphere(f.a), sphere(f.b), short(f.distance))).collect();
    out += &format!(
        "sphere pairs held apart for good (no joint moves them; the distances leave them out): {}{}\n",
        fixed.len(),
        if held.is_empty() { String::new() } else { format!(": {}", held.join(", ")) }
    );
    let grids = pair_grids(tree, spheres, &pairs.pairs);
    out += &format!(
        "self-collision grids (pairs decided ahead of time by the values of the one or two joints that move them): {}\n",
        grids.len()
    );
    for grid in &grids {
        let names: Vec<String> =
            grid.pairs.iter().map(|&(a, b)| format!("{}-{}", tree.link(a).name, tree.link(b).name)).collect();
        let joints: Vec<&str> = grid.joints.iter().map(|&j| tree.joint(j).name.as_str()).collect();
        let (free, colliding, test) = grid.counts();
        let share = |n: usize| format!("{:.1}%", 100.0 * n as f64 / grid.states.len() as f64);
        out += &format!(
            "  {} over {} ({} cells): {} free, {} colliding, {} to test\n",
            names.join(", "),
            joints.join(" x "),
            grid.cells.iter().filter(|&&n| n > 1).map(ToString::to_string).collect::<Vec<_>>().join(" x "),
            share(free),
            share(colliding),
            share(test)
        );
    }
    out
}

/// `a / b` as `3.1x`, or `-` where `b` is zero (a link whose meshes enclose no volume).
fn ratio(a: f64, b: f64) -> String {
    if b > 0.0 { format!("{:.1}x", a / b) } else { "-".to_owned() }
}

/// A number in at most 6 decimals, without trailing zeros (`1`, `-0.5`, `0.707107`).
pub fn short(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.') } else { &s };
    if s == "-0" { "0".to_owned() } else { s.to_owned() }
}

/// The widest a padded column gets, in characters: longer names overflow their column instead of
/// widening every line (`format!` width arguments also stop at 65,535).
pub const MAX_COLUMN: usize = 64;

/// The width of a column holding texts of these lengths (in characters), at most [`MAX_COLUMN`].
pub fn column_width<'a>(texts: impl IntoIterator<Item = &'a str>) -> usize {
    // No texts: an empty column.
    texts.into_iter().map(|t| t.chars().count()).max().unwrap_or(0).min(MAX_COLUMN)
}

/// `text` padded with spaces on the right to `width` characters (longer text is left as it is).
pub fn pad(text: &str, width: usize) -> String {
    let mut out = text.to_owned();
    out.extend(std::iter::repeat_n(' ', width.saturating_sub(text.chars().count())));
    out
}

/// The angles the exactness policy changed, one line each, or why there are none.
pub fn recognised_angles(tree: &KinematicTree) -> String {
    if tree.exact_angles() == ExactAngles::Off {
        return "exact angles: off (every angle as written)\n".to_owned();
    }
    let angles = tree.recognised_angles();
    if angles.is_empty() {
        return "exact angles: none changed\n".to_owned();
    }
    let mut out = format!("exact angles: {} changed (written -> exact, change)\n", angles.len());
    for a in angles {
        // The f64 nearest to the exact angle differs from it by less than the change can show.
        let change = match a.change() {
            0.0 => "the nearest f64 to it".to_owned(),
            change => format!("{change:+.2e} rad"),
        };
        out += &format!("  joint `{}`: {} -> {} ({change})\n", a.joint, a.written, a.exact);
    }
    out
}

/// The tree: counts, links, one line per joint (type, parent -> child, axis, limits, where its
/// value comes from), the DoF order, and the chain from the root to each leaf.
pub fn describe(tree: &KinematicTree) -> String {
    // A floating joint's seven entries of `q` are six degrees of freedom, a spherical joint's four
    // are three.
    let q_entries =
        if tree.dof() == tree.velocity_dof() { String::new() } else { format!(" ({} entries of q)", tree.dof()) };
    let mut out = format!(
        "robot `{}`: {} links, {} joints, {} degrees of freedom{q_entries}\n",
        tree.name(),
        tree.links().len(),
        tree.joints().len(),
        tree.velocity_dof()
    );
    out += &format!("root link: {}\n", tree.link(tree.root()).name);
    let links: Vec<&str> = tree.links().iter().map(|l| l.name.as_str()).collect();
    out += &format!("links (depth-first from the root): {}\n", links.join(", "));
    out += "joints (depth-first from the root):\n";
    let name_width = column_width(tree.joints().iter().map(|j| j.name.as_str()));
    let edges: Vec<String> =
        tree.joints().iter().map(|j| format!("{} -> {}", tree.link(j.parent).name, tree.link(j.child).name)).collect();
    let edge_width = column_width(edges.iter().map(String::as_str));
    for (joint, edge) in tree.joints().iter().zip(&edges) {
        let mut line =
            format!("  {}  {} {}", pad(&joint.name, name_width), pad(joint.kind.name(), 10), pad(edge, edge_width));
        // Fixed, floating and spherical joints have no axis (theirs is kept as written, unused).
        if !matches!(joint.kind, JointKind::Fixed | JointKind::Floating | JointKind::Spherical) {
            let [x, y, z] = joint.axis.map(short);
            line += &format!("  axis ({x}, {y}, {z})");
        }
        if let Some(l) = joint.limits {
            line += &format!("  limits [{}, {}]", short(l.lower), short(l.upper));
        }
        match joint.motion {
            JointMotion::Fixed => {}
            JointMotion::Dof(i) => line += &entries(i, joint.kind.positions()),
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
    out += &recognised_angles(tree);
    if !tree.ignored().is_empty() {
        out += &format!("not applied ({}):\n", tree.ignored().len());
        for item in tree.ignored() {
            out += &format!("  {item}\n");
        }
    }
    out += "chains from the root to each leaf:\n";
    for leaf in tree.leaves() {
        let link = tree.link(leaf);
        let path = tree.path_from_root(leaf);
        let mut names = vec![tree.link(tree.root()).name.as_str()];
        names.extend(path.iter().map(|&j| tree.link(tree.joint(j).child).name.as_str()));
        let chain = Chain { base: tree.root(), tip: leaf, joints: path.clone() };
        let dofs = tree.chain_dofs(&chain);
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
    out += &ik_families(tree);
    out
}

/// The links' masses as the description gives them: the total, each link with a mass (its
/// centre of mass in its frame and principal moments), the massless ones, and each inertia that
/// breaks a rigid body's rules (which dynamics refuse) or is left to MuJoCo to infer.
pub fn inertias(tree: &KinematicTree) -> String {
    let with: Vec<_> = tree.links().iter().filter_map(|l| l.inertial.as_ref().map(|i| (l, i))).collect();
    let inferred = tree.inertia_from_geometry();
    if with.is_empty() && inferred.is_empty() {
        return "mass: none given (no <inertial>)\n".to_owned();
    }
    let total: f64 = with.iter().map(|(_, i)| i.mass).sum();
    let mut out = format!("mass: {} kg on {} of {} links\n", short(total), with.len(), tree.links().len());
    let width = column_width(with.iter().map(|(l, _)| l.name.as_str()));
    let point = |p: [f64; 3]| format!("({}, {}, {})", short(p[0]), short(p[1]), short(p[2]));
    for (link, inertial) in &with {
        let [a, b, c] = inertial.principal_moments();
        out += &format!(
            "  {}  {} kg at {}; principal moments {}, {}, {} kg m^2\n",
            pad(&link.name, width),
            short(inertial.mass),
            point(inertial.origin.apply([0.0; 3])),
            short(a),
            short(b),
            short(c)
        );
    }
    let massless: Vec<&str> = tree
        .links()
        .iter()
        .filter(|l| l.inertial.is_none() && !inferred.contains(&l.name))
        .map(|l| l.name.as_str())
        .collect();
    if !massless.is_empty() {
        out += &format!("  massless: {}\n", massless.join(", "));
    }
    if !inferred.is_empty() {
        out += &format!(
            "  left to MuJoCo to infer from their geoms (dynamics refuse them; write an <inertial>): {}\n",
            inferred.join(", ")
        );
    }
    for (link, inertial) in &with {
        if let Some(fault) = inertial.fault(false) {
            let line = tree.inertial_line(&link.name).map(|l| format!(" (line {l})")).unwrap_or_default();
            out += &format!("  link `{}`{line}: {fault}\n", link.name);
        }
    }
    out
}

/// The closed-form inverse kinematics family of each leaf's chain from the root, or why none
/// applies (`kinematics ik` solves with it; the derive's `ik` key emits it).
pub fn ik_families(tree: &KinematicTree) -> String {
    let root = &tree.link(tree.root()).name;
    let mut out = "inverse kinematics in closed form, from the root to each leaf:\n".to_owned();
    for leaf in tree.leaves() {
        let tip = &tree.link(leaf).name;
        let what = match kinematics_compiler::ik::classify(tree, root, tip) {
            Ok(plan) if plan.notes.is_empty() => plan.family().name().to_owned(),
            Ok(plan) => format!("{} ({})", plan.family().name(), plan.notes.join("; ")),
            Err(kinematics_compiler::CompileError::NoIkFamily(none)) => format!("none: {}", none.reason),
            Err(other) => format!("none: {other}"),
        };
        out += &format!("  {tip}: {what}\n");
    }
    out
}

/// The entries of `q` a joint takes: `  q[3]`, or `  q[3..10]` for a floating joint's seven.
pub fn entries(first: usize, count: usize) -> String {
    if count == 1 { format!("  q[{first}]") } else { format!("  q[{first}..{}]", first + count) }
}

#[cfg(test)]
mod tests {
    #[test]
    fn columns_are_padded_by_hand_and_capped() {
        assert_eq!(super::pad("ab", 4), "ab  ");
        assert_eq!(super::pad("abcdef", 4), "abcdef");
        assert_eq!(super::pad("é", 2), "é ");
        let long = "x".repeat(70_000);
        assert_eq!(super::column_width([long.as_str(), "a"]), super::MAX_COLUMN);
        assert_eq!(super::column_width(["abc", "a"]), 3);
        assert_eq!(super::pad(&long, super::column_width([long.as_str()])), long);
    }

    #[test]
    fn numbers_are_short() {
        for (x, expected) in
            [(1.0, "1"), (-0.5, "-0.5"), (0.0, "0"), (-0.0, "0"), (1.0 / 3.0, "0.333333"), (-1e-9, "0")]
        {
            assert_eq!(super::short(x), expected, "{x}");
        }
    }
}
