"""The scene query from Python: obbsat.find_pairs, obbsat.PairFinder,
obbsat.bounds and obbsat.dask.find_pairs.

The brute force is the library's own verdict on every pair, i < j
(obbsat.collide, the method's word on each pair), with the rule the query
states: it reports exactly the pairs whose bounds overlap and that the method
calls colliding. Backends, threads, stores and layouts give the same bytes;
a PairFinder equals a fresh query on every frame; refusals name what is
wrong; the GIL is released during a query, as test_threads.py checks for
collide."""

import threading
import time
import tracemalloc

import numpy as np
import pytest

import obbsat
from conftest import calls_in_two_threads, random_poses, random_rects

CORNER_METHODS = obbsat.methods()
POSE_METHODS = obbsat.methods(poses=True)
BACKENDS = obbsat.backends()


def all_pairs(n, m=None):
    """Every pair (i, j), i < j, of n boxes, or every (i, j) of n boxes against m."""
    if m is None:
        i, j = np.triu_indices(n, k=1)
    else:
        i, j = np.repeat(np.arange(n), m), np.tile(np.arange(m), n)
    return np.stack([i, j], axis=1).astype(np.uint32)


def overlapping(bounds_a, bounds_b, pairs):
    """Whether the closed bounds of each pair overlap (touching bounds overlap)."""
    a, b = bounds_a[pairs[:, 0]], bounds_b[pairs[:, 1]]
    return (a[:, 0] <= b[:, 2]) & (b[:, 0] <= a[:, 2]) & (a[:, 1] <= b[:, 3]) & (b[:, 1] <= a[:, 3])


def brute_force(boxes, method, against=None):
    """The pairs find_pairs must report: bounds overlap and the method's verdict, on every pair."""
    if against is None:
        pairs = all_pairs(len(boxes))
        verdicts = obbsat.collide(boxes, pairs, method=method, backend="scalar")
        bounds_b = obbsat.bounds(boxes)
    else:
        pairs = all_pairs(len(boxes), len(against))
        # One store holding both sides: boxes first, then against, so pair (i, j) is decided as (boxes[i], against[j]).
        joined = np.concatenate([boxes, against])
        verdicts = obbsat.collide(joined, pairs + np.array([0, len(boxes)], dtype=np.uint32), method=method,
                                  backend="scalar")
        bounds_b = obbsat.bounds(against)
    return pairs[overlapping(obbsat.bounds(boxes), bounds_b, pairs) & verdicts], pairs[verdicts]


def small_scenes():
    """Seeded scenes of a few hundred boxes, dense enough that many bounds overlap."""
    rng = np.random.default_rng(21)
    uniform = obbsat.testing.make_pose_scene(boxes=400, sizes="uniform", pairs_per_box=4, seed=3)
    mixed = obbsat.testing.make_pose_scene(boxes=400, sizes="mixed", pairs_per_box=4, seed=4)
    odd = random_poses(rng, 400, spread=30.0)  # zero extents, rotation vectors of length 0.25 to 4
    return {"uniform": uniform, "mixed": mixed, "random": odd}


SCENES = small_scenes()


def corner_scenes():
    rng = np.random.default_rng(22)
    scenes = {name: obbsat.corners_of_poses(poses).reshape(-1, 8) for name, poses in SCENES.items()
              if name != "random"}
    scenes["random"] = random_rects(rng, 400, spread=30.0)
    return scenes


CORNER_SCENES = corner_scenes()


def assert_pairs(got, expected):
    assert got.dtype == np.uint32 and got.ndim == 2 and got.shape[1] == 2 and got.flags.c_contiguous
    assert got.shape == expected.shape, f"{len(got)} pairs, {len(expected)} expected"
    assert got.tobytes() == expected.tobytes()


# --- The answer: brute force -------------------------------------------------


@pytest.mark.parametrize("scene", SCENES)
@pytest.mark.parametrize("method", POSE_METHODS)
def test_poses_give_the_pairs_of_brute_force(scene, method):
    poses = SCENES[scene]
    expected, verdict_only = brute_force(poses, method)
    assert len(expected) > 200
    assert_pairs(obbsat.find_pairs(poses, method=method), expected)
    if method in ("exact", "conservative"):
        # Bounds contain the exact rectangles: no colliding pair has bounds apart.
        assert_pairs(expected, verdict_only)


