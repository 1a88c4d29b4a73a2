"""Arguments every entry point takes alike: None for a default method or
backend, a store where an array is expected (or the wrong kind of store), and
the range of ``threads``."""

import numpy as np
import pytest

import obbsat

RECTS = np.array([[0, 1, 2, 1, 2, 0, 0, 0], [1, 2, 3, 2, 3, 0.5, 1, 0.5], [9, 10, 10, 10, 10, 9, 9, 9]],
                 dtype=np.float32)
POSES = np.array([[1, 0.5, 1, 0.5, 1, 0], [2, 1.25, 1, 0.75, 1, 0], [9.5, 9.5, 0.5, 0.5, 1, 0]], dtype=np.float32)
PAIRS = np.array([[0, 1], [0, 2], [1, 2]], dtype=np.uint32)
# A store of each kind: float32 and double, corners and poses.
STORES = {name: obbsat.records(rows, precision=precision)
          for name, rows, precision in [("RectRecords", RECTS, "float32"), ("PoseRecords", POSES, "float32"),
                                        ("RectRecords64", RECTS, "float64"), ("PoseRecords64", POSES, "float64")]}


def dask_modules():
    da = pytest.importorskip("dask.array")
    import obbsat.dask

    return da, obbsat.dask


# --- None means the default -------------------------------------------------


@pytest.mark.parametrize("boxes", [RECTS, POSES], ids=["corners", "poses"])
def test_none_method_and_backend_of_a_scene_query_are_the_defaults(boxes):
    expected = obbsat.find_pairs(boxes)
    assert np.array_equal(obbsat.find_pairs(boxes, method=None), expected)
    assert np.array_equal(obbsat.find_pairs(boxes, backend=None), expected)
    assert np.array_equal(obbsat.find_pairs(boxes, boxes, method=None, backend=None), obbsat.find_pairs(boxes, boxes))
    finder = obbsat.PairFinder(method=None, backend=None)
    assert repr(finder) == "PairFinder(method='exact', backend='auto', threads=1)"
    assert np.array_equal(finder.find(boxes), expected)


@pytest.mark.parametrize("boxes", [RECTS, POSES], ids=["corners", "poses"])
def test_none_backend_of_a_pair_list_call_is_auto(boxes):
    expected = obbsat.collide(boxes, PAIRS)
    assert np.array_equal(obbsat.collide(boxes, PAIRS, backend=None), expected)
    assert np.array_equal(obbsat.collide(obbsat.records(boxes), PAIRS, method=None, backend=None), expected)
    assert np.array_equal(obbsat.colliding_pairs(boxes, PAIRS, backend=None), PAIRS[expected])
    assert np.array_equal(obbsat.collide_stream(boxes, boxes[::-1], backend=None),
                          obbsat.collide_stream(boxes, boxes[::-1]))


def test_none_backend_of_the_other_calls_is_auto():
    assert obbsat.resolved_backend(None) == obbsat.resolved_backend()
    assert np.array_equal(obbsat.corners_of_poses(POSES, backend=None), obbsat.corners_of_poses(POSES))
    assert np.array_equal(obbsat.corners_of_poses(obbsat.records(POSES), backend=None), obbsat.corners_of_poses(POSES))


def test_none_method_and_backend_in_obbsat_dask():
    da, odask = dask_modules()
    lazy = odask.find_pairs(POSES, 1.0, method=None, backend=None)
    assert np.array_equal(lazy.compute(scheduler="sync"), obbsat.find_pairs(POSES))
    verdicts = odask.collide(RECTS, da.from_array(PAIRS, chunks=(2, 2)), method=None, backend=None)
    assert np.array_equal(verdicts.compute(scheduler="sync"), obbsat.collide(RECTS, PAIRS))


def test_an_unknown_method_is_still_refused():
    with pytest.raises(ValueError, match="unknown method 'sat5'"):
        obbsat.find_pairs(POSES, method="sat5")
    with pytest.raises(ValueError, match="unknown backend 'neon'"):
        obbsat.PairFinder(backend="neon")


# --- A store where it does not go --------------------------------------------


@pytest.mark.parametrize("kind", ["RectRecords", "RectRecords64"])
def test_corners_of_poses_names_a_corner_store(kind):
    with pytest.raises(TypeError, match=r"^corners_of_poses: poses must be a PoseRecords or PoseRecords64 store or "
                                        rf"an \(N, 6\) float array, got {kind}$"):
        obbsat.corners_of_poses(STORES[kind])


@pytest.mark.parametrize("kind", list(STORES))
@pytest.mark.parametrize("side", ["a", "b"])
def test_collide_stream_names_a_store(kind, side):
    boxes = STORES[kind].corners if "Rect" in kind else STORES[kind].poses
    batches = {"a": boxes, "b": boxes}
    batches[side] = STORES[kind]
    with pytest.raises(TypeError, match=rf"^collide_stream: {side} must be an array of corners, \(N, 8\) or "
                                        rf"\(N, 4, 2\), or of poses, \(N, 6\), not a store, got {kind}$"):
        obbsat.collide_stream(batches["a"], batches["b"])


