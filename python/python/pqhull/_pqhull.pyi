"""Type stubs of the extension module behind `pqhull` (see `pqhull/__init__.py`)."""

import os
from typing import Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

class Error(ValueError): ...
class HullError(Error): ...
class GraspError(Error): ...
class QualityError(Error): ...
class InputError(Error): ...

class ConvexHull:
    """scipy.spatial.ConvexHull's interface over the exact hull (see ``help(pqhull)``)."""

    def __init__(
        self,
        points: npt.ArrayLike,
        incremental: bool = False,
        qhull_options: Optional[Union[str, bytes]] = None,
    ) -> None: ...
    def add_points(self, points: npt.ArrayLike, restart: bool = False) -> None: ...
    def close(self) -> None: ...
    def __reduce__(
        self,
    ) -> tuple[type[ConvexHull], tuple[npt.NDArray[np.float64], bool, Optional[str]]]: ...
    @property
    def points(self) -> npt.NDArray[np.float64]: ...
    @property
    def vertices(self) -> npt.NDArray[np.intc]: ...
    @property
    def simplices(self) -> npt.NDArray[np.intc]: ...
    @property
    def neighbors(self) -> npt.NDArray[np.intc]: ...
    @property
    def equations(self) -> npt.NDArray[np.float64]: ...
    @property
    def coplanar(self) -> npt.NDArray[np.intc]: ...
    @property
    def good(self) -> Optional[npt.NDArray[np.bool_]]: ...
    @property
    def volume(self) -> float: ...
    @property
    def area(self) -> float: ...
    @property
    def ndim(self) -> int: ...
    @property
    def npoints(self) -> int: ...
    @property
    def nsimplex(self) -> int: ...
    @property
    def min_bound(self) -> npt.NDArray[np.float64]: ...
    @property
    def max_bound(self) -> npt.NDArray[np.float64]: ...
    @property
    def points_processed(self) -> int: ...
    @property
    def facets_created(self) -> int: ...

class Distance:
    signed_distance: float
    facet: list[int]
    nearest_point: list[float]
    points_processed: int
    facets_created: int
    expansions: int

class Quality:
    value: Optional[float]
    force_closure: bool
    points_processed: int
    facets_created: int
    elapsed_us: float
    # q1 / qinf / ows(..., gradient=True) only (None otherwise): d value / d positions (m, 3),
    # d value / d unit normals (m, 3), d value / d mu, differentiable. For ows also None when
    # the grasp is not force closure (value None: no value, no gradient).
    gradient_positions: Optional[npt.NDArray[np.float64]]
    gradient_normals: Optional[npt.NDArray[np.float64]]
    gradient_friction: Optional[float]
    differentiable: Optional[bool]

class ObjectWrenchSpace:
    @staticmethod
    def from_mesh(path: str, *, friction: float, cone_edges: int) -> ObjectWrenchSpace: ...
    @staticmethod
    def from_arrays(
        vertices: npt.ArrayLike, faces: npt.ArrayLike, *, friction: float, cone_edges: int
    ) -> ObjectWrenchSpace: ...
    @staticmethod
    def from_disturbances(wrenches: npt.ArrayLike) -> ObjectWrenchSpace: ...
    @property
    def torque_frame(self) -> Optional[tuple[list[float], float]]: ...
    @property
    def disturbances(self) -> npt.NDArray[np.float64]: ...
    def __len__(self) -> int: ...
    def __reduce__(self) -> tuple[object, tuple[npt.NDArray[np.float64], str]]: ...

def load_mesh(path: str) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...

class Batch:
    quality: npt.NDArray[np.float64]
    force_closure: npt.NDArray[np.bool_]
    errors: list[tuple[int, str]]
    evaluation_s: float
    # evaluate(..., metric="q1" / "qinf" / "ows", gradient=True) only (None otherwise):
    # (N, m, 3), (N, m, 3), (N,), (N,) bool; NaN / False for a row without a value: a bad row
    # (with an error entry) or, for "ows", a grasp not in force closure (quality NaN too, no
    # error entry).
    gradient_positions: Optional[npt.NDArray[np.float64]]
    gradient_normals: Optional[npt.NDArray[np.float64]]
    gradient_friction: Optional[npt.NDArray[np.float64]]
    differentiable: Optional[npt.NDArray[np.bool_]]

class Distances:
    signed_distance: npt.NDArray[np.float64]
    facets: npt.NDArray[np.intc]
    nearest_points: npt.NDArray[np.float64]
    points_processed: int
    facets_created: int
    def __len__(self) -> int: ...

class Penetration:
    depth: float
    direction: npt.NDArray[np.float64]
    translation: npt.NDArray[np.float64]
    relation: str
    rounding: float
    scale: float
    points_processed: int
    facets_created: int

