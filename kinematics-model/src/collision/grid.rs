//! Self-collision decided ahead of time: where the links of a checked pair are moved apart by one
//! or two revolute joints only, whether they touch depends on those joints' values alone, so it
//! can be worked out before run time over a grid of them. A [`PairGrid`] covers every checked pair
//! with the same such joints (VAMP's Panda: `panda_link5` against `panda_link7`, `panda_hand` and
//! the fingers, over `panda_joint6` and `panda_joint7`) and marks each cell **free** (no sphere
//! pair of those pairs touches anywhere in the cell), **colliding** (one sphere pair overlaps
//! everywhere in it) or **to test** (the check tests the pairs as it would without the grid).
//!
//! A cell is classified from the sphere distances at its centre and a bound on how far they move
//! within it, so the classification holds for every configuration in the cell, not only for the
//! ones sampled: a joint turning by `h` moves a point at most `h` times the point's distance from
//! the joint's origin (the axis passes through it); where the other joint lies between, that
//! distance is bounded by the distance between the two joints' origins plus the point's distance
//! from the nearer origin, which no joint changes. Each cell is widened by a thousandth of its
//! width before it is classified, so a value that rounding puts in a neighbouring cell at run
//! time is still covered; a value outside the joint's limits is in no cell and its lanes are
//! tested.
//!
//! Only revolute joints with limits that take their own entry of `q` make a grid (a continuous,
//! prismatic or mimic joint between two links leaves their pairs to the tests). The check reads
//! the grid as 2 bits a cell ([`CellState`]); the pairs a grid decides are tested only on the
//! configurations whose cells say "to test", and the others are decided by the grid.

use std::collections::BTreeMap;

use super::LinkSphere;
use super::fixed::{distance, paths};
use crate::JointKind;
use crate::joint::JointMotion;
use crate::tree::{JointId, KinematicTree, LinkId};

/// How many cells a grid over two joints has along each, at most.
pub const CELLS_2D: usize = 256;
/// How many cells a grid over one joint has, at most.
pub const CELLS_1D: usize = 1024;

/// The most sphere pairs a grid's cells may ask for, all cells together (each cell the product of
/// the numbers of spheres of each pair's links): a grid halves its cells along each joint until
/// it keeps to this, and where 16 cells a joint would not, the pairs get no grid. It bounds the
/// work at compile time; the regions classified whole leave far less (VAMP's Panda: 256 x 256
/// cells of 324 sphere pairs, 21 million at most; 19 ms in fact, optimised).
pub const WORK: usize = 25_000_000;

/// The most grids a robot gets (the core's checks read as many): those of the most sphere pairs.
pub const MAX_GRIDS: usize = 8;

/// The fraction of a cell's width each cell is widened by on each side before it is classified.
const WIDENING: f64 = 1e-3;

/// How far (m) a gap must clear zero for a cell to be decided: far above the rounding of the
/// distances computed here, far below any sphere's size.
const MARGIN: f64 = 1e-9;

/// What a cell says of every configuration in it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CellState {
    /// The pairs must be tested (code 0).
    Test,
    /// No sphere pair of the grid's pairs touches (code 1).
    Free,
    /// Some sphere pair of the grid's pairs overlaps (code 2).
    Colliding,
}

impl CellState {
    /// The 2-bit code the check reads.
    pub fn code(self) -> u8 {
        match self {
            CellState::Test => 0,
            CellState::Free => 1,
            CellState::Colliding => 2,
        }
    }
}

/// A grid over the values of the one or two revolute joints that move the links of some checked
/// pairs relative to each other.
#[derive(Debug, Clone, PartialEq)]
pub struct PairGrid {
    /// The joints (one or two), in `q`'s order.
    pub joints: Vec<JointId>,
    /// Each joint's entry of `q` (the second repeats the first for one joint).
    pub dofs: [usize; 2],
    /// Where cell 0 starts along each joint (its lower limit).
    pub lower: [f64; 2],
    /// Each cell's width along each joint (radians).
    pub width: [f64; 2],
    /// How many cells along each joint (1 along the second for one joint).
    pub cells: [usize; 2],
    /// The pairs the grid decides, in the order given.
    pub pairs: Vec<(LinkId, LinkId)>,
    /// Cell `(i, j)`'s state is `states[i * cells[1] + j]`.
    pub states: Vec<CellState>,
}

