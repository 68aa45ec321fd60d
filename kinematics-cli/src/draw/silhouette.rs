//! The region a solid covers on the screen, in the two forms `svg.rs` draws: a convex polygon
//! (a primitive's outline, the hull of projected surface points) and, for a mesh, the outline of
//! the cells of a grid that its projected triangles touch.
//!
//! A mesh of thousands of triangles drawn triangle by triangle would weigh megabytes, and most of
//! its triangles lie over others. The grid's cells are [`CELL`] pixels wide, aligned on the
//! screen's origin; a cell is kept when it meets a triangle (edges and corners included, so a
//! sheet seen edge-on or a sliver is kept too). The region kept holds the projection and lies
//! within one cell's diagonal of it; its boundary is traced into closed loops of horizontal and
//! vertical edges, clockwise on the screen around the region and anticlockwise around its holes,
//! so the nonzero fill rule fills the region and no hole.

/// Side of a grid cell, in pixels.
pub const CELL: f64 = 0.5;

/// The convex hull of screen points, counter-clockwise in (x, y) from the smallest (x, then y),
/// without points on its edges (Andrew's monotone chain; ties broken by the points' order).
pub fn hull(mut points: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    points.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    points.dedup();
    if points.len() < 3 {
        return points;
    }
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(points.len() + 1);
    for pass in [points.clone(), points.into_iter().rev().collect()] {
        let start = out.len();
        for p in pass {
            while out.len() >= start + 2 && cross(out[out.len() - 2], out[out.len() - 1], p) <= 0.0 {
                out.pop();
            }
            out.push(p);
        }
        // The pass's last point is the next pass's first.
        out.pop();
    }
    out
}

/// Whether the triangle `t` (screen points) meets the closed cell `(i, j)`: no separating axis
/// among the triangle's edge normals (the cell's own axes are the bounding box the caller
/// scanned).
fn meets(t: &[(f64, f64); 3], i: i64, j: i64) -> bool {
    let (cx, cy) = ((i as f64 + 0.5) * CELL, (j as f64 + 0.5) * CELL);
    (0..3).all(|k| {
        let (p, q, r) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
        let n = (p.1 - q.1, q.0 - p.0);
        if n == (0.0, 0.0) {
            return true;
        }
        let dot = |a: (f64, f64)| n.0 * a.0 + n.1 * a.1;
        let (a, b) = (dot(p), dot(r));
        let (centre, reach) = (dot((cx, cy)), (n.0.abs() + n.1.abs()) * CELL / 2.0);
        a.min(b) <= centre + reach && a.max(b) >= centre - reach
    })
}

/// The first and last cell whose inside meets a closed interval holding the coordinates `x` (an
/// end on a cell's edge takes the cell inside, not the one it touches; a point takes one cell).
fn span(x: [f64; 3]) -> (i64, i64) {
    let (lo, hi) = (x.into_iter().fold(f64::INFINITY, f64::min), x.into_iter().fold(f64::NEG_INFINITY, f64::max));
    let first = (lo / CELL).floor() as i64;
    (first, ((hi / CELL).ceil() as i64 - 1).max(first))
}

/// The directions of a boundary edge on the screen (y down), clockwise from east.
const STEPS: [(i64, i64); 4] = [(1, 0), (0, 1), (-1, 0), (0, -1)];

