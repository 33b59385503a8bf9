"""The Open3D example: run when python3-open3d is installed, skipped otherwise."""
import os
import subprocess
import sys

import numpy as np
import pytest

import pcl_flowseg as fs
from conftest import SAMPLES, SOURCE

o3d = pytest.importorskip("open3d")


def test_open3d_cloud_segments_like_the_file(tmp_path):
    sample = os.path.join(SAMPLES, "animal3d.pcd")
    cloud = o3d.io.read_point_cloud(sample)
    labels = fs.segment(np.asarray(cloud.points)).labels
    assert (labels == fs.segment(fs.read_points(sample)[0]).labels).all()


def test_example_writes_a_coloured_cloud(tmp_path):
    out = str(tmp_path / "coloured.ply")
    run = subprocess.run([sys.executable, os.path.join(SOURCE, "python", "examples", "open3d_segment.py"),
                          os.path.join(SAMPLES, "animal3d.pcd"), out], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "features" in run.stdout
    assert o3d.io.read_point_cloud(out).has_colors()
