"""Rectangles given as poses, float32 (N, 6) rows cx, cy, hx, hy, c, s: every
pose method on every backend against the scalar reference and against an
independent evaluation in numpy, exact contacts, the default method, the
refusals (nothing written), the corners of poses bit for bit, the store, the
command-line program on the same bytes, and the GIL released meanwhile."""

import os
import pickle
import re
import subprocess
import threading
import time

import numpy as np
import pytest

import obbsat
from conftest import calls_in_two_threads, random_pairs, random_poses

POSE_METHODS = obbsat.methods(poses=True)
CORNER_METHODS = obbsat.methods()
BACKENDS = obbsat.backends()
CANARY = 0xA5
FIELDS = ["cx", "cy", "hx", "hy", "c", "s"]


def near_contact(rng, poses):
    """A partner for each pose, placed (in float64, then rounded to float32)
    so that the two touch along the first pose's x axis, up to a relative
    1e-7 either way: pairs whose verdicts hang on the last bits."""
    n = len(poses)
    partners = random_poses(rng, n)
    a, b = poses.astype(np.float64), partners.astype(np.float64)
    length = np.hypot(a[:, 4], a[:, 5])
    axis = a[:, 4:6] / length[:, None]
    across = np.stack([-axis[:, 1], axis[:, 0]], axis=1)
    reach_b = (b[:, 2] * np.abs((b[:, 4:6] * axis).sum(axis=1))
               + b[:, 3] * np.abs((np.stack([-b[:, 5], b[:, 4]], axis=1) * axis).sum(axis=1)))
    distance = (a[:, 2] * length + reach_b) * (1 + rng.uniform(-1e-7, 1e-7, size=n))
    sideways = rng.uniform(-1, 1, size=n) * a[:, 3] * length
    side = np.where(rng.random(size=n) < 0.5, 1.0, -1.0)
    b[:, 0:2] = a[:, 0:2] + axis * (side * distance)[:, None] + across * sideways[:, None]
    return b.astype(np.float32)


@pytest.fixture(scope="module")
def batch():
    """3000 random poses and 40000 random pairs of them, and 2000 pairs near contact."""
    rng = np.random.default_rng(21)
    poses = random_poses(rng, 3000)
    near = near_contact(rng, poses[:2000])
    pairs = np.concatenate([random_pairs(rng, len(poses), 40_000),
                            np.stack([np.arange(2000), 3000 + np.arange(2000)], axis=1).astype(np.uint32)])
    return np.concatenate([poses, near]), pairs


def canary_out(n):
    return np.full(n, CANARY, dtype=np.uint8)


def test_methods_per_store():
    assert POSE_METHODS == ["conservative", "exact", "local"]
    assert CORNER_METHODS == ["sat4", "sat4_centered", "sat4_double", "conservative", "exact"]


@pytest.mark.parametrize("method", POSE_METHODS)
@pytest.mark.parametrize("backend", BACKENDS)
def test_every_backend_matches_the_scalar_reference(batch, method, backend):
    # The scalar backend's stream calls the method's scalar reference on each
    # pair; the indexed call on every backend, and the stream on every
    # backend, must give its bytes.
    poses, pairs = batch
    a, b = poses[pairs[:, 0]], poses[pairs[:, 1]]
    reference = obbsat.collide_stream(a, b, method=method, backend="scalar")
    assert 0.1 < reference.mean() < 0.9
    got = obbsat.collide(poses, pairs, method=method, backend=backend)
    assert got.dtype == np.bool_ and got.shape == (len(pairs),)
    assert got.tobytes() == reference.tobytes()
    assert obbsat.collide_stream(a, b, method=method, backend=backend, threads=2).tobytes() == reference.tobytes()
    store = obbsat.records(poses)
    assert obbsat.collide(store, pairs, method=method, backend=backend).tobytes() == reference.tobytes()