impl PairGrid {
    /// The cells' states packed four to a byte (cell `k` in bits `2 (k % 4)` of byte `k / 4`), as
    /// the check reads them.
    pub fn packed(&self) -> Vec<u8> {
        let mut out = vec![0u8; self.states.len().div_ceil(4)];
        for (k, state) in self.states.iter().enumerate() {
            out[k / 4] |= state.code() << (2 * (k % 4));
        }
        out
    }

    /// Cells per unit of each joint's value, as the check multiplies by: the inverse of each
    /// width, and 0 along the second for one joint (every value is then in its one cell).
    pub fn scale(&self) -> [f64; 2] {
        [0, 1].map(|d| if self.joints.len() == 1 && d == 1 { 0.0 } else { 1.0 / self.width[d] })
    }

    /// How many cells are in each state: free, colliding, to test.
    pub fn counts(&self) -> (usize, usize, usize) {
        let count = |s: CellState| self.states.iter().filter(|&&x| x == s).count();
        (count(CellState::Free), count(CellState::Colliding), count(CellState::Test))
    }

    /// The state of the cell `q` falls in (`Test` outside the grid).
    pub fn state(&self, q: &[f64]) -> CellState {
        let index = |d: usize| {
            let x = (q[self.dofs[d]] - self.lower[d]) / self.width[d];
            (x >= 0.0 && x < self.cells[d] as f64).then_some(x as usize)
        };
        match (index(0), if self.joints.len() == 2 { index(1) } else { Some(0) }) {
            (Some(i), Some(j)) => self.states[i * self.cells[1] + j],
            _ => CellState::Test,
        }
    }
}

/// One side of a pair: its link's joints up to the pair's common ancestor (from the link
/// upwards), a sphere holding its spheres, and the spheres.
struct Side {
    /// The transform from the link's frame to the ancestor's, from the link upwards: fixed parts
    /// (folded together) and the moving joints' turns.
    pieces: Vec<Piece>,
    /// A sphere holding every sphere of the side.
    bound: Carried,
    /// The spheres.
    spheres: Vec<Carried>,
}

/// A part of the transform from a side's link up to the common ancestor.
enum Piece {
    /// A fixed transform: three rows of a rotation and a translation.
    Fixed([[f64; 4]; 3]),
    /// A moving joint's turn about its unit axis (in the frame below it).
    Turn(JointId, [f64; 3]),
}

/// A sphere of a side, with what bounds its motion.
struct Carried {
    /// The centre in its link's frame.
    center: [f64; 3],
    /// The radius.
    radius: f64,
    /// For each moving joint on `up`: a bound on the centre's distance from the joint's origin,
    /// whatever the joints' values.
    reach: Vec<(JointId, f64)>,
}

