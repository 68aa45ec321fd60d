//! Collada (`.dae`): the scene read here (the unit, the node tree's transforms, which geometry is
//! placed where), the geometry by mesh-loader.
//!
//! **Why not mesh-loader's placement.** mesh-loader 0.1.13 does read `<unit meter>` and the node
//! transforms, but places geometry in a way a collision mesh cannot rely on (all in
//! `src/collada/instance.rs`, `build`, and `src/collada/scene.rs`):
//! - it multiplies a node's transform by its parents' in the wrong order (`transform *=
//!   node.transform` walking up gives node · parent · … · root, where the world transform is
//!   root · … · parent · node), so any nesting beyond one level with translations or rotations
//!   comes out wrong;
//! - the unit is folded into the visual scene's root the same way, so it scales each node's
//!   geometry before the node's own transform rather than after: a node translated by 1000 in a
//!   millimetre file stays 1000 *metres* away;
//! - a geometry placed by several nodes comes out once, at the last placement (a `HashMap` from
//!   geometry to one transform);
//! - a transform within 0.01 of the identity in every entry (`Matrix4x4::is_identity`, epsilon
//!   `10e-3`) is dropped: a 5 mm offset, or `<unit meter="0.995"/>`, is lost;
//! - `<rotate>` axes are not normalised, `<instance_node>` is not followed, and geometry no node
//!   places is output anyway, unplaced and unscaled.
//!
//! So the scene is read here with roxmltree, and mesh-loader is given the document without
//! `<library_visual_scenes>` and `<scene>`: it then returns each `<geometry>` as written, named by
//! its id (untransformed: `build` finds no node to apply), and each placement found here is
//! applied in `f64` with the unit outermost.
//!
//! **What is applied.** `<unit meter>` (default 1); every node's `<matrix>`, `<translate>`,
//! `<rotate>`, `<scale>` and `<lookat>`, composed parent first; each `<instance_geometry>`, each
//! time it occurs; `<instance_node>` (to a depth of 32). A mirroring placement reverses the
//! triangles' winding so inside stays inside. Without a `<scene>` the first visual scene is used;
//! with no visual scene at all, every geometry is taken once, scaled by the unit.
//!
//! **What is not.** `<up_axis>` (as mesh-loader, which leaves it a TODO, and the robotics loaders
//! built on assimp, which set `AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION`: URDF meshes are
//! authored in the link's frame whatever the file claims); `<skew>` (refused: no robot exporter
//! writes it); `<instance_controller>` (skinned geometry: not placed, so not read); references to
//! other files. Within a geometry, mesh-loader triangulates polygons as fans and skips lines and
//! points (`src/collada/iter.rs`); it cuts `<tristrips>` as fans too, which is wrong for a strip
//! of more than one triangle (exporters for robots write `<triangles>` or `<polylist>`).

use std::collections::HashMap;

use roxmltree::{Document, Node};

use crate::affine::Affine;
use crate::merge::Merged;

/// How deep `<node>` and `<instance_node>` may nest: far beyond any exporter's trees, and an end to
/// an `<instance_node>` cycle.
const MAX_NESTING: usize = 32;

/// Reads the Collada document `bytes` into `merged`.
pub(crate) fn read(bytes: &[u8], merged: &mut Merged) -> Result<(), String> {
    let text = decode(bytes)?;
    let doc = Document::parse(&text).map_err(|e| format!("it is not XML: {e}"))?;
    let root = doc.root_element();
    if root.tag_name().name() != "COLLADA" {
        return Err(format!("its root element is <{}>, not <COLLADA>", root.tag_name().name()));
    }
    let unit = Affine::scale([unit(root)?; 3]);
    let placements = match visual_scene(root)? {
        Some(scene) => {
            let mut walk = Walk { root, placements: Vec::new() };
            for node in children(scene, "node") {
                walk.node(node, &Affine::IDENTITY, 0)?;
            }
            Some(walk.placements)
        }
        None => None,
    };
    let geometry_only = without_scene(&text, root);
    let scene = mesh_loader::collada::from_str(&geometry_only).map_err(|e| e.to_string())?;
    match placements {
        Some(placements) => {
            let by_id: HashMap<&str, &mesh_loader::Mesh> = scene.meshes.iter().map(|m| (m.name.as_str(), m)).collect();
            for (id, placement) in placements {
                let mesh = by_id.get(id).ok_or_else(|| {
                    format!("a node places geometry `{id}`, which is not a <geometry> with a <mesh> in this file")
                })?;
                merged.add(&mesh.vertices, &mesh.faces, Some(&(unit * placement)))?;
            }
        }
        None => {
            for mesh in &scene.meshes {
                merged.add(&mesh.vertices, &mesh.faces, Some(&unit))?;
            }
        }
    }
    Ok(())
}

/// The document as text: UTF-8, or UTF-16 with a byte-order mark (as mesh-loader accepts).
fn decode(bytes: &[u8]) -> Result<String, String> {
    let utf16 = |rest: &[u8], word: fn([u8; 2]) -> u16| {
        let words = rest.chunks_exact(2).map(|c| word([c[0], c[1]]));
        char::decode_utf16(words).collect::<Result<String, _>>().map_err(|_| "it is not valid UTF-16 text".to_owned())
    };
    match bytes {
        [0xFF, 0xFE, rest @ ..] => utf16(rest, u16::from_le_bytes),
        [0xFE, 0xFF, rest @ ..] => utf16(rest, u16::from_be_bytes),
        _ => {
            let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
            String::from_utf8(bytes.to_vec()).map_err(|e| format!("it is not UTF-8 text ({e})"))
        }
    }
}