def separation_in_double(a, b):
    """The separating axis test for the exact rectangles of poses a and b
    (rows of (M, 6)), evaluated in float64 from the definition: on each of
    the four axes (A's and B's rotation vector and its perpendicular), the
    distance between the projections of the two rectangles, divided by the
    axis length; positive on some axis iff the rectangles are apart."""
    a, b = a.astype(np.float64), b.astype(np.float64)
    d = b[:, 0:2] - a[:, 0:2]

    def sides(p):
        rotation = p[:, 4:6]
        normal = np.stack([-rotation[:, 1], rotation[:, 0]], axis=1)
        return rotation * p[:, 2:3], normal * p[:, 3:4]

    sides_a, sides_b = sides(a), sides(b)
    gaps = []
    for axis in (a[:, 4:6], np.stack([-a[:, 5], a[:, 4]], axis=1),
                 b[:, 4:6], np.stack([-b[:, 5], b[:, 4]], axis=1)):
        def reach(half_sides):
            return sum(np.abs((side * axis).sum(axis=1)) for side in half_sides)

        offset = np.abs((d * axis).sum(axis=1))
        gaps.append((offset - reach(sides_a) - reach(sides_b)) / np.hypot(axis[:, 0], axis[:, 1]))
    return np.max(gaps, axis=0)


def test_away_from_contact_every_method_gives_the_answer_of_numpy(batch):
    poses, pairs = batch
    gap = separation_in_double(poses[pairs[:, 0]], poses[pairs[:, 1]])
    # Rounding in float32 moves a projection by far less than 1e-3 at these
    # sizes (|center| <= 30, |half side| <= 12): every method must then agree.
    clear = np.abs(gap) > 1e-3
    assert clear[:40_000].mean() > 0.99 and (~clear[40_000:]).sum() > 1000
    truth = gap[clear] <= 0
    assert 0.1 < truth.mean() < 0.9
    for method in POSE_METHODS:
        for backend in BACKENDS:
            verdicts = obbsat.collide(poses, pairs[clear], method=method, backend=backend)
            assert (verdicts == truth).all(), f"{method} on {backend}"


def test_the_guarantees_hold_near_contact(batch):
    poses, pairs = batch
    near = pairs[40_000:]
    exact = obbsat.collide(poses, near, method="exact")
    conservative = obbsat.collide(poses, near, method="conservative")
    local = obbsat.collide(poses, near, method="local")
    assert 0.2 < exact.mean() < 0.8
    assert (conservative | ~exact).all(), "conservative missed a collision"
    assert (local != exact).any() or (conservative != exact).any(), "no pair near enough to tell the methods apart"


def nudged(poses, row, field):
    """poses with one field of one row moved one ulp away from zero."""
    out = poses.copy()
    value = out[row, field]
    out[row, field] = np.nextafter(value, np.float32(np.inf) if value >= 0 else np.float32(-np.inf))
    return out


# Contacts with integer rotation vectors (3, 4): every float operation of the
# tests is exact, so the contact is exactly on the boundary. Each case is
# (A, B, the field of B whose one-ulp nudge pulls the rectangles apart).
CONTACTS = {
    # [-1, 1]^2 and a square of half side 5 whose corner (1, 1) touches A's.
    "corner_on_corner": ([0, 0, 1, 1, 1, 0], [8, 2, 1, 1, 3, 4], 0),
    # The same square whose lowest corner (0, 1) lies on A's top edge.
    "corner_on_edge": ([0, 0, 1, 1, 1, 0], [-1, 8, 1, 1, 3, 4], 1),
    # Two squares turned by (3, 4), sharing the edge through (3, 4) +- (-4, 3).
    "edge_on_edge": ([0, 0, 1, 1, 3, 4], [6, 8, 1, 1, 3, 4], 0),
    # A segment (hy = 0) along (4, 3) whose end (2, 0) lies on a square's edge.
    "segment_end_on_edge": ([0, 0, 2, 2, 1, 0], [10, 6, 2, 0, 4, 3], 0),
    # A point (both half extents 0) on the corner of a (3, 4) square.
    "point_on_corner": ([0, 0, 0.5, 0.5, 3, 4], [-0.5, 3.5, 0, 0, 1, 0], 1),
}


