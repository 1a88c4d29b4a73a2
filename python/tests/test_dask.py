"""obbsat.dask on a LocalCluster of two worker processes (loopback only):
verdicts identical to the single-process call, for corners and for poses, the
rectangles sent to each worker once, errors named by their row in the whole
list; the scene query in tiles gives the in-memory pairs."""

import doctest

import numpy as np
import pytest

import obbsat
from conftest import random_pairs, random_poses, utm_poses

da = pytest.importorskip("dask.array")
distributed = pytest.importorskip("distributed")
import obbsat.dask  # noqa: E402


# These two run first, before the cluster fixture makes its client the default.
def test_without_a_cluster_the_local_scheduler_works(scene):
    rects, pairs = scene
    lazy = obbsat.dask.collide(rects, da.from_array(pairs, chunks=(50_000, 2)))
    assert lazy.chunks == ((50_000,) * 6,)
    assert lazy.compute(scheduler="threads").tobytes() == obbsat.collide(rects, pairs).tobytes()


def test_module_example():
    result = doctest.testmod(obbsat.dask, extraglobs={"np": np, "obbsat": obbsat})
    assert result.attempted > 0 and result.failed == 0


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                       dashboard_address=None, worker_dashboard_address=None)
    with cluster, distributed.Client(cluster, timeout=60) as c:
        c.wait_for_workers(2, timeout=60)
        yield c


@pytest.fixture(scope="module")
def scene():
    return obbsat.testing.make_scene(rects=20_000, pairs=300_000, density="typical", seed=6)


def test_two_workers_give_the_single_process_verdicts(client, scene):
    rects, pairs = scene
    lazy_pairs = da.from_array(pairs, chunks=(40_000, 2))
    for method in obbsat.methods():
        expected = obbsat.collide(rects, pairs, method=method)
        got = obbsat.dask.collide(rects, lazy_pairs, method=method, client=client).compute()
        assert got.dtype == np.bool_ and got.tobytes() == expected.tobytes()
    hits = obbsat.dask.colliding_pairs(rects, lazy_pairs.astype(np.int64), method="exact").compute()
    assert (hits == obbsat.colliding_pairs(rects, pairs.astype(np.int64), method="exact")).all()


def test_work_is_spread_and_the_rectangles_sent_once(client, scene):
    rects, pairs = scene
    store = obbsat.dask.shared_records(rects, client)
    holders = client.who_has([store])[store.key]
    assert len(holders) == 2, "the store is on both workers"
    lazy = obbsat.dask.collide(store, da.from_array(pairs, chunks=(20_000, 2)))
    with distributed.get_task_stream(client) as stream:
        verdicts = client.compute(lazy).result()
    ran_on = {t["worker"] for t in stream.data if "_decide_chunk" in str(t["key"])}
    assert len(ran_on) == 2, "both workers decided chunks"
    assert verdicts.tobytes() == obbsat.collide(rects, pairs).tobytes()
    # The graph refers to the store by key: no task carries the rectangles.
    graph = dict(lazy.__dask_graph__())
    assert all(not isinstance(v, np.ndarray) or v.nbytes < 1 << 20 for v in graph.values())


def test_an_index_out_of_range_names_its_row(client, scene):
    rects, pairs = scene
    bad = pairs.copy()
    bad[123_456, 1] = len(rects)
    lazy = obbsat.dask.collide(rects, da.from_array(bad, chunks=(40_000, 2)))
    with pytest.raises(IndexError, match=r"^pair 123456: index 20000 is out of range \(20000 rectangles\)$"):
        lazy.compute()


def test_bad_arguments_are_refused_before_any_work(client, scene):
    rects, pairs = scene
    broken = rects.copy()
    broken[7, 2] = np.nan
    with pytest.raises(ValueError, match="rectangle 7: coordinate urx is not finite"):
        obbsat.dask.collide(broken, da.from_array(pairs, chunks=(40_000, 2)))
    with pytest.raises(TypeError, match="pairs: expected a dask.array"):
        obbsat.dask.collide(rects, pairs)
    with pytest.raises(ValueError, match=r"pairs: expected shape \(M, 2\)"):
        obbsat.dask.collide(rects, da.zeros((10, 3), dtype=np.uint32, chunks=5))


