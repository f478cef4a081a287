"""The descent grasp planner from Python (`pqhull.plan_descent`, the library's
`plan::plan_descent`, `pqh plan --planner descent`), checked on a 1 x 0.4 x 0.2 bar:

* the planner's own guarantees: no planned grasp worse than its start (by force closure, then
  value), contacts on the bar's surface with its inward face normals, the evaluation budget;
* independently of pqhull: Q1 of every force-closure planned grasp rebuilt from the wrench
  formula and scipy.spatial.ConvexHull (`wrenches` and `scipy_q1` of test_gradient.py), by the
  partial and the full method, and Q_OWS likewise (`scipy_ows`) against the space's
  disturbances;
* the refusals: metrics it does not climb, the library's bounds, bad arguments;
* the same plan as `pqh plan --planner descent --json` (its best grasp), when the binary is there
  (as test_grasp.py's CLI test).
"""

import json
import subprocess
import threading
import time

import numpy as np
import pytest

import pqhull
from test_gradient import scipy_ows, scipy_q1, wrenches
from test_grasp import pqh_binary

MU, K = 0.5, 8
HALF = np.array([0.5, 0.2, 0.1])  # the bar's half extents
# The bar of cli/tests/pqh/cli_plan.rs (bar_obj), its faces 0-based: counter-clockwise seen from
# outside.
VERTICES = np.array([[-0.5, -0.2, -0.1], [0.5, -0.2, -0.1], [0.5, 0.2, -0.1], [-0.5, 0.2, -0.1],
                     [-0.5, -0.2, 0.1], [0.5, -0.2, 0.1], [0.5, 0.2, 0.1], [-0.5, 0.2, 0.1]])
