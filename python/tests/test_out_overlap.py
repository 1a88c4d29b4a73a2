"""An ``out`` that shares memory with the arrays a call reads is refused
(ValueError naming both) before anything is written: verdicts written by one
thread would overwrite indices or coordinates another has yet to read."""

import subprocess
import sys

import numpy as np
import pytest

import obbsat
from obbsat import _core


def apart_rects(n=64):
    """Unit squares ten apart along x: no two collide, so every verdict is 0."""
    x = 10 * np.arange(n, dtype=np.float32)[:, None]
    return np.concatenate([x, x * 0 + 1, x + 1, x * 0 + 1, x + 1, x * 0, x, x * 0], axis=1).astype(np.float32)


def apart_poses(n=64):
    x = 10 * np.arange(n, dtype=np.float32) + 0.5
    return np.stack([x, x * 0 + 0.5, x * 0 + 0.5, x * 0 + 0.5, x * 0 + 1, x * 0], axis=1).astype(np.float32)


def pairs_with_room(m=4096, n=64):
    """uint32 (m, 2) pairs (i, i + 1) of distinct boxes at the start of a
    buffer with m bytes after them, and the buffer as bytes."""
    buffer = np.zeros(9 * m, dtype=np.uint8)
    pairs = buffer[:8 * m].view(np.uint32).reshape(m, 2)
    pairs[:, 0] = np.arange(m) % n
    pairs[:, 1] = (pairs[:, 0] + 1) % n
    return pairs, buffer


def test_out_sharing_pairs_with_two_threads_is_refused_in_a_fresh_process():
    # Unchecked, this crashed (SIGSEGV) or read indices already overwritten,
    # so it runs in a child process.
    code = ("import numpy as np, obbsat\n"
            "rects, pairs = obbsat.testing.make_scene(rects=2000, pairs=20_000, seed=4)\n"
            "out = pairs.view(np.uint8).reshape(-1)[:len(pairs)]\n"
            "before = pairs.copy()\n"
            "try:\n"
            "    obbsat.collide(rects, pairs, out=out, threads=2)\n"
            "    print('accepted')\n"
            "except ValueError as e:\n"
            "    print('refused:', e, np.array_equal(pairs, before))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, f"exit status {done.returncode}: {done.stderr[-2000:]}"
    assert done.stdout.strip() == "refused: out and pairs share memory: out must not overlap pairs True"


@pytest.mark.parametrize("start", [0, 8 * 4096 - 8, 8 * 4096 - 1])
@pytest.mark.parametrize("form", ["corners", "poses", "corner store", "pose store"])
def test_out_sharing_pairs_is_refused(form, start):
    rects = {"corners": apart_rects(), "poses": apart_poses(), "corner store": obbsat.records(apart_rects()),
             "pose store": obbsat.records(apart_poses())}[form]
    pairs, buffer = pairs_with_room()
    before = buffer.copy()
    with pytest.raises(ValueError, match="^out and pairs share memory: out must not overlap pairs$"):
        obbsat.collide(rects, pairs, out=buffer[start:start + len(pairs)], threads=1)
    assert np.array_equal(buffer, before)


def test_out_sharing_converted_pairs_is_refused():
    # int64 pairs are copied before the call, but out would still overwrite the caller's array.
    pairs = np.array([[0, 1]] * 64, dtype=np.int64)
    with pytest.raises(ValueError, match="out and pairs share memory"):
        obbsat.collide(apart_rects(), pairs, out=pairs.view(np.uint8)[:64])


def test_out_sharing_rects_is_refused():
    rects, pairs = obbsat.testing.make_scene(rects=2000, pairs=20_000, seed=4)
    before = rects.copy()
    out = rects.view(np.uint8).reshape(-1)[:len(pairs)]
    with pytest.raises(ValueError, match="^out and rects share memory: out must not overlap rects$"):
        obbsat.collide(rects, pairs, out=out, threads=2)
    assert np.array_equal(rects, before)
    poses = np.zeros((len(pairs), 6), dtype=np.float32)
    poses[:] = apart_poses(1)
    before = poses.copy()
    with pytest.raises(ValueError, match="^out and rects share memory"):
        obbsat.collide(poses, pairs % 64, out=poses.view(np.uint8).reshape(-1)[-len(pairs):], threads=2)
    assert np.array_equal(poses, before)


@pytest.mark.parametrize("side", ["a", "b"])
@pytest.mark.parametrize("make", [apart_rects, apart_poses])
def test_out_sharing_a_stream_batch_is_refused(make, side):
    batches = {"a": make(), "b": make()}
    before = batches[side].copy()
    out = batches[side].view(np.uint8).reshape(-1)[:len(before)]
    with pytest.raises(ValueError, match=f"^out and {side} share memory: out must not overlap {side}$"):
        obbsat.collide_stream(batches["a"], batches["b"], out=out)
    assert np.array_equal(batches[side], before)


def test_out_apart_from_the_inputs_is_accepted():
    pairs, buffer = pairs_with_room()
    out = buffer[8 * len(pairs):]  # starts right after the last pair
    for threads in (1, 2):
        out[:] = 0xA5
        obbsat.collide(apart_rects(), pairs, out=out, threads=threads)
        assert not out.any()
    a = apart_rects()
    obbsat.collide_stream(a, a.copy(), out=np.empty(len(a), bool))


def test_the_compiled_entry_points_refuse_overlap_themselves():
    # The address ranges are checked in the binding too, for callers of obbsat._core.
    rects, poses = apart_rects(), apart_poses()
    for store, call, rows in [(rects, _core.collide_records, "rects"), (poses, _core.collide_poses, "poses"),
                              (obbsat.records(rects), _core.collide_store, None),
                              (obbsat.records(poses), _core.collide_pose_store, None)]:
        method = "sat4" if call in (_core.collide_records, _core.collide_store) else "local"
        pairs, buffer = pairs_with_room()
        with pytest.raises(ValueError, match="^out and pairs share memory"):
            call(store, pairs, buffer[:len(pairs)], method, "auto", 1)
        if rows is not None:
            with pytest.raises(ValueError, match=f"^out and {rows} share memory"):
                call(store, np.zeros((64, 2), np.uint32), store.view(np.uint8).reshape(-1)[:64], method, "auto", 1)
    for a, call, method in [(rects, _core.collide_stream, "sat4"), (poses, _core.collide_pose_stream, "local")]:
        b = a.copy()
        with pytest.raises(ValueError, match="^out and b share memory"):
            call(a, b, b.view(np.uint8).reshape(-1)[:len(a)], method, "auto", 1)
    # The corners of poses written over the poses.
    memory = np.zeros(64 * 8, dtype=np.float32)
    memory[:64 * 6] = apart_poses().reshape(-1)
    with pytest.raises(ValueError, match="^out and poses share memory"):
        _core.pose_corners(memory[:64 * 6].reshape(64, 6), memory.reshape(64, 4, 2), "auto")