/// The outline of the cells that the triangles `triangles` (indices into the screen points
/// `points`) meet: closed loops of grid points (`(i, j)` is the screen point `(i, j) * CELL`),
/// each starting at its first point in row order and listing only its corners.
pub fn outline(points: &[(f64, f64)], triangles: &[[u32; 3]]) -> Vec<Vec<(i64, i64)>> {
    let corners = |t: &[u32; 3]| t.map(|i| points[i as usize]);
    let (mut lo, mut hi) = ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN));
    for t in triangles {
        let t = corners(t);
        let ((i0, i1), (j0, j1)) = (span(t.map(|p| p.0)), span(t.map(|p| p.1)));
        lo = (lo.0.min(i0), lo.1.min(j0));
        hi = (hi.0.max(i1), hi.1.max(j1));
    }
    if lo.0 > hi.0 {
        return Vec::new();
    }
    let (width, height) = ((hi.0 - lo.0 + 1) as usize, (hi.1 - lo.1 + 1) as usize);
    let mut grid = vec![false; width * height];
    for t in triangles {
        let t = corners(t);
        let ((i0, i1), (j0, j1)) = (span(t.map(|p| p.0)), span(t.map(|p| p.1)));
        for j in j0..=j1 {
            for i in i0..=i1 {
                let at = (j - lo.1) as usize * width + (i - lo.0) as usize;
                if !grid[at] && meets(&t, i, j) {
                    grid[at] = true;
                }
            }
        }
    }
    // Every side of a kept cell whose neighbour is not kept, as a bit (its direction in STEPS) at
    // its first point, the cell's sides taken clockwise; points are grid corners relative to
    // `lo`, in rows of `width + 1`.
    let filled = |i: i64, j: i64| {
        (0..width as i64).contains(&i) && (0..height as i64).contains(&j) && grid[j as usize * width + i as usize]
    };
    let row = width as i64 + 1;
    let mut edges = vec![0u8; (width + 1) * (height + 1)];
    for j in 0..height as i64 {
        for i in 0..width as i64 {
            if !filled(i, j) {
                continue;
            }
            // Top (east from the top-left corner), right, bottom, left.
            for (direction, (start, neighbour)) in
                [((i, j), (i, j - 1)), ((i + 1, j), (i + 1, j)), ((i + 1, j + 1), (i, j + 1)), ((i, j + 1), (i - 1, j))]
                    .into_iter()
                    .enumerate()
            {
                if !filled(neighbour.0, neighbour.1) {
                    edges[(start.1 * row + start.0) as usize] |= 1 << direction;
                }
            }
        }
    }
    let mut loops = Vec::new();
    for first in 0..edges.len() {
        while edges[first] != 0 {
            let mut at = (first as i64 % row, first as i64 / row);
            let mut heading = edges[first].trailing_zeros() as usize;
            let mut corners = vec![(at.0 + lo.0, at.1 + lo.1)];
            loop {
                edges[(at.1 * row + at.0) as usize] &= !(1 << heading);
                at = (at.0 + STEPS[heading].0, at.1 + STEPS[heading].1);
                let index = (at.1 * row + at.0) as usize;
                if edges[index] == 0 {
                    break;
                }
                // Where two loops touch at a corner, turn right, then go on, then turn left.
                let Some(next) =
                    [1, 0, 3].map(|turn| (heading + turn) % 4).into_iter().find(|d| edges[index] >> d & 1 == 1)
                else {
                    break;
                };
                if next != heading {
                    corners.push((at.0 + lo.0, at.1 + lo.1));
                }
                heading = next;
            }
            loops.push(corners);
        }
    }
    loops
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hull_drops_inner_and_edge_points() {
        let square = vec![(0.0, 0.0), (1.0, 0.5), (2.0, 0.0), (2.0, 2.0), (1.0, 1.0), (0.0, 2.0), (1.0, 2.0)];
        assert_eq!(hull(square), [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        assert_eq!(hull(vec![(1.0, 1.0), (1.0, 1.0)]), [(1.0, 1.0)]);
    }

    #[test]
    fn outlines_hold_every_triangle_clockwise_with_holes_anticlockwise() {
        // A 2 px square of two triangles from (1, 1): cells 2 to 5 both ways; the cells its
        // edges only touch are left out.
        let points = [(1.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0)];
        assert_eq!(outline(&points, &[[0, 1, 2], [0, 2, 3]]), [vec![(2, 2), (6, 2), (6, 6), (2, 6)]]);
        // A thin sliver seen edge-on still marks the cells it crosses.
        assert_eq!(
            outline(&[(0.1, 0.1), (2.1, 0.1), (1.1, 0.1)], &[[0, 1, 2]]),
            [vec![(0, 0), (5, 0), (5, 1), (0, 1)]]
        );
        // A right triangle: a staircase.
        assert_eq!(
            outline(&[(0.1, 0.1), (1.8, 0.1), (0.1, 1.8)], &[[0, 1, 2]]),
            [vec![(0, 0), (4, 0), (4, 1), (3, 1), (3, 2), (2, 2), (2, 3), (1, 3), (1, 4), (0, 4)]]
        );
        // A frame of four bars 0.3 px wide around a hole: the outside clockwise, the hole
        // anticlockwise.
        let (near, far) = ((0.1, 0.4), (2.6, 2.9));
        let mut frame = Vec::new();
        let mut bars = Vec::new();
        for ((x0, x1), (y0, y1)) in
            [((near.0, far.1), near), ((near.0, far.1), far), (near, (near.0, far.1)), (far, (near.0, far.1))]
        {
            let k = frame.len() as u32;
            frame.extend([(x0, y0), (x1, y0), (x1, y1), (x0, y1)]);
            bars.extend([[k, k + 1, k + 2], [k, k + 2, k + 3]]);
        }
        let loops = outline(&frame, &bars);
        assert_eq!(loops, [vec![(0, 0), (6, 0), (6, 6), (0, 6)], vec![(1, 1), (1, 5), (5, 5), (5, 1)]]);
    }
}