@pytest.mark.parametrize("scene", CORNER_SCENES)
@pytest.mark.parametrize("method", CORNER_METHODS)
def test_corners_give_the_pairs_of_brute_force(scene, method):
    rects = CORNER_SCENES[scene]
    expected, verdict_only = brute_force(rects, method)
    assert len(expected) > 200
    assert_pairs(obbsat.find_pairs(rects, method=method), expected)
    assert_pairs(obbsat.find_pairs(rects.reshape(-1, 4, 2), method=method), expected)
    if method == "exact":
        assert_pairs(expected, verdict_only)


@pytest.mark.parametrize("method", POSE_METHODS)
def test_a_cross_query_indexes_boxes_then_against(method):
    poses = SCENES["mixed"]
    boxes, against = poses[:150], poses[150:]
    expected, _ = brute_force(boxes, method, against)
    got = obbsat.find_pairs(boxes, against, method=method)
    assert len(expected) > 50
    assert_pairs(got, expected)
    # Not i < j: j indexes against, whatever i is.
    assert (got[:, 1] < got[:, 0]).any()
    # Against itself, a cross query reports both (i, j) and (j, i) and every (i, i).
    self_pairs = obbsat.find_pairs(boxes, boxes, method="exact")
    assert set(map(tuple, self_pairs)) >= {(i, i) for i in range(len(boxes))}


@pytest.mark.parametrize("method", CORNER_METHODS)
def test_a_cross_query_on_corners(method):
    rects = CORNER_SCENES["random"]
    expected, _ = brute_force(rects[:100], method, rects[100:])
    assert_pairs(obbsat.find_pairs(rects[:100], rects[100:], method=method), expected)


def near_contact_pairs(count, seed):
    """Pairs of poses placed edge to edge along A's rotation, a few float steps off contact:
    the float methods misjudge some of them."""
    rng = np.random.default_rng(seed)
    angle = rng.uniform(0, 2 * np.pi, count)
    rotation = np.stack([np.cos(angle), np.sin(angle)], axis=1).astype(np.float32)
    half = rng.uniform(0.5, 2.0, (count, 2)).astype(np.float32)
    center = rng.uniform(-1, 1, (count, 2)).astype(np.float32)
    reach = (half[:, 0] * 2).astype(np.float64) * (1 + rng.integers(-4, 5, count) * 2.0**-23)
    other = center.astype(np.float64) + reach[:, None] * rotation.astype(np.float64)
    a = np.concatenate([center, half, rotation], axis=1)
    b = np.concatenate([other.astype(np.float32), half, rotation], axis=1)
    return np.ascontiguousarray(a, dtype=np.float32), np.ascontiguousarray(b, dtype=np.float32)


def test_the_default_method_is_exact_as_in_obbsat_pairs():
    a, b = near_contact_pairs(4000, seed=5)
    misjudged = obbsat.collide_stream(a, b, method="local") != obbsat.collide_stream(a, b, method="exact")
    assert misjudged.any()
    scene = np.concatenate([a[misjudged], b[misjudged]])
    assert_pairs(obbsat.find_pairs(scene), obbsat.find_pairs(scene, method="exact"))
    assert_pairs(obbsat.find_pairs(scene), brute_force(scene, "exact")[0])
    assert not np.array_equal(obbsat.find_pairs(scene), obbsat.find_pairs(scene, method="local"))
    rects = obbsat.corners_of_poses(SCENES["random"])
    assert_pairs(obbsat.find_pairs(rects), brute_force(rects, "exact")[0])


