"""pqhull.ConvexHull as a drop-in for scipy.spatial.ConvexHull: each attribute and option
against scipy (Qhull) on random input in 2-D to 6-D, incremental hulls against a fresh scipy
hull of all the points, and the errors scipy raises for bad input."""

import itertools
import pickle

import numpy as np
import pytest
import scipy.spatial
from scipy.spatial import QhullError

import pqhull

DIMENSIONS = range(2, 7)


def random_sets():
    rng = np.random.default_rng(2027)
    for d in DIMENSIONS:
        for n in (d + 2, 40, 150):
            yield pytest.param(d, rng.standard_normal((n, d)), id=f"gauss-{d}d-{n}")
        yield pytest.param(d, rng.uniform(-1e3, 1e3, (60, d)), id=f"cube-{d}d")
        sphere = rng.standard_normal((60, d))
        yield pytest.param(d, sphere / np.linalg.norm(sphere, axis=1)[:, None], id=f"sphere-{d}d")


def facet_set(simplices, good=None):
    rows = simplices if good is None else simplices[good]
    return {tuple(sorted(s)) for s in rows.tolist()}


def assert_same_hull(ours, ref):
    """The same hull as scipy's (points in general position: the same simplices)."""
    assert set(ours.vertices.tolist()) == set(ref.vertices.tolist())
    assert facet_set(ours.simplices) == facet_set(ref.simplices)
    assert ours.volume == pytest.approx(ref.volume, rel=1e-12)
    assert ours.area == pytest.approx(ref.area, rel=1e-12)
    assert (ours.ndim, ours.npoints, ours.nsimplex) == (ref.ndim, ref.npoints, ref.nsimplex)
    np.testing.assert_array_equal(ours.points, ref.points)
    np.testing.assert_array_equal(ours.min_bound, ref.min_bound)
    np.testing.assert_array_equal(ours.max_bound, ref.max_bound)


@pytest.mark.parametrize("d,points", list(random_sets()))
def test_attributes_equal_scipys(d, points):
    ours = pqhull.ConvexHull(points)
    ref = scipy.spatial.ConvexHull(points)
    assert_same_hull(ours, ref)
    # scipy's layout: np.intc indices, shapes, vertices sorted beyond 2-D, no coplanar or good.
    for name in ("vertices", "simplices", "neighbors", "coplanar"):
        assert getattr(ours, name).dtype == getattr(ref, name).dtype == np.intc, name
    assert ours.simplices.shape == ours.neighbors.shape == (ref.nsimplex, d)
    assert ours.equations.shape == (ref.nsimplex, d + 1)
    assert ours.coplanar.shape == ref.coplanar.shape == (0, 3)
    assert ours.good is None and ref.good is None
    assert isinstance(ours.volume, float) and isinstance(ours.area, float)
    if d > 2:
        np.testing.assert_array_equal(ours.vertices, np.unique(ours.simplices))
    # Neighbour j of facet i shares all its vertices but vertex j.
    for i, (simplex, neighbors) in enumerate(zip(ours.simplices, ours.neighbors)):
        for j, n in enumerate(neighbors):
            assert set(simplex.tolist()) - {simplex[j]} <= set(ours.simplices[n].tolist())
            assert i in ours.neighbors[n]
    # The attributes are arrays made once: each access gives the same one, as scipy's do.
    assert ours.simplices is ours.simplices and ours.points is ours.points


@pytest.mark.parametrize("d", DIMENSIONS)
def test_two_d_vertices_counter_clockwise_and_facet_order(d):
    rng = np.random.default_rng(d)
    points = rng.standard_normal((50, d))
    hull = pqhull.ConvexHull(points)
    # Facets by their vertex indices taken largest first, lexicographically.
    keys = [tuple(sorted(s, reverse=True)) for s in hull.simplices.tolist()]
    assert keys == sorted(keys)
    if d == 2:
        x, y = points[hull.vertices].T
        angle = np.unwrap(np.arctan2(y - y.mean(), x - x.mean()))
        assert np.all(np.diff(angle) > 0)


