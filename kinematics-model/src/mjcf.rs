//! MJCF front end: the kinematics of a MuJoCo model (`<mujoco>`) into a [`Description`].
//!
//! MuJoCo's documentation is the authority; the sections are cited where each rule is applied
//! (XML reference: `compiler`, `default`, `body`, `body/inertial`, `body/joint`, `body/freejoint`,
//! `body/site`, `body/geom`, `asset/mesh`, `contact`, `frame`, `attach`, `include`, `equality/joint`;
//! Modeling chapter: "Frame orientations", "Default settings", "Model composition").
//!
//! - The world body is the link `world`; each `<body>` is a link named as the body, its frame
//!   its `pos` and orientation in its parent's frame (both default to the identity).
//! - A body's joints move it relative to its parent, composed in the order written (MuJoCo's
//!   rule, XML reference `body/joint`): `hinge` is revolute, `slide` prismatic, about `axis`
//!   (default `0 0 1`) through `pos` in the body's frame, moving by `qpos - ref`. A hinge off the
//!   body's origin is `Trans(pos) Rot(axis, q - ref) Trans(-pos)`, exactly. Of several joints in
//!   one body, all but the last move an intermediate link named `body.joint`. A body without
//!   joints is welded to its parent by a fixed joint named as the body.
//! - `range` gives limits when `limited="true"`, or when `limited` is `auto` (the default) and
//!   `<compiler autolimits>` is true (the default) and a range is written; with
//!   `autolimits="false"` a range needs `limited="true"`, as MuJoCo's compiler requires. An
//!   unlimited hinge is a continuous joint; an unlimited slide a prismatic joint without limits.
//! - `free` joints (and `<freejoint>`) are the floating base ([`crate::JointKind::Floating`]),
//!   allowed only as the one joint of a child of the world body: `q` is the body's position and
//!   then its quaternion as `qx, qy, qz, qw` (MuJoCo's `qpos` writes `qw` first), and the body's
//!   `pos` and orientation are only MuJoCo's initial `qpos`, not part of the kinematics.
//! - Unnamed elements load under names from MuJoCo's ids, which number a file's bodies (the world
//!   body 0) and joints in the order written, a body before its children: `body<id>` and
//!   `joint<id>`, without the attached model's prefix (MuJoCo gives them none). The one unnamed
//!   free joint of a model, if it has only one, is `root_joint`, as a URDF's floating base is named.
//! - `ball` joints are spherical joints ([`crate::JointKind::Spherical`]) turning about their
//!   `pos` (`Trans(pos) Rot(quaternion) Trans(-pos)`, exactly): four entries of `q`, the body's
//!   orientation relative to where it is written as `qx, qy, qz, qw` (MuJoCo's `qpos` writes `qw`
//!   first; the quaternion is normalised, as a free joint's), and three velocities, the body's
//!   angular velocity in its own axes. `axis` and `ref`, which MuJoCo ignores for a ball joint,
//!   are refused when written on the joint and ignored when a default class gives them; a
//!   `range` that limits it (a cone) is refused, as is an `<equality><joint>` naming a ball or
//!   free joint (MuJoCo couples hinges and slides only).
//! - Named `<site>`s and named `<frame>`s become links joined to their body by a fixed joint,
//!   both named as the site or frame (`NAME.site`, `NAME.frame` where a body or joint has the
//!   name: MuJoCo keeps names per kind), so they can be tips; a frame's transform applies to
//!   everything inside it. Unnamed sites are skipped (nothing could name them as a tip).
//! - Orientation: `quat`, `axisangle`, `euler` (with `<compiler eulerseq>`), `xyaxes`, `zaxis`,
//!   and a site's `fromto` (z from `to` towards `from`, as MuJoCo's compiler gives it), mapped onto
//!   elementary rotations as the `rotation` module says. Angles are
//!   degrees unless `<compiler angle="radian">`; whole degrees are exact multiples of pi.
//! - `<default>` classes (nested, `class` and `childclass`) give joints, sites, geoms, meshes and
//!   equality constraints their attributes, as MuJoCo's Modeling chapter, "Default settings", describes.
//! - `<include file>` inserts another file's children of `<mujoco>` (read through the caller's
//!   [`ReadFile`]; paths as written, for the caller to resolve relative to the main file's
//!   directory, as MuJoCo does); `<attach model body|frame prefix>` (the prefix required, as
//!   MuJoCo requires it) attaches, of the
//!   `<asset><model file>` named `model`, body `body`, or frame `frame`, or without either its
//!   whole world body (its bodies, sites and frames), with every name prefixed and that file's
//!   own compiler settings and classes; its joint `<equality>` constraints are read with the
//!   prefix, and one naming a joint the attachment leaves out is listed in
//!   [`Description::ignored`] (MuJoCo drops it).
//! - `<equality><joint joint1 joint2 polycoef>` with a linear polynomial makes `joint1` a mimic of
//!   `joint2`: MuJoCo's constraint `y - y0 = a0 + a1 (x - x0)` (y0, x0 the joints' `ref`) is
//!   `multiplier = a1`, `offset = a0 + y0 - a1 x0`. Every other equality (connect, weld, tendon,
//!   a joint polynomial of higher degree, an inactive one, one without `joint2`) is listed in
//!   [`Description::ignored`] and not applied.
//! - A body's `<geom>`s are its link's collision geometry, `<contact>` and the geoms' contact
//!   bits the pairs ruled out of collision checking (the `geom` module says how each is read).
//! - A body's `<inertial>` is its link's mass and inertia, as written; `<compiler
//!   inertiafromgeom>` says which bodies MuJoCo gives an inertia computed from their geoms
//!   instead, which are listed ([`Description::inertia_from_geometry`]) for dynamics to refuse
//!   rather than take as massless (the `inertial` module says how each is read).
//! - Actuators, sensors, tendons, keyframes, cameras and lights are not kinematics and are
//!   ignored; an element MuJoCo does not define, in `<mujoco>` or among a body's, frame's or the
//!   world body's children, is refused. On the elements read (`body`, `joint`, `freejoint`,
//!   `inertial`, `site`, `frame`, `geom`, `asset/mesh`, `compiler`, `equality/joint`, `contact`),
//!   every attribute is either used, or one of MuJoCo's that has no kinematic, geometric or
//!   inertial effect (damping, `rgba`, `friction`, ...), or refused naming the element and line.
//!
//! Why not `mjcf-rs`: it was read (0.36.1) and would resolve includes, classes and orientation
//! forms, but it reads included files from disk itself (this crate does no IO), keeps no line
//! numbers for its errors, folds every orientation into a quaternion after converting degrees to
//! radians (so `euler="0 90 0"` can no longer be an exact quarter turn), silently skips letters of
//! `eulerseq` that are no axis, turns a zero quaternion, axis or `xyaxes` pair into the identity
//! rather than refusing it, and ignores attributes it does not know. The reader is therefore
//! written on `roxmltree`, as the URDF reader is.
//!
//! Each error names the element, the line and, in an included file, that file.

mod geom;
mod inertial;
mod rotation;

use std::collections::{BTreeMap, BTreeSet};

use roxmltree::{Document, Node};

use crate::angle::Angle;
use crate::description::{Description, JointDescription, JointTypeDescription, LimitsDescription, MimicDescription};
use crate::error::{Element, LoadErrorKind};
use crate::transform::FixedTransform;
use crate::urdf::{row, xml_error};

/// Supplies the text of a file an MJCF document names (`<include file>`, `<model file>`), by the
/// path as written; an `Err` carries the reason, which the error naming the element shows. The
/// model crate reads no files: the facade, the build API, the derive and the CLI pass one that
/// reads relative to the main file's directory.
pub type ReadFile<'a> = &'a dyn Fn(&str) -> Result<String, String>;

/// The name of the world body's link.
pub const WORLD: &str = "world";

/// Parses MJCF text that names no other file; an `<include>` or `<model file>` is an error
/// naming its line ([`parse_mjcf_with`] takes a [`ReadFile`]).
pub fn parse_mjcf(text: &str) -> Result<Description, LoadErrorKind> {
    parse_mjcf_with(text, &|path| Err(format!("`{path}` cannot be read here (no file reader was given)")))
}