def test_small_and_empty_scenes():
    poses = SCENES["uniform"]
    for n in (0, 1):
        got = obbsat.find_pairs(poses[:n])
        assert got.shape == (0, 2) and got.dtype == np.uint32
    assert obbsat.find_pairs(poses[:0], poses).shape == (0, 2)
    assert obbsat.find_pairs(poses, poses[:0]).shape == (0, 2)
    assert_pairs(obbsat.find_pairs(poses[:1], poses), brute_force(poses[:1], "exact", poses)[0])
    assert_pairs(obbsat.find_pairs(poses, poses[:1]), brute_force(poses, "exact", poses[:1])[0])
    same = np.repeat(poses[:1], 3, axis=0)
    assert_pairs(obbsat.find_pairs(same, method="exact"), np.array([[0, 1], [0, 2], [1, 2]], dtype=np.uint32))
    assert obbsat.find_pairs(np.empty((0, 4, 2))).shape == (0, 2)
    assert obbsat.find_pairs(np.zeros((0, 8))).shape == (0, 2)


# --- Every backend, thread count, store and layout ---------------------------


@pytest.fixture(scope="module")
def large_poses():
    return obbsat.testing.make_pose_scene(boxes=30_000, sizes="mixed", pairs_per_box=3, seed=8)


@pytest.mark.parametrize("backend", BACKENDS)
def test_backends_and_threads_give_the_same_pairs(large_poses, backend):
    rects = obbsat.corners_of_poses(large_poses)
    for boxes, methods in ((large_poses, POSE_METHODS), (rects, CORNER_METHODS)):
        for method in methods:
            expected = obbsat.find_pairs(boxes, method=method, backend="scalar")
            assert len(expected) > 50_000
            for threads in (1, 2, 3, 0):
                got = obbsat.find_pairs(boxes, method=method, backend=backend, threads=threads)
                assert got.tobytes() == expected.tobytes(), (method, threads)
            cross = obbsat.find_pairs(boxes[:10_000], boxes[10_000:], method=method, backend=backend, threads=2)
            assert cross.tobytes() == obbsat.find_pairs(boxes[:10_000], boxes[10_000:], method=method,
                                                        backend="scalar").tobytes()


def test_stores_dtypes_and_layouts_give_the_same_pairs():
    poses, rects = SCENES["mixed"], CORNER_SCENES["mixed"]
    expected = obbsat.find_pairs(poses, method="exact")
    for same in (obbsat.records(poses), poses.astype(np.float64), np.asfortranarray(poses), poses.tolist(),
                 poses.astype(">f4")):
        assert_pairs(obbsat.find_pairs(same, method="exact"), expected)
    cross = obbsat.find_pairs(poses[:100], poses[100:], method="exact")
    assert_pairs(obbsat.find_pairs(obbsat.records(poses[:100]), poses[100:], method="exact"), cross)
    assert_pairs(obbsat.find_pairs(poses[:100], obbsat.records(poses[100:]), method="exact"), cross)
    expected = obbsat.find_pairs(rects, method="sat4")
    strided = np.repeat(rects, 2, axis=0)[::2]
    for same in (obbsat.records(rects), rects.reshape(-1, 4, 2), strided):
        assert_pairs(obbsat.find_pairs(same, method="sat4"), expected)
    # float64 data is decided in float64, where sat4 does not run; rounded explicitly, it is the float32 answer.
    assert_pairs(obbsat.find_pairs(rects.astype(np.float64), method="sat4", precision="float32"), expected)
    assert_pairs(obbsat.find_pairs(rects.astype(np.float64), method="exact"), obbsat.find_pairs(rects, method="exact"))


def test_the_pairs_own_the_librarys_result():
    # The array holds the library's vector itself, no copy through numpy: tracemalloc (numpy's buffers) sees
    # nothing of the 8 bytes per pair.
    store = obbsat.records(obbsat.testing.make_pose_scene(boxes=100_000, seed=5))
    tracemalloc.start()
    try:
        pairs = obbsat.find_pairs(store)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert len(pairs) > 150_000 and peak < 64 * 1024
    assert pairs.flags.writeable and not pairs.flags.owndata


# --- Bounds -------------------------------------------------------------------


