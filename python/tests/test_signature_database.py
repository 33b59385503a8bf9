"""Signatures, matching and the database: the same content as flowseg_db, every bad-input path."""
import os
import subprocess
import threading

import numpy as np
import pytest

import pcl_flowseg as fs
from conftest import SAMPLES, app


def test_signatures_equal_those_flowseg_db_stores(collection, tmp_path):
    db_path = str(tmp_path / "cli.db")
    subprocess.run([app("flowseg_db"), "build", db_path, str(collection), "-q"], check=True)
    db = fs.Database.open(db_path)
    files = fs.list_shape_files(str(collection))
    assert [name for name, _, _ in db.entries()] == files
    for name, label, stored in db.entries():
        assert label == fs.shape_label(name)
        sig = fs.signature_of_file(os.path.join(str(collection), name))
        assert np.array_equal(sig.points, stored.points) and np.array_equal(sig.weights, stored.weights)
        assert sig.unit == stored.unit and sig.dimension == stored.dimension


def test_database_add_save_open_query(collection, tmp_path):
    db = fs.Database()
    for name in fs.list_shape_files(str(collection)):
        assert db.add(name, fs.shape_label(name), fs.signature_of_file(os.path.join(str(collection), name)))
    assert len(db) == 9 and "animal3d/animal3d-1.pcd" in db
    path = str(tmp_path / "py.db")
    db.save(path)
    again = fs.Database.open(path)
    assert len(again) == 9
    query = fs.signature_of_file(os.path.join(str(collection), "snowman3d", "snowman3d-2.pcd"))
    hits = again.query(query, k=3)
    assert len(hits) == 3 and hits[0].name == "snowman3d/snowman3d-2.pcd" and hits[0].similarity == pytest.approx(1.0)
    assert hits[0].label == "snowman3d" and hits[0].compared
    few = again.query(query, k=0, candidates=2)
    assert len(few) == 9 and sum(h.compared for h in few) == 2
    assert all(np.isnan(h.similarity) for h in few if not h.compared)
    # The description methods give a distance, the paper's method its own score; the old names warn.
    assert hits[0].distance == pytest.approx(0.0, abs=1e-9) and np.isnan(hits[0].paper_score)
    assert hits[1].similarity == pytest.approx(np.exp(-hits[1].distance))
    with pytest.deprecated_call():
        assert hits[1].aligned == hits[1].compared
    with pytest.deprecated_call():
        assert hits[1].score == hits[1].distance
    paper = again.query(query, k=2, method="paper", alignment_points=3)
    assert paper[0].paper_score > 0 and np.isnan(paper[0].distance)
    with pytest.deprecated_call():
        assert paper[0].score == paper[0].paper_score


def test_match_is_symmetric_and_invariant():
    points, _ = fs.read_points(os.path.join(SAMPLES, "animal3d.pcd"))
    a = fs.signature(points)
    rotation = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    b = fs.signature(2.5 * points @ rotation.T + np.array([3.0, -1.0, 7.0]))
    result = fs.match(a, b, method="paper")
    assert result.similarity == pytest.approx(1.0, abs=1e-6)
    assert result.linear.shape == (3, 3) and len(result.pairs) == len(a)
    # The default compares descriptions; the cells they are measured on are drawn in an order that
    # moving the shape does not change, so a moved copy describes the same.
    assert fs.match(a, b).similarity == pytest.approx(1.0, abs=1e-9)
    assert a.parts.shape[1] == 6 and len(a.parts) >= 6 and a.parts[:, 0].sum() == pytest.approx(1.0)
    assert a.distributions["inner_distance"].sum() == pytest.approx(1.0)
    assert a.distributions["inner_profiles"].shape == (16, 32)
    assert a.distributions["inner_profiles"].sum(axis=1) == pytest.approx([1.0] * 16)
    assert a.distributions["thickness_profile"].shape == (16,)
    assert a.distributions["contour"].shape == (0, 60)  # 3D shapes have no outline
    contexts = a.distributions["inner_contexts"]
    assert contexts.shape == (64, 17) and contexts.dtype == np.float32
    assert contexts[:, 1:].sum(axis=1) == pytest.approx([1.0] * 64, abs=1e-4)
    other = fs.signature(fs.read_points(os.path.join(SAMPLES, "snowman3d.pcd"))[0])
    assert fs.match(a, other).similarity == pytest.approx(fs.match(other, a).similarity)
    paper = fs.match(a, other, method="paper", threshold=0.2, allow_mirror=False, alignment_points=2)
    assert paper.alignments > 0 and np.isnan(paper.distance)
    assert paper.similarity == pytest.approx(paper.paper_score / max(len(a), len(other)))
    described = fs.match(a, other)
    assert np.isnan(described.paper_score) and described.similarity == pytest.approx(np.exp(-described.distance))
    with pytest.deprecated_call():
        assert described.score == described.distance
    for method in ("flowseg", "parts", "thickness", "inner", "solid", "inner-profile", "thickness-profile",
                   "inner-context"):
        assert fs.match(a, other, method=method).similarity < fs.match(a, b, method=method).similarity, method
    with pytest.raises(ValueError, match="method"):
        fs.match(a, other, method="d2")


