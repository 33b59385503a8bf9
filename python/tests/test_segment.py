"""segment(): the same labels as flowseg_segment, parameters that round-trip, every bad input."""
import glob
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import pcl_flowseg as fs
from conftest import NO_SEGMENT, SAMPLES, app, read_label_pcd


@pytest.mark.parametrize("sample", sorted(glob.glob(os.path.join(SAMPLES, "*.pcd"))), ids=os.path.basename)
def test_labels_equal_flowseg_segment(sample, tmp_path):
    prefix = str(tmp_path / "out")
    subprocess.run([app("flowseg_segment"), sample, "-o", prefix, "-q"], check=True)
    expected = read_label_pcd(prefix + ".labels.pcd")
    points, normals = fs.read_points(sample)
    labels = fs.segment(points).labels
    assert labels.dtype == np.int64 and len(labels) == len(expected)
    assert [NO_SEGMENT if v < 0 else v for v in labels.tolist()] == expected
    assert normals is None  # the samples carry no normals


def test_result_holds_features_adjacency_timings():
    points, _ = fs.read_points(os.path.join(SAMPLES, "animal3d.pcd"))
    seg = fs.segment(points)
    assert seg.dimension == 3 and seg.input_points == len(points)
    features = seg.features
    assert len(features) >= 5
    assert sum(f.point_count for f in features) == np.count_nonzero(seg.labels >= 0)
    assert abs(sum(f.share for f in features) - 1.0) < 1e-9
    assert [f.volume for f in features] == sorted((f.volume for f in features), reverse=True)
    assert seg.significant == [f.index for f in features if f.significant]
    pairs, radii = seg.adjacency
    assert pairs.shape == (len(radii), 2) and len(radii) > 0
    assert (pairs[:, 0] < pairs[:, 1]).all() and pairs.max() < len(features) and (radii > 0).all()
    assert set(seg.timings) >= {"delaunay", "interior", "merge", "total"} and seg.timings["total"] > 0
    assert seg.interior["computed"] and seg.interior["inside_volume"] > 0
    centroid = features[0].centroid
    assert centroid.shape == (3,) and np.isfinite(centroid).all()


def test_parameters_round_trip():
    points, _ = fs.read_points(os.path.join(SAMPLES, "snowman3d.pcd"))
    given = dict(rho=1.3, sampling_tolerance=0.25, stump_ratio=0.0, compact_rho=1.5, compact_size=0.0, min_part_share=0.01,
                 single_view_min_part_share=0.02,
                 denoising="off", outliers="off", smoothing="on", smoothing_passes=1, features="both", threads=1, dimension="3", planar_tolerance=1e-6,
                 viewpoint=(0.0, 0.0, 10.0), memory_limit=8 << 30, separate_interior=True, manifold_repair=False, hidden_side=False, exterior_opening=6.0, significance=0.05)
    seg = fs.segment(points, **given)
    used = seg.parameters
    for name, value in given.items():
        assert used[name] == value, name
    assert set(used) == set(fs.defaults()) - {"mesh_points", "seed", "use_sensor_origin", "method", "weights_3d", "weights_2d", "threshold", "allow_mirror", "alignment_points",
                                              "k", "candidates"}
    assert seg.hidden_side_vertices == 0 and seg.interior["island_cells"] == 0
    again = fs.segment(points, **used)
    assert (again.labels == seg.labels).all() and again.parameters == used


def test_old_spellings_work_with_a_deprecation_warning():
    points, _ = fs.read_points(os.path.join(SAMPLES, "snowman3d.pcd"))
    old = dict(dimension="spatial", smoothing="always", outliers="automatic", separate=True)
    new = dict(dimension="3", smoothing="on", outliers="auto", separate_interior=True)
    with pytest.warns(DeprecationWarning) as caught:
        seg = fs.segment(points, threads=1, **old)
    said = " ".join(str(w.message) for w in caught)
    assert "'separate' is deprecated" in said and "'spatial' is deprecated" in said and "'always' is deprecated" in said
    assert seg.parameters == fs.segment(points, threads=1, **new).parameters
    with pytest.raises(TypeError, match="given twice"):
        fs.segment(points, separate=True, separate_interior=True)