def pose_bounds_in_numpy(poses):
    """obbsat/ref/bounds.hpp's steps in float32, each operation rounded once by numpy."""
    f = np.float32
    cx, cy, hx, hy, c, s = (poses[:, k].astype(f) for k in range(6))
    ac, as_ = np.abs(c), np.abs(s)
    ex = (ac * hx) + (as_ * hy)
    ey = (as_ * hx) + (ac * hy)
    tiny, scale = f(2.0**-140), f(2.0**-21)
    with np.errstate(over="ignore"):  # huge poses overflow to infinity, as the contract says
        mx = ((np.abs(cx) + ex) * scale) + tiny
        my = ((np.abs(cy) + ey) * scale) + tiny
        return np.stack([(cx - ex) - mx, (cy - ey) - my, (cx + ex) + mx, (cy + ey) + my], axis=1)


@pytest.mark.parametrize("scene", SCENES)
def test_bounds_of_poses_follow_the_contract_bit_for_bit(scene):
    poses = SCENES[scene]
    got = obbsat.bounds(poses)
    assert got.dtype == np.float32 and got.shape == (len(poses), 4)
    assert got.tobytes() == pose_bounds_in_numpy(poses).tobytes()
    assert got.tobytes() == obbsat.bounds(obbsat.records(poses)).tobytes()
    # They contain the corners (which are rounded, so only nearly on the rectangle: far inside the margin here).
    corners = obbsat.corners_of_poses(poses)
    assert (got[:, :2] <= corners.min(axis=1)).all() and (corners.max(axis=1) <= got[:, 2:]).all()


def test_bounds_of_huge_poses_are_infinite_never_nan():
    poses = np.array([[3e38, 0, 1e38, 1, 1, 0], [0, -3e38, 1, 3e38, 1, 0], [1e-40, 0, 0, 0, 1, 0]], dtype=np.float32)
    got = obbsat.bounds(poses)
    assert not np.isnan(got).any()
    assert got[0, 2] == np.inf and got[1, 1] == -np.inf
    assert got.tobytes() == pose_bounds_in_numpy(poses).tobytes()
    assert got[2, 0] < poses[2, 0] < got[2, 2]


@pytest.mark.parametrize("scene", CORNER_SCENES)
def test_bounds_of_corners_are_the_corners_least_and_greatest(scene):
    rects = CORNER_SCENES[scene]
    quads = rects.reshape(-1, 4, 2)
    expected = np.concatenate([quads.min(axis=1), quads.max(axis=1)], axis=1)
    for same in (rects, quads, obbsat.records(rects), rects.astype(np.float64)):
        assert obbsat.bounds(same).tobytes() == expected.tobytes()


# --- PairFinder ------------------------------------------------------------------


def frames(poses, count, seed):
    """The scene moved a little, frame after frame."""
    rng = np.random.default_rng(seed)
    velocity = rng.uniform(-0.05, 0.05, size=(len(poses), 2)).astype(np.float32)
    out = []
    for k in range(count):
        frame = poses.copy()
        frame[:, :2] += velocity * np.float32(k)
        out.append(frame)
    return out


@pytest.mark.parametrize("method", ["local", "exact", "conservative"])
def test_a_pair_finder_equals_fresh_queries_frame_after_frame(large_poses, method):
    finder = obbsat.PairFinder(method=method, threads=2)
    assert finder.stats.boxes == 0 and not finder.stats.reused_order
    answers = []
    reused_candidates = reused_orders = 0
    for k, frame in enumerate(frames(large_poses, 6, seed=1)):
        got = finder.find(frame)
        assert_pairs(got, obbsat.find_pairs(frame, method=method))
        stats = finder.stats
        assert isinstance(stats, obbsat.FindPairsStats)
        assert stats.boxes == len(frame) and stats.pairs == len(got) and stats.candidates >= stats.pairs
        assert stats.strips > 0 and 0 < stats.kernel_seconds <= stats.sweep_seconds * 2.5
        assert stats.reused_order <= (k > 0), k
        reused_orders += stats.reused_order
        assert (stats.slow_path_pairs > 0) <= (method == "exact")
        # The first call answers as a plain query and keeps nothing; the others keep
        # at least the pairs they test.
        assert stats.kept_candidates == 0 if k == 0 else stats.kept_candidates >= stats.candidates
        reused_candidates += stats.reused_candidates
        answers.append(got)
    # Each answer is a copy: the next frame did not overwrite it.
    for frame, got in zip(frames(large_poses, 6, seed=1), answers):
        assert_pairs(got, obbsat.find_pairs(frame, method=method))
    assert "reused_order=True" in repr(finder.stats)
    # Steady motion: some frames from the kept candidates, some not (the first
    # keeps nothing, so the second runs the full query that keeps pairs).
    assert 1 <= reused_candidates <= 4, reused_candidates
    # Frames after the first repair the last order or keep the candidates; a
    # full query whose widening changed may sort anew.
    assert reused_orders >= 3, reused_orders


