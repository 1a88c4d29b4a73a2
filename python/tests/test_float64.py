"""float64 arrays are decided in float64, never rounded to float32 unless
asked (``precision="float32"``): checked against exact rational arithmetic
(fractions.Fraction) on UTM-like scenes whose float32 rounding flips
verdicts. float32 arrays keep their float32 answers."""

import itertools
from fractions import Fraction

import numpy as np
import pytest

import obbsat
from conftest import utm_poses


def exact_pose_corners(row):
    cx, cy, hx, hy, c, s = (Fraction(float(v)) for v in row)
    u, v = (hx * c, hx * s), (-(hy * s), hy * c)
    return [(cx + a * u[0] + b * v[0], cy + a * u[1] + b * v[1]) for a, b in ((-1, 1), (1, 1), (1, -1), (-1, -1))]


def exact_quad(row):
    return [(Fraction(float(row[2 * k])), Fraction(float(row[2 * k + 1]))) for k in range(4)]


def separated(p, q):
    """True iff some edge normal of the convex quads p or q separates them strictly (exact SAT)."""
    for poly in (p, q):
        for k in range(4):
            (x0, y0), (x1, y1) = poly[k], poly[(k + 1) % 4]
            nx, ny = y1 - y0, x0 - x1
            if nx == 0 and ny == 0:
                continue
            a = [nx * x + ny * y for x, y in p]
            b = [nx * x + ny * y for x, y in q]
            if max(a) < min(b) or max(b) < min(a):
                return True
    return False


def exact_pairs(quads, other=None):
    """The colliding pairs by exact rational SAT, over all pairs (bounds first, exactly)."""
    box = [(min(x for x, _ in q), min(y for _, y in q), max(x for x, _ in q), max(y for _, y in q)) for q in quads]
    obox = box if other is None else [(min(x for x, _ in q), min(y for _, y in q), max(x for x, _ in q),
                                       max(y for _, y in q)) for q in other]
    targets = quads if other is None else other
    out = []
    for i in range(len(quads)):
        for j in range(i + 1 if other is None else 0, len(targets)):
            a, b = box[i], obox[j]
            if a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3] and not separated(quads[i], targets[j]):
                out.append((i, j))
    return np.array(out, dtype=np.uint32).reshape(-1, 2)


def corners64(poses):
    return obbsat.corners_of_poses(poses).reshape(-1, 8)


@pytest.fixture(scope="module")
def scene():
    poses = utm_poses(300, 4)
    rects = corners64(poses)
    return poses, rects, exact_pairs([exact_pose_corners(r) for r in poses]), exact_pairs([exact_quad(r) for r in rects])


def test_float64_poses_and_corners_give_the_exact_answer(scene):
    poses, rects, truth_poses, truth_rects = scene
    assert len(truth_poses) > 50
    for threads in (1, 2):
        assert obbsat.find_pairs(poses, threads=threads).tolist() == truth_poses.tolist()
        assert obbsat.find_pairs(rects, threads=threads).tolist() == truth_rects.tolist()
        assert obbsat.find_pairs(rects.reshape(-1, 4, 2), threads=threads).tolist() == truth_rects.tolist()
    # Pair lists and streams over every pair with overlapping bounds and more.
    pairs = np.array(list(itertools.combinations(range(60), 2)), dtype=np.uint32)
    in_truth = {tuple(p) for p in truth_poses.tolist()}
    expected = np.array([tuple(p) in in_truth for p in pairs.tolist()])
    assert obbsat.collide(poses, pairs, method="exact").tolist() == expected.tolist()
    assert obbsat.collide_stream(poses[pairs[:, 0]], poses[pairs[:, 1]], method="exact").tolist() == expected.tolist()
    in_rects = {tuple(p) for p in truth_rects.tolist()}
    expected_rects = np.array([tuple(p) in in_rects for p in pairs.tolist()])
    # Corners default to exact on float64 (sat4 has no double form).
    assert obbsat.collide(rects, pairs).tolist() == expected_rects.tolist()
    assert obbsat.collide_stream(rects[pairs[:, 0]], rects[pairs[:, 1]]).tolist() == expected_rects.tolist()
    assert obbsat.colliding_pairs(rects, pairs).tolist() == pairs[expected_rects].tolist()


def test_float64_corners_give_the_exact_answer_on_every_backend(scene):
    poses, rects, truth_poses, truth_rects = scene
    pairs = np.array(list(itertools.combinations(range(60), 2)), dtype=np.uint32)
    in_rects = {tuple(p) for p in truth_rects.tolist()}
    expected = [tuple(p) in in_rects for p in pairs.tolist()]
    for backend in obbsat.backends():
        assert obbsat.collide(rects, pairs, method="exact", backend=backend).tolist() == expected, backend
        conservative = obbsat.collide(rects, pairs, method="conservative", backend=backend, threads=2)
        assert conservative.tolist() == obbsat.collide(rects, pairs, method="conservative", backend="scalar").tolist()
        assert obbsat.find_pairs(rects, backend=backend).tolist() == truth_rects.tolist(), backend


def test_float32_rounding_flips_verdicts_and_is_only_taken_on_request(scene):
    poses, rects, truth_poses, truth_rects = scene
    rounded = obbsat.find_pairs(poses, precision="float32")
    assert rounded.tolist() == obbsat.find_pairs(poses.astype(np.float32)).tolist()
    flipped = {tuple(p) for p in rounded.tolist()} ^ {tuple(p) for p in truth_poses.tolist()}
    assert len(flipped) > 5, "float32 rounding should change verdicts of this scene"
    assert obbsat.find_pairs(poses).tolist() == truth_poses.tolist()
    assert obbsat.find_pairs(poses, precision="float64").tolist() == truth_poses.tolist()