def test_description_weights_are_keywords_by_name():
    a = fs.signature(fs.read_points(os.path.join(SAMPLES, "animal3d.pcd"))[0])
    other = fs.signature(fs.read_points(os.path.join(SAMPLES, "snowman3d.pcd"))[0])
    names = fs.defaults()["weights_3d"]
    assert names.startswith("parts=3,") and "inner_context=5" in names
    only_parts = {name.split("=")[0]: 0.0 for name in names.split(",")}
    only_parts["parts"] = 2.0
    weighted = fs.match(a, other, weights_3d=only_parts)
    assert weighted.distance == pytest.approx(2.0 * fs.match(a, other, method="parts").distance)
    as_text = ",".join(f"{name}={value}" for name, value in only_parts.items())
    assert fs.match(a, other, weights_3d=as_text).distance == weighted.distance
    # 2D weights leave 3D shapes alone; a weight not named keeps its default.
    assert fs.match(a, other, weights_2d="contour=1").distance == fs.match(a, other).distance
    for bad in ("parts=-1", "girth=1", {"parts": "x"}, {n: 0 for n in only_parts}, 3.0):
        with pytest.raises(ValueError):
            fs.match(a, other, weights_3d=bad)


def test_contour_of_a_2d_shape_survives_mirroring():
    points, _ = fs.read_points(os.path.join(SAMPLES, "hand2d.pcd"))
    a = fs.signature(points)
    contour = a.distributions["contour"]
    assert contour.shape == (64, 60) and contour.dtype == np.float32
    assert contour.sum(axis=1) == pytest.approx([1.0] * 64, abs=1e-4)
    mirror = np.array([[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    b = fs.signature(0.5 * points @ mirror.T)
    other = fs.signature(fs.read_points(os.path.join(SAMPLES, "star2d.pcd"))[0])
    assert fs.match(a, b, method="contour").similarity > fs.match(a, other, method="contour").similarity


def test_concurrent_adds_from_threads_lose_nothing(tmp_path):
    path = str(tmp_path / "threads.db")
    sig = fs.signature(fs.read_points(os.path.join(SAMPLES, "snowman3d.pcd"))[0])
    errors = []

    def add(i):
        try:
            fs.Database.add_to_file(path, [("shape%02d" % i, "c%d" % (i % 3), sig)])
        except Exception as error:  # collected, asserted below
            errors.append(error)

    threads = [threading.Thread(target=add, args=(i,)) for i in range(16)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors and len(fs.Database.open(path)) == 16


def test_queries_from_threads_while_another_thread_adds(collection):
    files = fs.list_shape_files(str(collection))
    signatures = {name: fs.signature_of_file(os.path.join(str(collection), name)) for name in files}
    db = fs.Database()
    for name in files[:3]:
        db.add(name, fs.shape_label(name), signatures[name])
    labels = {fs.shape_label(name) for name in files}
    done = threading.Event()
    errors, counts = [], [0, 0, 0]

    def query(reader, name):
        try:
            while True:
                finished = done.is_set()
                for method in ("flowseg", "paper"):
                    hits = db.query(signatures[name], k=0, candidates=4, method=method)
                    assert 3 <= len(hits) <= 3 + 20, len(hits)
                    assert hits[0].name == name and hits[0].similarity == pytest.approx(1.0), (hits[0], method)
                    compared = [h for h in hits if h.compared]
                    assert len(compared) == min(4, len(hits))
                    assert all(a.similarity >= b.similarity for a, b in zip(compared, compared[1:]))
                    assert all(np.isnan(h.similarity) for h in hits if not h.compared)
                    assert all(h.label in labels for h in hits)
                assert name in db and 3 <= len(db) <= 3 + 20 and len(db.entries()) >= 3
                counts[reader] += 1
                if finished:
                    break
        except Exception as error:  # collected, asserted below
            errors.append(error)

    readers = [threading.Thread(target=query, args=(r, name)) for r, name in enumerate(files[:3])]
    for t in readers:
        t.start()
    try:
        i = 0  # new shapes, then replacements, and a merge, while every reader queries a few times
        while (i < 40 or min(counts) < 5) and i < 10000 and not errors:
            name = files[3 + i % (len(files) - 3)]
            db.add("extra%02d" % (i % 20), fs.shape_label(name), signatures[name])
            if i == 20:
                db.merge(db)
            i += 1
    finally:
        done.set()
        for t in readers:
            t.join()
    assert not errors, errors[0]
    assert min(counts) >= 5 and len(db) == 3 + 20


def test_merge_files_in_order(collection, tmp_path):
    files = fs.list_shape_files(str(collection))
    shards = []
    for part in (files[:4], files[4:]):
        db = fs.Database()
        for name in part:
            db.add(name, fs.shape_label(name), fs.signature_of_file(os.path.join(str(collection), name)))
        shards.append(str(tmp_path / ("shard%d.db" % len(shards))))
        db.save(shards[-1])
    merged = str(tmp_path / "merged.db")
    assert fs.Database.merge_files(merged, shards) == 9
    whole = str(tmp_path / "whole.db")
    subprocess.run([app("flowseg_db"), "build", whole, str(collection), "-q"], check=True)
    assert open(merged, "rb").read() == open(whole, "rb").read()


def test_bad_input_raises(tmp_path):
    with pytest.raises(OSError, match="cannot open"):
        fs.Database.open(str(tmp_path / "missing.db"))
    damaged = tmp_path / "damaged.db"
    damaged.write_text("pcl_flowseg signature database 7\nshapes 1\nshape a 3 1 1 0.02 1 0 0 0 one\np 0 0 1 8e300\n")
    with pytest.raises(OSError, match="damaged.db:4"):
        fs.Database.open(str(damaged))
    with pytest.raises(OSError):
        fs.Database.merge_files(str(tmp_path / "m.db"), [str(damaged)])
    assert not (tmp_path / "m.db").exists()
    with pytest.raises(OSError, match="cannot open"):
        fs.read_points(str(tmp_path / "none.pcd"))
    (tmp_path / "bad.pcd").write_text("not a pcd\n")
    with pytest.raises(OSError):
        fs.read_points(str(tmp_path / "bad.pcd"))
    with pytest.raises(OSError):
        fs.signature_of_file(str(tmp_path / "bad.pcd"))
    with pytest.raises(ValueError, match="mesh"):
        fs.signature_of_file(os.path.join(SAMPLES, "animal3d.pcd"), mesh_points=2)
    with pytest.raises(ValueError, match="weight"):
        fs.Signature(np.zeros((2, 3)), [0.2, 0.9])
    with pytest.raises(ValueError, match="weights"):
        fs.Signature(np.zeros((2, 3)), [1.0])
    sig = fs.Signature(np.zeros((1, 3)), [1.0])
    with pytest.raises(ValueError, match="label"):
        fs.Database().add("x", "two words", sig)
    with pytest.raises(ValueError, match="name"):
        fs.Database().add("", "c", sig)
    with pytest.raises(ValueError, match="alignment"):
        fs.match(sig, sig, alignment_points=0)
    with pytest.raises(ValueError, match="threshold"):
        fs.Database().query(sig, threshold=-1)
    with pytest.raises(TypeError):
        fs.match(sig, sig, rho=2)
    with pytest.raises(TypeError):
        fs.Database().query(sig, k=-1)


def _two_balls_off(path):
    """Two UV spheres side by side (radii 1 and 0.6) as an OFF mesh."""
    vertices, faces = [], []
    for centre, radius in (((0.0, 0.0, 0.0), 1.0), ((1.5, 0.0, 0.0), 0.6)):
        base = len(vertices)
        for i in range(17):
            for j in range(32):
                theta, phi = np.pi * i / 16, 2 * np.pi * j / 32
                vertices.append([centre[0] + radius * np.sin(theta) * np.cos(phi),
                                 centre[1] + radius * np.sin(theta) * np.sin(phi), centre[2] + radius * np.cos(theta)])
        at = lambda i, j: base + i * 32 + j % 32
        for i in range(16):
            for j in range(32):
                faces += [(at(i, j), at(i + 1, j), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i, j + 1))]
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        f.writelines(f"{x} {y} {z}\n" for x, y, z in vertices)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)


def test_signature_of_a_scan_file_from_its_own_viewpoint(tmp_path):
    mesh, scan = str(tmp_path / "balls.off"), str(tmp_path / "scan.pcd")
    _two_balls_off(mesh)
    subprocess.run([app("flowseg_sample"), mesh, "--scan-from", "0.5,0,12", "-n", "3000", "-o", scan, "-q"], check=True)
    own = fs.signature_of_file(scan, use_sensor_origin=True)
    assert len(own) == 2  # both balls, seen from the front, each a part
    assert fs.match(own, fs.signature_of_file(scan, viewpoint=(0.5, 0.0, 12.0))).similarity == pytest.approx(1.0)
    assert fs.match(own, fs.signature_of_file(scan)).similarity < 1.0
    with pytest.raises(ValueError, match="viewpoint"):
        fs.signature_of_file(scan, use_sensor_origin=True, viewpoint=(0.5, 0.0, 12.0))
    with pytest.raises(OSError, match="sensor origin"):
        fs.signature_of_file(mesh, use_sensor_origin=True)


def _box_off(path, sides):
    """An axis-aligned box with the given side lengths, as an OFF mesh."""
    corners = [(x * sides[0], y * sides[1], z * sides[2]) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    faces = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
             (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]
    with open(path, "w") as f:
        f.write("OFF\n8 12 0\n" + "".join("%g %g %g\n" % c for c in corners) + "".join("3 %d %d %d\n" % t for t in faces))


def test_a_scan_query_finds_its_shape_among_complete_ones(tmp_path, capfd):
    balls, slab, scan = str(tmp_path / "balls.off"), str(tmp_path / "slab.off"), str(tmp_path / "scan.pcd")
    _two_balls_off(balls)
    _box_off(slab, (3.0, 1.5, 0.4))
    subprocess.run([app("flowseg_sample"), balls, "--scan-from", "3,4,10", "-n", "3000", "-o", scan, "-q"], check=True)
    db = fs.Database()
    for name, mesh in (("balls", balls), ("slab", slab)):
        complete = fs.signature_of_file(mesh)
        assert not complete.single_view and complete.view_count == 42
        db.add(name, name, complete)
    query = fs.signature_of_file(scan, use_sensor_origin=True)
    assert query.single_view and query.view_count == 1
    hits = db.query(query, k=0)
    assert [h.name for h in hits] == ["balls", "slab"] and all(h.compared for h in hits)
    assert hits[0].distance < hits[1].distance
    assert db.view_candidates == 40
    db.view_candidates = 1
    assert sum(h.compared for h in db.query(query, k=0)) == 1
    with pytest.raises(ValueError, match="at least 1"):
        db.view_candidates = 0
    bare = fs.Database()
    for name, _, signature in db.entries():
        stripped = signature.without_views()
        assert stripped.view_count == 0 and signature.view_count == 42 and len(stripped) == len(signature)
        bare.add(name, name, stripped)
    assert bare.query(query, k=0) == []  # a scan finds nothing without views
    assert bare.query(fs.signature_of_file(balls), k=1)[0].name == "balls"  # a complete shape still does
    capfd.readouterr()
    fs.signature_of_file(scan)  # its viewpoint forgotten: warned
    assert "looks like a single view" in capfd.readouterr().err
