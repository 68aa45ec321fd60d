//! `kinematics spherize FILE [--spheres N] [--cover D] [--package NAME=PATH]... [--skip-meshes]
//! [-o OUT]`: the URDF again, each link's collision geometry replaced by the spheres the compiler
//! covers it with, one `<collision name="sphere_K">` per sphere; the spherized format VAMP, cuRobo
//! and this crate read, so users of other planners get the same cover.
//!
//! The file is rewritten, not re-serialised: `roxmltree` finds each link's `<collision>` elements
//! by byte range, those are cut out (with the whitespace and newline that led up to them) and the
//! spheres go where the link's first one was, indented like it. Every other byte (visuals,
//! inertials, joints, comments, materials, the declaration) stays as written, so a diff shows the
//! collision geometry and the header comment alone. Links follow the URDF reader's rule: the
//! `<link>` children of `<robot>`, each one's `<collision>` children, in the robot's namespace.
//!
//! With `--skip-meshes` a link's mesh elements are kept as written (the cover left them out) and
//! only its other elements give way to spheres; a link of meshes alone is untouched. Only URDF is
//! read: an MJCF file or a DH table has no URDF text to keep, and is refused.

use std::collections::BTreeMap;
use std::io::Write;
use std::ops::Range;

use kinematics::model::collision::{Shape, Sphere, link_covers};
use kinematics::model::{ExactAngles, KinematicTree, LinkId, Source, SourceFormat};
use kinematics::{LoadError, LoadErrorKind};
use roxmltree::{Document, Node};

use crate::error::CliError;

/// Arguments of `spherize`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml) with collision geometry.
    file: String,
    /// How the geometry becomes spheres, as the derive's `collision(...)`, and where meshes are.
    #[command(flatten)]
    cover: crate::cover::CoverArgs,
    /// Write to this file (atomically) instead of standard output.
    #[arg(short, long)]
    output: Option<std::path::PathBuf>,
}

/// Writes `args.file` with each link's collision geometry replaced by its sphere cover.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let cover = args.cover.cover()?;
    let (text, mut tree) = load_urdf(&args.file)?;
    args.cover.read_meshes(&mut tree, &args.file)?;
    let covers =
        link_covers(&tree, &cover, args.cover.meshes()).map_err(|e| CliError::Usage(format!("{}: {e}", args.file)))?;
    let spheres: BTreeMap<&str, &[Sphere]> =
        covers.iter().map(|(link, c)| (tree.link(*link).name.as_str(), c.spheres.as_slice())).collect();
    let fault = |fault: String| CliError::Usage(format!("{}: {fault}", args.file));
    let (mut edits, written) = collision_edits(&text, &spheres, args.cover.skip_meshes).map_err(fault)?;
    let spheres_alone = covers.iter().filter(|(link, _)| spheres_alone(&tree, *link, args.cover.skip_meshes)).count();
    let summary =
        Summary { file: &args.file, cover: crate::cover::CoverArgs::describe(&cover), written, spheres_alone };
    edits.push(header(&text, &summary));
    let spherized = apply(&text, edits).map_err(fault)?;
    crate::error::deliver(&spherized, args.output.as_deref(), &args.file, out)
}

/// The text and tree of the URDF `file`, loaded as `crate::robot::load` loads any description
/// (`--format`, `--exact-angles`), once the format is known to be URDF: the text is what is
/// rewritten, so a format without URDF text is a usage error before anything is parsed.
fn load_urdf(file: &str) -> Result<(String, KinematicTree), CliError> {
    let bytes = std::fs::read(file).map_err(|e| LoadError::new(file, LoadErrorKind::Io(e)))?;
    let source = Source::from_bytes(file, crate::robot::format().kind(), bytes)?;
    let format = match source.format {
        SourceFormat::Urdf => None,
        SourceFormat::Mjcf => Some("MJCF"),
        SourceFormat::DhToml | SourceFormat::DhJson => Some("a DH table"),
    };
    if let Some(format) = format {
        return Err(CliError::Usage(format!(
            "{file}: `spherize` rewrites a URDF file in place and reads no other format, and this is {format}"
        )));
    }
    let tree = source.load(ExactAngles::on(crate::robot::exact_angles_on()))?;
    Ok((source.text, tree))
}

/// Whether the geometry the cover reads on `link` is `<sphere>` elements alone (meshes left out
/// under `skip_meshes`), which the cover keeps as written.
fn spheres_alone(tree: &KinematicTree, link: LinkId, skip_meshes: bool) -> bool {
    tree.link(link)
        .collisions
        .iter()
        .filter(|c| !(skip_meshes && matches!(c.shape, Shape::Mesh { .. })))
        .all(|c| matches!(c.shape, Shape::Sphere { .. }))
}

