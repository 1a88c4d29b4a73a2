"""obbsat: which pairs of 2D rotated rectangles collide, decided in batches.

Rectangles are numpy arrays in one of two forms, told apart by shape:

- corners: four corners UL, UR, LR, LL in cyclic order (either winding),
  shaped ``(N, 4, 2)`` or ``(N, 8)``;
- poses: rows ``cx, cy, hx, hy, c, s`` shaped ``(N, 6)``, the closed set
  ``{(cx, cy) + a*(c, s) + b*(-s, c) : |a| <= hx, |b| <= hy}`` (the rotation
  vector ``(c, s)`` need not be a unit: its length scales the rectangle).

Pairs are integer arrays shaped ``(M, 2)`` of 0-based indices; with no pair
list at all, :func:`find_pairs` returns every colliding pair of a scene. Each call
decides the whole batch in C++ with the SIMD backend this CPU runs best, with
the GIL released; every backend gives verdicts bitwise identical to the
method's scalar reference. The methods differ per form (:func:`methods`).

float64 data is decided in float64 (never rounded to float32 unless a call
is given ``precision="float32"``); see docs/python.md.

Zero copy: a C-contiguous float32 corner or pose array and a C-contiguous
uint32 pair array are read where they are. Anything else (float16 corners,
int64 pairs, a strided view) is converted once per call, which costs one pass
and a temporary of N * 32 (corners) or N * 24 bytes (poses), or M * 8 bytes
(pairs). A :func:`records` store is checked once, when built, where an array
is checked on every call; float64 data gives a double store
(:class:`RectRecords64`, :class:`PoseRecords64`), decided as the array.

>>> import numpy as np, obbsat
>>> rects = np.array([[0, 1, 2, 1, 2, 0, 0, 0],
...                   [1, 2, 3, 2, 3, 0.5, 1, 0.5],
...                   [9, 10, 10, 10, 10, 9, 9, 9]], dtype=np.float32)
>>> obbsat.collide(rects, [[0, 1], [0, 2]])
array([ True, False])
>>> poses = np.array([[1, 0.5, 1, 0.5, 1, 0],          # the same rectangles as poses
...                   [2, 1.25, 1, 0.75, 1, 0],
...                   [9.5, 9.5, 0.5, 0.5, 1, 0]], dtype=np.float32)
>>> obbsat.collide(poses, [[0, 1], [0, 2]])
array([ True, False])
"""

import operator as _operator
import numpy as _np

from . import _core, testing
from ._core import FindPairsStats, PoseRecords, PoseRecords64, RectRecords, RectRecords64, UnsupportedBackendError

__version__ = _core.__version__

# Submodules imported on first use (``obbsat.geo``), so that ``import obbsat``
# needs none of their optional dependencies (shapely, geopandas).
_LAZY_SUBMODULES = ("geo",)


def __getattr__(name):
    if name in _LAZY_SUBMODULES:
        import importlib

        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = [
    "Contacts",
    "Distances",
    "FindPairsStats",
    "PairFinder",
    "PoseRecords",
    "PoseRecords64",
    "RectRecords",
    "RectRecords64",
    "UnsupportedBackendError",
    "aligned",
    "backends",
    "bounds",
    "collide",
    "collide_stream",
    "colliding_pairs",
    "contacts",
    "contacts_stream",
    "corners_of_poses",
    "distances",
    "distances_stream",
    "find_contacts",
    "find_pairs",
    "methods",
    "records",
    "resolved_backend",
]

_MAX_INDEX = 2**32 - 1

# The most cores a call may ask for: the library counts them in an unsigned int.
_MAX_THREADS = 2**32 - 1

# The method of the pair-list calls when none is given: the article's test on
# each form (as the command-line program's ``collide --rects`` and ``collide
# --poses``). Scene queries default to exact instead.
_DEFAULT_METHOD = {"corners": "sat4", "poses": "local"}
# float64 rows: sat4 has no double form, so corners default to exact.
_DEFAULT_METHOD64 = {"corners": "exact", "poses": "local"}
_PRECISIONS = ("float32", "float64")
_SCENE_METHOD = "exact"
_DEFAULT_BACKEND = "auto"

# The stores records() builds: float32 ones and double ones (every double
# kept exactly), and for each its form and the _core call that decides a
# pair list over it.
_FLOAT_STORES = (RectRecords, PoseRecords)
_DOUBLE_STORES = (RectRecords64, PoseRecords64)
_STORES = _FLOAT_STORES + _DOUBLE_STORES
_STORE_FORM = {RectRecords: "corners", PoseRecords: "poses", RectRecords64: "corners", PoseRecords64: "poses"}
_STORE_CALL = {RectRecords: "collide_store", PoseRecords: "collide_pose_store",
               RectRecords64: "collide_store64", PoseRecords64: "collide_pose_store64"}


def _backend(backend):
    """The backend to ask for: ``"auto"`` for ``None``."""
    return _DEFAULT_BACKEND if backend is None else backend


def _threads(threads):
    """``threads`` as an int: a whole number (``TypeError`` for a float or a
    string, as the compiled calls refuse them), refused (``ValueError``)
    outside 0 .. 2**32 - 1."""
    try:
        value = _operator.index(threads)
    except TypeError:
        raise TypeError(f"threads must be a whole number, not {type(threads).__name__}") from None
    if not 0 <= value <= _MAX_THREADS:
        raise ValueError(f"threads must be >= 0 and <= {_MAX_THREADS} (0 means every core), not {value}")
    return value


def _refuse_store(value, call, what, expected):
    """``TypeError`` naming the call, the argument and what it expected when a
    store (:class:`RectRecords`, :class:`PoseRecords`, or a double one) is passed where it does not go."""
    if isinstance(value, _STORES):
        raise TypeError(f"{call}: {what} must be {expected}, got {type(value).__name__}")


def _require_apart(out, **inputs):
    """``ValueError`` naming both when ``out`` shares memory with one of the
    arrays the call reads: the results would overwrite them."""
    if not isinstance(out, _np.ndarray):
        return
    for name, value in inputs.items():
        if isinstance(value, _np.ndarray) and _np.shares_memory(out, value):
            raise ValueError(f"out and {name} share memory: out must not overlap {name}")


