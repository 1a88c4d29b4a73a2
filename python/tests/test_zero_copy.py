"""Matching arrays are read where they are: a call allocates nothing that
grows with the batch, neither in Python (tracemalloc sees numpy's buffers)
nor in the process as a whole (peak resident memory, reset before the call)."""

import pathlib
import tracemalloc

import numpy as np
import pytest

import obbsat

N = 1_000_000  # 32 MB of rectangles, 8 MB of pairs
MB = 1 << 20


@pytest.fixture(scope="module")
def batch():
    rng = np.random.default_rng(5)
    rects = np.tile(np.array([0, 1, 2, 1, 2, 0, 0, 0], dtype=np.float32), (N, 1))
    rects += rng.uniform(-100, 100, size=(N, 1)).astype(np.float32)
    pairs = rng.integers(0, N, size=(N, 2)).astype(np.uint32)
    out = np.zeros(N, dtype=bool)
    return rects, pairs, out


def traced_peak(call):
    tracemalloc.start()
    try:
        call()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_matching_arrays_allocate_nothing_in_python(batch):
    rects, pairs, out = batch
    assert traced_peak(lambda: obbsat.collide(rects, pairs, out=out)) < 64 * 1024
    assert traced_peak(lambda: obbsat.collide(rects.reshape(N, 4, 2), pairs, out=out)) < 64 * 1024
    # The check is able to fail: a float64 copy of the rectangles is 32 MB.
    assert traced_peak(lambda: obbsat.collide(rects.astype(np.float64), pairs, out=out)) > 32 * MB
    # int64 pairs are converted once: an 8 MB uint32 temporary.
    wide_pairs = pairs.astype(np.int64)
    assert N * 8 <= traced_peak(lambda: obbsat.collide(rects, wide_pairs, out=out)) < 40 * MB


def peak_growth(call):
    """How far peak resident memory rises above the current resident memory during `call`."""
    clear = pathlib.Path("/proc/self/clear_refs")

    def field(name):
        for line in pathlib.Path("/proc/self/status").read_text().splitlines():
            if line.startswith(name + ":"):
                return int(line.split()[1]) * 1024
        raise LookupError(name)

    clear.write_text("5")  # resets VmHWM to the current resident size
    before = field("VmRSS")
    call()
    return field("VmHWM") - before


def test_matching_arrays_allocate_nothing_in_the_library(batch):
    if not pathlib.Path("/proc/self/clear_refs").exists():
        pytest.skip("needs Linux's /proc/self/clear_refs")
    rects, pairs, out = batch
    obbsat.collide(rects, pairs, out=out, threads=2)  # thread pool and first touch
    assert peak_growth(lambda: obbsat.collide(rects, pairs, out=out, threads=2)) < 4 * MB
    copied = peak_growth(lambda: obbsat.records(rects))
    assert copied > 24 * MB, "a RectRecords copy of 32 MB should show"


def test_aligned_copies_only_what_is_not_aligned():
    raw = np.zeros(8 * 1000 + 16, dtype=np.float32)
    offset = next(k for k in range(16) if (raw.ctypes.data + 4 * k) % 64 == 16)
    unaligned = raw[offset:offset + 8000].reshape(1000, 8)
    unaligned[:] = np.arange(8000, dtype=np.float32).reshape(1000, 8)
    assert unaligned.ctypes.data % 64 == 16
    copy = obbsat.aligned(unaligned)
    assert copy is not unaligned and copy.ctypes.data % 64 == 0
    assert copy.dtype == np.float32 and copy.shape == (1000, 8) and copy.flags.c_contiguous
    assert np.array_equal(copy, unaligned)
    assert obbsat.aligned(copy) is copy
    assert obbsat.aligned(unaligned, alignment=16) is unaligned
    assert obbsat.aligned(unaligned[:, :6]).flags.c_contiguous  # a strided view is copied too
    rects, pairs = obbsat.testing.make_scene(rects=1000, pairs=4000, seed=3)
    assert np.array_equal(obbsat.collide(obbsat.aligned(rects), pairs), obbsat.collide(rects, pairs))
    with pytest.raises(ValueError, match="power of two"):
        obbsat.aligned(copy, alignment=48)