@pytest.mark.parametrize("case", CONTACTS, ids=str)
@pytest.mark.parametrize("backend", BACKENDS)
def test_exact_contacts_with_integer_rotation_vectors(case, backend):
    a, b, field = CONTACTS[case]
    touching = np.array([a, b], dtype=np.float32)
    apart = nudged(touching, 1, field)
    assert separation_in_double(touching[:1], touching[1:])[0] == 0.0
    assert separation_in_double(apart[:1], apart[1:])[0] > 0.0
    for method in POSE_METHODS:
        # Exactly on the boundary with exact float operations: all say touching.
        assert obbsat.collide(touching, [[0, 1], [1, 0]], method=method, backend=backend).all(), method
    assert not obbsat.collide(apart, [[0, 1], [1, 0]], method="exact", backend=backend).any()
    # Conservative may call a near miss colliding, never a contact apart.
    assert obbsat.collide(apart, [[0, 1]], method="conservative", backend=backend).dtype == np.bool_


def test_the_default_method_is_local_on_poses_and_sat4_on_corners(batch, monkeypatch):
    poses, pairs = batch
    assert obbsat.collide(poses, pairs).tobytes() == obbsat.collide(poses, pairs, method="local").tobytes()
    corners = obbsat.corners_of_poses(poses)
    assert obbsat.collide(corners, pairs).tobytes() == obbsat.collide(corners, pairs, method="sat4").tobytes()
    # Which method each call hands to the library when none is given.
    asked = []
    for name in ("collide_poses", "collide_pose_store", "collide_pose_stream", "collide_records",
                 "collide_store", "collide_stream"):
        real = getattr(obbsat._core, name)

        def spy(*args, real=real, name=name):
            asked.append((name, args[3]))
            return real(*args)

        monkeypatch.setattr(obbsat._core, name, spy)
    obbsat.collide(poses, pairs[:10])
    obbsat.colliding_pairs(obbsat.records(poses), pairs[:10])
    obbsat.collide_stream(poses[:10], poses[10:20])
    obbsat.collide(corners, pairs[:10])
    obbsat.collide(obbsat.records(corners), pairs[:10])
    obbsat.collide_stream(corners[:10], corners[10:20])
    assert asked == [("collide_poses", "local"), ("collide_pose_store", "local"),
                     ("collide_pose_stream", "local"), ("collide_records", "sat4"),
                     ("collide_store", "sat4"), ("collide_stream", "sat4")]


def test_the_program_gives_the_same_verdicts_on_the_same_bytes(batch, tmp_path):
    program = os.environ.get("OBBSAT_CLI")
    if not program:
        pytest.skip("OBBSAT_CLI names no command-line program")
    poses, pairs = batch
    pairs = pairs[:5000]
    pose_file, pair_file = tmp_path / "poses.csv", tmp_path / "pairs.csv"
    pose_file.write_text("".join(",".join(float(v).hex() for v in row) + "\n" for row in poses))
    pair_file.write_text("".join(f"{i},{j}\n" for i, j in pairs))
    for method in [None] + POSE_METHODS:
        out = tmp_path / "verdicts.txt"
        command = [program, "collide", "--poses", str(pose_file), "--pairs", str(pair_file), "--out", str(out)]
        subprocess.run(command + (["--method", method] if method else []), check=True)
        from_program = np.array([c == "1" for c in out.read_text().split()])
        assert from_program.tobytes() == obbsat.collide(poses, pairs, method=method).tobytes(), method


@pytest.mark.parametrize("method", [m for m in CORNER_METHODS if m not in POSE_METHODS])
def test_a_corner_method_on_poses_is_refused_and_nothing_written(batch, method):
    poses, pairs = batch
    text = f"^method {method} does not run on poses \\(pose_records take {', '.join(POSE_METHODS)}\\)$"
    out = canary_out(len(pairs))
    with pytest.raises(ValueError, match=text):
        obbsat.collide(poses, pairs, method=method, out=out)
    with pytest.raises(ValueError, match=text):
        obbsat.collide(obbsat.records(poses), pairs, method=method, out=out)
    with pytest.raises(ValueError, match=text):
        obbsat.colliding_pairs(poses, pairs, method=method)
    stream_out = canary_out(100)
    with pytest.raises(ValueError, match=text):
        obbsat.collide_stream(poses[:100], poses[100:200], method=method, out=stream_out)
    assert (out == CANARY).all() and (stream_out == CANARY).all()


