"""Pair lists larger than one machine, decided on a Dask cluster.

The pairs are a chunked ``dask.array`` of shape (M, 2); the rectangles are one
array that every worker needs whole (any pair may name any rectangle), corners
or poses as :func:`obbsat.collide` takes them. It is copied once into a
:func:`obbsat.records` store (a :class:`obbsat.RectRecords` or
:class:`obbsat.PoseRecords`; for float64 data a :class:`obbsat.RectRecords64`
or :class:`obbsat.PoseRecords64`, every double kept; checked once) and, with a ``distributed`` client,
sent to every worker once (``Client.scatter(...,
broadcast=True)``); each chunk of pairs then becomes one task that decides its
pairs against the worker's copy. The verdicts are a lazy boolean
``dask.array`` chunked like the pairs' rows, byte-identical to
``obbsat.collide`` on the whole list.

>>> import dask.array as da
>>> rects, pairs = obbsat.testing.make_scene(rects=2000, pairs=20_000, seed=4)
>>> lazy = obbsat.dask.collide(rects, da.from_array(pairs, chunks=(5000, 2)))
>>> bool((lazy.compute() == obbsat.collide(rects, pairs)).all())
True

A scene too large for one query at a time is cut into tiles:
:func:`find_pairs` runs :func:`obbsat.find_pairs` per tile, on the boxes whose
bounds touch it, and returns the same sorted pairs as the in-memory query.

The same code runs on a cluster of many machines: connect a client to its
scheduler (``distributed.Client("tcp://scheduler:8786")``) before calling, and
make obbsat importable on every worker (installed the same way on each).
"""

import math as _math
import re as _re

import numpy as _np

import obbsat as _obbsat

__all__ = ["collide", "colliding_pairs", "find_pairs", "shared_records"]


def _client_or_none(client):
    if client is not None:
        return client
    try:
        from distributed import default_client
    except ImportError:
        return None
    try:
        return default_client()
    except ValueError:
        return None


def shared_records(rects, client=None, *, precision=None):
    """The rectangles as every worker will read them: a checked
    :func:`obbsat.records` store (:class:`obbsat.RectRecords` for corners,
    :class:`obbsat.PoseRecords` for poses; :class:`obbsat.RectRecords64` and
    :class:`obbsat.PoseRecords64` for float64 data, which stays float64
    unless ``precision="float32"`` asks for a float32 store, as
    :func:`obbsat.records` takes it), broadcast to all workers of
    ``client`` (or of the default client) when there is one, in which case a
    ``distributed.Future`` is returned. Pass the result as ``rects`` to
    :func:`collide` to reuse one broadcast for many pair lists.

    >>> store = obbsat.dask.shared_records(np.zeros((3, 8), dtype=np.float32))
    >>> len(store)
    3
    >>> poses = obbsat.dask.shared_records(np.array([[0, 0, 1, 1, 1, 0]] * 2, dtype=np.float32))
    >>> type(poses).__name__, len(poses)
    ('PoseRecords', 2)
    """
    store = _obbsat.records(rects, precision=precision)
    client = _client_or_none(client)
    if client is None:
        return store
    return client.scatter(store, broadcast=True, hash=False)


def _decide_chunk(pairs, store, method, backend, threads, block_info=None):
    try:
        return _obbsat.collide(store, pairs, method=method, backend=backend, threads=threads)
    except IndexError as error:
        # Name the pair by its row in the whole list, not in this chunk.
        first_row = block_info[0]["array-location"][0][0] if block_info else 0
        text = str(error)
        if first_row and text.startswith("pair "):
            row, rest = text[5:].split(":", 1)
            raise IndexError(f"pair {int(row) + first_row}:{rest}") from None
        raise


def _as_pair_array(pairs):
    import dask.array as da

    if not isinstance(pairs, da.Array):
        raise TypeError(f"pairs: expected a dask.array of shape (M, 2), got {type(pairs).__name__}")
    if pairs.ndim != 2 or pairs.shape[1] != 2:
        raise ValueError(f"pairs: expected shape (M, 2), got {pairs.shape}")
    if pairs.dtype.kind not in "iu":
        raise TypeError(f"pairs: expected an integer array, got dtype {pairs.dtype}")
    if len(pairs.chunks[1]) != 1:
        pairs = pairs.rechunk({1: 2})
    return pairs


