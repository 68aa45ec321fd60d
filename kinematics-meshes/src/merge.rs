//! One triangle soup from a file's parts: every sub-mesh (and, in Collada, every placement of
//! one) appended, in `f64`, with exactly equal vertices shared.

use std::collections::HashMap;

use crate::affine::Affine;

/// The vertices and triangles gathered so far.
///
/// mesh-loader gives every triangle three vertices of its own (a cube's 12 triangles come as 36
/// vertices); the ones that are bit for bit the same point are shared here, which keeps the mesh a
/// third the size and leaves the geometry exactly as read.
#[derive(Debug, Default)]
pub(crate) struct Merged {
    vertices: Vec<[f64; 3]>,
    triangles: Vec<[u32; 3]>,
    index: HashMap<[u64; 3], u32>,
}

impl Merged {
    /// Appends one part: its vertices (converted to `f64`, then placed by `placement` if any) and
    /// triangles (indices into `vertices`). A placement that mirrors reverses each triangle's
    /// winding, so that its outside stays outside.
    pub(crate) fn add(
        &mut self,
        vertices: &[[f32; 3]],
        triangles: &[[u32; 3]],
        placement: Option<&Affine>,
    ) -> Result<(), String> {
        let ids = vertices
            .iter()
            .map(|v| {
                let p = v.map(f64::from);
                self.vertex(placement.map_or(p, |a| a.apply(p)))
            })
            .collect::<Result<Vec<u32>, String>>()?;
        let mirrored = placement.is_some_and(|a| a.determinant() < 0.0);
        for t in triangles {
            let mut global = [0; 3];
            for (g, &i) in global.iter_mut().zip(t) {
                *g = *ids
                    .get(i as usize)
                    .ok_or_else(|| format!("a triangle names vertex {i} of a part that has {} vertices", ids.len()))?;
            }
            if mirrored {
                global.swap(1, 2);
            }
            self.triangles.push(global);
        }
        Ok(())
    }

    fn vertex(&mut self, p: [f64; 3]) -> Result<u32, String> {
        // `+ 0.0` makes -0.0 into 0.0: one point, one key.
        let key = p.map(|x| (x + 0.0).to_bits());
        if let Some(&id) = self.index.get(&key) {
            return Ok(id);
        }
        let id = u32::try_from(self.vertices.len())
            .map_err(|_| format!("it has more than {} distinct vertices", u32::MAX))?;
        self.vertices.push(p);
        self.index.insert(key, id);
        Ok(id)
    }

    /// The triangles gathered, degenerate ones included (the model's check drops them).
    pub(crate) fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    pub(crate) fn finish(self) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        (self.vertices, self.triangles)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_vertices_are_shared_and_mirrors_keep_the_winding() {
        let mut merged = Merged::default();
        let quad =
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        merged.add(&quad, &[[0, 1, 2], [3, 4, 5]], None).unwrap();
        merged.add(&quad[..3], &[[0, 1, 2]], Some(&Affine::scale([-1.0, 1.0, 1.0]))).unwrap();
        let (vertices, triangles) = merged.finish();
        assert_eq!(vertices.len(), 4 + 2);
        assert_eq!(triangles[..2], [[0, 1, 2], [0, 2, 3]]);
        // (0,0,0) is shared; the mirrored copy's last two corners are swapped.
        assert_eq!(triangles[2], [0, 5, 4]);
    }

    #[test]
    fn an_index_past_the_part_is_an_error() {
        let mut merged = Merged::default();
        let error = merged.add(&[[0.0; 3]], &[[0, 0, 3]], None).unwrap_err();
        assert!(error.contains("vertex 3"), "{error}");
    }
}