def test_a_pair_finder_on_cross_queries_corners_and_stores(large_poses):
    finder = obbsat.PairFinder(method="exact", backend="scalar")
    a, b = large_poses[:10_000], large_poses[10_000:]
    for frame in frames(a, 3, seed=2):
        assert_pairs(finder.find(frame, b), obbsat.find_pairs(frame, b, method="exact"))
    assert_pairs(finder.find(obbsat.records(a)), obbsat.find_pairs(a, method="exact"))
    rects = obbsat.corners_of_poses(a)
    assert_pairs(finder.find(rects), obbsat.find_pairs(rects, method="exact"))
    assert not finder.stats.reused_order
    # The default method is exact, on both forms.
    default = obbsat.PairFinder()
    assert_pairs(default.find(rects), obbsat.find_pairs(rects, method="exact"))
    assert_pairs(default.find(a), obbsat.find_pairs(a, method="exact"))


# --- Refusals --------------------------------------------------------------------


def test_arrays_of_the_wrong_dtype_or_shape():
    poses = SCENES["uniform"][:10]
    with pytest.raises(TypeError, match="^boxes: expected real numbers, got dtype <U1$"):
        obbsat.find_pairs(np.full((4, 6), "x"))
    with pytest.raises(TypeError, match="^against: expected real numbers, got dtype complex64$"):
        obbsat.find_pairs(poses, np.zeros((2, 6), dtype=np.complex64))
    with pytest.raises(ValueError, match=r"^boxes: expected shape \(N, 8\) or \(N, 4, 2\) .* got \(4, 7\)$"):
        obbsat.find_pairs(np.zeros((4, 7), dtype=np.float32))
    with pytest.raises(ValueError, match=r"^against: expected shape .* got \(6,\)$"):
        obbsat.PairFinder().find(poses, np.zeros(6, dtype=np.float32))
    with pytest.raises(ValueError, match=r"^boxes: expected shape .* got \(3, 4, 3\)$"):
        obbsat.bounds(np.zeros((3, 4, 3)))
    with pytest.raises(ValueError, match="^boxes hold poses, against holds corners: a scene query compares one form$"):
        obbsat.find_pairs(poses, obbsat.corners_of_poses(poses))
    with pytest.raises(ValueError, match="^boxes hold corners, against holds poses"):
        obbsat.PairFinder().find(obbsat.records(obbsat.corners_of_poses(poses)), obbsat.records(poses))


def test_core_refuses_what_it_cannot_read_in_place():
    poses = SCENES["uniform"][:10]
    with pytest.raises(TypeError, match=r"^boxes: expected a C-contiguous float32 array of shape \(N, 6\)$"):
        obbsat._core.find_pairs_poses(poses.astype(np.float64), None, "exact", "auto", 1)
    with pytest.raises(TypeError, match=r"^against: expected a C-contiguous float32 array of shape \(N, 6\)$"):
        obbsat._core.find_pairs_poses(poses, np.asfortranarray(poses), "exact", "auto", 1)
    with pytest.raises(TypeError, match=r"^boxes: expected a C-contiguous float32 array of shape \(N, 8\)"):
        obbsat._core.corner_bounds(poses)
    with pytest.raises(TypeError, match="^boxes: expected a numpy array or a PoseRecords, got list$"):
        obbsat._core.find_pairs_poses([[0, 0, 1, 1, 1, 0]], None, "exact", "auto", 1)
    with pytest.raises(TypeError, match="^boxes: expected a numpy array or a RectRecords, got PoseRecords$"):
        obbsat._core.find_pairs_corners(obbsat.records(poses), None, "exact", "auto", 1)


