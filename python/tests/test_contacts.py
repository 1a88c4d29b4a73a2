"""obbsat.contacts, contacts_stream, distances, distances_stream and
find_contacts: hand-checked cases, the arrays bit for bit equal to the
library's values as the command-line program prints them (shortest
round-trip text), the same bits on every backend, thread count, store and
layout, the errors of collide, and the GIL released."""

import os
import pathlib
import subprocess
import tempfile
import threading
import time

import numpy as np
import pytest

import obbsat


def square(cx, cy, h=1.0):
    return [cx, cy, h, h, 1.0, 0.0]


@pytest.fixture(scope="module")
def scene():
    poses = obbsat.testing.make_pose_scene(boxes=3000, sizes="mixed", pairs_per_box=2.0, seed=4)
    rng = np.random.default_rng(7)
    pairs = rng.integers(0, len(poses), size=(4000, 2)).astype(np.uint32)
    pairs = np.concatenate([obbsat.find_pairs(poses), pairs])
    return np.ascontiguousarray(poses, dtype=np.float32), pairs


# --- Hand-checked cases ---------------------------------------------------------

def test_two_overlapping_squares():
    poses = np.array([square(0, 0), square(1.5, 0)], dtype=np.float32)
    c = obbsat.contacts(poses, [[0, 1]])
    assert len(c) == 1
    assert c.normals.tolist() == [[1.0, 0.0]]
    assert c.depths.tolist() == [0.5]
    assert c.counts.tolist() == [2]
    assert sorted(c.points[0].tolist()) == [[0.5, -1.0], [0.5, 1.0]]
    assert c.separations.tolist() == [[-0.5, -0.5]]
    # Each key: one side a face (type 1), the other a corner (type 0).
    for key in c.features[0]:
        type_a, type_b = (int(key) >> 8) & 0xFF, (int(key) >> 24) & 0xFF
        assert {type_a, type_b} == {0, 1}
        assert (int(key) & 0xFF) < 4 and ((int(key) >> 16) & 0xFF) < 4
    assert c.normals.dtype == np.float32 and c.counts.dtype == np.uint8 and c.features.dtype == np.uint32
    assert c.points.shape == (1, 2, 2) and c.separations.shape == (1, 2) and c.features.shape == (1, 2)


def test_apart_pairs_have_no_points_unless_within_the_margin():
    poses = np.array([square(0, 0), square(2.5, 0)], dtype=np.float32)
    c = obbsat.contacts(poses, [[0, 1]])
    assert c.counts.tolist() == [0]
    assert c.depths[0] == np.float32(-0.5)
    assert c.points.tolist() == [[[0, 0], [0, 0]]] and c.features.tolist() == [[0, 0]]
    near = obbsat.contacts(poses, [[0, 1]], margin=0.5)
    assert near.counts.tolist() == [2]
    assert near.separations.tolist() == [[0.5, 0.5]]


def test_distances_of_apart_and_colliding_pairs():
    poses = np.array([square(0, 0), square(4, 0), square(1, 1)], dtype=np.float32)
    d = obbsat.distances(poses, [[0, 1], [0, 2]])
    assert d.distance.tolist() == [2.0, 0.0]
    assert d.a[0, 0] == 1.0 and d.b[0, 0] == 3.0 and d.a[0, 1] == d.b[0, 1]
    assert d.a[1].tolist() == [0.0, 0.0] and d.b[1].tolist() == [0.0, 0.0]  # colliding: every value +0
    assert not np.signbit(d.a[1]).any()


def test_find_contacts_of_a_row_of_squares():
    poses = np.array([square(0, 0), square(1.5, 0), square(3.6, 0), square(9, 9)], dtype=np.float32)
    pairs, c = obbsat.find_contacts(poses)
    assert pairs.tolist() == [[0, 1]] and pairs.dtype == np.uint32
    assert c.depths.tolist() == [0.5]
    pairs, c = obbsat.find_contacts(poses, margin=0.2)
    assert pairs.tolist() == [[0, 1], [1, 2]]
    assert c.counts.tolist() == [2, 2]


# --- The library's values ---------------------------------------------------------