def distance_to_boundary(
    points: npt.NDArray[np.float64], query: Optional[npt.NDArray[np.float64]] = None
) -> Distance: ...
def distances_to_boundary(
    points: npt.NDArray[np.float64], queries: npt.NDArray[np.float64]
) -> Distances: ...
def penetration_depth(
    a: npt.NDArray[np.float64], b: npt.NDArray[np.float64]
) -> Penetration: ...
def q1(
    positions: npt.NDArray[np.float64],
    normals: npt.NDArray[np.float64],
    tangents: Optional[npt.NDArray[np.float64]] = None,
    *,
    torsion: Optional[npt.ArrayLike] = None,
    friction: float,
    cone_edges: int,
    torque_reference: Optional[npt.NDArray[np.float64]] = None,
    torque_scale: Optional[float] = None,
    method: str = "partial",
    gradient: bool = False,
) -> Quality: ...
def qinf(
    positions: npt.NDArray[np.float64],
    normals: npt.NDArray[np.float64],
    tangents: Optional[npt.NDArray[np.float64]] = None,
    *,
    torsion: Optional[npt.ArrayLike] = None,
    friction: float,
    cone_edges: int,
    torque_reference: Optional[npt.NDArray[np.float64]] = None,
    torque_scale: Optional[float] = None,
    with_zero_wrench: bool = False,
    method: str = "partial",
    gradient: bool = False,
) -> Quality: ...
def ows(
    positions: npt.NDArray[np.float64],
    normals: npt.NDArray[np.float64],
    tangents: Optional[npt.NDArray[np.float64]] = None,
    *,
    torsion: Optional[npt.ArrayLike] = None,
    space: ObjectWrenchSpace,
    friction: float,
    cone_edges: int,
    torque_reference: Optional[npt.NDArray[np.float64]] = None,
    torque_scale: Optional[float] = None,
    method: str = "partial",
    gradient: bool = False,
) -> Quality: ...
def evaluate(
    positions: npt.NDArray[np.float64],
    normals: npt.NDArray[np.float64],
    tangents: Optional[npt.NDArray[np.float64]] = None,
    *,
    torsion: Optional[npt.NDArray[np.float64]] = None,
    friction: npt.NDArray[np.float64],
    cone_edges: int,
    torque_reference: Optional[npt.NDArray[np.float64]] = None,
    torque_scale: Optional[float] = None,
    metric: str = "q1",
    method: str = "partial",
    with_zero_wrench: bool = False,
    space: Optional[ObjectWrenchSpace] = None,
    threads: Optional[int] = None,
    wrench: Optional[npt.NDArray[np.float64]] = None,
    gradient: bool = False,
) -> Batch: ...

def cone_bracket(
    positions: npt.NDArray[np.float64], normals: npt.NDArray[np.float64],
    tangents: Optional[npt.NDArray[np.float64]] = None, *,
    torsion: Optional[npt.NDArray[np.float64]] = None, friction: float, cone_edges: int,
    torque_reference: Optional[npt.NDArray[np.float64]] = None,
    torque_scale: Optional[float] = None, method: str = "partial",
) -> tuple[float, float]: ...
def resist(
    positions: npt.NDArray[np.float64], normals: npt.NDArray[np.float64],
    tangents: Optional[npt.NDArray[np.float64]] = None, *,
    torsion: Optional[npt.NDArray[np.float64]] = None, wrench: npt.NDArray[np.float64],
    friction: float, cone_edges: int,
    torque_reference: Optional[npt.NDArray[np.float64]] = None,
    torque_scale: Optional[float] = None, method: str = "partial",
) -> Quality: ...
def gws_volume(
    positions: npt.NDArray[np.float64], normals: npt.NDArray[np.float64],
    tangents: Optional[npt.NDArray[np.float64]] = None, *,
    torsion: Optional[npt.NDArray[np.float64]] = None, friction: float, cone_edges: int,
    torque_reference: Optional[npt.NDArray[np.float64]] = None,
    torque_scale: Optional[float] = None,
) -> float: ...
def grasp_matrix_metrics(
    positions: npt.NDArray[np.float64], normals: npt.NDArray[np.float64],
    tangents: Optional[npt.NDArray[np.float64]] = None, *,
    torsion: Optional[npt.NDArray[np.float64]] = None, friction: float, cone_edges: int,
    torque_reference: Optional[npt.NDArray[np.float64]] = None,
    torque_scale: Optional[float] = None,
) -> tuple[npt.NDArray[np.float64], float, float]: ...

class DescentReport:
    # One row per start (S), in start order; m contacts per grasp.
    positions: npt.NDArray[np.float64]  # (S, m, 3)
    normals: npt.NDArray[np.float64]  # (S, m, 3), unit inward normals
    values: npt.NDArray[np.float64]  # (S,): the metric's when force closure, else <= 0
    force_closure: npt.NDArray[np.bool_]  # (S,)
    start_values: npt.NDArray[np.float64]  # (S,)
    start_force_closure: npt.NDArray[np.bool_]  # (S,)
    evaluations: npt.NDArray[np.int64]  # (S,), the start's included
    steps: npt.NDArray[np.int64]  # (S,)
    stop: list[str]  # "step", "evaluations" or "stationary"
    best: Optional[int]  # index of the best force-closure grasp
    total_evaluations: int
    quality_s: float
    gradient_s: float
    other_s: float
    facets_created: int
    torque_reference: npt.NDArray[np.float64]  # (3,)
    torque_scale: float
    metric: str
    method: str
    def __len__(self) -> int: ...

def plan_descent(
    mesh: Union[str, os.PathLike[str], tuple[npt.ArrayLike, npt.ArrayLike]],
    *,
    contacts: int = 4,
    friction: float,
    cone_edges: int,
    metric: str = "q1",
    starts: int = 10,
    evaluations: int = 50,
    screen: int = 1,
    seed: int = 1,
    method: str = "partial",
    space: Optional[ObjectWrenchSpace] = None,
) -> DescentReport: ...