def test_poses_on_two_workers(client):
    rng = np.random.default_rng(9)
    poses = random_poses(rng, 20_000, spread=100.0)
    pairs = random_pairs(rng, len(poses), 200_000)
    lazy_pairs = da.from_array(pairs, chunks=(40_000, 2))
    for method in [None] + obbsat.methods(poses=True):
        expected = obbsat.collide(poses, pairs, method=method)
        assert 0 < expected.sum() < len(pairs)
        got = obbsat.dask.collide(poses, lazy_pairs, method=method, client=client).compute()
        assert got.dtype == np.bool_ and got.tobytes() == expected.tobytes(), method
    store = obbsat.dask.shared_records(poses, client)
    assert len(client.who_has([store])[store.key]) == 2, "the pose store is on both workers"
    hits = obbsat.dask.colliding_pairs(store, lazy_pairs.astype(np.int64), method="exact").compute()
    assert (hits == obbsat.colliding_pairs(poses, pairs.astype(np.int64), method="exact")).all()
    with pytest.raises(ValueError, match=r"^method sat4 does not run on poses \(pose_records take "):
        obbsat.dask.collide(store, lazy_pairs, method="sat4").compute()


def test_double_stores_on_two_workers(client):
    """float64 data is broadcast as a double store (pickled as its rows) and
    decided in float64 on each worker, as obbsat.collide decides the array."""
    poses = utm_poses(4000, 21, span=600)
    rng = np.random.default_rng(3)
    pairs = random_pairs(rng, len(poses), 100_000)
    pairs[:2000] = np.arange(4000, dtype=np.uint32).reshape(-1, 2)
    lazy_pairs = da.from_array(pairs, chunks=(25_000, 2))
    for rows in (poses, obbsat.corners_of_poses(poses).reshape(-1, 8)):
        store = obbsat.dask.shared_records(rows, client)
        assert len(client.who_has([store])[store.key]) == 2, "the double store is on both workers"
        assert type(store.result()) in (obbsat.RectRecords64, obbsat.PoseRecords64)
        expected = obbsat.collide(rows, pairs, method="exact")
        assert expected.tobytes() != obbsat.collide(rows, pairs, method="exact", precision="float32").tobytes()
        got = obbsat.dask.collide(store, lazy_pairs, method="exact").compute()
        assert got.tobytes() == expected.tobytes()


def test_a_bad_pose_is_refused_before_any_work(client):
    poses = np.tile(np.array([0, 0, 1, 1, 1, 0], dtype=np.float32), (10, 1))
    poses[7, 3] = -2
    with pytest.raises(ValueError, match="^pose 7: half extent hy is -2, negative$"):
        obbsat.dask.collide(poses, da.zeros((10, 2), dtype=np.uint32, chunks=5))


def test_a_scene_query_in_tiles_on_two_workers(client):
    poses = obbsat.testing.make_pose_scene(boxes=40_000, sizes="mixed", pairs_per_box=3, seed=12)
    lazy_boxes = da.from_array(poses, chunks=(10_000, 6))
    side = float(obbsat.bounds(poses)[:, 2:].max())
    lazy = obbsat.dask.find_pairs(lazy_boxes, side / 6, method="exact")
    with distributed.get_task_stream(client) as stream:
        pairs = client.compute(lazy).result()
    assert pairs.tobytes() == obbsat.find_pairs(poses, method="exact").tobytes()
    ran_on = {t["worker"] for t in stream.data if "_tile_pairs" in str(t["key"])}
    assert len(ran_on) == 2, "both workers searched tiles"
    a, b = poses[:15_000], poses[15_000:]
    cross = obbsat.dask.find_pairs(da.from_array(a, chunks=(5000, 6)), side / 4, b).compute()
    assert cross.tobytes() == obbsat.find_pairs(a, b).tobytes()
