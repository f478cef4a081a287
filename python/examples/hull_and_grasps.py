"""pqhull from Python: a hull beside scipy's, then 100,000 grasps scored on all cores.

Run it: pip install ./python scipy && python python/examples/hull_and_grasps.py
"""

import time

import numpy as np
import scipy.spatial

import pqhull

rng = np.random.default_rng(0)

# A 5-D hull, exact, in scipy's layout.
points = rng.standard_normal((2000, 5))
started = time.perf_counter()
ours = pqhull.ConvexHull(points)
ours_s = time.perf_counter() - started
started = time.perf_counter()
ref = scipy.spatial.ConvexHull(points)
ref_s = time.perf_counter() - started
print(f"5-D hull of 2000 points: {len(ours.vertices)} vertices, {len(ours.simplices)} facets, "
      f"volume {ours.volume:.6f} (scipy: {len(ref.vertices)}, {len(ref.simplices)}, {ref.volume:.6f}); "
      f"{ours_s * 1e3:.0f} ms vs scipy {ref_s * 1e3:.0f} ms")
assert set(ours.vertices) == set(ref.vertices)

# The distance from the origin to the boundary, from a partial hull.
d = pqhull.distance_to_boundary(points)
print(f"distance from the origin to the boundary: {d.signed_distance:.6f} "
      f"({d.points_processed} of {len(points)} points added)")

# 100,000 random 4-finger grasps on the unit sphere, Q1 with 8-edge friction pyramids.
n, m = 100_000, 4
normals = rng.standard_normal((n, m, 3))
normals /= np.linalg.norm(normals, axis=2, keepdims=True)
positions = -normals
started = time.perf_counter()
batch = pqhull.evaluate(positions, normals, friction=0.5, cone_edges=8)
seconds = time.perf_counter() - started
print(f"{n} grasps: {batch.force_closure.sum()} force closure, best Q1 {np.nanmax(batch.quality):.4f}, "
      f"{seconds:.2f} s ({n / seconds:,.0f} grasps/s), {len(batch.errors)} errors")
