"""Q1's exact gradient from Python (`q1(..., gradient=True)`, `evaluate(..., gradient=True)`),
checked independently: central differences of a Q1 built here from the wrench formula and
scipy.spatial.ConvexHull, not from pqhull.

The reference (`wrenches`, `scipy_q1`) re-implements the library's conventions
(src/grasp/contact.rs, src/grasp/friction.rs, src/grasp/wrench.rs):

* n = normal / |normal|;
* t: a given tangent normalised, made orthogonal to n (Gram-Schmidt) and normalised again; or,
  none given, the default t = (n x e_a) / |n x e_a| with e_a the axis of smallest |n_a| (the
  lowest index on ties);
* edge j of the friction pyramid, j = 0 .. k-1: f_j = n + mu (cos(2 pi j / k) t
  + sin(2 pi j / k) (n x t));
* wrench w_j = [f_j ; (p - c) x f_j / rho] (c: torque_reference, default 0; rho: torque_scale,
  default 1); a soft finger (torsion g > 0) has 2k: [f_j ; ((p - c) x f_j + g n) / rho] for
  every j, then the same with - g n.

Q1 of a force-closure grasp is the distance from the origin to the nearest facet of the hull of
the wrenches, min over facets of -offset (scipy's equations are unit normal . x + offset <= 0
inside). Outside the hull Q1 is minus the distance to the hull, which a facet list does not give
directly, so the scipy reference is used on force-closure grasps only (with a margin that the
steps cannot cross).
"""

import threading
import time

import numpy as np
import pytest
from scipy.spatial import ConvexHull

import pqhull

# Central-difference step. Truncation: h^2/6 |Q1'''| ~ 1e-12 (Q1 is piecewise smooth with
# derivatives of order 1-10 at the grasp scale of 1). Rounding: scipy's facet offsets are
# accurate to a few ulps of the wrench scale (~1e-15, Qhull's merging of the pyramids'
# coplanar wrenches to ~1e-14), divided by 2h: ~1e-9 to 1e-8. pqhull's gradient is exact to
# ~1e-12. So a correct gradient agrees with the differences to ~1e-8; TOLERANCE allows 100x that.
STEP = 1e-6
TOLERANCE = 1e-6
# A component is a kink (a face switch within a step, where the one-sided slopes differ by
# O(|gradient|)) when its forward and backward slopes differ by more than this: the smooth part
# of their difference is h |Q1''| <= ~1e-5 and rounding 2e-15 / h ~ 2e-9.
KINK = 1e-5


def unit(v):
    return v / np.linalg.norm(v)


def frame(normal, tangent):
    """The contact's unit normal and tangent, as the library derives them."""
    n = unit(np.asarray(normal, dtype=float))
    if tangent is None:
        a = int(np.argmin(np.abs(n)))  # argmin: the lowest index on ties
        t = unit(np.cross(n, np.eye(3)[a]))
    else:
        g = unit(np.asarray(tangent, dtype=float))
        r = g - np.dot(g, n) * n
        r = r - np.dot(r, n) * n
        t = unit(r)
    return n, t


def wrenches(positions, normals, tangents, torsion, mu, k, reference, rho):
    """Every wrench of the grasp (m k, or 2k per soft contact, by 6), in the library's order."""
    out = []
    angles = 2.0 * np.pi * np.arange(k) / k
    for i in range(len(positions)):
        n, t = frame(normals[i], None if tangents is None else tangents[i])
        b = np.cross(n, t)
        forces = n + mu * (np.cos(angles)[:, None] * t + np.sin(angles)[:, None] * b)
        torques = np.cross(positions[i] - reference, forces)
        g = 0.0 if torsion is None else torsion[i]
        if g > 0.0:
            for sign in (1.0, -1.0):
                out.append(np.hstack([forces, (torques + sign * g * n) / rho]))
        else:
            out.append(np.hstack([forces, torques / rho]))
    return np.vstack(out)


