"""obbsat: which pairs of 2D rotated rectangles collide, decided in batches.

Rectangles are numpy arrays of corners, four float32 corners UL, UR, LR, LL in
cyclic order (either winding), shaped ``(N, 4, 2)`` or ``(N, 8)``. Pairs are
integer arrays shaped ``(M, 2)`` of 0-based indices. Each call decides the
whole batch in C++ with the SIMD backend this CPU runs best, with the GIL
released; every backend gives verdicts bitwise identical to the method's
scalar reference.

Zero copy: a C-contiguous float32 rectangle array and a C-contiguous uint32
pair array are read where they are. Anything else (float64 corners, int64
pairs, a strided view) is converted once per call, which costs one pass and a
temporary of N * 32 bytes (rectangles) or M * 8 bytes (pairs).

>>> import numpy as np, obbsat
>>> rects = np.array([[0, 1, 2, 1, 2, 0, 0, 0],
...                   [1, 2, 3, 2, 3, 0.5, 1, 0.5],
...                   [9, 10, 10, 10, 10, 9, 9, 9]], dtype=np.float32)
>>> obbsat.collide(rects, [[0, 1], [0, 2]])
array([ True, False])
"""

import numpy as _np

from . import _core, testing
from ._core import RectRecords, UnsupportedBackendError

__version__ = _core.__version__

__all__ = [
    "RectRecords",
    "UnsupportedBackendError",
    "backends",
    "collide",
    "collide_stream",
    "colliding_pairs",
    "methods",
    "records",
    "resolved_backend",
]

_MAX_INDEX = 2**32 - 1


def methods():
    """The collision tests this build offers on corner rectangles, in the library's order.

    >>> "sat4" in obbsat.methods()
    True
    """
    return list(_core.methods())


def backends(compiled=False):
    """The backends this CPU runs, best first (``"scalar"`` is always last).

    With ``compiled=True``: every backend compiled into this build, whether
    this CPU runs it or not.

    >>> obbsat.backends()[-1]
    'scalar'
    """
    return list(_core.compiled_backends() if compiled else _core.runnable_backends())


def resolved_backend(backend="auto"):
    """The backend a request runs on here: for ``"auto"``, the environment
    variable ``OBBSAT_BACKEND`` if set, else the best this CPU runs.
    Raises ``UnsupportedBackendError`` for one this CPU cannot run.

    >>> obbsat.resolved_backend("scalar")
    'scalar'
    """
    return _core.resolved_backend(backend)


def _corners(rects, what):
    """The rectangles as the library stores them: a C-contiguous float32 array
    whose rows are eight floats (the array itself when it already is one).

    This is the one place that maps an array's shape to a store; a further
    store (say, poses) is one more shape recognised here and one more entry
    point in _core.
    """
    if not isinstance(rects, _np.ndarray):
        rects = _np.asarray(rects)
    if rects.dtype.kind not in "fiu":
        raise TypeError(f"{what}: expected real numbers, got dtype {rects.dtype}")
    shape = rects.shape
    if not ((len(shape) == 2 and shape[1] == 8) or (len(shape) == 3 and shape[1:] == (4, 2))):
        raise ValueError(f"{what}: expected shape (N, 8) or (N, 4, 2) (corners UL, UR, LR, LL), got {shape}")
    return _np.ascontiguousarray(rects, dtype=_np.float32)


def records(rects):
    """A :class:`RectRecords` store: the rectangles copied once into the
    library's packed records (32 bytes each, 64-byte aligned), every
    coordinate checked finite once.

    :func:`collide` reads a float32 array in place but checks its coordinates
    on every call (one pass over the N rectangles); a store is checked when it
    is built, so calls over it read only the pairs. Use one when many pair
    lists meet the same rectangles. ``store.corners`` is a read-only (N, 8)
    view of its records. A store pickles (for Dask workers, say) as its corners.

    >>> store = obbsat.records(np.array([[0, 1, 2, 1, 2, 0, 0, 0]] * 2, dtype=np.float32))
    >>> len(store), obbsat.collide(store, [[0, 1]])
    (2, array([ True]))
    """
    if isinstance(rects, RectRecords):
        return rects
    return RectRecords(_corners(rects, "rects"))


def _pairs(pairs, rect_count):
    """The pairs as the library reads them: a C-contiguous uint32 (M, 2) array
    (the array itself when it already is one). Indices that do not fit are
    refused here, naming the first pair that holds one."""
    if not isinstance(pairs, _np.ndarray):
        pairs = _np.asarray(pairs)
        if pairs.size == 0 and pairs.ndim < 2:
            pairs = pairs.reshape(0, 2).astype(_np.uint32)
    if pairs.dtype.kind not in "iu":
        raise TypeError(f"pairs: expected an integer array, got dtype {pairs.dtype}")
    if pairs.ndim != 2 or pairs.shape[1] != 2:
        raise ValueError(f"pairs: expected shape (M, 2), got {pairs.shape}")
    if pairs.dtype == _np.uint32 and pairs.dtype.isnative and pairs.flags.c_contiguous:
        return pairs
    if pairs.size and (pairs.min() < 0 or pairs.max() > _MAX_INDEX):
        flat = pairs.ravel()
        first = int(_np.flatnonzero((flat < 0) | (flat > _MAX_INDEX))[0])
        raise IndexError(
            f"pair {first // 2}: index {int(flat[first])} is out of range ({rect_count} rectangles)")
    return _np.ascontiguousarray(pairs, dtype=_np.uint32)


