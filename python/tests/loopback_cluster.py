"""A Ray cluster on this machine, inside a network namespace with only loopback up: nothing it
does can leave the machine. Shared by tests/test_ray.py and benches/ray_scaling.py.

Needs root and iproute2's `ip`; Ray's usage statistics are off, its token authentication on
(a token of the cluster's own), and it has a home and temporary directory of its own, so that
nothing is read from or left in the user's ~/.ray or /tmp/ray."""

import contextlib
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

PORT = 6379  # the namespace is the cluster's alone: no clash with anything outside it


class Cluster:
    """A head node, and worker nodes added with `add_node`, all inside `namespace`."""

    def __init__(self, namespace, home):
        self.namespace = namespace
        self.home = home
        self.address = f"127.0.0.1:{PORT}"
        self.nodes = 0
        self.env = dict(os.environ, RAY_USAGE_STATS_ENABLED="0", HOME=home, RAY_TMPDIR=home,
                        RAY_AUTH_MODE="token", RAY_AUTH_TOKEN=secrets.token_hex(32))
        self.ray = pathlib.Path(sys.executable).with_name("ray")

    def run(self, *command, check=True, timeout=600, **kwargs):
        """`command` inside the namespace; raises with its output when it fails and `check`."""
        result = subprocess.run(["ip", "netns", "exec", self.namespace, *map(str, command)],
                                env=self.env, capture_output=True, text=True, timeout=timeout,
                                **kwargs)
        if check and result.returncode != 0:
            raise AssertionError(f"{' '.join(map(str, command))} failed ({result.returncode}):"
                                 f"\n{result.stdout}\n{result.stderr}")
        return result

    def popen(self, *command):
        return subprocess.Popen(["ip", "netns", "exec", self.namespace, *map(str, command)],
                                env=self.env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True)

    def pids(self):
        """Every process in the namespace (the cluster's, and drivers run in it)."""
        out = subprocess.run(["ip", "netns", "pids", self.namespace], capture_output=True,
                             text=True).stdout
        return {int(p) for p in out.split()}

    def evaluate(self, *args, check=True):
        """`python -m pqhull.ray evaluate` against the cluster."""
        return self.run(sys.executable, "-m", "pqhull.ray", "evaluate", "--address",
                        self.address, "--node-ip-address", "127.0.0.1", *map(str, args),
                        check=check)

    def add_node(self, cpus=1):
        """`ray start`: the head first, then worker nodes; waits until the node is alive."""
        common = ["--node-ip-address=127.0.0.1", f"--num-cpus={cpus}", "--disable-usage-stats"]
        if self.nodes == 0:
            self.run(self.ray, "start", "--head", f"--port={PORT}", "--include-dashboard=false",
                     f"--temp-dir={self.home}", *common)
        else:
            self.run(self.ray, "start", f"--address={self.address}", *common)
        self.nodes += 1
        alive = self.run(sys.executable, "-c", textwrap.dedent(f"""
            import ray, time
            ray.init(address="{self.address}", _node_ip_address="127.0.0.1",
                     logging_level="ERROR")
            for _ in range(100):
                alive = [n for n in ray.nodes() if n["Alive"]]
                if len(alive) == {self.nodes}:
                    break
                time.sleep(0.1)
            print(len(alive))
            """)).stdout.split()
        assert alive == [str(self.nodes)], f"{alive} nodes alive, {self.nodes} started"


def unavailable():
    """Why a loopback cluster cannot run here, or None."""
    if importlib.util.find_spec("ray") is None:
        return "Ray is not installed (pip install ray; CI installs it)"
    if os.geteuid() != 0 or shutil.which("ip") is None:
        return "needs root and iproute2's `ip` to make a network namespace"
    return None


@contextlib.contextmanager
def loopback_cluster(nodes=2, cpus_per_node=1):
    """A cluster of `nodes` nodes (the head and nodes − 1 workers); every process in its
    namespace is killed and the namespace deleted on exit."""
    namespace = f"pqhull-ray-{os.getpid()}"
    subprocess.run(["ip", "netns", "add", namespace], check=True)
    home = tempfile.mkdtemp(prefix="pqray", dir="/tmp")  # short: Ray's sockets live under it
    cluster = Cluster(namespace, home)
    try:
        cluster.run("ip", "link", "set", "lo", "up")
        for _ in range(nodes):
            cluster.add_node(cpus_per_node)
        yield cluster
    finally:
        for sig in (signal.SIGTERM, signal.SIGKILL):
            for pid in cluster.pids():
                try:
                    os.kill(pid, sig)
                except ProcessLookupError:
                    pass
            time.sleep(1.0)
        subprocess.run(["ip", "netns", "delete", namespace])
        shutil.rmtree(home, ignore_errors=True)