def run_cli(args):
    program = os.environ.get("OBBSAT_CLI")
    if not program:
        pytest.skip("OBBSAT_CLI names no command-line program")
    result = subprocess.run([program] + args, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return result.stdout.splitlines()


def write_inputs(folder, poses, pairs):
    pose_path = pathlib.Path(folder) / "poses.csv"
    pose_path.write_text("".join(",".join(float(v).hex() for v in row) + "\n" for row in poses))
    pair_path = pathlib.Path(folder) / "pairs.csv"
    pair_path.write_text("".join(f"{i},{j}\n" for i, j in pairs))
    return str(pose_path), str(pair_path)


def bits(values):
    return np.asarray(values, dtype=np.float32).view(np.uint32)


def test_contacts_equal_the_programs_values_bit_for_bit(scene):
    poses, pairs = scene
    c = obbsat.contacts(poses, pairs, margin=0.05)
    with tempfile.TemporaryDirectory() as folder:
        pose_path, pair_path = write_inputs(folder, poses, pairs)
        lines = run_cli(["contacts", "--poses", pose_path, "--pairs", pair_path, "--margin", "0.05"])
    kept = np.flatnonzero(c.counts > 0)
    assert len(lines) == len(kept) > 100
    for line, k in zip(lines, kept):
        f = line.split(",")
        assert [int(f[0]), int(f[1])] == pairs[k].tolist()
        assert bits([float(v) for v in f[2:5]]).tolist() == bits([*c.normals[k], c.depths[k]]).tolist()
        assert int(f[5]) == c.counts[k]
        for p in range(c.counts[k]):
            got = bits([float(v) for v in f[6 + 3 * p:9 + 3 * p]]).tolist()
            assert got == bits([*c.points[k, p], c.separations[k, p]]).tolist()


def test_distances_equal_the_programs_values_bit_for_bit(scene):
    poses, pairs = scene
    d = obbsat.distances(poses, pairs)
    with tempfile.TemporaryDirectory() as folder:
        pose_path, pair_path = write_inputs(folder, poses, pairs)
        lines = run_cli(["distance", "--poses", pose_path, "--pairs", pair_path])
    assert len(lines) == len(pairs)
    got = np.array([[float(v) for v in line.split(",")[2:]] for line in lines])
    expected = np.column_stack([d.distance, d.a, d.b])
    assert (bits(got) == bits(expected)).all()


def test_find_contacts_equals_the_programs_scene(scene):
    poses, _ = scene
    pairs, c = obbsat.find_contacts(poses, margin=0.05)
    with tempfile.TemporaryDirectory() as folder:
        pose_path, _ = write_inputs(folder, poses, [])
        lines = run_cli(["contacts", "--poses", pose_path, "--margin", "0.05"])
    assert [[int(v) for v in line.split(",")[:2]] for line in lines] == pairs.tolist()
    assert bits([float(line.split(",")[4]) for line in lines]).tolist() == bits(c.depths).tolist()


def same_contacts(x, y):
    for name in ("normals", "depths", "counts", "points", "separations", "features"):
        a, b = getattr(x, name), getattr(y, name)
        assert a.dtype == b.dtype and a.shape == b.shape
        assert a.tobytes() == b.tobytes(), name


def test_every_backend_thread_count_store_and_layout_gives_the_same_bits(scene):
    poses, pairs = scene
    first = obbsat.contacts(poses, pairs, margin=0.05, backend="scalar")
    for backend in obbsat.backends():
        for threads in (1, 3):
            same_contacts(obbsat.contacts(poses, pairs, margin=0.05, backend=backend, threads=threads), first)
    same_contacts(obbsat.contacts(obbsat.records(poses), pairs, margin=0.05), first)
    same_contacts(obbsat.contacts(poses.astype(np.float64), pairs.astype(np.int64), margin=0.05,
                                  precision="float32"), first)
    same_contacts(obbsat.contacts_stream(poses[pairs[:, 0]], poses[pairs[:, 1]], margin=0.05), first)
    corners = obbsat.corners_of_poses(poses)
    on_corners = obbsat.contacts(corners, pairs)
    same_contacts(obbsat.contacts(obbsat.records(corners), pairs), on_corners)
    same_contacts(obbsat.contacts(corners.reshape(-1, 8), pairs), on_corners)
    same_contacts(obbsat.contacts_stream(corners[pairs[:, 0]], corners[pairs[:, 1]]), on_corners)
    d = obbsat.distances(poses, pairs, backend="scalar")
    for other in (obbsat.distances(obbsat.records(poses), pairs, threads=2),
                  obbsat.distances_stream(poses[pairs[:, 0]], poses[pairs[:, 1]])):
        assert other.distance.tobytes() == d.distance.tobytes() and other.a.tobytes() == d.a.tobytes()
        assert other.b.tobytes() == d.b.tobytes()
    dc = obbsat.distances(corners, pairs)
    assert dc.distance.tobytes() == obbsat.distances(obbsat.records(corners), pairs).distance.tobytes()


def test_float64_contacts_and_distances_are_the_same_bits_on_every_backend(scene):
    poses, pairs = scene
    wide = poses.astype(np.float64)
    wide[:, :2] += 4.0e5  # centers far from the origin, as UTM coordinates are
    first = obbsat.contacts(wide, pairs, margin=0.05, backend="scalar")
    assert first.depths.dtype == np.float64
    d = obbsat.distances(wide, pairs, backend="scalar")
    corners = obbsat.corners_of_poses(wide)
    on_corners = obbsat.contacts(corners, pairs, backend="scalar")
    for backend in obbsat.backends():
        for threads in (1, 2):
            same_contacts(obbsat.contacts(wide, pairs, margin=0.05, backend=backend, threads=threads), first)
            same_contacts(obbsat.contacts(corners, pairs, backend=backend, threads=threads), on_corners)
            other = obbsat.distances(wide, pairs, backend=backend, threads=threads)
            assert other.distance.tobytes() == d.distance.tobytes() and other.a.tobytes() == d.a.tobytes()
            assert other.b.tobytes() == d.b.tobytes()


def test_find_contacts_equals_contacts_on_its_pairs(scene):
    poses, _ = scene
    for margin in (0.0, 0.05):
        pairs, c = obbsat.find_contacts(poses, margin=margin, threads=2)
        same_contacts(obbsat.contacts(poses, pairs, margin=margin), c)
        store_pairs, store_c = obbsat.find_contacts(obbsat.records(poses), margin=margin)
        assert store_pairs.tolist() == pairs.tolist()
        same_contacts(store_c, c)
    exact = obbsat.find_pairs(poses)
    assert obbsat.find_contacts(poses)[0].tolist() == exact.tolist()
    assert len(obbsat.find_contacts(poses, margin=0.05)[0]) > len(exact)


def test_pair_finder_frames_with_contacts(scene):
    poses, _ = scene
    finder = obbsat.PairFinder(threads=2)
    rng = np.random.default_rng(11)
    ids = np.arange(len(poses), dtype=np.uint64) + 500
    for frame in range(4):
        moved = poses.copy()
        moved[:, :2] += (0.01 * frame * rng.standard_normal((len(poses), 2))).astype(np.float32)
        pairs, c = finder.find_contacts(moved, ids=ids)
        assert pairs.tolist() == obbsat.find_pairs(moved).tolist()
        same_contacts(obbsat.contacts(moved, pairs), c)
        assert finder.find(moved, ids=ids).tolist() == pairs.tolist()
    a, b = poses[:1000], poses[1000:]
    pairs, c = finder.find_contacts(a, b)
    assert pairs.tolist() == obbsat.find_pairs(a, b).tolist()
    same_contacts(obbsat.contacts_stream(a[pairs[:, 0]], b[pairs[:, 1]]), c)


def test_pair_finder_contacts_keep_the_feature_keys_of_a_persisting_contact():
    finder = obbsat.PairFinder()
    keys = None
    for frame in range(6):
        poses = np.array([[0, 0, 8, 0.5, 1, 0], [-2 + 0.5 * frame, 0.95, 0.5, 0.5, 1, 0]], dtype=np.float32)
        pairs, c = finder.find_contacts(poses)
        assert pairs.tolist() == [[0, 1]] and c.counts.tolist() == [2]
        if keys is not None:
            assert c.features.tolist() == keys
        keys = c.features.tolist()


def test_pair_finder_contacts_of_float64_stay_float64():
    poses = np.array([square(0, 0), square(1.5, 0)], dtype=np.float64)
    for finder in (obbsat.PairFinder(), obbsat.PairFinder(precision="float64")):
        pairs, c = finder.find_contacts(poses)
        assert pairs.tolist() == [[0, 1]] and c.depths.dtype == np.float64
        same_contacts(obbsat.contacts(poses, pairs), c)
    pairs, c = obbsat.PairFinder(precision="float32").find_contacts(poses)
    assert pairs.tolist() == [[0, 1]] and c.depths.dtype == np.float32


def test_find_contacts_of_float64_equals_contacts_in_double_on_every_backend_and_thread_count():
    """At UTM-like coordinates, where float32 would decide otherwise: the pairs
    are find_pairs' on the doubles (with a margin, those and every pair whose
    double contact has points), each contact bit for bit obbsat.contacts' in
    double, on every backend and thread count, from arrays and double stores."""
    poses, _ = utm_scene()
    for margin in (0.0, 0.05):
        pairs, c = obbsat.find_contacts(poses, margin=margin, backend="scalar")
        assert c.depths.dtype == np.float64 and len(pairs) > 50
        same_contacts(obbsat.contacts(poses, pairs, margin=margin), c)
        if margin == 0.0:
            assert pairs.tolist() == obbsat.find_pairs(poses).tolist()
        else:
            touching = obbsat.find_pairs(poses).tolist()
            assert all(c.counts[k] > 0 or p in touching for k, p in enumerate(pairs.tolist()))
            assert len(pairs) > len(touching)
        for backend in obbsat.backends():
            for threads in (1, 2, 3):
                got_pairs, got = obbsat.find_contacts(poses, margin=margin, backend=backend, threads=threads)
                assert got_pairs.tolist() == pairs.tolist()
                same_contacts(got, c)
        store_pairs, store_c = obbsat.find_contacts(obbsat.records(poses), margin=margin)
        assert store_pairs.tolist() == pairs.tolist()
        same_contacts(store_c, c)
    # Rounded to float32, the scene's pairs differ: the double path is not float32 in disguise.
    assert obbsat.find_contacts(poses, precision="float32")[0].tolist() != obbsat.find_pairs(poses).tolist()


def test_find_contacts_of_float64_corners():
    corners = np.array([[0, 1, 2, 1, 2, 0, 0, 0], [1, 2, 3, 2, 3, 0.5, 1, 0.5], [2.05, 1, 3, 1, 3, 0, 2.05, 0]],
                       dtype=np.float64) + 5e5
    pairs, c = obbsat.find_contacts(corners)
    assert pairs.tolist() == [[0, 1], [1, 2]] and c.depths.dtype == np.float64
    same_contacts(obbsat.contacts(corners, pairs), c)
    near_pairs, near = obbsat.find_contacts(corners, margin=0.1)
    assert near_pairs.tolist() == [[0, 1], [0, 2], [1, 2]]
    same_contacts(obbsat.contacts(corners, near_pairs, margin=0.1), near)


def test_pair_finder_frames_with_float64_contacts():
    poses, _ = utm_scene()
    finder = obbsat.PairFinder(threads=2)
    rng = np.random.default_rng(12)
    ids = np.arange(len(poses), dtype=np.uint64) + 500
    rows = poses.copy()
    for frame in range(6):
        rows[:, :2] += 0.002 * rng.standard_normal((len(rows), 2))
        if frame == 3:  # a box goes (swap-removed), one comes
            rows[10], ids[10] = rows[-1], ids[-1]
            rows = np.vstack([rows[:-1], rows[5] + [0.3, 0, 0, 0, 0, 0]])
            ids = np.append(ids[:-1], np.uint64(99999))
        pairs, c = finder.find_contacts(rows, ids=ids)
        assert c.depths.dtype == np.float64
        assert pairs.tolist() == obbsat.find_pairs(rows).tolist()
        same_contacts(obbsat.contacts(rows, pairs), c)
    a, b = rows[:150], rows[150:]
    pairs, c = finder.find_contacts(a, obbsat.records(b))
    assert pairs.tolist() == obbsat.find_pairs(a, b).tolist() and len(pairs) > 0
    same_contacts(obbsat.contacts_stream(a[pairs[:, 0]], b[pairs[:, 1]]), c)


def test_float64_scene_contacts_errors_name_the_row():
    poses, _ = utm_scene()
    bad = poses.copy()
    bad[7, 1] = np.nan
    with pytest.raises(ValueError, match="pose 7"):
        obbsat.find_contacts(bad)
    with pytest.raises(ValueError, match="pose 7"):
        obbsat.PairFinder().find_contacts(bad)
    for margin in (-1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="margin"):
            obbsat.find_contacts(poses, margin=margin)
    with pytest.raises(ValueError, match="does not run on double"):
        obbsat.find_contacts(poses, method="sat4")


# --- Errors ----------------------------------------------------------------------

def test_errors_name_the_argument_the_row_or_the_pair():
    poses = np.array([square(0, 0), square(1.5, 0)], dtype=np.float32)
    with pytest.raises(IndexError, match="pair 1"):
        obbsat.contacts(poses, [[0, 1], [0, 2]])
    with pytest.raises(IndexError, match="pair 0"):
        obbsat.distances(poses, [[-1, 0]])
    bad = poses.copy()
    bad[1, 3] = np.nan
    with pytest.raises(ValueError, match="pose 1"):
        obbsat.contacts(bad, [[0, 1]])
    with pytest.raises(ValueError, match="pose 1"):
        obbsat.find_contacts(bad)
    with pytest.raises(ValueError, match="b: pose 1"):
        obbsat.contacts_stream(poses, bad)
    for margin in (-1.0, float("nan"), float("inf"), 1e300):
        with pytest.raises(ValueError, match="margin"):
            obbsat.contacts(poses, [[0, 1]], margin=margin)
    with pytest.raises(ValueError, match="margin"):
        obbsat.find_contacts(poses, margin=-0.5)
    with pytest.raises(TypeError, match="margin"):
        obbsat.contacts(poses, [[0, 1]], margin="0.1")
    with pytest.raises(ValueError, match="shape"):
        obbsat.contacts(np.zeros((2, 5), dtype=np.float32), [[0, 1]])
    with pytest.raises(TypeError, match="pairs"):
        obbsat.contacts(poses, [[0.0, 1.0]])
    with pytest.raises(TypeError, match="pairs"):
        obbsat.contacts(poses, obbsat.records(poses))
    with pytest.raises(ValueError, match="backend"):
        obbsat.contacts(poses, [[0, 1]], backend="mmx")
    with pytest.raises(ValueError, match="threads"):
        obbsat.distances(poses, [[0, 1]], threads=-1)
    with pytest.raises(ValueError, match="differ in length"):
        obbsat.distances_stream(poses, poses[:1])
    with pytest.raises(ValueError, match="one form"):
        obbsat.contacts_stream(poses, obbsat.corners_of_poses(poses))
    with pytest.raises(TypeError, match="store"):
        obbsat.contacts_stream(obbsat.records(poses), poses)
    with pytest.raises(ValueError, match="method"):
        obbsat.find_contacts(poses, method="sat4")
    bow_tie = np.array([[0, 0, 1, 1, 1, 0, 0, 1], [0, 1, 2, 1, 2, 0, 0, 0]], dtype=np.float32)
    with pytest.raises(ValueError, match="rectangle 0"):
        obbsat.contacts(bow_tie, [[1, 1]])


# --- The GIL ---------------------------------------------------------------------

def test_python_runs_while_contacts_are_computed():
    poses = obbsat.testing.make_pose_scene(boxes=200_000, pairs_per_box=2.0, seed=3)
    pairs = obbsat.find_pairs(poses)
    pairs = np.concatenate([pairs] * 4)
    worker = threading.Thread(target=lambda: obbsat.contacts(poses, pairs, backend="scalar"))
    started = time.perf_counter()
    worker.start()
    steps = 0
    while worker.is_alive():
        steps += 1
    took = time.perf_counter() - started
    assert took > 0.02, "the call was too short to tell"
    # Held, the GIL would stall this loop for the whole call; released, it spins at millions of steps a second.
    assert steps > 1000 * took * 100


def test_float64_boxes_are_computed_in_double_unless_rounding_is_asked_for():
    poses = np.array([square(0, 0), square(1.5, 0)], dtype=np.float64)
    calls = {"depths": (lambda **k: obbsat.contacts(poses, [[0, 1]], **k),
                        lambda **k: obbsat.contacts_stream(poses[:1], poses[1:], **k)),
             "distance": (lambda **k: obbsat.distances(poses, [[0, 1]], **k),
                          lambda **k: obbsat.distances_stream(poses[:1], poses[1:], **k))}
    for column, pair in calls.items():
        for call in pair:
            assert getattr(call(), column).dtype == np.float64
            assert getattr(call(precision="float64"), column).dtype == np.float64
            assert getattr(call(precision="float32"), column).dtype == np.float32
    rounded = obbsat.contacts(poses, [[0, 1]], precision="float32")
    same_contacts(rounded, obbsat.contacts(poses.astype(np.float32), [[0, 1]]))
    # The scene's contacts too: float64 stays float64 unless rounding is asked for.
    assert obbsat.find_contacts(poses)[1].depths.dtype == np.float64
    assert obbsat.find_contacts(poses, precision="float64")[1].depths.dtype == np.float64
    assert obbsat.find_contacts(poses, precision="float32")[1].depths.dtype == np.float32
    # A float32 store cannot give float64 rows.
    with pytest.raises(ValueError, match="float64"):
        obbsat.contacts(obbsat.records(poses.astype(np.float32)), [[0, 1]], precision="float64")


def utm_scene():
    """Poses at UTM-like coordinates (eastings near 5e5, northings near 5e6, in
    metres) whose float32 rounding (0.03 to 0.5 m) would move them by more
    than their gaps: pairs a few centimetres apart or overlapping."""
    rng = np.random.default_rng(11)
    count = 400
    centers = np.column_stack([rng.uniform(500000, 500200, count), rng.uniform(5000000, 5000200, count)])
    angles = rng.uniform(0, np.pi, count)
    poses = np.column_stack([centers, rng.uniform(0.5, 4, (count, 2)), np.cos(angles), np.sin(angles)])
    pairs = obbsat.find_pairs(poses.astype(np.float64), method="conservative")
    near = rng.integers(0, count, size=(600, 2)).astype(np.uint32)
    return poses, np.concatenate([pairs, near]).astype(np.uint32)


def test_float64_contacts_equal_the_programs_double_values_bit_for_bit():
    poses, pairs = utm_scene()
    c = obbsat.contacts(poses, pairs, margin=0.05)
    assert c.depths.dtype == np.float64 and c.points.dtype == np.float64
    with tempfile.TemporaryDirectory() as folder:
        pose_path, pair_path = write_inputs(folder, poses, pairs)
        lines = run_cli(["contacts", "--poses", pose_path, "--pairs", pair_path, "--margin", "0.05",
                         "--precision", "double"])
        distance_lines = run_cli(["distance", "--poses", pose_path, "--pairs", pair_path, "--precision", "double"])
    kept = np.flatnonzero(c.counts > 0)
    assert len(lines) == len(kept) > 50
    for line, k in zip(lines, kept):
        f = line.split(",")
        assert [int(f[0]), int(f[1])] == pairs[k].tolist()
        assert [float(v) for v in f[2:5]] == [*c.normals[k], c.depths[k]]
        assert int(f[5]) == c.counts[k]
        for p in range(c.counts[k]):
            assert [float(v) for v in f[6 + 3 * p:9 + 3 * p]] == [*c.points[k, p], c.separations[k, p]]
    d = obbsat.distances(poses, pairs)
    got = np.array([[float(v) for v in line.split(",")[2:]] for line in distance_lines])
    assert (got == np.column_stack([d.distance, d.a, d.b])).all()
    # Rounded to float32, the same pairs lose centimetres: the double path is not float32 in disguise.
    rounded = obbsat.contacts(poses, pairs, margin=0.05, precision="float32")
    assert (rounded.depths.astype(np.float64) != c.depths).any()


def test_float64_contacts_are_the_same_on_every_thread_count_and_stream():
    poses, pairs = utm_scene()
    first = obbsat.contacts(poses, pairs, margin=0.05)
    for threads in (0, 3):
        same_contacts(obbsat.contacts(poses, pairs, margin=0.05, threads=threads, backend="scalar"), first)
    same_contacts(obbsat.contacts_stream(poses[pairs[:, 0]], poses[pairs[:, 1]], margin=0.05), first)
    d = obbsat.distances(poses, pairs)
    s = obbsat.distances_stream(poses[pairs[:, 0]], poses[pairs[:, 1]], threads=2)
    assert d.distance.tobytes() == s.distance.tobytes() and d.a.tobytes() == s.a.tobytes()
    # Corners in double too: the corners of a float64 pose, the same pairs.
    corners = np.array([[0, 1, 2, 1, 2, 0, 0, 0], [1, 2, 3, 2, 3, 0.5, 1, 0.5]], dtype=np.float64) + 5e5
    cc = obbsat.contacts(corners, [[0, 1]])
    assert cc.depths.dtype == np.float64 and cc.counts.tolist() == [2] and cc.depths.tolist() == [0.5]


def test_float64_errors_name_the_row():
    poses = np.array([square(0, 0), square(1.5, 0), [0, 0, 1, 1, 0, 0]], dtype=np.float64)
    with pytest.raises(ValueError, match="pose 2"):
        obbsat.contacts(poses, [[0, 1]])
    with pytest.raises(IndexError, match="pair 1"):
        obbsat.contacts(poses[:2], [[0, 1], [0, 5]])
    with pytest.raises(ValueError, match="margin"):
        obbsat.contacts(poses[:2], [[0, 1]], margin=-1.0)