def collide(rects, pairs, method=None, backend="auto", threads=1, client=None, *, precision=None):
    """Whether each pair collides, as a lazy boolean ``dask.array`` of shape
    (M,) chunked like the rows of ``pairs``.

    Parameters
    ----------
    rects : array_like (N, 4, 2), (N, 8) or (N, 6), a store, or the result of :func:`shared_records`
        Corners or poses, as in :func:`obbsat.collide`. Checked and
        broadcast once per call (once overall when you pass a
        :func:`shared_records` result).
    pairs : dask.array of int, shape (M, 2)
        Chunked along rows; each chunk is one task.
    method, backend, threads
        As in :func:`obbsat.collide`, for each chunk (``threads`` per task);
        ``method=None`` is ``"sat4"`` on float32 corners, ``"exact"`` on
        float64 corners, ``"local"`` on poses.
        ``threads`` out of 0 .. 2**32 - 1 is refused here (``ValueError``).
    client : distributed.Client, optional
        Where to broadcast the rectangles; the default client if omitted.
        Without any client (Dask's local schedulers) the store is shared in
        memory.

    precision : None, "float32" or "float64"
        As in :func:`obbsat.records`: float64 data is decided in float64
        unless ``"float32"`` asks for it rounded.

    Errors in the rectangles are raised here; an index out of range is
    raised when computed (``IndexError`` naming the pair's row in ``pairs``).
    """
    import dask.array as da

    threads = _obbsat._threads(threads)
    pairs = _as_pair_array(pairs)
    store = rects if _is_shared(rects) else shared_records(rects, client, precision=precision)
    return da.map_blocks(_decide_chunk, pairs, store, method, backend, threads,
                         drop_axis=1, dtype=bool, meta=_np.empty((0,), dtype=bool))


def _is_shared(rects):
    if isinstance(rects, _obbsat._STORES):
        return False
    try:
        from distributed import Future
    except ImportError:
        return False
    return isinstance(rects, Future)


def colliding_pairs(rects, pairs, method=None, backend="auto", threads=1, client=None, *, precision=None):
    """The rows of ``pairs`` that collide, in order, as a lazy ``dask.array``
    of shape (K, 2) (K unknown until computed). Arguments as :func:`collide`.
    """
    pairs = _as_pair_array(pairs)
    hits = collide(rects, pairs, method=method, backend=backend, threads=threads, client=client, precision=precision)
    return pairs[hits]


# --- Scene queries in tiles -------------------------------------------------
#
# The grid: tiles of side `tile` from (x0, y0), nx columns and ny rows; a
# coordinate v lies in column clip(floor((v - x0) / tile), 0, nx - 1),
# evaluated in float64. That is a non-decreasing function of v (each step
# rounds monotonically), so:
#   - a box goes to every tile from the column of its lo_x to that of its
#     hi_x and from the row of its lo_y to that of its hi_y;
#   - two boxes whose bounds overlap share the point (max lo_x, max lo_y),
#     the lower left corner of the intersection of their bounds, whose tile
#     is (max of their first columns, max of their first rows) and lies in
#     both boxes' ranges: the pair is found there;
#   - a pair is kept only in that tile, so each pair is reported once.
# Within a tile the boxes keep their order in the input (their global indices
# increase), so the tile's query sees each pair (i, j) in the orientation the
# whole query gives it (methods are not symmetric). Boxes beyond the grid
# (bounds outside `extent`, infinite bounds) fall into the border tiles.

_MAX_TILES = 1 << 16
_ROWS_PER_CHUNK = 1 << 20


def _tile_of(values, origin, tile, count):
    """The column (or row) of the grid holding each coordinate."""
    k = _np.floor((values.astype(_np.float64) - origin) / tile)
    return _np.clip(k, 0, count - 1).astype(_np.int64)


_NAMED_BOX = _re.compile(r"^(rectangle|pose) (\d+):")


