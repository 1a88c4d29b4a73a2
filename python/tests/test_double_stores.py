"""The double stores (obbsat.RectRecords64, obbsat.PoseRecords64): what
obbsat.records builds from float64 data, every double kept. Each call over
one gives the bytes the same call gives over the float64 array of its rows,
on UTM-like scenes where float32 rounding flips verdicts, so a store that
rounded would fail here. float32 is taken only when asked for, and a store
is never converted, either way."""

import itertools
import pickle

import numpy as np
import pytest

import obbsat
from conftest import utm_poses

POSE_METHODS64 = ["conservative", "exact", "local"]
CORNER_METHODS64 = ["conservative", "exact"]


@pytest.fixture(scope="module")
def scene():
    """float64 poses and their float64 corners, their stores, and pairs:
    every pair among the first 80 boxes and random pairs of the rest."""
    poses = utm_poses(300, 11)
    rects = obbsat.corners_of_poses(poses).reshape(-1, 8)
    rng = np.random.default_rng(5)
    pairs = np.concatenate([np.array(list(itertools.combinations(range(80), 2)), dtype=np.uint32),
                            rng.integers(0, len(poses), size=(3000, 2)).astype(np.uint32)])
    return poses, rects, obbsat.records(poses), obbsat.records(rects), pairs


def test_float32_rounding_flips_verdicts_of_the_scene(scene):
    """The premise of this file: a store that held float32 would answer otherwise."""
    poses, rects, _, _, pairs = scene
    for rows in (poses, rects):
        rounded = obbsat.collide(rows, pairs, method="exact", precision="float32")
        assert (rounded != obbsat.collide(rows, pairs, method="exact")).sum() > 5
        assert not np.array_equal(obbsat.find_pairs(rows, precision="float32"), obbsat.find_pairs(rows))


def test_records_of_float64_is_a_double_store_holding_every_double(scene):
    poses, rects, pose_store, rect_store, _ = scene
    assert type(pose_store) is obbsat.PoseRecords64 and len(pose_store) == len(poses)
    assert type(rect_store) is obbsat.RectRecords64 and len(rect_store) == len(rects)
    view = pose_store.poses
    assert view.dtype == np.float64 and view.shape == (len(poses), 6) and view.strides == (64, 8)
    assert not view.flags.writeable and view.tobytes() == poses.tobytes()
    corners = rect_store.corners
    assert corners.dtype == np.float64 and corners.shape == (len(rects), 8) and corners.flags.c_contiguous
    assert not corners.flags.writeable and corners.tobytes() == rects.tobytes()
    assert obbsat.records(rects.reshape(-1, 4, 2)).corners.tobytes() == rects.tobytes()
    assert obbsat.records(pose_store) is pose_store and obbsat.records(rect_store, precision="float64") is rect_store
    # The view keeps its store alive.
    view = obbsat.records(poses).poses
    assert view.tobytes() == poses.tobytes()
    assert repr(pose_store) == f"PoseRecords64({len(poses)} poses)"
    assert repr(rect_store) == f"RectRecords64({len(rects)} rectangles)"
    assert repr(obbsat.records(rects.astype(np.float32))) == f"RectRecords({len(rects)} rectangles)"


def test_precision_picks_the_store_explicitly(scene):
    poses, rects, _, _, pairs = scene
    rounded = obbsat.records(poses, precision="float32")
    assert type(rounded) is obbsat.PoseRecords
    assert rounded.poses.tobytes() == poses.astype(np.float32).tobytes()
    assert np.array_equal(obbsat.collide(rounded, pairs), obbsat.collide(poses.astype(np.float32), pairs))
    assert type(obbsat.records(rects, precision="float32")) is obbsat.RectRecords
    widened = obbsat.records(poses.astype(np.float32), precision="float64")
    assert type(widened) is obbsat.PoseRecords64
    assert widened.poses.tobytes() == poses.astype(np.float32).astype(np.float64).tobytes()
    whole = np.array([[0, 0, 2, 1, 1, 0], [3, 0, 1, 1, 0, 1]], dtype=np.int64)
    assert type(obbsat.records(whole)) is obbsat.PoseRecords
    assert type(obbsat.records(whole, precision="float64")) is obbsat.PoseRecords64


@pytest.mark.parametrize("threads", [1, 2])
def test_collide_over_a_double_store_is_the_float64_array_call(scene, threads):
    poses, rects, pose_store, rect_store, pairs = scene
    for method in POSE_METHODS64 + [None]:
        for backend in obbsat.backends():
            expected = obbsat.collide(poses, pairs, method=method, backend=backend, threads=threads)
            got = obbsat.collide(pose_store, pairs, method=method, backend=backend, threads=threads)
            assert got.tobytes() == expected.tobytes(), (method, backend)
    for method in CORNER_METHODS64 + [None]:
        expected = obbsat.collide(rects, pairs, method=method, threads=threads)
        assert obbsat.collide(rect_store, pairs, method=method, threads=threads).tobytes() == expected.tobytes()
    out = np.zeros(len(pairs), dtype=np.uint8)
    assert obbsat.collide(rect_store, pairs.astype(np.int64), out=out) is out
    assert out.astype(bool).tolist() == obbsat.collide(rects, pairs).tolist()
    for rows, store in ((poses, pose_store), (rects, rect_store)):
        assert np.array_equal(obbsat.colliding_pairs(store, pairs, method="exact"),
                              obbsat.colliding_pairs(rows, pairs, method="exact"))