def scipy_q1(w):
    """Q1 of a force-closure wrench set by scipy: the nearest facet's distance (positive)."""
    return float(np.min(-ConvexHull(w).equations[:, -1]))


class Grasp:
    """One grasp's inputs, as the tests pass them to pqhull and to the reference."""

    def __init__(self, positions, normals, tangents, torsion, mu, k, reference, rho):
        self.positions, self.normals, self.tangents = positions, normals, tangents
        self.torsion, self.mu, self.k, self.reference, self.rho = torsion, mu, k, reference, rho

    def kwargs(self):
        return dict(torsion=self.torsion, friction=self.mu, cone_edges=self.k,
                    torque_reference=None if self.reference is None else self.reference,
                    torque_scale=None if self.rho is None else self.rho)

    def pqhull(self, **extra):
        return pqhull.q1(self.positions, self.normals, self.tangents, **self.kwargs(), **extra)

    def reference_q1(self, positions=None, normals=None, mu=None):
        positions = self.positions if positions is None else positions
        normals = self.normals if normals is None else normals
        mu = self.mu if mu is None else mu
        reference = np.zeros(3) if self.reference is None else self.reference
        rho = 1.0 if self.rho is None else self.rho
        return scipy_q1(wrenches(positions, normals, self.tangents, self.torsion, mu, self.k,
                                 reference, rho))


def random_grasp(rng):
    """Generic contacts on a random ellipsoid: inward normals tilted off the surface's at random
    (never axis-aligned), cone edges 4 to 8, hard or soft fingers, given tangents or the default,
    the default torque frame or a random one."""
    axes = rng.uniform(0.5, 1.5, 3)
    m = int(rng.integers(3, 7))
    d = rng.standard_normal((m, 3))
    positions = d / np.sqrt(((d / axes) ** 2).sum(axis=1, keepdims=True))
    inward = -positions / axes**2
    inward /= np.linalg.norm(inward, axis=1, keepdims=True)
    normals = inward + 0.3 * rng.standard_normal((m, 3))
    # Still inward (within ~70 degrees of the surface's normal); resampled otherwise.
    while True:
        cosine = (normals * inward).sum(axis=1) / np.linalg.norm(normals, axis=1)
        tilted = cosine < 0.35
        if not tilted.any():
            break
        normals[tilted] = inward[tilted] + 0.3 * rng.standard_normal((int(tilted.sum()), 3))
    normals *= rng.uniform(0.5, 2.0, (m, 1))  # not unit: the library normalises them
    tangents = rng.standard_normal((m, 3)) if rng.random() < 0.5 else None
    torsion = rng.uniform(0.01, 0.1, m) if rng.random() < 0.3 else None
    mu = float(rng.uniform(0.3, 1.0))
    k = int(rng.choice([4, 5, 6, 8]))
    reference = rng.uniform(-0.2, 0.2, 3) if rng.random() < 0.5 else None
    rho = float(rng.uniform(0.5, 2.0)) if rng.random() < 0.5 else None
    return Grasp(positions, normals, tangents, torsion, mu, k, reference, rho)


def sphere_step(normal, axis, h):
    """The normal moved by h along the sphere direction e_a - n_a n (at the unit normal n),
    renormalised, at the length it was given with."""
    length = np.linalg.norm(normal)
    n = normal / length
    e = np.eye(3)[axis]
    return unit(n + h * (e - n[axis] * n)) * length


def finite_differences(grasp):
    """Central differences of the scipy Q1, and the forward/backward disagreement, for every
    position coordinate, every normal moved along the sphere (per axis), and the friction."""
    base = grasp.reference_q1()
    central, disagreement = [], []

    def record(plus, minus):
        central.append((plus - minus) / (2 * STEP))
        forward, backward = (plus - base) / STEP, (base - minus) / STEP
        disagreement.append(abs(forward - backward))

    m = len(grasp.positions)
    for i in range(m):
        for a in range(3):
            p = grasp.positions.copy()
            p[i, a] += STEP
            plus = grasp.reference_q1(positions=p)
            p[i, a] -= 2 * STEP
            record(plus, grasp.reference_q1(positions=p))
    for i in range(m):
        for a in range(3):
            n = grasp.normals.copy()
            n[i] = sphere_step(grasp.normals[i], a, STEP)
            plus = grasp.reference_q1(normals=n)
            n[i] = sphere_step(grasp.normals[i], a, -STEP)
            record(plus, grasp.reference_q1(normals=n))
    record(grasp.reference_q1(mu=grasp.mu + STEP), grasp.reference_q1(mu=grasp.mu - STEP))
    return base, np.array(central), np.array(disagreement)


