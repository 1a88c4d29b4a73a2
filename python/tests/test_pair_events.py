"""PairFinder's begin/end events: began() and ended() equal the set
differences of consecutive fresh find_pairs answers (rows matched by
position), over frames of small motion, large jumps and changes of the row
count, within one set and across two; the first call begins every pair; a
change of the kind of query starts over; events are off by default (began()
and ended() raise RuntimeError); a call that raises changes no events."""

import numpy as np
import pytest

import obbsat

from conftest import random_poses


def keys(pairs):
    """Each pair (i, j) as one number that sorts as (i, j) does."""
    pairs = np.asarray(pairs, dtype=np.uint32).reshape(-1, 2)
    return pairs[:, 0].astype(np.uint64) << np.uint64(32) | pairs[:, 1]


def assert_same(got, want_keys):
    """got is a (K, 2) uint32 array sorted by (i, j), each pair once: the pairs of want_keys (sorted keys)."""
    assert got.dtype == np.uint32 and got.ndim == 2 and got.shape[1] == 2 and got.flags.c_contiguous
    k = keys(got)
    assert np.all(k[1:] > k[:-1]), "not sorted by (i, j), or a pair twice"
    np.testing.assert_array_equal(k, want_keys)


def assert_events(finder, before, now):
    assert_same(finder.began(), np.setdiff1d(keys(now), keys(before)))
    assert_same(finder.ended(), np.setdiff1d(keys(before), keys(now)))


def moved(rng, poses, frame, spread):
    """The next frame: a little motion; every fourth frame a twentieth of the
    rows jump anywhere; every fifth frame rows dropped or added at the end."""
    poses = poses.copy()
    poses[:, :2] += rng.uniform(-0.02, 0.02, size=(len(poses), 2)).astype(np.float32)
    if frame % 4 == 3:
        jump = rng.integers(0, len(poses), size=len(poses) // 20)
        poses[jump, :2] = rng.uniform(-spread / 2, spread / 2, size=(len(jump), 2))
    if frame % 5 == 4:
        if frame % 10 == 4:
            poses = poses[: len(poses) - 1 - rng.integers(0, len(poses) // 10)]
        else:
            poses = np.concatenate([poses, random_poses(rng, 1 + rng.integers(0, len(poses) // 10), spread)])
    return poses


@pytest.mark.parametrize("method,threads", [("exact", 1), ("exact", 2), ("local", 2)])
def test_events_are_the_differences_of_fresh_queries(method, threads):
    rng = np.random.default_rng(5 + threads)
    spread = 300.0
    poses = random_poses(rng, 3000, spread)
    finder = obbsat.PairFinder(method=method, threads=threads, events=True)
    assert finder.events and repr(finder).endswith("events=True)")
    before = np.zeros((0, 2), dtype=np.uint32)
    full = kept = 0
    for frame in range(24):
        now = obbsat.find_pairs(poses, method=method)
        got = finder.find(poses)
        np.testing.assert_array_equal(got, now)
        assert_events(finder, before, now)
        kept += finder.stats.reused_candidates
        full += not finder.stats.reused_candidates
        before = now
        poses = moved(rng, poses, frame, spread)
    assert kept >= 4 and full >= 4, (kept, full)


def test_events_across_two_sets_and_changes_of_kind():
    rng = np.random.default_rng(9)
    spread = 200.0
    a, b = random_poses(rng, 1000, spread), random_poses(rng, 1500, spread)
    finder = obbsat.PairFinder(events=True)
    before = np.zeros((0, 2), dtype=np.uint32)
    for frame in range(15):
        now = obbsat.find_pairs(a, b)
        np.testing.assert_array_equal(finder.find(a, b), now)
        assert_events(finder, before, now)
        before = now
        a, b = moved(rng, a, frame, spread), moved(rng, b, frame + 2, spread)
    # Within one set after across two: every pair of the last ends, every one of this begins.
    within = obbsat.find_pairs(a)
    finder.find(a)
    assert_same(finder.began(), keys(within))
    assert_same(finder.ended(), keys(before))
    # Corners and a store: the kind of rectangle does not matter, only the kind of query.
    finder.find(obbsat.records(obbsat.corners_of_poses(a)))
    assert len(finder.began()) == 0 and len(finder.ended()) == 0


def test_first_call_off_by_default_and_a_failed_call():
    poses = np.array([[0, 0, 1, 1, 1, 0], [2, 0, 1, 1, 1, 0], [5, 0, 1, 1, 1, 0]], dtype=np.float32)
    plain = obbsat.PairFinder()
    assert not plain.events and repr(plain) == "PairFinder(method='exact', backend='auto', threads=1)"
    plain.find(poses)
    for call in (plain.began, plain.ended):
        with pytest.raises(RuntimeError, match="events were not requested; construct PairFinder"):
            call()
    finder = obbsat.PairFinder(events=True)
    assert finder.began().shape == (0, 2) and finder.ended().shape == (0, 2)  # no call yet
    finder.find(poses)
    np.testing.assert_array_equal(finder.began(), [[0, 1]])
    assert finder.ended().shape == (0, 2)
    # The arrays are copies: the next call leaves them as they were.
    began = finder.began()
    poses[2, 0] = 3.5
    finder.find(poses)
    np.testing.assert_array_equal(began, [[0, 1]])
    np.testing.assert_array_equal(finder.began(), [[1, 2]])
    # A call that raises changes nothing: the next is compared with the last that answered.
    bad = poses.copy()
    bad[1, 1] = np.nan
    with pytest.raises(ValueError):
        finder.find(bad)
    np.testing.assert_array_equal(finder.began(), [[1, 2]])
    poses[0, 0] = -5
    finder.find(poses)
    assert finder.began().shape == (0, 2)
    np.testing.assert_array_equal(finder.ended(), [[0, 1]])
    # Fewer rows: the pairs of the rows gone end.
    finder.find(poses[:2])
    np.testing.assert_array_equal(finder.ended(), [[1, 2]])
    with pytest.raises(TypeError):
        obbsat.PairFinder("exact", "auto", 1, True)  # events is keyword-only
