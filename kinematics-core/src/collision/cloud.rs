//! Point clouds as obstacles (with the `point-cloud` feature, which the facade's `std` turns on):
//! points with one radius, in a grid of our own built once per scene and asked by every check.
//!
//! A check asks "does this sphere touch any point?", not "which point is nearest?", and most
//! spheres it asks about are far from every point. Kiddo's k-d tree answered the nearest-point
//! question (measured on the Panda against points sampled on the tabletop scene's surfaces:
//! `collides` took 9 us per configuration at 10^3 points, 160 us at 10^5, 1.2 ms at 10^6), so
//! the cloud is a uniform grid instead: each cell holds its points, knows how many cells away
//! (Chebyshev rings) the nearest occupied cell is, and blocks of 8^3 cells know whether they hold
//! any point. A sphere whose cell is farther from every occupied cell than its reach is free at
//! once; otherwise the blocks and then the cells its reach overlaps are visited, a block or cell
//! lying wholly within reach answering at once, one wholly out of reach skipped, and only the
//! rest testing their points.
//!
//! `PointCloud` is asked through `SphereQuery`, which an `Environment` takes with `with_query`.

use std::collections::VecDeque;
use std::vec;
use std::vec::Vec;

use super::obstacles::{ObstacleError, SphereQuery, Vec3};

/// Cells per block side: the coarse level a query visits first.
const BLOCK: usize = 8;

/// Points, each a ball of `radius` (the sensor's resolution, or zero), as obstacles: built once
/// into a grid, then given to an environment with
/// [`Environment::with_query`](super::Environment::with_query). A sphere touches the cloud when a
/// point lies within the two radii of its centre (touching counts).
///
/// ```
/// use kinematics_core::collision::{Environment, PointCloud};
/// let points = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.3, 0.3, 3.0]];
/// let cloud = PointCloud::new(&points, 0.01)?;
/// let env = Environment::empty().with_query(&cloud);
/// assert!(env.hits([0.9, 0.0, 0.0], 0.09) && !env.hits([0.9, 0.0, 0.0], 0.08));
/// assert_eq!(env.len(), 3);
/// # Ok::<(), kinematics_core::collision::ObstacleError>(())
/// ```
pub struct PointCloud {
    radius: f64,
    /// The points' box.
    low: Vec3,
    high: Vec3,
    /// Cell size and the cells along each axis (x fastest).
    cell: f64,
    cells: [usize; 3],
    /// Per cell, its points' range in `points` (`starts[i]..starts[i + 1]`).
    starts: Vec<u32>,
    points: Vec<Vec3>,
    /// Per cell, the Chebyshev rings to the nearest occupied cell (0: occupied), at most 255.
    rings: Vec<u8>,
    /// Blocks of `BLOCK`^3 cells along each axis, and whether each holds a point.
    blocks: [usize; 3],
    occupied: Vec<bool>,
    /// Slack for rounding in the cells' boxes (a point's cell is found by a division).
    slack: f64,
}

impl core::fmt::Debug for PointCloud {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PointCloud")
            .field("points", &self.points.len())
            .field("radius", &self.radius)
            .field("cell", &self.cell)
            .field("cells", &self.cells)
            .finish()
    }
}

/// The squared distances from `c` to the nearest and the farthest point of the box `low..high`.
fn box_distances(c: &Vec3, low: &Vec3, high: &Vec3) -> (f64, f64) {
    let (mut near, mut far) = (0.0, 0.0);
    for i in 0..3 {
        let below = low[i] - c[i];
        let above = c[i] - high[i];
        let gap = below.max(above).max(0.0);
        near += gap * gap;
        let reach = (c[i] - low[i]).abs().max((high[i] - c[i]).abs());
        far += reach * reach;
    }
    (near, far)
}