@pytest.mark.parametrize("method", [m for m in CORNER_METHODS if m not in POSE_METHODS])
def test_a_corner_method_on_poses_is_refused_in_the_librarys_words(method):
    poses = SCENES["uniform"]
    text = f"^method {method} does not run on poses \\(pose_records take {', '.join(POSE_METHODS)}\\)$"
    with pytest.raises(ValueError, match=text):
        obbsat.find_pairs(poses, method=method)
    with pytest.raises(ValueError, match=text):
        obbsat.find_pairs(obbsat.records(poses), poses, method=method)
    with pytest.raises(ValueError, match=text):
        obbsat.PairFinder(method=method).find(poses)
    # Refused before the poses are read: a bad pose is not what is reported.
    broken = poses.copy()
    broken[3, 2] = -1
    with pytest.raises(ValueError, match=text):
        obbsat.find_pairs(broken, method=method)


def test_local_on_corners_is_refused():
    text = f"^method local does not run on corners \\(rect stores take {', '.join(CORNER_METHODS)}\\)$"
    with pytest.raises(ValueError, match=text):
        obbsat.find_pairs(CORNER_SCENES["uniform"], method="local")
    with pytest.raises(ValueError, match=text):
        obbsat.PairFinder(method="local").find(CORNER_SCENES["uniform"])


def test_bad_boxes_are_named():
    poses = SCENES["uniform"].copy()
    poses[7, 3] = -2
    with pytest.raises(ValueError, match="^pose 7: half extent hy is -2, negative$"):
        obbsat.find_pairs(poses)
    with pytest.raises(ValueError, match="^pose 7: half extent hy is -2, negative$"):
        obbsat.bounds(poses)
    with pytest.raises(ValueError, match="^against: pose 7: half extent hy is -2, negative$"):
        obbsat.find_pairs(SCENES["mixed"], poses)
    with pytest.raises(ValueError, match="^boxes: pose 7: half extent hy is -2, negative$"):
        obbsat.PairFinder().find(poses, SCENES["mixed"])
    rects = CORNER_SCENES["uniform"].copy()
    rects[4, 5] = np.nan
    with pytest.raises(ValueError, match="^rectangle 4: coordinate lry is not finite$"):
        obbsat.find_pairs(rects)
    with pytest.raises(ValueError, match="^rectangle 4: coordinate lry is not finite$"):
        obbsat.bounds(rects)
    with pytest.raises(ValueError, match="^against: rectangle 4: coordinate lry is not finite$"):
        obbsat.find_pairs(rects[:2], rects)


def test_unknown_names_and_threads():
    poses = SCENES["uniform"]
    with pytest.raises(ValueError, match=r"^unknown method 'sat5' \(known: sat4, "):
        obbsat.find_pairs(poses, method="sat5")
    with pytest.raises(ValueError, match=r"^unknown backend 'neon' \(known: auto, "):
        obbsat.find_pairs(poses, backend="neon")
    with pytest.raises(ValueError, match="^threads must be >= 0"):
        obbsat.find_pairs(poses, threads=-1)
    with pytest.raises(ValueError, match=r"^unknown method 'sat5' \(known: sat4, "):
        obbsat.PairFinder(method="sat5")
    with pytest.raises(ValueError, match=r"^unknown backend 'neon' \(known: auto, "):
        obbsat.PairFinder(backend="neon")
    with pytest.raises(ValueError, match="^threads must be >= 0"):
        obbsat.PairFinder(threads=-1)
    with pytest.raises(TypeError):
        obbsat.find_pairs(poses, None, "exact")  # method is keyword-only


def test_a_backend_this_cpu_cannot_run():
    missing = [b for b in obbsat.backends(compiled=True) if b not in obbsat.backends()]
    if not missing:
        pytest.skip("this CPU runs every compiled backend")
    with pytest.raises(obbsat.UnsupportedBackendError, match=missing[0]):
        obbsat.find_pairs(SCENES["uniform"], backend=missing[0])
    with pytest.raises(obbsat.UnsupportedBackendError, match=missing[0]):
        obbsat.PairFinder(backend=missing[0])


# --- The GIL ---------------------------------------------------------------------


@pytest.fixture(scope="module")
def huge_scene():
    return obbsat.testing.make_pose_scene(boxes=600_000, seed=2)


