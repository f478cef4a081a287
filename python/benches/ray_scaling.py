"""Ray throughput with one and with two worker nodes on this machine, against the library's own
batch on one core.

Run it as root (it makes a loopback-only network namespace for the cluster), after
`pip install './python[ray]'`:

    python python/benches/ray_scaling.py [--objects 8] [--grasps 5000] [--rounds 3]

It writes a dataset of `objects` .npz files (random Q1 grasps of 4 contacts on the unit sphere,
k = 8), starts a head node with one CPU, evaluates the dataset with `python -m pqhull.ray
evaluate` (`rounds` times; the median is kept), adds a second node with one CPU, and evaluates
again. Throughput counts the evaluation only (the driver's "in … s" line: from submitting the
first chunk to the last result), not Ray's start-up. Each run's results are checked equal to the
local batch before its time is used.
"""

import argparse
import pathlib
import re
import statistics
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))
import loopback_cluster  # noqa: E402
import pqhull  # noqa: E402
from pqhull import ray as pqray  # noqa: E402


def dataset(directory, objects, grasps, seed=0):
    rng = np.random.default_rng(seed)
    sets = {}
    for i in range(objects):
        normals = rng.standard_normal((grasps, 4, 3))
        normals /= np.linalg.norm(normals, axis=2, keepdims=True)
        positions = -normals * rng.uniform(0.5, 1.0, (grasps, 4, 1))
        sets[f"object{i:03}"] = (positions, normals)
        np.savez(directory / f"object{i:03}.npz", positions=positions, normals=normals,
                 friction=0.5, cone_edges=8)
    return sets


def run(cluster, directory, out, chunk_size):
    result = cluster.evaluate(directory, "--output", out, "--chunk-size", chunk_size)
    seconds = float(re.search(r"grasps of \d+ objects in ([0-9.]+) s", result.stderr).group(1))
    return seconds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--objects", type=int, default=8)
    parser.add_argument("--grasps", type=int, default=5000)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--chunk-size", type=int, default=pqray.DEFAULT_CHUNK_SIZE)
    args = parser.parse_args()
    reason = loopback_cluster.unavailable()
    if reason:
        sys.exit(f"ray_scaling: {reason}")
    directory = pathlib.Path(tempfile.mkdtemp(prefix="pqray-bench"))
    (directory / "data").mkdir()
    sets = dataset(directory / "data", args.objects, args.grasps)
    total = args.objects * args.grasps
    started = time.perf_counter()
    reference = {name: pqhull.evaluate(p, n, friction=0.5, cone_edges=8, threads=1)
                 for name, (p, n) in sets.items()}
    one_core = time.perf_counter() - started
    library = sum(b.evaluation_s for b in reference.values())
    print(f"dataset: {args.objects} objects x {args.grasps} grasps (Q1, 4 contacts, k = 8), "
          f"chunks of {args.chunk_size}")
    print(f"local batch, one thread: {one_core:.2f} s ({total / one_core:,.0f} grasps/s; "
          f"library's own batch time {library:.2f} s)")
    medians = []
    with loopback_cluster.loopback_cluster(nodes=1) as cluster:
        for nodes in (1, 2):
            if nodes == 2:
                cluster.add_node()
            out = directory / f"out{nodes}.npz"
            run(cluster, directory / "data", out, args.chunk_size)  # warm the workers up
            times = [run(cluster, directory / "data", out, args.chunk_size)
                     for _ in range(args.rounds)]
            for r in pqray.load_results(out):
                expected = reference[r.name]
                assert np.array_equal(r.quality, expected.quality, equal_nan=True), r.name
            median = statistics.median(times)
            medians.append(median)
            print(f"Ray, {nodes} node(s) of one CPU: median {median:.2f} s of "
                  f"{', '.join(f'{t:.2f}' for t in times)} ({total / median:,.0f} grasps/s, "
                  f"{one_core / median:.0%} of one local thread)")
    print(f"two nodes / one node: {medians[0] / medians[1]:.2f}x")


if __name__ == "__main__":
    main()
