"""Verdicts from Python against the scalar reference, the command-line program
and the labelled cases, for every method and backend, in every accepted layout."""

import os
import pickle
import subprocess

import numpy as np
import pytest

import obbsat
from conftest import random_pairs, random_rects, read_case, shared_case_folders

METHODS = obbsat.methods()
BACKENDS = obbsat.backends()


def test_names_come_from_the_library():
    assert METHODS[0] == "sat4" and "exact" in METHODS
    assert BACKENDS[-1] == "scalar"
    assert set(BACKENDS) <= set(obbsat.backends(compiled=True))
    assert obbsat.resolved_backend("auto") in BACKENDS
    assert obbsat.__version__.count(".") == 2


@pytest.fixture(scope="module")
def scene():
    return obbsat.testing.make_scene(rects=4000, pairs=50_000, density="typical", seed=3)


@pytest.fixture(scope="module")
def random_batch():
    rng = np.random.default_rng(11)
    rects = random_rects(rng, 3000)
    return rects, random_pairs(rng, len(rects), 40_000)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("backend", BACKENDS)
def test_every_backend_matches_the_scalar_reference(scene, random_batch, method, backend):
    for rects, pairs in (scene, random_batch):
        expected = obbsat.collide(rects, pairs, method=method, backend="scalar")
        got = obbsat.collide(rects, pairs, method=method, backend=backend)
        assert got.dtype == np.bool_ and got.shape == (len(pairs),)
        assert got.tobytes() == expected.tobytes()
        assert 0 < expected.sum() < len(pairs)


def test_the_scene_is_the_libraries():
    rects, pairs = obbsat.testing.make_scene(rects=1000, pairs=5000, seed=7)
    again, again_pairs = obbsat.testing.make_scene(rects=1000, pairs=5000, seed=7)
    other, _ = obbsat.testing.make_scene(rects=1000, pairs=5000, seed=8)
    assert rects.tobytes() == again.tobytes() and pairs.tobytes() == again_pairs.tobytes()
    assert rects.tobytes() != other.tobytes()
    assert (pairs[:, 0] < pairs[:, 1]).all()
    hits = obbsat.collide(rects, pairs).mean()
    assert 0.1 < hits < 0.5


@pytest.mark.parametrize("folder", shared_case_folders(), ids=lambda p: p.name)
def test_labelled_cases_against_the_program_and_the_truth(folder, tmp_path):
    rects, pairs, truth = read_case(folder)
    program = os.environ.get("OBBSAT_CLI")
    for method in METHODS:
        verdicts = [obbsat.collide(rects, pairs, method=method, backend=b) for b in BACKENDS]
        for v in verdicts[1:]:
            assert v.tobytes() == verdicts[0].tobytes()
        if method == "exact":
            assert (verdicts[0] == truth).all(), f"exact differs from the truth on {folder.name}"
        if program:
            out = tmp_path / f"{method}.txt"
            subprocess.run([program, "collide", "--rects", str(folder / "rects.csv"), "--pairs",
                            str(folder / "pairs.csv"), "--method", method, "--out", str(out)], check=True)
            from_program = np.array([c == "1" for c in out.read_text().split()])
            assert from_program.tobytes() == verdicts[0].tobytes(), f"{method} on {folder.name}"


def test_shared_cases_are_there_when_announced():
    if os.environ.get("OBBSAT_SHARED_CASES") and os.path.isdir(os.environ["OBBSAT_SHARED_CASES"]):
        assert len(shared_case_folders()) >= 8