def analytic(q, m):
    """pqhull's gradient in the order of `finite_differences`. The normals' gradient is with
    respect to the unit normal; the differences move the unit normal (the given length kept) by
    h (e_a - n_a n), whose derivative is exactly gradient_normals[i, a]."""
    assert q.gradient_positions.shape == (m, 3) and q.gradient_normals.shape == (m, 3)
    return np.concatenate([q.gradient_positions.ravel(), q.gradient_normals.ravel(),
                           [q.gradient_friction]])


def force_closure_grasps(count, seed):
    """`count` generic force-closure grasps whose Q1 has a margin the steps cannot cross."""
    rng = np.random.default_rng(seed)
    grasps = []
    while len(grasps) < count:
        g = random_grasp(rng)
        q = g.pqhull()
        if q.force_closure and q.value > 1e-3:
            grasps.append(g)
    return grasps


def test_gradient_matches_scipy_finite_differences():
    grasps = force_closure_grasps(60, seed=28)
    compared = kinks = 0
    worst = 0.0
    flags = []
    kinds = {"tangents": 0, "soft": 0, "frame": 0}
    for index, g in enumerate(grasps):
        kinds["tangents"] += g.tangents is not None
        kinds["soft"] += g.torsion is not None
        kinds["frame"] += g.reference is not None or g.rho is not None
        q = g.pqhull(gradient=True)
        m = len(g.positions)
        base, central, disagreement = finite_differences(g)
        # The reference is the same function: its value agrees with pqhull's exact one.
        assert abs(base - q.value) <= 1e-12 * (1 + abs(base)), (index, base, q.value)
        flags.append(q.differentiable)
        exact = analytic(q, m)
        smooth = disagreement <= KINK * (1 + np.abs(central))
        kinks += int((~smooth).sum())
        compared += int(smooth.sum())
        error = np.abs(exact - central)[smooth]
        bound = TOLERANCE * (1 + np.abs(exact[smooth]))
        assert np.all(error <= bound), (index, np.flatnonzero(smooth)[error > bound],
                                        exact[smooth][error > bound],
                                        central[smooth][error > bound])
        worst = max(worst, float(np.max(error / (1 + np.abs(exact[smooth])), initial=0.0)))
        # The normals' rows are tangent to the sphere: orthogonal to each unit normal.
        units = g.normals / np.linalg.norm(g.normals, axis=1, keepdims=True)
        assert np.all(np.abs((q.gradient_normals * units).sum(axis=1)) <= 1e-12 *
                      (1 + np.abs(q.gradient_normals).sum(axis=1)))
    print(f"\n{len(grasps)} grasps, {compared} components compared, {kinks} kinks skipped, "
          f"worst relative error {worst:.2e}, {sum(flags)} differentiable, kinds {kinds}")
    # Every kind of input was exercised.
    assert all(v >= 5 for v in kinds.values()), kinds
    # Kinks are rare on generic grasps (a face switch within 1e-6 of the grasp).
    assert kinks <= 0.01 * (compared + kinks), (kinks, compared)
    # Generic grasps are differentiable (no ties, no axis-aligned normals).
    assert all(flags), flags


