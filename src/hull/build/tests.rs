use crate::geometry::Rng;
use crate::{ClosestToOrigin, FarthestPoint, Hull};

/// Random points in [−1, 1]^6, and the cross-polytope's twelve vertices ±e_i after them.
fn points(rng: &mut Rng) -> Vec<[f64; 6]> {
    let mut points: Vec<[f64; 6]> = (0..40)
        .map(|_| std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0)))
        .collect();
    for i in 0..12 {
        let mut e = [0.0; 6];
        e[i / 2] = if i % 2 == 0 { 1.0 } else { -1.0 };
        points.push(e);
    }
    points
}

#[test]
fn colliding_ridge_keys_are_caught_and_the_cone_linked_right() {
    let mut rng = Rng::new(5);
    for _ in 0..10 {
        let p = points(&mut rng);
        let mut plain = Hull::empty();
        plain
            .rebuild_with_strategy(&p, FarthestPoint::new())
            .unwrap();
        let mut colliding = Hull::empty();
        colliding.scratch.colliding_shares = true;
        colliding
            .rebuild_with_strategy(&p, FarthestPoint::new())
            .unwrap();
        assert!(
            colliding.scratch.colliding_shares,
            "kept across the rebuild"
        );
        assert!(
            colliding.scratch.confirming_passes > 0,
            "the collisions were caught"
        );
        assert_eq!(plain.scratch.confirming_passes, 0);
        colliding.check().unwrap();
        assert_eq!(colliding.vertex_indices(), plain.vertex_indices());
        assert_eq!(colliding.facet_count(), plain.facet_count());
        assert_eq!(
            colliding.stats().facets_created,
            plain.stats().facets_created
        );
    }
}

#[test]
fn a_chosen_start_gives_the_same_hull_and_a_bad_one_is_ignored() {
    let mut rng = Rng::new(3);
    let mut other_work = 0;
    for _ in 0..20 {
        let p = points(&mut rng);
        let mut greedy = Hull::empty();
        greedy
            .rebuild_with_strategy(&p, FarthestPoint::new())
            .unwrap();
        let nearest = Hull::empty()
            .rebuild_with_strategy(&p, ClosestToOrigin::new())
            .unwrap();
        // A simplex around the origin's side (the six +e_i and −e_1) and two bad ones (a
        // repeated index, an index out of range).
        let around: Vec<usize> = (0..6).map(|i| 40 + 2 * i).chain([41]).collect();
        let repeated = [0, 0, 1, 2, 3, 4, 5];
        let out_of_range = [0, 1, 2, 3, 4, 5, p.len()];
        for start in [&around[..], &repeated[..], &out_of_range[..]] {
            let mut hull = Hull::empty();
            hull.start_next_build_from(start);
            hull.rebuild_with_strategy(&p, FarthestPoint::new())
                .unwrap();
            hull.check().unwrap();
            assert_eq!(hull.vertex_indices(), greedy.vertex_indices());
            assert_eq!(hull.facet_count(), greedy.facet_count());
            // The partial strategy finds the same nearest facet from any start.
            let mut partial = Hull::empty();
            partial.start_next_build_from(start);
            let r = partial
                .rebuild_with_strategy(&p, ClosestToOrigin::new())
                .unwrap();
            partial.check().unwrap();
            // The same facet; its distance computed from its vertices in another order.
            let sorted = |mut v: [usize; 6]| {
                v.sort_unstable();
                v
            };
            assert_eq!(
                sorted(r.closest_facet_vertices),
                sorted(nearest.closest_facet_vertices)
            );
            let (a, b) = (r.signed_distance, nearest.signed_distance);
            assert!((a - b).abs() <= 4.0 * f64::EPSILON * b.abs(), "{a} vs {b}");
            // The chosen start is used: the search does other work from it.
            if start == &around[..] && r.stats.facets_created != nearest.stats.facets_created {
                other_work += 1;
            }
        }
        // The start is for the next build only.
        let mut hull = Hull::empty();
        hull.start_next_build_from(&around);
        hull.rebuild_with_strategy(&p, FarthestPoint::new())
            .unwrap();
        assert!(hull.start.is_none());
    }
    assert!(other_work > 0);
}

