"""pqhull: exact convex hulls and partial hulls in 2 to 8 dimensions, and the grasp-quality
metrics they make fast (Liu & Carpin's PQHGWS), with numpy arrays in and out.

>>> import numpy as np, pqhull
>>> square = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.2, 0.1]])
>>> hull = pqhull.ConvexHull(square)
>>> hull.volume, hull.area
(4.0, 8.0)
>>> pqhull.distance_to_boundary(square, [0.5, 0.0]).signed_distance
0.5
>>> pqhull.penetration_depth(square, square + [1.5, 0.0]).depth  # they overlap by 0.5 along x
0.5

ConvexHull, a drop-in for scipy.spatial.ConvexHull
--------------------------------------------------

``pqhull.ConvexHull(points, incremental=False, qhull_options=None)`` takes scipy's arguments
and has its attributes: ``points``, ``vertices`` (counter-clockwise in 2-D, increasing
otherwise), ``simplices``, ``neighbors``, ``equations`` (``normal . x + offset <= 0`` inside),
``coplanar``, ``good``, ``area`` (the perimeter in 2-D), ``volume``, ``ndim``, ``npoints``,
``nsimplex``, ``min_bound`` and ``max_bound``, indices as ``np.intc``; and two of its own,
``points_processed`` and ``facets_created`` (the engine's work counters). With
``incremental=True``, ``add_points(points, restart=False)`` grows the hull to the exact hull of
all the points (``restart=True`` rebuilds from all of them: the same hull), and ``close()``
ends that: ``add_points`` then raises ``RuntimeError("incremental mode not enabled or already
closed")``, as on a hull that is not incremental, both as in scipy. Each attribute is one numpy
array, the same object at every access, remade by ``add_points``.

Facets are listed by their vertex indices taken largest first, compared lexicographically: the
order in which inserting the points one at a time, in input order, creates them, which is what
Qhull's ``add_points`` does. So after ``add_points`` the facets that survive keep their order
and the new ones follow, as in scipy, and the order does not depend on how the hull was reached
(at once, grown, rebuilt or unpickled). Each row of ``simplices`` lists its vertices largest
first as far as the facet's orientation allows (the last two swapped when needed).

``qhull_options`` (Qhull's options, separated by spaces; several after one ``Q`` as Qhull reads
them, e.g. ``Qci``):

* accepted with no effect, as they only tune how Qhull copes with its rounding and the hull is
  exact: ``Qt`` (always on in scipy too), ``Qbb``, ``Qx``, ``Qs``, ``Qv``, ``Qw``, ``Qf``,
  ``Qm``, ``Qr``, ``Qa``, ``QJ`` / ``QJn``, ``Q0`` to ``Q12`` and ``Q14``, ``Pp``, ``Po``,
  ``Tv``, ``Tc``, ``FA``, and the precision thresholds ``C-n``, ``Cn``, ``A-n``, ``An``, ``En``,
  ``Rn``, ``Un``, ``Vn``, ``Wn``;
* ``Qc``: ``coplanar`` lists, as ``[point, facet, nearest vertex]`` rows, every input point
  exactly on the boundary (exact test) that is not a vertex, duplicates of vertices included,
  with the facet through it whose simplex contains it and that facet's vertex nearest it;
  ``Qi``: every point strictly inside, with the facet of the nearest plane. Without them
  ``coplanar`` is empty, shape (0, 3), as scipy's. Rows are ordered by facet, then point;
* ``QGn`` / ``QG-n``: point n takes no part in the hull (as in Qhull), and ``good`` says per
  facet whether point n sees it, strictly beyond its plane, decided exactly (``QG-n``: does not
  see it); without a ``QG`` option ``good`` is None;
* anything else raises ``pqhull.InputError`` naming the option: scaling (``QbB``, ``Qbk:n``,
  ``QBk:n``), random rotation (``QRn``), ``QVn``, ``Qg``, the Delaunay options ``Qz`` and
  ``Qu`` (scipy refuses them too), another mode (``d``, ``v``, ``Hn``), the qhull program's
  print and output options (``P``, ``F``, ``G``, ``T`` ones other than those above, ``o``,
  ``i``, ``n``, ``p``, ``s``, ``m``, ``f``), ``Q13``, ``Q15`` and unknown options. As in scipy,
  ``Qbb`` is refused with ``incremental=True`` ("incompatible with incremental mode").

Masked arrays are refused with scipy's message, "Input points cannot be a masked array", as a
``pqhull.InputError`` (a ``ValueError``, as scipy's); a NaN is a ``ValueError``
(``pqhull.HullError``), as in scipy. scipy's own ConvexHull
tests (``python/tests/test_scipy_convexhull.py`` runs them from the installed scipy) all pass.

Differences from scipy
~~~~~~~~~~~~~~~~~~~~~~

* Exceptions: input that admits no hull (fewer than d + 1 points, all of them in a hyperplane,
  an infinite coordinate) raises ``pqhull.HullError``, a ``pqhull.Error`` and so a
  ``ValueError``, where scipy raises ``scipy.spatial.QhullError`` (a ``RuntimeError``); a
  refused or unknown option raises ``pqhull.InputError`` (a ``ValueError``) where scipy raises
  ``QhullError`` (or accepts it, for the refused options it knows); points that are not a 2-D
  array raise ``pqhull.InputError`` (scipy: ``ValueError`` or ``IndexError``).
* Dimensions 2 to 8 only (scipy's Qhull takes any dimension from 2).
* The hull is exact: its vertices are exactly the extreme points, a point on an edge or a face
  is never a vertex, and nothing is merged or joggled. Where Qhull's rounding decides (nearly
  coplanar points, ``QJ``, large thresholds such as ``C0.1``, ``A0.9``, ``W0.5``, ``E1e-3``
  that make Qhull merge into an approximate hull, or fail), the answers differ: pqhull's is the
  hull of the points as given. On degenerate input (four or more points on one facet plane)
  the triangulation of that face may differ from Qhull's; both are valid. Of several copies of
  one point, the vertex is the first (lowest index), the others are coplanar points; Qhull may
  make another copy the vertex, and may list the other copies or drop them.
* ``Qbb``: in scipy's ConvexHull Qhull scales the last coordinate (of the caller's array, in
  place, when it is already C-contiguous float64) and reports the hull of the scaled points;
  pqhull ignores the option.
* The facet order (see above) is pqhull's own; it agrees with Qhull's after ``add_points`` (new
  facets after the surviving ones) but not, in general, for a hull built at once. The 2-D
  vertex list may start at another vertex (it is counter-clockwise in both).
* ``coplanar`` is decided exactly (Qhull's with its tolerance), its facet and nearest vertex as
  described above (Qhull's are the facet it partitioned the point to and the nearest vertex of
  that), and after ``add_points`` it covers every point (scipy's incremental Qhull lists no
  added point that lands inside until a restart). ``Qc`` and ``Qi`` cost a distance test of
  every non-vertex point against every facet (Qhull gets them from its partitioning).
* ``good`` is decided exactly (Qhull: a floating-point distance > 0).
* ``add_points`` refuses a NaN or infinite coordinate with ``pqhull.HullError``, naming the
  point, and leaves the hull as it was (scipy takes a NaN and reports a NaN volume).
* ``points`` is a copy (scipy's non-incremental hull keeps the caller's array when it is already
  C-contiguous float64). The attributes are read-only properties (scipy's can be reassigned);
  there are no private ``_points`` / ``_vertices`` / ``_qhull``.
* Pickling (and ``copy``) rebuilds the hull from its points and options; an incremental hull
  that is not closed comes back incremental (scipy cannot pickle an incremental hull).
* ``add_points`` runs without the GIL; another thread using the same hull meanwhile gets a
  ``RuntimeError`` ("Already mutably borrowed") rather than waiting.
"""

