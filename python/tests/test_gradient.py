"""The exact gradients of Q1, Q-infinity and Q_OWS from Python (`q1` / `qinf` / `ows(...,
gradient=True)`, `evaluate(..., gradient=True)`), checked independently: central differences of
the metric built here from the wrench formula and scipy.spatial.ConvexHull, not from pqhull (Q1:
the nearest facet of the wrenches' hull; Q-infinity: the nearest facet of the hull of the
Minkowski sum of the contacts' wrench sets, written out; Q_OWS: the disturbances' ray exits
through the wrenches' facets), and for Q_OWS also central differences of pqhull's own value.

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


def random_grasp(rng, m=None, edges=(4, 5, 6, 8)):
    """Generic contacts on a random ellipsoid: inward normals tilted off the surface's at random
    (never axis-aligned), cone edges from `edges`, hard or soft fingers, given tangents or the
    default, the default torque frame or a random one; m contacts (3 to 6 at random by
    default)."""
    axes = rng.uniform(0.5, 1.5, 3)
    m = int(rng.integers(3, 7)) if m is None else m
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
    k = int(rng.choice(list(edges)))
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


def finite_differences(grasp, reference=None):
    """Central differences of `reference` (a function of the grasp's positions, normals and
    friction, keywords as `Grasp.reference_q1`'s; default: the scipy Q1), and the
    forward/backward disagreement, for every position coordinate, every normal moved along the
    sphere (per axis), and the friction."""
    reference = grasp.reference_q1 if reference is None else reference
    base = reference()
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
            plus = reference(positions=p)
            p[i, a] -= 2 * STEP
            record(plus, reference(positions=p))
    for i in range(m):
        for a in range(3):
            n = grasp.normals.copy()
            n[i] = sphere_step(grasp.normals[i], a, STEP)
            plus = reference(normals=n)
            n[i] = sphere_step(grasp.normals[i], a, -STEP)
            record(plus, reference(normals=n))
    record(reference(mu=grasp.mu + STEP), reference(mu=grasp.mu - STEP))
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
    for metric in ("volume", "sigma-min", "isotropy"):
        with pytest.raises(pqhull.InputError,
                           match=f"gradient is computed for q1, qinf and ows only .*{metric}"):
            pqhull.evaluate(positions, normals, friction=friction, cone_edges=6, metric=metric,
                            gradient=True)
    with pytest.raises(pqhull.InputError, match="gradient is computed for q1, qinf and ows only"):
        pqhull.evaluate(positions, normals, friction=friction, cone_edges=6, metric="resist",
                        wrench=np.ones(6), gradient=True)
    # The default, gradient=False, changes nothing for them.
    assert pqhull.evaluate(positions, normals, friction=friction, cone_edges=6,
                           metric="volume").gradient_positions is None
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


# --- Q-infinity and Q_OWS ---------------------------------------------------------------------


def compare(exact, central, disagreement, where):
    """Asserts that `exact` matches the central differences at every smooth component (one-sided
    slopes agreeing to KINK); returns (compared, kinks, worst relative error)."""
    smooth = disagreement <= KINK * (1 + np.abs(central))
    error = np.abs(exact - central)[smooth]
    bound = TOLERANCE * (1 + np.abs(exact[smooth]))
    assert np.all(error <= bound), (where, np.flatnonzero(smooth)[error > bound],
                                    exact[smooth][error > bound], central[smooth][error > bound])
    worst = float(np.max(error / (1 + np.abs(exact[smooth])), initial=0.0))
    return int(smooth.sum()), int((~smooth).sum()), worst


def contact_sets(g, positions, normals, mu, with_zero_wrench):
    """Each contact's wrench set (`wrenches` of that contact alone), with the zero wrench added
    when `with_zero_wrench`: the summands of Q-infinity's Minkowski sum."""
    reference = np.zeros(3) if g.reference is None else g.reference
    rho = 1.0 if g.rho is None else g.rho
    sets = []
    for i in range(len(positions)):
        w = wrenches(positions[i:i + 1], normals[i:i + 1],
                     None if g.tangents is None else g.tangents[i:i + 1],
                     None if g.torsion is None else g.torsion[i:i + 1], mu, g.k, reference, rho)
        sets.append(np.vstack([w, np.zeros(6)]) if with_zero_wrench else w)
    return sets


def minkowski_sum(sets):
    """Every sum of one wrench of each set (prod |W_i| points)."""
    total = np.zeros((1, 6))
    for w in sets:
        total = (total[:, None, :] + w[None, :, :]).reshape(-1, 6)
    return total


def scipy_qinf(g, with_zero_wrench, positions=None, normals=None, mu=None):
    """Q-infinity of a force-closure grasp by scipy: the signed distance from the origin to the
    boundary of the hull of the Minkowski sum, min over its facets of -offset (inside
    positive)."""
    positions = g.positions if positions is None else positions
    normals = g.normals if normals is None else normals
    mu = g.mu if mu is None else mu
    points = minkowski_sum(contact_sets(g, positions, normals, mu, with_zero_wrench))
    return float(np.min(-ConvexHull(points).equations[:, -1]))


def qinf_grasps(count, seed, with_zero_wrench):
    """`count` generic grasps of 3 contacts with 3 or 4 cone edges, at most the first contact
    soft and only with 3 edges (27 to 125 Minkowski points, 54 to 112 with the soft one, so
    that scipy's hull takes milliseconds: three soft contacts of 4 edges, 512 to 729 points,
    take a third of a second each), whose Q-infinity is force closure with a margin the steps
    cannot cross."""
    rng = np.random.default_rng(seed)
    grasps = []
    while len(grasps) < count:
        g = random_grasp(rng, m=3, edges=(3, 4))
        if g.torsion is not None:
            g.torsion = None if g.k > 3 else g.torsion * np.array([1.0, 0.0, 0.0])
        q = pqhull.qinf(g.positions, g.normals, g.tangents, **g.kwargs(),
                        with_zero_wrench=with_zero_wrench)
        if q.force_closure and q.value > 1e-3:
            grasps.append(g)
    return grasps


def qinf_faces(g, with_zero_wrench):
    """(affine dimension, vertex count) of each contact's face of the Minkowski sum along the
    deciding direction (the nearest facet's normal, from scipy's hull): a generic Q-infinity is
    differentiable where the dimensions add up to 5, the deciding facet's."""
    sets = contact_sets(g, g.positions, g.normals, g.mu, with_zero_wrench)
    equations = ConvexHull(minkowski_sum(sets)).equations
    u = equations[np.argmin(-equations[:, -1]), :6]
    dimensions = []
    for w in sets:
        support = w @ u
        face = w[support >= support.max() - 1e-9]
        dimensions.append((int(np.linalg.matrix_rank(face - face[0], tol=1e-9)), len(face)))
    return dimensions


@pytest.mark.parametrize("with_zero_wrench", [False, True])
def test_qinf_gradient_matches_scipy_finite_differences(with_zero_wrench):
    """Q-infinity's gradient (`qinf(..., gradient=True)`) against central differences of a
    Q-infinity built here: the Minkowski sum of the contacts' wrench sets (`wrenches` per
    contact, plus the zero wrench in each set with `with_zero_wrench`) written out with numpy,
    its hull by scipy, the nearest facet's distance. The same step, tolerance and kink test as
    Q1's: the sum's facet offsets are accurate to a few ulps of its scale (~3 here), so the
    rounding part of a difference is ~1e-15 * 3 / 2e-6 ~ 2e-9 (the worst error seen is ~4e-10,
    TOLERANCE is 1e-6)."""
    grasps = qinf_grasps(12, seed=41 + with_zero_wrench, with_zero_wrench=with_zero_wrench)
    compared = kinks = 0
    worst = 0.0
    flags = []
    generic = []
    simplices = []
    soft = 0
    for index, g in enumerate(grasps):
        soft += g.torsion is not None
        q = pqhull.qinf(g.positions, g.normals, g.tangents, **g.kwargs(),
                        with_zero_wrench=with_zero_wrench, gradient=True)
        m = len(g.positions)

        def reference(positions=None, normals=None, mu=None):
            return scipy_qinf(g, with_zero_wrench, positions, normals, mu)

        base, central, disagreement = finite_differences(g, reference)
        assert abs(base - q.value) <= 1e-12 * (1 + abs(base)), (index, base, q.value)
        flags.append(q.differentiable)
        faces = qinf_faces(g, with_zero_wrench)
        generic.append(sum(d for d, _ in faces) == 5)
        simplices.append(all(d == n - 1 for d, n in faces))
        # Never differentiable where the faces along the deciding direction are degenerate.
        assert generic[-1] or not q.differentiable, index
        c, k, w = compare(analytic(q, m), central, disagreement, index)
        compared, kinks, worst = compared + c, kinks + k, max(worst, w)
        units = g.normals / np.linalg.norm(g.normals, axis=1, keepdims=True)
        assert np.all(np.abs((q.gradient_normals * units).sum(axis=1)) <= 1e-12 *
                      (1 + np.abs(q.gradient_normals).sum(axis=1)))
    print(f"\nQ-infinity (zero wrench {with_zero_wrench}): {len(grasps)} grasps ({soft} soft), "
          f"{compared} components compared, {kinks} kinks skipped, worst relative error "
          f"{worst:.2e}, {sum(flags)} differentiable, {sum(generic)} with generic faces, "
          f"{sum(simplices)} of them with simplex faces")
    assert all(generic), generic  # the seeds' grasps are generic
    assert kinks <= 0.01 * (compared + kinks), (kinks, compared)
    # Generic grasps whose contact faces are simplices are differentiable. The others (a whole
    # pyramid rim of 4 edges, a 2-flat, in the face: with the zero wrench the library counts
    # its dimension as min(4 - 1, 3) = 3) may be flagged not differentiable, conservatively:
    # their gradient matches the differences above all the same.
    assert all(f for f, s in zip(flags, simplices) if s), (flags, simplices)
    assert sum(simplices) >= len(grasps) // 3, simplices
    if not with_zero_wrench:
        assert all(flags), flags


def test_qinf_other_method_and_batch_give_the_same_gradient():
    """`method="full"` (the hull of every Minkowski point) gives the same gradient as the partial
    hull; `evaluate(metric="qinf", gradient=True)` gives qinf's numbers row for row, with and
    without the zero wrench, NaN and False for a bad row."""
    for g in qinf_grasps(4, seed=8, with_zero_wrench=False):
        a = pqhull.qinf(g.positions, g.normals, g.tangents, **g.kwargs(), gradient=True)
        b = pqhull.qinf(g.positions, g.normals, g.tangents, **g.kwargs(), gradient=True,
                        method="full")
        assert abs(a.value - b.value) <= 1e-12 * (1 + abs(a.value))
        np.testing.assert_allclose(b.gradient_positions, a.gradient_positions, rtol=0, atol=1e-9)
        np.testing.assert_allclose(b.gradient_normals, a.gradient_normals, rtol=0, atol=1e-9)
        assert abs(b.gradient_friction - a.gradient_friction) <= 1e-9
    positions, normals, tangents, torsion, friction = batch_inputs(n=40, m=3, seed=12)
    bad = 5
    normals[bad, 1] = 0.0
    for zero in (False, True):
        batch = pqhull.evaluate(positions, normals, tangents, torsion=torsion, friction=friction,
                                cone_edges=4, metric="qinf", with_zero_wrench=zero,
                                gradient=True)
        assert [row for row, _ in batch.errors] == [bad]
        assert batch.gradient_positions.shape == (40, 3, 3)
        assert np.all(np.isnan(batch.gradient_positions[bad]))
        assert np.isnan(batch.gradient_friction[bad]) and not batch.differentiable[bad]
        plain = pqhull.evaluate(positions, normals, tangents, torsion=torsion,
                                friction=friction, cone_edges=4, metric="qinf",
                                with_zero_wrench=zero)
        np.testing.assert_array_equal(plain.quality, batch.quality)
        closure = 0
        for i in range(40):
            if i == bad:
                continue
            q = pqhull.qinf(positions[i], normals[i], tangents[i], torsion=torsion[i],
                            friction=friction[i], cone_edges=4, with_zero_wrench=zero,
                            gradient=True)
            assert q.value == batch.quality[i]
            np.testing.assert_array_equal(q.gradient_positions, batch.gradient_positions[i])
            np.testing.assert_array_equal(q.gradient_normals, batch.gradient_normals[i])
            assert q.gradient_friction == batch.gradient_friction[i]
            assert q.differentiable == batch.differentiable[i]
            closure += q.force_closure
        # Q-infinity has a value (and a gradient) inside and outside.
        assert 0 < closure < 39
        assert np.all(np.isfinite(np.delete(batch.gradient_positions, bad, axis=0)))


def scipy_ows(w, disturbances):
    """Q_OWS of a force-closure wrench set by scipy: for each disturbance d, where the ray -t d
    leaves the hull (the first facet plane it crosses outward, normal . x + offset = 0); the
    smallest t over the disturbances."""
    eq = ConvexHull(w).equations
    along = eq[:, :6] @ (-np.asarray(disturbances).T)  # (facets, disturbances)
    with np.errstate(divide="ignore", invalid="ignore"):
        exits = np.where(along > 0, -eq[:, 6:7] / along, np.inf)
    return float(exits.min())


def cube_space():
    """An object wrench space from a small cube mesh (its own torque frame)."""
    v = np.array([[x, y, z] for x in (-0.1, 0.1) for y in (-0.1, 0.1) for z in (-0.1, 0.1)])
    faces = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
             [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]
    return pqhull.ObjectWrenchSpace.from_arrays(v, faces, friction=0.5, cone_edges=4)


def ows_cases(count, seed):
    """`count` (grasp, space) pairs: random task wrench spaces of 1 to 20 disturbances, and every
    fourth one the cube's object wrench space (the grasp in the cube's torque frame, so given
    none of its own, and at the cube's size); each grasp force closure with a Q_OWS margin
    the steps cannot cross."""
    rng = np.random.default_rng(seed)
    cube = cube_space()
    cases = []
    while len(cases) < count:
        g = random_grasp(rng)
        if len(cases) % 4 == 3:
            space = cube
            g.positions = 0.1 * g.positions
            g.reference = g.rho = None
        else:
            d = rng.standard_normal((int(rng.choice([1, 5, 20])), 6))
            space = pqhull.ObjectWrenchSpace.from_disturbances(d)
        q = pqhull.ows(g.positions, g.normals, g.tangents, **g.kwargs(), space=space)
        if q.force_closure and q.value > 1e-3:
            cases.append((g, space))
    return cases


def ows_reference(g, space, positions=None, normals=None, mu=None):
    """scipy's Q_OWS of the grasp moved to (positions, normals, mu), in the space's torque frame
    when it has one, else the grasp's."""
    positions = g.positions if positions is None else positions
    normals = g.normals if normals is None else normals
    mu = g.mu if mu is None else mu
    if space.torque_frame is not None:
        reference, rho = space.torque_frame
        reference = np.asarray(reference)
    else:
        reference = np.zeros(3) if g.reference is None else g.reference
        rho = 1.0 if g.rho is None else g.rho
    w = wrenches(positions, normals, g.tangents, g.torsion, mu, g.k, reference, rho)
    return scipy_ows(w, space.disturbances)


def test_ows_gradient_matches_finite_differences():
    """Q_OWS's gradient (`ows(..., gradient=True)`) on force-closure grasps, against central
    differences of two values:

    * scipy's Q_OWS built here (`scipy_ows`: the hull of the wrenches by scipy, each
      disturbance's ray exit through its facets, the smallest), an independent reference; its
      value is also checked against pqhull's at every grasp (test_metrics.py checks the
      one-disturbance case, `resist`, the same way);
    * pqhull.ows's own value: a consistency check of the derivative against the value it
      differentiates (not independent of pqhull).

    Same step, tolerance and kink test as Q1's (Q_OWS is an offset over a ray's slope: the same
    accuracy relative to its size, whence the relative part of the bound; the worst error seen
    is ~2e-10, TOLERANCE is 1e-6)."""
    cases = ows_cases(32, seed=17)
    compared = kinks = 0
    own_compared = own_kinks = 0
    worst = own_worst = 0.0
    flags = []
    for index, (g, space) in enumerate(cases):
        q = pqhull.ows(g.positions, g.normals, g.tangents, **g.kwargs(), space=space,
                       gradient=True)
        m = len(g.positions)
        exact = analytic(q, m)

        def scipy_value(positions=None, normals=None, mu=None):
            return ows_reference(g, space, positions, normals, mu)

        def own_value(positions=None, normals=None, mu=None):
            v = pqhull.ows(g.positions if positions is None else positions,
                           g.normals if normals is None else normals, g.tangents,
                           **dict(g.kwargs(), friction=g.mu if mu is None else mu),
                           space=space).value
            assert v is not None  # the margin keeps every step in force closure
            return v

        base, central, disagreement = finite_differences(g, scipy_value)
        assert abs(base - q.value) <= 1e-9 * abs(base), (index, base, q.value)
        c, k, w = compare(exact, central, disagreement, ("scipy", index))
        compared, kinks, worst = compared + c, kinks + k, max(worst, w)
        _, central, disagreement = finite_differences(g, own_value)
        c, k, w = compare(exact, central, disagreement, ("pqhull", index))
        own_compared, own_kinks, own_worst = own_compared + c, own_kinks + k, max(own_worst, w)
        flags.append(q.differentiable)
    mesh = sum(space.torque_frame is not None for _, space in cases)
    print(f"\nQ_OWS: {len(cases)} grasps ({mesh} in a mesh's frame), against scipy: {compared} "
          f"compared, {kinks} kinks, worst {worst:.2e}; against its own value: {own_compared} "
          f"compared, {own_kinks} kinks, worst {own_worst:.2e}; {sum(flags)} differentiable")
    assert mesh >= 5
    assert kinks <= 0.01 * (compared + kinks), (kinks, compared)
    assert own_kinks <= 0.01 * (own_compared + own_kinks), (own_kinks, own_compared)
    # Generic grasps and disturbances: no ridge, no tie between disturbances.
    assert all(flags), flags


def not_force_closure():
    """Four contacts on one side of a sphere, all pushing towards +z: no force closure."""
    positions = np.array([[0.3, 0.1, -0.9], [-0.2, 0.3, -0.9], [0.1, -0.3, -0.9],
                          [-0.2, -0.2, -0.95]])
    normals = np.array([[0.05, 0.02, 1.0], [-0.03, 0.04, 1.0], [0.02, -0.05, 1.0],
                        [0.01, 0.03, 1.0]])
    return positions, normals


def test_ows_without_force_closure_has_no_gradient():
    positions, normals = not_force_closure()
    space = pqhull.ObjectWrenchSpace.from_disturbances(
        np.random.default_rng(2).standard_normal((10, 6)))
    q = pqhull.ows(positions, normals, space=space, friction=0.5, cone_edges=6, gradient=True)
    assert not q.force_closure and q.value is None
    assert q.gradient_positions is None and q.gradient_normals is None
    assert q.gradient_friction is None and q.differentiable is None
    assert "differentiable" not in repr(q)
    # Q1 and Q-infinity of the same grasp have a value (negative) and so a gradient.
    for f in (pqhull.q1, pqhull.qinf):
        other = f(positions, normals, friction=0.5, cone_edges=6, gradient=True)
        assert not other.force_closure and other.value < 0
        assert np.all(np.isfinite(other.gradient_positions))


def test_ows_batch_gradient_equals_single_grasp_gradient_row_by_row():
    """`evaluate(metric="ows", gradient=True)`: a force-closure row has ows's gradient, bit for
    bit; a row without force closure has quality NaN (no error entry) and NaN gradients,
    differentiable False; a bad row the same, with an error entry."""
    positions, normals, tangents, torsion, friction = batch_inputs(n=60, seed=21)
    positions[3], normals[3] = not_force_closure()
    bad = 9
    normals[bad, 0] = 0.0
    space = pqhull.ObjectWrenchSpace.from_disturbances(
        np.random.default_rng(4).standard_normal((12, 6)))
    args = dict(torsion=torsion, friction=friction, cone_edges=6, metric="ows", space=space)
    batch = pqhull.evaluate(positions, normals, tangents, **args, gradient=True)
    assert [row for row, _ in batch.errors] == [bad]
    plain = pqhull.evaluate(positions, normals, tangents, **args)
    np.testing.assert_array_equal(plain.quality, batch.quality)
    np.testing.assert_array_equal(plain.force_closure, batch.force_closure)
    closure = without = 0
    for i in range(60):
        if i == bad:
            continue
        q = pqhull.ows(positions[i], normals[i], tangents[i], torsion=torsion[i],
                       friction=friction[i], cone_edges=6, space=space, gradient=True)
        assert q.force_closure == batch.force_closure[i]
        if q.value is None:
            without += 1
            assert np.isnan(batch.quality[i])
            assert np.all(np.isnan(batch.gradient_positions[i]))
            assert np.all(np.isnan(batch.gradient_normals[i]))
            assert np.isnan(batch.gradient_friction[i]) and not batch.differentiable[i]
            assert q.gradient_positions is None
        else:
            closure += 1
            assert q.value == batch.quality[i]
            np.testing.assert_array_equal(q.gradient_positions, batch.gradient_positions[i])
            np.testing.assert_array_equal(q.gradient_normals, batch.gradient_normals[i])
            assert q.gradient_friction == batch.gradient_friction[i]
            assert q.differentiable == batch.differentiable[i]
    assert closure > 0 and without > 0, (closure, without)
    assert np.all(np.isnan(batch.gradient_positions[bad])) and not batch.differentiable[bad]
    one = pqhull.evaluate(positions, normals, tangents, **args, gradient=True, threads=1)
    for name in ("gradient_positions", "gradient_normals", "gradient_friction"):
        np.testing.assert_array_equal(getattr(one, name), getattr(batch, name))
    np.testing.assert_array_equal(one.differentiable, batch.differentiable)


def test_ows_exact_methods_agree_and_the_ellipsoid_is_refused():
    for g, space in ows_cases(6, seed=3):
        a = pqhull.ows(g.positions, g.normals, g.tangents, **g.kwargs(), space=space,
                       gradient=True)
        for method in ("full", "partial-rays"):
            b = pqhull.ows(g.positions, g.normals, g.tangents, **g.kwargs(), space=space,
                           gradient=True, method=method)
            assert abs(a.value - b.value) <= 1e-9 * a.value
            np.testing.assert_allclose(b.gradient_positions, a.gradient_positions, rtol=0,
                                       atol=1e-9 * (1 + np.abs(a.gradient_positions).max()))
            np.testing.assert_allclose(b.gradient_normals, a.gradient_normals, rtol=0,
                                       atol=1e-9 * (1 + np.abs(a.gradient_normals).max()))
            assert abs(b.gradient_friction - a.gradient_friction) <= 1e-9 * (
                1 + abs(a.gradient_friction))
    # A space the ellipsoid can enclose (disturbances spanning the six dimensions).
    space = pqhull.ObjectWrenchSpace.from_disturbances(
        np.random.default_rng(6).standard_normal((20, 6)))
    with pytest.raises(pqhull.InputError, match="exact method"):
        pqhull.ows(g.positions, g.normals, g.tangents, **g.kwargs(), space=space,
                   gradient=True, method="ellipsoid")
    positions, normals, _, _, friction = batch_inputs(n=3)
    with pytest.raises(pqhull.InputError, match="exact method"):
        pqhull.evaluate(positions, normals, friction=friction, cone_edges=6, metric="ows",
                        space=space, method="ellipsoid", gradient=True)
    # Without the gradient the ellipsoid still answers.
    assert pqhull.ows(g.positions, g.normals, g.tangents, **g.kwargs(), space=space,
                      method="ellipsoid").value > 0
