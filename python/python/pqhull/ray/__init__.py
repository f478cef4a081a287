"""Grasp datasets evaluated on a Ray cluster: many objects, each with many grasps.

Install with the `ray` extra (``pip install './python[ray]'``). Each object's grasps are a
:class:`GraspSet` (or a ``.npz`` file: :func:`load_grasp_set` reads it now, :func:`open_grasp_set`
when its grasps are submitted); :func:`evaluate_dataset` splits
every set into chunks, evaluates each chunk as a Ray task with :func:`pqhull.evaluate`, and puts
the results back in input order. An object's wrench space (Q_OWS) is built once, by a task, and
shared through the object store: every chunk of that object receives a reference to it, and each
worker process keeps the spaces it has unpickled for the next chunk.

A worker that dies mid-task loses nothing: Ray runs the task again (``max_retries``), and each
chunk's result is written into its own slot once, so no grasp is missing or counted twice. The
computation is deterministic, so a retried chunk gives the same numbers.

Ray's usage statistics are switched off (``RAY_USAGE_STATS_ENABLED=0``) unless the caller set
that variable.

Command line: ``python -m pqhull.ray evaluate --address auto|local|HOST:PORT --output OUT.npz
INPUT...`` (``python -m pqhull.ray evaluate -h``).
"""

from __future__ import annotations

import dataclasses
import os
import pathlib
import zipfile
from typing import Callable, Iterable, Optional, Sequence, Union

import numpy as np

os.environ.setdefault("RAY_USAGE_STATS_ENABLED", "0")

try:
    import ray
except ImportError as e:  # pragma: no cover - exercised only without the extra
    raise ImportError(
        "pqhull.ray needs Ray: pip install 'pqhull[ray]' (or pip install ray)") from e

import pqhull

__all__ = [
    "GraspSet",
    "GraspFile",
    "ObjectResult",
    "load_grasp_set",
    "open_grasp_set",
    "evaluate_dataset",
    "save_results",
    "load_results",
    "DEFAULT_CHUNK_SIZE",
]

#: Grasps per task: large enough that Ray's per-task cost (about a millisecond) is small next to
#: the evaluation (tens of microseconds per Q1 grasp), small enough to spread a set over a cluster.
DEFAULT_CHUNK_SIZE = 2048

#: Keys a grasp-set file may hold; anything else is refused (a typo must not be ignored).
FILE_KEYS = ("positions", "normals", "tangents", "torsion", "friction", "cone_edges",
             "torque_reference", "torque_scale", "vertices", "faces", "disturbances",
             "ows_friction", "ows_edges")


@dataclasses.dataclass
class GraspSet:
    """One object's grasps, as :func:`pqhull.evaluate` takes them, and what its wrench space is
    built from (for ``metric="ows"``).

    - ``positions``, ``normals`` (and optional ``tangents``): (N, m, 3) arrays;
    - ``torsion`` (optional): soft contacts' torsional friction, one number or (N, m);
    - ``friction``: one value or one per grasp; ``cone_edges``: the friction pyramid's edges;
    - ``torque_reference`` (3,), ``torque_scale``: the grasps' torque frame (ignored for a space
      built from a mesh, which sets its own);
    - the wrench space, at most one of: ``space`` (an :class:`pqhull.ObjectWrenchSpace` already
      built), ``vertices`` and ``faces`` (a mesh, built on the cluster with ``ows_friction`` and
      ``ows_edges``), or ``disturbances`` ((k, 6), a task wrench space).
    """

    name: str
    positions: np.ndarray
    normals: np.ndarray
    friction: Union[float, np.ndarray]
    cone_edges: int
    tangents: Optional[np.ndarray] = None
    torsion: Optional[Union[float, np.ndarray]] = None
    torque_reference: Optional[np.ndarray] = None
    torque_scale: Optional[float] = None
    space: Optional[pqhull.ObjectWrenchSpace] = None
    vertices: Optional[np.ndarray] = None
    faces: Optional[np.ndarray] = None
    disturbances: Optional[np.ndarray] = None
    ows_friction: Optional[float] = None
    ows_edges: Optional[int] = None

    def __len__(self) -> int:
        return len(self.positions)

    def check(self, needs_space: bool) -> None:
        """Raises :class:`pqhull.InputError` naming this set when its arrays cannot be
        evaluated as a whole (bad rows are reported per row by the evaluation instead)."""
        self.positions = np.ascontiguousarray(self.positions, dtype=np.float64)
        self.normals = np.ascontiguousarray(self.normals, dtype=np.float64)
        if self.tangents is not None:
            self.tangents = np.ascontiguousarray(self.tangents, dtype=np.float64)
        friction = np.asarray(self.friction, dtype=np.float64)
        self.friction = friction if friction.ndim == 1 else float(friction)
        if self.torsion is not None:
            torsion = np.asarray(self.torsion, dtype=np.float64)
            self.torsion = torsion if torsion.ndim > 0 else float(torsion)
        shapes = {key: np.shape(getattr(self, key)) for key in
                  ("positions", "normals", "tangents", "torsion", "friction", "vertices",
                   "disturbances") if getattr(self, key) is not None}
        present = {key for key in ("space", "faces", "ows_friction", "ows_edges")
                   if getattr(self, key) is not None}
        _check_layout(self.name, shapes, present, needs_space)


