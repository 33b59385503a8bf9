"""Python-side figures for the README: the cost of a Python call over the C++ pipeline, and a
database build on Dask against flowseg_db build.

    PYTHONPATH=build/python python3 python/bench/bench_python.py overhead POINTS_FILE [--runs 5]
    PYTHONPATH=build/python python3 python/bench/bench_python.py database ROOT [--workers 1 2] [--shard-size 25]

overhead: segment() on the file's points, several runs; prints the wall time of the Python call,
the pipeline's own total (FlowResult timings, measured inside the C++ call) and their difference
(argument conversion, result objects, labels array).
database: builds ROOT's database with flowseg_db build -j 1 and -j 2, and with
pcl_flowseg.dask_build on LocalClusters of each given number of one-thread workers (cluster
start-up timed apart); checks that every database is byte for byte the same.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import pcl_flowseg as fs


def overhead(path, runs):
    points, _ = fs.read_points(path)
    fs.segment(points)  # warm-up: page cache, allocator, thread pool
    walls, totals = [], []
    for _ in range(runs):
        start = time.perf_counter()
        seg = fs.segment(points)
        labels = seg.labels  # the result as a Python user takes it
        walls.append((time.perf_counter() - start) * 1000)
        totals.append(seg.timings["total"])
        assert len(labels) == len(points)
    extra = [w - t for w, t in zip(walls, totals)]
    print("points %d, runs %d" % (len(points), runs))
    print("| | median ms | min ms |\n|---|---|---|")
    for name, values in (("Python segment() call, labels taken", walls), ("C++ pipeline inside it", totals),
                         ("difference (Python's share)", extra)):
        print("| %s | %.1f | %.1f |" % (name, statistics.median(values), min(values)))
    print("overhead: %.1f%% of the pipeline (median)" % (100 * statistics.median(extra) / statistics.median(totals)))


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def database(root, workers, shard_size, build_dir):
    from distributed import Client, LocalCluster
    from pcl_flowseg.dask_build import build_database

    files = len(fs.list_shape_files(root))
    app = os.path.join(build_dir, "apps", "flowseg_db")
    with tempfile.TemporaryDirectory() as work:
        rows = []
        reference = os.path.join(work, "cli1.db")
        rows.append(("flowseg_db build -j 1", timed([app, "build", reference, root, "-j", "1", "-q"]), None))
        rows.append(("flowseg_db build -j 2", timed([app, "build", os.path.join(work, "cli2.db"), root, "-j", "2", "-q"]), None))
        for n in workers:
            start = time.perf_counter()
            with LocalCluster(n_workers=n, threads_per_worker=1, dashboard_address=None) as cluster, Client(cluster) as client:
                client.wait_for_workers(n)
                ready = time.perf_counter()
                out = os.path.join(work, "dask%d.db" % n)
                report = build_database(out, root, client, shard_size=shard_size)
                rows.append(("Dask, %d worker%s" % (n, "s" if n > 1 else ""), time.perf_counter() - ready, ready - start))
                assert report["files"] == files, report
        same = all(open(os.path.join(work, f), "rb").read() == open(reference, "rb").read()
                   for f in os.listdir(work) if f.endswith(".db"))
    print("%s: %d shape files" % (root, files))
    print("| build | seconds | cluster start-up s |\n|---|---|---|")
    for name, seconds, startup in rows:
        print("| %s | %.2f | %s |" % (name, seconds, "-" if startup is None else "%.2f" % startup))
    print("every database identical: %s" % same)
    return 0 if same else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="what", required=True)
    o = sub.add_parser("overhead")
    o.add_argument("points")
    o.add_argument("--runs", type=int, default=5)
    d = sub.add_parser("database")
    d.add_argument("root")
    d.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    d.add_argument("--shard-size", type=int, default=25)
    d.add_argument("--build", default=os.environ.get("PCL_FLOWSEG_BUILD", "build"))
    args = parser.parse_args()
    if args.what == "overhead":
        overhead(args.points, args.runs)
        return 0
    return database(args.root, args.workers, args.shard_size, args.build)


if __name__ == "__main__":
    sys.exit(main())