/// Parses MJCF text, reading the files it names through `read`.
pub fn parse_mjcf_with(text: &str, read: ReadFile<'_>) -> Result<Description, LoadErrorKind> {
    let texts = gather(text, read)?;
    let mut docs = BTreeMap::new();
    for (file, text) in &texts {
        let options = roxmltree::ParsingOptions { allow_dtd: true, ..roxmltree::ParsingOptions::default() };
        let doc = Document::parse_with_options(text, options).map_err(|e| in_file(file, mjcf_xml_error(text, &e)))?;
        docs.insert(file.clone(), doc);
    }
    #[allow(clippy::expect_used, reason = "invariant: `gather` starts from the main text")]
    let main = docs.get(MAIN).expect("invariant: the main file is among the documents");
    let root = main.root_element();
    let place = Place { file: MAIN, doc: main };
    if root.tag_name().name() != "mujoco" {
        return Err(place.error(root, None, format!("the root element is <{}>, not <mujoco>", root.tag_name().name())));
    }
    let mut reader = Reader {
        docs: &docs,
        description: Description::default(),
        refs: BTreeMap::new(),
        several: BTreeMap::new(),
        next_body: 1,
        next_joint: 0,
        unnamed_free: Vec::new(),
        link_names: BTreeMap::from([(WORLD.to_owned(), Claim { kind: "world body", file: MAIN.to_owned(), line: 0 })]),
        joint_names: BTreeMap::new(),
        site_and_frame_names: BTreeMap::new(),
        attached: Vec::new(),
        geom_links: BTreeMap::new(),
        geom_bits: Vec::new(),
        geom_bodies: BTreeSet::new(),
        excluded: BTreeMap::new(),
        paired: BTreeSet::new(),
    };
    reader.description.name = root.attribute("model").unwrap_or("MuJoCo Model").to_owned();
    reader.description.links.push(WORLD.to_owned());
    let model = reader.settings(MAIN, String::new())?;
    reader.check_sections(MAIN)?;
    for (place, node) in reader.top_level(MAIN, &mut Vec::new())? {
        if node.tag_name().name() == "worldbody" {
            let world = FixedTransform::identity();
            let at = Within { model: &model, parent: WORLD, frame: &world, childclass: None, top: true };
            reader.children(place, node, &at)?;
        }
    }
    reader.name_the_floating_base();
    for (place, node) in reader.top_level(MAIN, &mut Vec::new())? {
        match node.tag_name().name() {
            "equality" => reader.equality(&model, place, node, None)?,
            "contact" => reader.contact(&model, place, node)?,
            _ => {}
        }
    }
    for (model, file, asset) in std::mem::take(&mut reader.attached) {
        for (place, node) in reader.top_level(&file, &mut Vec::new())? {
            match node.tag_name().name() {
                "equality" => reader.equality(&model, place, node, Some(&asset))?,
                "contact" => reader.contact(&model, place, node)?,
                _ => {}
            }
        }
    }
    reader.exclude_pairs();
    Ok(reader.description)
}

/// The main file's key among the documents.
const MAIN: &str = "";

/// Every file the document names, read once each: the main text under [`MAIN`], the rest under
/// their paths as written.
fn gather(text: &str, read: ReadFile<'_>) -> Result<BTreeMap<String, String>, LoadErrorKind> {
    let mut texts = BTreeMap::from([(MAIN.to_owned(), text.to_owned())]);
    let mut pending = vec![MAIN.to_owned()];
    while let Some(file) = pending.pop() {
        #[allow(clippy::expect_used, reason = "invariant: a file is pending once its text is in `texts`")]
        let text = texts.get(&file).expect("invariant: a pending file was read");
        let options = roxmltree::ParsingOptions { allow_dtd: true, ..roxmltree::ParsingOptions::default() };
        let doc = Document::parse_with_options(text, options).map_err(|e| in_file(&file, mjcf_xml_error(text, &e)))?;
        let place = Place { file: &file, doc: &doc };
        let mut found = Vec::new();
        for node in doc.descendants().filter(|n| n.is_element()) {
            let named = match node.tag_name().name() {
                "include" => true,
                "model" => node.parent_element().is_some_and(|p| p.tag_name().name() == "asset"),
                _ => false,
            };
            if !named {
                continue;
            }
            let Some(path) = node.attribute("file") else {
                return Err(place.error(node, None, format!("<{}> needs a `file` attribute", node.tag_name().name())));
            };
            if !texts.contains_key(path) && !found.iter().any(|(p, _)| p == path) {
                let text = read(path).map_err(|why| place.error(node, None, format!("cannot read `{path}`: {why}")))?;
                found.push((path.to_owned(), text));
            }
        }
        for (path, text) in found {
            pending.push(path.clone());
            texts.insert(path, text);
        }
    }
    Ok(texts)
}

/// Malformed XML, as the URDF reader words it, a second root element named as MJCF's.
fn mjcf_xml_error(text: &str, error: &roxmltree::Error) -> LoadErrorKind {
    match xml_error(text, error) {
        LoadErrorKind::Syntax { line, message } if message.starts_with("a second root element") => {
            LoadErrorKind::Syntax { line, message: "a second root element: an MJCF file holds one <mujoco>".to_owned() }
        }
        other => other,
    }
}

/// An error in file `file` (the main one or one it names).
fn in_file(file: &str, error: LoadErrorKind) -> LoadErrorKind {
    if file == MAIN { error } else { LoadErrorKind::Included { file: file.to_owned(), error: Box::new(error) } }
}

/// A document and its name, for errors.
#[derive(Clone, Copy)]
struct Place<'d, 't> {
    file: &'d str,
    doc: &'d Document<'t>,
}

impl Place<'_, '_> {
    fn line(&self, byte: usize) -> usize {
        row(self.doc.text_pos_at(byte))
    }

    fn error(&self, node: Node<'_, '_>, element: Option<Element>, message: String) -> LoadErrorKind {
        let line = self.line(node.range().start);
        in_file(self.file, LoadErrorKind::Located { element, line, message })
    }

    fn written(&self, node: Node<'_, '_>, name: &str, value: &str) -> Written {
        let byte = node.attributes().find(|a| a.name() == name).map_or(node.range().start, |a| a.range().start);
        Written { value: value.to_owned(), file: self.file.to_owned(), line: self.line(byte) }
    }
}

/// An attribute's value and where it was written (the element itself or a default class).
#[derive(Debug, Clone)]
struct Written {
    value: String,
    file: String,
    line: usize,
}

impl Written {
    fn error(&self, element: &Option<Element>, message: String) -> LoadErrorKind {
        in_file(&self.file, LoadErrorKind::Located { element: element.clone(), line: self.line, message })
    }

    /// One to `max` numbers.
    fn list(&self, name: &str, element: &Option<Element>, max: usize) -> Result<Vec<f64>, LoadErrorKind> {
        let words: Vec<&str> = self.value.split_whitespace().collect();
        if words.is_empty() || words.len() > max {
            let found = words.len();
            return Err(
                self.error(element, format!("`{name}=\"{}\"` needs 1 to {max} numbers, found {found}", self.value))
            );
        }
        words
            .into_iter()
            .map(|word| {
                word.parse()
                    .map_err(|_| self.error(element, format!("`{name}=\"{}\"`: `{word}` is not a number", self.value)))
            })
            .collect()
    }

    /// Exactly `N` numbers.
    fn numbers<const N: usize>(&self, name: &str, element: &Option<Element>) -> Result<[f64; N], LoadErrorKind> {
        let words: Vec<&str> = self.value.split_whitespace().collect();
        if words.len() != N {
            let found = words.len();
            return Err(self.error(element, format!("`{name}=\"{}\"` needs {N} numbers, found {found}", self.value)));
        }
        let mut out = [0.0; N];
        for (slot, word) in out.iter_mut().zip(words) {
            *slot = word
                .parse()
                .map_err(|_| self.error(element, format!("`{name}=\"{}\"`: `{word}` is not a number", self.value)))?;
        }
        Ok(out)
    }

    fn word<'a>(&self, name: &str, element: &Option<Element>, words: &[&'a str]) -> Result<&'a str, LoadErrorKind> {
        let value = self.value.trim();
        words.iter().find(|w| **w == value).copied().ok_or_else(|| {
            self.error(element, format!("`{name}=\"{}\"` is not one of {}", self.value, words.join(", ")))
        })
    }
}