/// The grids of the checked `pairs` (each `(a, b)` with `a` first in tree order) of `spheres`:
/// one per set of one or two revolute joints with limits that alone move some pairs' links
/// relative to each other, over those pairs, in as many cells as [`WORK`] allows; kept where
/// they decide at least half their cells, at most [`MAX_GRIDS`] of them (those of the most
/// sphere pairs), in that order. Pairs moved by other joints get none.
pub fn pair_grids(tree: &KinematicTree, spheres: &[LinkSphere], pairs: &[(LinkId, LinkId)]) -> Vec<PairGrid> {
    let mut by_joints: BTreeMap<Vec<JointId>, Vec<(LinkId, LinkId)>> = BTreeMap::new();
    for &(a, b) in pairs {
        let (up_a, up_b) = paths(tree, a, b);
        let mut moving: Vec<JointId> =
            up_a.iter().chain(&up_b).copied().filter(|&j| tree.joint(j).kind != JointKind::Fixed).collect();
        moving.sort_by_key(|&j| dof(tree, j));
        let gridded = (1..=2).contains(&moving.len()) && moving.iter().all(|&j| dof(tree, j).is_some());
        if gridded {
            by_joints.entry(moving).or_default().push((a, b));
        }
    }
    let count = |link: LinkId| spheres.iter().filter(|s| s.link == link).count();
    let mut grids: Vec<(usize, PairGrid)> = by_joints
        .into_iter()
        .filter_map(|(joints, pairs)| {
            let work: usize = pairs.iter().map(|&(a, b)| count(a) * count(b)).sum();
            let mut along = if joints.len() == 2 { CELLS_2D } else { CELLS_1D };
            let cells = |along: usize| if joints.len() == 2 { along * along } else { along };
            while along > 16 && cells(along).saturating_mul(work) > WORK {
                along /= 2;
            }
            (cells(along).saturating_mul(work) <= WORK).then(|| (work, grid(tree, spheres, joints, pairs, along)))
        })
        // A grid that leaves most cells to the tests costs a lookup and saves little.
        .filter(|(_, grid)| 2 * grid.counts().2 < grid.states.len())
        .collect();
    // The most sphere pairs first (stable: ties in the joints' order).
    grids.sort_by_key(|g| core::cmp::Reverse(g.0));
    grids.truncate(MAX_GRIDS);
    grids.into_iter().map(|(_, grid)| grid).collect()
}

/// Joint `j`'s entry of `q`, if it is a revolute joint with limits taking its own entry.
fn dof(tree: &KinematicTree, j: JointId) -> Option<usize> {
    let joint = tree.joint(j);
    match (joint.kind, joint.limits, joint.motion) {
        (JointKind::Revolute, Some(limits), JointMotion::Dof(i)) if limits.upper > limits.lower => Some(i),
        _ => None,
    }
}

/// The grid over `joints` (sorted by their entries of `q`) deciding `pairs`, with `along` cells
/// along each joint.
fn grid(
    tree: &KinematicTree,
    spheres: &[LinkSphere],
    joints: Vec<JointId>,
    pairs: Vec<(LinkId, LinkId)>,
    along: usize,
) -> PairGrid {
    let limits = |d: usize| {
        #[allow(clippy::expect_used, reason = "invariant: a grid's joints have limits (`dof`)")]
        let l = tree.joint(joints[d.min(joints.len() - 1)]).limits.expect("a gridded joint has limits");
        l
    };
    let cells = if joints.len() == 2 { [along, along] } else { [along, 1] };
    let lower = [limits(0).lower, limits(1).lower];
    let width = [0, 1].map(|d| (limits(d).upper - limits(d).lower) / cells[d] as f64);
    #[allow(clippy::expect_used, reason = "invariant: a grid's joints take their own entries (`dof`)")]
    let dofs = [0, 1].map(|d| dof(tree, joints[d.min(joints.len() - 1)]).expect("a gridded joint has an entry"));
    let center = |s: &LinkSphere| s.sphere.center;
    // Each pair's two sides: the path up to the pair's common ancestor, a sphere holding the
    // side's spheres, and the spheres, each with its reach.
    let sides: Vec<[Side; 2]> = pairs
        .iter()
        .map(|&(a, b)| {
            let (up_a, up_b) = paths(tree, a, b);
            let side = |link: LinkId, up: Vec<JointId>| {
                let carried =
                    |center: [f64; 3], radius: f64| Carried { center, radius, reach: reach(tree, &up, center) };
                let own: Vec<Carried> =
                    spheres.iter().filter(|s| s.link == link).map(|s| carried(center(s), s.sphere.radius)).collect();
                let n = own.len().max(1) as f64;
                let middle = [0, 1, 2].map(|i| own.iter().map(|s| s.center[i]).sum::<f64>() / n);
                let radius = own.iter().map(|s| distance(s.center, middle) + s.radius).fold(0.0, f64::max);
                Side { bound: carried(middle, radius), spheres: own, pieces: pieces(tree, &up) }
            };
            [side(a, up_a), side(b, up_b)]
        })
        .collect();
    let mut states = vec![CellState::Test; cells[0] * cells[1]];
    // Regions of cells, each classified as a whole and split where that leaves it to the tests:
    // the state of a region holds for each of its cells, so only the cells along the border
    // between free and colliding are classified one by one.
    let mut regions = vec![([0, 0], cells)];
    while let Some((from, to)) = regions.pop() {
        let extent = [0, 1].map(|d| to[d] - from[d]);
        let middle = [0, 1].map(|d| lower[d] + (from[d] + to[d]) as f64 / 2.0 * width[d]);
        let half = [0, 1].map(|d| width[d] * (extent[d] as f64 / 2.0 + WIDENING));
        let state = classify(&joints, &sides, (middle, half), extent == [1, 1]);
        if state != CellState::Test || extent == [1, 1] {
            for i in from[0]..to[0] {
                states[i * cells[1] + from[1]..i * cells[1] + to[1]].fill(state);
            }
            continue;
        }
        let split = [0, 1].map(|d| from[d] + extent[d] / 2);
        let parts = |d: usize| {
            if extent[d] > 1 { vec![(from[d], split[d]), (split[d], to[d])] } else { vec![(from[d], to[d])] }
        };
        for &(a0, a1) in &parts(0) {
            for &(b0, b1) in &parts(1) {
                regions.push(([a0, b0], [a1, b1]));
            }
        }
    }
    PairGrid { joints, dofs, lower, width, cells, pairs, states }
}