FACES = np.array([[0, 3, 2], [0, 2, 1], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                  [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])
BAR = (VERTICES, FACES)


def plan(**kwargs):
    args = dict(contacts=4, friction=MU, cone_edges=K, starts=4, evaluations=20)
    args.update(kwargs)
    return pqhull.plan_descent(args.pop("mesh", BAR), **args)


def grasp_wrenches(p, i):
    """Planned grasp i's primitive wrenches, built here (default tangents, the run's frame)."""
    return wrenches(p.positions[i], p.normals[i], None, None, MU, K, p.torque_reference,
                    p.torque_scale)


def assert_never_worse(p):
    for i in range(len(p)):
        now = (bool(p.force_closure[i]), p.values[i])
        start = (bool(p.start_force_closure[i]), p.start_values[i])
        assert now >= start, (i, now, start)
        if p.start_force_closure[i]:
            assert p.force_closure[i] and p.values[i] >= p.start_values[i]


def test_q1_plans_are_never_worse_than_their_starts_and_lie_on_the_surface():
    p = plan()
    assert len(p) == 4 and p.metric == "q1" and p.method == "partial"
    assert p.positions.shape == (4, 4, 3) and p.normals.shape == (4, 4, 3)
    for name in ("values", "start_values", "force_closure", "start_force_closure",
                 "evaluations", "steps"):
        assert getattr(p, name).shape == (4,), name
    assert p.force_closure.dtype == np.bool_ and p.evaluations.dtype == np.int64
    assert_never_worse(p)
    assert p.force_closure.any()
    # The budget, and the run's totals.
    assert np.all((1 <= p.evaluations) & (p.evaluations <= 20))
    assert p.total_evaluations == p.evaluations.sum()
    assert np.all(p.steps >= 0)
    assert set(p.stop) <= {"step", "evaluations", "stationary"} and len(p.stop) == 4
    assert min(p.quality_s, p.gradient_s, p.other_s) >= 0 and p.facets_created > 0
    assert p.best == int(np.argmax(np.where(p.force_closure, p.values, -np.inf)))
    # The mesh's torque frame: centre of mass (the origin) and largest vertex distance.
    assert p.torque_reference.shape == (3,)
    assert np.allclose(p.torque_reference, 0.0, atol=1e-15)
    assert p.torque_scale == pytest.approx(np.linalg.norm(HALF), rel=1e-12)
    # Every contact on a face of the bar, with that face's inward normal.
    for position, normal in zip(p.positions.reshape(-1, 3), p.normals.reshape(-1, 3)):
        assert np.all(np.abs(position) <= HALF + 1e-12), position
        faces = [(a, np.sign(position[a])) for a in range(3)
                 if abs(abs(position[a]) - HALF[a]) <= 1e-12]
        inward = [-s * np.eye(3)[a] for a, s in faces]
        assert any(np.allclose(normal, n, atol=1e-12) for n in inward), (position, normal)
    # The same seed, the same plan; another seed, other starts.
    again = plan()
    assert np.array_equal(again.positions, p.positions)
    assert np.array_equal(again.values, p.values)
    other = plan(seed=2)
    assert not np.array_equal(other.start_values, p.start_values)


@pytest.mark.parametrize("method", ["partial", "full"])
def test_q1_values_equal_scipy_on_the_wrenches_built_here(method):
    p = plan(method=method, starts=6)
    assert p.method == method
    closure = np.flatnonzero(p.force_closure)
    assert len(closure) >= 3, p
    for i in closure:
        reference = scipy_q1(grasp_wrenches(p, i))
        assert p.values[i] == pytest.approx(reference, rel=1e-9), (method, i)
        # And pqhull.q1 on the grasp in the reported frame gives the planner's value.
        q = pqhull.q1(p.positions[i], p.normals[i], friction=MU, cone_edges=K,
                      torque_reference=p.torque_reference, torque_scale=p.torque_scale)
        assert q.force_closure
        assert q.value == pytest.approx(p.values[i], rel=1e-12, abs=0)
    # The starts that were force closure, too.
    for i in np.flatnonzero(p.start_force_closure):
        assert p.start_values[i] > 0


def test_partial_and_full_climb_from_the_same_starts():
    partial, full = plan(starts=6), plan(starts=6, method="full")
    assert np.array_equal(partial.start_force_closure, full.start_force_closure)
    assert np.allclose(partial.start_values, full.start_values, rtol=1e-12, atol=1e-15)


def test_ows_plans_from_the_mesh_own_space_equal_scipy():
    p = plan(metric="ows", starts=3)
    assert p.metric == "ows" and len(p) == 3
    assert np.all(np.isfinite(p.values))
    assert_never_worse(p)
    assert p.force_closure.any()
    # Built with the grasps' friction: the same plan as with the space given.
    space = pqhull.ObjectWrenchSpace.from_arrays(VERTICES, FACES, friction=MU, cone_edges=K)
    given = plan(metric="ows", starts=3, space=space)
    assert np.array_equal(given.values, p.values)
    assert np.array_equal(given.positions, p.positions)
    reference, scale = space.torque_frame
    assert np.array_equal(p.torque_reference, reference) and p.torque_scale == scale
    for i in np.flatnonzero(p.force_closure):
        assert p.values[i] > 0
        expected = scipy_ows(grasp_wrenches(p, i), space.disturbances)
        assert p.values[i] == pytest.approx(expected, rel=1e-9), i
        q = pqhull.ows(p.positions[i], p.normals[i], space=space, friction=MU, cone_edges=K)
        assert q.value == pytest.approx(p.values[i], rel=1e-12, abs=0)


def test_screened_ows_plans_use_their_evaluations_and_equal_scipy():
    space = pqhull.ObjectWrenchSpace.from_arrays(VERTICES, FACES, friction=MU, cone_edges=K)
    p = plan(metric="ows", starts=2, evaluations=40, screen=8, space=space)
    assert_never_worse(p)
    # Screening and climbing again after a stop spend the budget (a few evaluations, too few
    # for a screen and a step, may be left), where an unscreened climb may stop early.
    assert np.all(p.evaluations <= 40) and np.all(p.evaluations >= 36)
    for i in np.flatnonzero(p.force_closure):
        expected = scipy_ows(grasp_wrenches(p, i), space.disturbances)
        assert p.values[i] == pytest.approx(expected, rel=1e-9), i


@pytest.mark.parametrize("metric,with_zero_wrench", [("qinf", False), ("qinf0", True)])
def test_qinf_plans_equal_pqhull_qinf(metric, with_zero_wrench):
    p = plan(metric=metric, starts=3)
    assert p.metric == metric
    assert_never_worse(p)
    for i in range(len(p)):
        q = pqhull.qinf(p.positions[i], p.normals[i], friction=MU, cone_edges=K,
                        torque_reference=p.torque_reference, torque_scale=p.torque_scale,
                        with_zero_wrench=with_zero_wrench)
        assert q.force_closure == p.force_closure[i]
        assert q.value == pytest.approx(p.values[i], rel=1e-12, abs=1e-15)


def test_the_mesh_may_be_a_path_or_arrays(tmp_path):
    obj = tmp_path / "bar.obj"
    obj.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in VERTICES)
                   + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in FACES))
    arrays = plan()
    for mesh in (obj, str(obj), pqhull.load_mesh(obj), [VERTICES.tolist(), FACES.tolist()]):
        p = plan(mesh=mesh)
        assert np.array_equal(p.positions, arrays.positions), type(mesh)
        assert np.array_equal(p.values, arrays.values), type(mesh)