def _checked_bounds(rows, first, what):
    """obbsat.bounds of a chunk; an error names the box by its row in the
    whole array (and the side, for a cross query)."""
    try:
        return _obbsat.bounds(rows)
    except ValueError as error:
        text = _NAMED_BOX.sub(lambda m: f"{m.group(1)} {int(m.group(2)) + first}:", str(error), count=1)
        raise ValueError(f"{what}: {text}" if what else text) from None


def _finite_extent(b):
    """The least finite lo_x, lo_y and the greatest finite hi_x, hi_y of
    bounds rows ``b`` (+inf, -inf where there is none)."""
    b = _np.asarray(b, dtype=_np.float64).reshape(-1, 4)
    lo = _np.where(_np.isfinite(b[:, :2]), b[:, :2], _np.inf).min(axis=0, initial=_np.inf)
    hi = _np.where(_np.isfinite(b[:, 2:]), b[:, 2:], -_np.inf).max(axis=0, initial=-_np.inf)
    return _np.concatenate([lo, hi])


def _chunk_extent(rows, what, block_info=None):
    """_finite_extent of a chunk's bounds, shape (1, 4)."""
    first = block_info[0]["array-location"][0][0] if block_info else 0
    return _finite_extent(_checked_bounds(rows, first, what))[None, :]


