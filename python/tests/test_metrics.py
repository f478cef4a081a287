"""The other metrics from Python against references written here with numpy and scipy: the GWS
volume against scipy's ConvexHull of the wrenches built here, resistance against the ray's exit
through scipy's facets, the grasp matrix's singular values against numpy's SVD, and the cone
bracket around Q1 with 256 edges."""

import numpy as np
import pytest
from scipy.spatial import ConvexHull

import pqhull

MU, K = 0.6, 8


def grasp(seed, m=4):
    """m contacts on the unit sphere pushing inward, with explicit unit tangents."""
    rng = np.random.default_rng(seed)
    n = rng.standard_normal((m, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    p = -n * rng.uniform(0.5, 1.0, (m, 1))
    t = np.cross(n, rng.standard_normal(3))
    t /= np.linalg.norm(t, axis=1, keepdims=True)
    return p, n, t


def wrenches(p, n, t, mu=MU, k=K):
    """The documented wrench set: f_j = n + mu (cos(2 pi j/k) t + sin(2 pi j/k) (n x t)),
    w = [f; p x f] (torque reference the origin, scale 1)."""
    out = []
    for pi, ni, ti in zip(p, n, t):
        bi = np.cross(ni, ti)
        for j in range(k):
            a = 2 * np.pi * j / k
            f = ni + mu * (np.cos(a) * ti + np.sin(a) * bi)
            out.append(np.concatenate([f, np.cross(pi, f)]))
    return np.array(out)


def force_closure_grasps(count):
    found = []
    seed = 0
    while len(found) < count:
        p, n, t = grasp(seed)
        if pqhull.q1(p, n, t, friction=MU, cone_edges=K).force_closure:
            found.append((p, n, t))
        seed += 1
    return found


def test_volume_equals_scipy_on_the_wrenches_built_here():
    for i, (p, n, t) in enumerate(force_closure_grasps(15)):
        ours = pqhull.gws_volume(p, n, t, friction=MU, cone_edges=K)
        scipy = ConvexHull(wrenches(p, n, t)).volume
        assert ours == pytest.approx(scipy, rel=1e-9), i


def test_resistance_equals_the_ray_exit_through_scipys_facets():
    rng = np.random.default_rng(3)
    for i, (p, n, t) in enumerate(force_closure_grasps(15)):
        w = rng.standard_normal(6)
        q = pqhull.resist(p, n, t, wrench=w, friction=MU, cone_edges=K)
        eq = ConvexHull(wrenches(p, n, t)).equations  # normal . x + offset <= 0 inside
        along = eq[:, :6] @ (-w)
        exit_t = np.min(-eq[along > 0, 6] / along[along > 0])
        assert q.force_closure and q.value == pytest.approx(exit_t, rel=1e-9), i
    with pytest.raises(pqhull.Error, match="zero"):
        pqhull.resist(p, n, t, wrench=np.zeros(6), friction=MU, cone_edges=K)
    with pytest.raises(pqhull.InputError, match="6 numbers"):
        pqhull.resist(p, n, t, wrench=np.ones(5), friction=MU, cone_edges=K)


def test_singular_values_equal_numpys_svd():
    for seed in range(10):
        p, n, t = grasp(seed, m=3)
        g = np.hstack([np.vstack([np.eye(3), np.cross(pi, np.eye(3))]) for pi in p])
        expected = np.linalg.svd(g, compute_uv=False)
        s, sigma_min, isotropy = pqhull.grasp_matrix_metrics(p, n, t, friction=MU, cone_edges=K)
        np.testing.assert_allclose(s, expected, rtol=1e-12, atol=1e-14 * expected[0])
        assert sigma_min == s[5] and isotropy == pytest.approx(expected[5] / expected[0])
    two = pqhull.grasp_matrix_metrics(p[:2], n[:2], t[:2], friction=MU, cone_edges=K)
    assert two[1] <= 1e-14 * two[0][0]


def test_the_bracket_holds_q1_with_256_edges():
    for seed in range(20):
        p, n, t = grasp(seed)
        low, high = pqhull.cone_bracket(p, n, t, friction=MU, cone_edges=K)
        fine = pqhull.q1(p, n, t, friction=MU, cone_edges=256).value
        assert low <= fine <= high, seed


def test_the_batch_equals_single_calls_for_every_new_metric():
    found = force_closure_grasps(8)
    p = np.stack([g[0] for g in found] + [grasp(100)[0]])
    n = np.stack([g[1] for g in found] + [grasp(100)[1]])
    t = np.stack([g[2] for g in found] + [grasp(100)[2]])
    w = np.array([0.1, -0.3, -1.0, 0.02, 0.0, 0.05])
    resist = pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="resist", wrench=w)
    volume = pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="volume")
    smin = pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="sigma-min")
    iso = pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="isotropy")
    for i in range(len(p)):
        r = pqhull.resist(p[i], n[i], t[i], wrench=w, friction=MU, cone_edges=K)
        assert resist.force_closure[i] == r.force_closure
        assert (r.value is None and np.isnan(resist.quality[i])) or resist.quality[i] == r.value
        assert volume.quality[i] == pqhull.gws_volume(p[i], n[i], t[i], friction=MU, cone_edges=K)
        _, sigma_min, isotropy = pqhull.grasp_matrix_metrics(p[i], n[i], t[i], friction=MU,
                                                             cone_edges=K)
        assert smin.quality[i] == sigma_min and iso.quality[i] == isotropy
        q1 = pqhull.q1(p[i], n[i], t[i], friction=MU, cone_edges=K)
        assert volume.force_closure[i] == iso.force_closure[i] == q1.force_closure
    with pytest.raises(pqhull.InputError, match="needs wrench"):
        pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="resist")
    with pytest.raises(pqhull.InputError, match="only for|is for"):
        pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="q1", wrench=w)
    # For the volume and the grasp-matrix metrics the method decides the verdict (Q1's) only.
    full = pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="volume", method="full")
    assert np.array_equal(full.quality, volume.quality)
    assert np.array_equal(full.force_closure, volume.force_closure)
    with pytest.raises(pqhull.QualityError, match="partial-rays"):
        pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="volume", method="partial-rays")
    with pytest.raises(pqhull.InputError, match="zero"):
        pqhull.evaluate(p, n, t, friction=MU, cone_edges=K, metric="resist", wrench=np.zeros(6))


