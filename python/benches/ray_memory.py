"""The Ray driver's peak memory with every file read up front (`load_grasp_set`) against files
opened from their headers and read when their chunks are submitted (`open_grasp_set`, what
`python -m pqhull.ray evaluate` does).

Run it as root (it makes a loopback-only network namespace for the cluster), after
`pip install './python[ray]'`:

    python python/benches/ray_memory.py [--objects 12] [--grasps 40000]

It writes `objects` .npz files of random 4-contact grasps (positions and normals: 192 bytes per
grasp), starts a one-node cluster with two CPUs, and runs one driver process per way of reading
the files, each evaluating the whole dataset (Q1 is not the point here: isotropy, whose value is
an SVD, keeps the run short) and reporting its own peak resident memory (`ru_maxrss`). Both
drivers' results are checked equal.
"""

import argparse
import pathlib
import sys
import tempfile
import textwrap

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))
import loopback_cluster  # noqa: E402

DRIVER = textwrap.dedent("""
    import resource, sys, pathlib
    import numpy as np
    from pqhull import ray as pqray
    mode, directory, address, out = sys.argv[1:5]
    files = sorted(pathlib.Path(directory).glob("*.npz"))
    read = pqray.load_grasp_set if mode == "load" else pqray.open_grasp_set
    sets = [read(f) for f in files]
    results = pqray.evaluate_dataset(sets, metric="isotropy", address=address,
                                     node_ip_address="127.0.0.1")
    pqray.save_results(out, results)
    print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
""")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--objects", type=int, default=12)
    parser.add_argument("--grasps", type=int, default=40000)
    args = parser.parse_args()
    reason = loopback_cluster.unavailable()
    if reason:
        sys.exit(f"ray_memory: {reason}")
    with tempfile.TemporaryDirectory() as tmp:
        directory = pathlib.Path(tmp) / "data"
        directory.mkdir()
        rng = np.random.default_rng(0)
        for i in range(args.objects):
            normals = rng.standard_normal((args.grasps, 4, 3))
            normals /= np.linalg.norm(normals, axis=2, keepdims=True)
            np.savez(directory / f"object{i:03}.npz", positions=-normals, normals=normals,
                     friction=0.5, cone_edges=8)
        size = sum(f.stat().st_size for f in directory.glob("*.npz")) / 2**20
        print(f"{args.objects} files x {args.grasps:,} grasps: {size:.0f} MiB of arrays")
        peaks = {}
        with loopback_cluster.loopback_cluster(nodes=1, cpus_per_node=2) as cluster:
            for mode in ("load", "open"):
                out = pathlib.Path(tmp) / f"{mode}.npz"
                result = cluster.run(sys.executable, "-c", DRIVER, mode, directory,
                                     cluster.address, out)
                peaks[mode] = int(result.stdout.split()[-1]) / 1024
                print(f"{mode:>4}: driver peak resident memory {peaks[mode]:.0f} MiB")
            a, b = (np.load(pathlib.Path(tmp) / f"{m}.npz") for m in ("load", "open"))
            assert np.array_equal(a["quality"], b["quality"], equal_nan=True)
        print(f"open / load: {peaks['open'] / peaks['load']:.2f}; "
              f"saved {peaks['load'] - peaks['open']:.0f} MiB")


if __name__ == "__main__":
    main()