def _check_layout(name, shapes, present, needs_space):
    """What :meth:`GraspSet.check` checks, from the arrays' shapes alone (`present`: the other
    fields given), so that a file can be checked from its headers."""
    def fail(message):
        raise pqhull.InputError(f"grasp set {name!r}: {message}")

    shape = shapes["positions"]
    if len(shape) != 3 or shape[2] != 3:
        fail(f"positions must have shape (N, m, 3), not {shape}")
    for key in ("normals", "tangents"):
        if key in shapes and shapes[key] != shape:
            fail(f"{key} have shape {shapes[key]}, positions {shape}")
    friction = shapes["friction"]
    if len(friction) > 1 or (len(friction) == 1 and friction[0] != shape[0]):
        fail(f"friction must be one number or one per grasp ({shape[0]}), not shape {friction}")
    if "torsion" in shapes and shapes["torsion"] not in ((), shape[:2]):
        fail(f"torsion must be one number or one per contact {shape[:2]}, "
             f"not shape {shapes['torsion']}")
    sources = [n for n in ("space", "vertices", "disturbances") if n in shapes or n in present]
    if len(sources) > 1:
        fail(f"give one wrench space, not {' and '.join(sources)}")
    if ("vertices" in shapes) != ("faces" in present):
        fail("a mesh needs both vertices and faces")
    if "vertices" in shapes and not {"ows_friction", "ows_edges"} <= present:
        fail("a mesh's wrench space needs ows_friction and ows_edges")
    if needs_space and not sources:
        fail("metric 'ows' needs a wrench space (space, vertices and faces, or disturbances)")


@dataclasses.dataclass
class ObjectResult:
    """One grasp set's results, in its grasps' order: ``quality`` (N,) (NaN where a row was bad
    or, for Q_OWS, not force closure), ``force_closure`` (N,), ``errors`` as (row, message)."""

    name: str
    quality: np.ndarray
    force_closure: np.ndarray
    errors: list


def load_grasp_set(path, **defaults) -> GraspSet:
    """A grasp set from a ``.npz`` file whose arrays are named as :class:`GraspSet`'s fields
    (``positions``, ``normals``, …); its name is the file's stem. ``defaults`` fill fields the
    file does not hold (``friction=0.5``, ``cone_edges=8``, …). The whole file is read now;
    :func:`open_grasp_set` reads it only when its grasps are evaluated."""
    path = pathlib.Path(path)
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {key: data[key] for key in data.files}
    except (OSError, ValueError) as e:
        raise pqhull.InputError(f"{path}: not a readable .npz file ({e})") from None
    _known(path, arrays)
    fields = dict(defaults)
    for key, value in arrays.items():
        if key in ("cone_edges", "ows_edges"):
            fields[key] = int(value)
        elif key in ("torque_scale", "ows_friction"):
            fields[key] = float(value)
        else:
            fields[key] = value
    _required(path, fields)
    return GraspSet(name=path.stem, **fields)


