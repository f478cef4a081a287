"""pqhull: exact convex hulls and partial hulls in 2 to 8 dimensions, and the grasp-quality
metrics they make fast (Liu & Carpin's PQHGWS), with numpy arrays in and out.

>>> import numpy as np, pqhull
>>> square = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.2, 0.1]])
>>> hull = pqhull.ConvexHull(square)
>>> hull.volume
4.0
>>> pqhull.distance_to_boundary(square, [0.5, 0.0]).signed_distance
0.5
"""

from __future__ import annotations

import numpy as np

from . import _pqhull
from ._pqhull import (
    Batch,
    ConvexHull,
    Distance,
    Error,
    GraspError,
    HullError,
    InputError,
    ObjectWrenchSpace,
    Quality,
    QualityError,
    load_mesh,
)

__all__ = [
    "ConvexHull",
    "distance_to_boundary",
    "q1",
    "qinf",
    "ows",
    "ObjectWrenchSpace",
    "load_mesh",
    "evaluate",
    "cone_bracket",
    "resist",
    "gws_volume",
    "grasp_matrix_metrics",
    "Batch",
    "Distance",
    "Quality",
    "Error",
    "HullError",
    "GraspError",
    "QualityError",
    "InputError",
]


def _array(value, ndim, name):
    """`value` as a C-contiguous float64 array of `ndim` dimensions, or an InputError."""
    try:
        array = np.ascontiguousarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise InputError(f"{name}: not an array of numbers ({e})") from None
    if array.ndim != ndim:
        raise InputError(f"{name} must have {ndim} dimensions, not shape {array.shape}")
    return array


def _optional(value, ndim, name):
    return None if value is None else _array(value, ndim, name)


def _torsion(torsion, shape):
    """Soft contacts' torsion, one per contact: a number (every contact) or an array, broadcast to
    `shape`; None for hard contacts."""
    if torsion is None:
        return None
    try:
        return np.ascontiguousarray(np.broadcast_to(np.asarray(torsion, dtype=np.float64), shape))
    except ValueError:
        raise InputError(f"torsion must be a number or have shape {shape}, "
                         f"not {np.shape(torsion)}") from None


def distance_to_boundary(points, query=None):
    """The signed distance from `query` (default: the origin) to the boundary of the hull of
    `points`: positive inside, negative outside, exactly signed; from a partial hull that stops
    as soon as the nearest facet is certain. Returns a Distance (`signed_distance`, `facet`,
    `nearest_point` and the work counters)."""
    return _pqhull.distance_to_boundary(_array(points, 2, "points"), _optional(query, 1, "query"))


def _frame(torque_reference):
    return _optional(torque_reference, 1, "torque_reference")


def q1(positions, normals, tangents=None, *, torsion=None, friction, cone_edges, torque_reference=None,
       torque_scale=None, method="partial"):
    """Ferrari-Canny Q1 of one grasp of m contacts: (m, 3) positions and inward normals,
    optional (m, 3) tangents; exact on its wrenches. Returns a Quality (`value`,
    `force_closure`, counters)."""
    return _pqhull.q1(
        _array(positions, 2, "positions"), _array(normals, 2, "normals"),
        _optional(tangents, 2, "tangents"), torsion=_torsion(torsion, np.shape(positions)[:1]),
        friction=float(friction), cone_edges=int(cone_edges),
        torque_reference=_frame(torque_reference),
        torque_scale=None if torque_scale is None else float(torque_scale), method=method)


def qinf(positions, normals, tangents=None, *, torsion=None, friction, cone_edges, torque_reference=None,
         torque_scale=None, with_zero_wrench=False, method="partial"):
    """Q-infinity (the Minkowski sum of the contacts' wrench sets) of one grasp; as q1."""
    return _pqhull.qinf(
        _array(positions, 2, "positions"), _array(normals, 2, "normals"),
        _optional(tangents, 2, "tangents"), torsion=_torsion(torsion, np.shape(positions)[:1]),
        friction=float(friction), cone_edges=int(cone_edges),
        torque_reference=_frame(torque_reference),
        torque_scale=None if torque_scale is None else float(torque_scale),
        with_zero_wrench=bool(with_zero_wrench), method=method)


def ows(positions, normals, tangents=None, *, torsion=None, space, friction, cone_edges, torque_reference=None,
        torque_scale=None, method="partial"):
    """Q_OWS of one grasp against `space` (an ObjectWrenchSpace): how large a disturbance of the
    space the grasp resists. `value` is None when the grasp is not force closure. With a space
    built from a mesh the grasp is evaluated in the mesh's torque frame."""
    return _pqhull.ows(
        _array(positions, 2, "positions"), _array(normals, 2, "normals"),
        _optional(tangents, 2, "tangents"), torsion=_torsion(torsion, np.shape(positions)[:1]),
        space=space, friction=float(friction),
        cone_edges=int(cone_edges), torque_reference=_frame(torque_reference),
        torque_scale=None if torque_scale is None else float(torque_scale), method=method)