impl PointCloud {
    /// The cloud of `points`, each of `radius` (zero or more). A point or a radius with a NaN or
    /// an infinity, and a negative radius, are errors (such a point would never collide); so is a
    /// cloud of 2^32 points or more.
    pub fn new(points: &[Vec3], radius: f64) -> Result<Self, ObstacleError> {
        if !radius.is_finite() {
            return Err(ObstacleError::NonFinite { kind: "point cloud radius", index: 0 });
        }
        if radius < 0.0 {
            return Err(ObstacleError::BadSize { kind: "point cloud radius", index: 0 });
        }
        if let Some(index) = points.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(ObstacleError::NonFinite { kind: "point", index });
        }
        if u32::try_from(points.len()).is_err() {
            return Err(ObstacleError::TooMany { kind: "point", count: points.len() });
        }
        let (mut low, mut high) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for p in points {
            for i in 0..3 {
                low[i] = low[i].min(p[i]);
                high[i] = high[i].max(p[i]);
            }
        }
        if points.is_empty() {
            (low, high) = ([0.0; 3], [0.0; 3]);
        }
        // About two cells per point along the longest side's cube root (a surface's points
        // fill a few cells each), between 16 and 128 cells along it.
        let extent = (0..3).map(|i| high[i] - low[i]).fold(0.0, f64::max);
        #[allow(clippy::cast_precision_loss)]
        let along = (2.0 * (8.0 * points.len() as f64).cbrt()).clamp(16.0, 128.0);
        let cell = (extent / along).max(1e-6);
        let scale = (0..3).map(|i| low[i].abs().max(high[i].abs())).fold(cell, f64::max);
        let cells_along = |i: usize| {
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let n = ((high[i] - low[i]) / cell).floor() as usize + 1;
            n
        };
        let cells = [cells_along(0), cells_along(1), cells_along(2)];
        let count = cells[0] * cells[1] * cells[2];
        let mut cloud = PointCloud {
            radius,
            low,
            high,
            cell,
            cells,
            starts: vec![0; count + 1],
            points: Vec::with_capacity(points.len()),
            rings: vec![u8::MAX; count],
            blocks: cells.map(|n| n.div_ceil(BLOCK)),
            occupied: Vec::new(),
            slack: scale * 1e-12,
        };
        // Counting sort of the points by cell.
        let index: Vec<usize> = points.iter().map(|p| cloud.cell_index(cloud.cell_of(p))).collect();
        for &i in &index {
            cloud.starts[i + 1] += 1;
        }
        for i in 0..count {
            cloud.starts[i + 1] += cloud.starts[i];
        }
        let mut next: Vec<u32> = cloud.starts[..count].to_vec();
        let mut sorted = vec![[0.0; 3]; points.len()];
        for (p, &i) in points.iter().zip(&index) {
            sorted[next[i] as usize] = *p;
            next[i] += 1;
        }
        cloud.points = sorted;
        cloud.fill_rings();
        let [bx, by, _] = cloud.blocks;
        cloud.occupied = vec![false; bx * by * cloud.blocks[2]];
        for i in 0..count {
            if cloud.starts[i] < cloud.starts[i + 1] {
                let [x, y, z] = cloud.cell_coordinates(i);
                cloud.occupied[(z / BLOCK * by + y / BLOCK) * bx + x / BLOCK] = true;
            }
        }
        Ok(cloud)
    }

    /// Each point's radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The cell holding `p` (clamped to the grid).
    fn cell_of(&self, p: &Vec3) -> [usize; 3] {
        let along = |i: usize| {
            let t = ((p[i] - self.low[i]) / self.cell).floor().max(0.0);
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let t = t as usize;
            t.min(self.cells[i] - 1)
        };
        [along(0), along(1), along(2)]
    }

    fn cell_index(&self, [x, y, z]: [usize; 3]) -> usize {
        (z * self.cells[1] + y) * self.cells[0] + x
    }

    fn cell_coordinates(&self, i: usize) -> [usize; 3] {
        let [nx, ny, _] = self.cells;
        [i % nx, (i / nx) % ny, i / (nx * ny)]
    }

    /// The box of cells `from..to` (in cell coordinates, `to` exclusive), widened by the slack.
    fn cells_box(&self, from: [usize; 3], to: [usize; 3]) -> (Vec3, Vec3) {
        #[allow(clippy::cast_precision_loss)]
        let at = |i: usize, n: usize| self.low[i] + n as f64 * self.cell;
        (
            [at(0, from[0]) - self.slack, at(1, from[1]) - self.slack, at(2, from[2]) - self.slack],
            [at(0, to[0]) + self.slack, at(1, to[1]) + self.slack, at(2, to[2]) + self.slack],
        )
    }

    /// Each cell's rings to the nearest occupied cell: a breadth-first search from every occupied
    /// cell over the 26 neighbours (a Chebyshev step each), up to 255.
    fn fill_rings(&mut self) {
        let mut queue = VecDeque::new();
        for i in 0..self.rings.len() {
            if self.starts[i] < self.starts[i + 1] {
                self.rings[i] = 0;
                queue.push_back(i);
            }
        }
        let [nx, ny, nz] = self.cells;
        while let Some(i) = queue.pop_front() {
            let ring = self.rings[i];
            if ring == u8::MAX - 1 {
                continue;
            }
            let [x, y, z] = self.cell_coordinates(i);
            for z2 in z.saturating_sub(1)..(z + 2).min(nz) {
                for y2 in y.saturating_sub(1)..(y + 2).min(ny) {
                    for x2 in x.saturating_sub(1)..(x + 2).min(nx) {
                        let j = (z2 * ny + y2) * nx + x2;
                        if self.rings[j] == u8::MAX {
                            self.rings[j] = ring + 1;
                            queue.push_back(j);
                        }
                    }
                }
            }
        }
    }

    /// Whether a point lies within `reach` of `c` among the cells `from..to` of one block.
    fn cells_touch(&self, c: &Vec3, reach2: f64, from: [usize; 3], to: [usize; 3]) -> bool {
        for z in from[2]..to[2] {
            for y in from[1]..to[1] {
                for x in from[0]..to[0] {
                    let i = self.cell_index([x, y, z]);
                    let (start, end) = (self.starts[i] as usize, self.starts[i + 1] as usize);
                    if start == end {
                        continue;
                    }
                    let (low, high) = self.cells_box([x, y, z], [x + 1, y + 1, z + 1]);
                    let (near, far) = box_distances(c, &low, &high);
                    if near > reach2 {
                        continue;
                    }
                    if far <= reach2 {
                        return true;
                    }
                    for p in &self.points[start..end] {
                        let d = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
                        let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                        // Not above: a NaN distance counts as touching.
                        if d2.partial_cmp(&reach2) != Some(core::cmp::Ordering::Greater) {
                            return true;
                        }
                    }
                }
            }
        }
        false
    }
}

