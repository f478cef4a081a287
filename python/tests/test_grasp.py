"""Grasps as arrays: the batch equals single calls and `pqh grasp`, bit for bit; the GIL is
released; bad rows are named."""

import json
import os
import pathlib
import subprocess
import threading
import time

import numpy as np
import pytest

import pqhull

ROOT = pathlib.Path(__file__).resolve().parents[2]


def random_grasps(n, m=4, seed=1):
    """N grasps of m contacts on the unit sphere, pushing inward."""
    rng = np.random.default_rng(seed)
    normals = rng.standard_normal((n, m, 3))
    normals /= np.linalg.norm(normals, axis=2, keepdims=True)
    positions = -normals * rng.uniform(0.5, 1.0, (n, m, 1))
    return positions, normals


def test_batch_equals_single_calls_bit_for_bit():
    positions, normals = random_grasps(200)
    friction = np.linspace(0.2, 0.9, 200)
    for metric, single in (("q1", pqhull.q1), ("qinf", pqhull.qinf)):
        batch = pqhull.evaluate(positions, normals, friction=friction, cone_edges=8, metric=metric)
        assert batch.errors == []
        assert batch.quality.shape == (200,) and batch.force_closure.dtype == bool
        for i in range(200):
            q = single(positions[i], normals[i], friction=friction[i], cone_edges=8)
            assert batch.quality[i] == q.value, (metric, i)
            assert batch.force_closure[i] == q.force_closure
        assert 0 < batch.force_closure.sum() < 200


def pqh_binary():
    explicit = os.environ.get("PQHULL_PQH")
    if explicit:
        return explicit
    default = ROOT / "target" / "release" / "pqh"
    return str(default) if default.exists() else None


def test_batch_equals_the_cli():
    pqh = pqh_binary()
    if pqh is None:
        pytest.skip("no pqh binary: build it (cargo build --release) or set PQHULL_PQH")
    positions, normals = random_grasps(50, seed=2)
    lines = []
    for p, n in zip(positions, normals):
        contacts = [{"position": a.tolist(), "normal": b.tolist()} for a, b in zip(p, n)]
        lines.append(json.dumps({"contacts": contacts, "friction": 0.5, "cone_edges": 8}))
    out = subprocess.run([pqh, "grasp", "--quiet"], input="\n".join(lines), text=True,
                         capture_output=True, check=True).stdout
    cli = [json.loads(line) for line in out.splitlines()]
    batch = pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8)
    assert [c["quality"] for c in cli] == batch.quality.tolist()
    assert [c["force_closure"] for c in cli] == batch.force_closure.tolist()


def test_the_gil_is_released():
    positions, normals = random_grasps(1500, seed=3)

    def run():
        pqhull.evaluate(positions, normals, friction=0.5, cone_edges=16, threads=1)

    run()  # warm up
    started = time.perf_counter()
    run()
    one = time.perf_counter() - started
    threads = [threading.Thread(target=run) for _ in range(2)]
    started = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    two = time.perf_counter() - started
    print(f"one call {one:.3f} s, two calls on two threads {two:.3f} s: {two / one:.2f}x")
    if (os.cpu_count() or 1) < 2:
        pytest.skip("one core: two threads cannot overlap")  # a skip CI fails on, not a pass
    assert two < 1.6 * one, f"two threads took {two / one:.2f}x one call"


def test_bad_rows_are_named_and_the_others_kept():
    positions, normals = random_grasps(5, seed=4)
    normals[1, 2] = 0.0  # a zero normal
    positions[3, 0, 1] = np.nan
    friction = np.array([0.5, 0.5, 0.5, 0.5, -0.1])
    batch = pqhull.evaluate(positions, normals, friction=friction, cone_edges=8)
    rows = [row for row, _ in batch.errors]
    assert rows == [1, 3, 4]
    messages = dict(batch.errors)
    assert "row 1: contact 2" in messages[1] and "zero" in messages[1].lower()
    assert "row 3: contact 0" in messages[3]
    assert "row 4" in messages[4] and "friction" in messages[4].lower()
    assert np.isnan(batch.quality[[1, 3, 4]]).all() and not batch.force_closure[[1, 3, 4]].any()
    good = [0, 2]
    for i in good:
        q = pqhull.q1(positions[i], normals[i], friction=0.5, cone_edges=8)
        assert batch.quality[i] == q.value


@pytest.mark.parametrize(
    "call,match",
    [
        (lambda p, n: pqhull.evaluate(p[0], n, friction=0.5, cone_edges=8), "3 dimensions"),
        (lambda p, n: pqhull.evaluate(p, n[:, :2], friction=0.5, cone_edges=8), "shape of positions"),
        (lambda p, n: pqhull.evaluate(p, n, friction=[0.5, 0.5], cone_edges=8), "one per grasp"),
        (lambda p, n: pqhull.evaluate(p, n, friction=0.5, cone_edges=8, metric="q2"), "metric"),
        (lambda p, n: pqhull.evaluate(p, n, friction=0.5, cone_edges=8, threads=0), "threads"),
        (lambda p, n: pqhull.q1(p[0], n[0] * 0, friction=0.5, cone_edges=8), "contact 0"),
        (lambda p, n: pqhull.q1(p[0], n[0], friction=-0.5, cone_edges=8), "friction"),
        (lambda p, n: pqhull.q1(p[0][:, :2], n[0], friction=0.5, cone_edges=8), r"shape \(m, 3\)"),
    ],
)
def test_bad_input_raises_the_typed_error(call, match):
    positions, normals = random_grasps(3, seed=5)
    with pytest.raises(pqhull.Error, match=match):
        call(positions, normals)


