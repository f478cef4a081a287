"""pqhull.penetration_depth against a reference built here with scipy on the same data: every
pairwise difference a_i - b_j materialised, Qhull's hull of them when the origin is inside
(the depth is the nearest facet's distance), and, when it is outside, the distance from the
origin to their hull by an active-set (Wolfe) nearest-point method started from scipy's NNLS,
with a certified bracket: a point of the hull bounds the distance above, the plane through it
orthogonal to it bounds it below."""

import concurrent.futures
import threading
import time

import numpy as np
import pytest
import scipy.optimize
import scipy.spatial

import pqhull

# The library's documented accuracy: within 1e-12 of itself or 2e-15 of `scale` of the exact
# depth of the computed differences fl(a_i - b_j), which the reference uses too.
RELATIVE, ABSOLUTE = 1e-12, 2e-15
# The reference's own accuracy, measured on every case (Qhull's offsets against the support
# function along its normals; the width of the nearest-point bracket), must be below this much
# of the scale: 1e-13 (it is about 1e-15; a sloppy reference fails here, not in the comparison).
REFERENCE_TOLERANCE = 1e-13
# Seen: ours and the reference agree to 1e-16 * scale, and a real error (another facet or
# vertex of the difference) is off by a fraction of the bodies' size, so the comparison allows
# only the library's documented error plus the reference's measured one.


def bound(depth, scale):
    """The library's documented error bound on a depth."""
    return RELATIVE * abs(depth) + ABSOLUTE * scale


def differences(a, b):
    """Every a_i - b_j, rounded as float64 computes it (as the library does)."""
    return (a[:, None, :] - b[None, :, :]).reshape(-1, a.shape[1])


def support(points, u):
    """h(u) = max over the points of u . p."""
    return float(np.max(points @ u))


def nearest_point(vertices):
    """The point of conv(vertices) nearest the origin (which is outside it), as (x, weights):
    scipy.optimize.nnls on the augmented system [V^T; M 1^T] w = [0; M] for a first support,
    then Wolfe's active-set iterations (affine projections by least squares, a line search back
    to feasibility when a weight goes negative, the most violating vertex added) until no
    vertex lies below the plane through x orthogonal to x."""
    k, d = vertices.shape
    size = np.abs(vertices).max()
    weight = 1e3 * size
    system = np.vstack([vertices.T, np.full((1, k), weight)])
    w, _ = scipy.optimize.nnls(system, np.concatenate([np.zeros(d), [weight]]))
    active = list(np.flatnonzero(w > 1e-9 * w.max()))
    w = np.where(np.isin(np.arange(k), active), w, 0.0)
    w /= w.sum()
    for _ in range(50 * k):
        # Minor cycles: the affine projection of the origin on the active vertices.
        while True:
            base, rest = vertices[active[0]], vertices[active[1:]]
            if len(active) > 1:
                c, *_ = np.linalg.lstsq((rest - base).T, -base, rcond=None)
            else:
                c = np.zeros(0)
            v = np.zeros(k)
            v[active] = np.concatenate([[1.0 - c.sum()], c])
            if (v[active] > 0.0).all():
                w = v
                break
            # Back to the segment's last feasible point; the first weight to reach 0 leaves.
            shrinking = [i for i in active if v[i] <= 0.0]
            theta = min(w[i] / (w[i] - v[i]) for i in shrinking)
            w = np.clip(w + theta * (v - w), 0.0, None)
            active = [i for i in active if w[i] > 0.0]
            w /= w.sum()
        x = w @ vertices
        gap = vertices @ x - x @ x
        worst = int(np.argmin(gap))
        if gap[worst] >= -1e-15 * size * size or worst in active:
            return x, w
        active.append(worst)
    raise AssertionError("the reference's nearest-point iterations did not converge")


def reference(a, b):
    """The signed depth of the same data, its accuracy, and the facet normal or nearest point
    it comes from."""
    diffs = differences(a, b)
    scale = np.linalg.norm(np.abs(diffs).max(axis=0))
    hull = scipy.spatial.ConvexHull(diffs)
    normals, offsets = hull.equations[:, :-1], hull.equations[:, -1]
    if (offsets < 0).all():
        # Every facet plane must support the differences: Qhull's offsets against the support
        # function along each normal, recomputed here, give the reference's accuracy.
        h = np.max(diffs @ normals.T, axis=0)
        accuracy = float(np.max(np.abs(h + offsets)))
        assert accuracy <= REFERENCE_TOLERANCE * scale, accuracy
        nearest = int(np.argmin(-offsets))
        return float(-offsets[nearest]), accuracy, normals[nearest]
    x, w = nearest_point(hull.points[hull.vertices])
    assert (w >= 0).all() and abs(w.sum() - 1.0) < 1e-15 * len(w)
    upper = float(np.linalg.norm(x))
    lower = float(np.min(diffs @ (x / upper)))
    # (lower may exceed upper by the rounding of the dot products.)
    assert 0.0 < lower <= upper + 1e-15 * scale
    accuracy = abs(upper - lower)
    assert accuracy <= REFERENCE_TOLERANCE * scale, accuracy
    return -upper, accuracy, x


