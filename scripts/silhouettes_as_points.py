#!/usr/bin/env python3
"""Turns a folder tree of silhouette images into the point files held-out 2D sets arrive as.

Each image's boundary (the pixel-edge midpoints of its staircase outline, as pcl_flowseg reads an
image) is subsampled to N points (default 1,000; all when fewer), each moved by a uniform jitter of
up to a quarter pixel in x and y, and written as an `x y 0` text file ROOT_OUT/<class>/<name>.xyz.

usage: PYTHONPATH=build/python python3 scripts/silhouettes_as_points.py ROOT OUT [--points N] [--seed S]
"""
import argparse
import os
import sys

import numpy as np

import pcl_flowseg as fs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root")
    parser.add_argument("out")
    parser.add_argument("--points", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    if args.points < 3:
        parser.error("--points must be at least 3")
    rng = np.random.default_rng(args.seed)
    files = [f for f in fs.list_shape_files(args.root) if f.lower().endswith((".png", ".bmp", ".pgm"))]
    if not files:
        sys.exit("no silhouette images below " + args.root)
    for relative in files:
        boundary = fs.read_shape(os.path.join(args.root, relative))
        keep = rng.choice(len(boundary), size=min(args.points, len(boundary)), replace=False)
        points = boundary[np.sort(keep)].copy()
        points[:, :2] += rng.uniform(-0.25, 0.25, size=(len(points), 2))
        target = os.path.join(args.out, os.path.splitext(relative)[0] + ".xyz")
        os.makedirs(os.path.dirname(target), exist_ok=True)
        np.savetxt(target, points, fmt="%.4f")
    print("wrote %d point files below %s" % (len(files), args.out))


if __name__ == "__main__":
    main()