@pytest.mark.parametrize("d", DIMENSIONS)
@pytest.mark.parametrize("sign", ["", "-"])
def test_good_is_scipys(d, sign):
    rng = np.random.default_rng(10 + d)
    points = rng.standard_normal((80, d))
    full = scipy.spatial.ConvexHull(points)
    inside = int(np.argmin(np.linalg.norm(points, axis=1)))
    for n in (int(full.vertices[0]), int(full.vertices[-1]), inside):
        option = f"QG{sign}{n}"
        ours = pqhull.ConvexHull(points, qhull_options=option)
        ref = scipy.spatial.ConvexHull(points, qhull_options=option)
        # Point n takes no part in the hull, in both.
        assert n not in ours.simplices and n not in ref.simplices
        assert_same_hull(ours, ref)
        assert ours.good.dtype == np.bool_ and ours.good.shape == (ours.nsimplex,)
        assert facet_set(ours.simplices, ours.good) == facet_set(ref.simplices, ref.good)
        # Visible means strictly beyond: normal . p + offset > 0.
        beyond = ours.equations[:, :-1] @ points[n] + ours.equations[:, -1] > 0
        np.testing.assert_array_equal(ours.good, beyond if sign == "" else ~beyond)
        if n == inside:
            assert not np.any(ours.good) if sign == "" else np.all(ours.good)


def test_good_counts_a_point_on_a_facet_plane_as_not_visible():
    # Point 4 lies exactly on the line of the top edge once (0.5, 0.6) and (0.6, 0.6) are in.
    square = np.array([[0.2, 0.2], [0.2, 0.4], [0.4, 0.4], [0.4, 0.2], [0.3, 0.6]])
    hull = pqhull.ConvexHull(square, incremental=True, qhull_options="QG4")
    hull.add_points([[0.5, 0.6], [0.6, 0.6]])
    top = [i for i, s in enumerate(hull.simplices.tolist()) if set(s) == {5, 6}]
    assert len(top) == 1 and not hull.good[top[0]]


@pytest.mark.parametrize("d", DIMENSIONS)
@pytest.mark.parametrize("option", [None, "QG0", "QG-0"])
def test_add_points_is_a_fresh_scipy_hull_of_all_points(d, option):
    rng = np.random.default_rng(100 + d)
    chunks = [rng.standard_normal((d + 3, d))] + [
        rng.standard_normal((k, d)) * s for k, s in ((1, 1.0), (7, 0.3), (20, 1.5), (5, 3.0))
    ]
    grown = pqhull.ConvexHull(chunks[0], incremental=True, qhull_options=option)
    restarted = pqhull.ConvexHull(chunks[0], incremental=True, qhull_options=option)
    for k, chunk in enumerate(chunks[1:], start=1):
        before = [tuple(sorted(s)) for s in grown.simplices.tolist()]
        grown.add_points(chunk)
        restarted.add_points(chunk, restart=True)
        so_far = np.concatenate(chunks[: k + 1])
        ref = scipy.spatial.ConvexHull(so_far, qhull_options=option)
        for ours in (grown, restarted):
            assert_same_hull(ours, ref)
            if option is not None:
                assert facet_set(ours.simplices, ours.good) == facet_set(ref.simplices, ref.good)
        # restart=True is the same answer, in the same order (up to each row's rotation).
        assert [sorted(s) for s in grown.simplices.tolist()] == [
            sorted(s) for s in restarted.simplices.tolist()
        ]
        # The facets that survive keep their order, and the new ones follow them (scipy's).
        after = [tuple(sorted(s)) for s in grown.simplices.tolist()]
        kept = [s for s in after if s in set(before)]
        assert after[: len(kept)] == kept
        assert kept == [s for s in before if s in set(after)]
    assert grown.points_processed >= len(grown.vertices)