def evaluate(positions, normals, tangents=None, *, torsion=None, friction, cone_edges, torque_reference=None,
             torque_scale=None, metric="q1", method="partial", with_zero_wrench=False,
             space=None, threads=None, wrench=None):
    """The metric of N grasps of m contacts: (N, m, 3) positions and normals, optional tangents;
    `friction` one value or one per grasp. Metrics: "q1", "qinf", "ows" (with `space`),
    "resist" (with `wrench`, 6 numbers), "volume", "sigma-min", "isotropy" (for the last three,
    force_closure is Q1's, and `method` computes only that verdict). Runs on all cores (or `threads`) with the GIL
    released. Returns a Batch: `quality` (N,) and `force_closure` (N,) arrays, and `errors`, a
    list of (row, message); a bad row is NaN and False there, the others are kept. For "ows" and
    "resist", a grasp not in force closure is NaN and False without an error entry."""
    mu = np.atleast_1d(np.asarray(friction, dtype=np.float64))
    if mu.ndim != 1:
        raise InputError(f"friction must be a number or a 1-D array, not shape {mu.shape}")
    return _pqhull.evaluate(
        _array(positions, 3, "positions"), _array(normals, 3, "normals"),
        _optional(tangents, 3, "tangents"), torsion=_torsion(torsion, np.shape(positions)[:2]),
        friction=np.ascontiguousarray(mu),
        cone_edges=int(cone_edges), torque_reference=_frame(torque_reference),
        torque_scale=None if torque_scale is None else float(torque_scale), metric=metric,
        method=method, with_zero_wrench=bool(with_zero_wrench), space=space, threads=threads,
        wrench=_optional(wrench, 1, "wrench"))


def _one(positions, normals, tangents):
    return (_array(positions, 2, "positions"), _array(normals, 2, "normals"),
            _optional(tangents, 2, "tangents"))


def _frame_args(torque_reference, torque_scale):
    return dict(torque_reference=_frame(torque_reference),
                torque_scale=None if torque_scale is None else float(torque_scale))


def cone_bracket(positions, normals, tangents=None, *, torsion=None, friction, cone_edges,
                 torque_reference=None, torque_scale=None, method="partial"):
    """(low, high): Q1 of the true circular friction cones lies between them. low is Q1 with
    the k-edge pyramids inscribed in the cones, high with the pyramids circumscribed about them
    (rim scaled by 1/cos(pi/k)), each widened by its evaluation's accuracy."""
    return _pqhull.cone_bracket(*_one(positions, normals, tangents),
        torsion=_torsion(torsion, np.shape(positions)[:1]), friction=float(friction),
                                cone_edges=int(cone_edges),
                                **_frame_args(torque_reference, torque_scale), method=method)


def resist(positions, normals, tangents=None, *, torsion=None, wrench, friction, cone_edges,
           torque_reference=None, torque_scale=None, method="partial"):
    """The largest t such that the grasp resists -t*wrench (6 numbers in the grasp's torque
    units, e.g. gravity at the centre of mass): Q_OWS with that single disturbance, by the
    partial hull. A Quality; `value` is None when the grasp is not force closure."""
    return _pqhull.resist(*_one(positions, normals, tangents),
        torsion=_torsion(torsion, np.shape(positions)[:1]), wrench=_array(wrench, 1, "wrench"),
                          friction=float(friction), cone_edges=int(cone_edges),
                          **_frame_args(torque_reference, torque_scale), method=method)


def gws_volume(positions, normals, tangents=None, *, torsion=None, friction, cone_edges, torque_reference=None,
               torque_scale=None):
    """The volume of the grasp wrench space (the full hull of the Q1 wrenches: a volume needs
    every facet). 0 for wrenches spanning fewer than six dimensions."""
    return _pqhull.gws_volume(*_one(positions, normals, tangents),
        torsion=_torsion(torsion, np.shape(positions)[:1]), friction=float(friction),
                              cone_edges=int(cone_edges),
                              **_frame_args(torque_reference, torque_scale))


def grasp_matrix_metrics(positions, normals, tangents=None, *, torsion=None, friction, cone_edges,
                         torque_reference=None, torque_scale=None):
    """(singular_values, sigma_min, isotropy) of the grasp matrix (6 x 3m, contact forces to
    wrenches in the grasp's torque frame): its six singular values largest first, the smallest,
    and smallest / largest."""
    return _pqhull.grasp_matrix_metrics(*_one(positions, normals, tangents),
        torsion=_torsion(torsion, np.shape(positions)[:1]),
                                        friction=float(friction), cone_edges=int(cone_edges),
                                        **_frame_args(torque_reference, torque_scale))