def runs_beside(call):
    """How many steps this thread took while `call` ran in another, and how long it ran."""
    worker = threading.Thread(target=call)
    started = time.perf_counter()
    worker.start()
    steps = 0
    while worker.is_alive():
        steps += 1
    return steps, time.perf_counter() - started


def test_python_runs_while_a_query_works(huge_scene):
    steps, took = runs_beside(lambda: obbsat.find_pairs(huge_scene, method="exact", backend="scalar"))
    # With the GIL held (during the copy into records, the query or the sort), this loop would stall for the
    # whole call; released, it spins at millions of steps per second.
    assert took > 0.02, "the query was too short to tell"
    assert steps > 1000 * took * 100
    finder = obbsat.PairFinder(method="exact", backend="scalar")
    steps, took = runs_beside(lambda: finder.find(huge_scene))
    assert took > 0.02 and steps > 1000 * took * 100


def test_two_threads_query_at_the_same_time(huge_scene):
    # As test_threads.py: were the GIL held during a query, the two threads' calls could not overlap.
    answers, overlap, busy = calls_in_two_threads(
        lambda i: obbsat.find_pairs(huge_scene, method="local", backend="scalar"))
    assert overlap > 0.5 * busy, f"queries overlapped {overlap:.3f} s of {busy:.3f} s"
    assert answers[0].tobytes() == answers[1].tobytes()


