"""Pair lists larger than one machine, decided on a Dask cluster.

The pairs are a chunked ``dask.array`` of shape (M, 2); the rectangles are one
array that every worker needs whole (any pair may name any rectangle), corners
or poses as :func:`obbsat.collide` takes them. It is copied once into a
:func:`obbsat.records` store (a :class:`obbsat.RectRecords` or
:class:`obbsat.PoseRecords`, checked once) and, with a ``distributed`` client,
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

The same code runs on a cluster of many machines: connect a client to its
scheduler (``distributed.Client("tcp://scheduler:8786")``) before calling, and
make obbsat importable on every worker (installed the same way on each).
"""

import numpy as _np

import obbsat as _obbsat

__all__ = ["collide", "colliding_pairs", "shared_records"]


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


def shared_records(rects, client=None):
    """The rectangles as every worker will read them: a checked
    :func:`obbsat.records` store (:class:`obbsat.RectRecords` for corners,
    :class:`obbsat.PoseRecords` for poses), broadcast to all workers of
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
    store = _obbsat.records(rects)
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


def collide(rects, pairs, method=None, backend="auto", threads=1, client=None):
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
        ``method=None`` is ``"sat4"`` on corners, ``"local"`` on poses.
    client : distributed.Client, optional
        Where to broadcast the rectangles; the default client if omitted.
        Without any client (Dask's local schedulers) the store is shared in
        memory.

    Errors in the rectangles are raised here; an index out of range is
    raised when computed (``IndexError`` naming the pair's row in ``pairs``).
    """
    import dask.array as da

    pairs = _as_pair_array(pairs)
    store = rects if _is_shared(rects) else shared_records(rects, client)
    return da.map_blocks(_decide_chunk, pairs, store, method, backend, int(threads),
                         drop_axis=1, dtype=bool, meta=_np.empty((0,), dtype=bool))


def _is_shared(rects):
    if isinstance(rects, (_obbsat.RectRecords, _obbsat.PoseRecords)):
        return False
    try:
        from distributed import Future
    except ImportError:
        return False
    return isinstance(rects, Future)


def colliding_pairs(rects, pairs, method=None, backend="auto", threads=1, client=None):
    """The rows of ``pairs`` that collide, in order, as a lazy ``dask.array``
    of shape (K, 2) (K unknown until computed). Arguments as :func:`collide`.
    """
    pairs = _as_pair_array(pairs)
    hits = collide(rects, pairs, method=method, backend=backend, threads=threads, client=client)
    return pairs[hits]
