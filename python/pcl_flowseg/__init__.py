"""pcl_flowseg: shape segmentation and matching by flow discretization.

The method of Dey, Giesen and Goswami, "Shape Segmentation and Matching with Flow Discretization":
the Delaunay triangulation of a 2D or 3D point sample, the flow of the distance function between
its cells, the stable manifolds of the maxima merged into features, and signatures of the
significant features that are matched invariantly to rotation, translation, mirroring and scale.

    import numpy as np, pcl_flowseg as fs
    seg = fs.segment(points)                  # (n, 2) or (n, 3) float array
    seg.labels                                # feature of each point, -1 for none
    [f.volume for f in seg.features]
    sig = seg.signature()
    fs.match(sig, fs.signature_of_file("other.ply")).similarity
    db = fs.Database.open("shapes.db"); db.query(sig, k=5)

Every keyword is a field of the C++ parameters, with the same name and default: see defaults().
Bad input raises ValueError (arrays, parameters, unsegmentable samples), TypeError (unknown
keywords) or OSError (files). The computation releases the GIL.

The C++ library is the module _pcl_flowseg; dask_build builds databases on a Dask cluster.
"""

from ._pcl_flowseg import (  # noqa: F401
    Database,
    Feature,
    MatchResult,
    QueryHit,
    Segmentation,
    Signature,
    defaults,
    list_shape_files,
    match,
    paper_rule,
    read_points,
    read_shape,
    segment,
    shape_label,
    signature,
    signature_of_file,
)

__all__ = [
    "Database", "Feature", "MatchResult", "QueryHit", "Segmentation", "Signature", "defaults",
    "list_shape_files", "match", "paper_rule", "read_points", "read_shape", "segment", "shape_label",
    "signature", "signature_of_file",
]
