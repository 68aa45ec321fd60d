//! MJCF mass and inertia: a body's `<inertial>` as its link's [`Inertial`], and the bodies whose
//! inertia MuJoCo computes from their geoms instead (`<compiler inertiafromgeom>`).
//!
//! MuJoCo's XML reference is the authority (`body/inertial`; `compiler`: `inertiafromgeom`,
//! `inertiagrouprange`), checked against MuJoCo 4.0.1's compiler where the reference leaves a
//! case open:
//!
//! - `<inertial pos mass diaginertia|fullinertia quat|axisangle|xyaxes|zaxis|euler>` belongs to
//!   its body's link (of a body with several joints, the last link, the one named as the body).
//!   A body holds at most one (MuJoCo's schema: "unique element"); one in the world body, or in a
//!   `<frame>` of it, is refused ("World body cannot have inertia"). One in a `<frame>` of a body
//!   is the body's, placed by the frame, as MuJoCo 4 places it.
//! - `pos` and `mass` are required. The frame of the centre of mass is `Trans(pos)` then the
//!   orientation, read as a body's (`quat`, `axisangle`, `xyaxes`, `zaxis`, `euler`, in the
//!   compiler's angle unit and `eulerseq`).
//! - Exactly one of `diaginertia` and `fullinertia` (the reference makes the second required
//!   when the first is missing; MuJoCo 4.0.1's compiler itself takes a missing tensor as zeros,
//!   a point mass: refused here, as the reference says). `diaginertia` gives the principal
//!   moments in the orientation's axes: the tensor `[ixx, 0, 0, iyy, 0, izz]`. `fullinertia` is
//!   the symmetric tensor in the body's axes, written `M(1,1) M(2,2) M(3,3) M(1,2) M(1,3)
//!   M(2,3)`: the diagonal first, where URDF's order, which [`Inertial::inertia`] keeps, is
//!   `ixx ixy ixz iyy iyz izz`. MuJoCo turns it to its principal axes; it is kept as written
//!   here (the same body). `fullinertia` beside an orientation is refused, as MuJoCo refuses it
//!   (the tensor's axes are the body's), and so is `fullinertia` beside `diaginertia`.
//! - The values are taken as written, as the URDF reader takes them: a rigid body's rules (a
//!   mass of zero or more, a positive semi-definite tensor, the triangle inequality) are checked
//!   where dynamics are asked for ([`Inertial::fault`]), not on load. A word that is no number is
//!   refused, naming the body and the line.
//!
//! Which bodies MuJoCo gives an inertia from their geoms (`<compiler inertiafromgeom>`, read per
//! model file, so an attached model keeps its own): each such body is listed in
//! [`crate::Description::inertia_from_geometry`] and has no inertial from this reader, so that
//! dynamics refuse it by name rather than take it as massless.
//!
//! - `auto` (the default): a body with a geom and no `<inertial>`.
//! - `true`: every body with a geom; its `<inertial>`, if written, is what MuJoCo replaces, so it
//!   is read (and refused if malformed) but not kept. A body with no geom keeps its `<inertial>`.
//! - `false`: only `<inertial>`s count; a body without one is massless.
//!
//! A body with neither a geom nor an `<inertial>` is massless; the world body's geoms are the
//! scene and never count. A geom counts whether it collides or not (a visual geom, `contype` and
//! `conaffinity` both 0, has mass in MuJoCo), and wherever it is in the body (in a `<frame>`
//! too). Simplified: MuJoCo counts only the geoms whose `group` lies within `<compiler
//! inertiagrouprange>` (default 0 to 5), and a geom of zero `mass` or `density` adds nothing;
//! here every geom counts. So a body is listed where MuJoCo might give it no mass from its
//! geoms (or, under `true`, keep its `<inertial>`): the simplification can only refuse a body
//! dynamics would otherwise take, never give one a mass MuJoCo does not.

use roxmltree::Node;

use super::{ORIENTATION, Place, Reader, WORLD, Within, pose};
use crate::description::InertialDescription;
use crate::error::{Element, LoadErrorKind};
use crate::inertia::Inertial;

/// `<compiler inertiafromgeom>`: whether MuJoCo computes a body's inertia from its geoms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum FromGeom {
    /// Never: only `<inertial>` elements count.
    False,
    /// Always, for a body with geoms, replacing its `<inertial>`.
    True,
    /// For a body with geoms and no `<inertial>` (MuJoCo's default).
    Auto,
}