/// `<compiler>` settings that change kinematics (XML reference, `compiler`).
#[derive(Debug, Clone, Copy)]
struct Compiler {
    /// `angle="degree"` (MuJoCo's default) or `"radian"`.
    degrees: bool,
    /// `eulerseq`, default `xyz`.
    eulerseq: [u8; 3],
    /// `autolimits`, default true.
    autolimits: bool,
    /// `inertiafromgeom`, default `auto` (the `inertial` module).
    inertia_from_geom: inertial::FromGeom,
}

impl Default for Compiler {
    fn default() -> Self {
        Compiler { degrees: true, eulerseq: *b"xyz", autolimits: true, inertia_from_geom: inertial::FromGeom::Auto }
    }
}

/// `<compiler>` settings that say where mesh files are (XML reference, `compiler`): `meshdir`
/// (else `assetdir`) and `strippath`.
#[derive(Debug, Clone, Default)]
struct MeshFiles {
    /// `meshdir`, or `assetdir` when no `meshdir` is written.
    dir: Option<String>,
    /// Whether `assetdir` gave `dir` (a later `meshdir` replaces it).
    from_assetdir: bool,
    /// `strippath`: file names lose their directories.
    strip: bool,
}

/// One `<default>` class: its parent and its prototypes' attributes by element tag.
#[derive(Debug, Clone, Default)]
struct Class {
    parent: Option<String>,
    prototypes: BTreeMap<&'static str, BTreeMap<String, Written>>,
}

/// What one model file's elements are read with: its compiler settings, its classes, and the
/// prefix its names get (empty for the main file; an `<attach>`'s `prefix`).
#[derive(Clone)]
struct Model {
    compiler: Compiler,
    meshes: MeshFiles,
    classes: BTreeMap<String, Class>,
    prefix: String,
    /// The model's file among the documents ([`MAIN`] for the main one).
    file: String,
}

/// Where a body's children hang: the model they are read in, the link they are fixed to or move
/// relative to, the transform from that link's frame to the enclosing element's, the class
/// their attributes default from, and whether they are the world body's own.
#[derive(Clone, Copy)]
struct Within<'a> {
    model: &'a Model,
    parent: &'a str,
    frame: &'a FixedTransform,
    childclass: Option<&'a str>,
    top: bool,
}

/// The element tags default classes give attributes to (others, such as `inertial`, are ignored).
const DEFAULTED: [&str; 5] = ["joint", "site", "equality", "geom", "mesh"];

/// The orientation attributes, one of which a frame may have (XML reference, `body`).
const ORIENTATION: [&str; 5] = ["quat", "axisangle", "xyaxes", "zaxis", "euler"];

/// Attributes each element read may carry: those used, then those MuJoCo gives no kinematic
/// effect (physics, rendering), which are ignored. Anything else is refused.
fn known(tag: &str) -> (&'static [&'static str], &'static [&'static str]) {
    match tag {
        "body" => (
            &["name", "childclass", "pos", "quat", "axisangle", "xyaxes", "zaxis", "euler", "mocap"],
            &["gravcomp", "user", "sleep"],
        ),
        "joint" => (
            &["name", "class", "type", "pos", "axis", "limited", "range", "ref"],
            &[
                "group",
                "springdamper",
                "actuatorfrclimited",
                "solreflimit",
                "solimplimit",
                "solreffriction",
                "solimpfriction",
                "stiffness",
                "actuatorfrcrange",
                "actuatorgravcomp",
                "margin",
                "springref",
                "armature",
                "damping",
                "frictionloss",
                "user",
            ],
        ),
        "freejoint" => (&["name", "align"], &["group"]),
        "site" => (
            &["name", "class", "type", "pos", "quat", "axisangle", "xyaxes", "zaxis", "euler", "fromto"],
            &["group", "size", "material", "rgba", "user"],
        ),
        "frame" => (&["name", "childclass", "pos", "quat", "axisangle", "xyaxes", "zaxis", "euler"], &[]),
        "equality" => (&["name", "class", "joint1", "joint2", "polycoef", "active"], &["solref", "solimp"]),
        "geom" => (
            &[
                "name",
                "class",
                "type",
                "size",
                "fromto",
                "pos",
                "quat",
                "axisangle",
                "xyaxes",
                "zaxis",
                "euler",
                "mesh",
                "contype",
                "conaffinity",
            ],
            &[
                "group",
                "priority",
                "condim",
                "friction",
                "solmix",
                "solref",
                "solimp",
                "margin",
                "gap",
                "material",
                "rgba",
                "mass",
                "density",
                "shellinertia",
                "fluidshape",
                "fluidcoef",
                "hfield",
                "fitscale",
                "user",
            ],
        ),
        "inertial" => {
            (&["pos", "quat", "axisangle", "xyaxes", "zaxis", "euler", "mass", "diaginertia", "fullinertia"], &[])
        }
        "mesh" => (
            &["name", "class", "file", "scale", "vertex", "face", "builtin", "params", "refpos", "refquat"],
            &["content_type", "smoothnormal", "maxhullvert", "inertia", "material", "normal", "texcoord"],
        ),
        _ => (&[], &[]),
    }
}

struct Reader<'d, 't> {
    docs: &'d BTreeMap<String, Document<'t>>,
    description: Description,
    /// Each hinge and slide joint's `ref` (qpos units), for equality constraints.
    refs: BTreeMap<String, f64>,
    /// Each ball and free joint's type, which an equality constraint cannot couple.
    several: BTreeMap<String, &'static str>,
    /// MuJoCo's id of the next body read (the world body is 0): bodies are numbered in the order
    /// the file gives them, a body before its children, as MuJoCo's compiler numbers them.
    next_body: usize,
    /// MuJoCo's id of the next joint read, numbered the same way (a body's joints in order).
    next_joint: usize,
    /// The unnamed free joints read (named `joint<id>` until the end; one alone becomes
    /// `root_joint`).
    unnamed_free: Vec<String>,
    /// Each link name given so far: the kind of element that gave it, its file and line.
    link_names: BTreeMap<String, Claim>,
    /// Each joint name given so far, the same way.
    joint_names: BTreeMap<String, Claim>,
    /// The names sites and named frames hold as written (link and fixed joint alike), each with
    /// its kind: a body or joint read later under one of them moves it aside.
    site_and_frame_names: BTreeMap<String, &'static str>,
    /// Each `<attach>` read: the attached model's settings, its file and its asset's name, whose
    /// `<equality>` constraints are read after every body.
    attached: Vec<(Model, String, String)>,
    /// Each named geom's link (names prefixed as their model's), for `<contact><pair>`.
    geom_links: BTreeMap<String, String>,
    /// Every collision geom's link and contact bits, for the pairs they rule out.
    geom_bits: Vec<geom::GeomBits>,
    /// The bodies with a geom of their own (in them or in a frame of theirs, visual geoms too),
    /// whose inertia MuJoCo may compute from their geoms (`<compiler inertiafromgeom>`).
    geom_bodies: BTreeSet<String>,
    /// Link pairs `<contact><exclude>` rules out, each with the element that says so.
    excluded: BTreeMap<(String, String), String>,
    /// Link pairs a `<contact><pair>` names, which no filter rules out.
    paired: BTreeSet<(String, String)>,
}

/// Where a link or joint name was given: the kind of element (`body`, `site`, ...), its file and
/// line.
#[derive(Debug, Clone)]
struct Claim {
    kind: &'static str,
    file: String,
    line: usize,
}

type Elements<'d, 't> = Vec<(Place<'d, 't>, Node<'d, 't>)>;

impl<'d, 't> Reader<'d, 't> {
    fn place(&self, file: &str) -> Place<'d, 't> {
        #[allow(clippy::expect_used, reason = "invariant: `gather` read every file an element names")]
        let (file, doc) = self.docs.get_key_value(file).expect("invariant: every named file was gathered");
        Place { file, doc }
    }

    /// The element children of `node`, with `<include>`s replaced by the included file's
    /// children of `<mujoco>` (XML reference, `include`), recursively; `stack` holds the files
    /// being included, to refuse a cycle.
    fn expand(
        &self,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        stack: &mut Vec<String>,
    ) -> Result<Elements<'d, 't>, LoadErrorKind> {
        let mut out = Vec::new();
        for child in node.children().filter(|c| c.is_element()) {
            if child.tag_name().name() != "include" {
                out.push((place, child));
                continue;
            }
            for attribute in child.attributes() {
                if attribute.name() != "file" {
                    let message = format!("<include> takes only `file`, not `{}`", attribute.name());
                    return Err(place.error(child, None, message));
                }
            }
            #[allow(clippy::expect_used, reason = "invariant: `gather` refused an <include> without `file`")]
            let file = child.attribute("file").expect("invariant: an include names its file");
            if stack.iter().any(|f| f == file) || file == place.file {
                return Err(place.error(child, None, format!("`{file}` includes itself (an include cycle)")));
            }
            let included = self.place(file);
            let root = included.doc.root_element();
            if root.tag_name().name() != "mujoco" {
                let message = format!("the root element is <{}>, not <mujoco>", root.tag_name().name());
                return Err(included.error(root, None, message));
            }
            stack.push(file.to_owned());
            out.extend(self.expand(included, root, stack)?);
            stack.pop();
        }
        Ok(out)
    }