/// One change to the text: the bytes of `range` replaced by `with`.
struct Edit {
    range: Range<usize>,
    with: String,
}

/// What the rewrite did, for the header comment.
#[derive(Default)]
struct Written {
    /// Spheres written, over all links.
    spheres: usize,
    /// Links whose collision elements were replaced.
    links: usize,
    /// Mesh `<collision>` elements kept as written (`--skip-meshes`).
    meshes_kept: usize,
}

/// The edits that replace each link's collision elements by its spheres (`spheres`, by link
/// name), and what they write. With `skip_meshes` mesh elements stay. A fault is a message.
fn collision_edits(
    text: &str,
    spheres: &BTreeMap<&str, &[Sphere]>,
    skip_meshes: bool,
) -> Result<(Vec<Edit>, Written), String> {
    // The options the URDF reader parses with, so a file it read parses here too.
    let options = roxmltree::ParsingOptions { allow_dtd: true, ..roxmltree::ParsingOptions::default() };
    let doc = Document::parse_with_options(text, options).map_err(|e| e.to_string())?;
    let robot = doc.root_element();
    let mut edits = Vec::new();
    let mut written = Written::default();
    for link in children(robot, "link") {
        let Some(name) = link.attribute("name") else { continue };
        let (meshes, replaced): (Vec<Node<'_, '_>>, Vec<Node<'_, '_>>) =
            children(link, "collision").partition(|c| skip_meshes && is_mesh(*c));
        written.meshes_kept += meshes.len();
        let Some(first) = replaced.first() else { continue };
        // Every link with geometry the cover reads has spheres (`link_covers`); one without
        // would lose its geometry silently, so it is refused rather than written.
        let Some(&link_spheres) = spheres.get(name).filter(|s| !s.is_empty()) else {
            return Err(format!("link `{name}`: its collision geometry was given no spheres"));
        };
        let lead = lead(text, first.range().start)?;
        let step = step(text, *first, &lead)?;
        let mut with = String::new();
        for (k, sphere) in link_spheres.iter().enumerate() {
            with += &lead;
            with += &sphere_element(k, sphere, &lead, &step);
        }
        for (k, element) in replaced.iter().enumerate() {
            let start = element.range().start - lead_len(text, element.range().start)?;
            let with = if k == 0 { std::mem::take(&mut with) } else { String::new() };
            edits.push(Edit { range: start..element.range().end, with });
        }
        written.spheres += link_spheres.len();
        written.links += 1;
    }
    Ok((edits, written))
}

/// The element children of `node` named `name` in `node`'s namespace (the URDF reader's rule).
fn children<'a, 'input>(node: Node<'a, 'input>, name: &'static str) -> impl Iterator<Item = Node<'a, 'input>> {
    let namespace = node.tag_name().namespace();
    node.children()
        .filter(move |c| c.is_element() && c.tag_name().namespace() == namespace && c.tag_name().name() == name)
}

/// Whether a `<collision>` element's geometry is a `<mesh>` (what the cover leaves out under
/// `--skip-meshes`: the reader's `Shape::Mesh`).
fn is_mesh(collision: Node<'_, '_>) -> bool {
    children(collision, "geometry").any(|g| children(g, "mesh").next().is_some())
}

/// The whitespace that leads up to the element at `start`: the spaces and tabs before it on its
/// line, and the line break before those if nothing else is on the line (`"\n    "`); only the
/// spaces when the element follows something on its line (`" "`, or `""`).
fn lead(text: &str, start: usize) -> Result<String, String> {
    let n = lead_len(text, start)?;
    Ok(text.get(start - n..start).unwrap_or_default().to_owned())
}

/// The length in bytes of [`lead`].
fn lead_len(text: &str, start: usize) -> Result<usize, String> {
    let before = text.get(..start).ok_or_else(|| format!("byte {start} is not in the text"))?;
    let spaces = before.trim_end_matches([' ', '\t']);
    let line_break = if spaces.ends_with("\r\n") {
        2
    } else if spaces.ends_with('\n') {
        1
    } else {
        0
    };
    Ok(before.len() - spaces.len() + line_break)
}

/// The indentation one level deeper than `collision`'s: what its first child adds to its own
/// (`lead`), else two spaces (a tab where the file indents with tabs).
fn step(text: &str, collision: Node<'_, '_>, lead: &str) -> Result<String, String> {
    let indent = lead.trim_start_matches(['\r', '\n']);
    if let Some(child) = collision.children().find(Node::is_element) {
        let inner = self::lead(text, child.range().start)?;
        let inner = inner.trim_start_matches(['\r', '\n']);
        if let Some(step) = inner.strip_prefix(indent).filter(|s| !s.is_empty()) {
            return Ok(step.to_owned());
        }
    }
    Ok(if indent.contains('\t') { "\t".to_owned() } else { "  ".to_owned() })
}

