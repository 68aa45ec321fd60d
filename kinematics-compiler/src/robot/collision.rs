//! Collision: every sphere's centre in the base frame (`sphere_centers`), from the poses of the
//! links that carry spheres, each centre `R p + t` of its link's pose with `p` its place in the
//! link's frame (the `<collision>` element's origin applied to the cover's centre): only what the
//! centres need of the poses is computed.

use proc_macro2::TokenStream;

use super::Context;
use crate::emit::emit_points;
use crate::error::CompileError;
use crate::ik::geometry::transform_point;
use crate::request::{Request, compile};

/// The generic body of `sphere_centers`, named `name`, and its function's doc.
pub(super) fn sphere_centers(cx: &Context<'_>, name: &str) -> Result<(TokenStream, String), CompileError> {
    let tree = cx.tree();
    let spheres = cx.spheres();
    let mut links: Vec<usize> = spheres.iter().map(|s| s.link.0).collect();
    links.sort_unstable();
    links.dedup();
    let request = Request {
        base: Some(cx.base.clone()),
        tips: links.iter().map(|&l| tree.links()[l].name.clone()).collect(),
        position_only: false,
        velocity: None,
    };
    let mut compiled = compile(tree, &request)?;
    let points: Vec<(usize, [f64; 3])> = spheres
        .iter()
        .map(|s| {
            // Spheres come in tree order of their links, so `links` is sorted.
            #[allow(clippy::expect_used, reason = "invariant: every sphere's link is in `links`")]
            let frame = links.binary_search(&s.link.0).expect("the links are those of the spheres");
            let origin = &tree.link(s.link).collisions[s.collision].origin;
            (frame, transform_point(origin, s.sphere.center))
        })
        .collect();
    let centers = compiled.points(&points);
    let doc = format!(
        "The centres of the robot's {} collision spheres in `{}` (radii in `SPHERE_RADII`, links in `SPHERE_LINKS`)",
        spheres.len(),
        cx.base
    );
    let body_doc = format!(" {doc}.");
    Ok((emit_points(&compiled, &centers, &cx.body_options(name), &body_doc), doc))
}