def _known(path, keys):
    unknown = sorted(set(keys) - set(FILE_KEYS))
    if unknown:
        raise pqhull.InputError(f"{path}: unknown arrays {unknown}; known: {list(FILE_KEYS)}")


def _required(path, fields):
    for key in ("positions", "normals", "friction", "cone_edges"):
        if key not in fields:
            raise pqhull.InputError(f"{path}: no {key!r} (in the file or given as a default)")


@dataclasses.dataclass
class GraspFile:
    """A grasp set still on disk (:func:`open_grasp_set`): checked from its arrays' headers,
    read when :func:`evaluate_dataset` reaches it, and let go once its last chunk is submitted,
    so a dataset of many files needs the driver's memory for one file at a time."""

    path: pathlib.Path
    name: str
    defaults: dict
    shapes: dict
    present: set

    def __len__(self) -> int:
        return self.shapes["positions"][0]

    def check(self, needs_space: bool) -> None:
        """As :meth:`GraspSet.check`, from the headers."""
        _check_layout(self.name, self.shapes, self.present, needs_space)

    def load(self) -> GraspSet:
        """The set, read from the file now."""
        return load_grasp_set(self.path, **self.defaults)


def open_grasp_set(path, **defaults) -> GraspFile:
    """A grasp set file (as :func:`load_grasp_set`) opened without reading its arrays: only
    their names and shapes (the ``.npy`` headers inside the ``.npz``) are read and checked."""
    path = pathlib.Path(path)
    shapes = {}
    try:
        with zipfile.ZipFile(path) as archive:
            for member in archive.namelist():
                key = member[:-4] if member.endswith(".npy") else member
                with archive.open(member) as f:
                    version = np.lib.format.read_magic(f)
                    read = (np.lib.format.read_array_header_1_0 if version == (1, 0)
                            else np.lib.format.read_array_header_2_0)
                    shapes[key] = tuple(read(f)[0])
    except (OSError, ValueError, zipfile.BadZipFile) as e:
        raise pqhull.InputError(f"{path}: not a readable .npz file ({e})") from None
    _known(path, shapes)
    fields = {**{key: () for key in defaults}, **shapes}
    _required(path, fields)
    array_keys = ("positions", "normals", "tangents", "torsion", "friction", "vertices",
                  "disturbances")
    return GraspFile(path, path.stem, dict(defaults),
                     {key: tuple(fields[key]) for key in array_keys if key in fields},
                     {key for key in fields if key not in array_keys})


def _frame(reference, scale):
    return dict(torque_reference=reference, torque_scale=scale)


@ray.remote(num_cpus=1)
def _build_space(vertices, faces, disturbances, friction, cone_edges):
    if vertices is not None:
        return pqhull.ObjectWrenchSpace.from_arrays(vertices, faces, friction=friction,
                                                    cone_edges=cone_edges)
    return pqhull.ObjectWrenchSpace.from_disturbances(disturbances)


# The spaces this worker process has unpickled, by object reference: a worker runs many chunks
# of one object in a row, and a mesh's space (tens of thousands of wrenches and their index)
# is worth keeping. Bounded, oldest out.
_SPACES: dict = {}
_SPACES_KEPT = 4


def _space(boxed):
    """The space behind a reference passed in a list (so that Ray hands over the reference, not
    a fresh copy per task)."""
    ref = boxed[0]
    key = ref.hex()
    if key not in _SPACES:
        if len(_SPACES) >= _SPACES_KEPT:
            _SPACES.pop(next(iter(_SPACES)))
        _SPACES[key] = ray.get(ref)
    return _SPACES[key]


@ray.remote(num_cpus=1)
def _evaluate_chunk(positions, normals, tangents, torsion, friction, cone_edges, frame,
                    boxed_space, options):
    space = None if boxed_space is None else _space(boxed_space)
    batch = pqhull.evaluate(positions, normals, tangents, torsion=torsion, friction=friction,
                            cone_edges=cone_edges, space=space, threads=1, **frame, **options)
    return batch.quality, batch.force_closure, batch.errors


def _connect(address, node_ip_address):
    """Joins (or starts) a Ray cluster; returns whether this call started the session (and so
    must end it)."""
    if address is None and ray.is_initialized():
        return False
    extra = {} if node_ip_address is None else {"_node_ip_address": node_ip_address}
    if address == "local":  # Ray's own word for "a new cluster, even if one is running here"
        extra["include_dashboard"] = False
    ray.init(address=address, **extra)
    return True