def test_one_finder_shared_by_two_threads_answers_each(huge_scene):
    # One query at a time: the second thread waits (without the GIL) and each gets its own answer.
    finder = obbsat.PairFinder(method="local")
    small = huge_scene[:50_000]
    answers = {}

    def work(name, boxes):
        for _ in range(3):
            answers[name] = finder.find(boxes)

    threads = [threading.Thread(target=work, args=("huge", huge_scene)),
               threading.Thread(target=work, args=("small", small))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert_pairs(answers["huge"], obbsat.find_pairs(huge_scene, method="local"))
    assert_pairs(answers["small"], obbsat.find_pairs(small, method="local"))


# --- Dask: the same pairs, tile by tile --------------------------------------------


@pytest.fixture(scope="module")
def dask_array():
    da = pytest.importorskip("dask.array")
    import obbsat.dask  # noqa: F401

    return da


@pytest.mark.parametrize("scheduler", ["synchronous", "threads"])
@pytest.mark.parametrize("sizes,seed", [("uniform", 1), ("mixed", 2), ("mixed", 3)])
def test_dask_tiles_give_the_in_memory_pairs(dask_array, scheduler, sizes, seed):
    import dask

    da = dask_array
    poses = obbsat.testing.make_pose_scene(boxes=20_000, sizes=sizes, pairs_per_box=3, seed=seed)
    side = float(obbsat.bounds(poses)[:, 2:].max())
    with dask.config.set(scheduler=scheduler):
        for method in ("local", "exact"):
            expected = obbsat.find_pairs(poses, method=method)
            # Tiles much larger than the boxes, near their size (mixed boxes span many), and one tile.
            for tile, chunks in ((side / 6, 4000), (side / 40, 7000), (2 * side, 20_000)):
                lazy = obbsat.dask.find_pairs(da.from_array(poses, chunks=(chunks, 6)), tile=tile, method=method)
                assert lazy.dtype == np.uint32 and lazy.shape[1] == 2
                assert_pairs(lazy.compute(), expected)
        quads = obbsat.corners_of_poses(poses)
        expected = obbsat.find_pairs(quads, method="exact")
        assert_pairs(obbsat.dask.find_pairs(quads.reshape(-1, 8), side / 8, method="exact").compute(), expected)
        for chunks in ((3000, 4, 2), (3000, 2, 1)):
            got = obbsat.dask.find_pairs(da.from_array(quads, chunks=chunks), side / 8, method="exact")
            assert_pairs(got.compute(), expected)


@pytest.mark.parametrize("scheduler", ["synchronous", "threads"])
def test_dask_cross_queries_stores_and_extents(dask_array, scheduler):
    import dask

    da = dask_array
    poses = obbsat.testing.make_pose_scene(boxes=20_000, sizes="mixed", pairs_per_box=3, seed=4)
    a, b = poses[:7000], poses[7000:]
    with dask.config.set(scheduler=scheduler):
        expected = obbsat.find_pairs(a, b, method="exact")
        got = obbsat.dask.find_pairs(da.from_array(a, chunks=(2000, 6)), 30.0, da.from_array(b, chunks=(5000, 6)),
                                     method="exact")
        assert_pairs(got.compute(), expected)
        assert_pairs(obbsat.dask.find_pairs(obbsat.records(a), 30.0, b, method="exact").compute(), expected)
        # An extent that covers only part of the scene: the rest falls into the border tiles.
        expected = obbsat.find_pairs(poses)
        assert_pairs(obbsat.dask.find_pairs(poses, 20.0, extent=(100, 100, 300, 200)).compute(), expected)
        # A box across the whole float range, whose bounds are infinite, and a float64 dask array.
        huge = np.concatenate([poses[:3000], [[100, 5, np.finfo(np.float32).max, 1, 1, 0]]]).astype(np.float32)
        expected = obbsat.find_pairs(huge, method="exact")
        assert np.isinf(obbsat.bounds(huge)[-1, [0, 2]]).all() and (expected[:, 1] == 3000).sum() > 5
        got = obbsat.dask.find_pairs(da.from_array(huge.astype(np.float64), chunks=(1000, 6)), 25.0, method="exact")
        assert_pairs(got.compute(), expected)
        # A finite box as large as the plane: the default extent would need too many tiles; a given one holds.
        huge = np.concatenate([huge, [[50, 50, 1e37, 1e37, 3, 4]]])
        with pytest.raises(ValueError, match="pass a larger tile, or an extent"):
            obbsat.dask.find_pairs(huge, 25.0)
        got = obbsat.dask.find_pairs(huge, 25.0, extent=(0, 0, 200, 200), method="exact")
        assert_pairs(got.compute(), obbsat.find_pairs(huge, method="exact"))
        empty = obbsat.dask.find_pairs(np.zeros((0, 6), dtype=np.float32), 1.0)
        assert empty.compute().shape == (0, 2)


def test_dask_refusals(dask_array):
    da = dask_array
    poses = obbsat.testing.make_pose_scene(boxes=5000, seed=6)
    lazy = da.from_array(poses, chunks=(1000, 6))
    with pytest.raises(ValueError, match=r"^method sat4 does not run on poses \(pose_records take "):
        obbsat.dask.find_pairs(lazy, 10.0, method="sat4")
    with pytest.raises(ValueError, match="^tile: expected a finite side > 0, got 0.0$"):
        obbsat.dask.find_pairs(lazy, 0)
    with pytest.raises(ValueError, match="more than 65536: pass a larger tile, or an extent"):
        obbsat.dask.find_pairs(lazy, 0.01)
    with pytest.raises(ValueError, match="^boxes hold poses, against holds corners"):
        obbsat.dask.find_pairs(lazy, 10.0, obbsat.corners_of_poses(poses))
    with pytest.raises(ValueError, match=r"^boxes: expected shape"):
        obbsat.dask.find_pairs(da.zeros((10, 5), chunks=5), 10.0)
    broken = poses.copy()
    broken[3456, 3] = -2
    # Named by its row in the whole array, when the extent is computed (here, at the call).
    with pytest.raises(ValueError, match="^pose 3456: half extent hy is -2, negative$"):
        obbsat.dask.find_pairs(da.from_array(broken, chunks=(1000, 6)), 10.0)
    with pytest.raises(ValueError, match="^against: pose 3456: half extent hy is -2, negative$"):
        obbsat.dask.find_pairs(poses, 10.0, da.from_array(broken, chunks=(1000, 6)))
    # With an extent given nothing is read at the call; the error comes when computed.
    lazy_pairs = obbsat.dask.find_pairs(da.from_array(broken, chunks=(1000, 6)), 10.0, extent=(0, 0, 100, 100))
    with pytest.raises(ValueError, match="^pose 3456: half extent hy is -2, negative$"):
        lazy_pairs.compute(scheduler="synchronous")