/// What every sphere pair of `sides` does in the region of joint values within `half` of
/// `middle` (each side's spheres placed by its frame there; each gap moves by at most the
/// spheres' reaches times `half`). Unless `whole`, the first pair left to the tests ends the
/// search (a region that is split is searched again in its parts).
fn classify(joints: &[JointId], sides: &[[Side; 2]], (middle, half): ([f64; 2], [f64; 2]), whole: bool) -> CellState {
    let turns = middle.map(f64::sin_cos);
    let turn = |j: JointId| if joints[0] == j { turns[0] } else { turns[1] };
    let slack =
        |s: &Carried| -> f64 { s.reach.iter().map(|&(j, r)| r * if joints[0] == j { half[0] } else { half[1] }).sum() };
    // The least a gap between two spheres can be in the region, and the most, from their centres
    // there and how far each moves (widened by `MARGIN` for the rounding of what is computed here).
    let gap = |(x, cx, sx): (&Carried, [f64; 3], f64), (y, cy, sy): (&Carried, [f64; 3], f64)| {
        let (gap, moves) = (distance(cx, cy) - x.radius - y.radius, sx + sy + MARGIN);
        (gap - moves, gap + moves)
    };
    let mut state = CellState::Free;
    for [a, b] in sides {
        let (frame_a, frame_b) = (frame(&a.pieces, &turn), frame(&b.pieces, &turn));
        let bound_a = (&a.bound, place(&frame_a, a.bound.center), slack(&a.bound));
        let bound_b = (&b.bound, place(&frame_b, b.bound.center), slack(&b.bound));
        if gap(bound_a, bound_b).0 > 0.0 {
            continue;
        }
        let placed_b: Vec<(&Carried, [f64; 3], f64)> =
            b.spheres.iter().map(|s| (s, place(&frame_b, s.center), slack(s))).collect();
        for sa in &a.spheres {
            let sa = (sa, place(&frame_a, sa.center), slack(sa));
            if gap(sa, bound_b).0 > 0.0 {
                continue;
            }
            for &sb in &placed_b {
                let (least, most) = gap(sa, sb);
                if most < 0.0 {
                    return CellState::Colliding;
                }
                if least <= 0.0 {
                    if !whole {
                        return CellState::Test;
                    }
                    state = CellState::Test;
                }
            }
        }
    }
    state
}