impl SphereQuery for PointCloud {
    fn touches(&self, c: Vec3, radius: f64) -> bool {
        if self.points.is_empty() {
            return false;
        }
        let reach = radius + self.radius;
        let reach2 = reach * reach;
        // Out of reach of the points' box: free.
        if box_distances(&c, &self.low, &self.high).0 > reach2 + self.slack {
            return false;
        }
        // Inside the grid, the rings to the nearest occupied cell bound the distance to every
        // point from below: a point `k` rings away is at least `k - 1` cells from `c`.
        let inside = (0..3).all(|i| c[i] >= self.low[i] && c[i] <= self.high[i]);
        let cell = self.cell_of(&c);
        if inside {
            let rings = self.rings[self.cell_index(cell)];
            if rings > 1 && f64::from(rings - 1) * self.cell - self.slack > reach {
                return false;
            }
        }
        // The cells the reach's box overlaps, block by block.
        let span = |i: usize, value: f64| {
            let t = ((value - self.low[i]) / self.cell).floor().max(0.0);
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let t = (t as usize).min(self.cells[i] - 1);
            t
        };
        let from = [span(0, c[0] - reach), span(1, c[1] - reach), span(2, c[2] - reach)];
        let to = [span(0, c[0] + reach) + 1, span(1, c[1] + reach) + 1, span(2, c[2] + reach) + 1];
        let [bx, by, _] = self.blocks;
        for z in from[2] / BLOCK..=(to[2] - 1) / BLOCK {
            for y in from[1] / BLOCK..=(to[1] - 1) / BLOCK {
                for x in from[0] / BLOCK..=(to[0] - 1) / BLOCK {
                    if !self.occupied[(z * by + y) * bx + x] {
                        continue;
                    }
                    let start = [x * BLOCK, y * BLOCK, z * BLOCK];
                    let end = [0, 1, 2].map(|i| (start[i] + BLOCK).min(self.cells[i]));
                    let (low, high) = self.cells_box(start, end);
                    let (near, far) = box_distances(&c, &low, &high);
                    if near > reach2 {
                        continue;
                    }
                    if far <= reach2 {
                        return true; // the block holds a point, and all of it is within reach
                    }
                    let lo = [0, 1, 2].map(|i| start[i].max(from[i]));
                    let hi = [0, 1, 2].map(|i| end[i].min(to[i]));
                    if self.cells_touch(&c, reach2, lo, hi) {
                        return true;
                    }
                }
            }
        }
        false
    }

