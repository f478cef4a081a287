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

import operator
import sys

import numpy as np

from . import _pqhull
from ._pqhull import (
    Batch,
    ConvexHull,
    DescentReport,
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
    "plan_descent",
    "Batch",
    "DescentReport",
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


def _count(value, name):
    """`value` as a Python int from 0 to 2**64 - 1 (the library's counts and seeds), or an
    InputError."""
    try:
        n = operator.index(value)
    except TypeError:
        raise InputError(f"{name} must be an integer, not {value!r}") from None
    if not 0 <= n < 2**64:
        raise InputError(f"{name} must be an integer from 0 to 2**64 - 1, not {n}")
    return n


def plan_descent(mesh, *, contacts=4, friction, cone_edges, metric="q1", starts=10,
                 evaluations=50, screen=1, seed=1, method="partial", space=None):
    """Grasps planned on a mesh by climbing the metric (the library's descent planner,
    ``pqhull::plan::plan_descent``; ``pqh plan --planner descent`` on the command line): from each
    of `starts` random grasps of `contacts` contacts (drawn uniformly by area on the surface,
    inward face normals, as the sampling planner draws them; the same `seed` gives the same
    starts), contacts move over the surface along the exact gradient of the value, a move kept
    only when it is strictly better, until the step is too small, the run has used its
    `evaluations` (the start's included) or the gradient vanishes. A run that cannot reach
    force closure starts again from a fresh random grasp while evaluations remain. Grasps are
    ranked by (force closure, value): the metric's value for a force-closure grasp, else the value
    climbed toward force closure (negative or zero: Q1's, or for "qinf" / "qinf0" Q-infinity's
    own), which a start short of force closure climbs first. So every planned grasp is at least
    as good as its start. Runs one after the other (one core) with the GIL released.

    * `mesh`: the path of an OBJ or STL file, or a ``(vertices, faces)`` pair of arrays ((n, 3)
      positions, (f, 3) vertex indices counter-clockwise seen from outside), as
      ``load_mesh`` returns and ``ObjectWrenchSpace.from_arrays`` takes.
    * `friction`, `cone_edges`: every contact's friction coefficient and pyramid edges.
    * `metric`: "q1", "qinf", "qinf0" (Q-infinity with the zero wrench) or "ows". For "ows",
      `space` is the object's ObjectWrenchSpace (of this same mesh: its torque frame is the
      grasps'); without it, the mesh's own is built with the grasps' `friction` and
      `cone_edges` (as ``pqh plan`` does, and as ``ObjectWrenchSpace.from_arrays`` /
      ``from_mesh`` would). `space` is refused for the other metrics. Any other metric
      ("volume", ...) raises InputError: the planner follows gradients, which only these have.
    * `method`: "partial" (the partial hull) or "full" (the full hull), both exact.
    * `starts` (1 to 100,000), `evaluations` per planned grasp (1 to 10,000; at least 2 for
      "ows"), `screen` (1 to 10,000): the library's bounds, refused (InputError) before any
      work. With `screen` above 1 each climb starts from the best of `screen` random grasps
      (each one evaluation out of `evaluations`), and a climb that stops with evaluations left
      screens a fresh start and climbs again; about 10 pays for "ows", whose climbs stop at
      kinks soon after they start.

    Returns a DescentReport, one row per start (S of them, in start order): ``positions`` and
    ``normals`` (S, m, 3) (unit inward normals), ``values`` and ``start_values`` (S,),
    ``force_closure`` and ``start_force_closure`` (S,) bool, ``evaluations`` and ``steps``
    (S,) int64, ``stop`` (a list of "step", "evaluations" or "stationary"), ``best`` (the index
    of the best force-closure grasp, or None); and the run's ``total_evaluations`` (the sum of
    ``evaluations``), ``quality_s``, ``gradient_s``, ``other_s`` (seconds), ``facets_created``,
    ``metric`` and ``method``. The grasps are in the torque frame ``torque_reference`` (3,),
    ``torque_scale`` (the mesh's centre of mass and largest vertex distance, or the space's):
    pass them to ``q1`` / ``qinf`` to evaluate a planned grasp again (``ows`` takes the
    space's frame itself).

    >>> import numpy as np, pqhull
    >>> vertices = np.array([[-0.5, -0.2, -0.1], [0.5, -0.2, -0.1], [0.5, 0.2, -0.1],
    ...                      [-0.5, 0.2, -0.1], [-0.5, -0.2, 0.1], [0.5, -0.2, 0.1],
    ...                      [0.5, 0.2, 0.1], [-0.5, 0.2, 0.1]])
    >>> faces = [[0, 3, 2], [0, 2, 1], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
    ...          [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]]
    >>> plan = pqhull.plan_descent((vertices, faces), contacts=4, friction=0.5, cone_edges=8,
    ...                            starts=4, evaluations=20)
    >>> bool(np.all(plan.values >= plan.start_values))
    True
    >>> i = plan.best
    >>> q = pqhull.q1(plan.positions[i], plan.normals[i], friction=0.5, cone_edges=8,
    ...               torque_reference=plan.torque_reference, torque_scale=plan.torque_scale)
    >>> bool(np.isclose(q.value, plan.values[i], rtol=1e-12, atol=0))
    True

    Errors: InputError for a bad argument (the library's message: a bound, a metric the
    planner does not climb, an unknown name, a bad mesh), GraspError for a bad friction model,
    QualityError if an evaluation fails; all are ValueErrors."""
    return _pqhull.plan_descent(
        mesh, contacts=_count(contacts, "contacts"), friction=float(friction),
        cone_edges=_count(cone_edges, "cone_edges"), metric=metric,
        starts=_count(starts, "starts"), evaluations=_count(evaluations, "evaluations"),
        screen=_count(screen, "screen"), seed=_count(seed, "seed"), method=method, space=space)