    fn top_level(&self, file: &str, stack: &mut Vec<String>) -> Result<Elements<'d, 't>, LoadErrorKind> {
        let place = self.place(file);
        self.expand(place, place.doc.root_element(), stack)
    }

    /// Refuses an element of `<mujoco>` that MuJoCo's XML reference does not define (a misspelt
    /// `<worldbdy>` is an error, not a robot without bodies); the sections that hold no
    /// kinematics are ignored.
    fn check_sections(&self, file: &str) -> Result<(), LoadErrorKind> {
        const SECTIONS: [&str; 17] = [
            "compiler",
            "option",
            "size",
            "visual",
            "statistic",
            "default",
            "extension",
            "custom",
            "asset",
            "worldbody",
            "contact",
            "deformable",
            "equality",
            "tendon",
            "actuator",
            "sensor",
            "keyframe",
        ];
        for (place, node) in self.top_level(file, &mut Vec::new())? {
            let tag = node.tag_name().name();
            if !SECTIONS.contains(&tag) {
                return Err(place.error(node, None, format!("unknown element <{tag}> in <mujoco>")));
            }
        }
        Ok(())
    }

    /// The compiler settings and default classes of model file `file`.
    fn settings(&self, file: &str, prefix: String) -> Result<Model, LoadErrorKind> {
        let mut model = Model {
            compiler: Compiler::default(),
            meshes: MeshFiles::default(),
            classes: BTreeMap::new(),
            prefix,
            file: file.to_owned(),
        };
        let top = self.top_level(file, &mut Vec::new())?;
        for (place, node) in &top {
            if node.tag_name().name() == "compiler" {
                compiler(*place, *node, &mut model.compiler, &mut model.meshes)?;
            }
        }
        for (place, node) in top {
            if node.tag_name().name() == "default" {
                self.default_class(&mut model, place, node, None)?;
            }
        }
        model.classes.entry("main".to_owned()).or_default();
        Ok(model)
    }

    /// A `<default>` element and those nested in it (Modeling chapter, "Default settings"): the
    /// top one is class `main`, nested ones need a `class` and inherit from their parent.
    fn default_class(
        &self,
        model: &mut Model,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        parent: Option<&str>,
    ) -> Result<(), LoadErrorKind> {
        let name = match (node.attribute("class"), parent) {
            (Some(name), _) => name.to_owned(),
            (None, None) => "main".to_owned(),
            (None, Some(_)) => return Err(place.error(node, None, "a nested <default> needs a `class`".to_owned())),
        };
        if model.classes.contains_key(&name) && !(name == "main" && parent.is_none()) {
            return Err(place.error(node, None, format!("default class `{name}` is defined more than once")));
        }
        // A second top-level <default> adds to class `main` (a prototype written again replaces
        // the earlier one's attributes it repeats).
        let mut class = match model.classes.remove(&name) {
            Some(main) => main,
            None => Class { parent: parent.map(str::to_owned), prototypes: BTreeMap::new() },
        };
        for (place, child) in self.expand(place, node, &mut Vec::new())? {
            let tag = child.tag_name().name();
            if tag == "default" {
                continue;
            }
            let Some(tag) = DEFAULTED.iter().find(|t| **t == tag) else { continue };
            let (used, ignored) = known(tag);
            let mut attributes = BTreeMap::new();
            for a in child.attributes() {
                if !used.contains(&a.name()) && !ignored.contains(&a.name()) || a.name() == "name" {
                    let message = format!("<default> <{tag}>: unknown attribute `{}`", a.name());
                    return Err(place.error(child, None, message));
                }
                attributes.insert(a.name().to_owned(), place.written(child, a.name(), a.value()));
            }
            class.prototypes.entry(tag).or_default().extend(attributes);
        }
        model.classes.insert(name.clone(), class);
        for (place, child) in self.expand(place, node, &mut Vec::new())? {
            if child.tag_name().name() == "default" {
                self.default_class(model, place, child, Some(&name))?;
            }
        }
        Ok(())
    }

    /// The attributes of element `node` (tag `tag`) after its class's defaults: the element's own
    /// win, and an orientation written at a level replaces every orientation form below it.
    #[allow(clippy::too_many_arguments)]
    fn attributes(
        &self,
        model: &Model,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        tag: &str,
        childclass: Option<&str>,
        element: &Option<Element>,
    ) -> Result<BTreeMap<String, Written>, LoadErrorKind> {
        let (used, ignored) = known(tag);
        for a in node.attributes() {
            if !used.contains(&a.name()) && !ignored.contains(&a.name()) {
                let message = format!("<{}>: unknown attribute `{}`", node.tag_name().name(), a.name());
                return Err(place.error(node, element.clone(), message));
            }
        }
        let mut levels = Vec::new();
        if DEFAULTED.contains(&tag) {
            let class = node.attribute("class").or(childclass).unwrap_or("main");
            let mut at = Some(class.to_owned());
            while let Some(name) = at {
                let Some(class) = model.classes.get(&name) else {
                    return Err(place.error(node, element.clone(), format!("default class `{name}` does not exist")));
                };
                if let Some(p) = class.prototypes.get(tag) {
                    levels.push(p.clone());
                }
                at = class.parent.clone();
            }
        }
        levels.reverse();
        levels
            .push(node.attributes().map(|a| (a.name().to_owned(), place.written(node, a.name(), a.value()))).collect());
        let mut out: BTreeMap<String, Written> = BTreeMap::new();
        for level in levels {
            if level.keys().any(|k| ORIENTATION.contains(&k.as_str())) {
                out.retain(|k, _| !ORIENTATION.contains(&k.as_str()));
            }
            out.extend(level);
        }
        Ok(out)
    }

    /// The children of a body, frame or the world body: bodies, frames, sites, attachments, geoms
    /// and a body's `<inertial>`; with `frame` the transform from `parent`'s frame to theirs.
    /// Joints are read by [`Self::body`].
    fn children(&mut self, place: Place<'d, 't>, node: Node<'d, 't>, at: &Within<'_>) -> Result<(), LoadErrorKind> {
        let Within { model, parent, frame, childclass, .. } = *at;
        for (place, child) in self.expand(place, node, &mut Vec::new())? {
            match child.tag_name().name() {
                "body" => self.body(place, child, at)?,
                "frame" => self.frame(place, child, at)?,
                "site" => {
                    let Some(name) = child.attribute("name") else { continue };
                    let name = format!("{}{name}", model.prefix);
                    let element = Some(Element::Site(name.clone()));
                    let attributes = self.attributes(model, place, child, "site", childclass, &element)?;
                    let origin = frame.clone().then(&site_pose(model, &attributes, &element)?);
                    let name = self.claim_site_or_frame(&name, "site", place, child, &element)?;
                    self.fixed(&name, parent, origin);
                }
                "attach" => self.attach(model, place, child, parent, frame)?,
                "joint" | "freejoint" if node.tag_name().name() != "body" => {
                    let message = format!(
                        "a <{}> belongs in a <body>, not in <{}>",
                        child.tag_name().name(),
                        node.tag_name().name()
                    );
                    return Err(place.error(child, None, message));
                }
                "replicate" | "composite" | "flexcomp" => {
                    let message =
                        format!("<{}> (bodies generated by the compiler) is not read", child.tag_name().name());
                    return Err(place.error(child, None, message));
                }
                "geom" => {
                    // Every geom of a body counts for its inertia, a visual one too (the
                    // `inertial` module), though only collision geoms are its geometry.
                    if parent != WORLD {
                        self.geom_bodies.insert(parent.to_owned());
                    }
                    self.geom(place, child, at)?;
                }
                "inertial" => self.inertial(place, node, child, at)?,
                // Joints are the body's; cameras, lights and plugins are not kinematics.
                "joint" | "freejoint" | "camera" | "light" | "plugin" => {}
                other => {
                    let message = format!("unknown element <{other}> in <{}>", node.tag_name().name());
                    return Err(place.error(child, None, message));
                }
            }
        }
        Ok(())
    }