    /// The nearest point by shells of cells around `center`'s (clamped to the grid): a cell
    /// `k` shells away lies at least `k - 1` cells from `center`, so the search ends at the first
    /// shell beyond the nearest point found (or beyond `limit`); inside the grid it starts at the
    /// rings to the nearest occupied cell.
    fn nearest(&self, c: Vec3, limit: f64) -> Option<(f64, Vec3)> {
        if self.points.is_empty() {
            return None;
        }
        let reach = limit + self.radius;
        if box_distances(&c, &self.low, &self.high).0.sqrt() - self.slack >= reach {
            return None;
        }
        let home = self.cell_of(&c);
        let inside = (0..3).all(|i| c[i] >= self.low[i] && c[i] <= self.high[i]);
        let first = if inside { usize::from(self.rings[self.cell_index(home)]) } else { 0 };
        let widest = self.cells[0].max(self.cells[1]).max(self.cells[2]);
        let (mut best, mut point) = (reach, None);
        for k in first..=widest {
            #[allow(clippy::cast_precision_loss)]
            let floor = (k.saturating_sub(1)) as f64 * self.cell - self.slack;
            if floor >= best {
                break;
            }
            self.shell(home, k, |cell| {
                let i = self.cell_index(cell);
                let (start, end) = (self.starts[i] as usize, self.starts[i + 1] as usize);
                if start == end {
                    return;
                }
                let (low, high) = self.cells_box(cell, cell.map(|x| x + 1));
                if box_distances(&c, &low, &high).0.sqrt() >= best {
                    return;
                }
                for p in &self.points[start..end] {
                    let d = [c[0] - p[0], c[1] - p[1], c[2] - p[2]];
                    let length = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                    if length < best {
                        best = length;
                        point = Some(d);
                    }
                }
            });
        }
        let d = point?;
        let normal = if best > 0.0 { d.map(|x| x / best) } else { [0.0; 3] };
        Some((best - self.radius, normal))
    }

    fn len(&self) -> usize {
        self.points.len()
    }
}

