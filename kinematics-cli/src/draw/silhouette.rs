//! The region a solid covers on the screen, in the two forms `svg.rs` draws: a convex polygon
//! (a primitive's outline, the hull of projected surface points) and, for a mesh, the cells of a
//! grid that its projected triangles touch, merged into rectangles.
//!
//! A mesh of thousands of triangles drawn triangle by triangle would weigh megabytes, and most of
//! its triangles lie over others. The grid's cells are [`CELL`] pixels wide, aligned on the
//! screen's origin; a cell is kept when it meets a triangle (edges and corners included, so a
//! sheet seen edge-on or a sliver is kept too). The region kept holds the projection and lies
//! within one cell's diagonal of it.

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

/// A rectangle of whole cells: columns `x0..x1`, rows `y0..y1` (cell `(i, j)` is the square from
/// `(i, j) * CELL` to `(i + 1, j + 1) * CELL`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cells {
    /// First column.
    pub x0: i64,
    /// Last column + 1.
    pub x1: i64,
    /// First row.
    pub y0: i64,
    /// Last row + 1.
    pub y1: i64,
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

/// The first and last cell a closed interval holding the coordinates `x` meets inside.
fn span(x: [f64; 3]) -> (i64, i64) {
    let (lo, hi) = (x.into_iter().fold(f64::INFINITY, f64::min), x.into_iter().fold(f64::NEG_INFINITY, f64::max));
    let first = (lo / CELL).floor() as i64;
    (first, ((hi / CELL).ceil() as i64 - 1).max(first))
}

/// The cells that the triangles `triangles` (indices into the screen points `points`) meet, as
/// rectangles: each row's runs, a run carried down while the rows below repeat it; ordered by
/// first row, then first column.
pub fn cells(points: &[(f64, f64)], triangles: &[[u32; 3]]) -> Vec<Cells> {
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
        // The cells whose inside meets the triangle's bounding box (a box edge on a cell's edge
        // takes the cell inside it, not the one it only touches; a point or segment takes one).
        let (i0, i1) = span(t.map(|p| p.0));
        let (j0, j1) = span(t.map(|p| p.1));
        for j in j0..=j1 {
            for i in i0..=i1 {
                let at = (j - lo.1) as usize * width + (i - lo.0) as usize;
                if !grid[at] && meets(&t, i, j) {
                    grid[at] = true;
                }
            }
        }
    }
    let mut done = Vec::new();
    // Rectangles still growing downwards: columns and first row.
    let mut open: Vec<(i64, i64, i64)> = Vec::new();
    for row in 0..=height {
        let j = lo.1 + row as i64;
        let mut runs = Vec::new();
        if row < height {
            let line = &grid[row * width..(row + 1) * width];
            let mut i = 0;
            while i < width {
                if line[i] {
                    let start = i;
                    while i < width && line[i] {
                        i += 1;
                    }
                    runs.push((lo.0 + start as i64, lo.0 + i as i64));
                } else {
                    i += 1;
                }
            }
        }
        let mut still = Vec::new();
        for (x0, x1, y0) in open {
            if runs.contains(&(x0, x1)) {
                still.push((x0, x1, y0));
            } else {
                done.push(Cells { x0, x1, y0, y1: j });
            }
        }
        for run in runs {
            if !still.iter().any(|&(x0, x1, _)| (x0, x1) == run) {
                still.push((run.0, run.1, j));
            }
        }
        open = still;
    }
    done.sort_by_key(|c| (c.y0, c.x0));
    done
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
    fn cells_hold_every_triangle_and_merge_into_rectangles() {
        // A 2 px square of two triangles from (1, 1): four columns, four rows of cells, one
        // rectangle; the cells its edges only touch are left out.
        let points = [(1.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0)];
        let square = cells(&points, &[[0, 1, 2], [0, 2, 3]]);
        assert_eq!(square, [Cells { x0: 2, x1: 6, y0: 2, y1: 6 }]);
        // A thin sliver seen edge-on still marks the cells it crosses.
        let sliver = cells(&[(0.1, 0.1), (2.1, 0.1), (1.1, 0.1)], &[[0, 1, 2]]);
        assert_eq!(sliver, [Cells { x0: 0, x1: 5, y0: 0, y1: 1 }]);
        // A right triangle: rows narrowing, each its own run.
        let triangle = cells(&[(0.1, 0.1), (1.8, 0.1), (0.1, 1.8)], &[[0, 1, 2]]);
        assert_eq!(triangle.len(), 4);
        assert_eq!(triangle[0], Cells { x0: 0, x1: 4, y0: 0, y1: 1 });
        assert_eq!(triangle[3], Cells { x0: 0, x1: 1, y0: 3, y1: 4 });
    }
}