    /// The model's one unnamed free joint, if it has exactly one, is `root_joint` (Pinocchio's name
    /// for a free-flyer, as a URDF's floating base is named), unless a joint has that name; with
    /// several, each keeps `joint<id>`.
    fn name_the_floating_base(&mut self) {
        let root = crate::description::FLOATING_BASE_JOINT;
        let [unnamed] = &self.unnamed_free[..] else { return };
        if self.description.joints.iter().any(|j| j.name == root) {
            return;
        }
        for joint in self.description.joints.iter_mut().filter(|j| j.name == *unnamed) {
            joint.name = root.to_owned();
            joint.element = Element::Joint(root.to_owned());
        }
        if let Some(kind) = self.several.remove(unnamed) {
            self.several.insert(root.to_owned(), kind);
        }
    }

    /// Takes the link name (`joint` false) or joint name `name` for an element of kind `kind` at
    /// `node`, or refuses it if an element gave it already, naming both elements, their kinds
    /// and lines (MuJoCo keeps names per kind, a body's apart from a site's; in the model both
    /// are links, and a site's or frame's fixed joint is named as it is).
    fn claim(
        &mut self,
        joint: bool,
        name: &str,
        kind: &'static str,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        element: &Option<Element>,
    ) -> Result<(), LoadErrorKind> {
        if self.site_and_frame_names.contains_key(name) {
            self.move_aside(name, place, node, element)?;
        }
        self.take(joint, name, kind, place, node, element)
    }

    /// Takes the name as [`Reader::claim`] does, but moving no site or frame aside: for the sites
    /// and frames themselves.
    fn take(
        &mut self,
        joint: bool,
        name: &str,
        kind: &'static str,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        element: &Option<Element>,
    ) -> Result<(), LoadErrorKind> {
        let line = place.line(node.range().start);
        let (names, what) = if joint { (&mut self.joint_names, "joint") } else { (&mut self.link_names, "link") };
        if let Some(first) = names.get(name) {
            let at = match (first.line, first.file == place.file) {
                (0, _) => "the model's root".to_owned(),
                (line, true) => format!("line {line}"),
                (line, false) => format!("line {line} of `{}`", first.file),
            };
            let message = format!(
                "this {kind} makes a {what} named `{name}`, and so does the {} at {at}: the model's {what}s \
                 need names of their own (rename one)",
                first.kind
            );
            return Err(place.error(node, element.clone(), message));
        }
        names.insert(name.to_owned(), Claim { kind, file: place.file.to_owned(), line });
        Ok(())
    }

    /// One `<frame>` (XML reference, `frame`): its transform applies to what it holds, and a named
    /// one is also a link fixed to the enclosing body.
    fn frame(&mut self, place: Place<'d, 't>, node: Node<'d, 't>, at: &Within<'_>) -> Result<(), LoadErrorKind> {
        let Within { model, parent, frame, childclass, .. } = *at;
        let name = node.attribute("name").map(|n| format!("{}{n}", model.prefix));
        let element = name.clone().map(Element::Frame);
        let attributes = self.attributes(model, place, node, "frame", childclass, &element)?;
        let inner = frame.clone().then(&pose(model, &attributes, &element)?);
        if let Some(name) = name {
            let name = self.claim_site_or_frame(&name, "frame", place, node, &element)?;
            self.fixed(&name, parent, inner.clone());
        }
        let childclass = node.attribute("childclass").or(childclass);
        self.children(place, node, &Within { frame: &inner, childclass, ..*at })
    }

    /// The name of the link, and of the fixed joint holding it, that a site or named frame
    /// (`kind`) called `name` makes: `name` if no link or joint has it yet, else `name.site` (or
    /// `name.frame`). MuJoCo keeps a site's names apart from a body's and a joint's; the model
    /// makes links and joints of all of them, so the site or frame gives way: bodies and joints
    /// keep the names written. A body or joint read later under its name moves it aside the same
    /// way ([`Reader::move_aside`]).
    fn claim_site_or_frame(
        &mut self,
        name: &str,
        kind: &'static str,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        element: &Option<Element>,
    ) -> Result<String, LoadErrorKind> {
        if self.site_and_frame_names.get(name) == Some(&kind) {
            // Two sites (or frames) of one name: MuJoCo refuses them too.
            self.take(false, name, kind, place, node, element)?;
        }
        let taken = self.link_names.contains_key(name) || self.joint_names.contains_key(name);
        let name = if taken { format!("{name}.{kind}") } else { name.to_owned() };
        let fixed = if kind == "site" {
            "site (fixed to its body by a joint of its name)"
        } else {
            "frame (fixed to its body by a joint of its name)"
        };
        self.take(false, &name, kind, place, node, element)?;
        self.take(true, &name, fixed, place, node, element)?;
        if !taken {
            self.site_and_frame_names.insert(name.clone(), kind);
        }
        Ok(name)
    }

    /// Renames the site or frame that holds `name` (link and fixed joint) to `name.site` (or
    /// `name.frame`), for a body or joint read after it under that name.
    fn move_aside(
        &mut self,
        name: &str,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        element: &Option<Element>,
    ) -> Result<(), LoadErrorKind> {
        #[allow(clippy::expect_used, reason = "invariant: the caller found `name` among them")]
        let kind = self.site_and_frame_names.remove(name).expect("invariant: a site's or frame's name");
        let aside = format!("{name}.{kind}");
        for taken in [&self.link_names, &self.joint_names] {
            if let Some(first) = taken.get(&aside) {
                let message = format!(
                    "the {kind} `{name}` gives way to this element's name, as `{aside}`, which the {} at line {} \
                     already has (rename one)",
                    first.kind, first.line
                );
                return Err(place.error(node, element.clone(), message));
            }
        }
        for names in [&mut self.link_names, &mut self.joint_names] {
            if let Some(claim) = names.remove(name) {
                names.insert(aside.clone(), claim);
            }
        }
        for link in self.description.links.iter_mut().filter(|l| **l == name) {
            link.clone_from(&aside);
        }
        for joint in self.description.joints.iter_mut().filter(|j| j.name == name) {
            joint.name.clone_from(&aside);
            joint.element = Element::Joint(aside.clone());
            joint.child.clone_from(&aside);
        }
        Ok(())
    }

    /// A link `name` fixed to `parent` by a joint of the same name.
    fn fixed(&mut self, name: &str, parent: &str, origin: FixedTransform) {
        self.description.links.push(name.to_owned());
        self.description.joints.push(JointDescription {
            name: name.to_owned(),
            element: Element::Joint(name.to_owned()),
            kind: JointTypeDescription::Fixed,
            parent: parent.to_owned(),
            child: name.to_owned(),
            origin,
            after_motion: FixedTransform::identity(),
            // URDF's default axis, which a fixed joint keeps unused.
            axis: [1.0, 0.0, 0.0],
            limits: None,
            mimic: None,
        });
    }

    /// One `<body>` (XML reference, `body`), its joints and its children. An unnamed body is
    /// `body<id>`, MuJoCo's id for it.
    fn body(&mut self, place: Place<'d, 't>, node: Node<'d, 't>, at: &Within<'_>) -> Result<(), LoadErrorKind> {
        let Within { model, parent, frame, childclass, top } = *at;
        let id = self.next_body;
        self.next_body += 1;
        let name = match node.attribute("name") {
            Some(name) => format!("{}{name}", model.prefix),
            None => format!("body{id}"),
        };
        let element = Some(Element::Body(name.clone()));
        self.claim(false, &name, "body", place, node, &element)?;
        let attributes = self.attributes(model, place, node, "body", childclass, &element)?;
        if let Some(mocap) = attributes.get("mocap")
            && mocap.word("mocap", &element, &["true", "false"])? == "true"
        {
            return Err(mocap.error(&element, "a mocap body (placed by the simulation's data) is not read".to_owned()));
        }
        let body_pose = frame.clone().then(&pose(model, &attributes, &element)?);
        let childclass = node.attribute("childclass").or(childclass);
        let elements = self.expand(place, node, &mut Vec::new())?;
        let joints: Vec<_> =
            elements.iter().filter(|(_, n)| matches!(n.tag_name().name(), "joint" | "freejoint")).collect();
        if joints.is_empty() {
            self.claim(true, &name, "body (fixed to its parent by a joint of its name)", place, node, &element)?;
            self.fixed(&name, parent, body_pose.clone());
        }
        let mut link = parent.to_owned();
        let count = joints.len();
        let first_joint = self.next_joint;
        self.next_joint += count;
        for (k, (place, joint)) in joints.into_iter().enumerate() {
            let id = first_joint + k;
            let child = if k + 1 == count { name.clone() } else { format!("{name}.{}", joint_name(model, *joint, id)) };
            let origin = if k == 0 { body_pose.clone() } else { FixedTransform::identity() };
            let description = self.joint(model, *place, *joint, id, &link, &child, origin, childclass, (top, count))?;
            let joint_element = Some(Element::Joint(description.name.clone()));
            self.claim(true, &description.name, "joint", *place, *joint, &joint_element)?;
            if k + 1 < count {
                self.claim(false, &child, "joint (the link between a body's joints)", *place, *joint, &joint_element)?;
            }
            self.description.links.push(child.clone());
            self.description.joints.push(description);
            link = child;
        }
        let identity = FixedTransform::identity();
        self.children(place, node, &Within { model, parent: &name, frame: &identity, childclass, top: false })?;
        self.inertia_from_geoms(model, &name);
        Ok(())
    }