def test_defaults_are_the_library_defaults():
    points, _ = fs.read_points(os.path.join(SAMPLES, "star2d.pcd"))
    defaults = fs.defaults()
    used = fs.segment(points).parameters
    assert all(used[name] == defaults[name] for name in used)
    assert defaults["rho"] == 1.05 and defaults["threads"] == 0 and defaults["viewpoint"] is None


def test_float32_two_columns_paper_rule_and_remerge():
    points, _ = fs.read_points(os.path.join(SAMPLES, "star2d.pcd"))
    seg = fs.segment(points[:, :2].astype(np.float32))
    assert seg.dimension == 2
    assert (seg.labels == fs.segment(points).labels).all()
    paper = fs.segment(points, **fs.paper_rule(1.3))
    assert paper.parameters["compact_size"] == 0 and paper.parameters["rho"] == 1.3
    remerged = fs.segment(points).remerge(**fs.paper_rule(1.3))
    assert (remerged.labels == paper.labels).all()
    with pytest.raises(TypeError, match="threads"):
        seg.remerge(threads=2)


def test_threads_do_not_change_labels():
    points, _ = fs.read_points(os.path.join(SAMPLES, "animal3d.pcd"))
    assert (fs.segment(points, threads=1).labels == fs.segment(points, threads=2).labels).all()


BAD_ARRAYS = [
    (np.zeros((10, 4)), "shape"),
    (np.zeros(10), "shape"),
    (np.zeros((10, 3), dtype=np.int32), "float32 or float64"),
    (np.zeros((10, 3), dtype=np.complex128), "float32 or float64"),
    (np.array([["a", "b", "c"]] * 4), "float32 or float64"),
    ([[0.0, 0.0, 0.0]] * 4, "numpy array"),
    (np.zeros((2, 3)), ""),
    (np.full((10, 3), np.nan), ""),
    (np.zeros((10, 3)), ""),  # all duplicates
    (np.column_stack([np.arange(10.0), np.arange(10.0), np.zeros(10)]), "collinear"),
]


@pytest.mark.parametrize("array,message", BAD_ARRAYS)
def test_bad_arrays_raise_value_error(array, message):
    with pytest.raises(ValueError, match=message):
        fs.segment(array)


BAD_PARAMETERS = [
    dict(rho=-1), dict(rho=float("nan")), dict(rho="big"), dict(rho=True), dict(threads=-1), dict(threads=1.5),
    dict(threads=10 ** 30), dict(threads=5000), dict(dimension="cubic"), dict(dimension=3), dict(viewpoint=(1, 2)), dict(viewpoint="up"),
    dict(viewpoint=(0, 0, float("inf"))), dict(viewpoint=b"abc"), dict(viewpoint=[0, 0, "z"]), dict(rho=[1.0]), dict(features="outside"), dict(denoising="maybe"), dict(outliers="sometimes"), dict(smoothing_passes=99), dict(smoothing_passes=-1), dict(smoothing_passes=0), dict(smoothing="sometimes"), dict(separate=1), dict(manifold_repair="yes"), dict(exterior_opening=1.0), dict(exterior_opening=float("nan")),
    dict(significance=1.5), dict(memory_limit=-5), dict(stump_ratio=0.5), dict(compact_size=-1),
]


@pytest.mark.parametrize("params", BAD_PARAMETERS, ids=str)
def test_bad_parameters_raise_value_error(params):
    points, _ = fs.read_points(os.path.join(SAMPLES, "star2d.pcd"))
    with pytest.raises(ValueError):
        fs.segment(points, **params)


def test_unknown_keyword_and_bad_extras():
    points, _ = fs.read_points(os.path.join(SAMPLES, "star2d.pcd"))
    with pytest.raises(TypeError, match="frobnicate"):
        fs.segment(points, frobnicate=1)
    with pytest.raises(TypeError, match="threshold"):
        fs.segment(points, threshold=0.4)  # a matching keyword, not a segmentation one
    with pytest.raises(ValueError, match="normals"):
        fs.segment(points, normals=np.zeros((3, 3)))
    with pytest.raises(TypeError, match="progress"):
        fs.segment(points, progress=5)