impl<'d, 't> Reader<'d, 't> {
    /// One `<inertial>` (`node`) among the children of `container` (a body, a frame in one, or
    /// the world body), for link `at.parent`, placed by `at.frame`.
    pub(super) fn inertial(
        &mut self,
        place: Place<'d, 't>,
        container: Node<'d, 't>,
        node: Node<'d, 't>,
        at: &Within<'_>,
    ) -> Result<(), LoadErrorKind> {
        let Within { model, parent, frame, .. } = *at;
        if parent == WORLD || container.tag_name().name() == "worldbody" {
            let message = format!(
                "an <inertial> belongs in a <body>, not in <{}>: the world body has no mass (MuJoCo: \"World body \
                 cannot have inertia\")",
                container.tag_name().name()
            );
            return Err(place.error(node, None, message));
        }
        let element = Some(Element::Body(parent.to_owned()));
        let attributes = self.attributes(model, place, node, "inertial", None, &element)?;
        let here = |message: &str| place.error(node, element.clone(), format!("<inertial>: {message}"));
        if self.description.inertials.iter().any(|i| i.link == parent) {
            return Err(here("a second one in this body (MuJoCo's schema allows one)"));
        }
        if !attributes.contains_key("pos") {
            return Err(here("needs a `pos` (MuJoCo requires one)"));
        }
        let Some(mass) = attributes.get("mass") else { return Err(here("needs a `mass` (MuJoCo requires one)")) };
        let read = || -> Result<Inertial, LoadErrorKind> {
            let [mass] = mass.numbers::<1>("mass", &element)?;
            let origin = frame.clone().then(&pose(model, &attributes, &element)?);
            let inertia = match (attributes.get("diaginertia"), attributes.get("fullinertia")) {
                (Some(diagonal), None) => {
                    let [xx, yy, zz] = diagonal.numbers::<3>("diaginertia", &element)?;
                    [xx, 0.0, 0.0, yy, 0.0, zz]
                }
                (None, Some(full)) => {
                    if let Some(form) = ORIENTATION.iter().find(|form| attributes.contains_key(**form)) {
                        let message = format!(
                            "`fullinertia` and `{form}` cannot both be written: the tensor is in the body's axes \
                             (MuJoCo refuses both)"
                        );
                        return Err(full.error(&element, message));
                    }
                    // MuJoCo's order, the diagonal first, into URDF's.
                    let [xx, yy, zz, xy, xz, yz] = full.numbers::<6>("fullinertia", &element)?;
                    [xx, xy, xz, yy, yz, zz]
                }
                (Some(_), Some(full)) => {
                    let message = "`diaginertia` and `fullinertia` cannot both be written".to_owned();
                    return Err(full.error(&element, message));
                }
                (None, None) => {
                    let message = "needs `diaginertia` or `fullinertia` (MuJoCo's XML reference requires one)";
                    return Err(place.error(node, element.clone(), message.to_owned()));
                }
            };
            Ok(Inertial { mass, origin, inertia })
        };
        let inertial = read().map_err(within_inertial)?;
        let line = Some(place.line(node.range().start));
        self.description.inertials.push(InertialDescription { link: parent.to_owned(), line, inertial });
        Ok(())
    }

    /// After body `body` (read in `model`) and its children: whether MuJoCo computes its inertia
    /// from its geoms, by `<compiler inertiafromgeom>` (module doc). If so it is listed in
    /// [`crate::Description::inertia_from_geometry`], and under `true` its written
    /// `<inertial>` is dropped.
    pub(super) fn inertia_from_geoms(&mut self, model: &super::Model, body: &str) {
        if !self.geom_bodies.contains(body) {
            return;
        }
        let written = self.description.inertials.iter().rposition(|i| i.link == body);
        let inferred = match (model.compiler.inertia_from_geom, written) {
            (FromGeom::False, _) => false,
            (FromGeom::Auto, written) => written.is_none(),
            (FromGeom::True, written) => {
                if let Some(k) = written {
                    self.description.inertials.remove(k);
                }
                true
            }
        };
        if inferred {
            self.description.inertia_from_geometry.push(body.to_owned());
        }
    }
}

/// An error inside an `<inertial>`, its message saying so.
fn within_inertial(error: LoadErrorKind) -> LoadErrorKind {
    match error {
        LoadErrorKind::Located { element, line, message } => {
            LoadErrorKind::Located { element, line, message: format!("<inertial>: {message}") }
        }
        LoadErrorKind::Included { file, error } => {
            LoadErrorKind::Included { file, error: Box::new(within_inertial(*error)) }
        }
        other => other,
    }
}
