"""Segmenting an Open3D point cloud with pcl_flowseg and colouring it by feature.

    python3 open3d_segment.py INPUT.ply|.pcd [OUTPUT.ply]

Reads the cloud with Open3D, hands its points to pcl_flowseg.segment as a numpy array (no copy on
the Open3D side), colours every point by its feature (grey: none) and writes the coloured cloud.
"""
import sys

import numpy as np
import open3d as o3d

import pcl_flowseg as fs


def colour_by_feature(labels, seed=7):
    """One random colour per feature, grey for points without one."""
    rng = np.random.default_rng(seed)
    palette = rng.uniform(0.2, 1.0, size=(max(int(labels.max()) + 1, 1), 3))
    colours = np.full((len(labels), 3), 0.5)
    colours[labels >= 0] = palette[labels[labels >= 0]]
    return colours


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    cloud = o3d.io.read_point_cloud(argv[1])
    points = np.asarray(cloud.points)
    if len(points) == 0:
        print("open3d_segment: no points read from " + argv[1], file=sys.stderr)
        return 1
    normals = np.asarray(cloud.normals) if cloud.has_normals() else None
    try:
        seg = fs.segment(points, normals)
    except ValueError as error:
        print("open3d_segment: " + str(error), file=sys.stderr)
        return 1
    cloud.colors = o3d.utility.Vector3dVector(colour_by_feature(seg.labels))
    print("%d points, %d features (%d significant), %.0f ms" % (
        len(points), len(seg.features), len(seg.significant), seg.timings["total"]))
    if len(argv) == 3 and not o3d.io.write_point_cloud(argv[2], cloud):
        print("open3d_segment: cannot write " + argv[2], file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