def test_layouts_and_dtypes_give_the_same_verdicts(random_batch):
    rects, pairs = random_batch
    expected = obbsat.collide(rects, pairs)
    assert obbsat.collide(rects.reshape(-1, 4, 2), pairs).tobytes() == expected.tobytes()
    assert obbsat.collide(rects.astype(np.float64), pairs).tobytes() == expected.tobytes()
    assert obbsat.collide(rects.astype(">f4"), pairs).tobytes() == expected.tobytes()
    assert obbsat.collide(np.asfortranarray(rects), pairs).tobytes() == expected.tobytes()
    assert obbsat.collide(rects.tolist(), pairs.tolist()).tobytes() == expected.tobytes()
    for dtype in (np.int64, np.int32, np.uint64, np.uint16, np.intp):
        assert obbsat.collide(rects, pairs.astype(dtype)).tobytes() == expected.tobytes()
    strided = np.zeros((len(pairs), 3), dtype=np.uint32)
    strided[:, :2] = pairs
    assert obbsat.collide(rects, strided[:, :2]).tobytes() == expected.tobytes()
    assert obbsat.collide(rects, pairs[::-1]).tobytes() == expected[::-1].tobytes()


def test_threads_never_change_verdicts(scene):
    rects, pairs = scene
    expected = obbsat.collide(rects, pairs, threads=1)
    for threads in (0, 2, 3):
        assert obbsat.collide(rects, pairs, threads=threads).tobytes() == expected.tobytes()


def test_out_receives_the_verdicts(random_batch):
    rects, pairs = random_batch
    expected = obbsat.collide(rects, pairs)
    for dtype in (np.bool_, np.uint8):
        out = np.full(len(pairs), 7 if dtype is np.uint8 else True, dtype=dtype)
        returned = obbsat.collide(rects, pairs, out=out)
        assert returned is out
        assert (out.astype(bool) == expected).all() and set(np.unique(out.view(np.uint8))) <= {0, 1}


def test_colliding_pairs_keeps_order_and_dtype(random_batch):
    rects, pairs = random_batch
    verdicts = obbsat.collide(rects, pairs, method="exact")
    for dtype in (np.uint32, np.int64):
        hits = obbsat.colliding_pairs(rects, pairs.astype(dtype), method="exact")
        assert hits.dtype == dtype and hits.shape == (verdicts.sum(), 2)
        assert (hits == pairs[verdicts]).all()


def test_stream_matches_the_indexed_call(random_batch):
    rects, pairs = random_batch
    a, b = rects[pairs[:, 0]], rects[pairs[:, 1]]
    for method in METHODS:
        expected = obbsat.collide(rects, pairs, method=method, backend="scalar")
        for backend in BACKENDS:
            got = obbsat.collide_stream(a, b, method=method, backend=backend, threads=2)
            assert got.tobytes() == expected.tobytes()
    out = np.zeros(len(a), dtype=np.uint8)
    assert obbsat.collide_stream(a.reshape(-1, 4, 2), b, out=out) is out


def test_a_store_decides_like_the_array(random_batch):
    rects, pairs = random_batch
    store = obbsat.records(rects.reshape(-1, 4, 2))
    assert len(store) == len(rects) and obbsat.records(store) is store
    assert store.corners.tobytes() == rects.tobytes() and not store.corners.flags.writeable
    for method in METHODS:
        assert (obbsat.collide(store, pairs, method=method).tobytes()
                == obbsat.collide(rects, pairs, method=method).tobytes())
    again = pickle.loads(pickle.dumps(store))
    assert again.corners.tobytes() == rects.tobytes()
    assert obbsat.colliding_pairs(again, pairs).tolist() == obbsat.colliding_pairs(rects, pairs).tolist()


def test_empty_batches():
    rects = np.zeros((0, 8), dtype=np.float32)
    assert obbsat.collide(rects, np.zeros((0, 2), dtype=np.uint32)).shape == (0,)
    assert obbsat.collide(rects, []).shape == (0,)
    assert obbsat.colliding_pairs(rects, []).shape == (0, 2)
    assert obbsat.collide_stream(rects, rects).shape == (0,)
    assert len(obbsat.records(rects)) == 0


def test_touching_tiles_per_method():
    # Two unit squares sharing an edge: only exact (and conservative, which
    # never misses a contact) must report the contact.
    rects = np.array([[0, 1, 1, 1, 1, 0, 0, 0], [1, 1, 2, 1, 2, 0, 1, 0]], dtype=np.float32)
    assert obbsat.collide(rects, [[0, 1]], method="exact")[0]
    assert obbsat.collide(rects, [[0, 1]], method="conservative")[0]