def test_add_points_keeps_counting_and_close_ends_it():
    rng = np.random.default_rng(5)
    hull = pqhull.ConvexHull(rng.standard_normal((10, 3)), incremental=True)
    created = hull.facets_created
    hull.add_points(rng.standard_normal((10, 3)) * 3)
    assert hull.facets_created > created and hull.npoints == 20
    hull.add_points(np.zeros((0, 3)))  # nothing to add: as scipy, a no-op
    assert hull.npoints == 20
    volume = hull.volume
    hull.close()
    hull.close()  # twice is fine
    assert hull.volume == volume and hull.npoints == 20  # the attributes stay
    with pytest.raises(RuntimeError, match="incremental mode not enabled or already closed"):
        hull.add_points([[9.0, 9.0, 9.0]])


def grid_with_extras(d):
    """A 3^d grid (vertices: the 2^d corners; the rest on the boundary but one), duplicates of
    corners and of a boundary point, and a few random interior points."""
    grid = np.array(list(itertools.product([0.0, 1.0, 2.0], repeat=d)))
    rng = np.random.default_rng(d)
    return np.vstack([grid, grid[[0, 1, -1]], rng.uniform(0.2, 1.8, (4, d))])


@pytest.mark.parametrize("d", [2, 3, 4])
@pytest.mark.parametrize("option", ["Qc", "Qi", "Qc Qi"])
def test_coplanar_lists_what_scipy_lists(d, option):
    points = grid_with_extras(d)
    ours = pqhull.ConvexHull(points, qhull_options=option)
    ref = scipy.spatial.ConvexHull(points, qhull_options=option)
    assert set(ours.vertices.tolist()) == set(ref.vertices.tolist())
    assert ours.coplanar.dtype == np.intc and ours.coplanar.shape[1] == 3
    assert sorted(ours.coplanar[:, 0].tolist()) == sorted(ref.coplanar[:, 0].tolist())
    corners = set(ours.vertices.tolist())
    on_boundary = {
        i for i, p in enumerate(points) if i not in corners and (np.any(p == 0) or np.any(p == 2))
    }
    listed = set(ours.coplanar[:, 0].tolist())
    expected = set()
    if "Qc" in option:
        expected |= on_boundary
    if "Qi" in option:
        expected |= set(range(len(points))) - corners - on_boundary
    assert listed == expected
    for point, facet, vertex in ours.coplanar.tolist():
        assert vertex in ours.simplices[facet]
        distances = np.linalg.norm(points[ours.simplices[facet]] - points[point], axis=1)
        assert np.linalg.norm(points[vertex] - points[point]) == pytest.approx(distances.min())
        if point in on_boundary:
            # On the facet's plane and inside its simplex (barycentric coordinates >= 0).
            normal, offset = ours.equations[facet, :-1], ours.equations[facet, -1]
            assert abs(normal @ points[point] + offset) < 1e-12
            v = points[ours.simplices[facet]]
            weights = np.linalg.lstsq(np.vstack([v.T, np.ones(d)]),
                                      np.append(points[point], 1.0), rcond=None)[0]
            assert weights.min() > -1e-12
        else:
            # The facet of the nearest plane.
            planes = ours.equations[:, :-1] @ points[point] + ours.equations[:, -1]
            assert planes[facet] == pytest.approx(planes.max(), abs=1e-12)
    rows = [(f, p) for p, f, _ in ours.coplanar.tolist()]
    assert rows == sorted(rows)


def test_coplanar_after_add_points_covers_every_point():
    points = grid_with_extras(2)
    hull = pqhull.ConvexHull(points[:9], incremental=True, qhull_options="Qc")
    hull.add_points(points[9:])
    assert sorted(hull.coplanar[:, 0].tolist()) == sorted(
        pqhull.ConvexHull(points, qhull_options="Qc").coplanar[:, 0].tolist()
    )


