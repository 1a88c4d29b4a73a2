"""PairFinder.find(..., ids=...): rows followed by id while they are
appended, removed, swap-removed and reordered; every call equals a fresh
find_pairs; frames of small change are answered from the kept candidates;
events are uint64 id pairs equal to the differences of consecutive answers
read as ids; wrong ids (negative, float, wrong shape or length, duplicates,
on one side of two) are refused naming the argument, and a refused call
changes nothing."""

import numpy as np
import pytest

import obbsat

from conftest import random_poses


def id_pairs(pairs, ids, against_ids=None):
    """The rows of `pairs` read as ids, sorted, each as a tuple."""
    pairs = np.asarray(pairs, dtype=np.int64).reshape(-1, 2)
    a = ids[pairs[:, 0]]
    b = (ids if against_ids is None else against_ids)[pairs[:, 1]]
    if against_ids is None:
        a, b = np.minimum(a, b), np.maximum(a, b)
    return sorted(zip(a.tolist(), b.tolist()))


def as_tuples(events):
    assert events.dtype == np.uint64 and events.ndim == 2 and events.shape[1] == 2
    return [tuple(row) for row in events.tolist()]


class Bodies:
    """Poses with ids; new bodies get new ids."""

    def __init__(self, rng, count, spread):
        self.rng = rng
        self.spread = spread
        self.poses = random_poses(rng, count, spread)
        self.ids = np.arange(count, dtype=np.int64) * 2
        self.next_id = 2 * count

    def step(self, change):
        rng = self.rng
        self.poses = self.poses.copy()
        self.poses[:, :2] += rng.uniform(-0.02, 0.02, size=(len(self.poses), 2)).astype(np.float32)
        for _ in range(change):
            at = int(rng.integers(0, len(self.poses)))
            what = int(rng.integers(0, 4))
            if what == 0:  # erase, the others keep their order
                self.poses = np.delete(self.poses, at, axis=0)
                self.ids = np.delete(self.ids, at)
            elif what == 1:  # swap-remove
                self.poses[at] = self.poses[-1]
                self.ids[at] = self.ids[-1]
                self.poses = self.poses[:-1]
                self.ids = self.ids[:-1]
            elif what == 2:  # append
                self.poses = np.concatenate([self.poses, random_poses(rng, 1, self.spread)])
                self.ids = np.append(self.ids, self.next_id)
                self.next_id += 1
            else:  # swap two rows
                other = int(rng.integers(0, len(self.poses)))
                self.poses[[at, other]] = self.poses[[other, at]]
                self.ids[[at, other]] = self.ids[[other, at]]


@pytest.mark.parametrize("method,threads", [("exact", 1), ("local", 1), ("exact", 2)])
def test_every_frame_equals_a_fresh_query_and_small_changes_reuse(method, threads):
    rng = np.random.default_rng(3 + threads)
    bodies = Bodies(rng, 3000, 300.0)
    finder = obbsat.PairFinder(method=method, threads=threads, events=True)
    last = []
    reused = 0
    for frame in range(24):
        if frame > 1:
            bodies.step(20)
        got = finder.find(bodies.poses, ids=bodies.ids)
        np.testing.assert_array_equal(got, obbsat.find_pairs(bodies.poses, method=method, threads=threads))
        reused += finder.stats.reused_candidates
        now = id_pairs(got, bodies.ids)
        assert as_tuples(finder.began()) == sorted(set(now) - set(last))
        assert as_tuples(finder.ended()) == sorted(set(last) - set(now))
        last = now
    assert reused >= 15


def test_cross_queries_take_ids_for_both_sides():
    rng = np.random.default_rng(8)
    a = Bodies(rng, 1500, 200.0)
    b = Bodies(rng, 1500, 200.0)
    finder = obbsat.PairFinder(events=True)
    last = []
    reused = 0
    for frame in range(16):
        if frame > 1:
            a.step(10)
            b.step(10)
        got = finder.find(a.poses, b.poses, ids=a.ids, against_ids=b.ids)
        np.testing.assert_array_equal(got, obbsat.find_pairs(a.poses, b.poses))
        reused += finder.stats.reused_candidates
        now = id_pairs(got, a.ids, b.ids)
        assert as_tuples(finder.began()) == sorted(set(now) - set(last))
        assert as_tuples(finder.ended()) == sorted(set(last) - set(now))
        last = now
    assert reused >= 10
    with pytest.raises(ValueError, match="against_ids"):
        finder.find(a.poses, b.poses, ids=a.ids)
    with pytest.raises(ValueError, match="against_ids"):
        finder.find(a.poses, ids=a.ids, against_ids=a.ids)


def test_ids_of_any_integer_dtype_and_the_refusals():
    rng = np.random.default_rng(9)
    poses = random_poses(rng, 50, 40.0)
    finder = obbsat.PairFinder(events=True)
    want = obbsat.find_pairs(poses)
    for ids in (list(range(50)), np.arange(50, dtype=np.int32), np.arange(50, dtype=np.uint16),
                np.arange(50, dtype=np.uint64) + np.uint64(2**63)):
        np.testing.assert_array_equal(finder.find(poses, ids=ids), want)
    before_began, before_ended = finder.began(), finder.ended()
    bad = np.arange(50)
    bad[7] = -3
    with pytest.raises(ValueError, match=r"ids: row 7 holds the negative id -3"):
        finder.find(poses, ids=bad)
    with pytest.raises(TypeError, match="ids"):
        finder.find(poses, ids=np.arange(50, dtype=np.float64))
    with pytest.raises(ValueError, match="ids"):
        finder.find(poses, ids=np.arange(50).reshape(5, 10))
    with pytest.raises(ValueError, match="49 ids for 50 rows"):
        finder.find(poses, ids=np.arange(49))
    duplicate = np.arange(50)
    duplicate[40] = 12
    with pytest.raises(ValueError, match="rows 12 and 40 share the id 12"):
        finder.find(poses, ids=duplicate)
    np.testing.assert_array_equal(finder.began(), before_began)
    np.testing.assert_array_equal(finder.ended(), before_ended)
    # Without ids the events are row pairs again.
    finder.find(poses)
    assert finder.began().dtype == np.uint32