    /// One `<joint>` or `<freejoint>` (XML reference, `body/joint`, `body/freejoint`), MuJoCo's
    /// joint `id`, moving `child` relative to `parent`, after the fixed `origin`.
    #[allow(clippy::too_many_arguments)]
    fn joint(
        &mut self,
        model: &Model,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        id: usize,
        parent: &str,
        child: &str,
        origin: FixedTransform,
        childclass: Option<&str>,
        (top, count): (bool, usize),
    ) -> Result<JointDescription, LoadErrorKind> {
        let free_element = node.tag_name().name() == "freejoint";
        let name = joint_name(model, node, id);
        let element = Some(Element::Joint(name.clone()));
        let tag = if free_element { "freejoint" } else { "joint" };
        let attributes = self.attributes(model, place, node, tag, childclass, &element)?;
        let kind = match attributes.get("type") {
            _ if free_element => "free",
            None => "hinge",
            Some(t) => t.word("type", &element, &["hinge", "slide", "ball", "free"])?,
        };
        let here = |message: String| place.error(node, element.clone(), message);
        let mut description = JointDescription {
            name: name.clone(),
            element: Element::Joint(name.clone()),
            kind: JointTypeDescription::Floating,
            parent: parent.to_owned(),
            child: child.to_owned(),
            origin: FixedTransform::identity(),
            after_motion: FixedTransform::identity(),
            axis: [0.0, 0.0, 1.0],
            limits: None,
            mimic: None,
        };
        match kind {
            "ball" => return self.ball(model, node, &attributes, description, origin),
            "free" => {
                if !top || count != 1 {
                    return Err(here(
                        "a free joint must be the only joint of a body whose parent is the world body".to_owned(),
                    ));
                }
                if let Some(align) = attributes.get("align")
                    && align.word("align", &element, &["true", "false", "auto"])? == "true"
                {
                    return Err(align
                        .error(&element, "`align=\"true\"` (a frame moved to the inertia's) is not read".to_owned()));
                }
                for refused in ["pos", "axis", "range", "limited", "ref"] {
                    if let Some(w) = attributes.get(refused) {
                        return Err(w.error(&element, format!("a free joint takes no `{refused}`")));
                    }
                }
                self.several.insert(name.clone(), "free");
                if node.attribute("name").is_none() {
                    self.unnamed_free.push(name.clone());
                }
                return Ok(description);
            }
            _ => {}
        }
        let hinge = kind == "hinge";
        let pos = match attributes.get("pos") {
            Some(w) => w.numbers::<3>("pos", &element)?,
            None => [0.0; 3],
        };
        let axis = match attributes.get("axis") {
            Some(w) => w.numbers::<3>("axis", &element)?,
            None => [0.0, 0.0, 1.0],
        };
        let length = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
        if length == 0.0 || !length.is_finite() {
            let w = attributes.get("axis");
            let message = "the axis is zero".to_owned();
            return Err(w.map_or_else(|| here(message.clone()), |w| w.error(&element, message.clone())));
        }
        let unit = axis.map(|c| c / length);
        // `ref`: the joint's value where the body is as written (qpos0); hinge refs are angles.
        let reference = match attributes.get("ref") {
            Some(w) => {
                let [r] = w.numbers::<1>("ref", &element)?;
                if hinge { angle(model, r) } else { Angle::Radians(r) }
            }
            None => Angle::ZERO,
        };
        self.refs.insert(name.clone(), reference.radians());
        description.axis = axis;
        description.limits = self.limits(model, &attributes, hinge, &element)?;
        if hinge {
            description.kind = if description.limits.is_some() {
                JointTypeDescription::Revolute
            } else {
                JointTypeDescription::Continuous
            };
            // Trans(pos) Rot(axis, -ref) Rot(axis, q) Trans(-pos): the rotation about the axis
            // through `pos`, by `q - ref` (XML reference, `body/joint`: pos, ref).
            let mut origin = origin.translate(pos);
            if !reference.is_zero() {
                let Some(steps) = rotation::axis_angle(axis, rotation::negate(reference)) else {
                    return Err(here("the axis is zero".to_owned()));
                };
                origin = steps.into_iter().fold(origin, |t, (a, angle)| t.rotate(a, angle));
            }
            description.origin = origin;
            description.after_motion = FixedTransform::identity().translate(pos.map(|c| -c));
        } else {
            description.kind = JointTypeDescription::Prismatic;
            // A slide moves along its axis wherever `pos` puts it: Trans(axis (q - ref)).
            let r = reference.radians();
            description.origin = origin.translate(unit.map(|c| -r * c));
        }
        Ok(description)
    }

    /// A ball joint (XML reference, `body/joint`: type ball): a spherical joint turning about
    /// its `pos`, `Trans(pos) Rot(quaternion) Trans(-pos)`. MuJoCo ignores `axis` and `ref` for
    /// ball joints: written on the element itself they are refused (they would say something the
    /// joint does not do), from a default class (given to every joint of it) they are ignored as
    /// MuJoCo ignores them. A `range` that limits it (a cone about the body as written) is
    /// refused, wherever it was written: the model holds no such limit.
    fn ball(
        &mut self,
        model: &Model,
        node: Node<'d, 't>,
        attributes: &BTreeMap<String, Written>,
        mut description: JointDescription,
        origin: FixedTransform,
    ) -> Result<JointDescription, LoadErrorKind> {
        let element = Some(description.element.clone());
        for (refused, why) in
            [("axis", "it turns about every axis through its `pos`"), ("ref", "its `qpos0` is the body as written")]
        {
            if let (Some(_), Some(w)) = (node.attribute(refused), attributes.get(refused)) {
                return Err(w.error(&element, format!("a ball joint takes no `{refused}` ({why})")));
            }
        }
        if self.limits(model, attributes, false, &element)?.is_some() {
            #[allow(clippy::expect_used, reason = "invariant: `limits` gives limits only from a written `range`")]
            let range = attributes.get("range").expect("invariant: limits come from a range");
            return Err(range.error(
                &element,
                "a ball joint's `range` is a cone limit (its largest angle from the body as written), which is not \
                 modelled: remove it or write `limited=\"false\"`"
                    .to_owned(),
            ));
        }
        let pos = match attributes.get("pos") {
            Some(w) => w.numbers::<3>("pos", &element)?,
            None => [0.0; 3],
        };
        self.several.insert(description.name.clone(), "ball");
        description.kind = JointTypeDescription::Ball;
        description.origin = origin.translate(pos);
        description.after_motion = FixedTransform::identity().translate(pos.map(|c| -c));
        Ok(description)
    }

