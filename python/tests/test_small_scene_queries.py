"""A scene query refuses a bad box whatever the size of the query: one row,
or rows against an empty set, give the error a hundred rows give."""

import numpy as np
import pytest

import obbsat


def poses(n):
    """n unit squares as poses, five apart along x."""
    p = np.zeros((n, 6), dtype=np.float32)
    p[:, 0] = 5 * np.arange(n)
    p[:, 2:4] = 0.5
    p[:, 4] = 1
    return p


# Each scene query entry point, called as find_pairs is.
QUERIES = pytest.mark.parametrize("query", [
    lambda boxes, against=None: obbsat.find_pairs(boxes, against),
    lambda boxes, against=None: obbsat.PairFinder().find(boxes, against),
], ids=["find_pairs", "PairFinder"])


NAN_MESSAGE = "pose 0: cx is nan, not a finite number"


@QUERIES
def test_a_hundred_rows_with_a_nan_row_are_refused(query):
    # What the small queries below must match.
    p = poses(100)
    p[50] = np.nan
    with pytest.raises(ValueError, match="^pose 50: cx is nan, not a finite number$"):
        query(p)


@QUERIES
def test_one_nan_row_is_refused(query):
    with pytest.raises(ValueError, match=f"^{NAN_MESSAGE}$"):
        query(np.array([[np.nan] * 6]))
    with pytest.raises(ValueError, match=f"^{NAN_MESSAGE}$"):
        query(np.full((1, 6), np.nan, dtype=np.float32))


@QUERIES
def test_one_pose_with_a_negative_half_extent_is_refused(query):
    p = poses(100)
    p[50, 2] = -1
    with pytest.raises(ValueError, match="^pose 50: half extent hx is -1, negative$"):
        query(p)
    with pytest.raises(ValueError, match="^pose 0: half extent hx is -1, negative$"):
        query(p[50:51])


@QUERIES
def test_nan_rows_against_an_empty_set_are_refused(query):
    nan_rows = np.full((3, 6), np.nan, dtype=np.float32)
    # Against a hundred boxes, the query refuses them ...
    with pytest.raises(ValueError, match=f"^boxes: {NAN_MESSAGE}$"):
        query(nan_rows, poses(100))
    # ... and against none too.
    with pytest.raises(ValueError, match=f"^boxes: {NAN_MESSAGE}$"):
        query(nan_rows, np.zeros((0, 6), dtype=np.float32))
    with pytest.raises(ValueError, match=f"^against: {NAN_MESSAGE}$"):
        query(np.zeros((0, 6), dtype=np.float32), nan_rows)