def test_find_pairs_and_pair_finder_over_double_stores(scene):
    poses, rects, pose_store, rect_store, _ = scene
    for rows, store, methods in ((poses, pose_store, POSE_METHODS64), (rects, rect_store, CORNER_METHODS64)):
        for method in methods:
            expected = obbsat.find_pairs(rows, method=method)
            assert np.array_equal(obbsat.find_pairs(store, method=method, threads=2), expected)
            finder = obbsat.PairFinder(method=method)
            assert np.array_equal(finder.find(store), expected)
        a, b = rows[:120], rows[120:]
        expected = obbsat.find_pairs(a, b)
        for other in (b, obbsat.records(b), b.astype(np.float32).astype(np.float64)):
            assert np.array_equal(obbsat.find_pairs(obbsat.records(a), other), obbsat.find_pairs(a, other))
        assert np.array_equal(obbsat.find_pairs(obbsat.records(a), obbsat.records(b)), expected)
        assert np.array_equal(obbsat.PairFinder().find(obbsat.records(a), obbsat.records(b)), expected)
        # A float32 side is widened (exactly), as beside a float64 array.
        small = b.astype(np.float32)
        assert np.array_equal(obbsat.find_pairs(obbsat.records(a), small), obbsat.find_pairs(a, small))
        groups = np.arange(len(rows)) % 3
        assert np.array_equal(obbsat.find_pairs(store, groups=groups), obbsat.find_pairs(rows, groups=groups))


def test_a_pair_finder_follows_double_stores_frame_by_frame():
    poses = utm_poses(400, 8, span=250)
    rng = np.random.default_rng(2)
    finder = obbsat.PairFinder(events=True)
    for _ in range(5):
        poses[:, :2] += rng.uniform(-0.005, 0.005, size=(len(poses), 2))
        assert np.array_equal(finder.find(obbsat.records(poses), ids=np.arange(len(poses))),
                              obbsat.find_pairs(poses))


def test_bounds_and_corners_of_double_stores(scene):
    poses, rects, pose_store, rect_store, _ = scene
    assert obbsat.bounds(pose_store).tobytes() == obbsat.bounds(poses).tobytes()
    assert obbsat.bounds(rect_store).tobytes() == obbsat.bounds(rects).tobytes()
    corners = obbsat.corners_of_poses(pose_store)
    assert corners.dtype == np.float64 and corners.tobytes() == obbsat.corners_of_poses(poses).tobytes()


def test_a_double_store_pickles_as_its_rows(scene):
    poses, rects, pose_store, rect_store, pairs = scene
    for store, rows in ((pose_store, poses), (rect_store, rects)):
        again = pickle.loads(pickle.dumps(store))
        assert type(again) is type(store) and len(again) == len(store)
        view = again.poses if isinstance(again, obbsat.PoseRecords64) else again.corners
        assert view.tobytes() == rows.tobytes()
        assert obbsat.collide(again, pairs, method="exact").tobytes() == \
            obbsat.collide(rows, pairs, method="exact").tobytes()
    empty = pickle.loads(pickle.dumps(obbsat.records(np.zeros((0, 6)))))
    assert type(empty) is obbsat.PoseRecords64 and len(empty) == 0 and obbsat.collide(empty, []).shape == (0,)


def test_bad_rows_are_named_and_build_no_store(scene):
    poses, rects, _, _, _ = scene
    bad = poses.copy()
    bad[3, 3] = -1.0
    with pytest.raises(ValueError, match=r"^pose 3: half extent hy is -1, negative"):
        obbsat.records(bad)
    bad = poses.copy()
    bad[7, 4:] = 0.0
    with pytest.raises(ValueError, match=r"^pose 7: "):
        obbsat.PoseRecords64(bad)
    bad = rects.copy()
    bad[2, 3] = np.nan
    with pytest.raises(ValueError, match=r"^rectangle 2: coordinate ury is nan"):
        obbsat.records(bad)
    with pytest.raises(ValueError, match=r"^rectangle 2: coordinate ury is nan"):
        obbsat.records(bad.astype(np.float32), precision="float64")
    with pytest.raises(TypeError, match=r"corners: expected a C-contiguous float64 array of shape \(N, 8\)"):
        obbsat.RectRecords64(rects.astype(np.float32))


