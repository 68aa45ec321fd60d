//! MJCF geometry: a body's `<geom>`s as its link's collision geometry, `<asset><mesh>` for the
//! mesh files they name, and `<contact>` with the geoms' `contype` and `conaffinity` as the pairs
//! the model rules out of collision checking.
//!
//! MuJoCo's XML reference is the authority (`body/geom`, `asset/mesh`, `contact/exclude`,
//! `contact/pair`, `compiler`: `meshdir`, `assetdir`, `strippath`), with the Computation
//! chapter's "Collision detection" for which geoms may touch:
//!
//! - `size` is read per type: `sphere` its radius; `capsule` and `cylinder` radius and
//!   half-length; `box` half-sizes; `ellipsoid` radii. A type given fewer sizes than it reads is
//!   refused (MuJoCo's default size is zero, which its compiler refuses too).
//! - `fromto` (capsule, cylinder, box, ellipsoid): the shape runs between the two points, its
//!   frame at their midpoint with z along them; its length is their distance (a capsule's
//!   segment, the others' full extent along z), and `size`'s first number is the radius (both
//!   other half-sizes of a box or an ellipsoid). A `pos` or orientation beside it is refused.
//! - `mesh` names an `<asset><mesh>` of the same model file (its `name`, else its file name
//!   without directories and extension), whose `file` is found under `meshdir` (else `assetdir`)
//!   relative to that model file's folder, with its `scale`. Its triangles are read by the caller
//!   ([`crate::KinematicTree::load_meshes`]). MuJoCo collides a mesh as its convex hull; the cover
//!   holds the mesh's own triangles (see the guide's collision chapter). A mesh given inline
//!   (`vertex`, `face`, `builtin`) or moved by `refpos`/`refquat` is refused, as is a primitive
//!   fitted to a mesh (`type="box" mesh="..."`).
//! - A geom whose `contype` and `conaffinity` are both 0 collides with nothing (a visual geom)
//!   and is not collision geometry. Geoms of the world body are the scene's, not the robot's, and
//!   are not read; nor are `plane` and `hfield` geoms (MuJoCo allows them only in static bodies).
//!   An `sdf` geom (a plugin's distance field) is refused.
//! - Pairs ruled out for good: `<contact><exclude body1 body2>`, and two links no geom of which
//!   may touch a geom of the other (`contype & conaffinity` is zero both ways). A
//!   `<contact><pair geom1 geom2>` brings its links' pair back: MuJoCo checks an explicit pair
//!   whatever the filters say.

use std::collections::BTreeMap;

use roxmltree::Node;

use super::{Model, Place, Reader, WORLD, Within, Written, fromto_frame, pose};
use crate::collision::{Collision, Shape};
use crate::description::{CollisionDescription, ExcludedPair};
use crate::error::{Element, LoadErrorKind};

/// A collision geom's link and its contact bits, for the pair rule.
#[derive(Debug, Clone)]
pub(super) struct GeomBits {
    link: String,
    contype: u32,
    conaffinity: u32,
}

impl GeomBits {
    /// Whether MuJoCo lets the two geoms touch (Computation chapter, "Collision detection").
    fn meet(&self, other: &GeomBits) -> bool {
        self.contype & other.conaffinity != 0 || other.contype & self.conaffinity != 0
    }
}