def polytope(rng, d, n, centre, radius):
    """n random points: a ball's worth of Gaussian directions, some on the sphere, some inside."""
    g = rng.standard_normal((n, d))
    g /= np.linalg.norm(g, axis=1, keepdims=True)
    g *= rng.uniform(0.3, 1.0, (n, 1))
    return centre + radius * g


def cases():
    rng = np.random.default_rng(20240611)
    for d in (2, 3, 4, 5):
        for k in range(8):
            n, m = rng.integers(d + 1, 12, size=2)
            a = polytope(rng, d, n, rng.uniform(-2, 2, d), rng.uniform(0.5, 3.0))
            offset = rng.standard_normal(d)
            offset /= np.linalg.norm(offset)
            # Even k: centres close (overlapping, mostly); odd k: far apart (separated).
            reach = rng.uniform(0.0, 1.0) if k % 2 == 0 else rng.uniform(4.0, 9.0)
            b = polytope(rng, d, m, a.mean(axis=0) + reach * offset, rng.uniform(0.5, 3.0))
            yield pytest.param(a, b, id=f"d{d}-{k}-{'near' if k % 2 == 0 else 'far'}")


CASES = list(cases())


def test_cases_are_overlapping_and_separated_in_every_dimension():
    seen = {(a.shape[1], pqhull.penetration_depth(a, b).relation) for a, b in
            (c.values for c in CASES)}
    assert seen == {(d, r) for d in (2, 3, 4, 5) for r in ("overlapping", "separated")}


@pytest.mark.parametrize("a,b", CASES)
def test_matches_scipy_reference(a, b):
    p = pqhull.penetration_depth(a, b)
    ref, accuracy, witness = reference(a, b)
    diffs = differences(a, b)
    assert abs(p.depth - ref) <= bound(ref, p.scale) + accuracy, (p.depth, ref, accuracy)
    assert p.relation == ("overlapping" if ref > 0 else "separated")
    # scale bounds every difference's norm.
    assert np.linalg.norm(diffs, axis=1).max() <= p.scale
    assert p.rounding >= 0.0 and p.rounding <= 1e-15 * p.scale
    # The direction is unit and attains the depth: depth = min over unit u of h(u).
    assert p.direction.shape == p.translation.shape == (a.shape[1],)
    assert p.direction.dtype == p.translation.dtype == np.float64
    assert np.linalg.norm(p.direction) == pytest.approx(1.0, abs=1e-15)
    # (the support function computed in float64: a few ulps of the scale more.)
    assert abs(support(diffs, p.direction) - p.depth) <= bound(p.depth, p.scale) + 1e-15 * p.scale
    np.testing.assert_array_equal(p.translation, p.depth * p.direction)
    if ref > 0:
        # Overlapping: the outward normal of the nearest facet (the random data has one).
        np.testing.assert_allclose(p.direction, witness, atol=1e-12)
    else:
        # Disjoint: minus the nearest point of the difference, normalised (from a to b).
        np.testing.assert_allclose(p.direction, -witness / np.linalg.norm(witness), atol=1e-12)


@pytest.mark.parametrize("a,b", CASES)
def test_translation_makes_the_bodies_touch(a, b):
    p = pqhull.penetration_depth(a, b)
    # b + translation is rounded (by at most 2^-53 of each coordinate: about 1e-16 * scale per
    # difference), and each depth is within the library's bound: 1e-14 * scale covers both.
    tolerance = 1e-14 * p.scale
    moved = pqhull.penetration_depth(a, b + p.translation)
    assert abs(moved.depth) <= tolerance, (p.depth, moved.depth)
    # Moving a by the opposite does the same.
    assert abs(pqhull.penetration_depth(a - p.translation, b).depth) <= tolerance