    /// A joint's limits (XML reference, `body/joint`: limited, range; `compiler`: autolimits).
    fn limits(
        &self,
        model: &Model,
        attributes: &BTreeMap<String, Written>,
        hinge: bool,
        element: &Option<Element>,
    ) -> Result<Option<LimitsDescription>, LoadErrorKind> {
        let range = attributes.get("range");
        let limited = match attributes.get("limited") {
            Some(w) => w.word("limited", element, &["true", "false", "auto"])?,
            None => "auto",
        };
        let limited = match (limited, range) {
            ("true", _) => true,
            ("false", _) => false,
            (_, None) => false,
            (_, Some(_)) if model.compiler.autolimits => true,
            (_, Some(w)) => {
                let message = "a `range` without `limited=\"true\"` under `<compiler autolimits=\"false\">`".to_owned();
                return Err(w.error(element, message));
            }
        };
        if !limited {
            return Ok(None);
        }
        let Some(range) = range else {
            let w = attributes.get("limited");
            #[allow(clippy::expect_used, reason = "invariant: `limited` is only true when written")]
            let w = w.expect("invariant: limited=true was written");
            return Err(w.error(element, "`limited=\"true\"` needs a `range`".to_owned()));
        };
        let [lower, upper] = range.numbers::<2>("range", element)?;
        let convert = |x: f64| if hinge && model.compiler.degrees { x.to_radians() } else { x };
        Ok(Some(LimitsDescription { lower: convert(lower), upper: convert(upper), velocity: None, effort: None }))
    }

    /// `<attach model body|frame prefix>` (XML reference, `attach`; Modeling chapter, "Model
    /// composition"): body `body`, frame `frame` or (neither written, as MuJoCo 4 allows) the
    /// whole world body of the model asset `model`, read with that file's compiler settings and
    /// classes, every name prefixed; its equality constraints are read after every body.
    fn attach(
        &mut self,
        model: &Model,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        parent: &str,
        frame: &FixedTransform,
    ) -> Result<(), LoadErrorKind> {
        for a in node.attributes() {
            if !["model", "body", "frame", "prefix"].contains(&a.name()) {
                return Err(place.error(node, None, format!("<attach>: unknown attribute `{}`", a.name())));
            }
        }
        let Some(asset) = node.attribute("model") else {
            return Err(place.error(node, None, "<attach> needs a `model` attribute".to_owned()));
        };
        let what = match (node.attribute("body"), node.attribute("frame")) {
            (Some(_), Some(_)) => {
                return Err(place.error(node, None, "<attach> takes a `body` or a `frame`, not both".to_owned()));
            }
            (Some(body), None) => Some(("body", body)),
            (None, Some(frame)) => Some(("frame", frame)),
            (None, None) => None,
        };
        // MuJoCo 4's compiler requires the prefix ("required attribute missing: 'prefix'").
        let Some(prefix) = node.attribute("prefix") else {
            return Err(place.error(
                node,
                None,
                "<attach> needs a `prefix` attribute (MuJoCo requires one)".to_owned(),
            ));
        };
        let prefix = format!("{}{prefix}", model.prefix);
        let Some(file) = self.model_file(asset)? else {
            return Err(place.error(node, None, format!("no <asset><model name=\"{asset}\" file=...> to attach")));
        };
        let attached = self.settings(&file, prefix)?;
        self.check_sections(&file)?;
        let top_level = self.top_level(&file, &mut Vec::new())?;
        self.attached.push((attached.clone(), file.clone(), asset.to_owned()));
        let top = parent == WORLD;
        let worldbodies = top_level.into_iter().filter(|(_, n)| n.tag_name().name() == "worldbody");
        let Some((tag, name)) = what else {
            // The whole world body: its bodies, sites and frames, in place of the <attach>.
            for (p, world) in worldbodies {
                self.children(p, world, &Within { model: &attached, parent, frame, childclass: None, top })?;
            }
            return Ok(());
        };
        for (p, world) in worldbodies {
            if let Some(found) =
                world.descendants().find(|n| n.tag_name().name() == tag && n.attribute("name") == Some(name))
            {
                let childclass = found.ancestors().skip(1).find_map(|a| a.attribute("childclass"));
                let at = Within { model: &attached, parent, frame, childclass, top };
                return if tag == "body" { self.body(p, found, &at) } else { self.frame(p, found, &at) };
            }
        }
        Err(place.error(node, None, format!("the model `{asset}` (`{file}`) has no {tag} `{name}` to attach")))
    }

    /// The file of the model asset named `asset` in the main file's `<asset>`s.
    fn model_file(&self, asset: &str) -> Result<Option<String>, LoadErrorKind> {
        for (_, node) in self.top_level(MAIN, &mut Vec::new())? {
            if node.tag_name().name() != "asset" {
                continue;
            }
            for m in node.children().filter(|c| c.is_element() && c.tag_name().name() == "model") {
                let name = m.attribute("name").or_else(|| m.attribute("file"));
                if name == Some(asset) {
                    return Ok(m.attribute("file").map(str::to_owned));
                }
            }
        }
        Ok(None)
    }

    /// One `<equality>` section (XML reference, `equality/joint`) of the main file (`attached`
    /// none) or of the model attached as asset `attached`, its joint names prefixed as the
    /// model's are: linear joint couplings become mimics, everything else is listed as ignored.
    /// An attached model's constraint naming a joint the attachment left out is not applied
    /// (MuJoCo drops it too) and is listed as such.
    fn equality(
        &mut self,
        model: &Model,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        attached: Option<&str>,
    ) -> Result<(), LoadErrorKind> {
        for (place, child) in self.expand(place, node, &mut Vec::new())? {
            let tag = child.tag_name().name();
            let line = place.line(child.range().start);
            let of = match attached {
                Some(asset) => format!(" of `{}`, attached as `{asset}`", place.file),
                None => String::new(),
            };
            let label = match child.attribute("name") {
                Some(name) => format!("<equality><{tag} name=\"{name}\"> (line {line}{of})"),
                None => format!("<equality><{tag}> (line {line}{of})"),
            };
            if tag != "joint" {
                self.description.ignored.push(format!("{label}: not kinematics of a tree, not applied"));
                continue;
            }
            let element = None;
            let attributes = self.attributes(model, place, child, "equality", None, &element)?;
            // MuJoCo couples hinges and slides only (XML reference, `equality/joint`).
            let prefixed = |w: &Written| format!("{}{}", model.prefix, w.value);
            let named = ["joint1", "joint2"].into_iter().filter_map(|a| attributes.get(a));
            if let Some((joint, kind)) = named.into_iter().find_map(|w| self.several.get(&prefixed(w)).map(|k| (w, k)))
            {
                let message = format!(
                    "<equality><joint>: `{}` is a {kind} joint (a quaternion in `q`, not one value): only hinges \
                     and slides are coupled",
                    prefixed(joint)
                );
                return Err(joint.error(&element, message));
            }
            if let Some(active) = attributes.get("active")
                && active.word("active", &element, &["true", "false"])? == "false"
            {
                self.description.ignored.push(format!("{label}: inactive, not applied"));
                continue;
            }
            let Some(joint1) = attributes.get("joint1") else {
                return Err(place.error(child, None, "<equality><joint> needs `joint1`".to_owned()));
            };
            let Some(joint2) = attributes.get("joint2") else {
                self.description
                    .ignored
                    .push(format!("{label}: holds `{}` at a constant, not applied", prefixed(joint1)));
                continue;
            };
            let coefficients: Vec<f64> = match attributes.get("polycoef") {
                Some(w) => w.numbers::<5>("polycoef", &element)?.to_vec(),
                None => vec![0.0, 1.0, 0.0, 0.0, 0.0],
            };
            if coefficients[2..].iter().any(|c| *c != 0.0) {
                self.description.ignored.push(format!("{label}: a polynomial of degree above 1, not applied"));
                continue;
            }
            let (y, x) = (prefixed(joint1), prefixed(joint2));
            let (Some(&y0), Some(&x0)) = (self.refs.get(&y), self.refs.get(&x)) else {
                let missing = if self.refs.contains_key(&y) { &x } else { &y };
                if attached.is_some() && !self.joint_names.contains_key(missing) {
                    self.description.ignored.push(format!(
                        "{label}: names `{missing}`, which the attachment leaves out, not applied (as MuJoCo drops it)"
                    ));
                    continue;
                }
                return Err(place.error(
                    child,
                    None,
                    format!("<equality><joint>: no hinge or slide joint `{missing}`"),
                ));
            };
            let (a0, a1) = (coefficients[0], coefficients[1]);
            #[allow(clippy::expect_used, reason = "invariant: `refs` holds the joints read")]
            let follower = self.description.joints.iter_mut().find(|j| j.name == y).expect("invariant: a read joint");
            if follower.mimic.is_some() {
                return Err(place.error(child, None, format!("joint `{y}` is coupled by more than one <equality>")));
            }
            follower.mimic = Some(MimicDescription { joint: x, multiplier: a1, offset: a0 + y0 - a1 * x0 });
        }
        Ok(())
    }
}