@pytest.mark.parametrize("kind", list(STORES))
def test_pairs_that_are_a_store_are_named(kind):
    store = STORES[kind]
    with pytest.raises(TypeError, match=rf"^collide: pairs must be an \(M, 2\) integer array, got {kind}$"):
        obbsat.collide(RECTS, store)
    with pytest.raises(TypeError, match=rf"^colliding_pairs: pairs must be an \(M, 2\) integer array, got {kind}$"):
        obbsat.colliding_pairs(RECTS, store)


def test_stores_of_both_kinds_still_go_where_they_belong():
    assert obbsat.corners_of_poses(obbsat.records(POSES)).shape == (3, 4, 2)
    assert obbsat.corners_of_poses(STORES["PoseRecords64"]).shape == (3, 4, 2)
    for boxes in (RECTS, POSES, RECTS.astype(np.float64), POSES.astype(np.float64)):
        store = obbsat.records(boxes)
        assert np.array_equal(obbsat.collide(store, PAIRS), obbsat.collide(boxes, PAIRS))
        assert np.array_equal(obbsat.find_pairs(store), obbsat.find_pairs(boxes))
        assert np.array_equal(obbsat.bounds(store), obbsat.bounds(boxes))
    for precision in ("float32", "float64"):
        with pytest.raises(ValueError, match="boxes hold corners, against holds poses"):
            obbsat.find_pairs(obbsat.records(RECTS, precision=precision), obbsat.records(POSES, precision=precision))


# --- threads: 0 .. 2**32 - 1 ---------------------------------------------------

OUT_OF_RANGE = [-1, 2**32, 2**32 + 40, 2**64, -(2**63)]
THREADS_MESSAGE = r"^threads must be >= 0 and <= 4294967295 \(0 means every core\), not {}$"


def threads_calls():
    """Every entry point that takes threads, as a function of it."""
    return {
        "collide": lambda t: obbsat.collide(RECTS, PAIRS, threads=t),
        "collide store": lambda t: obbsat.collide(obbsat.records(POSES), PAIRS, threads=t),
        "colliding_pairs": lambda t: obbsat.colliding_pairs(POSES, PAIRS, threads=t),
        "collide_stream": lambda t: obbsat.collide_stream(RECTS, RECTS, threads=t),
        "find_pairs": lambda t: obbsat.find_pairs(POSES, threads=t),
        "PairFinder": lambda t: obbsat.PairFinder(threads=t),
    }


@pytest.mark.parametrize("threads", OUT_OF_RANGE)
@pytest.mark.parametrize("call", sorted(threads_calls()))
def test_threads_out_of_range_are_refused(call, threads):
    out = np.full(len(PAIRS), 0xA5, dtype=np.uint8)
    with pytest.raises(ValueError, match=THREADS_MESSAGE.format(threads)):
        if call == "collide":
            obbsat.collide(RECTS, PAIRS, threads=threads, out=out)
        else:
            threads_calls()[call](threads)
    assert (out == 0xA5).all()


@pytest.mark.parametrize("threads", [2.0, 2.5, "2"])
@pytest.mark.parametrize("call", sorted(threads_calls()))
def test_threads_that_are_not_whole_numbers_are_refused(call, threads):
    out = np.full(len(PAIRS), 0xA5, dtype=np.uint8)
    with pytest.raises(TypeError, match="threads must be a whole number"):
        if call == "collide":
            obbsat.collide(RECTS, PAIRS, threads=threads, out=out)
        else:
            threads_calls()[call](threads)
    assert (out == 0xA5).all()


@pytest.mark.parametrize("threads", OUT_OF_RANGE)
def test_threads_out_of_range_are_refused_by_obbsat_dask(threads):
    da, odask = dask_modules()
    with pytest.raises(ValueError, match=THREADS_MESSAGE.format(threads)):
        odask.collide(RECTS, da.from_array(PAIRS, chunks=(2, 2)), threads=threads)
    with pytest.raises(ValueError, match=THREADS_MESSAGE.format(threads)):
        odask.find_pairs(POSES, 1.0, threads=threads)


@pytest.mark.parametrize("threads", [2**32 + 40, 2**32])
def test_the_compiled_entry_points_refuse_threads_that_would_wrap(threads):
    with pytest.raises(ValueError, match=THREADS_MESSAGE.format(threads)):
        obbsat._core.collide_records(RECTS, PAIRS, np.empty(3, bool), "sat4", "auto", threads)
    with pytest.raises(ValueError, match=THREADS_MESSAGE.format(threads)):
        obbsat._core.PairFinder("exact", "auto", threads)


@pytest.mark.parametrize("call", sorted(threads_calls()))
def test_threads_at_the_ends_of_the_range_run(call):
    for threads in (0, 1, 2**32 - 1):
        threads_calls()[call](threads)
