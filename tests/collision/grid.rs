//! The self-collision grids (the model's `pair_grids`) against the reference: a configuration in
//! a cell the grid marks free has every sphere pair of the grid's pairs apart, and one in a cell
//! marked colliding has one overlapping, by the reference's own distances (its link poses,
//! nalgebra), on configurations within the limits and beyond them, for every collision robot.
//! And the generated checks decide the configurations of such cells without testing the pairs:
//! the answer is the grid's even where it is the only thing that could give it.

use kinematics::model::collision::{CellState, pair_grids};
use kinematics::{Configurations, ReferenceFk};

use super::spheres_and_pairs;

/// Each grid of the robot of `reference` (its spheres at `cover`, its pairs less `srdf`'s)
/// against the reference on `samples` configurations drawn uniformly within the limits, then on
/// as many of the agreement stream (special angles, values beyond the limits). Returns per grid
/// the configurations within the limits found free, colliding and left to the tests.
fn grids_hold(reference: &ReferenceFk, cover: Option<f64>, srdf: Option<&str>, samples: usize) -> Vec<[usize; 3]> {
    let tree = reference.tree();
    let (spheres, pairs) = spheres_and_pairs(tree, cover, srdf);
    let grids = pair_grids(tree, &spheres, &pairs);
    assert!(!grids.is_empty(), "{}: no grid", tree.name());
    let mut seen = vec![[0usize; 3]; grids.len()];
    let mut beyond = vec![[0usize; 3]; grids.len()];
    let within = Configurations::new(tree).uniform().take(samples).map(|q| (q, true));
    let stream = Configurations::new(tree).take(samples).map(|q| (q, false));
    for (q, uniform) in within.chain(stream) {
        let seen = if uniform { &mut seen } else { &mut beyond };
        for (grid, seen) in grids.iter().zip(seen.iter_mut()) {
            let state = grid.state(&q);
            if state == CellState::Test {
                seen[2] += 1;
                continue;
            }
            let d = reference.self_distance(&q, &spheres, &grid.pairs).unwrap();
            match state {
                CellState::Free => {
                    assert!(d > 0.0, "{}: a free cell at {q:?}, distance {d:e}", tree.name());
                    seen[0] += 1;
                }
                _ => {
                    assert!(d < 0.0, "{}: a colliding cell at {q:?}, distance {d:e}", tree.name());
                    seen[1] += 1;
                }
            }
        }
    }
    eprintln!("{}: free, colliding, to test per grid: {seen:?} within the limits, {beyond:?} beyond", tree.name());
    seen
}

#[test]
fn panda_grid_cells_hold_against_the_reference() {
    let seen = grids_hold(&super::PandaSrdf::reference().unwrap(), None, Some("robots/panda.srdf"), 3000);
    // One grid (panda_link5 against the links beyond joints 6 and 7), both verdicts decided, and
    // all but a few configurations within the limits decided by it.
    assert_eq!(seen.len(), 1);
    let [free, colliding, test] = seen[0];
    assert!(free > 0 && colliding > 0, "{seen:?}");
    assert!(test * 20 < free + colliding, "{seen:?}: the grid leaves too much to the tests");
}

#[test]
fn ur5_grid_cells_hold_against_the_reference() {
    let seen = grids_hold(&super::Ur5Checked::reference().unwrap(), None, None, 2000);
    assert!(seen.iter().any(|[_, colliding, _]| *colliding > 0), "{seen:?}");
    assert!(seen.iter().all(|[free, _, _]| *free > 0), "{seen:?}");
}

#[test]
fn primitives_grid_cells_hold_against_the_reference() {
    grids_hold(&super::Ur5PrimitivesChecked::reference().unwrap(), Some(0.02), None, 2000);
}

/// Configurations whose only self-collision is decided by the Panda's grid (the hand folded onto
/// `panda_link5` at joint 6's lower end): `self_collides` says so in every form, and the
/// configurations the grid marks free next to them are free.
#[test]
fn the_generated_checks_take_the_grids_verdicts() {
    let reference = super::PandaSrdf::reference().unwrap();
    let tree = reference.tree();
    let (spheres, pairs) = spheres_and_pairs(tree, None, Some("robots/panda.srdf"));
    let grid = &pair_grids(tree, &spheres, &pairs)[0];
    let mut decided = [0usize; 2];
    for q in Configurations::new(tree).uniform().take(4000) {
        let q: [f64; 7] = q.try_into().unwrap();
        let state = grid.state(&q);
        let expected = match state {
            CellState::Test => continue,
            CellState::Colliding => true,
            CellState::Free => {
                // Free of the grid's pairs; the others decide.
                let others: Vec<_> = pairs.iter().filter(|p| !grid.pairs.contains(p)).copied().collect();
                reference.self_distance(&q, &spheres, &others).unwrap() < 0.0
            }
        };
        decided[usize::from(state == CellState::Colliding)] += 1;
        assert_eq!(super::PandaSrdf::self_collides(&q), expected, "{q:?} in a {state:?} cell");
        let q32 = q.map(|v| v as f32);
        if state == CellState::Colliding {
            assert!(super::PandaSrdf::self_collides_f32(&q32), "{q:?} in f32");
        }
    }
    assert!(decided[0] > 0 && decided[1] > 0, "{decided:?}");
}

/// The compiler writes at most as many grids as the checks read: a grid beyond the core's count
/// would only leave its pairs to the tests, so the two counts are one.
#[test]
fn the_compiler_writes_no_more_grids_than_the_checks_read() {
    assert_eq!(kinematics::collision::MAX_GRIDS, kinematics::model::collision::grid::MAX_GRIDS);
}