def _verdicts(out, count):
    if out is None:
        return _np.empty(count, dtype=bool)
    if not isinstance(out, _np.ndarray):
        raise TypeError(f"out: expected a numpy array, got {type(out).__name__}")
    return out


def collide(rects, pairs, method="sat4", backend="auto", threads=1, out=None):
    """Whether each pair of rectangles collides.

    Parameters
    ----------
    rects : array_like, shape (N, 4, 2) or (N, 8), or RectRecords
        Corners UL, UR, LR, LL of each rectangle (x, y each). float32 and
        C-contiguous is read in place; anything else is converted once.
        Every coordinate must be finite (checked on every call: one read
        pass; a :func:`records` store was checked once, when built).
    pairs : array_like of int, shape (M, 2)
        Indices into ``rects``: row i asks whether ``rects[pairs[i, 0]]``
        and ``rects[pairs[i, 1]]`` collide. C-contiguous uint32 is read in
        place; any other integer dtype is range-checked and converted once.
    method : str
        One of :func:`methods` (``"sat4"``, ``"exact"``, ...).
    backend : str
        ``"auto"`` or one of :func:`backends`; verdicts never depend on it.
    threads : int
        Cores to split the batch over; 0 means all. The GIL is released.
    out : ndarray of bool or uint8, shape (M,), optional
        Where to write the verdicts (C-contiguous, writable).

    Returns
    -------
    ndarray of bool, shape (M,)
        ``out`` when given (as passed), else a new array.

    Raises
    ------
    IndexError
        An index is negative or not below N (the message names the pair).
    ValueError
        A coordinate is NaN or infinite (the message names the rectangle and
        the coordinate), a shape is wrong, a method or backend unknown, or the
        backend cannot run here (``UnsupportedBackendError``).
    TypeError
        A dtype is not numeric (rects), not integer (pairs), or ``out`` is not
        a writable C-contiguous bool/uint8 array.

    Nothing is written to ``out`` when an error is raised.

    >>> rects = np.array([[[0, 1], [2, 1], [2, 0], [0, 0]],
    ...                   [[1, 2], [3, 2], [3, .5], [1, .5]]], dtype=np.float32)
    >>> obbsat.collide(rects, np.array([[0, 1]], dtype=np.uint32), method="exact")
    array([ True])
    """
    if isinstance(rects, RectRecords):
        decide = _core.collide_store
    else:
        rects = _corners(rects, "rects")
        decide = _core.collide_records
    pairs = _pairs(pairs, len(rects))
    verdicts = _verdicts(out, len(pairs))
    decide(rects, pairs, verdicts, method, backend, int(threads))
    return verdicts


def colliding_pairs(rects, pairs, method="sat4", backend="auto", threads=1):
    """The rows of ``pairs`` whose rectangles collide, in their input order,
    shape (K, 2), with the dtype of ``pairs``. Arguments as :func:`collide`.

    >>> rects = np.array([[0, 1, 2, 1, 2, 0, 0, 0],
    ...                   [1, 2, 3, 2, 3, 0.5, 1, 0.5],
    ...                   [9, 10, 10, 10, 10, 9, 9, 9]], dtype=np.float32)
    >>> obbsat.colliding_pairs(rects, np.array([[0, 1], [0, 2], [1, 0]]))
    array([[0, 1],
           [1, 0]])
    """
    if not isinstance(pairs, _np.ndarray):
        pairs = _np.asarray(pairs)
    if pairs.size == 0 and pairs.ndim < 2:
        pairs = pairs.reshape(0, 2).astype(_np.int64)
    hits = collide(rects, pairs, method=method, backend=backend, threads=threads)
    return pairs[hits]


def collide_stream(a, b, method="sat4", backend="auto", threads=1, out=None):
    """Whether ``a[i]`` and ``b[i]`` collide, for every i: two batches of
    rectangles of equal length, each shaped (N, 4, 2) or (N, 8).

    Both batches are copied into the library's structure-of-arrays store
    (eight coordinate arrays), which is what the streaming kernels read; the
    copy checks that every coordinate is finite. Other arguments, the result
    and the errors are as in :func:`collide`; a length mismatch is a
    ``ValueError``.

    >>> a = np.array([[0, 1, 2, 1, 2, 0, 0, 0]] * 2, dtype=np.float32)
    >>> b = np.array([[1, 2, 3, 2, 3, .5, 1, .5], [5, 6, 6, 6, 6, 5, 5, 5]], dtype=np.float32)
    >>> obbsat.collide_stream(a, b)
    array([ True, False])
    """
    a = _corners(a, "a")
    b = _corners(b, "b")
    verdicts = _verdicts(out, len(a))
    _core.collide_stream(a, b, verdicts, method, backend, int(threads))
    return verdicts