def batch_inputs(n=120, m=4, seed=5):
    rng = np.random.default_rng(seed)
    normals = rng.standard_normal((n, m, 3))
    normals /= np.linalg.norm(normals, axis=2, keepdims=True)
    positions = -normals * rng.uniform(0.5, 1.0, (n, m, 1)) + 0.05 * rng.standard_normal((n, m, 3))
    tangents = rng.standard_normal((n, m, 3))
    torsion = np.where(rng.random((n, m)) < 0.3, rng.uniform(0.01, 0.05, (n, m)), 0.0)
    friction = rng.uniform(0.2, 0.9, n)
    return positions, normals, tangents, torsion, friction


@pytest.mark.parametrize("given_tangents", [False, True])
def test_batch_gradient_equals_single_grasp_gradient_row_by_row(given_tangents):
    positions, normals, tangents, torsion, friction = batch_inputs()
    if not given_tangents:
        tangents = None
    bad = 7
    normals[bad, 2] = 0.0  # a zero normal: a bad row
    batch = pqhull.evaluate(positions, normals, tangents, torsion=torsion, friction=friction,
                            cone_edges=6, torque_scale=0.8, gradient=True)
    n, m = positions.shape[:2]
    assert [row for row, _ in batch.errors] == [bad]
    assert batch.gradient_positions.shape == (n, m, 3)
    assert batch.gradient_normals.shape == (n, m, 3)
    assert batch.gradient_friction.shape == (n,)
    assert batch.differentiable.shape == (n,) and batch.differentiable.dtype == bool
    # The bad row: NaN and False, like its quality and force_closure.
    assert np.isnan(batch.quality[bad]) and not batch.force_closure[bad]
    assert np.all(np.isnan(batch.gradient_positions[bad]))
    assert np.all(np.isnan(batch.gradient_normals[bad]))
    assert np.isnan(batch.gradient_friction[bad]) and not batch.differentiable[bad]
    # The values are those without the gradient, bit for bit.
    plain = pqhull.evaluate(positions, normals, tangents, torsion=torsion, friction=friction,
                            cone_edges=6, torque_scale=0.8)
    np.testing.assert_array_equal(plain.quality, batch.quality)
    np.testing.assert_array_equal(plain.force_closure, batch.force_closure)
    assert plain.gradient_positions is None and plain.differentiable is None
    closure = 0
    for i in range(n):
        if i == bad:
            continue
        q = pqhull.q1(positions[i], normals[i], None if tangents is None else tangents[i],
                      torsion=torsion[i], friction=friction[i], cone_edges=6, torque_scale=0.8,
                      gradient=True)
        assert q.value == batch.quality[i] and q.force_closure == batch.force_closure[i]
        np.testing.assert_array_equal(q.gradient_positions, batch.gradient_positions[i])
        np.testing.assert_array_equal(q.gradient_normals, batch.gradient_normals[i])
        assert q.gradient_friction == batch.gradient_friction[i]
        assert q.differentiable == batch.differentiable[i]
        closure += q.force_closure
    # Both kinds of rows: the gradient inside (nearest facet) and outside (nearest face).
    assert 0 < closure < n - 1
    # A single thread gives the same rows.
    one = pqhull.evaluate(positions, normals, tangents, torsion=torsion, friction=friction,
                          cone_edges=6, torque_scale=0.8, gradient=True, threads=1)
    np.testing.assert_array_equal(one.gradient_positions, batch.gradient_positions)
    np.testing.assert_array_equal(one.gradient_normals, batch.gradient_normals)
    np.testing.assert_array_equal(one.gradient_friction, batch.gradient_friction)
    np.testing.assert_array_equal(one.differentiable, batch.differentiable)


def test_the_gil_is_released_with_gradient():
    """The batch's values and gradients are computed without the GIL: while a thread runs the
    batch, this one keeps running (no gap in its ticks as long as the evaluation)."""
    positions, normals, _, _, friction = batch_inputs(n=800, seed=9)
    span = {}

    def run():
        span["start"] = time.perf_counter()
        span["batch"] = pqhull.evaluate(positions, normals, friction=friction, cone_edges=16,
                                        gradient=True, threads=1)
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=run)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    evaluation = span["batch"].evaluation_s
    assert evaluation > 0.05, evaluation  # long enough to tell
    inside = np.array([t for t in ticks if span["start"] <= t <= span["end"]])
    gaps = np.diff(np.concatenate([[span["start"]], inside, [span["end"]]]))
    # Holding the GIL would stop this thread for the whole evaluation.
    print(f"\nevaluation {evaluation:.3f} s, {len(inside)} ticks, longest gap {gaps.max():.4f} s")
    assert gaps.max() < 0.5 * evaluation, (gaps.max(), evaluation)