impl PointCloud {
    /// Calls `visit` with each cell of the grid exactly `k` cells from `home` (Chebyshev).
    fn shell(&self, home: [usize; 3], k: usize, mut visit: impl FnMut([usize; 3])) {
        let range = |i: usize| home[i].saturating_sub(k)..=(home[i] + k).min(self.cells[i] - 1);
        for z in range(2) {
            for y in range(1) {
                let edge = z.abs_diff(home[2]) == k || y.abs_diff(home[1]) == k;
                if edge {
                    for x in range(0) {
                        visit([x, y, z]);
                    }
                } else {
                    // Only the two faces at x = home +- k, where they lie in the grid.
                    if let Some(x) = home[0].checked_sub(k).filter(|_| k > 0) {
                        visit([x, y, z]);
                    }
                    if home[0] + k < self.cells[0] {
                        visit([home[0] + k, y, z]);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic stream in [-1, 1) (splitmix64).
    fn stream(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            #[allow(clippy::cast_precision_loss)]
            let unit = ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64;
            2.0 * unit - 1.0
        }
    }

    /// The cloud against every point asked in turn, on queries from inside and far outside its
    /// box, small and large.
    fn agrees(points: &[Vec3], point_radius: f64, next: &mut impl FnMut() -> f64) -> (usize, usize) {
        let cloud = PointCloud::new(points, point_radius).unwrap();
        let (mut touching, mut apart) = (0, 0);
        for k in 0..3_000 {
            let spread = if k % 3 == 0 { 3.0 } else { 1.2 };
            let center = [spread * next(), spread * next(), spread * next()];
            let radius = if k % 2 == 0 { 0.3 * next().abs() } else { 0.01 + 0.05 * next().abs() };
            let reach = radius + point_radius;
            let brute = points.iter().any(|p| (0..3).map(|i| (p[i] - center[i]).powi(2)).sum::<f64>() <= reach * reach);
            assert_eq!(cloud.touches(center, radius), brute, "{} points, {center:?} {radius}", points.len());
            if brute {
                touching += 1
            } else {
                apart += 1
            }
            // The nearest point, within a limit or none (every third query).
            let nearest = points
                .iter()
                .map(|p| (0..3).map(|i| (center[i] - p[i]).powi(2)).sum::<f64>().sqrt() - point_radius)
                .fold(f64::INFINITY, f64::min);
            let limit = if k % 3 == 1 { f64::INFINITY } else { radius };
            match cloud.nearest(center, limit) {
                Some((d, n)) => {
                    assert_eq!(d.to_bits(), nearest.to_bits(), "{} points, {center:?} within {limit}", points.len());
                    let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                    assert!((length - 1.0).abs() < 1e-12 || d == -point_radius, "{n:?}");
                }
                None => assert!(nearest >= limit, "{} points, {center:?}: {nearest} within {limit}", points.len()),
            }
        }
        (touching, apart)
    }

    #[test]
    fn the_grid_answers_as_every_point_asked_in_turn() {
        let mut next = stream(5);
        // A haze, planes (a sensor's surfaces), a line, one point, and many copies of one.
        for count in [1, 7, 100, 5_000] {
            let haze: Vec<Vec3> = (0..count).map(|_| [next(), next(), next()]).collect();
            agrees(&haze, 0.02, &mut next);
        }
        let plane: Vec<Vec3> = (0..8_000).map(|_| [next(), next(), 0.25]).collect();
        let (touching, apart) = agrees(&plane, 0.0, &mut next);
        assert!(touching > 100 && apart > 1_000, "{touching} touching, {apart} apart");
        let line: Vec<Vec3> = (0..500).map(|_| [0.1, next(), -0.3]).collect();
        agrees(&line, 0.005, &mut next);
        agrees(&[[0.2, 0.2, 0.2]; 300], 0.1, &mut next);
    }

    #[test]
    fn far_cells_know_they_are_far() {
        let cloud = PointCloud::new(&[[0.0; 3], [1.0, 1.0, 1.0]], 0.0).unwrap();
        let middle = cloud.cell_of(&[0.5, 0.5, 0.5]);
        assert!(cloud.rings[cloud.cell_index(middle)] > 3, "{cloud:?}");
        assert!(!cloud.touches([0.5, 0.5, 0.5], 0.8) && cloud.touches([0.5, 0.5, 0.5], 0.87));
    }

    #[test]
    fn bad_clouds_are_refused() {
        assert_eq!(
            PointCloud::new(&[[0.0; 3], [f64::NAN, 0.0, 0.0]], 0.1).unwrap_err(),
            ObstacleError::NonFinite { kind: "point", index: 1 }
        );
        assert!(PointCloud::new(&[[0.0; 3]], -0.1).is_err());
        assert!(PointCloud::new(&[[0.0; 3]], f64::INFINITY).is_err());
        let empty = PointCloud::new(&[], 0.0).unwrap();
        assert!(!empty.touches([0.0; 3], 10.0) && empty.is_empty());
        assert_eq!(empty.nearest([0.0; 3], f64::INFINITY), None);
        // A point of radius zero still collides with a sphere around it.
        assert!(PointCloud::new(&[[0.0; 3]], 0.0).unwrap().touches([0.05, 0.0, 0.0], 0.05));
    }
}
