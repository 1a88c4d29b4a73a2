"""Every refusal: the exception type, a message naming what and where, and
nothing written to the caller's output."""

import os
import subprocess
import sys

import numpy as np
import pytest

import obbsat

CANARY = 0xA5


@pytest.fixture
def rects():
    base = np.array([0, 1, 2, 1, 2, 0, 0, 0], dtype=np.float32)
    return np.stack([base + i for i in range(6)])


def canary_out(n):
    return np.full(n, CANARY, dtype=np.uint8)


@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("coordinate", range(8))
def test_non_finite_coordinate_names_rectangle_and_coordinate(rects, value, coordinate):
    names = ["ulx", "uly", "urx", "ury", "lrx", "lry", "llx", "lly"]
    rects[4, coordinate] = value
    out = canary_out(2)
    with pytest.raises(ValueError, match=f"^rectangle 4: coordinate {names[coordinate]} is not finite$"):
        obbsat.collide(rects, np.array([[0, 1], [2, 3]], dtype=np.uint32), out=out)
    assert (out == CANARY).all()
    with pytest.raises(ValueError, match=f"rectangle 4: coordinate {names[coordinate]} is not finite"):
        obbsat.records(rects)
    with pytest.raises(ValueError, match=f"^b: rectangle 4: coordinate {names[coordinate]} is not finite$"):
        obbsat.collide_stream(np.ones_like(rects), rects, out=canary_out(6))


def test_non_finite_refused_whatever_the_pairs(rects):
    # A rectangle no pair uses is still refused: the store's invariant, as in C++.
    rects[5, 0] = np.nan
    with pytest.raises(ValueError, match="rectangle 5"):
        obbsat.collide(rects, [[0, 1]])


def test_float64_beyond_float_range_is_kept_in_float64_and_refused_once_rounded(rects):
    wide = rects.astype(np.float64)
    wide[2, 3] = 1e300
    # Decided in float64, where 1e300 is a finite coordinate like any other.
    assert obbsat.collide(wide, [[0, 1], [0, 2]], method="exact").tolist() == \
        obbsat.collide(wide, [[0, 1], [0, 2]], method="exact", backend="scalar").tolist()
    # Rounded to float32 on request, it becomes infinite and is refused.
    with pytest.raises(ValueError, match="^rectangle 2: coordinate ury is not finite$"):
        obbsat.collide(wide, [[0, 1]], precision="float32")


@pytest.mark.parametrize("dtype", [np.uint32, np.int64, np.uint64, np.int32])
def test_index_out_of_range_names_pair_and_index(rects, dtype):
    pairs = np.array([[0, 1], [1, 2], [3, 6], [7, 0]]).astype(dtype)
    out = canary_out(4)
    with pytest.raises(IndexError, match=r"^pair 2: index 6 is out of range \(6 rectangles\)$"):
        obbsat.collide(rects, pairs, out=out)
    assert (out == CANARY).all()
    with pytest.raises(IndexError, match="pair 2: index 6"):
        obbsat.collide(obbsat.records(rects), pairs, out=out)
    assert (out == CANARY).all()


def test_negative_and_huge_indices(rects):
    out = canary_out(3)
    with pytest.raises(IndexError, match=r"^pair 1: index -1 is out of range \(6 rectangles\)$"):
        obbsat.collide(rects, np.array([[0, 1], [2, -1], [0, 0]]), out=out)
    with pytest.raises(IndexError, match=r"^pair 2: index 4294967296 is out of range"):
        obbsat.collide(rects, np.array([[0, 1], [2, 1], [2**32, 0]], dtype=np.uint64), out=out)
    with pytest.raises(IndexError, match=r"^pair 0: index 4294967295 is out of range"):
        obbsat.collide(rects, np.array([[2**32 - 1, 0]], dtype=np.int64))
    assert (out == CANARY).all()


@pytest.mark.parametrize("pairs", [np.zeros((2, 2), dtype=np.float64), np.zeros((2, 2), dtype=bool),
                                   np.array([["0", "1"]])])
def test_pairs_that_are_not_integers(rects, pairs):
    with pytest.raises(TypeError, match="pairs: expected an integer array"):
        obbsat.collide(rects, pairs)


@pytest.mark.parametrize("shape", [(4,), (4, 3), (2, 2, 2), (0,)])
def test_pairs_of_the_wrong_shape(rects, shape):
    if shape == (0,):
        pytest.skip("an empty list is an empty batch")
    with pytest.raises(ValueError, match=r"pairs: expected shape \(M, 2\)"):
        obbsat.collide(rects, np.zeros(shape, dtype=np.uint32))