# Options that only tune how Qhull copes with rounding: accepted, no effect.
ACCEPTED = [
    "Qt", "Qbb", "Qx", "Qs", "Qv", "Qw", "Qf", "Qm", "Qr", "Qa", "QJ", "QJ1e-9", "Q0", "Q3",
    "Q11", "Q12", "Q14", "Pp", "Po", "E1e-12", "R1e-9", "C-0", "C-1e-9", "C0.1", "A-0.99",
    "A0.9", "U1e-9", "V1e-9", "W1e-9", "Tv", "Tc", "FA", "Qt Qbb Qc Qx Q12", "QJ Pp", "",
]

# Refused, each naming the option. scipy refuses those marked True (QhullError); the others it
# accepts with a different answer (scaled or rotated input, another notion of good facets) or
# as output formats of the qhull program.
REFUSED = [
    ("Qz", True), ("Qu", True), ("Qq", True), ("Q13", True), ("QG", True), ("En", True),
    ("QG0 QG1", True), ("qt", True), ("QbB", False), ("Qbk:0Bk:0", True), ("Qb0:-1B0:1", False),
    ("QR0", False), ("QV0", False), ("Qg", True), ("Pg", False), ("PD0", False), ("T1", False),
    ("Fa", False), ("s", False), ("o", False), ("d", False),
]


@pytest.mark.parametrize("option", ACCEPTED)
def test_accepted_options_change_nothing(option):
    rng = np.random.default_rng(3)
    points = rng.standard_normal((60, 3))
    plain = pqhull.ConvexHull(points)
    hull = pqhull.ConvexHull(points, qhull_options=option)
    np.testing.assert_array_equal(hull.simplices, plain.simplices)
    np.testing.assert_array_equal(hull.equations, plain.equations)
    assert (hull.volume, hull.area) == (plain.volume, plain.area)
    assert hull.good is None
    assert pqhull.ConvexHull(points, qhull_options=option.encode()).volume == plain.volume


@pytest.mark.parametrize("option,scipy_refuses", REFUSED)
def test_refused_options_name_the_option(option, scipy_refuses):
    points = np.random.default_rng(4).standard_normal((20, 3))
    with pytest.raises(pqhull.InputError) as e:
        pqhull.ConvexHull(points, qhull_options=option)
    assert isinstance(e.value, ValueError) and isinstance(e.value, pqhull.Error)
    assert str(e.value).startswith("qhull_options: ")
    assert any(f"'{word}" in str(e.value) for word in option.split()), str(e.value)
    if scipy_refuses:
        with pytest.raises(QhullError):
            scipy.spatial.ConvexHull(points.copy(), qhull_options=option)


def test_qbb_is_refused_in_incremental_mode_as_in_scipy():
    points = np.random.default_rng(4).standard_normal((20, 3))
    with pytest.raises(ValueError, match="incompatible with incremental mode") as ref:
        scipy.spatial.ConvexHull(points.copy(), incremental=True, qhull_options="Qbb")
    with pytest.raises(pqhull.InputError, match="incompatible with incremental mode") as ours:
        pqhull.ConvexHull(points, incremental=True, qhull_options="Qbb")
    assert "Qbb" in str(ref.value) and "Qbb" in str(ours.value)


def test_qg_out_of_range_and_too_few_points_left():
    points = np.random.default_rng(4).standard_normal((5, 3))
    with pytest.raises(QhullError):
        scipy.spatial.ConvexHull(points, qhull_options="QG5")
    with pytest.raises(pqhull.InputError, match="QG5"):
        pqhull.ConvexHull(points, qhull_options="QG5")
    with pytest.raises(pqhull.HullError, match="QG0"):
        pqhull.ConvexHull(points[:4], qhull_options="QG0")


