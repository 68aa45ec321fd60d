//! Self-collision pairs decided by table: a [`PairGrid`] covers the checked pairs whose links only
//! one or two revolute joints move relative to each other, over those joints' values (the
//! compiler's `pair_grids` works out each cell ahead of time: free, colliding or to test). A check
//! looks up each configuration's cell, marks the configurations of colliding cells, and tests the
//! grid's pairs only on those whose cells say "to test" (or that fall outside the grid).

use super::verdicts::{CheckLanes, LaneMask};

/// The most grids a check reads; the compiler writes no more.
pub const MAX_GRIDS: usize = 8;

/// A cell's code: the pairs must be tested there.
const TEST: u8 = 0;
/// A cell's code: some sphere pair of the grid's pairs overlaps everywhere in the cell.
const COLLIDING: u8 = 2;

/// A grid over the values of one or two joints, each cell saying whether the self-collision pairs
/// it covers are free, colliding or to be tested for every configuration in the cell.
///
/// ```
/// use kinematics_core::collision::PairGrid;
/// // One joint (q[0]) from -1 to 1 in four cells: to test, free, colliding, free.
/// let grid = PairGrid {
///     dofs: [0, 0],
///     lower: [-1.0, -1.0],
///     scale: [2.0, 0.0],
///     cells: [4, 1],
///     states: &[0b01_10_01_00],
///     pairs: &[0],
/// };
/// assert_eq!(grid.code(-0.9, -0.9), 0);
/// assert_eq!(grid.code(-0.4, -0.4), 1);
/// assert_eq!(grid.code(0.2, 0.2), 2);
/// assert_eq!(grid.code(1.5, 1.5), 0); // outside: tested
/// assert_eq!(grid.code(f64::NAN, f64::NAN), 0);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct PairGrid<'a> {
    /// The entries of `q` the grid is over (the second is the first again for one joint).
    pub dofs: [usize; 2],
    /// Where cell 0 starts along each joint.
    pub lower: [f64; 2],
    /// Cells per unit of each joint's value (0 along the second for one joint).
    pub scale: [f64; 2],
    /// How many cells along each joint (1 along the second for one joint).
    pub cells: [usize; 2],
    /// The cells' codes, four to a byte: cell `(i, j)` is `k = i * cells[1] + j`, in bits
    /// `2 (k % 4)` of byte `k / 4` (0 to test, 1 free, 2 colliding).
    pub states: &'a [u8],
    /// The pairs it decides (indices into the tables' `pairs`).
    pub pairs: &'a [usize],
}

impl PairGrid<'_> {
    /// The code of the cell the joints' values `(a, b)` fall in: 0 (to test) outside the grid, for
    /// a NaN, and for a cell the states do not hold.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn code(&self, a: f64, b: f64) -> u8 {
        let x = (a - self.lower[0]) * self.scale[0];
        let y = (b - self.lower[1]) * self.scale[1];
        let inside = x >= 0.0 && x < self.cells[0] as f64 && y >= 0.0 && y < self.cells[1] as f64;
        if !inside {
            return TEST;
        }
        // In range and not NaN, so the truncations are the floors.
        let k = x as usize * self.cells[1] + y as usize;
        self.states.get(k / 4).map_or(TEST, |byte| (byte >> (2 * (k % 4))) & 3)
    }

    /// The lanes of `q` whose cells collide, and the lanes left to the tests (every lane where
    /// `q` has no entry the grid is over).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn lanes<L: CheckLanes>(&self, q: &[L]) -> (LaneMask, LaneMask) {
        let (mut colliding, mut test) = (0u32, 0u32);
        let (Some(&a), Some(&b)) = (q.get(self.dofs[0]), q.get(self.dofs[1])) else {
            return (LaneMask::NONE, LaneMask::full(L::WIDTH));
        };
        for lane in 0..L::WIDTH {
            let code = u32::from(self.code(a.lane_f64(lane), b.lane_f64(lane)));
            colliding |= u32::from(code == u32::from(COLLIDING)) << lane;
            test |= u32::from(code == u32::from(TEST)) << lane;
        }
        (LaneMask::from_bits(colliding), LaneMask::from_bits(test))
    }
}

/// Which lanes each grid leaves to the tests (grid `g`'s in entry `g`), and the lanes some grid
/// says collide.
#[derive(Debug, Clone, Copy)]
pub(super) struct GridVerdicts {
    /// Per grid, the lanes to test.
    pub test: [LaneMask; MAX_GRIDS],
    /// The lanes some grid says collide.
    pub colliding: LaneMask,
}

impl GridVerdicts {
    /// Every grid's verdicts on `q`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn of<L: CheckLanes>(grids: &[PairGrid<'_>], q: &[L]) -> Self {
        let mut verdicts = GridVerdicts { test: [LaneMask::NONE; MAX_GRIDS], colliding: LaneMask::NONE };
        for (slot, grid) in verdicts.test.iter_mut().zip(grids) {
            let (colliding, test) = grid.lanes(q);
            verdicts.colliding = verdicts.colliding | colliding;
            *slot = test;
        }
        verdicts
    }

    /// The lanes on which pair `pair` must be tested: those its grid leaves to the tests, or
    /// every lane if no grid covers it.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn tested(&self, grids: &[PairGrid<'_>], pair: usize) -> LaneMask {
        grids
            .iter()
            .zip(&self.test)
            .find(|(grid, _)| grid.pairs.contains(&pair))
            .map_or(LaneMask::from_bits(u32::MAX), |(_, test)| *test)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::F64x4;

    /// Two joints (q[1] and q[2]), two cells each over [0, 2): (0, 0) free, (0, 1) colliding,
    /// (1, 0) to test, (1, 1) free.
    const GRID: PairGrid<'static> = PairGrid {
        dofs: [1, 2],
        lower: [0.0, 0.0],
        scale: [1.0, 1.0],
        cells: [2, 2],
        states: &[0b01_00_10_01],
        pairs: &[3],
    };

    #[test]
    fn each_lane_gets_its_cells_verdict() {
        let q = [F64x4::splat(9.0), F64x4::new([0.5, 0.5, 1.5, 2.5]), F64x4::new([0.5, 1.5, 0.5, 0.5])];
        let (colliding, test) = GRID.lanes(&q);
        // Lane 0 free, lane 1 colliding, lane 2 to test, lane 3 outside the grid: to test.
        assert_eq!((colliding.bits(), test.bits()), (0b0010, 0b1100));
        for lane in 0..4 {
            let scalar = [q[0].lane(lane), q[1].lane(lane), q[2].lane(lane)];
            let (c, t) = GRID.lanes(&scalar);
            assert_eq!((c.lane(0), t.lane(0)), (colliding.lane(lane), test.lane(lane)), "lane {lane}");
        }
    }

    #[test]
    fn a_pair_outside_every_grid_is_tested_on_every_lane() {
        let q = [0.0, 0.5, 1.5];
        let verdicts = GridVerdicts::of(&[GRID], &q);
        assert!(verdicts.colliding.lane(0));
        assert_eq!(verdicts.tested(&[GRID], 3), LaneMask::NONE);
        assert_eq!(verdicts.tested(&[GRID], 2), LaneMask::from_bits(u32::MAX));
    }
}