#[test]
fn the_integer_key_orders_as_total_cmp() {
    let values = [
        f64::NEG_INFINITY,
        f64::MIN,
        -1.0,
        -f64::MIN_POSITIVE,
        -5e-324,
        -0.0,
        0.0,
        5e-324,
        f64::MIN_POSITIVE,
        1.0,
        1.0 + f64::EPSILON,
        f64::MAX,
        f64::INFINITY,
    ];
    for &a in &values {
        for &b in &values {
            assert_eq!(
                super::total_order_key(a).cmp(&super::total_order_key(b)),
                a.total_cmp(&b),
                "{a:e} against {b:e}"
            );
        }
    }
}

/// The one-pass extremes pick the indices that a `min_by` and a `max_by` per axis under
/// `total_cmp` pick (a brute force written here), ties and signed zeros included.
#[test]
fn the_axis_extremes_are_those_of_min_by_and_max_by() {
    fn reference<const D: usize>(points: &[[f64; D]]) -> Vec<usize> {
        let mut extremes = Vec::new();
        for axis in 0..D {
            let by =
                |a: &(usize, &[f64; D]), b: &(usize, &[f64; D])| a.1[axis].total_cmp(&b.1[axis]);
            extremes.push(points.iter().enumerate().min_by(by).unwrap().0);
            extremes.push(points.iter().enumerate().max_by(by).unwrap().0);
        }
        extremes
    }
    let mut rng = Rng::new(11);
    // Few distinct values (many ties), zeros of both signs.
    let grid = [-1.0, -0.0, 0.0, 0.5, 1.0];
    for n in [1, 2, 7, 60] {
        let points: Vec<[f64; 4]> = (0..n)
            .map(|_| std::array::from_fn(|_| grid[(rng.next_u64() % 5) as usize]))
            .collect();
        assert_eq!(super::axis_extremes(&points)[..8], reference(&points)[..]);
        let points: Vec<[f64; 3]> = (0..n)
            .map(|_| std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0)))
            .collect();
        assert_eq!(super::axis_extremes(&points)[..6], reference(&points)[..]);
    }
}

/// The extent on the coordinates' bits against the comparisons it replaced (written here):
/// finiteness, the largest magnitude and the smallest non-zero one, on inputs whose length is
/// not a multiple of the lanes, with signed zeros, subnormals, infinities and NaNs.
#[test]
fn the_extent_on_bits_is_that_of_the_comparisons() {
    fn brute<const D: usize>(points: &[[f64; D]]) -> (bool, f64, f64) {
        let mut finite = true;
        let (mut high, mut low) = (0.0f64, f64::INFINITY);
        for &x in points.iter().flatten() {
            finite &= x.is_finite();
            high = high.max(x.abs());
            if x != 0.0 {
                low = low.min(x.abs());
            }
        }
        (finite, high, low)
    }
    let special = [
        0.0,
        -0.0,
        5e-324,
        -2.5e-310,
        f64::MIN_POSITIVE,
        -1.5,
        3.0,
        f64::MAX,
        -f64::MAX,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    let mut rng = Rng::new(5);
    for n in [1, 2, 3, 4, 5, 9, 17, 40] {
        for _ in 0..200 {
            let points: Vec<[f64; 3]> = (0..n)
                .map(|_| {
                    std::array::from_fn(|_| match rng.index(3) {
                        0 => special[rng.index(special.len())],
                        1 => 0.0,
                        _ => (rng.index(2001) as f64 - 1000.0) * 1e-3,
                    })
                })
                .collect();
            let extent = super::Extent::of(&points);
            let (finite, high, low) = brute(&points);
            assert_eq!(extent.finite, finite, "{points:?}");
            if finite {
                assert_eq!(extent.max_abs.to_bits(), high.to_bits(), "{points:?}");
                assert_eq!(extent.min_abs.to_bits(), low.to_bits(), "{points:?}");
            }
        }
    }
    let zeros = super::Extent::of(&[[0.0, -0.0]; 3]);
    assert!(zeros.finite && zeros.max_abs == 0.0 && zeros.min_abs == f64::INFINITY);
}