def test_masked_array_is_refused_as_scipy_refuses_it():
    masked = np.ma.masked_array(np.random.default_rng(1).standard_normal((10, 2)))
    for make in (scipy.spatial.ConvexHull, pqhull.ConvexHull):
        with pytest.raises(ValueError, match="^Input points cannot be a masked array$"):
            make(masked)
        with pytest.raises(ValueError, match="masked array"):
            make(np.ma.masked_all(1))
    with pytest.raises(pqhull.InputError):
        pqhull.ConvexHull(masked)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_input_is_a_value_error(bad):
    points = np.random.default_rng(1).standard_normal((10, 3))
    points[7, 1] = bad
    with pytest.raises(pqhull.HullError, match="7") as e:
        pqhull.ConvexHull(points)
    assert isinstance(e.value, ValueError)
    # scipy: ValueError for NaN, QhullError for infinities.
    with pytest.raises(ValueError if np.isnan(bad) else QhullError):
        scipy.spatial.ConvexHull(points)


def test_add_points_errors():
    rng = np.random.default_rng(8)
    points = rng.standard_normal((10, 3))
    # Not incremental: scipy's RuntimeError and message.
    for make in (scipy.spatial.ConvexHull, pqhull.ConvexHull):
        with pytest.raises(RuntimeError, match="^incremental mode not enabled or already closed$"):
            make(points).add_points(rng.standard_normal((2, 3)))
        hull = make(points, incremental=True)
        for wrong in (np.zeros((2, 2)), np.zeros(3), np.zeros((0, 2)), np.zeros((1, 1, 3))):
            with pytest.raises(ValueError, match="invalid size for new points array"):
                hull.add_points(wrong)
        hull.close()
        with pytest.raises(RuntimeError, match="^incremental mode not enabled or already closed$"):
            hull.add_points(rng.standard_normal((2, 3)))
    # A NaN: scipy takes it (and reports a NaN volume); pqhull refuses, names the point, and
    # leaves the hull as it was.
    hull = pqhull.ConvexHull(points, incremental=True)
    volume, simplices = hull.volume, hull.simplices.copy()
    with pytest.raises(pqhull.HullError, match="11"):
        hull.add_points([[0.0, 0.0, 0.0], [np.nan, 0.0, 0.0]])
    assert hull.volume == volume and hull.npoints == 10
    np.testing.assert_array_equal(hull.simplices, simplices)
    hull.add_points([[5.0, 5.0, 5.0]])
    assert hull.npoints == 11 and 10 in hull.vertices


def test_pickle_rebuilds_the_same_hull():
    rng = np.random.default_rng(9)
    hull = pqhull.ConvexHull(rng.standard_normal((30, 4)), incremental=True, qhull_options="QG3 Qc")
    hull.add_points(rng.standard_normal((5, 4)) * 2)
    again = pickle.loads(pickle.dumps(hull))
    for name in ("points", "simplices", "neighbors", "coplanar", "good", "vertices"):
        np.testing.assert_array_equal(getattr(again, name), getattr(hull, name))
    # The planes from the same vertices, maybe taken in another order: equal up to rounding.
    np.testing.assert_allclose(again.equations, hull.equations, rtol=1e-13, atol=1e-13)
    again.add_points(rng.standard_normal((2, 4)))  # still incremental
    hull.close()
    with pytest.raises(RuntimeError):
        pickle.loads(pickle.dumps(hull)).add_points(np.zeros((1, 4)))


def test_subclass_and_keyword_arguments():
    class Named(pqhull.ConvexHull):
        pass

    hull = Named(points=[(0, 0), (1, 0), (0, 1), (1, 1)], incremental=False, qhull_options=None)
    assert isinstance(hull, pqhull.ConvexHull) and hull.volume == 1.0 and hull.area == 4.0


def test_truthy_flags_as_in_scipy():
    square = [(0, 0), (1, 0), (0, 1), (1, 1)]
    hull = pqhull.ConvexHull(square, 1)  # any truthy value, as scipy's `if incremental:`
    hull.add_points([(2, 2)], 1)
    assert hull.npoints == 5 and hull.volume == 2.0
    with pytest.raises(RuntimeError):
        pqhull.ConvexHull(square, incremental=0).add_points([(2, 2)])