@pytest.mark.parametrize("kwargs,match", [
    (dict(metric="volume"), "volume"),
    (dict(metric="sigma-min"), "sigma-min"),
    (dict(metric="resist"), "resist"),
    (dict(metric="nope"), "unknown metric"),
    (dict(starts=0), "at least one"),
    (dict(evaluations=0), "at least one"),
    (dict(contacts=0), "at least one"),
    (dict(evaluations=10_001), "10001 evaluations per start are too many"),
    (dict(starts=100_001), "100001 starts are too many"),
    (dict(screen=0), "at least one"),
    (dict(screen=10_001), "10001 candidates screened per start are too many"),
    (dict(metric="ows", evaluations=1), "too few"),
    (dict(contacts=257), "contacts"),
    (dict(method="ellipsoid"), "partial\" or \"full"),
    (dict(method="nope"), "unknown method"),
    (dict(starts=-1), "starts must be an integer"),
    (dict(seed=2**64), "seed must be an integer"),
    (dict(starts=2.5), "starts must be an integer"),
    (dict(friction=-1.0), "friction"),
    (dict(mesh=VERTICES), "mesh must be"),
    (dict(mesh="/nonexistent/bar.obj"), "bar.obj"),
    (dict(mesh=(VERTICES, FACES[:, :2])), "faces"),
])
def test_refusals_are_value_errors_with_the_library_message(kwargs, match):
    with pytest.raises(ValueError, match=match) as raised:
        plan(**kwargs)
    assert isinstance(raised.value, pqhull.Error)


def test_space_is_for_ows_only():
    space = pqhull.ObjectWrenchSpace.from_arrays(VERTICES, FACES, friction=MU, cone_edges=K)
    with pytest.raises(pqhull.InputError, match="space= is for metric \"ows\""):
        plan(space=space)


def test_bounds_are_refused_before_any_work():
    # The largest number of starts the planner would refuse at once: a refusal, not a run.
    started = time.perf_counter()
    with pytest.raises(pqhull.InputError):
        plan(starts=100_001, evaluations=10_000)
    with pytest.raises(pqhull.InputError):
        plan(metric="ows", starts=100_001)
    assert time.perf_counter() - started < 1.0


def test_the_gil_is_released_while_planning():
    done = threading.Event()
    ticks = []

    def run():
        plan(starts=12, evaluations=200)
        done.set()

    worker = threading.Thread(target=run)
    started = time.perf_counter()
    worker.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - started
    gaps = np.diff([started] + ticks + [time.perf_counter()])
    print(f"plan {elapsed:.3f} s, longest pause of this thread {gaps.max():.3f} s")
    assert elapsed > 0.1, "the plan is too short to tell"
    # With the GIL held, this thread would stand still for the whole plan.
    assert gaps.max() < 0.5 * elapsed


def test_the_same_plan_as_the_cli(tmp_path):
    pqh = pqh_binary()
    if pqh is None:
        pytest.skip("no pqh binary: build it (cargo build --release) or set PQHULL_PQH")
    obj = tmp_path / "bar.obj"
    obj.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in VERTICES)
                   + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in FACES))
    for metric in ("q1", "ows"):
        out = subprocess.run(
            [pqh, "plan", "--planner", "descent", "--mesh", str(obj), "--metric", metric,
             "--starts", "4", "--evaluations", "20", "--contacts", "4", "--friction", str(MU),
             "--edges", str(K), "--seed", "3", "--json"],
            capture_output=True, text=True, check=True).stdout
        cli = json.loads(out)
        for method in ("partial", "full"):
            p = plan(mesh=obj, metric=metric, seed=3, method=method)
            report = cli[method]
            assert report["evaluations"] == p.total_evaluations, (metric, method)
            assert report["force_closure"] == int(p.force_closure.sum())
            best = report["best"]
            assert best["start"] == p.best
            assert best["value"] == p.values[p.best]
            assert best["steps"] == p.steps[p.best]
            assert best["evaluations"] == p.evaluations[p.best]
            assert best["stop"] == p.stop[p.best]
            positions = [c["position"] for c in best["grasp"]["contacts"]]
            assert np.array_equal(positions, p.positions[p.best])
