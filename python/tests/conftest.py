"""Shared helpers of the obbsat Python tests."""

import os
import pathlib
import threading
import time

import numpy as np
import pytest

import obbsat


def pytest_report_header(config):
    return f"obbsat {obbsat.__version__} from {pathlib.Path(obbsat.__file__).parent}; backends {obbsat.backends()}"


@pytest.fixture(scope="session", autouse=True)
def installed_package():
    """Under CTest the package must come from the install prefix, not from a source or build folder."""
    prefix = os.environ.get("OBBSAT_EXPECT_PACKAGE_UNDER")
    if prefix:
        here = pathlib.Path(obbsat.__file__).resolve()
        assert pathlib.Path(prefix).resolve() in here.parents, f"obbsat imported from {here}, not from {prefix}"


def random_rects(rng, n, spread=20.0):
    """n random rotated rectangles as float32 (n, 8) corners, centers in a square of side `spread`."""
    centers = rng.uniform(-spread / 2, spread / 2, size=(n, 1, 2))
    half = rng.uniform(0.1, 3.0, size=(n, 1, 2))
    angle = rng.uniform(0, 2 * np.pi, size=(n, 1))
    unit = np.array([[-1, 1], [1, 1], [1, -1], [-1, -1]], dtype=np.float64)
    local = unit[None, :, :] * half
    c, s = np.cos(angle), np.sin(angle)
    x = c * local[..., 0] - s * local[..., 1]
    y = s * local[..., 0] + c * local[..., 1]
    corners = np.stack([x, y], axis=-1) + centers
    return corners.reshape(n, 8).astype(np.float32)


def random_poses(rng, n, spread=20.0):
    """n random poses as float32 (n, 6) rows cx, cy, hx, hy, c, s: half extents
    in [0, 3] (a few exactly 0: segments and points), rotation vectors of
    random direction, half of them unit length and half scaled by 0.25 to 4."""
    centers = rng.uniform(-spread / 2, spread / 2, size=(n, 2))
    half = rng.uniform(0.0, 3.0, size=(n, 2))
    half[rng.random(size=(n, 2)) < 0.02] = 0.0
    angle = rng.uniform(0, 2 * np.pi, size=n)
    length = np.where(rng.random(size=n) < 0.5, 1.0, rng.uniform(0.25, 4.0, size=n))
    rotation = np.stack([np.cos(angle), np.sin(angle)], axis=-1) * length[:, None]
    return np.concatenate([centers, half, rotation], axis=1).astype(np.float32)


def utm_poses(n, seed, span=150.0):
    """(n, 6) float64 poses near a UTM-like origin (3e5 .. 6e6 m), footprints
    5 .. 50 m, half of them in pairs that touch exactly (axis-aligned, or
    turned by the rotation vector (3, 4)) or lie a millimetre apart or over;
    every coordinate that must touch exactly is a multiple of 1/8."""
    rng = np.random.default_rng(seed)
    x0 = 300000.0 + np.floor(rng.uniform(0, 2.7e6)) + 0.125
    y0 = 3000000.0 + np.floor(rng.uniform(0, 2.9e6)) + 0.375
    eighths = lambda lo, hi: np.round(rng.uniform(lo, hi) * 8) / 8
    rows = []
    while len(rows) < n:
        cx, cy = x0 + eighths(0, span), y0 + eighths(0, span)
        hx, hy = eighths(2.5, 25), eighths(2.5, 25)
        shape = int(rng.integers(0, 4))
        if shape == 0:
            angle = rng.uniform(0, 2 * np.pi)
            rows.append([cx, cy, hx, hy, np.cos(angle), np.sin(angle)])
            continue
        turned = shape == 1
        c, s, scale = (0.6, 0.8, 5.0) if turned else (1.0, 0.0, 1.0)
        ax, bx, ay = hx / scale, eighths(2.5, 25) / scale, hy / scale
        gap = (0.001 if rng.uniform() < 0.5 else -0.001) if shape == 3 else 0.0
        along = (ax + bx) * scale + gap
        rot = (3.0, 4.0) if turned else (1.0, 0.0)
        rows.append([cx, cy, ax, ay, *rot])
        rows.append([cx + along * c, cy + along * s, bx, ay, *rot])
    return np.array(rows[:n], dtype=np.float64)


def random_pairs(rng, n, m):
    return rng.integers(0, n, size=(m, 2)).astype(np.uint32)


def read_case(folder):
    """rects (float32 (N, 8)), pairs (uint32 (M, 2)) and truth (bool (M,)) of a labelled case folder."""
    rects = []
    for line in (folder / "rects.csv").read_text().splitlines():
        if line and not line.startswith("#"):
            rects.append([float.fromhex(v) for v in line.split(",")])
    pairs = np.loadtxt(folder / "pairs.csv", delimiter=",", dtype=np.uint32, comments="#", ndmin=2)
    truth = np.array([c == "1" for c in (folder / "truth.txt").read_text().split()])
    return np.array(rects, dtype=np.float32), pairs, truth


def shared_case_folders():
    root = os.environ.get("OBBSAT_SHARED_CASES")
    if not root or not pathlib.Path(root).is_dir():
        return []
    return sorted(p for p in pathlib.Path(root).iterdir() if (p / "pairs.csv").exists())


def calls_in_two_threads(call, repeats=3):
    """Runs call(i) `repeats` times in each of two threads i = 0, 1, started
    together. Returns the last result of each thread, how long their calls
    overlapped in time and the shorter of the two threads' total time in
    calls, in seconds. Were the GIL held during a call, the other thread
    could not enter its own meanwhile and the overlap would be about 0."""
    spans = [[], []]
    results = [None, None]
    barrier = threading.Barrier(2)

    def work(i):
        barrier.wait()
        for _ in range(repeats):
            begin = time.perf_counter()
            results[i] = call(i)
            spans[i].append((begin, time.perf_counter()))

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    overlap = sum(max(0.0, min(e0, e1) - max(b0, b1)) for b0, e0 in spans[0] for b1, e1 in spans[1])
    busy = min(sum(e - b for b, e in s) for s in spans)
    return results, overlap, busy