def test_cross_queries_and_mixed_dtypes(scene):
    poses, rects, _, _ = scene
    a, b = rects[:120], rects[120:]
    truth = exact_pairs([exact_quad(r) for r in a], [exact_quad(r) for r in b])
    assert obbsat.find_pairs(a, b).tolist() == truth.tolist()
    # One side float64 makes both float64 (widening float32 is exact).
    small = poses[:, :].copy()
    assert obbsat.find_pairs(small[:100], small[100:].astype(np.float32)).tolist() == \
        obbsat.find_pairs(small[:100], small[100:].astype(np.float32).astype(np.float64)).tolist()


def test_pair_finder_on_float64_frames_answers_as_find_pairs():
    poses = utm_poses(400, 8, span=250)
    rng = np.random.default_rng(2)
    for method in ("exact", "conservative", "local"):
        finder = obbsat.PairFinder(method=method, events=True)
        for _ in range(6):
            poses[:, :2] += rng.uniform(-0.005, 0.005, size=(len(poses), 2))
            assert finder.find(poses).tolist() == obbsat.find_pairs(poses, method=method).tolist()
    assert obbsat.PairFinder(precision="float32").find(poses).tolist() == \
        obbsat.find_pairs(poses.astype(np.float32)).tolist()


def test_bounds_of_float64_contain_the_exact_corners(scene):
    poses, _, _, _ = scene
    b = obbsat.bounds(poses)
    assert b.dtype == np.float32
    for row, (lo_x, lo_y, hi_x, hi_y) in zip(poses[:50], b[:50]):
        for x, y in exact_pose_corners(row):
            assert Fraction(float(lo_x)) <= x <= Fraction(float(hi_x))
            assert Fraction(float(lo_y)) <= y <= Fraction(float(hi_y))


def test_float32_and_other_dtypes_keep_their_float32_answers():
    poses = obbsat.testing.make_pose_scene(boxes=2000, seed=3)
    expected = obbsat.find_pairs(poses, method="local")
    for same in (poses.astype(np.float16).astype(np.float32), poses):
        assert obbsat.find_pairs(same, method="local").dtype == np.uint32
    assert obbsat.find_pairs(poses, method="local", precision="float32").tolist() == expected.tolist()
    rects = poses[:, :6]
    # float16 and integer data go to float32 as before (sat4 runs there, not on float64).
    quads = obbsat.corners_of_poses(poses).reshape(-1, 8)
    assert obbsat.corners_of_poses(poses).dtype == np.float32
    assert obbsat.find_pairs(quads.astype(np.float16), method="sat4").dtype == np.uint32
    assert obbsat.collide(np.round(quads).astype(np.int64), [[0, 1]]).dtype == bool
    assert obbsat.corners_of_poses(poses.astype(np.float64)).dtype == np.float64
    assert rects.dtype == np.float32


def test_errors_name_method_dtype_and_row():
    poses = utm_poses(10, 1)
    with pytest.raises(ValueError, match=r"method sat4 does not run on float64 corners"):
        obbsat.find_pairs(corners64(poses), method="sat4")
    with pytest.raises(ValueError, match=r"method sat4 does not run on float64 poses"):
        obbsat.collide(poses, [[0, 1]], method="sat4")
    with pytest.raises(ValueError, match=r"method sat4 does not run on float64 corners"):
        obbsat.collide_stream(corners64(poses), corners64(poses), method="sat4")
    with pytest.raises(ValueError, match=r"method local does not run on float64 corners"):
        obbsat.PairFinder(method="local").find(corners64(poses))
    with pytest.raises(ValueError, match=r"precision: expected None, 'float32' or 'float64'"):
        obbsat.find_pairs(poses, precision="float16")
    with pytest.raises(ValueError, match=r"RectRecords holds float32"):
        obbsat.find_pairs(obbsat.records(corners64(poses).astype(np.float32)), precision="float64")
    bad = poses.copy()
    bad[3, 3] = -1.0
    with pytest.raises(ValueError, match=r"^pose 3: half extent hy"):
        obbsat.find_pairs(bad)
    with pytest.raises(ValueError, match=r"^pose 3: half extent hy"):
        obbsat.collide(bad, [[0, 1]], method="exact")
    with pytest.raises(ValueError, match=r"^b: pose 3: half extent hy"):
        obbsat.collide_stream(poses, bad, method="exact")
    with pytest.raises(ValueError, match=r"^against: pose 3: half extent hy"):
        obbsat.find_pairs(poses, bad)
    bad = poses.copy()
    bad[2, 0] = np.nan
    with pytest.raises(ValueError, match=r"^pose 2: "):
        obbsat.PairFinder().find(bad)
    with pytest.raises(ValueError, match=r"^pose 2: "):
        obbsat.corners_of_poses(bad)


def test_dask_keeps_float64(scene):
    da = pytest.importorskip("dask.array")
    import obbsat.dask

    poses, rects, truth_poses, truth_rects = scene
    got = obbsat.dask.find_pairs(da.from_array(poses, chunks=(100, 6)), 40.0).compute(scheduler="synchronous")
    assert got.tolist() == truth_poses.tolist()
    got = obbsat.dask.find_pairs(rects, 40.0).compute(scheduler="synchronous")
    assert got.tolist() == truth_rects.tolist()
    pairs = np.array(list(itertools.combinations(range(60), 2)), dtype=np.uint32)
    lazy = obbsat.dask.collide(rects, da.from_array(pairs, chunks=(500, 2)))
    assert lazy.compute(scheduler="synchronous").tolist() == obbsat.collide(rects, pairs).tolist()