def test_local_on_corners_is_refused_and_nothing_written(batch):
    poses, pairs = batch
    corners = obbsat.corners_of_poses(poses)
    text = f"^method local does not run on corners \\(rect stores take {', '.join(CORNER_METHODS)}\\)$"
    out = canary_out(len(pairs))
    for rects in (corners, obbsat.records(corners)):
        with pytest.raises(ValueError, match=text):
            obbsat.collide(rects, pairs, method="local", out=out)
    with pytest.raises(ValueError, match=text):
        obbsat.collide_stream(corners[:5], corners[5:10], method="local", out=out[:5])
    assert (out == CANARY).all()
    with pytest.raises(ValueError, match=r"unknown method 'lokal' \(known: sat4, .*, local\)"):
        obbsat.collide(poses, pairs, method="lokal", out=out)


def bad_poses():
    """(field, value, message) of every way a pose is refused."""
    cases = []
    for field, name in enumerate(FIELDS):
        for value, shown in ((np.nan, "-?nan"), (np.inf, "inf"), (-np.inf, "-inf")):
            cases.append((field, value, f"{name} is {shown}, not a finite number"))
    cases.append((2, -1.0, "half extent hx is -1, negative"))
    cases.append((3, -0.5, "half extent hy is -0.5, negative"))
    cases.append(((4, 5), 0.0, r"rotation vector \(c, s\) is \(0, 0\)"))
    return cases


@pytest.mark.parametrize("field, value, message", bad_poses(), ids=lambda v: str(v))
def test_a_bad_pose_names_pose_and_field_and_nothing_is_written(batch, field, value, message):
    poses, pairs = batch
    poses = poses[:50].copy()
    poses[37, field] = value
    pairs = pairs[:20] % 10  # no pair names pose 37: it is refused all the same
    out = canary_out(len(pairs))
    with pytest.raises(ValueError, match=f"^pose 37: {message}$"):
        obbsat.collide(poses, pairs, out=out)
    with pytest.raises(ValueError, match=f"^pose 37: {message}$"):
        obbsat.collide(poses, pairs, method="exact", backend="scalar", threads=2, out=out)
    assert (out == CANARY).all()
    with pytest.raises(ValueError, match=f"^pose 37: {message}$"):
        obbsat.records(poses)
    with pytest.raises(ValueError, match=f"^pose 37: {message}$"):
        obbsat.corners_of_poses(poses)
    good = np.tile(poses[0], (len(poses), 1))
    stream_out = canary_out(len(poses))
    with pytest.raises(ValueError, match=f"^b: pose 37: {message}$"):
        obbsat.collide_stream(good, poses, out=stream_out)
    with pytest.raises(ValueError, match=f"^a: pose 37: {message}$"):
        obbsat.collide_stream(poses, good, method="conservative", out=stream_out)
    assert (stream_out == CANARY).all()


def test_zero_half_extents_and_negative_zero_are_valid():
    poses = np.array([[0, 0, 0, 0, 1, 0], [0, 0, -0.0, 1, 0, 1], [0, 0, 1, 0, 0, -1]], dtype=np.float32)
    pairs = [[0, 1], [1, 2], [0, 2]]
    for method in POSE_METHODS:
        assert obbsat.collide(poses, pairs, method=method).all()


@pytest.mark.parametrize("shape", [(6,), (6, 5), (6, 7), (6, 6, 1), (6, 3, 2)])
def test_arrays_of_the_wrong_shape(shape):
    with pytest.raises(ValueError, match=r"^rects: expected shape \(N, 8\) or \(N, 4, 2\) .* or \(N, 6\)"):
        obbsat.collide(np.ones(shape, dtype=np.float32), [[0, 0]])
    with pytest.raises(ValueError, match=r"^poses: expected shape \(N, 6\) \(cx, cy, hx, hy, c, s\), got "):
        obbsat.corners_of_poses(np.ones(shape, dtype=np.float32))


