"""Shared fixtures: where the build and the sources are, the apps, a small labelled collection."""
import os
import subprocess

import pytest

SOURCE = os.environ.get("PCL_FLOWSEG_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("PCL_FLOWSEG_BUILD", os.path.join(SOURCE, "build"))
SAMPLES = os.path.join(SOURCE, "samples")
NO_SEGMENT = 4294967295  # the label flowseg_segment writes for "no feature"


def app(name):
    path = os.path.join(BUILD, "apps", name)
    if not os.access(path, os.X_OK):
        pytest.skip(name + " is not built")
    return path


def read_label_pcd(path):
    """The label column of an ASCII PointXYZL PCD written by flowseg_segment."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("DATA")) + 1
    return [int(line.split()[3]) for line in lines[start:] if line.strip()]


@pytest.fixture(scope="session")
def collection(tmp_path_factory):
    """Nine generated shapes in three classes (folders), as the app tests make them."""
    root = tmp_path_factory.mktemp("collection")
    generator = app("flowseg_make_samples")
    for seed in (1, 2, 3):
        out = root / ("gen%d" % seed)
        subprocess.run([generator, "--output", str(out), "--points3d", "1500", "--points2d", "300", "--seed", str(seed)],
                       check=True, capture_output=True)
        for shape in ("snowman3d", "dumbbell3d", "animal3d"):
            (root / "tree" / shape).mkdir(parents=True, exist_ok=True)
            os.replace(out / (shape + ".pcd"), root / "tree" / shape / ("%s-%d.pcd" % (shape, seed)))
    return root / "tree"