def test_progress_is_reported_and_its_errors_propagate():
    points, _ = fs.read_points(os.path.join(SAMPLES, "star2d.pcd"))
    seen = []
    fs.segment(points, progress=lambda stage, fraction: seen.append((stage, fraction)))
    assert seen and all(0.0 <= f <= 1.0 for _, f in seen)

    def fail(stage, fraction):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        fs.segment(points, progress=fail)


def test_non_finite_points_are_counted_not_labelled():
    points, _ = fs.read_points(os.path.join(SAMPLES, "animal3d.pcd"))
    points[5] = np.nan
    seg = fs.segment(points)
    assert seg.non_finite_points == 1 and seg.labels[5] == -1


def test_isolated_points_are_left_out_and_counted():
    points, _ = fs.read_points(os.path.join(SAMPLES, "snowman3d.pcd"))
    lo, hi = points.min(0), points.max(0)
    far = hi + (hi - lo) * np.random.default_rng(3).uniform(0.5, 1.5, size=(30, 3))
    noisy = np.vstack([points, far])
    seg = fs.segment(noisy)
    assert seg.noise["isolated_share"] > 0.001
    assert 25 <= seg.outlier_points <= 60
    assert (seg.labels[len(points):] == -1).sum() >= 25
    kept = fs.segment(noisy, outliers="off")
    assert kept.outlier_points == 0 and kept.noise["isolated_share"] == seg.noise["isolated_share"]


def test_outliers_inside_the_shape_are_detached_and_left_out():
    points, _ = fs.read_points(os.path.join(SAMPLES, "snowman3d.pcd"))
    lo, hi = points.min(0), points.max(0)
    inner = lo + (hi - lo) * np.random.default_rng(4).uniform(0.0, 1.0, size=(40, 3))
    seg = fs.segment(np.vstack([points, inner]))
    assert seg.noise["detached_share"] > 0.004
    assert (seg.labels[len(points):] == -1).sum() >= 30
    assert (seg.labels[:len(points)] == -1).sum() <= 10
    clean = fs.segment(points)
    assert clean.noise["detached_share"] == 0.0 and clean.outlier_points == 0


def test_noisy_samples_are_smoothed_automatically():
    points, _ = fs.read_points(os.path.join(SAMPLES, "snowman3d.pcd"))
    clean = fs.segment(points)
    assert clean.noise["roughness"] < 0.1 and clean.smoothing_passes == 0
    diagonal = np.linalg.norm(points.max(0) - points.min(0))
    noisy = points + np.random.default_rng(2).normal(scale=0.005 * diagonal, size=points.shape)
    seg = fs.segment(noisy)
    assert seg.noise["roughness"] > 0.1 and 1 <= seg.smoothing_passes <= seg.parameters["smoothing_passes"]
    raw = fs.segment(noisy, smoothing="off")
    assert raw.smoothing_passes == 0 and len(raw.features) > len(seg.features)


def test_gil_is_released_during_the_computation():
    rng = np.random.default_rng(1)
    points = rng.normal(size=(60000, 3))
    ticks = []
    running = threading.Event()

    def ticker():
        while running.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.005)

    running.set()
    t = threading.Thread(target=ticker)
    start = time.perf_counter()
    t.start()
    fs.segment(points, threads=1)
    end = time.perf_counter()
    running.clear()
    t.join()
    during = [x for x in ticks if start < x < end]
    # With the GIL held the ticker could not run at all while segment() works (> 0.1 s here).
    assert end - start > 0.1 and len(during) >= 0.25 * (end - start) / 0.005, (end - start, len(during))


def test_any_memory_layout_gives_the_same_labels():
    points, _ = fs.read_points(os.path.join(SAMPLES, "animal3d.pcd"))
    labels = fs.segment(points).labels
    assert (fs.segment(np.asfortranarray(points)).labels == labels).all()
    assert (fs.segment(points[::2]).labels == fs.segment(np.ascontiguousarray(points[::2])).labels).all()
    wide = np.zeros((len(points), 5))
    wide[:, 1:4] = points
    assert (fs.segment(wide[:, 1:4]).labels == labels).all()  # a column slice: strides of 40 bytes
    with pytest.raises(ValueError, match="empty"):
        fs.segment(np.zeros((0, 3)))
