//! A `PointSource` that breaks its contract gets a typed `SourceError` naming the facet and the
//! point, not a panic (`ClosestToOrigin` used to `assert!` it).

use pqhull::geometry::Support;
use pqhull::hull::StrategyHooks;
use pqhull::predicates::Sign;
use pqhull::strategy::{DistanceResult, PointSource, SourceError};
use pqhull::{ClosestToOrigin, FacetId, Hull};

/// Three corners of [−1, 1]²: the fourth, (−1, 1), is what an honest source would add.
const INPUT: [[f64; 2]; 3] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]];

/// Returns `point` the first time it is asked for a point beyond a facet, nothing afterwards;
/// its support function returns `support` (if any) for every direction.
struct Fixed {
    point: Option<[f64; 2]>,
    support: Option<[f64; 2]>,
}

impl Fixed {
    fn beyond(point: [f64; 2]) -> Self {
        Fixed {
            point: Some(point),
            support: None,
        }
    }
}

impl PointSource<2> for Fixed {
    fn beyond(&mut self, _: &Hull<2>, _: FacetId) -> Option<[f64; 2]> {
        self.point.take()
    }
}

impl Support<2> for Fixed {
    fn support_point(&mut self, _: &[f64; 2]) -> Option<[f64; 2]> {
        self.support
    }
}

type Outcome = Result<DistanceResult<2>, SourceError<2>>;

fn run(source: Fixed, query: [f64; 2]) -> (Outcome, Hull<2>) {
    let (hull, result) =
        Hull::try_with_strategy(&INPUT, ClosestToOrigin::with_source(query, source)).unwrap();
    (result, hull)
}

#[test]
fn a_point_not_beyond_the_facet_is_an_error() {
    // An input vertex lies on (or beneath) every facet: never strictly beyond.
    for (point, sides) in [
        ([1.0, 1.0], &[Sign::Zero][..]),
        ([0.5, -0.5], &[Sign::Negative, Sign::Zero][..]),
    ] {
        let (result, hull) = run(Fixed::beyond(point), [0.5, 0.0]);
        let error = result.expect_err("a point not beyond must be an error");
        let SourceError::NotBeyond {
            facet,
            facet_vertices,
            point: returned,
            side,
        } = error.clone()
        else {
            panic!("wrong error: {error:?}");
        };
        assert_eq!(returned, point);
        assert!(sides.contains(&side), "{error}");
        assert_eq!(facet_vertices, hull.facet(facet).vertices());
        assert_eq!(hull.side_of(facet, &point), side);
        let message = error.to_string();
        assert!(
            message.contains("not strictly beyond")
                && message.contains(&format!("facet {}", facet.index()))
                && message.contains(&format!("{point:?}")),
            "{message}"
        );
        // The hull is left valid, without the point.
        hull.check().unwrap();
        assert_eq!(hull.point_count(), 3);
    }
}

#[test]
fn a_point_out_of_range_is_an_error() {
    for point in [[-1.0, 1e10], [f64::NAN, 0.0], [f64::INFINITY, 1.0]] {
        let (result, hull) = run(Fixed::beyond(point), [0.5, 0.0]);
        let error = result.expect_err("a point out of range must be an error");
        match &error {
            SourceError::OutOfRange {
                facet,
                facet_vertices,
                point: returned,
                bound,
            } => {
                assert_eq!(*facet_vertices, hull.facet(*facet).vertices());
                assert_eq!(format!("{returned:?}"), format!("{point:?}"));
                assert_eq!(*bound, hull.coordinate_bound());
            }
            other => panic!("wrong error: {other:?}"),
        }
        assert!(error.to_string().contains("coordinate range"), "{error}");
        hull.check().unwrap();
    }
}

#[test]
fn a_support_point_out_of_range_is_an_error() {
    // The query is outside; `beyond` finds nothing, but the support point along the outside
    // certificate's direction is beyond it — and out of range.
    let source = Fixed {
        point: None,
        support: Some([1e10, 1e10]),
    };
    let (result, _) = run(source, [3.0, 3.0]);
    match result {
        Err(SourceError::SupportOutOfRange { point, .. }) => assert_eq!(point, [1e10, 1e10]),
        other => panic!("wrong result: {other:?}"),
    }
}

#[test]
fn an_honest_source_still_gets_its_answer() {
    struct Corners;
    impl PointSource<2> for Corners {
        fn beyond(&mut self, hull: &Hull<2>, id: FacetId) -> Option<[f64; 2]> {
            let n = hull.facet(id).normal();
            let corner = [n[0].signum(), n[1].signum()];
            (hull.side_of(id, &corner) == Sign::Positive).then_some(corner)
        }
    }
    impl Support<2> for Corners {
        fn support_point(&mut self, d: &[f64; 2]) -> Option<[f64; 2]> {
            Some([d[0].signum(), d[1].signum()])
        }
    }
    let (_, result) =
        Hull::try_with_strategy(&INPUT, ClosestToOrigin::with_source([0.5, 0.0], Corners)).unwrap();
    assert!((result.unwrap().signed_distance - 0.5).abs() < 1e-12);
    let (_, outside) =
        Hull::try_with_strategy(&INPUT, ClosestToOrigin::with_source([-3.0, 3.0], Corners))
            .unwrap();
    assert_eq!(outside.unwrap().nearest_point, [-1.0, 1.0]);
}