def soft_wrenches(p, n, t, gamma, mu=MU, k=K):
    """The documented soft wrench set: each edge f_j twice, with torque p x f_j + gamma n and
    p x f_j - gamma n (torque reference the origin, scale 1)."""
    out = []
    for pi, ni, ti, g in zip(p, n, t, gamma):
        bi = np.cross(ni, ti)
        edges = [ni + mu * (np.cos(2 * np.pi * j / k) * ti + np.sin(2 * np.pi * j / k) * bi)
                 for j in range(k)]
        for sign in (1.0, -1.0):
            out.extend(np.concatenate([f, np.cross(pi, f) + sign * g * ni]) for f in edges)
    return np.array(out)


def test_soft_contacts_equal_scipy_on_the_soft_wrenches_built_here():
    gamma = np.array([0.02, 0.05, 0.0, 0.03])
    compared = 0
    for seed in range(25):
        p, n, t = grasp(seed)
        q = pqhull.q1(p, n, t, torsion=gamma, friction=MU, cone_edges=K)
        hull = ConvexHull(soft_wrenches(p, n, t, gamma))
        if q.force_closure:
            assert q.value == pytest.approx(-hull.equations[:, 6].max(), rel=1e-9), seed
            assert pqhull.gws_volume(p, n, t, torsion=gamma, friction=MU, cone_edges=K) == \
                pytest.approx(hull.volume, rel=1e-9)
            compared += 1
    assert compared > 5
    # The batch takes (N, m) torsion (or one number) and equals the single calls.
    ps, ns, ts = (np.stack(a) for a in zip(*(grasp(s) for s in range(6))))
    batch = pqhull.evaluate(ps, ns, ts, torsion=0.04, friction=MU, cone_edges=K)
    for i in range(6):
        single = pqhull.q1(ps[i], ns[i], ts[i], torsion=[0.04] * 4, friction=MU, cone_edges=K)
        assert batch.quality[i] == single.value
    # The soft grasp matrix has a torsion column per soft contact.
    s, _, _ = pqhull.grasp_matrix_metrics(p, n, t, torsion=gamma, friction=MU, cone_edges=K)
    g = np.hstack([np.vstack([np.eye(3), np.cross(pi, np.eye(3))]) for pi in p] +
                  [np.concatenate([np.zeros(3), ni])[:, None] for ni, gi in zip(n, gamma) if gi > 0])
    np.testing.assert_allclose(s, np.linalg.svd(g, compute_uv=False), rtol=1e-12)
    with pytest.raises(pqhull.GraspError, match="contact 1.*torsion"):
        pqhull.q1(p, n, t, torsion=[0.0, -1.0, 0.0, 0.0], friction=MU, cone_edges=K)
    with pytest.raises(pqhull.InputError, match="torsion"):
        pqhull.q1(p, n, t, torsion=[0.1, 0.2], friction=MU, cone_edges=K)


def test_soft_qinf_equals_scipy_on_the_minkowski_sum_written_out_here():
    """Q-infinity with soft contacts: each contact's summand is the hull of its 2k soft wrenches
    (k for a hard one, torsion 0); the sum of one wrench per contact, every combination."""
    k, mu = 4, 0.8
    gamma = np.array([0.05, 0.0, 0.03])
    compared = 0
    for seed in range(30):
        p, n, t = grasp(seed, m=3)
        q = pqhull.qinf(p, n, t, torsion=gamma, friction=mu, cone_edges=k)
        sets = []
        for i in range(3):
            w = soft_wrenches(p[i:i + 1], n[i:i + 1], t[i:i + 1], gamma[i:i + 1], mu=mu, k=k)
            sets.append(w if gamma[i] > 0 else w[:k])
        points = np.array([a + b + c for a in sets[0] for b in sets[1] for c in sets[2]])
        assert len(points) == 8 * 4 * 8
        if q.force_closure:
            hull = ConvexHull(points)
            assert q.value == pytest.approx(-hull.equations[:, 6].max(), rel=1e-9), seed
            compared += 1
    assert compared > 3
