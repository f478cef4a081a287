"""pqhull.ConvexHull against scipy.spatial.ConvexHull (Qhull), an independent reference."""

import numpy as np
import pytest
import scipy.spatial

import pqhull


def seeded_sets():
    rng = np.random.default_rng(7)
    for d in range(2, 7):
        for n in (d + 1, 30, 200):
            yield d, rng.standard_normal((n, d))
            yield d, rng.uniform(-1.0, 1.0, (n, d)) * 1e3


@pytest.mark.parametrize("d,points", list(seeded_sets()))
def test_equals_scipy(d, points):
    ours = pqhull.ConvexHull(points)
    ref = scipy.spatial.ConvexHull(points)
    assert set(ours.vertices.tolist()) == set(ref.vertices.tolist())
    assert ours.volume == pytest.approx(ref.volume, rel=1e-9)
    assert ours.simplices.shape == ref.simplices.shape == (len(ref.simplices), d)
    assert ours.equations.shape == (len(ref.simplices), d + 1)
    np.testing.assert_array_equal(ours.points, points)
    # Random points in general position: every facet is a simplex, matched by its vertex set.
    ref_eq = {tuple(sorted(s)): e for s, e in zip(ref.simplices.tolist(), ref.equations)}
    for simplex, equation, neighbors in zip(ours.simplices, ours.equations, ours.neighbors):
        key = tuple(sorted(simplex.tolist()))
        assert key in ref_eq
        np.testing.assert_allclose(equation, ref_eq[key], rtol=1e-9, atol=1e-9 * abs(points).max())
        # Neighbour j shares every vertex but vertex j (scipy's convention).
        for j, n in enumerate(neighbors):
            shared = set(simplex.tolist()) - {int(simplex[j])}
            assert shared <= set(ours.simplices[n].tolist())
    # Inside means normal . x + offset <= 0, as in scipy.
    centroid = points.mean(axis=0)
    assert (ours.equations[:, :-1] @ centroid + ours.equations[:, -1] < 0).all()


def test_two_d_vertices_are_counter_clockwise():
    points = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0], [1.0, 0.5]])
    v = pqhull.ConvexHull(points).vertices
    p = points[v]
    area = 0.5 * np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])
    assert area == pytest.approx(2.0)
    assert sorted(v.tolist()) == [0, 1, 2, 3]


def test_flat_input_is_a_clear_error_where_scipy_raises():
    flat = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.3, 0.2, 0.0]])
    with pytest.raises(scipy.spatial.QhullError):
        scipy.spatial.ConvexHull(flat)
    with pytest.raises(pqhull.HullError, match="rank|dimension|flat|affin") as e:
        pqhull.ConvexHull(flat)
    assert isinstance(e.value, pqhull.Error) and isinstance(e.value, ValueError)


@pytest.mark.parametrize(
    "points,match",
    [
        (np.zeros((3, 9)), "2 to 8 dimensions"),
        (np.array([[0.0, np.nan], [1.0, 0.0], [0.0, 1.0]]), "NaN|finite"),
        (np.zeros(5), "2-dimensional"),
        ([["a", "b"]], "not an array of numbers"),
    ],
)
def test_bad_input_raises_the_typed_error(points, match):
    with pytest.raises(pqhull.Error, match=match):
        pqhull.ConvexHull(points)


def test_distance_to_boundary_is_the_full_hulls():
    rng = np.random.default_rng(3)
    for d in range(2, 7):
        points = rng.standard_normal((300, d))
        ref = scipy.spatial.ConvexHull(points)
        for query in (np.zeros(d), rng.standard_normal(d) * 0.3):
            got = pqhull.distance_to_boundary(points, query)
            # Inside: the distance to the nearest facet plane (scipy's equations, independent).
            expected = -(ref.equations[:, :-1] @ query + ref.equations[:, -1]).max()
            assert got.signed_distance == pytest.approx(expected, rel=1e-9, abs=1e-12)
            assert got.points_processed <= len(points)
    with pytest.raises(pqhull.InputError, match="query has 3 coordinates"):
        pqhull.distance_to_boundary(rng.standard_normal((10, 2)), [0.0, 0.0, 0.0])


def test_many_queries_share_one_partial_hull():
    """An (m, d) array of queries: every answer is the one a query alone gets (itself checked
    against the full hull above), the sign against scipy's facets."""
    rng = np.random.default_rng(11)
    for d in (2, 3, 5):
        points = rng.standard_normal((400, d))
        queries = rng.standard_normal((50, d)) * 1.5
        many = pqhull.distance_to_boundary(points, queries)
        assert isinstance(many, pqhull.Distances) and len(many) == 50
        assert many.signed_distance.shape == (50,)
        assert many.facets.shape == (50, d) and many.facets.dtype == np.intc
        assert many.nearest_points.shape == (50, d)
        equations = scipy.spatial.ConvexHull(points).equations
        for i, q in enumerate(queries):
            alone = pqhull.distance_to_boundary(points, q)
            assert abs(many.signed_distance[i] - alone.signed_distance) <= 1e-12
            outside = (equations[:, :-1] @ q + equations[:, -1]).max()
            if abs(outside) > 1e-9:
                assert (many.signed_distance[i] < 0) == (outside > 0)
    with pytest.raises(pqhull.InputError):
        pqhull.distance_to_boundary(rng.standard_normal((10, 2)), np.zeros((3, 3)))
    with pytest.raises(pqhull.InputError):
        pqhull.distance_to_boundary(rng.standard_normal((10, 2)), [[0.0, np.nan]])
