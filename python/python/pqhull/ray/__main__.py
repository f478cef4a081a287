"""python -m pqhull.ray evaluate: a grasp dataset (one .npz file per object) evaluated on Ray."""

from __future__ import annotations

import argparse
import pathlib
import sys
import time

import pqhull
from pqhull import ray as pqray


def _inputs(paths):
    """The .npz files named, a directory standing for the .npz files in it (sorted)."""
    files = []
    for path in map(pathlib.Path, paths):
        if path.is_dir():
            found = sorted(path.glob("*.npz"))
            if not found:
                raise pqhull.InputError(f"{path}: no .npz file in this directory")
            files.extend(found)
        elif path.exists():
            files.append(path)
        else:
            raise pqhull.InputError(f"{path}: no such file or directory")
    return files


class _Progress:
    """One line on stderr at most every `interval` seconds, and one at the end."""

    def __init__(self, quiet, interval=1.0):
        self.quiet, self.interval = quiet, interval
        self.started = self.last = self.finished = None

    def __call__(self, done, total):
        now = time.perf_counter()
        if self.started is None:  # the first call: connected, nothing submitted yet
            self.started = self.last = now
        if done == total:
            self.finished = now
        if self.quiet or (done < total and now - self.last < self.interval):
            return
        self.last = now
        elapsed = now - self.started
        rate = done / elapsed if elapsed > 0 else 0.0
        print(f"pqhull.ray: {done:,} / {total:,} grasps ({done / max(total, 1):.0%}), "
              f"{elapsed:.1f} s, {rate:,.0f} grasps/s", file=sys.stderr, flush=True)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m pqhull.ray")
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser(
        "evaluate", help="evaluate a grasp dataset on Ray and write the results to a .npz file",
        description="Evaluates every grasp of every object (one .npz file per object, arrays "
        "named as pqhull.ray.GraspSet's fields: positions, normals, friction, cone_edges, ...) "
        "as Ray tasks and writes the results, in input order, to OUTPUT (see "
        "pqhull.ray.save_results for its arrays). Exit status: 0 done, 2 bad input.")
    run.add_argument("inputs", nargs="+", metavar="INPUT",
                     help="a .npz grasp set, or a directory of them")
    run.add_argument("--output", "-o", required=True, help="the results file (.npz)")
    run.add_argument("--address", default="local",
                     help="'local' (a one-machine cluster for this run, the default), 'auto' "
                     "(the running cluster) or HOST:PORT")
    run.add_argument("--node-ip-address", help="this machine's address in the cluster")
    run.add_argument("--metric", default="q1",
                     choices=["q1", "qinf", "ows", "resist", "volume", "sigma-min", "isotropy"])
    run.add_argument("--wrench", help="resist: the wrench to resist, fx,fy,fz,tx,ty,tz in the "
                     "grasps' torque units (as pqh grasp --wrench)")
    run.add_argument("--method", default="partial",
                     help="partial (the default), full, qhull, partial-rays or ellipsoid, as "
                     "pqh grasp --method")
    run.add_argument("--with-zero-wrench", action="store_true",
                     help="Q-infinity: include the zero wrench (as pqh grasp)")
    run.add_argument("--friction", type=float,
                     help="friction coefficient for sets whose file has none")
    run.add_argument("--cone-edges", type=int, help="cone edges for sets whose file has none")
    run.add_argument("--torsion", type=float,
                     help="soft contacts' torsion (a length) for sets whose file has none")
    run.add_argument("--ows-friction", type=float,
                     help="friction of the object wrench space's cones, for mesh sets whose "
                     "file has none")
    run.add_argument("--ows-edges", type=int,
                     help="edges of the object wrench space's cones, likewise")
    run.add_argument("--chunk-size", type=int, default=pqray.DEFAULT_CHUNK_SIZE,
                     help="grasps per Ray task (default %(default)s)")
    run.add_argument("--max-retries", type=int, default=3,
                     help="how often a task whose worker died is run again (default %(default)s)")
    run.add_argument("--quiet", "-q", action="store_true", help="no progress lines")
    args = parser.parse_args(argv)

    defaults = {key: value for key, value in (
        ("friction", args.friction), ("cone_edges", args.cone_edges), ("torsion", args.torsion),
        ("ows_friction", args.ows_friction), ("ows_edges", args.ows_edges)) if value is not None}
    try:
        wrench = None
        if args.wrench is not None:
            try:
                wrench = [float(x) for x in args.wrench.split(",")]
            except ValueError:
                raise pqhull.InputError(f"--wrench {args.wrench!r}: six numbers, comma "
                                        "separated") from None
        # Opened, not read: each file is read when its grasps are submitted.
        sets = [pqray.open_grasp_set(path, **defaults) for path in _inputs(args.inputs)]
        progress = _Progress(args.quiet)
        results = pqray.evaluate_dataset(
            sets, metric=args.metric, method=args.method,
            with_zero_wrench=args.with_zero_wrench, wrench=wrench, chunk_size=args.chunk_size,
            address=args.address, node_ip_address=args.node_ip_address,
            max_retries=args.max_retries, progress=progress)
        elapsed = (progress.finished or 0.0) - (progress.started or 0.0)
    except pqhull.Error as e:
        print(f"pqhull.ray: {e}", file=sys.stderr)
        return 2
    pqray.save_results(args.output, results)
    if not args.quiet:
        grasps = sum(len(r.quality) for r in results)
        errors = sum(len(r.errors) for r in results)
        rate = grasps / elapsed if elapsed > 0 else 0.0
        print(f"pqhull.ray: {grasps:,} grasps of {len(results)} objects in {elapsed:.2f} s "
              f"({rate:,.0f} grasps/s; connecting and disconnecting not counted), {errors} bad rows; wrote {args.output}",
              file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