@pytest.mark.parametrize("a,b", CASES)
def test_symmetric(a, b):
    # fl(b - a) = -fl(a - b) exactly: the two differences are exact reflections, so their exact
    # depths are equal, and the computed ones are each within the library's bound of it (seen:
    # bit-identical in 29 of the 32 cases, an ulp apart in the others; the directions an ulp or
    # two apart in 9).
    p, q = pqhull.penetration_depth(a, b), pqhull.penetration_depth(b, a)
    assert abs(p.depth - q.depth) <= 2 * bound(p.depth, p.scale)
    assert p.relation == q.relation
    np.testing.assert_allclose(q.direction, -p.direction, atol=1e-12)
    assert q.scale == p.scale and q.rounding == p.rounding


def test_overlapping_squares_exact():
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    p = pqhull.penetration_depth(square, square + [0.75, 0.0])
    assert p.depth == 0.25
    assert p.relation == "overlapping"
    assert p.rounding == 0.0
    np.testing.assert_array_equal(p.direction, [1.0, 0.0])
    np.testing.assert_array_equal(p.translation, [0.25, 0.0])
    q = pqhull.penetration_depth(square + [0.75, 0.0], square)
    assert q.depth == 0.25
    np.testing.assert_array_equal(q.direction, [-1.0, 0.0])
    # Shifted along y too: still 0.25 along x (the y overlap is 0.875).
    r = pqhull.penetration_depth(square, square + [0.75, 0.125])
    assert r.depth == 0.25
    np.testing.assert_array_equal(r.translation, [0.25, 0.0])


@pytest.mark.parametrize("shift", [[1, 0], [0, -1], [1, 1], [-1, 1], [1, 0.5]])
def test_touching_integer_squares_exact(shift):
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]])
    p = pqhull.penetration_depth(square, square + shift)
    assert p.depth == 0.0
    assert p.relation == "touching"
    assert p.rounding == 0.0
    assert np.linalg.norm(p.direction) == pytest.approx(1.0, abs=1e-15)
    np.testing.assert_array_equal(p.translation, [0.0, 0.0])


def test_separated_cubes():
    cube = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], dtype=float)
    p = pqhull.penetration_depth(cube, cube + [0.0, 3.0, 0.5])
    assert p.depth == pytest.approx(-2.0, abs=1e-15)
    assert p.relation == "separated"
    np.testing.assert_allclose(p.direction, [0.0, 1.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(p.translation, [0.0, -2.0, 0.0], atol=1e-15)


def test_repr_and_types():
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    p = pqhull.penetration_depth(square, [[0.5, 0.5], [2, 0.5], [2, 2]])
    assert isinstance(p, pqhull.Penetration)
    assert type(p.depth) is float and type(p.rounding) is float and type(p.scale) is float
    assert type(p.relation) is str
    assert repr(p).startswith("Penetration(depth=") and "overlapping" in repr(p)
    # One array per attribute, read as often as wanted.
    assert p.direction is p.direction
    assert isinstance(p.points_processed, int) and isinstance(p.facets_created, int)
    assert "penetration_depth" in pqhull.__all__ and "Penetration" in pqhull.__all__


@pytest.mark.parametrize("d", [6, 7, 8])
def test_high_dimensions(d):
    rng = np.random.default_rng(d)
    # Each body holds a cross-polytope (so the ball of radius 1/sqrt(d) about its centre), and
    # the centres are 0.05 * sqrt(d) apart, less than 2 / sqrt(d): they overlap.
    cross = np.vstack([np.eye(d), -np.eye(d)])
    a = np.vstack([polytope(rng, d, 10, np.zeros(d), 1.0), cross])
    b = np.vstack([polytope(rng, d, 10, np.full(d, 0.05), 1.0), cross + 0.05])
    p = pqhull.penetration_depth(a, b)
    assert p.relation == "overlapping" and p.direction.shape == (d,)
    assert abs(support(differences(a, b), p.direction) - p.depth) <= (
        bound(p.depth, p.scale) + 1e-15 * p.scale)
    far = pqhull.penetration_depth(a, b + 5.0)
    assert far.relation == "separated"
    ref, accuracy, _ = reference_outside(a, b + 5.0)
    assert abs(far.depth - ref) <= bound(ref, far.scale) + accuracy


def reference_outside(a, b):
    """The distance reference alone (no Qhull: its hull in 6 to 8 dimensions is large)."""
    diffs = differences(a, b)
    x, _ = nearest_point(diffs)
    upper = float(np.linalg.norm(x))
    lower = float(np.min(diffs @ (x / upper)))
    accuracy = abs(upper - lower)
    assert accuracy <= REFERENCE_TOLERANCE * np.linalg.norm(np.abs(diffs).max(axis=0))
    return -upper, accuracy, x


def test_threads():
    # Threads side by side each get their own answer.
    cases = [c.values for c in CASES[:8]]
    expected = [pqhull.penetration_depth(a, b).depth for a, b in cases]
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        got = list(pool.map(lambda ab: pqhull.penetration_depth(*ab).depth, cases * 4))
    assert got == expected * 4


def test_gil_is_released():
    # Two flat bodies in 3-D (their difference is flat and holds the origin: every difference
    # is materialised, a fraction of a second): the main thread keeps ticking meanwhile, which
    # it could not if the call held the GIL.
    rng = np.random.default_rng(3)
    a, b = (np.c_[rng.uniform(-1, 1, (150, 2)), np.zeros(150)] for _ in range(2))
    span, result, ticks = [], [], []

    def work():
        span.append(time.perf_counter())
        result.append(pqhull.penetration_depth(a, b))
        span.append(time.perf_counter())

    worker = threading.Thread(target=work)
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    assert result[0].depth == 0.0 and result[0].relation == "touching"
    start, end = span
    third = (end - start) / 3
    assert any(start + third < t < end - third for t in ticks), (end - start, len(ticks))


# Errors: every one a pqhull.Error, and so a ValueError.

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])