/// The geometry types MuJoCo defines.
const TYPES: [&str; 8] = ["plane", "hfield", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh"];

impl<'d, 't> Reader<'d, 't> {
    /// One `<geom>` of a body (or of a frame in it) hung on link `at.parent`: its shape, placed by
    /// `at.frame` and its own pose, added to the link's collision geometry.
    pub(super) fn geom(
        &mut self,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
        at: &Within<'_>,
    ) -> Result<(), LoadErrorKind> {
        let Within { model, parent, frame, childclass, .. } = *at;
        let element = Some(Element::Body(parent.to_owned()));
        let attributes = self.attributes(model, place, node, "geom", childclass, &element)?;
        let here = |message: String| place.error(node, element.clone(), format!("<geom>: {message}"));
        let kind = match attributes.get("type") {
            Some(w) => w.word("type", &element, &TYPES)?,
            None => "sphere",
        };
        if let Some(name) = node.attribute("name") {
            self.geom_links.insert(format!("{}{name}", model.prefix), parent.to_owned());
        }
        let contype = bits(&attributes, "contype", &element)?;
        let conaffinity = bits(&attributes, "conaffinity", &element)?;
        // The world body's geoms are the scene (a floor, a table); planes and height fields are
        // static by MuJoCo's rule; a geom that touches nothing is drawn, not collided.
        if parent == WORLD || matches!(kind, "plane" | "hfield") || contype | conaffinity == 0 {
            return Ok(());
        }
        if let (Some(mesh), false) = (attributes.get("mesh"), kind == "mesh") {
            let message = format!("a {kind} fitted to mesh `{}` is not read: write `type=\"mesh\"`", mesh.value);
            return Err(mesh.error(&element, format!("<geom>: {message}")));
        }
        let sizes = match attributes.get("size") {
            Some(w) => w.list("size", &element, 3)?,
            None => Vec::new(),
        };
        let (origin, length) = match attributes.get("fromto") {
            Some(fromto) => {
                if matches!(kind, "sphere" | "mesh") {
                    let message = "`fromto` needs a geom type with an axis (capsule, cylinder, box, ellipsoid)";
                    return Err(fromto.error(&element, format!("<geom>: {message}")));
                }
                for other in ["pos", "quat", "axisangle", "xyaxes", "zaxis", "euler"] {
                    if let Some(w) = attributes.get(other) {
                        return Err(w.error(&element, format!("<geom>: `{other}` and `fromto` cannot both place it")));
                    }
                }
                let (placed, length) = fromto_frame(fromto, &element)?;
                (frame.clone().then(&placed), Some(length))
            }
            None => (frame.clone().then(&pose(model, &attributes, &element)?), None),
        };
        let need = |n: usize, what: &str| -> Result<(), LoadErrorKind> {
            if sizes.len() < n {
                let written = attributes.get("size").map_or("none".to_owned(), |w| format!("`{}`", w.value));
                return Err(here(format!("a {kind} needs {n} sizes ({what}), `size` gives {written}")));
            }
            Ok(())
        };
        let shape = match (kind, length) {
            ("sphere", _) => {
                need(1, "radius")?;
                Shape::Sphere { radius: sizes[0] }
            }
            ("capsule", None) => {
                need(2, "radius, half-length")?;
                Shape::Capsule { radius: sizes[0], length: 2.0 * sizes[1] }
            }
            ("cylinder", None) => {
                need(2, "radius, half-length")?;
                Shape::Cylinder { radius: sizes[0], length: 2.0 * sizes[1] }
            }
            ("box", None) => {
                need(3, "half-sizes")?;
                Shape::Box { size: [2.0 * sizes[0], 2.0 * sizes[1], 2.0 * sizes[2]] }
            }
            ("ellipsoid", None) => {
                need(3, "radii")?;
                Shape::Ellipsoid { radii: [sizes[0], sizes[1], sizes[2]] }
            }
            (_, Some(length)) if kind != "mesh" => {
                need(1, "radius")?;
                let r = sizes[0];
                match kind {
                    "capsule" => Shape::Capsule { radius: r, length },
                    "cylinder" => Shape::Cylinder { radius: r, length },
                    "box" => Shape::Box { size: [2.0 * r, 2.0 * r, length] },
                    _ => Shape::Ellipsoid { radii: [r, r, length / 2.0] },
                }
            }
            _ => {
                let Some(name) = attributes.get("mesh") else {
                    return Err(here("`type=\"mesh\"` needs a `mesh` naming an <asset><mesh>".to_owned()));
                };
                self.mesh_asset(model, name, &element)?
            }
        };
        // Sizes checked here, in MuJoCo's words, rather than by validation in URDF's.
        if let Some(fault) = shape.fault() {
            let written = ["size", "fromto", "mesh"].iter().find_map(|a| attributes.get(*a).map(|w| (a, w)));
            let at = written.map_or(String::new(), |(a, w)| format!("`{a}=\"{}\"`: ", w.value));
            return Err(here(format!("{at}{fault}")));
        }
        self.description.collisions.push(CollisionDescription {
            link: parent.to_owned(),
            line: Some(place.line(node.range().start)),
            collision: Collision { origin, shape },
        });
        self.geom_bits.push(GeomBits { link: parent.to_owned(), contype, conaffinity });
        Ok(())
    }

    /// The mesh asset `name` (written at `name`) of `model`'s file: its file (under the model's
    /// mesh folder) and scale.
    fn mesh_asset(&self, model: &Model, name: &Written, element: &Option<Element>) -> Result<Shape, LoadErrorKind> {
        for (place, section) in self.top_level(&model.file, &mut Vec::new())? {
            if section.tag_name().name() != "asset" {
                continue;
            }
            for (place, mesh) in self.expand(place, section, &mut Vec::new())? {
                if mesh.tag_name().name() != "mesh" {
                    continue;
                }
                let file = mesh.attribute("file");
                let own = mesh.attribute("name").map(str::to_owned).or_else(|| file.map(stem));
                if own.as_deref() != Some(name.value.as_str()) {
                    continue;
                }
                let attributes = self.attributes(model, place, mesh, "mesh", None, &None)?;
                let here = |message: &str| {
                    place.error(mesh, element.clone(), format!("<mesh name=\"{}\">: {message}", name.value))
                };
                for refused in ["vertex", "face", "builtin", "params", "refpos", "refquat"] {
                    if attributes.contains_key(refused) {
                        return Err(here(&format!(
                            "`{refused}` is not read (give the mesh as a file, placed by the geom)"
                        )));
                    }
                }
                let Some(file) = file else { return Err(here("needs a `file`")) };
                let scale = match attributes.get("scale") {
                    Some(w) => w.numbers::<3>("scale", element)?,
                    None => [1.0; 3],
                };
                return Ok(Shape::Mesh { filename: mesh_path(model, file), scale, loaded: None });
            }
        }
        Err(name.error(element, format!("<geom>: no <asset><mesh> named `{}`", name.value)))
    }

    /// One `<contact>` section of `model`'s file: its `<exclude>`s and `<pair>`s, names prefixed
    /// as the model's are.
    pub(super) fn contact(
        &mut self,
        model: &Model,
        place: Place<'d, 't>,
        node: Node<'d, 't>,
    ) -> Result<(), LoadErrorKind> {
        for (place, child) in self.expand(place, node, &mut Vec::new())? {
            let line = place.line(child.range().start);
            let tag = child.tag_name().name();
            let (first, second) = match tag {
                "exclude" => ("body1", "body2"),
                "pair" => ("geom1", "geom2"),
                other => {
                    let message = format!("unknown element <{other}> in <contact>");
                    return Err(place.error(child, None, message));
                }
            };
            let mut links = Vec::new();
            for attribute in [first, second] {
                let Some(name) = child.attribute(attribute) else {
                    return Err(place.error(child, None, format!("<contact><{tag}> needs `{attribute}`")));
                };
                let name = format!("{}{name}", model.prefix);
                let link = if tag == "exclude" {
                    let is_body =
                        self.link_names.get(&name).is_some_and(|c| c.kind == "body" || c.kind == "world body");
                    is_body.then(|| name.clone())
                } else {
                    self.geom_links.get(&name).cloned()
                };
                let Some(link) = link else {
                    let what = if tag == "exclude" { "body" } else { "geom" };
                    return Err(place.error(child, None, format!("<contact><{tag}>: no {what} `{name}`")));
                };
                links.push(link);
            }
            let pair = ordered(&links[0], &links[1]);
            if tag == "exclude" {
                let of = if place.file == super::MAIN { String::new() } else { format!(" of `{}`", place.file) };
                self.excluded.entry(pair).or_insert_with(|| format!("<contact><exclude> (line {line}{of})"));
            } else {
                self.paired.insert(pair);
            }
        }
        Ok(())
    }

    /// The pairs ruled out for good, into the description: the `<exclude>`s, then each pair of
    /// links no geom of which may touch one of the other; less the explicit `<pair>`s.
    pub(super) fn exclude_pairs(&mut self) {
        let mut by_link: BTreeMap<&str, Vec<&GeomBits>> = BTreeMap::new();
        for geom in &self.geom_bits {
            by_link.entry(geom.link.as_str()).or_default().push(geom);
        }
        let links: Vec<&str> = by_link.keys().copied().collect();
        for (k, a) in links.iter().enumerate() {
            for b in &links[k + 1..] {
                let meet = by_link[a].iter().any(|g| by_link[b].iter().any(|h| g.meet(h)));
                if !meet {
                    self.excluded
                        .entry(ordered(a, b))
                        .or_insert_with(|| "their geoms' contype and conaffinity never meet".to_owned());
                }
            }
        }
        for (pair, why) in std::mem::take(&mut self.excluded) {
            if !self.paired.contains(&pair) {
                self.description.excluded_pairs.push(ExcludedPair { link1: pair.0, link2: pair.1, why });
            }
        }
    }
}

/// A pair of names in order.
fn ordered(a: &str, b: &str) -> (String, String) {
    if a <= b { (a.to_owned(), b.to_owned()) } else { (b.to_owned(), a.to_owned()) }
}

/// A contact bit mask (`contype`, `conaffinity`): a whole number from 0 to 2^31 - 1, default 1.
fn bits(attributes: &BTreeMap<String, Written>, name: &str, element: &Option<Element>) -> Result<u32, LoadErrorKind> {
    let Some(w) = attributes.get(name) else { return Ok(1) };
    let [x] = w.numbers::<1>(name, element)?;
    if !(x.fract() == 0.0 && (0.0..2_147_483_648.0).contains(&x)) {
        return Err(w.error(element, format!("<geom>: `{name}=\"{}\"` is not a bit mask (0 to 2^31 - 1)", w.value)));
    }
    // Exact: a whole number below 2^31.
    Ok(x as u32)
}

/// A mesh asset's default name: its file name without directories and extension (XML
/// reference, `asset/mesh`: name).
fn stem(file: &str) -> String {
    let name = file.rsplit(['/', '\\']).next().unwrap_or(file);
    name.rsplit_once('.').map_or(name, |(stem, _)| stem).to_owned()
}

/// Where a mesh file is, as the caller resolves a relative path (from the main file's folder):
/// `model`'s folder, then its mesh folder, then the file (its directories dropped under
/// `strippath`); an absolute folder or file starts afresh.
fn mesh_path(model: &Model, file: &str) -> String {
    let file = if model.meshes.strip { file.rsplit(['/', '\\']).next().unwrap_or(file) } else { file };
    let folder = model.file.rsplit_once('/').map_or("", |(folder, _)| folder);
    let mut path = String::new();
    for part in [folder, model.meshes.dir.as_deref().unwrap_or(""), file] {
        if part.starts_with('/') {
            path.clear();
        }
        if !part.is_empty() {
            if !path.is_empty() && !path.ends_with('/') {
                path.push('/');
            }
            path.push_str(part);
        }
    }
    path
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mesh_is_named_by_its_file() {
        assert_eq!(stem("assets/link0.obj"), "link0");
        assert_eq!(stem("hand.collision.stl"), "hand.collision");
        assert_eq!(stem("plain"), "plain");
    }

    #[test]
    fn contact_bits_meet_either_way() {
        let bits = |contype, conaffinity| GeomBits { link: String::new(), contype, conaffinity };
        assert!(bits(1, 1).meet(&bits(1, 1)));
        assert!(bits(2, 0).meet(&bits(0, 2)));
        assert!(bits(0, 2).meet(&bits(2, 0)));
        assert!(!bits(1, 0).meet(&bits(1, 0)));
        assert!(!bits(2, 2).meet(&bits(1, 1)));
    }
}
