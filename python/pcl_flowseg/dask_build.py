"""Building a signature database from a large shape collection on a Dask cluster.

The collection's files (every shape file below ROOT, as `flowseg_db build` lists them) are split,
in their sorted order, into shards of `shard_size` files. Each shard is one Dask task: it computes
the signatures of its files and returns them as a database file's text, so workers need to read
the shapes but share no output directory. The client merges the shards in order (Database.merge),
which gives the same database `flowseg_db build DB ROOT` writes.

    from distributed import Client, LocalCluster
    from pcl_flowseg.dask_build import build_database
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        report = build_database("shapes.db", "collection/", client)

On a real cluster, connect the client to its scheduler (Client("tcp://scheduler:8786")) and give
ROOT as a path every worker can read. From the shell:

    python3 -m pcl_flowseg.dask_build shapes.db collection/ --workers 2
    python3 -m pcl_flowseg.dask_build shapes.db /shared/collection --scheduler tcp://scheduler:8786
"""

import argparse
import os
import sys
import tempfile

from ._pcl_flowseg import Database, list_shape_files, shape_label, signature_of_file

__all__ = ["build_database", "shard_signatures", "main"]


def shard_signatures(root, files, params):
    """One task: the signatures of `files` (relative to `root`) as a database file's text, and the
    files that failed as (file, message) pairs. Runs on a worker."""
    db = Database()
    failures = []
    for name in files:
        try:
            sig = signature_of_file(os.path.join(root, name), **params)
        except (OSError, ValueError) as error:
            failures.append((name, str(error)))
            continue
        db.add(name, shape_label(name) or "-", sig)
    with tempfile.TemporaryDirectory(prefix="pcl_flowseg_shard") as work:
        path = os.path.join(work, "shard.db")
        db.save(path)
        with open(path, "rb") as shard:
            return shard.read(), failures


def _check_keywords(params):
    """Raises TypeError / ValueError for keywords signature_of_file would refuse, before any task
    runs: the library checks them before it opens the (here empty) path."""
    try:
        signature_of_file("", **params)
    except OSError:
        pass


def build_database(db_path, root, client, shard_size=25, replace=True, progress=None, **params):
    """Computes the signatures of every shape file below `root` on the Dask `client`'s workers and
    writes them to the database `db_path`.

    replace: True writes the database anew (as `flowseg_db build`); False adds the shapes to the
        database file in one locked transaction (as `flowseg_db merge`), keeping what it holds.
    shard_size: files per task (and per shard).
    progress: None, or a callable(done_shards, all_shards, failures_so_far).
    params: the keywords of signature_of_file (rho, significance, mesh_points, ...). threads
        defaults to 1 here: the workers' tasks run side by side, one core each.
    Returns a dict: shapes (stored), files, failures [(file, message)], shards.
    Raises OSError when root cannot be listed or the database not written; the database is then
    unchanged."""
    if shard_size < 1:
        raise ValueError("shard_size: needs a whole number >= 1, got %r" % (shard_size,))
    params.setdefault("threads", 1)
    _check_keywords(params)
    files = list_shape_files(root)
    if not files:
        raise OSError("no shape files below " + root)
    chunks = [files[i:i + shard_size] for i in range(0, len(files), shard_size)]
    futures = client.map(shard_signatures, [root] * len(chunks), chunks, [params] * len(chunks), pure=False)
    return _merge_shards(db_path, futures, len(files), replace, progress)


def _merge_shards(db_path, futures, file_count, replace, progress):
    """Waits for the shard tasks, then merges their databases in collection order."""
    from distributed import as_completed

    texts = {future.key: None for future in futures}
    failures = []
    done = 0
    for future in as_completed(futures):
        text, shard_failures = future.result()
        texts[future.key] = text
        failures.extend(shard_failures)
        done += 1
        if progress:
            progress(done, len(futures), len(failures))
    with tempfile.TemporaryDirectory(prefix="pcl_flowseg_shards") as work:
        paths = []
        for i, future in enumerate(futures):
            paths.append(os.path.join(work, "shard%06d.db" % i))
            with open(paths[-1], "wb") as shard:
                shard.write(texts[future.key])
        if replace:
            db = Database()
            for path in paths:
                db.merge(Database.open(path))
            db.save(db_path)
            stored = len(db)
        else:
            stored = Database.merge_files(db_path, paths)
    failures.sort()
    return {"shapes": stored, "files": file_count, "failures": failures, "shards": len(futures)}


def _parse_value(text):
    """A --set value as Python would write it: int, float, True/False/None, or a string."""
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    return {"True": True, "False": False, "None": None}.get(text, text)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m pcl_flowseg.dask_build",
        description="Build a signature database from every shape file below ROOT on a Dask cluster "
                    "(the same database as flowseg_db build DB ROOT).")
    parser.add_argument("db", metavar="DB")
    parser.add_argument("root", metavar="ROOT")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="ADDRESS", help="a running Dask scheduler (tcp://host:8786)")
    where.add_argument("--workers", type=int, default=2, metavar="N", help="a local cluster of N worker processes (default 2)")
    parser.add_argument("--shard-size", type=int, default=25, metavar="N", help="files per task (default 25)")
    parser.add_argument("--add", action="store_true", help="add to the database instead of replacing it")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="a keyword of signature_of_file, e.g. --set rho=1.2 --set mesh_points=3000")
    parser.add_argument("-q", "--quiet", action="store_true")
    args = parser.parse_args(argv)
    params = {}
    for item in args.set:
        name, sep, value = item.partition("=")
        if not sep:
            parser.error("--set needs NAME=VALUE, got " + item)
        params[name] = _parse_value(value)
    from distributed import Client, LocalCluster

    def report(done, total, failed):
        if not args.quiet:
            print("\rshards %d/%d, %d files failed" % (done, total, failed), end="", file=sys.stderr, flush=True)

    try:
        if args.scheduler:
            with Client(args.scheduler) as client:
                result = build_database(args.db, args.root, client, args.shard_size, not args.add, report, **params)
        else:
            if args.workers < 1:
                parser.error("--workers needs a whole number >= 1")
            with LocalCluster(n_workers=args.workers, threads_per_worker=1, dashboard_address=None) as cluster, \
                    Client(cluster) as client:
                result = build_database(args.db, args.root, client, args.shard_size, not args.add, report, **params)
    except (OSError, ValueError, TypeError) as error:
        print("\npcl_flowseg.dask_build: " + str(error), file=sys.stderr)
        return 1
    for name, message in result["failures"]:
        print("\npcl_flowseg.dask_build: skipped " + message, file=sys.stderr, end="")
    if not args.quiet:
        print("\n%s: %d shapes from %d files (%d failed, %d shards)" % (
            args.db, result["shapes"], result["files"], len(result["failures"]), result["shards"]), file=sys.stderr)
    return 0 if len(result["failures"]) < result["files"] else 1


if __name__ == "__main__":
    # Run as the package's module, not as __main__: Dask then sends the tasks by reference.
    from pcl_flowseg.dask_build import main as package_main

    sys.exit(package_main())