def test_dtypes_and_layouts_give_the_same_verdicts(batch):
    poses, pairs = batch
    expected = obbsat.collide(poses, pairs, method="exact")
    for variant in (poses.astype(np.float64), poses.astype(">f4"), np.asfortranarray(poses), poses.tolist()):
        assert obbsat.collide(variant, pairs, method="exact").tobytes() == expected.tobytes()
    wide = np.zeros((len(poses), 8), dtype=np.float32)
    wide[:, :6] = poses
    assert obbsat.collide(wide[:, :6], pairs.astype(np.int64), method="exact").tobytes() == expected.tobytes()
    with pytest.raises(TypeError, match="rects: expected real numbers"):
        obbsat.collide(poses.astype(np.complex64), pairs)
    with pytest.raises(ValueError, match=r"^a holds poses \(shape \(5000, 6\)\), b holds corners"):
        obbsat.collide_stream(poses, obbsat.corners_of_poses(poses))
    with pytest.raises(ValueError, match=r"^poses: expected shape \(N, 6\)"):
        obbsat.corners_of_poses(obbsat.corners_of_poses(poses))
    # _core reads only what it can read in place; the package converted the rest.
    out = np.zeros(1, dtype=np.uint8)
    with pytest.raises(TypeError, match=r"poses: expected a C-contiguous float32 array of shape \(N, 6\)"):
        obbsat._core.collide_poses(poses.astype(np.float64), pairs[:1], out, "local", "auto", 1)
    with pytest.raises(TypeError, match=r"poses: expected a C-contiguous float32"):
        obbsat._core.collide_poses(wide[:, :6], pairs[:1], out, "local", "auto", 1)


def test_unequal_streams_indices_and_out(batch):
    poses, pairs = batch
    out = canary_out(100)
    with pytest.raises(ValueError, match="^stream batches differ in length: 100 poses in a, 99 in b$"):
        obbsat.collide_stream(poses[:100], poses[:99], out=out)
    bad = pairs[:100].copy()
    bad[42, 1] = len(poses)
    with pytest.raises(IndexError, match=r"^pair 42: index 5000 is out of range \(5000 rectangles\)$"):
        obbsat.collide(poses, bad, out=out)
    with pytest.raises(IndexError, match=r"^pair 42: index 5000 is out of range"):
        obbsat.collide(obbsat.records(poses), bad, out=out)
    signed = bad.astype(np.int64)
    signed[42, 1] = -1
    with pytest.raises(IndexError, match=r"^pair 42: index -1 is out of range"):
        obbsat.collide(poses, signed, out=out)
    assert (out == CANARY).all()
    with pytest.raises(ValueError, match="out: holds 100 verdicts, 99 needed"):
        obbsat.collide(poses, pairs[:99], out=out)
    returned = obbsat.collide(poses, pairs[:100], out=out)
    assert returned is out and set(np.unique(out)) <= {0, 1}


def corners_in_numpy(poses):
    """obbsat/ref/pose_corners.hpp's corners in float32, one numpy operation
    per float operation (numpy rounds each, and never fuses them)."""
    cx, cy, hx, hy, c, s = (poses[:, k] for k in range(6))
    ux, uy = hx * c, hx * s
    vx, vy = -(hy * s), hy * c
    left_x, left_y = cx - ux, cy - uy
    right_x, right_y = cx + ux, cy + uy
    corners = [(left_x + vx, left_y + vy), (right_x + vx, right_y + vy),
               (right_x - vx, right_y - vy), (left_x - vx, left_y - vy)]
    return np.stack([np.stack(corner, axis=-1) for corner in corners], axis=1)