def test_no_precision_converts_a_store(scene):
    poses, rects, pose_store, rect_store, pairs = scene
    for store in (pose_store, rect_store):
        name = type(store).__name__
        message = rf"^precision='float32' asks for float32 rows, but a {name} holds float64 and is never rounded"
        for call in (lambda: obbsat.records(store, precision="float32"),
                     lambda: obbsat.collide(store, pairs, precision="float32"),
                     lambda: obbsat.colliding_pairs(store, pairs, precision="float32"),
                     lambda: obbsat.find_pairs(store, precision="float32"),
                     lambda: obbsat.find_pairs(poses if store is pose_store else rects, store, precision="float32"),
                     lambda: obbsat.PairFinder(precision="float32").find(store),
                     lambda: obbsat.bounds(store, precision="float32")):
            with pytest.raises(ValueError, match=message):
                call()
    with pytest.raises(ValueError, match=r"PoseRecords64 holds float64 and is never rounded"):
        obbsat.corners_of_poses(pose_store, precision="float32")
    for rows in (poses, rects):
        store = obbsat.records(rows, precision="float32")
        message = rf"^precision='float64' asks for float64 rows, but a {type(store).__name__} holds float32"
        for call in (lambda: obbsat.records(store, precision="float64"),
                     lambda: obbsat.collide(store, pairs, precision="float64"),
                     lambda: obbsat.find_pairs(store, precision="float64")):
            with pytest.raises(ValueError, match=message):
                call()
    with pytest.raises(ValueError, match=r"^boxes is a PoseRecords64, against a PoseRecords: a scene query over two "
                                         r"stores takes them of one precision"):
        obbsat.find_pairs(pose_store, obbsat.records(poses, precision="float32"))


def test_methods_without_a_double_form_are_refused_on_double_stores(scene):
    _, _, pose_store, rect_store, pairs = scene
    with pytest.raises(ValueError, match=r"^method sat4 does not run on float64 corners \(they take conservative, "
                                         r"exact\)"):
        obbsat.collide(rect_store, pairs, method="sat4")
    with pytest.raises(ValueError, match=r"^method local does not run on float64 corners"):
        obbsat.find_pairs(rect_store, method="local")
    with pytest.raises(ValueError, match=r"^method sat4 does not run on float64 poses"):
        obbsat.PairFinder(method="sat4").find(pose_store)


def test_contacts_and_distances_over_a_double_store_are_the_float64_arrays(scene):
    """Contacts and distances over a double store are computed in double, bit
    for bit those of its float64 rows; asking for float32 is refused, never
    rounded; the scene's contacts of a double store are in double too."""
    poses, rects, pose_store, rect_store, pairs = scene
    for rows, store in ((poses, pose_store), (rects, rect_store)):
        for call in (obbsat.contacts, obbsat.distances):
            got, want = call(store, pairs), call(rows, pairs)
            for field in type(want).__slots__:
                a, b = getattr(got, field), getattr(want, field)
                assert a.dtype == b.dtype and a.tobytes() == b.tobytes(), field
        store_pairs, store_c = obbsat.find_contacts(store)
        rows_pairs, rows_c = obbsat.find_contacts(rows)
        assert store_pairs.tolist() == rows_pairs.tolist() and store_c.depths.dtype == np.float64
        assert store_c.depths.tobytes() == rows_c.depths.tobytes()
        assert store_c.points.tobytes() == rows_c.points.tobytes()
        for call in (lambda: obbsat.contacts(store, pairs, precision="float32"),
                     lambda: obbsat.distances(store, pairs, precision="float32"),
                     lambda: obbsat.find_contacts(store, precision="float32")):
            with pytest.raises(ValueError, match=rf"a {type(store).__name__} holds float64 and is never rounded"):
                call()


def test_dask_over_a_double_store(scene):
    da = pytest.importorskip("dask.array")
    import obbsat.dask

    poses, rects, pose_store, rect_store, pairs = scene
    shared = obbsat.dask.shared_records(poses)
    assert type(shared) is obbsat.PoseRecords64 and shared.poses.tobytes() == poses.tobytes()
    assert type(obbsat.dask.shared_records(poses, precision="float32")) is obbsat.PoseRecords
    lazy_pairs = da.from_array(pairs, chunks=(1000, 2))
    for rows, store in ((poses, pose_store), (rects, rect_store)):
        for rects_given in (store, obbsat.dask.shared_records(rows), rows):
            got = obbsat.dask.collide(rects_given, lazy_pairs, method="exact").compute(scheduler="synchronous")
            assert got.tobytes() == obbsat.collide(rows, pairs, method="exact").tobytes()
        got = obbsat.dask.find_pairs(store, 40.0).compute(scheduler="synchronous")
        assert np.array_equal(got, obbsat.find_pairs(rows))
    rounded = obbsat.dask.collide(poses, lazy_pairs, method="exact", precision="float32")
    assert rounded.compute(scheduler="synchronous").tobytes() == \
        obbsat.collide(poses, pairs, method="exact", precision="float32").tobytes()
    with pytest.raises(ValueError, match=r"method sat4 does not run on float64 corners"):
        obbsat.dask.find_pairs(rect_store, 40.0, method="sat4")