from __future__ import annotations

import sys

import numpy as np

from . import _pqhull
from ._pqhull import (
    Batch,
    ConvexHull,
    Distance,
    Distances,
    Error,
    GraspError,
    HullError,
    InputError,
    ObjectWrenchSpace,
    Penetration,
    Quality,
    QualityError,
    load_mesh,
)

__all__ = [
    "ConvexHull",
    "distance_to_boundary",
    "penetration_depth",
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
    "Distances",
    "Penetration",
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
    `nearest_point` and the work counters).

    `query` may also be an (m, d) array of queries: they are answered from one partial hull
    shared by all of them (each answer the one a query alone gets), and the result is a
    Distances of arrays (`signed_distance` (m,), `facets` (m, d), `nearest_points` (m, d))."""
    points = _array(points, 2, "points")
    if query is not None and np.ndim(query) == 2:
        return _pqhull.distances_to_boundary(points, _array(query, 2, "query"))
    return _pqhull.distance_to_boundary(points, _optional(query, 1, "query"))


def penetration_depth(a, b):
    """The signed penetration depth of the convex hulls of `a` ((n, d)) and `b` ((m, d), the
    same d, 2 to 8): the signed distance from the origin to the boundary of their Minkowski
    difference {a_i - b_j}, positive when the interiors overlap (the length of the smallest
    translation of `b` that separates them), negative when the bodies are disjoint (minus their
    distance), zero when they touch; by GJK, then a partial hull over the difference, which is
    never materialised, with the GIL released. Returns a Penetration (`depth`, unit
    `direction` (d,), `translation` = depth * direction (d,): moving `b` by it makes the bodies
    touch, `relation`: "overlapping", "touching" or "separated", `rounding` and `scale`: the
    accuracy's terms, and the work counters).

    Masked arrays are refused (pqhull.InputError), as by ConvexHull; an empty body or a NaN or
    infinite coordinate raises pqhull.HullError naming the body ("a" or "b") and the vertex."""
    return _pqhull.penetration_depth(_body(a, "a"), _body(b, "b"))


def _body(value, name):
    # A masked array exists only once numpy.ma is imported (as ConvexHull checks it).
    ma = sys.modules.get("numpy.ma")
    if ma is not None and ma.isMaskedArray(value):
        raise InputError(f"{name} cannot be a masked array")
    return _array(value, 2, name)


def _frame(torque_reference):
    return _optional(torque_reference, 1, "torque_reference")


def q1(positions, normals, tangents=None, *, torsion=None, friction, cone_edges, torque_reference=None,
       torque_scale=None, method="partial", gradient=False):
    """Ferrari-Canny Q1 of one grasp of m contacts: (m, 3) positions and inward normals,
    optional (m, 3) tangents; exact on its wrenches. Returns a Quality (`value`,
    `force_closure`, counters).

    With ``gradient=True`` the Quality also carries Q1's exact gradient (Danskin's theorem on
    the deciding face, the library's ``grasp::q1_gradient``), with respect to the grasp's own
    inputs:

    * ``gradient_positions``: (m, 3) array, dQ1/dp_i, contacts in input order;
    * ``gradient_normals``: (m, 3) array, dQ1/dn_i with respect to the *unit* normal: each row
      is orthogonal to n_i (moving a normal along itself changes nothing); the tangent is
      re-derived from the moved normal as the contact does (a given tangent orthogonalised
      against it, or the default one). For a normal passed with length L, divide by L to get
      the derivative with respect to the array you passed;
    * ``gradient_friction``: float, dQ1/dmu;
    * ``differentiable``: bool. False where Q1 is not differentiable -- the origin on the hull's
      boundary, a tie between faces, a zero weight, repeated contacts, or a default tangent whose
      axis is tied (axis-aligned normals): the numbers are then the derivative along the
      deciding face found, one element of the generalised gradient.

    The torque frame (torque_reference, torque_scale), the given tangents and the torsion are
    held fixed. Without ``gradient`` those four attributes are None. A grasp whose Q1 is found
    but cannot be differentiated (wrenches rescaled beyond 2**+-256) raises QualityError."""
    return _pqhull.q1(
        _array(positions, 2, "positions"), _array(normals, 2, "normals"),
        _optional(tangents, 2, "tangents"), torsion=_torsion(torsion, np.shape(positions)[:1]),
        friction=float(friction), cone_edges=int(cone_edges),
        torque_reference=_frame(torque_reference),
        torque_scale=None if torque_scale is None else float(torque_scale), method=method,
        gradient=bool(gradient))


def qinf(positions, normals, tangents=None, *, torsion=None, friction, cone_edges, torque_reference=None,
         torque_scale=None, with_zero_wrench=False, method="partial", gradient=False):
    """Q-infinity (the Minkowski sum of the contacts' wrench sets, each with the zero wrench
    added when `with_zero_wrench`) of one grasp; as q1.

    ``gradient=True`` adds Q-infinity's exact gradient (the library's ``grasp::qinf_gradient``,
    on the face of the Minkowski sum along the deciding direction: the sum of each contact's
    face), in the attributes and conventions of ``q1(..., gradient=True)``:
    ``gradient_positions`` (m, 3), ``gradient_normals`` (m, 3, with respect to the unit
    normals), ``gradient_friction`` and ``differentiable`` (False also where the deciding face
    of the sum is degenerate: more contacts' faces tied along the direction than its dimension
    needs; or more than 65,536 tuples of them to sum, where the numbers are all zero). A grasp
    whose Q-infinity is found but cannot be differentiated raises QualityError."""
    return _pqhull.qinf(
        _array(positions, 2, "positions"), _array(normals, 2, "normals"),
        _optional(tangents, 2, "tangents"), torsion=_torsion(torsion, np.shape(positions)[:1]),
        friction=float(friction), cone_edges=int(cone_edges),
        torque_reference=_frame(torque_reference),
        torque_scale=None if torque_scale is None else float(torque_scale),
        with_zero_wrench=bool(with_zero_wrench), method=method, gradient=bool(gradient))


def ows(positions, normals, tangents=None, *, torsion=None, space, friction, cone_edges, torque_reference=None,
        torque_scale=None, method="partial", gradient=False):
    """Q_OWS of one grasp against `space` (an ObjectWrenchSpace): how large a disturbance of the
    space the grasp resists. `value` is None when the grasp is not force closure. With a space
    built from a mesh the grasp is evaluated in the mesh's torque frame.

    ``gradient=True`` (an exact method: "partial", "full" or "partial-rays"; "ellipsoid" raises
    InputError) adds Q_OWS's exact gradient (the library's ``grasp::ows_gradient``, through the
    facet the deciding disturbance's ray leaves the grasp wrench space by), in the attributes and
    conventions of ``q1(..., gradient=True)``: ``gradient_positions`` (m, 3),
    ``gradient_normals`` (m, 3, with respect to the unit normals), ``gradient_friction`` (the
    grasp's friction; a mesh space's own friction is part of the space, held fixed) and
    ``differentiable`` (False also where another disturbance ties with the deciding one). The
    disturbances and the torque frame are held fixed. A grasp that is not force closure has no
    value and so no gradient: the four attributes are None (as ``value``). A force-closure grasp
    whose value is found but whose deciding facet is not raises QualityError."""
    return _pqhull.ows(
        _array(positions, 2, "positions"), _array(normals, 2, "normals"),
        _optional(tangents, 2, "tangents"), torsion=_torsion(torsion, np.shape(positions)[:1]),
        space=space, friction=float(friction),
        cone_edges=int(cone_edges), torque_reference=_frame(torque_reference),
        torque_scale=None if torque_scale is None else float(torque_scale), method=method,
        gradient=bool(gradient))


def evaluate(positions, normals, tangents=None, *, torsion=None, friction, cone_edges, torque_reference=None,
             torque_scale=None, metric="q1", method="partial", with_zero_wrench=False,
             space=None, threads=None, wrench=None, gradient=False):
    """The metric of N grasps of m contacts: (N, m, 3) positions and normals, optional tangents;
    `friction` one value or one per grasp. Metrics: "q1", "qinf", "ows" (with `space`),
    "resist" (with `wrench`, 6 numbers), "volume", "sigma-min", "isotropy" (for the last three,
    force_closure is Q1's, and `method` computes only that verdict). Runs on all cores (or `threads`) with the GIL
    released. Returns a Batch: `quality` (N,) and `force_closure` (N,) arrays, and `errors`, a
    list of (row, message); a bad row is NaN and False there, the others are kept. For "ows" and
    "resist", a grasp not in force closure is NaN and False without an error entry.

    ``gradient=True`` (metrics "q1", "qinf" and "ows", by an exact method; another metric, or
    "ellipsoid", raises InputError) adds the value's gradient of every row, as
    ``q1`` / ``qinf`` / ``ows(..., gradient=True)`` gives it, row for row the same numbers: the
    Batch's ``gradient_positions`` (N, m, 3), ``gradient_normals`` (N, m, 3),
    ``gradient_friction`` (N,) and ``differentiable`` (N,) bool, NaN and False for a row
    without a value: a bad row (a row whose value cannot be differentiated is a bad row, with
    an error entry) and, for "ows", a grasp not in force closure (its quality NaN too, without
    an error entry; ``ows`` gives None there). Without ``gradient`` they are None."""
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
        wrench=_optional(wrench, 1, "wrench"), gradient=bool(gradient))


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