@pytest.mark.parametrize("shape", [(6,), (6, 7), (6, 4, 3), (6, 2, 4), (48,)])
def test_rects_of_the_wrong_shape(shape):
    with pytest.raises(ValueError, match=r"rects: expected shape \(N, 8\) or \(N, 4, 2\)"):
        obbsat.collide(np.zeros(shape, dtype=np.float32), [[0, 0]])


def test_rects_that_are_not_numbers():
    with pytest.raises(TypeError, match="rects: expected real numbers"):
        obbsat.collide(np.full((2, 8), "x"), [[0, 1]])
    with pytest.raises(TypeError, match="rects: expected real numbers"):
        obbsat.collide(np.zeros((2, 8), dtype=np.complex64), [[0, 1]])


def test_unknown_method_and_backend(rects):
    out = canary_out(1)
    with pytest.raises(ValueError, match=r"unknown method 'sat5' \(known: sat4, "):
        obbsat.collide(rects, [[0, 1]], method="sat5", out=out)
    with pytest.raises(ValueError, match=r"unknown backend 'neon' \(known: auto, "):
        obbsat.collide(rects, [[0, 1]], backend="neon", out=out)
    with pytest.raises(ValueError, match="threads must be >= 0"):
        obbsat.collide(rects, [[0, 1]], threads=-1, out=out)
    assert (out == CANARY).all()


def test_a_backend_this_cpu_cannot_run(rects):
    missing = [b for b in obbsat.backends(compiled=True) if b not in obbsat.backends()]
    if not missing:
        pytest.skip("this CPU runs every compiled backend")
    with pytest.raises(obbsat.UnsupportedBackendError, match=missing[0]):
        obbsat.collide(rects, [[0, 1]], backend=missing[0])


def test_a_bad_obbsat_backend_variable():
    # Read once per process, so in a fresh interpreter.
    code = ("import obbsat, numpy as np\n"
            "r = np.zeros((2, 8), np.float32)\n"
            "try:\n obbsat.collide(r, [[0, 1]])\n"
            "except obbsat.UnsupportedBackendError as e:\n print('refused:', e)\n"
            "try:\n obbsat.collide(r, [[0, 1]], backend='scalar')\n print('explicit ran')\n"
            "except obbsat.UnsupportedBackendError as e:\n print('explicit refused:', e)\n")
    env = dict(os.environ, OBBSAT_BACKEND="avx1024")
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert done.stdout.startswith("refused:") and "avx1024" in done.stdout
    assert issubclass(obbsat.UnsupportedBackendError, ValueError)


@pytest.mark.parametrize("make_out", [
    lambda n: np.zeros(n, dtype=np.int32),
    lambda n: np.zeros(n, dtype=np.float32),
    lambda n: np.zeros((n, 1), dtype=np.uint8),
    lambda n: np.zeros(2 * n, dtype=np.uint8)[::2],
    lambda n: [0] * n,
])
def test_out_of_the_wrong_kind(rects, make_out):
    with pytest.raises(TypeError, match="out: expected"):
        obbsat.collide(rects, [[0, 1], [1, 2]], out=make_out(2))


def test_out_of_the_wrong_length_or_read_only(rects):
    out = canary_out(3)
    with pytest.raises(ValueError, match="out: holds 3 verdicts, 2 needed"):
        obbsat.collide(rects, [[0, 1], [1, 2]], out=out)
    assert (out == CANARY).all()
    frozen = canary_out(2)
    frozen.flags.writeable = False
    with pytest.raises(TypeError, match="writable"):
        obbsat.collide(rects, [[0, 1], [1, 2]], out=frozen)


def test_stream_batches_of_unequal_length(rects):
    out = canary_out(6)
    with pytest.raises(ValueError, match="stream batches differ in length: 6 rectangles in a, 5 in b"):
        obbsat.collide_stream(rects, rects[:5], out=out)
    assert (out == CANARY).all()


def test_core_refuses_layouts_it_cannot_read_in_place(rects):
    # The package converts before calling _core; _core itself still refuses
    # memory it would misread.
    out = np.zeros(1, dtype=np.uint8)
    pairs = np.array([[0, 1]], dtype=np.uint32)
    with pytest.raises(TypeError, match="rects: expected a C-contiguous float32"):
        obbsat._core.collide_records(rects.astype(np.float64), pairs, out, "sat4", "auto", 1)
    with pytest.raises(TypeError, match="rects: expected a C-contiguous float32"):
        obbsat._core.collide_records(np.asfortranarray(rects), pairs, out, "sat4", "auto", 1)
    with pytest.raises(TypeError, match="pairs: expected a C-contiguous uint32"):
        obbsat._core.collide_records(rects, pairs.astype(np.int64), out, "sat4", "auto", 1)
    with pytest.raises(TypeError, match="pairs: expected a C-contiguous uint32"):
        obbsat._core.collide_records(rects, pairs.astype(">u4"), out, "sat4", "auto", 1)
