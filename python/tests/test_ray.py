"""pqhull.ray on a real Ray cluster: a head and a second worker node, started with `ray start`
inside a network namespace that has only loopback up (so nothing can leave the machine), with
usage statistics off. Every result is compared with the local batch, `pqhull.evaluate`, on the
same arrays: bit for bit, errors included.

Needs root and iproute2's `ip` (to make the namespace) and Ray (`pip install ray`); without them
the tests are skipped, which CI counts as a failure."""

import importlib.util
import os
import pathlib
import secrets
import shutil
import signal
import subprocess
import sys
import tempfile
import textwrap
import time

import numpy as np
import pytest

import pqhull

ROOT = pathlib.Path(__file__).resolve().parents[2]
MESH = ROOT / "data" / "meshes" / "woody.obj"
PORT = 6379  # the namespace is ours alone: no clash with anything outside it


class Cluster:
    def __init__(self, namespace, home):
        self.namespace = namespace
        self.address = f"127.0.0.1:{PORT}"
        # Ray's token authentication, with a token of the test's own, and a home of its own so
        # that nothing is read from or left in the user's ~/.ray.
        self.env = dict(os.environ, RAY_USAGE_STATS_ENABLED="0", HOME=home, RAY_TMPDIR=home,
                        RAY_AUTH_MODE="token", RAY_AUTH_TOKEN=secrets.token_hex(32))

    def run(self, *command, check=True, timeout=300, **kwargs):
        """`command` inside the namespace."""
        return subprocess.run(["ip", "netns", "exec", self.namespace, *map(str, command)],
                              env=self.env, capture_output=True, text=True, check=check,
                              timeout=timeout, **kwargs)

    def popen(self, *command):
        return subprocess.Popen(["ip", "netns", "exec", self.namespace, *map(str, command)],
                                env=self.env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True)

    def pids(self):
        out = subprocess.run(["ip", "netns", "pids", self.namespace], capture_output=True,
                             text=True).stdout
        return {int(p) for p in out.split()}

    def evaluate(self, *args, check=True):
        """`python -m pqhull.ray evaluate` against the cluster."""
        return self.run(sys.executable, "-m", "pqhull.ray", "evaluate", "--address",
                        self.address, "--node-ip-address", "127.0.0.1", *args, check=check)


def _fail(what, result):
    raise AssertionError(f"{what} failed ({result.returncode}):\n{result.stdout}\n{result.stderr}")


@pytest.fixture(scope="module")
def cluster():
    if importlib.util.find_spec("ray") is None:
        pytest.skip("Ray is not installed (pip install ray; CI installs it)")
    if os.geteuid() != 0 or shutil.which("ip") is None:
        pytest.skip("needs root and iproute2's `ip` to make a network namespace")
    namespace = f"pqhull-ray-{os.getpid()}"
    subprocess.run(["ip", "netns", "add", namespace], check=True)
    temp = tempfile.mkdtemp(prefix="pqray", dir="/tmp")  # short: Ray's sockets live under it
    c = Cluster(namespace, temp)
    ray_cli = pathlib.Path(sys.executable).with_name("ray")
    try:
        c.run("ip", "link", "set", "lo", "up")
        common = ["--node-ip-address=127.0.0.1", "--num-cpus=1", "--disable-usage-stats"]
        head = c.run(ray_cli, "start", "--head", f"--port={PORT}", "--include-dashboard=false",
                     f"--temp-dir={temp}", *common, check=False)
        if head.returncode != 0:
            _fail("ray start --head", head)
        worker = c.run(ray_cli, "start", f"--address={c.address}", *common, check=False)
        if worker.returncode != 0:
            _fail("ray start --address", worker)
        nodes = c.run(sys.executable, "-c", textwrap.dedent(f"""
            import ray, time
            ray.init(address="{c.address}", _node_ip_address="127.0.0.1", logging_level="ERROR")
            for _ in range(100):
                alive = [n for n in ray.nodes() if n["Alive"]]
                if len(alive) == 2:
                    break
                time.sleep(0.1)
            print(len(alive), int(ray.cluster_resources().get("CPU", 0)))
            """))
        assert nodes.stdout.split() == ["2", "2"], nodes.stdout + nodes.stderr
        yield c
    finally:
        for sig in (signal.SIGTERM, signal.SIGKILL):
            for pid in c.pids():
                try:
                    os.kill(pid, sig)
                except ProcessLookupError:
                    pass
            time.sleep(1.0)
        subprocess.run(["ip", "netns", "delete", namespace])
        shutil.rmtree(temp, ignore_errors=True)


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
