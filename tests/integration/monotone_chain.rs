//! Andrew's monotone chain on `robust::orient2d` (Shewchuk's exact orientation, not the
//! engine's): the reference 2-D hull of the integration tests that need one.

/// The hull's vertices by Andrew's monotone chain on `robust::orient2d` (Shewchuk's exact
/// orientation, not the engine's), strictly convex turns only (a point on an edge is no
/// vertex), as indices of `points` (one per distinct vertex: the first in sorted order).
pub fn monotone_chain(points: &[[f64; 2]]) -> Vec<usize> {
    let mut sorted: Vec<usize> = (0..points.len()).collect();
    sorted.sort_by(|&a, &b| points[a].partial_cmp(&points[b]).unwrap());
    sorted.dedup_by(|a, b| points[*a] == points[*b]);
    let coord = |i: usize| robust::Coord {
        x: points[i][0],
        y: points[i][1],
    };
    let mut chain: Vec<usize> = Vec::new();
    for pass in 0..2 {
        let start = chain.len();
        let walk = |i: usize, chain: &mut Vec<usize>| {
            while chain.len() >= start + 2
                && robust::orient2d(
                    coord(chain[chain.len() - 2]),
                    coord(chain[chain.len() - 1]),
                    coord(i),
                ) <= 0.0
            {
                chain.pop();
            }
            chain.push(i);
        };
        if pass == 0 {
            sorted.iter().for_each(|&i| walk(i, &mut chain));
        } else {
            sorted.iter().rev().for_each(|&i| walk(i, &mut chain));
        }
        chain.pop(); // the other pass's first point
    }
    chain
}