def evaluate_dataset(
    grasp_sets: Iterable[Union[GraspSet, GraspFile]],
    *,
    metric: str = "q1",
    method: str = "partial",
    with_zero_wrench: bool = False,
    wrench: Optional[Sequence[float]] = None,
    chunk_size: int = DEFAULT_CHUNK_SIZE,
    address: Optional[str] = None,
    node_ip_address: Optional[str] = None,
    max_in_flight: Optional[int] = None,
    max_retries: int = 3,
    progress: Optional[Callable[[int, int], None]] = None,
) -> list:
    """Evaluates every grasp set on Ray and returns one :class:`ObjectResult` per set, in input
    order, each equal (bit for bit) to :func:`pqhull.evaluate` on that set alone. ``metric``,
    ``method``, ``with_zero_wrench`` and ``wrench`` (for ``"resist"``) are
    :func:`pqhull.evaluate`'s. A :class:`GraspFile` is read when its first chunk is submitted
    and let go after its last, so only one file's arrays are in the driver's memory at a time.

    ``address``: ``None`` uses the current Ray session (or starts one as ``ray.init()`` does),
    ``"local"`` starts a single-machine cluster for this call, ``"auto"`` or ``"HOST:PORT"``
    joins a running cluster. ``max_in_flight`` bounds the chunks submitted but not collected
    (default: twice the cluster's CPUs, plus two), so that a large dataset is not copied into
    the object store at once. ``max_retries``: how often Ray re-runs a chunk whose worker
    died. ``progress(done, total)`` is called with grasp counts once connected, before the first
    chunk is submitted, and after every chunk.

    Raises :class:`pqhull.InputError` naming the set for arrays that cannot be evaluated as a
    whole; a bad row is NaN plus an error entry in its set's result, as in
    :func:`pqhull.evaluate`.
    """
    if chunk_size < 1:
        raise pqhull.InputError(f"chunk_size must be at least 1, not {chunk_size}")
    if max_retries < 0:
        raise pqhull.InputError(f"max_retries must be at least 0, not {max_retries}")
    sets = list(grasp_sets)
    for s in sets:
        s.check(needs_space=metric == "ows")
    options = dict(metric=metric, method=method, with_zero_wrench=with_zero_wrench)
    if wrench is not None:
        options["wrench"] = np.asarray(wrench, dtype=np.float64)
    _check_options(options)
    started_here = _connect(address, node_ip_address)
    try:
        return _run(sets, options, chunk_size, max_in_flight, max_retries, progress)
    finally:
        if started_here:
            ray.shutdown()


def _check_options(options):
    """Raises what :func:`pqhull.evaluate` raises for these options (an unknown metric, a method
    the metric does not take, a zero wrench to resist), before anything is submitted: an empty
    batch runs every check on them."""
    empty = np.zeros((0, 1, 3))
    space = (pqhull.ObjectWrenchSpace.from_disturbances(np.eye(6))
             if options["metric"] == "ows" else None)
    pqhull.evaluate(empty, empty, friction=0.5, cone_edges=4, space=space, **options)