def methods(poses=False):
    """The collision tests that run on corner rectangles, or with
    ``poses=True`` on poses, in the library's order. A method named for the
    other form is refused with ``ValueError``.

    >>> obbsat.methods()
    ['sat4', 'sat4_centered', 'sat4_double', 'conservative', 'exact']
    >>> obbsat.methods(poses=True)
    ['conservative', 'exact', 'local']
    """
    return list(_core.methods("poses" if poses else "corners"))


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
    ``None`` is ``"auto"``.

    >>> obbsat.resolved_backend("scalar")
    'scalar'
    """
    return _core.resolved_backend(_backend(backend))


def _precision(precision):
    """``precision`` checked: None (from the data), ``"float32"`` or ``"float64"``."""
    if precision is not None and precision not in _PRECISIONS:
        raise ValueError(f"precision: expected None, 'float32' or 'float64', got {precision!r}")
    return precision


def _dtype_of(dtype, precision):
    """The float type the library reads an array of ``dtype`` as: the one
    ``precision`` names, else float64 for float64 (or wider) data, so that no
    double is rounded, and float32 for the rest (float32 and float16 exactly,
    integers as before: exactly up to 2**24)."""
    if precision is not None:
        return _np.dtype(precision)
    return _np.dtype(_np.float64) if dtype.kind == "f" and dtype.itemsize > 4 else _np.dtype(_np.float32)


def _form(rects, what, precision=None):
    """``(form, array)``: which store the rectangles go to, ``"corners"`` or
    ``"poses"``, and the array as the library reads it, C-contiguous float32
    or float64 (:func:`_dtype_of`; the array itself when it already is one).

    This is the one place that maps an array's shape to a store: rows of
    eight floats (``(N, 8)`` or ``(N, 4, 2)``) are corners, rows of six
    (``(N, 6)``) are poses. A store is refused: calls that take one handle
    it before (:func:`_store_form`).
    """
    if isinstance(rects, _STORES):
        _store_form(rects, precision)
        raise TypeError(f"{what}: expected an array of corners or poses, got {type(rects).__name__}")
    if not isinstance(rects, _np.ndarray):
        rects = _np.asarray(rects)
    if rects.dtype.kind not in "fiu":
        raise TypeError(f"{what}: expected real numbers, got dtype {rects.dtype}")
    shape = rects.shape
    if (len(shape) == 2 and shape[1] == 8) or (len(shape) == 3 and shape[1:] == (4, 2)):
        form = "corners"
    elif len(shape) == 2 and shape[1] == 6:
        form = "poses"
    else:
        raise ValueError(f"{what}: expected shape (N, 8) or (N, 4, 2) (corners UL, UR, LR, LL) "
                         f"or (N, 6) (poses cx, cy, hx, hy, c, s), got {shape}")
    return form, _np.ascontiguousarray(rects, dtype=_dtype_of(rects.dtype, precision))


def _is64(rows):
    """True for rows the library reads as doubles: a float64 array or a double store."""
    return isinstance(rows, _DOUBLE_STORES) or (isinstance(rows, _np.ndarray) and rows.dtype == _np.float64)


def _store_form(store, precision):
    """The form of ``store``, ``"corners"`` or ``"poses"``. A store is never
    converted: ``precision`` naming the other float type is a ``ValueError``
    naming both (a float32 store cannot give back the doubles it was built
    from; a double store is not rounded behind the caller's back)."""
    name = type(store).__name__
    if precision == "float64" and isinstance(store, _FLOAT_STORES):
        raise ValueError(f"precision='float64' asks for float64 rows, but a {name} holds float32: "
                         "pass the float64 array itself, or its double store (obbsat.records(rows))")
    if precision == "float32" and isinstance(store, _DOUBLE_STORES):
        raise ValueError(f"precision='float32' asks for float32 rows, but a {name} holds float64 and is never "
                         "rounded: pass the array, or a float32 store (obbsat.records(rows, precision='float32'))")
    return _STORE_FORM[type(store)]


def _poses(poses, what, precision="float32"):
    """The poses as the library reads them: a C-contiguous float32 (N, 6)
    array, or float64 as :func:`_dtype_of` says when ``precision`` is None."""
    if not isinstance(poses, _np.ndarray):
        poses = _np.asarray(poses)
    if poses.dtype.kind not in "fiu":
        raise TypeError(f"{what}: expected real numbers, got dtype {poses.dtype}")
    if poses.ndim != 2 or poses.shape[1] != 6:
        raise ValueError(f"{what}: expected shape (N, 6) (cx, cy, hx, hy, c, s), got {poses.shape}")
    return _np.ascontiguousarray(poses, dtype=_dtype_of(poses.dtype, precision))


def records(rects, *, precision=None):
    """A store of the rectangles in the library's packed records (64-byte
    aligned), copied and checked once. Its precision follows the data, as
    every call's does: float64 rows give a double store, every double kept
    exactly (:class:`RectRecords64` for corners, :class:`PoseRecords64` for
    poses, 64 bytes a row); anything else (float32, float16, integers) a
    float32 store (:class:`RectRecords`, :class:`PoseRecords`, 32 bytes a
    row).

    ``precision="float32"`` asks for the float32 store of float64 data,
    rounding each coordinate to the nearest float32: faster calls and half
    the memory, but the answers are then those of the rounded rectangles
    (docs/python.md says what that costs). ``precision="float64"`` widens
    float32 or integer data (exactly) to a double store. A store passed in
    is returned as it is; a precision naming the other float type is a
    ``ValueError`` (a store is never converted).

    :func:`collide` reads a float32 corner array in place but checks its
    coordinates on every call (one pass over the N rectangles), and copies a
    pose array (or any float64 array) into records on every call; a store
    is checked (and copied) when it is built, so calls over it read only the
    pairs, and decide them on the same path as an array of its rows (the
    same verdicts, byte for byte). Use one when many pair lists meet the
    same rectangles. ``store.corners`` (or ``store.poses``) is a read-only
    view of its records, float32 or float64. A store pickles (for Dask
    workers, say) as its corners (or poses).

    >>> store = obbsat.records(np.array([[0, 1, 2, 1, 2, 0, 0, 0]] * 2, dtype=np.float32))
    >>> len(store), obbsat.collide(store, [[0, 1]])
    (2, array([ True]))
    >>> poses = obbsat.records(np.array([[0, 0, 1, 1, 1, 0], [2, 0, 1, 1, 0, 1]], dtype=np.float32))
    >>> type(poses).__name__, obbsat.collide(poses, [[0, 1]], method="exact")
    ('PoseRecords', array([ True]))
    >>> utm = obbsat.records(np.array([[500000.125, 4e6, 1, 1, 1, 0], [500002.125, 4e6, 1, 1, 1, 0]]))
    >>> utm, obbsat.collide(utm, [[0, 1]], method="exact")
    (PoseRecords64(2 poses), array([ True]))
    """
    precision = _precision(precision)
    if isinstance(rects, _STORES):
        _store_form(rects, precision)
        return rects
    form, rects = _form(rects, "rects", precision)
    if _is64(rects):
        return PoseRecords64(rects) if form == "poses" else RectRecords64(rects)
    return PoseRecords(rects) if form == "poses" else RectRecords(rects)


def aligned(array, alignment=64):
    """``array`` itself when it starts on a multiple of ``alignment`` bytes
    and is C-contiguous, else a C-contiguous copy that does (same dtype and
    shape; the copy costs one pass over the array).

    A corner row is 32 bytes. numpy starts large arrays on 16 bytes, so half
    the rows of a float32 (N, 8) array straddle two cache lines, and a
    pair-list call over that array, which reads each row at random, fetches
    more lines: on the 1M-pair benchmark (docs/python.md) an aligned copy
    made :func:`collide` about 13% faster. Align once, call many times.

    >>> rects = obbsat.aligned(np.zeros((1000, 8), dtype=np.float32))
    >>> rects.ctypes.data % 64
    0
    >>> obbsat.aligned(rects) is rects
    True
    """
    alignment = int(alignment)
    if alignment < 1 or alignment & (alignment - 1):
        raise ValueError(f"alignment: expected a power of two, got {alignment}")
    array = _np.asarray(array)
    if array.flags.c_contiguous and array.ctypes.data % alignment == 0:
        return array
    raw = _np.empty(array.nbytes + alignment, dtype=_np.uint8)
    start = -raw.ctypes.data % alignment
    out = raw[start:start + array.nbytes].view(array.dtype).reshape(array.shape)
    out[...] = array
    return out


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


_PAIRS_EXPECTED = "an (M, 2) integer array"


def _default_method(form, rows, method):
    """``method``, or for None the default of a pair-list call over ``rows`` (an array or a store) of ``form``."""
    if method is not None:
        return method
    return (_DEFAULT_METHOD64 if _is64(rows) else _DEFAULT_METHOD)[form]


def _store(rects, method, precision=None):
    """``(rects, call, method)``: the rectangles as the library reads them, the
    ``_core`` call for their store and precision, and the method (the
    default for ``None``)."""
    if isinstance(rects, _STORES):
        form, call = _store_form(rects, precision), getattr(_core, _STORE_CALL[type(rects)])
    else:
        form, rects = _form(rects, "rects", precision)
        if _is64(rects):
            call = _core.collide_poses64 if form == "poses" else _core.collide_records64
        else:
            call = _core.collide_poses if form == "poses" else _core.collide_records
    return rects, call, _default_method(form, rects, method)


def collide(rects, pairs, method=None, backend="auto", threads=1, out=None, *, precision=None):
    """Whether each pair of rectangles collides.

    Parameters
    ----------
    rects : array_like, shape (N, 4, 2), (N, 8) or (N, 6), or a store
        Corners UL, UR, LR, LL of each rectangle (x, y each), or poses
        ``cx, cy, hx, hy, c, s`` (shape (N, 6)), or a :func:`records` store
        (:class:`RectRecords`, :class:`PoseRecords`, or the double
        :class:`RectRecords64`, :class:`PoseRecords64`, decided as the
        float64 array of their rows). float32 C-contiguous
        corners are read in place; anything else is converted once. Every
        coordinate must be finite (checked on every call: one read pass).
        float32 C-contiguous poses are read in place too, each checked on
        every call (finite, half extents >= 0, rotation not (0, 0)). A store
        was checked once, when built.
    pairs : array_like of int, shape (M, 2)
        Indices into ``rects``: row i asks whether ``rects[pairs[i, 0]]``
        and ``rects[pairs[i, 1]]`` collide. C-contiguous uint32 is read in
        place; any other integer dtype is range-checked and converted once.
    method : str, optional
        One of :func:`methods` for the form of ``rects`` (``methods()`` on
        corners, ``methods(poses=True)`` on poses; on float64 rows and
        double stores only those with a double form). ``None``: ``"sat4"``
        on corners (``"exact"`` on float64 corners), ``"local"`` on poses.
    backend : str, optional
        ``"auto"`` (also for ``None``) or one of :func:`backends`; verdicts
        never depend on it.
    threads : int
        Cores to split the batch over, 0 .. 2**32 - 1; 0 means all. The GIL
        is released.
    out : ndarray of bool or uint8, shape (M,), optional
        Where to write the verdicts (C-contiguous, writable), sharing no
        memory with ``rects`` or ``pairs``.

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
        the coordinate), a pose is invalid (the message names the pose and the
        field, e.g. ``pose 3: half extent hy is -1, negative``), a shape is
        wrong, a method unknown or not one that runs on the form of
        ``rects``, a backend unknown, or the backend cannot run here
        (``UnsupportedBackendError``), ``threads`` is outside 0 .. 2**32 - 1,
        ``out`` shares memory with ``rects`` or ``pairs``, or ``precision``
        names the other float type than a store's (a store is never
        converted).
    TypeError
        A dtype is not numeric (rects), not integer (pairs), ``pairs`` is a
        store, or ``out`` is not a writable C-contiguous bool/uint8 array.

    Nothing is written to ``out`` when an error is raised.

    >>> rects = np.array([[[0, 1], [2, 1], [2, 0], [0, 0]],
    ...                   [[1, 2], [3, 2], [3, .5], [1, .5]]], dtype=np.float32)
    >>> obbsat.collide(rects, np.array([[0, 1]], dtype=np.uint32), method="exact")
    array([ True])

    Poses: the square [-1, 1] x [-1, 1], and a square of half extents 1
    scaled by its rotation vector (3, 4) to a half side of 5, whose corner
    (1, 1) touches the first square's:

    >>> poses = np.array([[0, 0, 1, 1, 1, 0],
    ...                   [8, 2, 1, 1, 3, 4]], dtype=np.float32)
    >>> obbsat.collide(poses, [[0, 1]], method="exact"), obbsat.collide(poses, [[0, 1]])
    (array([ True]), array([ True]))
    >>> obbsat.collide(poses, [[0, 1]], method="sat4")
    Traceback (most recent call last):
    ...
    ValueError: method sat4 does not run on poses (pose_records take conservative, exact, local)
    """
    _refuse_store(pairs, "collide", "pairs", _PAIRS_EXPECTED)
    _require_apart(out, rects=rects, pairs=pairs)
    threads = _threads(threads)
    rects, call, method = _store(rects, method, _precision(precision))
    pairs = _pairs(pairs, len(rects))
    verdicts = _verdicts(out, len(pairs))
    call(rects, pairs, verdicts, method, _backend(backend), threads)
    return verdicts


def colliding_pairs(rects, pairs, method=None, backend="auto", threads=1, *, precision=None):
    """The rows of ``pairs`` whose rectangles collide, in their input order,
    shape (K, 2), with the dtype of ``pairs``. Arguments as :func:`collide`
    (corners or poses).

    >>> rects = np.array([[0, 1, 2, 1, 2, 0, 0, 0],
    ...                   [1, 2, 3, 2, 3, 0.5, 1, 0.5],
    ...                   [9, 10, 10, 10, 10, 9, 9, 9]], dtype=np.float32)
    >>> obbsat.colliding_pairs(rects, np.array([[0, 1], [0, 2], [1, 0]]))
    array([[0, 1],
           [1, 0]])
    >>> poses = np.array([[1, 0.5, 1, 0.5, 1, 0], [9.5, 9.5, 0.5, 0.5, 0, 1]], dtype=np.float32)
    >>> obbsat.colliding_pairs(poses, [[0, 1], [1, 1]], method="conservative")
    array([[1, 1]])
    """
    _refuse_store(pairs, "colliding_pairs", "pairs", _PAIRS_EXPECTED)
    if not isinstance(pairs, _np.ndarray):
        pairs = _np.asarray(pairs)
    if pairs.size == 0 and pairs.ndim < 2:
        pairs = pairs.reshape(0, 2).astype(_np.int64)
    hits = collide(rects, pairs, method=method, backend=backend, threads=threads, precision=precision)
    return pairs[hits]


def collide_stream(a, b, method=None, backend="auto", threads=1, out=None, *, precision=None):
    """Whether ``a[i]`` and ``b[i]`` collide, for every i: two batches of
    rectangles of equal length and the same form, each shaped (N, 4, 2) or
    (N, 8) (corners), or each (N, 6) (poses).

    Both batches are copied into the library's structure-of-arrays store
    (eight coordinate arrays for corners, six field arrays for poses), which
    is what the streaming kernels read; the copy checks every coordinate (or
    pose). Other arguments, the default method, the result and the errors
    are as in :func:`collide`; a length mismatch, or corners against poses,
    is a ``ValueError``; a :func:`records` store, a ``TypeError`` (a stream
    reads arrays).

    >>> a = np.array([[0, 1, 2, 1, 2, 0, 0, 0]] * 2, dtype=np.float32)
    >>> b = np.array([[1, 2, 3, 2, 3, .5, 1, .5], [5, 6, 6, 6, 6, 5, 5, 5]], dtype=np.float32)
    >>> obbsat.collide_stream(a, b)
    array([ True, False])
    >>> obbsat.collide_stream(np.array([[0, 0, 1, 1, 1, 0]] * 2, dtype=np.float32),
    ...                       np.array([[1.5, 1, 0.5, 0.5, 0.6, 0.8], [3, 0, 1, 1, 0, 1]], dtype=np.float32))
    array([ True, False])
    """
    for what, batch in (("a", a), ("b", b)):
        _refuse_store(batch, "collide_stream", what,
                      "an array of corners, (N, 8) or (N, 4, 2), or of poses, (N, 6), not a store")
    _require_apart(out, a=a, b=b)
    threads = _threads(threads)
    precision = _precision(precision)
    if precision is None:
        # Both batches in one precision: float64 when either holds float64 data (widening is exact).
        precision = "float64" if any(_dtype_of(_np.asarray(x).dtype, None) == _np.float64 for x in (a, b)) else None
    form_a, a = _form(a, "a", precision)
    form_b, b = _form(b, "b", precision)
    if form_a != form_b:
        raise ValueError(f"a holds {form_a} (shape {a.shape}), b holds {form_b} (shape {b.shape}): "
                         "a stream compares one form")
    method = _default_method(form_a, a, method)
    verdicts = _verdicts(out, len(a))
    if _is64(a):
        decide = _core.collide_pose_stream64 if form_a == "poses" else _core.collide_stream64
    else:
        decide = _core.collide_pose_stream if form_a == "poses" else _core.collide_stream
    decide(a, b, verdicts, method, _backend(backend), threads)
    return verdicts


def corners_of_poses(poses, backend="auto", *, precision=None):
    """The corners UL, UR, LR, LL of each pose, float32 of shape (N, 4, 2):
    the library's conversion (``obbsat::convert_to_corners``), which every
    backend computes bit for bit as stated in ``obbsat/ref/pose_corners.hpp``.
    With ``u = (hx*c, hx*s)`` and ``v = (-(hy*s), hy*c)``, in float32, each
    operation rounded once, no fused multiply-add::

        UL = ((cx - ux) + vx, (cy - uy) + vy)    UR = ((cx + ux) + vx, (cy + uy) + vy)
        LR = ((cx + ux) - vx, (cy + uy) - vy)    LL = ((cx - ux) - vx, (cy - uy) - vy)

    ``poses`` is a (N, 6) array (copied once into pose records and checked,
    as in :func:`collide`) or a :class:`PoseRecords` store. float64 poses (an
    array, or a :class:`PoseRecords64` store) give float64 corners, the same
    operations in float64. Use it to run a
    corner method (``sat4``, ...) on poses; the corner methods then answer
    for the rounded quads, not for the poses. A pose near the end of the
    float range can give infinite corners, which :func:`collide` refuses.

    >>> obbsat.corners_of_poses(np.array([[1, 0.5, 1, 0.5, 1, 0], [8, 2, 1, 1, 3, 4]], dtype=np.float32))
    array([[[ 0.,  1.],
            [ 2.,  1.],
            [ 2.,  0.],
            [ 0.,  0.]],
    <BLANKLINE>
           [[ 1.,  1.],
            [ 7.,  9.],
            [15.,  3.],
            [ 9., -5.]]], dtype=float32)
    """
    backend = _backend(backend)
    precision = _precision(precision)
    if isinstance(poses, (PoseRecords, PoseRecords64)):
        _store_form(poses, precision)
        if isinstance(poses, PoseRecords64):
            return _corners_of_poses64(poses.poses)
        out = _np.empty((len(poses), 4, 2), dtype=_np.float32)
        _core.store_corners(poses, out, backend)
        return out
    _refuse_store(poses, "corners_of_poses", "poses", "a PoseRecords or PoseRecords64 store or an (N, 6) float array")
    poses = _poses(poses, "poses", precision)
    if _is64(poses):
        # The poses are checked as the library checks them (the message names the pose).
        _core.pose_bounds64(poses)
        return _corners_of_poses64(poses)
    out = _np.empty((len(poses), 4, 2), dtype=_np.float32)
    _core.pose_corners(poses, out, backend)
    return out


def _corners_of_poses64(poses):
    """The corners of valid float64 poses (N, 6), float64 (N, 4, 2): the
    operations of :func:`corners_of_poses` in float64, each rounded once
    (numpy, no fused multiply-add)."""
    cx, cy, hx, hy, c, s = (poses[:, k] for k in range(6))
    ux, uy = hx * c, hx * s
    vx, vy = -(hy * s), hy * c
    out = _np.empty((len(poses), 4, 2), dtype=_np.float64)
    out[:, 0, 0], out[:, 0, 1] = (cx - ux) + vx, (cy - uy) + vy
    out[:, 1, 0], out[:, 1, 1] = (cx + ux) + vx, (cy + uy) + vy
    out[:, 2, 0], out[:, 2, 1] = (cx + ux) - vx, (cy + uy) - vy
    out[:, 3, 0], out[:, 3, 1] = (cx - ux) - vx, (cy - uy) - vy
    return out


def _scene_form(boxes, what, precision=None):
    """``(form, boxes)`` for a scene query: a store as it is (refused when
    ``precision`` names the other float type), an array as :func:`_form`
    gives it."""
    if isinstance(boxes, _STORES):
        return _store_form(boxes, precision), boxes
    return _form(boxes, what, precision)


def _holds_float64(boxes):
    """True when the library reads ``boxes`` as doubles unless told
    otherwise: a double store, or float64 (or wider) data."""
    if isinstance(boxes, _STORES):
        return isinstance(boxes, _DOUBLE_STORES)
    return _dtype_of(_np.asarray(boxes).dtype, None) == _np.float64


def _scene(boxes, against, precision=None):
    """``(form, boxes, against)``: both sides of a scene query in the form and
    precision the library reads, refused when they hold different forms. With
    ``precision`` None, both sides are float64 when either holds float64 data
    (widening float32 is exact), else float32."""
    precision = _precision(precision)
    if isinstance(boxes, _STORES) and isinstance(against, _STORES) and _is64(boxes) != _is64(against):
        raise ValueError(f"boxes is a {type(boxes).__name__}, against a {type(against).__name__}: a scene query "
                         "over two stores takes them of one precision (a store is never converted)")
    if precision is None and (_holds_float64(boxes) or (against is not None and _holds_float64(against))):
        precision = "float64"
    form, boxes = _scene_form(boxes, "boxes", precision)
    if against is not None:
        form_against, against = _scene_form(against, "against", precision)
        if form_against != form:
            raise ValueError(f"boxes hold {form}, against holds {form_against}: a scene query compares one form")
    return form, boxes, against


def _scene_call(form, boxes, name):
    """The ``_core`` scene call ``name`` (find_pairs or a finder's find) for the form and precision of ``boxes``."""
    suffix = "poses" if form == "poses" else "corners"
    return name + "_" + suffix + ("64" if _is64(boxes) else "")


def find_pairs(boxes, against=None, *, method="exact", backend="auto", threads=1, categories=None, masks=None,
               groups=None, against_categories=None, against_masks=None, against_groups=None, precision=None):
    """Every pair of rectangles that collides, with no pair list: the
    library's scene query (``obbsat::find_pairs``).

    A broadphase over each rectangle's :func:`bounds` finds the pairs whose
    bounds overlap (closed: touching bounds overlap), the method decides them
    on the chosen backend, and the colliding ones come back sorted. So the
    answer is exactly the pairs whose bounds overlap and that ``method``
    calls colliding; with ``method="exact"`` that is every pair of
    rectangles that share a point, the exact answer among all N(N-1)/2. A
    float method's false positive between rectangles whose bounds are apart
    is not reported; every other verdict is the method's own, the same as
    :func:`collide` gives on that pair, on every backend and thread count.

    Parameters
    ----------
    boxes : array_like, shape (N, 4, 2), (N, 8) or (N, 6), or a store
        Corners or poses, as in :func:`collide`, or a :func:`records` store
        (read as it is). A float32 C-contiguous array is read in place (no
        copy) and checked by the query; other dtypes and layouts are
        converted to that first, as in :func:`collide`.
    against : array_like or store of the same form, optional
        With it, the pairs (i, j) with i indexing ``boxes`` and j indexing
        ``against`` (every i and j, not only i < j).
    method : str, optional
        One of :func:`methods` for the form. The default (also for ``None``),
        ``"exact"``, is the default of every scene query (``obbsat pairs`` on the command line,
        :func:`obbsat.dask.find_pairs`, :class:`PairFinder`): the exact answer.
        :func:`collide` defaults to the fastest float method instead.
    backend, threads
        As in :func:`collide`; the answer never depends on them. The GIL is
        released during the query.
    categories, masks : array_like of integers, shape (N,), optional
        Pair filters as Box2D's ``b2Filter``: each box's category bits and
        the categories it collides with (up to 64 bits). A pair (i, j) is
        reported only if ``categories[i] & masks[j]`` and ``categories[j] &
        masks[i]`` are both non-zero. Not given: every bit set (the box
        pairs with everything). Any integer dtype; uint64 C-contiguous is
        read in place, others are converted; a negative value is a
        ValueError.
    groups : array_like of integers, shape (N,), optional
        Each box's group; two boxes of one group other than 0 (say the
        pieces of one compound body) never pair. Not given: all 0. Values
        must fit in int32 (int32 is read in place).
    against_categories, against_masks, against_groups : optional
        The same for the rows of ``against`` (only with it). A group number
        means one body on both sides. Filtered pairs are dropped in the
        broadphase, before the method tests them, at no narrowphase cost.

    Returns
    -------
    ndarray of uint32, shape (K, 2)
        Rows (i, j) sorted by i, then j; i < j without ``against``. The
        array owns the library's result (no copy).

    Raises
    ------
    ValueError
        A coordinate or pose is invalid (named as in :func:`collide`, with
        ``boxes: `` or ``against: `` in front for a cross query), a shape is
        wrong, ``boxes`` and ``against`` hold different forms, a method is
        unknown or does not run on the form, a backend unknown, ``threads``
        outside 0 .. 2**32 - 1, or the backend cannot run here
        (``UnsupportedBackendError``).
        A filter array has another length than its rows (the message names
        the argument and both lengths) or a value out of its range.
    TypeError
        A dtype is not numeric, or a filter array's is not integer.

    >>> poses = np.array([[0, 0, 1, 1, 1, 0],       # the square [-1, 1]^2
    ...                   [2, 0, 1, 1, 0, 1],       # touching it along x = 1
    ...                   [9, 9, 1, 1, 1, 0],
    ...                   [1, 1, 0.5, 0.5, 0.6, 0.8]], dtype=np.float32)
    >>> obbsat.find_pairs(poses, method="exact")
    array([[0, 1],
           [0, 3],
           [1, 3]], dtype=uint32)
    >>> obbsat.find_pairs(poses[:2], poses[2:], method="exact")
    array([[0, 1],
           [1, 1]], dtype=uint32)
    >>> obbsat.find_pairs(poses, groups=np.array([1, 0, 0, 1]))   # 0 and 3 are one body
    array([[0, 1],
           [1, 3]], dtype=uint32)
    """
    method = _SCENE_METHOD if method is None else method
    threads = _threads(threads)
    form, boxes, against = _scene(boxes, against, precision)
    query = getattr(_core, _scene_call(form, boxes, "find_pairs"))
    return query(boxes, against, method, _backend(backend), threads, categories=categories, masks=masks,
                 groups=groups, against_categories=against_categories, against_masks=against_masks,
                 against_groups=against_groups)


def _ids(ids, what):
    """``ids`` as a C-contiguous uint64 vector (None stays None): any integer
    array whose values fit uint64 without loss."""
    if ids is None:
        return None
    array = _np.asarray(ids)
    if array.size == 0 and array.dtype.kind == "f":
        array = array.astype(_np.uint64)  # [] is float64 to numpy
    if array.dtype.kind not in "iu":
        raise TypeError(f"{what}: expected an integer array, got dtype {array.dtype}")
    if array.ndim != 1:
        raise ValueError(f"{what}: expected shape (N,), got {array.shape}")
    if array.dtype.kind == "i" and array.size and array.min() < 0:
        row = int(_np.argmax(array < 0))
        raise ValueError(f"{what}: row {row} holds the negative id {int(array[row])}; ids are unsigned 64-bit")
    return _np.ascontiguousarray(array, dtype=_np.uint64)


class PairFinder:
    """A scene query that persists between calls (``obbsat::pair_finder``),
    for simulations: it keeps the order of the rectangles, its buffers and the
    candidates of slightly widened bounds, so a scene whose rectangles moved
    a little is answered from those candidates (or, once a rectangle left its
    widened bounds, by repairing the previous order), with no allocation once
    its buffers have grown.

    ``find(boxes, against=None)`` returns what :func:`find_pairs` with the
    finder's method, backend and threads returns on the same data, always;
    the pairs are copied out of the finder's buffer (K * 8 bytes), which the
    next call reuses. ``stats`` says what the last call did
    (:class:`FindPairsStats`: ``boxes``, ``strips``, ``visits``,
    ``candidates``, ``pairs``, ``slow_path_pairs``, ``reused_order``,
    ``reused_candidates``, ``kept_candidates`` and the seconds of each phase).

    With ``events=True`` (keyword only; off by default, and then nothing is
    kept for them), ``began()`` and ``ended()`` return the pairs that began
    and ended colliding at the last call of :meth:`find`: uint32 (K, 2),
    sorted like find's pairs (``i < j`` within one set, ``i`` in ``boxes`` and
    ``j`` in ``against`` across two), new arrays. Rows are matched by
    position whatever their count (a pair of a row that no longer exists
    ends, one of a new row begins). The first call reports every pair as
    begun and none ended, and so does a call of the other kind (one set, two
    sets) than the last, which also ends every pair of the last; a call that
    raises changes no events; before the first call both are empty. With
    events off they raise ``RuntimeError``. When the last call gave
    ``ids=`` the events are id pairs instead: uint64 (K, 2), the smaller id
    first within one set (the id in ``boxes`` first across two), sorted; a
    removed box ends all its pairs, a new box's pairs begin, a box that
    changed rows keeps its pairs. A call with ids after one without (or the
    other way round) reports every pair as begun and none ended. The default method is ``"exact"``, as in
    :func:`find_pairs` (``method=None`` too; ``backend=None`` is ``"auto"``). One call runs at a time (another thread calling meanwhile waits, with
    the GIL released).

    >>> finder = obbsat.PairFinder()
    >>> poses = np.array([[0, 0, 1, 1, 1, 0], [2, 0, 1, 1, 1, 0], [5, 0, 1, 1, 1, 0]], dtype=np.float32)
    >>> finder.find(poses)
    array([[0, 1]], dtype=uint32)
    >>> poses[2, 0] = 3.5                           # the third moves onto the second
    >>> finder.find(poses)
    array([[0, 1],
           [1, 2]], dtype=uint32)
    >>> finder.stats.boxes, finder.stats.pairs
    (3, 2)
    >>> finder = obbsat.PairFinder(events=True)
    >>> _ = finder.find(poses)
    >>> finder.began()                              # the first call: every pair began
    array([[0, 1],
           [1, 2]], dtype=uint32)
    >>> poses[0, 0] = -5                            # the first moves away
    >>> _ = finder.find(poses)
    >>> finder.ended()
    array([[0, 1]], dtype=uint32)
    >>> len(finder.began())
    0
    >>> finder = obbsat.PairFinder(events=True)
    >>> _ = finder.find(poses, ids=[10, 11, 12])
    >>> finder.find(poses[1:], ids=[11, 12])        # box 10 is gone; the others moved up a row
    array([[0, 1]], dtype=uint32)
    >>> finder.ended(), len(finder.began())
    (array([], shape=(0, 2), dtype=uint64), 0)
    """

    def __init__(self, method="exact", backend="auto", threads=1, *, events=False, precision=None):
        self._precision = _precision(precision)
        self._method = _SCENE_METHOD if method is None else method
        self._backend = _backend(backend)
        self._threads = _threads(threads)
        self._ran = False
        self._events = bool(events)
        # An unknown method or backend, one this CPU cannot run, or threads out of range is refused here.
        self._query = _core.PairFinder(self._method, self._backend, self._threads)
        if self._events:
            self._query.track_events(True)

    def __repr__(self):
        events = ", events=True" if self._events else ""
        return f"PairFinder(method={self._method!r}, backend={self._backend!r}, threads={self._threads}{events})"

    def find(self, boxes, against=None, *, ids=None, against_ids=None, categories=None, masks=None, groups=None,
             against_categories=None, against_masks=None, against_groups=None):
        """The pairs of ``find_pairs(boxes, against, ...)`` with the finder's
        settings and the same pair filters: uint32 (K, 2), sorted, a new
        array. Filters that differ from the last call's in any value make
        the call a full query (the kept candidates hold only the pairs the
        filters they were kept with let through; with ids, rows that came,
        went or changed places since the last full query too).

        ``ids`` (and ``against_ids`` with ``against``; both or neither) give
        each row a stable id: any integer array of shape (N,) whose values
        fit uint64 (a negative value is a ValueError, a non-integer dtype a
        TypeError). The finder then follows each box by its id from call to
        call, so rows may be appended, removed, swap-removed or reordered
        between calls and still be answered from the kept candidates; the
        pairs are still row indices of this call. Without ids rows are
        matched by position. Two rows with one id raise ValueError naming
        both rows and the id, and change nothing."""
        return self._frame("find", boxes, against, ids, against_ids, categories=categories, masks=masks,
                           groups=groups, against_categories=against_categories, against_masks=against_masks,
                           against_groups=against_groups)

    def find_contacts(self, boxes, against=None, *, ids=None, against_ids=None, categories=None, masks=None,
                      groups=None, against_categories=None, against_masks=None, against_groups=None):
        """The pairs of :meth:`find` with the same arguments, each with its
        contact (``obbsat::pair_finder::find_contacts``, margin 0):
        ``(pairs, contacts)``, a :class:`Contacts` row per pair, each what
        :func:`contacts` gives for that pair of this call's rows (``boxes``
        then ``against`` across two sets). A pair that persists from one
        call to the next keeps its points' feature keys while the same
        corners touch the same edges, so a solver can match them by key.
        float64 rows (or double stores, or a finder of
        ``precision="float64"``) are decided and their contacts computed in
        double (``obbsat::pair_finder::find_contacts64``): the columns are
        float64, each what :func:`contacts` gives in double for that pair;
        nothing is rounded. A row contacts do not accept raises ValueError
        before the frame changes anything.

        >>> finder = obbsat.PairFinder()
        >>> poses = np.array([[0, 0, 1, 1, 1, 0], [1.5, 0, 1, 1, 1, 0]], dtype=np.float32)
        >>> pairs, c = finder.find_contacts(poses)
        >>> pairs, c.depths
        (array([[0, 1]], dtype=uint32), array([0.5], dtype=float32))
        >>> far = np.array([[500000.1, 0, 1, 1, 1, 0], [500002.0999, 0, 1, 1, 1, 0]])  # float64
        >>> pairs, c = obbsat.PairFinder().find_contacts(far)
        >>> pairs, c.depths.dtype
        (array([[0, 1]], dtype=uint32), dtype('float64'))
        """
        pairs, columns = self._frame("find_contacts", boxes, against, ids, against_ids, categories=categories,
                                     masks=masks, groups=groups, against_categories=against_categories,
                                     against_masks=against_masks, against_groups=against_groups)
        return pairs, Contacts(columns)

    def _frame(self, call, boxes, against, ids, against_ids, **filters):
        """The finder's ``call`` (find or find_contacts) for the form of ``boxes``."""
        form, boxes, against = _scene(boxes, against, self._precision)
        if against is None and against_ids is not None:
            raise ValueError("against_ids given without against")
        ids = _ids(ids, "ids")
        against_ids = _ids(against_ids, "against_ids")
        answer = getattr(self._query, _scene_call(form, boxes, call))(boxes, against, ids, against_ids, **filters)
        self._ran = True
        return answer

    @property
    def stats(self):
        """What the last call of :meth:`find` did (all zero before the first)."""
        return self._query.stats if self._ran else FindPairsStats()

    @property
    def events(self):
        """Whether the finder keeps begin/end events (``PairFinder(events=True)``)."""
        return self._events

    def began(self):
        """The pairs that began colliding at the last call of :meth:`find`:
        uint32 (K, 2), sorted, a new array; every pair of the first call."""
        self._require_events("began")
        return self._query.began()

    def ended(self):
        """The pairs that ended colliding at the last call of :meth:`find`:
        uint32 (K, 2), sorted, a new array; none at the first call."""
        self._require_events("ended")
        return self._query.ended()

    def _require_events(self, call):
        if not self._events:
            raise RuntimeError(
                f"PairFinder.{call}: begin/end events were not requested; construct PairFinder(..., events=True)"
            )


def bounds(boxes, *, precision=None):
    """The axis-aligned bounds of each rectangle as the scene queries compute
    them (``obbsat/ref/bounds.hpp``): float32 (N, 4), rows ``lo_x, lo_y,
    hi_x, hi_y``, closed. :func:`find_pairs` hands a pair to its method
    exactly when these overlap: ``lo_x[i] <= hi_x[j]`` and ``lo_x[j] <=
    hi_x[i]``, the same in y.

    For corners they are the least and greatest corner coordinates, exactly.
    For poses, per axis in float32 with each operation rounded once::

        ex = (|c|*hx) + (|s|*hy)                 ey = (|s|*hx) + (|c|*hy)
        mx = ((|cx| + ex) * 2**-21) + 2**-140    my likewise with cy, ey
        lo_x = (cx - ex) - mx                    hi_x = (cx + ex) + mx

    which contain the pose's exact point set (the margin covers the
    rounding; a pose near the end of the float range gets infinite bounds).

    ``boxes`` is an array as :func:`collide` takes it (checked the same way,
    not copied when float32 and C-contiguous) or a store.

    >>> obbsat.bounds(np.array([[0, 1, 2, 1, 2, 0, 0, 0]], dtype=np.float32))
    array([[0., 0., 2., 1.]], dtype=float32)
    >>> obbsat.bounds(np.array([[0, 0, 2, 1, 0, 1]], dtype=np.float32))  # turned a quarter
    array([[-1.0000005, -2.000001 ,  1.0000005,  2.000001 ]], dtype=float32)
    """
    precision = _precision(precision)
    form, boxes = _scene_form(boxes, "boxes", precision)
    if _is64(boxes):
        return _core.pose_bounds64(boxes) if form == "poses" else _core.corner_bounds64(boxes)
    return _core.pose_bounds(boxes) if form == "poses" else _core.corner_bounds(boxes)


class Contacts:
    """The contacts of K pairs (A, B), one row per pair, as new numpy arrays
    (``obbsat/contact_manifold.hpp`` holds the meaning of every value); the
    float32 columns below are float64 when the boxes were float64:

    - ``normals``: float32 (K, 2), the unit normal from A to B;
    - ``depths``: float32 (K,), the penetration along it (> 0 overlapping,
      0 touching, < 0 apart);
    - ``counts``: uint8 (K,), how many points (0, 1 or 2) are meaningful;
    - ``points``: float32 (K, 2, 2), the points x, y;
    - ``separations``: float32 (K, 2), each point's signed distance from the
      reference face (< 0 penetrating);
    - ``features``: uint32 (K, 2), each point's feature key
      ``index_a | type_a << 8 | index_b << 16 | type_b << 24``, an index
      0 to 3 and a type (0 a corner UL, UR, LR, LL; 1 the edge from corner
      k to corner k + 1) for each box; equal keys from one step to the next
      name the same corner touching the same edge.

    The points k >= ``counts[i]`` of row i are all zero.
    """

    __slots__ = ("normals", "depths", "counts", "points", "separations", "features")

    def __init__(self, columns):
        for name in self.__slots__:
            setattr(self, name, columns[name])

    def __len__(self):
        return len(self.depths)

    def __repr__(self):
        return f"Contacts({len(self)} pairs, {int(_np.count_nonzero(self.counts))} with points)"


class Distances:
    """The distances of K pairs (A, B) and a closest point of each, new numpy
    arrays: ``distance`` float32 (K,), ``a`` float32 (K, 2) a point of A at
    that distance from B, ``b`` float32 (K, 2) a point of B (float64 all three
    when the boxes were float64). A pair that collides (touching included) has
    every value +0."""

    __slots__ = ("distance", "a", "b")

    def __init__(self, columns):
        for name in self.__slots__:
            setattr(self, name, columns[name])

    def __len__(self):
        return len(self.distance)

    def __repr__(self):
        return f"Distances({len(self)} pairs)"


def _margin(margin):
    """``margin`` as a float; the library refuses a negative or non-finite one (ValueError)."""
    if isinstance(margin, (str, bytes)) or not isinstance(margin, (int, float, _np.integer, _np.floating)):
        raise TypeError(f"margin must be a number, not {type(margin).__name__}")
    return float(margin)


def _boxes(boxes, precision=None):
    """The boxes of a pair-list call: a store as it is, an array as :func:`_form`
    gives it (float64 data stays float64 and is computed in double, unless
    ``precision`` says otherwise)."""
    if isinstance(boxes, _FLOAT_STORES):
        _store_form(boxes, precision)
        return boxes
    if isinstance(boxes, _DOUBLE_STORES):
        # The double rows as they are stored: computed in double, never rounded.
        return _np.ascontiguousarray(boxes.poses if _store_form(boxes, precision) == "poses" else boxes.corners)
    return _form(boxes, "boxes", precision)[1]


def _stream_pair(a, b, call, precision=None):
    """Both batches of a stream call, of one form and equal length, in one
    precision: float64 when ``precision`` says so or, when it is None, when
    either batch holds float64 data (the other is widened, exactly)."""
    for what, batch in (("a", a), ("b", b)):
        _refuse_store(batch, call, what,
                      "an array of corners, (N, 8) or (N, 4, 2), or of poses, (N, 6), not a store")
    if precision is None:
        precision = "float64" if _holds_float64(a) or _holds_float64(b) else "float32"
    form_a, a = _form(a, "a", precision)
    form_b, b = _form(b, "b", precision)
    if form_a != form_b:
        raise ValueError(f"a holds {form_a} (shape {a.shape}), b holds {form_b} (shape {b.shape}): "
                         "a stream compares one form")
    if len(a) != len(b):
        raise ValueError(f"stream batches differ in length: {len(a)} in a, {len(b)} in b")
    return a, b


def contacts(boxes, pairs, *, margin=0.0, backend="auto", threads=1, precision=None):
    """The contact of each pair of boxes (``obbsat::contact_pairs``): normal,
    depth and up to two points with feature keys, as a physics solver needs
    them, bit for bit the same on every backend and thread count.

    ``boxes`` and ``pairs`` are as in :func:`collide` (poses (N, 6), corners
    (N, 8) or (N, 4, 2), or a :func:`records` store); corners must be strictly
    convex quads (``docs/contacts.md``). ``margin`` (finite, >= 0): pairs
    apart by at most this much get points too. Float64 boxes are computed in
    double (``obbsat/ref/contact.hpp`` states how), never rounded, and give
    float64 columns; ``precision="float32"`` rounds them to float32 instead,
    ``precision="float64"`` widens float32 data. Double contacts run on every
    backend, bit for bit the same. The GIL is released.

    Returns a :class:`Contacts`, one row per pair. Raises ``IndexError`` for an
    index out of range (naming the pair), ``ValueError`` for a bad box (naming
    the row and field), margin, backend or threads, ``TypeError`` for a
    non-numeric dtype or a store passed as ``pairs``.

    >>> poses = np.array([[0, 0, 1, 1, 1, 0], [1.5, 0, 1, 1, 1, 0]], dtype=np.float32)
    >>> c = obbsat.contacts(poses, [[0, 1]])
    >>> c.normals[0], float(c.depths[0]), int(c.counts[0])
    (array([1., 0.], dtype=float32), 0.5, 2)
    """
    _refuse_store(pairs, "contacts", "pairs", _PAIRS_EXPECTED)
    threads = _threads(threads)
    margin = _margin(margin)
    boxes = _boxes(boxes, _precision(precision))
    pairs = _pairs(pairs, len(boxes))
    call = _core.contacts_of_pairs64 if _is64(boxes) else _core.contacts_of_pairs
    return Contacts(call(boxes, pairs, margin, _backend(backend), threads))


def contacts_stream(a, b, *, margin=0.0, backend="auto", threads=1, precision=None):
    """The contact of ``a[k]`` and ``b[k]`` for every k: two arrays of one
    form and equal length (copied into the library's stores, which checks
    them; errors name ``a`` or ``b``). Otherwise as :func:`contacts`.

    >>> a = np.array([[0, 0, 1, 1, 1, 0]] * 2, dtype=np.float32)
    >>> b = np.array([[1.5, 0, 1, 1, 1, 0], [0, 1.75, 1, 1, 1, 0]], dtype=np.float32)
    >>> obbsat.contacts_stream(a, b).depths
    array([0.5 , 0.25], dtype=float32)
    """
    threads = _threads(threads)
    margin = _margin(margin)
    a, b = _stream_pair(a, b, "contacts_stream", _precision(precision))
    call = _core.contacts_of_stream64 if _is64(a) else _core.contacts_of_stream
    return Contacts(call(a, b, margin, _backend(backend), threads))


def distances(boxes, pairs, *, backend="auto", threads=1, precision=None):
    """The Euclidean distance of each pair of boxes and a closest point of
    each (``obbsat::distance_pairs``); every value +0 for a pair that
    collides. Arguments and errors as :func:`contacts` (an array is copied
    into a store first). Returns a :class:`Distances`.

    >>> poses = np.array([[0, 0, 1, 1, 1, 0], [4, 0, 1, 1, 1, 0]], dtype=np.float32)
    >>> d = obbsat.distances(poses, [[0, 1]])
    >>> float(d.distance[0]), d.a[0], d.b[0]
    (2.0, array([1., 1.], dtype=float32), array([3., 1.], dtype=float32))
    """
    _refuse_store(pairs, "distances", "pairs", _PAIRS_EXPECTED)
    threads = _threads(threads)
    boxes = _boxes(boxes, _precision(precision))
    pairs = _pairs(pairs, len(boxes))
    call = _core.distances_of_pairs64 if _is64(boxes) else _core.distances_of_pairs
    return Distances(call(boxes, pairs, _backend(backend), threads))


def distances_stream(a, b, *, backend="auto", threads=1, precision=None):
    """The distance of ``a[k]`` and ``b[k]`` for every k; as :func:`distances`
    and :func:`contacts_stream`.

    >>> a = np.array([[0, 0, 1, 1, 1, 0]] * 2, dtype=np.float32)
    >>> b = np.array([[1.5, 0, 1, 1, 1, 0], [0, 5, 1, 1, 1, 0]], dtype=np.float32)
    >>> obbsat.distances_stream(a, b).distance
    array([0., 3.], dtype=float32)
    """
    threads = _threads(threads)
    a, b = _stream_pair(a, b, "distances_stream", _precision(precision))
    call = _core.distances_of_stream64 if _is64(a) else _core.distances_of_stream
    return Distances(call(a, b, _backend(backend), threads))


def find_contacts(boxes, *, method="exact", margin=0.0, backend="auto", threads=1, precision=None):
    """Every colliding pair of a scene with its contact (``obbsat::find_contacts``):
    ``(pairs, contacts)``, pairs uint32 (K, 2) sorted by i then j (i < j) as
    :func:`find_pairs` gives them, and a :class:`Contacts` row for each.

    With ``margin`` > 0, also every other pair apart by at most the margin
    whose contact has points (found by bounds widened by the margin; see
    ``obbsat/find_contacts.hpp``). Arguments and errors as :func:`find_pairs`
    and :func:`contacts`; the GIL is released.

    float64 data (or a double store) stays float64, as in :func:`find_pairs`
    and :func:`contacts`: the pairs are those of :func:`find_pairs` on the
    doubles, each contact computed in double (``obbsat::find_contacts64``,
    bit for bit :func:`contacts` on those pairs), the columns float64 and the
    margin taken as a double; ``precision="float32"`` rounds the data first.

    >>> poses = np.array([[0, 0, 1, 1, 1, 0], [1.5, 0, 1, 1, 1, 0], [3.6, 0, 1, 1, 1, 0]], dtype=np.float32)
    >>> pairs, c = obbsat.find_contacts(poses)
    >>> pairs
    array([[0, 1]], dtype=uint32)
    >>> obbsat.find_contacts(poses, margin=0.2)[0]
    array([[0, 1],
           [1, 2]], dtype=uint32)
    >>> far = np.array([[500000.1, 0, 1, 1, 1, 0], [500002.101, 0, 1, 1, 1, 0]])  # float64, 0.001 apart
    >>> len(obbsat.find_contacts(far)[0]), len(obbsat.find_contacts(far, precision="float32")[0])
    (0, 1)
    >>> float(obbsat.find_contacts(far, margin=0.002)[1].depths[0])  # doctest: +ELLIPSIS
    -0.00100000...
    """
    method = _SCENE_METHOD if method is None else method
    threads = _threads(threads)
    margin = _margin(margin)
    precision = _precision(precision)
    if precision is None and _holds_float64(boxes):
        precision = "float64"
    _, boxes = _scene_form(boxes, "boxes", precision or "float32")
    call = _core.find_contacts64 if _is64(boxes) else _core.find_contacts
    pairs, columns = call(boxes, method, margin, _backend(backend), threads)
    return pairs, Contacts(columns)
