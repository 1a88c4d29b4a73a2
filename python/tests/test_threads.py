"""The GIL is released while the library works: other Python threads run
meanwhile, and two threads calling at once use two cores."""

import threading
import time

import numpy as np
import pytest

import obbsat
from conftest import calls_in_two_threads


@pytest.fixture(scope="module")
def scene():
    return obbsat.testing.make_scene(rects=100_000, pairs=400_000, seed=2)


def test_python_runs_while_a_call_works(scene):
    rects, pairs = scene
    worker = threading.Thread(target=lambda: obbsat.collide(rects, pairs, method="exact", backend="scalar"))
    started = time.perf_counter()
    worker.start()
    steps = 0
    while worker.is_alive():
        steps += 1
    took = time.perf_counter() - started
    # With the GIL held, this loop would stall for the whole call; released,
    # it spins at millions of steps per second.
    assert took > 0.02, "the call was too short to tell"
    assert steps > 1000 * took * 100


def test_two_threads_decide_at_the_same_time(scene):
    # Each thread records when its calls ran. Were the GIL held during a call,
    # the other thread could not even enter its own call meanwhile, and the
    # intervals would be disjoint; released, they overlap for nearly the whole
    # run. (How far that scales with free cores: python/bench/bench_collide.py.)
    rects, pairs = scene
    outs = [np.empty(len(pairs), dtype=bool) for _ in range(2)]
    _, overlap, busy = calls_in_two_threads(
        lambda i: obbsat.collide(rects, pairs, method="sat4_double", backend="scalar", out=outs[i]))
    assert overlap > 0.5 * busy, f"calls overlapped {overlap:.3f} s of {busy:.3f} s"
    assert outs[0].tobytes() == outs[1].tobytes()