/// The pieces of the transform from the frame below the joints `up` (from a link upwards) to the
/// frame above them: each joint's fixed transforms (folded with their neighbours) and its turn.
fn pieces(tree: &KinematicTree, up: &[JointId]) -> Vec<Piece> {
    let mut out = Vec::new();
    let mut fixed = identity();
    for &j in up {
        let joint = tree.joint(j);
        fixed = compose(&affine(&joint.after_motion), &fixed);
        if joint.kind != JointKind::Fixed {
            out.push(Piece::Fixed(fixed));
            out.push(Piece::Turn(j, joint.axis));
            fixed = identity();
        }
        fixed = compose(&affine(&joint.origin), &fixed);
    }
    out.push(Piece::Fixed(fixed));
    out
}

/// The frame of a side's link in the common ancestor's, each turn by the angle whose sine and
/// cosine are `turn(joint)`.
fn frame(pieces: &[Piece], turn: &impl Fn(JointId) -> (f64, f64)) -> [[f64; 4]; 3] {
    pieces.iter().fold(identity(), |below, piece| match piece {
        Piece::Fixed(m) => compose(m, &below),
        Piece::Turn(j, axis) => compose(&rotation(*axis, turn(*j)), &below),
    })
}

/// The identity transform.
fn identity() -> [[f64; 4]; 3] {
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]
}

/// A fixed transform's rows: its images of the axes and of the origin, in floating point.
fn affine(t: &crate::transform::FixedTransform) -> [[f64; 4]; 3] {
    let origin = t.apply([0.0; 3]);
    let axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(|e| t.apply(e));
    [0, 1, 2].map(|i| [axes[0][i] - origin[i], axes[1][i] - origin[i], axes[2][i] - origin[i], origin[i]])
}

/// `a` after `b`.
fn compose(a: &[[f64; 4]; 3], b: &[[f64; 4]; 3]) -> [[f64; 4]; 3] {
    [0, 1, 2].map(|i| {
        let row = |k: usize| a[i][0] * b[0][k] + a[i][1] * b[1][k] + a[i][2] * b[2][k];
        [row(0), row(1), row(2), row(3) + a[i][3]]
    })
}

/// The turn about the unit `axis` by the angle whose sine and cosine are `(s, c)` (Rodrigues'
/// formula), as rows.
fn rotation(axis: [f64; 3], turn: (f64, f64)) -> [[f64; 4]; 3] {
    let columns = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(|e| rotate(axis, turn, e));
    [0, 1, 2].map(|i| [columns[0][i], columns[1][i], columns[2][i], 0.0])
}

/// The point `p` of a side's link placed by its `frame`.
fn place(frame: &[[f64; 4]; 3], p: [f64; 3]) -> [f64; 3] {
    frame.map(|r| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3])
}

/// For each moving joint on `up` (from the link upwards): a bound on the distance of the point
/// `p` (in the link's frame) from the joint's origin, whatever the joints' values: exact for the
/// first moving joint, and for each above it the distance from its origin to the one below's
/// plus the bound below.
fn reach(tree: &KinematicTree, up: &[JointId], p: [f64; 3]) -> Vec<(JointId, f64)> {
    let mut out = Vec::new();
    // The point, or once a moving joint is passed, that joint's origin, in the current frame;
    // and the bound on the point's distance from that origin.
    let (mut anchor, mut below) = (p, 0.0);
    for &j in up {
        let joint = tree.joint(j);
        let y = joint.after_motion.apply(anchor);
        if joint.kind != JointKind::Fixed {
            below += distance(y, [0.0; 3]);
            out.push((j, below));
            anchor = joint.origin.apply([0.0; 3]);
        } else {
            anchor = joint.origin.apply(y);
        }
    }
    out
}

