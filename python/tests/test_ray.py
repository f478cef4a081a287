"""pqhull.ray on a real Ray cluster: a head and a second worker node, started with `ray start`
inside a network namespace that has only loopback up (so nothing can leave the machine), with
usage statistics off. Every result is compared with the local batch, `pqhull.evaluate`, on the
same arrays: bit for bit, errors included.

Needs root and iproute2's `ip` (to make the namespace) and Ray (`pip install ray`); without them
the tests are skipped, which CI counts as a failure."""

import os
import pathlib
import signal
import sys
import textwrap
import time

import numpy as np
import pytest

import loopback_cluster
import pqhull

ROOT = pathlib.Path(__file__).resolve().parents[2]
MESH = ROOT / "data" / "meshes" / "woody.obj"


@pytest.fixture(scope="module")
def cluster():
    reason = loopback_cluster.unavailable()
    if reason is not None:
        pytest.skip(reason)
    with loopback_cluster.loopback_cluster(nodes=2) as c:
        yield c


def grasps(n, m, seed):
    """N grasps of m contacts on the unit sphere, pushing inward."""
    rng = np.random.default_rng(seed)
    normals = rng.standard_normal((n, m, 3))
    normals /= np.linalg.norm(normals, axis=2, keepdims=True)
    return -normals * rng.uniform(0.5, 1.0, (n, m, 1)), normals