/// Sphere `k` of a link as a `<collision>` element: laid out over lines like the one it replaces
/// when that one began its line (`lead` holds a line break), on one line otherwise. Numbers are
/// written to the last bit ([`number`]), so the file reads back to the same spheres.
fn sphere_element(k: usize, sphere: &Sphere, lead: &str, step: &str) -> String {
    let [x, y, z] = sphere.center.map(number);
    let (open, origin) =
        (format!("<collision name=\"sphere_{k}\">"), format!("<origin xyz=\"{x} {y} {z}\" rpy=\"0 0 0\"/>"));
    let shape = format!("<sphere radius=\"{}\"/>", number(sphere.radius));
    if !lead.contains('\n') {
        return format!("{open}{origin}<geometry>{shape}</geometry></collision>");
    }
    let newline = if lead.contains("\r\n") { "\r\n" } else { "\n" };
    let indent = lead.trim_start_matches(['\r', '\n']);
    let line = |depth: usize, element: &str| format!("{newline}{indent}{}{element}", step.repeat(depth));
    [line(1, &origin), line(1, "<geometry>"), line(2, &shape), line(1, "</geometry>"), line(0, "</collision>")]
        .into_iter()
        .fold(open, |element, line| element + &line)
}

/// `x` to the last bit, as `{}` writes it (`0.045`), or as `{:e}` does where that is shorter
/// (`1.3877787807814457e-17` for the rounding residue a centre on an axis often has, which `{}`
/// writes with sixteen zeros); both read back to the same `f64`, and URDF readers take either.
fn number(x: f64) -> String {
    let plain = format!("{x}");
    let exponent = format!("{x:e}");
    if exponent.len() < plain.len() { exponent } else { plain }
}

/// What the header comment says: the source, the cover, and what was written.
struct Summary<'a> {
    file: &'a str,
    cover: String,
    written: Written,
    /// Links whose covered geometry was `<sphere>` elements alone: the cover keeps those as
    /// written, however many, so the budget does not bound them.
    spheres_alone: usize,
}

/// The comment saying how the file was made, after the XML declaration (which must come first)
/// or at the top when there is none.
fn header(text: &str, summary: &Summary<'_>) -> Edit {
    let newline = if text.contains("\r\n") { "\r\n" } else { "\n" };
    let Written { spheres, links, meshes_kept } = summary.written;
    let mut body = format!(
        "Written by `kinematics spherize` from {}: each link's collision geometry replaced by{newline}     \
         its sphere cover, {} on {} ({}).{newline}     ",
        summary.file,
        count(spheres, "sphere"),
        count(links, "link"),
        summary.cover,
    );
    if meshes_kept == 0 {
        body += "Every point of each link's primitives and mesh triangles lies inside the link's spheres.";
    } else {
        body += &format!(
            "Every point of each link's primitives lies inside the link's spheres. Meshes were left out{newline}     \
             of the cover: {} kept as written.",
            count(meshes_kept, "mesh <collision> element")
        );
    }
    if summary.spheres_alone > 0 {
        body += &format!(
            "{newline}     Links whose geometry was spheres alone keep them as written, however many (the cover's \
             rule): {}.",
            summary.spheres_alone
        );
    }
    let comment = format!("<!-- {} -->", crate::convert::comment(&body));
    let bom = if text.starts_with('\u{feff}') { '\u{feff}'.len_utf8() } else { 0 };
    let rest = &text[bom..];
    let declaration = rest
        .strip_prefix("<?xml")
        .filter(|after| after.starts_with(|c: char| c.is_ascii_whitespace()))
        .and_then(|_| rest.find("?>"));
    match declaration {
        Some(end) => {
            let at = bom + end + "?>".len();
            Edit { range: at..at, with: format!("{newline}{comment}") }
        }
        None => Edit { range: bom..bom, with: format!("{comment}{newline}") },
    }
}

/// `n` things: `1 link`, `7 links`.
fn count(n: usize, thing: &str) -> String {
    if n == 1 { format!("1 {thing}") } else { format!("{n} {thing}s") }
}

/// `text` with `edits` made (disjoint ranges, in any order); ranges that overlap or split a
/// character are a fault, not a panic.
fn apply(text: &str, mut edits: Vec<Edit>) -> Result<String, String> {
    edits.sort_by_key(|e| e.range.start);
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    for edit in edits {
        out += text.get(at..edit.range.start).ok_or("overlapping edits of the text")?;
        out += &edit.with;
        at = edit.range.end;
    }
    out += text.get(at..).ok_or("an edit past the end of the text")?;
    Ok(out)
}