def _run(sets, options, chunk_size, max_in_flight, max_retries, progress):
    evaluate = _evaluate_chunk.options(max_retries=max_retries, retry_exceptions=False)
    build = _build_space.options(max_retries=max_retries, retry_exceptions=False)
    results = [ObjectResult(s.name, np.full(len(s), np.nan), np.zeros(len(s), dtype=bool), [])
               for s in sets]
    chunks = ((i, start, min(start + chunk_size, len(s)))
              for i, s in enumerate(sets) for start in range(0, len(s), chunk_size))
    total = sum(len(s) for s in sets)
    if max_in_flight is None:
        max_in_flight = 2 * int(ray.cluster_resources().get("CPU", 1)) + 2
    # The set whose chunks are being submitted, its arrays and its space: chunks come set by set,
    # so a file's arrays are dropped (the submitted chunks hold their own slices) when the next
    # set starts.
    current = {}

    def open_set(i):
        s = sets[i]
        if isinstance(s, GraspFile):
            s = s.load()
            s.check(needs_space=options["metric"] == "ows")
        if options["metric"] != "ows":
            space = None
        elif s.space is not None:
            space = [ray.put(s.space)]
        else:
            space = [build.remote(s.vertices, s.faces, s.disturbances, s.ows_friction,
                                  s.ows_edges)]
        current.clear()
        current[i] = (s, space)

    def submit(i, start, stop):
        if i not in current:
            open_set(i)
        s, space = current[i]
        rows = slice(start, stop)
        friction = s.friction if np.ndim(s.friction) == 0 else s.friction[rows]
        torsion = s.torsion if np.ndim(s.torsion) == 0 else s.torsion[rows]
        tangents = None if s.tangents is None else s.tangents[rows]
        frame = _frame(s.torque_reference, s.torque_scale)
        return evaluate.remote(s.positions[rows], s.normals[rows], tangents, torsion, friction,
                               s.cone_edges, frame, space, options)

    pending, done = {}, 0
    if progress is not None:
        progress(0, total)
    while True:
        for chunk in chunks:
            pending[submit(*chunk)] = chunk
            if len(pending) >= max_in_flight:
                break
        if not pending:
            break
        ready, _ = ray.wait(list(pending), num_returns=1)
        for ref in ready:
            i, start, stop = pending.pop(ref)
            try:
                quality, force_closure, errors = ray.get(ref)
            except ray.exceptions.RayTaskError as e:
                raise _located(e, f"grasp set {sets[i].name!r}, grasps {start}..{stop}") from e
            results[i].quality[start:stop] = quality
            results[i].force_closure[start:stop] = force_closure
            results[i].errors.extend(_shifted(row, message, start) for row, message in errors)
            done += stop - start
            if progress is not None:
                progress(done, total)
    for r in results:
        r.errors.sort()
    return results


def _located(error, where):
    """A task's failure as the caller's exception: a pqhull error keeps its type (raised in a
    worker, e.g. a mesh that is not a solid), anything else becomes a RuntimeError; both say
    which set and grasps failed."""
    cause = getattr(error, "cause", None)
    if isinstance(cause, pqhull.Error):
        return type(cause)(f"{where}: {cause}")
    return RuntimeError(f"{where}: {error}")


def _shifted(row, message, start):
    """A chunk's error entry renumbered to its set's rows ("row 3: ..." of the chunk starting
    at 2048 is "row 2051: ..." of the set)."""
    prefix = f"row {row}: "
    if message.startswith(prefix):
        message = f"row {start + row}: " + message[len(prefix):]
    return (start + row, message)


def save_results(path, results: Sequence[ObjectResult]) -> None:
    """Writes results to a ``.npz`` file: ``names`` (one per set), ``offsets`` (set i's grasps
    are ``offsets[i]:offsets[i+1]``), ``quality`` and ``force_closure`` (all sets, in order),
    and the errors as ``error_set``, ``error_row`` and ``error_message``."""
    offsets = np.cumsum([0] + [len(r.quality) for r in results])
    errors = [(i, row, message) for i, r in enumerate(results) for row, message in r.errors]
    np.savez(
        path,
        names=np.array([r.name for r in results], dtype=str),
        offsets=offsets.astype(np.int64),
        quality=np.concatenate([r.quality for r in results]) if results else np.zeros(0),
        force_closure=(np.concatenate([r.force_closure for r in results]) if results
                       else np.zeros(0, dtype=bool)),
        error_set=np.array([e[0] for e in errors], dtype=np.int64),
        error_row=np.array([e[1] for e in errors], dtype=np.int64),
        error_message=np.array([e[2] for e in errors], dtype=str),
    )


def load_results(path) -> list:
    """Reads what :func:`save_results` wrote."""
    with np.load(path, allow_pickle=False) as data:
        names, offsets = data["names"], data["offsets"]
        results = [ObjectResult(str(name), data["quality"][a:b], data["force_closure"][a:b], [])
                   for name, a, b in zip(names, offsets[:-1], offsets[1:])]
        for i, row, message in zip(data["error_set"], data["error_row"], data["error_message"]):
            results[i].errors.append((int(row), str(message)))
    return results