/// A joint's name with its model's prefix; an unnamed one is `joint<id>`, MuJoCo's id for it
/// (see [`Reader::name_the_floating_base`] for the one exception).
fn joint_name(model: &Model, node: Node<'_, '_>, id: usize) -> String {
    match node.attribute("name") {
        Some(name) => format!("{}{name}", model.prefix),
        None => format!("joint{id}"),
    }
}

/// An angle in the compiler's unit.
fn angle(model: &Model, value: f64) -> Angle {
    if model.compiler.degrees { Angle::from_degrees(value) } else { Angle::Radians(value) }
}

/// `<compiler>` (XML reference, `compiler`): `angle`, `eulerseq`, `autolimits` and
/// `inertiafromgeom` are read; `coordinate="global"` and `alignfree="true"` are refused; the rest
/// (files, meshes, inertia bounds, `inertiagrouprange`: the `inertial` module) has no kinematic
/// effect and is not read.
fn compiler(
    place: Place<'_, '_>,
    node: Node<'_, '_>,
    out: &mut Compiler,
    meshes: &mut MeshFiles,
) -> Result<(), LoadErrorKind> {
    for a in node.attributes() {
        let w = place.written(node, a.name(), a.value());
        let element = None;
        match a.name() {
            "angle" => out.degrees = w.word("angle", &element, &["degree", "radian"])? == "degree",
            "autolimits" => out.autolimits = w.word("autolimits", &element, &["true", "false"])? == "true",
            "inertiafromgeom" => {
                out.inertia_from_geom = match w.word("inertiafromgeom", &element, &["false", "true", "auto"])? {
                    "false" => inertial::FromGeom::False,
                    "true" => inertial::FromGeom::True,
                    _ => inertial::FromGeom::Auto,
                }
            }
            "eulerseq" => {
                let seq = a.value().as_bytes();
                let [x, y, z] = seq else {
                    return Err(
                        w.error(&element, format!("`eulerseq=\"{}\"` needs three letters of xyzXYZ", a.value()))
                    );
                };
                if !seq.iter().all(|c| b"xyzXYZ".contains(c)) {
                    return Err(
                        w.error(&element, format!("`eulerseq=\"{}\"`: only x, y, z, X, Y, Z name axes", a.value()))
                    );
                }
                out.eulerseq = [*x, *y, *z];
            }
            "coordinate" => {
                w.word("coordinate", &element, &["local"])?;
            }
            "alignfree" => {
                if w.word("alignfree", &element, &["true", "false"])? == "true" {
                    return Err(w.error(
                        &element,
                        "`alignfree=\"true\"` (free bodies moved to their inertia's frame) is not read".to_owned(),
                    ));
                }
            }
            "meshdir" => {
                meshes.dir = Some(a.value().to_owned());
                meshes.from_assetdir = false;
            }
            "assetdir" => {
                if meshes.dir.is_none() || meshes.from_assetdir {
                    meshes.dir = Some(a.value().to_owned());
                    meshes.from_assetdir = true;
                }
            }
            "strippath" => meshes.strip = w.word("strippath", &element, &["true", "false"])? == "true",
            "texturedir" | "boundmass" | "boundinertia" | "settotalmass" | "balanceinertia" | "discardvisual"
            | "convexhull" | "usethread" | "fitaabb" | "inertiagrouprange" | "exactmeshinertia" | "saveinertial"
            | "fusestatic" | "maxhullvert" => {}
            other => return Err(w.error(&element, format!("<compiler>: unknown attribute `{other}`"))),
        }
    }
    Ok(())
}

/// A frame's `pos` and orientation (XML reference, `body`; Modeling chapter, "Frame
/// orientations"): `Trans(pos)` then the rotation's elementary steps.
fn pose(
    model: &Model,
    attributes: &BTreeMap<String, Written>,
    element: &Option<Element>,
) -> Result<FixedTransform, LoadErrorKind> {
    let pos = match attributes.get("pos") {
        Some(w) => w.numbers::<3>("pos", element)?,
        None => [0.0; 3],
    };
    let steps = orientation(model, attributes, element)?;
    Ok(steps.into_iter().fold(FixedTransform::identity().translate(pos), |t, (axis, a)| t.rotate(axis, a)))
}

/// A site's frame: as [`pose`], or from `fromto` (XML reference, `body/site`): the midpoint, with
/// z along `from - to` (the smallest rotation taking +z there, as `zaxis`), for the shapes that
/// have an axis. The XML reference says the site's axis runs along the segment without a sign;
/// MuJoCo's compiler points z from `to` towards `from` (MuJoCo 4.0.1's `site_xmat` for
/// `fromto="0 0 0 1 0 0"` has z = (-1, 0, 0)), and that is what is followed here:
/// `tests/fixtures/mujoco/fromto_sites.xml` holds the reader to it.
fn site_pose(
    model: &Model,
    attributes: &BTreeMap<String, Written>,
    element: &Option<Element>,
) -> Result<FixedTransform, LoadErrorKind> {
    let Some(fromto) = attributes.get("fromto") else { return pose(model, attributes, element) };
    let kind = match attributes.get("type") {
        Some(w) => w.word("type", element, &["sphere", "capsule", "ellipsoid", "cylinder", "box"])?,
        None => "sphere",
    };
    if kind == "sphere" {
        return Err(fromto
            .error(element, "`fromto` needs a site type with an axis (capsule, ellipsoid, cylinder, box)".to_owned()));
    }
    for other in ["pos"].iter().chain(ORIENTATION.iter()) {
        if let Some(w) = attributes.get(*other) {
            return Err(w.error(element, format!("`{other}` and `fromto` cannot both place a site")));
        }
    }
    Ok(fromto_frame(fromto, element)?.0)
}

/// The frame a `fromto` gives a site or geom (XML reference, `body/site`, `body/geom`): at the
/// midpoint, z along the segment, pointing from `to` towards `from` as MuJoCo's compiler gives it
/// (see [`site_pose`]; every geom shape read is symmetric about its xy plane, so the sign moves
/// no geometry); and the segment's length.
fn fromto_frame(fromto: &Written, element: &Option<Element>) -> Result<(FixedTransform, f64), LoadErrorKind> {
    let [x0, y0, z0, x1, y1, z1] = fromto.numbers::<6>("fromto", element)?;
    let d = [x0 - x1, y0 - y1, z0 - z1];
    let Some(steps) = rotation::z_axis(d) else {
        return Err(fromto.error(element, "`fromto` has the same point twice".to_owned()));
    };
    let mid = [(x0 + x1) / 2.0, (y0 + y1) / 2.0, (z0 + z1) / 2.0];
    let frame = steps.into_iter().fold(FixedTransform::identity().translate(mid), |t, (axis, a)| t.rotate(axis, a));
    Ok((frame, (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()))
}

/// The one orientation form written, as elementary rotations (the `rotation` module).
fn orientation(
    model: &Model,
    attributes: &BTreeMap<String, Written>,
    element: &Option<Element>,
) -> Result<rotation::Steps, LoadErrorKind> {
    let written: Vec<(&str, &Written)> =
        ORIENTATION.iter().filter_map(|k| attributes.get(*k).map(|w| (*k, w))).collect();
    let (form, w) = match written[..] {
        [] => return Ok(Vec::new()),
        [one] => one,
        [_, (second, w), ..] => {
            let message = format!("more than one orientation (`{}` and `{second}`): write one", written[0].0);
            return Err(w.error(element, message));
        }
    };
    let steps = match form {
        "quat" => rotation::quaternion(w.numbers::<4>(form, element)?),
        "axisangle" => {
            let [x, y, z, a] = w.numbers::<4>(form, element)?;
            rotation::axis_angle([x, y, z], angle(model, a))
        }
        "euler" => {
            Some(rotation::euler(w.numbers::<3>(form, element)?.map(|a| angle(model, a)), model.compiler.eulerseq))
        }
        "xyaxes" => {
            let [a, b, c, d, e, f] = w.numbers::<6>(form, element)?;
            rotation::xy_axes([a, b, c], [d, e, f])
        }
        _ => rotation::z_axis(w.numbers::<3>(form, element)?),
    };
    steps
        .ok_or_else(|| w.error(element, format!("`{form}=\"{}\"` is no rotation (a zero or parallel vector)", w.value)))
}