def box_grasp():
    """Six contacts at the face centres' neighbourhoods of an axis-aligned box, pushing inward
    along the axes: every default tangent's axis is tied (|n| = (1, 0, 0) and so on)."""
    half = np.array([0.6, 0.4, 0.3])
    positions, normals = [], []
    offsets = [(0.1, -0.05), (-0.08, 0.12), (0.07, 0.04)]
    for a in range(3):
        for s in (1.0, -1.0):
            p = np.zeros(3)
            p[a] = s * half[a]
            others = [b for b in range(3) if b != a]
            p[others[0]], p[others[1]] = offsets[a]
            n = np.zeros(3)
            n[a] = -s
            positions.append(p)
            normals.append(n)
    return np.array(positions), np.array(normals)


def test_axis_aligned_box_grasp_is_not_differentiable():
    positions, normals = box_grasp()
    q = pqhull.q1(positions, normals, friction=0.5, cone_edges=8, gradient=True)
    assert q.force_closure
    assert q.differentiable is False
    assert q.gradient_positions.shape == (6, 3) and np.all(np.isfinite(q.gradient_positions))
    batch = pqhull.evaluate(positions[None], normals[None], friction=0.5, cone_edges=8,
                            gradient=True)
    assert batch.differentiable.tolist() == [False]
    # Given tangents remove the tie: the same contacts are differentiable then.
    tangents = np.array([[0.0, 1.0, 0.3], [0.0, 0.2, 1.0], [1.0, 0.0, 0.4],
                         [0.3, 0.0, 1.0], [1.0, 0.5, 0.0], [0.2, 1.0, 0.0]])
    given = pqhull.q1(positions, normals, tangents, friction=0.5, cone_edges=8, gradient=True)
    assert given.force_closure and given.differentiable is True


def test_gradient_for_another_metric_is_an_input_error():
    positions, normals, _, _, friction = batch_inputs(n=3)
    for metric in ("qinf", "volume", "sigma-min"):
        with pytest.raises(pqhull.InputError, match="gradient is computed for q1 only so far"):
            pqhull.evaluate(positions, normals, friction=friction, cone_edges=6, metric=metric,
                            gradient=True)
    # The default, gradient=False, changes nothing for them.
    assert pqhull.evaluate(positions, normals, friction=friction, cone_edges=6,
                           metric="qinf").gradient_positions is None


def test_without_gradient_nothing_changes():
    positions, normals = box_grasp()
    plain = pqhull.q1(positions, normals, friction=0.5, cone_edges=8)
    assert plain.gradient_positions is None and plain.gradient_normals is None
    assert plain.gradient_friction is None and plain.differentiable is None
    assert "differentiable" not in repr(plain)
    full = pqhull.q1(positions, normals, friction=0.5, cone_edges=8, gradient=True)
    assert (full.value, full.force_closure) == (plain.value, plain.force_closure)
    assert "differentiable=False" in repr(full)


@pytest.mark.parametrize("method", ["full"])
def test_other_methods_give_the_same_gradient(method):
    g = force_closure_grasps(5, seed=3)
    for grasp in g:
        a = grasp.pqhull(gradient=True)
        b = grasp.pqhull(gradient=True, method=method)
        assert abs(a.value - b.value) <= 1e-12 * (1 + abs(a.value))
        np.testing.assert_allclose(b.gradient_positions, a.gradient_positions, rtol=0, atol=1e-9)
        np.testing.assert_allclose(b.gradient_normals, a.gradient_normals, rtol=0, atol=1e-9)
        assert abs(b.gradient_friction - a.gradient_friction) <= 1e-9