MESH = ROOT / "data" / "meshes" / "woody.obj"


def test_ows_batch_equals_single_calls_and_the_cli():
    space = pqhull.ObjectWrenchSpace.from_mesh(str(MESH), friction=0.5, cone_edges=6)
    assert len(space) > 0 and space.torque_frame is not None
    positions, normals = random_grasps(40, seed=6)
    positions *= 0.1
    batch = pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8, metric="ows", space=space)
    assert batch.errors == []
    for i in range(40):
        q = pqhull.ows(positions[i], normals[i], space=space, friction=0.5, cone_edges=8)
        full = pqhull.ows(positions[i], normals[i], space=space, friction=0.5, cone_edges=8,
                          method="full")
        assert q.force_closure == batch.force_closure[i] == full.force_closure
        if q.force_closure:
            assert batch.quality[i] == q.value
            assert q.value == pytest.approx(full.value, rel=1e-9)
        else:
            assert q.value is None and np.isnan(batch.quality[i])
    assert batch.force_closure.any()
    pqh = pqh_binary()
    if pqh is None:
        pytest.skip("no pqh binary: build it (cargo build --release) or set PQHULL_PQH")
    lines = []
    for p, n in zip(positions, normals):
        contacts = [{"position": a.tolist(), "normal": b.tolist()} for a, b in zip(p, n)]
        lines.append(json.dumps({"contacts": contacts, "friction": 0.5, "cone_edges": 8}))
    out = subprocess.run([pqh, "grasp", "--quiet", "--metric", "ows", "--mesh", str(MESH),
                          "--ows-friction", "0.5", "--ows-edges", "6"],
                         input="\n".join(lines), text=True, capture_output=True, check=True).stdout
    cli = [json.loads(line) for line in out.splitlines()]
    assert [c["force_closure"] for c in cli] == batch.force_closure.tolist()
    for c, v in zip(cli, batch.quality.tolist()):
        assert (c["quality"] is None and np.isnan(v)) or c["quality"] == v


def test_task_wrench_space_from_arrays_and_disturbances():
    cube_v = np.array([[x, y, z] for x in (-0.1, 0.1) for y in (-0.1, 0.1) for z in (-0.1, 0.1)])
    faces = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
             [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]
    space = pqhull.ObjectWrenchSpace.from_arrays(cube_v, faces, friction=0.5, cone_edges=4)
    assert len(space) > 0
    single = pqhull.ObjectWrenchSpace.from_disturbances([[0.0, 0.0, -1.0, 0.0, 0.0, 0.0]])
    assert single.torque_frame is None and len(single) == 1
    positions, normals = random_grasps(10, seed=7)
    a = pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8, metric="ows", space=single)
    b = pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8, metric="ows", space=single,
                        method="full")
    np.testing.assert_allclose(a.quality, b.quality, rtol=1e-9)
    with pytest.raises(pqhull.InputError, match="needs space"):
        pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8, metric="ows")
    with pytest.raises(pqhull.QualityError, match="does not compute"):
        pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8, metric="ows",
                        space=single, method="qhull")
    with pytest.raises(pqhull.Error, match="shape"):
        pqhull.ObjectWrenchSpace.from_disturbances(np.zeros((3, 5)))


def test_spaces_pickle_exactly_and_load_mesh_matches_from_mesh():
    import pickle

    vertices, faces = pqhull.load_mesh(MESH)
    assert vertices.shape[1] == 3 and faces.shape[1] == 3 and faces.dtype == np.int64
    from_file = pqhull.ObjectWrenchSpace.from_mesh(MESH, friction=0.5, cone_edges=6)
    from_arrays = pqhull.ObjectWrenchSpace.from_arrays(vertices, faces, friction=0.5,
                                                       cone_edges=6)
    assert np.array_equal(from_file.disturbances, from_arrays.disturbances)
    assert from_file.torque_frame == from_arrays.torque_frame
    task = pqhull.ObjectWrenchSpace.from_disturbances(
        np.random.default_rng(10).standard_normal((30, 6)))
    positions, normals = random_grasps(60, seed=11)
    positions *= 0.1
    for space in (from_file, task):
        copy = pickle.loads(pickle.dumps(space))
        assert copy.torque_frame == space.torque_frame and len(copy) == len(space)
        assert np.array_equal(copy.disturbances, space.disturbances)
        a = pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8, metric="ows",
                            space=space)
        b = pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8, metric="ows",
                            space=copy)
        assert np.array_equal(a.quality, b.quality, equal_nan=True) and a.force_closure.any()
    with pytest.raises(pqhull.InputError, match="description"):
        pqhull.ObjectWrenchSpace._from_state(np.eye(6), "{not json")
    with pytest.raises(pqhull.InputError, match="no such file|No such file|cannot"):
        pqhull.load_mesh(ROOT / "no_such_mesh.obj")
