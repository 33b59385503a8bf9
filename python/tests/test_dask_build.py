"""The Dask database build: the same database as flowseg_db build, on a LocalCluster of two workers."""
import subprocess
import sys

import pytest

import pcl_flowseg as fs
from conftest import app

distributed = pytest.importorskip("distributed")


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None, processes=True) as cluster, \
            distributed.Client(cluster) as c:
        yield c


def test_dask_build_equals_flowseg_db_build(collection, tmp_path, client):
    from pcl_flowseg.dask_build import build_database

    whole = str(tmp_path / "cli.db")
    subprocess.run([app("flowseg_db"), "build", whole, str(collection), "-q"], check=True)
    built = str(tmp_path / "dask.db")
    seen = []
    report = build_database(built, str(collection), client, shard_size=2, progress=lambda *a: seen.append(a))
    assert report == {"shapes": 9, "files": 9, "failures": [], "shards": 5}
    assert seen[-1] == (5, 5, 0)
    assert open(built, "rb").read() == open(whole, "rb").read()


def test_dask_build_adds_and_reports_failures(collection, tmp_path, client):
    from pcl_flowseg.dask_build import build_database

    (collection.parent / "broken").mkdir(exist_ok=True)
    bad_root = collection.parent / "broken"
    (bad_root / "cls").mkdir(exist_ok=True)
    (bad_root / "cls" / "bad.pcd").write_text("not a pcd\n")
    good = collection / "animal3d" / "animal3d-1.pcd"
    (bad_root / "cls" / "good.pcd").write_bytes(good.read_bytes())
    db = str(tmp_path / "add.db")
    fs.Database.add_to_file(db, [("kept", "x", fs.signature_of_file(str(good)))])
    report = build_database(db, str(bad_root), client, replace=False)
    assert report["shapes"] == 2 and [f for f, _ in report["failures"]] == ["cls/bad.pcd"]
    assert "kept" in fs.Database.open(db)
    with pytest.raises(OSError):
        build_database(db, str(tmp_path / "missing"), client)
    with pytest.raises(TypeError):
        build_database(db, str(collection), client, frobnicate=1)
    with pytest.raises(TypeError):
        build_database(db, str(collection), client, alignment_points=2)  # a matching keyword
    with pytest.raises(ValueError, match="rho"):
        build_database(db, str(collection), client, rho=-1)
    assert "kept" in fs.Database.open(db)
    with pytest.raises(ValueError):
        build_database(db, str(collection), client, shard_size=0)


def test_command_line(collection, tmp_path):
    out = str(tmp_path / "cmd.db")
    run = subprocess.run([sys.executable, "-m", "pcl_flowseg.dask_build", out, str(collection), "--workers", "1", "-q",
                          "--set", "rho=1.05"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert len(fs.Database.open(out)) == 9
    bad = subprocess.run([sys.executable, "-m", "pcl_flowseg.dask_build", out, str(tmp_path / "none"), "--workers", "1", "-q"],
                         capture_output=True, text=True)
    assert bad.returncode == 1 and "cannot open" in bad.stderr