/// `p` turned about the unit `axis` by the angle whose sine and cosine are `(s, c)` (Rodrigues'
/// formula).
fn rotate(axis: [f64; 3], (s, c): (f64, f64), p: [f64; 3]) -> [f64; 3] {
    let [x, y, z] = axis;
    let dot = x * p[0] + y * p[1] + z * p[2];
    let cross = [y * p[2] - z * p[1], z * p[0] - x * p[2], x * p[1] - y * p[0]];
    [0, 1, 2].map(|i| p[i] * c + cross[i] * s + axis[i] * dot * (1.0 - c))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::{Cover, Meshes, link_spheres};
    use crate::exactness::ExactAngles;
    use crate::source::{Source, SourceFormat};

    /// A base with a ball at (0.3, 0, 0) and an arm turning about z with a ball at (0.35, 0, 0.05):
    /// their distance is a function of the joint's angle alone (touching within about 0.45 rad
    /// of zero).
    const ARM: &str = r#"<robot name="arm">
      <link name="base"><collision><origin xyz="0.3 0 0"/><geometry><sphere radius="0.1"/></geometry></collision></link>
      <link name="arm"><collision><origin xyz="0.35 0 0.05"/><geometry><sphere radius="0.05"/></geometry></collision></link>
      <joint name="turn" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
        <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
    </robot>"#;

    /// The one-joint grid (the pair kept by hand: the default rule leaves adjacent bodies out)
    /// against the distance at sampled angles: free cells apart, colliding cells overlapping,
    /// both seen, and the cells left to the tests few.
    #[test]
    fn a_one_joint_grid_holds_at_every_sampled_angle() {
        let tree = Source::new(SourceFormat::Urdf, "arm.urdf", ARM).load(ExactAngles::default()).unwrap();
        let spheres = link_spheres(&tree, &Cover::default(), Meshes::Read).unwrap();
        let pair = (tree.link_id("base").unwrap(), tree.link_id("arm").unwrap());
        let grids = pair_grids(&tree, &spheres, &[pair]);
        assert_eq!(grids.len(), 1);
        let grid = &grids[0];
        assert_eq!((grid.cells, grid.dofs, grid.scale()[1]), ([CELLS_1D, 1], [0, 0], 0.0));
        let mut seen = [0usize; 3];
        for k in 0..=60_000 {
            let angle = -3.2 + 6.4 * k as f64 / 60_000.0;
            // The arm's ball at angle `angle` about z, 0.05 above the base's.
            let (s, c) = angle.sin_cos();
            let gap = distance([0.35 * c, 0.35 * s, 0.05], [0.3, 0.0, 0.0]) - 0.15;
            let state = grid.state(&[angle]);
            match state {
                CellState::Free => assert!(gap > 0.0, "free at {angle}: {gap}"),
                CellState::Colliding => assert!(gap < 0.0, "colliding at {angle}: {gap}"),
                // Beyond the limits every value is tested.
                CellState::Test => {}
            }
            if angle.abs() > 3.0 {
                assert_eq!(state, CellState::Test, "{angle} is beyond the limits");
                continue;
            }
            seen[state.code() as usize] += 1;
        }
        let [test, free, colliding] = seen;
        assert!(free > 0 && colliding > 0, "{seen:?}");
        assert!(test * 50 < free + colliding, "{seen:?}");
        // The packed codes say the same as the states.
        let packed = grid.packed();
        for (k, state) in grid.states.iter().enumerate() {
            assert_eq!((packed[k / 4] >> (2 * (k % 4))) & 3, state.code(), "cell {k}");
        }
    }

    /// A pair moved by a joint without limits (continuous) gets no grid.
    #[test]
    fn only_pairs_one_or_two_limited_joints_move_get_grids() {
        let continuous = ARM.replace(r#"type="revolute""#, r#"type="continuous""#);
        let tree = Source::new(SourceFormat::Urdf, "arm.urdf", continuous).load(ExactAngles::default()).unwrap();
        let spheres = link_spheres(&tree, &Cover::default(), Meshes::Read).unwrap();
        let pair = (tree.link_id("base").unwrap(), tree.link_id("arm").unwrap());
        assert!(pair_grids(&tree, &spheres, &[pair]).is_empty());
    }
}