/// Metres per unit of the file: `<asset><unit meter>`, 1 when absent.
fn unit(root: Node<'_, '_>) -> Result<f64, String> {
    let Some(meter) = children(root, "asset").flat_map(|a| children(a, "unit")).find_map(|u| u.attribute("meter"))
    else {
        return Ok(1.0);
    };
    // mesh-loader's reading too: some exporters write the locale's decimal comma.
    match meter.trim().replace(',', ".").parse::<f64>() {
        Ok(m) if m.is_finite() && m > 0.0 => Ok(m),
        _ => Err(format!("<unit meter=\"{meter}\"> is not a positive number")),
    }
}

/// The visual scene `<scene>` instantiates; without a `<scene>`, the first one (what a viewer
/// shows); `None` when there is none.
fn visual_scene<'a, 'input>(root: Node<'a, 'input>) -> Result<Option<Node<'a, 'input>>, String> {
    let mut scenes = children(root, "library_visual_scenes").flat_map(|l| children(l, "visual_scene"));
    let Some(instance) = children(root, "scene").flat_map(|s| children(s, "instance_visual_scene")).next() else {
        return Ok(scenes.next());
    };
    let id = local_id(instance)?;
    scenes
        .find(|s| s.attribute("id") == Some(id))
        .map(Some)
        .ok_or_else(|| format!("<instance_visual_scene> names `#{id}`, which is not a <visual_scene> in this file"))
}

/// The node tree's walk: every geometry placement, in document order.
struct Walk<'a, 'input> {
    root: Node<'a, 'input>,
    placements: Vec<(&'a str, Affine)>,
}

impl<'a> Walk<'a, '_> {
    fn node(&mut self, node: Node<'a, '_>, parent: &Affine, depth: usize) -> Result<(), String> {
        if depth > MAX_NESTING {
            return Err(format!("nodes nest deeper than {MAX_NESTING} (an <instance_node> cycle?)"));
        }
        // A node's transformation elements compose in the order written, and apply to everything
        // the node holds wherever they sit among its children.
        let mut local = Affine::IDENTITY;
        for child in node.children().filter(Node::is_element) {
            if let Some(t) = transform(child)? {
                local = local * t;
            }
        }
        let world = *parent * local;
        for child in node.children().filter(Node::is_element) {
            match child.tag_name().name() {
                "instance_geometry" => self.placements.push((local_id(child)?, world)),
                "instance_node" => {
                    let id = local_id(child)?;
                    let target = self
                        .root
                        .descendants()
                        .find(|n| n.has_tag_name("node") && n.attribute("id") == Some(id))
                        .ok_or_else(|| format!("<instance_node> names `#{id}`, which is not a <node> in this file"))?;
                    self.node(target, &world, depth + 1)?;
                }
                "node" => self.node(child, &world, depth + 1)?,
                _ => {}
            }
        }
        Ok(())
    }
}

/// The map a transformation element stands for; `None` for any other element.
fn transform(element: Node<'_, '_>) -> Result<Option<Affine>, String> {
    let name = element.tag_name().name();
    let count = match name {
        "matrix" => 16,
        "translate" | "scale" => 3,
        "rotate" => 4,
        "lookat" => 9,
        "skew" => return Err("a <skew> transform is not supported".to_owned()),
        _ => return Ok(None),
    };
    let text = element.text().unwrap_or("").replace(',', ".");
    let numbers: Vec<f64> = text
        .split_whitespace()
        .map(str::parse)
        .collect::<Result<_, _>>()
        .map_err(|_| format!("<{name}> holds `{}`, which is not {count} numbers", text.trim()))?;
    if numbers.len() != count || numbers.iter().any(|x| !x.is_finite()) {
        return Err(format!("<{name}> holds `{}`, which is not {count} finite numbers", text.trim()));
    }
    let v = |i: usize| [numbers[i], numbers[i + 1], numbers[i + 2]];
    let map = match name {
        "matrix" => {
            let mut m = [0.0; 16];
            m.copy_from_slice(&numbers);
            Some(Affine::from_rows(&m))
        }
        "translate" => Some(Affine::translation(v(0))),
        "scale" => Some(Affine::scale(v(0))),
        "rotate" => Affine::rotation(v(0), numbers[3]),
        _ => Affine::look_at(v(0), v(3), v(6)),
    };
    map.map(Some).ok_or_else(|| format!("<{name}> `{}` is degenerate (a zero axis or direction)", text.trim()))
}

/// The id a `url="#id"` attribute names within this file.
fn local_id<'a>(element: Node<'a, '_>) -> Result<&'a str, String> {
    let name = element.tag_name().name();
    let url = element.attribute("url").ok_or_else(|| format!("<{name}> has no url"))?;
    url.strip_prefix('#')
        .ok_or_else(|| format!("<{name} url=\"{url}\"> refers to another file, which is not supported"))
}

fn children<'a, 'input>(node: Node<'a, 'input>, name: &'static str) -> impl Iterator<Item = Node<'a, 'input>> {
    node.children().filter(move |c| c.is_element() && c.tag_name().name() == name)
}

/// `text` without the root's `<library_visual_scenes>` and `<scene>` elements: what mesh-loader
/// is given, so that it places nothing.
fn without_scene(text: &str, root: Node<'_, '_>) -> String {
    let mut out = String::with_capacity(text.len());
    let mut from = 0;
    for element in root.children().filter(|c| c.has_tag_name("library_visual_scenes") || c.has_tag_name("scene")) {
        let range = element.range();
        out.push_str(&text[from..range.start]);
        from = range.end;
    }
    out.push_str(&text[from..]);
    out
}
