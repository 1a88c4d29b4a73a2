"""Pair filters from Python: categories=, masks=, groups= (and against_...
for the cross query) on obbsat.find_pairs and PairFinder.find.

The expected answer is the same query without filters, filtered afterwards
with numpy by the rule (categories[i] & masks[j]) != 0, (categories[j] &
masks[i]) != 0, and not groups[i] == groups[j] != 0. Arrays of any integer
dtype are taken without loss; wrong lengths, negative bits, groups out of
int32 and non-integer dtypes are refused by name; the GIL is released."""

import threading
import time

import numpy as np
import pytest

import obbsat
import obbsat.testing


def random_filters(rng, n):
    """Four categories, masks that leave one out for a third of the boxes,
    half the boxes in bodies of four consecutive rows."""
    categories = (np.uint64(1) << rng.integers(0, 4, size=n).astype(np.uint64)).astype(np.uint64)
    masks = np.full(n, np.iinfo(np.uint64).max, dtype=np.uint64)
    narrow = rng.random(n) < 1 / 3
    masks[narrow] = np.uint64(0xF) & ~(np.uint64(1) << rng.integers(0, 4, size=int(narrow.sum())).astype(np.uint64))
    bodies = np.arange(n) // 4 + 1
    groups = np.where(rng.random(n // 4 + 1)[np.arange(n) // 4] < 0.5, bodies, 0).astype(np.int32)
    return categories, masks, groups


def allowed(pairs, a, b):
    """Which of `pairs` the filters a = (categories, masks, groups) of the first
    index and b of the second let through; None for a default array."""
    i, j = pairs[:, 0], pairs[:, 1]
    ones = np.iinfo(np.uint64).max

    def pick(values, index, default):
        return np.full(len(index), default, dtype=np.uint64 if default else np.int64) if values is None else values[index]

    ci, mi, gi = pick(a[0], i, ones), pick(a[1], i, ones), pick(a[2], i, 0)
    cj, mj, gj = pick(b[0], j, ones), pick(b[1], j, ones), pick(b[2], j, 0)
    bits = ((ci & mj) != 0) & ((cj & mi) != 0)
    return bits & ~((gi == gj) & (gi != 0))


@pytest.fixture(scope="module")
def scene():
    return obbsat.testing.make_pose_scene(boxes=40_000, seed=7)


@pytest.mark.parametrize("method", ["exact", "local"])
@pytest.mark.parametrize("threads", [1, 2])
def test_one_set_equals_the_unfiltered_answer_filtered(scene, method, threads):
    rng = np.random.default_rng(1)
    categories, masks, groups = random_filters(rng, len(scene))
    everything = obbsat.find_pairs(scene, method=method, threads=threads)
    for given in [(categories, masks, groups), (categories, None, None), (None, masks, None), (None, None, groups)]:
        want = everything[allowed(everything, given, given)]
        got = obbsat.find_pairs(scene, method=method, threads=threads, categories=given[0], masks=given[1],
                                groups=given[2])
        assert got.dtype == np.uint32 and got.tobytes() == want.tobytes()
    assert len(want) < len(everything)


def test_across_two_sets_each_side_has_its_own(scene):
    rng = np.random.default_rng(2)
    a, b = scene[:25_000], scene[25_000:]
    fa, fb = random_filters(rng, len(a)), random_filters(rng, len(b))
    everything = obbsat.find_pairs(a, b)
    want = everything[allowed(everything, fa, fb)]
    got = obbsat.find_pairs(a, b, categories=fa[0], masks=fa[1], groups=fa[2], against_categories=fb[0],
                            against_masks=fb[1], against_groups=fb[2])
    assert got.tobytes() == want.tobytes()
    only_b = obbsat.find_pairs(a, b, against_groups=fb[2])
    assert only_b.tobytes() == everything[allowed(everything, (None, None, None), (None, None, fb[2]))].tobytes()
    finder = obbsat.PairFinder()
    assert finder.find(a, b, groups=fa[2], against_groups=fb[2]).tobytes() == \
        everything[allowed(everything, (None, None, fa[2]), (None, None, fb[2]))].tobytes()


def test_any_integer_dtype_and_lists_give_the_same_pairs(scene):
    rng = np.random.default_rng(3)
    boxes = scene[:3000]
    categories, masks, groups = random_filters(rng, len(boxes))
    want = obbsat.find_pairs(boxes, categories=categories, masks=masks, groups=groups)
    small = categories.astype(np.uint8), (masks & np.uint64(0xF)).astype(np.int16), groups.astype(np.int64)
    assert obbsat.find_pairs(boxes, categories=small[0], masks=small[1], groups=small[2]).tobytes() == want.tobytes()
    # Lists of Python ints (numpy reads 2**64 - 1 among small ones as a float: masks of four bits here).
    as_lists = [int(c) for c in categories], [int(m) for m in masks & np.uint64(0xF)], [int(g) for g in groups]
    assert obbsat.find_pairs(boxes, categories=as_lists[0], masks=as_lists[1],
                             groups=as_lists[2]).tobytes() == want.tobytes()
    # Strided arrays are taken too (copied into contiguous ones).
    wide = np.repeat(groups, 2)[::2]
    assert obbsat.find_pairs(boxes, categories=categories, masks=masks, groups=wide).tobytes() == want.tobytes()
    # The top bit of a category is kept: uint64 values above 2**63 pass whole.
    top = np.full(len(boxes), np.uint64(1) << np.uint64(63), dtype=np.uint64)
    assert len(obbsat.find_pairs(boxes, categories=top, masks=top)) == len(obbsat.find_pairs(boxes))
    assert len(obbsat.find_pairs(boxes, categories=top, masks=~top)) == 0


def test_pair_finder_follows_changes_of_the_filters(scene):
    rng = np.random.default_rng(4)
    poses = scene.copy()
    categories, masks, groups = random_filters(rng, len(poses))
    finder = obbsat.PairFinder(threads=2)
    from_kept = 0
    for frame in range(16):
        poses[:, :2] += rng.uniform(-0.002, 0.002, size=(len(poses), 2)).astype(np.float32)
        if frame in (5, 9):
            groups[::3] = 0                  # bodies broken up, in place
        if frame == 12:
            categories[::7] = 2
        use_masks = masks if frame < 10 else None
        got = finder.find(poses, categories=categories, masks=use_masks, groups=groups)
        everything = obbsat.find_pairs(poses)
        want = everything[allowed(everything, (categories, use_masks, groups), (categories, use_masks, groups))]
        assert got.tobytes() == want.tobytes(), f"frame {frame}"
        from_kept += finder.stats.reused_candidates
    assert from_kept >= 6


def test_fewer_candidates_reach_the_method(scene):
    # Bodies of four rows placed together: most of their overlapping pairs are within a body.
    boxes = scene.copy()
    boxes[:, :2] = boxes[(np.arange(len(boxes)) // 4) * 4, :2]
    plain, filtered = obbsat.PairFinder(), obbsat.PairFinder()
    plain.find(boxes)
    filtered.find(boxes, groups=np.arange(len(boxes)) // 4 + 1)
    # Each body's six pairs overlap and collide: dropped before the method, they are missing from the
    # candidates exactly as from the pairs.
    assert filtered.stats.candidates + len(boxes) < plain.stats.candidates
    assert plain.stats.candidates - filtered.stats.candidates == plain.stats.pairs - filtered.stats.pairs


def test_refusals_name_the_argument(scene):
    boxes = scene[:100]
    with pytest.raises(ValueError, match=r"categories: 99 values for the 100 rows of boxes"):
        obbsat.find_pairs(boxes, categories=np.ones(99, dtype=np.uint64))
    with pytest.raises(ValueError, match=r"against_groups: 3 values for the 5 rows of against"):
        obbsat.find_pairs(boxes, scene[:5], against_groups=np.zeros(3, dtype=np.int32))
    with pytest.raises(ValueError, match=r"masks\[4\] = -1 is negative"):
        obbsat.find_pairs(boxes, masks=np.where(np.arange(100) == 4, -1, 1))
    with pytest.raises(ValueError, match=r"groups\[0\] = 2147483648 does not fit in int32"):
        obbsat.find_pairs(boxes, groups=np.full(100, 2**31, dtype=np.int64))
    with pytest.raises(ValueError, match=r"groups\[0\] = 4294967295 does not fit in int32"):
        obbsat.find_pairs(boxes, groups=np.full(100, 2**32 - 1, dtype=np.uint32))
    with pytest.raises(TypeError, match=r"categories: expected integers, got dtype float64"):
        obbsat.find_pairs(boxes, categories=np.ones(100))
    with pytest.raises(TypeError, match=r"groups: expected integers, got dtype bool"):
        obbsat.find_pairs(boxes, groups=np.ones(100, dtype=bool))
    with pytest.raises(ValueError, match=r"categories: expected one value per row"):
        obbsat.find_pairs(boxes, categories=np.ones((100, 1), dtype=np.uint64))
    with pytest.raises(ValueError, match=r"against_masks given without against"):
        obbsat.find_pairs(boxes, against_masks=np.ones(100, dtype=np.uint64))
    finder = obbsat.PairFinder()
    with pytest.raises(ValueError, match=r"groups: 7 values for the 100 rows of boxes"):
        finder.find(boxes, groups=np.zeros(7, dtype=np.int32))
    # None is "not given": the answer without filters.
    assert obbsat.find_pairs(boxes, categories=None, masks=None, groups=None).tobytes() == \
        obbsat.find_pairs(boxes).tobytes()


def test_the_gil_is_released_with_filters():
    boxes = obbsat.testing.make_pose_scene(boxes=600_000, seed=3)
    groups = (np.arange(len(boxes)) // 4).astype(np.int32)
    worker = threading.Thread(target=lambda: obbsat.find_pairs(boxes, backend="scalar", groups=groups))
    started = time.perf_counter()
    worker.start()
    steps = 0
    while worker.is_alive():
        steps += 1
    took = time.perf_counter() - started
    assert took > 0.02, "the query was too short to tell"
    assert steps > 1000 * took * 100
