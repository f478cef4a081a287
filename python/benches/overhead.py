"""What Python costs on top of the library: batch throughput and per-call overhead.

Run it (after `pip install ./python`): python python/benches/overhead.py
- batch: `pqhull.evaluate` on N random grasps; its wall time against `Batch.evaluation_s`, the
  library's own batch evaluation inside the call (the rest is array conversion, building the
  grasps from the arrays, and the results' arrays);
- single call: `pqhull.q1` on one grasp; its wall time against `Quality.elapsed_us`, the
  library's own time for that grasp.
Medians of several rounds.
"""

import statistics
import time

import numpy as np

import pqhull


def grasps(n, m=4, seed=0):
    rng = np.random.default_rng(seed)
    normals = rng.standard_normal((n, m, 3))
    normals /= np.linalg.norm(normals, axis=2, keepdims=True)
    return -normals * rng.uniform(0.5, 1.0, (n, m, 1)), normals


def batch(n=20000, rounds=5):
    positions, normals = grasps(n)
    walls, inside = [], []
    for _ in range(rounds):
        started = time.perf_counter()
        result = pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8)
        walls.append(time.perf_counter() - started)
        inside.append(result.evaluation_s)
    wall, lib = statistics.median(walls), statistics.median(inside)
    print(f"batch of {n} grasps (Q1, 4 contacts x 8 edges, all cores): {wall:.3f} s in Python, "
          f"{lib:.3f} s in the library's batch: Python throughput {lib / wall:.1%} of the library's "
          f"({n / wall:,.0f} vs {n / lib:,.0f} grasps/s)")


def single(calls=3000):
    positions, normals = grasps(1, seed=1)
    p, n = positions[0], normals[0]
    pqhull.q1(p, n, friction=0.5, cone_edges=8)  # warm up
    overheads, walls = [], []
    for _ in range(calls):
        started = time.perf_counter()
        q = pqhull.q1(p, n, friction=0.5, cone_edges=8)
        wall = (time.perf_counter() - started) * 1e6
        walls.append(wall)
        overheads.append(wall - q.elapsed_us)
    print(f"one q1 call: {statistics.median(walls):.1f} us in Python, of which "
          f"{statistics.median(overheads):.1f} us outside the library's evaluation (median of {calls})")


if __name__ == "__main__":
    batch()
    single()