def raises(kind, match, a, b):
    with pytest.raises(kind, match=match) as e:
        pqhull.penetration_depth(a, b)
    assert isinstance(e.value, pqhull.Error) and isinstance(e.value, ValueError)
    return e.value


def test_dimension_mismatch():
    raises(pqhull.InputError, "b has 3 coordinates but a has 2", SQUARE, np.zeros((4, 3)))


@pytest.mark.parametrize("d", [0, 1, 9])
def test_dimension_out_of_range(d):
    raises(pqhull.InputError, f"{d} coordinates; pqhull works in 2 to 8 dimensions",
           np.zeros((4, d)), np.zeros((4, d)))


def test_not_two_dimensional():
    raises(pqhull.InputError, r"a must have 2 dimensions, not shape \(2,\)", [0.0, 1.0], SQUARE)
    raises(pqhull.InputError, r"b must have 2 dimensions", SQUARE, np.zeros((2, 2, 2)))
    raises(pqhull.InputError, "a: not an array of numbers", [["x", "y"]], SQUARE)


@pytest.mark.parametrize("body", ["a", "b"])
def test_empty_body(body):
    empty = np.empty((0, 2))
    a, b = (empty, SQUARE) if body == "a" else (SQUARE, empty)
    raises(pqhull.HullError, f"^body {body} has no vertex$", a, b)


@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("body", ["a", "b"])
def test_not_finite(body, value):
    bad = SQUARE.copy()
    bad[2, 1] = value
    a, b = (bad, SQUARE) if body == "a" else (SQUARE, bad)
    raises(pqhull.HullError,
           rf"^vertex 2 of body {body} has a NaN or infinite coordinate \(coordinate 1\)$", a, b)


def test_overflowing_differences():
    raises(pqhull.HullError, "overflow", [[1.7e308, 0.0], [1.7e308, 1.0], [1.6e308, 0.0]],
           [[-1.7e308, 0.0], [-1.7e308, 1.0], [-1.6e308, 0.0]])


def test_flat_difference_too_large():
    # Two polygons in one plane of 3-D, touching: more pairs than the flat case materialises.
    rng = np.random.default_rng(5)
    a, b = (np.c_[rng.uniform(-1, 1, (n, 2)), np.zeros(n)] for n in (257, 256))
    raises(pqhull.HullError, "flat .* 65792 vertex pairs are more than .* \\(65536\\)", a, b)


@pytest.mark.parametrize("body", ["a", "b"])
def test_masked_arrays_are_refused(body):
    masked = np.ma.masked_array(SQUARE, mask=np.zeros_like(SQUARE, dtype=bool))
    a, b = (masked, SQUARE) if body == "a" else (SQUARE, masked)
    raises(pqhull.InputError, f"^{body} cannot be a masked array$", a, b)


def test_float64_convertible_input():
    # Lists, integers and float32 are converted (float32 values are exact in float64).
    p = pqhull.penetration_depth([[0, 0], [4, 0], [4, 4], [0, 4]],
                                 np.array([[3, 1], [6, 1], [6, 3]], dtype=np.float32))
    assert p.depth == 1.0 and p.relation == "overlapping"
    # Views that are not contiguous too.
    wide = np.hstack([SQUARE, SQUARE])[:, :2]
    assert not wide.flags.c_contiguous
    assert pqhull.penetration_depth(wide, SQUARE + [0.5, 0.0]).depth == 0.5