@pytest.mark.parametrize("backend", BACKENDS)
def test_corners_of_poses_match_the_documented_formula_bit_for_bit(backend):
    rng = np.random.default_rng(8)
    poses = np.concatenate([random_poses(rng, 5000), random_poses(rng, 5000, spread=2e6),
                            random_poses(rng, 5000, spread=1e-3)])
    expected = corners_in_numpy(poses)
    assert expected.dtype == np.float32 and expected.shape == (len(poses), 4, 2)
    got = obbsat.corners_of_poses(poses, backend=backend)
    assert got.dtype == np.float32 and got.shape == (len(poses), 4, 2) and got.flags.c_contiguous
    mismatch = np.flatnonzero((got.view(np.uint32) != expected.view(np.uint32)).any(axis=(1, 2)))
    assert mismatch.size == 0, f"pose {mismatch[0]}: {got[mismatch[0]]} against {expected[mismatch[0]]}"
    assert obbsat.corners_of_poses(obbsat.records(poses), backend=backend).tobytes() == expected.tobytes()
    assert obbsat.corners_of_poses(poses[:0]).shape == (0, 4, 2)


def test_a_pose_store_decides_like_the_array(batch):
    poses, pairs = batch
    store = obbsat.records(poses)
    assert isinstance(store, obbsat.PoseRecords) and len(store) == len(poses)
    assert obbsat.records(store) is store
    view = store.poses
    assert view.shape == (len(poses), 6) and view.strides == (32, 4) and not view.flags.writeable
    assert (view == poses).all()
    for method in POSE_METHODS:
        assert (obbsat.collide(store, pairs, method=method).tobytes()
                == obbsat.collide(poses, pairs, method=method).tobytes())
    again = pickle.loads(pickle.dumps(store))
    assert isinstance(again, obbsat.PoseRecords) and again.poses.tobytes() == view.tobytes()
    assert obbsat.colliding_pairs(again, pairs).tolist() == obbsat.colliding_pairs(poses, pairs).tolist()
    empty = obbsat.records(np.zeros((0, 6), dtype=np.float32))
    assert len(empty) == 0 and obbsat.collide(empty, []).shape == (0,)


def test_colliding_pairs_threads_and_empty_batches(batch):
    poses, pairs = batch
    expected = obbsat.collide(poses, pairs, method="exact")
    for threads in (0, 2, 3):
        assert obbsat.collide(poses, pairs, method="exact", threads=threads).tobytes() == expected.tobytes()
    for dtype in (np.uint32, np.int64):
        hits = obbsat.colliding_pairs(poses, pairs.astype(dtype), method="exact")
        assert hits.dtype == dtype and (hits == pairs[expected]).all()
    none = np.zeros((0, 6), dtype=np.float32)
    assert obbsat.collide(none, []).shape == (0,)
    assert obbsat.colliding_pairs(none, []).shape == (0, 2)
    assert obbsat.collide_stream(none, none).shape == (0,)


@pytest.fixture(scope="module")
def large():
    rng = np.random.default_rng(2)
    poses = random_poses(rng, 100_000, spread=400.0)
    return poses, random_pairs(rng, len(poses), 1_000_000)


def test_python_runs_while_a_pose_call_works(large):
    poses, pairs = large
    worker = threading.Thread(target=lambda: obbsat.collide(poses, pairs, method="exact", backend="scalar"))
    started = time.perf_counter()
    worker.start()
    steps = 0
    while worker.is_alive():
        steps += 1
    took = time.perf_counter() - started
    # With the GIL held during the copy or the decisions, this loop would
    # stall for the whole call; released, it spins at millions of steps per second.
    assert took > 0.02, "the call was too short to tell"
    assert steps > 1000 * took * 100


def test_two_threads_decide_poses_at_the_same_time(large):
    # As test_threads.py: were the GIL held during a call, the two threads'
    # calls could not overlap in time.
    poses, pairs = large
    outs = [np.empty(len(pairs), dtype=bool) for _ in range(2)]
    _, overlap, busy = calls_in_two_threads(
        lambda i: obbsat.collide(poses, pairs, method="exact", backend="scalar", out=outs[i]))
    assert overlap > 0.5 * busy, f"calls overlapped {overlap:.3f} s of {busy:.3f} s"
    assert outs[0].tobytes() == outs[1].tobytes()