def _split_chunk(rows, first, grid, what):
    """The rows of one chunk sorted into the tiles their bounds touch: one
    piece per tile, ``(global indices, rows, first columns, first rows)``."""
    x0, y0, tile, nx, ny = grid
    b = _checked_bounds(rows, first, what)
    col_lo, col_hi = _tile_of(b[:, 0], x0, tile, nx), _tile_of(b[:, 2], x0, tile, nx)
    row_lo, row_hi = _tile_of(b[:, 1], y0, tile, ny), _tile_of(b[:, 3], y0, tile, ny)
    widths = col_hi - col_lo + 1
    counts = widths * (row_hi - row_lo + 1)
    box = _np.repeat(_np.arange(len(rows)), counts)
    step = _np.arange(len(box)) - _np.repeat(_np.cumsum(counts) - counts, counts)
    tiles = (row_lo[box] + step // widths[box]) * nx + col_lo[box] + step % widths[box]
    order = _np.argsort(tiles, kind="stable")  # within a tile, the boxes in their order
    box, tiles = box[order], tiles[order]
    edges = _np.searchsorted(tiles, _np.arange(nx * ny + 1))
    pieces = []
    for t in range(nx * ny):
        chosen = box[edges[t]:edges[t + 1]]
        pieces.append((chosen + first, rows[chosen], col_lo[chosen], row_lo[chosen]))
    return tuple(pieces)


def _joined(pieces, width):
    if not pieces:
        return (_np.empty(0, _np.int64), _np.empty((0, width), _np.float32), _np.empty(0, _np.int64),
                _np.empty(0, _np.int64))
    return tuple(_np.concatenate(parts) for parts in zip(*pieces))


def _tile_pairs(t, pieces, against_pieces, grid, width, method, backend, threads):
    """The pairs owned by tile t: found by obbsat.find_pairs among the boxes
    touching it, kept when the tile holds the lower left corner of the
    intersection of their bounds."""
    nx = grid[3]
    col, row = t % nx, t // nx
    index_a, rows_a, col_a, row_a = _joined(pieces, width)
    if against_pieces is None:
        index_b, rows_b, col_b, row_b = index_a, None, col_a, row_a
    else:
        index_b, rows_b, col_b, row_b = _joined(against_pieces, width)
    local = _obbsat.find_pairs(rows_a, rows_b, method=method, backend=backend, threads=threads)
    a, b = local[:, 0], local[:, 1]
    kept = (_np.maximum(col_a[a], col_b[b]) == col) & (_np.maximum(row_a[a], row_b[b]) == row)
    return _np.stack([index_a[a[kept]], index_b[b[kept]]], axis=1).astype(_np.uint32)


def _merge_pairs(parts):
    """The pairs of every tile, sorted by (i, j)."""
    pairs = _np.concatenate(parts) if parts else _np.empty((0, 2), _np.uint32)
    keys = (pairs[:, 0].astype(_np.uint64) << _np.uint64(32)) | pairs[:, 1].astype(_np.uint64)
    keys.sort()
    out = _np.empty((len(keys), 2), dtype=_np.uint32)
    out[:, 0] = keys >> _np.uint64(32)
    out[:, 1] = keys & _np.uint64(0xFFFFFFFF)
    return out


def _lazy_boxes(boxes, what):
    """``(form, boxes)``: the boxes as a dask.array of rows (N, 8) for corners
    or (N, 6) for poses, float32 (float64 for float64 data), chunked along rows only."""
    import dask.array as da

    if isinstance(boxes, (_obbsat.RectRecords, _obbsat.RectRecords64)):
        boxes = boxes.corners
    elif isinstance(boxes, (_obbsat.PoseRecords, _obbsat.PoseRecords64)):
        boxes = boxes.poses
    if isinstance(boxes, da.Array):
        if boxes.dtype.kind not in "fiu":
            raise TypeError(f"{what}: expected real numbers, got dtype {boxes.dtype}")
        # The one mapping from a shape to a form, on an empty array of that shape.
        form, _ = _obbsat._form(_np.empty((0,) + tuple(boxes.shape[1:]), dtype=boxes.dtype), what)
        if any(_math.isnan(size) for size in boxes.chunks[0]):
            raise ValueError(f"{what}: the chunks' lengths are unknown (call compute_chunk_sizes() first): "
                             "each box is named by its row")
        # float64 stays float64 (decided in double), anything else goes to float32, as obbsat.find_pairs does.
        boxes = boxes.rechunk({axis: -1 for axis in range(1, boxes.ndim)}).astype(_obbsat._dtype_of(boxes.dtype, None))
    else:
        form, boxes = _obbsat._form(boxes, what)
        boxes = da.from_array(boxes, chunks=(_ROWS_PER_CHUNK,) + boxes.shape[1:])
    if boxes.ndim == 3:
        boxes = boxes.reshape((boxes.shape[0], 8))
    return form, boxes


def _grid(sides, tile, extent):
    """``(x0, y0, tile, nx, ny)``: the tiles covering ``extent``, or the
    finite bounds of every box (computed now, one pass) when it is None."""
    if extent is None:
        import dask
        import dask.array as da

        parts = [da.map_blocks(_chunk_extent, side, what, chunks=((1,) * side.numblocks[0], (4,)),
                               dtype=_np.float64, meta=_np.empty((0, 4)))
                 for side, what in sides]
        x_lo, y_lo, x_hi, y_hi = _finite_extent(_np.concatenate(dask.compute(*parts)))
        # No finite bound on a side: the grid is one tile wide there (the clamp places every box).
        x_lo, y_lo = (lo if _math.isfinite(lo) else (hi if _math.isfinite(hi) else 0.0)
                      for lo, hi in ((x_lo, x_hi), (y_lo, y_hi)))
        x_hi, y_hi = max(x_hi, x_lo), max(y_hi, y_lo)
        extent = (x_lo, y_lo, x_hi, y_hi)
    x_lo, y_lo, x_hi, y_hi = (float(v) for v in extent)
    if not all(_math.isfinite(v) for v in (x_lo, y_lo, x_hi, y_hi)) or x_hi < x_lo or y_hi < y_lo:
        raise ValueError(f"extent: expected finite (x_lo, y_lo, x_hi, y_hi) with lo <= hi, got {extent}")
    nx = max(1, _math.ceil((x_hi - x_lo) / tile))
    ny = max(1, _math.ceil((y_hi - y_lo) / tile))
    if nx * ny > _MAX_TILES:
        raise ValueError(f"tile {tile} cuts the extent ({x_lo}, {y_lo}, {x_hi}, {y_hi}) into {nx} x {ny} tiles, "
                         f"more than {_MAX_TILES}: pass a larger tile, or an extent (boxes beyond it go to the border "
                         "tiles)")
    return x_lo, y_lo, tile, nx, ny


def find_pairs(boxes, tile, against=None, *, method="exact", backend="auto", threads=1, extent=None):
    """Every colliding pair of a scene, found tile by tile: a lazy
    ``dask.array`` of shape (K, 2), uint32, sorted by (i, j), equal to
    :func:`obbsat.find_pairs` on the same boxes (K unknown until computed).

    The plane is cut into square tiles of side ``tile`` over the boxes'
    :func:`obbsat.bounds`. Each chunk of boxes is one task that sorts its
    boxes into the tiles their bounds touch; each tile is one task that runs
    :func:`obbsat.find_pairs` on those boxes and keeps a pair only when the
    tile holds the lower left corner of the intersection of the two boxes'
    bounds (every pair whose bounds overlap is found in that tile, and kept
    in no other); one last task sorts the pairs of every tile.

    Parameters
    ----------
    boxes : dask.array or array_like, shape (N, 4, 2), (N, 8) or (N, 6), or a store
        Corners or poses as :func:`obbsat.collide` takes them; a dask.array
        is chunked along rows (one task per chunk).
    tile : float
        The side of a tile, in the boxes' units. A box larger than a tile
        goes to every tile it touches; aim for tiles holding thousands of
        boxes, at most 65536 tiles.
    against : the same, optional
        A cross query, as :func:`obbsat.find_pairs`: i indexes ``boxes``,
        j ``against``, both of one form.
    method, backend, threads
        As in :func:`obbsat.find_pairs` (``threads`` per task; the method
        ``"exact"`` by default, also for ``None``). Checked here, before any
        work.
    extent : (x_lo, y_lo, x_hi, y_hi), optional
        The region the tiles cover. Without it, the least and greatest
        finite bounds of the boxes, computed when called (one pass over the
        boxes with Dask's current scheduler, which also refuses a bad box
        here, naming its row). Boxes beyond the extent go to the border
        tiles: the answer never depends on it, nor on ``tile``.

    >>> import dask.array as da
    >>> poses = obbsat.testing.make_pose_scene(boxes=5000, seed=3)
    >>> lazy = obbsat.dask.find_pairs(da.from_array(poses, chunks=(1000, 6)), tile=25)
    >>> np.array_equal(lazy.compute(), obbsat.find_pairs(poses))
    True
    """
    import dask.array as da
    from dask import delayed

    form, boxes = _lazy_boxes(boxes, "boxes")
    sides = [(boxes, "boxes" if against is not None else "")]
    if against is not None:
        form_against, against = _lazy_boxes(against, "against")
        if form_against != form:
            raise ValueError(f"boxes hold {form}, against holds {form_against}: a scene query compares one form")
        sides.append((against, "against"))
    width = boxes.shape[1]
    # An unknown method or backend, a method not on the form (in the precision the tiles decide), threads < 0:
    # refused now.
    dtype = _np.result_type(*(side.dtype for side, _ in sides))
    _obbsat.find_pairs(_np.empty((0, width), dtype=dtype), method=method, backend=backend, threads=threads)
    threads = _obbsat._threads(threads)
    tile = float(tile)
    if not (_math.isfinite(tile) and tile > 0):
        raise ValueError(f"tile: expected a finite side > 0, got {tile}")
    grid = _grid(sides, tile, extent)
    tiles = grid[3] * grid[4]

    def split(side, what):
        firsts = _np.concatenate([[0], _np.cumsum(side.chunks[0])[:-1]]).astype(int).tolist()
        blocks = side.to_delayed().ravel()
        return [delayed(_split_chunk, nout=tiles, pure=True)(block, first, grid, what)
                for block, first in zip(blocks, firsts)]

    split_a = split(*sides[0])
    split_b = split(*sides[1]) if against is not None else None
    per_tile = [delayed(_tile_pairs, pure=True)(t, [pieces[t] for pieces in split_a],
                                                None if split_b is None else [pieces[t] for pieces in split_b],
                                                grid, width, method, backend, int(threads))
                for t in range(tiles)]
    merged = delayed(_merge_pairs, pure=True)(per_tile)
    return da.from_delayed(merged, shape=(_np.nan, 2), dtype=_np.uint32, meta=_np.empty((0, 2), _np.uint32))