def q1_dataset(directory, n=1500):
    """Four objects that differ in every way a set can: contact count, friction per grasp,
    tangents, torque frame, bad rows far from the first chunk."""
    sets = {}
    p, nrm = grasps(n, 3, 1)
    sets["a_three_contacts"] = dict(positions=p, normals=nrm, friction=0.7, cone_edges=8)
    p, nrm = grasps(n, 4, 2)
    sets["b_friction_per_grasp"] = dict(positions=p, normals=nrm, cone_edges=6,
                                        friction=np.linspace(0.1, 1.0, n))
    p, nrm = grasps(n // 2, 5, 3)
    tangents = np.cross(nrm, [0.0, 0.0, 1.0])
    tangents /= np.linalg.norm(tangents, axis=2, keepdims=True)
    sets["c_tangents_and_frame"] = dict(positions=p, normals=nrm, tangents=tangents,
                                        friction=0.4, cone_edges=5,
                                        torque_reference=np.array([0.1, -0.2, 0.05]),
                                        torque_scale=1.7)
    p, nrm = grasps(n, 4, 4)
    nrm[1234, 2] = 0.0
    p[777, 0, 1] = np.nan
    sets["d_bad_rows"] = dict(positions=p, normals=nrm, friction=0.5, cone_edges=8)
    for name, arrays in sets.items():
        np.savez(directory / f"{name}.npz", **arrays)
    return sets


def local(arrays, **options):
    """The reference: pqhull.evaluate on one set, on this machine."""
    args = dict(arrays)
    space = args.pop("space", None)
    return pqhull.evaluate(args.pop("positions"), args.pop("normals"), args.pop("tangents", None),
                           space=space, **args, **options)


def assert_equal(results, sets, **options):
    assert [r.name for r in results] == list(sets)
    for r, (name, arrays) in zip(results, sets.items()):
        expected = local(arrays, **options)
        assert np.array_equal(r.quality, expected.quality, equal_nan=True), name
        assert np.array_equal(r.force_closure, expected.force_closure), name
        assert r.errors == expected.errors, name


def test_a_dataset_on_two_nodes_equals_the_local_batch(cluster, tmp_path):
    from pqhull import ray as pqray

    sets = q1_dataset(tmp_path)
    out = tmp_path / "q1.npz"
    result = cluster.evaluate(tmp_path, "--output", out, "--chunk-size", "200")
    assert "5,250 / 5,250 grasps (100%)" in result.stderr, result.stderr
    results = pqray.load_results(out)
    assert_equal(results, sets)
    bad = results[3].errors
    assert [row for row, _ in bad] == [777, 1234]
    assert bad[1][1].startswith("row 1234: contact 2")
    assert 0 < sum(r.force_closure.sum() for r in results) < 5250

    out = tmp_path / "qinf.npz"
    cluster.evaluate(*sorted(tmp_path.glob("[ab]_*.npz")), "--output", out, "--metric", "qinf",
                     "--chunk-size", "300", "--quiet")
    assert_equal(pqray.load_results(out), {k: sets[k] for k in list(sets)[:2]}, metric="qinf")


def test_object_wrench_spaces_built_once_and_shared(cluster, tmp_path):
    """Q_OWS of a mesh object (its space built by a task from the file's arrays), a task wrench
    space, and, through the Python API, a space built by the caller and pickled."""
    from pqhull import ray as pqray

    vertices, faces = pqhull.load_mesh(MESH)
    p, nrm = grasps(300, 4, 5)
    p *= 0.1
    disturbances = np.random.default_rng(6).standard_normal((40, 6))
    np.savez(tmp_path / "mesh.npz", positions=p, normals=nrm, friction=0.5, cone_edges=8,
             vertices=vertices, faces=faces, ows_friction=0.5, ows_edges=6)
    np.savez(tmp_path / "task.npz", positions=p[:200], normals=nrm[:200], friction=0.8,
             cone_edges=8, disturbances=disturbances)
    out = tmp_path / "ows.npz"
    cluster.evaluate(tmp_path / "mesh.npz", tmp_path / "task.npz", "--output", out,
                     "--metric", "ows", "--chunk-size", "64", "--quiet")
    mesh_space = pqhull.ObjectWrenchSpace.from_mesh(MESH, friction=0.5, cone_edges=6)
    task_space = pqhull.ObjectWrenchSpace.from_disturbances(disturbances)
    sets = {
        "mesh": dict(positions=p, normals=nrm, friction=0.5, cone_edges=8, space=mesh_space),
        "task": dict(positions=p[:200], normals=nrm[:200], friction=0.8, cone_edges=8,
                     space=task_space),
    }
    results = pqray.load_results(out)
    assert_equal(results, sets, metric="ows")
    assert results[0].force_closure.any() and results[1].force_closure.any()

    script = textwrap.dedent(f"""
        import numpy as np, pqhull
        from pqhull import ray as pqray
        p, n = np.load("{tmp_path}/in.npz")["p"], np.load("{tmp_path}/in.npz")["n"]
        space = pqhull.ObjectWrenchSpace.from_mesh("{MESH}", friction=0.5, cone_edges=6)
        sets = [pqray.GraspSet("prebuilt", p, n, friction=0.5, cone_edges=8, space=space)]
        results = pqray.evaluate_dataset(sets, metric="ows", chunk_size=50,
                                         address="{cluster.address}", node_ip_address="127.0.0.1")
        pqray.save_results("{tmp_path}/api.npz", results)
        """)
    np.savez(tmp_path / "in.npz", p=p, n=nrm)
    cluster.run(sys.executable, "-c", script)
    assert_equal(pqray.load_results(tmp_path / "api.npz"), {"prebuilt": sets["mesh"]},
                 metric="ows")


def test_soft_contacts_and_every_metric_on_the_cluster(cluster, tmp_path):
    """Issue 16's additions through Ray: torsion per contact (from the file, or --torsion for a
    file without it) and the metrics resist (--wrench), volume, sigma-min and isotropy, each
    equal to the local batch."""
    from pqhull import ray as pqray

    p, nrm = grasps(400, 3, 11)
    torsion = np.random.default_rng(12).uniform(0.0, 0.05, (400, 3))
    np.savez(tmp_path / "soft.npz", positions=p, normals=nrm, friction=0.6, cone_edges=6,
             torsion=torsion)
    np.savez(tmp_path / "plain.npz", positions=p[:150], normals=nrm[:150], friction=0.6,
             cone_edges=6)
    sets = {
        "plain": dict(positions=p[:150], normals=nrm[:150], friction=0.6, cone_edges=6,
                      torsion=0.02),
        "soft": dict(positions=p, normals=nrm, friction=0.6, cone_edges=6, torsion=torsion),
    }
    wrench = "0.1,-0.3,-1,0.02,0,0.05"
    for metric, extra, options in [
        ("resist", ["--wrench", wrench], dict(wrench=[0.1, -0.3, -1, 0.02, 0, 0.05])),
        ("qinf", [], {}),
        ("isotropy", [], {}),
        ("volume", ["--method", "full"], dict(method="full")),
    ]:
        out = tmp_path / f"{metric}.npz"
        cluster.evaluate(tmp_path / "plain.npz", tmp_path / "soft.npz", "--output", out,
                         "--metric", metric, "--torsion", "0.02", "--chunk-size", "128",
                         "--quiet", *extra)
        assert_equal(pqray.load_results(out), sets, metric=metric, **options)
    result = cluster.evaluate(tmp_path / "soft.npz", "--output", tmp_path / "o.npz", "--metric",
                              "resist", "--wrench", "0,0,0,0,0,0", check=False)
    assert result.returncode == 2 and "zero" in result.stderr, result.stderr
    assert not (tmp_path / "o.npz").exists()


def test_a_worker_killed_mid_run_loses_nothing(cluster, tmp_path):
    from pqhull import ray as pqray

    p, nrm = grasps(16000, 4, 7)  # about 4 s of work: 80 chunks of 50 ms
    np.savez(tmp_path / "big.npz", positions=p, normals=nrm, friction=0.5, cone_edges=8)
    out = tmp_path / "big_out.npz"
    driver = cluster.popen(sys.executable, "-m", "pqhull.ray", "evaluate", "--address",
                           cluster.address, "--node-ip-address", "127.0.0.1", tmp_path / "big.npz",
                           "--output", out, "--chunk-size", "200")
    killed = None
    deadline = time.monotonic() + 120
    while killed is None and driver.poll() is None and time.monotonic() < deadline:
        for pid in cluster.pids():
            try:
                title = pathlib.Path(f"/proc/{pid}/cmdline").read_bytes()
            except OSError:
                continue
            if title.startswith(b"ray::_evaluate_chunk"):
                os.kill(pid, signal.SIGKILL)
                killed = pid
                break
        time.sleep(0.01)
    stdout, stderr = driver.communicate(timeout=300)
    assert killed is not None, "no worker was seen running a chunk\n" + stderr
    assert driver.returncode == 0, stderr
    assert "16,000 / 16,000 grasps (100%)" in stderr, stderr
    results = pqray.load_results(out)
    assert_equal(results, {"big": dict(positions=p, normals=nrm, friction=0.5, cone_edges=8)})
    print(f"killed worker {killed} mid-run; all 16,000 results present and equal")


def test_bad_input_is_named_before_anything_runs(cluster, tmp_path):
    p, nrm = grasps(10, 4, 8)
    np.savez(tmp_path / "typo.npz", positions=p, normals=nrm, friction=0.5, cone_edge=8)
    result = cluster.evaluate(tmp_path / "typo.npz", "--output", tmp_path / "o.npz", check=False)
    assert result.returncode == 2
    assert "typo.npz: unknown arrays ['cone_edge']" in result.stderr, result.stderr
    np.savez(tmp_path / "shape.npz", positions=p, normals=nrm[:, :3], friction=0.5, cone_edges=8)
    result = cluster.evaluate(tmp_path / "shape.npz", "--output", tmp_path / "o.npz", check=False)
    assert result.returncode == 2
    assert "grasp set 'shape': normals have shape (10, 3, 3)" in result.stderr, result.stderr
    np.savez(tmp_path / "nospace.npz", positions=p, normals=nrm, friction=0.5, cone_edges=8)
    result = cluster.evaluate(tmp_path / "nospace.npz", "--output", tmp_path / "o.npz",
                              "--metric", "ows", check=False)
    assert result.returncode == 2 and "needs a wrench space" in result.stderr, result.stderr
    assert not (tmp_path / "o.npz").exists()


def test_local_address_starts_and_ends_its_own_cluster(cluster, tmp_path):
    from pqhull import ray as pqray

    p, nrm = grasps(500, 4, 9)
    np.savez(tmp_path / "one.npz", positions=p, normals=nrm, friction=0.5, cone_edges=8)
    cluster.run(sys.executable, "-m", "pqhull.ray", "evaluate", "--address", "local",
                tmp_path / "one.npz", "--output", tmp_path / "local.npz", "--quiet")
    assert_equal(pqray.load_results(tmp_path / "local.npz"),
                 {"one": dict(positions=p, normals=nrm, friction=0.5, cone_edges=8)})


def test_open_grasp_set_checks_headers_and_reads_no_array(tmp_path, monkeypatch):
    """A dataset file is opened from its .npy headers only (so the driver holds one file's
    arrays at a time), with the same checks as a loaded set; it is read on load()."""
    from pqhull import ray as pqray

    p, nrm = grasps(30, 4, 13)
    np.savez(tmp_path / "a.npz", positions=p, normals=nrm, friction=0.5, torsion=0.01)
    np.savez(tmp_path / "bad.npz", positions=p, normals=nrm, friction=np.ones(29), cone_edges=8)
    real_load = np.load

    def no_load(*args, **kwargs):
        raise AssertionError("an array was read")

    monkeypatch.setattr(np, "load", no_load)
    opened = pqray.open_grasp_set(tmp_path / "a.npz", cone_edges=6)
    assert len(opened) == 30 and opened.name == "a"
    opened.check(needs_space=False)
    with pytest.raises(pqhull.InputError, match="needs a wrench space"):
        opened.check(needs_space=True)
    with pytest.raises(pqhull.InputError, match="friction must be one number or one per grasp"):
        pqray.open_grasp_set(tmp_path / "bad.npz").check(needs_space=False)
    with pytest.raises(pqhull.InputError, match="no 'cone_edges'"):
        pqray.open_grasp_set(tmp_path / "a.npz")
    monkeypatch.setattr(np, "load", real_load)
    loaded = opened.load()
    assert loaded.cone_edges == 6 and float(loaded.torsion) == 0.01
    assert np.array_equal(loaded.positions, p)
